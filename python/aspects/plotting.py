"""Pictures of a result: the project's one plotting code.

`aspects plot`, `aspects view`, `aspects export`, `aspects path --plot`, `Result.plot()` and
paper_repro/figures.py draw with these functions (`view` in aspects/view3d.py, `export` in
aspects/meshes.py). The module needs only numpy and matplotlib (not the compiled part of
the package), so the command line runs it as a script:

    /usr/bin/python3 plotting.py DATA.json OUT

where DATA.json (written by results/plot_data.cpp) names a binary file of the boxes (every
variable; an undecided box's command part is NaN: the index keeps its pose part only),
says which figure to make ("kind": plot, view or vtk) and with which options. An
illustration only: nothing drawn here is a claim, except the count in the title, which is
the run's certified one (summary.json), said as what it is.

Every figure first states the certified count ("at least N aspects (certified)"), then
draws the separated representatives (CSNCs certified to lie in pairwise distinct aspects),
then the largest other CSNCs, each in its own colour; the undecided boxes are quiet (light
grey).
- 2 axes: an overview of the drawn CSNCs (translucent fills and outlines, so that none
  hides another), then one panel per CSNC;
- 3 axes: one 3-D panel per CSNC (at most three), the undecided boxes as faint context;
- 1 pose variable: each CSNC's projection on the pose axis.
A path (what `aspects path --json` prints) is drawn on top, on pose axes.
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

try:  # in the package
    from . import raster
except ImportError:
    # Run as a script, or loaded from its path (paper_repro/figures.py): its siblings
    # (raster, solids, view3d, meshes) are imported from its directory.
    _here = os.path.dirname(os.path.abspath(__file__))
    if _here not in sys.path:
        sys.path.insert(0, _here)
    import raster

# Box status codes, as aspects.Result.status holds them (1 + the index's undecided kind).
SOLUTION, NO_EXISTENCE, SINGULAR, CONSTRAINT, UNEXPLORED = 0, 1, 2, 3, 4

DPI = 110
MIN_DPI, MAX_DPI = 10, 2400
MAX_INCHES = 100
MAX_POLYS = 200_000          # rectangles per panel layer before subsampling
DEFAULT_PANELS = 25          # CSNC panels of the 2-D figure unless chosen
DEFAULT_3D_PANELS = 3
OUTLINE_CELLS = 400          # raster cells per axis of the overview's outlines
RED = "#d62728"              # paper_repro's figures only (the paper's colours)
BLUE = "#1f4fd6"
GREY = "0.55"
QUIET = "0.85"               # undecided boxes: light grey, beneath the CSNCs
QUIET_EDGE = "0.74"
QUIET_CONSTRAINT = "#cdd6e2"
QUIET_UNEXPLORED = "0.70"
OTHER = "#e9dfcb"            # CSNCs that are not drawn one by one
PATH_COLOR = "k"


def rng():
    """A fixed seed: the same figure from the same result."""
    return np.random.default_rng(20240521)


def csnc_colors(n):
    base = list(plt.get_cmap("tab10").colors)
    # No grey (the undecided boxes) and no red (paper_repro's undecided boxes).
    base = [c for i, c in enumerate(base) if i not in (3, 7)]
    pal = base + list(plt.get_cmap("tab20b").colors)
    return [pal[i % len(pal)] for i in range(n)]


def aspects_word(n):
    return f"{n} aspect{'' if n == 1 else 's'}"


def boxes_word(n):
    return f"{n} box{'' if n == 1 else 'es'}"


class BoxSet:
    """Boxes of a result: lower and upper ends (one column per variable in `names`; a
    column may be NaN where the result does not record it), status codes, CSNC (-1 for
    undecided boxes), and the number of CSNCs the size-ratio filter keeps (the largest).
    lower_bound: the certified lower bound on the number of aspects (None: not known);
    representatives: CSNCs certified to lie in pairwise distinct aspects; exact, upper: a
    certified exact count or upper bound when one was computed (None: none)."""

    def __init__(self, names, lower, upper, status, csnc, filtered, robot="", eps=None,
                 pose=None, periodic=None, csnc_count=None, lower_bound=None,
                 representatives=(), exact=None, upper_bound=None):
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
        self.lower_bound = None if lower_bound is None else int(lower_bound)
        self.representatives = [int(k) for k in (representatives or [])]
        self.exact = None if exact is None else int(exact)
        self.upper_bound = None if upper_bound is None else int(upper_bound)

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

    def csnc_size(self, k):
        return int((self.csnc == k).sum())


def count_claim(bs):
    """The certified count, said as what it is: an exact count, or a lower bound (and an
    upper bound when one was computed); no number when none is known."""
    if bs.exact is not None:
        return f"exactly {aspects_word(bs.exact)} (certified)"
    if bs.lower_bound is None:
        return "no certified count of aspects recorded"
    if bs.lower_bound == 0:  # "at least 0" would be true and say nothing
        return "no aspect separated yet (certified lower bound 0)"
    claim = f"at least {aspects_word(bs.lower_bound)} (certified)"
    if bs.upper_bound is not None:
        claim += f", at most {bs.upper_bound} (certified)"
    return claim


# ------------------------------------------------------------------------------ options
def resolve_axes(bs, axes=None, counts=(2, 3)):
    """Column indices of the plotted variables: `axes` (names, or "a,b" text), as many as
    one of `counts`; when None, the pose's, as many as it has up to max(counts) (x1, x2 of
    two, x1, x2, x3 of three when it has them). ValueError naming the problem."""
    if axes is None:
        n = min(len(bs.pose), max(counts))
        if n == 0:
            raise ValueError("the result has no pose variable to plot")
        if n == 2:
            return list(bs.workspace_axes())
        names = [bs.vars[c] for c in bs.pose]
        if n == 3 and all(v in names for v in ("x1", "x2", "x3")):
            return [bs.col(v) for v in ("x1", "x2", "x3")]
        return bs.pose[:n]
    names = axes.split(",") if isinstance(axes, str) else list(axes)
    if len(names) not in counts:
        want = " or ".join(str(c) for c in counts)
        raise ValueError(f"axes: give {want} variables, got {len(names)} "
                         f"({', '.join(map(str, names))})")
    cols = []
    for n in names:
        if n not in bs.vars:
            raise ValueError(f"axes: '{n}' is not a variable of {bs.robot} "
                             f"(its variables: {', '.join(bs.vars)})")
        if bs.col(n) in cols:
            raise ValueError(f"axes: '{n}' is given twice")
        cols.append(bs.col(n))
    return cols


def choose_csncs(bs, csncs=None, largest=None, most=DEFAULT_PANELS):
    """The CSNCs to draw, in drawing order: `csncs` as given; else the separated
    representatives first, then the largest others: the `largest` largest CSNCs, or by
    default those the filter keeps, `most` in all."""
    present = sorted(set(bs.csnc[bs.csnc >= 0].tolist()))
    if csncs is not None:
        chosen = []
        for k in csncs:
            if isinstance(k, bool) or not isinstance(k, (int, np.integer)):
                raise ValueError(f"csncs: CSNC numbers are integers, got {k!r}")
            if not 0 <= k < bs.csnc_count:
                raise ValueError(f"csncs: CSNCs are numbered 0 to {bs.csnc_count - 1} "
                                 f"(the result has {bs.csnc_count}), got {k}")
            if k in chosen:
                raise ValueError(f"csncs: CSNC {k} is given twice")
            chosen.append(int(k))
        return chosen
    reps = [k for k in bs.representatives if k in present]
    if largest is not None:
        if isinstance(largest, bool) or not isinstance(largest, (int, np.integer)) or largest < 1:
            raise ValueError(f"largest: a number of CSNCs, at least 1, got {largest!r}")
        pool = present[:largest]
        return [k for k in reps if k in pool] + [k for k in pool if k not in reps]
    pool = [k for k in present if k < bs.n_kept and k not in reps]
    return (reps + pool)[:max(most, 1)]


def check_dpi_size(dpi, size):
    if dpi is not None and (isinstance(dpi, bool) or not isinstance(dpi, (int, np.integer))
                            or not MIN_DPI <= dpi <= MAX_DPI):
        raise ValueError(f"dpi: an integer from {MIN_DPI} to {MAX_DPI}, got {dpi!r}")
    if size is not None:
        ok = isinstance(size, (tuple, list)) and len(size) == 2 and all(
            isinstance(v, (int, float)) and not isinstance(v, bool) and 0 < v <= MAX_INCHES
            for v in size)
        if not ok:
            raise ValueError(f"size: (width, height) in inches, each above 0 and at most "
                             f"{MAX_INCHES}, got {size!r}")


def read_data(meta_path):
    """The BoxSet, the path (or None) and the figure's options (a dict: kind, out, axes,
    csncs, largest, dpi, size, ...) of a DATA.json written by results/plot_data.cpp."""
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
                pose=d["pose"], periodic=d["periodic"], csnc_count=d["csnc_count"],
                lower_bound=d.get("lower_bound"), representatives=d.get("representatives"))
    return bs, d.get("path"), d.get("figure") or {}


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


def save(fig, out, dpi=None):
    """Writes the figure under a temporary name, then renames it (never a half file). The
    format follows the name's extension (PNG, PDF, SVG, ...)."""
    root, ext = os.path.splitext(out)
    tmp = f"{root}.tmp{os.getpid()}{ext or '.png'}"
    try:
        # SVG text as text, not outlines: a paper's editor can change it, a test can read it.
        with matplotlib.rc_context({"svg.fonttype": "none"}):
            fig.savefig(tmp, dpi=DPI if dpi is None else dpi)
        os.replace(tmp, out)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


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


