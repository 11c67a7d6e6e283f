// The disc_cam study: the paper's example, the oscillating example and an undercut cam through
// the C++ entry points (Parse, Run); the files the CLI writes; and every kind of bad input rejected
// with exit code 2 and a message naming the JSON path.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/common/scalar.h"
#include "studies/disc_cam_study.h"
#include "studies/study.h"
#include "tests/test_util.h"

namespace camopt {
namespace disc_cam_study_test {

using camopt::testing::ReadFile;
using camopt::testing::RunCamopt;
using camopt::testing::SourcePath;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;
using nlohmann::json;

using camopt::testing::Example;
using studies::Node;
using studies::RunContext;
namespace disc_study = studies::disc_cam;

// The index of the grid angle closest to angle_deg.
size_t IndexAt(const std::vector<double>& cam_angle_deg, double angle_deg) {
  size_t best = 0;
  for (size_t i = 1; i < cam_angle_deg.size(); ++i)
    if (std::abs(cam_angle_deg[i] - angle_deg) < std::abs(cam_angle_deg[best] - angle_deg)) best = i;
  return best;
}

// Parse and Run, the C++ entry points of the kind.
struct Ran {
  disc_study::Study study;
  disc_study::Result result;
};
Ran ParseAndRun(const json& file) {
  const Node root(&file, "study.json", "");
  Ran r{disc_study::Parse(root), {}};
  RunContext ctx;
  ctx.quiet = true;
  r.result = disc_study::Run(r.study, ctx);
  return r;
}

TEST(DiscCamStudy, PaperExample) {
  const Ran ran = ParseAndRun(Example("disc_cam_translating.json"));
  const disc_study::Result& r = ran.result;
  // Paper §5: maximum radial dimension 63.525 mm.
  EXPECT_NEAR(r.max_radial_dimension_mm.value, 63.525, 5e-4);
  EXPECT_NEAR(r.min_radial_dimension_mm, 40.0, 1e-9);  // base circle
  EXPECT_FALSE(r.undercut);
  // On the base circle φ = −atan(e/L₀): the largest |φ| is not smaller than that.
  const double L0 = std::sqrt(50.0 * 50.0 - 144.0);
  EXPECT_LE(r.min_pressure_angle_deg.value, -std::atan(12.0 / L0) * 180 / kPi);
  EXPECT_GT(r.max_pressure_angle_deg.value, 0.0);
  ASSERT_TRUE(r.min_radius_of_curvature_mm.has_value());
  EXPECT_GT(r.min_radius_of_curvature_mm->value, 0.0);
  EXPECT_LE(r.min_radius_of_curvature_mm->value, 40.0);  // ≤ the base circle's
  // Worst case between the tolerances' sum (cos φ = 1, λ = 0 at best) and the sum over the
  // smallest cos φ; RMS below the worst case.
  const double wor = r.max_worst_case_error_um.value;
  const double phimax = std::max(std::abs(r.min_pressure_angle_deg.value),
                                 std::abs(r.max_pressure_angle_deg.value));
  EXPECT_GT(wor, 28.0);
  EXPECT_LT(wor, 28.0 / std::cos(phimax * kPi / 180) + 1e-9);
  EXPECT_LT(r.max_rms_error_um.value, wor);
  const double at = r.max_worst_case_error_um.cam_angle_deg;
  EXPECT_TRUE(at > 170.0 && at < 290.0) << "the return has the largest |φ|: " << at;
  // Closed form in the upper dwell (θ = 145°): λ = 0, cos φ = L/|C|,
  // ΔS_wor = (19 + 9) |C| / L with L = L₀ + 24.
  const size_t i = IndexAt(r.series.cam_angle_deg, 145.0);
  const double L = L0 + 24.0, C = std::sqrt(L * L + 144.0);
  EXPECT_NEAR(r.series.error_worst_case_um[i], 28.0 * C / L, 1e-7);
  EXPECT_NEAR(r.series.radial_dimension_mm[i], C - 10.0, 1e-7);
  EXPECT_NEAR(r.series.follower[i], 24.0, 1e-12);
  // Motion: cycloidal against dwells is C² at every joint; peak velocity Cv h/β = 2·24/(2π/3).
  for (const auto& j : r.joints) EXPECT_EQ(j.order, 2);
  EXPECT_NEAR(r.peak_velocity, 48.0 / (2 * kPi / 3), 1e-6);
  // Monte-Carlo: the linear model holds to well under 1% at the tolerance scale.
  const auto& mc = r.monte_carlo_rows;
  ASSERT_GE(mc.size(), 1u);
  EXPECT_EQ(mc[0].scale, 1.0);
  EXPECT_LT(mc[0].relative_difference, 1e-3);
  EXPECT_EQ(mc[0].within_worst_case_fraction, 1.0);
}

TEST(DiscCamStudy, PaperExampleThroughTheCli) {
  const auto dir = TempDir("disc-cam-translating");
  json study = Example("disc_cam_translating.json");
  study["analysis"]["monte_carlo"] = {{"samples", 10}, {"angle_steps", 90}, {"scales", {1}}};
  WriteFile(dir / "study.json", study.dump());
  const auto res = RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " +
                             (dir / "out").string());
  ASSERT_EQ(res.exit_code, 0) << res.stderr_text;
  const json r = json::parse(ReadFile(dir / "out" / "result.json"));
  EXPECT_EQ(r["study"], "disc_cam");
  EXPECT_EQ(r["motion"]["joints"][0]["continuity"], "C2");
  // The CLI writes what the C++ entry points give: result.json is WriteResult(Run(Parse)).
  const Ran ran = ParseAndRun(study);
  EXPECT_EQ(camopt::testing::WithoutRunStamp(r), studies::WriteResult(ran.result));
  for (const char* f : {"series.csv", "error.svg", "angles.svg", "svaj.svg", "profile.svg", "profile.dxf"})
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / f)) << f;
  // S-V-A-J stacked in one plot, per degree of cam; no speed given, so nothing over time.
  const std::string svaj = ReadFile(dir / "out" / "svaj.svg");
  for (const char* label : {"displacement [mm]", "velocity [mm/deg]", "acceleration [mm/deg²]", "jerk [mm/deg³]"})
    EXPECT_NE(svaj.find(label), std::string::npos) << label;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "svaj_time.svg"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "svaj_velocity.svg"));
  EXPECT_EQ(ReadFile(dir / "out" / "angles.svg").find("Fig."), std::string::npos);
  // The drawing's main dimensions (the study's base circle, roller and offset).
  const std::string profile = ReadFile(dir / "out" / "profile.svg");
  EXPECT_NE(profile.find("base circle diameter 80 mm; roller diameter 20 mm; offset 12 mm"), std::string::npos);
  EXPECT_NE(profile.find("profile radius from the cam centre"), std::string::npos);
  EXPECT_NE(ReadFile(dir / "out" / "profile.dxf").find("POLYLINE"), std::string::npos);
  // series.csv against the motion's closed form: the cycloidal rise of 24 mm over 120° ends at
  // 120°, where the upper dwell starts, and the largest velocity is Cv h/β = 2·24/(2π/3).
  const auto series = camopt::testing::ReadCsv(ReadFile(dir / "out" / "series.csv"));
  const std::vector<double>& deg = series.at("cam_angle_deg");
  const size_t at_120 = size_t(std::find_if(deg.begin(), deg.end(), [](double d) { return d >= 120.0 - 1e-9; }) -
                               deg.begin());
  ASSERT_LT(at_120, deg.size());
  EXPECT_NEAR(deg[at_120], 120.0, 1e-9);
  EXPECT_NEAR(series.at("follower_mm")[at_120], 24.0, 1e-9);
  const std::vector<double>& v = series.at("velocity_mm_per_rad");
  EXPECT_NEAR(*std::max_element(v.begin(), v.end()), 48.0 / (2 * kPi / 3), 1e-6);
}

