# Sourced by the shell tests. expect CODE REGEX COMMAND...: runs COMMAND with its stdout and
# stderr in "$expect_log", and fails (the caller's `fail`) unless it exits with CODE and a
# line matches REGEX. The caller sets expect_log and defines fail.
expect() {
  code=$1 re=$2
  shift 2
  set +e
  "$@" > "$expect_log" 2>&1
  got=$?
  set -e
  [ "$got" -eq "$code" ] || { cat "$expect_log" >&2; fail "exit $got, expected $code: $*"; }
  grep -E -q -e "$re" "$expect_log" || { cat "$expect_log" >&2; fail "no /$re/: $*"; }
}
