// Speed of the cycloid sizing (docs/performance.md, "Cycloid sizing"):
//   build/camopt_bench --benchmark_filter=CycloidMinSize
// The ratio-29 drive of studies/examples/cycloid_min_size_ratio29.json solved directly (Ipopt,
// 2 starts, 16 × 16 cells, 4 crank angles per mesh period, the verified-optimum loop): the time
// split between the LTCA cycles (values), their implicit derivatives (gradients) and the accurate
// re-check (verification) is reported as counters [s], with the model runs.
#include <benchmark/benchmark.h>

#include "objectives/cycloid_min_size.h"

namespace camopt::objectives {
namespace {

CycloidSizingSpec Ratio29() {
  CycloidSizingSpec s;
  s.drive.teeth = 29;
  s.drive.rollers = 30;
  s.drive.roller_position_radius_mm = 35;
  s.drive.roller_radius_mm = 2.5;
  s.drive.eccentricity_mm = 0.9;
  s.drive.face_width_mm = 8;
  s.drive.delta_position_mm = -0.010;
  s.drive.delta_radius_mm = -0.005;
  s.crowning.type = cycloid::CrowningType::kLogarithmic;
  s.crowning.coefficient_mm = 0.002;
  s.design_torque_Nmm = 20e3;
  s.overload_torque_Nmm = 40e3;
  s.angles_per_period = 4;
  s.options.profile_cells = 16;
  s.options.axial_cells = 16;
  s.limits.contact_stress_MPa = 1500;
  s.variables = {{"eccentricity_mm", 0.3, 2.0, 0.9, 0.1},
                 {"roller_position_radius_mm", 8.0, 60.0, 35.0, 10.0},
                 {"roller_radius_mm", 0.5, 5.0, 2.5, 1.0},
                 {"delta_position_um", -30.0, 0.0, -10.0, 10.0},
                 {"delta_radius_um", -30.0, 0.0, -5.0, 10.0},
                 {"coefficient_mm", 0.0, 0.02, 0.002, 0.001}};
  return s;
}

void BM_CycloidMinSizeRatio29(benchmark::State& state) {
  CycloidMinSizeOptions o;
  o.solver.backend = state.range(0) == 0 ? "ipopt" : "slsqp";
  o.solver.tolerance = 1e-6;
  o.solver.constraint_tolerance = 1e-3;
  o.solver.stall_iterations = 3;
  o.solver.stall_violation = 1.0;
  o.solver.max_evaluations = 200;
  o.starts = 2;
  CycloidMinSizeOutcome r;
  // (DoNotOptimize is not given r's doubles: its "+r" constraint on a double field corrupted
  // it here with GCC 12 -O1 and above; the solve has effects that cannot be optimised away.)
  for (auto _ : state) r = SolveCycloidMinSize(Ratio29(), o);
  state.counters["values_s"] = r.value_seconds;
  state.counters["gradients_s"] = r.gradient_seconds;
  state.counters["verification_s"] = r.verification_seconds;
  state.counters["model_runs"] = r.evaluations;
  state.counters["gradient_runs"] = r.gradient_evaluations;
  state.counters["D_mm"] = r.check.accurate.outer_diameter_mm;
  state.counters["verified"] = r.verified ? 1 : 0;
}
BENCHMARK(BM_CycloidMinSizeRatio29)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace camopt::objectives
