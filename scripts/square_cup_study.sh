#!/usr/bin/env bash
# The square-cup validation study of docs/validation.md: the aluminium NUMISHEET'93 square cup to
# 40 mm with each contact search (standard, modified) on two blank meshes (2.5 mm, the case's, and
# 1.25 mm), then a table of the draw-ins at 15 and 40 mm against the measured averages, the peak
# punch force, the thinning, the energy ratios and the run times.
#
#   scripts/square_cup_study.sh [WORK_DIR]     (default build/square_cup_study; about 90 min on
#                                               one core of the reference machine)
#   SF_STUDY_SIZES="1.25" SF_STUDY_SEARCHES="cached" scripts/square_cup_study.sh WORK_DIR
#                                               only some of the runs (others in WORK_DIR stay)
#
# Each run's folder (WORK_DIR/<size>-<search>) can be post-processed with the scripts of
# docs/post-processing.md; scripts/validation_tables.py WORK_DIR prints the tables again.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
work="$(realpath -m "${1:-$root/build/square_cup_study}")"
sheetform="${SF_SHEETFORM:-$root/build/sheetform}"
mkdir -p "$work"
for size in ${SF_STUDY_SIZES:-2.5 1.25}; do
  case_dir="$work/case-$size"
  rm -rf "$case_dir"; cp -r "$root/cases/square_cup_aluminium" "$case_dir"; rm -rf "$case_dir/results"
  sed -i "0,/^element_size = 2.5 .*/s//element_size = $size          # mm (study)/" "$case_dir/case.toml"
  grep -q "^element_size = $size " "$case_dir/case.toml"
  for search in ${SF_STUDY_SEARCHES:-modified standard}; do
    out="$work/$size-$search"
    echo "== blank $size mm, $search search"
    "$sheetform" run "$case_dir/case.toml" -o "$out" --search "$search" -q --overwrite
  done
done
/usr/bin/python3 "$root/scripts/validation_tables.py" "$work"
