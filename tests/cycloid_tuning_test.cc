// The joint tuning of the cycloid modifications and crowning: the problem's exact
// Jacobian against central differences of its own values, the general study form (variables named
// by their field, optimizer backends), its determinism and its input errors.
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "objectives/cycloid_crowning.h"
#include "studies/cycloid_crowning_tuning_study.h"
#include "studies/cycloid_ltca_study.h"
#include "studies/input.h"
#include "studies/study.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt::objectives {
namespace cycloid_tuning_test {

// The problem's Jacobian rows (smooth stress, end distance per angle, LTE p-p) against central
// differences of the evaluator's values; the solves are tight so that the differences resolve
// the derivatives. Relative tolerance of each entry (to its row's largest central difference).
constexpr double kTuningJacobianRelTol = 1e-4;

// |ad − fd| <= kTuningJacobianRelTol · (the largest |fd| of the entry's row or column), no absolute part.
camopt::testing::JacobianCheck RelativeToLargest(camopt::testing::JacobianCheck::Scale scale) {
  camopt::testing::JacobianCheck check;
  check.rel_tol = kTuningJacobianRelTol;
  check.abs_tol = 0.0;
  check.scale = scale;
  return check;
}

// The problem's values as a function of its variables, for central differences.
auto ValuesOf(const Problem& p) {
  return [&p](const std::vector<double>& x) {
    std::vector<double> y(size_t(p.evaluator->num_outputs()));
    p.evaluator->Eval(x, y);
    return y;
  };
}

// Contact solves tight enough for central differences to resolve the derivatives.
cycloid::LoadedOptions TightSolves() {
  cycloid::LoadedOptions o;
  o.profile_cells = o.axial_cells = 12;
  o.tolerance = 1e-11;
  o.solver_tolerance = 1e-12;
  o.rough_solver_tolerance = 0;
  o.max_iterations = 400;
  return o;
}

cycloid::Crowning TestCrown() {
  cycloid::Crowning c;
  c.type = cycloid::CrowningType::kLogarithmic;
  c.coefficient_mm = 0.003;
  c.effective_length_mm = 18.7;
  return c;
}

TEST(CycloidTuningProblem, JacobianMatchesCentralDifferencesInTheVariablesUnits) {
  const cycloid::LoadedOptions o = TightSolves();
  const cycloid::Crowning c = TestCrown();
  const std::vector<std::string> names = {"coefficient_mm", "effective_length_mm", "delta_position_um",
                                          "delta_radius_um"};
  CycloidTuningModel model(camopt::testing::CycloidNnm(), c, cycloid::Material{}, o, 350.0e3, 550.0e3,
                           cycloid::UniformCrankAngles(3, 2 * kPi / 16), names, 5.0);
  CycloidTuningSpec spec;
  for (const auto& n : names) spec.variables.push_back({n, -kInf, kInf, 0.0, 1.0});
  const Problem p = CycloidTuningProblem(model, spec, nullptr);
  const std::vector<double> x = {0.003, 18.7, -16.0, -8.0};
  const int m = p.evaluator->num_outputs(), n = int(names.size());
  ASSERT_EQ(m, 1 + 3 + 1 + 3);
  std::vector<double> y(m), jac(size_t(m) * n);
  p.evaluator->EvalWithJacobian(x, y, jac);
  camopt::testing::JacobianCheck check = RelativeToLargest(camopt::testing::JacobianCheck::Scale::kRow);
  check.steps = {3e-8, 1.87e-4, 1e-3, 1e-3};
  check.variable_names = names;
  camopt::testing::ExpectGivenJacobianMatchesCentralDifferences(ValuesOf(p), x, y, jac, check);
  // β0 is the unloaded TE: the crowning does not move it.
  for (int k = 5; k < 8; ++k) EXPECT_EQ(jac[size_t(k) * n + 0], 0.0);
  // Each distinct point runs its cycles once: 1 + 2n cycle runs, 1 derivative run.
  EXPECT_EQ(model.evaluations(), 1 + 2 * n);
  EXPECT_EQ(model.gradient_evaluations(), 1);
}

// A subset of the evaluated angles (the accurate check's v(N) from its 2N run): on every angle it
// is Evaluate's values to the bit; on the even ones it is a model over those angles alone, each
// solve warm-started from another neighbour, equal to the contact solver's tolerance (tight here).
TEST(CycloidTuningModel, ValuesOnASubsetOfTheAnglesEqualARunOverThemAlone) {
  const cycloid::LoadedOptions o = TightSolves();
  const std::vector<double> all = cycloid::UniformCrankAngles(6, 2 * kPi / 16);
  const std::vector<double> even = {all[0], all[2], all[4]};
  CycloidTuningModel model(camopt::testing::CycloidNnm(), TestCrown(), cycloid::Material{}, o, 350.0e3, 550.0e3,
                           all, {}, 5.0);
  EXPECT_THROW(model.EvaluatedOn({0}), std::logic_error);
  const TuningEvaluation full = model.Evaluate({}, false);
  const TuningEvaluation same = model.EvaluatedOn({0, 1, 2, 3, 4, 5});
  EXPECT_EQ(same.stress_MPa, full.stress_MPa);
  EXPECT_EQ(same.smooth_stress_MPa, full.smooth_stress_MPa);
  EXPECT_EQ(same.edge_margin_um, full.edge_margin_um);
  EXPECT_EQ(same.lte_peak_to_peak_arcsec, full.lte_peak_to_peak_arcsec);
  EXPECT_EQ(same.pair_peak_MPa, full.pair_peak_MPa);
  EXPECT_THROW(model.EvaluatedOn({6}), std::out_of_range);

  const TuningEvaluation sub = model.EvaluatedOn({0, 2, 4});
  CycloidTuningModel alone(camopt::testing::CycloidNnm(), TestCrown(), cycloid::Material{}, o, 350.0e3, 550.0e3,
                           even, {}, 5.0);
  const TuningEvaluation ref = alone.Evaluate({}, false);
  EXPECT_NEAR(sub.stress_MPa, ref.stress_MPa, 1e-6 * ref.stress_MPa);
  EXPECT_NEAR(sub.edge_margin_um, ref.edge_margin_um, 1e-6 * std::abs(ref.edge_margin_um) + 1e-9);
  EXPECT_NEAR(sub.lte_peak_to_peak_arcsec, ref.lte_peak_to_peak_arcsec, 1e-6);
  ASSERT_EQ(sub.pair_peak_MPa.size(), ref.pair_peak_MPa.size());
  for (size_t k = 0; k < ref.pair_peak_MPa.size(); ++k)
    EXPECT_NEAR(sub.pair_peak_MPa[k], ref.pair_peak_MPa[k], 1e-6 * ref.stress_MPa) << k;
  // A subset's maximum never exceeds the whole cycle's.
  EXPECT_LE(sub.stress_MPa, full.stress_MPa);
}

// The epigraph form: x = [variables, t], outputs [t, end distance per angle, LTE p-p, β0 per
// angle, p(angle, roller) − t per angle and roller]. Its new rows (every pair's peak minus t)
// against central differences, with the same tight solves and tolerance as above; the peak cell of
// each pair stays put for these steps. Rows of rollers without load are 0 − t.
TEST(CycloidTuningProblem, EpigraphRowsMatchCentralDifferences) {
  const cycloid::LoadedOptions o = TightSolves();
  const cycloid::Crowning c = TestCrown();
  const std::vector<std::string> names = {"coefficient_mm", "delta_position_um", "delta_radius_um"};
  const int angles = 3, rollers = 16;
  CycloidTuningModel model(camopt::testing::CycloidNnm(), c, cycloid::Material{}, o, 350.0e3, 550.0e3,
                           cycloid::UniformCrankAngles(angles, 2 * kPi / 16), names, 5.0);
  CycloidTuningSpec spec;
  for (const auto& n : names) spec.variables.push_back({n, -kInf, kInf, 0.0, 1.0});
  spec.epigraph = true;
  spec.initial_peak_bound_MPa = 1200;
  const Problem p = CycloidTuningProblem(model, spec, nullptr);
  ASSERT_EQ(p.num_vars(), 4);
  EXPECT_EQ(p.objective, kTuningPeakBound);
  const std::vector<double> x = {0.003, -16.0, -8.0, 1234.5};
  const int m = p.evaluator->num_outputs(), n = p.num_vars();
  const int first = 2 + 2 * angles;
  ASSERT_EQ(m, first + angles * rollers);
  std::vector<double> y(m), jac(size_t(m) * n);
  p.evaluator->EvalWithJacobian(x, y, jac);
  EXPECT_EQ(y[0], 1234.5);
  EXPECT_EQ(jac[0 * n + 3], 1.0);
  // The rows' values: the model's pair peaks at each angle minus t.
  const TuningEvaluation e = model.Evaluate({0.003, -16.0, -8.0}, false);
  int loaded = 0;
  for (int k = 0; k < angles * rollers; ++k) {
    EXPECT_EQ(y[first + k], e.pair_peak_MPa[size_t(k)] - 1234.5);
    loaded += e.pair_peak_MPa[size_t(k)] > 0;
  }
  ASSERT_GE(loaded, angles * 2);
  double largest = 0;
  for (double v : e.pair_peak_MPa) largest = std::max(largest, v);
  EXPECT_EQ(largest, e.stress_MPa);
  // Relative to each variable's largest central difference over the new rows; t (variable 3)
  // enters them exactly, checked below.
  camopt::testing::JacobianCheck check = RelativeToLargest(camopt::testing::JacobianCheck::Scale::kColumn);
  check.steps = {3e-8, 1e-3, 1e-3, 0.0};
  check.variables = {0, 1, 2};
  for (int k = first; k < m; ++k) check.rows.push_back(k);
  check.variable_names = {names[0], names[1], names[2], "t"};
  camopt::testing::ExpectGivenJacobianMatchesCentralDifferences(ValuesOf(p), x, y, jac, check);
  for (int k = first; k < m; ++k) EXPECT_EQ(jac[size_t(k) * n + 3], -1.0);
}

TEST(CycloidTuningProblem, VariablesAreCheckedAgainstTheCrowningType) {
  EXPECT_EQ(TuningVariableAllowed("radius_mm", cycloid::CrowningType::kFull), "");
  EXPECT_NE(TuningVariableAllowed("coefficient_mm", cycloid::CrowningType::kFull), "");
  EXPECT_EQ(TuningVariableAllowed("delta_radius_um", cycloid::CrowningType::kNone), "");
  EXPECT_NE(TuningVariableAllowed("radius_mm", cycloid::CrowningType::kLogarithmic), "");
  EXPECT_EQ(TuningVariableAllowed("flat_length_mm", cycloid::CrowningType::kPartial), "");
}

// A small general-form study (coarse: the suite stays fast).
constexpr const char* kJointStudy = R"({
    "study": "cycloid_crowning_tuning",
    "drive": {"teeth": 15, "rollers": 16, "roller_position_radius_mm": 90, "roller_radius_mm": 7.2,
              "eccentricity_mm": 4.5, "face_width_mm": 17},
    "modification": {"delta_position_um": -16, "delta_radius_um": -8},
    "crowning": {"type": "logarithmic", "coefficient_mm": 0.005, "effective_length_mm": 18.7},
    "variables": {"delta_radius_um": [-30, 0], "coefficient_mm": [0, 0.02], "delta_position_um": [-30, 0]},
    "optimizer": {"backend": "ipopt", "max_evaluations": 3},
    "load": {"design_torque_Nm": 350, "max_torque_Nm": 550},
    "material": {"youngs_modulus_GPa": 206, "poisson_ratio": 0.3},
    "tuning": {"curve_points": 3},
    "analysis": {"crank_angles_per_mesh_period": 2, "grid": [10, 10]}})";

