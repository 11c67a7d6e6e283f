// Tests of model/common/bearing_life.h: ISO 281:2007 basic rating life against hand calculations,
// the p-mean equivalent load against closed forms of its integral, the duty cycle's equivalent
// load against Palmgren–Miner summation, AD gradients against central differences, bad input.
#include <array>
#include <functional>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "model/common/bearing_life.h"
#include "tests/test_util.h"

namespace camopt {
namespace bearing_life_test {

/// Agreement of two evaluations of the same closed form in double (a few roundings of pow/log).
constexpr double kClosedFormRelTol = 1e-12;
/// The bar for hand calculations of L10 and of a two-line duty cycle.
constexpr double kHandCalcRelTol = 1e-9;
/// AD against central differences: the lives are smooth power laws of order 1e3 h; the helper's
/// default ε^(2/3) analysis holds with a margin of 10^4.
constexpr double kLifeGradRelTol = 1e-6;
constexpr double kLifeGradAbsTol = 1e-8;

std::vector<double> UniformSamples(int n, const std::function<double(double)>& f) {
  std::vector<double> v(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) v[size_t(k)] = f(2.0 * kPi * k / n);
  return v;
}

TEST(BearingLife, SingleLoadRollerHandCalculation) {
  // C = 20 kN, P = 5 kN, roller (p = 10/3): L10 = 4^(10/3) = 101.5937 million rev;
  // at 1500 rpm: L10h = 1e6 · 101.5937 / (60 · 1500) = 1128.82 h.
  const double l10 = BasicRatingLifeMrev(20000.0, 5000.0, BearingKind::kRoller);
  EXPECT_NEAR(l10, 101.593667, 1e-6);
  EXPECT_NEAR(l10, std::pow(4.0, 10.0 / 3.0), kHandCalcRelTol * l10);
  const double l10h = RatingLifeHours(l10, 1500.0);
  EXPECT_NEAR(l10h, 1128.8185, 1e-4);
  EXPECT_NEAR(l10h, 1e6 * std::pow(4.0, 10.0 / 3.0) / 90000.0, kHandCalcRelTol * l10h);
}

TEST(BearingLife, SingleLoadBallHandCalculation) {
  // C = 20 kN, P = 5 kN, ball (p = 3): L10 = 4³ = 64 million rev; at 1500 rpm:
  // L10h = 64e6 / 90000 = 711.111 h.
  const double l10 = BasicRatingLifeMrev(20000.0, 5000.0, BearingKind::kBall);
  EXPECT_NEAR(l10, 64.0, kHandCalcRelTol * 64.0);
  EXPECT_NEAR(RatingLifeHours(l10, 1500.0), 64e6 / 90000.0, kHandCalcRelTol * 711.1);
}

// Published worked examples, reproduced to the digits they print (each bound is half a unit of
// the last printed digit, carried through the formula).

TEST(BearingLife, SkfCatalogueExample1DeepGrooveBall6309) {
  // SKF General Catalogue 6000 EN (2005), "Selection of bearing size", Calculation examples,
  // Example 1: an SKF Explorer 6309 deep groove ball bearing, C = 55.3 kN (product table), purely
  // radial P = Fr = 10 kN, 3000 r/min: L10 = (55.3/10)³ = 169 million revolutions,
  // L10h = 10⁶/(60·3000)·169 = 940 operating hours.
  const double l10 = BasicRatingLifeMrev(55300.0, 10000.0, BearingKind::kBall);
  EXPECT_NEAR(l10, 169.0, 0.5);  // ours 169.112
  EXPECT_NEAR(RatingLifeHours(l10, 3000.0), 940.0, 5.0);  // ours 939.51
}

TEST(BearingLife, ShigleyProblem11_3CylindricalRoller) {
  // Budynas & Nisbett, Shigley's Mechanical Engineering Design, 8th ed. (2006), Instructor's
  // Solutions Manual, Problem 11-3 (straight-roller 03-series): design life 50 000 h at 480 rev/min
  // (x_D = 50 000·480·60/10⁶ = 1440 rating lives), design load F_D = 1.4·1650 lbf = 10.279 kN,
  // C10 = 10.279·1440^(3/10) = 91.1 kN (a = 10/3, the reliability term taken as 1). Reversed with
  // our functions: the printed C10 = 91.1 kN at F = 10.279 kN and 480 rpm gives 50 000 h, within
  // what the rounding of C10 to 0.1 kN allows: (1 + 0.05/91.1)^(10/3) − 1 = 0.18%.
  const double l10 = BasicRatingLifeMrev(91100.0, 10279.0, BearingKind::kRoller);
  const double bound = std::pow(1.0 + 0.05 / 91.1, 10.0 / 3.0) - 1.0;
  EXPECT_NEAR(l10, 1440.0, bound * 1440.0);  // ours 1440.6
  EXPECT_NEAR(RatingLifeHours(l10, 480.0), 50000.0, bound * 50000.0);  // ours 50 022 h
  // The forward direction of the manual: C10 = F_D x_D^(1/a) = 91.09 kN.
  EXPECT_NEAR(10279.0 * std::pow(50000.0 * 480.0 * 60.0 / 1e6, 0.3), 91100.0, 50.0);
}

TEST(BearingLife, NoLoadOrNoSpeedGivesInfiniteLife) {
  EXPECT_EQ(BasicRatingLifeMrev(20000.0, 0.0, BearingKind::kBall), kInf);
  EXPECT_EQ(RatingLifeHours(64.0, 0.0), kInf);
  EXPECT_EQ(EquivalentLoad(std::vector<double>{0.0, 0.0}, BearingKind::kRoller), 0.0);
}

TEST(BearingLife, EquivalentLoadOfAConstantLoadIsTheLoad) {
  for (BearingKind kind : {BearingKind::kBall, BearingKind::kRoller}) {
    EXPECT_NEAR(EquivalentLoad(std::vector<double>(7, 1234.5), kind), 1234.5, kClosedFormRelTol * 1234.5);
    std::vector<DutyCycleLine<double>> cycle = {{0.3, 100.0, std::vector<double>(5, 800.0)},
                                                {0.7, 2500.0, std::vector<double>(9, 800.0)}};
    EXPECT_NEAR(DutyCycleEquivalentLoad(cycle, kind), 800.0, kClosedFormRelTol * 800.0);
  }
}

TEST(BearingLife, CubicMeanOfSinusoidalLoadMatchesItsIntegral) {
  // F(θ) = F0 (1 + a cos θ): (1/2π)∫F³ dθ = F0³ (1 + 3a·0 + 3a²·½ + a³·0) = F0³ (1 + 3a²/2).
  // With F0 = 1000 N, a = 0.5: P = 1000 · (1.375)^(1/3) = 1111.99 N. F³ is a trigonometric
  // polynomial of degree 3, so the uniform-sample mean is exact from N = 4 samples on.
  const double f0 = 1000.0, a = 0.5;
  const double exact = f0 * std::cbrt(1.0 + 1.5 * a * a);
  EXPECT_NEAR(exact, 1111.9900, 1e-4);
  for (int n : {4, 5, 12, 360}) {
    const auto loads = UniformSamples(n, [&](double t) { return f0 * (1.0 + a * std::cos(t)); });
    EXPECT_NEAR(EquivalentLoad(loads, BearingKind::kBall), exact, kClosedFormRelTol * exact) << "N = " << n;
  }
  // N = 3 aliases cos³θ's cos 3θ term: (1/3)Σ cos³(2πk/3) = 1/4 ≠ 0, the error a³/4 of F0³.
  const auto three = UniformSamples(3, [&](double t) { return f0 * (1.0 + a * std::cos(t)); });
  EXPECT_NEAR(std::pow(EquivalentLoad(three, BearingKind::kBall), 3.0),
              f0 * f0 * f0 * (1.0 + 1.5 * a * a + a * a * a / 4.0), 1e-9 * f0 * f0 * f0);
}

TEST(BearingLife, TenThirdsMeanOfSmoothLoadConvergesSpectrally) {
  // F^(10/3) with F = F0 (1 + a cos θ) > 0 is analytic in a strip of half-width acosh(1/a)
  // (a = 0.5: 1.317), so the error falls like e^(−1.317 N): N = 32 and N = 64 agree to rounding.
  const double f0 = 1000.0, a = 0.5;
  auto f = [&](double t) { return f0 * (1.0 + a * std::cos(t)); };
  const double p32 = EquivalentLoad(UniformSamples(32, f), BearingKind::kRoller);
  const double p64 = EquivalentLoad(UniformSamples(64, f), BearingKind::kRoller);
  EXPECT_NEAR(p32, p64, kClosedFormRelTol * p64);
}

TEST(BearingLife, QuadratureErrorOfLoadZeroOverPartOfTheCycle) {
  // F = F0 max(0, cos θ): loaded over half a revolution, leaving zero linearly. Closed forms
  // (1/2π)∫ cos₊^p = (1/2π) √π Γ((p+1)/2) / Γ(p/2 + 1): p = 3: 2/(3π) = 0.212207;
  // p = 10/3: 0.202929. The error of the mean of F^p is O(N^−(p+1)); measured N^(p+1)·error/F0^p
  // is 4.1–4.3 (p = 3) and 5.4–5.7 (p = 10/3) for N = 16…128 divisible by 4.
  constexpr double kScaledErrorBound = 6.0;
  for (BearingKind kind : {BearingKind::kBall, BearingKind::kRoller}) {
    const double p = LifeExponent(kind);
    const double exact = std::sqrt(kPi) * std::tgamma((p + 1) / 2) / std::tgamma(p / 2 + 1) / (2 * kPi);
    double previous = 0.0;
    for (int n : {32, 64, 128}) {
      const double pe = EquivalentLoad(UniformSamples(n, [](double t) { return std::max(0.0, std::cos(t)); }), kind);
      const double error = std::abs(std::pow(pe, p) - exact);
      EXPECT_LT(error * std::pow(n, p + 1), kScaledErrorBound) << "p = " << p << ", N = " << n;
      if (previous > 0.0) {
        EXPECT_NEAR(previous / error, std::pow(2.0, p + 1), 0.1 * std::pow(2.0, p + 1)) << "N = " << n;
      }
      previous = error;
    }
  }
  // A load that jumps: F = F0 on θ ∈ [0, 1 rad), 0 elsewhere; mean of F^p = F0^p / 2π. Two jumps
  // of F0^p: the error stays below F0^p / N, first order.
  for (int n : {16, 17, 64, 100, 101}) {
    const double pe = EquivalentLoad(UniformSamples(n, [](double t) { return t < 1.0 ? 1.0 : 0.0; }), BearingKind::kBall);
    EXPECT_LT(std::abs(std::pow(pe, 3.0) - 1.0 / (2 * kPi)), 1.0 / n) << "N = " << n;
  }
}

// Two lines, ball bearing, C = 30 kN, constant loads:
//   line 1: t = 0.4, n = 1000 rpm, P1 = 6 kN:  L10 = 5³ = 125 Mrev, L10h = 125e6/60000 = 2083.33 h
//   line 2: t = 0.6, n =  500 rpm, P2 = 10 kN: L10 = 3³ = 27 Mrev,  L10h = 27e6/30000  = 900 h
// Miner: 1/L10h = 0.4/2083.33 + 0.6/900 = 8.58667e-4 /h → L10h = 1164.596 h.
// Equivalent: n̄ = 0.4·1000 + 0.6·500 = 700 rpm; P³ = (400·6³ + 300·10³)/700 = 552 kN³,
//   P = 8.20313 kN; L10 = 27000/552 = 48.913 Mrev; L10h = 48.913e6/(60·700) = 1164.596 h.
std::vector<DutyCycleLine<double>> TwoLineCycle() {
  return {{0.4, 1000.0, std::vector<double>(3, 6000.0)}, {0.6, 500.0, std::vector<double>(4, 10000.0)}};
}

// The revolution-weighted p-mean (a bearing turning at a varying speed over the load cycle)
// against closed forms of ∫ w F^p dθ / ∫ w dθ.
TEST(BearingLife, RevolutionWeightedMeanMatchesItsIntegral) {
  // F = F0 (1 + a cos θ), w = 1 + b cos θ, p = 3: w F³ is a trigonometric polynomial of degree 4,
  // so N >= 5 uniform samples integrate it exactly:
  //   ∫ w F³ / ∫ w = F0³ (1 + 3a²/2 + b (3a/2 + 3a³/8)).
  const double f0 = 2000.0, a = 0.4, b = 0.7;
  for (int n : {5, 12, 360}) {
    const auto loads = UniformSamples(n, [&](double t) { return f0 * (1 + a * std::cos(t)); });
    const auto weights = UniformSamples(n, [&](double t) { return 1 + b * std::cos(t); });
    const double expected = f0 * std::cbrt(1 + 1.5 * a * a + b * (1.5 * a + 0.375 * a * a * a));
    EXPECT_NEAR(EquivalentLoad(loads, weights, BearingKind::kBall), expected, kClosedFormRelTol * expected) << n;
  }
  // A load F0 over the half revolution where the bearing turns twice as fast, 0 elsewhere
  // (roller, p = 10/3): P^p = (2 · F0^p · π) / (2 · π + 1 · π) = (2/3) F0^p.
  const int n = 8;
  std::vector<double> loads(n, 0.0), weights(n, 1.0);
  for (int k = 0; k < n / 2; ++k) loads[k] = f0, weights[k] = 2.0;
  const double expected = f0 * std::pow(2.0 / 3.0, 0.3);
  EXPECT_NEAR(EquivalentLoad(loads, weights, BearingKind::kRoller), expected, kClosedFormRelTol * expected);
  // Weighted by input angle instead (equal weights) it would be (1/2)^(3/10) F0: lower.
  EXPECT_LT(EquivalentLoad(loads, BearingKind::kRoller), expected);
  // Equal weights: EquivalentLoad.
  EXPECT_NEAR(EquivalentLoad(loads, std::vector<double>(n, 3.0), BearingKind::kRoller),
              EquivalentLoad(loads, BearingKind::kRoller), kClosedFormRelTol * f0);
  // Bad weights.
  EXPECT_THROW(EquivalentLoad(loads, std::vector<double>(n - 1, 1.0), BearingKind::kRoller), std::invalid_argument);
  EXPECT_THROW(EquivalentLoad(loads, std::vector<double>(n, 0.0), BearingKind::kRoller), std::invalid_argument);
  weights[3] = -1.0;
  EXPECT_THROW(EquivalentLoad(loads, weights, BearingKind::kRoller), std::invalid_argument);
}

TEST(BearingLife, TwoLineDutyCycleHandCalculation) {
  const auto cycle = TwoLineCycle();
  const double hand_h = 1e6 * (27000.0 / 552.0) / (60.0 * 700.0);
  EXPECT_NEAR(hand_h, 1164.5963, 1e-4);
  EXPECT_NEAR(DutyCycleMeanSpeed(cycle), 700.0, 1e-12);
  EXPECT_NEAR(DutyCycleEquivalentLoad(cycle, BearingKind::kBall), 1000.0 * std::cbrt(552.0), kHandCalcRelTol * 8203.0);
  EXPECT_NEAR(DutyCycleLifeHours(30000.0, cycle, BearingKind::kBall), hand_h, kHandCalcRelTol * hand_h);
  const double miner_h = 1.0 / (0.4 / (125e6 / 60000.0) + 0.6 / (27e6 / 30000.0));
  EXPECT_NEAR(miner_h, hand_h, kHandCalcRelTol * hand_h);
}

TEST(BearingLife, DutyCycleEquivalentLoadAgreesWithPalmgrenMiner) {
  // Varying loads per line, a stationary line and a zero share: the equivalent-load route
  // (C/P)^p at n̄ and the line-by-line Miner sum 1/L10h = Σ t_i / L10h,i are the same number.
  for (BearingKind kind : {BearingKind::kBall, BearingKind::kRoller}) {
    std::vector<DutyCycleLine<double>> cycle = {
        {0.25, 1500.0, UniformSamples(36, [](double t) { return 3000.0 * (1.0 + 0.3 * std::cos(t)); })},
        {0.5, 300.0, UniformSamples(24, [](double t) { return 9000.0 * std::max(0.0, std::sin(t)); })},
        {0.15, 0.0, std::vector<double>(5, 20000.0)},
        {0.1, 3000.0, std::vector<double>(8, 1000.0)},
        {0.0, 800.0, std::vector<double>(2, 50000.0)}};
    const double c = 40000.0;
    const double p_eq = DutyCycleEquivalentLoad(cycle, kind);
    const double n_mean = DutyCycleMeanSpeed(cycle);
    const double via_equivalent = RatingLifeHours(BasicRatingLifeMrev(c, p_eq, kind), n_mean);
    double damage_per_h = 0.0;
    for (const auto& line : cycle) {
      const double l10h_i = RatingLifeHours(BasicRatingLifeMrev(c, EquivalentLoad(line.loads_N, kind), kind),
                                            line.speed_rpm);
      damage_per_h += line.time_share / l10h_i;  // t_i / ∞ = 0 for the stationary line
    }
    const double via_miner = 1.0 / damage_per_h;
    EXPECT_NEAR(via_equivalent, via_miner, kClosedFormRelTol * via_miner);
    EXPECT_NEAR(DutyCycleLifeHours(c, cycle, kind), via_miner, kClosedFormRelTol * via_miner);
    EXPECT_NEAR(LifeMargin(c, cycle, kind, 2000.0), std::log(via_miner / 2000.0), 1e-12);
  }
}

TEST(BearingLife, StaticSafetyFactor) {
  // C0 = 25 kN, largest load 10 kN (line 2 of the two-line cycle): s0 = 2.5.
  EXPECT_DOUBLE_EQ(StaticSafetyFactor(25000.0, TwoLineCycle()), 2.5);
  EXPECT_DOUBLE_EQ(StaticSafetyFactor(25000.0, std::vector<double>{1.0, 5000.0, 0.0}), 5.0);
  EXPECT_EQ(StaticSafetyFactor(25000.0, std::vector<double>{0.0}), kInf);
}

// ---- gradients: ceres::Jet against central differences ----------------------------------------

TEST(BearingLife, SingleLoadGradientsMatchCentralDifferences) {
  // x = {C, P, n}: L10 (both kinds) and L10h.
  auto f = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    const T roller = BasicRatingLifeMrev(x[0], x[1], BearingKind::kRoller);
    return std::vector<T>{roller, BasicRatingLifeMrev(x[0], x[1], BearingKind::kBall), RatingLifeHours(roller, x[2])};
  };
  testing::ExpectJacobianMatchesCentralDifferences<3>(f, {20000.0, 5000.0, 1500.0}, kLifeGradRelTol, kLifeGradAbsTol);
}

TEST(BearingLife, EquivalentLoadGradientMatchesCentralDifferences) {
  // Four samples of one revolution.
  auto f = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    const std::vector<T> loads(x.begin(), x.end());
    return std::vector<T>{EquivalentLoad(loads, BearingKind::kBall), EquivalentLoad(loads, BearingKind::kRoller)};
  };
  testing::ExpectJacobianMatchesCentralDifferences<4>(f, {1200.0, 800.0, 300.0, 50.0}, kLifeGradRelTol, kLifeGradAbsTol);
  // A sample at 0 (a roller out of contact; no central difference, loads are >= 0): dP/dF = 0
  // there, since d F^p / dF = p F^(p−1) = 0; the other derivatives stay finite.
  using J = ceres::Jet<double, 2>;
  const J p = EquivalentLoad(std::vector<J>{J(1200.0, 0), J(0.0, 1)}, BearingKind::kRoller);
  EXPECT_EQ(p.v[1], 0.0);
  EXPECT_GT(p.v[0], 0.0);
  EXPECT_TRUE(camopt::IsFinite(p));
}

