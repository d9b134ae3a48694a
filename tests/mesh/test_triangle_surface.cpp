// TriangleSurface (derived data) and orient_surface. Expected values are exact geometry of the
// small meshes built here (normals of axis-aligned or explicitly tilted triangles); tolerances
// are round-off (1e-14).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "mesh/triangle_surface.hpp"

namespace sf {
namespace {

/// Height field z = f(x, y) on [0, n] x [0, n], two triangles per cell, normals toward +z.
TriangleSurface make_grid(const std::string& name, int n, double (*f)(double, double),
                          double z_offset = 0) {
  Matrix3X x(3, (n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      x.col(j * (n + 1) + i) = Vec3(i, j, f(i, j) + z_offset);
    }
  }
  TriConn t(3, 2 * n * n);
  int k = 0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      t.col(k++) << a, b, c;
      t.col(k++) << a, c, d;
    }
  }
  return TriangleSurface(name, x, t);
}

double bumpy(double x, double y) {
  return 0.2 * std::sin(x) * std::cos(0.7 * y);
}
double flat(double, double) {
  return 0;
}

TEST(TriangleSurface, NormalsAndAdjacency) {
  const TriangleSurface s = make_grid("flat", 2, flat);
  EXPECT_EQ(s.num_nodes(), 9);
  EXPECT_EQ(s.num_triangles(), 8);
  for (int t = 0; t < 8; ++t) {
    EXPECT_NEAR((s.triangle_normals().col(t) - Vec3::UnitZ()).norm(), 0, 1e-14);
  }
  // Centre node 4 is shared by 6 triangles (cell diagonals all run a -> c), corner 0 by 2.
  const auto& off = s.node_triangle_offsets();
  EXPECT_EQ(off[5] - off[4], 6);
  EXPECT_EQ(off[1] - off[0], 2);
  EXPECT_EQ(off.back(), 24);
  for (int i = 0; i < 9; ++i) {
    for (int k = off[i]; k < off[i + 1]; ++k) {
      const int t = s.node_triangles()[k];
      EXPECT_TRUE((s.triangles().col(t).array() == i).any());
    }
  }
}

TEST(TriangleSurface, AveragedNodalNormalIsNormalisedArithmeticMean) {
  // Apex of a square pyramid with slope 1 on each of 4 triangles: the face normals are
  // (+-1, 0, 1)/sqrt2 and (0, +-1, 1)/sqrt2; their mean is +z. Corner node 1 has one triangle
  // with normal (0, -1, 1)/sqrt2 and one with (1, 0, 1)/sqrt2: mean (1, -1, 2)/sqrt6.
  Matrix3X x(3, 5);
  x << 0, 1, 1, -1, -1,  //
      0, -1, 1, 1, -1,   //
      1, 0, 0, 0, 0;
  TriConn t(3, 4);
  t << 0, 0, 0, 0,  //
      1, 2, 3, 4,   //
      2, 3, 4, 1;
  const TriangleSurface s("pyramid", x, t);
  EXPECT_NEAR((s.node_normals().col(0) - Vec3::UnitZ()).norm(), 0, 1e-14);
  EXPECT_NEAR((s.node_normals().col(1) - Vec3(1, -1, 2).normalized()).norm(), 0, 1e-14);
  EXPECT_NEAR((s.triangle_normals().col(0) - Vec3(1, 0, 1).normalized()).norm(), 0, 1e-14);
}

