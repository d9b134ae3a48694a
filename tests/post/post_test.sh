#!/usr/bin/env bash
# Post-processing end to end (docs/post-processing.md): a short square-cup run with a forming
# limit curve, then
#   (a) ParaView reads blank.xdmf and every tool's .xdmf (scripts/check_xdmf.py),
#   (b) scripts/render_results.py renders thinning.png and plastic_strain.png (pvbatch, Xvfb),
#   (c) scripts/plot_history.py and scripts/plot_forming_limit.py plot, and their CSV files hold
#       the run's own numbers;
# and each script stops with exit code 2 and a message naming what is missing.
#   post_test.sh SHEETFORM SOURCE_DIR WORK_DIR
# scripts/run_tests.sh installs ParaView and Xvfb: a missing pvpython, pvbatch or xvfb-run is a
# failure, not a skip (as in tests/cli/cli_test.sh).
set -u
sheetform="$1"; src="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
failures=0; passed=0
py=/usr/bin/python3
# Xvfb resets when its last client disconnects, and a connection made during the reset fails
# ("bad X server connection", about 1 pvbatch start in 10): -noreset; 24-bit colour for OpenGL.
xvfb=(xvfb-run -a -s "-screen 0 1280x1024x24 -noreset")

pass() { echo "ok   $1"; passed=$((passed+1)); }
fail() { echo "FAIL $1"; failures=$((failures+1)); }

expect() {  # expect NAME CODE PATTERN -- command...
  local name="$1" code="$2" pattern="$3"; shift 4
  local out rc
  out=$("$@" 2>&1); rc=$?
  if [ "$rc" -ne "$code" ]; then
    fail "$name: exit code $rc, expected $code"; echo "$out" | tail -8; return
  fi
  if ! grep -qE -- "$pattern" <<<"$out"; then
    fail "$name: output lacks /$pattern/"; echo "$out" | tail -8; return
  fi
  pass "$name"
}

check() {  # check NAME -- python code (argv: the remaining arguments); exit 0 = pass
  local name="$1"; shift 2
  local out
  if out=$("$py" - "$@" 2>&1); then
    pass "$name${out:+: $out}"
  else
    fail "$name"; echo "$out" | tail -8
  fi
}

# Python checks of a PNG: exists, the size asked for, more than one colour.
png_ok() {  # png_ok NAME FILE WIDTH HEIGHT
  check "$1" -- "$2" "$3" "$4" <<'EOF'
import sys
import numpy as np
import matplotlib.image as mpimg
path, width, height = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
image = mpimg.imread(path)  # [height][width][channels]
assert image.shape[:2] == (height, width), f"{path}: {image.shape[1]} x {image.shape[0]} pixels, expected {width} x {height}"
colours = np.unique(image.reshape(-1, image.shape[2]), axis=0)
assert len(colours) > 1, f"{path}: a single colour {colours[0]}"
print(f"{width} x {height}, {len(colours)} colours")
EOF
}

for program in pvpython pvbatch xvfb-run; do
  command -v "$program" >/dev/null || fail "$program not found (scripts/run_tests.sh installs ParaView and Xvfb)"
done

# The square cup with a forming limit curve. The curve is made up for this test (low, so that
# some elements pass it at 4 mm of stroke); it is not the benchmark aluminium's.
cp -r "$src/cases/square_cup_aluminium" "$work/case"; rm -rf "$work/case/results"
sed 's/^poisson = 0.33.*/&\nforming_limit_curve = [[-0.2, 0.02], [0.0, 0.008], [0.2, 0.02]]/' \
  "$src/cases/square_cup_aluminium/case.toml" > "$work/case/case.toml"
run="$work/run"
expect "run with a forming limit curve" 0 "" -- "$sheetform" run "$work/case/case.toml" -o "$run" --stroke 4 -q
grep -q '^forming_limit_curve = \[\[-0.2, 0.02\], \[0.0, 0.008\], \[0.2, 0.02\]\]' "$run/case.resolved.toml" \
  && pass "the resolved case holds the forming limit curve" \
  || fail "the resolved case lacks forming_limit_curve"
expect "resolved case with the curve re-reads" 0 "Case is valid" -- "$sheetform" check "$run/case.resolved.toml"

