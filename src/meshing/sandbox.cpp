// The sandboxed child: fork, limits, capabilities, Landlock, seccomp; the parent's watch over it.
#include "meshing/sandbox.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <linux/capability.h>
#include <linux/landlock.h>
#include <omp.h>
#include <poll.h>
#include <seccomp.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <thread>

// The sanitizers' hook run before a sanitizer ends the process (libFuzzer sets it to save the
// input as a finding). Weak: null in a build without sanitizers.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace sf {
namespace {

// The report descriptor in the child (the pipe's write end is moved here; all others closed).
constexpr int kReportFd = 3;
// A report line that the SIGSYS handler sends before the child exits: "!refused <number>".
constexpr const char* kRefusedPrefix = "!refused ";
constexpr int kRefusedExit = 159;
constexpr int kJobThrewExit = 125;

// Landlock access rights by ABI version (linux/landlock.h; Debian 12's headers stop at ABI 2,
// the later rights are the kernel's numbers).
constexpr __u64 kFsTruncate = 1ULL << 14;  // ABI 3
constexpr __u64 kFsIoctlDev = 1ULL << 15;  // ABI 5
constexpr __u64 kNetBindTcp = 1ULL << 0;   // ABI 4
constexpr __u64 kNetConnectTcp = 1ULL << 1;
constexpr __u64 kScopeAbstractUnix = 1ULL << 0;  // ABI 6
constexpr __u64 kScopeSignal = 1ULL << 1;

constexpr __u64 kFsRead = LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_READ_DIR;

// The ruleset attribute as the newest kernels take it; older ones read its first 8 or 16 bytes.
struct RulesetAttr {
  __u64 handled_access_fs = 0;
  __u64 handled_access_net = 0;
  __u64 scoped = 0;
};

int probe_landlock_abi() {
  const long abi =
      ::syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION);
  return abi < 0 ? 0 : static_cast<int>(abi);
}

__u64 handled_fs(int abi) {
  __u64 rights = (LANDLOCK_ACCESS_FS_MAKE_SYM << 1) - 1;  // ABI 1: execute ... make_sym
  if (abi >= 2) {
    rights |= LANDLOCK_ACCESS_FS_REFER;
  }
  if (abi >= 3) {
    rights |= kFsTruncate;
  }
  if (abi >= 5) {
    rights |= kFsIoctlDev;
  }
  return rights;
}

// Rights that make sense on a file, not only on a folder (Landlock refuses the others there).
__u64 file_rights(__u64 rights, int abi) {
  __u64 file =
      LANDLOCK_ACCESS_FS_EXECUTE | LANDLOCK_ACCESS_FS_WRITE_FILE | LANDLOCK_ACCESS_FS_READ_FILE;
  if (abi >= 3) {
    file |= kFsTruncate;
  }
  if (abi >= 5) {
    file |= kFsIoctlDev;
  }
  return rights & file;
}

// Child only (after fork: no allocation that can fail silently matters any more, the child is
// ours alone). Returns false if a rule cannot be added.
bool add_path_rule(int ruleset, const std::filesystem::path& path, __u64 rights, int abi) {
  const int fd = ::open(path.c_str(), O_PATH | O_CLOEXEC);
  if (fd < 0) {
    return errno == ENOENT;  // a folder that does not exist needs no rule
  }
  struct stat st {};
  const bool is_dir = ::fstat(fd, &st) == 0 && S_ISDIR(st.st_mode);
  landlock_path_beneath_attr rule{};
  rule.allowed_access = is_dir ? rights : file_rights(rights, abi);
  rule.parent_fd = fd;
  const long added =
      ::syscall(SYS_landlock_add_rule, ruleset, LANDLOCK_RULE_PATH_BENEATH, &rule, 0);
  ::close(fd);
  return added == 0;
}

// In the scratch folder: files and folders, made, written, read and removed; no links (a
// symbolic or hard link there could make the parent read a file the child may not), no devices,
// pipes or sockets, nothing executed.
__u64 scratch_rights(int abi) {
  __u64 rights = kFsRead | LANDLOCK_ACCESS_FS_WRITE_FILE | LANDLOCK_ACCESS_FS_MAKE_REG |
                 LANDLOCK_ACCESS_FS_MAKE_DIR | LANDLOCK_ACCESS_FS_REMOVE_FILE |
                 LANDLOCK_ACCESS_FS_REMOVE_DIR;
  if (abi >= 3) {
    rights |= kFsTruncate;
  }
  return rights;
}

