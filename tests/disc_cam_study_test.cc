// The disc_cam study through the CLI: the paper's example and the oscillating example end to end,
// and every kind of bad input rejected with exit code 2 and a message naming the JSON path.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/common/scalar.h"
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

// The CSV row whose first column (cam angle) is closest to angle_deg, by column name.
std::map<std::string, double> CsvRowAt(const std::string& csv, double angle_deg) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  {
    std::istringstream h(line);
    std::string n;
    while (std::getline(h, n, ',')) names.push_back(n);
  }
  std::map<std::string, double> best;
  double best_d = 1e9;
  while (std::getline(in, line)) {
    std::istringstream r(line);
    std::string v;
    std::map<std::string, double> row;
    for (size_t i = 0; i < names.size() && std::getline(r, v, ','); ++i) row[names[i]] = std::stod(v);
    if (std::abs(row["cam_angle_deg"] - angle_deg) < best_d)
      best_d = std::abs(row["cam_angle_deg"] - angle_deg), best = row;
  }
  return best;
}

TEST(DiscCamStudy, PaperExampleThroughTheCli) {
  const auto dir = TempDir("disc-cam-translating");
  const auto res = RunCamopt("run " + SourcePath("studies/examples/disc_cam_translating.json") +
                             " --quiet --out " + dir.string());
  ASSERT_EQ(res.exit_code, 0) << res.stderr_text;
  const json r = json::parse(ReadFile(dir / "result.json"));
  // Paper §5: maximum radial dimension 63.525 mm.
  EXPECT_NEAR(r["max_radial_dimension_mm"].get<double>(), 63.525, 5e-4);
  EXPECT_NEAR(r["min_radial_dimension_mm"].get<double>(), 40.0, 1e-9);  // base circle
  EXPECT_FALSE(r["undercut"].get<bool>());
  // On the base circle φ = −atan(e/L₀): the largest |φ| is not smaller than that.
  const double L0 = std::sqrt(50.0 * 50.0 - 144.0);
  EXPECT_LE(r["pressure_angle_deg"]["min"].get<double>(), -std::atan(12.0 / L0) * 180 / kPi);
  EXPECT_GT(r["pressure_angle_deg"]["max"].get<double>(), 0.0);
  EXPECT_GT(r["min_radius_of_curvature_mm"].get<double>(), 0.0);
  EXPECT_LE(r["min_radius_of_curvature_mm"].get<double>(), 40.0);  // ≤ the base circle's
  // Worst case between the tolerances' sum (cos φ = 1, λ = 0 at best) and the sum over the
  // smallest cos φ; RMS below the worst case.
  const double wor = r["worst_case_error_um"]["max"].get<double>();
  const double phimax = std::max(std::abs(r["pressure_angle_deg"]["min"].get<double>()),
                                 std::abs(r["pressure_angle_deg"]["max"].get<double>()));
  EXPECT_GT(wor, 28.0);
  EXPECT_LT(wor, 28.0 / std::cos(phimax * kPi / 180) + 1e-9);
  EXPECT_LT(r["rms_error_um"]["max"].get<double>(), wor);
  const double at = r["worst_case_error_um"]["at_cam_angle_deg"].get<double>();
  EXPECT_TRUE(at > 170.0 && at < 290.0) << "the return has the largest |φ|: " << at;
  // Closed form in the upper dwell (θ = 145°): λ = 0, cos φ = L/|C|,
  // ΔS_wor = (19 + 9) |C| / L with L = L₀ + 24.
  const auto row = CsvRowAt(ReadFile(dir / "series.csv"), 145.0);
  const double L = L0 + 24.0, C = std::sqrt(L * L + 144.0);
  EXPECT_NEAR(row.at("error_worst_case_um"), 28.0 * C / L, 1e-7);  // CSV: 10 digits
  EXPECT_NEAR(row.at("radial_dimension_mm"), C - 10.0, 1e-7);
  EXPECT_NEAR(row.at("follower_mm"), 24.0, 1e-12);
  // Motion: cycloidal against dwells is C² at every joint; peak velocity Cv h/β = 2·24/(2π/3).
  for (const auto& j : r["motion"]["joints"]) EXPECT_EQ(j["continuity"], "C2");
  EXPECT_NEAR(r["motion"]["peak_velocity_mm_per_rad"].get<double>(), 48.0 / (2 * kPi / 3), 1e-6);
  // Monte-Carlo: the linear model holds to well under 1% at the tolerance scale.
  const json& mc = r["monte_carlo"]["scales"];
  ASSERT_GE(mc.size(), 1u);
  EXPECT_EQ(mc[0]["scale"].get<double>(), 1.0);
  EXPECT_LT(mc[0]["relative_difference"].get<double>(), 1e-3);
  EXPECT_EQ(mc[0]["within_worst_case_fraction"].get<double>(), 1.0);
  for (const char* f : {"series.csv", "error.svg", "angles.svg", "svaj_displacement.svg",
                        "svaj_velocity.svg", "svaj_acceleration.svg", "svaj_jerk.svg",
                        "profile.svg", "profile.dxf"})
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  EXPECT_NE(ReadFile(dir / "profile.dxf").find("POLYLINE"), std::string::npos);
}