/// Checks the edge adjacency of `s` against its definition: a neighbour across edge a of t holds
/// both end nodes of that edge and points back to t across the same edge; -1 exactly when no
/// other triangle, or more than one, holds both nodes. Returns the number of boundary edges.
int check_neighbours(const TriangleSurface& s) {
  const TriConn& tri = s.triangles();
  const TriConn& nb = s.triangle_neighbours();
  EXPECT_EQ(nb.cols(), tri.cols());
  int boundary = 0;
  for (int t = 0; t < s.num_triangles(); ++t) {
    for (int a = 0; a < 3; ++a) {
      const int u = tri(a, t), v = tri((a + 1) % 3, t);
      int holders = 0, holder = -1;
      for (int w = 0; w < s.num_triangles(); ++w) {
        if (w != t && (tri.col(w).array() == u).any() && (tri.col(w).array() == v).any()) {
          ++holders;
          holder = w;
        }
      }
      if (holders != 1) {
        EXPECT_EQ(nb(a, t), -1) << "triangle " << t << " edge " << a;
        ++boundary;
        continue;
      }
      EXPECT_EQ(nb(a, t), holder) << "triangle " << t << " edge " << a;
      // Back across the same edge.
      int back = -1;
      for (int b = 0; b < 3; ++b) {
        const int p = tri(b, holder), q = tri((b + 1) % 3, holder);
        if ((p == u && q == v) || (p == v && q == u)) {
          back = nb(b, holder);
        }
      }
      EXPECT_EQ(back, t) << "triangle " << t << " edge " << a;
    }
  }
  return boundary;
}

TEST(TriangleSurface, EdgeNeighbours) {
  // 3 x 3 cells: 18 triangles, 12 boundary edges, each interior edge seen from both sides.
  const TriangleSurface s = make_grid("flat", 3, flat);
  EXPECT_EQ(check_neighbours(s), 12);
  // Cell (0, 0) holds triangles 0 = (0, 1, 5) and 1 = (0, 5, 4): they meet across the diagonal
  // 0 -> 5 (edge 2 of triangle 0 runs 5 -> 0, edge 0 of triangle 1 runs 0 -> 5); edge 0 of
  // triangle 0 (0 -> 1) lies on the boundary y = 0; edge 1 of triangle 0 (1 -> 5) is shared with
  // cell (1, 0)'s triangle 3 = (1, 6, 5).
  EXPECT_EQ(s.triangle_neighbours()(2, 0), 1);
  EXPECT_EQ(s.triangle_neighbours()(0, 1), 0);
  EXPECT_EQ(s.triangle_neighbours()(0, 0), -1);
  EXPECT_EQ(s.triangle_neighbours()(1, 0), 3);

  // Flipping reorders each flipped triangle's edges; the adjacency follows.
  TriangleSurface flipped = make_grid("flat", 3, flat);
  std::vector<char> flip(18, 0);
  for (int t = 0; t < 18; t += 3) {
    flip[t] = 1;
  }
  flipped.flip_triangles(flip);
  EXPECT_EQ(check_neighbours(flipped), 12);

  // A fin: a third triangle on edge (0, 1) makes that edge non-manifold (no neighbour there).
  Matrix3X x(3, 5);
  x << 0, 1, 0, 0.5, 0.5,  //
      0, 0, 1, -1, 0,      //
      0, 0, 0, 0, 1;
  TriConn t(3, 3);
  t.col(0) << 0, 1, 2;
  t.col(1) << 1, 0, 3;
  t.col(2) << 0, 1, 4;
  const TriangleSurface fin("fin", x, t);
  EXPECT_EQ(fin.triangle_neighbours()(0, 0), -1);
  EXPECT_EQ(check_neighbours(fin), 9);
}

TEST(TriangleSurface, DegenerateTriangleThrowsNamingIt) {
  Matrix3X x(3, 4);
  x << 0, 1, 0, 2,  //
      0, 0, 1, 0,   //
      0, 0, 0, 0;
  TriConn t(3, 2);
  t.col(0) << 0, 1, 2;
  t.col(1) << 0, 1, 3;  // collinear: zero area
  try {
    TriangleSurface("die", x, t);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("die"), std::string::npos) << msg;
    EXPECT_NE(msg.find("triangle 1"), std::string::npos) << msg;
  }
  t.col(1) << 0, 1, 7;  // out of range
  EXPECT_THROW(TriangleSurface("die", x, t), InputError);
}