TEST(DiscCamStudy, OscillatingExample) {
  json study = Example("disc_cam_oscillating.json");
  study["analysis"]["monte_carlo"] = {{"samples", 10}, {"angle_steps", 90}, {"scales", {1}}};
  const Ran ran = ParseAndRun(study);
  const disc_study::Result& r = ran.result;
  EXPECT_TRUE(r.oscillating);
  EXPECT_EQ(studies::WriteResult(r)["follower"], "oscillating_roller");
  EXPECT_NEAR(r.min_radial_dimension_mm, 40.0, 1e-9);
  // The error at the roller centre is l·Δξ: µm and arc seconds agree through l = 80 mm.
  ASSERT_TRUE(r.max_worst_case_error_arcsec.has_value());
  EXPECT_NEAR(r.max_worst_case_error_um.value,
              r.max_worst_case_error_arcsec->value / 3600 * kPi / 180 * 80e3, 1e-9);
  EXPECT_GT(r.max_worst_case_error_um.value, 19.0 + 9.0 + 5.0 - 1e-9 - 19.0 * 0.2);
  ASSERT_EQ(r.monte_carlo_rows.size(), 1u);
  EXPECT_LT(r.monte_carlo_rows[0].relative_difference, 1e-2);
  // Dwell at ξ₀ + 20°: S = 20° in the series.
  EXPECT_NEAR(r.series.follower[IndexAt(r.series.cam_angle_deg, 130.0)], 20.0, 1e-9);
}

