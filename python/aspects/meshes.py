"""`aspects export --vtk FILE`: the drawn CSNCs in three variables as a file ParaView opens
(meshio, Debian's python3-meshio): triangle surfaces (marching cubes over the rasterised
boxes), or with --voxels the raster's occupied cells as hexahedra. Each cell carries its
CSNC's number ("csnc") and whether that CSNC is a separated representative ("separated":
1, certified to lie in an aspect apart from the other separated ones). Points are in the
axes' variables, in the order given. An illustration only, as the figures.
"""
import os

import numpy as np

try:  # in the package, or run as a script from its directory
    from . import solids as sol
except ImportError:
    import solids as sol


def csnc_mesh(bs, axes=None, csncs=None, largest=None, voxels=False, cells=None):
    """(the meshio.Mesh of `aspects export`, the axes' names): one cell block ("triangle"
    or "hexahedron") holding every drawn CSNC, in drawing order."""
    import meshio
    cols, grid, shown, _ = sol.solids(bs, axes, csncs, largest, cells)
    geometry = sol.voxel_hexahedra if voxels else sol.surface
    points, blocks, label, separated = [], [], [], []
    offset = 0
    for s in shown:
        verts, cells_ = geometry(s.occ, grid)
        points.append(verts)
        blocks.append(cells_ + offset)
        offset += len(verts)
        label.append(np.full(len(cells_), s.csnc, dtype=np.int32))
        separated.append(np.full(len(cells_), int(s.csnc in bs.representatives), dtype=np.int32))
    kind = "hexahedron" if voxels else "triangle"
    width = 8 if voxels else 3
    pts = np.concatenate(points) if points else np.zeros((0, 3))
    conn = np.concatenate(blocks) if blocks else np.zeros((0, width), dtype=np.int64)
    return meshio.Mesh(pts, [(kind, conn)],
                       cell_data={"csnc": [np.concatenate(label) if label else
                                           np.zeros(0, np.int32)],
                                  "separated": [np.concatenate(separated) if separated else
                                                np.zeros(0, np.int32)]}), \
        [bs.vars[c] for c in cols]


def write_vtk(bs, out, axes=None, csncs=None, largest=None, voxels=False, cells=None):
    """Writes `out` (.vtu or .vtk, meshio's choice by extension) under a temporary name
    with the same extension, then renames it."""
    import meshio
    out = str(out)
    if not out.endswith((".vtu", ".vtk")):
        raise ValueError(f"out: give a file name ending in .vtu (VTK XML) or .vtk (legacy "
                         f"VTK), got '{out}'")
    mesh, _ = csnc_mesh(bs, axes, csncs, largest, voxels, cells)
    root, ext = os.path.splitext(out)
    tmp = f"{root}.tmp{os.getpid()}{ext}"
    try:
        meshio.write(tmp, mesh)
        os.replace(tmp, out)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)
