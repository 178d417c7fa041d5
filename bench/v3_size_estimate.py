#!/usr/bin/python3
"""v3_size_estimate.py — what a compact certificate format (issue 31's version 3) would
weigh, measured on real version 2 certificates before it is built.

  v3_size_estimate.py [--grid G] [--zstd LEVEL] CERT...

Re-encodes every record of the search tree, the links and the CSNCs of a text certificate
the way the draft below would, and prints, per certificate, the bytes per output box of the
text (raw and zstd) and of the draft (raw and zstd), with each record kind's share. Nothing
here is checked: it is a size estimate. The grid offsets are computed from the version 2
values rounded outward, which is what a solver writing version 3 would have to record (its
contraction bounds, Q~ and IMAGE moved outward by less than 2^-G of the width).

The draft (all integers unsigned LEB128 varints unless said; one tag byte a record, kind in
the high 3 bits, a variable or hint in the low 5):
- P v k_lo k_hi: LO = lo + k_lo*u, HI = hi - k_hi*u, u = (hi - lo)*2^-G of the current cell.
- B v d: X = lo + (2^(G-1) + d)*u, d zigzag-coded (a bisection near the middle: one byte).
- X: the tag alone (the hint is free text today).
- U, N: the tag and the signs, two bits a factor.
- S: the tag, the signs, a bit mask of the weights that are not 1 (each then 2 bytes: a
  bfloat16, the solver's weight rounded to 8 significant bits, with which it proves P2), and per
  command j: Q~ = [c.lo - a*u, c.hi + b*u] (u of the cell's command j), then IMAGE =
  [Q~.lo + c*u', Q~.hi - d*u'] (u' of Q~). No preconditioner: the checker computes its own
  (the inverse of the midpoint of its enclosure), as it already does for refutations.
- K: A as a delta from the previous A, B - A, the shift (two bits a variable), the witness
  per pose variable as an offset on the grid of the inner intersection I_v (zigzag from its
  middle), Q~ per command on the grid of I_command as in S; no preconditioner.
- csnc: its size then its ids, each a delta from the one before.
"""
import math
import struct
import os
import subprocess
import sys

KINDS = "PBXUNSKc"
TWO_PI = 2 * math.pi


def varint(n):
    n = int(n)
    assert n >= 0, n
    out = bytearray()
    while n >= 128:
        out.append(0x80 | (n & 127))
        n >>= 7
    out.append(n)
    return bytes(out)


def zigzag(d):
    d = int(d)
    return varint(2 * d if d >= 0 else -2 * d - 1)


def bfloat16(x):
    """x's top 16 bits as a binary32: a weight the solver would round to 8 significant bits
    (and prove P2 with)."""
    return (struct.unpack("<I", struct.pack("<f", x))[0] >> 16).to_bytes(2, "little")


def zsize(path, level):
    p = subprocess.run(["zstd", "-%d" % level, "-T2", "-c", path], stdout=subprocess.PIPE,
                       check=True)
    return len(p.stdout)


def steps(dist, lo, hi, scale, rnd=math.floor):
    """A distance in steps of the grid of [lo, hi] ((hi - lo)*scale each), rounded by `rnd`
    (down for an end moved inward, so that it only moves back out; up for an end outside
    [lo, hi]); 0 on an empty width."""
    u = (hi - lo) * scale
    return rnd(dist / u) if u > 0 else 0


