#include "cad/bspline.h"

#include <algorithm>
#include <cmath>

namespace camopt::cad {

namespace {

int Mod(long i, long n) { return static_cast<int>(((i % n) + n) % n); }

// The inverse of the circulant (1, 4, 1)/6 on an infinite sequence: √3 r^|k|, r = √3 − 2 (from
// c_{k−1} + 4 c_k + c_{k+1} = 6 δ_k: r + 1/r = −4, and 2r + 4 = 2√3 at k = 0). |r|^31 < 2e-18.
constexpr int kInverseTerms = 30;

}  // namespace

Vec2<double> PointOnClosedCubic(const ClosedCubic& s, double u) {
  const long n = static_cast<long>(s.poles.size());
  double whole = std::floor(u);
  double f = u - whole;
  if (f >= 1.0) f = 0.0, whole += 1.0;  // u just below an integer rounded up
  const long i = static_cast<long>(whole);
  const double f2 = f * f, f3 = f2 * f, g = 1.0 - f;
  return (g * g * g * s.poles[Mod(i - 1, n)] + (3 * f3 - 6 * f2 + 4) * s.poles[Mod(i, n)] +
          (-3 * f3 + 3 * f2 + 3 * f + 1) * s.poles[Mod(i + 1, n)] + f3 * s.poles[Mod(i + 2, n)]) /
         6.0;
}

namespace {

// The curve's parameter as a smooth function of the spline's: the knots are placed at uniform
// steps of arc length F(t) = ∫|C'(t)| dt. A cubic interpolating a curve by arc length is off by
// about h⁴ |C⁗(s)| / 384 (the curve's own parameter may crowd the knots where the profile turns
// least: at uniform steps of its own parameter the cycloid disc's tooth needed more poles than it
// has arcs; by arc length 435 for 690 arcs). Steps weighted by curvature, (κ² + 1/D²)^(−3/8) as the
// error on a circle (|C⁗| = κ³) suggests, were tried and needed more poles on a lobed curve with
// inflections (627 against about 130 by arc length; 4.8e-2 against 4.5e-3 mm at 88 spans): C⁗
// holds κ'' and κκ' too. |C'| by central differences of the curve function; F by 3-point
// Gauss-Legendre on a dense grid, inverted by Newton's method on the same rule (so that t(u) is
// smooth, as the spline's accuracy needs).
class Reparameterisation {
 public:
  Reparameterisation(const CurveFunction& curve, double t0, double t1, int dense)
      : curve_(curve), t0_(t0), t1_(t1), dense_(dense), h_fd_(1e-5 * (t1 - t0)) {
    f_.assign(static_cast<size_t>(dense) + 1, 0.0);
    for (int j = 0; j < dense; ++j) f_[j + 1] = f_[j] + Integral(Node(j), Node(j + 1));
  }
  bool Finite() const { return std::isfinite(f_.back()) && f_.back() > 0; }
  // t where F is the fraction w ∈ [0, 1] of its total.
  double At(double w) const {
    const double level = w * f_.back();
    const int j = Interval(level);
    double lo = Node(j), hi = Node(j + 1);
    double t = Rough(w);
    for (int k = 0; k < 12; ++k) {
      const double g = f_[j] + Integral(Node(j), t) - level;
      if (g > 0) hi = t; else lo = t;
      double next = t - g / Monitor(t);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::abs(next - t) <= 1e-15 * (t1_ - t0_)) return next;
      t = next;
    }
    return t;
  }
  // The same from the dense table alone (linear between its nodes): a start for Newton's method.
  double Rough(double w) const {
    const double level = w * f_.back();
    const int j = Interval(level);
    return Node(j) + (Node(j + 1) - Node(j)) * (level - f_[j]) / std::max(f_[j + 1] - f_[j], 1e-300);
  }
  Vec2<double> Derivative(double t) const { return (curve_(t + h_fd_) - curve_(t - h_fd_)) / (2 * h_fd_); }

 private:
  int Interval(double level) const {
    const int j = static_cast<int>(std::upper_bound(f_.begin(), f_.end(), level) - f_.begin()) - 1;
    return std::clamp(j, 0, dense_ - 1);
  }
  double Node(int j) const { return t0_ + (t1_ - t0_) * j / dense_; }
  double Monitor(double t) const { return Derivative(t).norm(); }
  double Integral(double a, double b) const {
    const double m = 0.5 * (a + b), r = 0.5 * (b - a), x = std::sqrt(0.6);
    return r * (5.0 / 9.0 * Monitor(m - r * x) + 8.0 / 9.0 * Monitor(m) + 5.0 / 9.0 * Monitor(m + r * x));
  }
  const CurveFunction& curve_;
  double t0_, t1_;
  int dense_;
  double h_fd_;
  std::vector<double> f_;
};

}  // namespace

