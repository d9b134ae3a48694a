#!/usr/bin/env bash
# The sheetform command: exit codes and messages for good and bad input.
#   cli_test.sh SHEETFORM SOURCE_DIR WORK_DIR
set -u
sheetform="$1"; src="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
source "$(dirname "$0")/expect.sh"

# Work on a copy of the demo case folder (geometry files are found relative to the case file).
cp -r "$src/cases/square_cup_aluminium" "$work/case"; rm -rf "$work/case/results"
demo="$work/case/case.toml"
expect "check demo" 0 "Case is valid" -- "$sheetform" check "$demo"
expect "check prints cycles" 0 "Cycles +about [0-9]+" -- "$sheetform" check "$demo"
expect "check prints the force-controlled holder" 0 "'holder'.*force-controlled.*mass [0-9.e+-]+ tonne.*sqrt\(sum k / mass\) dt = 0\.[0-9]+" -- "$sheetform" check "$demo"
expect "missing case file" 2 "case.toml" -- "$sheetform" run "$work/nowhere/case.toml"
expect "no subcommand" 2 "subcommand" -- "$sheetform"

# A case with an unknown key: exit 2 and the key is named.
sed 's/^thickness = 0.81 .*/thickness = 0.81\nthicknes = 0.8/' "$demo" > "$work/case/cli_test_unknown.toml"
expect "unknown key" 2 "thicknes" -- "$sheetform" check "$work/case/cli_test_unknown.toml"
# A negative thickness: exit 2, the key named.
sed 's/^thickness = 0.81/thickness = -0.81/' "$demo" > "$work/case/cli_test_negative.toml"
expect "negative thickness" 2 "blank.thickness" -- "$sheetform" check "$work/case/cli_test_negative.toml"
# A missing physical group: exit 2, the group named.
sed 's/^group = "blank"/group = "no_such_group"/' "$demo" > "$work/case/cli_test_group.toml"
expect "missing group" 2 "no_such_group" -- "$sheetform" check "$work/case/cli_test_group.toml"
# Mass-proportional damping too strong for the time step (c dt = 4 > 2: the explicit damping update
# amplifies) makes the run unstable: it stops (exit 3) with a diagnosis naming the key, and the
# frames so far stay readable. (A coarse 5 mm blank keeps it quick: dt = 8.3e-7 s.)
sed -e 's/^output_frames = 40/output_frames = 40\ndamping = 5.0e6/' \
    -e 's/^element_size = 2.5 .*/element_size = 5.0/' "$demo" > "$work/case/cli_test_unstable.toml"
"$sheetform" run "$work/case/cli_test_unstable.toml" -o "$work/unstable" --stroke 12 > "$work/unstable.log" 2>&1
unstable_rc=$?
expect "unstable run" 3 "unstable: energy blow-up at t = .* cycle [0-9]+.*control.damping.*the last frame in the results \(t = [0-9.e+-]+ s\) is the state at the stop" -- bash -c "cat '$work/unstable.log'; exit $unstable_rc"
if h5ls "$work/unstable/results.h5/parts/blank/frames" >/dev/null 2>&1 && grep -q "<Time" "$work/unstable/blank.xdmf"; then
  passed=$((passed+1))
else
  echo "FAIL unstable run: results not readable after the stop"; failures=$((failures+1))
fi
# The last frame is the state at the stop: its time is the stop time the message gives.
stop_time=$(sed -nE 's/.*the last frame in the results \(t = ([0-9.e+-]+) s\).*/\1/p' "$work/unstable.log")
last_time=$(grep -oE '<Time Value="[^"]+"' "$work/unstable/blank.xdmf" | tail -1 | sed -E 's/.*"([^"]+)"/\1/')
if [ -n "$stop_time" ] && python3 -c "import sys; a, b = map(float, sys.argv[1:]); sys.exit(0 if abs(a - b) <= 1e-6 * abs(a) else 1)" "$stop_time" "$last_time"; then
  echo "ok   unstable run: last frame at the stop time ($last_time s)"; passed=$((passed+1))
else
  echo "FAIL unstable run: last frame time '$last_time' is not the stop time '$stop_time'"; failures=$((failures+1))
fi

