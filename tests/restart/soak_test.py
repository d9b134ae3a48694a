#!/usr/bin/env python3
"""Soak of kills and restarts (issue 31, item 5): the aluminium square cup, shortened with
--stroke, run RUNS times; each run is stopped 1 to 3 times at random moments (so at random cycles)
by SIGKILL or SIGTERM, on 1 or 2 threads at random for each part, and continued each time with
`--restart results/checkpoint.h5` (or, after a SIGKILL before the first checkpoint, started
again with --overwrite), until it ends. Every final result must be the uninterrupted run's bits
(scripts/compare_results.py: every results.h5 dataset and summary.json number), and after every
kill the results folder must agree with itself as tests/restart/kill_results_test.py checks.

    soak_test.py SHEETFORM SOURCE_DIR WORK_DIR [--runs 50] [--seed 1] [--stroke 2]

Seeded (--seed or SF_SOAK_SEED): the same seed draws the same kills, signals, moments and thread
counts (the cycles they land on vary with the machine's speed). Exit 0 when every run gives the
uninterrupted run's bits, 1 otherwise (the failing runs' folders and logs are kept).
"""
import argparse
import os
import pathlib
import random
import shutil
import signal
import subprocess
import sys
import time

import h5py

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import kill_results_test as kill_check  # noqa: E402  (the folder check, the writers' wait)


