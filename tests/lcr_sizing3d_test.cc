// lcr_min_size with the finite-length contact: AD gradients of the new constraint rows
// (3D stress margin, overload edge margin) against central differences, the crowned sizing of one
// combination held to an independent 3D check and the half_space re-check, the fast path of a
// crowning-free study, and bad input (exit 2 with the JSON path).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/lcr/contact3d_cycle.h"
#include "model/lcr/contact3d_edge.h"
#include "model/lcr/cycle.h"
#include "model/lcr/forces.h"
#include "sizing/lcr_sizing3d.h"
#include "studies/input.h"
#include "studies/lcr_min_size_study.h"
#include "tests/test_util.h"

namespace camopt {
namespace lcr_sizing3d_test {

using nlohmann::json;
using sizing::LcrContactSample;

// Central differences of an iterative solve (line loads converged to 1e-10 relative): the
// difference quotient carries ~1e-10/h ≈ 2e-5 relative noise.
constexpr double kGradientRelTol = 2e-4;
constexpr double kGradientAbsTol = 1e-6;
constexpr double kHalfSpaceAgreementPercent = 3.0;  // slices within 3% for crowned rollers

// One combination of the ratio −90 study (20/21 + 26/27) near the crowned optimum.
objectives::LcrSizingSpec Spec() {
  objectives::LcrSizingSpec s;
  s.lobes_a = 20, s.rollers_a = 21, s.lobes_b = 26, s.rollers_b = 27;
  s.roller_length_mm = 10, s.cam_thickness_mm = 8;
  s.output_torque_Nmm = 80e3;
  s.limits.contact_stress_MPa = 1500;
  s.limits.roller_load_N = 1050;
  s.limits.undercut_margin_mm = 0.5;
  s.limits.roller_gap_mm = 1.0;
  s.form = objectives::LcrConstraintForm::kActiveSet;
  return s;
}

sizing::LcrSizing3DSpec Spec3D() {
  sizing::LcrSizing3DSpec s;
  s.contact.model = lcr::ContactModel::kSlices;
  s.contact.slices = 20;
  s.contact.misalignment_rad = 1e-3;
  s.crowning.type = contact::CrowningType::kLogarithmic;
  s.crowning.effective_length = 12;
  s.coefficient_range_mm = std::array<double, 2>{1e-4, 0.05};
  s.overload_torque_Nmm = 120e3;
  return s;
}

// The most loaded roller of a cam at θ.
int TopRoller(const objectives::LcrSizingSpec& s, const std::vector<double>& x, int side, double theta) {
  const auto r = objectives::LcrDesign(s, std::span<const double>(x).first(5));
  const auto a = lcr::AnalyzeAngle(r, s.material, lcr::LoadCase{s.output_torque_Nmm, 0, 0}, theta);
  const auto& f = (side == 0 ? a.input : a.output).force;
  return int(std::max_element(f.begin(), f.end()) - f.begin());
}

// The 3D rows' Jacobian (AD through the evaluator) against central differences over all N
// variables of the problem of s3 at x0 (the 5 line variables of Spec() first).
template <int N>
void ExpectRowsMatchCentralDifferences(const std::vector<double>& x0, const sizing::LcrSizing3DSpec& s3,
                                       double cam_thickness_mm = 8, double roller_length_mm = 10) {
  objectives::LcrSizingSpec s = Spec();
  s.limits.contact_stress_MPa = kInf;
  s.cam_thickness_mm = cam_thickness_mm, s.roller_length_mm = roller_length_mm;
  sizing::LcrTracked3D tr;
  for (int side = 0; side < 2; ++side)
    for (double theta : {0.05, 0.11}) {
      tr.stress.push_back({side, theta, TopRoller(s, x0, side, theta)});
      tr.edge.push_back({side, theta, TopRoller(s, x0, side, theta)});
    }
  for (int side = 0; side < 2; ++side) s.active.force[side] = {{0.05, TopRoller(s, x0, side, 0.05), 0.0}};
  const objectives::Problem p = sizing::MakeLcrSizing3DProblem(s, s3, 1500, tr);
  ASSERT_EQ(p.num_vars(), N);
  ASSERT_EQ(int(x0.size()), N);
  const auto& ev = *p.evaluator;
  const int first = ev.block("input_stress_margin_3d").offset, m = ev.num_outputs();
  ASSERT_EQ(m - first, 8);
  camopt::testing::JacobianCheck check;
  check.rel_tol = kGradientRelTol;
  check.abs_tol = kGradientAbsTol;
  for (int k = first; k < m; ++k) check.rows.push_back(k);
  EXPECT_EQ(camopt::testing::ExpectEvaluatorJacobianMatchesCentralDifferences(ev, x0, check), 8 * N);
}

TEST(LcrSizing3D, StressAndEdgeRowsMatchCentralDifferencesOffTheEnds) {
  // e, r_dA, r_dB, d_r, R, f_A, f_B: crowned enough to keep the overload well off the ends (near
  // the onset a slice entering the contact set is a kink of the discrete model, where central
  // differences straddle two pieces).
  const std::vector<double> x = {1.2266, 48.889, 48.889, 7.722, 52.75, 0.03, 0.025};
  ExpectRowsMatchCentralDifferences<7>(x, Spec3D());
}

TEST(LcrSizing3D, StressAndEdgeRowsMatchCentralDifferencesOnTheEnds) {
  // A light crown: at 1 mrad the overload pressure reaches an end (edge margins negative).
  const std::vector<double> x = {1.2266, 48.889, 48.889, 7.722, 52.75, 0.002, 0.0015};
  ExpectRowsMatchCentralDifferences<7>(x, Spec3D());
}

// The polish problem's evaluator computes the values with the Jacobian and keeps both for the
// last point: values and Jacobian asked at points in any order are those of a fresh evaluation at
// that point, and the values of Eval and EvalWithJacobian agree (Jet arithmetic may round the last
// bit differently, e.g. a division done as a product with the reciprocal).
TEST(LcrSizing3D, ThePolishEvaluatorsLastPointCacheGivesEachPointsOwnNumbers) {
  objectives::LcrSizingSpec s = Spec();
  s.limits.contact_stress_MPa = kInf;
  const std::vector<double> x1 = {1.2266, 48.889, 48.889, 7.722, 52.75, 0.03, 0.025};
  std::vector<double> x2 = x1;
  x2[0] *= 1.01, x2[5] *= 0.9;
  sizing::LcrTracked3D tr;
  for (int side = 0; side < 2; ++side) {
    tr.stress.push_back({side, 0.05, TopRoller(s, x1, side, 0.05)});
    tr.edge.push_back({side, 0.11, TopRoller(s, x1, side, 0.11)});
    s.active.force[side] = {{0.05, TopRoller(s, x1, side, 0.05), 0.0}};
  }
  const auto make = [&] { return sizing::MakeLcrSizing3DProblem(s, Spec3D(), 1500, tr); };
  const objectives::Problem p = make();
  const int n = p.num_vars(), m = p.evaluator->num_outputs();
  // Fresh problems (no cached point) give the reference numbers of each point.
  std::vector<double> y1(m), j1(size_t(m) * n), y2(m), j2(size_t(m) * n), v1(m);
  make().evaluator->EvalWithJacobian(x1, y1, j1);
  make().evaluator->EvalWithJacobian(x2, y2, j2);
  make().evaluator->Eval(x1, v1);
  for (int k = 0; k < m; ++k) EXPECT_NEAR(v1[k], y1[k], 1e-12 * std::max(1.0, std::abs(y1[k]))) << k;
  // One problem asked in a mixed order.
  std::vector<double> y(m), j(size_t(m) * n);
  p.evaluator->Eval(x1, y);
  EXPECT_EQ(y, y1);
  p.evaluator->Eval(x2, y);
  EXPECT_EQ(y, y2);
  p.evaluator->EvalWithJacobian(x1, y, j);
  EXPECT_EQ(y, y1);
  EXPECT_EQ(j, j1);
  p.evaluator->EvalWithJacobian(x2, y, j);
  EXPECT_EQ(y, y2);
  EXPECT_EQ(j, j2);
  p.evaluator->EvalWithJacobian(x2, y, j);
  EXPECT_EQ(j, j2);
}

TEST(LcrSizing3D, RowsMatchCentralDifferencesInTheCrownRadiusFlatLengthAndLengths) {
  // A partial crown (R, L0 per cam as variables) and the roller length and cam thickness as
  // variables: 5 + 2 + 2 + 1 + 1 = 11. The contact length is min(l_r, b_c): with l_r < b_c the
  // roller length sets it (the cam thickness column is zero), with b_c < l_r the cam thickness.
  sizing::LcrSizing3DSpec s3 = Spec3D();
  s3.coefficient_range_mm.reset();
  s3.crowning = {};
  s3.crowning.type = contact::CrowningType::kPartial;
  s3.crowning.radius = 300, s3.crowning.flat_length = 2;
  s3.radius_range_mm = std::array<double, 2>{50, 2000};
  s3.flat_length_range_mm = std::array<double, 2>{0, 6};
  s3.roller_length_range_mm = std::array<double, 2>{5, 12};
  s3.cam_thickness_range_mm = std::array<double, 2>{5, 12};
  ExpectRowsMatchCentralDifferences<11>({1.2266, 48.889, 48.889, 7.722, 52.75, 300, 350, 2.0, 1.5, 9.0, 10.0}, s3, 10, 9);
  ExpectRowsMatchCentralDifferences<11>({1.2266, 48.889, 48.889, 7.722, 52.75, 300, 350, 2.0, 1.5, 10.0, 8.5}, s3, 8.5, 10);
}

TEST(LcrSizing3D, RowsMatchCentralDifferencesInTheLogCoefficientAndLengths) {
  sizing::LcrSizing3DSpec s3 = Spec3D();  // log crown, Le 12, coefficient per cam
  s3.roller_length_range_mm = std::array<double, 2>{5, 11};
  s3.cam_thickness_range_mm = std::array<double, 2>{5, 12};
  ExpectRowsMatchCentralDifferences<9>({1.2266, 48.889, 48.889, 7.722, 52.75, 0.03, 0.025, 9.5, 10.5}, s3, 10.5, 9.5);
}

TEST(LcrSizing3D, EdgeMarginSignFollowsAConvergedSolution) {
  // The margin (model/lcr/contact3d_edge.h) is extrapolated from the two end slices to the
  // contact's end: at 20 slices its sign says whether a converged solution (320 slices) has load on
  // an end slice, for a light crown (loaded end), a crown near the onset and a heavy crown (free
  // ends), and the margin itself converges at second order in the slice width.
  lcr::RollerCrowning<double> c;
  c.type = contact::CrowningType::kLogarithmic;
  c.effective_length = 12;
  for (double f : {0.001, 0.004, 0.02}) {
    c.coefficient = f;
    const auto fine = lcr::RollerContactSlices<double>(900.0, 3.0, 8.0, 226373.6, c, 1e-3, 320);
    const auto sol = lcr::RollerContactSlices<double>(900.0, 3.0, 8.0, 226373.6, c, 1e-3, 20);
    const double m = lcr::EdgeMargin<double>(sol, 900.0, 3.0, 8.0, 226373.6, c, 1e-3);
    EXPECT_EQ(m > 0, !fine.edge_loaded) << "f = " << f << ", margin " << m;
  }
  // Convergence off the ends (f = 0.02): the change per doubling of the slices falls by >= 3x
  // (second order: 4x; the end slice's own value, first order, would give 2x).
  c.coefficient = 0.02;
  std::vector<double> m;
  for (int n : {10, 20, 40, 80, 160}) {
    const auto sol = lcr::RollerContactSlices<double>(900.0, 3.0, 8.0, 226373.6, c, 1e-3, n);
    m.push_back(lcr::EdgeMargin<double>(sol, 900.0, 3.0, 8.0, 226373.6, c, 1e-3));
    std::printf("edge margin, f 0.02, %d slices: %.6f\n", n, m.back());
  }
  for (size_t i = 2; i < m.size(); ++i)
    EXPECT_GE(std::abs(m[i - 2] - m[i - 1]), 3 * std::abs(m[i - 1] - m[i])) << i;
}

// One combination of the crowned example (max_lobes 14: 12/13 + 14/15).
json CrownedStudy() {
  json j = camopt::testing::Example("lcr_min_size_crowned.json");
  j["search"]["max_lobes"] = 14;
  return j;
}

TEST(LcrSizing3D, CrownedSizingHoldsTheLimitsUnderAnIndependentCheck) {
  const json j = CrownedStudy();
  const studies::Node root(&j, "crowned.json", "");
  const auto study = studies::lcr_min_size::Parse(root);
  ASSERT_TRUE(study.contact3d);
  const auto res = studies::lcr_min_size::Run(study, studies::RunContext("", true));
  ASSERT_GE(res.best, 0);
  const auto& best = res.candidates[res.best];
  const auto& r = *best.outcome.design;
  const auto& o3 = *best.outcome3d;
  // Independent check: the slices model over a finer cycle (7200 angles) with the chosen crowning.
  const auto series = lcr::AnalyzeCycle(r, study.base.material, lcr::LoadCase{80e3, 0, 0}, 7200, lcr::Stages{true, false, false});
  lcr::ContactModelOptions o = study.contact3d->contact;
  o.model = lcr::ContactModel::kSlices;
  for (int k = 0; k < 2; ++k) {
    const auto side = k == 0 ? lcr::Side::kInput : lcr::Side::kOutput;
    EXPECT_GT(o3.crowning[k].coefficient, 1e-4);  // a crown, inside its range
    EXPECT_LT(o3.crowning[k].coefficient, 0.05);
    const auto c = lcr::AnalyzeCycleContact3D(r, side, series, study.base.material.composite_modulus_MPa(),
                                              o3.crowning[k], o);
    // The 3600-angle check holds the limit; 7200 angles may find a peak between its angles.
    EXPECT_LE(c.max_contact_stress_MPa, 1500 * (1 + 1e-4)) << k;
    EXPECT_GT(o3.contact->overload_edge_margin[k], 0) << k;
    ASSERT_TRUE(res.half_space);
    EXPECT_LE(std::abs(res.half_space->difference_percent[k]), kHalfSpaceAgreementPercent) << k;
  }
  // The 3D limit makes the reducer larger than the line model's optimum.
  EXPECT_GT(best.outcome.check->outer_diameter_mm, o3.line_outer_diameter_mm);
  const json out = studies::WriteResult(res);
  EXPECT_EQ(out["best"]["input"]["crowning"]["type"], "logarithmic");
  EXPECT_TRUE(out["best"].contains("half_space_check"));
}

// Branch and bound over candidates (sizing/sizing_driver.h): a polish stopped at a bound goes on
// from where it stopped to the design, numbers and counts of the polish that never stopped, and each
// stop's lower bound is at most the final outer diameter.
TEST(LcrSizing3D, APolishStoppedAtABoundContinuesToTheSameDesign) {
  const json j = CrownedStudy();
  const auto study = studies::lcr_min_size::Parse(studies::Node(&j, "crowned.json", ""));
  objectives::LcrSizingSpec spec = study.base;
  const auto combos = objectives::LobeCombinations(study.ratio, study.max_lobes, study.differences);
  ASSERT_EQ(combos.size(), 1u);
  spec.lobes_a = combos[0].lobes_a, spec.rollers_a = combos[0].rollers_a;
  spec.lobes_b = combos[0].lobes_b, spec.rollers_b = combos[0].rollers_b;
  const auto full = sizing::SolveLcrMinSize3D(spec, *study.contact3d, study.options);
  ASSERT_TRUE(full.outcome.converged);
  ASSERT_FALSE(full.paused);
  const double od = full.outcome.check->outer_diameter_mm;
  ASSERT_GE(full.outcome.polish_rounds, 3);
  // Bound 0: every converged round exceeds it, the polish stops after its first round.
  auto o = sizing::SolveLcrMinSize3D(spec, *study.contact3d, study.options, 0.0);
  ASSERT_TRUE(o.paused);
  EXPECT_FALSE(o.outcome.converged);
  EXPECT_EQ(o.outcome.polish_rounds, 1);
  double lower = o.paused->lower_bound_mm;
  EXPECT_LE(lower, od);
  // A bound just above the first round's optimum: it stops again, later and higher.
  sizing::ContinueLcrMinSize3D(spec, study.options, o, lower + 1e-9);
  ASSERT_TRUE(o.paused);
  EXPECT_EQ(o.outcome.polish_rounds, 2);
  EXPECT_GT(o.paused->lower_bound_mm, lower);
  EXPECT_LE(o.paused->lower_bound_mm, od);
  lower = o.paused->lower_bound_mm;
  sizing::ContinueLcrMinSize3D(spec, study.options, o);
  ASSERT_FALSE(o.paused);
  ASSERT_TRUE(o.outcome.converged);
  EXPECT_EQ(o.outcome.x, full.outcome.x);  // bit for bit
  EXPECT_EQ(o.outcome.check->outer_diameter_mm, od);
  EXPECT_EQ(o.outcome.polish_rounds, full.outcome.polish_rounds);
  EXPECT_EQ(o.outcome.result.value_evaluations, full.outcome.result.value_evaluations);
  EXPECT_EQ(o.outcome.result.gradient_evaluations, full.outcome.result.gradient_evaluations);
  EXPECT_EQ(o.outcome.result.iterations, full.outcome.result.iterations);
  EXPECT_EQ(o.crowning[0].coefficient, full.crowning[0].coefficient);
  EXPECT_EQ(o.crowning[1].coefficient, full.crowning[1].coefficient);
  EXPECT_EQ(o.tracked.stress, full.tracked.stress);
  EXPECT_THROW(sizing::ContinueLcrMinSize3D(spec, study.options, o), std::invalid_argument);
}

// The crowned example's 4 combinations: the best (20/21 + 26/27) is the design of the search that
// solves every combination (scripts/compare_examples.sh against a build without pruning gives the
// same bits, 103.64474369403028 mm); the others stop at a polish round above it and say so.
TEST(LcrSizing3D, CrownedExamplePrunesTheCombinationsAboveTheBest) {
  const json j = camopt::testing::Example("lcr_min_size_crowned.json");
  const auto study = studies::lcr_min_size::Parse(studies::Node(&j, "crowned.json", ""));
  const auto res = studies::lcr_min_size::Run(study, studies::RunContext("", true));
  ASSERT_GE(res.best, 0);
  const json out = studies::WriteResult(res);
  const double best = out["best"]["outer_diameter_mm"].get<double>();
  EXPECT_NEAR(best, 103.64474369403028, 1e-6);
  EXPECT_EQ(out["best"]["input"]["lobes"], 20);
  int pruned = 0;
  for (const json& c : out["candidates"]) {
    if (c["status"] != "pruned") continue;
    ++pruned;
    EXPECT_FALSE(c["feasible"].get<bool>());
    EXPECT_GT(c["outer_diameter_lower_bound_mm"].get<double>(), best) << c.dump();
    EXPECT_FALSE(c.contains("outer_diameter_mm"));
  }
  EXPECT_EQ(pruned, 3);
}

// One combination (12/13 + 14/15) with a circular crown's radius per cam as the variable, or the
// cam thickness as a variable (log crown), sized by Ipopt and by NLopt SLSQP.
json OneCombination(const std::string& variant, const std::string& backend) {
  json j = CrownedStudy();
  j["optimizer"]["backend"] = backend;
  if (variant == "radius") {
    j["variables"].erase("crowning_coefficient_mm");
    j["variables"]["crowning_radius_mm"] = {20, 2000};
    j["fixed"]["crowning"] = {{"type", "circular"}, {"radius_mm", 200}};
  } else {
    j["variables"]["cam_thickness_mm"] = {5, 9};
  }
  return j;
}

TEST(LcrSizing3D, CrownRadiusAndCamThicknessVariablesIpoptAndSlsqpAgree) {
  for (const std::string variant : {"radius", "cam_thickness"}) {
    std::array<double, 2> od{};
    std::array<std::array<double, 2>, 2> param{};
    int b = 0;
    for (const std::string backend : {"ipopt", "slsqp"}) {
      const json j = OneCombination(variant, backend);
      const auto study = studies::lcr_min_size::Parse(studies::Node(&j, "vars.json", ""));
      ASSERT_TRUE(study.contact3d);
      const auto res = studies::lcr_min_size::Run(study, studies::RunContext("", true));
      ASSERT_GE(res.best, 0) << variant << " " << backend;
      const auto& best = res.candidates[res.best];
      const auto& r = *best.outcome.design;
      const auto& o3 = *best.outcome3d;
      od[b] = best.outcome.check->outer_diameter_mm;
      for (int k = 0; k < 2; ++k)
        param[b][k] = variant == "radius" ? o3.crowning[k].radius : Value(r.side(k == 0 ? lcr::Side::kInput : lcr::Side::kOutput).cam_thickness);
      std::printf("%s, %s: outer diameter %.6f mm, %s %.4f / %.4f mm\n", variant.c_str(), backend.c_str(), od[b],
                  variant.c_str(), param[b][0], param[b][1]);
      // Independent check with the chosen crowning and lengths: the slices model over 7200 angles.
      const auto series = lcr::AnalyzeCycle(r, study.base.material, lcr::LoadCase{80e3, 0, 0}, 7200, lcr::Stages{true, false, false});
      lcr::ContactModelOptions o = study.contact3d->contact;
      o.model = lcr::ContactModel::kSlices;
      for (int k = 0; k < 2; ++k) {
        const auto side = k == 0 ? lcr::Side::kInput : lcr::Side::kOutput;
        const auto c = lcr::AnalyzeCycleContact3D(r, side, series, study.base.material.composite_modulus_MPa(), o3.crowning[k], o);
        EXPECT_LE(c.max_contact_stress_MPa, 1500 * (1 + 1e-4)) << variant << " " << backend << " " << k;
        EXPECT_GT(o3.contact->overload_edge_margin[k], 0) << variant << " " << backend << " " << k;
      }
      ++b;
    }
    EXPECT_NEAR(od[0], od[1], 1e-4 * od[1]) << variant;  // the same optimum
    if (variant == "cam_thickness") {  // at its upper bound: a thicker cam only lowers the stress
      EXPECT_NEAR(param[0][0], 9, 1e-6);
      EXPECT_NEAR(param[1][0], 9, 1e-6);
    } else {
      for (int k = 0; k < 2; ++k) EXPECT_NEAR(param[0][k], param[1][k], 0.01 * param[1][k]) << k;
    }
  }
}

TEST(LcrSizing3D, NewVariablesBadInputIsExit2WithThePath) {
  using camopt::testing::ExpectStudyRejected;
  json radius_log = CrownedStudy();  // a radius with a logarithmic crown
  radius_log["variables"]["crowning_radius_mm"] = {20, 2000};
  ExpectStudyRejected(radius_log, "var-radius-log", "/variables/crowning_radius_mm", "circular");
  json flat_circ = OneCombination("radius", "ipopt");  // a flat length with a circular crown
  flat_circ["variables"]["crowning_flat_length_mm"] = {0, 4};
  ExpectStudyRejected(flat_circ, "var-flat-circ", "/variables/crowning_flat_length_mm", "partial");
  json small_r = OneCombination("radius", "ipopt");  // R = 3 mm cannot crown a 10 mm roller
  small_r["variables"]["crowning_radius_mm"] = {3, 2000};
  ExpectStudyRejected(small_r, "var-radius-small", "/variables/crowning_radius_mm", "half the roller length");
  json long_roller = CrownedStudy();  // the roller's upper end reaches Le = 12
  long_roller["variables"]["roller_length_mm"] = {5, 12.5};
  ExpectStudyRejected(long_roller, "var-length-le", "/fixed/crowning", "effective length");
  json line = camopt::testing::Example("lcr_min_size.json");  // a length variable under the line model
  line["variables"]["cam_thickness_mm"] = {5, 9};
  line["contact"] = {{"model", "line"}};
  ExpectStudyRejected(line, "var-length-line", "/contact/model", "line model ignores");
  json catalogue = camopt::testing::Example("lcr_min_size_catalogue.json");
  catalogue["roller_catalogue"] = json::array({{{"name", "NR 5x10"}, {"diameter_mm", 5}, {"length_mm", 10}, {"load_limit_N", 800}}});
  catalogue["contact"] = {{"model", "slices"}};
  catalogue["variables"]["roller_length_mm"] = {5, 9};
  ExpectStudyRejected(catalogue, "var-length-cat", "/variables/roller_length_mm", "catalogue");
}

TEST(LcrSizing3D, CrowningFreeStudyTakesTheLinePath) {
  json j = camopt::testing::Example("lcr_min_size.json");
  EXPECT_FALSE(studies::lcr_min_size::Parse(studies::Node(&j, "s.json", "")).contact3d);
  j["contact"] = {{"model", "line"}};
  EXPECT_FALSE(studies::lcr_min_size::Parse(studies::Node(&j, "s.json", "")).contact3d);
}

TEST(LcrSizing3D, BadInputIsExit2WithThePath) {
  using camopt::testing::ExpectStudyRejected;
  json line = CrownedStudy();
  line["contact"]["model"] = "line";
  line["contact"].erase("misalignment_mrad");
  ExpectStudyRejected(line, "crown-line", "/contact/model", "line model ignores");
  json no_crown = CrownedStudy();
  no_crown["fixed"].erase("crowning");
  ExpectStudyRejected(no_crown, "crown-var", "/variables/crowning_coefficient_mm", "logarithmic");
  json short_le = CrownedStudy();
  short_le["fixed"]["crowning"]["effective_length_mm"] = 10;
  ExpectStudyRejected(short_le, "crown-le", "/fixed/crowning", "effective length");
  json over = CrownedStudy();
  over["load"]["overload_torque_Nm"] = 50;
  ExpectStudyRejected(over, "crown-over", "/load/overload_torque_Nm", "overload");
  json circ = CrownedStudy();
  circ["fixed"]["crowning"] = {{"type", "circular"}, {"radius_mm", 500}};
  ExpectStudyRejected(circ, "crown-circ", "/variables/crowning_coefficient_mm", "logarithmic");
}

}  // namespace lcr_sizing3d_test
}  // namespace camopt
