#!/usr/bin/env bash
# libFuzzer runs of the input readers (tests/fuzz, docs/tooling.md).
#
#   scripts/fuzz.sh short              CI: case_reader 45 s, mesh_reader 35 s, geo_safety,
#                                      checkpoint and formed_part 20 s (the scanner is covered
#                                      within seconds; the HDF5 readers' findings lie in libhdf5,
#                                      met in seconds or not in minutes), msh41 15 s (a parser
#                                      without gmsh: a million inputs); SF_FUZZ_SECONDS=N gives
#                                      every target N s
#   scripts/fuzz.sh long HOURS         HOURS (e.g. 0.5, 8) of the machine's cores shared equally
#                                      among the targets; a finding does not stop the run
#                                      (libFuzzer's fork mode)
#   The targets run side by side, one per core (nproc), each for its seconds: the short run takes
#   about 80 s of fuzzing on two cores instead of 155.
#   scripts/fuzz.sh build              only configure and build (preset fuzz, build-fuzz/)
#   SF_FUZZ_TARGETS="case_reader" scripts/fuzz.sh short     a subset of the targets
#
# Targets (tests/fuzz/fuzz_<name>.cpp): case_reader (case.toml -> read_case, and the resolved case
# must read back to the same text), mesh_reader (.msh through gmsh -> load_gmsh_model,
# extract_part_mesh, extract_node_group), geo_safety (the .geo command scanner), checkpoint
# (checkpoint.h5 -> read_checkpoint, into the state of cases/verify_bounce), formed_part
# (formed_part.h5 -> read_formed_part) and msh41 (the MSH 4.1 binary reader of what the sandboxed
# gmsh hands back). A finding is
# a crash, a sanitizer report (ASan, UBSan), an exception other than sf::InputError, a broken
# property, a timeout (SF_FUZZ_TIMEOUT s per input) or more memory than SF_FUZZ_RSS_MB.
#
# Seeds (build-fuzz/seeds/<name>, made anew each run): every cases/*/case.toml; the .msh files in
# cases/ up to the target's max_len and .msh files gmsh makes from tests/data/*.geo, in MSH 4.1
# and 2.2; every .geo in cases/ and tests/data; the checkpoints in tests/fuzz/seeds/checkpoint; MSH
# 4.1 binary files gmsh makes from tests/data/*.geo (msh41). Plus every saved finding in
# tests/fuzz/regressions/<name>. The case reader gets a dictionary of the case file's keys taken
# from src/casefile (build-fuzz/case_reader.dict), the others small dictionaries in tests/fuzz.
# The corpus grows in build-fuzz/corpus/<name> and is kept between runs in the same build folder.
# Findings go to build-fuzz/findings/<name>/ (crash-*, leak-*, timeout-*, oom-*): reproduce one
# with build-fuzz/tests/fuzz/fuzz_<name> FILE; once fixed, copy it to
# tests/fuzz/regressions/<name>/ (ctest's fuzz_replay.<name> then replays it for good).
#
# Exit status: 0 when no target found anything, 1 otherwise (the findings are listed). In the short
# run (CI) a target with open findings (inputs in tests/fuzz/open-findings/<name>/, reported and
# waiting for a fix) does not fail it: its findings are listed, and it fails again once the folder
# is emptied into regressions/ with the fix.
set -euo pipefail
# The machine's cores. GNU nproc answers OMP_NUM_THREADS when it is set (CI sets it to 1 for
# the tests), which would build and test one job at a time.
sf_cores() { env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc; }
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
mode="${1:-short}"
all_targets="case_reader mesh_reader geo_safety checkpoint msh41 formed_part"
targets="${SF_FUZZ_TARGETS:-$all_targets}"
timeout_s="${SF_FUZZ_TIMEOUT:-20}"
rss_mb="${SF_FUZZ_RSS_MB:-4096}"
declare -A seconds_of=([case_reader]=45 [mesh_reader]=35 [geo_safety]=20 [checkpoint]=20 [msh41]=15
                       [formed_part]=20)
