#pragma once
// Exact (bit for bit) comparison of two search answers, field by field.
#include <gtest/gtest.h>

#include <algorithm>

#include "contact/contact_search.hpp"

namespace sf::test {

/// Success when every field of `a` and `b` is identical (doubles compared with ==); otherwise
/// names the first field that differs.
inline ::testing::AssertionResult identical(const ClosestPoint& a, const ClosestPoint& b) {
  auto fail = [&](const char* field) {
    return ::testing::AssertionFailure()
           << field << " differs: triangle " << a.triangle << " vs " << b.triangle << ", distance "
           << a.distance << " vs " << b.distance << ", set size " << a.set_size << " vs "
           << b.set_size;
  };
  if (a.triangle != b.triangle) {
    return fail("triangle");
  }
  if (a.set_size != b.set_size ||
      !std::equal(a.set.begin(), a.set.begin() + a.set_size, b.set.begin())) {
    return fail("set");
  }
  if (a.set_truncated != b.set_truncated) {
    return fail("set_truncated");
  }
  if (a.feature != b.feature) {
    return fail("feature");
  }
  if (!(a.distance == b.distance)) {
    return fail("distance");
  }
  if (!(a.signed_distance == b.signed_distance)) {
    return fail("signed_distance");
  }
  if (!(a.point == b.point)) {
    return fail("point");
  }
  if (!(a.normal == b.normal)) {
    return fail("normal");
  }
  if (!(a.barycentric == b.barycentric)) {
    return fail("barycentric");
  }
  return ::testing::AssertionSuccess();
}

}  // namespace sf::test
