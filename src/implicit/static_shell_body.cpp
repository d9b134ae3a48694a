#include "implicit/static_shell_body.hpp"

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <variant>

#include "element/element_block.hpp"
#include "element/shell_directors.hpp"
#include "mesh/mean_edge_length.hpp"

namespace sf {

namespace {

// Young's modulus (MPa) and Poisson's ratio of the part's material, or their means over the
// elements for a part of several materials.
std::pair<double, double> mean_elastic_constants(const ShellPart& part) {
  if (part.materials.size() == 1) {
    const Material& law = part.materials.front().law;
    return {young_modulus(law), poisson_ratio(law)};
  }
  double young = 0.0;
  double poisson = 0.0;
  for (int e = 0; e < element_count(part); ++e) {
    young += young_modulus(material_of(part, e).law);
    poisson += poisson_ratio(material_of(part, e).law);
  }
  const double n = element_count(part);
  return {young / n, poisson / n};
}

}  // namespace

StaticShellBody::StaticShellBody(const ShellPart& part, const Matrix3X& x, const ShellState& state)
    : part_(part),
      x_(x),
      state_(state),
      x_trial_(3, x.cols()),
      node_corners_(build_node_corners(part, static_cast<int>(x.cols()))) {
  // The assumed strain's stabilisation must be continuous in the increment for Newton.
  part_.stabilization_unloading = StabilizationUnloading::as_loading;
  if (part_.hourglass_form == HourglassForm::viscous) {
    part_.hourglass_form = HourglassForm::stiffness;
    state_.hourglass.assign(
        static_cast<std::size_t>(kHourglassModes) * static_cast<std::size_t>(element_count(part_)),
        0.0);
  }
  // Mean edge length and mean thickness.
  if (element_count(part_) == 0) {
    throw std::invalid_argument("StaticShellBody: the part has no elements");
  }
  length_scale_ = mean_edge_length(x_, part_.quads, part_.triangles);
  const double t = std::accumulate(state_.thickness.begin(), state_.thickness.end(), 0.0) /
                   static_cast<double>(state_.thickness.size());
  const auto [young, poisson] = mean_elastic_constants(part_);
  membrane_stiffness_ = young * t;
  drilling_stiffness_ =
      kDrillingStiffnessFraction * young * t * t * t / (12.0 * (1.0 - poisson * poisson));
  update_normals();
}

void StaticShellBody::update_normals() {
  normal_.setZero(3, x_.cols());
  for (Eigen::Index e = 0; e < part_.quads.cols(); ++e) {
    const auto q = part_.quads.col(e);
    const Vec3 n = (x_.col(q(2)) - x_.col(q(0))).cross(x_.col(q(3)) - x_.col(q(1)));
    for (int a = 0; a < 4; ++a) {
      normal_.col(q(a)) += n;
    }
  }
  for (Eigen::Index e = 0; e < part_.triangles.cols(); ++e) {
    const auto q = part_.triangles.col(e);
    const Vec3 n = (x_.col(q(1)) - x_.col(q(0))).cross(x_.col(q(2)) - x_.col(q(0)));
    for (int a = 0; a < 3; ++a) {
      normal_.col(q(a)) += n;
    }
  }
  for (Eigen::Index i = 0; i < normal_.cols(); ++i) {
    const double length = normal_.col(i).norm();
    if (length > 0.0) {
      normal_.col(i) /= length;
    }
  }
}

ShellForceResult StaticShellBody::compute_forces(const Matrix3X& du, const Matrix3X& dtheta,
                                                 Matrix3X& f, Matrix3X& m, ShellState& trial,
                                                 bool small_strain) const {
  trial = state_;  // same sizes after the first call: no allocation
  if (small_strain) {
    centre_directors(dtheta, trial);
  }
  // The element takes its strain increments on x_end - du / 2.
  x_trial_ = x_ + (small_strain ? 0.5 : 1.0) * du;  // into the sized buffer: no allocation
  f.resize(3, x_.cols());
  m.resize(3, x_.cols());
  // One step of unit length: "velocities" du, dtheta over dt = 1; every node's corners summed
  // into f, m (the scratch and the lists are the body's: a Newton iteration allocates nothing).
  ShellForceResult r =
      run_element_pass(part_, ElementInputs{x_trial_, du, dtheta, 1.0, true}, trial, pass_);
  gather_corner_forces(node_corners_, pass_.corners, f, m);
  // Drilling springs about the committed normals, anchored at the increment's start: their work
  // over it, 1/2 k (n . dtheta)^2 per node, is part of the body's internal work (without it a
  // drilling rotation's work would be missing from the energy balance).
  for (Eigen::Index i = 0; i < x_.cols(); ++i) {
    const Vec3 n = normal_.col(i);
    const double drill = n.dot(dtheta.col(i));
    m.col(i) += (drilling_stiffness_ * drill) * n;
    r.internal_work += 0.5 * drilling_stiffness_ * drill * drill;
  }
  return r;
}

void StaticShellBody::centre_directors(const Matrix3X& dtheta, ShellState& trial) const {
  // A linear analysis evaluates the increment about the committed state (x - du/2 to x + du/2),
  // so that second-order terms cancel: the directors start turned back by half the rotation, at
  // every corner of every block (the triangles' too: until issue 34 only the quads' were, and a
  // triangle strip's energy balance at 10 N was -1.4e-4 instead of the quads' -3.7e-5).
  for (const ElementBlock& block : element_blocks(part_)) {
    for (int e = block.first; e < block.end(); ++e) {
      const int* nodes = block.element_nodes(e);
      for (int a = 0; a < block.nodes_per_element(); ++a) {
        double* d = trial.director.data() + 3 * (kDirectorNodes * e + a);
        const Vec3 turned = rotate_director(Vec3(d[0], d[1], d[2]), -0.5 * dtheta.col(nodes[a]));
        d[0] = turned(0);
        d[1] = turned(1);
        d[2] = turned(2);
      }
    }
  }
}

void StaticShellBody::commit(const Matrix3X& du, const ShellState& trial) {
  x_ += du;
  state_ = trial;
  update_normals();
}

}  // namespace sf
