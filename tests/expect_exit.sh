#!/bin/sh
# Usage: expect_exit.sh EXPECTED_CODE REGEX [REGEX...] -- COMMAND [ARGS...]
# Runs COMMAND, then checks that its exit code is EXPECTED_CODE and that its combined
# stdout+stderr matches every extended REGEX (grep -E, any line). Prints what it got on
# failure. Exit status: 0 pass, 1 fail, 2 bad usage.
if [ $# -lt 4 ]; then
  echo "usage: $0 EXPECTED_CODE REGEX [REGEX...] -- COMMAND [ARGS...]" >&2
  exit 2
fi
expected=$1
shift
case $expected in
  '' | *[!0-9]*) echo "$0: EXPECTED_CODE must be a number, got '$expected'" >&2; exit 2 ;;
esac

# Collect the regexes (up to --) as positional data in a temp file: POSIX sh has no arrays.
tmp=${TMPDIR:-/tmp}/expect_exit.$$
trap 'rm -f "$tmp.re" "$tmp.out"' EXIT HUP INT TERM
: > "$tmp.re"
found_sep=0
while [ $# -gt 0 ]; do
  if [ "$1" = "--" ]; then
    found_sep=1
    shift
    break
  fi
  printf '%s\n' "$1" >> "$tmp.re"
  shift
done
if [ $found_sep -ne 1 ] || [ $# -eq 0 ] || [ ! -s "$tmp.re" ]; then
  echo "usage: $0 EXPECTED_CODE REGEX [REGEX...] -- COMMAND [ARGS...]" >&2
  exit 2
fi

"$@" > "$tmp.out" 2>&1
code=$?

status=0
if [ "$code" -ne "$expected" ]; then
  echo "FAIL: exit code $code, expected $expected" >&2
  status=1
fi
while IFS= read -r re; do
  if ! grep -E -q -e "$re" "$tmp.out"; then
    echo "FAIL: output does not match /$re/" >&2
    status=1
  fi
done < "$tmp.re"

if [ $status -ne 0 ]; then
  echo "---- command:" >&2
  printf ' %s' "$@" >&2
  echo >&2
  echo "---- output (stdout+stderr):" >&2
  cat "$tmp.out" >&2
  echo "---- end of output" >&2
fi
exit $status
