// Disc cam stages: motion-law evaluation, one cam revolution (profile, angles, curvature,
// mechanical error) in double and ceres::Jet, the exact follower position and a Monte-Carlo sample.
#include <benchmark/benchmark.h>
#include <ceres/jet.h>

#include "model/disc_cam/disc_cam.h"
#include "model/disc_cam/exact_motion.h"
#include "model/disc_cam/mechanical_error.h"
#include "tests/reference_designs.h"

namespace disc_cam_bench {

using namespace camopt;
using namespace camopt::disc_cam;
using motion::MotionLaw;

// The paper's example (tests/reference_designs.h).
template <typename T>
DiscCamTpl<T> PaperCam() {
  return camopt::testing::DiscCamPaperExample<T>();
}

void BM_MotionLawModifiedSine(benchmark::State& state) {
  double u = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(motion::NormalizedLaw(MotionLaw::kModifiedSine, u));
    u = u > 1.0 ? 0.0 : u + 0.001;
  }
}
BENCHMARK(BM_MotionLawModifiedSine);

template <typename T>
void Revolution(const DiscCamTpl<T>& cam, int n, benchmark::State& state) {
  const Deviations<T> tol{T(0.0), T(0.019), T(0.009)};
  for (auto _ : state) {
    T worst(0.0);
    for (int i = 0; i < n; ++i) {
      const CamPoint<T> p = EvaluateCam(cam, T(2 * kPi * i / n));
      const MechanicalError<T> e = FollowerError(cam, p, tol);
      if (Value(e.worst_case) > Value(worst)) worst = e.worst_case;
    }
    benchmark::DoNotOptimize(worst);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

void BM_RevolutionDouble3600(benchmark::State& state) { Revolution(PaperCam<double>(), 3600, state); }
BENCHMARK(BM_RevolutionDouble3600)->Unit(benchmark::kMillisecond);

void BM_RevolutionJet4x3600(benchmark::State& state) {
  using J = ceres::Jet<double, 4>;
  DiscCamTpl<J> cam = PaperCam<J>();
  cam.base_radius = J(40.0, 0);
  cam.roller_radius = J(10.0, 1);
  cam.offset = J(12.0, 2);
  Revolution(cam, 3600, state);
}
BENCHMARK(BM_RevolutionJet4x3600)->Unit(benchmark::kMillisecond);

void BM_ExactFollowerPosition(benchmark::State& state) {
  const DiscCam cam = PaperCam<double>();
  double t = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(ExactFollowerPosition(cam, {0.0, 0.019, 0.009}, t));
    t += 0.01;
  }
}
BENCHMARK(BM_ExactFollowerPosition)->Unit(benchmark::kMicrosecond);

void BM_MonteCarloSample360(benchmark::State& state) {
  const DiscCam cam = PaperCam<double>();
  MonteCarloOptions o;
  o.samples = 1;
  o.angle_steps = 360;
  o.scales = {1.0};
  for (auto _ : state) benchmark::DoNotOptimize(MonteCarloLinearisation(cam, {0.0, 0.019, 0.009}, o));
}
BENCHMARK(BM_MonteCarloSample360)->Unit(benchmark::kMillisecond);

}  // namespace disc_cam_bench
