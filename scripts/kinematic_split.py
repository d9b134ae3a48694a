#!/usr/bin/env python3
"""Split a monotonic flow curve between isotropic and kinematic hardening: writes the isotropic
part sigma_iso(eps_p) = sigma(eps_p) - sum_i C_i / gamma_i (1 - exp(-gamma_i eps_p)) as a
tabulated hardening file ([materials.NAME.hardening] law = "tabulated"), so that with the back
stresses C_i, gamma_i ([materials.NAME.kinematic]) the material's monotonic uniaxial curve along
the rolling direction stays sigma(eps_p) while reversed loading shows a Bauschinger effect
(docs/case-file.md, kinematic hardening). The monotonic curve here is Swift's,
sigma = K (eps0 + eps_p)^n.

    scripts/kinematic_split.py --swift K EPS0 N --C C1 [C2 ..] --gamma G1 [G2 ..] -o FILE.csv

Refuses a split whose isotropic part would soften (sigma_iso must not decrease: the tabulated law
requires it) and prints the largest difference between the table, interpolated linearly as
sheetform does, and the exact isotropic part (MPa).
"""
import argparse
import sys

import numpy as np


def isotropic_part(eps, swift, C, gamma):
    K, eps0, n = swift
    back = sum(c / g * (1.0 - np.exp(-g * eps)) if g > 0 else c * eps for c, g in zip(C, gamma))
    return K * (eps0 + eps) ** n - back


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--swift", nargs=3, type=float, required=True, metavar=("K", "EPS0", "N"))
    p.add_argument("--C", nargs="+", type=float, required=True, help="MPa, one per back stress")
    p.add_argument("--gamma", nargs="+", type=float, required=True, help="-, one per back stress")
    p.add_argument("--max-strain", type=float, default=1.0, help="last plastic strain of the table (1.0)")
    p.add_argument("--points", type=int, default=400, help="points, geometric from 1e-5 (400)")
    p.add_argument("-o", "--output", required=True)
    a = p.parse_args()
    if len(a.C) != len(a.gamma):
        sys.exit("kinematic_split.py: one gamma per C")
    eps = np.concatenate([[0.0], np.geomspace(1e-5, a.max_strain, a.points)])
    iso = isotropic_part(eps, a.swift, a.C, a.gamma)
    fine = np.linspace(0.0, a.max_strain, 200001)
    exact = isotropic_part(fine, a.swift, a.C, a.gamma)
    if np.any(np.diff(exact) < 0.0) or iso[0] <= 0.0:
        worst = fine[np.argmin(np.diff(exact))]
        sys.exit(f"kinematic_split.py: the isotropic part softens near eps_p = {worst:.4g} (or starts <= 0): "
                 "the back stresses harden faster than the curve there; lower C or raise gamma")
    with open(a.output, "w") as f:
        f.write(f"# Isotropic part of Swift {a.swift[0]:g} ({a.swift[1]:g} + eps_p)^{a.swift[2]:g} MPa with the back "
                f"stresses C = {a.C} MPa, gamma = {a.gamma}\n")
        f.write("# (scripts/kinematic_split.py): with them, the monotonic uniaxial curve is the Swift curve.\n")
        f.write("eps_p, sigma_iso_MPa\n")
        for e, s in zip(eps, iso):
            f.write(f"{e:.10g}, {s:.10g}\n")
    error = np.abs(np.interp(fine, eps, iso) - exact).max()
    print(f"{a.output}: {len(eps)} points, sigma_iso {iso[0]:.2f} to {iso[-1]:.2f} MPa; "
          f"largest interpolation error {error:.3g} MPa")


if __name__ == "__main__":
    main()
