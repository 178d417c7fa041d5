#!/usr/bin/python3
"""gen_corpus.py — writes the golden corpus of check_cert (valid/, invalid/, malformed/).

Certificates are built independently of the solver: the LINE ones are spelled out record by
record; the PRRP-like circle and a periodic SINE model come from a tiny branch-and-prune for
one pose and one command written here with plain float intervals widened by one ulp per
operation. None of that needs to be rigorous: check_cert re-verifies every claim, and the
corpus test fails if a generated valid certificate is not accepted.

Usage: /usr/bin/python3 gen_corpus.py [TESTS_DIR]   (default: the directory of this file)
"""
import hashlib
import math
import os
import sys


def hx(v):
    """A double as C's printf("%a") prints it (float.hex keeps trailing zeros)."""
    v = float(v)
    if v == 0:
        return "-0x0p+0" if math.copysign(1, v) < 0 else "0x0p+0"
    mant, exp = float.hex(v).split("p")
    if "." in mant:
        mant = mant.rstrip("0").rstrip(".")
    return mant + "p" + exp


def dn(x):
    return math.nextafter(x, -math.inf)


def up(x):
    return math.nextafter(x, math.inf)


class I:
    """Float interval, each result widened by one ulp each way (good enough for hints)."""

    def __init__(self, lo, hi=None):
        self.lo, self.hi = lo, lo if hi is None else hi

    @staticmethod
    def of(x):
        return x if isinstance(x, I) else I(float(x))

    def __add__(a, b):
        b = I.of(b)
        return I(dn(a.lo + b.lo), up(a.hi + b.hi))

    __radd__ = __add__

    def __sub__(a, b):
        b = I.of(b)
        return I(dn(a.lo - b.hi), up(a.hi - b.lo))

    def __rsub__(a, b):
        return I.of(b) - a

    def __neg__(a):
        return I(-a.hi, -a.lo)

    def __mul__(a, b):
        b = I.of(b)
        p = [a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi]
        return I(dn(min(p)), up(max(p)))

    __rmul__ = __mul__

    def __truediv__(a, b):
        b = I.of(b)
        assert not b.has0()
        return a * I(dn(1 / b.hi), up(1 / b.lo))

    def sqr(a):
        if a.has0():
            return I(0.0, up(max(a.lo * a.lo, a.hi * a.hi)))
        m, M = sorted([abs(a.lo), abs(a.hi)])
        return I(dn(m * m), up(M * M))

    def has0(a):
        return a.lo <= 0 <= a.hi

    def mid(a):
        return a.lo + 0.5 * (a.hi - a.lo)

    def width(a):
        return a.hi - a.lo

    def inside(a, b):  # a strictly inside b
        return b.lo < a.lo and a.hi < b.hi


def isin(a, shift=0.0):
    """sin over an interval: end values, plus ±1 where an extremum lies inside."""
    if a.width() >= 6.3:
        return I(-1.0, 1.0)
    lo, hi = min(math.sin(a.lo), math.sin(a.hi)), max(math.sin(a.lo), math.sin(a.hi))
    k0 = math.floor((a.lo - shift - math.pi / 2) / math.pi) - 1
    for k in range(k0, k0 + 5):
        t = shift + math.pi / 2 + k * math.pi
        if a.lo - 1e-9 <= t <= a.hi + 1e-9:
            if k % 2 == 0:
                hi = 1.0
            else:
                lo = -1.0
    return I(max(-1.0, lo - 1e-15), min(1.0, hi + 1e-15))


def icos(a):
    return isin(a + math.pi / 2)


PI_UP = up(math.pi)  # math.pi is the double just below π

