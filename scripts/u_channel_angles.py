#!/usr/bin/env python3
"""The U-channel's springback angles taken apart (docs/validation.md, "Is theta2 above 90 deg the
measure, the model or real?"): from a run of cases/u_channel_* with springback, the section's
bottom, wall and flange (the ranges of the case's [springback.u_channel]) at the formed state
and after springback, and

- theta1, theta2 as sheetform measures them (docs/springback-measures.md: the wall's chord);
- the same angles with the wall's end tangents instead of its chord (a line through the wall's
  `--end-nodes` nodes nearest each end): theta1_t at the bottom corner, theta2_t at the flange;
- the rotations, after springback, of the bottom line, the wall chord, the wall's two end tangents
  and the flange line, in the x-z plane (deg, counter-clockwise about +y seen with x right, z up).

    scripts/u_channel_angles.py RESULTS_DIR [--end-nodes N]
"""
import argparse
import pathlib
import tomllib

import h5py
import numpy as np


def unit(v):
    return v / np.linalg.norm(v)


def line_direction(points):
    """Principal axis of the points' scatter (orthogonal regression), unit."""
    centred = points - points.mean(axis=0)
    return unit(np.linalg.svd(centred, full_matrices=False)[2][0])


def angle(u, v):
    return np.degrees(np.arctan2(abs(u[0] * v[1] - u[1] * v[0]), u @ v))


def heading(v):
    return np.degrees(np.arctan2(v[1], v[0]))


def measures(xz, formed, regions, end_nodes):
    bottom, wall, flange = regions
    wall = wall[np.argsort(formed[wall, 1])]  # by formed z, from the bottom's end
    if abs(formed[wall[0], 1] - formed[bottom].mean(axis=0)[1]) > abs(
            formed[wall[-1], 1] - formed[bottom].mean(axis=0)[1]):
        wall = wall[::-1]
    def oriented(d, towards):
        return d if d @ towards > 0 else -d
    b = oriented(line_direction(xz[bottom]), xz[bottom].mean(axis=0) - xz[wall[0]])
    f = oriented(line_direction(xz[flange]), xz[flange].mean(axis=0) - xz[wall[-1]])
    chord = unit(xz[wall[-1]] - xz[wall[0]])
    low = oriented(line_direction(xz[wall[:end_nodes]]), chord)
    high = oriented(line_direction(xz[wall[-end_nodes:]]), chord)
    return {
        "theta1 (chord)": angle(b, chord), "theta2 (chord)": angle(chord, f),
        "theta1_t (bottom-end tangent)": angle(b, low), "theta2_t (flange-end tangent)": angle(high, f),
        "heading bottom_back": heading(b), "heading chord": heading(chord),
        "heading wall tangent, bottom end": heading(low), "heading wall tangent, flange end": heading(high),
        "heading flange_out": heading(f),
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results", type=pathlib.Path)
    parser.add_argument("--end-nodes", type=int, default=5)
    args = parser.parse_args()
    case = tomllib.loads((args.results / "case.resolved.toml").read_text())["springback"]["u_channel"]
    with h5py.File(args.results / "results.h5", "r") as h5:
        blank = h5["parts/blank"]
        frames = blank["frames"]
        keys = sorted(frames.keys())
        springback = [k for k in keys if np.abs(frames[k]["springback_displacement"][:]).max() > 0.0]
        formed_key = keys[keys.index(springback[0]) - 1]
        # the mesh of the formed frame (after a trim: the trimmed mesh, docs/results-format.md)
        topology = frames[formed_key].attrs.get("topology")
        mesh = blank if topology is None else blank["topologies"][str(int(topology))]
        ref = mesh["reference_coordinates"][:]
        formed3 = frames[formed_key]["coordinates"][:]
        final3 = frames[keys[-1]]["coordinates"][:]
    section = np.flatnonzero(np.abs(ref[:, 1]) < 1e-9)
    formed, final = formed3[section][:, [0, 2]], final3[section][:, [0, 2]]
    x, z = formed[:, 0], formed[:, 1]
    def within(v, r):
        return np.flatnonzero((v >= r[0]) & (v <= r[1]))
    regions = (within(x, case["bottom"]), within(z, case["wall"]), within(x, case["flange"]))
    a = measures(formed, formed, regions, args.end_nodes)
    s = measures(final, formed, regions, args.end_nodes)
    print(f"{len(section)} section nodes: bottom {len(regions[0])}, wall {len(regions[1])}, flange {len(regions[2])}")
    print(f"{'':36s} {'formed':>9s} {'sprung':>9s} {'change':>9s}")
    for k in a:
        print(f"{k:36s} {a[k]:9.2f} {s[k]:9.2f} {s[k] - a[k]:+9.2f}")


if __name__ == "__main__":
    main()
