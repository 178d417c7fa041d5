#!/bin/sh
# solve_and_check.sh ASPECTS CHECK_CERT MODEL EPS WORKDIR [PREC [FORMAT]] — solves MODEL
# with the real solver (which writes WORKDIR/aspects.cert), at PREC bits (default 53), in
# certificate format FORMAT (default 2), and requires check_cert to verify it. In format 3
# it also requires the trusted core alone (--trusted-only) to verify it, and --print to
# print one line per record with every end decoded.
# Prints both times so that the cost of checking can be compared with the cost of solving.
set -u
aspects=$1 check=$2 model=$3 eps=$4 work=$5 prec=${6:-53} format=${7:-2}
rm -rf "$work"
t0=$(date +%s.%N)
"$aspects" solve "$model" --eps "$eps" --prec "$prec" --out "$work" --quiet --cert-format "$format" ||
  { echo "FAIL: solver exited $?"; exit 1; }
t1=$(date +%s.%N)
[ -f "$work/aspects.cert" ] || { echo "FAIL: no certificate written"; exit 1; }
out=$("$check" --quiet "$work/aspects.cert")
code=$?
t2=$(date +%s.%N)
echo "$out"
echo "solve $(awk "BEGIN{print $t1 - $t0}") s, check $(awk "BEGIN{print $t2 - $t1}") s, certificate $(wc -c < "$work/aspects.cert") bytes"
[ "$code" = 0 ] || { echo "FAIL: check_cert exited $code"; exit 1; }
case "$out" in "check_cert: VERIFIED "*) ;; *) echo "FAIL: no VERIFIED line"; exit 1 ;; esac
[ "$format" = 3 ] || exit 0
head -c 22 "$work/aspects.cert" | grep -q "^aspects-certificate 3" || { echo "FAIL: not format 3"; exit 1; }
trusted=$("$check" --quiet --trusted-only "$work/aspects.cert")
[ "$trusted" = "$out" ] || { echo "FAIL: --trusted-only says $trusted"; exit 1; }
"$check" --quiet --print "$work/aspects.cert" > "$work/printed.txt" || { echo "FAIL: --print"; exit 1; }
# `end N` counts the lines before it (the model text's too); then comes the verdict line.
records=$(tail -n 2 "$work/printed.txt" | head -n 1 | sed -n 's/^end //p')
lines=$(wc -l < "$work/printed.txt")
[ -n "$records" ] && [ "$lines" = $((records + 2)) ] ||
  { echo "FAIL: --print gave $lines lines for $records records"; exit 1; }
grep -q '?' "$work/printed.txt" && { echo "FAIL: --print left an end undecoded"; exit 1; }
exit 0
