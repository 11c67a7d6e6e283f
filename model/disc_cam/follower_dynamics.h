// The dynamic response of a disc cam's translating follower: one degree of freedom, the follower's
// lumped mass m on its own stiffness k_f between the roller and the mass, held down by the return
// spring k_s with its preload (Norton, Cam Design and Manufacturing Handbook, ch. 10, the
// single-DOF lumped model; Koster's one-mass model). The cam imposes the roller's position S(θ),
// θ = ω t, as long as the follower's spring pushes the roller onto it:
//   in contact   m ẍ = F_a − k_s x − F₀ − P − W,   F_a = k_f (S − x) + c (Ṡ − ẋ) > 0
//   separated    m ẍ = −k_s x − F₀ − P − W           (the roller rides on the mass, F_a = 0)
// x the mass's displacement [mm] (x = S − F/k_f in contact), F_a the axial force at the roller,
// c = 2ζ √(m (k_f + k_s)) the follower's damping (ζ of its mode in contact). Contact is lost where
// F_a falls to 0 and comes back where the mass returns to the cam (x = S); both are located as
// events and the solver restarted there. The normal contact force is F_a / cos φ (kinetostatics.h);
// as k_f → ∞, F_a tends to kinetostatics.h's F_y = m S''ω² + k_s S + F₀ + P + W.
// Units: mm, N, kg, s.
//
// An oscillating follower's arm (roller, knife edge or flat face on an arm pivoted at O₃) is the same
// single-DOF lumped model written about the pivot (Norton, Cam Design and Manufacturing Handbook,
// ch. 10, the lumped model applied to the rotating arm): the cam imposes the arm angle ψ_c(θ) (the
// swing S(θ) from the base circle, rad) at the contact; the follower train's torsional stiffness k_f
// [N·m/rad] lies between it and the arm's inertia J [kg·m²] about the pivot, held by the return
// spring k [N·m/rad] with its moment M₀ on the base circle and a constant moment M_e:
//   in contact   J ψ̈ = M_a − k ψ − M₀ − M_e,   M_a = k_f (ψ_c − ψ) + c (ψ̇_c − ψ̇) > 0
//   separated    J ψ̈ = −k ψ − M₀ − M_e
// c = 2ζ √(J (k_f + k)). It is the translating equation with (m, x, S, k_s, F₀ + P + W, F_a) ↔
// (J, ψ, ψ_c, k, M₀ + M_e, M_a), solved by the same integrator (SimulateArm maps it); as k_f → ∞,
// M_a tends to kinetostatics.h's ArmMoment, J S'' ω² + k S + M₀ + M_e. The normal contact force at
// the cam is M_a over the lever arm of the normal about the pivot (n · dC/dξ for a roller,
// OscillatingRollerLoadAt; ℓ for a flat face, oscillating_flat_faced.h), which the study applies.
#pragma once

#include <string>
#include <vector>

#include "model/disc_cam/kinetostatics.h"
#include "model/motion/motion_program.h"

