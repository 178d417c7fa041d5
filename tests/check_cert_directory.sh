#!/bin/sh
# Usage: check_cert_directory.sh ASPECTS CHECK_CERT ROBOT_FILE
# check_cert given the directory `aspects solve --out DIR` wrote checks the certificate in
# it, compressed or not (it said "MALFORMED ... compressed data corrupt"); a directory with
# none, or both, says which file it wants (exit 2); a file it cannot open says why.
aspects=$1
check=$2
robot=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT HUP INT TERM
status=0
expect() {  # expect CODE REGEX -- COMMAND...
  code=$1 re=$2
  shift 3
  "$@" > "$work/out" 2>&1
  got=$?
  if [ "$got" -ne "$code" ] || ! grep -E -q -e "$re" "$work/out"; then
    echo "FAIL: $* exited $got (expected $code), output:" >&2
    cat "$work/out" >&2
    echo "(expected a line matching /$re/)" >&2
    status=1
  fi
}
"$aspects" solve --eps 0.1 --quiet --out "$work/text" "$robot" || exit 1
"$aspects" solve --eps 0.1 --quiet --compress-cert --out "$work/zst" "$robot" || exit 1
expect 0 '^check_cert: VERIFIED .* csncs=4 .*checked_lower_bound=4 robot="PRRP"$' -- "$check" --quiet "$work/text"
expect 0 '^check_cert: VERIFIED .* csncs=4 .*checked_lower_bound=4 robot="PRRP"$' -- "$check" --quiet "$work/zst/"
mkdir "$work/empty"
expect 2 "^check_cert: MALFORMED: $work/empty is a directory with no certificate in it \(aspects\.cert or aspects\.cert\.zst, as \`aspects solve --out DIR\` writes\): name the certificate file$" -- "$check" "$work/empty"
cp "$work/zst/aspects.cert.zst" "$work/text/"
expect 2 "^check_cert: MALFORMED: $work/text holds both aspects\.cert and aspects\.cert\.zst: name the one to check$" -- "$check" "$work/text"
expect 0 '^check_cert: VERIFIED ' -- "$check" --quiet "$work/text/aspects.cert.zst"
expect 2 "^check_cert: MALFORMED: cannot open $work/none\.cert: No such file or directory$" -- "$check" "$work/none.cert"
exit $status
