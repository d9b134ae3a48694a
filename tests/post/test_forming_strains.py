"""Unit tests of scripts/forming_strains.py: the per-element in-plane principal true strains
against exact solutions of homogeneous deformations, the mixed-mesh cell order, reading a
results.h5 blank, and the forming-limit margin.

Run: /usr/bin/python3 -m unittest tests/post/test_forming_strains.py   (or run this file)

Tolerances: the exact strains below are closed forms; the computation is a handful of products,
one 2 x 2 inverse and a logarithm on O(1) numbers, so its error is a few units of round-off
(about 1e-16 each). 1e-12 (the brief's tolerance) leaves ample room; rigid-body motions are
checked to 1e-14 absolute (exactly 0 up to round-off).
"""
import math
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import forming_strains as fs  # noqa: E402


def rotation(axis, angle_deg):
    """Rotation matrix about `axis` (Rodrigues' formula)."""
    axis = np.asarray(axis, dtype=float)
    axis /= np.linalg.norm(axis)
    k = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
    a = math.radians(angle_deg)
    return np.eye(3) + math.sin(a) * k + (1.0 - math.cos(a)) * (k @ k)


def in_plane_stretch(l1, l2, angle_deg):
    """U = R diag(l1, l2, 1) R^T with R the rotation by angle_deg about z: stretches l1, l2 along
    in-plane axes at angle_deg to x, y (a homogeneous deformation of the xy plane)."""
    r = rotation([0.0, 0.0, 1.0], angle_deg)
    return r @ np.diag([l1, l2, 1.0]) @ r.T


# A rigid rotation about a skew axis and a translation, applied after the in-plane deformation.
Q = rotation([1.0, 2.0, 3.0], 40.0)
C = np.array([12.5, -3.0, 7.25])

# Reference elements in the xy plane (mm), counter-clockwise.
SQUARE = np.array([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 2.0, 0.0], [0.0, 2.0, 0.0]])
# Not a parallelogram (no two sides parallel): the bilinear map is not affine.
DISTORTED = np.array([[0.0, 0.0, 0.0], [2.0, 0.3, 0.0], [2.4, 1.9, 0.0], [-0.2, 1.4, 0.0]])
TRIANGLE = np.array([[0.3, -0.1, 0.0], [2.1, 0.4, 0.0], [0.9, 1.7, 0.0]])  # scalene

QUAD = np.array([[0, 1, 2, 3]])
TRI = np.array([[0, 1, 2]])


def deformed(reference, a, q=Q, c=C):
    """x = q (a X) + c for every node X."""
    return (reference @ a.T) @ q.T + c


class HomogeneousStretch(unittest.TestCase):
    """Stretches 1.2 and 0.9 along axes at 30 deg to x, y; then rotated by Q and translated."""

    U = in_plane_stretch(1.2, 0.9, 30.0)

    def check(self, major, minor):
        # Exact: eps1 = ln 1.2, eps2 = ln 0.9 (principal stretches of U); tolerance 1e-12 (above).
        self.assertAlmostEqual(major[0], math.log(1.2), delta=1e-12)
        self.assertAlmostEqual(minor[0], math.log(0.9), delta=1e-12)

    def test_square_quad(self):
        self.check(*fs.quad_strains(SQUARE, deformed(SQUARE, self.U), QUAD))

    def test_distorted_quad(self):
        # Homogeneous deformation: the centre tangents map exactly (module docstring), so the
        # non-parallelogram quad gives the exact strain too.
        self.check(*fs.quad_strains(DISTORTED, deformed(DISTORTED, self.U), QUAD))

    def test_triangle(self):
        self.check(*fs.triangle_strains(TRIANGLE, deformed(TRIANGLE, self.U), TRI))

    def test_reference_not_in_the_xy_plane(self):
        # The reference itself rotated (by Q0) and moved out of the xy plane: the strain is
        # measured in the element's own plane, not in global xy.
        q0 = rotation([-2.0, 1.0, 0.5], 65.0)
        for shape, cells, strains in ((DISTORTED, QUAD, fs.quad_strains),
                                      (TRIANGLE, TRI, fs.triangle_strains)):
            reference = shape @ q0.T + np.array([1.0, 2.0, 3.0])
            current = deformed(shape, self.U)
            self.check(*strains(reference, current, cells))

    def test_node_order_does_not_matter(self):
        # Clockwise numbering (and a different first node) flips the local normal: same strains.
        order = [2, 1, 0, 3]
        quad = DISTORTED[order]
        self.check(*fs.quad_strains(quad, deformed(quad, self.U), QUAD))
        tri = TRIANGLE[[1, 0, 2]]
        self.check(*fs.triangle_strains(tri, deformed(tri, self.U), TRI))


