// The lcr_min_size study end to end through the CLI: the ratio −90 example, its best design run
// back through lcr_analysis, backend agreement, the roller catalogue, and bad input.
#include <cmath>
#include <algorithm>
#include <filesystem>
#include <map>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/lcr/kinematics.h"
#include "model/lcr/reducer.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt {
namespace {

using camopt::testing::ReadFile;
using camopt::testing::RunCamopt;
using camopt::testing::SourcePath;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;
using nlohmann::json;

using camopt::testing::Example;

// Runs a study given as json in dir; returns result.json (or null json on a non-zero exit).
json RunStudy(const json& study, const std::filesystem::path& dir, int* exit_code = nullptr,
         std::string* stderr_text = nullptr) {
  const auto file = dir / "study.json";
  WriteFile(file, study.dump());
  const auto r = RunCamopt("run " + file.string() + " --out " + (dir / "out").string() + " --quiet");
  if (exit_code) *exit_code = r.exit_code;
  if (stderr_text) *stderr_text = r.stderr_text;
  if (r.exit_code != 0) return json();
  return json::parse(ReadFile(dir / "out" / "result.json"));
}

TEST(LcrMinSize, RatioMinus90BestSatisfiesEveryLimitInLcrAnalysis) {
  const auto dir = TempDir("lcr-min-size-90");
  const json study = Example("lcr_min_size.json");
  int code = -1;
  std::string err;
  const json res = RunStudy(study, dir, &code, &err);
  ASSERT_EQ(code, 0) << err;
  EXPECT_EQ(err, "");  // --quiet: no progress line
  ASSERT_TRUE(res["best"].is_object());
  const json& best = res["best"];
  EXPECT_EQ(best["speed_ratio"].get<double>(), -90.0);
  EXPECT_EQ(lcr::SpeedReductionRatio(best["input"]["lobes"], best["input"]["rollers"],
                                     best["output"]["lobes"], best["output"]["rollers"]),
            -90.0);
  // Outer diameter by the study's definition, from the reported design.
  const double rr = best["input"]["roller_diameter_mm"].get<double>() / 2;
  EXPECT_NEAR(best["outer_diameter_mm"].get<double>(),
              2 * std::max(best["input"]["turret_radius_mm"].get<double>() + rr,
                           best["output"]["turret_radius_mm"].get<double>() + rr),
              1e-9);
  // The paper's LCR II is 96 mm by the same definition; the study beats it by a wide margin.
  const double lcr_ii = lcr::OuterDiameter(camopt::testing::LcrII());
  EXPECT_DOUBLE_EQ(lcr_ii, 96.0);
  EXPECT_LT(best["outer_diameter_mm"].get<double>(), 0.8 * lcr_ii);
  // One candidate per combination, each with a status and what binds it.
  ASSERT_EQ(res["candidates"].size(), 4u);
  for (const json& c : res["candidates"]) {
    EXPECT_TRUE(c.contains("status"));
    EXPECT_TRUE(c["binding"].is_array());
  }

  // Run the best design back through lcr_analysis and check every limit there.
  const auto analysis_dir = TempDir("lcr-min-size-90-analysis");
  const auto r = RunCamopt("run " + (dir / "out" / "best_lcr_analysis.json").string() + " --out " +
                           (analysis_dir / "out").string() + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const json a = json::parse(ReadFile(analysis_dir / "out" / "result.json"));
  EXPECT_EQ(a["speed_ratio"].get<double>(), -90.0);
  EXPECT_NEAR(a["outer_diameter_mm"].get<double>(), best["outer_diameter_mm"].get<double>(), 1e-9);
  const json& limits = study["limits"];
  for (const char* side : {"input_cam", "output_cam"}) {
    const json& s = a[side];
    EXPECT_TRUE(s["contact_stress_ok"].get<bool>()) << side;
    EXPECT_TRUE(s["roller_load_ok"].get<bool>()) << side;
    EXPECT_LE(s["max_contact_stress_MPa"].get<double>(), limits["contact_stress_MPa"].get<double>());
    EXPECT_LE(s["max_roller_force_N"].get<double>(), limits["roller_load_N"].get<double>());
    EXPECT_GE(s["undercut_margin_mm"].get<double>(), limits["undercut_margin_mm"].get<double>());
    EXPECT_GE(s["roller_gap_mm"].get<double>(), limits["roller_gap_mm"].get<double>());
    EXPECT_FALSE(s["undercut"].get<bool>());
  }
}

// NLopt (SLSQP) and Ipopt reach the same optimum within 0.5% of the outer diameter; COBYLA, with
// no gradients, reaches it too but needs far more model evaluations than Ipopt.
TEST(LcrMinSize, BackendsAgreeAndGradientsSaveEvaluations) {
  json study = Example("lcr_min_size.json");
  std::map<std::string, json> res;
  for (const char* backend : {"ipopt", "nlopt_slsqp", "nlopt_cobyla"}) {
    study["optimizer"]["backend"] = backend;
    int code = -1;
    std::string err;
    res[backend] = RunStudy(study, TempDir(std::string("lcr-min-size-") + backend), &code, &err);
    ASSERT_EQ(code, 0) << backend << ": " << err;
    ASSERT_TRUE(res[backend]["best"].is_object()) << backend;
  }
  const double od = res["ipopt"]["best"]["outer_diameter_mm"];
  EXPECT_NEAR(res["nlopt_slsqp"]["best"]["outer_diameter_mm"].get<double>(), od, 0.005 * od);
  EXPECT_NEAR(res["nlopt_cobyla"]["best"]["outer_diameter_mm"].get<double>(), od, 0.005 * od);
  const json& ipopt = res["ipopt"]["optimizer"];
  const json& cobyla = res["nlopt_cobyla"]["optimizer"];
  EXPECT_EQ(cobyla["gradient_evaluations"].get<int>(), 0);
  const int ipopt_runs = ipopt["value_evaluations"].get<int>() + ipopt["gradient_evaluations"].get<int>();
  EXPECT_LT(3 * ipopt_runs, cobyla["value_evaluations"].get<int>());
}

// An efficiency limit that binds (the unconstrained optimum has 92.2% at μ = 0.05): the best
// design meets it in lcr_analysis' own 3600-angle mean.
TEST(LcrMinSize, EfficiencyLimitIsHeld) {
  json study = Example("lcr_min_size.json");
  study["limits"]["min_efficiency"] = 0.93;
  study["optimizer"]["backend"] = "nlopt_slsqp";
  const auto dir = TempDir("lcr-min-size-efficiency");
  int code = -1;
  std::string err;
  const json res = RunStudy(study, dir, &code, &err);
  ASSERT_EQ(code, 0) << err;
  ASSERT_TRUE(res["best"].is_object());
  const json& binding = res["best"]["binding"];
  EXPECT_NE(std::find(binding.begin(), binding.end(), "mean_efficiency"), binding.end());
  const auto r = RunCamopt("run " + (dir / "out" / "best_lcr_analysis.json").string() + " --out " +
                           (dir / "analysis").string() + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const json a = json::parse(ReadFile(dir / "analysis" / "result.json"));
  EXPECT_GE(a["efficiency"]["mean"].get<double>(), 0.93);
  EXPECT_NEAR(a["efficiency"]["mean"].get<double>(), res["best"]["mean_efficiency"].get<double>(), 1e-12);
}

// A roller size per cam when the study asks for it: never larger than with one roller for both
// (the one-roller design is a feasible point of the wider problem), and still within every limit.
TEST(LcrMinSize, RollerPerCam) {
  json study = Example("lcr_min_size.json");
  study["search"]["max_lobes"] = 14;  // LCR II's combination only
  study["optimizer"]["backend"] = "nlopt_slsqp";
  int code = -1;
  std::string err;
  const json same = RunStudy(study, TempDir("lcr-min-size-same"), &code, &err);
  ASSERT_EQ(code, 0) << err;
  study["variables"]["same_roller_on_both_cams"] = false;
  const auto dir = TempDir("lcr-min-size-per-cam");
  const json per_cam = RunStudy(study, dir, &code, &err);
  ASSERT_EQ(code, 0) << err;
  ASSERT_TRUE(same["best"].is_object() && per_cam["best"].is_object());
  EXPECT_LE(per_cam["best"]["outer_diameter_mm"].get<double>(),
            same["best"]["outer_diameter_mm"].get<double>() * (1 + 1e-6));
  const auto r = RunCamopt("run " + (dir / "out" / "best_lcr_analysis.json").string() + " --out " +
                           (dir / "analysis").string() + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const json a = json::parse(ReadFile(dir / "analysis" / "result.json"));
  for (const char* side : {"input_cam", "output_cam"}) {
    EXPECT_TRUE(a[side]["contact_stress_ok"].get<bool>());
    EXPECT_TRUE(a[side]["roller_load_ok"].get<bool>());
    EXPECT_GE(a[side]["undercut_margin_mm"].get<double>(), 0.5);
    EXPECT_GE(a[side]["roller_gap_mm"].get<double>(), 1.0);
  }
  // With a catalogue the catalogue roller serves both cams: asking otherwise is an error.
  study["roller_catalogue"] = json::parse(R"([{"diameter_mm": 5, "length_mm": 10, "load_limit_N": 800}])");
  RunStudy(study, TempDir("lcr-min-size-per-cam-bad"), &code, &err);
  EXPECT_EQ(code, 2);
  EXPECT_NE(err.find("/variables/same_roller_on_both_cams"), std::string::npos) << err;
}

TEST(LcrMinSize, CatalogueRollerIsPickedAndItsLoadLimitHeld) {
  json study = Example("lcr_min_size_catalogue.json");
  study["search"]["max_lobes"] = 26;  // two combinations (12/14, 20/26): keep the test short
  study["roller_catalogue"] = json::parse(R"([
    {"name": "A", "diameter_mm": 5, "length_mm": 10, "load_limit_N": 800},
    {"name": "B", "diameter_mm": 6, "length_mm": 10, "load_limit_N": 1000}])");
  int code = -1;
  std::string err;
  const json res = RunStudy(study, TempDir("lcr-min-size-catalogue"), &code, &err);
  ASSERT_EQ(code, 0) << err;
  ASSERT_EQ(res["candidates"].size(), 4u);  // 2 combinations × 2 rollers
  const json& best = res["best"];
  ASSERT_TRUE(best.is_object());
  const std::string name = best["catalogue_roller"];
  const double d = best["input"]["roller_diameter_mm"];
  EXPECT_EQ(d, name == "A" ? 5.0 : 6.0);
  EXPECT_EQ(best["output"]["roller_diameter_mm"].get<double>(), d);
  EXPECT_EQ(best["input"]["roller_length_mm"].get<double>(), 10.0);
  EXPECT_LE(best["max_roller_force_N"].get<double>(), name == "A" ? 800.0 : 1000.0);
  for (const json& c : res["candidates"]) {
    if (!c["feasible"].get<bool>()) continue;
    EXPECT_GE(c["outer_diameter_mm"].get<double>(), best["outer_diameter_mm"].get<double>());
  }
}

// The catalogue file is found relative to the study file, whatever the working directory.
TEST(LcrMinSize, CatalogueFileRelativeToTheStudy) {
  json study = Example("lcr_min_size_catalogue.json");
  study["search"]["max_lobes"] = 14;
  const auto dir = TempDir("lcr-min-size-catalogue-file");
  std::filesystem::copy_file(SourcePath("studies/examples/needle_rollers.json"), dir / "needle_rollers.json");
  const json res = RunStudy(study, dir, nullptr, nullptr);
  ASSERT_TRUE(res.is_object());
  const json catalogue = json::parse(ReadFile(dir / "needle_rollers.json"));
  EXPECT_EQ(res["candidates"].size(), catalogue.size());  // one combination × every roller
  ASSERT_TRUE(res["best"].is_object());
  bool found = false;
  for (const json& r : catalogue)
    found = found || (r["name"] == res["best"]["catalogue_roller"] &&
                      r["diameter_mm"].get<double>() == res["best"]["input"]["roller_diameter_mm"].get<double>());
  EXPECT_TRUE(found);
}

TEST(LcrMinSize, ImpossibleLimitsGiveNoBestAndSayWhy) {
  json study = Example("lcr_min_size.json");
  study["search"]["max_lobes"] = 14;
  study["limits"]["contact_stress_MPa"] = 50;  // unreachable within the size bounds
  int code = -1;
  std::string err;
  const json res = RunStudy(study, TempDir("lcr-min-size-impossible"), &code, &err);
  ASSERT_EQ(code, 0) << err;
  EXPECT_TRUE(res["best"].is_null());
  ASSERT_EQ(res["candidates"].size(), 1u);
  const json& c = res["candidates"][0];
  EXPECT_FALSE(c["feasible"].get<bool>());
  EXPECT_NE(c["status"].get<std::string>(), "converged");
  EXPECT_FALSE(c["violated"].empty());
}

TEST(LcrMinSize, ProgressLineWithoutQuiet) {
  json study = Example("lcr_min_size.json");
  study["search"]["max_lobes"] = 14;
  const auto dir = TempDir("lcr-min-size-progress");
  WriteFile(dir / "study.json", study.dump());
  const auto r = RunCamopt("run " + (dir / "study.json").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("lcr_min_size:"), std::string::npos) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("12/13 + 14/15"), std::string::npos) << r.stderr_text;
}

TEST(LcrMinSize, BadInputIsAClearErrorWithExitCode2) {
  struct Case {
    std::string pointer, value, expect;
  };
  const std::vector<Case> cases = {
      {"/target/speed_ratio", "-90.5", "/target/speed_ratio"},
      {"/optimizer/backend", "\"simplex\"", "/optimizer/backend"},
      {"/search/roller_lobe_difference", "[2]", "/search/roller_lobe_difference/0"},
      {"/variables/eccentricity_mm", "[5, 0.5]", "/variables/eccentricity_mm"},
      {"/search/max_lobes", "3", "no lobe/roller combination"},
      {"/roller_catalogue", "{\"file\": \"no_such_file.json\"}", "no_such_file.json"},
      {"/optimizer/samples_per_period", "100000", "/optimizer/samples_per_period"},
      {"/optimizer/constraints", "\"all\"", "/optimizer/constraints"},
  };
  for (const auto& c : cases) {
    json study = Example("lcr_min_size.json");
    study["search"]["max_lobes"] = 14;  // one combination: keep the test short
    study[json::json_pointer(c.pointer)] = json::parse(c.value);
    int code = -1;
    std::string err;
    RunStudy(study, TempDir("lcr-min-size-bad"), &code, &err);
    EXPECT_EQ(code, 2) << c.pointer << " = " << c.value << ": " << err;
    EXPECT_NE(err.find(c.expect), std::string::npos) << err;
  }
}

TEST(LcrMinSize, MisspeltNestedFieldIsRejected) {
  // Would otherwise be read as "no efficiency limit".
  json study = Example("lcr_min_size.json");
  study["limits"]["min_efficency"] = 0.9;
  camopt::testing::ExpectStudyRejected(study, "lcr-min-size-typo", "/limits/min_efficency", "unknown field");
  // A catalogue entry's fields are checked too.
  study = Example("lcr_min_size_catalogue.json");
  study["roller_catalogue"] = json::parse(
      R"([{"nmae": "NR 6x10", "diameter_mm": 6, "length_mm": 10, "load_limit_N": 1050}])");
  camopt::testing::ExpectStudyRejected(study, "lcr-min-size-catalogue-typo", "/roller_catalogue/0/nmae",
                                       "unknown field");
}

}  // namespace
}  // namespace camopt
