#include "solver/stop_request.hpp"

#include <atomic>
#include <csignal>

namespace sf {

namespace {

// Written by the handlers, read by the time loop: lock-free atomics are async-signal-safe.
std::atomic<int> g_requests{0};
std::atomic<int> g_stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_run_signal(int signal_number) {
  if (signal_number == SIGUSR1) {
    g_requests.fetch_or(request_checkpoint);
    return;
  }
  g_stop_signal = signal_number;
  g_requests.fetch_or(request_stop);
  std::signal(signal_number, SIG_DFL);  // a second one ends the process
}

}  // namespace

void install_run_request_handlers() {
  for (int s : {SIGINT, SIGTERM, SIGUSR1}) {
    // A SIGINT ignored by the parent stays ignored (a job a script sent to the background, which
    // the terminal's Ctrl-C is not meant for).
    if (std::signal(s, on_run_signal) == SIG_IGN && s == SIGINT) {
      std::signal(s, SIG_IGN);
    }
  }
}

void restore_default_signal_actions() {
  for (int s : {SIGINT, SIGTERM, SIGUSR1}) {
    std::signal(s, SIG_DFL);
  }
}

int take_run_requests() {
  return g_requests.exchange(0);
}

const char* stop_signal_name() {
  switch (g_stop_signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "";
  }
}

}  // namespace sf
