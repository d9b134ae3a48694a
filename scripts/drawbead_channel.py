#!/usr/bin/python3
"""The drawbead channel (cases/drawbead_channel, after NUMISHEET 2005 BM3) at several bead
penetrations: punch force and draw-in against penetration (docs/validation.md).

Usage:

    /usr/bin/python3 scripts/drawbead_channel.py --sheetform build/sheetform --out DIR
        [--depths 1 2 3 4] [--stroke MM] [--plot PNG] [--reuse]

Runs `sheetform run cases/drawbead_channel/case.toml --set drawbeads[0].depth=D` for each bead
depth D (mm; the bead's full height is 4 mm, so 1, 2, 3, 4 mm are 25, 50, 75 and 100 %
penetration) into DIR/depth_D, and the case without its bead (--set drawbeads=[] is not a key:
the bead-free run is cases/u_channel_bhf_19600N's, given as the 0 % row from its own run in
DIR/no_bead). Prints a markdown table: penetration, the bead's restraining and uplift force per
length at full closure (from the run's banner), the punch's peak force, the strip end's
draw-in, the smallest thickness and the bead work; with --plot, the punch force against the
punch travel for every run. Forces are the quarter model's (N). With --reuse, a run whose
folder holds a summary.json and a run.log already is read, not run again. Needs h5py and
matplotlib.
Exit codes: 0 done; 1 a run failed (its log is named).
"""
import argparse
import json
import pathlib
import re
import subprocess
import sys

import h5py

ROOT = pathlib.Path(__file__).resolve().parent.parent
FULL_HEIGHT = 4.0  # mm, the bead's radius: a depth of 4 mm is full penetration


def run(sheetform, case, out, settings, stroke, reuse):
    if reuse and (out / "results" / "summary.json").is_file() and (out / "run.log").is_file():
        return read(out)
    out.mkdir(parents=True, exist_ok=True)
    command = [str(sheetform), "run", str(case), "-o", str(out / "results")]
    for s in settings:
        command += ["--set", s]
    if stroke:
        command += ["--stroke", str(stroke)]
    log = out / "run.log"
    with open(log, "w") as f:
        code = subprocess.run(command, stdout=f, stderr=subprocess.STDOUT).returncode
    if code != 0:
        print(f"drawbead_channel: {' '.join(command)} failed (exit {code}): see {log}",
              file=sys.stderr)
        sys.exit(1)
    return read(out)


def read(out):
    """The figures of the run in `out`."""
    text = (out / "run.log").read_text()
    bead = re.search(r"restraining (\S+) N/mm, uplift (\S+) N/mm", text)
    summary = json.loads((out / "results" / "summary.json").read_text())
    history = h5py.File(out / "results" / "results.h5", "r")["history"]
    return {
        "restraining": float(bead.group(1)) if bead else 0.0,
        "uplift": float(bead.group(2)) if bead else 0.0,
        "peak": summary["tools"]["punch"]["peak_force_N"],
        "draw_in": summary["draw_in"]["end"]["computed_mm"],
        "thickness": summary["min_thickness_mm"],
        "bead_work": summary["energy_Nmm"].get("drawbead_work", 0.0),
        "travel": -history["punch_travel"][:] if history["punch_travel"][-1] < 0
        else history["punch_travel"][:],
        "force": history["punch_force"][:],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sheetform", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--depths", type=float, nargs="+", default=[1.0, 2.0, 3.0, 4.0])
    parser.add_argument("--stroke", type=float, help="mm of punch travel (default: the case's 70)")
    parser.add_argument("--plot", help="PNG of punch force against travel")
    parser.add_argument("--reuse", action="store_true", help="read the runs already in --out")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    rows = []
    for depth in args.depths:
        rows.append((f"{100 * depth / FULL_HEIGHT:.0f}", run(
            args.sheetform, ROOT / "cases/drawbead_channel/case.toml", out / f"depth_{depth:g}",
            [f"drawbeads[0].depth={depth}"], args.stroke, args.reuse)))
    rows.insert(0, ("0 (no bead)", run(args.sheetform,
                                       ROOT / "cases/u_channel_bhf_19600N/case.toml",
                                       out / "no_bead", [], args.stroke, args.reuse)))
    print("| penetration (%) | restraining (N/mm) | uplift (N/mm) | punch force, peak (N) | "
          "draw-in (mm) | thickness, least (mm) | bead work (N mm) |")
    print("|---|---|---|---|---|---|---|")
    for name, r in rows:
        print(f"| {name} | {r['restraining']:.4g} | {r['uplift']:.4g} | {r['peak']:.0f} | "
              f"{r['draw_in']:.2f} | {r['thickness']:.3f} | {r['bead_work']:.0f} |")
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for name, r in rows:
            ax.plot(r["travel"], r["force"], label=f"{name} %")
        ax.set_xlabel("punch travel (mm)")
        ax.set_ylabel("punch force, quarter model (N)")
        ax.set_title("Channel through a round drawbead: penetration")
        ax.grid(True, alpha=0.3)
        ax.legend(title="penetration")
        fig.tight_layout()
        fig.savefig(args.plot, dpi=110)
        print(f"drawbead_channel: wrote {args.plot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
