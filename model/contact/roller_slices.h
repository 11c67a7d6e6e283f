// Finite-length roller contact by slices coupled through the elastic half-space (the `slices`
// fidelity of the LCR contact, docs/lcr.md "Crowned rollers and 3D contact").
//
// The contact of length l (the overlap of roller and cam) is cut into N slices of width w = l/N
// along the roller axis y. Slice j carries a line load q_j [N/mm] spread across rolling (x) as a
// semi-elliptic Hertz strip p_j(x) = p0_j sqrt(1 − x²/b_j²) of its own line-contact half-width
// b_j = sqrt(4 q_j R'/(π E*)) (model/contact/hertz.h), so p0_j = 2 q_j/(π b_j) = sqrt(q_j E*/(π R')).
// Slices are coupled through the half-space (Boussinesq, both bodies: u = (1/(π E*)) ∫ p/ρ dA):
// the surface approach on the centre line of slice i is u_i = Σ_j C_ij(b_j) q_j with
//     C_ij = (4/(π² E*)) ∫₀¹ sqrt(1 − t²) [asinh(η₂/(b_j t)) − asinh(η₁/(b_j t))] dt,
// η₁,₂ = y_j ∓ w/2 − y_i (the y integral of 1/ρ over the slice in closed form, x = b_j t). The
// logarithmic parts are integrated in closed form (∫₀¹ sqrt(1 − t²) ln t dt = −(π/8)(1 + 2 ln 2)),
// the smooth remainder ∫₀¹ sqrt(1 − t²) ln(1 + sqrt(1 + (b t/η)²)) dt by Gauss–Legendre in
// t = sin φ (split at b t = |η|), or by its series in (b/η)² where b/|η| < 0.15 (error < 1e-7 of C).
// Contact conditions: u_i = δ − h_i where q_i > 0, u_i ≥ δ − h_i where q_i = 0, q ≥ 0,
// w Σ q_j = F (h the gap along y: crowning + misalignment). Solved in double by an active-set
// method on the (dense, N × N) system with the half-widths updated to the loads, then Newton steps
// on the contact set (exact Jacobian) until the loads stop changing; the result is checked against
// the equations. The half-widths use q_j + 1e-6 F/l
// so that C stays finite for an unloaded slice (its effect on the pressures is below 1e-6).
//
// Derivatives (T = ceres::Jet): one Newton step of the compatibility equations at the solution
// with the contact set frozen (implicit-function theorem): x = x₀ − J⁻¹ R(x₀, p),
// J the exact Jacobian in (q_C, δ) including the half-widths' dependence on q. Exact away from a
// change of the contact set (a kink, like any max).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <ceres/jet.h>

#include "model/common/scalar.h"
#include "model/contact/hertz.h"

namespace camopt::contact {

struct SliceOptions {
  int slices = 40;            // N
  int max_iterations = 100;   // half-width updates
  double tolerance = 1e-10;   // relative change of the line loads between updates
};

template <typename T>
struct SliceSolution {
  std::vector<T> y_mm;               // slice centres, from the contact's mid-length
  std::vector<T> line_load_N_per_mm; // q_j
  std::vector<T> pressure_MPa;       // p0_j, the peak of slice j's strip
  std::vector<double> half_width_mm; // b_j (values)
  T peak_pressure{};                 // max_j p0_j [MPa]
  T approach{};                      // δ [mm]
  T slice_width{};                   // w [mm] (the resolution of an edge peak)
  int peak_slice = -1;
  int slices_in_contact = 0;
  bool edge_loaded = false;          // an end slice carries load
  int iterations = 0;
  bool converged = false;
  double residual = 0;               // max |u_i − δ + h_i| over loaded slices / max |δ − h_i|
};

namespace slices_detail {

/// Gauss–Legendre nodes and weights on [−1, 1] (Newton on P_n).
struct Gauss {
  std::vector<double> x, w;
  explicit Gauss(int n) : x(n), w(n) {
    for (int i = 0; i < n; ++i) {
      double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1, p1 = 0;
        for (int k = 1; k <= n; ++k) {
          const double p2 = p1;
          p1 = p0;
          p0 = ((2.0 * k - 1) * z * p1 - (k - 1.0) * p2) / k;
        }
        dp = n * (z * p0 - p1) / (z * z - 1);
        const double dz = p0 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-15) break;
      }
      x[i] = z;
      w[i] = 2 / ((1 - z * z) * dp * dp);
    }
  }
};

