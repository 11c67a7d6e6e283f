// Gap fields of the closed-form reference contacts used to validate the half-space solver
// (Hertz point and line contact, docs/papers.md §1), on a Grid of half_space.h.
#pragma once

#include <vector>

#include "model/contact/half_space.h"

namespace camopt::contact {

/// Sphere of effective radius R [mm] on a flat, first touching at (xc, yc): the paraboloid
/// h = ((x − xc)² + (y − yc)²) / (2R) [mm] at every cell centre.
inline std::vector<double> SphereGap(const Grid& grid, double radius_mm, double xc_mm = 0,
                                     double yc_mm = 0) {
  std::vector<double> h(grid.cells());
  for (int iy = 0; iy < grid.ny; ++iy)
    for (int ix = 0; ix < grid.nx; ++ix) {
      const double x = grid.x_centre_mm(ix) - xc_mm, y = grid.y_centre_mm(iy) - yc_mm;
      h[iy * grid.nx + ix] = (x * x + y * y) / (2 * radius_mm);
    }
  return h;
}

/// Straight (uncrowned) cylinder of effective radius R [mm] with its axis along y, on a flat:
/// h = x² / (2R) [mm]. The roller's length is the grid's y extent (cells only where it exists).
inline std::vector<double> CylinderGap(const Grid& grid, double radius_mm) {
  std::vector<double> h(grid.cells());
  for (int iy = 0; iy < grid.ny; ++iy)
    for (int ix = 0; ix < grid.nx; ++ix) {
      const double x = grid.x_centre_mm(ix);
      h[iy * grid.nx + ix] = x * x / (2 * radius_mm);
    }
  return h;
}

}  // namespace camopt::contact
