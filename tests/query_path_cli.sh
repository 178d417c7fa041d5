#!/bin/sh
# `aspects query` and `aspects path` on damaged result directories (exit 2, a message
# naming the problem), `aspects path --plot` writing a PNG, and a periodic pose: a query
# modulo 2π and a path across the ±π seam through a certified link, printed unwrapped;
# poses shifted by whole turns onto box faces, answered as the unshifted ones. $2: a result
# directory written by `aspects solve --out` for RRRRR (the query_fixture test); $3: the
# model tests/models/seam_pose.robot.
set -eu
aspects=$1
result=$2
seam_model=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "query_path_cli: $*" >&2; exit 1; }

# expect CODE REGEX COMMAND...: exit code and a line of stdout+stderr (in $tmp/out) matching
# REGEX.
expect_log=$tmp/out
. "$(dirname "$0")/expect_output.sh"

mkdir "$tmp/truncated" "$tmp/version" "$tmp/garbage" "$tmp/empty"
head -c 1000 "$result/aspects.idx" > "$tmp/truncated/aspects.idx"
# Byte 14 (after the 14-byte magic) is the low byte of the version.
head -c 14 "$result/aspects.idx" > "$tmp/version/aspects.idx"
printf '\011' >> "$tmp/version/aspects.idx"
tail -c +16 "$result/aspects.idx" >> "$tmp/version/aspects.idx"
echo "id,status" > "$tmp/garbage/aspects.idx"

expect 2 "truncated/aspects.idx: malformed result index at byte [0-9]+: truncated" \
  "$aspects" query "$tmp/truncated" --pose 3,5
expect 2 "result index version 9, this aspects reads version 2" \
  "$aspects" query "$tmp/version" --pose 3,5
expect 2 "bad magic" "$aspects" path "$tmp/garbage" --from 3,5 --to 0,8
expect 2 "RESULT_DIR .*/empty: no aspects.idx" "$aspects" query "$tmp/empty" --pose 3,5
expect 2 "RESULT_DIR .*/missing: no such directory" \
  "$aspects" path "$tmp/missing" --from 3,5 --to 0,8

expect 0 "certified singularity-free path in CSNC [0-9]+" \
  "$aspects" path "$result" --from 3,5 --to 0,8 --plot "$tmp/path.png"
[ -s "$tmp/path.png" ] || fail "no PNG written"
head -c 4 "$tmp/path.png" | grep -q PNG || fail "not a PNG"
ls "$tmp" | grep -q tmp && fail "temporary file left: $(ls "$tmp")"
# Around a hole of the RRRRR fixture (issue 51): 5 waypoints (start, 3 corners, goal), so
# the CSV has a header and 5 rows and the JSON 5 waypoints.
expect 0 "^certified singularity-free path in CSNC 1: 5 waypoints, length 6\\.66142, straight line 6\\.3 \\(ratio 1\\.057\\), CSNCs crossed: 1$" \
  "$aspects" path "$result" --from 3.6,-2.6 --to 3.6,3.7 --out "$tmp/hole.csv"
[ "$(wc -l < "$tmp/hole.csv")" -eq 6 ] || { cat "$tmp/hole.csv" >&2; fail "hole CSV rows"; }
head -n 1 "$tmp/hole.csv" | grep -q "^kind,x1,x2,q1_lo,q1_hi,q2_lo,q2_hi,box$" || fail "hole CSV header"
[ "$(cut -d, -f1 "$tmp/hole.csv" | tr '\n' ' ')" = "kind start corner corner corner goal " ] ||
  fail "hole CSV kinds: $(cut -d, -f1 "$tmp/hole.csv" | tr '\n' ' ')"
"$aspects" path "$result" --from 3.6,-2.6 --to 3.6,3.7 --out "$tmp/hole.json" > /dev/null 2>&1 ||
  fail "path --out hole.json"
[ "$(grep -o '"kind":' "$tmp/hole.json" | wc -l)" -eq 5 ] || fail "hole JSON waypoints"
rm "$tmp/hole.csv" "$tmp/hole.json"
# Seam: -9.42 is 3.1464 modulo 2π; from 2.9 to -2.9 the short way is across ±π (length
# 2π - 5.8), through one link whose witness is ±π.
"$aspects" solve "$seam_model" --eps 0.1 --no-cert --quiet --out "$tmp/seam"
expect 0 "^CSNC 0  signs -,\\+$" "$aspects" query "$tmp/seam" --pose=-9.42
# Shortcut (issue 51): one straight segment across the seam, through the two end boxes
# linked there; the chain of links had 3 waypoints (the witness at ±π).
expect 0 "certified singularity-free path in CSNC 0: 2 waypoints, length 0\\.483185, straight line 0\\.483185 \\(ratio 1\\.000\\), CSNCs crossed: 1$" \
  "$aspects" path "$tmp/seam" --from 2.9 --to=-2.9
