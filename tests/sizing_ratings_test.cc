// "ratings" in the sizing kinds (docs/ratings.md, Ratings as sizing limits): the sized design reaches
// the rated torque asked for, checked by the analysis kind that solves ratings (lcr_analysis,
// cycloid_ltca) run on the best design the sizing writes, not by the sizing's own numbers; and the
// block's conflicts exit 2 naming it.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "tests/test_util.h"

namespace sizing_ratings_test {

namespace t = camopt::testing;

struct CliRun {
  int exit_code = -1;
  std::string stderr_text;
  nlohmann::json result;
  std::filesystem::path out;
};

CliRun RunFile(const std::filesystem::path& file, const std::filesystem::path& out) {
  const auto res = t::RunCamopt("run " + file.string() + " --quiet --out " + out.string());
  CliRun r;
  r.exit_code = res.exit_code;
  r.stderr_text = res.stderr_text;
  r.out = out;
  if (std::filesystem::exists(out / "result.json")) r.result = nlohmann::json::parse(t::ReadFile(out / "result.json"));
  return r;
}

CliRun RunStudy(const nlohmann::json& study, const std::string& tag) {
  const auto dir = t::TempDir("sizing-ratings-" + tag);
  t::WriteFile(dir / "study.json", study.dump());
  return RunFile(dir / "study.json", dir / "out");
}

// lcr_min_size_life.json with the rated point instead of its life limit: 60 N·m for 6000 h at 15 rpm.
nlohmann::json LcrRated() {
  nlohmann::json s = t::Example("lcr_min_size_life.json");
  s["limits"].erase("life_h");
  s["load"].erase("input_speed_rpm");
  s["load"]["friction_coefficient"] = 0.0;
  s["ratings"] = {{"rated_torque_Nm", 60.0}, {"rated_life_h", 6000.0}, {"rated_output_speed_rpm", 15.0}};
  return s;
}

// cycloid_min_size_quick.json with the ratio-29 life example's bearings: 15 N·m for 800 h at 30 rpm.
nlohmann::json CycloidRated() {
  nlohmann::json s = t::Example("cycloid_min_size_quick.json");
  const nlohmann::json life = t::Example("cycloid_min_size_ratio29_life.json");
  for (const char* k : {"crank_bearing", "pins", "output_mechanism"}) s[k] = life[k];
  s["ratings"] = {{"rated_torque_Nm", 15.0}, {"rated_life_h", 800.0}, {"rated_output_speed_rpm", 30.0}};
  return s;
}

TEST(SizingRatings, LcrSizedReducerReachesTheRatedTorqueAsLcrAnalysisSolvesIt) {
  const CliRun run = RunStudy(LcrRated(), "lcr");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  ASSERT_TRUE(run.result["verified"].get<bool>());
  const nlohmann::json& g = run.result["best"]["ratings"];
  EXPECT_TRUE(g["met"].get<bool>());
  EXPECT_GE(g["L10h_at_required_torque"].get<double>(), 6000.0);
  // The lives' one line is the rated point: 15 rpm at the output, |r_i| = 90 times that at the input.
  const nlohmann::json& line = run.result["best"]["life"]["duty_cycle"][0];
  EXPECT_EQ(line["output_torque_Nm"].get<double>(), 60.0);
  EXPECT_EQ(line["input_speed_rpm"].get<double>(), 1350.0);
  // The life binds, so the design's rated torque is the one asked for within the sizing's tolerance.
  const double sized = g["rated_torque_Nm"].get<double>();
  EXPECT_GE(sized, 60.0 * (1 - 1e-9));
  EXPECT_LT(sized, 60.0 * 1.001);
  // lcr_analysis on the best design: its rated torque, a root search of analyses at trial torques,
  // against the sizing's closed form of the rigid law.
  const CliRun check = RunFile(run.out / "best_lcr_analysis.json", run.out / "analysis");
  ASSERT_EQ(check.exit_code, 0) << check.stderr_text;
  EXPECT_NEAR(check.result["rated_torque_Nm"].get<double>(), sized, 1e-9 * sized);
  EXPECT_EQ(check.result["ratings"]["rated_by"], g["rated_by"]);
}

// The momentary torque as a limit of lcr_min_size: every bearing with C0 keeps s0 >= 1 at 250 N·m
// (the rows' soft maximum of the sampled roller loads is above the largest, so the design errs on
// the safe side); lcr_analysis on the best design solves the same momentary torque by its own root
// search, and its s0 at 250 N·m is what the sizing reports.
TEST(SizingRatings, LcrMomentaryTorqueLimitHoldsAsLcrAnalysisSolvesIt) {
  nlohmann::json study = LcrRated();
  study["search"]["max_lobes"] = 14;  // one combination (12/13 + 14/15): a short test
  study["ratings"]["momentary_torque_Nm"] = 250.0;
  const CliRun run = RunStudy(study, "lcr-momentary");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  ASSERT_TRUE(run.result["verified"].get<bool>());
  const nlohmann::json& g = run.result["best"]["ratings"];
  EXPECT_TRUE(g["met"].get<bool>());
  EXPECT_TRUE(g["momentary_met"].get<bool>());
  // The accurate model's check holds the momentary torque's s0 like every other limit.
  bool checked = false;
  for (const auto& c : run.result["verification"]["checks"])
    if (c["limit"] == "min_static_safety") checked = c["holds"].get<bool>();
  EXPECT_TRUE(checked) << run.result["verification"].dump();
  const double s0 = g["s0_at_required_momentary_torque"].get<double>();
  EXPECT_GE(s0, 1.0);
  EXPECT_LT(s0, 1.05);  // the static row binds (within the soft maximum's bias)
  const double sized = g["momentary_torque_Nm"].get<double>();
  EXPECT_NEAR(sized, 250.0 * s0, 1e-9 * sized);  // s0 ∝ 1/T under the rigid law
  const CliRun check = RunFile(run.out / "best_lcr_analysis.json", run.out / "analysis");
  ASSERT_EQ(check.exit_code, 0) << check.stderr_text;
  EXPECT_NEAR(check.result["momentary_torque_Nm"].get<double>(), sized, 1e-9 * sized);
  EXPECT_EQ(check.result["ratings"]["momentary_limited_by"].get<std::string>(),
            g["momentary_by"].get<std::string>() + " (static rating)");
  // The same sizing without static ratings has nothing to hold the momentary torque: exit 2.
  study["rollers"].erase("static_rating_N");
  study["eccentric_bearing"].erase("static_rating_N");
  const CliRun bad = RunStudy(study, "lcr-momentary-no-c0");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.stderr_text.find("/ratings/momentary_torque_Nm"), std::string::npos) << bad.stderr_text;
}