// Lazy stages: "analysis.evaluate": ["profile"] needs no tolerances and computes neither the
// mechanical error nor the Monte-Carlo check (no error series, fields or plot), with the same
// profile as the full study; ["error"] adds the error but not the Monte-Carlo check.
TEST(DiscCamStudy, ProfileOnlySkipsTheErrorStages) {
  const Ran full = ParseAndRun(Example("disc_cam_translating.json"));
  ASSERT_TRUE(full.result.error_evaluated);
  ASSERT_EQ(full.result.monte_carlo, disc_study::Result::MonteCarlo::kDone);

  json file = Example("disc_cam_translating.json");
  file.erase("tolerances");
  file["analysis"]["evaluate"] = {"profile"};
  const Ran bare = ParseAndRun(file);
  EXPECT_FALSE(bare.result.error_evaluated);
  EXPECT_TRUE(bare.result.series.error_worst_case_um.empty());
  EXPECT_EQ(bare.result.monte_carlo, disc_study::Result::MonteCarlo::kOff);
  EXPECT_TRUE(bare.result.monte_carlo_rows.empty());
  EXPECT_EQ(bare.result.series.pressure_angle_deg, full.result.series.pressure_angle_deg);
  EXPECT_EQ(bare.result.max_radial_dimension_mm.value, full.result.max_radial_dimension_mm.value);
  const json j = studies::WriteResult(bare.result);
  EXPECT_FALSE(j.contains("worst_case_error_um"));
  EXPECT_FALSE(j.contains("monte_carlo"));
  EXPECT_EQ(j["evaluated"], json({"profile"}));

  const auto dir = TempDir("disc-cam-profile-only");
  WriteFile(dir / "study.json", file.dump());
  const auto res = RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " +
                             (dir / "out").string());
  ASSERT_EQ(res.exit_code, 0) << res.stderr_text;
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "profile.svg"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "error.svg"));
  EXPECT_EQ(ReadFile(dir / "out" / "series.csv").find("error_"), std::string::npos);

  file = Example("disc_cam_translating.json");
  file["analysis"]["evaluate"] = {"error"};
  const Ran error = ParseAndRun(file);
  EXPECT_TRUE(error.result.error_evaluated);
  EXPECT_EQ(error.result.monte_carlo, disc_study::Result::MonteCarlo::kOff);
  EXPECT_EQ(error.result.series.error_worst_case_um, full.result.series.error_worst_case_um);
}

TEST(DiscCamStudy, UndercutIsReportedNotHidden) {
  json study = Example("disc_cam_translating.json");
  study["base_circle_radius_mm"] = 10;
  study["follower"] = {{"type", "translating_roller"}, {"roller_radius_mm", 15}};
  study["motion"] = json::parse(R"([{"law": "cycloidal", "rise_mm": 24, "cam_angle_deg": 60},
      {"law": "cycloidal", "rise_mm": -24, "cam_angle_deg": 60},
      {"law": "dwell", "cam_angle_deg": 240}])");
  const Ran ran = ParseAndRun(study);
  const disc_study::Result& r = ran.result;
  EXPECT_TRUE(r.undercut);
  EXPECT_GE(r.undercut_cam_angle_deg.size(), 1u);
  ASSERT_TRUE(r.min_radius_of_curvature_mm.has_value());
  EXPECT_LT(r.min_radius_of_curvature_mm->value, 0.0);
  EXPECT_EQ(r.monte_carlo, disc_study::Result::MonteCarlo::kSkippedUndercut);
  EXPECT_TRUE(studies::WriteResult(r)["monte_carlo"].contains("skipped"));
}

