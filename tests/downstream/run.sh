#!/bin/sh
# Installs the build into a fresh prefix, configures and builds this folder's project
# against that prefix alone, and runs it on MODEL (PRRP: 4 CSNCs, lower bound 4). Then the
# same program with wrong expectations must fail, so a check that always passes is caught.
# Usage: run.sh CMAKE BUILD_DIR GENERATOR CXX WORK_DIR MODEL
set -eu
cmake=$1 build=$2 generator=$3 cxx=$4 work=$5 model=$6
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "downstream: $*" >&2; exit 1; }
rm -rf "$work"
mkdir -p "$work"
"$cmake" --install "$build" --prefix "$work/prefix" > "$work/install.log" || fail "install failed (see $work/install.log)"
for f in bin/aspects bin/check_cert include/aspects/generalized_aspects.h lib/cmake/aspects/aspectsConfig.cmake; do
  [ -f "$work/prefix/$f" ] || fail "not installed: $f"
done
"$cmake" -S "$here" -B "$work/build" -G "$generator" -DCMAKE_CXX_COMPILER="$cxx" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix"
# The package must come from the prefix, not from the build tree.
found=$(sed -n 's/^aspects_DIR:PATH=//p' "$work/build/CMakeCache.txt")
[ "$found" = "$work/prefix/lib/cmake/aspects" ] || fail "aspects found in '$found', not in the prefix"
"$cmake" --build "$work/build"
"$work/build/count_aspects" "$model" || fail "count_aspects failed on $model (exit $?)"
if "$work/build/count_aspects" "$model" 5 5 2>/dev/null; then
  fail "count_aspects accepted 5 CSNCs for $model"
fi
"$work/prefix/bin/aspects" --version
echo "downstream: ok"
