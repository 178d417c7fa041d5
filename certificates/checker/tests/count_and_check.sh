#!/bin/sh
# count_and_check.sh ASPECTS CHECK_CERT MODEL SECONDS WORKDIR [EXACT] — counts MODEL's
# aspects with a time limit (exit 0 or 3: a stopped count claims the bounds it reached) and
# requires check_cert to verify the count certificate, by its trusted core alone too. With
# EXACT, the count must be exact and equal to it, and check_cert must verify both bounds
# (checked_lower_bound=EXACT and upper_bound=EXACT). On RRRRR the count decides thousands of
# charts, points, pavings, star tests, joins and refutations on periodic commands.
set -u
aspects=$1 check=$2 model=$3 seconds=$4 work=$5 exact=${6:-}
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
if [ -n "$exact" ]; then
  line=$(head -n 1 "$work/count.txt")
  [ "$line" = "$exact aspects (certified: lower = upper)" ] ||
    { echo "FAIL: want the exact count $exact, got: $line"; exit 1; }
  case "$out" in *" checked_lower_bound=$exact "*) ;;
    *) echo "FAIL: check_cert's lower bound is not $exact"; exit 1 ;; esac
  case "$out" in *" upper_bound=$exact "*) ;;
    *) echo "FAIL: check_cert's upper bound is not $exact"; exit 1 ;; esac
fi