MODELS = {
    "line": dict(
        text="robot LINE\npose x in [0, 1]\ncommand q in [0, 1]\nequation x - q = 0\n",
        domain=[(0.0, 1.0), (0.0, 1.0)], periodic=[False, False],
        f=lambda x, q: x - q, fx=lambda x, q: I(1.0), fq=lambda x, q: I(-1.0)),
    # Constraints (FORMAT.md, "Constraints"): the feasible solutions are 1/4 < x <= 7/8. The
    # first constraint exercises and/or, both readings of a parenthesised group and a
    # statement continued over a newline inside parentheses.
    "line_c": dict(
        text=("robot LINE-C\npose x in [0, 1]\ncommand q in [0, 1]\nequation x - q = 0\n"
              "constraint ((q + 1) > 1.25 and x >= 0.25) or (x < -1 or\n  q <= -1)\n"
              "constraint x <= 0.875\n"),
        domain=[(0.0, 1.0), (0.0, 1.0)], periodic=[False, False]),
    "circle": dict(
        text=("# PRRP-like circle: (x - a)^2 + (q - b)^2 = l^2\nrobot PRRP\nconstant a = 0\n"
              "constant b = 0\nconstant l = 1\npose    x in [-2, 2]\ncommand q in [-2, 2]\n"
              "equation (x - a)^2 + (q - b)^2 = l^2\n"),
        domain=[(-2.0, 2.0), (-2.0, 2.0)], periodic=[False, False],
        f=lambda x, q: x.sqr() + q.sqr() - 1.0, fx=lambda x, q: 2.0 * x, fq=lambda x, q: 2.0 * q),
    "sine": dict(
        text=("# x = sin(q): the aspect with cos(q) < 0 crosses the seam q = +-pi\nrobot SINE\n"
              "pose x in [-2, 2]\ncommand q in [-pi, pi] periodic\nequation x - sin(q) = 0\n"),
        domain=[(-2.0, 2.0), (-PI_UP, PI_UP)], periodic=[False, True],
        f=lambda x, q: x - isin(q), fx=lambda x, q: I(1.0), fq=lambda x, q: -icos(q)),
}


def header(model, factors, eps=0.25):
    t = model["text"].encode()
    out = ["aspects-certificate 1", "tool aspects gen_corpus",
           "model %d %s" % (len(t), hashlib.sha256(t).hexdigest())]
    out.append(model["text"] + "\nend-model")  # BYTES of text, then one '\n', then end-model
    out += ["precision 53", "tau " + hx(1.01), "eps " + hx(eps),
            "domain " + " ".join(hx(lo) + " " + hx(hi) for lo, hi in model["domain"]),
            "factors %d" % len(factors)] + ["factor " + f for f in factors]
    return out


def finish(lines):
    lines.append("end %d" % (sum(l.count("\n") + 1 for l in lines)))
    return "\n".join(lines) + "\n"


