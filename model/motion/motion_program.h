// A follower displacement program: a sequence of motion-law segments over one cycle of the cam
// angle θ. Each segment scales a normalised law (motion_law.h) to a rise h over a duration β:
//   S(θ) = S₀ + h N(u), u = (θ − θ₀)/β, dS/dθ = h N'(u)/β, d²S/dθ² = h N''/β², d³S/dθ³ = h N'''/β³.
// A polynomial segment (law kPolynomial) carries its own shape instead of a normalised law:
//   S(θ) = S₀ + P(u), P(u) = Σ_{k=1..n} c_k u^k, fitted through boundary values at both ends
//   (PolynomialThrough: position and velocity → degree 3, with acceleration → 5, with jerk → 7;
//   Norton, Cam Design and Manufacturing Handbook §3.9–3.10, polynomial functions fitted to
//   boundary conditions). Its rise is P(1).
// A B-spline segment (law kBSpline) carries control values instead:
//   S(θ) = S₀ + Σ_{i=0..n} N_{i,p}(u) c_i, c_0 = 0, rise c_n,
// N_{i,p} the B-spline basis of degree p on the clamped knot vector with p + 1 zeros, p + 1 ones and
// n − p uniform interior knots (de Boor, A Practical Guide to Splines, ch. IX–X): the curve starts
// and ends at its first and last control values, tangent to the control polygon there, so that
// repeating the first k + 1 values makes its first k derivatives zero at the start (likewise at the
// end). A derivative is a B-spline of one degree less on the inner knots with the control values
// p (c_{i+1} − c_i)/(t_{i+p+1} − t_{i+1}); each is evaluated by de Boor's algorithm.
// The rise is in the follower's own unit (mm for a translating follower, rad for an oscillating
// one or a globoidal turret); angles are in rad. Independent of any cam type.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "model/common/scalar.h"
#include "model/motion/motion_law.h"

namespace camopt::motion {

template <typename T>
struct MotionSegment {
  MotionSegment() = default;
  /// A segment of a normalised law: {law, rise, duration}.
  MotionSegment(MotionLaw segment_law, T segment_rise, T segment_duration)
      : law(segment_law), rise(segment_rise), duration(segment_duration) {}

