// Shared reference problems with known optima, run through every solver adapter.
#pragma once

#include <cmath>
#include <span>

#include "model/common/roots.h"
#include "objectives/lcr_sizing.h"
#include "objectives/problem.h"
#include "tests/reference_designs.h"

namespace camopt::testing {

/// Hock & Schittkowski problem 71: min x1 x4 (x1 + x2 + x3) + x3
/// s.t. x1 x2 x3 x4 >= 25, x1^2 + x2^2 + x3^2 + x4^2 = 40, 1 <= x <= 5, x0 = (1, 5, 5, 1).
/// Known optimum f* = 17.0140173 at (1, 4.7429994, 3.8211503, 1.3794082) (Hock & Schittkowski 1981).
/// unit_scale expresses every variable in a unit unit_scale times smaller (x_here = unit_scale x),
/// with the matching variable scale, to check that scaling is translated correctly.
inline objectives::Problem Hs71(double unit_scale = 1.0) {
  objectives::Problem p;
  const char* names[4] = {"x1", "x2", "x3", "x4"};
  for (int i = 0; i < 4; ++i)
    p.variables.push_back({names[i], 1.0 * unit_scale, 5.0 * unit_scale,
                           (i == 0 || i == 3 ? 1.0 : 5.0) * unit_scale, unit_scale});
  p.evaluator = objectives::MakeEvaluator<4>(
      4, {{"f", 0, 1}, {"product", 1, 1}, {"sum_squares", 2, 1}},
      [unit_scale](auto x, auto y) {
        using T = std::decay_t<decltype(x[0])>;
        const T x1 = x[0] / unit_scale, x2 = x[1] / unit_scale, x3 = x[2] / unit_scale,
                x4 = x[3] / unit_scale;
        y[0] = x1 * x4 * (x1 + x2 + x3) + x3;
        y[1] = x1 * x2 * x3 * x4;
        y[2] = x1 * x1 + x2 * x2 + x3 * x3 + x4 * x4;
      });
  p.objective = "f";
  p.constraints = {{"product", 25.0, kInf, 25.0}, {"sum_squares", 40.0, 40.0, 40.0}};
  return p;
}
constexpr double kHs71Optimum = 17.0140173;

/// A convex QP whose optimum has a general constraint and a variable bound active:
///   min (x − 3)² + (y − 2)²  s.t. x + y <= 2,  −10 <= x <= 10,  −10 <= y <= 0.25,  start (0, 0).
/// KKT by hand: with y at its upper bound 0.25, x + y = 2 gives x = 1.75; ∇f = (−2.5, −3.5) and
/// ∇f + λ (1, 1) + μ (0, 1) = 0 give λ = 2.5 >= 0 and μ = 1 >= 0. A KKT point of a convex problem
/// is its global minimum: x* = (1.75, 0.25), f* = 1.25² + 1.75² = 4.625.
inline objectives::Problem QpWithActiveConstraintAndBound() {
  objectives::Problem p;
  p.variables = {{"x", -10.0, 10.0, 0.0, 1.0}, {"y", -10.0, 0.25, 0.0, 1.0}};
  p.evaluator = objectives::MakeEvaluator<2>(2, {{"f", 0, 1}, {"sum", 1, 1}}, [](auto x, auto y) {
    y[0] = (x[0] - 3.0) * (x[0] - 3.0) + (x[1] - 2.0) * (x[1] - 2.0);
    y[1] = x[0] + x[1];
  });
  p.objective = "f";
  p.constraints = {{"sum", -kInf, 2.0, 1.0}};
  return p;
}
constexpr double kQpOptimum = 4.625;
constexpr double kQpOptimumX = 1.75, kQpOptimumY = 0.25;

/// Rosenbrock restricted to the unit disk: min (1 - x)^2 + 100 (y - x^2)^2 s.t. x^2 + y^2 <= 1,
/// unbounded variables (real infinities), start at (-0.5, 0.5).
inline objectives::Problem RosenbrockOnDisk() {
  objectives::Problem p;
  p.variables = {{"x", -kInf, kInf, -0.5, 1.0}, {"y", -kInf, kInf, 0.5, 1.0}};
  p.evaluator = objectives::MakeEvaluator<2>(2, {{"f", 0, 1}, {"r2", 1, 1}}, [](auto x, auto y) {
    using T = std::decay_t<decltype(x[0])>;
    const T a = T(1.0) - x[0], b = x[1] - x[0] * x[0];
    y[0] = a * a + T(100.0) * b * b;
    y[1] = x[0] * x[0] + x[1] * x[1];
  });
  p.objective = "f";
  p.constraints = {{"r2", -kInf, 1.0, 1.0}};
  return p;
}

/// The disk problem's optimum, by an independent construction: the unconstrained minimum (1, 1)
/// lies outside the disk, so the optimum is on the circle (cos t, sin t); minimise over t by a
/// dense scan and golden-section refinement.
inline std::pair<double, double> RosenbrockOnDiskOptimum() {
  auto f = [](double t) {
    const double x = std::cos(t), y = std::sin(t);
    return (1 - x) * (1 - x) + 100 * (y - x * x) * (y - x * x);
  };
  double best_t = 0, best = f(0);
  for (int i = 1; i < 20000; ++i) {
    const double t = 2 * kPi * i / 20000;
    if (f(t) < best) best = f(t), best_t = t;
  }
  const GoldenSectionBracket b = GoldenSectionMaximize([&](double t) { return -f(t); },
                                                       best_t - 2 * kPi / 20000, best_t + 2 * kPi / 20000, 200);
  const double t = 0.5 * (b.lo + b.hi);
  return {t, f(t)};
}

}  // namespace camopt::testing