namespace camopt::disc_cam {

struct FollowerDynamicsInput {
  motion::MotionProgram<double> motion;  ///< S(θ) of the roller centre [mm]
  FollowerLoads loads;                   ///< m, k_s, F₀, P, W (kinetostatics.h)
  double follower_stiffness_N_per_mm = 0.0;  ///< k_f > 0
  double damping_ratio = 0.0;                ///< ζ ≥ 0 of the follower's mode in contact
  double speed_rad_s = 0.0;                  ///< ω > 0
  /// Revolutions simulated from static equilibrium on the cam at θ = 0; the results are those of
  /// the last one (the start transient decays with ζ; without damping it stays).
  int revolutions = 3;
  double relative_tolerance = 1e-9;   ///< CVODE's local error control
  double absolute_tolerance = 1e-9;   ///< [mm, mm/s] on the deflection x − S and its rate
  long max_steps = 5000000;           ///< accepted solver steps, at most (std::runtime_error past it)
  int samples = 720;                  ///< samples of the last revolution for plots and tables
};

struct FollowerDynamicsSample {
  double cam_angle_deg;           ///< within the last revolution, [0, 360)
  double cam_follower_mm;         ///< S, imposed by the cam
  double follower_mm;             ///< x, the mass
  double axial_force_N;           ///< F_a (0 while separated)
  double kinetostatic_force_N;    ///< F_y of the rigid follower at the same angle
};

/// The last revolution's extremes; the peaks are taken at every solver step, its midpoint and
/// every contact event, and refined inside a step by golden section on the dense output.
struct FollowerDynamicsResult {
  double natural_frequency_Hz = 0.0;  ///< √((k_f + k_s)/m) / 2π, the mode in contact
  double min_axial_force_N = 0.0, min_axial_force_cam_angle_deg = 0.0;
  double max_axial_force_N = 0.0, max_axial_force_cam_angle_deg = 0.0;
  bool separates = false;                 ///< contact lost somewhere in the last revolution
  double first_separation_cam_angle_deg = 0.0;
  /// The largest |x − x_s| over the dwells of the last revolution, x_s = (k_f S − F₀ − P − W)/(k_f + k_s)
  /// the mass's static position there: the vibration a rise leaves behind [mm] (0: no dwell).
  double residual_vibration_mm = 0.0, residual_vibration_cam_angle_deg = 0.0;
  std::vector<FollowerDynamicsSample> samples;
  long steps = 0;
  int events = 0;  ///< contact losses and returns over the whole run
};

/// Integrates the follower over `revolutions` turns with CVODE (BDF, error control, contact events).
/// @throws std::invalid_argument for inputs out of range, std::runtime_error when the run needs
/// more than max_steps steps or the tolerances cannot be met.
FollowerDynamicsResult SimulateFollower(const FollowerDynamicsInput& in);

/// The lowest speed at which the dynamic follower leaves the cam in its last simulated revolution.
struct DynamicJumpSpeed {
  bool found = false;          ///< separation seen at a scanned speed ≤ upper_rad_s
  double speed_rad_s = 0.0;    ///< the bracket's upper end: separates there (found)
  double lower_rad_s = 0.0;    ///< the bracket's lower end: holds there (and at every scanned speed below)
  double scan_step_rad_s = 0.0;
  int runs = 0;                ///< simulations
};

/// Scans speeds k·upper/scan_steps (k = 1 … scan_steps) upward with in's follower (in.speed_rad_s
/// ignored), stops at the first that separates and bisects between it and the speed below until
/// the bracket is within relative_width of its upper end. The answer bounds the first separation
/// from above, to relative_width, when separation sets in at one speed and stays above it; a band
/// of separation narrower than the scan step (a resonance between two scanned speeds) can be missed.
/// @throws as SimulateFollower.
DynamicJumpSpeed FindDynamicJumpSpeed(FollowerDynamicsInput in, double upper_rad_s, int scan_steps = 30,
                                      double relative_width = 1e-3);

/// An oscillating follower's arm on the follower train's torsional stiffness (equations above).
struct ArmDynamicsInput {
  motion::MotionProgram<double> motion;  ///< ψ_c(θ), the arm's swing the cam imposes [rad]
  ArmLoads loads;                        ///< J, k, M₀, M_e (kinetostatics.h)
  double arm_stiffness_N_m_per_rad = 0.0;  ///< k_f > 0
  double damping_ratio = 0.0;              ///< ζ ≥ 0 of the arm's mode in contact
  double speed_rad_s = 0.0;                ///< ω > 0
  int revolutions = 3;                     ///< as FollowerDynamicsInput::revolutions
  double relative_tolerance = 1e-9;
  double absolute_tolerance = 1e-10;  ///< [rad, rad/s] on ψ − ψ_c and its rate
  long max_steps = 5000000;
  int samples = 720;
};

struct ArmDynamicsSample {
  double cam_angle_deg;            ///< within the last revolution, [0, 360)
  double cam_arm_rad;              ///< ψ_c, imposed by the cam
  double arm_rad;                  ///< ψ, the arm's inertia
  double contact_moment_N_m;       ///< M_a (0 while separated)
  double kinetostatic_moment_N_m;  ///< ArmMoment of the rigid arm at the same angle
};

/// The last revolution's extremes, found as FollowerDynamicsResult's.
struct ArmDynamicsResult {
  double natural_frequency_Hz = 0.0;  ///< √((k_f + k)/J) / 2π
  double min_contact_moment_N_m = 0.0, min_contact_moment_cam_angle_deg = 0.0;
  double max_contact_moment_N_m = 0.0, max_contact_moment_cam_angle_deg = 0.0;
  bool separates = false;
  double first_separation_cam_angle_deg = 0.0;
  /// The largest |ψ − ψ_s| over the dwells, ψ_s = (k_f ψ_c − M₀ − M_e)/(k_f + k) [rad].
  double residual_vibration_rad = 0.0, residual_vibration_cam_angle_deg = 0.0;
  std::vector<ArmDynamicsSample> samples;
  long steps = 0;
  int events = 0;
};

/// The translating follower that is the arm's equation (the correspondence above): m = 10³ J [kg]
/// so that m ẍ[mm/s²]·10⁻³ = J ψ̈, k_s = k, F₀ = M₀, P = M_e, W = 0, k_f = the arm's.
FollowerDynamicsInput ArmAsFollower(const ArmDynamicsInput& in);

/// Integrates the arm (SimulateFollower on ArmAsFollower). @throws as SimulateFollower.
ArmDynamicsResult SimulateArm(const ArmDynamicsInput& in);

/// The arm's dynamic jump speed: FindDynamicJumpSpeed on ArmAsFollower (in.speed_rad_s ignored).
DynamicJumpSpeed FindArmDynamicJumpSpeed(const ArmDynamicsInput& in, double upper_rad_s, int scan_steps = 30,
                                         double relative_width = 1e-3);

}  // namespace camopt::disc_cam
