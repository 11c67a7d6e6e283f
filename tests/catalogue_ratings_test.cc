// Tests of model/common/catalogue_ratings.h: Harmonic Drive's worked example of the torsion angle,
// the three-segment stiffness recovered from a synthetic trilinear curve, lost motion and
// hysteresis loss of synthetic loops against hand values, transmission accuracy of a synthetic
// sine error, the momentary-peak count against a hand calculation, the rated-torque solver's round
// trips, and bad input.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "model/common/catalogue_ratings.h"
#include "model/common/scalar.h"
#include "tests/test_util.h"

namespace camopt {
namespace catalogue_ratings_test {

/// Recovering exact piecewise-linear data: a few roundings of sums of order-one numbers.
constexpr double kExactRelTol = 1e-12;
/// The rated-torque round trip: the solver stops at a bracket of 1e-12·T.
constexpr double kRoundTripRelTol = 1e-9;

using camopt::testing::ExpectRejects;
using camopt::testing::ExpectRel;

// ---- The three-segment characteristic ------------------------------------------------------------

TEST(CatalogueRatings, HarmonicDriveTorsionAngleWorkedExample) {
  // [HDAG-CSD] §4.2, example HFUC-32-100-2UH: T = 60 N·m, T1 = 29 N·m, T2 = 108 N·m,
  // K1 = 6.7·10⁴, K2 = 1.1·10⁵, K3 = 1.2·10⁵ N·m/rad; T1 < T <= T2, so φ = T1/K1 + (T − T1)/K2,
  // printed as φ = 7.15·10⁻⁴ rad = 2.5 arcmin. Unrounded: 7.146540·10⁻⁴ rad = 2.456799 arcmin.
  const double phi = ThreeSegmentTorsionAngle(60.0, 29.0, 108.0, 6.7e4, 1.1e5, 1.2e5);
  ExpectRel(phi, 29.0 / 6.7e4 + 31.0 / 1.1e5, kExactRelTol);
  EXPECT_NEAR(phi, 7.15e-4, 0.005e-4);                // their 3 digits
  EXPECT_NEAR(phi * kArcminPerRad, 2.5, 0.05);        // their 2 digits
  ExpectRel(phi * kArcminPerRad, 2.456799490, 1e-9);  // the unrounded value, 10 digits by hand
  // The other two segments, and odd symmetry.
  ExpectRel(ThreeSegmentTorsionAngle(20.0, 29.0, 108.0, 6.7e4, 1.1e5, 1.2e5), 20.0 / 6.7e4, kExactRelTol);
  ExpectRel(ThreeSegmentTorsionAngle(150.0, 29.0, 108.0, 6.7e4, 1.1e5, 1.2e5),
            29.0 / 6.7e4 + 79.0 / 1.1e5 + 42.0 / 1.2e5, kExactRelTol);
  EXPECT_EQ(ThreeSegmentTorsionAngle(-60.0, 29.0, 108.0, 6.7e4, 1.1e5, 1.2e5), -phi);
}

/// A synthetic trilinear loading branch from −T_r to +T_r with a lost-motion region of width
/// `backlash` at zero torque: θ(T) = ±backlash/2 + φ(T), φ the three-segment wind-up. Points at the
/// kinks, at both ends of the zero-torque run, and in between.
struct Trilinear {
  double t1 = 20.0, t2 = 60.0, tr = 150.0;   // N·m
  double k1 = 10.0, k2 = 25.0, k3 = 40.0;    // N·m/arcmin
  double backlash = 1.2;                      // arcmin
  double Angle(double t, double sign_at_zero) const {
    const double s = t > 0.0 ? 1.0 : (t < 0.0 ? -1.0 : sign_at_zero);
    return s * 0.5 * backlash + ThreeSegmentTorsionAngle(t, t1, t2, k1, k2, k3);
  }
  std::vector<TorsionPoint> Branch(double offset = 0.0) const {
    std::vector<TorsionPoint> b;
    for (double t : {-150.0, -120.0, -60.0, -45.0, -20.0, -7.0}) b.push_back({t, Angle(t, 0.0) + offset});
    b.push_back({0.0, -0.5 * backlash + offset});
    b.push_back({0.0, 0.0 + offset});
    b.push_back({0.0, 0.5 * backlash + offset});
    for (double t : {3.0, 20.0, 33.0, 60.0, 100.0, 150.0}) b.push_back({t, Angle(t, 0.0) + offset});
    return b;
  }
};

TEST(CatalogueRatings, ThreeSegmentStiffnessRecoveredFromATrilinearCurve) {
  const Trilinear c;
  const ThreeSegmentStiffness s = ThreeSegmentTorsionalStiffness(c.Branch(), c.t1, c.t2, c.tr);
  ExpectRel(s.k1_Nm_per_arcmin, c.k1, kExactRelTol);
  ExpectRel(s.k2_Nm_per_arcmin, c.k2, kExactRelTol);
  ExpectRel(s.k3_Nm_per_arcmin, c.k3, kExactRelTol);
  // θ(0+) is first contact on the positive side: the end of the lost-motion region.
  ExpectRel(s.contact_angle_arcmin, 0.5 * c.backlash, kExactRelTol);
  // The branch may also start at torque 0 (the catalogues' one-sided loading branch).
  std::vector<TorsionPoint> one_sided;
  for (const TorsionPoint& p : c.Branch())
    if (p.torque_Nm >= 0.0) one_sided.push_back(p);
  const ThreeSegmentStiffness s1 = ThreeSegmentTorsionalStiffness(one_sided, c.t1, c.t2, c.tr);
  ExpectRel(s1.k1_Nm_per_arcmin, c.k1, kExactRelTol);
  ExpectRel(s1.k3_Nm_per_arcmin, c.k3, kExactRelTol);
}

TEST(CatalogueRatings, AngleAtAnyTorqueByLinearInterpolation) {
  const Trilinear c;
  const auto b = c.Branch();
  for (double t : {-150.0, -100.0, -33.3, -1.0, 1.0, 10.0, 20.0, 47.5, 60.0, 123.4, 150.0})
    EXPECT_NEAR(TorsionAngleAt(b, t), c.Angle(t, 0.0), kExactRelTol * 10.0) << "T = " << t;
  // At zero torque on the lost-motion region: θ(0+).
  EXPECT_EQ(TorsionAngleAt(b, 0.0), 0.5 * c.backlash);
  // Between two points the interpolation is linear even where the curve is not: a coarse branch.
  const std::vector<TorsionPoint> coarse = {{0.0, 0.0}, {10.0, 2.0}, {30.0, 3.0}};
  EXPECT_DOUBLE_EQ(TorsionAngleAt(coarse, 20.0), 2.5);
}

TEST(CatalogueRatings, LostMotionAtThreePercentAndTwentyPercentAgainstHandValues) {
  // T_r = 150 N·m, backlash 1.2 arcmin, K1 = 10 N·m/arcmin over 0–20 N·m, K2 = 25 over 20–60:
  //   3 %:  T = 4.5 N·m < T1: θ(±4.5) = ±(0.6 + 4.5/10) = ±1.05 arcmin → lost motion 2.10 arcmin;
  //   20 %: T = 30 N·m in T1..T2: θ(±30) = ±(0.6 + 20/10 + 10/25) = ±3.0 arcmin → 6.0 arcmin.
  const Trilinear c;
  ExpectRel(LostMotionArcmin(c.Branch(), c.tr, 0.03), 2.10, kExactRelTol);
  ExpectRel(LostMotionArcmin(c.Branch(), c.tr, 0.20), 6.0, kExactRelTol);
  // No backlash: 2·4.5/10 = 0.9 arcmin at 3 %.
  Trilinear tight;
  tight.backlash = 0.0;
  ExpectRel(LostMotionArcmin(tight.Branch(), tight.tr, 0.03), 0.9, kExactRelTol);
}

/// A synthetic hysteresis loop: the loading branch (torque ascending from −T_r) lies `width`/2 below
/// the trilinear curve, the unloading branch (torque descending from +T_r) `width`/2 above it.
std::vector<TorsionPoint> Unloading(const Trilinear& c, double width) {
  std::vector<TorsionPoint> b = c.Branch(+0.5 * width);
  return std::vector<TorsionPoint>(b.rbegin(), b.rend());
}

TEST(CatalogueRatings, HysteresisLossOfASyntheticLoop) {
  // No backlash: the width at zero torque is the loop's width, 0.8 arcmin.
  Trilinear c;
  c.backlash = 0.0;
  const double w = 0.8;
  ExpectRel(HysteresisLossArcmin(c.Branch(-0.5 * w), Unloading(c, w)), w, kExactRelTol);
  // With a lost-motion region the width at zero torque includes it: 1.2 + 0.8 = 2.0 arcmin
  // (Nabtesco's "backlash" of the loop).
  const Trilinear lash;
  ExpectRel(HysteresisLossArcmin(lash.Branch(-0.5 * w), Unloading(lash, w)), lash.backlash + w, kExactRelTol);
}

TEST(CatalogueRatings, LostMotionOnALoopUsesTheMidpointsOfItsWidth) {
  // The loop's mid-line is the trilinear curve: at 3 % the same 2.10 arcmin as the single branch,
  // whatever the loop's width.
  const Trilinear c;
  for (double w : {0.0, 0.8, 3.0})
    ExpectRel(LostMotionArcmin(c.Branch(-0.5 * w), Unloading(c, w), c.tr, 0.03), 2.10, kExactRelTol);
}

// ---- Transmission accuracy -----------------------------------------------------------------------

TEST(CatalogueRatings, TransmissionAccuracyOfASyntheticSineError) {
  // R = 100, 3600 samples over one output revolution (every 0.1° of output); the output lags the
  // ideal by e(θ) = A (sin(2θ + 30°) − sin 30°), A = 0.75 arcmin: the deviation from the first
  // sample peaks at +A(1 − ½) = 0.375 and −A(1 + ½) = −1.125 arcmin (at 2θ + 30° = 90° and 270°,
  // both on the sample grid), the accuracy is 2A = 1.5 arcmin.
  const double r = 100.0, a_deg = 0.75 / 60.0, phase = 30.0 * kPi / 180.0;
  std::vector<double> in, out;
  for (int k = 0; k <= 3600; ++k) {
    const double theta_out_deg = 0.1 * k;
    const double e = a_deg * std::sin(2.0 * theta_out_deg * kPi / 180.0 + phase);
    in.push_back(r * theta_out_deg + 17.0);  // any start angle
    out.push_back(theta_out_deg + e + 3.0);  // any start angle
  }
  const TransmissionAccuracy acc = TransmissionAccuracyFromSamples(in, out, r);
  EXPECT_NEAR(acc.largest_positive_arcmin, 0.375, 1e-9);
  EXPECT_NEAR(acc.largest_negative_arcmin, -1.125, 1e-9);
  EXPECT_NEAR(acc.accuracy_arcmin, 1.5, 1e-9);
  // The other direction of rotation, and a reversing ratio (output turning the other way).
  std::vector<double> in_rev(in.rbegin(), in.rend()), out_rev(out.rbegin(), out.rend());
  EXPECT_NEAR(TransmissionAccuracyFromSamples(in_rev, out_rev, r).accuracy_arcmin, 1.5, 1e-9);
  std::vector<double> out_neg;
  for (double o : out) out_neg.push_back(-o);
  EXPECT_NEAR(TransmissionAccuracyFromSamples(in, out_neg, -r).accuracy_arcmin, 1.5, 1e-9);
}

// ---- Momentary peaks ------------------------------------------------------------------------------

TEST(CatalogueRatings, MomentaryPeakCountAgainstAHandCalculation) {
  // Output 14 rpm at the peak, R = 100, t = 0.15 s: the wave generator turns 1400/60·0.15 = 3.5
  // revolutions, 7 flexings, so N_max = 10⁴/7 = 1428.571 peaks.
  ExpectRel(AllowedMomentaryPeakCount(14.0, 0.15, 100.0), 1e4 / 7.0, kExactRelTol);
  ExpectRel(AllowedMomentaryPeakCount(14.0, 0.15, 100.0), 1428.571428571, 1e-12);
  // The same in the wave generator's speed (R = 1): 10⁴ / (2 · 1400 · 0.15 / 60).
  ExpectRel(AllowedMomentaryPeakCount(1400.0, 0.15, 1.0), 1e4 / (2.0 * 1400.0 * 0.15 / 60.0), kExactRelTol);
}

// ---- The rated-torque solver ----------------------------------------------------------------------

TEST(CatalogueRatings, RatedTorqueRoundTripOnAPowerLaw) {
  // L(T) = L0 (T0/T)^p: the torque for L_target is T0 (L0/L_target)^(1/p).
  const double l0 = 7000.0, t0 = 100.0;
  for (double p : {3.0, 10.0 / 3.0}) {
    auto life = [&](double t) { return l0 * std::pow(t0 / t, p); };
    for (double target : {20000.0, 7000.0, 500.0})
      for (double guess : {1e-3, 1.0, 100.0, 1e5}) {
        const double t = RatedTorqueForLife(life, target, guess);
        ExpectRel(t, t0 * std::pow(l0 / target, 1.0 / p), kRoundTripRelTol);
      }
  }
}

TEST(CatalogueRatings, RatedTorqueRoundTripOnANonPowerLaw) {
  // Two parts in series by Miner, a ball part (p = 3) and a roller part (p = 10/3):
  // 1/L = (T/300)³/2·10⁴ + (T/250)^(10/3)/3·10⁴. Choose T* = 87.3 N·m, set the target L(T*), solve.
  auto life = [](double t) { return 1.0 / (std::pow(t / 300.0, 3.0) / 2e4 + std::pow(t / 250.0, 10.0 / 3.0) / 3e4); };
  const double t_star = 87.3, target = life(t_star);
  for (double guess : {0.01, 87.3, 1000.0}) ExpectRel(RatedTorqueForLife(life, target, guess), t_star, kRoundTripRelTol);
  // Scaling from T = 100 N·m with either exponent misses by more than half a per cent: solve, do
  // not scale (design notes §4).
  for (double p : {3.0, 10.0 / 3.0})
    EXPECT_GT(std::abs(100.0 * std::pow(life(100.0) / target, 1.0 / p) / t_star - 1.0), 5e-3);
}

TEST(CatalogueRatings, RatedTorqueEvaluatesEachTorqueOnce) {
  // Each evaluation is a model run: the bracket's ends are not evaluated again by the regula falsi
  // (exp(log T) need not give T back), on a power law and on a law whose life jumps by 1e-5 of
  // itself every 1e-7 of the torque (a model's solver noise), where a bracket of 1e-6 · T ends the
  // search near the crossing.
  const double t_star = 123.4;
  auto smooth = [&](double t) { return 5000.0 * std::pow(t_star / t, 10.0 / 3.0); };
  auto noisy = [&](double t) { return smooth(t) * (1.0 + 1e-5 * std::sin(1e7 * t)); };
  for (double guess : {10.0, 123.4, 800.0}) {
    for (int law = 0; law < 2; ++law) {
      std::vector<double> torques;
      auto life = [&](double t) {
        torques.push_back(t);
        return law == 0 ? smooth(t) : noisy(t);
      };
      const double tolerance = law == 0 ? 1e-12 : 1e-6;
      const double t = RatedTorqueForLife(life, 5000.0, guess, tolerance);
      std::vector<double> sorted = torques;
      std::sort(sorted.begin(), sorted.end());
      for (size_t i = 1; i < sorted.size(); ++i)
        EXPECT_GT(sorted[i] - sorted[i - 1], 1e-14 * sorted[i])
            << "a torque evaluated twice (to rounding), guess " << guess << ", law " << law;
      EXPECT_NE(std::find(torques.begin(), torques.end(), t), torques.end());  // an evaluated torque
      // The noise moves the crossing by up to 1e-5 / (10/3) of the torque.
      ExpectRel(t, t_star, law == 0 ? kRoundTripRelTol : 4e-6);
      EXPECT_LE(torques.size(), law == 0 ? 16u : 30u) << "guess " << guess << ", law " << law;
    }
  }
}

TEST(CatalogueRatings, RatedTorqueFromANearGuessBracketsWithinItsFirstStep) {
  // A guess within 0.3 % of the answer (the same rating of a neighbouring model) with the first
  // factor 1.01: its first bracket is [guess, 1.01 guess] or [guess / 1.01, guess], so no torque
  // outside it is run; a guess 30 % off with that step still finds the answer (the factor squares:
  // 1.01, 1.02, 1.04, 1.08, 1.17, 1.37, 1.88, 2), above or below. No two torques run lie closer
  // than half the tolerance (Brent's smallest step), on a power law and on one with solver noise.
  const double t_star = 123.4;
  auto smooth = [&](double t) { return 5000.0 * std::pow(t_star / t, 10.0 / 3.0); };
  auto noisy = [&](double t) { return smooth(t) * (1.0 + 1e-5 * std::sin(1e7 * t)); };
  for (int law = 0; law < 2; ++law) {
    for (double guess : {t_star * 1.003, t_star / 1.003, t_star * 1.3, t_star / 1.3}) {
      std::vector<double> torques;
      const double t = RatedTorqueForLife(
          [&](double x) { torques.push_back(x); return law == 0 ? smooth(x) : noisy(x); }, 5000.0, guess, 1e-6, 1.01);
      ExpectRel(t, t_star, law == 0 ? 1e-6 : 4e-6);
      if (std::abs(guess / t_star - 1.0) < 0.01) {
        for (double x : torques)
          EXPECT_TRUE(x >= guess / 1.01 * (1 - 1e-15) && x <= guess * 1.01 * (1 + 1e-15))
              << "torque " << x << " outside the first bracket, guess " << guess << ", law " << law;
      }
      std::sort(torques.begin(), torques.end());
      for (size_t i = 1; i < torques.size(); ++i)
        EXPECT_GE(torques[i] - torques[i - 1], 0.5e-6 * torques[i] * (1 - 1e-9))
            << "guess " << guess << ", law " << law;
    }
  }
  for (double bad : {1.0, 0.5, 2.5, std::nan("")})
    ExpectRejects([&] { RatedTorqueForLife(smooth, 5000.0, 100.0, 1e-6, bad); }, "first_step");
}

TEST(CatalogueRatings, RatedTorqueAcceptsInfiniteAndZeroLives) {
  // No load below 10 N·m (life +∞), broken above 1000 N·m (life 0), a power law between.
  auto life = [](double t) { return t < 10.0 ? kInf : (t > 1000.0 ? 0.0 : 1e4 * std::pow(100.0 / t, 3.0)); };
  ExpectRel(RatedTorqueForLife(life, 1e4, 1.0), 100.0, kRoundTripRelTol);
  ExpectRel(RatedTorqueForLife(life, 1e4, 5000.0), 100.0, kRoundTripRelTol);
}

TEST(CatalogueRatings, RatedTorqueThrowsWhenTheLifeNeverCrossesTheTarget) {
  ExpectRejects([&] { RatedTorqueForLife([](double) { return 100.0; }, 1000.0, 10.0); }, "never reaches the target");
  ExpectRejects([&] { RatedTorqueForLife([](double) { return 1e6; }, 1000.0, 10.0); }, "never falls to the target");
  ExpectRejects([&] { RatedTorqueForLife([](double) { return std::nan(""); }, 1000.0, 10.0); }, "life_h(T)");
  ExpectRejects([&] { RatedTorqueForLife([](double t) { return -t; }, 1000.0, 10.0); }, "life_h(T)");
  ExpectRejects([&] { RatedTorqueForLife([](double t) { return 1.0 / t; }, 0.0, 10.0); }, "target_life_h");
  ExpectRejects([&] { RatedTorqueForLife([](double t) { return 1.0 / t; }, std::nan(""), 10.0); }, "target_life_h");
  ExpectRejects([&] { RatedTorqueForLife([](double t) { return 1.0 / t; }, 1.0, -10.0); }, "torque_guess_Nm");
}

// ---- Bad input --------------------------------------------------------------------------------------

TEST(CatalogueRatings, RejectsBadInputNamingTheQuantity) {
  const double nan = std::nan("");
  const Trilinear c;
  const auto good = c.Branch();

  // Branches.
  ExpectRejects([&] { TorsionAngleAt({}, 1.0); }, "loading_branch.size()");
  ExpectRejects([&] { TorsionAngleAt({{0.0, 0.0}}, 0.0); }, "loading_branch.size()");
  ExpectRejects([&] { TorsionAngleAt({{0.0, 0.0}, {nan, 1.0}}, 0.0); }, "loading_branch[1].torque_Nm");
  ExpectRejects([&] { TorsionAngleAt({{0.0, 0.0}, {1.0, nan}}, 0.0); }, "loading_branch[1].angle_arcmin");
  ExpectRejects([&] { TorsionAngleAt({{0.0, 0.0}, {2.0, 1.0}, {1.0, 2.0}}, 0.5); }, "loading_branch[2].torque_Nm");
  ExpectRejects([&] { TorsionAngleAt({{0.0, 0.0}, {1.0, 1.0}, {1.0, 2.0}}, 0.5); }, "loading_branch[2].torque_Nm");
  ExpectRejects([&] { TorsionAngleAt({{0.0, 0.0}, {1.0, 1.0}, {2.0, 0.5}}, 0.5); }, "loading_branch[2].angle_arcmin");
  ExpectRejects([&] { TorsionAngleAt(good, 151.0); }, "torque_Nm");
  ExpectRejects([&] { TorsionAngleAt(good, nan); }, "torque_Nm");

  // Three-segment stiffness.
  ExpectRejects([&] { ThreeSegmentTorsionalStiffness(good, 0.0, 60.0, 150.0); }, "T1_Nm");
  ExpectRejects([&] { ThreeSegmentTorsionalStiffness(good, nan, 60.0, 150.0); }, "T1_Nm");
  ExpectRejects([&] { ThreeSegmentTorsionalStiffness(good, 20.0, 10.0, 150.0); }, "T2_Nm");
  ExpectRejects([&] { ThreeSegmentTorsionalStiffness(good, 20.0, 60.0, 60.0); }, "T_r_Nm");
  ExpectRejects([&] { ThreeSegmentTorsionalStiffness(good, 20.0, 60.0, 200.0); }, "torque_Nm");
  ExpectRejects([&] { ThreeSegmentTorsionalStiffness({{1.0, 0.0}, {200.0, 5.0}}, 20.0, 60.0, 150.0); },
                "loading_branch[0].torque_Nm");
  ExpectRejects([&] { ThreeSegmentTorsionalStiffness({{0.0, 0.0}, {30.0, 0.0}, {200.0, 5.0}}, 20.0, 60.0, 150.0); }, "K1");
  ExpectRejects([&] { ThreeSegmentTorsionAngle(nan, 1.0, 2.0, 1.0, 1.0, 1.0); }, "torque");
  ExpectRejects([&] { ThreeSegmentTorsionAngle(1.0, -1.0, 2.0, 1.0, 1.0, 1.0); }, "T1");
  ExpectRejects([&] { ThreeSegmentTorsionAngle(1.0, 1.0, 0.5, 1.0, 1.0, 1.0); }, "T2");
  ExpectRejects([&] { ThreeSegmentTorsionAngle(1.0, 1.0, 2.0, 0.0, 1.0, 1.0); }, "K1");
  ExpectRejects([&] { ThreeSegmentTorsionAngle(1.0, 1.0, 2.0, 1.0, nan, 1.0); }, "K2");
  ExpectRejects([&] { ThreeSegmentTorsionAngle(1.0, 1.0, 2.0, 1.0, 1.0, -3.0); }, "K3");

  // Lost motion and hysteresis.
  ExpectRejects([&] { LostMotionArcmin(good, 0.0, 0.03); }, "T_r_Nm");
  ExpectRejects([&] { LostMotionArcmin(good, 150.0, 0.0); }, "fraction");
  ExpectRejects([&] { LostMotionArcmin(good, 150.0, nan); }, "fraction");
  ExpectRejects([&] { LostMotionArcmin(good, 150.0, 1.5); }, "fraction");
  ExpectRejects([&] { LostMotionArcmin(good, 1000.0, 0.5); }, "torque_Nm");
  ExpectRejects([&] { LostMotionArcmin(good, good, 150.0, 0.03); }, "unloading_branch");  // ascending: not unloading
  ExpectRejects([&] { HysteresisLossArcmin({}, Unloading(c, 0.5)); }, "loading_branch.size()");
  ExpectRejects([&] { HysteresisLossArcmin(good, {}); }, "unloading_branch");
  ExpectRejects([&] { HysteresisLossArcmin({{1.0, 0.0}, {2.0, 1.0}}, {{2.0, 1.5}, {1.0, 0.5}}); }, "torque_Nm");

  // Transmission accuracy.
  const std::vector<double> in = {0.0, 18000.0, 36000.0}, out = {0.0, 180.0, 360.0};
  ExpectRejects([&] { TransmissionAccuracyFromSamples({}, {}, 100.0); }, "input_angle_deg.size()");
  ExpectRejects([&] { TransmissionAccuracyFromSamples(in, {0.0, 1.0}, 100.0); }, "output_angle_deg.size()");
  ExpectRejects([&] { TransmissionAccuracyFromSamples(in, out, 0.0); }, "reduction_ratio");
  ExpectRejects([&] { TransmissionAccuracyFromSamples(in, out, nan); }, "reduction_ratio");
  ExpectRejects([&] { TransmissionAccuracyFromSamples({0.0, nan, 36000.0}, out, 100.0); }, "input_angle_deg[1]");
  ExpectRejects([&] { TransmissionAccuracyFromSamples(in, {0.0, nan, 360.0}, 100.0); }, "output_angle_deg[1]");
  ExpectRejects([&] { TransmissionAccuracyFromSamples({0.0, 18000.0, 17000.0, 36000.0}, {0, 1, 2, 3}, 100.0); },
                "input_angle_deg[2]");
  ExpectRejects([&] { TransmissionAccuracyFromSamples(in, out, 200.0); }, "one output revolution");

  // Momentary peaks.
  ExpectRejects([&] { AllowedMomentaryPeakCount(0.0, 0.1, 100.0); }, "n_rpm");
  ExpectRejects([&] { AllowedMomentaryPeakCount(-5.0, 0.1, 100.0); }, "n_rpm");
  ExpectRejects([&] { AllowedMomentaryPeakCount(5.0, std::nan(""), 100.0); }, "t_s");
  ExpectRejects([&] { AllowedMomentaryPeakCount(5.0, 0.1, -100.0); }, "R (reduction_ratio)");
}

}  // namespace catalogue_ratings_test
}  // namespace camopt
