// Benchmarks of the transmission rigidity chain and the LCR stiffness (docs/performance.md).
#include <benchmark/benchmark.h>

#include "model/rigidity/chain_elements.h"
#include "model/rigidity/lcr_stiffness.h"
#include "tests/reference_designs.h"

namespace rigidity_bench {

using namespace camopt;
using namespace camopt::rigidity;

std::vector<ElementSpec> Gearbox() {
  return {
      {ElementKind::kShaftTorsion, "", "", {}, {80000, 19, 0, 60}},
      {ElementKind::kCoupling, "", "", {}, {3e6}},
      {ElementKind::kShaftTorsion, "", "", {}, {80000, 20, 0, 80}},
      {ElementKind::kGearStage, "", "", {}, {5, 4e5, 100}},
      {ElementKind::kShaftTorsion, "", "", {}, {80000, 40, 0, 150}},
      {ElementKind::kLeverSection, "", "", {}, {206000, 20, 40, 120}},
  };
}

void BM_ChainEvaluate(benchmark::State& state) {
  const auto specs = Gearbox();
  for (auto _ : state) benchmark::DoNotOptimize(EvaluateChain(specs).compliance_b);
}
BENCHMARK(BM_ChainEvaluate);

void BM_ChainElasticities(benchmark::State& state) {
  const auto specs = Gearbox();
  for (auto _ : state) benchmark::DoNotOptimize(RigidityElasticities(specs));
}
BENCHMARK(BM_ChainElasticities);

void BM_LcrDeflectAtAngle(benchmark::State& state) {
  const auto r = camopt::testing::LcrII();
  const double clearance = state.range(0) * 1e-3;
  double theta = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(DeflectAtAngle<double>(r, camopt::testing::Steel(), theta, 80000.0, clearance));
    theta += 1e-3;
  }
}
BENCHMARK(BM_LcrDeflectAtAngle)->Arg(0)->Arg(5);

void BM_LcrDeflectAtAngleBearing(benchmark::State& state) {
  const auto r = camopt::testing::LcrII();
  double theta = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(DeflectAtAngle<double>(r, camopt::testing::Steel(), theta, 80000.0, 0.005, 1.5e5));
    theta += 1e-3;
  }
}
BENCHMARK(BM_LcrDeflectAtAngleBearing);

void BM_LcrDeflectAtAngleJet4(benchmark::State& state) {
  using J = ceres::Jet<double, 4>;
  lcr::Reducer<J> r = camopt::testing::LcrII().cast<J>();
  r.eccentricity.v[0] = 1;
  r.output.turret_radius.v[1] = 1;
  r.input.cam_thickness.v[2] = 1;
  J torque(80000.0, 3);
  for (auto _ : state)
    benchmark::DoNotOptimize(DeflectAtAngle<J>(r, camopt::testing::Steel(), J(0.3), torque, J(0.0)));
}
BENCHMARK(BM_LcrDeflectAtAngleJet4);

void BM_LcrStiffnessCycle720(benchmark::State& state) {
  const auto r = camopt::testing::LcrII();
  for (auto _ : state)
    benchmark::DoNotOptimize(StiffnessCycle(r, camopt::testing::Steel(), 80000.0, 0.0, 720));
}
BENCHMARK(BM_LcrStiffnessCycle720)->Unit(benchmark::kMillisecond);

}  // namespace rigidity_bench
