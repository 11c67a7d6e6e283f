// The translating follower of follower_dynamics.h held on the cam (no separation), integrated on a
// fixed grid by the classical fourth-order Runge-Kutta scheme, over any scalar type: with
// ceres::Jet control values of the motion program this is the forward sensitivity of the response
// (the sensitivity equations of the linear ODE integrated by the same RK4 steps, by forward-mode
// automatic differentiation), so a design objective built on it has the exact derivative of its
// own discretisation. The fine, independent answer is follower_dynamics.h's CVODE run with
// contact events; this one is the optimizer's fast model (objectives/disc_cam_motion.h).
//
// In contact (Norton, Cam Design and Manufacturing Handbook, ch. 10, single-DOF lumped model), with
// the deflection u = x − S and its rate w = ẋ − Ṡ as in follower_dynamics.cc:
//   u̇ = w,   ẇ = (F_a − k_s (u + S) − F₀ − P − W)/m − S_θθ ω²,   F_a = −k_f u − c w,
// c = 2ζ √(m (k_f + k_s)), from static equilibrium on the cam at θ = 0 (w = 0), `revolutions`
// turns. The grid puts a step boundary on every joint of the program (a law's acceleration may
// jump there) and evaluates each segment on its own side of a joint, so the scheme keeps its order.
//
// After a rise that ends in a dwell (S constant, Ṡ = 0) the motion is free: e = x − x_s with
// x_s = (k_f S − F₀ − P − W)/(k_f + k_s), and
//   e(τ) = e^{−ζω_n τ} (e₀ cos ω_d τ + (ė₀ + ζω_n e₀)/ω_d sin ω_d τ),
// so the residual vibration's amplitude is A = √(e₀² + ((ė₀ + ζω_n e₀)/ω_d)²), ω_n = √((k_f + k_s)/m),
// ω_d = ω_n √(1 − ζ²) (Thomson, Theory of Vibration with Applications, §2.6, the free damped
// response): |e| ≤ A throughout the dwell, with equality at its first peak when ζ = 0.
// Units: mm, N, kg, s, rad.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "model/disc_cam/kinetostatics.h"
#include "model/motion/motion_program.h"

