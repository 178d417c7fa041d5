#!/usr/bin/python3
"""Numerical, NOT certified, grid components of the full 3-RRR (robots/3rrr.robot): no count of its aspects.

Samples the pose (x1, x2, x3) on a regular grid, x3 periodic. For each pose and each of the
8 working modes (the branch of each leg's inverse kinematics, q_i = phi_i +- acos(d_i / 20)),
the commands are determined, so a working mode is a continuous sheet of the configuration
manifold over the poses where every leg is reachable (0 < d_i < 20). Fq is diagonal: its
entries vanish only where a leg is stretched or folded (d_i = 20 or 0), the edges of the
sheet, so each sheet has constant det Fq signs. A generalized aspect is then a connected set
of grid cells of one sheet where det Fx keeps its sign, found by flood fill (face
neighbours, and across the x3 = +-pi seam).

What sampling cannot see: a neck or a component thinner than the grid step, a sign of det Fx
at a point where it is nearly zero, and the slivers near a stretched leg (d_i = 20), where
q_i behaves like sqrt(20 - d_i) so that an aspect there can be quadratically thin in the
pose (a regular pose grid has no chart in the leg angles there). An independent study with
such charts finds small aspects near the corners where two d_i = 20 surfaces meet that this
grid does not see. Hence only the thick components are counted (see components()), and the
result is labelled numerical: it is not the number of aspects.

Usage: robots/3rrr_sampling.py [N ...] [--slice X3] [--json FILE]    (N: cells per axis, default 64 128)
"""
import argparse
import json
import math
import sys

import numpy as np
from scipy import ndimage

L = 10.0  # both link lengths, from the model
BASES = ((10.0, 10.0), (10.0, 10.0), (0.0, 10.0))  # A1, A2, A3, read off robots/3rrr.robot
R2 = 10.0 * math.sqrt(2.0)


def platform_points(x1, x2, x3):
    """P_i(x) and dP_i/dx3, as the model's equations write them."""
    c, s = np.cos(x3), np.sin(x3)
    c4, s4 = np.cos(x3 + math.pi / 4), np.sin(x3 + math.pi / 4)
    pts = ((x1, x2), (x1 + L * c, x2 + L * s), (x1 + R2 * c4, x2 + R2 * s4))
    dx3 = ((0.0 * x1, 0.0 * x2), (-L * s, L * c), (-R2 * s4, R2 * c4))
    return pts, dx3


def sheet(x1, x2, x3, mode):
    """On one working mode: (valid, sign det Fx, signs of the Fq diagonal) per grid point."""
    pts, dx3 = platform_points(x1, x2, x3)
    rows, fq = [], []
    valid = np.ones(np.broadcast(x1, x2, x3).shape, dtype=bool)
    for (px, py), (dpx, dpy), (ax, ay), s in zip(pts, dx3, BASES, mode):
        ux, uy = px - ax, py - ay
        d = np.hypot(ux, uy)
        valid &= (d > 0) & (d < 2 * L)
        q = np.arctan2(uy, ux) + s * np.arccos(np.clip(d / (2 * L), -1.0, 1.0))
        # f_i = |P_i - E_i|^2 - L^2 with E_i = A_i + L (cos q, sin q)
        ex, ey = px - ax - L * np.cos(q), py - ay - L * np.sin(q)
        rows.append((2 * ex, 2 * ey, 2 * (ex * dpx + ey * dpy)))
        fq.append(2 * L * (ex * np.sin(q) - ey * np.cos(q)))
    (a, b, c), (d, e, f), (g, h, i) = rows
    det_fx = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    return valid, np.sign(det_fx), [np.sign(v) for v in fq]


def components(mask, periodic):
    """Face-connected components of a 2-D or 3-D mask (periodic along the last axis when
    asked), as (cells, thick) sorted by size: thick when the component holds a cell whose
    every neighbour, diagonals included, is in the mask. A sliver one or two cells thick
    along a boundary, where sampling aliases, is not thick; a real component becomes thick
    once the grid resolves it."""
    labels, n = ndimage.label(mask)
    parent = list(range(n + 1))

    def find(k):
        while parent[k] != k:
            parent[k] = parent[parent[k]]
            k = parent[k]
        return k

    if periodic:
        a, b = labels[..., 0], labels[..., -1]
        for u, v in zip(a[(a > 0) & (b > 0)], b[(a > 0) & (b > 0)]):
            ru, rv = find(u), find(v)
            if ru != rv:
                parent[ru] = rv
    roots = np.array([find(k) for k in range(n + 1)])[labels]
    sizes = np.bincount(roots.ravel(), minlength=n + 1)
    wrap = [(0, 0)] * (mask.ndim - 1) + [(1, 1) if periodic else (0, 0)]
    padded = np.pad(mask, wrap, mode="wrap") if periodic else mask
    core = ndimage.binary_erosion(padded, structure=np.ones((3,) * mask.ndim), border_value=0)
    if periodic:
        core = core[..., 1:-1]
    thick = np.zeros(n + 1, dtype=bool)
    thick[np.unique(roots[core])] = True
    comps = sorted(((int(sizes[k]), bool(thick[k]), k) for k in range(1, n + 1) if sizes[k] > 0),
                   reverse=True)
    # Where the second largest lies (grid indices, the range of each axis): where a
    # further aspect of this class would be, if it is one.
    where = None
    if len(comps) > 1:
        idx = np.nonzero(roots == comps[1][2])
        where = [(int(i.min()), int(i.max())) for i in idx]
    return [(c, t) for c, t, _ in comps], where


