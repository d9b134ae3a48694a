#!/usr/bin/env python3
"""The regression suite over the case folders: run, measure, compare, and bless.

Each case folder under cases/ that holds a `reference.toml` is a regression case. The file says
which searches the case runs with, how to shorten it for CI, and each metric's reference value,
tolerance and source (docs/regression.md). For every case and search this script runs

    sheetform run CASE/case.toml -o WORK/CASE/SEARCH-LENGTH -q --search SEARCH [--stroke S]

extracts the metrics from the run's summary.json and results.h5, compares each with its
reference and prints one table. Exit status 0 when every gated metric is within tolerance, 1
when one is not or a run failed, 2 for bad usage or a bad reference file.

    scripts/regress.py run cases/square_cup_aluminium --search standard --length short
    scripts/regress.py run cases/* --length full              # every case, every search
    scripts/regress.py run cases/u_channel_bhf_2450N --bless   # rewrite the reference values
    scripts/regress.py list                                    # the cases and their searches

--bless rewrites only reference.toml files: the `value` of each metric of kind "regression"
(never an "exact" or "published" one), from the run with the case's first search, and the
`blessed` line of the length it ran. Comments and layout are kept (tomlkit).

Metric sources (`from`):
  summary:<dotted.path>                 a number in summary.json, e.g. draw_in.DX.computed_mm
  history:<column>:<reduction>          max, min, first, last, or last_over_first
  history:<column>@<column2>=<x>        <column> where <column2> first reaches x (linear
                                        interpolation between history rows), e.g.
                                        history:draw_in_DX@punch_travel=15
  history:<column>:duration_above=<y>   time from the first to the last row with |<column>| > y
  field:<name>[<component>]:<reduction> a blank field of the last frame: min, max, mean,
                                        absmax, spread (max - min); [<component>] optional (0)
  <source> - <source>                   the difference of two of the above, e.g.
                                        summary:draw_in.D45.computed_mm - summary:draw_in.D0.computed_mm

Gates: a metric passes when |x - value| <= max(abs, rel |value|); a metric of kind "exact" or
"published" may instead (or also) give bounds, `min` and/or `max` (x >= min, x <= max), for a
result whose published form is an inequality (an ear at 0 degrees: D45 - D0 > 0); its `value`
is then optional.
"""
import argparse
import datetime
import json
import math
import os
import pathlib
import shutil
import subprocess
import sys
import time

import h5py
import numpy as np

try:
    import tomlkit
except ImportError:  # pragma: no cover - scripts/setup.sh installs python3-tomlkit
    sys.exit("regress.py needs tomlkit (Debian: python3-tomlkit; scripts/setup.sh installs it)")

ROOT = pathlib.Path(__file__).resolve().parent.parent
LENGTHS = ("short", "full")
KINDS = ("regression", "exact", "published")


class ReferenceFileError(Exception):
    """A reference.toml that cannot be used: names the file and the key."""


class MetricError(Exception):
    """A metric that cannot be extracted from a run: names the source."""


# ---------------------------------------------------------------------------- reference files
def load_reference(case_dir):
    path = case_dir / "reference.toml"
    if not path.is_file():
        raise ReferenceFileError(f"{path}: missing (a regression case needs a reference.toml)")
    try:
        doc = tomlkit.parse(path.read_text())
    except Exception as error:  # tomlkit raises several types
        raise ReferenceFileError(f"{path}: {error}") from error
    allowed = {"searches", "ci_searches", *LENGTHS}
    for key in doc:
        if key not in allowed:
            raise ReferenceFileError(f"{path}: unknown key '{key}' (expected {sorted(allowed)})")
    searches = list(doc.get("searches", []))
    for s in searches:
        if s not in ("standard", "modified", "cached"):
            raise ReferenceFileError(f"{path}: searches: unknown search '{s}'")
    # ci_searches: the searches whose short run is in CI (tests/CMakeLists.txt labels the other
    # short runs slow); default all of them.
    for s in doc.get("ci_searches", []):
        if s not in searches:
            raise ReferenceFileError(f"{path}: ci_searches: '{s}' is not one of searches {searches}")
    if "short" not in doc:
        raise ReferenceFileError(f"{path}: missing table [short] (the CI version)")
    for length in LENGTHS:
        if length in doc:  # [full] is absent when the case is short as it is
            check_length_table(path, length, doc[length])
    return path, doc, searches or ["none"]


