#!/bin/sh
# Issue 30: `mpirun -n 2 check_cert --threads 1` against one process with --threads 2 (and
# with --threads 1, the base of the speed-ups), interleaved, RUNS runs each, on one
# certificate; prints the wall seconds of each command, the load average, and the verdict
# line's hash (every run must give the same line).
# Usage: bench/check_mpi_vs_threads.sh CHECK_CERT_MPI_BUILD CERT [RUNS]
set -eu
check=$1 cert=$2 runs=${3:-3}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
now() { date +%s.%N; }
one() {  # KIND COMMAND...: one timed run
  kind=$1
  shift
  t0=$(now)
  line=$("$@" --quiet "$cert" | sha256sum | cut -c1-12)
  t1=$(now)
  printf '%-9s wall %7.2f s  load %s  line %s\n' "$kind" "$(echo "$t1 - $t0" | bc)" \
    "$(cut -d' ' -f1 /proc/loadavg)" "$line"
}
for i in $(seq "$runs"); do
  one threads1 "$check" --threads 1
  one threads2 "$check" --threads 2
  one mpi2x1 mpirun -n 2 --bind-to none "$check" --threads 1
done