// Limits and verdict (docs/disc_cam.md "Limits and verdict"). The paper's translating example
// with the default limits: on the rise (and dwells) the largest |φ| is on the base circle, where
// S' = 0 and φ = −atan(e/L₀) (eq. 3); on the return the cycloidal fall of 24 mm over 120° from
// θ = 170° gives φ = atan((S' − e)/L), recomputed here from the law's closed form on the study's
// grid: 30.596° > 30° (the default, Norton's ±30° for a translating roller follower) — the one
// limit the paper's design does not meet. The smallest convex profile radius 36.56 mm ≥ the roller
// radius 10 mm (the default margin: pitch-curve radius ≥ 2 × roller).
TEST(DiscCamStudy, DefaultLimitsGiveAVerdict) {
  json file = Example("disc_cam_translating.json");
  file["analysis"]["monte_carlo"] = false;
  const Ran ran = ParseAndRun(file);
  const disc_study::Result& r = ran.result;
  const double L0 = std::sqrt(50.0 * 50.0 - 144.0);
  EXPECT_NEAR(r.max_pressure_angle_rise_deg.value, std::atan(12.0 / L0) * 180 / kPi, 1e-9);
  double ret = 0.0, ret_at = 0.0;
  const double beta = 120.0 * kPi / 180;
  for (int i = 0; i < 3600; ++i) {
    const double deg = 0.1 * i;
    if (deg <= 170.0 || deg >= 290.0) continue;
    const double u = (deg - 170.0) * kPi / 180 / beta;
    const double S = 24.0 - 24.0 * (u - std::sin(2 * kPi * u) / (2 * kPi));
    const double dS = -24.0 / beta * (1.0 - std::cos(2 * kPi * u));
    const double phi = std::abs(std::atan((dS - 12.0) / (L0 + S))) * 180 / kPi;
    if (phi > ret) ret = phi, ret_at = deg;
  }
  ASSERT_TRUE(r.max_pressure_angle_return_deg.has_value());
  EXPECT_NEAR(r.max_pressure_angle_return_deg->value, ret, 1e-9);
  EXPECT_NEAR(r.max_pressure_angle_return_deg->cam_angle_deg, ret_at, 1e-9);
  EXPECT_NEAR(ret, 30.596, 1e-3);
  const json j = studies::WriteResult(r);
  EXPECT_EQ(j["pressure_angle_deg"]["limit"], 30.0);
  EXPECT_EQ(j["pressure_angle_deg"]["rise_ok"], true);
  EXPECT_EQ(j["pressure_angle_deg"]["return_ok"], false);
  EXPECT_EQ(j["radius_margin_limit_mm"], 10.0);
  EXPECT_EQ(j["radius_margin_ok"], true);
  EXPECT_EQ(j["limits_ok"], false);
  EXPECT_EQ(j["limits"]["defaults"], json({"pressure_angle_deg", "radius_margin_mm"}));
  // report.html: the banner counts the three limits; the CLI exits 0 as lcr_analysis does with a
  // limit exceeded (the verdict is in result.json and the report, not in the exit code).
  RunContext ctx;
  ctx.quiet = true;
  const std::string html = studies::RunStudy(file, ctx).files().at("report.html");
  EXPECT_NE(html.find("1 of 3 limits exceeded"), std::string::npos);
  const auto dir = TempDir("disc-cam-verdict");
  WriteFile(dir / "study.json", file.dump());
  const auto res = RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " + (dir / "out").string() +
                             " > " + (dir / "stdout.txt").string());
  EXPECT_EQ(res.exit_code, 0) << res.stderr_text;
  const std::string summary = ReadFile(dir / "stdout.txt");
  EXPECT_NE(summary.find("  verdict: 1 of 3 limits exceeded: largest pressure angle, return\n"), std::string::npos)
      << summary;
  EXPECT_NE(summary.find("largest pressure angle, return: 30.5965 deg (limit ≤ 30 deg: fail)"), std::string::npos)
      << summary;

  // Given limits replace the defaults: 31° passes the return; a margin of 37 mm fails 36.56 mm.
  file["limits"] = {{"pressure_angle_deg", 31}, {"radius_margin_mm", 37}};
  const Ran given = ParseAndRun(file);
  const json g = studies::WriteResult(given.result);
  EXPECT_EQ(g["pressure_angle_deg"]["return_ok"], true);
  EXPECT_EQ(g["radius_margin_ok"], false);
  EXPECT_NEAR(g["min_radius_of_curvature_mm"].get<double>(), 36.558, 1e-3);
  EXPECT_EQ(g["limits"]["defaults"], json::array());
  EXPECT_EQ(g["limits_ok"], false);
  file["limits"] = {{"radius_margin_mm", 36.5}};
  const json h = studies::WriteResult(ParseAndRun(file).result);
  EXPECT_EQ(h["radius_margin_ok"], true);
  EXPECT_EQ(h["limits"]["defaults"], json({"pressure_angle_deg"}));
}

