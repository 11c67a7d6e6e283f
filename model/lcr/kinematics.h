// LCR kinematics (paper eqs. 1–3, Table 1): speeds of the cam and the output turret relative to
// the eccentric input shaft, and the speed reduction ratio, for any lobe and roller counts.
#pragma once

#include "model/lcr/reducer.h"

namespace camopt::lcr {

/// ω_c/ω_in = 1 − n_A/m_A (eq. 1).
inline double CamSpeedRatio(int lobes_a, int rollers_a) {
  return 1.0 - double(rollers_a) / double(lobes_a);
}

/// ω_o/ω_in = 1 − n_A m_B/(m_A n_B) (eq. 2).
inline double OutputSpeedRatio(int lobes_a, int rollers_a, int lobes_b, int rollers_b) {
  return 1.0 - double(rollers_a) * lobes_b / (double(lobes_a) * rollers_b);
}

/// r_i = ω_in/ω_o = m_A n_B/(m_A n_B − m_B n_A) (eq. 3); infinite when the output stands still.
inline double SpeedReductionRatio(int lobes_a, int rollers_a, int lobes_b, int rollers_b) {
  const long den = long(lobes_a) * rollers_b - long(lobes_b) * rollers_a;
  if (den == 0) return kInf;
  return double(long(lobes_a) * rollers_b) / double(den);
}

template <typename T>
double CamSpeedRatio(const Reducer<T>& r) {
  return CamSpeedRatio(r.input.lobes, r.input.rollers);
}
template <typename T>
double OutputSpeedRatio(const Reducer<T>& r) {
  return OutputSpeedRatio(r.input.lobes, r.input.rollers, r.output.lobes, r.output.rollers);
}
template <typename T>
double SpeedReductionRatio(const Reducer<T>& r) {
  return SpeedReductionRatio(r.input.lobes, r.input.rollers, r.output.lobes, r.output.rollers);
}

}  // namespace camopt::lcr
