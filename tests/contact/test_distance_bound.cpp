// The distance bounds of the penalty contact: ToolDistanceBound never exceeds the distance to the
// tool (against the brute-force oracle) and is exact within its reach; skipping the nodes that
// the bounds prove beyond the cutoff changes nothing, bit for bit, over a moving sequence on a
// curved tool (nodes approaching, touching and leaving it, the tool moving), with friction and
// the interpolated projection, for the cached and the modified search. The front bounds (nodes
// within the cutoff proved out of contact) the same way, around a tool's edges, behind it and over
// a crease, where the side a node is on decides its contact.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

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

/// The contact's per-node results: normal forces and sliding distances.
bool same_state(const ContactState& a, const ContactState& b) {
  const auto same = [](const VectorX& x, const VectorX& y) {
    return x.size() == y.size() &&
           std::memcmp(x.data(), y.data(), sizeof(double) * static_cast<std::size_t>(x.size())) ==
               0;
  };
  return same(a.normal_force, b.normal_force) && same(a.sliding_distance, b.sliding_distance);
}

/// One call for a single node at p (velocity v, mm/s; half thickness h, mm) without the bounds
/// (`reference`) and with them (`skipping`): the same forces, results, contact fields and stick
/// forces, bit for bit (`what` names the step in a failure). The reference's result.
ContactResult step_one_node(Contact& reference, Contact& skipping, const Vec3& p, const Vec3& v,
                            double h, double what) {
  const Matrix3X x = p, velocity = v;
  const VectorX half = VectorX::Constant(1, h);
  Matrix3X f_ref = Matrix3X::Zero(3, 1), f_skip = f_ref;
  const ContactKinematics kinematics{x, velocity, half, Vec3::Zero(), Vec3::Zero(), 1e-3};
  const ContactResult r_ref =
      compute_penalty_contact(reference.pair, reference.state, kinematics, f_ref);
  const ContactResult r_skip =
      compute_penalty_contact(skipping.pair, skipping.state, kinematics, f_skip);
  EXPECT_TRUE(same_bits(f_skip, f_ref)) << what;
  EXPECT_TRUE(same_result(r_skip, r_ref)) << what;
  EXPECT_TRUE(same_state(skipping.state, reference.state)) << what;
  EXPECT_TRUE(same_bits(skipping.state.stick_force, reference.state.stick_force)) << what;
  return r_ref;
}

/// One call at `kinematics` without the bounds (`reference`) and with them (`skipping`, cached;
/// `skipping_modified`): expects the same forces, results, stick forces and contact fields, bit
/// for bit (step k names a failure). Adds the two bounded calls' allocations to *allocations.
/// The reference's result, its forces into f_ref.
ContactResult call_alike(Contact& reference, Contact& skipping, Contact& skipping_modified,
                         const ContactKinematics& kinematics, int k, long* allocations,
                         Matrix3X& f_ref) {
  f_ref.setZero(3, kinematics.x.cols());
  Matrix3X f_skip = f_ref, f_mod = f_ref;
  const ContactResult r_ref =
      compute_penalty_contact(reference.pair, reference.state, kinematics, f_ref);
  const long before = test::allocation_count();
  const ContactResult r_skip =
      compute_penalty_contact(skipping.pair, skipping.state, kinematics, f_skip);
  const ContactResult r_mod =
      compute_penalty_contact(skipping_modified.pair, skipping_modified.state, kinematics, f_mod);
  *allocations += test::allocation_count() - before;
  EXPECT_TRUE(same_bits(f_skip, f_ref)) << "step " << k;
  EXPECT_TRUE(same_bits(f_mod, f_ref)) << "step " << k;
  EXPECT_TRUE(same_result(r_skip, r_ref)) << "step " << k;
  EXPECT_TRUE(same_result(r_mod, r_ref)) << "step " << k;
  EXPECT_TRUE(same_bits(skipping.state.stick_force, reference.state.stick_force)) << k;
  EXPECT_TRUE(same_bits(skipping_modified.state.stick_force, reference.state.stick_force)) << k;
  EXPECT_TRUE(same_state(skipping.state, reference.state)) << k;
  EXPECT_TRUE(same_state(skipping_modified.state, reference.state)) << k;
  return r_ref;
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
    const ContactKinematics kinematics{
        x, v, h, tool, k > 0 ? tool_step : Vec3::Zero(), k > 0 ? dt : 0.0};
    long call_allocations = 0;
    Matrix3X f_ref;
    const ContactResult r_ref =
        call_alike(reference, skipping, skipping_modified, kinematics, k, &call_allocations, f_ref);
    ASSERT_FALSE(::testing::Test::HasFailure()) << "step " << k;
    if (k > 0) {
      allocations += call_allocations;
      ++calls_after_first;
    }
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
  for (const double z : {9.0, 9.0, 0.3, 0.3, 5.0, 0.2, 1.25, 1.15}) {
    const ContactResult r =
        step_one_node(reference, skipping, Vec3(0.3, -0.2, z), Vec3::Zero(), 0.4, z);
    EXPECT_EQ(r.nodes_in_contact, z < 0.4 ? 1 : 0) << z;
  }
}

