#!/usr/bin/env python3
"""The shape of the source tree (issue 48): per top-level folder, its files and lines, the
largest file, and the deepest chain of the project's own #include "..." (each header
resolved as the compiler would: the including file's folder first, then the include roots
of the build). Usage: bench/tree_shape.py [FOLDER...] (default: the code folders)."""
import os
import re
import sys
from functools import lru_cache

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The include roots the libraries put on the path (their CMakeLists), in no particular order:
# a header name is found in at most one of them.
ROOTS = ["", "core", "proofs", "certificates", "apps", "planning", "run", "results",
         "distribution", "python/src"]
DEFAULT = ["apps", "core", "proofs", "planning", "run", "results", "distribution",
           "certificates", "python"]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
SOURCE = (".h", ".hpp", ".cpp", ".cc")


def resolve(name, here):
    for d in [here] + [os.path.join(ROOT, r) for r in ROOTS]:
        p = os.path.normpath(os.path.join(d, name))
        if os.path.isfile(p):
            return p
    return None  # generated (aspects_version.h) or not the project's


def includes(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        text = f.read()
    out = []
    for name in INCLUDE.findall(text):
        p = resolve(name, os.path.dirname(path))
        if p:
            out.append(p)
    return out


@lru_cache(maxsize=None)
def deepest(path, within="", stack=()):
    """The longest chain of includes from `path` (a cycle is cut where it closes); with
    `within`, only through the files of that folder."""
    best = (path,)
    for inc in includes(path):
        if inc in stack or inc == path or not inc.startswith(within):
            continue
        chain = (path,) + deepest(inc, within, stack + (path,))
        if len(chain) > len(best):
            best = chain
    return best


def files_of(folder):
    for dirpath, _, names in os.walk(os.path.join(ROOT, folder)):
        if "/tests" in dirpath[len(ROOT):] and folder != "tests":
            continue  # a folder's own test data (certificates/checker/tests)
        for n in sorted(names):
            if n.endswith(SOURCE):
                yield os.path.join(dirpath, n)


def lines(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        return sum(1 for _ in f)


def rel(p):
    return os.path.relpath(p, ROOT)


def main():
    folders = sys.argv[1:] or DEFAULT
    for folder in folders:
        fs = list(files_of(folder))
        if not fs:
            continue
        sizes = {f: lines(f) for f in fs}
        big = max(fs, key=lambda f: sizes[f])
        chain = max((deepest(f) for f in fs), key=len)
        inside = os.path.join(ROOT, folder) + "/"
        own = max((deepest(f, inside) for f in fs), key=len)
        print(f"{folder}/: {len(fs)} files, {sum(sizes.values())} lines; largest "
              f"{rel(big)} ({sizes[big]} lines)")
        print(f"  deepest include chain {len(chain) - 1}: " + " -> ".join(rel(c) for c in chain))
        print(f"  within {folder}/ {len(own) - 1}: " + " -> ".join(rel(c) for c in own))


if __name__ == "__main__":
    main()