inline const Gauss& Rule() {
  static const Gauss g(12);
  return g;
}

/// cos φ_i and sin φ_i at the rule's nodes mapped to [0, π/2] (the whole range of SmoothIntegral
/// for k <= 1): the same φ_i = π/4 + (π/4) x_i and the same library calls as a run-time evaluation,
/// so the values are the same bits, computed once.
struct QuarterNodes {
  std::vector<double> c, s;
  QuarterNodes() {
    const Gauss& g = Rule();
    const double half = 0.5 * (kPi / 2 - 0.0), mid = 0.5 * (kPi / 2 + 0.0);
    for (double x : g.x) {
      const double phi = mid + half * x;
      c.push_back(std::cos(phi));
      s.push_back(std::sin(phi));
    }
  }
};
inline const QuarterNodes& Quarter() {
  static const QuarterNodes q;
  return q;
}

/// ∫₀¹ sqrt(1 − t²) ln(1 + sqrt(1 + (k t)²)) dt, k = b/|η| > 0.
template <typename S>
S SmoothIntegral(const S& k) {
  using std::asin;
  using std::cos;
  using std::log;
  using std::sin;
  using std::sqrt;
  if (Value(k) < 0.15) {  // ln 2 + ε²/4 − 3ε⁴/32 with the moments π/4, π/16, π/32 of t⁰, t², t⁴
    const S k2 = k * k;
    return S(kPi / 4 * std::log(2.0)) + S(kPi / 64) * k2 - S(3 * kPi / 1024) * k2 * k2;
  }
  const Gauss& g = Rule();
  const auto segment = [&](const S& a, const S& b) {  // ∫_a^b cos²φ f(sin φ) dφ
    S sum(0.0);
    const S half = S(0.5) * (b - a), mid = S(0.5) * (b + a);
    for (size_t i = 0; i < g.x.size(); ++i) {
      const S phi = mid + half * S(g.x[i]);
      const S c = cos(phi), kt = k * sin(phi);
      sum += S(g.w[i]) * c * c * log(S(1.0) + sqrt(S(1.0) + kt * kt));
    }
    return half * sum;
  };
  if (Value(k) <= 1.0) {  // segment(0, π/2) with the nodes' cos and sin from the table
    const QuarterNodes& q = Quarter();
    S sum(0.0);
    for (size_t i = 0; i < g.x.size(); ++i) {
      const S c(q.c[i]), kt = k * S(q.s[i]);
      sum += S(g.w[i]) * c * c * log(S(1.0) + sqrt(S(1.0) + kt * kt));
    }
    return S(0.5 * (kPi / 2 - 0.0)) * sum;
  }
  const S split = asin(S(1.0) / k);
  return segment(S(0.0), split) + segment(split, S(kPi / 2));
}

/// (π/4) ln((d + w/2)/(d − w/2)), d = |offset|: the term of Influence for another slice that does
/// not depend on the half-width b (the slice geometry's alone), 0 for the slice itself.
template <typename S>
S FarLog(const S& offset, const S& width) {
  using std::abs;
  using std::log;
  const S d = abs(offset);
  if (Value(d) < 0.5 * Value(width)) return S(0.0);
  const S near = d - S(0.5) * width, far = d + S(0.5) * width;
  return S(kPi / 4) * log(far / near);
}

/// 4 / (π² E*): the factor of every influence coefficient.
inline double InfluenceScale(double e_star) { return 4.0 / (kPi * kPi * e_star); }

