#!/usr/bin/env bash
# A run stopped and restarted from its checkpoint gives the uninterrupted run's bits (issue 18,
# item 1): every results.h5 dataset and every summary.json number (scripts/compare_results.py).
# The square cup (steel, 1.875 mm quads, 0.5 mm stroke): force-controlled holder, friction, the
# cached search, and mass scaling; stopped at the first cycle, at a frame's cycle, twice in a row,
# restarted on 2 threads, by a real SIGTERM at an arbitrary moment; Yld89 with back stresses; a SIGUSR1 checkpoint that the
# run goes on from; the U-channel stopped during the forming and restarted, its implicit
# springback after the restart; a trim between two draws stopped before and after the trim; at 2
# ranks stopped and restarted serially and at 3 ranks; a turning tool stopped mid-turn. Then
# what a restart refuses (a changed case, another run's folder) and what it allows (a longer
# stroke), and the results folder of an earlier run (refused without --overwrite).
#   restart_bitwise.sh SHEETFORM SOURCE_DIR WORK_DIR MPIEXEC
set -u
sheetform="$1"; src="$2"; work="$3"; mpiexec="$4"
rm -rf "$work"; mkdir -p "$work"
export OMP_WAIT_POLICY=passive OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# Waiting ranks yield their core instead of polling (tests/CMakeLists.txt says why).
export OMPI_MCA_mpi_yield_when_idle=1
cup_case="$src/cases/square_cup_steel/case.toml"
failures=0
fail() { echo "FAIL $*"; failures=$((failures+1)); }
same() {  # same NAME A B
  /usr/bin/python3 "$src/scripts/compare_results.py" "$2" "$3" > "$work/$1.cmp" 2>&1 ||
    { fail "$1: not the uninterrupted run's bits:"; head -5 "$work/$1.cmp"; }
}
# run NAME EXPECTED_EXIT ARGS...: sheetform run with the output in $work/NAME.log
run() {
  local name="$1" expected="$2"; shift 2
  "$sheetform" run "$@" > "$work/$name.log" 2>&1
  local rc=$?
  [ "$rc" -eq "$expected" ] || { fail "$name: exit $rc, expected $expected:"; tail -5 "$work/$name.log"; }
}

cup_physics=(--stroke 0.5 --set blank.element_size=1.875 --set control.mass_scaling_dt=6e-7
             --set control.mass_scaling_max_added=0)
cup=("${cup_physics[@]}" -q --threads 1)
run cup 0 "$cup_case" "${cup[@]}" -o "$work/cup"
grep -q '"added_mass_tonne": [1-9]' "$work/cup/summary.json" || fail "cup: no mass added"

# Stopped at the first cycle, then again at cycle 400 (of 681), then on to the end on 2 threads.
run cup_1 5 "$cup_case" "${cup[@]}" -o "$work/cup_stops" --stop-at-cycle 1
grep -q "Continue with: sheetform run .* --restart $work/cup_stops/checkpoint.h5" \
  "$work/cup_1.log" || fail "cup_1: the stop does not say how to continue"
run cup_400 5 "$cup_case" "${cup[@]}" -o "$work/cup_stops" --restart "$work/cup_stops/checkpoint.h5" \
  --stop-at-cycle 400
run cup_end 0 "$cup_case" "${cup_physics[@]}" -q -o "$work/cup_stops" \
  --restart "$work/cup_stops/checkpoint.h5" --threads 2
same cup_stops "$work/cup" "$work/cup_stops"

# Stopped at the cycle of a frame (frame 3 of the uninterrupted run).
frame_cycle=$(/usr/bin/python3 -c "import h5py,sys; print(h5py.File(sys.argv[1])['parts/blank/frames/000003'].attrs['cycle'])" "$work/cup/results.h5")
run cup_frame 5 "$cup_case" "${cup[@]}" -o "$work/cup_frame" --stop-at-cycle "$frame_cycle"
run cup_frame_end 0 "$cup_case" "${cup[@]}" -o "$work/cup_frame" \
  --restart "$work/cup_frame/checkpoint.h5"
same cup_frame "$work/cup" "$work/cup_frame"

# Yld89 with two Armstrong-Frederick back stresses (issue 19): the back stresses are part of the
# checkpoint; stopped mid-run and restarted on 2 threads.
cp -r "$src/cases/square_cup_steel" "$work/kin_case"; rm -rf "$work/kin_case/results"
/usr/bin/python3 - "$work/kin_case/case.toml" <<'PY'
import sys
s = open(sys.argv[1]).read()
s = s.replace('type = "hill48"', 'type = "yld89"\nexponent = 6.0', 1)
s = s.replace("[materials.mild_steel.hardening]",
              "[materials.mild_steel.kinematic]\nC = [20000, 1500]\ngamma = [200, 10]\n\n"
              "[materials.mild_steel.hardening]")
