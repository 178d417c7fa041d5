#!/bin/sh
# compressed.sh ASPECTS CHECK_CERT MODEL EPS WORKDIR — `aspects solve --compress-cert` writes
# WORKDIR/z/aspects.cert.zst, which check_cert must verify with the very text's SHA-256 of
# the plain certificate of the same run; a truncated copy and a copy with one byte changed
# must be MALFORMED (exit 2) with the reason that says so, never read as other text.
set -u
aspects=$1 check=$2 model=$3 eps=$4 work=$5
rm -rf "$work"
mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
"$aspects" solve "$model" --eps "$eps" --out "$work/plain" --quiet || fail "solver exited $?"
"$aspects" solve "$model" --eps "$eps" --out "$work/z" --quiet --compress-cert || fail "solver exited $?"
z=$work/z/aspects.cert.zst
[ -f "$z" ] || fail "no aspects.cert.zst"
[ -e "$work/z/aspects.cert" ] && fail "a plain certificate beside the compressed one"
plain_bytes=$(wc -c < "$work/plain/aspects.cert")
z_bytes=$(wc -c < "$z")
[ $((z_bytes * 2)) -lt "$plain_bytes" ] || fail "compressed $z_bytes bytes, plain $plain_bytes"
a=$("$check" --quiet "$work/plain/aspects.cert") || fail "plain: check_cert exited $?: $a"
b=$("$check" --quiet --threads 2 "$z") || fail "compressed: check_cert exited $?: $b"
case "$b" in "check_cert: VERIFIED "*) ;; *) fail "no VERIFIED line: $b" ;; esac
[ "$a" = "$b" ] || fail "different verdicts:
$a
$b"
echo "$b"
echo "plain $plain_bytes bytes, compressed $z_bytes bytes"

expect_malformed() {
  out=$("$check" --quiet "$1")
  code=$?
  [ "$code" = 2 ] || fail "$2: exit $code, not 2: $out"
  case "$out" in
    *MALFORMED*"compressed data corrupt or truncated"*) echo "$2: $out" ;;
    *) fail "$2: not the reason expected: $out" ;;
  esac
}
head -c $((z_bytes / 2)) "$z" > "$work/truncated.zst"
expect_malformed "$work/truncated.zst" truncated
head -c $((z_bytes - 1)) "$z" > "$work/last_byte.zst"
expect_malformed "$work/last_byte.zst" "without its last byte"
/usr/bin/python3 - "$z" "$work/flipped.zst" <<'PY'
import sys
data = bytearray(open(sys.argv[1], "rb").read())
data[len(data) // 2] ^= 0x10
open(sys.argv[2], "wb").write(data)
PY
expect_malformed "$work/flipped.zst" "one byte changed"
