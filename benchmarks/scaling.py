#!/usr/bin/env python3
"""Strong scaling of one case over OpenMP threads and MPI ranks: wall time, speed-up, efficiency.

    benchmarks/scaling.py [--binary build/sheetform] [--case cases/square_cup_fine/case.toml]
                          [--out build/scaling] [--stroke 1] [--threads-list 1,2]
                          [--ranks-list 1,2] [--repeat 1] [--dry-run]

Runs the case for a short fixed stroke (default 1 mm of the fine square cup, issue 17):
  threads: `sheetform run CASE --stroke S -o OUT/threads-N -q --threads N`, OMP_NUM_THREADS=N;
  ranks:   `mpirun -np N sheetform run ... -o OUT/ranks-N` with OMP_NUM_THREADS=1 and Open MPI's
           run-as-root and oversubscribe variables (a 2-core CI box, as root).
Then prints, from each run's summary.json: wall time (the engine's `wall_seconds`; also the
whole process's wall time and the CPU time of all its threads and ranks, the steadier figure on
a shared host), speed-up and parallel efficiency, overall and per phase
(`phase_ns_per_element_cycle`: elements, contact, time_step, nodal, output, other); for MPI
runs also the per-rank phase times and the load imbalance max/mean per phase
(`phase_seconds_per_rank`: {phase: [seconds per rank]}, when the binary writes it), and each
rank's own work (its step phases less its `communication` seconds, which include waiting for
the others) with its max/mean: the imbalance of the work itself. The
oversubscribe variable only allows more ranks than cores; on a big host pass the binding
options with --mpirun-args. Each run's results stay in OUT (with --stroke 1 the fine square
cup writes about 250 MB of results.h5 per run; --set control.output_frames=2 keeps it small).

Speed-up = T(baseline) / T(run), efficiency = speed-up / (threads x ranks). The baseline is the
first thread count of --threads-list (normally 1; a plain serial run), or, without thread runs,
the first rank count. Per phase the same with the phase's seconds (ns per element-cycle x
elements x cycles).

A binary without `--threads` (before the OpenMP work) is run once without it, OMP_NUM_THREADS=1,
for the 1-thread figures; a binary that does not link MPI, or whose MPI run fails, gets its rank
runs skipped with a message. `--dry-run` prints the commands only. On a shared or small host the
figures show overheads, not a scaling curve: docs/parallel.md.
"""
import argparse
import json
import os
import pathlib
import resource
import shlex
import shutil
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
PHASES = ["elements", "contact", "time_step", "nodal", "output", "other"]
MPI_ENV = {
    "OMPI_ALLOW_RUN_AS_ROOT": "1",
    "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
    "OMPI_MCA_rmaps_base_oversubscribe": "1",
    "OMP_NUM_THREADS": "1",
}


def host_description():
    model = "unknown"
    try:
        out = subprocess.run(["lscpu"], capture_output=True, text=True, check=True).stdout
        for line in out.splitlines():
            if line.startswith("Model name:"):
                model = line.split(":", 1)[1].strip()
    except (OSError, subprocess.CalledProcessError):
        pass
    cpus = os.cpu_count()
    try:
        load = " ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:
        load = "?"
    return f'Host: "{model}" (lscpu Model name), {cpus} CPUs, load average {load}'


def int_list(text):
    try:
        values = [int(x) for x in text.split(",") if x.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}': a comma-separated list of integers")
    if any(v < 1 for v in values):
        raise argparse.ArgumentTypeError(f"'{text}': counts must be >= 1")
    return values


def binary_help(binary):
    try:
        return subprocess.run([binary, "run", "--help"], capture_output=True, text=True).stdout
    except OSError as error:
        sys.exit(f"scaling.py: cannot run {binary}: {error}")


def links_mpi(binary):
    try:
        proc = subprocess.run(["ldd", binary], capture_output=True, text=True)
    except OSError:
        return None  # unknown: try it
    if proc.returncode != 0:
        return None  # not a dynamic executable (a wrapper script?): try it
    return "libmpi" in proc.stdout


def phase_seconds(summary):
    phases = summary.get("phase_ns_per_element_cycle") or {}
    scale = summary["elements"] * summary["cycles"] * 1e-9
    return {p: phases[p] * scale for p in PHASES if p in phases}