// Folders every reader needs whatever the file: OpenCASCADE's and gmsh's resource files, the
// C library's locale and time-zone data. Nothing below them is the user's.
const std::vector<std::filesystem::path>& system_readable() {
  static const std::vector<std::filesystem::path> folders = {"/usr/share", "/usr/lib", "/usr/lib64",
                                                             "/lib", "/lib64"};
  return folders;
}

bool restrict_files(const SandboxPolicy& policy, int abi) {
  RulesetAttr attr;
  attr.handled_access_fs = handled_fs(abi);
  std::size_t size = sizeof(__u64);
  if (abi >= 4) {
    attr.handled_access_net = kNetBindTcp | kNetConnectTcp;  // no rule: no TCP at all
    size = 2 * sizeof(__u64);
  }
  if (abi >= 6) {
    attr.scoped = kScopeAbstractUnix | kScopeSignal;  // no signals to processes outside
    size = 3 * sizeof(__u64);
  }
  const int ruleset = static_cast<int>(::syscall(SYS_landlock_create_ruleset, &attr, size, 0));
  if (ruleset < 0) {
    return false;
  }
  bool ok = true;
  for (const auto& folder : system_readable()) {
    ok = ok && add_path_rule(ruleset, folder, kFsRead, abi);
  }
  for (const auto& folder : policy.readable) {
    ok = ok && add_path_rule(ruleset, folder, kFsRead, abi);
  }
  ok = ok && add_path_rule(ruleset, policy.writable, scratch_rights(abi), abi);
  ok = ok && ::syscall(SYS_landlock_restrict_self, ruleset, 0) == 0;
  ::close(ruleset);
  return ok;
}

// Calls that start a program or a process end the child with a report (SIGSYS handler below);
// clone3 says "not here" so that the C library falls back to clone, whose flags the filter can
// read (a thread is allowed); sockets and the kernel-level calls fail.
bool filter_system_calls() {
  scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ALLOW);
  if (ctx == nullptr) {
    return false;
  }
  int rc = 0;
  for (const int call : {SCMP_SYS(execve), SCMP_SYS(execveat), SCMP_SYS(fork), SCMP_SYS(vfork)}) {
    rc |= seccomp_rule_add(ctx, SCMP_ACT_TRAP, call, 0);
  }
  rc |= seccomp_rule_add(ctx, SCMP_ACT_TRAP, SCMP_SYS(clone), 1,
                         SCMP_A0(SCMP_CMP_MASKED_EQ, CLONE_THREAD, 0));
  rc |= seccomp_rule_add(ctx, SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3), 0);
  for (const int call : {SCMP_SYS(socket), SCMP_SYS(socketpair)}) {
    rc |= seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EACCES), call, 0);
  }
  for (const int call : {SCMP_SYS(ptrace),
                         SCMP_SYS(process_vm_readv),
                         SCMP_SYS(process_vm_writev),
                         SCMP_SYS(mount),
                         SCMP_SYS(umount2),
                         SCMP_SYS(pivot_root),
                         SCMP_SYS(chroot),
                         SCMP_SYS(unshare),
                         SCMP_SYS(setns),
                         SCMP_SYS(reboot),
                         SCMP_SYS(kexec_load),
                         SCMP_SYS(kexec_file_load),
                         SCMP_SYS(init_module),
                         SCMP_SYS(finit_module),
                         SCMP_SYS(delete_module),
                         SCMP_SYS(bpf),
                         SCMP_SYS(perf_event_open),
                         SCMP_SYS(keyctl),
                         SCMP_SYS(add_key),
                         SCMP_SYS(request_key),
                         SCMP_SYS(userfaultfd),
                         SCMP_SYS(swapon),
                         SCMP_SYS(swapoff),
                         SCMP_SYS(acct),
                         SCMP_SYS(settimeofday),
                         SCMP_SYS(clock_settime),
                         SCMP_SYS(sethostname),
                         SCMP_SYS(setdomainname),
                         SCMP_SYS(iopl),
                         SCMP_SYS(ioperm)}) {
    rc |= seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), call, 0);
  }
  rc |= seccomp_load(ctx);
  seccomp_release(ctx);
  return rc == 0;
}

