#!/bin/sh
# compressed.sh ASPECTS CHECK_CERT MODEL EPS WORKDIR — `aspects solve --compress-cert` writes
# WORKDIR/z/aspects.cert.zst, which check_cert must verify with the very text's SHA-256 of
# the plain certificate of the same run; a truncated copy and a copy with a checksum byte
# changed must be MALFORMED (exit 2) with the reason that says so, and no damaged copy may
# be VERIFIED.
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
# A byte of the checksum (the frame's last 4): the text is intact, the file is not.
# A byte in the middle: the text changes before the checksum is reached, so the check may
# reject a claim first (exit 1) or find the damage (exit 2), but never verify it.
/usr/bin/python3 - "$z" "$work" <<'PY'
import sys
data = open(sys.argv[1], "rb").read()
for name, at in (("checksum", len(data) - 2), ("middle", len(data) // 2)):
    d = bytearray(data)
    d[at] ^= 0x10
    open("%s/%s.zst" % (sys.argv[2], name), "wb").write(d)
PY
expect_malformed "$work/checksum.zst" "a checksum byte changed"
out=$("$check" --quiet "$work/middle.zst")
code=$?
case "$code" in
  1 | 2) echo "a middle byte changed: $out" ;;
  *) fail "a middle byte changed: exit $code: $out" ;;
esac
