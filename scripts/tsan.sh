#!/usr/bin/env bash
# ThreadSanitizer check of sheetform's OpenMP code (issue 17).
#
#   scripts/tsan.sh [BUILD_DIR]          (default build-tsan, beside build/)
#   SF_TSAN_TARGETS="test_core_exact_sum test_threads_foo" scripts/tsan.sh
#   SF_TSAN_THREADS=4 scripts/tsan.sh    (default 3: more threads than the CI box's 2 cores)
#
# What it does:
#  1. configures a separate build (BUILD_DIR, Ninja) with the CMake preset tsan: clang++,
#     RelWithDebInfo, -fsanitize=thread -g, -DSF_BUILD_TESTS=ON -DSF_BUILD_BENCHMARKS=OFF;
#  2. builds only the targets in SF_TSAN_TARGETS (below): the test executables whose tests carry
#     the ctest label `threads`, plus test_core_exact_sum; then also any executable that a
#     `threads`-labelled add_test() test names and that is not built yet (ctest --show-only);
#  3. runs `ctest -L threads` and the exact-sum tests by name (-R '^ExactSum\.') with
#     OMP_NUM_THREADS=3 and TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1
#     ignore_noninstrumented_modules=1": the first race report stops the test and fails it;
#  4. fails if Archer (below) did not announce itself, i.e. if the run was not checked with the
#     OpenMP semantics (it would then report false races, or worse, none).
# Add every new test executable that has `threads`-labelled gtest tests to SF_TSAN_TARGETS:
# gtest_discover_tests lists an executable's tests only once it is built, so they cannot be found
# before the build.
#
# Why clang and LLVM's OpenMP runtime, not GCC: ThreadSanitizer only sees synchronisation it
# instruments or is told about. GCC's libgomp is not instrumented, so TSan does not see its
# barriers (they are futex/spin waits) and reports false races between code before and after
# `#pragma omp barrier` or the end of a worksharing loop (seen here with gcc 12.2: a per-thread
# partial written before a barrier and read in `omp single` after it is reported as a race). The
# known ways out: rebuild libgomp with --disable-linux-futex (not packaged), suppress reports
# from libgomp (hides real races too), or clang with LLVM's libomp and Archer. Archer is an OMPT
# tool shipped with LLVM's OpenMP since LLVM 10 (Debian 12: libomp-14-dev, pulled in by
# libomp-dev, /usr/lib/llvm-14/lib/libarcher.so); libomp loads it when the program is built with
# -fsanitize=thread and it tells TSan the happens-before of OpenMP's barriers, tasks, locks and
# reductions (llvm-project openmp/tools/archer/README.rst). Its README recommends
# TSAN_OPTIONS=ignore_noninstrumented_modules=1 against false reports from inside the
# (uninstrumented) runtime itself; without it clang 14 reports one in libomp's own
# pthread_mutex_init/lock. OMP_TOOL_LIBRARIES names libarcher.so explicitly, because some
# distributions' libomp does not find it by itself (BLAST-WarpX/warpx PR 5826;
# llvm-project issue 45290 for Debian's clang-10 package; clang 14 here finds it either way).
# Checked on Debian 12 (clang 14.0.6, libomp 14): a real race (a shared partial updated by
# every thread) is reported; the barrier-ordered code above is not.
# Requirements: clang, libomp-dev (apt-get install clang libomp-dev).
#
# Cost: see the last lines it prints; the first run builds sheetform with TSan (minutes), and
# the whole-run test (threads_bitwise) runs 5-15 times slower than without it.
set -euo pipefail

# The targets built and checked: tests/core/test_exact_sum.cpp, tests/threads/test_*.cpp.
SF_TSAN_TARGETS="${SF_TSAN_TARGETS:-test_core_exact_sum test_threads_element_pass_threads}"
SF_TSAN_THREADS="${SF_TSAN_THREADS:-3}"
ARCHER_LIB="${ARCHER_LIB:-/usr/lib/llvm-14/lib/libarcher.so}"

root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(realpath -m "${1:-$root/build-tsan}")"
cxx="${SF_TSAN_CXX:-clang++}"
cc="${SF_TSAN_CC:-clang}"

for tool in "$cxx" "$cc" cmake ninja ctest; do
  command -v "$tool" >/dev/null || { echo "tsan.sh: $tool not found (apt-get install clang libomp-dev cmake ninja-build)" >&2; exit 2; }
done
[ -f "$ARCHER_LIB" ] || { echo "tsan.sh: $ARCHER_LIB not found (apt-get install libomp-dev, or set ARCHER_LIB)" >&2; exit 2; }