def count(n, x3_slice=None):
    """Components of every (mode, sign det Fx) class at n cells per axis (cell centres).
    With x3_slice, the 2-D slice at that orientation (3-RRR*'s is 0), not periodic."""
    lo, hi = -10.0, 30.0  # |P1 - A1| < 20 confines (x1, x2) to this square
    g = lo + (np.arange(n) + 0.5) * (hi - lo) / n
    if x3_slice is None:
        t, dt = -math.pi + (np.arange(n) + 0.5) * 2 * math.pi / n, 2 * math.pi / n
    else:
        t, dt = np.array([x3_slice]), 1.0
    cell = ((hi - lo) / n) ** 2 * dt
    classes = []
    for mode in [(s1, s2, s3) for s1 in (1, -1) for s2 in (1, -1) for s3 in (1, -1)]:
        # sign of det Fx on the sheet, 0 where a leg cannot reach; computed in slabs of x1
        # so that a fine grid fits in memory
        signs = np.zeros((n, n, len(t)), dtype=np.int8)
        fq_seen = [set() for _ in mode]
        for a in range(0, n, 16):
            x1, x2, x3 = np.meshgrid(g[a:a + 16], g, t, indexing="ij")
            valid, sdx, sfq = sheet(x1, x2, x3, mode)
            signs[a:a + 16] = np.where(valid, sdx, 0)
            for seen, v in zip(fq_seen, sfq):
                seen.update(np.unique(v[valid & (v != 0)]).astype(int).tolist())
        fq_signs = tuple(seen.pop() if len(seen) == 1 else 0 for seen in fq_seen)
        for sign in (1, -1):
            mask = signs == sign
            comps, where = (components(mask, True) if x3_slice is None
                            else components(mask[:, :, 0], False))
            if where is not None:  # grid indices to pose coordinates
                axes = [g, g, t][:len(where)]
                where = [(float(a[i]), float(a[j])) for a, (i, j) in zip(axes, where)]
            classes.append(dict(mode=mode, fq_signs=fq_signs, det_fx=sign,
                                sizes=[cells for cells, _ in comps],
                                thick=sum(1 for _, is_thick in comps if is_thick),
                                volume=sum(cells for cells, _ in comps) * cell,
                                second_where=where))
    return classes


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("n", nargs="*", type=int, default=[64, 128])
    ap.add_argument("--json", help="write the counts here")
    ap.add_argument("--slice", type=float, metavar="X3",
                    help="count on the slice at this orientation only (3-RRR* is --slice 0)")
    args = ap.parse_args()
    out = []
    print("NUMERICAL (not certified): grid components of the full 3-RRR by sampling; "
          "blind to aspects thinner than the grid step and near d_i = 20 (not a count of the aspects)")
    print(f"{'N':>5} {'components':>10} {'thick':>6}  per class (mode, det Fx sign): "
          "components, thick ones [sizes in cells]")
    for n in args.n:
        classes = count(n, args.slice)
        total = sum(len(c["sizes"]) for c in classes)
        cells = n ** 2 if args.slice is not None else n ** 3
        big = sum(c["thick"] for c in classes)
        volume = sum(c["volume"] for c in classes)  # an area on a slice
        second = max((c["sizes"][1] for c in classes if len(c["sizes"]) > 1), default=0)
        smallest_main = min(c["sizes"][0] for c in classes if c["sizes"])
        print(f"{n:>5} {total:>10} {big:>6}   pose volume of the 8 sheets: {volume:.1f}; "
              f"smallest largest component {smallest_main / cells:.4f} of the cells, "
              f"largest other {second / cells:.2e}")
        for c in classes:
            head = ", ".join(str(s) for s in c["sizes"][:4])
            more = f" (+{len(c['sizes']) - 4} more)" if len(c["sizes"]) > 4 else ""
            print(f"        mode {c['mode']} Fq signs {c['fq_signs']} det Fx {c['det_fx']:+d}: "
                  f"{len(c['sizes'])}, {c['thick']} thick [{head}{more}]")
        out.append(dict(n=n, components=total, thick=big,
                        volume=volume, classes=classes))
        sys.stdout.flush()
    if args.json:
        with open(args.json + ".tmp", "w") as f:
            json.dump(dict(kind="numerical, not certified", runs=out), f, indent=1)
        import os
        os.replace(args.json + ".tmp", args.json)


if __name__ == "__main__":
    main()
