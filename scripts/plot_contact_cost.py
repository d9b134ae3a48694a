#!/usr/bin/env python3
"""Plots the contact-search cost study (benchmarks/bench_contact_search.cpp).

Usage: plot_contact_cost.py run1.csv [run2.csv ...] [-o docs/img/contact_cost.png]

Several CSV files (runs of the benchmark on a shared machine) are merged by taking, for each
mesh, search and mode, the LOWEST time (other jobs only ever slow a run down); operation counts
do not depend on the run. Two log-log panels against the number of tool triangles: time per
query (per node-cycle for the trajectories), and multiplications + divisions per query.
Needs matplotlib (Debian: apt-get install python3-matplotlib).
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# (search, mode) -> legend label, style
SERIES = [
    ("standard_brute_force", "static", "standard, brute force", "o-", "tab:blue"),
    ("modified_brute_force", "static", "modified, brute force", "s-", "tab:red"),
    ("standard", "static", "standard, grid (static points)", "o--", "tab:blue"),
    ("modified", "static", "modified, grid (static points)", "s--", "tab:red"),
    ("standard", "motion_1e-3", "standard, grid (per node-cycle)", "o:", "tab:cyan"),
    ("modified", "motion_1e-3", "modified, grid (per node-cycle)", "s:", "tab:orange"),
    ("cached", "motion_1e-3", "cached, per node-cycle, 1e-3 mm/cycle", "D-", "tab:green"),
    ("cached", "motion_2e-2", "cached, per node-cycle, 2e-2 mm/cycle", "D--", "tab:olive"),
    ("cached", "static_build", "cached, list build per query", "D:", "tab:gray"),
]


def read(paths):
    """(search, mode, triangles) -> {ns, ops}: the lowest ns over the files."""
    merged = {}
    for path in paths:
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                if row["mode"].startswith("margin_"):
                    continue
                key = (row["search"], row["mode"], int(row["triangles"]))
                ns = float(row["ns_per_query"])
                ops = None
                if row["mult_per_query"] and row["div_per_query"]:
                    ops = float(row["mult_per_query"]) + float(row["div_per_query"])
                old = merged.get(key)
                if old is None or ns < old["ns"]:
                    merged[key] = {"ns": ns, "ops": ops if ops is not None else (old or {}).get("ops")}
                elif ops is not None and old.get("ops") is None:
                    old["ops"] = ops
    return merged


def print_markdown(data):
    """Times, operation counts and ratios per mesh, from the merged data."""
    tris = sorted({t for (_, _, t) in data})

    def ns(search, mode, t):
        v = data.get((search, mode, t))
        return v["ns"] if v else float("nan")

    def ops(search, mode, t):
        v = data.get((search, mode, t))
        return v["ops"] if v and v["ops"] is not None else float("nan")

    print("| triangles | standard brute | modified brute | standard grid | modified grid "
          "| standard grid, node-cycle | modified grid, node-cycle | cached, node-cycle 1e-3 "
          "| cached, node-cycle 2e-2 | cached list build |")
    print("|" + "---|" * 10)
    for t in tris:
        cells = [ns("standard_brute_force", "static", t), ns("modified_brute_force", "static", t),
                 ns("standard", "static", t), ns("modified", "static", t),
                 ns("standard", "motion_1e-3", t), ns("modified", "motion_1e-3", t),
                 ns("cached", "motion_1e-3", t), ns("cached", "motion_2e-2", t),
                 ns("cached", "static_build", t)]
        print(f"| {t} | " + " | ".join(f"{c:,.0f}" for c in cells) + " |")
    print()
    print("| triangles | standard brute | modified brute | standard grid | modified grid "
          "| cached 1e-3 | cached 2e-2 |")
    print("|" + "---|" * 7)
    for t in tris:
        cells = [ops("standard_brute_force", "static", t), ops("modified_brute_force", "static", t),
                 ops("standard", "static", t), ops("modified", "static", t),
                 ops("cached", "motion_1e-3", t), ops("cached", "motion_2e-2", t)]
        print(f"| {t} | " + " | ".join(f"{c:,.0f}" for c in cells) + " |")
    print()
    print("| triangles | modified/standard brute, time | modified/standard brute, mult+div "
          "| cached/standard grid, node-cycle | cached/modified grid, node-cycle "
          "| cached/standard grid, mult+div | cached/modified grid, mult+div |")
    print("|" + "---|" * 7)
    for t in tris:
        r = [ns("modified_brute_force", "static", t) / ns("standard_brute_force", "static", t),
             ops("modified_brute_force", "static", t) / ops("standard_brute_force", "static", t),
             ns("cached", "motion_1e-3", t) / ns("standard", "motion_1e-3", t),
             ns("cached", "motion_1e-3", t) / ns("modified", "motion_1e-3", t),
             ops("cached", "motion_1e-3", t) / ops("standard", "static", t),
             ops("cached", "motion_1e-3", t) / ops("modified", "static", t)]
        print(f"| {t} | " + " | ".join(f"{c:.2f}" for c in r) + " |")
    print()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv", nargs="+")
    ap.add_argument("-o", "--output", default="docs/img/contact_cost.png")
    ap.add_argument("--markdown", action="store_true",
                    help="also print the merged figures as markdown tables")
    args = ap.parse_args()
    data = read(args.csv)
    if not data:
        sys.exit("no data")
    if args.markdown:
        print_markdown(data)

    fig, (ax_t, ax_o) = plt.subplots(1, 2, figsize=(13, 5.2))
    for search, mode, label, style, color in SERIES:
        pts = sorted((t, v) for (s, m, t), v in data.items() if s == search and m == mode)
        if not pts:
            continue
        tris = [t for t, _ in pts]
        ax_t.plot(tris, [v["ns"] for _, v in pts], style, color=color, label=label, ms=4)
        ops = [(t, v["ops"]) for t, v in pts if v["ops"] is not None]
        if ops:
            ax_o.plot([t for t, _ in ops], [o for _, o in ops], style, color=color, label=label,
                      ms=4)
    # A line of slope 1 through the standard brute force, for the eye.
    sb = sorted((t, v["ns"]) for (s, m, t), v in data.items()
                if s == "standard_brute_force" and m == "static")
    if sb:
        t0, y0 = sb[0]
        ts = [t for t, _ in sb]
        ax_t.plot(ts, [y0 * t / t0 for t in ts], "-", color="0.8", lw=3, zorder=0,
                  label="slope 1 (linear)")
    for ax, title, ylabel in (
        (ax_t, "time per query", "ns per query (or per node-cycle)"),
        (ax_o, "multiplications + divisions per query", "mult + div per query"),
    ):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("tool triangles")
        ax.set_ylabel(ylabel)
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
    ax_t.legend(fontsize=7, loc="upper left")
    ax_o.legend(fontsize=7, loc="upper left")
    fig.suptitle("Contact search cost: punch height field, cutoff 1.6 mm, points within ±1 mm "
                 "(bench_contact_search; fastest of the runs)", fontsize=10)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
