// LCR transmission error and lost motion from manufacturing tolerances, and the compliant
// load-sharing model.
//
// The exact model at one input angle θ: the deviations (model/lcr/tolerance.h) give each roller's
// normal gap c_k from the exact geometry; the rollers are the compliant contacts of the stiffness
// model (model/rigidity/lcr_stiffness.h, Palmgren's line contact, one home), each closing by
// ψ a_k − c_k, so that which rollers touch — and how much each carries — is re-solved for every
// sample: interference preloads rollers, clearance leaves them out. With the input held and the
// output torque T (signed as in DeflectAtAngle), the fixed turret turns by ψ_A with g_A(ψ_A) = −ρT
// and the output turret by ψ_B with g_B(ψ_B) = T; the output angle δθ_o = ψ_B − ρ ψ_A.
// The transmission error is the output angle's change from the nominal reducer's at the same θ and
// torque: TE(θ) = δθ_o(θ; deviations) − δθ_o(θ; 0). Lost motion at θ: the output angle between
// +T_lm and −T_lm (the bearing clearance shifting the cam with the load's sense).
// Linearised: TE ≈ Σ_p S_p(θ) t_p with S_p from ceres::Jet through the same functions.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "model/common/tolerance_stats.h"
#include "model/lcr/cycle.h"
#include "model/lcr/forces.h"
#include "model/lcr/tolerance.h"
#include "model/rigidity/lcr_stiffness.h"

