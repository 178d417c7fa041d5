"""Tests of the figures: `aspects plot` and Result.plot(), `aspects view` (a page that
headless Chromium draws), `aspects export --vtk` (read back with meshio). Run by ctest as
figures.pytest with PYTHONPATH on build/python and ASPECTS_EXE, ASPECTS_ROBOTS set.

The assertions are on what was drawn or written: the title's words, the legend's
entries, the axes' labels, the coloured collections, the pixels of a saved PNG, the
cells and labels of a VTK file. RRRRR at eps 0.5 is the case of issue 51: 12 CSNCs kept
by the filter, a certified bound of 10 whose representatives include CSNCs 64 and 134,
which the filter drops.
"""
import json
import os
import struct
import subprocess

import numpy as np
import pytest

import matplotlib
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection

import aspects
from aspects import plotting

EXE = os.environ["ASPECTS_EXE"]
ROBOTS = os.environ["ASPECTS_ROBOTS"]


def cli(*args, check=True):
    run = subprocess.run([EXE, *args], capture_output=True, text=True)
    if check and run.returncode != 0:
        raise AssertionError(f"{args}: exit {run.returncode}: {run.stderr}")
    return run


def solved(tmp_path_factory, robot, eps):
    d = str(tmp_path_factory.mktemp(robot.split(".")[0]) / "out")
    cli("solve", os.path.join(ROBOTS, robot), "--eps", str(eps), "--out", d, "--quiet")
    return d


@pytest.fixture(scope="module")
def rrrrr(tmp_path_factory):
    return solved(tmp_path_factory, "rrrrr.robot", 0.5)


@pytest.fixture(scope="module")
def rprpr(tmp_path_factory):
    return solved(tmp_path_factory, "rprpr.robot", 0.2)


@pytest.fixture(scope="module")
def rpr3(tmp_path_factory):
    return solved(tmp_path_factory, "3rpr.robot", 3)


def boxes(n):
    return f"{n} box" if n == 1 else f"{n} boxes"


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", head[16:24])


def legend_texts(fig_or_ax):
    leg = fig_or_ax.legends[0] if hasattr(fig_or_ax, "legends") and fig_or_ax.legends else \
        fig_or_ax.get_legend()
    return [t.get_text() for t in leg.get_texts()]


def colour_collections(ax):
    """The PolyCollections of an axes whose face colour is not grey (the CSNCs')."""
    out = []
    for c in ax.collections:
        if isinstance(c, PolyCollection) and len(c.get_facecolors()):
            r, g, b, _ = c.get_facecolors()[0]
            if not (abs(r - g) < 1e-6 and abs(g - b) < 1e-6) and \
                    matplotlib.colors.to_hex((r, g, b)) != plotting.OTHER:
                out.append(matplotlib.colors.to_hex((r, g, b)))
    return out


# ------------------------------------------------------------------------------ plot
RRRRR_DRAWN = [0, 1, 2, 3, 4, 5, 8, 9, 64, 134, 6, 7, 10, 11]


def test_plot_states_the_certified_count_then_separated_then_large(rrrrr):
    r = aspects.load(rrrrr)
    assert r.summary["csncs"]["filtered"] == 12 and r.lower_bound == 10
    fig = r.plot()
    assert fig._suptitle.get_text() == (
        "RRRRR, ε = 0.5: at least 10 aspects (certified)\n"
        "14 of 210 CSNCs drawn, the 10 separated first (certified in pairwise distinct "
        "aspects); on (x1, x2)")
    sizes = {k: int((r.csnc == k).sum()) for k in RRRRR_DRAWN}
    labels = legend_texts(fig)
    assert sizes[64] == sizes[134] == 1
    assert labels[:10] == [f"CSNC {k} ({boxes(sizes[k])})" + (", separated" if i < 10 else "")
                           for i, k in enumerate(RRRRR_DRAWN[:10])]
    assert labels[10:] == [
        "... 4 more CSNCs drawn",
        f"196 other CSNCs ({int(((r.csnc >= 0) & ~np.isin(r.csnc, RRRRR_DRAWN)).sum())} "
        "boxes), not drawn one by one",
        f"undecided ({int((r.status != aspects.SOLUTION).sum())} boxes: singular or "
        "unresolved)"]
    # The overview, then one panel per drawn CSNC, each in its own colour.
    panels = [ax for ax in fig.axes if ax.get_title()]
    assert [ax.get_title() for ax in panels[1:]] == [
        f"CSNC {k}: {boxes(sizes[k])}" + (", separated" if i < 10 else "")
        for i, k in enumerate(RRRRR_DRAWN)]
    overview = colour_collections(panels[0])
    assert len(overview) == 14 and len(set(overview)) == 14
    # The overview does not overdraw: translucent fills, and an outline in each colour.
    fills = [c for c in panels[0].collections if isinstance(c, PolyCollection)
             and matplotlib.colors.to_hex(c.get_facecolors()[0]) in overview]
    assert [c.get_alpha() for c in fills] == [0.35] * 14
    outlines = [matplotlib.colors.to_hex(c.get_edgecolors()[0]) for c in panels[0].collections
                if c.get_gid() == "outline" and len(c.get_paths())]
    assert outlines == overview
    assert [colour_collections(ax) for ax in panels[1:]] == [[c] for c in overview]
    # The one-box CSNCs get a ring in their colour, visible where the box is a speck.
    for i, k in enumerate(RRRRR_DRAWN):
        rings = [c for c in panels[1 + i].collections if not isinstance(c, PolyCollection)
                 and len(c.get_offsets()) and len(c.get_edgecolors())]
        assert len(rings) == (1 if k in (64, 134) else 0), k
        if rings:
            assert matplotlib.colors.to_hex(rings[0].get_edgecolors()[0]) == overview[i]
    assert (panels[0].get_xlabel(), panels[0].get_ylabel()) == ("x1", "x2")
    plt.close(fig)


