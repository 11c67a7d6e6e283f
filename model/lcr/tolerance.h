// Manufacturing deviations of a built LCR and the normal gap they open (or close) at each roller,
// from the exact geometry: the cams are cut to the nominal pitch curves (docs/papers.md §1), the
// parts that are assembled around them deviate.
//
// At input angle θ the cam's centre is C = (e + Δe) u(θ) + s (s: the eccentric bearing's
// clearance shift), the cam is turned by its nominal φ = (1 − n_A/m_A) θ and the output turret by
// its nominal θ_o = (1 − n_A m_B/(m_A n_B)) θ. A roller of radius r_r + Δr_k sits at
// O_k = (r_d + Δr_d) u(2πk/n + Δβ_k [+ θ_o]). In the cam frame, x_k = R(−φ)(O_k − C), its distance
// from the nominal pitch curve X(ψ) = r_d u(ψ) − e u(kψ) along the outward normal is
// s_k = (x_k − X(ψ*))·n_out(ψ*), ψ* the foot point ((X − x)·X' = 0, Newton from the nominal ψ).
// The cam profile carries a normal offset δ (material added, per cam), so the gap is
//     c_k = s_k − Δr_k − δ          (> 0: clearance, < 0: interference).
// With no deviation every c_k is 0: the conjugate profile touches every roller.
// The closure under the small rotations of the stiffness model (model/rigidity/lcr_stiffness.h)
// is then δ_k = ψ a_k − c_k; tests check that c_k moves by −a_k per radian of the output turret.
#pragma once

#include <cmath>
#include <vector>

#include "model/common/geometry.h"
#include "model/common/profile_deviation.h"
#include "model/common/scalar.h"
#include "model/lcr/contact.h"
#include "model/lcr/kinematics.h"

namespace camopt::lcr {

/// Deviations of one built reducer (one Monte-Carlo sample, or the Jet-seeded zero of the
/// linearisation). Sizes of the per-roller vectors: n_A and n_B (empty = all zero).
template <typename T>
struct Deviations {
  T eccentricity{};                          ///< Δe [mm]
  T turret_radius[2] = {T(0.0), T(0.0)};     ///< Δr_d of the fixed (0) and output (1) turret [mm]
  std::vector<T> roller_radius[2];           ///< Δr_r per roller, half the diameter error [mm]
  std::vector<T> roller_angle[2];            ///< Δβ per roller, angular pitch error [rad]
  T profile[2] = {T(0.0), T(0.0)};           ///< normal offset of cam A / cam B, material added [mm]
  T bearing_clearance{};                     ///< radial clearance of the eccentric bearing [mm]
  /// A normal deviation of cam A / cam B that varies along it, d(ψ) of the pitch-curve parameter ψ
  /// (the profile's, OffsetPoint), material added, evaluated at the roller's foot point ψ* and
  /// added to `profile` (a measured cam, model/common/profile_deviation.h): to first order the
  /// roller's distance to the moved profile falls by d(ψ*) (the envelope theorem). Empty: none.
  camopt::profile::NormalDeviation<T> profile_shape[2];
};

inline int SideIndex(Side s) { return s == Side::kInput ? 0 : 1; }

/// Signed distance [mm] of a cam-frame point x from the pitch curve X(ψ) of a cam (positive away
/// from the cam), with the foot point found by Newton from ψ0 (in double, then one Newton step in
/// T, which carries the exact first derivatives: implicit function theorem). @pre x near X(ψ0).
/// `foot` (nullptr: not asked) receives ψ*.
template <typename T>
T PitchCurveDistance(const CamSide<double>& c, double e, const Vec2<T>& x, double psi0, T* foot = nullptr) {
  const double k = c.pitch_factor(), rd = c.turret_radius;
  auto derivs = [&](const auto& psi, auto& p, auto& d1, auto& d2) {
    using S = std::decay_t<decltype(psi)>;
    p = S(rd) * U(psi) - S(e) * U(S(k) * psi);
    d1 = S(rd) * Perp(U(psi)) - S(e * k) * Perp(U(S(k) * psi));
    d2 = -S(rd) * U(psi) + S(e * k * k) * U(S(k) * psi);
  };
  const Vec2<double> xv(Value(x.x()), Value(x.y()));
  double psi = psi0;
  for (int it = 0; it < 20; ++it) {
    Vec2<double> p, d1, d2;
    derivs(psi, p, d1, d2);
    const double f = (p - xv).dot(d1), fp = d1.dot(d1) + (p - xv).dot(d2);
    const double step = f / fp;
    psi -= step;
    if (std::abs(step) < 1e-15) break;
  }
  T psi_t(psi);
  Vec2<T> p, d1, d2;
  derivs(psi_t, p, d1, d2);
  psi_t = psi_t - (p - x).dot(d1) / (d1.dot(d1) + (p - x).dot(d2));
  derivs(psi_t, p, d1, d2);
  if (foot) *foot = psi_t;
  // Outward normal: the pitch curve runs counter-clockwise around the cam, so −J X'/|X'| points
  // away from the cam (−InwardNormal of profile.h).
  const Vec2<T> n_out = Vec2<T>(d1.y(), -d1.x()) / d1.norm();
  return (x - p).dot(n_out);
}

/// The cam centre's shift by the eccentric bearing's clearance c at angle θ: the cam is pushed by
/// its load G (the force it puts on the eccentric, paper law, forward torque) until the bore
/// meets the journal, s = ±c·G/|G| (− for the reversed torque). `load_direction` is G/|G|.
template <typename T>
Vec2<T> BearingShift(const T& clearance, const Vec2<double>& load_direction, double sense) {
  return T(sense) * clearance * load_direction.template cast<T>();
}

/// Normal gaps c_k [mm] of every roller of one turret at input angle θ [rad] (see the file comment).
template <typename T>
std::vector<T> RollerGaps(const Reducer<double>& r, Side s, const Deviations<T>& dev, double theta,
                          const Vec2<T>& bearing_shift) {
  const int i = SideIndex(s);
  const CamSide<double>& c = r.side(s);
  const double phi = CamSpeedRatio(r) * theta;
  const double turn = s == Side::kInput ? 0.0 : OutputSpeedRatio(r) * theta;
  const Vec2<T> centre = (T(r.eccentricity) + dev.eccentricity) * U(T(theta)) + bearing_shift;
  const T radius = T(c.turret_radius) + dev.turret_radius[i];
  const Vec2<double> back = U(-phi);  // rotation by −φ
  std::vector<T> gaps(c.rollers);
  for (int k = 0; k < c.rollers; ++k) {
    const double slot = 2.0 * kPi * k / c.rollers;
    const T beta = dev.roller_angle[i].empty() ? T(0.0) : dev.roller_angle[i][k];
    const Vec2<T> o = radius * U(T(slot + turn) + beta) - centre;
    const Vec2<T> x(T(back.x()) * o.x() - T(back.y()) * o.y(), T(back.y()) * o.x() + T(back.x()) * o.y());
    const T dr = dev.roller_radius[i].empty() ? T(0.0) : dev.roller_radius[i][k];
    T foot(0.0);
    gaps[k] = PitchCurveDistance(c, r.eccentricity, x, slot + turn - phi, &foot) - dr - dev.profile[i];
    if (dev.profile_shape[i]) gaps[k] -= dev.profile_shape[i](foot, nullptr);
  }
  return gaps;
}

}  // namespace camopt::lcr
