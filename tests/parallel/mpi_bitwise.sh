#!/usr/bin/env bash
# `mpirun -np N sheetform run` gives the serial run's bits (issue 17, item 3): results.h5 datasets
# and summary.json numbers (scripts/compare_results.py) at 1, 2 and 3 ranks (3 oversubscribe a
# 2-core machine) and 2 ranks x 2 threads. The square cup (steel) on a 1.875 mm blank to 0.5 mm of
# stroke (force-controlled holder, friction, the cached search, quads), then the same blank as
# triangles (assumed strain, the modified search); the U-channel to 4 mm with its implicit
# springback (on rank 0 after the gather); a closing then a draw as two operations (issue 32) at
# 2 ranks, and a draw, a trim (removing, then cutting) and a draw on at 2 ranks; the cup with two
# drawbead lines on the holder across the flange (issue 33: lines that cross the partitions) at 2
# ranks; mass scaling with a pressure load at 2 and 3 ranks, springback by dynamic relaxation and a
# static analysis (on rank 0) at 2 ranks (issue 34). Then what a distributed run refuses or stops
# with: more ranks than elements (exit 2), an energy blow-up
# (exit 3, said once, the results readable up to the stop), and an element failure met by one
# rank (exit 3, the serial run's message on every rank count).
#   mpi_bitwise.sh SHEETFORM SOURCE_DIR WORK_DIR MPIEXEC
set -u
sheetform="$1"; src="$2"; work="$3"; mpiexec="$4"
rm -rf "$work"; mkdir -p "$work"
export OMP_WAIT_POLICY=passive OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# Waiting ranks yield their core instead of polling (tests/CMakeLists.txt says why).
export OMPI_MCA_mpi_yield_when_idle=1
cp -r "$src/cases/square_cup_steel" "$work/case"; rm -rf "$work/case/results"
cp -r "$work/case" "$work/case_triangles"; sed -i '/^Recombine/d' "$work/case_triangles/blank.geo"
failures=0
fail() { echo "FAIL $*"; failures=$((failures+1)); }

# run_variant NAME CASE_FILE -- options...: serial, then 1, 2, 3 ranks and 2 ranks x 2 threads.
run_variant() {
  local name="$1" case_file="$2"; shift 3
  "$sheetform" run "$case_file" --threads 1 -q -o "$work/$name-serial" "$@" \
    > "$work/$name-serial.log" 2>&1 || { fail "$name serial:"; tail -5 "$work/$name-serial.log"; return; }
  for layout in 1x1 2x1 3x1 2x2; do
    local ranks="${layout%x*}" threads="${layout#*x}"
    if ! "$mpiexec" -np "$ranks" --bind-to none "$sheetform" run "$case_file" --threads "$threads" \
         -q -o "$work/$name-$layout" "$@" > "$work/$name-$layout.log" 2>&1; then
      fail "$name at $layout (ranks x threads):"; tail -5 "$work/$name-$layout.log"; continue
    fi
    grep -q "\"ranks\": $ranks" "$work/$name-$layout/summary.json" ||
      fail "$name $layout: summary.json does not say $ranks ranks"
    /usr/bin/python3 "$src/scripts/compare_results.py" "$work/$name-serial" "$work/$name-$layout" ||
      fail "$name $layout: not the serial bits"
  done
}
cup=(--stroke 0.5 --set blank.element_size=1.875)
run_variant quads "$work/case/case.toml" -- "${cup[@]}"
run_variant triangles "$work/case_triangles/case.toml" -- "${cup[@]}" \
  --set 'blank.element="as_meshed"' --set 'blank.formulation="assumed_strain"' --search modified

# Drawbead lines (issue 33) crossing the ranks' partitions, and the contact's result fields:
# 2 ranks give the serial bits (3 ranks too, checked by hand when they were added).
cp -r "$work/case" "$work/case_beads"
for axis in x y; do
  if [ "$axis" = x ]; then line='[[55.0, 0.0, 0.39], [55.0, 80.0, 0.39]]'
  else line='[[0.0, 55.0, 0.39], [80.0, 55.0, 0.39]]'; fi
  printf '\n[[drawbeads]]\nname = "bead_%s"\ntool = "holder"\nline = %s\nwidth = 8.0\nheight = 1.0\nclosure = [0.0, 1.0]\nrestraining_force = [0.0, 50.0]\nuplift_force = [0.0, 10.0]\n' \
    "$axis" "$line" >> "$work/case_beads/case.toml"
done
"$sheetform" run "$work/case_beads/case.toml" --threads 1 -q -o "$work/beads-serial" "${cup[@]}" \
  > "$work/beads-serial.log" 2>&1 || fail "beads serial"
