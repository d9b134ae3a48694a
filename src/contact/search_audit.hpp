#pragma once
// The search audit: while a contact pair runs a search that may pick a wrong triangle (the
// standard search), compare its answer with the exact closest triangle of the modified search and
// record, per blank node, where they differ and by how much the gap differs.
#include <memory>

#include "contact/contact_search.hpp"
#include "contact/tool_placement.hpp"
#include "contact/triangle_projection.hpp"
#include "core/types.hpp"
#include "mesh/triangle_surface.hpp"

namespace sf {

/// What one audit of all blank nodes found.
struct SearchAuditCount {
  int nodes_checked = 0;  ///< nodes with a tool triangle within the cutoff (exact search)
  int misses = 0;         ///< of those, nodes whose audited triangle is not an exact closest one
  double max_gap_error = 0.0;  ///< mm, largest |gap error| over the misses
};

/// Compares a search with the exact (modified) search over the same tool surface.
class SearchAudit {
 public:
  /// `surface` must outlive the audit.
  explicit SearchAudit(const TriangleSurface& surface);

  /// For every blank node i, queried at R^T (x_i - t) (the tool's mesh frame; R, t: `tool`'s
  /// rotation and translation, contact/tool_placement.hpp): when the
  /// exact search finds a triangle within `cutoff` (mm), the node is checked; it is a miss when the
  /// audited search's triangle (queried without a cutoff, so that its own choice is seen even when
  /// that choice lies beyond the cutoff) is not in the exact tie set and its distance exceeds the
  /// exact one beyond the tie tolerance. Writes miss[i] = 1 or 0 and
  /// gap_error[i] = audited signed distance - exact signed distance (mm; 0 where no miss; the
  /// audited search's error in the contact gap). Unchecked nodes get 0 and 0. No allocation.
  SearchAuditCount run(const ContactSearch& audited, const Matrix3X& x, const ToolPlacement& tool,
                       double cutoff, VectorX& miss, VectorX& gap_error) const;

 private:
  std::unique_ptr<ContactSearch> exact_;
  detail::TieTolerance tolerance_;
};

}  // namespace sf
