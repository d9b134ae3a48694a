#pragma once
// The standard node-to-segment contact search (Benson & Hallquist 1990, CMAME 78:141-163;
// Wriggers 2002, "Computational Contact Mechanics", ch. 4), as described by Wawrzyk & Kowalczyk:
// find the tool NODE closest to the point, then take the contact triangle among the triangles
// sharing that node. On meshes where the closest node is not a vertex of the triangle holding
// the projection (the paper's figure 1) it returns a wrong triangle: that is the algorithm, kept
// for comparison with the modified search and for the cost study of the paper's section 3.
#include <string_view>
#include <vector>

#include "contact/box_grid.hpp"
#include "contact/contact_search.hpp"
#include "contact/triangle_projection.hpp"

namespace sf {

/// What both standard searches share: the kernels of the triangles and the second step (the
/// closest of the triangles around a node).
class StandardSearchBase : public ContactSearch {
 public:
  /// `surface` must outlive the search.
  explicit StandardSearchBase(const TriangleSurface& surface);

  /// Squared distance (mm^2) from p to tool node `node`, the one formula both variants use (so
  /// that they rank the nodes identically, ties to the lowest index).
  double node_distance2(int node, const Vec3& p) const {
    return (surface_.nodes().col(node) - p).squaredNorm();
  }
  /// Whether `node` belongs to a triangle (only such nodes are candidates).
  bool has_triangles(int node) const {
    const auto& offsets = surface_.node_triangle_offsets();
    return offsets[node + 1] > offsets[node];
  }
  /// Longest tool edge, mm.
  double longest_edge() const { return longest_edge_; }

 protected:
  /// The second step: among the triangles sharing `node` (-1: none), the least distance within
  /// `cutoff` and its tie set, by the modified search's kernel (same fields and conventions:
  /// detail::TieSet::fill). out.triangle = -1 if none is within the cutoff.
  void closest_on_node_triangles(int node, const Vec3& p, double cutoff, ClosestPoint& out) const;

  const TriangleSurface& surface_;
  std::vector<detail::TriangleProjector> projectors_;
  detail::TieTolerance tol_;
  double longest_edge_ = 0;
};

/// "standard_brute_force": the closest node over every tool node (the paper's cost), then its
/// triangles.
class StandardBruteForceSearch final : public StandardSearchBase {
 public:
  using StandardSearchBase::StandardSearchBase;
  void find_closest(const Vec3& p, double cutoff, ClosestPoint& out) const override;
  std::string_view name() const override { return "standard_brute_force"; }
};

/// "standard": the same answer as "standard_brute_force", the closest node found with a uniform
/// grid over the tool nodes (detail::BoxGrid, nodes as zero-size boxes, cells about the mean edge
/// length).
///
/// Search radius: a point q of a triangle lies within the longest edge L of each vertex of that
/// triangle (q is a convex combination of the vertices, and a vertex's farthest point of the
/// triangle is another vertex). So if a triangle is within `cutoff` of p, one of its nodes is
/// within cutoff + L; conversely, if no node is within cutoff + L (plus the tie tolerance), every
/// triangle around the closest node is farther than the cutoff and the brute force returns
/// nothing too. The grid therefore looks for nodes only within that radius (no radius for an
/// infinite cutoff: then it grows its shells until the distance of the best node so far bounds
/// them). Ties between nodes go to the lowest index, as in the brute force.
class StandardSearch final : public StandardSearchBase {
 public:
  /// `surface` must outlive the search.
  explicit StandardSearch(const TriangleSurface& surface);
  void find_closest(const Vec3& p, double cutoff, ClosestPoint& out) const override;
  std::string_view name() const override { return "standard"; }

  /// The closest tool node to p among the nodes that belong to a triangle, lowest index among
  /// equals, looking no farther than `radius` (mm, may be +infinity); -1 if there is none.
  int closest_node(const Vec3& p, double radius) const;

  /// The node grid (item i = tool node grid_nodes()[i]), for diagnostics and operation counts.
  const detail::BoxGrid& grid() const { return grid_; }
  const std::vector<int>& grid_nodes() const { return grid_nodes_; }
  const std::vector<detail::TriangleProjector>& projectors() const { return projectors_; }
  const detail::TieTolerance& tolerance() const { return tol_; }

 private:
  std::vector<int> grid_nodes_;  ///< grid item -> tool node (ascending)
  detail::BoxGrid grid_;
};

}  // namespace sf
