#!/usr/bin/env python3
"""Verification of the rectangular cup's CAD tools (README.md, "Verification").

    verify.py areas   [--sheetform PATH] [--work DIR] [--check]
    verify.py compare [--sheetform PATH] [--work DIR] [--stroke MM] [--check]
    verify.py study   [--sheetform PATH] [--work DIR] [--stroke MM]

areas: meshes the case (`sheetform mesh`: the tools from the STEP files) at the case's tool mesh
(element_size 2 mm, curvature_elements 32) and at half of it (1 mm, 64), and compares each
tool's meshed area with the exact area of its designed faces (planes, cylinders and torus
fillets, closed forms below) and its bounding box with the design's (a STEP unit read wrongly
shows at once: metres would make it 1000 times too small). A faceted surface misses an area of
second order in the element size: the deviation must fall about 4 times from one mesh to the
next, and the Richardson extrapolation (4 A(h/2) - A(h)) / 3 must leave only a fourth-order rest.
--check: fails unless, for every tool, the bounding box is the design's to 1e-6 mm, the deviation
ratio is between 3 and 5, and the extrapolated area is within 5e-5 of the exact one (relative;
measured 1.5e-5 at most, README.md; the smallest contact face is 3.7 % of its tool's area).

compare: runs the case twice to the same stroke (default 8 mm, the CI length): with the tools from
the STEP files, and with the same tools meshed from the gmsh scripts in cad/ directly (the
OpenCASCADE geometry before it was written to STEP; a case file written to WORK that differs
only in its tools' `mesh` keys). The two routes mesh the same surfaces into different triangles
(nodes placed by the mesher from a re-read geometry), so they agree to within what faceting
differences explain, and no closer. --check (at 8 mm only): fails unless the draw-ins, the punch
force (peak and along the stroke) and the smallest thickness agree within TOLERANCES, set from
`study` (README.md): twice the largest change that a different but about as fine tool mesh makes.

study: the faceting study behind those tolerances: the STEP case with about as fine but different
tool meshes (element_size 1.8, 1.9, 2.1, 2.2 mm with curvature_elements 36, 34, 30, 29), and with
tool meshes twice as fine (1 mm, 64), each compared with the case as it is. --reuse keeps runs
already in WORK.
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
TOOLS = ["punch", "die", "holder"]

# The design (cad/*.geo): half sizes, radii, heights in mm.
T = 0.81                       # sheet thickness; tool faces at z = +-T/2
PUNCH = dict(a=35.0, b=20.0, rc=10.0, rp=6.0, top=40.0)
DIE = dict(a=37.0, b=22.0, rc=12.0, rp=6.0, ox=70.0, oy=55.0, bottom=-40.0)
HOLDER = dict(a=38.0, b=23.0, rc=13.0, ox=70.0, oy=55.0)


def rounded_rectangle_quarter(a, b, r):
    """Area of a quarter of a rectangle 2a x 2b with plan corner radius r."""
    return a * b - (1.0 - math.pi / 4.0) * r * r


def exact_areas():
    """The contact faces' exact areas, face by face (closed forms), per tool."""
    p, d, h = PUNCH, DIE, HOLDER
    quarter_arc = math.pi / 2.0
    # Punch: flat bottom (the outline shrunk by the profile radius), two profile fillets (quarter
    # cylinders of radius rp along the straight sides), the corner fillet (a quarter of a quarter
    # torus: tube radius rp around a circle of radius rc - rp; the part between the bottom and
    # the wall has area (pi/2) rp ((rc - rp) pi/2 + rp)), the two walls and the corner cylinder,
    # from the fillet's top (z = T/2 + rp) to the top.
    wall_p = p["top"] - (T / 2 + p["rp"])
    punch = {
        "bottom": rounded_rectangle_quarter(p["a"] - p["rp"], p["b"] - p["rp"], p["rc"] - p["rp"]),
        "fillet_x": (p["a"] - p["rc"]) * quarter_arc * p["rp"],
        "fillet_y": (p["b"] - p["rc"]) * quarter_arc * p["rp"],
        "fillet_corner": quarter_arc * p["rp"] * ((p["rc"] - p["rp"]) * quarter_arc + p["rp"]),
        "wall_x": (p["a"] - p["rc"]) * wall_p,
        "wall_y": (p["b"] - p["rc"]) * wall_p,
        "wall_corner": quarter_arc * p["rc"] * wall_p,
    }
    # Die: the top face (the quarter plate less the opening grown by the profile radius), the
    # profile fillets (the corner one: tube rp around a circle of radius rc + rp, the part between
    # the top and the wall, (pi/2) rp ((rc + rp) pi/2 - rp)), the opening's walls down to the
    # bottom.
    wall_d = (-T / 2 - d["rp"]) - d["bottom"]
    die = {
        "top": d["ox"] * d["oy"]
        - rounded_rectangle_quarter(d["a"] + d["rp"], d["b"] + d["rp"], d["rc"] + d["rp"]),
        "fillet_x": (d["a"] - d["rc"]) * quarter_arc * d["rp"],
        "fillet_y": (d["b"] - d["rc"]) * quarter_arc * d["rp"],
        "fillet_corner": quarter_arc * d["rp"] * ((d["rc"] + d["rp"]) * quarter_arc - d["rp"]),
        "wall_x": (d["a"] - d["rc"]) * wall_d,
        "wall_y": (d["b"] - d["rc"]) * wall_d,
        "wall_corner": quarter_arc * d["rc"] * wall_d,
    }
    holder = {"bottom": h["ox"] * h["oy"] - rounded_rectangle_quarter(h["a"], h["b"], h["rc"])}
    return {"punch": punch, "die": die, "holder": holder}


