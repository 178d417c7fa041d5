#!/usr/bin/python3
"""deep_tree.py — check_cert reads a search tree far deeper than a thread's stack.

Usage: deep_tree.py CHECK_CERT WORKDIR

Issue 50: a run stopped tens of thousands of levels down the tree crashed the solver's
recursive walks. The checker's tree reader keeps its own stack of cells; this certificate
(format 2, written here, not by the solver) bisects x 200,000 times, each time again in
the left half, and then discards the 200,001 cells, deepest first. The model has no
solution (x + q + 1 > 0 on the domain), so every cell is refuted and the verdict is
VERIFIED, complete, with no output box.
"""
import hashlib
import os
import subprocess
import sys

from gen_corpus import hx

LEVELS = 200000


def certificate():
    text = "robot DEEP\npose x in [0, 1]\ncommand q in [0, 1]\nequation x + q + 1 = 0\n"
    t = text.encode()
    lines = ["aspects-certificate 2", "tool aspects deep_tree.py",
             "model %d %s" % (len(t), hashlib.sha256(t).hexdigest()),
             text + "\nend-model",  # the text's bytes, one '\n', then end-model
             "precision 53", "tau " + hx(1.01), "eps " + hx(0.25),
             "domain " + " ".join([hx(0.0), hx(1.0)] * 2),
             "factors 2", "factor detFx", "factor detFq", "tree"]
    # Each cut strictly inside the left cell [0, 1 - k 2^-40], the previous cut's left half.
    lines += ["B 0 " + hx(1.0 - (k + 1) * 2.0 ** -40) for k in range(LEVELS)]
    lines += ["X eq0"] * (LEVELS + 1)
    lines += ["end-tree 0", "links 0", "csncs 0", "cuspidal 0", "assembly 0", "claim filtered 0",
              "claim lower-bound 0"]
    lines.append("end %d" % sum(line.count("\n") + 1 for line in lines))
    return "\n".join(lines) + "\n"


def main():
    check, work = sys.argv[1:3]
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, "deep_tree.cert")
    with open(path, "w") as f:
        f.write(certificate())
    p = subprocess.run([check, "--threads", "2", path], capture_output=True, text=True)
    verdict = p.stdout.splitlines()[0] if p.stdout else ""
    want = ("complete=yes eps=0.25 solutions=0 undecided=0 unexplored=0 wide_undecided=0 links=0 "
            "csncs=0 cuspidal=0 cuspidal_csncs=0 assembly=0 lower_bound=0 checked_lower_bound=0 "
            "robot=\"DEEP\"")
    if p.returncode != 0 or not verdict.startswith("check_cert: VERIFIED ") or not verdict.endswith(want):
        print("FAIL: check_cert exit %d: %r %r" % (p.returncode, p.stdout, p.stderr[-2000:]))
        sys.exit(1)
    if "%d refutations" % (LEVELS + 1) not in p.stderr:
        print("FAIL: not every cell refuted: %r" % p.stderr[-2000:])
        sys.exit(1)
    print("ok: %d levels" % LEVELS)


main()
