#!/usr/bin/env bash
# The command line for verification work: [[history]] groups against the frames and the loads,
# a static analysis's frame schedule and cut messages, .geo parameters and --set, what check
# prints for a static case in its own units, and scripts/plot_history.py --group.
#   cli_verification_test.sh SHEETFORM SOURCE_DIR WORK_DIR
set -u
sheetform="$1"; src="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
source "$(dirname "$0")/expect.sh"
python=/usr/bin/python3

expect_not() {  # expect_not NAME PATTERN -- command...: exit 0 and no line matching PATTERN
  local name="$1" pattern="$2"; shift 3
  local out rc
  out=$("$@" 2>&1); rc=$?
  if [ "$rc" -ne 0 ] || grep -qE -- "$pattern" <<<"$out"; then
    echo "FAIL $name: exit code $rc or a line matching /$pattern/"; echo "$out" | tail -5
    failures=$((failures+1)); return
  fi
  echo "ok   $name"; passed=$((passed+1))
}

check_python() {  # check_python NAME SCRIPT ARGS...: the script prints "ok" when the check holds
  local name="$1" script="$2"; shift 2
  local out
  out=$("$python" -c "$script" "$@" 2>&1)
  if [ "$out" = "ok" ]; then
    echo "ok   $name"; passed=$((passed+1))
  else
    echo "FAIL $name: $out"; failures=$((failures+1))
  fi
}

# The strip of tests/data/strip_parameters.geo (DefineConstant n = 20, b = 10): 100 x 10 x 2 mm,
# clamped at x = 0, 10 N up at its tip (5 N on each tip node).
strip_case() {  # strip_case FILE EXTRA
  cat > "$1" <<EOF
title = "verification strip"
units = "mm-s-tonne-N-MPa"
[blank]
mesh = "$src/tests/data/strip_parameters.geo"
thickness = 2.0
material = "steel"
[materials.steel]
type = "elastic"
density = 7.85e-9
young = 210000.0
poisson = 0.0
[[boundary]]
group = "clamp"
type = "fixed"
[[load]]
group = "tip"
type = "force"
value = [0.0, 0.0, 5.0]
[[history]]
group = "tip_corner"
[[history]]
group = "clamp"
quantities = ["reaction"]
$2
EOF
}

# --- check: a static case prints the lines that apply, in the case's units -------------------
static_case="$work/static.toml"
strip_case "$static_case" '
[analysis]
type = "static"
[implicit]
increments = 4
force_tolerance = 1e-11
displacement_tolerance = 1e-11
[control]
end_time = 1.0
output_frames = 2'
expect "check static: valid" 0 "Case is valid" -- "$sheetform" check "$static_case"
expect_not "check static: no time step, cycles or mass lines" "^(Time step|Cycles|Mass|End time) " -- "$sheetform" check "$static_case"
expect "check static: the analysis and the units" 0 "Units       mm-s-tonne-N-MPa: length mm, time s, mass tonne, force N, stress MPa" -- "$sheetform" check "$static_case"
expect "check static: the assumed-strain element (the default)" 0 "^Elements    20 assumed-strain quadrilaterals \(one in-plane point, directors, MITC4 transverse shear, physical hourglass stabilisation\)" -- "$sheetform" check "$static_case"
expect "check static: the stiffness hourglass form the step uses" 0 "^Elements    20 Belytschko-Lin-Tsay quadrilaterals \(one in-plane point, stiffness hourglass control" -- "$sheetform" check "$static_case" --set 'blank.formulation="belytschko_tsay"'
expect "check static: the history groups" 0 "^History     'tip_corner' \(1 nodes\): mean displacement, mean rotation, summed reaction" -- "$sheetform" check "$static_case"
# The same case declared in SI: check names those units (the numbers are not converted).
expect "check: the case's units, not mm-MPa" 0 "E = 210000 Pa" -- "$sheetform" check "$static_case" --set 'units="m-s-kg-N-Pa"'
expect "check: an inconsistent unit system" 2 "units: inconsistent units: tonne x mm / s\^2 is N, not kN" -- "$sheetform" check "$static_case" --set 'units="mm-s-tonne-kN-MPa"'