// An oscillating follower's default pressure-angle limit is 45° (Rothbart; docs/disc_cam.md):
// the example's 26.3° passes. An undercut profile fails the radius margin whatever it is.
TEST(DiscCamStudy, OscillatingDefaultAndUndercutVerdict) {
  json osc = Example("disc_cam_oscillating.json");
  osc["analysis"]["monte_carlo"] = false;
  const Ran o = ParseAndRun(osc);
  const json jo = studies::WriteResult(o.result);
  EXPECT_EQ(jo["pressure_angle_deg"]["limit"], 45.0);
  EXPECT_NEAR(jo["pressure_angle_deg"]["max_return"].get<double>(), 26.311, 1e-3);
  EXPECT_EQ(jo["limits_ok"], true);

  json study = Example("disc_cam_translating.json");
  study["base_circle_radius_mm"] = 10;
  study["follower"] = {{"type", "translating_roller"}, {"roller_radius_mm", 15}};
  study["limits"] = {{"radius_margin_mm", 0}, {"pressure_angle_deg", 88}};
  study["analysis"]["monte_carlo"] = false;
  study["motion"] = json::parse(R"([{"law": "cycloidal", "rise_mm": 24, "cam_angle_deg": 60},
      {"law": "cycloidal", "rise_mm": -24, "cam_angle_deg": 60},
      {"law": "dwell", "cam_angle_deg": 240}])");
  const Ran u = ParseAndRun(study);
  const json ju = studies::WriteResult(u.result);
  EXPECT_EQ(ju["undercut"], true);
  EXPECT_EQ(ju["radius_margin_ok"], false);
  EXPECT_EQ(ju["limits_ok"], false);
}

struct BadCase {
  const char* name;
  const char* example;
  const char* patch;  // a JSON merge patch applied to the example
  const char* path;   // the JSON path the message must name
  const char* words;  // and a phrase it must contain
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

class DiscCamBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(DiscCamBadInput, ExitCode2AndTheJsonPath) {
  const BadCase& c = GetParam();
  json study = Example(c.example);
  study.merge_patch(json::parse(c.patch));
  camopt::testing::ExpectStudyRejected(study, std::string("disc-cam-") + c.name, c.path, c.words);
}

const char* kT = "disc_cam_translating.json";
const char* kO = "disc_cam_oscillating.json";

INSTANTIATE_TEST_SUITE_P(
    Cases, DiscCamBadInput,
    ::testing::Values(
        BadCase{"sum", kT, R"({"motion": [{"law": "cycloidal", "rise_mm": 24, "cam_angle_deg": 120},
            {"law": "dwell", "cam_angle_deg": 50}, {"law": "cycloidal", "rise_mm": -24, "cam_angle_deg": 120},
            {"law": "dwell", "cam_angle_deg": 60}]})", "/motion", "sum to 350"},
        BadCase{"noreturn", kT, R"({"motion": [{"law": "cycloidal", "rise_mm": 24, "cam_angle_deg": 120},
            {"law": "dwell", "cam_angle_deg": 50}, {"law": "cycloidal", "rise_mm": -20, "cam_angle_deg": 120},
            {"law": "dwell", "cam_angle_deg": 70}]})", "/motion", "rises sum to 4 mm"},
        BadCase{"base", kT, R"({"base_circle_radius_mm": -40})", "/base_circle_radius_mm", "> 0"},
        BadCase{"roller", kT, R"({"follower": {"roller_radius_mm": -10}})", "/follower/roller_radius_mm", "> 0"},
        BadCase{"offset", kT, R"({"follower": {"offset_mm": 55}})", "/follower/offset_mm", "smaller than"},
        BadCase{"law", kT, R"({"motion": [{"law": "parabolic", "rise_mm": 24, "cam_angle_deg": 360}]})",
                "/motion/0/law", "cycloidal"},
        BadCase{"dwellrise", kT, R"({"motion": [{"law": "cycloidal", "rise_mm": 24, "cam_angle_deg": 120},
            {"law": "dwell", "rise_mm": 3, "cam_angle_deg": 50}, {"law": "cycloidal", "rise_mm": -24, "cam_angle_deg": 120},
            {"law": "dwell", "cam_angle_deg": 70}]})", "/motion/1/rise_mm", "dwell has no rise"},
        BadCase{"angle", kT, R"({"motion": [{"law": "cycloidal", "rise_mm": 24, "cam_angle_deg": -120},
            {"law": "cycloidal", "rise_mm": -24, "cam_angle_deg": 480}]})", "/motion/0/cam_angle_deg", "> 0"},
        BadCase{"inside", kT, R"({"motion": [{"law": "cycloidal", "rise_mm": -10, "cam_angle_deg": 180},
            {"law": "cycloidal", "rise_mm": 10, "cam_angle_deg": 180}]})", "/motion", "inside the base circle"},
        BadCase{"jam", kT, R"({"motion": [{"law": "cycloidal", "rise_mm": 80, "cam_angle_deg": 1},
            {"law": "cycloidal", "rise_mm": -80, "cam_angle_deg": 359}]})", "/motion", "pressure angle"},
        BadCase{"tolerance", kT, R"({"tolerances": {"profile_radial_um": -19}})",
                "/tolerances/profile_radial_um", ">= 0"},
        BadCase{"typo", kT, R"({"tolerances": {"profile_radial_mm": 0.019}})",
                "/tolerances/profile_radial_mm", "unknown field"},
        BadCase{"follower", kT, R"({"follower": {"type": "flat_faced"}})", "/follower/type", "translating_roller"},
        BadCase{"arm", kO, R"({"follower": {"arm_length_mm": null}})", "/follower/arm_length_mm", "missing"},
        BadCase{"reach", kO, R"({"follower": {"arm_length_mm": 20}})", "/follower/arm_length_mm", "cannot reach"},
        BadCase{"riseunit", kO, R"({"motion": [{"law": "modified_sine", "rise_mm": 20, "cam_angle_deg": 180},
            {"law": "modified_sine", "rise_deg": -20, "cam_angle_deg": 180}]})", "/motion/0/rise_mm", "rise_deg"},
        BadCase{"noreturndeg", kO, R"({"motion": [{"law": "modified_sine", "rise_deg": 20, "cam_angle_deg": 180},
            {"law": "modified_sine", "rise_deg": -15, "cam_angle_deg": 180}]})", "/motion", "rises sum to 5 deg"},
        BadCase{"steps", kT, R"({"analysis": {"angle_steps": 10}})", "/analysis/angle_steps", ">= 36"},
        BadCase{"stage", kT, R"({"analysis": {"evaluate": ["stress"]}})", "/analysis/evaluate/0",
                "\"monte_carlo\""},
        BadCase{"limit_pa", kT, R"({"limits": {"pressure_angle_deg": 89}})", "/limits/pressure_angle_deg",
                "jam limit"},
        BadCase{"limit_margin", kT, R"({"limits": {"radius_margin_mm": -1}})", "/limits/radius_margin_mm", ">= 0"},
        BadCase{"limit_typo", kT, R"({"limits": {"pressure_angle": 30}})", "/limits/pressure_angle", "unknown field"},
        BadCase{"stage_input", kT, R"({"tolerances": null, "analysis": {"evaluate": ["error"]}})",
                "/tolerances", "missing"}),
    [](const ::testing::TestParamInfo<BadCase>& p) { return std::string(p.param.name); });

