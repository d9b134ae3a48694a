// The time a sandboxed gmsh job gets, stage by stage (meshing/mesh_limits.hpp).
#include "meshing/mesh_limits.hpp"

#include <gtest/gtest.h>

#include <string>

namespace sf {
namespace {

TEST(MeshTimeLimit, ScaledWithTheFileAndTheElements) {
  MeshTimeLimit time(MeshLimits{}, 2.5e6);  // a 2.5 MB file
  // Reading: 60 s + 4 s per MB.
  EXPECT_DOUBLE_EQ(time.seconds_for(""), 70.0);
  EXPECT_DOUBLE_EQ(time.seconds_for("reading"), 70.0);
  // Meshing, once the estimate is known: 60 s + 2 ms per element.
  EXPECT_DOUBLE_EQ(time.seconds_for("estimate 100000"), 260.0);
  EXPECT_DOUBLE_EQ(time.seconds_for("writing"), 260.0);
}

TEST(MeshTimeLimit, AFileThatIsOnlyReadKeepsTheReadingTime) {
  MeshTimeLimit time(MeshLimits{}, 1e6);
  EXPECT_DOUBLE_EQ(time.seconds_for("reading"), 64.0);
  EXPECT_DOUBLE_EQ(time.seconds_for("writing"), 64.0);
}

TEST(MeshTimeLimit, TheEstimateCountsNoMoreThanTheElementLimit) {
  MeshTimeLimit time(MeshLimits{.max_elements = 1000.0}, 0.0);
  EXPECT_DOUBLE_EQ(time.seconds_for("estimate 1e12"), 62.0);
  EXPECT_DOUBLE_EQ(time.cpu_seconds(), 60.0 + 62.0 + 1.0);
}

TEST(MeshTimeLimit, AGivenLimitIsTheWholeJobs) {
  MeshTimeLimit time(MeshLimits{.seconds = 5.0}, 1e9);
  EXPECT_LE(time.seconds_for(""), 5.0);
  EXPECT_GT(time.seconds_for("estimate 1e6"), 4.0);  // what is left of the 5 s, not more
  EXPECT_LE(time.seconds_for("estimate 1e6"), 5.0);
  EXPECT_DOUBLE_EQ(time.cpu_seconds(), 6.0);
  const std::string why = time.explain("writing", 5.0);
  EXPECT_NE(why.find("within 5 s (limits.mesh_seconds; stopped while writing the mesh)"),
            std::string::npos)
      << why;
}

TEST(MeshTimeLimit, TheMessageSaysWhichStageRanOut) {
  MeshTimeLimit time(MeshLimits{}, 0.0);
  time.seconds_for("reading");
  EXPECT_NE(time.explain("reading", 60.0).find("did not finish reading it within 60 s"),
            std::string::npos);
  time.seconds_for("estimate 5000");
  EXPECT_NE(time.explain("estimate 5000", 70.0)
                .find("did not finish meshing it within 70 s, the time allowed for about 5e+03"),
            std::string::npos)
      << time.explain("estimate 5000", 70.0);
}

}  // namespace
}  // namespace sf