TEST(DiscCamStudy, OscillatingExampleThroughTheCli) {
  const auto dir = TempDir("disc-cam-oscillating");
  json study = Example("disc_cam_oscillating.json");
  study["analysis"]["monte_carlo"] = {{"samples", 10}, {"angle_steps", 90}, {"scales", {1}}};
  WriteFile(dir / "study.json", study.dump());
  const auto res = RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " +
                             (dir / "out").string());
  ASSERT_EQ(res.exit_code, 0) << res.stderr_text;
  const json r = json::parse(ReadFile(dir / "out" / "result.json"));
  EXPECT_EQ(r["follower"], "oscillating_roller");
  EXPECT_NEAR(r["min_radial_dimension_mm"].get<double>(), 40.0, 1e-9);
  // The error at the roller centre is l·Δξ: µm and arc seconds agree through l = 80 mm.
  EXPECT_NEAR(r["worst_case_error_um"]["max"].get<double>(),
              r["worst_case_error_arcsec"]["max"].get<double>() / 3600 * kPi / 180 * 80e3, 1e-9);
  EXPECT_GT(r["worst_case_error_um"]["max"].get<double>(), 19.0 + 9.0 + 5.0 - 1e-9 - 19.0 * 0.2);
  EXPECT_LT(r["monte_carlo"]["scales"][0]["relative_difference"].get<double>(), 1e-2);
  // Dwell at ξ₀ + 20°: S = 20° in the CSV.
  const auto row = CsvRowAt(ReadFile(dir / "out" / "series.csv"), 130.0);
  EXPECT_NEAR(row.at("follower_deg"), 20.0, 1e-9);
}

TEST(DiscCamStudy, UndercutIsReportedNotHidden) {
  const auto dir = TempDir("disc-cam-undercut");
  json study = Example("disc_cam_translating.json");
  study["base_circle_radius_mm"] = 10;
  study["follower"] = {{"type", "translating_roller"}, {"roller_radius_mm", 15}};
  study["motion"] = json::parse(R"([{"law": "cycloidal", "rise_mm": 24, "cam_angle_deg": 60},
      {"law": "cycloidal", "rise_mm": -24, "cam_angle_deg": 60},
      {"law": "dwell", "cam_angle_deg": 240}])");
  WriteFile(dir / "study.json", study.dump());
  const auto res = RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " +
                             (dir / "out").string());
  ASSERT_EQ(res.exit_code, 0) << res.stderr_text;
  const json r = json::parse(ReadFile(dir / "out" / "result.json"));
  EXPECT_TRUE(r["undercut"].get<bool>());
  EXPECT_GE(r["undercut_cam_angle_deg"].size(), 1u);
  EXPECT_LT(r["min_radius_of_curvature_mm"].get<double>(), 0.0);
  EXPECT_TRUE(r["monte_carlo"].contains("skipped"));
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
        BadCase{"steps", kT, R"({"analysis": {"angle_steps": 10}})", "/analysis/angle_steps", ">= 36"}),
    [](const ::testing::TestParamInfo<BadCase>& p) { return std::string(p.param.name); });

}  // namespace
}  // namespace camopt
