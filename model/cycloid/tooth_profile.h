// Cycloid gear tooth profile by circle enveloping, with profile modification (Δa, Δρ).
// Cycloid load-distribution paper, eqs. (1)–(4).
//
// Frames. Fixed frame: crank axis at O, rollers (pins) at a·u(ψ_i), ψ_i = 2πi/n1. The disc centre
// is at e·u(φ) for crank angle φ and the disc turns by −φ/n2 (ring fixed, ratio n2 : 1, the disc
// turns against the crank). In the disc frame the roller centres trace the roller-centre curve
//     X(t) = a u(t) − e u(n1 t)                                  (the curtate epitrochoid)
// and the tooth profile is its inner envelope of circles of radius ρ: P(t) = X(t) − ρ N(t), N the
// outward unit normal of X. The paper writes the same envelope with its meshing equation (eq. 2);
// here the meshing condition is solved in closed form: the envelope point lies on the normal of
// the roller-centre curve. Profile modification (eqs. 3–4) generates the profile with the grinding
// wheel at a' = a + Δa and of radius ρ' = ρ + Δρ; the mating rollers keep a and ρ.
#pragma once

#include <cmath>
#include <string>

#include "model/common/geometry.h"
#include "model/common/scalar.h"

namespace camopt::cycloid {

/// The design of one cycloid stage. Lengths in mm.
template <typename T>
struct DriveTpl {
  int teeth = 15;    ///< n2, cycloid gear teeth
  int rollers = 16;  ///< n1 = n2 + 1, rollers (pins) on the housing
  T roller_position_radius_mm = T(90.0);  ///< a
  T roller_radius_mm = T(7.2);            ///< ρ
  T eccentricity_mm = T(4.5);             ///< e
  T face_width_mm = T(17.0);              ///< B
  T delta_position_mm = T(0.0);           ///< Δa, profile modification of the roller position
  T delta_radius_mm = T(0.0);             ///< Δρ, profile modification of the roller radius
};
using Drive = DriveTpl<double>;

/// A point of the (modified) tooth profile in the disc frame.
template <typename T>
struct ProfilePoint {
  Vec2<T> centre;     ///< X'(t), centre of the generating circle (roller-centre curve) [mm]
  Vec2<T> point;      ///< P(t) = X'(t) − ρ' N(t), on the tooth [mm]
  Vec2<T> normal;     ///< N(t), outward unit normal (from the disc towards the roller)
  Vec2<T> tangent;    ///< unit tangent, direction of increasing t
  T speed;            ///< |dX'/dt| [mm/rad]
  T centre_curvature; ///< signed curvature of X' [1/mm], > 0 where X' is convex
  T curvature;        ///< signed curvature of the tooth profile [1/mm], > 0 convex (tip)
};

/// The modified tooth profile at curve parameter t [rad] (eqs. 3–4).
/// @tparam T double or ceres::Jet.
template <typename T>
ProfilePoint<T> ToothProfile(const DriveTpl<T>& d, const T& t) {
  using std::sqrt;
  const T a = d.roller_position_radius_mm + d.delta_position_mm;
  const T rho = d.roller_radius_mm + d.delta_radius_mm;
  const T e = d.eccentricity_mm;
  const T n1 = T(double(d.rollers));
  const Vec2<T> u0 = U(t), u1 = U(T(n1 * t));
  ProfilePoint<T> p;
  p.centre = a * u0 - e * u1;
  const Vec2<T> xt = a * Perp(u0) - e * n1 * Perp(u1);
  const Vec2<T> xtt = -a * u0 + e * n1 * n1 * u1;
  p.speed = sqrt(xt.squaredNorm());
  p.tangent = xt / p.speed;
  p.normal = -Perp(p.tangent);  // X' runs counter-clockwise: the outward normal is on the right
  p.centre_curvature = Cross(xt, xtt) / (p.speed * p.speed * p.speed);
  p.point = p.centre - rho * p.normal;
  // Inner offset by ρ': radius 1/κ − ρ', written as a curvature so that inflections stay finite.
  p.curvature = p.centre_curvature / (T(1.0) - rho * p.centre_curvature);
  return p;
}

/// Roller i centre in the disc frame at crank angle φ [rad] with the disc turned by an extra
/// angle β [rad] (counter-clockwise in the fixed frame) from its kinematic position.
template <typename T>
Vec2<T> RollerCentreInDisc(const DriveTpl<T>& d, int i, const T& crank, const T& beta) {
  const T psi = T(2.0 * kPi * i / d.rollers);
  const Vec2<T> rel = d.roller_position_radius_mm * U(psi) - d.eccentricity_mm * U(crank);
  return Rotate(rel, T(crank / double(d.teeth) - beta));
}

/// Curve parameter of the unmodified profile point that roller i touches at crank φ:
/// t_i = ψ_i + φ/n2 (exact for Δa = Δρ = 0, the start of the modified search otherwise).
template <typename T>
T NominalParameter(const DriveTpl<T>& d, int i, const T& crank) {
  return T(2.0 * kPi * i / d.rollers) + crank / double(d.teeth);
}

/// Checks that a design is a drive: returns "" or why it is not (infeasible geometry).
/// n1 = n2 + 1; lengths positive; K1 = e n1 / a' < 1 (the roller-centre curve has no loops);
/// rollers do not overlap; the tooth is not undercut (every convex radius of X' exceeds ρ').
inline std::string CheckDrive(const Drive& d) {
  if (d.teeth < 2) return "the cycloid gear needs at least 2 teeth";
  if (d.rollers != d.teeth + 1) return "rollers must be teeth + 1 (one-tooth-difference drive)";
  const double a = d.roller_position_radius_mm + d.delta_position_mm;
  const double rho = d.roller_radius_mm + d.delta_radius_mm;
  if (!(d.roller_position_radius_mm > 0 && d.roller_radius_mm > 0 && d.eccentricity_mm > 0 &&
        d.face_width_mm > 0))
    return "roller position, roller radius, eccentricity and face width must be > 0";
  if (!(rho > 0)) return "the modified roller radius rho + delta_rho must be > 0";
  if (!(d.eccentricity_mm * d.rollers < a))
    return "eccentricity too large: e * rollers must be < roller position radius (K1 < 1)";
  if (!(2.0 * d.roller_position_radius_mm * std::sin(kPi / d.rollers) > 2.0 * d.roller_radius_mm))
    return "rollers overlap: 2 a sin(pi / rollers) must exceed 2 rho";
  // Undercut: sample one tooth finely for the largest convex curvature of X'.
  const int n = 2000;
  for (int k = 0; k <= n; ++k) {
    const double t = 2.0 * kPi / d.teeth * k / n;
    const double kappa = ToothProfile(d, t).centre_curvature;
    if (kappa * rho >= 1.0) return "the tooth profile is undercut (a convex radius < rho)";
  }
  return "";
}

}  // namespace camopt::cycloid
