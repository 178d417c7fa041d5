#!/usr/bin/python3
"""Share of a robot's solution set covered by the kept CSNCs of a result directory, by
Monte Carlo: random poses, their commands by closed-form inverse kinematics (every
branch), and the share of those (pose, commands) points inside a kept solution box of
DIR/boxes.csv. Compares bisectors fairly: fewer boxes is a gain only at the same cover.

    bench/coverage.py [--samples N] DIR ...

Knows 3-RPR and RRRRR (robots/3rpr.robot, robots/rrrrr.robot; the robot is read from
DIR/summary.json). A sampling estimate, not a certified measure: its standard error is
about sqrt(p (1 - p) / points), printed with it."""
import argparse, csv, json, math, os
from collections import defaultdict

import numpy as np


def rpr_points(rng, n):
    x1, x2 = rng.uniform(-50, 50, n), rng.uniform(-50, 50, n)
    x3 = rng.uniform(-np.pi, np.pi, n)
    q1 = np.hypot(x1, x2)
    q2 = np.hypot(x1 + 17 * np.cos(x3) - 15.9, x2 + 17 * np.sin(x3))
    q3 = np.hypot(x1 + 20.8 * np.cos(x3 + 0.8822), x2 + 20.8 * np.sin(x3 + 0.8822) - 10)
    ok = np.all([(q >= 10) & (q <= 32) for q in (q1, q2, q3)], axis=0)  # lengths in [10, 32]
    return np.column_stack([x1, x2, x3, q1, q2, q3])[ok], [2]


def rrrrr_points(rng, n):
    x = rng.uniform(-20, 20, (n, 2))

    def angles(cx, link, distal):  # q with |x - c - link (cos q, sin q)| = distal
        d = x - np.array([cx, 0.0])
        r = np.hypot(d[:, 0], d[:, 1])
        c = (r ** 2 + link ** 2 - distal ** 2) / (2 * link * r)
        base, delta = np.arctan2(d[:, 1], d[:, 0]), np.arccos(np.clip(c, -1, 1))
        return np.abs(c) < 1, (base + delta, base - delta)

    wrap = lambda a: (a + np.pi) % (2 * np.pi) - np.pi
    ok1, b1 = angles(0, 8, 5)
    ok2, b2 = angles(9, 5, 8)
    m = ok1 & ok2
    pts = [np.column_stack([x[m], wrap(q1[m]), wrap(q2[m])]) for q1 in b1 for q2 in b2]
    return np.vstack(pts), [2, 3]


ROBOTS = {"3-RPR": rpr_points, "RRRRR": rrrrr_points}


def kept_boxes(path, nv):
    rows = []
    with open(path) as f:
        r = csv.reader(f)
        next(r)
        for row in r:
            if row[1] == "solution" and row[3] == "1":
                rows.append([float(v) for v in row[4:4 + 2 * nv]])
    b = np.array(rows).reshape(-1, 2 * nv)
    return b[:, 0::2], b[:, 1::2]


def covered(points, lo, hi, periodic, cell=1.0):
    # Boxes bucketed by unit cells of the first two pose coordinates.
    grid = defaultdict(list)
    c = lambda a: np.floor(a / cell).astype(int)
    for i, (a0, a1, b0, b1) in enumerate(zip(c(lo[:, 0]), c(hi[:, 0]), c(lo[:, 1]), c(hi[:, 1]))):
        for a in range(a0, a1 + 1):
            for b in range(b0, b1 + 1):
                grid[(a, b)].append(i)
    at = defaultdict(list)
    for j, key in enumerate(zip(c(points[:, 0]), c(points[:, 1]))):
        at[key].append(j)
    hit = 0
    for key, js in at.items():
        if key not in grid:
            continue
        idx, p = np.array(grid[key]), points[js]
        inside = np.ones((len(js), len(idx)), bool)
        for v in range(points.shape[1]):
            x, L, H = p[:, v][:, None], lo[idx, v], hi[idx, v]
            shifts = (0, 2 * np.pi, -2 * np.pi) if v in periodic else (0,)
            inside &= np.any([(x + s >= L) & (x + s <= H) for s in shifts], axis=0)
        hit += int(inside.any(1).sum())
    return hit


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--samples", type=int, default=200000)
    ap.add_argument("dirs", nargs="+")
    a = ap.parse_args()
    for d in a.dirs:
        robot = json.load(open(os.path.join(d, "summary.json")))["robot"]
        if robot not in ROBOTS:
            raise SystemExit(f"coverage.py: no inverse kinematics for robot {robot!r}")
        points, periodic = ROBOTS[robot](np.random.default_rng(1), a.samples)
        lo, hi = kept_boxes(os.path.join(d, "boxes.csv"), points.shape[1])
        p = covered(points, lo, hi, periodic) / len(points)
        se = math.sqrt(p * (1 - p) / len(points))
        print(f"{d}: {robot}, {len(lo)} kept solution boxes, {len(points)} points, "
              f"covered {100 * p:.2f} % (± {100 * se:.2f})")


if __name__ == "__main__":
    main()
