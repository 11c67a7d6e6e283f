// Finite-length roller contact on the elastic half-space by the DC-FFT solver (model/contact/
// half_space.h): the `half_space` fidelity of the LCR contact, to verify a design and to measure
// the slicing model's error (docs/lcr.md "Crowned rollers and 3D contact"). Double only.
//
// Grid: ny cells over exactly the contact length l along y (the contact's ends are the grid's y
// edges, so an edge peak is the pressure of the end row, resolved by dy = l/ny); nx cells across
// rolling over [−X, X], X = 1.3 × the largest slice half-width of a slices solve (or the Hertz line
// half-width of F/l when none is given), doubled while the pressure touches the x edge.
// Gap h(x, y) = x²/(2R') + h_y(y) (crowning + misalignment along y).
#pragma once

#include <functional>
#include <vector>

#include "model/contact/half_space.h"

namespace camopt::contact {

struct RollerHalfSpaceResult {
  double peak_pressure_MPa = 0;
  double approach_mm = 0;
  double dx_mm = 0, dy_mm = 0;            // the cell size every number was computed with
  std::vector<double> y_mm;               // row centres
  std::vector<double> pressure_along_y;   // max over x of each row [MPa]
  bool edge_loaded = false;               // the end rows carry load
  bool converged = false;
  int iterations = 0;
  std::string message;
  double half_x_mm = 0;                   // the grid's extent across rolling, [−X, X]
  std::vector<double> pressure_MPa;       // per cell (row-major, iy * nx + ix)
};

/// @param half_width_hint_mm  X/1.3 (e.g. the largest slice half-width); <= 0: the line value.
/// @param start  optional: a pressure field (nx × ny cells) on the first grid tried (X = 1.3 ×
///        the hint) to start the iteration from (HalfSpaceSolver::SolveForLoad with a start: the
///        same equations and stopping test, usually fewer iterations); ignored once X is doubled.
RollerHalfSpaceResult SolveRollerHalfSpace(double force_N, double r_eff_mm, double length_mm,
                                           double e_star_MPa, const std::function<double(double)>& gap_y,
                                           int nx, int ny, double half_width_hint_mm,
                                           HalfSpaceSolver& solver, const std::vector<double>* start = nullptr);

/// A logarithmic crown designed for its load by Fujiwara & Kawase's criterion (NTN Technical
/// Review 75, 2007: the crown's parameters minimise the peak contact pressure at the design load):
/// Lundberg's form f ln(1/(1 − (2y/Le)²)) with a given effective length Le > l and the
/// coefficient f = K1·F/(π l E*) (K1 their load coefficient; 1 is Lundberg's), K1 the minimiser of
/// the half_space peak pressure at F over [k1_lo, k1_hi] on an nx × ny grid (golden section to a
/// bracket of k1_tolerance). The peak is the larger of the middle's pressure (rises with K1) and
/// the end region's (falls with K1), so the minimiser is where they meet.
struct LogCrownDesign {
  double k1 = 0;               ///< load coefficient [-]
  double coefficient_mm = 0;   ///< f = K1 F/(π l E*)
  double peak_pressure_MPa = 0;  ///< at the design, on the design grid
  int solves = 0;
};
LogCrownDesign DesignLogCrownForLoad(double force_N, double r_eff_mm, double length_mm, double e_star_MPa,
                                     double effective_length_mm, int nx, int ny, double k1_lo, double k1_hi,
                                     double k1_tolerance, HalfSpaceSolver& solver);

}  // namespace camopt::contact