def finite_on(bs, mask, cols):
    """mask, less the boxes with no extent on one of `cols` (an undecided box on a command
    variable: the index keeps its pose part only)."""
    m = mask.copy()
    for c in cols:
        m &= ~np.isnan(bs.lo[:, c])
    return m


def undecided_layers(ax, bs, ix, iy, constraint=True, cap=MAX_POLYS, zorder=1):
    """The undecided boxes, quiet: light grey beneath the CSNCs, with thin grey edges when
    few enough to tell apart."""
    def layer(mask, color):
        n = int(finite_on(bs, mask, (ix, iy)).sum())
        edge, lw = (QUIET_EDGE, 0.2) if n <= 5000 else (None, 0.0)
        return add_rects(ax, bs, finite_on(bs, mask, (ix, iy)), ix, iy, color, edge=edge,
                         lw=lw, cap=cap, zorder=zorder)
    layer(bs.singular_bd if constraint else bs.singular_bd | bs.constraint_bd, QUIET)
    if constraint:
        layer(bs.constraint_bd, QUIET_CONSTRAINT)
    layer(bs.unexplored, QUIET_UNEXPLORED)


def undecided_handles(bs, cols, constraint=True):
    h = []
    shown = finite_on(bs, bs.undecided, cols)
    if bs.undecided.any() and not shown.any():
        return [Patch(color="w", label=f"undecided boxes ({int(bs.undecided.sum())}) not drawn: "
                      "the result keeps their pose part only")]
    singular = bs.singular_bd if constraint else bs.singular_bd | bs.constraint_bd
    if singular.any():
        h.append(Patch(facecolor=QUIET, edgecolor=QUIET_EDGE, label=f"undecided "
                       f"({int(singular.sum())} boxes: singular or unresolved)"))
    if constraint and bs.constraint_bd.any():
        h.append(Patch(facecolor=QUIET_CONSTRAINT, edgecolor=QUIET_EDGE, label="constraint "
                       f"boundary ({int(bs.constraint_bd.sum())} boxes)"))
    if bs.unexplored.any():
        h.append(Patch(facecolor=QUIET_UNEXPLORED, edgecolor=QUIET_EDGE, label="unexplored "
                       f"({int(bs.unexplored.sum())} boxes: the run was stopped)"))
    return h


