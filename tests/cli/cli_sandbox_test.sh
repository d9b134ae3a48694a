#!/usr/bin/env bash
# A case cannot touch the machine, and no mesh source crashes or hangs sheetform (issue 31;
# docs/security.md): .geo files that try to run commands, write or read outside the case folder by
# routes the old scan did not follow; CAD, STL and .msh files that crash gmsh or OpenCASCADE, hang
# them, or are cut short. Each of these passed `check` (or crashed it, or hung it) before the
# sandbox; each is now an exit-2 message naming the file, with no side effect.
#   cli_sandbox_test.sh SHEETFORM SOURCE_DIR WORK_DIR
set -u
sheetform="$1"; src="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
source "$(dirname "$0")/expect.sh"

# A case of the unit-square plate under a lid tool (tests/data/cracked_tool), all in one folder.
make_case() {  # make_case DIR TOOL_MESH_FILE [tool keys]
  local dir="$1" tool="$2" keys="${3:-}"
  mkdir -p "$dir"
  cp "$src/tests/data/unit_square_quads.geo" "$dir/blank.geo"
  sed -e 's|^mesh = "../unit_square_quads.geo"|mesh = "blank.geo"|' \
      -e "s|^mesh = \"lid.stl\"|mesh = \"$tool\"\n$keys|" \
      "$src/tests/data/cracked_tool/case.toml" > "$dir/case.toml"
  cp "$src/tests/data/cracked_tool/lid.stl" "$dir/lid.stl"
}

outside="$work/outside"; mkdir -p "$outside"
marker="$outside/pwned"

# --- .geo files that run commands by routes the scan once missed: it now follows every Include
# and every Merge of a script, and the sandbox stops what gets past it.
make_case "$work/include_txt" lid.stl
printf 'SystemCall "touch %s";\n' "$marker" > "$work/include_txt/payload.txt"
printf 'Include "payload.txt";\n' >> "$work/include_txt/blank.geo"
expect "Include of a .txt holding SystemCall" 2 "payload.txt', line 1: the statement SystemCall" -- \
  "$sheetform" check "$work/include_txt/case.toml"
absent "Include of a .txt" "$marker"

make_case "$work/include_upper" lid.stl
printf 'SystemCall "touch %s";\n' "$marker" > "$work/include_upper/PAYLOAD.GEO"
printf 'Include "PAYLOAD.GEO";\n' >> "$work/include_upper/blank.geo"
expect "Include of a .GEO holding SystemCall" 2 "PAYLOAD.GEO', line 1: the statement SystemCall" -- \
  "$sheetform" check "$work/include_upper/case.toml"
absent "Include of a .GEO" "$marker"

make_case "$work/merge_txt" lid.stl
printf 'SystemCall "touch %s";\n' "$marker" > "$work/merge_txt/payload.txt"
printf 'Merge "payload.txt";\n' >> "$work/merge_txt/blank.geo"
expect "Merge of a .txt holding SystemCall" 2 "payload.txt', line 1: the statement SystemCall" -- \
  "$sheetform" check "$work/merge_txt/case.toml"
absent "Merge of a .txt" "$marker"

# --- Files written and read by a .geo: only the sandbox stops these (the scan does not look).
make_case "$work/printf" lid.stl
printf 'Printf("pwned") > "%s";\n' "$marker" >> "$work/printf/blank.geo"
expect "Printf to a file outside the case" 2 "blank.geo', line [0-9]+: Unable to open file '.*outside/pwned'" -- \
  "$sheetform" check "$work/printf/case.toml"
absent "Printf to a file outside" "$marker"
make_case "$work/printf_here" lid.stl
printf 'Printf("pwned") > "written.txt";\n' >> "$work/printf_here/blank.geo"
expect "Printf to a file in the case folder" 2 "Unable to open file" -- \
  "$sheetform" check "$work/printf_here/case.toml"
absent "Printf in the case folder" "$work/printf_here/written.txt"

