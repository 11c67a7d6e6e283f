// Disc cam with an offset translating roller follower or an oscillating roller follower:
// pitch curve, profile, pressure angle, instant centre Q, shift angle, radius of curvature and
// undercut. Rzine et al., "Mechanical Error Analysis of Disc Cam Mechanisms" (docs/papers.md §2),
// eqs. (1)–(12), and eq. (28) for the shift angle λ.
//
// Frame and sense (the paper's): coordinates fixed on the cam, origin at the cam pivot O₂; the cam
// angle θ is measured against the cam's rotation, so in the cam frame the follower turns
// counter-clockwise with θ and the pitch curve C(θ) is traced counter-clockwise.
//   Translating: follower moves along u(θ), offset e along J u(θ):
//     C = L u(θ) + e J u(θ), L = sqrt((r_b + r_f)² − e²) + S(θ)                (eq. 5)
//   Oscillating: pivot O₃ = f u(θ), arm l, ξ the angle at O₃ between O₃O₂ and O₃C:
//     C = f u(θ) + l u(θ + π − ξ), ξ = acos((l² + f² − (r_b + r_f)²)/(2lf)) + S(θ)   (eq. 11)
// Contact point A = C − r_f n, n the unit outward normal of the pitch curve (toward the roller
// centre); the common normal passes through Q.
#pragma once

#include <cmath>
#include <vector>

#include "model/common/geometry.h"
#include "model/common/scalar.h"
#include "model/motion/motion_program.h"

