#include "solver/tool_mesh_report.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/log.hpp"
#include "model/blank_parts.hpp"
#include "solver/start_gaps.hpp"

namespace sf {
namespace {

/// Positions named per kind of finding; the count says how many there are in all.
constexpr std::size_t kListed = 3;

/// "(x, y, z)"; a coordinate below 1e-12 of the largest is round-off, printed as 0.
std::string at(const Vec3& p) {
  const double scale = p.cwiseAbs().maxCoeff();
  const auto c = [scale](double v) { return std::abs(v) <= 1e-12 * scale ? 0.0 : v; };
  return fmt::format("({:.4g}, {:.4g}, {:.4g})", c(p.x()), c(p.y()), c(p.z()));
}

std::string plural(std::size_t n, const char* one, const char* many) {
  return fmt::format("{} {}", n, n == 1 ? one : many);
}

/// "value unit at (x, y, z), ..." for the first kListed findings.
std::string list(const std::vector<ToolFinding>& findings, const std::string& format_value) {
  std::string text;
  for (std::size_t i = 0; i < std::min(kListed, findings.size()); ++i) {
    text += fmt::format("{}{} at {}", i == 0 ? "" : ", ",
                        fmt::format(fmt::runtime(format_value), findings[i].value),
                        at(findings[i].position));
  }
  return text + (findings.size() > kListed ? ", ..." : "");
}

std::string gaps_warning(const std::string& tool, const ToolDiagnosis& d, double thickness,
                         const std::string& unit) {
  return fmt::format(
      "tool '{}': {} beside another free edge of the tool without sharing its nodes (faces that "
      "are not joined): widest gap {:.4g} {} at {}, narrowest {:.4g} {} at {}; sew the faces or "
      "mesh them as one surface: a gap narrower than the blank's thickness ({:.4g} {}) catches "
      "its nodes, a wider one lets them through (docs/tool-diagnosis.md)\n",
      tool, plural(d.gaps.size(), "free edge runs", "free edges run"), d.gaps.front().value, unit,
      at(d.gaps.front().position), d.gaps.back().value, unit, at(d.gaps.back().position), thickness,
      unit);
}

std::string flipped_warning(const std::string& tool, const ToolDiagnosis& d) {
  return fmt::format(
      "tool '{}': the faces on the two sides of {} are oriented opposite ways (normals {}): one "
      "of them faces away from the blank, and contact pushes the blank through it; orient the "
      "faces alike in the CAD or mesh them as one surface (docs/tool-diagnosis.md)\n",
      tool, plural(d.flipped.size(), "gap edge", "gap edges"), list(d.flipped, "{:.4g} deg apart"));
}

std::string overlaps_warning(const std::string& tool, const ToolDiagnosis& d) {
  return fmt::format(
      "tool '{}': {} no node with (a face given twice, faces that overlap or cross), the planes "
      "{}; remove the duplicate or trim the faces (docs/tool-diagnosis.md)\n",
      tool,
      plural(d.overlaps.size(), "triangle lies on or crosses a triangle it shares",
             "triangles lie on or cross triangles they share"),
      list(d.overlaps, "{:.3g} deg apart"));
}

std::string slivers_warning(const std::string& tool, const ToolDiagnosis& d,
                            const std::string& unit) {
  return fmt::format(
      "tool '{}': {} of near-zero area (a height below {:g} % of the longest edge, or an area "
      "below {:g} of the median {:.4g} {}^2): {}; their normals are unreliable and enter the "
      "averaged nodal normals contact uses: re-mesh the tool (docs/tool-diagnosis.md)\n",
      tool, plural(d.slivers.size(), "triangle", "triangles"),
      100.0 * tool_check::kSliverHeightRatio, tool_check::kTinyAreaRatio, d.median_area, unit,
      list(d.slivers, "{:.3g} " + unit + "^2"));
}

std::string folds_warning(const std::string& tool, const ToolDiagnosis& d) {
  return fmt::format(
      "tool '{}': {} between triangles whose normals differ by more than {:g} deg (the surface "
      "folds back): {}; check the tool's geometry there (docs/tool-diagnosis.md)\n",
      tool, plural(d.folds.size(), "edge", "edges"), tool_check::kFoldDegrees,
      list(d.folds, "{:.4g} deg"));
}

std::string summary(const ToolMeshReport& r) {
  const ToolDiagnosis& d = r.diagnosis;
  if (d.clean()) {
    return fmt::format(
        "Tool mesh   '{}': {} triangles: no gaps, overlaps, near-zero-area triangles or folds\n",
        r.tool, r.triangles);
  }
  return fmt::format(
      "Tool mesh   '{}': {} triangles: {} gap edges ({} between faces oriented opposite ways), {} "
      "overlapping triangles, {} of near-zero area, {} folds (warnings)\n",
      r.tool, r.triangles, d.gaps.size(), d.flipped.size(), d.overlaps.size(), d.slivers.size(),
      d.folds.size());
}

/// "Surface     'die': open: 2 boundaries, 96 free edges (412.3 mm); 1 component; orientation
/// as read" (or the triangles orient_surface turned over).
std::string surface_line(const ToolMeshReport& r, const std::string& unit) {
  const SurfaceBoundary& b = r.diagnosis.boundary;
  const std::string shape =
      b.closed()
          ? "closed (no free edges)"
          : fmt::format("open: {}, {} ({:.4g} {} in all)",
                        plural(static_cast<std::size_t>(b.boundaries), "boundary", "boundaries"),
                        plural(static_cast<std::size_t>(b.free_edges), "free edge", "free edges"),
                        b.length, unit);
  const SurfaceOrientation& o = r.orientation;
  const std::string turned =
      o.made_consistent == 0 && o.turned_to_blank == 0
          ? "orientation as read"
          : fmt::format(
                "triangles turned over: {} to agree with their neighbours, {} with their "
                "component to face the blank",
                o.made_consistent, o.turned_to_blank);
  return fmt::format("Surface     '{}': {}; {}; {}\n", r.tool, shape,
                     plural(static_cast<std::size_t>(o.components), "component", "components"),
                     turned);
}

std::string clearance_line(const ToolMeshReport& r, double thickness, const std::string& unit) {
  // Below a millionth of the thickness is the round-off of a tool resting on the blank (as for
  // the penetration the run estimate reports).
  const double round_off = 1e-6 * thickness;
  if (r.clearance > round_off) {
    return fmt::format("Clearance   '{}' clears the blank by {:.4g} {} at {} on the tool\n", r.tool,
                       r.clearance, unit, at(r.approach.tool_point));
  }
  if (r.clearance >= -round_off) {
    return fmt::format("Clearance   '{}' touches the blank (0 {}) at {} on the tool\n", r.tool,
                       unit, at(r.approach.tool_point));
  }
  return fmt::format(
      "Clearance   '{}' is inside the blank's thickness at {} on the tool: {:.4g} {} from the "
      "mid-surface, less than half the thickness\n",
      r.tool, at(r.approach.tool_point), r.approach.distance, unit);
}

// The tool's closest approach to the blank where its motion places it at time 0 (a tool that
// starts turned: the blank taken into the tool's frame, the points brought back).
SurfaceApproach approach_at_start(const Tool& tool, const PartMesh& blank) {
  const ToolPlacement at_start = tool.motion.placement(0.0);
  if (!at_start.turned()) {
    return closest_approach(tool.surface, at_start.translation, blank.nodes, blank.quads,
                            blank.triangles);
  }
  const Matrix3X in_tool_frame =
      at_start.rotation.transpose() * (blank.nodes.colwise() - at_start.translation);
  SurfaceApproach approach =
      closest_approach(tool.surface, Vec3::Zero(), in_tool_frame, blank.quads, blank.triangles);
  approach.tool_point = at_start.apply(approach.tool_point);
  approach.shell_point = at_start.apply(approach.shell_point);
  return approach;
}

// A blank of several thicknesses: the least over its nodes of the distance to the tool less the
// node's half thickness, as node-on-surface contact sees it, through the tool's contact search
// (none within its reach: nullopt). The mid-surfaces' approach alone cannot tell which thickness
// faces the tool.
std::optional<double> nodal_clearance(const Model& model, std::size_t tool_index) {
  const auto contact = std::find_if(
      model.contacts.begin(), model.contacts.end(),
      [&](const ContactInterface& c) { return c.tool == static_cast<int>(tool_index); });
  if (contact == model.contacts.end()) {
    return std::nullopt;
  }
  std::optional<double> least;
  for (const double gap : start_gaps(model, *contact)) {
    if (!std::isnan(gap) && (!least || gap < *least)) {
      least = gap;
    }
  }
  return least;
}

}  // namespace

std::vector<ToolMeshReport> diagnose_tool_meshes(const Model& model) {
  std::vector<ToolMeshReport> reports;
  const double thickness = model.initial.thickness;
  const PartMesh& blank = model.blank.mesh;
  const VectorX half = initial_half_thickness(model.blank, model.initial);  // mm per node
  for (std::size_t t = 0; t < model.tools.size(); ++t) {
    const Tool& tool = model.tools[t];
    using Clock = std::chrono::steady_clock;
    const auto seconds_since = [](Clock::time_point t) {
      return std::chrono::duration<double>(Clock::now() - t).count();
    };
    auto start = Clock::now();
    ToolMeshReport r;
    r.tool = tool.name;
    r.triangles = tool.surface.num_triangles();
    r.diagnosis = diagnose_tool(tool.surface, thickness);
    r.orientation = tool.orientation;
    // Reading the mesh made its orientation consistent already (PartMesh::reoriented).
    r.orientation.made_consistent += tool.mesh.reoriented;
    r.check_seconds = seconds_since(start);
    start = Clock::now();
    r.approach = approach_at_start(tool, blank);
    r.clearance = r.approach.distance - 0.5 * thickness;
    if (!model.initial.element_thickness.empty()) {
      r.clearance = nodal_clearance(model, t).value_or(r.approach.distance - half.minCoeff());
    }
    r.clearance_seconds = seconds_since(start);
    reports.push_back(std::move(r));
  }
  return reports;
}

ToolMeshLines describe_tool_mesh(const ToolMeshReport& r, double thickness,
                                 const std::string& unit) {
  ToolMeshLines lines;
  lines.info.push_back(summary(r));
  if (r.triangles > 0) {
    lines.info.push_back(surface_line(r, unit));
    lines.info.push_back(clearance_line(r, thickness, unit));
  }
  const ToolDiagnosis& d = r.diagnosis;
  if (!d.gaps.empty()) {
    lines.warnings.push_back(gaps_warning(r.tool, d, thickness, unit));
  }
  if (!d.flipped.empty()) {
    lines.warnings.push_back(flipped_warning(r.tool, d));
  }
  if (!d.overlaps.empty()) {
    lines.warnings.push_back(overlaps_warning(r.tool, d));
  }
  if (!d.slivers.empty()) {
    lines.warnings.push_back(slivers_warning(r.tool, d, unit));
  }
  if (!d.folds.empty()) {
    lines.warnings.push_back(folds_warning(r.tool, d));
  }
  if (r.approach.distance > 0.0 && r.approach.facing < 0.0) {
    lines.warnings.push_back(fmt::format(
        "tool '{}' faces away from the blank where it comes closest, at {}: its normals point "
        "away from the blank there, and contact would push the blank through it; check the "
        "orientation of that face (docs/tool-diagnosis.md)\n",
        r.tool, at(r.approach.tool_point)));
  }
  return lines;
}

void report_tool_meshes(const CaseConfig& config, const Model& model) {
  const std::string unit = parse_unit_system(config.units).length;
  std::vector<std::string> warnings;
  for (const ToolMeshReport& r : diagnose_tool_meshes(model)) {
    const ToolMeshLines lines = describe_tool_mesh(r, model.initial.thickness, unit);
    for (const std::string& line : lines.info) {
      log_info("{}", line);
    }
    log_verbose("Tool mesh   '{}': checked in {:.0f} ms, clearance in {:.0f} ms\n", r.tool,
                1e3 * r.check_seconds, 1e3 * r.clearance_seconds);
    warnings.insert(warnings.end(), lines.warnings.begin(), lines.warnings.end());
  }
  for (const std::string& w : warnings) {
    log_warning("{}", w);
  }
}

}  // namespace sf
