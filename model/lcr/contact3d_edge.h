// How far the pressure of a sliced roller contact stays from the contact's ends (issue 12: at an
// overload torque the pressure must stay off the ends), as one smooth, signed number for the
// sizing problem (objectives/lcr_sizing3d.h):
//     m = min over the two end slices e of  (h_e + u_e − δ)/f_L − q_e/(F/l),
// with h the gap along the roller, u_e = Σ_j C_ej(b_j) q_j the elastic approach on the end slice
// (the slices model's influence coefficients, model/contact/roller_slices.h), δ the approach,
// f_L = F/(π l E*) (Lundberg's coefficient, the scale of the approach's variation along y) and q
// the line loads. Off the ends q_e = 0 and the separation is >= 0; on an end the separation is 0
// and q_e > 0: m > 0 exactly when the pressure stays off both ends, and m is continuous at the
// onset. Over T: the line loads and δ carry the slices model's implicit-step derivatives, the
// half-widths b_j = b(q_j) follow them.
#pragma once

#include <vector>

#include "model/contact/crowning.h"
#include "model/contact/roller_slices.h"
#include "model/lcr/contact3d.h"

namespace camopt::lcr {

/// m above for the solution sol of the contact (F, R', l, E*, crowning, γ).
template <typename T>
T EdgeMargin(const contact::SliceSolution<T>& sol, const T& force, const T& r_eff, const T& length, double e_star,
             const RollerCrowning<T>& crowning, const T& misalignment_rad) {
  using contact::slices_detail::HalfWidth;
  using contact::slices_detail::Influence;
  const int n = int(sol.y_mm.size());
  const T q_mean = force / length;
  const T f_lundberg = contact::LundbergCoefficient(force, length, T(e_star));
  const T q_floor(1e-6 * Value(q_mean));  // as the solver's half-widths (roller_slices.h)
  std::vector<T> b(n);
  for (int j = 0; j < n; ++j) b[j] = HalfWidth(sol.line_load_N_per_mm[j], q_floor, r_eff, e_star);
  T best(0.0);
  for (int k = 0; k < 2; ++k) {
    const int e = k == 0 ? 0 : n - 1;
    T u(0.0);
    for (int j = 0; j < n; ++j) u += Influence(T(sol.y_mm[e] - sol.y_mm[j]), sol.slice_width, b[j], e_star) * sol.line_load_N_per_mm[j];
    const T sep = GapAlongRoller(crowning, misalignment_rad, sol.y_mm[e]) + u - sol.approach;
    const T m = sep / f_lundberg - sol.line_load_N_per_mm[e] / q_mean;
    if (k == 0 || Value(m) < Value(best)) best = m;
  }
  return best;
}

}  // namespace camopt::lcr