namespace camopt::disc_cam {

/// The follower train in contact: the loads of kinetostatics.h with the follower stiffness and
/// damping ratio of follower_dynamics.h.
struct ContactFollower {
  FollowerLoads loads;
  double follower_stiffness_N_per_mm = 0.0;  ///< k_f > 0
  double damping_ratio = 0.0;                ///< ζ in [0, 1)
  double NaturalFrequencyRadS() const {
    return std::sqrt((follower_stiffness_N_per_mm + loads.spring_rate_N_per_mm) / (loads.mass_kg * 1e-3));
  }
  double Hold() const { return loads.spring_preload_N + loads.external_load_N + loads.weight_N; }
};

/// One revolution's step boundaries: every joint of the program, and each segment cut into equal
/// steps of at most 2π/min_steps.
struct ContactGrid {
  std::vector<double> theta;  ///< boundaries, theta[0] = 0 … theta.back() = the period [rad]
  std::vector<int> segment;   ///< the segment of step k (theta[k], theta[k+1])
  std::vector<double> u0, u1; ///< its local parameter at both ends
};

inline ContactGrid MakeContactGrid(const std::vector<double>& durations, int min_steps) {
  if (min_steps < 1) throw std::invalid_argument("contact grid: min_steps");
  double period = 0;
  for (double d : durations) period += d;
  ContactGrid g;
  g.theta.push_back(0.0);
  double start = 0;
  for (size_t s = 0; s < durations.size(); ++s) {
    const int n = std::max(1, int(std::ceil(durations[s] / period * min_steps - 1e-9)));
    for (int k = 0; k < n; ++k) {
      g.segment.push_back(int(s));
      g.u0.push_back(double(k) / n);
      g.u1.push_back(double(k + 1) / n);
      g.theta.push_back(k + 1 == n ? start + durations[s] : start + durations[s] * (k + 1) / n);
    }
    start += durations[s];
  }
  return g;
}

/// The response of the last revolution at every step boundary k = 0 … steps (θ_k of the grid).
template <typename T>
struct ContactResponse {
  std::vector<T> s, u, w;  ///< S [mm], u = x − S [mm], w = ẋ − Ṡ [mm/s]
  std::vector<T> axial;    ///< F_a = −k_f u − c w [N] (negative: the cam would have to pull)
};

/// Integrates the follower held on the cam over `revolutions` turns at ω [rad/s] on `grid`.
/// @pre grid made from the program's durations; revolutions >= 1, ω > 0.
template <typename T>
ContactResponse<T> IntegrateInContact(const motion::MotionProgram<T>& program, const ContactFollower& f,
                                      double omega, int revolutions, const ContactGrid& grid) {
  const auto& segs = program.segments();
  const double m = f.loads.mass_kg * 1e-3, kf = f.follower_stiffness_N_per_mm, ks = f.loads.spring_rate_N_per_mm;
  const double c = 2 * f.damping_ratio * std::sqrt(m * (kf + ks)), hold = f.Hold();
  // Each segment's start value S₀ (the program's net rise over a cycle is 0 for a disc cam).
  std::vector<T> s0(segs.size(), T(0.0));
  for (size_t i = 1; i < segs.size(); ++i) s0[i] = s0[i - 1] + segs[i - 1].rise;
  const size_t steps = grid.segment.size();
  // S and S_θθ at the three stage points of every step, on the step's own segment.
  std::vector<T> sa(3 * steps), aa(3 * steps);
  for (size_t k = 0; k < steps; ++k) {
    const auto& seg = segs[size_t(grid.segment[k])];
    const T b = seg.duration;
    const double us[3] = {grid.u0[k], 0.5 * (grid.u0[k] + grid.u1[k]), grid.u1[k]};
    for (int j = 0; j < 3; ++j) {
      const motion::Svaj<T> n = motion::MotionSegmentShape(seg, T(us[j]));
      sa[3 * k + size_t(j)] = s0[size_t(grid.segment[k])] + n.s;
      aa[3 * k + size_t(j)] = n.a / (b * b);
    }
  }
  const T w2(omega * omega);
  auto rhs = [&](const T& u, const T& w, const T& s, const T& a, T& du, T& dw) {
    du = w;
    dw = (T(-kf) * u - T(c) * w - T(ks) * (u + s) - T(hold)) / T(m) - a * w2;
  };
  T u = (T(kf) * sa[0] - T(hold)) / T(kf + ks) - sa[0], w(0.0);
  ContactResponse<T> out;
  auto record = [&](const T& s) {
    out.s.push_back(s);
    out.u.push_back(u);
    out.w.push_back(w);
    out.axial.push_back(T(-kf) * u - T(c) * w);
  };
  for (int r = 0; r < revolutions; ++r) {
    const bool last = r + 1 == revolutions;
    if (last) record(sa[0]);
    for (size_t k = 0; k < steps; ++k) {
      const double h = (grid.theta[k + 1] - grid.theta[k]) / omega;
      const T* s = &sa[3 * k];
      const T* a = &aa[3 * k];
      T k1u, k1w, k2u, k2w, k3u, k3w, k4u, k4w;
      rhs(u, w, s[0], a[0], k1u, k1w);
      rhs(u + T(h / 2) * k1u, w + T(h / 2) * k1w, s[1], a[1], k2u, k2w);
      rhs(u + T(h / 2) * k2u, w + T(h / 2) * k2w, s[1], a[1], k3u, k3w);
      rhs(u + T(h) * k3u, w + T(h) * k3w, s[2], a[2], k4u, k4w);
      u = u + T(h / 6) * (k1u + T(2.0) * k2u + T(2.0) * k3u + k4u);
      w = w + T(h / 6) * (k1w + T(2.0) * k2w + T(2.0) * k3w + k4w);
      if (last) record(s[2]);
    }
  }
  return out;
}

/// The residual vibration's amplitude A² [mm²] (see above) of a free follower on a dwell at
/// height S with the state (u, w) at the dwell's start.
template <typename T>
T ResidualAmplitudeSquared(const ContactFollower& f, const T& s, const T& u, const T& w) {
  const double kf = f.follower_stiffness_N_per_mm, ks = f.loads.spring_rate_N_per_mm;
  const double wn = f.NaturalFrequencyRadS(), z = f.damping_ratio, wd = wn * std::sqrt(1 - z * z);
  const T e = u + s - (T(kf) * s - T(f.Hold())) / T(kf + ks);
  const T v = (w + T(z * wn) * e) / T(wd);
  return e * e + v * v;
}

}  // namespace camopt::disc_cam
