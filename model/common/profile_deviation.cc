#include "model/common/profile_deviation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace camopt::profile {

namespace {
// 5-point Gauss–Legendre nodes and weights on [−1, 1].
constexpr double kNodes[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                              0.9061798459386640};
constexpr double kWeights[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                0.2369268850561891};
}  // namespace

Curve CurveFromPoints(std::function<Vec2<double>(double)> f, double h) {
  return [f = std::move(f), h](double t) {
    const Vec2<double> m2 = f(t - 2 * h), m1 = f(t - h), p0 = f(t), p1 = f(t + h), p2 = f(t + 2 * h);
    const Vec2<double> d1 = (m2 - 8.0 * m1 + 8.0 * p1 - p2) / (12.0 * h);
    const Vec2<double> d2 = (-m2 + 16.0 * m1 - 30.0 * p0 + 16.0 * p1 - p2) / (12.0 * h * h);
    CurvePoint c;
    c.point = p0;
    c.speed = d1.norm();
    c.tangent = d1 / c.speed;
    c.curvature = Cross(d1, d2) / (c.speed * c.speed * c.speed);
    return c;
  };
}

ClosedProfile::ClosedProfile(Curve curve, double t0, double period, int samples)
    : curve_(std::move(curve)), t0_(t0), period_(period) {
  const int n = std::max(16, samples);
  table_t_.resize(size_t(n) + 1);
  table_s_.assign(size_t(n) + 1, 0.0);
  table_p_.resize(size_t(n));
  double area2 = 0, lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
  for (int i = 0; i <= n; ++i) table_t_[size_t(i)] = t0 + period * i / n;
  for (int i = 0; i < n; ++i) {
    table_p_[size_t(i)] = curve_(table_t_[size_t(i)]).point;
    const Vec2<double>& p = table_p_[size_t(i)];
    lo_x = std::min(lo_x, p.x()), hi_x = std::max(hi_x, p.x());
    lo_y = std::min(lo_y, p.y()), hi_y = std::max(hi_y, p.y());
  }
  for (int i = 0; i < n; ++i) {
    area2 += Cross(table_p_[size_t(i)], table_p_[size_t((i + 1) % n)]);
    table_s_[size_t(i) + 1] = table_s_[size_t(i)] + Gauss(table_t_[size_t(i)], table_t_[size_t(i) + 1]);
  }
  length_ = table_s_.back();
  size_ = std::hypot(hi_x - lo_x, hi_y - lo_y);
  // Counter-clockwise (positive area): the material on the left, the outward normal on the right.
  outward_ = area2 >= 0 ? 1.0 : -1.0;
}

double ClosedProfile::Gauss(double a, double b) const {
  double s = 0;
  for (int k = 0; k < 5; ++k) s += kWeights[k] * curve_(0.5 * (a + b) + 0.5 * (b - a) * kNodes[k]).speed;
  return 0.5 * (b - a) * s;
}

double ClosedProfile::Wrap(double t) const {
  double u = t - period_ * std::floor((t - t0_) / period_);
  if (u >= t0_ + period_) u -= period_;
  return u;
}

double ClosedProfile::ArcLength(double t) const {
  const int n = int(table_p_.size());
  const double f = (t - t0_) / period_ * n;
  const int k = std::clamp(int(std::floor(f)), 0, n - 1);
  return table_s_[size_t(k)] + Gauss(table_t_[size_t(k)], t);
}

