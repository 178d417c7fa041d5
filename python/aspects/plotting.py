"""Pictures of a result: the project's one plotting code.

`aspects plot`, `aspects path --plot`, `aspects.Result.plot()` and paper_repro/figures.py all
draw with these functions. The module needs only numpy and matplotlib (not the compiled
part of the package), so the command line runs it as a script:

    /usr/bin/python3 plotting.py DATA.json OUT.png

where DATA.json (written by apps/plot_data.cpp) names a binary file of the boxes' pose
parts. An illustration only: nothing drawn here is a claim.

- 2 pose variables: every filtered CSNC projected on the pose plane, then one panel per
  CSNC, undecided boxes on top (as the paper's Fig. 7);
- 3 or more pose variables: the first three, the undecided boxes and the largest CSNCs
  in 3-D (as the paper's Fig. 6);
- 1 pose variable: each CSNC's projection on the pose axis.
A path (what `aspects path --json` prints) is drawn on top.
"""
import json
import math
import os
import sys

import numpy as np
import matplotlib

if "matplotlib.pyplot" not in sys.modules and not os.environ.get("MPLBACKEND"):
    matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

# Box status codes, as aspects.Result.status holds them (1 + the index's undecided kind).
SOLUTION, NO_EXISTENCE, SINGULAR, CONSTRAINT, UNEXPLORED = 0, 1, 2, 3, 4

DPI = 110
MAX_POLYS = 200_000          # rectangles per panel layer before subsampling
RED = "#d62728"
BLUE = "#1f4fd6"
GREY = "0.55"
PATH_COLOR = "k"


def rng():
    """A fixed seed: the same figure from the same result."""
    return np.random.default_rng(20240521)


def csnc_colors(n):
    base = list(plt.get_cmap("tab10").colors)
    base = [c for i, c in enumerate(base) if i != 3]          # no red: red = undecided
    pal = base + list(plt.get_cmap("tab20b").colors)
    return [pal[i % len(pal)] for i in range(n)]


class BoxSet:
    """Boxes of a result: lower and upper ends (one column per variable in `names`; a
    column may be NaN where the result does not record it), status codes, CSNC (-1 for
    undecided boxes), and the number of CSNCs the size-ratio filter keeps (the largest)."""

    def __init__(self, names, lower, upper, status, csnc, filtered, robot="", eps=None,
                 pose=None, periodic=None, csnc_count=None):
        self.vars = list(names)
        nv = len(self.vars)
        self.lo = np.asarray(lower, dtype=float).reshape(-1, nv)
        self.hi = np.asarray(upper, dtype=float).reshape(-1, nv)
        self.status = np.asarray(status, dtype=np.int8)
        self.csnc = np.asarray(csnc, dtype=np.int64)
        self.solution = self.status == SOLUTION
        self.undecided = ~self.solution
        self.unexplored = self.status == UNEXPLORED
        self.constraint_bd = self.status == CONSTRAINT
        self.singular_bd = self.undecided & ~self.constraint_bd & ~self.unexplored
        self.n_kept = int(filtered)
        self.kept = (self.csnc >= 0) & (self.csnc < self.n_kept)
        counts = np.bincount(self.csnc[self.csnc >= 0]) if (self.csnc >= 0).any() else []
        self.sizes = sorted((int(c) for c in counts), reverse=True)
        self.csnc_count = len(self.sizes) if csnc_count is None else int(csnc_count)
        self.robot = robot
        self.eps = eps
        self.pose = list(range(nv)) if pose is None else list(pose)
        self.periodic = [False] * nv if periodic is None else list(periodic)

    def col(self, name):
        return self.vars.index(name)

    def workspace_axes(self):
        """The two plotted pose columns: x1, x2 when the pose has them, else the first two."""
        names = [self.vars[c] for c in self.pose]
        if "x1" in names and "x2" in names:
            return self.col("x1"), self.col("x2")
        return self.pose[0], self.pose[1]

    def title(self):
        eps = f", ε = {self.eps:g}" if self.eps is not None else ""
        return f"{self.robot}{eps}"