std::optional<ClosedCubic> FitClosedCubic(const CurveFunction& curve, double t0, double t1, int symmetry,
                                          int min_spans, double target_mm, int max_poles) {
  const long sym = std::max(1, symmetry);
  const auto round_up = [&](double n) {
    const long periods = static_cast<long>(std::ceil(n / double(sym) - 1e-9));
    return std::max<long>(periods, 1) * sym;
  };
  double weights[kInverseTerms + 1];
  const double r = std::sqrt(3.0) - 2.0;
  weights[0] = std::sqrt(3.0);
  for (int k = 1; k <= kInverseTerms; ++k) weights[k] = weights[k - 1] * r;
  // F's dense grid: 64 nodes a period at least, and 4 a span of the most the fit may take.
  const long dense = std::min<long>(std::max<long>(64 * sym, 4L * max_poles), 1L << 20);
  const Reparameterisation param(curve, t0, t1, static_cast<int>(dense));
  if (!param.Finite()) return std::nullopt;
  long n = round_up(std::max(min_spans, 4));
  for (int attempt = 0; attempt < 80; ++attempt) {
    if (n > max_poles) return std::nullopt;
    std::vector<Vec2<double>> q(static_cast<size_t>(n));
    for (long i = 0; i < n; ++i) {
      q[i] = curve(param.At(double(i) / double(n)));
      if (!q[i].allFinite()) return std::nullopt;
    }
    ClosedCubic s;
    s.poles.assign(static_cast<size_t>(n), Vec2<double>::Zero());
    for (long i = 0; i < n; ++i) {
      Vec2<double> p = weights[0] * q[i];
      for (int k = 1; k <= kInverseTerms; ++k) p += weights[k] * (q[Mod(i - k, n)] + q[Mod(i + k, n)]);
      s.poles[i] = p;
    }
    // The error is zero at the knots and peaks inside the spans: 16 points of each, every one's
    // distance to the exact curve (the foot of the perpendicular by two Gauss-Newton steps from the
    // curve's point at the same fraction of F).
    constexpr int kChecks = 16;
    // After the first count only "within the target or not" steers the search (the next count
    // is a fixed step), so a check beyond the target ends that count's checking; the first
    // count's whole error feeds the h⁴ law, and a count returned was checked at every point.
    const bool stop_at_first_miss = attempt > 0;
    double worst = 0.0;
    for (long i = 0; i < n && !(stop_at_first_miss && !(worst <= target_mm)); ++i) {
      for (int j = 0; j < kChecks; ++j) {
        const double u = double(i) + (j + 0.5) / kChecks;
        const Vec2<double> p = PointOnClosedCubic(s, u);
        double t = param.Rough(u / double(n));
        for (int k = 0; k < 2; ++k) {
          const Vec2<double> d = param.Derivative(t);
          t -= (curve(t) - p).dot(d) / std::max(d.squaredNorm(), 1e-300);
        }
        const double dist = (curve(t) - p).norm();
        if (!(dist <= worst)) worst = dist;  // NaN wins
      }
    }
    s.max_deviation_mm = worst;
    s.checked_points = n * kChecks;
    if (!std::isfinite(worst)) return std::nullopt;
    if (worst <= target_mm) return s;
    // From the first count, the one the error's h⁴ law asks for; then up by steps of a period or
    // 2 %, the first count within the target kept: the error is not monotone in the count (lcr_ii's
    // input cam: 1.21, 3.24, 2.50, 0.49 µm at 264, 276, 288, 300 spans), and a larger jump lands
    // on a worse count as often as on a better one (the cycloid tooth took 645 poles that way,
    // 435 by steps).
    const long law = round_up(double(n) * std::pow(worst / target_mm, 0.25));
    n = attempt == 0 && law > n ? law : round_up(double(n) + std::max(double(sym), 0.02 * double(n)));
  }
  return std::nullopt;
}

std::vector<Vec2<double>> ClampedSpans(const ClosedCubic& s, int a, int b) {
  const long n = static_cast<long>(s.poles.size());
  // The unrolled curve over knots u_j = j, j = a−3 … b+3, with poles D_j = P_{j+2}, j = a−3 … b−1
  // (the basis of D_j spans [u_j, u_{j+4}); span a uses D_{a−3} … D_a = P_{a−1} … P_{a+2}).
  std::vector<double> knots;
  std::vector<Vec2<double>> d;
  for (int j = a - 3; j <= b + 3; ++j) knots.push_back(j);
  for (int j = a - 3; j <= b - 1; ++j) d.push_back(s.poles[Mod(j + 2, n)]);
  // Boehm's insertion of x (The NURBS Book, algorithm A5.1 with p = 3): k the last knot ≤ x;
  // Q_i = α_i D_i + (1 − α_i) D_{i−1}, α_i = (x − u_i)/(u_{i+3} − u_i) for k−2 ≤ i ≤ k, D_i before,
  // D_{i−1} after (α_i is 0 where x is already a knot of u_i, which gives D_{i−1}).
  const auto insert = [&](double x) {
    const int k = static_cast<int>(std::upper_bound(knots.begin(), knots.end(), x) - knots.begin()) - 1;
    std::vector<Vec2<double>> q(d.size() + 1);
    for (int i = 0; i < static_cast<int>(q.size()); ++i) {
      if (i <= k - 3) {
        q[i] = d[i];
      } else if (i > k) {
        q[i] = d[i - 1];
      } else {
        // α = 0 where x is already a knot at or before u_i (at the run's last knot i = k is one past
        // the poles): D_{i−1} alone, D_i not read.
        const double alpha = (x - knots[i]) / (knots[i + 3] - knots[i]);
        q[i] = alpha > 0 ? alpha * d[i] + (1.0 - alpha) * d[i - 1] : d[i - 1];
      }
    }
    knots.insert(knots.begin() + k + 1, x);
    d = std::move(q);
  };
  insert(a), insert(a), insert(b), insert(b);
  // Knot a now at indices 3, 4, 5: the curve passes through D_2 there; b likewise at the end.
  return std::vector<Vec2<double>>(d.begin() + 2, d.end() - 2);
}

ClosedCubic Rotated(const ClosedCubic& s, double angle_rad) {
  ClosedCubic out = s;
  const double c = std::cos(angle_rad), sn = std::sin(angle_rad);
  for (Vec2<double>& p : out.poles) p = Vec2<double>(c * p.x() - sn * p.y(), sn * p.x() + c * p.y());
  return out;
}

}  // namespace camopt::cad
