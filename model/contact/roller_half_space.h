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
};

/// @param half_width_hint_mm  X/1.3 (e.g. the largest slice half-width); <= 0: the line value.
RollerHalfSpaceResult SolveRollerHalfSpace(double force_N, double r_eff_mm, double length_mm,
                                           double e_star_MPa, const std::function<double(double)>& gap_y,
                                           int nx, int ny, double half_width_hint_mm,
                                           HalfSpaceSolver& solver);

}  // namespace camopt::contact