/// The plane of a triangle: the signed distance of p from it, on the side of its normal.
double plane_side(const TriangleSurface& s, int t, const Vec3& p) {
  const Vec3 x1 = s.nodes().col(s.triangles()(0, t));
  return s.triangle_normals().col(t).dot(p - x1);
}

TEST(ToolDistanceBound, FrontClearanceIsTheBruteForceOneWithinReach) {
  // Against every triangle by brute force (the oracle's distance): the least plane side and the
  // least distance over the triangles within reach, and the normal cone, on the bowl (smooth:
  // sided) and on a roof creased by 2 atan(2) = 127 degrees (not sided near the crease).
  const TriangleSurface bowl = make_bowl();
  const TriangleSurface roof = test::make_height_field(
      "roof", 8, 8, -4, 4, -4, 4, [](double x, double) { return -2.0 * std::abs(x); });
  const double reach = 1.5;
  int sided = 0, unsided = 0;
  for (const TriangleSurface* s : {&bowl, &roof}) {
    const ToolDistanceBound bound(*s);
    for (const Vec3& p : test::random_points(1500, Vec3(-5, -5, -9), Vec3(5, 5, 6), 7)) {
      double nearest = std::numeric_limits<double>::infinity();
      double least_side = nearest;
      std::vector<int> within;
      for (int t = 0; t < s->num_triangles(); ++t) {
        const Vec3 q = oracle::closest_point_on_triangle(p, s->nodes().col(s->triangles()(0, t)),
                                                         s->nodes().col(s->triangles()(1, t)),
                                                         s->nodes().col(s->triangles()(2, t)));
        const double d = (q - p).norm();
        if (d <= reach) {
          nearest = std::min(nearest, d);
          least_side = std::min(least_side, plane_side(*s, t, p));
          within.push_back(t);
        }
      }
      const FrontClearance front = bound.front_clearance(p, reach);
      if (within.empty()) {
        EXPECT_GE(front.distance, reach - 1e-12) << p.transpose();
        continue;
      }
      EXPECT_NEAR(front.nearest, nearest, 1e-12) << p.transpose();
      EXPECT_NEAR(front.distance, nearest, 1e-12) << p.transpose();
      EXPECT_NEAR(front.least_side, least_side, 1e-12) << p.transpose();
      // The largest angle between two face normals within reach: a sided answer needs it below
      // 90 degrees, and its sine bounds that angle's.
      double least_cos = 1.0;
      for (const int a : within) {
        for (const int b : within) {
          least_cos =
              std::min(least_cos, s->triangle_normals().col(a).dot(s->triangle_normals().col(b)));
        }
      }
      if (front.sided) {
        EXPECT_GT(least_cos, 0.0) << p.transpose();
        EXPECT_GE(front.cone_sine, std::sqrt(1.0 - least_cos * least_cos) - 1e-12) << p.transpose();
        ++sided;
      } else {
        ++unsided;
      }
      if (s == &bowl) {
        EXPECT_TRUE(front.sided) << p.transpose();  // 20 degrees at most within reach
      }
      if (least_cos < 0.0) {
        EXPECT_FALSE(front.sided) << p.transpose();
      }
    }
  }
  EXPECT_GT(sided, 300);
  EXPECT_GT(unsided, 50);
}

/// Runs `steps` contact calls of nodes x wandering (`wander` mm per step, random directions) with
/// the tool moving by tool_step(k), without bounds (the reference) and with them (cached and
/// modified search); asserts the same forces, results and stick forces, bit for bit, at every
/// step. Returns {node queries that reached the bounded cached search, node-steps with the tool
/// within the cutoff (brute force), most nodes in contact in a step, node-steps pressed while
/// below z = 0 (behind a flat tool at z = 0)}.
struct SequenceCounts {
  long searched = 0, within_cutoff = 0;
  int most_in_contact = 0;
  long pressed_from_behind = 0;
};

