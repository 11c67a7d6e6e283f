// The cycloid stage's lubricated losses (model/cycloid/lubrication.h): the ring pins' speeds against
// the bodies' rigid velocities, the power balance against the disc's statics with friction forces,
// the output pins' speeds, and metamorphic relations.
#include "model/cycloid/lubrication.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "tests/reference_designs.h"

namespace camopt::cycloid {
namespace cycloid_lubrication_test {

Drive Unmodified() {
  Drive d = testing::CycloidNnm();
  d.delta_position_mm = d.delta_radius_mm = 0.0;
  return d;
}

// The disc's velocity per crank radian at a fixed-frame point X: its centre D = e u(φ) moves at
// e u⊥(φ), it turns at −1/n2 (the ring stands).
Vec2<double> DiscVelocity(const Drive& d, double crank, const Vec2<double>& x) {
  const Vec2<double> centre = d.eccentricity_mm * U(crank);
  return Vec2<double>(d.eccentricity_mm * Perp(U(crank))) - Perp(Vec2<double>(x - centre)) / double(d.teeth);
}

TEST(CycloidLubrication, RingPinSpeedsAreThoseOfTheRigidBodies) {
  for (const Drive& d : {Unmodified(), testing::CycloidNnm()}) {
    const bool modified = d.delta_position_mm != 0.0;
    int checked = 0;
    for (double crank : {0.05, 0.4, 1.3, 2.9, 4.4}) {
      const UnloadedMesh<double> u = UnloadedTca<double>(d, crank);
      const double h = 1e-6;
      const UnloadedMesh<double> before = UnloadedTca<double>(d, crank - h), after = UnloadedTca<double>(d, crank + h);
      const double turn = -crank / d.teeth;
      for (int i = 0; i < d.rollers; ++i) {
        const PairGeometry<double>& g = u.pairs[size_t(i)];
        if (!g.converged || !g.loaded_flank || !before.pairs[size_t(i)].converged || !after.pairs[size_t(i)].converged)
          continue;
        const Vec2<double> c = d.eccentricity_mm * U(crank) + Rotate(g.point, turn);
        const Vec2<double> n = Rotate(g.normal, turn);
        const Vec2<double> ring_on_disc = -DiscVelocity(d, crank, c);  // the ring's point C against the disc's
        // Conjugate (unmodified) tooth: no relative motion along the normal; the modified one's
        // contact is off the conjugate point by microns.
        if (!modified) { EXPECT_NEAR(ring_on_disc.dot(n), 0.0, 1e-9 * (1 + ring_on_disc.norm())) << i; }
        const PinSpeeds<double> fixed = RingPinSpeeds(d, g, crank, false);
        EXPECT_NEAR(fixed.sliding, std::abs(ring_on_disc.dot(Perp(n))), 1e-9 * (1 + fixed.sliding)) << i;
        // The contact point's travel along the tooth (disc frame), by a central difference.
        const Vec2<double> travel = (after.pairs[size_t(i)].point - before.pairs[size_t(i)].point) / (2 * h);
        const PinSpeeds<double> rolling = RingPinSpeeds(d, g, crank, true);
        // (The modified tooth's unloaded contact is where the pair's gap closes first, not a conjugate
        // point: it also runs along the tooth with the gap-closing rotation, fast near a tip, which the
        // conjugate law of the entraining speed leaves out; the speeds' check is the unmodified tooth's.)
        if (!modified) {
          const double tol = 1e-6 * (1 + travel.norm());
          EXPECT_NEAR(rolling.entraining, travel.norm(), tol) << i;
          const Vec2<double> ring_in_disc = Rotate(ring_on_disc, -turn);
          EXPECT_NEAR(fixed.entraining, 0.5 * (ring_in_disc - 2.0 * travel).norm(), tol) << i;
        }
        EXPECT_EQ(rolling.sliding, 0.0);
        EXPECT_NEAR(rolling.spin, RollerSpinRate(d, g, crank), 1e-12);
        ++checked;
      }
    }
    EXPECT_GT(checked, 5 * d.rollers / 3);
  }
}

// Power balance of one disc with fixed ring pins and friction forces μ F at them: the ring pins'
// normal loads of the rigid law, the friction along the ring's motion relative to the disc, the
// output torque from the disc's moment balance (the output pins frictionless, their sine
// distribution scaled to it), the crank bearing's force from the disc's force balance and the input
// torque from the crank's; P_in − P_out = Σ μ F v_s with the model's sliding speeds, to rounding.
TEST(CycloidLubrication, InputLessOutputPowerIsTheSumOfTheSlidingLosses) {
  const Drive d = Unmodified();
  const OutputMechanism m{10, 60.0};
  const double mu = 0.07, torque = 500e3;
  for (int k = 0; k < 16; ++k) {
    const double crank = 2 * kPi * k / 16 + 0.021;
    const UnloadedMesh<double> u = UnloadedTca<double>(d, crank);
    const double turn = -crank / d.teeth;
    Vec2<double> ring(0.0, 0.0);
    double moment = 0.0, losses = 0.0;
    for (const auto& [i, f] : RigidRingPinLoads(d, torque, crank)) {
      const PairGeometry<double>& g = u.pairs[size_t(i)];
      const Vec2<double> c = d.eccentricity_mm * U(crank) + Rotate(g.point, turn);
      const Vec2<double> slide = -DiscVelocity(d, crank, c);
      const Vec2<double> on_disc = -f * Rotate(g.normal, turn) + mu * f * slide / slide.norm();
      ring += on_disc;
      moment += Cross(Vec2<double>(c - d.eccentricity_mm * U(crank)), on_disc);
      losses += mu * f * RingPinSpeeds(d, g, crank, false).sliding;
    }
    const double out_torque = -moment;  // the output pins' moment on the disc balances the ring's
    ASSERT_GT(out_torque, 0.0);
    const double q = OutputPinResultant<double>(m, d.teeth, out_torque, crank);
    const Vec2<double> bearing = -(ring - q * U(crank));                 // the crank bearing on the disc
    const double t_in = Cross(Vec2<double>(d.eccentricity_mm * U(crank)), bearing);  // the crank's balance
    EXPECT_NEAR(t_in - out_torque / d.teeth, losses, 1e-9 * t_in) << crank;
    EXPECT_GT(losses, 0.0);
  }
}

// The output pins: v_s = e Ω without a roller; a roller rolls with spin e Ω / r; Ω = n1/n2.
TEST(CycloidLubrication, OutputPinSpeedsByHand) {
  const Drive d = testing::CycloidNnm();
  const double omega = 16.0 / 15.0;
  const PinSpeeds<double> pin = OutputPinSpeeds(d, {8.0, 12.5, 0.0});
  EXPECT_DOUBLE_EQ(pin.sliding, 4.5 * omega);
  EXPECT_DOUBLE_EQ(pin.entraining, std::abs(4.5 - 16.0) * omega / 2);
  const PinSpeeds<double> roller = OutputPinSpeeds(d, {6.0, 14.5, 10.0});
  EXPECT_EQ(roller.sliding, 0.0);
  EXPECT_DOUBLE_EQ(roller.spin, 4.5 * omega / 10.0);
  EXPECT_DOUBLE_EQ(roller.entraining, 5.5 * omega);
}

CycloidLubricationSpec Spec(bool rotate) {
  CycloidLubricationSpec s;
  s.ring_pins_rotate = rotate;
  s.ring_pin_bearing = {3.0, 0.0005, 10.0};
  s.crank_bearing = {2.0, 0.0003, 40.0};
  return s;
}

// μ → 0 with no bearing friction: no loss; a thicker oil raises λ at the ring pins; the sliding loss of
// the boundary regime doubles with the speed.
TEST(CycloidLubrication, MetamorphicRelations) {
  const Drive d = Unmodified();
  const OutputMechanism m{10, 60.0};
  const std::optional<OutputPinContact> pins = OutputPinContact{8.0, 12.5, 0.0};
  const double e_star = Material{}.composite_modulus_MPa(), torque = 500e3;
  const double crank = 0.3;
  MeshLoad mesh;
  mesh.crank_angle_rad = crank;
  for (const auto& [i, f] : RigidRingPinLoads(d, torque, crank)) {
    PairLoad p;
    p.roller = i;
    p.load_N = f;
    p.effective_radius_mm = 6.0;
    mesh.pairs.push_back(p);
  }
  const MeshLubricationLoads x = LubricationLoadsAt(d, m, mesh, torque);
  CycloidLubricationSpec none = Spec(false);
  none.friction = {0.0, 0.0};
  none.crank_bearing.f0 = none.crank_bearing.f1 = 0.0;
  none.rolling_loss = false;  // the viscous rolling loss is no friction coefficient
  EXPECT_EQ(LossesAtCrankAngle(d, none, e_star, x, pins, 1500, 60).total(), 0.0);
  none.rolling_loss = true;
  const CycloidAngleLosses rolling = LossesAtCrankAngle(d, none, e_star, x, pins, 1500, 60);
  EXPECT_GT(rolling.ring_pins_rolling, 0.0);
  EXPECT_GT(rolling.output_pins_rolling, 0.0);
  EXPECT_EQ(rolling.total(), rolling.ring_pins_rolling + rolling.output_pins_rolling);
  double lambda = 0.0;
  for (double nu40 : {32.0, 68.0, 150.0}) {
    CycloidLubricationSpec s = Spec(true);
    s.oil.nu40_mm2_s = nu40;
    s.oil.nu100_mm2_s = nu40 / 8;
    const CycloidAngleLosses l = LossesAtCrankAngle(d, s, e_star, x, pins, 1500, 60);
    EXPECT_GT(l.min_lambda, lambda);
    lambda = l.min_lambda;
  }
  CycloidLubricationSpec rough = Spec(false);
  rough.composite_roughness_mm = 0.1;  // λ ≪ 1
  const CycloidAngleLosses one = LossesAtCrankAngle(d, rough, e_star, x, pins, 1000, 60);
  const CycloidAngleLosses two = LossesAtCrankAngle(d, rough, e_star, x, pins, 2000, 60);
  EXPECT_LT(two.min_lambda, 1.0);
  EXPECT_NEAR(two.ring_pins_sliding, 2 * one.ring_pins_sliding, 1e-12 * two.ring_pins_sliding);
  EXPECT_NEAR(two.output_pins_sliding, 2 * one.output_pins_sliding, 1e-12 * two.output_pins_sliding);
  // The rolling loss 2 u F_R with F_R ∝ u^0.658 on the same loads: × 2^1.658.
  EXPECT_NEAR(two.ring_pins_rolling, std::pow(2.0, 1.658) * one.ring_pins_rolling, 1e-12 * two.ring_pins_rolling);
  EXPECT_NEAR(two.output_pins_rolling, std::pow(2.0, 1.658) * one.output_pins_rolling, 1e-12 * two.output_pins_rolling);
  EXPECT_GT(one.output_pins_sliding, 0.0);
}

}  // namespace cycloid_lubrication_test
}  // namespace camopt::cycloid

