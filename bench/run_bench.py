#!/usr/bin/python3
"""Benchmark of `aspects solve` (and `check_cert` when built): median wall time over
repeated runs, boxes per second, peak memory, certificate size per output box, and the
check/solve time ratio. Usage:

    bench/run_bench.py [--build build] [--repeat 3] [--threads 1,2] [CASE ...]

A CASE is ROBOT:EPS (robot file name under robots/ without .robot), e.g. rrrrr:0.1.
Prints a Markdown table to stdout (paste it into bench/RESULTS.md with the command)."""
import argparse, json, os, statistics, subprocess, sys, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT = ["prrp:0.1", "rprpr:0.1", "rrrrr:0.2", "rrrrr:0.1"]


def run(cmd):
    t = time.perf_counter()
    p = subprocess.run(["/usr/bin/time", "-f", "%M"] + cmd, capture_output=True, text=True)
    dt = time.perf_counter() - t
    if p.returncode != 0:
        sys.exit(f"bench: {' '.join(cmd)} failed ({p.returncode}):\n{p.stderr}")
    return dt, int(p.stderr.strip().splitlines()[-1])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("cases", nargs="*", default=DEFAULT)
    a = ap.parse_args()
    aspects = os.path.join(a.build, "apps", "aspects")
    checker = os.path.join(a.build, "certificates", "checker", "check_cert")
    print("| robot | eps | threads | median solve s | runs | boxes | boxes/s | peak MiB | cert bytes/box | median check s | check/solve |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for case in a.cases:
        robot, eps = case.split(":")
        model = os.path.join(ROOT, "robots", robot + ".robot")
        for th in [int(t) for t in a.threads.split(",")]:
            times, mems, checks = [], [], []
            with tempfile.TemporaryDirectory() as out:
                for _ in range(a.repeat):
                    dt, mem = run([aspects, "solve", model, "--eps", eps, "--threads", str(th),
                                   "--out", out, "--quiet"])
                    times.append(dt)
                    mems.append(mem)
                    if os.path.exists(checker):
                        checks.append(run([checker, "--quiet", os.path.join(out, "aspects.cert")])[0])
                s = json.load(open(os.path.join(out, "summary.json")))
                boxes = s["boxes"]["total"]
                cert = os.path.getsize(os.path.join(out, "aspects.cert"))
            med = statistics.median(times)
            chk = statistics.median(checks) if checks else None
            print(f"| {s['robot']} | {eps} | {th} | {med:.3f} | {a.repeat} | {boxes} | "
                  f"{s['boxes']['processed'] / med:.0f} | {max(mems) / 1024:.0f} | "
                  f"{cert / max(boxes, 1):.0f} | {'' if chk is None else f'{chk:.3f}'} | "
                  f"{'' if chk is None else f'{chk / med:.2f}'} |", flush=True)


if __name__ == "__main__":
    main()