def csnc_label(bs, k):
    sep = ", separated" if k in bs.representatives else ""
    return f"CSNC {k} ({boxes_word(bs.csnc_size(k))}){sep}"


def csnc_handles(bs, shown, colors, legend_csncs=None):
    n = len(shown) if legend_csncs is None else legend_csncs
    h = [Patch(facecolor=colors[j], edgecolor=colors[j], label=csnc_label(bs, k))
         for j, k in enumerate(shown[:n])]
    if len(shown) > n:
        h.append(Patch(color="w", label=f"... {len(shown) - n} more CSNCs drawn"))
    others = bs.solution & (bs.csnc >= 0) & ~np.isin(bs.csnc, shown)
    if others.any():
        count = len(set(bs.csnc[others].tolist()))
        h.append(Patch(color=OTHER, label=f"{count} other CSNC{'s' if count > 1 else ''} "
                       f"({boxes_word(int(others.sum()))}), not drawn one by one"))
    return h


def drawn_line(bs, shown, cols):
    """What the figure draws, for its title's second line."""
    reps = sum(1 for k in shown if k in bs.representatives)
    sep = f", the {reps} separated first (certified in pairwise distinct aspects)" if reps else ""
    where = ", ".join(bs.vars[c] for c in cols)
    return f"{len(shown)} of {bs.csnc_count} CSNCs drawn{sep}; on ({where})"