# mesh writes the parts; a short run writes results, the summary and the resolved case.
expect "mesh" 0 "Meshes written" -- "$sheetform" mesh "$demo" -o "$work/mesh"
for f in results.h5 blank.xdmf punch.xdmf die.xdmf holder.xdmf; do
  [ -f "$work/mesh/$f" ] && passed=$((passed+1)) || { echo "FAIL mesh: $f missing"; failures=$((failures+1)); }
done
expect "short run" 0 "draw-in DX" -- "$sheetform" run "$demo" -o "$work/run" --stroke 0.5
for f in results.h5 blank.xdmf summary.json case.resolved.toml; do
  [ -f "$work/run/$f" ] && passed=$((passed+1)) || { echo "FAIL run: $f missing"; failures=$((failures+1)); }
done
# The history's draw-in columns end at the summary's draw-ins (the same measure, same state).
expect "history draw-in = summary draw-in; measured at 40 mm not compared at 0.5 mm" 0 "^draw-in ok" -- /usr/bin/python3 -c "
import h5py, json, sys
h = h5py.File(sys.argv[1], 'r')['history']
s = json.load(open(sys.argv[2]))['draw_in']
bad = [n for n in ('DX', 'DD') if h['draw_in_' + n][-1] != s[n]['computed_mm']]
# The measured values are for 40 mm of stroke (measured_stroke); this run ends at 0.5 mm.
bad += [n + ' compared' for n in ('DX', 'DD') if s[n]['compared'] is not False]
print('draw-in ok' if not bad else 'mismatch: ' + ', '.join(bad))
" "$work/run/results.h5" "$work/run/summary.json"
# ParaView opens what the run wrote: every part, all frames, all arrays (scripts/run_tests.sh
# installs ParaView, so a missing pvpython is a failure, not a skip).
if command -v pvpython >/dev/null; then
  # The times ParaView must show: the frames' time attributes in results.h5 (41 frames: output_frames = 40 and the initial one).
  times=$(/usr/bin/python3 -c "import h5py,sys; g=h5py.File(sys.argv[1],'r')['parts/blank/frames']; print(' '.join(repr(float(g[k].attrs['time'])) for k in sorted(g)))" "$work/run/results.h5")
  [ "$(wc -w <<<"$times")" -eq 41 ] && passed=$((passed+1)) || { echo "FAIL run: expected 41 frames, got: $times"; failures=$((failures+1)); }
  expect "ParaView reads blank.xdmf" 0 "" -- pvpython "$src/scripts/check_xdmf.py" "$work/run/blank.xdmf" --times $times \
    --points 961 --cells 900 --point-arrays displacement:3 velocity:3 contact_force:3 \
    contact_pressure_punch:1 sliding_distance_punch:1 contact_pressure_die:1 sliding_distance_die:1 contact_pressure_holder:1 sliding_distance_holder:1 contact_tool:1 \
    --cell-arrays thickness:1 plastic_strain:1 stress_mid:6 stress_top:6 stress_bottom:6 \
    major_strain_bottom:1 minor_strain_bottom:1 major_strain_mid:1 minor_strain_mid:1 major_strain_top:1 minor_strain_top:1 \
    thinning_percent:1 flc_margin:1 formability_zone:1 wrinkle_indicator:1
  for tool in punch die holder; do
    expect "ParaView reads $tool.xdmf" 0 "" -- pvpython "$src/scripts/check_xdmf.py" "$work/run/$tool.xdmf" --times $times \
      --points "$(grep -o 'Dimensions="[0-9]* 3"' "$work/run/$tool.xdmf" | sed -n 2p | grep -o '[0-9]*' | head -1)" \
      --cells "$(grep -o 'NumberOfElements="[0-9]*"' "$work/run/$tool.xdmf" | head -1 | grep -o '[0-9]*')" \
      --point-arrays displacement:3
  done
else
  echo "FAIL ParaView: pvpython not found (scripts/run_tests.sh installs it)"; failures=$((failures+1))
