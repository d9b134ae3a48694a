#!/usr/bin/env python3
"""Checks that a case's checked-in STEP files are what its gmsh scripts make (ctest
case_step_files, label case).

A case folder whose tools come from CAD keeps the STEP files and the script that writes them,
`make_step.sh` (cases/rectangular_cup_cad). This runs that script into a scratch folder with the
given gmsh and compares each file it writes with the case's file of the same name, line by line,
all but the time stamp in the header's FILE_NAME entry (OpenCASCADE writes the time of writing
there). A changed script, a hand-edited STEP file or another gmsh/OpenCASCADE version shows as a
difference; the case's STEP files are rewritten with `CASE_DIR/make_step.sh`.

    scripts/check_case_step.py [--gmsh PATH] CASE_DIR...

Exit status 0 when every file matches, 1 when one differs or is missing, 2 for bad usage or a
make_step.sh that fails.
"""
import argparse
import difflib
import os
import re
import subprocess
import sys
import tempfile

# The time stamp in FILE_NAME('name','2026-11-26T19:18:05',...), the header's only varying field.
TIME_STAMP = re.compile(r"'\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d'")


def normalised(path):
    """The file's lines, the header's time stamp replaced by a fixed text."""
    with open(path, encoding="utf-8", errors="replace") as f:
        lines = f.read().splitlines()
    out, in_header = [], False
    for line in lines:
        if line.startswith("HEADER;"):
            in_header = True
        elif line.startswith("ENDSEC;"):
            in_header = False
        out.append(TIME_STAMP.sub("'<time stamp>'", line) if in_header else line)
    return out


def check_case(case_dir, gmsh):
    script = os.path.join(case_dir, "make_step.sh")
    if not os.access(script, os.X_OK):
        print(f"{case_dir}: no executable make_step.sh", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as scratch:
        run = subprocess.run([script, "--gmsh", gmsh, "--out", scratch], capture_output=True,
                             text=True)
        if run.returncode != 0:
            print(run.stdout + run.stderr, file=sys.stderr)
            print(f"{script} failed (exit status {run.returncode})", file=sys.stderr)
            return 2
        written = sorted(name for name in os.listdir(scratch) if name.lower().endswith(".step"))
        if not written:
            print(f"{script} wrote no .step file", file=sys.stderr)
            return 2
        status = 0
        for name in written:
            target = os.path.join(case_dir, name)
            if not os.path.isfile(target):
                print(f"missing: {target} (run {script})")
                status = 1
                continue
            new, old = normalised(os.path.join(scratch, name)), normalised(target)
            if new == old:
                print(f"ok     {target} ({len(old)} lines, the same but the header's time stamp)")
            else:
                diff = list(difflib.unified_diff(old, new, target, "made now", n=1, lineterm=""))
                print(f"stale: {target} differs from what {script} makes now "
                      f"({len(diff)} diff lines; run {script}):")
                print("\n".join(diff[:20]))
                status = 1
        return status


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--gmsh", default="gmsh", help="the gmsh executable (default: gmsh)")
    parser.add_argument("cases", nargs="+", metavar="CASE_DIR")
    args = parser.parse_args()
    status = 0
    for case_dir in args.cases:
        status = max(status, check_case(case_dir, args.gmsh))
    return status


if __name__ == "__main__":
    sys.exit(main())
