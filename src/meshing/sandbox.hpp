#pragma once
// A child process that runs code we do not control (gmsh and OpenCASCADE reading a user's file)
// and cannot start programs or touch files beyond what it is given (docs/security.md):
//   - no execve, no new processes (fork, vfork, clone without CLONE_THREAD): seccomp, through
//     libseccomp; a refused call ends the child, and the parent is told which call it was;
//   - no privileges (all capabilities dropped, PR_SET_NO_NEW_PRIVS), no kernel-level calls
//     (mount, ptrace, module loading, ...), no sockets;
//   - files: read only below the folders given, write only below one scratch folder, execute
//     nothing: Landlock (Linux >= 5.13); where the kernel has none, the child runs without it and
//     sandbox_support() says so;
//   - limits: address space, CPU time, and a wall-clock deadline the parent keeps per stage of the
//     child's work (the child reports its stages through a pipe).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace sf {

/// What the kernel offers the sandbox on this machine.
struct SandboxSupport {
  int landlock_abi = 0;  ///< 0: no Landlock (file access not limited by the kernel)
  bool seccomp = false;  ///< system-call filter available
  /// One line for `sheetform check`: what a mesh file's reader can and cannot do here.
  std::string describe() const;
};

/// Probed once per process.
const SandboxSupport& sandbox_support();

/// What the child may do.
struct SandboxPolicy {
  std::vector<std::filesystem::path> readable;  ///< folders (or files) the child may read
  std::filesystem::path writable;               ///< the one folder it may write (and read)
  double memory_bytes = 0.0;                    ///< address-space limit; 0 = none
  double cpu_seconds = 0.0;                     ///< CPU-time limit; 0 = none
  double max_file_bytes = 0.0;                  ///< largest file it may write; 0 = any
  bool keep_output = false;  ///< keep the child's stdout and stderr (else /dev/null)
  /// false: only the limits apply (a file the user trusts, --allow-geo-system-calls).
  bool confine = true;
};

/// The child's side: tells the parent where its work stands (one short line per stage).
class SandboxReporter {
 public:
  explicit SandboxReporter(int fd) : fd_(fd) {}
  /// Sends `line` (no newline in it) to the parent; async-signal-safe.
  void report(const std::string& line) const;

 private:
  int fd_;
};

/// How the child ended, as the parent saw it.
struct SandboxOutcome {
  enum class End {
    exited,        ///< it returned from its job; status() is its exit status
    crashed,       ///< killed by a signal (signal())
    refused_call,  ///< it made a system call the sandbox refuses (refused_call())
    cpu_limit,     ///< it used its CPU time
    file_limit,    ///< it tried to write a file larger than its limit
    deadline,      ///< the parent's deadline for its stage passed; the parent killed it
  };
  End end = End::exited;
  int status = 0;            ///< exit status (exited)
  int signal = 0;            ///< the signal (crashed)
  std::string refused_call;  ///< name of the refused system call (refused_call)
  std::string last_report;   ///< the last stage line the child sent ("" if none)
  double deadline_s = 0.0;   ///< the deadline that passed (deadline), s
  double elapsed_s = 0.0;    ///< wall time from fork to the end, s
};

/// Gives each stage its time: called with "" before the child starts and with each line the child
/// reports; returns the seconds the child may take from now until its next report or its end
/// (<= 0: no deadline).
using SandboxDeadline = std::function<double(const std::string& report)>;

/// Runs `job` in a sandboxed child under `policy` and waits for it. The job's return value is the
/// child's exit status; an exception escaping it exits with status 125. Everything the child
/// produces goes through files in policy.writable and its reports. Throws std::runtime_error if
/// the child cannot be started.
SandboxOutcome run_sandboxed(const SandboxPolicy& policy,
                             const std::function<int(const SandboxReporter&)>& job,
                             const SandboxDeadline& deadline);

}  // namespace sf