"$aspects" path "$tmp/seam" --from 2.9 --to=-2.9 --json | grep -q '"chain_waypoints":3,' ||
  fail "the chain before the shortcut is not of 3 waypoints"
expect 1 "refused: .*different determinant signs" "$aspects" path "$tmp/seam" --from 2.5 --to=-2.9

# The seam path as written by --out: unwrapped, the goal is -2.9 + 2π, every pose is above
# the one before. CSV: a header and one row per waypoint; JSON: what --json prints.
"$aspects" path "$tmp/seam" --from 2.9 --to=-2.9 --out "$tmp/seam.csv" > /dev/null 2>&1 ||
  fail "path --out seam.csv"
[ "$(wc -l < "$tmp/seam.csv")" -eq 3 ] || { cat "$tmp/seam.csv" >&2; fail "CSV rows"; }
head -n 1 "$tmp/seam.csv" | grep -q "^kind,t,q_lo,q_hi,box$" || fail "CSV header"
grep -q "^goal,3\.38318530717958" "$tmp/seam.csv" || { cat "$tmp/seam.csv" >&2; fail "goal not unwrapped"; }
awk -F, 'NR > 1 { if (n++ && $2 + 0 <= last) bad = 1; last = $2 } END { exit bad || n != 2 }' \
  "$tmp/seam.csv" || { cat "$tmp/seam.csv" >&2; fail "poses not increasing"; }
"$aspects" path "$tmp/seam" --from 2.9 --to=-2.9 --out "$tmp/seam.json" > /dev/null 2>&1 ||
  fail "path --out seam.json"
"$aspects" path "$tmp/seam" --from 2.9 --to=-2.9 --json > "$tmp/seam_stdout.json"
cmp -s "$tmp/seam.json" "$tmp/seam_stdout.json" || fail "--out FILE.json differs from --json"
grep -q '"turns":\[1\]' "$tmp/seam.json" || fail "the goal's turns are not [1] in --out JSON"
ls "$tmp" | grep -q 'seam\.csv\.\|seam\.json\.' && fail "temporary file left: $(ls "$tmp")"

# 4.71238898038469 is -π/2 + 2π to an ulp, on a face of the helix's subdivision after the
# shift; at 24 bits a test sure only of "inside" misses a window about 5e-7 wide.
cat > "$tmp/helix.robot" <<'M'
robot HELIX
pose    x in [-pi, pi] periodic
command q in [-10, 10]
equation sin(q/2 - x) = 0
M
for prec in 53 24; do
  "$aspects" solve "$tmp/helix.robot" --eps 0.3 --threads 1 --all-links --no-cert --quiet \
    --prec $prec --out "$tmp/helix$prec"
  for pose in 4.71238898038469 -1.5707963267948966 4.7123891 -4.712389; do
    expect 0 "^4 certified command\(s\)" "$aspects" query "$tmp/helix$prec" --pose=$pose
  done
  # ±π lies in the boxes at both ends of the root cell (which spans 2π and a few ulps):
  # the same commands for either sign, -2π, 0 and 2π, each listed once though boxes at
  # both ends hold it (issue 50, item 10: 8 listed at 53 bits, 6 at 24, before). 3π
  # rounded is 3.7e-16 below 3π: one turn down it is inside the end at π only, at 53 bits
  # (at 24 bits the root cell is 1e-7 wider): -2π, 0 (in two boxes) and 2π.
  counts=$(for pose in 3.141592653589793 -3.141592653589793; do
    "$aspects" query "$tmp/helix$prec" --pose=$pose | sed -n 's/^\([0-9]*\) certified.*/\1/p'
  done | sort -u)
  [ "$(echo "$counts" | wc -l)" -eq 1 ] && [ "$counts" -eq 3 ] ||
    fail "at +-pi ($prec bits): certified command counts '$counts'"
  want=3
  [ $prec = 53 ] || want='[0-9]+'
  expect 0 "^$want certified command\(s\)" "$aspects" query "$tmp/helix$prec" --pose=9.42477796076938
  expect 0 "^certified singularity-free path in CSNC 0" \
    "$aspects" path "$tmp/helix$prec" --from 4.71238898038469 --to 0.5
done
# 3-RPR at eps 4: x3 = -M_PI lies in box 19817 as x3 = M_PI does (-M_PI + 2π is within
# the root cell's rounding of π).
rpr=$(dirname "$0")/../robots/3rpr.robot
"$aspects" solve "$rpr" --eps 4 --threads 1 --no-cert --quiet --out "$tmp/rpr4"
for x3 in -3.141592653589793 3.141592653589793 9.42477796076938; do
  expect 0 "^  box 19817: q1 in" \
    "$aspects" query "$tmp/rpr4" --pose 27.410181655089485,10.585191937597198,$x3
done
echo ok
