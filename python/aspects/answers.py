"""The answers of Result.query and Result.path as small classes (frozen dataclasses).

Each is built from the JSON object `aspects query --json` or `aspects path --json` prints
(the same C++ code makes both), keeps it whole as .to_dict(), and reads as it did when
query and path returned that dict: answer["outcome"] still works. Keys the classes do not
name (a later version's) stay in .to_dict().
"""
import copy
from dataclasses import dataclass, field
from typing import Optional, Tuple

import numpy as np


def _tuple(values):
    return tuple(tuple(v) if isinstance(v, list) else v for v in (values or ()))


class _FromJson:
    """What every answer shares: the dict it was made from."""

    def to_dict(self):
        """The answer as `aspects query|path --json` prints it (a copy)."""
        return copy.deepcopy(self._data)

    def __getitem__(self, key):
        # query() and path() returned this dict before they returned classes.
        return self._data[key]


@dataclass(frozen=True)
class Command(_FromJson):
    """A certified command of a pose: the solution `box` holding it, its `csnc`, the
    command's enclosure [command_lo, command_hi] (command order, proved at the pose) and its
    `width`, the `signs` of the determinant factors, and the other boxes (`same_boxes`, in
    `same_csncs`) whose command at the pose is proved to be this one."""
    box: int
    csnc: int
    command_lo: Tuple[float, ...]
    command_hi: Tuple[float, ...]
    width: float
    signs: Tuple[int, ...]
    same_boxes: Tuple[int, ...]
    same_csncs: Tuple[int, ...]
    _data: dict = field(repr=False, compare=False)

    @classmethod
    def from_dict(cls, d):
        return cls(d["box"], d["csnc"], tuple(d["command_lo"]), tuple(d["command_hi"]),
                   d.get("width"), tuple(d.get("signs", ())), tuple(d.get("same_boxes", ())),
                   tuple(d.get("same_csncs", ())), d)


@dataclass(frozen=True)
class QueryResult(_FromJson):
    """The certified commands of one pose (README "What each command claims"). `outcome`:
    answered, not_proved, undecided_region, outside_workspace or membership_unknown;
    `answers`: the Commands, by CSNC; the boxes holding the pose without a proved command
    (`unproved_boxes`), the undecided ones (`undecided_boxes`), those whose membership was
    not decided; the pairs of answers neither proved one nor proved distinct."""
    pose: Tuple[float, ...]
    outcome: str
    answers: Tuple[Command, ...]
    unproved_boxes: Tuple[int, ...]
    undecided_boxes: Tuple[int, ...]
    membership_unknown_boxes: Tuple[int, ...]
    not_proved_distinct: Tuple[Tuple[int, int], ...]
    _data: dict = field(repr=False, compare=False)

    @classmethod
    def from_dict(cls, d):
        return cls(tuple(d["pose"]), d["outcome"],
                   tuple(Command.from_dict(a) for a in d.get("answers", ())),
                   tuple(d.get("unproved_boxes", ())), tuple(d.get("undecided_boxes", ())),
                   tuple(d.get("membership_unknown_boxes", ())),
                   _tuple(d.get("not_proved_distinct")), d)

    @property
    def csncs(self):
        """The CSNC of each answer."""
        return tuple(a.csnc for a in self.answers)


@dataclass(frozen=True)
class QueryBatch:
    """The answers for N poses (Result.query on an N x n array), as arrays: `outcome` (N,)
    strings, `count` (N,) certified commands of each pose, `csnc` (N, k) and
    `command_lo`/`command_hi` (N, k, m) for its k first commands, k the largest count
    (-1 and NaN past a pose's count). `results[i]` (or batch[i]) is row i's QueryResult."""
    poses: np.ndarray
    outcome: np.ndarray
    count: np.ndarray
    csnc: np.ndarray
    command_lo: np.ndarray
    command_hi: np.ndarray
    results: Tuple[QueryResult, ...] = field(repr=False)

    @classmethod
    def from_results(cls, poses, results, commands):
        n, k = len(results), max((len(r.answers) for r in results), default=0)
        csnc = np.full((n, k), -1, dtype=np.int32)
        lo = np.full((n, k, commands), np.nan)
        hi = np.full((n, k, commands), np.nan)
        for i, r in enumerate(results):
            for j, a in enumerate(r.answers):
                csnc[i, j] = a.csnc
                lo[i, j] = a.command_lo
                hi[i, j] = a.command_hi
        outcome = np.array([r.outcome for r in results], dtype=object)
        count = np.array([len(r.answers) for r in results], dtype=np.int32)
        for a in (poses, outcome, count, csnc, lo, hi):
            a.setflags(write=False)
        return cls(poses, outcome, count, csnc, lo, hi, tuple(results))

    def __len__(self):
        return len(self.results)

    def __getitem__(self, i):
        return self.results[i]

    def to_dict(self):
        """One dict a pose, as `aspects query --json` prints it."""
        return [r.to_dict() for r in self.results]


@dataclass(frozen=True)
class Waypoint(_FromJson):
    """A point of a path: its `kind` (start, corner, witness, goal), `pose`, the first solution
    `box` of the segment that follows (docs/path.md), the command's enclosure there, and the whole turns
    (`turns`, pose order) that unwrap a periodic pose variable along the path."""
    kind: str
    pose: Tuple[float, ...]
    box: int
    command_lo: Tuple[float, ...]
    command_hi: Tuple[float, ...]
    turns: Tuple[int, ...]
    _data: dict = field(repr=False, compare=False)

    @classmethod
    def from_dict(cls, d):
        return cls(d.get("kind"), tuple(d["pose"]), d.get("box"), tuple(d.get("command_lo", ())),
                   tuple(d.get("command_hi", ())), tuple(d.get("turns", ())), d)