# (a) ParaView reads every part: all frames (times from results.h5), points, cells, arrays.
times=$("$py" -c "import h5py,sys; g=h5py.File(sys.argv[1],'r')['parts/blank/frames']; print(' '.join(repr(float(g[k].attrs['time'])) for k in sorted(g)))" "$run/results.h5")
sizes() {  # sizes PART -> "points cells"
  "$py" -c "import h5py,sys; g=h5py.File(sys.argv[1],'r')['parts'][sys.argv[2]]; print(g['reference_coordinates'].shape[0], g['connectivity'].shape[0] + (g['triangle_connectivity'].shape[0] if 'triangle_connectivity' in g else 0))" "$run/results.h5" "$1"
}
read -r points cells <<<"$(sizes blank)"
expect "ParaView reads blank.xdmf" 0 "OK \($(wc -w <<<"$times") time steps\)" -- pvpython "$src/scripts/check_xdmf.py" "$run/blank.xdmf" --times $times \
  --points "$points" --cells "$cells" --point-arrays displacement:3 velocity:3 contact_force:3 \
  contact_pressure_punch:1 sliding_distance_punch:1 contact_pressure_die:1 sliding_distance_die:1 contact_pressure_holder:1 sliding_distance_holder:1 contact_tool:1 \
  --cell-arrays thickness:1 plastic_strain:1 stress_mid:6 stress_top:6 stress_bottom:6 \
  major_strain_bottom:1 minor_strain_bottom:1 major_strain_mid:1 minor_strain_mid:1 major_strain_top:1 minor_strain_top:1 \
  thinning_percent:1 flc_margin:1 formability_zone:1 wrinkle_indicator:1
for tool in punch die holder; do
  read -r points cells <<<"$(sizes "$tool")"
  expect "ParaView reads $tool.xdmf" 0 "OK" -- pvpython "$src/scripts/check_xdmf.py" "$run/$tool.xdmf" --times $times \
    --points "$points" --cells "$cells" --point-arrays displacement:3
done

# (b) Rendering: the default size into the results folder, and another size elsewhere.
expect "render_results.py, default size and folder" 0 "wrote .*plastic_strain.png" -- \
  "${xvfb[@]}" pvbatch "$src/scripts/render_results.py" "$run"
for image in thinning plastic_strain; do png_ok "$image.png 1200 x 800" "$run/$image.png" 1200 800; done
expect "render_results.py --size 640 480 -o, no tools" 0 "wrote .*thinning.png" -- \
  "${xvfb[@]}" pvbatch "$src/scripts/render_results.py" "$run" -o "$work/render" --size 640 480 --no-tools
for image in thinning plastic_strain; do png_ok "$image.png 640 x 480" "$work/render/$image.png" 640 480; done
expect "render_results.py: missing folder" 2 "render_results: $work/nowhere: no such folder" -- \
  "${xvfb[@]}" pvbatch "$src/scripts/render_results.py" "$work/nowhere"
expect "render_results.py --frame 0 --prefix" 0 "wrote .*first_thinning.png" -- \
  "${xvfb[@]}" pvbatch "$src/scripts/render_results.py" "$run" -o "$work/render" --size 640 480 \
  --frame 0 --prefix first_
expect "render_results.py: no such frame" 2 "no frame 999: it has frames 0 to" -- \
  "${xvfb[@]}" pvbatch "$src/scripts/render_results.py" "$run" -o "$work/render" --frame 999
mkdir -p "$work/empty"
expect "render_results.py: missing blank.xdmf" 2 "$work/empty/blank.xdmf: no such file" -- \
  "${xvfb[@]}" pvbatch "$src/scripts/render_results.py" "$work/empty"
# A blank.xdmf without the thickness array (renamed), beside a copy of the results.
mkdir -p "$work/no_thickness"; cp "$run/results.h5" "$run/case.resolved.toml" "$work/no_thickness/"
sed 's/Name="thickness"/Name="thick"/' "$run/blank.xdmf" > "$work/no_thickness/blank.xdmf"
expect "render_results.py: missing array" 2 "no_thickness/blank.xdmf: no cell array 'thickness'" -- \
  "${xvfb[@]}" pvbatch "$src/scripts/render_results.py" "$work/no_thickness"

