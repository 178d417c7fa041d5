"""Tests of the Python module `aspects` (run by ctest as python.pytest, with PYTHONPATH on
build/python and ASPECTS_EXE, ASPECTS_ROBOTS set).

Each test compares with exact values: the command line's own outputs on the same model and
eps (summary.json, boxes.csv, aspects.idx byte for byte, query and path --json), exact
error positions, exact exception types. Deliberate breaks that made them fail: the
undecided boxes' status left unshifted in box_arrays (py_result.cpp; three tests: the status
counts differ from summary.json, the unexplored count), the pose length check removed from
Result._pose (the wrong-length cases: the message is then the C++ one).
"""
import json
import math
import os
import signal
import subprocess
import threading
import time

import numpy as np
import pytest

import aspects

EXE = os.environ["ASPECTS_EXE"]
ROBOTS = os.environ["ASPECTS_ROBOTS"]
PRRP = os.path.join(ROBOTS, "prrp.robot")
RPRPR = os.path.join(ROBOTS, "rprpr.robot")
with open(os.path.join(ROBOTS, "rrrrr.robot")) as _f:
    RRRRR_TEXT = _f.read()


def cli(*args, check=True):
    run = subprocess.run([EXE, *args], capture_output=True, text=True)
    if check and run.returncode != 0:
        raise AssertionError(f"{args}: exit {run.returncode}: {run.stderr}")
    return run


@pytest.fixture(scope="module")
def rprpr(tmp_path_factory):
    """RPRPR at eps 0.2 solved by the command line and by Python, both with --out."""
    base = tmp_path_factory.mktemp("rprpr")
    cli_dir, py_dir = str(base / "cli"), str(base / "py")
    cli("solve", RPRPR, "--eps", "0.2", "--out", cli_dir, "--quiet")
    model = aspects.Model.from_file(RPRPR)
    result = aspects.solve(model, eps=0.2, out=py_dir)
    with open(os.path.join(cli_dir, "summary.json")) as f:
        summary = json.load(f)
    return cli_dir, py_dir, result, summary


# ------------------------------------------------------------------------------ Model
def test_model_from_file_names():
    m = aspects.Model.from_file(RPRPR)
    assert m.name == "RPRPR"
    assert m.pose == ["x1", "x2"] and m.command == ["q1", "q2"]
    assert m.file == RPRPR


def test_model_error_carries_file_line_col():
    text = "robot X\npose x in [0, 1]\ncommand q in [0, 1]\nequation x + q * = 1\n"
    with pytest.raises(aspects.ModelError) as e:
        aspects.Model.from_string(text, "bad.robot")
    assert str(e.value) == "bad.robot:4:18: error: expected an expression, found '='"
    assert (e.value.file, e.value.line, e.value.col) == ("bad.robot", 4, 18)
    assert isinstance(e.value, ValueError)


def test_model_missing_file_says_why():
    with pytest.raises(aspects.ModelError) as e:
        aspects.Model.from_file("/nonexistent/x.robot")
    assert str(e.value) == ("/nonexistent/x.robot: error: cannot open model file: "
                            "No such file or directory")
    assert (e.value.file, e.value.line, e.value.col) == ("/nonexistent/x.robot", 0, 0)


def test_model_wrong_type():
    with pytest.raises(TypeError):
        aspects.Model.from_string(42)


# ------------------------------------------------------------------------------ solve
def test_solve_counts_equal_the_command_line(rprpr):
    _, _, r, s = rprpr
    assert r.summary["boxes"] == s["boxes"]
    assert r.summary["csncs"]["count"] == s["csncs"]["count"]
    assert r.summary["csncs"]["sizes"] == s["csncs"]["sizes"]
    assert r.lower_bound == s["csncs"]["separated_lower_bound"] == 2
    assert len(r.ids) == s["boxes"]["total"]
    assert int((r.status == aspects.SOLUTION).sum()) == s["boxes"]["solution"]
    assert int((r.status != aspects.SOLUTION).sum()) == s["boxes"]["undecided"]
    assert [c.size for c in r.csncs] == s["csncs"]["sizes"]
    assert len(r.filtered_csncs) == s["csncs"]["filtered"]
    assert r.complete and r.stopped_by is None


def test_arrays_shapes_and_nan_commands(rprpr):
    _, _, r, _ = rprpr
    n = len(r.ids)
    assert r.lower.shape == (n, 4) and r.upper.shape == (n, 4)
    assert np.all(np.diff(r.ids.astype(np.int64)) > 0)
    sol = r.status == aspects.SOLUTION
    assert not np.isnan(r.lower[sol]).any()
    # An undecided box's command part is not in aspects.idx: NaN, its pose part is not.
    assert np.isnan(r.lower[~sol][:, 2:]).all() and not np.isnan(r.lower[~sol][:, :2]).any()
    assert np.all(r.lower[sol] <= r.upper[sol])
    assert set(np.unique(r.csnc[~sol]).tolist()) == {-1}


