#!/usr/bin/env bash
# Sets up sheetform (packages + build) and runs the bundled demo: a quarter model of the
# NUMISHEET'93 square cup drawn to 15 mm. Results go to cases/square_cup_aluminium/results/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build_dir="${SF_BUILD_DIR:-build}"
echo "== Running the demo case"
"$build_dir/sheetform" run cases/square_cup_aluminium/case.toml --overwrite
