#pragma once
// The contact search interface: the closest feature of a rigid tool surface to a point.
#include <array>
#include <memory>
#include <string_view>

#include "contact/contact_choices.hpp"
#include "core/types.hpp"
#include "mesh/triangle_surface.hpp"

namespace sf {

/// The closest feature of a tool surface to a point (reference frame of the tool).
struct ClosestPoint {
  static constexpr int max_set_size = 8;
  enum class Feature { face, edge, vertex };

  int triangle = -1;  ///< one triangle holding the closest point (-1: nothing within the cutoff);
                      ///< the lowest index of the tie set, so the answer is deterministic
  Feature feature = Feature::face;  ///< where `point` lies on `triangle`: inside, on an edge or
                                    ///< at a vertex (barycentric coordinates within 1e-12 of 0)
  double distance = 0;              ///< unsigned distance D, mm
  double signed_distance = 0;  ///< D with the sign of the oriented surface normal (positive on the
                               ///< normal's side), mm
  Vec3 point = Vec3::Zero();   ///< closest point on the surface, mm
  /// Unit contact normal on the POSITIVE side of the oriented surface, i.e. the gradient of
  /// `signed_distance` with respect to the query point: the face normal for a face hit; for an
  /// edge or vertex hit (p - point) / D, negated if the point lies on the negative side
  /// (continuous across convex ridges). When D ~ 0 (below the tie tolerance) the normalised mean
  /// normal of the triangles in `set`.
  Vec3 normal = Vec3::UnitZ();
  /// (T1, T2, T3) of `point` in `triangle` as in the paper: point = x1 + T1 (x2 - x1) +
  /// T2 (x3 - x1), T3 = 1 - T1 - T2; i.e. the weights of nodes 2, 3 and 1 of the triangle.
  Vec3 barycentric = Vec3::Zero();
  /// All triangles whose distance equals the minimum within the tie tolerance (a shared edge or
  /// vertex), ascending; at most `max_set_size`: beyond that `set_truncated` is true.
  std::array<int, max_set_size> set{};
  int set_size = 0;
  bool set_truncated = false;
};

class ContactSearch;

/// Per-node state that a search keeps between cycles (the cached search's candidate lists). It
/// belongs to the caller (ContactState), not to the search, so that a search is immutable once
/// built and one search can serve several independent runs. Made by ContactSearch::make_cache.
class SearchCache {
 public:
  virtual ~SearchCache() = default;
  SearchCache(const SearchCache&) = delete;
  SearchCache& operator=(const SearchCache&) = delete;
  /// The search that made this cache (only that search may use it).
  const ContactSearch* owner() const { return owner_; }

 protected:
  explicit SearchCache(const ContactSearch& owner) : owner_(&owner) {}

 private:
  const ContactSearch* owner_;
};

/// Finds the closest point of a rigid triangle surface to a query point. Immutable once built.
class ContactSearch {
 public:
  virtual ~ContactSearch() = default;
  /// Finds the closest point of the surface to p (reference frame, mm) among features within
  /// `cutoff` (mm, may be +infinity); out.triangle = -1 if none. Does not allocate; thread-safe
  /// (const, no shared scratch).
  virtual void find_closest(const Vec3& p, double cutoff, ClosestPoint& out) const = 0;
  /// The per-node state of `node_count` blank nodes for `find_closest_for_node` (may allocate);
  /// nullptr for a search that keeps none (the default).
  virtual std::unique_ptr<SearchCache> make_cache(int node_count) const {
    (void)node_count;
    return nullptr;
  }
  /// The query of blank node `node` at p: the same answer as find_closest(p, cutoff, out).
  /// `cache` is what make_cache returned (0 <= node < its node count), or nullptr (then no state
  /// is used). Searches that keep per-node state between cycles (a candidate cache) override it;
  /// calls for different nodes may run concurrently, calls for one node may not. Does not
  /// allocate.
  virtual void find_closest_for_node(SearchCache* cache, int node, const Vec3& p, double cutoff,
                                     ClosestPoint& out) const {
    (void)cache;
    (void)node;
    find_closest(p, cutoff, out);
  }
  /// The name this search is chosen by (case file key).
  virtual std::string_view name() const = 0;
};

/// The search's name ("standard", ..., "cached"): the one name table, used both ways.
std::string_view contact_search_name(ContactSearchKind kind);
/// The search called `name`. Throws InputError for an unknown name, listing the accepted ones
/// (`where` starts the message, e.g. the tool).
ContactSearchKind parse_contact_search(std::string_view name, std::string_view where);

/// Options of the searches that have any (the others ignore them).
struct SearchOptions {
  /// "cached": how far (mm) a node may move from where its candidate list was built before the
  /// list is rebuilt; <= 0 chooses the default, a quarter of the mean tool edge length
  /// (CachedSearch).
  double cached_margin = 0;
  /// "cached": candidate triangles kept per node (beyond that the node falls back to the grid).
  int cached_capacity = 32;
};

/// Makes the search called `name` over `surface` (which must outlive it):
///  - "modified": the paper's search (closest triangle over all triangles), accelerated by a
///    uniform grid of triangle bounding boxes; exactly the brute-force answer;
///  - "modified_brute_force": the same, testing every triangle per query (the paper's cost);
///  - "standard": the standard search (Benson & Hallquist 1990): the triangles around the tool
///    node closest to the point; the node found with a grid. Can return a wrong triangle (the
///    paper's figure 1): kept for comparison;
///  - "standard_brute_force": the same, the closest node over every node (the paper's cost);
///  - "cached": the modified search's answer (bit-identical to "modified") from a per-node list of
///    candidate triangles, rebuilt when the node has moved more than `options.cached_margin`.
/// Throws InputError for an unknown name, listing the accepted ones.
std::unique_ptr<ContactSearch> make_contact_search(std::string_view name,
                                                   const TriangleSurface& surface,
                                                   const SearchOptions& options = {});
/// The same, by kind.
std::unique_ptr<ContactSearch> make_contact_search(ContactSearchKind kind,
                                                   const TriangleSurface& surface,
                                                   const SearchOptions& options = {});

}  // namespace sf
