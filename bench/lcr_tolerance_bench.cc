// Benchmarks of the LCR transmission-error model: one Monte-Carlo sample of the exact
// model (LCR II, the precision grade of studies/examples/lcr_ii_tolerances.json, 72 input angles:
// per angle the exact gaps of 28 rollers and two compliant turret solves), and its linearisation.
#include <benchmark/benchmark.h>

#include "model/lcr/transmission_error.h"
#include "tests/reference_designs.h"

namespace lcr_tolerance_bench {

using namespace camopt;

lcr::ToleranceBands Grade() {
  lcr::ToleranceBands b;
  b.eccentricity_mm = 3e-3, b.turret_radius_mm = 5e-3, b.roller_diameter_mm = 2e-3;
  b.roller_pitch_rad = 10.0 * kPi / (180 * 3600), b.profile_mm = 3e-3, b.bearing_clearance_mm = 5e-3;
  return b;
}

void BM_LcrTransmissionErrorSample(benchmark::State& state) {
  const lcr::Reducer<double> r = testing::LcrII();
  const auto params = lcr::ToleranceParameters(r, Grade());
  std::vector<double> theta;
  for (int i = 0; i < state.range(0); ++i) theta.push_back(2 * kPi * i / state.range(0));
  std::uint64_t seed = 1;
  for (auto _ : state) {
    const lcr::Deviations<double> d = lcr::SampleDeviations(r, params, seed);
    benchmark::DoNotOptimize(lcr::ExactTransmissionError(r, testing::Steel(), d, 80000.0, theta));
  }
}
BENCHMARK(BM_LcrTransmissionErrorSample)->Arg(72)->Unit(benchmark::kMillisecond);

// The whole analysis without Monte-Carlo: nominal solves and the Jet<8> sensitivities of all 63
// deviations at 72 angles.
void BM_LcrTransmissionErrorLinear(benchmark::State& state) {
  const lcr::Reducer<double> r = testing::LcrII();
  lcr::TransmissionErrorOptions o;
  o.output_torque_Nmm = 80000.0, o.lost_motion_torque_Nmm = 2400.0, o.angle_steps = int(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(lcr::AnalyzeTransmissionError(r, testing::Steel(), Grade(), o));
}
BENCHMARK(BM_LcrTransmissionErrorLinear)->Arg(72)->Unit(benchmark::kMillisecond);

}  // namespace lcr_tolerance_bench
