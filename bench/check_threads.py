#!/usr/bin/python3
"""check_threads.py — check_cert's speed-up from 1 to 2 threads.

  check_threads.py REPS CERT... -- CHECK_CERT...

Runs every CHECK_CERT on every certificate with --threads 1 and --threads 2, interleaved
(each repetition runs all of them once), and prints per certificate and checker the median
wall and CPU (user+sys) seconds at 1 and 2 threads and the speed-up (wall 1 / wall 2). On a
shared machine a run that did not get two cores shows CPU/wall below 2; the medians only
mean something when most runs got them (the CPU/wall column says).
"""
import os
import statistics
import subprocess
import sys
import time


def run(binary, threads, cert):
    t0 = time.monotonic()
    p = subprocess.Popen([binary, "--quiet", "--threads", str(threads), cert],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, ru = os.wait4(p.pid, 0)
    if status != 0:
        sys.exit("%s --threads %d %s: exit status %d" % (binary, threads, cert, status))
    return time.monotonic() - t0, ru.ru_utime + ru.ru_stime


def main():
    reps = int(sys.argv[1])
    cut = sys.argv.index("--")
    certs, checkers = sys.argv[2:cut], sys.argv[cut + 1:]
    res = {}
    for _ in range(reps):
        for cert in certs:
            for c in checkers:
                for t in (1, 2):
                    res.setdefault((cert, c, t), []).append(run(c, t, cert))
    print("| certificate | checker | wall 1 s | CPU 1 s | wall 2 s | CPU 2 s | CPU/wall at 2 | speed-up |")
    print("|---|---|---|---|---|---|---|---|")
    for cert in certs:
        for c in checkers:
            w1 = statistics.median(x[0] for x in res[(cert, c, 1)])
            c1 = statistics.median(x[1] for x in res[(cert, c, 1)])
            w2 = statistics.median(x[0] for x in res[(cert, c, 2)])
            c2 = statistics.median(x[1] for x in res[(cert, c, 2)])
            print("| %s | %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |" % (
                cert, c, w1, c1, w2, c2, c2 / w2, w1 / w2))


if __name__ == "__main__":
    main()
