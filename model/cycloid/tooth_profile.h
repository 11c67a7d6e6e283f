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

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "model/common/design_issue.h"
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

  /// The same drive over another scalar (ScalarCast per member): a Jet drive from a double one
  /// (constants, to be seeded), or the values of a Jet drive.
  template <typename U>
  DriveTpl<U> cast() const {
    DriveTpl<U> d;
    d.teeth = teeth;
    d.rollers = rollers;
    d.roller_position_radius_mm = ScalarCast<U>(roller_position_radius_mm);
    d.roller_radius_mm = ScalarCast<U>(roller_radius_mm);
    d.eccentricity_mm = ScalarCast<U>(eccentricity_mm);
    d.face_width_mm = ScalarCast<U>(face_width_mm);
    d.delta_position_mm = ScalarCast<U>(delta_position_mm);
    d.delta_radius_mm = ScalarCast<U>(delta_radius_mm);
    return d;
  }
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
CAMOPT_FLATTEN ProfilePoint<T> ToothProfile(const DriveTpl<T>& d, const T& t) {
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

/// Checks that a design is a drive: empty, or why it is not (infeasible geometry), each issue on
/// a field of Drive ("teeth", "rollers", "roller_position_radius_mm", "roller_radius_mm",
/// "eccentricity_mm", "face_width_mm", "delta_radius_mm"); value and limit in mm or counts.
/// n1 = n2 + 1; lengths positive; K1 = e n1 / a' < 1 (the roller-centre curve has no loops);
/// rollers do not overlap; the tooth is not undercut (every convex radius of X' exceeds ρ'). The
/// first failed rule ends the check.
inline std::vector<DesignIssue> CheckDrive(const Drive& d) {
  auto n = [](double v, int digits = 6) { return IssueNumber(v, digits); };
  const std::string teeth = std::to_string(d.teeth), rollers = std::to_string(d.rollers);
  if (d.teeth < 2)
    return {{"teeth", "the cycloid gear needs at least 2 teeth, found " + teeth, double(d.teeth), 2.0}};
  if (d.rollers != d.teeth + 1)
    return {{"rollers",
             "rollers must be teeth + 1 (one-tooth-difference drive): found " + rollers + " rollers for " + teeth +
                 " teeth; " + std::to_string(d.teeth + 1) + " rollers would fit",
             double(d.rollers), double(d.teeth + 1)}};
  for (const auto& [field, v] : {std::pair<const char*, double>{"roller_position_radius_mm", d.roller_position_radius_mm},
                                 {"roller_radius_mm", d.roller_radius_mm},
                                 {"eccentricity_mm", d.eccentricity_mm},
                                 {"face_width_mm", d.face_width_mm}})
    if (!(v > 0)) return {{field, std::string(field) + " must be > 0, found " + n(v), v, 0.0}};
  const double a = d.roller_position_radius_mm + d.delta_position_mm;
  const double rho = d.roller_radius_mm + d.delta_radius_mm;
  if (!(rho > 0))
    return {{"delta_radius_mm",
             "the modified roller radius rho + delta_rho = " + n(rho) + " mm must be > 0: a delta_rho above " +
                 n(-d.roller_radius_mm) + " mm would fit",
             rho, 0.0}};
  if (!(d.eccentricity_mm * d.rollers < a))
    return {{"eccentricity_mm",
             "eccentricity too large: e * rollers = " + n(d.eccentricity_mm * d.rollers) +
                 " mm must be < the roller position radius a + delta_a = " + n(a) + " mm (K1 = " +
                 n(d.eccentricity_mm * d.rollers / a, 4) + " < 1): e must be below " + n(a / d.rollers) + " mm for " +
                 rollers + " rollers on a " + n(a) + " mm pin circle",
             d.eccentricity_mm, a / d.rollers}};
  const double half_chord = d.roller_position_radius_mm * std::sin(kPi / d.rollers);
  if (!(2.0 * half_chord > 2.0 * d.roller_radius_mm))
    return {{"roller_radius_mm",
             "rollers overlap: 2 a sin(pi / rollers) = " + n(2.0 * half_chord) + " mm must exceed 2 rho = " +
                 n(2.0 * d.roller_radius_mm) + " mm: a roller radius below " + n(half_chord) + " mm for " + rollers +
                 " rollers on a " + n(d.roller_position_radius_mm) + " mm pin circle would fit",
             d.roller_radius_mm, half_chord}};
  // Undercut: sample one tooth finely for the largest convex curvature of X'.
  const int samples = 2000;
  double kappa_max = 0.0;
  for (int k = 0; k <= samples; ++k) {
    const double t = 2.0 * kPi / d.teeth * k / samples;
    kappa_max = std::max(kappa_max, ToothProfile(d, t).centre_curvature);
  }
  if (kappa_max * rho >= 1.0)
    return {{"roller_radius_mm",
             "the tooth profile is undercut (a convex radius < rho): the roller-centre curve's sharpest convex "
             "radius is " + n(1.0 / kappa_max) + " mm, below rho + delta_rho = " + n(rho) +
                 " mm; a roller radius below " + n(1.0 / kappa_max - d.delta_radius_mm) +
                 " mm (or a smaller eccentricity) would fit",
             rho, 1.0 / kappa_max}};
  return {};
}

}  // namespace camopt::cycloid
