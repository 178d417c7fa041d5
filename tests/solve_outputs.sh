#!/bin/sh
# `aspects solve MODEL --out DIR` writes summary.json, boxes.csv and aspects.cert with the
# documented fields, and leaves no temporary file behind.
set -eu
aspects=$1
model=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$aspects" solve "$model" --eps 0.1 --out "$out" --quiet
fail() { echo "solve_outputs: $*" >&2; exit 1; }
[ -f "$out/summary.json" ] || fail "no summary.json"
[ -f "$out/boxes.csv" ] || fail "no boxes.csv"
[ -f "$out/aspects.cert" ] || fail "no aspects.cert"
ls -a "$out" | grep -q tmp && fail "temporary file left: $(ls -a "$out")"
/usr/bin/python3 - "$out" <<'PY'
import csv, json, sys
d = sys.argv[1]
s = json.load(open(d + "/summary.json"))
for k in ["robot", "eps", "precision_bits", "tau", "time_seconds"]:
    assert k in s, k
for k in ["total", "solution", "undecided"]:
    assert k in s["boxes"], k
for k in ["neighbor", "certified"]:
    assert k in s["links"], k
for k in ["count", "filtered", "separated_lower_bound", "sizes"]:
    assert k in s["csncs"], k
assert s["robot"] == "PRRP" and s["csncs"]["filtered"] == 4 and s["csncs"]["separated_lower_bound"] == 4
assert s["factors"][0]["origin"] == "det Fx", s["factors"]
# The bound is the sum of its classes' components, each class a sign per factor.
cls = s["csncs"]["separated_classes"]
assert sum(c["components"] for c in cls) == 4 and all(c["components"] > 0 for c in cls), cls
assert all(len(c["signs"]) == len(s["factors"]) and set(c["signs"]) <= set("+-") for c in cls), cls
assert len({c["signs"] for c in cls}) == len(cls), cls
# Phases: each with its time and the peak memory at its end, which only grows, up to the
# run's peak; the outputs come last.
names = [ph["name"] for ph in s["phases"]]
assert names[0] == "search" and names[-1] == "outputs" and sorted(names) == sorted(s["phase_seconds"]), s
assert all(ph["seconds"] == s["phase_seconds"][ph["name"]] for ph in s["phases"]), s
peaks = [ph["peak_memory_mib"] for ph in s["phases"]]
assert 0 < peaks[0] and peaks == sorted(peaks) and peaks[-1] <= s["peak_memory_mib"], s
# PRRP has one command per pose and one pose per command in each aspect: no witness.
c = s["cuspidal"]
assert (c["witnesses"], c["assembly_witnesses"], c["csncs_assembly_search_capped"]) == (0, 0, 0), c
assert c["per_csnc"] == [], c
rows = list(csv.reader(open(d + "/boxes.csv")))
assert rows[0] == ["id", "status", "csnc", "kept", "x_lo", "x_hi", "q_lo", "q_hi", "boundary"], rows[0]
body = rows[1:]
assert len(body) == s["boxes"]["total"]
sol = [r for r in body if r[1] == "solution"]
assert len(sol) == s["boxes"]["solution"]
assert all(int(r[2]) >= 0 and r[3] == "1" and r[8] == "" for r in sol)
assert all(r[2] == "-1" and r[8] == "singular" for r in body if r[1] == "undecided")
# Endpoints round-trip exactly: repr(float(text)) parses back to the same double.
for r in body:
    for t in r[4:8]:
        assert float(t) == float(repr(float(t)))
    assert float(r[4]) <= float(r[5]) and float(r[6]) <= float(r[7])
print("ok")
PY
