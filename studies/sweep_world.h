// The processes of a sweep: one, or the ranks of `mpirun -n N` in a build with MPI
// (CAMOPT_HAVE_MPI). Only the sweep's main thread calls into MPI (MPI_THREAD_FUNNELED); the
// case threads never do.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace camopt::studies::sweep {

class World {
 public:
  World() = default;
  World(const World&) = delete;
  World& operator=(const World&) = delete;
  ~World();

  /// Joins the MPI job when the process was started by mpirun (or another MPI launcher) and the
  /// build has MPI; otherwise a world of one. False, with the reason, when started by a launcher
  /// with several ranks in a build without MPI (each rank would run every case).
  bool Start(std::string& why);
  int rank() const { return rank_; }
  int size() const { return size_; }
  /// Ranks on this machine (for the default number of threads per rank).
  int local_size() const { return local_size_; }

  /// Rank 0's value, on every rank.
  int BroadcastInt(int value);
  std::vector<uint64_t> BroadcastIndices(const std::vector<uint64_t>& values);
  /// On rank 0: every rank's text, concatenated in rank order; elsewhere: empty.
  std::string GatherToRoot(const std::string& mine);
  /// Ends every rank with `code` (a rank cannot go on alone).
  [[noreturn]] void Abort(int code);
  void Finish();

 private:
  int rank_ = 0, size_ = 1, local_size_ = 1;
  bool mpi_ = false;
};

}  // namespace camopt::studies::sweep
