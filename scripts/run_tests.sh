#!/usr/bin/env bash
# Sets up sheetform with ParaView (if not yet done), builds, and runs the whole test suite with
# ctest. Extra arguments go to ctest (e.g. -L contact, or -LE slow).
set -euo pipefail
cd "$(dirname "$0")/.."
SF_WITH_PARAVIEW=1 scripts/setup.sh
build_dir="${SF_BUILD_DIR:-build}"
echo "== Running the tests"
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)" -LE slow "$@"
