"""In-plane principal true strains of a shell blank's mid-surface, per element.

Importable by the post-processing scripts and by the unit tests
(tests/post/test_forming_strains.py); needs numpy (an open h5py file for `read_blank`).

Strain measure. Each element's in-plane deformation gradient F (2 x 2) maps a local orthonormal
frame of the element in the reference configuration to one in the current configuration. The
right Cauchy-Green tensor C = F^T F has eigenvalues lambda1^2 >= lambda2^2 (the squared principal
in-plane stretches); the major and minor true (logarithmic) strains are

    eps1 = ln lambda1 = ln(lambda1^2) / 2,   eps2 = ln lambda2 = ln(lambda2^2) / 2.

The thickness strain does not enter: these are membrane strains of the mid-surface, from the node
coordinates only (the reference coordinates and a frame's coordinates in results.h5).

- Triangle: the map is affine, so F is exact and constant: F = Y X^-1, where the columns of X are
  the edges x1 - x0, x2 - x0 in the reference local frame and those of Y the same edges in the
  current local frame.
- Quadrilateral (bilinear, nodes at (xi, eta) = (-1,-1), (1,-1), (1,1), (-1,1)): F at the centre
  xi = eta = 0 from the tangents dx/dxi = (-x0 + x1 + x2 - x3) / 4 and
  dx/deta = (-x0 - x1 + x2 + x3) / 4 (reference: X, current: Y as above). A homogeneous
  deformation maps these tangents exactly, so F is exact for it even when the quadrilateral is
  not a parallelogram.

Each local frame is built from the two tangent vectors t1, t2: a1 = t1 / |t1|,
n = t1 x t2 / |t1 x t2|, a2 = n x a1. A rigid rotation and translation leave C unchanged.
Lengths are in the case's unit (mm); strains are dimensionless.
"""
import numpy as np


def _local_components(t1, t2):
    """The 2 x 2 matrices [[t1.a1, t2.a1], [t1.a2, t2.a2]] of tangent pairs (arrays [n][3]) in
    the local orthonormal frames a1 = t1/|t1|, a2 = n x a1 they define. Shape [n][2][2]."""
    a1 = t1 / np.linalg.norm(t1, axis=1)[:, None]
    n = np.cross(t1, t2)
    n /= np.linalg.norm(n, axis=1)[:, None]
    a2 = np.cross(n, a1)
    m = np.empty((t1.shape[0], 2, 2))
    m[:, 0, 0] = np.einsum("ij,ij->i", t1, a1)
    m[:, 0, 1] = np.einsum("ij,ij->i", t2, a1)
    m[:, 1, 0] = np.einsum("ij,ij->i", t1, a2)
    m[:, 1, 1] = np.einsum("ij,ij->i", t2, a2)
    return m


def _principal_log_strains(ref_t1, ref_t2, cur_t1, cur_t2):
    """(eps1, eps2) per element from the reference and current tangent pairs ([n][3] each)."""
    x = _local_components(ref_t1, ref_t2)
    y = _local_components(cur_t1, cur_t2)
    f = y @ np.linalg.inv(x)  # in-plane deformation gradient, [n][2][2]
    c = np.transpose(f, (0, 2, 1)) @ f  # right Cauchy-Green tensor
    # Eigenvalues of the symmetric 2 x 2 C: mean +- radius (Mohr's circle), no cancellation in
    # the radius even when the two are close.
    mean = 0.5 * (c[:, 0, 0] + c[:, 1, 1])
    radius = np.hypot(0.5 * (c[:, 0, 0] - c[:, 1, 1]), c[:, 0, 1])
    major = 0.5 * np.log(mean + radius)
    minor = 0.5 * np.log(mean - radius)
    return major, minor


def triangle_strains(reference, current, triangles):
    """Major and minor true strains of triangles.

    reference, current: node coordinates [n_nodes][3] (mm); triangles: node indices [n][3].
    Returns (major, minor), each [n].
    """
    reference = np.asarray(reference, dtype=float)
    current = np.asarray(current, dtype=float)
    t = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    return _principal_log_strains(reference[t[:, 1]] - reference[t[:, 0]],
                                  reference[t[:, 2]] - reference[t[:, 0]],
                                  current[t[:, 1]] - current[t[:, 0]],
                                  current[t[:, 2]] - current[t[:, 0]])


