#!/usr/bin/python3
"""count_certs.py — count certificates (FORMAT.md, "Count certificates") against check_cert.

Usage: count_certs.py CHECK_CERT ASPECTS ROBOTS_DIR MODELS_DIR WORKDIR

Acceptance: `aspects count --cert` on PRRP, RPRPR and the constructed models of
tests/test_exact_count.cpp (tests/models/count_*.robot) writes certificates that check_cert
verifies, by its trusted core alone too, with the bounds the count printed.
Tampering: each mutation of a real certificate states the exit code check_cert must give
(1 REJECTED, 2 MALFORMED) and a word of the reason; every mutation must change the file, so
the suite cannot silently shrink.
"""
import os
import re
import subprocess
import sys

CHECK, ASPECTS, ROBOTS, MODELS, WORK = sys.argv[1:6]
os.makedirs(WORK, exist_ok=True)
failures = []

# (name, model file, eps, the count's exact number of aspects)
CASES = [
    ("prrp", os.path.join(ROBOTS, "prrp.robot"), "0.5", 4),
    ("rprpr", os.path.join(ROBOTS, "rprpr.robot"), "0.5", 2),
    ("cubic", os.path.join(MODELS, "count_cubic.robot"), "0.5", 3),
    ("cubic_wide", os.path.join(MODELS, "count_cubic.robot"), "8", 3),
    ("thin", os.path.join(MODELS, "count_thin.robot"), "0.5", 3),
    ("parabola", os.path.join(MODELS, "count_parabola.robot"), "0.5", 2),
    ("bow_tie_neck", os.path.join(MODELS, "count_bow_tie_neck.robot"), "0.5", 3),
    ("bow_tie_pinch", os.path.join(MODELS, "count_bow_tie_pinch.robot"), "0.5", 3),
    ("seam", os.path.join(MODELS, "count_seam.robot"), "0.5", 2),
    ("circle_closed", os.path.join(MODELS, "count_circle_closed.robot"), "0.5", 2),
    ("circle_or", os.path.join(MODELS, "count_circle_or.robot"), "0.5", 3),
    ("circle_union", os.path.join(MODELS, "count_circle_union.robot"), "0.5", 3),
]


def check(path, *opts):
    p = subprocess.run([CHECK, "--quiet", *opts, path], capture_output=True, text=True)
    return p.returncode, (p.stdout + p.stderr).strip()


def fail(what):
    failures.append(what)
    print("FAIL: " + what)


certs = {}
for name, model, eps, count in CASES:
    cert = os.path.join(WORK, name + ".ccert")
    p = subprocess.run([ASPECTS, "count", model, "--eps", eps, "--cert", cert],
                       capture_output=True, text=True)
    first = p.stdout.split("\n")[0]
    if p.returncode != 0 or first != "%d aspects (certified: lower = upper)" % count:
        fail("%s: aspects count exited %d: %s" % (name, p.returncode, first))
        continue
    certs[name] = cert
    code, out = check(cert)
    want = "lower_bound=%d checked_lower_bound=%d " % (count, count)
    want_upper = " upper_bound=%d " % count
    if code != 0 or not out.startswith("check_cert: VERIFIED") or want not in out:
        fail("%s: check_cert exited %d: %s" % (name, code, out))
    elif want_upper not in out:
        fail("%s: upper bound not verified: %s" % (name, out))
    else:
        print("ok %s: %s" % (name, re.sub(r"sha256\S+ ", "", out)))
    code2, out2 = check(cert, "--trusted-only")
    if (code2, out2) != (code, out):
        fail("%s: --trusted-only says %s" % (name, out2))

# Two disjuncts' boundaries crossing on the curve: at least 3, no upper bound, verified.
corner = os.path.join(WORK, "circle_corner.ccert")
p = subprocess.run([ASPECTS, "count", os.path.join(MODELS, "count_circle_corner.robot"),
                    "--min-width", "1e-3", "--cert", corner], capture_output=True, text=True)
first_line = p.stdout.split("\n")[0]
code, out = check(corner)
if p.returncode != 0 or not first_line.startswith("at least 3 aspects (certified); no upper bound"):
    fail("circle_corner: aspects count exited %d: %s" % (p.returncode, first_line))
elif code != 0 or "checked_lower_bound=3 " not in out or " upper_bound=none " not in out:
    fail("circle_corner: check_cert exited %d: %s" % (code, out))
else:
    certs["circle_corner"] = corner
    print("ok circle_corner: %s" % re.sub(r"sha256\S+ ", "", out))