namespace tuning = studies::cycloid_crowning_tuning;

std::pair<tuning::Result, nlohmann::json> RunStudy(const std::string& text) {
  const nlohmann::json study = nlohmann::json::parse(text);
  const tuning::Study s = tuning::Parse(studies::Node(&study, "t.json", ""));
  const tuning::Result r = tuning::Run(s, studies::RunContext{"", true});
  return {r, studies::WriteResult(r)};
}

TEST(CycloidTuningStudy, GeneralFormReportsEveryVariableAndTheOptimizer) {
  const auto [r, j] = RunStudy(kJointStudy);
  // Variables in a fixed order whatever the file's, each reported by name.
  ASSERT_EQ(j["tuned"].size(), 3u);
  for (const char* name : {"coefficient_mm", "delta_position_um", "delta_radius_um"})
    EXPECT_TRUE(j["tuned"].contains(name)) << name;
  EXPECT_EQ(j["optimizer"]["backend"], "ipopt");
  EXPECT_GT(j["optimizer"]["gradient_evaluations"].get<int>(), 0);
  EXPECT_GE(j["optimizer"]["evaluations"].get<int>(), j["optimizer"]["gradient_evaluations"].get<int>());
  EXPECT_TRUE(j["estimated_error"].contains("tuned_max_contact_stress_MPa"));
  // The fast model's tuned stress is the exact maximum of the best evaluation; its smooth peak is
  // above it by at most τ ln N (N <= angles × pairs = 2 × 16).
  EXPECT_EQ(j["tuned_max_contact_stress_fast_model_MPa"].get<double>(), r.joint_best.stress_MPa);
  EXPECT_GE(j["tuned_smooth_max_contact_stress_MPa"].get<double>(), r.joint_best.stress_MPa);
  EXPECT_LE(j["tuned_smooth_max_contact_stress_MPa"].get<double>(), r.joint_best.stress_MPa + 2.0 * std::log(32.0));
  // The reported stress is the accurate model's (verification), with its error.
  ASSERT_EQ(j["verification"]["checks"].size(), 2u);
  EXPECT_EQ(j["verification"]["checks"][0]["accurate_value"], j["tuned_max_contact_stress_MPa"]);
  EXPECT_EQ(j["verification"]["checks"][0]["estimated_error"], j["estimated_error"]["tuned_max_contact_stress_MPa"]);
  EXPECT_EQ(j["verification"]["checks"][1]["accurate_value"], j["tuned_edge_margin_at_max_torque_um"]);
  // Ipopt minimises the exact peak (epigraph): the reported design is no worse than its start.
  if (r.feasible) {
    EXPECT_LE(r.joint_best.stress_MPa, r.joint_history.front().stress_MPa);
  }
  ASSERT_EQ(r.curve.size(), 3u);  // f scanned at the other variables' start values
}

