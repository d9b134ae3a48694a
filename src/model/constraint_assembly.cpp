#include "model/constraint_assembly.hpp"

#include <fmt/core.h>

#include <cmath>
#include <numbers>
#include <string>

#include "core/dof_names.hpp"
#include "core/errors.hpp"

namespace sf {

namespace {

/// Two directions closer than this (the residual of one after removing the other, or the cosine
/// of their angle from 90 degrees) count as one direction, or as perpendicular.
constexpr double kSameDirection = 1e-6;
/// A direction whose cosine with a frame axis is above 1 - this lies along the axis (1.4e-6 rad).
constexpr double kAlongAxis = 1e-12;

/// Who holds or drives a direction: a [[boundary]] entry or one prescription.
struct Owner {
  std::string name;   // "boundary[2]", "prescribed_motion[0]"
  int line = 0;       // of its table in the case file; 0 = unknown
  std::string group;  // its node group
  std::string dof;    // a prescription's degree of freedom, e.g. "uz"; empty for a boundary
  Mat3 frame = Mat3::Identity();  // its axes
};

/// One held or prescribed direction at a node.
struct NodeDirection {
  Vec3 direction;
  int owner = 0;
  int prescription = -1;  // -1 = held, else an index into model.prescribed_motions
  int position = 0;       // the node's position in that prescription's node list
};

/// Where one prescription lands in a node's axes.
struct PrescribedComponent {
  int prescription = 0;
  int position = 0;
  int component = 0;  // 0..2 within the space
  double sign = 1.0;
};

/// The axes of one space (translations or rotations) of one node.
struct SpaceFrame {
  Mat3 axes = Mat3::Identity();
  bool global = true;
  unsigned held = 0;  // bits 0..2
  std::vector<PrescribedComponent> prescribed;
};

/// Everything assemble_constraints needs to name things in messages.
struct Context {
  const CaseConfig& config;
  const Blank& blank;
  std::vector<Owner> owners;

