#!/bin/sh
# At 53 bits the double fast path gives MPFI's ends (core/numerics/double_interval.h): a solve with
# it and one with `--mpfi-only` must write the same certificate, boxes and index, byte for
# byte, on a robot with periodic variables (sin/cos, their projections) and one without.
# Usage: mpfi_only_same.sh ASPECTS ROBOTS_DIR
set -eu
aspects=$1 robots=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "mpfi_only_same: $*" >&2; exit 1; }
for case in "rrrrr.robot 0.4" "rprpr.robot 0.4" "3rpr.robot 4"; do
  set -- $case
  "$aspects" solve "$robots/$1" --eps "$2" --threads 2 --quiet --out "$out/d" || fail "$1: exit $?"
  "$aspects" solve "$robots/$1" --eps "$2" --threads 2 --quiet --out "$out/m" --mpfi-only ||
    fail "$1 --mpfi-only: exit $?"
  for f in aspects.cert boxes.csv aspects.idx; do
    cmp "$out/d/$f" "$out/m/$f" || fail "$1 eps $2: $f differs with --mpfi-only"
  done
  echo "$1 eps $2: same outputs ($(grep -c '' "$out/d/boxes.csv") lines of boxes.csv)"
done