SequenceCounts run_sequence(const TriangleSurface& s, Matrix3X x, double h, int steps,
                            double wander, const std::function<Vec3(int)>& tool_step) {
  const int n = static_cast<int>(x.cols());
  const VectorX half = VectorX::Constant(n, h);
  const double dt = 1e-3;  // s
  Contact reference = make_contact(s, "cached", false, n);
  Contact skipping = make_contact(s, "cached", true, n);
  Contact skipping_modified = make_contact(s, "modified", true, n);
  std::mt19937 rng(5);
  std::normal_distribution<double> g(0.0, 1.0);
  Vec3 tool = Vec3::Zero();
  Matrix3X v = Matrix3X::Zero(3, n);
  SequenceCounts counts;
  for (int k = 0; k < steps; ++k) {
    const Vec3 step = tool_step(k);
    const ContactKinematics kinematics{
        x, v, half, tool, k > 0 ? step : Vec3::Zero(), k > 0 ? dt : 0.0};
    long allocations = 0;
    Matrix3X f_ref;
    const ContactResult r_ref =
        call_alike(reference, skipping, skipping_modified, kinematics, k, &allocations, f_ref);
    if (::testing::Test::HasFailure()) {
      return counts;
    }
    counts.most_in_contact = std::max(counts.most_in_contact, r_ref.nodes_in_contact);
    for (int i = 0; i < n; ++i) {
      const Vec3 p = x.col(i) - tool;
      const oracle::OracleAnswer o = oracle::closest(s.nodes(), s.triangles(), p, 0.0);
      counts.within_cutoff += o.distance <= reference.pair.cutoff ? 1 : 0;
      counts.pressed_from_behind += f_ref.col(i).squaredNorm() > 0.0 && p.z() < 0.0 ? 1 : 0;
    }
    for (int i = 0; i < n; ++i) {
      v.col(i) = (wander / dt) * Vec3(g(rng), g(rng), g(rng)).normalized();  // mm/s
    }
    x += dt * v;
    tool += step;
  }
  const auto& cached = dynamic_cast<const CachedSearch&>(*skipping.pair.search);
  counts.searched = cached.statistics(*skipping.state.search_cache).queries;
  std::printf("node-steps: %ld with the tool within the cutoff, %ld searched with the bounds\n",
              counts.within_cutoff, counts.searched);
  return counts;
}

TEST(FrontBound, SkippingNodesNearAFlatToolChangesNothingAroundItsEdgesAndBehindIt) {
  // A flat square tool [-4, 4]^2 (normal +z) and 17 x 17 nodes over [-6, 6]^2 in layers at
  // z = +0.6, -0.6 and +1.0 mm, h = 0.4 mm, cutoff 0.8 mm: nodes above it apart or touching as
  // the tool bobs, nodes below it pressed through (the penalty acts within h + cutoff behind a
  // tool), nodes beyond its edges turning round them. Without the side test a front bound would
  // skip a node that went round an edge to the back.
  const TriangleSurface plate =
      test::make_height_field("plate", 8, 8, -4, 4, -4, 4, [](double, double) { return 0.0; });
  const int side = 17;
  Matrix3X x(3, side * side);
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      const double z = (i + j) % 3 == 0 ? 0.6 : ((i + j) % 3 == 1 ? -0.6 : 1.0);
      x.col(j * side + i) = Vec3(-6.0 + 0.75 * i, -6.0 + 0.75 * j, z);
    }
  }
  const SequenceCounts counts = run_sequence(plate, x, 0.4, 400, 4e-3, [](int k) {
    return Vec3(0.003, 0.001, 0.004 * std::sin(0.05 * k));  // mm
  });
  EXPECT_GT(counts.most_in_contact, 20);
  EXPECT_GT(counts.pressed_from_behind, 1000);
  // The front bounds did skip nodes within the cutoff.
  EXPECT_LT(counts.searched, counts.within_cutoff * 3 / 4);
}