def test_plot_undecided_boxes_are_quiet(rprpr, tmp_path):
    """Light grey beneath the CSNCs, never red: no red pixel in the PNG, light grey ones."""
    r = aspects.load(rprpr)
    fig = r.plot(str(tmp_path / "p.png"))
    ax = fig.axes[1]
    und = [c for c in ax.collections if isinstance(c, PolyCollection)
           and matplotlib.colors.to_hex(c.get_facecolors()[0]) == matplotlib.colors.to_hex(
               plotting.QUIET)]
    assert len(und) == 1 and und[0].get_zorder() < 2
    assert float(und[0].get_linewidths()[0]) == pytest.approx(0.2)
    img = (plt.imread(str(tmp_path / "p.png"))[:, :, :3] * 255).round().astype(int)
    red = (np.abs(img - [214, 39, 40]).sum(axis=2) < 30).sum()
    grey = (np.abs(img - [217, 217, 217]).sum(axis=2) < 6).sum()
    assert red == 0 and grey > 2000
    plt.close(fig)


def test_plot_exact_or_upper_count_is_said_as_such():
    kw = dict(names=["x1", "x2"], lower=[[0, 0]], upper=[[1, 1]], status=[0], csnc=[0],
              filtered=1, robot="R", eps=0.5)
    assert plotting.count_claim(plotting.BoxSet(**kw, lower_bound=3)) == \
        "at least 3 aspects (certified)"
    assert plotting.count_claim(plotting.BoxSet(**kw, lower_bound=1)) == \
        "at least 1 aspect (certified)"
    assert plotting.count_claim(plotting.BoxSet(**kw, lower_bound=2, upper_bound=4)) == \
        "at least 2 aspects (certified), at most 4 (certified)"
    assert plotting.count_claim(plotting.BoxSet(**kw, lower_bound=2, exact=2)) == \
        "exactly 2 aspects (certified)"
    assert plotting.count_claim(plotting.BoxSet(**kw)) == "no certified count of aspects recorded"
    assert plotting.count_claim(plotting.BoxSet(**kw, lower_bound=0)) == \
        "no aspect separated yet (certified lower bound 0)"


def test_plot_joint_space_axes(rrrrr):
    r = aspects.load(rrrrr)
    fig = r.plot(axes=["q1", "q2"], largest=3)
    ax = fig.axes[0]
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("q1", "q2")
    assert fig._suptitle.get_text().endswith(
        "3 of 210 CSNCs drawn, the 3 separated first (certified in pairwise distinct "
        "aspects); on (q1, q2)")
    undecided = int((r.status != aspects.SOLUTION).sum())
    assert legend_texts(fig)[-1] == (f"undecided boxes ({undecided}) not drawn: the result "
                                     "keeps their pose part only")
    assert len(colour_collections(ax)) == 3
    # A command axis spans the boxes' command parts.
    lo, hi = ax.get_xlim()
    sol = r.status == aspects.SOLUTION
    q1 = r.variables.index("q1")
    assert lo < r.lower[sol, q1].min() and hi > r.upper[sol, q1].max() and hi - lo < 8
    plt.close(fig)