namespace camopt::disc_cam {

enum class FollowerType { kTranslatingRoller, kOscillatingRoller };

/// A disc cam design. Lengths in mm; the motion program's rise is in mm for a translating
/// follower and in rad for an oscillating one; cam angles in rad.
template <typename T>
struct DiscCamTpl {
  FollowerType follower = FollowerType::kTranslatingRoller;
  T base_radius = T(0.0);     ///< r_b: base circle of the cam profile [mm]
  T roller_radius = T(0.0);   ///< r_f [mm]
  T offset = T(0.0);          ///< e, translating only [mm] (positive as in the paper's Fig. 1)
  T pivot_distance = T(0.0);  ///< f = O₂O₃, oscillating only [mm]
  T arm_length = T(0.0);      ///< l = O₃C, oscillating only [mm]
  motion::MotionProgram<T> motion;
};
using DiscCam = DiscCamTpl<double>;

/// The design with every number converted to the scalar To (a Jet gets constants; seed the
/// variables afterwards), as pinocchio's `model.cast<NewScalar>()`.
template <typename To>
DiscCamTpl<To> CastCam(const DiscCamTpl<double>& cam) {
  DiscCamTpl<To> out;
  out.follower = cam.follower;
  out.base_radius = To(cam.base_radius);
  out.roller_radius = To(cam.roller_radius);
  out.offset = To(cam.offset);
  out.pivot_distance = To(cam.pivot_distance);
  out.arm_length = To(cam.arm_length);
  std::vector<motion::MotionSegment<To>> segments;
  for (const motion::MotionSegment<double>& s : cam.motion.segments()) {
    motion::MotionSegment<To> c(s.law, To(s.rise), To(s.duration));
    for (double k : s.coefficients) c.coefficients.push_back(To(k));
    c.spline_degree = s.spline_degree;
    segments.push_back(std::move(c));
  }
  out.motion = motion::MotionProgram<To>(std::move(segments));
  return out;
}

/// The cam and follower at one cam angle.
template <typename T>
struct CamPoint {
  T theta;                  ///< cam angle [rad]
  T s, ds, d2s;             ///< follower motion S(θ) and its θ-derivatives (mm or rad per rad^k)
  Vec2<T> pitch;            ///< roller centre C [mm]
  Vec2<T> pitch_d1;         ///< dC/dθ [mm/rad]
  Vec2<T> contact;          ///< contact point A on the cam profile [mm]
  Vec2<T> normal;           ///< unit outward normal of the profile at A (from A toward C)
  Vec2<T> follower_dir;     ///< dC/dS at fixed θ: u(θ) (translating) or l·(unit velocity) [mm/unit]
  T q;                      ///< signed O₂Q: eq. (4) or eq. (8) [mm]; Q = q J u(θ) or −q u(θ)
  Vec2<T> instant_centre;   ///< Q [mm]
  T pressure_angle;         ///< φ [rad], eq. (3) or eq. (12)
  T shift_angle;            ///< λ = ∠O₂AQ [rad], eq. (28)
  T pitch_curvature;        ///< κ of the pitch curve [1/mm], > 0 where the cam is convex
  T radial_dimension;       ///< |O₂A| [mm]
};

/// Initial follower coordinate on the base circle: sqrt((r_b + r_f)² − e²) (eq. 5) for a
/// translating follower, ξ₀ = acos((l² + f² − (r_b + r_f)²)/(2lf)) (eq. 11) for an oscillating one.
/// @pre the geometry is feasible (see GeometryIssue).
template <typename T>
T InitialFollowerCoordinate(const DiscCamTpl<T>& cam) {
  using std::acos;
  using std::sqrt;
  const T r0 = cam.base_radius + cam.roller_radius;
  if (cam.follower == FollowerType::kTranslatingRoller)
    return sqrt(r0 * r0 - cam.offset * cam.offset);
  const T l = cam.arm_length, f = cam.pivot_distance;
  return acos((l * l + f * f - r0 * r0) / (T(2.0) * l * f));
}

/// The oscillating follower's pivot O₃ = f u(θ) in the cam frame [mm] (eq. 11).
template <typename T>
Vec2<T> FollowerPivot(const DiscCamTpl<T>& cam, const T& theta) {
  return cam.pivot_distance * U(theta);
}

/// The profile's contact point at cam angle theta, all a search over the profile needs (the
/// exact follower position of exact_motion.h): EvaluateCam's first part, by the same operations.
template <typename T>
struct CamContact {
  motion::Svaj<T> m;        ///< the follower motion S(θ) and its derivatives
  Vec2<T> u, ju;            ///< u(θ), J u(θ)
  T coordinate;             ///< L (eq. 5) or ξ (eq. 11)
  Vec2<T> w;                ///< oscillating: unit O₃ → C, u(θ + π − ξ); translating: unused
  Vec2<T> pitch;            ///< roller centre C [mm]
  Vec2<T> normal;           ///< unit outward normal of the profile at A
  Vec2<T> contact;          ///< contact point A [mm]
  T radial_dimension;       ///< |O₂A| [mm]
};

/// @param initial_coordinate InitialFollowerCoordinate(cam), taken once by a caller that
/// evaluates many angles.
template <typename T>
CAMOPT_FLATTEN CamContact<T> EvaluateCamContact(const DiscCamTpl<T>& cam, const T& theta, const T& initial_coordinate) {
  using std::sqrt;
  CamContact<T> c;
  c.m = cam.motion.Evaluate(theta);
  const motion::Svaj<T>& m = c.m;
  c.u = U(theta);
  c.ju = Perp(c.u);
  const Vec2<T>& u = c.u;
  const Vec2<T>& ju = c.ju;
  if (cam.follower == FollowerType::kTranslatingRoller) {
    const T e = cam.offset;
    const T L = initial_coordinate + m.s;  // eq. (5)
    c.coordinate = L;
    c.pitch = L * u + e * ju;
    // Eq. (2): A = C − r_f u(θ − φ); u(θ − φ) = (L u − (q − e) J u)/sqrt(L² + (q − e)²), q = dL/dθ.
    const T h = sqrt(L * L + (m.v - e) * (m.v - e));
    c.normal = (L * u - (m.v - e) * ju) / h;
    c.w = Vec2<T>::Zero();
  } else {
    const T f = cam.pivot_distance, l = cam.arm_length;
    const T xi = initial_coordinate + m.s;  // eq. (11)
    c.coordinate = xi;
    const T w1 = T(1.0) - m.v;              // 1 − dξ/dθ
    c.w = U(theta + T(kPi) - xi);           // unit O₃ → C
    c.pitch = f * u + l * c.w;              // O₃ = f u(θ) (FollowerPivot)
    // Eq. (8): q = f ξ'/(1 − ξ'), Q = −q u(θ). Q runs to infinity where ξ' = 1, so the normal
    // C − Q of eqs. (6)–(10) is taken in the regular form (1 − ξ')(C − Q) = (1 − ξ')C + f ξ' u,
    // which keeps its outward sense on both sides of ξ' = 1.
    const Vec2<T> nq = w1 * c.pitch + f * m.v * u;
    c.normal = nq / nq.norm();
  }
  c.contact = c.pitch - cam.roller_radius * c.normal;  // eqs. (1)/(6)
  c.radial_dimension = c.contact.norm();
  return c;
}

/// Evaluates the cam at angle theta [rad].
template <typename T>
CAMOPT_FLATTEN CamPoint<T> EvaluateCam(const DiscCamTpl<T>& cam, const T& theta) {
  using std::atan;
  using std::atan2;
  const CamContact<T> c = EvaluateCamContact(cam, theta, InitialFollowerCoordinate(cam));
  const motion::Svaj<T>& m = c.m;
  const Vec2<T>& u = c.u;
  const Vec2<T>& ju = c.ju;
  CamPoint<T> p;
  p.theta = theta;
  p.s = m.s;
  p.ds = m.v;
  p.d2s = m.a;
  p.pitch = c.pitch;
  p.normal = c.normal;
  p.contact = c.contact;
  p.radial_dimension = c.radial_dimension;
  Vec2<T> d2;  // d²C/dθ²
  if (cam.follower == FollowerType::kTranslatingRoller) {
    const T e = cam.offset;
    const T L = c.coordinate;
    p.q = m.v;                                          // eq. (4): q = dL/dθ
    p.pressure_angle = atan((p.q - e) / L);             // eq. (3)
    p.pitch_d1 = (p.q - e) * u + L * ju;
    d2 = (m.a - L) * u + (T(2.0) * p.q - e) * ju;
    p.instant_centre = p.q * ju;
    p.follower_dir = u;
  } else {
    const T f = cam.pivot_distance, l = cam.arm_length;
    const T xi = c.coordinate;
    const T w1 = T(1.0) - m.v;
    const Vec2<T>& w = c.w;
    p.pitch_d1 = f * ju + l * w1 * Perp(w);
    d2 = -f * u - l * w1 * w1 * w - l * m.a * Perp(w);
    p.q = f * m.v / w1;                                 // eq. (8)
    p.instant_centre = -p.q * u;
    // Eq. (10): α, the angle of the normal QC from u(θ); eq. (12): φ = 90° − α − ξ.
    const T alpha = atan2(Cross(u, p.normal), u.dot(p.normal));
    p.pressure_angle = T(kPi / 2) - alpha - xi;
    p.follower_dir = -l * Perp(w);  // dC/dξ
  }
  // Eq. (28): λ = ∠O₂AQ, the angle between O₂A and the common normal (AQ lies along −n where Q is
  // inside the pitch curve), written with atan2 so that it stays defined when Q is at infinity.
  const Vec2<T> ar = p.contact / p.radial_dimension;
  p.shift_angle = atan2(Cross(p.normal, ar), p.normal.dot(ar));
  const T speed = p.pitch_d1.norm();
  p.pitch_curvature = Cross(p.pitch_d1, d2) / (speed * speed * speed);
  return p;
}

/// Radius of curvature of the cam profile at a point: 1/κ − r_f, positive where convex, negative
/// where concave; ±infinite at an inflection of the pitch curve (κ = 0).
template <typename T>
T ProfileRadiusOfCurvature(const CamPoint<T>& p, const T& roller_radius) {
  return T(1.0) / p.pitch_curvature - roller_radius;
}

/// Undercut: the pitch curve is convex with a radius smaller than the roller (κ r_f > 1), so the
/// offset profile folds over itself (docs/disc_cam.md).
template <typename T>
bool IsUndercut(const CamPoint<T>& p, const T& roller_radius) {
  return Value(p.pitch_curvature) * Value(roller_radius) > 1.0;
}

}  // namespace camopt::disc_cam
