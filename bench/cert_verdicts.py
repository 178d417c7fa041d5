#!/usr/bin/python3
"""cert_verdicts.py — the verdict, exit code and first line of check_cert on every
certificate under some directories, recorded or compared: a refactoring of the checker must
keep all three for the golden corpus, the tamper suite and the adversarial cases.

  cert_verdicts.py record CHECK_CERT OUT.tsv DIR...   one line per (file, options)
  cert_verdicts.py compare CHECK_CERT IN.tsv [--trusted-only]

Each file is checked on one thread and on two (CHECK_CERT_BATCH=3, many batch boundaries);
a work bomb (a name containing 'bomb') also with CHECK_CERT_WORK_BASE=20. compare re-runs
every recorded case (with --trusted-only added if asked) and prints each difference; it
exits 1 on any difference, 0 otherwise. The deliberate break that made it fail: a checker
without the test that P2's column weights are positive (the tamper case of a negative
weight then gave another first line, on 1 and on 2 threads: 2 cases differ).
"""
import os
import subprocess
import sys


def runs(path):
    yield "t1", ["--threads", "1"], {}
    yield "t2", ["--threads", "2"], {"CHECK_CERT_BATCH": "3"}
    if "bomb" in os.path.basename(path):
        yield "t1w20", ["--threads", "1"], {"CHECK_CERT_WORK_BASE": "20"}


def check(binary, path, args, env):
    r = subprocess.run([binary, "--quiet"] + args + [path], stdout=subprocess.PIPE,
                       stderr=subprocess.DEVNULL, env=dict(os.environ, **env))
    lines = r.stdout.decode(errors="replace").split("\n")
    return str(r.returncode), lines[0]


def main():
    mode, binary, table = sys.argv[1], sys.argv[2], sys.argv[3]
    if mode == "record":
        rows = []
        for top in sys.argv[4:]:
            for root, _, files in sorted(os.walk(top)):
                for f in sorted(files):
                    if not f.endswith(".cert"):
                        continue
                    path = os.path.abspath(os.path.join(root, f))
                    for tag, args, env in runs(path):
                        code, line = check(binary, path, args, env)
                        rows.append("\t".join((path, tag, code, line)))
        with open(table, "w") as out:
            out.write("\n".join(rows) + "\n")
        print("%d cases recorded in %s" % (len(rows), table))
        return 0
    extra = ["--trusted-only"] if "--trusted-only" in sys.argv[4:] else []
    differ = 0
    rows = [r.split("\t") for r in open(table).read().splitlines()]
    for path, tag, code, line in rows:
        args, env = next((a, e) for t, a, e in runs(path) if t == tag)
        got = check(binary, path, args + extra, env)
        if got != (code, line):
            differ += 1
            print("DIFF %s [%s]\n  was  %s %s\n  now  %s %s" % (path, tag, code, line, *got))
    print("%d cases, %d differ%s" % (len(rows), differ, " (--trusted-only)" if extra else ""))
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
