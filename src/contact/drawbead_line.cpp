#include "contact/drawbead_line.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "contact/tool_frame.hpp"
#include "mesh/nodal_area.hpp"

namespace sf {
namespace {

// Where a node stands relative to the line, in the tool's mesh frame.
struct LinePlace {
  bool on_line = false;  ///< beside the line, not beyond its ends
  Vec3 across;           ///< c, unit, across the line
  Vec3 normal;           ///< n, unit, the surface normal made normal to the line
  double s = 0.0;        ///< mm, the distance across the line
  double d = 0.0;        ///< mm, the distance along the normal
};

// The nearest point of the line to p (the first segment on a tie) and the frame there.
LinePlace place_on_line(const DrawbeadLine& line, const Vec3& p) {
  const std::size_t segments = line.points.size() - 1;
  double best = INFINITY;
  std::size_t best_k = 0;
  double best_u = 0.0;
  for (std::size_t k = 0; k < segments; ++k) {
    const Vec3 e = line.points[k + 1] - line.points[k];
    const double u = std::clamp((p - line.points[k]).dot(e) / e.squaredNorm(), 0.0, 1.0);
    const double d2 = (p - line.points[k] - u * e).squaredNorm();
    if (d2 < best) {
      best = d2;
      best_k = k;
      best_u = u;
    }
  }
  LinePlace place;
  const Vec3 e = line.points[best_k + 1] - line.points[best_k];
  const Vec3 t = e.normalized();
  const Vec3 q = line.points[best_k] + best_u * e;
  // Beyond an end of the line: off the bead.
  if ((best_k == 0 && best_u == 0.0 && (p - q).dot(t) < 0.0) ||
      (best_k + 1 == segments && best_u == 1.0 && (p - q).dot(t) > 0.0)) {
    return place;
  }
  Vec3 n = (1.0 - best_u) * line.normals[best_k] + best_u * line.normals[best_k + 1];
  n = (n - n.dot(t) * t).normalized();
  place.on_line = true;
  place.normal = n;
  place.across = n.cross(t);
  place.s = (p - q).dot(place.across);
  place.d = (p - q).dot(n);
  return place;
}

bool inside_box(const DrawbeadLine& line, const Vec3& p) {
  return (p.array() >= line.box_min.array()).all() && (p.array() <= line.box_max.array()).all();
}

// The bead's force on node i, added to f_contact and its reaction to the share.
void node_force(const DrawbeadLine& line, DrawbeadState& state, const ContactKinematics& kin,
                bool rotating, int i, DrawbeadShare& share, Matrix3X& f_contact) {
  const Vec3 p = node_in_tool_frame(kin, rotating, i);
  double& stored = state.restraint[i];
  const LinePlace place = inside_box(line, p) ? place_on_line(line, p) : LinePlace{};
  const double half_width = 0.5 * line.width;
  const double h = kin.half_thickness[i];
  const double closure =
      place.on_line ? std::clamp(1.0 - (std::abs(place.d) - h) / line.height, 0.0, 1.0) : 0.0;
  if (!(std::abs(place.s) < half_width) || !(closure > 0.0)) {
    if (stored != 0.0) {  // most nodes are far off every bead: no store for them
      stored = 0.0;
    }
    return;
  }
  const double window =
      (1.0 + std::cos(std::numbers::pi * place.s / half_width)) / line.width;   // 1/mm
  const double area = area_now(line.area[i], line.start_half_thickness[i], h);  // mm^2
  const double share_of_line = area * window;                                   // mm of line
  const Vec3 across = rotating ? Vec3(kin.tool_rotation * place.across) : place.across;
  const Vec3 normal = rotating ? Vec3(kin.tool_rotation * place.normal) : place.normal;
  // The node's step across the line relative to the tool's point at it.
  const double du =
      kin.dt > 0.0 ? (kin.dt * kin.v.col(i) - tool_step_at(kin, rotating, p)).dot(across) : 0.0;
  const double k = line.stiffness[i];
  const double trial = stored - k * du;
  double restraint = trial;
  if (!line.locking) {
    const double limit = line.restraining_at(closure) * share_of_line;
    if (std::abs(trial) > limit) {
      restraint = std::copysign(limit, trial);
      share.work.add(limit * (std::abs(trial) - limit) / k);
      ++share.sliding_nodes;
    }
  }
  stored = restraint;
  const double uplift = line.uplift_at(closure) * share_of_line;
  const Vec3 f = restraint * across + std::copysign(uplift, place.d) * normal;
  f_contact.col(i) += f;
  for (int c = 0; c < 3; ++c) {
    share.force_on_tool[c].add(-f[c]);
  }
  if (rotating) {
    const Vec3 moment = kin.x.col(i).cross(-f);
    for (int c = 0; c < 3; ++c) {
      share.moment_on_tool[c].add(moment[c]);
    }
  }
  ++share.nodes_in_bead;
}

// Blank nodes per unit of work the threads take.
constexpr int kBeadBlock = 512;

DrawbeadResult merge(std::vector<DrawbeadShare>& shares, int used) {
  DrawbeadShare& total = shares[0];
  for (int t = 1; t < used; ++t) {
    const DrawbeadShare& s = shares[static_cast<std::size_t>(t)];
    for (int c = 0; c < 3; ++c) {
      total.force_on_tool[c].merge(s.force_on_tool[c]);
      total.moment_on_tool[c].merge(s.moment_on_tool[c]);
    }
    total.work.merge(s.work);
    total.nodes_in_bead += s.nodes_in_bead;
    total.sliding_nodes += s.sliding_nodes;
  }
  DrawbeadResult r;
  for (int c = 0; c < 3; ++c) {
    r.force_on_tool[c] = total.force_on_tool[c].round();
    r.moment_on_tool[c] = total.moment_on_tool[c].round();
  }
  r.work = total.work.round();
  r.nodes_in_bead = total.nodes_in_bead;
  r.sliding_nodes = total.sliding_nodes;
  return r;
}

}  // namespace

void DrawbeadLine::set_box(double thickness) {
  box_min = Vec3::Constant(INFINITY);
  box_max = Vec3::Constant(-INFINITY);
  for (const Vec3& p : points) {
    box_min = box_min.cwiseMin(p);
    box_max = box_max.cwiseMax(p);
  }
  const double reach = 0.5 * width + height + thickness;
  box_min.array() -= reach;
  box_max.array() += reach;
}

double DrawbeadLine::curve_at(const std::vector<double>& values, double kappa) const {
  if (values.empty()) {
    return 0.0;
  }
  const auto upper = std::upper_bound(closure.begin(), closure.end(), kappa);
  if (upper == closure.begin()) {
    return values.front();
  }
  if (upper == closure.end()) {
    return values.back();
  }
  const auto k = static_cast<std::size_t>(upper - closure.begin());
  const double w = (kappa - closure[k - 1]) / (closure[k] - closure[k - 1]);
  return (1.0 - w) * values[k - 1] + w * values[k];
}

double DrawbeadLine::length() const {
  double sum = 0.0;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    sum += (points[k + 1] - points[k]).norm();
  }
  return sum;
}

