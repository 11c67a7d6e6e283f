// The oscillating arm's dynamic response (model/disc_cam/follower_dynamics.h, SimulateArm) against:
// - the rigid limit: with the train stiffness k_f = 10⁴ k the contact moment tends to the
//   kinetostatic closed form M = J ψ_c'' ω² + k ψ_c + M₀ + M_e (written out here with the 4-5-6-7
//   polynomial, and against kinetostatics.h's OscillatingRollerLoadAt), the gap shrinking as 1/k_f;
// - the dynamic jump speed of an independent fixed-step RK4 integration of the arm with its contact
//   switching, written here, scanned over the same speeds and bisected;
// - the residual-vibration spectrum (residual_spectrum.h): the undamped arm rings after a cycloidal
//   rise with r |h| A(τ)/h, r = k_f/(k_f + k);
// - the disc_cam study: the arm's response in result.json in the rigid limit (roller and flat face)
//   against the kinetostatic contact force, and bad input refused with exit 2 through the CLI.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/disc_cam/disc_cam.h"
#include "model/disc_cam/follower_dynamics.h"
#include "model/disc_cam/kinetostatics.h"
#include "model/disc_cam/residual_spectrum.h"
#include "studies/disc_cam_study.h"
#include "studies/study.h"
#include "tests/test_util.h"

