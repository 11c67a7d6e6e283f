// The smallest base circle of a disc cam with an offset translating or an oscillating roller
// (or knife-edge: the roller model with r_f = 0, its profile the pitch curve) follower, for a given motion program, under the limits of the disc_cam verdict (docs/disc_cam.md
// "Limits and verdict").
//
// Variables (any subset; the others keep the study's values): base_circle_radius_mm r_b (always a
// variable: it is the objective), roller_radius_mm r_f, and offset_mm e (translating) or
// pivot_distance_mm f = O₂O₃ and arm_length_mm l = O₃C (oscillating; Rzine et al. eq. 11).
// Objective: minimise r_b.
//
// Constraint rows over N uniformly sampled cam angles θᵢ = 2π i/N (model/disc_cam/disc_cam.h over
// ceres::Jet, so every row has its exact first derivative):
//   kDiscCamPressureRise    −α_rise ≤ φ(θᵢ) ≤ α_rise at every sample where the follower rises or
//                           dwells (S' ≥ 0), φ from Rzine et al. eq. (3), or eq. (12) for an
//                           oscillating follower [deg];
//   kDiscCamPressureReturn  −α_return ≤ φ(θᵢ) ≤ α_return where it returns (S' < 0). The two blocks
//                           are the disc_cam verdict's two limits, one row per sample
//                           (epigraph rows, not a soft max). Which sample is rise or return
//                           depends on the motion program only, not on the design.
//   kDiscCamCurvature       κ(θᵢ)·(r_f + m) ≤ 1: the pitch curve's convex radius 1/κ at least
//                           r_f + m, i.e. the profile's convex radius ρ_pitch − r_f at least the
//                           margin m (Norton, Cam Design and Manufacturing Handbook §7.7: undercut
//                           where ρ_pitch < r_f); where κ ≤ 0 (concave) the row holds, as the
//                           verdict says. Smooth through inflections, where 1/κ is not.
//                           With the default margin (the roller radius) m = r_f moves with r_f.
//   kDiscCamStress          F_c E*/(π w s²) − R' ≤ 0 [mm], with F_c the kinetostatic contact force
//                           (model/disc_cam/kinetostatics.h: CamLoadAt translating,
//                           OscillatingRollerLoadAt oscillating) and R' = r_f (1 − r_f κ): for R' > 0
//                           and F_c > 0 the same as the Hertz peak p₀ = sqrt(F_c E*/(π w R')) ≤ s
//                           (Johnson, Contact Mechanics eq. 4.45), without the division by R'
//                           (R' ≤ 0 under load, an undercut profile, breaks the row). Only with a
//                           contact-stress limit.
// A design outside the geometry (|e| ≥ r_b + r_f, or for an oscillating follower an arm that cannot
// reach the base circle, |f − l| < r_b + r_f < f + l failing, or that leaves (0, π) from O₃O₂ over the
// cycle) gives finite rows far beyond their limits with zero derivatives (SLSQP's line search backs
// off). The contact-stress rows need the follower's loads: a translating follower's, or an
// oscillating follower's arm loads (model/disc_cam/kinetostatics.h).
//
// Verification (objectives/verification.h, docs/optimization.md): the fast rows sample N angles;
// the accurate model re-evaluates the design on accurate_factor·N angles and refines every local
// peak there within 1% of the largest by golden-section search on the continuous functions (to
// 1e-12 rad), so the accurate value is the cycle maximum itself; its estimated error is the
// change from the dense grid's maximum to the refined one (the refinement's own error is far
// below it). While an accurate value is beyond its limit, the fast limit is tightened by the
// excess (plus 2e-7 of the limit; the first solve is given limits 2e-7 inside the study's, as the
// solvers meet rows to about 1e-7 of their scale) and the problem solved again from the last design, until the
// accurate value itself is within the limit or verify_rounds is spent.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "model/disc_cam/disc_cam.h"
#include "model/disc_cam/flat_faced.h"
#include "model/disc_cam/kinetostatics.h"
#include "objectives/problem.h"
#include "objectives/verification.h"
#include "optimizers/solver.h"
#include "sizing/limit_slope.h"

