#!/bin/sh
# Builds the libFuzzer targets with clang (ASan + UBSan) and runs each for a bounded
# time on a seed corpus. Usage: tests/fuzz/run_fuzz.sh [SECONDS_PER_TARGET] [WORKDIR]
# Exits non-zero when a target crashes, leaks, hangs (> 10 s on one input) or fails to
# build. Skips (exit 0 with a message) when clang++ is not installed.
set -eu
secs=${1:-30}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=${2:-$(mktemp -d)}
mkdir -p "$work"
command -v clang++ >/dev/null || { echo "run_fuzz: clang++ not installed, skipped"; exit 0; }
flags="-std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined"
libs="-lmpfi -lmpfr -lgmp -lflint-arb -lflint"

# Model parser, linked with the whole of core/ (a list of files fell out of date twice as
# the parser and the evaluator gained files).
clang++ $flags -I"$root/core" -isystem /usr/include/eigen3 -isystem /usr/include/flint \
  "$here/fuzz_model_parser.cpp" "$root"/core/*/*.cpp $libs -o "$work/fuzz_model_parser"
mkdir -p "$work/corpus_model"
cp "$root"/robots/*.robot "$root"/tests/models/*.robot "$work/corpus_model/"
"$work/fuzz_model_parser" -max_total_time="$secs" -timeout=10 -max_len=4096 \
  -dict="$here/model.dict" "$work/corpus_model" 2>&1 | tail -5

# Certificate reader of check_cert, when its fuzz target exists.
if [ -f "$root/certificates/checker/tests/fuzz/fuzz_cert_reader.cpp" ]; then
  sh "$root/certificates/checker/tests/fuzz/build_fuzz.sh" "$work" "$flags"
  mkdir -p "$work/corpus_cert"
  cp "$root"/certificates/checker/tests/valid/*.cert "$work/corpus_cert/" 2>/dev/null || true
  "$work/fuzz_cert_reader" -max_total_time="$secs" -timeout=10 -max_len=65536 \
    "$work/corpus_cert" 2>&1 | tail -5
fi
echo "run_fuzz: no crash in ${secs}s per target"