def estimate(path, grid, out):
    """Writes the draft's bytes to `out` and returns {kind: [records, bytes]}."""
    scale = 2.0 ** -grid
    half = 2 ** (grid - 1)
    stats = {k: [0, 0] for k in KINDS}

    def emit(kind, tag, body=b""):
        rec = bytes([tag & 255]) + body
        stats[kind][0] += 1
        stats[kind][1] += len(rec)
        out.write(rec)

    def signs(field):  # also a link's shift: the same three characters
        bits = 0
        for i, ch in enumerate(field if field != "." else ""):
            bits |= {"0": 0, "+": 1, "-": 2}[ch] << (2 * i)
        return bits.to_bytes((2 * len(field.strip(".")) + 7) // 8, "little")

    with open(path, "rb") as f:
        lines = iter(f)
        command, nv, n = [], 0, 0
        stack, boxes, last_a = [], [], 0
        for raw in lines:
            line = raw.decode("ascii").rstrip("\n")
            if line.startswith("model "):
                size = int(line.split()[1])
                text = b""
                while len(text) < size + 1:
                    text += next(lines)
                for decl in text.decode().splitlines():
                    w = decl.split()
                    if w and w[0] in ("pose", "command"):
                        command.append(w[0] == "command")
                nv, n = len(command), sum(command)
                cmd = [v for v in range(nv) if command[v]]
                pose = [v for v in range(nv) if not command[v]]
                continue
            w = line.split()
            if not w:
                continue
            k = w[0]
            if k == "domain":
                ends = [float.fromhex(x) for x in w[1:]]
                stack = [[(ends[2 * v], ends[2 * v + 1]) for v in range(nv)]]
            elif k == "P":
                cell = stack[-1]
                v, lo, hi = int(w[1]), float.fromhex(w[2]), float.fromhex(w[3])
                clo, chi = cell[v]
                klo = steps(lo - clo, clo, chi, scale)
                khi = steps(chi - hi, clo, chi, scale)
                emit("P", 0 << 5 | v, varint(klo) + varint(khi))
                u = (chi - clo) * scale
                cell[v] = (clo + klo * u, chi - khi * u)
            elif k == "B":
                cell = stack.pop()
                v, x = int(w[1]), float.fromhex(w[2])
                clo, chi = cell[v]
                d = steps(x - clo, clo, chi, scale, round) - half
                emit("B", 1 << 5 | v, zigzag(d))
                right, left = list(cell), list(cell)
                right[v] = (x, chi)
                left[v] = (clo, x)
                stack.append(right)
                stack.append(left)
            elif k == "X":
                stack.pop()
                emit("X", 2 << 5)
            elif k in ("U", "N"):
                cell = stack.pop()
                boxes.append(cell)
                emit(k, (3 if k == "U" else 4) << 5, signs(w[2]))
            elif k == "S":
                cell = stack.pop()
                vals = [float.fromhex(x) for x in w[3:]]
                qt, img = vals[0:2 * n], vals[2 * n:4 * n]
                weights = vals[4 * n + 3 * n * n:]
                body = bytearray(signs(w[2]))
                mask = sum(1 << i for i, x in enumerate(weights) if x != 1.0)
                body += varint(mask)
                body += b"".join(bfloat16(x) for x in weights if x != 1.0)
                box = list(cell)
                for j, v in enumerate(cmd):
                    clo, chi = cell[v]
                    u = (chi - clo) * scale
                    a = max(0, steps(clo - qt[2 * j], clo, chi, scale, math.ceil))
                    b = max(0, steps(qt[2 * j + 1] - chi, clo, chi, scale, math.ceil))
                    qlo, qhi = clo - a * u, chi + b * u
                    c = max(0, steps(img[2 * j] - qlo, qlo, qhi, scale))
                    d = max(0, steps(qhi - img[2 * j + 1], qlo, qhi, scale))
                    body += varint(a) + varint(b) + varint(c) + varint(d)
                    box[v] = (img[2 * j], img[2 * j + 1])
                boxes.append(box)
                emit("S", 5 << 5, bytes(body))
            elif k == "K":
                a, b = int(w[1]), int(w[2])
                shift = w[3]
                vals = [float.fromhex(x) for x in w[4:]]
                wit, qt = vals[0:n], vals[n:3 * n]
                body = bytearray(varint(a - last_a if a >= last_a else a) + varint(b - a))
                body += signs(shift)
                last_a = a
                inter = []
                for v in range(nv):
                    s = {"0": 0, "+": 1, "-": -1}[shift[v]] * TWO_PI
                    inter.append((max(boxes[a][v][0], boxes[b][v][0] + s),
                                  min(boxes[a][v][1], boxes[b][v][1] + s)))
                for j, v in enumerate(pose):
                    lo, hi = inter[v]
                    body += zigzag(steps(wit[j] - lo, lo, hi, scale) - half)
                for j, v in enumerate(cmd):
                    lo, hi = inter[v]
                    body += zigzag(steps(lo - qt[2 * j], lo, hi, scale, math.ceil))
                    body += zigzag(steps(qt[2 * j + 1] - hi, lo, hi, scale, math.ceil))
                emit("K", 6 << 5, bytes(body))
            elif k == "csnc":
                ids = [int(x) for x in w[3:]]
                body = varint(len(ids)) + b"".join(
                    varint(ids[i] - (ids[i - 1] if i else 0)) for i in range(len(ids)))
                emit("c", 7 << 5, body)
    return stats


def main():
    args = sys.argv[1:]
    grid, level = 20, 12
    while args and args[0].startswith("--"):
        if args[0] == "--grid":
            grid = int(args[1])
        elif args[0] == "--zstd":
            level = int(args[1])
        else:
            sys.exit("unknown option " + args[0])
        args = args[2:]
    for path in args:
        draft = path + ".v3draft"
        with open(draft, "wb") as sink:
            stats = estimate(path, grid, sink)
        boxes = stats["U"][0] + stats["N"][0] + stats["S"][0]
        raw = os.path.getsize(path)
        print("%s: %d output boxes; text %.0f B/box raw, %.0f zstd-%d; draft (grid 2^-%d) %.1f "
              "B/box raw, %.1f zstd-%d" % (path, boxes, raw / boxes, zsize(path, level) / boxes,
                                           level, grid, os.path.getsize(draft) / boxes,
                                           zsize(draft, level) / boxes, level))
        os.remove(draft)
        print("  " + ", ".join("%s %d records %.1f B/box" % (k if k != "c" else "csnc", s[0], s[1] / boxes)
                               for k, s in stats.items() if s[0]))


if __name__ == "__main__":
    main()