# --- .geo parameters and --set ---------------------------------------------------------------
expect "the .geo's default: 20 elements" 0 "^Blank       42 nodes, 20 elements" -- "$sheetform" check "$static_case"
expect "--set blank.parameters.n=8: 8 elements" 0 "^Blank       18 nodes, 8 elements" -- "$sheetform" check "$static_case" --set blank.parameters.n=8
expect "a parameter the .geo does not define" 2 "command line \(--set blank.parameters.m=3\): blank.parameters.m: '.*strip_parameters.geo' does not define m" -- "$sheetform" check "$static_case" --set blank.parameters.m=3
expect "a parameter the .geo assigns itself" 2 "blank.parameters.n: '.*strip.geo' assigns n itself" -- "$sheetform" check "$static_case" --set "blank.mesh=\"$src/tests/data/strip.geo\"" --set blank.parameters.n=8
expect "a malformed --set" 2 "--set blank.parameters.n: expected KEY=VALUE" -- "$sheetform" check "$static_case" --set blank.parameters.n

# --- a static run: history against frames, reactions against the load ------------------------
expect "static run" 0 "group clamp" -- "$sheetform" run "$static_case" -o "$work/static" --set blank.parameters.n=10
grep -q '^parameters = { n = 10.0 }' "$work/static/case.resolved.toml" && passed=$((passed+1)) || { echo "FAIL resolved case lacks the parameter"; failures=$((failures+1)); }
expect "the resolved case re-reads" 0 "^Blank       22 nodes, 10 elements" -- "$sheetform" check "$work/static/case.resolved.toml"
history_equals_frames='
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r"); h = f["history"]
x0 = f["parts/blank/reference_coordinates"][:]
node = int(np.flatnonzero((x0[:, 0] == 100.0) & (x0[:, 1] == 0.0))[0])  # the group tip_corner
bad = []
frames = f["parts/blank/frames"]
for k in sorted(frames):
    t = frames[k].attrs["time"]
    rows = np.flatnonzero(h["time"][:] == t)
    if len(rows) != 1:
        bad.append(f"frame {k}: {len(rows)} history rows at t = {t}"); continue
    for field, stem in [("displacement", "displacement")] + ([("velocity", "velocity")] if sys.argv[2] == "explicit" else []):
        frame = frames[k][field][node]
        hist = [h[f"tip_corner_{stem}_{a}"][rows[0]] for a in "xyz"]
        if list(frame) != hist:  # a one-node group: its mean is the node value, bit for bit
            bad.append(f"frame {k} {field}: {list(frame)} != {hist}")
print("ok" if not bad and len(frames) > 2 else "; ".join(bad) or "too few frames")'
# History rows are written at every frame: the one-node group equals the frame's node value.
check_python "static: history tip_corner displacement = the frame's nodal displacement" "$history_equals_frames" "$work/static/results.h5" static
check_python "static: clamp reaction = -10 N (equilibrium, 1e-8)" '
import sys, json
r = json.load(open(sys.argv[1]))["history"]["clamp"]["reaction_force"]
print("ok" if abs(r[2] + 10.0) <= 1e-8 * 10.0 and abs(r[0]) <= 1e-8 * 10.0 else f"reaction {r}")' "$work/static/summary.json"
check_python "history columns carry their units" '
import sys, h5py
h = h5py.File(sys.argv[1], "r")["history"]
units = {c: h[c].attrs["unit"].decode() for c in ["time", "tip_corner_displacement_z", "tip_corner_rotation_y", "clamp_reaction_force_z", "clamp_reaction_moment_y", "internal_energy"]}
want = {"time": "s", "tip_corner_displacement_z": "mm", "tip_corner_rotation_y": "rad", "clamp_reaction_force_z": "N", "clamp_reaction_moment_y": "N mm", "internal_energy": "N mm"}
print("ok" if units == want else f"{units}")' "$work/static/results.h5"
# plot_history.py --group: the static case has no tool, so only the energies and the groups.
expect "plot_history --group" 0 "wrote .*group_tip_corner.png" -- "$python" "$src/scripts/plot_history.py" "$work/static" --group tip_corner --group clamp --csv
[ -s "$work/static/group_clamp.png" ] && [ -s "$work/static/group_tip_corner.csv" ] && passed=$((passed+1)) || { echo "FAIL plot_history: group images or CSV missing"; failures=$((failures+1)); }
expect "plot_history --group of no such group" 2 "no columns of group 'nowhere'" -- "$python" "$src/scripts/plot_history.py" "$work/static" --group nowhere