def check_length_table(path, length, table):
    allowed = {"stroke", "end_time", "set", "blessed", "metrics", "note"}
    for key in table:
        if key not in allowed:
            raise ReferenceFileError(f"{path}: unknown key '{length}.{key}' (expected {sorted(allowed)})")
    if "stroke" in table and "end_time" in table:
        raise ReferenceFileError(f"{path}: {length}: give stroke or end_time, not both")
    overrides = table.get("set", [])
    if not isinstance(overrides, list) or not all(isinstance(o, str) and "=" in o for o in overrides):
        raise ReferenceFileError(f"{path}: {length}.set: expected a list of \"KEY=VALUE\" strings "
                                 "(sheetform run --set), e.g. [\"operations[0].stroke=10.0\"]")
    if overrides and length != "short":
        raise ReferenceFileError(f"{path}: {length}.set: only the short version changes the case")
    metrics = table.get("metrics", {})
    if not metrics:
        raise ReferenceFileError(f"{path}: [{length}.metrics] has no metric")
    for name, m in metrics.items():
        where = f"{path}: {length}.metrics.{name}"
        for key in m:
            if key not in {"from", "value", "rel", "abs", "min", "max", "unit", "kind", "gate", "source"}:
                raise ReferenceFileError(f"{where}: unknown key '{key}'")
        bounded = "min" in m or "max" in m
        for key in ("from", "source") if bounded else ("from", "value", "source"):
            if key not in m:
                raise ReferenceFileError(f"{where}: missing '{key}'")
        kind = m.get("kind", "regression")
        if kind not in KINDS:
            raise ReferenceFileError(f"{where}.kind: '{kind}', expected one of {KINDS}")
        if bounded and kind == "regression":
            raise ReferenceFileError(f"{where}: min/max bound an exact or published result; a regression "
                                     "value is blessed, not bounded (give kind = \"exact\" or \"published\")")
        if "min" in m and "max" in m and not float(m["min"]) <= float(m["max"]):
            raise ReferenceFileError(f"{where}: min {m['min']} is above max {m['max']}")
        if ("rel" in m or "abs" in m) and "value" not in m:
            raise ReferenceFileError(f"{where}: a tolerance (rel/abs) needs the 'value' it is around")
        if m.get("gate", True) and "rel" not in m and "abs" not in m and not bounded:
            raise ReferenceFileError(f"{where}: a gated metric needs a tolerance (rel and/or abs) or bounds (min/max)")
        for key in ("rel", "abs"):
            if key in m and not float(m[key]) >= 0.0:
                raise ReferenceFileError(f"{where}.{key}: expected a number >= 0")


# ---------------------------------------------------------------------------- metric extraction
class Run:
    """The outputs of one run, read lazily."""

    def __init__(self, directory):
        self.directory = directory
        self._summary = None
        self._h5 = None

    def summary(self):
        if self._summary is None:
            self._summary = json.loads((self.directory / "summary.json").read_text())
        return self._summary

    def h5(self):
        if self._h5 is None:
            self._h5 = h5py.File(self.directory / "results.h5", "r")
        return self._h5

    def history(self, column):
        h = self.h5()["history"]
        if column not in h:
            raise MetricError(f"history has no column '{column}' (has: {', '.join(sorted(h))})")
        return np.asarray(h[column][:], dtype=float)

    def last_field(self, name):
        frames = self.h5()["parts/blank/frames"]
        last = frames[sorted(frames)[-1]]
        if name not in last:
            raise MetricError(f"the last frame has no blank field '{name}' (has: {', '.join(sorted(last))})")
        return np.asarray(last[name][:], dtype=float)

    def close(self):
        if self._h5 is not None:
            self._h5.close()


def reduce(values, reduction, source):
    if values.size == 0:
        raise MetricError(f"{source}: no values")
    if reduction == "max":
        return float(values.max())
    if reduction == "min":
        return float(values.min())
    if reduction == "mean":
        return float(values.mean())
    if reduction == "absmax":
        return float(np.abs(values).max())
    if reduction == "spread":
        return float(values.max() - values.min())
    if reduction == "first":
        return float(values[0])
    if reduction == "last":
        return float(values[-1])
    if reduction == "last_over_first":
        return float(values[-1] / values[0])
    raise MetricError(f"{source}: unknown reduction '{reduction}'")


def value_where(y, x, target, source):
    """y where x first reaches target, interpolated linearly between rows."""
    above = np.nonzero(x >= target)[0]
    if above.size == 0:
        raise MetricError(f"{source}: the run never reached {target} (largest {x.max():.6g})")
    i = int(above[0])
    if i == 0:
        return float(y[0])
    w = (target - x[i - 1]) / (x[i] - x[i - 1])
    return float(y[i - 1] + w * (y[i] - y[i - 1]))


