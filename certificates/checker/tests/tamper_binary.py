#!/usr/bin/python3
"""tamper_binary.py — mutation tests of check_cert on format 3's binary records.

Usage: tamper_binary.py CHECK_CERT ASPECTS ROBOTS_DIR WORKDIR

ASPECTS solves three small robots with --cert-format 3 (PRRP; RRRRR joint limit, with a
constraint; 3-RRR*, with periodic commands and the point variable x3 in [0, 0]). A reader
of format 3 (FORMAT.md, "Format 3: binary records") splits each certificate into records
with the byte offsets of every field, replays the search tree to decode every coded end,
and is tested first: its parse ends exactly at `end N` after N records, and every binary
record it decodes prints exactly as `check_cert --print` prints it.

Then, as in tamper.py, each mutation takes a valid certificate, changes its bytes, and
states the exit code check_cert must give: 1 (REJECTED) for a certificate that reads but
claims something false, 2 (MALFORMED) for one that breaks the format, 0 where every claim
is still true (a different coding of the same records); with a word of the message where
the reason matters, and the number of the record that must be blamed where it is known.
Every mutation must change the file and be applicable; the script fails otherwise, so the
suite cannot silently shrink. Last, a seeded loop of random single-byte flips and
truncations of binary records: check_cert must give 0, 1 or 2, never a signal or an
internal error, and a file it verifies must be one the reader (which refuses what
FORMAT.md calls malformed) reads.
"""
import math
import os
import random
import struct
import subprocess
import sys
import time
from fractions import Fraction

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_corpus import hx  # C's %a form of a double, as check_cert --print prints it

BASES = (("prrp", "0.1"), ("rrrrr_joint_limit", "0.3"), ("3rrr_star", "1"))
KINDS = ("X", "U", "N", "S", "K", "csnc")  # first bytes 0xC0..0xC5
G, G_P, MIDDLE = 16, 10, 1 << 15  # grid bits; P records' grid bits; B records' OFFSET
SAME = "same claims"  # expected word: the verdict line of the base, but for sha256(cert)


# ------------------------------------------------------------------ the reader

class Malformed(Exception):
    """What FORMAT.md calls malformed in a binary record, found by the reader."""


def read_varint(data, i):
    """(value, offset after it) of the unsigned LEB128 at i (at most 8 bytes, < 2^53)."""
    x = 0
    for k in range(8):
        b = data[i + k]
        x |= (b & 0x7F) << (7 * k)
        if not b & 0x80:
            if x >= 1 << 53:
                raise Malformed("integer of 2^53 or more at byte %d" % i)
            return x, i + k + 1
    raise Malformed("integer longer than 8 bytes at byte %d" % i)


def varint(x):
    out = bytearray()
    while x >= 0x80:
        out.append(0x80 | (x & 0x7F))
        x >>= 7
    out.append(x)
    return bytes(out)


def zigzag(c):
    """The z of a code c >= 1: 1, 2, 3, 4, ... are 0, -1, 1, -2, ..."""
    d = c - 1
    return d // 2 if d % 2 == 0 else -(d + 1) // 2


def code(z):
    """The bytes of a grid code z (c = 1 + zigzag)."""
    return varint(1 + (2 * z if z >= 0 else -2 * z - 1))


def raw(x):
    """The bytes of a raw coded end: c = 0, then the binary64 little-endian."""
    return b"\x00" + struct.pack("<d", x)


def raw_bits(bits):
    return b"\x00" + struct.pack("<Q", bits)


def grid_value(z, a, b, upper, offset=0, bits=G):
    """fma(z + OFFSET, u, R) rounded once, u = (b - a)·2^-bits, R = b for an upper end."""
    u = math.ldexp(b - a, -bits)
    r = b if upper else a
    k = float(z + offset)  # exact: |z| < 2^52
    if not math.isfinite(u) or not math.isfinite(r):
        return k * u + r  # 0·inf is NaN and inf + finite is inf, as in fma
    exact = Fraction(k) * Fraction(u) + Fraction(r)
    if exact == 0:
        return k * u + r  # the sign of an exact zero, as fma gives it
    try:
        return float(exact)  # integer true division: correctly rounded to nearest
    except OverflowError:
        return math.copysign(math.inf, exact)


def grid_near(x, a, b, upper, offset=0, bits=G):
    """(z, value): the grid point nearest to x for the reference [a, b]."""
    u = math.ldexp(b - a, -bits)
    z = round((x - (b if upper else a)) / u) - offset
    return z, grid_value(z, a, b, upper, offset, bits)


class End:
    """A coded end: bytes [start, stop), its code c (z when c >= 1), the offset of its 8
    raw bytes when c = 0, its reference and the value it decodes to."""

    def __init__(self, start, stop, c, z, raw_at, ref, upper, offset, bits, value):
        self.start, self.stop, self.c, self.z, self.raw_at = start, stop, c, z, raw_at
        self.ref, self.upper, self.offset, self.bits, self.value = ref, upper, offset, bits, value

    def near(self, x):
        """The bytes of the grid code nearest to x, and the value they decode to."""
        z, v = grid_near(x, self.ref[0], self.ref[1], self.upper, self.offset, self.bits)
        return code(z), v


class Rec:
    """One record: kind, bytes [start, stop), record number (as check_cert counts them).
    A text record has `line`; a binary one `ints` (each varint: start, stop, value),
    `packed` (start, stop, characters) and `ends` (End objects), in byte order."""

    def __init__(self, kind, start, number, binary):
        self.kind, self.start, self.number, self.binary = kind, start, number, binary
        self.stop = None
        self.line = None
        self.ints, self.packed, self.ends = [], None, []

    def text(self):
        """The record as version 2 text, as check_cert --print shows a binary one."""
        if not self.binary:
            return self.line
        e = [hx(x.value) for x in self.ends]
        if self.kind == "P":
            return "P %d %s %s" % (self.v, e[0], e[1])
        if self.kind == "B":
            return "B %d %s" % (self.v, e[0])
        if self.kind == "X":
            return "X " + self.hint
        if self.kind in "UNS":
            return " ".join([self.kind, str(self.id), self.chars] + e)
        if self.kind == "K":
            return " ".join(["K", str(self.a), str(self.b), self.chars] + e)
        return " ".join(["csnc", str(self.k), str(len(self.ids))] + [str(i) for i in self.ids])


