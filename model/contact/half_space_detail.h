// Internals shared by the DC-FFT solver and the dense reference (not part of the interface).
#pragma once

#include <string>
#include <vector>

#include "model/contact/half_space.h"

namespace camopt::contact::detail {

/// Throws std::invalid_argument naming `where` when the grid, a field or the modulus is unusable.
void CheckGrid(const Grid& grid, const char* where);
void CheckField(const Grid& grid, const std::vector<double>& field, const char* name,
                const char* where);
void CheckModulus(double e_star_MPa, const char* where);
void CheckFinite(double value, const char* name, const char* where);

/// Fills the derived fields (load, peak, contact count, area, edge flag, cell sizes) from
/// solution.pressure_MPa.
void Summarise(const Grid& grid, ContactSolution& solution);

/// The unloaded answer: p = 0 everywhere, approach as given.
ContactSolution Unloaded(const Grid& grid, double approach_mm, std::string message);

}  // namespace camopt::contact::detail
