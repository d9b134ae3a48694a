"""The dynain file read back by a parser of its own (issue 32, item 5).

Run: /usr/bin/python3 tests/dynain/test_dynain.py SHEETFORM   (ctest: dynain_round_trip)

Draws the NUMISHEET'93 aluminium square cup to 2 mm (5 Gauss points, Hill48, plastic at the punch
radius), writes `sheetform dynain` of its formed part, and reads the keyword file here by the
fixed columns of the LS-DYNA keyword manual (*NODE: I8, 3E16, 2I8; *ELEMENT_SHELL_THICKNESS:
10 I8, then 5 E16; *INITIAL_STRESS_SHELL with LARGE = 0: 8 I10, then per point 8 E10: T, SIGXX,
SIGYY, SIGZZ, SIGXY, SIGYZ, SIGZX, EPS). Checked against the formed part (h5py), independently of
the writer: every line's width and keyword order; node coordinates and thickness to the 16-column
field's precision; connectivity; per point the position T (the 5-point Gauss rule), the plastic
strain, and the stress tensor's invariants against the part's element-frame components (trace,
Frobenius norm: a rotation keeps both) and its normal stress on the element's plane (zero: plane
stress in the element frame, the normal from the current corner coordinates), to the 10-column
field's precision.
"""
import math
import os
import subprocess
import sys
import tempfile
import unittest

import h5py
import numpy as np

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
SHEETFORM = None
GAUSS5 = [-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640]


def fields(line, widths):
    """The line cut into fixed-width fields (the keyword manual's columns)."""
    out, at = [], 0
    for w in widths:
        out.append(line[at:at + w])
        at += w
    return out


def parse_dynain(path):
    """Sections by keyword: lists of data lines (comments '$' dropped)."""
    sections, order, current = {}, [], None
    with open(path) as f:
        for raw in f:
            line = raw.rstrip("\n")
            if line.startswith("$"):
                continue
            if line.startswith("*"):
                current = line.strip()
                order.append(current)
                sections.setdefault(current, [])
                continue
            sections[current].append(line)
    return order, sections


