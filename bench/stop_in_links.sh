#!/bin/bash
# How soon does a signal stop a run after its search? Solves ROBOT at EPS with
# --all-links --progress, sends SIGINT SECONDS into the link phase, prints the time from the
# signal to the exit, and checks the partial certificate.
#
#   bench/stop_in_links.sh [ROBOT EPS SECONDS]     (default: 3rpr 1 5)
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
robot=${1:-3rpr} eps=${2:-1} wait=${3:-5}
d=$(mktemp -d); trap 'rm -rf "$d"' EXIT
"$root/build/apps/aspects" solve "$root/robots/$robot.robot" --eps "$eps" --threads 2 \
  --all-links --progress --out "$d/out" > "$d/stdout" 2> "$d/stderr" &
pid=$!
until grep -q "merge:" "$d/stderr" 2>/dev/null; do sleep 0.5; done
sleep "$wait"
kill -INT $pid; t0=$(date +%s.%N)
wait $pid; rc=$?
echo "exit $rc, $(echo "$(date +%s.%N) - $t0" | bc) s after SIGINT"
grep -v "boxes processed" "$d/stderr" | tail -5; cat "$d/stdout"
"$root/build/certificates/check_cert" --threads 2 "$d/out/aspects.cert"; echo "check_cert exit $?"