/// Counts triangles whose normal has the given sign of z (all triangles here are far from
/// vertical, |n_z| > 0.5).
int count_facing(const TriangleSurface& s, double sign) {
  int n = 0;
  for (int t = 0; t < s.num_triangles(); ++t) {
    n += s.triangle_normals()(2, t) * sign > 0.5 ? 1 : 0;
  }
  return n;
}

TriangleSurface randomly_flipped(const TriangleSurface& s, unsigned seed) {
  std::mt19937 rng(seed);
  TriConn t = s.triangles();
  for (int k = 0; k < t.cols(); ++k) {
    if (rng() % 2) {
      std::swap(t(1, k), t(2, k));
    }
  }
  return TriangleSurface(s.name(), s.nodes(), t);
}

TEST(OrientSurface, RandomlyFlippedMeshBecomesConsistentAndFacesTheBlank) {
  const TriangleSurface base = make_grid("punch", 10, bumpy);
  for (double side : {1.0, -1.0}) {
    TriangleSurface s = randomly_flipped(base, side > 0 ? 1 : 2);
    ASSERT_GT(count_facing(s, 1), 20);  // the input really is mixed
    ASSERT_GT(count_facing(s, -1), 20);
    Matrix3X blank(3, 121);
    for (int j = 0; j <= 10; ++j) {
      for (int i = 0; i <= 10; ++i) {
        blank.col(j * 11 + i) = Vec3(i, j, side * 1.5);
      }
    }
    // What was turned over: the seed triangle's component kept its orientation first, the
    // others were turned to agree with it (made_consistent); then the whole component was turned
    // to face the blank if the seed did not (turned_to_blank = all of them).
    const int facing = count_facing(s, side), away = s.num_triangles() - facing;
    const SurfaceOrientation o = orient_surface(s, blank);
    EXPECT_EQ(count_facing(s, side), s.num_triangles()) << "blank on side " << side;
    EXPECT_EQ(o.components, 1);
    if (o.turned_to_blank == 0) {
      EXPECT_EQ(o.made_consistent, away) << "blank on side " << side;
    } else {
      EXPECT_EQ(o.turned_to_blank, s.num_triangles()) << "blank on side " << side;
      EXPECT_EQ(o.made_consistent, facing) << "blank on side " << side;
    }
  }
}

TEST(OrientSurface, EachComponentFacesTheBlank) {
  // Punch above the blank (normals must point down) and die below (up), in one surface.
  const TriangleSurface punch = randomly_flipped(make_grid("p", 6, bumpy, 3.0), 3);
  const TriangleSurface die = randomly_flipped(make_grid("d", 6, bumpy, -3.0), 4);
  Matrix3X x(3, punch.num_nodes() + die.num_nodes());
  x << punch.nodes(), die.nodes();
  TriConn t(3, punch.num_triangles() + die.num_triangles());
  t << punch.triangles(), (die.triangles().array() + punch.num_nodes()).matrix();
  TriangleSurface s("tools", x, t);
  Matrix3X blank(3, 49);
  for (int j = 0; j <= 6; ++j) {
    for (int i = 0; i <= 6; ++i) {
      blank.col(j * 7 + i) = Vec3(i, j, 0.1);
    }
  }
  EXPECT_EQ(orient_surface(s, blank).components, 2);
  for (int k = 0; k < s.num_triangles(); ++k) {
    const double expected = k < punch.num_triangles() ? -1 : 1;
    EXPECT_GT(s.triangle_normals()(2, k) * expected, 0.5) << "triangle " << k;
  }
}

