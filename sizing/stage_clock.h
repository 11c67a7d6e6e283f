// CPU and wall time of the stages of a sizing that `camopt run --timings` reports beside its own
// phases: the verification of the answer by the accurate model and the re-solves that price its
// binding limits, taken out of the solve phase (docs/performance.md, "camopt run of every example").
// The outermost open stage is charged: a verification inside a limit's re-solve is part of the
// limit costs. Nothing is recorded unless the caller started the clock on its thread.
#pragma once

#include <string>
#include <vector>

namespace camopt::sizing {

/// The process's CPU time so far [s] (user + system, every thread: CLOCK_PROCESS_CPUTIME_ID).
double ProcessCpuSeconds();
/// A monotonic wall clock [s].
double WallSeconds();

struct StageTime {
  std::string name;
  double cpu_s = 0.0, wall_s = 0.0;  ///< the process's CPU time (every thread) and wall time [s]
};

class StageClock {
 public:
  /// Clears the totals and records on this thread from now on.
  static void Start();
  /// The totals in the order each stage was first entered; stops recording.
  static std::vector<StageTime> Stop();

  /// One stage, from construction to destruction.
  class Scope {
   public:
    explicit Scope(const char* name);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    const char* name_;
    bool entered_ = false, charged_ = false;
    double cpu_ = 0.0, wall_ = 0.0;
  };
};

}  // namespace camopt::sizing
