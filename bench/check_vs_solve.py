#!/usr/bin/python3
"""check_vs_solve.py — CPU time (user+sys) and peak memory of check_cert against the solver
that wrote the certificate, on the same thread count.

  check_vs_solve.py ASPECTS OUTDIR THREADS REPS CHECK_CERT... -- ROBOT:EPS...

Solves each robot once (aspects solve --threads THREADS), then runs every CHECK_CERT on its
certificate REPS times, interleaved (A B A B ...), and prints one markdown row per robot:
solver CPU and peak RSS, and per checker the median CPU, its ratio to the solver's, the
median wall time and the peak RSS. A check that does not print VERIFIED stops the script.
ROBOT:EPS:zst solves with --compress-cert (the certificate is then aspects.cert.zst, and
both CPU figures include zstd: the solver's compression, the checker's decompression); for
runs whose text certificate would not fit on the disk (3-RPR at eps 0.1 writes 53 GB).
ROBOT:EPS:v3 (or :v3:zst) writes certificate format 3 (--cert-format 3). Each row also gives
the output boxes and the archived bytes a box: the certificate compressed by zstd -12
(the .zst file recompressed at -12 when the solver compressed it).
"""
import json
import os
import statistics
import subprocess
import sys


def measure(cmd, err=None):
    """(user+sys seconds, wall seconds, peak RSS in MB, stdout) of one run; its stderr goes
    to the file `err` if given."""
    import time
    t0 = time.monotonic()
    errf = open(err, "w") if err else subprocess.DEVNULL
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=errf)
    out = p.stdout.read()
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.monotonic() - t0
    if err:
        errf.close()
    return ru.ru_utime + ru.ru_stime, wall, ru.ru_maxrss / 1024, out.decode(), status


def main():
    aspects, outdir, threads, reps = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
    cut = sys.argv.index("--")
    checkers, cases = sys.argv[5:cut], sys.argv[cut + 1:]
    robots = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "robots")
    head = "| robot, eps | boxes | CSNCs (kept) | bound | archived B/box | solve CPU s (RSS MB) |" + "".join(
        " check %d: CPU s, ratio, wall s, RSS MB |" % (i + 1) for i in range(len(checkers)))
    print(head)
    print("|---" * (6 + len(checkers)) + "|")
    os.makedirs(outdir, exist_ok=True)  # each solve's stderr is kept beside its output
    for case in cases:
        robot, eps, *flags = case.split(":")
        zst, v3 = "zst" in flags, "v3" in flags
        out = os.path.join(outdir, "%s_%s%s" % (robot, eps, "_v3" if v3 else ""))
        cpu, _, rss, _, st = measure([aspects, "solve", os.path.join(robots, robot + ".robot"),
                                      "--eps", eps, "--threads", threads, "--out", out, "--quiet"]
                                     + (["--compress-cert"] if zst else [])
                                     + (["--cert-format", "3"] if v3 else []),
                                     err=out + ".solve.err")
        if st != 0:
            sys.exit("solve %s failed (exit status %d; its stderr: %s.solve.err)" % (case, st, out))
        cert = os.path.join(out, "aspects.cert" + (".zst" if zst else ""))
        with open(os.path.join(out, "boxes.csv")) as f:
            boxes = sum(1 for _ in f) - 1
        with open(os.path.join(out, "summary.json")) as f:
            csncs = json.load(f)["csncs"]
        unpack = "zstd -dc %s | " % cert if zst else ""
        archived = int(subprocess.run(unpack + "zstd -12 -T2 -c %s | wc -c" % ("" if zst else cert),
                                      shell=True, stdout=subprocess.PIPE, check=True).stdout)
        runs = [[] for _ in checkers]
        for _ in range(reps):
            for i, c in enumerate(checkers):
                r = measure([c, "--quiet", "--threads", threads, cert])
                if not r[3].startswith("check_cert: VERIFIED"):
                    sys.exit("%s on %s: %s" % (c, cert, r[3][:200]))
                runs[i].append(r)
        row = "| %s %s%s | %d | %d (%d) | %d | %.1f | %.2f (%.0f) |" % (
            robot, eps, " (format 3)" if v3 else "", boxes, csncs["count"], csncs["filtered"],
            csncs["separated_lower_bound"], archived / boxes, cpu, rss)
        for r in runs:
            c = statistics.median(x[0] for x in r)
            row += " %.2f, %.2f, %.2f, %.0f |" % (c, c / cpu, statistics.median(x[1] for x in r),
                                                  max(x[2] for x in r))
        print(row, flush=True)


if __name__ == "__main__":
    main()
