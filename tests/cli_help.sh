#!/bin/sh
# Usage: cli_help.sh ASPECTS ROBOT_FILE
# The command line as a newcomer meets it (issue 51): the short options -e, -o, -j act as
# their long forms; --help shows the real defaults (solve's --bisect comes from the model)
# and that plot writes PDF and SVG; an option error names the subcommand's --help, not the
# main command's. Exit 0 when every check holds, 1 otherwise (each failure said).
aspects=$1
robot=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT HUP INT TERM
status=0
fail() {
  echo "FAIL: $*" >&2
  status=1
}
has() {  # has FILE REGEX WHAT
  grep -E -q -e "$2" "$1" || { fail "$3: no line matches /$2/ in:"; cat "$1" >&2; }
}
lacks() {  # lacks FILE REGEX WHAT
  ! grep -E -q -e "$2" "$1" || { fail "$3: a line matches /$2/ in:"; cat "$1" >&2; }
}

"$aspects" solve --help > "$work/solve_help" 2>&1 || fail "solve --help: exit $?"
has "$work/solve_help" '^  -e,--eps FLOAT=0\.1 ' "solve -e"
has "$work/solve_help" '^  -o,--out ' "solve -o"
has "$work/solve_help" '^  -j,--threads INT=0 ' "solve -j"
# The model's `bisect` statement is the default: no fixed value may be shown.
has "$work/solve_help" '^  --bisect ' "solve --bisect"
lacks "$work/solve_help" '^  --bisect .*=' "solve --bisect shows a fixed default"

"$aspects" count --help > "$work/count_help" 2>&1 || fail "count --help: exit $?"
has "$work/count_help" '^  -e,--eps FLOAT=0\.5 ' "count -e"
has "$work/count_help" '^  -j,--threads INT=0 ' "count -j"
"$aspects" verify --help > "$work/verify_help" 2>&1 || fail "verify --help: exit $?"
has "$work/verify_help" '^  -j,--threads ' "verify -j"

"$aspects" plot --help > "$work/plot_help" 2>&1 || fail "plot --help: exit $?"
has "$work/plot_help" '^  -o,--out .*PNG, PDF or SVG' "plot --out names the formats"

# The short options act as the long ones: the summary records eps and threads.
"$aspects" solve -e 0.25 -j 1 -o "$work/out" --quiet "$robot" > "$work/solve_out" 2>&1 ||
  { fail "solve -e -j -o: exit $?"; cat "$work/solve_out" >&2; }
has "$work/out/summary.json" '"eps": 0\.25,' "-e 0.25 in summary.json"
has "$work/out/summary.json" '"threads": 1,' "-j 1 in summary.json"

# An option error inside a subcommand: that subcommand's --help, and the option meant.
"$aspects" solve --epsilon 1 > "$work/bad_option" 2>&1
code=$?
[ "$code" -eq 2 ] || fail "solve --epsilon: exit $code, expected 2"
has "$work/bad_option" "^\(run 'aspects solve --help' for usage\)$" "solve's --help"
lacks "$work/bad_option" "'aspects --help'" "the main --help"
has "$work/bad_option" '^did you mean --eps\?$' "the option meant"
"$aspects" count --eps abc > "$work/bad_value" 2>&1
code=$?
[ "$code" -eq 2 ] || fail "count --eps abc: exit $code, expected 2"
has "$work/bad_value" "^aspects: --eps: 'abc' is not a number$" "the bad value"
has "$work/bad_value" "^\(run 'aspects count --help' for usage\)$" "count's --help"
exit $status
