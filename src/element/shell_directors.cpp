#include "element/shell_directors.hpp"

#include <string>

#include "core/errors.hpp"
#include "element/element_block.hpp"

namespace sf {

namespace {

// Twice the area times the unit normal of quad e / triangle k at x.
Vec3 quad_normal(const ShellPart& part, const Matrix3X& x, Eigen::Index e) {
  const auto q = part.quads.col(e);
  return (x.col(q(2)) - x.col(q(0))).cross(x.col(q(3)) - x.col(q(1)));
}
Vec3 triangle_normal(const ShellPart& part, const Matrix3X& x, Eigen::Index k) {
  const auto t = part.triangles.col(k);
  return (x.col(t(1)) - x.col(t(0))).cross(x.col(t(2)) - x.col(t(0)));
}

// A mean normal shorter than this fraction of the summed lengths: the elements' normals cancel.
constexpr double kCancelled = 1e-6;

}  // namespace

Matrix3X compute_nodal_normals(const ShellPart& part, const Matrix3X& x) {
  Matrix3X sum = Matrix3X::Zero(3, x.cols());
  VectorX weight = VectorX::Zero(x.cols());
  for (Eigen::Index e = 0; e < part.quads.cols(); ++e) {
    const Vec3 n = quad_normal(part, x, e);
    for (int a = 0; a < 4; ++a) {
      sum.col(part.quads(a, e)) += n;
      weight(part.quads(a, e)) += n.norm();
    }
  }
  for (Eigen::Index k = 0; k < part.triangles.cols(); ++k) {
    const Vec3 n = triangle_normal(part, x, k);
    for (int a = 0; a < 3; ++a) {
      sum.col(part.triangles(a, k)) += n;
      weight(part.triangles(a, k)) += n.norm();
    }
  }
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    const double length = sum.col(i).norm();
    if (length > kCancelled * weight(i)) {
      sum.col(i) /= length;
    } else {
      sum.col(i).setZero();
    }
  }
  return sum;
}

void initialize_directors(const ShellPart& part, const Matrix3X& x, ShellState& state) {
  const Matrix3X averaged = compute_nodal_normals(part, x);
  const double cos_fold = std::cos(kFoldAngle);
  auto set = [&](Eigen::Index element, int corner, int node, const Vec3& own) {
    const Vec3 mean = averaged.col(node);
    const bool smooth = mean.squaredNorm() > 0.0 && mean.dot(own) >= cos_fold;
    const Vec3 d = smooth ? mean : own;
    const std::size_t at = 3 * (kDirectorNodes * static_cast<std::size_t>(element) + corner);
    state.director[at] = d(0);
    state.director[at + 1] = d(1);
    state.director[at + 2] = d(2);
  };
  auto unit = [](const Vec3& n, Eigen::Index element) {
    const double length = n.norm();
    if (!(length > 0.0) || !std::isfinite(length)) {
      throw InputError("shell element " + std::to_string(element) +
                       ": collapsed or non-finite geometry (no normal)");
    }
    return Vec3(n / length);
  };
  for (const ElementBlock& block : element_blocks(part)) {
    const bool quads = block.shape == ElementShape::quad;
    for (int e = block.first; e < block.end(); ++e) {
      const Vec3 own = unit(
          quads ? quad_normal(part, x, block.local(e)) : triangle_normal(part, x, block.local(e)),
          e);
      const int* nodes = block.element_nodes(e);
      for (int a = 0; a < block.nodes_per_element(); ++a) {
        set(e, a, nodes[a], own);
      }
    }
  }
}

}  // namespace sf