TINY_CSNC = 10               # boxes: at most this many get a ring around each (visible)


def ring_tiny(ax, bs, mask, ix, iy, color, zorder=4.5):
    """A ring around each box of a CSNC of at most TINY_CSNC boxes, which would otherwise
    be a speck (RRRRR at eps 0.5: two separated CSNCs of one box each)."""
    if 0 < int(mask.sum()) <= TINY_CSNC:
        cx = 0.5 * (bs.lo[mask, ix] + bs.hi[mask, ix])
        cy = 0.5 * (bs.lo[mask, iy] + bs.hi[mask, iy])
        ax.scatter(cx, cy, s=90, facecolors="none", edgecolors=[color], linewidths=1.4,
                   zorder=zorder)


def draw_outline(ax, bs, mask, ix, iy, color, grid, zorder=4):
    """The outline of the union of the boxes in mask, from their raster on `grid`."""
    occ = raster.occupancy(grid, bs.lo[mask][:, [ix, iy]], bs.hi[mask][:, [ix, iy]])
    if occ.any():
        cs = ax.contour(grid.centres(0), grid.centres(1), occ.T.astype(float), levels=[0.5],
                        colors=[color], linewidths=1.0, zorder=zorder)
        for c in cs.collections:
            c.set_gid("outline")  # in an SVG too


def draw_overview(ax, bs, ix, iy, shown, colors, constraint=True, cap=MAX_POLYS):
    """Every drawn CSNC on one panel without hiding one behind another: translucent fills
    and an outline each; the other CSNCs pale beneath; the undecided boxes quiet."""
    undecided_layers(ax, bs, ix, iy, constraint, cap=cap, zorder=1)
    add_rects(ax, bs, bs.solution & (bs.csnc >= 0) & ~np.isin(bs.csnc, shown), ix, iy, OTHER,
              cap=cap, zorder=1.5)
    drawn = bs.solution & np.isin(bs.csnc, shown)
    if not drawn.any():
        return
    grid = raster.Grid.around(bs.lo[drawn][:, [ix, iy]], bs.hi[drawn][:, [ix, iy]],
                              OUTLINE_CELLS)
    for j, k in enumerate(shown):
        m = bs.csnc == k
        add_rects(ax, bs, m, ix, iy, colors[j], alpha=0.35, cap=cap, zorder=2)
        draw_outline(ax, bs, m, ix, iy, colors[j], grid)
        ring_tiny(ax, bs, m, ix, iy, colors[j])


def decorate_2d(ax, bs, ix, iy, obstacle=None):
    from matplotlib.patches import Circle
    set_limits(ax, bs, finite_on(bs, np.ones(len(bs.status), bool), (ix, iy)), ix, iy)
    if ix in bs.pose and iy in bs.pose:
        ax.set_aspect("equal")
    if obstacle is not None:
        ax.add_patch(Circle(obstacle[:2], obstacle[2], color="k", zorder=6))
    ax.tick_params(labelsize=7)
    ax.set_xlabel(bs.vars[ix], fontsize=8)
    ax.set_ylabel(bs.vars[iy], fontsize=8)