// A pressure angle of 88° is feasible (the jam limit is 89°) but gets a line in the result's
// warnings above model/disc_cam/check.h kHighPressureAngle (45°); the paper example (30.6°) none.
TEST(DiscCamStudy, HighPressureAngleIsAWarning) {
  const auto warnings_of = [](const json& study) {
    RunContext ctx;
    ctx.quiet = true;
    const studies::Outputs out = studies::RunStudy(study, ctx);
    return json::parse(out.files().at("result.json"))["warnings"];
  };
  json steep = Example("disc_cam_translating.json");
  steep.erase("tolerances");
  steep["analysis"].erase("monte_carlo");
  steep["motion"] = json::parse(R"([{"law": "cycloidal", "rise_mm": 24, "cam_angle_deg": 1.5},
      {"law": "dwell", "cam_angle_deg": 168.5}, {"law": "cycloidal", "rise_mm": -24, "cam_angle_deg": 120},
      {"law": "dwell", "cam_angle_deg": 70}])");
  const json w = warnings_of(steep);
  ASSERT_EQ(w.size(), 1u) << w.dump();
  EXPECT_NE(w[0].get<std::string>().find("the pressure angle reaches 88.1"), std::string::npos) << w.dump();
  EXPECT_NE(w[0].get<std::string>().find("45 deg warning limit"), std::string::npos) << w.dump();
  json plain = Example("disc_cam_translating.json");
  plain["analysis"].erase("monte_carlo");
  EXPECT_TRUE(warnings_of(plain).empty());
}

