#!/usr/bin/python3
"""Plots a sheetform run's history: tool force against travel, the energies, the draw-in.

Usage:

    /usr/bin/python3 scripts/plot_history.py RESULTS_DIR [-o OUT_DIR] [--tool NAME] [--csv]
                                             [--group NAME ...]

Reads the /history columns of RESULTS_DIR/results.h5 (docs/results-format.md) and writes, in
OUT_DIR (default RESULTS_DIR):

- `<tool>_force.png` (`punch_force.png` for the bundled cases): the force of the blank on the
  tool, `<tool>_force`, in kN against the tool's travel `<tool>_travel` in mm. The tool is the
  case's `[control] stroke_tool` from RESULTS_DIR/case.resolved.toml unless --tool is given.
- `energies.png`: kinetic, internal, hourglass and contact energy, friction work and external
  work in N mm (= mJ) against time in ms; below, the ratio kinetic / internal energy (-).
- `draw_in.png`, only when the history has columns `draw_in_<name>`: each draw-in in mm against
  the same tool's travel in mm.

- `group_<name>.png` for each `--group NAME` (a `[[history]]` group of the case): one panel per
  quantity the history holds for it (displacement, velocity, rotation, reaction force, reaction
  moment), its x, y and z components against time, in the units of the columns' `unit`
  attributes. A case without a moving tool (a static analysis) then needs no --tool: the force and
  draw-in plots are left out.

With --csv, the plotted series also go to `<tool>_force.csv`, `energies.csv` and `draw_in.csv`
beside the images (one row per history row, full double precision, units in the headers).

Units: the case's; the conversions (N -> kN, s -> ms) assume the forming cases' system
mm-s-tonne-N-MPa, and a warning is printed when the resolved case names another.

Exit codes: 0 done; 2 a missing folder, file or history column (the message names it).
Needs h5py, numpy and matplotlib (Debian: python3-h5py python3-numpy python3-matplotlib).
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

EXPECTED_UNITS = "mm-s-tonne-N-MPa"

# (history column, legend label) of the energies plot, all in N mm.
ENERGIES = [
    ("kinetic_energy", "kinetic"),
    ("internal_energy", "internal"),
    ("hourglass_energy", "hourglass"),
    ("contact_energy", "contact"),
    ("friction_work", "friction work"),
    ("external_work", "external work"),
]


# {results.h5 path: {column: unit}}, filled by read_history.
UNITS = {}

# The quantities of a [[history]] group: (column stem after "<group>_", panel title).
GROUP_QUANTITIES = [
    ("displacement", "mean displacement"),
    ("velocity", "mean velocity"),
    ("rotation", "mean rotation"),
    ("reaction_force", "reaction force (sum)"),
    ("reaction_moment", "reaction moment (sum)"),
]


class InputProblem(Exception):
    """Bad input: a missing folder, file or column. The message names it."""


def read_history(path):
    """{column: array} of results.h5's /history, in the file's column order; each array's unit
    (the dataset's `unit` attribute, when the file has it) is in UNITS[path][column]."""
    if not os.path.isfile(path):
        raise InputProblem(f"{path}: no such file (not a sheetform results folder?)")
    with h5py.File(path, "r") as f:
        if "history" not in f:
            raise InputProblem(f"{path}: no /history group")
        group = f["history"]
        names = group.attrs.get("columns")
        if names is None:
            raise InputProblem(f"{path}: /history has no 'columns' attribute")
        if isinstance(names, bytes):
            names = names.decode()
        history = {}
        for name in str(names).split(","):
            if name not in group:
                raise InputProblem(f"{path}: /history/{name} is listed in 'columns' but missing")
            history[name] = group[name][:].astype(float)
            unit = group[name].attrs.get("unit")
            if unit is not None:
                UNITS.setdefault(path, {})[name] = unit.decode() if isinstance(unit, bytes) \
                    else str(unit)
    return history


def column(history, name, path):
    """A history column, or InputProblem naming it and the file."""
    if name not in history:
        raise InputProblem(f"{path}: /history has no column '{name}' "
                           f"(columns: {', '.join(history)})")
    return history[name]


def read_resolved_case(results_dir):
    """The parsed case.resolved.toml, or None when the folder has none."""
    path = os.path.join(results_dir, "case.resolved.toml")
    if not os.path.isfile(path):
        return None
    with open(path, "rb") as f:
        return tomllib.load(f)


def choose_tool(case, results_dir, given):
    if given:
        return given
    path = os.path.join(results_dir, "case.resolved.toml")
    if case is None:
        raise InputProblem(f"{path}: no such file; give the tool with --tool NAME")
    tool = case.get("control", {}).get("stroke_tool")
    if not tool:
        raise InputProblem(f"{path}: control.stroke_tool is not set (no tool moves); give the "
                           f"tool with --tool NAME")
    return tool


def write_csv(path, header, columns):
    with open(path, "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(header)
        for row in zip(*columns):
            writer.writerow([repr(float(v)) for v in row])
    print(f"plot_history: wrote {path}")


def save(fig, path):
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print(f"plot_history: wrote {path}")


def plot_force(history, h5_path, tool, title, out_dir, with_csv):
    time_ms = column(history, "time", h5_path) * 1e3
    travel = column(history, f"{tool}_travel", h5_path)
    force_kn = column(history, f"{tool}_force", h5_path) * 1e-3
    fig, ax = plt.subplots(figsize=(8, 5))
    ax.plot(travel, force_kn, "-", color="tab:blue")
    ax.set_xlabel(f"{tool} travel (mm)")
    ax.set_ylabel(f"{tool} force (kN)")
    ax.set_title(f"{title}\n{tool}: force of the blank against travel" if title else
                 f"{tool}: force of the blank against travel")
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    save(fig, os.path.join(out_dir, f"{tool}_force.png"))
    if with_csv:
        write_csv(os.path.join(out_dir, f"{tool}_force.csv"),
                  ["time_ms", f"{tool}_travel_mm", f"{tool}_force_kN"], [time_ms, travel, force_kn])


def plot_energies(history, h5_path, title, out_dir, with_csv):
    time_ms = column(history, "time", h5_path) * 1e3
    series = [(label, column(history, name, h5_path)) for name, label in ENERGIES]
    kinetic = column(history, "kinetic_energy", h5_path)
    internal = column(history, "internal_energy", h5_path)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(internal > 0.0, kinetic / internal, np.nan)

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), sharex=True,
                                      gridspec_kw={"height_ratios": [3, 1.3]})
    for label, values in series:
        top.plot(time_ms, values, label=label)
    top.set_ylabel("energy, work (N mm)")
    top.set_title(f"{title}\nenergies" if title else "energies")
    top.legend(fontsize="small")
    top.grid(True, alpha=0.3)
    bottom.plot(time_ms, ratio, color="black")
    bottom.set_ylabel("kinetic / internal (-)")
    bottom.set_xlabel("time (ms)")
    if np.any(ratio > 0.0):
        bottom.set_yscale("log")
    bottom.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    save(fig, os.path.join(out_dir, "energies.png"))
    if with_csv:
        names = [name.replace(" ", "_") for _, name in ENERGIES]
        write_csv(os.path.join(out_dir, "energies.csv"),
                  ["time_ms"] + [f"{n}_Nmm" for n in names] + ["kinetic_over_internal"],
                  [time_ms] + [v for _, v in series] + [ratio])


