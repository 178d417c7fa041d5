"""Executes examples/five_bar_tour.ipynb with nbconvert (Debian's jupyter-nbconvert and the
python3 kernel of python3-ipykernel, on README.md's install line) and checks what it
printed and showed: no cell failed, the certificate VERIFIED with the bound 8, the grid's
outcomes, a path found, two figures.

Usage: check_notebook.py NOTEBOOK OUTPUT_DIR (PYTHONPATH on the build's package).
Exit 0 when every check holds; a missing nbconvert or kernel fails (not skipped).
"""
import json
import os
import re
import subprocess
import sys


def main(notebook, out_dir):
    os.makedirs(out_dir, exist_ok=True)
    run = subprocess.run([sys.executable, "-m", "nbconvert", "--to", "notebook", "--execute",
                          "--ExecutePreprocessor.timeout=300", "--output-dir", out_dir,
                          notebook], capture_output=True, text=True)
    if run.returncode != 0:
        print(f"FAIL: nbconvert exited {run.returncode}:\n{run.stderr}", file=sys.stderr)
        return 1
    with open(os.path.join(out_dir, os.path.basename(notebook))) as f:
        nb = json.load(f)
    text, images, errors = "", 0, []
    for cell in nb["cells"]:
        for o in cell.get("outputs", []):
            if o["output_type"] == "stream":
                text += "".join(o["text"])
            elif o["output_type"] == "error":
                errors.append(f"{o['ename']}: {o['evalue']}")
            elif "image/png" in o.get("data", {}):
                images += 1
    problems = [f"a cell raised {e}" for e in errors]
    for pattern in (r"^aspects \d+\.\d+\.\d+$",
                    r"^certified lower bound on the number of aspects: 8$",
                    r"^check_cert: VERIFIED - checked lower bound 8$",
                    r"^answered in CSNCs \(1, 3, 5, 9\)$",
                    r"^986 poses: \{'answered': 174, 'outside_workspace': 717, "
                    r"'undecided_region': 95\}$",
                    r"^path: found - \d+ waypoints, length "):
        if not re.search(pattern, text, re.M):
            problems.append(f"no output line matches /{pattern}/")
    if images != 2:
        problems.append(f"{images} PNG images shown, expected 2")
    for p in problems:
        print("FAIL:", p, file=sys.stderr)
    if problems:
        print("---- the notebook printed:\n" + text, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