class Solver:
    """Branch and prune for n = 1 (variable 0 = pose x, 1 = command q)."""

    def __init__(self, model, eps, tau=1.5):
        self.m, self.eps, self.tau = model, eps, tau
        self.recs, self.boxes = [], []  # boxes: (lo/hi list, is_solution, signs)

    def hs_q(self, X, Q):
        """Hansen–Sengupta image of Q (x in X) with the n = 1 formulas of FORMAT.md."""
        J = self.m["fq"](X, Q)
        if J.has0():
            return None, None
        C = 1.0 / J.mid()
        qc = Q.mid()
        b = C * self.m["f"](X, I(qc))
        return I(qc) - b / (C * J), C

    def prune(self, cell):
        """HS contraction of q and of x (the other as a parameter); None: no solution."""
        X, Q = cell
        for _ in range(10):
            y, _ = self.hs_q(X, Q)
            if y is not None:
                if y.hi < Q.lo or y.lo > Q.hi:
                    return None
                Q = I(max(Q.lo, y.lo), min(Q.hi, y.hi))
            J = self.m["fx"](X, Q)
            if not J.has0():
                xc = X.mid()
                yx = I(xc) - self.m["f"](I(xc), Q) / J
                if yx.hi < X.lo or yx.lo > X.hi:
                    return None
                X = I(max(X.lo, yx.lo), min(X.hi, yx.hi))
            if self.m["f"](X, Q).lo > 0 or self.m["f"](X, Q).hi < 0:
                return None
        return X, Q

    def prove(self, cell):
        X, Q = cell
        m = Q.mid()
        Qt = I(dn(m - self.tau * (m - Q.lo)) - 1e-12, up(m + self.tau * (Q.hi - m)) + 1e-12)
        y, C = self.hs_q(X, Qt)
        if y is None or not y.inside(Qt):
            return None
        slack = 1e-7 * y.width() + 1e-300  # so that slightly perturbed hints still prove it
        img = I(dn(y.lo - slack), up(y.hi + slack))
        if not img.inside(Qt):
            return None
        dlo, dhi = self.m["domain"][1]
        if not self.m["periodic"][1] and (img.lo < dlo or img.hi > dhi):
            return None
        fx, fq = self.m["fx"](X, img), self.m["fq"](X, img)
        if fx.has0() or fq.has0():
            return None
        return Qt, img, C, 1.0 / fx.mid(), 1.0 / fq.mid(), fx, fq

    def node(self, cell, depth):
        X, Q = cell
        pr = self.prune(cell)
        if pr is None:
            self.recs.append("X hs")
            return
        gap = 1e-9
        for v, (old, new) in enumerate(zip(cell, pr)):
            lo = max(old.lo, new.lo - gap) if new.lo > old.lo else old.lo
            hi = min(old.hi, new.hi + gap) if new.hi < old.hi else old.hi
            if lo > old.lo or hi < old.hi:
                self.recs.append("P %d %s %s" % (v, hx(lo), hx(hi)))
                cell = (I(lo, hi), cell[1]) if v == 0 else (cell[0], I(lo, hi))
        X, Q = cell
        proof = self.prove(cell)
        if proof:
            Qt, img, C, cx, cq, fx, fq = proof
            signs = ("+" if fx.lo > 0 else "-") + ("+" if fq.lo > 0 else "-")
            self.recs.append("S %d %s %s %s %s %s %s %s %s" % (
                len(self.boxes), signs, hx(Qt.lo), hx(Qt.hi), hx(img.lo), hx(img.hi),
                hx(C), hx(cx), hx(cq)))
            self.boxes.append(([X.lo, X.hi, img.lo, img.hi], True, signs))
            return
        v = 0 if X.width() >= Q.width() else 1
        if cell[v].width() <= self.eps:
            self.recs.append("U %d 00" % len(self.boxes))
            self.boxes.append(([X.lo, X.hi, Q.lo, Q.hi], False, "00"))
            return
        at = cell[v].mid()
        self.recs.append("B %d %s" % (v, hx(at)))
        left = (I(X.lo, at), Q) if v == 0 else (X, I(Q.lo, at))
        right = (I(at, X.hi), Q) if v == 0 else (X, I(at, Q.hi))
        self.node(left, depth + 1)
        self.node(right, depth + 1)

    def shifted(self, b, k):
        lo, hi = b[2] + 2 * math.pi * k, b[3] + 2 * math.pi * k
        return lo, hi

    def links(self):
        """Pairs of solution boxes with a link provable at the middle of their intersection."""
        out = []
        ks = [-1, 0, 1] if self.m["periodic"][1] else [0]
        for a in range(len(self.boxes)):
            for b in range(a + 1, len(self.boxes)):
                A, B = self.boxes[a], self.boxes[b]
                if not (A[1] and B[1]):
                    continue
                for k in ks:
                    blo, bhi = self.shifted(B[0], k)
                    blo, bhi = up(up(blo)), dn(dn(bhi))  # inward, below MPFI's rounding
                    xl, xh = max(A[0][0], B[0][0]), min(A[0][1], B[0][1])
                    ql, qh = max(A[0][2], blo), min(A[0][3], bhi)
                    if xl > xh or ql >= qh:
                        continue
                    w = xl + 0.5 * (xh - xl)
                    Qt = I(ql - (qh - ql), qh + (qh - ql))
                    y, C = self.hs_q(I(w), Qt)
                    if y is None or not y.inside(Qt) or y.lo < ql or y.hi > qh:
                        continue
                    shift = "0" + {-1: "-", 0: "0", 1: "+"}[k]
                    out.append((a, b, "K %d %d %s %s %s %s %s" % (a, b, shift, hx(w), hx(Qt.lo), hx(Qt.hi), hx(C))))
                    break
        return out

    def lower_bound(self):
        """Bound (11) with factors (detFx, detFq), naive O(N²) neighbourhood graph."""
        N = len(self.boxes)
        ks = [-1, 0, 1] if self.m["periodic"][1] else [0]
        edges = []
        for a in range(N):
            for b in range(N):
                if a == b:
                    continue
                A, B = self.boxes[a][0], self.boxes[b][0]
                for k in ks:
                    blo, bhi = self.shifted(B, k)
                    if A[0] <= B[1] and B[0] <= A[1] and A[2] <= bhi + 1e-12 and blo - 1e-12 <= A[3]:
                        edges.append((a, b))
        total = 0
        for s in ["++", "+-", "-+", "--"]:
            comp = [i for i in range(N) if all(c == "0" or c == w for c, w in zip(self.boxes[i][2], s))]
            par = {i: i for i in comp}

            def find(i):
                while par[i] != i:
                    i = par[i]
                return i
            for a, b in edges:
                if a in par and b in par:
                    par[find(a)] = find(b)
            total += len({find(i) for i in comp if self.boxes[i][1] and self.boxes[i][2] == s})
        return total

    def certificate(self, eps):
        m = self.m
        self.node((I(*m["domain"][0]), I(*m["domain"][1])), 0)
        lines = header(m, ["detFx", "detFq"], eps)
        lines += ["tree"] + self.recs + ["end-tree %d" % len(self.boxes)]
        links = self.links()
        lines += ["links %d" % len(links)] + [l[2] for l in links]
        par = list(range(len(self.boxes)))

        def find(i):
            while par[i] != i:
                i = par[i]
            return i
        for a, b, _ in links:
            par[find(a)] = find(b)
        comps = {}
        for i, b in enumerate(self.boxes):
            if b[1]:
                comps.setdefault(find(i), []).append(i)
        comps = sorted(comps.values(), key=lambda c: (-len(c), c[0]))
        lines += ["csncs %d" % len(comps)]
        lines += ["csnc %d %d %s" % (k, len(c), " ".join(map(str, c))) for k, c in enumerate(comps)]
        sizes = [len(c) for c in comps]
        ratios = [sizes[i] / sizes[i + 1] for i in range(len(sizes) - 1)]
        filt = len(sizes)
        if ratios and max(ratios) >= 2:
            filt = ratios.index(max(ratios)) + 1
        lines += ["claim filtered %d" % filt, "claim lower-bound %d" % self.lower_bound()]
        return finish(lines)


