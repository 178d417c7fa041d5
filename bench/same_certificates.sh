#!/bin/bash
# Do two `aspects` binaries write the same certificates? Solves each case with both and
# compares the certificates byte for byte, apart from the `tool aspects <version>` line
# (the version names the commit). For a change that must not alter results: a refactoring,
# a speed-up. Exit 0 when every pair is identical, 1 otherwise.
#
#   bench/same_certificates.sh OLD_BINARY NEW_BINARY [ROBOT:EPS ...]
#
# Without cases: the robots of the paper's Table 1 at the paper's eps (3-RPR at 1 and
# 3-RRR* at 0.5, to stay within minutes) and the three constrained RRRRR models at 0.1.
set -uo pipefail
old=${1:?usage: same_certificates.sh OLD NEW [ROBOT:EPS ...]}
new=${2:?usage: same_certificates.sh OLD NEW [ROBOT:EPS ...]}
shift 2
root=$(cd "$(dirname "$0")/.." && pwd)
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(prrp:0.1 rprpr:0.1 rrrrr:0.1 rrrrr_collisions:0.1
  rrrrr_joint_limit:0.1 rrrrr_obstacle:0.1 3rrr_star:0.5 3rpr:1)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
for c in "${cases[@]}"; do
  robot=${c%%:*} eps=${c#*:}
  model=$robot; [ -f "$model" ] || model=$root/robots/$robot.robot
  for side in old new; do
    bin=$old; [ $side = new ] && bin=$new
    if ! "$bin" solve "$model" --eps "$eps" --threads 2 --quiet --out "$work/$side" \
        2> "$work/$side.err"; then
      echo "$c: $side binary failed:"; cat "$work/$side.err"; status=1; continue 2
    fi
    grep -v '^tool aspects ' "$work/$side/aspects.cert" | sha256sum | cut -d' ' -f1 > "$work/$side.sum"
    wc -c < "$work/$side/aspects.cert" > "$work/$side.bytes"
  done
  if cmp -s "$work/old.sum" "$work/new.sum"; then
    echo "$c: identical ($(cat "$work/new.bytes") bytes, sha256 without the version line $(cut -c1-16 "$work/new.sum"))"
  else
    echo "$c: DIFFERENT"; status=1
  fi
done
exit $status
