// The sandbox's primitives (meshing/sandbox.hpp), each shown by a child that tries what it must
// not: start a program, write or read where it may not, reach a descriptor of its parent, open a
// socket, signal its parent; and each limit reached: the deadline, CPU time, memory, file size.
#include "meshing/sandbox.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>
#include <thread>
#include <vector>

namespace sf {
namespace {

namespace fs = std::filesystem;

/// Folders of one test: `allowed` (readable), `scratch` (writable), `outside` (neither).
struct Folders {
  explicit Folders(const std::string& name) {
    root = fs::path(SF_BINARY_DIR) / "test_scratch" / "sandbox" / name;
    fs::remove_all(root);
    allowed = root / "allowed";
    scratch = root / "scratch";
    outside = root / "outside";
    for (const auto& f : {allowed, scratch, outside}) {
      fs::create_directories(f);
    }
    std::ofstream(allowed / "input.txt") << "allowed";
    std::ofstream(outside / "secret.txt") << "secret";
  }
  SandboxPolicy policy() const {
    SandboxPolicy p;
    p.readable = {allowed};
    p.writable = scratch;
    return p;
  }
  fs::path root, allowed, scratch, outside;
};

SandboxOutcome run(const SandboxPolicy& policy, const std::function<int()>& job,
                   double seconds = 30.0) {
  return run_sandboxed(
      policy, [&](const SandboxReporter&) { return job(); },
      [seconds](const std::string&) { return seconds; });
}

/// errno of open(path, flags), 0 if it opened.
int open_errno(const fs::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC, 0644);
  if (fd < 0) {
    return errno;
  }
  ::close(fd);
  return 0;
}

bool has_landlock() {
  return sandbox_support().landlock_abi > 0;
}

TEST(Sandbox, TheChildsExitStatusComesBack) {
  const Folders f("status");
  const SandboxOutcome o = run(f.policy(), [] { return 7; });
  EXPECT_EQ(o.end, SandboxOutcome::End::exited);
  EXPECT_EQ(o.status, 7);
}

TEST(Sandbox, StartingAProgramThroughTheShellIsRefusedAndNamed) {
  const Folders f("system");
  const fs::path marker = f.outside / "ran";
  const std::string command = "touch " + marker.string();
  const SandboxOutcome o = run(f.policy(), [&] { return std::system(command.c_str()); });
  EXPECT_EQ(o.end, SandboxOutcome::End::refused_call);
  // The C library's posix_spawn clones with every signal blocked: the kernel kills the child
  // instead of calling its handler, so the call is named by what the filter traps.
  EXPECT_NE(o.refused_call.find("clone"), std::string::npos) << o.refused_call;
  EXPECT_FALSE(fs::exists(marker));
}

TEST(Sandbox, ExecveIsRefusedAndNamed) {
  const Folders f("execve");
  const SandboxOutcome o = run(f.policy(), [] {
    ::execl("/bin/true", "true", static_cast<char*>(nullptr));
    return 0;
  });
  EXPECT_EQ(o.end, SandboxOutcome::End::refused_call);
  EXPECT_EQ(o.refused_call, "execve");
}

TEST(Sandbox, ForkIsRefused) {
  const Folders f("fork");
  const SandboxOutcome o = run(f.policy(), [] {
    const pid_t pid = ::fork();
    if (pid == 0) {
      ::_exit(0);
    }
    return 0;
  });
  EXPECT_EQ(o.end, SandboxOutcome::End::refused_call);
}

TEST(Sandbox, ThreadsAreAllowed) {
  const Folders f("thread");
  const SandboxOutcome o = run(f.policy(), [] {
    int value = 0;
    std::thread t([&value] { value = 5; });
    t.join();
    return value;
  });
  EXPECT_EQ(o.end, SandboxOutcome::End::exited);
  EXPECT_EQ(o.status, 5);
}

TEST(Sandbox, FilesAreReadOnlyInTheReadableFoldersAndWrittenOnlyInTheScratch) {
  if (!has_landlock()) {
    GTEST_SKIP() << "this kernel has no Landlock: " << sandbox_support().describe();
  }
  const Folders f("files");
  // Each check's errno in a byte of the status would not fit: the child returns the index of the
  // first check that went wrong (0: all as expected).
  const SandboxOutcome o = run(f.policy(), [&] {
    if (open_errno(f.allowed / "input.txt", O_RDONLY) != 0)
      return 1;
    if (open_errno(f.outside / "secret.txt", O_RDONLY) != EACCES)
      return 2;
    if (open_errno(f.allowed / "input.txt", O_WRONLY) != EACCES)
      return 3;
    if (open_errno(f.allowed / "new.txt", O_WRONLY | O_CREAT) != EACCES)
      return 4;
    if (open_errno(f.outside / "new.txt", O_WRONLY | O_CREAT) != EACCES)
      return 5;
    if (open_errno(f.scratch / "out.txt", O_WRONLY | O_CREAT) != 0)
      return 6;
    if (open_errno(f.scratch / "out.txt", O_RDONLY) != 0)
      return 7;
    if (::symlink((f.outside / "secret.txt").c_str(), (f.scratch / "link").c_str()) == 0)
      return 8;
    if (open_errno("/etc/passwd", O_RDONLY) != EACCES)
      return 9;
    if (open_errno(fs::temp_directory_path() / "sheetform-sandbox-test", O_WRONLY | O_CREAT) !=
        EACCES)
      return 10;
    return 0;
  });
  EXPECT_EQ(o.end, SandboxOutcome::End::exited);
  EXPECT_EQ(o.status, 0) << "check " << o.status << " went wrong";
  EXPECT_TRUE(fs::exists(f.scratch / "out.txt"));
  EXPECT_FALSE(fs::exists(f.allowed / "new.txt"));
  EXPECT_FALSE(fs::exists(f.outside / "new.txt"));
}

TEST(Sandbox, TheParentsDescriptorsAreClosed) {
  const Folders f("descriptors");
  const fs::path results = f.outside / "results.h5";
  const int opened = ::open(results.c_str(), O_WRONLY | O_CREAT, 0644);
  ASSERT_GE(opened, 0);
  const int fd = ::fcntl(opened, F_DUPFD, 100);  // inherited by fork; not a number the child uses
  ::close(opened);
  ASSERT_GE(fd, 100);
  const SandboxOutcome o =
      run(f.policy(), [fd] { return ::write(fd, "x", 1) < 0 && errno == EBADF ? 0 : 1; });
  ::close(fd);
  EXPECT_EQ(o.status, 0);
  EXPECT_EQ(fs::file_size(results), 0u);
}

TEST(Sandbox, NoSockets) {
  const Folders f("sockets");
  const SandboxOutcome o = run(f.policy(), [] {
    const int s = ::socket(AF_INET, SOCK_STREAM, 0);
    return s < 0 ? 0 : 1;
  });
  EXPECT_EQ(o.status, 0);
}

TEST(Sandbox, NoSignalsToTheParent) {
  if (sandbox_support().landlock_abi < 6) {
    GTEST_SKIP() << "Landlock's signal scoping needs ABI 6, this kernel has "
                 << sandbox_support().landlock_abi;
  }
  const Folders f("signals");
  const pid_t parent = ::getpid();
  const SandboxOutcome o =
      run(f.policy(), [parent] { return ::kill(parent, SIGTERM) < 0 && errno == EPERM ? 0 : 1; });
  EXPECT_EQ(o.status, 0);
}

TEST(Sandbox, ACrashIsReportedWithItsSignal) {
  const Folders f("crash");
  const SandboxOutcome o = run(f.policy(), [] {
    std::raise(SIGSEGV);
    return 0;
  });
  EXPECT_EQ(o.end, SandboxOutcome::End::crashed);
  EXPECT_EQ(o.signal, SIGSEGV);
}

TEST(Sandbox, TheDeadlineOfAStageStopsAChildThatNeverEnds) {
  const Folders f("deadline");
  const auto start = std::chrono::steady_clock::now();
  const SandboxOutcome o = run_sandboxed(
      f.policy(),
      [](const SandboxReporter& reporter) {
        reporter.report("looping");
        for (volatile long k = 0;; k = k + 1) {
        }
        return 0;
      },
      [](const std::string& report) { return report.empty() ? 20.0 : 0.3; });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(o.end, SandboxOutcome::End::deadline);
  EXPECT_EQ(o.last_report, "looping");
  EXPECT_DOUBLE_EQ(o.deadline_s, 0.3);
  EXPECT_LT(seconds, 10.0);
}

TEST(Sandbox, TheCpuLimitStopsABusyChild) {
  const Folders f("cpu");
  SandboxPolicy policy = f.policy();
  policy.cpu_seconds = 1.0;
  const SandboxOutcome o = run(policy, [] {
    for (volatile long k = 0;; k = k + 1) {
    }
    return 0;
  });
  EXPECT_EQ(o.end, SandboxOutcome::End::cpu_limit);
}

TEST(Sandbox, TheMemoryLimitFailsAnAllocation) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer's shadow memory needs an unlimited address space";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  GTEST_SKIP() << "AddressSanitizer's shadow memory needs an unlimited address space";
#endif
#endif
  const Folders f("memory");
  SandboxPolicy policy = f.policy();
  policy.memory_bytes = 2e9;
  const SandboxOutcome o = run(policy, [] {
    try {
      std::vector<char> big(static_cast<std::size_t>(4e9));
      big[big.size() - 1] = 1;
      return 1;
    } catch (const std::bad_alloc&) {
      return 0;
    }
  });
  EXPECT_EQ(o.end, SandboxOutcome::End::exited);
  EXPECT_EQ(o.status, 0);
}

TEST(Sandbox, TheFileLimitStopsALargeWrite) {
  const Folders f("file_size");
  SandboxPolicy policy = f.policy();
  policy.max_file_bytes = 1e6;
  const fs::path out = f.scratch / "big.bin";
  const SandboxOutcome o = run(policy, [&] {
    std::ofstream file(out, std::ios::binary);
    const std::string block(1 << 16, 'x');
    for (int k = 0; k < 100; ++k) {
      file.write(block.data(), static_cast<std::streamsize>(block.size()));
      file.flush();
    }
    return 0;
  });
  EXPECT_EQ(o.end, SandboxOutcome::End::file_limit);
  EXPECT_LE(fs::file_size(out), 1000000u);
}

TEST(Sandbox, SupportIsDescribed) {
  const std::string text = sandbox_support().describe();
  EXPECT_NE(text.find(has_landlock() ? "Landlock ABI" : "no Landlock"), std::string::npos) << text;
}

}  // namespace
}  // namespace sf
