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

}  // namespace camopt::disc_cam
