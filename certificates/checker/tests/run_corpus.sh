#!/bin/sh
# run_corpus.sh CHECK_CERT TESTS_DIR — the golden corpus: every certificate in valid/ must
# exit 0 with a VERIFIED line whose sha256(cert) is the file's SHA-256, every one in
# invalid/ must exit 1 (REJECTED) and every one in malformed/ must exit 2 (MALFORMED), with
# the same line with --trusted-only.
bin=$1
dir=$2
fail=0
count=0
for pair in valid:0:VERIFIED invalid:1:REJECTED malformed:2:MALFORMED; do
  sub=${pair%%:*}
  rest=${pair#*:}
  want=${rest%%:*}
  word=${rest#*:}
  for f in "$dir/$sub"/*.cert; do
    [ -e "$f" ] || continue
    count=$((count + 1))
    out=$("$bin" --quiet "$f")
    got=$?
    # The trusted core alone gives the same line and exit status as with the speed layer.
    core=$("$bin" --quiet --trusted-only "$f")
    [ "$?" = "$got" ] && [ "$core" = "$out" ] || out="--trusted-only differs: $core"
    case "$out" in "check_cert: $word "*) ok=1 ;; *) ok=0 ;; esac
    if [ "$got" = 0 ]; then
      sum=$(sha256sum "$f" | cut -d' ' -f1)
      case "$out" in *"sha256(cert)=$sum "*) ;; *) ok=0 ;; esac
    fi
    if [ "$got" != "$want" ] || [ "$ok" != 1 ]; then
      echo "FAIL $f: exit $got (expected $want): $out"
      fail=1
    else
      echo "ok   $sub/$(basename "$f"): $out"
    fi
  done
done
if [ "$count" -lt 10 ]; then
  echo "FAIL: only $count certificates found under $dir"
  exit 1
fi
exit $fail
