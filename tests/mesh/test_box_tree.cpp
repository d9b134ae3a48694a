// BoxTree against brute force on random boxes: every box within the bound is visited and none
// farther, and a shrinking bound finds the nearest box, for queries near and far.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>

#include "mesh/box_tree.hpp"

namespace sf {
namespace {

struct Boxes {
  std::vector<Vec3> lo, hi;
};

Boxes random_boxes(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> where(-50.0, 50.0), size(0.0, 3.0);
  Boxes b;
  for (int i = 0; i < n; ++i) {
    const Vec3 lo(where(rng), where(rng), where(rng) * 0.2);
    b.lo.push_back(lo);
    b.hi.push_back(lo + Vec3(size(rng), size(rng), size(rng)));
  }
  return b;
}

TEST(BoxTree, VisitsExactlyTheBoxesWithinTheBound) {
  std::mt19937 rng(7);
  for (const int n : {1, 3, 5, 17, 1000}) {
    const Boxes b = random_boxes(n, rng);
    const BoxTree tree(b.lo, b.hi);
    std::uniform_real_distribution<double> where(-80.0, 80.0);
    for (int q = 0; q < 50; ++q) {
      const Vec3 lo(where(rng), where(rng), where(rng));
      const Vec3 hi = lo + Vec3(1, 2, 0.5);
      const double bound = q % 5 == 0 ? std::numeric_limits<double>::infinity() : 0.2 * q;
      std::set<int> visited;
      tree.visit(lo, hi, bound, [&](int i) {
        visited.insert(i);
        return bound;
      });
      std::set<int> expected;
      for (int i = 0; i < n; ++i) {
        if (std::sqrt(box_distance2(lo, hi, b.lo[i], b.hi[i])) <= bound) {
          expected.insert(i);
        }
      }
      EXPECT_EQ(visited, expected) << "n " << n << ", query " << q;
    }
  }
}

TEST(BoxTree, ShrinkingBoundFindsTheNearest) {
  std::mt19937 rng(11);
  const Boxes b = random_boxes(2000, rng);
  const BoxTree tree(b.lo, b.hi);
  std::uniform_real_distribution<double> where(-500.0, 500.0);  // near and far
  for (int q = 0; q < 200; ++q) {
    const Vec3 p(where(rng), where(rng), where(rng));
    double best = std::numeric_limits<double>::infinity();
    int visits = 0;
    tree.visit(p, p, best, [&](int i) {
      ++visits;
      best = std::min(best, std::sqrt(box_distance2(p, p, b.lo[i], b.hi[i])));
      return best;
    });
    double expected = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < b.lo.size(); ++i) {
      expected = std::min(expected, std::sqrt(box_distance2(p, p, b.lo[i], b.hi[i])));
    }
    EXPECT_EQ(best, expected);
    EXPECT_LT(visits, 200);  // far fewer than the 2000 boxes
  }
}

TEST(BoxTree, NegativeBoundEndsTheVisit) {
  std::mt19937 rng(3);
  const Boxes b = random_boxes(100, rng);
  const BoxTree tree(b.lo, b.hi);
  int visits = 0;
  tree.visit(Vec3::Zero(), Vec3::Zero(), std::numeric_limits<double>::infinity(), [&](int) {
    ++visits;
    return -1.0;
  });
  EXPECT_EQ(visits, 1);
  tree.visit(Vec3::Zero(), Vec3::Zero(), -1.0, [&](int) {
    ++visits;
    return 0.0;
  });
  EXPECT_EQ(visits, 1);
  const BoxTree empty({}, {});
  empty.visit(Vec3::Zero(), Vec3::Zero(), 1.0, [&](int) {
    ++visits;
    return 1.0;
  });
  EXPECT_EQ(visits, 1);
}

}  // namespace
}  // namespace sf
