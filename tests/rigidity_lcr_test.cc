// Tests of the lobe cam reducer's torsional stiffness (model/rigidity/lcr_stiffness.h,
// derivation in docs/lcr_stiffness.md).
#include <array>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/lcr/contact.h"
#include "model/rigidity/lcr_stiffness.h"
#include "model/rigidity/lost_motion.h"
#include "studies/transmission_rigidity_study.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt::rigidity {
namespace rigidity_lcr_test {

using camopt::testing::LcrII;
using camopt::testing::LcrIII;
using camopt::testing::Steel;

TEST(LcrStiffness, PalmgrenLawAtItsSteelAndItsInverse) {
  // At Palmgren's own steel (E = 207 GPa, ν = 0.3) the law is δ = 3.84e-5 Q^0.9 / L^0.8.
  const double e_star_ref = 207000.0 / (2.0 * (1.0 - 0.09));
  for (double q : {10.0, 960.0, 5000.0})
    for (double l : {4.0, 8.0, 14.0}) {
      const double d = PalmgrenApproach(q, l, e_star_ref);
      EXPECT_NEAR(d, 3.84e-5 * std::pow(q, 0.9) / std::pow(l, 0.8), 1e-12 * d);
      // At a fixed approach the force is proportional to E* (δ depends on Q/E* only).
      EXPECT_NEAR(PalmgrenForce(d, l, 2.0 * e_star_ref), 2.0 * q, 1e-9 * q);
      EXPECT_NEAR(PalmgrenForce(PalmgrenApproach(q, l, 90000.0), l, 90000.0), q, 1e-9 * q);
    }
  EXPECT_EQ(PalmgrenForce(-1e-3, 8.0, 1e5), 0.0);
  EXPECT_EQ(PalmgrenForce(0.0, 8.0, 1e5), 0.0);
}

// The hand check of docs/lcr_stiffness.md: LCR III at θ = 0 under 10 N·m. At θ = 0 the pitch
// points lie on the x axis, I = e n/(n − m) (20 mm and 24 mm), and every arm has the closed form
// a = O × unit(I − O) = −r_d I sin φ / sqrt(r_d² + I² − 2 r_d I cos φ).
double HandArm(double rd, double pitch, double phi_deg) {
  const double p = phi_deg * kPi / 180.0;
  return -rd * pitch * std::sin(p) / std::sqrt(rd * rd + pitch * pitch - 2 * rd * pitch * std::cos(p));
}

TEST(LcrStiffness, HandCheckLcrIIIAtZeroAngle) {
  const auto r = LcrIII();
  const auto contacts_a = lcr::RollerContacts(r, lcr::Side::kInput, 0.0);
  const auto contacts_b = lcr::RollerContacts(r, lcr::Side::kOutput, 0.0);
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(contacts_a[i].arm, HandArm(36, 20, 72.0 * i), 1e-12);
  for (int j = 0; j < 6; ++j) EXPECT_NEAR(contacts_b[j].arm, HandArm(41, 24, 60.0 * j), 1e-12);
  // The hand numbers: |a_A| = 19.3601, 7.9121; |a_B| = 23.8842, 14.9688 mm.
  EXPECT_NEAR(HandArm(36, 20, 288), 19.3601, 1e-4);
  EXPECT_NEAR(HandArm(36, 20, 216), 7.9121, 1e-4);
  EXPECT_NEAR(HandArm(41, 24, 300), 23.8842, 1e-4);
  EXPECT_NEAR(HandArm(41, 24, 240), 14.9688, 1e-4);
  // Closed form: ψ = (T / (C Σ a^(19/9)))^0.9, C = E* (L^0.8 / K_P)^(10/9), L = min(16, 14).
  const double e_star = 206000.0 / (2 * 0.91), l = 14.0;
  const double kp = 3.84e-5 * std::pow(207000.0 / 1.82, 0.9);
  const double c = e_star * std::pow(std::pow(l, 0.8) / kp, 10.0 / 9.0);
  const double sa = std::pow(19.360094453, 19.0 / 9) + std::pow(7.912130311, 19.0 / 9);
  const double sb = std::pow(23.884245597, 19.0 / 9) + std::pow(14.968773421, 19.0 / 9);
  const double rho = 5.0 * 5.0 / (6.0 * 4.0);  // m_B n_A / (n_B m_A)
  const double t = 10000.0;                    // N·mm; LCR III's sign of load is +1
  const double psi_b = std::pow(t / (c * sb), 0.9), psi_a = -std::pow(rho * t / (c * sa), 0.9);
  const double hand = psi_b - rho * psi_a;
  EXPECT_NEAR(hand, 9.7164e-5, 1e-9);  // the value worked out in the docs
  ASSERT_EQ(lcr::LoadedArmSign(r, lcr::Side::kOutput), 1.0);
  const auto d = DeflectAtAngle<double>(r, Steel(), 0.0, t, 0.0);
  EXPECT_NEAR(d.output_rotation, hand, 1e-9 * hand);
  EXPECT_NEAR(d.psi_output, psi_b, 1e-9 * psi_b);
  // Tangent rigidity: (10/9) g/ψ on each turret, in series through ρ².
  const double kt = 1.0 / (psi_b / ((10.0 / 9) * t) + rho * rho * (-psi_a) / ((10.0 / 9) * rho * t));
  EXPECT_NEAR(d.tangent_rigidity, kt, 1e-9 * kt);
}

// An independent construction of the same equilibrium, straight from the vector kinematics and
// without the decoupling of the derivation: unknowns δφ_c (cam about O_c) and δθ_o (turret about O);
// roller k's approach is −d_k·(v_cam(P_k) − v_roller), v_cam = δφ_c J(P_k − O_c),
// v_roller = δθ_o J O_k (output) or 0 (fixed turret). Cam moment about O_c and turret moment are
// solved by nested bisection (each residual is monotone in its own unknown).
struct TwoDof {
  lcr::Reducer<double> r;
  double theta, clearance, e_star, bearing;
  std::vector<lcr::RollerContact<double>> ca, cb;
  Vec2<double> oc;

