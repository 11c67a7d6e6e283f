// getrusage for camopt's executables (the command line, the test and benchmark binaries).
#include <sys/resource.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

#include "model/common/build_flags.h"

// Ipopt 3.11 times each of its internal tasks (IpTimedTask.hpp: two getrusage calls at a task's
// start and two at its end, for its CPU and system time) whether or not its timing statistics are
// printed, with no option to turn that off; camopt reads none of those times. A line-model sizing
// made about 10^5 such calls, each a system call (in a virtual machine a trap to the hypervisor):
// a quarter of `lcr_min_size`'s CPU. So this process's getrusage(RUSAGE_SELF) answers with the last
// answer the kernel gave on the calling thread while that is under 1 ms old (CLOCK_MONOTONIC, no
// system call), and asks the kernel again after that; RUSAGE_CHILDREN and RUSAGE_THREAD are always
// asked. The times are then at most 1 ms old, and Ipopt's `max_cpu_time` and camopt's own clocks
// (clock_gettime, sizing/stage_clock.h) are unaffected at that resolution. Compiled into each
// executable (CMakeLists.txt: camopt, camopt_with_test_kind, camopt_tests, camopt_bench), so the
// shared libraries' calls resolve to it first; the library and the Python module leave the host's
// getrusage alone. Not under the sanitizers, whose runtime intercepts getrusage itself.
#ifndef CAMOPT_SANITIZED_BUILD
extern "C" int getrusage(__rusage_who_t who, struct rusage* usage) noexcept {
  if (who != RUSAGE_SELF) return static_cast<int>(syscall(SYS_getrusage, who, usage));
  thread_local struct rusage last {};
  thread_local long long last_ns = -1;
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  const long long now_ns = now.tv_sec * 1000000000LL + now.tv_nsec;
  if (last_ns < 0 || now_ns - last_ns >= 1000000) {
    struct rusage fresh {};
    const int rc = static_cast<int>(syscall(SYS_getrusage, who, &fresh));
    if (rc != 0) return rc;
    last = fresh;
    last_ns = now_ns;
  }
  *usage = last;
  return 0;
}
#endif

