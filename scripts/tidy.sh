#!/usr/bin/env bash
# clang-tidy (Debian 12's clang-tidy 14) with the repository's .clang-tidy (bugprone-*,
# performance-*, the noisy checks off with their reasons) over src/ and apps/. Not a CI step: it
# takes about as long as a build (docs/tooling.md has the last measured time and counts).
#
#   scripts/tidy.sh                 every .cpp of src/ and apps/
#   scripts/tidy.sh src/casefile/*.cpp    these files
#   SF_TIDY_JOBS=1 scripts/tidy.sh  parallel jobs (default: nproc)
#   SF_TIDY_CHECKS='-*,bugprone-*' scripts/tidy.sh    other checks than .clang-tidy's
#
# It configures build-tidy/ (clang, no build: clang-tidy needs only compile_commands.json and the
# generated headers), runs run-clang-tidy-14, writes the whole report to build-tidy/tidy.log and
# prints the number of distinct findings per check (a finding in a header counts once, however
# many files include it). Exit 1 when there is any finding.
set -euo pipefail
# The machine's cores. GNU nproc answers OMP_NUM_THREADS when it is set (CI sets it to 1 for
# the tests), which would build and test one job at a time.
sf_cores() { env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc; }
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
scripts/install_packages.sh clang clang-tidy-14 libomp-dev
build="$root/build-tidy"
start=$(date +%s)
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DSF_BUILD_TESTS=OFF -DSF_BUILD_BENCHMARKS=OFF \
  -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >"$build.configure.log" 2>&1 \
  || { cat "$build.configure.log"; exit 1; }
mv "$build.configure.log" "$build/configure.log"
if [ $# -gt 0 ]; then
  files=()
  for f in "$@"; do files+=("$(realpath "$f")"); done
  pattern=$(printf '%s\n' "${files[@]}" | sed 's/[.[\*^$]/\\&/g' | paste -sd'|')
else
  pattern="^$root/(src|apps)/.*\\.cpp\$"
fi
log="$build/tidy.log"
echo "== clang-tidy over $pattern (log $log)"
checks=()
[ -n "${SF_TIDY_CHECKS:-}" ] && checks=(-checks="$SF_TIDY_CHECKS")
run-clang-tidy-14 -p "$build" -j"${SF_TIDY_JOBS:-$(sf_cores)}" -quiet "${checks[@]}" \
  -header-filter="^$root/(src|apps)/" "$pattern" >"$log" 2>&1 || true
# "file:line:col: warning: text [check]" -> distinct (place, check), counted per check.
# (run-clang-tidy-14 colours its output: the escapes are stripped first.)
counts=$(sed 's/\x1b\[[0-9;]*m//g' "$log" \
  | grep -E '^/.*:[0-9]+:[0-9]+: (warning|error): .*\[[a-z0-9.,-]+\]$' \
  | sed -E 's/^([^:]+:[0-9]+:[0-9]+): (warning|error): .*\[([a-z0-9.,-]+)\]$/\1 \3/' \
  | sort -u | awk '{print $2}' | sort | uniq -c | sort -rn || true)
total=$(printf '%s\n' "$counts" | awk '{s += $1} END {print s + 0}')
echo "== clang-tidy: $total findings ($(( $(date +%s) - start )) s)"
[ -n "$counts" ] && printf '%s\n' "$counts"
[ "$total" -eq 0 ]
