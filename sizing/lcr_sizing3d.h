// The minimum-size search of one LCR lobe/roller combination under the finite-length contact
// model (docs/lcr.md "Sizing with crowned rollers"): the stress limit holds for the
// slices model (model/lcr/contact3d.h) at the study's misalignment, the roller crowning
// coefficient of each cam may be a variable, and at an overload torque the pressure must stay off
// the contact's ends.
//
// Method (on top of sizing/lcr_min_size.h):
// 1. The line-model search (SolveLcrMinSize) gives the starting design; the crowning starts at
//    Lundberg's coefficient of the largest roller force (clamped to its range).
// 2. Rounds of a polish problem: the line problem in its active-set form without stress rows
//    (geometry, undercut, gap, pitch, the tracked roller-force peaks) with the crowning
//    coefficients appended as variables, plus, per tracked contact (cam, input angle, roller):
//    - `input_stress_margin_3d` / `output_...`: s = (R'/r_r)(1 − p²/p_lim²), p the slices peak
//      pressure (the line margin of lcr_sizing.h with the 3D peak; the line form where R' <= 0);
//    - `input_edge_margin` / `output_...`: at the contact's force scaled to the edge torque (the
//      overload torque when one is given, else the design torque; the forces of the load stage are
//      linear in the torque), the end slice's separation over Lundberg's length F/(π l E*) minus
//      its line load over F/l, the smaller of the two ends: positive when the pressure stays off
//      the ends, negative when it reaches one, continuous at the onset (a kink there, like any
//      max). A straight roller has no design with a positive margin: SolveLcrMinSize3D says so
//      ("edge-loaded: ... crown the rollers") without a polish.
//    Derivatives are exact: Jets through the force pipeline and the slices model's implicit step.
//    Tracked contacts are fixed (angle, roller) pairs; after each solve the dense check (3600
//    angles: the line check for geometry and forces, lcr::AnalyzeCycleContact3D for the 3D
//    stress, exact slices solves at the largest overload forces for the ends) adds the contacts
//    that come near a limit, each stress peak with the contacts 2 dense angles either side of it
//    (they bracket the peak as it moves with the design), until it holds (at most 8 rounds).
// 3. The best design is verified by the half_space model on a refined grid, with the slices
//    stress limit tightened and the polish re-run where it breaks the limit (VerifyLcrMinSize3D).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "model/lcr/contact3d.h"
#include "model/lcr/contact3d_cycle.h"
#include "sizing/lcr_min_size.h"
#include "objectives/lcr_sizing.h"
#include "objectives/verification.h"

namespace camopt::sizing {
// The sizing loops speak the objectives' vocabulary (problems, limits, the verification contract).
using namespace camopt::objectives;

struct LcrSizing3DSpec {
  lcr::ContactModelOptions contact;  ///< slices N, misalignment γ, half_space grid of the check
  /// Crowning of both cams (type and fixed parameters; the coefficient is the start value when it
  /// is a variable).
  lcr::RollerCrowning<double> crowning;
  /// Crowning parameters of each cam as variables over these ranges (empty: fixed): the
  /// logarithmic coefficient f, the radius R (circular, partial) and the flat length L0 (partial)
  /// [mm]; each adds one variable per cam (input, output).
  std::optional<std::array<double, 2>> coefficient_range_mm;
  std::optional<std::array<double, 2>> radius_range_mm;
  std::optional<std::array<double, 2>> flat_length_range_mm;
  /// The roller length and the cam thickness (one value for both cams) as variables [mm] (empty:
  /// the spec's fixed values). They set the contact length min(l_r, b_c) of the 3D rows.
  std::optional<std::array<double, 2>> roller_length_range_mm;
  std::optional<std::array<double, 2>> cam_thickness_range_mm;
  double overload_torque_Nmm = 0;  ///< 0: no end constraint

