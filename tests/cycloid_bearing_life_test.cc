// Tests of the cycloid stage's bearing loads (model/cycloid/bearing_loads.h): the output pins'
// forces against their closed forms, the contact normals through the pitch point, the rollers'
// spin against a finite difference of the contact's travel and the elliptic-integral mean, the
// crank bearing's force against the moment and power balances, and a two-line duty cycle by hand.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/cycloid/bearing_loads.h"
#include "studies/cycloid_ltca_study.h"
#include "studies/input.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt::cycloid {
namespace cycloid_bearing_life_test {

Drive Nnm() { return camopt::testing::CycloidNnm(); }  // the paper's drive with its NNM modification
Drive Unmodified() {
  Drive d = Nnm();
  d.delta_position_mm = 0.0;
  d.delta_radius_mm = 0.0;
  return d;
}

LoadedOptions Coarse() {
  LoadedOptions o;
  o.profile_cells = 16;
  o.axial_cells = 16;
  o.crank_slope = false;
  return o;
}

TEST(CycloidBearingLoads, FourOutputPinsMatchTheirClosedForm) {
  // N_w = 4 with pin 0 at α from the crank: pins 0 and 1 (sin α, cos α) carry load, Σ sin² = 1,
  // so Q_max = T/R_w and the resultant is T (sin α + cos α)/R_w.
  const OutputMechanism m{4, 60.0};
  const double torque = 350e3, alpha = 0.3;
  const int n2 = 15;
  const double crank = -alpha * n2 / (n2 + 1.0);  // φ_0 = −φ n1/n2 = α
  std::vector<double> q;
  const double resultant = OutputPinResultant<double>(m, n2, torque, crank, &q);
  ASSERT_EQ(q.size(), 4u);
  EXPECT_NEAR(resultant, torque * (std::sin(alpha) + std::cos(alpha)) / 60.0, 1e-9);
  EXPECT_NEAR(q[0], torque * std::sin(alpha) / 60.0, 1e-9);
  EXPECT_NEAR(q[1], torque * std::cos(alpha) / 60.0, 1e-9);
  EXPECT_EQ(q[2], 0.0);
  EXPECT_EQ(q[3], 0.0);
}

TEST(CycloidBearingLoads, OutputPinsBalanceTheTorqueAndTendToTheContinuousLimit) {
  const double torque = 350e3, rw = 60.0;
  for (int pins : {3, 8, 10, 13})
    for (double crank : {0.0, 0.11, 1.7, 4.0}) {
      std::vector<double> q;
      OutputPinResultant<double>({pins, rw}, 15, torque, crank, &q);
      double moment = 0.0;
      for (int j = 0; j < pins; ++j) moment += q[j] * rw * std::sin(2 * kPi * j / pins - crank * 16.0 / 15.0);
      EXPECT_NEAR(moment, torque, 1e-9 * torque) << pins << " pins at " << crank;
    }
  // Exact finite sum with a pin on the crank line (φ = 0), N_w = 2M even: Σ_{j=0}^{M} sin(πj/M) =
  // cot(π/N_w) and Σ sin² = N_w/4, so the resultant is (4T/(N_w R_w)) cot(π/N_w).
  for (int pins : {4, 8, 12, 400}) {
    const double exact = 4.0 * torque / (pins * rw) / std::tan(kPi / pins);
    EXPECT_NEAR(OutputPinResultant<double>({pins, rw}, 15, torque, 0.0), exact, 1e-9 * exact) << pins;
  }
  // Continuous limit 4T/(π R_w): cot(π/N)·4/N = (4/π)(1 − π²/(3N²) + …).
  const double limit = 4.0 * torque / (kPi * rw);
  EXPECT_DOUBLE_EQ(OutputPinResultant<double>({0, rw}, 15, torque, 0.7), limit);
  EXPECT_NEAR(OutputPinResultant<double>({400, rw}, 15, torque, 0.0) / limit, 1.0 - kPi * kPi / (3.0 * 400 * 400), 1e-9);
  EXPECT_EQ(OutputPinPeriodInMeshPeriods({8, rw}, 15), 15);
  EXPECT_EQ(OutputPinPeriodInMeshPeriods({10, rw}, 15), 3);
  EXPECT_EQ(OutputPinPeriodInMeshPeriods({0, rw}, 15), 1);
  EXPECT_THROW(OutputPinResultant<double>({2, rw}, 15, torque, 0.0), std::invalid_argument);
  EXPECT_THROW(OutputPinResultant<double>({8, 0.0}, 15, torque, 0.0), std::invalid_argument);
}

TEST(CycloidBearingLoads, ContactNormalsPassThroughThePitchPoint) {
  // Unmodified tooth: the conjugate normal passes through I exactly. NNM (Δa −16, Δρ −8 µm) moves
  // each contact along the tooth (t by up to 1e-3 rad) and its normal off I: on the pairs that can
  // carry load (backlash below 20″) by less than 0.65 mm, 1% of the pitch radius n2 e = 67.5 mm
  // (measured 0.004–0.60 mm at 0°, 7°, 13°, 120°; the largest beyond the first-contact pair); by up to 1.2 mm at the nearly unloaded pairs
  // near a tip. The forces use the true normals either way.
  double worst_loaded = 0.0;
  for (double deg : {0.0, 7.0, 13.0, 120.0}) {
    const double crank = deg * kPi / 180.0;
    for (const Drive& d : {Unmodified(), Nnm()}) {
      const UnloadedMesh<double> u = UnloadedTca<double>(d, crank);
      const Vec2<double> pitch = PitchPointInDisc(d, crank, 0.0);
      for (const auto& g : u.pairs) {
        if (!g.loaded_flank) continue;
        const double miss = std::abs(Cross(Vec2<double>(pitch - g.point), g.normal));
        if (d.delta_position_mm == 0.0) EXPECT_LT(miss, 1e-9) << "roller " << g.roller << " at " << deg;
        else if (g.backlash < 20.0 / 206264.8) worst_loaded = std::max(worst_loaded, miss);
      }
    }
  }
  EXPECT_GT(worst_loaded, 0.0);
  EXPECT_LT(worst_loaded, 0.65);
}

TEST(CycloidBearingLoads, RollerSpinMatchesTheContactTravelAndTheEllipticMean) {
  const Drive d = Unmodified();
  const double a = d.roller_position_radius_mm, e = d.eccentricity_mm, rho = d.roller_radius_mm;
  const int n1 = d.rollers, n2 = d.teeth;
  // No slip: the contact point's velocity relative to the disc equals that relative to the roller,
  // R(θ_d) dP/dφ = ρ (dθ_c/dφ − ω_r) J û_c, θ_c the angle of û_c = C − O_i (fixed frame), θ_d = −φ/n2.
  // Central differences of the unloaded TCA's contact point P (disc frame) give ω_r.
  const double h = 1e-5;
  for (int i : {0, 3, 7, 12})
    for (double crank : {0.2, 1.0, 2.5}) {
      auto contact = [&](double phi, Vec2<double>* p_disc, double* theta_c) {
        const PairGeometry<double> g = SolvePair(d, i, phi);
        *p_disc = g.point;
        const Vec2<double> n_fixed = Rotate(g.normal, -phi / n2);
        *theta_c = std::atan2(-n_fixed.y(), -n_fixed.x());
      };
      Vec2<double> pp, pm;
      double tp, tm;
      contact(crank + h, &pp, &tp);
      contact(crank - h, &pm, &tm);
      double dtheta = tp - tm;
      dtheta -= 2 * kPi * std::round(dtheta / (2 * kPi));
      const Vec2<double> dp = Rotate(Vec2<double>((pp - pm) / (2 * h)), -crank / n2);
      const PairGeometry<double> g = SolvePair(d, i, crank);
      const Vec2<double> uc = Rotate(Vec2<double>(-g.normal), -crank / n2);
      const double omega = dtheta / (2 * h) - dp.dot(Perp(uc)) / rho;
      EXPECT_NEAR(RollerSpinRate(d, g, crank), std::abs(omega), 1e-6) << "roller " << i << " at " << crank;
      // The closed form (S − ρ)/(n2 ρ), S = |O_i − I|.
      const double s = std::sqrt(a * a + n1 * e * n1 * e - 2 * a * n1 * e * std::cos(2 * kPi * i / n1 - crank));
      EXPECT_NEAR(RollerSpinRate(d, g, crank), (s - rho) / (n2 * rho), 1e-12);
    }
  // Over one mesh period at N angles, the (angle, roller) samples are one roller's at N n1 uniform
  // phases: their mean is (⟨S⟩ − ρ)/(n2 ρ), ⟨S⟩ = (2/π)(A + B) E(2√(AB)/(A + B)), A = a, B = n1 e.
  std::vector<MeshLoad> meshes;
  for (double phi : UniformCrankAngles(8, 2 * kPi / n1)) {
    MeshLoad m;
    m.crank_angle_rad = phi;
    meshes.push_back(m);
  }
  const PinLoadSamples x = PinBearingLoads(d, meshes);
  ASSERT_EQ(x.spin_rate.size(), size_t(8 * n1));
  double mean = 0.0;
  for (double w : x.spin_rate) mean += w / x.spin_rate.size();
  const double A = a, B = n1 * e;
  const double s_mean = 2.0 / kPi * (A + B) * std::comp_ellint_2(2 * std::sqrt(A * B) / (A + B));
  EXPECT_NEAR(mean, (s_mean - rho) / (n2 * rho), 1e-10);
  EXPECT_DOUBLE_EQ(CrankBearingRevolutionsPerInputRevolution(d), 16.0 / 15.0);
}

TEST(CycloidBearingLoads, CrankBearingForceBalancesTheMomentAndThePower) {
  // At one solved mesh: the ring-pin forces' moment about the disc centre is −T (equilibrium,
  // eq. 25, to the compatibility tolerance), and, the normals passing through the pitch point
  // n2 e from the disc centre on the crank line, the bearing's force across the crank is T/(n2 e):
  // the input torque e·B_y = T/n2 of a frictionless drive.
  const double torque = 350e3;
  for (const Drive& d : {Unmodified(), Nnm()}) {
    const LoadedTca tca(d, Crowning{}, Material{}, Coarse());
    for (double deg : {0.0, 9.0, 120.0}) {
      const MeshLoad m = tca.Solve(torque, deg * kPi / 180.0);
      ASSERT_TRUE(m.converged) << m.message;
      double moment = 0.0;
      const Vec2<double> g = RingPinResultantCrankFrame(d, m, &moment);
      EXPECT_NEAR(moment, -torque, 1e-3 * torque) << deg;
      const Vec2<double> b = CrankBearingForce(g, OutputPinResultant<double>({0, 60.0}, d.teeth, torque, m.crank_angle_rad));
      const double across = torque / (d.teeth * d.eccentricity_mm);
      EXPECT_NEAR(b.y(), across, (d.delta_position_mm == 0.0 ? 2e-3 : 1e-2) * across) << deg;
      // Along the crank: the output pins' 4T/(π R_w) minus the ring pins' radial resultant.
      EXPECT_NEAR(b.x(), 4 * torque / (kPi * 60.0) - g.x(), 1e-9 * torque);
    }
  }
}

TEST(CycloidBearingLoads, TwoLineDutyCycleByHand) {
  // Crank bearing samples of two lines (uniform weights) and a hand Palmgren–Miner sum.
  const Drive d = Nnm();
  const LoadedTca tca(d, Crowning{}, Material{}, Coarse());
  const std::vector<double> angles = UniformCrankAngles(4, 2 * kPi / d.rollers);
  const OutputMechanism m{8, 60.0};
  std::vector<BearingLineSamples> lines;
  const double torques[2] = {350e3, 150e3}, speeds[2] = {1000.0, 2000.0}, shares[2] = {0.25, 0.75};
  double hand_damage = 0.0;
  const double c = 80000.0, p = 10.0 / 3.0, r = 16.0 / 15.0;
  std::vector<double> hand_p;
  for (int i = 0; i < 2; ++i) {
    const CycleResult cycle = RunCycle(tca, torques[i], angles);
    const std::vector<double> loads = CrankBearingLoads(d, m, cycle.meshes, torques[i]);
    ASSERT_EQ(loads.size(), 4u * 15u);  // 8 pins: the load repeats every 15 mesh periods
    double sum = 0.0;
    for (double f : loads) sum += std::pow(f, p);
    hand_p.push_back(std::pow(sum / loads.size(), 1.0 / p));
    hand_damage += shares[i] * 60.0 * speeds[i] * r * std::pow(hand_p[i] / c, p) / 1e6;
    lines.push_back({shares[i], speeds[i], loads, std::vector<double>(loads.size(), 1.0)});
  }
  const BearingLifeOverCycle life = LifeOverDutyCycle(c, BearingKind::kRoller, r, lines);
  EXPECT_NEAR(life.line_equivalent_load_N[0], hand_p[0], 1e-9 * hand_p[0]);
  EXPECT_NEAR(life.line_equivalent_load_N[1], hand_p[1], 1e-9 * hand_p[1]);
  EXPECT_NEAR(life.L10h, 1.0 / hand_damage, 1e-9 / hand_damage);
  const double n_mean = 0.25 * 1000 + 0.75 * 2000;
  const double p_hand = std::pow((0.25 * 1000 * std::pow(hand_p[0], p) + 0.75 * 2000 * std::pow(hand_p[1], p)) / n_mean, 1 / p);
  EXPECT_NEAR(life.equivalent_load_N, p_hand, 1e-9 * p_hand);
  EXPECT_NEAR(life.mean_speed_rpm, r * n_mean, 1e-9);
  // The crank bearing's load is at least its component across the crank, T/(n2 e) = 5185 N at 350 N·m.
  EXPECT_GT(hand_p[0], 0.99 * 350e3 / (15 * 4.5));
}

// ---- the cycloid_ltca study's life (docs/life.md, "Cycloid") ------------------------------------

/// Hand calculations from the study's own per-line numbers: a few roundings of pow.
constexpr double kHandCalcRelTol = 1e-9;

nlohmann::json LifeExample() {
  nlohmann::json j = nlohmann::json::parse(
      camopt::testing::ReadFile(camopt::testing::SourcePath("studies/examples/cycloid_ltca_life.json")));
  // Coarse and fast: the hand checks hold at any sampling.
  j["analysis"] = {{"crank_angles_per_mesh_period", 4}, {"grid", {12, 12}}, {"estimate_error", false}};
  return j;
}

nlohmann::json RunLife(const nlohmann::json& study) {
  const studies::Node root(&study, "life.json", "");
  const auto s = studies::cycloid_ltca::Parse(root);
  return studies::WriteResult(studies::cycloid_ltca::Run(s, {"life.json", true}));
}

const nlohmann::json& Row(const nlohmann::json& life, const std::string& element) {
  for (const auto& r : life["table"])
    if (r["element"] == element) return r;
  throw std::runtime_error("no row " + element);
}

TEST(CycloidLife, ExampleLivesByHand) {
  const nlohmann::json j = RunLife(LifeExample());
  ASSERT_TRUE(j.contains("life"));
  const nlohmann::json& life = j["life"];
  // Lines: (t, n, T) = (0.6, 1500, 350), (0.3, 3000, 150), (0.1, 0, 450): 1/L10h = Σ t_i 60 n_i R
  // (P_i/C)^p / 10⁶ with the study's P_i; the standing line adds no damage but sets s0.
  const double t[3] = {0.6, 0.3, 0.1}, n[3] = {1500, 3000, 0};
  for (const char* element : {"crank_bearing", "pins"}) {
    const nlohmann::json& row = Row(life, element);
    const double c = row["dynamic_rating_N"], c0 = row["static_rating_N"], r = row["revolutions_per_input_revolution"];
    const double p = 10.0 / 3.0;
    double damage = 0.0;
    for (int i = 0; i < 3; ++i)
      damage += t[i] * 60.0 * n[i] * r * std::pow(row["line_equivalent_load_N"][i].get<double>() / c, p) / 1e6;
    EXPECT_NEAR(row["L10h"].get<double>(), 1.0 / damage, kHandCalcRelTol / damage) << element;
    EXPECT_NEAR(life[std::string(element) + "_L10h"].get<double>(), 1.0 / damage, kHandCalcRelTol / damage);
    EXPECT_NEAR(row["s0"].get<double>(), c0 / row["max_load_N"].get<double>(), 1e-12) << element;
    EXPECT_TRUE(row["pass"].is_null());
    // 450 N·m standing loads more than 350 N·m turning.
    EXPECT_GT(row["line_equivalent_load_N"][2].get<double>(), row["line_equivalent_load_N"][0].get<double>());
    EXPECT_GT(row["line_equivalent_load_N"][0].get<double>(), row["line_equivalent_load_N"][1].get<double>());
  }
  EXPECT_DOUBLE_EQ(Row(life, "crank_bearing")["revolutions_per_input_revolution"].get<double>(), 16.0 / 15.0);
  // Pins: the mean spin (S − ρ)/(n2 ρ) of the unmodified tooth (elliptic mean); NNM moves the
  // contact by micrometres.
  const double a = 90, e = 4.5, rho = 7.2, A = a, B = 16 * e;
  const double s_mean = 2.0 / kPi * (A + B) * std::comp_ellint_2(2 * std::sqrt(A * B) / (A + B));
  EXPECT_NEAR(Row(life, "pins")["revolutions_per_input_revolution"].get<double>(), (s_mean - rho) / (15 * rho), 1e-4);
  EXPECT_EQ(life["shortest_bearing"],
            Row(life, "pins")["L10h"].get<double>() < Row(life, "crank_bearing")["L10h"].get<double>() ? "pins"
                                                                                                         : "crank_bearing");
  EXPECT_DOUBLE_EQ(life["mean_input_speed_rpm"].get<double>(), 0.6 * 1500 + 0.3 * 3000);
  EXPECT_TRUE(life["efficiency_energy_mean"].is_null());
  EXPECT_EQ(life["duty_cycle"].size(), 3u);
  EXPECT_EQ(life["crank_bearing_samples_per_line"], 4 * 15);  // 4 angles × the 15 mesh periods of 8 pins
}

TEST(CycloidLife, OneLineDutyCycleEqualsTorqueAndSpeed) {
  nlohmann::json speed = LifeExample();
  speed.erase("duty_cycle");
  speed["load"]["input_speed_rpm"] = 1200;
  nlohmann::json duty = LifeExample();
  duty["duty_cycle"] = {{{"output_torque_Nm", 350}, {"input_speed_rpm", 1200}, {"time_share", 1.0}}};
  const nlohmann::json a = RunLife(speed)["life"], b = RunLife(duty)["life"];
  EXPECT_EQ(a["table"], b["table"]);
  // L10h = 10⁶ (C/P)^p / (60 n R) for one line.
  const nlohmann::json& row = Row(a, "crank_bearing");
  const double expected = 1e6 * std::pow(row["dynamic_rating_N"].get<double>() / row["equivalent_load_N"].get<double>(),
                                         10.0 / 3.0) / (60.0 * 1200 * 16.0 / 15.0);
  EXPECT_NEAR(row["L10h"].get<double>(), expected, kHandCalcRelTol * expected);
}

TEST(CycloidLife, ContinuousOutputMechanismIsTheLimitOfManyPins) {
  nlohmann::json few = LifeExample(), many = LifeExample(), continuous = LifeExample();
  many["output_mechanism"]["pin_count"] = 300;
  continuous["output_mechanism"].erase("pin_count");
  const double p_many = Row(RunLife(many)["life"], "crank_bearing")["equivalent_load_N"];
  const double p_cont = Row(RunLife(continuous)["life"], "crank_bearing")["equivalent_load_N"];
  const double p_few = Row(RunLife(few)["life"], "crank_bearing")["equivalent_load_N"];
  EXPECT_NEAR(p_many, p_cont, 1e-3 * p_cont);  // the resultant differs by π²/(3N²) of 4T/(πR_w)
  EXPECT_GT(std::abs(p_few - p_cont), 1e-4 * p_cont);  // eight pins are not the continuous limit
}

TEST(CycloidLife, StudyWithoutSpeedHasNoLife) {
  nlohmann::json j = LifeExample();
  j.erase("duty_cycle");
  EXPECT_FALSE(RunLife(j).contains("life"));
}

TEST(CycloidLife, BadInputExitsTwoNamingThePath) {
  using camopt::testing::ExpectStudyRejected;
  const nlohmann::json base = LifeExample();
  nlohmann::json s = base;
  s["duty_cycle"][0]["time_share"] = 0.5;
  ExpectStudyRejected(s, "cyc-life-shares", "/duty_cycle", "time shares summing to 1");
  s = base;
  s["duty_cycle"][1]["input_speed_rpm"] = -100;
  ExpectStudyRejected(s, "cyc-life-speed", "/duty_cycle/1/input_speed_rpm", "expected");
  s = base;
  s["crank_bearing"].erase("dynamic_rating_N");
  ExpectStudyRejected(s, "cyc-life-no-c", "/crank_bearing/dynamic_rating_N", "dynamic load rating C");
  s = base;
  s["pins"].erase("dynamic_rating_N");
  ExpectStudyRejected(s, "cyc-life-no-pin-c", "/pins/dynamic_rating_N", "dynamic load rating C");
  s = base;
  s.erase("crank_bearing");
  ExpectStudyRejected(s, "cyc-life-no-bearing", "/crank_bearing", "a life is asked");
  s = base;
  s.erase("output_mechanism");
  ExpectStudyRejected(s, "cyc-life-no-output", "/output_mechanism", "pin_circle_radius_mm");
  s = base;
  s["load"]["input_speed_rpm"] = 1000;
  ExpectStudyRejected(s, "cyc-life-both", "/load/input_speed_rpm", "one or the other");
  s = base;
  s["output_mechanism"]["pin_circle_radius_mm"] = 80;
  ExpectStudyRejected(s, "cyc-life-pin-circle", "/output_mechanism/pin_circle_radius_mm", "root radius");
  s = base;
  s["crank_bearing"]["kind"] = "needle";
  ExpectStudyRejected(s, "cyc-life-kind", "/crank_bearing/kind", "ball, roller");
  s = base;
  s["analysis"] = {{"crank_angles_deg", {0, 3, 10}}};
  ExpectStudyRejected(s, "cyc-life-angles", "/duty_cycle", "whole mesh periods");
}

TEST(CycloidLife, SizingLifeLimitNeedsTheSpeedAndRatings) {
  using camopt::testing::ExpectStudyRejected;
  const nlohmann::json base = nlohmann::json::parse(
      camopt::testing::ReadFile(camopt::testing::SourcePath("studies/examples/cycloid_min_size_ratio29_life.json")));
  nlohmann::json s = base;
  s.erase("load");
  ExpectStudyRejected(s, "cyc-size-life-no-speed", "/limits/life_h", "needs the speed");
  s = base;
  s["duty_cycle"] = {{{"output_torque_Nm", 20}, {"input_speed_rpm", 100}, {"time_share", 1.0}}};
  ExpectStudyRejected(s, "cyc-size-life-both", "/load/input_speed_rpm", "one or the other");
  s = base;
  s["crank_bearing"].erase("dynamic_rating_N");
  ExpectStudyRejected(s, "cyc-size-life-no-c", "/crank_bearing/dynamic_rating_N", "dynamic load rating C");
  s = base;
  s["limits"]["life_h"] = -5;
  ExpectStudyRejected(s, "cyc-size-life-negative", "/limits/life_h", "expected");
}

}  // namespace cycloid_bearing_life_test
}  // namespace camopt::cycloid
