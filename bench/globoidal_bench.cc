// Globoidal cam stages: one working-surface point (double and ceres::Jet with 7 partials), the
// surface grid of the study (720 cam angles × 7 axis points × 2 rollers), and the contact
// dynamics over one cam revolution (CVODE; speed against error in the tolerance, against a
// reference RK4 run at a tiny fixed step).
#include <benchmark/benchmark.h>
#include <ceres/jet.h>

#include <cmath>
#include <map>

#include "model/globoidal/contact_dynamics.h"
#include "model/globoidal/paper_example.h"
#include "tests/globoidal_reference_rk4.h"

namespace globoidal_bench {

using namespace camopt;
using namespace camopt::globoidal;

void BM_GloboidalSurfacePoint(benchmark::State& state) {
  const auto cam = PaperExampleCam<double>();
  double t = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(EvaluateSurface(cam, 1, 22.0, t));
    t = t > 6.28 ? 0.0 : t + 0.001;
  }
}
BENCHMARK(BM_GloboidalSurfacePoint);

void BM_GloboidalSurfacePointJet7(benchmark::State& state) {
  using J = ceres::Jet<double, 7>;
  const auto cam = PaperExampleCam<J>(J(45.0, 0), J(4.0, 1), J(22.0, 2), J(kPi / 4, 3),
                                      J(kPi / 9, 4));
  double t = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(EvaluateSurface(cam, 1, J(22.0, 5), J(t, 6)));
    t = t > 6.28 ? 0.0 : t + 0.001;
  }
}
BENCHMARK(BM_GloboidalSurfacePointJet7);

void BM_GloboidalSurfaceGrid(benchmark::State& state) {
  const auto cam = PaperExampleCam<double>();
  for (auto _ : state) {
    double acc = 0;
    for (int i = 0; i < 720; ++i)
      for (int j = 1; j <= 2; ++j)
        for (int k = 0; k < 7; ++k)
          acc += EvaluateSurface(cam, j, 19.5 + k, 2 * kPi * i / 720).undercut_margin;
    benchmark::DoNotOptimize(acc);
  }
}
BENCHMARK(BM_GloboidalSurfaceGrid)->Unit(benchmark::kMillisecond);

// The example's dynamics: one revolution at `rpm` (500 N·m, J = 0.001 kg·m², C_max = 10 N·s/mm,
// d = 0.1 mm as in studies/examples/globoidal_cam_paper.json).
DynamicsInput ExampleRun(double rpm) {
  DynamicsInput in;
  in.cam = PaperExampleCam<double>();
  in.cam_speed_rad_s = 2 * kPi * rpm / 60;
  in.load_torque_Nmm = 500e3;
  in.inertia_Nmms2 = 1.0;
  in.contact.penetration_depth_mm = 0.1;
  in.end_time_s = 60.0 / rpm;
  in.output_interval_s = in.end_time_s / 2000;
  return in;
}

// Reference peaks at a tiny RK4 step (1e-7 s), computed once per speed.
const globoidal::testing::ReferencePeaks& Reference(int rpm) {
  static std::map<int, globoidal::testing::ReferencePeaks> cache;
  auto it = cache.find(rpm);
  if (it == cache.end()) it = cache.emplace(rpm, globoidal::testing::ReferenceRk4(ExampleRun(rpm), 1e-7)).first;
  return it->second;
}

// Args: cam speed [rpm], −log10 of the relative tolerance. Counters: solver steps, right-hand
// sides, the peaks and their relative errors against the reference.
void BM_GloboidalDynamicsTolerance(benchmark::State& state) {
  const int rpm = int(state.range(0));
  DynamicsInput in = ExampleRun(rpm);
  in.relative_tolerance = std::pow(10.0, -double(state.range(1)));
  DynamicsResult r;
  for (auto _ : state) benchmark::DoNotOptimize(r = SimulateDynamics(in));
  const globoidal::testing::ReferencePeaks& ref = Reference(rpm);
  state.counters["steps"] = double(r.steps);
  state.counters["rhs"] = double(r.rhs_evaluations);
  state.counters["acc"] = r.peaks.swing_acc_rad_s2;
  state.counters["force"] = r.peaks.force_N[0];
  state.counters["acc_err"] = r.peaks.swing_acc_rad_s2 / ref.swing_acc_rad_s2 - 1;
  state.counters["force_err"] = r.peaks.force_N[0] / ref.force_N[0] - 1;
  state.counters["t_acc"] = r.peaks.swing_acc_time_s;
}
BENCHMARK(BM_GloboidalDynamicsTolerance)
    ->ArgsProduct({{600, 120}, {6, 7, 8, 9, 10, 11, 12}})
    ->Unit(benchmark::kMillisecond);

// The fixed-step RK4 (every step's peaks) at step 10^(−Arg) s, against the same reference.
void BM_GloboidalDynamicsFixedStepRk4(benchmark::State& state) {
  const int rpm = int(state.range(0));
  const double h = std::pow(10.0, -double(state.range(1)) / 2);
  const DynamicsInput in = ExampleRun(rpm);
  globoidal::testing::ReferencePeaks r;
  for (auto _ : state) benchmark::DoNotOptimize(r = globoidal::testing::ReferenceRk4(in, h));
  const globoidal::testing::ReferencePeaks& ref = Reference(rpm);
  state.counters["steps"] = double(r.steps);
  state.counters["rhs"] = 4.0 * double(r.steps);
  state.counters["acc"] = r.swing_acc_rad_s2;
  state.counters["force"] = r.force_N[0];
  state.counters["acc_err"] = r.swing_acc_rad_s2 / ref.swing_acc_rad_s2 - 1;
  state.counters["force_err"] = r.force_N[0] / ref.force_N[0] - 1;
  state.counters["t_acc"] = r.swing_acc_time_s;
}
// Arg 2: 2·(−log10 h): 10 → 1e-5 s (the old default), 11 → 3.2e-6 s, 12 → 1e-6 s, 14 → 1e-7 s.
BENCHMARK(BM_GloboidalDynamicsFixedStepRk4)
    ->ArgsProduct({{600, 120}, {10, 11, 12, 14}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace globoidal_bench