def check_path_axes(bs, path, cols):
    if path and path.get("waypoints") and not all(c in bs.pose for c in cols):
        raise ValueError("path: a path is drawn in pose coordinates, and "
                         f"{', '.join(bs.vars[c] for c in cols if c not in bs.pose)} "
                         "is not a pose variable (leave the path out, or choose pose axes)")


def csnc_grid(bs, title, constraint=True, obstacle=None, max_panels=DEFAULT_PANELS + 1,
              undecided_on_top=True, path=None, legend_csncs=10, axes=None, csncs=None,
              largest=None, size=None):
    """The overview of the drawn CSNCs (draw_overview), then one panel per CSNC with the
    undecided boxes quiet beneath. undecided_on_top is kept for paper_repro's calls: the
    undecided boxes are always beneath now."""
    del undecided_on_top
    ix, iy = resolve_axes(bs, axes, counts=(2,))
    check_path_axes(bs, path, (ix, iy))
    shown = choose_csncs(bs, csncs, largest, most=max_panels - 1)
    path_csnc = path.get("csnc") if path and path.get("waypoints") else None
    colors = csnc_colors(len(shown))
    npan = 1 + len(shown)
    ncol = min(npan, 6 if npan > 12 else (4 if npan > 4 else npan))
    nrow = (npan + ncol - 1) // ncol
    side = 6.0 if npan == 1 else (3.4 if npan <= 12 else 2.6)
    extent = finite_on(bs, np.ones(len(bs.status), bool), (ix, iy))
    xr = np.nanmax(bs.hi[extent, ix]) - np.nanmin(bs.lo[extent, ix]) if extent.any() else 1.0
    yr = np.nanmax(bs.hi[extent, iy]) - np.nanmin(bs.lo[extent, iy]) if extent.any() else 1.0
    ratio = yr / xr if xr > 0 else 1.0
    pw, ph = (side, max(0.45 * side, side * ratio)) if ratio < 1 else \
        (max(0.45 * side, side / ratio), side)
    pw += 0.45
    figsize = size or (pw * ncol + 0.4, (ph + 0.45) * nrow + 1.9)
    fig, axs = plt.subplots(nrow, ncol, figsize=figsize, squeeze=False)
    for ax in axs.flat[npan:]:
        ax.axis("off")
    cap = max(10_000, min(MAX_POLYS, 600_000 // npan))

    ax0 = axs.flat[0]
    draw_overview(ax0, bs, ix, iy, shown, colors, constraint, cap=cap)
    decorate_2d(ax0, bs, ix, iy, obstacle)
    if path_csnc is not None:
        draw_path_2d(ax0, bs, path, ix, iy)
    ax0.set_title(f"the {len(shown)} drawn CSNCs together", fontsize=9)
    for j, k in enumerate(shown):
        ax = axs.flat[1 + j]
        undecided_layers(ax, bs, ix, iy, constraint, cap=cap, zorder=1)
        add_rects(ax, bs, bs.csnc == k, ix, iy, colors[j], zorder=2)
        ring_tiny(ax, bs, bs.csnc == k, ix, iy, colors[j])
        decorate_2d(ax, bs, ix, iy, obstacle)
        if k == path_csnc:
            draw_path_2d(ax, bs, path, ix, iy)
        sep = ", separated" if k in bs.representatives else ""
        ax.set_title(f"CSNC {k}: {boxes_word(bs.csnc_size(k))}{sep}", fontsize=8)
    handles = csnc_handles(bs, shown, colors, legend_csncs)
    handles += undecided_handles(bs, (ix, iy), constraint) + path_handles(path)
    if obstacle is not None:
        handles.append(Patch(color="k", label="obstacle"))
    fig.suptitle(f"{title}{bs.title()}: {count_claim(bs)}\n{drawn_line(bs, shown, (ix, iy))}",
                 fontsize=11)
    ncols_leg = 1 if npan == 1 else min(4, max(1, len(handles) // 3 + 1))
    fig.legend(handles=handles, loc="lower center", ncol=ncols_leg, fontsize=8, frameon=False)
    legend_rows = math.ceil(len(handles) / ncols_leg)
    bottom = min(0.45, (0.22 * legend_rows + 0.1) / fig.get_figheight())
    fig.tight_layout(rect=(0, bottom, 1, 1 - 0.75 / fig.get_figheight()), h_pad=2.2)
    return fig


def draw_into(ax, bs, cols, path=None, csncs=None, largest=None, title=""):
    """The overview alone, into a given matplotlib axes (Result.plot(ax=...)): the drawn
    CSNCs, the undecided boxes, the path, a legend, and the count as the axes' title."""
    ix, iy = cols
    check_path_axes(bs, path, cols)
    shown = choose_csncs(bs, csncs, largest)
    colors = csnc_colors(len(shown))
    draw_overview(ax, bs, ix, iy, shown, colors)
    decorate_2d(ax, bs, ix, iy)
    if path and path.get("waypoints"):
        draw_path_2d(ax, bs, path, ix, iy)
    handles = csnc_handles(bs, shown, colors) + undecided_handles(bs, cols) + path_handles(path)
    ax.legend(handles=handles, fontsize=7, loc="best")
    ax.set_title(f"{title}{bs.title()}: {count_claim(bs)}", fontsize=9)
    return ax.figure


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


def csnc_3d(bs, title, path=None, largest=None, axes=None, csncs=None, size=None):
    """Three variables in 3-D: one panel per drawn CSNC (the separated first, at most
    DEFAULT_3D_PANELS unless chosen), the undecided boxes as faint grey context, and the
    path's CSNC with the path when it is not among them. For turning it: `aspects view`."""
    cols = resolve_axes(bs, axes, counts=(3,))
    check_path_axes(bs, path, cols)
    ids = choose_csncs(bs, csncs, largest, most=DEFAULT_3D_PANELS)
    path_csnc = path.get("csnc") if path and path.get("waypoints") else None
    if path_csnc is not None and path_csnc not in ids:
        ids.append(path_csnc)
    cc = csnc_colors(len(ids))
    fig = plt.figure(figsize=size or (4.6 * max(1, len(ids)), 5.4))
    known = finite_on(bs, np.ones(len(bs.status), bool), cols)
    lim = [(np.nanmin(bs.lo[known, c]), np.nanmax(bs.hi[known, c])) if known.any() else (0, 1)
           for c in cols]
    und = np.flatnonzero(finite_on(bs, bs.undecided, cols))
    ctx = rng().choice(und, size=min(len(und), 15000), replace=False) if len(und) else und
    for i, k in enumerate(ids):
        ax = fig.add_subplot(1, len(ids), i + 1, projection="3d")
        on_path = k == path_csnc
        if on_path:
            # Drawn in call order, so the path stays visible in front of the boxes.
            ax.computed_zorder = False
        n, how = draw_3d(ax, bs, bs.csnc == k, cols, cc[i], alpha=0.2 if on_path else 0.55)
        if len(ctx):
            c = 0.5 * (bs.lo[ctx][:, cols] + bs.hi[ctx][:, cols])
            ax.scatter(c[:, 0], c[:, 1], c[:, 2], s=0.4, c=QUIET_UNEXPLORED, alpha=0.12,
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
        sep = ", separated" if k in bs.representatives else ""
        ax.set_title(f"CSNC {k}{sep}: {n} {how}", fontsize=9)
        ax.view_init(elev=22, azim=-60)
    fig.suptitle(f"{title}{bs.title()}: {count_claim(bs)}\n{drawn_line(bs, ids, cols)}",
                 fontsize=10)
    handles = csnc_handles(bs, ids, cc)
    if len(ctx):
        handles.append(Patch(color=QUIET_UNEXPLORED, alpha=0.4,
                             label="undecided box centres (context)"))
    handles += path_handles(path)
    fig.legend(handles=handles, loc="lower center", ncol=min(4, len(handles)), fontsize=8,
               frameon=False)
    fig.subplots_adjust(left=0.01, right=0.97, top=0.84, bottom=0.12, wspace=0.05)
    return fig


def csnc_strips(bs, title, path=None, csncs=None, largest=None, size=None):
    """One pose variable: each CSNC's projection on the pose axis, one row per CSNC."""
    c = bs.pose[0]
    ids = choose_csncs(bs, csncs, largest, most=30)
    colors = csnc_colors(len(ids))
    fig, ax = plt.subplots(figsize=size or (9, 1.6 + 0.35 * (len(ids) + 1)))
    for j, k in enumerate(ids):
        m = bs.csnc == k
        for a, b in zip(bs.lo[m, c], bs.hi[m, c]):
            ax.plot([a, b], [j, j], color=colors[j], lw=6, solid_capstyle="butt")
    m = bs.undecided
    for a, b in zip(bs.lo[m, c], bs.hi[m, c]):
        ax.plot([a, b], [-1, -1], color=QUIET, lw=4, solid_capstyle="butt")
    ax.set_yticks([-1] + list(range(len(ids))))
    ax.set_yticklabels(["undecided"] + [csnc_label(bs, k) for k in ids], fontsize=8)
    ax.set_xlabel(bs.vars[c])
    ax.set_title(f"{title}{bs.title()}: {count_claim(bs)}\n{drawn_line(bs, ids, [c])}",
                 fontsize=10)
    if path and path.get("waypoints"):
        xs = [w["pose"][0] for w in path["waypoints"]]
        k = path.get("csnc")
        y = ids.index(k) if k in ids else -1
        ax.plot(xs, [y] * len(xs), "-o", color=PATH_COLOR, ms=3, label="certified path")
        ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def plot(bs, out=None, path=None, title="", axes=None, csncs=None, largest=None, dpi=None,
         size=None, ax=None):
    """The figure of a result (see the module's docstring); saved to `out` when given (the
    format from its extension). axes: two or three variable names (pose or command), as a
    list or "a,b" text; csncs: the CSNCs to draw (numbers), or largest: the N largest;
    dpi; size: (width, height) in inches; ax: a 2-D matplotlib axes to draw the overview
    into (two axes only). Returns the matplotlib Figure. ValueError for a bad option."""
    check_dpi_size(dpi, size)
    if csncs is not None and largest is not None:
        raise ValueError("csncs and largest: give one of them")
    if axes is None and len(bs.pose) == 1:
        if ax is not None:
            raise ValueError("ax: the figure of one pose variable has its own axes")
        fig = csnc_strips(bs, title, path=path, csncs=csncs, largest=largest, size=size)
    else:
        cols = resolve_axes(bs, axes, counts=(2, 3))
        if ax is not None:
            if len(cols) != 2:
                raise ValueError("ax: draws two axes; give axes= two variables (3-D: "
                                 "`aspects view`)")
            fig = draw_into(ax, bs, cols, path=path, csncs=csncs, largest=largest, title=title)
        elif len(cols) == 3:
            fig = csnc_3d(bs, title, path=path, largest=largest,
                          axes=[bs.vars[c] for c in cols], csncs=csncs, size=size)
        else:
            fig = csnc_grid(bs, title, path=path, axes=[bs.vars[c] for c in cols],
                            csncs=csncs, largest=largest, size=size)
    if out:
        save(fig, out, dpi)
    return fig


def _sibling(name):
    """aspects.NAME in the package, NAME when run as a script from this directory."""
    import importlib
    return importlib.import_module(f".{name}", __package__) if __package__ else \
        importlib.import_module(name)


def main(argv):
    if len(argv) != 3:
        sys.exit("usage: plotting.py DATA.json OUT")
    bs, path, opt = read_data(argv[1])
    kind = opt.get("kind", "plot")
    size = tuple(opt["size"]) if opt.get("size") else None
    common = dict(axes=opt.get("axes"), csncs=opt.get("csncs"), largest=opt.get("largest"))
    if kind == "plot":
        fig = plot(bs, out=argv[2], path=path, dpi=opt.get("dpi"), size=size, **common)
        plt.close(fig)
    elif kind == "view":
        _sibling("view3d").write_view(bs, argv[2], voxels=opt.get("voxels", False),
                                      cells=opt.get("cells"), **common)
    elif kind == "vtk":
        _sibling("meshes").write_vtk(bs, argv[2], voxels=opt.get("voxels", False),
                                     cells=opt.get("cells"), **common)
    else:
        sys.exit(f"plotting.py: unknown figure kind {kind!r}")


if __name__ == "__main__":
    main(sys.argv)
