#!/usr/bin/python3
"""Plots the blank's elements in the forming limit diagram: major against minor true strain.

Usage:

    /usr/bin/python3 scripts/plot_forming_limit.py RESULTS_DIR [-o OUT_DIR] [--frame N] [--csv]

For every blank element of output frame N (default: the last; negative N counts from the end),
takes the major and minor true strains of the mid-surface, eps1 and eps2, from the frame's
result fields major_strain_mid and minor_strain_mid (docs/formability.md); with
--from-coordinates, or for results written before those fields existed, computes them from
/parts/blank/reference_coordinates and the frame's coordinates (scripts/forming_strains.py: a
triangle's exact constant deformation gradient, a quadrilateral's at its centre; the same
measure). Writes OUT_DIR/forming_limit.png (default OUT_DIR = RESULTS_DIR): one point per
element, coloured by its formability_zone when the frame has it, with the strain paths of
uniaxial tension (eps2 = -eps1/2), plane strain (eps2 = 0) and equi-biaxial stretching
(eps2 = eps1) for orientation.

Forming limit curve (FLC): the blank's material's `forming_limit_curve = [[minor, major], ...]`
in RESULTS_DIR/case.resolved.toml (true strains; the case's curve, or the Keeler-Brazier curve
the run used), drawn, and each element's FLC margin = the curve's major strain at the element's
eps2 minus eps1 (linear between the curve's points, constant beyond its end points), as the
flc_margin field: negative is above the curve (beyond the limit; drawn red). The script prints
how many elements are above, the least margin, and the count per zone.

With --csv, also writes OUT_DIR/forming_limit.csv: one row per element (cell order of the
results: quadrilaterals first, then triangles) with element, cell type, major, minor and, with
an FLC, the curve's major strain and the margin, and with the zone field the zone.

Strains are dimensionless (true strain, not per cent). Exit codes: 0 done; 2 a missing folder,
file, frame or dataset (the message names it). Needs h5py, numpy, matplotlib.
"""
import argparse
import csv
import os
import sys
import tomllib

import h5py
import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import forming_strains  # noqa: E402  (beside this script)


class InputProblem(Exception):
    """Bad input: a missing folder, file, frame or dataset. The message names it."""


# The formability result fields this script reads when a frame has them.
FORMABILITY_FIELDS = ("major_strain_mid", "minor_strain_mid", "formability_zone")
ZONES = ("safe", "insufficient stretching", "wrinkling tendency", "risk of cracks",
         "severe thinning", "cracks")
ZONE_COLOURS = ("tab:green", "tab:grey", "tab:purple", "gold", "tab:orange", "red")


def read_frame(h5_path, part, frame):
    """(frame key, time s, reference, current, quads, triangles, formability fields by name) of
    output frame `frame`."""
    if not os.path.isfile(h5_path):
        raise InputProblem(f"{h5_path}: no such file (not a sheetform results folder?)")
    with h5py.File(h5_path, "r") as f:
        frames_path = f"parts/{part}/frames"
        keys = sorted(f[frames_path]) if frames_path in f else []
        if not keys:
            raise InputProblem(f"{h5_path}: /{frames_path}: no output frames")
        if not -len(keys) <= frame < len(keys):
            raise InputProblem(f"{h5_path}: no frame {frame}: the file has frames 0 to "
                               f"{len(keys) - 1} (or -1 to -{len(keys)} from the end)")
        key = keys[frame]
        try:
            reference, quads, triangles = forming_strains.read_blank(f, part, key)  # its mesh
        except forming_strains.ResultsError as error:
            raise InputProblem(str(error)) from None
        group = f[f"{frames_path}/{key}"]
        if "coordinates" not in group:
            raise InputProblem(f"{h5_path}: /{frames_path}/{key}/coordinates: missing")
        current = group["coordinates"][:]
        time = float(group.attrs.get("time", np.nan))
        fields = {name: group[name][:].reshape(-1) for name in FORMABILITY_FIELDS if name in group}
    if current.shape != reference.shape:
        raise InputProblem(f"{h5_path}: /{frames_path}/{key}/coordinates has shape "
                           f"{current.shape}, the reference {reference.shape}")
    return key, time, reference, current, quads, triangles, fields


def read_flc(results_dir):
    """(title, material name, curve [[minor, major], ...] or None) from case.resolved.toml."""
    path = os.path.join(results_dir, "case.resolved.toml")
    if not os.path.isfile(path):
        print(f"plot_forming_limit: {path}: no such file: no forming limit curve",
              file=sys.stderr)
        return "", None, None
    with open(path, "rb") as f:
        case = tomllib.load(f)
    name = case.get("blank", {}).get("material")
    material = case.get("materials", {}).get(name)
    if material is None:
        raise InputProblem(f"{path}: blank.material '{name}' has no [materials.{name}] table")
    curve = material.get("forming_limit_curve")
    return case.get("title", ""), name, (np.asarray(curve, dtype=float) if curve else None)


