#pragma once
// The modified contact search of Wawrzyk & Kowalczyk ("Modified contact search algorithm for
// sheet metal forming"): the contact triangle is the triangle CLOSEST to the point, found over
// the triangles (not only those around the closest node, as in the standard search of Benson &
// Hallquist 1990), so that it is right on meshes where the closest node is not a vertex of the
// triangle holding the projection.
#include <string_view>
#include <vector>

#include "contact/box_grid.hpp"
#include "contact/contact_search.hpp"
#include "contact/triangle_projection.hpp"

namespace sf {

/// "modified_brute_force": the paper's search at its literal cost, every triangle per query.
class ModifiedBruteForceSearch final : public ContactSearch {
 public:
  /// `surface` must outlive the search.
  explicit ModifiedBruteForceSearch(const TriangleSurface& surface);
  void find_closest(const Vec3& p, double cutoff, ClosestPoint& out) const override;
  std::string_view name() const override { return "modified_brute_force"; }

 private:
  const TriangleSurface& surface_;
  std::vector<detail::TriangleProjector> projectors_;
  detail::TieTolerance tol_;
};

/// "modified": the paper's search, visiting only the triangles that can be the closest.
///
/// A uniform grid over the surface's bounding box (detail::BoxGrid) holds, in each cell, every
/// triangle whose bounding box overlaps the cell (built once in the reference frame). A query
/// visits the cells in shells of growing Chebyshev distance around p's cell and stops when the
/// nearest cell of the next shell is farther than min(cutoff, best distance so far) plus the tie
/// tolerance; inside a shell it skips cells, and then triangles, whose bounding box is that far.
/// Exactness: the distance from p to a triangle is never less than the distance from p to any
/// box holding it, so every skipped triangle is farther than the bound, i.e. it can neither be the
/// closest triangle within the cutoff nor tie with it; the triangles that are tested are tested
/// by the same kernel as the brute force. Hence the same distance and the same tie set.
class ModifiedSearch final : public ContactSearch {
 public:
  /// `surface` must outlive the search.
  explicit ModifiedSearch(const TriangleSurface& surface);
  void find_closest(const Vec3& p, double cutoff, ClosestPoint& out) const override;
  std::string_view name() const override { return "modified"; }

  /// Grid dimensions and cell size (mm), for diagnostics.
  const Eigen::Vector3i& grid_cells() const { return grid_.cells(); }
  double cell_size() const { return grid_.cell_size(); }

  /// The pieces the cached search reuses: the surface, the per-triangle kernels, the tie
  /// tolerance and the grid of triangle bounding boxes (item i = triangle i).
  const TriangleSurface& surface() const { return surface_; }
  const std::vector<detail::TriangleProjector>& projectors() const { return projectors_; }
  const detail::TieTolerance& tolerance() const { return tol_; }
  const detail::BoxGrid& grid() const { return grid_; }

 private:
  const TriangleSurface& surface_;
  std::vector<detail::TriangleProjector> projectors_;
  detail::TieTolerance tol_;
  detail::BoxGrid grid_;
};

}  // namespace sf