# --- an explicit run: history against frames (displacement and velocity) ---------------------
explicit_case="$work/explicit.toml"
strip_case "$explicit_case" '
[control]
end_time = 2e-4
output_frames = 4
history_interval = 7'
expect "explicit run" 0 "group tip_corner" -- "$sheetform" run "$explicit_case" -o "$work/explicit"
check_python "explicit: history tip_corner displacement and velocity = the frame's nodal values" "$history_equals_frames" "$work/explicit/results.h5" explicit
# The balance from the history's columns, half-kick term included, is the column the solver
# wrote (no initial velocity here), row by row.
check_python "explicit: energy_balance_error = the balance of the history's energy columns" '
import sys, h5py, numpy as np
h = h5py.File(sys.argv[1], "r")["history"]
c = {k: np.asarray(h[k]) for k in h}
total = sum(c[k + "_energy"] for k in ("kinetic", "internal", "hourglass", "contact", "damping", "mass_scaling"))
scale = np.maximum(np.maximum(total, c["external_work"]), 1e-300)
balance = np.where(np.maximum(total, c["external_work"]) > 0, (total - c["half_kick_energy"] - c["external_work"]) / scale, 0.0)
worst = np.max(np.abs(balance - c["energy_balance_error"]))
half_kick = c["half_kick_energy"]
print("ok" if worst <= 1e-12 and np.any(half_kick != 0) else f"deviation {worst}, half-kick column {half_kick[:3]}")' "$work/explicit/results.h5"

# --- a static analysis with cut increments: output_frames + 1 frames -------------------------
cp -r "$src/cases/verify_roll_up" "$work/roll"; rm -rf "$work/roll/results"
# 4 increments of 90 degrees of roll each fail in 12 iterations and are halved: 8 increments of
# 0.125, finer than the 4 frames asked for (0.25 apart).
expect "static with cut increments" 0 "halved \(1 of 8\): tried again from load factor 0.0000 to 0.1250" -- \
  "$sheetform" run "$work/roll/case.toml" -o "$work/roll_cut" --set implicit.increments=4 --set implicit.max_iterations=12 --set control.output_frames=4
check_python "static with cuts: exactly output_frames + 1 = 5 frames, 9 history rows" '
import sys, h5py
f = h5py.File(sys.argv[1], "r")
frames = sorted(f["parts/blank/frames"])
times = [float(f["parts/blank/frames"][k].attrs["time"]) for k in frames]
rows = len(f["history/time"])
# The initial state, then the first converged increment at or past 0.25, 0.5, 0.75 and 1.
print("ok" if times == [0.0, 0.25, 0.5, 0.75, 1.0] and rows == 9 else f"frame times {times}, {rows} rows")' "$work/roll_cut/results.h5"
# One 360-degree increment without line search diverges: the message gives the growth of the
# residual against the documented limit (docs/static-analysis.md), and the step stops (exit 4).
# Belytschko-Tsay: its residual grows past the limit; the assumed-strain element
# inverts first, which is the other documented reason an iteration fails.
expect "static divergence message" 4 "the residual diverged: [0-9.e+]+ times its norm at the start of the increment, beyond the limit 1e\+06" -- \
  "$sheetform" run "$work/roll/case.toml" -o "$work/roll_diverged" --set implicit.increments=1 --set implicit.line_search=false --set implicit.max_cuts=1 --set implicit.max_iterations=40 --set 'blank.formulation="belytschko_tsay"'
expect "static inverted-element message" 4 "the static step did not converge: .*shell element [0-9]+: inverted, collapsed or non-finite geometry" -- \
  "$sheetform" run "$work/roll/case.toml" -o "$work/roll_inverted" --set implicit.increments=1 --set implicit.line_search=false --set implicit.max_cuts=1 --set implicit.max_iterations=40 --set 'blank.formulation="assumed_strain"'

echo "$passed passed, $failures failed"
[ "$failures" -eq 0 ]