# ------------------------------------------------------------------ tampering


def records(path):
    with open(path) as f:
        text = f.read()
    lines = text.split("\n")
    assert lines[-1] == ""
    return lines[:-1]


def fix_end(lines):
    assert lines[-1].startswith("end ")
    lines[-1] = "end %d" % (len(lines) - 1)
    return lines


def first(lines, pred):
    for i, l in enumerate(lines):
        if pred(l.split(" ")):
            return i
    raise LookupError("no record to mutate")


def after_tree(lines):
    return lines.index([l for l in lines if l.startswith("end-tree ")][0])


def forged_upper(lines):
    i = first(lines, lambda f: f[:2] == ["claim", "count-upper"])
    lines[i] = "claim count-upper %d" % (int(lines[i].split(" ")[2]) - 1)
    return lines


def forged_lower(lines):
    i = first(lines, lambda f: f[:2] == ["claim", "count-lower"])
    lines[i] = "claim count-lower %d" % (int(lines[i].split(" ")[2]) + 1)
    return lines


def join_dropped(lines):
    # The claimed upper bound without one of the joins it rests on.
    del lines[first(lines, lambda f: f[0] == "joined")]
    return lines


def join_point_moved(lines):
    # A join whose point is another pair's: outside this pair's common part.
    joins = [i for i, l in enumerate(lines) if l.split(" ")[0] == "joined" and l.split(" ")[5] == "point"]
    a, b = joins[0], joins[-1]
    fa, fb = lines[a].split(" "), lines[b].split(" ")
    assert fa[6:] != fb[6:]
    lines[a] = " ".join(fa[:6] + fb[6:])
    return lines


def join_forged(lines):
    # A join between two pieces of one class that no join record connects: the bound would
    # drop, if the checker took the record's word.
    pieces = {}
    for l in lines:
        f = l.split(" ")
        if f[0] == "piece" and f[3] != "empty":
            pieces.setdefault(f[2], []).append(int(f[1]))
    have = set()
    for l in lines:
        f = l.split(" ")
        if f[0] in ("joined", "refuted"):
            have.add((int(f[1]), int(f[2])))
    donor = lines[first(lines, lambda f: f[0] == "joined" and f[5] == "point")].split(" ")
    ids = pieces[donor[3]]
    a, b = ids[0], ids[-1]
    assert a < b and (a, b) not in have
    lines.insert(first(lines, lambda f: f[0] == "claim"),
                 " ".join(["joined", str(a), str(b)] + donor[3:]))
    return lines


def join_unshifted(lines):
    # A join across the seam of a periodic variable claimed without its 2*pi shift.
    i = first(lines, lambda f: f[0] == "joined" and f[4].strip("0") != "")
    f = lines[i].split(" ")
    f[4] = "0" * len(f[4])
    lines[i] = " ".join(f)
    return lines


def star_centre_moved(lines):
    # A star-shaped piece's centre replaced by another piece's centre.
    stars = [i for i, l in enumerate(lines) if " connected star point " in l]
    a, b = stars[0], stars[-1]
    fa, fb = lines[a].split(" "), lines[b].split(" ")
    assert fa[6:] != fb[6:]
    lines[a] = " ".join(fa[:6] + fb[6:])
    return lines


def star_without_test(lines):
    # A piece the star test proved connected, now claimed connected as a whole graph.
    i = first(lines, lambda f: f[0] == "piece" and f[4] == "star")
    lines[i] = lines[i].replace(" connected star ", " connected graph ")
    return lines


def piece_dropped(lines):
    # The record of a connected piece removed: the upper bound loses its proof.
    del lines[first(lines, lambda f: f[0] == "piece" and f[3] == "connected")]
    return lines


def connected_called_empty(lines):
    i = first(lines, lambda f: f[0] == "piece" and f[3] == "connected")
    f = lines[i].split(" ")
    lines[i] = " ".join(f[:3] + ["empty", "signs"])
    return lines


def cell_removed(lines):
    # The last cell's records gone (the cover misses it).
    k = int(lines[first(lines, lambda f: f[0] == "count")].split(" ")[1]) - 1
    return [l for l in lines
            if not (l.split(" ")[0] in ("half", "fit", "void", "none", "piece")
                    and l.split(" ")[1] == str(k))]