namespace camopt::disc_cam {
namespace arm_dynamics_test {

using motion::MotionLaw;
using motion::MotionSegment;
using nlohmann::json;
constexpr double kDeg = kPi / 180.0;

// 4-5-6-7 rise of h over β, dwell 60°, return, dwell 60° (N = 35u⁴ − 84u⁵ + 70u⁶ − 20u⁷).
constexpr double kH = 20 * kDeg, kBeta = 120 * kDeg;
motion::MotionProgram<double> Poly4567Program() {
  return motion::MotionProgram<double>({MotionSegment<double>(MotionLaw::kPolynomial4567, kH, kBeta),
                                        MotionSegment<double>(MotionLaw::kDwell, 0.0, 60 * kDeg),
                                        MotionSegment<double>(MotionLaw::kPolynomial4567, -kH, kBeta),
                                        MotionSegment<double>(MotionLaw::kDwell, 0.0, 60 * kDeg)});
}
// ψ_c and ψ_c'' [rad, rad/rad²] of Poly4567Program, written out.
std::pair<double, double> Poly4567(double theta) {
  auto n = [](double u) { return u * u * u * u * (35 - 84 * u + 70 * u * u - 20 * u * u * u); };
  auto n2 = [](double u) { return u * u * (420 - 1680 * u + 2100 * u * u - 840 * u * u * u); };
  if (theta < kBeta) return {kH * n(theta / kBeta), kH * n2(theta / kBeta) / (kBeta * kBeta)};
  if (theta < kBeta + 60 * kDeg) return {kH, 0.0};
  const double t = theta - kBeta - 60 * kDeg;
  if (t < kBeta) return {kH - kH * n(t / kBeta), -kH * n2(t / kBeta) / (kBeta * kBeta)};
  return {0.0, 0.0};
}

ArmLoads Loads() {
  ArmLoads a;
  a.inertia_kg_m2 = 0.01;
  a.spring_rate_N_m_per_rad = 30.0;
  a.spring_preload_N_m = 4.0;
  a.external_moment_N_m = 1.0;
  return a;
}

// The largest |M_a − M| over the last revolution's samples, relative to the largest |M|.
double RigidGap(double stiffness, const DiscCam* cam) {
  ArmDynamicsInput in;
  in.motion = Poly4567Program();
  in.loads = Loads();
  in.arm_stiffness_N_m_per_rad = stiffness;
  in.damping_ratio = 0.05;
  in.speed_rad_s = RadPerSecond(300.0);
  const ArmDynamicsResult r = SimulateArm(in);
  EXPECT_FALSE(r.separates);
  const ArmLoads a = Loads();
  const double w = in.speed_rad_s;
  double gap = 0, peak = 0;
  for (const ArmDynamicsSample& q : r.samples) {
    const auto [psi, d2psi] = Poly4567(q.cam_angle_deg * kDeg);
    const double m = a.inertia_kg_m2 * d2psi * w * w + a.spring_rate_N_m_per_rad * psi + a.spring_preload_N_m +
                     a.external_moment_N_m;
    EXPECT_NEAR(q.kinetostatic_moment_N_m, m, 1e-9 * std::abs(m));
    if (cam) {
      const double ks = OscillatingRollerLoadAt(EvaluateCam(*cam, q.cam_angle_deg * kDeg), a, w).moment;
      EXPECT_NEAR(ks, m, 1e-9 * std::abs(m));
    }
    gap = std::max(gap, std::abs(q.contact_moment_N_m - m));
    peak = std::max(peak, std::abs(m));
  }
  EXPECT_EQ(r.samples.size(), 720u);
  EXPECT_NEAR(r.natural_frequency_Hz, std::sqrt((stiffness + 30.0) / 0.01) / (2 * kPi), 1e-9);
  return gap / peak;
}

TEST(ArmDynamics, RigidLimitTendsToTheKinetostaticMoment) {
  DiscCam cam;
  cam.follower = FollowerType::kOscillatingRoller;
  cam.base_radius = 40;
  cam.roller_radius = 10;
  cam.pivot_distance = 100;
  cam.arm_length = 80;
  cam.motion = Poly4567Program();
  const double stiff = RigidGap(1e4 * 30.0, &cam), softer = RigidGap(1e3 * 30.0, nullptr);
  // k_f = 10⁴ k: within 0.1 % of the largest moment; the gap shrinks as 1/k_f (the quasi-static
  // correction −(J/k_f) d²M/dt² of the lumped model): ten times stiffer, about ten times smaller.
  std::printf("rigid-limit gap / peak moment: k_f = 1e4 k: %.3e, 1e3 k: %.3e\n", stiff, softer);
  EXPECT_LT(stiff, 1e-3);
  EXPECT_GT(softer / stiff, 6.0);
  EXPECT_LT(softer / stiff, 14.0);
}

// ---- An independent arm: fixed-step RK4 with contact switching (equations of follower_dynamics.h).
constexpr double kRise = 20 * kDeg, kStroke = 90 * kDeg;
// Cycloidal rise over 90°, dwell 90°, cycloidal return over 90°, dwell 90°: ψ_c and ψ̇_c/ω.
std::pair<double, double> Cycloid(double theta) {
  theta = std::fmod(theta, 2 * kPi);
  auto rise = [](double u) {
    return std::pair{kRise * (u - std::sin(2 * kPi * u) / (2 * kPi)), kRise * (1 - std::cos(2 * kPi * u)) / kStroke};
  };
  if (theta < kStroke) return rise(theta / kStroke);
  if (theta < 2 * kStroke) return {kRise, 0.0};
  if (theta < 3 * kStroke) {
    const auto [s, v] = rise((theta - 2 * kStroke) / kStroke);
    return {kRise - s, -v};
  }
  return {0.0, 0.0};
}
motion::MotionProgram<double> CycloidProgram() {
  return motion::MotionProgram<double>({MotionSegment<double>(MotionLaw::kCycloidal, kRise, kStroke),
                                        MotionSegment<double>(MotionLaw::kDwell, 0.0, kStroke),
                                        MotionSegment<double>(MotionLaw::kCycloidal, -kRise, kStroke),
                                        MotionSegment<double>(MotionLaw::kDwell, 0.0, kStroke)});
}
constexpr double kJ = 0.01, kK = 20.0, kM0 = 5.0, kKf = 2000.0, kZeta = 0.05;

// Does the RK4 arm leave the cam during its third revolution at speed w?
bool Rk4Separates(double w) {
  const double K = kKf + kK, c = 2 * kZeta * std::sqrt(kJ * K), wn = std::sqrt(K / kJ);
  const double period = 2 * kPi / w, h0 = std::min(2 * kPi / wn / 400, 0.25 * kDeg / w);
  const int per_rev = int(std::ceil(period / h0));
  const double h = period / per_rev;
  double psi = -kM0 / K, dpsi = 0.0;  // static on the base circle
  bool contact = true;
  auto moment = [&](double t, double p, double dp) {
    const auto [s, v] = Cycloid(w * t);
    return kKf * (s - p) + c * (v * w - dp);
  };
  auto accel = [&](double t, double p, double dp) {
    const double m = contact ? moment(t, p, dp) : 0.0;
    return (m - kK * p - kM0) / kJ;
  };
  for (int i = 0; i < 3 * per_rev; ++i) {
    const double t = i * h;
    const double k1p = dpsi, k1v = accel(t, psi, dpsi);
    const double k2p = dpsi + h / 2 * k1v, k2v = accel(t + h / 2, psi + h / 2 * k1p, dpsi + h / 2 * k1v);
    const double k3p = dpsi + h / 2 * k2v, k3v = accel(t + h / 2, psi + h / 2 * k2p, dpsi + h / 2 * k2v);
    const double k4p = dpsi + h * k3v, k4v = accel(t + h, psi + h * k3p, dpsi + h * k3v);
    psi += h / 6 * (k1p + 2 * k2p + 2 * k3p + k4p);
    dpsi += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    const double tn = t + h;
    if (contact && moment(tn, psi, dpsi) < 0.0) contact = false;
    else if (!contact && psi >= Cycloid(w * tn).first) contact = true;
    if (i >= 2 * per_rev && !contact) return true;
  }
  return false;
}

TEST(ArmDynamics, DynamicJumpSpeedMatchesAnIndependentRk4) {
  // Kinetostatic jump speed from its definition: ω² = min (k ψ_c + M₀)/(−J ψ_c'') over the rise's
  // decelerating half, ψ_c'' = 2π h sin(2πu)/β².
  double w2 = 1e300;
  for (int i = 1; i < 10000; ++i) {
    const double u = 0.5 + 0.5 * i / 10000.0;
    const double s = kRise * (u - std::sin(2 * kPi * u) / (2 * kPi)), a = 2 * kPi * kRise * std::sin(2 * kPi * u) / (kStroke * kStroke);
    w2 = std::min(w2, (kK * s + kM0) / (-kJ * a));
  }
  const double upper = 1.5 * std::sqrt(w2);
  ArmDynamicsInput in;
  in.motion = CycloidProgram();
  in.loads.inertia_kg_m2 = kJ;
  in.loads.spring_rate_N_m_per_rad = kK;
  in.loads.spring_preload_N_m = kM0;
  in.arm_stiffness_N_m_per_rad = kKf;
  in.damping_ratio = kZeta;
  const DynamicJumpSpeed ours = FindArmDynamicJumpSpeed(in, upper, 30, 1e-3);
  ASSERT_TRUE(ours.found);
  // The same scan and bisection on the RK4 arm.
  const double step = upper / 30;
  double lo = 0, hi = 0;
  for (int k = 1; k <= 30; ++k) {
    if (Rk4Separates(k * step)) {
      hi = k * step;
      break;
    }
    lo = k * step;
  }
  ASSERT_GT(hi, 0.0);
  while (hi - lo > 1e-3 * hi) {
    const double mid = 0.5 * (lo + hi);
    (Rk4Separates(mid) ? hi : lo) = mid;
  }
  const double widths = (ours.speed_rad_s - ours.lower_rad_s) + (hi - lo);
  EXPECT_NEAR(ours.speed_rad_s, hi, widths) << "CVODE [" << ours.lower_rad_s << ", " << ours.speed_rad_s << "], RK4 ["
                                            << lo << ", " << hi << "], kinetostatic " << std::sqrt(w2);
  // The flexible arm leaves the cam below the rigid one's jump speed here (τ ≈ 3 rings the dwell).
  EXPECT_LT(ours.speed_rad_s, std::sqrt(w2));
  std::printf("dynamic jump [rad/s]: CVODE [%.6f, %.6f], RK4 [%.6f, %.6f], kinetostatic %.6f\n", ours.lower_rad_s,
              ours.speed_rad_s, lo, hi, std::sqrt(w2));
  RecordProperty("cvode_bracket", std::to_string(ours.lower_rad_s) + " " + std::to_string(ours.speed_rad_s));
  RecordProperty("rk4_bracket", std::to_string(lo) + " " + std::to_string(hi));
}

TEST(ArmDynamics, UndampedRingingMatchesTheResidualSpectrum) {
  // Cycloidal rise at τ = 1.3, return at τ = 2 (a zero of its spectrum): both dwells ring with r h A(1.3).
  const double wn = std::sqrt((kKf + kK) / kJ), rise = 100 * kDeg, ret = 2.0 / 1.3 * rise;
  ArmDynamicsInput in;
  in.motion = motion::MotionProgram<double>({MotionSegment<double>(MotionLaw::kCycloidal, kRise, rise),
                                             MotionSegment<double>(MotionLaw::kDwell, 0.0, 40 * kDeg),
                                             MotionSegment<double>(MotionLaw::kCycloidal, -kRise, ret),
                                             MotionSegment<double>(MotionLaw::kDwell, 0.0, 2 * kPi - rise - ret - 40 * kDeg)});
  in.loads.inertia_kg_m2 = kJ;
  in.loads.spring_rate_N_m_per_rad = kK;
  in.loads.spring_preload_N_m = 2000.0;  // no separation (the ringing swings k_f ψ by about 170 N·m)
  in.arm_stiffness_N_m_per_rad = kKf;
  in.damping_ratio = 0.0;
  in.speed_rad_s = rise * wn / (2 * kPi * 1.3);
  in.revolutions = 1;
  in.relative_tolerance = 1e-11;
  in.absolute_tolerance = 1e-12;
  const ArmDynamicsResult r = SimulateArm(in);
  ASSERT_FALSE(r.separates);
  const double a = std::abs(std::sin(kPi * 1.3)) / (kPi * 1.3 * (1.3 * 1.3 - 1.0));  // cycloidal, closed form
  std::printf("arm ringing: simulated %.10e rad, r h A(1.3) %.10e rad\n", r.residual_vibration_rad, kKf / (kKf + kK) * kRise * a);
  EXPECT_NEAR(r.residual_vibration_rad, kKf / (kKf + kK) * kRise * a, 1e-6 * kRise * a);
}

// ---- The disc_cam study.
json ArmStudy(const std::string& example, double stiffness) {
  json j = camopt::testing::Example(example);
  j["arm_dynamics"] = {{"speed_rpm", 300}, {"arm_inertia_kg_m2", 0.01}, {"spring_rate_N_m_per_rad", 30},
                       {"spring_preload_N_m", 4}, {"external_moment_N_m", 1},
                       {"arm_stiffness_N_m_per_rad", stiffness}};
  j["motion"] = json::parse(R"([ { "law": "poly_4567", "rise_deg": 20, "cam_angle_deg": 120 },
                                  { "law": "dwell", "cam_angle_deg": 60 },
                                  { "law": "poly_4567", "rise_deg": -20, "cam_angle_deg": 120 },
                                  { "law": "dwell", "cam_angle_deg": 60 } ])");
  j["analysis"] = {{"angle_steps", 720}, {"monte_carlo", false}};
  j.erase("tolerances");
  return j;
}

json RunStudy(const json& file) {
  const studies::Node root(&file, "study.json", "");
  const studies::disc_cam::Study s = studies::disc_cam::Parse(root);
  studies::RunContext ctx;
  ctx.quiet = true;
  return studies::WriteResult(studies::disc_cam::Run(s, ctx));
}

// In the rigid limit the study's dynamic contact force (M_a over the normal's lever arm) meets the
// kinetostatic one's extremes, for a roller (n · dC/dξ) and a flat face (ℓ).
TEST(ArmDynamics, StudyResponseInTheRigidLimitMeetsTheKinetostaticForce) {
  for (const char* example : {"disc_cam_oscillating.json", "disc_cam_oscillating_flat_faced.json"}) {
    const json out = RunStudy(ArmStudy(example, 3e5));
    const json& aj = out["arm_dynamics"];
    ASSERT_TRUE(aj.contains("response")) << example;
    const json& rj = aj["response"];
    const double fmax = aj["max_contact_force_N"], fmin = aj["min_contact_force_N"];
    std::printf("%s: dynamic force [%.6f, %.6f] N, kinetostatic [%.6f, %.6f] N\n", example,
                rj["min_contact_force_N"].get<double>(), rj["max_contact_force_N"].get<double>(), fmin, fmax);
    EXPECT_NEAR(rj["max_contact_force_N"].get<double>(), fmax, 2e-3 * fmax) << example;
    EXPECT_NEAR(rj["min_contact_force_N"].get<double>(), fmin, 2e-3 * fmax) << example;
    EXPECT_EQ(rj["separates"], false);
    EXPECT_TRUE(aj.contains("dynamic_jump_speed_rpm"));
    ASSERT_TRUE(aj.contains("residual_spectrum")) << example;
    EXPECT_EQ(aj["residual_spectrum"]["segments"].size(), 2u);
    // τ of the rise at the speed: (β/ω) f_n.
    const double fn = std::sqrt((3e5 + 30) / 0.01) / (2 * kPi);
    EXPECT_NEAR(aj["residual_spectrum"]["segments"][0]["tau"].get<double>(), kBeta / RadPerSecond(300) * fn, 1e-9);
  }
}

// A critically damped arm does not ring: no spectrum, a note says why; the response is still reported.
TEST(ArmDynamics, CriticallyDampedArmHasNoSpectrum) {
  json file = ArmStudy("disc_cam_oscillating.json", 2000.0);
  file["arm_dynamics"]["damping_ratio"] = 1.0;
  const json out = RunStudy(file);
  EXPECT_TRUE(out["arm_dynamics"].contains("response"));
  EXPECT_FALSE(out["arm_dynamics"].contains("residual_spectrum"));
  bool noted = false;
  for (const json& n : out["notes"]) noted = noted || n.get<std::string>().find("no residual_spectrum") != std::string::npos;
  EXPECT_TRUE(noted) << out["notes"].dump();
}

// Through the CLI: the response and spectrum files, the chart in report.html, and the same study
// giving byte-identical outputs twice.
TEST(ArmDynamics, CliWritesTheResponseAndTheSpectrumIdentically) {
  namespace fs = std::filesystem;
  const auto dir = camopt::testing::TempDir("arm-dynamics-cli");
  json study = ArmStudy("disc_cam_oscillating.json", 2000.0);
  camopt::testing::WriteFile(dir / "study.json", study.dump());
  for (const char* out : {"a", "b"}) {
    const auto res = camopt::testing::RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " +
                                                (dir / out).string());
    ASSERT_EQ(res.exit_code, 0) << res.stderr_text;
  }
  for (const char* file : {"result.json", "arm_response.csv", "arm_response.svg", "residual_spectrum.csv",
                           "residual_spectrum_operating.csv", "residual_spectrum.svg", "report.html"}) {
    ASSERT_TRUE(fs::exists(dir / "a" / file)) << file;
    EXPECT_EQ(camopt::testing::ReadFile(dir / "a" / file), camopt::testing::ReadFile(dir / "b" / file)) << file;
  }
  const std::string report = camopt::testing::ReadFile(dir / "a" / "report.html");
  EXPECT_NE(report.find("residual-vibration spectrum"), std::string::npos);
  EXPECT_NE(report.find("residual_spectrum.svg"), std::string::npos);
  const std::string csv = camopt::testing::ReadFile(dir / "a" / "residual_spectrum.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "tau,amplitude_per_rise_segment_0,amplitude_per_rise_segment_2");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), studies::disc_cam::kSpectrumPoints + 1);
  const json out = json::parse(camopt::testing::ReadFile(dir / "a" / "result.json"));
  EXPECT_EQ(out["arm_dynamics"]["response"]["separates"], false);
  EXPECT_TRUE(out["arm_dynamics"]["dynamic_jump_speed_rpm"].is_number());
}

TEST(ArmDynamics, BadInputExitsTwoThroughTheCli) {
  const auto dir = camopt::testing::TempDir("arm-dynamics-bad");
  struct Case {
    const char* field;
    json value;
  };
  for (const Case& c : {Case{"arm_stiffness_N_m_per_rad", -5.0}, Case{"arm_stiffness_N_m_per_rad", 0.0},
                        Case{"damping_ratio", 1.5}, Case{"revolutions", 0}, Case{"arm_stiffness_N_m_per_rad", "stiff"}}) {
    json study = ArmStudy("disc_cam_oscillating.json", 3e5);
    study["arm_dynamics"][c.field] = c.value;
    camopt::testing::WriteFile(dir / "study.json", study.dump());
    const auto res = camopt::testing::RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " +
                                                (dir / "out").string());
    EXPECT_EQ(res.exit_code, 2) << c.field << " " << c.value.dump() << ": " << res.stderr_text;
    EXPECT_NE(res.stderr_text.find(c.field), std::string::npos) << res.stderr_text;
  }
  // The arm's stiffness on a translating follower: its block is refused.
  json translating = camopt::testing::Example("disc_cam_translating.json");
  translating["arm_dynamics"] = ArmStudy("disc_cam_oscillating.json", 3e5)["arm_dynamics"];
  camopt::testing::WriteFile(dir / "study.json", translating.dump());
  const auto res = camopt::testing::RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " +
                                              (dir / "out").string());
  EXPECT_EQ(res.exit_code, 2) << res.stderr_text;
}

}  // namespace arm_dynamics_test
}  // namespace camopt::disc_cam
