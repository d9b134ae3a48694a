#include "solver/u_channel_measures.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "core/errors.hpp"

namespace sf {
namespace {

/// The x-z coordinates (mm) of blank node `node` in `coordinates`: x along the channel, z the
/// punch axis; y (across the width) plays no part in the measures.
Vec2 section_point(const Matrix3X& coordinates, int node) {
  return {coordinates(0, node), coordinates(2, node)};
}

/// Unit direction (either sense) of the least-squares line through `points` (mm): the principal
/// axis of their scatter, i.e. the line that minimises the sum of squared perpendicular
/// distances (orthogonal regression), so that the answer does not depend on the axes.
Vec2 fit_line_direction(const std::vector<Vec2>& points, const Vec2& centroid) {
  Mat2 scatter = Mat2::Zero();
  for (const Vec2& p : points) {
    const Vec2 d = p - centroid;
    scatter += d * d.transpose();
  }
  // Largest eigenvector of the symmetric 2x2 scatter matrix, in closed form.
  const double a = scatter(0, 0);
  const double b = scatter(0, 1);
  const double c = scatter(1, 1);
  const double angle = 0.5 * std::atan2(2.0 * b, a - c);
  return {std::cos(angle), std::sin(angle)};
}

Vec2 centroid_of(const std::vector<Vec2>& points) {
  Vec2 sum = Vec2::Zero();
  for (const Vec2& p : points) {
    sum += p;
  }
  return sum / static_cast<double>(points.size());
}

/// deg, the angle between two unit vectors, in [0, 180].
double angle_deg(const Vec2& u, const Vec2& v) {
  // atan2 of |cross| and dot: accurate near 0 and 180 deg too, where acos of the dot is not.
  const double sine = std::abs(u.x() * v.y() - u.y() * v.x());
  return std::atan2(sine, u.dot(v)) * 180.0 / std::numbers::pi;
}

/// mm, radius of the circle through p1, p2, p3 (abc / (4 area)); +infinity when they are
/// collinear to round-off.
double three_point_radius(const Vec2& p1, const Vec2& p2, const Vec2& p3) {
  const Vec2 a = p2 - p1;
  const Vec2 b = p3 - p1;
  const Vec2 c = p3 - p2;
  const double twice_area = std::abs(a.x() * b.y() - a.y() * b.x());
  if (twice_area <= 1e-14 * a.norm() * b.norm()) {
    return std::numeric_limits<double>::infinity();
  }
  return a.norm() * b.norm() * c.norm() / (2.0 * twice_area);
}

std::string format_range(const std::array<double, 2>& range) {
  return fmt::format("[{}, {}]", range[0], range[1]);
}

enum class Region { none, bottom, wall, flange };

/// "the bottom (x in [0, 29] mm on the formed shape)"
std::string describe(Region r, const UChannelMeasureConfig& config) {
  switch (r) {
    case Region::bottom:
      return fmt::format("the bottom (x in {} mm on the formed shape)",
                         format_range(config.bottom));
    case Region::wall:
      return fmt::format("the wall (z in {} mm on the formed shape)", format_range(config.wall));
    case Region::flange:
      return fmt::format("the flange (x in {} mm on the formed shape)",
                         format_range(config.flange));
    case Region::none:
      break;
  }
  return "no region";
}

bool in_range(double value, const std::array<double, 2>& range) {
  return value >= range[0] && value <= range[1];
}

}  // namespace

UChannelMeasures measure_u_channel(const UChannelMeasureConfig& config,
                                   const std::vector<int>& section_nodes, const Matrix3X& formed,
                                   const Matrix3X& current) {
  const std::string where = fmt::format("springback.u_channel (section '{}')", config.section);
  if (formed.cols() != current.cols()) {
    throw InputError(fmt::format("{}: {} formed but {} current node coordinates", where,
                                 formed.cols(), current.cols()));
  }

  // Pick the regions on the formed shape.
  std::vector<int> bottom;
  std::vector<int> wall;
  std::vector<int> flange;
  for (const int node : section_nodes) {
    if (node < 0 || node >= formed.cols()) {
      throw InputError(fmt::format("{}: node index {} out of range (the blank has {} nodes)", where,
                                   node, formed.cols()));
    }
    const double x = formed(0, node);
    const double z = formed(2, node);
    Region region = Region::none;
    const auto assign = [&](Region candidate) {
      if (region != Region::none) {
        throw InputError(fmt::format(
            "{}: node {} (formed x = {:.4g} mm, z = {:.4g} mm) is in both {} and {}: the ranges "
            "overlap on the formed shape",
            where, node, x, z, describe(region, config), describe(candidate, config)));
      }
      region = candidate;
    };
    if (in_range(x, config.bottom)) {
      assign(Region::bottom);
    }
    if (in_range(z, config.wall)) {
      assign(Region::wall);
    }
    if (in_range(x, config.flange)) {
      assign(Region::flange);
    }
    switch (region) {
      case Region::bottom:
        bottom.push_back(node);
        break;
      case Region::wall:
        wall.push_back(node);
        break;
      case Region::flange:
        flange.push_back(node);
        break;
      case Region::none:
        break;
    }
  }
  const auto require = [&](Region r, const std::vector<int>& nodes, std::size_t minimum) {
    if (nodes.size() < minimum) {
      throw InputError(
          fmt::format("{}: {} holds {} of the section's {} nodes; it needs at least {}", where,
                      describe(r, config), nodes.size(), section_nodes.size(), minimum));
    }
  };
  require(Region::bottom, bottom, 2);
  require(Region::wall, wall, 3);
  require(Region::flange, flange, 2);

  // Order the wall along the section by the formed z, starting at the end nearer the bottom.
  std::sort(wall.begin(), wall.end(), [&](int a, int b) { return formed(2, a) < formed(2, b); });
  std::vector<Vec2> bottom_formed;
  for (const int node : bottom) {
    bottom_formed.push_back(section_point(formed, node));
  }
  const Vec2 bottom_formed_centre = centroid_of(bottom_formed);
  if ((section_point(formed, wall.back()) - bottom_formed_centre).norm() <
      (section_point(formed, wall.front()) - bottom_formed_centre).norm()) {
    std::reverse(wall.begin(), wall.end());
  }

  // Measure on the current shape.
  std::vector<Vec2> bottom_points;
  for (const int node : bottom) {
    bottom_points.push_back(section_point(current, node));
  }
  std::vector<Vec2> flange_points;
  for (const int node : flange) {
    flange_points.push_back(section_point(current, node));
  }
  const Vec2 wall_first = section_point(current, wall.front());
  const Vec2 wall_middle = section_point(current, wall[(wall.size() - 1) / 2]);
  const Vec2 wall_last = section_point(current, wall.back());

  const Vec2 wall_chord = wall_last - wall_first;
  if (wall_chord.norm() == 0.0) {
    throw InputError(fmt::format("{}: the first and last nodes of {} coincide", where,
                                 describe(Region::wall, config)));
  }
  const Vec2 wall_up = wall_chord.normalized();  // from the bottom end towards the flange end

  const Vec2 bottom_centre = centroid_of(bottom_points);
  Vec2 bottom_back = fit_line_direction(bottom_points, bottom_centre);
  if (bottom_back.dot(bottom_centre - wall_first) < 0.0) {
    bottom_back = -bottom_back;  // from the bottom-wall corner back along the bottom
  }
  const Vec2 flange_centre = centroid_of(flange_points);
  Vec2 flange_out = fit_line_direction(flange_points, flange_centre);
  if (flange_out.dot(flange_centre - wall_last) < 0.0) {
    flange_out = -flange_out;  // from the wall-flange corner outwards along the flange
  }

  UChannelMeasures m;
  m.theta1 = angle_deg(bottom_back, wall_up);
  // The wall chord continued upwards past the corner against the flange going outwards: 90 deg
  // formed, smaller when the wall opens and the flange stays level (docs/springback-measures.md).
  m.theta2 = angle_deg(wall_up, flange_out);
  m.rho = three_point_radius(wall_first, wall_middle, wall_last);
  m.bottom_nodes = static_cast<int>(bottom.size());
  m.wall_nodes = static_cast<int>(wall.size());
  m.flange_nodes = static_cast<int>(flange.size());
  return m;
}

}  // namespace sf
