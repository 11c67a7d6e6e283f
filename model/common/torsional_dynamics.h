// Torsional dynamics of a reducer: a lumped two-inertia model with a time-varying mesh stiffness,
// independent of the reducer type (the cycloid and the lobe cam reducer tabulate their own mesh
// stiffness from their loaded contact and hand it over).
//
// The model is the standard two-inertia mesh model of gear dynamics with parametric (time-varying)
// mesh stiffness and the static transmission error as the excitation (Özgüven & Houser,
// "Mathematical models used in gear dynamics", J. Sound Vib. 121 (1988), the single-mesh torsional
// model, with the mesh stiffness and the static transmission error as functions of the mesh
// position; Kahraman & Singh, "Non-linear dynamics of a spur gear pair", J. Sound Vib. 142 (1990),
// for the time-varying stiffness). For a cycloid or cam reducer the "mesh" is every loaded
// roller-tooth contact of one stage acting together, as its LTCA gives them.
// Everything is referred to the output shaft:
//
//   u₁ = θ_in/i − Ω t/i        the input inertia's deviation from the nominal motion, referred
//   u₂ = θ_out − Ω t/i         the output inertia's deviation
//   δ  = u₁ − u₂               the mesh's dynamic transmission error (output side, rad)
//   θ  = Ω t                   the nominal crank (input) angle that the mesh tables are read at
//
//   J₁' = J_in i²,  k_s' = k_s i²  (input inertia and input shaft stiffness referred to the output)
//
//   mesh torque    T_m = T_ref + k(θ) (δ − δ_s(θ)) + c_m δ̇                               (1)
//   input          J₁' ü₁ = T_drive − T_m,  T_drive = i T_motor (no input shaft)           (2)
//                                            T_drive = −k_s' u₁ − c_s u̇₁ (motor at Ω t
//                                                      through the input shaft)
//   output         J₂ ü₂ = T_m − T_L                                                         (3)
//
// k(θ) is the tangent mesh stiffness dT/dδ of the loaded contact at the reference torque T_ref and
// δ_s(θ) the static (loaded) transmission error there: (1) is the contact's torque linearised about
// its quasi-static loaded state at each crank angle, so that at low speed δ → δ_s and T_m → T_ref.
// Both tables are periodic over one mesh period (uniform samples, linear interpolation). Damping
// is viscous with a ratio ζ of the mean-stiffness modes: c_m = 2ζ √(k̄ μ), μ = J₁'J₂/(J₁' + J₂),
// and c_s = 2ζ √(k_s' J₁').
//
// Linearised modes (mean stiffness k̄): M = diag(J₁', J₂), K = [[k̄ + k_s', −k̄], [−k̄, k̄]],
// K φ = ω² M φ. Without input shaft the pair is free (a rigid-body mode at 0 Hz, dropped) and
// ω² = k̄ (1/J₁' + 1/J₂).
//
// Periodic steady state: (1)–(3) are linear with T-periodic coefficients (T = mesh period / Ω),
// so the state after one period is x(T) = Φ x(0) + p (Φ the monodromy matrix, p the response from
// rest); the periodic solution is x₀ = (I − Φ)⁻¹ p (shooting), stable when every Floquet
// multiplier (eigenvalue of Φ) lies inside the unit circle (Floquet theory: Nayfeh & Mook,
// Nonlinear Oscillations, 1979, §5.2). Φ's columns are integrated with the
// forcing off, p with it on, each over one period with CVODE (error-controlled BDF); the periodic
// solution is then integrated once more from x₀ and its residual |x(T) − x₀| reported. Without
// input shaft the free pair is reduced to δ alone (motor torque balancing the load, i T_motor =
// T_L: the rigid-body motion does not change and does not enter δ).
#pragma once

#include <array>
#include <complex>
#include <string>
#include <vector>