make_case "$work/read_outside" lid.stl
cp "$src/tests/data/unit_square_quads.geo" "$outside/secret.geo"
printf 'Include "../outside/secret.geo";\n' > "$work/read_outside/blank.geo"
expect "Include of a file outside the case folder" 2 "Unable to open file .*outside/secret.geo" -- \
  "$sheetform" check "$work/read_outside/case.toml"

# --- CAD, STL and .msh files that crashed, hung or were half read.
make_case "$work/crash_step" tool.step "element_size = 0.5"
cp "$src/tests/data/cad/crashes_opencascade.step" "$work/crash_step/tool.step"
expect "a STEP file that crashes OpenCASCADE" 2 "tool.step': gmsh crashed reading it \(Segmentation fault\)" -- \
  "$sheetform" check "$work/crash_step/case.toml"

make_case "$work/hang_step" tool.step "element_size = 5"
cp "$src/tests/data/cad/hangs_gmsh_meshing.step" "$work/hang_step/tool.step"
start=$SECONDS
expect "a STEP file gmsh meshes without end" 2 "tool.step': gmsh did not finish reading and meshing it within 3 s \(limits.mesh_seconds; stopped while meshing\)" -- \
  "$sheetform" check "$work/hang_step/case.toml" --set limits.mesh_seconds=3
[ $((SECONDS - start)) -lt 30 ] && passed=$((passed+1)) || { echo "FAIL hanging STEP: $((SECONDS - start)) s"; failures=$((failures+1)); }

make_case "$work/cut_brep" tool.brep "element_size = 5"
head -c 900 "$src/tests/data/cad/punch.brep" > "$work/cut_brep/tool.brep"
start=$SECONDS
expect "a BREP file cut short" 2 "tool.brep': the BREP file is not whole" -- \
  "$sheetform" check "$work/cut_brep/case.toml"
[ $((SECONDS - start)) -lt 30 ] && passed=$((passed+1)) || { echo "FAIL cut BREP: $((SECONDS - start)) s"; failures=$((failures+1)); }

make_case "$work/cut_stl" lid.stl
head -n -9 "$src/tests/data/cracked_tool/lid.stl" > "$work/cut_stl/lid.stl"
expect "an ASCII STL file cut short" 2 "lid.stl': the ASCII STL file is not whole: it ends inside a facet" -- \
  "$sheetform" check "$work/cut_stl/case.toml"

cp -r "$src/cases/verify_patch" "$work/big_msh"
sed -i 's|^mesh = "blank.geo"|mesh = "blank.msh"|' "$work/big_msh/case.toml"
awk '/^\$Nodes/ {print; getline; print "17 2000000000 1 2000000000"; next} {print}' \
  "$src/cases/verify_patch/blank.msh" > "$work/big_msh/blank.msh"
expect "a .msh claiming two billion nodes" 2 "blank.msh': the file says its \\\$Nodes section holds 2000000000 nodes, more than its [0-9]+ bytes can" -- \
  "$sheetform" check "$work/big_msh/case.toml"

cp -r "$src/cases/verify_patch" "$work/far_node"
sed -i 's|^mesh = "blank.geo"|mesh = "blank.msh"|' "$work/far_node/case.toml"
# Node 1's coordinates (the line after its tag in the first node block) moved to x = 1e300.
awk '/^\$Nodes/ {nodes = 1} nodes && !done && prev == "1" && NF == 3 {print "1e300 0 0"; done = 1; next} {prev = $0; print}' \
  "$src/cases/verify_patch/blank.msh" > "$work/far_node/blank.msh"
expect "a node at 1e300" 2 "blank.msh', physical group .*: node 1 lies at \(1e\+300, 0, 0\), beyond 1e\+12" -- \
  "$sheetform" check "$work/far_node/case.toml"

# --- check says what the sandbox is on this machine.
expect "check describes the sandbox" 0 "Sandbox +gmsh reads the mesh files in a sandbox: no programs can be started \(seccomp\); files are read only in the mesh file's folder and written only in a scratch folder \(Landlock ABI [0-9]+\)" -- \
  "$sheetform" check "$src/cases/verify_patch/case.toml"

echo "cli_sandbox: $passed passed, $failures failed"
[ "$failures" -eq 0 ]
