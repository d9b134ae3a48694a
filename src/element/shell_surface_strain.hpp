#pragma once
// Total strains of a shell's surfaces from its reference and current geometry, for the formed
// part's strain output (the dynain file's *INITIAL_STRAIN_SHELL, docs/process-chain.md). The
// shells keep stresses, not strains; the strains are measured from the shape: a surface point
// of a node is its mid-surface point moved half the thickness along the nodal normal, and the
// surface's deformation gradient at the element centre, with the normal stretched by t / t0,
// gives the logarithmic strain 1/2 ln(F F^T) in global components.
#include <span>

#include "core/types.hpp"

namespace sf {

/// Logarithmic strain, global tensor components (xx, yy, zz, xy, yz, xz), -.
using Strain6 = Eigen::Matrix<double, 6, 1>;

/// The averaged unit normal of every node (the normalised sum of the corner normals of the
/// elements sharing it: a quad's diagonals' cross product, a triangle's edges'), column per node.
Matrix3X nodal_unit_normals(const QuadConn& quads, const TriConn& triangles, const Matrix3X& x);

/// One element's corners: reference and current mid-surface points (mm) and unit normals, 3 or 4
/// of each, counter-clockwise about the normal.
struct ElementCorners {
  std::span<const Vec3> X, x;  ///< mm
  std::span<const Vec3> N, n;  ///< unit nodal normals
};

/// The strain of the element's surface at zeta (-1 bottom, 0 mid-surface, +1 top), for
/// reference and current thicknesses t0 and t (mm). Zero for a rigid motion; exact for a
/// homogeneous deformation of a flat element.
Strain6 surface_log_strain(const ElementCorners& corners, double zeta, double t0, double t);

/// The in-plane principal true strains of a surface, major >= minor (-).
struct PrincipalStrains {
  double major = 0.0;
  double minor = 0.0;
};

/// The principal strains in the surface's tangent plane at zeta (as surface_log_strain, whose
/// in-plane eigenvalues they are: the normal is a principal direction, stretched by t / t0):
/// half the logs of the eigenvalues of the surface's right Cauchy-Green tensor, from its
/// reference and current tangent metrics. No allocation.
PrincipalStrains surface_principal_strains(const ElementCorners& corners, double zeta, double t0,
                                           double t);

}  // namespace sf
