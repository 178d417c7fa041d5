#!/usr/bin/env bash
# aspects count on the paper's robots: median wall time of R runs (default 3) and the bounds
# reached, within a time limit per run (default 120 s). Prints a Markdown table.
# Usage: bench/count_bench.sh [BUILD_DIR] [RUNS] [TIME_LIMIT]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}; runs=${2:-3}; limit=${3:-120}
aspects=$build/apps/aspects
echo "| robot | result | median wall (s) | runs | first cover boxes | boxes at the end | bisections |"
echo "|---|---|---|---|---|---|---|"
for robot in prrp rprpr rrrrr 3rpr; do
  times=(); line=""
  for ((i = 0; i < runs; i++)); do
    out=$(/usr/bin/time -f "%e" -o /tmp/count_bench.time "$aspects" count "robots/$robot.robot" \
          --time-limit "$limit" --json 2>/dev/null || true)
    times+=("$(cat /tmp/count_bench.time)")
    line=$(printf '%s' "$out" | /usr/bin/python3 -c '
import json, sys
j = json.load(sys.stdin)
u = j["upper_bound"]
res = (f"{j[\"lower_bound\"]} exactly" if j["exact"] else
       f"{j[\"lower_bound\"]}..{u if u is not None else \"?\"} ({j[\"stop\"]})")
print(f"{res} | {{t}} | {{n}} | {j[\"first_cover\"][\"boxes\"]} | {j[\"boxes\"]} | {j[\"bisections\"]}")')
  done
  median=$(printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  echo "| $robot | ${line//\{t\}/$median} |" | sed "s/{n}/$runs/"
done
