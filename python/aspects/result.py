"""aspects.Result: a solved or loaded result (the compiled aspects._aspects._Result inside)."""
import collections
import json
import math
import os
import shutil
import subprocess

from .answers import PathResult, QueryBatch, QueryResult

CSNC = collections.namedtuple("CSNC", "id size kept signs")
CSNC.__doc__ = ("A CSNC: its number (by decreasing size), its boxes, whether the size-ratio "
                "filter keeps it (a heuristic), the signs of the determinant factors on it.")


def _check_cert_program():
    """check_cert: $ASPECTS_CHECK_CERT, the build tree's, the installed one (P/bin for a
    package in P/lib/python3/dist-packages), else the one on PATH."""
    here = os.path.dirname(os.path.abspath(__file__))
    for p in (os.environ.get("ASPECTS_CHECK_CERT"),
              os.path.join(here, "..", "..", "certificates", "check_cert"),
              os.path.join(here, "..", "..", "..", "..", "bin", "check_cert"),
              shutil.which("check_cert")):
        if p and os.path.isfile(p) and os.access(p, os.X_OK):
            return os.path.normpath(p)
    raise FileNotFoundError("check_cert not found (build it, install it, or set "
                            "ASPECTS_CHECK_CERT)")


class Result:
    """What `aspects solve` computed. The claims are those of README "What each command
    claims": solution boxes, links, CSNCs and the bound are certified (check() re-verifies
    the certificate); the filter is a heuristic."""

    def __init__(self, core):
        self._core = core
        self._arrays = None

    def __repr__(self):
        state = "complete" if self.complete else f"partial (stopped by {self.stopped_by})"
        return (f"<aspects.Result {self.robot} eps={self.eps:g}: {len(self.ids)} boxes, "
                f"{self._core.csnc_count} CSNCs, lower bound {self.lower_bound}, {state}>")

    # ---------------------------------------------------------------- about the run
    robot = property(lambda self: self._core.robot)
    eps = property(lambda self: self._core.eps)
    variables = property(lambda self: self._core.variables, doc="model order")
    pose_variables = property(lambda self: self._core.pose_variables, doc="pose order")
    directory = property(lambda self: self._core.directory or None,
                         doc="the result directory (None: solved without out=)")
    model_source = property(lambda self: self._core.model_source)
    factors = property(lambda self: self._core.factors,
                       doc="(origin, expression) of each determinant factor")

    @property
    def summary(self):
        """summary.json as a dict (None for a loaded directory that has none)."""
        return self._core.summary

    @property
    def complete(self):
        s = self.summary
        return True if s is None else bool(s.get("complete", True))

    @property
    def stopped_by(self):
        s = self.summary
        return None if s is None else s.get("stopped_by")

    @property
    def lower_bound(self):
        """The certified lower bound on the number of aspects (separation, paper 4.4.2)."""
        s = self.summary
        return None if s is None else s["csncs"]["separated_lower_bound"]

    # ---------------------------------------------------------------- boxes
    def _a(self, key):
        if self._arrays is None:
            self._arrays = self._core._arrays()
            for a in self._arrays.values():
                a.setflags(write=False)
        return self._arrays[key]

    ids = property(lambda self: self._a("id"), doc="box ids (as in boxes.csv), increasing")
    lower = property(lambda self: self._a("lower"),
                     doc="lower ends, one column per variable (model order); an undecided "
                         "box's command columns are NaN (aspects.idx keeps its pose part)")
    upper = property(lambda self: self._a("upper"), doc="upper ends, as lower")
    status = property(lambda self: self._a("status"),
                      doc="aspects.SOLUTION, UNDECIDED_NO_EXISTENCE, UNDECIDED_SINGULAR, "
                          "UNDECIDED_CONSTRAINT or UNEXPLORED")
    csnc = property(lambda self: self._a("csnc"), doc="CSNC of each box, -1 when undecided")
    signs = property(lambda self: self._a("signs"),
                     doc="signs of the determinant factors (summary['factors'] order) on each "
                         "solution box, certified by interval evaluation: -1, +1, or 0 where "
                         "the enclosure contains 0 (and on undecided boxes)")

    @property
    def csncs(self):
        """Every CSNC, largest first."""
        import numpy as np
        sizes = np.bincount(self.csnc[self.csnc >= 0], minlength=self._core.csnc_count)
        signs = self._core._csnc_signs()
        n = self._core.filtered_count
        return [CSNC(k, int(sizes[k]), k < n, tuple(signs[k])) for k in range(len(sizes))]

    @property
    def filtered_csncs(self):
        """The CSNCs the paper's size-ratio filter keeps (a heuristic, never certified)."""
        return [c for c in self.csncs if c.kept]

    # ---------------------------------------------------------------- using it
    def query(self, pose):
        """The certified commands of a pose: a QueryResult (aspects.answers), whose
        to_dict() is what `aspects query --json` prints. Given an N x n array of poses (one
        a row), a QueryBatch: the answers as arrays, and each row's QueryResult."""
        import numpy as np
        try:
            rows = not isinstance(pose, (str, bytes)) and np.ndim(pose) == 2
        except ValueError:  # numpy refuses ragged rows
            raise TypeError("poses must be an N x n array of numbers") from None
        if rows:
            return self._query_many(pose)
        return QueryResult.from_dict(self._core._query(self._pose(pose, "pose")))

    def _query_many(self, poses):
        import numpy as np
        try:
            a = np.array(poses, dtype=float)
        except (TypeError, ValueError):
            raise TypeError("poses must be an N x n array of numbers") from None
        names = self.pose_variables
        if a.shape[1] != len(names):
            raise ValueError(f"poses must have {len(names)} columns ({', '.join(names)}), "
                             f"got {a.shape[1]}")
        bad = np.argwhere(~np.isfinite(a))
        if len(bad):
            i, j = bad[0]
            raise ValueError(f"poses[{i}]: {names[j]} = {a[i, j]} is not a finite number")
        results = [QueryResult.from_dict(d) for d in self._core._query_many(a.tolist())]
        commands = len(self.variables) - len(names)
        return QueryBatch.from_results(a, results, commands)

    def path(self, start, goal, csnc=None):
        """A certified singularity-free path: a PathResult (aspects.answers; outcome
        "found" with its waypoints, or why there is none), whose to_dict() is what `aspects
        path --json` prints."""
        if csnc is not None and (isinstance(csnc, bool) or not isinstance(csnc, int)):
            raise TypeError("csnc must be an integer")
        return PathResult.from_dict(
            self._core._path(self._pose(start, "start"), self._pose(goal, "goal"), csnc))

    def _pose(self, pose, what):
        """A pose as a list of floats, one finite number per pose variable (the C++ side
        checks the domain, as for --pose)."""
        values = _pose(pose, what)
        names = self.pose_variables
        if len(values) != len(names):
            raise ValueError(f"{what} must have {len(names)} coordinates ({', '.join(names)}), "
                             f"got {len(values)}")
        for name, x in zip(names, values):
            if not math.isfinite(x):
                raise ValueError(f"{what}: {name} = {x} is not a finite number")
        return values

    def check(self, threads=None, trust_factors=False):
        """Runs check_cert --json on the result's certificate (the one aspects.idx records);
        returns its verdict (a dict: "verdict" VERIFIED, UNCHECKED or a failure, and the
        counts). Raises ValueError when there is none, and when the certificate check_cert
        read is not this result's: its sha256 or its model's differs from those the result
        records (a file of another run). The index and summary's own ties to it: `aspects
        verify DIR`."""
        if not self.directory:
            raise ValueError("no certificate: solve with out=DIR (or load a directory)")
        name = self._core.certificate_file
        if not name:
            raise ValueError(f"{self.directory}: the result has no certificate (solved with "
                             "certificate=False)")
        cert = os.path.join(self.directory, name)
        if not os.path.isfile(cert):
            raise ValueError(f"{cert}: missing (the result's certificate)")
        cmd = [_check_cert_program(), "--json", cert]
        if threads is not None:
            cmd += ["--threads", str(int(threads))]
        if trust_factors:
            cmd.append("--trust-factors")
        run = subprocess.run(cmd, capture_output=True, text=True)
        try:
            verdict = json.loads(run.stdout)
        except ValueError:
            raise RuntimeError(f"check_cert gave no JSON (exit {run.returncode}): "
                               f"{run.stderr.strip()}") from None
        # Read after it was written? Its hashes say whether it is still the result's.
        for key, want, what in (("sha256_model", self._core.model_sha256, "model"),
                                ("sha256_cert", self._core.certificate_sha256, "certificate")):
            got = verdict.get(key)
            if got is not None and got != want:
                raise ValueError(f"{cert} is not this result's certificate: its {what} sha256 "
                                 f"is {got[:16]}, the result's {want[:16]} (a file of another "
                                 "run; solve again)")
        return verdict

    def plot(self, out=None, path=None, title="", *, axes=None, csncs=None, largest=None,
             dpi=None, size=None, ax=None):
        """The figure of `aspects plot` (aspects.plotting): the certified count in the
        title, then the separated representatives and the largest CSNCs, each in its own
        colour, the undecided boxes quiet. axes: two variables (pose or command, e.g.
        ["q1", "q2"]) or three (3-D); default: the pose's. csncs: the CSNC numbers to draw,
        or largest: the N largest. dpi, size=(width, height) in inches. ax: a matplotlib
        axes to draw the overview into (two axes). `path`: a dict from path() or a file of
        `aspects path --json` output. Saved to `out` when given (PNG, PDF, SVG: from the
        extension); returns the matplotlib Figure. ValueError for a bad option."""
        from . import plotting
        if isinstance(path, PathResult):  # Result.path's answer
            path = path.to_dict()
        if isinstance(path, (str, os.PathLike)):
            with open(path) as f:
                path = json.load(f)
        if path is not None and not isinstance(path, dict):
            raise TypeError("path must be a dict from Result.path() or a file name")
        return plotting.plot(self._box_set(), out=None if out is None else os.fspath(out),
                             path=path, title=title, axes=axes, csncs=csncs, largest=largest,
                             dpi=dpi, size=size, ax=ax)

    def view(self, out, *, axes=None, csncs=None, largest=None, voxels=False, grid=None):
        """Writes `out`, the HTML page of `aspects view` (plotly): the CSNCs of three
        variables (default: a 3-DOF robot's pose) as surfaces, or voxels, that turn in a
        browser. grid: raster cells per axis (4 to 256, default 64). ValueError for a bad
        option."""
        from . import view3d
        view3d.write_view(self._box_set(), os.fspath(out), axes=axes, csncs=csncs,
                          largest=largest, voxels=voxels, cells=grid)

    def export_vtk(self, out, *, axes=None, csncs=None, largest=None, voxels=False, grid=None):
        """Writes `out` (.vtu or .vtk), the file of `aspects export --vtk` (meshio): the
        CSNCs as triangles, or hexahedra with voxels=True, with the cell fields "csnc" and
        "separated". Options as view()."""
        from . import meshes
        meshes.write_vtk(self._box_set(), os.fspath(out), axes=axes, csncs=csncs,
                         largest=largest, voxels=voxels, cells=grid)

    def _box_set(self):
        """The boxes for aspects.plotting: every variable, with the run's certified count."""
        from . import plotting
        names = list(self.variables)
        s = self.summary or {}
        csncs = s.get("csncs", {})
        return plotting.BoxSet(names, self.lower, self.upper, self.status, self.csnc,
                               self._core.filtered_count, robot=self.robot, eps=self.eps,
                               pose=[names.index(v) for v in self.pose_variables],
                               periodic=[v in self._periodic_pose() for v in names],
                               csnc_count=self._core.csnc_count,
                               lower_bound=csncs.get("separated_lower_bound"),
                               representatives=csncs.get("separated_representatives"))

    def _periodic_pose(self):
        return {v for v, p in zip(self.pose_variables, self._core.pose_periodic) if p}


def _pose(pose, what):
    """A pose as a list of floats; numbers only (a string is not a pose)."""
    if isinstance(pose, (str, bytes)):
        raise TypeError(f"{what} must be a sequence of numbers, got {type(pose).__name__}")
    try:
        values = list(pose)
    except TypeError:
        raise TypeError(f"{what} must be a sequence of numbers, got "
                        f"{type(pose).__name__}") from None
    for x in values:
        if isinstance(x, bool) or not isinstance(x, (int, float)) and not hasattr(x, "__float__"):
            raise TypeError(f"{what} must be a sequence of numbers, got an element "
                            f"{type(x).__name__}")
    return [float(x) for x in values]
