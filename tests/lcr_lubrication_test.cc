// The LCR's lubricated losses (model/lcr/lubrication.h): the contact speeds against the bodies' rigid
// velocities, the power balance against the statics with friction forces, metamorphic relations
// and derivatives against central differences.
#include "model/lcr/lubrication.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "model/lcr/forces.h"
#include "studies/lcr_analysis_study.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt::lcr {
namespace lcr_lubrication_test {

using testing::LcrII;
using testing::Steel;

// The velocities of the bodies per unit input speed, written from the mechanism alone: the cam's
// centre rides the eccentric at e u(θ) and the cam turns at ω_c (eq. 1); the output turret turns
// about the origin at ω_o (eq. 2), the input turret stands.
struct Bodies {
  Vec2<double> cam_centre, cam_centre_velocity;
  double cam_rate, turret_rate;
  Vec2<double> Cam(const Vec2<double>& p) const { return cam_centre_velocity + cam_rate * Perp(Vec2<double>(p - cam_centre)); }
  Vec2<double> Turret(const Vec2<double>& p) const { return turret_rate * Perp(p); }
};

Bodies BodiesAt(const Reducer<double>& r, Side s, double theta) {
  const Vec2<double> u = U(theta);
  return {r.eccentricity * u, r.eccentricity * Perp(u), CamSpeedRatio(r), s == Side::kInput ? 0.0 : OutputSpeedRatio(r)};
}

TEST(LcrLubrication, ContactSpeedsAreThoseOfTheRigidBodies) {
  const Reducer<double> r = LcrII();
  int checked = 0;
  for (double theta : {0.1, 0.77, 1.9, 3.3, 5.2})
    for (Side s : {Side::kInput, Side::kOutput}) {
      const Bodies b = BodiesAt(r, s, theta);
      const auto contacts = RollerContacts(r, s, theta);
      const double h = 1e-6;
      const auto before = RollerContacts(r, s, theta - h), after = RollerContacts(r, s, theta + h);
      const double rr = r.side(s).roller_radius;
      for (size_t k = 0; k < contacts.size(); ++k) {
        const Vec2<double> p = contacts[k].point, d = contacts[k].direction;
        const Vec2<double> relative = b.Turret(p) - b.Cam(p);  // the turret's point P against the cam's
        // Conjugate profiles: no relative motion along the normal.
        EXPECT_NEAR(relative.dot(d), 0.0, 1e-9 * (1.0 + relative.norm()));
        const ContactSpeeds<double> fixed = RollerContactSpeeds(r, s, contacts[k], theta, false);
        EXPECT_NEAR(fixed.sliding, relative.norm(), 1e-9 * (1.0 + relative.norm())) << k;
        // The contact point's own velocity (a central difference of its position), and the surfaces'
        // velocities relative to it.
        const Vec2<double> travel = (after[k].point - before[k].point) / (2 * h);
        const Vec2<double> cam_surface = b.Cam(p) - travel;
        const double tol = 1e-6 * (1.0 + travel.norm());
        EXPECT_NEAR(fixed.entraining, 0.5 * (b.Turret(p) - travel + cam_surface).norm(), tol) << k;
        // A rotating roller rolls: its surface at P moves with the cam's; its rate about its centre
        // in the fixed frame, less the turret's, is its speed relative to its pin.
        const ContactSpeeds<double> rolling = RollerContactSpeeds(r, s, contacts[k], theta, true);
        EXPECT_EQ(rolling.sliding, 0.0);
        EXPECT_NEAR(rolling.entraining, cam_surface.norm(), tol) << k;
        const Vec2<double> o = contacts[k].centre;
        const double roller_rate = (b.Cam(p) - b.Turret(o)).dot(Perp(d)) / rr;
        EXPECT_NEAR(rolling.roller_spin, std::abs(roller_rate - b.turret_rate), 1e-9) << k;
        ++checked;
      }
    }
  EXPECT_EQ(checked, 5 * (13 + 15));
}

// Power balance: with fixed rollers and friction forces μ F at the contacts, the statics of the
// cam and the output turret re-solved (the rollers' normal loads follow the law F = C |a| with the
// two constants unknown), the input torque from the shaft's balance gives P_in − P_out equal to
// Σ μ F v_s with the sliding speeds of the model, to rounding, at every sampled angle.
TEST(LcrLubrication, InputLessOutputPowerIsTheSumOfTheSlidingLosses) {
  const Reducer<double> r = LcrII();
  const double mu = 0.08, torque = 80e3;  // N·mm
  for (int i = 0; i < 24; ++i) {
    const double theta = 2 * kPi * i / 24 + 0.013;
    const Bodies bin = BodiesAt(r, Side::kInput, theta), bout = BodiesAt(r, Side::kOutput, theta);
    const auto ca = RollerContacts(r, Side::kInput, theta), cb = RollerContacts(r, Side::kOutput, theta);
    const double sa = LoadedArmSign(r, Side::kInput), sb = LoadedArmSign(r, Side::kOutput);
    // Per unit C on a side: the force on the cam from every loaded roller, and its moment about the
    // cam's centre; for the output side also the moment about the origin of the force on the turret.
    struct Unit {
      Vec2<double> force{0, 0};
      double cam_moment = 0, turret_moment = 0, sliding_loss = 0;
    };
    const auto unit = [&](const std::vector<RollerContact<double>>& c, double sign, const Bodies& b, Side s) {
      Unit out;
      for (const auto& k : c) {
        const double f = std::max(sign * k.arm, 0.0);
        if (f <= 0.0) continue;
        const Vec2<double> rel = b.Turret(k.point) - b.Cam(k.point);
        const Vec2<double> on_cam = f * (k.direction + mu * rel / rel.norm());
        out.force += on_cam;
        out.cam_moment += Cross(Vec2<double>(k.point - b.cam_centre), on_cam);
        out.turret_moment += Cross(k.point, Vec2<double>(-on_cam));
        out.sliding_loss += mu * f * RollerContactSpeeds(r, s, k, theta, false).sliding;
      }
      return out;
    };
    const Unit a = unit(ca, sa, bin, Side::kInput), b = unit(cb, sb, bout, Side::kOutput);
    // Output turret: C_B · turret_moment drives it against T_o (the sign of its motion, which gives a
    // positive output power); cam: C_A a.cam_moment + C_B b.cam_moment = 0.
    const double w_o = OutputSpeedRatio(r);
    const double c_b = torque * (w_o > 0 ? 1.0 : -1.0) / b.turret_moment;
    ASSERT_GT(c_b, 0.0);
    const double c_a = -c_b * b.cam_moment / a.cam_moment;
    ASSERT_GT(c_a, 0.0);
    const Vec2<double> g = c_a * a.force + c_b * b.force;          // the cam's push on the eccentric
    const double t_in = -Cross(bin.cam_centre, g);                  // the shaft's balance
    const double p_out = torque * std::abs(w_o);                    // per unit input speed
    const double losses = c_a * a.sliding_loss + c_b * b.sliding_loss;
    EXPECT_NEAR(t_in - p_out, losses, 1e-9 * t_in) << theta;
    // And without friction the balance is the frictionless one.
    EXPECT_GT(losses, 0.0);
  }
}

LubricationSpec Spec(bool rotate) {
  LubricationSpec s;
  s.rollers_rotate = rotate;
  s.roller_bearing = {2.0, 0.0005, 8.0};
  s.eccentric_bearing = {2.0, 0.0005, 40.0};
  return s;
}

TEST(LcrLubrication, NoFrictionGivesEfficiencyOne) {
  const Reducer<double> r = LcrII();
  LoadCase load;
  load.output_torque_Nmm = 80e3;
  for (bool rotate : {true, false}) {
    LubricationSpec s = Spec(rotate);
    s.friction = {0.0, 0.0};
    s.rolling_loss = false;  // the viscous rolling loss is no friction coefficient
    s.roller_bearing.f0 = s.roller_bearing.f1 = s.eccentric_bearing.f0 = s.eccentric_bearing.f1 = 0.0;
    const CycleLubrication c = LubricatedCycle(r, Steel(), load, LoadModel::kRigid, s, 1500.0, 60.0, 90);
    EXPECT_EQ(c.mean.total(), 0.0);
    EXPECT_EQ(c.efficiency, 1.0);
    // The rolling (Poiseuille) loss alone: positive, and it vanishes with the oil's viscosity as
    // F_R ∝ (η0 u)^0.658 (η0 = ρν: a thousandth of the density, a thousandth of η0).
    s.rolling_loss = true;
    const CycleLubrication rolling = LubricatedCycle(r, Steel(), load, LoadModel::kRigid, s, 1500.0, 60.0, 90);
    EXPECT_GT(rolling.mean.rolling_input + rolling.mean.rolling_output, 0.0);
    EXPECT_EQ(rolling.mean.total(), rolling.mean.rolling_input + rolling.mean.rolling_output);
    s.oil.density15_kg_m3 *= 1e-3;
    const CycleLubrication thin = LubricatedCycle(r, Steel(), load, LoadModel::kRigid, s, 1500.0, 60.0, 90);
    EXPECT_NEAR(thin.mean.total() / rolling.mean.total(), std::pow(1e-3, 0.658), 1e-12);
    // With friction the efficiency falls below one.
    const CycleLubrication f = LubricatedCycle(r, Steel(), load, LoadModel::kRigid, Spec(rotate), 1500.0, 60.0, 90);
    EXPECT_LT(f.efficiency, 1.0);
    EXPECT_GT(f.efficiency, 0.0);
  }
}

TEST(LcrLubrication, AThickerOilRaisesLambdaAndLowersTheSlidingLoss) {
  const Reducer<double> r = LcrII();
  LoadCase load;
  load.output_torque_Nmm = 80e3;
  double lambda = 0, sliding = 1e300;
  for (double nu40 : {32.0, 68.0, 150.0, 320.0}) {
    LubricationSpec s = Spec(false);
    s.oil.nu40_mm2_s = nu40;
    s.oil.nu100_mm2_s = nu40 / 8.0;
    s.composite_roughness_mm = 0.03e-3;  // finely finished: the band 1 < λ < 3 is crossed
    const CycleLubrication c = LubricatedCycle(r, Steel(), load, LoadModel::kRigid, s, 1500.0, 60.0, 60);
    EXPECT_GT(c.mean.min_lambda, lambda) << nu40;
    EXPECT_LE(c.mean.sliding_input + c.mean.sliding_output, sliding) << nu40;
    lambda = c.mean.min_lambda;
    sliding = c.mean.sliding_input + c.mean.sliding_output;
  }
}

// At a fixed temperature, doubling the speed doubles a loss of speed-independent friction: the
// sliding loss in the boundary regime (rough surfaces: μ = μ_b at every contact) and Palmgren's M1
// part; M0's power grows as n^(5/3) (νn above 2000).
TEST(LcrLubrication, DoublingTheSpeedScalesTheLossesAsTheLawsSay) {
  const Reducer<double> r = LcrII();
  LoadCase load;
  load.output_torque_Nmm = 80e3;
  LubricationSpec s = Spec(false);
  s.composite_roughness_mm = 100e-3;  // λ ≪ 1 everywhere
  s.eccentric_bearing.f0 = 0.0;
  const auto at = [&](double n) { return LubricatedCycle(r, Steel(), load, LoadModel::kRigid, s, n, 60.0, 60); };
  const CycleLubrication one = at(1000.0), two = at(2000.0);
  EXPECT_LT(two.mean.min_lambda, 1.0);
  EXPECT_NEAR(two.mean.sliding_input, 2 * one.mean.sliding_input, 1e-12 * two.mean.sliding_input);
  EXPECT_NEAR(two.mean.sliding_output, 2 * one.mean.sliding_output, 1e-12 * two.mean.sliding_output);
  EXPECT_NEAR(two.mean.eccentric_bearing, 2 * one.mean.eccentric_bearing, 1e-12 * two.mean.eccentric_bearing);
  // The rolling loss 2 u F_R with F_R ∝ u^0.658 on the same loads: × 2^1.658.
  EXPECT_NEAR(two.mean.rolling_input, std::pow(2.0, 1.658) * one.mean.rolling_input, 1e-12 * two.mean.rolling_input);
  EXPECT_NEAR(two.mean.rolling_output, std::pow(2.0, 1.658) * one.mean.rolling_output, 1e-12 * two.mean.rolling_output);
  LubricationSpec m0 = Spec(true);
  m0.roller_bearing.f1 = m0.eccentric_bearing.f1 = 0.0;
  m0.rolling_loss = false;  // M0 alone
  const auto rolling = [&](double n) { return LubricatedCycle(r, Steel(), load, LoadModel::kRigid, m0, n, 60.0, 30); };
  // (The slowest roller turns at 0.069 of the input speed: at 28.5 mm²/s, νn ≥ 2000 from 1020 rpm.)
  const double p1 = rolling(2000.0).mean.total(), p2 = rolling(4000.0).mean.total();
  EXPECT_NEAR(p2 / p1, std::pow(2.0, 5.0 / 3.0), 1e-12);
}

// The losses at one angle and two oil temperatures against the published formulas evaluated
// directly at that temperature's viscosity (LossesAtAngle computes the temperature-free part once
// and scales it by powers of η0 and ν): Pan & Hamrock's h_min, Goksem & Hargreaves' 2 u F_R,
// Palmgren's M0 + M1 per roller and the eccentric, and μ(λ) F v_s for fixed rollers.
TEST(LcrLubrication, OneAngleLossesAreTheFormulasAtEachTemperature) {
  const Reducer<double> r = LcrII();
  const Material m = Steel();
  LoadCase load;
  load.output_torque_Nmm = 80e3;
  const double theta = 0.37, n_in = 1500.0, omega = n_in * 2 * kPi / 60;
  const AngleLoads<double> a = AnalyzeAngle(r, m, load, theta, {true, false, true});
  for (bool rotate : {true, false}) {
    LubricationSpec s = Spec(rotate);
    s.composite_roughness_mm = 0.5e-3;  // λ inside the mixed band for the fixed rollers' μ(λ)
    for (double t : {40.0, 85.0}) {
      const double nu = s.oil.KinematicViscosityAt(t), eta0 = s.oil.DynamicViscosityAt(t);
      double rolling = 0, sliding = 0, bearings = 0, min_h = 1e300;
      for (int side = 0; side < 2; ++side) {
        const Side sd = side == 0 ? Side::kInput : Side::kOutput;
        const auto& k = side == 0 ? a.input : a.output;
        const CamSide<double>& cam = r.side(sd);
        for (size_t i = 0; i < k.contacts.size(); ++i) {
          const ContactSpeeds<double> v = RollerContactSpeeds(r, sd, k.contacts[i], theta, rotate);
          const double f = k.force[i];
          if (rotate) bearings += PalmgrenPowerLoss(s.roller_bearing, nu, v.roller_spin * n_in, std::max(f, 0.0)) * 1e-3;
          if (!(f > 0)) continue;
          const double r_eff = cam.roller_radius * (1 - cam.roller_radius * k.contacts[i].curvature);
          const double u = v.entraining * omega, w = f / cam.contact_length();
          const double alpha = s.oil.pressure_viscosity_per_MPa;
          const double h = contact::LineContactFilm(eta0, u, r_eff, w, m.composite_modulus_MPa(), alpha).minimum;
          min_h = std::min(min_h, h);
          rolling += 2 * u *
                     contact::LineContactRollingForcePerLength(eta0, u, r_eff, w, m.composite_modulus_MPa(), alpha) *
                     cam.contact_length() * 1e-3;
          if (!rotate)
            sliding += contact::FrictionCoefficient(s.friction, h / s.composite_roughness_mm) * f * v.sliding * omega *
                       1e-3;
        }
      }
      const double n_ecc = n_in * r.input.rollers / r.input.lobes;
      const double eccentric = PalmgrenPowerLoss(s.eccentric_bearing, nu, n_ecc, a.eccentric_load.norm()) * 1e-3;
      const AngleLosses<double> l =
          LossesAtAngle(r, s, m.composite_modulus_MPa(), a.input.contacts, a.input.force, a.output.contacts,
                        a.output.force, a.eccentric_load.norm(), theta, n_in, t);
      const double tol = 1e-12;
      EXPECT_NEAR(l.rolling_input + l.rolling_output, rolling, tol * rolling) << rotate << " " << t;
      EXPECT_NEAR(l.sliding_input + l.sliding_output, sliding, tol * std::max(sliding, 1.0)) << rotate << " " << t;
      EXPECT_NEAR(l.roller_bearings_input + l.roller_bearings_output, bearings, tol * std::max(bearings, 1.0))
          << rotate << " " << t;
      EXPECT_NEAR(l.eccentric_bearing, eccentric, tol * eccentric) << rotate << " " << t;
      EXPECT_NEAR(l.min_film_mm, min_h, tol * min_h) << rotate << " " << t;
      if (!rotate) { EXPECT_GT(sliding, 0.0); }
      if (rotate) { EXPECT_GT(bearings, 0.0); }
    }
  }
}

// A contact whose load is at the rounding level of the largest (a frictionless law's zero computed as
// ±1e-13 N) has no film and no rolling loss, so the loss does not come and go with the rounding; a
// small but real load (1e-6 of the largest) has both.
TEST(LcrLubrication, ALoadAtTheRoundingLevelIsNoContact) {
  const Reducer<double> r = LcrII();
  const Material m = Steel();
  LoadCase load;
  load.output_torque_Nmm = 80e3;
  const double theta = 0.37;
  const AngleLoads<double> a = AnalyzeAngle(r, m, load, theta, {true, false, true});
  size_t unloaded = a.input.force.size();
  double largest = 0;
  for (size_t k = 0; k < a.input.force.size(); ++k) {
    largest = std::max(largest, a.input.force[k]);
    if (!(a.input.force[k] > 0)) unloaded = k;
  }
  ASSERT_LT(unloaded, a.input.force.size());
  const auto rolling = [&](double f) {
    std::vector<double> forces = a.input.force;
    forces[unloaded] = f;
    const AngleLosses<double> l = LossesAtAngle(r, Spec(true), m.composite_modulus_MPa(), a.input.contacts, forces,
                                                a.output.contacts, a.output.force, a.eccentric_load.norm(), theta,
                                                1500.0, 60.0);
    return l.rolling_input;
  };
  EXPECT_EQ(rolling(1e-13), rolling(0.0));
  EXPECT_EQ(rolling(-1e-13), rolling(0.0));
  EXPECT_GT(rolling(1e-6 * largest), rolling(0.0));
}

// ∂(min λ, loss)/∂(e, oil temperature) at one angle against central differences.
TEST(LcrLubrication, DerivativesMatchCentralDifferences) {
  for (bool rotate : {true, false}) {
    const LubricationSpec s = [&] {
      LubricationSpec x = Spec(rotate);
      x.composite_roughness_mm = 0.15e-3;  // the mixed band, where μ depends on λ
      return x;
    }();
    const auto f = [&](const auto& x) {
      using T = std::decay_t<decltype(x[0])>;
      Reducer<T> r = LcrII().template cast<T>();
      r.eccentricity = x[0];
      LoadCase load;
      load.output_torque_Nmm = 80e3;
      const T theta(0.4);
      const AngleLoads<T> a = AnalyzeAngle(r, Steel(), load, theta, {true, false, true});
      const AngleLosses<T> l = LossesAtAngle(r, s, Steel().composite_modulus_MPa(), a.input.contacts, a.input.force,
                                             a.output.contacts, a.output.force, T(a.eccentric_load.norm()), theta,
                                             T(1500.0), x[1]);
      return std::vector<T>{l.min_lambda, l.total()};
    };
    testing::ExpectJacobianMatchesCentralDifferences<2>(f, {2.0, 55.0});
  }
}

}  // namespace lcr_lubrication_test
}  // namespace camopt::lcr

