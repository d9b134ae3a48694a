#include "results/hdf5_probe.hpp"

#include <fmt/core.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <system_error>

#include "core/errors.hpp"

// The sanitizers' hook run before a sanitizer ends the process (libFuzzer sets it to save the
// input as a finding). Weak: null in a build without sanitizers.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace sf {
namespace {

// The child's crash is the parent's answer, nothing more: a handler inherited from the parent (a
// fuzzer's, which would save the input as its own finding, or a sanitizer's) must not act on it.
void forget_inherited_handlers() {
  if (__sanitizer_set_death_callback != nullptr) {
    __sanitizer_set_death_callback(nullptr);
  }
  for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGALRM}) {
    std::signal(signal, SIG_DFL);
  }
}

void silence_output() {
  const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (null >= 0) {
    ::dup2(null, 1);
    ::dup2(null, 2);
  }
}

unsigned time_limit(const std::filesystem::path& file) {
  std::error_code error;
  const auto bytes = std::filesystem::file_size(file, error);
  return 10u + (error ? 0u : static_cast<unsigned>(bytes / 5'000'000u));
}

}  // namespace

void read_in_child_first(const std::filesystem::path& file, const std::string& what,
                         const std::function<void()>& read) {
  const unsigned seconds = time_limit(file);
  const pid_t child = ::fork();
  if (child < 0) {
    return;  // cannot fork: the caller reads it, as before
  }
  if (child == 0) {
    forget_inherited_handlers();
    silence_output();
    ::alarm(seconds);
    try {
      read();
    } catch (...) {
      // an error the read reports: the caller's own read reports it again
    }
    ::_exit(0);
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM) {
    throw InputError(
        fmt::format("{}: the HDF5 library did not finish reading it in {} s: the {} is damaged",
                    file.string(), seconds, what));
  }
  // A sanitizer build's child exits 1 after its report instead of dying by the signal.
  if (WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) != 0)) {
    throw InputError(fmt::format(
        "{}: the HDF5 library crashed reading it ({}): the {} is damaged", file.string(),
        WIFSIGNALED(status) ? std::string(strsignal(WTERMSIG(status)))
                            : fmt::format("exit status {}", WEXITSTATUS(status)),
        what));
  }
}

}  // namespace sf