def _centre_tangents(x, q):
    """dx/dxi and dx/deta of bilinear quadrilaterals q ([n][4]) at their centre."""
    x0, x1, x2, x3 = (x[q[:, i]] for i in range(4))
    return 0.25 * (-x0 + x1 + x2 - x3), 0.25 * (-x0 - x1 + x2 + x3)


def quad_strains(reference, current, quads):
    """Major and minor true strains of quadrilaterals, at the element centre.

    reference, current: node coordinates [n_nodes][3] (mm); quads: node indices [n][4].
    Returns (major, minor), each [n].
    """
    reference = np.asarray(reference, dtype=float)
    current = np.asarray(current, dtype=float)
    q = np.asarray(quads, dtype=np.int64).reshape(-1, 4)
    ref_t1, ref_t2 = _centre_tangents(reference, q)
    cur_t1, cur_t2 = _centre_tangents(current, q)
    return _principal_log_strains(ref_t1, ref_t2, cur_t1, cur_t2)


def element_strains(reference, current, quads=None, triangles=None):
    """Major and minor true strains of every cell, in the results' cell order: the
    quadrilaterals first, then the triangles (either may be None or empty)."""
    majors, minors = [], []
    if quads is not None and len(quads) > 0:
        a, b = quad_strains(reference, current, quads)
        majors.append(a)
        minors.append(b)
    if triangles is not None and len(triangles) > 0:
        a, b = triangle_strains(reference, current, triangles)
        majors.append(a)
        minors.append(b)
    if not majors:
        return np.zeros(0), np.zeros(0)
    return np.concatenate(majors), np.concatenate(minors)


class ResultsError(Exception):
    """A results file lacks what is needed (the message names the file and the object)."""


def read_blank(h5file, part="blank", frame=None):
    """(reference [n][3], quads [nq][4] or None, triangles [nt][3] or None) of a part of an open
    results.h5 (h5py.File), following its `nodes_per_cell` attribute (4 quadrilaterals,
    3 triangles, 0 mixed: `connectivity` holds the quadrilaterals and `triangle_connectivity`
    the triangles, which follow them in the cell order). With `frame` (a frame group's key,
    "000012"), the mesh of that frame: after a trim, the trimmed mesh its attribute `topology`
    names (/parts/<part>/topologies/<m>). See docs/results-format.md."""
    path = f"parts/{part}"
    if path not in h5file:
        raise ResultsError(f"{h5file.filename}: /{path}: no such group")
    if frame is not None and f"{path}/frames/{frame}" in h5file:
        topology = h5file[f"{path}/frames/{frame}"].attrs.get("topology")
        if topology is not None:
            path = f"{path}/topologies/{int(topology)}"
    where = f"{h5file.filename}: /{path}"
    if path not in h5file:
        raise ResultsError(f"{where}: no such group")
    group = h5file[path]
    for name in ("reference_coordinates", "connectivity"):
        if name not in group:
            raise ResultsError(f"{where}/{name}: missing")
    if "nodes_per_cell" not in group.attrs:
        raise ResultsError(f"{where}: attribute nodes_per_cell missing")
    nodes_per_cell = int(group.attrs["nodes_per_cell"])
    reference = group["reference_coordinates"][:]
    connectivity = group["connectivity"][:]
    if nodes_per_cell == 4:
        return reference, connectivity, None
    if nodes_per_cell == 3:
        return reference, None, connectivity
    if nodes_per_cell == 0:
        if "triangle_connectivity" not in group:
            raise ResultsError(f"{where}/triangle_connectivity: missing (nodes_per_cell = 0)")
        return reference, connectivity, group["triangle_connectivity"][:]
    raise ResultsError(f"{where}: nodes_per_cell = {nodes_per_cell}, expected 4, 3 or 0")


def flc_major(minor, curve):
    """The forming limit curve's major strain at each minor strain.

    curve: [[minor, major], ...] true strains with minor strictly increasing; linear between its
    points and constant beyond its end points.
    """
    curve = np.asarray(curve, dtype=float)
    return np.interp(np.asarray(minor, dtype=float), curve[:, 0], curve[:, 1])


def flc_margin(minor, major, curve):
    """The forming limit curve's major strain at the same minor strain (`flc_major`) minus the
    major strain, as sheetform's `flc_margin` result field: positive = below the curve (the safe
    side, by that much major strain); negative = above it (beyond the limit)."""
    return flc_major(minor, curve) - np.asarray(major, dtype=float)
