#pragma once
// MPI for the sheetform command (issue 17): initialised only when the process was started by an
// MPI launcher (mpirun, mpiexec, srun), so that a plain `sheetform run` never touches MPI, and
// finalised on the way out. Threads: MPI_THREAD_FUNNELED (only the main thread calls MPI; the
// OpenMP regions never do).
#include <cstdint>
#include <string>

namespace sf {

class MpiSession {
 public:
  /// Initialises MPI if a launcher started this process; throws std::runtime_error when MPI
  /// cannot give MPI_THREAD_FUNNELED.
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  bool active() const { return active_; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  /// Ranks on this machine (the launcher's local size; size() when it does not say).
  int local_size() const;

  /// Whether every rank has the same `digest` (collective; true when not active).
  bool same_on_all_ranks(std::uint64_t digest) const;

  /// Rank 0's `text` on every rank (collective; identity when not active).
  std::string broadcast_from_root(const std::string& text) const;

  /// Waits for every rank (no-op when not active): a rank that stops with an error code waits
  /// for rank 0 to finish reporting, as the launcher kills the others when one exits non-zero.
  void barrier() const;

  /// Ends every rank of the run with `code` (after an error that only this rank met: the others
  /// would otherwise wait for it forever).
  [[noreturn]] void abort(int code) const;

 private:
  bool active_ = false;
  int rank_ = 0;
  int size_ = 1;
};

/// Whether an MPI launcher started this process (its environment variables).
bool launched_by_mpi();

}  // namespace sf
