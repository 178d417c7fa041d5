#!/usr/bin/python3
"""Interleaved comparison of `aspects solve` variants (binaries and/or options) on the
same cases, for ablation tables: on a shared, noisy machine, variant A and B alternate
run by run so that both see the same load. Reports medians of wall and CPU seconds,
the output boxes (solution/undecided) and the peak RSS. With --count, the variants run
`aspects count` (EPS is its first cover's) and the table gives its bounds (exact counts),
rounds and boxes instead. Usage:

    bench/ablate.py [--repeat 3] [--threads 1] [--count] --variant NAME=BINARY[,ARG...] ... CASE ...

A CASE is ROBOT:EPS (a file under robots/ without .robot, or a path), e.g. rrrrr:0.3.
Example (before/after of one change, old binary built from the previous commit):

    bench/ablate.py --variant before=/tmp/aspects.old --variant after=build/apps/aspects rrrrr:0.3

Prints a Markdown table to stdout."""
import argparse, json, os, statistics, subprocess, sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def solve(binary, args, model, eps, threads):
    cmd = ["/usr/bin/time", "-f", "%e %U %S %M", binary, "solve", model, "--eps", eps,
           "--threads", str(threads), "--no-cert"] + args
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"ablate: {' '.join(cmd)} failed ({p.returncode}):\n{p.stderr}")
    wall, user, sys_, rss = p.stderr.strip().splitlines()[-1].split()
    line = lambda head: next(l for l in p.stdout.splitlines() if l.startswith(head))
    boxes = line("boxes:").split(":", 1)[1].strip()
    links = line("links:").split(":", 1)[1].strip()
    csncs = line("CSNCs:").split(":", 1)[1].strip()
    bound = line("separated lower bound").rsplit(":", 1)[1].strip()
    return (float(wall), float(user) + float(sys_), int(rss), boxes,
            f"{links}; CSNCs {csncs}; bound {bound}")


def count(binary, args, model, eps, threads):
    cmd = ["/usr/bin/time", "-f", "%e %U %S %M", binary, "count", model, "--eps", eps,
           "--threads", str(threads), "--json"] + args
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode not in (0, 3):  # 3: stopped by --time-limit, the bounds reached hold
        sys.exit(f"ablate: {' '.join(cmd)} failed ({p.returncode}):\n{p.stderr}")
    wall, user, sys_, rss = p.stderr.strip().splitlines()[-1].split()
    j = json.loads(p.stdout)
    upper = "?" if j["upper_bound"] is None else j["upper_bound"]
    bounds = f"{j['lower_bound']}" if j["exact"] else f"{j['lower_bound']}..{upper}"
    return (float(wall), float(user) + float(sys_), int(rss),
            f"{j['boxes']} (first cover {j['first_cover']['boxes']})",
            f"{bounds}; {j['rounds']} rounds; {j['stop']}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--variant", action="append", required=True)
    ap.add_argument("--count", action="store_true",
                    help="run `aspects count` (its bounds, rounds and boxes) instead of solve")
    ap.add_argument("--counts", action="store_true",
                    help="add a column with the links, CSNCs and the lower bound")
    ap.add_argument("cases", nargs="+")
    a = ap.parse_args()
    variants = []
    for v in a.variant:
        name, spec = v.split("=", 1)
        parts = spec.split(",")
        variants.append((name, parts[0], parts[1:]))
    print(f"threads {a.threads}, {a.repeat} interleaved runs per variant\n")
    run = count if a.count else solve
    a.counts = a.counts or a.count
    extra = (" aspects; rounds; stop |" if a.count else " links; CSNCs; bound |") if a.counts else ""
    boxes = "boxes" if a.count else "boxes (solution, undecided)"
    print(f"| robot | eps | variant | median wall s | median CPU s | {boxes} | peak MiB |" + extra)
    print("|---|---|---|---|---|---|---|" + ("---|" if a.counts else ""))
    for case in a.cases:
        robot, eps = case.rsplit(":", 1)
        model = robot if os.path.sep in robot else os.path.join(ROOT, "robots", robot + ".robot")
        results = {name: [] for name, _, _ in variants}
        for _ in range(a.repeat):
            for name, binary, args in variants:
                results[name].append(run(binary, args, model, eps, a.threads))
        for name, _, _ in variants:
            r = results[name]
            print(f"| {os.path.basename(robot)} | {eps} | {name} | "
                  f"{statistics.median(x[0] for x in r):.2f} | "
                  f"{statistics.median(x[1] for x in r):.2f} | {r[0][3]} | "
                  f"{max(x[2] for x in r) / 1024:.0f} |" + (f" {r[0][4]} |" if a.counts else ""),
                  flush=True)


if __name__ == "__main__":
    main()
