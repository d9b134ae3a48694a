#!/usr/bin/env pvbatch
"""Renders a sheetform run's blank at a frame (the last by default): thinning, plastic strain and formability zone images.

Run with ParaView's batch Python, under a virtual display:

    xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" pvbatch scripts/render_results.py \
        RESULTS_DIR [-o OUT_DIR] [--size 1200 800] [--no-tools] [--camera-direction X Y Z] \
        [--frame N] [--prefix NAME_]

(`xvfb-run -a pvbatch ...` works too, but Xvfb's default server reset when a client
disconnects makes about one start in ten fail with "bad X server connection": -noreset avoids
it; see docs/post-processing.md.)

Opens RESULTS_DIR/blank.xdmf with Xdmf3ReaderS, goes to its last time step (or frame N, counted
from 0, negative from the end) and writes, in OUT_DIR (default RESULTS_DIR), two PNG images of the
requested size in pixels (width height), their names prefixed by --prefix:

- `thinning.png`: thinning in per cent, 100 (1 - t / t0), from the cell array `thickness` (mm)
  with a Calculator; t0 is the blank's initial thickness, `[blank] thickness` of
  RESULTS_DIR/case.resolved.toml (a blank of several parts: each element's part's, from
  `[[blank.parts]]` and the cell array `part`). Positive = thinner than the blank, negative =
  thickened.
- `plastic_strain.png`: the cell array `plastic_strain` (equivalent plastic strain, the mean
  through the thickness, -).
- `formability_zone.png`, when the blank has the cell array `formability_zone` (results of
  builds with the formability fields, docs/formability.md): each element coloured by its zone,
  safe green, insufficient stretching grey, wrinkling tendency purple, risk of cracks yellow,
  severe thinning orange, cracks red.

Each has a scalar bar titled with the quantity and its unit, a text with the case title, the
time (ms) and the stroke tool's travel (mm), a fixed isometric-style camera (from -x, -y, +z,
z up; --camera-direction changes it) fitted to the blank, a white background. The tools'
surfaces (`<tool>.xdmf` of each `[[tools]]` entry, when present) are drawn in translucent grey
at the same time, unless --no-tools.

Units: the case's, labelled for mm-s-tonne-N-MPa (the forming cases' system).
Exit codes: 0 done; 2 a missing folder, file or array (the message names it); 1 anything else.
"""
import argparse
import math
import os
import sys
import tomllib

# (cell array, scalar bar title, unit, image file)
IMAGES = [
    ("thinning", "Thinning", "(%)", "thinning.png"),
    ("plastic_strain", "Equivalent plastic strain, thickness mean", "(-)", "plastic_strain.png"),
]
# The formability zones (docs/formability.md): code, name, colour, drawn when the blank has the
# cell array formability_zone.
ZONE_IMAGE = ("formability_zone", "Formability zone", "", "formability_zone.png")
ZONES = [(0, "safe", [0.2, 0.65, 0.2]), (1, "insufficient stretching", [0.6, 0.6, 0.6]),
         (2, "wrinkling tendency", [0.5, 0.3, 0.75]), (3, "risk of cracks", [1.0, 0.85, 0.1]),
         (4, "severe thinning", [1.0, 0.5, 0.0]), (5, "cracks", [0.85, 0.1, 0.1])]
COLOR_MAP = "Turbo"  # a ParaView colour map preset
CAMERA_DIRECTION = [-1.0, -1.0, 1.3]  # from the blank's centre towards the camera; z is up


class InputProblem(Exception):
    """Bad input: a missing folder, file or array. The message names it."""


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results_dir", help="a sheetform results folder (holds blank.xdmf)")
    parser.add_argument("-o", "--out-dir", help="where the images go (default: RESULTS_DIR)")
    parser.add_argument("--size", type=int, nargs=2, default=[1200, 800],
                        metavar=("WIDTH", "HEIGHT"), help="image size in pixels (1200 800)")
    parser.add_argument("--no-tools", action="store_true", help="do not draw the tools")
    parser.add_argument("--camera-direction", type=float, nargs=3, default=CAMERA_DIRECTION,
                        metavar=("X", "Y", "Z"),
                        help="from the blank's centre towards the camera, z up (default "
                             f"{' '.join(map(str, CAMERA_DIRECTION))})")
    parser.add_argument("--frame", type=int, default=-1,
                        help="the output frame to show, from 0 (negative: from the end; default -1)")
    parser.add_argument("--prefix", default="", help="put before each image's file name")
    args = parser.parse_args()
    if args.size[0] < 16 or args.size[1] < 16:
        parser.error(f"--size {args.size[0]} {args.size[1]}: at least 16 x 16 pixels")
    return args


