// lcr_analysis with "analysis.load_model" and "tolerances": numbers through Parse/Run,
// bad input through the CLI.
#include <gtest/gtest.h>

#include "studies/input.h"
#include "studies/lcr_analysis_study.h"
#include "tests/test_util.h"

namespace camopt {
namespace lcr_tolerance_study_test {

using camopt::testing::Example;
using camopt::testing::ExpectStudyRejected;

studies::lcr_analysis::Result RunStudy(const nlohmann::json& j) {
  const studies::Node root(&j, "lcr.json", "");
  return studies::lcr_analysis::Run(studies::lcr_analysis::Parse(root), {"lcr.json", true});
}

// The two named load models on LCR II at 80 N·m: the paper's rigid law 957.9 N (paper Table 3:
// 960 N) and the compliant contacts, which give the stiffness model's 974.6 N.
TEST(LcrLoadModel, RigidAndCompliantLargestInputForce) {
  nlohmann::json j = Example("lcr_ii.json");
  j["analysis"]["angle_steps"] = 360;
  j["analysis"]["evaluate"] = {"forces", "stress"};
  const auto rigid = RunStudy(j);
  j["analysis"]["load_model"] = "compliant";
  const auto compliant = RunStudy(j);
  EXPECT_NEAR(rigid.input_cam.max_roller_force_N, 957.9, 0.1);
  EXPECT_NEAR(compliant.input_cam.max_roller_force_N, 974.6, 0.1);
  EXPECT_GT(compliant.input_cam.max_contact_stress_MPa, rigid.input_cam.max_contact_stress_MPa);
  EXPECT_EQ(studies::WriteResult(compliant)["load_model"], "compliant");
}

TEST(LcrLoadModel, TolerancesAddTransmissionError) {
  nlohmann::json j = Example("lcr_ii_tolerances.json");
  j["analysis"]["evaluate"] = {"forces"};
  j["analysis"]["angle_steps"] = 36;
  j["monte_carlo"] = {{"samples", 20}, {"seed", 1}, {"angle_steps", 24}};
  const studies::Node root(&j, "lcr.json", "");
  const auto st = studies::lcr_analysis::Parse(root);
  const auto res = studies::lcr_analysis::Run(st, {"lcr.json", true});
  ASSERT_TRUE(res.transmission_error.has_value());
  const nlohmann::json te = studies::WriteResult(res)["transmission_error"];
  for (const char* k : {"linear_worst_case_arcsec", "linear_rms_arcsec", "monte_carlo_max_arcsec",
                        "monte_carlo_p99_arcsec", "monte_carlo_rms_arcsec", "lost_motion_arcmin"})
    EXPECT_GT(te[k].get<double>(), 0.0) << k;
  for (const char* k : {"eccentricity_um", "turret_radius_um", "roller_diameter_um", "roller_pitch_arcsec",
                        "profile_um", "bearing_clearance_um"})
    EXPECT_TRUE(te["contributions"].contains(k)) << k;
  EXPECT_LE(te["monte_carlo_p99_arcsec"].get<double>(), te["monte_carlo_max_arcsec"].get<double>());
}

TEST(LcrLoadModel, BadInputIsRejected) {
  nlohmann::json j = Example("lcr_ii_tolerances.json");
  j["analysis"]["load_model"] = "elastic";
  ExpectStudyRejected(j, "load-model", "/analysis/load_model", "rigid");
  j = Example("lcr_ii_tolerances.json");
  j["tolerances"]["roller_diameter_um"] = -1;
  ExpectStudyRejected(j, "tol-negative", "/tolerances/roller_diameter_um", "expected");
  j = Example("lcr_ii_tolerances.json");
  j["tolerances"]["flatness_um"] = 1;
  ExpectStudyRejected(j, "tol-unknown", "/tolerances/flatness_um", "unknown field");
  j = Example("lcr_ii.json");
  j["monte_carlo"] = {{"samples", 10}};
  ExpectStudyRejected(j, "mc-alone", "/monte_carlo", "tolerances");
}

}  // namespace lcr_tolerance_study_test
}  // namespace camopt
