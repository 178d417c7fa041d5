#!/usr/bin/python3
"""A robot of our own, from Python: an asymmetric five-bar (not one of robots/).

Base joints at (0, 0) and (6, 0), proximal links 4 and 3, distal links 5 and 5; the pose is
the end point (x, y), the commands the two actuated angles. Solves it, prints what is
certified, plots it, queries a pose, plans a certified path between two poses.

    PYTHONPATH=build/python /usr/bin/python3 examples/five_bar.py [OUTDIR]
"""
import os
import sys

import aspects

MODEL = """
robot five-bar-4-3
pose    x in [-12, 12]
pose    y in [-12, 12]
command q1 in [-pi, pi] periodic
command q2 in [-pi, pi] periodic
equation (x - 4*cos(q1))^2 + (y - 4*sin(q1))^2 = 25
equation (x - 6 - 3*cos(q2))^2 + (y - 3*sin(q2))^2 = 25
"""


def main(outdir):
    os.makedirs(outdir, exist_ok=True)
    model = aspects.Model.from_string(MODEL, "five_bar.robot")
    print(model)
    result = aspects.solve(model, eps=0.2, out=os.path.join(outdir, "result"), all_links=True)
    s = result.summary
    print(f"boxes: {s['boxes']['total']} ({s['boxes']['solution']} solution, "
          f"{s['boxes']['undecided']} undecided)")
    print(f"CSNCs: {len(result.csncs)}, filtered: {len(result.filtered_csncs)}")
    print(f"certified lower bound on the number of aspects: {result.lower_bound}")

    png = os.path.join(outdir, "five_bar.png")
    start, goal = (3.0, 4.0), (1.0, 6.0)
    path = result.path(start, goal)
    print(f"path {start} -> {goal}: {path['outcome']}, {len(path['waypoints'])} waypoints"
          f" in CSNC {path['csnc']}")
    result.plot(png, path=path)
    print(f"wrote {png}")

    answer = result.query(start)
    print(f"pose {start}: {answer['outcome']}, {len(answer['answers'])} certified commands")
    for a in answer["answers"]:
        print(f"  CSNC {a['csnc']}: q in {list(zip(a['command_lo'], a['command_hi']))}")

    verdict = result.check()
    print(f"check_cert: {verdict['verdict']}, lower bound {verdict['checked_lower_bound']}")
    return 0 if verdict["verdict"] == "VERIFIED" and path["outcome"] == "found" else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "five_bar_out"))
