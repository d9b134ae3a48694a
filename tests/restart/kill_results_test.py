#!/usr/bin/env python3
"""Results that agree after any kill (issue 31, item 3): runs a small case that writes a frame
every few cycles and a checkpoint every few dozen, SIGKILLs it at many wall-clock moments spread
over the whole run (meshing, start, time loop, frame and checkpoint writes), and after each kill
checks what a reader without a restart finds in the results folder:

- no `*.tmp` file is left;
- results.h5, when it exists, opens, and the frames it holds are frames 0..n-1 with n its commit
  record (`/parts` attribute `frames`; a file without one holds every frame group it has);
- every part's .xdmf lists exactly those frames (the same group names and times), and every part
  of results.h5 has its .xdmf;
- every dataset a .xdmf names reads back with the shape the .xdmf gives.

    kill_results_test.py SHEETFORM SOURCE_DIR WORK_DIR [--kills N] [--seed S]

The kill moments are stratified over the uninterrupted run's wall time (one random moment in each
of N equal slices, seeded), so that the run's every phase is hit, wherever its writes fall.
Exit 0 when every kill leaves agreeing files, 1 (listing the kills and what disagreed) otherwise.
"""
import argparse
import concurrent.futures
import ctypes
import os
import pathlib
import random
import re
import shutil
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ElementTree

import h5py

PR_SET_CHILD_SUBREAPER = 36


def become_subreaper():
    """Orphans of a killed run (a results writer finishing its write) become our children rather
    than init's, so that we can reap them (wait_for_writers)."""
    libc = ctypes.CDLL(None, use_errno=True)
    libc.prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)  # without it, init reaps them: also fine


def writers_of(folder):
    """Live processes (not zombies) whose command line names `folder`: what is left of a run."""
    pids = []
    for entry in pathlib.Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            if str(folder) not in (entry / "cmdline").read_bytes().decode(errors="replace"):
                continue
            if (entry / "stat").read_text().rsplit(")", 1)[1].split()[0] != "Z":
                pids.append(int(entry.name))
        except OSError:
            continue  # ended meanwhile
    return pids


def wait_for_writers(folder):
    """Waits until no process of the killed run is left (a writer finishes the write under way):
    the files are then what a reader finds. Returns whether one was left."""
    left = writers_of(folder)
    while writers_of(folder):
        time.sleep(0.001)
    for pid in left:
        try:
            os.waitpid(pid, 0)
        except ChildProcessError:
            pass  # init's child, not ours
    return bool(left)


def run_args(sheetform, source, folder):
    case = source / "cases" / "square_cup_steel" / "case.toml"
    return [str(sheetform), "run", str(case), "-q", "--threads", "1", "-o", str(folder),
            "--stroke", "0.1", "--set", "blank.element_size=3.75",
            "--set", "tools[0].element_size=6", "--set", "tools[1].element_size=6",
            "--set", "tools[2].element_size=6", "--set", "control.output_frames=40",
            "--set", "control.history_interval=3", "--set", "control.checkpoint_cycles=20"]


def xdmf_frames(path):
    """[(grid name, time, [(dataset, dims)])] of a part's .xdmf, in order."""
    root = ElementTree.parse(path).getroot()
    frames = []
    for grid in root.iter("Grid"):
        if grid.get("GridType") != "Uniform":
            continue
        time_value = float(grid.find("Time").get("Value"))
        items = []
        for item in grid.iter("DataItem"):
            file_name, _, dataset = item.text.strip().partition(":")
            if file_name != "results.h5":
                raise AssertionError(f"{path.name}: DataItem names {file_name}, not results.h5")
            items.append((dataset, tuple(int(d) for d in item.get("Dimensions").split())))
        frames.append((grid.get("Name"), time_value, items))
    return frames


def held_frames(h5, part):
    """The frames results.h5 holds for `part`, as a reader sees them: 0..n-1 with n the commit
    record when there is one, else every frame group."""
    groups = sorted(h5[f"parts/{part}/frames"].keys())
    if "frames" in h5["parts"].attrs:
        count = int(h5["parts"].attrs["frames"])
        missing = [g for g in (f"{k:06d}" for k in range(count)) if g not in groups]
        if missing:
            raise AssertionError(f"part {part}: committed frame(s) {missing} missing")
        return [f"{k:06d}" for k in range(count)]
    return groups


def check_folder(folder):
    """The problems a reader would meet in `folder` (an empty list when the files agree)."""
    problems = [f"{p.name} left behind" for p in folder.glob("*.tmp")]
    h5_path = folder / "results.h5"
    xdmfs = sorted(folder.glob("*.xdmf"))
    if not h5_path.exists():
        if xdmfs:
            problems.append(f"{xdmfs[0].name} exists but results.h5 does not")
        return problems
    try:
        h5 = h5py.File(h5_path, "r")
    except OSError as error:
        return problems + [f"results.h5 does not open: {error}"]
    with h5:
        parts = sorted(h5["parts"].keys()) if "parts" in h5 else []
        if {p.stem for p in xdmfs} != set(parts):
            problems.append(f"parts {parts}, .xdmf files {[p.name for p in xdmfs]}")
        for part in parts:
            problems += check_part(folder, h5, part)
    return problems


