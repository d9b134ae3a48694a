#!/usr/bin/env python3
"""Compares two sheetform results folders bit for bit: every dataset of results.h5 and every
number of summary.json, except what describes the run rather than its results (wall time and
phase costs, the thread and rank counts, the build's version and hash, the resolved case text).

    scripts/compare_results.py RESULTS_A RESULTS_B

Exit 0 when they are the same bits, 1 (listing the first differences) when not. Used by the
parallel tests: a run at 1, 2 and 3 threads (or ranks) must give the same bits.
"""
import json
import pathlib
import sys

import h5py
import numpy as np

# summary.json keys that describe how the run went, not what it computed.
RUN_KEYS = ("wall", "seconds", "time_share", "per_element", "per_node", "version", "git_hash",
            "threads", "ranks")


def compare_h5(a, b, diffs):
    with h5py.File(a) as fa, h5py.File(b) as fb:
        def visit(name, obj):
            if not isinstance(obj, h5py.Dataset):
                return
            if name not in fb:
                diffs.append(f"results.h5 {name}: missing in {b}")
                return
            x, y = obj[()], fb[name][()]
            if obj.dtype.kind in "SOU" or isinstance(x, bytes):
                if "resolved" in name or "git_hash" in name or "version" in name:
                    return
                if not np.array_equal(np.asarray(x), np.asarray(y)):
                    diffs.append(f"results.h5 {name}")
                return
            x, y = np.asarray(x), np.asarray(y)
            if x.shape != y.shape or x.tobytes() != y.tobytes():
                diffs.append(f"results.h5 {name}")
        fa.visititems(visit)


def compare_json(x, y, path, diffs):
    if isinstance(x, dict):
        for k in x:
            if any(key in k for key in RUN_KEYS):
                continue
            if not isinstance(y, dict) or k not in y:
                diffs.append(f"summary.json {path}/{k}: missing")
                continue
            compare_json(x[k], y[k], f"{path}/{k}", diffs)
    elif isinstance(x, list):
        if not isinstance(y, list) or len(x) != len(y):
            diffs.append(f"summary.json {path}: lengths differ")
            return
        for i, (u, v) in enumerate(zip(x, y)):
            compare_json(u, v, f"{path}[{i}]", diffs)
    elif x != y and not (x != x and y != y):  # NaN equals NaN here
        diffs.append(f"summary.json {path}: {x!r} vs {y!r}")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    a, b = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    diffs = []
    for folder in (a, b):
        for name in ("results.h5", "summary.json"):
            if not (folder / name).exists():
                sys.exit(f"error: {folder / name} does not exist")
    compare_h5(a / "results.h5", b / "results.h5", diffs)
    compare_json(json.loads((a / "summary.json").read_text()),
                 json.loads((b / "summary.json").read_text()), "", diffs)
    if diffs:
        print(f"{a} and {b} differ ({len(diffs)}):")
        for d in diffs[:20]:
            print("  " + d)
        return 1
    print(f"{a} and {b}: the same bits")
    return 0


if __name__ == "__main__":
    sys.exit(main())
