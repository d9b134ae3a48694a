// The distance bounds of the penalty contact: ToolDistanceBound never exceeds the distance to the
// tool (against the brute-force oracle) and is exact within its reach; skipping the nodes that
// the bounds prove beyond the cutoff changes nothing, bit for bit, over a moving sequence on a
// curved tool (nodes approaching, touching and leaving it, the tool moving), with friction and
// the interpolated projection, for the cached and the modified search.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <random>

#include "allocation_counter.hpp"
#include "brute_force_oracle.hpp"
#include "contact/cached_search.hpp"
#include "contact/penalty_contact.hpp"
#include "contact/tool_distance_bound.hpp"
#include "test_meshes.hpp"

namespace sf {
namespace {

/// A curved tool: the bowl z = 0.05 (x^2 + y^2) over [-4, 4]^2, 16 x 16 cells, normals up.
TriangleSurface make_bowl() {
  return test::make_height_field("bowl", 16, 16, -4, 4, -4, 4,
                                 [](double x, double y) { return 0.05 * (x * x + y * y); });
}

TEST(ToolDistanceBound, NeverAboveTheDistanceAndExactWithinReach) {
  const TriangleSurface s = make_bowl();
  const ToolDistanceBound bound(s);
  const double reach = 1.5;
  const auto points = test::random_points(3000, Vec3(-7, -7, -3), Vec3(7, 7, 8), 3);
  int within = 0, beyond = 0;
  for (const Vec3& p : points) {
    const double d = oracle::closest(s.nodes(), s.triangles(), p, 0.0).distance;
    const double lower = bound.lower_bound(p, reach);
    EXPECT_LE(lower, d + 1e-12) << p.transpose();
    if (d < reach) {
      EXPECT_NEAR(lower, d, 1e-12) << p.transpose();
      ++within;
    } else {
      EXPECT_GE(lower, reach) << p.transpose();
      ++beyond;
    }
  }
  EXPECT_GT(within, 200);
  EXPECT_GT(beyond, 200);
}

/// A contact pair over `s` with its state; `bounded`: with the distance bounds.
struct Contact {
  ContactPair pair;
  ContactState state;
};

Contact make_contact(const TriangleSurface& s, const char* search, bool bounded, int n) {
  Contact c;
  c.pair.surface = &s;
  c.pair.search = make_contact_search(search, s);
  c.pair.stiffness = VectorX::LinSpaced(n, 80.0, 120.0);  // N/mm
  c.pair.cutoff = 0.8;                                    // mm
  c.pair.projection = ContactProjection::interpolated;
  c.pair.projector = std::make_unique<InterpolatedProjector>(s);
  c.pair.friction.static_coefficient = 0.3;
  c.pair.friction.dynamic_coefficient = 0.2;
  c.pair.friction.decay = 0.01;  // s/mm
  if (bounded) {
    c.pair.distance_bound = std::make_unique<ToolDistanceBound>(s);
  }
  return c;
}

bool same_bits(const Matrix3X& a, const Matrix3X& b) {
  return a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

bool same_result(const ContactResult& a, const ContactResult& b) {
  return std::memcmp(a.force_on_tool.data(), b.force_on_tool.data(), 3 * sizeof(double)) == 0 &&
         a.nodes_in_contact == b.nodes_in_contact && a.energy == b.energy &&
         a.friction_work == b.friction_work && a.sliding_nodes == b.sliding_nodes &&
         a.sticking_nodes == b.sticking_nodes && a.projection_fallbacks == b.projection_fallbacks;
}

TEST(DistanceBound, SkippingGivesTheSameForcesAsSearchingEveryNode) {
  // 13 x 13 nodes over [-6, 6]^2 (some beyond the tool's edge) at z = 3.2 mm, h = 0.4 mm,
  // wandering 4e-3 mm per step in random directions; the bowl rises 3.6 mm in 180 steps while
  // sliding along x, then falls back: nodes approach, touch, penetrate, slide and leave.
  const TriangleSurface s = make_bowl();
  const int side = 13, n = side * side, steps = 360;
  Matrix3X x(3, n);
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      x.col(j * side + i) = Vec3(-6.0 + i, -6.0 + j, 3.2);
    }
  }
  const VectorX h = VectorX::Constant(n, 0.4);
  const double dt = 1e-3;  // s
  Contact reference = make_contact(s, "cached", false, n);
  Contact skipping = make_contact(s, "cached", true, n);
  Contact skipping_modified = make_contact(s, "modified", true, n);
  std::mt19937 rng(11);
  std::normal_distribution<double> g(0.0, 1.0);
  Vec3 tool = Vec3::Zero();
  Matrix3X v = Matrix3X::Zero(3, n);
  int most_in_contact = 0, last_in_contact = -1;
  long calls_after_first = 0, allocations = 0;
  for (int k = 0; k < steps; ++k) {
    const Vec3 tool_step(0.004, -0.002, k < steps / 2 ? 0.02 : -0.02);  // mm
    Matrix3X f_ref = Matrix3X::Zero(3, n), f_skip = f_ref, f_mod = f_ref;
    const ContactKinematics kinematics{
        x, v, h, tool, k > 0 ? tool_step : Vec3::Zero(), k > 0 ? dt : 0.0};
    const ContactResult r_ref =
        compute_penalty_contact(reference.pair, reference.state, kinematics, f_ref);
    const long before = test::allocation_count();
    const ContactResult r_skip =
        compute_penalty_contact(skipping.pair, skipping.state, kinematics, f_skip);
    const ContactResult r_mod =
        compute_penalty_contact(skipping_modified.pair, skipping_modified.state, kinematics, f_mod);
    if (k > 0) {
      allocations += test::allocation_count() - before;
      ++calls_after_first;
    }
    ASSERT_TRUE(same_bits(f_skip, f_ref)) << "step " << k;
    ASSERT_TRUE(same_bits(f_mod, f_ref)) << "step " << k;
    ASSERT_TRUE(same_result(r_skip, r_ref)) << "step " << k;
    ASSERT_TRUE(same_result(r_mod, r_ref)) << "step " << k;
    ASSERT_TRUE(same_bits(skipping.state.stick_force, reference.state.stick_force)) << k;
    ASSERT_TRUE(same_bits(skipping_modified.state.stick_force, reference.state.stick_force)) << k;
    most_in_contact = std::max(most_in_contact, r_ref.nodes_in_contact);
    last_in_contact = r_ref.nodes_in_contact;
    // The next step: the nodes wander, the tool moves.
    for (int i = 0; i < n; ++i) {
      v.col(i) = (4e-3 / dt) * Vec3(g(rng), g(rng), g(rng)).normalized();  // mm/s
    }
    x += dt * v;
    tool += tool_step;
  }
  EXPECT_GT(most_in_contact, 40);  // the bowl pressed well into the nodes
  EXPECT_EQ(last_in_contact, 0);   // and left them
  EXPECT_EQ(allocations, 0) << "over " << calls_after_first << " calls";
  // The bounds did skip: fewer node queries reached the cached search.
  const auto& cached = dynamic_cast<const CachedSearch&>(*skipping.pair.search);
  const auto& cached_reference = dynamic_cast<const CachedSearch&>(*reference.pair.search);
  const long searched = cached.statistics(*skipping.state.search_cache).queries;
  const long all = cached_reference.statistics(*reference.state.search_cache).queries;
  EXPECT_EQ(all, static_cast<long>(n) * steps);
  EXPECT_LT(searched, all / 2);
  std::printf("nodes searched with the distance bounds: %ld of %ld node-steps\n", searched, all);
}

TEST(DistanceBound, ANodeJumpingTowardsTheToolIsNotSkipped) {
  // A node bounded far away, then moved next to the tool in one call: the bound has run out,
  // so it is searched and pressed, exactly as without bounds.
  const TriangleSurface s = make_bowl();
  Contact reference = make_contact(s, "modified", false, 1);
  Contact skipping = make_contact(s, "modified", true, 1);
  const VectorX h = VectorX::Constant(1, 0.4);
  const Matrix3X v = Matrix3X::Zero(3, 1);
  for (const double z : {9.0, 9.0, 0.3, 0.3, 5.0, 0.2, 1.25, 1.15}) {
    const Matrix3X x = Vec3(0.3, -0.2, z);
    Matrix3X f_ref = Matrix3X::Zero(3, 1), f_skip = f_ref;
    const ContactKinematics kinematics{x, v, h, Vec3::Zero(), Vec3::Zero(), 1e-3};
    const ContactResult r_ref =
        compute_penalty_contact(reference.pair, reference.state, kinematics, f_ref);
    const ContactResult r_skip =
        compute_penalty_contact(skipping.pair, skipping.state, kinematics, f_skip);
    EXPECT_TRUE(same_bits(f_skip, f_ref)) << z;
    EXPECT_TRUE(same_result(r_skip, r_ref)) << z;
    EXPECT_EQ(r_ref.nodes_in_contact, z < 0.4 ? 1 : 0) << z;
  }
}

}  // namespace
}  // namespace sf