fi
# --search overrides every [[contact]]'s search; the resolved case records it.
expect "--search override" 0 "draw-in DX" -- "$sheetform" run "$demo" -o "$work/run_standard" --stroke 0.2 --search standard
n_standard=$(grep -c '^search = "standard"' "$work/run_standard/case.resolved.toml")
[ "$n_standard" -eq 3 ] && passed=$((passed+1)) || { echo "FAIL --search: $n_standard of 3 contacts resolved as standard"; failures=$((failures+1)); }
expect "--search unknown name" 2 "search" -- "$sheetform" run "$demo" -o "$work/run_bad" --search nearest
# The resolved case is itself a valid case.
cp "$work/run/case.resolved.toml" "$work/case/cli_test_resolved.toml"
expect "resolved case re-reads" 0 "Case is valid" -- "$sheetform" check "$work/case/cli_test_resolved.toml"

# Threads: the count in the banner and the summary; a bad count is bad input.
expect "threads in the banner" 0 "Threads +2 \(OpenMP" -- \
  env OMP_WAIT_POLICY=passive "$sheetform" run "$demo" --stroke 0.02 --threads 2 -o "$work/threads"
expect "threads in summary.json" 0 '"threads": 2' -- cat "$work/threads/summary.json"
expect "threads 0 refused" 2 "threads" -- "$sheetform" run "$demo" --threads 0 -o "$work/threads0"

# End-condition overrides must be finite and positive (issue 18: they were silently ignored).
for bad in "--stroke -5" "--stroke nan" "--stroke 0" "--end-time -1" "--end-time inf"; do
  # shellcheck disable=SC2086  # the option and its value are two words
  expect "run $bad refused" 2 "expected a finite value > 0" -- "$sheetform" run "$demo" $bad -o "$work/bad_end"
done

# Bad meshes are bad input naming the node or element (issue 18: a repeated node tag was taken
# silently, a non-finite coordinate or a zero-area element reported as an unstable run, exit 3).
# The membrane patch's four-quad .msh, edited: node 6 given twice, node 6's x as nan, node 5 moved
# onto node 1 (quad 9, nodes 1 2 5 4, then has no area).
cp -r "$src/cases/verify_patch" "$work/patch"
sed -i 's/^mesh = "blank.geo"/mesh = "blank.msh"/' "$work/patch/case.toml"
/usr/bin/python3 - "$work/patch" <<'PY'
import sys, pathlib
d = pathlib.Path(sys.argv[1]); s = (d / "blank.msh").read_text()
edits = {"dup": [("0 6 0 1\n6\n10 5 0", "0 6 0 2\n6\n6\n10 5 0\n11 5 0"), ("17 9 1 9", "17 10 1 9")],
         "nan": [("0 6 0 1\n6\n10 5 0", "0 6 0 1\n6\nnan 5 0")],
         "zero": [("0 5 0 1\n5\n4.2 6.1 0", "0 5 0 1\n5\n0 0 0")]}
case = (d / "case.toml").read_text()
for name, pairs in edits.items():
    t = s
    for a, b in pairs:
        assert a in t, (name, a)
        t = t.replace(a, b, 1)
    (d / f"{name}.msh").write_text(t)
    (d / f"{name}.toml").write_text(case.replace('mesh = "blank.msh"', f'mesh = "{name}.msh"'))
PY
expect "patch .msh reads" 0 "Case is valid" -- "$sheetform" check "$work/patch/case.toml"
expect "repeated node tag" 2 "node tag 6 appears more than once" -- "$sheetform" check "$work/patch/dup.toml"
expect "non-finite coordinate" 2 "node 6 has a non-finite coordinate" -- "$sheetform" check "$work/patch/nan.toml"
expect "zero-area element" 2 "element 9 has zero area" -- "$sheetform" run "$work/patch/zero.toml" -o "$work/zero"

# Names that name results are checked with the case (issue 18: they failed at run time, exit 1).
sed 's/^name = "DX"/name = "D X"/' "$demo" > "$work/case/cli_test_draw_in_name.toml"
expect "draw-in name with a space" 2 'draw_in\[0\]\.name: expected a name of letters' -- \
  "$sheetform" check "$work/case/cli_test_draw_in_name.toml"
sed -e 's/^name = "punch"/name = "my punch"\ngroup = "punch"/' -e 's/"punch"$/"my punch"/' \
  "$demo" > "$work/case/cli_test_tool_name.toml"
expect "tool name with a space" 2 'tools\[0\]\.name: expected a name of letters' -- \
  "$sheetform" check "$work/case/cli_test_tool_name.toml"

