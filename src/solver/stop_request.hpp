#pragma once
// Requests that reach a run from outside, by signal: SIGINT (Ctrl-C) and SIGTERM (a batch
// system's time limit) ask it to stop cleanly at the end of the current cycle, with its last
// frame and a checkpoint written; SIGUSR1 asks for a checkpoint and goes on. A second SIGINT or
// SIGTERM ends the process at once (the default action), for a run that does not stop.
namespace sf {

/// What has been asked for since the last take_run_requests (bits; also the flags the
/// processes of a distributed run agree on, Domain::agree_flags).
enum RunRequest : int {
  request_checkpoint = 1,
  request_stop = 2,
};

/// Installs the handlers of SIGINT, SIGTERM and SIGUSR1 (again: harmless); a SIGINT the process
/// was started with ignored (a background job of a script) stays ignored.
void install_run_request_handlers();

/// Puts back the default actions of SIGINT, SIGTERM and SIGUSR1.
void restore_default_signal_actions();

/// The requests received since the last call (RunRequest bits), cleared.
int take_run_requests();

/// The name of the last signal that asked to stop ("SIGINT", "SIGTERM"), or "" for none.
const char* stop_signal_name();

}  // namespace sf
