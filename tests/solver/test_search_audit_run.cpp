// The search audit in a run: the recorder counts the standard search's misses as an independent
// brute-force oracle does (Voronoi-region closest point, Ericson 2005: tests/contact), and a run
// with audit = true writes the per-node fields, the history column and the summary consistently.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "casefile/case_config.hpp"
#include "contact/brute_force_oracle.hpp"
#include "contact/test_meshes.hpp"
#include "model/build_model.hpp"
#include "results/hdf5_file.hpp"
#include "solver/explicit_driver.hpp"
#include "solver/search_audit_recorder.hpp"

namespace fs = std::filesystem;

namespace sf {
namespace {

TEST(SearchAuditRun, RecorderCountsTheStandardSearchMissesLikeTheOracle) {
  // The thin-triangle trap of the contact tests (long thin triangles over a dense strip): the
  // standard search misses there. 2000 "blank nodes" near it, the tool moved by (0.01, 0, 0.02).
  Model model;
  Tool tool;
  tool.name = "trap";
  tool.surface = test::make_thin_trap();
  model.tools.push_back(std::move(tool));
  ContactInterface contact;
  contact.tool = 0;
  contact.search = ContactSearchKind::standard;
  contact.audit = true;
  contact.pair.surface = &model.tools[0].surface;
  contact.pair.search = make_contact_search("standard", model.tools[0].surface);
  contact.pair.cutoff = 0.2;
  model.contacts.push_back(std::move(contact));
  const std::vector<Vec3> points =
      test::random_points(2000, Vec3(-1.1, -0.3, -0.25), Vec3(1.1, 0.3, 0.25), 11);
  model.blank.mesh.nodes.resize(3, static_cast<Eigen::Index>(points.size()));
  const Vec3 shift(0.01, 0.0, 0.02);
  for (std::size_t i = 0; i < points.size(); ++i) {
    model.blank.mesh.nodes.col(static_cast<Eigen::Index>(i)) = points[i] + shift;
  }
  SolutionState state;
  state.x = model.blank.mesh.nodes;
  state.tools.resize(1);
  state.tools[0].displacement = shift;
  state.cycle = 7;
  state.time = 1e-3;

  SearchAuditRecorder recorder(model);
  recorder.record(model, state);
  ASSERT_EQ(recorder.records().size(), 1u);
  const SearchAuditRecord& r = recorder.records()[0];

  // The oracle: a node is checked when some triangle lies within the cutoff; a miss when the
  // standard search's triangle (no cutoff) is farther than the least distance (1e-9 mm apart).
  const auto standard = make_contact_search("standard", model.tools[0].surface);
  const TriangleSurface& s = model.tools[0].surface;
  int checked = 0, misses = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const oracle::OracleAnswer exact = oracle::closest(s.nodes(), s.triangles(), points[i], 1e-9);
    if (exact.distance > contact.pair.cutoff) {
      continue;
    }
    ++checked;
    ClosestPoint cp;
    standard->find_closest(points[i], std::numeric_limits<double>::infinity(), cp);
    const double chosen =
        oracle::distance_to_triangle(s.nodes(), s.triangles(), cp.triangle, points[i]);
    const bool miss = chosen > exact.distance + 1e-9;
    misses += miss ? 1 : 0;
    EXPECT_EQ(r.miss[static_cast<Eigen::Index>(i)], miss ? 1.0 : 0.0) << "node " << i;
    if (miss) {
      // gap error = the standard search's signed distance - the exact signed distance, so the
      // exact signed distance it implies has the oracle's magnitude.
      const double implied_exact = cp.signed_distance - r.gap_error[static_cast<Eigen::Index>(i)];
      EXPECT_NEAR(std::abs(implied_exact), exact.distance, 1e-9) << "node " << i;
    }
  }
  std::printf("audit: %d misses of %d nodes within reach on the thin-triangle trap\n", misses,
              checked);
  EXPECT_GT(misses, 10);
  EXPECT_EQ(r.last.nodes_checked, checked);
  EXPECT_EQ(r.last.misses, misses);
  EXPECT_EQ(r.max_misses, misses);
  EXPECT_EQ(r.max_misses_time, 1e-3);
  // A second record in the same cycle is not counted twice.
  recorder.record(model, state);
  EXPECT_EQ(recorder.records()[0].audits, 1);
}

TEST(SearchAuditRun, ShortDemoWritesFieldsHistoryAndSummary) {
  CaseConfig config = read_case(fs::path(SF_SOURCE_DIR) / "cases/square_cup_aluminium/case.toml");
  config.control.stroke = 0.5;
  config.control.output_frames = 2;
  for (ContactConfig& c : config.contacts) {
    c.search = ContactSearchKind::standard;
    c.audit = true;
  }
  Model model = build_model(config);
  const fs::path out = fs::path(SF_BINARY_DIR) / "test_output" / "search_audit_run";
  fs::remove_all(out);
  RunOptions options;
  options.output_directory = out;
  const RunSummary summary = run_explicit(model, options);
  ASSERT_EQ(summary.search_audits.size(), 3u);
  h5::File file(out / "results.h5", h5::FileMode::read_only);
  const std::vector<double> time = file.read_doubles("/history/time");
  for (const SearchAuditSummary& a : summary.search_audits) {
    EXPECT_EQ(a.search, "standard");
    EXPECT_EQ(a.audits, static_cast<int>(time.size())) << a.tool;  // every history row
    EXPECT_GT(a.final_nodes_checked, 0) << a.tool;
    const std::vector<double> misses = file.read_doubles("/history/" + a.tool + "_search_misses");
    ASSERT_EQ(misses.size(), time.size());
    EXPECT_EQ(misses.back(), a.final_misses);
    double total = 0;
    for (double m : misses) {
      total += m;
    }
    EXPECT_EQ(total, static_cast<double>(a.total_misses)) << a.tool;
    const std::string frame = "/parts/blank/frames/000002/";
    const std::vector<double> miss = file.read_doubles(frame + "search_miss_" + a.tool);
    const std::vector<double> gap = file.read_doubles(frame + "search_gap_error_" + a.tool);
    ASSERT_EQ(miss.size(), model.blank.mesh.nodes.cols());
    double flagged = 0;
    for (std::size_t i = 0; i < miss.size(); ++i) {
      flagged += miss[i];
      EXPECT_TRUE(miss[i] == 1.0 || gap[i] == 0.0) << a.tool << " node " << i;
    }
    EXPECT_EQ(flagged, a.final_misses) << a.tool;
  }
}

}  // namespace
}  // namespace sf