def design_boxes():
    """Each tool's contact faces' bounding box (lo, hi), mm."""
    p, d, h = PUNCH, DIE, HOLDER
    return {
        "punch": ((0.0, 0.0, T / 2), (p["a"], p["b"], p["top"])),
        "die": ((0.0, 0.0, d["bottom"]), (d["ox"], d["oy"], -T / 2)),
        "holder": ((0.0, 0.0, T / 2), (h["ox"], h["oy"], T / 2)),
    }


def run(cmd):
    result = subprocess.run(cmd, capture_output=True, text=True)
    if result.returncode != 0:
        sys.stdout.write(result.stdout + result.stderr)
        raise SystemExit(f"failed (exit status {result.returncode}): {' '.join(cmd)}")
    return result


def tool_mesh(results_h5, tool):
    with h5py.File(results_h5, "r") as f:
        x = f[f"parts/{tool}/reference_coordinates"][()]
        c = f[f"parts/{tool}/connectivity"][()]
    return x, c


def mesh_area(x, c):
    a, b, d = x[c[:, 0]], x[c[:, 1]], x[c[:, 2]]
    return 0.5 * np.linalg.norm(np.cross(b - a, d - a), axis=1).sum()


def tool_sets(size, curvature):
    out = []
    for k in range(len(TOOLS)):
        out += ["--set", f"tools[{k}].element_size={size}",
                "--set", f"tools[{k}].curvature_elements={curvature}"]
    return out


def areas(args):
    exact = exact_areas()
    boxes = design_boxes()
    levels = [(2.0, 32), (1.0, 64)]
    measured = {}
    for size, curvature in levels:
        out = os.path.join(args.work, f"mesh_{size:g}mm")
        run([args.sheetform, "mesh", os.path.join(HERE, "case.toml"), "-o", out, "-q"]
            + tool_sets(size, curvature))
        for tool in TOOLS:
            x, c = tool_mesh(os.path.join(out, "results.h5"), tool)
            measured[(tool, size)] = (mesh_area(x, c), len(c), x.min(axis=0), x.max(axis=0))
    failures = []
    print("tool    exact mm^2   | h = 2 mm: triangles  area  deviation | h = 1 mm: triangles  "
          "area  deviation | ratio | extrapolated  deviation")
    for tool in TOOLS:
        a_exact = sum(exact[tool].values())
        (a1, n1, lo1, hi1), (a2, n2, lo2, hi2) = measured[(tool, 2.0)], measured[(tool, 1.0)]
        e1, e2 = a1 / a_exact - 1.0, a2 / a_exact - 1.0
        ratio = e1 / e2 if e2 != 0.0 else math.inf
        a_rich = (4.0 * a2 - a1) / 3.0
        e_rich = a_rich / a_exact - 1.0
        print(f"{tool:7s} {a_exact:11.4f} | {n1:6d} {a1:11.4f} {e1:+.3e} | {n2:6d} {a2:11.4f} "
              f"{e2:+.3e} | {ratio:5.2f} | {a_rich:11.4f} {e_rich:+.2e}")
        lo, hi = boxes[tool]
        for lo_m, hi_m in ((lo1, hi1), (lo2, hi2)):
            if np.abs(lo_m - lo).max() > 1e-6 or np.abs(hi_m - hi).max() > 1e-6:
                failures.append(f"{tool}: bounding box {lo_m} - {hi_m}, designed {lo} - {hi}")
        if not 3.0 <= ratio <= 5.0:
            failures.append(f"{tool}: area deviation ratio {ratio:.2f}, not second order (3 to 5)")
        if abs(e_rich) > 5e-5:
            failures.append(f"{tool}: extrapolated area {a_rich:.4f} mm^2 is {e_rich:+.2e} off "
                            f"the exact {a_exact:.4f} (limit 5e-5)")
        print("        faces: " + ", ".join(f"{k} {v:.4f}" for k, v in exact[tool].items()))
    for tool in TOOLS:
        lo, hi = measured[(tool, 2.0)][2:]
        print(f"{tool:7s} bounding box ({lo[0]:g}, {lo[1]:g}, {lo[2]:g}) - "
              f"({hi[0]:g}, {hi[1]:g}, {hi[2]:g}) mm")
    return report(failures, args.check)