def run_one(label, command, env, out, dry_run, repeat):
    """Runs command (fresh output folder each time); returns the fastest run's record or an error."""
    print(f"$ {' '.join(f'{k}={v}' for k, v in env.items())} {shlex.join(command)}", flush=True)
    if dry_run:
        return None
    best = None
    for attempt in range(repeat):
        if out.exists():
            shutil.rmtree(out)
        usage = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.monotonic()
        proc = subprocess.run(command, env={**os.environ, **env}, capture_output=True, text=True)
        elapsed = time.monotonic() - start
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - usage.ru_utime) + (after.ru_stime - usage.ru_stime)
        if proc.returncode != 0:
            lines = [line for line in (proc.stderr or proc.stdout).splitlines()
                     if line.strip() and not line.startswith("-----")]
            return {"label": label, "error": proc.returncode,
                    "stderr": lines if len(lines) <= 8 else lines[:4] + ["..."] + lines[-4:]}
        summary_file = out / "summary.json"
        if not summary_file.exists():
            return {"label": label, "error": "no summary.json", "stderr": []}
        summary = json.loads(summary_file.read_text())
        record = {"label": label, "process_seconds": elapsed, "cpu_seconds": cpu, "summary": summary}
        print(f"  run {attempt + 1}/{repeat}: {elapsed:.1f} s (engine {summary['wall_seconds']:.1f} s, "
              f"{summary['cycles']} cycles, CPU time {cpu:.1f} s)", flush=True)
        if best is None or summary["wall_seconds"] < best["summary"]["wall_seconds"]:
            best = record
    return best


def table(rows, base):
    """rows: records with threads, ranks, summary. Prints the whole-run and per-phase tables."""
    bs = base["summary"]
    bphase = phase_seconds(bs)
    print()
    print(f"Baseline: {base['label']} ({bs['wall_seconds']:.2f} s, {bs['cycles']} cycles, "
          f"{bs['elements']} elements, {bs['ns_per_element_cycle']:.0f} ns per element-cycle)")
    print()
    head = (f"{'run':12s} {'cores':>5s} {'wall s':>9s} {'process s':>9s} {'CPU s':>9s} "
            f"{'cycles':>7s} {'ns/el-cyc':>9s} {'speed-up':>8s} {'eff.':>6s}")
    print(head)
    print("-" * len(head))
    for r in rows:
        s = r["summary"]
        cores = r["threads"] * r["ranks"]
        speedup = bs["wall_seconds"] / s["wall_seconds"]
        print(f"{r['label']:12s} {cores:5d} {s['wall_seconds']:9.2f} {r['process_seconds']:9.2f} "
              f"{r['cpu_seconds']:9.2f} {s['cycles']:7d} {s['ns_per_element_cycle']:9.0f} {speedup:8.2f} "
              f"{100 * speedup / cores:5.0f}%")
        if s["cycles"] != bs["cycles"]:
            print(f"  note: {s['cycles']} cycles, the baseline {bs['cycles']}: not the same run")
    if not bphase:
        print("\n(no phase_ns_per_element_cycle in the baseline's summary.json: no phase table)")
        return
    print()
    print("Per phase: seconds (speed-up, efficiency) against the baseline")
    head = f"{'run':12s} " + " ".join(f"{p:>21s}" for p in PHASES)
    print(head)
    print("-" * len(head))
    for r in rows:
        ph = phase_seconds(r["summary"])
        cores = r["threads"] * r["ranks"]
        cells = []
        for p in PHASES:
            if p not in ph:
                cells.append(f"{'-':>21s}")
            elif ph[p] <= 0 or bphase.get(p, 0) <= 0:
                cells.append(f"{ph[p]:8.2f} {'(-)':>12s}")
            else:
                sp = bphase[p] / ph[p]
                cells.append(f"{ph[p]:8.2f} ({sp:4.2f}, {100 * sp / cores:3.0f}%)")
        print(f"{r['label']:12s} " + " ".join(cells))