void size_drawbead_state(DrawbeadState& state, int n) {
  if (state.restraint.size() != n) {
    state.restraint.setZero(n);
  }
}

DrawbeadResult compute_drawbead_forces(const DrawbeadLine& line, DrawbeadState& state,
                                       const ContactKinematics& kin, Matrix3X& f_contact) {
  const int n = static_cast<int>(kin.x.cols());
  size_drawbead_state(state, n);
  const bool subset = !kin.owned_nodes.empty() || !kin.ghost_nodes.empty();
  const std::span<const int> counted = subset ? kin.owned_nodes : std::span<const int>();
  const std::span<const int> ghosts = subset ? kin.ghost_nodes : std::span<const int>();
  const int n_counted = subset ? static_cast<int>(counted.size()) : n;
  const int n_ghosts = static_cast<int>(ghosts.size());
  const int counted_blocks = (n_counted + kBeadBlock - 1) / kBeadBlock;
  const int blocks = counted_blocks + (n_ghosts + kBeadBlock - 1) / kBeadBlock;
  const int threads = n_counted + n_ghosts >= 2 * kBeadBlock ? omp_get_max_threads() : 1;
  for (std::vector<DrawbeadShare>* shares : {&state.shares, &state.ghost_shares}) {
    if (shares->size() < static_cast<std::size_t>(threads)) {
      shares->resize(static_cast<std::size_t>(threads));
    }
  }
  const bool rotating = tool_turns(kin);
  int used = 1;
  // Each node writes only its own entries; the sums are exact, so the share-out cannot change a
  // bit of the result.
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    if (t == 0) {
      used = omp_get_num_threads();
    }
    DrawbeadShare& share = state.shares[static_cast<std::size_t>(t)];
    DrawbeadShare& ghost_share = state.ghost_shares[static_cast<std::size_t>(t)];
    share.reset();
    ghost_share.reset();
#pragma omp for schedule(static)
    for (int b = 0; b < blocks; ++b) {
      const bool is_ghost = b >= counted_blocks;
      const std::span<const int> list = is_ghost ? ghosts : counted;
      const int size = is_ghost ? n_ghosts : n_counted;
      const int begin = (is_ghost ? b - counted_blocks : b) * kBeadBlock;
      const int end = std::min(size, begin + kBeadBlock);
      for (int k = begin; k < end; ++k) {
        const int i = list.empty() ? k : list[static_cast<std::size_t>(k)];
        node_force(line, state, kin, rotating, i, is_ghost ? ghost_share : share, f_contact);
      }
    }
  }
  return merge(state.shares, used);
}

}  // namespace sf
