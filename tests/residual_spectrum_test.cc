// The residual-vibration spectrum (model/disc_cam/residual_spectrum.h) against:
// - the closed forms of the undamped cycloidal and simple-harmonic rises, derived here from the
//   Fourier transform of the rise's velocity (the spectra Koster, Vibrations of Cam Mechanisms, and
//   Rothbart, Cam Design Handbook, plot for these laws): cycloidal A/h = |sin πτ|/(πτ|τ² − 1|), simple harmonic
//   A/h = |cos πτ|/|4τ² − 1|, and their zeros (τ = 2, 3, … and τ = 3/2, 5/2, …);
// - an independent fixed-step RK4 integration, written here, of z̈ + 2ζω_n ż + ω_n² z = −ÿ over the
//   segment (damped, a modified trapezoid with its kinks and a B-spline), its free-vibration envelope
//   at the segment's end;
// - the CVODE simulation of the disc cam's follower (follower_dynamics.h): the residual vibration it
//   reports in the dwells equals r |h| A/h, r = k_f/(k_f + k_s), at the rise's τ (ζ = 0, the return
//   placed at a zero of its own spectrum so that it adds nothing).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/disc_cam/follower_dynamics.h"
#include "model/disc_cam/residual_spectrum.h"
#include "studies/disc_cam_study.h"
#include "studies/study.h"
#include "tests/test_util.h"

