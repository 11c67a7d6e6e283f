// The lcr_analysis study: numbers through the C++ entry points (Parse, Run, WriteResult, Write), and
// through the CLI the exit codes, messages and files written.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/lcr_analysis_study.h"
#include "tests/test_util.h"

namespace camopt {
namespace lcr_study_test {

namespace fs = std::filesystem;
using camopt::testing::ReadFile;
using camopt::testing::RunCamopt;
using camopt::testing::SourcePath;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;

nlohmann::json LcrIIStudy() {
  return nlohmann::json::parse(ReadFile(SourcePath("studies/examples/lcr_ii.json")));
}

// The C++ entry points: Parse then Run on a study held in memory.
studies::lcr_analysis::Result RunAnalysis(const nlohmann::json& study) {
  const studies::Node root(&study, "lcr.json", "");
  return studies::lcr_analysis::Run(studies::lcr_analysis::Parse(root), {"lcr.json", true});
}

TEST(LcrStudy, ExampleNumbers) {
  nlohmann::json study = LcrIIStudy();
  study["analysis"]["angle_steps"] = 720;
  const studies::lcr_analysis::Result res = RunAnalysis(study);
  EXPECT_DOUBLE_EQ(res.speed_ratio, -90.0);
  for (const auto* cam : {&res.input_cam, &res.output_cam}) EXPECT_GE(cam->undercut_margin_mm, 0.0);
  for (double eta : {res.efficiency_mean, res.efficiency_min, res.efficiency_max}) {
    EXPECT_GT(eta, 0.0);
    EXPECT_LT(eta, 1.0);
  }
  EXPECT_NEAR(res.fixed_turret_torque_Nm, 80.0 * 14 * 13 / (15.0 * 12), 1e-9);
  EXPECT_EQ(res.series.theta_rad.size(), 720u);
}

// The CLI: exit code, no progress line with --quiet, result.json fields, every file written.
TEST(LcrStudy, ExampleWritesEveryOutputWithTheRequiredFields) {
  const fs::path dir = TempDir("lcr-study");
  nlohmann::json study = LcrIIStudy();
  study["analysis"]["angle_steps"] = 720;
  // A cutter other than the roller: the DXF has a CUTTER_PATH layer only then.
  study["reducer"]["input"]["cutter_diameter_mm"] = 10;
  WriteFile(dir / "s.json", study.dump());
  const auto r = RunCamopt("run " + (dir / "s.json").string() + " --out " + (dir / "out").string() + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(r.stderr_text, "");  // --quiet: no progress line
  const auto res = nlohmann::json::parse(ReadFile(dir / "out/result.json"));
  EXPECT_EQ(res["study"], "lcr_analysis");
  EXPECT_EQ(res["name"], "LCR II");
  for (const char* cam : {"input_cam", "output_cam"}) {
    for (const char* f : {"actuating_rollers_max", "actuating_rollers_min", "max_roller_force_N",
                          "max_contact_stress_MPa", "min_pitch_curve_radius_mm", "undercut_margin_mm"})
      EXPECT_TRUE(res[cam][f].is_number()) << cam << "/" << f;
    EXPECT_EQ(res[cam]["undercut"], false);
  }
  EXPECT_TRUE(res["input_torque_Nm"]["mean"].is_number());
  EXPECT_TRUE(res["input_torque_Nm"]["max"].is_number());
  // The CLI writes what the C++ entry points give: result.json is WriteResult(Run(Parse)).
  const studies::Node root(&study, "lcr.json", "");
  const studies::lcr_analysis::Study st = studies::lcr_analysis::Parse(root);
  EXPECT_EQ(camopt::testing::WithoutRunStamp(res), studies::WriteResult(studies::lcr_analysis::Run(st, {"lcr.json", true})));
  for (const char* f : {"series.csv", "forces.svg", "contact_stress.svg", "efficiency.svg", "input_cam.dxf",
                        "output_cam.dxf", "input_assembly.svg", "output_assembly.svg"})
    EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
  const std::string csv = ReadFile(dir / "out/series.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 721);
  EXPECT_EQ(csv.find("nan"), std::string::npos);
  const std::string dxf = ReadFile(dir / "out/input_cam.dxf");
  for (const char* layer : {"CAM_PROFILE", "PITCH_CURVE", "CUTTER_PATH"}) EXPECT_NE(dxf.find(layer), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "out/.camopt-staging"));
}

TEST(LcrStudy, ProfileOnlyEvaluatesNoForces) {
  nlohmann::json study = LcrIIStudy();
  study["analysis"]["evaluate"] = {"profile", "undercut"};
  study["reducer"]["input"]["cutter_diameter_mm"] = 10;
  const studies::Node root(&study, "lcr.json", "");
  const studies::lcr_analysis::Study st = studies::lcr_analysis::Parse(root);
  const studies::lcr_analysis::Result res = studies::lcr_analysis::Run(st, {"lcr.json", true});
  const nlohmann::json j = studies::WriteResult(res);
  EXPECT_FALSE(j["input_cam"].contains("max_roller_force_N"));
  EXPECT_FALSE(j.contains("efficiency"));
  EXPECT_TRUE(res.series.theta_rad.empty());
  studies::Outputs out;
  studies::lcr_analysis::Write(st, res, out);
  EXPECT_FALSE(out.files().count("series.csv"));
  EXPECT_TRUE(out.files().count("input_cam.dxf"));
  EXPECT_DOUBLE_EQ(res.input_cam.cutter_diameter_mm, 10.0);
  EXPECT_NEAR(res.input_cam.min_cutter_path_radius_mm, res.input_cam.min_pitch_curve_radius_mm - 1.0, 1e-12);
}

TEST(LcrStudy, ZeroTorqueAndUndercutAreReportedNotCrashed) {
  nlohmann::json study = LcrIIStudy();
  study["analysis"]["angle_steps"] = 360;
  study["load"]["output_torque_Nm"] = 0;
  studies::lcr_analysis::Result res = RunAnalysis(study);
  EXPECT_EQ(res.input_cam.max_roller_force_N, 0.0);
  EXPECT_FALSE(res.notes.empty());

  // A roller larger than the smallest convex pitch radius (9.05 mm on the input cam) undercuts.
  study = LcrIIStudy();
  study["analysis"]["angle_steps"] = 360;
  study["reducer"]["eccentricity_mm"] = 2.7;
  res = RunAnalysis(study);
  EXPECT_TRUE(res.any_undercut);
  EXPECT_LT(res.input_cam.undercut_margin_mm, 0.0);
  EXPECT_FALSE(res.notes.empty());
}

struct BadCase {
  std::string name, patch_path, patch_value, message;  // patch_value "REMOVE" deletes the field
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

class LcrStudyBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(LcrStudyBadInput, OneClearLineAndExitCode2) {
  const BadCase& c = GetParam();
  nlohmann::json study = LcrIIStudy();
  const nlohmann::json::json_pointer ptr(c.patch_path);
  if (c.patch_value == "REMOVE") {
    study[ptr.parent_pointer()].erase(ptr.back());
  } else {
    study[ptr] = nlohmann::json::parse(c.patch_value);
  }
  // The message's JSON path is the one in c.message (before its first ": ").
  camopt::testing::ExpectStudyRejected(study, "lcr-" + c.name, c.message.substr(0, c.message.find(": ")),
                                       c.message);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, LcrStudyBadInput,
    ::testing::Values(
        BadCase{"missing", "/reducer/eccentricity_mm", "REMOVE", "/reducer/eccentricity_mm: missing required field"},
        BadCase{"type", "/reducer/input/lobes", "\"twelve\"", "/reducer/input/lobes: expected a whole number >= 1, found a string \"twelve\""},
        BadCase{"negative", "/reducer/output/turret_radius_mm", "-42", "/reducer/output/turret_radius_mm: expected a number > 0, found -42"},
        BadCase{"overlap", "/reducer/input/roller_diameter_mm", "18", "/reducer/input/roller_diameter_mm: rollers overlap"},
        BadCase{"lobes", "/reducer/output/lobes", "15", "/reducer/output/rollers: expected more rollers than lobes (15)"},
        BadCase{"kind", "/study", "\"lcr_analysys\"", "/study: expected a known study kind"},
        BadCase{"steps", "/analysis/angle_steps", "0", "/analysis/angle_steps: expected a whole number >= 12"},
        BadCase{"poisson", "/material/poisson_ratio", "0.7", "/material/poisson_ratio: expected a number in [0, 0.4999]"},
        BadCase{"cutter", "/reducer/input/cutter_diameter_mm", "14", "/reducer/input/cutter_diameter_mm: expected a cutter diameter <= the roller diameter"},
        BadCase{"loop", "/reducer/eccentricity_mm", "3", "/reducer/input/turret_radius_mm: the pitch point"},
        BadCase{"typo", "/load/friction_coeficient", "0.05", "/load/friction_coeficient: unknown field (known: cam_weight_N, friction_coefficient, input_speed_rpm, output_torque_Nm)"},
        BadCase{"evaluate", "/analysis/evaluate", "[\"forcez\"]", "/analysis/evaluate/0: expected one of profile"}),
    [](const auto& p) { return p.param.name; });

}  // namespace lcr_study_test
}  // namespace camopt
