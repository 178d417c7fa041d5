#!/usr/bin/python3
"""Boxes and time against 1/eps, on log-log axes, with fitted slopes (least squares of
log boxes and log CPU seconds against log 1/eps). Runs `aspects solve --no-cert` once per
(robot, eps); writes a Markdown table to stdout and the plot to --plot. Usage:

    bench/scaling.py [--build build] [--threads 2] [--plot bench/scaling.png] ROBOT:EPS,EPS,...

Example (the figures in bench/RESULTS.md):

    bench/scaling.py rrrrr:0.5,0.3,0.2,0.15,0.1 3rrr_star:1,0.7,0.5,0.35 3rpr:4,3,2.5,2
"""
import argparse, json, math, os, subprocess, sys, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(aspects, model, eps, threads):
    with tempfile.TemporaryDirectory() as out:
        cmd = ["/usr/bin/time", "-f", "%e %U %S %M", aspects, "solve", model, "--eps", eps,
               "--threads", str(threads), "--no-cert", "--quiet", "--out", out]
        p = subprocess.run(cmd, capture_output=True, text=True)
        if p.returncode != 0:
            sys.exit(f"scaling: {' '.join(cmd)} failed ({p.returncode}):\n{p.stderr}")
        wall, user, sys_, rss = p.stderr.strip().splitlines()[-1].split()
        s = json.load(open(os.path.join(out, "summary.json")))
    return {"eps": float(eps), "wall": float(wall), "cpu": float(user) + float(sys_),
            "rss_mib": int(rss) / 1024, "boxes": s["boxes"]["total"],
            "solution": s["boxes"]["solution"], "undecided": s["boxes"]["undecided"],
            "robot": s["robot"]}


def slope(xs, ys):
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    den = sum((a - mx) ** 2 for a in lx)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / den if den else float("nan")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--plot", default=os.path.join(ROOT, "bench", "scaling.png"))
    ap.add_argument("series", nargs="+")
    a = ap.parse_args()
    aspects = os.path.join(a.build, "apps", "aspects")
    print(f"threads {a.threads}\n")
    print("| robot | eps | boxes | solution | undecided | wall s | CPU s | peak MiB |")
    print("|---|---|---|---|---|---|---|---|")
    series = []
    for spec in a.series:
        robot, epss = spec.split(":")
        model = os.path.join(ROOT, "robots", robot + ".robot")
        rows = []
        for eps in epss.split(","):
            r = run(aspects, model, eps, a.threads)
            rows.append(r)
            print(f"| {r['robot']} | {eps} | {r['boxes']} | {r['solution']} | {r['undecided']} | "
                  f"{r['wall']:.2f} | {r['cpu']:.2f} | {r['rss_mib']:.0f} |", flush=True)
        series.append(rows)
    print("\n| robot | slope of boxes vs 1/eps | slope of CPU s vs 1/eps |")
    print("|---|---|---|")
    for rows in series:
        inv = [1 / r["eps"] for r in rows]
        print(f"| {rows[0]['robot']} | {slope(inv, [r['boxes'] for r in rows]):.2f} | "
              f"{slope(inv, [r['cpu'] for r in rows]):.2f} |")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for rows in series:
        inv = [1 / r["eps"] for r in rows]
        name = rows[0]["robot"]
        b = slope(inv, [r["boxes"] for r in rows])
        c = slope(inv, [r["cpu"] for r in rows])
        ax[0].loglog(inv, [r["boxes"] for r in rows], "o-", label=f"{name} (slope {b:.2f})")
        ax[1].loglog(inv, [r["cpu"] for r in rows], "o-", label=f"{name} (slope {c:.2f})")
    ax[0].set(xlabel="1/eps", ylabel="output boxes", title="boxes")
    ax[1].set(xlabel="1/eps", ylabel="CPU seconds", title=f"time ({a.threads} threads)")
    for x in ax:
        x.legend()
        x.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    tmp = a.plot + ".tmp.png"
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, a.plot)


if __name__ == "__main__":
    main()
