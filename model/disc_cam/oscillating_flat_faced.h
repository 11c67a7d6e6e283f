// Disc cam with an oscillating flat-faced follower: an arm pivoted at O₃ carries a flat face, the line
// parallel to the arm at perpendicular distance d from the pivot, on the cam's side (Rothbart, Cam
// Design Handbook ch. 5, "oscillating flat-faced follower"; Norton, Cam Design and Manufacturing
// Handbook ch. 7, the flat-faced follower as the envelope of its face lines).
//
// Frame and sense as model/disc_cam/disc_cam.h (coordinates fixed on the cam, θ against the cam's
// rotation): the pivot is O₃ = f u(θ), the arm's direction from the pivot is u(θ + π − ξ) = −u(α)
// with α = θ − ξ, ξ = ξ₀ + S(θ) the arm's angle from the line O₃O₂ (eq. 11's ξ, here for the face).
// The unit normal m = J u(θ + π − ξ) = −J u(α) points from the arm toward the cam (its component
// along O₃→O₂ is sin ξ > 0 for 0 < ξ < π). The face is the line (P − O₃) · m = d, i.e.
//   P · n(θ) = h(θ),   n = J u(α),   h = f sin ξ − d,
// using f u(θ) · J u(α) = f sin(θ − α) = f sin ξ. n is the cam's outward normal at the contact and h
// the face's distance from the cam centre: the cam is the intersection of the half-planes P · n ≤ h.
// On the base circle the face is tangent to it: h = r_b at S = 0, so sin ξ₀ = (r_b + d)/f (the arm
// below the horizontal through O₃ as seen from O₂, ξ₀ < 90°; needs r_b + d < f).
//
// The profile is the envelope of the lines. With the normal's angle φ = α + π/2 as parameter, h(φ) is
// the support function of the cam, and the envelope point and radius of curvature are the classical
//   A = h n + h_φ dn/dφ = h J u(α) − h_φ u(α),      ρ = h + h_φφ
// (the support-function form of an envelope of lines: Rothbart ch. 5; any convex-geometry text).
// Here dφ/dθ = α' = 1 − ξ' (ξ' = S'), dh/dθ = f ξ' cos ξ, so
//   h_φ  = f ξ' cos ξ / (1 − ξ'),
//   h_φφ = (h'' α' − h' α'') / α'³ = f [ξ'' cos ξ − ξ'² sin ξ (1 − ξ')] / (1 − ξ')³,
//   ρ = f sin ξ − d + f [ξ'' cos ξ − ξ'² sin ξ (1 − ξ')] / (1 − ξ')³.
// The profile is smooth and convex only where ρ > 0 (a flat face cannot follow a concave profile);
// the formulas need 1 − ξ' > 0 (the arm turns slower than the cam; where ξ' ≥ 1 the face turns back
// and the envelope is not a cam profile: `CheckOscillatingFlatFaced`).
// Where the contact lies on the face, from the foot of the perpendicular from the pivot, along the arm:
//   ℓ = (A − O₃) · (−u(α)) = f cos ξ − h_φ = f cos ξ / (1 − ξ'),
// so the face must reach from min ℓ to max ℓ. The pressure angle (between the common normal m and the
// velocity of the follower's contact point, perpendicular to O₃A = d m + ℓ(−u(α))) is atan(d/ℓ): 0 for
// a face through the pivot.
//
// Loads (kinetostatic, frictionless, constant cam speed ω; Norton, Cam Design and Manufacturing
// Handbook ch. 8, written here for the arm): the arm's angle ξ = ξ₀ + S turns with ξ̇ = S' ω,
// ξ̈ = S'' ω². About the pivot, the cam must supply the moment that accelerates the arm (inertia J)
// against the return spring (rate k, moment M₀ on the base circle) and a constant moment M_e pressing
// the arm onto the cam:
//   M = J S'' ω² + k S + M₀ + M_e.
// The contact force acts along the face's normal at A; its arm about the pivot is ℓ (A − O₃ = d m +
// ℓ(−u(α)) with m ∥ the force, so only ℓ has a moment), hence F = M/ℓ; F ≤ 0 is a separation. The
// camshaft torque from the power balance T ω = M ξ̇ is T = M S'. The arm first leaves the cam where
// F = 0 first, at ω² = (k S + M₀ + M_e)/(−J S'') over the decelerating angles (S'' < 0). Hertz: the
// plane face on the profile's osculating cylinder of radius ρ (Johnson, Contact Mechanics eq. 4.45).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "model/common/geometry.h"
#include "model/common/scalar.h"
#include "model/contact/hertz.h"
#include "model/disc_cam/kinetostatics.h"
#include "model/motion/motion_program.h"

