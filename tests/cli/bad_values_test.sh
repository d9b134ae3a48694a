#!/usr/bin/env bash
# Issue 31: values no sheet can have, a critical time step that cannot advance a run, and
# messages that must name the file, the key and what is expected.
#   bad_values_test.sh SHEETFORM SOURCE_DIR WORK_DIR
# Each check ran before on a value that hung the run, crashed it at cycle 0, passed `check`, or
# was told something that did not say what to do; `timeout` turns a hang into a failure.
set -u
sheetform="$1"; src="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
source "$(dirname "$0")/expect.sh"
expect_timeout=300
refute() {  # refute NAME PATTERN -- command...: the output must not match
  local name="$1" pattern="$2"; shift 3
  if timeout 300 "$@" 2>&1 | grep -qE -- "$pattern"; then
    echo "FAIL $name: output has /$pattern/"; failures=$((failures+1)); return
  fi
  echo "ok   $name"; passed=$((passed+1))
}

cp -r "$src/cases/square_cup_aluminium" "$work/case"; rm -rf "$work/case/results"
demo="$work/case/case.toml"
refute "the demo case has no physical-range warning" "Physical ranges" -- "$sheetform" check "$demo"

# young = 1e300: the wave speed overflows, the critical step is 0 and the run cycled at t = 0 for
# ever ("Cycles about inf", "Case is valid"). check and run refuse it, naming the keys.
young='materials\.aluminium: young = 1e\+300 MPa .*density = 2\.7e-09 tonne/mm\^3 and poisson = 0\.33 give a plate wave speed .* of inf mm/s and a critical time step of 0 s'
expect "young 1e300: check refuses" 2 "$young" -- "$sheetform" check "$demo" --set materials.aluminium.young=1e300
expect "young 1e300: run refuses before the first cycle" 2 "$young" -- \
  "$sheetform" run "$demo" -o "$work/young" --set materials.aluminium.young=1e300
[ ! -e "$work/young/results.h5" ] && passed=$((passed+1)) || { echo "FAIL young 1e300: the run started"; failures=$((failures+1)); }
# An infinite cycle count is refused, naming where the end time comes from.
expect "infinite cycle count refused" 2 "the run needs about inf cycles \(end time 1.7e\+308 s from control.end_time / time step [0-9.e-]+ s\), more than limits.max_cycles" -- \
  "$sheetform" check "$demo" --set control.stroke=0.0 --set control.end_time=1.7e308

# Values outside what any accepted unit system makes physical: refused with the range.
expect "thickness 1e300 refused" 2 "case.toml: blank.thickness = 1e\+300 mm cannot be a sheet's thickness in any unit system sheetform accepts: expected a number in \[1e-06, 1e\+06\], what 1e-06 to 1 m is" -- \
  "$sheetform" check "$demo" --set blank.thickness=1e300
expect "thickness 1e300: run refuses" 2 "blank.thickness = 1e\+300 mm cannot be" -- \
  "$sheetform" run "$demo" -o "$work/thick" --set blank.thickness=1e300
expect "young 1e200 refused" 2 "materials.aluminium.young = 1e\+200 MPa cannot be a sheet's Young's modulus .*\[100, 2e\+06\] MPa in the case's units" -- \
  "$sheetform" check "$demo" --set materials.aluminium.young=1e200
expect "density 1e-300 refused" 2 "materials.aluminium.density = 1e-300 tonne/mm\^3 cannot be a sheet's density" -- \
  "$sheetform" check "$demo" --set materials.aluminium.density=1e-300
expect "element size 1e300 refused" 2 "blank.element_size = 1e\+300 mm cannot be a sheet's element size" -- \
  "$sheetform" check "$demo" --set blank.element_size=1e300
# Dimensionless ratios, refused without regard to units.
expect "thickness beyond the blank's size refused" 2 "blank.thickness = 200 mm: its ratio to the blank's size \(the diagonal of its bounding box, 106.066 mm\) is 1.89, which no sheet can have .*expected at most 1" -- \
  "$sheetform" check "$demo" --set blank.thickness=200
