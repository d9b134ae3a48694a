// A drawn part trimmed and drawn on (issue 32, item 3, work in progress): the square cup drawn to
// 2 mm, its flange's outer ring trimmed off (solver/trim.hpp), the model built from the trimmed
// part's own mesh (build_model with a BlankMesh) and the draw continued from the trimmed part's
// state to 3 mm.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "casefile/case_config.hpp"
#include "core/errors.hpp"
#include "model/build_model.hpp"
#include "part_measures.hpp"
#include "results/hdf5_file.hpp"
#include "solver/case_model.hpp"
#include "solver/explicit_driver.hpp"
#include "solver/formed_part.hpp"
#include "solver/trim.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

fs::path output_folder(const std::string& name) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / "trim_chain" / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

CaseConfig cup(double stroke) {
  // The draw-in probes sit on the blank's outer edge, which the trim takes away.
  return read_case(
      fs::path(SF_SOURCE_DIR) / "cases/square_cup_aluminium/case.toml",
      CaseOptions{.set = {"draw_in=[]"}, .stroke = stroke, .end_time = {}, .search = {}});
}

TEST(TrimChain, ADrawTrimmedAndDrawnOn) {
  const fs::path first = output_folder("draw");
  RunOptions options;
  options.output_directory = first;
  options.checkpoints = false;
  const Model drawn = build_model(cup(2.0));
  run_explicit(drawn, options);
  const FormedPart part = read_formed_part(formed_part_path(first));

  // Keep what lies within 60 mm of the symmetry planes (the blank reaches 75 mm).
  TrimSummary summary;
  const TrimOutline keep = TrimOutline::polyline(
      {Vec3(-1.0, -1.0, 0.0), Vec3(60.0, -1.0, 0.0), Vec3(60.0, 60.0, 0.0), Vec3(-1.0, 60.0, 0.0)},
      Vec3(0.0, 0.0, -1.0), true);
  auto trimmed = std::make_shared<const FormedPart>(trim_by_removal(part, keep, &summary));
  EXPECT_GT(summary.elements_removed, 0);
  EXPECT_EQ(summary.piece_elements.size(), 1u);
  const BlankMesh mesh = blank_mesh_of(*trimmed);
  const Model model = build_model(cup(3.0), &mesh);
  EXPECT_EQ(model.blank.mesh.nodes.cols(), trimmed->reference_nodes.cols());
  // Uniform sheet: the mass goes with the area kept.
  EXPECT_LT(model.blank.physical_mass, drawn.blank.physical_mass);

  RunOptions on;
  on.output_directory = output_folder("drawn_on");
  on.checkpoints = false;
  on.start_part = trimmed;
  SolutionState s;
  run_explicit(model, on, &s);
  EXPECT_NEAR(s.tools[0].travel, 3.0, 1e-9);
  EXPECT_GT(s.time, trimmed->fields.at("time")[0]);
  // Every kept element's plastic strain came with it and only grew.
  const std::vector<double>& before = trimmed->fields.at("shell/eps_p");
  ASSERT_EQ(before.size(), s.shell.eps_p.size());
  for (std::size_t k = 0; k < before.size(); ++k) {
    ASSERT_GE(s.shell.eps_p[k], before[k]) << k;
  }
}

// The same line as a case's operation: the cup drawn to 2 mm, trimmed, drawn on to 3 mm (the
// punch restarting its ramp from where it stands, as after any operation it stood still in).
const std::string kTrimChain =
    "operations=[{name=\"OP10\", kind=\"forming\", stroke=2.0}, "
    "{name=\"OP20-trim\", kind=\"trim\", line=[[-1, -1], [60, -1], [60, 60], [-1, 60]]}, "
    "{name=\"OP30\", kind=\"forming\", stroke=3.0}]";

CaseConfig cup_with(const std::vector<std::string>& set) {
  return read_case(fs::path(SF_SOURCE_DIR) / "cases/square_cup_aluminium/case.toml",
                   CaseOptions{.set = set, .stroke = {}, .end_time = {}, .search = {}});
}

