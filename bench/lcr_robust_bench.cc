// Benchmarks of the sizing across tolerances (objectives/lcr_robust.h): one Monte-Carlo sample of
// the exact model as the robust check runs it (LCR II, the precision grade of
// lcr_ii_tolerances.json, 720 input angles of a revolution: per angle the exact gaps of 28
// rollers and two compliant turret solves) and the robust problem's Jacobian (samples form). The
// robust sizing study's time is measured through the CLI (docs/performance.md).
#include <benchmark/benchmark.h>

#include "objectives/lcr_robust.h"
#include "tests/reference_designs.h"

namespace lcr_robust_bench {

using namespace camopt;

objectives::LcrSizingSpec Spec() {
  objectives::LcrSizingSpec s;
  s.lobes_a = 12, s.rollers_a = 13, s.lobes_b = 14, s.rollers_b = 15;
  s.material = camopt::testing::Steel();
  s.output_torque_Nmm = 80000.0;
  s.limits.contact_stress_MPa = 1500, s.limits.roller_load_N = 1050, s.limits.undercut_margin_mm = 0.5;
  s.limits.roller_gap_mm = 1.0;
  auto rule = std::make_shared<objectives::LcrRobustRule>();
  rule->bands.eccentricity_mm = 3e-3, rule->bands.turret_radius_mm = 5e-3, rule->bands.roller_diameter_mm = 2e-3;
  rule->bands.roller_pitch_rad = 10.0 * kPi / (180 * 3600), rule->bands.profile_mm = 3e-3;
  rule->bands.bearing_clearance_mm = 5e-3;
  s.robust = rule;
  return s;
}

void BM_LcrRobustMonteCarloSample(benchmark::State& state) {
  const objectives::LcrSizingSpec s = Spec();
  const lcr::Reducer<double> r = camopt::testing::LcrII();
  std::uint64_t seed = 1;
  for (auto _ : state) benchmark::DoNotOptimize(objectives::MonteCarloCheck(s, r, 1, seed++, int(state.range(0))));
}
BENCHMARK(BM_LcrRobustMonteCarloSample)->Arg(720)->Unit(benchmark::kMillisecond);

void BM_LcrRobustJacobian(benchmark::State& state) {
  objectives::LcrSizingSpec s = Spec();
  s.form = objectives::LcrConstraintForm::kSamples;
  const objectives::Problem p = objectives::MakeLcrSizingProblem(s);
  const std::vector<double> x = {2.0, 37.0, 42.0, 12.0, 48.0};
  std::vector<double> y(p.evaluator->num_outputs()), jac(y.size() * x.size());
  for (auto _ : state) p.evaluator->EvalWithJacobian(x, y, jac);
}
BENCHMARK(BM_LcrRobustJacobian)->Unit(benchmark::kMillisecond);

}  // namespace lcr_robust_bench
