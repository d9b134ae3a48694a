#include "model/drawbead_setup.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <variant>

#include "contact/round_drawbead.hpp"
#include "core/errors.hpp"
#include "mesh/nodal_area.hpp"
#include "mesh/triangle_distance.hpp"
#include "meshing/curve_loop.hpp"
#include "meshing/gmsh_reader.hpp"
#include "meshing/mesh_import.hpp"
#include "model/blank_parts.hpp"

namespace sf {
namespace {

std::string where(const CaseConfig& config, std::size_t b) {
  return fmt::format("{}: drawbeads[{}] ({})", config.file.string(), b, config.drawbeads[b].name);
}

// The nearest point of the surface to p and the normal of its triangle (the first on a tie).
struct SurfacePoint {
  Vec3 point;
  Vec3 normal;
  double distance = INFINITY;
};

SurfacePoint nearest_on_surface(const TriangleSurface& surface, const Vec3& p) {
  SurfacePoint best;
  for (int t = 0; t < surface.num_triangles(); ++t) {
    Tri3 tri;
    for (int k = 0; k < 3; ++k) {
      tri.col(k) = surface.nodes().col(surface.triangles()(k, t));
    }
    const Vec3 q = closest_point_on_triangle(p, tri);
    const double d = (q - p).norm();
    if (d < best.distance) {
      best = {q, surface.triangle_normals().col(t), d};
    }
  }
  return best;
}

// The line's points as given: the polyline, or the curves of its file meshed by gmsh (sandboxed)
// and joined into one open line. Errors name the case file and the key.
std::vector<Vec3> given_points(const CaseConfig& config, std::size_t b) {
  const DrawbeadConfig& bead = config.drawbeads[b];
  std::vector<Vec3> points;
  if (bead.line_file.empty()) {
    for (const auto& p : bead.line) {
      points.push_back(Vec3(p[0], p[1], p[2]));
    }
    return points;
  }
  const bool meshed = is_meshed(mesh_format(bead.line_file));
  MeshImportOptions import;
  import.group = bead.line_group;
  import.curves_only = true;
  import.curves = bead.line_curves;
  try {
    const GmshModel curves = load_gmsh_model(bead.line_file, meshed ? bead.line_element_size : 0.0,
                                             false, {}, import, mesh_limits(config.limits));
    return open_curve_points(curves, bead.line_group, 0.01 * bead.line_element_size);
  } catch (const InputError& error) {
    throw InputError(
        fmt::format("{}: drawbeads[{}].line_file: {}", config.file.string(), b, error.what()));
  }
}

// The line as the tool stands, cut into pieces no longer than a quarter of the width and laid on
// the tool's surface.
void lay_line(const CaseConfig& config, std::size_t b, const Tool& tool, const Vec3& shift,
              DrawbeadLine& line) {
  const DrawbeadConfig& bead = config.drawbeads[b];
  const double reach = 0.5 * bead.width;
  std::vector<Vec3> given = given_points(config, b);
  for (Vec3& p : given) {
    p += shift;
  }
  for (std::size_t k = 0; k < given.size(); ++k) {
    const Vec3& p = given[k];
    const Vec3& next = k + 1 < given.size() ? given[k + 1] : p;
    // (a length of whole pieces, give or take rounding, is not cut once more)
    const int pieces =
        std::max(1, static_cast<int>(std::ceil((next - p).norm() / (0.5 * reach) - 1e-9)));
    for (int j = 0; j < (k + 1 < given.size() ? pieces : 1); ++j) {
      const SurfacePoint on =
          nearest_on_surface(tool.surface, p + (double(j) / pieces) * (next - p));
      if (!(on.distance <= reach)) {
        const Vec3 g = given[k] - shift;
        const std::string what =
            j == 0 ? fmt::format("point {} ({:g}, {:g}, {:g})", k + 1, g.x(), g.y(), g.z())
                   : fmt::format("the line between points {} and {}", k + 1, k + 2);
        throw InputError(fmt::format(
            "{}: {} is {:.4g} mm from tool '{}' surface, more than half the bead's width "
            "({:g} mm): the bead line misses the tool (give its points on the tool's surface, "
            "where the tool is meshed)",
            where(config, b), what, on.distance, tool.name, reach));
      }
      // Two pieces' ends can land on one surface point (a concave corner): keep one.
      if (line.points.empty() || (on.point - line.points.back()).norm() > 1e-9 * reach) {
        line.points.push_back(on.point);
        line.normals.push_back(on.normal);
      }
    }
  }
}

// Drops the laid points where the line runs straight on a flat face (the point within 1e-9 of
// the width of the chord of its neighbours, its normal theirs within 1e-9): each segment costs
// every node near the line a distance per cycle, and a straight bead on a flat binder is one.
void drop_straight_points(DrawbeadLine& line) {
  std::vector<Vec3> points{line.points.front()};
  std::vector<Vec3> normals{line.normals.front()};
  const double tolerance = 1e-9 * line.width;
  for (std::size_t k = 1; k + 1 < line.points.size(); ++k) {
    const Vec3& a = points.back();
    const Vec3& b = line.points[k + 1];
    const Vec3 chord = (b - a).normalized();
    const Vec3 off = line.points[k] - a;
    const bool straight = (off - off.dot(chord) * chord).norm() <= tolerance &&
                          (line.normals[k] - normals.back()).norm() <= 1e-9 &&
                          (line.normals[k + 1] - normals.back()).norm() <= 1e-9;
    if (!straight) {
      points.push_back(line.points[k]);
      normals.push_back(line.normals[k]);
    }
  }
  points.push_back(line.points.back());
  normals.push_back(line.normals.back());
  line.points = std::move(points);
  line.normals = std::move(normals);
}

// The round bead's hardening curve (MPa against the equivalent plastic strain): the constant
// `flow_stress` given, or the blank material's.
std::function<double(double)> bead_flow_stress(const CaseConfig& config, std::size_t b,
                                               const Model& model) {
  const DrawbeadConfig& bead = config.drawbeads[b];
  if (bead.flow_stress > 0.0) {
    return [stress = bead.flow_stress](double) { return stress; };
  }
  const Material& law = model.blank.part.materials.front().law;
  if (std::holds_alternative<ElasticPlaneStress>(law) || model.blank.part.materials.size() > 1) {
    throw InputError(fmt::format(
        "{}: a round bead needs the sheet's flow_stress (MPa): the blank {}", where(config, b),
        model.blank.part.materials.size() > 1 ? "has several parts" : "is elastic"));
  }
  const Hardening hardening = std::visit(
      [](const auto& m) -> Hardening {
        if constexpr (requires { m.hardening; }) {
          return m.hardening;
        } else {
          return LinearHardening{};  // not reached: elastic refused above
        }
      },
      law);
  return [hardening](double eps) { return flow_stress(hardening, eps); };
}

// The force curves: the case's, or the round bead's force at its depth times the closure.
std::string set_force(const CaseConfig& config, std::size_t b, const Model& model,
                      const ContactInterface& contact, DrawbeadLine& line) {
  const DrawbeadConfig& bead = config.drawbeads[b];
  if (bead.force == DrawbeadConfig::Force::curve) {
    line.closure = bead.closure;
    line.restraining = bead.restraining_force;
    line.uplift = bead.uplift_force;
    line.height = bead.height;
    return "curve";
  }
  if (bead.thickness == 0.0 && config.blank_parts().size() > 1) {
    throw InputError(
        fmt::format("{}: a round bead on a blank of several parts needs the sheet's thickness (mm)",
                    where(config, b)));
  }
  if (bead.friction < 0.0 && contact.pair.friction.needs_pressure()) {
    throw InputError(fmt::format(
        "{}: a round bead takes one friction coefficient, and the contact with tool '{}' has a "
        "pressure-dependent one: give the bead's friction",
        where(config, b), bead.tool));
  }
  const double t = bead.thickness > 0.0 ? bead.thickness : config.blank.thickness;
  const RoundBeadGeometry geometry{.bead_radius = bead.bead_radius,
                                   .shoulder_radius = bead.shoulder_radius,
                                   .depth = bead.depth,
                                   .clearance = bead.clearance};
  const RoundBeadSheet sheet{
      .thickness = t,
      .flow_stress = bead_flow_stress(config, b, model),
      .friction = bead.friction >= 0.0 ? bead.friction : contact.pair.friction.dynamic_coefficient};
  const RoundBeadForces forces = round_bead_forces(geometry, sheet);
  line.closure = {0.0, 1.0};
  line.restraining = {0.0, forces.restraining};
  line.uplift = {0.0, forces.uplift};
  line.height = bead.height > 0.0 ? bead.height : bead.depth;
  return fmt::format(
      "round bead R_b {:g} mm, R_s {:g} mm, depth {:g} mm, wrap {:.1f} deg, t {:g} mm, {}, mu {:g}",
      bead.bead_radius, bead.shoulder_radius, bead.depth, forces.wrap_angle * 180.0 / M_PI, t,
      bead.flow_stress > 0.0 ? fmt::format("flow stress {:g} MPa", bead.flow_stress)
                             : std::string("the blank's hardening over the six bends"),
      sheet.friction);
}

}  // namespace

void set_up_drawbeads(const CaseConfig& config, Model& model) {
  if (config.drawbeads.empty()) {
    return;
  }
  const Blank& blank = model.blank;
  const VectorX area =
      nodal_tributary_area(blank.mesh.nodes, blank.mesh.quads, blank.mesh.triangles);
  const VectorX half_thickness = initial_half_thickness(blank, model.initial);
  for (std::size_t b = 0; b < config.drawbeads.size(); ++b) {
    const DrawbeadConfig& bead = config.drawbeads[b];
    DrawbeadInterface out;
    const auto tool = std::find_if(model.tools.begin(), model.tools.end(),
                                   [&](const Tool& t) { return t.name == bead.tool; });
    out.tool = static_cast<int>(tool - model.tools.begin());
    const auto contact =
        std::find_if(model.contacts.begin(), model.contacts.end(),
                     [&](const ContactInterface& c) { return c.tool == out.tool; });
    const ToolConfig& tc = *config.find_tool(bead.tool);
    const Vec3 direction =
        Vec3(tc.motion.direction[0], tc.motion.direction[1], tc.motion.direction[2]).normalized();
    DrawbeadLine& line = out.line;
    line.name = bead.name;
    line.width = bead.width;
    line.locking = bead.locking;
    lay_line(config, b, *tool, tool->touch_shift * direction, line);
    if (line.points.size() >= 2) {
      drop_straight_points(line);
    }
    if (line.points.size() < 2) {
      throw InputError(fmt::format("{}: the bead line lies on one point of tool '{}' surface",
                                   where(config, b), tool->name));
    }
    out.source = set_force(config, b, model, *contact, line);
    line.stiffness = kDrawbeadStiffnessRatio * contact->pair.stiffness;
    line.area = area;
    line.start_half_thickness = half_thickness;
    line.set_box(config.largest_blank_thickness());
    model.drawbeads.push_back(std::move(out));
  }
}

}  // namespace sf
