// A FILE* whose bytes are compressed with zstd (one frame) into a file, for certificates
// that would not fit on the disk as text: 3-RPR at eps 0.1 makes about 53 GB of records.
// check_cert reads such a file as it reads the text (it recognises zstd's magic number).
#pragma once

#include <cstdio>

namespace aspects {

// Takes ownership of `raw`. Writes to the returned stream are compressed at `level` on
// `workers` helper threads of libzstd (0: on the writer's thread). fclose() on it ends the
// frame, flushes and fsyncs `raw`, closes it, and returns 0 only if every byte reached the
// file. Returns null (raw closed, errno set) if libzstd cannot be set up.
FILE* open_compressed_output(FILE* raw, int level, int workers);

}  // namespace aspects
