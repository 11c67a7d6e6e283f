// The problem layer and the LCR sizing problem: exact gradients of every output against central
// differences, the one-period sampling against full-cycle analysis, the stress margin against
// the pipeline's Hertz stress, and the lobe combinations against an independent derivation.
#include <cmath>
#include <limits>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include "model/lcr/cycle.h"
#include "model/lcr/kinematics.h"
#include "model/lcr/profile.h"
#include "objectives/lcr_sizing.h"
#include "tests/optim_reference_problems.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt {
namespace objectives_test {

using objectives::LcrConstraintForm;
using objectives::LcrSizingSpec;

// Checks the evaluator's Jacobian (ceres::Jet) against central differences of its double
// evaluation (tests/test_util.h): every entry of every output, the outputs being exactly those of
// the blocks, |ad − fd| <= abs_tol + rel_tol max(|ad|, |fd|).
void ExpectEvaluatorJacobianMatches(const objectives::Evaluator& ev, const std::vector<double>& x,
                                    double rel_tol, double abs_tol) {
  testing::JacobianCheck check;
  check.rel_tol = rel_tol;
  check.abs_tol = abs_tol;
  int in_blocks = 0;
  for (const auto& b : ev.blocks()) in_blocks += b.size;
  EXPECT_EQ(in_blocks, ev.num_outputs());
  EXPECT_EQ(testing::ExpectEvaluatorJacobianMatchesCentralDifferences(ev, x, check),
            ev.num_vars() * ev.num_outputs());
}

LcrSizingSpec LcrIISpec(LcrConstraintForm form) {
  LcrSizingSpec s = testing::LcrIISizingSpec(form);
  if (form == LcrConstraintForm::kActiveSet)
    for (int side = 0; side < 2; ++side)  // two rollers share one angle
      s.active.force[side] = s.active.stress[side] = {{0.1, 0}, {0.1, 3}, {0.37, 5}, {1.2, 11}, {2.9, 12}};
  return s;
}

// LCR II of Table 2 as a variable vector (e, r_dA, r_dB, d_r, R).
std::vector<double> LcrIIVariables() { return {2.0, 37.0, 42.0, 12.0, 48.0}; }

TEST(Problem, Hs71GradientsMatchCentralDifferences) {
  const auto p = testing::Hs71();
  ExpectEvaluatorJacobianMatches(*p.evaluator, {1.3, 4.1, 3.7, 1.5}, 1e-7, 1e-9);
}

TEST(Problem, ValidateRejectsBadData) {
  auto p = testing::RosenbrockOnDisk();
  p.variables[0].scale = 0.0;
  EXPECT_THROW(p.Validate(), std::invalid_argument);
  auto q = testing::RosenbrockOnDisk();
  q.constraints[0].lower = 2.0;  // lower > upper = 1
  EXPECT_THROW(q.Validate(), std::invalid_argument);
  auto r = testing::RosenbrockOnDisk();
  r.variables[1].initial = std::nan("");
  EXPECT_THROW(r.Validate(), std::invalid_argument);
  // A scale whose reciprocal overflows (a limit given as a denormal was a constraint's scale and
  // crashed the sparse solver under Ipopt), or a huge one, is refused before any solver sees it.
  for (const double scale : {5e-324, 1e-300, 1e300}) {
    auto c = testing::RosenbrockOnDisk();
    c.constraints[0].scale = scale;
    EXPECT_THROW(c.Validate(), std::invalid_argument) << scale;
    auto o = testing::RosenbrockOnDisk();
    o.objective_scale = scale;
    EXPECT_THROW(o.Validate(), std::invalid_argument) << scale;
  }
  auto ok = testing::RosenbrockOnDisk();
  ok.constraints[0].scale = 1e-100;
  EXPECT_NO_THROW(ok.Validate());
}

TEST(Problem, CacheCountsModelRunsOnce) {
  const auto p = testing::Hs71();
  objectives::ProblemCache cache(p);
  const std::vector<double> x = {1, 2, 3, 4};
  cache.Values(x);
  cache.Values(x);
  cache.Jacobian(x);
  cache.Values(x);  // values came with the Jacobian
  EXPECT_EQ(cache.value_evaluations(), 1);
  EXPECT_EQ(cache.jacobian_evaluations(), 1);
  EXPECT_DOUBLE_EQ(cache.last_values()[0], 1 * 4 * (1 + 2 + 3) + 3);
}

// Roller variants: 0 one roller for both cams, 1 a catalogue roller (fixed), 2 one per cam.
class LcrSizingGradients
    : public ::testing::TestWithParam<std::tuple<LcrConstraintForm, int>> {};

// Every output (objective, envelopes, gaps, undercut margins, pitch clearances, roller forces,
// stress margins, mean efficiency; soft aggregates or every sample) has the exact derivative. Probed at LCR II and
// at a design near the −90 optimum where the stress limit binds.
TEST_P(LcrSizingGradients, EveryOutputMatchesCentralDifferences) {
  const auto [form, rollers] = GetParam();
  LcrSizingSpec s = LcrIISpec(form);
  s.samples_per_period = 8;
  s.limits.min_efficiency = 0.9;  // adds the mean-efficiency output
  s.friction_coefficient = 0.05;
  s.efficiency_samples = 12;
  if (rollers == 1) s.fixed_roller_diameter_mm = 12.0;
  if (rollers == 2) s.same_roller = false;
  if (form == LcrConstraintForm::kActiveSet)  // tracked peaks too (envelope theorem)
    for (int side = 0; side < 2; ++side) {
      s.active.force[side].push_back({0.2, 2, 0.1});
      s.active.stress[side].push_back({0.2, 2, 0.1});
    }
  const auto p = objectives::MakeLcrSizingProblem(s);
  for (std::vector<double> x : {LcrIIVariables(), std::vector<double>{1.84, 33.97, 33.97, 6.33, 37.13}}) {
    if (rollers == 1) x.erase(x.begin() + 3);
    if (rollers == 2) x.insert(x.begin() + 4, x[3] * 0.9);  // a smaller output roller
    // Kinks (a roller entering the loaded set, PositivePart) are isolated: a relative tolerance of
    // 1e-5 with the ∛ε step separates a wrong derivative from truncation error.
    ExpectEvaluatorJacobianMatches(*p.evaluator, x, 1e-5, 1e-7);
  }
}

INSTANTIATE_TEST_SUITE_P(Objectives, LcrSizingGradients,
                         ::testing::Combine(::testing::Values(LcrConstraintForm::kAggregate,
                                                              LcrConstraintForm::kSamples,
                                                              LcrConstraintForm::kActiveSet),
                                            ::testing::Values(0, 1, 2)));

// The problem's geometric outputs equal the pipeline's own functions on the same design.
TEST(LcrSizing, OutputsAreThePipelineQuantities) {
  const LcrSizingSpec s = LcrIISpec(LcrConstraintForm::kAggregate);
  const auto p = objectives::MakeLcrSizingProblem(s);
  const auto x = LcrIIVariables();
  std::vector<double> y(p.evaluator->num_outputs());
  p.evaluator->Eval(x, y);
  auto out = [&](const std::string& name) { return y[p.evaluator->block(name).offset]; };
  const lcr::Reducer<double> r = testing::LcrII();
  EXPECT_DOUBLE_EQ(out("outer_diameter_bound_mm"), 96.0);
  EXPECT_DOUBLE_EQ(lcr::OuterDiameter(r), 96.0);  // the paper's LCR II by this definition
  EXPECT_NEAR(out("output_envelope_mm"), 0.0, 1e-12);
  EXPECT_NEAR(out("input_envelope_mm"), -5.0, 1e-12);
  EXPECT_NEAR(out("input_roller_gap_mm"), 2 * 37 * std::sin(kPi / 13) - 12, 1e-12);
  EXPECT_NEAR(out("output_roller_gap_mm"), 2 * 42 * std::sin(kPi / 15) - 12, 1e-12);
  EXPECT_NEAR(out("input_undercut_margin_mm"), lcr::UndercutMargin(r.input, 2.0), 1e-12);
  EXPECT_NEAR(out("output_undercut_margin_mm"), lcr::UndercutMargin(r.output, 2.0), 1e-12);
  EXPECT_NEAR(out("input_pitch_clearance_mm"), 37 * 0.98 - 2.0 * 13, 1e-12);
  const auto design = objectives::LcrDesign(s, x);
  EXPECT_EQ(design.input.rollers, 13);
  EXPECT_DOUBLE_EQ(design.output.roller_radius, 6.0);
}

// One load period holds every configuration: the period maximum of the roller force equals the
// full-cycle maximum of the pipeline's own cycle analysis (input side on the same angle grid,
// output side on a fine grid).
// The mean-efficiency output is the mean of the pipeline's per-angle efficiency.
TEST(LcrSizing, MeanEfficiencyIsThePipelines) {
  LcrSizingSpec s = LcrIISpec(LcrConstraintForm::kAggregate);
  s.limits.min_efficiency = 0.5;
  s.friction_coefficient = 0.05;
  s.efficiency_samples = 360;
  const auto p = objectives::MakeLcrSizingProblem(s);
  std::vector<double> y(p.evaluator->num_outputs());
  p.evaluator->Eval(LcrIIVariables(), y);
  const auto cycle = lcr::AnalyzeCycle(testing::LcrII(), testing::Steel(), {80000, 0.05, 0.0}, 360, {});
  double mean = 0;
  for (double e : cycle.efficiency) mean += e / 360;
  EXPECT_NEAR(y[p.evaluator->block("mean_efficiency").offset], mean, 1e-12);
  ASSERT_EQ(p.constraints.back().output, "mean_efficiency");
  EXPECT_EQ(p.constraints.back().lower, 0.5);
}

TEST(LcrSizing, OnePeriodSamplesCoverTheWholeCycle) {
  LcrSizingSpec s = LcrIISpec(LcrConstraintForm::kSamples);
  s.samples_per_period = 360;
  const auto p = objectives::MakeLcrSizingProblem(s);
  std::vector<double> y(p.evaluator->num_outputs());
  p.evaluator->Eval(LcrIIVariables(), y);
  auto block_max = [&](const std::string& name) {
    const auto& b = p.evaluator->block(name);
    return *std::max_element(y.begin() + b.offset, y.begin() + b.offset + b.size);
  };
  const lcr::Reducer<double> r = testing::LcrII();
  const lcr::LoadCase load{80000, 0.0, 0.0};
  const auto full = lcr::AnalyzeCycle(r, testing::Steel(), load, 360 * 13, {true, false, false});
  EXPECT_NEAR(block_max("input_roller_force_N"),
              *std::max_element(full.input.max_force_N.begin(), full.input.max_force_N.end()), 1e-9);
  EXPECT_NEAR(block_max("output_roller_force_N"),
              *std::max_element(full.output.max_force_N.begin(), full.output.max_force_N.end()), 1e-3);
}

// The Hertz capacity margin s = (R'/r_r)(1 − p²/p_lim²) with p the pipeline's stress.
TEST(LcrSizing, StressMarginIsTheHertzCapacityOfThePipeline) {
  LcrSizingSpec s = LcrIISpec(LcrConstraintForm::kSamples);
  s.samples_per_period = 5;
  const auto p = objectives::MakeLcrSizingProblem(s);
  std::vector<double> y(p.evaluator->num_outputs());
  p.evaluator->Eval(LcrIIVariables(), y);
  const auto& b = p.evaluator->block("input_stress_margin");
  const lcr::Reducer<double> r = testing::LcrII();
  int loaded = 0;
  for (int i = 0; i < 5; ++i) {
    const double theta = 2 * kPi / 13 * i / 5;
    const auto a = lcr::AnalyzeAngle(r, testing::Steel(), {80000, 0, 0}, theta);
    for (int k = 0; k < 13; ++k) {
      const double rr = 6.0, r_eff = rr * (1 - rr * a.input.contacts[k].curvature);
      const double pk = a.input.stress[k];
      EXPECT_NEAR(y[b.offset + i * 13 + k], r_eff / rr * (1 - pk * pk / (1500.0 * 1500.0)), 1e-12);
      loaded += a.input.force[k] > 0;
    }
  }
  EXPECT_GT(loaded, 10);
}

// Active-set rows are the pipeline's force and Hertz margin of the listed (angle, roller) samples,
// in the order listed; a tracked peak is the largest force of its roller over its window (checked
// against a fine scan).
TEST(LcrSizing, ActiveSetRowsAreThePipelineSamples) {
  const LcrSizingSpec s = LcrIISpec(LcrConstraintForm::kActiveSet);
  const auto p = objectives::MakeLcrSizingProblem(s);
  std::vector<double> y(p.evaluator->num_outputs());
  p.evaluator->Eval(LcrIIVariables(), y);
  const lcr::Reducer<double> r = testing::LcrII();
  const char* names[2] = {"input", "output"};
  for (int side = 0; side < 2; ++side) {
    const auto& f = p.evaluator->block(std::string(names[side]) + "_roller_force_N");
    const auto& m = p.evaluator->block(std::string(names[side]) + "_stress_margin");
    ASSERT_EQ(f.size, int(s.active.force[side].size()));
    ASSERT_EQ(m.size, int(s.active.stress[side].size()));
    for (int i = 0; i < f.size; ++i) {
      const auto [theta, k] = std::pair{s.active.force[side][i].theta_rad, s.active.force[side][i].roller};
      const auto a = lcr::AnalyzeAngle(r, testing::Steel(), {80000, 0, 0}, theta);
      const auto& sl = side == 0 ? a.input : a.output;
      EXPECT_DOUBLE_EQ(y[f.offset + i], sl.force[k]);
      const double rr = 6.0, r_eff = rr * (1 - rr * sl.contacts[k].curvature);
      EXPECT_NEAR(y[m.offset + i], r_eff / rr * (1 - sl.stress[k] * sl.stress[k] / (1500.0 * 1500.0)), 1e-12);
    }
  }
  LcrSizingSpec peak = s;
  peak.active.force[0] = {{0.2, 2, 0.1}};
  const auto pp = objectives::MakeLcrSizingProblem(peak);
  std::vector<double> yp(pp.evaluator->num_outputs());
  pp.evaluator->Eval(LcrIIVariables(), yp);
  double scan = 0;
  for (int i = 0; i <= 20000; ++i)
    scan = std::max(scan, lcr::AnalyzeAngle(r, testing::Steel(), {80000, 0, 0}, 0.1 + 0.2 * i / 20000).input.force[2]);
  EXPECT_NEAR(yp[pp.evaluator->block("input_roller_force_N").offset], scan, 1e-6 * scan);
}

// The one cycle aggregate: a +inf sample (undercut contact) gives +inf with a zero derivative,
// never NaN; finite samples stay within [max, max + scale ln(N)/k].
TEST(LcrAggregates, ScaledSoftMaxIsSafeAtInfinityAndBounded) {
  using J = ceres::Jet<double, 2>;
  std::vector<J> x = {J(900.0, 0), J(1200.0, 1), J(kInf)};
  const J inf = lcr::ScaledSoftMax(x, 1000.0, 200.0);
  EXPECT_EQ(inf.a, kInf);
  EXPECT_EQ(inf.v[0], 0.0);
  EXPECT_EQ(inf.v[1], 0.0);
  x.pop_back();
  const J soft = lcr::ScaledSoftMax(x, 1000.0, 200.0);
  EXPECT_GE(soft.a, 1200.0);
  EXPECT_LE(soft.a, 1200.0 + 1000.0 * std::log(2.0) / 200.0);
  EXPECT_NEAR(soft.v[0] + soft.v[1], 1.0, 1e-12);  // weights of a soft max sum to one
}

// The soft aggregate bounds the sampled maximum from above by at most F_ref ln(N)/k.
TEST(LcrSizing, AggregateBoundsTheSampledMaximum) {
  LcrSizingSpec agg = LcrIISpec(LcrConstraintForm::kAggregate), smp = LcrIISpec(LcrConstraintForm::kSamples);
  const auto pa = objectives::MakeLcrSizingProblem(agg), ps = objectives::MakeLcrSizingProblem(smp);
  std::vector<double> ya(pa.evaluator->num_outputs()), ys(ps.evaluator->num_outputs());
  pa.evaluator->Eval(LcrIIVariables(), ya);
  ps.evaluator->Eval(LcrIIVariables(), ys);
  for (std::string side : {"input", "output"}) {
    const auto& bs = ps.evaluator->block(side + "_roller_force_N");
    const double exact = *std::max_element(ys.begin() + bs.offset, ys.begin() + bs.offset + bs.size);
    const double soft = ya[pa.evaluator->block(side + "_roller_force_N").offset];
    EXPECT_GE(soft, exact);
    EXPECT_LE(soft, exact + 1050.0 * std::log(double(bs.size)) / agg.sharpness);
    const auto& ms = ps.evaluator->block(side + "_stress_margin");
    double min_margin = kInf;
    for (int k = 0; k < ms.size; ++k)
      if (ys[bs.offset + k] > 0) min_margin = std::min(min_margin, ys[ms.offset + k]);
    const double soft_margin = ya[pa.evaluator->block(side + "_stress_margin").offset];
    EXPECT_LE(soft_margin, min_margin);
    EXPECT_GE(soft_margin, min_margin - std::log(double(ms.size)) / agg.sharpness);
  }
}

// Ratio −90 with n = m + 1: m_A (m_B + 1)/(m_A − m_B) = −90 gives m_A = 90 m_B/(m_B + 91), so
// m_B + 91 divides 90·91 = 8190 = 2·3²·5·7·13; its divisors in [92, 131] are 105, 117, 126, 130.
TEST(LcrSizing, LobeCombinationsOfRatioMinus90) {
  const auto c = objectives::LobeCombinations(-90, 40, {1});
  std::set<std::tuple<int, int, int, int>> got;
  for (const auto& k : c) {
    got.insert({k.lobes_a, k.rollers_a, k.lobes_b, k.rollers_b});
    EXPECT_EQ(lcr::SpeedReductionRatio(k.lobes_a, k.rollers_a, k.lobes_b, k.rollers_b), -90.0);
  }
  const std::set<std::tuple<int, int, int, int>> expected = {
      {12, 13, 14, 15}, {20, 21, 26, 27}, {25, 26, 35, 36}, {27, 28, 39, 40}};
  EXPECT_EQ(got, expected);
  // The papers' other designs are found for their ratios.
  const auto c399 = objectives::LobeCombinations(-399, 40, {1});
  EXPECT_TRUE(std::any_of(c399.begin(), c399.end(), [](const auto& k) { return k.lobes_a == 19 && k.lobes_b == 20; }));
  const auto c24 = objectives::LobeCombinations(-24, 40, {1});
  EXPECT_TRUE(std::any_of(c24.begin(), c24.end(), [](const auto& k) { return k.lobes_a == 4 && k.lobes_b == 5; }));
  EXPECT_TRUE(objectives::LobeCombinations(7, 3, {1}).empty());
}

}  // namespace objectives_test
}  // namespace camopt
