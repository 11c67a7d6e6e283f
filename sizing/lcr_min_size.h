// The minimum-size search of one LCR lobe/roller combination, to the optimum of the exact
// constraints: the cycle maxima of contact stress and roller force as the dense check evaluates
// them (lcr_analysis' grid of 3600 input angles over the full cycle), the exact undercut margin
// (lcr::UndercutMargin) and roller gap.
//
// 0. With a life limit, the longest life the combination reaches (MakeLcrLongestLifeProblem: the
//    life rows' smallest margin maximised over the geometric rows alone, a relaxation, from the
//    same starts). When even that, raised by its sampling error (the relative difference of the
//    rows' life and the dense check's at that design, plus 1%), is below the limit, no design of
//    the combination can meet it: the combination is reported infeasible without a size solve
//    (`life_out_of_reach`). A life limit that removes most combinations costs one small solve
//    each instead of an optimizer's search for a feasible point that does not exist (the
//    ratio −90 example at 20000 h, 3000 rpm: 224 s of CPU with Ipopt before this step).
//    The maximisation is local (from the size solve's starts); the life grows with the size
//    and the eccentricity, so its maximum sits on the variable bounds and geometric rows.
// 1. Smooth phase: the aggregate problem (one soft-max row per cam and quantity, kAggregate of
//    lcr_sizing.h) from several starting points. Its soft max over-estimates the cycle maximum by
//    up to scale·ln(N)/k, so its optimum is feasible but short of the limit (1484 of 1500 MPa on
//    the ratio −90 example: a 1.4% larger reducer).
// 2. Polish from each smooth optimum: the same problem with one row per peak that comes near a
//    limit (kActiveSet with tracked peaks): the dense check finds, per cam and quantity (roller
//    force, contact stress), the rollers' local maxima in angle within 3% of the limit (or of the
//    current maximum), one per phase of the cam's load period (a peak repeats every period on the
//    next roller), at most 4; each becomes a row "largest force (smallest Hertz margin) of that
//    roller within ±1/8 period", its maximiser found on values, so the row follows the peak as the
//    design moves and is never below the dense grid's value. After each solve the dense check runs
//    again; peaks that came near the limit join the set (or re-centre the one they belong to) and
//    the problem is solved again from the last point, until the dense check holds (at most 8
//    rounds). Samples far from the limit carry no row: they are inactive at the optimum of the
//    full dense problem, so a KKT point of the small problem is one of the dense problem (Drake's
//    MinimumValueConstraint makes the same argument with its influence distance).
// 3. A combination is `converged` only when the optimizer's own test passes on the last polish
//    and the dense check holds at its point (with the power-loss objective, also when the dense
//    check has the lubricated operating point). Its starts are compared by the objective's value
//    on the dense check (LcrObjectiveValue: the outer diameter, or the lubricated loss over the
//    check's 3600 angles, the accurate value of the problem's 48-angle mean).
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "model/lcr/reducer.h"
#include "sizing/limit_slope.h"
#include "objectives/lcr_dense_check.h"
#include "objectives/lcr_sizing.h"
#include "objectives/verification.h"
#include "optimizers/solver.h"