def extract(run, source):
    if " - " in source:  # the difference of two sources
        first, _, second = source.partition(" - ")
        return extract(run, first.strip()) - extract(run, second.strip())
    kind, _, rest = source.partition(":")
    if kind == "summary":
        node = run.summary()
        for key in rest.split("."):
            if not isinstance(node, dict) or key not in node:
                raise MetricError(f"{source}: summary.json has no '{key}'")
            node = node[key]
        if not isinstance(node, (int, float)) or isinstance(node, bool):
            raise MetricError(f"{source}: not a number in summary.json")
        return float(node)
    if kind == "history":
        if "@" in rest:
            column, _, condition = rest.partition("@")
            other, _, target = condition.partition("=")
            return value_where(run.history(column), run.history(other), float(target), source)
        column, _, reduction = rest.partition(":")
        if reduction.startswith("duration_above="):
            threshold = float(reduction.partition("=")[2])
            t, y = run.history("time"), np.abs(run.history(column))
            above = np.nonzero(y > threshold)[0]
            if above.size == 0:
                raise MetricError(f"{source}: '{column}' never exceeds {threshold}")
            return float(t[above[-1]] - t[above[0]])
        return reduce(run.history(column), reduction, source)
    if kind == "field":
        spec, _, reduction = rest.partition(":")
        name, component = spec, 0
        if "[" in spec:
            name, _, index = spec.partition("[")
            component = int(index.rstrip("]"))
        values = run.last_field(name)
        if component >= values.shape[1]:
            raise MetricError(f"{source}: field '{name}' has {values.shape[1]} components")
        return reduce(values[:, component], reduction, source)
    raise MetricError(f"{source}: unknown source kind '{kind}' (summary, history or field)")


# ---------------------------------------------------------------------------- running and comparing
def run_case(sheetform, case_dir, search, length, table, work, verbose):
    out = work / case_dir.name / f"{search}-{length}"
    if out.exists():
        shutil.rmtree(out)
    command = [str(sheetform), "run", str(case_dir / "case.toml"), "-o", str(out), "-q"]
    if search != "none":
        command += ["--search", search]
    if length == "short" and "stroke" in table:
        command += ["--stroke", repr(float(table["stroke"]))]
    if length == "short" and "end_time" in table:
        command += ["--end-time", repr(float(table["end_time"]))]
    for override in table.get("set", []) if length == "short" else []:
        command += ["--set", override]
    if verbose:
        print("$", " ".join(command), flush=True)
    start = time.monotonic()
    proc = subprocess.run(command, capture_output=True, text=True)
    seconds = time.monotonic() - start
    log = proc.stdout + proc.stderr
    (work / case_dir.name).mkdir(parents=True, exist_ok=True)
    (work / case_dir.name / f"{search}-{length}.log").write_text(" ".join(command) + "\n" + log)
    return out, proc.returncode, log, seconds


def within(value, reference, rel, abs_tol):
    return abs(value - reference) <= max(abs_tol, rel * abs(reference))


def passes(value, m):
    """Whether a gated metric's value meets its tolerance and its bounds (either may be absent)."""
    if not math.isfinite(value):
        return False
    if ("rel" in m or "abs" in m) and not within(value, float(m["value"]), float(m.get("rel", 0.0)),
                                                   float(m.get("abs", 0.0))):
        return False
    if "min" in m and value < float(m["min"]):
        return False
    return not ("max" in m and value > float(m["max"]))


def tolerance_text(m):
    rel, abs_tol = float(m.get("rel", 0.0)), float(m.get("abs", 0.0))
    parts = [f"{rel:g} rel" if rel else "", f"{abs_tol:g} abs" if abs_tol else ""]
    if "min" in m:
        parts.append(f">= {float(m['min']):g}")
    if "max" in m:
        parts.append(f"<= {float(m['max']):g}")
    return " ".join(p for p in parts if p)


def compare(run, metrics):
    """Rows (name, value, reference or None, tolerance text, status, metric) for every metric."""
    rows = []
    for name, m in metrics.items():
        reference = float(m["value"]) if "value" in m else None
        try:
            value = extract(run, str(m["from"]))
        except (MetricError, OSError, KeyError, ValueError) as error:
            rows.append((name, None, reference, "", f"ERROR {error}", m))
            continue
        if not m.get("gate", True):
            status = "info"
        elif not math.isfinite(value):
            status = "FAIL (not finite)"
        else:
            status = "ok" if passes(value, m) else "FAIL"
        rows.append((name, value, reference, tolerance_text(m), status, m))
    return rows


def deviation(value, reference):
    if value is None or reference is None or reference == 0.0:
        return ""
    return f"{100.0 * (value - reference) / abs(reference):+.2f} %"


def print_table(results):
    header = ("case", "search", "length", "metric", "value", "reference", "deviation", "tolerance", "kind", "status")
    lines = [header]
    for case, search, length, rows in results:
        for name, value, reference, tolerance, status, m in rows:
            unit = f" {m['unit']}" if "unit" in m else ""
            shown = "-" if value is None else f"{value:.6g}{unit}"
            shown_reference = "-" if reference is None else f"{reference:.6g}{unit}"
            lines.append((case, search, length, name, shown, shown_reference, deviation(value, reference),
                          tolerance, str(m.get("kind", "regression")), status))
    widths = [max(len(str(line[i])) for line in lines) for i in range(len(header))]
    for k, line in enumerate(lines):
        print("  ".join(str(c).ljust(w) for c, w in zip(line, widths)).rstrip())
        if k == 0:
            print("  ".join("-" * w for w in widths))