expect "yield stress above young refused" 2 "materials.aluminium: the yield strain \(yield stress at 0.2 % plastic strain / young\) is 3.36, which no sheet can have .*expected in \[1e-06, 1\]" -- \
  "$sheetform" check "$demo" --set materials.aluminium.hardening.K=1e6
expect "tool faster than sound refused" 2 "tools\[0\].motion.curve \('punch'\): a peak speed of 3e\+07 mm/s: its ratio to the sheet's wave speed .* is 5.52, which no sheet can have" -- \
  "$sheetform" check "$demo" --set 'tools[0].motion.curve=[[0.0, 0.0], [0.0005, 3.0e7]]'
# Outside the range in the case's declared units only: a warning with the range, and the case runs.
expect "density in kg/mm^3 warned" 0 "warning: .*materials.aluminium.density = 2.7e-06 tonne/mm\^3 is outside \[1e-10, 1e-07\] tonne/mm\^3 in the case's units, a sheet's density \(100 to 100000 kg/m\^3\)" -- \
  "$sheetform" check "$demo" --set materials.aluminium.density=2.7e-6
expect "a thick blank warned" 0 "warning: .*blank.thickness = 30 mm: its ratio to the blank's size .* is 0.283, not at most 0.25 as usual" -- \
  "$sheetform" check "$demo" --set blank.thickness=30

# The stroke a motion curve never reaches names the case file, the stroke and the curve.
expect "stroke never reached" 2 "case.toml: control.stroke = 40 mm: tool 'punch' never travels that far: its tools\[0\].motion.curve \(type = \"velocity\", \[s, mm/s\]\) reaches 1.5 mm" -- \
  "$sheetform" check "$demo" --set 'tools[0].motion.curve=[[0.0, 0.0], [0.0005, 3000.0], [0.001, 0.0]]'

# An integer beyond what the key can hold is told the bound (and the run's limit).
expect "output_frames 2^63-1" 2 "control.output_frames: expected an integer >= 1, at most 2147483647 \(the largest this key holds; a run is held to limits.max_frames, 10000 by default\), got 9223372036854775807" -- \
  "$sheetform" check "$demo" --set control.output_frames=9223372036854775807

# --threads with a word.
expect "--threads two" 2 "^--threads: expected a whole number of threads >= 1, got 'two'" -- \
  "$sheetform" run "$demo" --threads two -o "$work/threads"

# A folder where the run writes a file: bad input naming the path (was "internal error", exit 1).
mkdir -p "$work/xdmf_folder/blank.xdmf"
expect "blank.xdmf a folder" 2 "results folder .*xdmf_folder: .*xdmf_folder/blank.xdmf is a folder, where the run writes a file" -- \
  "$sheetform" run "$demo" --stroke 0.01 -o "$work/xdmf_folder"

# A full disk: continue from a checkpoint only when there is one. A 6 MB tmpfs fills before the
# first checkpoint (30 min of wall time), or after the one of cycle 20; without a mount (no
# privilege), a file-size limit stands in for it.
steel="$src/cases/square_cup_steel/case.toml"
full_disk() {  # full_disk NAME PATTERN TAG [OPTION...]: a run of the steel cup on a 6 MB disk
  local name="$1" pattern="$2" disk="$work/disk_$3"; shift 3
  mkdir -p "$disk"
  if mount -t tmpfs -o size=6m tmpfs "$disk" 2>/dev/null; then
    expect "$name" 6 "$pattern" -- "$sheetform" run "$steel" --stroke 0.5 --set blank.element_size=1.875 -q -o "$disk/out" "$@"
    umount "$disk"
  else
    expect "$name" 6 "$pattern" -- bash -c 'trap "" XFSZ; ulimit -f 6000; exec "$@"' _ \
      "$sheetform" run "$steel" --stroke 0.5 --set blank.element_size=1.875 -q -o "$disk/out" "$@"
  fi
}
full_disk "full disk before a checkpoint" "^No checkpoint of this run was written before it stopped .* run the case again with --overwrite" none
full_disk "full disk after a checkpoint" "^Once the results folder can be written again \(free some space\), continue from the last checkpoint: sheetform run .* --restart .*/disk_cycles/out/checkpoint.h5" \
  cycles --set control.checkpoint_cycles=20

echo "$passed passed, $failures failed"
[ "$failures" -eq 0 ]