def geo_variant(work):
    """The case file with the tools meshed from cad/*.geo (and the blank's path made absolute)."""
    with open(os.path.join(HERE, "case.toml"), encoding="utf-8") as f:
        text = f.read()
    text = text.replace('mesh = "blank.geo"', f'mesh = "{os.path.join(HERE, "blank.geo")}"')
    for tool in TOOLS:
        text, n = re.subn(rf'^mesh = "{tool}\.step".*$',
                          f'mesh = "{os.path.join(HERE, "cad", tool + ".geo")}"', text,
                          flags=re.M)
        assert n == 1, f"case.toml: no mesh = \"{tool}.step\" line"
    # The scripts name their contact faces (physical groups) and set their own curvature
    # refinement (Mesh.MeshSizeFromCurvature = 32): these keys belong to the STEP files.
    text = re.sub(r"^(surfaces|curvature_elements) = .*\n", "", text, flags=re.M)
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, "case_geo_tools.toml")
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    return path


def run_case(args, case, name, extra=()):
    out = os.path.join(args.work, name)
    # --overwrite: the work folder is this script's own, and a second run must not stop at it.
    cmd = [args.sheetform, "run", case, "-o", out, "--overwrite", "-q", "--threads", "1",
           "--stroke", f"{args.stroke:g}"] + list(extra)
    if not (args.reuse and os.path.isfile(os.path.join(out, "summary.json"))):
        run(cmd)
    with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
        summary = json.load(f)
    with h5py.File(os.path.join(out, "results.h5"), "r") as f:
        history = {k: f["history"][k][()] for k in ("punch_travel", "punch_force", "draw_in_DX",
                                                    "draw_in_DY", "draw_in_DD")}
    return summary, history


# Tolerances of `compare --check`, at the CI stroke (8 mm) only: twice the largest change that
# one of four about as fine but different tool meshes makes (`study --stroke 8`, README.md):
# draw-ins DX 0.0046, DY 0.0052, DD 0.0020 mm; punch force peak 21.6 N, along the stroke 23.5 N;
# smallest thickness 0.00079 mm. A metric passes when |STEP - .geo| <= the tolerance.
CHECK_STROKE = 8.0
TOLERANCES = {
    "DX": 0.0092,           # mm
    "DY": 0.0103,           # mm
    "DD": 0.0040,           # mm
    "punch_peak": 43.0,     # N
    "punch_curve": 47.0,    # N, the largest difference of the force curves over the stroke
    "min_thickness": 0.0016,  # mm
}


def metrics(summary, history):
    force = history["punch_force"]
    return {
        "DX": summary["draw_in"]["DX"]["computed_mm"],
        "DY": summary["draw_in"]["DY"]["computed_mm"],
        "DD": summary["draw_in"]["DD"]["computed_mm"],
        "punch_peak": summary["tools"]["punch"]["peak_force_N"],
        "min_thickness": summary["min_thickness_mm"],
        "max_plastic_strain": summary["max_plastic_strain"],
        "internal_energy": summary["energy_Nmm"]["internal"],
        "friction_work": summary["energy_Nmm"]["friction_work"],
        "_force": (history["punch_travel"], force),
    }


