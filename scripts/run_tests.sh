#!/usr/bin/env bash
# Sets up sheetform with ParaView (if not yet done), builds, and runs the whole test suite with
# ctest. Extra arguments go to ctest (e.g. -L contact, or -LE slow).
set -euo pipefail
cd "$(dirname "$0")/.."
SF_WITH_PARAVIEW=1 scripts/setup.sh
build_dir="${SF_BUILD_DIR:-build}"
echo "== Running the tests"
# ctest runs nproc tests at once: one OpenMP thread each, so that they do not oversubscribe the
# cores (the thread tests set their own counts: --threads, omp_set_num_threads), and threads
# that wait sleep instead of spinning.
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-1}" OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-passive}"
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)" -LE slow "$@"