TEST(CycloidTuningStudy, ResultDoesNotDependOnTheScanOrWhatRanBefore) {
  // The optimizer starts from the start values, not from the scan: the tuned design, its outputs
  // and the optimizer's report are the same bits with a scan of 0, 3 or 5 points, and the same
  // study gives byte-identical result.json after other studies ran in the process.
  const auto [a, ja] = RunStudy(kJointStudy);
  std::string five = kJointStudy;
  five.replace(five.find("\"curve_points\": 3"), 17, "\"curve_points\": 5");
  const auto [b, jb] = RunStudy(five);
  std::string none = kJointStudy;
  none.replace(none.find("\"curve_points\": 3"), 17, "\"curve_points\": 0");
  const auto [c, jc] = RunStudy(none);
  const auto [d, jd] = RunStudy(kJointStudy);
  EXPECT_EQ(ja.dump(), jd.dump());
  for (const char* key : {"tuned", "optimizer", "tuned_max_contact_stress_MPa", "tuned_edge_margin_at_max_torque_um",
                          "estimated_error", "tuned_smooth_max_contact_stress_MPa"}) {
    EXPECT_EQ(ja[key].dump(), jb[key].dump()) << key;
    EXPECT_EQ(ja[key].dump(), jc[key].dump()) << key;
  }
  // The variables' order in the file does not matter either.
  std::string reordered = kJointStudy;
  reordered.replace(reordered.find("\"variables\""), std::string("\"variables\": {\"delta_radius_um\": [-30, 0], "
                                                                 "\"coefficient_mm\": [0, 0.02], \"delta_position_um\": [-30, 0]}").size(),
                    "\"variables\": {\"delta_position_um\": [-30, 0], \"delta_radius_um\": [-30, 0], "
                    "\"coefficient_mm\": [0, 0.02]}");
  EXPECT_EQ(RunStudy(reordered).second.dump(), ja.dump());
}