# (c) History plots and their CSV files.
plots="$work/plots"
expect "plot_history.py --csv" 0 "wrote .*energies.csv" -- "$py" "$src/scripts/plot_history.py" "$run" -o "$plots" --csv
png_ok "punch_force.png" "$plots/punch_force.png" 960 600
png_ok "energies.png" "$plots/energies.png" 960 840
check "punch force CSV ends at the summary's final force and travel" -- "$plots/punch_force.csv" "$run/summary.json" "$run/results.h5" <<'EOF'
import csv, json, sys
import h5py
rows = list(csv.DictReader(open(sys.argv[1])))
punch = json.load(open(sys.argv[2]))["tools"]["punch"]
n = h5py.File(sys.argv[3], "r")["history/time"].shape[0]
assert len(rows) == n, f"{len(rows)} rows, the history has {n}"
force_n = float(rows[-1]["punch_force_kN"]) * 1e3
travel = float(rows[-1]["punch_travel_mm"])
# Same doubles, through kN and back and the CSV's repr: 1e-9 relative is round-off.
assert abs(force_n - punch["final_force_N"]) <= 1e-9 * abs(punch["final_force_N"]), (force_n, punch)
assert abs(travel - punch["travel_mm"]) <= 1e-9 * abs(punch["travel_mm"]), (travel, punch)
print(f"{force_n:.6g} N at {travel:.6g} mm")
EOF
check "energies CSV ends at the summary's energies" -- "$plots/energies.csv" "$run/summary.json" <<'EOF'
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
energy = json.load(open(sys.argv[2]))["energy_Nmm"]
last = rows[-1]
for column, key in [("kinetic_Nmm", "kinetic"), ("internal_Nmm", "internal"),
                    ("hourglass_Nmm", "hourglass"), ("contact_Nmm", "contact"),
                    ("friction_work_Nmm", "friction_work"), ("external_work_Nmm", "external_work")]:
    value = float(last[column])
    # The summary and the last history row are the same state: equal to round-off (1e-9).
    assert abs(value - energy[key]) <= 1e-9 * max(abs(energy[key]), 1e-30), (column, value, energy[key])
ratio = float(last["kinetic_over_internal"])
assert abs(ratio - energy["kinetic"] / energy["internal"]) <= 1e-9 * ratio, ratio
print(f"{len(rows)} rows")
EOF
# The solver writes a draw_in_<name> history column per [[draw_in]]: draw_in.png and its CSV, which
# ends at the summary's draw-ins.
png_ok "draw_in.png" "$plots/draw_in.png" 960 600
check "draw-in CSV ends at the summary's draw-ins" -- "$plots/draw_in.csv" "$run/summary.json" <<'EOF'
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
draw_in = json.load(open(sys.argv[2]))["draw_in"]
for name in ("DX", "DD"):
    value, reference = float(rows[-1][f"draw_in_{name}_mm"]), draw_in[name]["computed_mm"]
    # The same double through the CSV's repr: 1e-12 relative is round-off.
    assert abs(value - reference) <= 1e-12 * abs(reference), (name, value, reference)
print(f"{len(rows)} rows, DX {rows[-1]['draw_in_DX_mm']} mm")
EOF
expect "plot_history.py --tool holder" 0 "wrote .*holder_force.png" -- "$py" "$src/scripts/plot_history.py" "$run" -o "$work/holder" --tool holder
expect "plot_history.py: unknown tool" 2 "results.h5: /history has no column 'ram_travel'" -- "$py" "$src/scripts/plot_history.py" "$run" -o "$work/ram" --tool ram
expect "plot_history.py: missing folder" 2 "plot_history: $work/nowhere: no such folder" -- "$py" "$src/scripts/plot_history.py" "$work/nowhere"
expect "plot_history.py: missing results.h5" 2 "$work/empty/results.h5: no such file" -- "$py" "$src/scripts/plot_history.py" "$work/empty"

# Forming limit diagram, with the curve.
out=$("$py" "$src/scripts/plot_forming_limit.py" "$run" -o "$plots" --csv 2>&1); rc=$?
echo "$out" | sed 's/^/     /'
[ "$rc" -eq 0 ] && pass "plot_forming_limit.py --csv" || fail "plot_forming_limit.py: exit code $rc"
png_ok "forming_limit.png" "$plots/forming_limit.png" 840 840
check "forming limit CSV: one point per element, the printed count and worst margin" -- \
  "$plots/forming_limit.csv" "$run/results.h5" "$out" "$run/case.resolved.toml" "$src/scripts" <<'EOF'
