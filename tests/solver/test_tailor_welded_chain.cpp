// A tailor-welded blank through the process chain (issue 32, items 1, 3, 5, 6): the formed part
// carries each element's part (format 3), a trim keeps every piece in its parent's part, a second
// case starts from the trimmed part with its parts named in another order and gives the bits of
// one case, and the dynain file gives each element its part's id. On tests/data/twb_strip.geo
// (x in [0, 40] the "inner" part, steel 1.2 mm; [40, 100] the "outer", aluminium 0.8 mm), clamped
// at x = 0, its tip pushed out of plane, cut along y = 7 mm across both parts.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "element/element_block.hpp"
#include "model/build_model.hpp"
#include "results/hdf5_file.hpp"
#include "solver/case_model.hpp"
#include "solver/dynain_writer.hpp"
#include "solver/explicit_driver.hpp"
#include "solver/formed_part.hpp"
#include "support/expect_input_error.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

constexpr double kWeld = 40.0;  // mm, the weld's x
constexpr double kCutY = 7.0;   // mm, the trim line's y

fs::path folder_of(const std::string& name) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / "twb_chain" / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

std::string part_table(const std::string& name, const std::string& group, double thickness,
                       const std::string& material) {
  return fmt::format("[[blank.parts]]\nname = \"{}\"\n{}thickness = {}\nmaterial = \"{}\"\n", name,
                     group.empty() ? "" : fmt::format("group = \"{}\"\n", group), thickness,
                     material);
}

const std::string kMaterials = R"(
[materials.steel]
type = "elastic"
density = 7.85e-9
young = 210000.0
poisson = 0.3
[materials.aluminium]
type = "elastic"
density = 2.7e-9
young = 70000.0
poisson = 0.33
[[boundary]]
group = "clamp"
type = "fixed"
[[load]]
group = "tip"
type = "force"
value = [0.0, 0.0, 0.5]
[control]
land_on_end = false
)";

const std::string kBend = "{name=\"OP10\", kind=\"forming\", end=\"time\", time=1e-4}";
const std::string kCut = fmt::format(
    "{{name=\"OP20-trim\", kind=\"trim\", mode=\"cut\", keep=\"inside\", "
    "line=[[-1.0, -1.0], [101.0, -1.0], [101.0, {0}], [-1.0, {0}]]}}",
    kCutY);
const std::string kBendOn = "{name=\"OP30\", kind=\"forming\", end=\"time\", time=1e-4}";

// The strip's case in `folder`: its blank the strip's mesh (the parts by group), or with
// `formed_part` that part's own mesh (the parts by name, listed outer first).
fs::path write_case(const fs::path& folder, const std::vector<std::string>& operations,
                    const fs::path& formed_part = {}) {
  std::string blank;
  if (formed_part.empty()) {
    blank =
        fmt::format("mesh = \"{}\"\n", (fs::path(SF_TEST_DATA_DIR) / "twb_strip.geo").string()) +
        part_table("inner", "inner", 1.2, "steel") + part_table("outer", "outer", 0.8, "aluminium");
  } else {
    blank = fmt::format("formed_part = \"{}\"\n", formed_part.string()) +
            part_table("outer", "", 0.8, "aluminium") + part_table("inner", "", 1.2, "steel");
  }
  std::string ops;
  for (const std::string& op : operations) {
    ops += (ops.empty() ? "" : ", ") + op;
  }
  const fs::path file = folder / "case.toml";
  std::ofstream(file) << "operations = [" << ops << "]\n[blank]\n" << blank << kMaterials;
  return file;
}

// Bit for bit, NaN included (an elastic law's points keep flow_stress_at = NaN: never yielded).
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](double u, double v) {
           return std::bit_cast<std::uint64_t>(u) == std::bit_cast<std::uint64_t>(v);
         });
}

void run_case(const fs::path& case_file, const fs::path& results) {
  const CaseConfig config = read_case(case_file);
  RunOptions options;
  options.output_directory = results;
  options.checkpoints = false;
  options.rebuild.model = [&config](const BlankMesh& blank) { return build_model(config, &blank); };
  run_explicit(build_case_model(config), options);
}

// The centre of element e of the part's reference mesh.
Vec3 centre(const FormedPart& part, std::size_t e) {
  const ElementBlock block = element_blocks(part.quads, part.triangles).of(static_cast<int>(e));
  Vec3 sum = Vec3::Zero();
  const int count = block.nodes_per_element();
  for (int a = 0; a < count; ++a) {
    sum += part.reference_nodes.col(block.element_nodes(static_cast<int>(e))[a]);
  }
  return sum / count;
}