def test_out_writes_the_command_lines_files(rprpr):
    cli_dir, py_dir, _, _ = rprpr
    for name in ("boxes.csv", "aspects.idx"):
        with open(os.path.join(cli_dir, name), "rb") as a, open(os.path.join(py_dir, name), "rb") as b:
            assert a.read() == b.read(), name
    assert os.path.isfile(os.path.join(py_dir, "aspects.cert"))
    assert not [f for f in os.listdir(py_dir) if "tmp" in f]


def test_boxes_csv_ends_are_the_solvers_doubles(rprpr):
    """boxes.csv's decimal ends read back as exactly the doubles the index holds (shortest
    round-trip printing; seen failing when printed with 15 significant digits)."""
    cli_dir, _, r, _ = rprpr
    with open(os.path.join(cli_dir, "boxes.csv")) as f:
        rows = [line.rstrip("\n").split(",") for line in f][1:]
    assert len(rows) == len(r.ids)
    ends = np.array([[float(t) for t in row[4:12]] for row in rows])
    lower, upper = ends[:, 0::2], ends[:, 1::2]
    sol = r.status == aspects.SOLUTION
    assert sol.sum() > 100
    assert np.array_equal(lower[sol], r.lower[sol]) and np.array_equal(upper[sol], r.upper[sol])
    # The index keeps an undecided box's pose part only.
    assert np.array_equal(lower[~sol][:, :2], r.lower[~sol][:, :2])
    assert np.array_equal(upper[~sol][:, :2], r.upper[~sol][:, :2])


def test_load_equals_solve(rprpr):
    _, py_dir, r, _ = rprpr
    loaded = aspects.load(py_dir)
    for key in ("ids", "status", "csnc"):
        assert np.array_equal(getattr(loaded, key), getattr(r, key))
    assert np.array_equal(loaded.lower, r.lower, equal_nan=True)
    assert loaded.summary["boxes"] == r.summary["boxes"]
    assert loaded.directory == py_dir


def test_load_does_not_read_boxes_csv(rprpr, tmp_path):
    _, py_dir, r, _ = rprpr
    d = tmp_path / "idx_only"
    d.mkdir()
    for name in ("aspects.idx", "summary.json"):
        (d / name).write_bytes(open(os.path.join(py_dir, name), "rb").read())
    assert len(aspects.load(str(d)).ids) == len(r.ids)


def test_query_and_path_equal_the_command_line(rprpr):
    cli_dir, _, r, _ = rprpr
    q = json.loads(cli("query", cli_dir, "--pose", "3,5", "--json").stdout)
    assert r.query([3, 5]).to_dict() == q
    assert q["outcome"] == "answered" and [a["csnc"] for a in q["answers"]] == [1]
    lo, hi = q["answers"][0]["command_lo"][0], q["answers"][0]["command_hi"][0]
    assert lo <= math.sqrt(34) <= hi and hi - lo < 1e-14  # q1 = |(3, 5)|
    p = json.loads(cli("path", cli_dir, "--from", "3,5", "--to", "4,2.5", "--json").stdout)
    assert r.path((3.0, 5.0), np.array([4.0, 2.5])).to_dict() == p
    assert p["outcome"] == "found"


def test_check_verifies(rprpr):
    _, _, r, s = rprpr
    v = r.check()
    assert v["verdict"] == "VERIFIED"
    assert v["solutions"] == s["boxes"]["solution"]
    assert v["checked_lower_bound"] == 2


def test_check_without_directory():
    r = aspects.solve(aspects.Model.from_file(PRRP), eps=0.1)
    assert r.directory is None
    with pytest.raises(ValueError, match="out=DIR"):
        r.check()


def test_a_run_removes_the_certificate_it_does_not_rewrite(tmp_path):
    """Issue 50, item 3: RRRRR's certificate stayed beside a PRRP result solved with
    certificate=False, and check() verified it (lower bound 10)."""
    d = str(tmp_path / "d")
    rrrrr = aspects.solve(aspects.Model.from_string(RRRRR_TEXT, "rrrrr"), eps=0.5, out=d)
    assert rrrrr.check()["lower_bound"] == 10
    prrp = aspects.solve(aspects.Model.from_file(PRRP), eps=0.1, out=d, certificate=False)
    assert sorted(os.listdir(d)) == [".lock", "aspects.idx", "boxes.csv", "summary.json"]
    with pytest.raises(ValueError, match=r"the result has no certificate \(solved with "
                                         r"certificate=False\)$"):
        prrp.check()
    # Compressed after plain: the plain one goes.
    aspects.solve(aspects.Model.from_file(PRRP), eps=0.1, out=d)
    r = aspects.solve(aspects.Model.from_file(PRRP), eps=0.1, out=d, compress_certificate=True)
    assert "aspects.cert" not in os.listdir(d) and "aspects.cert.zst" in os.listdir(d)
    v = r.check()
    assert (v["verdict"], v["lower_bound"], v["sha256_cert"]) == (
        "VERIFIED", 4, r.summary["certificate_sha256"])


