#!/usr/bin/env bash
# Sets up sheetform with ParaView (if not yet done), builds, and runs the whole test suite with
# ctest. Extra arguments go to ctest (e.g. -L contact, or -LE slow).
# Then the checks that keep it so (docs/tooling.md), each after the other, all run even when one
# fails: the format check (scripts/check_format.sh), the unit tests under ASan + UBSan
# (scripts/sanitize.sh) and a short fuzz run of the input readers (scripts/fuzz.sh short).
# They run when no ctest arguments are given (CI) or with SF_EXTRA_CHECKS=1; SF_EXTRA_CHECKS=0
# skips them.
set -euo pipefail
# The machine's cores. GNU nproc answers OMP_NUM_THREADS when it is set (CI sets it to 1 for
# the tests), which would build and test one job at a time.
sf_cores() { env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc; }
cd "$(dirname "$0")/.."
t_start=$(date +%s)
SF_WITH_PARAVIEW=1 scripts/setup.sh
build_dir="${SF_BUILD_DIR:-build}"
t_built=$(date +%s)
echo "== Set up and built in $((t_built - t_start)) s"
echo "== Running the tests"
# ctest runs nproc tests at once: one OpenMP thread each, so that they do not oversubscribe the
# cores (the thread tests set their own counts: --threads, omp_set_num_threads), and threads
# that wait sleep instead of spinning.
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-1}" OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-passive}"
status=0
ctest --test-dir "$build_dir" --output-on-failure -j"$(sf_cores)" -LE slow "$@" \
  | tee "$build_dir/ctest-main.log" || status=1  # pipefail: ctest's own status
echo "== The tests ran in $(( $(date +%s) - t_built )) s"

extra="${SF_EXTRA_CHECKS:-auto}"
if [ "$extra" = 1 ] || { [ "$extra" = auto ] && [ $# -eq 0 ]; }; then
  for step in scripts/check_format.sh scripts/sanitize.sh "scripts/fuzz.sh short"; do
    t0=$(date +%s)
    echo "== $step"
    $step || { status=1; echo "== $step FAILED"; }
    echo "== $step: $(( $(date +%s) - t0 )) s"
  done
  # The main suite's closing line last, as the summary of the run.
  echo "== Everything in $(( $(date +%s) - t_start )) s"
  grep -E 'tests passed|tests failed' "$build_dir/ctest-main.log" | tail -1
fi
exit $status
