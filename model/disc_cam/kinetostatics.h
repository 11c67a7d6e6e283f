// Kinetostatic loads of a disc cam with a translating roller follower: the follower is rigid, its
// motion is the one the cam prescribes, friction is neglected (Rothbart, Cam Design Handbook,
// ch. 8 "Cam mechanism forces"; Norton, Cam Design and Manufacturing Handbook, ch. 8).
//   Cam speed ω [rad/s]; follower acceleration in time a = S''(θ) ω² (S'' in mm/rad²).
//   Axial force the cam must supply:  F_y = m a + k S + F₀ + P + W          (Rothbart Fig. 8.7)
//     m follower mass, k spring rate, F₀ spring force at S = 0 (preload), P external load pressing
//     the follower onto the cam, W the weight component along the follower axis toward the cam.
//   Contact force along the common normal:  F_c = F_y / cos φ
//   Camshaft torque (moment of F_c about the cam axis):  T = F_c (n × A), which equals F_y S'(θ)
//     (frictionless power balance T ω = F_y Ṡ; a test checks the two).
//   Jump speed (F_c reaches 0 first; cos φ > 0 does not move the zero):
//     ω_jump² = min over θ with S'' < 0 of (k S + F₀ + P + W) / (−m S'').
//   Hertz stress, roller on cam (line contact, Johnson eq. 4.45): p₀ = sqrt(F_c E* / (π w R')),
//     1/R' = 1/r_f + 1/ρ with ρ = 1/κ − r_f the profile radius, i.e. R' = r_f (1 − r_f κ): finite at
//     an inflection of the pitch curve (κ = 0: R' = r_f), not positive where the profile is undercut.
// Units: lengths mm, forces N, mass kg, speed rad/s, torque N·mm, stress MPa.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "model/common/geometry.h"
#include "model/common/scalar.h"
#include "model/contact/hertz.h"
#include "model/disc_cam/disc_cam.h"

