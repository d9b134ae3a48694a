// Imported mesh sources (meshing/mesh_import.hpp through load_gmsh_model): STEP, IGES and BREP
// files of one punch (tests/data/cad/punch.geo: exact surface areas) meshed as triangles, the STEP
// file's unit conversion, scale, curvature refinement and surface selection; STL triangles taken
// as they are (an open hat-shaped die of known area, a binary box), their orientation made
// consistent and a non-manifold edge refused; a planar CAD face meshed as quadrilaterals for a
// blank; Nastran, UNV and VTK sheets with their property ids and groups; and the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <string>

#include "core/errors.hpp"
#include "meshing/chord_error_size.hpp"
#include "meshing/gmsh_reader.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

const fs::path cad_dir = fs::path(SF_TEST_DATA_DIR) / "cad";
constexpr double kPi = std::numbers::pi;

// The punch's surfaces (tests/data/cad/punch.geo), mm^2.
constexpr double kSideArea = 2 * kPi * 25 * 35;
constexpr double kFilletArea = 2 * kPi * 5 * (20 * kPi / 2 + 5);
constexpr double kTopArea = kPi * 25 * 25;
constexpr double kBottomArea = kPi * 20 * 20;
constexpr double kPunchArea = kSideArea + kFilletArea + kTopArea + kBottomArea;

double area(const PartMesh& mesh) {
  double a = 0.0;
  for (Eigen::Index e = 0; e < mesh.triangles.cols(); ++e) {
    const Vec3 p0 = mesh.nodes.col(mesh.triangles(0, e));
    const Vec3 p1 = mesh.nodes.col(mesh.triangles(1, e));
    const Vec3 p2 = mesh.nodes.col(mesh.triangles(2, e));
    a += 0.5 * (p1 - p0).cross(p2 - p0).norm();
  }
  for (Eigen::Index e = 0; e < mesh.quads.cols(); ++e) {
    const Vec3 p0 = mesh.nodes.col(mesh.quads(0, e));
    const Vec3 p1 = mesh.nodes.col(mesh.quads(1, e));
    const Vec3 p2 = mesh.nodes.col(mesh.quads(2, e));
    const Vec3 p3 = mesh.nodes.col(mesh.quads(3, e));
    a += 0.5 * (p2 - p0).cross(p3 - p1).norm();
  }
  return a;
}

PartMesh load_part(const fs::path& file, double size, MeshImportOptions import,
                   bool recombine = false) {
  import.group = "tool";
  return extract_part_mesh(load_gmsh_model(file, size, recombine, {}, import), "tool", "tool");
}

