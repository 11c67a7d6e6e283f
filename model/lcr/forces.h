// LCR forces, torques, efficiency and Hertz stress at one input angle (paper §4, eqs. 20–33, in
// the consistent form of docs/papers.md §1).
//
//   F_k = C |a_k| on loaded rollers (sign(a_k) = LoadedArmSign), 0 elsewhere   (paper eqs. 20–21)
//   output turret:  T_o = C_B Σ a_Bj²                                           (eq. 25)
//   cam about O_c (arms (m/n) a_k): C_A (m_A/n_A) Σ a_Ai² = C_B (m_B/n_B) Σ a_Bj²
//   fixed turret:   T_A = C_A Σ a_Ai² = T_o m_B n_A /(n_B m_A)                  (eq. 24)
//   eccentric load G = Σ F_k d_k + W (weight along −y); F_t = −G·t, F_r = G·u(θ), t = J u(θ)
//   input torque    T_in = (F_t + μ |F_r|) e, efficiency η = T_o /(T_in |r_i|)   (eqs. 32–33,
//                   written once in friction.h)
//   Hertz line contact p = sqrt(F E* /(π L R')), R' = r_r (1 − r_r κ)           (docs/papers.md §1)
// Without friction e F_t = T_o/|r_i| exactly (power balance), which the tests check.
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "model/common/scalar.h"
#include "model/contact/hertz.h"
#include "model/lcr/contact.h"
#include "model/lcr/friction.h"

