// sizing/stage_clock.h: the stages of a sizing that `camopt run --timings` reports, against a
// clock read around them here.
#include <chrono>
#include <ctime>

#include <gtest/gtest.h>

#include "sizing/stage_clock.h"

namespace camopt::sizing {
namespace {

double ProcessCpu() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Burns about `seconds` of CPU time.
void Busy(double seconds) {
  const double end = ProcessCpu() + seconds;
  volatile double x = 1.0;
  while (ProcessCpu() < end) x = x * 1.0000001 + 1e-9;
}

// A stage inside another is charged to the outer one (its time counted once); the totals come in
// the order first entered, a stage entered twice adds up; their CPU time is what a clock read
// around the scopes here says, within a few milliseconds.
TEST(StageClock, TheOutermostOpenStageIsChargedOnce) {
  StageClock::Start();
  const double t0 = ProcessCpu();
  {
    const StageClock::Scope outer("limit costs");
    Busy(0.02);
    const StageClock::Scope inner("verification");  // inside the limit costs: not a stage of its own
    Busy(0.02);
  }
  const double t1 = ProcessCpu();
  {
    const StageClock::Scope v("verification");
    Busy(0.01);
  }
  {
    const StageClock::Scope v("verification");
    Busy(0.01);
  }
  const double t2 = ProcessCpu();
  const std::vector<StageTime> totals = StageClock::Stop();
  ASSERT_EQ(totals.size(), 2u);
  EXPECT_EQ(totals[0].name, "limit costs");
  EXPECT_EQ(totals[1].name, "verification");
  EXPECT_NEAR(totals[0].cpu_s, t1 - t0, 0.003);
  EXPECT_NEAR(totals[1].cpu_s, t2 - t1, 0.003);
  EXPECT_GE(totals[0].cpu_s, 0.04);
  EXPECT_GE(totals[1].cpu_s, 0.02);
  EXPECT_GE(totals[0].wall_s, 0.0);
}

// Nothing is recorded before Start or after Stop (a sizing run by a test or a library user).
TEST(StageClock, RecordsOnlyBetweenStartAndStop) {
  (void)StageClock::Stop();
  {
    const StageClock::Scope v("verification");
    Busy(0.002);
  }
  StageClock::Start();
  EXPECT_TRUE(StageClock::Stop().empty());
  {
    const StageClock::Scope v("verification");
  }
  EXPECT_TRUE(StageClock::Stop().empty());
}

}  // namespace
}  // namespace camopt::sizing