def test_check_and_load_refuse_another_runs_certificate(tmp_path):
    """A certificate put back from another run: of another model, load() refuses the
    directory (the certificate's model line); of the same model at another eps, check()
    refuses it after check_cert (its sha256 is not the one the index records)."""
    a, b, c = (str(tmp_path / n) for n in "abc")
    aspects.solve(aspects.Model.from_string(RRRRR_TEXT, "rrrrr"), eps=1, out=a)
    aspects.solve(aspects.Model.from_file(PRRP), eps=0.1, out=b)
    aspects.solve(aspects.Model.from_file(PRRP), eps=0.2, out=c)
    with open(os.path.join(b, "aspects.cert"), "rb") as f:
        prrp_cert = f.read()
    with open(os.path.join(b, "aspects.cert"), "wb") as f:
        f.write(open(os.path.join(a, "aspects.cert"), "rb").read())
    with pytest.raises(aspects.ResultError, match=r"aspects.cert: its model \(sha256 "
                                                  r"[0-9a-f]{16}\) is not the result's"):
        aspects.load(b)
    with open(os.path.join(b, "aspects.cert"), "wb") as f:
        f.write(prrp_cert)
    with open(os.path.join(c, "aspects.cert"), "wb") as f:
        f.write(prrp_cert)  # eps 0.1's beside eps 0.2's index
    r = aspects.load(c)
    with pytest.raises(ValueError, match=r"is not this result's certificate: its certificate "
                                         r"sha256 is [0-9a-f]{16}, the result's [0-9a-f]{16}"):
        r.check()
    assert aspects.load(b).check()["verdict"] == "VERIFIED"


def test_out_with_a_nul_character_creates_nothing(tmp_path):
    """Issue 50, item 8: out="a\\0b" created directory a, then failed."""
    with pytest.raises(ValueError, match="path contains a NUL character"):
        aspects.solve(aspects.Model.from_file(PRRP), eps=0.1, out=str(tmp_path / "a") + "\0b")
    assert os.listdir(tmp_path) == []
    with pytest.raises(aspects.ResultError, match=r"a\x00b: not a directory"):
        aspects.load(str(tmp_path / "a") + "\0b")


def test_out_locked_by_another_run_is_refused_at_once(tmp_path):
    """Issue 50, item 4: two runs writing one directory mixed their files."""
    import fcntl
    d = tmp_path / "d"
    d.mkdir()
    with open(d / ".lock", "w") as held:
        fcntl.flock(held, fcntl.LOCK_EX)
        start = time.monotonic()
        with pytest.raises(ValueError, match=r"d is being written by another run \(it holds "
                                              r".*/d/\.lock\): wait for that run to end"):
            aspects.solve(aspects.Model.from_file(PRRP), eps=0.1, out=str(d))
        assert time.monotonic() - start < 5
        assert sorted(os.listdir(d)) == [".lock"]
    aspects.solve(aspects.Model.from_file(PRRP), eps=0.1, out=str(d))  # released: it runs


def test_max_boxes_gives_a_partial_result():
    r = aspects.solve(aspects.Model.from_file(PRRP), eps=0.1, max_boxes=10)
    assert not r.complete and r.stopped_by == "max-boxes"
    assert r.summary["boxes"]["unexplored"] == int((r.status == aspects.UNEXPLORED).sum()) > 0


def test_progress_callback_and_its_exception():
    seen = []
    model = aspects.Model.default()
    aspects.solve(model, eps=0.3, progress=seen.append)
    assert seen and {"processed", "solutions", "undecided", "decided", "phases"} <= set(seen[-1])
    assert [name for name, _ in seen[-1]["phases"]][:1] == ["search"]

    def fail(d):
        raise KeyError("from the callback")
    with pytest.raises(KeyError, match="from the callback"):
        aspects.solve(model, eps=0.05, progress=fail)


def test_progress_true_uses_tqdm_when_installed(monkeypatch):
    import sys
    import types
    bars = []

    class FakeTqdm:
        def __init__(self, total, **kw):
            self.total, self.n, self.closed = total, 0.0, False
            bars.append(self)

        def update(self, x):
            self.n += x

        def set_postfix_str(self, s, refresh=True):
            self.postfix = s

        def close(self):
            self.closed = True
    monkeypatch.setitem(sys.modules, "tqdm", types.SimpleNamespace(tqdm=FakeTqdm))
    aspects.solve(aspects.Model.default(), eps=0.1)  # warm: the next run is the measured one
    aspects.solve(aspects.Model.default(), eps=0.1, progress=True)
    assert len(bars) == 1 and bars[0].closed and bars[0].total == 100
    assert 0 < bars[0].n <= 100 and "boxes" in bars[0].postfix


