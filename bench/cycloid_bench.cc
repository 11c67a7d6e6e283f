// Speed of the cycloid drive stages (docs/performance.md, "Cycloid drive"):
//   build/camopt_bench --benchmark_filter=Cycloid
// A full 60-angle mesh cycle of the paper's example (NNM, 350 N·m, 40 × 40 cells per pair) from a
// fresh LoadedTca (cold kernel cache, as a study run), and the crowning tuning example study.
#include <filesystem>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include "model/cycloid/loaded_tca.h"
#include "model/cycloid/unloaded_tca.h"
#include "bench/example_study.h"
#include "tests/reference_designs.h"


namespace camopt::cycloid {
namespace cycloid_bench {

using camopt::testing::CycloidNnm;

Crowning Case(int k) {
  Crowning c;
  if (k == 1) {
    c.type = CrowningType::kFull;
    c.radius_mm = 3000;
  } else if (k == 2) {
    c.type = CrowningType::kPartial;
    c.radius_mm = 4500;
    c.flat_length_mm = 13.6;
  } else if (k == 3) {
    c.type = CrowningType::kLogarithmic;
    c.coefficient_mm = 0.005;
  }
  return c;
}

void BM_CycloidUnloadedTca(benchmark::State& state) {
  const Drive d = CycloidNnm();
  double a = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(UnloadedTca<double>(d, a));
    a += 0.1;
  }
}
BENCHMARK(BM_CycloidUnloadedTca);

// Arg: crowning case 0 none, 1 FCM, 2 PCM, 3 LCM.
void BM_CycloidMeshCycle60(benchmark::State& state) {
  const auto angles = UniformCrankAngles(60, 2 * kPi);
  CycleResult r;
  for (auto _ : state) {
    LoadedTca tca(CycloidNnm(), Case(int(state.range(0))), Material{}, LoadedOptions{});
    r = RunCycle(tca, 350.0e3, angles);
    benchmark::DoNotOptimize(r.max_pressure_MPa);
  }
  state.counters["max_MPa"] = r.max_pressure_MPa;
  state.counters["solves"] = r.contact_solves;
  state.counters["solves_per_angle"] = r.contact_solves / 60.0;
  state.counters["cg_iters"] = double(r.solver_iterations);
  state.counters["slope_cg_iters"] = double(r.slope_iterations);
}
BENCHMARK(BM_CycloidMeshCycle60)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->Iterations(2);

// One mesh period at the cycloid_ltca default (32 angles), no error estimate. Args: crowning case;
// the gear ratio's implicit crank slope at every solve (LoadedOptions::crank_slope) off / on.
void BM_CycloidMeshPeriod32(benchmark::State& state) {
  const auto angles = UniformCrankAngles(32, 2 * kPi / 16);
  LoadedOptions o;
  o.crank_slope = state.range(1) == 1;
  CycleResult r;
  for (auto _ : state) {
    LoadedTca tca(CycloidNnm(), Case(int(state.range(0))), Material{}, o);
    r = RunCycle(tca, 350.0e3, angles);
    benchmark::DoNotOptimize(r.max_pressure_MPa);
  }
  state.counters["solves"] = r.contact_solves;
  state.counters["cg_iters"] = double(r.solver_iterations);
}
BENCHMARK(BM_CycloidMeshPeriod32)->ArgsProduct({{0, 1, 2, 3}, {0, 1}})->Unit(benchmark::kMillisecond)->Iterations(2);

// One LTCA solve (40 x 40, LCM with L = 18.7 mm, 120°) and, Arg 1, the same solve followed by its
// implicit derivatives for one parameter (coefficient_mm): the gradient's cost over the value's.
void BM_CycloidSolveAndDerivative(benchmark::State& state) {
  Crowning c;
  c.type = CrowningType::kLogarithmic;
  c.coefficient_mm = 0.004;
  c.effective_length_mm = 18.7;
  const LoadedTca tca(CycloidNnm(), c, Material{}, LoadedOptions{});
  tca.Solve(350.0e3, 2.0);  // kernels and plans cached: the pure model's answer does not change
  for (auto _ : state) {
    const MeshLoad m = tca.Solve(350.0e3, 2.0944);
    if (state.range(0) == 1) benchmark::DoNotOptimize(tca.Differentiate(m, "coefficient_mm").deflection_rad);
    benchmark::DoNotOptimize(m.max_pressure_MPa);
  }
}
BENCHMARK(BM_CycloidSolveAndDerivative)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(10);


// The 60-angle cycle of the LCM example (L = 18.7 mm) from a warm model, Arg 0: its value;
// Arg 1: the value and the cycle's implicit derivatives w.r.t. f, Δa and Δρ (DifferentiateCycle,
// CG tolerance: second Arg × 1e-6; the tuning and sizing use the solver tolerance, 1e-4 by
// default); third Arg: the crank slope on (the analysis) or off (the tuning and sizing loops).
// The gradient's share is the difference.
void BM_CycloidCycle60Gradient(benchmark::State& state) {
  Crowning c;
  c.type = CrowningType::kLogarithmic;
  c.coefficient_mm = 0.0035;
  c.effective_length_mm = 18.7;
  LoadedOptions o;
  o.sensitivity_tolerance = state.range(1) * 1e-6;
  o.crank_slope = state.range(2) != 0;
  const LoadedTca tca(CycloidNnm(), c, Material{}, o);
  const auto angles = UniformCrankAngles(60, 2 * kPi);
  RunCycle(tca, 350.0e3, angles);  // kernels and plans cached (cost only)
  for (auto _ : state) {
    const CycleResult r = RunCycle(tca, 350.0e3, angles);
    if (state.range(0) == 1) {
      const std::vector<CycleDerivative> d =
          DifferentiateCycle(tca, r, {"coefficient_mm", "delta_position_mm", "delta_radius_mm"}, 2.0);
      benchmark::DoNotOptimize(d.front().smooth_peak_MPa);
      state.counters["gradient_cg_iters"] = double(d.front().cg_iterations);
    }
    state.counters["solver_iters"] = double(r.solver_iterations);
    state.counters["slope_iters"] = double(r.slope_iterations);
    benchmark::DoNotOptimize(r.max_pressure_MPa);
  }
}
// {value only / value + gradient, sensitivity tolerance [1e-6], crank slope off / on}: the
// tuning and sizing loops run with the slope off.
BENCHMARK(BM_CycloidCycle60Gradient)
    ->Args({0, 1, 1})
    ->Args({1, 1, 1})
    ->Args({1, 100, 1})
    ->Args({0, 100, 0})
    ->Args({1, 100, 0})
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(3)
    ->Iterations(1);

// The joint tuning example (Ipopt, f with Δa and Δρ).
void BM_CycloidJointTuningStudy(benchmark::State& state) {
  bench::RunExampleStudy(state, "cycloid_crowning_tuning_joint_nnm.json");
}

// The cycloid_ltca example without crowning: 32 angles per mesh period and its error estimate.
void BM_CycloidLtcaExampleStudy(benchmark::State& state) { bench::RunExampleStudy(state, "cycloid_ltca_nnm_none.json"); }
BENCHMARK(BM_CycloidLtcaExampleStudy)->Unit(benchmark::kMillisecond)->Iterations(2);

void BM_CycloidCrowningTuningStudy(benchmark::State& state) {
  bench::RunExampleStudy(state, "cycloid_crowning_tuning_nnm.json");
}
BENCHMARK(BM_CycloidCrowningTuningStudy)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_CycloidJointTuningStudy)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace cycloid_bench
}  // namespace camopt::cycloid
