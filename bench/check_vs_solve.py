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
"""
import os
import statistics
import subprocess
import sys


def measure(cmd):
    """(user+sys seconds, wall seconds, peak RSS in MB, stdout) of one run."""
    import time
    t0 = time.monotonic()
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    out = p.stdout.read()
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.monotonic() - t0
    return ru.ru_utime + ru.ru_stime, wall, ru.ru_maxrss / 1024, out.decode(), status


def main():
    aspects, outdir, threads, reps = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
    cut = sys.argv.index("--")
    checkers, cases = sys.argv[5:cut], sys.argv[cut + 1:]
    robots = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "robots")
    head = "| robot, eps | solve CPU s (RSS MB) |" + "".join(
        " check %d: CPU s, ratio, wall s, RSS MB |" % (i + 1) for i in range(len(checkers)))
    print(head)
    print("|---" * (2 + len(checkers)) + "|")
    for case in cases:
        robot, eps, *zst = case.split(":")
        out = os.path.join(outdir, "%s_%s" % (robot, eps))
        cpu, _, rss, _, st = measure([aspects, "solve", os.path.join(robots, robot + ".robot"),
                                      "--eps", eps, "--threads", threads, "--out", out, "--quiet"]
                                     + (["--compress-cert"] if zst == ["zst"] else []))
        if st != 0:
            sys.exit("solve %s failed" % case)
        cert = os.path.join(out, "aspects.cert" + (".zst" if zst == ["zst"] else ""))
        runs = [[] for _ in checkers]
        for _ in range(reps):
            for i, c in enumerate(checkers):
                r = measure([c, "--quiet", "--threads", threads, cert])
                if not r[3].startswith("check_cert: VERIFIED"):
                    sys.exit("%s on %s: %s" % (c, cert, r[3][:200]))
                runs[i].append(r)
        row = "| %s %s | %.2f (%.0f) |" % (robot, eps, cpu, rss)
        for r in runs:
            c = statistics.median(x[0] for x in r)
            row += " %.2f, %.2f, %.2f, %.0f |" % (c, c / cpu, statistics.median(x[1] for x in r),
                                                  max(x[2] for x in r))
        print(row, flush=True)


if __name__ == "__main__":
    main()
