#!/bin/sh
# Interleaved A/B of one phase of the solve, by default the outputs phase (boxes.csv,
# aspects.idx and the certificate, written concurrently after the solve); PHASE=NAME for
# another (summary.json's phase_seconds names): every binary once a round, in turn.
#   [PHASE=NAME] sh bench/outputs_ab.sh MODEL EPS ROUNDS THREADS ASPECTS_A ASPECTS_B ...
# Prints one line a run: binary, round, the phase and all phases (summary.json's
# phase_seconds), and the size of boxes.csv; then each binary's medians.
set -eu
[ $# -ge 5 ] || { echo "usage: $0 MODEL EPS ROUNDS THREADS ASPECTS..." >&2; exit 2; }
model=$1 eps=$2 rounds=$3 threads=$4
shift 4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for r in $(seq "$rounds"); do
  i=0
  for exe in "$@"; do
    i=$((i + 1))
    rm -rf "$work/out"
    "$exe" solve "$model" --eps "$eps" --threads "$threads" --out "$work/out" --quiet
    /usr/bin/python3 - "$work/out" "$exe" "$r" "$i" >>"$work/runs" <<'PY'
import json, os, sys
d, exe, r, i = sys.argv[1:]
s = json.load(open(os.path.join(d, "summary.json")))
p = s["phase_seconds"]
print(i, exe, r, "%.3f" % p[os.environ.get("PHASE", "outputs")], "%.3f" % sum(p.values()),
      os.path.getsize(os.path.join(d, "boxes.csv")))
PY
    tail -n 1 "$work/runs"
  done
done
/usr/bin/python3 - "$work/runs" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    i, exe, r, out, total, size = line.split()
    runs.setdefault((int(i), exe), []).append((float(out), float(total), int(size)))
for (i, exe), v in sorted(runs.items()):
    print("median %s: phase %.3f s, all phases %.3f s, boxes.csv %d bytes (%d runs)" %
          (exe, statistics.median(x[0] for x in v), statistics.median(x[1] for x in v), v[0][2], len(v)))
PY