/// A slice's influence on itself, 2[(π/4) ln(w/(2b)) + (π/8)(1 + 2 ln 2) + J(w/2)] times the scale,
/// from half = w/2 and smooth = SmoothIntegral(b / half).
template <typename S>
S SelfInfluence(const S& half, const S& b, double scale, const S& smooth) {
  using std::log;
  return S(2.0 * scale) * (S(kPi / 4) * log(half / b) + S(kPi / 8 * (1 + 2 * std::log(2.0))) + smooth);
}

/// The SmoothIntegral terms of one loaded slice's column of influence coefficients on slices of
/// equal width w: edge[m] = SmoothIntegral(b / ((m + ½) w)), m = 0 … count − 1. The slice m away
/// has its near edge at (m − ½) w and its far edge at (m + ½) w, so its near term is the far term
/// of the slice m − 1 away: one quadrature per distance instead of two per slice (the self term's
/// is edge[0]).
template <typename S>
void EdgeIntegrals(const S& b, double w, int count, std::vector<S>& edge) {
  edge.resize(size_t(count));
  for (int m = 0; m < count; ++m) edge[size_t(m)] = SmoothIntegral(S(b / S((m + 0.5) * w)));
}

/// Influence of a slice of width w and half-width b on the slice m = |i − j| slices away, from
/// its column's EdgeIntegrals and FarLog (Influence's formula with d = m w).
template <typename S>
S InfluenceFromEdges(int m, double w, const S& b, double e_star, const S& far_log, const std::vector<S>& edge) {
  const double scale = InfluenceScale(e_star);
  if (m == 0) return SelfInfluence(S(0.5 * w), b, scale, edge[0]);
  return S(scale) * (far_log + edge[size_t(m)] - edge[size_t(m - 1)]);
}

/// Influence with its FarLog term given (FarLog of the same offset and width): the same
/// arithmetic, so the same number; the solver's fills of one solve share the term.
template <typename S>
S InfluenceWithFarLog(const S& offset, const S& width, const S& b, double e_star, const S& far_log) {
  using std::abs;
  const double scale = InfluenceScale(e_star);
  const S d = abs(offset);
  if (Value(d) < 0.5 * Value(width)) {  // self
    const S half = S(0.5) * width;
    return SelfInfluence(half, b, scale, SmoothIntegral(S(b / half)));
  }
  const S near = d - S(0.5) * width, far = d + S(0.5) * width;
  return S(scale) * (far_log + SmoothIntegral(S(b / far)) - SmoothIntegral(S(b / near)));
}

/// C_ij [mm per N/mm]: approach on the centre line of a slice at offset d = y_i − y_j from a unit
/// line load on a slice of width w with half-width b. `self` for i = j.
template <typename S>
S Influence(const S& offset, const S& width, const S& b, double e_star) {
  return InfluenceWithFarLog(offset, width, b, e_star, FarLog(offset, width));
}

/// b(q) with the floor q_floor (see the header comment).
template <typename S>
S HalfWidth(const S& q, const S& q_floor, const S& r_eff, double e_star) {
  using std::sqrt;
  return sqrt(S(4.0) * (q + q_floor) * r_eff / S(kPi * e_star));
}

/// Influence over a Jet with many derivative parts: Influence on a Jet of the three arguments
/// (offset, width, b), then the chain rule to the parts of T. The value is the same number (a
/// Jet's value arithmetic does not depend on its size); the derivatives are the same up to
/// rounding, at a fraction of the cost of the quadrature over the long Jet.
template <typename T>
T InfluenceByChainRule(const T& offset, const T& width, const T& b, double e_star) {
  if constexpr (std::is_same_v<T, double>) {
    return Influence(offset, width, b, e_star);
  } else {
    using J3 = ceres::Jet<double, 3>;
    const J3 c = Influence(J3(offset.a, 0), J3(width.a, 1), J3(b.a, 2), e_star);
    T out(c.a);
    out.v = c.v[0] * offset.v + c.v[1] * width.v + c.v[2] * b.v;
    return out;
  }
}

inline void ApplyInverse(const Eigen::PartialPivLU<Eigen::MatrixXd>&, std::vector<double>&) {}

