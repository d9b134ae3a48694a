// The formability result fields (solver/formability_output.hpp; docs/formability.md) of a blank
// of quadrilaterals and triangles in a tilted plane under a homogeneous in-plane stretch l1 along
// a direction at 0.5 rad to its edges and l2 across, thinned to t0 / (l1 l2) (constant volume),
// then turned rigidly. Closed forms: every element's major and minor true strains at every
// surface are ln l1 and ln l2, its thinning 100 (1 - 1 / (l1 l2)) per cent, its margin the
// Keeler-Brazier curve's major strain at ln l2 minus ln l1, its zone the one these give, its
// wrinkle indicator max(0, -(ln l1 + ln l2)). Tolerance 1e-12: the strains are exact for a
// homogeneous deformation of flat elements, to rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "case_fixture.hpp"
#include "solver/formability_output.hpp"

namespace sf {
namespace {

// A plane through the origin tilted by z = 0.3 x + 0.2 y: a recombined (quadrilateral) surface
// beside a triangulated one, sharing the line x = 10.
const char* kTiltedBlank = R"(
Point(1) = {0, 0, 0}; Point(2) = {10, 0, 3}; Point(3) = {10, 8, 4.6}; Point(4) = {0, 8, 1.6};
Point(5) = {17, 0, 5.1}; Point(6) = {17, 8, 6.7};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 3};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
Mesh.MeshSizeMax = 2.5;
Recombine Surface{1};
Physical Surface("blank") = {1, 2};
)";

const char* kCase = R"(thickness = 1.0
material = "steel"
[materials.steel]
density = 7.85e-9
young = 210000.0
poisson = 0.3
[materials.steel.hardening]
law = "swift"
K = 550.0
eps0 = 0.01
n = 0.2
[control]
end_time = 1e-4
)";

// The blank of `element` meshing ("as_meshed": the .geo's recombined surface beside its
// triangulated one; "quad": every surface recombined) stretched as the file's comment says.
void check_homogeneous_stretch(const std::string& name, const std::string& element, bool mixed) {
  const Model model =
      build_model(test::write_case(name, kTiltedBlank, "element = \"" + element + "\"\n" + kCase));
  const ShellPart& part = model.blank.part;
  ASSERT_GT(part.quads.cols(), 0);
  if (mixed) {
    ASSERT_GT(part.triangles.cols(), 0);
  }
  // The plane's orthonormal axes, and the stretch along a (0.5 rad from the first axis) and b.
  const Vec3 e1 = Vec3(10, 0, 3).normalized();
  const Vec3 normal = e1.cross(Vec3(0, 8, 1.6)).normalized();
  const Vec3 e2 = normal.cross(e1);
  const Vec3 a = std::cos(0.5) * e1 + std::sin(0.5) * e2;
  const Vec3 b = normal.cross(a);
  const double l1 = 1.3, l2 = 0.95, t0 = 1.0;
  const Mat3 stretch =
      l1 * a * a.transpose() + l2 * b * b.transpose() + normal * normal.transpose();
  const Mat3 turn = Eigen::AngleAxisd(0.8, Vec3(1, 2, -1).normalized()).toRotationMatrix();
  const Matrix3X x = ((turn * stretch) * model.blank.mesh.nodes).colwise() + Vec3(3, -2, 7);
  const int n = element_count(part);
  const std::vector<double> thickness(static_cast<std::size_t>(n), t0 / (l1 * l2));

  FormabilityFields fields;
  FormabilityEvaluator(model).evaluate(model, x, thickness, fields);

  const double major = std::log(l1), minor = std::log(l2);
  const double flc = keeler_brazier_curve(0.2, t0).major_at(minor);
  const double thinning = 100.0 * (1.0 - 1.0 / (l1 * l2));
  const auto zone = formability_zone(major, minor, flc - major, thinning, FormabilityConfig{});
  // The stretch was chosen to land between the curve and the safety margin.
  ASSERT_EQ(zone, FormabilityZone::risk_of_cracks);
  for (int e = 0; e < n; ++e) {
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_NEAR(fields.major[k][e], major, 1e-12) << "element " << e << " surface " << k;
      EXPECT_NEAR(fields.minor[k][e], minor, 1e-12) << "element " << e << " surface " << k;
    }
    EXPECT_NEAR(fields.thinning_percent[e], thinning, 1e-12) << e;
    EXPECT_NEAR(fields.flc_margin[e], flc - major, 1e-12) << e;
    EXPECT_EQ(fields.zone[e], static_cast<double>(zone)) << e;
    EXPECT_EQ(fields.wrinkle_indicator[e], 0.0) << e;  // ln l1 + ln l2 > 0
  }
  // A compression across beyond the stretch along: the indicator is the thickening strain.
  const Mat3 drawn =
      1.05 * a * a.transpose() + 0.9 * b * b.transpose() + normal * normal.transpose();
  FormabilityEvaluator(model).evaluate(model, drawn * model.blank.mesh.nodes,
                                       std::vector<double>(static_cast<std::size_t>(n), t0 / 0.945),
                                       fields);
  const double thickening = -(std::log(1.05) + std::log(0.9));
  for (int e = 0; e < n; ++e) {
    EXPECT_NEAR(fields.wrinkle_indicator[e], thickening, 1e-12) << e;
    EXPECT_EQ(fields.zone[e], static_cast<double>(FormabilityZone::wrinkling_tendency)) << e;
  }
}

TEST(FormabilityFields, HomogeneousStretchOfATiltedMixedMesh) {
  check_homogeneous_stretch("formability_fields_mixed", "as_meshed", true);
}

// The same with every surface recombined: gmsh's Frontal-Delaunay for quads crashed on this
// unstructured blank (gmsh 4.8.4); the triangles recombined by Blossom are quadrilaterals.
TEST(FormabilityFields, HomogeneousStretchOfARecombinedUnstructuredMesh) {
  check_homogeneous_stretch("formability_fields_quads", "quad", false);
}

}  // namespace
}  // namespace sf
