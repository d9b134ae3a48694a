#!/usr/bin/env bash
# Writes this case's tools as STEP files from their gmsh scripts: cad/<tool>.geo -> <tool>.step
# (gmsh -0: the script's OpenCASCADE geometry, the whole quarter solid, written by OpenCASCADE's
# STEP writer in mm). Run it from anywhere after changing a script in cad/; the files are checked
# in (README.md).
#
#   cases/rectangular_cup_cad/make_step.sh [--gmsh PATH] [--out DIR]
#
# --out DIR writes the files there instead of the case folder (ctest case_step_files compares them
# with the checked-in ones, all but the header's time stamp: scripts/check_case_step.py).
set -euo pipefail
gmsh=gmsh
here="$(cd "$(dirname "$0")" && pwd)"
out="$here"
while [ $# -gt 0 ]; do
  case "$1" in
    --gmsh) gmsh="$2"; shift ;;
    --out) out="$2"; shift ;;
    *) echo "make_step.sh: unknown argument $1" >&2; exit 2 ;;
  esac
  shift
done
mkdir -p "$out"
for tool in punch die holder; do
  # gmsh 4.8 exits 0 even when the script fails: check its log for errors and that the file exists.
  rm -f "$out/$tool.step"
  log=$("$gmsh" "$here/cad/$tool.geo" -0 -o "$out/$tool.step" 2>&1)
  if grep -q "^Error" <<<"$log" || [ ! -s "$out/$tool.step" ]; then
    echo "$log" >&2
    echo "make_step.sh: gmsh failed on cad/$tool.geo" >&2
    exit 1
  fi
  echo "wrote $out/$tool.step"
done
