// A FILE* whose bytes are compressed with zstd (one frame) into a file, for certificates
// that would not fit on the disk as text: 3-RPR at eps 0.1 makes about 53 GB of records.
// check_cert reads such a file as it reads the text (it recognises zstd's magic number).
#pragma once

#include <cstdio>

namespace aspects {

// Writes to the returned stream are compressed at `level` on `workers` helper threads of
// libzstd (0: on the writer's thread) and written to `raw`, which stays the caller's to
// flush, sync and close. fclose() on the returned stream ends the frame and returns 0 only
// if every compressed byte was handed to `raw` (else EOF, errno set). Returns null (errno
// set) if libzstd cannot be set up.
FILE* open_compressed_output(FILE* raw, int level, int workers);

}  // namespace aspects