def rank_tables(rows):
    mpi_rows = [r for r in rows if r["ranks"] > 1 or r.get("mpi")]
    if not mpi_rows:
        return
    print()
    print("Per rank (MPI runs): seconds per phase on each rank, imbalance = max / mean")
    for r in mpi_rows:
        per_rank = r["summary"].get("phase_seconds_per_rank")
        if not per_rank:
            print(f"{r['label']}: summary.json has no phase_seconds_per_rank: no per-rank phase "
                  "times (this binary does not write them)")
            continue
        ranks = max(len(v) for v in per_rank.values())
        print(f"{r['label']}:")
        print(f"  {'phase':10s} " + " ".join(f"{'rank ' + str(i):>9s}" for i in range(ranks))
              + f" {'max/mean':>9s}")
        for p in PHASES + sorted(set(per_rank) - set(PHASES)):
            values = per_rank.get(p)
            if not values:
                continue
            mean = sum(values) / len(values)
            ratio = max(values) / mean if mean > 0 else float("nan")
            print(f"  {p:10s} " + " ".join(f"{v:9.3f}" for v in values) + f" {ratio:9.3f}")
        if per_rank.get("communication"):
            # Each rank's own work: its step phases less the time it spent in messages (waiting
            # for the others included), so that max / mean is the imbalance of the work itself.
            work = [sum(per_rank[p][i] for p in ("elements", "contact", "time_step", "nodal")
                        if p in per_rank) - per_rank["communication"][i] for i in range(ranks)]
            mean = sum(work) / len(work)
            ratio = max(work) / mean if mean > 0 else float("nan")
            print(f"  {'work':10s} " + " ".join(f"{v:9.3f}" for v in work) + f" {ratio:9.3f}"
                  "   (step phases less communication: the load imbalance)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog="\n".join(__doc__.splitlines()[1:]))
    parser.add_argument("--binary", default=str(ROOT / "build" / "sheetform"))
    parser.add_argument("--case", default=str(ROOT / "cases" / "square_cup_fine" / "case.toml"))
    parser.add_argument("--out", default=str(ROOT / "build" / "scaling"),
                        help="parent folder of the runs' results (each run: threads-N, ranks-N)")
    parser.add_argument("--stroke", type=float, default=1.0, help="punch stroke in mm (default 1)")
    parser.add_argument("--threads-list", type=int_list, default=[1, 2], metavar="N,N,...",
                        help="OpenMP thread counts (default 1,2); empty string: none")
    parser.add_argument("--ranks-list", type=int_list, default=[1, 2], metavar="N,N,...",
                        help="MPI rank counts, 1 thread each (default 1,2); empty string: none")
    parser.add_argument("--mpirun", default="mpirun", help="MPI launcher (default mpirun)")
    parser.add_argument("--mpirun-args", default="",
                        help="extra launcher options, e.g. '--bind-to core --map-by core'")
    parser.add_argument("--repeat", type=int, default=1,
                        help="runs per configuration; the fastest counts (default 1)")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="passed to sheetform run --set (repeatable)")
    parser.add_argument("--dry-run", action="store_true", help="print the commands only")
    args = parser.parse_args()

    print(host_description(), flush=True)
    binary = str(pathlib.Path(args.binary).resolve())
    if not os.access(binary, os.X_OK):
        sys.exit(f"scaling.py: {binary}: not an executable (build first)")
    try:
        version = subprocess.run([binary, "--version"], capture_output=True, text=True).stdout.strip()
    except OSError:
        version = "?"
    print(f"Binary: {binary} ({version}); case {args.case}; stroke {args.stroke:g} mm")
    out_root = pathlib.Path(args.out).resolve()
    if not args.dry_run:
        out_root.mkdir(parents=True, exist_ok=True)
    common = ["run", str(pathlib.Path(args.case).resolve()), "--stroke", f"{args.stroke:g}", "-q"]
    for item in args.set:
        common += ["--set", item]
    if "--overwrite" in binary_help(args.binary):
        common.append("--overwrite")  # the result folders of an earlier measurement

    rows = []
    has_threads = "--threads" in binary_help(binary)
    for n in args.threads_list:
        out = out_root / f"threads-{n}"
        command = [binary, *common, "-o", str(out)]
        if has_threads:
            command += ["--threads", str(n)]
        elif n == 1:
            print("note: this binary has no --threads option (`sheetform run --help`); the 1-thread "
                  "run goes without it, OMP_NUM_THREADS=1")
        else:
            print(f"skipped: {n} threads: this binary has no --threads option "
                  "(`sheetform run --help`; the OpenMP work of issue 17 adds it)")
            continue
        rec = run_one(f"{n} thread{'s' if n > 1 else ''}", command,
                      {"OMP_NUM_THREADS": str(n)}, out, args.dry_run, args.repeat)
        if rec is None:
            continue
        if "error" in rec:
            rejected = any("--threads" in line for line in rec["stderr"])
            if rejected and n == 1:
                print("note: the binary rejected --threads; the 1-thread run goes without it")
                command = command[:-2]  # drop the trailing "--threads", "1"
                rec = run_one("1 thread", command, {"OMP_NUM_THREADS": "1"}, out,
                              args.dry_run, args.repeat)
            elif rejected:
                print(f"skipped: {n} threads: the binary rejected --threads")
                continue
            if rec is None or "error" in rec:
                print(f"FAILED: {n} threads (exit {rec['error']}):\n  " + "\n  ".join(rec["stderr"]))
                continue
        rec.update(threads=n, ranks=1)
        rows.append(rec)

    mpi_ok = True
    if args.ranks_list:
        launcher = shutil.which(args.mpirun)
        linked = links_mpi(binary)
        if launcher is None:
            print(f"skipped: MPI runs: {args.mpirun} not found (apt-get install openmpi-bin)")
            mpi_ok = False
        elif linked is False:
            print("skipped: MPI runs: the binary does not link an MPI library (ldd), so "
                  "`mpirun -np N` would run N independent copies of the whole case; MPI support "
                  "is issue 17's next step")
            mpi_ok = False
    if not mpi_ok and args.dry_run:
        print("(dry run: the MPI commands it would run otherwise follow)")
    for n in args.ranks_list if mpi_ok or args.dry_run else []:
        out = out_root / f"ranks-{n}"
        command = [args.mpirun, *shlex.split(args.mpirun_args), "-np", str(n), binary, *common,
                   "-o", str(out)]
        rec = run_one(f"{n} rank{'s' if n > 1 else ''}", command, MPI_ENV, out,
                      args.dry_run, args.repeat)
        if rec is None:
            continue
        if "error" in rec:
            print(f"skipped: MPI runs: `mpirun -np {n}` failed (exit {rec['error']}); the binary "
                  "does not support MPI runs yet, or the launcher failed:\n  "
                  + "\n  ".join(rec["stderr"]))
            break
        reported = rec["summary"].get("ranks", rec["summary"].get("mpi_ranks"))
        if reported is not None and int(reported) != n:
            print(f"skipped: MPI runs: summary.json says {reported} rank(s) for -np {n}: the "
                  "processes did not run as one MPI job")
            break
        if reported is None:
            print(f"  note: summary.json does not say how many ranks ran (no 'ranks' key)")
        rec.update(threads=1, ranks=n, mpi=True)
        rows.append(rec)

    if args.dry_run:
        return
    if not rows:
        sys.exit("scaling.py: no run succeeded")
    thread_rows = [r for r in rows if not r.get("mpi")]
    base = thread_rows[0] if thread_rows else rows[0]
    table(rows, base)
    rank_tables(rows)
    record = [{"label": r["label"], "threads": r["threads"], "ranks": r["ranks"],
               "process_seconds": r["process_seconds"], "cpu_seconds": r["cpu_seconds"],
               "wall_seconds": r["summary"]["wall_seconds"],
               "cycles": r["summary"]["cycles"], "elements": r["summary"]["elements"],
               "phase_seconds": phase_seconds(r["summary"]),
               "phase_seconds_per_rank": r["summary"].get("phase_seconds_per_rank")} for r in rows]
    (out_root / "scaling.json").write_text(json.dumps({"host": host_description(), "binary": binary,
                                                       "version": version, "stroke_mm": args.stroke,
                                                       "runs": record}, indent=2) + "\n")
    print(f"\nwritten: {out_root / 'scaling.json'}")


if __name__ == "__main__":
    main()