open(sys.argv[1], "w").write(s)
PY
run kin 0 "$work/kin_case/case.toml" "${cup[@]}" -o "$work/kin"
run kin_stop 5 "$work/kin_case/case.toml" "${cup[@]}" -o "$work/kin_stop" --stop-at-cycle 450
run kin_end 0 "$work/kin_case/case.toml" "${cup_physics[@]}" -q -o "$work/kin_stop" \
  --restart "$work/kin_stop/checkpoint.h5" --threads 2
same kin "$work/kin" "$work/kin_stop"
/usr/bin/python3 - "$work/kin/results.h5" <<'PY' || fail "Yld89 with back stresses: no back stress in the results"
import h5py, sys
f = h5py.File(sys.argv[1])
last = sorted(f["parts/blank/frames"].keys())[-1]
assert abs(f["parts/blank/frames"][last]["back_stress_top"][()]).max() > 0.0
PY

# in_time_loop FOLDER: waits until the run writing FOLDER has written its second frame (it is in
# its time loop, not meshing), up to 60 s.
in_time_loop() {
  for _ in $(seq 600); do
    grep -q '000001' "$1/blank.xdmf" 2>/dev/null && return 0
    sleep 0.1
  done
  fail "no second frame in $1 after 60 s"
}

# A real SIGTERM at an arbitrary moment of the time loop.
"$sheetform" run "$cup_case" "${cup[@]}" -o "$work/cup_term" > "$work/cup_term.log" 2>&1 &
pid=$!; in_time_loop "$work/cup_term"; kill -TERM "$pid"; wait "$pid"; rc=$?
if [ "$rc" -eq 5 ]; then
  grep -q "Stopped by SIGTERM at t = " "$work/cup_term.log" || fail "SIGTERM: not said"
  run cup_term_end 0 "$cup_case" "${cup[@]}" -o "$work/cup_term" \
    --restart "$work/cup_term/checkpoint.h5"
  same cup_term "$work/cup" "$work/cup_term"
else
  fail "SIGTERM: exit $rc, expected 5 (did the run end before the signal?)"; tail -3 "$work/cup_term.log"
fi

# Ctrl-C (SIGINT; a script's background job starts with SIGINT ignored: python puts the default
# back before it runs sheetform) stops it the same way.
/usr/bin/python3 -c 'import os, signal, sys; signal.signal(signal.SIGINT, signal.SIG_DFL); os.execv(sys.argv[1], sys.argv[1:])' \
  "$sheetform" run "$cup_case" "${cup[@]}" -o "$work/cup_int" > "$work/cup_int.log" 2>&1 &
pid=$!; in_time_loop "$work/cup_int"; kill -INT "$pid"; wait "$pid"; rc=$?
if [ "$rc" -eq 5 ] && grep -q "Stopped by SIGINT at t = " "$work/cup_int.log"; then
  run cup_int_end 0 "$cup_case" "${cup[@]}" -o "$work/cup_int" --restart "$work/cup_int/checkpoint.h5"
  same cup_int "$work/cup" "$work/cup_int"
else
  fail "SIGINT: exit $rc, expected 5 and a message"; tail -3 "$work/cup_int.log"
fi

# SIGUSR1: a checkpoint, and the run goes on to the same bits.
cup_loud=("${cup_physics[@]}" --threads 1)
"$sheetform" run "$cup_case" "${cup_loud[@]}" -o "$work/cup_usr1" > "$work/cup_usr1.log" 2>&1 &
pid=$!; in_time_loop "$work/cup_usr1"; kill -USR1 "$pid"; wait "$pid"; rc=$?
[ "$rc" -eq 0 ] || fail "SIGUSR1: exit $rc, expected 0"
[ "$(grep -c '^Checkpoint  ' "$work/cup_usr1.log")" -eq 2 ] ||
  fail "SIGUSR1: expected a checkpoint on the signal and one at the end: $(grep '^Checkpoint' "$work/cup_usr1.log")"
same cup_usr1 "$work/cup" "$work/cup_usr1"

# The U-channel: stopped during the forming; the restart does the rest and the springback.
uch=("$src/cases/u_channel_bhf_2450N/case.toml" --stroke 4 -q)
run uch 0 "${uch[@]}" -o "$work/uch"
run uch_stop 5 "${uch[@]}" -o "$work/uch_stop" --stop-at-cycle 3000
run uch_end 0 "${uch[@]}" -o "$work/uch_stop" --restart "$work/uch_stop/checkpoint.h5"
grep -q '"springback"' "$work/uch_stop/summary.json" || fail "U-channel restart: no springback"
same uch "$work/uch" "$work/uch_stop"

# A trim between two draws (issue 32): stopped before the trim, and after it (no checkpoint is
# written after a trim: the restart goes on from the one before it and trims again); both give
# the uninterrupted run's bits, the trimmed mesh's frames and the operations' records included.
trim=(--set control.stroke=0 --set blank.element_size=1.875 -q --threads 1
      --set "operations=[{name=\"draw\", kind=\"forming\", stroke=0.3}, {name=\"trim\", kind=\"trim\", line=[[-1, -1], [50, -1], [50, 50], [-1, 50]]}, {name=\"on\", kind=\"forming\", stroke=0.5}]")
