// The globoidal_cam study: the paper's example through the C++ entry points (the paper's printed
// numbers, the surfaces to export against an independent roller-axis construction), the files the
// CLI writes (point cloud, STL mesh), and bad input rejected with exit code 2 and the JSON path.
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/common/scalar.h"
#include "studies/globoidal_cam_study.h"
#include "tests/test_util.h"

namespace camopt {
namespace globoidal_study_test {

using camopt::testing::ReadCsv;
using camopt::testing::ReadFile;
using camopt::testing::RunCamopt;
using camopt::testing::SourcePath;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;
using nlohmann::json;
using studies::Node;
using studies::RunContext;
namespace globoidal_study = studies::globoidal_cam;

constexpr double kDeg = kPi / 180.0;

json Example() {
  return json::parse(ReadFile(SourcePath("studies/examples/globoidal_cam_paper.json")));
}

// Modified sine, written here from its definition (independent of model/motion): the rise's
// peak acceleration coefficient is 4π²/(4 + π).
double ModifiedSineCa() { return 4 * kPi * kPi / (4 + kPi); }

// Parse and Run, the C++ entry points of the kind.
struct Ran {
  globoidal_study::Study study;
  globoidal_study::Result result;
};
Ran ParseAndRun(const json& file) {
  const Node root(&file, "study.json", "");
  Ran r{globoidal_study::Parse(root), {}};
  RunContext ctx;
  ctx.quiet = true;
  r.result = globoidal_study::Run(r.study, ctx);
  return r;
}

TEST(GloboidalStudy, PaperExample) {
  const Ran ran = ParseAndRun(Example());
  const globoidal_study::Result& r = ran.result;
  // Eqs. (8)–(9) and (7).
  EXPECT_DOUBLE_EQ(r.roller_axis_limits_mm.l1, 25.5);
  EXPECT_DOUBLE_EQ(r.roller_axis_limits_mm.l2, 19.5);
  EXPECT_NEAR(r.initial_angle_top_deg[0], 12.5, 1e-12);
  EXPECT_NEAR(r.initial_angle_top_deg[1], -32.5, 1e-12);
  EXPECT_NEAR(r.initial_angle_bottom_deg[0], 32.5, 1e-12);
  EXPECT_NEAR(r.initial_angle_bottom_deg[1], -12.5, 1e-12);
  EXPECT_NEAR(r.roller_angle_range_deg[0][0], 12.5, 1e-9);
  EXPECT_NEAR(r.roller_angle_range_deg[0][1], 32.5, 1e-9);
  EXPECT_NEAR(r.roller_angle_range_deg[1][0], -32.5, 1e-9);
  EXPECT_FALSE(r.undercut);
  EXPECT_GT(r.survey.min_undercut_margin.value, 0.0);
  // Peak acceleration of the swing per rad²: Ca φ_f/θ_f1² on the 60° rise.
  EXPECT_NEAR(r.peak_acceleration_deg_per_rad2, ModifiedSineCa() * 20.0 / std::pow(60 * kDeg, 2),
              1e-3);
  // The largest pressure angle from the closed form tan α = l φ'/(C − l cos φ), maximised here
  // by brute force over the rise (peak φ' at its middle for l = l₁, checked on a grid).
  {
    double best = 0;
    const double k = 1 / (4 + kPi), b = 60 * kDeg, f = 20 * kDeg;
    for (int i = 0; i <= 6000; ++i) {
      const double u = i / 6000.0;
      double s, v;
      if (u <= 0.125) {
        s = k * (kPi * u - std::sin(4 * kPi * u) / 4), v = k * kPi * (1 - std::cos(4 * kPi * u));
      } else if (u < 0.875) {
        const double a = kPi / 3 + 4 * kPi / 3 * u;
        s = k * (2 + kPi * u - 2.25 * std::sin(a)), v = k * kPi * (1 - 3 * std::cos(a));
      } else {
        s = k * (4 + kPi * u - std::sin(4 * kPi * u) / 4), v = k * kPi * (1 - std::cos(4 * kPi * u));
      }
      for (double phi0 : {12.5 * kDeg, -32.5 * kDeg})
        for (double l : {19.5, 25.5}) {
          const double phi = phi0 + f * s, dphi = f * v / b;
          best = std::max(best, std::atan(l * dphi / (45 - l * std::cos(phi))));
        }
    }
    EXPECT_NEAR(r.survey.max_abs_pressure_angle.value / kDeg, best / kDeg, 0.05);
  }

  // Dynamics at both speeds: the kinematic peak acceleration Ca φ_f ω²/θ_f1² (sampled), the
  // dynamic force never below the static share of the load, and the slower run deflects less.
  const auto& speeds = r.speeds;
  ASSERT_EQ(speeds.size(), 2u);
  for (const auto& s : speeds) {
    ASSERT_TRUE(s.failed.empty()) << s.failed;
    const double w = s.cam_speed_rpm * 2 * kPi / 60;
    const double expect = ModifiedSineCa() * 20 * kDeg * w * w / std::pow(60 * kDeg, 2);
    EXPECT_NEAR(s.peak_turret_acceleration_kinematic_rad_s2 / expect, 1.0, 2e-3);
    EXPECT_GT(s.max_force_roller_1_N, 500e3 / 22.0);
    EXPECT_GE(s.max_quasi_static_force_N, 500e3 / 22.0);
  }
  EXPECT_LT(speeds[1].peak_turret_acceleration_dynamic_rad_s2,
            speeds[0].peak_turret_acceleration_dynamic_rad_s2);

  // The working surfaces to export: every point is R = 4 mm from the roller axis built here from
  // eq. (4) with the roller angle of the series (the export grid is every second series angle).
  ASSERT_EQ(r.surface_axis_mm.size(), 6u);
  size_t count = 0;
  for (int j = 1; j <= 2; ++j) {
    const auto& pts = r.surface_points[j - 1];
    ASSERT_EQ(pts.size(), 360u);
    for (size_t i = 0; i < pts.size(); ++i) {
      for (size_t m = 0; m < pts[i].size(); ++m, ++count) {
        if (count % 7 != 0) continue;
        const double t = 2 * kPi * i / 360;
        const double phi = r.series.roller_angle_deg[j - 1][2 * i] * kDeg;
        const double px = 45 * std::sin(t), py = 45 * std::cos(t);
        const double qx = -std::cos(phi) * std::sin(t), qy = -std::cos(phi) * std::cos(t),
                     qz = std::sin(phi);
        const double vx = pts[i][m].x() - px, vy = pts[i][m].y() - py, vz = pts[i][m].z();
        const double along = vx * qx + vy * qy + vz * qz;
        const double dist = std::sqrt(vx * vx + vy * vy + vz * vz - along * along);
        EXPECT_NEAR(dist, 4.0, 1e-6) << count;
        EXPECT_NEAR(along, r.surface_axis_mm[m], 1e-6) << count;
      }
    }
  }
  EXPECT_EQ(count, 2u * 360 * 6);
}

TEST(GloboidalStudy, PaperExampleThroughTheCli) {
  const auto dir = TempDir("globoidal-paper") / "out";
  // The STL asked for as ASCII (binary is the default now; GeometryFiles tests check it).
  json file = Example();
  file["geometry_files"] = {{"stl_format", "ascii"}};
  WriteFile(dir.parent_path() / "globoidal-paper.json", file.dump());
  const auto res = RunCamopt("run " + (dir.parent_path() / "globoidal-paper.json").string() +
                             " --quiet --out " + dir.string());
  ASSERT_EQ(res.exit_code, 0) << res.stderr_text;
  const json r = json::parse(ReadFile(dir / "result.json"));
  EXPECT_EQ(r["dynamics"]["speeds"].size(), 2u);
  // The CLI writes what the C++ entry points give: result.json is WriteResult(Run(Parse)).
  const Ran ran = ParseAndRun(file);
  EXPECT_EQ(camopt::testing::WithoutRunStamp(r), studies::WriteResult(ran.result));
  for (const char* f : {"series.csv", "dynamics_600rpm.csv", "dynamics_120rpm.csv",
                        "svaj.svg", "svaj_time.svg", "pressure_angle.svg", "contact_forces_600rpm.svg",
                        "contact_forces_120rpm.svg", "turret_velocity_600rpm.svg",
                        "turret_acceleration_120rpm.svg", "working_surfaces.csv",
                        "working_surfaces.stl"})
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  // S-V-A-J stacked, per degree of cam and over time at the first speed (600 rpm: 100 ms a turn).
  const std::string svaj_time = ReadFile(dir / "svaj_time.svg");
  for (const char* label : {"at 600 rpm", "time [ms]", "velocity [deg/s]", "jerk [deg/s³]"})
    EXPECT_NE(svaj_time.find(label), std::string::npos) << label;
  EXPECT_NE(ReadFile(dir / "svaj.svg").find("acceleration [deg/deg²]"), std::string::npos);

  // The exported point cloud: one row per surface point.
  const auto cloud = ReadCsv(ReadFile(dir / "working_surfaces.csv"));
  ASSERT_EQ(cloud.at("x_mm").size(), 2u * 360 * 6);
  // ASCII STL: 2 rollers × 360 × 5 cells × 2 triangles, unit facet normals.
  const std::string stl = ReadFile(dir / "working_surfaces.stl");
  EXPECT_EQ(stl.rfind("solid ", 0), 0u);
  size_t facets = 0, pos = 0;
  while ((pos = stl.find("facet normal", pos)) != std::string::npos) ++facets, ++pos;
  EXPECT_EQ(facets, 2u * 360 * 5 * 2);
  EXPECT_NE(stl.find("endsolid"), std::string::npos);
  // The first facet (roller 1, θ = 0, l = l₂) faces out of the rib like the point cloud's normal.
  {
    std::istringstream in(stl.substr(stl.find("facet normal") + 12));
    double nx, ny, nz;
    in >> nx >> ny >> nz;
    const double dot = nx * cloud.at("normal_x")[0] + ny * cloud.at("normal_y")[0] +
                       nz * cloud.at("normal_z")[0];
    EXPECT_GT(dot, 0.99);
    EXPECT_NEAR(nx * nx + ny * ny + nz * nz, 1.0, 1e-6);
  }
}

// Lazy stages: "analysis.evaluate": ["geometry"] needs no load, contact or dynamics inputs and
// runs neither the dynamics nor the surface export, even when the file asks for speeds and files;
// the geometry is that of the full study.
TEST(GloboidalStudy, GeometryOnlySkipsDynamicsAndExport) {
  const Ran full = ParseAndRun(Example());
  json file = Example();
  file.erase("load");
  file.erase("contact");
  file.erase("dynamics");
  file["analysis"]["evaluate"] = {"geometry"};
  const Ran bare = ParseAndRun(file);
  EXPECT_TRUE(bare.result.speeds.empty());
  EXPECT_TRUE(bare.result.surface_points[0].empty());
  EXPECT_TRUE(bare.result.surface_axis_mm.empty());
  EXPECT_EQ(bare.result.survey.max_abs_pressure_angle.value,
            full.result.survey.max_abs_pressure_angle.value);
  EXPECT_EQ(bare.result.series.min_undercut_margin, full.result.series.min_undercut_margin);

  file = Example();  // speeds and export given, but not asked for
  file["analysis"]["evaluate"] = {"geometry"};
  const Ran asked = ParseAndRun(file);
  EXPECT_TRUE(asked.result.speeds.empty());
  EXPECT_TRUE(asked.result.surface_points[1].empty());
  const json j = studies::WriteResult(asked.result);
  EXPECT_FALSE(j.contains("dynamics"));
  EXPECT_FALSE(j.contains("load"));
  EXPECT_FALSE(j.contains("surface_export"));
  EXPECT_EQ(j["evaluated"], json({"geometry"}));

  // Through the CLI: no dynamics or surface files are written.
  const auto dir = TempDir("globoidal-geometry-only");
  WriteFile(dir / "study.json", file.dump());
  const auto res = RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " +
                             (dir / "out").string());
  ASSERT_EQ(res.exit_code, 0) << res.stderr_text;
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "series.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "dynamics_600rpm.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "working_surfaces.stl"));

  // Dynamics without the export: the speeds run, no surfaces.
  file = Example();
  file["analysis"]["evaluate"] = {"geometry", "dynamics"};
  file["dynamics"]["relative_tolerance"] = 1e-6;
  const Ran dyn = ParseAndRun(file);
  EXPECT_EQ(dyn.result.speeds.size(), 2u);
  EXPECT_TRUE(dyn.result.surface_points[0].empty());
}