def check_part(folder, h5, part):
    xdmf = folder / f"{part}.xdmf"
    if not xdmf.exists():
        return []  # said above
    try:
        held = held_frames(h5, part)
        listed = xdmf_frames(xdmf)
    except (AssertionError, KeyError, OSError, ElementTree.ParseError) as error:
        return [f"{part}: {error}"]
    names = [re.sub(r"^.*_", "", name) for name, _, _ in listed]
    if names != held:
        return [f"{xdmf.name} lists frames {names[-3:]} (of {len(names)}), results.h5 holds "
                f"{held[-3:]} (of {len(held)})"]
    problems = []
    for (name, time_value, items), group in zip(listed, held):
        try:
            frame = h5[f"parts/{part}/frames/{group}"]
            if float(frame.attrs["time"]) != time_value:
                problems.append(f"{name}: time {time_value}, results.h5 {frame.attrs['time']}")
            for dataset, dims in items:
                values = h5[dataset][()]
                if values.shape != dims and values.size != dims[0]:
                    problems.append(f"{name}: {dataset} has shape {values.shape}, .xdmf {dims}")
        except (KeyError, OSError) as error:
            problems.append(f"{name}: unreadable ({error})")
    return problems


def time_the_run(command, env, folder):
    """Runs `command` to its end: (seconds until its results.h5 appeared, seconds in all)."""
    started = time.monotonic()
    process = subprocess.Popen(command, env=env, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True)
    first_write = None
    while process.poll() is None:
        if first_write is None and (folder / "results.h5").exists():
            first_write = time.monotonic() - started
        time.sleep(0.002)
    duration = time.monotonic() - started
    output = process.stdout.read()
    if process.returncode != 0 or first_write is None:
        sys.exit(f"kill_results_test: the uninterrupted run failed:\n{output[-2000:]}")
    return first_write, duration


def kill_and_check(command, env, folder, moment):
    """Starts the run and SIGKILLs it at `moment` = (seconds, "start" or "results"): counted from
    its start, or from when its results.h5 appeared (so that the kill lands in the writing phase
    however long the start took). Then waits for what is left of the run and checks the folder:
    (problems, whether it was killed, whether a write was under way, frames held)."""
    seconds, origin = moment
    process = subprocess.Popen(command, env=env, stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL)
    if origin == "results":
        while not (folder / "results.h5").exists() and process.poll() is None:
            time.sleep(0.001)
    time.sleep(seconds)
    process.send_signal(signal.SIGKILL)
    process.wait()
    in_write = wait_for_writers(folder)
    problems = check_folder(folder)
    frames = None
    if not problems and (folder / "results.h5").exists():
        with h5py.File(folder / "results.h5", "r") as h5:
            frames = len(held_frames(h5, "blank"))
    if not problems:
        shutil.rmtree(folder, ignore_errors=True)
    return problems, process.returncode == -signal.SIGKILL, in_write, frames


def kill_moments(kills, first_write, duration, seed):
    """One random moment in each of `kills` equal slices: a tenth of them from the start to the
    results' creation (meshing, set-up), the rest over the time the run writes (to a little
    before its end: the runs' wall times vary)."""
    rng = random.Random(seed)
    early = max(1, kills // 10)
    writing = 0.9 * (duration - first_write)
    moments = [(first_write * (k + rng.random()) / early, "start") for k in range(early)]
    moments += [(writing * (k + rng.random()) / (kills - early), "results")
                for k in range(kills - early)]
    return moments


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sheetform", type=pathlib.Path)
    parser.add_argument("source", type=pathlib.Path)
    parser.add_argument("work", type=pathlib.Path)
    parser.add_argument("--kills", type=int, default=36)
    parser.add_argument("--jobs", type=int, default=2, help="runs killed at once")
    parser.add_argument("--seed", type=int, default=int(os.environ.get("SF_KILL_SEED", "1")))
    args = parser.parse_args()
    become_subreaper()
    shutil.rmtree(args.work, ignore_errors=True)
    args.work.mkdir(parents=True)
    env = dict(os.environ, OMP_WAIT_POLICY="passive")

    # Timed as the killed runs will go: `jobs` at once.
    started = time.monotonic()
    wholes = [args.work / f"whole{j}" for j in range(args.jobs)]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        timings = list(pool.map(
            lambda folder: time_the_run(run_args(args.sheetform, args.source, folder), env,
                                        folder), wholes))
    first_write = sum(t[0] for t in timings) / len(timings)
    duration = sum(t[1] for t in timings) / len(timings)
    with h5py.File(wholes[0] / "results.h5", "r") as h5:
        frames = len(h5["parts/blank/frames"])
    print(f"uninterrupted runs ({args.jobs} at once): {duration:.2f} s, results from "
          f"{first_write:.2f} s, {frames} frames; seed {args.seed}")

    moments = kill_moments(args.kills, first_write, duration, args.seed)
    folders = [args.work / f"kill{k:03d}" for k in range(args.kills)]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        outcomes = list(pool.map(
            lambda k: kill_and_check(run_args(args.sheetform, args.source, folders[k]), env,
                                     folders[k], moments[k]), range(args.kills)))
    failures = 0
    for k, (problems, killed, in_write, held) in enumerate(outcomes):
        status = "ok" if not problems else "FAIL: " + "; ".join(problems)
        when = "" if killed else " (the run had ended)"
        seconds, origin = moments[k]
        print(f"kill {k:2d} at {seconds:6.3f} s after its {origin}{when}: {held} frames, "
              f"{'a write under way, ' if in_write else ''}{status}")
        failures += bool(problems)
    held = [h for _, _, _, h in outcomes if h is not None]
    print(f"{args.kills} kills: {sum(o[1] for o in outcomes)} killed a run, "
          f"{sum(o[2] for o in outcomes)} during a results write, {len(held)} after results.h5 "
          f"existed (frames held {min(held, default=0)}..{max(held, default=0)}); "
          f"{failures} disagreeing; {time.monotonic() - started:.1f} s in all")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