  MotionLaw law = MotionLaw::kDwell;
  T rise = T(0.0);      ///< signed rise h over the segment (follower unit)
  T duration = T(0.0);  ///< cam angle β of the segment [rad], > 0
  /// kPolynomial only: c_1 … c_n of P(u) = Σ c_k u^k (follower unit); rise = P(1). (No default
  /// member initialiser: with one, g++ 12 fails on MotionSegment<ceres::Jet> in nothrow_spec_p.)
  std::vector<T> coefficients;
  /// kBSpline only: the degree p (1 … 7); the coefficients are then the control values c_0 … c_n.
  int spline_degree = 0;
};

namespace internal {
/// de Boor's algorithm: the B-spline of degree q with control values c[0 … m] on the knots
/// t[0 … m + q + 1] (clamped) at u ∈ [0, 1]; 0 for q < 0 (a derivative beyond the degree).
template <typename T>
T DeBoor(const T* c, int count, const double* t, int q, const T& u) {
  if (q < 0 || count == 0) return T(0.0);
  const int m = count - 1;
  const double uv = std::clamp(Value(u), 0.0, 1.0);
  int k = q;  // the knot span: t_k <= u < t_{k+1}, q <= k <= m
  while (k < m && t[k + 1] <= uv) ++k;
  T d_small[8];
  std::vector<T> d_heap;
  T* d = q < 8 ? d_small : (d_heap.resize(size_t(q) + 1), d_heap.data());
  for (int j = 0; j <= q; ++j) d[j] = c[j + k - q];
  for (int r = 1; r <= q; ++r)
    for (int j = q; j >= r; --j) {
      const double lo = t[j + k - q], hi = t[j + 1 + k - r];
      const T alpha = (u - T(lo)) / T(hi - lo);
      d[j] = (T(1.0) - alpha) * d[j - 1] + alpha * d[j];
    }
  return d[q];
}

/// The value and the first three u-derivatives of a B-spline segment's shape. The derivative's
/// control values (Piegl & Tiller eq. 3.8) overwrite the segment's in place, on the inner knots
/// t_1 … t_{m+q}; no allocation (a cam profile evaluates this at every point).
template <typename T>
Svaj<T> BSplineShape(const std::vector<T>& control, int degree, const T& u) {
  const int n = int(control.size());
  // Up to 32 control values on the stack, more on the heap (the same arithmetic either way).
  constexpr int kSmall = 32;
  T c_small[kSmall];
  double t_small[kSmall + 8];
  std::vector<T> c_heap;
  std::vector<double> t_heap;
  const bool small = n <= kSmall && degree <= 7;
  if (!small) c_heap.resize(size_t(n)), t_heap.resize(size_t(n + degree + 1));
  T* c = small ? c_small : c_heap.data();
  double* t = small ? t_small : t_heap.data();
  for (int i = 0; i < n; ++i) c[i] = control[size_t(i)];
  for (int i = 0; i <= n + degree; ++i)  // clamped, uniform inside
    t[i] = i <= degree ? 0.0 : i > n - 1 ? 1.0 : double(i - degree) / double(n - 1 - degree + 1);
  int count = n;
  T out[4] = {T(0.0), T(0.0), T(0.0), T(0.0)};
  for (int order = 0; order < 4; ++order) {
    const int q = degree - order;
    out[order] = DeBoor(c, count, t, q, u);
    if (q <= 0) break;  // the higher derivatives are 0
    for (int i = 0; i + 1 < count; ++i) c[i] = T(double(q)) * (c[i + 1] - c[i]) / T(t[i + q + 1] - t[i + 1]);
    --count;
    ++t;
  }
  return {out[0], out[1], out[2], out[3]};
}
}  // namespace internal

/// The B-spline segment of duration β [rad] through the control values `control` (follower unit,
/// absolute: the first is where the segment starts), of degree `degree`.
/// @pre 1 <= degree <= 7, control.size() >= degree + 1, duration > 0.
template <typename T>
MotionSegment<T> BSplineThrough(const std::vector<T>& control, int degree, const T& duration) {
  MotionSegment<T> seg;
  seg.law = MotionLaw::kBSpline;
  seg.duration = duration;
  seg.spline_degree = degree;
  for (const T& c : control) seg.coefficients.push_back(c - control.front());
  seg.rise = control.back() - control.front();
  return seg;
}


/// The segment's displacement above its start and its derivatives with respect to u (not θ):
/// h N(u), h N'(u), h N''(u), h N'''(u) for a law; P(u) and its derivatives for a polynomial.
template <typename T>
Svaj<T> MotionSegmentShape(const MotionSegment<T>& seg, const T& u) {
  if (seg.law == MotionLaw::kBSpline) return internal::BSplineShape(seg.coefficients, seg.spline_degree, u);
  if (seg.law != MotionLaw::kPolynomial) {
    const Svaj<T> n = NormalizedLaw(seg.law, u);
    return {seg.rise * n.s, seg.rise * n.v, seg.rise * n.a, seg.rise * n.j};
  }
  // Horner's scheme on Q(u) = Σ c_k u^(k−1), carrying Q, Q', Q'', Q'''; then P = u Q.
  Svaj<T> q{T(0.0), T(0.0), T(0.0), T(0.0)};
  for (size_t i = seg.coefficients.size(); i-- > 0;) {
    q.j = q.j * u + T(3.0) * q.a;
    q.a = q.a * u + T(2.0) * q.v;
    q.v = q.v * u + q.s;
    q.s = q.s * u + seg.coefficients[i];
  }
  return {q.s * u, q.s + q.v * u, T(2.0) * q.v + q.a * u, T(3.0) * q.a + q.j * u};
}

/// The follower at one end of a polynomial segment: position S and the θ-derivatives given,
/// derivatives[0] = dS/dθ [unit/rad], [1] = d²S/dθ² [unit/rad²], [2] = d³S/dθ³ [unit/rad³].
template <typename T>
struct BoundaryState {
  T position = T(0.0);
  std::vector<T> derivatives;
};

/// The polynomial segment of duration β [rad] from `start` to `end`: the c_k of the lowest-degree
/// polynomial P(u) with P(0) = 0, P(1) = S_end − S_start, P^(k)(0) = S_start^(k) β^k and
/// P^(k)(1) = S_end^(k) β^k for every derivative given (degree = number of conditions − 1: 3, 5
/// or 7 with the first, second or third derivative at both ends). Gaussian elimination with
/// partial pivoting, the pivots chosen on the value (a Jet gets the derivative of that solution).
/// @pre each end gives 1 to 3 derivatives; duration > 0.
template <typename T>
MotionSegment<T> PolynomialThrough(const BoundaryState<T>& start, const BoundaryState<T>& end,
                                   const T& duration) {
  const size_t m0 = start.derivatives.size(), m1 = end.derivatives.size();
  const size_t n = 1 + m0 + m1;  // unknowns c_1 … c_n
  std::vector<std::vector<T>> a(n, std::vector<T>(n + 1, T(0.0)));
  // d^k/du^k u^i = i (i − 1) … (i − k + 1) u^(i−k): at u = 1 the falling factorial, at u = 0
  // k! for i = k and 0 otherwise.
  auto falling = [](size_t i, size_t k) {
    double f = 1.0;
    for (size_t r = 0; r < k; ++r) f *= double(i) - double(r);
    return f;
  };
  size_t row = 0;
  T bk = T(1.0);
  for (size_t k = 1; k <= m0; ++k, ++row) {
    bk = bk * duration;
    a[row][k - 1] = T(falling(k, k));
    a[row][n] = start.derivatives[k - 1] * bk;
  }
  for (size_t i = 1; i <= n; ++i) a[row][i - 1] = T(1.0);
  a[row][n] = end.position - start.position;
  ++row;
  bk = T(1.0);
  for (size_t k = 1; k <= m1; ++k, ++row) {
    bk = bk * duration;
    for (size_t i = 1; i <= n; ++i) a[row][i - 1] = T(falling(i, k));
    a[row][n] = end.derivatives[k - 1] * bk;
  }
  for (size_t c = 0; c < n; ++c) {
    size_t pivot = c;
    for (size_t r = c + 1; r < n; ++r)
      if (std::abs(Value(a[r][c])) > std::abs(Value(a[pivot][c]))) pivot = r;
    std::swap(a[c], a[pivot]);
    for (size_t r = 0; r < n; ++r) {
      if (r == c) continue;
      const T f = a[r][c] / a[c][c];
      for (size_t k = c; k <= n; ++k) a[r][k] = a[r][k] - f * a[c][k];
    }
  }
  MotionSegment<T> seg;
  seg.law = MotionLaw::kPolynomial;
  seg.duration = duration;
  seg.coefficients.resize(n);
  for (size_t c = 0; c < n; ++c) seg.coefficients[c] = a[c][n] / a[c][c];
  seg.rise = end.position - start.position;
  return seg;
}

template <typename T>
class MotionProgram {
 public:
  MotionProgram() = default;
  explicit MotionProgram(std::vector<MotionSegment<T>> segments) : segments_(std::move(segments)) {}