TEST(GloboidalStudy, UndercutSkipsDynamicsAndIsReported) {
  json study = Example();
  study["cam"]["roller_radius_mm"] = 7.5;
  study["cam"]["roller_angle_deg"] = 60;
  study["motion"] = json::parse(R"([{"law": "modified_sine", "rise_deg": 20, "cam_angle_deg": 12},
      {"law": "dwell", "cam_angle_deg": 108}, {"law": "modified_sine", "rise_deg": -20, "cam_angle_deg": 135},
      {"law": "dwell", "cam_angle_deg": 105}])");
  const Ran ran = ParseAndRun(study);
  const globoidal_study::Result& r = ran.result;
  EXPECT_TRUE(r.undercut);
  EXPECT_LE(r.survey.min_undercut_margin.value, 0.0);
  EXPECT_FALSE(r.dynamics_skipped.empty());
  EXPECT_TRUE(r.speeds.empty());
  EXPECT_TRUE(studies::WriteResult(r)["dynamics"].contains("skipped"));
}

// The verdict's limits: the pressure angle against its default 45° (Rothbart, for a follower on a
// pivot) or a given one, the contact stress when a limit is given (the paper example's 500 N·m on
// 4 mm rollers: about 7.7 GPa, so 2000 MPa fails), limits_ok, and --strict's exit 3.
TEST(GloboidalStudy, LimitsGiveTheVerdict) {
  const Ran ran = ParseAndRun(Example());
  json j = studies::WriteResult(ran.result);
  EXPECT_EQ(j["limits"]["pressure_angle_deg"], 45.0);
  EXPECT_EQ(j["limits"]["defaults"], json({"pressure_angle_deg"}));
  EXPECT_TRUE(j["pressure_angle_ok"].get<bool>());  // 34.97°
  EXPECT_TRUE(j["limits_ok"].get<bool>());
  EXPECT_FALSE(j.contains("contact_stress_ok"));
  // The largest stress is the larger speed's peak, each ≥ the quasi-static stress on the dwell.
  const double peak = j["max_contact_stress_MPa"].get<double>();
  for (const auto& sp : j["dynamics"]["speeds"]) EXPECT_LE(sp["max_contact_stress_MPa"].get<double>(), peak);
  EXPECT_GT(peak, 6000.0);
  EXPECT_LT(peak, 9000.0);

  json study = Example();
  study["limits"] = {{"pressure_angle_deg", 30}, {"contact_stress_MPa", 2000}};
  const Ran strict = ParseAndRun(study);
  j = studies::WriteResult(strict.result);
  EXPECT_EQ(j["limits"]["defaults"], json::array());
  EXPECT_FALSE(j["pressure_angle_ok"].get<bool>());
  EXPECT_FALSE(j["contact_stress_ok"].get<bool>());
  EXPECT_FALSE(j["limits_ok"].get<bool>());

  const auto dir = TempDir("globoidal-limits");
  study["analysis"]["evaluate"] = {"geometry", "dynamics"};
  study["dynamics"]["cam_speeds_rpm"] = {120};
  WriteFile(dir / "study.json", study.dump());
  const auto res =
      RunCamopt("run " + (dir / "study.json").string() + " --strict --quiet --out " + (dir / "out").string());
  EXPECT_EQ(res.exit_code, 3) << res.stderr_text;
  EXPECT_NE(res.stderr_text.find("2 of 4 limits exceeded"), std::string::npos) << res.stderr_text;
}

