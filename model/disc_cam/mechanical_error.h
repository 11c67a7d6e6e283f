// Mechanical error of the follower motion caused by tolerances: Rzine et al. (docs/papers.md §2),
// eqs. (16)–(32), by the equivalent linkage and the small-displacement diagram. To first order:
//   normal profile error Δn:      ΔS_n  = Δn / cos φ               (translating, eq. 17)
//                                 ΔS_n  = Δn / (l cos φ)           (oscillating, eq. 22)
//   roller radius error Δr_f:     ΔS_rf = Δr_f / cos φ  or Δr_f /(l cos φ)   (eqs. 19, 25)
//   radial dimension error Δr:    ΔS_r  = Δr cos λ / cos φ  or /(l cos φ)   (eqs. 26, 29, 30)
//   worst case  ΔS_wor = Σ |ΔS_k|  (eq. 31),   root mean square  ΔS_rms = sqrt(Σ ΔS_k²)  (eq. 32).
// ΔS is in mm for a translating follower, in rad for an oscillating one.
#pragma once

#include <cmath>

#include "model/disc_cam/disc_cam.h"

namespace camopt::disc_cam {

/// Deviations (or tolerances) of the manufactured cam and roller [mm].
template <typename T>
struct Deviations {
  T normal = T(0.0);  ///< Δn: profile error along the normal (material added > 0)
  T radial = T(0.0);  ///< Δr: error of the radial dimension O₂A (eq. 26)
  T roller = T(0.0);  ///< Δr_f: roller radius error
};

/// The follower errors at one cam angle.
template <typename T>
struct MechanicalError {
  T normal, radial, roller;  ///< ΔS_n, ΔS_r, ΔS_rf (mm or rad)
  T worst_case;              ///< eq. (31), with |ΔS_n| added when a normal tolerance is given
  T rms;                     ///< eq. (32), likewise
};

/// ΔS per unit normal profile error, 1/cos φ or 1/(l cos φ) (eqs. 17, 22); also per unit roller
/// radius error (eqs. 19, 25).
template <typename T>
T NormalErrorGain(const DiscCamTpl<T>& cam, const CamPoint<T>& p) {
  using std::cos;
  const T c = cos(p.pressure_angle);
  return cam.follower == FollowerType::kTranslatingRoller ? T(1.0) / c
                                                          : T(1.0) / (cam.arm_length * c);
}

/// cos λ / cos φ: the follower error per unit radial-dimension error of a translating follower
/// (eq. 29; an oscillating follower's adds the factor 1/l, eq. 30).
template <typename T>
T RadialErrorRatio(const CamPoint<T>& p) {
  using std::cos;
  return cos(p.shift_angle) / cos(p.pressure_angle);
}

/// Displacement of the roller centre per unit follower error: 1 for a translating follower (mm
/// per mm), the arm length l for an oscillating one (mm per rad: the roller centre moves l·Δξ).
template <typename T>
T RollerCentreMmPerFollowerUnit(const DiscCamTpl<T>& cam) {
  return cam.follower == FollowerType::kTranslatingRoller ? T(1.0) : cam.arm_length;
}

/// The follower errors at one cam angle for deviations d (signed) or tolerances (then the signs
/// of the components are those of a positive deviation, and worst_case/rms are the bounds).
template <typename T>
MechanicalError<T> FollowerError(const DiscCamTpl<T>& cam, const CamPoint<T>& p,
                                 const Deviations<T>& d) {
  using std::abs;
  using std::cos;
  using std::sqrt;
  const T g = NormalErrorGain(cam, p);
  MechanicalError<T> e;
  e.normal = d.normal * g;                         // eqs. (17), (22)
  e.roller = d.roller * g;                         // eqs. (19), (25)
  e.radial = d.radial * cos(p.shift_angle) * g;    // eqs. (29), (30)
  e.worst_case = abs(e.normal) + abs(e.radial) + abs(e.roller);  // eq. (31)
  // eq. (32); the tiny floor keeps the derivative of sqrt finite when every tolerance is zero.
  e.rms = sqrt(e.normal * e.normal + e.radial * e.radial + e.roller * e.roller + T(1e-300));
  return e;
}

}  // namespace camopt::disc_cam
