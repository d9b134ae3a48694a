#!/usr/bin/env bash
# The sensitivity of the aluminium square cup's draw-ins to the modelling choices a user makes
# (docs/validation.md): the bundled case with Yld89 (M = 8, fitted to the benchmark's r-values),
# then one change at a time: the friction of each tool, the holder force, the punch speed, the
# die's profile radius. Prints DX and DD at 15 and 40 mm per run and their change from the base.
#
#   scripts/square_cup_sensitivity.sh [WORK_DIR]   (default build/square_cup_sensitivity; 14 runs,
#                                                  about 1 h on one core of the reference machine)
#   SF_SENSITIVITY_RUNS="base die_radius_5" scripts/square_cup_sensitivity.sh WORK_DIR
#                                                  only some of the runs (others in WORK_DIR stay)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
work="$(realpath -m "${1:-$root/build/square_cup_sensitivity}")"
sheetform="${SF_SHEETFORM:-$root/build/sheetform}"
case_file="$root/cases/square_cup_aluminium/case.toml"
mkdir -p "$work"

# name -> the --set overrides of that run (tools: 0 punch, 1 die, 2 holder; contact in that order)
declare -A runs=(
  [base]=""
  [punch_friction_0.10]="contact[0].friction=0.10"
  [punch_friction_0.20]="contact[0].friction=0.20"
  [die_friction_0.10]="contact[1].friction=0.10"
  [die_friction_0.20]="contact[1].friction=0.20"
  [holder_friction_0.10]="contact[2].friction=0.10"
  [holder_friction_0.20]="contact[2].friction=0.20"
  [holder_force_0.75]="tools[2].motion.curve=[[0.0,0.0],[0.0002,3675.0]]"
  [holder_force_1.25]="tools[2].motion.curve=[[0.0,0.0],[0.0002,6125.0]]"
  [punch_speed_1.5]="tools[0].motion.curve=[[0.0,0.0],[0.001,1500.0]]"
  [punch_speed_6]="tools[0].motion.curve=[[0.0,0.0],[0.00025,6000.0]]"
  [die_radius_5]="tools[1].parameters.profile_radius=5"
  [die_radius_10]="tools[1].parameters.profile_radius=10"
  [hill48]=""   # the bundled case as it is (Hill48), for the criterion's share
)
order="base punch_friction_0.10 punch_friction_0.20 die_friction_0.10 die_friction_0.20
  holder_friction_0.10 holder_friction_0.20 holder_force_0.75 holder_force_1.25 punch_speed_1.5
  punch_speed_6 die_radius_5 die_radius_10 hill48"
for name in ${SF_SENSITIVITY_RUNS:-$order}; do
  sets=(--set 'materials.aluminium.type="yld89"' --set materials.aluminium.exponent=8)
  if [[ "$name" == hill48 ]]; then
    sets=()
  fi
  for s in ${runs[$name]}; do
    sets+=(--set "$s")
  done
  echo "== $name ${runs[$name]}"
  "$sheetform" run "$case_file" -o "$work/$name" "${sets[@]}" -q --overwrite
done
/usr/bin/python3 "$root/scripts/sensitivity_table.py" "$work" $order