double ClosedProfile::ParameterAt(double s) const {
  const int n = int(table_p_.size());
  const int k = std::clamp(int(std::upper_bound(table_s_.begin(), table_s_.end(), s) - table_s_.begin()) - 1, 0, n - 1);
  double lo = table_t_[size_t(k)], hi = table_t_[size_t(k) + 1];
  const double s_lo = table_s_[size_t(k)];
  // Newton on S(t) − s inside [lo, hi] (S increasing), bisection when a step leaves it.
  double t = lo + (hi - lo) * std::clamp((s - s_lo) / (table_s_[size_t(k) + 1] - s_lo), 0.0, 1.0);
  for (int it = 0; it < 60; ++it) {
    const double g = s_lo + Gauss(table_t_[size_t(k)], t) - s;
    if (g > 0) hi = t; else lo = t;
    double next = t - g / curve_(t).speed;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool done = std::abs(next - t) <= 1e-15 * std::max(1.0, std::abs(t));
    t = next;
    if (done) break;
  }
  return t;
}

ClosedProfile::Projection ClosedProfile::Project(const Vec2<double>& q) const {
  const int n = int(table_p_.size());
  int best = 0;
  double best_d2 = INFINITY;
  for (int i = 0; i < n; ++i) {
    const double d2 = (table_p_[size_t(i)] - q).squaredNorm();
    if (d2 < best_d2) best_d2 = d2, best = i;
  }
  const double h = period_ / n;
  auto g = [&](double t, double* slope) {
    const CurvePoint c = curve_(t);
    const Vec2<double> r = c.point - q;
    if (slope) *slope = c.speed * (1.0 + c.curvature * r.dot(Perp(c.tangent)));
    return r.dot(c.tangent);
  };
  double lo = table_t_[size_t(best)] - h, hi = table_t_[size_t(best)] + h;
  double g_lo = g(lo, nullptr), g_hi = g(hi, nullptr);
  double t = table_t_[size_t(best)];
  if (g_lo <= 0 && g_hi >= 0) {
    // Safeguarded Newton on g in the bracket.
    for (int it = 0; it < 100; ++it) {
      double slope;
      const double gv = g(t, &slope);
      if (gv > 0) hi = t; else lo = t;
      double next = slope > 0 ? t - gv / slope : 0.5 * (lo + hi);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      const bool done = std::abs(next - t) <= 4e-16 * std::max(1.0, std::abs(t));
      t = next;
      if (done || hi - lo <= 4e-16 * std::max(1.0, std::abs(t))) break;
    }
  } else {
    // No sign change (q far from a smooth neighbourhood): golden section on the distance.
    const double r = 0.5 * (std::sqrt(5.0) - 1.0);
    double a = lo, b = hi;
    auto dist2 = [&](double u) { return (curve_(u).point - q).squaredNorm(); };
    double c = b - r * (b - a), d = a + r * (b - a), fc = dist2(c), fd = dist2(d);
    for (int it = 0; it < 200 && b - a > 1e-15 * std::max(1.0, std::abs(a)); ++it) {
      if (fc < fd) b = d, d = c, fd = fc, c = b - r * (b - a), fc = dist2(c);
      else a = c, c = d, fc = fd, d = a + r * (b - a), fd = dist2(d);
    }
    t = 0.5 * (a + b);
  }
  Projection p;
  p.t = Wrap(t);
  const CurvePoint c = curve_(p.t);
  p.foot = c.point;
  p.normal = OutwardNormal(c);
  p.deviation_mm = (q - c.point).dot(p.normal);
  p.distance_mm = (q - c.point).norm();
  return p;
}

std::vector<InspectionPoint> InspectionPoints(const ClosedProfile& profile, double spacing_mm) {
  const double length = profile.length_mm();
  const long n = std::max(3L, long(std::ceil(length / spacing_mm * (1.0 + 1e-12))));
  std::vector<InspectionPoint> out;
  out.reserve(size_t(n));
  for (long i = 0; i < n; ++i) {
    InspectionPoint ip;
    ip.t = i == 0 ? profile.t0() : profile.ParameterAt(length * double(i) / double(n));
    const CurvePoint c = profile.Eval(ip.t);
    ip.point = c.point;
    ip.normal = profile.OutwardNormal(c);
    out.push_back(ip);
  }
  return out;
}