TEST(TrimChain, ATrimOperationTrimsThePartAsItStandsAndTheRunGoesOnInTheSameResults) {
  const CaseConfig config = cup_with({"control.stroke=0", kTrimChain});
  const Model model = build_model(config);
  const fs::path folder = output_folder("in_case");
  RunOptions options;
  options.output_directory = folder;
  options.checkpoints = false;
  options.rebuild.model = [&config](const BlankMesh& blank) { return build_model(config, &blank); };
  SolutionState s;
  const RunSummary summary = run_explicit(model, options, &s);

  // The trimmed part is the first operation's part trimmed by the same line, field for field.
  const FormedPart drawn = read_formed_part(operation_formed_part_path(folder, "OP10"));
  const TrimOutline keep = TrimOutline::polyline(
      {Vec3(-1.0, -1.0, 0.0), Vec3(60.0, -1.0, 0.0), Vec3(60.0, 60.0, 0.0), Vec3(-1.0, 60.0, 0.0)},
      Vec3(0.0, 0.0, -1.0), true);
  TrimSummary removed;
  const FormedPart expected = trim_by_removal(drawn, keep, &removed);
  const FormedPart trimmed = read_formed_part(operation_formed_part_path(folder, "OP20-trim"));
  EXPECT_EQ(trimmed.quads, expected.quads);
  for (const char* key : {"x", "v", "shell/eps_p", "shell/sxx", "shell/thickness", "time"}) {
    EXPECT_EQ(trimmed.fields.at(key), expected.fields.at(key)) << key;
  }
  // The trimmed part as a file of its own: what it lacks (the forces, masses and offsets the
  // next model makes, the contact history) listed, and read back as it was.
  const fs::path by_hand = folder / "trimmed_by_hand.h5";
  write_formed_part(by_hand, expected);
  const FormedPart back = read_formed_part(by_hand);
  EXPECT_EQ(back.fields, expected.fields);
  EXPECT_EQ(back.quads, expected.quads);
  EXPECT_EQ(back.groups, expected.groups);
  EXPECT_FALSE(back.fields.contains("f_int"));
  {
    h5::File h5(by_hand, h5::FileMode::read_write);
    const std::string left_out = h5.read_attribute_string("/state", "left_out");
    EXPECT_NE(left_out.find("f_int"), std::string::npos) << left_out;
    EXPECT_NE(left_out.find("contacts/0/stick_force"), std::string::npos) << left_out;
    h5.write_attribute("/state", "left_out", std::string("mass"));  // the rest unlisted
  }
  try {
    read_formed_part(by_hand);
    ADD_FAILURE() << "a part lacking an unlisted field was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no entry /state/"), std::string::npos) << e.what();
  }

  ASSERT_EQ(s.shell.eps_p.size(), expected.fields.at("shell/eps_p").size());
  for (std::size_t k = 0; k < s.shell.eps_p.size(); ++k) {
    ASSERT_GE(s.shell.eps_p[k], expected.fields.at("shell/eps_p")[k]) << k;  // drawn on
  }
  EXPECT_NEAR(s.tools[0].travel, 3.0, 1e-9);

  // One summary over the three operations; the trim took no time.
  ASSERT_EQ(summary.operations.size(), 3u);
  const OperationRecord& trim = summary.operations[1];
  EXPECT_EQ(trim.kind, "trim");
  EXPECT_EQ(trim.start_time, trim.end_time);
  EXPECT_EQ(trim.start_time, summary.operations[0].end_time);
  EXPECT_NE(trim.ended_by.find(fmt::format("{} of {} elements", removed.elements_removed,
                                           removed.elements_before)),
            std::string::npos)
      << trim.ended_by;
  EXPECT_LT(std::abs(summary.energies.balance_error()), 1e-3);
  // The draw-in probes sat on the edge the trim took away.
  for (const DrawInResult& d : summary.draw_ins) {
    EXPECT_TRUE(std::isnan(d.computed)) << d.name;
  }

  // One results file: the frames after the trim have the trimmed mesh.
  const h5::File file(folder / "results.h5", h5::FileMode::read_only);
  EXPECT_EQ(file.read_attribute_string("/operations/1", "kind"), "trim");
  EXPECT_EQ(file.shape("/parts/blank/topologies/1/connectivity").at(0),
            static_cast<hsize_t>(expected.quads.cols()));
  const int first_trimmed = file.read_attribute_int("/parts/blank/topologies/1", "first_frame");
  EXPECT_EQ(first_trimmed, summary.operations[0].last_frame + 1);
  EXPECT_EQ(
      file.read_attribute_int(
          "/parts/blank/frames/" + frame_group_name(summary.operations[2].last_frame), "topology"),
      1);
}