import csv, re, sys, tomllib
import h5py
import numpy as np
rows = list(csv.DictReader(open(sys.argv[1])))
f = h5py.File(sys.argv[2], "r")
blank = f["parts/blank"]
n = blank["connectivity"].shape[0] + (blank["triangle_connectivity"].shape[0] if "triangle_connectivity" in blank else 0)
assert len(rows) == n, f"{len(rows)} points, {n} elements"
assert [int(r["element"]) for r in rows] == list(range(n))
major = np.array([float(r["major_true_strain"]) for r in rows])
minor = np.array([float(r["minor_true_strain"]) for r in rows])
margin = np.array([float(r["flc_margin"]) for r in rows])
zone = np.array([int(r["formability_zone"]) for r in rows])
assert np.all(major >= minor)
# The curve [[-0.2, 0.02], [0.0, 0.008], [0.2, 0.02]] by hand at each minor strain (1e-15).
limit = np.where(minor < 0.0, 0.008 - 0.06 * np.maximum(minor, -0.2), 0.008 + 0.06 * np.minimum(minor, 0.2))
assert np.allclose(margin, limit - major, rtol=0.0, atol=1e-15)
above = int(np.count_nonzero(margin < 0.0))
match = re.search(r"(\d+) of (\d+) elements above the forming limit curve; least margin (\S+)", sys.argv[3])
assert match, "no count printed"
assert int(match.group(1)) == above and int(match.group(2)) == n, (match.group(0), above, n)
assert 0 < above < n, f"{above} of {n} above: the made-up curve should split them"
assert abs(float(match.group(3)) - margin.min()) <= 1e-5 * abs(margin.min())  # printed to 6 digits
# The solver's fields against this script's own arithmetic: its strains (forming_strains.py,
# from the coordinates) and margin equal the frame's major_strain_mid, minor_strain_mid and
# flc_margin to round-off (1e-12), and the elements above the curve are those of zone 5 (cracks).
frame = sorted(blank["frames"])[-1]
group = blank["frames"][frame]
sys.path.insert(0, sys.argv[5])
import forming_strains
ref, quads, tris = forming_strains.read_blank(f, "blank", frame)
own_major, own_minor = forming_strains.element_strains(ref, group["coordinates"][:], quads, tris)
for name, own in (("major_strain_mid", own_major), ("minor_strain_mid", own_minor), ("flc_margin", margin)):
    field = group[name][:].reshape(-1)
    assert np.max(np.abs(field - own)) < 1e-12, (name, np.max(np.abs(field - own)))
assert np.array_equal(zone == 5, margin < 0.0), "cracks are not the elements above the curve"
assert np.all(np.abs(major - own_major) < 1e-12)  # the CSV read the fields
# Mid-surface strains against the thickness: plastic flow keeps the volume, so
# eps1 + eps2 + ln(t / t0) is the elastic volume strain, (1 - 2 nu) sigma_m / E < 0.5e-2 here
# (ln(t/t0) from the element's own thickness integration, the strains from the nodes).
thickness = group["thickness"][:, 0]
t0 = tomllib.load(open(sys.argv[4], "rb"))["blank"]["thickness"]
volume = major + minor + np.log(thickness / t0)
assert np.max(np.abs(volume)) < 5e-3, np.max(np.abs(volume))
print(f"{n} points, {above} above, worst {margin.max():.4g}, |volume strain| <= {np.max(np.abs(volume)):.2g}")
EOF
# Frame 0 is the undeformed blank (t = 0): zero strain to round-off (1e-14).
expect "plot_forming_limit.py --frame 0" 0 "frame 0 " -- "$py" "$src/scripts/plot_forming_limit.py" "$run" -o "$work/frame0" --frame 0 --csv
check "frame 0: zero strain" -- "$work/frame0/forming_limit.csv" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
worst = max(max(abs(float(r["major_true_strain"])), abs(float(r["minor_true_strain"]))) for r in rows)
assert worst < 1e-14, worst
print(f"|strain| <= {worst:.1e}")
EOF
# Without a curve: no margin columns.
mkdir -p "$work/no_flc"; cp "$run/results.h5" "$work/no_flc/"
grep -v '^forming_limit_curve' "$run/case.resolved.toml" > "$work/no_flc/case.resolved.toml"
expect "plot_forming_limit.py without a curve" 0 "no forming_limit_curve for material 'aluminium'" -- \
  "$py" "$src/scripts/plot_forming_limit.py" "$work/no_flc" --csv
[ "$(head -1 "$work/no_flc/forming_limit.csv")" = "element,cell_type,major_true_strain,minor_true_strain,formability_zone" ] \
  && pass "no margin columns without a curve" || fail "forming_limit.csv header: $(head -1 "$work/no_flc/forming_limit.csv")"
expect "plot_forming_limit.py: no such frame" 2 "results.h5: no frame 99: the file has frames 0 to [0-9]+" -- \
  "$py" "$src/scripts/plot_forming_limit.py" "$run" -o "$work/bad" --frame 99
expect "plot_forming_limit.py: missing results.h5" 2 "$work/empty/results.h5: no such file" -- \
  "$py" "$src/scripts/plot_forming_limit.py" "$work/empty"

echo "$passed passed, $failures failed"
[ "$failures" -eq 0 ]