  std::string where(const Owner& o) const {
    return o.line > 0 ? fmt::format("{}:{}", config.file.string(), o.line) : config.file.string();
  }
  std::string describe(const Owner& o) const {
    return o.line > 0 ? fmt::format("{} (line {}, group '{}')", o.name, o.line, o.group)
                      : fmt::format("{} (group '{}')", o.name, o.group);
  }
  std::string node_name(int node) const {
    return fmt::format("node {} (gmsh {})", node,
                       blank.mesh.gmsh_node_tags[static_cast<std::size_t>(node)]);
  }
};

Vec3 to_vec(const std::array<double, 3>& v) {
  return Vec3(v[0], v[1], v[2]);
}

/// The held directions of a [[boundary]] entry in its frame, as (translations, rotations).
void add_boundary_directions(const BoundaryConfig& b, const Mat3& frame, std::vector<Vec3>& held_t,
                             std::vector<Vec3>& held_r) {
  using Type = BoundaryConfig::Type;
  const int normal = b.normal ? 0 : b.axis;  // the plane frame has the normal first
  switch (b.type) {
    case Type::fixed:
      for (int c = 0; c < 3; ++c) {
        held_t.push_back(frame.col(c));
        held_r.push_back(frame.col(c));
      }
      return;
    case Type::symmetry:
      held_t.push_back(frame.col(normal));
      for (int c = 0; c < 3; ++c) {
        if (c != normal) {
          held_r.push_back(frame.col(c));
        }
      }
      return;
    case Type::diaphragm:
      for (int c = 0; c < 3; ++c) {
        if (c != normal) {
          held_t.push_back(frame.col(c));
        }
      }
      return;
    case Type::hold:
      for (int c = 0; c < 6; ++c) {
        if (b.hold[static_cast<std::size_t>(c)]) {
          (c < 3 ? held_t : held_r).push_back(frame.col(c % 3));
        }
      }
      return;
  }
}

Mat3 boundary_frame(const BoundaryConfig& b) {
  if (b.normal) {
    return make_plane_frame(to_vec(*b.normal));
  }
  return b.axes ? make_frame(*b.axes) : Mat3::Identity();
}

LoadCurve make_curve(const CurveConfig& curve) {
  return LoadCurve(curve.times, curve.values);
}

/// model.prescribed_motions from [[prescribed_velocity]] (one per component) and
/// [[prescribed_motion]], with an owner each.
void make_prescriptions(Context& context, double end_time, Model& model) {
  const CaseConfig& config = context.config;
  for (std::size_t i = 0; i < config.prescribed_velocities.size(); ++i) {
    const PrescribedVelocityConfig& pv = config.prescribed_velocities[i];
    for (int c = 0; c < 3; ++c) {
      if (!pv.components[static_cast<std::size_t>(c)]) {
        continue;
      }
      PrescribedMotion p;
      p.kind = PrescribedMotion::Kind::velocity;
      p.entry = fmt::format("prescribed_velocity[{}]", i);
      p.group = pv.group;
      p.direction = Vec3::Unit(c);
      p.value = pv.velocity[static_cast<std::size_t>(c)];
      p.scale = pv.curve.times.empty() ? LoadCurve({0.0}, {1.0}) : make_curve(pv.curve);
      model.prescribed_motions.push_back(std::move(p));
      context.owners.push_back({model.prescribed_motions.back().entry, pv.line, pv.group,
                                std::string(1, static_cast<char>('x' + c)), Mat3::Identity()});
    }
  }
  for (std::size_t i = 0; i < config.prescribed_motions.size(); ++i) {
    const PrescribedMotionConfig& pc = config.prescribed_motions[i];
    const Mat3 frame = pc.axes ? make_frame(*pc.axes) : Mat3::Identity();
    PrescribedMotion p;
    p.kind = pc.type == PrescribedMotionConfig::Type::displacement
                 ? PrescribedMotion::Kind::displacement
                 : PrescribedMotion::Kind::velocity;
    p.entry = fmt::format("prescribed_motion[{}]", i);
    p.group = pc.group;
    p.rotation = pc.dof >= 3;
    p.direction = frame.col(pc.dof % 3);
    if (!pc.curve.times.empty()) {
      p.value = 1.0;
      p.scale = make_curve(pc.curve);
    } else {
      p.value = pc.value;
      // A displacement ramps from the initial state (a static analysis's convention, as its loads
      // do); a velocity is held.
      p.scale = p.kind == PrescribedMotion::Kind::displacement
                    ? LoadCurve({0.0, end_time}, {0.0, 1.0})
                    : LoadCurve({0.0}, {1.0});
    }
    model.prescribed_motions.push_back(std::move(p));
    context.owners.push_back(
        {model.prescribed_motions.back().entry, pc.line, pc.group, kDofNames[pc.dof], frame});
  }
}

const std::vector<int>& group_nodes(const Context& context, const Owner& owner) {
  const std::vector<int>& nodes = context.blank.group(owner.group).nodes;
  if (nodes.empty()) {
    throw InputError(fmt::format("{}: {}.group: group '{}' holds no node of the blank",
                                 context.where(owner), owner.name, owner.group));
  }
  return nodes;
}

/// A prescribed direction at a node meets a held or another prescribed one that is neither the
/// same nor perpendicular: the message names both entries.
[[noreturn]] void throw_conflict(const Context& context, int node, const NodeDirection& prescribed,
                                 const NodeDirection& other, double cosine) {
  const Owner& p = context.owners[static_cast<std::size_t>(prescribed.owner)];
  const Owner& o = context.owners[static_cast<std::size_t>(other.owner)];
  const bool held = other.prescription < 0;
  std::string why;
  if (cosine > 1.0 - kSameDirection) {
    why = held ? fmt::format("which {} holds: a degree of freedom is either held or prescribed",
                             context.describe(o))
               : fmt::format("which {} prescribes too", context.describe(o));
  } else {
    why = fmt::format(
        "at {:.3g} degrees to a direction {} {} there: at a node, a prescribed direction must be "
        "along or perpendicular to the others (give them common axes)",
        std::acos(std::min(1.0, cosine)) * 180.0 / std::numbers::pi, context.describe(o),
        held ? "holds" : "prescribes");
  }
  throw InputError(fmt::format("{}: {}: prescribes {} of {}, {}", context.where(p), p.name, p.dof,
                               context.node_name(node), why));
}

/// Checks that every prescribed direction is perpendicular to the held ones and to the other
/// prescribed ones; returns an orthonormal basis of the held directions' span.
std::vector<Vec3> check_directions(const Context& context, int node,
                                   const std::vector<NodeDirection>& directions) {
  std::vector<Vec3> basis;
  for (const NodeDirection& d : directions) {
    if (d.prescription >= 0) {
      continue;
    }
    Vec3 r = d.direction;
    for (const Vec3& q : basis) {
      r -= q.dot(r) * q;
    }
    if (r.norm() > kSameDirection) {
      basis.push_back(r.normalized());
    }
  }
  for (std::size_t a = 0; a < directions.size(); ++a) {
    const NodeDirection& p = directions[a];
    if (p.prescription < 0) {
      continue;
    }
    double in_held = 0.0;
    for (const Vec3& q : basis) {
      in_held += q.dot(p.direction) * q.dot(p.direction);
    }
    if (std::sqrt(in_held) > kSameDirection) {
      // Name the held entry whose direction is most aligned with it.
      const NodeDirection* worst = nullptr;
      for (const NodeDirection& h : directions) {
        if (h.prescription < 0 && (!worst || std::abs(h.direction.dot(p.direction)) >
                                                 std::abs(worst->direction.dot(p.direction)))) {
          worst = &h;
        }
      }
      throw_conflict(context, node, p, *worst, std::sqrt(in_held));
    }
    for (std::size_t b = 0; b < a; ++b) {
      const NodeDirection& q = directions[b];
      const double cosine = std::abs(q.direction.dot(p.direction));
      if (q.prescription >= 0 && cosine > kSameDirection) {
        throw_conflict(context, node, p, q, cosine);
      }
    }
  }
  return basis;
}

/// Whether `axes` fits the directions: each axis lies in the held directions' span or
/// perpendicular to it (so the span is that of some axes), and each prescribed direction lies
/// along an axis outside it; if so, `out` says which axes are held and which prescribed.
bool fits_frame(const Mat3& axes, const std::vector<Vec3>& held_basis,
                const std::vector<NodeDirection>& directions, SpaceFrame& out) {
  out = SpaceFrame{.axes = axes, .global = false, .held = 0, .prescribed = {}};
  int held_count = 0;
  for (int k = 0; k < 3; ++k) {
    double in_span = 0.0;
    for (const Vec3& q : held_basis) {
      in_span += q.dot(axes.col(k)) * q.dot(axes.col(k));
    }
    if (in_span > 1.0 - kAlongAxis) {
      out.held |= 1u << k;
      ++held_count;
    } else if (in_span > kAlongAxis) {
      return false;  // neither in the span nor perpendicular to it
    }
  }
  if (held_count != static_cast<int>(held_basis.size())) {
    return false;
  }
  for (const NodeDirection& d : directions) {
    if (d.prescription < 0) {
      continue;
    }
    int along = -1;
    double cosine = 0.0;
    for (int k = 0; k < 3 && along < 0; ++k) {
      cosine = axes.col(k).dot(d.direction);
      if (std::abs(cosine) > 1.0 - kAlongAxis) {
        along = k;
      }
    }
    if (along < 0) {
      return false;
    }
    out.prescribed.push_back({d.prescription, d.position, along, cosine > 0.0 ? 1.0 : -1.0});
  }
  return true;
}

/// A frame built from the directions: the held basis, then the prescribed directions (made
/// exactly perpendicular to it), then global axes to complete it, right-handed.
SpaceFrame build_frame(const std::vector<Vec3>& held_basis,
                       const std::vector<NodeDirection>& directions) {
  SpaceFrame out{.axes = Mat3::Zero(), .global = false, .held = 0, .prescribed = {}};
  int k = 0;
  const auto add = [&](Vec3 r) {
    for (int j = 0; j < k; ++j) {
      r -= out.axes.col(j).dot(r) * out.axes.col(j);
    }
    out.axes.col(k++) = r.normalized();
  };
  for (const Vec3& q : held_basis) {
    out.held |= 1u << k;
    add(q);
  }
  for (const NodeDirection& d : directions) {
    if (d.prescription >= 0) {
      out.prescribed.push_back({d.prescription, d.position, k, 1.0});
      add(d.direction);
    }
  }
  while (k < 3) {
    // The global axis with the largest part perpendicular to the axes so far.
    Vec3 best = Vec3::Zero();
    for (int c = 0; c < 3; ++c) {
      Vec3 r = Vec3::Unit(c);
      for (int j = 0; j < k; ++j) {
        r -= out.axes.col(j).dot(r) * out.axes.col(j);
      }
      if (r.norm() > best.norm() + 1e-12) {
        best = r;
      }
    }
    add(best);
  }
  if (out.axes.determinant() < 0.0) {
    out.axes.col(2) *= -1.0;
    for (PrescribedComponent& p : out.prescribed) {
      if (p.component == 2) {
        p.sign = -1.0;
      }
    }
  }
  return out;
}

/// The axes of one space of a node: the global ones, an entry's, or built from the directions.
SpaceFrame resolve_space(const Context& context, int node,
                         const std::vector<NodeDirection>& directions,
                         const std::vector<int>& owners_here) {
  const std::vector<Vec3> held_basis = check_directions(context, node, directions);
  SpaceFrame out;
  if (fits_frame(Mat3::Identity(), held_basis, directions, out)) {
    out.global = true;
    return out;
  }
  for (const int o : owners_here) {
    if (fits_frame(context.owners[static_cast<std::size_t>(o)].frame, held_basis, directions,
                   out)) {
      return out;
    }
  }
  return build_frame(held_basis, directions);
}

}  // namespace

std::string describe_boundary(const BoundaryConfig& b) {
  using Type = BoundaryConfig::Type;
  const auto vector = [](const std::array<double, 3>& v) {
    return fmt::format("({:.3g}, {:.3g}, {:.3g})", v[0], v[1], v[2]);
  };
  const std::string axes =
      b.axes ? fmt::format(" (axes x {}, y {})", vector(b.axes->x), vector(b.axes->y)) : "";
  const std::string normal =
      b.normal ? vector(*b.normal) : fmt::format("{}{}", "xyz"[b.axis], axes);
  switch (b.type) {
    case Type::fixed:
      return "fixed (all six degrees of freedom held)";
    case Type::symmetry:
      return fmt::format("symmetry plane normal to {}", normal);
    case Type::diaphragm:
      return fmt::format("diaphragm normal to {}: the two in-plane translations held", normal);
    case Type::hold: {
      std::string names;
      for (int k = 0; k < 6; ++k) {
        if (b.hold[static_cast<std::size_t>(k)]) {
          names += fmt::format("{}{}", names.empty() ? "" : ", ", kDofNames[k]);
        }
      }
      return fmt::format("{} held{}", names, axes);
    }
  }
  return "";
}

Mat3 make_plane_frame(const Vec3& normal) {
  const Vec3 n = normal.normalized();
  int least = 0;
  for (int c = 1; c < 3; ++c) {
    if (std::abs(n[c]) < std::abs(n[least])) {
      least = c;
    }
  }
  const Vec3 t1 = (Vec3::Unit(least) - n[least] * n).normalized();
  Mat3 frame;
  frame << n, t1, n.cross(t1);
  return frame;
}

Mat3 make_frame(const AxesConfig& axes) {
  const Vec3 x = to_vec(axes.x);
  const Vec3 y = to_vec(axes.y);
  Mat3 frame;
  frame << x, y, x.cross(y);
  return frame;
}

void assemble_constraints(const CaseConfig& config, const Blank& blank, double end_time,
                          Model& model) {
  const std::size_t n = static_cast<std::size_t>(blank.mesh.nodes.cols());
  NodalConstraints& constraints = model.constraints;
  constraints.mask.assign(n, 0);
  constraints.prescribed.assign(n, 0);
  constraints.frames = NodeFrames(static_cast<int>(n));
  model.prescribed_motions.clear();

  Context context{config, blank, {}};
  // Per node and space (0 translations, 1 rotations), the directions held or prescribed there.
  std::vector<std::vector<NodeDirection>> directions[2];
  directions[0].resize(n);
  directions[1].resize(n);
  std::vector<std::vector<int>> owners_at(n);
  const auto note_owner = [&](int node, int owner) {
    std::vector<int>& list = owners_at[static_cast<std::size_t>(node)];
    if (list.empty() || list.back() != owner) {
      list.push_back(owner);
    }
  };

  for (std::size_t i = 0; i < config.boundaries.size(); ++i) {
    const BoundaryConfig& b = config.boundaries[i];
    const Mat3 frame = boundary_frame(b);
    context.owners.push_back({fmt::format("boundary[{}]", i), b.line, b.group, "", frame});
    const int owner = static_cast<int>(context.owners.size()) - 1;
    std::vector<Vec3> held[2];
    add_boundary_directions(b, frame, held[0], held[1]);
    for (const int node : group_nodes(context, context.owners.back())) {
      for (int space = 0; space < 2; ++space) {
        for (const Vec3& d : held[space]) {
          directions[space][static_cast<std::size_t>(node)].push_back({d, owner, -1, 0});
        }
      }
      note_owner(node, owner);
    }
  }
  const int first_prescription_owner = static_cast<int>(context.owners.size());
  make_prescriptions(context, end_time, model);
  for (std::size_t p = 0; p < model.prescribed_motions.size(); ++p) {
    PrescribedMotion& motion = model.prescribed_motions[p];
    const int owner = first_prescription_owner + static_cast<int>(p);
    motion.nodes = group_nodes(context, context.owners[static_cast<std::size_t>(owner)]);
    motion.component.assign(motion.nodes.size(), 0);
    motion.sign.assign(motion.nodes.size(), 1.0);
    const int space = motion.rotation ? 1 : 0;
    for (std::size_t k = 0; k < motion.nodes.size(); ++k) {
      const int node = motion.nodes[k];
      directions[space][static_cast<std::size_t>(node)].push_back(
          {motion.direction, owner, static_cast<int>(p), static_cast<int>(k)});
      note_owner(node, owner);
    }
  }

  for (std::size_t i = 0; i < n; ++i) {
    if (owners_at[i].empty()) {
      continue;
    }
    const int node = static_cast<int>(i);
    NodeFrame frame;
    bool global = true;
    for (int space = 0; space < 2; ++space) {
      const SpaceFrame s = resolve_space(context, node, directions[space][i], owners_at[i]);
      global = global && s.global;
      (space == 0 ? frame.translation : frame.rotation) = s.axes;
      constraints.mask[i] |= static_cast<unsigned char>(s.held << (3 * space));
      for (const PrescribedComponent& c : s.prescribed) {
        PrescribedMotion& motion =
            model.prescribed_motions[static_cast<std::size_t>(c.prescription)];
        const int component = c.component + 3 * space;
        motion.component[static_cast<std::size_t>(c.position)] =
            static_cast<unsigned char>(component);
        motion.sign[static_cast<std::size_t>(c.position)] = c.sign;
        constraints.prescribed[i] |= static_cast<unsigned char>(1u << component);
      }
    }
    if (!global) {
      constraints.frames.set(node, frame);
    }
  }
}

}  // namespace sf
