// Feasibility and cycle extremes of a globoidal cam design: the rollers fit (they end before the
// turret axis, stay off the cam axis, leave a rib between them), the swing program runs between
// the dead points, the contact arm lies on the roller, and the pressure angle stays below the jam
// limit. Returns DesignIssues (model/common/design_issue.h) on the cam's fields; a study maps them
// to the JSON paths of its inputs (studies/design_issue_paths.h).
//
// The cycle survey samples the surfaces on a uniform cam-angle grid plus 64 points inside every
// motion segment (so that a short segment is never stepped over), over roller 1 and 2 and
// axis_steps points of the roller axis in [l₂, l₁].
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "model/common/design_issue.h"
#include "model/common/scalar.h"
#include "model/globoidal/contact_dynamics.h"
#include "model/globoidal/globoidal.h"

namespace camopt::globoidal {

/// Pressure angle at which the turret is taken to jam [rad] (89°).
inline constexpr double kJamPressureAngle = 89.0 * (kPi / 180.0);
/// Pressure angle above which a study warns [rad] (45°, docs/globoidal.md "Pressure angle
/// warning"): the contact force exceeds √2 × the force that drives the turret and the side thrust
/// equals it; the design works but is close to the self-locking that kJamPressureAngle refuses.
inline constexpr double kHighPressureAngle = 45.0 * (kPi / 180.0);

/// Thickness of the rib between the two rollers at the turret-side end of the rollers (l = l₂):
/// 2 l₂ sin(β/2) − 2R [mm]; ≤ 0 when the rollers overlap.
template <typename T>
T RibThickness(const GloboidalCam<T>& cam) {
  using std::sin;
  return T(2.0) * RollerAxisLimits(cam).l2 * sin(cam.roller_angle / T(2.0)) -
         T(2.0) * cam.roller_radius;
}

/// The fit of the rollers (does not look at the motion program):
///   - "roller_length": l₂ = R_e − m/2 ≤ 0, the roller reaches past the turret axis; value m,
///     limit 2 R_e [mm];
///   - "center_distance": C ≤ l₁ + R, the rollers reach the cam axis; value C, limit l₁ + R [mm];
///   - "roller_angle": RibThickness ≤ 0, the rollers overlap; value 2 l₂ sin(β/2), limit 2R [mm].
std::vector<DesignIssue> CheckGeometry(const GloboidalCam<double>& cam);
/// "motion": the swing program runs from 0 to φ_f (eq. 7 places the dead points there; 3600
/// samples, 1e-9 rad below 0, 1e-6 rad at the top); value the sampled minimum (when below 0) or
/// maximum of φ_i, limit 0 or φ_f [rad].
std::vector<DesignIssue> CheckSwing(const GloboidalCam<double>& cam);
/// "contact_arm_mm": a given contact arm (contact_arm_mm > 0) lies in [l₂, l₁]; value l_c, limit
/// the bound it passes [mm].
std::vector<DesignIssue> CheckContactArm(const DynamicsInput& in);

/// An extreme over the survey samples: the first sample that reaches it.
struct Extreme {
  double value = 0.0;
  double cam_angle_rad = 0.0, axis_mm = 0.0;
  int roller = 1;
  bool set = false;
};

struct CycleSurvey {
  Extreme max_abs_pressure_angle;  ///< max |α| [rad]
  Extreme min_undercut_margin;     ///< min 1 − R κ₁ (≤ 0: undercut)
  Extreme min_offset_jacobian;     ///< min area ratio working/trajectory surface
  Extreme min_contact_radius;      ///< min eq. (12) radius at the contact arm [mm], where > 0
  bool conformal = false;          ///< the contact radius at the arm is ≤ 0 somewhere

  /// On the uniform grid θᵢ = 2π i/angle_steps, per roller (index j − 1): the roller angle φʲ
  /// [rad], the pressure angle at l₁ and at l₂ [rad], the contact radius at the contact arm [mm]
  /// (≤ 0 where conformal); and the smallest undercut margin over both rollers and the axis.
  struct Grid {
    std::array<std::vector<double>, 2> roller_angle, pressure_angle_at_l1, pressure_angle_at_l2,
        contact_radius;
    std::vector<double> min_undercut_margin;
  } grid;
};

/// Axis point k of axis_steps in [l₂, l₁] [mm].
inline double AxisGridPoint(const AxisLimits<double>& lim, int k, int axis_steps) {
  return lim.l2 + (lim.l1 - lim.l2) * k / (axis_steps - 1);
}

/// The cycle extremes on angle_steps uniform cam angles plus 64 per motion segment, both rollers,
/// axis_steps points on the roller axis, and the series on the uniform grid; the contact radius at
/// contact_arm_mm.
CycleSurvey SurveyCycle(const GloboidalCam<double>& cam, double contact_arm_mm, int angle_steps,
                        int axis_steps);

/// Every check in order: geometry (when it fails, nothing else is checked), swing, contact arm,
/// and the jam limit over the cycle survey of ContactArm(in) ("motion": max |α| ≥
/// kJamPressureAngle, the turret jams; value max |α|, limit kJamPressureAngle [rad], at the cam
/// angle where it is met).
std::vector<DesignIssue> CheckDesign(const DynamicsInput& in, int angle_steps, int axis_steps);

}  // namespace camopt::globoidal