def test_progress_true_without_tqdm_prints_lines(monkeypatch, capsys):
    import sys
    monkeypatch.setitem(sys.modules, "tqdm", None)  # import tqdm raises ImportError
    aspects.solve(aspects.Model.from_file(PRRP), eps=0.1, progress=True)
    err = capsys.readouterr().err
    assert err.startswith("[aspects] ") and "[aspects] done: 95 boxes, 36 solution" in err


def test_sigint_stops_the_search_and_raises_interrupted_with_the_result(capsys):
    # Ctrl-C (issue 50, item 9): the search stops within a second, the links and CSNCs are
    # made on the boxes it made, and aspects.Interrupted (a KeyboardInterrupt) carries the
    # result. Before: a warning, and a result without a link.
    model = aspects.Model.default()
    fired = []

    def interrupt():
        time.sleep(1.0)
        fired.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)
    threading.Thread(target=interrupt).start()
    with pytest.raises(aspects.Interrupted) as caught:
        aspects.solve(model, eps=0.02, threads=1)
    assert isinstance(caught.value, KeyboardInterrupt)
    r = caught.value.result
    assert fired and time.monotonic() - fired[0] < 5.0
    assert not r.complete and r.stopped_by == "signal"
    s = r.summary
    assert s["boxes"]["unexplored"] > 0 and s["boxes"]["solution"] > 0
    assert s["links"]["certified"] > 0
    assert s["csncs"]["count"] < s["boxes"]["solution"]
    err = capsys.readouterr().err
    assert "aspects.solve: interrupted: no more boxes are searched" in err
    assert "interrupted again" not in err


def test_second_sigint_says_it_stops_at_once(capsys):
    # The second Ctrl-C, once the first was handled (the search is over), stops the phases
    # after the search (what it cuts depends on when it comes: PhaseStops.ASecondInterrupt*
    # in C++ shows it) and says so: still Interrupted with the result. A KeyboardInterrupt
    # raised inside the progress callback is such a Ctrl-C, not the callback's failure.
    model = aspects.Model.default()
    sent = []

    def progress(d):
        if not sent and d["processed"] > 0:
            sent.append(1)
            os.kill(os.getpid(), signal.SIGINT)
        elif len(sent) == 1 and d["phases"]:  # the first was seen: the search has ended
            sent.append(2)
            os.kill(os.getpid(), signal.SIGINT)
    with pytest.raises(aspects.Interrupted) as caught:
        aspects.solve(model, eps=0.02, threads=1, progress=progress)
    r = caught.value.result
    assert len(sent) == 2
    assert not r.complete and r.stopped_by == "signal"
    err = capsys.readouterr().err
    assert "interrupted: no more boxes are searched" in err
    assert "aspects.solve: interrupted again: stopping now" in err


# ------------------------------------------------------------------------------ bad input
@pytest.mark.parametrize("pose, error, match", [
    ([float("nan"), 1.0], ValueError, "not a finite number"),
    ([1.0], ValueError, "2 coordinates"),
    ([1.0, 2.0, 3.0], ValueError, "2 coordinates"),
    ("3,5", TypeError, "sequence of numbers"),
    ([None, 1], TypeError, "sequence of numbers"),
    (5, TypeError, "sequence of numbers"),
    ([math.inf, 1], ValueError, "not a finite number"),
])
def test_bad_pose(rprpr, pose, error, match):
    _, _, r, _ = rprpr
    with pytest.raises(error, match=match):
        r.query(pose)
    with pytest.raises(error, match=match):
        r.path(pose, [3, 5])


@pytest.mark.parametrize("x1", [1e-310, -5e-324, 2.2250738585072009e-308, 1e-400])
def test_subnormal_pose(rprpr, x1):
    # A subnormal (or an underflow to 0) is a finite pose like any other, as in `--pose`.
    cli_dir, _, r, _ = rprpr
    q = r.query([x1, 5])
    assert q["pose"] == [x1, 5.0]
    assert q.to_dict() == json.loads(cli("query", cli_dir, "--pose", f"{x1!r},5", "--json",
                                         check=False).stdout)
    p = r.path([x1, 5], [3, 5])
    assert p["from"] == [x1, 5.0]
    assert p.to_dict() == json.loads(cli("path", cli_dir, "--from", f"{x1!r},5", "--to", "3,5",
                                         "--json", check=False).stdout)


def test_bad_csnc(rprpr):
    _, _, r, _ = rprpr
    with pytest.raises(ValueError, match="csnc must be between 0 and 1"):
        r.path([3, 5], [4, 2.5], csnc=7)
    # Issue 50, item 8: -1 was taken as "any CSNC".
    with pytest.raises(ValueError, match=r"^csnc must be between 0 and 1, got -1$"):
        r.path([3, 5], [4, 2.5], csnc=-1)
    with pytest.raises(TypeError):
        r.path([3, 5], [4, 2.5], csnc="0")


