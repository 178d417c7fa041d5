#!/bin/sh
# Usage: man_page.sh MAN_DIR ASPECTS
# The man pages the build made with help2man (cmake/man_pages.cmake): aspects.1 has a
# section for every subcommand `aspects --help` lists, with its options; check_cert.1 its
# options. Fails when they were not made (help2man is on README.md's install line).
man=$1
aspects=$2
status=0
fail() {
  echo "FAIL: $*" >&2
  status=1
}
for page in aspects.1 check_cert.1; do
  [ -s "$man/$page" ] || { echo "FAIL: $man/$page was not made (is help2man installed?)" >&2; exit 1; }
done
grep -q '^\.TH ASPECTS "1"' "$man/aspects.1" || fail "aspects.1 has no .TH ASPECTS 1 header"
subs=$("$aspects" --help | sed -n '/^Subcommands:/,$p' | sed -n 's/^  \([a-z][a-z_-]*\)  .*/\1/p')
[ "$(echo $subs)" = "info solve query path plot view export count verify" ] ||
  fail "aspects --help lists the subcommands '$(echo $subs)'"
for sub in $subs; do
  grep -q "^\.SS \"aspects $sub\"\$" "$man/aspects.1" || fail "aspects.1 has no section for $sub"
done
grep -q '^  \\-e,\\-\\-eps FLOAT=0\.1 ' "$man/aspects.1" || fail "aspects.1 lacks solve's -e,--eps"
grep -q 'check_cert(1)' "$man/aspects.1" || fail "aspects.1 does not refer to check_cert(1)"
grep -q '^\.TH CHECK_CERT "1"' "$man/check_cert.1" || fail "check_cert.1 has no .TH header"
grep -q 'threads' "$man/check_cert.1" || fail "check_cert.1 lacks --threads"
exit $status
