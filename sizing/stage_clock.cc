#include "sizing/stage_clock.h"

#include <chrono>
#include <ctime>

namespace camopt::sizing {

namespace {

struct State {
  bool on = false;
  int depth = 0;
  std::vector<StageTime> totals;
};

State& ThisThread() {
  thread_local State state;
  return state;
}

}  // namespace

double ProcessCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double WallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void StageClock::Start() {
  State& s = ThisThread();
  s = State{};
  s.on = true;
}

std::vector<StageTime> StageClock::Stop() {
  State& s = ThisThread();
  s.on = false;
  return std::move(s.totals);
}

StageClock::Scope::Scope(const char* name) : name_(name) {
  State& s = ThisThread();
  if (!s.on) return;
  entered_ = true;
  if (s.depth++ == 0) {
    charged_ = true;
    cpu_ = ProcessCpuSeconds();
    wall_ = WallSeconds();
  }
}

StageClock::Scope::~Scope() {
  State& s = ThisThread();
  if (!entered_ || !s.on) return;
  --s.depth;
  if (!charged_) return;
  const double cpu = ProcessCpuSeconds() - cpu_, wall = WallSeconds() - wall_;
  for (StageTime& t : s.totals)
    if (t.name == name_) {
      t.cpu_s += cpu, t.wall_s += wall;
      return;
    }
  s.totals.push_back({name_, cpu, wall});
}

}  // namespace camopt::sizing