"$mpiexec" -np 2 --bind-to none "$sheetform" run "$work/case_beads/case.toml" --threads 1 -q \
  -o "$work/beads-2" "${cup[@]}" > "$work/beads-2.log" 2>&1 || fail "beads at 2 ranks"
grep -q '"drawbead_work"' "$work/beads-2/summary.json" || fail "beads at 2 ranks: no bead work"
/usr/bin/python3 "$src/scripts/compare_results.py" "$work/beads-serial" "$work/beads-2" ||
  fail "beads at 2 ranks: not the serial bits"

# The U-channel with its implicit springback, at 2 ranks.
"$sheetform" run "$src/cases/u_channel_bhf_2450N/case.toml" --stroke 4 -q -o "$work/uch-serial" \
  > "$work/uch-serial.log" 2>&1 || fail "U-channel serial"
"$mpiexec" -np 2 "$sheetform" run "$src/cases/u_channel_bhf_2450N/case.toml" --stroke 4 -q \
  -o "$work/uch-2" > "$work/uch-2.log" 2>&1 || fail "U-channel at 2 ranks"
grep -q '"springback"' "$work/uch-2/summary.json" || fail "U-channel at 2 ranks: no springback"
/usr/bin/python3 "$src/scripts/compare_results.py" "$work/uch-serial" "$work/uch-2" ||
  fail "U-channel at 2 ranks: not the serial bits"

# serial_and_two_ranks NAME OPTIONS...: the steel cup serially and at 2 ranks ($work/NAME-serial,
# $work/NAME-2), the same bits.
serial_and_two_ranks() {
  local name="$1"; shift
  "$sheetform" run "$work/case/case.toml" -q -o "$work/$name-serial" "$@" \
    > "$work/$name-serial.log" 2>&1 || { fail "$name serial:"; tail -5 "$work/$name-serial.log"; }
  "$mpiexec" -np 2 --bind-to none "$sheetform" run "$work/case/case.toml" -q -o "$work/$name-2" \
    "$@" > "$work/$name-2.log" 2>&1 || { fail "$name at 2 ranks:"; tail -5 "$work/$name-2.log"; }
  /usr/bin/python3 "$src/scripts/compare_results.py" "$work/$name-serial" "$work/$name-2" ||
    fail "$name at 2 ranks: not the serial bits"
}

# The press line over ranks (issue 32, item 8): a closing with the punch out of play, ended by the
# holder's push, then the draw; 2 ranks give the serial bits, and the operations' records agree.
close='{name="close", kind="closing", tools=["holder", "die"], end="force", tool="holder", '
close+='force=4000.0, time=0.002}'
ops=(--set control.stroke=0 --set blank.element_size=1.875
     --set "operations=[$close, {name=\"draw\", kind=\"forming\", stroke=0.4}]")
serial_and_two_ranks ops "${ops[@]}"
/usr/bin/python3 - "$work/ops-serial" "$work/ops-2" <<'PY' || fail "operations at 2 ranks: the records or formed parts differ"
import sys, h5py, numpy as np
a, b = sys.argv[1], sys.argv[2]
with h5py.File(a + "/results.h5") as fa, h5py.File(b + "/results.h5") as fb:
    for k in ("0", "1"):
        for name in ("name", "end_time", "end_cycle", "last_frame"):
            assert fa["operations"][k].attrs[name] == fb["operations"][k].attrs[name], (k, name)
for part in ("formed_part.close.h5", "formed_part.h5"):
    with h5py.File(a + "/" + part) as fa, h5py.File(b + "/" + part) as fb:
        keys = []
        fa["state"].visit(lambda n: keys.append(n) if isinstance(fa["state"][n], h5py.Dataset) else None)
        for k in keys:
            assert fa["state"][k][()].tobytes() == fb["state"][k][()].tobytes(), (part, k)
PY

# A trim between two draws (issue 32, item 3): every rank trims the part the output process wrote,
# the model is built again on the trimmed mesh and split over the ranks afresh; 2 ranks give the
# serial bits, the trimmed mesh's frames included.
trim=(--set control.stroke=0 --set blank.element_size=1.875
      --set "operations=[{name=\"draw\", kind=\"forming\", stroke=0.3}, {name=\"trim\", kind=\"trim\", line=[[-1, -1], [50, -1], [50, 50], [-1, 50]]}, {name=\"on\", kind=\"forming\", stroke=0.5}]")