def read_data(meta_path):
    """The BoxSet and the path (or None) of a DATA.json written by apps/plot_data.cpp."""
    with open(meta_path) as f:
        d = json.load(f)
    n, k = d["boxes"], len(d["names"])
    with open(os.path.join(os.path.dirname(meta_path), d["binary"]), "rb") as f:
        raw = f.read()
    off = 0

    def take(dtype, count):
        nonlocal off
        a = np.frombuffer(raw, dtype=np.dtype(dtype).newbyteorder("<"), count=count, offset=off)
        off += a.nbytes
        return a

    lo = take(np.float64, n * k).reshape(n, k)
    hi = take(np.float64, n * k).reshape(n, k)
    csnc = take(np.int32, n)
    status = take(np.int8, n)
    if off != len(raw):
        raise ValueError(f"{meta_path}: the binary file has {len(raw)} bytes, expected {off}")
    bs = BoxSet(d["names"], lo, hi, status, csnc, d["filtered"], robot=d["robot"], eps=d["eps"],
                periodic=d["periodic"], csnc_count=d["csnc_count"])
    return bs, d.get("path")


# ------------------------------------------------------------------------------ drawing
def rects(bs, mask, ix, iy, cap=MAX_POLYS):
    """Vertices of the (ix, iy) projections of the boxes selected by mask, subsampled."""
    idx = np.flatnonzero(mask)
    total = len(idx)
    if total > cap:
        idx = np.sort(rng().choice(idx, size=cap, replace=False))
    x0, x1 = bs.lo[idx, ix], bs.hi[idx, ix]
    y0, y1 = bs.lo[idx, iy], bs.hi[idx, iy]
    v = np.stack([np.stack([x0, y0], 1), np.stack([x1, y0], 1),
                  np.stack([x1, y1], 1), np.stack([x0, y1], 1)], 1)
    return v, total


def add_rects(ax, bs, mask, ix, iy, color, alpha=1.0, edge=None, lw=0.0, cap=MAX_POLYS,
              zorder=1):
    v, total = rects(bs, mask, ix, iy, cap)
    if len(v) == 0:
        return 0, 0
    pc = PolyCollection(v, facecolors=[color], edgecolors=[edge] if edge else "none",
                        linewidths=lw, alpha=alpha, zorder=zorder)
    ax.add_collection(pc)
    return len(v), total


def set_limits(ax, bs, mask, ix, iy, pad=0.03):
    if not mask.any():
        return
    x0, x1 = np.nanmin(bs.lo[mask, ix]), np.nanmax(bs.hi[mask, ix])
    y0, y1 = np.nanmin(bs.lo[mask, iy]), np.nanmax(bs.hi[mask, iy])
    dx, dy = (x1 - x0) * pad + 1e-9, (y1 - y0) * pad + 1e-9
    ax.set_xlim(x0 - dx, x1 + dx)
    ax.set_ylim(y0 - dy, y1 + dy)


def save(fig, out, dpi=DPI):
    """Writes the figure under a temporary name, then renames it (never a half PNG)."""
    root, ext = os.path.splitext(out)
    tmp = f"{root}.tmp{os.getpid()}{ext or '.png'}"
    fig.savefig(tmp, dpi=dpi)
    os.replace(tmp, out)


def path_segments(bs, path, cols):
    """The path's straight segments in the columns `cols`, from the waypoints' unwrapped
    poses (pose + 2π·turns); on a periodic coordinate each segment is shifted by whole
    turns so that it starts in [-π, π] (drawn where its box lies)."""
    wps = (path or {}).get("waypoints") or []
    pts = []
    for w in wps:
        turns = w.get("turns") or [0] * len(w["pose"])
        pts.append([p + 2 * math.pi * t for p, t in zip(w["pose"], turns)])
    segs = []
    for a, b in zip(pts, pts[1:]):
        a, b = list(a), list(b)
        for j, c in enumerate(bs.pose):
            if bs.periodic[c]:
                k = math.floor((a[j] + math.pi) / (2 * math.pi))
                a[j] -= 2 * math.pi * k
                b[j] -= 2 * math.pi * k
        segs.append(([a[bs.pose.index(c)] for c in cols], [b[bs.pose.index(c)] for c in cols]))
    return segs


