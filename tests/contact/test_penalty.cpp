// Penalty contact: force law, energy gradient, stiffness and its cap, and the point-mass bounce.
// Sources: the gap and force law of src/contact/penalty_contact.hpp (Wriggers 2002, ch. 2 and 4);
// the bounce closed form (contact time pi sqrt(m/k), restitution 1, peak penetration
// v0 sqrt(m/k)) from /work/shared/REFERENCES.md, "Analytic checks", grade B.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "contact/contact_search.hpp"
#include "contact/penalty_contact.hpp"
#include "core/errors.hpp"
#include "test_meshes.hpp"

namespace sf {
namespace {

TriangleSurface make_flat(double z) {
  return test::make_height_field("die", 4, 4, 0, 4, 0, 4, [z](double, double) { return z; });
}

/// A contact pair and its state.
struct Contact {
  ContactPair pair;
  ContactState state;
};

Contact make_pair(const TriangleSurface& s, int n_nodes, double k, double cutoff,
                  ContactProjection projection = ContactProjection::orthogonal) {
  Contact c;
  c.pair.surface = &s;
  c.pair.search = make_contact_search("modified", s);
  c.pair.stiffness = VectorX::Constant(n_nodes, k);
  c.pair.cutoff = cutoff;
  c.pair.projection = projection;
  if (projection == ContactProjection::interpolated) {
    c.pair.projector = std::make_unique<InterpolatedProjector>(s);
  }
  return c;
}

/// Contact of nodes at rest (no relative motion: frictionless behaviour).
ContactResult contact_at_rest(Contact& c, const Matrix3X& x, const VectorX& h,
                              const Vec3& tool_displacement, Matrix3X& f) {
  const Matrix3X v = Matrix3X::Zero(3, x.cols());
  return compute_penalty_contact(c.pair, c.state, {x, v, h, tool_displacement, Vec3::Zero(), 0.0},
                                 f);
}

TEST(PenaltyContact, ForceIsStiffnessTimesPenetrationAlongNormal) {
  // Flat tool z = 0 (normal +z), half thickness 0.5, k = 100 N/mm, cutoff 2 mm.
  const TriangleSurface s = make_flat(0.0);
  Matrix3X x(3, 5);
  x.col(0) = Vec3(2.3, 1.7, 0.1);   // g = -0.4: f = 40 N up
  x.col(1) = Vec3(1.1, 2.9, 0.6);   // g = +0.1: separated
  x.col(2) = Vec3(3.2, 0.4, -0.3);  // behind the surface, g = -0.8: f = 80 N up
  x.col(3) = Vec3(2.0, 2.0, -3.0);  // far behind (beyond the search radius): ignored
  x.col(4) = Vec3(9.0, 2.0, 0.0);   // off the tool, 5 mm away: ignored
  Contact pair = make_pair(s, 5, 100.0, 2.0);
  const VectorX h = VectorX::Constant(5, 0.5);
  Matrix3X f = Matrix3X::Zero(3, 5);
  const ContactResult r = contact_at_rest(pair, x, h, Vec3::Zero(), f);
  EXPECT_NEAR((f.col(0) - Vec3(0, 0, 40)).norm(), 0, 1e-12);
  EXPECT_EQ(f.col(1).norm(), 0.0);
  EXPECT_NEAR((f.col(2) - Vec3(0, 0, 80)).norm(), 0, 1e-12);
  EXPECT_EQ(f.col(3).norm(), 0.0);
  EXPECT_EQ(f.col(4).norm(), 0.0);
  EXPECT_EQ(r.nodes_in_contact, 2);
  EXPECT_NEAR((r.force_on_tool - Vec3(0, 0, -120)).norm(), 0, 1e-12);
  EXPECT_NEAR(r.energy, 0.5 * 100 * (0.4 * 0.4 + 0.8 * 0.8), 1e-12);

  // The tool moved up by 1 mm: node 0 at z = 1.1 is in the same state as before.
  Matrix3X x2 = x.col(0);
  x2(2, 0) += 1.0;
  Matrix3X f2 = Matrix3X::Zero(3, 1);
  Contact pair1 = make_pair(s, 1, 100.0, 2.0);
  contact_at_rest(pair1, x2, h.head(1), Vec3(0, 0, 1.0), f2);
  EXPECT_NEAR((f2.col(0) - Vec3(0, 0, 40)).norm(), 0, 1e-12);
}

TEST(PenaltyContact, CutoffMustExceedHalfThickness) {
  const TriangleSurface s = make_flat(0.0);
  Contact pair = make_pair(s, 1, 100.0, 0.4);
  Matrix3X x = Vec3(1, 1, 0.1);
  Matrix3X f = Matrix3X::Zero(3, 1);
  EXPECT_THROW(contact_at_rest(pair, x, VectorX::Constant(1, 0.5), Vec3::Zero(), f), InputError);
}

TEST(PenaltyContact, ForceIsMinusGradientOfPenaltyEnergy) {
  // Ridge z = -0.5 |y| (x in [-1, 1]); points in a face region, the ridge-edge region, a vertex
  // region at the end of the ridge, and behind the surface. Central differences, step 1e-6 mm:
  // truncation ~ 1e-12 * curvature terms, round-off ~ 1e-16 / 1e-6; tolerance 1e-6 relative.
  Matrix3X nodes(3, 6);
  nodes << -1, 1, -1, 1, -1, 1,  //
      -1, -1, 0, 0, 1, 1,        //
      -0.5, -0.5, 0, 0, -0.5, -0.5;
  TriConn t(3, 4);
  t << 0, 0, 2, 2,  //
      1, 3, 3, 5,   //
      3, 2, 5, 4;
  const TriangleSurface s("ridge", nodes, t);
  const double k = 7.0;
  const VectorX h = VectorX::Constant(1, 0.2);
  Contact pair = make_pair(s, 1, k, 1.0);
  auto energy_and_force = [&](const Vec3& p, Vec3& force) {
    Matrix3X x = p;
    Matrix3X f = Matrix3X::Zero(3, 1);
    const double e = contact_at_rest(pair, x, h, Vec3::Zero(), f).energy;
    force = f.col(0);
    return e;
  };
  const Vec3 points[] = {Vec3(0.1, 0.4, 0.0), Vec3(0.1, 0.02, 0.15), Vec3(1.05, 0.02, 0.1),
                         Vec3(-0.3, 0.3, -0.3)};
  for (const Vec3& p : points) {
    Vec3 f;
    energy_and_force(p, f);
    ASSERT_GT(f.norm(), 0.01) << "not in contact at " << p.transpose();
    Vec3 grad;
    const double step = 1e-6;
    for (int a = 0; a < 3; ++a) {
      Vec3 dummy;
      Vec3 pp = p, pm = p;
      pp[a] += step;
      pm[a] -= step;
      grad[a] = (energy_and_force(pp, dummy) - energy_and_force(pm, dummy)) / (2 * step);
    }
    EXPECT_NEAR((f + grad).norm(), 0, 1e-6 * f.norm()) << "at " << p.transpose();
  }
}

TEST(PenaltyContact, InterpolatedOnAFlatToolEqualsOrthogonal) {
  // A tilted flat tool: the interpolated normal is the face normal and D the orthogonal distance,
  // so forces and energies agree to round-off.
  const TriangleSurface s = test::make_height_field(
      "plane", 6, 6, -3, 3, -3, 3, [](double x, double y) { return 0.2 * x + 0.1 * y; });
  const int n = 200;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2.5, 2.5), dz(-0.8, 0.8);
  Matrix3X x(3, n);
  for (int i = 0; i < n; ++i) {
    const double px = u(rng), py = u(rng);
    x.col(i) = Vec3(px, py, 0.2 * px + 0.1 * py + dz(rng));
  }
  const VectorX h = VectorX::Constant(n, 0.5);
  Contact orthogonal = make_pair(s, n, 100.0, 1.5, ContactProjection::orthogonal);
  Contact interpolated = make_pair(s, n, 100.0, 1.5, ContactProjection::interpolated);
  Matrix3X fo = Matrix3X::Zero(3, n), fi = Matrix3X::Zero(3, n);
  const ContactResult ro = contact_at_rest(orthogonal, x, h, Vec3::Zero(), fo);
  const ContactResult ri = contact_at_rest(interpolated, x, h, Vec3::Zero(), fi);
  EXPECT_GT(ro.nodes_in_contact, 50);
  EXPECT_EQ(ri.nodes_in_contact, ro.nodes_in_contact);
  EXPECT_EQ(ri.projection_fallbacks, 0);
  EXPECT_NEAR((fi - fo).cwiseAbs().maxCoeff(), 0, 1e-12);
  EXPECT_NEAR(ri.energy, ro.energy, 1e-12 * ro.energy);
}

TEST(PenaltyContact, InterpolatedContactInTheFoldDeadZone) {
  // REFERENCES.md item 2: flange z = 0 (x < 0) meeting a shoulder falling at 40 degrees; a node
  // 0.3 mm from the fold edge inside the wedge of the face normals (no orthogonal projection onto
  // either face) with half thickness 0.5 mm is in contact with both projections. The
  // interpolated force is k (h - D) along n(T), D >= 0.3 (D is a distance to the surface along a
  // line, at least the least distance).
  const double slope = std::tan(40.0 * std::numbers::pi / 180);
  const TriangleSurface s = test::make_height_field(
      "shoulder", 8, 8, -4, 4, -4, 4, [slope](double x, double) { return x > 0 ? -x * slope : 0; });
  const Vec3 dir = (Vec3::UnitZ() + Vec3(slope, 0, 1).normalized()).normalized();
  Matrix3X x = Vec3(Vec3(0, 0.45, 0) + 0.3 * dir);
  const VectorX h = VectorX::Constant(1, 0.5);
  Contact orthogonal = make_pair(s, 1, 100.0, 1.5, ContactProjection::orthogonal);
  Contact interpolated = make_pair(s, 1, 100.0, 1.5, ContactProjection::interpolated);
  Matrix3X fo = Matrix3X::Zero(3, 1), fi = Matrix3X::Zero(3, 1);
  const ContactResult ro = contact_at_rest(orthogonal, x, h, Vec3::Zero(), fo);
  const ContactResult ri = contact_at_rest(interpolated, x, h, Vec3::Zero(), fi);
  EXPECT_EQ(ro.nodes_in_contact, 1);
  EXPECT_EQ(ri.nodes_in_contact, 1);
  EXPECT_EQ(ri.projection_fallbacks, 0);
  EXPECT_NEAR((fo.col(0) - 100.0 * 0.2 * dir).norm(), 0, 1e-12);  // gap -0.2 along p - edge
  EXPECT_GT(fi.col(0).norm(), 0.0);
  EXPECT_LE(fi.col(0).norm(), 100.0 * 0.2 * (1 + 1e-12));
}

TEST(PenaltyContact, InterpolatedForceIsNotAGradient) {
  // The work of the contact force around a closed loop (a 0.15 mm circle in a vertical plane,
  // the node in contact all the way, midpoint rule with 4000 steps) vanishes for a gradient
  // field. Orthogonal: zero to the rule's error; interpolated: clearly not (so the driver must
  // count its contact energy as work, not as 1/2 k g^2).
  const TriangleSurface s = test::make_height_field(
      "warped", 8, 8, -4, 4, -4, 4,
      [](double x, double y) { return 0.8 * std::sin(0.7 * x) * std::cos(0.5 * y); });
  const VectorX h = VectorX::Constant(1, 0.5);
  const Vec3 centre(0.9, 0.35, 0.8 * std::sin(0.7 * 0.9) * std::cos(0.5 * 0.35) + 0.2);
  const double r = 0.15, k = 100.0;
  const int steps = 4000;
  double work[2] = {0, 0};
  for (int m = 0; m < 2; ++m) {
    Contact pair = make_pair(
        s, 1, k, 1.5, m == 0 ? ContactProjection::orthogonal : ContactProjection::interpolated);
    for (int i = 0; i < steps; ++i) {
      const double a0 = 2 * std::numbers::pi * i / steps,
                   a1 = 2 * std::numbers::pi * (i + 1) / steps;
      const double am = 0.5 * (a0 + a1);
      const Vec3 p0 = centre + r * Vec3(std::cos(a0), 0.3 * std::cos(a0), std::sin(a0));
      const Vec3 p1 = centre + r * Vec3(std::cos(a1), 0.3 * std::cos(a1), std::sin(a1));
      const Matrix3X pm = Vec3(centre + r * Vec3(std::cos(am), 0.3 * std::cos(am), std::sin(am)));
      Matrix3X f = Matrix3X::Zero(3, 1);
      ASSERT_EQ(contact_at_rest(pair, pm, h, Vec3::Zero(), f).nodes_in_contact, 1);
      work[m] += f.col(0).dot(p1 - p0);
    }
  }
  const double scale = k * 0.3 * 2 * std::numbers::pi * r;  // |f| x loop length
  std::printf("closed-loop work / (|f| x length): orthogonal %.2e, interpolated %.2e\n",
              work[0] / scale, work[1] / scale);
  EXPECT_LT(std::abs(work[0]), 1e-6 * scale);
  EXPECT_GT(std::abs(work[1]), 1e-4 * scale);
}

TEST(PenaltyStiffness, ShellFormulaAndTimeStepCap) {
  // 2 x 2 unit quads. K = E / (3 (1 - 2 nu)) = 175000 MPa; corner node A = 1/4 mm^2, centre
  // node A = 1 mm^2; largest diagonal sqrt 2 mm.
  Matrix3X x(3, 9);
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      x.col(3 * j + i) = Vec3(i, j, 0);
    }
  }
  QuadConn q(4, 4);
  q.col(0) << 0, 1, 4, 3;
  q.col(1) << 1, 2, 5, 4;
  q.col(2) << 3, 4, 7, 6;
  q.col(3) << 4, 5, 8, 7;
  const VectorX mass = VectorX::Constant(9, 1e-6);  // t
  const double kbulk = 210000.0 / (3 * (1 - 2 * 0.3));
  VectorX k = compute_penalty_stiffness(x, q, TriConn(3, 0), mass, 210000, 0.3, 0.1, 0.0);
  EXPECT_NEAR(k[0], 0.1 * kbulk * 0.25 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(k[4], 0.1 * kbulk * 1.0 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(k[1], 0.1 * kbulk * 0.5 / std::sqrt(2.0), 1e-9);
  // Cap: dt_target 1e-4 s -> k <= m (2 * 0.9 / dt)^2 = 324 N/mm; and the capped spring on the
  // node mass is exactly at the stability limit dt_target = 0.9 * 2 / omega.
  const double dt = 1e-4;
  k = compute_penalty_stiffness(x, q, TriConn(3, 0), mass, 210000, 0.3, 0.1, dt);
  for (int i = 0; i < 9; ++i) {
    EXPECT_NEAR(k[i], 324.0, 1e-9);
    EXPECT_NEAR(0.9 * 2.0 / std::sqrt(k[i] / mass[i]), dt, 1e-15);
  }
  EXPECT_THROW(compute_penalty_stiffness(x, q, TriConn(3, 0), mass, 210000, 0.5, 0.1, dt),
               InputError);
}

struct Bounce {
  double contact_time, restitution, peak_penetration;
};

/// Point mass m (t) with half thickness h = 0.5 mm moving at -v0 (mm/s) onto the flat tool
/// z = 5 mm displaced by (0, 0, -5) (so at z = 0), central differences with step dt (s).
Bounce simulate_bounce(double m, double k, double v0, double dt) {
  const TriangleSurface s = make_flat(5.0);
  Contact pair = make_pair(s, 1, k, 3.0);
  const VectorX h = VectorX::Constant(1, 0.5);
  const Vec3 tool_displacement(0, 0, -5.0);
  Matrix3X x = Vec3(1.3, 2.1, 0.5 + 0.25);  // gap 0.25 mm
  Vec3 v_half(0, 0, -v0);                   // v at t - dt/2
  Matrix3X f(3, 1);
  double t = 0, t_in = -1, t_out = -1, peak = 0;
  double g_prev = x(2, 0) - 0.5;
  for (int n = 0; n < 1000000 && t_out < 0; ++n) {
    f.setZero();
    contact_at_rest(pair, x, h, tool_displacement, f);
    v_half += (dt / m) * f.col(0);
    x.col(0) += dt * v_half;
    t += dt;
    const double g = x(2, 0) - 0.5;
    // Crossing times by linear interpolation between steps.
    if (t_in < 0 && g_prev >= 0 && g < 0) {
      t_in = t - dt + dt * g_prev / (g_prev - g);
    } else if (t_in >= 0 && g_prev < 0 && g >= 0) {
      t_out = t - dt + dt * (-g_prev) / (g - g_prev);
    }
    peak = std::max(peak, -g);
    g_prev = g;
  }
  return {t_out - t_in, v_half.z() / v0, peak};
}

TEST(PenaltyContact, PointMassBounce) {
  // m = 1e-3 t (1 kg), k = 1000 N/mm, v0 = 1000 mm/s: contact time pi sqrt(m/k) = pi ms,
  // restitution 1, peak penetration v0 sqrt(m/k) = 1 mm.
  const double m = 1e-3, k = 1000.0, v0 = 1000.0;
  const double tc = std::numbers::pi * std::sqrt(m / k);
  const double peak = v0 * std::sqrt(m / k);
  double previous_error = 0;
  for (int per_contact : {50, 100, 200}) {
    const Bounce b = simulate_bounce(m, k, v0, tc / per_contact);
    const double e_time = std::abs(b.contact_time / tc - 1);
    std::printf("dt = Tc/%d: contact time error %.2e, restitution - 1 = %.2e, peak error %.2e\n",
                per_contact, e_time, b.restitution - 1, b.peak_penetration / peak - 1);
    EXPECT_LT(e_time, 1e-2);
    EXPECT_NEAR(b.restitution, 1.0, 1e-3);
    EXPECT_NEAR(b.peak_penetration / peak, 1.0, 1e-2);
    if (per_contact > 50) {
      // Second order: halving dt divides the contact-time error by ~4 (at least 3 asked).
      EXPECT_LT(e_time, previous_error / 3) << "dt = Tc/" << per_contact;
    }
    previous_error = e_time;
  }
}

}  // namespace
}  // namespace sf
