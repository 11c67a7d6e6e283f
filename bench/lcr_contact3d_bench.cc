// Speed of the LCR finite-length contact: one slices contact (value; value + gradient
// by the implicit step with a Jet of 4), one half_space contact, and an LCR II cycle with the
// slices model. Run: build/camopt_bench --benchmark_filter=Contact3D
#include <benchmark/benchmark.h>

#include "model/contact/roller_half_space.h"
#include "model/lcr/contact3d.h"
#include "model/lcr/contact3d_cycle.h"
#include "tests/reference_designs.h"

namespace lcr_contact3d_bench {

using namespace camopt;

// LCR II's worst output contact at 80 N·m (F = 835 N, R' = 2.02 mm, l = 8 mm), crowned
// f = 0.01 mm, Le = 10.5 mm, 0.5 mrad.
lcr::RollerCrowning<double> Crown() {
  lcr::RollerCrowning<double> c;
  c.type = contact::CrowningType::kLogarithmic;
  c.coefficient = 0.01;
  c.effective_length = 10.5;
  return c;
}

void BM_Contact3DSlices(benchmark::State& state) {
  const double e_star = testing::Steel().composite_modulus_MPa();
  for (auto _ : state)
    benchmark::DoNotOptimize(lcr::RollerContactSlices<double>(835.0, 2.02, 8.0, e_star, Crown(), 5e-4, int(state.range(0))));
}
BENCHMARK(BM_Contact3DSlices)->Arg(20)->Arg(40)->Arg(80)->Unit(benchmark::kMicrosecond);

void BM_Contact3DSlicesGradient(benchmark::State& state) {
  using J = ceres::Jet<double, 4>;
  const double e_star = testing::Steel().composite_modulus_MPa();
  lcr::RollerCrowning<J> c = Crown().cast<J>();
  c.coefficient.v[2] = 1;
  for (auto _ : state)
    benchmark::DoNotOptimize(lcr::RollerContactSlices<J>(J(835.0, 0), J(2.02, 1), J(8.0), e_star, c, J(5e-4, 3),
                                                         int(state.range(0))));
}
BENCHMARK(BM_Contact3DSlicesGradient)->Arg(20)->Arg(40)->Arg(80)->Unit(benchmark::kMicrosecond);

void BM_Contact3DHalfSpace(benchmark::State& state) {
  const double e_star = testing::Steel().composite_modulus_MPa();
  contact::HalfSpaceSolver solver;
  const auto c = Crown();
  for (auto _ : state)
    benchmark::DoNotOptimize(contact::SolveRollerHalfSpace(
        835.0, 2.02, 8.0, e_star, [&](double y) { return lcr::GapAlongRoller(c, 5e-4, y); }, int(state.range(0)),
        int(state.range(1)), 0.0, solver));
}
BENCHMARK(BM_Contact3DHalfSpace)->Args({32, 128})->Args({48, 256})->Unit(benchmark::kMillisecond);

// The slices model over a revolution of LCR II (both cams), after AnalyzeCycle.
void BM_Contact3DLcrCycle(benchmark::State& state) {
  const auto r = testing::LcrII();
  const lcr::LoadCase load{80000.0, 0.05, 0.0};
  const auto series = lcr::AnalyzeCycle(r, testing::Steel(), load, int(state.range(0)), {});
  lcr::ContactModelOptions o;
  o.model = lcr::ContactModel::kSlices;
  o.misalignment_rad = 5e-4;
  const double e_star = testing::Steel().composite_modulus_MPa();
  for (auto _ : state)
    for (lcr::Side s : {lcr::Side::kInput, lcr::Side::kOutput})
      benchmark::DoNotOptimize(lcr::AnalyzeCycleContact3D(r, s, series, e_star, Crown(), o));
}
BENCHMARK(BM_Contact3DLcrCycle)->Arg(360)->Arg(3600)->Unit(benchmark::kMillisecond);

}  // namespace lcr_contact3d_bench
