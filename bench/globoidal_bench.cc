// Globoidal cam stages: one working-surface point (double and ceres::Jet with 7 partials), the
// surface grid of the study (720 cam angles × 7 axis points × 2 rollers), and the contact
// dynamics over one cam revolution at 600 rpm (RK4, 10 µs step).
#include <benchmark/benchmark.h>
#include <ceres/jet.h>

#include "model/globoidal/contact_dynamics.h"
#include "model/globoidal/paper_example.h"

namespace {

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

void BM_GloboidalDynamicsRevolution600rpm(benchmark::State& state) {
  DynamicsInput in;
  in.cam = PaperExampleCam<double>();
  in.cam_speed_rad_s = 2 * kPi * 10;
  in.load_torque_Nmm = 500e3;
  in.inertia_Nmms2 = 1.0;
  in.end_time_s = 0.1;
  in.time_step_s = 1e-5;
  in.output_every = 50;
  for (auto _ : state) benchmark::DoNotOptimize(SimulateDynamics(in).samples.size());
}
BENCHMARK(BM_GloboidalDynamicsRevolution600rpm)->Unit(benchmark::kMillisecond);

}  // namespace
