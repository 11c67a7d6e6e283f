// The motion program of a disc cam as a design: the control values of B-spline segments
// (model/motion/motion_program.h) are the variables, the rest of the program, the segments' rises,
// cam angles and boundary values are fixed, and one objective of the follower's kinematics or
// dynamics is minimised under the disc_cam limits.
//
// Variables: the free control values c_i of each optimized segment (mm, or rad for an oscillating
// follower), and an epigraph variable t. A segment of degree p with control values c_0 … c_n on
// the clamped uniform knots starts at c_0 = 0 and ends at c_n = h (its rise); the first k + 1
// values fix its first k derivatives at the start (likewise at the end), so matching the
// neighbours' velocity (always) and acceleration (boundary.acceleration) fixes c_1 (, c_2) and
// c_{n−1} (, c_{n−2}) from the neighbours' values, solved on the basis' derivatives at u = 0 and
// u = 1; the values between are free. Everything the rows need is affine in them.
//
// Objective (minimise t, rows value ≤ t over the fast samples):
//   peak_acceleration   |S''(θ_i)| ≤ t at the samples inside the optimized segments [unit/rad²]
//   peak_jerk           |S'''(θ_i)| ≤ t [unit/rad³]
//   residual_vibration  A²_{j,n} ≤ t: A the free vibration's amplitude at the start of the dwell
//                       after optimized segment j (model/disc_cam/contact_response.h), at every
//                       speed n of the band [mm²]; reported as A [mm]
//   max_contact_force   F_a(θ_k)/cos φ(θ_k) ≤ t over a revolution at the study's speed: the
//                       follower's dynamic axial force (with a follower stiffness) or the
//                       kinetostatic F_y (kinetostatics.h), along the normal [N]
// Limit rows (each over the fast samples, all of the cycle):
//   pressure_angle_deg  −α ≤ φ(θ_i) ≤ α (rise and return alike: the disc_cam verdict's one limit)
//   radius_margin_mm    κ(θ_i)·(r_f + m) ≤ 1 (sizing/disc_cam_min_size.h kDiscCamCurvature)
//   stroke_mm           0 ≤ S(θ_i) ≤ stroke: a free spline neither dips below the base circle nor
//                       overshoots the stroke
//   contact_stress_MPa  F_c(θ_i) E*/(π w s²) − R'(θ_i) ≤ 0 with the kinetostatic contact force (a
//                       translating roller follower; sizing/disc_cam_min_size.h kDiscCamStress)
//   no_separation_up_to_rpm  F_a(θ_k; n) ≥ 0 at every step of the last revolution of the
//                       held-on follower at separation_speeds speeds n = n_max·j/K (j = 1 … K)
// The dynamic rows integrate the follower held on the cam by RK4 on a grid with ≥ 64 steps per
// natural period at the highest speed and ≥ 8 at the lowest (contact_response.h), their derivatives by forward-mode differentiation of those
// steps (the forward sensitivities of the ODE).
//
// Accurate model: the kinematic values on accurate_factor times the samples, every peak within 1% of
// the largest refined by golden-section search (as sizing/disc_cam_min_size.h); the dynamic values
// by follower_dynamics.h's CVODE run (error control 1e-10, contact events: a separation is seen,
// not assumed away), the residual amplitude fitted to the free response over the dwell by least
// squares, the contact force on the dense grid, separation at four times as many speeds. Each
// value's estimated error is the change from the dense to the refined value (kinematics), from the
// fast speeds to the dense ones (separation), or from CVODE at 1e-8 to 1e-10 (the response).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/disc_cam/contact_response.h"
#include "model/disc_cam/disc_cam.h"
#include "objectives/problem.h"
#include "objectives/verification.h"

