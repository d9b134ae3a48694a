#pragma once
// Writes that a kill of the run cannot cut in half (issue 31). A write of the results (a frame,
// history rows, a checkpoint) changes more than one file, and no system call changes two files
// at once: results.h5 gets its frame and then its frame count, then every part's .xdmf is
// replaced. However they are ordered, a process killed between two of these steps leaves files
// that disagree. So the steps run in a child process of its own process group that ignores the
// catchable signals, and the run waits for it: a SIGKILL (or Ctrl-C, SIGTERM, SIGHUP, a kill of
// the process group) of the run lands before the write or after it, and a write under way when
// the run dies is finished by the child, which then exits. Only a kill of both processes at once
// (every process of a job or container) or a power loss can still land inside a write; the order
// of the steps then keeps every listed frame readable (docs/results-format.md).
#include <functional>

namespace sf {

/// Runs `write` (which must change nothing in this process's memory that the caller relies on:
/// the child has its own copy) in a detached child process and waits for it to end. An exception
/// `write` throws is thrown again here, with its message and its kind: sf::InputError,
/// sf::OutputError, std::invalid_argument, else std::runtime_error. A child that dies (a crash in
/// a library) is an sf::OutputError. When the process cannot fork (no memory for it), `write`
/// runs here.
void run_detached(const std::function<void()>& write);

}  // namespace sf