serial_and_two_ranks trim "${trim[@]}"
/usr/bin/python3 - "$work/trim-2" <<'PY' || fail "trim at 2 ranks: no trimmed mesh in the results"
import sys, h5py
with h5py.File(sys.argv[1] + "/results.h5") as f:
    assert f["operations/1"].attrs["kind"] in ("trim", b"trim")
    trimmed = f["parts/blank/topologies/1/connectivity"].shape[0]
    assert 0 < trimmed < f["parts/blank/connectivity"].shape[0], trimmed
PY

# The same trim cutting cleanly: the mesh after it mixes quads and the cut's triangles, split over
# the ranks afresh; 2 ranks give the serial bits.
trim_cut=(--set control.stroke=0 --set blank.element_size=1.875
          --set "operations=[{name=\"draw\", kind=\"forming\", stroke=0.3}, {name=\"trim\", kind=\"trim\", mode=\"cut\", line=[[-1, -1], [50, -1], [50, 50], [-1, 50]]}, {name=\"on\", kind=\"forming\", stroke=0.5}]")
serial_and_two_ranks trim_cut "${trim_cut[@]}"
/usr/bin/python3 - "$work/trim_cut-2" <<'PY' || fail "cut at 2 ranks: no cut mesh in the results"
import sys, h5py
with h5py.File(sys.argv[1] + "/formed_part.trim.h5") as f:
    assert f["mesh/triangles"].shape[0] > 0, "no triangles after the cut"
PY

# A tool that turns (issue 32, item 7): the flanging steel's first 1.5 ms (25 degrees); its
# moment summed over the ranks, its torque and angle in the history, the same bits at 2 ranks.
flange=(--set 'operations=[{name="flange", kind="forming", end="time", time=0.0015, damping=0.0}]')
"$sheetform" run "$src/cases/flange_rotary_bend/case.toml" -q -o "$work/flange-serial" \
  "${flange[@]}" > "$work/flange-serial.log" 2>&1 ||
  { fail "flange serial:"; tail -5 "$work/flange-serial.log"; }
"$mpiexec" -np 2 --bind-to none "$sheetform" run "$src/cases/flange_rotary_bend/case.toml" -q \
  -o "$work/flange-2" "${flange[@]}" > "$work/flange-2.log" 2>&1 ||
  { fail "flange at 2 ranks:"; tail -5 "$work/flange-2.log"; }
/usr/bin/python3 "$src/scripts/compare_results.py" "$work/flange-serial" "$work/flange-2" ||
  fail "flange at 2 ranks: not the serial bits"

# Mass scaling and a pressure load (issue 34, item 4): the steel cup with a target step that
# scales elements at the start and more of them as the cup is drawn (mass added across the ranks'
# borders), under 0.2 MPa on the blank's top face; serial, 2 and 3 ranks, the same bits.
scaled=(--stroke 0.5 --set blank.element_size=1.875 --set control.mass_scaling_dt=4e-7
        --set control.mass_scaling_max_added=0
        --set 'load=[{group="blank", type="pressure", pressure=0.2}]')
"$sheetform" run "$work/case/case.toml" --threads 1 -q -o "$work/scaled-serial" "${scaled[@]}" \
  > "$work/scaled-serial.log" 2>&1 || { fail "scaled serial:"; tail -5 "$work/scaled-serial.log"; }
for ranks in 2 3; do
  "$mpiexec" -np "$ranks" --bind-to none "$sheetform" run "$work/case/case.toml" --threads 1 -q \
    -o "$work/scaled-$ranks" "${scaled[@]}" > "$work/scaled-$ranks.log" 2>&1 ||
    { fail "scaled at $ranks ranks:"; tail -5 "$work/scaled-$ranks.log"; continue; }
  /usr/bin/python3 "$src/scripts/compare_results.py" "$work/scaled-serial" "$work/scaled-$ranks" ||
    fail "scaled at $ranks ranks: not the serial bits"
done
/usr/bin/python3 - "$work/scaled-serial" <<'PY' || fail "scaled: no mass added during the draw"
import sys, h5py, numpy as np
with h5py.File(sys.argv[1] + "/results.h5") as f:
    added = f["history/added_mass"][()]
assert added[0] > 0 and added[-1] > added[0], (added[0], added[-1])
PY

# Springback by dynamic relaxation after a 2-rank draw (on rank 0 after the gather, as the
# implicit one): the U-channel to 4 mm, the serial bits.
dr=(--stroke 4 --set 'springback.method="dynamic_relaxation"' --set springback.release_time=2e-4)
"$sheetform" run "$src/cases/u_channel_bhf_2450N/case.toml" -q -o "$work/dr-serial" "${dr[@]}" \
  > "$work/dr-serial.log" 2>&1 || { fail "DR springback serial:"; tail -5 "$work/dr-serial.log"; }
