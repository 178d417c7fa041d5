#!/bin/sh
# `aspects path` through the pieces of a count (`aspects count --out DIR`, planning/piece_path.h):
# - the bow tie with a neck (3 aspects): (-0.5, 0) and (0.5, 0) lie in two CSNCs of the solve
#   (the neck, 0.02 wide, is not resolved at its eps), so the CSNC path finds none; through
#   the count's pieces the path succeeds, crossing at least 2 pieces;
# - a pose of another aspect of the same class, and one of another class: refused (exit 1);
# - the seam model: the path of class ++ crosses q = ±π, its goal unwrapped by −1 turn;
# - a pose on a singular curve: in no piece; RPRPR: a path across a bridge;
# - bad input: exit 2 with a message naming the problem.
# $1: aspects; $2: tests/models; $3: robots.
set -eu
aspects=$1
models=$2
robots=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "count_path_cli: $*" >&2; exit 1; }

# expect CODE REGEX COMMAND...: exit code and a line of stdout+stderr (in $tmp/out) matching
# REGEX.
expect_log=$tmp/out
. "$(dirname "$0")/expect_output.sh"

bow=$models/count_bow_tie_neck.robot
expect 0 "^3 aspects \(certified: lower = upper\)" "$aspects" count "$bow" --out "$tmp/bow"
[ -f "$tmp/bow/count.pieces" ] && [ -f "$tmp/bow/summary.json" ] || fail "count --out wrote no files"
ls "$tmp/bow" | grep -v -E '^(count\.pieces|summary\.json)$' && fail "a temporary left in the count directory"
"$aspects" solve "$bow" --out "$tmp/bow_solve" --no-cert --quiet || fail "solve failed"

# Two CSNCs of the solve...
expect 1 "no CSNC holds both poses.*start lies in CSNC [0-9]+ \(signs \+\); the goal in CSNC [0-9]+ \(signs \+\)" \
  "$aspects" path "$tmp/bow_solve" --from -0.5,0 --to 0.5,0
# ...one aspect, through the count's pieces.
expect 0 "^certified singularity-free path through [0-9]+ pieces of class \+ \(one aspect\): [0-9]+ waypoints, [0-9]+ segments \([0-9]+ join points, 0 bridges\); each segment is straight in the u-coordinates of its box's chart, not in pose space$" \
  "$aspects" path "$tmp/bow" --from -0.5,0 --to 0.5,0
