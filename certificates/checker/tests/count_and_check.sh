#!/bin/sh
# count_and_check.sh ASPECTS CHECK_CERT MODEL SECONDS WORKDIR — counts MODEL's aspects with
# a time limit (exit 0 or 3: a stopped count claims the bounds it reached) and requires
# check_cert to verify the count certificate, by its trusted core alone too. On RRRRR the
# count decides thousands of charts, points, pavings, star tests, joins and refutations on
# periodic commands before the limit stops it.
set -u
aspects=$1 check=$2 model=$3 seconds=$4 work=$5
rm -rf "$work" && mkdir -p "$work"
"$aspects" count "$model" --time-limit "$seconds" --cert "$work/count.ccert" > "$work/count.txt"
code=$?
head -n 1 "$work/count.txt"
[ "$code" = 0 ] || [ "$code" = 3 ] || { echo "FAIL: aspects count exited $code"; exit 1; }
out=$("$check" --quiet "$work/count.ccert")
code=$?
echo "$out"
[ "$code" = 0 ] || { echo "FAIL: check_cert exited $code"; exit 1; }
case "$out" in "check_cert: VERIFIED "*) ;; *) echo "FAIL: no VERIFIED line"; exit 1 ;; esac
trusted=$("$check" --quiet --trusted-only "$work/count.ccert")
[ "$trusted" = "$out" ] || { echo "FAIL: --trusted-only says $trusted"; exit 1; }
