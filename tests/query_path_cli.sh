#!/bin/sh
# `aspects query` and `aspects path` on damaged result directories (exit 2, a message
# naming the problem), `aspects path --plot` writing a PNG, and a periodic pose: a query
# modulo 2π and a path across the ±π seam through a certified link. $2: a result
# directory written by `aspects solve --out` for RRRRR (the query_fixture test); $3: the
# model tests/models/seam_pose.robot.
set -eu
aspects=$1
result=$2
seam_model=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "query_path_cli: $*" >&2; exit 1; }

# expect CODE REGEX COMMAND...: exit code and a line of stdout+stderr matching REGEX.
expect() {
  code=$1 re=$2
  shift 2
  set +e
  "$@" > "$tmp/out" 2>&1
  got=$?
  set -e
  [ "$got" -eq "$code" ] || { cat "$tmp/out" >&2; fail "exit $got, expected $code: $*"; }
  grep -E -q -e "$re" "$tmp/out" || { cat "$tmp/out" >&2; fail "no /$re/: $*"; }
}

mkdir "$tmp/truncated" "$tmp/version" "$tmp/garbage" "$tmp/empty"
head -c 1000 "$result/aspects.idx" > "$tmp/truncated/aspects.idx"
# Byte 14 (after the 14-byte magic) is the low byte of the version.
head -c 14 "$result/aspects.idx" > "$tmp/version/aspects.idx"
printf '\011' >> "$tmp/version/aspects.idx"
tail -c +16 "$result/aspects.idx" >> "$tmp/version/aspects.idx"
echo "id,status" > "$tmp/garbage/aspects.idx"

expect 2 "truncated/aspects.idx: malformed result index at byte [0-9]+: truncated" \
  "$aspects" query "$tmp/truncated" --pose 3,5
expect 2 "result index version 9, this aspects reads version 1" \
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
# Seam: -9.42 is 3.1464 modulo 2π; from 2.9 to -2.9 the short way is across ±π (length
# 2π - 5.8), through one link whose witness is ±π.
"$aspects" solve "$seam_model" --eps 0.1 --no-cert --quiet --out "$tmp/seam"
expect 0 "^CSNC 0  signs -,\\+$" "$aspects" query "$tmp/seam" --pose=-9.42
expect 0 "certified singularity-free path in CSNC 0: 3 waypoints, length 0\\.483185$" \
  "$aspects" path "$tmp/seam" --from 2.9 --to=-2.9
grep -E -q "^  witness \\(-?3\\.141592654\\)  box [0-9]+: q in \\[0\\.99999" "$tmp/out" ||
  { cat "$tmp/out" >&2; fail "no witness at the seam"; }
expect 1 "refused: .*different determinant signs" "$aspects" path "$tmp/seam" --from 2.5 --to=-2.9
echo ok
