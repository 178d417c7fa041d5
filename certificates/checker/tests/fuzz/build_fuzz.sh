#!/bin/sh
# build_fuzz.sh WORKDIR "FLAGS" — builds WORKDIR/fuzz_cert_reader, the libFuzzer target of
# check_cert, with clang++ and FLAGS (e.g. -fsanitize=fuzzer,address,undefined) from the
# checker's own sources (all but cli.cpp, its command line). Called by tests/fuzz/run_fuzz.sh.
set -eu
work=$1
flags=$2
here=$(cd "$(dirname "$0")" && pwd)
src=$here/../..
mkdir -p "$work"
# Every source of the checker but its command line (a file added to it is fuzzed too).
set --
for f in "$src"/*.cpp; do
  [ "$(basename "$f")" = cli.cpp ] || set -- "$@" "$f"
done
# shellcheck disable=SC2086 # FLAGS is a list of options
clang++ -std=c++17 $flags "$here/fuzz_cert_reader.cpp" "$@" -pthread \
  -lmpfi -lmpfr -lgmp -lflint-arb -lflint -lcrypto -lzstd -o "$work/fuzz_cert_reader"
