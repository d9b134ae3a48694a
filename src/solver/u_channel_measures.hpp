#pragma once
// The NUMISHEET'93 U-channel (2-D draw bending) springback measures theta1, theta2 and rho, from a
// line of blank nodes along the channel. Definitions: docs/static-analysis.md.
#include <vector>

#include "casefile/case_config.hpp"
#include "core/types.hpp"

namespace sf {

struct UChannelMeasures {
  double theta1 = 0.0;  ///< deg, between the bottom and the side wall (90 before springback)
  double theta2 = 0.0;  ///< deg, between the side wall and the flange (90 before springback)
  double rho = 0.0;     ///< mm, radius of the side wall's curl; +infinity for a straight wall
  int bottom_nodes = 0;
  int wall_nodes = 0;
  int flange_nodes = 0;
};

/// The measures of the section `section_nodes` (blank node indices) at coordinates `current`
/// (mm), its bottom, wall and flange picked by the ranges of `config` on the formed coordinates
/// `formed` (mm). Throws InputError naming the region and its range when it holds fewer than the
/// nodes it needs.
UChannelMeasures measure_u_channel(const UChannelMeasureConfig& config,
                                   const std::vector<int>& section_nodes, const Matrix3X& formed,
                                   const Matrix3X& current);

}  // namespace sf