# Mass scaling that would add more than the blank's own mass (the default limit, 100 %) is refused
# before the run (issue 18: 1e12 times the mass ran with a warning).
expect "mass scaling beyond the default limit" 2 "mass_scaling_dt.*adds .* more than control.mass_scaling_max_added = 100.00 %" -- \
  "$sheetform" check "$demo" --set control.mass_scaling_dt=1e-3

# -o naming a file is bad input (issue 18: an internal error, exit 1).
touch "$work/a_file"
expect "run -o naming a file" 2 "results folder .*a_file: cannot create it" -- \
  "$sheetform" run "$demo" --stroke 0.01 -o "$work/a_file"
expect "mesh -o naming a file" 2 "results folder .*a_file: cannot create it" -- \
  "$sheetform" mesh "$demo" -o "$work/a_file"
expect "-o under a file" 2 "results folder .*a_file/sub: cannot create it" -- \
  "$sheetform" run "$demo" --stroke 0.01 -o "$work/a_file/sub"

# A case's .geo must not run commands (issue 18: SystemCall ran `touch`): SystemCall and Exit,
# also in an included file, are refused before gmsh reads them, unless --allow-geo-system-calls.
cp -r "$src/cases/verify_patch" "$work/geo"
printf '// SystemCall "in a comment" is harmless;\nSystemCall "touch %s";\n' "$work/geo/marker" >> "$work/geo/blank.geo"
expect "geo SystemCall refused" 2 "blank.geo', line [0-9]+: the statement SystemCall" -- \
  "$sheetform" check "$work/geo/case.toml"
[ ! -e "$work/geo/marker" ] && passed=$((passed+1)) || { echo "FAIL geo SystemCall: the command ran"; failures=$((failures+1)); }
expect "geo SystemCall allowed" 0 "Case is valid" -- "$sheetform" check "$work/geo/case.toml" --allow-geo-system-calls
[ -e "$work/geo/marker" ] && passed=$((passed+1)) || { echo "FAIL --allow-geo-system-calls: the command did not run"; failures=$((failures+1)); }
printf 'Exit;\n' > "$work/geo/exit.geo"
grep -v SystemCall "$work/geo/blank.geo" > "$work/geo/blank_include.geo"
printf 'Include "exit.geo";\n' >> "$work/geo/blank_include.geo"
sed 's/"blank.geo"/"blank_include.geo"/' "$work/geo/case.toml" > "$work/geo/include.toml"
expect "geo Exit in an included file refused" 2 "exit.geo', line 1: the statement Exit" -- \
  "$sheetform" check "$work/geo/include.toml"
grep -v SystemCall "$work/geo/blank.geo" > "$work/geo/blank_computed.geo"
printf 'Include StrCat("ex", "it.geo");\n' >> "$work/geo/blank_computed.geo"
sed 's/"blank.geo"/"blank_computed.geo"/' "$work/geo/case.toml" > "$work/geo/computed.toml"
expect "geo computed Include refused" 2 "Include with a computed path cannot be checked" -- \
  "$sheetform" check "$work/geo/computed.toml"

# No input runs until killed (issue 18, item 3): check prints the cost, and what exceeds the
# case's [limits] is refused before any work (exit 2, the limit named), each of which ran until
# killed before: a density of 1e-300, 2e9 frames, a .geo asked for 1e10 elements, a mesh path
# with a NUL, a .geo with an endless loop (gmsh's time budget).
expect "check prints the cost" 0 "Cost +about [0-9.e+]+ cycles x 900 elements = .* element-cycles" -- "$sheetform" check "$demo"
expect "check prints memory and output" 0 "Memory +about [0-9]+ MB; output about [0-9]+ MB \(40 frames" -- "$sheetform" check "$demo"
# (A density of 1e-300 is now refused as no sheet's density, tests/cli/bad_values_test.sh; 1e-16
# is one in some unit system, with a warning, and asks for too many cycles.)
expect "density 1e-16 refused" 2 "the run needs about .* cycles .* more than limits.max_cycles = 1e\+08" -- \
  "$sheetform" run "$demo" -o "$work/tiny_density" --set materials.aluminium.density=1e-16