// Polynomial segments in a study file (docs/disc_cam.md "Polynomial segments"): the example's
// dwell → constant velocity → dwell rise. Between 60° and 140° the follower moves at exactly
// 0.25 mm/deg: S(100°) = 10 + 0.25 × 40 = 20 mm, S' = 0.25 × 180/π mm/rad, S'' = 0; the first blend
// is P(u) = 40u³ − 45u⁴ + 15u⁵ (solved by hand from S(1) = 10, S'(1)β = 15, S''(1) = 0), so
// S(30°) = 5 − 2.8125 + 0.46875 = 2.65625 mm; every joint is C² (the cycloid meets zero velocity
// and acceleration at 360°).
TEST(DiscCamStudy, PolynomialSegmentsWriteDwellConstantVelocityDwell) {
  json file = Example("disc_cam_dynamics.json");
  const Ran ran = ParseAndRun(file);
  const auto& t = ran.result.series;
  const size_t i100 = IndexAt(t.cam_angle_deg, 100.0), i30 = IndexAt(t.cam_angle_deg, 30.0);
  EXPECT_NEAR(t.follower[i100], 20.0, 1e-12);
  EXPECT_NEAR(t.velocity_per_rad[i100], 0.25 * 180 / kPi, 1e-12);
  EXPECT_NEAR(t.acceleration_per_rad2[i100], 0.0, 1e-10);
  EXPECT_NEAR(t.follower[i30], 2.65625, 1e-12);
  for (const auto& j : ran.result.joints) EXPECT_GE(j.order, 2) << "joint after segment " << j.segment;
}

// A B-spline segment in a study file (studies/examples/disc_cam_bspline.json): the rise starts
// and ends at its first and last control points with zero velocity and acceleration (three repeated
// at each end), so the joints with the dwells are C² at least; halfway it is at 10 mm exactly, since
// the control values 0,0,0,5,15,20,20,20 are antisymmetric about 10 and the knots symmetric about
// u = 1/2.
TEST(DiscCamStudy, BSplineSegmentsInAStudy) {
  const Ran ran = ParseAndRun(Example("disc_cam_bspline.json"));
  const auto& t = ran.result.series;
  EXPECT_NEAR(t.follower[IndexAt(t.cam_angle_deg, 0.0)], 0.0, 1e-12);
  EXPECT_NEAR(t.follower[IndexAt(t.cam_angle_deg, 120.0)], 20.0, 1e-12);
  EXPECT_NEAR(t.velocity_per_rad[IndexAt(t.cam_angle_deg, 120.0)], 0.0, 1e-9);
  for (const auto& j : ran.result.joints) EXPECT_GE(j.order, 2) << "joint after segment " << j.segment;
  EXPECT_NEAR(t.follower[IndexAt(t.cam_angle_deg, 60.0)], 10.0, 1e-12);
  // A first point that does not continue the program, a degree above the points, a rise given.
  json s = Example("disc_cam_bspline.json");
  s["motion"][0]["control_points_mm"][0] = 1;
  camopt::testing::ExpectStudyRejected(s, "bspline-start", "/motion/0/control_points_mm/0",
                                       "the cycle starts on the base circle with position 0 mm, this control point gives 1 mm");
  s = Example("disc_cam_bspline.json");
  s["motion"][0]["control_points_mm"] = {0, 0, 0, 10, 20, 20};
  s["motion"][0]["degree"] = 6;
  camopt::testing::ExpectStudyRejected(s, "bspline-degree", "/motion/0/degree", "needs at least 7 control points, found 6");
  s = Example("disc_cam_bspline.json");
  s["motion"][0]["rise_mm"] = 20;
  camopt::testing::ExpectStudyRejected(s, "bspline-rise", "/motion/0/rise_mm", "last control point minus its first");
  // Another kind with a motion program (globoidal_cam) does not take B-spline segments.
  json g = Example("globoidal_cam_paper.json");
  g["motion"][0]["law"] = "bspline";
  camopt::testing::ExpectStudyRejected(g, "globoidal-bspline", "/motion/0/law", "a motion law (dwell");
}

