#!/usr/bin/python3
"""Runs every example of README.md and docs/*.md and compares its output (ctest
`cli.doc_examples`), so that the documentation cannot go stale.

    doc_examples.py SOURCE_DIR BUILD_DIR [--python=DIR] [FILE.md ...]

An example is a fenced block (``` ... ```) with a line `$ ./build/...`. Each line that
starts with `$ ` is a command, run by bash; the lines under it, up to the next command,
are its expected standard output. With --python=DIR (the build tree's package, given when
the module is built), a fenced block with `>>> ` lines is run by doctest too (option
ELLIPSIS: `...` in an expected output matches any text), PYTHONPATH=DIR.
Normalisation of the `$ ` examples, and nothing else:
- trailing spaces are ignored;
- a line `...` matches any number of lines (none included);
- `...` within a line matches any text on that line (times, hashes, versions, elided
  numbers);
- a last expected line `[exit N]` says the command exits N (otherwise it must exit 0);
- standard error is not compared (append `2>&1` to a command to compare it too).

Each file runs in a scratch directory of its own that mirrors the source tree (symbolic
links to its files, `build` to BUILD_DIR), so `out/...` and figures are written there, and
the blocks of one file run in order (a later block may read an earlier one's `out/`).
A failure names the file, the block's line, the command's line and the first expected
line that does not match, then shows the expected and the actual output.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

COMMAND_TIMEOUT = 60  # seconds; an example should take a few


def blocks(path):
    """(line of the opening fence, [(line number, text)]) of every fenced block."""
    out, inside, start, body, indent = [], False, 0, [], 0
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            line = line.rstrip("\n")
            stripped = line.lstrip()
            if stripped.startswith("```"):
                if inside:
                    out.append((start, body))
                    inside = False
                else:
                    inside, start, body = True, n, []
                    indent = len(line) - len(stripped)
                continue
            if inside:
                # Blocks inside list items are indented; the indentation is not output.
                body.append((n, line[indent:] if line[:indent].strip() == "" else line))
    return out


PY_RUNNER = r"""
import doctest, sys
text, name, lineno = open(sys.argv[1]).read(), sys.argv[2], int(sys.argv[3])
test = doctest.DocTestParser().get_doctest(text, {}, name, name, lineno)
runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
runner.run(test)
sys.exit(1 if runner.failures else 0)
"""


def python_blocks(path):
    """[(line of the opening fence, text)] of the blocks with `>>> ` lines."""
    return [(start, "\n".join(text for _, text in body) + "\n")
            for start, body in blocks(path)
            if any(text.startswith(">>> ") for _, text in body)]


def run_python(rel, root, env, python_dir, build, start, text):
    """Runs one `>>>` block by doctest; returns True when it passed."""
    script = os.path.join(root, ".doc_block.py")
    with open(script, "w", encoding="utf-8") as f:
        f.write(text)
    env = dict(env, PYTHONPATH=python_dir, MPLBACKEND="Agg", PYTHONDONTWRITEBYTECODE="1",
               ASPECTS_EXE=os.path.join(build, "apps", "aspects"),
               ASPECTS_CHECK_CERT=os.path.join(build, "certificates", "check_cert"))
    t0 = time.monotonic()
    try:
        p = subprocess.run(["/usr/bin/python3", "-c", PY_RUNNER, script, rel, str(start)],
                           cwd=root, env=env, capture_output=True, text=True,
                           timeout=COMMAND_TIMEOUT)
        code, out = p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired:
        code, out = None, f"(timed out after {COMMAND_TIMEOUT} s)"
    seconds = time.monotonic() - t0
    if code == 0:
        print(f"ok   {rel}:{start}  ({seconds:.1f} s)  python block (doctest)")
        return True
    print(f"FAIL {rel}:{start}: python block at line {start} ({seconds:.1f} s), doctest says"
          " (its line numbers are the file's):")
    for line in out.rstrip("\n").split("\n"):
        print("    | " + line)
    return False


def examples(path):
    """[(block line, [(command line, command, [(line, expected)])])] of the examples."""
    found = []
    for start, body in blocks(path):
        if not any(text.startswith("$ ./build/") for _, text in body):
            continue
        steps = []
        for n, text in body:
            if text.startswith("$ "):
                steps.append((n, text[2:], []))
            elif steps:
                steps[-1][2].append((n, text))
            elif text.strip():
                steps.append((n, None, [(n, text)]))  # output before any command
        found.append((start, steps))
    return found


def line_pattern(expected):
    return re.compile("".join(".*?" if part == "..." else re.escape(part)
                              for part in re.split(r"(\.\.\.)", expected.rstrip())) + r"\Z")


def match(expected, actual):
    """None when `actual` lines match the `expected` (line, text) pairs, otherwise the
    index of the furthest expected line that could not be matched (match.actual_line: the
    actual line it was tried against, 0-based; len(actual) when the output ended)."""
    pats = [None if text.strip() == "..." else line_pattern(text) for _, text in expected]
    furthest = [(0, 0)]
    memo = {}

    def go(i, j):
        key = (i, j)
        if key in memo:
            return memo[key]
        furthest[0] = max(furthest[0], (i, j))
        if i == len(pats):
            ok = j == len(actual)
        elif pats[i] is None:
            ok = any(go(i + 1, k) for k in range(j, len(actual) + 1))
        else:
            ok = j < len(actual) and pats[i].match(actual[j].rstrip()) is not None \
                and go(i + 1, j + 1)
        memo[key] = ok
        return ok

    sys.setrecursionlimit(max(10000, 4 * (len(pats) + len(actual))))
    if go(0, 0):
        return None
    match.actual_line = furthest[0][1]
    return furthest[0][0]


def check_matcher():
    """The normalisation itself, so that the test cannot pass by matching anything."""
    lines = lambda *ts: [(i, s) for i, s in enumerate(ts)]
    cases = [
        (lines("a", "b"), ["a", "b"], None),
        (lines("a", "b"), ["a", "c"], 1),
        (lines("a"), ["a", "b"], 1),            # extra actual lines fail
        (lines("a", "b"), ["a"], 1),            # missing actual lines fail
        (lines("a", "...", "d"), ["a", "b", "c", "d"], None),
        (lines("a", "...", "d"), ["a", "d"], None),
        (lines("time: ... s"), ["time: 1.5 s"], None),
        (lines("time: ... s"), ["time: 1.5 ms"], 0),
        (lines("x [...] y"), ["x [1, 2] y  "], None),  # trailing spaces ignored
        (lines("a.b"), ["axb"], 0),             # no other pattern character
    ]
    for expected, actual, want in cases:
        got = match(expected, actual)
        assert got == want, (expected, actual, got, want)


def scratch_tree(source, build):
    root = tempfile.mkdtemp(prefix="doc_examples.")
    for name in os.listdir(source):
        if name.startswith("build") or name in (".git", "out"):
            continue
        os.symlink(os.path.join(source, name), os.path.join(root, name))
    os.symlink(os.path.abspath(build), os.path.join(root, "build"))
    return root


def run_file(source, build, path, python_dir):
    rel = os.path.relpath(path, source)
    found = examples(path)
    pyfound = python_blocks(path) if python_dir else []
    if not found and not pyfound:
        return 0, 0
    root = scratch_tree(source, build)
    env = dict(os.environ, LC_ALL="C.UTF-8", COLUMNS="100")
    failures = 0
    try:
        for start, steps in found:
            for n, command, expected in steps:
                where = f"{rel}:{start}: block at line {start}"
                if command is None:
                    print(f"FAIL {where}: line {n} is output before any `$ ` command")
                    failures += 1
                    break
                want_exit = 0
                if expected and re.fullmatch(r"\[exit \d+\]", expected[-1][1].strip()):
                    want_exit = int(expected[-1][1].strip()[6:-1])
                    expected = expected[:-1]
                t0 = time.monotonic()
                try:
                    p = subprocess.run(["bash", "-c", command], cwd=root, env=env,
                                       capture_output=True, text=True,
                                       timeout=COMMAND_TIMEOUT)
                    out, err, code = p.stdout, p.stderr, p.returncode
                except subprocess.TimeoutExpired:
                    out, err, code = "", f"(timed out after {COMMAND_TIMEOUT} s)", None
                seconds = time.monotonic() - t0
                actual = out.replace(root + "/", "").replace(root, ".").split("\n")
                if actual and actual[-1] == "":
                    actual.pop()
                bad = match(expected, actual)
                if bad is None and code == want_exit:
                    print(f"ok   {rel}:{n}  ({seconds:.1f} s)  $ {command}")
                    continue
                failures += 1
                print(f"FAIL {where}, command at line {n} ({seconds:.1f} s): $ {command}")
                if code != want_exit:
                    print(f"  exit code {code}, expected {want_exit}")
                if bad is not None:
                    j = match.actual_line
                    got = (f"actual line {j + 1}: {actual[j]}" if j < len(actual)
                           else "the actual output ended")
                    if bad < len(expected):
                        ln, text = expected[bad]
                        print(f"  first expected line not matched: {rel}:{ln}: {text}")
                        print(f"  against {got}")
                    else:
                        print(f"  the actual output has more lines than the example: {got}")
                print("  expected:")
                for _, text in expected:
                    print("    | " + text)
                print("  actual stdout:")
                for text in actual:
                    print("    | " + text)
                if err.strip():
                    print("  stderr:")
                    for text in err.rstrip("\n").split("\n")[-20:]:
                        print("    ! " + text)
                break  # the block's later commands may depend on this one
        for start, text in pyfound:
            if not run_python(rel, root, env, python_dir, build, start, text):
                failures += 1
    finally:
        shutil.rmtree(root, ignore_errors=True)
    return sum(len(s) for _, s in found) + len(pyfound), failures


def main(argv):
    python_dir = None
    for a in [a for a in argv if a.startswith("--python=")]:
        python_dir = os.path.abspath(a[len("--python="):])
        argv = [b for b in argv if b != a]
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    check_matcher()
    source, build = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    if python_dir is None:
        print("doc_examples: no --python: the `>>>` blocks are not run (module not built)")
    files = argv[3:] or [os.path.join(source, "README.md")] + sorted(
        os.path.join(source, "docs", f) for f in os.listdir(os.path.join(source, "docs"))
        if f.endswith(".md"))
    total = failed = 0
    for path in files:
        n, bad = run_file(source, build, os.path.abspath(path), python_dir)
        total, failed = total + n, failed + bad
    print(f"doc_examples: {total} command(s) and python block(s) in {len(files)} file(s),"
          f" {failed} failed")
    if total == 0:
        print("doc_examples: no example found: the documentation lost its examples?")
        return 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
