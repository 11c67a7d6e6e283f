// The one-degree-of-freedom follower (model/disc_cam/follower_dynamics.h) against:
// - the closed-form response of the undamped follower in contact to a 3-4-5 polynomial rise
//   (written out here: for a polynomial input the particular solution is the finite series
//   x_p = (k_f/K)(S − S''/ω_n² + S''''/ω_n⁴) − F/K, plus the free vibration that meets the static
//   start), through the rise and the dwell after it, where the rise's residual vibration rings;
// - the rigid follower's kinetostatic force (kinetostatics.h) as k_f grows;
// - the kinetostatic jump speed (computed here from its definition): a stiff follower separates
//   just above it and not below; a flexible one separates earlier, below it.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "model/disc_cam/follower_dynamics.h"
#include "model/disc_cam/kinetostatics.h"

namespace camopt::disc_cam {
namespace follower_dynamics_test {

constexpr double kDeg = kPi / 180.0;
constexpr double kH = 20.0, kBeta = 120.0 * kDeg;  // 3-4-5 rise of 20 mm over 120°

motion::MotionProgram<double> RiseDwellReturnDwell() {
  using motion::MotionLaw;
  using motion::MotionSegment;
  return motion::MotionProgram<double>({MotionSegment<double>(MotionLaw::kPolynomial345, kH, kBeta),
                                        MotionSegment<double>(MotionLaw::kDwell, 0.0, 60 * kDeg),
                                        MotionSegment<double>(MotionLaw::kPolynomial345, -kH, kBeta),
                                        MotionSegment<double>(MotionLaw::kDwell, 0.0, 60 * kDeg)});
}

FollowerDynamicsInput Input(double stiffness, double zeta, double rpm) {
  FollowerDynamicsInput in;
  in.motion = RiseDwellReturnDwell();
  in.loads.mass_kg = 1.0;
  in.loads.spring_rate_N_per_mm = 10.0;
  in.loads.spring_preload_N = 200.0;
  in.follower_stiffness_N_per_mm = stiffness;
  in.damping_ratio = zeta;
  in.speed_rad_s = RadPerSecond(rpm);
  return in;
}

TEST(FollowerDynamics, UndampedRiseAndDwellMatchTheClosedForm) {
  FollowerDynamicsInput in = Input(1000.0, 0.0, 300.0);
  in.revolutions = 1;
  in.samples = 720;
  in.relative_tolerance = 1e-11;
  in.absolute_tolerance = 1e-11;
  const FollowerDynamicsResult r = SimulateFollower(in);
  const double kf = 1000.0, K = kf + 10.0, F = 200.0, m = 1e-3;  // m in N·s²/mm
  const double wn = std::sqrt(K / m), w = in.speed_rad_s, T = kBeta / w;
  EXPECT_NEAR(r.natural_frequency_Hz, wn / (2 * kPi), 1e-9);
  // S(t) = h(10u³ − 15u⁴ + 6u⁵), u = t/T, and its time derivatives up to the fifth.
  auto S = [&](double t, int k) {
    const double u = t / T;
    const double c[6] = {0, 0, 0, 10, -15, 6};
    double v = 0;
    for (int p = k; p <= 5; ++p) {
      double coef = c[p];
      for (int q = 0; q < k; ++q) coef *= p - q;
      v += coef * std::pow(u, p - k);
    }
    return kH * v / std::pow(T, k);
  };
  auto xp = [&](double t) { return kf / K * (S(t, 0) - S(t, 2) / (wn * wn) + S(t, 4) / std::pow(wn, 4)) - F / K; };
  auto vp = [&](double t) { return kf / K * (S(t, 1) - S(t, 3) / (wn * wn) + S(t, 5) / std::pow(wn, 4)); };
  const double x0 = -F / K, A = x0 - xp(0), B = -vp(0) / wn;
  auto x_rise = [&](double t) { return xp(t) + A * std::cos(wn * t) + B * std::sin(wn * t); };
  auto v_rise = [&](double t) { return vp(t) - A * wn * std::sin(wn * t) + B * wn * std::cos(wn * t); };
  const double xs = (kf * kH - F) / K, C = x_rise(T) - xs, D = v_rise(T) / wn;
  auto x_dwell = [&](double t) { return xs + C * std::cos(wn * (t - T)) + D * std::sin(wn * (t - T)); };
  const double residual = std::hypot(C, D);
  EXPECT_GT(residual, 1e-4);  // a rise of 10.7 natural periods leaves a measurable ring
  int compared = 0;
  double worst = 0, residual_seen = 0;
  for (const FollowerDynamicsSample& s : r.samples) {
    const double t = s.cam_angle_deg * kDeg / w;
    if (s.cam_angle_deg >= 180.0) break;
    const double exact = s.cam_angle_deg < 120.0 ? x_rise(t) : x_dwell(t);
    worst = std::max(worst, std::abs(s.follower_mm - exact));
    if (s.cam_angle_deg >= 120.0) residual_seen = std::max(residual_seen, std::abs(s.follower_mm - xs));
    ++compared;
  }
  EXPECT_EQ(compared, 360);
  EXPECT_LT(worst, 1e-6) << "largest difference to the closed form [mm]";
  // The dwell's 60° hold 5.3 natural periods: the sampled ring reaches its amplitude within the
  // sampling's 1 − cos(π ω_n/(720 ω) ·…) and the refined peak matches it closely.
  EXPECT_NEAR(residual_seen, residual, 0.02 * residual);
  EXPECT_GE(r.residual_vibration_mm, residual * (1 - 1e-6));  // the return's ring adds in its dwell
  EXPECT_FALSE(r.separates);
}

TEST(FollowerDynamics, AStiffFollowerCarriesTheKinetostaticForce) {
  FollowerDynamicsInput in = Input(1e6, 0.2, 600.0);
  const FollowerDynamicsResult r = SimulateFollower(in);
  double worst = 0, top = 0;
  for (const FollowerDynamicsSample& s : r.samples) {
    worst = std::max(worst, std::abs(s.axial_force_N - s.kinetostatic_force_N));
    top = std::max(top, std::abs(s.kinetostatic_force_N));
  }
  EXPECT_LT(worst / top, 5e-3);
  EXPECT_GT(r.min_axial_force_N, 0.0);
  EXPECT_LT(r.residual_vibration_mm, 1e-3);
}

// The last revolution's extremes of the contact force against the same run's dense output
// sampled 100 000 times (its samples are CVODE's interpolation, not the refinement's search): the
// refined extreme is never short of the sampled one by more than rounding, and exceeds it by at
// most what the sampling can miss, an eighth of the largest second difference of the samples.
// A search that skipped the step holding an extreme falls short by up to that much (≈ 1e-7 of the
// force range at these speeds), far beyond the 1e-10 allowed.
TEST(FollowerDynamics, RefinedForceExtremesBoundTheDenselySampledOnes) {
  struct Case { double stiffness, zeta, rpm; };
  for (const Case& c : {Case{1000.0, 0.0, 300.0}, Case{1000.0, 0.05, 600.0}, Case{300.0, 0.02, 450.0},
                        Case{1e5, 0.2, 700.0}}) {
    FollowerDynamicsInput in = Input(c.stiffness, c.zeta, c.rpm);
    in.samples = 100000;
    const FollowerDynamicsResult r = SimulateFollower(in);
    ASSERT_FALSE(r.separates) << c.stiffness << " N/mm at " << c.rpm << " rpm";
    std::vector<double> f;
    for (const FollowerDynamicsSample& s : r.samples) f.push_back(s.axial_force_N);
    const double lo = *std::min_element(f.begin(), f.end()), hi = *std::max_element(f.begin(), f.end());
    double second = 0;
    for (size_t i = 1; i + 1 < f.size(); ++i) second = std::max(second, std::abs(f[i - 1] - 2 * f[i] + f[i + 1]));
    const double range = hi - lo, slack = 1e-10 * range;
    SCOPED_TRACE(::testing::Message() << c.stiffness << " N/mm, zeta " << c.zeta << ", " << c.rpm << " rpm");
    EXPECT_GE(r.max_axial_force_N, hi - slack);
    EXPECT_LE(r.max_axial_force_N, hi + second / 8 + slack);
    EXPECT_LE(r.min_axial_force_N, lo + slack);
    EXPECT_GE(r.min_axial_force_N, lo - second / 8 - slack);
    EXPECT_LT(second / 8, 1e-6 * range);  // the sampling itself resolves the extremes to 1e-6
  }
}

// ω_j² = min over θ with S'' < 0 of (k_s S + F₀)/(−m S''), by a fine scan of the program here.
double KinetostaticJumpSpeed(const FollowerDynamicsInput& in) {
  double best = INFINITY;
  for (int i = 0; i < 360000; ++i) {
    const motion::Svaj<double> k = in.motion.Evaluate(2 * kPi * i / 360000);
    if (k.a < 0)
      best = std::min(best, (in.loads.spring_rate_N_per_mm * k.s + in.loads.spring_preload_N) /
                                (-in.loads.mass_kg * 1e-3 * k.a));
  }
  return std::sqrt(best);
}

TEST(FollowerDynamics, JumpSpeedStiffAtTheKinetostaticValueFlexibleEarlier) {
  FollowerDynamicsInput stiff = Input(1e5, 0.2, 0.0);
  const double wj = KinetostaticJumpSpeed(stiff);
  EXPECT_GT(Rpm(wj), 300.0);
  stiff.speed_rad_s = 0.97 * wj;
  EXPECT_FALSE(SimulateFollower(stiff).separates);
  stiff.speed_rad_s = 1.03 * wj;
  EXPECT_TRUE(SimulateFollower(stiff).separates);
  // A flexible follower (k_f = 100 N/mm, 53 Hz: about 4.6 natural periods per rise at 0.8 ω_j)
  // rings and leaves the cam at 80 % of the rigid follower's jump speed, where the stiff one holds.
  stiff.speed_rad_s = 0.8 * wj;
  EXPECT_FALSE(SimulateFollower(stiff).separates);
  FollowerDynamicsInput flexible = Input(100.0, 0.05, 0.0);
  flexible.speed_rad_s = 0.8 * wj;
  const FollowerDynamicsResult r = SimulateFollower(flexible);
  EXPECT_TRUE(r.separates);
  EXPECT_GT(r.events, 0);
  EXPECT_EQ(r.min_axial_force_N, 0.0);
}

TEST(FollowerDynamics, DynamicJumpSpeedSearch) {
  // A stiff follower first leaves the cam at the kinetostatic jump speed (the test's own closed
  // form over the rise), a flexible one below 80 % of it (where the test above sees it separate).
  FollowerDynamicsInput stiff = Input(1e5, 0.2, 0.0);
  const double wj = KinetostaticJumpSpeed(stiff);
  const DynamicJumpSpeed js = FindDynamicJumpSpeed(stiff, 1.5 * wj);
  ASSERT_TRUE(js.found);
  EXPECT_NEAR(js.speed_rad_s / wj, 1.0, 0.03);
  EXPECT_LE(js.speed_rad_s - js.lower_rad_s, 1e-3 * js.speed_rad_s);
  EXPECT_NEAR(js.scan_step_rad_s, 0.05 * wj, 1e-12 * wj);
  const DynamicJumpSpeed jf = FindDynamicJumpSpeed(Input(100.0, 0.05, 0.0), 1.5 * wj);
  ASSERT_TRUE(jf.found);
  EXPECT_LE(jf.speed_rad_s, 0.8 * wj);
  FollowerDynamicsInput flexible = Input(100.0, 0.05, 0.0);
  flexible.speed_rad_s = jf.lower_rad_s;
  EXPECT_FALSE(SimulateFollower(flexible).separates);
  flexible.speed_rad_s = jf.speed_rad_s;
  EXPECT_TRUE(SimulateFollower(flexible).separates);
  // Nothing separates below a tenth of the jump speed.
  const DynamicJumpSpeed none = FindDynamicJumpSpeed(stiff, 0.1 * wj, 4);
  EXPECT_FALSE(none.found);
  EXPECT_EQ(none.runs, 4);
  EXPECT_THROW(FindDynamicJumpSpeed(stiff, 0.0), std::invalid_argument);
}

TEST(FollowerDynamics, BadInputThrows) {
  FollowerDynamicsInput in = Input(1000.0, 0.0, 300.0);
  in.loads.mass_kg = 0;
  EXPECT_THROW(SimulateFollower(in), std::invalid_argument);
  in = Input(0.0, 0.0, 300.0);
  EXPECT_THROW(SimulateFollower(in), std::invalid_argument);
  in = Input(1000.0, -0.1, 300.0);
  EXPECT_THROW(SimulateFollower(in), std::invalid_argument);
  in = Input(1000.0, 0.0, 0.0);
  EXPECT_THROW(SimulateFollower(in), std::invalid_argument);
}

}  // namespace follower_dynamics_test
}  // namespace camopt::disc_cam