namespace camopt::disc_cam {

/// An oscillating flat-faced follower: pivot distance f = O₂O₃ [mm], face offset d from the pivot
/// [mm] (0: the face passes through the pivot), base circle r_b [mm]; the motion's rise in rad.
struct OscillatingFlatFaced {
  double base_radius = 0.0;     ///< r_b [mm]
  double pivot_distance = 0.0;  ///< f [mm]
  double face_offset = 0.0;     ///< d [mm], the face's distance from the pivot, toward the cam
  motion::MotionProgram<double> motion;
};

/// The arm's angle on the base circle, ξ₀ = asin((r_b + d)/f) [rad]; NaN when r_b + d ≥ f.
inline double InitialArmAngle(const OscillatingFlatFaced& c) {
  const double x = (c.base_radius + c.face_offset) / c.pivot_distance;
  return x < 1.0 && x > -1.0 ? std::asin(x) : std::nan("");
}

/// The cam and the oscillating flat face at one cam angle.
struct OscillatingFlatFacePoint {
  double theta = 0.0;                ///< cam angle [rad]
  double xi = 0.0, dxi = 0.0, d2xi = 0.0;  ///< ξ = ξ₀ + S [rad], ξ', ξ''
  Vec2<double> pivot;                ///< O₃ [mm]
  Vec2<double> normal;               ///< n = J u(θ − ξ), the cam's outward normal at the contact
  double support = 0.0;              ///< h = f sin ξ − d, the face's distance from the cam centre [mm]
  Vec2<double> contact;              ///< A [mm]
  double contact_on_face = 0.0;      ///< ℓ = f cos ξ/(1 − ξ') [mm], from the pivot's foot along the arm
  double radius_of_curvature = 0.0;  ///< ρ = h + h_φφ [mm]; > 0 convex, ≤ 0 a cusp
  double pressure_angle = 0.0;       ///< atan(d/ℓ) [rad]
};

/// The contact at cam angle theta [rad]. @pre 1 − ξ' ≠ 0 (CheckOscillatingFlatFaced).
inline OscillatingFlatFacePoint EvaluateOscillatingFlatFaced(const OscillatingFlatFaced& c, double theta) {
  OscillatingFlatFacePoint p;
  const motion::Svaj<double> m = c.motion.Evaluate(theta);
  const double f = c.pivot_distance, d = c.face_offset;
  p.theta = theta;
  p.xi = InitialArmAngle(c) + m.s;
  p.dxi = m.v;
  p.d2xi = m.a;
  const double alpha = theta - p.xi, w1 = 1.0 - m.v;
  const double sx = std::sin(p.xi), cx = std::cos(p.xi);
  p.pivot = f * U(theta);
  p.normal = Perp(U(alpha));
  p.support = f * sx - d;
  const double h_phi = f * m.v * cx / w1;
  p.contact = p.support * p.normal - h_phi * U(alpha);
  p.contact_on_face = f * cx / w1;
  p.radius_of_curvature = p.support + f * (m.a * cx - m.v * m.v * sx * w1) / (w1 * w1 * w1);
  p.pressure_angle = std::atan2(d, p.contact_on_face);
  return p;
}

/// Feasibility over angle_steps cam angles: the face reaches the base circle (r_b + d < f), and the
/// arm stays in (0, π) and turns slower than the cam (ξ' < 1). Returns the first message, empty
/// when feasible.
inline std::string CheckOscillatingFlatFaced(const OscillatingFlatFaced& c, int angle_steps) {
  if (!(c.base_radius + c.face_offset < c.pivot_distance))
    return "the face cannot touch the base circle: need base circle + face offset < pivot distance";
  const double xi0 = InitialArmAngle(c);
  for (int i = 0; i < angle_steps; ++i) {
    const double th = 2 * kPi * i / angle_steps;
    const motion::Svaj<double> m = c.motion.Evaluate(th);
    if (m.s < -1e-9) return "the follower goes inside the base circle";
    if (!(xi0 + m.s > 0.0 && xi0 + m.s < kPi)) return "the arm leaves (0, 180) deg from the cam centre line";
    if (!(m.v < 1.0)) return "the arm turns as fast as the cam (dξ/dθ >= 1): the face's envelope is no cam profile";
  }
  return "";
}

/// The loads at one point at cam speed omega [rad/s] (derivation above).
struct ArmLoad {
  double moment_N_m = 0.0;        ///< M, the cam's moment on the arm about the pivot
  double contact_force_N = 0.0;   ///< F = M/ℓ (ℓ in m)
  double camshaft_torque_N_m = 0.0;  ///< T = M S'
};
inline ArmLoad OscillatingFlatFaceLoadAt(const OscillatingFlatFaced& c, const OscillatingFlatFacePoint& p,
                                         const ArmLoads& a, double omega) {
  const double lift = p.xi - InitialArmAngle(c);  // S [rad]
  ArmLoad out;
  out.moment_N_m = a.inertia_kg_m2 * p.d2xi * omega * omega + a.spring_rate_N_m_per_rad * lift +
                   a.spring_preload_N_m + a.external_moment_N_m;
  out.contact_force_N = out.moment_N_m / (p.contact_on_face * 1e-3);
  out.camshaft_torque_N_m = out.moment_N_m * p.dxi;
  return out;
}

/// The lowest cam speed [rad/s] at which the face leaves the cam (F = 0) over the points: +∞ when the
/// arm never decelerates (or J = 0), 0 when the spring and the moments do not hold it on the base
/// circle.
inline double OscillatingFlatFaceJumpSpeed(const OscillatingFlatFaced& c,
                                           const std::vector<OscillatingFlatFacePoint>& points, const ArmLoads& a) {
  double best = std::numeric_limits<double>::infinity();
  const double xi0 = InitialArmAngle(c);
  for (const OscillatingFlatFacePoint& p : points) {
    const double hold = a.spring_rate_N_m_per_rad * (p.xi - xi0) + a.spring_preload_N_m + a.external_moment_N_m;
    if (hold <= 0.0) return 0.0;
    const double pull = -a.inertia_kg_m2 * p.d2xi;  // the inertia's moment per ω², away from the cam
    if (pull > 0.0) best = std::min(best, std::sqrt(hold / pull));
  }
  return best;
}

/// Peak Hertz pressure of the face on the profile [MPa] (line contact over face_width_mm along the
/// camshaft axis on a cylinder of radius ρ): 0 for F ≤ 0; NaN where ρ ≤ 0 (a cusp).
inline double OscillatingFlatFaceContactStress(const OscillatingFlatFacePoint& p, double force_N, double face_width_mm,
                                               double composite_modulus_MPa) {
  if (!(force_N > 0.0)) return 0.0;
  if (!(p.radius_of_curvature > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return contact::LineContactPeakPressure(force_N, face_width_mm, p.radius_of_curvature, composite_modulus_MPa);
}

}  // namespace camopt::disc_cam
