// Tests of the cycloid crowning problem (objectives/cycloid_crowning.h) on a coarse grid.
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "objectives/cycloid_crowning.h"
#include "optimizers/solver.h"
#include "tests/reference_designs.h"

namespace camopt::objectives {
namespace cycloid_crowning_objective_test {

cycloid::LoadedOptions Coarse() {
  cycloid::LoadedOptions o;
  o.profile_cells = 8;
  o.axial_cells = 8;
  return o;
}

CycloidCrowningModel Model() {
  const auto angles = cycloid::UniformCrankAngles(2, 2.0 * kPi / 16);
  return CycloidCrowningModel(camopt::testing::CycloidNnm(), cycloid::Material{}, Coarse(), 350.0e3,
                              550.0e3, angles);
}

CycloidCrowningSpec Spec() {
  CycloidCrowningSpec s;
  s.coefficient_lo_mm = 0.0;
  s.coefficient_hi_mm = 0.02;
  s.initial_coefficient_mm = 0.004;
  s.length_lo_mm = s.length_hi_mm = 17.0;
  s.stress_scale_MPa = 1000.0;
  return s;
}

TEST(CycloidCrowningProblem, OutputsAreTheModelsAndEachPointRunsOnce) {
  CycloidCrowningModel model = Model();
  std::vector<CrowningEvaluation> seen;
  const Problem p = CycloidCrowningProblem(model, Spec(), [&](const CrowningEvaluation& e) { seen.push_back(e); });
  p.Validate();
  ASSERT_EQ(p.num_vars(), 1);
  EXPECT_EQ(p.objective, kCrowningStress);
  ASSERT_EQ(p.constraints.size(), 1u);
  EXPECT_EQ(p.constraints[0].lower, 0.0);
  std::vector<double> y(2), y2(2);
  p.evaluator->Eval(std::vector<double>{0.004}, y);
  p.evaluator->Eval(std::vector<double>{0.004}, y2);  // answered from memory
  EXPECT_EQ(model.evaluations(), 1);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(y, y2);
  EXPECT_EQ(y[p.evaluator->block(kCrowningStress).offset], seen[0].stress_MPa);
  EXPECT_EQ(y[p.evaluator->block(kCrowningEdgeMargin).offset], seen[0].edge_margin_um);
  EXPECT_EQ(seen[0].length_mm, 17.0);
  // The same crowning through the model directly (a fresh model: the model is pure, same bits).
  CycloidCrowningModel fresh = Model();
  const CrowningEvaluation e = fresh.Evaluate(0.004, 17.0);
  EXPECT_NEAR(e.stress_MPa, seen[0].stress_MPa, 1e-6 * e.stress_MPa);
  EXPECT_NEAR(e.edge_margin_um, seen[0].edge_margin_um, 1e-6 + 1e-6 * std::abs(e.edge_margin_um));
  EXPECT_EQ(e.stress_MPa, seen[0].stress_MPa);
  EXPECT_EQ(e.edge_margin_um, seen[0].edge_margin_um);
  // Value-only: asking for derivatives is a defect of the caller.
  std::vector<double> jac(2);
  EXPECT_THROW(p.evaluator->EvalWithJacobian(std::vector<double>{0.004}, y, jac), std::logic_error);
}

TEST(CycloidCrowningModel, EvaluationsDoNotDependOnTheirOrder) {
  // A scan in one order and in the other gives the same bits at every point.
  CycloidCrowningModel up = Model(), down = Model();
  const std::vector<double> fs = {0.0, 0.003, 0.008, 0.02};
  std::vector<CrowningEvaluation> a, b(fs.size());
  for (double f : fs) a.push_back(up.Evaluate(f, 17.0));
  for (size_t k = fs.size(); k-- > 0;) b[k] = down.Evaluate(fs[k], 17.0);
  for (size_t k = 0; k < fs.size(); ++k) {
    EXPECT_EQ(a[k].stress_MPa, b[k].stress_MPa);
    EXPECT_EQ(a[k].edge_margin_um, b[k].edge_margin_um);
  }
}

TEST(CycloidCrowningProblem, LengthIsAVariableWhenTuned) {
  CycloidCrowningModel model = Model();
  CycloidCrowningSpec s = Spec();
  s.tune_length = true;
  s.length_hi_mm = 25.0;
  const Problem p = CycloidCrowningProblem(model, s, nullptr);
  ASSERT_EQ(p.num_vars(), 2);
  EXPECT_EQ(p.variables[1].lower, 17.0);
  EXPECT_EQ(p.variables[1].upper, 25.0);
  std::vector<double> y(2);
  p.evaluator->Eval(std::vector<double>{0.004, 20.0}, y);
  EXPECT_GT(y[0], 0.0);
}

TEST(CycloidCrowningProblem, CobylaFindsAFeasiblePointBetterThanTheStart) {
  // A straight tooth (f = 0) touches the edges at 550 N·m, and the stress grows with f: from a
  // feasible start (f = 7 µm) COBYLA lowers f and the stress while keeping the edges free.
  CycloidCrowningModel model = Model();
  CycloidCrowningModel probe = Model();
  EXPECT_LT(probe.Evaluate(0.0, 17.0).edge_margin_um, 0.0);
  std::vector<CrowningEvaluation> seen;
  CycloidCrowningSpec spec = Spec();
  spec.initial_coefficient_mm = 0.007;
  const Problem p = CycloidCrowningProblem(model, spec, [&](const CrowningEvaluation& e) { seen.push_back(e); });
  optimizers::SolverOptions o;
  o.backend = optimizers::Backend::kCobyla;
  o.tolerance = 1e-3;
  o.constraint_tolerance = 1e-2;
  o.max_evaluations = 12;
  const optimizers::SolverResult r = optimizers::Solve(p, o);
  ASSERT_FALSE(r.x.empty()) << r.message;
  ASSERT_FALSE(seen.empty());
  ASSERT_GE(seen.front().edge_margin_um, 0.0);  // the start is feasible
  EXPECT_GT(r.x[0], 0.0);
  EXPECT_LT(r.x[0], 0.007);
  // The best feasible point it visited (what the study reports) is better than the start.
  const CrowningEvaluation* best = nullptr;
  for (const auto& e : seen)
    if (e.edge_margin_um >= 0.0 && (!best || e.stress_MPa < best->stress_MPa)) best = &e;
  ASSERT_NE(best, nullptr);
  EXPECT_LT(best->coefficient_mm, 0.007);
  EXPECT_LT(best->stress_MPa, seen.front().stress_MPa);
  EXPECT_EQ(model.evaluations(), int(seen.size()));  // the final assessment ran nothing new
}

TEST(CycloidCrowningProblem, ScanSelections) {
  auto ev = [](double f, double stress, double margin) {
    CrowningEvaluation e;
    e.coefficient_mm = f;
    e.stress_MPa = stress;
    e.edge_margin_um = margin;
    return e;
  };
  const std::vector<CrowningEvaluation> scan = {ev(0.0, 1200, -3.0), ev(0.002, 1160, 0.3),
                                                ev(0.004, 1260, 5.0), ev(0.006, 1160, 7.0)};
  // Lowest stress among margin >= required; the first of a tie.
  EXPECT_EQ(LowestFeasibleStress(scan, 0.0)->coefficient_mm, 0.002);
  EXPECT_EQ(LowestFeasibleStress(scan, 1.0)->coefficient_mm, 0.006);
  EXPECT_FALSE(LowestFeasibleStress(scan, 10.0).has_value());
  EXPECT_EQ(LargestEdgeMargin(scan).coefficient_mm, 0.006);
  EXPECT_THROW(LargestEdgeMargin({}), std::invalid_argument);
}

}  // namespace cycloid_crowning_objective_test
}  // namespace camopt::objectives
