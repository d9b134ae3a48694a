// read_case: CAD and STL mesh sources and their keys (scale, curvature_elements, surfaces), each
// error naming the case file, the line and the dotted key, and the resolved-case round trip.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "casefile/case_config.hpp"
#include "casefile/read_case_fixture.hpp"

namespace {

using namespace sf_test;

// kMinimal with its blank's mesh line replaced by `mesh_lines`.
std::string with_blank_mesh(std::string_view mesh_lines) {
  return replaced(kMinimal, "mesh = \"blank.geo\"\n", std::string(mesh_lines));
}

class ReadCaseMeshSources : public ReadCase {
 protected:
  void SetUp() override {
    ReadCase::SetUp();
    for (const char* mesh : {"blank.step", "die.stl", "punch.IGS", "part.brep"}) {
      std::ofstream(dir_ / mesh) << "";
    }
  }
};

TEST_F(ReadCaseMeshSources, CadAndStlSourcesReadTheirKeys) {
  const sf::CaseConfig c = sf::read_case(write_case(with_blank_mesh(
      "mesh = \"blank.step\"\nelement_size = 2.5\nscale = 1000\ncurvature_elements = 24\n"
      "surfaces = [3, 1]\n")));
  const sf::MeshSourceConfig& m = c.blank.mesh;
  EXPECT_EQ(m.file.filename(), "blank.step");
  EXPECT_EQ(m.scale, 1000.0);
  EXPECT_EQ(m.curvature_elements, 24);
  EXPECT_EQ(m.surfaces, (std::vector<int>{3, 1}));
  // An STL takes scale and surfaces; upper-case extensions are accepted.
  const sf::CaseConfig d = sf::read_case(
      write_case(with_blank_mesh("mesh = \"die.stl\"\nscale = 0.5\nsurfaces = [1]\n")));
  EXPECT_EQ(d.blank.mesh.scale, 0.5);
  EXPECT_NO_THROW(
      sf::read_case(write_case(with_blank_mesh("mesh = \"punch.IGS\"\nelement_size = 2\n"))));
}

TEST_F(ReadCaseMeshSources, KeysOutsideTheirFormatsAreErrors) {
  std::string text = with_blank_mesh("mesh = \"blank.step\"\n");
  expect_error(text, 0, {"blank.element_size", "a CAD file has no mesh sizes"});
  text = with_blank_mesh("mesh = \"blank.geo\"\nscale = 2\n");
  expect_error(text, line_of(text, "scale = 2"), {"blank.scale", "sets its own lengths"});
  text = with_blank_mesh("mesh = \"die.stl\"\ncurvature_elements = 12\n");
  expect_error(text, line_of(text, "curvature_elements"),
               {"blank.curvature_elements", "CAD mesh source"});
  text = with_blank_mesh("mesh = \"die.msh\"\nsurfaces = [1]\n");
  expect_error(text, line_of(text, "surfaces"), {"blank.surfaces", "physical groups"});
  text = with_blank_mesh("mesh = \"die.stl\"\nsurfaces = [1.5]\n");
  expect_error(text, line_of(text, "surfaces"), {"blank.surfaces", "whole surface tags"});
  text = with_blank_mesh("mesh = \"die.stl\"\nscale = 0\n");
  expect_error(text, line_of(text, "scale = 0"), {"blank.scale", "> 0"});
  std::ofstream(dir_ / "blank.obj") << "";
  text = with_blank_mesh("mesh = \"blank.obj\"\n");
  expect_error(text, line_of(text, "blank.obj"), {"blank.mesh", ".step", ".stl"});
}

TEST_F(ReadCaseMeshSources, ImportKeysRoundTripThroughTheResolvedCase) {
  const std::string text = with_blank_mesh(
      "mesh = \"part.brep\"\nelement_size = 1.5\nscale = 25.4\ncurvature_elements = 16\n"
      "surfaces = [2, 4]\n");
  const sf::CaseConfig a = sf::read_case(write_case(text));
  const std::string resolved = sf::format_resolved_case(a);
  const sf::CaseConfig b = sf::read_case(write_case(resolved, "again.toml"));
  const auto body = [](const std::string& t) { return t.substr(t.find("\ntitle")); };
  EXPECT_EQ(body(sf::format_resolved_case(b)), body(resolved));
  EXPECT_EQ(b.blank.mesh.scale, 25.4);
  EXPECT_EQ(b.blank.mesh.curvature_elements, 16);
  EXPECT_EQ(b.blank.mesh.surfaces, (std::vector<int>{2, 4}));
}

}  // namespace