/// r ← J⁻¹ r for the derivative parts only (the value of r is the residual at a converged
/// solution: it is kept out so that the values stay those of the double solve).
template <int N>
void ApplyInverse(const Eigen::PartialPivLU<Eigen::MatrixXd>& lu, std::vector<ceres::Jet<double, N>>& r) {
  const int n = int(r.size());
  Eigen::MatrixXd rhs(n, N);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < N; ++k) rhs(i, k) = r[i].v[k];
  const Eigen::MatrixXd x = lu.solve(rhs);
  for (int i = 0; i < n; ++i) {
    r[i].a = 0.0;
    for (int k = 0; k < N; ++k) r[i].v[k] = x(i, k);
  }
}

}  // namespace slices_detail

/// Solves the sliced finite-length contact for total force F [N], effective radius across rolling
/// R' [mm], contact length l [mm], composite modulus E* [MPa] and gap h(y) [mm] (y from the
/// contact's mid-length, |y| < l/2): `gap` is called with T and returns T. F <= 0 gives no load.
/// @throws std::invalid_argument for N < 1, R' <= 0, l <= 0, E* <= 0 or a non-finite gap.
template <typename T, typename Gap>
SliceSolution<T> SolveRollerSlices(const T& force, const T& r_eff, const T& length, double e_star,
                                   const Gap& gap, const SliceOptions& options = {}) {
  using slices_detail::HalfWidth;
  const int n = options.slices;
  if (n < 1 || !(Value(r_eff) > 0) || !(Value(length) > 0) || !(e_star > 0))
    throw std::invalid_argument("roller slices: need slices >= 1, R' > 0, length > 0, E* > 0");
  SliceSolution<T> out;
  out.slice_width = length / T(double(n));
  out.y_mm.resize(n);
  std::vector<T> h(n);
  std::vector<double> y(n), hd(n);
  const double w = Value(out.slice_width);
  for (int j = 0; j < n; ++j) {
    out.y_mm[j] = (T(j + 0.5) - T(0.5 * n)) * out.slice_width;
    y[j] = Value(out.y_mm[j]);
    h[j] = gap(out.y_mm[j]);
    hd[j] = Value(h[j]);
    if (!std::isfinite(hd[j])) throw std::invalid_argument("roller slices: non-finite gap");
  }
  out.line_load_N_per_mm.assign(n, T(0.0));
  out.pressure_MPa.assign(n, T(0.0));
  out.half_width_mm.assign(n, 0.0);
  const double f = Value(force), rp = Value(r_eff);
  if (!(f > 0)) {
    out.converged = true;
    out.peak_pressure = T(0.0);
    out.approach = T(*std::min_element(hd.begin(), hd.end()));
    return out;
  }
  const double q_ref = f / Value(length), q_floor = 1e-6 * q_ref;

  // Double solve: active set inside, half-width updates outside.
  std::vector<double> q(n, q_ref), b(n);
  std::vector<char> active(n, 1);
  double delta = 0;
  Eigen::MatrixXd c(n, n);
  // The influence coefficients' b-free terms (slice geometry only), computed once for the solve's
  // fills and Newton Jacobians (in each scalar type's own arithmetic, so the same numbers).
  using J1 = ceres::Jet<double, 1>;
  Eigen::MatrixXd far_log(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) far_log(i, j) = slices_detail::FarLog(y[i] - y[j], w);
  std::vector<J1> far_log1;  // on the first Jacobian
  // Slice j's column from its edge terms (slices_detail::EdgeIntegrals): slice i is |i − j| away.
  std::vector<double> edge;
  const auto fill = [&] {
    for (int j = 0; j < n; ++j) b[j] = HalfWidth(q[j], q_floor, rp, e_star);
    for (int j = 0; j < n; ++j) {
      slices_detail::EdgeIntegrals(b[j], w, std::max(j, n - 1 - j) + 1, edge);
      for (int i = 0; i < n; ++i)
        c(i, j) = slices_detail::InfluenceFromEdges(std::abs(i - j), w, b[j], e_star, far_log(i, j), edge);
    }
  };
  const auto solve_active_set = [&] {
    for (int pass = 0; pass < 4 * n + 10; ++pass) {
      std::vector<int> a;
      for (int i = 0; i < n; ++i)
        if (active[i]) a.push_back(i);
      const int m = int(a.size());
      Eigen::MatrixXd k(m + 1, m + 1);
      Eigen::VectorXd rhs(m + 1);
      for (int r = 0; r < m; ++r) {
        for (int s = 0; s < m; ++s) k(r, s) = c(a[r], a[s]);
        k(r, m) = -1.0;
        k(m, r) = w;
        rhs(r) = -hd[a[r]];
      }
      k(m, m) = 0.0;
      rhs(m) = f;
      const Eigen::VectorXd x = k.partialPivLu().solve(rhs);
      std::fill(q.begin(), q.end(), 0.0);
      for (int r = 0; r < m; ++r) q[a[r]] = x(r);
      delta = x(m);
      // Drop negative loads (all of them in the first passes, then the most negative only, which
      // cannot cycle), else add the most penetrating free slice.
      int worst = -1;
      double worst_q = 0;
      for (int r = 0; r < m; ++r) {
        if (x(r) < worst_q) worst_q = x(r), worst = a[r];
        if (pass < 4 && x(r) < 0 && m > 1) active[a[r]] = 0;
      }
      if (worst >= 0) {
        active[worst] = 0;
        continue;
      }
      double scale = 0;
      for (int i = 0; i < n; ++i) scale = std::max(scale, std::abs(delta - hd[i]));
      int add = -1;
      double most = 1e-12 * scale;
      for (int i = 0; i < n; ++i) {
        if (active[i]) continue;
        double u = 0;
        for (int j = 0; j < n; ++j) u += c(i, j) * q[j];
        const double pen = delta - hd[i] - u;  // > 0: the bodies overlap at a free slice
        if (pen > most) most = pen, add = i;
      }
      if (add < 0) return true;
      active[add] = 1;
    }
    return false;
  };
  // Newton step on the current contact set with the exact Jacobian (half-widths included);
  // false when it leaves the set's conditions (then the active-set solve takes over).
  const auto jacobian = [&](const std::vector<int>& a) {
    const int m = int(a.size());
    Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(m + 1, m + 1);
    if (far_log1.empty()) {
      far_log1.resize(size_t(n) * n);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) far_log1[size_t(i) * n + j] = slices_detail::FarLog(J1(y[i] - y[j]), J1(w));
    }
    std::vector<J1> edge1;
    for (int s = 0; s < m; ++s) {
      const int j = a[s];
      const double dbdq = 2.0 * rp / (kPi * e_star * b[j]);
      const J1 bj(b[j], 0);
      slices_detail::EdgeIntegrals(bj, w, std::max(j - a.front(), a.back() - j) + 1, edge1);
      for (int r = 0; r < m; ++r) {
        const J1 cj = slices_detail::InfluenceFromEdges(std::abs(a[r] - j), w, bj, e_star,
                                                        far_log1[size_t(a[r]) * n + j], edge1);
        jac(r, s) = cj.a + q[j] * cj.v[0] * dbdq;
      }
      jac(m, s) = w;
    }
    for (int r = 0; r < m; ++r) jac(r, m) = -1.0;
    return jac;
  };
  const auto newton = [&] {
    std::vector<int> a;
    for (int i = 0; i < n; ++i)
      if (active[i]) a.push_back(i);
    const int m = int(a.size());
    Eigen::VectorXd res(m + 1);
    for (int r = 0; r < m; ++r) {
      double u = 0;
      for (int s = 0; s < m; ++s) u += c(a[r], a[s]) * q[a[s]];
      res(r) = u - delta + hd[a[r]];
    }
    double total = 0;
    for (int s = 0; s < m; ++s) total += q[a[s]];
    res(m) = w * total - f;
    const Eigen::VectorXd dx = jacobian(a).partialPivLu().solve(-res);
    for (int s = 0; s < m; ++s)
      if (!(q[a[s]] + dx(s) > 0)) return false;
    for (int s = 0; s < m; ++s) q[a[s]] += dx(s);
    delta += dx(m);
    double scale = 0;
    for (int i = 0; i < n; ++i) scale = std::max(scale, std::abs(delta - hd[i]));
    for (int i = 0; i < n; ++i) {  // a free slice that the bodies overlap: the set must change
      if (active[i]) continue;
      double u = 0;
      for (int j = 0; j < n; ++j) u += c(i, j) * q[j];
      if (delta - hd[i] - u > 1e-12 * scale) return false;
    }
    return true;
  };
  bool set_ok = true;
  for (out.iterations = 1; out.iterations <= options.max_iterations; ++out.iterations) {
    const std::vector<double> previous = q;
    fill();
    set_ok = out.iterations > 2 && newton() ? true : solve_active_set();
    double change = 0, top = 0;
    for (int j = 0; j < n; ++j) change = std::max(change, std::abs(q[j] - previous[j])), top = std::max(top, q[j]);
    if (set_ok && change <= options.tolerance * top) {
      out.converged = true;
      break;
    }
  }
  out.iterations = std::min(out.iterations, options.max_iterations);
  fill();  // the coefficients of the final loads: the equations are checked with them
  {
    double scale = 0, res = 0;
    for (int i = 0; i < n; ++i) scale = std::max(scale, std::abs(delta - hd[i]));
    for (int i = 0; i < n; ++i) {
      if (!(q[i] > 0)) continue;
      double u = 0;
      for (int j = 0; j < n; ++j) u += c(i, j) * q[j];
      res = std::max(res, std::abs(u - delta + hd[i]));
    }
    out.residual = scale > 0 ? res / scale : res;
  }

  // Implicit-function step over T on the frozen contact set.
  std::vector<int> a;
  for (int i = 0; i < n; ++i)
    if (q[i] > 0) a.push_back(i);
  const int m = int(a.size());
  std::vector<T> qt(n, T(0.0));
  T delta_t(delta);
  if constexpr (!std::is_same_v<T, double>) {
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(jacobian(a));
    std::vector<T> res(m + 1, T(0.0));
    std::vector<T> bt(n);
    for (int s = 0; s < m; ++s) bt[a[s]] = HalfWidth(T(q[a[s]]), T(q_floor), r_eff, e_star);
    for (int r = 0; r < m; ++r) {
      T u(0.0);
      for (int s = 0; s < m; ++s)
        u += slices_detail::InfluenceByChainRule(T(out.y_mm[a[r]] - out.y_mm[a[s]]), out.slice_width, bt[a[s]], e_star) *
             T(q[a[s]]);
      res[r] = u - T(delta) + h[a[r]];
    }
    T total(0.0);
    for (int s = 0; s < m; ++s) total += T(q[a[s]]);
    res[m] = out.slice_width * total - force;
    slices_detail::ApplyInverse(lu, res);
    for (int s = 0; s < m; ++s) qt[a[s]] = T(q[a[s]]) - res[s];
    delta_t = T(delta) - res[m];
  } else {
    for (int j = 0; j < n; ++j) qt[j] = q[j];
  }

  out.approach = delta_t;
  out.peak_pressure = T(0.0);
  double peak = -1;
  for (int j = 0; j < n; ++j) {
    out.line_load_N_per_mm[j] = qt[j];
    out.half_width_mm[j] = q[j] > 0 ? b[j] : 0.0;
    if (q[j] > 0) {
      using std::sqrt;
      out.pressure_MPa[j] = sqrt(qt[j] * T(e_star) / (T(kPi) * r_eff));
      ++out.slices_in_contact;
    }
    if (Value(out.pressure_MPa[j]) > peak) peak = Value(out.pressure_MPa[j]), out.peak_slice = j;
  }
  out.peak_pressure = out.pressure_MPa[out.peak_slice];
  out.edge_loaded = q[0] > 1e-9 * q_ref || q[n - 1] > 1e-9 * q_ref;
  if (!set_ok) out.converged = false;
  return out;
}

}  // namespace camopt::contact
