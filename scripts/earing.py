#!/usr/bin/env python3
"""The ears of a drawn cup from a quarter model's results (cases/cylindrical_cup_aa2090): the rim's
radius against the angle from the rolling direction (x) at the last frame, mirrored onto 0-360
degrees by the model's symmetry planes x = 0 and y = 0, and the ears: the rim's local maxima of
radius (in the flange, an ear is where the rim drew in least; in a drawn-through cup, where the
wall is tallest), each standing above both neighbouring valleys by more than `--prominence`.

    scripts/earing.py RESULTS_DIR [--prominence MM] [--frame N]

Prints one line per ear (angle, rim radius), the valleys, the earing height (largest minus
smallest rim radius) and the profile every 2.5 degrees of a quarter.
"""
import argparse
import pathlib

import h5py
import numpy as np


def rim_profile(results, frame=None):
    """Angles (deg, 0-90) and current rim radii (mm) of the rim nodes, sorted by angle."""
    with h5py.File(results, "r") as f:
        blank = f["parts/blank"]
        reference = blank["reference_coordinates"][:]
        frames = sorted(blank["frames"].keys())
        key = frames[-1] if frame is None else f"{frame:06d}"
        current = blank["frames"][key]["coordinates"][:]
    r0 = np.hypot(reference[:, 0], reference[:, 1])
    rim = np.flatnonzero(r0 > r0.max() - 1e-6 * r0.max())
    angle = np.degrees(np.arctan2(reference[rim, 1], reference[rim, 0]))
    radius = np.hypot(current[rim, 0], current[rim, 1])
    order = np.argsort(angle)
    return angle[order], radius[order]


def full_circle(angle, radius):
    """The quarter's profile mirrored about y = 0 and x = 0: angles in [0, 360)."""
    a = np.concatenate([angle, 180.0 - angle, 180.0 + angle, 360.0 - angle]) % 360.0
    r = np.concatenate([radius] * 4)
    a, unique = np.unique(np.round(a, 9), return_index=True)
    return a, r[unique]


def extrema(angle, radius, prominence):
    """Ears (local maxima) and valleys of a periodic profile whose ears stand out by more than
    `prominence` (mm) above the lowest point between them and each neighbouring ear."""
    n = len(radius)
    peaks = [i for i in range(n) if radius[i] >= radius[i - 1] and radius[i] > radius[(i + 1) % n]]
    valleys = [i for i in range(n) if radius[i] <= radius[i - 1] and radius[i] < radius[(i + 1) % n]]
    # Drop the least prominent peak until every peak clears the threshold.
    while len(peaks) > 1:
        def lowest_between(i, j):
            idx = np.arange(i, j + (n if j <= i else 0) + 1) % n
            return radius[idx].min()

        prom = []
        for k, p in enumerate(peaks):
            left = lowest_between(peaks[k - 1], p)
            right = lowest_between(p, peaks[(k + 1) % len(peaks)])
            prom.append(radius[p] - max(left, right))
        worst = int(np.argmin(prom))
        if prom[worst] > prominence:
            break
        peaks.pop(worst)
    kept_valleys = []
    for k, p in enumerate(peaks):
        q = peaks[(k + 1) % len(peaks)]
        idx = np.arange(p, q + (n if q <= p else 0) + 1) % n
        kept_valleys.append(int(idx[np.argmin(radius[idx])]))
    return [angle[i] for i in peaks], [angle[i] for i in sorted(set(kept_valleys))]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results", type=pathlib.Path, help="a run's results folder (or its results.h5)")
    parser.add_argument("--prominence", type=float, default=0.05, help="mm an ear must stand out (0.05)")
    parser.add_argument("--frame", type=int, default=None, help="frame number (default: the last)")
    args = parser.parse_args()
    path = args.results / "results.h5" if args.results.is_dir() else args.results
    angle, radius = rim_profile(path, args.frame)
    a, r = full_circle(angle, radius)
    ears, valleys = extrema(a, r, args.prominence)
    print(f"rim: {len(angle)} nodes on the quarter; radius {r.min():.3f} to {r.max():.3f} mm, "
          f"earing height {r.max() - r.min():.3f} mm")
    print(f"ears: {len(ears)} at " + ", ".join(f"{e:.1f}" for e in ears) + " deg from the rolling direction")
    print("valleys at " + ", ".join(f"{v:.1f}" for v in valleys) + " deg")
    print("quarter profile (deg: rim radius mm):")
    print("  " + "  ".join(f"{x:.1f}: {y:.3f}" for x, y in zip(angle, radius)))


if __name__ == "__main__":
    main()
