// Cycle aggregates of a disc cam for design work: the numbers a sizing study would bound, as
// functions of the design over the scalar T. Maxima over the angle grid are HardMax (the
// derivative is that of the worst sample, exact while the worst sample does not switch) and,
// for smooth constraints, SoftMax with sharpness k (bound: max ≤ SoftMax ≤ max + ln(N)/k).
#pragma once

#include <vector>

#include "model/common/scalar.h"
#include "model/disc_cam/disc_cam.h"
#include "model/disc_cam/mechanical_error.h"

namespace camopt::disc_cam {

template <typename T>
struct CamSummary {
  T max_radial_dimension;      ///< [mm]
  T max_abs_pressure_angle;    ///< [rad], HardMax of |φ|
  T soft_max_abs_pressure_angle;  ///< [rad], SoftMax with k = 50 /rad (≤ max + ln N/50)
  T curvature_margin;          ///< min over θ of (1/r_f − κ) [1/mm]; > 0 means no undercut
  T max_worst_case_error;      ///< [mm or rad], eq. (31)
  T max_rms_error;             ///< [mm or rad], eq. (32)
};

/// Aggregates over n equally spaced cam angles.
template <typename T>
CamSummary<T> SummarizeCam(const DiscCamTpl<T>& cam, const Deviations<T>& tolerances, int n) {
  using std::abs;
  std::vector<T> radial(n), phi(n), margin(n), worst(n), rms(n);
  for (int i = 0; i < n; ++i) {
    const CamPoint<T> p = EvaluateCam(cam, T(2.0 * kPi * i / n));
    const MechanicalError<T> e = FollowerError(cam, p, tolerances);
    radial[i] = p.radial_dimension;
    phi[i] = abs(p.pressure_angle);
    margin[i] = T(1.0) / cam.roller_radius - p.pitch_curvature;
    worst[i] = e.worst_case;
    rms[i] = e.rms;
  }
  return {HardMax(radial), HardMax(phi), SoftMax(phi, 50.0), HardMin(margin), HardMax(worst),
          HardMax(rms)};
}

}  // namespace camopt::disc_cam
