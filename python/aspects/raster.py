"""Boxes rasterised on a regular grid, for the figures' outlines, surfaces and voxels.

A cell is occupied when it meets a box (closed boxes), so a box narrower than a cell is
never lost: the drawn region covers the boxes, a little larger than their union (at most
one cell on each side). An illustration only, as every figure: nothing here is a claim.
Needs only numpy.
"""
import numpy as np


class Grid:
    """A regular grid over [origin, origin + step * shape] (one entry per axis)."""

    def __init__(self, origin, step, shape):
        self.origin = np.asarray(origin, dtype=float)
        self.step = np.asarray(step, dtype=float)
        self.shape = tuple(int(n) for n in shape)

    @classmethod
    def around(cls, lo, hi, cells, pad=1):
        """`cells` cells along every axis covering the boxes lo..hi (rows: boxes), and `pad`
        empty cells more on each side (so that an outline or a surface closes)."""
        lo = np.asarray(lo, dtype=float)
        hi = np.asarray(hi, dtype=float)
        a, b = np.nanmin(lo, axis=0), np.nanmax(hi, axis=0)
        step = np.where(b > a, b - a, 1.0) / cells
        return cls(a - pad * step, step, [cells + 2 * pad] * len(a))

    def centres(self, axis):
        return self.origin[axis] + (np.arange(self.shape[axis]) + 0.5) * self.step[axis]

    def edges(self, axis):
        return self.origin[axis] + np.arange(self.shape[axis] + 1) * self.step[axis]


def occupancy(grid, lo, hi):
    """Boolean array of grid.shape: the cells that meet at least one box lo..hi (rows:
    boxes; columns: the grid's axes). Boxes with a NaN end are skipped. One pass: a
    difference array gets ±1 at each box's 2^d corners, then a cumulative sum per axis."""
    lo = np.asarray(lo, dtype=float).reshape(-1, len(grid.shape))
    hi = np.asarray(hi, dtype=float).reshape(-1, len(grid.shape))
    ok = ~(np.isnan(lo).any(axis=1) | np.isnan(hi).any(axis=1))
    lo, hi = lo[ok], hi[ok]
    d = len(grid.shape)
    n = np.array(grid.shape)
    diff = np.zeros(tuple(n + 1), dtype=np.int64)
    if len(lo):
        i0 = np.clip(np.floor((lo - grid.origin) / grid.step).astype(np.int64), 0, n - 1)
        i1 = np.ceil((hi - grid.origin) / grid.step).astype(np.int64)
        i1 = np.clip(np.maximum(i1, i0 + 1), 1, n)
        for corner in range(1 << d):
            idx = tuple(np.where((corner >> a) & 1, i1[:, a], i0[:, a]) for a in range(d))
            sign = -1 if bin(corner).count("1") % 2 else 1
            np.add.at(diff, idx, sign)
    for a in range(d):
        diff = np.cumsum(diff, axis=a)
    return diff[tuple(slice(0, k) for k in n)] > 0
