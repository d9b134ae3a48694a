#include "results/detached_write.hpp"

#include <fmt/core.h>

#include <sched.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"

// The sanitizers do not know a task that shares the memory of a thread (clone with CLONE_VM):
// their builds give the writer a copy of the memory (fork) instead.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SF_WRITER_FORKS 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define SF_WRITER_FORKS 1
#endif
#endif

namespace sf {
namespace {

// How the write ended, as the child reports it: the kind of exception, then its message.
enum class Kind : char {
  pending = 0,
  none = '0',
  input = 'I',
  output = 'O',
  argument = 'A',
  other = 'R'
};

// The report lives in memory both processes share, whichever way the child was made.
struct Report {
  Kind kind;
  char message[8191];
};

struct Job {
  const std::function<void()>* write;
  Report* report;
};

void set_report(Report& report, Kind kind, const char* message) {
  const std::size_t size = std::min(std::strlen(message), sizeof(report.message) - 1);
  std::memcpy(report.message, message, size);
  report.message[size] = '\0';
  report.kind = kind;
}

// Runs the write, catching what it throws as a kind and a message.
void run_and_report(const std::function<void()>& write, Report& report) {
  try {
    write();
    set_report(report, Kind::none, "");
  } catch (const InputError& e) {
    set_report(report, Kind::input, e.what());
  } catch (const OutputError& e) {
    set_report(report, Kind::output, e.what());
  } catch (const std::invalid_argument& e) {
    set_report(report, Kind::argument, e.what());
  } catch (const std::exception& e) {
    set_report(report, Kind::other, e.what());
  }
}

// The child: out of the run's process group (a kill of the group, a Ctrl-C at the terminal does
// not reach it) and deaf to the catchable signals, it does the write and reports.
int be_the_writer(void* argument) {
  const Job& job = *static_cast<const Job*>(argument);
  ::setpgid(0, 0);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGPIPE, SIGALRM}) {
    std::signal(signal, SIG_IGN);  // the child's own copy of the dispositions
  }
  run_and_report(*job.write, *job.report);
  return 0;
}

// Anonymous memory of `bytes`, shared with the children (a fork's as well as a clone's).
class SharedMemory {
 public:
  explicit SharedMemory(std::size_t bytes, int flags = MAP_SHARED)
      : bytes_(bytes),
        data_(::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, flags | MAP_ANONYMOUS, -1, 0)) {}
  SharedMemory(const SharedMemory&) = delete;
  SharedMemory& operator=(const SharedMemory&) = delete;
  ~SharedMemory() {
    if (valid()) {
      ::munmap(data_, bytes_);
    }
  }
  bool valid() const { return data_ != MAP_FAILED; }
  void* data() const { return data_; }
  void* end() const { return static_cast<char*>(data_) + bytes_; }

 private:
  std::size_t bytes_;
  void* data_;
};

// Starts the child; -1 when the system cannot. Without the sanitizers, it shares this process's
// memory and this thread waits until it ends (CLONE_VM | CLONE_VFORK): no copy of the memory,
// whatever the model's size, and the write sees the data as it is.
pid_t start_writer(Job& job, const SharedMemory& stack) {
#ifdef SF_WRITER_FORKS
  (void)stack;
  const pid_t child = ::fork();
  if (child == 0) {
    ::_exit(be_the_writer(&job));
  }
  return child;
#else
  return ::clone(be_the_writer, stack.end(), CLONE_VM | CLONE_VFORK | SIGCHLD, &job);
#endif
}

[[noreturn]] void throw_report(const Report& report, int status) {
  const std::string message = report.message;
  if (report.kind == Kind::pending || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw OutputError(
        fmt::format("the results writer (a child process) ended without finishing its write ({})",
                    WIFSIGNALED(status) ? std::string(strsignal(WTERMSIG(status)))
                                        : fmt::format("exit status {}", WEXITSTATUS(status))));
  }
  switch (report.kind) {
    case Kind::input:
      throw InputError(message);
    case Kind::output:
      throw OutputError(message);
    case Kind::argument:
      throw std::invalid_argument(message);
    default:
      throw std::runtime_error(message);
  }
}

}  // namespace

void run_detached(const std::function<void()>& write) {
  constexpr std::size_t stack_bytes = std::size_t{8} << 20;  // touched pages only
  const SharedMemory shared(sizeof(Report));
  const SharedMemory stack(stack_bytes, MAP_PRIVATE | MAP_STACK | MAP_NORESERVE);
  // A guard page below the stack: an overflow faults rather than writing over other memory.
  if (!shared.valid() || !stack.valid() || ::mprotect(stack.data(), 4096, PROT_NONE) != 0) {
    write();  // no memory for a child: write here, as before
    return;
  }
  auto* report = new (shared.data()) Report{Kind::pending, {}};
  Job job{&write, report};
  const pid_t child = start_writer(job, stack);
  if (child < 0) {
    write();
    return;
  }
  ::setpgid(child, child);  // fails harmlessly once the child has ended
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (report->kind == Kind::none && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    return;
  }
  throw_report(*report, status);
}

}  // namespace sf