#include "studies/cycloid_ltca_study.h"
#include "tests/test_util.h"

namespace camopt {
namespace cycloid_lubrication_test {

nlohmann::json CycloidLubricated() {
  nlohmann::json s =
      nlohmann::json::parse(testing::ReadFile(testing::SourcePath("studies/examples/cycloid_ltca_lubricated.json")));
  s["analysis"]["estimate_error"] = false;
  s.erase("efficiency_map");
  return s;
}

struct CycloidRun {
  studies::cycloid_ltca::Study study;
  studies::cycloid_ltca::Result result;
};
CycloidRun RunCycloid(const nlohmann::json& s) {
  const studies::Node root(&s, "c.json", "");
  CycloidRun out{studies::cycloid_ltca::Parse(root), {}};
  out.result = studies::cycloid_ltca::Run(out.study, {"c.json", true});
  return out;
}

// The example's losses by hand from other parts of the engine: the crank bearing's Palmgren moment
// on the mean of the life model's crank-bearing loads over their period (bearing_loads.h
// CrankBearingLoads), the ring pins' at the life model's spin rates (PinBearingLoads), the output
// rollers' at e Ω / r on the sine law's forces, the viscosity from the Walther law written out, and
// the housing's balance at the answer.
TEST(CycloidLubricationStudy, TheExamplesLossesByHand) {
  const CycloidRun run = RunCycloid(CycloidLubricated());
  ASSERT_TRUE(run.result.lubrication) << run.result.lubrication_error;
  const studies::LubricationResult& l = *run.result.lubrication;
  const cycloid::Drive& d = run.study.drive;
  const double t = l.oil_temperature_C;
  const auto z = [](double nu) { return std::log10(std::log10(nu + 0.7)); };
  const double x40 = std::log10(313.15), x100 = std::log10(373.15);
  const double b = (z(150.0) - z(14.7)) / (x100 - x40), a = z(150.0) + b * x40;
  const double nu = std::pow(10.0, std::pow(10.0, a - b * std::log10(t + 273.15))) - 0.7;
  EXPECT_NEAR(l.viscosity_cSt, nu, 1e-12 * nu);
  const auto& meshes = run.result.cycle.meshes;
  const cycloid::OutputMechanism m{8, 50.0};
  const double torque = 350e3;
  const std::vector<double> crank = cycloid::CrankBearingLoads(d, m, meshes, torque);
  double mean_b = 0.0;
  for (double x : crank) mean_b += x / double(crank.size());
  const double n_crank = 1500.0 * 16 / 15, w_crank = n_crank * 2 * kPi / 60;
  const auto m0 = [&](double f0, double n, double dm) {
    return 1e-7 * f0 * std::cbrt(std::pow(std::max(nu * n, 2000.0), 2)) * dm * dm * dm;
  };
  const double crank_loss = (m0(2, n_crank, 55) + 0.0003 * mean_b * 55) * w_crank * 1e-3;
  EXPECT_NEAR(*l.power_loss_W.crank_bearing, crank_loss, 1e-9 * crank_loss);
  const cycloid::PinLoadSamples pins = cycloid::PinBearingLoads(d, meshes);
  double ring = 0.0;
  for (size_t k = 0; k < pins.load_N.size(); ++k) {
    const double n = 1500.0 * pins.spin_rate[k];
    ring += (m0(3, n, 11) + 0.0005 * pins.load_N[k] * 11) * n * 2 * kPi / 60 * 1e-3 / double(meshes.size());
  }
  EXPECT_NEAR(*l.power_loss_W.ring_pin_bearings, ring, 1e-9 * ring);
  // Output rollers: Σ Q_j over the pins is the sine law's resultant, every roller at e Ω / r.
  const double n_roller = 1500.0 * 4.5 * 16.0 / 15.0 / 9.0, w_roller = n_roller * 2 * kPi / 60;
  double sum_q = 0.0;
  int samples = 0;
  // The pins' pattern repeats every 15/gcd(15, 8) = 15 mesh periods; one is sampled: 15 shifts.
  for (int shift = 0; shift < 15; ++shift)
    for (const auto& mesh : meshes) {
      sum_q += cycloid::OutputPinResultant<double>(m, 15, torque, mesh.crank_angle_rad + shift * 2 * kPi / 16);
      ++samples;
    }
  const double rollers = (8 * m0(3, n_roller, 15) + 0.0005 * (sum_q / samples) * 15) * w_roller * 1e-3;
  EXPECT_NEAR(*l.power_loss_W.output_roller_bearings, rollers, 1e-9 * rollers);
  EXPECT_EQ(*l.power_loss_W.ring_pins_sliding + *l.power_loss_W.output_pins_sliding, 0.0);  // all roll
  EXPECT_FALSE(l.power_loss_W.eccentric_bearing.has_value());  // an LCR's element
  EXPECT_NEAR(l.output_power_W, 350.0 * 1500 * 2 * kPi / 60 / 15, 1e-12 * l.output_power_W);
  EXPECT_NEAR(l.power_loss_W.total, 0.25 * 15 * (t - 25.0), 1e-6 * l.power_loss_W.total);
  EXPECT_NEAR(l.efficiency, l.output_power_W / (l.output_power_W + l.power_loss_W.total), 1e-15);
}

TEST(CycloidLubricationStudy, ALargerHousingRunsCoolerAndBadInputExitsTwo) {
  nlohmann::json s = CycloidLubricated();
  double previous = 1e300;
  for (double area : {0.1, 0.25, 1.0}) {
    s["lubricant"]["thermal"]["housing_area_m2"] = area;
    const CycloidRun run = RunCycloid(s);
    ASSERT_TRUE(run.result.lubrication) << area;
    EXPECT_LT(run.result.lubrication->oil_temperature_C, previous);
    previous = run.result.lubrication->oil_temperature_C;
  }
  nlohmann::json bad = CycloidLubricated();
  bad.erase("output_mechanism");
  bad.erase("crank_bearing");
  bad.erase("pins");
  bad["load"].erase("input_speed_rpm");
  testing::ExpectStudyRejected(bad, "cyc-lub-speed", "/load", "input_speed_rpm");
  bad["load"]["input_speed_rpm"] = 1500;
  bad["crank_bearing"] = CycloidLubricated()["crank_bearing"];
  // (The speed asks for the bearing lives too, whose checks come first and say the same.)
  testing::ExpectStudyRejected(bad, "cyc-lub-mech", "/output_mechanism", "the output pins' circle");
  bad = CycloidLubricated();
  bad["analysis"]["crank_angles_deg"] = {0.0, 10.0};
  bad["analysis"].erase("crank_angles_per_mesh_period");
  testing::ExpectStudyRejected(bad, "cyc-lub-angles", "/analysis", "whole mesh periods");
}

}  // namespace cycloid_lubrication_test
}  // namespace camopt