// Every element of the part is in the part its place says: inner left of the weld, outer right.
void expect_parts_by_place(const FormedPart& part) {
  ASSERT_EQ(part.part_names, (std::vector<std::string>{"inner", "outer"}));
  const auto n = static_cast<std::size_t>(part.quads.cols() + part.triangles.cols());
  ASSERT_EQ(part.element_part.size(), n);
  for (std::size_t e = 0; e < n; ++e) {
    EXPECT_EQ(part.element_part[e], centre(part, e).x() < kWeld ? 0 : 1) << "element " << e;
    EXPECT_DOUBLE_EQ(part.initial_thickness[e], centre(part, e).x() < kWeld ? 1.2 : 0.8) << e;
  }
}

TEST(TailorWeldedChain, TheFormedPartCarriesEachElementsPartThroughACut) {
  const fs::path results = folder_of("one_case");
  run_case(write_case(results, {kBend, kCut}), results);
  const FormedPart bent = read_formed_part(operation_formed_part_path(results, "OP10"));
  expect_parts_by_place(bent);
  EXPECT_EQ(bent.quads.cols(), 20);
  EXPECT_EQ(bent.law, "elastic, elastic");
  const FormedPart cut = read_formed_part(operation_formed_part_path(results, "OP20-trim"));
  expect_parts_by_place(cut);
  // Every element was cut across (one row of 5 x 10 mm quads): the same 20, 7 mm wide now.
  ASSERT_EQ(cut.quads.cols(), 20);
  // The line cuts the part as it stands (bent); where it falls on the reference mesh differs from
  // y = 7 mm by the in-plane strain the bending gave the strip (measured: 7.9e-9 mm at most).
  for (Eigen::Index i = 0; i < cut.reference_nodes.cols(); ++i) {
    EXPECT_LE(cut.reference_nodes(1, i), kCutY + 1e-3);
  }
  // The cut part's thickness field: each piece its parent's, so its part's (within the bending
  // the first operation gave it).
  const std::vector<double>& t = cut.fields.at("shell/thickness");
  for (std::size_t e = 0; e < t.size(); ++e) {
    EXPECT_NEAR(t[e], centre(cut, e).x() < kWeld ? 1.2 : 0.8, 1e-6) << "element " << e;
  }
}

TEST(TailorWeldedChain, ASecondCaseFromTheCutPartWithItsPartsInAnotherOrderGivesTheBitsOfOne) {
  const fs::path one = folder_of("whole_line");
  run_case(write_case(one, {kBend, kCut, kBendOn}), one);
  const fs::path first = folder_of("first");
  run_case(write_case(first, {kBend, kCut}), first);
  const fs::path second = folder_of("second");
  run_case(write_case(second, {kBendOn}, operation_formed_part_path(first, "OP20-trim")), second);

  const FormedPart a = read_formed_part(one / "formed_part.h5");
  const FormedPart b = read_formed_part(second / "formed_part.h5");
  expect_parts_by_place(a);
  // The second case lists outer first: its formed part names the parts in its own order.
  ASSERT_EQ(b.part_names, (std::vector<std::string>{"outer", "inner"}));
  ASSERT_EQ(a.element_part.size(), b.element_part.size());
  for (std::size_t e = 0; e < a.element_part.size(); ++e) {
    EXPECT_EQ(a.part_names[static_cast<std::size_t>(a.element_part[e])],
              b.part_names[static_cast<std::size_t>(b.element_part[e])])
        << "element " << e;
  }
  EXPECT_EQ(b.law, "elastic, elastic");
  ASSERT_EQ(a.reference_nodes, b.reference_nodes);
  ASSERT_EQ(a.quads, b.quads);
  int compared = 0;
  for (const auto& [key, values] : a.fields) {
    if (key.starts_with("operation/")) {
      continue;  // the operation's number and start: the third of one case, the first of two
    }
    EXPECT_TRUE(same_bits(values, b.fields.at(key))) << key << " differs between one case and two";
    ++compared;
  }
  EXPECT_GT(compared, 20);
  EXPECT_GT(a.fields.at("time")[0], 1.5e-4);  // bent on after the cut
  // The tip moved out of plane: the line bent the strip.
  const std::vector<double>& x = a.fields.at("x");
  double tip_z = 0.0;
  for (Eigen::Index i = 0; i < a.reference_nodes.cols(); ++i) {
    if (a.reference_nodes(0, i) == 100.0) {
      tip_z = std::max(tip_z, x[static_cast<std::size_t>(3 * i + 2)]);
    }
  }
  EXPECT_GT(tip_z, 1e-3);
}