// Distance (mm) from (x, y) to the punch seen from above: the NUMISHEET'93 square punch, 70 x 70
// mm with a plan corner radius of 10 mm (cases/square_cup_aluminium/punch.geo), centred on the
// axis (0 inside).
double punch_outline_distance(double x, double y) {
  const double qx = std::abs(x) - 25.0, qy = std::abs(y) - 25.0;
  return std::max(std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) - 10.0, 0.0);
}

// Element centres (mm) of a part as it stands, quads then triangles.
std::vector<Vec3> centres(const FormedPart& part) {
  const std::vector<double>& x = part.fields.at("x");
  std::vector<Vec3> out;
  for (Eigen::Index e = 0; e < part.quads.cols(); ++e) {
    Vec3 c = Vec3::Zero();
    for (int a = 0; a < 4; ++a) {
      const int n = part.quads(a, e);
      c += Vec3(x[3 * n], x[3 * n + 1], x[3 * n + 2]) / 4.0;
    }
    out.push_back(c);
  }
  EXPECT_EQ(part.triangles.cols(), 0);
  return out;
}

// The square cup drawn to 2 mm, trimmed 12 mm outside the punch (the trim's further keys
// `trim_keys`), drawn on to 2.2 mm; the results folder.
fs::path draw_trim_by_punch_and_draw_on(const std::string& name, const std::string& trim_keys) {
  const CaseConfig config =
      cup_with({"control.stroke=0",
                "operations=[{name=\"OP10\", kind=\"forming\", stroke=2.0}, {name=\"OP20-trim\", "
                "kind=\"trim\", line_tool=\"punch\", line_offset=12.0" +
                    trim_keys + "}, {name=\"OP30\", kind=\"forming\", stroke=2.2}]"});
  const Model model = build_model(config);
  EXPECT_EQ(model.tools[static_cast<std::size_t>(model.operations[1].trim_tool)].name, "punch");
  EXPECT_EQ(model.operations[1].trim_cut, trim_keys.find("cut") != std::string::npos);
  const fs::path folder = output_folder(name);
  RunOptions options;
  options.output_directory = folder;
  options.checkpoints = false;
  options.rebuild.model = [&config](const BlankMesh& blank) { return build_model(config, &blank); };
  run_explicit(model, options);
  return folder;
}

TEST(TrimChain, ATrimByThePunchsOutlineKeepsWhatLiesWithinTheOffsetOfIt) {
  // The flange trimmed 12 mm outside the punch (3.5 mm outside the die's 8 mm profile radius,
  // whose opening is 74 x 74 mm).
  const double offset = 12.0;
  const fs::path folder = draw_trim_by_punch_and_draw_on("punch_outline", "");

  // Against the exact outline: kept where the centre lies within the offset of the punch (the
  // punch's meshed plan corner stands within 0.05 mm of its circle: 2 mm chords on 10 mm).
  const FormedPart drawn = read_formed_part(operation_formed_part_path(folder, "OP10"));
  const FormedPart trimmed = read_formed_part(operation_formed_part_path(folder, "OP20-trim"));
  std::vector<Vec3> expected;
  int near_the_line = 0;
  for (const Vec3& c : centres(drawn)) {
    const double d = punch_outline_distance(c.x(), c.y());
    ASSERT_GT(std::abs(d - offset), 0.05) << "a centre on the line: " << c.transpose();
    near_the_line += std::abs(d - offset) < 2.0;
    if (d < offset) {
      expected.push_back(c);
    }
  }
  EXPECT_GT(near_the_line, 20);  // the line crosses the mesh, not a gap in it
  EXPECT_LT(expected.size(), static_cast<std::size_t>(drawn.quads.cols()));
  EXPECT_EQ(centres(trimmed), expected);
}

