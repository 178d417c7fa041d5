#!/usr/bin/env bash
# aspects count on the paper's robots: median wall time of R runs (default 3) and the bounds
# reached, within a time limit per run (default 120 s). Prints a Markdown table.
# Usage: bench/count_bench.sh [BUILD_DIR] [RUNS] [TIME_LIMIT]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}; runs=${2:-3}; limit=${3:-120}
aspects=$build/apps/aspects
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for robot in prrp rprpr rrrrr 3rpr; do
  for ((i = 0; i < runs; i++)); do
    /usr/bin/time -f "%e" -o "$tmp/time" "$aspects" count "robots/$robot.robot" \
      --time-limit "$limit" --json > "$tmp/$robot.$i.json" 2>/dev/null || true
    echo "$robot $(tail -n 1 "$tmp/time") $tmp/$robot.$i.json" >> "$tmp/runs"
  done
done
/usr/bin/python3 - "$tmp/runs" <<'PY'
import json, statistics, sys
rows = {}
for line in open(sys.argv[1]):
    robot, secs, path = line.split()
    rows.setdefault(robot, []).append((float(secs), json.load(open(path))))
print("| robot | result | median wall (s) | runs | first cover boxes | boxes at the end | bisections | open pieces (no chart / no point / star failed / not reached) |")
print("|---|---|---|---|---|---|---|---|")
for robot, runs in rows.items():
    j = runs[-1][1]
    up = j["upper_bound"]
    res = "%d exactly" % j["lower_bound"] if j["exact"] else "%d..%s (%s)" % (
        j["lower_bound"], "?" if up is None else up, j["stop"])
    r = j["open_pieces_by_reason"]
    print("| %s | %s | %.2f | %d | %d | %d | %d | %d / %d / %d / %s |" % (
        robot, res, statistics.median(s for s, _ in runs), len(runs), j["first_cover"]["boxes"],
        j["boxes"], j["bisections"], r["no_chart"], r["no_point"], r["not_star"],
        r.get("not_reached", "-")))
PY
