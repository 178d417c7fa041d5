#!/bin/sh
# Interleaved A/B of MPI builds of aspects: ROUNDS rounds, each running every binary once
# in turn as `mpirun -n P aspects solve MODEL --eps EPS --threads 1` (the order alternating
# from round to round), so that a noisy shared machine slows all of them alike. Prints
# "BINARY WALL_S USER_S SYS_S" a run (user and sys of the whole job); compare medians.
#   bench/mpi_ab.sh MODEL EPS ROUNDS P ASPECTS_A ASPECTS_B ...
set -eu
if [ $# -lt 5 ]; then
  echo "usage: $0 MODEL EPS ROUNDS P ASPECTS..." >&2
  exit 2
fi
model=$1 eps=$2 rounds=$3 p=$4
shift 4
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for r in $(seq "$rounds"); do
  if [ $((r % 2)) -eq 1 ]; then order="$*"; else order=$(printf '%s\n' "$@" | tac | tr '\n' ' '); fi
  for b in $order; do
    rm -rf "$work/out"
    /usr/bin/time -f "$b %e %U %S" -o "$work/time" mpirun -n "$p" --bind-to none "$b" solve \
      "$model" --eps "$eps" --threads 1 --quiet --out "$work/out" > /dev/null
    cat "$work/time"
  done
done