def line_certs():
    """LINE certificates written record by record."""
    m = MODELS["line"]
    single = header(m, ["detFx", "detFq"]) + [
        "tree",
        "S 0 +- %s %s %s %s %s %s %s" % (hx(-0.0625), hx(1.0625), hx(0.0), hx(1.0), hx(-1.0), hx(1.0), hx(-1.0)),
        "end-tree 1", "links 0", "csncs 1", "csnc 0 1 0", "claim filtered 1", "claim lower-bound 1"]
    split = header(m, ["detFx", "detFq"]) + [
        "tree", "B 0 " + hx(0.5),
        "P 1 %s %s" % (hx(0.0), hx(0.5625)),
        "S 0 +- %s %s %s %s %s %s %s" % (hx(-0.0625), hx(0.625), hx(0.0), hx(0.5), hx(-1.0), hx(1.0), hx(-1.0)),
        "B 1 " + hx(0.25),
        "X eq0",
        "P 1 %s %s" % (hx(0.4375), hx(1.0)),
        "S 1 +- %s %s %s %s %s %s %s" % (hx(0.4375), hx(1.0625), hx(0.5), hx(1.0), hx(-1.0), hx(1.0), hx(-1.0)),
        "end-tree 2",
        "links 1", "K 0 1 00 %s %s %s %s" % (hx(0.5), hx(0.25), hx(0.75), hx(-1.0)),
        "csncs 1", "csnc 0 2 0 1", "claim filtered 1", "claim lower-bound 1"]
    undecided = header(m, []) + [
        "tree", "B 0 " + hx(0.5), "U 0 .",
        "S 1 . %s %s %s %s %s %s %s" % (hx(-0.0625), hx(1.0625), hx(0.5), hx(1.0), hx(-1.0), hx(1.0), hx(-1.0)),
        "end-tree 2", "links 0", "csncs 1", "csnc 0 1 1", "claim filtered 1", "claim lower-bound 1"]
    return {"line_single": finish(single), "line_split": finish(split), "line_undecided": finish(undecided)}


def constrained_certs():
    """LINE-C written record by record: a discard and a slab refuted by a constraint (the
    first only after HC4 narrows q), undecided boxes on both constraint boundaries, and a
    solution box that passes the inner test."""
    m = MODELS["line_c"]
    recs = header(m, ["detFx", "detFq"]) + [
        "tree", "B 0 " + hx(0.25),
        "P 1 %s %s" % (hx(0.0), hx(0.28125)),  # x <= 1/4: the slab q >= 0.28125 has x != q
        "X c0",  # x = q <= 1/4: (q + 1) > 1.25 is false once HC4 has narrowed q to [0, 1/4]
        "B 0 " + hx(0.3125),
        "U 0 00",  # 1/4 <= x <= 5/16: on the boundary of constraint 0
        "P 0 %s %s" % (hx(0.3125), hx(0.9375)),  # x >= 15/16: constraint 1 is false
        "P 1 %s %s" % (hx(0.296875), hx(0.96875)),
        "B 0 " + hx(0.875),
        "S 1 +- %s %s %s %s %s %s %s" % (hx(0.25), hx(1.0), hx(0.3125), hx(0.875), hx(-1.0), hx(1.0), hx(-1.0)),
        "U 2 00",  # 7/8 <= x <= 15/16: on the boundary of constraint 1
        "end-tree 3", "links 0", "csncs 1", "csnc 0 1 1", "claim filtered 1", "claim lower-bound 1"]
    return finish(recs)