start=$(date +%s)
echo "== Configure $build ($cxx, -fsanitize=thread)"
mkdir -p "$build"
# The preset tsan (CMakePresets.json) holds the configuration; BUILD_DIR and the compilers given
# here override its folder and clang/clang++.
(cd "$root" && cmake --preset tsan -B "$build" \
  -DCMAKE_C_COMPILER="$cc" -DCMAKE_CXX_COMPILER="$cxx") >"$build/tsan-configure.log" 2>&1 \
  || { cat "$build/tsan-configure.log"; echo "tsan.sh: configure failed" >&2; exit 1; }
grep -q 'OpenMP_CXX_FLAGS:STRING=-fopenmp=libomp' "$build/CMakeCache.txt" \
  || echo "tsan.sh: warning: OpenMP is not LLVM's libomp ($(grep '^OpenMP_CXX_FLAGS' "$build/CMakeCache.txt"))"

echo "== Build: $SF_TSAN_TARGETS"
# shellcheck disable=SC2086
cmake --build "$build" --target $SF_TSAN_TARGETS

# Executables of this build named by `threads`-labelled add_test() tests (not gtest-discovered:
# as the program or as an argument, e.g. a script given $<TARGET_FILE:sheetform>) that are not
# built yet: build them too.
extra=$(ctest --test-dir "$build" -L threads --show-only=json-v1 2>/dev/null | /usr/bin/python3 -c '
import json, os, sys
try:
    tests = json.load(sys.stdin).get("tests", [])
except ValueError:
    tests = []
names = set()
for t in tests:
    for arg in t.get("command") or []:  # the program, or an argument (a script given sheetform)
        if arg.startswith(sys.argv[1]) and not os.path.exists(arg):
            names.add(os.path.basename(arg))
targets = set(line.split(":")[0] for line in open(sys.argv[2]))  # "name: rule" (ninja -t targets)
print(" ".join(sorted(names & targets)))' "$build/" <(ninja -C "$build" -t targets all))
if [ -n "$extra" ]; then
  echo "== Build (named by threads tests): $extra"
  # shellcheck disable=SC2086
  cmake --build "$build" --target $extra
fi

export OMP_NUM_THREADS="$SF_TSAN_THREADS"
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 ignore_noninstrumented_modules=1"
export OMP_TOOL=enabled OMP_TOOL_LIBRARIES="$ARCHER_LIB"
export ARCHER_OPTIONS="verbose=1"
export OMP_WAIT_POLICY=passive  # threads > cores on the CI box: no spinning
log="$build/tsan-last.log"
: >"$log"
status=0

echo "== ctest -L threads (OMP_NUM_THREADS=$OMP_NUM_THREADS)"
count=$(ctest --test-dir "$build" -N -L threads | sed -n 's/^Total Tests: //p')
if [ "${count:-0}" -eq 0 ]; then
  echo "   no test carries the label threads in this build yet (add its executable to SF_TSAN_TARGETS)"
else
  ctest --test-dir "$build" -L threads --output-on-failure -V >>"$log" 2>&1 || status=1
  grep -E '^[0-9]+/[0-9]+ Test|tests passed|WARNING: ThreadSanitizer|SUMMARY: ThreadSanitizer' "$log" || true
fi

echo "== exact sum (ctest -R '^ExactSum\\.')"
before=$(wc -l <"$log")
ctest --test-dir "$build" -R '^ExactSum\.' --output-on-failure -V >>"$log" 2>&1 || status=1
tail -n +"$((before + 1))" "$log" | grep -E '^[0-9]+/[0-9]+ Test|tests passed|WARNING: ThreadSanitizer|SUMMARY: ThreadSanitizer' || true
exact_count=$(ctest --test-dir "$build" -N -R '^ExactSum\.' | sed -n 's/^Total Tests: //p')
[ "${exact_count:-0}" -gt 0 ] || { echo "tsan.sh: no ExactSum tests found in $build" >&2; status=1; }

if ! grep -q 'Archer detected OpenMP application with TSan' "$log"; then
  echo "tsan.sh: Archer did not load (no 'Archer detected' line in $log): OpenMP synchronisation was not modelled" >&2
  status=1
fi
if grep -q 'WARNING: ThreadSanitizer' "$log"; then
  echo "tsan.sh: ThreadSanitizer reported a problem; the full output is in $log" >&2
  status=1
fi
echo "== $( [ $status -eq 0 ] && echo clean || echo FAILED ) ($(( $(date +%s) - start )) s; log $log)"
exit $status
