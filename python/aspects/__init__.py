"""Certified generalized aspects of parallel robots, from Python.

    import aspects
    model = aspects.Model.from_file("robots/prrp.robot")   # or solve("robots/prrp.robot")
    result = aspects.solve(model, eps=0.1)
    result.summary["csncs"]["count"], result.lower_bound
    result.query([0.5]); result.path([0.2], [0.8]); result.plot("prrp.png")
    result.query(np.linspace(0, 1, 50).reshape(-1, 1)).count   # one row a pose

The computation is the command line's (`aspects solve`), in the compiled module
`aspects._aspects`; this package adds the progress display, the Result class and the
figures (aspects.plotting, shared with `aspects plot`).
"""
import os as _os

from ._aspects import (  # noqa: F401
    __version__, Model, ModelError, ResultError,
    SOLUTION, UNDECIDED_NO_EXISTENCE, UNDECIDED_SINGULAR, UNDECIDED_CONSTRAINT, UNEXPLORED,
)
from . import _aspects
from .progress import progress_callback as _progress_callback
from .answers import (  # noqa: F401
    Command, CountRegion, CountResult, OpenPlace, PathResult, PiecePathResult, QueryBatch,
    QueryResult, Waypoint,
)
from .count_pieces import CountPieces
from .result import Result, _pose as _pose_list

__all__ = ["Model", "ModelError", "ResultError", "Result", "Interrupted", "solve", "load",
           "count", "piece_path", "load_count", "CountPieces", "CountResult", "CountRegion", "OpenPlace", "QueryResult",
           "QueryBatch", "Command", "PathResult", "PiecePathResult", "Waypoint", "__version__"]


class Interrupted(KeyboardInterrupt):
    """Raised by solve() after Ctrl-C, once the run has returned: `.result` is the Result
    it made (result.complete is False when the interrupt cut the search or a later phase;
    every claim holds either way). A KeyboardInterrupt, so a script that does not catch it
    stops as on any Ctrl-C:

        try:
            r = aspects.solve(model, eps=0.01)
        except aspects.Interrupted as e:
            r = e.result
    """

    def __init__(self, result):
        super().__init__("aspects.solve: interrupted (Ctrl-C); the result so far is this "
                         "exception's .result (result.complete: %s; every claim holds)"
                         % result.complete)
        self.result = result


def _number(name, value, kind=float):
    if isinstance(value, bool) or not isinstance(value, (int, float) if kind is float else int):
        raise TypeError(f"{name} must be {'a number' if kind is float else 'an integer'}, "
                        f"got {type(value).__name__}")
    return kind(value)


def _model_of(model):
    """An aspects.Model, or the path of a .robot file read as Model.from_file reads it."""
    if isinstance(model, (str, _os.PathLike)):
        model = Model.from_file(_os.fspath(model))
    if not isinstance(model, Model):
        raise TypeError(f"model must be an aspects.Model or the path of a .robot file, got "
                        f"{type(model).__name__}")
    return model


def _eps(eps):
    eps = _number("eps", eps)
    if not (eps > 0 and eps < float("inf")):
        raise ValueError(f"eps must be a positive number, got {eps}")
    return eps


def _threads(threads):
    threads = _number("threads", threads, int)
    if not 0 <= threads <= 1024:
        raise ValueError(f"threads must be between 0 (one per core) and 1024, got {threads}")
    return threads


def _time_limit(time_limit):
    """-1.0 for none (the compiled module's convention), else positive seconds."""
    time_limit = -1.0 if time_limit is None else _number("time_limit", time_limit)
    if time_limit != -1.0 and not time_limit > 0:
        raise ValueError(f"time_limit must be a positive number of seconds, got {time_limit}")
    return time_limit


