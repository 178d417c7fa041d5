#!/bin/sh
# Issue 30: `mpirun -n 2 aspects solve --threads 1` against one process with --threads 2,
# interleaved, RUNS runs each; prints one line per run (wall seconds of the whole command,
# summary.json's search and total seconds) and checks that the outputs are the same.
# --bind-to none, as README advises: rank 0 bound to one core could not take the idle
# rank's core for the phases after the search.
# Usage: bench/mpi_vs_threads.sh ASPECTS_MPI_BUILD MODEL EPS [RUNS]
set -eu
aspects=$1 model=$2 eps=$3 runs=${4:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
now() { date +%s.%N; }
report() {  # KIND RUN START END DIR
  /usr/bin/python3 - "$@" <<'PY'
import json, sys
kind, run, start, end, d = sys.argv[1:]
s = json.load(open(d + "/summary.json"))
print(f"{kind:8} run {run}  wall {float(end) - float(start):6.2f} s  search {s['phase_seconds']['search']:6.2f} s"
      f"  total {s['time_seconds']:6.2f} s  load {open('/proc/loadavg').read().split()[0]}")
PY
}
threads() {
  t0=$(now); "$aspects" solve "$model" --eps "$eps" --threads 2 --quiet --out "$work/t$i"; t1=$(now)
  report threads2 "$i" "$t0" "$t1" "$work/t$i"
}
mpi() {
  t0=$(now); mpirun -n 2 --bind-to none "$aspects" solve "$model" --eps "$eps" --threads 1 --quiet --out "$work/m$i"; t1=$(now)
  report mpi2x1 "$i" "$t0" "$t1" "$work/m$i"
}
# The order alternates: a run that writes its outputs just after the other's (hundreds of
# MB still being written back) is the slower to write them (0.55-0.61 s against 0.49-0.51
# for 3-RRR* at eps 0.1's outputs phase, whichever runs second).
for i in $(seq "$runs"); do
  if [ $((i % 2)) = 1 ]; then threads; mpi; else mpi; threads; fi
  for f in boxes.csv aspects.cert aspects.idx; do cmp -s "$work/t$i/$f" "$work/m$i/$f" || echo "DIFFERENT $f"; done
  rm -rf "$work/t$i" "$work/m$i"
done