extern "C" void on_refused_call(int /*signal*/, siginfo_t* info, void* /*context*/) {
  // Only async-signal-safe calls: format the number by hand.
  char line[64];
  std::size_t n = 0;
  for (const char* p = kRefusedPrefix; *p != '\0'; ++p) {
    line[n++] = *p;
  }
  char digits[16];
  int k = 0;
  unsigned number = static_cast<unsigned>(info->si_syscall);
  do {
    digits[k++] = static_cast<char>('0' + number % 10);
    number /= 10;
  } while (number > 0 && k < 16);
  while (k > 0) {
    line[n++] = digits[--k];
  }
  line[n++] = '\n';
  [[maybe_unused]] const ssize_t written = ::write(kReportFd, line, n);
  ::_exit(kRefusedExit);
}

// No capability survives (a root user's child would otherwise keep CAP_DAC_OVERRIDE and more).
void drop_capabilities() {
  for (int cap = 0; cap <= 63; ++cap) {
    ::prctl(PR_CAPBSET_DROP, cap, 0, 0, 0);  // fails harmlessly for numbers the kernel lacks
  }
  __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
  __user_cap_data_struct data[2] = {};
  ::syscall(SYS_capset, &header, data);
}

// The hard limit a unit above the soft one: at the soft limit the kernel sends its own signal
// (SIGXCPU, SIGXFSZ), which the parent can tell from a crash; at the hard one, SIGKILL.
void set_limit(int resource, double value) {
  if (!(value > 0.0)) {
    return;
  }
  const rlim_t limit = value >= 1.8e19 ? RLIM_INFINITY : static_cast<rlim_t>(std::ceil(value));
  const rlimit r{limit, limit == RLIM_INFINITY ? limit : limit + 1};
  ::setrlimit(resource, &r);
}

bool address_space_limit_allowed() {
  // AddressSanitizer reserves terabytes of address space for its shadow memory.
#if defined(__SANITIZE_ADDRESS__)
  return false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return false;
#else
  return true;
#endif
#else
  return true;
#endif
}

// The child's own handlers from the parent (a fuzzer's, a sanitizer's) must not act on its end:
// its crash is the parent's answer, nothing more.
void reset_inherited_handlers() {
  if (__sanitizer_set_death_callback != nullptr) {
    __sanitizer_set_death_callback(nullptr);
  }
  for (const int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGINT, SIGTERM, SIGUSR1, SIGALRM,
                      SIGXCPU, SIGXFSZ, SIGPIPE}) {
    std::signal(s, SIG_DFL);
  }
  struct sigaction refused {};
  refused.sa_sigaction = on_refused_call;
  refused.sa_flags = SA_SIGINFO;
  ::sigaction(SIGSYS, &refused, nullptr);
  sigset_t none;
  sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
}

// Standard streams to /dev/null (or kept), the report pipe on kReportFd, every other descriptor
// closed: an inherited descriptor (a results file, an MPI socket) is beyond Landlock's reach.
void arrange_descriptors(int report_fd, bool keep_output) {
  if (report_fd != kReportFd) {
    ::dup2(report_fd, kReportFd);
  }
  const int null = ::open("/dev/null", O_RDWR);
  if (null >= 0) {
    ::dup2(null, 0);
    if (!keep_output) {
      ::dup2(null, 1);
      ::dup2(null, 2);
    }
  }
  if (::syscall(SYS_close_range, kReportFd + 1, UINT_MAX, 0) != 0) {
    for (int fd = kReportFd + 1; fd < 65536; ++fd) {
      ::close(fd);
    }
  }
}

// Everything but the limits: no privileges, files as the policy says, no programs.
bool confine(const SandboxPolicy& policy) {
  drop_capabilities();
  const SandboxSupport& support = sandbox_support();
  bool confined = ::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0;
  if (support.landlock_abi > 0) {
    confined = confined && restrict_files(policy, support.landlock_abi);
  }
  return confined && filter_system_calls();
}

