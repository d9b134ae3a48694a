#include "implicit/rigid_body_modes.hpp"

#include <fmt/core.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sf {

namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Row6 = Eigen::Matrix<double, 1, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

// Rigid motions are parametrised by q = (a, L w): the translation a (mm) and the rotation w (rad)
// times the body's radius L (mm), so that both halves of q are lengths. A nodal degree of freedom
// is a linear function of q, one row of the 6N x 6 rigid-mode matrix R; rotational degrees of
// freedom are measured times L too, so every row has a norm between 1 and sqrt(2).

/// A mode is free when G = R_h^T R_h holds it with an eigenvalue below this fraction of the
/// largest (or of 1, the eigenvalue one held translation gives its own direction).
constexpr double free_eigenvalue_tolerance = 1e-12;
/// A candidate hold removes a free mode only if its row keeps at least this squared norm in the
/// free space left (a translation 1e-3 L from a rotation axis, or an equivalent lever).
constexpr double hold_norm2_tolerance = 1e-6;
/// Candidates whose residual norms differ by less than this fraction count as tied.
constexpr double tie_tolerance = 1e-9;

/// The row of R for degree of freedom `dof` (0..5) of a node at offset r (mm) from the centroid.
Row6 mode_row(const Vec3& r, int dof, double length) {
  Row6 row = Row6::Zero();
  row(dof) = 1.0;
  if (dof < 3) {
    // (w x r)_dof = (-[r]x w)_dof, with w = (L w) / L.
    Mat3 skew;
    skew << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
    row.tail<3>() = -skew.row(dof) / length;
  }
  return row;
}

/// The row of R for degree of freedom `dof` of node `node` at offset r: along the node's own axis
/// where it has a frame (rows are linear in the direction).
Row6 node_row(const NodeFrames& frames, int node, const Vec3& r, int dof, double length) {
  if (!frames.has(node)) {
    return mode_row(r, dof, length);
  }
  const Vec3 axis = frames.axis(node, dof);
  const int first = dof < 3 ? 0 : 3;
  Row6 row = Row6::Zero();
  for (int c = 0; c < 3; ++c) {
    row += axis[c] * mode_row(r, first + c, length);
  }
  return row;
}

/// v with entries below `tiny` (absolute) set to 0, -0 included.
double clean(double v, double tiny) {
  return std::abs(v) <= tiny ? 0.0 : v;
}

std::string format_vector(const Vec3& v, double tiny) {
  return fmt::format("({:.6g}, {:.6g}, {:.6g})", clean(v.x(), tiny), clean(v.y(), tiny),
                     clean(v.z(), tiny));
}

/// A unit direction as "x", "y", "z" when it is one of the axes (either sense), else its
/// components with the largest one positive.
std::string direction_name(Vec3 u) {
  int k = 0;
  u.cwiseAbs().maxCoeff(&k);
  if (u[k] < 0) {
    u = -u;
  }
  const double tiny = 1e-9;
  if (std::abs(u[(k + 1) % 3]) <= tiny && std::abs(u[(k + 2) % 3]) <= tiny) {
    return std::string(1, static_cast<char>('x' + k));
  }
  return format_vector(u, tiny);
}

/// Describes the rigid motion q = (a, L w) about the centroid c: a translation when w = 0, else a
/// rotation about its axis (through the axis point where the axis's largest coordinate is 0),
/// with the advance along the axis when it is a screw.
std::string describe_mode(const Vec6& q, const Vec3& c, double length) {
  const Vec3 a = q.head<3>();
  const Vec3 w = q.tail<3>() / length;
  const double size = q.norm();
  if (length * w.norm() <= 1e-9 * size) {
    return "translation along " + direction_name(a.normalized());
  }
  Vec3 u = w.normalized();
  int k = 0;
  u.cwiseAbs().maxCoeff(&k);
  if (u[k] < 0) {
    u = -u;
  }
  // The points whose motion a + w x (x - c) is along w: c + w x a / |w|^2 + s u.
  const Vec3 on_axis = c + w.cross(a) / w.squaredNorm();
  const Vec3 point = on_axis - (on_axis[k] / u[k]) * u;
  const double tiny = 1e-9 * (length + c.norm());
  std::string text = "rotation about an axis along " + direction_name(u) + " through " +
                     format_vector(point, tiny) + " mm";
  const double advance = a.dot(w) / w.squaredNorm();  // mm per rad
  if (std::abs(a.dot(u)) > 1e-9 * size) {
    text += fmt::format(", advancing {:.6g} mm per rad along it", advance);
  }
  return text;
}