def plot(major, minor, curve, margin, zone, title, out_path):
    fig, ax = plt.subplots(figsize=(7, 7))
    lo = min(0.0, float(np.min(minor)) if minor.size else 0.0)
    hi = max(0.02, float(np.max(major)) if major.size else 0.0)
    if curve is not None:
        lo = min(lo, float(curve[0, 0]))
        hi = max(hi, float(np.max(curve[:, 1])))
    span = 1.1 * max(hi, -lo, 1e-3)
    # Strain paths from the origin, for orientation.
    e = np.array([0.0, span])
    ax.plot(-e / 2.0, e, "--", color="grey", lw=1, label="uniaxial, eps2 = -eps1/2")
    ax.plot([0.0, 0.0], [0.0, span], ":", color="grey", lw=1, label="plane strain, eps2 = 0")
    ax.plot(e, e, "-.", color="grey", lw=1, label="equi-biaxial, eps2 = eps1")
    if zone is not None:
        for code, (name, colour) in enumerate(zip(ZONES, ZONE_COLOURS)):
            mine = zone == code
            if np.any(mine):
                ax.scatter(minor[mine], major[mine], s=8, color=colour,
                           label=f"{name} ({int(np.count_nonzero(mine))})")
    elif curve is None:
        ax.scatter(minor, major, s=8, color="tab:blue", label=f"elements ({major.size})")
    else:
        above = margin < 0.0
        ax.scatter(minor[~above], major[~above], s=8, color="tab:blue",
                   label=f"below the FLC ({int(np.count_nonzero(~above))})")
        ax.scatter(minor[above], major[above], s=10, color="red",
                   label=f"above the FLC ({int(np.count_nonzero(above))})")
    if curve is not None:
        # The curve as used: held constant beyond its end points.
        x = np.concatenate([[min(-span, curve[0, 0])], curve[:, 0], [max(span, curve[-1, 0])]])
        y = np.concatenate([[curve[0, 1]], curve[:, 1], [curve[-1, 1]]])
        ax.plot(x, y, "-", color="black", lw=2, label="forming limit curve")
    ax.set_xlim(-span, span)
    ax.set_ylim(min(-0.1 * span, float(np.min(major)) if major.size else 0.0), span)
    ax.set_xlabel("minor true strain eps2 (-)")
    ax.set_ylabel("major true strain eps1 (-)")
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small", loc="best")
    fig.tight_layout()
    fig.savefig(out_path, dpi=120)
    plt.close(fig)
    print(f"plot_forming_limit: wrote {out_path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results_dir", help="a sheetform results folder (holds results.h5)")
    parser.add_argument("-o", "--out-dir", help="where the image goes (default: RESULTS_DIR)")
    parser.add_argument("--frame", type=int, default=-1,
                        help="output frame index (default -1, the last; negative from the end)")
    parser.add_argument("--csv", action="store_true",
                        help="also write the strains per element to forming_limit.csv")
    parser.add_argument("--from-coordinates", action="store_true",
                        help="compute the strains from the node coordinates, not the frame's "
                             "major_strain_mid / minor_strain_mid fields")
    args = parser.parse_args()

    if not os.path.isdir(args.results_dir):
        raise InputProblem(f"{args.results_dir}: no such folder")
    h5_path = os.path.join(args.results_dir, "results.h5")
    key, time, reference, current, quads, triangles, fields = read_frame(h5_path, "blank",
                                                                         args.frame)
    from_fields = not args.from_coordinates and "major_strain_mid" in fields
    if from_fields:
        major, minor = fields["major_strain_mid"], fields["minor_strain_mid"]
    else:
        major, minor = forming_strains.element_strains(reference, current, quads, triangles)
    zone = fields.get("formability_zone")
    zone = None if zone is None else zone.astype(int)
    n_quads = 0 if quads is None else len(quads)
    case_title, material, curve = read_flc(args.results_dir)

    source = "the frame's fields" if from_fields else "the coordinates"
    print(f"plot_forming_limit: frame {int(key)} (t = {time * 1e3:.6g} ms), {major.size} "
          f"elements (strains from {source}): major strain {np.max(major):.4g} at most, minor "
          f"strain from {np.min(minor):.4g} to {np.max(minor):.4g}")
    if zone is not None:
        counts = ", ".join(f"{name} {int(np.count_nonzero(zone == code))}"
                           for code, name in enumerate(ZONES))
        print(f"plot_forming_limit: zones: {counts}")
    margin = flc_major = None
    if curve is None:
        print(f"plot_forming_limit: no forming_limit_curve for material '{material}': no margin")
    else:
        flc_major = forming_strains.flc_major(minor, curve)
        margin = flc_major - major
        worst = int(np.argmin(margin))
        print(f"plot_forming_limit: {int(np.count_nonzero(margin < 0.0))} of {major.size} "
              f"elements above the forming limit curve; least margin {margin[worst]:.6g} "
              f"(element {worst}, major {major[worst]:.6g} at minor {minor[worst]:.6g})")

    out_dir = args.out_dir or args.results_dir
    os.makedirs(out_dir, exist_ok=True)
    title = f"{case_title}\n" if case_title else ""
    title += f"forming limit diagram, frame {int(key)}, t = {time * 1e3:.4g} ms"
    plot(major, minor, curve, margin, zone, title, os.path.join(out_dir, "forming_limit.png"))
    if args.csv:
        path = os.path.join(out_dir, "forming_limit.csv")
        with open(path, "w", newline="") as f:
            writer = csv.writer(f, lineterminator="\n")
            header = ["element", "cell_type", "major_true_strain", "minor_true_strain"]
            if curve is not None:
                header += ["flc_major_true_strain", "flc_margin"]
            if zone is not None:
                header += ["formability_zone"]
            writer.writerow(header)
            for i in range(major.size):
                row = [i, "quad" if i < n_quads else "triangle", repr(float(major[i])),
                       repr(float(minor[i]))]
                if curve is not None:
                    row += [repr(float(flc_major[i])), repr(float(margin[i]))]
                if zone is not None:
                    row += [int(zone[i])]
                writer.writerow(row)
        print(f"plot_forming_limit: wrote {path}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except InputProblem as problem:
        print(f"plot_forming_limit: {problem}", file=sys.stderr)
        sys.exit(2)