def solve(model, eps=0.1, threads=0, time_limit=None, out=None, progress=None, *,
          max_boxes=None, prec=53, tau=1.01, all_links=False, bisect=None, certificate=True,
          compress_certificate=False, mpfi_only=False):
    """Solve `model` as `aspects solve` does; returns a Result. `model`: an aspects.Model,
    or the path of a .robot file (str or os.PathLike; read as Model.from_file reads it).

    threads: 0 is one per core (the result does not depend on it). time_limit (seconds)
    and max_boxes stop the search early: the result is then partial (result.complete is
    False) and every claim still holds. Ctrl-C stops the search within a second, and the
    links, CSNCs, bound and witnesses are finished on the boxes it made (a second Ctrl-C
    stops them too); then aspects.Interrupted, a KeyboardInterrupt, is raised with the
    result as its `.result`. out: a directory, written
    as `aspects solve --out` writes it (summary.json, boxes.csv, aspects.cert,
    aspects.idx; certificate=False leaves out the certificate): the files of a run written
    there before are removed first, and the directory is locked while the run writes it
    (ValueError at once when another run holds it). progress: None (quiet),
    True (tqdm when installed, else a line on stderr now and then), or a callable given a
    dict (processed, solutions, undecided, decided share, seconds, phases) about every
    0.1 s; an exception it raises stops the run and is raised here. mpfi_only: every
    operation MPFI's, as `aspects solve --mpfi-only` (the same result, slower); it is this
    run's alone, also when other solves run at once in the process.
    """
    model = _model_of(model)
    eps = _eps(eps)
    threads = _threads(threads)
    time_limit = _time_limit(time_limit)
    max_boxes = -1 if max_boxes is None else _number("max_boxes", max_boxes, int)
    if max_boxes != -1 and max_boxes < 1:
        raise ValueError(f"max_boxes must be at least 1, got {max_boxes}")
    if bisect is not None and not isinstance(bisect, str):
        raise TypeError("bisect must be a string")
    out = "" if out is None else _os.fspath(out)
    callback, finish = _progress_callback(progress)
    try:
        core, interrupted = _aspects._solve(
            model, eps, threads, time_limit, max_boxes, _number("prec", prec, int),
            _number("tau", tau), bool(all_links), bisect or "", out, bool(certificate),
            bool(compress_certificate), bool(mpfi_only), callback)
    finally:
        finish()
    result = Result(core)
    if interrupted:
        raise Interrupted(result)
    return result


def count(model, eps=0.5, threads=0, time_limit=None, *, min_width=1e-9, rounds=200,
          out=None):
    """The certified number of aspects of `model`, as `aspects count` computes it; returns a
    CountResult (its .count is the number when lower = upper is certified, else None, and
    .lower/.upper the certified bounds). `model`: an aspects.Model or a .robot path.

    eps: the first cover's (the refinement after it is adaptive). min_width: boxes narrower
    than this fraction of the domain are not bisected. rounds: the refinement's round
    budget. time_limit (seconds) and Ctrl-C stop the refinement: the bounds reached are
    returned (they hold; .interrupted says Ctrl-C). ValueError for a model the count
    refuses (`factor` or `constraint` statements).

    out: a directory, made if missing, where the count writes count.pieces and
    summary.json as `aspects count --out` does, for aspects.piece_path (ValueError for a
    file, or a solve's result directory).
    """
    model = _model_of(model)
    eps = _eps(eps)
    min_width = _number("min_width", min_width)
    if not 0 < min_width < 1:
        raise ValueError(f"min_width must be in (0, 1), got {min_width}")
    rounds = _number("rounds", rounds, int)
    if not 1 <= rounds <= 1000000:
        raise ValueError(f"rounds must be between 1 and 1000000, got {rounds}")
    threads = _threads(threads)
    time_limit = _time_limit(time_limit)
    out = "" if out is None else _os.fspath(out)
    data, line, interrupted = _aspects._count(model, eps, min_width, rounds, time_limit,
                                              threads, out)
    return CountResult.from_dict(data, line, interrupted)


def piece_path(directory, start, goal, cls=None):
    """A certified singularity-free path through the pieces of a count, between two poses
    of one aspect whatever CSNCs they lie in, as `aspects path DIRECTORY --from START --to
    GOAL [--class CLS]` plans it (docs/path.md, "Through the pieces of a count"); returns a
    PiecePathResult. `directory`: what count(out=...) or `aspects count --out` wrote. `cls`:
    the sign class to stay in ('+-', one sign per factor), or None for any. ValueError for
    a bad pose or class, ResultError for a directory that is not a count's."""
    directory = _os.fspath(directory)
    if cls is not None and not isinstance(cls, str):
        raise TypeError("cls must be a string of signs, such as '+-', or None")
    data, line = _aspects._piece_path(directory, _pose_list(start, "start"),
                                      _pose_list(goal, "goal"), cls or "")
    return PiecePathResult.from_dict(data, line)


def load_count(directory):
    """The pieces of a count directory (what count(out=...) or `aspects count --out` wrote):
    a CountPieces, whose aspects() labels each piece with its component of the joins (the
    aspects when the count is exact) and figure() draws them. ResultError when it is not
    one."""
    directory = _os.fspath(directory)
    return CountPieces.from_arrays(_aspects._count_pieces(directory), directory)


def load(directory):
    """The result that `aspects solve --out DIRECTORY` (or solve(out=...)) wrote, read
    from its aspects.idx (boxes.csv is not read). ResultError when it is not one."""
    directory = _os.fspath(directory)
    if not _os.path.isdir(directory):
        raise ResultError(f"{directory}: not a directory (give what `aspects solve --out` wrote)")
    return Result(_aspects._load(directory))