def test_load_not_a_result(tmp_path):
    with pytest.raises(aspects.ResultError, match="no aspects.idx"):
        aspects.load(str(tmp_path))
    with pytest.raises(aspects.ResultError, match="not a directory"):
        aspects.load(str(tmp_path / "missing"))
    (tmp_path / "aspects.idx").write_bytes(b"not an index at all")
    with pytest.raises(aspects.ResultError, match="aspects.idx"):
        aspects.load(str(tmp_path))
    with pytest.raises(TypeError):
        aspects.load(3)


@pytest.mark.parametrize("kw, error", [
    (dict(eps=-1), ValueError), (dict(eps=float("nan")), ValueError), (dict(eps="a"), TypeError),
    (dict(threads=-3), ValueError), (dict(threads=1.5), TypeError),
    (dict(time_limit=0), ValueError), (dict(bisect="sideways"), ValueError),
    (dict(progress=3), TypeError), (dict(max_boxes=0), ValueError),
])
def test_bad_solve_arguments(kw, error):
    with pytest.raises(error):
        aspects.solve(aspects.Model.from_file(PRRP), **kw)
    with pytest.raises(TypeError, match="aspects.Model or the path of a .robot file"):
        aspects.solve(42)


# ------------------------------------------------------------------------------ plots
def is_png(path):
    with open(path, "rb") as f:
        return f.read(8) == b"\x89PNG\r\n\x1a\n"


def test_result_plot_and_cli_plot(rprpr, tmp_path):
    cli_dir, _, r, _ = rprpr
    path = r.path([3, 5], [4, 2.5])
    fig = r.plot(str(tmp_path / "py.png"), path=path)
    assert is_png(tmp_path / "py.png")
    assert fig.axes[0].get_xlabel() == "x1" and fig.axes[0].get_ylabel() == "x2"
    (tmp_path / "path.json").write_text(json.dumps(path.to_dict()))
    out = cli("plot", cli_dir, "--out", str(tmp_path / "cli.png"), "--path",
              str(tmp_path / "path.json"))
    assert out.stdout == f"wrote {tmp_path / 'cli.png'}\n"
    assert is_png(tmp_path / "cli.png")
    assert sorted(os.listdir(tmp_path)) == ["cli.png", "path.json", "py.png"]


def test_cli_plot_bad_input(rprpr, tmp_path):
    cli_dir, _, _, _ = rprpr
    assert cli("plot", str(tmp_path), check=False).returncode == 2
    (tmp_path / "bad.json").write_text("{not json")
    run = cli("plot", cli_dir, "--out", str(tmp_path / "x.png"), "--path",
              str(tmp_path / "bad.json"), check=False)
    assert run.returncode == 2 and "not JSON" in run.stderr
    (tmp_path / "short.json").write_text(json.dumps(
        {"csnc": 0, "waypoints": [{"pose": [1.0]}]}))
    run = cli("plot", cli_dir, "--out", str(tmp_path / "x.png"), "--path",
              str(tmp_path / "short.json"), check=False)
    assert run.returncode == 2 and "2 pose coordinates" in run.stderr
    assert not (tmp_path / "x.png").exists()


def test_plot_three_pose_variables(tmp_path):
    text = """robot cartesian-3
pose x1 in [-2, 2]
pose x2 in [-2, 2]
pose x3 in [-2, 2]
command q1 in [-3, 3]
command q2 in [-3, 3]
command q3 in [-3, 3]
equation q1 = x1 + x2
equation q2 = x2 - x1
equation q3^2 = x3 + 2.5
"""
    r = aspects.solve(aspects.Model.from_string(text), eps=0.5)
    assert r.lower_bound == 2
    path = r.path([0.2, 0.3, 1.0], [-1.0, 0.5, 1.2])
    assert path["outcome"] == "found"
    fig = r.plot(str(tmp_path / "three.png"), path=path)
    assert is_png(tmp_path / "three.png")
    assert fig.axes[0].name == "3d" and fig.axes[1].get_zlabel() == "x3"


def test_csnc_signs_hold_every_counted_class():
    """A class counts toward the bound through a certified box whose factors all have a
    decided sign; that box's CSNC must report the class."""
    r = aspects.solve(aspects.Model.from_file(os.path.join(ROBOTS, "3rrr.robot")), eps=2, threads=2)
    decided = {"".join("+" if v > 0 else "-" for v in c.signs) for c in r.csncs if all(c.signs)}
    counted = {c["signs"] for c in r.summary["csncs"]["separated_classes"]}
    assert len(counted) == r.lower_bound == 16
    assert counted <= decided