class DynainRoundTrip(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        out = os.path.join(cls.tmp.name, "cup")
        case = os.path.join(ROOT, "cases", "square_cup_aluminium", "case.toml")
        subprocess.run([SHEETFORM, "run", case, "-o", out, "--stroke", "2", "-q"], check=True)
        cls.part_file = os.path.join(out, "formed_part.h5")
        cls.dynain = os.path.join(cls.tmp.name, "cup.k")
        subprocess.run([SHEETFORM, "dynain", cls.part_file, "-o", cls.dynain, "-q"], check=True)
        with h5py.File(cls.part_file, "r") as f:
            cls.x = f["/state/x"][()]
            cls.quads = f["/mesh/quads"][()]
            cls.triangles = f["/mesh/triangles"][()]
            cls.thickness = f["/state/shell/thickness"][()].reshape(-1)
            cls.s = {k: f["/state/shell/" + k][()] for k in ("sxx", "syy", "sxy", "eps_p")}
            cls.sxz = f["/state/shell/sxz"][()].reshape(-1)
            cls.syz = f["/state/shell/syz"][()].reshape(-1)
            cls.x0 = f["/mesh/reference_nodes"][()]
            cls.t0 = f["/mesh/initial_thickness"][()]
        cls.order, cls.sections = parse_dynain(cls.dynain)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_keywords_in_order(self):
        self.assertEqual(self.order, ["*KEYWORD", "*NODE", "*ELEMENT_SHELL_THICKNESS",
                                      "*INITIAL_STRESS_SHELL", "*INITIAL_STRAIN_SHELL", "*END"])

    def test_nodes(self):
        lines = self.sections["*NODE"]
        self.assertEqual(len(lines), self.x.shape[0])
        for i, line in enumerate(lines):
            self.assertEqual(len(line), 72, line)  # I8, 3 E16, 2 I8
            nid, x, y, z, tc, rc = fields(line, [8, 16, 16, 16, 8, 8])
            self.assertEqual(int(nid), i + 1)
            self.assertEqual((int(tc), int(rc)), (0, 0))
            for value, expected in zip((x, y, z), self.x[i]):
                # 16 columns (a blank, then 15) keep at least 11 significant digits
                self.assertAlmostEqual(float(value), expected, delta=1e-10 * max(1, abs(expected)))

    def test_elements_and_thickness(self):
        lines = self.sections["*ELEMENT_SHELL_THICKNESS"]
        n_el = self.quads.shape[0] + self.triangles.shape[0]
        self.assertEqual(len(lines), 2 * n_el)
        for e in range(n_el):
            card1, card2 = lines[2 * e], lines[2 * e + 1]
            self.assertEqual((len(card1), len(card2)), (80, 80))
            ids = [int(v) for v in fields(card1, [8] * 10)]
            self.assertEqual(ids[0], e + 1)
            self.assertEqual(ids[1], 1)
            corners = (list(self.quads[e]) if e < self.quads.shape[0]
                       else list(self.triangles[e - self.quads.shape[0]]) * 1)
            if len(corners) == 3:
                corners.append(corners[2])
            self.assertEqual(ids[2:6], [c + 1 for c in corners])
            self.assertEqual(ids[6:], [0, 0, 0, 0])
            t = [float(v) for v in fields(card2, [16] * 5)]
            for k in range(4):
                self.assertAlmostEqual(t[k], self.thickness[e], delta=1e-12)
            self.assertEqual(t[4], 0.0)

    def element_normal(self, e):
        corners = self.x[self.quads[e]]
        n = np.cross(corners[2] - corners[0], corners[3] - corners[1])
        return n / np.linalg.norm(n)

    def test_stresses_per_point(self):
        lines = self.sections["*INITIAL_STRESS_SHELL"]
        n_el = self.quads.shape[0]
        self.assertEqual(self.triangles.shape[0], 0)
        self.assertEqual(len(lines), n_el * 6)
        largest_eps = 0.0
        worst_normal = 0.0
        for e in range(n_el):
            head = lines[6 * e]
            self.assertEqual(len(head), 80)
            self.assertEqual([int(v) for v in fields(head, [10] * 8)], [e + 1, 1, 5, 0, 0, 0, 0, 0])
            n = self.element_normal(e)
            for k in range(5):
                card = lines[6 * e + 1 + k]
                self.assertEqual(len(card), 80, card)
                t, sxx, syy, szz, sxy, syz, szx, eps = [float(v) for v in fields(card, [10] * 8)]
                self.assertAlmostEqual(t, GAUSS5[k], delta=5.0001e-7)  # 6 decimals in 10 columns
                local = [self.s[c][e, k] for c in ("sxx", "syy", "sxy")]
                scale = max(1.0, max(abs(v) for v in local + [self.sxz[e], self.syz[e]]))
                tol = 1e-5 * scale  # 10 columns keep at least 6 significant digits of the largest
                self.assertEqual([c[0] for c in fields(card, [10] * 8)], [" "] * 8)
                g = np.array([[sxx, sxy, szx], [sxy, syy, syz], [szx, syz, szz]])
                self.assertAlmostEqual(np.trace(g), local[0] + local[1], delta=4 * tol)
                frobenius = math.sqrt(local[0] ** 2 + local[1] ** 2 + 2 * local[2] ** 2 +
                                      2 * self.sxz[e] ** 2 + 2 * self.syz[e] ** 2)
                self.assertAlmostEqual(np.linalg.norm(g), frobenius, delta=6 * tol)
                worst_normal = max(worst_normal, abs(n @ g @ n) / scale)
                # 10 columns (a blank, then 9) keep 7 decimals of a strain below 1: 5e-8
                self.assertAlmostEqual(eps, self.s["eps_p"][e, k], delta=5.0001e-8)
                largest_eps = max(largest_eps, eps)
        self.assertGreater(largest_eps, 1e-3)  # the cup has yielded: the test sees plastic strain
        # The element frame's e3 is the normal of the diagonals (a flat or nearly flat element):
        # the normal stress on the element's plane is zero up to the fields' rounding.
        self.assertLess(worst_normal, 1e-4)

    def mid_surface_strain(self, e):
        """The log strain of the element's mid-surface at its centre, computed here: the bilinear
        map's centre tangents, reference to current, the normal stretched by t / t0."""
        def basis(p):
            g1 = 0.25 * (-p[0] + p[1] + p[2] - p[3])
            g2 = 0.25 * (-p[0] - p[1] + p[2] + p[3])
            n = np.cross(g1, g2)
            return np.column_stack([g1, g2, n / np.linalg.norm(n)])
        ref = basis(self.x0[self.quads[e]])
        cur = basis(self.x[self.quads[e]])
        cur[:, 2] *= self.thickness[e] / self.t0[e]
        f = cur @ np.linalg.inv(ref)
        w, v = np.linalg.eigh(f @ f.T)
        return v @ np.diag(0.5 * np.log(w)) @ v.T, cur[:, 2] / np.linalg.norm(cur[:, 2])

    def test_surface_strains(self):
        lines = self.sections["*INITIAL_STRAIN_SHELL"]
        n_el = self.quads.shape[0]
        self.assertEqual(len(lines), 3 * n_el)
        largest = 0.0
        for e in range(n_el):
            head = lines[3 * e]
            self.assertEqual(len(head), 40)
            self.assertEqual([int(v) for v in fields(head, [10] * 4)], [e + 1, 1, 2, 0])
            surfaces = []
            for k, t_expected in enumerate((-1.0, 1.0)):
                card = lines[3 * e + 1 + k]
                self.assertEqual(len(card), 70, card)
                xx, yy, zz, xy, yz, zx, t = [float(v) for v in fields(card, [10] * 7)]
                self.assertEqual(t, t_expected)
                surfaces.append(np.array([[xx, xy, zx], [xy, yy, yz], [zx, yz, zz]]))
            mid, normal = self.mid_surface_strain(e)
            # Bending cancels between the surfaces to first order: their mean is the mid-surface
            # strain up to (t kappa)^2 terms and the 10-column fields' rounding.
            self.assertLess(np.abs(0.5 * (surfaces[0] + surfaces[1]) - mid).max(), 2e-3)
            # The normal fibre's strain is the thickness strain ln(t / t0).
            for g in surfaces:
                self.assertAlmostEqual(normal @ g @ normal,
                                       math.log(self.thickness[e] / self.t0[e]), delta=2e-4)
            largest = max(largest, np.abs(mid).max())
        self.assertGreater(largest, 5e-3)  # the cup has strained: the check sees strains


if __name__ == "__main__":
    SHEETFORM = sys.argv.pop(1)
    unittest.main()
