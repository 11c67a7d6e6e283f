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
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "model/common/geometry.h"
#include "model/common/scalar.h"
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

}  // namespace camopt::disc_cam