  /// Variables appended after the line problem's: 2 per crowning range, 1 per length range.
  int extra_variables() const {
    return 2 * (int(bool(coefficient_range_mm)) + int(bool(radius_range_mm)) + int(bool(flat_length_range_mm))) +
           int(bool(roller_length_range_mm)) + int(bool(cam_thickness_range_mm));
  }
};

/// One tracked contact of the 3D rows.
struct LcrContactSample {
  int side = 0;  ///< 0 input cam, 1 output cam
  double theta_rad = 0;
  int roller = 0;
  bool operator==(const LcrContactSample&) const = default;
};

/// Rows of the 3D polish problem.
struct LcrTracked3D {
  std::vector<LcrContactSample> stress, edge;
};

/// The polish problem (header step 2): variables of MakeLcrSizingProblem(base) followed by those
/// of spec3d's ranges, in this order: `input_crowning_coefficient_mm`, `output_…`,
/// `input_crowning_radius_mm`, `output_…`, `input_crowning_flat_length_mm`, `output_…`,
/// `roller_length_mm`, `cam_thickness_mm` (each pair or single only when it is a variable).
/// base: the tightened spec in kActiveSet form without a stress limit; stress_limit_MPa the
/// (tightened) 3D limit.
Problem MakeLcrSizing3DProblem(const LcrSizingSpec& base, const LcrSizing3DSpec& spec3d, double stress_limit_MPa,
                               const LcrTracked3D& tracked);

/// The 3D numbers of a design (header step 2's dense check).
struct LcrContact3DCheck {
  std::array<lcr::Contact3DCycleSide, 2> design;  ///< slices model over the cycle per cam
  std::array<double, 2> overload_edge_margin{kInf, kInf};  ///< smallest over the checked contacts
  std::array<bool, 2> overload_edge_loaded{false, false};
};

struct LcrHalfSpaceCheck {
  std::array<double, 2> half_space_MPa{}, slices_MPa{};  ///< at each cam's worst contact
  std::array<double, 2> difference_percent{};             ///< (slices − half_space)/half_space
  std::array<bool, 2> edge_loaded{false, false};
  double cell_dx_mm = 0, cell_dy_mm = 0;
  bool converged = true;
};

/// Where a polish stopped at a bound (SolveLcrMinSize3D's `bound`), to continue from.
struct LcrPolishPause {
  int next_round = 0;         ///< the polish round to continue with
  double lower_bound_mm = 0;  ///< the last round's optimum (less the solver tolerance): ≤ the final outer diameter
  double p_fast_MPa = 0;      ///< the 3D stress limit of the rows
  LcrSizing3DSpec spec3d;     ///< the 3D spec the polish runs with (the start values of its variables)
};

struct LcrMinSize3DOutcome {
  /// check->max_stress_MPa holds the 3D (slices) peaks; design carries the chosen roller length
  /// and cam thickness when they are variables.
  LcrMinSizeOutcome outcome;
  std::array<lcr::RollerCrowning<double>, 2> crowning;  ///< the chosen crowning per cam
  std::optional<LcrContact3DCheck> contact;
  LcrTracked3D tracked;
  double line_outer_diameter_mm = 0;  ///< the line-model optimum it started from (0: none)
  /// Set while the polish is stopped at a bound (not converged; design, x and the counts are
  /// those of its last round); ContinueLcrMinSize3D goes on from it.
  std::optional<LcrPolishPause> paused;
};

/// Solves one combination under the 3D contact model (header). Branch and bound over candidates
/// (sizing/sizing_driver.h): each polish round's problem has the rows of the round before and
/// more, so its optimum bounds the final outer diameter from below (as far as the local optima are
/// global ones); once a converged round's optimum (less the solver's relative tolerance) exceeds
/// `bound` [mm] the polish stops there and the outcome is `paused` with that lower bound.
LcrMinSize3DOutcome SolveLcrMinSize3D(const LcrSizingSpec& spec, const LcrSizing3DSpec& spec3d,
                                      const LcrMinSizeOptions& options, double bound = kInf);

/// Continues a paused outcome (same spec and options as its SolveLcrMinSize3D) where it stopped,
/// to the end or to the next round whose optimum exceeds `bound`: the rounds and numbers are those
/// of the polish that never stopped. @throws std::invalid_argument when out is not paused.
void ContinueLcrMinSize3D(const LcrSizingSpec& spec, const LcrMinSizeOptions& options, LcrMinSize3DOutcome& out,
                          double bound = kInf);

/// The verified-optimum contract (objectives/verification.h) of a converged outcome: the accurate
/// model is the half_space solver at the slices cycle's worst contacts (3600 input angles) on the
/// study's grid and on one with twice the cells each way; the finer value is reported with the
/// difference as its error. Checks, per cam: the contact stress at the design torque against the
/// study's limit, and the largest pressure at a contact end as a share of the peak (<= 0.01) at the
/// edge torque (the overload's, else the design torque). Where a stress check fails, the slices
/// model's stress limit is tightened by the accurate/fast ratio (TightenedUpperLimit) and the
/// polish re-run from the outcome's point (out is updated), at most 3 rounds. first_grid, when
/// given, receives the last round's half_space numbers on the study's own grid.
Verification VerifyLcrMinSize3D(const LcrSizingSpec& spec, const LcrSizing3DSpec& spec3d,
                                const LcrMinSizeOptions& options, LcrMinSize3DOutcome& out,
                                LcrHalfSpaceCheck* first_grid = nullptr);


}  // namespace camopt::sizing