namespace camopt::disc_cam {
namespace residual_spectrum_test {

using motion::MotionLaw;
using motion::MotionSegment;
constexpr double kDeg = kPi / 180.0;

double CycloidalClosedForm(double tau) {
  if (std::abs(tau - 1.0) < 1e-12) return 0.5;
  return std::abs(std::sin(kPi * tau)) / (kPi * tau * std::abs(tau * tau - 1.0));
}
double HarmonicClosedForm(double tau) {
  if (std::abs(tau - 0.5) < 1e-12) return kPi / 4.0;
  return std::abs(std::cos(kPi * tau)) / std::abs(4.0 * tau * tau - 1.0);
}

// Fixed-step RK4 of the base-excited follower over the segment (T = 1 s, ω_n = 2πτ), from rest:
// the envelope √(z² + ((ż + ζω_n z)/ω_d)²)/|h| at the end.
double Rk4Residual(const MotionSegment<double>& seg, double zeta, double tau, int steps) {
  const double wn = 2 * kPi * tau, wd = wn * std::sqrt(1 - zeta * zeta);
  // The acceleration of the piece the step lies on: a law's jumps (u = 0, 1/2, 1 of the quadratic
  // parabola) fall on step boundaries, and each stage takes the value inside the step.
  double t0 = 0.0, h = 1.0 / steps;
  auto yddot = [&](double t) { return motion::MotionSegmentShape(seg, std::clamp(t, t0 + 1e-3 * h, t0 + h - 1e-3 * h)).a; };
  auto f = [&](double t, double z, double v, double* dz, double* dv) {
    *dz = v;
    *dv = -2 * zeta * wn * v - wn * wn * z - yddot(t);
  };
  double z = 0, v = 0;
  for (int i = 0; i < steps; ++i) {
    const double t = i * h;
    t0 = t;
    double k1z, k1v, k2z, k2v, k3z, k3v, k4z, k4v;
    f(t, z, v, &k1z, &k1v);
    f(t + h / 2, z + h / 2 * k1z, v + h / 2 * k1v, &k2z, &k2v);
    f(t + h / 2, z + h / 2 * k2z, v + h / 2 * k2v, &k3z, &k3v);
    f(t + h, z + h * k3z, v + h * k3v, &k4z, &k4v);
    z += h / 6 * (k1z + 2 * k2z + 2 * k3z + k4z);
    v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
  return std::hypot(z, (v + zeta * wn * z) / wd) / std::abs(seg.rise);
}

TEST(ResidualSpectrum, CycloidalMatchesItsClosedForm) {
  const MotionSegment<double> seg(MotionLaw::kCycloidal, 20.0, 100 * kDeg);
  for (double tau : {0.25, 0.5, 0.8, 1.0, 1.3, 1.5, 2.5, 3.7, 5.0, 7.25, 10.0, 14.6}) {
    const ResidualAmplitude a = ResidualAmplitudeAt(seg, 0.0, tau);
    EXPECT_NEAR(a.amplitude, CycloidalClosedForm(tau), 1e-10) << "tau " << tau;
    EXPECT_LT(a.error, 1e-9) << "tau " << tau;
  }
  // The amplitude is per unit rise: a return (negative rise) and another duration give the same.
  const MotionSegment<double> back(MotionLaw::kCycloidal, -3.0, 40 * kDeg);
  EXPECT_NEAR(ResidualSpectrum(back, 0.0, {1.3})[0], CycloidalClosedForm(1.3), 1e-10);
}

TEST(ResidualSpectrum, SimpleHarmonicMatchesItsClosedForm) {
  const MotionSegment<double> seg(MotionLaw::kSimpleHarmonic, 1.0, 60 * kDeg);
  const std::vector<double> tau = {0.3, 0.5, 0.9, 1.2, 2.0, 3.3, 6.1, 9.9};
  const std::vector<double> a = ResidualSpectrum(seg, 0.0, tau);
  for (size_t i = 0; i < tau.size(); ++i) EXPECT_NEAR(a[i], HarmonicClosedForm(tau[i]), 1e-10) << "tau " << tau[i];
}

TEST(ResidualSpectrum, ZerosOfTheCycloidalAndHarmonicSpectra) {
  const MotionSegment<double> cyc(MotionLaw::kCycloidal, 1.0, 1.0);
  const std::vector<SpectrumMinimum> m = ResidualSpectrumMinima(cyc, 0.0, 0.5, 10.0, 400);
  ASSERT_EQ(m.size(), 8u);  // τ = 2 … 9 (10 is the range's end)
  for (size_t i = 0; i < m.size(); ++i) {
    EXPECT_NEAR(m[i].tau, 2.0 + double(i), 1e-7);
    EXPECT_TRUE(m[i].zero);
    EXPECT_LT(m[i].amplitude, 1e-8);
  }
  const MotionSegment<double> shm(MotionLaw::kSimpleHarmonic, 1.0, 1.0);
  const std::vector<SpectrumMinimum> h = ResidualSpectrumMinima(shm, 0.0, 0.5, 5.0, 200);
  ASSERT_EQ(h.size(), 4u);  // τ = 1.5, 2.5, 3.5, 4.5
  for (size_t i = 0; i < h.size(); ++i) EXPECT_NEAR(h[i].tau, 1.5 + double(i), 1e-7);
}

TEST(ResidualSpectrum, AgreesWithAnIndependentRk4ForDampedKinkedAndSplineRises) {
  const MotionSegment<double> trap(MotionLaw::kModifiedTrapezoid, 5.0, 1.0);
  const MotionSegment<double> spline = motion::BSplineThrough<double>({0, 0, 0, 0.2, 0.8, 1, 1, 1}, 5, 1.0);
  const MotionSegment<double> quad(MotionLaw::kQuadraticParabola, 2.0, 1.0);
  for (const MotionSegment<double>* seg : {&trap, &spline, &quad})
    for (double zeta : {0.0, 0.05, 0.3})
      for (double tau : {0.7, 1.9, 4.3}) {
        const double ours = ResidualAmplitudeAt(*seg, zeta, tau).amplitude;
        // RK4's error is O(h⁴) on the smooth pieces; 40000 steps put it far below 1e-8 here.
        const double rk4 = Rk4Residual(*seg, zeta, tau, 40000);
        EXPECT_NEAR(ours, rk4, 1e-8) << "law " << int(seg->law) << " zeta " << zeta << " tau " << tau;
      }
}

TEST(ResidualSpectrum, RefusesBadInput) {
  const MotionSegment<double> cyc(MotionLaw::kCycloidal, 1.0, 1.0);
  EXPECT_THROW(ResidualAmplitudeAt(MotionSegment<double>(MotionLaw::kDwell, 0.0, 1.0), 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(ResidualAmplitudeAt(cyc, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(ResidualAmplitudeAt(cyc, 0.0, 0.0), std::invalid_argument);
}

// The disc cam's follower (CVODE, contact events) in the dwells after a cycloidal rise at τ = 1.3,
// undamped, with the cycloidal return at τ = 2 (a zero of its spectrum): the residual vibration is
// r |h| A(1.3)/h in both dwells.
TEST(ResidualSpectrum, EqualsTheSimulatedFollowersResidualVibration) {
  const double m = 1.0, kf = 1000.0, ks = 10.0, h = 20.0;
  const double wn = std::sqrt((kf + ks) / (m * 1e-3));
  const double rise = 100 * kDeg, tau_rise = 1.3, tau_return = 2.0;
  const double omega = rise * wn / (2 * kPi * tau_rise);  // τ = (β/ω)/(2π/ω_n)
  const double ret = tau_return / tau_rise * rise;
  FollowerDynamicsInput in;
  in.motion = motion::MotionProgram<double>({MotionSegment<double>(MotionLaw::kCycloidal, h, rise),
                                             MotionSegment<double>(MotionLaw::kDwell, 0.0, 40 * kDeg),
                                             MotionSegment<double>(MotionLaw::kCycloidal, -h, ret),
                                             MotionSegment<double>(MotionLaw::kDwell, 0.0, 2 * kPi - rise - ret - 40 * kDeg)});
  in.loads.mass_kg = m;
  in.loads.spring_rate_N_per_mm = ks;
  in.loads.spring_preload_N = 20000.0;  // no separation (peak inertia ≈ 1.9 kN)
  in.follower_stiffness_N_per_mm = kf;
  in.damping_ratio = 0.0;
  in.speed_rad_s = omega;
  in.revolutions = 1;
  in.relative_tolerance = 1e-11;
  in.absolute_tolerance = 1e-11;
  const FollowerDynamicsResult r = SimulateFollower(in);
  ASSERT_FALSE(r.separates);
  const double expected = kf / (kf + ks) * h * CycloidalClosedForm(tau_rise);
  const double spectrum = kf / (kf + ks) * h * ResidualAmplitudeAt(in.motion.segments()[0], 0.0, tau_rise).amplitude;
  EXPECT_NEAR(spectrum, expected, 1e-9);
  std::printf("follower ringing: simulated %.10e mm, r h A(1.3) %.10e mm\n", r.residual_vibration_mm, spectrum);
  EXPECT_NEAR(r.residual_vibration_mm, spectrum, 1e-6 * spectrum);
}

// The same check through the disc_cam study: result.json's residual_spectrum predicts, for the
// rise at the study's speed, the residual_vibration_mm its CVODE response reports (ζ = 0, one
// revolution from rest, the return at τ = 2).
TEST(ResidualSpectrum, StudysPredictionEqualsItsSimulatedResidualVibration) {
  const double kf = 1000.0, ks = 10.0, wn = std::sqrt((kf + ks) / 1e-3);  // m = 1 kg
  const double rise_deg = 100.0, return_deg = 2.0 / 1.3 * rise_deg;
  const double omega = rise_deg * kDeg * wn / (2 * kPi * 1.3);
  nlohmann::json file = camopt::testing::Example("disc_cam_translating.json");
  file["base_circle_radius_mm"] = 80;
  file["motion"] = {{{"law", "cycloidal"}, {"rise_mm", 20}, {"cam_angle_deg", rise_deg}},
                    {{"law", "dwell"}, {"cam_angle_deg", 40}},
                    {{"law", "cycloidal"}, {"rise_mm", -20}, {"cam_angle_deg", return_deg}},
                    {{"law", "dwell"}, {"cam_angle_deg", 360 - 40 - rise_deg - return_deg}}};
  file["dynamics"] = {{"speed_rpm", Rpm(omega)}, {"follower_mass_kg", 1.0}, {"spring_rate_N_per_mm", ks},
                      {"spring_preload_N", 20000}, {"follower_axis", "horizontal"},
                      {"follower_stiffness_N_per_mm", kf}, {"damping_ratio", 0.0}, {"revolutions", 1}};
  file["analysis"] = {{"angle_steps", 720}, {"monte_carlo", false}};
  file.erase("tolerances");
  const studies::Node root(&file, "study.json", "");
  const studies::disc_cam::Study st = studies::disc_cam::Parse(root);
  studies::RunContext ctx;
  ctx.quiet = true;
  const nlohmann::json out = studies::WriteResult(studies::disc_cam::Run(st, ctx));
  const nlohmann::json& dj = out["dynamics"];
  ASSERT_EQ(dj["response"]["separates"], false);
  const nlohmann::json& rise = dj["residual_spectrum"]["segments"][0];
  EXPECT_NEAR(rise["tau"].get<double>(), 1.3, 1e-9);
  EXPECT_NEAR(dj["residual_spectrum"]["segments"][1]["tau"].get<double>(), 2.0, 1e-9);
  EXPECT_NEAR(dj["residual_spectrum"]["segments"][1]["amplitude_per_rise"].get<double>(), 0.0, 1e-9);
  const double predicted = rise["predicted_residual_vibration_mm"], simulated = dj["response"]["residual_vibration_mm"];
  std::printf("study: predicted %.10e mm, simulated (CVODE, default tolerances) %.10e mm\n", predicted, simulated);
  EXPECT_NEAR(predicted, kf / (kf + ks) * 20.0 * CycloidalClosedForm(1.3), 1e-9);
  EXPECT_NEAR(simulated, predicted, 1e-5 * predicted);
  // The cycloidal rise's zeros in τ = 0.5 … 10: 2, 3, …, 9.
  ASSERT_EQ(rise["minima"].size(), 8u);
  EXPECT_NEAR(rise["minima"][0]["tau"].get<double>(), 2.0, 1e-7);
}

}  // namespace residual_spectrum_test
}  // namespace camopt::disc_cam