case "$mode" in
  short)
    if [ -n "${SF_FUZZ_SECONDS:-}" ]; then
      for t in $all_targets; do seconds_of[$t]="$SF_FUZZ_SECONDS"; done
    fi
    ;;
  long)
    hours="${2:?usage: scripts/fuzz.sh long HOURS}"
    # The targets run one per core: each gets its share of HOURS times the cores at work.
    seconds=$(python3 -c "import sys; n = int(sys.argv[2]); print(max(1, int(float(sys.argv[1]) * 3600 * min(n, int(sys.argv[3])) / n)))" \
      "$hours" "$(echo "$targets" | wc -w)" "$(sf_cores)")
    for t in $all_targets; do seconds_of[$t]="$seconds"; done
    ;;
  build) ;;
  *) echo "usage: scripts/fuzz.sh short | long HOURS | build" >&2; exit 2 ;;
esac

# clang with libFuzzer and the sanitizer runtimes, LLVM's OpenMP, gmsh (the seeds).
scripts/install_packages.sh clang libclang-rt-14-dev libomp-dev lld gmsh

build="$root/build-fuzz"  # the preset's binaryDir
start=$(date +%s)
echo "== Fuzz: configure $build (preset fuzz: clang, -fsanitize=fuzzer-no-link,address,undefined)"
mkdir -p "$build"
cmake --preset fuzz >"$build/fuzz-configure.log" 2>&1 \
  || { cat "$build/fuzz-configure.log"; echo "fuzz.sh: configure failed" >&2; exit 1; }
fuzzers=""
for t in $targets; do fuzzers+=" fuzz_$t"; done
echo "== Build:$fuzzers"
# shellcheck disable=SC2086
cmake --build "$build" -j"$(sf_cores)" --target $fuzzers
echo "== Built in $(( $(date +%s) - start )) s"
[ "$mode" = build ] && exit 0

# --- seeds, made anew
seeds="$build/seeds"
rm -rf "$seeds"
mkdir -p "$seeds/case_reader" "$seeds/mesh_reader" "$seeds/geo_safety" "$seeds/checkpoint" \
  "$seeds/msh41" "$seeds/formed_part"
cp tests/fuzz/seeds/checkpoint/* "$seeds/checkpoint/"
cp tests/fuzz/seeds/formed_part/* "$seeds/formed_part/"
for f in cases/*/case.toml; do cp "$f" "$seeds/case_reader/$(basename "$(dirname "$f")").toml"; done
for f in cases/*/*.geo tests/data/*.geo; do
  cp "$f" "$seeds/geo_safety/$(basename "$(dirname "$f")")_$(basename "$f")"
done
declare -A max_len=([case_reader]=16384 [mesh_reader]=32768 [geo_safety]=8192 [checkpoint]=65536
                    [msh41]=32768 [formed_part]=65536)
for f in cases/*/*.msh; do
  [ "$(stat -c %s "$f")" -le "${max_len[mesh_reader]}" ] \
    && cp "$f" "$seeds/mesh_reader/$(basename "$(dirname "$f")")_$(basename "$f")"