@dataclass(frozen=True)
class PathResult(_FromJson):
    """A certified singularity-free path, or why there is none (`outcome`: found, or the
    reason). `start` and `goal` are the poses asked for, `csnc` the CSNC the path stays in
    (None: none), `waypoints` its Waypoints, `length` the sum of its segments (None when
    not found), `start_csncs` and `goal_csncs` the CSNCs holding each pose."""
    outcome: str
    csnc: Optional[int]
    start: Tuple[float, ...]
    goal: Tuple[float, ...]
    waypoints: Tuple[Waypoint, ...]
    length: Optional[float]
    start_csncs: Tuple[int, ...]
    goal_csncs: Tuple[int, ...]
    _data: dict = field(repr=False, compare=False)

    @classmethod
    def from_dict(cls, d):
        return cls(d["outcome"], d.get("csnc"), tuple(d["from"]), tuple(d["to"]),
                   tuple(Waypoint.from_dict(w) for w in d.get("waypoints", ())),
                   d.get("length"), tuple(d.get("start_csncs", ())),
                   tuple(d.get("goal_csncs", ())), d)

    @property
    def found(self):
        return self.outcome == "found"

    @property
    def poses(self):
        """The waypoints' poses, one row each (an array of shape (len(waypoints), n))."""
        n = len(self.start)
        return np.array([w.pose for w in self.waypoints], dtype=float).reshape(-1, n)


@dataclass(frozen=True)
class OpenPlace(_FromJson):
    """A place that holds the gap between a count's bounds: the `reason` (the test that
    failed there), the sign `cls` of its piece ('+-', one sign per factor) and its box
    [lo, hi] (model order)."""
    reason: str
    cls: str
    lo: Tuple[float, ...]
    hi: Tuple[float, ...]
    _data: dict = field(repr=False, compare=False)

    @classmethod
    def from_dict(cls, d):
        return cls(d["reason"], d["class"], tuple(d["lo"]), tuple(d["hi"]), d)


@dataclass(frozen=True)
class CountRegion(_FromJson):
    """A region of a count's lower bound (a component of its pieces that no refutation
    splits, holding a piece proved nonempty): one aspect when the count is exact, at least
    one otherwise. Its sign `cls`, the `boxes` holding its pieces (`connected_pieces` of them
    proved connected), their hull [lo, hi] (model order) and `pose_volume`, the total
    volume of their pose parts (a pose fixed by its domain left out): where it lies and an
    upper bound on its size."""
    cls: str
    boxes: int
    connected_pieces: int
    lo: Tuple[float, ...]
    hi: Tuple[float, ...]
    pose_volume: float
    _data: dict = field(repr=False, compare=False)

    @classmethod
    def from_dict(cls, d):
        return cls(d["class"], d["boxes"], d["connected_pieces"], tuple(d["lo"]),
                   tuple(d["hi"]), d["pose_volume"], d)


@dataclass(frozen=True)
class CountResult(_FromJson):
    """The certified count of aspects.count: `lower` and `upper` bounds (upper None when a
    piece is not proved connected), `exact` when they meet (then `count` is the number),
    `line` the sentence `aspects count` prints first, `stop` why the refinement ended,
    `open` the first places that hold the gap, `regions` the lower bound's regions
    (CountRegion, largest first: the aspects when the count is exact), and `interrupted`
    when Ctrl-C stopped it (the bounds still hold). .to_dict() is `aspects count --json`'s
    object."""
    lower: int
    upper: Optional[int]
    exact: bool
    line: str
    stop: str
    open: Tuple[OpenPlace, ...]
    regions: Tuple[CountRegion, ...]
    interrupted: bool
    _data: dict = field(repr=False, compare=False)

    @classmethod
    def from_dict(cls, d, line, interrupted=False):
        return cls(d["lower_bound"], d["upper_bound"], d["exact"], line, d["stop"],
                   tuple(OpenPlace.from_dict(o) for o in d.get("open", ())),
                   tuple(CountRegion.from_dict(r) for r in d.get("regions", ())),
                   bool(interrupted), d)

    @property
    def count(self):
        """The number of aspects when it is certified exactly (lower = upper), else None."""
        return self.lower if self.exact else None

    def __str__(self):
        return self.line


@dataclass(frozen=True)
class PiecePathResult(_FromJson):
    """A certified singularity-free path through the pieces of a count (aspects.piece_path),
    or why there is none: `outcome` (found, or the reason), `line` what `aspects path DIR`
    prints, `cls` the sign class it stays in (None when not found), `start_classes` and
    `goal_classes` the classes of the configurations proved for each pose, `pieces` crossed,
    and `waypoints` (dicts: kind start/centre/join/point/goal, box, config, lo, hi, turns).
    Each segment is straight in the u-coordinates of its box's chart (`segments`), not in
    pose space. .to_dict() is `aspects path DIR --json`'s object."""
    outcome: str
    line: str
    cls: Optional[str]
    start_classes: Tuple[str, ...]
    goal_classes: Tuple[str, ...]
    pieces: int
    waypoints: Tuple[dict, ...]
    segments: Tuple[dict, ...]
    _data: dict = field(repr=False, compare=False)

    @classmethod
    def from_dict(cls, d, line):
        return cls(d["outcome"], line, d.get("class"), tuple(d.get("start_classes", ())),
                   tuple(d.get("goal_classes", ())), d.get("pieces", 0),
                   tuple(d.get("waypoints", ())), tuple(d.get("segments", ())), d)

    @property
    def found(self):
        return self.outcome == "found"

    def __str__(self):
        return self.line
