// The one-dimensional searches of model/common/roots.h against closed forms.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "model/common/roots.h"

namespace camopt {
namespace roots_test {

// max of sin on [0, 3]: x = π/2, f = 1 (closed form).
TEST(Roots, GoldenSectionFindsTheMaximumOfSine) {
  int calls = 0;
  const GoldenSectionBracket b = GoldenSectionMaximize([&](double x) { ++calls; return std::sin(x); }, 0.0, 3.0, 100);
  EXPECT_NEAR(0.5 * (b.lo + b.hi), M_PI / 2, 1e-7);  // f is flat at the top: x to ~sqrt(eps)
  EXPECT_NEAR(std::max(b.f1, b.f2), 1.0, 1e-15);
  EXPECT_LE(b.lo, b.x1);
  EXPECT_LE(b.x1, b.x2);
  EXPECT_LE(b.x2, b.hi);
  EXPECT_EQ(calls, 102);  // two to start, one per step
}

// Each step shrinks the bracket by (√5 − 1)/2; the tolerance stops it early.
TEST(Roots, GoldenSectionShrinksByTheGoldenRatioAndStopsAtTheTolerance) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  auto parabola = [](double x) { return -(x - 0.3) * (x - 0.3); };
  const GoldenSectionBracket ten = GoldenSectionMaximize(parabola, -1.0, 1.0, 10);
  EXPECT_NEAR(ten.hi - ten.lo, 2.0 * std::pow(g, 10), 1e-12);
  EXPECT_LE(ten.lo, 0.3);
  EXPECT_GE(ten.hi, 0.3);
  const GoldenSectionBracket tol = GoldenSectionMaximize(parabola, -1.0, 1.0, 1000, 1e-6);
  EXPECT_LE(tol.hi - tol.lo, 1e-6);
  EXPECT_GT(tol.hi - tol.lo, 1e-6 * g);  // stopped at the first bracket below the tolerance
  // A minimum by maximising −f: min of x² − 2x on [−3, 4] at x = 1.
  const GoldenSectionBracket m = GoldenSectionMaximize([](double x) { return -(x * x - 2 * x); }, -3.0, 4.0, 200);
  EXPECT_NEAR(0.5 * (m.lo + m.hi), 1.0, 1e-7);
}

// Brent's method against closed forms: a parabola's vertex by its first parabolic steps; sin's
// maximum π/2 and a quartic's x = 0.7 to the tolerance in far fewer evaluations than golden
// sections; a function undefined (−∞) on part of the bracket. (A tolerance below what the values
// can resolve at a flat top, ~sqrt(eps) of the scale, only adds steps in the rounding noise.)
TEST(Roots, BrentFindsSmoothMaximaInFewEvaluations) {
  int calls = 0;
  const auto [xp, fp] = BrentMaximize([&](double x) { ++calls; return 2.0 - (x - 0.3) * (x - 0.3); }, -1.0, 1.0, 100, 1e-7);
  EXPECT_NEAR(xp, 0.3, 1e-12);
  EXPECT_NEAR(fp, 2.0, 1e-15);
  EXPECT_LE(calls, 8);
  calls = 0;
  const auto [xs, fs] = BrentMaximize([&](double x) { ++calls; return std::sin(x); }, 0.0, 3.0, 100, 1e-7);
  EXPECT_NEAR(xs, M_PI / 2, 1e-7);
  EXPECT_NEAR(fs, 1.0, 1e-15);
  EXPECT_LE(calls, 12);  // golden sections: 35 for a bracket of 3 to 1e-7
  const auto quartic = [](double x) { return -std::pow(x - 0.7, 2) * (1.0 + std::pow(x - 0.7, 2)); };
  calls = 0;
  const auto [xq, fq] = BrentMaximize([&](double x) { ++calls; return quartic(x); }, -2.0, 2.0, 100, 1e-9);
  EXPECT_NEAR(xq, 0.7, 1e-7);
  EXPECT_LE(calls, 14);
  EXPECT_GE(fq, -1e-14);
  // f = −∞ left of 0 (undefined), maximum of −(x − 0.2)² at 0.2.
  const auto [xi, fi] = BrentMaximize(
      [](double x) { return x < 0 ? -std::numeric_limits<double>::infinity() : -(x - 0.2) * (x - 0.2); }, -1.0, 1.0,
      100, 1e-9);
  EXPECT_NEAR(xi, 0.2, 1e-7);
  EXPECT_TRUE(std::isfinite(fi));
  // The maximum at the bracket's end: found within the tolerance of it.
  const auto [xe, fe] = BrentMaximize([](double x) { return x; }, 0.0, 1.0, 200, 1e-9);
  EXPECT_NEAR(xe, 1.0, 1e-8);
  EXPECT_NEAR(fe, 1.0, 1e-8);
}

// Brent's method started from three known samples (the best and its two neighbours) takes their
// parabola's vertex first; with a value tolerance it stops after the step whose parabola promised
// less than it. sin's maximum from samples 0.3 apart, and a quartic's: the value within the
// tolerance, in a few evaluations where the cold start takes a dozen.
TEST(Roots, BrentFromThreeSamplesStopsOnTheValueTolerance) {
  const auto sin_start = [](double x0) {
    return BrentStart{x0, std::sin(x0), x0 - 0.3, std::sin(x0 - 0.3), x0 + 0.3, std::sin(x0 + 0.3)};
  };
  for (double x0 : {1.45, 1.6, 1.75}) {
    int calls = 0;
    const auto [x, fx] = BrentMaximize([&](double t) { ++calls; return std::sin(t); }, x0 - 0.3, x0 + 0.3,
                                       sin_start(x0), 100, 1e-8, 1e-13);
    EXPECT_GE(fx, 1.0 - 1e-13) << x0;
    EXPECT_LE(fx, 1.0);
    EXPECT_LE(calls, 5) << x0;
    int cold = 0;
    BrentMaximize([&](double t) { ++cold; return std::sin(t); }, x0 - 0.3, x0 + 0.3, 100, 1e-8);
    EXPECT_GT(cold, 2 * calls) << x0;
    // Without the value tolerance the start still holds: the same maximum, by the bracket's rule.
    const auto [xb, fb] = BrentMaximize([](double t) { return std::sin(t); }, x0 - 0.3, x0 + 0.3, sin_start(x0), 100,
                                        1e-8);
    EXPECT_NEAR(xb, M_PI / 2, 1e-7);
    EXPECT_GE(fb, 1.0 - 1e-15);
  }
  // An asymmetric peak, −(x − 0.7)² (1 + 5 (x − 0.7)): the cubic term moves the parabola's vertex.
  const auto f = [](double x) { return -std::pow(x - 0.7, 2) * (1.0 + 5.0 * (x - 0.7)); };
  int calls = 0;
  const auto [xq, fq] = BrentMaximize([&](double x) { ++calls; return f(x); }, 0.6, 0.8,
                                      BrentStart{0.7 + 0.02, f(0.72), 0.62, f(0.62), 0.8, f(0.8)}, 100, 1e-8, 1e-13);
  EXPECT_GE(fq, -1e-13);
  EXPECT_NEAR(xq, 0.7, 1e-6);
  EXPECT_LE(calls, 8);
}

// x³ = 2 on [0, 2]: the cube root of 2.
TEST(Roots, BisectionFindsTheCubeRoot) {
  const RootBracket b = BisectIncreasing([](double x) { return x * x * x; }, 2.0, 0.0, 2.0, 200, 1e-15);
  EXPECT_NEAR(b.mid(), std::cbrt(2.0), 4e-15);
  EXPECT_LT(b.lo * b.lo * b.lo, 2.0);
  EXPECT_GE(b.hi * b.hi * b.hi, 2.0);
  // Iteration cap: 10 halvings of [0, 2] leave 2/1024.
  const RootBracket ten = BisectIncreasing([](double x) { return x * x * x; }, 2.0, 0.0, 2.0, 10, 0.0);
  EXPECT_DOUBLE_EQ(ten.hi - ten.lo, 2.0 / 1024);
}

// A piecewise-linear, non-decreasing function with a flat piece (like a dead band): x = 2.5.
TEST(Roots, BisectionOnAFunctionWithAFlatPiece) {
  auto f = [](double x) { return x < 1 ? 0.0 : 2 * (x - 1); };
  EXPECT_NEAR(BisectIncreasing(f, 3.0, 0.0, 10.0, 200, 1e-15, 1e-6).mid(), 2.5, 1e-13);
}

// √x² = 10 and x^(10/9) = 5 by safeguarded Newton: closed forms √10 and 5^0.9.
TEST(Roots, SafeguardedNewtonMatchesClosedForms) {
  const double sq = SafeguardedNewtonIncreasing([](double x) { return x * x; }, [](double x) { return 2 * x; },
                                                10.0, 1.0, 8.0, 200, 1e-14, 1e-15);
  EXPECT_NEAR(sq, std::sqrt(10.0), 1e-13);
  const double p = SafeguardedNewtonIncreasing([](double x) { return std::pow(x, 10.0 / 9.0); },
                                               [](double x) { return 10.0 / 9.0 * std::pow(x, 1.0 / 9.0); },
                                               5.0, 1e-3, 100.0, 200, 1e-14, 1e-15);
  EXPECT_NEAR(p, std::pow(5.0, 0.9), 1e-12);
  // A zero slope everywhere: every step is the bracket's midpoint, i.e. bisection.
  const double flat = SafeguardedNewtonIncreasing([](double x) { return x < 3 ? -1.0 : 1.0; },
                                                  [](double) { return 0.0; }, 0.0, 1.0, 5.0, 200, 1e-14, 1e-15);
  EXPECT_NEAR(flat, 3.0, 1e-13);
}

}  // namespace roots_test
}  // namespace camopt
