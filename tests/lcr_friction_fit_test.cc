// The lcr_friction_fit study: recovery of known friction from synthetic data made by a different
// study (lcr_analysis), the Table 4 fit with its covariance against the linear-regression closed
// form, and bad input.
#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/lcr/friction.h"
#include "tests/test_util.h"

namespace camopt {
namespace {

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

// Measurements made by lcr_analysis with μ = 0.12 plus a drag of 0.02 N·m: the fit returns both.
TEST(LcrFrictionFit, RecoversFrictionFromLcrAnalysisData) {
  const json fit_study = json::parse(ReadFile(SourcePath("studies/examples/lcr_friction_fit.json")));
  json analysis = json::parse(ReadFile(SourcePath("studies/examples/lcr_ii.json")));
  analysis["load"]["friction_coefficient"] = 0.12;
  analysis["analysis"] = {{"angle_steps", 3600}, {"evaluate", {"forces", "efficiency"}}};
  json study = fit_study;
  study["measurements"] = json::array();
  int code = -1;
  std::string err;
  for (double to : {5.0, 15.0, 30.0}) {
    analysis["load"]["output_torque_Nm"] = to;
    const json a = RunJson(analysis, "friction-synthetic-analysis", &code, &err);
    ASSERT_EQ(code, 0) << err;
    const double tin = a["input_torque_Nm"]["mean"].get<double>() + 0.02;
    study["measurements"].push_back({{"output_torque_Nm", to}, {"input_torque_Nm", tin}, {"input_torque_sd_Nm", 0.005}});
  }
  const json res = RunJson(study, "friction-synthetic-fit", &code, &err);
  ASSERT_EQ(code, 0) << err;
  EXPECT_EQ(res["status"], "converged");
  EXPECT_NEAR(res["parameters"]["friction_coefficient"]["value"].get<double>(), 0.12, 1e-6);
  EXPECT_NEAR(res["parameters"]["drag_torque_Nm"]["value"].get<double>(), 0.02, 1e-6);
  EXPECT_LT(res["chi_square"].get<double>(), 1e-8);
  // Without friction the mean input torque is the ideal T_o/|r_i| (power balance).
  EXPECT_NEAR(res["ideal_input_torque_per_output_torque"].get<double>(), 1.0 / 90.0, 1e-9);
}

// Table 4 of the paper: the fit is inside its bounds, every measurement within 3 SD, and the
// covariance equals (X^T W X)^-1 of the equivalent linear regression
// T_in − T_o t_ideal = T_drag + μ (T_o t_friction).
TEST(LcrFrictionFit, Table4FitAndItsCovariance) {
  const json study = json::parse(ReadFile(SourcePath("studies/examples/lcr_friction_fit.json")));
  int code = -1;
  std::string err;
  const json res = RunJson(study, "friction-table4", &code, &err);
  ASSERT_EQ(code, 0) << err;
  EXPECT_EQ(res["status"], "converged");
  for (const char* p : {"friction_coefficient", "drag_torque_Nm"}) {
    EXPECT_FALSE(res["parameters"][p]["at_bound"].get<bool>()) << p;
    EXPECT_GT(res["parameters"][p]["standard_error"].get<double>(), 0.0) << p;
  }
  for (const json& m : res["measurements"]) EXPECT_LT(std::abs(m["weighted_residual"].get<double>()), 3.0);
  const double tf = res["friction_input_torque_per_output_torque_and_mu"];
  double s00 = 0, s01 = 0, s11 = 0;  // X^T W X with columns (T_o t_friction, 1)
  for (const json& m : study["measurements"]) {
    const double w = 1 / std::pow(m["input_torque_sd_Nm"].get<double>(), 2);
    const double x = m["output_torque_Nm"].get<double>() * tf;
    s00 += w * x * x, s01 += w * x, s11 += w;
  }
  const double det = s00 * s11 - s01 * s01;
  const json& cov = res["covariance"];
  EXPECT_NEAR(cov[0][0].get<double>(), s11 / det, 1e-6 * s11 / det);
  EXPECT_NEAR(cov[0][1].get<double>(), -s01 / det, 1e-6 * std::abs(s01 / det));
  EXPECT_NEAR(cov[1][1].get<double>(), s00 / det, 1e-6 * s00 / det);
  // Prediction uncertainty at each load: sqrt(gᵀ C g) with g = (T_o t_friction, 1).
  for (const json& m : res["measurements"]) {
    const double x = m["output_torque_Nm"].get<double>() * tf;
    const double var = (x * x * s11 - 2 * x * s01 + s00) / det;
    EXPECT_NEAR(m["fitted_input_torque_sd_Nm"].get<double>(), std::sqrt(var), 1e-6 * std::sqrt(var));
  }
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

}  // namespace
}  // namespace camopt
