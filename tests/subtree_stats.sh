#!/bin/sh
# `aspects solve --subtree-stats FILE --cut-depth CUT` observes only: the outputs are those
# of a plain run byte for byte; FILE has one top row, one row per depth above the cut (the
# top's boxes there) and one row per deferred subtree (the count is given: an exact value),
# tasks in order, each path of CUT digits, depth first
# (sorted, none a prefix of another); its nodes sum to summary.json's processed boxes and
# its output boxes to its total. With MPIRUN, the same under `mpirun -n 2`: the parts the
# other rank sent have their message bytes.
# Usage: subtree_stats.sh ASPECTS MODEL EPS CUT SUBTREES [MPIRUN]
#
# Seen failing on purpose, then restored: the top's nodes counted with its deferred leaves
# (its levels no longer sum to it); the paths built with the children swapped (not depth
# first).
set -eu
aspects=$1 model=$2 eps=$3 cut=$4 subtrees=$5 mpirun=${6:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "subtree_stats: $*" >&2; exit 1; }
"$aspects" solve "$model" --eps "$eps" --threads 2 --quiet --out "$work/plain" || fail "plain run exited $?"
run() {  # NAME [LAUNCHER...]
  name=$1; shift
  "$@" "$aspects" solve "$model" --eps "$eps" --threads 2 --quiet --out "$work/$name" \
    --cut-depth "$cut" --subtree-stats "$work/$name.csv" || fail "$name exited $?"
  for f in boxes.csv aspects.cert aspects.idx; do
    cmp "$work/plain/$f" "$work/$name/$f" || fail "$name: $f differs from the plain run's"
  done
  ls -a "$work" | grep -q "\.tmp\." && fail "$name: a temporary file is left: $(ls -a "$work")"
  /usr/bin/python3 - "$work/$name.csv" "$work/$name/summary.json" "$cut" "$subtrees" "$name" <<'PY' || fail "$name: $work/$name.csv"
import csv, json, sys
path, summary, cut, subtrees, name = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
rows = list(csv.reader(open(path)))
assert rows[0] == ["part", "task", "depth", "path", "nodes", "output_boxes", "cpu_seconds",
                   "wall_seconds", "part_bytes", "decode_seconds", "message_bytes",
                   "searched_by"], rows[0]
head = rows[0]
r = [dict(zip(head, x)) for x in rows[1:]]
assert [x["part"] for x in r] == ["top"] + ["level"] * cut + ["subtree"] * subtrees, (len(r), subtrees)
levels, sub = r[1:cut + 1], r[cut + 1:]
assert [int(x["depth"]) for x in levels] == list(range(cut))
for f in ["nodes", "output_boxes"]:  # the top, depth by depth
    assert sum(int(x[f]) for x in levels) == int(r[0][f]), f
assert int(levels[0]["nodes"]) == 1 and all(int(x["nodes"]) > 0 for x in levels)
r = [r[0]] + sub
assert [int(x["task"]) for x in sub] == list(range(subtrees))
paths = [x["path"] for x in sub]
assert all(len(p) == cut == int(x["depth"]) and set(p) <= set("01") for p, x in zip(paths, sub))
assert paths == sorted(paths) and len(set(paths)) == subtrees  # depth first, distinct
s = json.load(open(summary))
assert sum(int(x["nodes"]) for x in r) == s["boxes"]["processed"], (sum(int(x["nodes"]) for x in r), s["boxes"])
assert sum(int(x["output_boxes"]) for x in r) == s["boxes"]["total"]
assert all(int(x["part_bytes"]) > 0 and float(x["decode_seconds"]) >= 0 for x in r)
here = [x for x in r if x["searched_by"] == "here"]
remote = [x for x in r if x["searched_by"] == "remote"]
assert len(here) + len(remote) == len(r) and r[0]["searched_by"] == "here"
assert all(float(x["cpu_seconds"]) >= 0 and float(x["wall_seconds"]) >= 0 and x["message_bytes"] == "" for x in here)
# A message carries its part and the certificate records (kind, task, held, record count:
# 14 bytes; held records come later, counted here too).
assert all(x["cpu_seconds"] == "" and int(x["message_bytes"]) > int(x["part_bytes"]) + 14 for x in remote)
if name == "mpi":
    assert remote, "no part came from the other rank"
else:
    assert not remote
print(name, "ok:", len(sub), "subtrees,", len(remote), "from the other rank")
PY
}
run single
if [ -n "$mpirun" ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  mkdir "$work/ranktmp"
  TMPDIR="$work/ranktmp"
  export TMPDIR
  run mpi "$mpirun" --oversubscribe --bind-to none -n 2 -x TMPDIR -x OMPI_ALLOW_RUN_AS_ROOT \
    -x OMPI_ALLOW_RUN_AS_ROOT_CONFIRM
fi
echo "subtree_stats: ok"