def cell_discarded(lines):
    # The last cell's half claimed refuted in its parent's split, the cell gone, CELLS one less.
    i = first(lines, lambda f: f[0] == "count")
    f = lines[i].split(" ")
    k = int(f[1]) - 1
    lines[i] = " ".join(["count", str(k), f[2]])
    j = first(lines, lambda f: f[0] == "split" and str(k) in f[4:6])
    g = lines[j].split(" ")
    lines[j] = " ".join(g[:4] + ["-1" if x == str(k) else x for x in g[4:6]])
    out = []
    for l in lines:
        f = l.split(" ")
        if f[0] in ("half", "fit", "void", "none", "piece") and f[1] == str(k):
            continue
        if f[0] in ("joined", "refuted") and str(k) in f[1:3]:
            continue
        out.append(l)
    return out


def refutation_forged(lines):
    # A joined pair claimed refuted too.
    f = lines[first(lines, lambda f: f[0] == "joined")].split(" ")
    lines.insert(first(lines, lambda f: f[0] == "claim"), " ".join(["refuted"] + f[1:4]))
    return lines


def chart_box_grown(lines):
    # A fit whose box is wider than the chart shows it to be, in its first variable.
    i = first(lines, lambda f: f[0] == "fit")
    f = lines[i].split(" ")
    n = (len(lines[first(lines, lambda g: g[0] == "domain")].split(" ")) - 1) // 4
    k = 2 + 3 * n  # fit ID W(n) W~(2n) BOX
    f[k] = float.hex(float.fromhex(f[k]) - 0.5)
    lines[i] = " ".join(f)
    return lines


def fit_u_moved(lines, delta_of_width):
    # A fit whose box's u (the first variable not in W) has its lower end moved by
    # delta_of_width(width): above the origin's, or out of the root cell.
    i = first(lines, lambda f: f[0] == "fit")
    f = lines[i].split(" ")
    n = (len(lines[first(lines, lambda g: g[0] == "domain")].split(" ")) - 1) // 4
    w = {int(x) for x in f[2:2 + n]}
    v = min(x for x in range(2 * n) if x not in w)
    k = 2 + 3 * n + 2 * v  # fit ID W(n) W~(2n) BOX: BOX's lo of v
    lo, hi = float.fromhex(f[k]), float.fromhex(f[k + 1])
    f[k] = float.hex(lo + delta_of_width(hi - lo))
    lines[i] = " ".join(f)
    return lines


def fit_u_shrunk(lines):
    return fit_u_moved(lines, lambda width: 0.25 * width)


def fit_u_out_of_root(lines):
    return fit_u_moved(lines, lambda width: -1000.0)


def unsplit(lines):
    # A split undone: the box before it claimed final, its pieces claimed star-shaped about
    # the centres of one half's pieces. On cubic_wide that box holds both outer aspects of
    # one class: the star test must fail there.
    j = first(lines, lambda f: f[0] == "split")
    f = lines[j].split(" ")
    c, gone = f[1], {f[4], f[5]}
    donor = [l.split(" ") for l in lines if l.split(" ")[0] == "piece" and l.split(" ")[1] == f[4]]
    ids = sorted({int(l.split(" ")[1]) for l in lines
                  if l.split(" ")[0] in ("half", "fit", "void", "none", "split", "piece")} |
                 {int(x) for x in range(int(lines[first(lines, lambda g: g[0] == "count")].split(" ")[2]))})
    new = {}
    for x in ids:
        if str(x) not in gone:
            new[str(x)] = str(len(new))
    out = []
    for i, l in enumerate(lines):
        g = l.split(" ")
        if i == j:
            out += [" ".join(["piece", c] + d[2:]) for d in donor]
            continue
        if g[0] == "count":
            out.append(" ".join(["count", str(int(g[1]) - 2), g[2]]))
        elif g[0] in ("half", "fit", "void", "none", "piece", "split"):
            if g[1] in gone:
                continue
            g[1] = new[g[1]]
            if g[0] == "split":
                g[4:6] = [new.get(x, x) for x in g[4:6]]
            out.append(" ".join(g))
        elif g[0] in ("joined", "refuted"):
            if g[1] in gone or g[2] in gone:
                continue
            out.append(" ".join([g[0], new[g[1]], new[g[2]]] + g[3:]))
        else:
            out.append(l)
    return out


def hexpair(w):
    return "%s %s" % (float.hex(w - 1e-12), float.hex(w + 1e-12))