def test_csnc_signs_are_decided_by_any_of_its_boxes():
    """Each factor's sign is constant on a CSNC: a CSNC reports it when one of its boxes
    decides it, and no box decides the other sign. (Break that made it fail: the signs of
    the CSNC's first box only; on 3-RRR* at eps 0.7, 12 CSNCs have a first box whose
    enclosure straddles 0 where another box decides the sign.)"""
    r = aspects.solve(aspects.Model.from_file(os.path.join(ROBOTS, "3rrr_star.robot")), eps=0.7,
                      threads=2)
    straddling_first = 0
    for c in r.csncs:
        box_signs = r.signs[r.csnc == c.id]
        for k, s in enumerate(c.signs):
            decided_here = set(box_signs[:, k].tolist()) - {0}
            assert decided_here == ({s} if s != 0 else set()), (c, k, decided_here)
            straddling_first += int(box_signs[0, k] == 0 and s != 0)
    assert straddling_first > 0  # the case the test is about occurs here


# ------------------------------------------------------------------------------ issue 51
def test_version_is_the_programs():
    assert aspects.__version__ == cli("--version").stdout.split()[1]


def test_solve_takes_a_path(tmp_path):
    # A str or os.PathLike is read as Model.from_file reads it (it was a TypeError).
    import pathlib
    by_model = aspects.solve(aspects.Model.from_file(PRRP), eps=0.2)
    for given in (PRRP, pathlib.Path(PRRP)):
        r = aspects.solve(given, eps=0.2)
        assert r.robot == "PRRP" and r.lower_bound == by_model.lower_bound == 4
        assert np.array_equal(r.ids, by_model.ids)
    with pytest.raises(aspects.ModelError, match="cannot open model file: No such file"):
        aspects.solve(str(tmp_path / "none.robot"))


def test_model_shows_variables_domains_equations():
    m = aspects.Model.from_file(RPRPR)
    assert m.variables == ["x1", "x2", "q1", "q2"]
    assert m.domains == {"x1": (-20.0, 20.0), "x2": (-20.0, 20.0), "q1": (2.0, 6.0),
                         "q2": (4.0, 9.0)}
    assert list(m.domains) == m.variables  # model order
    assert m.equations == ["x1^2 + x2^2 - q1^2 = 0", "(x1 - 9)^2 + x2^2 - q2^2 = 0"]
    assert m.periodic == [] and m.factors == [] and m.constraints == [] and m.bisect == ""
    assert repr(m) == (f"<aspects.Model RPRPR ({RPRPR})\n"
                       "  pose    x1 in [-20, 20]\n  pose    x2 in [-20, 20]\n"
                       "  command q1 in [2, 6]\n  command q2 in [4, 9]\n"
                       "  equation   x1^2 + x2^2 - q1^2 = 0\n"
                       "  equation   (x1 - 9)^2 + x2^2 - q2^2 = 0>")
    d = aspects.Model.default()
    assert d.periodic == ["q1", "q2"] and d.bisect == "verdict"
    lo, hi = d.domains["q1"]
    assert lo <= -math.pi and math.pi <= hi and hi - lo < 2 * math.pi + 1e-14  # outward
    assert "command q1 in [-3.14159, 3.14159] periodic" in repr(d)


def test_query_and_path_are_classes_with_their_dict(rprpr):
    _, _, r, _ = rprpr
    q = r.query([3, 5])
    assert isinstance(q, aspects.QueryResult)
    assert q.outcome == "answered" and q.pose == (3.0, 5.0) and q.csncs == (1,)
    a = q.answers[0]
    assert isinstance(a, aspects.Command) and a.csnc == 1
    assert a.command_lo[0] <= math.sqrt(34) <= a.command_hi[0]
    assert a.to_dict() == q.to_dict()["answers"][0]
    assert q["outcome"] == "answered" and q["answers"][0]["csnc"] == 1  # the dict's keys
    q.to_dict()["outcome"] = "changed"  # a copy
    assert q.outcome == "answered" and q["outcome"] == "answered"
    p = r.path([3, 5], [4, 2.5])
    assert isinstance(p, aspects.PathResult) and p.found and p.csnc == 1
    assert p.start == (3.0, 5.0) and p.goal == (4.0, 2.5)
    assert p.waypoints[0].kind == "start" and p.waypoints[-1].pose == (4.0, 2.5)
    assert p.poses.shape == (len(p.waypoints), 2)
    # Issue 51: the straight segment, certified through a chain of linked boxes (the chain
    # of links before the shortcut was longer).
    assert len(p.waypoints) == 2 and p.waypoints[0].kind == "start"
    assert p.length == p.to_dict()["length"] == p.to_dict()["straight"] == math.dist((3, 5), (4, 2.5))
    assert p.to_dict()["chain_length"] > p.length
    none = r.path([3, 5], [19, 19])
    assert not none.found and none.outcome == "goal_in_no_solution_box"
    assert none.csnc is None and none.length is None and none.poses.shape == (0, 2)


