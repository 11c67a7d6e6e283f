// Kinetostatic loads of a translating roller follower (model/disc_cam/kinetostatics.h) and the
// disc_cam study's "dynamics" block: Rothbart's cam-surface load example in SI, the camshaft torque
// against the power balance, the jump speed against its closed form (written out here) and against
// a bisection on the speed of the smallest contact force, and the Hertz stress on the base circle.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/disc_cam/disc_cam.h"
#include "model/disc_cam/kinetostatics.h"
#include "studies/disc_cam_study.h"
#include "studies/study.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt::disc_cam {
namespace disc_cam_dynamics_test {

using nlohmann::json;
using testing::DiscCamPaperExample;
constexpr double kDeg = kPi / 180.0;
constexpr double kLbf = 4.4482216152605;  // N (exact by definition of the pound-force)
constexpr double kInch = 0.0254;          // m

// Rothbart, Cam Design Handbook, Fig. 8.7 (load on the cam surface): follower weight 2 lb, external
// load 10 lb, spring force 30 lb; inertia force +104 lb at +20,200 in/s² and −35 lb at −6,750 in/s².
// By hand: m = 2 lb / 386.09 in/s²; m·a = 2/386.09 × 20,200 = 104.64 lb and 2/386.09 × 6,750 =
// 34.97 lb; the load on the cam 2 + 10 + 30 + 104.64 = 146.64 lb and 2 + 10 + 30 − 34.97 = 7.03 lb.
// Here in SI through FollowerAxialForce (ω = 1 rad/s, so S'' in mm/rad² is the acceleration in mm/s²).
TEST(DiscCamLoads, RothbartCamSurfaceLoadInSi) {
  FollowerLoads f;
  f.mass_kg = 2 * kLbf / kStandardGravity;  // 0.90718 kg
  f.spring_preload_N = 30 * kLbf;           // the spring force, constant over the example
  f.external_load_N = 10 * kLbf;
  f.weight_N = f.mass_kg * kStandardGravity;  // vertical follower above the cam: 2 lb
  const double a_up = 20200 * kInch * 1e3, a_down = -6750 * kInch * 1e3;  // mm/s²
  const double inertia_up = FollowerAxialForce(f, 0.0, a_up, 1.0) - FollowerStaticForce(f, 0.0);
  const double inertia_down = FollowerAxialForce(f, 0.0, a_down, 1.0) - FollowerStaticForce(f, 0.0);
  EXPECT_NEAR(inertia_up / kLbf, 2.0 / 386.0886 * 20200, 1e-3);   // 104.64 lb (Rothbart: 104)
  EXPECT_NEAR(inertia_down / kLbf, -2.0 / 386.0886 * 6750, 1e-3);  // −34.97 lb (Rothbart: −35)
  EXPECT_NEAR(inertia_up / kLbf, 104.0, 1.0);
  EXPECT_NEAR(inertia_down / kLbf, -35.0, 0.05);
  EXPECT_NEAR(FollowerAxialForce(f, 0.0, a_up, 1.0) / kLbf, 146.64, 5e-3);
  EXPECT_NEAR(FollowerAxialForce(f, 0.0, a_down, 1.0) / kLbf, 7.03, 5e-3);
  EXPECT_NEAR(FollowerAxialForce(f, 0.0, a_up, 1.0), 652.28, 5e-2);  // N
}

std::vector<CamPoint<double>> Grid(const DiscCam& cam, int n) {
  std::vector<CamPoint<double>> pts;
  for (int i = 0; i < n; ++i) pts.push_back(EvaluateCam(cam, 2 * kPi * i / n));
  return pts;
}

FollowerLoads SpringLoaded() {
  FollowerLoads f;
  f.mass_kg = 0.8;
  f.spring_rate_N_per_mm = 2.0;
  f.spring_preload_N = 40.0;
  f.external_load_N = 15.0;
  f.weight_N = 0.8 * kStandardGravity;
  return f;
}

// The camshaft torque from the moment of F_c about the cam axis equals the power balance
// T ω = F_y dS/dt, i.e. T = F_y S'(θ), at every angle of the paper's offset follower.
TEST(DiscCamLoads, CamshaftTorqueIsThePowerBalance) {
  const DiscCam cam = DiscCamPaperExample();
  const FollowerLoads f = SpringLoaded();
  const double omega = RadPerSecond(300.0);
  for (const CamPoint<double>& p : Grid(cam, 720)) {
    const CamLoad<double> c = CamLoadAt(p, f, omega);
    const double fy = f.mass_kg * p.d2s * omega * omega * 1e-3 + 2.0 * p.s + 40.0 + 15.0 + 0.8 * kStandardGravity;
    EXPECT_NEAR(c.axial_force, fy, 1e-9 * std::abs(fy));
    EXPECT_NEAR(c.contact_force, fy / std::cos(p.pressure_angle), 1e-9 * std::abs(fy));
    EXPECT_NEAR(c.camshaft_torque, fy * p.ds, 1e-9 * (1 + std::abs(fy * p.ds))) << p.theta / kDeg;
  }
}

// The jump speed: the closed form, written here over the cycloidal rise and return of the
// paper's example (S'' = 2π h/β² sin 2πu), and a bisection on the speed at which the smallest
// contact force of CamLoadAt reaches zero.
TEST(DiscCamLoads, JumpSpeedClosedFormAndBisection) {
  const DiscCam cam = DiscCamPaperExample();
  const FollowerLoads f = SpringLoaded();
  const int n = 3600;
  const std::vector<CamPoint<double>> pts = Grid(cam, n);
  const double beta = 120 * kDeg;
  double w2 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const double th = 2 * kPi * i / n;
    double s = 0, a = 0;
    if (th < beta) {  // rise 24 mm
      const double u = th / beta;
      s = 24 * (u - std::sin(2 * kPi * u) / (2 * kPi));
      a = 24 * 2 * kPi / (beta * beta) * std::sin(2 * kPi * u);
    } else if (th < 170 * kDeg) {
      s = 24;
    } else if (th < 290 * kDeg) {  // return
      const double u = (th - 170 * kDeg) / beta;
      s = 24 - 24 * (u - std::sin(2 * kPi * u) / (2 * kPi));
      a = -24 * 2 * kPi / (beta * beta) * std::sin(2 * kPi * u);
    }
    if (a < 0) w2 = std::min(w2, (2.0 * s + 40.0 + 15.0 + 0.8 * kStandardGravity) / (-0.8 * a * 1e-3));
  }
  const double jump = JumpSpeed(pts, f);
  EXPECT_NEAR(jump, std::sqrt(w2), 1e-9 * std::sqrt(w2));
  auto min_force = [&](double omega) {
    double m = std::numeric_limits<double>::infinity();
    for (const auto& p : pts) m = std::min(m, CamLoadAt(p, f, omega).contact_force);
    return m;
  };
  double lo = 0.0, hi = 10 * jump;
  ASSERT_GT(min_force(lo), 0.0);
  ASSERT_LT(min_force(hi), 0.0);
  for (int k = 0; k < 100; ++k) (min_force(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
  EXPECT_NEAR(0.5 * (lo + hi), jump, 1e-9 * jump);
  EXPECT_GT(Rpm(jump), 100.0);  // a plausible size: this cam jumps at about 1000 rpm
  // A follower that never decelerates never jumps; one that is pulled off at rest jumps at 0.
  EXPECT_TRUE(std::isinf(JumpSpeed({pts[0]}, f)));
  FollowerLoads pulled = f;
  pulled.external_load_N = -1000.0;
  EXPECT_EQ(JumpSpeed(pts, pulled), 0.0);
}

// The spring that keeps contact up to a speed, against the closed form written here from the
// paper's cycloidal rise and return (S, S'' by hand, as above): F₀,min = max −(min(0, m S'' ω²) +
// k S + P + W) and k_min = max over S > 0 of −(min(0, m S'' ω²) + F₀ + P + W)/S; then the claim
// checked: with that preload (or rate) the smallest contact force over the cam at ω is zero, and
// positive at every lower speed tried.
TEST(DiscCamLoads, SpringThatKeepsContactUpToASpeed) {
  const DiscCam cam = DiscCamPaperExample();
  const FollowerLoads f = SpringLoaded();
  const int n = 3600;
  const std::vector<CamPoint<double>> pts = Grid(cam, n);
  const double omega = 2.0 * JumpSpeed(pts, f), beta = 120 * kDeg;
  double f0 = 0, k = 0;
  for (int i = 0; i < n; ++i) {
    const double th = 2 * kPi * i / n;
    double s = 0, a = 0;
    if (th < beta) {
      const double u = th / beta;
      s = 24 * (u - std::sin(2 * kPi * u) / (2 * kPi));
      a = 24 * 2 * kPi / (beta * beta) * std::sin(2 * kPi * u);
    } else if (th < 170 * kDeg) {
      s = 24;
    } else if (th < 290 * kDeg) {
      const double u = (th - 170 * kDeg) / beta;
      s = 24 - 24 * (u - std::sin(2 * kPi * u) / (2 * kPi));
      a = -24 * 2 * kPi / (beta * beta) * std::sin(2 * kPi * u);
    }
    const double rest = std::min(0.0, 0.8 * a * 1e-3 * omega * omega) + 15.0 + 0.8 * kStandardGravity;
    f0 = std::max(f0, -(rest + 2.0 * s));
    if (s > 1e-12) k = std::max(k, -(rest + 40.0) / s);
  }
  const SpringRequirement r = RequiredSpringOver(pts, f, omega);
  EXPECT_NEAR(r.min_preload_N, f0, 1e-9 * f0);
  EXPECT_NEAR(r.min_rate_N_per_mm, k, 1e-9 * k);
  ASSERT_GT(f0, f.spring_preload_N);  // at twice the jump speed the study's spring is too weak
  auto min_force = [&](const FollowerLoads& g, double w) {
    double m = std::numeric_limits<double>::infinity();
    for (const auto& p : pts) m = std::min(m, CamLoadAt(p, g, w).contact_force);
    return m;
  };
  FollowerLoads preloaded = f;
  preloaded.spring_preload_N = r.min_preload_N;
  FollowerLoads stiffer = f;
  stiffer.spring_rate_N_per_mm = r.min_rate_N_per_mm;
  for (const FollowerLoads& g : {preloaded, stiffer}) {
    EXPECT_NEAR(min_force(g, omega), 0.0, 1e-9 * f0);
    for (double w : {0.0, 0.3 * omega, 0.7 * omega, 0.99 * omega}) EXPECT_GT(min_force(g, w), -1e-9 * f0) << w;
  }
  // A deficit on the base circle (pulled off at rest): no rate helps, only a preload.
  FollowerLoads pulled = f;
  pulled.external_load_N = -200.0;
  const SpringRequirement rp = RequiredSpringOver(pts, pulled, 0.0);
  EXPECT_TRUE(std::isinf(rp.min_rate_N_per_mm));
  EXPECT_NEAR(rp.min_preload_N, 200.0 - 0.8 * kStandardGravity, 1e-9);
}

// On the base circle the roller is a cylinder of r_f on a cylinder of r_b (both convex):
// R' = r_f r_b/(r_f + r_b) = 8 mm for the paper's cam, and the Hertz line-contact pressure
// p₀ = sqrt(F E*/(π w R')) with F = (F₀ + P + W)/cos φ (no acceleration, S = 0 in the dwell).
TEST(DiscCamLoads, HertzStressOnTheBaseCircle) {
  const DiscCam cam = DiscCamPaperExample();
  const CamPoint<double> p = EvaluateCam(cam, 330 * kDeg);
  EXPECT_NEAR(RollerCamEffectiveRadius(p, 10.0), 8.0, 1e-9);
  const FollowerLoads f = SpringLoaded();
  const double F = (40.0 + 15.0 + 0.8 * kStandardGravity) / std::cos(std::atan(-12.0 / std::sqrt(2500.0 - 144.0)));
  const double e_star = 206000.0 / (2 * (1 - 0.09));
  const CamLoad<double> c = CamLoadAt(p, f, RadPerSecond(500.0));
  EXPECT_NEAR(c.contact_force, F, 1e-9 * F);
  EXPECT_NEAR(RollerCamContactStress(p, 10.0, c.contact_force, 12.0, e_star),
              std::sqrt(F * e_star / (kPi * 12.0 * 8.0)), 1e-9);
  EXPECT_EQ(RollerCamContactStress(p, 10.0, -1.0, 12.0, e_star), 0.0);  // no contact, no stress
}

// ---- The study: "dynamics", the separation and stress limits, and the refusals.
namespace ds = studies::disc_cam;

json DynamicsStudy() {
  json s = camopt::testing::Example("disc_cam_translating.json");
  s.erase("tolerances");
  s["analysis"] = {{"evaluate", {"profile"}}};
  s["dynamics"] = {{"speed_rpm", 300}, {"follower_mass_kg", 0.8}, {"spring_rate_N_per_mm", 2},
                   {"spring_preload_N", 40}, {"external_load_N", 15}};
  s["face_width_mm"] = 12;
  s["material"] = {{"youngs_modulus_GPa", 206}, {"poisson_ratio", 0.3}};
  s["limits"] = {{"pressure_angle_deg", 31}, {"contact_stress_MPa", 1500}};
  return s;
}

ds::Result RunFile(const json& file, ds::Study* study = nullptr) {
  const studies::Node root(&file, "study.json", "");
  const ds::Study st = ds::Parse(root);
  studies::RunContext ctx;
  ctx.quiet = true;
  if (study) *study = st;
  return ds::Run(st, ctx);
}

TEST(DiscCamStudyDynamics, ReportsForcesTorqueJumpSpeedAndStress) {
  ds::Study st;
  const ds::Result r = RunFile(DynamicsStudy(), &st);
  ASSERT_TRUE(r.loads.has_value());
  const ds::Result::Loads& L = *r.loads;
  // The same numbers as the model over the study's grid (3600 steps).
  const std::vector<CamPoint<double>> pts = Grid(DiscCamPaperExample(), 3600);
  EXPECT_NEAR(L.jump_speed_rpm, Rpm(JumpSpeed(pts, SpringLoaded())), 1e-9);
  EXPECT_NEAR(L.weight_N, 0.8 * 9.80665, 1e-12);
  // On the base circle dwell the contact force is the static one (above); the smallest force is
  // on the return's deceleration, still positive at 300 rpm, well below the jump speed.
  EXPECT_GT(L.min_contact_force_N.value, 0.0);
  EXPECT_LT(300.0, L.jump_speed_rpm);
  const json j = studies::WriteResult(r);
  EXPECT_EQ(j["dynamics"]["separation_ok"], true);
  EXPECT_EQ(j["dynamics"]["contact_stress_ok"], true);
  EXPECT_EQ(j["limits_ok"], true);
  // The peak stress is at least that of the base circle (closed form as in HertzStressOnTheBaseCircle).
  const double f_base = (40.0 + 15.0 + 0.8 * kStandardGravity) / std::cos(std::atan(-12.0 / std::sqrt(2500.0 - 144.0)));
  const double e_star = 206000.0 / (2 * (1 - 0.09));
  EXPECT_GE(j["dynamics"]["max_contact_stress_MPa"].get<double>(), std::sqrt(f_base * e_star / (kPi * 12.0 * 8.0)));
  EXPECT_NEAR(j["dynamics"]["composite_modulus_MPa"].get<double>(), e_star, 1e-9);
  // Above the jump speed the follower separates: min contact force < 0, separation fails.
  json fast = DynamicsStudy();
  fast["dynamics"]["speed_rpm"] = 1.05 * L.jump_speed_rpm;
  ds::Study st2;
  const ds::Result r2 = RunFile(fast, &st2);
  EXPECT_LT(r2.loads->min_contact_force_N.value, 0.0);
  const json j2 = studies::WriteResult(r2);
  EXPECT_EQ(j2["dynamics"]["separation_ok"], false);
  EXPECT_EQ(j2["limits_ok"], false);
  // And just below it, it holds.
  fast["dynamics"]["speed_rpm"] = 0.95 * L.jump_speed_rpm;
  EXPECT_GT(RunFile(fast).loads->min_contact_force_N.value, 0.0);
  // Above the jump speed result.json says which preload (with this rate) would keep contact: with
  // it the study holds the cam, its smallest force is zero and its jump speed is the speed.
  fast["dynamics"]["speed_rpm"] = 1.2 * L.jump_speed_rpm;
  ds::Study st3;
  const ds::Result r3 = RunFile(fast, &st3);
  const double preload = studies::WriteResult(r3)["dynamics"]["min_spring_preload_N"].get<double>();
  EXPECT_GT(preload, 40.0);
  fast["dynamics"]["spring_preload_N"] = preload;
  const ds::Result r4 = RunFile(fast);
  EXPECT_NEAR(r4.loads->min_contact_force_N.value, 0.0, 1e-9 * preload);
  EXPECT_NEAR(r4.loads->jump_speed_rpm, 1.2 * L.jump_speed_rpm, 1e-9 * L.jump_speed_rpm);
}

TEST(DiscCamStudyDynamics, RefusalsNameWhatToAdd) {
  json s = DynamicsStudy();
  s.erase("face_width_mm");
  camopt::testing::ExpectStudyRejected(s, "disc-cam-no-width", "/limits/contact_stress_MPa", "face_width_mm");
  s = DynamicsStudy();
  s.erase("dynamics");
  camopt::testing::ExpectStudyRejected(s, "disc-cam-no-dynamics", "/limits/contact_stress_MPa", "dynamics");
  s = DynamicsStudy();
  s.erase("material");
  camopt::testing::ExpectStudyRejected(s, "disc-cam-no-material", "/limits/contact_stress_MPa", "material");
  json o = camopt::testing::Example("disc_cam_oscillating.json");
  o["dynamics"] = {{"speed_rpm", 300}, {"follower_mass_kg", 0.8}};
  camopt::testing::ExpectStudyRejected(o, "disc-cam-osc-dynamics", "/dynamics", "translating followers only");
  s = DynamicsStudy();
  s["dynamics"]["follower_axis"] = "sideways";
  camopt::testing::ExpectStudyRejected(s, "disc-cam-axis", "/dynamics/follower_axis", "horizontal");
  s = DynamicsStudy();
  s["dynamics"].erase("speed_rpm");
  camopt::testing::ExpectStudyRejected(s, "disc-cam-speed", "/dynamics/speed_rpm", "missing");
}

}  // namespace disc_cam_dynamics_test
}  // namespace camopt::disc_cam
