#!/bin/sh
# `aspects solve MODEL --out DIR` writes summary.json, boxes.csv and aspects.cert with the
# documented fields, and leaves no temporary file behind. Then (issue 50) the directory
# holds one run's files: a run removes the outputs it does not rewrite, two runs cannot
# write it at once, its files record the hashes that tie them, which query refuses when
# they differ, and `aspects verify` checks. $3: check_cert.
set -eu
aspects=$1
model=$2
check_cert=$3
out=$(mktemp -d)
holder=
trap 'if [ -n "$holder" ]; then kill "$holder" 2>/dev/null || true; fi; rm -rf "$out"' EXIT
fail() { echo "solve_outputs: $*" >&2; exit 1; }
# The number of aspects comes first, right after the run's settings, as a lower bound.
"$aspects" solve "$model" --eps 0.1 --no-cert | sed -n 2p | grep -qx \
  'aspects: at least 4 (certified lower bound; no upper bound: `aspects count` seeks one)' ||
  fail "the count line is not the second line of solve's report"
"$aspects" solve "$model" --eps 0.1 --out "$out" --quiet
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
assert s["lower_bound"] == 4 and s["upper_bound"] is None and s["exact"] is False, s
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
PY

# expect CODE REGEX COMMAND...: exit code and a line of stdout+stderr matching REGEX.
expect_log=$out/log
. "$(dirname "$0")/expect_output.sh"
files() { ls -A "$1" | tr '\n' ' '; }

# The hashes: summary.json's are check_cert's sha256(cert) and sha256(model), and the
# index file's sha256sum; the index records the certificate's.
"$check_cert" --json "$out/aspects.cert" > "$out/verdict.json" 2>/dev/null
/usr/bin/python3 - "$out" "$model" <<'PY'
import hashlib, json, sys
d, model = sys.argv[1], sys.argv[2]
s = json.load(open(d + "/summary.json"))
v = json.load(open(d + "/verdict.json"))
idx = open(d + "/aspects.idx", "rb").read()
assert s["certificate"] == "aspects.cert", s["certificate"]
assert s["certificate_sha256"] == v["sha256_cert"], (s["certificate_sha256"], v["sha256_cert"])
assert s["model_sha256"] == v["sha256_model"] == hashlib.sha256(open(model, "rb").read()).hexdigest()
assert s["index_sha256"] == hashlib.sha256(idx).hexdigest()
assert v["sha256_cert"].encode() in idx and b"aspects.cert" in idx
# The last 32 bytes are the SHA-256 of all before them.
assert idx[-32:] == hashlib.sha256(idx[:-32]).digest()
PY
ASPECTS_CHECK_CERT=$check_cert
export ASPECTS_CHECK_CERT
expect 0 "^VERIFIED: check_cert verified the certificate; the index and the summary are tied" \
  "$aspects" verify "$out"
grep -q "^aspects.idx       matches: records this certificate's sha256" "$out/log" || fail "verify: index"
grep -q "^summary.json      matches: records this certificate's sha256" "$out/log" || fail "verify: summary"

# A run removes the outputs it does not rewrite (issue 50, item 3: the certificate of the
# run before stayed and was verified as this one's). RRRRR, then PRRP --no-cert.
rrrrr="$out/rrrrr"
"$aspects" solve --eps 1 --threads 2 --quiet --out "$rrrrr"
"$aspects" solve "$model" --eps 0.1 --no-cert --quiet --out "$rrrrr"
[ "$(files "$rrrrr")" = ".lock aspects.idx boxes.csv summary.json " ] ||
  fail "after --no-cert: $(files "$rrrrr")"
expect 2 "the result has no certificate \(solved with --no-cert\): nothing for check_cert" \
  "$aspects" verify "$rrrrr"
expect 1 "note: this result has no certificate \(solved with --no-cert\)" \
  "$aspects" query "$rrrrr" --pose 1
# --compress-cert after a plain certificate: only the .zst.
"$aspects" solve "$model" --eps 0.1 --quiet --out "$rrrrr"
"$aspects" solve "$model" --eps 0.1 --compress-cert --quiet --out "$rrrrr"
[ "$(files "$rrrrr")" = ".lock aspects.cert.zst aspects.idx boxes.csv summary.json " ] ||
  fail "after --compress-cert: $(files "$rrrrr")"
expect 0 "^VERIFIED" "$aspects" verify "$rrrrr"
# --resume ... --compress-cert of a run stopped with a plain certificate: only the .zst.
stopped="$out/stopped"
expect 3 "stopped by max-boxes" \
  "$aspects" solve --eps 0.5 --threads 2 --max-boxes 2000 --checkpoint 1000 --quiet --out "$stopped"
[ -f "$stopped/aspects.cert" ] && [ -f "$stopped/checkpoint" ] || fail "stopped: $(files "$stopped")"
"$aspects" solve --resume "$stopped" --compress-cert --quiet
[ "$(files "$stopped")" = ".lock aspects.cert.zst aspects.idx boxes.csv summary.json " ] ||
  fail "after --resume --compress-cert: $(files "$stopped")"
expect 0 "^VERIFIED" "$aspects" verify "$stopped"

