// Closed cubic B-splines of the STEP walls (cad/bspline.h): the fit checked by distances computed
// here by minimisation (not the fit's own parametric check), its h⁴ convergence, the clamped runs
// against a de Boor evaluation written here, and the STEP solid of a spline profile read back by
// OpenCASCADE against the closed-form volume.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cad/arc_fit.h"
#include "cad/bspline.h"
#include "cad/extrusion.h"
#include "cad/solid.h"

namespace camopt {
namespace cad_bspline_test {

constexpr double kPi = 3.14159265358979323846;

// r(t) = R + A cos(S t) in polar form: smooth, star-shaped, S-fold symmetric, counter-clockwise;
// its area π R² + π A²/2.
struct Lobed {
  double R = 50, A = 2;
  int S = 11;
  Vec2<double> operator()(double t) const {
    const double r = R + A * std::cos(S * t);
    return Vec2<double>(r * std::cos(t), r * std::sin(t));
  }
  double Area() const { return kPi * R * R + kPi * A * A / 2; }
};

// The least of |f(x) − p| over x near x0 (±half): 64 samples, then golden section about the best.
double DistanceTo(const std::function<Vec2<double>(double)>& f, const Vec2<double>& p, double x0, double half) {
  double best_x = x0, best = INFINITY;
  for (int i = 0; i <= 64; ++i) {
    const double x = x0 - half + 2 * half * i / 64.0, d = (f(x) - p).norm();
    if (d < best) best = d, best_x = x;
  }
  double lo = best_x - 2 * half / 64, hi = best_x + 2 * half / 64;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int k = 0; k < 80; ++k) {
    const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
    if ((f(a) - p).norm() < (f(b) - p).norm()) hi = b; else lo = a;
  }
  return std::min(best, (f(0.5 * (lo + hi)) - p).norm());
}

TEST(ClosedCubic, WithinTheTargetBothWaysByMinimisedDistances) {
  const Lobed c;
  const double target = 0.9e-3;
  const auto s = cad::FitClosedCubic(c, 0, 2 * kPi, c.S, 8 * c.S, target, 5000);
  ASSERT_TRUE(s.has_value());
  const int n = static_cast<int>(s->poles.size());
  EXPECT_EQ(n % c.S, 0);
  EXPECT_LE(s->max_deviation_mm, target);
  const auto spline = [&](double u) { return cad::PointOnClosedCubic(*s, u); };
  double worst_spline = 0, worst_exact = 0;
  for (int i = 0; i < 4000; ++i) {
    const double u = n * (i + 0.37) / 4000.0, t = 2 * kPi * u / n;
    // A point of the spline to the exact curve, and a point of the curve to the spline.
    worst_spline = std::max(worst_spline, DistanceTo(c, spline(u), t, 4 * 2 * kPi / n));
    worst_exact = std::max(worst_exact, DistanceTo(spline, c(t), u, 4.0));
  }
  std::printf("lobed curve: %d poles, fit's check %.4f um, minimised %.4f / %.4f um\n", n, s->max_deviation_mm * 1e3,
              worst_spline * 1e3, worst_exact * 1e3);
  EXPECT_LE(worst_spline, target);
  EXPECT_LE(worst_exact, target);
  // The normal distance is at most the parametric one, which the fit found at 16 points a span.
  EXPECT_LE(worst_spline, 1.02 * s->max_deviation_mm);
  // A circle: the distance from it is ||S(u)| − r| in closed form.
  const auto circle = [](double t) { return Vec2<double>(20 * std::cos(t), 20 * std::sin(t)); };
  const auto o = cad::FitClosedCubic(circle, 0, 2 * kPi, 1, 8, 1e-4, 5000);
  ASSERT_TRUE(o.has_value());
  double worst_circle = 0;
  for (int i = 0; i < 20000; ++i)
    worst_circle = std::max(worst_circle, std::abs(cad::PointOnClosedCubic(*o, o->poles.size() * i / 20000.0).norm() - 20));
  EXPECT_LE(worst_circle, 1e-4);
  EXPECT_GT(worst_circle, 1e-6);  // the spline is not the circle: the check is not vacuous
}

TEST(ClosedCubic, ErrorFallsAsTheFourthPowerOfTheStep) {
  const Lobed c;
  // A target no fit misses: the first span count is returned with its error.
  const auto coarse = cad::FitClosedCubic(c, 0, 2 * kPi, c.S, 16 * c.S, 1e9, 5000);
  const auto fine = cad::FitClosedCubic(c, 0, 2 * kPi, c.S, 32 * c.S, 1e9, 5000);
  ASSERT_TRUE(coarse && fine);
  ASSERT_EQ(coarse->poles.size(), 176u);
  ASSERT_EQ(fine->poles.size(), 352u);
  const double ratio = coarse->max_deviation_mm / fine->max_deviation_mm;
  std::printf("error at 176 / 352 spans: %.3e / %.3e mm, ratio %.2f (h^4: 16)\n", coarse->max_deviation_mm,
              fine->max_deviation_mm, ratio);
  EXPECT_GT(ratio, 12.0);
  EXPECT_LT(ratio, 20.0);
}

// A clamped cubic B-spline evaluated by de Boor's algorithm (The NURBS Book, A3.1 / §3.2).
Vec2<double> DeBoor(const std::vector<double>& knots, const std::vector<Vec2<double>>& poles, double x) {
  int k = 3;
  while (k + 1 < static_cast<int>(knots.size()) - 4 && knots[k + 1] <= x) ++k;
  std::vector<Vec2<double>> d(poles.begin() + (k - 3), poles.begin() + k + 1);
  for (int r = 1; r <= 3; ++r)
    for (int j = 3; j >= r; --j) {
      const int i = k - 3 + j;
      const double alpha = (x - knots[i]) / (knots[i + 4 - r] - knots[i]);
      d[j] = (1 - alpha) * d[j - 1] + alpha * d[j];
    }
  return d[3];
}

TEST(ClosedCubic, ClampedRunsAreTheSameCurve) {
  const Lobed c;
  const auto s = cad::FitClosedCubic(c, 0, 2 * kPi, c.S, 8 * c.S, 1e9, 5000);
  ASSERT_TRUE(s.has_value());
  const int n = static_cast<int>(s->poles.size());
  for (const auto& [a, b] : std::vector<std::pair<int, int>>{{0, 44}, {44, 88}, {80, 95}, {3, 4}, {0, 88}}) {
    const std::vector<Vec2<double>> poles = cad::ClampedSpans(*s, a, b);
    ASSERT_EQ(static_cast<int>(poles.size()), b - a + 3);
    std::vector<double> knots(4, a);
    for (int k = a + 1; k < b; ++k) knots.push_back(k);
    for (int k = 0; k < 4; ++k) knots.push_back(b);
    double worst = 0;
    for (int i = 0; i <= 200; ++i) {
      const double x = a + (b - a) * i / 200.0;
      const double u = std::fmod(x, double(n));
      worst = std::max(worst, (DeBoor(knots, poles, std::min(x, b - 1e-12)) - cad::PointOnClosedCubic(*s, u)).norm());
    }
    EXPECT_LT(worst, 1e-11) << a << ".." << b;
    // The ends are the spline's points at the knots a and b.
    EXPECT_LT((poles.front() - cad::PointOnClosedCubic(*s, a % n)).norm(), 1e-12);
    EXPECT_LT((poles.back() - cad::PointOnClosedCubic(*s, b % n)).norm(), 1e-12);
  }
}

TEST(ClosedCubic, ACurvatureJumpIsNotForcedIntoFewPoles) {
  // A stadium: half circles of radius 10 joined by lines of 20 (curvature 0.1 → 0): the error falls
  // as h² near the joints, and 1 µm would take hundreds of spans.
  const auto stadium = [](double t) {
    const double L = 20, r = 10, p = 2 * L + 2 * kPi * r;
    double s = std::fmod(t * p / (2 * kPi), p);
    if (s < L) return Vec2<double>(-L / 2 + s, -r);
    s -= L;
    if (s < kPi * r) return Vec2<double>(L / 2 + r * std::sin(s / r), -r * std::cos(s / r));
    s -= kPi * r;
    if (s < L) return Vec2<double>(L / 2 - s, r);
    s -= L;
    return Vec2<double>(-L / 2 - r * std::sin(s / r), r * std::cos(s / r));
  };
  EXPECT_FALSE(cad::FitClosedCubic(stadium, 0, 2 * kPi, 1, 16, 1e-3, 120).has_value());
  const auto loose = cad::FitClosedCubic(stadium, 0, 2 * kPi, 1, 16, 1e-3, 100000);
  ASSERT_TRUE(loose.has_value());
  EXPECT_GT(loose->poles.size(), 120u);
  EXPECT_LE(loose->max_deviation_mm, 1e-3);
}

TEST(ClosedCubic, StepWallsOfTheSplineReadBackWithTheExactVolume) {
  const Lobed c;
  cad::FitOptions o;
  o.tolerance_mm = 0.9e-3;
  cad::Extrusion e;
  e.profile = cad::FitBiarcsSymmetric(c, 0, 2 * kPi, c.S, Vec2<double>::Zero(), o).arcs;
  e.bore_diameter_mm = 20;
  e.thickness_mm = 12;
  e.name = "lobed";
  ASSERT_GT(e.profile.size(), 64u);
  const std::string arcs = cad::StepOfExtrusion(e);
  e.profile_spline = cad::FitClosedCubic(c, 0, 2 * kPi, c.S, 8 * c.S, 0.9e-3, int(e.profile.size()) - 1);
  ASSERT_TRUE(e.profile_spline.has_value());
  ASSERT_TRUE(cad::SplineWalls(e));
  const std::string spline = cad::StepOfExtrusion(e);
  EXPECT_NE(spline.find("B_SPLINE_SURFACE_WITH_KNOTS('',3,1,"), std::string::npos);
  EXPECT_EQ(spline.find("RATIONAL_B_SPLINE_SURFACE"), std::string::npos);
  const double volume = (c.Area() - kPi * 100) * 12;
  for (const std::string* file : {&arcs, &spline}) {
    const cad::StepReadBack back = cad::ReadStep(*file);
    EXPECT_EQ(back.solids, 1);
    EXPECT_TRUE(back.valid);
    // Either wall is within 1 µm of the exact curve: the volume within perimeter × 1 µm × t.
    EXPECT_NEAR(back.volume_mm3, volume, 2 * kPi * 52 * 1e-3 * 12);
  }
  std::printf("%zu arcs: STEP %zu bytes; %zu-pole cubic: %zu bytes\n", e.profile.size(), arcs.size(),
              e.profile_spline->poles.size(), spline.size());
  EXPECT_LT(spline.size(), arcs.size() / 2);
  // Fewer poles than arcs is the condition: a spline of as many is not used.
  e.profile_spline->poles.resize(e.profile.size());
  EXPECT_FALSE(cad::SplineWalls(e));
}

}  // namespace cad_bspline_test
}  // namespace camopt