TEST(TrimChain, ACutByThePunchsOutlinePutsThePartsEdgeOnTheOffsetLine) {
  // The same trim cutting cleanly (solver/trim_cut.hpp), then drawn on over the mixed mesh of
  // quads and the cut's triangles.
  const double offset = 12.0;
  const fs::path folder = draw_trim_by_punch_and_draw_on("punch_outline_cut", ", mode=\"cut\"");
  // The exact line lies within 0.05 mm of the meshed punch's (its plan corner: 2 mm chords on
  // 10 mm); the cut's nodes lie on the meshed one.
  const double meshed = 0.05;
  const FormedPart trimmed = read_formed_part(operation_formed_part_path(folder, "OP20-trim"));
  for (int n = 0; n < trimmed.reference_nodes.cols(); ++n) {
    const Vec3 x = test::node_at(trimmed, n);
    EXPECT_LE(punch_outline_distance(x.x(), x.y()), offset + meshed) << "node " << n;
  }
  int on_line = 0;
  for (const auto& [a, b] : test::free_edges(trimmed)) {
    for (const int n : {a, b}) {
      const Vec3 x = test::node_at(trimmed, n);
      if (std::min(x.x(), x.y()) > 1e-9) {  // not on a symmetry plane
        EXPECT_NEAR(punch_outline_distance(x.x(), x.y()), offset, meshed) << "node " << n;
        ++on_line;
      }
    }
  }
  EXPECT_GT(on_line, 20);
  // Its area seen along z: the quarter of the square [-25, 25]^2 grown by 22 mm, less the
  // segments between the line's nodes on the 22 mm arc (2.5 mm elements: sagitta 0.036 mm, at
  // most 2/3 of it times the 34.6 mm arc, 0.8 mm^2) and the meshed punch's (at most 0.05 mm
  // times the arc, 1.7 mm^2).
  const double r = 10.0 + offset;  // the punch's corner radius is 10 mm
  const double area = 25.0 * 25.0 + 2.0 * 25.0 * r + std::acos(-1.0) * r * r / 4.0;
  EXPECT_NEAR(test::projected_area(trimmed), area, 0.8 + meshed * std::acos(-1.0) * r / 2.0);
}

// The cup's case for a second case of a chain: its blank's mesh keys replaced by the formed part
// `part` (whose own mesh the blank then is), its tools' meshes by their absolute paths.
fs::path case_from_part(const fs::path& folder, const fs::path& part) {
  const fs::path cup_folder = fs::path(SF_SOURCE_DIR) / "cases/square_cup_aluminium";
  std::ifstream in(cup_folder / "case.toml");
  std::stringstream text;
  text << in.rdbuf();
  std::string toml = text.str();
  const auto replace = [&toml](const std::string& from, const std::string& to) {
    const std::size_t at = toml.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    toml.replace(at, from.size(), to);
  };
  replace("mesh = \"blank.geo\"\ngroup = \"blank\"\nelement_size = 2.5          # mm\n",
          fmt::format("formed_part = \"{}\"\n", part.string()));
  for (const std::string tool : {"punch", "die", "holder"}) {
    replace(fmt::format("mesh = \"{}.geo\"", tool),
            fmt::format("mesh = \"{}\"", (cup_folder / (tool + ".geo")).string()));
  }
  const fs::path file = folder / "case.toml";
  std::ofstream(file) << toml;
  return file;
}