pieces=$(sed -n 's/^certified singularity-free path through \([0-9]*\) pieces.*/\1/p' "$tmp/out")
[ "$pieces" -ge 2 ] || fail "the path crosses $pieces piece(s), expected at least 2"
# The JSON: starts and ends at the poses, every segment's piece a box of the count, the
# waypoints' x1 going from -0.5 to 0.5 through the neck (|x2| < 0.01 at x1 = 0).
"$aspects" path "$tmp/bow" --from -0.5,0 --to 0.5,0 --json > "$tmp/bow.json" ||
  { cat "$tmp"/*.json >&2; fail "path --json failed"; }
python3 - "$tmp/bow.json" <<'PY' || fail "bad path JSON"
import json, sys
d = json.load(open(sys.argv[1]))
w = d["waypoints"]
assert d["outcome"] == "found" and d["class"] == "+", d["outcome"]
assert w[0]["kind"] == "start" and w[-1]["kind"] == "goal"
assert w[0]["config"][:2] == [-0.5, 0.0] and w[-1]["config"][:2] == [0.5, 0.0]
assert len(d["segments"]) == len(w) - 1 and d["pieces"] >= 2
assert len({s["box"] for s in d["segments"]}) == d["pieces"]
for s in d["segments"]:
    assert s["how"] in ("graph", "star") and len(s["straight_in"]) == 2
# every star segment has the piece's centre at one end
for k, s in enumerate(d["segments"]):
    if s["how"] == "star":
        assert "centre" in (w[k]["kind"], w[k + 1]["kind"]), k
# crossing x1 = 0 happens inside the neck
for a, b in zip(w, w[1:]):
    if a["config"][0] <= 0 <= b["config"][0]:
        assert abs(a["config"][1]) < 0.011 and abs(b["config"][1]) < 0.011, (a, b)
PY

# The top and bottom aspects: one class, two aspects (the count is exact): refused.
expect 1 "^refused: the configurations found lie in different aspects: the start's configurations found are of class -, the goal's of class -, and the count is exact" \
  "$aspects" path "$tmp/bow" --from 0,0.9 --to 0,-0.9
# The top aspect and the middle one: different classes: refused.
expect 1 "^refused: the start's configurations found are of class -, the goal's of class \+; configurations of different classes lie in different aspects" \
  "$aspects" path "$tmp/bow" --from 0,0.9 --to 0.5,0
expect 1 "^no path in the class asked for: the start's configurations found are of class \+" \
  "$aspects" path "$tmp/bow" --from -0.5,0 --to 0.5,0 --class -
expect 0 "^certified singularity-free path through [0-9]+ pieces of class \+" \
  "$aspects" path "$tmp/bow" --from -0.5,0 --to 0.5,0 --class +

# The seam: class ++ (cos q < 0) runs across q = ±π; its goal is reached one turn down in q.
seam=$models/count_seam.robot
expect 0 "^2 aspects" "$aspects" count "$seam" --out "$tmp/seam"
expect 0 "other classes holding both poses \(other working modes\): \+\+ \(use --class\)" \
  "$aspects" path "$tmp/seam" --from -0.9 --to 0.9
"$aspects" path "$tmp/seam" --from -0.9 --to 0.9 --class ++ --json > "$tmp/seam.json" ||
  { cat "$tmp"/*.json >&2; fail "path --json failed"; }
python3 - "$tmp/seam.json" <<'PY' || fail "bad seam path JSON"
import json, math, sys
d = json.load(open(sys.argv[1]))
w = d["waypoints"]
assert d["outcome"] == "found" and d["class"] == "++"
assert w[-1]["turns"] == [0, -1], w[-1]["turns"]
q = [x["config"][1] for x in w]
# unwrapped: q decreases through -pi, no jump of 2*pi between waypoints
assert all(abs(b - a) < 1 for a, b in zip(q, q[1:])), q
assert q[0] > -math.pi > q[-1], q
assert abs(q[-1] - (math.pi - math.asin(0.6) - 2 * math.pi)) < 1e-9, q[-1]
PY

# A pose on the singular curve x2 = sqrt(x1^2 + 0.0001) of the bow tie: no class.
expect 1 "^no path: no configuration of the start pose was proved in a piece the count proved connected \([0-9]+ of its boxes with such pieces hold the pose\)$" \
  "$aspects" path "$tmp/bow" --from 0,0.01 --to 0.5,0

# RPRPR: a path; a bridge it crosses (a chart on two boxes' hull, no point in both) is a
# segment straight in the bridge chart's u, here the commands. (Since the count's boxes
# overlap a little, joins by a point have room and this path crosses no bridge: RPRPR's
# count has one bridge left, between cells 302 and 307, which no path found here uses.)
expect 0 "^2 aspects" "$aspects" count "$robots/rprpr.robot" --out "$tmp/rprpr"
"$aspects" path "$tmp/rprpr" --from 2.2,-4.8 --to 2.6,-5.2 --json > "$tmp/rprpr.json" ||
  { cat "$tmp"/*.json >&2; fail "path --json failed"; }
python3 - "$tmp/rprpr.json" <<'PY' || fail "bad bridge path JSON"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["outcome"] == "found", (d["outcome"], d.get("bridges"))
b = [s for s in d["segments"] if s["how"] == "bridge"]
assert len(b) == d["bridges"] and all(s["straight_in"] == ["q1", "q2"] for s in b), b
PY

# Bad input: exit 2, the problem named.
expect 2 "^aspects: RESULT_DIR $tmp/none: no such directory" \
  "$aspects" path "$tmp/none" --from -0.5,0 --to 0.5,0
expect 2 "^aspects: --class needs a count directory \(written by \`aspects count MODEL --out DIR\`\); $tmp/bow_solve is not one" \
  "$aspects" path "$tmp/bow_solve" --from -0.5,0 --to 0.5,0 --class +
expect 2 "^aspects: --from" "$aspects" path "$tmp/bow" --from -0.5 --to 0.5,0
expect 2 "^aspects: --to" "$aspects" path "$tmp/bow" --from -0.5,0 --to 0.5,0,1
expect 2 "^aspects: --class must be 1 signs, each \+ or -" \
  "$aspects" path "$tmp/bow" --from -0.5,0 --to 0.5,0 --class +-
expect 2 "^aspects: --csnc: .* is a count directory" \
  "$aspects" path "$tmp/bow" --from -0.5,0 --to 0.5,0 --csnc 0
expect 2 "^aspects: --out: not available for a path through a count's pieces" \
  "$aspects" path "$tmp/bow" --from -0.5,0 --to 0.5,0 --out "$tmp/p.csv"
expect 2 "^aspects: --out: '$tmp/bow_solve' holds a solve's result" \
  "$aspects" count "$bow" --out "$tmp/bow_solve"
expect 2 "^aspects: --out: '$tmp/bow/count.pieces' exists and is not a directory" \
  "$aspects" count "$bow" --out "$tmp/bow/count.pieces"
# A damaged pieces file: refused by its checksum, or as truncated.
mkdir "$tmp/edited" "$tmp/truncated"
cp "$tmp/bow/count.pieces" "$tmp/edited/"
printf 'X' | dd of="$tmp/edited/count.pieces" bs=1 seek=300 conv=notrunc 2>/dev/null
expect 2 "count.pieces: the count pieces file does not match its checksum" \
  "$aspects" path "$tmp/edited" --from -0.5,0 --to 0.5,0
head -c 1000 "$tmp/bow/count.pieces" > "$tmp/truncated/count.pieces"
expect 2 "count.pieces: malformed count pieces file at byte [0-9]+: truncated" \
  "$aspects" path "$tmp/truncated" --from -0.5,0 --to 0.5,0
echo "count_path_cli: ok"