// The verified-optimum contract on both shipped examples at their own settings: the tuned design
// re-evaluated at twice the crank angles on a grid with twice the cells holds its edge-margin
// limit within its error; the reported stress and margin are the accurate values.
TEST(CycloidTuningStudy, ExamplesAreVerifiedByTheAccurateModel) {
  for (const char* name : {"cycloid_crowning_tuning_nnm.json", "cycloid_crowning_tuning_joint_nnm.json"}) {
    SCOPED_TRACE(name);
    const nlohmann::json study = camopt::testing::Example(name);
    const tuning::Study s = tuning::Parse(studies::Node(&study, name, ""));
    const tuning::Result r = tuning::Run(s, studies::RunContext{"", true});
    const nlohmann::json j = studies::WriteResult(r);
    EXPECT_EQ(j["verified"], true);
    EXPECT_EQ(j["feasible"], true);
    const nlohmann::json& checks = j["verification"]["checks"];
    ASSERT_EQ(checks.size(), 2u);
    EXPECT_EQ(checks[0]["limit"], "max_contact_stress_MPa");
    EXPECT_EQ(checks[0]["accurate_value"], j["tuned_max_contact_stress_MPa"]);
    EXPECT_EQ(checks[0]["fast_value"], j["tuned_max_contact_stress_fast_model_MPa"]);
    EXPECT_EQ(checks[1]["limit"], "edge_margin_um");
    EXPECT_EQ(checks[1]["upper"], false);
    EXPECT_EQ(checks[1]["limit_value"], 0.0);
    EXPECT_GE(checks[1]["accurate_value"].get<double>(), -checks[1]["estimated_error"].get<double>());
    EXPECT_EQ(checks[1]["accurate_value"], j["tuned_edge_margin_at_max_torque_um"]);
    // The accurate stress differs from the fast one by less than its own estimated error.
    EXPECT_LE(std::abs(j["tuned_max_contact_stress_MPa"].get<double>() -
                       j["tuned_max_contact_stress_fast_model_MPa"].get<double>()),
              j["estimated_error"]["tuned_max_contact_stress_MPa"].get<double>());
    studies::Outputs out;
    tuning::Write(s, r, out);
    EXPECT_EQ(out.incomplete(), "");
  }
}

