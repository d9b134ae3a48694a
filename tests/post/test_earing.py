"""Unit tests of scripts/earing.py: the ears of known rim profiles, written as a quarter model's
results.h5 (reference rim at 70 mm, current rim radius R(theta)).

Run: /usr/bin/python3 -m unittest tests/post/test_earing.py   (or run this file)

Exact answers: R = 60 + A cos(k theta) on the quarter, mirrored by the symmetry planes, has k ears
at theta = 360 j / k for k = 2, 4, 6 (orthotropic profiles: even in theta and in 180 - theta);
the earing height is 2A up to the rim's sampling (nodes every 2.5 deg: for k = 6 the lowest point
sampled is cos(6 * 30) exactly, so 2A holds to round-off). A ripple below the prominence is no ear.
"""
import math
import os
import sys
import tempfile
import unittest

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import earing  # noqa: E402


def write_quarter(path, radius_of_angle):
    """A quarter disc's rim (every 2.5 deg) and one inner node, reference and current."""
    angles = np.radians(np.arange(0.0, 90.0 + 1e-9, 2.5))
    ref = np.array([[70 * math.cos(a), 70 * math.sin(a), 0.0] for a in angles] + [[0.0, 0.0, 0.0]])
    cur = np.array([[radius_of_angle(a) * math.cos(a), radius_of_angle(a) * math.sin(a), -3.0]
                    for a in angles] + [[0.0, 0.0, -40.0]])
    with h5py.File(path, "w") as f:
        blank = f.create_group("parts/blank")
        blank["reference_coordinates"] = ref
        blank.create_group("frames/000000")["coordinates"] = ref
        blank.create_group("frames/000001")["coordinates"] = cur


class EaringTest(unittest.TestCase):
    def ears_of(self, radius_of_angle, prominence=0.05):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "results.h5")
            write_quarter(path, radius_of_angle)
            angle, radius = earing.rim_profile(path)
        a, r = earing.full_circle(angle, radius)
        self.assertEqual(len(a), 144)  # 360 / 2.5: the mirrored copies of 0, 90, ... counted once
        return earing.extrema(a, r, prominence), r

    def test_k_ears_at_their_angles(self):
        for k in (2, 4, 6):
            (ears, valleys), r = self.ears_of(lambda t, k=k: 60.0 + 0.8 * math.cos(k * t))
            self.assertEqual(len(ears), k, f"k = {k}")
            np.testing.assert_allclose(sorted(ears), [360.0 * j / k for j in range(k)], atol=1e-9)
            np.testing.assert_allclose(sorted(valleys), [360.0 * (j + 0.5) / k for j in range(k)],
                                       atol=1e-9)
            self.assertAlmostEqual(r.max() - r.min(), 1.6, places=12)

    def test_ears_at_45_degrees(self):
        (ears, _), _ = self.ears_of(lambda t: 60.0 - 0.5 * math.cos(4 * t))
        np.testing.assert_allclose(sorted(ears), [45.0, 135.0, 225.0, 315.0], atol=1e-9)

    def test_a_ripple_below_the_prominence_is_no_ear(self):
        # Four ears at 0/90/.. with flat valleys carrying a 0.01 mm ripple (36 lobes): the
        # ripple's peaks stand 0.02 mm out, below the default 0.05, so four ears; with a
        # prominence of 0.001 mm they count.
        def profile(t):
            return 60.0 + 0.8 * max(math.cos(4 * t), 0.0) + 0.01 * math.cos(36 * t)
        (ears, _), _ = self.ears_of(profile)
        np.testing.assert_allclose(sorted(ears), [0.0, 90.0, 180.0, 270.0], atol=1e-9)
        (ears, _), _ = self.ears_of(profile, prominence=0.001)
        self.assertGreater(len(ears), 4)

if __name__ == "__main__":
    unittest.main()