// The message of the InputError that `f` throws ("" if none).
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Flat facets on a curved face fall short of its area by about c^2 / (24 R^2) (chords c on a
// radius R): with 1.5 mm triangles 0.4 % of the 5 mm fillet, 0.02 % of the 25 mm side, 7e-4 of
// the whole punch. Tolerances below are about three times that estimate.
constexpr double kSize = 1.5;  // mm

TEST(MeshImport, StepIgesAndBrepPunchesMeshToTheirExactArea) {
  for (const char* name : {"punch.step", "punch.brep", "punch.iges", "punch_metres.step"}) {
    SCOPED_TRACE(name);
    const PartMesh mesh = load_part(cad_dir / name, kSize, {});
    EXPECT_EQ(mesh.quads.cols(), 0);
    EXPECT_GT(mesh.triangles.cols(), 5000);
    EXPECT_NEAR(area(mesh), kPunchArea, 2e-3 * kPunchArea);
    // Nodes lie on the surfaces: the flat faces exactly, the side within its radius.
    EXPECT_NEAR(mesh.nodes.row(2).maxCoeff(), 40.0, 1e-6);
    EXPECT_NEAR(mesh.nodes.row(2).minCoeff(), 0.0, 1e-6);
    EXPECT_NEAR(mesh.nodes.row(0).maxCoeff(), 25.0, 1e-6);
    std::printf("%-18s %5ld triangles, area %.2f mm^2 (exact %.2f, %.2e)\n", name,
                static_cast<long>(mesh.triangles.cols()), area(mesh), kPunchArea,
                area(mesh) / kPunchArea - 1.0);
  }
}

TEST(MeshImport, ScaleMultipliesLengthsAndSurfacesSelectThePart) {
  MeshImportOptions half;
  half.scale = 0.5;  // with triangles of half the size: the same mesh, scaled
  const PartMesh scaled = load_part(cad_dir / "punch.step", 0.5 * kSize, half);
  EXPECT_NEAR(area(scaled), 0.25 * kPunchArea, 2e-3 * 0.25 * kPunchArea);
  EXPECT_NEAR(scaled.nodes.row(2).maxCoeff(), 20.0, 1e-6);

  MeshImportOptions top;  // surface 3: the top disk (punch.geo)
  top.surfaces = {3};
  EXPECT_NEAR(area(load_part(cad_dir / "punch.step", kSize, top)), kTopArea, 2e-3 * kTopArea);
  top.surfaces = {2, 4};  // the fillet and the bottom, the punch's working face: 0.2 % short
  EXPECT_NEAR(area(load_part(cad_dir / "punch.step", kSize, top)), kFilletArea + kBottomArea,
              6e-3 * (kFilletArea + kBottomArea));

  MeshImportOptions wrong;
  wrong.surfaces = {7};
  const std::string message = error_of([&] { load_part(cad_dir / "punch.step", 3.0, wrong); });
  EXPECT_NE(message.find("surface 7 is not in the file"), std::string::npos) << message;
  EXPECT_NE(message.find("1, 2, 3, 4"), std::string::npos) << message;
}

TEST(MeshImport, CurvatureRefinementPutsMoreTrianglesOnTheFillet) {
  MeshImportOptions fillet;
  fillet.surfaces = {2};
  const PartMesh coarse = load_part(cad_dir / "punch.step", 5.0, fillet);
  fillet.curvature_elements = 24;  // on the fillet's 5 mm radius: at most 2 pi 5 / 24 = 1.3 mm
  const PartMesh fine = load_part(cad_dir / "punch.step", 5.0, fillet);
  EXPECT_GT(fine.triangles.cols(), 4 * coarse.triangles.cols());
  // The finer facets follow the quarter torus closer.
  EXPECT_LT(std::abs(area(fine) - kFilletArea), std::abs(area(coarse) - kFilletArea));
  EXPECT_NEAR(area(fine), kFilletArea, 1e-2 * kFilletArea);  // estimate 0.3 %
}

// The largest and the mean distance (mm) of the mid-points of the triangles' edges from the
// punch's side (surface 1: a cylinder of radius 25) and fillet (surface 2: the tube of radius 5
// about the circle of radius 20 at z = 5): the chords' sagittas. Both ends of every edge lie on
// the surface, so a mid-point's distance from it is the chord's stand-off.
std::pair<double, double> chord_stand_off(const PartMesh& mesh) {
  const auto distance = [](const Vec3& p) {
    const double rho = std::hypot(p.x(), p.y());
    if (p.z() >= 5.0) {
      return std::abs(rho - 25.0);
    }
    return std::abs(std::hypot(rho - 20.0, p.z() - 5.0) - 5.0);
  };
  double largest = 0.0, sum = 0.0;
  for (Eigen::Index e = 0; e < mesh.triangles.cols(); ++e) {
    for (int a = 0; a < 3; ++a) {
      const Vec3 mid = 0.5 * (mesh.nodes.col(mesh.triangles(a, e)) +
                              mesh.nodes.col(mesh.triangles((a + 1) % 3, e)));
      largest = std::max(largest, distance(mid));
      sum += distance(mid);
    }
  }
  return {largest, sum / (3.0 * static_cast<double>(mesh.triangles.cols()))};
}

TEST(MeshImport, ChordErrorBoundsTheFacetsStandOffOnEveryRadius) {
  // The side and the fillet at element_size 5: a 5 mm chord stands 0.125 mm off the 25 mm side
  // and 0.64 mm off the 5 mm fillet. chord_error = 0.02 asks for 2.0 mm chords on the side and
  // 0.89 mm on the fillet. gmsh's frontal mesher accepts edges up to about 1.4 times the size
  // asked for, and a sagitta grows with the chord squared: the largest stand-off is within
  // 1.4^2 e = 2 e, the mean within e. (Measured with gmsh 4.8.4: largest 0.038 mm, from a 2.76 mm
  // chord on the side; at element_size 5 without it 0.61 mm, on the fillet.)
  MeshImportOptions curved;
  curved.surfaces = {1, 2};
  const auto [coarse_largest, coarse_mean] =
      chord_stand_off(load_part(cad_dir / "punch.step", 5.0, curved));
  EXPECT_GT(coarse_largest, 0.3) << "mean " << coarse_mean;  // the fillet's 5 mm chords
  const double e = 0.02;
  curved.chord_error = e;
  const auto [largest, mean] = chord_stand_off(load_part(cad_dir / "punch.step", 5.0, curved));
  EXPECT_LT(largest, 2.0 * e) << "mean " << mean;
  EXPECT_LT(mean, e) << "largest " << largest;
  EXPECT_GT(mean, 0.2 * e) << "not refined far beyond the chord error";
}

TEST(MeshImport, ChordErrorSizeIsTheChordOfThatSagitta) {
  // A chord h of a circle of radius R stands off it by R - sqrt(R^2 - h^2 / 4) (exact).
  for (const double radius : {0.5, 5.0, 250.0}) {
    const double h = chord_error_size(1.0 / radius, 0.01);
    EXPECT_NEAR(radius - std::sqrt(radius * radius - 0.25 * h * h), 0.01, 1e-12 * radius);
  }
  EXPECT_EQ(chord_error_size(0.0, 0.01), std::numeric_limits<double>::infinity());    // flat
  EXPECT_EQ(chord_error_size(200.0, 0.01), std::numeric_limits<double>::infinity());  // R < e
}

TEST(MeshImport, APlanarCadFaceMeshesAsQuadrilateralsForABlank) {
  const PartMesh blank = load_part(cad_dir / "plate.step", 2.0, {}, /*recombine=*/true);
  EXPECT_GT(blank.quads.cols(), 500);
  EXPECT_NEAR(area(blank), 2400.0, 1e-9 * 2400.0);  // a 60 x 40 mm rectangle: exact
  EXPECT_NEAR(blank.nodes.row(2).cwiseAbs().maxCoeff(), 0.0, 1e-12);
}

TEST(MeshImport, StlTrianglesAreTakenAsTheyAre) {
  // The open die: 40 facets of a hat section 40 x 20 mm, 8 mm deep (flats of 10, slopes over 5).
  const double die_area = 2 * 200.0 + 200.0 + 2 * std::hypot(5.0, 8.0) * 20.0;
  const PartMesh die = load_part(cad_dir / "die_open.stl", 0.0, {});
  EXPECT_EQ(die.triangles.cols(), 40);
  EXPECT_EQ(die.quads.cols(), 0);
  EXPECT_NEAR(area(die), die_area, 1e-9 * die_area);
  MeshImportOptions doubled;
  doubled.scale = 2.0;
  EXPECT_NEAR(area(load_part(cad_dir / "die_open.stl", 0.0, doubled)), 4 * die_area,
              1e-9 * die_area);
  // A binary STL: a closed box of 12 facets.
  EXPECT_EQ(load_part(cad_dir / "box_binary.stl", 0.0, {}).triangles.cols(), 12);
}

// Writes an ASCII STL of the given triangles.
void write_stl(const fs::path& file, const std::vector<std::array<Vec3, 3>>& triangles) {
  std::ofstream out(file);
  out << "solid t\n";
  for (const auto& t : triangles) {
    out << " facet normal 0 0 0\n  outer loop\n";
    for (const Vec3& p : t) {
      out << "   vertex " << p(0) << " " << p(1) << " " << p(2) << "\n";
    }
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid t\n";
}

TEST(MeshImport, StlOrientationIsMadeConsistentAndANonManifoldEdgeIsRefused) {
  const fs::path dir = fs::temp_directory_path() / "sf_test_mesh_import_stl";
  fs::create_directories(dir);
  // A unit square as two triangles, the second written the other way round.
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(0, 1, 0);
  write_stl(dir / "flipped.stl", {{a, b, c}, {a, d, c}});
  const PartMesh square = load_part(dir / "flipped.stl", 0.0, {});
  ASSERT_EQ(square.triangles.cols(), 2);
  const auto normal = [&](int e) {
    const Vec3 p0 = square.nodes.col(square.triangles(0, e));
    return Vec3((square.nodes.col(square.triangles(1, e)) - p0)
                    .cross(square.nodes.col(square.triangles(2, e)) - p0));
  };
  EXPECT_GT(normal(0).dot(normal(1)), 0.0) << "orientation made consistent";
  EXPECT_EQ(square.reoriented, 1);
  // Three triangles on one edge (a fin).
  write_stl(dir / "fin.stl", {{a, b, c}, {a, c, d}, {a, c, Vec3(0.5, 0.5, 1.0)}});
  const std::string message = error_of([&] { load_part(dir / "fin.stl", 0.0, {}); });
  EXPECT_NE(message.find("non-manifold"), std::string::npos) << message;
  EXPECT_NE(message.find("mid-point at (0.5, 0.5, 0)"), std::string::npos) << message;
  EXPECT_NE(message.find("fin.stl"), std::string::npos) << message;
  fs::remove_all(dir);
}

TEST(MeshImport, BadSourcesAreRefusedNamingTheFile) {
  std::string message = error_of([] { load_part(cad_dir / "punch.step", 0.0, {}); });
  EXPECT_NE(message.find("element_size"), std::string::npos) << message;
  MeshImportOptions zero;
  zero.scale = 0.0;
  message = error_of([&] { load_part(cad_dir / "punch.step", 3.0, zero); });
  EXPECT_NE(message.find("scale"), std::string::npos) << message;
  message = error_of([] { load_part(cad_dir / "punch.obj", 3.0, {}); });
  EXPECT_NE(message.find("punch.obj"), std::string::npos) << message;
  const fs::path dir = fs::temp_directory_path() / "sf_test_mesh_import_bad";
  fs::create_directories(dir);
  {
    std::ofstream(dir / "bad.step") << "ISO-10303-21;\nthis is not a STEP file\n";
    std::ofstream(dir / "unknown.obj") << "v 0 0 0\n";
  }
  message = error_of([&] { load_part(dir / "bad.step", 3.0, {}); });
  EXPECT_NE(message.find("bad.step"), std::string::npos) << message;
  message = error_of([&] { load_part(dir / "unknown.obj", 3.0, {}); });
  EXPECT_NE(message.find("unknown mesh file extension '.obj'"), std::string::npos) << message;
  fs::remove_all(dir);
}

// The meshes of other codes (tests/data/other_codes): one bent sheet of 2 quads (Nastran property
// 1, UNV physical property 1) and 2 triangles (property 2): 10 x 10 mm quads, triangles of the
// 10 x sqrt(125) mm strip rising 5 mm over 10 mm: total area 200 + 10 sqrt(125) mm^2.
const fs::path other_dir = fs::path(SF_TEST_DATA_DIR) / "other_codes";
const double kSheetArea = 200.0 + 10.0 * std::sqrt(125.0);

TEST(MeshImport, NastranUnvAndVtkSheetsAreReadAsTheyAre) {
  for (const char* name : {"sheet.bdf", "sheet_fixed.nas", "sheet.unv", "sheet.vtk"}) {
    SCOPED_TRACE(name);
    const PartMesh sheet = load_part(other_dir / name, 0.0, {});
    EXPECT_EQ(sheet.quads.cols(), 2);
    EXPECT_EQ(sheet.triangles.cols(), 2);
    EXPECT_NEAR(area(sheet), kSheetArea, 1e-12 * kSheetArea);
  }
  // Nastran's property ids and UNV's physical property numbers are the surfaces.
  for (const char* name : {"sheet.bdf", "sheet.unv"}) {
    SCOPED_TRACE(name);
    MeshImportOptions flange;
    flange.surfaces = {2};
    const PartMesh part = load_part(other_dir / name, 0.0, flange);
    EXPECT_EQ(part.quads.cols(), 0);
    EXPECT_EQ(part.triangles.cols(), 2);
  }
  // Node ids are kept (the Nastran GRID ids).
  const PartMesh bdf = load_part(other_dir / "sheet.bdf", 0.0, {});
  EXPECT_EQ(bdf.gmsh_node_tags.front(), 11u);
  EXPECT_EQ(bdf.gmsh_node_tags.back(), 32u);
}

TEST(MeshImport, UnvGroupsNameTheParts) {
  // Dataset 2477: element groups BLANK (the quads) and FLANGE (the triangles).
  const GmshModel model = load_gmsh_model(other_dir / "sheet_groups.unv", 0.0, false);
  EXPECT_EQ(extract_part_mesh(model, "BLANK", "blank").quads.cols(), 2);
  EXPECT_EQ(extract_part_mesh(model, "FLANGE", "flange").triangles.cols(), 2);
  MeshImportOptions listed;
  listed.surfaces = {1};
  const std::string message =
      error_of([&] { load_gmsh_model(other_dir / "sheet_groups.unv", 0.0, false, {}, listed); });
  EXPECT_NE(message.find("names its parts (BLANK, FLANGE)"), std::string::npos) << message;
}

TEST(MeshImport, FormatsGmshCannotReadAreNamed) {
  const std::string message = error_of([] { load_part(other_dir / "sheet.inp", 0.0, {}); });
  EXPECT_NE(message.find("gmsh 4.8 cannot read Abaqus .inp files"), std::string::npos) << message;
  EXPECT_NE(message.find("sheet.inp"), std::string::npos) << message;
}

}  // namespace
}  // namespace sf