expect "2e9 frames refused" 2 "control.output_frames = 2000000000, more than limits.max_frames = 10000" -- \
  "$sheetform" check "$demo" --set control.output_frames=2000000000
expect "1e10 elements refused before meshing" 2 "blank.geo.*element_size = 0.001 mm asks gmsh for about [0-9.e+]+ elements.*limits.max_elements" -- \
  "$sheetform" check "$demo" --set blank.element_size=1e-3
expect "a limit raised" 0 "Case is valid" -- "$sheetform" check "$demo" --set limits.max_frames=20000 --set control.output_frames=15000
cp -r "$src/cases/verify_patch" "$work/nul"
sed -i 's|^mesh = "blank.geo"|mesh = "blank\\u0000.geo"|' "$work/nul/case.toml"
expect "mesh path with a NUL refused" 2 "blank.mesh.*without a NUL character" -- "$sheetform" check "$work/nul/case.toml"
cp -r "$src/cases/verify_patch" "$work/loop"
printf 'For i In {1:1e15}\nEndFor\n' >> "$work/loop/blank.geo"
start=$SECONDS
expect "endless .geo loop stopped" 2 "blank.geo.*gmsh did not finish reading and meshing it within 2 s \(limits.mesh_seconds; stopped while reading\)" -- \
  "$sheetform" check "$work/loop/case.toml" --set limits.mesh_seconds=2
[ $((SECONDS - start)) -lt 30 ] && passed=$((passed+1)) || { echo "FAIL endless loop: $((SECONDS - start)) s"; failures=$((failures+1)); }
# Tools inside the blank at the start are reported at check, and refused beyond the limit.
expect "initial penetration reported" 0 "'holder' penetrates the blank at [0-9]+ nodes: deepest node [0-9]+ at .* by 0.595 mm \(29.8 % of the thickness\)" -- \
  "$sheetform" check "$demo" --set blank.thickness=2
expect "no penetration said" 0 "'holder' does not penetrate the blank" -- "$sheetform" check "$demo"
expect "initial penetration refused" 2 "tool 'punch' penetrates the blank at the start at [0-9]+ nodes.*limits.max_initial_penetration = 0.2" -- \
  "$sheetform" check "$demo" --set blank.thickness=2 --set limits.max_initial_penetration=0.2
expect "memory limit" 2 "the run needs about .* GB of memory, more than limits.max_memory_gb = 0.01" -- \
  "$sheetform" check "$demo" --set limits.max_memory_gb=0.01
# Tool meshes are diagnosed at check and at the start of a run (docs/tool-diagnosis.md): the demo's
# tools are clean; a lid whose two faces are 0.05 mm apart has its gap named, and its clearance.
expect "clean tool said" 0 "Tool mesh +'die': [0-9]+ triangles: no gaps, overlaps, near-zero-area triangles or folds" -- \
  "$sheetform" check "$demo"
lid="$src/tests/data/cracked_tool/case.toml"
expect "gap between faces named" 0 "warning: tool 'lid': 8 free edges run beside another free edge .*widest gap 0.05 mm at \(0.5, [0-9.]+, 0.6\), narrowest 0.05 mm" -- \
  "$sheetform" check "$lid"
expect "clearance said" 0 "Clearance +'lid' clears the blank by 0.5 mm at \([0-9.-]+, [0-9.-]+, 0.6\) on the tool" -- \
  "$sheetform" check "$lid"
expect "run logs the tool diagnosis" 0 "warning: tool 'lid': 8 free edges run beside" -- \
  "$sheetform" run "$lid" -o "$work/lid"
# The lid's two STL faces: an open surface of two boundaries, as read (normals -z, to the blank).
expect "surface said" 0 "Surface +'lid': open: 2 boundaries, 24 free edges \(11.9 mm in all\); 2 components; orientation as read" -- \
  "$sheetform" check "$lid"

# A blank from a planar STEP face has no physical groups: its supports and measurement point are
# node groups chosen by position ([[node_group]]), printed with their node counts, used by a
# boundary, a prescribed velocity and a history group, and written to the resolved case.
cad_blank="$src/tests/data/cad_blank/case.toml"
expect "node group by plane" 0 "Boundary +'clamped': 11 nodes, fixed" -- "$sheetform" check "$cad_blank"
expect "node group by point" 0 "Node group  'corner': 1 node, the node at \(60, 40, 0\) mm" -- \
  "$sheetform" check "$cad_blank"
