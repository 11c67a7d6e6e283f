// Disc cam with a translating flat-faced follower whose face is perpendicular to its line of motion
// (Norton, Design of Machinery §8.9, "flat-faced follower"; Rothbart, Cam Design Handbook ch. 5).
//
// Frame and sense as model/disc_cam/disc_cam.h: coordinates fixed on the cam, θ against the cam's
// rotation, the follower's line of motion along u(θ). The face is the line
//   { P : P · u(θ) = r_b + S(θ) },
// and the cam profile is the envelope of these lines over θ (differentiate P · u(θ) = r_b + S in θ
// with P fixed: P · J u(θ) = S'), so the contact point is
//   A(θ) = (r_b + S) u(θ) + S' J u(θ):
// the contact lies S' off the follower's axis (the face must reach max S' on one side and −min S'
// on the other: the face width needed), dA/dθ = (r_b + S + S'') J u(θ), so the profile's radius of
// curvature is ρ = r_b + S + S'' and the profile is smooth and convex only where ρ > 0 (a flat face
// cannot follow a concave profile; ρ ≤ 0 is a cusp, the follower skips part of the motion). The
// pressure angle is 0: the common normal u(θ) is the line of motion. An offset of the line of motion
// moves the contact along the face only (S' + e off the axis), not the profile.
//
// Loads (kinetostatic, frictionless; Norton, Cam Design and Manufacturing Handbook ch. 8; Rothbart,
// Cam Design Handbook ch. 8): the contact force is the axial force F_y (the normal is the line of
// motion, φ = 0). The cam feels −F_y u(θ) at A, whose moment about the cam axis is
//   A × (−F_y u) = −F_y ((r_b + S) u + S' J u) × u = F_y S',
// the camshaft torque (the power balance T ω = F_y Ṡ with Ṡ = S' ω holds exactly). Hertz stress:
// a plane on the profile's osculating cylinder of radius ρ (Johnson, Contact Mechanics eq. 4.45 with
// 1/R' = 1/ρ + 1/∞): p₀ = sqrt(F E*/(π w ρ)), w the contact length along the camshaft axis.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "model/common/geometry.h"
#include "model/common/scalar.h"
#include "model/contact/hertz.h"
#include "model/disc_cam/check.h"
#include "model/disc_cam/kinetostatics.h"
#include "model/motion/motion_program.h"

namespace camopt::disc_cam {

/// The cam and a flat-faced translating follower at one cam angle.
template <typename T>
struct FlatFacePoint {
  T theta;                ///< cam angle [rad]
  T s, ds, d2s;           ///< S(θ) [mm] and its θ-derivatives [mm/rad^k]
  Vec2<T> contact;        ///< contact point A on the cam profile [mm]
  T contact_offset;       ///< where A lies on the face, from the follower's axis: S' [mm]
  T radius_of_curvature;  ///< ρ = r_b + S + S'' [mm]; > 0 convex, ≤ 0 a cusp
};

/// The flat-faced follower's contact at cam angle theta [rad] on a cam of base radius r_b [mm].
template <typename T>
FlatFacePoint<T> EvaluateFlatFaced(const motion::MotionProgram<T>& program, const T& base_radius, const T& theta) {
  FlatFacePoint<T> p;
  const motion::Svaj<T> m = program.Evaluate(theta);
  p.theta = theta;
  p.s = m.s;
  p.ds = m.v;
  p.d2s = m.a;
  const Vec2<T> u = U(theta);
  p.contact = (base_radius + m.s) * u + m.v * Perp(u);
  p.contact_offset = m.v;
  p.radius_of_curvature = base_radius + m.s + m.a;
  return p;
}

/// The cycle of a flat-faced follower on n uniform cam angles: the profile's smallest radius of
/// curvature (and where), and how far the contact runs each side of the follower's axis (the face
/// must reach both: width needed = max_offset − min_offset, without any margin).
struct FlatFaceCycle {
  double min_radius_of_curvature_mm = 0, at_cam_angle_deg = 0;
  double max_offset_mm = 0, min_offset_mm = 0;
  double face_width_needed_mm() const { return max_offset_mm - min_offset_mm; }
};

inline FlatFaceCycle SummarizeFlatFaced(const motion::MotionProgram<double>& program, double base_radius, int n) {
  FlatFaceCycle c;
  for (int i = 0; i < n; ++i) {
    const double th = 2 * kPi * i / n;
    const FlatFacePoint<double> p = EvaluateFlatFaced(program, base_radius, th);
    if (i == 0 || p.radius_of_curvature < c.min_radius_of_curvature_mm)
      c.min_radius_of_curvature_mm = p.radius_of_curvature, c.at_cam_angle_deg = 360.0 * i / n;
    c.max_offset_mm = i == 0 ? p.contact_offset : std::max(c.max_offset_mm, p.contact_offset);
    c.min_offset_mm = i == 0 ? p.contact_offset : std::min(c.min_offset_mm, p.contact_offset);
  }
  return c;
}

/// Loads at one point of a flat-faced translating follower at speed omega [rad/s]: the contact force
/// is F_y (φ = 0), the camshaft torque F_y S' [N·mm] (derivation above).
template <typename T>
CamLoad<T> FlatFaceLoadAt(const FlatFacePoint<T>& p, const FollowerLoads& f, const T& omega) {
  CamLoad<T> out;
  out.axial_force = FollowerAxialForce(f, p.s, p.d2s, omega);
  out.contact_force = out.axial_force;
  out.camshaft_torque = out.axial_force * p.contact_offset;
  return out;
}

/// The speed [rad/s] at which the flat face first leaves the cam (as JumpSpeed: φ = 0 does not
/// change where F_y = 0).
inline double JumpSpeed(const std::vector<FlatFacePoint<double>>& points, const FollowerLoads& f) {
  return JumpSpeedOver(points, f);
}

/// Peak Hertz pressure between the flat face and the cam [MPa] (a plane on a cylinder of radius ρ,
/// line contact over face_width_mm along the camshaft axis): 0 for a force ≤ 0 (no contact); NaN
/// where ρ ≤ 0 (a cusp: no smooth contact).
inline double FlatFaceContactStress(const FlatFacePoint<double>& p, double force_N, double face_width_mm,
                                    double composite_modulus_MPa) {
  if (!(force_N > 0.0)) return 0.0;
  if (!(p.radius_of_curvature > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return contact::LineContactPeakPressure(force_N, face_width_mm, p.radius_of_curvature, composite_modulus_MPa);
}

/// Feasibility of a flat-faced follower's program over angle_steps cam angles: the first angle where
/// the follower goes inside the base circle (S < −1e-9 r_b), as CheckDesign's (InsideBaseCircleIssue).
/// The flat face cannot jam (φ = 0); a cusp (ρ ≤ 0) is a result, not an input error.
inline std::vector<DesignIssue> CheckFlatFaced(const motion::MotionProgram<double>& program, double base_radius,
                                               int angle_steps) {
  for (int i = 0; i < angle_steps; ++i) {
    const double theta = 2 * kPi * i / angle_steps;
    const double s = program.Evaluate(theta).s;
    if (s < -1e-9 * base_radius) return {InsideBaseCircleIssue(s, theta, false)};
  }
  return {};
}

}  // namespace camopt::disc_cam
