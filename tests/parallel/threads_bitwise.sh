#!/usr/bin/env bash
# A forming run at 1, 2 and 3 threads gives the same bits (issue 17): results.h5 datasets and
# summary.json numbers (scripts/compare_results.py). The square cup (steel) on a 1.875 mm blank
# (1600 elements, 1681 nodes: enough for every threaded loop to take threads) to 0.5 mm of stroke:
# force-controlled holder, friction, the cached search, quads (Belytschko-Tsay), then the same
# blank meshed as triangles (its .geo without the Recombine) with the assumed-strain formulation
# and the modified search.
#   threads_bitwise.sh SHEETFORM SOURCE_DIR WORK_DIR
set -u
sheetform="$1"; src="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
export OMP_WAIT_POLICY=passive  # 3 threads on a 2-core machine must not spin
cp -r "$src/cases/square_cup_steel" "$work/case"; rm -rf "$work/case/results"
cp -r "$work/case" "$work/case_triangles"; sed -i '/^Recombine/d' "$work/case_triangles/blank.geo"
failures=0
run_variant() {  # run_variant NAME CASE_FILE -- extra sheetform options...
  local name="$1" case_file="$2"; shift 3
  for threads in 1 2 3; do
    if ! "$sheetform" run "$case_file" --stroke 0.5 --threads "$threads" -q \
         --set blank.element_size=1.875 \
         -o "$work/$name-$threads" "$@" > "$work/$name-$threads.log" 2>&1; then
      echo "FAIL $name at $threads threads:"; tail -5 "$work/$name-$threads.log"
      failures=$((failures+1)); return
    fi
    grep -q "\"threads\": $threads" "$work/$name-$threads/summary.json" ||
      { echo "FAIL $name: summary.json does not say $threads threads"; failures=$((failures+1)); }
  done
  for threads in 2 3; do
    /usr/bin/python3 "$src/scripts/compare_results.py" "$work/$name-1" "$work/$name-$threads" ||
      failures=$((failures+1))
  done
}
run_variant quads "$work/case/case.toml" --
run_variant triangles "$work/case_triangles/case.toml" -- --set 'blank.element="as_meshed"' \
  --set 'blank.formulation="assumed_strain"' --search modified
grep -q '"elements": 3200' "$work/triangles-1/summary.json" ||
  { echo "FAIL the triangle variant is not 3200 triangles"; failures=$((failures+1)); }
[ "$failures" -eq 0 ] && echo "threads_bitwise: all the same bits" || echo "threads_bitwise: $failures failures"
exit "$failures"
