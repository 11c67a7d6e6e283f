// Lost motion of a lobe cam reducer (the rotation of its output, input held, over a torque
// range) and the chain rule that carries an element's own rigidity elasticities to a chain.
//
// Units: torques N·mm, rotations rad, clearances mm, stiffness N/mm (as lcr_stiffness.h).
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "model/rigidity/lcr_stiffness.h"

namespace camopt::rigidity {

/// The torques of a lost-motion curve from −T to +T: T·f·|f| at f = i/n, i = −n … n, denser near
/// zero load; 0 itself is replaced by ±1e-9·T (inside a clearance the position at zero load is
/// undetermined), so the curve has 2n + 2 points. @param torque_Nmm T > 0 [N·mm].
inline std::vector<double> LostMotionTorques(double torque_Nmm, int half_points = 40) {
  std::vector<double> torques;
  const int n = half_points;
  for (int i = -n; i <= n; ++i) {
    if (i == 0) {
      for (double t : {-1e-9, 1e-9}) torques.push_back(t * torque_Nmm);
      continue;
    }
    const double f = double(i) / n;
    torques.push_back(f * std::abs(f) * torque_Nmm);
  }
  return torques;
}

/// LostMotionCurve with the torques taken in a load sense s = ±1: the reducer carries s·t and the
/// rotation is reported as s·rotation, so that the curve reads the same in both senses.
inline std::vector<double> LostMotionCurveInSense(const lcr::Reducer<double>& r,
                                                  const lcr::Material& material,
                                                  const std::vector<double>& torques_Nmm,
                                                  double sense, double clearance_mm, int steps,
                                                  double bearing_N_per_mm = 0.0) {
  std::vector<double> signed_t;
  signed_t.reserve(torques_Nmm.size());
  for (double t : torques_Nmm) signed_t.push_back(sense * t);
  std::vector<double> rotations =
      LostMotionCurve(r, material, signed_t, clearance_mm, steps, bearing_N_per_mm);
  for (double& x : rotations) x *= sense;
  return rotations;
}

/// Lost motion as reducer catalogues define it: the output rotation [rad] between −f·T and +f·T
/// (f = 3 % of the rated torque by default), mean over `steps` input angles, input held.
/// @param torque_Nmm the rated (here: load) torque, signed in the load sense [N·mm].
inline double LostMotion(const lcr::Reducer<double>& r, const lcr::Material& material,
                         double torque_Nmm, double clearance_mm, int steps,
                         double bearing_N_per_mm = 0.0, double fraction = 0.03) {
  const auto lm = LostMotionCurve(r, material, {-fraction * torque_Nmm, fraction * torque_Nmm},
                                  clearance_mm, steps, bearing_N_per_mm);
  return std::abs(lm[1] - lm[0]);
}

/// Chain rule of rigidity elasticities through a series chain: with R = 1/Σ c_j and c_k = 1/R_k
/// (referred to the same end), ∂ln R/∂ln R_k = c_k/Σ c_j, the element's compliance share, so
/// ∂ln R/∂ln p = share_k · ∂ln R_k/∂ln p for a parameter p of element k alone.
/// @tparam T double or ceres::Jet.
template <typename T>
T ChainElasticity(const T& share, const T& own_elasticity) {
  return share * own_elasticity;
}

/// ChainElasticity for each named own elasticity of one element.
template <typename T>
std::vector<std::pair<std::string, T>> ChainElasticities(
    const T& share, const std::vector<std::pair<std::string, T>>& own) {
  std::vector<std::pair<std::string, T>> out;
  out.reserve(own.size());
  for (const auto& [name, v] : own) out.push_back({name, ChainElasticity(share, v)});
  return out;
}

}  // namespace camopt::rigidity
