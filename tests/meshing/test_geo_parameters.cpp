// .geo parameters: numbers set in a .geo before gmsh parses it (load_gmsh_model's `parameters`),
// against element counts known exactly from the transfinite meshes of the test data.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "meshing/gmsh_reader.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

const fs::path data_dir = SF_TEST_DATA_DIR;

// Quadrilaterals of the 2-D group `group`.
long quad_count(const GmshModel& model, const std::string& group) {
  return extract_part_mesh(model, group, "part").quads.cols();
}

// The GeoParameterError that loading `file` with `parameters` throws.
GeoParameterError parameter_error(const fs::path& file, const std::vector<GeoParameter>& p) {
  try {
    load_gmsh_model(file, 0.0, false, p);
  } catch (const GeoParameterError& error) {
    return error;
  }
  ADD_FAILURE() << "no GeoParameterError for " << file;
  return GeoParameterError(99, "");
}

TEST(GeoParameters, WithoutParametersTheFileKeepsItsDefaults) {
  // DefineConstant[ n = 20 ]: 20 x 1 quadrilaterals.
  EXPECT_EQ(quad_count(load_gmsh_model(data_dir / "strip_parameters.geo", 0.0, false), "blank"),
            20);
}

TEST(GeoParameters, AParameterSetsTheMesh) {
  const std::vector<GeoParameter> p = {{"b", 20.0, ""}, {"n", 8.0, ""}};
  const GmshModel model = load_gmsh_model(data_dir / "strip_parameters.geo", 0.0, false, p);
  const PartMesh mesh = extract_part_mesh(model, "blank", "blank");
  EXPECT_EQ(mesh.quads.cols(), 8);                // n = 8 elements along the strip
  EXPECT_EQ(mesh.nodes.cols(), 18);               // (8 + 1) x 2 nodes
  EXPECT_EQ(mesh.nodes.row(1).maxCoeff(), 20.0);  // the width b = 20 mm, exactly
}

TEST(GeoParameters, ValuesDoNotLeakIntoTheNextFile) {
  // gmsh 4.8 keeps -setnumber values for the rest of the process; parameters must not: the
  // next load without them meshes the file's default again (20, not 8).
  load_gmsh_model(data_dir / "strip_parameters.geo", 0.0, false, {{{"n", 8.0, ""}}});
  EXPECT_EQ(quad_count(load_gmsh_model(data_dir / "strip_parameters.geo", 0.0, false), "blank"),
            20);
}

TEST(GeoParameters, AnIncludedFileResolvesAgainstItsOwnFolder) {
  // include_outer.geo includes include_body.geo by a relative path; n = 4 gives 4 x 4 quads.
  const GmshModel model =
      load_gmsh_model(data_dir / "include_outer.geo", 0.0, false, {{{"n", 4.0, ""}}});
  EXPECT_EQ(quad_count(model, "plate"), 16);
}

TEST(GeoParameters, AParameterTheFileDoesNotDefineIsAnError) {
  const GeoParameterError error =
      parameter_error(data_dir / "strip_parameters.geo", {{"n", 8.0, ""}, {"width", 5.0, ""}});
  EXPECT_EQ(error.index(), 1u);  // the second parameter, "width"
  const std::string message = error.what();
  EXPECT_NE(message.find("strip_parameters.geo' does not define width: declare it in the file "
                         "with DefineConstant[ width = <default> ];"),
            std::string::npos)
      << message;
}

TEST(GeoParameters, APlainAssignmentInTheFileIsAnError) {
  // strip.geo assigns n = 20 itself, which would override the value set: refused, not ignored.
  const GeoParameterError error = parameter_error(data_dir / "strip.geo", {{"n", 8.0, ""}});
  EXPECT_EQ(error.index(), 0u);
  const std::string message = error.what();
  EXPECT_NE(message.find("strip.geo' assigns n itself (n = 20 once the file is read, not the 8 "
                         "set): declare it with DefineConstant[ n = 20 ];"),
            std::string::npos)
      << message;
}

TEST(GeoParameters, AMshFileTakesNone) {
  const fs::path msh = fs::path(SF_BINARY_DIR) / "test_output" / "geo_parameters" / "strip.msh";
  fs::create_directories(msh.parent_path());
  write_msh(data_dir / "strip_parameters.geo", 0.0, false, msh, {{{"n", 6.0, ""}}});
  // The .msh holds the mesh the parameters made: 6 quadrilaterals.
  EXPECT_EQ(quad_count(load_gmsh_model(msh, 0.0, false), "blank"), 6);
  try {
    load_gmsh_model(msh, 0.0, false, {{{"n", 6.0, ""}}});
    ADD_FAILURE() << "no InputError for parameters of a .msh";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("a .msh file is read as it is"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace sf
