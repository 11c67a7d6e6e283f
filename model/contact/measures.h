// Measures read off a half-space contact solution: line load and peak of a grid row, and the
// semi-axis of a Hertz-like (elliptic) pressure found by a least-squares fit of p² against the
// squared distance. Counting cells gives the contact size only to ±dx/2; the fit uses the
// pressure values themselves and is much closer (see docs/validation.md).
#pragma once

#include <algorithm>
#include <cmath>

#include "model/contact/half_space.h"

namespace camopt::contact {

/// Load per unit length of row iy, Σ_ix p·dx [N/mm].
inline double RowLineLoad(const Grid& grid, const ContactSolution& s, int iy) {
  double w = 0;
  for (int ix = 0; ix < grid.nx; ++ix) w += s.pressure_MPa[iy * grid.nx + ix];
  return w * grid.dx;
}

/// Largest pressure of row iy [MPa].
inline double RowPeakPressure(const Grid& grid, const ContactSolution& s, int iy) {
  double m = 0;
  for (int ix = 0; ix < grid.nx; ++ix) m = std::max(m, s.pressure_MPa[iy * grid.nx + ix]);
  return m;
}

/// Fits p² = A + B d² over the loaded cells (d from `distance_sq(ix, iy)`), the exact form of a
/// Hertz pressure p = p₀ sqrt(1 − d²/c²), and returns c = sqrt(−A/B) [mm]; 0 when fewer than two
/// cells are loaded or the fit is not a cap.
template <typename DistanceSq>
double FitEllipticSemiAxis(const Grid& grid, const ContactSolution& s, int iy_begin, int iy_end,
                           const DistanceSq& distance_sq) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int iy = iy_begin; iy < iy_end; ++iy)
    for (int ix = 0; ix < grid.nx; ++ix) {
      const double p = s.pressure_MPa[iy * grid.nx + ix];
      if (p <= 0) continue;
      const double x = distance_sq(ix, iy), y = p * p;
      n += 1;
      sx += x;
      sy += y;
      sxx += x * x;
      sxy += x * y;
    }
  const double det = n * sxx - sx * sx;
  if (n < 2 || !(det > 0)) return 0;
  const double b = (n * sxy - sx * sy) / det, a = (sy - b * sx) / n;
  return (b < 0 && a > 0) ? std::sqrt(-a / b) : 0;
}

/// Half-width of row iy's contact about x = xc, by the elliptic fit [mm].
inline double RowHalfWidth(const Grid& grid, const ContactSolution& s, int iy, double xc_mm = 0) {
  return FitEllipticSemiAxis(grid, s, iy, iy + 1, [&](int ix, int) {
    const double x = grid.x_centre_mm(ix) - xc_mm;
    return x * x;
  });
}

/// Radius of a circular contact centred at (xc, yc), by the elliptic fit [mm].
inline double CircularContactRadius(const Grid& grid, const ContactSolution& s, double xc_mm = 0,
                                    double yc_mm = 0) {
  return FitEllipticSemiAxis(grid, s, 0, grid.ny, [&](int ix, int iy) {
    const double x = grid.x_centre_mm(ix) - xc_mm, y = grid.y_centre_mm(iy) - yc_mm;
    return x * x + y * y;
  });
}

}  // namespace camopt::contact