def disjunction_called_star(lines):
    # circle_corner: the piece left undecided where both disjuncts are Unknown, claimed
    # star-shaped about a feasible point of its box (x > 0.6 there): without the
    # disjunction's check the star test, blind to the constraint, passes.
    i = first(lines, lambda f: f[0] == "piece" and f[3] == "undecided")
    cid, cls = lines[i].split(" ")[1:3]
    fit = lines[first(lines, lambda f: f[:2] == ["fit", cid])].split(" ")
    w = int(fit[2])
    box = [float.fromhex(x) for x in fit[5:9]]
    ulo, uhi = box[2 * (1 - w)], box[2 * (1 - w) + 1]
    wlo, whi = box[2 * w], box[2 * w + 1]
    for k in range(1, 200):
        u = ulo + (uhi - ulo) * k / 200
        wv = (1 - u * u) ** 0.5
        x, q = (wv, u) if w == 0 else (u, wv)
        if wlo < wv < whi and (x > 0.6 + 1e-9 or q > 0.8 + 1e-9):
            lines[i] = "piece %s %s connected star point %d %s %s" % (cid, cls, w, float.hex(u), hexpair(wv))
            return lines
    raise LookupError("no feasible point in the box")


def centre_outside_c(lines):
    # circle_closed: a star piece of a box across x = 0.5 claimed nonempty by a point of the
    # circle in the box with x = 0.48, outside C (x >= 0.5); no upper bound claimed.
    for i, l in enumerate(lines):
        f = l.split(" ")
        if f[0] != "piece" or f[4] != "star":
            continue
        fit = lines[first(lines, lambda g: g[:2] == ["fit", f[1]])].split(" ")
        box = [float.fromhex(x) for x in fit[5:9]]
        if not box[0] < 0.48 < box[1] or f[6] != "1":
            continue
        q = (1 - 0.48 ** 2) ** 0.5 * (1 if f[2][1] == "+" else -1)
        if not box[2] < q < box[3]:
            continue
        lines[i] = "piece %s %s nonempty - point 1 %s %s" % (f[1], f[2], float.hex(0.48), hexpair(q))
        j = first(lines, lambda g: g[:2] == ["claim", "count-upper"])
        lines[j] = "claim count-upper none"
        return lines
    raise LookupError("no star piece across x = 0.5")


def feasible_called_empty(lines):
    # circle_closed: a connected piece claimed empty by a constraint (none is False on its box).
    i = first(lines, lambda f: f[0] == "piece" and f[3] == "connected")
    lines[i] = " ".join(lines[i].split(" ")[:3] + ["empty", "constraint"])
    return lines


# (certificate, mutation, word of the reason)
TAMPER = [
    ("prrp", forged_upper, "upper bound"),
    ("bow_tie_pinch", forged_upper, "upper bound"),
    ("prrp", forged_lower, "lower bound"),
    ("prrp", join_dropped, "below the recomputed"),
    ("prrp", join_point_moved, "joined"),
    ("cubic", join_forged, "joined"),
    ("seam", join_unshifted, "joined"),
    ("prrp", star_centre_moved, "point"),
    ("cubic_wide", unsplit, "star-shaped test fails"),
    ("prrp", star_without_test, "graph"),
    ("prrp", piece_dropped, "not proved connected"),
    ("prrp", connected_called_empty, "signs"),
    ("prrp", cell_removed, "never made"),
    ("prrp", cell_discarded, "discarded half"),
    ("bow_tie_pinch", refutation_forged, "refuted"),
    ("prrp", chart_box_grown, "chart"),
    ("prrp", fit_u_shrunk, "does not hold the origin's"),
    ("prrp", fit_u_out_of_root, "leaves the root cell"),
    ("circle_corner", disjunction_called_star, "star-shaped test fails"),
    ("circle_closed", centre_outside_c, "point"),
    ("circle_closed", feasible_called_empty, "empty by a constraint"),
]

for name, mutate, word in TAMPER:
    if name not in certs:
        fail("tamper %s on %s: no certificate" % (mutate.__name__, name))
        continue
    before = records(certs[name])
    after = fix_end(mutate(list(before)))
    if after == before:
        fail("tamper %s on %s: the mutation changed nothing" % (mutate.__name__, name))
        continue
    path = os.path.join(WORK, "%s-%s.ccert" % (name, mutate.__name__))
    with open(path, "w") as f:
        f.write("\n".join(after) + "\n")
    code, out = check(path)
    if code != 1 or not out.startswith("check_cert: REJECTED") or word not in out:
        fail("tamper %s on %s: exit %d, want 1 with '%s': %s" % (mutate.__name__, name, code, word, out))
    else:
        print("ok tamper %s on %s: %s" % (mutate.__name__, name, out))

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
