// How far the pressure of a sliced roller contact stays from the contact's ends (at an
// overload torque the pressure must stay off the ends), as one smooth, signed number for the
// sizing problem (sizing/lcr_sizing3d.h):
//     m_i = (h_i + u_i − δ)/f_L − q_i/(F/l)   at slice i,
// with h the gap along the roller, u_i = Σ_j C_ij(b_j) q_j the elastic approach on slice i (the
// slices model's influence coefficients, model/contact/roller_slices.h), δ the approach,
// f_L = F/(π l E*) (Lundberg's coefficient, the scale of the approach's variation along y) and q
// the line loads. Off contact q_i = 0 and the separation is >= 0; in contact the separation is 0
// and q_i > 0: m_i > 0 exactly when slice i carries no load, continuous at its onset. The margin
// is the smaller, over the two ends, of m extrapolated linearly from the end slice and its
// neighbour to the contact's end (half a slice beyond the end slice's centre):
//     m = min( m_0 + (m_0 − m_1)/2,  m_{n−1} + (m_{n−1} − m_{n−2})/2 ).
// The end slice's own value sits w/2 inside the end and converges at first order in the slice
// width w (a sizing with it followed the slice count: 1.2 mm of outer diameter per doubling); the
// extrapolation converges at second order (tests/lcr_sizing3d_test.cc), and m > 0 says that the
// converged solution keeps the pressure off both ends. Over T: the line loads and δ carry the
// slices model's implicit-step derivatives, the half-widths b_j = b(q_j) follow them.
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
  // m_i of the header at slice i.
  const auto at = [&](int i) {
    T u(0.0);
    for (int j = 0; j < n; ++j) u += Influence(T(sol.y_mm[i] - sol.y_mm[j]), sol.slice_width, b[j], e_star) * sol.line_load_N_per_mm[j];
    const T sep = GapAlongRoller(crowning, misalignment_rad, sol.y_mm[i]) + u - sol.approach;
    return T(sep / f_lundberg - sol.line_load_N_per_mm[i] / q_mean);
  };
  T best(0.0);
  for (int k = 0; k < 2; ++k) {
    const int e = k == 0 ? 0 : n - 1, inner = k == 0 ? 1 : n - 2;
    const T m_e = at(e), m = n > 1 ? T(m_e + 0.5 * (m_e - at(inner))) : m_e;  // header: to the end
    if (k == 0 || Value(m) < Value(best)) best = m;
  }
  return best;
}

}  // namespace camopt::lcr
