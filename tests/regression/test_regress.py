"""Unit tests of scripts/regress.py: metric extraction, gates and reference-file checks, on a
hand-made run folder whose every value is known exactly (no solver run)."""
import importlib.util
import json
import pathlib
import tempfile
import unittest

import h5py
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
spec = importlib.util.spec_from_file_location("regress", ROOT / "scripts" / "regress.py")
regress = importlib.util.module_from_spec(spec)
spec.loader.exec_module(regress)


class RunFolder(unittest.TestCase):
    """A run folder with summary.json and a history of 3 rows: travel 0, 10, 20 mm."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)
        summary = {"draw_in": {"D0": {"computed_mm": 17.5}, "D45": {"computed_mm": 21.25}}, "flag": True,
                   "git_hash": "0123456789ab"}
        (self.dir / "summary.json").write_text(json.dumps(summary))
        with h5py.File(self.dir / "results.h5", "w") as f:
            f["history/time"] = np.array([0.0, 1.0, 2.0])
            f["history/punch_travel"] = np.array([0.0, 10.0, 20.0])
            f["history/force"] = np.array([0.0, -4.0, 2.0])
            f["parts/blank/frames/000001/thickness"] = np.array([[0.8], [0.7], [0.9]])
        self.run = regress.Run(self.dir)

    def tearDown(self):
        self.run.close()
        self.tmp.cleanup()

    def test_summary_history_and_field_sources(self):
        self.assertEqual(regress.extract(self.run, "summary:draw_in.D0.computed_mm"), 17.5)
        self.assertEqual(regress.extract(self.run, "history:force:absmax"), 4.0)
        self.assertEqual(regress.extract(self.run, "history:force@punch_travel=15"), -1.0)  # halfway -4 .. 2
        self.assertEqual(regress.extract(self.run, "history:force:duration_above=1"), 1.0)
        self.assertAlmostEqual(regress.extract(self.run, "field:thickness:spread"), 0.2, places=15)

    def test_difference_of_two_sources(self):
        value = regress.extract(self.run, "summary:draw_in.D45.computed_mm - summary:draw_in.D0.computed_mm")
        self.assertEqual(value, 3.75)

    def test_bad_sources_name_what_is_missing(self):
        with self.assertRaisesRegex(regress.MetricError, "no 'D90'"):
            regress.extract(self.run, "summary:draw_in.D90.computed_mm")
        with self.assertRaisesRegex(regress.MetricError, "not a number"):
            regress.extract(self.run, "summary:flag")
        with self.assertRaisesRegex(regress.MetricError, "never reached 30"):
            regress.extract(self.run, "history:force@punch_travel=30")

    def test_tolerance_and_bounds(self):
        self.assertTrue(regress.passes(10.04, {"value": 10.0, "rel": 0.005}))
        self.assertFalse(regress.passes(10.06, {"value": 10.0, "rel": 0.005}))
        self.assertTrue(regress.passes(0.3, {"value": 0.0, "abs": 0.3}))
        self.assertFalse(regress.passes(-0.31, {"value": 0.0, "abs": 0.3}))
        self.assertTrue(regress.passes(1.0, {"min": 1.0}))
        self.assertFalse(regress.passes(0.999, {"min": 1.0}))
        self.assertFalse(regress.passes(2.5, {"min": 1.0, "max": 2.0}))
        self.assertFalse(regress.passes(float("nan"), {"min": 1.0}))
        # both a tolerance and a bound: both must hold
        self.assertFalse(regress.passes(0.5, {"value": 1.0, "abs": 1.0, "min": 0.6}))

    def test_compare_rows(self):
        metrics = {"ear": {"from": "summary:draw_in.D45.computed_mm - summary:draw_in.D0.computed_mm",
                           "min": 4.0, "kind": "published", "source": "s"}}
        (name, value, reference, tolerance, status, _), = regress.compare(self.run, metrics)
        self.assertEqual((name, value, reference, tolerance, status), ("ear", 3.75, None, ">= 4", "FAIL"))

    def test_bless_rewrites_only_regression_values(self):
        path = self.dir / "reference.toml"
        path.write_text("""[short]