// A duty cycle in the tuning: the tuned design's lives (the tuning's objective unchanged) agree with
// those of cycloid_ltca run on the tuned design with the accurate model's settings (grid doubled,
// 2n angles per mesh period), and each L10h is 10⁶ (C/P)^p / (60 n̄) from its own table row. The
// two runs' LTCA solves start from different warm starts and stop at the compatibility tolerance:
// measured 1.5e-6 (crank bearing) and 8e-4 (pins, whose lives weigh the lightly loaded pairs that
// enter and leave contact) relative; kSameDesignLifeRelTol bounds both.
TEST(CycloidTuningStudy, TunedDesignLivesEqualTheLtcaOfTheTunedDesign) {
  nlohmann::json study = camopt::testing::Example("cycloid_crowning_tuning_nnm.json");
  study["tuning"]["curve_points"] = 3;
  study["tuning"]["max_evaluations"] = 6;
  study["analysis"] = {{"crank_angles_per_mesh_period", 4}, {"grid", {16, 16}}};
  const nlohmann::json duty = {{{"output_torque_Nm", 350}, {"input_speed_rpm", 1500}, {"time_share", 0.7}},
                               {{"output_torque_Nm", 200}, {"input_speed_rpm", 3000}, {"time_share", 0.3}}};
  const nlohmann::json crank = {{"kind", "roller"}, {"dynamic_rating_N", 60000}, {"static_rating_N", 55000}};
  const nlohmann::json pins = {{"dynamic_rating_N", 7000}, {"static_rating_N", 8000}};
  const nlohmann::json output = {{"pin_count", 8}, {"pin_circle_radius_mm", 50}};
  study["duty_cycle"] = duty;
  study["crank_bearing"] = crank;
  study["pins"] = pins;
  study["output_mechanism"] = output;
  const tuning::Study s = tuning::Parse(studies::Node(&study, "tuning.json", ""));
  const tuning::Result r = tuning::Run(s, studies::RunContext{"", true});
  const nlohmann::json j = studies::WriteResult(r);
  ASSERT_TRUE(j.contains("life")) << j.dump(1);
  const nlohmann::json& life = j["life"];

  nlohmann::json ltca = camopt::testing::Example("cycloid_ltca_life.json");
  ltca["drive"].erase("bore_diameter_mm");
  ltca["crowning"] = {{"type", "logarithmic"}, {"coefficient_mm", j["tuned_coefficient_mm"]},
                      {"effective_length_mm", j["tuned_effective_length_mm"]}};
  ltca["load"] = {{"torque_Nm", 350}};
  ltca["duty_cycle"] = duty;
  ltca["crank_bearing"] = crank;
  ltca["pins"] = pins;
  ltca["output_mechanism"] = output;
  ltca["analysis"] = {{"crank_angles_per_mesh_period", 8}, {"grid", {32, 32}}};
  const studies::cycloid_ltca::Study ls = studies::cycloid_ltca::Parse(studies::Node(&ltca, "ltca.json", ""));
  const nlohmann::json lj = studies::WriteResult(studies::cycloid_ltca::Run(ls, studies::RunContext{"", true}));
  constexpr double kSameDesignLifeRelTol = 2e-3;
  for (const char* key : {"crank_bearing_L10h", "pins_L10h", "shortest_L10h"})
    EXPECT_NEAR(life[key].get<double>(), lj["life"][key].get<double>(),
                kSameDesignLifeRelTol * lj["life"][key].get<double>()) << key;
  for (const nlohmann::json& row : life["table"]) {
    const double p = row["kind"] == "ball" ? 3.0 : 10.0 / 3.0;
    const double hand = 1e6 * std::pow(row["dynamic_rating_N"].get<double>() / row["equivalent_load_N"].get<double>(), p) /
                        (60.0 * row["mean_speed_rpm"].get<double>());
    EXPECT_NEAR(row["L10h"].get<double>(), hand, 1e-9 * hand) << row.dump();
  }
}

