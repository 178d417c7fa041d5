#!/usr/bin/python3
"""Draws the paper's figures from `aspects solve` runs.

Usage: /usr/bin/python3 paper_repro/figures.py OUTDIR RUNDIR...

Each RUNDIR holds summary.json and boxes.csv of one `aspects solve --out RUNDIR` (and, when
run_all.sh made it, record.txt and model.robot). The robot of a run is identified by
record.txt's key, else by the model file name in summary.json, else by the robot name.
Writes into OUTDIR (only the figures whose runs are given):

  fig2_prrp.png               Fig. 2: PRRP solution circle and the computed paving
  fig5_csnc_sizes.png         Fig. 5: CSNC sizes, largest first, with the filter threshold
  fig6_3rpr.png               Fig. 6: 3-RPR in (x1, x2, x3): undecided boxes, 2 largest CSNCs
  fig7a_rprpr.png, fig7b_rrrrr.png, fig7c_3rrr_star.png
                              Fig. 7: filtered CSNCs projected on (x1, x2)
  fig8_rrrrr_decomposition.png  Fig. 8: the largest RRRRR CSNC and its constrained pieces
  fig9_rrrrr_collisions.png, fig10_rrrrr_joint_limit.png, fig11_rrrrr_obstacle.png
                              Figs. 9-11: constrained RRRRR CSNCs, constraint boundary blue
  3rrr_csncs.png              beyond the paper: the full 3-RRR as in Fig. 6
"""
import importlib.util
import json
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402


