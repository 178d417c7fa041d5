"""The CSNCs of a result as solids in three variables, for `aspects view` (view3d.py) and
`aspects export` (meshes.py): each CSNC's boxes rasterised on one grid (raster.py), then
a surface (marching cubes, scikit-image) or voxels. An illustration only: the raster
covers the boxes and a little more (at most a cell on each side), so the solids neither
prove nor refute anything; the boxes are the result.
"""
import numpy as np

try:  # in the package, or run as a script from its directory
    from . import plotting, raster
except ImportError:
    import plotting
    import raster

DEFAULT_SOLIDS = 6          # CSNCs drawn unless chosen (the separated first)
DEFAULT_CELLS, MIN_CELLS, MAX_CELLS = 64, 4, 256


def check_cells(cells):
    """The raster's cells per axis (None: the default); ValueError naming `grid`."""
    if cells is None:
        return DEFAULT_CELLS
    if isinstance(cells, bool) or not isinstance(cells, (int, np.integer)) or \
            not MIN_CELLS <= cells <= MAX_CELLS:
        raise ValueError(f"grid: cells per axis, an integer from {MIN_CELLS} to {MAX_CELLS}, "
                         f"got {cells!r}")
    return int(cells)


class Solid:
    """One CSNC (or the undecided region: csnc None) rasterised: its label, colour, box
    count and occupancy grid."""

    def __init__(self, csnc, label, color, boxes, occ):
        self.csnc, self.label, self.color, self.boxes, self.occ = csnc, label, color, boxes, occ


def solids(bs, axes=None, csncs=None, largest=None, cells=None):
    """(columns, grid, CSNC solids in drawing order, undecided solid or None). The
    undecided region is None when the axes leave the pose (the result keeps the undecided
    boxes' pose part only) or when there is none."""
    cells = check_cells(cells)
    cols = plotting.resolve_axes(bs, axes, counts=(3,))
    if csncs is not None and largest is not None:
        raise ValueError("csncs and largest: give one of them")
    shown = plotting.choose_csncs(bs, csncs, largest, most=DEFAULT_SOLIDS)
    colors = [plotting.matplotlib.colors.to_hex(c) for c in plotting.csnc_colors(len(shown))]
    known = plotting.finite_on(bs, np.ones(len(bs.status), bool), cols)
    grid = raster.Grid.around(bs.lo[known][:, cols], bs.hi[known][:, cols], cells)
    out = []
    for k, color in zip(shown, colors):
        m = bs.csnc == k
        occ = raster.occupancy(grid, bs.lo[m][:, cols], bs.hi[m][:, cols])
        out.append(Solid(k, plotting.csnc_label(bs, k), color, int(m.sum()), occ))
    und = plotting.finite_on(bs, bs.undecided, cols)
    shell = None
    if und.any():
        occ = raster.occupancy(grid, bs.lo[und][:, cols], bs.hi[und][:, cols])
        shell = Solid(None, f"undecided region ({plotting.boxes_word(int(und.sum()))})", plotting.QUIET,
                      int(und.sum()), occ)
    return cols, grid, out, shell


def surface(occ, grid):
    """Vertices (n × 3, in the variables' units) and triangles (m × 3) of the boundary of
    the occupied cells: marching cubes at level 1/2 over the cell centres."""
    from skimage import measure
    if not occ.any():
        return np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64)
    # The grid has an empty border (Grid.around's pad): the surface closes.
    verts, faces, _, _ = measure.marching_cubes(occ.astype(np.float32), level=0.5,
                                                spacing=tuple(grid.step))
    return verts + grid.origin + 0.5 * grid.step, faces.astype(np.int64)


def _compact(corners):
    """Shared vertices: (unique integer corners, index of each given corner)."""
    flat = corners.reshape(-1, 3)
    uniq, inverse = np.unique(flat, axis=0, return_inverse=True)
    return uniq, inverse.reshape(corners.shape[:-1])


def voxel_faces(occ, grid):
    """Vertices and triangles of the occupied cells' faces that border an empty cell."""
    padded = np.pad(occ, 1)
    quads = []
    for a in range(3):
        for side in (0, 1):
            shift = [0, 0, 0]
            shift[a] = 1 if side else -1
            neighbour = np.roll(padded, -shift[a], axis=a)[1:-1, 1:-1, 1:-1]
            cells = np.argwhere(occ & ~neighbour)
            if not len(cells):
                continue
            b, c = [d for d in range(3) if d != a]
            base = cells.copy()
            base[:, a] += side
            corners = np.repeat(base[:, None, :], 4, axis=1)
            corners[:, 1, b] += 1
            corners[:, 2, b] += 1
            corners[:, 2, c] += 1
            corners[:, 3, c] += 1
            quads.append(corners)
    if not quads:
        return np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64)
    uniq, idx = _compact(np.concatenate(quads))
    tris = np.concatenate([idx[:, [0, 1, 2]], idx[:, [0, 2, 3]]])
    return grid.origin + uniq * grid.step, tris.astype(np.int64)


def voxel_hexahedra(occ, grid):
    """Vertices and hexahedra (m × 8, VTK's order: the lower face counter-clockwise, then
    the upper one) of the occupied cells."""
    cells = np.argwhere(occ)
    offsets = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                        [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]])
    if not len(cells):
        return np.zeros((0, 3)), np.zeros((0, 8), dtype=np.int64)
    uniq, idx = _compact(cells[:, None, :] + offsets[None, :, :])
    return grid.origin + uniq * grid.step, idx.astype(np.int64)