TEST(TrimChain, ASecondCaseFromTheTrimmedPartGivesTheBitsOfOneCase) {
  // One case: drawn to 2 mm, cut 12 mm outside the punch, drawn on to 2.2 mm. Two cases: the
  // first draws and cuts, the second starts from the trimmed part's file, its blank the part's
  // own mesh (no blank.mesh), and draws on.
  const std::string draw = "{name=\"OP10\", kind=\"forming\", stroke=2.0}";
  const std::string cut =
      "{name=\"OP20-trim\", kind=\"trim\", line_tool=\"punch\", line_offset=12.0, mode=\"cut\"}";
  const std::string draw_on = "{name=\"OP30\", kind=\"forming\", stroke=2.2}";
  const auto run_case = [](const CaseConfig& config, const fs::path& folder) {
    RunOptions options;
    options.output_directory = folder;
    options.checkpoints = false;
    options.rebuild.model = [&config](const BlankMesh& blank) {
      return build_model(config, &blank);
    };
    run_explicit(build_case_model(config), options);
  };
  const fs::path one = output_folder("one_case");
  run_case(cup_with({"control.stroke=0", "draw_in=[]",
                     "operations=[" + draw + ", " + cut + ", " + draw_on + "]"}),
           one);
  const fs::path first = output_folder("first_case");
  run_case(cup_with({"control.stroke=0", "draw_in=[]", "operations=[" + draw + ", " + cut + "]"}),
           first);
  const fs::path second = output_folder("second_case");
  const CaseConfig config = read_case(
      case_from_part(second, operation_formed_part_path(first, "OP20-trim")),
      CaseOptions{.set = {"control.stroke=0", "draw_in=[]", "operations=[" + draw_on + "]"},
                  .stroke = {},
                  .end_time = {},
                  .search = {}});
  EXPECT_TRUE(config.blank.mesh.file.empty());
  run_case(config, second);

  const FormedPart a = read_formed_part(one / "formed_part.h5");
  const FormedPart b = read_formed_part(second / "formed_part.h5");
  ASSERT_EQ(a.reference_nodes, b.reference_nodes);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_GT(a.triangles.cols(), 0);  // the cut's
  ASSERT_EQ(a.fields.size(), b.fields.size());
  int compared = 0;
  for (const auto& [key, values] : a.fields) {
    if (key.starts_with("operation/")) {
      continue;  // the operation's number and start: the third of one case, the first of two
    }
    EXPECT_EQ(values, b.fields.at(key)) << key << " differs between one case and two";
    ++compared;
  }
  EXPECT_GT(compared, 100);
  EXPECT_GT(a.fields.at("time")[0],
            read_formed_part(operation_formed_part_path(first, "OP20-trim")).fields.at("time")[0]);
  // Without [[operations]] the tools the trim left standing would stay: refused. Without a mesh,
  // the blank's mesh keys are refused.
  const fs::path plain = output_folder("plain_case");
  const fs::path plain_case = case_from_part(plain, operation_formed_part_path(first, "OP20-trim"));
  const auto message = [&](const std::vector<std::string>& set) {
    try {
      run_case(read_case(plain_case,
                         CaseOptions{.set = set, .stroke = {}, .end_time = {}, .search = {}}),
               plain);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  const std::string standing = message({"control.stroke=2.2", "draw_in=[]"});
  EXPECT_NE(standing.find("tool 'punch' stood still"), std::string::npos) << standing;
  const std::string size = message({"control.stroke=2.2", "draw_in=[]", "blank.element_size=2.5"});
  EXPECT_NE(size.find("blank.element_size"), std::string::npos) << size;
  EXPECT_NE(size.find("no `mesh`"), std::string::npos) << size;
}

TEST(TrimChain, ATrimLineFromAGeoFilesPhysicalCurveIsThatCurve) {
  const fs::path geo = fs::path(SF_TEST_DATA_DIR) / "trim_line.geo";
  const auto operations = [&](const std::string& keys) {
    return "operations=[{name=\"a\", kind=\"forming\", stroke=1.0}, {name=\"t\", kind=\"trim\", "
           "line_file=\"" +
           geo.string() + "\"" + keys + "}]";
  };
  const Model model = build_model(cup_with({"control.stroke=0", operations("")}));
  const std::vector<Vec3>& line = model.operations[1].trim_line;
  EXPECT_GE(line.size(), 156u);  // 140 mm of lines and a 15.7 mm arc, points 1 mm apart
  for (const Vec3& p : line) {   // on the rounded rectangle [0, 50] x [0, 30]
    const bool on_side = p.x() == 0.0 || p.y() == 0.0 || p.y() == 30.0 || p.x() == 50.0;
    const bool on_arc = std::abs((p - Vec3(40.0, 20.0, 0.0)).norm() - 10.0) < 1e-9;
    EXPECT_TRUE(on_side || on_arc) << p.transpose();
  }
  // Coarser points: fewer of them.
  const Model coarse =
      build_model(cup_with({"control.stroke=0", operations(", line_element_size=5.0")}));
  EXPECT_LT(coarse.operations[1].trim_line.size(), 40u);
  // A group the file lacks: the case, the key and the file's groups.
  std::string message;
  try {
    build_model(cup_with({"control.stroke=0", operations(", line_group=\"cut\"")}));
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("operations[1] ('t').line_file:"), std::string::npos) << message;
  EXPECT_NE(message.find("no 1-D physical group 'cut'"), std::string::npos) << message;
  EXPECT_NE(message.find("trim (1-D)"), std::string::npos) << message;
}

TEST(TrimChain, ATrimWithoutAWayToBuildTheModelAgainIsRefused) {
  const Model model = build_model(cup_with({"control.stroke=0", kTrimChain}));
  RunOptions options;
  options.output_directory = output_folder("no_rebuild");
  options.checkpoints = false;
  try {
    run_explicit(model, options);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("operations[1] ('OP20-trim')"), std::string::npos)
        << e.what();
  }
}

TEST(TrimChain, BadTrimsAreRefusedNamingTheKey) {
  auto error = [](const std::string& operations) {
    try {
      cup_with({"control.stroke=0", operations});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  const std::string draw = "{name=\"a\", kind=\"forming\", stroke=1.0}";
  EXPECT_NE(
      error("operations=[" + draw + ", {name=\"t\", kind=\"trim\"}]").find("operations[1].line"),
      std::string::npos);
  EXPECT_NE(error("operations=[" + draw + ", {name=\"t\", kind=\"trim\", line=[[0, 0], [1, 0]]}]")
                .find("at least 3 points"),
            std::string::npos);
  EXPECT_NE(error("operations=[" + draw +
                  ", {name=\"t\", kind=\"trim\", line=[[0, 0], [1, 0], [\"a\", 1]]}]")
                .find("not a finite number"),
            std::string::npos);
  EXPECT_NE(
      error("operations=[{name=\"t\", kind=\"trim\", line=[[0, 0], [1, 0], [1, 1]]}, " + draw + "]")
          .find("not first"),
      std::string::npos);
  EXPECT_NE(error("operations=[" + draw +
                  ", {name=\"t\", kind=\"trim\", line=[[0, 0], [1, 0], [1, 1]], "
                  "tools=[\"punch\"]}]")
                .find("operations[1].tools"),
            std::string::npos);
  EXPECT_NE(error("operations=[{name=\"a\", kind=\"forming\", stroke=1.0, "
                  "line=[[0, 0], [1, 0], [1, 1]]}]")
                .find("operations[0].line"),
            std::string::npos);
  // The line from exactly one source; each source's keys only with it.
  const std::string none = error("operations=[" + draw + ", {name=\"t\", kind=\"trim\"}]");
  EXPECT_NE(none.find("one of line (a polyline), line_file (a curve of a file) or line_tool"),
            std::string::npos)
      << none;
  EXPECT_NE(error("operations=[" + draw +
                  ", {name=\"t\", kind=\"trim\", line=[[0, 0], [1, 0], [1, 1]], "
                  "line_tool=\"punch\"}]")
                .find("not more"),
            std::string::npos);
  EXPECT_NE(error("operations=[" + draw + ", {name=\"t\", kind=\"trim\", line_tool=\"ram\"}]")
                .find("operations[1].line_tool"),
            std::string::npos);
  EXPECT_NE(error("operations=[" + draw +
                  ", {name=\"t\", kind=\"trim\", line=[[0, 0], [1, 0], [1, 1]], "
                  "line_offset=2.0}]")
                .find("operations[1].line_offset"),
            std::string::npos);
  EXPECT_NE(error("operations=[" + draw +
                  ", {name=\"t\", kind=\"trim\", line_tool=\"punch\", line_offset=-2.0}]")
                .find("operations[1].line_offset"),
            std::string::npos);
  // A clean cut's keys: the mode of a trim only, the sliver fraction of a cut only, below 0.5.
  const std::string line = "line=[[0, 0], [1, 0], [1, 1]]";
  EXPECT_NE(error("operations=[{name=\"a\", kind=\"forming\", stroke=1.0, mode=\"cut\"}]")
                .find("operations[0].mode"),
            std::string::npos);
  EXPECT_NE(error("operations=[" + draw + ", {name=\"t\", kind=\"trim\", " + line +
                  ", sliver_fraction=0.2}]")
                .find("operations[1].sliver_fraction"),
            std::string::npos);
  const std::string half = error("operations=[" + draw + ", {name=\"t\", kind=\"trim\", " + line +
                                 ", mode=\"cut\", sliver_fraction=0.5}]");
  EXPECT_NE(half.find("operations[1].sliver_fraction"), std::string::npos) << half;
  EXPECT_NE(
      error("operations=[" + draw + ", {name=\"t\", kind=\"trim\", " + line + ", mode=\"split\"}]")
          .find("\"cut\""),
      std::string::npos);
  const std::string geo = (fs::path(SF_TEST_DATA_DIR) / "trim_line.geo").string();
  EXPECT_NE(error("operations=[" + draw + ", {name=\"t\", kind=\"trim\", line_file=\"" + geo +
                  "\", line_curves=[1]}]")
                .find("operations[1].line_curves"),
            std::string::npos);
  EXPECT_NE(
      error("operations=[" + draw + ", {name=\"t\", kind=\"trim\", line_file=\"missing.geo\"}]")
          .find("operations[1].line_file"),
      std::string::npos);
  EXPECT_NE(error("operations=[" + draw + ", {name=\"t\", kind=\"trim\", line_file=\"" +
                  (fs::path(SF_TEST_DATA_DIR) / "cad" / "box_binary.stl").string() + "\"}]")
                .find("a .geo, .msh, .step, .stp, .iges, .igs or .brep file"),
            std::string::npos);
}

}  // namespace
}  // namespace sf