def draw_path_2d(ax, bs, path, ix, iy):
    segs = path_segments(bs, path, (ix, iy))
    for a, b in segs:
        ax.plot([a[0], b[0]], [a[1], b[1]], "-", color=PATH_COLOR, lw=1.6, zorder=8)
        ax.plot([a[0]], [a[1]], "o", color=PATH_COLOR, ms=2.2, zorder=8)
    if segs:
        ax.plot([segs[0][0][0]], [segs[0][0][1]], "s", color="#2ca02c", ms=8, mec="k", zorder=9)
        ax.plot([segs[-1][1][0]], [segs[-1][1][1]], "*", color="#ffdd00", ms=14, mec="k",
                zorder=9)


def path_handles(path):
    if not path or not path.get("waypoints"):
        return []
    n = len(path["waypoints"])
    return [Line2D([], [], color=PATH_COLOR, lw=1.6, marker="o", ms=2.2,
                   label=f"certified path in CSNC {path.get('csnc')}: {n} waypoints"),
            Line2D([], [], ls="", marker="s", color="#2ca02c", mec="k", ms=8, label="start"),
            Line2D([], [], ls="", marker="*", color="#ffdd00", mec="k", ms=14, label="goal")]


def undecided_handles(bs, constraint=True):
    h = []
    if bs.singular_bd.any():
        h.append(Patch(color=RED, alpha=0.5, label=f"undecided ({int(bs.singular_bd.sum())} "
                       "boxes: singular or unresolved)"))
    if constraint and bs.constraint_bd.any():
        h.append(Patch(color=BLUE, alpha=0.5, label=f"constraint boundary "
                       f"({int(bs.constraint_bd.sum())} boxes)"))
    if bs.unexplored.any():
        h.append(Patch(color=GREY, alpha=0.5, label=f"unexplored ({int(bs.unexplored.sum())} "
                       "boxes: the run was stopped)"))
    return h