"$mpiexec" -np 2 "$sheetform" run "$src/cases/u_channel_bhf_2450N/case.toml" -q -o "$work/dr-2" \
  "${dr[@]}" > "$work/dr-2.log" 2>&1 || { fail "DR springback at 2 ranks:"; tail -5 "$work/dr-2.log"; }
grep -q '"dynamic_relaxation"' "$work/dr-2/summary.json" || fail "DR at 2 ranks: no relaxation"
/usr/bin/python3 "$src/scripts/compare_results.py" "$work/dr-serial" "$work/dr-2" ||
  fail "DR springback at 2 ranks: not the serial bits"

# A static analysis at 2 ranks: computed on rank 0 alone (CHOLMOD's serial solver), said in the
# banner, the serial bits.
"$sheetform" run "$src/cases/shell_cantilever_end_shear/case.toml" -q -o "$work/static-serial" \
  > "$work/static-serial.log" 2>&1 || { fail "static serial:"; tail -5 "$work/static-serial.log"; }
"$mpiexec" -np 2 "$sheetform" run "$src/cases/shell_cantilever_end_shear/case.toml" \
  -o "$work/static-2" > "$work/static-2.log" 2>&1 ||
  { fail "static at 2 ranks:"; tail -5 "$work/static-2.log"; }
grep -q "the static analysis runs on rank 0 alone" "$work/static-2.log" ||
  fail "static at 2 ranks: the banner does not say where it runs"
/usr/bin/python3 "$src/scripts/compare_results.py" "$work/static-serial" "$work/static-2" ||
  fail "static at 2 ranks: not the serial bits"

# Refused: more ranks than elements (exit 2, a message naming the counts).
"$mpiexec" -np 2 "$sheetform" run "$src/cases/verify_bounce/case.toml" -q -o "$work/one" \
  > "$work/one.log" 2>&1
rc=$?
[ "$rc" -eq 2 ] && grep -q "1 element for 2 MPI ranks" "$work/one.log" ||
  { fail "1 element at 2 ranks: exit $rc, expected 2:"; cat "$work/one.log"; }

# Unstable (damping beyond the explicit limit, as tests/cli): exit 3, said once, frames readable.
sed -i 's/^output_frames = \(.*\)/output_frames = \1\ndamping = 5.0e6/' "$work/case/case.toml"
"$mpiexec" -np 2 "$sheetform" run "$work/case/case.toml" --stroke 0.5 -o "$work/unstable" \
  --set blank.element_size=3.75 > "$work/unstable.log" 2>&1
rc=$?
[ "$rc" -eq 3 ] && [ "$(grep -c 'the run went unstable: energy blow-up' "$work/unstable.log")" -eq 1 ] ||
  { fail "unstable at 2 ranks: exit $rc, expected 3 and one message:"; tail -20 "$work/unstable.log"; }
h5ls "$work/unstable/results.h5/parts/blank/frames" > /dev/null 2>&1 ||
  fail "unstable at 2 ranks: results.h5 not readable"

# A failure inside one rank's share (non-finite initial velocities where x > 50 mm on the plate
# deck: the elements there fail in the first element pass): every rank stops with the serial
# run's message, naming the serial run's element, exit 3.
cp -r "$src/benchmarks/plate_deck" "$work/plate"
sed -i 's|^velocity = .*|velocity = [0, 0, "2e4 * sqrt(50 - x)"]|' "$work/plate/case.toml"
"$sheetform" run "$work/plate/case.toml" --end-time 1e-5 -q -o "$work/nan-serial" > "$work/nan-serial.log" 2>&1
want=$(head -1 "$work/nan-serial.log")
for ranks in 2 3; do
  "$mpiexec" -np "$ranks" "$sheetform" run "$work/plate/case.toml" --end-time 1e-5 -q \
    -o "$work/nan-$ranks" > "$work/nan-$ranks.log" 2>&1
  rc=$?
  [ "$rc" -eq 3 ] && [ "$(grep -c '^error:' "$work/nan-$ranks.log")" -eq 1 ] &&
    [ "$(head -1 "$work/nan-$ranks.log")" = "$want" ] && grep -q "shell element [0-9]*: non-finite" <<< "$want" ||
    { fail "element failure at $ranks ranks: exit $rc, expected 3 and the serial message '$want':"
      head -3 "$work/nan-$ranks.log"; }
done

[ "$failures" -eq 0 ] && echo "mpi_bitwise: all the same bits" || echo "mpi_bitwise: $failures failures"
exit "$failures"