class SimpleShear(unittest.TestCase):
    """x = X + g Y (g = 0.5), rotated and translated: principal stretches
    sqrt(1 + g^2/4) +- g/2 (closed form of simple shear's stretches)."""

    def test_distorted_quad_and_triangle(self):
        g = 0.5
        a = np.array([[1.0, g, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
        l1 = math.sqrt(1.0 + g * g / 4.0) + g / 2.0
        l2 = math.sqrt(1.0 + g * g / 4.0) - g / 2.0
        for shape, cells, strains in ((DISTORTED, QUAD, fs.quad_strains),
                                      (TRIANGLE, TRI, fs.triangle_strains)):
            major, minor = strains(shape, deformed(shape, a), cells)
            # Exact closed form, tolerance 1e-12 (module docstring of this test).
            self.assertAlmostEqual(major[0], math.log(l1), delta=1e-12)
            self.assertAlmostEqual(minor[0], math.log(l2), delta=1e-12)
            # Isochoric in plane: eps1 + eps2 = ln(l1 l2) = 0, to round-off (1e-12).
            self.assertAlmostEqual(major[0] + minor[0], 0.0, delta=1e-12)


class QuadCentre(unittest.TestCase):
    def test_bilinear_deformation_is_evaluated_at_the_centre(self):
        # Square [-1, 1]^2 (so xi = X, eta = Y) under the bilinear map x = 1.2 X + 0.1 X Y,
        # y = Y, which the element represents exactly: F = [[1.2 + 0.1 Y, 0.1 X], [0, 1]] is
        # diag(1.2, 1) at the centre only. Exact: eps1 = ln 1.2, eps2 = 0 (1e-12, as above).
        # Gradients from corner edges would see 1.2 +- 0.1 and a shear instead.
        square = np.array([[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0]])
        current = square.copy()
        current[:, 0] = 1.2 * square[:, 0] + 0.1 * square[:, 0] * square[:, 1]
        major, minor = fs.quad_strains(square, current @ Q.T + C, QUAD)
        self.assertAlmostEqual(major[0], math.log(1.2), delta=1e-12)
        self.assertAlmostEqual(minor[0], 0.0, delta=1e-12)


class RigidBodyMotion(unittest.TestCase):
    def test_zero_strain(self):
        for shape, cells, strains in ((SQUARE, QUAD, fs.quad_strains),
                                      (DISTORTED, QUAD, fs.quad_strains),
                                      (TRIANGLE, TRI, fs.triangle_strains)):
            major, minor = strains(shape, deformed(shape, np.eye(3)), cells)
            # Exact: 0; tolerance 1e-14 absolute (round-off of C = I, about 1e-16).
            self.assertAlmostEqual(major[0], 0.0, delta=1e-14)
            self.assertAlmostEqual(minor[0], 0.0, delta=1e-14)

    def test_identical_coordinates_give_exactly_zero(self):
        # current == reference: F = X X^-1, which numpy's inverse need not make exactly I; the
        # strain is 0 to round-off (1e-15).
        major, minor = fs.quad_strains(DISTORTED, DISTORTED.copy(), QUAD)
        self.assertAlmostEqual(major[0], 0.0, delta=1e-15)
        self.assertAlmostEqual(minor[0], 0.0, delta=1e-15)


class MixedMesh(unittest.TestCase):
    """A quad and a triangle sharing an edge: the results' cell order is quads, then triangles."""

    def setUp(self):
        self.reference = np.array([[0.0, 0.0, 0.0], [2.0, 0.3, 0.0], [2.4, 1.9, 0.0],
                                   [-0.2, 1.4, 0.0], [3.5, 0.8, 0.0]])
        self.quads = np.array([[0, 1, 2, 3]])
        self.triangles = np.array([[1, 4, 2]])
        self.u = in_plane_stretch(1.2, 0.9, 30.0)

    def test_order_and_values(self):
        current = deformed(self.reference, self.u)
        major, minor = fs.element_strains(self.reference, current, self.quads, self.triangles)
        self.assertEqual(major.shape, (2,))
        # Both exact under the homogeneous stretch (tolerance 1e-12, as above).
        np.testing.assert_allclose(major, math.log(1.2), rtol=0, atol=1e-12)
        np.testing.assert_allclose(minor, math.log(0.9), rtol=0, atol=1e-12)

    def test_each_cell_its_own_strain(self):
        # Only the triangle's free node moves (x-stretch of the triangle only): the quad stays
        # unstrained (exactly 0, to 1e-15) and comes first; the triangle is strained.
        current = self.reference.copy()
        current[4, 0] += 0.7
        major, minor = fs.element_strains(self.reference, current, self.quads, self.triangles)
        self.assertAlmostEqual(major[0], 0.0, delta=1e-15)
        self.assertAlmostEqual(minor[0], 0.0, delta=1e-15)
        self.assertGreater(major[1], 0.05)

    def test_read_blank_follows_nodes_per_cell(self):
        import h5py  # only this test needs it

        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "results.h5")
            with h5py.File(path, "w") as f:
                g = f.create_group("parts/blank")
                g.attrs["nodes_per_cell"] = np.int32(0)
                g["reference_coordinates"] = self.reference
                g["connectivity"] = self.quads.astype(np.int32)
                g["triangle_connectivity"] = self.triangles.astype(np.int32)
                t = f.create_group("parts/tri")
                t.attrs["nodes_per_cell"] = np.int32(3)
                t["reference_coordinates"] = self.reference
                t["connectivity"] = self.triangles.astype(np.int32)
                b = f.create_group("parts/bad")
                b.attrs["nodes_per_cell"] = np.int32(0)
                b["reference_coordinates"] = self.reference
                b["connectivity"] = self.quads.astype(np.int32)
                # a trim: frame 1 is of the first quadrilateral alone (its 4 nodes)
                g.create_group("frames/000000")
                g.create_group("frames/000001").attrs["topology"] = np.int32(1)
                m = g.create_group("topologies/1")
                m.attrs["nodes_per_cell"] = np.int32(4)
                m["reference_coordinates"] = self.reference[self.quads[0]]
                m["connectivity"] = np.array([[0, 1, 2, 3]], dtype=np.int32)
            with h5py.File(path, "r") as f:
                reference, quads, triangles = fs.read_blank(f)
                np.testing.assert_array_equal(quads, self.quads)
                np.testing.assert_array_equal(triangles, self.triangles)
                reference, quads, triangles = fs.read_blank(f, "tri")
                self.assertIsNone(quads)
                np.testing.assert_array_equal(triangles, self.triangles)
                with self.assertRaisesRegex(fs.ResultsError, "triangle_connectivity: missing"):
                    fs.read_blank(f, "bad")
                reference, quads, triangles = fs.read_blank(f, "blank", "000000")
                np.testing.assert_array_equal(quads, self.quads)
                reference, quads, triangles = fs.read_blank(f, "blank", "000001")
                np.testing.assert_array_equal(quads, [[0, 1, 2, 3]])
                np.testing.assert_array_equal(reference, self.reference[self.quads[0]])
                self.assertIsNone(triangles)
                with self.assertRaisesRegex(fs.ResultsError, "/parts/punch: no such group"):
                    fs.read_blank(f, "punch")


class FormingLimitMargin(unittest.TestCase):
    CURVE = [[-0.2, 0.4], [0.0, 0.25], [0.3, 0.45]]

    def test_interpolated_and_constant_beyond_the_ends(self):
        minor = np.array([-0.5, -0.2, -0.1, 0.0, 0.15, 0.3, 0.9])
        major = np.full(minor.shape, 0.3)
        # The curve's major at each minor: held 0.4 before -0.2, linear between points (0.325 at
        # -0.1, 0.35 at 0.15), held 0.45 beyond 0.3; margins exact to round-off (1e-15).
        expected = np.array([0.4, 0.4, 0.325, 0.25, 0.35, 0.45, 0.45]) - 0.3
        np.testing.assert_allclose(fs.flc_margin(minor, major, self.CURVE), expected, rtol=0,
                                   atol=1e-15)


if __name__ == "__main__":
    unittest.main()
