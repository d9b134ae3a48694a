#!/usr/bin/env python3
"""The square cup's sensitivity table (scripts/square_cup_sensitivity.sh): DX and DD at 15 and
40 mm of punch travel for each run folder under WORK, with the change from the folder `base` and
the deviation from the NUMISHEET'93 measured averages (docs/references.md).

    scripts/sensitivity_table.py WORK [RUN ...]      (default: every folder under WORK)
"""
import pathlib
import sys

import h5py
import numpy as np

MEASURED = {("DX", 15.0): 5.3, ("DD", 15.0): 3.3, ("DX", 40.0): 28.5, ("DD", 40.0): 15.0}


def draw_ins(run_dir):
    if not (run_dir / "results.h5").is_file():
        print(f"sensitivity_table.py: {run_dir / 'results.h5'}: no such file (has the run been made?)",
              file=sys.stderr)
        raise SystemExit(2)
    with h5py.File(run_dir / "results.h5", "r") as f:
        travel = np.asarray(f["history"]["punch_travel"][:])
        values = {}
        for point, stroke in MEASURED:
            column = np.asarray(f["history"][f"draw_in_{point}"][:])
            if travel[-1] < stroke - 1e-6:
                print(f"sensitivity_table.py: {run_dir}: the run stopped at {travel[-1]:.2f} mm, short of "
                      f"{stroke} mm", file=sys.stderr)
                raise SystemExit(2)
            values[(point, stroke)] = float(np.interp(stroke, travel, column))
        return values


def main():
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    work = pathlib.Path(sys.argv[1])
    names = sys.argv[2:] or sorted(p.name for p in work.iterdir() if (p / "results.h5").exists())
    data = {name: draw_ins(work / name) for name in names}
    base = data.get("base")
    keys = list(MEASURED)
    print("| run | " + " | ".join(f"{p} at {s:g} mm" for p, s in keys) + " |")
    print("|---|" + "---|" * len(keys))
    measured = " | ".join(f"{MEASURED[k]:.2f}" for k in keys)
    print(f"| measured (NUMISHEET'93 averages) | {measured} |")
    for name, values in data.items():
        cells = []
        for k in keys:
            dev = 100.0 * (values[k] - MEASURED[k]) / MEASURED[k]
            cell = f"{values[k]:.2f} ({dev:+.1f} %)"
            if base is not None and name != "base":
                cell += f", {values[k] - base[k]:+.2f}"
            cells.append(cell)
        print(f"| {name} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
