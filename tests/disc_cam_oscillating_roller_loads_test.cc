// Loads of an oscillating roller follower (model/disc_cam/kinetostatics.h, OscillatingRollerLoadAt;
// the disc_cam study's "arm_dynamics" and disc_cam_min_size's contact-stress rows for it). The
// expected values are written out here from the mechanism, not taken from the code under test:
// the triangle O₂O₃C on the base circle, the roller centre C(θ, ξ) = f u(θ) + l u(θ + π − ξ) (the
// common normal through C from its tangent by central differences, the arm's lever dC/dξ by central
// differences), the arm's moment balance M = J S'' ω² + k S + M₀ + M_e, the frictionless power
// balance T ω = M ξ̇ for the camshaft torque, and the in-line translating follower's closed form
// F = (m S'' ω² + k S + F₀ + P)/cos φ, tan φ = S'/(r₀ + S) (Rothbart, Cam Design Handbook ch. 8) as
// the limit of a long arm.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/disc_cam/disc_cam.h"
#include "model/disc_cam/kinetostatics.h"
#include "sizing/disc_cam_min_size.h"
#include "studies/disc_cam_min_size_study.h"
#include "studies/disc_cam_study.h"
#include "studies/input.h"
#include "tests/test_util.h"

namespace camopt {
namespace disc_cam_oscillating_roller_loads_test {

using nlohmann::json;
constexpr double kPiHere = 3.14159265358979323846;
constexpr double kDegHere = kPiHere / 180.0;

// A cycloidal rise of h over 120°, dwell 50°, cycloidal return over 120°, dwell 70° (S, S', S'' per rad),
// from the law S = h (u − sin 2πu/(2π)) (Norton, Design of Machinery §8.5).
struct Svaj3 {
  double s, v, a;
};
Svaj3 Cycloidal(double h, double th) {
  const double beta = 120 * kDegHere, k = 2 * kPiHere;
  auto rise = [&](double u) {
    return Svaj3{h * (u - std::sin(k * u) / k), h / beta * (1 - std::cos(k * u)), k * h / (beta * beta) * std::sin(k * u)};
  };
  if (th < beta) return rise(th / beta);
  if (th < 170 * kDegHere) return {h, 0, 0};
  if (th < 290 * kDegHere) {
    const Svaj3 r = rise((th - 170 * kDegHere) / beta);
    return {h - r.s, -r.v, -r.a};
  }
  return {0, 0, 0};
}
motion::MotionProgram<double> CycloidalProgram(double h) {
  using motion::MotionLaw;
  using motion::MotionSegment;
  return motion::MotionProgram<double>({MotionSegment<double>(MotionLaw::kCycloidal, h, 120 * kDegHere),
                                        MotionSegment<double>(MotionLaw::kDwell, 0.0, 50 * kDegHere),
                                        MotionSegment<double>(MotionLaw::kCycloidal, -h, 120 * kDegHere),
                                        MotionSegment<double>(MotionLaw::kDwell, 0.0, 70 * kDegHere)});
}

// The oscillating mechanism written out: pivot distance f, arm l, r₀ = r_b + r_f, swing S(θ) [rad].
struct Mechanism {
  double f, l, r0, h;
  double Xi0() const { return std::acos((l * l + f * f - r0 * r0) / (2 * l * f)); }
  std::pair<double, double> Centre(double th, double xi) const {
    return {f * std::cos(th) + l * std::cos(th + kPiHere - xi), f * std::sin(th) + l * std::sin(th + kPiHere - xi)};
  }
  std::pair<double, double> Pitch(double th) const { return Centre(th, Xi0() + Cycloidal(h, th).s); }
  // The contact force [N] for the arm's moment M [N·m]: M over the lever n · dC/dξ [m].
  double Force(double th, double moment) const {
    const double e = 1e-6;
    const auto [px, py] = Pitch(th + e);
    const auto [mx, my] = Pitch(th - e);
    const double tx = px - mx, ty = py - my, tn = std::hypot(tx, ty);
    const double nx = ty / tn, ny = -tx / tn;  // outward: the pitch curve runs counter-clockwise
    const double xi = Xi0() + Cycloidal(h, th).s;
    const auto [ax, ay] = Centre(th, xi + e);
    const auto [bx, by] = Centre(th, xi - e);
    const double lever = (nx * (ax - bx) + ny * (ay - by)) / (2 * e);
    return moment / (lever * 1e-3);
  }
  // The pitch curve's curvature [1/mm] from C's derivatives in θ, differentiated here by hand:
  // with ψ = θ + π − ξ, C' = f J u(θ) + l (1 − ξ') J u(ψ), C'' = −f u(θ) − l (1 − ξ')² u(ψ) − l ξ'' J u(ψ)
  // (J u = (−sin, cos)); κ = (C' × C'')/|C'|³. (Central differences of C would lose the first order
  // where the law's jerk jumps, at the ends of the dwells.)
  double Curvature(double th) const {
    const Svaj3 q = Cycloidal(h, th);
    const double psi = th + kPiHere - (Xi0() + q.s), w = 1 - q.v;
    const double dx = -f * std::sin(th) - l * w * std::sin(psi), dy = f * std::cos(th) + l * w * std::cos(psi);
    const double ddx = -f * std::cos(th) - l * w * w * std::cos(psi) + l * q.a * std::sin(psi);
    const double ddy = -f * std::sin(th) - l * w * w * std::sin(psi) - l * q.a * std::cos(psi);
    return (dx * ddy - dy * ddx) / std::pow(dx * dx + dy * dy, 1.5);
  }
};

disc_cam::DiscCam OscillatingCam(const Mechanism& m, double rf) {
  disc_cam::DiscCam cam;
  cam.follower = disc_cam::FollowerType::kOscillatingRoller;
  cam.base_radius = m.r0 - rf;
  cam.roller_radius = rf;
  cam.pivot_distance = m.f;
  cam.arm_length = m.l;
  cam.motion = CycloidalProgram(m.h);
  return cam;
}

// At rest on the base circle the common normal is radial (O₂C), so the spring's moment M₀ is balanced
// by F times the distance from O₃ to the line O₂C, l sin γ with γ the triangle's angle at C:
// cos γ = (l² + r₀² − f²)/(2 l r₀). f = 100, l = 80, r₀ = 50 mm, M₀ = 4 N·m, M_e = 1 N·m:
// cos γ = −1100/8000 = −0.1375, sin γ = 0.990502, F = 5/(0.08 · 0.990502) = 63.0993 N.
TEST(DiscCamOscillatingRollerLoads, StaticMomentOnTheBaseCircleByHand) {
  const Mechanism m{100, 80, 50, 20 * kDegHere};
  const disc_cam::DiscCam cam = OscillatingCam(m, 10);
  disc_cam::ArmLoads a;
  a.inertia_kg_m2 = 0.01;
  a.spring_rate_N_m_per_rad = 30;
  a.spring_preload_N_m = 4;
  a.external_moment_N_m = 1;
  const double cos_gamma = (80.0 * 80 + 50 * 50 - 100 * 100) / (2 * 80 * 50);
  const double by_hand = 5.0 / (0.08 * std::sqrt(1 - cos_gamma * cos_gamma));
  EXPECT_NEAR(by_hand, 63.0993, 1e-4);
  for (double deg : {300.0, 330.0, 355.0}) {  // the dwell on the base circle, at any speed
    const disc_cam::CamPoint<double> p = disc_cam::EvaluateCam(cam, deg * kDegHere);
    EXPECT_NEAR(disc_cam::OscillatingRollerLoadAt(p, a, 40.0).contact_force, by_hand, 1e-9 * by_hand) << deg;
  }
}

// Over the cycle at 300 rpm: the force against the moment over the lever written out above, and the
// camshaft torque (the force's moment about the cam centre) against the power balance M S'.
TEST(DiscCamOscillatingRollerLoads, ForceAndTorqueOverTheCycleAgainstTheMechanism) {
  const Mechanism m{100, 80, 50, 20 * kDegHere};
  const disc_cam::DiscCam cam = OscillatingCam(m, 10);
  disc_cam::ArmLoads a;
  a.inertia_kg_m2 = 0.01;
  a.spring_rate_N_m_per_rad = 30;
  a.spring_preload_N_m = 4;
  a.external_moment_N_m = 1;
  const double omega = 300 * 2 * kPiHere / 60;
  double worst_f = 0, worst_t = 0, peak_t = 0;
  for (int i = 0; i < 720; ++i) {
    const double th = 2 * kPiHere * i / 720;
    const Svaj3 q = Cycloidal(m.h, th);
    const double moment = a.inertia_kg_m2 * q.a * omega * omega + a.spring_rate_N_m_per_rad * q.s + 5.0;
    const disc_cam::ArmCamLoad<double> load = disc_cam::OscillatingRollerLoadAt(disc_cam::EvaluateCam(cam, th), a, omega);
    const double f = m.Force(th, moment);
    worst_f = std::max(worst_f, std::abs(load.contact_force - f) / std::abs(f));
    worst_t = std::max(worst_t, std::abs(load.camshaft_torque * 1e-3 - moment * q.v));
    peak_t = std::max(peak_t, std::abs(moment * q.v));
  }
  EXPECT_LT(worst_f, 1e-7);  // the central differences' error
  EXPECT_LT(worst_t, 1e-9 * peak_t + 1e-12);
  EXPECT_GT(peak_t, 1.0);
}

// A long arm whose path is tangent to the line O₂C on the base circle (arm ⟂ O₂C: f² = l² + r₀²) is an
// in-line translating follower in the limit: with J = m l², k_θ = k l², M₀ = F₀ l, M_e = P l and a swing
// of h/l, the contact force tends to the in-line closed form; its difference falls as 1/l.
TEST(DiscCamOscillatingRollerLoads, LongArmTendsToTheInLineTranslatingClosedForm) {
  const double r0 = 50, h = 24, mass = 1.5, k = 2.0, f0 = 40, load = 10;  // mm, kg, N/mm, N, N
  const double omega = 400 * 2 * kPiHere / 60;
  auto in_line = [&](double th) {
    const Svaj3 q = Cycloidal(h, th);
    const double fy = mass * q.a * 1e-3 * omega * omega + k * q.s + f0 + load;
    return fy / std::cos(std::atan(q.v / (r0 + q.s)));
  };
  double diff[2] = {0, 0};
  int d = 0;
  for (double l : {1e4, 1e5}) {
    const double lm = l * 1e-3;
    Mechanism mech{std::sqrt(l * l + r0 * r0), l, r0, h / l};
    const disc_cam::DiscCam cam = OscillatingCam(mech, 10);
    disc_cam::ArmLoads a;
    a.inertia_kg_m2 = mass * lm * lm;
    a.spring_rate_N_m_per_rad = k * 1e3 * lm * lm;
    a.spring_preload_N_m = f0 * lm;
    a.external_moment_N_m = load * lm;
    for (int i = 0; i < 360; ++i) {
      const double th = 2 * kPiHere * i / 360;
      const double ours = disc_cam::OscillatingRollerLoadAt(disc_cam::EvaluateCam(cam, th), a, omega).contact_force;
      diff[d] = std::max(diff[d], std::abs(ours - in_line(th)) / std::abs(in_line(th)));
    }
    ++d;
  }
  EXPECT_LT(diff[1], 2e-4) << diff[0];
  EXPECT_GT(diff[0] / diff[1], 5.0) << diff[0] << " " << diff[1] << ": first order in 1/l";
}

json OscillatingLoadsStudy() {
  json j = camopt::testing::Example("disc_cam_oscillating.json");
  j["arm_dynamics"] = {{"speed_rpm", 300}, {"arm_inertia_kg_m2", 0.01}, {"spring_rate_N_m_per_rad", 30},
                       {"spring_preload_N_m", 4}, {"external_moment_N_m", 1}};
  j["face_width_mm"] = 10;
  j["material"] = {{"youngs_modulus_GPa", 206}, {"poisson_ratio", 0.3}};
  j["limits"] = {{"contact_stress_MPa", 900}};
  j["motion"] = json::parse(R"([ { "law": "cycloidal", "rise_deg": 20, "cam_angle_deg": 120 },
                                  { "law": "dwell", "cam_angle_deg": 50 },
                                  { "law": "cycloidal", "rise_deg": -20, "cam_angle_deg": 120 },
                                  { "law": "dwell", "cam_angle_deg": 70 } ])");
  j["analysis"] = {{"angle_steps", 3600}, {"monte_carlo", false}};
  return j;
}

// The disc_cam study of an oscillating roller with arm_dynamics: the jump speed against the closed form
// ω² = min (k S + M₀ + M_e)/(−J S'') over the law, the contact force series against the mechanism, the
// peak Hertz stress against Johnson eq. 4.45 with R' = r_f (1 − r_f κ), κ of the pitch curve from C's
// derivatives, E* = E/(2(1 − ν²)); the camshaft torque's largest |T| against max |M S'|.
TEST(DiscCamOscillatingRollerLoads, StudyReportsForceTorqueJumpAndStress) {
  const json file = OscillatingLoadsStudy();
  const studies::Node root(&file, "study.json", "");
  const studies::disc_cam::Study s = studies::disc_cam::Parse(root);
  studies::RunContext ctx;
  ctx.quiet = true;
  const studies::disc_cam::Result r = studies::disc_cam::Run(s, ctx);
  const json out = studies::WriteResult(r);
  ASSERT_TRUE(out.contains("arm_dynamics")) << out.dump(1);
  const json& aj = out["arm_dynamics"];
  const Mechanism m{100, 80, 50, 20 * kDegHere};
  const double omega = 300 * 2 * kPiHere / 60, J = 0.01, k = 30, hold0 = 5;
  double w2 = 1e300, max_t = 0;
  for (int i = 0; i < 3600; ++i) {
    const double th = 2 * kPiHere * i / 3600;
    const Svaj3 q = Cycloidal(m.h, th);
    if (q.a < 0) w2 = std::min(w2, (k * q.s + hold0) / (-J * q.a));
    const double moment = J * q.a * omega * omega + k * q.s + hold0;
    max_t = std::max(max_t, std::abs(moment * q.v));
    if (i % 10 == 0) {
      EXPECT_NEAR(r.loads->contact_force_N[size_t(i)], m.Force(th, moment), 1e-6 * std::abs(m.Force(th, moment))) << i;
    }
  }
  EXPECT_NEAR(aj["jump_speed_rpm"].get<double>(), std::sqrt(w2) * 60 / (2 * kPiHere), 1e-9 * std::sqrt(w2) * 60);
  EXPECT_NEAR(aj["max_camshaft_torque_Nm"].get<double>(), max_t, 1e-9 * max_t);
  EXPECT_TRUE(aj["separation_ok"].get<bool>());
  EXPECT_GT(aj["min_contact_force_N"].get<double>(), 0.0);
  // Hertz at the reported peak.
  const double at = aj["at_max_contact_stress_cam_angle_deg"].get<double>();
  const int ip = int(std::lround(at * 10));
  const double th = at * kDegHere, rf = 10;
  const double r_eff = rf * (1 - rf * m.Curvature(th));
  const double e_star = 206000.0 / (2 * (1 - 0.09));
  const double p0 = std::sqrt(r.loads->contact_force_N[size_t(ip)] * e_star / (kPiHere * 10 * r_eff));
  EXPECT_NEAR(aj["max_contact_stress_MPa"].get<double>(), p0, 1e-5 * p0);
  EXPECT_EQ(aj["contact_stress_ok"].get<bool>(), p0 <= 900);
  // The spring keeping contact up to the speed: M ≥ 0 with the inertia at 300 rpm where S'' < 0.
  double need = 0;
  for (int i = 0; i < 3600; ++i) {
    const Svaj3 q = Cycloidal(m.h, 2 * kPiHere * i / 3600);
    need = std::max(need, -(std::min(0.0, J * q.a * omega * omega) + 1.0 + k * q.s));
  }
  EXPECT_NEAR(aj["min_spring_preload_N_m"].get<double>(), need, 1e-12 + 1e-12 * need);
}

namespace dcs = studies::disc_cam_min_size;

json OscillatingStressSizing(const std::string& backend) {
  json j = camopt::testing::Example("disc_cam_min_size_oscillating.json");
  j["motion"] = OscillatingLoadsStudy()["motion"];
  j["arm_dynamics"] = OscillatingLoadsStudy()["arm_dynamics"];
  j["face_width_mm"] = 10;
  j["material"] = {{"youngs_modulus_GPa", 206}, {"poisson_ratio", 0.3}};
  j["limits"] = {{"pressure_angle_deg", 30}, {"contact_stress_MPa", 250}};
  j["variables"]["roller_radius_mm"] = {4, 16};
  j["optimizer"] = {{"backend", backend}};
  return j;
}

// disc_cam_min_size of an oscillating roller with a contact-stress limit: every row (pressure angle,
// curvature and the stress rows through the arm's moment balance) has its exact derivative, the
// ceres::Jet Jacobian against central differences, at two designs.
TEST(DiscCamOscillatingRollerLoads, SizingStressRowsHaveExactDerivatives) {
  json j = OscillatingStressSizing("ipopt");
  j["analysis"] = {{"angle_steps", 72}};
  const dcs::Study s = dcs::Parse(studies::Node(&j, "s.json", ""));
  ASSERT_TRUE(s.spec.stress && s.spec.stress->arm);
  const objectives::Problem p = sizing::DiscCamSizingProblem(s.spec, sizing::StudyFastLimits(s.spec));
  for (const std::vector<double>& x : {std::vector<double>{40, 100, 80, 10}, std::vector<double>{22, 90, 75, 15}}) {
    camopt::testing::JacobianCheck check;
    check.abs_tol_scales_with_value = true;
    EXPECT_GT(camopt::testing::ExpectEvaluatorJacobianMatchesCentralDifferences(*p.evaluator, x, check), 0);
  }
}

// The smallest base circle under a 250 MPa limit (base circle, pivot, arm and roller free): Ipopt and
// SLSQP agree within 0.1%, and the peak stress of the answer, computed here from the mechanism on
// 36 000 angles (force over the lever, Johnson eq. 4.45 with R' = r_f (1 − r_f κ)), meets the limit
// and binds.
TEST(DiscCamOscillatingRollerLoads, SizingStressLimitIpoptAgreesWithSlsqpAndTheMechanism) {
  double rb[2] = {0, 0};
  for (int b = 0; b < 2; ++b) {
    const json j = OscillatingStressSizing(b == 0 ? "ipopt" : "slsqp");
    const dcs::Result r = dcs::Run(dcs::Parse(studies::Node(&j, "s.json", "")), {"s.json", true});
    const auto& o = r.outcome;
    ASSERT_TRUE(o.converged) << o.result.message;
    ASSERT_TRUE(o.verified) << r.blocking_message;
    EXPECT_NE(std::find(o.binding.begin(), o.binding.end(), "contact_stress_MPa"), o.binding.end());
    rb[b] = o.cam.base_radius;
    const double rf = o.cam.roller_radius;
    const Mechanism m{o.cam.pivot_distance, o.cam.arm_length, o.cam.base_radius + rf, 20 * kDegHere};
    const double omega = 300 * 2 * kPiHere / 60, e_star = 206000.0 / (2 * (1 - 0.09));
    double peak = 0;
    for (int i = 0; i < 36000; ++i) {
      const double th = 2 * kPiHere * i / 36000;
      const Svaj3 q = Cycloidal(m.h, th);
      const double force = m.Force(th, 0.01 * q.a * omega * omega + 30 * q.s + 5);
      const double r_eff = rf * (1 - rf * m.Curvature(th));
      ASSERT_GT(r_eff, 0.0);
      if (force > 0) peak = std::max(peak, std::sqrt(force * e_star / (kPiHere * 10 * r_eff)));
    }
    EXPECT_LE(peak, 250.0 * (1 + 1e-5));
    EXPECT_GT(peak, 250.0 * (1 - 1e-3)) << "the limit binds";
  }
  EXPECT_LE(std::abs(rb[0] - rb[1]), 1e-3 * rb[0]) << rb[0] << " vs " << rb[1];
}

// The arm's loads belong to oscillating followers, the follower loads to translating ones: each
// refused for the other with exit 2, the path and what would fit; a knife edge on an arm gets the
// force but no stress.
TEST(DiscCamOscillatingRollerLoads, RefusalsAndTheKnifeEdge) {
  json o = OscillatingLoadsStudy();
  o.erase("arm_dynamics");
  o["dynamics"] = {{"speed_rpm", 300}, {"follower_mass_kg", 0.8}};
  o.erase("limits");
  camopt::testing::ExpectStudyRejected(o, "osc-roller-dynamics", "/dynamics", "takes \"arm_dynamics\"");
  json t = camopt::testing::Example("disc_cam_translating.json");
  t["arm_dynamics"] = {{"speed_rpm", 300}, {"arm_inertia_kg_m2", 0.01}};
  camopt::testing::ExpectStudyRejected(t, "trans-arm-dynamics", "/arm_dynamics", "takes \"dynamics\"");
  json s = OscillatingLoadsStudy();
  s.erase("arm_dynamics");
  camopt::testing::ExpectStudyRejected(s, "osc-roller-stress", "/limits/contact_stress_MPa", "arm_dynamics");

  json k = OscillatingLoadsStudy();
  k["follower"] = {{"type", "oscillating_knife_edge"}, {"pivot_distance_mm", 100}, {"arm_length_mm", 80}};
  k["base_circle_radius_mm"] = 50;  // r₀ = 50 mm as the roller's
  k.erase("limits");
  k.erase("tolerances");
  k["analysis"] = {{"angle_steps", 3600}, {"evaluate", {"profile"}}};
  const studies::Node root(&k, "study.json", "");
  const studies::disc_cam::Study ks = studies::disc_cam::Parse(root);
  studies::RunContext ctx;
  ctx.quiet = true;
  const studies::disc_cam::Result kr = studies::disc_cam::Run(ks, ctx);
  const json out = studies::WriteResult(kr);
  ASSERT_TRUE(out.contains("arm_dynamics"));
  EXPECT_FALSE(out["arm_dynamics"].contains("max_contact_stress_MPa"));
  const Mechanism m{100, 80, 50, 20 * kDegHere};
  const double omega = 300 * 2 * kPiHere / 60;
  for (int i : {300, 573, 1200, 2400}) {
    const double th = 2 * kPiHere * i / 3600;
    const Svaj3 q = Cycloidal(m.h, th);
    const double moment = 0.01 * q.a * omega * omega + 30 * q.s + 5;
    EXPECT_NEAR(kr.loads->contact_force_N[size_t(i)], m.Force(th, moment), 1e-6 * std::abs(m.Force(th, moment))) << i;
  }
}

}  // namespace disc_cam_oscillating_roller_loads_test
}  // namespace camopt
