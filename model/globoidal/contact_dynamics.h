// Contact-force dynamics of the globoidal cam's turret (paper §4, eqs. 10–14): the Adams impact
// force F = K δ^e + step(δ, 0, 0, d, C_max) δ̇ between each roller and its flank of the rib, with
// K = (4/3) √R E* (eq. 11), 1/R = 1/R₁ + 1/R₂ (eq. 12) and 1/E* = (1−μ₁²)/E₁ + (1−μ₂²)/E₂
// (eq. 13). The cam turns at a prescribed speed; the turret is one rigid body on its axis
// (inertia J) with a constant load torque; its swing ψ is integrated by SUNDIALS CVODE (variable
// order, variable step, local error control by relative/absolute tolerances), with the contact
// onset and loss of each roller located as root-finding events where the force law switches.
//
// Penetration of roller j: the roller axis (at the contact arm l_c) is displaced from its
// kinematic position by l_c p (ψ − φ_i(θ)) along e_φ; the part of that along the contact normal
// n_j is the penetration, δ_j = l_c p (ψ − φ_i) (e_φ · n_j) (small deflection, geometry at the
// kinematic position). The force on the roller is −F_j n_j; its moment about the turret axis
// drives ψ. Decisions (docs/globoidal.md): no adhesion (F ≥ 0), zero backlash, contact at the
// roller middle l_c = R_e unless given.
//
// Units: mm, N, s; torque in N·mm, inertia in N·mm·s² (= 10⁻³ kg·m²).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/common/scalar.h"
#include "model/contact/hertz.h"
#include "model/globoidal/globoidal.h"

namespace camopt::globoidal {

/// Adams STEP(x, x0, h0, x1, h1): h0 below x0, h1 above x1, the cubic h0 + (h1−h0) s²(3 − 2s),
/// s = (x − x0)/(x1 − x0), between (C¹ at both ends, so the branch choice is continuous).
template <typename T>
T Step(const T& x, double x0, double h0, double x1, double h1) {
  if (Value(x) <= x0) return T(h0);
  if (Value(x) >= x1) return T(h1);
  const T s = (x - T(x0)) / T(x1 - x0);
  return T(h0) + T(h1 - h0) * s * s * (T(3.0) - T(2.0) * s);
}

/// Eqs. (11)–(12): K = (4/3) √R E*, 1/R = 1/R₁ + 1/R₂ [N/mm^1.5]. R₂ may be negative (concave).
/// E* (eq. 13) is camopt::CompositeModulus (model/common/material.h).
template <typename T>
T ContactStiffness(const T& r1, const T& r2, const T& e_star) {
  const T r = T(1.0) / (T(1.0) / r1 + T(1.0) / r2);
  return contact::PointContactStiffness(r, e_star);
}

/// The contact law of eq. (10) with the damping of eq. (14) while roller and rib are in contact,
/// K δ^e + step(δ, 0, 0, d, C_max) δ̇, extended smoothly past δ = 0 as −K |δ|^e (the damping term
/// is already 0 there). It is negative exactly where the contact carries no force, so its zero
/// is the switching surface of the force law: the dynamics locate contact onset and loss as its
/// roots and integrate this smooth law, or 0, on either side.
template <typename T>
T ContactLaw(const T& delta, const T& delta_rate, double stiffness, double exponent,
             double c_max, double depth) {
  using std::pow;
  const T elastic = Value(delta) >= 0.0 ? T(stiffness) * pow(delta, T(exponent))
                                        : -T(stiffness) * pow(-delta, T(exponent));
  return elastic + Step(delta, 0.0, 0.0, depth, c_max) * delta_rate;
}

/// Eq. (10) with the damping of eq. (14): F = K δ^e + step(δ, 0, 0, d, C_max) δ̇ for δ > 0, never
/// negative (no adhesion); 0 without penetration. The force is continuous in δ (both terms vanish
/// at δ = 0), so branching on the value of δ keeps it continuous.
template <typename T>
T ImpactForce(const T& delta, const T& delta_rate, double stiffness, double exponent,
              double c_max, double depth) {
  if (Value(delta) <= 0.0) return T(0.0);
  return PositivePart(ContactLaw(delta, delta_rate, stiffness, exponent, c_max, depth));
}

struct ContactMaterial {
  double cam_modulus_MPa = 206000.0, cam_poisson = 0.3;
  double roller_modulus_MPa = 206000.0, roller_poisson = 0.3;
  double exponent = 1.5;             ///< e of eq. (10)
  double max_damping_Ns_per_mm = 10.0;  ///< C_max of eq. (14)
  double penetration_depth_mm = 0.01;   ///< d of eq. (14)
  /// E* of cam against roller, eq. (13).
  double composite_modulus_MPa() const {
    return CompositeModulus(cam_modulus_MPa, cam_poisson, roller_modulus_MPa, roller_poisson);
  }
};

struct DynamicsInput {
  GloboidalCam<double> cam;
  ContactMaterial contact;
  double inertia_Nmms2 = 10.0;     ///< turret inertia J [N·mm·s²] (0.01 kg·m²)
  double load_torque_Nmm = 0.0;    ///< constant load on the turret, acting against direction p
  double cam_speed_rad_s = 0.0;    ///< ω (0 holds the cam still)
  double start_cam_angle_rad = 0.0;  ///< θ at t = 0: θ(t) = θ₀ + ω t
  double end_time_s = 0.1;
  /// CVODE's local error control on the state (ψ − φ_i, ψ̇ − φ_i' ω): relative tolerance, and
  /// the absolute tolerance [rad, rad/s] below which a component counts as zero.
  double relative_tolerance = 1e-8;
  double absolute_tolerance = 1e-10;
  double max_steps = 2e7;          ///< limit on accepted steps over the run (DynamicsError)
  /// Samples for plots/CSV every output_interval_s (interpolated by the solver's dense output);
  /// ≤ 0 keeps a sample at every accepted step and event. The peaks never depend on it.
  double output_interval_s = 0.0;
  double contact_arm_mm = -1.0;    ///< l_c; ≤ 0 means R_e
  bool start_static = true;        ///< start at the static deflection under the load at θ₀
  double initial_swing_rate_rad_s = 0.0;  ///< added to the kinematic rate at t = 0
};

struct DynamicsSample {
  double time_s, cam_angle_rad;
  double swing_rad, swing_rate_rad_s, swing_acc_rad_s2;      ///< ψ, ψ̇, ψ̈ (dynamic)
  double kin_swing_rad, kin_rate_rad_s, kin_acc_rad_s2;      ///< φ_i and its time derivatives
  double penetration_mm[2], force_N[2];                       ///< rollers 1 and 2
  double energy_Nmm;  ///< J ψ̇²/2 + Σ K δ^(e+1)/(e+1) (kinetic + elastic)
};

/// Extremes over the whole run, taken at every accepted solver step, at the midpoint of each step
/// (dense output) and at every contact event — never from the thinned samples.
struct DynamicsPeaks {
  double swing_rate_rad_s = 0, swing_acc_rad_s2 = 0;  ///< max |ψ̇|, max |ψ̈|
  double kin_rate_rad_s = 0, kin_acc_rad_s2 = 0;      ///< max |φ_i'ω|, max |φ_i''ω²|
  double force_N[2] = {0, 0};                          ///< max F per roller
  /// max Hertz line-contact pressure per roller [MPa]: p0 = √(F E*/(π m R)) with R the eq. (12)
  /// radius at that instant and m the roller length (QuasiStaticContactStress), and where it is
  double contact_stress_MPa[2] = {0, 0}, contact_stress_time_s[2] = {0, 0};
  double swing_deviation_rad = 0;                      ///< max |ψ − φ_i|
  double penetration_mm = 0;                           ///< max δ over both rollers
  double swing_acc_time_s = 0, force_time_s[2] = {0, 0};  ///< where those maxima are
};

struct DynamicsResult {
  std::vector<DynamicsSample> samples;
  DynamicsPeaks peaks;
  double stiffness[2] = {0, 0};  ///< K at θ₀ for rollers 1, 2 [N/mm^1.5] (for reference)
  long steps = 0;       ///< accepted solver steps
  long rhs_evaluations = 0;
  long error_test_failures = 0;
  int events = 0;       ///< contact onsets and losses located (each restarts the solver)
  std::vector<double> event_times_s;
  double smallest_step_s = 0, largest_step_s = 0;
};

/// An integration that cannot be completed with the given settings (too many steps, tolerance
/// out of reach, repeated error-test or convergence failures). what() says what to change;
/// setting() names the DynamicsInput field to change.
class DynamicsError : public std::runtime_error {
 public:
  DynamicsError(const std::string& setting, const std::string& message)
      : std::runtime_error(message), setting_(setting) {}
  const std::string& setting() const { return setting_; }

