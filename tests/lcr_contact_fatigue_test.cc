// Contact fatigue of the LCR's cam surfaces (model/lcr/contact_fatigue.h, studies/contact_fatigue_input.h,
// docs/life.md "Contact fatigue of the cam surfaces"): the subsurface stresses reported beside each
// cam's peak Hertz pressure, checked by hand from the peak contact's p0 and half-width b.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/contact/hertz.h"
#include "model/lcr/contact_fatigue.h"
#include "model/lcr/forces.h"
#include "studies/lcr_analysis_study.h"
#include "tests/test_util.h"

namespace camopt {
namespace lcr_contact_fatigue_test {

using camopt::testing::ReadFile;
using camopt::testing::SourcePath;

/// The closed forms of the line contact's maxima (τ1 exact; τ0 = p0/4 at b/2 exactly, found by
/// golden sections to a bracket of 1e-12 of b: the value is flat there, so to ~1e-12 of p0).
constexpr double kClosedFormRelTol = 1e-9;
/// The von Mises maximum is quoted to four digits (0.5575 p0 at 0.7043 b, ν = 0.3).
constexpr double kFourDigitsRelTol = 1e-4;

nlohmann::json Example(const std::string& name) {
  return nlohmann::json::parse(ReadFile(SourcePath("studies/examples/" + name)));
}

struct StudyRun {
  studies::lcr_analysis::Study study;
  studies::lcr_analysis::Result result;
  nlohmann::json json;
};

StudyRun RunStudy(const nlohmann::json& s) {
  const studies::Node root(&s, "s.json", "");
  StudyRun r{studies::lcr_analysis::Parse(root), {}, {}};
  r.result = studies::lcr_analysis::Run(r.study, {"s.json", true});
  r.json = studies::WriteResult(r.result);
  return r;
}

// The line-contact maxima from p0 and b, by the closed forms (docs/life.md, "Contact fatigue").
void ExpectLineMaxima(const nlohmann::json& sub, double p0, double b) {
  const double phi = 0.5 * (1 + std::sqrt(5.0));
  EXPECT_NEAR(sub["peak_pressure_MPa"].get<double>(), p0, 1e-12 * p0);
  EXPECT_NEAR(sub["half_width_mm"].get<double>(), b, 1e-9 * b);
  EXPECT_NEAR(sub["max_shear_MPa"].get<double>(), p0 * std::pow(phi, -2.5), kClosedFormRelTol * p0);
  EXPECT_NEAR(sub["max_shear_MPa"].get<double>(), 0.30028 * p0, 1e-5 * p0);
  EXPECT_NEAR(sub["max_shear_depth_mm"].get<double>(), b / std::sqrt(phi), kClosedFormRelTol * b);
  EXPECT_NEAR(sub["max_shear_depth_mm"].get<double>(), 0.78615 * b, 1e-5 * b);
  EXPECT_NEAR(sub["max_orthogonal_shear_MPa"].get<double>(), 0.25 * p0, kClosedFormRelTol * p0);
  EXPECT_NEAR(sub["max_orthogonal_shear_depth_mm"].get<double>(), 0.5 * b, 1e-6 * b);
  EXPECT_NEAR(sub["max_orthogonal_shear_offset_mm"].get<double>(), 0.5 * std::sqrt(3.0) * b, 1e-6 * b);
  EXPECT_NEAR(sub["max_von_mises_MPa"].get<double>(), 0.5575 * p0, kFourDigitsRelTol * p0);
  EXPECT_NEAR(sub["max_von_mises_depth_mm"].get<double>(), 0.7043 * b, kFourDigitsRelTol * b);
}

// LCR II (line model): the peak contact found again by AnalyzeAngle at every angle, its b by hand
// b = sqrt(4 F R'/(π L E*)), and the maxima from p0 and b.
TEST(LcrContactFatigue, SubsurfaceStressesOfTheExamplesPeakContactByHand) {
  nlohmann::json s = Example("lcr_ii.json");
  s["analysis"]["angle_steps"] = 720;
  const StudyRun run = RunStudy(s);
  const lcr::Reducer<double>& r = run.study.reducer;
  const double e_star = 206000.0 / (2 * (1 - 0.09));
  for (const char* side : {"input_cam", "output_cam"}) {
    SCOPED_TRACE(side);
    const bool input = std::string(side) == "input_cam";
    const lcr::CamSide<double>& cam = input ? r.input : r.output;
    double p_best = 0, b_best = 0;
    for (int i = 0; i < 720; ++i) {
      const lcr::AngleLoads<double> a = lcr::AnalyzeAngle(r, run.study.material, run.study.load, 2 * kPi * i / 720);
      const lcr::SideLoads<double>& sl = input ? a.input : a.output;
      for (size_t k = 0; k < sl.force.size(); ++k) {
        if (!(sl.force[k] > 0)) continue;
        const double r_eff = cam.roller_radius * (1 - cam.roller_radius * sl.contacts[k].curvature);
        const double l = cam.contact_length();
        const double p = std::sqrt(sl.force[k] * e_star / (kPi * l * r_eff));
        if (p > p_best) p_best = p, b_best = std::sqrt(4 * sl.force[k] * r_eff / (kPi * l * e_star));
      }
    }
    const nlohmann::json& cj = run.json[side];
    ASSERT_TRUE(cj.contains("subsurface"));
    EXPECT_NEAR(cj["max_contact_stress_MPa"].get<double>(), p_best, 1e-9 * p_best);
    ExpectLineMaxima(cj["subsurface"], cj["max_contact_stress_MPa"].get<double>(), b_best);
    // b = 2 p0 R'/E* (the same contact): b/p0 of the order 2 r_r/E* (R' ≤ r_r on the convex cam).
    EXPECT_GT(b_best, 0.0);
    EXPECT_NE(cj["subsurface"]["basis"].get<std::string>().find("line contact"), std::string::npos);
  }
}

// The slices model with misalignment: the worst slice's values, b = 2 p0 R'/E* of the contact
// that sets the cam's peak.
TEST(LcrContactFatigue, SubsurfaceOfTheWorstSliceUnderMisalignment) {
  nlohmann::json s = Example("lcr_ii_crowned.json");
  s["analysis"]["angle_steps"] = 120;
  s["contact"]["slices"] = 20;
  const StudyRun run = RunStudy(s);
  const double e_star = 206000.0 / (2 * (1 - 0.09));
  for (const char* side : {"input_cam", "output_cam"}) {
    SCOPED_TRACE(side);
    const lcr::Contact3DCycleSide& c3 =
        std::string(side) == "input_cam" ? *run.result.contact_input : *run.result.contact_output;
    const double p0 = c3.max_contact_stress_MPa;
    const double b = 2 * p0 * c3.stress_radius_mm[size_t(c3.worst_angle)] / e_star;
    const nlohmann::json& cj = run.json[side];
    EXPECT_EQ(cj["max_contact_stress_MPa"].get<double>(), p0);
    ExpectLineMaxima(cj["subsurface"], p0, b);
    EXPECT_NE(cj["subsurface"]["basis"].get<std::string>().find("worst slice"), std::string::npos);
  }
}

// Another ν moves only the von Mises maximum (τ1 and τ0 of plane strain do not depend on ν).
TEST(LcrContactFatigue, VonMisesFollowsThePoissonRatio) {
  nlohmann::json s = Example("lcr_ii.json");
  s["analysis"]["angle_steps"] = 72;
  s["material"]["poisson_ratio"] = 0.25;
  const StudyRun run = RunStudy(s);
  const nlohmann::json& sub = run.json["input_cam"]["subsurface"];
  const double p0 = sub["peak_pressure_MPa"].get<double>(), b = sub["half_width_mm"].get<double>();
  // Dense scan of the axis von Mises stress at ν = 0.25 (σ_y = ν(σ_x + σ_z)), by hand.
  double best = 0;
  for (int i = 1; i <= 200000; ++i) {
    const double z = 2.0 * i / 200000, rt = std::sqrt(1 + z * z);
    const double sx = -((1 + 2 * z * z) / rt - 2 * z), sz = -1 / rt, sy = 0.25 * (sx + sz);
    best = std::max(best, std::sqrt(0.5 * ((sx - sy) * (sx - sy) + (sy - sz) * (sy - sz) + (sz - sx) * (sz - sx))));
  }
  EXPECT_NEAR(sub["max_von_mises_MPa"].get<double>() / p0, best, 1e-9);
  const double phi = 0.5 * (1 + std::sqrt(5.0));
  EXPECT_NEAR(sub["max_shear_MPa"].get<double>(), p0 * std::pow(phi, -2.5), kClosedFormRelTol * p0);
  EXPECT_GT(b, 0.0);
}

// ---- Contact life of the cam tracks -------------------------------------------------------------

// Over-rollings of a point of the track per input revolution, N_c = n ψ', from the example's
// speed ratios by hand: the fixed turret against the cam (ω_c = −ω_in/12): 13 rollers × 1/12;
// the output turret (−1/90) against the cam (−1/12): 15 × (1/12 − 1/90) = 15 × 13/180.
TEST(LcrContactFatigue, OverRollingsPerInputRevolutionByHand) {
  nlohmann::json s = Example("lcr_ii.json");
  const studies::Node root(&s, "s.json", "");
  const lcr::Reducer<double> r = studies::lcr_analysis::Parse(root).reducer;
  EXPECT_NEAR(lcr::ContactPassesPerInputRevolution(r, lcr::Side::kInput), 13.0 / 12.0, 1e-14);
  EXPECT_NEAR(lcr::ContactPassesPerInputRevolution(r, lcr::Side::kOutput), 15.0 * 13.0 / 180.0, 1e-14);
}

nlohmann::json FatigueStudy() {
  nlohmann::json s = Example("lcr_ii_life.json");
  s["analysis"]["angle_steps"] = 360;
  s["material"]["contact_fatigue"] = {{"reference_pressure_MPa", 1500}, {"reference_cycles", 1e8}};
  s["load"].erase("input_speed_rpm");
  s["duty_cycle"] = {{{"output_torque_Nm", 80}, {"input_speed_rpm", 1000}, {"time_share", 0.6}},
                     {{"output_torque_Nm", 20}, {"input_speed_rpm", 1500}, {"time_share", 0.3}},
                     {{"output_torque_Nm", 80}, {"input_speed_rpm", 0}, {"time_share", 0.1}}};
  return s;
}

// Two running lines and a standing one, by hand: under the rigid law the forces are linear in the
// torque, so the peak pressure at 20 N·m is p0(80 N·m)·√(1/4) = p0/2;
// 1/L = Σ t_i 60 n_i N_c (p_i/p_ref)^n / N_ref, n = 8 (the default), N_c = 13/12.
TEST(LcrContactFatigue, ContactLifeOverADutyCycleByHand) {
  const StudyRun run = RunStudy(FatigueStudy());
  const nlohmann::json& life = run.json["life"];
  for (const char* side : {"input_cam", "output_cam"}) {
    SCOPED_TRACE(side);
    const double p = run.json[side]["max_contact_stress_MPa"].get<double>();  // at 80 N·m
    const nlohmann::json& c = life["contact_life"][std::string(side) + "_contact"];
    const std::vector<double> peaks = c["line_peak_pressure_MPa"].get<std::vector<double>>();
    ASSERT_EQ(peaks.size(), 3u);
    EXPECT_NEAR(peaks[0], p, 1e-12 * p);
    EXPECT_NEAR(peaks[1], 0.5 * p, 1e-12 * p);
    const double nc = 13.0 / 12.0, q = p / 1500;
    const double rate = 60 * nc * (0.6 * 1000 * std::pow(q, 8) + 0.3 * 1500 * std::pow(0.5 * q, 8)) / 1e8;
    EXPECT_NEAR(life[std::string(side) + "_contact_L10h"].get<double>(), 1 / rate, 1e-12 / rate);
    // p_eq at the mean speed gives the same life: N_ref (p_ref/p_eq)^8 / (60 n̄ N_c), n̄ = 1050 rpm.
    const double peq = c["equivalent_pressure_MPa"].get<double>();
    EXPECT_NEAR(1e8 * std::pow(1500 / peq, 8) / (60 * 1050 * nc), 1 / rate, 1e-10 / rate);
  }
  EXPECT_EQ(life["contact_life"]["exponent"].get<double>(), 8.0);
  // The cam contact lives do not enter the bearings' shortest life.
  double shortest = kInf;
  for (const char* b : {"input_roller_L10h", "output_roller_L10h", "eccentric_bearing_L10h"})
    shortest = std::min(shortest, life[b].get<double>());
  EXPECT_EQ(life["shortest_L10h"].get<double>(), shortest);
}

// A given exponent replaces the default; the life scales as (p_ref/p)^n.
TEST(LcrContactFatigue, GivenExponent) {
  nlohmann::json s = FatigueStudy();
  s["duty_cycle"] = {{{"output_torque_Nm", 80}, {"input_speed_rpm", 1000}, {"time_share", 1}}};
  s["material"]["contact_fatigue"]["exponent"] = 20.0 / 3.0;
  const StudyRun run = RunStudy(s);
  const double p = run.json["input_cam"]["max_contact_stress_MPa"].get<double>();
  const double expected = 1e8 * std::pow(1500 / p, 20.0 / 3.0) / (60 * 1000 * 13.0 / 12.0);
  EXPECT_NEAR(run.json["life"]["input_cam_contact_L10h"].get<double>(), expected, 1e-12 * expected);
  EXPECT_EQ(run.json["life"]["contact_life"]["exponent_source"], "given");
}

// The life table (lcr_min_size's row keys) with pass/fail against limits.life_h.
TEST(LcrContactFatigue, LifeTableRowsAndLimit) {
  nlohmann::json s = FatigueStudy();
  s["limits"]["life_h"] = 5000;
  const StudyRun run = RunStudy(s);
  const nlohmann::json& life = run.json["life"];
  EXPECT_EQ(life["life_h"].get<double>(), 5000.0);
  const nlohmann::json& table = life["table"];
  ASSERT_EQ(table.size(), 5u);  // three bearings, two cam tracks
  for (const auto& row : table) {
    const std::string e = row["element"].get<std::string>();
    SCOPED_TRACE(e);
    EXPECT_EQ(row["L10h"], life[e + "_L10h"]);
    EXPECT_EQ(row["pass"].get<bool>(), row["L10h"].get<double>() >= 5000.0);
    EXPECT_TRUE(row.contains("kind"));
  }
  EXPECT_EQ(table[0]["element"], "input_roller");
  EXPECT_EQ(table[0]["dynamic_rating_N"].get<double>(), 3300.0);
  EXPECT_EQ(table[3]["kind"], "cam contact");
}

TEST(LcrContactFatigue, BadInputExitsTwoNamingThePath) {
  nlohmann::json s = FatigueStudy();
  s["material"]["contact_fatigue"]["reference_cycles"] = -1;
  camopt::testing::ExpectStudyRejected(s, "cf-cycles", "/material/contact_fatigue/reference_cycles", "expected");
  s = FatigueStudy();
  s["material"]["contact_fatigue"]["exponent"] = 0;
  camopt::testing::ExpectStudyRejected(s, "cf-exponent", "/material/contact_fatigue/exponent", "expected");
  s = FatigueStudy();
  s["material"]["contact_fatigue"]["cycles"] = 1e8;
  camopt::testing::ExpectStudyRejected(s, "cf-unknown", "/material/contact_fatigue/cycles", "unknown field");
  s = Example("lcr_ii.json");
  s["material"]["contact_fatigue"] = {{"reference_pressure_MPa", 1500}, {"reference_cycles", 1e8}};
  camopt::testing::ExpectStudyRejected(s, "cf-no-speed", "/material/contact_fatigue", "needs one");
  s = Example("lcr_ii.json");
  s["limits"]["life_h"] = 1000;
  camopt::testing::ExpectStudyRejected(s, "life-limit-no-speed", "/limits/life_h", "needs one");
}

}  // namespace lcr_contact_fatigue_test
}  // namespace camopt
