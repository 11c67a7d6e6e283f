// Speed of the LCR pipeline: one angle (double and Jet), a whole cycle against the angle step,
// and the undercut stage. Run: build/camopt_bench --benchmark_filter=Lcr
#include <benchmark/benchmark.h>

#include "model/lcr/cycle.h"
#include "tests/reference_designs.h"

namespace lcr_bench {

using namespace camopt;

void BM_LcrAngle(benchmark::State& state) {
  const auto r = testing::LcrII();
  const lcr::LoadCase load{80000.0, 0.05, 0.0};
  double theta = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(lcr::AnalyzeAngle(r, testing::Steel(), load, theta));
    theta += 0.001;
  }
}
BENCHMARK(BM_LcrAngle);

void BM_LcrAngleJet6(benchmark::State& state) {
  using J = ceres::Jet<double, 6>;
  lcr::Reducer<J> r = testing::LcrII().cast<J>();
  r.eccentricity.v[0] = 1;
  const lcr::LoadCase load{80000.0, 0.05, 0.0};
  for (auto _ : state) benchmark::DoNotOptimize(lcr::AnalyzeAngle(r, testing::Steel(), load, J(0.3)));
}
BENCHMARK(BM_LcrAngleJet6);

// Cycle sweep versus angle steps: the error of the max input-cam roller force against 36000 steps
// is reported as a counter (N).
void BM_LcrCycle(benchmark::State& state) {
  const auto r = testing::LcrII();
  const lcr::LoadCase load{80000.0, 0.05, 0.0};
  static const double reference = [&] {
    const auto s = lcr::AnalyzeCycle(r, testing::Steel(), load, 36000, {});
    return *std::max_element(s.input.max_force_N.begin(), s.input.max_force_N.end());
  }();
  double fmax = 0;
  for (auto _ : state) {
    const auto s = lcr::AnalyzeCycle(r, testing::Steel(), load, int(state.range(0)), {});
    fmax = *std::max_element(s.input.max_force_N.begin(), s.input.max_force_N.end());
  }
  state.counters["max_force_error_N"] = reference - fmax;
}
BENCHMARK(BM_LcrCycle)->Arg(90)->Arg(360)->Arg(1440)->Arg(3600)->Unit(benchmark::kMillisecond);

void BM_LcrUndercutMargin(benchmark::State& state) {
  const auto r = testing::LcrII();
  for (auto _ : state) benchmark::DoNotOptimize(lcr::UndercutMargin(r.input, r.eccentricity));
}
BENCHMARK(BM_LcrUndercutMargin);

// One full cycle of both cams as the optimizers see it (AggregateCycle: forces, stresses,
// efficiency, soft maxima), in double; the Jet6 twin below is its value with exact gradient.
void BM_LcrCycleAggregates(benchmark::State& state) {
  const lcr::Reducer<double> r = testing::LcrII();
  for (auto _ : state)
    benchmark::DoNotOptimize(lcr::AggregateCycle(r, testing::Steel(), {80000.0, 0.05, 0.0}, int(state.range(0))));
}
BENCHMARK(BM_LcrCycleAggregates)->Arg(90)->Arg(360)->Unit(benchmark::kMicrosecond);

void BM_LcrCycleAggregatesJet6(benchmark::State& state) {
  using J = ceres::Jet<double, 6>;
  lcr::Reducer<J> r = testing::LcrII().cast<J>();
  r.eccentricity.v[0] = 1;
  for (auto _ : state)
    benchmark::DoNotOptimize(lcr::AggregateCycle(r, testing::Steel(), {80000.0, 0.05, 0.0}, int(state.range(0))));
}
BENCHMARK(BM_LcrCycleAggregatesJet6)->Arg(90)->Arg(360)->Unit(benchmark::kMicrosecond);

}  // namespace lcr_bench