def test_query_many_poses_gives_arrays(rprpr):
    _, _, r, _ = rprpr
    poses = np.array([[3, 5], [4, 2.5], [19.5, 19.5]])
    b = r.query(poses)
    assert isinstance(b, aspects.QueryBatch) and len(b) == 3
    assert list(b.outcome) == ["answered", "answered", "outside_workspace"]
    assert b.count.tolist() == [1, 1, 0]
    assert b.csnc.tolist() == [[1], [1], [-1]]
    assert b.command_lo.shape == b.command_hi.shape == (3, 1, 2)
    assert np.isnan(b.command_lo[2]).all()
    for i, pose in enumerate(poses):  # each row as the one-pose query answers it
        one = r.query(pose)
        assert b[i] == one and b.to_dict()[i] == one.to_dict()
        assert b.command_lo[i, :b.count[i]].tolist() == [list(a.command_lo) for a in one.answers]
    assert len(r.query(np.empty((0, 2)))) == 0
    assert r.query([[3, 5]]).count.tolist() == [1]  # a list of rows too


@pytest.mark.parametrize("poses, error, match", [
    (np.zeros((2, 3)), ValueError, r"^poses must have 2 columns \(x1, x2\), got 3$"),
    (np.array([[3, 5], [np.nan, 1]]), ValueError, r"^poses\[1\]: x1 = nan is not a finite number$"),
    (np.array([[3, 5], [30, 1]]), ValueError, r"^poses\[1\]: x1 = 30 is outside its declared domain"),
    ([[3, 5], [1]], TypeError, r"^poses must be an N x n array of numbers$"),
    ([["a", "b"]], TypeError, r"^poses must be an N x n array of numbers$"),
])
def test_query_many_bad_poses(rprpr, poses, error, match):
    _, _, r, _ = rprpr
    with pytest.raises(error, match=match):
        r.query(poses)


