#!/usr/bin/env pvpython
"""Check that ParaView reads a sheetform part's .xdmf as expected.

Run with ParaView's Python (no display needed):

    pvpython scripts/check_xdmf.py results/blank.xdmf --times 0.001 0.002 \
        --points 6 --cells 2 \
        --point-arrays displacement:3 velocity:3 --cell-arrays thickness:1 stress_mid:6

Opens the file with Xdmf3ReaderS (paraview.simple), then checks the time steps (count and
values), and at every time step the number of points and cells and the exact set of point and
cell arrays with their component counts. Exits 0 when everything matches; otherwise prints every
mismatch and exits 1 (2 for bad usage or a file that cannot be read).
"""
import argparse
import math
import os
import sys


def parse_arrays(specs):
    """['displacement:3', 'thickness'] -> {'displacement': 3, 'thickness': 1}"""
    arrays = {}
    for spec in specs:
        name, _, components = spec.partition(":")
        arrays[name] = int(components) if components else 1
    return arrays


def arrays_of(data):
    """{name: components} of a vtkDataSetAttributes."""
    return {
        data.GetArrayName(i): data.GetArray(i).GetNumberOfComponents()
        for i in range(data.GetNumberOfArrays())
    }


def first_leaf(dataset):
    """The dataset itself, or the first non-empty leaf of a composite dataset."""
    if not dataset.IsA("vtkCompositeDataSet"):
        return dataset
    iterator = dataset.NewIterator()
    iterator.InitTraversal()
    while not iterator.IsDoneWithTraversal():
        leaf = iterator.GetCurrentDataObject()
        if leaf is not None and leaf.GetNumberOfPoints() > 0:
            return leaf
        iterator.GoToNextItem()
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("xdmf", help="the part's .xdmf file")
    parser.add_argument("--times", type=float, nargs="*", default=[],
                        help="expected time step values, in order (their count is the number "
                             "of frames)")
    parser.add_argument("--points", type=int, required=True, help="expected number of points")
    parser.add_argument("--cells", type=int, required=True, help="expected number of cells")
    parser.add_argument("--point-arrays", nargs="*", default=[], metavar="NAME[:COMPONENTS]")
    parser.add_argument("--cell-arrays", nargs="*", default=[], metavar="NAME[:COMPONENTS]")
    parser.add_argument("--first-points", type=float, nargs="*", default=None, metavar="X Y Z",
                        help="expected coordinates of point 0 at each time step (3 values per "
                             "step): checks that every frame has its own geometry")
    args = parser.parse_args()

    if not os.path.isfile(args.xdmf):
        print(f"check_xdmf: no such file: {args.xdmf}", file=sys.stderr)
        return 2

    from paraview import simple  # imported late: slow, and only needed for a real file

    reader = simple.Xdmf3ReaderS(FileName=[os.path.abspath(args.xdmf)])
    reader.UpdatePipelineInformation()
    errors = []

    values = reader.TimestepValues
    if values is None:
        times = []
    elif isinstance(values, float):  # a single time step comes back as a float
        times = [values]
    else:
        times = list(values)
    if len(times) != len(args.times) or any(
            not math.isclose(a, e, rel_tol=1e-15, abs_tol=0.0) for a, e in zip(times, args.times)):
        errors.append(f"time steps {times}, expected {args.times}")

    if args.first_points is not None and len(args.first_points) != 3 * len(args.times):
        print("check_xdmf: --first-points needs 3 values per expected time", file=sys.stderr)
        return 2
    expected_points = parse_arrays(args.point_arrays)
    expected_cells = parse_arrays(args.cell_arrays)
    for step, time in enumerate(times if times else [None]):
        if time is None:
            reader.UpdatePipeline()
        else:
            reader.UpdatePipeline(time)
        dataset = first_leaf(simple.servermanager.Fetch(reader))
        where = f"at time {time}"
        if dataset is None:
            errors.append(f"{where}: no data read")
            continue
        if dataset.GetNumberOfPoints() != args.points:
            errors.append(f"{where}: {dataset.GetNumberOfPoints()} points, expected {args.points}")
        if dataset.GetNumberOfCells() != args.cells:
            errors.append(f"{where}: {dataset.GetNumberOfCells()} cells, expected {args.cells}")
        if args.first_points is not None and dataset.GetNumberOfPoints() > 0 and \
                step < len(args.times):
            expected = args.first_points[3 * step:3 * step + 3]
            actual = list(dataset.GetPoint(0))
            if any(not math.isclose(a, e, rel_tol=1e-12, abs_tol=1e-300)
                   for a, e in zip(actual, expected)):
                errors.append(f"{where}: point 0 at {actual}, expected {expected}")
        point_arrays = arrays_of(dataset.GetPointData())
        if point_arrays != expected_points:
            errors.append(f"{where}: point arrays {point_arrays}, expected {expected_points}")
        cell_arrays = arrays_of(dataset.GetCellData())
        if cell_arrays != expected_cells:
            errors.append(f"{where}: cell arrays {cell_arrays}, expected {expected_cells}")

    for error in errors:
        print(f"check_xdmf: {args.xdmf}: {error}", file=sys.stderr)
    if not errors:
        print(f"check_xdmf: {args.xdmf}: OK ({len(times)} time steps)")
    return 1 if errors else 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except SystemExit:
        raise
    except Exception as error:  # any failure inside ParaView must give a non-zero exit code
        print(f"check_xdmf: {type(error).__name__}: {error}", file=sys.stderr)
        sys.exit(2)