namespace camopt::lcr {

template <typename T>
struct SideLoads {
  std::vector<RollerContact<T>> contacts;
  std::vector<T> force;             // F_k [N]; 0 on rollers that carry no load
  std::vector<T> stress;            // Hertz p_max [MPa]; 0 where unloaded, +inf at an undercut contact
  T proportionality{};              // C [N/mm]
  T turret_torque{};                // |Σ F_k a_k| [N·mm]
  int actuating = 0;                // rollers carrying load
  T max_force{}, max_stress{};
};

template <typename T>
struct AngleLoads {
  T theta{};
  SideLoads<T> input, output;
  Vec2<T> eccentric_load;      // G [N], force of the cam on the eccentric
  T tangential_force{};        // F_t [N]
  T radial_force{};            // F_r [N]
  T input_torque{};            // T_in [N·mm]
  T efficiency{};              // η, fraction
};

/// What to evaluate beyond the contact geometry.
struct Stages {
  bool forces = true;
  bool stress = true;      // needs forces
  bool efficiency = true;  // needs forces
  /// AnalyzeCycle only: every roller's stress, SideSeries::roller_stress_MPa (needs stress;
  /// AnalyzeAngle always has SideLoads::stress).
  bool roller_stress = false;
};

namespace internal {

// Σ over loaded rollers of a_k² (a_k of the loaded sign).
template <typename T>
T SumLoadedArmSquares(const std::vector<RollerContact<T>>& contacts, double sign) {
  T s(0.0);
  for (const auto& c : contacts) {
    const T a = PositivePart(T(sign) * c.arm);
    s += a * a;
  }
  return s;
}

// The same sum from the arms alone (TowardPitch, without the curvatures and contact points): bit
// for bit SumLoadedArmSquares(RollerContacts(r, s, θ), sign).
template <typename T>
T SumLoadedArmSquares(const Reducer<T>& r, Side s, const T& theta, double sign) {
  const Vec2<T> pitch = PitchPointOfCam(r, s, theta);
  T sum(0.0);
  for (const Vec2<T>& o : RollerCentres(r, s, theta)) {
    const T a = PositivePart(T(sign) * Cross(o, TowardPitch(pitch, o).first));
    sum += a * a;
  }
  return sum;
}

// C of one cam (the header's law): C_B = T_o / Σ a_Bj² and, from the cam's moment balance,
// C_A = C_B (m_B/n_B) Σ a_Bj² / ((m_A/n_A) Σ a_Ai²), written so (its value is
// T_o (m_B/n_B) / ((m_A/n_A) Σ a_Ai²); the written form's rounding is every result's since the
// start). The output cam's needs only its own contacts (AnalyzeSide).
template <typename T>
CAMOPT_FLATTEN T ForceScale(const Reducer<T>& r, Side side, const LoadCase& load, const T& sum_a, const T& sum_b) {
  const T c_b = T(load.output_torque_Nmm) / sum_b;
  if (side == Side::kOutput) return c_b;
  const double ratio_b = double(r.output.lobes) / r.output.rollers;
  const double ratio_a = double(r.input.lobes) / r.input.rollers;
  return c_b * T(ratio_b) * sum_b / (T(ratio_a) * sum_a);
}

template <typename T>
void FillForces(SideLoads<T>& side, double sign, const T& proportionality, double arm_tolerance) {
  side.proportionality = proportionality;
  side.force.resize(side.contacts.size());
  side.actuating = 0;
  side.max_force = T(0.0);
  side.turret_torque = T(0.0);
  for (size_t k = 0; k < side.contacts.size(); ++k) {
    const T a = PositivePart(T(sign) * side.contacts[k].arm);
    side.force[k] = proportionality * a;
    side.turret_torque += side.force[k] * a;
    if (Value(a) > arm_tolerance) ++side.actuating;
    if (Value(side.force[k]) > Value(side.max_force)) side.max_force = side.force[k];
  }
}

template <typename T>
void FillStresses(SideLoads<T>& side, const CamSide<T>& cam, double e_star) {
  using std::sqrt;
  side.stress.assign(side.contacts.size(), T(0.0));
  side.max_stress = T(0.0);
  const T length = cam.contact_length();
  for (size_t k = 0; k < side.contacts.size(); ++k) {
    if (!(Value(side.force[k]) > 0)) continue;  // p → 0 continuously as F → 0
    const T r_eff = cam.roller_radius * (T(1.0) - cam.roller_radius * side.contacts[k].curvature);
    if (!(Value(r_eff) > 0)) {
      side.stress[k] = T(kInf);  // the roller sits on an undercut part of the pitch curve
    } else {
      side.stress[k] = contact::LineContactPeakPressure(side.force[k], length, r_eff, T(e_star));
    }
    if (Value(side.stress[k]) > Value(side.max_stress)) side.max_stress = side.stress[k];
  }
}

}  // namespace internal

/// Everything at input angle θ [rad] for the stages asked. Throws std::domain_error when no roller
/// of a turret can carry load (a degenerate design).
template <typename T>
AngleLoads<T> AnalyzeAngle(const Reducer<T>& r, const Material& material, const LoadCase& load,
                           const T& theta, const Stages& stages = {}) {
  AngleLoads<T> out;
  out.theta = theta;
  out.input.contacts = RollerContacts(r, Side::kInput, theta);
  out.output.contacts = RollerContacts(r, Side::kOutput, theta);
  if (!stages.forces && !stages.stress && !stages.efficiency) return out;

  const double sign_a = LoadedArmSign(r, Side::kInput), sign_b = LoadedArmSign(r, Side::kOutput);
  const T sum_a = internal::SumLoadedArmSquares(out.input.contacts, sign_a);
  const T sum_b = internal::SumLoadedArmSquares(out.output.contacts, sign_b);
  if (!(Value(sum_a) > 0) || !(Value(sum_b) > 0))
    throw std::domain_error("no roller of a turret can carry load at this input angle");
  const T c_a = internal::ForceScale(r, Side::kInput, load, sum_a, sum_b);
  const T c_b = internal::ForceScale(r, Side::kOutput, load, sum_a, sum_b);
  const double tol_a = 1e-9 * Value(r.input.turret_radius), tol_b = 1e-9 * Value(r.output.turret_radius);
  internal::FillForces(out.input, sign_a, c_a, tol_a);
  internal::FillForces(out.output, sign_b, c_b, tol_b);

  if (stages.stress) {
    const double e_star = material.composite_modulus_MPa();
    internal::FillStresses(out.input, r.input, e_star);
    internal::FillStresses(out.output, r.output, e_star);
  }
  if (stages.efficiency) {
    // Everything but the weight is linear in T_o, so the efficiency at T_o = 0 is its limit
    // T_o → 0⁺: computed from the load per unit torque (0 when a cam weight must still be carried).
    const bool unloaded = load.output_torque_Nmm == 0.0;
    Vec2<T> per_torque(T(0.0), T(0.0));  // G per N·mm of output torque
    const LoadCase unit_torque_load{1.0};  // C per N·mm of output torque: the same law at T_o = 1
    const T unit_a = internal::ForceScale(r, Side::kInput, unit_torque_load, sum_a, sum_b);
    const T unit_b = internal::ForceScale(r, Side::kOutput, unit_torque_load, sum_a, sum_b);
    for (const auto& [side, sign, c] :
         {std::tuple{&out.input, sign_a, unit_a}, std::tuple{&out.output, sign_b, unit_b}})
      for (const auto& contact : side->contacts)
        per_torque += c * PositivePart(T(sign) * contact.arm) * contact.direction;
    const Vec2<T> g = T(load.output_torque_Nmm) * per_torque + Vec2<T>(T(0.0), T(-load.cam_weight_N));
    out.eccentric_load = g;
    const Vec2<T> u = U(theta);
    out.tangential_force = -g.dot(Perp(u));
    out.radial_force = g.dot(u);
    // |F_r| in the friction law (ceres' abs: sign(F_r)·dF_r, no branch) has a corner where the
    // radial load reverses. Harmless for gradients: it is the Coulomb law's own corner (friction
    // follows the load's direction), the value is continuous, and an exact zero of F_r at a sampled
    // angle is met on a set of designs of measure zero, where either side is a valid subgradient.
    const T mu(load.friction_coefficient);
    out.input_torque = InputTorque(out.tangential_force, out.radial_force, mu, r.eccentricity);
    const double ratio = std::abs(SpeedReductionRatio(r));
    if (!unloaded) {
      out.efficiency = Efficiency(T(load.output_torque_Nmm), out.input_torque, ratio);
    } else if (load.cam_weight_N > 0) {
      out.efficiency = T(0.0);
    } else {
      const T unit_torque = InputTorque(T(-per_torque.dot(Perp(u))), T(per_torque.dot(u)), mu, r.eccentricity);
      out.efficiency = Efficiency(T(1.0), unit_torque, ratio);
    }
  }
  return out;
}

/// One cam's contacts, forces and (Stages::stress) stresses at input angle θ [rad]: bit for bit
/// AnalyzeAngle's SideLoads of that cam. The output cam's scale needs only its own contacts (half
/// AnalyzeAngle's work); the input cam's takes the output's Σ a² too (internal::ForceScale's
/// written form), from the output's arms alone. Stages::efficiency needs both cams' forces: not here.
/// Throws std::domain_error when no roller of a turret it uses can carry load.
template <typename T>
SideLoads<T> AnalyzeSide(const Reducer<T>& r, const Material& material, const LoadCase& load, Side side,
                         const T& theta, const Stages& stages = {true, true, false}) {
  if (stages.efficiency) throw std::invalid_argument("lcr::AnalyzeSide: the efficiency needs both cams (AnalyzeAngle)");
  SideLoads<T> out;
  out.contacts = RollerContacts(r, side, theta);
  if (!stages.forces && !stages.stress) return out;
  const double sign = LoadedArmSign(r, side);
  const T sum = internal::SumLoadedArmSquares(out.contacts, sign);
  const T other = side == Side::kOutput ? sum
                                        : internal::SumLoadedArmSquares(r, Side::kOutput, theta,
                                                                        LoadedArmSign(r, Side::kOutput));
  if (!(Value(sum) > 0) || !(Value(other) > 0))
    throw std::domain_error("no roller of a turret can carry load at this input angle");
  // The output cam's `other` is its own sum (ForceScale's output branch reads Σ a_B² only).
  const T scale = side == Side::kInput ? internal::ForceScale(r, side, load, sum, other)
                                       : internal::ForceScale(r, side, load, other, sum);
  internal::FillForces(out, sign, scale, 1e-9 * Value(r.side(side).turret_radius));
  if (stages.stress) internal::FillStresses(out, r.side(side), material.composite_modulus_MPa());
  return out;
}

}  // namespace camopt::lcr
