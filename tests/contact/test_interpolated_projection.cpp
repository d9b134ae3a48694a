// The interpolated projection (Wawrzyk & Kowalczyk, /work/shared/seed/modified-contact-search.txt,
// "interpolated projection"; src/contact/interpolated_projection.hpp): a point projected onto the
// search's triangle along the normal interpolated from the averaged nodal normals.
//
// Exact references: a flat region (the interpolated normal is the face normal, so the answer is
// the orthogonal projection); a point on a nodal normal's line through a vertex (the vertex is a
// solution by construction); a faceted cylinder whose nodal normals are exactly radial (derived
// below: the interpolated normal passes through the axis and D is measured to the chord).
// Tolerances: round-off (1e-14 relative) where the answer is the same arithmetic; otherwise a few
// times the projector's residual tolerance (1e-12 of the tool size) divided by the conditioning.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <numbers>
#include <random>
#include <vector>

#include "allocation_counter.hpp"
#include "contact/contact_search.hpp"
#include "contact/interpolated_projection.hpp"
#include "faceted_cylinder.hpp"
#include "test_meshes.hpp"

namespace sf {
namespace {

using Feature = ClosestPoint::Feature;

/// Search + interpolated projection of p (cutoff: everything).
InterpolatedProjection project(const ContactSearch& search, const InterpolatedProjector& proj,
                               const Vec3& p, ClosestPoint* closest_out = nullptr) {
  ClosestPoint cp;
  search.find_closest(p, std::numeric_limits<double>::infinity(), cp);
  InterpolatedProjection ip;
  proj.project(p, cp, ip);
  if (closest_out) {
    *closest_out = cp;
  }
  return ip;
}

double residual(const InterpolatedProjection& ip, const Vec3& p) {
  return (ip.point + ip.distance * ip.normal - p).norm();
}

/// The interpolated normal recomputed from the result's triangle and coordinates.
Vec3 interpolated_normal(const TriangleSurface& s, const InterpolatedProjection& ip) {
  const auto& t = s.triangles().col(ip.triangle);
  const Matrix3X& nn = s.node_normals();
  return (ip.barycentric[2] * nn.col(t[0]) + ip.barycentric[0] * nn.col(t[1]) +
          ip.barycentric[1] * nn.col(t[2]))
      .normalized();
}

double warped(double x, double y) {
  return 0.8 * std::sin(0.7 * x) * std::cos(0.5 * y) + 0.01 * x * y;
}

TEST(InterpolatedProjection, FlatRegionEqualsOrthogonalProjection) {
  // A tilted plane: all nodal normals equal the face normal (to round-off).
  const TriangleSurface s = test::make_height_field(
      "plane", 8, 8, -4, 4, -4, 4, [](double x, double y) { return 0.3 * x - 0.2 * y + 1; });
  const auto search = make_contact_search("modified", s);
  const InterpolatedProjector proj(s);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-3.5, 3.5), dz(-1.0, 1.0);
  for (int k = 0; k < 500; ++k) {
    const double x = u(rng), y = u(rng);
    const Vec3 p(x, y, 0.3 * x - 0.2 * y + 1 + dz(rng));
    ClosestPoint cp;
    const InterpolatedProjection ip = project(*search, proj, p, &cp);
    ASSERT_FALSE(ip.fallback);
    EXPECT_EQ(ip.iterations, 0);
    EXPECT_EQ(ip.triangle, cp.triangle);
    EXPECT_NEAR(ip.distance, cp.signed_distance, 1e-14 * (1 + std::abs(cp.distance)));
    EXPECT_NEAR((ip.point - cp.point).norm(), 0, 1e-14);
    EXPECT_NEAR((ip.normal - cp.normal).norm(), 0, 1e-15);
    EXPECT_NEAR((ip.barycentric - cp.barycentric).norm(), 0, 1e-14);
  }
}

TEST(InterpolatedProjection, PointOnNodalNormalLineProjectsOntoTheVertex) {
  const TriangleSurface s = test::make_height_field("warped", 16, 16, -4, 4, -4, 4, warped);
  const auto search = make_contact_search("modified", s);
  const InterpolatedProjector proj(s);
  const double tol = 10 * proj.tolerance();
  int checked = 0;
  for (int v = 0; v < s.num_nodes(); ++v) {
    const Vec3 xv = s.nodes().col(v);
    if (std::abs(xv.x()) > 3 || std::abs(xv.y()) > 3) {
      continue;
    }
    for (double d : {0.3, 0.05, 0.0, -0.2}) {
      const Vec3 p = xv + d * s.node_normals().col(v);
      const InterpolatedProjection ip = project(*search, proj, p);
      SCOPED_TRACE(::testing::Message() << "vertex " << v << " d " << d);
      ASSERT_FALSE(ip.fallback);
      EXPECT_NEAR((ip.point - xv).norm(), 0, tol);
      EXPECT_NEAR(ip.distance, d, tol);
      EXPECT_NEAR((ip.normal - s.node_normals().col(v)).norm(), 0, tol);
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

TEST(InterpolatedProjection, FacetedCylinderNormalPassesThroughTheAxis) {
  // Nodal normals radial: with (w_k, w_k+1) the summed coordinates of the nodes at the facet's
  // two angles, x(T) = R (w_k r_k + w_k+1 r_k+1) + y e_y and m(T) = w_k r_k + w_k+1 r_k+1, so
  // x(T) - y e_y = R m(T): the interpolated normal at the solution points away from the axis
  // through p. Hence n = (cos phi, 0, sin phi) (phi: p's angle about the axis) and D is measured
  // along that ray from the chord: D = rho - R cos(pi/N) / cos(phi - theta_mid), theta_mid the
  // mid-angle of the facet holding phi.
  const double radius = 50, phase = 0.1;
  const int facets = 32;
  const TriangleSurface s = test::make_faceted_cylinder(radius, facets, phase, -20, 20, 4);
  // The nodal normals of the three inner rows are radial to round-off.
  for (int v = facets; v < 4 * facets; ++v) {
    const Vec3 x = s.nodes().col(v);
    EXPECT_NEAR((s.node_normals().col(v) - Vec3(x.x(), 0, x.z()) / radius).norm(), 0, 1e-15);
  }
  const auto search = make_contact_search("modified", s);
  const InterpolatedProjector proj(s);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi), dr(-3.0, 3.0),
      y(-9.5, 9.5);
  const double facet_angle = 2 * std::numbers::pi / facets;
  double max_n = 0, max_d = 0;
  int walked = 0;
  for (int k = 0; k < 2000; ++k) {
    const double phi = angle(rng), rho = radius + dr(rng);
    const Vec3 p(rho * std::cos(phi), y(rng), rho * std::sin(phi));
    ClosestPoint cp;
    const InterpolatedProjection ip = project(*search, proj, p, &cp);
    ASSERT_FALSE(ip.fallback) << p.transpose();
    walked += ip.triangles_tried > std::max(cp.set_size, 1) ? 1 : 0;
    const double facet = std::floor((phi - phase) / facet_angle);
    const double mid = phase + (facet + 0.5) * facet_angle;
    const double d_exact = rho - radius * std::cos(facet_angle / 2) / std::cos(phi - mid);
    const Vec3 n_exact(std::cos(phi), 0, std::sin(phi));
    max_n = std::max(max_n, (ip.normal - n_exact).norm());
    max_d = std::max(max_d, std::abs(ip.distance - d_exact));
    EXPECT_LE(residual(ip, p), proj.tolerance());
  }
  std::printf(
      "cylinder R 50, N 32: max |n - n_exact| %.2e, max |D - D_exact| %.2e mm, "
      "%d of 2000 points needed the walk beyond the tie set\n",
      max_n, max_d, walked);
  // D and n follow from the residual (<= 1e-12 x 70 mm = 7e-11 mm) through a Jacobian of
  // conditioning ~ R / facet size: a few 1e-10 at most.
  EXPECT_LT(max_n, 1e-10);
  EXPECT_LT(max_d, 1e-9);
}

TEST(InterpolatedProjection, ResidualBelowToleranceOnAWarpedSurface) {
  const TriangleSurface s = test::make_height_field("warped", 20, 20, -5, 5, -5, 5, warped);
  const auto search = make_contact_search("modified", s);
  const InterpolatedProjector proj(s);
  // The stated tolerance: 1e-12 of the tool size (bounding-box diagonal, ~14.2 mm here).
  const Matrix3X& nodes = s.nodes();
  const double size = std::max((nodes.rowwise().maxCoeff() - nodes.rowwise().minCoeff()).norm(),
                               nodes.cwiseAbs().maxCoeff());
  EXPECT_DOUBLE_EQ(proj.tolerance(), 1e-12 * size);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-4, 4), dz(-1, 1);
  int fallbacks = 0, max_iterations = 0;
  long iterations = 0;
  const int n = 5000;
  for (int k = 0; k < n; ++k) {
    const double x = u(rng), y = u(rng);
    const Vec3 p(x, y, warped(x, y) + dz(rng));
    const InterpolatedProjection ip = project(*search, proj, p);
    if (ip.fallback) {
      ++fallbacks;
      continue;
    }
    EXPECT_LE(residual(ip, p), proj.tolerance()) << p.transpose();
    EXPECT_GE(ip.barycentric.minCoeff(), -InterpolatedProjector::inside_tolerance);
    EXPECT_NEAR(ip.barycentric.sum(), 1.0, 1e-15);
    EXPECT_NEAR((ip.normal - interpolated_normal(s, ip)).norm(), 0, 1e-15);
    iterations += ip.iterations;
    max_iterations = std::max(max_iterations, ip.iterations);
  }
  std::printf("warped surface: %d points, %d fallbacks, Newton iterations mean %.2f, max %d\n", n,
              fallbacks, static_cast<double>(iterations) / (n - fallbacks), max_iterations);
  EXPECT_EQ(fallbacks, 0);
}

TEST(InterpolatedProjection, NoFallbackAwayFromTheBoundaryOfALargeWarpedSurface) {
  // 200000 random points within 1 mm of a 50 x 50 mm warped surface, at least 5 mm inside its
  // boundary: every one has an interpolated solution. Some need the walk beyond the tie set, a
  // few the vertex fan (without step 3 of the treatment, 6 of these points fell back).
  const TriangleSurface s = test::make_height_field("warped", 50, 50, -25, 25, -25, 25, warped);
  const auto search = make_contact_search("modified", s);
  const InterpolatedProjector proj(s);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-20, 20), dz(-1, 1);
  ClosestPoint cp;
  InterpolatedProjection ip;
  int fallbacks = 0, beyond_set = 0;
  const int n = 200000;
  for (int k = 0; k < n; ++k) {
    const double x = u(rng), y = u(rng);
    const Vec3 p(x, y, warped(x, y) + dz(rng));
    search->find_closest(p, 2.0, cp);
    proj.project(p, cp, ip);
    fallbacks += ip.fallback ? 1 : 0;
    beyond_set += ip.triangles_tried > std::max(cp.set_size, 1) ? 1 : 0;
    ASSERT_LE(residual(ip, p), proj.tolerance());
  }
  std::printf("large warped surface: %d points, %d needed the walk or the fan, %d fallbacks\n", n,
              beyond_set, fallbacks);
  EXPECT_EQ(fallbacks, 0);
}

/// Ridge z = -|x| tan(alpha) (alpha = 15 degrees) on 1 mm cells, the ridge along the grid line
/// x = 0: the surface bends away from the +z side.
TriangleSurface make_ridge() {
  const double slope = std::tan(15.0 * std::numbers::pi / 180);
  return test::make_height_field("ridge", 6, 6, -3, 3, -3, 3,
                                 [slope](double x, double) { return -std::abs(x) * slope; });
}

struct SweepJumps {
  double interpolated_normal = 0, interpolated_distance = 0;
  double orthogonal_normal = 0, orthogonal_distance = 0;
};

/// Largest change of normal and D between neighbouring points of the sweep x in [-1.5, 1.5] at
/// y = 0.37, z = z0, spacing `step`.
SweepJumps sweep_ridge(const TriangleSurface& s, double z0, double step) {
  const auto search = make_contact_search("modified", s);
  const InterpolatedProjector proj(s);
  SweepJumps j;
  ClosestPoint prev_cp;
  InterpolatedProjection prev_ip;
  const int n = static_cast<int>(std::lround(3.0 / step));
  for (int k = 0; k <= n; ++k) {
    const Vec3 p(-1.5 + (k + 0.37) * step, 0.37, z0);  // never exactly on the ridge line
    ClosestPoint cp;
    const InterpolatedProjection ip = project(*search, proj, p, &cp);
    EXPECT_FALSE(ip.fallback) << p.transpose();
    if (k > 0) {
      j.interpolated_normal = std::max(j.interpolated_normal, (ip.normal - prev_ip.normal).norm());
      j.interpolated_distance =
          std::max(j.interpolated_distance, std::abs(ip.distance - prev_ip.distance));
      j.orthogonal_normal = std::max(j.orthogonal_normal, (cp.normal - prev_cp.normal).norm());
      j.orthogonal_distance =
          std::max(j.orthogonal_distance, std::abs(cp.signed_distance - prev_cp.signed_distance));
    }
    prev_cp = cp;
    prev_ip = ip;
  }
  return j;
}

TEST(InterpolatedProjection, ConvexRidgeSweepIsContinuous) {
  // Continuity: the largest jump between neighbouring samples halves with the spacing (a
  // Lipschitz field); a discontinuity keeps a jump that does not shrink. Swept 0.3 mm above the
  // apex (outside the tool) and 0.2 mm below it (behind the surface near the ridge).
  const TriangleSurface s = make_ridge();
  const double face_normal_jump = 2 * std::sin(15.0 * std::numbers::pi / 180);  // 0.518
  for (double z0 : {0.3, -0.2}) {
    SweepJumps previous;
    for (double step : {0.02, 0.01, 0.005}) {
      const SweepJumps j = sweep_ridge(s, z0, step);
      std::printf(
          "ridge sweep z0 %+.1f step %.3f: interpolated max jump |dn| %.2e |dD| %.2e; "
          "orthogonal |dn| %.2e |dD| %.2e\n",
          z0, step, j.interpolated_normal, j.interpolated_distance, j.orthogonal_normal,
          j.orthogonal_distance);
      if (step < 0.02) {
        // Halving the spacing at least nearly halves the interpolated jumps (Lipschitz).
        EXPECT_LT(j.interpolated_normal, 0.6 * previous.interpolated_normal);
        EXPECT_LT(j.interpolated_distance, 0.6 * previous.interpolated_distance);
      }
      if (z0 < 0) {
        // Behind the ridge the orthogonal normal switches from one face normal to the other.
        EXPECT_GT(j.orthogonal_normal, 0.99 * face_normal_jump);
      }
      previous = j;
    }
  }
}

TEST(InterpolatedProjection, FoldDeadZoneGetsASolution) {
  // REFERENCES.md item 2: the flange z = 0 (x < 0) meets a shoulder falling at 40 degrees
  // (x > 0); seen from +z the surface bends away, and points in the wedge between the two face
  // normals at the fold project orthogonally onto neither triangle (the search reports the fold
  // edge). The interpolated normals fan across the wedge: every such point has a solution.
  const double slope = std::tan(40.0 * std::numbers::pi / 180);
  const TriangleSurface s = test::make_height_field(
      "shoulder", 8, 8, -4, 4, -4, 4, [slope](double x, double) { return x > 0 ? -x * slope : 0; });
  const auto search = make_contact_search("modified", s);
  const InterpolatedProjector proj(s);
  const Vec3 n_flange = Vec3::UnitZ();
  const Vec3 n_shoulder = Vec3(slope, 0, 1).normalized();
  int dead_zone = 0;
  double max_ratio = 0;
  for (double d : {0.05, 0.3, 1.0}) {
    for (int k = 1; k < 20; ++k) {
      const double w = k / 20.0;
      const Vec3 dir = ((1 - w) * n_flange + w * n_shoulder).normalized();
      const Vec3 p = Vec3(0, 0.45, 0) + d * dir;
      ClosestPoint cp;
      const InterpolatedProjection ip = project(*search, proj, p, &cp);
      SCOPED_TRACE(::testing::Message() << "p = " << p.transpose());
      dead_zone += cp.feature == Feature::edge ? 1 : 0;
      EXPECT_NE(cp.feature, Feature::face);
      ASSERT_FALSE(ip.fallback);
      EXPECT_GE(ip.barycentric.minCoeff(), -InterpolatedProjector::inside_tolerance);
      EXPECT_LE(residual(ip, p), proj.tolerance());
      // |D| = |p - x(T)| is at least the distance d from p to the surface (the fold edge).
      EXPECT_GE(ip.distance, d * (1 - 1e-12));
      max_ratio = std::max(max_ratio, ip.distance / d);
    }
  }
  EXPECT_EQ(dead_zone, 57);
  std::printf("fold dead zone: 57 points, largest D / (distance to the fold) %.4f\n", max_ratio);
  // A loose sanity bound, not a derived one (measured 1.062): the interpolated normals lean at
  // most the 40 degree wedge away from the directions p - fold.
  EXPECT_LT(max_ratio, 1.0 / std::cos(40.0 * std::numbers::pi / 180));

  // Seen from the other side (-z) the same fold is a valley: points there project onto both
  // faces; the interpolated projection still gives one answer without a fallback.
  for (double d : {0.05, 0.3}) {
    for (int k = 0; k <= 20; ++k) {
      const double w = k / 20.0;
      const Vec3 p = Vec3(0, -0.45, 0) - d * ((1 - w) * n_flange + w * n_shoulder).normalized();
      const InterpolatedProjection ip = project(*search, proj, p);
      ASSERT_FALSE(ip.fallback) << p.transpose();
      EXPECT_LE(residual(ip, p), proj.tolerance());
      EXPECT_LT(ip.distance, 0);
    }
  }
}

/// The same surface with its triangles in reverse order and each triangle's nodes rotated
/// (a, b, c) -> (b, c, a) (same orientation).
TriangleSurface renumbered(const TriangleSurface& s) {
  TriConn t(3, s.num_triangles());
  for (int k = 0; k < s.num_triangles(); ++k) {
    const auto c = s.triangles().col(s.num_triangles() - 1 - k);
    t.col(k) << c[1], c[2], c[0];
  }
  return TriangleSurface(s.name(), s.nodes(), t);
}

TEST(InterpolatedProjection, EdgeAndVertexHitsDoNotDependOnSetOrder) {
  const TriangleSurface s = make_ridge();
  const TriangleSurface r = renumbered(s);
  const auto search_s = make_contact_search("modified", s);
  const auto search_r = make_contact_search("modified", r);
  const InterpolatedProjector proj_s(s), proj_r(r);
  std::vector<Vec3> points;
  // On the surface at vertices and edge midpoints (D = 0: the set is every triangle there).
  const TriConn& tri = s.triangles();
  for (int t = 0; t < s.num_triangles(); t += 3) {
    points.push_back(s.nodes().col(tri(0, t)));
    if (s.triangle_neighbours()(0, t) >= 0) {  // an interior edge: two triangles
      points.push_back(0.5 * (s.nodes().col(tri(0, t)) + s.nodes().col(tri(1, t))));
    }
  }
  // Above the ridge edge (x = 0) in its wedge: the set is the two ridge triangles.
  points.push_back(Vec3(0, 0.3, 0.4));
  points.push_back(Vec3(0, -1.7, 0.1));
  int multi = 0;
  for (const Vec3& p : points) {
    ClosestPoint cp;
    search_s->find_closest(p, 1.0, cp);
    ASSERT_GE(cp.triangle, 0);
    multi += cp.set_size > 1 ? 1 : 0;
    InterpolatedProjection a, b;
    proj_s.project(p, cp, a);
    ClosestPoint reversed = cp;
    std::reverse(reversed.set.begin(), reversed.set.begin() + reversed.set_size);
    proj_s.project(p, reversed, b);
    SCOPED_TRACE(::testing::Message() << "p = " << p.transpose() << " set " << cp.set_size);
    ASSERT_FALSE(a.fallback);
    // Bitwise the same answer for the set in any order.
    EXPECT_EQ(a.triangle, b.triangle);
    EXPECT_EQ(a.distance, b.distance);
    EXPECT_EQ(a.point, b.point);
    EXPECT_EQ(a.normal, b.normal);
    // The renumbered surface: the same point, normal and D (possibly from another triangle of
    // the set) to round-off.
    const InterpolatedProjection c = project(*search_r, proj_r, p);
    ASSERT_FALSE(c.fallback);
    EXPECT_NEAR((a.point - c.point).norm(), 0, 1e-12);
    EXPECT_NEAR((a.normal - c.normal).norm(), 0, 1e-12);
    EXPECT_NEAR(a.distance, c.distance, 1e-12);
  }
  EXPECT_EQ(multi, static_cast<int>(points.size()));
}

TEST(InterpolatedProjection, OffTheSurfaceFallsBackToTheOrthogonalAnswer) {
  // A flat patch: beyond its boundary the interpolated solution (the plane projection) lies
  // outside every triangle; the walk meets the boundary and the orthogonal answer is returned.
  const TriangleSurface s =
      test::make_height_field("patch", 4, 4, 0, 4, 0, 4, [](double, double) { return 0.0; });
  const auto search = make_contact_search("modified", s);
  const InterpolatedProjector proj(s);
  const Vec3 p(4.5, 2.2, 0.3);
  ClosestPoint cp;
  const InterpolatedProjection ip = project(*search, proj, p, &cp);
  EXPECT_TRUE(ip.fallback);
  EXPECT_EQ(ip.triangle, cp.triangle);
  EXPECT_EQ(ip.distance, cp.signed_distance);
  EXPECT_EQ(ip.point, cp.point);
  EXPECT_EQ(ip.normal, cp.normal);
  // The boundary triangle (the walk stops at the boundary), then the fan of its nearest vertex.
  EXPECT_GE(ip.triangles_tried, 2);

  // A knife edge: a triangle and its reversed copy (a two-sided sheet of zero thickness). Every
  // nodal normal is the mean of +n and -n, i.e. zero: no interpolated normal exists anywhere.
  Matrix3X x(3, 3);
  x << 0, 1, 0.5,  //
      0, 0, 1,     //
      0, 0, 0;
  TriConn t(3, 2);
  t.col(0) << 0, 1, 2;
  t.col(1) << 1, 0, 2;
  const TriangleSurface knife("knife", x, t);
  EXPECT_EQ(knife.node_normals().norm(), 0.0);
  const auto knife_search = make_contact_search("modified", knife);
  const InterpolatedProjector knife_proj(knife);
  const InterpolatedProjection kp = project(*knife_search, knife_proj, Vec3(0.5, 0.3, 0.2), &cp);
  EXPECT_TRUE(kp.fallback);
  EXPECT_EQ(kp.triangles_tried, 2);
  EXPECT_EQ(kp.triangle, 0);
  EXPECT_EQ(kp.distance, cp.signed_distance);
  EXPECT_EQ(kp.normal, cp.normal);
}

TEST(InterpolatedProjection, DoesNotAllocate) {
  const TriangleSurface s = test::make_height_field("warped", 20, 20, -5, 5, -5, 5, warped);
  const auto search = make_contact_search("modified", s);
  const InterpolatedProjector proj(s);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-4, 4), dz(-1, 1);
  std::vector<Vec3> points;
  for (int k = 0; k < 200; ++k) {
    const double x = u(rng), y = u(rng);
    points.push_back(Vec3(x, y, warped(x, y) + dz(rng)));
  }
  ClosestPoint cp;
  InterpolatedProjection ip;
  double sum = 0;
  const long before = test::allocation_count();
  for (const Vec3& p : points) {
    search->find_closest(p, 2.0, cp);
    proj.project(p, cp, ip);
    sum += ip.distance;
  }
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace sf
