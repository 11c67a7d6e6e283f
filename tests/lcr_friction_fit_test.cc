// The lcr_friction_fit study: the friction law, recovery of known friction from synthetic data
// made by a different study (lcr_analysis), the Table 4 fit with its covariance against the
// linear-regression closed form (C++ entry points), and bad input (CLI).
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/lcr/friction.h"
#include "studies/lcr_analysis_study.h"
#include "studies/lcr_friction_fit_study.h"
#include "studies/report.h"
#include "tests/test_util.h"

namespace camopt {
namespace lcr_friction_fit_test {

using camopt::testing::ReadFile;
using camopt::testing::RunCamopt;
using camopt::testing::SourcePath;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;
using nlohmann::json;

json RunJson(const json& study, const std::string& name, int* code, std::string* err) {
  const auto dir = TempDir(name);
  WriteFile(dir / "study.json", study.dump());
  const auto r = RunCamopt("run " + (dir / "study.json").string() + " --out " + (dir / "out").string() + " -q");
  *code = r.exit_code;
  *err = r.stderr_text;
  return r.exit_code == 0 ? json::parse(ReadFile(dir / "out" / "result.json")) : json();
}

// The friction law of model/lcr/friction.h on hand-computed numbers (eq. 32: T_in = (F_t + μ|F_r|) e,
// eq. 33: η = T_o/(T_in |r_i|)), and its AD gradient in (μ, T_drag).
TEST(LcrFrictionLaw, HandComputedValuesAndGradient) {
  EXPECT_DOUBLE_EQ(lcr::InputTorque(100.0, -40.0, 0.1, 2.0), (100.0 + 4.0) * 2.0);
  EXPECT_DOUBLE_EQ(lcr::InputTorque(100.0, 40.0, 0.0, 2.0), 200.0);
  EXPECT_DOUBLE_EQ(lcr::Efficiency(90.0, 2.0, 50.0), 0.9);
  EXPECT_DOUBLE_EQ(lcr::IdealInputTorque(90.0, -90.0), 1.0);
  const lcr::CycleInputTorque unit = lcr::MeanInputTorquePerOutputTorque({1.0, 3.0}, {-2.0, 4.0}, 0.5);
  EXPECT_DOUBLE_EQ(unit.ideal, 1.0);     // (1 + 3)/2 · 0.5
  EXPECT_DOUBLE_EQ(unit.friction, 1.5);  // (2 + 4)/2 · 0.5
  EXPECT_DOUBLE_EQ(lcr::MeanInputTorque(unit, 10.0, 0.2, 0.03), 0.03 + 10.0 * (1.0 + 0.2 * 1.5));
  testing::ExpectJacobianMatchesCentralDifferences<2>(
      [&](const auto& x) {
        using T = std::decay_t<decltype(x[0])>;
        return std::vector<T>{lcr::MeanInputTorque(unit, T(10.0), x[0], x[1])};
      },
      std::array<double, 2>{0.2, 0.03});
}

namespace fit = studies::lcr_friction_fit;

fit::Result RunFit(const json& study) {
  const studies::Node root(&study, "fit.json", "");
  return fit::Run(fit::Parse(root), {"fit.json", true});
}

// Measurements made by lcr_analysis with μ = 0.12 plus a drag of 0.02 N·m: the fit returns both.
TEST(LcrFrictionFit, RecoversFrictionFromLcrAnalysisData) {
  const json fit_study = json::parse(ReadFile(SourcePath("studies/examples/lcr_friction_fit.json")));
  json analysis = json::parse(ReadFile(SourcePath("studies/examples/lcr_ii.json")));
  analysis["load"]["friction_coefficient"] = 0.12;
  analysis["analysis"] = {{"angle_steps", 3600}, {"evaluate", {"forces", "efficiency"}}};
  json study = fit_study;
  study["measurements"] = json::array();
  for (double to : {5.0, 15.0, 30.0}) {
    analysis["load"]["output_torque_Nm"] = to;
    const studies::Node root(&analysis, "analysis.json", "");
    const auto a = studies::lcr_analysis::Run(studies::lcr_analysis::Parse(root), {"analysis.json", true});
    const double tin = a.input_torque_mean_Nm + 0.02;
    study["measurements"].push_back({{"output_torque_Nm", to}, {"input_torque_Nm", tin}, {"input_torque_sd_Nm", 0.005}});
  }
  const fit::Result res = RunFit(study);
  EXPECT_EQ(res.fit.status, optimizers::SolverStatus::kConverged);
  EXPECT_NEAR(res.fit.x[0], 0.12, 1e-6);
  EXPECT_NEAR(res.fit.x[1], 0.02, 1e-6);
  EXPECT_LT(res.chi_square, 1e-8);
  // Without friction the mean input torque is the ideal T_o/|r_i| (power balance).
  EXPECT_NEAR(res.per_output_torque.ideal, 1.0 / 90.0, 1e-9);
}

// Table 4 of the paper: the fit is inside its bounds, every measurement within 3 SD, and the
// covariance equals (X^T W X)^-1 of the equivalent linear regression
// T_in − T_o t_ideal = T_drag + μ (T_o t_friction).
TEST(LcrFrictionFit, Table4FitAndItsCovariance) {
  const json study = json::parse(ReadFile(SourcePath("studies/examples/lcr_friction_fit.json")));
  const fit::Result res = RunFit(study);
  EXPECT_EQ(res.fit.status, optimizers::SolverStatus::kConverged);
  EXPECT_FALSE(res.friction_coefficient_at_bound);
  EXPECT_FALSE(res.drag_torque_at_bound);
  ASSERT_EQ(res.fit.standard_errors.size(), 2u);
  for (int p = 0; p < 2; ++p) EXPECT_GT(res.fit.standard_errors[p], 0.0) << p;
  for (const fit::Row& m : res.rows) EXPECT_LT(std::abs(m.weighted_residual), 3.0);
  const double tf = res.per_output_torque.friction;
  double s00 = 0, s01 = 0, s11 = 0;  // X^T W X with columns (T_o t_friction, 1)
  for (const json& m : study["measurements"]) {
    const double w = 1 / std::pow(m["input_torque_sd_Nm"].get<double>(), 2);
    const double x = m["output_torque_Nm"].get<double>() * tf;
    s00 += w * x * x, s01 += w * x, s11 += w;
  }
  const double det = s00 * s11 - s01 * s01;
  const std::vector<double>& cov = res.fit.covariance;  // row-major 2 x 2
  ASSERT_EQ(cov.size(), 4u);
  EXPECT_NEAR(cov[0], s11 / det, 1e-6 * s11 / det);
  EXPECT_NEAR(cov[1], -s01 / det, 1e-6 * std::abs(s01 / det));
  EXPECT_NEAR(cov[3], s00 / det, 1e-6 * s00 / det);
  // Prediction uncertainty at each load: sqrt(gᵀ C g) with g = (T_o t_friction, 1).
  ASSERT_EQ(res.rows.size(), study["measurements"].size());
  for (size_t i = 0; i < res.rows.size(); ++i) {
    const double x = study["measurements"][i]["output_torque_Nm"].get<double>() * tf;
    const double var = (x * x * s11 - 2 * x * s01 + s00) / det;
    ASSERT_TRUE(res.rows[i].fitted_input_torque_sd_Nm.has_value());
    EXPECT_NEAR(*res.rows[i].fitted_input_torque_sd_Nm, std::sqrt(var), 1e-6 * std::sqrt(var));
  }
}

// The fit's verdict, the chi-square test: with 3 measurements and 2 parameters (one degree of
// freedom) the p-value is P(χ²(1) ≥ χ²) = erfc(√(χ²/2)) in closed form; the example passes the
// default 0.05, and a study asking for a p-value above the fit's fails.
TEST(LcrFrictionFit, ChiSquareTestIsTheVerdict) {
  json study = json::parse(ReadFile(SourcePath("studies/examples/lcr_friction_fit.json")));
  ASSERT_EQ(study["measurements"].size(), 3u);
  const studies::Node root(&study, "fit.json", "");
  const fit::Input st = fit::Parse(root);
  const json j = studies::WriteResult(fit::Run(st, {"fit.json", true}));
  ASSERT_EQ(j["degrees_of_freedom"], 1);
  const double chi2 = j["chi_square"].get<double>(), p = j["chi_square_p_value"].get<double>();
  EXPECT_NEAR(p, std::erfc(std::sqrt(chi2 / 2)), 1e-12);
  EXPECT_EQ(j["chi_square_p_value_limit"], 0.05);
  studies::HeadlineTable t = studies::EvaluateHeadlines("lcr_friction_fit", study, j);
  EXPECT_EQ(t.limits, 1);
  EXPECT_EQ(t.exceeded.empty(), p >= 0.05) << "p = " << p;
  study["limits"] = {{"chi_square_p_value", std::min(0.999, 2 * p)}};
  const fit::Input strict = fit::Parse(studies::Node(&study, "fit.json", ""));
  const json js = studies::WriteResult(fit::Run(strict, {"fit.json", true}));
  t = studies::EvaluateHeadlines("lcr_friction_fit", study, js);
  ASSERT_EQ(t.exceeded.size(), 1u);
  study["limits"] = {{"chi_square_p_value", 1.0}};
  camopt::testing::ExpectStudyRejected(study, "friction-p", "/limits/chi_square_p_value", "a number in (0, 1)");
}

// The CLI writes what the C++ entry points give: result.json is WriteResult(Run(Parse)); fit.csv has a
// row per measurement of the study file, its torques, and residual = fitted − measured; fit.svg is
// written.
TEST(LcrFrictionFit, CliWritesTheEntryPointsResult) {
  const json study = json::parse(ReadFile(SourcePath("studies/examples/lcr_friction_fit.json")));
  const auto dir = TempDir("friction-cli");
  WriteFile(dir / "study.json", study.dump());
  const auto r = RunCamopt("run " + (dir / "study.json").string() + " --out " + (dir / "out").string() + " -q");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const json written = json::parse(ReadFile(dir / "out" / "result.json"));
  const studies::Node root(&study, "fit.json", "");
  const fit::Input st = fit::Parse(root);
  EXPECT_EQ(camopt::testing::WithoutRunStamp(written), studies::WriteResult(fit::Run(st, {"fit.json", true})));
  for (const char* f : {"fit.csv", "fit.svg"}) EXPECT_TRUE(std::filesystem::exists(dir / "out" / f)) << f;
  const auto table = camopt::testing::ReadCsv(ReadFile(dir / "out" / "fit.csv"));
  const json& measured = study["measurements"];
  ASSERT_EQ(table.at("output_torque_Nm").size(), measured.size());
  for (size_t i = 0; i < measured.size(); ++i) {
    const double input = measured[i]["input_torque_Nm"].get<double>();
    const double fitted = table.at("fitted_input_torque_Nm")[i];
    EXPECT_EQ(table.at("output_torque_Nm")[i], measured[i]["output_torque_Nm"].get<double>()) << i;
    EXPECT_EQ(table.at("measured_input_torque_Nm")[i], input) << i;
    EXPECT_NEAR(table.at("residual_Nm")[i], fitted - input, 1e-9) << i;
    EXPECT_NEAR(fitted, written["measurements"][i]["fitted_input_torque_Nm"].get<double>(), 1e-9 * std::abs(fitted)) << i;
  }
  const std::string svg = ReadFile(dir / "out" / "fit.svg");
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

TEST(LcrFrictionFit, BadInputIsExitCode2) {
  json study = json::parse(ReadFile(SourcePath("studies/examples/lcr_friction_fit.json")));
  study["measurements"].erase(0);
  int code = -1;
  std::string err;
  RunJson(study, "friction-bad", &code, &err);
  EXPECT_EQ(code, 2);
  EXPECT_NE(err.find("/measurements"), std::string::npos) << err;
  study = json::parse(ReadFile(SourcePath("studies/examples/lcr_friction_fit.json")));
  study["parameters"]["friction_coefficient"]["initial"] = 2.0;
  RunJson(study, "friction-bad2", &code, &err);
  EXPECT_EQ(code, 2);
  EXPECT_NE(err.find("/parameters/friction_coefficient/initial"), std::string::npos) << err;
}

TEST(LcrFrictionFit, MisspeltNestedFieldIsRejected) {
  // Would otherwise start from the default 0.05.
  json study = json::parse(ReadFile(SourcePath("studies/examples/lcr_friction_fit.json")));
  study["parameters"]["friction_coefficient"]["intial"] = 0.1;
  camopt::testing::ExpectStudyRejected(study, "friction-typo", "/parameters/friction_coefficient/intial",
                                       "unknown field");
}

}  // namespace lcr_friction_fit_test
}  // namespace camopt