class Soak:
    def __init__(self, args):
        self.args = args
        self.case = args.source / "cases" / "square_cup_aluminium" / "case.toml"
        self.env = dict(os.environ, OMP_WAIT_POLICY="passive")
        self.counts = {"SIGKILL": 0, "SIGTERM": 0, "restart": 0, "fresh": 0, "ended_first": 0,
                       "runs_stopped": 0}
        self.duration = 1.0  # s, a whole run's wall time: measured, then followed (the load varies)
        self.cycles = []  # cycles the restarts went on from
        self.total_cycles = 1

    def command(self, folder, threads, extra=()):
        return [str(self.args.sheetform), "run", str(self.case), "-q", "-o", str(folder),
                "--stroke", str(self.args.stroke), "--threads", str(threads),
                "--set", "control.checkpoint_cycles=300", *extra]

    def reference(self):
        folder = self.args.work / "uninterrupted"
        started = time.monotonic()
        done = subprocess.run(self.command(folder, 1), env=self.env, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True)
        if done.returncode != 0:
            sys.exit(f"soak: the uninterrupted run failed:\n{done.stdout[-3000:]}")
        with h5py.File(folder / "results.h5", "r") as h5:
            self.total_cycles = int(h5["parts/blank/frames"][sorted(h5["parts/blank/frames"])[-1]]
                                    .attrs["cycle"])
        return folder, time.monotonic() - started

    def segment(self, folder, log, threads, extra, kill):
        """One part of a run: started, and stopped by kill = (signal, seconds) unless None.
        Returns its exit status (negative: the signal that ended it)."""
        with open(log, "a") as out:
            out.write(f"$ {' '.join(self.command(folder, threads, extra))}  # kill {kill}\n")
            out.flush()
            process = subprocess.Popen(self.command(folder, threads, extra), env=self.env,
                                       stdout=out, stderr=subprocess.STDOUT)
            started = time.monotonic()
            try:
                status = process.wait(timeout=None if kill is None else kill[1])
                self.elapsed = time.monotonic() - started  # it ran to its end
                return status
            except subprocess.TimeoutExpired:
                process.send_signal(kill[0])
                return process.wait()

    def follow_the_load(self, cycle):
        """A segment that ran to its end from `cycle` took self.elapsed s: the whole run's wall
        time it implies updates self.duration, so that the kill moments follow the machine's
        load."""
        whole = self.elapsed / max(0.2, 1.0 - cycle / self.total_cycles)
        self.duration = 0.7 * self.duration + 0.3 * whole

    def one_run(self, index, reference):
        rng = random.Random(self.args.seed * 1000003 + index)
        folder = self.args.work / f"run{index:03d}"
        log = self.args.work / f"run{index:03d}.log"
        shutil.rmtree(folder, ignore_errors=True)
        log.unlink(missing_ok=True)
        problems, extra, cycle, stopped = [], (), 0, 0
        stops = rng.randint(1, 3)
        for stop in range(stops + 1):
            threads = rng.choice((1, 2))
            kill = None
            if stop < stops:
                # Over most of what is left of the run (its time from the cycle it goes on
                # from), so that nearly every drawn signal lands before the end.
                left = 0.8 * self.duration * max(0.2, 1.0 - cycle / self.total_cycles)
                kill = (rng.choice((signal.SIGKILL, signal.SIGTERM)), rng.uniform(0.0, left))
            status = self.segment(folder, log, threads, extra, kill)
            if status == 0:
                self.follow_the_load(cycle)
                if kill is not None:
                    self.counts["ended_first"] += 1
                break
            if kill is None or status not in (5, -signal.SIGKILL, -signal.SIGTERM):
                problems.append(f"exit {status} (stop {stop}, {kill})")
                break
            self.counts[signal.Signals(kill[0]).name] += 1
            self.counts["runs_stopped"] += stop == 0
            stopped += 1
            kill_check.wait_for_writers(folder)
            problems += [f"after {signal.Signals(kill[0]).name}: {p}"
                         for p in kill_check.check_folder(folder)]
            extra, cycle = self.go_on_from(folder)
        else:
            problems.append("did not end")
        if not problems:
            compare = subprocess.run(
                ["/usr/bin/python3", str(self.args.source / "scripts" / "compare_results.py"),
                 str(reference), str(folder)], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                text=True)
            if compare.returncode != 0:
                problems.append("not the uninterrupted run's bits: " +
                                " | ".join(compare.stdout.splitlines()[:4]))
        if not problems:
            shutil.rmtree(folder, ignore_errors=True)
            log.unlink(missing_ok=True)
        return stopped, problems

    def go_on_from(self, folder):
        """The next part's options, a restart from the checkpoint or a new start, and the cycle
        it goes on from."""
        checkpoint = folder / "checkpoint.h5"
        if checkpoint.exists():
            with h5py.File(checkpoint, "r") as h5:
                self.cycles.append(int(h5["state/cycle"][0]))
            self.counts["restart"] += 1
            return ("--restart", str(checkpoint)), self.cycles[-1]
        self.counts["fresh"] += 1
        return ("--overwrite",), 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sheetform", type=pathlib.Path)
    parser.add_argument("source", type=pathlib.Path)
    parser.add_argument("work", type=pathlib.Path)
    parser.add_argument("--runs", type=int, default=50)
    parser.add_argument("--seed", type=int, default=int(os.environ.get("SF_SOAK_SEED", "1")))
    parser.add_argument("--stroke", type=float, default=2.0, help="mm (the case's is 40)")
    args = parser.parse_args()
    kill_check.become_subreaper()
    shutil.rmtree(args.work, ignore_errors=True)
    args.work.mkdir(parents=True)
    soak = Soak(args)
    started = time.monotonic()
    reference, soak.duration = soak.reference()
    print(f"uninterrupted run: {soak.duration:.1f} s (--stroke {args.stroke}); seed {args.seed}",
          flush=True)
    failures = 0
    for index in range(args.runs):
        stops, problems = soak.one_run(index, reference)
        print(f"run {index:2d}: {stops} stop(s): " + ("same bits" if not problems else
                                                     "FAIL: " + "; ".join(problems)), flush=True)
        failures += bool(problems)
    c, cycles = soak.counts, sorted(soak.cycles)
    print(f"{args.runs} runs ({c['runs_stopped']} stopped at least once): {c['SIGKILL']} SIGKILL, "
          f"{c['SIGTERM']} SIGTERM, "
          f"{c['restart']} restarts from a checkpoint (cycles {cycles[:1]}..{cycles[-1:]}), "
          f"{c['fresh']} new starts (killed before a checkpoint), {c['ended_first']} signals "
          f"after the end; {failures} failing; {time.monotonic() - started:.0f} s in all")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