run trim 0 "$cup_case" "${trim[@]}" -o "$work/trim"
for stop in 500 1400; do  # the trim is at cycle 1010 of 1835
  run "trim_stop_$stop" 5 "$cup_case" "${trim[@]}" -o "$work/trim_$stop" --stop-at-cycle "$stop"
  run "trim_end_$stop" 0 "$cup_case" "${trim[@]}" -o "$work/trim_$stop" \
    --restart "$work/trim_$stop/checkpoint.h5"
  same "trim_$stop" "$work/trim" "$work/trim_$stop"
done
grep -q "written before the last trim" "$work/trim_stop_1400.log" ||
  fail "a stop after the trim does not say its checkpoint is before the trim"

# A tool that turns (issue 32, item 7): the flanging steel stopped mid-turn (its rotation, turn
# and moment a step ago in the checkpoint) and restarted: the uninterrupted run's bits.
flange_case="$src/cases/flange_rotary_bend/case.toml"
flange=(-q --set 'operations=[{name="flange", kind="forming", end="time", time=0.0015, damping=0.0}]')
run flange 0 "$flange_case" "${flange[@]}" -o "$work/flange"
run flange_stop 5 "$flange_case" "${flange[@]}" -o "$work/flange_stop" --stop-at-cycle 5000
run flange_end 0 "$flange_case" "${flange[@]}" -o "$work/flange_stop" \
  --restart "$work/flange_stop/checkpoint.h5"
same flange "$work/flange" "$work/flange_stop"

# Ranks: stopped at 2 ranks, restarted serially and at 3 ranks (no mass scaling over ranks).
ranks=(--stroke 0.5 --set blank.element_size=1.875 -q --threads 1)
run serial 0 "$cup_case" "${ranks[@]}" -o "$work/serial"
"$mpiexec" -np 2 --bind-to none "$sheetform" run "$cup_case" "${ranks[@]}" -o "$work/r2" \
  --stop-at-cycle 500 > "$work/r2.log" 2>&1
rc=$?; [ "$rc" -eq 5 ] || { fail "2 ranks: exit $rc, expected 5"; tail -3 "$work/r2.log"; }
cp -r "$work/r2" "$work/r2_3"
run r2_serial 0 "$cup_case" "${ranks[@]}" -o "$work/r2" --restart "$work/r2/checkpoint.h5"
same ranks_2_to_1 "$work/serial" "$work/r2"
"$mpiexec" -np 3 --bind-to none "$sheetform" run "$cup_case" "${ranks[@]}" -o "$work/r2_3" \
  --restart "$work/r2_3/checkpoint.h5" > "$work/r2_3.log" 2>&1 || fail "3 ranks restart"
same ranks_2_to_3 "$work/serial" "$work/r2_3"

# Refused: a case whose physics changed, a checkpoint of another run's folder (exit 2).
run changed 2 "$cup_case" "${cup[@]}" -o "$work/cup_frame" --restart "$work/cup_frame/checkpoint.h5" \
  --set 'contact[0].friction=0.3'
grep -q "the case changed since this checkpoint was written" "$work/changed.log" ||
  fail "changed case: not said"
run other_run 2 "$cup_case" "${cup[@]}" -o "$work/cup" --restart "$work/cup_frame/checkpoint.h5"
grep -q "holds the results of another run" "$work/other_run.log" || fail "another run: not said"

# Allowed: a longer stroke from the checkpoint at the end of a shorter run.
short=(--set blank.element_size=1.875 -q --threads 1)
run short 0 "$cup_case" "${short[@]}" --stroke 0.25 -o "$work/extend"
run extend 0 "$cup_case" "${short[@]}" --stroke 0.5 -o "$work/extend" \
  --restart "$work/extend/checkpoint.h5"
/usr/bin/python3 - "$work/extend/results.h5" <<'PY' || fail "extended run: the punch did not reach 0.5 mm"
import h5py, sys
travel = h5py.File(sys.argv[1])["history/punch_travel"][()]
assert abs(travel[-1] - 0.5) < 1e-9 and abs(travel).max() <= 0.5 + 1e-9, travel[-1]
PY

# An earlier run's results folder: refused, or replaced with --overwrite.
run again 2 "$cup_case" "${cup[@]}" -o "$work/cup"
grep -q "holds the results of an earlier run" "$work/again.log" || fail "earlier run: not said"
run overwrite 0 "$cup_case" "${cup[@]}" -o "$work/cup_stops" --overwrite
same overwrite "$work/cup" "$work/cup_stops"

[ "$failures" -eq 0 ] && echo "restart_bitwise: all passed" || echo "restart_bitwise: $failures failure(s)"
exit $((failures > 0))