def test_solves_at_once_keep_their_own_arithmetic():
    """Three solves at once on three Python threads, one MPFI only and one at 80 bits, each
    give what the same solve gives alone: the arithmetic is each run's own (issue 48; the
    C++ test test_two_solves sees each run's evaluators compute as it asked)."""
    model = aspects.Model.from_file(RPRPR)
    asks = [{}, {"mpfi_only": True}, {"prec": 80}]
    alone = [aspects.solve(model, eps=0.03, threads=1, **a) for a in asks]
    together = [None] * len(asks)
    spans = [None] * len(asks)
    start = threading.Barrier(len(asks))

    def run(i):
        start.wait()
        t = time.monotonic()
        together[i] = aspects.solve(model, eps=0.03, threads=1, **asks[i])
        spans[i] = (t, time.monotonic())

    threads = [threading.Thread(target=run, args=(i,)) for i in range(len(asks))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert max(s[0] for s in spans) < min(s[1] for s in spans)  # all three ran at once
    for a, b in zip(alone, together):
        assert b.summary["boxes"] == a.summary["boxes"]
        assert b.summary["csncs"]["sizes"] == a.summary["csncs"]["sizes"]
        assert b.lower_bound == a.lower_bound == 2
        assert np.array_equal(b.ids, a.ids)
        assert np.array_equal(b.lower, a.lower, equal_nan=True)
        assert np.array_equal(b.upper, a.upper, equal_nan=True)
    # MPFI alone gives the double path's result, bit for bit.
    assert alone[1].summary["boxes"] == alone[0].summary["boxes"]
    assert np.array_equal(alone[1].lower, alone[0].lower, equal_nan=True)
    for a in alone:  # as `aspects solve robots/rprpr.robot --eps 0.03`
        assert (a.summary["boxes"]["solution"], a.summary["boxes"]["undecided"]) == (5314, 2358)


# ------------------------------------------------------------------------------ count
def test_count_is_exact_on_prrp_and_equals_the_command_line():
    c = aspects.count(PRRP)
    assert c.exact and c.count == 4 and c.lower == c.upper == 4
    assert str(c) == "4 aspects (certified: lower = upper)"
    assert not c.interrupted and c.open == ()
    j = json.loads(cli("count", PRRP, "--json").stdout)
    d = c.to_dict()
    for key in ("lower_bound", "upper_bound", "exact", "stop", "boxes", "pieces", "adjacencies"):
        assert d[key] == j[key], key


def test_count_with_a_round_budget_gives_the_lower_bound_and_the_open_places():
    c = aspects.count(PRRP, rounds=1)
    assert not c.exact and c.count is None
    assert c.lower == 4 and c.upper is None
    assert c.stop == "round budget spent"
    assert str(c) == "at least 4 aspects (certified); no upper bound: 3 piece(s) not proved connected"
    assert len(c.open) == 3 and {p.cls for p in c.open} == {"-+", "+-", "++"}
    assert all(p.reason == "no chart proved (pose, command or mixed)" for p in c.open)
    assert all(lo <= hi for p in c.open for lo, hi in zip(p.lo, p.hi))


def test_count_refuses_what_the_command_line_refuses():
    model = aspects.Model.from_string(
        "robot r\npose x in [-2, 2]\ncommand q in [-5, 5]\nequation q - x = 0\n"
        "factor x - 1\n", "r.robot")
    with pytest.raises(ValueError, match=r"r\.robot: count: models with `factor`"):
        aspects.count(model)
    # Constraints are counted (the feasible aspects): the circle with x >= 0.5 keeps two arcs.
    cut = aspects.Model.from_string(
        "robot c\npose x in [-2, 2]\ncommand q in [-2, 2]\nequation x^2 + q^2 = 1\n"
        "constraint x >= 0.5\n", "c.robot")
    c = aspects.count(cut)
    assert c.exact and c.lower == c.upper == 2
    with pytest.raises(ValueError, match="rounds must be"):
        aspects.count(PRRP, rounds=0)
    with pytest.raises(ValueError, match="min_width must be"):
        aspects.count(PRRP, min_width=1)
    with pytest.raises(TypeError):
        aspects.count(42)


def test_count_regions_are_the_aspects_when_exact():
    c = aspects.count(PRRP)
    assert len(c.regions) == c.count == 4
    assert sorted(r.cls for r in c.regions) == ["++", "+-", "-+", "--"]
    volumes = [r.pose_volume for r in c.regions]
    assert volumes == sorted(volumes, reverse=True)
    for r in c.regions:  # x = ±sqrt(1 - q²): an arc of class (sign x, sign q) lies on its side
        x_lo, x_hi = r.lo[0], r.hi[0]
        assert (x_hi > 0.99) if r.cls[0] == "+" else (x_lo < -0.99)
    assert c.to_dict()["regions"][0]["class"] == c.regions[0].cls


def test_piece_path_through_a_count_directory(tmp_path):
    out = tmp_path / "rprpr"
    c = aspects.count(RPRPR, out=out)
    assert c.exact and c.count == 2
    assert sorted(p.name for p in out.iterdir()) == ["count.pieces", "summary.json"]
    assert json.loads((out / "summary.json").read_text())["lower_bound"] == 2
    p = aspects.piece_path(out, (3, 2), (4, 1))
    assert p.found and p.cls == "+--" and p.pieces == 6, p.line
    assert p.waypoints[0]["kind"] == "start" and p.waypoints[-1]["kind"] == "goal"
    j = json.loads(cli("path", str(out), "--from", "3,2", "--to", "4,1", "--json").stdout)
    assert p.to_dict() == j
    assert str(p) == cli("path", str(out), "--from", "3,2", "--to", "4,1").stdout
    assert "through 6 pieces of class +-- (one aspect): 7 waypoints, 6 segments" in p.line
    assert "through 1 piece of class +-- (one aspect): 2 waypoints, 1 segment (0 join points" \
        in aspects.piece_path(out, (3, 2), (3, 3)).line
    # The two half-planes x2 > 0 and x2 < 0 are two aspects: refused, with the count exact.
    q = aspects.piece_path(out, (3, 2), (3, -2))
    assert not q.found and q.outcome == "different_classes", q.line
    with pytest.raises(ValueError, match="--class must be 3 signs"):
        aspects.piece_path(out, (3, 2), (4, 1), cls="+")
    with pytest.raises(ValueError, match="start expects 2 numbers"):
        aspects.piece_path(out, (3,), (4, 1))
    with pytest.raises(aspects.ResultError):
        aspects.piece_path(tmp_path, (3, 2), (4, 1))
    with pytest.raises(ValueError, match="holds a solve's result"):
        (tmp_path / "solved").mkdir()
        (tmp_path / "solved" / "aspects.idx").write_bytes(b"")
        aspects.count(PRRP, out=tmp_path / "solved")


def test_load_count_labels_the_aspects_and_draws_them(tmp_path):
    aspects.count(PRRP, out=tmp_path / "prrp")
    c = aspects.load_count(tmp_path / "prrp")
    assert c.exact and c.lower == c.upper == 4 and c.robot == "PRRP"
    labels = c.aspects()
    assert labels.shape == c.cls.shape and labels.max() + 1 == 4
    # One class per aspect: the circle's four quarter arcs.
    for a in range(4):
        assert len(set(c.cls[labels == a].tolist())) == 1
    assert sorted(c.class_signs(k) for k in set(c.cls.tolist())) == ["++", "+-", "-+", "--"]
    c.figure(tmp_path / "prrp.png", x="x", y="q")
    assert (tmp_path / "prrp.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(ValueError, match="no variable 'z'"):
        c.figure(tmp_path / "bad.png", x="x", y="z")
    with pytest.raises(aspects.ResultError):
        aspects.load_count(tmp_path)