namespace camopt::sizing {
// The sizing loops speak the objectives' vocabulary (problems, limits, the verification contract).
using namespace camopt::objectives;

struct LcrMinSizeOptions {
  optimizers::SolverOptions solver;  ///< backend, tolerances, limits of each local solve
  int starts = 3;                    ///< smooth-phase starting points (LcrStartingPoints)
  int dense_steps = 3600;            ///< the dense check's grid over the full cycle
  int max_polish_rounds = 8;
  /// Form of the smooth phase (kAggregate or kSamples: one row per uniform sample).
  LcrConstraintForm smooth_form = LcrConstraintForm::kAggregate;
  /// false: stop after the smooth phase (for comparisons; its optimum is then `converged` only
  /// when the dense check holds there).
  bool polish = true;
};

/// Result of one start (smooth phase and its polish).
struct LcrStartOutcome {
  optimizers::SolverStatus status = optimizers::SolverStatus::kFailed;
  bool converged = false;            ///< optimizer's test and dense check both hold
  double outer_diameter_mm = 0.0;    ///< meaningful when converged
  double objective = 0.0;            ///< LcrObjectiveValue at its design; meaningful when converged
};

/// Result of one combination.
struct LcrMinSizeOutcome {
  /// The last solve of the chosen start, evaluation counts summed over every solve of every start.
  optimizers::SolverResult result;
  std::vector<double> x;                        ///< its variables (empty when every start failed)
  std::optional<lcr::Reducer<double>> design;   ///< the optimum, or the closest point when infeasible
  std::optional<LcrDenseCheck> check;           ///< dense check of design against the study's limits
  bool converged = false;
  int polish_rounds = 0;                        ///< of the chosen start
  std::vector<LcrStartOutcome> starts;          ///< every start, in order
  LcrActiveSet active;                          ///< the chosen start's last active set
  std::string note;                             ///< why a design has no check, when it has none
  /// With a life limit, when the longest-life solve (step 0 of the header comment) found no design
  /// that reaches the limit: the longest life the combination reaches, the larger of the life rows'
  /// and the dense check's value at the longest-life design. Unset when a start reached the limit
  /// (the solve stops there) or did not converge.
  std::optional<double> longest_life_h;
  /// The longest life, raised by its sampling error, is below the limit: the size was not solved,
  /// `design` and `check` are the longest-life design's (its violations say by how much).
  bool life_out_of_reach = false;
};

/// Solves one combination (spec's lobe/roller counts, roller options and the study's own limits;
/// spec.form is ignored) to the optimum of the exact constraints.
LcrMinSizeOutcome SolveLcrMinSize(const LcrSizingSpec& spec, const LcrMinSizeOptions& options);

/// d(objective)/d(limit) at a converged outcome [the objective's unit — mm of outer diameter, or W
/// of lubricated loss with kPowerLoss — per unit of the limit], for every limit of spec that binds
/// there (dense-check value within 0.1% of the limit; stress, load, undercut margin, roller gap,
/// efficiency, life, oil temperature, outer diameter), named by the limit key; the objective's
/// values are the dense check's (LcrObjectiveValue). Computed by re-solving the polish from
/// the optimum with the limit moved by ±0.5% (central difference; one-sided where the other side
/// fails), for ±0.5% of max(|limit|, 1) in the limit's unit. Negative where raising the limit
/// shrinks the reducer (stress, load: −0.046 mm/MPa on the ratio −90 example), positive where it
/// grows it (undercut margin, gap, efficiency, life_h in mm per hour). Local: the lobe combination is kept.
std::map<std::string, double> LimitSensitivity(const LcrSizingSpec& spec, const LcrMinSizeOptions& options,
                                               const LcrMinSizeOutcome& outcome);
/// The same re-solves with both sides kept (sizing/limit_slope.h): left, right, central, kink.
/// LimitSensitivity is their `slope`.
std::map<std::string, LimitSlope> LimitSlopes(const LcrSizingSpec& spec, const LcrMinSizeOptions& options,
                                              const LcrMinSizeOutcome& outcome);

/// The smallest value of an upper limit ("contact_stress_MPa" or "roller_load_N") at which spec
/// has a converged design, the other limits held, to 1%; for the lower limit "life_h", the largest.
/// For a study where nothing fits: the value of the blocking limit that would admit this
/// combination. Each trial is a whole SolveLcrMinSize of 1 start. Without `near`: the limit doubled
/// (halved for life_h) until a design fits, at most 6 times, then bisected. With `near`, the
/// limit's value at the closest point the search reached: the first trial is 1% past it and the
/// bracket is stepped from there by factors 1.01, 1.02, 1.04, … (each squared, at most 2), which takes 2–4
/// trials instead of about 8 when the closest point is near the answer. Empty when none fits within
/// 64 times the limit. `solves`, when given, receives the number of trials.
std::optional<double> LimitToFit(const LcrSizingSpec& spec, const LcrMinSizeOptions& options,
                                 const std::string& key, std::optional<double> near = std::nullopt,
                                 int* solves = nullptr);

}  // namespace camopt::sizing
