// The finite-length contact model over an LCR revolution (docs/lcr.md "Crowned rollers
// and 3D contact"), double only: per angle, the largest contact pressure of one cam by the chosen
// model (model/lcr/contact3d.h), with the force and effective radius of the contact that sets it.
//
// Cost: a slices solve takes milliseconds, and a revolution has (angles × loaded rollers) contacts.
// All contacts of one cam share the gap along y (crowning, misalignment, length), so the slices
// peak depends on the contact only through (F, R'). The ratio ρ = p_slices / p_line (smooth in
// both) is tabulated on a grid of 13 forces (geometric, F_max/1000 … F_max) × 5 radii (linear over
// the radii met) and interpolated bilinearly in (ln F, R'); the contacts of the largest
// interpolated pressures (the worst 4, distinct angles) are then solved exactly, and the largest
// difference between interpolated and exact pressure there is reported as the interpolation error.
// The cam's maximum and the pressure along the roller are those exact solves. For `half_space` the
// same worst contacts are solved with the DC-FFT model (its cell size reported); the per-angle
// series stay the slices model's.
#pragma once

#include <array>
#include <vector>

#include "model/lcr/contact3d.h"
#include "model/lcr/cycle.h"

namespace camopt::lcr {

struct Contact3DCycleSide {
  std::vector<double> max_stress_MPa;    // per angle: largest pressure over the loaded rollers
  std::vector<double> stress_force_N;    // per angle: F of the contact that sets it
  std::vector<double> stress_radius_mm;  // per angle: R' of that contact
  double max_contact_stress_MPa = 0;     // over the revolution (+inf on an undercut contact)
  int worst_angle = -1, worst_roller = -1;
  bool edge_loaded = false;              // the pressure reaches an end of the contact at some angle
  std::vector<double> worst_y_mm, worst_pressure_MPa;  // along the roller at the worst contact
  double slice_width_mm = 0;             // resolution of the slices model
  double cell_dx_mm = 0, cell_dy_mm = 0; // half_space cell size
  double interpolation_error_MPa = 0;    // see the header comment (0 for line)
  double slices_peak_at_worst_MPa = 0;   // half_space: the slices model at the same contact
  bool converged = true;
  int half_space_iterations = 0;         // half_space: the solver's iterations, summed over the solves
};

/// series: the forces of AnalyzeCycle (roller_force_N per angle). @pre series.theta_rad not empty.
/// Every half_space solve starts cold (the solver's own Hertz-like start).
Contact3DCycleSide AnalyzeCycleContact3D(const Reducer<double>& r, Side s, const CycleSeries& series,
                                         double e_star, const RollerCrowning<double>& crowning,
                                         const ContactModelOptions& options);

/// Where a half_space solve of AnalyzeCycleContact3DOnGrids starts from. A start changes the
/// iterations, not the equations or the stopping test (the relative pressure change of
/// contact::SolverOptions::tolerance): the results agree with cold starts to about that tolerance.
struct HalfSpaceStarts {
  /// A grid of twice the cells of the grid before it in both directions (over the same extent:
  /// the same contact, the same X) starts each contact from that grid's pressure, each coarse
  /// cell's value on its four fine cells.
  bool from_coarser_grid = false;
  /// Otherwise each solve after a grid's first starts from the previous contact's pressure on
  /// the same grid, cell by cell (the grid is scaled to each contact's slice half-width, so the
  /// fields of neighbouring worst contacts are alike cell by cell).
  bool from_previous_contact = false;
};

/// AnalyzeCycleContact3D with the half_space model on several grids (nx, ny) at once: the slices
/// part (tables, per-angle series, the worst contacts and their exact slices solves) is computed
/// once, and the same worst contacts are solved on each grid; one result per grid (the series are
/// the same in all). Other models: grids only sets the number of (identical) results.
std::vector<Contact3DCycleSide> AnalyzeCycleContact3DOnGrids(const Reducer<double>& r, Side s,
                                                             const CycleSeries& series, double e_star,
                                                             const RollerCrowning<double>& crowning,
                                                             const ContactModelOptions& options,
                                                             const std::vector<std::array<int, 2>>& grids,
                                                             const HalfSpaceStarts& starts);

}  // namespace camopt::lcr