/// The rows of m (k x 6) brought to reduced row-echelon form (partial pivoting, columns in the
/// order given), entries below 1e-12 set to 0.
Eigen::MatrixXd reduced_row_echelon(Eigen::MatrixXd m) {
  const Eigen::Index rows = m.rows();
  Eigen::Index pivot_row = 0;
  for (Eigen::Index col = 0; col < m.cols() && pivot_row < rows; ++col) {
    Eigen::Index best = pivot_row;
    for (Eigen::Index r = pivot_row + 1; r < rows; ++r) {
      if (std::abs(m(r, col)) > std::abs(m(best, col))) {
        best = r;
      }
    }
    if (std::abs(m(best, col)) <= 1e-9) {
      m.col(col).tail(rows - pivot_row).setZero();  // round-off: the column is dependent
      continue;
    }
    m.row(best).swap(m.row(pivot_row));
    m.row(pivot_row) /= m(pivot_row, col);
    for (Eigen::Index r = 0; r < rows; ++r) {
      if (r != pivot_row) {
        m.row(r) -= m(r, col) * m.row(pivot_row);
      }
    }
    ++pivot_row;
  }
  return m.unaryExpr([](double v) { return clean(v, 1e-12); });
}

}  // namespace

RigidBodyModes find_free_rigid_body_modes(const Matrix3X& x, const std::vector<unsigned char>& held,
                                          const NodeFrames& frames) {
  const Eigen::Index nodes = x.cols();
  if (nodes == 0) {
    throw std::invalid_argument("find_free_rigid_body_modes: no nodes");
  }
  if (held.size() != static_cast<std::size_t>(nodes)) {
    throw std::invalid_argument(
        fmt::format("find_free_rigid_body_modes: {} masks for {} nodes", held.size(), nodes));
  }
  if (frames.node_count() != 0 && frames.node_count() != nodes) {
    throw std::invalid_argument(fmt::format(
        "find_free_rigid_body_modes: frames for {} nodes, {} nodes", frames.node_count(), nodes));
  }
  if (!x.allFinite()) {
    throw std::invalid_argument("find_free_rigid_body_modes: a coordinate is not finite");
  }
  const Vec3 centroid = x.rowwise().mean();
  double length = (x.colwise() - centroid).colwise().norm().maxCoeff();
  if (!(length > 1e-12 * std::max(1.0, centroid.norm()))) {
    length = 1.0;  // all nodes at one point: rotations measured in rad times 1 mm
  }

  Mat6 g = Mat6::Zero();
  for (Eigen::Index i = 0; i < nodes; ++i) {
    const unsigned mask = held[static_cast<std::size_t>(i)];
    for (int dof = 0; dof < 6; ++dof) {
      if (mask & (1u << dof)) {
        const Row6 row = node_row(frames, static_cast<int>(i), x.col(i) - centroid, dof, length);
        g.noalias() += row.transpose() * row;
      }
    }
  }
  // Eigenvalues ascending; the free space is spanned by the eigenvectors of the smallest ones.
  const Eigen::SelfAdjointEigenSolver<Mat6> eigen(g);
  const double largest = eigen.eigenvalues()(5);
  const double threshold = free_eigenvalue_tolerance * std::max(largest, 1.0);
  int free_count = 0;
  while (free_count < 6 && eigen.eigenvalues()(free_count) <= threshold) {
    ++free_count;
  }
  RigidBodyModes result;
  result.free_count = free_count;
  if (free_count == 0) {
    return result;
  }
  const Eigen::MatrixXd free_basis = eigen.eigenvectors().leftCols(free_count);  // 6 x k

  // A readable basis: the reduced row-echelon form of the free modes with the rotation columns
  // first, so that a rotation that is free about some point reads as a rotation about an axis
  // through that point (a pinned node, a hinge line) and a free translation as a translation.
  // Listed translations first.
  const Eigen::MatrixXd rotations_first =
      reduced_row_echelon((Eigen::MatrixXd(free_count, 6) << free_basis.bottomRows<3>().transpose(),
                           free_basis.topRows<3>().transpose())
                              .finished());
  std::vector<std::string> translations, rotations;
  for (Eigen::Index r = 0; r < rotations_first.rows(); ++r) {
    Vec6 q;
    q << rotations_first.row(r).tail<3>().transpose(), rotations_first.row(r).head<3>().transpose();
    std::string text = describe_mode(q, centroid, length);
    (text.starts_with("translation") ? translations : rotations).push_back(std::move(text));
  }
  result.free_modes = std::move(translations);
  result.free_modes.insert(result.free_modes.end(), rotations.begin(), rotations.end());

  // The extra holds: a greedy column-pivoted QR (modified Gram-Schmidt) over the free-space
  // components of the candidate rows. Each step takes the candidate with the largest component
  // left: the node farthest from the axes of the remaining free rotations, so the support is as
  // wide as the body allows. Translations first; rotations only for modes that no translation
  // holds (a single node, nodes on one line).
  std::vector<std::array<int, 2>> candidates;
  for (Eigen::Index i = 0; i < nodes; ++i) {
    for (int dof = 0; dof < 6; ++dof) {
      if (!(held[static_cast<std::size_t>(i)] & (1u << dof))) {
        candidates.push_back({static_cast<int>(i), dof});
      }
    }
  }
  Eigen::MatrixXd components(static_cast<Eigen::Index>(candidates.size()), free_count);
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const auto [node, dof] = candidates[c];
    components.row(static_cast<Eigen::Index>(c)) =
        node_row(frames, node, x.col(node) - centroid, dof, length) * free_basis;
  }
  // At least hold_norm2_tolerance, and far above the free test of the support with the holds
  // added, whose largest eigenvalue is at most largest + 12 (6 rows of squared norm <= 2).
  const double hold_threshold =
      std::max(hold_norm2_tolerance, 1e3 * free_eigenvalue_tolerance * (largest + 12.0));
  for (const bool translation_phase : {true, false}) {
    while (static_cast<int>(result.added.size()) < free_count) {
      const Eigen::VectorXd norm2 = components.rowwise().squaredNorm();
      double best_norm2 = 0.0;
      for (std::size_t c = 0; c < candidates.size(); ++c) {
        if ((candidates[c][1] < 3) == translation_phase) {
          best_norm2 = std::max(best_norm2, norm2(static_cast<Eigen::Index>(c)));
        }
      }
      if (best_norm2 <= hold_threshold) {
        break;
      }
      std::size_t best = 0;
      while ((candidates[best][1] < 3) != translation_phase ||
             norm2(static_cast<Eigen::Index>(best)) < (1.0 - tie_tolerance) * best_norm2) {
        ++best;
      }
      result.added.push_back(candidates[best]);
      const Eigen::RowVectorXd direction = components.row(static_cast<Eigen::Index>(best)) /
                                           std::sqrt(norm2(static_cast<Eigen::Index>(best)));
      components -= (components * direction.transpose()) * direction;
    }
  }
  if (static_cast<int>(result.added.size()) != free_count) {
    // Every free mode moves some unheld degree of freedom (else it would not be free), so this
    // cannot happen short of a bug.
    throw std::logic_error("find_free_rigid_body_modes: found holds for " +
                           std::to_string(result.added.size()) + " of " +
                           std::to_string(free_count) + " free modes");
  }
  return result;
}

}  // namespace sf