class Cert:
    """A format 3 certificate read into records, the search tree replayed: every coded end
    decoded against the interval the checker holds when it reads it."""

    def __init__(self, data):
        self.data = data
        lines = data.split(b"\n", 3)
        assert lines[0] == b"aspects-certificate 3", lines[0]
        nbytes = int(lines[2].split()[1])
        model_at = len(lines[0]) + len(lines[1]) + len(lines[2]) + 3
        self.model = data[model_at:model_at + nbytes].decode()
        pos = model_at + nbytes
        assert data[pos:pos + 11] == b"\nend-model\n"
        pos += 11
        self.header = {}
        while True:  # precision, tau, eps, domain, factors, factor lines, up to `tree`
            stop = data.index(b"\n", pos) + 1
            f = data[pos:stop - 1].decode().split(" ")
            if f[0] == "tree":
                break
            self.header.setdefault(f[0], []).append(f[1:])
            pos = stop
        self.tree_at = pos
        self.root = [float.fromhex(x) for x in self.header["domain"][0]]
        self.nv = len(self.root) // 2
        self.p = int(self.header["factors"][0][0])
        # The variables in model order: `pose NAME in [LO, HI] [periodic]` and `command ...`.
        self.vars = []
        for line in self.model.split("\n"):
            f = line.split("#")[0].split()
            if f and f[0] in ("pose", "command"):
                self.vars.append((f[1], f[0] == "pose", "periodic" in f))
        self.pose = [v for v, x in enumerate(self.vars) if x[1]]
        self.command = [v for v, x in enumerate(self.vars) if not x[1]]
        self.n = len(self.command)
        assert len(self.vars) == self.nv == 2 * self.n and len(self.pose) == self.n
        self.periodic = [x[2] for x in self.vars]
        self.records = []
        self.boxes, self.solution = [], []  # output boxes in id order; S or not
        self._parse(data[:pos].count(b"\n") + 1)

    # -- records
    def _next(self, pos, number):
        if self.data[pos] >= 0x80:
            return self._binary(pos, number)
        r = Rec(None, pos, number, False)
        r.stop = self.data.index(b"\n", pos) + 1
        r.line = self.data[pos:r.stop - 1].decode()
        r.kind = r.line.split(" ")[0]
        return r

    def _binary(self, pos, number):
        d = self.data
        tag = d[pos]
        if tag > 0xC5:
            raise Malformed("unknown first byte %#x at byte %d" % (tag, pos))
        kind = "P" if tag < 0xA0 else "B" if tag < 0xC0 else KINDS[tag - 0xC0]
        r = Rec(kind, pos, number, True)
        r.tag = tag
        i = [pos + 1]

        def vint():
            v, j = read_varint(d, i[0])
            r.ints.append((i[0], j, v))
            i[0] = j
            return v

        def end(a, b, upper, offset=0, bits=G):
            start = i[0]
            c = vint()
            r.ints.pop()
            if c == 0:
                x = struct.unpack("<d", d[i[0]:i[0] + 8])[0]
                r.ends.append(End(start, i[0] + 8, 0, None, i[0], (a, b), upper, offset, bits, x))
                i[0] += 8
            else:
                z = zigzag(c)
                x = grid_value(z, a, b, upper, offset, bits)
                r.ends.append(End(start, i[0], c, z, None, (a, b), upper, offset, bits, x))
            if not math.isfinite(r.ends[-1].value):
                raise Malformed("an end that is not finite at byte %d" % start)
            return r.ends[-1].value

        def interval(lo, hi):
            if not lo <= hi:
                raise Malformed("an interval with LO > HI in record %d" % number)
            return lo, hi

        def packed(k):
            start = i[0]
            chars = ""
            for j in range(0, k, 4):
                b = d[i[0]]
                i[0] += 1
                chars += "".join("0+-?"[(b >> (2 * m)) & 3] for m in range(min(4, k - j)))
                if b >> (2 * min(4, k - j)):
                    raise Malformed("a bit set after the last character at byte %d" % (i[0] - 1))
            if "?" in chars:
                raise Malformed("a character of code 3 at byte %d" % start)
            r.packed = (start, i[0], chars)
            return chars or "."

        if kind in "PB":
            r.v = tag & 0x1F
            if r.v == 31:
                r.v += vint()
            cell = self.open_cell()
            r.cell = list(cell)
            a, b = cell[2 * r.v], cell[2 * r.v + 1]
            if kind == "P":
                cell[2 * r.v], cell[2 * r.v + 1] = interval(end(a, b, False, 0, G_P),
                                                            end(a, b, True, 0, G_P))
            else:
                x = end(a, b, False, MIDDLE)
                right = list(cell)
                right[2 * r.v] = x
                cell[2 * r.v + 1] = x
                self.stack += [right, cell]
                self.cell = None
        elif kind == "X":
            r.cell = list(self.open_cell())
            h = vint()
            r.hint = "hs" if h == 0 else "eq%d" % ((h - 1) // 2) if h % 2 else "c%d" % ((h - 2) // 2)
            self.cell = None
        elif kind in "UNS":
            cell = self.open_cell()
            r.cell = list(cell)
            r.id = len(self.boxes)
            r.chars = packed(self.p)
            box = list(cell)
            if kind == "S":
                n = self.n
                q = self.command
                Q = [x for j in range(n) for x in interval(
                    end(cell[2 * q[j]], cell[2 * q[j] + 1], False),
                    end(cell[2 * q[j]], cell[2 * q[j] + 1], True))]
                img = [x for j in range(n) for x in interval(end(Q[2 * j], Q[2 * j + 1], False),
                                                             end(Q[2 * j], Q[2 * j + 1], True))]
                r.Q, r.img = Q, img
                r.weights = [end(1.0, 2.0, False) for _ in range(2 * n)]
                for j in range(n):
                    box[2 * q[j]], box[2 * q[j] + 1] = img[2 * j], img[2 * j + 1]
            self.boxes.append(box)
            self.solution.append(kind == "S")
            r.box = box
            self.cell = None
        elif kind == "K":
            self.last_a += vint()
            r.a = self.last_a
            r.b = r.a + 1 + vint()
            r.chars = packed(self.nv)
            A = self.boxes[r.a]
            r.witness = [end(A[2 * v], A[2 * v + 1], False) for v in self.pose]
            r.Q = [x for v in self.command for x in interval(end(A[2 * v], A[2 * v + 1], False),
                                                             end(A[2 * v], A[2 * v + 1], True))]
        else:  # csnc
            r.k = vint()
            size = vint()
            r.ids = []
            for _ in range(size):
                r.ids.append((r.ids[-1] if r.ids else -1) + 1 + vint())
        r.stop = i[0]
        return r

    def open_cell(self):
        """The current cell: the top of the stack, popped at a node's first record."""
        if self.cell is None:
            self.cell = self.stack.pop()
        return self.cell

    def _parse(self, number):
        self.stack, self.cell, self.last_a = [list(self.root)], None, 0
        pos = self.tree_at
        while pos < len(self.data):
            r = self._next(pos, number)
            self.records.append(r)
            pos, number = r.stop, number + 1
            if r.kind == "end":
                break
        self.end = self.records[-1]
        assert self.end.kind == "end", "no `end` record"
        assert self.end.stop == len(self.data), "bytes after `end`"
        assert int(self.end.line.split()[1]) == self.end.number - 1, "`end N` miscounts"
        assert not self.stack and self.cell is None, "the tree leaves cells"
        assert self.one("end-tree").line == "end-tree %d" % len(self.boxes)

    # -- lookups
    def find(self, kind, pred=lambda r: True):
        return [r for r in self.records if r.kind == kind and pred(r)]

    def one(self, kind, pred=lambda r: True, k=0):
        found = self.find(kind, pred)
        if not found:
            raise AssertionError("no %s record with that property" % kind)
        return found[min(k, len(found) - 1)] if k >= 0 else found[k]

    def binary_records(self):
        return [r for r in self.records if r.binary]

    def meet(self, a, b, shift=None):
        """Boxes a and b (b shifted by 2π·k) meet, with a margin, on every variable."""
        A, B = self.boxes[a], self.boxes[b]
        k = shift or [0] * self.nv
        return all(A[2 * v] <= B[2 * v + 1] + 2 * math.pi * k[v] + 1e-9 and
                   B[2 * v] + 2 * math.pi * k[v] - 1e-9 <= A[2 * v + 1] for v in range(self.nv))


# ------------------------------------------------------------------ byte edits

def splice(data, *edits):
    """data with each (start, stop, bytes) edit applied (non-overlapping)."""
    out = bytearray(data)
    for start, stop, new in sorted(edits, key=lambda e: e[0], reverse=True):
        out[start:stop] = new
    return bytes(out)


def set_end(e, new):
    return (e.start, e.stop, new)


def set_int(r, k, value, nbytes=None):
    """Varint k of record r rewritten (padded to nbytes with continuation bits if given)."""
    start, stop, _ = r.ints[k]
    return (start, stop, padded(value, nbytes) if nbytes else varint(value))


def padded(value, nbytes):
    """value in LEB128 stretched to nbytes (continuation bits, high groups zero)."""
    out = bytearray()
    for k in range(nbytes):
        out.append((value >> (7 * k)) & 0x7F | (0x80 if k < nbytes - 1 else 0))
    return bytes(out)


def set_tag(r, tag):
    return (r.start, r.start + 1, bytes([tag]))


def set_packed(r, chars, extra=0, byte=0):
    """Packed field of r rewritten from chars ('0', '+', '-', or '?' for code 3); `extra`
    ORed into byte `byte` (stray bits)."""
    out = bytearray((len(chars) + 3) // 4)
    for j, ch in enumerate(chars):
        out[j // 4] |= "0+-?".index(ch) << (2 * (j % 4))
    out[byte] |= extra
    return (r.packed[0], r.packed[1], bytes(out))


def replace(r, new):
    return (r.start, r.stop, new)


def fix_end(c, data, delta):
    """data (with `delta` records more than c) with its `end N` line recounted."""
    return data[:len(data) - (c.end.stop - c.end.start)] + b"end %d\n" % (c.end.number - 1 + delta)


def all_raw(c, kinds=("P", "B", "S", "K")):
    """Every grid-coded end of the records of `kinds` written raw (c = 0 and the 8 bytes of
    the value it decoded to)."""
    return splice(c.data, *[set_end(e, raw(e.value)) for r in c.binary_records()
                            if r.kind in kinds for e in r.ends if e.c])


def as_text(kind):
    """The first record of `kind` written as the version 2 text line it stands for (S and
    K records with preconditioners 1: valid ones when n = 1, where any nonzero C proves
    P1, P2 and P3)."""
    def mutate(c):
        r = c.one(kind)
        assert kind not in ("S", "K") or c.n == 1
        f = r.text().split(" ")
        at = {"S": 3 + 4 * c.n, "K": len(f)}.get(kind, len(f))  # C (CX CQ) before DX DQ
        f[at:at] = ["0x1p+0"] * (c.n * c.n * {"S": 3, "K": 1}.get(kind, 0))
        return splice(c.data, replace(r, " ".join(f).encode() + b"\n")), r.number
    return mutate


# ------------------------------------------------------------------ mutations
# Each is (name, function of the parsed base Cert, expected): the function returns the new
# bytes, or (bytes, record number the message must name); expected is an exit code or
# (code, word of the message).

def s_after_p_on_command(c):
    """(P, S): a contraction of a command variable right before a solution leaf, the
    middle of the leaf's IMAGE on that command well inside the contraction."""
    recs = c.records
    for k in range(1, len(recs)):
        P, S = recs[k - 1], recs[k]
        if S.kind == "S" and P.kind == "P" and P.v in c.command:
            j = c.command.index(P.v)
            mid = 0.5 * (S.img[2 * j] + S.img[2 * j + 1])
            lo, hi = P.ends[0].value, P.ends[1].value
            if lo + 0.1 * (hi - lo) < mid < hi - 0.1 * (hi - lo):
                return P, S
    raise AssertionError("no P on a command right before an S record")


def contraction_inward(c, recode_leaf):
    """A P on command q right before an S: LO moved to the middle of the S record's IMAGE
    on q, so the slab below holds solutions. With `recode_leaf` the S record's ends are
    written raw, so that it keeps its values on the narrowed cell."""
    P, S = s_after_p_on_command(c)
    j = c.command.index(P.v)
    new, lo = P.ends[0].near(0.5 * (S.img[2 * j] + S.img[2 * j + 1]))
    assert P.ends[0].value < lo < P.ends[1].value
    edits = [set_end(P.ends[0], new)]
    if recode_leaf:
        edits += [set_end(e, raw(e.value)) for e in S.ends]
    return splice(c.data, *edits), P.number


def contraction_lo_above_hi(c):
    P = c.one("P", lambda r: r.ends[1].value < r.cell[2 * r.v + 1])
    return splice(c.data, set_end(P.ends[0], raw(math.nextafter(P.ends[1].value, math.inf)))), P.number


def u_with_sign(c, factor, sign, var):
    """A U record whose cell holds x_var = 0 and negative values (PRRP: detFx = 2x is not
    positive on it), claiming `sign` for `factor` in place of '0'."""
    v = var
    U = c.one("U", lambda r: r.cell[2 * v] < 0 <= r.cell[2 * v + 1] and r.chars[factor] == "0")
    chars = U.chars[:factor] + sign + U.chars[factor + 1:]
    return splice(c.data, set_packed(U, chars)), U.number


def sign_flip(c):
    S = c.one("S", lambda r: r.chars.strip("0"))
    flipped = "".join({"+": "-", "-": "+"}.get(ch, ch) for ch in S.chars)
    return splice(c.data, set_packed(S, flipped)), S.number


def image_inward(c, upper):
    """IMAGE of command 1 narrowed by 30% of its width at one end (its grid is Q~'s)."""
    S = c.one("S", k=len(c.find("S")) // 2)
    lo, hi = S.img[0], S.img[1]
    e = S.ends[2 * c.n + (1 if upper else 0)]
    new, x = e.near(hi - 0.3 * (hi - lo) if upper else lo + 0.3 * (hi - lo))
    assert lo < x < hi
    return splice(c.data, set_end(e, new)), S.number


def weight(c, new, k=0):
    """DX_1 (k = 0), ... of the middle S record replaced by the bytes `new`."""
    S = c.one("S", k=len(c.find("S")) // 2)
    return splice(c.data, set_end(S.ends[4 * c.n + k], new)), S.number


def x_to_leaf(c, tag, fix_count):
    """The first discarded cell made an undecided (U) or unexplored (N) leaf claiming no
    sign: every later output id is one more. The tree then holds one leaf more than
    end-tree says; with end-tree recounted, the first link names a box that moved."""
    X = c.one("X")
    new = bytes([tag]) + bytes((c.p + 3) // 4)
    E = c.one("end-tree")
    if not fix_count:
        return splice(c.data, replace(X, new)), E.number
    K = c.one("K")
    x_id = sum(1 for r in c.records if r.kind in ("U", "N", "S") and r.number < X.number)
    moved = c.solution[:x_id] + [False] + c.solution[x_id:]  # box i is now what i was ...
    assert not (moved[K.a] and moved[K.b])  # ... so the first link names a box not an S box
    return splice(c.data, replace(X, new), replace(E, b"end-tree %d\n" % (len(c.boxes) + 1))), K.number


def solution_to_undecided(c):
    S = c.one("S")
    K = c.one("K", lambda r: S.id in (r.a, r.b))
    return splice(c.data, replace(S, b"\xc1" + c.data[S.packed[0]:S.packed[1]])), K.number


def last_link_of_its_a(c, pred=lambda r: True):
    """A K record after which the next one has a larger A (or none): its B may grow."""
    ks = c.find("K")
    for k, r in enumerate(ks):
        if (k + 1 == len(ks) or ks[k + 1].a > r.a) and pred(r):
            return r
    raise AssertionError("no K record last of its A")


def link_b_moved(c, which):
    """B − A − 1 of a K record changed: B becomes a solution box that does not meet A
    (`apart`), an output box that is not a solution box (`undecided`), one past the last
    box (`out_of_range`), or beyond 2^53 (`huge`)."""
    K = last_link_of_its_a(c)
    if which == "apart":
        b = next(b for b in range(K.b + 1, len(c.boxes)) if c.solution[b] and not c.meet(K.a, b))
    elif which == "undecided":
        b = next(b for b in range(K.b + 1, len(c.boxes)) if not c.solution[b])
    elif which == "out_of_range":
        b = len(c.boxes)
    else:
        return splice(c.data, set_int(K, 1, (1 << 53) - 1)), K.number
    return splice(c.data, set_int(K, 1, b - K.a - 1)), K.number


def link_shift(c, pred, new_chars):
    K = c.one("K", pred)
    return splice(c.data, set_packed(K, new_chars(K.chars))), K.number


def link_shift_on_command(c):
    """A '0' on periodic command q1 made '+' where box B + 2π misses box A on q1."""
    v = c.command[0]
    k = [0] * c.nv
    k[v] = 1

    def far(r):
        return r.chars == "0" * c.nv and not c.meet(r.a, r.b, k)
    K = c.one("K", far)
    return splice(c.data, set_packed(K, K.chars[:v] + "+" + K.chars[v + 1:])), K.number


def link_witness_outside(c):
    K = c.one("K")
    A = c.boxes[K.a]
    x = A[2 * c.pose[0] + 1] + 0.5 * (A[2 * c.pose[0] + 1] - A[2 * c.pose[0]])
    return splice(c.data, set_end(K.ends[0], raw(x))), K.number


def link_iterate_moved(c):
    """Q~ of command 1 moved off A's commands by twice its width: no zero in it."""
    K = c.one("K")
    lo, hi = K.Q[0], K.Q[1]
    w = hi - lo
    return splice(c.data, set_end(K.ends[c.n], raw(hi + w)),
                  set_end(K.ends[c.n + 1], raw(hi + 2 * w))), K.number


def point_variable_witness(c):
    """3-RRR*: x3 in [0, 0], so u = 0 and every code of a witness on x3 decodes to 0:
    a code changed from its value to another keeps the record (the grid is a coding)."""
    j = next(j for j, v in enumerate(c.pose) if c.root[2 * v] == c.root[2 * v + 1])
    K = c.one("K")
    e = K.ends[j]
    assert e.value == 0 and e.c
    return splice(c.data, set_end(e, code(e.z + 12345)))


def csnc_unconnected(c):
    """The last id of a CSNC moved (a larger step) to a solution box of a later CSNC (so
    not linked to it, and not yet claimed), keeping the ids increasing: the component is
    not connected."""
    owner = {}
    for r in c.find("csnc"):
        for i in r.ids:
            owner[i] = r.k
    for r in c.find("csnc", lambda r: len(r.ids) >= 2):
        last = r.ids[-1]
        b = next((b for b in range(last + 1, len(c.boxes))
                  if c.solution[b] and owner.get(b, -1) > r.k), None)
        if b is not None:
            return splice(c.data, set_int(r, len(r.ints) - 1, b - r.ids[-2] - 1)), r.number
    raise AssertionError("no CSNC whose last id can move to another one")


def csnc_not_solution(c):
    """One id of a CSNC moved to an undecided box between its neighbours (the steps of
    that id and of the next one re-coded, so that the other ids stay)."""
    for r in c.find("csnc"):
        ids = [-1] + r.ids + [len(c.boxes)]
        for i in range(1, len(ids) - 1):
            b = next((b for b in range(ids[i - 1] + 1, ids[i + 1]) if not c.solution[b]), None)
            if b is None:
                continue
            edits = [set_int(r, 1 + i, b - ids[i - 1] - 1)]
            if i + 1 < len(ids) - 1:
                edits.append(set_int(r, 2 + i, ids[i + 1] - b - 1))
            return splice(c.data, *edits), r.number
    raise AssertionError("no undecided box between two ids of a CSNC")


def truncated_inside(c, kind, where):
    """The file cut inside a binary record: after its first byte, in a multi-byte varint,
    in the 8 bytes of a raw end (an end first written raw), or in the middle."""
    r = c.one(kind, lambda r: r.stop - r.start > 3)
    if where == "tag":
        return c.data[:r.start + 1], r.number
    if where == "varint":
        e = next(e for r2 in c.find(kind) for e in r2.ends if e.c >= 0x80)
        r = next(r2 for r2 in c.find(kind) if e in r2.ends)
        return c.data[:e.start + 1], r.number
    if where == "raw":
        e = r.ends[0]
        data = splice(c.data, set_end(e, raw(e.value)))
        return data[:e.start + 5], r.number
    return c.data[:(r.start + r.stop) // 2], r.number


def on(kind, edit, k=0, pred=lambda r: True):
    """A mutation of record k (-1: the last; a function of the Cert) of `kind` satisfying
    pred: edit(c, r) gives the byte edit (or a list of them); the message must name that
    record."""
    def mutate(c):
        r = c.one(kind, pred, k(c) if callable(k) else k)
        e = edit(c, r)
        return splice(c.data, *(e if isinstance(e, list) else [e])), r.number
    return mutate


def middle_s(c):
    return len(c.find("S")) // 2


def mutations_prrp():
    nan, inf, eof = math.nan, math.inf, "unexpected end of file"
    not_finite, not_positive = "a binary real is not finite", "P2: a column weight is not positive"
    strictly = "bisection point not strictly inside the cell"
    return [
        # ---- truncation: MALFORMED at the record the file ends in
        ("truncated_after_tag", lambda c: truncated_inside(c, "S", "tag"), (2, eof)),
        ("truncated_in_varint", lambda c: truncated_inside(c, "S", "varint"), (2, eof)),
        ("truncated_in_raw_double", lambda c: truncated_inside(c, "S", "raw"), (2, eof)),
        ("truncated_mid_s", lambda c: truncated_inside(c, "S", "middle"), (2, eof)),
        ("truncated_mid_k", lambda c: truncated_inside(c, "K", "middle"), (2, eof)),
        ("truncated_mid_csnc", lambda c: truncated_inside(c, "csnc", "middle"), (2, eof)),
        # Right after a whole binary record: the next record is missing.
        ("truncated_after_s", lambda c: (c.data[:c.one("S").stop], c.one("S").number + 1), (2, eof)),
        ("truncated_after_last_tree_record",
         lambda c: (c.data[:c.one("end-tree").start], c.one("end-tree").number), (2, eof)),
        ("truncated_after_last_csnc",
         lambda c: (c.data[:c.one("csnc", k=-1).stop], c.one("csnc", k=-1).number + 1), (2, eof)),
        # ---- first bytes
        ("unknown_first_byte_c6", on("S", lambda c, r: set_tag(r, 0xC6)),
         (2, "unknown binary record (first byte 198)")),
        ("unknown_first_byte_ff", on("K", lambda c, r: set_tag(r, 0xFF)),
         (2, "unknown binary record (first byte 255)")),
        ("unknown_first_byte_e0_first_record", on("P", lambda c, r: set_tag(r, 0xE0)),
         (2, "unknown binary record (first byte 224)")),
        ("p_variable_out_of_range", on("P", lambda c, r: set_tag(r, 0x80 + c.nv)),
         (1, "index 2 out of range")),
        ("p_variable_escape_31", on("P", lambda c, r: (r.start, r.start + 1, b"\x9f\x00")),
         (1, "index 31 out of range")),
        ("b_variable_escape_huge",
         on("B", lambda c, r: (r.start, r.start + 1, b"\xbf" + varint((1 << 53) - 1))),
         (1, "index 9007199254741022 out of range")),
        # The binary records are read after the factors: in place of `tree` one is read, and
        # is not `tree`; before, its first byte is not text.
        ("binary_record_for_tree", lambda c: splice(c.data, (c.tree_at, c.tree_at + 5, b"\xc0\x00")),
         (2, "expected 'tree' and 0 field(s), found 'X'")),
        ("binary_record_in_header", lambda c: splice(c.data, (c.tree_at, c.tree_at, b"\xc0\x00")),
         (2, "expected 'tree' and 0 field(s), found 'X'")),
        ("binary_record_before_factors",
         lambda c: splice(c.data, (c.data.index(b"\nfactors ") + 1,) * 2 + (b"\xc0\x00",)),
         (2, "byte 192 is not printable ASCII")),
        ("binary_u_after_csncs",
         lambda c: fix_end(c, splice(c.data, (c.one("claim").start,) * 2 + (b"\xc1\x00",)), 1),
         (2, "expected 'claim filtered'")),
        ("binary_csnc_among_links",
         on("K", lambda c, r: replace(r, c.data[c.one("csnc").start:c.one("csnc").stop])),
         (2, "expected a K record (32 announced)")),
        ("binary_k_in_tree", on("U", lambda c, r: replace(r, c.data[c.one("K").start:c.one("K").stop])),
         (2, "unknown record type 'K'")),
        # ---- packed characters: a code 3, or a bit after the last character, is malformed
        ("signs_code_3", on("S", lambda c, r: set_packed(r, "?" + r.chars[1:])), (2, "bad SIGNS field")),
        ("undecided_signs_code_3", on("U", lambda c, r: set_packed(r, r.chars[:-1] + "?")),
         (2, "bad SIGNS field")),
        ("signs_stray_bit_after_p", on("S", lambda c, r: set_packed(r, r.chars, 1 << (2 * c.p))),
         (2, "bad SIGNS field")),
        ("signs_stray_high_bit", on("U", lambda c, r: set_packed(r, r.chars, 0x80)), (2, "bad SIGNS field")),
        ("shift_code_3", on("K", lambda c, r: set_packed(r, "?" + r.chars[1:])), (2, "bad SHIFT field")),
        ("shift_stray_bit", on("K", lambda c, r: set_packed(r, r.chars, 0x10)), (2, "bad SHIFT field")),
        ("sign_flipped", sign_flip, (1, "not proved")),
        # detFx = 2x has no sign on a cell where x takes the value 0 and negative values.
        ("undecided_sign_claimed", lambda c: u_with_sign(c, 0, "+", 0),
         (1, "sign '+' of factor 1 not proved")),
        # FORMAT.md asks for at most 8 bytes and a value below 2^53, not the shortest form:
        # a padded integer is the same record.
        ("code_padded_to_8_bytes", on("S", lambda c, r: set_end(r.ends[0], padded(r.ends[0].c, 8))),
         (0, SAME)),
        # ---- raw ends that are not finite, coded ends that decode to no finite number
        ("raw_nan_contraction", on("P", lambda c, r: set_end(r.ends[0], raw(nan))), (2, not_finite)),
        ("raw_inf_weight", lambda c: weight(c, raw(inf)), (2, not_finite)),
        ("raw_minus_inf_witness", on("K", lambda c, r: set_end(r.ends[0], raw(-inf))), (2, not_finite)),
        ("raw_signalling_nan_bisection",
         on("B", lambda c, r: set_end(r.ends[0], raw_bits(0x7FF0000000000001))), (2, not_finite)),
        # Q~ = [-DBL_MAX, DBL_MAX]: IMAGE's reference is infinitely wide, its codes decode to
        # NaN or infinities.
        ("iterate_widest_image_not_finite",
         on("S", lambda c, r: [set_end(r.ends[0], raw(-sys.float_info.max)),
                               set_end(r.ends[1], raw(sys.float_info.max))]),
         (2, "a coded end is not finite")),
        # ---- contractions
        ("contraction_lo_above_hi", contraction_lo_above_hi, (2, "interval with LO > HI")),
        ("contraction_lo_raw_below_cell", on("P", lambda c, r: set_end(r.ends[0], raw(r.cell[2 * r.v] - 1))),
         (1, "contraction is not inside the cell")),
        ("contraction_hi_code_above_cell", on("P", lambda c, r: set_end(r.ends[1], code(1))),
         (1, "contraction is not inside the cell")),
        ("contraction_inward_leaf_recoded", lambda c: contraction_inward(c, True),
         (1, "cannot refute the slab below the contraction")),
        ("contraction_inward", lambda c: contraction_inward(c, False),
         (1, "cannot refute the slab below the contraction")),
        # ---- bisections: z = -2^15 and 2^15 are the cell's ends exactly (OFFSET 2^15, G 16)
        ("bisection_raw_outside", on("B", lambda c, r: set_end(r.ends[0], raw(r.cell[2 * r.v + 1] + 1))),
         (1, strictly)),
        ("bisection_at_hi", on("B", lambda c, r: set_end(r.ends[0], code(MIDDLE))), (1, strictly)),
        ("bisection_at_lo", on("B", lambda c, r: set_end(r.ends[0], code(-MIDDLE))), (1, strictly)),
        # ---- leaves
        # U made N: the same claims, but the run is not complete.
        ("undecided_to_unexplored", lambda c: splice(c.data, set_tag(c.one("U"), 0xC2)),
         (0, " complete=no eps=0.1 solutions=36 undecided=11 unexplored=1 ")),
        # S made U (its signs kept): the first link to it joins a box that is not an S box.
        ("solution_to_undecided", solution_to_undecided,
         (1, "link between boxes that are not both solution boxes")),
        ("image_lo_inward", lambda c: image_inward(c, False),
         (1, "P1: the Hansen-Sengupta image is not inside IMAGE")),
        ("image_hi_inward", lambda c: image_inward(c, True),
         (1, "P1: the Hansen-Sengupta image is not inside IMAGE")),
        ("image_lo_raw_below_iterate", on("S", lambda c, r: set_end(r.ends[2 * c.n], raw(r.Q[0] - 1e-3))),
         (1, "IMAGE is not inside Q~")),
        ("iterate_lo_above_cell", on("S", lambda c, r: set_end(r.ends[0], code(3))),
         (1, "coverage: the cell's q is not inside Q~")),
        ("weight_raw_zero", lambda c: weight(c, raw(0.0)), (1, not_positive)),
        ("weight_raw_minus_zero", lambda c: weight(c, raw(-0.0)), (1, not_positive)),
        ("weight_raw_negative", lambda c: weight(c, raw(-1.0)), (1, not_positive)),
        # z = -2^16 on [1, 2]: fma(-65536, 2^-16, 1) = 0 exactly; one step more is negative.
        ("weight_code_zero", lambda c: weight(c, code(-(1 << 16)), c.n), (1, not_positive)),
        ("weight_code_negative", lambda c: weight(c, code(-(1 << 16) - 1)), (1, not_positive)),
        # ---- links
        ("link_b_apart", lambda c: link_b_moved(c, "apart"), (1, "the linked boxes do not meet")),
        ("link_b_undecided", lambda c: link_b_moved(c, "undecided"), (1, "not both solution boxes")),
        ("link_b_out_of_range", lambda c: link_b_moved(c, "out_of_range"), (1, "index 48 out of range")),
        ("link_b_huge", lambda c: link_b_moved(c, "huge"), (2, "binary id out of range")),
        ("link_shift_on_nonperiodic", on("K", lambda c, r: set_packed(r, "+" + r.chars[1:])),
         (1, "shift on a non-periodic variable")),
        ("link_witness_raw_outside", link_witness_outside, (1, "witness outside the boxes' intersection")),
        ("link_witness_code_outside", on("K", lambda c, r: set_end(r.ends[0], code((1 << 16) + 5))),
         (1, "witness outside the boxes' intersection")),
        ("link_iterate_moved", link_iterate_moved, (1, "P3: ")),
        # ---- CSNCs
        ("csnc_id_step_unconnected", csnc_unconnected, (1, "component is not connected by certified links")),
        ("csnc_id_not_solution", csnc_not_solution, (1, "component holds a box that is not a solution box")),
        ("csnc_number_changed", on("csnc", lambda c, r: set_int(r, 0, 1)),
         (1, "components must be numbered 0, 1, 2")),
        ("csnc_size_zero", on("csnc", lambda c, r: replace(r, b"\xc5\x00\x00")),
         (2, "csnc: SIZE does not match the ids")),
        # ---- another coding of the same records: the grid is only a coding
        ("all_ends_raw", lambda c: all_raw(c), (0, SAME)),
        # ---- but these records are binary only: one written as a (valid) version 2 text
        # line is malformed, whatever it says.
        ("contraction_as_text", as_text("P"), (2, "a text 'P' record in a format 3 certificate")),
        ("undecided_as_text", as_text("U"), (2, "a text 'U' record in a format 3 certificate")),
        ("solution_as_text", as_text("S"), (2, "a text 'S' record in a format 3 certificate")),
        ("link_as_text", as_text("K"), (2, "a text 'K' record in a format 3 certificate")),
        ("csnc_as_text", as_text("csnc"), (2, "a text 'csnc' record in a format 3 certificate")),
        # ---- after `end`
        ("byte_after_end", lambda c: c.data + b"\x00", (2, "content after 'end'")),
        ("binary_record_after_end", lambda c: c.data + b"\xc1\x00", (2, "content after 'end'")),
        ("newline_after_end", lambda c: c.data + b"\n", (2, "content after 'end'")),
    ]


def mutations_rrrrr_joint_limit():
    bad_int = "binary integer out of range"
    not_both = "link between boxes that are not both solution boxes"
    return [
        ("all_ends_raw", lambda c: all_raw(c), (0, SAME)),
        ("discard_as_text", as_text("X"), (2, "a text 'X' record in a format 3 certificate")),
        # ---- integers and hints (PRRP has no discarded cell); the first X is `c0`
        ("varint_9_bytes", on("X", lambda c, r: set_int(r, 0, 0, 9)), (2, bad_int)),
        ("varint_2_53", on("X", lambda c, r: set_int(r, 0, 1 << 53)), (2, bad_int)),
        ("varint_2_53_minus_1_hint", on("X", lambda c, r: set_int(r, 0, (1 << 53) - 1)),
         (2, "bad hint 'eq4503599627370495'")),
        # FORMAT.md asks for at most 8 bytes and a value below 2^53, not the shortest form.
        ("varint_padded_to_8_bytes", on("X", lambda c, r: set_int(r, 0, r.ints[0][2], 8)), (0, SAME)),
        # The hint is a label (the checker refutes the cell whatever it says) ...
        ("hint_c0_to_hs", on("X", lambda c, r: set_int(r, 0, 0), pred=lambda r: r.hint == "c0"), (0, SAME)),
        ("hint_c0_to_eq0", on("X", lambda c, r: set_int(r, 0, 1), pred=lambda r: r.hint == "c0"), (0, SAME)),
        # ... naming an equation or a constraint of the model.
        ("hint_c1_of_one_constraint", on("X", lambda c, r: set_int(r, 0, 4)), (2, "bad hint 'c1'")),
        ("hint_eq2_of_two_equations", on("X", lambda c, r: set_int(r, 0, 5)), (2, "bad hint 'eq2'")),
        # X made U: every later output id shifts; the leaf count no longer matches.
        ("discard_to_undecided", lambda c: x_to_leaf(c, 0xC1, False),
         (1, "end-tree: wrong number of leaves")),
        # ... with end-tree recounted: the first link names a box that moved.
        ("discard_to_undecided_recounted", lambda c: x_to_leaf(c, 0xC1, True), (1, not_both)),
        ("discard_to_unexplored_recounted", lambda c: x_to_leaf(c, 0xC2, True), (1, not_both)),
        # A feasible solution cell discarded as infeasible by the constraint (ids shift after).
        ("solution_discarded_c0", on("S", lambda c, r: replace(r, b"\xc0\x02"), k=middle_s),
         (1, "cannot refute the discarded cell")),
        ("weight_raw_2_40", lambda c: weight(c, raw(2.0 ** 40)),
         (1, "P2: C_X*Fx*D_X is not strictly diagonally dominant")),
        ("weight_code_zero", lambda c: weight(c, code(-(1 << 16)), 1),
         (1, "P2: a column weight is not positive")),
        ("image_lo_inward", lambda c: image_inward(c, False),
         (1, "P1: the Hansen-Sengupta image is not inside IMAGE")),
        ("contraction_inward_leaf_recoded", lambda c: contraction_inward(c, True),
         (1, "cannot refute the slab below the contraction")),
        ("sign_flipped", sign_flip, (1, "not proved")),
        ("link_b_apart", lambda c: link_b_moved(c, "apart"), (1, "the linked boxes do not meet")),
        ("link_shift_on_command", link_shift_on_command, (1, "the linked boxes do not meet")),
        ("truncated_mid_file", lambda c: c.data[:len(c.data) // 2], (2, "unexpected end of file")),
    ]


def mutations_3rrr_star():
    return [
        ("all_ends_raw", lambda c: all_raw(c), (0, SAME)),
        ("bisection_as_text", as_text("B"), (2, "a text 'B' record in a format 3 certificate")),
        ("point_variable_witness_code", point_variable_witness, (0, SAME)),
        # A link across the seam of a periodic command written without its shift.
        ("link_seam_shift_dropped",
         on("K", lambda c, r: set_packed(r, "0" * c.nv), pred=lambda r: r.chars.strip("0")),
         (1, "the linked boxes do not meet")),
        ("link_shift_on_command", link_shift_on_command, (1, "the linked boxes do not meet")),
        # SHIFT has 6 characters: the second byte holds two, its 4 high bits must be 0.
        ("shift_stray_bit_second_byte", on("K", lambda c, r: set_packed(r, r.chars, 0x10, 1)),
         (2, "bad SHIFT field")),
        ("shift_on_point_variable", on("K", lambda c, r: set_packed(r, "".join(
            "+" if c.root[2 * v] == c.root[2 * v + 1] else ch for v, ch in enumerate(r.chars)))),
         (1, "shift on a non-periodic variable")),
        ("sign_flipped", sign_flip, (1, "not proved")),
        ("link_witness_raw_outside", link_witness_outside, (1, "witness outside the boxes' intersection")),
        ("csnc_id_step_unconnected", csnc_unconnected, (1, "component is not connected by certified links")),
    ]


# ------------------------------------------------------------------ running

# check_cert's modes: one thread; three threads with batches of three proofs (many batch
# boundaries: slow on a large certificate); two threads with the default batches; the
# trusted core alone.
MODES = {"one": (["--threads", "1"], {}), "batch3": (["--threads", "3"], {"CHECK_CERT_BATCH": "3"}),
         "two": (["--threads", "2"], {}), "trusted": (["--trusted-only"], {})}
SMALL, LARGE = ("one", "batch3", "trusted"), ("one", "two", "trusted")


def run(check, path, modes=SMALL):
    """check_cert in each of `modes` (as tamper.py): the verdict and its reason must not
    depend on threads, batches or the speed layer. (code, message); code -1 when the modes
    disagree, the negative signal on a crash."""
    env = dict(os.environ)
    results = []
    for args, extra in (MODES[m] for m in modes):
        r = subprocess.run([check, "--quiet"] + args + [path], stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, env=dict(env, **extra))
        results.append((r.returncode, r.stdout.decode(errors="replace").strip()))
        if r.returncode < 0:
            return results[-1]
    if any(x != results[0] for x in results):
        return -1, "the verdict depends on threads or the speed layer: %r" % results
    return results[0]


def without_sha(msg):
    return " ".join(w for w in msg.split() if not w.startswith("sha256(cert)="))


def reader_tests(check, tag, path, c):
    """The reader: a full parse ends at `end N` after N records (asserted while parsing),
    and every binary record decodes to exactly what check_cert --print prints."""
    r = subprocess.run([check, "--quiet", "--threads", "1", "--print", path],
                       stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    printed = r.stdout.decode().split("\n")
    bad = [rec for rec in c.records if rec.binary and printed[rec.number - 1] != rec.text()]
    kinds = {}
    for rec in c.binary_records():
        kinds[rec.kind] = kinds.get(rec.kind, 0) + 1
    grid = sum(1 for rec in c.binary_records() for e in rec.ends if e.c)
    ends = sum(len(rec.ends) for rec in c.binary_records())
    ok = r.returncode == 0 and not bad and len(printed) >= c.end.number
    print("%s reader/%-48s %d records (%s), %d ends (%d on the grid), %d bytes: %s" % (
        "ok  " if ok else "FAIL", tag, c.end.number,
        " ".join("%s=%d" % kv for kv in sorted(kinds.items())), ends, grid, len(c.data),
        "decoded as --print" if ok else
        "record %d: %r, --print %r" % (bad[0].number, bad[0].text(), printed[bad[0].number - 1])
        if bad else "exit %d" % r.returncode))
    return not ok


def flip_loop(check, tag, c, base_msg, count, rng, modes, work):
    """Random single-byte changes (a bit flipped, a byte replaced, a byte xored) and
    truncations inside the binary records: exit 0, 1 or 2, no signal, no internal error."""
    recs = c.binary_records()
    verdicts = {0: 0, 1: 0, 2: 0}
    failed = 0
    path = os.path.join(work, "flip__%s.cert" % tag)
    for k in range(count):
        r = rng.choice(recs)
        i = rng.randrange(r.start, r.stop)
        how = rng.randrange(4)
        if how == 3:
            data, what = c.data[:i], "truncated at %d" % i
        else:
            old = c.data[i]
            if how == 0:
                new = old ^ (1 << rng.randrange(8))
            else:
                new = rng.randrange(256) if how == 1 else old ^ rng.randrange(1, 256)
            if new == old:
                new = old ^ 0x80
            data, what = splice(c.data, (i, i + 1, bytes([new]))), "byte %d %02x -> %02x" % (i, old, new)
        with open(path, "wb") as f:
            f.write(data)
        code, msg = run(check, path, modes)
        if code == 0:  # verified: which field changed; FORMAT.md must call the file valid
            field = "first byte" if i == r.start else next(
                ("end %d" % m for m, e in enumerate(r.ends) if e.start <= i < e.stop),
                "SIGNS/SHIFT" if r.packed and r.packed[0] <= i < r.packed[1] else "integer")
            try:
                Cert(data)
                why = None
            except Exception as e:
                why = "VERIFIED, but the reader of FORMAT.md refuses it: %s" % e
            same = without_sha(msg) == without_sha(base_msg)
            print("%s flip/%s %s in %s record %d (%s): %s" % (
                "FAIL" if why else "    ", tag, what, r.kind, r.number, field,
                why or ("verified, same claims" if same else msg)))
            if why:
                failed += 1
                with open(os.path.join(work, "flip__%s__%d.cert" % (tag, k)), "wb") as f:
                    f.write(data)
        if code not in verdicts or "internal error" in msg:
            print("FAIL flip/%s %s (in %s record %d): exit %d: %s" % (tag, what, r.kind, r.number,
                                                                    code, msg[:200]))
            keep = os.path.join(work, "flip__%s__%d.cert" % (tag, k))
            os.replace(path, keep)
            failed += 1
            continue
        verdicts[code] += 1
    print("%s flip/%-50s %d changes: %d verified, %d rejected, %d malformed" % (
        "ok  " if not failed else "FAIL", tag, count, verdicts[0], verdicts[1], verdicts[2]))
    return failed


def main():
    check, aspects, robots, work = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    t0 = time.time()
    muts = {"prrp": mutations_prrp(), "rrrrr_joint_limit": mutations_rrrrr_joint_limit(),
            "3rrr_star": mutations_3rrr_star()}
    failed = 0
    certs = {}
    for robot, eps in BASES:
        out = os.path.join(work, robot)
        subprocess.run([aspects, "solve", os.path.join(robots, robot + ".robot"), "--eps", eps,
                        "--out", out, "--cert-format", "3", "--quiet"], check=True)
        path = os.path.join(out, "aspects.cert")
        data = open(path, "rb").read()
        code, msg = run(check, path, SMALL if robot == "prrp" else LARGE)
        if code != 0:
            print("FAIL base certificate %s not verified: %s" % (path, msg))
            return 1
        try:
            c = Cert(data)
        except Exception as e:  # the reader must read every certificate of the writer
            print("FAIL reader/%s: %r" % (robot, e))
            failed += 1
            continue
        certs[robot] = (c, msg)
        failed += reader_tests(check, robot, path, c)
    print("solved and read in %.1f s" % (time.time() - t0))
    total = 0
    tally = {0: 0, 1: 0, 2: 0}
    for robot, _ in BASES:
        if robot not in certs:
            continue
        c, base_msg = certs[robot]
        for name, fn, want in muts[robot]:
            total += 1
            want, word = want if isinstance(want, tuple) else (want, "")
            label = "%s/%s" % (robot, name)
            try:
                got = fn(c)
            except Exception as e:  # a mutation that does not apply is a failure of the suite
                print("FAIL %-52s mutation not applicable: %r" % (label, e))
                failed += 1
                continue
            data, record = got if isinstance(got, tuple) else (got, None)
            if data == c.data:
                print("FAIL %-52s mutation changed nothing" % label)
                failed += 1
                continue
            path = os.path.join(work, label.replace("/", "__") + ".cert")
            with open(path, "wb") as f:
                f.write(data)
            code, msg = run(check, path, SMALL if robot == "prrp" else LARGE)
            if word == SAME:
                ok = code == want and without_sha(msg) == without_sha(base_msg) and msg != base_msg
            else:
                ok = code == want and word in msg
            if ok and record is not None and code != 0:
                ok = (" record %d: " % record) in msg
            tally[code] = tally.get(code, 0) + 1
            print("%s %-52s exit %d (want %d%s%s): %s" % (
                "ok  " if ok else "FAIL", label, code, want, ", '%s'" % word if word else "",
                ", record %d" % record if record is not None and want else "", msg[:120]))
            failed += not ok
    print("%d mutations, %d failed: %d verified, %d rejected, %d malformed" % (
        total, failed, tally.get(0, 0), tally.get(1, 0), tally.get(2, 0)))
    rng = random.Random(3)
    for robot, count, modes in (("prrp", 300, SMALL), ("3rrr_star", 30, ("two",)),
                                ("rrrrr_joint_limit", 30, ("two",))):
        if robot in certs:
            failed += flip_loop(check, robot, certs[robot][0], certs[robot][1], count, rng, modes, work)
    print("%.1f s, %d failed" % (time.time() - t0, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