namespace camopt::lcr {

/// Tolerance bands: ± half-widths (uniform), the eccentric bearing's radial clearance 0 … c.
struct ToleranceBands {
  double eccentricity_mm = 0, turret_radius_mm = 0, roller_diameter_mm = 0, roller_pitch_rad = 0,
         profile_mm = 0, bearing_clearance_mm = 0;
  bool any() const {
    return eccentricity_mm > 0 || turret_radius_mm > 0 || roller_diameter_mm > 0 || roller_pitch_rad > 0 ||
           profile_mm > 0 || bearing_clearance_mm > 0;
  }
};

/// The tolerance keys of the study files, in this order (contributions are reported by key).
inline const std::vector<std::string>& ToleranceKeys() {
  static const std::vector<std::string> keys = {"eccentricity_um", "turret_radius_um", "roller_diameter_um",
                                                "roller_pitch_arcsec", "profile_um", "bearing_clearance_um"};
  return keys;
}

/// One scalar deviation of the reducer: which tolerance key, which turret/roller, its band.
struct ToleranceParameter {
  int key = 0;       ///< index into ToleranceKeys()
  int side = 0;      ///< 0 fixed turret / cam A, 1 output turret / cam B
  int roller = -1;   ///< roller index for per-roller deviations
  double band = 0;   ///< ± half-width (bearing clearance: the upper end of 0 … c), model units
};

/// Every non-zero deviation of the bands for this design (per roller where the tolerance is).
std::vector<ToleranceParameter> ToleranceParameters(const Reducer<double>& r, const ToleranceBands& bands);

/// Deviations with parameter p set to `value` (added to what `dev` holds).
template <typename T>
void AddDeviation(Deviations<T>& dev, const Reducer<double>& r, const ToleranceParameter& p, const T& value) {
  const int n = p.side == 0 ? r.input.rollers : r.output.rollers;
  auto per_roller = [&](std::vector<T>& v) {
    if (v.empty()) v.assign(n, T(0.0));
    v[p.roller] += value;
  };
  switch (p.key) {
    case 0: dev.eccentricity += value; break;
    case 1: dev.turret_radius[p.side] += value; break;
    case 2: per_roller(dev.roller_radius[p.side]); break;  // value is the radius deviation
    case 3: per_roller(dev.roller_angle[p.side]); break;
    case 4: dev.profile[p.side] += value; break;
    case 5: dev.bearing_clearance += value; break;
  }
}

/// The compliant model at one angle.
template <typename T>
struct CompliantAngle {
  T output_rotation{};          ///< δθ_o [rad], input held
  T psi_input{}, psi_output{};  ///< generalised rotations of the two turrets [rad]
  std::vector<T> force_input, force_output;  ///< roller forces [N]
};

/// Compliant equilibrium at input angle θ [rad] under output torque `torque` [N·mm] (signed:
/// forward is LoadedArmSign(r, Side::kOutput)·|T|). `dev == nullptr`: the nominal reducer, exactly
/// the stiffness model's DeflectAtAngle (no gaps). `load_direction`: G/|G| of the paper law at θ
/// (forward torque), for the bearing clearance's shift.
template <typename T>
CompliantAngle<T> CompliantAtAngle(const Reducer<double>& r, const Material& material, double theta,
                                   double torque, const Deviations<T>* dev,
                                   const Vec2<double>& load_direction = {1.0, 0.0}) {
  const T e_star(material.composite_modulus_MPa());
  rigidity::TurretSpring<T> a{{}, T(r.input.contact_length()), e_star, T(0.0), T(0.0)};
  rigidity::TurretSpring<T> b{{}, T(r.output.contact_length()), e_star, T(0.0), T(0.0)};
  for (const auto& c : RollerContacts(r, Side::kInput, theta)) a.arms.push_back(T(c.arm));
  for (const auto& c : RollerContacts(r, Side::kOutput, theta)) b.arms.push_back(T(c.arm));
  if (dev) {
    const double sense = torque * LoadedArmSign(r, Side::kOutput) >= 0 ? 1.0 : -1.0;
    const Vec2<T> shift = BearingShift(dev->bearing_clearance, load_direction, sense);
    a.gaps = RollerGaps(r, Side::kInput, *dev, theta, shift);
    b.gaps = RollerGaps(r, Side::kOutput, *dev, theta, shift);
  }
  const double rho = rigidity::FixedTurretTorqueRatio(r);
  CompliantAngle<T> out;
  out.psi_output = b.Rotation(T(torque));
  out.psi_input = a.Rotation(T(-rho * torque));
  out.output_rotation = out.psi_output - T(rho) * out.psi_input;
  out.force_input = a.Forces(out.psi_input);
  out.force_output = b.Forces(out.psi_output);
  return out;
}

/// G/|G| of the paper law at θ under the forward torque (the bearing clearance pushes the cam
/// this way); (1, 0) where the eccentric carries no load. D: double or a Jet.
template <typename D>
Vec2<D> EccentricLoadDirection(const Reducer<D>& r, const Material& material, double torque_Nmm, double theta) {
  const AngleLoads<D> a = AnalyzeAngle(r, material, LoadCase{std::max(torque_Nmm, 1.0), 0.0, 0.0}, D(theta));
  const D n = a.eccentric_load.norm();
  return Value(n) > 0 ? Vec2<D>(a.eccentric_load / n) : Vec2<D>(D(1.0), D(0.0));
}

/// The load-sharing model of an analysis: the paper's rigid law (F ∝ moment arm, forces.h) or the
/// compliant contacts of the stiffness model (CompliantAtAngle).
enum class LoadModel { kRigid, kCompliant };

/// AnalyzeCycle's series with the compliant load sharing of the nominal reducer: roller forces from
/// CompliantAtAngle (the stiffness model's, Palmgren contacts), Hertz stress and efficiency from
/// those forces with the formulas of forces.h/friction.h. @pre load.output_torque_Nmm > 0.
/// @throws std::domain_error when a turret cannot carry the torque.
CycleSeries AnalyzeCycleCompliant(const Reducer<double>& r, const Material& material, const LoadCase& load,
                                  int steps, const Stages& stages,
                                  const std::function<void(double)>& progress = {});

/// What to compute.
struct TransmissionErrorOptions {
  double output_torque_Nmm = 0;     ///< |T| of the loaded transmission error
  double lost_motion_torque_Nmm = 0;  ///< ±T_lm of the lost motion
  int angle_steps = 72;             ///< input angles over one revolution
  int samples = 0;                  ///< Monte-Carlo samples (0: linear only)
  std::uint64_t seed = 1;
  std::function<void(double)> progress;  ///< fraction done of the Monte-Carlo run
};

using ToleranceContribution = tolerance::Contribution;

/// The shared statistics (model/common/tolerance_stats.h) over one input revolution, and the LCR's
/// own: the angles, the nominal wind-up and the lost motion.
struct TransmissionErrorResult : tolerance::Statistics {
  std::vector<double> theta_rad;
  std::vector<double> nominal_rotation_rad;   ///< δθ_o of the nominal reducer (elastic windup)
  double lost_motion_nominal_arcmin = 0;  ///< max over θ, nominal reducer
  double lost_motion_arcmin = 0;          ///< max over θ, worst Monte-Carlo sample (nominal if none)
  double lost_motion_p99_arcmin = 0;
};

/// Linear (Jet) and Monte-Carlo transmission error over one input revolution.
/// @throws std::domain_error when a turret cannot carry the torque.
TransmissionErrorResult AnalyzeTransmissionError(const Reducer<double>& r, const Material& material,
                                                 const ToleranceBands& bands,
                                                 const TransmissionErrorOptions& options);

/// One Monte-Carlo sample's deviations (uniform in each band, bearing clearance in 0 … c), drawn
/// from a 64-bit generator state (SplitMix64, fixed and portable, so runs are byte-identical).
Deviations<double> SampleDeviations(const Reducer<double>& r, const std::vector<ToleranceParameter>& params,
                                    std::uint64_t& state, std::vector<double>* values = nullptr);

/// TE(θ) [rad] of one set of deviations at the angles of `theta` (exact model).
std::vector<double> ExactTransmissionError(const Reducer<double>& r, const Material& material,
                                           const Deviations<double>& dev, double torque_Nmm,
                                           const std::vector<double>& theta);

}  // namespace camopt::lcr
