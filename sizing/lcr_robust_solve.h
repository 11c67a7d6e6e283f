// The robust LCR sizing of one lobe/roller combination: the robust rows of objectives/lcr_robust.h
// (LcrSizingSpec::robust) solved to a design whose limits hold across the tolerances, checked by
// the nominal dense check and the linearised robust grid check.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "objectives/lcr_dense_check.h"
#include "objectives/lcr_robust.h"
#include "optimizers/solver.h"
#include "sizing/lcr_min_size.h"

namespace camopt::sizing {
// The sizing loops speak the objectives' vocabulary (problems, limits, the verification contract).
using namespace camopt::objectives;

/// The robust optimum of one combination (spec.robust set), started from x0 (the nominal optimum):
/// the aggregate form, then the samples form (one row per sample), then the robust grid check at
/// four times the problem's samples per period; a limit the grid finds broken is tightened by 1.5
/// times the excess and the samples form solved again (at most 4 rounds). Converged when the
/// optimizer's test passes, the grid check holds and the nominal dense check holds.
struct LcrRobustOutcome {
  optimizers::SolverResult result;  ///< last solve; evaluation counts summed over every solve
  std::vector<double> x;
  std::optional<lcr::Reducer<double>> design;
  std::optional<LcrDenseCheck> dense;   ///< nominal dense check (the study's limits, no tolerance)
  std::optional<LcrRobustCheck> grid;   ///< linearised robust check
  bool converged = false;
  int rounds = 0;
  std::string note;
};
LcrRobustOutcome SolveLcrRobust(const LcrSizingSpec& spec, const LcrMinSizeOptions& options,
                                const std::vector<double>& x0);

}  // namespace camopt::sizing