  const std::vector<MotionSegment<T>>& segments() const { return segments_; }

  /// Cam angle of one cycle: the sum of the durations [rad].
  T Period() const {
    T p(0.0);
    for (const auto& s : segments_) p += s.duration;
    return p;
  }
  /// Net rise over one cycle (0 for a program that returns).
  T NetRise() const {
    T h(0.0);
    for (const auto& s : segments_) h += s.rise;
    return h;
  }

  /// S and its θ-derivatives at cam angle theta [rad]; theta is taken modulo the period, and
  /// for a program with a net rise each further cycle adds the net rise (an indexing motion).
  /// The segment is chosen on the value of θ; segments meet with continuous S, so the
  /// derivative of S with respect to the design is right at the joints.
  Svaj<T> Evaluate(const T& theta) const {
    const T period = Period();
    const double cycles = std::floor(Value(theta) / Value(period));
    T t = theta - T(cycles) * period;
    T start(0.0), s0 = T(cycles) * NetRise();
    for (size_t i = 0; i < segments_.size(); ++i) {
      const MotionSegment<T>& seg = segments_[i];
      const bool last = i + 1 == segments_.size();
      if (last || Value(t) < Value(start + seg.duration)) {
        const T u = (t - start) / seg.duration;
        const Svaj<T> n = MotionSegmentShape(seg, u);
        const T b = seg.duration;
        return {s0 + n.s, n.v / b, n.a / (b * b), n.j / (b * b * b)};
      }
      start += seg.duration;
      s0 += seg.rise;
    }
    return {s0, T(0.0), T(0.0), T(0.0)};
  }

 private:
  std::vector<MotionSegment<T>> segments_;
};

/// Continuity of the program at one joint (the end of segment `segment`, the start of the next;
/// the last joint wraps to the start of the cycle).
struct JointContinuity {
  int segment = 0;
  double cam_angle_rad = 0.0;
  double jump_s = 0.0, jump_v = 0.0, jump_a = 0.0, jump_j = 0.0;  // absolute jumps
  /// Highest derivative order that is continuous: -1 (S jumps), 0, 1, 2 (C²) or 3.
  int order = -1;
};

/// The jumps of S, S', S'', S''' at every joint. A jump counts as continuous when it is below
/// rel_tol times the program's largest magnitude of that derivative (sampled).
std::vector<JointContinuity> CheckContinuity(const MotionProgram<double>& program,
                                             double rel_tol = 1e-9);

/// A problem with a program, naming the segment (-1 for the whole program).
struct ProgramIssue {
  int segment = -1;
  std::string field;  ///< "cam_angle_deg", "rise", or "" for the whole program
  std::string message;
};

/// Checks a program for a cam: at least one segment, positive durations, dwells without rise,
/// moving segments (other than polynomials, which may return to their start) with a non-zero rise, durations summing to `period` (2π for a disc cam)
/// within `angle_tol` [rad], and, when `must_return`, a net rise of zero within `rise_tol`.
std::optional<ProgramIssue> CheckProgram(const MotionProgram<double>& program, double period,
                                         bool must_return, double angle_tol = 1e-9,
                                         double rise_tol = 1e-9);

}  // namespace camopt::motion