// The dynain file's *ELEMENT_SHELL_THICKNESS pid column (columns 9-16 of each element's first
// card, manual field layout), element by element.
std::vector<int> dynain_part_ids(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::vector<int> ids;
  bool in_elements = false;
  bool first_card = true;
  while (std::getline(in, line)) {
    if (line.starts_with("*")) {
      in_elements = line == "*ELEMENT_SHELL_THICKNESS";
      first_card = true;
      continue;
    }
    if (!in_elements || line.starts_with("$")) {
      continue;
    }
    if (first_card) {
      ids.push_back(std::stoi(line.substr(8, 8)));
    }
    first_card = !first_card;
  }
  return ids;
}

TEST(TailorWeldedChain, TheDynainFileGivesEachElementItsPartsId) {
  const fs::path results = folder_of("dynain");
  run_case(write_case(results, {kBend, kCut}), results);
  const FormedPart cut = read_formed_part(operation_formed_part_path(results, "OP20-trim"));
  const fs::path file = results / "dynain.k";
  write_dynain(cut, file);
  const std::vector<int> ids = dynain_part_ids(file);
  ASSERT_EQ(ids.size(), 20u);
  for (std::size_t e = 0; e < ids.size(); ++e) {
    EXPECT_EQ(ids[e], centre(cut, e).x() < kWeld ? 1 : 2) << "element " << e;
  }
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("$   1 = inner\n$   2 = outer\n"), std::string::npos) << text.str();
}

using sf::test::expect_input_error;

// Replaces the first `from` of the case file by `to`.
void edit(const fs::path& file, const std::string& from, const std::string& to) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  in.close();
  std::string s = text.str();
  const std::size_t at = s.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  s.replace(at, from.size(), to);
  std::ofstream(file) << s;
}

TEST(TailorWeldedChain, PartsThatAreNotTheFormedPartsAreRefused) {
  const fs::path results = folder_of("refusals_part");
  run_case(write_case(results, {kBend}), results);
  const fs::path part = formed_part_path(results);
  const fs::path folder = folder_of("refusals");
  const auto build = [](const fs::path& file) { build_case_model(read_case(file)); };
  // A part of another name.
  fs::path file = write_case(folder, {kBendOn}, part);
  edit(file, "name = \"outer\"", "name = \"thin\"");
  expect_input_error([&] { build(file); }, {"formed part", "a part 'outer' the case does not name",
                                            "the case's parts: thin, inner"});
  // One part in the case.
  file = write_case(folder, {kBendOn}, part);
  std::ofstream(file) << "operations = [" << kBendOn << "]\n[blank]\nformed_part = \""
                      << part.string() << "\"\nthickness = 1.0\nmaterial = \"steel\"\n"
                      << kMaterials;
  expect_input_error([&] { build(file); },
                     {"is a blank of parts inner, outer", "[[blank.parts]] for each"});
  // A group on a blank that is the formed part's own mesh, none on a mesh.
  file = write_case(folder, {kBendOn}, part);
  edit(file, "name = \"outer\"\n", "name = \"outer\"\ngroup = \"outer\"\n");
  expect_input_error([&] { read_case(file); }, {"blank.parts[0].group", "formed part's own mesh"});
  file = write_case(folder, {kBend});
  edit(file, "group = \"outer\"\n", "");
  expect_input_error([&] { read_case(file); }, {"blank.parts[1].group", "missing"});
  // A damaged part naming one part twice.
  const fs::path twice = folder / "twice.h5";
  fs::copy_file(part, twice, fs::copy_options::overwrite_existing);
  {
    h5::File f(twice, h5::FileMode::read_write);
    f.write_attribute("/mesh/parts/1", "name", std::string("inner"));
  }
  expect_input_error([&] { read_formed_part(twice); },
                     {"twice.h5", "/mesh/parts/1", "names part 'inner' a second time"});
  // The formed part of a blank of one part, into a case of parts.
  const fs::path one_part = folder_of("refusals_one_part");
  std::ofstream(one_part / "case.toml") << "operations = [" << kBend << "]\n[blank]\nmesh = \""
                                        << (fs::path(SF_TEST_DATA_DIR) / "twb_strip.geo").string()
                                        << "\"\nthickness = 1.0\nmaterial = \"steel\"\n"
                                        << kMaterials;
  run_case(one_part / "case.toml", one_part);
  file = write_case(folder, {kBendOn}, formed_part_path(one_part));
  expect_input_error([&] { build(file); },
                     {"is a blank of one part", "expected a blank of one part"});
}

}  // namespace
}  // namespace sf