namespace camopt::sizing {
// The sizing loops speak the objectives' vocabulary (problems, limits, the verification contract).
using namespace camopt::objectives;

inline constexpr const char* kDiscCamBaseCircle = "base_circle_radius_mm";
inline constexpr const char* kDiscCamPressureRise = "pressure_angle_rise_deg";
inline constexpr const char* kDiscCamPressureReturn = "pressure_angle_return_deg";
inline constexpr const char* kDiscCamCurvature = "pitch_curvature_ratio";
inline constexpr const char* kDiscCamStress = "contact_stress_row_mm";

enum class DiscCamSizingVariable { kBaseCircle, kOffset, kRollerRadius, kPivotDistance, kArmLength };
/// "base_circle_radius_mm", "offset_mm", "roller_radius_mm", "pivot_distance_mm", "arm_length_mm".
std::string DiscCamSizingVariableName(DiscCamSizingVariable v);

/// The study's limits (the disc_cam "limits" with their defaults applied).
struct DiscCamSizingLimits {
  double pressure_angle_deg = 30.0;     ///< on the rise and on the return
  double radius_margin_mm = 0.0;        ///< ρ_pitch,min − r_f ≥ this (when not following the roller)
  bool radius_margin_is_roller = false; ///< the default: the margin is the roller radius (moves with it)
  double radius_margin_shift_mm = 0.0;  ///< added to either margin (a moved limit, for its cost)
  double contact_stress_MPa = kInf;     ///< peak Hertz stress; needs DiscCamSizingSpec::stress
};

/// What the contact stress needs: the kinetostatic loads at one speed (a translating follower's
/// loads, or an oscillating follower's arm loads), the face width, E*.
struct DiscCamStressModel {
  disc_cam::FollowerLoads loads;           ///< translating
  std::optional<disc_cam::ArmLoads> arm;   ///< oscillating: the arm's (OscillatingRollerLoadAt)
  double omega_rad_per_s = 0.0;
  double face_width_mm = 0.0;
  double composite_modulus_MPa = 0.0;
};

struct DiscCamSizingSpec {
  disc_cam::DiscCam cam;  ///< a roller follower: the fixed values and the starts
  /// A translating flat-faced follower (model/disc_cam/flat_faced.h; cam holds its base circle and
  /// motion): the base circle is the only variable, the pressure angle is 0 (its rows are 0), the
  /// curvature rows are 1 + (m − ρ)/max(1, |m|) ≤ 1 with ρ = r_b + S + S'' (ρ ≥ the margin m, linear in
  /// r_b), and the stress rows F_y E*/(π w s²) − ρ ≤ 0 (a plane on the profile's osculating cylinder).
  bool flat_face = false;
  /// The variables (base circle first, then any of offset or pivot distance and arm length, and
  /// roller radius), with bounds, start
  /// (within the bounds) and scale in their own units [mm].
  std::vector<DiscCamSizingVariable> which;
  std::vector<Variable> variables;
  DiscCamSizingLimits limits;
  std::optional<DiscCamStressModel> stress;  ///< the loads; required by a finite stress limit
  int angle_steps = 360;                     ///< N of the fast rows
  int accurate_factor = 8;                   ///< the accurate model's grid is accurate_factor·N
};

/// The limits the solver is given (the study's, tightened by the verification loop).
struct DiscCamFastLimits {
  double rise_deg = 30.0, return_deg = 30.0;
  double radius_margin_extra_mm = 0.0;  ///< added to the study's margin
  double contact_stress_MPa = kInf;
};
DiscCamFastLimits StudyFastLimits(const DiscCamSizingSpec& spec);

/// The design that the variables x (in the order of spec.variables) give.
disc_cam::DiscCam DiscCamDesign(const DiscCamSizingSpec& spec, const std::vector<double>& x);

/// The radius margin the design must keep [mm]: the study's, or its roller radius by default.
double RadiusMarginOf(const DiscCamSizingSpec& spec, const disc_cam::DiscCam& cam);

/// The sizing problem with the fast limits. @throws std::invalid_argument for a spec it cannot
/// build (no base-circle variable, a stress limit without the follower's loads, an
/// offset variable of an oscillating or a pivot or arm variable of a translating follower).
Problem DiscCamSizingProblem(const DiscCamSizingSpec& spec, const DiscCamFastLimits& fast);

/// The cycle maxima of one design over `steps` uniform angles, optionally with each peak refined.
struct DiscCamCycleValues {
  double max_pressure_rise_deg = 0.0, at_rise_deg = 0.0;  ///< |φ| where S' ≥ 0
  bool has_return = false;
  double max_pressure_return_deg = 0.0, at_return_deg = 0.0;  ///< |φ| where S' < 0
  double max_pitch_curvature_per_mm = 0.0, at_curvature_deg = 0.0;
  /// The profile's smallest convex radius 1/κ_max − r_f [mm] (+∞ when the pitch curve has no convex part).
  double min_radius_of_curvature_mm = kInf;
  bool stress_evaluated = false;
  double max_contact_stress_MPa = 0.0, at_stress_deg = 0.0;  ///< NaN: loaded on an undercut profile
  double max_radial_dimension_mm = 0.0;
};
DiscCamCycleValues DiscCamCycle(const DiscCamSizingSpec& spec, const disc_cam::DiscCam& cam, int steps,
                                bool refine);

/// The design's fast values (N angles), the dense grid's (accurate_factor·N) and the accurate ones
/// (the dense grid's peaks refined), and the study's limits checked against the accurate values.
struct DiscCamAccurateCheck {
  DiscCamCycleValues fast, dense, accurate;
  std::string model;
  std::vector<VerifiedLimit> checks;
};
DiscCamAccurateCheck CheckDiscCamDesign(const DiscCamSizingSpec& spec, const disc_cam::DiscCam& cam);

struct DiscCamMinSizeOptions {
  optimizers::SolverOptions solver;  ///< backend, tolerances, budget of each solve
  int verify_rounds = 4;             ///< tightening rounds of the verification loop
};

struct DiscCamMinSizeOutcome {
  bool converged = false;  ///< the last solve converged (KKT test met, rows within tolerance)
  bool verified = false;   ///< every limit holds on the accurate model
  std::vector<double> x;   ///< the reported design's variables (empty: none)
  disc_cam::DiscCam cam;
  optimizers::SolverResult result;  ///< the last solve (evaluation counts summed over all)
  DiscCamAccurateCheck check;       ///< at the reported design
  Verification verification;
  DiscCamFastLimits fast;           ///< the fast limits of the last solve
  /// The study's limits that bind at the answer (accurate value within 0.1% of the limit; the
  /// radius margin within 1e-3 mm), and d(r_b)/d(limit) [mm per unit of the limit] for each, by
  /// re-solving from the answer with the study's limit moved by ±0.5% (central difference), each
  /// re-solve verified and tightened as the answer was (the sampled rows' bias moves with the limit).
  std::vector<std::string> binding;
  std::map<std::string, double> limit_cost;
  /// The same re-solves with both sides kept (sizing/limit_slope.h): limit_cost is their slope.
  std::map<std::string, LimitSlope> limit_slope;
  std::vector<optimizers::SolverResult> starts;  ///< each start's first solve
  int rounds = 0;                                ///< solves after the first (tightening rounds)
};

/// @throws std::invalid_argument as DiscCamSizingProblem.
DiscCamMinSizeOutcome SolveDiscCamMinSize(const DiscCamSizingSpec& spec, const DiscCamMinSizeOptions& options);

}  // namespace camopt::sizing