namespace camopt {
namespace lcr_lubrication_test {

using testing::ExpectStudyRejected;
using testing::ReadFile;
using testing::SourcePath;

nlohmann::json LubricatedStudy() {
  nlohmann::json s = nlohmann::json::parse(ReadFile(SourcePath("studies/examples/lcr_ii_lubricated.json")));
  s["analysis"]["angle_steps"] = 360;
  s.erase("efficiency_map");
  return s;
}

struct StudyRun {
  studies::lcr_analysis::Study study;
  studies::lcr_analysis::Result result;
};
StudyRun RunLubricated(const nlohmann::json& s) {
  const studies::Node root(&s, "lubricated.json", "");
  StudyRun out{studies::lcr_analysis::Parse(root), {}};
  out.result = studies::lcr_analysis::Run(out.study, {"lubricated.json", true});
  return out;
}

// The example's losses by hand from other parts of the engine: the eccentric bearing's Palmgren
// moment on |G| of the frictionless force series (lcr::AnalyzeCycle, series.csv's columns), the
// rollers' on their loads at the spin rate of the life model (life.h RollerSpinRate), the
// viscosity from the Walther law written out here, and the housing's balance at the answer.
TEST(LcrLubricationStudy, TheExamplesLossesByHand) {
  const StudyRun run = RunLubricated(LubricatedStudy());
  ASSERT_TRUE(run.result.lubrication.has_value()) << run.result.lubrication_error;
  const studies::LubricationResult& l = *run.result.lubrication;
  const double t = l.oil_temperature_C;
  const auto z = [](double nu) { return std::log10(std::log10(nu + 0.7)); };
  const double x40 = std::log10(313.15), x100 = std::log10(373.15);
  const double b = (z(68.0) - z(8.7)) / (x100 - x40), a = z(68.0) + b * x40;
  const double nu = std::pow(10.0, std::pow(10.0, a - b * std::log10(t + 273.15))) - 0.7;
  EXPECT_NEAR(l.viscosity_cSt, nu, 1e-12 * nu);
  const lcr::Reducer<double>& r = run.study.reducer;
  const auto& series = run.result.series;
  ASSERT_EQ(series.theta_rad.size(), 360u);
  double g = 0.0;
  for (size_t i = 0; i < 360; ++i) g += std::hypot(series.tangential_force_N[i], series.radial_force_N[i]) / 360;
  const double n_ecc = 1500.0 * 13 / 12, w_ecc = n_ecc * 2 * kPi / 60;
  const double eccentric = (1e-7 * 2 * std::cbrt(nu * n_ecc * nu * n_ecc) * 16 * 16 * 16 + 0.0003 * g * 16) * w_ecc * 1e-3;
  EXPECT_NEAR(*l.power_loss_W.eccentric_bearing, eccentric, 1e-9 * eccentric);
  double rollers = 0.0, rolling = 0.0;
  // The rolling loss 2 u F_R in SI, Goksem & Hargreaves' F_R/L = 4.318 (G U)^0.658 W'^0.0126 R/α on the
  // Hertz R' = r_r (1 − r_r κ) and w' = F/L; α 21 GPa⁻¹ (the example's), E' = 2 E*.
  const double eta0 = run.study.lubrication->spec.oil.DynamicViscosityAt(t) * 1e6;  // Pa·s
  const double e_prime = 2 * run.study.material.composite_modulus_MPa() * 1e6, alpha = 21e-9;
  for (size_t i = 0; i < 360; ++i)
    for (lcr::Side s : {lcr::Side::kInput, lcr::Side::kOutput}) {
      const lcr::AngleLoads<double> al = lcr::AnalyzeAngle(r, run.study.material, run.study.load, series.theta_rad[i]);
      const auto& forces = s == lcr::Side::kInput ? al.input.force : al.output.force;
      const auto& contacts = s == lcr::Side::kInput ? al.input.contacts : al.output.contacts;
      const lcr::CamSide<double>& cam = r.side(s);
      for (size_t k = 0; k < forces.size(); ++k) {
        const double n = 1500.0 * lcr::RollerSpinRate(r, s, series.theta_rad[i], int(k));
        const double m0 = 1e-7 * 3 * std::cbrt(std::pow(std::max(nu * n, 2000.0), 2)) * 8 * 8 * 8;
        rollers += (m0 + 0.0005 * forces[k] * 8) * n * 2 * kPi / 60 * 1e-3 / 360;
        if (!(forces[k] > 0)) continue;
        const double u = lcr::RollerContactSpeeds(r, s, contacts[k], series.theta_rad[i], true).entraining * 1500.0 *
                         2 * kPi / 60 * 1e-3;  // m/s
        const double rr = cam.roller_radius * 1e-3, big_r = rr * (1 - cam.roller_radius * contacts[k].curvature);
        const double length = cam.contact_length() * 1e-3, w = forces[k] / length;
        const double U = eta0 * u / (e_prime * big_r), G = alpha * e_prime, W = w / (e_prime * big_r);
        const double force = 4.318 * std::pow(G * U, 0.658) * std::pow(W, 0.0126) * big_r / alpha * length;
        rolling += 2 * u * force / 360;
      }
    }
  EXPECT_NEAR(*l.power_loss_W.rolling_input_cam + *l.power_loss_W.rolling_output_cam, rolling, 1e-9 * rolling);
  EXPECT_GT(rolling, 0.0);
  EXPECT_NEAR(*l.power_loss_W.roller_bearings_input + *l.power_loss_W.roller_bearings_output, rollers, 1e-9 * rollers);
  EXPECT_EQ(*l.power_loss_W.sliding_input_cam + *l.power_loss_W.sliding_output_cam, 0.0);  // rotating rollers
  EXPECT_FALSE(l.power_loss_W.ring_pins_sliding.has_value());  // a cycloid's element
  EXPECT_NEAR(l.power_loss_W.total,
              *l.power_loss_W.sliding_input_cam + *l.power_loss_W.sliding_output_cam + *l.power_loss_W.rolling_input_cam +
                  *l.power_loss_W.rolling_output_cam + *l.power_loss_W.roller_bearings_input +
                  *l.power_loss_W.roller_bearings_output + *l.power_loss_W.eccentric_bearing,
              1e-12 * l.power_loss_W.total);
  // Power: input = output + losses; η their ratio; the output power T_o ω_in / |r_i|.
  EXPECT_NEAR(l.output_power_W, 80.0 * 1500 * 2 * kPi / 60 / 90, 1e-12 * l.output_power_W);
  EXPECT_NEAR(l.efficiency, l.output_power_W / (l.output_power_W + l.power_loss_W.total), 1e-15);
  // The thermal fixed point: the housing gives off the loss, within 1e-6 of it.
  ASSERT_TRUE(l.thermal_residual_W.has_value());
  EXPECT_NEAR(l.power_loss_W.total, 0.045 * 15 * (t - 25.0), 1e-6 * l.power_loss_W.total);
  EXPECT_LE(std::abs(*l.thermal_residual_W), 1e-6 * l.power_loss_W.total);
  // The angle grid's error estimate bounds the change to a finer grid.
  nlohmann::json fine = LubricatedStudy();
  fine["analysis"]["angle_steps"] = 1440;
  const StudyRun f = RunLubricated(fine);
  EXPECT_LE(std::abs(f.result.lubrication->power_loss_W.total - l.power_loss_W.total), l.power_loss_sampling_error_W);
}

// A larger housing area runs cooler (and its oil, thicker, gives a larger λ); a given temperature is
// used as given.
TEST(LcrLubricationStudy, ALargerHousingRunsCoolerAndAGivenTemperatureIsUsed) {
  nlohmann::json s = LubricatedStudy();
  double previous = 1e300;
  for (double area : {0.02, 0.045, 0.1, 0.3}) {
    s["lubricant"]["thermal"]["housing_area_m2"] = area;
    const StudyRun run = RunLubricated(s);
    ASSERT_TRUE(run.result.lubrication) << area;
    EXPECT_LT(run.result.lubrication->oil_temperature_C, previous) << area;
    previous = run.result.lubrication->oil_temperature_C;
  }
  s["lubricant"].erase("thermal");
  s["lubricant"]["temperature_C"] = 70.0;
  const StudyRun given = RunLubricated(s);
  EXPECT_EQ(given.result.lubrication->oil_temperature_C, 70.0);
  EXPECT_EQ(given.result.lubrication->temperature_source, "given");
  EXPECT_FALSE(given.result.lubrication->thermal_residual_W.has_value());
}

// No equilibrium below the oil's limit: exit 3, saying why, and the block carries the reason.
TEST(LcrLubricationStudy, NoThermalEquilibriumExitsThreeSayingWhy) {
  nlohmann::json s = LubricatedStudy();
  s["lubricant"]["thermal"]["housing_area_m2"] = 1e-4;
  s["lubricant"]["thermal"]["max_oil_temperature_C"] = 60;
  const auto dir = testing::TempDir("lub-hot");
  testing::WriteFile(dir / "hot.json", s.dump());
  const testing::CliResult res = testing::RunCamopt("run " + (dir / "hot.json").string() + " --quiet --out " +
                                                    (dir / "out").string());
  EXPECT_EQ(res.exit_code, 3) << res.stderr_text;
  EXPECT_NE(res.stderr_text.find("no thermal equilibrium"), std::string::npos) << res.stderr_text;
  const nlohmann::json r = nlohmann::json::parse(ReadFile(dir / "out" / "result.json"));
  EXPECT_EQ(r["status"], "not_converged");
  EXPECT_NE(r["lubrication"]["error"].get<std::string>().find("no equilibrium below the oil's limit"), std::string::npos);
}

TEST(LcrLubricationStudy, BadInputExitsTwoNamingThePath) {
  nlohmann::json s = LubricatedStudy();
  s.erase("lubricant");
  ExpectStudyRejected(s, "lub-surfaces", "/surfaces", "needs \"lubricant\"");
  s = LubricatedStudy();
  s["lubricant"]["nu100_cSt"] = 90;
  ExpectStudyRejected(s, "lub-nu100", "/lubricant/nu100_cSt", "at most nu40_cSt");
  s = LubricatedStudy();
  s["lubricant"]["temperature_C"] = 60;
  ExpectStudyRejected(s, "lub-both", "/lubricant", "not both");
  s = LubricatedStudy();
  s["load"].erase("input_speed_rpm");
  ExpectStudyRejected(s, "lub-speed", "/load", "input_speed_rpm");
  s = LubricatedStudy();
  s["surfaces"]["rollers"] = "sliding";
  ExpectStudyRejected(s, "lub-rollers", "/surfaces/rollers", "rotating");
  s = LubricatedStudy();
  s.erase("lubricant");
  s.erase("surfaces");
  s.erase("bearing_friction");
  ExpectStudyRejected(s, "lub-limit", "/limits/min_efficiency", "needs \"lubricant\"");
  // The built-in oils: a grade the table has, one way, with its base.
  s = LubricatedStudy();
  s["lubricant"]["iso_vg"] = 68;
  ExpectStudyRejected(s, "lub-vg-both", "/lubricant/nu40_cSt", "one way");
  s["lubricant"].erase("nu40_cSt");
  s["lubricant"].erase("nu100_cSt");
  s["lubricant"]["iso_vg"] = 75;
  ExpectStudyRejected(s, "lub-vg-grade", "/lubricant/iso_vg", "32, 46, 68, 100, 150, 220, 320, 460, 680");
  s["lubricant"]["iso_vg"] = 68;
  s["lubricant"]["base_oil"] = "ester";
  ExpectStudyRejected(s, "lub-vg-base", "/lubricant/base_oil", "synthetic");
  s = LubricatedStudy();
  s["lubricant"]["base_oil"] = "mineral";
  ExpectStudyRejected(s, "lub-base-alone", "/lubricant/base_oil", "iso_vg");
  s = LubricatedStudy();
  s["lubricant"].erase("nu100_cSt");
  ExpectStudyRejected(s, "lub-no-nu100", "/lubricant", "found no nu100_cSt");
}

// "iso_vg": 68 (mineral) is the built-in Shell Omala S2 GX 68: the same operating point as its data
// sheet's ν40 68, ν100 8.7 mm²/s and 885 kg/m³ given by hand.
TEST(LcrLubricationStudy, ABuiltInOilIsItsDataSheet) {
  nlohmann::json by_hand = LubricatedStudy();
  by_hand["lubricant"]["density_kg_m3"] = 885;
  by_hand["lubricant"]["name"] = "x";
  nlohmann::json built_in = LubricatedStudy();
  built_in["lubricant"].erase("nu40_cSt");
  built_in["lubricant"].erase("nu100_cSt");
  built_in["lubricant"]["iso_vg"] = 68;
  built_in["lubricant"]["name"] = "x";
  const StudyRun a = RunLubricated(by_hand), b = RunLubricated(built_in);
  ASSERT_TRUE(a.result.lubrication && b.result.lubrication);
  EXPECT_EQ(a.result.lubrication->efficiency, b.result.lubrication->efficiency);
  EXPECT_EQ(a.result.lubrication->oil_temperature_C, b.result.lubrication->oil_temperature_C);
  EXPECT_EQ(b.result.lubrication->oil.nu100_cSt, 8.7);
  EXPECT_EQ(b.result.lubrication->oil.density_kg_m3, 885.0);
  EXPECT_NE(b.result.lubrication->oil.source.find("Omala S2 GX 68"), std::string::npos);
  EXPECT_EQ(a.result.lubrication->oil.source, "given");
  // The synthetic VG 68 of the table (ν100 11.6 against 8.7): above 40 °C a thicker oil, so at the
  // same given temperature of 60 °C a larger least λ.
  nlohmann::json synthetic = built_in;
  synthetic["lubricant"]["base_oil"] = "synthetic";
  synthetic["lubricant"].erase("thermal");
  synthetic["lubricant"]["temperature_C"] = 60;
  nlohmann::json mineral = built_in;
  mineral["lubricant"].erase("thermal");
  mineral["lubricant"]["temperature_C"] = 60;
  const StudyRun m = RunLubricated(mineral), y = RunLubricated(synthetic);
  ASSERT_TRUE(m.result.lubrication && y.result.lubrication);
  EXPECT_GT(y.result.lubrication->viscosity_cSt, m.result.lubrication->viscosity_cSt);
  EXPECT_GT(y.result.lubrication->min_film_lambda.value, m.result.lubrication->min_film_lambda.value);
  EXPECT_NE(y.result.lubrication->oil.source.find("880 kg/m³ assumed"), std::string::npos);
}

}  // namespace lcr_lubrication_test
}  // namespace camopt