namespace camopt::objectives {

enum class MotionObjective { kPeakAcceleration, kPeakJerk, kResidualVibration, kMaxContactForce };
/// "peak_acceleration", "peak_jerk", "residual_vibration", "max_contact_force".
std::string MotionObjectiveName(MotionObjective o);
/// The objective's unit as reported ("mm/rad^2", "mm", "N", …) for a follower unit ("mm"/"rad").
std::string MotionObjectiveUnit(MotionObjective o, const std::string& follower_unit);

/// A segment of the program whose shape is designed.
struct OptimizedSegment {
  int segment = 0;             ///< index in the program
  int degree = 5;              ///< p
  int control_points = 10;     ///< n + 1
  bool acceleration = true;    ///< match the neighbours' acceleration too (velocity always)
};

struct DiscCamMotionSpec {
  /// The start design: its optimized segments are B-splines (their start shape); every other
  /// value is fixed.
  disc_cam::DiscCam cam;
  std::vector<OptimizedSegment> segments;
  MotionObjective objective = MotionObjective::kPeakAcceleration;
  /// The follower's dynamics (a translating follower with a follower stiffness): needed by
  /// residual_vibration, no_separation_up_to_rpm, and the dynamic contact force.
  std::optional<disc_cam::ContactFollower> follower;
  /// Kinetostatic loads (max_contact_force without a follower stiffness).
  std::optional<disc_cam::FollowerLoads> loads;
  double speed_rpm = 0.0;                   ///< the study's cam speed
  std::vector<double> objective_speeds_rpm; ///< residual_vibration: the speeds of the band
  int revolutions = 3;                      ///< of every response, as follower_dynamics.h
  // Limits.
  double pressure_angle_deg = 30.0;
  double radius_margin_mm = 0.0;
  bool radius_margin_is_roller = false;
  std::optional<double> stroke_mm;
  std::optional<double> no_separation_up_to_rpm;
  /// The peak Hertz stress between roller and cam under the kinetostatic load at the study's speed
  /// (a translating roller follower with `loads`): rows F_c E*/(π w s²) − R' ≤ 0, R' the relative
  /// radius (sizing/disc_cam_min_size.h kDiscCamStress), so p₀ = √(F_c E*/(π w R')) ≤ s.
  std::optional<double> contact_stress_MPa;
  double face_width_mm = 0.0, composite_modulus_MPa = 0.0;
  int separation_speeds = 8;                ///< K
  int angle_steps = 720;                    ///< N of the fast rows (kinematics)
  int accurate_factor = 8;
};

/// RK4 steps a revolution of the dynamic rows: N, and at least 64 per natural period of the
/// follower at the rows' highest speed and 8 at their lowest (the separation rows' n_max/K).
int ContactStepsPerRevolution(const DiscCamMotionSpec& spec);

/// The free control values of the start design (the variables' starts, without t).
std::vector<double> StartControls(const DiscCamMotionSpec& spec);
/// The design with the free control values x (size: the free count; t not included).
disc_cam::DiscCam MotionDesign(const DiscCamMotionSpec& spec, const std::vector<double>& x);
/// The count of free control values; @throws std::invalid_argument when a segment has none.
int FreeControlCount(const DiscCamMotionSpec& spec);
/// The B-spline segment with control values c_0 … c_n (c_0 = 0, c_n = rise) for segment j of
/// spec at the free values `free` (in order), the boundary values fixed from the neighbours.
std::vector<double> ControlValues(const DiscCamMotionSpec& spec, size_t j, const std::vector<double>& free);

/// The fast limits the solver is given (the study's, tightened by the verification loop).
struct MotionFastLimits {
  double pressure_angle_deg = 30.0;
  double radius_margin_extra_mm = 0.0;
  double stroke_inset_mm = 0.0;
  double separation_margin_N = 0.0;
  double contact_stress_MPa = kInf;  ///< the fast rows' stress limit
  /// Speeds added to the no-separation rows by the verification loop: where the accurate check
  /// found the smallest contact force between the fast rows' speeds (an active set over speed).
  std::vector<double> extra_separation_rpm;
};

/// The problem: variables = free control values then t; objective t; rows as above.
Problem DiscCamMotionProblem(const DiscCamMotionSpec& spec, const MotionFastLimits& fast);

/// The objective's fast value at a design (the largest row value; residual_vibration: A, not A²).
double FastObjective(const DiscCamMotionSpec& spec, const disc_cam::DiscCam& cam);

/// The accurate model's values at one design.
struct MotionAccurate {
  double objective = 0.0, objective_error = 0.0, objective_fast = 0.0;
  double objective_at_deg = 0.0;  ///< where (kinematics, force) or the dwell's start (residual)
  std::string objective_where;
  std::vector<VerifiedLimit> checks;
  std::string model;  ///< in words
  /// Per dwell after an optimized segment and speed (residual_vibration): A [mm].
  struct Residual {
    int segment;
    double speed_rpm, amplitude_mm, fast_mm, error_mm;
  };
  std::vector<Residual> residuals;
  double lowest_separation_rpm = 0.0;  ///< 0: none seen up to no_separation_up_to_rpm
  double weakest_contact_rpm = 0.0;     ///< the speed of the smallest contact force (separation: the first)
};
/// objective_only: the objective alone (no limit checks), for the laws it is compared with.
MotionAccurate CheckMotionDesign(const DiscCamMotionSpec& spec, const disc_cam::DiscCam& cam,
                                 bool objective_only = false);

}  // namespace camopt::objectives