class Case:
    """What the images need from RESULTS_DIR/case.resolved.toml."""

    def __init__(self, results_dir):
        path = os.path.join(results_dir, "case.resolved.toml")
        if not os.path.isfile(path):
            raise InputProblem(f"{path}: no such file (it gives the blank's initial thickness)")
        with open(path, "rb") as f:
            case = tomllib.load(f)
        blank = case.get("blank", {})
        parts = blank.get("parts", [])
        thicknesses = [p.get("thickness") for p in parts] if parts else [blank.get("thickness")]
        for i, thickness in enumerate(thicknesses):
            if not isinstance(thickness, (int, float)) or not thickness > 0.0:
                key = f"blank.parts[{i}].thickness" if parts else "blank.thickness"
                raise InputProblem(f"{path}: {key} missing or not > 0 (got {thickness!r})")
        self.thicknesses = [float(t) for t in thicknesses]  # mm, initial, per part
        self.title = case.get("title", "")
        self.stroke_tool = case.get("control", {}).get("stroke_tool")
        # {tool name: unit motion direction, or None for a fixed tool}, in the case's order
        self.tools = {tool.get("name"): tool.get("motion", {}).get("direction")
                      for tool in case.get("tools", [])}


def initial_thickness_expression(thicknesses):
    """The initial thickness (mm) as a Calculator expression of the cell array `part` (the
    element's part, 0, 1, ...): the polynomial through (k, t_k), exact at the parts' indices and
    made of arithmetic alone, which every ParaView function parser takes. One part: the number."""
    if len(thicknesses) == 1:
        return repr(thicknesses[0])
    terms = []
    for k, t in enumerate(thicknesses):
        factors = [f"(part-{j})/({k - j})" for j in range(len(thicknesses)) if j != k]
        terms.append(f"{t!r}*" + "*".join(factors))
    return "(" + "+".join(terms) + ")"


def time_values(reader):
    values = reader.TimestepValues
    if values is None:
        return []
    if isinstance(values, float):  # a single time step comes back as a float
        return [values]
    return list(values)


def first_leaf(dataset):
    """The dataset itself, or the first leaf of a composite dataset (None if it has none)."""
    if not dataset.IsA("vtkCompositeDataSet"):
        return dataset
    iterator = dataset.NewIterator()
    iterator.InitTraversal()
    return None if iterator.IsDoneWithTraversal() else iterator.GetCurrentDataObject()


def travel_of(simple, reader, direction, time):
    """A tool's travel (mm) at `time`: the displacement of its point 0 (a rigid tool
    translates) along its unit motion direction; None when it cannot be read."""
    reader.UpdatePipeline(time)
    data = first_leaf(simple.servermanager.Fetch(reader))
    if data is None or data.GetNumberOfPoints() == 0:
        return None
    array = data.GetPointData().GetArray("displacement")
    if array is None:
        return None
    return sum(a * b for a, b in zip(array.GetTuple3(0), direction))


def open_blank(simple, blank_file, case):
    """The blank's reader, updated at its last time step, and its time values (s)."""
    reader = simple.Xdmf3ReaderS(FileName=[os.path.abspath(blank_file)])
    reader.UpdatePipelineInformation()
    times = time_values(reader)
    if not times:
        raise InputProblem(f"{blank_file}: no time steps (no output frame written)")
    reader.UpdatePipeline(times[-1])
    arrays = reader.CellData.keys()
    for name in ("thickness", "plastic_strain") + (("part",) if len(case.thicknesses) > 1 else ()):
        if name not in arrays:
            raise InputProblem(f"{blank_file}: no cell array '{name}' (cell arrays: "
                               f"{', '.join(arrays) or 'none'})")
    return reader, times


def annotation(simple, case, results_dir, times):
    """Title, time (ms) and the stroke tool's travel (mm) at the last frame."""
    text = f"t = {times[-1] * 1e3:.4f} ms"
    direction = case.tools.get(case.stroke_tool) if case.stroke_tool else None
    path = os.path.join(results_dir, f"{case.stroke_tool}.xdmf")
    if direction and os.path.isfile(path):
        reader = simple.Xdmf3ReaderS(FileName=[os.path.abspath(path)])
        travel = travel_of(simple, reader, direction, times[-1])
        simple.Delete(reader)
        if travel is not None:
            text += f", {case.stroke_tool} travel {travel:.3f} mm"
    text += f" (frame {len(times) - 1})"
    return f"{case.title}\n{text}" if case.title else text