def curve_difference(a, b):
    """Largest difference of two punch force curves (N), the second interpolated at the first's
    travel, over the common travel."""
    (sa, fa), (sb, fb) = a, b
    common = sa <= sb.max()
    return float(np.max(np.abs(fa[common] - np.interp(sa[common], sb, fb))))


def compare_table(reference, other, label_ref, label_other):
    rows = []
    for key in ("DX", "DY", "DD", "punch_peak", "min_thickness", "max_plastic_strain",
                "internal_energy", "friction_work"):
        r, o = reference[key], other[key]
        rows.append((key, r, o, o - r, (o - r) / r if r else math.nan))
    curve = curve_difference(reference["_force"], other["_force"])
    peak = reference["punch_peak"]
    rows.append(("punch_curve", peak, None, curve, curve / peak))
    print(f"{'metric':20s} {label_ref:>14s} {label_other:>14s} {'difference':>12s} "
          f"{'relative':>10s}")
    for key, r, o, d, rel in rows:
        o_text = f"{o:14.5g}" if o is not None else f"{'(max over stroke)':>14s}"
        print(f"{key:20s} {r:14.5g} {o_text} {d:+12.4g} {rel:+10.2e}")
    return {key: (d, r) for key, r, o, d, rel in rows}


def compare(args):
    step = metrics(*run_case(args, os.path.join(HERE, "case.toml"), "step_tools"))
    geo = metrics(*run_case(args, geo_variant(args.work), "geo_tools"))
    print(f"stroke {args.stroke:g} mm: tools from the STEP files against the same tools meshed "
          f"from cad/*.geo")
    diffs = compare_table(step, geo, "STEP", ".geo")
    failures = []
    if args.check and args.stroke != CHECK_STROKE:
        failures.append(f"the tolerances hold at {CHECK_STROKE:g} mm, not {args.stroke:g} mm")
    if args.stroke == CHECK_STROKE:
        print("tolerances (twice the largest change an about as fine tool mesh makes at 8 mm): "
              + ", ".join(f"{key} {limit:g}" for key, limit in TOLERANCES.items()))
    for key, limit in TOLERANCES.items():
        d, r = diffs[key]
        if abs(d) > limit:
            failures.append(f"{key}: STEP and .geo tools differ by {d:+.4g}, more than {limit:.4g}")
    return report(failures, args.check)


# The study's tool meshes (element_size mm, curvature_elements): four about as fine as the case's
# (2 mm, 32), then one twice as fine.
STUDY = (("tools_1.8mm", 1.8, 36), ("tools_1.9mm", 1.9, 34), ("tools_2.1mm", 2.1, 30),
         ("tools_2.2mm", 2.2, 29), ("tools_1mm", 1.0, 64))


def study(args):
    case = os.path.join(HERE, "case.toml")
    base = metrics(*run_case(args, case, "step_tools"))
    for name, size, curvature in STUDY:
        other = metrics(*run_case(args, case, name, tool_sets(size, curvature)))
        print(f"\nstroke {args.stroke:g} mm: the case (tools 2 mm, 32 per 2 pi) against tools "
              f"{size:g} mm, {curvature} per 2 pi")
        compare_table(base, other, "case", name)
    return 0


def report(failures, check):
    for failure in failures:
        print(("FAIL: " if check else "note: ") + failure)
    if check:
        print("check: " + ("failed" if failures else "passed"))
        return 1 if failures else 0
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("what", choices=["areas", "compare", "study"])
    parser.add_argument("--sheetform", default=os.path.join(ROOT, "build", "sheetform"))
    parser.add_argument("--work", default="/tmp/rectangular_cup_cad_verify")
    parser.add_argument("--stroke", type=float, default=CHECK_STROKE, help="mm (compare, study)")
    parser.add_argument("--check", action="store_true", help="fail outside the tolerances")
    parser.add_argument("--reuse", action="store_true",
                        help="compare, study: keep a run whose summary.json is already in WORK")
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    return {"areas": areas, "compare": compare, "study": study}[args.what](args)


if __name__ == "__main__":
    sys.exit(main())