// A design whose accurate edge margin breaks the limit beyond its error after the rounds is not
// verified: result.json says so and the run is incomplete (exit 3) with the limit named.
TEST(CycloidTuningStudy, AnUnverifiedDesignEndsIncomplete) {
  const nlohmann::json study = nlohmann::json::parse(kJointStudy);
  const tuning::Study s = tuning::Parse(studies::Node(&study, "t.json", ""));
  tuning::Result r;
  r.feasible = true;
  r.verification.ran = true;
  r.verification.max_rounds = tuning::kVerificationRounds;
  r.verification.accurate_model = "test";
  objectives::VerifiedLimit margin;
  margin.limit = "edge_margin_um";
  margin.where = "max torque";
  margin.limit_value = 0;
  margin.accurate_value = -5;
  margin.estimated_error = 1;
  margin.fast_value = 0.5;
  margin.upper = false;
  r.verification.checks = {margin};
  tuning::FillResult(s, r);
  const nlohmann::json j = studies::WriteResult(r);
  EXPECT_EQ(j["verified"], false);
  EXPECT_EQ(j["verification"]["checks"][0]["holds"], false);
  studies::Outputs out;
  tuning::Write(s, r, out);
  EXPECT_NE(out.incomplete().find("edge_margin_um"), std::string::npos) << out.incomplete();
  EXPECT_NE(out.incomplete().find("not verified"), std::string::npos) << out.incomplete();
  ASSERT_NE(out.result(), nullptr);  // handed to RunStudy, which writes result.json
  EXPECT_EQ((*out.result())["verified"], false);
}

TEST(CycloidTuningStudy, BadGeneralFormsAreInputErrors) {
  auto rejected = [](const std::string& text) {
    const nlohmann::json study = nlohmann::json::parse(text);
    EXPECT_THROW(tuning::Parse(studies::Node(&study, "t.json", "")), studies::StudyError) << text;
  };
  auto with = [](std::string from, const std::string& what, const std::string& by) {
    from.replace(from.find(what), what.size(), by);
    return from;
  };
  const nlohmann::json good = nlohmann::json::parse(kJointStudy);
  EXPECT_NO_THROW(tuning::Parse(studies::Node(&good, "t.json", "")));  // each case below is one edit
  rejected(with(kJointStudy, "\"coefficient_mm\": [0, 0.02]", "\"radius_mm\": [1000, 5000]"));  // not LCM's
  rejected(with(kJointStudy, "\"coefficient_mm\": [0, 0.02]", "\"coefficient_um\": [0, 20]"));   // unknown
  rejected(with(kJointStudy, "\"delta_position_um\": [-30, 0]", "\"delta_position_um\": [-30, 5]"));
  rejected(with(kJointStudy, "\"backend\": \"ipopt\"", "\"backend\": \"bfgs\""));
  rejected(with(kJointStudy, "\"coefficient_mm\": [0, 0.02]", "\"effective_length_mm\": [10, 20]"));  // < B
}

}  // namespace cycloid_tuning_test
}  // namespace camopt::objectives