 private:
  std::string setting_;
};

/// The contact arm l_c [mm]: contact_arm_mm when given (> 0), else the roller middle R_e.
inline double ContactArm(const DynamicsInput& in) {
  return in.contact_arm_mm > 0.0 ? in.contact_arm_mm : in.cam.pitch_radius;
}

/// The longest step the solver may take [s]: 0.5° of cam rotation (1/200 of the run with the cam
/// held), so that a contact cannot open and close within one step unseen by the root finder.
/// A run needs at least end_time / MaxStep(in) steps.
inline double MaxStep(const DynamicsInput& in) {
  return in.cam_speed_rad_s > 0.0 ? (0.5 * kPi / 180.0) / in.cam_speed_rad_s : in.end_time_s / 200.0;
}

/// Contact stiffness of roller j at cam angle θ from the geometry (eq. 11 with R₁ = R and R₂
/// the working surface's radius across the roller at the contact arm).
double RollerStiffness(const DynamicsInput& in, int j, double theta);

/// Integrates the turret swing over [0, end_time] with CVODE. @throws std::invalid_argument for
/// bad inputs, DynamicsError when the integration cannot be completed, std::domain_error when
/// the contact becomes conformal (no Hertz radius).
DynamicsResult SimulateDynamics(const DynamicsInput& in);

/// Quasi-static force on the loaded roller: |J φ̈_i ω² + T_load| /(l_c cos α) [N], where α is
/// the pressure angle of the roller that carries the torque.
double QuasiStaticForce(const DynamicsInput& in, double theta);

/// Hertz peak pressure of the loaded roller under QuasiStaticForce [MPa], as a line contact along
/// the roller's length m: p0 = √(F E*/(π m R)) (Johnson, Contact Mechanics §4.2), R the eq. (12)
/// radius across the roller at the contact arm. The dynamics' own force law is the paper's point
/// contact (eq. 11); for the stress the roller is taken as touching along its generator, as the
/// working surface is its envelope (no edge stress concentration: a straight roller's ends).
double QuasiStaticContactStress(const DynamicsInput& in, double theta);

}  // namespace camopt::globoidal