PeriodicSpline::PeriodicSpline(std::vector<double> t, std::vector<double> d, double period)
    : t_(std::move(t)), d_(std::move(d)), period_(period) {
  const size_t n = t_.size();
  if (n < 3 || d_.size() != n) throw std::invalid_argument("PeriodicSpline: needs at least 3 knots");
  std::vector<double> h(n);
  for (size_t i = 0; i < n; ++i) {
    h[i] = (i + 1 < n ? t_[i + 1] : t_[0] + period_) - t_[i];
    if (!(h[i] > 0)) throw std::invalid_argument("PeriodicSpline: knots must increase within one period");
  }
  // Row i: h_{i−1} M_{i−1}/6 + (h_{i−1} + h_i) M_i/3 + h_i M_{i+1}/6 = Δ_i/h_i − Δ_{i−1}/h_{i−1}.
  std::vector<double> lower(n), diag(n), upper(n), rhs(n);
  for (size_t i = 0; i < n; ++i) {
    const size_t im = (i + n - 1) % n, ip = (i + 1) % n;
    lower[i] = h[im] / 6.0;
    diag[i] = (h[im] + h[i]) / 3.0;
    upper[i] = h[i] / 6.0;
    rhs[i] = (d_[ip] - d_[i]) / h[i] - (d_[i] - d_[im]) / h[im];
  }
  // Cyclic tridiagonal by Sherman–Morrison: A = B + u vᵀ with u = (γ, 0 … 0, c_{n−1}),
  // v = (1, 0 … 0, a_0/γ), B tridiagonal with B_00 = b_0 − γ, B_{n−1,n−1} = b_{n−1} − c_{n−1} a_0/γ.
  const double corner_top = lower[0], corner_bottom = upper[n - 1];
  const double gamma = -diag[0];
  auto solve_tridiagonal = [&](std::vector<double> b, std::vector<double> r) {
    std::vector<double> c(n), x(n);
    b[0] -= gamma;
    b[n - 1] -= corner_bottom * corner_top / gamma;
    c[0] = upper[0] / b[0];
    r[0] = r[0] / b[0];
    for (size_t i = 1; i < n; ++i) {
      const double m = b[i] - lower[i] * c[i - 1];
      c[i] = upper[i] / m;
      r[i] = (r[i] - lower[i] * r[i - 1]) / m;
    }
    x[n - 1] = r[n - 1];
    for (size_t i = n - 1; i-- > 0;) x[i] = r[i] - c[i] * x[i + 1];
    return x;
  };
  std::vector<double> u(n, 0.0);
  u[0] = gamma;
  u[n - 1] = corner_bottom;
  const std::vector<double> y = solve_tridiagonal(diag, rhs);
  const std::vector<double> z = solve_tridiagonal(diag, u);
  const double vy = y[0] + corner_top / gamma * y[n - 1], vz = z[0] + corner_top / gamma * z[n - 1];
  m_.resize(n);
  for (size_t i = 0; i < n; ++i) m_[i] = y[i] - vy / (1.0 + vz) * z[i];
}

ProfileZone MeasureZone(const std::vector<double>& d) {
  ProfileZone z;
  if (d.empty()) return z;
  double sum = 0, sum2 = 0;
  z.argmax = z.argmin = 0;
  for (size_t i = 0; i < d.size(); ++i) {
    if (d[i] > d[size_t(z.argmax)]) z.argmax = int(i);
    if (d[i] < d[size_t(z.argmin)]) z.argmin = int(i);
    sum += d[i];
    sum2 += d[i] * d[i];
  }
  z.max_mm = d[size_t(z.argmax)];
  z.min_mm = d[size_t(z.argmin)];
  z.zone_width_mm = 2.0 * std::max(std::abs(z.max_mm), std::abs(z.min_mm));
  z.mean_mm = sum / double(d.size());
  z.rms_mm = std::sqrt(sum2 / double(d.size()));
  return z;
}

}  // namespace camopt::profile