def many_periodic_cert(n=13):
    """2n periodic variables and one undecided root box: the neighbourhood graph must not
    enumerate the 3^(2n) shifts of a box spanning every period."""
    text = "robot MANY\n" + "".join("pose x%d in [-pi, pi] periodic\n" % i for i in range(n))
    text += "".join("command q%d in [-pi, pi] periodic\n" % i for i in range(n))
    text += "".join("equation sin(x%d) - sin(q%d) = 0\n" % (i, i) for i in range(n))
    m = dict(text=text, domain=[(-PI_UP, PI_UP)] * (2 * n))
    return finish(header(m, []) + ["tree", "U 0 .", "end-tree 1", "links 0", "csncs 0", "claim filtered 0",
                                   "claim lower-bound 0"])


def with_model(cert, old, new):
    """cert with `old` replaced by `new` in its embedded model, the model record rehashed."""
    text = MODELS["line_c"]["text"]
    assert old in text
    t2 = text.replace(old, new).encode()
    t1 = text.encode()
    out = cert.replace("model %d %s" % (len(t1), hashlib.sha256(t1).hexdigest()),
                       "model %d %s" % (len(t2), hashlib.sha256(t2).hexdigest()))
    return out.replace(text, t2.decode())


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    valid = line_certs()
    valid["circle"] = Solver(MODELS["circle"], 0.25).certificate(0.25)
    valid["sine"] = Solver(MODELS["sine"], 0.4).certificate(0.4)
    valid["line_constrained"] = constrained_certs()
    valid["many_periodic"] = many_periodic_cert()
    for d in ("valid", "invalid", "malformed"):
        os.makedirs(os.path.join(root, d), exist_ok=True)
    for name, text in valid.items():
        with open(os.path.join(root, "valid", name + ".cert"), "w") as f:
            f.write(text)
    # A few hand-picked broken variants of line_split; the tamper suite has many more.
    base = valid["line_split"]
    invalid = {
        "claim_too_high": base.replace("claim lower-bound 1", "claim lower-bound 2"),
        "image_too_narrow": base.replace("S 0 +- %s %s %s %s" % (hx(-0.0625), hx(0.625), hx(0.0), hx(0.5)),
                                         "S 0 +- %s %s %s %s" % (hx(-0.0625), hx(0.625), hx(0.0), hx(0.25))),
        "wrong_sign": base.replace("S 1 +-", "S 1 ++"),
        "slab_holds_solution": base.replace("P 1 %s %s" % (hx(0.0), hx(0.5625)), "P 1 %s %s" % (hx(0.125), hx(0.5625))),
        "discard_holds_solution": base.replace("B 1 " + hx(0.25), "B 1 " + hx(0.75)),
        "bisection_outside": base.replace("B 0 " + hx(0.5), "B 0 " + hx(1.5)),
    }
    lc = valid["line_constrained"]
    invalid.update({  # constraints: each breaks exactly one check of LINE-C
        "constraint_inner_test_fails": with_model(lc, "x <= 0.875", "x <= 0.75"),
        "constraint_discard_not_false": with_model(lc, "> 1.25", "> 1.125"),
        "constraint_slab_not_false": lc.replace("P 0 %s %s" % (hx(0.3125), hx(0.9375)),
                                                "P 0 %s %s" % (hx(0.3125), hx(0.875))),
        "constraint_model_changed_not_rehashed": lc.replace("x <= 0.875", "x <= 0.625"),
    })
    malformed = {
        "decimal_real": base.replace("B 0 " + hx(0.5), "B 0 0.5"),
        "double_space": base.replace("X eq0", "X  eq0"),
        "wrong_version": base.replace("aspects-certificate 1", "aspects-certificate 3"),
        "truncated": base[: len(base) // 2],
        "after_end": base + "garbage\n",
        "unknown_record": base.replace("X eq0", "Z eq0"),
        "hint_names_no_equation": base.replace("X eq0", "X eq1"),
        "constraint_constant_comparison": with_model(lc, "x <= 0.875", "1 <= 0.875"),
        "constraint_bare_periodic": with_model(lc, "q in [0, 1]\nequation x - q", "q in [0, 2*pi] periodic\nequation x - sin(q)"),
        "constraint_dangling_and": with_model(lc, "x <= 0.875", "x <= 0.875 and"),
        "constraint_bad_hint": lc.replace("X c0", "X c"),
    }
    for d, group in (("invalid", invalid), ("malformed", malformed)):
        for name, text in group.items():
            assert text not in (base, lc), name
            with open(os.path.join(root, d, name + ".cert"), "w") as f:
                f.write(text)


if __name__ == "__main__":
    main()