TEST(SizingRatings, CycloidSizedDriveReachesTheRatedTorqueAsCycloidLtcaSolvesIt) {
  const CliRun run = RunStudy(CycloidRated(), "cycloid");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  ASSERT_TRUE(run.result["verified"].get<bool>());
  const nlohmann::json& g = run.result["best"]["ratings"];
  EXPECT_TRUE(g["met"].get<bool>());
  EXPECT_GE(g["L10h_at_required_torque"].get<double>(), 800.0);
  EXPECT_EQ(run.result["best"]["life"]["duty_cycle"][0]["input_speed_rpm"].get<double>(), 870.0);
  EXPECT_TRUE(g["rated_torque_Nm"].is_null());
  // cycloid_ltca on the best design solves the rated torque on LTCA cycles at trial torques: at
  // least the one asked for (less its estimated error), and close to it where the life binds.
  const CliRun check = RunFile(run.out / "best_cycloid_ltca.json", run.out / "analysis");
  ASSERT_EQ(check.exit_code, 0) << check.stderr_text;
  const double rated = check.result["rated_torque_Nm"].get<double>();
  const double error = check.result["ratings"]["estimated_error"]["rated_torque_Nm"].get<double>();
  EXPECT_GE(rated, 15.0 - error);
  EXPECT_LT(rated, 15.0 * 1.01);
}