struct BadCase {
  const char* name;
  const char* patch;  // a JSON merge patch applied to the example
  const char* path;   // the JSON path the message must name
  const char* words;  // and a phrase it must contain
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

class GloboidalBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(GloboidalBadInput, ExitCode2AndTheJsonPath) {
  const BadCase& c = GetParam();
  json study = Example();
  study.merge_patch(json::parse(c.patch));
  camopt::testing::ExpectStudyRejected(study, std::string("globoidal-") + c.name, c.path, c.words);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, GloboidalBadInput,
    ::testing::Values(
        BadCase{"missing", R"({"cam": {"roller_radius_mm": null}})", "/cam/roller_radius_mm", "missing"},
        BadCase{"negative", R"({"cam": {"pitch_radius_mm": -22}})", "/cam/pitch_radius_mm", "> 0"},
        BadCase{"typo", R"({"cam": {"roler_radius_mm": 4}})", "/cam/roler_radius_mm", "unknown field"},
        BadCase{"overlap", R"({"cam": {"roller_angle_deg": 20}})", "/cam/roller_angle_deg", "overlap"},
        BadCase{"axis", R"({"cam": {"center_distance_mm": 28}})", "/cam/center_distance_mm",
                "reach the cam axis"},
        BadCase{"length", R"({"cam": {"roller_length_mm": 50}})", "/cam/roller_length_mm",
                "turret axis"},
        BadCase{"direction", R"({"cam": {"first_motion": "up"}})", "/cam/first_motion", "clockwise"},
        BadCase{"jam_limit", R"({"limits": {"pressure_angle_deg": 89}})", "/limits/pressure_angle_deg",
                "the jam limit"},
        BadCase{"stress_limit", R"({"limits": {"contact_stress_MPa": 0}})", "/limits/contact_stress_MPa", "> 0"},
        BadCase{"law", R"({"motion": [{"law": "parabolic", "rise_deg": 20, "cam_angle_deg": 360}]})",
                "/motion/0/law", "modified_sine"},
        BadCase{"sum", R"({"motion": [{"law": "modified_sine", "rise_deg": 20, "cam_angle_deg": 60},
            {"law": "dwell", "cam_angle_deg": 60}, {"law": "modified_sine", "rise_deg": -20, "cam_angle_deg": 135},
            {"law": "dwell", "cam_angle_deg": 100}]})", "/motion", "355"},
        BadCase{"swing", R"({"motion": [{"law": "modified_sine", "rise_deg": 15, "cam_angle_deg": 60},
            {"law": "dwell", "cam_angle_deg": 60}, {"law": "modified_sine", "rise_deg": -15, "cam_angle_deg": 135},
            {"law": "dwell", "cam_angle_deg": 105}]})", "/motion", "swing must run from 0 to"},
        BadCase{"speed", R"({"dynamics": {"cam_speeds_rpm": [600, -120]}})", "/dynamics/cam_speeds_rpm/1",
                "a number in [0.01, 100000]"},
        BadCase{"step", R"({"dynamics": {"time_step_s": 1e-3}})", "/dynamics/time_step_s",
                "give \"relative_tolerance\""},
        BadCase{"tiny_step", R"({"dynamics": {"time_step_s": 1e-9}})", "/dynamics/time_step_s",
                "no longer used"},
        BadCase{"rtol", R"({"dynamics": {"relative_tolerance": 1e-20}})",
                "/dynamics/relative_tolerance", "[1e-13, 1e-3]"},
        BadCase{"loose_rtol", R"({"dynamics": {"relative_tolerance": 0.1}})",
                "/dynamics/relative_tolerance", "[1e-13, 1e-3]"},
        BadCase{"atol", R"({"dynamics": {"absolute_tolerance": 0}})",
                "/dynamics/absolute_tolerance", "> 0"},
        BadCase{"max_steps", R"({"dynamics": {"max_steps": 1000}})", "/dynamics/max_steps",
                "loosen relative_tolerance"},
        BadCase{"long_run", R"({"dynamics": {"end_time_s": 100, "max_steps": 10000}})", "/dynamics",
                "shorten end_time_s or raise max_steps"},
        BadCase{"stage", R"({"analysis": {"evaluate": ["geometry", "stress"]}})",
                "/analysis/evaluate/1", "\"dynamics\""},
        BadCase{"stage_input", R"({"dynamics": {"cam_speeds_rpm": null}, "analysis": {"evaluate": ["dynamics"]}})",
                "/dynamics/cam_speeds_rpm", "missing"},
        BadCase{"stage_speeds", R"({"dynamics": {"cam_speeds_rpm": []}, "analysis": {"evaluate": ["dynamics"]}})",
                "/dynamics/cam_speeds_rpm", "at least one cam speed"},
        BadCase{"poisson", R"({"contact": {"cam_poisson": 0.7}})", "/contact/cam_poisson", "0.499"},
        BadCase{"arm", R"({"contact": {"contact_arm_mm": 30}})", "/contact/contact_arm_mm", "[l₂, l₁]"},
        BadCase{"jam", R"({"motion": [{"law": "modified_sine", "rise_deg": 20, "cam_angle_deg": 0.5},
            {"law": "dwell", "cam_angle_deg": 119.5}, {"law": "modified_sine", "rise_deg": -20, "cam_angle_deg": 135},
            {"law": "dwell", "cam_angle_deg": 105}]})", "/motion", "pressure angle"}));

}  // namespace globoidal_study_test
}  // namespace camopt
