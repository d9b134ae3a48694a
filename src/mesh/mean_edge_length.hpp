#pragma once
// The mean length of a shell mesh's element edges: a length scale of the mesh (the static
// solver's moment scale, the thickness-to-element check of the physical ranges).
#include <Eigen/Core>

#include "core/types.hpp"

namespace sf {

/// Mean over every element's own edges (an edge two elements share counts twice), quads first,
/// then triangles, in element order; mm. 0 when there are no elements.
template <class Quads, class Triangles>
double mean_edge_length(const Matrix3X& x, const Quads& quads, const Triangles& triangles) {
  double sum = 0.0;
  long edges = 0;
  const auto add_edges = [&](const auto& elements) {
    const Eigen::Index corners = elements.rows();
    for (Eigen::Index e = 0; e < elements.cols(); ++e) {
      for (Eigen::Index i = 0; i < corners; ++i) {
        sum += (x.col(elements((i + 1) % corners, e)) - x.col(elements(i, e))).norm();
        ++edges;
      }
    }
  };
  add_edges(quads);
  add_edges(triangles);
  return edges > 0 ? sum / static_cast<double>(edges) : 0.0;
}

}  // namespace sf
