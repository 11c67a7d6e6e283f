// LCR input torque with friction and efficiency (paper §4, eqs. 32–33): the one home of the
// friction law, used by the per-angle analysis (forces.h) and by the friction fit alike.
//
//   T_in = (F_t + μ |F_r|) e          (eq. 32; F_t, F_r the tangential and radial load of the cam
//                                      on the eccentric, μ the eccentric-bearing friction)
//   η    = T_o / (T_in |r_i|)          (eq. 33)
//
// Without a cam weight the loads are linear in the output torque T_o, and the law is linear in
// F_t and |F_r|, so its mean over an input revolution is the same law applied to the means of F_t·e
// and |F_r|·e per unit output torque (CycleInputTorque). The friction fit adds a no-load drag:
//   T_in(T_o) = T_drag + T_o (t_ideal + μ t_friction).
#pragma once

#include <cmath>
#include <vector>

namespace camopt::lcr {

/// The paper's friction coefficient of the eccentric (§4), for comparison with its curves.
inline constexpr double kPaperFrictionCoefficient = 0.05;

/// Eq. 32: input torque T_in = (F_t + μ |F_r|)·lever that turns the eccentric against the cam.
/// @tparam T double or ceres::Jet.
/// @param tangential_force F_t [N] (or a torque per unit lever), @param radial_force F_r [N],
/// @param mu friction coefficient μ [-], @param lever the eccentricity e [mm] (1 when the forces
/// are already torques). Returns [N·mm] for forces in N and e in mm. Kink at F_r = 0 (|F_r|): a
/// true corner of the friction law, not a numerical artefact.
template <typename T>
T InputTorque(const T& tangential_force, const T& radial_force, const T& mu, const T& lever) {
  using std::abs;
  return (tangential_force + mu * abs(radial_force)) * lever;
}

/// Eq. 33: efficiency η = T_o / (T_in |r_i|) [-]; T_o and T_in in the same unit,
/// speed_ratio_abs = |r_i|.
template <typename T>
T Efficiency(const T& output_torque, const T& input_torque, double speed_ratio_abs) {
  return output_torque / (input_torque * T(speed_ratio_abs));
}

/// Frictionless input torque by power balance, T_o / |r_i| (same unit as T_o).
inline double IdealInputTorque(double output_torque, double speed_ratio) {
  return output_torque / std::abs(speed_ratio);
}

/// The two parts of the mean input torque over a revolution per unit output torque:
/// mean_θ T_in / T_o = ideal + μ·friction [N·mm per N·mm].
struct CycleInputTorque {
  double ideal = 0.0;     ///< mean F_t e / T_o (= 1/|r_i| by power balance)
  double friction = 0.0;  ///< mean |F_r| e / T_o
};

/// CycleInputTorque from the loads on the eccentric at equally spaced input angles, computed for
/// a unit output torque and no cam weight. tangential_N, radial_N: F_t, F_r per angle [N];
/// eccentricity_mm: e. @pre both series have the same, non-zero length.
inline CycleInputTorque MeanInputTorquePerOutputTorque(const std::vector<double>& tangential_N,
                                                       const std::vector<double>& radial_N,
                                                       double eccentricity_mm) {
  CycleInputTorque out;
  for (size_t i = 0; i < tangential_N.size(); ++i) {
    out.ideal += tangential_N[i] * eccentricity_mm;
    out.friction += std::abs(radial_N[i]) * eccentricity_mm;
  }
  const double n = static_cast<double>(tangential_N.size());
  out.ideal /= n;
  out.friction /= n;
  return out;
}

/// The friction fit's model of a measured input torque: eq. 32 averaged over a revolution plus a
/// no-load drag, T_in(T_o) = T_drag + T_o (t_ideal + μ t_friction). T_in and T_drag in the unit of
/// T_o. @tparam T double or ceres::Jet (μ and T_drag are the fitted parameters).
template <typename T>
T MeanInputTorque(const CycleInputTorque& per_output_torque, const T& output_torque, const T& mu,
                  const T& drag_torque) {
  // The coefficients already carry e, so the law's lever is 1.
  return drag_torque + output_torque * InputTorque(T(per_output_torque.ideal),
                                                   T(per_output_torque.friction), mu, T(1.0));
}

}  // namespace camopt::lcr