expect "misspelt node group" 2 "boundary\[0\].group: .*no physical group 'clampd'.*; node groups of the case: clamped, tip_edge, corner" -- \
  "$sheetform" check "$cad_blank" --set 'boundary[0].group="clampd"'
expect "empty node group" 2 "node_group\[1\]: node group 'tip_edge' chooses no blank node \(inside the box" -- \
  "$sheetform" check "$cad_blank" --set 'node_group[1].box=[70.0, -1.0, -1.0, 71.0, 41.0, 1.0]'
expect "node groups run" 0 "reaction prescribed_velocity\[0\] 'tip_edge'" -- \
  "$sheetform" run "$cad_blank" -o "$work/cad_blank"
expect "node groups in the resolved case" 0 "^\\[\\[node_group\\]\\]" -- cat "$work/cad_blank/case.resolved.toml"

# A full disk (issue 18: "internal error", then a segmentation fault, exit 139): exit 6, said,
# and what was written before stays readable. A 6 MB tmpfs holds a few frames; where
# mounting is not allowed, a file-size limit (ulimit -f, SIGXFSZ ignored) stands in for it. A
# read-only parent of -o (root writes anywhere else) is bad input, exit 2.
steel="$src/cases/square_cup_steel/case.toml"
disk="$work/small_disk"; mkdir -p "$disk" "$work/read_only"
if mount -t tmpfs -o size=6m tmpfs "$disk" 2>/dev/null; then
  expect "full disk" 6 "the disk is full" -- \
    "$sheetform" run "$steel" --stroke 0.5 --set blank.element_size=1.875 -q -o "$disk/out"
  mount -t tmpfs -o ro,size=100k tmpfs "$work/read_only"
  expect "read-only parent of -o" 2 "results folder .*read_only/out: cannot create it \(Read-only file system\)" -- \
    "$sheetform" run "$demo" --stroke 0.01 -o "$work/read_only/out"
  umount "$work/read_only"
else
  echo "note: cannot mount a tmpfs here; a file-size limit stands in for the full disk"
  expect "file size limit" 6 "the disk is full" -- bash -c 'trap "" XFSZ; ulimit -f 6000; exec "$@"' _ \
    "$sheetform" run "$steel" --stroke 0.5 --set blank.element_size=1.875 -q -o "$disk/out"
fi
/usr/bin/python3 - "$disk/out" <<'PY' && passed=$((passed+1)) || { echo "FAIL full disk: the results are not readable"; failures=$((failures+1)); }
import sys, h5py, xml.etree.ElementTree as ET
with h5py.File(sys.argv[1] + "/results.h5") as f:
    assert "000000" in f["parts/blank/frames"] and f["history/time"].shape[0] >= 1
frames = ET.parse(sys.argv[1] + "/blank.xdmf").getroot().findall(".//Time")
assert len(frames) >= 1, "no frame listed"
PY
mountpoint -q "$disk" && umount "$disk"

# --restart with what is not a checkpoint of the case (exit 2, the file named).
expect "restart from a missing file" 2 "nowhere.h5: no such checkpoint file" -- \
  "$sheetform" run "$demo" -o "$work/restart_missing" --restart "$work/nowhere.h5"
expect "restart from a case file" 2 "case.toml: cannot read the checkpoint" -- \
  "$sheetform" run "$demo" -o "$work/restart_toml" --restart "$demo"
expect "restart of a static analysis" 2 "--restart continues an explicit run" -- \
  "$sheetform" run "$src/cases/shell_scordelis_lo/case.toml" -o "$work/restart_static" --restart "$work/nowhere.h5"

# A results folder holding an earlier run is not mixed with a new one: refused (exit 2), or
# replaced with --overwrite.
expect "earlier run refused" 2 "holds the results of an earlier run \(results.h5\); give --overwrite" -- \
  "$sheetform" run "$demo" -o "$work/run" --stroke 0.05
expect "--overwrite replaces it" 0 "draw-in DX" -- "$sheetform" run "$demo" -o "$work/run" --stroke 0.05 --overwrite

echo "$passed passed, $failures failed"
[ "$failures" -eq 0 ]