def _load_plotting():
    """python/aspects/plotting.py, the project's one plotting code (`aspects plot` draws
    with it too), loaded by path: it needs numpy and matplotlib only, not the compiled
    module, so these figures need no build of it."""
    here = os.path.dirname(os.path.abspath(__file__))
    path = os.path.join(here, "..", "python", "aspects", "plotting.py")
    spec = importlib.util.spec_from_file_location("aspects_plotting", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


plotting = _load_plotting()
DPI = plotting.DPI
RNG = np.random.default_rng(20240521)
RED, BLUE = plotting.RED, plotting.BLUE
csnc_colors, add_rects = plotting.csnc_colors, plotting.add_rects
NAMES = {"prrp": "PRRP", "rprpr": "RPRPR", "rrrrr": "RRRRR", "3rpr": "3-RPR",
         "3rrr_star": "3-RRR*", "rrrrr_collisions": "RRRRR, link collisions",
         "rrrrr_joint_limit": "RRRRR, joint limit",
         "rrrrr_obstacle": "RRRRR, obstacle"}
ROBOT_TO_KEY = {"PRRP": "prrp", "RPRPR": "rprpr", "RRRRR": "rrrrr", "3-RPR": "3rpr",
                "3-RRR*": "3rrr_star"}
# Section 5.4.3: circular obstacle centred at C = (4.5, 0), radius R = 1.
OBSTACLE = (4.5, 0.0, 1.0)


# ------------------------------------------------------------------------------ data
class Run(plotting.BoxSet):
    """One run directory: boxes.csv read into a plotting.BoxSet (every variable)."""

    def __init__(self, rundir):
        self.dir = rundir
        with open(os.path.join(rundir, "summary.json")) as f:
            self.summary = json.load(f)
        self.key = self._key()
        self.name = NAMES.get(self.key, self.summary.get("robot", self.key))
        names, lo, hi, status, csnc = self._read_boxes(os.path.join(rundir, "boxes.csv"))
        sizes = self.summary.get("csncs", {}).get("sizes")
        n_kept = self.summary.get("csncs", {}).get("filtered", 0)
        pose_names = re.findall(r"^\s*pose\s+(\w+)", model_text(self), re.M) or \
            [v for v in names if v.startswith("x")] or names[:2]
        super().__init__(names, lo, hi, status, csnc, n_kept, robot=self.name,
                         eps=self.summary.get("eps"),
                         pose=[names.index(v) for v in pose_names if v in names],
                         csnc_count=len(sizes) if sizes is not None else None,
                         lower_bound=self.summary.get("csncs", {}).get("separated_lower_bound"),
                         representatives=self.summary.get("csncs", {}).get(
                             "separated_representatives"))
        if sizes is not None:
            self.sizes = list(sizes)

    def _key(self):
        rec = os.path.join(self.dir, "record.txt")
        if os.path.exists(rec):
            with open(rec) as f:
                for line in f:
                    if line.startswith("key="):
                        return line.strip()[4:]
        model = self.summary.get("model")
        if model:
            base = os.path.basename(model)
            if base.endswith(".robot"):
                return base[:-6]
        return ROBOT_TO_KEY.get(self.summary.get("robot"), os.path.basename(self.dir))

    @staticmethod
    def _read_boxes(path):
        """Variable names, lower and upper ends, status codes (plotting's), CSNCs."""
        with open(path) as f:
            header = f.readline().rstrip("\n").split(",")
            assert header[:4] == ["id", "status", "csnc", "kept"], header
            assert header[-1] == "boundary", header
            vcols = header[4:-1]
            names = [c[:-3] for c in vcols[0::2]]
            nv = len(names)
            los, his, csnc, status = [], [], [], []
            code = {("solution", ""): plotting.SOLUTION,
                    ("undecided", "constraint"): plotting.CONSTRAINT,
                    ("unexplored", ""): plotting.UNEXPLORED}
            while True:
                chunk = f.readlines(64 << 20)
                if not chunk:
                    break
                rows = [ln.rstrip("\n").split(",") for ln in chunk]
                a = np.array([r[4:4 + 2 * nv] for r in rows], dtype=float).reshape(-1, nv, 2)
                los.append(a[:, :, 0])
                his.append(a[:, :, 1])
                csnc.append(np.array([int(r[2]) for r in rows], dtype=np.int64))
                # boxes.csv does not tell P1 from P2 failures: both are singular (red).
                status.append(np.array([code.get((r[1], r[-1]), plotting.SINGULAR)
                                        for r in rows], dtype=np.int8))
        cat = (lambda xs, dt: np.concatenate(xs) if xs else np.zeros(0, dtype=dt))
        lo = np.concatenate(los) if los else np.zeros((0, nv))
        hi = np.concatenate(his) if his else np.zeros((0, nv))
        return names, lo, hi, cat(status, np.int8), cat(csnc, np.int64)


def save(fig, outdir, name, dpi=DPI):
    path = os.path.join(outdir, name)
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    print(f"wrote {path} ({os.path.getsize(path) // 1024} KB)")


def model_constants(run):
    """`constant NAME = NUMBER` statements of the run's model (for PRRP's a, b, l)."""
    text = model_text(run)
    consts = {}
    for m in re.finditer(r"^\s*constant\s+(\w+)\s*=\s*([-+0-9.eE]+)\s*(#.*)?$", text, re.M):
        try:
            consts[m.group(1)] = float(m.group(2))
        except ValueError:
            pass
    return consts


def merge_intervals(lo, hi):
    order = np.argsort(lo)
    out = []
    for a, b in zip(lo[order], hi[order]):
        if out and a <= out[-1][1]:
            out[-1][1] = max(out[-1][1], b)
        else:
            out.append([a, b])
    return out


# ------------------------------------------------------------------------------ Fig. 2
def fig2(run, outdir):
    c = model_constants(run)
    a, b, l = c.get("a", 0.0), c.get("b", 0.0), c.get("l", 1.0)
    ix, iq = 0, 1
    fig, (axl, axr) = plt.subplots(1, 2, figsize=(10, 4.8))
    t = np.linspace(0, 2 * np.pi, 400)
    for ax in (axl, axr):
        ax.plot(a + l * np.cos(t), b + l * np.sin(t), color="k", lw=1.0, zorder=5)
        ax.set_aspect("equal")
        ax.set_xlabel(run.vars[ix])
        ax.set_ylabel(run.vars[iq])
    axl.plot([a - l, a + l], [b, b], "o", color="#2ca02c", ms=9, zorder=6,
             label="serial singularities (det Fq = 0)")
    axl.plot([a, a], [b - l, b + l], "o", color=RED, ms=9, zorder=6,
             label="parallel singularities (det Fx = 0)")
    def shifted(v, c):
        return v if c == 0 else f"({v} − {c:g})" if c > 0 else f"({v} + {-c:g})"
    axl.set_title(f"solution set {shifted(run.vars[ix], a)}² + {shifted(run.vars[iq], b)}² = "
                  f"{l:g}²", fontsize=10)
    axl.legend(loc="lower center", fontsize=8, bbox_to_anchor=(0.5, -0.36))
    axl.set_xlim(a - 1.6 * l, a + 1.6 * l)
    axl.set_ylim(b - 1.6 * l, b + 1.6 * l)

    kept_ids = sorted(set(run.csnc[run.kept].tolist()))
    colors = csnc_colors(max(kept_ids) + 1 if kept_ids else 1)
    # Undecided boxes are thin after contraction: draw them with a thick red edge, on top.
    add_rects(axr, run, run.undecided, ix, iq, RED, edge=RED, lw=2.0, zorder=6)
    for k in sorted(set(run.csnc[run.csnc >= 0].tolist())):
        m = run.csnc == k
        col = colors[k] if k in kept_ids else "0.7"
        add_rects(axr, run, m, ix, iq, col, edge="k", lw=0.4, zorder=3)
    # Projections of the CSNCs on the x axis: inner approximations of the workspace.
    ytop, ybot = b + 1.25 * l, b - 1.25 * l
    for k in kept_ids:
        m = run.csnc == k
        qmid = 0.5 * (run.lo[m, iq] + run.hi[m, iq]).mean()
        y = ytop if qmid >= b else ybot
        for x0, x1 in merge_intervals(run.lo[m, ix], run.hi[m, ix]):
            axr.plot([x0, x1], [y, y], color=colors[k], lw=5, solid_capstyle="butt", zorder=4)
        xm = 0.5 * (run.lo[m, ix].min() + run.hi[m, ix].max())
        axr.text(xm, y + (0.1 if y > b else -0.1) * l, f"A{k + 1}", ha="center",
                 va="bottom" if y > b else "top", fontsize=9, color=colors[k])
    axr.set_xlim(a - 1.6 * l, a + 1.6 * l)
    axr.set_ylim(b - 1.6 * l, b + 1.6 * l)
    n_sol, n_und = int(run.solution.sum()), int(run.undecided.sum())
    axr.set_title(f"paving, ε = {run.eps:g}: {n_sol} solution boxes in {len(kept_ids)} CSNCs, "
                  f"{n_und} undecided (red)", fontsize=9)
    fig.suptitle("Fig. 2 — PRRP: solution set (left) and computed paving with the CSNCs' "
                 "projections on x (right)", fontsize=10)
    fig.tight_layout()
    save(fig, outdir, "fig2_prrp.png")


# ------------------------------------------------------------------------------ Fig. 5
def fig5(runs, outdir):
    runs = [r for r in runs if r.sizes]
    if not runs:
        return
    n = len(runs)
    ncol = min(n, 3)
    nrow = (n + ncol - 1) // ncol
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.3 * ncol, 3.4 * nrow), squeeze=False)
    for ax in axes.flat[n:]:
        ax.axis("off")
    for ax, r in zip(axes.flat, runs):
        k = r.n_kept
        shown = r.sizes[:k + 1]
        xs = np.arange(1, len(shown) + 1)
        cols = ["#1f77b4"] * min(k, len(shown)) + ["0.6"] * (len(shown) - k)
        ax.bar(xs, shown, color=cols, width=0.8, edgecolor="k", linewidth=0.3)
        ax.set_yscale("log")
        ax.set_ylim(0.7, max(shown) * 2.5)
        if k < len(r.sizes):
            ax.axvline(k + 0.5, color="k", ls="--", lw=1.2)
            ratio = r.sizes[k - 1] / r.sizes[k] if k >= 1 and r.sizes[k] > 0 else float("nan")
            ax.text(k + 0.45, max(shown) * 1.6, f"ratio {ratio:.3g}", fontsize=8,
                    ha="right", va="center",
                    bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none"))
            note = f"{k} kept of {len(r.sizes)}; grey: largest filtered out ({r.sizes[k]})"
        else:
            note = f"all {len(r.sizes)} kept (no ratio > 1)"
        ax.set_title(f"{r.title()}\n{note}", fontsize=9)
        ax.set_xlabel("CSNC (largest first)")
        ax.set_ylabel("boxes")
        if len(shown) <= 30:
            ax.set_xticks(xs)
            ax.tick_params(axis="x", labelsize=7 if len(shown) > 12 else 9)
    fig.suptitle("Fig. 5 — number of boxes of each CSNC (kept ones, then the largest "
                 "filtered out);\ndashed line: filtering threshold (largest size ratio)",
                 fontsize=10)
    fig.tight_layout()
    save(fig, outdir, "fig5_csnc_sizes.png")


# ------------------------------------------------------------------------------ Figs. 6, 7, 9-11
def fig6(run, outdir):
    save(plotting.csnc_3d(run, "Fig. 6 — "), outdir, "fig6_3rpr.png")


def csnc_grid(run, outdir, fname, title, constraint=False, obstacle=None,
              undecided_on_top=True):
    fig = plotting.csnc_grid(run, f"{title} — ", constraint=constraint, obstacle=obstacle,
                             undecided_on_top=undecided_on_top)
    npan = len(fig.axes)
    save(fig, outdir, fname, dpi=DPI if npan <= 12 else 85)


# ------------------------------------------------------------------------------ Fig. 8
def model_text(run):
    for p in (os.path.join(run.dir, "model.robot"), run.summary.get("model", "")):
        if p and os.path.exists(p):
            with open(p) as f:
                return f.read()
    return ""


def periodic_vars(run):
    return set(re.findall(r"^\s*(?:pose|command)\s+(\w+)\s+in\s+\[[^\]]*\]\s+periodic",
                          model_text(run), re.M))


def origin_of_csncs(base, run, samples=64):
    """For each kept CSNC of a constrained run: the kept CSNC of the unconstrained run whose
    box centres are nearest (in the full configuration space, periodic variables modulo
    2*pi) to most of its box centres. Works across different precisions."""
    names = [v for v in run.vars if v in base.vars]
    ci = [run.col(v) for v in names]
    bi = [base.col(v) for v in names]
    per = periodic_vars(base) | periodic_vars(run)
    periodic = np.array([v in per for v in names])
    bm = base.kept
    bc = 0.5 * (base.lo[bm][:, bi] + base.hi[bm][:, bi])
    bid = base.csnc[bm]
    out = {}
    if len(bc) == 0:
        return out
    for k in sorted(set(run.csnc[run.kept].tolist())):
        idx = np.flatnonzero(run.csnc == k)
        if len(idx) > samples:
            idx = RNG.choice(idx, size=samples, replace=False)
        votes = []
        for p in 0.5 * (run.lo[idx][:, ci] + run.hi[idx][:, ci]):
            d = bc - p
            d[:, periodic] = (d[:, periodic] + np.pi) % (2 * np.pi) - np.pi
            votes.append(int(bid[np.argmin((d * d).sum(axis=1))]))
        out[k] = int(np.bincount(votes).argmax())
    return out


def fig8(base, variants, outdir, which=0):
    ix, iy = base.workspace_axes()
    panels = [(f"(a) RRRRR CSNC {which + 1}, no constraint (ε = {base.eps:g})", base, [which],
               False, None)]
    for key, label in (("rrrrr_collisions", "(b) link collisions"),
                       ("rrrrr_joint_limit", "(c) joint limit"),
                       ("rrrrr_obstacle", "(d) obstacle")):
        r = variants.get(key)
        if r is None:
            continue
        org = origin_of_csncs(base, r)
        ids = [k for k, o in org.items() if o == which]
        panels.append((f"{label}: {len(ids)} CSNC{'s' if len(ids) != 1 else ''} (ε = {r.eps:g})",
                       r, ids, True,
                       obstacle_of(r) if key == "rrrrr_obstacle" else None))
    if len(panels) == 1:
        return
    fig, axes = plt.subplots(1, len(panels), figsize=(3.8 * len(panels), 4.3), squeeze=False)
    m0 = base.csnc == which
    for ax, (label, r, ids, constraint, obst) in zip(axes.flat, panels):
        cols = csnc_colors(max(len(ids), 1))
        rix, riy = r.workspace_axes()
        for j, k in enumerate(ids):
            add_rects(ax, r, r.csnc == k, rix, riy, cols[j], zorder=2)
        # Boundary boxes near this CSNC only (within its (x1, x2) bounding box).
        x0, x1 = base.lo[m0, ix].min(), base.hi[m0, ix].max()
        y0, y1 = base.lo[m0, iy].min(), base.hi[m0, iy].max()
        near = ((r.hi[:, rix] >= x0) & (r.lo[:, rix] <= x1) & (r.hi[:, riy] >= y0)
                & (r.lo[:, riy] <= y1))
        add_rects(ax, r, r.singular_bd & near, rix, riy, RED, alpha=0.5, zorder=3)
        if constraint:
            add_rects(ax, r, r.constraint_bd & near, rix, riy, BLUE, alpha=0.6, zorder=4)
        if obst is not None:
            ax.add_patch(Circle(obst[:2], obst[2], color="k", zorder=6))
        ax.set_xlim(x0 - 0.5, x1 + 0.5)
        ax.set_ylim(y0 - 0.5, y1 + 0.5)
        ax.set_aspect("equal")
        ax.set_title(label, fontsize=9)
        ax.tick_params(labelsize=7)
    fig.suptitle(f"Fig. 8 — decomposition of RRRRR's CSNC {which + 1} under additional "
                 "constraints (red: singular, blue: constraint boundary)", fontsize=10)
    fig.tight_layout()
    save(fig, outdir, "fig8_rrrrr_decomposition.png")


# ------------------------------------------------------------------------------ main
def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    outdir = sys.argv[1]
    os.makedirs(outdir, exist_ok=True)
    runs = {}
    for d in sys.argv[2:]:
        r = Run(d)
        print(f"read {d}: {r.name}, eps {r.eps}, {len(r.csnc)} boxes, {len(r.sizes)} CSNCs, "
              f"{r.n_kept} kept")
        runs[r.key] = r
    if "prrp" in runs:
        fig2(runs["prrp"], outdir)
    main5 = [runs[k] for k in ("prrp", "rprpr", "rrrrr", "3rpr", "3rrr_star",
                               "rrrrr_collisions", "rrrrr_joint_limit", "rrrrr_obstacle")
             if k in runs]
    if main5:
        fig5(main5, outdir)
    if "3rpr" in runs:
        fig6(runs["3rpr"], outdir)
    if "3rrr" in runs:  # beyond the paper: the full 3-RRR drawn as Fig. 6
        save(plotting.csnc_3d(runs["3rrr"], "Beyond the paper — "), outdir, "3rrr_csncs.png")
    for key, fname, sub in (("rprpr", "fig7a_rprpr.png", "(a)"),
                            ("rrrrr", "fig7b_rrrrr.png", "(b)"),
                            ("3rrr_star", "fig7c_3rrr_star.png", "(c)")):
        if key in runs:
            csnc_grid(runs[key], outdir, fname, f"Fig. 7{sub}",
                      undecided_on_top=(key != "3rrr_star"))
    variants = {k: runs[k] for k in ("rrrrr_collisions", "rrrrr_joint_limit",
                                     "rrrrr_obstacle") if k in runs}
    for key, fname, num in (("rrrrr_collisions", "fig9_rrrrr_collisions.png", 9),
                            ("rrrrr_joint_limit", "fig10_rrrrr_joint_limit.png", 10),
                            ("rrrrr_obstacle", "fig11_rrrrr_obstacle.png", 11)):
        if key in variants:
            csnc_grid(variants[key], outdir, fname, f"Fig. {num}", constraint=True,
                      obstacle=obstacle_of(variants[key]) if key == "rrrrr_obstacle" else None)
    if "rrrrr" in runs and variants:
        fig8(runs["rrrrr"], variants, outdir)


def obstacle_of(run):
    """The obstacle disc (cx, cy, r) from the model's constants, else the paper's."""
    c = model_constants(run)
    if all(k in c for k in ("cx", "cy", "r")):
        return (c["cx"], c["cy"], c["r"])
    return OBSTACLE


if __name__ == "__main__":
    main()