// A polynomial boundary value that does not continue the program is refused with its JSON path
// and both values; so are a rise on a polynomial, a jerk without acceleration, a missing velocity.
TEST(DiscCamStudy, PolynomialDiscontinuitiesAreRejectedWithBothValues) {
  struct Case {
    const char* tag;
    const char* pointer;  // set to value (null: removed)
    json value;
    const char* words;
  };
  const Case cases[] = {
      {"poly-velocity", "/motion/1/boundary/start/velocity_mm_per_deg", 0.3,
       "segment 0 ends with velocity 0.25 mm/deg, this boundary gives 0.3 mm/deg"},
      {"poly-position", "/motion/1/boundary/start/position_mm", 11, "segment 0 ends with position 10 mm, this boundary gives 11 mm"},
      {"poly-first", "/motion/0/boundary/start/position_mm", 1, "the cycle starts on the base circle with position 0 mm"},
      {"poly-accel", "/motion/0/boundary/start/acceleration_mm_per_deg2", 0.01, "segment 4 ends with acceleration"},
      {"poly-end", "/motion/2/boundary/end/velocity_mm_per_deg", 0.1, "segment 3 starts with velocity 0 mm/deg"},
      {"poly-rise", "/motion/0/rise_mm", 10, "boundary.end minus boundary.start"},
      {"poly-jerk", "/motion/0/boundary/end/jerk_mm_per_deg3", 0, ""},
      {"poly-missing", "/motion/0/boundary/end/velocity_mm_per_deg", nullptr, "missing"},
      {"poly-unit", "/motion/0/boundary/end/velocity_deg_per_deg", 0, "unknown field"}};
  for (const Case& c : cases) {
    json s = Example("disc_cam_dynamics.json");
    const json::json_pointer ptr(c.pointer);
    if (c.value.is_null()) {
      s[ptr.parent_pointer()].erase(ptr.back());
    } else {
      s[ptr] = c.value;
    }
    std::string words = c.words;
    if (std::string(c.tag) == "poly-jerk") {  // a jerk without the acceleration at that end
      s[json::json_pointer("/motion/0/boundary/end")].erase("acceleration_mm_per_deg2");
      words = "needs the acceleration";
    }
    camopt::testing::ExpectStudyRejected(s, std::string("disc-cam-") + c.tag, c.pointer, words);
  }
  // Another kind with a motion program (globoidal_cam) does not take polynomial segments.
  json g = Example("globoidal_cam_paper.json");
  g["motion"][0]["law"] = "polynomial";
  camopt::testing::ExpectStudyRejected(g, "globoidal-polynomial", "/motion/0/law", "a motion law (dwell");
}

// The jump study (studies/examples/disc_cam_jump.json): the cam of disc_cam_dynamics.json with a
// 50 N/mm follower train and 5 % damping at 250 rpm. Reference values from an independent fixed-step
// RK4 integration of the same one-DOF model (dt = 5 µs, S and S' interpolated from series.csv,
// written apart from model/disc_cam/follower_dynamics.cc): smallest axial force 5.673 N, residual
// vibration over the 200–240° dwell 0.7752 mm, contact held at 293.9 rpm and lost at 294.5 rpm. The
// kinetostatic jump speed by hand over the 0.1° grid: min (k S + F₀ + W)/(−m S'') → 356.43 rpm.
TEST(DiscCamStudy, JumpStudyAgainstAnIndependentIntegration) {
  const Ran ran = ParseAndRun(Example("disc_cam_jump.json"));
  const json d = studies::WriteResult(ran.result)["dynamics"];
  EXPECT_NEAR(d["jump_speed_rpm"].get<double>(), 356.43, 0.01);
  const double jump = d["dynamic_jump_speed_rpm"].get<double>();
  EXPECT_GT(jump, 293.9);
  EXPECT_LT(jump, 294.5);
  EXPECT_LT(jump, d["jump_speed_rpm"].get<double>());  // the flexible follower leaves the cam earlier
  const json b = d["dynamic_jump_search"]["bracket_rpm"];
  EXPECT_LE(b[1].get<double>() - b[0].get<double>(), 1e-3 * jump);
  EXPECT_EQ(b[1].get<double>(), jump);
  const json r = d["response"];
  EXPECT_NEAR(r["min_axial_force_N"].get<double>(), 5.673, 0.005);
  EXPECT_NEAR(r["residual_vibration_mm"].get<double>(), 0.7752, 0.001);
  EXPECT_EQ(r["separates"], false);
  EXPECT_NEAR(r["natural_frequency_Hz"].get<double>(), std::sqrt(51.5e3 / 1.2) / (2 * kPi), 1e-9);
  // At 300 rpm the response itself separates (RK4: smallest force −0.94 N before contact is lost),
  // the loads' verdict fails, and the jump speed found is still the first separation below it.
  json fast = Example("disc_cam_jump.json");
  fast["dynamics"]["speed_rpm"] = 300;
  const Ran f = ParseAndRun(fast);
  const json fd = studies::WriteResult(f.result);
  EXPECT_EQ(fd["dynamics"]["response"]["separates"], true);
  EXPECT_EQ(fd["dynamics"]["response"]["min_axial_force_N"], 0.0);
  EXPECT_NEAR(fd["dynamics"]["dynamic_jump_speed_rpm"].get<double>(), jump, 1e-9);
  EXPECT_EQ(fd["limits_ok"], false);
}

}  // namespace disc_cam_study_test
}  // namespace camopt