// The momentary torque as a limit of cycloid_min_size: 52 N·m with the output pins on a 16 mm circle
// (on 12 mm their resultant dominates the crank bearing's load, which then hardly falls with the
// drive's size), above what the rated-only design holds, so the static rows bind (the crank
// bearing's C0); cycloid_ltca on the best design root-solves its momentary torque on LTCA cycles:
// 52 N·m within their two estimated errors, and the accurate model's s0 at 52 N·m is 1 within its.
TEST(SizingRatings, CycloidMomentaryTorqueLimitHoldsAsCycloidLtcaSolvesIt) {
  nlohmann::json study = CycloidRated();
  study["output_mechanism"]["pin_circle_radius_mm"] = 16;
  study["ratings"]["momentary_torque_Nm"] = 52.0;
  const CliRun run = RunStudy(study, "cycloid-momentary");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  ASSERT_TRUE(run.result["verified"].get<bool>());
  const nlohmann::json& g = run.result["best"]["ratings"];
  EXPECT_TRUE(g["met"].get<bool>());  // as verified: within the estimated error
  EXPECT_TRUE(g["momentary_met"].get<bool>());
  const double s0 = g["s0_at_required_momentary_torque"].get<double>();
  const double s0_error = run.result["best"]["estimated_error"]["min_static_safety"].get<double>();
  EXPECT_GE(s0, 1.0 - s0_error);
  EXPECT_LT(s0, 1.01);  // it binds
  bool checked = false;
  for (const auto& c : run.result["verification"]["checks"])
    if (c["limit"] == "min_static_safety") checked = c["holds"].get<bool>();
  EXPECT_TRUE(checked) << run.result["verification"].dump();
  const CliRun check = RunFile(run.out / "best_cycloid_ltca.json", run.out / "analysis");
  ASSERT_EQ(check.exit_code, 0) << check.stderr_text;
  const double momentary = check.result["momentary_torque_Nm"].get<double>();
  const double error = check.result["ratings"]["estimated_error"]["momentary_torque_Nm"].get<double>();
  std::printf("[ sizing   ] momentary torque of the sized drive %.4f +- %.4f N m (52 asked), s0 %.6f +- %.1e\n",
              momentary, error, s0, s0_error);
  EXPECT_EQ(check.result["ratings"]["momentary_limited_by"], "crank_bearing (static rating)");
  EXPECT_NEAR(momentary, 52.0, error + 52.0 * s0_error);
}

TEST(SizingRatings, ConflictsAndMissingBearingsExitTwoNamingTheBlock) {
  nlohmann::json a = LcrRated();
  a["limits"]["life_h"] = 1000;
  CliRun r = RunStudy(a, "lcr-life");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("/ratings"), std::string::npos) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("limits.life_h"), std::string::npos) << r.stderr_text;

  nlohmann::json b = CycloidRated();
  b["duty_cycle"] = {{{"output_torque_Nm", 10}, {"input_speed_rpm", 1000}, {"time_share", 1}}};
  r = RunStudy(b, "cycloid-duty");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("ratings"), std::string::npos) << r.stderr_text;

  nlohmann::json m = CycloidRated();
  m["ratings"]["momentary_torque_Nm"] = 40;
  m["crank_bearing"].erase("static_rating_N");
  m["pins"].erase("static_rating_N");
  r = RunStudy(m, "cycloid-momentary-no-c0");
  EXPECT_EQ(r.exit_code, 2);  // nothing to hold the momentary torque with
  EXPECT_NE(r.stderr_text.find("/ratings/momentary_torque_Nm"), std::string::npos) << r.stderr_text;

  nlohmann::json c = CycloidRated();
  c.erase("crank_bearing");
  r = RunStudy(c, "cycloid-no-bearing");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("/crank_bearing"), std::string::npos) << r.stderr_text;

  nlohmann::json d = LcrRated();
  d.erase("rollers");
  r = RunStudy(d, "lcr-no-rollers");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("/rollers"), std::string::npos) << r.stderr_text;
}

}  // namespace sizing_ratings_test