// LLVM's OpenMP runtime (clang's -fopenmp: the sanitizer and fuzz builds) registers each process
// on its first OpenMP call with a file in /dev/shm named after the process, and ends the process
// when it cannot; gmsh calls OpenMP (omp_set_num_threads), and the C library resolves its calls to
// that runtime when the program brought it. The child therefore makes its first call before it is
// confined; the parent removes the file the child leaves (it ends by _exit). GCC's runtime, the
// release build's, registers nothing: both are no-ops there.
void register_openmp_runtime() {
  omp_get_max_threads();
}

void forget_openmp_registration(pid_t child) {
  const std::string name = fmt::format("/dev/shm/__KMP_REGISTERED_LIB_{}_{}", child, ::getuid());
  ::unlink(name.c_str());  // no such file with GCC's runtime
}

[[noreturn]] void run_child(const SandboxPolicy& policy,
                            const std::function<int(const SandboxReporter&)>& job, int report_fd) {
  reset_inherited_handlers();
  register_openmp_runtime();
  arrange_descriptors(report_fd, policy.keep_output);
  const SandboxReporter reporter(kReportFd);
  if (address_space_limit_allowed()) {
    set_limit(RLIMIT_AS, policy.memory_bytes);
  }
  set_limit(RLIMIT_CPU, policy.cpu_seconds);
  set_limit(RLIMIT_FSIZE, policy.max_file_bytes);
  const rlimit no_core{0, 0};
  ::setrlimit(RLIMIT_CORE, &no_core);
  if (policy.confine && !confine(policy)) {
    reporter.report("!unconfined");
    ::_exit(kJobThrewExit);
  }
  int status = kJobThrewExit;
  try {
    status = job(reporter);
  } catch (...) {
    status = kJobThrewExit;
  }
  std::fflush(nullptr);
  ::_exit(status);
}

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string call_name(const std::string& number_text) {
  const int number = std::atoi(number_text.c_str());
  char* name = seccomp_syscall_resolve_num_arch(SCMP_ARCH_NATIVE, number);
  std::string text = name != nullptr ? std::string(name) : "system call " + number_text;
  std::free(name);
  return text;
}

/// The parent's side: reads the child's reports until the pipe closes, keeping each stage's
/// deadline; kills the child when one passes.
class ChildWatch {
 public:
  ChildWatch(pid_t child, int fd, const SandboxDeadline& deadline)
      : child_(child), fd_(fd), deadline_(deadline), start_(Clock::now()) {
    set_deadline(deadline_(""));
  }