TEST(OrientSurface, MoebiusStripThrowsNamingTheTool) {
  // A strip of n quads around a circle whose cross-section turns by pi: the last quad joins the
  // first with its two edge nodes swapped.
  const int n = 12;
  Matrix3X x(3, 2 * n);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    const Vec3 centre(std::cos(a), std::sin(a), 0);
    const Vec3 across = 0.3 * (std::cos(a / 2) * centre + std::sin(a / 2) * Vec3::UnitZ());
    x.col(2 * i) = centre - across;
    x.col(2 * i + 1) = centre + across;
  }
  TriConn t(3, 2 * n);
  for (int i = 0; i < n; ++i) {
    int a = 2 * i, b = 2 * i + 1, c = 2 * ((i + 1) % n), d = c + 1;
    if (i == n - 1) {
      std::swap(c, d);  // the half twist
    }
    t.col(2 * i) << a, c, d;
    t.col(2 * i + 1) << a, d, b;
  }
  TriangleSurface s("moebius_punch", x, t);
  Matrix3X blank(3, 1);
  blank.col(0) = Vec3(0, 0, 2);
  try {
    orient_surface(s, blank);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("moebius_punch"), std::string::npos) << msg;
    EXPECT_NE(msg.find("orientable"), std::string::npos) << msg;
    // Where the strip meets itself reversed: the centroid of a triangle of the twisted quad,
    // on the unit circle's last segment (between angles 330 and 360 degrees).
    EXPECT_NE(msg.find("comes back reversed at ("), std::string::npos) << msg;
  }
}

TEST(OrientSurface, NonManifoldEdgesAreNamedByTheirEndPoints) {
  // Three triangles on the edge (0, 0, 0) - (1, 0, 0): a fin standing on a flat pair.
  Matrix3X x(3, 5);
  x << 0, 1, 0.5, 0.5, 0.5,  //
      0, 0, 1, -1, 0,        //
      0, 0, 0, 0, 1;
  TriConn t(3, 3);
  t << 0, 1, 0,  //
      1, 0, 1,   //
      2, 3, 4;
  TriangleSurface s("finned_die", x, t);
  Matrix3X blank(3, 1);
  blank.col(0) = Vec3(0.5, 0.5, 2);
  try {
    orient_surface(s, blank);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("tool 'finned_die': the surface is non-manifold: 1 edge is shared by more "
                       "than two triangles (3 triangles on the edge (0, 0, 0) - (1, 0, 0), mm)"),
              std::string::npos)
        << msg;
  }
}

TEST(OrientSurface, ClosedRingWithoutTwistIsOrientable) {
  // The same strip without the half twist (a band): orientable, must not throw.
  const int n = 12;
  Matrix3X x(3, 2 * n);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    x.col(2 * i) = Vec3(std::cos(a), std::sin(a), -0.3);
    x.col(2 * i + 1) = Vec3(std::cos(a), std::sin(a), 0.3);
  }
  TriConn t(3, 2 * n);
  for (int i = 0; i < n; ++i) {
    const int a = 2 * i, b = 2 * i + 1, c = 2 * ((i + 1) % n), d = c + 1;
    t.col(2 * i) << a, c, d;
    t.col(2 * i + 1) << a, d, b;
  }
  TriangleSurface s("band", randomly_flipped(TriangleSurface("band", x, t), 5).nodes(),
                    randomly_flipped(TriangleSurface("band", x, t), 5).triangles());
  Matrix3X blank(3, 1);
  blank.col(0) = Vec3(0, 0, 0);  // inside the band: normals must point inward
  EXPECT_NO_THROW(orient_surface(s, blank));
  for (int k = 0; k < s.num_triangles(); ++k) {
    const Vec3 centroid = (s.nodes().col(s.triangles()(0, k)) + s.nodes().col(s.triangles()(1, k)) +
                           s.nodes().col(s.triangles()(2, k))) /
                          3.0;
    EXPECT_LT(s.triangle_normals().col(k).dot(Vec3(centroid.x(), centroid.y(), 0)), 0)
        << "triangle " << k;
  }
}

}  // namespace
}  // namespace sf
