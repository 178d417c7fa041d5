#!/bin/sh
# Ctrl-C on `aspects solve` (issue 50, item 9), as SIGINT sent to a running solve once the
# search has begun (its first progress line; never a blind sleep):
#   once    the search stops, and the links, CSNCs and bound are made on the boxes it made
#           (before: "links: 0 certified", every solution box a CSNC); exit 3; the default
#           checkpoint (every 60 s, and when stopped) is written, and the exact command
#           that resumes it is printed, and resumes to a complete result (the checkpoint
#           then removed);
#   twice   the second stops the rest at once: exit 3, it says so, and how to resume;
#   off     --checkpoint 0: no checkpoint, and no resume command (it says why);
#   no_out  without --out: nothing to resume from, and it says why.
# Usage: solve_interrupt.sh ASPECTS ROBOTS_DIR
set -eu
aspects=$1
model=$2/rrrrr.robot  # eps 0.2: about 6 s of search on 2 threads
work=$(mktemp -d)
job=
trap '[ -n "$job" ] && kill -9 "$job" 2>/dev/null; rm -rf "$work"' EXIT
fail() { echo "solve_interrupt: $*" >&2; [ -f "$work/err" ] && cat "$work/err" >&2; exit 1; }

# wait_for PATTERN: until stderr shows it (10 s at most) while the run goes on.
wait_for() {
  i=0
  until grep -q "$1" "$work/err" 2>/dev/null; do
    kill -0 "$job" 2>/dev/null || fail "the run ended before \"$1\""
    i=$((i + 1))
    [ $i -le 200 ] || fail "no \"$1\" within 10 s"
    sleep 0.05
  done
}

# start DIR ARGS...: a solve in the background, its stdout and stderr in $work.
start() {
  : > "$work/err"  # here, not only in the child: wait_for must not read the last run's
  "$aspects" solve "$model" --eps 0.2 --threads 2 --progress "$@" > "$work/out" 2> "$work/err" &
  job=$!
  wait_for "^\[aspects\] [0-9]* boxes processed"  # the first progress line: the search has begun
}

finish() {
  status=0
  wait "$job" || status=$?
  job=
  [ "$status" = "$1" ] || fail "$2: exit $status, expected $1"
}

field() { sed -n "s/^$1//p" "$work/out"; }

# once
d=$work/once
start --out "$d"
kill -INT "$job"
finish 3 once
grep -q "interrupted: no more boxes are searched" "$work/err" || fail "once: no note"
links=$(field "links: [0-9]* neighbour pairs, " | sed 's/ certified//')
solutions=$(field "boxes: [0-9]* (" | sed 's/ solution.*//')
csncs=$(field "CSNCs: " | sed 's/,.*//')
[ "$links" -gt 0 ] || fail "once: $links certified links"
[ "$csncs" -lt "$solutions" ] || fail "once: $csncs CSNCs for $solutions solution boxes"
grep -q "unexplored" "$work/out" || fail "once: not a partial result"
[ -f "$d/checkpoint" ] || fail "once: no checkpoint"
# The interval the checkpoint records (layout: run/checkpoint.cpp): the default, 60 s.
interval=$(/usr/bin/python3 - "$d/checkpoint" <<'PY'
import struct, sys
b = open(sys.argv[1], "rb").read()
at = len(b"aspects-checkpoint 2\n")
def skip_str():
    global at
    (n,) = struct.unpack_from("<Q", b, at)
    at += 8 + n
for _ in range(4): skip_str()   # version, model_sha256, model_text, model_file
at += 8 + 8 + 8                 # eps, tau, precision
skip_str()                      # bisect
at += 3 + 4                     # all_links, no_cert, cert_format, defer_depth
print("%g" % struct.unpack_from("<d", b, at)[0])
PY
)
[ "$interval" = 60 ] || fail "once: the checkpoint's interval is $interval, not the default 60 s"
grep -qxF "aspects: to go on from its checkpoint: $aspects solve --resume $d" "$work/err" ||
  fail "once: no resume command"
/usr/bin/python3 -c "
import json, sys
s = json.load(open(sys.argv[1]))
assert s['complete'] is False and s['stopped_by'] == 'signal', s
" "$d/summary.json" || fail "once: summary.json"
# The command it printed, as printed.
eval "$aspects solve --resume $d --quiet --threads 2" > "$work/out" 2> "$work/err" ||
  fail "once: the resume command failed"
grep -q "unexplored" "$work/out" && fail "once: resumed, still partial"
[ ! -e "$d/checkpoint" ] || fail "once: the checkpoint left after the resumed run completed"

# twice: the second after the first's note (a signal sent before the first is handled
# would merge with it).
d=$work/twice
start --out "$d"
kill -INT "$job"
wait_for "interrupted: no more boxes"
kill -INT "$job"
finish 3 twice
grep -q "interrupted again: stopping now" "$work/err" || fail "twice: no second note"
grep -qxF "aspects: to go on from its checkpoint: $aspects solve --resume $d" "$work/err" ||
  fail "twice: no resume command"

# off
d=$work/off
start --out "$d" --checkpoint 0
kill -INT "$job"
finish 3 off
[ ! -e "$d/checkpoint" ] || fail "off: a checkpoint with --checkpoint 0"
grep -q "to go on from its checkpoint" "$work/err" && fail "off: a resume command without checkpoint"
grep -q "no checkpoint to resume from (checkpoints are off: --checkpoint 0)" "$work/err" ||
  fail "off: no reason"

# no_out
start
kill -INT "$job"
finish 3 no_out
grep -q "no checkpoint to resume from (without --out nothing is saved)" "$work/err" ||
  fail "no_out: no reason"
echo "solve_interrupt: ok"