# Files of two runs (issue 50, item 4's mixture): query and verify refuse them.
cp "$rrrrr/summary.json" "$out/summary.json"
expect 2 "summary.json: not of the run that wrote aspects.idx: its index_sha256 is [0-9a-f]{16}, the index's [0-9a-f]{16} \(files of two runs; solve again\)" \
  "$aspects" query "$out" --pose 1
expect 1 "^NOT VERIFIED: a file of the directory does not match the certificate" \
  "$aspects" verify "$out"
# (The same model and eps there: the same certificate, whose hash is that of its text,
# compressed or not; the index names the .zst.)
grep -q '^  index_sha256 "[0-9a-f]*", aspects.idx.s "[0-9a-f]*"$' "$out/log" ||
  { cat "$out/log" >&2; fail "verify: no index_sha256 mismatch"; }
cp "$stopped/aspects.cert.zst" "$out/"
expect 2 "/aspects.cert.zst: a certificate of another run: aspects.idx records aspects.cert \(remove it, or solve again\)" \
  "$aspects" path "$out" --from 1 --to 2
rm "$out/aspects.cert.zst"
# A file under the certificate's name that is none.
mv "$out/aspects.cert" "$out/saved.cert"
echo "not a certificate" > "$out/aspects.cert"
expect 2 "/aspects.cert: no model line could be read \(unreadable, or not a certificate\)$" \
  "$aspects" query "$out" --pose 1
mv "$out/saved.cert" "$out/aspects.cert"
# The summary's bound edited: verify compares it with the certificate's.
"$aspects" solve "$model" --eps 0.1 --quiet --out "$out"
sed 's/"separated_lower_bound": 4/"separated_lower_bound": 5/' "$out/summary.json" > "$out/s" &&
  mv "$out/s" "$out/summary.json"
expect 1 "^  separated_lower_bound 5, the certificate's 4$" "$aspects" verify "$out"
# A certificate check_cert rejects: verify says so, exit 1.
"$aspects" solve "$model" --eps 0.1 --quiet --out "$out"
sed 's/^claim lower-bound 4$/claim lower-bound 5/' "$out/aspects.cert" > "$out/c" &&
  mv "$out/c" "$out/aspects.cert"
expect 1 "^aspects.cert      check_cert REJECTED: claimed lower bound 5 exceeds the recomputed 4$" \
  "$aspects" verify "$out"
grep -q "^NOT VERIFIED: check_cert did not accept the certificate$" "$out/log" || fail "verify: rejected"
# The first solution box's signs flipped in the index (issue 50, item 5: query printed
# them as certified): its checksum refuses it. Layout: results/result_index.cpp.
"$aspects" solve "$model" --eps 0.1 --quiet --out "$out"
/usr/bin/python3 - "$out/aspects.idx" <<'PY'
import struct, sys
b = bytearray(open(sys.argv[1], "rb").read())
nv, n, p = struct.unpack_from("<III", b, 18)
at = 14 + 4 + 12 + 24
def skip_str(at):
    return at + 4 + struct.unpack_from("<I", b, at)[0]
for _ in range(2 + 2 * p):  # model file, model text, each factor's origin and text
    at = skip_str(at)
at += 8 + 4 + 8 + 16 * nv  # CSNC counts, S; the first box's id, CSNC and ends
assert all(b[at + k] in (1, 255) for k in range(p)), b[at:at + p]
for k in range(p):
    b[at + k] = (256 - b[at + k]) % 256  # +1 <-> -1
open(sys.argv[1], "wb").write(b)
PY
expect 2 "aspects.idx: the result index does not match its checksum: damaged or edited" \
  "$aspects" query "$out" --pose 1
expect 1 "^NOT VERIFIED: the index cannot be trusted" "$aspects" verify "$out"

# Two runs on one directory (issue 50, item 4): the second is refused at once, naming it;
# so is a resumed run. The lock is held here by another process, as a run holds it.
lockdir="$out/locked"
mkdir "$lockdir"
/usr/bin/python3 -c 'import fcntl, sys, time
f = open(sys.argv[1], "w"); fcntl.flock(f, fcntl.LOCK_EX); print("held", flush=True); time.sleep(60)' \
  "$lockdir/.lock" > "$out/held" &
holder=$!
i=0
until grep -q held "$out/held"; do i=$((i + 1)); [ $i -lt 100 ] || fail "no lock holder"; sleep 0.1; done
expect 2 "^aspects: $lockdir is being written by another run \(it holds $lockdir/\.lock\): wait for that run to end, or choose another output directory$" \
  "$aspects" solve "$model" --eps 0.1 --quiet --out "$lockdir"
[ "$(files "$lockdir")" = ".lock " ] || fail "refused run wrote: $(files "$lockdir")"
# (before its checkpoint is read: there is none here)
expect 2 "is being written by another run" "$aspects" solve --resume "$lockdir" --quiet
kill "$holder"
wait "$holder" 2>/dev/null || true
holder=
"$aspects" solve "$model" --eps 0.1 --quiet --out "$lockdir"  # released: it runs
[ -f "$lockdir/summary.json" ] || fail "no summary.json once the lock was released"
echo ok
