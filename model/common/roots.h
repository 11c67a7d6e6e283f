// One-dimensional searches on values (double), shared by every model: golden-section search for
// the maximum of a unimodal function, bisection and safeguarded Newton for the root of a
// non-decreasing function. They find where to evaluate; derivatives come from evaluating the model
// in T there (envelope theorem, implicit function theorem), as each caller documents.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace camopt {

/// The bracket left by GoldenSectionMaximize: [lo, hi] holds the maximiser; x1 < x2 are its two
/// interior points with f1 = f(x1), f2 = f(x2).
struct GoldenSectionBracket {
  double lo, hi, x1, x2, f1, f2;
};

/// Golden-section search for the maximum of f on [lo, hi], f unimodal there. Each step keeps the
/// part of the bracket around the larger interior value (on a tie, [lo, x2]) and reuses one
/// interior point, shrinking the bracket by (√5 − 1)/2. Stops after max_iterations or when
/// hi − lo <= x_tolerance. To minimise, maximise −f.
template <typename F>
GoldenSectionBracket GoldenSectionMaximize(const F& f, double lo, double hi, int max_iterations,
                                           double x_tolerance = 0.0) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  for (int it = 0; it < max_iterations && hi - lo > x_tolerance; ++it) {
    if (f1 < f2) {
      lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = f(x2);
    } else {
      hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = f(x1);
    }
  }
  return {lo, hi, x1, x2, f1, f2};
}

/// The largest value of circular samples v (sample i at i·h over a period of n·h) and, with refine,
/// every local maximum within `share` of it refined on the continuous function f by golden-section
/// search over its two neighbouring intervals to 1e-12 (2h/0.618^k ≤ 1e-12 within 80 steps); −∞
/// (samples or f) marks what does not count. Returns {value, where}, where in [0, n·h).
template <typename F>
std::pair<double, double> CircularMaxRefined(const std::vector<double>& v, double h, bool refine, double share,
                                             const F& f) {
  const int n = int(v.size());
  int best = -1;
  for (int i = 0; i < n; ++i)
    if (std::isfinite(v[size_t(i)]) && (best < 0 || v[size_t(i)] > v[size_t(best)])) best = i;
  if (best < 0) return {-std::numeric_limits<double>::infinity(), 0.0};
  double value = v[size_t(best)], at = best * h;
  if (!refine) return {value, at};
  const double threshold = value - share * std::max(std::abs(value), 1e-300);
  for (int i = 0; i < n; ++i) {
    const double vi = v[size_t(i)], vl = v[size_t((i + n - 1) % n)], vr = v[size_t((i + 1) % n)];
    if (!std::isfinite(vi) || vi < threshold || vi < vl || vi < vr) continue;
    const GoldenSectionBracket g = GoldenSectionMaximize(f, (i - 1) * h, (i + 1) * h, 80, 1e-12);
    const double fv = std::max(g.f1, g.f2), t = g.f1 >= g.f2 ? g.x1 : g.x2;
    if (std::isfinite(fv) && fv > value) value = fv, at = t;
  }
  const double period = n * h;
  return {value, std::fmod(at + period, period)};
}

/// [lo, hi] around the x where a non-decreasing f reaches target.
struct RootBracket {
  double lo, hi;
  double mid() const { return 0.5 * (lo + hi); }
};

/// Bisection for a non-decreasing f with f(lo) < target <= f(hi): halves the bracket, keeping
/// f(lo) < target <= f(hi), until hi − lo <= rel_tolerance·max(scale_floor, hi) or after
/// max_iterations.
template <typename F>
RootBracket BisectIncreasing(const F& f, double target, double lo, double hi, int max_iterations,
                             double rel_tolerance, double scale_floor = 0.0) {
  for (int it = 0; it < max_iterations && hi - lo > rel_tolerance * std::max(scale_floor, hi); ++it) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < target ? lo : hi) = mid;
  }
  return {lo, hi};
}

/// Newton's method safeguarded by bisection for a non-decreasing f on a bracket [lo, hi] with
/// f(lo) <= target <= f(hi), 0 < lo < hi, starting at x = hi. A Newton step that leaves the bracket
/// (or a non-positive slope) is replaced by the bracket's midpoint. Stops when a step is below
/// step_rel_tolerance·x or the bracket below bracket_rel_tolerance·hi, or after max_iterations;
/// returns the last iterate. slope(x) is f'(x).
template <typename F, typename D>
double SafeguardedNewtonIncreasing(const F& f, const D& slope, double target, double lo, double hi,
                                   int max_iterations, double step_rel_tolerance,
                                   double bracket_rel_tolerance) {
  double x = hi;
  for (int it = 0; it < max_iterations; ++it) {
    const double r = f(x) - target;
    (r > 0 ? hi : lo) = x;
    const double s = slope(x);
    double next = s > 0 ? x - r / s : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool done = std::abs(next - x) <= step_rel_tolerance * x || hi - lo <= bracket_rel_tolerance * hi;
    x = next;
    if (done) break;
  }
  return x;
}

}  // namespace camopt
