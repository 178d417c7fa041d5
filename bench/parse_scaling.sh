#!/usr/bin/env bash
# Times `aspects info` on large generated models (bench/parse_models.py), to see that
# parsing grows linearly with the model's size (issue 50, item 6). Not a ctest: timings
# need a quiet machine.
#
# Usage: bench/parse_scaling.sh [--callgrind] [--runs N] ASPECTS_BINARY [SIZE...]
#   SIZE in bytes (default: 100000 1000000). With --callgrind, each run is counted in
#   instructions (valgrind --tool=callgrind; deterministic, about 50x slower) instead of
#   timed. Prints one line per model: shape, size, exit status, median of N runs.
set -euo pipefail

callgrind=0
runs=3
while [[ $# -gt 0 ]]; do
  case "$1" in
    --callgrind) callgrind=1; shift ;;
    --runs) runs="$2"; shift 2 ;;
    *) break ;;
  esac
done
if [[ $# -lt 1 ]]; then
  sed -n '2,10p' "$0"
  exit 2
fi
aspects="$1"
shift
sizes=("$@")
[[ ${#sizes[@]} -gt 0 ]] || sizes=(100000 1000000)
shapes=${SHAPES:-"constants periodic expression lets variables constraint parens"}

here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

median() { sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }

printf '%-11s %9s %4s %s\n' shape bytes exit "$([[ $callgrind = 1 ]] && echo instructions || echo 'wall s')"
for size in "${sizes[@]}"; do
  python3 "$here/parse_models.py" "$work" "$size" >/dev/null
  for shape in $shapes; do
    model="$work/${shape}_${size}.robot"
    values=()
    status=0
    for ((r = 0; r < runs; r++)); do
      if [[ $callgrind = 1 ]]; then
        valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" "$aspects" info "$model" \
          >/dev/null 2>"$work/err" && status=0 || status=$?
        values+=("$(grep -o 'refs: *[0-9,]*' "$work/err" | tr -d ', ' | cut -d: -f2)")
      else
        start=$(date +%s.%N)
        "$aspects" info "$model" >/dev/null 2>&1 && status=0 || status=$?
        end=$(date +%s.%N)
        values+=("$(echo "$end - $start" | bc)")
      fi
    done
    printf '%-11s %9s %4s %s\n' "$shape" "$(stat -c %s "$model")" "$status" \
      "$(printf '%s\n' "${values[@]}" | median)"
  done
done