def test_plot_chosen_csncs_in_the_given_order(rrrrr):
    r = aspects.load(rrrrr)
    fig = r.plot(csncs=[134, 2])
    labels = legend_texts(fig)
    assert labels[0].startswith("CSNC 134 (") and labels[0].endswith(", separated")
    assert labels[1].startswith("CSNC 2 (")
    assert [ax.get_title().split(":")[0] for ax in fig.axes[1:3]] == ["CSNC 134", "CSNC 2"]
    assert len(colour_collections(fig.axes[0])) == 2
    plt.close(fig)


def test_plot_into_a_given_axes(rprpr):
    r = aspects.load(rprpr)
    fig, ax = plt.subplots()
    got = r.plot(ax=ax)
    assert got is fig and fig.axes == [ax]
    assert ax.get_title() == "RPRPR, ε = 0.2: at least 2 aspects (certified)"
    assert legend_texts(ax)[:2] == [f"CSNC {k} ({int((r.csnc == k).sum())} boxes), separated"
                                    for k in (0, 1)]
    assert len(colour_collections(ax)) == 2
    plt.close(fig)


def test_plot_dpi_and_size(rprpr, tmp_path):
    r = aspects.load(rprpr)
    plt.close(r.plot(str(tmp_path / "py.png"), dpi=50, size=(4, 3)))
    assert png_size(tmp_path / "py.png") == (200, 150)
    out = cli("plot", rprpr, "--out", str(tmp_path / "cli.png"), "--dpi", "40", "--size", "5x2.5")
    assert out.stdout == f"wrote {tmp_path / 'cli.png'}\n"
    assert png_size(tmp_path / "cli.png") == (200, 100)


def test_cli_plot_svg_says_the_count_and_legend(rrrrr, tmp_path):
    cli("plot", rrrrr, "--out", str(tmp_path / "f.svg"), "--axes", "q1,x2", "--csnc", "64,0")
    svg = (tmp_path / "f.svg").read_text()
    assert "RRRRR, ε = 0.5: at least 10 aspects (certified)" in svg
    assert "2 of 210 CSNCs drawn, the 2 separated first" in svg
    assert ">CSNC 64 (" in svg and ">CSNC 0 (" in svg and ">CSNC 1 (" not in svg
    assert "filtered" not in svg and "12 " not in svg.split("CSNCs drawn")[0][-40:]
    assert ">q1<" in svg and ">x2<" in svg


def test_plot_three_axes_is_3d(rpr3):
    r = aspects.load(rpr3)
    fig = r.plot(axes="x1,x2,q1")
    assert fig.axes[0].name == "3d" and fig.axes[0].get_zlabel() == "q1"
    assert fig._suptitle.get_text().startswith("3-RPR, ε = 3: at least 2 aspects (certified)\n")
    plt.close(fig)


@pytest.mark.parametrize("args, message", [
    (["--axes", "q9,x1"], "--axes: 'q9' is not a variable of RPRPR (its variables: x1, x2, q1, q2)"),
    (["--axes", "x1"], "--axes: give 2 or 3 variable names separated by commas, got 'x1'"),
    (["--axes", "x1,x1"], "--axes: 'x1' is given twice"),
    (["--csnc", "0,99"], "--csnc: CSNCs are numbered from 0 to 1 (the result has 2), got 99"),
    (["--csnc", "0,x"], "--csnc: give CSNC numbers separated by commas, got '0,x'"),
    (["--csnc", "1,1"], "--csnc: CSNC 1 is given twice"),
    (["--largest", "0"], "--largest: a number of CSNCs, an integer from 1 to 1000000, got '0'"),
    (["--dpi", "5"], "--dpi: dots per inch, an integer from 10 to 2400, got '5'"),
    (["--dpi", "9e9"], "--dpi: dots per inch, an integer from 10 to 2400, got '9e9'"),
    (["--size", "8"], "--size: give WIDTHxHEIGHT in inches (e.g. 8x6), each above 0 and at "
                      "most 100, got '8'"),
    (["--size", "0x3"], "--size: give WIDTHxHEIGHT in inches (e.g. 8x6), each above 0 and at "
                        "most 100, got '0x3'"),
    (["--axes", "q1,q2", "--path", "PATH"],
     "--axes: 'q1' is not a pose variable, and --path is drawn in pose coordinates (x1, x2)"),
])
def test_cli_plot_bad_options_name_the_option(rprpr, tmp_path, args, message):
    if "PATH" in args:
        r = aspects.load(rprpr)
        (tmp_path / "p.json").write_text(json.dumps(r.path([3, 5], [4, 2.5]).to_dict()))
        args = [str(tmp_path / "p.json") if a == "PATH" else a for a in args]
    run = cli("plot", rprpr, "--out", str(tmp_path / "x.png"), *args, check=False)
    assert (run.returncode, run.stderr) == (2, f"aspects: {message}\n")
    assert not (tmp_path / "x.png").exists()


