#!/bin/sh
# Interleaved A/B of check_cert builds on one certificate: REPS rounds, each running every
# binary once in turn at --threads 2, so that a noisy shared machine slows all of them
# alike. Prints "BINARY USER_S SYS_S WALL_S" a run; compare medians of user+sys.
#   bench/check_ab.sh CERT REPS CHECK_CERT_A CHECK_CERT_B ...
set -eu
if [ $# -lt 3 ]; then
  echo "usage: $0 CERT REPS CHECK_CERT..." >&2
  exit 2
fi
cert=$1
reps=$2
shift 2
for r in $(seq "$reps"); do
  for b in "$@"; do
    /usr/bin/time -f "$b %U %S %e" "$b" --quiet --threads 2 "$cert" 2>&1 >/dev/null | tail -1
  done
done