def plot_draw_in(history, h5_path, tool, title, out_dir, with_csv):
    """draw_in.png when the history has draw_in_<name> columns; returns whether it did."""
    names = [c for c in history if c.startswith("draw_in_")]
    if not names:
        return False
    travel = column(history, f"{tool}_travel", h5_path)
    fig, ax = plt.subplots(figsize=(8, 5))
    for name in names:
        ax.plot(travel, history[name], label=name[len("draw_in_"):])
    ax.set_xlabel(f"{tool} travel (mm)")
    ax.set_ylabel("draw-in (mm)")
    ax.set_title(f"{title}\ndraw-in" if title else "draw-in")
    ax.legend()
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    save(fig, os.path.join(out_dir, "draw_in.png"))
    if with_csv:
        write_csv(os.path.join(out_dir, "draw_in.csv"),
                  [f"{tool}_travel_mm"] + [f"{n}_mm" for n in names],
                  [travel] + [history[n] for n in names])
    return True


def plot_group(history, h5_path, group, title, out_dir, with_csv):
    """group_<group>.png: every quantity the history holds for the [[history]] group."""
    time = column(history, "time", h5_path)
    panels = [(stem, label) for stem, label in GROUP_QUANTITIES
              if f"{group}_{stem}_x" in history]
    if not panels:
        raise InputProblem(f"{h5_path}: /history has no columns of group '{group}' (a [[history]] "
                           f"group of the case: <group>_displacement_x, ...)")
    units = UNITS.get(h5_path, {})
    time_unit = units.get("time", "s")
    fig, axes = plt.subplots(len(panels), 1, figsize=(8, 2.6 * len(panels) + 0.8), sharex=True,
                             squeeze=False)
    header, series = [f"time_{time_unit}"], [time]
    for ax, (stem, label) in zip(axes[:, 0], panels):
        unit = units.get(f"{group}_{stem}_x", "")
        for axis in "xyz":
            name = f"{group}_{stem}_{axis}"
            ax.plot(time, history[name], label=axis)
            header.append(f"{name}_{unit.replace(' ', '').replace('/', '_per_')}" if unit
                          else name)
            series.append(history[name])
        ax.set_ylabel(f"{label}" + (f" ({unit})" if unit else ""))
        ax.legend(fontsize="small", ncol=3)
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel(f"time ({time_unit})")
    axes[0, 0].set_title(f"{title}\ngroup '{group}'" if title else f"group '{group}'")
    fig.tight_layout()
    save(fig, os.path.join(out_dir, f"group_{group}.png"))
    if with_csv:
        write_csv(os.path.join(out_dir, f"group_{group}.csv"), header, series)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results_dir", help="a sheetform results folder (holds results.h5)")
    parser.add_argument("-o", "--out-dir", help="where the images go (default: RESULTS_DIR)")
    parser.add_argument("--tool", help="the tool whose force and travel are plotted (default: the "
                                       "case's control.stroke_tool)")
    parser.add_argument("--csv", action="store_true", help="also write the plotted series as CSV")
    parser.add_argument("--group", action="append", default=[],
                        help="also plot this [[history]] group's columns (repeatable)")
    args = parser.parse_args()

    if not os.path.isdir(args.results_dir):
        raise InputProblem(f"{args.results_dir}: no such folder")
    h5_path = os.path.join(args.results_dir, "results.h5")
    history = read_history(h5_path)
    case = read_resolved_case(args.results_dir)
    has_stroke_tool = bool(case and case.get("control", {}).get("stroke_tool"))
    # With --group, a case without a moving tool (a static analysis) plots no tool force.
    tool = choose_tool(case, args.results_dir, args.tool) \
        if args.tool or has_stroke_tool or not args.group else None
    title = case.get("title", "") if case else ""
    units = case.get("units") if case else None
    if units is not None and units != EXPECTED_UNITS:
        print(f"plot_history: warning: the case's units are '{units}'; the labels assume "
              f"{EXPECTED_UNITS}", file=sys.stderr)
    # Check every column needed before writing anything.
    tool_columns = [f"{tool}_travel", f"{tool}_force"] if tool else []
    for name in ["time"] + tool_columns + [n for n, _ in ENERGIES]:
        column(history, name, h5_path)
    for group in args.group:
        if not any(f"{group}_{stem}_x" in history for stem, _ in GROUP_QUANTITIES):
            raise InputProblem(f"{h5_path}: /history has no columns of group '{group}' "
                               f"(a [[history]] group of the case: <group>_displacement_x, ...)")

    out_dir = args.out_dir or args.results_dir
    os.makedirs(out_dir, exist_ok=True)
    if tool:
        plot_force(history, h5_path, tool, title, out_dir, args.csv)
    else:
        print("plot_history: the case has no moving tool: no force or draw-in plot")
    plot_energies(history, h5_path, title, out_dir, args.csv)
    if tool and not plot_draw_in(history, h5_path, tool, title, out_dir, args.csv):
        print("plot_history: no draw_in_<name> columns in the history: no draw_in.png")
    for group in args.group:
        plot_group(history, h5_path, group, title, out_dir, args.csv)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except InputProblem as problem:
        print(f"plot_history: {problem}", file=sys.stderr)
        sys.exit(2)