done
for g in tests/data/*.geo; do  # the project's own test geometries: no commands in them
  name=$(basename "$g" .geo)
  gmsh -2 -format msh41 -o "$seeds/mesh_reader/${name}_41.msh" "$g" >/dev/null 2>&1 || true
  gmsh -2 -format msh22 -o "$seeds/mesh_reader/${name}_22.msh" "$g" >/dev/null 2>&1 || true
  gmsh -2 -bin -format msh41 -o "$seeds/msh41/${name}.msh" "$g" >/dev/null 2>&1 || true
done
find "$seeds/mesh_reader" "$seeds/msh41" -size +"${max_len[mesh_reader]}"c -delete

# The case reader's dictionary: the quoted key names of src/casefile's case reader, and TOML syntax.
dict="$build/case_reader.dict"
{
  grep -ohE '"[a-z_][a-z0-9_]*"' src/casefile/*.cpp | sort -u
  cat tests/fuzz/toml.dict
} >"$dict"

# One target's run: its report line into $build/fuzz-$t.report, its verdict (0 passed, 1 found
# or did not run) into $build/fuzz-$t.status, what to show into $build/fuzz-$t.out.
fuzz_target() {
  local t=$1 corpus="$build/corpus/$1" findings="$build/findings/$1" d seconds log before t0 t1
  local runs cov new written line verdict=0
  mkdir -p "$corpus" "$findings"
  local inputs=("$corpus" "$seeds/$t")
  [ -d "tests/fuzz/regressions/$t" ] && inputs+=("tests/fuzz/regressions/$t")
  case "$t" in
    case_reader) d="$dict" ;;
    *) d="tests/fuzz/$t.dict" ;;
  esac
  seconds="${seconds_of[$t]}"
  local options=(-max_total_time="$seconds" -timeout="$timeout_s" -rss_limit_mb="$rss_mb"
                 -max_len="${max_len[$t]}" -dict="$d" -artifact_prefix="$findings/"
                 -print_final_stats=1 -close_fd_mask=1)
  if [ "$mode" = short ]; then
    options+=(-seed=1)
  else
    options+=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  fi
  log="$build/fuzz-$t.log"
  before=$(find "$findings" -type f | wc -l)
  t0=$(date +%s)
  ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1" UBSAN_OPTIONS="print_stacktrace=1" \
    LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0" \
    "$build/tests/fuzz/fuzz_$t" "${options[@]}" "${inputs[@]}" >"$log" 2>&1 || true
  t1=$(date +%s)
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  if [ -z "$runs" ]; then  # fork mode: the last status line, "#N: cov: ..."
    runs=$(sed -n 's/^#\([0-9]*\):* .*cov.*/\1/p' "$log" | tail -1)
  fi
  cov=$(grep -oE 'cov: [0-9]+' "$log" | tail -1 | sed 's/cov: //' || true)
  new=$(( $(find "$findings" -type f | wc -l) - before ))
  written=$(grep -c 'Test unit written to' "$log" || true)
  [ "$new" -lt "$written" ] && new=$written
  line="fuzz_$t: ${runs:-?} runs in $((t1 - t0)) s, coverage ${cov:-?} edges, corpus $(find "$corpus" -type f | wc -l) inputs, $new new findings"
  {
    echo "== fuzz_$t: $seconds s ($mode; log $log)"
    echo "   $line"
    if [ -z "$runs" ]; then
      verdict=1
      echo "   fuzz_$t did not run:"; tail -20 "$log"
    elif [ "$new" -gt 0 ]; then
      local open_dir="tests/fuzz/open-findings/$t"
      if [ "$mode" = short ] && [ -n "$(find "$open_dir" -type f ! -name README.md 2>/dev/null)" ]; then
        echo "   not failing: $t has open findings waiting for a fix ($open_dir/README.md)"
      else
        verdict=1
      fi
      sed -n 's/.*Test unit written to /   finding: /p' "$log" | sort -u
      grep -E -A30 '^==[0-9]+==ERROR|runtime error|^fuzz: ' "$log" | head -60 || true
    fi
  } >"$build/fuzz-$t.out"
  echo "$line" >"$build/fuzz-$t.report"
  echo "$verdict" >"$build/fuzz-$t.status"
}

# The targets side by side, one per core (each gets its seconds of a core, as one after the
# other did); their outputs in the targets' order once all are done.
jobs_max=$(sf_cores)
echo "== Fuzzing$(for t in $targets; do printf ' %s (%s s)' "$t" "${seconds_of[$t]}"; done), $jobs_max at a time"
for t in $targets; do
  rm -f "$build/fuzz-$t.status" "$build/fuzz-$t.report" "$build/fuzz-$t.out"
  while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do
    wait -n || true
  done
  fuzz_target "$t" &
done
wait
status=0
report=""
for t in $targets; do
  cat "$build/fuzz-$t.out" 2>/dev/null || echo "== fuzz_$t: no output"
  [ "$(cat "$build/fuzz-$t.status" 2>/dev/null)" = 0 ] || status=1
  report+="$(cat "$build/fuzz-$t.report" 2>/dev/null || echo "fuzz_$t: no report")"$'\n'
done
echo "== Fuzz $( [ $status -eq 0 ] && echo passed || echo FOUND SOMETHING ) ($(( $(date +%s) - start )) s)"
printf '%s' "$report"
exit $status