  double Force(const lcr::RollerContact<double>& c, double dphi, double dtheta_o, bool output,
               double length) const {
    const Vec2<double> v_cam = dphi * Perp<double>(c.point - oc);
    const Vec2<double> v_rol = output ? Vec2<double>(dtheta_o * Perp<double>(c.centre)) : Vec2<double>(0, 0);
    const double closure = -c.direction.dot(v_cam - v_rol) - clearance;
    if (bearing == 0.0 || closure <= 0.0) return PalmgrenForce(closure, length, e_star);
    // Contact and needle bearing in series: δ_P(F) + F/k_b = closure, by bisection.
    return Bisect([&](double f) { return PalmgrenApproach(f, length, e_star) + f / bearing - closure; },
                  0.0, bearing * closure);
  }
  double CamMoment(double dphi, double dto) const {
    double m = 0;
    for (const auto& c : ca) m += Force(c, dphi, dto, false, r.input.contact_length()) * Cross<double>(c.point - oc, c.direction);
    for (const auto& c : cb) m += Force(c, dphi, dto, true, r.output.contact_length()) * Cross<double>(c.point - oc, c.direction);
    return m;
  }
  double TurretTorque(double dphi, double dto) const {  // torque the turret needs: Σ F a
    double t = 0;
    for (const auto& c : cb) t += Force(c, dphi, dto, true, r.output.contact_length()) * Cross<double>(c.centre, c.direction);
    return t;
  }
  static double Bisect(const std::function<double(double)>& f, double lo, double hi) {
    for (int i = 0; i < 64; ++i) {
      const double mid = 0.5 * (lo + hi);
      (f(mid) > 0 ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
  }
  double SolveCam(double dto) const {  // the cam moment falls as δφ_c rises
    return Bisect([&](double p) { return -CamMoment(p, dto); }, -1e-1, 1e-1);
  }
  double OutputRotation(double torque) const {
    return Bisect([&](double dto) { return TurretTorque(SolveCam(dto), dto) - torque; }, -1e-1, 1e-1);
  }
};

TEST(LcrStiffness, DecouplingAgreesWithTheFullTwoDofEquilibrium) {
  for (const auto& [clearance, bearing] : {std::pair{0.0, 0.0}, std::pair{0.004, 0.0}, std::pair{0.0, 1.5e5},
                                          std::pair{0.003, 1.5e5}}) {
    // The bearing cases nest a third bisection (per roller): one angle keeps them quick.
    for (double theta_deg : bearing > 0 ? std::vector<double>{7.0} : std::vector<double>{0.0, 7.0, 23.0}) {
      SCOPED_TRACE(::testing::Message() << "clearance " << clearance << " bearing " << bearing << " θ " << theta_deg);
      const auto r = LcrII();
      const double theta = theta_deg * kPi / 180.0;
      TwoDof s{r, theta, clearance, Steel().composite_modulus_MPa(), bearing,
               lcr::RollerContacts(r, lcr::Side::kInput, theta),
               lcr::RollerContacts(r, lcr::Side::kOutput, theta),
               r.eccentricity * U(theta)};
      for (double torque : {80000.0, -80000.0, 5000.0}) {
        const double full = s.OutputRotation(torque);
        const auto d = DeflectAtAngle<double>(r, Steel(), theta, torque, clearance, bearing);
        EXPECT_NEAR(d.output_rotation, full, 1e-7 * std::abs(full)) << "T " << torque;
      }
    }
  }
}

TEST(LcrStiffness, ForcesBalanceTheTorqueOnBothTurrets) {
  const auto r = LcrII();
  const double theta = 0.3, t = 80000.0;
  const double e_star = Steel().composite_modulus_MPa();
  const auto d = DeflectAtAngle<double>(r, Steel(), theta, t, 0.0);
  double tb = 0, ta = 0;
  for (const auto& c : lcr::RollerContacts(r, lcr::Side::kOutput, theta))
    tb += PalmgrenForce(d.psi_output * c.arm, r.output.contact_length(), e_star) * c.arm;
  for (const auto& c : lcr::RollerContacts(r, lcr::Side::kInput, theta))
    ta += PalmgrenForce(d.psi_input * c.arm, r.input.contact_length(), e_star) * c.arm;
  EXPECT_NEAR(tb, t, 1e-9 * t);
  // Fixed turret: T_A = −T_o m_B n_A /(n_B m_A) (docs/papers.md §1, in the signed form).
  EXPECT_NEAR(ta, -t * 14.0 * 13.0 / (15.0 * 12.0), 1e-9 * t);
}

TEST(LcrStiffness, MirrorSymmetryReversesTheLoad) {
  // The design is symmetric about the x axis at θ = 0, so reversing the torque at −θ mirrors the
  // state at θ: δθ_o(−T, −θ) = −δθ_o(T, θ).
  const auto r = LcrII();
  for (double theta : {0.1, 0.7, 2.0}) {
    const auto f = DeflectAtAngle<double>(r, Steel(), theta, 80000.0, 0.002);
    const auto b = DeflectAtAngle<double>(r, Steel(), -theta, -80000.0, 0.002);
    EXPECT_NEAR(f.output_rotation, -b.output_rotation, 1e-12);
  }
}

TEST(LcrStiffness, ClearanceAddsItsDeadBandAndNothingElseAtFirstContact) {
  const auto r = LcrII();
  const double c = 0.005;
  // Just above zero torque the output has turned by the first-contact angle, in each sense.
  const double tiny = 1e-6;
  const auto pos = DeflectAtAngle<double>(r, Steel(), 0.4, tiny, c);
  const auto neg = DeflectAtAngle<double>(r, Steel(), 0.4, -tiny, c);
  EXPECT_NEAR(pos.output_rotation, pos.first_contact, 1e-3 * pos.first_contact);
  EXPECT_NEAR(neg.output_rotation, neg.first_contact, 1e-3 * std::abs(neg.first_contact));
  EXPECT_GT(pos.first_contact, 0.0);
  EXPECT_LT(neg.first_contact, 0.0);
  // The dead band is c/max a on each turret and sense, ρ-weighted on the fixed one.
  double pos_a = 0, neg_a = 0, pos_b = 0, neg_b = 0;
  for (const auto& k : lcr::RollerContacts(r, lcr::Side::kInput, 0.4)) {
    pos_a = std::max(pos_a, k.arm);
    neg_a = std::max(neg_a, -k.arm);
  }
  for (const auto& k : lcr::RollerContacts(r, lcr::Side::kOutput, 0.4)) {
    pos_b = std::max(pos_b, k.arm);
    neg_b = std::max(neg_b, -k.arm);
  }
  const double rho = FixedTurretTorqueRatio(r);
  EXPECT_NEAR(pos.first_contact - neg.first_contact,
              c / pos_b + c / neg_b + rho * (c / pos_a + c / neg_a), 1e-12);
}

TEST(LcrStiffness, RippleIsSmallAndForcesMatchThePapersScale) {
  const auto r = LcrII();
  const auto cyc = StiffnessCycle(r, Steel(), 80000.0 * lcr::LoadedArmSign(r, lcr::Side::kOutput), 0.0, 360);
  EXPECT_GT(cyc.ripple, 0.0);
  EXPECT_LT(cyc.ripple, 0.1);
  EXPECT_LE(cyc.min_secant_Nmm_per_rad, cyc.mean_secant_Nmm_per_rad);
  EXPECT_GE(cyc.max_secant_Nmm_per_rad, cyc.mean_secant_Nmm_per_rad);
  // A power law F ∝ δ^(10/9) makes the tangent rigidity 10/9 of the secant on each turret.
  EXPECT_NEAR(cyc.mean_tangent_Nmm_per_rad / cyc.mean_secant_Nmm_per_rad, 10.0 / 9.0, 0.01);
  // Nearly linear contacts give nearly the paper's F = C|a| distribution: Table 3 has 960 N and
  // 720 N as the largest input and output roller forces at 80 N·m.
  EXPECT_NEAR(HardMax(cyc.max_force_input_N), 960.0, 0.03 * 960.0);
  EXPECT_NEAR(HardMax(cyc.max_force_output_N), 720.0, 0.03 * 720.0);
}

TEST(LcrStiffness, NeedleBearingSpringIsInSeriesWithTheContact) {
  const double e_star = Steel().composite_modulus_MPa();
  TurretSpring<double> s{{10.0}, 8.0, e_star, 0.0, 2.0e5};
  for (double closure : {1e-4, 3e-3, 2e-2}) {
    const double f = s.RollerForce(closure);
    EXPECT_NEAR(PalmgrenApproach(f, 8.0, e_star) + f / 2.0e5, closure, 1e-12 * closure);
    const double k = s.RollerRigidity(closure);
    const double kc = (10.0 / 9.0) * f / PalmgrenApproach(f, 8.0, e_star);
    EXPECT_NEAR(1.0 / k, 1.0 / kc + 1.0 / 2.0e5, 1e-12 / k);
  }
  // A very stiff bearing changes nothing; a real one makes the reducer softer.
  const auto r = LcrII();
  const double t = 80000.0;
  const double rigid = DeflectAtAngle<double>(r, Steel(), 0.2, t, 0.0).output_rotation;
  EXPECT_NEAR(DeflectAtAngle<double>(r, Steel(), 0.2, t, 0.0, 1e13).output_rotation, rigid, 1e-6 * rigid);
  EXPECT_GT(DeflectAtAngle<double>(r, Steel(), 0.2, t, 0.0, 2e5).output_rotation, 1.05 * rigid);
}

TEST(LcrStiffness, GradientsMatchCentralDifferences) {
  for (const auto& cb : {std::pair{0.0, 0.0}, std::pair{0.003, 0.0}, std::pair{0.002, 2e5}}) {
    // Plain copies: clang 14 cannot capture a structured binding in a lambda.
    const double clearance = cb.first, bearing = cb.second;
    SCOPED_TRACE(::testing::Message() << clearance << " " << bearing);
    // Variables: eccentricity, output turret radius, roller length (input and output), torque [N·m].
    auto f = [clearance, bearing](const auto& x) {
      using T = std::decay_t<decltype(x[0])>;
      lcr::Reducer<T> r = LcrII().template cast<T>();
      r.eccentricity = x[0];
      r.output.turret_radius = x[1];
      r.input.cam_thickness = x[2];
      r.output.cam_thickness = x[2];
      const auto d = DeflectAtAngle<T>(r, Steel(), T(0.37), x[3] * T(1000.0), T(clearance), T(bearing));
      return std::vector<T>{d.output_rotation * T(1e4), d.tangent_rigidity * T(1e-8),
                            d.elastic_rotation * T(1e4)};
    };
    camopt::testing::ExpectJacobianMatchesCentralDifferences<4>(f, {2.0, 42.0, 8.0, 80.0}, 1e-5, 1e-9);
  }
}

TEST(LcrStiffness, ElasticitiesObeyScalingAndMatchFiniteDifferences) {
  const auto r = LcrII();
  const double t = 80000.0;
  const int steps = 36;
  const auto el = ReducerStiffnessElasticities(r, Steel(), t, 0.0, 0.0, steps);
  ASSERT_EQ(el.size(), 5u);
  // Without clearance or bearings: the arms scale with e and r_d, ψ ∝ (T / Σ a^(19/9))^0.9, so
  // K ∝ λ^1.9 when all three scale; and K ∝ L^0.8 through Palmgren's law.
  EXPECT_NEAR(el[0].second + el[1].second + el[2].second, 1.9, 1e-9);
  EXPECT_NEAR(el[3].second + el[4].second, 0.8, 1e-9);
  // The eccentricity elasticity against a central difference of the cycle's mean stiffness.
  auto mean_k = [&](double e) {
    auto rr = r;
    rr.eccentricity = e;
    return StiffnessCycle(rr, Steel(), t, 0.0, steps).mean_secant_Nmm_per_rad;
  };
  const double h = 1e-5;
  const double fd = (std::log(mean_k(r.eccentricity * (1 + h))) - std::log(mean_k(r.eccentricity * (1 - h)))) /
                    (std::log1p(h) - std::log1p(-h));
  EXPECT_NEAR(el[0].second, fd, 1e-6);
  // With bearings the bearing stiffness shows up, and the length and geometry sums drop.
  const auto eb = ReducerStiffnessElasticities(r, Steel(), t, 0.0, 2e5, steps);
  ASSERT_EQ(eb.size(), 6u);
  EXPECT_GT(eb[5].second, 0.0);
  EXPECT_LT(eb[3].second + eb[4].second, 0.8);
}

// ---- Lost motion (model/rigidity/lost_motion.h) ----------------------------------------------

TEST(LcrLostMotion, TorqueGridIsSymmetricAndDenserNearZero) {
  const double t = 80000.0;
  const auto g = LostMotionTorques(t);
  ASSERT_EQ(g.size(), 82u);
  EXPECT_EQ(g.front(), -t);
  EXPECT_EQ(g.back(), t);
  EXPECT_NEAR(g[40], -1e-9 * t, 1e-20);
  EXPECT_NEAR(g[41], 1e-9 * t, 1e-20);
  EXPECT_NEAR(g[61], 0.25 * t, 1e-9);  // f = 1/2: T f|f|
  for (size_t i = 0; i < g.size(); ++i) {
    EXPECT_NEAR(g[i], -g[g.size() - 1 - i], 1e-9);
    if (i > 0) {
      EXPECT_GT(g[i], g[i - 1]);
    }
  }
}

TEST(LcrLostMotion, WithoutClearanceItScalesAsPalmgrensPowerLaw) {
  // No clearance, rigid bearings: the loaded rollers of each sense do not depend on the load, and
  // each contact force goes as approach^(10/9), so the rotation goes as T^0.9: the lost motion at
  // ±3 % is 0.03^0.9 times that at ±100 %.
  const auto r = LcrII();
  const double t = 80000.0 * lcr::LoadedArmSign(r, lcr::Side::kOutput);
  const double full = LostMotion(r, Steel(), t, 0.0, 36, 0.0, 1.0);
  const double at3 = LostMotion(r, Steel(), t, 0.0, 36);
  EXPECT_GT(full, 0.0);
  EXPECT_NEAR(at3, std::pow(0.03, 0.9) * full, 1e-9 * full);
  // The curve in the load sense is the model's curve of the signed torques, sign restored.
  const std::vector<double> ts = {-0.5 * std::abs(t), 0.25 * std::abs(t)};
  for (double sense : {1.0, -1.0}) {
    const auto in_sense = LostMotionCurveInSense(r, Steel(), ts, sense, 0.0, 12);
    const auto plain = LostMotionCurve(r, Steel(), {sense * ts[0], sense * ts[1]}, 0.0, 12);
    EXPECT_DOUBLE_EQ(in_sense[0], sense * plain[0]);
    EXPECT_DOUBLE_EQ(in_sense[1], sense * plain[1]);
  }
}

TEST(LcrLostMotion, ClearanceAddsAtLeastTheDeadBand) {
  // With a clearance c, roller k closes at ψ = c/a_k ≥ c/max(a), so each turret's restoring torque
  // g_c(ψ) = Σ F(ψ a_k − c) a_k ≤ g_0(ψ − c/max a): at any load it turns at least c/max(a) more than
  // without clearance. In both senses and averaged over the turn, that is the dead band: the lost
  // motion with clearance is at least the dead band plus the lost motion without.
  const auto r = LcrII();
  const double t = 80000.0 * lcr::LoadedArmSign(r, lcr::Side::kOutput);
  const double c = 0.005;
  const double with = LostMotion(r, Steel(), t, c, 36);
  const double without = LostMotion(r, Steel(), t, 0.0, 36);
  const double dead = DeadBand(r, c, 36);
  EXPECT_GT(dead, 0.0);
  EXPECT_GE(with, dead + without - 1e-12);
}

// ---- The element in a study -------------------------------------------------------------------

struct ExampleRun {
  studies::transmission_rigidity::Result result;
  nlohmann::json json;
};

ExampleRun RunExample(const std::string& file) {
  namespace tr = studies::transmission_rigidity;
  const nlohmann::json study = camopt::testing::Example(file);
  const tr::Study s = tr::Parse(studies::Node(&study, file, ""));
  studies::RunContext ctx;
  ctx.quiet = true;
  const tr::Result r = tr::Run(s, ctx);
  return {r, studies::WriteResult(r)};
}

TEST(LcrStiffnessStudy, ReducerElementCarriesItsRatioAndStiffness) {
  const auto [res, j] = RunExample("rigidity_lcr_ii.json");
  const double rb = j["rigidity_Nm_per_rad"].get<double>();
  EXPECT_NEAR(res.chain.total_ratio, 90.0, 1e-9);
  EXPECT_NEAR(1.0e-3 / res.chain.compliance_a, rb / 8100.0, 1e-9 * rb);
  ASSERT_TRUE(res.elements[0].reducer.has_value());
  EXPECT_NEAR(res.elements[0].reducer->cycle.mean_secant_Nmm_per_rad / 1000.0, rb, 1e-9 * rb);
  EXPECT_NEAR(j["elements"][0]["reducer"]["mean_secant_rigidity_Nm_per_rad"].get<double>(), rb, 1e-9 * rb);
  // The reducer alone equals the model's cycle mean.
  const auto r = LcrII();
  const auto cyc = StiffnessCycle(r, Steel(), 80000.0 * lcr::LoadedArmSign(r, lcr::Side::kOutput), 0.0, 720);
  EXPECT_NEAR(rb, cyc.mean_secant_Nmm_per_rad / 1000.0, 1e-9 * rb);
}

TEST(LcrStiffnessStudy, ReducerElementWritesItsCurves) {
  const auto dir = camopt::testing::TempDir("rigidity-lcr");
  const auto res = camopt::testing::RunCamopt(
      "run -q " + camopt::testing::SourcePath("studies/examples/rigidity_lcr_ii.json") + " -o " + dir.string());
  ASSERT_EQ(res.exit_code, 0) << res.stderr_text;
  EXPECT_TRUE(std::filesystem::exists(dir / "result.json"));
  EXPECT_TRUE(std::filesystem::exists(dir / "reducer_1_stiffness.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "reducer_1_lost_motion.svg"));
  // The registered runner writes what the C++ entry points return.
  const nlohmann::json j = nlohmann::json::parse(camopt::testing::ReadFile(dir / "result.json"));
  EXPECT_EQ(camopt::testing::WithoutRunStamp(j), RunExample("rigidity_lcr_ii.json").json);
  // The curve: one row per input angle of the study's angle_steps = 720 over one turn; the study's
  // 80 N·m over the mean elastic rotation of the rows is result.json's mean secant rigidity.
  const auto curve = camopt::testing::ReadCsv(camopt::testing::ReadFile(dir / "reducer_1_stiffness.csv"));
  const std::vector<double>& deg = curve.at("input_angle_deg");
  ASSERT_EQ(deg.size(), 720u);
  EXPECT_EQ(deg.front(), 0.0);
  for (size_t k = 1; k < deg.size(); ++k) EXPECT_NEAR(deg[k] - deg[k - 1], 0.5, 1e-9) << k;
  double mean_rotation_rad = 0;
  for (double v : curve.at("elastic_rotation_arcmin")) mean_rotation_rad += v / 60.0 * kPi / 180.0 / 720.0;
  const double reported = j["elements"][0]["reducer"]["mean_secant_rigidity_Nm_per_rad"].get<double>();
  EXPECT_NEAR(80.0 / mean_rotation_rad, reported, 1e-8 * reported);
}

TEST(LcrStiffnessStudy, ClearanceBecomesBacklashInTheChain) {
  const auto [res, j] = RunExample("rigidity_servo_lcr.json");
  const auto& e = j["elements"][2];
  ASSERT_TRUE(res.elements[2].reducer.has_value());
  const double dead_band_arcmin = e["reducer"]["dead_band_arcmin"].get<double>();
  EXPECT_NEAR(e["backlash_at_end_b_arcmin"].get<double>(), dead_band_arcmin, 1e-12);
  EXPECT_NEAR(j["backlash_at_end_b_arcmin"].get<double>(), dead_band_arcmin, 1e-12);
  EXPECT_NEAR(res.chain.backlash_a, 90.0 * res.chain.backlash_b, 1e-9);
  EXPECT_NEAR(j["backlash_at_end_a_arcmin"].get<double>(), 90.0 * j["backlash_at_end_b_arcmin"].get<double>(), 1e-9);
  EXPECT_GT(res.elements[2].reducer->dead_band_rad, 0.0);
}

TEST(LcrStiffnessStudy, BadReducerIsAClearError) {
  const auto dir = camopt::testing::TempDir("rigidity-lcr-bad");
  const std::string study = R"({"study": "transmission_rigidity", "chain": [{"element": "lobe_cam_reducer",
    "reducer": {"eccentricity_mm": 2,
      "input": {"lobes": 12, "rollers": 12, "turret_radius_mm": 37, "roller_diameter_mm": 12, "roller_length_mm": 10, "cam_thickness_mm": 8},
      "output": {"lobes": 14, "rollers": 15, "turret_radius_mm": 42, "roller_diameter_mm": 12, "roller_length_mm": 10, "cam_thickness_mm": 8}},
    "material": {"youngs_modulus_GPa": 206, "poisson_ratio": 0.3}, "load": {"output_torque_Nm": 80}}]})";
  camopt::testing::WriteFile(dir / "bad.json", study);
  const auto res = camopt::testing::RunCamopt("run -q " + (dir / "bad.json").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(res.exit_code, 2) << res.stderr_text;
  EXPECT_NE(res.stderr_text.find("/chain/0/reducer/input/rollers"), std::string::npos) << res.stderr_text;
}

}  // namespace rigidity_lcr_test
}  // namespace camopt::rigidity
