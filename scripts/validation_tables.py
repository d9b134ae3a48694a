#!/usr/bin/env python3
"""Tables and plots of the square-cup validation study (scripts/square_cup_study.sh).

    scripts/validation_tables.py STUDY_DIR [--img-dir DIR]

STUDY_DIR holds one results folder per run, named <blank element size>-<search> (e.g.
2.5-modified). Prints Markdown tables (draw-ins at 15 and 40 mm against the NUMISHEET'93
measured averages, forces and thinning, energy ratios, run times) and writes three plots to
--img-dir (default STUDY_DIR): square_cup_punch_force.png (punch force against stroke),
square_cup_draw_in.png (draw-ins against stroke, with the measured points) and
square_cup_diagonal_thinning.png (thinning along the diagonal at the end).
"""
import argparse
import json
import pathlib
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# NUMISHEET'93 aluminium square cup, measured averages (docs/references.md, grade A).
MEASURED = {15.0: {"DX": 5.3, "DD": 3.3}, 40.0: {"DX": 28.5, "DD": 15.0}}
T0 = 0.81  # mm, initial thickness


def load(run_dir):
    summary = json.loads((run_dir / "summary.json").read_text())
    f = h5py.File(run_dir / "results.h5", "r")
    history = {k: np.asarray(f["history"][k][:]) for k in f["history"]}
    blank = f["parts/blank"]
    cells = np.asarray(blank["connectivity"][:])
    reference = np.asarray(blank["reference_coordinates"][:])
    frames = blank["frames"]
    last = frames[sorted(frames)[-1]]
    thickness = np.asarray(last["thickness"][:, 0])
    f.close()
    return summary, history, cells, reference, thickness


def at_stroke(history, column, stroke):
    travel = history["punch_travel"]
    return float(np.interp(stroke, travel, history[column]))


def deviation(value, measured):
    return f"{100.0 * (value - measured) / measured:+.1f} %"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("study_dir")
    parser.add_argument("--img-dir", help="where the plots go (default: STUDY_DIR)")
    args = parser.parse_args()
    study = pathlib.Path(args.study_dir)
    img = pathlib.Path(args.img_dir) if args.img_dir else study
    img.mkdir(parents=True, exist_ok=True)
    runs = sorted((p for p in study.iterdir() if (p / "summary.json").is_file()),
                  key=lambda p: (-float(p.name.split("-")[0]), p.name.split("-")[1]))
    if not runs:
        print(f"validation_tables.py: {study}: no run folders with a summary.json", file=sys.stderr)
        return 2
    data = {run.name: load(run) for run in runs}

    print("### Draw-in against the measured averages (mm)\n")
    print("| blank mesh | search | DX 15 mm | DD 15 mm | DX 40 mm | DD 40 mm |")
    print("|---|---|---|---|---|---|")
    print("| measured | | 5.3 | 3.3 | 28.5 | 15.0 |")
    for name, (summary, history, *_rest) in data.items():
        size, search = name.split("-")
        cells = []
        for stroke in (15.0, 40.0):
            for point in ("DX", "DD"):
                value = at_stroke(history, f"draw_in_{point}", stroke)
                cells.append(f"{value:.2f} ({deviation(value, MEASURED[stroke][point])})")
        print(f"| {size} mm | {search} | " + " | ".join(cells) + " |")

    print("\n### Punch force, thinning, energies\n")
    print("| blank mesh | search | peak punch force (quarter) | min thickness | max thinning | max plastic strain "
          "| kinetic/internal end (peak) | hourglass/internal | friction/external work | energy balance |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name, (s, history, cells, reference, thickness) in data.items():
        size, search = name.split("-")
        e = s["energy_Nmm"]
        print(f"| {size} mm | {search} | {s['tools']['punch']['peak_force_N'] / 1000:.2f} kN "
              f"| {s['min_thickness_mm']:.3f} mm | {100 * (1 - s['min_thickness_mm'] / T0):.1f} % "
              f"| {s['max_plastic_strain']:.3f} | {100 * s['kinetic_ratio_end']:.2f} % ({100 * s['kinetic_ratio_peak']:.1f} %) "
              f"| {100 * e['hourglass'] / e['internal']:.2f} % | {100 * e['friction_work'] / e['external_work']:.1f} % "
              f"| {e['balance_error']:.1e} |")

    print("\n### Run time (one core of the reference machine)\n")
    print("| blank mesh | search | elements | cycles | wall time | ns per element-cycle | contact share |")
    print("|---|---|---|---|---|---|---|")
    for name, (s, *_rest) in data.items():
        size, search = name.split("-")
        print(f"| {size} mm | {search} | {s['elements']} | {s['cycles']} | {s['wall_seconds']:.0f} s "
              f"| {s['ns_per_element_cycle']:.0f} | {100 * s['contact_time_share']:.0f} % |")

    # Punch force against stroke.
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for name, (s, history, *_rest) in data.items():
        ax.plot(history["punch_travel"], history["punch_force"] / 1000.0, label=name.replace("-", " mm, "))
    ax.set_xlabel("punch travel (mm)")
    ax.set_ylabel("punch force, quarter model (kN)")
    ax.set_title("Square cup, aluminium: punch force")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(img / "square_cup_punch_force.png", dpi=110)
    plt.close(fig)

    # Draw-in against stroke with the measured points.
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for name, (s, history, *_rest) in data.items():
        for point, style in (("DX", "-"), ("DD", "--")):
            ax.plot(history["punch_travel"], history[f"draw_in_{point}"], style,
                    label=f"{point}, {name.replace('-', ' mm, ')}")
    for stroke, values in MEASURED.items():
        ax.plot([stroke], [values["DX"]], "ko")
        ax.plot([stroke], [values["DD"]], "ks", mfc="none")
    ax.plot([], [], "ko", label="DX measured (NUMISHEET'93)")
    ax.plot([], [], "ks", mfc="none", label="DD measured")
    ax.set_xlabel("punch travel (mm)")
    ax.set_ylabel("draw-in (mm)")
    ax.set_title("Square cup, aluminium: draw-in")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(img / "square_cup_draw_in.png", dpi=110)
    plt.close(fig)

    # Thinning along the diagonal (cells whose reference centre lies on x = y), at the end.
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for name, (s, history, cells, reference, thickness) in data.items():
        centres = reference[cells].mean(axis=1)
        size = float(name.split("-")[0])
        on_diagonal = np.abs(centres[:, 0] - centres[:, 1]) < 0.25 * size
        distance = np.sqrt(2.0) * centres[on_diagonal, 0]
        order = np.argsort(distance)
        thinning = 100.0 * (1.0 - thickness[on_diagonal] / T0)
        ax.plot(distance[order], thinning[order], ".-", label=name.replace("-", " mm, "))
    ax.set_xlabel("distance from the cup's centre along the diagonal, initial position (mm)")
    ax.set_ylabel("thinning 100 (1 - t / t0) (%)")
    ax.set_title("Square cup, aluminium: thinning along the diagonal at the end")
    ax.axhline(0.0, color="k", lw=0.5)
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(img / "square_cup_diagonal_thinning.png", dpi=110)
    plt.close(fig)
    print(f"\nplots: {img}/square_cup_punch_force.png, square_cup_draw_in.png, square_cup_diagonal_thinning.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