def csnc_grid(bs, title, constraint=True, obstacle=None, max_panels=26, undecided_on_top=True,
              path=None, legend_csncs=10):
    """Overview (all kept CSNCs) + one panel per kept CSNC, with the undecided boxes on top
    (so that singularity curves show across the projected CSNCs, as in the paper), or
    beneath when they cover most of the projected workspace (coarse 3-RRR* runs)."""
    from matplotlib.patches import Circle
    ix, iy = bs.workspace_axes()
    kept_ids = sorted(set(bs.csnc[bs.kept].tolist()))
    shown = kept_ids[:max_panels]
    path_csnc = path.get("csnc") if path and path.get("waypoints") else None
    colors = csnc_colors(len(kept_ids))
    npan = 1 + len(shown)
    ncol = min(npan, 6 if npan > 12 else (4 if npan > 4 else npan))
    nrow = (npan + ncol - 1) // ncol
    side = 6.0 if npan == 1 else (3.4 if npan <= 12 else 2.6)
    extent = ~np.isnan(bs.lo[:, ix])
    xr = np.nanmax(bs.hi[:, ix]) - np.nanmin(bs.lo[:, ix]) if extent.any() else 1.0
    yr = np.nanmax(bs.hi[:, iy]) - np.nanmin(bs.lo[:, iy]) if extent.any() else 1.0
    ratio = yr / xr if xr > 0 else 1.0
    pw, ph = (side, max(0.45 * side, side * ratio)) if ratio < 1 else \
        (max(0.45 * side, side / ratio), side)
    pw += 0.45
    fig, axes = plt.subplots(nrow, ncol, figsize=(pw * ncol + 0.4, (ph + 0.45) * nrow + 1.6),
                             squeeze=False)
    for ax in axes.flat[npan:]:
        ax.axis("off")
    und_cap = max(10_000, min(MAX_POLYS, 600_000 // npan))
    uz = 3 if undecided_on_top else 1

    def undecided_layers(ax, alpha):
        nr = add_rects(ax, bs, bs.singular_bd, ix, iy, RED, alpha=alpha, cap=und_cap, zorder=uz)
        nb = (0, 0)
        if constraint:
            nb = add_rects(ax, bs, bs.constraint_bd, ix, iy, BLUE, alpha=alpha, cap=und_cap,
                           zorder=uz + 0.5)
        add_rects(ax, bs, bs.unexplored, ix, iy, GREY, alpha=alpha, cap=und_cap, zorder=uz)
        return nr, nb

    def decorate(ax):
        set_limits(ax, bs, extent, ix, iy)
        ax.set_aspect("equal")
        if obstacle is not None:
            ax.add_patch(Circle(obstacle[:2], obstacle[2], color="k", zorder=6))
        ax.tick_params(labelsize=7)
        ax.set_xlabel(bs.vars[ix], fontsize=8)
        ax.set_ylabel(bs.vars[iy], fontsize=8)

    ax0 = axes.flat[0]
    # Filtered-out CSNCs (the size-ratio heuristic's small ones) in light grey beneath.
    add_rects(ax0, bs, bs.solution & ~bs.kept, ix, iy, "0.82", zorder=1.5)
    for j, k in enumerate(kept_ids):
        add_rects(ax0, bs, bs.csnc == k, ix, iy, colors[j], zorder=2)
    nr, nb = undecided_layers(ax0, 0.35)
    decorate(ax0)
    if path_csnc is not None:
        draw_path_2d(ax0, bs, path, ix, iy)
    sub = []
    if nr[0] < nr[1]:
        sub.append(f"red subsampled {nr[0]}/{nr[1]}")
    if nb[0] < nb[1]:
        sub.append(f"blue subsampled {nb[0]}/{nb[1]}")
    ax0.set_title(f"all {len(kept_ids)} kept CSNCs" + (f"\n({', '.join(sub)})" if sub else ""),
                  fontsize=9)
    for j, k in enumerate(shown):
        ax = axes.flat[1 + j]
        m = bs.csnc == k
        add_rects(ax, bs, m, ix, iy, colors[j], zorder=2)
        undecided_layers(ax, 0.5)
        decorate(ax)
        if k == path_csnc:
            draw_path_2d(ax, bs, path, ix, iy)
        ax.set_title(f"CSNC {k}: {int(m.sum())} boxes", fontsize=8)
    handles = [Patch(color=colors[j], label=f"CSNC {k} ({int((bs.csnc == k).sum())} boxes)")
               for j, k in enumerate(kept_ids[:legend_csncs])]
    if len(kept_ids) > legend_csncs:
        handles.append(Patch(color="w", label=f"... {len(kept_ids) - legend_csncs} more "
                             "kept CSNCs"))
    if (bs.solution & ~bs.kept).any():
        handles.append(Patch(color="0.82", label=f"{bs.csnc_count - len(kept_ids)} CSNCs "
                             "filtered out (small)"))
    handles += undecided_handles(bs, constraint) + path_handles(path)
    if obstacle is not None:
        handles.append(Patch(color="k", label="obstacle"))
    more = f" (first {len(shown)} of {len(kept_ids)} shown)" if len(shown) < len(kept_ids) else ""
    fig.suptitle(f"{title}{bs.title()}: {len(kept_ids)} filtered CSNCs of {bs.csnc_count} "
                 f"projected on ({bs.vars[ix]}, {bs.vars[iy]}){more}", fontsize=11)
    ncols_leg = 1 if npan == 1 else min(4, max(1, len(handles) // 3 + 1))
    fig.legend(handles=handles, loc="lower center", ncol=ncols_leg, fontsize=8, frameon=False)
    legend_rows = math.ceil(len(handles) / ncols_leg)
    bottom = min(0.45, (0.22 * legend_rows + 0.1) / fig.get_figheight())
    fig.tight_layout(rect=(0, bottom, 1, 1 - 0.5 / fig.get_figheight()), h_pad=1.5)
    return fig


def cuboid_faces(lo, hi):
    faces = []
    for b0, b1 in zip(lo, hi):
        x0, y0, z0 = b0
        x1, y1, z1 = b1
        c = np.array([[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0],
                      [x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]])
        for f in ((0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (2, 3, 7, 6), (1, 2, 6, 5),
                  (0, 3, 7, 4)):
            faces.append(c[list(f)])
    return faces


def draw_3d(ax, bs, mask, cols, color, max_cuboids=2500, max_points=60000, alpha=0.55):
    """Cuboids when few, else the box centres (subsampled beyond max_points)."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    idx = np.flatnonzero(mask)
    lo, hi = bs.lo[idx][:, cols], bs.hi[idx][:, cols]
    if len(idx) <= max_cuboids:
        if len(idx):
            pc = Poly3DCollection(cuboid_faces(lo, hi), facecolors=color, edgecolors="k",
                                  linewidths=0.15, alpha=alpha)
            ax.add_collection3d(pc)
        how = "boxes"
    else:
        sel = np.arange(len(idx))
        if len(idx) > max_points:
            sel = rng().choice(len(idx), size=max_points, replace=False)
        c = 0.5 * (lo[sel] + hi[sel])
        ax.scatter(c[:, 0], c[:, 1], c[:, 2], s=0.3, c=[color], alpha=0.35, depthshade=False,
                   linewidths=0)
        how = f"box centres{' (subsampled %d)' % len(sel) if len(sel) < len(idx) else ''}"
    return len(idx), how


def csnc_3d(bs, title, path=None, largest=2):
    """Three pose coordinates in 3-D: the undecided boxes, then the largest CSNCs (and the
    path's CSNC with the path, when it is not among them)."""
    names = [bs.vars[c] for c in bs.pose]
    cols = [bs.col(v) for v in ("x1", "x2", "x3")] if all(
        v in names for v in ("x1", "x2", "x3")) else bs.pose[:3]
    ids = sorted(set(bs.csnc[bs.csnc >= 0].tolist()))[:largest]
    path_csnc = path.get("csnc") if path and path.get("waypoints") else None
    if path_csnc is not None and path_csnc not in ids:
        ids.append(path_csnc)
    panels = [("undecided boxes", bs.undecided, RED, None)]
    cc = csnc_colors(len(ids))
    for j, k in enumerate(ids):
        kept = k < bs.n_kept
        panels.append((f"CSNC {k} ({'kept' if kept else 'filtered out'})", bs.csnc == k, cc[j],
                       k))
    fig = plt.figure(figsize=(4.4 * len(panels), 5.0))
    known = ~np.isnan(bs.lo[:, cols[0]])
    lim = [(np.nanmin(bs.lo[known, c]), np.nanmax(bs.hi[known, c])) if known.any() else (0, 1)
           for c in cols]
    und = np.flatnonzero(bs.undecided)
    ctx = rng().choice(und, size=min(len(und), 15000), replace=False) if len(und) else und
    for i, (label, m, color, k) in enumerate(panels):
        ax = fig.add_subplot(1, len(panels), i + 1, projection="3d")
        on_path = k is not None and k == path_csnc
        if on_path:
            # Drawn in call order, so the path stays visible in front of the boxes.
            ax.computed_zorder = False
        n, how = draw_3d(ax, bs, m, cols, color, alpha=0.2 if on_path else 0.55)
        if i > 0 and len(ctx):
            # Faint context: where the workspace is (undecided box centres, subsampled).
            c = 0.5 * (bs.lo[ctx][:, cols] + bs.hi[ctx][:, cols])
            ax.scatter(c[:, 0], c[:, 1], c[:, 2], s=0.4, c="0.5", alpha=0.15,
                       depthshade=False, linewidths=0)
        if on_path:
            segs = path_segments(bs, path, cols)
            for a, b in segs:
                ax.plot([a[0], b[0]], [a[1], b[1]], [a[2], b[2]], "-o", color=PATH_COLOR,
                        lw=2.0, ms=2.5, zorder=10)
            if segs:
                ax.scatter(*[[v] for v in segs[0][0]], marker="s", s=60, c="#2ca02c",
                           edgecolors="k", depthshade=False, zorder=11)
                ax.scatter(*[[v] for v in segs[-1][1]], marker="*", s=160, c="#ffdd00",
                           edgecolors="k", depthshade=False, zorder=11)
        ax.set_xlim(*lim[0])
        ax.set_ylim(*lim[1])
        ax.set_zlim(*lim[2])
        ax.set_xlabel(bs.vars[cols[0]])
        ax.set_ylabel(bs.vars[cols[1]])
        ax.set_zlabel(bs.vars[cols[2]])
        ax.set_title(f"{label}: {n} {how}", fontsize=9)
        ax.view_init(elev=22, azim=-60)
    extra = f" (first three of {len(bs.pose)} pose variables)" if len(bs.pose) > 3 else ""
    fig.suptitle(f"{title}{bs.title()}: pose space ({', '.join(bs.vars[c] for c in cols)})"
                 f"{extra}; undecided boxes, then the {min(largest, len(ids))} largest of "
                 f"{bs.csnc_count} CSNCs ({bs.n_kept} kept by the filter)", fontsize=10)
    handles = [Patch(color=RED, label="undecided boxes")] + \
        [Patch(color=cc[j], label=f"CSNC {k}") for j, k in enumerate(ids)] + \
        [Patch(color="0.5", alpha=0.4, label="undecided box centres (context)")] + \
        path_handles(path)
    fig.legend(handles=handles, loc="lower center", ncol=min(6, len(handles)), fontsize=8,
               frameon=False)
    fig.subplots_adjust(left=0.01, right=0.97, top=0.86, bottom=0.1, wspace=0.05)
    return fig


def csnc_strips(bs, title, path=None):
    """One pose variable: each CSNC's projection on the pose axis, one row per CSNC."""
    c = bs.pose[0]
    ids = sorted(set(bs.csnc[bs.csnc >= 0].tolist()))[:30]
    colors = csnc_colors(len(ids))
    fig, ax = plt.subplots(figsize=(9, 1.2 + 0.35 * (len(ids) + 1)))
    for j, k in enumerate(ids):
        m = bs.csnc == k
        for a, b in zip(bs.lo[m, c], bs.hi[m, c]):
            ax.plot([a, b], [j, j], color=colors[j], lw=6, solid_capstyle="butt")
    m = bs.undecided
    for a, b in zip(bs.lo[m, c], bs.hi[m, c]):
        ax.plot([a, b], [-1, -1], color=RED, lw=6, solid_capstyle="butt")
    ax.set_yticks([-1] + list(range(len(ids))))
    ax.set_yticklabels(["undecided"] + [f"CSNC {k}{'' if k < bs.n_kept else ' (filtered)'}"
                                        for k in ids], fontsize=8)
    ax.set_xlabel(bs.vars[c])
    ax.set_title(f"{title}{bs.title()}: the CSNCs projected on {bs.vars[c]}", fontsize=10)
    if path and path.get("waypoints"):
        xs = [w["pose"][0] for w in path["waypoints"]]
        k = path.get("csnc")
        y = ids.index(k) if k in ids else -1
        ax.plot(xs, [y] * len(xs), "-o", color=PATH_COLOR, ms=3, label="certified path")
        ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def plot(bs, out=None, path=None, title=""):
    """The figure of a result (see the module's docstring); saved to `out` when given.
    Returns the matplotlib Figure."""
    if len(bs.pose) >= 3:
        fig = csnc_3d(bs, title, path=path)
    elif len(bs.pose) == 2:
        fig = csnc_grid(bs, title, path=path)
    elif len(bs.pose) == 1:
        fig = csnc_strips(bs, title, path=path)
    else:
        raise ValueError("the result has no pose variable to plot")
    if out:
        save(fig, out)
    return fig


def main(argv):
    if len(argv) != 3:
        sys.exit("usage: plotting.py DATA.json OUT.png")
    bs, path = read_data(argv[1])
    fig = plot(bs, out=argv[2], path=path)
    plt.close(fig)


if __name__ == "__main__":
    main(sys.argv)
