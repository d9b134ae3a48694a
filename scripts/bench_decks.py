#!/usr/bin/env python3
"""Runs the comparison decks with one sheetform binary and prints each run's cost per phase.

    scripts/bench_decks.py [--binary build/sheetform] [--out /tmp/decks] [--tag after] [DECK ...]

Decks: plate_bt, plate_as (benchmarks/plate_deck with each element formulation), punch_cached,
punch_modified (benchmarks/punch_deck with each search), demo (cases/square_cup_aluminium, 40 mm).
Default: all. For a before/after table, run it with both binaries back to back on one host
(docs/performance.md); a binary older than the phase timers prints only elements and contact.
"""
import argparse
import json
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
DECKS = {
    "plate_bt": ("benchmarks/plate_deck/case.toml", ["--set", 'blank.formulation="belytschko_tsay"']),
    "plate_as": ("benchmarks/plate_deck/case.toml", ["--set", 'blank.formulation="assumed_strain"']),
    "punch_cached": ("benchmarks/punch_deck/case.toml", ["--search", "cached"]),
    "punch_modified": ("benchmarks/punch_deck/case.toml", ["--search", "modified"]),
    "demo": ("cases/square_cup_aluminium/case.toml", []),
}


def describe(deck, summary):
    whole = summary["ns_per_element_cycle"]
    elements = summary["element_time_share"] * whole
    contact = summary["contact_time_share"] * whole
    per_node = summary.get("contact_ns_per_node_cycle",
                           contact * summary["elements"] / summary["nodes"])
    line = (f"{deck:15s} wall {summary['wall_seconds']:7.1f} s  cycles {summary['cycles']:6d}  "
            f"ns per element-cycle: whole {whole:6.0f}  elements {elements:6.0f}  "
            f"contact {contact:6.0f} ({per_node:6.1f} per node)  outside {whole - elements - contact:5.0f}")
    phases = summary.get("phase_ns_per_element_cycle")
    if phases:
        line += (f"  [time step {phases['time_step']:.0f}, nodal {phases['nodal']:.0f}, "
                 f"output {phases['output']:.0f}, other {phases['other']:.0f}]")
    return line


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default=str(ROOT / "build" / "sheetform"))
    parser.add_argument("--out", default="/tmp/sheetform_decks")
    parser.add_argument("--tag", default="run", help="prefix of the result folders")
    parser.add_argument("decks", nargs="*", default=list(DECKS))
    args = parser.parse_args()
    for deck in args.decks:
        if deck not in DECKS:
            sys.exit(f"unknown deck '{deck}' (known: {', '.join(DECKS)})")
        case, extra = DECKS[deck]
        out = pathlib.Path(args.out) / f"{args.tag}_{deck}"
        subprocess.run([args.binary, "run", str(ROOT / case), "-o", str(out), "-q", "--overwrite",
                        *extra],
                       check=True, stdout=subprocess.DEVNULL)
        print(describe(deck, json.loads((out / "summary.json").read_text())), flush=True)


if __name__ == "__main__":
    main()