TEST(BearingLife, DutyCycleGradientsMatchCentralDifferences) {
  // x = {C, C0, n1, n2, F10, F11, F12, F20, F21}: P over the spectrum, L10h (Miner), the life
  // margin against 1000 h, and s0, both kinds.
  auto f = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    const std::vector<DutyCycleLine<T>> cycle = {{0.35, x[2], {x[4], x[5], x[6]}}, {0.65, x[3], {x[7], x[8]}}};
    std::vector<T> out;
    for (BearingKind kind : {BearingKind::kBall, BearingKind::kRoller}) {
      out.push_back(DutyCycleEquivalentLoad(cycle, kind));
      out.push_back(DutyCycleLifeHours(x[0], cycle, kind));
      out.push_back(LifeMargin(x[0], cycle, kind, 1000.0));
    }
    out.push_back(StaticSafetyFactor(x[1], cycle));
    return out;
  };
  testing::ExpectJacobianMatchesCentralDifferences<9>(
      f, {30000.0, 25000.0, 1000.0, 400.0, 5000.0, 7000.0, 2000.0, 9000.0, 6500.0}, kLifeGradRelTol, kLifeGradAbsTol);
}

// ---- bad input -----------------------------------------------------------------------------------

void ExpectRejected(const std::function<void()>& call, const std::string& words) {
  try {
    call();
    ADD_FAILURE() << "no error; expected one containing \"" << words << "\"";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(BearingLife, BadInputIsRejectedNamingTheFieldAndValue) {
  const auto k = BearingKind::kRoller;
  ExpectRejected([&] { BasicRatingLifeMrev(0.0, 100.0, k); }, "C_N must be finite and > 0, found 0");
  ExpectRejected([&] { BasicRatingLifeMrev(1000.0, -5.0, k); }, "P_N must be finite and >= 0, found -5");
  ExpectRejected([&] { RatingLifeHours(10.0, -100.0); }, "speed_rpm must be finite and >= 0, found -100");
  ExpectRejected([&] { StaticSafetyFactor(-1.0, std::vector<double>{1.0}); }, "C0_N must be finite and > 0, found -1");
  ExpectRejected([&] { EquivalentLoad(std::vector<double>{}, k); }, "loads_N.size() must be >= 1");
  ExpectRejected([&] { EquivalentLoad(std::vector<double>{1.0, std::nan("")}, k); },
                 "loads_N[1] must be finite and >= 0, found nan");
  ExpectRejected([&] { LifeMargin(1000.0, TwoLineCycle(), k, 0.0); }, "required_life_h must be finite and > 0, found 0");

  auto cycle = TwoLineCycle();
  cycle[1].time_share = 0.5;
  ExpectRejected([&] { DutyCycleLifeHours(30000.0, cycle, k); },
                 "the sum of duty_cycle[*].time_share must be 1 (within 1e-9), found 0.9");
  cycle = TwoLineCycle();
  cycle[0].time_share = -0.4;
  cycle[1].time_share = 1.4;
  ExpectRejected([&] { DutyCycleEquivalentLoad(cycle, k); }, "duty_cycle[0].time_share must be in [0, 1], found -0.4");
  cycle = TwoLineCycle();
  cycle[1].speed_rpm = -500.0;
  ExpectRejected([&] { DutyCycleMeanSpeed(cycle); }, "duty_cycle[1].speed_rpm must be finite and >= 0, found -500");
  cycle = TwoLineCycle();
  cycle[1].loads_N[2] = -1.0;
  ExpectRejected([&] { LifeMargin(30000.0, cycle, k, 1000.0); },
                 "duty_cycle[1].loads_N[2] must be finite and >= 0, found -1");
  cycle = TwoLineCycle();
  cycle[0].loads_N[0] = kInf;
  ExpectRejected([&] { StaticSafetyFactor(30000.0, cycle); }, "duty_cycle[0].loads_N[0] must be finite and >= 0, found inf");
  cycle = TwoLineCycle();
  cycle[0].speed_rpm = cycle[1].speed_rpm = 0.0;
  ExpectRejected([&] { DutyCycleLifeHours(30000.0, cycle, k); }, "speed_rpm must be > 0 (no revolutions");
  ExpectRejected([&] { DutyCycleLifeHours(30000.0, std::vector<DutyCycleLine<double>>{}, k); },
                 "duty_cycle.size() must be >= 1");
  // Within the tolerance: shares summing to 1 + 5e-10 are accepted.
  cycle = TwoLineCycle();
  cycle[1].time_share += 5e-10;
  EXPECT_NO_THROW(DutyCycleLifeHours(30000.0, cycle, k));
}

}  // namespace bearing_life_test
}  // namespace camopt
