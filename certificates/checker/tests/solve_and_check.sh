#!/bin/sh
# solve_and_check.sh ASPECTS CHECK_CERT MODEL EPS WORKDIR [PREC] — solves MODEL with the
# real solver (which writes WORKDIR/aspects.cert), at PREC bits (default 53), and requires
# check_cert to verify it.
# Prints both times so that the cost of checking can be compared with the cost of solving.
set -u
aspects=$1 check=$2 model=$3 eps=$4 work=$5 prec=${6:-53}
rm -rf "$work"
t0=$(date +%s.%N)
"$aspects" solve "$model" --eps "$eps" --prec "$prec" --out "$work" --quiet || { echo "FAIL: solver exited $?"; exit 1; }
t1=$(date +%s.%N)
[ -f "$work/aspects.cert" ] || { echo "FAIL: no certificate written"; exit 1; }
out=$("$check" --quiet "$work/aspects.cert")
code=$?
t2=$(date +%s.%N)
echo "$out"
echo "solve $(awk "BEGIN{print $t1 - $t0}") s, check $(awk "BEGIN{print $t2 - $t1}") s, certificate $(wc -c < "$work/aspects.cert") bytes"
[ "$code" = 0 ] || { echo "FAIL: check_cert exited $code"; exit 1; }
case "$out" in "check_cert: VERIFIED "*) exit 0 ;; *) echo "FAIL: no VERIFIED line"; exit 1 ;; esac
