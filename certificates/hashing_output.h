// A FILE* that hashes (SHA-256) every byte written to it and passes the bytes on to
// another stream: the certificate's hash as check_cert prints it, sha256(cert), is that
// of the bytes before any compression, and the result index and summary.json record it.
#pragma once

#include <cstdio>
#include <string>

namespace aspects {

// Writes to the returned stream go to `next` (which stays the caller's to flush and
// close), and are hashed. fclose() on the returned stream sets *hex to the hash (64
// lowercase hex digits) and returns 0 only if every byte was handed to `next`. Returns
// null (errno set) if the hash cannot be set up.
FILE* open_hashing_output(FILE* next, std::string* hex);

}  // namespace aspects
