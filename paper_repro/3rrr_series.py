#!/usr/bin/python3
"""The full 3-RRR's series of runs at decreasing eps, as one table and one figure.

Each DIR is an `aspects solve robots/3rrr.robot --out DIR` result; DIR/check.txt, when
present, holds `check_cert`'s output on DIR's certificate (run_all.sh writes it). The share
of the configuration manifold certified is the pose volume of the solution boxes (each holds
exactly one command per pose, and solution boxes do not overlap) over the pose volume of the
8 working-mode sheets, which robots/3rrr_sampling.py estimates numerically: the numerator is
certified, the ratio is not.

Usage: paper_repro/3rrr_series.py DIR ... [--sampling FILE.json] [--png FILE] [--md FILE]
"""
import argparse
import csv
import json
import os
import re
import sys


def solution_pose_volume(boxes_csv, pose):
    vol = 0.0
    with open(boxes_csv, newline="") as f:
        for row in csv.DictReader(f):
            if row["status"] != "solution":
                continue
            v = 1.0
            for p in pose:
                v *= float(row[p + "_hi"]) - float(row[p + "_lo"])
            vol += v
    return vol


def checked(run_dir):
    """(check_cert's verdict and time, the bound it recomputed or None): from run_all.sh's
    check.json and record.txt, or from a check.txt holding check_cert's text output."""
    cj = os.path.join(run_dir, "check.json")
    if os.path.exists(cj):
        j = json.load(open(cj))
        rec = os.path.join(run_dir, "record.txt")
        wall = re.search(r"^check_wall=([0-9.]+)", open(rec).read(), re.M) if os.path.exists(rec) else None
        return (j.get("verdict", "no verdict") + (f" in {float(wall.group(1)):.0f} s" if wall else ""),
                j.get("checked_lower_bound") if j.get("verdict") == "VERIFIED" else None)
    path = os.path.join(run_dir, "check.txt")
    if not os.path.exists(path):
        return "not run", None
    text = open(path).read()
    verdict = re.search(r"^check_cert: ([A-Z]+)\b", text, re.M)
    secs = re.search(r"([0-9.]+) s wall", text)
    bound = re.search(r" checked_lower_bound=([0-9]+)", text)
    out = verdict.group(1) if verdict else "no verdict"
    ok = out == "VERIFIED" and bound
    return out + (f" in {float(secs.group(1)):.0f} s" if secs else ""), int(bound.group(1)) if ok else None


def row(run_dir, sheets_volume):
    s = json.load(open(os.path.join(run_dir, "summary.json")))
    b, c = s["boxes"], s["csncs"]
    boxes_csv = os.path.join(run_dir, "boxes.csv")
    vol = solution_pose_volume(boxes_csv, ["x1", "x2", "x3"]) if os.path.exists(boxes_csv) else None
    stopped = f", stopped by {s['stopped_by']}" if s.get("stopped_by") else ""
    check, checked_bound = checked(run_dir)
    return dict(eps=s["eps"], boxes=b["total"], solution=b["solution"],
                neighbours=s["links"]["neighbor"],
                links=s["links"]["certified"], csncs=c["count"], filtered=c["filtered"],
                bound=c["separated_lower_bound"], checked_bound=checked_bound,
                time=s["time_seconds"], memory=s["peak_memory_mib"], stopped=stopped,
                volume=vol, share=(vol / sheets_volume if vol is not None and sheets_volume else None),
                check=check)


def markdown(rows, sheets_volume, reference):
    out = ["| ε | boxes (solution) | neighbour pairs | certified links | CSNCs (filtered) | "
           "lower bound (certified when check_cert VERIFIED it) | solve time | peak memory | certified pose volume "
           "(share of the sheets, numerical) | check_cert |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        share = f" ({100 * r['share']:.2g} %)" if r["share"] is not None else ""
        vol = f"{r['volume']:,.4g}{share}" if r["volume"] is not None else "—"
        bound = (f"{r['checked_bound']} (VERIFIED)" if r["checked_bound"] is not None
                 else f"{r['bound']} (solver, not checked)")
        out.append(f"| {r['eps']:g} | {r['boxes']:,} ({r['solution']:,}){r['stopped']} | "
                   f"{r['neighbours']:,} | {r['links']:,} | {r['csncs']:,} ({r['filtered']:,}) | "
                   f"{bound} | {r['time']:.1f} s | {r['memory']:.0f} MiB | {vol} | "
                   f"{r['check']} |")
    if reference:
        n, count = reference
        out.append(f"\nNumerical reference, NOT certified (robots/3rrr_sampling.py, {n} cells "
                   f"per axis): {count} thick grid components (blind to aspects thinner than the grid "
                   f"step and near d_i = 20: not a count of the aspects); pose volume of the 8 working-mode sheets "
                   f"{sheets_volume:.0f}.")
    return "\n".join(out) + "\n"


def plot(rows, reference, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = sorted(rows, key=lambda r: -r["eps"])
    eps = [r["eps"] for r in rows]
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].plot(eps, [r["checked_bound"] if r["checked_bound"] is not None else r["bound"]
                     for r in rows], "o-", label="lower bound (certified)")
    ax[0].plot(eps, [r["filtered"] for r in rows], "s--", label="CSNCs kept by the filter (heuristic)")
    # No line for the sampling's thick grid components: drawn beside the bound it read as the
    # number of aspects, which it is not (blind to thin aspects and near d_i = 20).
    from matplotlib.ticker import FixedLocator, NullLocator, ScalarFormatter
    for a in ax:
        a.set_xscale("log")
        a.xaxis.set_major_locator(FixedLocator(eps))
        a.xaxis.set_minor_locator(NullLocator())
        a.xaxis.set_major_formatter(ScalarFormatter())
        a.invert_xaxis()
    ax[0].set_yscale("log")
    ax[0].yaxis.set_major_formatter(ScalarFormatter())
    ax[0].set_xlabel("ε (log scale, finer to the right)")
    ax[0].set_ylabel("count (log scale)")
    ax[0].set_title("Full 3-RRR: certified lower bound against ε")
    ax[0].legend(fontsize=8)
    shares = [(r["eps"], 100 * r["share"]) for r in rows if r["share"] is not None]
    if shares:
        ax[1].plot([e for e, _ in shares], [s for _, s in shares], "o-")
    ax[1].set_xlabel("ε (log scale, finer to the right)")
    ax[1].set_ylabel("% of the sheets' pose volume")
    ax[1].set_title("Pose volume in certified solution boxes")
    fig.tight_layout()
    fig.savefig(png + ".tmp.png", dpi=120)
    os.replace(png + ".tmp.png", png)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dirs", nargs="+")
    ap.add_argument("--sampling", help="robots/3rrr_sampling.py --json output")
    ap.add_argument("--png")
    ap.add_argument("--md")
    a = ap.parse_args()
    sheets_volume, reference = None, None
    if a.sampling:
        runs = json.load(open(a.sampling))["runs"]
        finest = max(runs, key=lambda r: r["n"])
        sheets_volume, reference = finest["volume"], (finest["n"], finest["thick"])
    rows = sorted((row(d, sheets_volume) for d in a.dirs), key=lambda r: -r["eps"])
    text = markdown(rows, sheets_volume, reference)
    sys.stdout.write(text)
    if a.md:
        with open(a.md + ".tmp", "w") as f:
            f.write(text)
        os.replace(a.md + ".tmp", a.md)
    if a.png:
        plot(rows, reference, a.png)


if __name__ == "__main__":
    main()
