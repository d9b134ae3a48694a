#pragma once
// The contact choices a case makes ([[contact]], --search): the search and the projection, each
// an enum with its one name table (core/choice.hpp).
#include <array>

#include "core/choice.hpp"

namespace sf {

/// The contact searches, by the names a case file gives them (make_contact_search).
enum class ContactSearchKind {
  standard,
  standard_brute_force,
  modified,
  modified_brute_force,
  cached,
};

/// How the gap and the normal of a node in contact are measured.
enum class ContactProjection {
  /// The search's closest point: gap = signed distance - h, normal = ClosestPoint::normal (the
  /// gradient of the signed distance, so the force is -grad of 1/2 k g^2).
  orthogonal,
  /// Wawrzyk & Kowalczyk's interpolated projection (InterpolatedProjector) onto the search's
  /// triangle: gap = D - h with D measured along the interpolated normal n(T), force along n(T).
  /// Not a gradient field in general.
  interpolated,
};

inline constexpr std::array<Choice<ContactSearchKind>, 5> kContactSearchNames{{
    {ContactSearchKind::standard, "standard",
     "the closest tool node, then only its triangles (Benson & Hallquist 1990): can pick a wrong "
     "triangle"},
    {ContactSearchKind::standard_brute_force, "standard_brute_force",
     "the standard search at the paper's literal cost, for cost studies"},
    {ContactSearchKind::modified, "modified",
     "the closest triangle over all triangles (Wawrzyk & Kowalczyk): exact"},
    {ContactSearchKind::modified_brute_force, "modified_brute_force",
     "the modified search at the paper's literal cost, for cost studies"},
    {ContactSearchKind::cached, "cached",
     "exactly the modified answer, from a per-node candidate cache, at less cost"},
}};

inline constexpr std::array<Choice<ContactProjection>, 2> kContactProjectionNames{{
    {ContactProjection::interpolated, "interpolated",
     "after the search, project the node along the normal interpolated from the averaged nodal "
     "normals (the paper's interpolated projection; a smooth contact normal)"},
    {ContactProjection::orthogonal, "orthogonal", "keep the closest point and its normal"},
}};

}  // namespace sf
