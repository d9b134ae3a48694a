#!/usr/bin/env bash
# Format check (CI step, run by scripts/run_tests.sh): clang-format 14 (Debian 12's clang-format,
# the version .clang-format is written for) in dry-run mode with --Werror on every C++ file git
# tracks under src, apps, tests and benchmarks. Exit 1 and a list of the files to format when one
# differs; fix with
#     clang-format-14 -i FILE...
#   scripts/check_format.sh [FILE...]     only these files
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
scripts/install_packages.sh clang-format-14
if [ $# -gt 0 ]; then
  files=("$@")
else
  mapfile -t files < <(git ls-files -- 'src/*.cpp' 'src/*.hpp' 'src/*.h' 'apps/*.cpp' 'apps/*.hpp' \
    'tests/*.cpp' 'tests/*.hpp' 'tests/*.h' 'benchmarks/*.cpp' 'benchmarks/*.hpp')
fi
existing=()
for f in "${files[@]}"; do [ -f "$f" ] && existing+=("$f"); done  # not deleted in the work tree
# One run over every file; the files with a violation are those its messages name.
rc=0
out=$(clang-format-14 --style=file --dry-run --Werror "${existing[@]}" 2>&1) || rc=$?
mapfile -t bad < <(printf '%s\n' "$out" \
  | sed -n 's/^\([^:]*\):[0-9]*:[0-9]*: \(warning\|error\):.*/\1/p' | sort -u)
if [ $rc -ne 0 ] && [ ${#bad[@]} -eq 0 ]; then
  printf '%s\n' "$out"
  echo "check_format.sh: clang-format-14 failed (exit $rc)" >&2
  exit 1
fi
if [ ${#bad[@]} -gt 0 ]; then
  echo "check_format.sh: ${#bad[@]} of ${#existing[@]} files are not clang-formatted (clang-format-14 -i FILE):"
  printf '  %s\n' "${bad[@]}"
  exit 1
fi
echo "== Format: ${#existing[@]} files clang-formatted"
