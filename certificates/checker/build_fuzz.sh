#!/bin/sh
# build_fuzz.sh WORKDIR "FLAGS" — builds WORKDIR/fuzz_cert_reader, the libFuzzer target of
# check_cert, with clang++ and FLAGS (e.g. -fsanitize=fuzzer,address,undefined) from the
# checker's own sources (main.cpp without its main()). Called by tests/fuzz/run_fuzz.sh.
set -eu
work=$1
flags=$2
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
# shellcheck disable=SC2086 # FLAGS is a list of options
clang++ -std=c++17 $flags -DCHECK_CERT_NO_MAIN -I"$here" "$here/fuzz_cert_reader.cpp" "$here/main.cpp" \
  "$here/cert_reader.cpp" "$here/model.cpp" "$here/eval.cpp" "$here/proofs.cpp" "$here/graph.cpp" "$here/proof_batch.cpp" \
  "$here/compressed_input.cpp" -pthread \
  -lmpfi -lmpfr -lgmp -lcrypto -lzstd -o "$work/fuzz_cert_reader"
