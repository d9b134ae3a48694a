#!/usr/bin/env bash
# The unit tests under AddressSanitizer + UndefinedBehaviorSanitizer (CI step, run by
# scripts/run_tests.sh after the main ctest run).
#
#   scripts/sanitize.sh            configure the preset `sanitize` in build-sanitize/, build the
#                                  unit-test executables but the solver's, run their tests (CI)
#   scripts/sanitize.sh --all      also the solver's tests: whole explicit and static runs, each
#                                  minutes under the sanitizers (about an hour in all; by hand)
#   scripts/sanitize.sh -R Shell   extra arguments go to ctest
#
# The preset `sanitize` (CMakePresets.json) is the developers' `dev` preset (clang, Debug,
# -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined) at -O1
# with line tables only, linked by lld: the same checks, in about half the compile time of -O1 -g;
# at -O0 the contact tests run 100 times slower than in Release, at -O1 about 10 times. Built:
# every test_* executable (GoogleTest, one per module, tests/<module>/test_*.cpp, and the fuzz
# targets' replays; not sheetform, the MPI programs, the benchmarks, and without --all not
# tests/solver's). Run: ctest's test preset `sanitize`, i.e. the
# module labels (core mesh material element contact meshing casefile results model implicit parallel threads) less
# slow/cli/case/regression/post and the MPI runs; with --all the preset `sanitize-all`, which
# adds the label solver.
# Reports: ASan (heap/stack/global overflows, use after free or return, double free, leaks via
# LeakSanitizer, with tests/sanitizers/lsan.supp for leaks inside uninstrumented system libraries)
# and UBSan (signed overflow, bad shifts, misaligned or null access, float-to-int overflow, bad
# enum/bool loads, vptr): the first report fails the test, with its stack, in ctest's output.
#
# Cost on the 2-vCPU reference machine, from nothing: see docs/tooling.md (the script prints its
# own times on its last line).
set -euo pipefail
# The machine's cores. GNU nproc answers OMP_NUM_THREADS when it is set (CI sets it to 1 for
# the tests), which would build and test one job at a time.
sf_cores() { env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc; }
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
start=$(date +%s)
test_preset=sanitize
if [ "${1:-}" = --all ]; then
  test_preset=sanitize-all
  shift
fi

# clang and its sanitizer runtimes, LLVM's OpenMP (libomp) for clang's -fopenmp.
scripts/install_packages.sh clang libclang-rt-14-dev libomp-dev lld

build="$root/build-sanitize"  # the preset's binaryDir
echo "== Sanitizers: configure $build (preset sanitize: clang, ASan + UBSan, -O1)"
cmake --preset sanitize >"$root/.sanitize-configure.log" 2>&1 \
  || { cat "$root/.sanitize-configure.log"; echo "sanitize.sh: configure failed" >&2; exit 1; }
mv "$root/.sanitize-configure.log" "$build/sanitize-configure.log"

# Every GoogleTest executable: the targets test_<module>_<name> (tests/CMakeLists.txt), less those
# that cannot run under ASan:
#  - test_solver_step_allocations interposes malloc itself (calling __libc_malloc) to count a
#    step's allocations; ASan must own malloc (it stops with "CHECK failed: asan_posix.cpp");
#  - without --all, test_solver (CI's time budget).
# A test executable that is not built leaves a <target>_NOT_BUILT placeholder without labels, which
# the preset's label filter leaves out.
excluded="test_solver_step_allocations"
targets=$(ninja -C "$build" -t targets all | sed -n 's/^\(test_[A-Za-z0-9_]*\): phony$/\1/p' \
  | sort -u | grep -vxF -f <(tr ' ' '\n' <<<"$excluded"))
if [ "$test_preset" = sanitize ]; then
  targets=$(grep -v '^test_solver' <<<"$targets")
fi
[ -n "$targets" ] || { echo "sanitize.sh: no test_* targets in $build" >&2; exit 1; }
echo "== Build $(echo "$targets" | wc -w) test executables"
# shellcheck disable=SC2086
cmake --build "$build" -j"$(sf_cores)" --target $targets
built=$(date +%s)

echo "== ctest --preset $test_preset"
# One OpenMP thread per test and passive waiting (the preset sets both), nproc tests at once.
status=0
ctest --preset "$test_preset" -j"$(sf_cores)" "$@" || status=$?
end=$(date +%s)
echo "== Sanitizers: $( [ $status -eq 0 ] && echo clean || echo FAILED ): build $((built - start)) s, tests $((end - built)) s, total $((end - start)) s"
exit $status