namespace camopt::disc_cam {

/// Standard gravity [m/s²] (ISO 80000-3).
inline constexpr double kStandardGravity = 9.80665;

/// The loads on a translating roller follower.
struct FollowerLoads {
  double mass_kg = 0.0;               ///< m: follower, roller and a third of the spring [kg]
  double spring_rate_N_per_mm = 0.0;  ///< k
  double spring_preload_N = 0.0;      ///< F₀: spring force on the base circle (S = 0)
  double external_load_N = 0.0;       ///< P: constant, pressing the follower onto the cam
  double weight_N = 0.0;              ///< W: weight component toward the cam (m g for a vertical
                                      ///< follower above the cam, −m g below it, 0 horizontal)
};

/// Cam speed [rad/s] from revolutions per minute.
inline double RadPerSecond(double rpm) { return rpm * 2.0 * kPi / 60.0; }
/// Revolutions per minute from a speed [rad/s].
inline double Rpm(double rad_per_s) { return rad_per_s * 60.0 / (2.0 * kPi); }

/// F_y = m S'' ω² + k S + F₀ + P + W [N], the force along the follower axis the cam must supply.
/// @param s follower displacement S [mm]. @param d2s S'' [mm/rad²]. @param omega cam speed [rad/s].
template <typename T>
T FollowerAxialForce(const FollowerLoads& f, const T& s, const T& d2s, const T& omega) {
  const T inertia = T(f.mass_kg) * d2s * omega * omega * T(1e-3);  // kg · m/s²
  return inertia + T(f.spring_rate_N_per_mm) * s + T(f.spring_preload_N) + T(f.external_load_N) +
         T(f.weight_N);
}

/// The static part k S + F₀ + P + W [N]: what holds the follower on the cam at rest.
template <typename T>
T FollowerStaticForce(const FollowerLoads& f, const T& s) {
  return T(f.spring_rate_N_per_mm) * s + T(f.spring_preload_N) + T(f.external_load_N) + T(f.weight_N);
}

/// The contact force along the common normal and the camshaft torque at one cam point.
template <typename T>
struct CamLoad {
  T axial_force;     ///< F_y [N]
  T contact_force;   ///< F_c = F_y / cos φ [N] (negative: the follower has left the cam)
  T camshaft_torque; ///< T = F_c (n × A) [N·mm], > 0 where the camshaft drives the follower
};

/// Loads at one point of a translating roller follower cam at speed omega [rad/s].
template <typename T>
CamLoad<T> CamLoadAt(const CamPoint<T>& p, const FollowerLoads& f, const T& omega) {
  using std::cos;
  CamLoad<T> out;
  out.axial_force = FollowerAxialForce(f, p.s, p.d2s, omega);
  out.contact_force = out.axial_force / cos(p.pressure_angle);
  // The cam pushes the roller along +n at A; the roller pushes back along −n, whose moment about
  // O₂ is A × (−F_c n) = F_c (n × A): the torque the camshaft must overcome.
  out.camshaft_torque = out.contact_force * Cross(p.normal, p.contact);
  return out;
}

namespace kinetostatics_internal {

/// The closed-form jump speed of a follower whose contact force (or moment) at a point is
/// hold(p) − ω² pull(p): √(min over the points with pull > 0 of hold/pull); 0 when hold is not
/// positive somewhere, +infinity when pull > 0 nowhere.
template <typename Point, typename Hold, typename Pull>
double FirstZeroSpeed(const std::vector<Point>& points, const Hold& hold, const Pull& pull) {
  double best = std::numeric_limits<double>::infinity();
  for (const Point& p : points) {
    const double h = hold(p);
    if (!(h > 0.0)) return 0.0;
    const double q = pull(p);
    if (q > 0.0) best = std::min(best, h / q);
  }
  return std::sqrt(best);
}

}  // namespace kinetostatics_internal

/// The speed [rad/s] at which the contact force first reaches zero, from the closed form
/// ω² = min over the points with S'' < 0 of (k S + F₀ + P + W)/(−m S''): 0 when the static force
/// is not positive somewhere (the follower leaves the cam at rest), +infinity when no point
/// decelerates the follower (S'' ≥ 0 everywhere) or the mass is zero.
/// @param points the cam over the analysis grid (S, S'' used).
/// Any point with the follower's S and S'' (a roller's CamPoint, a flat face's FlatFacePoint).
template <typename Point>
double JumpSpeedOver(const std::vector<Point>& points, const FollowerLoads& f) {
  return kinetostatics_internal::FirstZeroSpeed(
      points, [&f](const Point& p) { return FollowerStaticForce(f, p.s); },
      [&f](const Point& p) { return -(f.mass_kg * p.d2s * 1e-3); });  // N per (rad/s)², away from the cam
}
inline double JumpSpeed(const std::vector<CamPoint<double>>& points, const FollowerLoads& f) {
  return JumpSpeedOver(points, f);
}

/// The spring that keeps the follower on the cam at every speed from rest up to omega [rad/s]:
/// F_y = m S'' ω² + k S + F₀ + P + W ≥ 0 at every point and speed; the worst speed of a point is
/// omega where it decelerates the follower (S'' < 0) and rest where it does not, so with
/// I(θ) = min(0, m S'' ω²):
///   the smallest preload with the given rate    F₀,min = max(0, max_θ −(I + k S + P + W)),
///   the smallest rate with the given preload    k_min = max(0, max_{θ: S > 0} −(I + F₀ + P + W)/S),
/// k_min infinite when a point with S = 0 has a deficit (on the base circle only a preload helps).
/// (Rothbart, Cam Design Handbook, ch. 8: the spring force must exceed the negative inertia load.)
struct SpringRequirement {
  double min_preload_N = 0.0;                                        ///< with the given rate
  double min_rate_N_per_mm = 0.0;                                    ///< with the given preload
};
template <typename Point>
SpringRequirement RequiredSpringOver(const std::vector<Point>& points, const FollowerLoads& f, double omega) {
  SpringRequirement r;
  for (const Point& p : points) {
    const double inertia = std::min(0.0, f.mass_kg * p.d2s * 1e-3 * omega * omega);
    const double fixed = inertia + f.external_load_N + f.weight_N;
    r.min_preload_N = std::max(r.min_preload_N, -(fixed + f.spring_rate_N_per_mm * p.s));
    const double deficit = -(fixed + f.spring_preload_N);
    if (deficit > 0.0)
      r.min_rate_N_per_mm = p.s > 0.0 ? std::max(r.min_rate_N_per_mm, deficit / p.s)
                                      : std::numeric_limits<double>::infinity();
  }
  return r;
}

/// The loads on a follower arm about its pivot: moment of inertia about the pivot J [kg·m²], return
/// spring rate k [N·m/rad] and its moment on the base circle M₀ [N·m], a constant moment M_e pressing
/// the arm onto the cam [N·m] (oscillating followers; model/disc_cam/oscillating_flat_faced.h for a
/// flat face, OscillatingRollerLoadAt below for a roller or knife edge).
struct ArmLoads {
  double inertia_kg_m2 = 0.0;
  double spring_rate_N_m_per_rad = 0.0;
  double spring_preload_N_m = 0.0;
  double external_moment_N_m = 0.0;
};

/// The moment the cam must supply to the arm about its pivot [N·m]:
///   M = J S'' ω² + k S + M₀ + M_e,
/// S [rad] the arm's swing from the base circle (ξ − ξ₀ of Rzine et al. eq. 11), S'' [rad/rad²], ω
/// [rad/s]: the arm's angular acceleration is ξ̈ = S'' ω² (ξ is measured from the frame line O₂O₃).
template <typename T>
T ArmMoment(const ArmLoads& a, const T& s, const T& d2s, const T& omega) {
  return T(a.inertia_kg_m2) * d2s * omega * omega + T(a.spring_rate_N_m_per_rad) * s + T(a.spring_preload_N_m) +
         T(a.external_moment_N_m);
}

/// The loads at one point of an oscillating roller (or knife-edge) follower cam.
template <typename T>
struct ArmCamLoad {
  T moment;           ///< M [N·m], the cam's moment on the arm about the pivot
  T contact_force;    ///< F_c [N] along the common normal (negative: the roller has left the cam)
  T camshaft_torque;  ///< T = F_c (n × A) [N·mm], > 0 where the camshaft drives the arm
};

/// Kinetostatic loads of an oscillating roller follower at speed omega [rad/s] (rigid arm, no
/// friction; Norton, Cam Design and Manufacturing Handbook ch. 8, the moment balance written about
/// the arm's pivot O₃). The cam pushes the roller with F_c along the profile's normal n, whose line
/// passes through the roller centre C, so by virtual work about the arm's angle ξ its moment about
/// O₃ is F_c n · dC/dξ (dC/dξ = follower_dir, of length l, perpendicular to O₃C; n · dC/dξ =
/// l cos φ with φ the pressure angle of eq. 12). The arm's moment balance J ξ̈ = F_c n · dC/dξ − (k S
/// + M₀ + M_e) gives
///   F_c = M / (n · dC/dξ),   M = J S'' ω² + k S + M₀ + M_e   (lengths in m).
/// The camshaft torque is the contact force's moment about O₂, as for the translating follower;
/// frictionless, it equals the power balance M S' (a test checks the two).
template <typename T>
ArmCamLoad<T> OscillatingRollerLoadAt(const CamPoint<T>& p, const ArmLoads& a, const T& omega) {
  ArmCamLoad<T> out;
  out.moment = ArmMoment(a, p.s, p.d2s, omega);
  out.contact_force = out.moment / (p.normal.dot(p.follower_dir) * T(1e-3));
  out.camshaft_torque = out.contact_force * Cross(p.normal, p.contact);
  return out;
}

/// The lowest cam speed [rad/s] at which an arm's moment M (hence its contact force) first reaches
/// zero: ω² = min over the points with S'' < 0 of (k S + M₀ + M_e)/(−J S''); 0 when the static
/// moment is not positive somewhere, +infinity when the arm never decelerates. Any point with S, S''
/// [rad] (a CamPoint of an oscillating roller).
template <typename Point>
double ArmJumpSpeedOver(const std::vector<Point>& points, const ArmLoads& a) {
  return kinetostatics_internal::FirstZeroSpeed(
      points, [&a](const Point& p) { return ArmMoment(a, p.s, 0.0, 0.0); },
      [&a](const Point& p) { return -a.inertia_kg_m2 * p.d2s; });  // per (rad/s)², away from the cam
}

/// The arm's spring that keeps contact at every speed up to omega [rad/s], as RequiredSpringOver
/// with moments: the smallest M₀ [N·m] with the given rate, the smallest rate [N·m/rad] with the
/// given M₀ (+infinity when the deficit is on the base circle).
template <typename Point>
SpringRequirement ArmRequiredSpringOver(const std::vector<Point>& points, const ArmLoads& a, double omega) {
  SpringRequirement r;
  for (const Point& p : points) {
    const double fixed = std::min(0.0, a.inertia_kg_m2 * p.d2s * omega * omega) + a.external_moment_N_m;
    r.min_preload_N = std::max(r.min_preload_N, -(fixed + a.spring_rate_N_m_per_rad * p.s));
    const double deficit = -(fixed + a.spring_preload_N_m);
    if (deficit > 0.0)
      r.min_rate_N_per_mm = p.s > 0.0 ? std::max(r.min_rate_N_per_mm, deficit / p.s)
                                      : std::numeric_limits<double>::infinity();
  }
  return r;
}

/// Effective radius R' = r_f (1 − r_f κ) of the roller on the cam profile [mm] (1/R' = 1/r_f + 1/ρ,
/// ρ the profile radius, concave negative); ≤ 0 where the profile is undercut.
template <typename T>
T RollerCamEffectiveRadius(const CamPoint<T>& p, const T& roller_radius) {
  return roller_radius * (T(1.0) - roller_radius * p.pitch_curvature);
}

/// Peak Hertz line-contact pressure between roller and cam [MPa] for a contact force [N] over the
/// face width [mm]; 0 for a force ≤ 0 (no contact); NaN where the profile is undercut (R' ≤ 0).
inline double RollerCamContactStress(const CamPoint<double>& p, double roller_radius, double force_N,
                                     double face_width_mm, double composite_modulus_MPa) {
  if (!(force_N > 0.0)) return 0.0;
  const double r_eff = RollerCamEffectiveRadius(p, roller_radius);
  if (!(r_eff > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return contact::LineContactPeakPressure(force_N, face_width_mm, r_eff, composite_modulus_MPa);
}

}  // namespace camopt::disc_cam