@pytest.mark.parametrize("kw, message", [
    (dict(axes=["x1", "q7"]), "axes: 'q7' is not a variable of RPRPR"),
    (dict(axes="x1"), "axes: give 2 or 3 variables, got 1 (x1)"),
    (dict(csncs=[5]), "csncs: CSNCs are numbered 0 to 1 (the result has 2), got 5"),
    (dict(largest=0), "largest: a number of CSNCs, at least 1, got 0"),
    (dict(dpi=3), "dpi: an integer from 10 to 2400, got 3"),
    (dict(size=(4,)), r"size: \(width, height\) in inches"),
    (dict(csncs=[0], largest=1), "csncs and largest: give one of them"),
])
def test_result_plot_bad_options(rprpr, kw, message):
    with pytest.raises(ValueError, match="^" + message.replace("(", r"\(").replace(")", r"\)")
                       if "\\" not in message else "^" + message):
        aspects.load(rprpr).plot(**kw)


# ------------------------------------------------------------------------------ view
def chromium_screenshot(html, png, size=(1100, 800)):
    """Headless Chromium's screenshot of a page (WebGL by SwiftShader: no GPU needed)."""
    exe = next((p for p in ("/usr/bin/chromium", "/usr/bin/chromium-browser") if os.path.exists(p)),
               None)
    assert exe, "chromium is missing (README's install line installs it)"
    run = subprocess.run([exe, "--headless", "--no-sandbox", "--disable-gpu",
                          "--enable-unsafe-swiftshader", "--use-angle=swiftshader",
                          "--hide-scrollbars", f"--window-size={size[0]},{size[1]}",
                          "--virtual-time-budget=15000", f"--screenshot={png}",
                          f"file://{html}"], capture_output=True, text=True, timeout=180)
    assert run.returncode == 0 and os.path.exists(png), run.stderr[-2000:]
    return (plt.imread(png)[:, :, :3] * 255).round().astype(int)


def page_figure(html):
    """(traces, layout) of the page's Plotly.newPlot("id", [traces], {layout}, ...) call."""
    start = html.rindex("Plotly.newPlot(")
    at = html.index("[", html.index(",", start))
    dec = json.JSONDecoder()
    traces, end = dec.raw_decode(html, at)
    layout, _ = dec.raw_decode(html, html.index("{", end))
    return traces, layout