  SandboxOutcome wait() {
    while (!pipe_closed_ && !deadline_passed()) {
      read_reports();
    }
    int status = 0;
    while (!deadline_passed()) {  // the pipe closes as the child ends; a child that closed it
      const pid_t done = ::waitpid(child_, &status, WNOHANG);  // itself still has its deadline
      if (done == child_) {
        return ended(status);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ::kill(child_, SIGKILL);
    while (::waitpid(child_, &status, 0) < 0 && errno == EINTR) {
    }
    outcome_.end = SandboxOutcome::End::deadline;
    outcome_.deadline_s = stage_seconds_;
    outcome_.elapsed_s = seconds_since(start_);
    return outcome_;
  }

 private:
  void set_deadline(double seconds) {
    stage_seconds_ = seconds;
    stage_start_ = Clock::now();
  }

  bool deadline_passed() const {
    return stage_seconds_ > 0.0 && seconds_since(stage_start_) > stage_seconds_;
  }

  int poll_milliseconds() const {
    if (!(stage_seconds_ > 0.0)) {
      return 1000;
    }
    const double left = stage_seconds_ - seconds_since(stage_start_);
    return static_cast<int>(std::clamp(std::ceil(1e3 * left), 1.0, 1000.0));
  }

  void read_reports() {
    pollfd p{fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, poll_milliseconds());
    if (ready <= 0) {
      return;  // timeout or EINTR: the loop checks the deadline
    }
    char buffer[4096];
    const ssize_t n = ::read(fd_, buffer, sizeof(buffer));
    if (n < 0) {
      pipe_closed_ = errno != EINTR && errno != EAGAIN;
      return;
    }
    if (n == 0) {
      pipe_closed_ = true;
      return;
    }
    pending_.append(buffer, static_cast<std::size_t>(n));
    for (std::size_t end; (end = pending_.find('\n')) != std::string::npos;) {
      const std::string line = pending_.substr(0, end);
      pending_.erase(0, end + 1);
      outcome_.last_report = line;
      if (line.rfind("!", 0) != 0) {
        set_deadline(deadline_(line));
      }
    }
    if (pending_.size() > 65536) {  // a child that floods the pipe without newlines
      pending_.clear();
    }
  }

  SandboxOutcome ended(int status) {
    outcome_.elapsed_s = seconds_since(start_);
    const std::string& last = outcome_.last_report;
    if (last.rfind(kRefusedPrefix, 0) == 0) {
      outcome_.end = SandboxOutcome::End::refused_call;
      outcome_.refused_call = call_name(last.substr(std::strlen(kRefusedPrefix)));
    } else if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU) {
      outcome_.end = SandboxOutcome::End::cpu_limit;
    } else if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXFSZ) {
      outcome_.end = SandboxOutcome::End::file_limit;
    } else if (WIFSIGNALED(status) && WTERMSIG(status) == SIGSYS) {
      // Killed without its handler: the call came with every signal blocked (the C library's
      // posix_spawn blocks them), so the kernel could not deliver it. Only the calls that start
      // a process or a program are trapped.
      outcome_.end = SandboxOutcome::End::refused_call;
      outcome_.refused_call = "fork, clone or execve";
    } else if (WIFSIGNALED(status)) {
      outcome_.end = SandboxOutcome::End::crashed;
      outcome_.signal = WTERMSIG(status);
    } else {
      outcome_.end = SandboxOutcome::End::exited;
      outcome_.status = WEXITSTATUS(status);
    }
    return outcome_;
  }

  pid_t child_;
  int fd_;
  const SandboxDeadline& deadline_;
  Clock::time_point start_, stage_start_;
  double stage_seconds_ = 0.0;
  bool pipe_closed_ = false;
  std::string pending_;
  SandboxOutcome outcome_;
};

}  // namespace

std::string SandboxSupport::describe() const {
  std::string text = seccomp ? "no programs can be started (seccomp)"
                             : "programs are NOT kept from starting (no seccomp in this kernel)";
  if (landlock_abi > 0) {
    text += fmt::format(
        "; files are read only in the mesh file's folder and written only in a scratch folder "
        "(Landlock ABI {})",
        landlock_abi);
  } else {
    text +=
        "; this kernel has no Landlock: a mesh file's reader could read and write any file you "
        "can, and only the .geo scan (SystemCall, Exit, Include/Merge) stands in";
  }
  return text;
}

const SandboxSupport& sandbox_support() {
  static const SandboxSupport support = [] {
    SandboxSupport s;
    s.landlock_abi = probe_landlock_abi();
    s.seccomp = ::prctl(PR_GET_SECCOMP, 0, 0, 0, 0) >= 0;
    return s;
  }();
  return support;
}

void SandboxReporter::report(const std::string& line) const {
  std::string text = line;
  std::replace(text.begin(), text.end(), '\n', ' ');
  text += '\n';
  [[maybe_unused]] const ssize_t written = ::write(fd_, text.data(), text.size());
}

SandboxOutcome run_sandboxed(const SandboxPolicy& policy,
                             const std::function<int(const SandboxReporter&)>& job,
                             const SandboxDeadline& deadline) {
  sandbox_support();  // probed before the fork, so that the child need not
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    throw std::runtime_error(fmt::format("cannot make a pipe: {}", std::strerror(errno)));
  }
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) {
    const int error = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(fmt::format("cannot start a process: {}", std::strerror(error)));
  }
  if (child == 0) {
    ::close(fds[0]);
    run_child(policy, job, fds[1]);
  }
  ::close(fds[1]);
  ChildWatch watch(child, fds[0], deadline);
  SandboxOutcome outcome = watch.wait();
  ::close(fds[0]);
  forget_openmp_registration(child);
  return outcome;
}

}  // namespace sf
