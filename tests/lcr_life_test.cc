// Bearing lives of the lcr_analysis study (model/lcr/life.h, model/common/bearing_life.h,
// docs/life.md): roller spin against its closed form (complete elliptic integral), the load
// periods, a two-line duty cycle by hand through the whole study, the one-line equivalence, and
// bad input (exit 2 naming the JSON path).
#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/lcr/cycle.h"
#include "model/lcr/life.h"
#include "studies/lcr_analysis_study.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt {
namespace lcr_life_test {

using camopt::testing::ExpectStudyRejected;
using camopt::testing::ReadFile;
using camopt::testing::SourcePath;

/// Uniform samples of a smooth periodic function (the spin rate): the trapezoidal rule is
/// spectrally accurate, so 3600 samples agree with the integral to rounding.
constexpr double kQuadratureRelTol = 1e-10;
/// Hand calculations from the study's own one-line numbers: a few roundings of pow.
constexpr double kHandCalcRelTol = 1e-9;

nlohmann::json LifeStudy() {
  return nlohmann::json::parse(ReadFile(SourcePath("studies/examples/lcr_ii_life.json")));
}

studies::lcr_analysis::Result RunStudy(const nlohmann::json& study) {
  const studies::Node root(&study, "life.json", "");
  return studies::lcr_analysis::Run(studies::lcr_analysis::Parse(root), {"life.json", true});
}

const studies::lcr_analysis::BearingLifeResult& Bearing(const studies::lcr_analysis::Result& res,
                                                        const std::string& name) {
  for (const auto& b : res.life->bearings)
    if (b.name == name) return b;
  throw std::runtime_error("no bearing " + name);
}

lcr::Reducer<double> LcrII() {
  const nlohmann::json s = LifeStudy();
  const studies::Node root(&s, "life.json", "");
  return studies::lcr_analysis::Parse(root).reducer;
}

// Revolutions of a roller per input revolution: ψ' (⟨ρ⟩ − r_r)/r_r with
// ⟨ρ⟩ = (1/2π) ∫ sqrt(A² + B² − 2AB cos φ) dφ = (2/π)(A + B) E(2√(AB)/(A + B)),
// A = r_d, B = e n/(n − m); ψ' = 1/12 (input, m_A = 12) and 13/180 (output: n_A(n_B − m_B)/(m_A n_B)).
// The eccentric bearing turns n_A/m_A = 13/12 times per input revolution.
TEST(LcrLife, RollerRevolutionsMatchTheEllipticIntegral) {
  const lcr::Reducer<double> r = LcrII();
  const struct {
    lcr::LcrBearing bearing;
    double turret_radius, pitch_radius, psi_rate;
  } cases[] = {{lcr::LcrBearing::kInputRoller, 37.0, 2.0 * 13, 1.0 / 12},
               {lcr::LcrBearing::kOutputRoller, 42.0, 2.0 * 15, 13.0 / 180}};
  for (const auto& c : cases) {
    const double a = c.turret_radius, b = c.pitch_radius, rr = 6.0;
    const double mean_rho = 2.0 / kPi * (a + b) * std::comp_ellint_2(2 * std::sqrt(a * b) / (a + b));
    const double expected = c.psi_rate * (mean_rho - rr) / rr;
    const double period = lcr::LoadPeriodRad(r, c.bearing, false);
    const int n = 3600;
    double sum = 0;
    for (int k = 0; k < n; ++k) sum += lcr::BearingSpinRate(r, c.bearing, period * k / n);
    EXPECT_NEAR(sum / n, expected, kQuadratureRelTol * expected);
    // The spin rate at the extremes of ρ: c = ±1 (roller on / opposite the eccentric side).
    EXPECT_NEAR(lcr::BearingSpinRate(r, c.bearing, 0.0), c.psi_rate * (a - b - rr) / rr, 1e-12);
  }
  EXPECT_NEAR(lcr::BearingSpinRate(r, lcr::LcrBearing::kEccentric, 0.3), 13.0 / 12, 1e-15);
}

// Each bearing's load repeats over its period: the output roller over 2π m_A n_B/(n_A m_B) =
// 2π·180/182, |G| over 2π lcm(12, 14)/(13·14) = 2π·6/13 (6 revolutions with a cam weight).
TEST(LcrLife, LoadsRepeatOverTheirPeriods) {
  const lcr::Reducer<double> r = LcrII();
  EXPECT_NEAR(lcr::LoadPeriodRad(r, lcr::LcrBearing::kOutputRoller, false), 2 * kPi * 180.0 / 182, 1e-15);
  EXPECT_NEAR(lcr::LoadPeriodRad(r, lcr::LcrBearing::kEccentric, false), 2 * kPi * 6.0 / 13, 1e-15);
  EXPECT_NEAR(lcr::LoadPeriodRad(r, lcr::LcrBearing::kEccentric, true), 2 * kPi * 6.0, 1e-12);
  const Material m = camopt::testing::Steel();
  const lcr::LoadCase load{80e3, 0.05, 0.0};
  const double p_out = lcr::LoadPeriodRad(r, lcr::LcrBearing::kOutputRoller, false);
  const double p_ecc = lcr::LoadPeriodRad(r, lcr::LcrBearing::kEccentric, false);
  for (double theta : {0.1, 0.7, 2.3}) {
    const auto a = lcr::LoadsAtAngle(r, m, load, lcr::LoadModel::kRigid, theta);
    const auto b = lcr::LoadsAtAngle(r, m, load, lcr::LoadModel::kRigid, theta + p_out);
    EXPECT_NEAR(a.output_force_N[0], b.output_force_N[0], 1e-9 * 1000);
    const auto c = lcr::LoadsAtAngle(r, m, load, lcr::LoadModel::kRigid, theta + p_ecc);
    EXPECT_NEAR(a.eccentric_load_N.norm(), c.eccentric_load_N.norm(), 1e-9 * 1000);
    EXPECT_NEAR(a.input_torque_Nmm, c.input_torque_Nmm, 1e-9 * 1000);
  }
}

// The structure-of-arrays path of the bearing loads (lcr::RigidRollerZeroLoads, used by
// SampleBearingLoad under the rigid law) gives exactly the numbers of the per-angle analysis it
// replaces (LoadsAtAngle and BearingSpinRate), at the sampled angles and at any others, with and
// without friction, cam weight and torque.
TEST(LcrLife, RigidRollerZeroLoadsAreThePerAngleAnalysisBitForBit) {
  const lcr::Reducer<double> r = LcrII();
  const Material m = camopt::testing::Steel();
  std::vector<double> theta;
  for (int k = 0; k < 97; ++k) theta.push_back(2 * kPi * 1.37 * k / 97 - 0.4);
  for (const lcr::LoadCase load : {lcr::LoadCase{80e3, 0.05, 0.0}, lcr::LoadCase{80e3, 0.0, 0.0},
                                   lcr::LoadCase{12e3, 0.08, 35.0}, lcr::LoadCase{0.0, 0.05, 10.0}}) {
    const lcr::RollerZeroLoads z = lcr::RigidRollerZeroLoads(r, load, theta);
    ASSERT_EQ(z.input_force_N.size(), theta.size());
    for (size_t k = 0; k < theta.size(); ++k) {
      const lcr::LcrAngleLoads a = lcr::LoadsAtAngle(r, m, load, lcr::LoadModel::kRigid, theta[k]);
      EXPECT_EQ(z.input_force_N[k], a.input_force_N[0]) << k;
      EXPECT_EQ(z.output_force_N[k], a.output_force_N[0]) << k;
      EXPECT_EQ(z.eccentric_load_N[k].x(), a.eccentric_load_N.x()) << k;
      EXPECT_EQ(z.eccentric_load_N[k].y(), a.eccentric_load_N.y()) << k;
      EXPECT_EQ(z.input_torque_Nmm[k], a.input_torque_Nmm) << k;
      EXPECT_EQ(z.input_spin_rate[k], lcr::BearingSpinRate(r, lcr::LcrBearing::kInputRoller, theta[k])) << k;
      EXPECT_EQ(z.output_spin_rate[k], lcr::BearingSpinRate(r, lcr::LcrBearing::kOutputRoller, theta[k])) << k;
    }
  }
  // Loaded somewhere: the comparison is not of zeros.
  const lcr::RollerZeroLoads z = lcr::RigidRollerZeroLoads(r, lcr::LoadCase{80e3, 0.05, 0.0}, theta);
  EXPECT_GT(*std::max_element(z.input_force_N.begin(), z.input_force_N.end()), 100.0);
  EXPECT_GT(*std::max_element(z.output_force_N.begin(), z.output_force_N.end()), 100.0);
}

// The sweep of the lubricated cycle's loads (lcr::RigidLoadsSweep) gives exactly AnalyzeAngle's
// contacts, forces and eccentric load, angle after angle with its vectors reused, on LCR II and on
// a design with other counts.
TEST(LcrLife, RigidLoadsSweepIsAnalyzeAngleBitForBit) {
  for (const lcr::Reducer<double>& r : {LcrII(), camopt::testing::LcrI()}) {
    const Material m = camopt::testing::Steel();
    for (const lcr::LoadCase load : {lcr::LoadCase{80e3, 0.0, 0.0}, lcr::LoadCase{12e3, 0.08, 35.0}}) {
      lcr::RigidLoadsSweep sweep(r, load);
      for (int k = 0; k < 61; ++k) {
        const double theta = 2 * kPi * k / 61 + 0.01;
        sweep.At(theta);
        const lcr::AngleLoads<double> a = lcr::AnalyzeAngle(r, m, load, theta, {true, false, true});
        EXPECT_EQ(sweep.eccentric_load_N.x(), a.eccentric_load.x()) << k;
        EXPECT_EQ(sweep.eccentric_load_N.y(), a.eccentric_load.y()) << k;
        for (auto [contacts, forces, side] : {std::tuple{&sweep.input_contacts, &sweep.input_force_N, &a.input},
                                              std::tuple{&sweep.output_contacts, &sweep.output_force_N, &a.output}}) {
          ASSERT_EQ(contacts->size(), side->contacts.size());
          ASSERT_EQ(forces->size(), side->force.size());
          for (size_t j = 0; j < contacts->size(); ++j) {
            const lcr::RollerContact<double>& x = (*contacts)[j];
            const lcr::RollerContact<double>& y = side->contacts[j];
            EXPECT_TRUE(x.centre == y.centre && x.direction == y.direction && x.point == y.point) << k << " " << j;
            EXPECT_EQ(x.arm, y.arm) << k << " " << j;
            EXPECT_EQ(x.curvature, y.curvature) << k << " " << j;
            EXPECT_EQ((*forces)[j], side->force[j]) << k << " " << j;
          }
        }
      }
    }
  }
}

// The input roller's equivalent load from the study against the same p-mean written out here from
// the force series of the existing analysis (roller 0 of the fixed turret over one revolution,
// AnalyzeCycle) and the closed-form spin weights ψ' (ρ(θ) − r_r)/r_r, ρ² = A² + B² − 2AB cos θ.
TEST(LcrLife, InputRollerEquivalentLoadIsTheRevolutionWeightedMean) {
  nlohmann::json study = LifeStudy();
  study["analysis"]["angle_steps"] = 720;
  const auto res = RunStudy(study);
  const double a = 37, b = 26, rr = 6, p = 10.0 / 3;
  double num = 0, den = 0;
  for (size_t i = 0; i < res.series.theta_rad.size(); ++i) {
    const double f = res.series.input.roller_force_N.row(i)[0];
    const double w = (std::sqrt(a * a + b * b - 2 * a * b * std::cos(res.series.theta_rad[i])) - rr) / rr;
    num += w * std::pow(f, p);
    den += w;
  }
  const double expected = std::pow(num / den, 1 / p);
  EXPECT_NEAR(Bearing(res, "input_roller").equivalent_load_N, expected, kHandCalcRelTol * expected);
  // The rigid law spreads the torque over 6–7 rollers: the equivalent load lies below the largest.
  EXPECT_LT(Bearing(res, "input_roller").equivalent_load_N, res.input_cam.max_roller_force_N);
}

// A two-line duty cycle by hand. Under the rigid load law (forces.h: F_k = C |a_k|, C ∝ T_o) every
// roller force is proportional to the output torque, so line i's equivalent load is
// P_i = (T_i/T_1) P_1 with P_1 from the one-line study at T_1; a bearing turning R times per input
// revolution turns t_i n_i R per minute on line i, and Palmgren–Miner gives
//   1/L10h = Σ_i t_i · 60 n_i R (P_i/C)^p / 10⁶,   P = (Σ t_i n_i P_i^p / Σ t_i n_i)^(1/p).
TEST(LcrLife, TwoLineDutyCycleByHand) {
  nlohmann::json one = LifeStudy();
  one["analysis"]["angle_steps"] = 720;
  const auto r1 = RunStudy(one);
  nlohmann::json two = one;
  two["load"].erase("input_speed_rpm");
  two["duty_cycle"] = {{{"output_torque_Nm", 80}, {"input_speed_rpm", 1000}, {"time_share", 0.3}},
                       {{"output_torque_Nm", 40}, {"input_speed_rpm", 2000}, {"time_share", 0.7}}};
  const auto r2 = RunStudy(two);
  for (const char* name : {"input_roller", "output_roller", "eccentric_bearing"}) {
    SCOPED_TRACE(name);
    const auto& b1 = Bearing(r1, name);
    const auto& b2 = Bearing(r2, name);
    const double c = b1.rating.dynamic_N, rev = b1.revolutions_per_input_revolution;
    const double p = b1.rating.kind == BearingKind::kBall ? 3.0 : 10.0 / 3;
    // One line: L10h = 10⁶ (C/P)^p / (60 n R).
    const double l1 = 1e6 * std::pow(c / b1.equivalent_load_N, p) / (60 * 1000 * rev);
    EXPECT_NEAR(b1.L10h, l1, kHandCalcRelTol * l1);
    EXPECT_NEAR(b1.mean_speed_rpm, 1000 * rev, 1e-9 * 1000);
    // Two lines: P_1 = P, P_2 = P/2 (linear in torque; the eccentric has no cam weight here).
    const double pa = b1.equivalent_load_N, pb = 0.5 * b1.equivalent_load_N;
    EXPECT_NEAR(b2.line_equivalent_load_N[0], pa, kHandCalcRelTol * pa);
    EXPECT_NEAR(b2.line_equivalent_load_N[1], pb, kHandCalcRelTol * pa);
    const double damage = 0.3 * 60 * 1000 * rev * std::pow(pa / c, p) / 1e6 + 0.7 * 60 * 2000 * rev * std::pow(pb / c, p) / 1e6;
    EXPECT_NEAR(b2.L10h, 1 / damage, kHandCalcRelTol / damage);
    const double p_eq = std::pow((0.3 * 1000 * std::pow(pa, p) + 0.7 * 2000 * std::pow(pb, p)) / (0.3 * 1000 + 0.7 * 2000), 1 / p);
    EXPECT_NEAR(b2.equivalent_load_N, p_eq, kHandCalcRelTol * p_eq);
    EXPECT_NEAR(b2.mean_speed_rpm, (0.3 * 1000 + 0.7 * 2000) * rev, 1e-9 * 1000);
    // s0 = C0 / (largest load of either line): the 80 N·m line.
    EXPECT_NEAR(b2.s0, b1.rating.static_N / b1.max_load_N, 1e-12 * b2.s0);
  }
  // The input torque is linear in the output torque too (no cam weight): each line's energy
  // efficiency is the same, so the energy-weighted mean is the one line's.
  EXPECT_NEAR(r2.life->efficiency_energy_mean, r1.life->efficiency_energy_mean, 1e-12);
  EXPECT_NEAR(r2.life->line_mean_input_torque_Nm[1], 0.5 * r2.life->line_mean_input_torque_Nm[0], 1e-12);
  // Energy-weighted: η = T_o / (|r_i| T̄_in) of the line.
  EXPECT_NEAR(r1.life->efficiency_energy_mean, 80.0 / (90 * r1.life->line_mean_input_torque_Nm[0]), 1e-12);
  double shortest = kInf;
  for (const auto& b : r2.life->bearings) shortest = std::min(shortest, b.L10h);
  EXPECT_EQ(r2.life->shortest_L10h, shortest);
}

// A single torque and speed is the one-line duty cycle, under either load model.
TEST(LcrLife, OneLineDutyCycleEqualsTorqueAndSpeed) {
  for (const char* model : {"rigid", "compliant"}) {
    SCOPED_TRACE(model);
    nlohmann::json one = LifeStudy();
    one["analysis"]["angle_steps"] = 180;
    one["analysis"]["load_model"] = model;
    nlohmann::json dc = one;
    dc["load"].erase("input_speed_rpm");
    dc["duty_cycle"] = {{{"output_torque_Nm", 80}, {"input_speed_rpm", 1000}, {"time_share", 1}}};
    const auto a = RunStudy(one), b = RunStudy(dc);
    const auto ja = studies::WriteResult(a)["life"];
    const auto jb = studies::WriteResult(b)["life"];
    EXPECT_EQ(ja, jb);
    EXPECT_TRUE(std::isfinite(a.life->shortest_L10h));
  }
}

// LCR II at the paper's torque (80 N·m, its Table 3) and the speed of its tests (900 rpm, Table 4):
// every bearing's L10h by hand from its own equivalent load and revolutions, 10⁶ (C/P)^p / (60 n R),
// and 10/9 of the lives at 1000 rpm (the loads do not depend on the speed; docs/life.md, "LCR").
TEST(LcrLife, PapersTorqueAndTestSpeedGiveEveryBearingsLifeByHand) {
  nlohmann::json s = LifeStudy();
  s["load"]["input_speed_rpm"] = 900;
  const studies::lcr_analysis::Result at900 = RunStudy(s);
  const studies::lcr_analysis::Result at1000 = RunStudy(LifeStudy());
  ASSERT_TRUE(at900.life && at1000.life);
  ASSERT_EQ(at900.life->bearings.size(), 3u);
  for (const auto& b : at900.life->bearings) {
    SCOPED_TRACE(b.name);
    const double p = b.rating.kind == BearingKind::kBall ? 3.0 : 10.0 / 3.0;
    const double hand = 1e6 * std::pow(b.rating.dynamic_N / b.equivalent_load_N, p) /
                        (60.0 * 900.0 * b.revolutions_per_input_revolution);
    EXPECT_NEAR(b.L10h, hand, kHandCalcRelTol * hand);
    const double l1000 = Bearing(at1000, b.name).L10h;
    EXPECT_NEAR(b.L10h, l1000 * 1000.0 / 900.0, kHandCalcRelTol * l1000);
  }
}

TEST(LcrLife, StudyWithoutSpeedHasNoLife) {
  nlohmann::json s = nlohmann::json::parse(ReadFile(SourcePath("studies/examples/lcr_ii.json")));
  s["analysis"]["angle_steps"] = 72;
  const studies::Node root(&s, "s.json", "");
  const auto st = studies::lcr_analysis::Parse(root);
  EXPECT_FALSE(st.life.has_value());
  EXPECT_FALSE(studies::WriteResult(studies::lcr_analysis::Run(st, {"s.json", true})).contains("life"));
}

TEST(LcrLife, BadInputExitsTwoNamingThePath) {
  nlohmann::json base = LifeStudy();
  base["analysis"]["angle_steps"] = 72;
  base["load"].erase("input_speed_rpm");
  base["duty_cycle"] = {{{"output_torque_Nm", 80}, {"input_speed_rpm", 1000}, {"time_share", 0.5}},
                        {{"output_torque_Nm", 40}, {"input_speed_rpm", 2000}, {"time_share", 0.4}}};
  ExpectStudyRejected(base, "life-shares", "/duty_cycle", "time shares summing to 1");
  nlohmann::json s = base;
  s["duty_cycle"][1]["time_share"] = 0.5;
  s["duty_cycle"][1]["input_speed_rpm"] = -500;
  ExpectStudyRejected(s, "life-speed", "/duty_cycle/1/input_speed_rpm", "expected");
  s["duty_cycle"][0]["input_speed_rpm"] = 0;
  s["duty_cycle"][1]["input_speed_rpm"] = 0;
  ExpectStudyRejected(s, "life-no-speed", "/duty_cycle", "input_speed_rpm > 0");
  s = base;
  s["duty_cycle"][1]["time_share"] = 0.5;
  s["reducer"]["output"].erase("dynamic_rating_N");
  ExpectStudyRejected(s, "life-no-c", "/reducer/output/dynamic_rating_N", "dynamic load rating C");
  s = base;
  s["duty_cycle"][1]["time_share"] = 0.5;
  s["load"]["input_speed_rpm"] = 1000;
  ExpectStudyRejected(s, "life-both", "/load/input_speed_rpm", "one or the other");
  s = LifeStudy();
  s["load"]["input_speed_rpm"] = 0;
  ExpectStudyRejected(s, "life-zero-speed", "/load/input_speed_rpm", "expected");
  s = LifeStudy();
  s["reducer"]["eccentric_bearing"]["kind"] = "needle";
  ExpectStudyRejected(s, "life-kind", "/reducer/eccentric_bearing/kind", "ball, roller");
}

}  // namespace lcr_life_test
}  // namespace camopt