TEST(FrontBound, SkippingNodesNearACreasedToolChangesNothing) {
  // A roof creased by 2 atan(0.25) = 28 degrees (sided, the cone's sine 0.47) and by 127 degrees
  // (not sided along the crease), nodes wandering over and under it as it rises and falls.
  for (const double slope : {0.25, 2.0}) {
    const TriangleSurface roof = test::make_height_field(
        "roof", 8, 8, -4, 4, -4, 4, [slope](double x, double) { return -slope * std::abs(x); });
    const int side = 15;
    Matrix3X x(3, side * side);
    for (int j = 0; j < side; ++j) {
      for (int i = 0; i < side; ++i) {
        const double px = -5.0 + 10.0 * i / (side - 1), py = -5.0 + 10.0 * j / (side - 1);
        const double z = -slope * std::min(std::abs(px), 4.0) + ((i + j) % 2 == 0 ? 0.7 : -0.55);
        x.col(j * side + i) = Vec3(px, py, z);
      }
    }
    const SequenceCounts counts = run_sequence(roof, x, 0.4, 300, 3e-3, [](int k) {
      return Vec3(0.002, -0.001, 0.004 * std::cos(0.04 * k));  // mm
    });
    EXPECT_GT(counts.most_in_contact, 10) << slope;
    EXPECT_LT(counts.searched, counts.within_cutoff) << slope;
  }
}

TEST(FrontBound, ANodeBackNearItsBoundAfterAPressHasItsForcesReset) {
  // Apart at 0.7 mm above the bowl (a front bound: 0.3 mm of gap slack), pressed at 0.3 mm (the
  // bound ran out), then back at 0.65 mm: within the old bound's slack, apart, and its normal
  // and stick forces must be zero again, as the search leaves them.
  const TriangleSurface s = make_bowl();
  Contact reference = make_contact(s, "cached", false, 1);
  Contact skipping = make_contact(s, "cached", true, 1);
  const Vec3 v = Vec3::Constant(1.0);  // mm/s: sliding, so friction sticks or slips
  for (const double z : {0.7, 0.3, 0.65, 0.3, 0.66}) {
    const ContactResult r = step_one_node(reference, skipping, Vec3(0.3, -0.2, z), v, 0.4, z);
    EXPECT_EQ(r.nodes_in_contact, z < 0.4 ? 1 : 0) << z;
  }
}

TEST(FrontBound, ANodeMovingIntoATieOfTwoFacetsAcrossAWideAngleIsNotSkipped) {
  // Two separate facets (a soup: every projection beyond their edges falls back to the
  // orthogonal one) whose edges are 0.6 mm from the origin along -x and -z, both facing the
  // origin's side of their planes, their normals 124 degrees apart. At the origin the two tie,
  // and the fallback's sign (p - the first facet's point against the mean normal) is negative:
  // pressed (D = -0.6 > -h - cutoff). 1e-3 mm towards the first facet it is apart (D = +0.599):
  // every plane side is positive there, so only the normal cone keeps a front bound from
  // skipping the node's step into the tie.
  const double a = 10.0 * std::numbers::pi / 180.0, b = 60.0 * std::numbers::pi / 180.0;
  Matrix3X nodes(3, 6);
  nodes.col(0) = Vec3(0.6, 5, 0);  // facet A, normal (-sin a, 0, cos a)
  nodes.col(1) = Vec3(0.6, -5, 0);
  nodes.col(2) = Vec3(0.6 + 3 * std::cos(a), 0, 3 * std::sin(a));
  nodes.col(3) = Vec3(0, -5, 0.6);  // facet B, normal (sin b, 0, -cos b)
  nodes.col(4) = Vec3(0, 5, 0.6);
  nodes.col(5) = Vec3(3 * std::cos(b), 0, 0.6 + 3 * std::sin(b));
  TriConn tri(3, 2);
  tri << 0, 3, 1, 4, 2, 5;
  const TriangleSurface facets("facets", nodes, tri);
  ASSERT_LT(facets.triangle_normals().col(0).dot(facets.triangle_normals().col(1)), -0.5);
  Contact reference = make_contact(facets, "modified", false, 1);
  Contact skipping = make_contact(facets, "modified", true, 1);
  int pressed = 0;
  for (const double x : {1e-3, 0.0, 1e-3, 0.0}) {
    const ContactResult r = step_one_node(reference, skipping, Vec3(x, 0, 0), Vec3::Zero(), 0.4, x);
    EXPECT_EQ(r.nodes_in_contact, x == 0.0 ? 1 : 0) << x;
    pressed += r.nodes_in_contact;
  }
  EXPECT_EQ(pressed, 2);
}

}  // namespace
}  // namespace sf