def saturated_hues(img):
    """Pixels with a clear colour (not white, grey or black), binned by hue (30° bins):
    {bin: pixels}."""
    mx, mn = img.max(axis=2), img.min(axis=2)
    sat = (mx - mn) > 40
    r, g, b = [img[:, :, i][sat].astype(float) for i in range(3)]
    hue = np.degrees(np.arctan2(np.sqrt(3) * (g - b), 2 * r - g - b)) % 360
    bins, counts = np.unique((hue // 30).astype(int), return_counts=True)
    return dict(zip(bins.tolist(), counts.tolist()))


def test_view_page_turns_in_a_browser(rpr3, tmp_path):
    r = aspects.load(rpr3)
    out = tmp_path / "v.html"
    run = cli("view", rpr3, "--out", str(out))
    assert run.stdout == f"wrote {out}\n"
    html = out.read_text()
    # Self-contained: plotly.js inside, nothing fetched.
    assert "<script src=" not in html and html.count("Plotly.newPlot") >= 1 and len(html) > 3e6
    sizes = {k: int((r.csnc == k).sum()) for k in range(6)}
    names = [f"CSNC 0 ({sizes[0]} boxes), separated", f"CSNC 2 ({sizes[2]} boxes), separated",
             f"CSNC 1 ({sizes[1]} boxes)", f"CSNC 3 ({sizes[3]} boxes)",
             f"CSNC 4 ({sizes[4]} boxes)",
             f"undecided region ({int((r.status != aspects.SOLUTION).sum())} boxes), faint shell"]
    traces, layout = page_figure(html)
    assert [t["name"] for t in traces] == names
    assert all(t["type"] == "mesh3d" and t["showlegend"] for t in traces)
    assert len({t["color"] for t in traces}) == 6
    assert [t["opacity"] for t in traces] == [1] * 5 + [0.08]
    assert layout["title"]["text"].startswith("3-RPR, ε = 3: at least 2 aspects (certified)<br>")
    assert [layout["scene"][a]["title"]["text"] for a in ("xaxis", "yaxis", "zaxis")] == \
        ["x1", "x2", "x3"]
    img = chromium_screenshot(str(out), str(tmp_path / "shot.png"))
    plot_area = img[90:, :780]                      # left of the legend, below the title
    nonwhite = (plot_area.min(axis=2) < 235).sum()
    hues = saturated_hues(plot_area)
    assert nonwhite > 40000, nonwhite
    assert sum(1 for c in hues.values() if c > 300) >= 3, hues


def test_view_voxels_and_chosen_axes(rprpr, tmp_path):
    r = aspects.load(rprpr)
    out = tmp_path / "v.html"
    cli("view", rprpr, "--out", str(out), "--axes", "x1,x2,q1", "--voxels", "--grid", "16")
    traces, layout = page_figure(out.read_text())
    assert [t["name"] for t in traces] == [
        f"CSNC {k} ({int((r.csnc == k).sum())} boxes), separated" for k in (0, 1)]
    title = layout["title"]["text"]
    assert (f"undecided boxes ({int((r.status != aspects.SOLUTION).sum())}) not drawn: the "
            "result keeps their pose part only") in title
    assert "voxels over the boxes on a 16³ grid" in title
    assert layout["scene"]["zaxis"]["title"]["text"] == "q1"
    img = chromium_screenshot(str(out), str(tmp_path / "shot.png"))
    assert len([c for c in saturated_hues(img[90:, :780]).values() if c > 300]) >= 2


@pytest.mark.parametrize("cmd, args, message", [
    ("view", [], "--axes: `aspects view` draws 3 variables and RPRPR has 2 pose variables "
                 "(x1, x2): give three of x1, x2, q1, q2 with --axes"),
    ("view", ["--axes", "x1,x2"], "--axes: give 3 variable names separated by commas, got "
                                  "'x1,x2'"),
    ("view", ["--axes", "x1,x2,q1", "--out", "OUT/v.png"],
     "--out: the view is an HTML page; give a name ending in .html, got OUT/v.png"),
    ("view", ["--axes", "x1,x2,q1", "--grid", "2"],
     "--grid: cells per axis, an integer from 4 to 256, got '2'"),
    ("export", ["--vtk", "OUT/m.vtu"], "--axes: `aspects export` draws 3 variables and RPRPR "
                                       "has 2 pose variables (x1, x2): give three of x1, x2, "
                                       "q1, q2 with --axes"),
    ("export", ["--vtk", "OUT/m.obj", "--axes", "x1,x2,q1"],
     "--vtk: give a file name ending in .vtu (VTK XML) or .vtk (legacy VTK), got "
     "'OUT/m.obj'"),
])
def test_view_and_export_bad_options(rprpr, tmp_path, cmd, args, message):
    args = [a.replace("OUT", str(tmp_path)) for a in args]
    run = cli(cmd, rprpr, *args, check=False)
    assert (run.returncode, run.stderr) == (2, "aspects: " + message.replace("OUT", str(tmp_path))
                                            + "\n")
    assert os.listdir(tmp_path) == []


# ------------------------------------------------------------------------------ export
def brute_force_cells(lo, hi, sel, cells):
    """The occupied cells of the boxes `sel`, found directly: the grid of raster.Grid.around
    over all the boxes (cells per axis over their extent, one empty cell on each side), a
    cell occupied when its interior meets one of the boxes."""
    a, b = lo.min(axis=0), hi.max(axis=0)
    step = (b - a) / cells
    origin = a - step
    idx = np.arange(cells + 2)
    occupied = np.zeros((cells + 2,) * 3, dtype=bool)
    for blo, bhi in zip(lo[sel], hi[sel]):
        m = [(origin[d] + idx * step[d] < bhi[d]) & (origin[d] + (idx + 1) * step[d] > blo[d])
             for d in range(3)]
        occupied |= m[0][:, None, None] & m[1][None, :, None] & m[2][None, None, :]
    return occupied


def test_export_voxels_read_back(rpr3, tmp_path):
    import meshio
    r = aspects.load(rpr3)
    out = tmp_path / "h.vtu"
    run = cli("export", rpr3, "--vtk", str(out), "--voxels", "--grid", "12", "--csnc", "4,2")
    assert run.stdout == f"wrote {out}\n"
    m = meshio.read(str(out))
    assert [c.type for c in m.cells] == ["hexahedron"]
    label = m.cell_data["csnc"][0]
    pose = [r.variables.index(v) for v in ("x1", "x2", "x3")]
    lo, hi = r.lower[:, pose], r.upper[:, pose]
    expected = {k: int(brute_force_cells(lo, hi, r.csnc == k, 12).sum()) for k in (4, 2)}
    assert expected[4] > 0 and expected[2] > expected[4]
    assert label.tolist() == [4] * expected[4] + [2] * expected[2]
    assert m.cell_data["separated"][0].tolist() == [0] * expected[4] + [1] * expected[2]
    assert sorted(os.listdir(tmp_path)) == ["h.vtu"]


def test_export_surfaces_read_back(rpr3, tmp_path):
    """Triangles labelled by CSNC in drawing order (the separated first), each CSNC's
    surface closed: every edge is shared by exactly two of its triangles."""
    import meshio
    r = aspects.load(rpr3)
    out = tmp_path / "m.vtk"
    cli("export", rpr3, "--vtk", str(out))
    m = meshio.read(str(out))
    assert [c.type for c in m.cells] == ["triangle"]
    tris, label = m.cells[0].data, m.cell_data["csnc"][0]
    order = [k for i, k in enumerate(label.tolist()) if i == 0 or label[i - 1] != k]
    assert order == [0, 2, 1, 3, 4]
    assert sorted(set(np.flatnonzero(m.cell_data["separated"][0]).tolist())) == \
        np.flatnonzero(np.isin(label, [0, 2])).tolist()
    for k in order:
        t = tris[label == k]
        edges = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
        _, counts = np.unique(edges, axis=0, return_counts=True)
        assert len(t) > 0 and set(counts.tolist()) == {2}, k
    pose = [r.variables.index(v) for v in ("x1", "x2", "x3")]
    assert (m.points.min(axis=0) >= r.lower[:, pose].min(axis=0) - 0.1 * np.ptp(
        r.upper[:, pose], axis=0)).all()


# ------------------------------------------------------------------------------ Python
def test_result_view_and_export_as_the_command_line(rpr3, tmp_path):
    import meshio
    r = aspects.load(rpr3)
    r.view(tmp_path / "py.html", largest=2, grid=16)
    cli("view", rpr3, "--out", str(tmp_path / "cli.html"), "--largest", "2", "--grid", "16")
    py, _ = page_figure((tmp_path / "py.html").read_text())
    cl, _ = page_figure((tmp_path / "cli.html").read_text())
    assert [t["name"] for t in py] == [t["name"] for t in cl] and len(py) == 3
    assert all(a["x"] == b["x"] and a["i"] == b["i"] for a, b in zip(py, cl))
    r.export_vtk(tmp_path / "py.vtu", voxels=True, grid=8, csncs=[2, 0])
    cli("export", rpr3, "--vtk", str(tmp_path / "cli.vtu"), "--voxels", "--grid", "8",
        "--csnc", "2,0")
    a, b = meshio.read(str(tmp_path / "py.vtu")), meshio.read(str(tmp_path / "cli.vtu"))
    assert np.array_equal(a.cells[0].data, b.cells[0].data) and np.array_equal(a.points, b.points)
    assert a.cell_data["csnc"][0].tolist() == b.cell_data["csnc"][0].tolist()
    assert set(a.cell_data["csnc"][0].tolist()) == {2, 0}


@pytest.mark.parametrize("call, message", [
    (lambda r, d: r.view(d / "v.png"), "out: the view is an HTML page"),
    (lambda r, d: r.view(d / "v.html", grid=2), "grid: cells per axis, an integer from 4 to 256, got 2"),
    (lambda r, d: r.view(d / "v.html", axes="x1,x2"), "axes: give 3 variables, got 2"),
    (lambda r, d: r.export_vtk(d / "m.obj"), "out: give a file name ending in .vtu"),
    (lambda r, d: r.export_vtk(d / "m.vtu", csncs=[0], largest=2), "csncs and largest"),
])
def test_result_view_and_export_bad_options(rpr3, tmp_path, call, message):
    with pytest.raises(ValueError, match="^" + message.replace("(", r"\(").replace(")", r"\)")):
        call(aspects.load(rpr3), tmp_path)
    assert os.listdir(tmp_path) == []
