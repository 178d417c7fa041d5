"""`aspects view`: one self-contained HTML page (plotly, with plotly.js inside, so that it
works offline) that turns in a browser: each drawn CSNC as a surface or voxels in its own
colour, shown or hidden from the legend, the undecided region as a faint shell, and the
certified count in the title. Needs plotly and scikit-image (Debian's python3-plotly,
python3-skimage). An illustration only: nothing drawn is a claim but the count.
"""
import os

try:  # in the package, or run as a script from its directory
    from . import plotting, solids as sol
except ImportError:
    import plotting
    import solids as sol

SHELL_OPACITY = 0.08


def mesh_trace(go, verts, tris, name, color, opacity=1.0, legendrank=1000):
    return go.Mesh3d(x=verts[:, 0], y=verts[:, 1], z=verts[:, 2], i=tris[:, 0], j=tris[:, 1],
                     k=tris[:, 2], color=color, opacity=opacity, name=name, showlegend=True,
                     flatshading=True, hoverinfo="name", legendrank=legendrank,
                     lighting=dict(ambient=0.55, diffuse=0.7, specular=0.15))


def view_figure(bs, axes=None, csncs=None, largest=None, voxels=False, cells=None):
    """The plotly Figure of `aspects view`."""
    import plotly.graph_objects as go
    cells = sol.check_cells(cells)
    cols, grid, shown, shell = sol.solids(bs, axes, csncs, largest, cells)
    geometry = sol.voxel_faces if voxels else sol.surface
    traces = []
    for rank, s in enumerate(shown):
        verts, tris = geometry(s.occ, grid)
        traces.append(mesh_trace(go, verts, tris, s.label, s.color, legendrank=rank + 1))
    notes = []
    if shell is not None:
        verts, tris = sol.surface(shell.occ, grid)
        traces.append(mesh_trace(go, verts, tris, shell.label + ", faint shell", "#9a9a9a",
                                 opacity=SHELL_OPACITY, legendrank=len(shown) + 1))
    elif bs.undecided.any():
        notes.append(f"undecided boxes ({int(bs.undecided.sum())}) not drawn: the result "
                     "keeps their pose part only")
    how = "voxels" if voxels else "surfaces"
    title = (f"{bs.title()}: {plotting.count_claim(bs)}<br><sup>"
             f"{plotting.drawn_line(bs, [s.csnc for s in shown], cols)}; {how} over the boxes "
             f"on a {cells}³ grid. Drag to turn; click a legend entry to hide or show it."
             + "".join(f"<br>{n}" for n in notes) + "</sup>")
    names = [bs.vars[c] for c in cols]
    fig = go.Figure(traces)
    fig.update_layout(
        title=dict(text=title, x=0.02), template="plotly_white",
        legend=dict(title=dict(text="CSNCs (click to hide or show)"), itemsizing="constant"),
        scene=dict(xaxis_title=names[0], yaxis_title=names[1], zaxis_title=names[2],
                   aspectmode="cube"),
        margin=dict(l=0, r=0, t=90, b=0))
    return fig


def write_view(bs, out, axes=None, csncs=None, largest=None, voxels=False, cells=None):
    """Writes `out` (HTML, plotly.js embedded) under a temporary name, then renames it."""
    if not str(out).endswith(".html"):
        raise ValueError(f"out: the view is an HTML page; give a name ending in .html, got {out}")
    fig = view_figure(bs, axes, csncs, largest, voxels, cells)
    tmp = f"{out}.tmp{os.getpid()}.html"
    try:
        fig.write_html(tmp, include_plotlyjs=True, full_html=True, auto_open=False)
        os.replace(tmp, out)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)
