#!/usr/bin/env bash
# Writes each case's meshes beside its .geo files: <part>.msh, meshed by gmsh exactly as a run
# meshes them (`sheetform mesh`: the case's element sizes and recombination), so a case folder
# keeps the .msh its .geo made.
#
#   scripts/update_case_meshes.sh [--check] [--sheetform PATH] CASE_DIR...
#
# --check: rewrite nothing; exit 1 and name every .msh that is missing or differs from what its
# .geo makes now (a changed .geo or element size, or another gmsh version).
set -euo pipefail
check=0
sheetform="$(dirname "$0")/../build/sheetform"
cases=()
while [ $# -gt 0 ]; do
  case "$1" in
    --check) check=1 ;;
    --sheetform) sheetform="$2"; shift ;;
    -*) echo "update_case_meshes.sh: unknown option $1" >&2; exit 2 ;;
    *) cases+=("$1") ;;
  esac
  shift
done
[ ${#cases[@]} -gt 0 ] || { echo "usage: update_case_meshes.sh [--check] [--sheetform PATH] CASE_DIR..." >&2; exit 2; }
[ -x "$sheetform" ] || { echo "update_case_meshes.sh: $sheetform: not an executable (build first)" >&2; exit 2; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
stale=0
for case_dir in "${cases[@]}"; do
  [ -f "$case_dir/case.toml" ] || { echo "update_case_meshes.sh: $case_dir/case.toml: missing" >&2; exit 2; }
  out="$scratch/$(basename "$case_dir")"
  "$sheetform" mesh "$case_dir/case.toml" -o "$out" -q
  for msh in "$out"/*.msh; do
    [ -e "$msh" ] || continue
    target="$case_dir/$(basename "$msh")"
    if [ "$check" -eq 1 ]; then
      if ! cmp -s "$msh" "$target"; then
        echo "stale: $target (missing or not what its .geo makes now; run scripts/update_case_meshes.sh $case_dir)"
        stale=$((stale + 1))
      else
        echo "ok     $target"
      fi
    else
      cp "$msh" "$target"
      echo "wrote  $target"
    fi
  done
done
[ "$stale" -eq 0 ]
