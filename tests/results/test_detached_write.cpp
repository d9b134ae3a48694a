// run_detached: a write runs in a child process that a kill of the run does not stop, and what
// the write throws comes back with its kind and message.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "core/errors.hpp"
#include "results/detached_write.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

fs::path output_dir(const std::string& name) {
  const fs::path dir = fs::path(SF_BINARY_DIR) / "test-output" / "detached_write" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(DetachedWrite, WritesAndReturnsWhenDone) {
  const fs::path file = output_dir("done") / "written";
  run_detached([&] { std::ofstream(file) << "whole"; });
  std::ifstream in(file);
  std::string text;
  in >> text;
  EXPECT_EQ(text, "whole");
}

TEST(DetachedWrite, ThrowsWhatTheWriteThrewWithItsKind) {
  EXPECT_THROW(run_detached([] { throw InputError("bad input"); }), InputError);
  EXPECT_THROW(run_detached([] { throw OutputError("disk full"); }), OutputError);
  EXPECT_THROW(run_detached([] { throw std::invalid_argument("wrong call"); }),
               std::invalid_argument);
  try {
    run_detached([] { throw std::runtime_error("HDF5 said no"); });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "HDF5 said no");
  }
}

TEST(DetachedWrite, AChildThatDiesIsAnOutputError) {
  EXPECT_THROW(run_detached([] { ::_exit(3); }), OutputError);
}

/// The write kills the process that asked for it (as a SIGKILL of the run would, at that
/// moment), then finishes: the file is whole after the process died.
[[noreturn]] void die_during_a_write(const fs::path& file) {
  run_detached([&] {
    ::kill(::getppid(), SIGKILL);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the run is gone by now
    std::ofstream(file) << "whole";
  });
  std::abort();  // not reached: the SIGKILL came first
}

TEST(DetachedWrite, AWriteUnderWayWhenTheRunIsKilledIsFinished) {
  const fs::path file = output_dir("killed") / "written";
  EXPECT_EXIT(die_during_a_write(file), ::testing::KilledBySignal(SIGKILL), "");
  std::string text;
  for (int wait = 0; wait < 100 && text != "whole"; ++wait) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    std::ifstream in(file);
    in >> text;
  }
  EXPECT_EQ(text, "whole");
}

/// Ctrl-C or SIGTERM sent to the run's process group does not reach the writer.
TEST(DetachedWrite, TheWriterIsOutsideTheRunsProcessGroupAndIgnoresSignals) {
  pid_t group = 0;
  pid_t writer = 0;
  run_detached([&] {
    group = ::getpgrp();
    writer = ::getpid();
    ::kill(0, SIGTERM);  // its own group: ignored
  });
  if (group != 0) {  // a fork (sanitizer builds) does not share the memory to tell
    EXPECT_EQ(group, writer);
    EXPECT_NE(writer, ::getpid());
  }
}

}  // namespace
}  // namespace sf
