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

/// Three points of f already known, the best first: Brent's method started from them (its first
/// step the vertex of their parabola) instead of from one golden-section point.
struct BrentStart {
  double x, fx;  ///< the best point
  double w, fw;  ///< the second best
  double v, fv;  ///< the third
};

/// The maximum of f on [lo, hi] (f unimodal there) by Brent's method (R. P. Brent, *Algorithms for
/// Minimization without Derivatives*, 1973, ch. 5): a parabola through the three best points when
/// its vertex falls well inside the bracket and the step shrinks, a golden-section step otherwise.
/// A smooth maximum is found in a handful of evaluations where golden sections take one per
/// 0.618 of the bracket. Stops when the bracket around the best point is within x_tolerance
/// (plus a few ulps of x) or after max_iterations. Values of −∞ (f undefined there) are allowed:
/// no parabola is fitted through them. Returns {x, f(x)} of the best point evaluated.
/// From a start of three samples (the best, the second, the third), the first step may be their
/// parabola's vertex. With f_tolerance > 0 it also stops after a parabolic step whose parabola
/// rose less than f_tolerance above the best value (a smooth maximum: what is left is of higher
/// order than that rise).
template <typename F>
std::pair<double, double> BrentMaximize(const F& f, double lo, double hi, const BrentStart& start, int max_iterations,
                                        double x_tolerance, double f_tolerance = 0.0) {
  const double golden = 0.5 * (3.0 - std::sqrt(5.0));
  const double eps = 4.0 * std::numeric_limits<double>::epsilon();
  // x: the best point so far, w: the second best, v: the previous w; fx >= fw >= fv.
  double x = start.x, w = start.w, v = start.v;
  double fx = start.fx, fw = start.fw, fv = start.fv;
  // With three distinct points the first step may be their parabola's (it must move less than
  // half the step before last: the bracket's width stands for it).
  double step = 0.0, previous = (w != x && v != x && v != w) ? hi - lo : 0.0;
  for (int it = 0; it < max_iterations; ++it) {
    const double mid = 0.5 * (lo + hi);
    const double tol = eps * std::abs(x) + x_tolerance / 3.0;
    if (std::abs(x - mid) <= 2.0 * tol - 0.5 * (hi - lo)) break;
    bool parabola = false, last = false;
    if (std::abs(previous) > tol && std::isfinite(fx) && std::isfinite(fw) && std::isfinite(fv)) {
      // The vertex of the parabola through (x, fx), (w, fw), (v, fv) as x + p/q.
      const double r = (x - w) * (fx - fv);
      double q = (x - v) * (fx - fw);
      double p = (x - v) * q - (x - w) * r;
      q = 2.0 * (q - r);
      if (q > 0.0) p = -p;
      q = std::abs(q);
      // Accepted when it lies inside the bracket and moves less than half the step before last.
      if (q != 0.0 && std::abs(p) < std::abs(0.5 * q * previous) && p > q * (lo - x) && p < q * (hi - x)) {
        previous = step;
        step = p / q;
        const double u = x + step;
        if (u - lo < 2.0 * tol || hi - u < 2.0 * tol) {
          step = x < mid ? tol : -tol;
        } else if (f_tolerance > 0.0) {
          // The parabola rises above fx by −f[x, w, v]·step² at its vertex: when that is below
          // f_tolerance, the vertex is the last step (what is left beyond it is of third order).
          const double dd = ((fx - fw) / (x - w) - (fx - fv) / (x - v)) / (w - v);
          last = dd < 0.0 && -dd * step * step < f_tolerance;
        }
        parabola = true;
      }
    }
    if (!parabola) {
      previous = (x < mid ? hi : lo) - x;
      step = golden * previous;
    }
    const double u = x + (std::abs(step) >= tol ? step : (step > 0 ? tol : -tol));
    const double fu = f(u);
    if (fu >= fx) {
      (u < x ? hi : lo) = x;
      v = w, fv = fw, w = x, fw = fx, x = u, fx = fu;
    } else {
      (u < x ? lo : hi) = u;
      if (fu >= fw || w == x) {
        v = w, fv = fw, w = u, fw = fu;
      } else if (fu >= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
    if (last) break;
  }
  return {x, fx};
}

/// Brent's method from one golden-section point of [lo, hi] (Brent's own start).
template <typename F>
std::pair<double, double> BrentMaximize(const F& f, double lo, double hi, int max_iterations,
                                        double x_tolerance) {
  const double x = lo + 0.5 * (3.0 - std::sqrt(5.0)) * (hi - lo);
  const double fx = f(x);
  return BrentMaximize(f, lo, hi, BrentStart{x, fx, x, fx, x, fx}, max_iterations, x_tolerance);
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
