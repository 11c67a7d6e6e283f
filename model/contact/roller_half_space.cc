// See roller_half_space.h.
#include "model/contact/roller_half_space.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/common/roots.h"
#include "model/contact/crowning.h"
#include "model/contact/hertz.h"

namespace camopt::contact {

RollerHalfSpaceResult SolveRollerHalfSpace(double force_N, double r_eff_mm, double length_mm,
                                           double e_star_MPa, const std::function<double(double)>& gap_y,
                                           int nx, int ny, double half_width_hint_mm,
                                           HalfSpaceSolver& solver, const std::vector<double>* start) {
  if (nx < 2 || ny < 1 || !(r_eff_mm > 0) || !(length_mm > 0) || !(e_star_MPa > 0))
    throw std::invalid_argument("roller half-space: need nx >= 2, ny >= 1, R' > 0, length > 0, E* > 0");
  RollerHalfSpaceResult out;
  double half_x = 1.3 * (half_width_hint_mm > 0
                             ? half_width_hint_mm
                             : LineContactHalfWidth(std::max(force_N, 0.0), length_mm, r_eff_mm, e_star_MPa));
  if (!(half_x > 0)) half_x = 1e-3 * length_mm;
  std::vector<double> hy(ny);
  for (int k = 0; k < 6; ++k) {
    const Grid grid = CenteredGrid(nx, ny, half_x, 0.5 * length_mm);
    std::vector<double> gap(grid.cells());
    for (int iy = 0; iy < ny; ++iy) {
      hy[iy] = gap_y(grid.y_centre_mm(iy));
      for (int ix = 0; ix < nx; ++ix) {
        const double x = grid.x_centre_mm(ix);
        gap[iy * nx + ix] = x * x / (2 * r_eff_mm) + hy[iy];
      }
    }
    const ContactSolution s = k == 0 && start ? solver.SolveForLoad(grid, gap, force_N, e_star_MPa, *start)
                                              : solver.SolveForLoad(grid, gap, force_N, e_star_MPa);
    out.iterations += s.iterations;
    if (s.contact_at_x_edge && k < 5) {
      half_x *= 2;
      continue;
    }
    out.peak_pressure_MPa = s.max_pressure_MPa;
    out.approach_mm = s.approach_mm;
    out.dx_mm = grid.dx;
    out.dy_mm = grid.dy;
    out.converged = s.converged && !s.contact_at_x_edge;
    out.half_x_mm = half_x;
    out.pressure_MPa = s.pressure_MPa;
    out.message = s.contact_at_x_edge ? "contact reaches the grid's x edge" : s.message;
    out.y_mm.resize(ny);
    out.pressure_along_y.assign(ny, 0.0);
    for (int iy = 0; iy < ny; ++iy) {
      out.y_mm[iy] = grid.y_centre_mm(iy);
      for (int ix = 0; ix < nx; ++ix)
        out.pressure_along_y[iy] = std::max(out.pressure_along_y[iy], s.pressure_MPa[iy * nx + ix]);
    }
    const double tiny = 1e-6 * out.peak_pressure_MPa;
    out.edge_loaded = out.pressure_along_y.front() > tiny || out.pressure_along_y.back() > tiny;
    break;
  }
  return out;
}

LogCrownDesign DesignLogCrownForLoad(double force_N, double r_eff_mm, double length_mm, double e_star_MPa,
                                     double effective_length_mm, int nx, int ny, double k1_lo, double k1_hi,
                                     double k1_tolerance, HalfSpaceSolver& solver) {
  if (!(effective_length_mm > length_mm) || !(k1_lo > 0) || !(k1_hi > k1_lo))
    throw std::invalid_argument("log crown design: need Le > l and 0 < k1_lo < k1_hi");
  const double f_lundberg = LundbergCoefficient(force_N, length_mm, e_star_MPa);
  LogCrownDesign out;
  const auto peak = [&](double k1) {
    const auto h = SolveRollerHalfSpace(force_N, r_eff_mm, length_mm, e_star_MPa, [&](double y) {
      return CrowningDrop<double>(CrowningType::kLogarithmic, 0.0, 0.0, k1 * f_lundberg, effective_length_mm, y);
    }, nx, ny, 0, solver);
    ++out.solves;
    if (!h.converged) throw std::runtime_error("log crown design: half_space solve not converged: " + h.message);
    return h.peak_pressure_MPa;
  };
  const auto b = GoldenSectionMaximize([&](double k1) { return -peak(k1); }, k1_lo, k1_hi, 60, k1_tolerance);
  // The better of the two interior points of the final bracket (both evaluated).
  out.k1 = b.f1 >= b.f2 ? b.x1 : b.x2;
  out.peak_pressure_MPa = -std::max(b.f1, b.f2);
  out.coefficient_mm = out.k1 * f_lundberg;
  return out;
}

}  // namespace camopt::contact
