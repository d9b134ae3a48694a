#include "contact/search_audit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/triangle_projection.hpp"

namespace sf {

SearchAudit::SearchAudit(const TriangleSurface& surface)
    : exact_(make_contact_search("modified", surface)),
      tolerance_(detail::make_tie_tolerance(surface)) {}

SearchAuditCount SearchAudit::run(const ContactSearch& audited, const Matrix3X& x,
                                  const ToolPlacement& tool, double cutoff, VectorX& miss,
                                  VectorX& gap_error) const {
  SearchAuditCount count;
  const Eigen::Index n = x.cols();
  miss.setZero(n);
  gap_error.setZero(n);
  ClosestPoint exact;
  ClosestPoint chosen;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vec3 p = tool.rotation.transpose() * (x.col(i) - tool.translation);
    exact_->find_closest(p, cutoff, exact);
    if (exact.triangle < 0) {
      continue;
    }
    ++count.nodes_checked;
    audited.find_closest(p, std::numeric_limits<double>::infinity(), chosen);
    const int* set_begin = exact.set.data();
    const int* set_end = set_begin + exact.set_size;
    const bool in_set = std::find(set_begin, set_end, chosen.triangle) != set_end;
    const bool same_distance =
        chosen.triangle >= 0 && chosen.distance <= tolerance_.window(exact.distance);
    if (in_set || same_distance) {
      continue;
    }
    ++count.misses;
    miss[i] = 1.0;
    gap_error[i] = chosen.triangle >= 0 ? chosen.signed_distance - exact.signed_distance
                                        : std::numeric_limits<double>::infinity();
    count.max_gap_error = std::max(count.max_gap_error, std::abs(gap_error[i]));
  }
  return count;
}

}  // namespace sf