def render(simple, view, args, case, blank, times, out_dir):
    """Shows the blank (and the tools) in `view` at the last time step and saves the images."""
    view.ViewSize = list(args.size)
    view.ViewTime = times[-1]
    view.OrientationAxesVisibility = 1
    view.OrientationAxesLabelColor = [0.0, 0.0, 0.0]
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]

    text = simple.Text(Text=annotation(simple, case, args.results_dir, times))
    text_display = simple.Show(text, view)
    text_display.Color = [0.0, 0.0, 0.0]
    text_display.FontSize = 14
    text_display.WindowLocation = "Upper Left Corner"
    text_display.Justification = "Left"

    if not args.no_tools:  # translucent grey, at the same time
        for name in case.tools:
            path = os.path.join(args.results_dir, f"{name}.xdmf")
            if os.path.isfile(path):
                display = simple.Show(simple.Xdmf3ReaderS(FileName=[os.path.abspath(path)]), view)
                display.ColorArrayName = ["POINTS", ""]  # solid colour
                display.AmbientColor = display.DiffuseColor = [0.6, 0.6, 0.6]
                display.Opacity = 0.25

    thinning = simple.Calculator(Input=blank)
    thinning.AttributeType = "Cell Data"
    thinning.ResultArrayName = "thinning"
    thinning.Function = f"100*(1-thickness/{initial_thickness_expression(case.thicknesses)})"
    display = simple.Show(thinning, view)
    display.SetRepresentationType("Surface With Edges")
    display.EdgeColor = [0.3, 0.3, 0.3]

    # Camera: a fixed direction, fitted to the blank's bounds (not the tools').
    thinning.UpdatePipeline(times[-1])
    bounds = thinning.GetDataInformation().GetBounds()
    centre = [(bounds[2 * i] + bounds[2 * i + 1]) / 2.0 for i in range(3)]
    norm = math.sqrt(sum(d * d for d in args.camera_direction))
    view.CameraFocalPoint = centre
    view.CameraPosition = [c + d / norm for c, d in zip(centre, args.camera_direction)]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera(*bounds)

    zones = "formability_zone" in blank.CellData.keys()
    for array, bar_title, unit, file_name in IMAGES + ([ZONE_IMAGE] if zones else []):
        simple.ColorBy(display, ("CELLS", array))
        lut = simple.GetColorTransferFunction(array)
        if array == "formability_zone":  # categories, one colour per zone
            lut.InterpretValuesAsCategories = 1
            lut.AnnotationsInitialized = 1
            lut.Annotations = [v for code, name, _ in ZONES for v in (str(code), name)]
            lut.IndexedColors = [c for _, _, colour in ZONES for c in colour]
        else:
            lut.ApplyPreset(COLOR_MAP, True)
            display.RescaleTransferFunctionToDataRange(False, True)
        bar = simple.GetScalarBar(lut, view)
        bar.Title = bar_title
        bar.ComponentTitle = unit
        bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
        bar.TitleFontSize = bar.LabelFontSize = 14
        bar.WindowLocation = "Lower Right Corner"
        bar.Orientation = "Vertical"
        bar.ScalarBarLength = 0.6
        bar.AutomaticLabelFormat = 0
        bar.LabelFormat = bar.RangeLabelFormat = "%-#.3g"
        display.SetScalarBarVisibility(view, True)
        path = os.path.join(out_dir, args.prefix + file_name)
        simple.SaveScreenshot(path, view, ImageResolution=list(args.size),
                              TransparentBackground=0)
        display.SetScalarBarVisibility(view, False)
        print(f"render_results: wrote {path} ({bar_title} {unit} at t = {times[-1] * 1e3:.4f} ms)")


def main():
    args = parse_args()
    if not os.path.isdir(args.results_dir):
        raise InputProblem(f"{args.results_dir}: no such folder")
    blank_file = os.path.join(args.results_dir, "blank.xdmf")
    if not os.path.isfile(blank_file):
        raise InputProblem(f"{blank_file}: no such file (not a sheetform results folder?)")
    case = Case(args.results_dir)
    out_dir = args.out_dir or args.results_dir
    os.makedirs(out_dir, exist_ok=True)

    from paraview import simple  # imported late: slow, and only needed once the input is fine

    simple._DisableFirstRenderCameraReset()
    blank, times = open_blank(simple, blank_file, case)
    if not -len(times) <= args.frame < len(times):
        raise InputProblem(f"{blank_file}: no frame {args.frame}: it has frames 0 to {len(times) - 1}")
    times = times[: args.frame % len(times) + 1]  # the frame shown is the last of these
    view = simple.CreateView("RenderView")
    try:
        render(simple, view, args, case, blank, times, out_dir)
    finally:
        # Destroy the view (and its OpenGL context) before Python exits: pvbatch leaving with a
        # live view after sys.exit() dies with "GLXBadContext" (exit code 1) under Xvfb.
        simple.Delete(view)
        del view
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except InputProblem as problem:
        print(f"render_results: {problem}", file=sys.stderr)
        sys.exit(2)
    except SystemExit:
        raise
    except Exception as error:  # any failure inside ParaView must give a non-zero exit code
        print(f"render_results: {type(error).__name__}: {error}", file=sys.stderr)
        sys.exit(1)