[short.metrics.d0]
from = "summary:draw_in.D0.computed_mm"   # kept comment
value = 1.0
rel = 0.005
source = "s"
[short.metrics.exact]
from = "summary:draw_in.D45.computed_mm"
value = 20.0
abs = 0.1
kind = "exact"
source = "s"
""")
        _, doc, _ = regress.load_reference(self.dir)
        regress.bless(path, doc, "short", self.run, "modified")
        text = path.read_text()
        _, doc, _ = regress.load_reference(self.dir)
        self.assertEqual(doc["short"]["metrics"]["d0"]["value"], 17.5)
        self.assertEqual(doc["short"]["metrics"]["exact"]["value"], 20.0)  # never rewritten
        self.assertIn("# kept comment", text)
        self.assertRegex(doc["short"]["blessed"], r"sheetform 0123456789ab, search modified$")


class ReferenceFile(unittest.TestCase):
    """load_reference refuses a file it cannot use, naming the file and the key."""

    def check(self, metric, message):
        with tempfile.TemporaryDirectory() as tmp:
            case = pathlib.Path(tmp)
            lines = [f"{k} = {json.dumps(v)}" for k, v in metric.items()]
            (case / "reference.toml").write_text("[short]\n[short.metrics.m]\n" + "\n".join(lines) + "\n")
            if message is None:
                regress.load_reference(case)
                return
            with self.assertRaisesRegex(regress.ReferenceFileError, message):
                regress.load_reference(case)

    def test_ci_searches_must_be_among_the_searches(self):
        with tempfile.TemporaryDirectory() as tmp:
            case = pathlib.Path(tmp)
            metric = '[short.metrics.m]\nfrom = "summary:x"\nvalue = 1.0\nrel = 0.01\nsource = "s"\n'
            (case / "reference.toml").write_text(
                'searches = ["modified", "standard"]\nci_searches = ["cached"]\n[short]\n' + metric)
            with self.assertRaisesRegex(regress.ReferenceFileError, "ci_searches: 'cached' is not one of searches"):
                regress.load_reference(case)
            (case / "reference.toml").write_text(
                'searches = ["modified", "standard"]\nci_searches = ["modified"]\n[short]\n' + metric)
            self.assertEqual(regress.load_reference(case)[2], ["modified", "standard"])

    def test_short_overrides_are_key_value_strings(self):
        metric = '[short.metrics.m]\nfrom = "summary:x"\nvalue = 1.0\nrel = 0.01\nsource = "s"\n'
        with tempfile.TemporaryDirectory() as tmp:
            case = pathlib.Path(tmp)
            (case / "reference.toml").write_text('[short]\nset = ["operations[0].stroke=10.0"]\n' + metric)
            regress.load_reference(case)
            for bad in ('set = "operations[0].stroke=10.0"', 'set = ["operations[0].stroke"]', "set = [1]"):
                (case / "reference.toml").write_text(f"[short]\n{bad}\n" + metric)
                with self.assertRaisesRegex(regress.ReferenceFileError, "short.set: expected a list"):
                    regress.load_reference(case)
            full = metric.replace("short", "full")
            (case / "reference.toml").write_text('[short]\n' + metric + '[full]\nset = ["a=1"]\n' + full)
            with self.assertRaisesRegex(regress.ReferenceFileError, "only the short version"):
                regress.load_reference(case)

    def test_bounds(self):
        base = {"from": "summary:x", "source": "s"}
        self.check({**base, "kind": "published", "min": 0.5}, None)
        self.check({**base, "min": 0.5}, "regression value is blessed, not bounded")
        self.check({**base, "kind": "exact", "min": 2.0, "max": 1.0}, "min 2.0 is above max 1.0")
        self.check({**base, "kind": "exact", "abs": 0.1, "min": 0.0}, "needs the 'value'")
        self.check({**base, "kind": "exact"}, "missing 'value'")
        self.check({**base, "value": 1.0}, "needs a tolerance")
        self.check({**base, "value": 1.0, "rel": -0.1}, "expected a number >= 0")
        self.check({**base, "value": 1.0, "rel": 0.1, "tolerance": 1}, "unknown key 'tolerance'")


if __name__ == "__main__":
    unittest.main()