def program_hash(run):
    """The commit of the sheetform that made the run (its summary.json), not the tree's HEAD:
    --sheetform may name another build."""
    value = run.summary().get("git_hash", "unknown")
    return value if isinstance(value, str) and value else "unknown"


def bless(path, doc, length, run, search):
    table = doc[length]
    for name, m in table["metrics"].items():
        if m.get("kind", "regression") != "regression":
            continue
        try:
            m["value"] = extract(run, str(m["from"]))
        except (MetricError, OSError, KeyError, ValueError) as error:
            raise MetricError(f"{path}: {length}.metrics.{name}: {error}") from error
    table["blessed"] = f"{datetime.date.today().isoformat()}, sheetform {program_hash(run)}, search {search}"
    path.write_text(tomlkit.dumps(doc))


def find_cases(paths):
    cases = []
    for p in paths:
        p = pathlib.Path(p).resolve()
        if (p / "reference.toml").is_file():
            cases.append(p)
        elif p.is_dir() and any(p.glob("*/reference.toml")):
            cases += sorted(q.parent for q in p.glob("*/reference.toml"))
        else:
            raise ReferenceFileError(f"{p}: not a case folder with a reference.toml")
    return cases


def command_list(args):
    for case in find_cases(args.cases or [ROOT / "cases"]):
        _, _, searches = load_reference(case)
        print(case.name, " ".join(searches))
    return 0


def command_run(args):
    sheetform = pathlib.Path(args.sheetform).resolve()
    if not os.access(sheetform, os.X_OK):
        print(f"regress.py: {sheetform}: not an executable (build first, or give --sheetform)", file=sys.stderr)
        return 2
    work = pathlib.Path(args.work).resolve()
    results, failures = [], 0
    for case in find_cases(args.cases):
        path, doc, searches = load_reference(case)
        chosen = [s for s in searches if not args.search or s in args.search]
        if args.search and not chosen:
            print(f"regress.py: {case.name}: runs with {searches}, not {args.search}", file=sys.stderr)
            return 2
        for length in args.length:
            if length not in doc:
                print(f"{case.name}: no [{length}] version (the short one is the whole case)", flush=True)
                continue
            table = doc[length]
            for k, search in enumerate(chosen):
                out, code, log, seconds = run_case(sheetform, case, search, length, table, work, args.verbose)
                if code != 0:
                    failures += 1
                    print(f"FAIL {case.name} {search} {length}: sheetform exited {code}; last lines:\n"
                          + "\n".join(log.strip().splitlines()[-8:]), flush=True)
                    continue
                run = Run(out)
                try:
                    if args.bless and k == 0:
                        bless(path, doc, length, run, search)
                        print(f"blessed {path} [{length}] from the {search} run", flush=True)
                    rows = compare(run, table["metrics"])
                finally:
                    run.close()
                failures += sum(1 for r in rows if r[4] not in ("ok", "info"))
                results.append((case.name, search, length, rows))
                print(f"{case.name} {search} {length}: {seconds:.1f} s, "
                      f"{sum(1 for r in rows if r[4] == 'ok')} of {sum(1 for r in rows if r[4] != 'info')} "
                      "gated metrics within tolerance", flush=True)
    print()
    print_table(results)
    print()
    print("all within tolerance" if failures == 0 else f"{failures} failure(s)")
    return 0 if failures == 0 else 1


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    run = sub.add_parser("run", help="run cases, compare with their references")
    run.add_argument("cases", nargs="+", help="case folders (or a folder of case folders)")
    run.add_argument("--search", nargs="+", choices=("standard", "modified", "cached", "none"),
                     help="only these of each case's searches (default: all of them)")
    run.add_argument("--length", nargs="+", choices=LENGTHS, default=["short"],
                     help="short (the CI version) and/or full (default: short)")
    run.add_argument("--sheetform", default=str(ROOT / "build" / "sheetform"), help="the sheetform executable")
    run.add_argument("--work", default=str(ROOT / "build" / "regression"), help="where the runs go")
    run.add_argument("--bless", action="store_true", help="rewrite the reference values from these runs")
    run.add_argument("-v", "--verbose", action="store_true", help="print the commands")
    listing = sub.add_parser("list", help="print each case and its searches")
    listing.add_argument("cases", nargs="*")
    args = parser.parse_args()
    try:
        return command_run(args) if args.command == "run" else command_list(args)
    except ReferenceFileError as error:
        print(f"regress.py: {error}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
