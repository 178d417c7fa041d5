"""The pieces of a count (what `aspects count --out DIR` or count(out=DIR) wrote), as arrays,
their aspects, and a figure of them.

Each row is a piece proved connected: W_s ∩ B for the sign class s of its box B. A join is a
point of W_s in two boxes (or a bridge chart over both): the components of the joins are
connected sets of nonsingular configurations, each inside one aspect; when the count is
exact (lower = upper), they are the aspects themselves (certificates/FORMAT.md,
"Counting"). The figure draws what the pieces file records; its claims are the count's.
"""
from dataclasses import dataclass, field
from typing import Optional, Tuple

import numpy as np


@dataclass(frozen=True)
class CountPieces:
    """`cell` (the count's box id), `cls` (bit i set: factor i positive), `lo`, `hi` (the
    box, one column per variable, model order) per piece; `join_a`, `join_b` the joined
    pairs of rows; the count's `lower` and `upper` bounds, `factors` (their texts) and
    `factor_origins` ("det Fx", ...), `variables`,
    `pose_variables` and `robot`."""
    cell: np.ndarray
    cls: np.ndarray
    lo: np.ndarray
    hi: np.ndarray
    join_a: np.ndarray
    join_b: np.ndarray
    lower: int
    upper: Optional[int]
    factors: Tuple[str, ...]
    factor_origins: Tuple[str, ...]
    variables: Tuple[str, ...]
    pose_variables: Tuple[str, ...]
    robot: str
    directory: str
    _labels: list = field(default_factory=list, repr=False, compare=False)

    @classmethod
    def from_arrays(cls, d, directory):
        return cls(np.asarray(d["cell"]), np.asarray(d["cls"]), np.asarray(d["lo"]),
                   np.asarray(d["hi"]), np.asarray(d["join_a"]), np.asarray(d["join_b"]),
                   d["lower"], d["upper"], tuple(d["factors"]), tuple(d["factor_origins"]),
                   tuple(d["variables"]),
                   tuple(d["pose_variables"]), d["robot"], directory)

    @property
    def exact(self):
        return self.upper is not None and self.upper == self.lower

    def class_signs(self, c):
        """'+-' for a class: one sign per factor, in the factors' order."""
        return "".join("+" if (int(c) >> i) & 1 else "-" for i in range(len(self.factors)))

    def aspects(self):
        """A label per piece, 0..k-1: the components of the joins, largest first (by pieces).
        When the count is exact, k is the number of aspects and each label one aspect;
        otherwise each label is a connected set inside one aspect."""
        if not self._labels:
            n = len(self.cls)
            parent = np.arange(n)

            def find(i):
                while parent[i] != i:
                    parent[i] = parent[parent[i]]
                    i = parent[i]
                return i

            for a, b in zip(self.join_a.tolist(), self.join_b.tolist()):
                ra, rb = find(a), find(b)
                if ra != rb:
                    parent[ra] = rb
            roots = np.array([find(i) for i in range(n)], dtype=np.int64)
            uniq, inverse, counts = np.unique(roots, return_inverse=True, return_counts=True)
            order = np.argsort(-counts, kind="stable")
            rank = np.empty_like(order)
            rank[order] = np.arange(len(order))
            self._labels.append(rank[inverse])
        return self._labels[0]

    def figure(self, out, x=None, y=None, dpi=None):
        """One panel per sign class, each aspect (component of the joins) in its own colour,
        its pieces' boxes drawn in the pose axes x, y (default: the first two pose variables
        that vary). Written under a temporary name, then renamed."""
        from . import plotting as pl
        from matplotlib.collections import PolyCollection

        ix, iy = self._axes(x, y)
        labels = self.aspects()
        classes = sorted(set(self.cls.tolist()), key=lambda c: self.class_signs(c))
        k = len(classes)
        cols = min(4, k)
        rows = (k + cols - 1) // cols
        fig, axes = pl.plt.subplots(rows, cols, figsize=(3.2 * cols, 3.0 * rows + 0.6),
                                    squeeze=False)
        colors = pl.csnc_colors(max(1, int(labels.max()) + 1 if len(labels) else 1))
        for ax in axes.ravel()[k:]:
            ax.set_visible(False)
        for ax, c in zip(axes.ravel(), classes):
            mine = self.cls == c
            ids = sorted(set(labels[mine].tolist()))
            for j, a in enumerate(ids):
                sel = mine & (labels == a)
                lo, hi = self.lo[sel], self.hi[sel]
                polys = [[(l[ix], l[iy]), (h[ix], l[iy]), (h[ix], h[iy]), (l[ix], h[iy])]
                         for l, h in zip(lo, hi)]
                ax.add_collection(PolyCollection(polys, facecolors=[colors[a]],
                                                 edgecolors=[colors[a]], linewidths=0.3))
            ax.autoscale_view()
            # An aspect too small to see at the panel's scale is ringed (the aspects of an
            # exact count: a stopped one's joined sets are too many to ring).
            (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
            for a in ids if self.exact else ():
                sel = mine & (labels == a)
                lo, hi = self.lo[sel], self.hi[sel]
                w = max(hi[:, ix].max() - lo[:, ix].min(), 0) / (x1 - x0)
                h = max(hi[:, iy].max() - lo[:, iy].min(), 0) / (y1 - y0)
                if max(w, h) < 0.04:
                    ax.plot([(lo[:, ix].min() + hi[:, ix].max()) / 2],
                            [(lo[:, iy].min() + hi[:, iy].max()) / 2], "o", ms=11, mfc="none",
                            mec=colors[a], mew=1.4)
            word = "aspect" if self.exact else "joined set"
            ax.set_title(f"class {self.class_signs(c)}: {len(ids)} {word}"
                         f"{'' if len(ids) == 1 else 's'}", fontsize=9)
            ax.set_xlabel(self.variables[ix], fontsize=8)
            ax.set_ylabel(self.variables[iy], fontsize=8)
            ax.tick_params(labelsize=7)
        claim = (f"{pl.aspects_word(self.lower)} (certified: lower = upper)" if self.exact else
                 f"at least {pl.aspects_word(self.lower)} (certified); components of the "
                 f"joined pieces, each inside one aspect")
        fig.suptitle(f"{self.robot}: {claim}\nsign classes over "
                     f"{', '.join(self.factor_origins)}", fontsize=10)
        fig.tight_layout()
        pl.save(fig, out, dpi)
        pl.plt.close(fig)

    def _axes(self, x, y):
        names = list(self.variables)
        if x is None or y is None:
            varying = [names.index(p) for p in self.pose_variables
                       if len(self.lo) and np.ptp(np.r_[self.lo[:, names.index(p)],
                                                        self.hi[:, names.index(p)]]) > 0]
            if len(varying) < 2:
                raise ValueError("give x and y: fewer than two pose variables vary")
            x = names[varying[0]] if x is None else x
            y = names[varying[1]] if y is None else y
        for v in (x, y):
            if v not in names:
                raise ValueError(f"no variable '{v}' (the model's: {', '.join(names)})")
        return names.index(x), names.index(y)

