"""Chain equivalence on the NUMISHEET'93 aluminium square cup (issue 32, item 2).

Run: /usr/bin/python3 tests/chain/chain_equivalence.py SHEETFORM OUT STROKE
     (ctest: chain_equivalence_short at 2 mm; chain_equivalence_40mm, label slow, at 40 mm)

Draws the cup (friction 0.162 on every tool, force-controlled holder) to STROKE three ways with the
`sheetform` command:
  one     one run to STROKE;
  ops     one case of two operations, to STROKE / 2 and then on to STROKE;
  chained a run to STROKE / 2 ending at a whole step (control.land_on_end = false), then a second
          case started from its formed part (blank.formed_part) to STROKE.
and checks that the three formed parts (formed_part.h5: every handed-on field of the state, the
contact pairs' stick forces and the force-controlled holder's velocity included) agree bit for
bit.
"""
import os
import subprocess
import sys

import h5py
import numpy as np

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
CASE = os.path.join(ROOT, "cases", "square_cup_aluminium", "case.toml")


def run(sheetform, out, *options):
    command = [sheetform, "run", CASE, "-o", out, "--overwrite", "-q", *options]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return os.path.join(out, "formed_part.h5")


def state_fields(path):
    """Every /state dataset of a formed part, by its path."""
    out = {}
    with h5py.File(path, "r") as f:
        f["state"].visititems(
            lambda name, item: out.__setitem__(name, item[()])
            if isinstance(item, h5py.Dataset) else None)
    return out


def main():
    sheetform, folder, stroke = sys.argv[1], sys.argv[2], float(sys.argv[3])
    half = stroke / 2
    one = run(sheetform, os.path.join(folder, "one"), "--stroke", str(stroke))
    ops = run(sheetform, os.path.join(folder, "ops"), "--set", "control.stroke=0", "--set",
              f'operations=[{{name="draw-1", kind="forming", stroke={half}}}, '
              f'{{name="draw-2", kind="forming", stroke={stroke}}}]')
    first = run(sheetform, os.path.join(folder, "first"), "--stroke", str(half), "--set",
                "control.land_on_end=false")
    chained = run(sheetform, os.path.join(folder, "second"), "--stroke", str(stroke), "--set",
                  f'blank.formed_part="{os.path.abspath(first)}"')
    reference = state_fields(one)
    failures = 0
    for label, path in (("two operations in one case", ops), ("two cases", chained)):
        other = state_fields(path)
        if sorted(other) != sorted(reference):
            print(f"{label}: other fields ({sorted(set(other) ^ set(reference))})")
            failures += 1
            continue
        differ = [k for k in reference
                  if reference[k].dtype != other[k].dtype or reference[k].shape != other[k].shape
                  or reference[k].tobytes() != other[k].tobytes()]
        for k in differ:
            a, b = np.asarray(reference[k], float), np.asarray(other[k], float)
            print(f"{label}: {k} differs, largest |difference| {np.max(np.abs(a - b)):.3e}")
        print(f"{label}: {len(reference) - len(differ)} of {len(reference)} fields bit for bit "
              f"at {stroke:g} mm")
        failures += len(differ)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