namespace camopt::torsion {

/// The lumped model (all torques and stiffnesses at the output side unless named input).
struct TorsionalModel {
  double input_inertia_kgm2 = 0;   ///< J_in, on the input (crank) shaft
  double output_inertia_kgm2 = 0;  ///< J₂ = J_out
  double ratio = 1;                ///< i, input turns per output turn (> 0)
  /// k_s, input shaft (motor to input inertia) [N·m/rad at the input]; 0: driven by a constant
  /// motor torque directly (free pair).
  double input_shaft_stiffness_Nm_per_rad = 0;
  double damping_ratio = 0.02;  ///< ζ
  double mesh_period_rad = 0;   ///< crank angle of one mesh period (the tables' period)
  std::vector<double> mesh_stiffness_Nm_per_rad;  ///< k(θ) at θ_k = k · period / N, k = 0 … N−1
  std::vector<double> static_te_rad;              ///< δ_s(θ) at the same angles (empty: 0)
  double reference_torque_Nm = 0;  ///< T_ref, the mesh torque at δ = δ_s
  double load_torque_Nm = 0;       ///< T_L on the output
};

/// k(θ) or δ_s(θ): periodic linear interpolation of uniform samples over `period`.
double PeriodicLinear(const std::vector<double>& values, double period, double angle);

/// Mean of the samples (the mean of the periodic linear interpolant).
double MeanOf(const std::vector<double>& values);

/// The mean-stiffness modes: frequencies [Hz] ascending, rigid-body mode dropped; each shape
/// {u₁ (input, referred to the output), u₂ (output)} with its largest |component| = +1.
struct Modes {
  std::vector<double> frequencies_Hz;
  std::vector<std::array<double, 2>> shapes;
  double mean_stiffness_Nm_per_rad = 0;
  double mesh_damping_Nms_per_rad = 0, shaft_damping_Nms_per_rad = 0;  ///< c_m, c_s (output side)
};
/// @throws std::invalid_argument for non-positive inertias, ratio or mean stiffness.
Modes LinearModes(const TorsionalModel& m);

/// The periodic steady state at one input speed.
struct SteadyState {
  double input_speed_rpm = 0;
  double mesh_frequency_Hz = 0;          ///< Ω / mesh period
  bool stable = true;                     ///< every Floquet multiplier |λ| < 1
  double max_floquet_multiplier = 0;     ///< max |λ|
  double te_peak_to_peak_rad = 0;        ///< p-p of δ over one period
  double te_mean_rad = 0;                ///< mean of δ over the samples
  double max_mesh_torque_Nm = 0, min_mesh_torque_Nm = 0;
  double overload_factor = 0;            ///< max T_m / T_ref
  /// |x(T) − x₀| / max |x| of the periodic solution integrated once more (each state scaled).
  double periodicity_residual = 0;
  /// |p-p at all samples − p-p at every other sample|, the sampling error estimate of the p-p and
  /// of the overload factor (same units).
  double te_sampling_error_rad = 0, overload_sampling_error = 0;
  long steps = 0;  ///< CVODE steps, all integrations
};

struct IntegrationOptions {
  double relative_tolerance = 1e-10;
  /// samples of the periodic solution per mesh period (besides the solver's steps)
  int samples_per_period = 128;
  long max_steps = 5000000;
};

/// @throws std::invalid_argument for a bad model or speed; std::runtime_error when CVODE fails.
SteadyState PeriodicSteadyState(const TorsionalModel& m, double input_speed_rpm, const IntegrationOptions& o = {});

/// A transient from a given state: y = {u₁, u₂, u̇₁, u̇₂} at t = 0 (output side), with the motor
/// torque i T_motor = motor_torque_Nm (no input shaft) and the load T_L of the model applied
/// from t = 0; the states at `times` (ascending, >= 0).
struct TransientSample {
  double t = 0;
  std::array<double, 4> y{};
  double mesh_torque_Nm = 0;
};
std::vector<TransientSample> Transient(const TorsionalModel& m, double input_speed_rpm, std::array<double, 4> y0,
                                       double motor_torque_Nm, const std::vector<double>& times,
                                       const IntegrationOptions& o = {});

/// Input speeds [rpm] at which order h of the mesh frequency equals a natural frequency:
/// h · (n/60) · (2π / mesh period) = f_j, for h = 1 … harmonics, within [lo, hi]; ascending, each
/// with its order and mode index (0-based); `mesh` is left 0 for the caller.
struct ResonanceSpeed {
  double rpm = 0;
  int order = 1, mode = 0, mesh = 0;
  double frequency_Hz = 0;
};
std::vector<ResonanceSpeed> ResonanceSpeeds(const Modes& modes, double mesh_period_rad, int harmonics, double lo_rpm,
                                            double hi_rpm);

}  // namespace camopt::torsion
