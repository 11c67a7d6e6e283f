// Speed of the cycloid sizing (docs/performance.md, "Cycloid sizing"):
//   build/camopt_bench --benchmark_filter=CycloidMinSize
// The ratio-29 drive of studies/examples/cycloid_min_size_ratio29.json solved directly (Ipopt,
// 2 starts, 16 × 16 cells, 4 crank angles per mesh period, the verified-optimum loop): the time
// split between the LTCA cycles (values), their implicit derivatives (gradients) and the accurate
// re-check (verification) is reported as counters [s], with the model runs.
#include <benchmark/benchmark.h>

#include "sizing/cycloid_min_size.h"
#include "bench/example_study.h"
#include "tests/reference_designs.h"

namespace camopt::sizing {
namespace cycloid_min_size_bench {

void BM_CycloidMinSizeRatio29(benchmark::State& state) {
  CycloidMinSizeOptions o;
  o.solver.backend = state.range(0) == 0 ? optimizers::Backend::kIpopt : optimizers::Backend::kSlsqp;
  o.solver.tolerance = 1e-6;
  o.solver.constraint_tolerance = 1e-3;
  o.solver.stall_iterations = 3;
  o.solver.stall_violation = 1.0;
  o.solver.stall_change = 1e-4;
  o.solver.max_evaluations = 200;
  o.starts = 2;
  CycloidMinSizeOutcome r;
  // (DoNotOptimize is not given r's doubles: its "+r" constraint on a double field corrupted
  // it here with GCC 12 -O1 and above; the solve has effects that cannot be optimised away.)
  for (auto _ : state) r = SolveCycloidMinSize(camopt::testing::CycloidRatio29Sizing(cycloid::CrowningType::kLogarithmic, 40), o);
  state.counters["values_s"] = r.value_seconds;
  state.counters["gradients_s"] = r.gradient_seconds;
  state.counters["verification_s"] = r.verification_seconds;
  state.counters["model_runs"] = r.evaluations;
  state.counters["gradient_runs"] = r.gradient_evaluations;
  state.counters["D_mm"] = r.check.accurate.outer_diameter_mm;
  state.counters["verified"] = r.verified ? 1 : 0;
}
BENCHMARK(BM_CycloidMinSizeRatio29)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(1);

// The example studies themselves, as `camopt run` runs them (parse, sizing, the accurate cycle of
// the best design for the plots, the files): ratio 29 (SLSQP) and the paper's drive (Ipopt).
void BM_CycloidMinSizeRatio29Study(benchmark::State& state) { bench::RunExampleStudy(state, "cycloid_min_size_ratio29.json"); }
void BM_CycloidMinSizePaperStudy(benchmark::State& state) { bench::RunExampleStudy(state, "cycloid_min_size_paper.json"); }
BENCHMARK(BM_CycloidMinSizeRatio29Study)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_CycloidMinSizePaperStudy)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace cycloid_min_size_bench
}  // namespace camopt::sizing
