// The cycloid crowning tuning's solves (study kind cycloid_crowning_tuning; docs/cycloid.md): the
// optimizer run over the problems of objectives/cycloid_crowning.h, with its settings, and the
// choice of the reported design among the points it evaluated.
//   - Joint (any crowning's parameters and the profile modifications, exact gradients): Ipopt or
//     SLSQP on the epigraph form (minimise t with every (angle, roller) peak <= t), or COBYLA on the
//     smooth peak stress; the reported design is the best feasible point evaluated (within the
//     constraint tolerance), else the one with the largest end distance.
//   - Shorthand (the logarithmic crowning's f, and L): COBYLA from the best feasible point of the
//     stress-versus-f scan; the reported design is the best feasible point seen (scan or solve).
// The scan, the accurate model's verification rounds and the study's numbers stay with the kind.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "objectives/cycloid_crowning.h"
#include "optimizers/solver.h"

namespace camopt::sizing {
// The sizing loops speak the objectives' vocabulary (problems, limits, the verification contract).
using namespace camopt::objectives;

/// The joint tuning's limits and budget.
struct CycloidJointTuningSpec {
  CycloidTuningSpec problem;  ///< variables, limits, scale (epigraph and its start are set here)
  optimizers::Backend backend = optimizers::Backend::kIpopt;
  int max_evaluations = 60;
};

struct CycloidJointTuningOutcome {
  optimizers::SolverResult solved;
  std::vector<TuningEvaluation> history;  ///< every model run of the solve, in order
  /// The reported design: the best feasible point evaluated (`feasible`), else the one with the
  /// largest end distance, else the start.
  TuningEvaluation best;
  bool feasible = false;
  bool epigraph = false;  ///< the solver saw the exact maximum (else the soft-max)
};

/// Solves from `start` (model.Evaluate has not run it yet); on_evaluation after each model run
/// (may be empty). `model` keeps its counts.
CycloidJointTuningOutcome TuneCycloidCrowningJoint(CycloidTuningModel& model, const CycloidJointTuningSpec& spec,
                                                   const std::vector<double>& start,
                                                   const std::function<void(const TuningEvaluation&)>& on_evaluation);

struct CycloidShorthandTuningOutcome {
  optimizers::SolverResult solved;
  std::vector<CrowningEvaluation> history;  ///< the solve's model runs, in order
  CrowningEvaluation best;                  ///< the best feasible point seen (scan or solve), else the start
  bool feasible = false;
};

/// COBYLA over [f] or [f, L] from spec.initial_coefficient_mm (the start, `start`, is the best
/// feasible scan point or the widest one); `scan` the stress-versus-f curve already evaluated.
CycloidShorthandTuningOutcome TuneCycloidCrowningShorthand(
    CycloidCrowningModel& model, const CycloidCrowningSpec& spec, int max_evaluations,
    const std::vector<CrowningEvaluation>& scan, const CrowningEvaluation& start,
    const std::function<void(const CrowningEvaluation&)>& on_evaluation);

}  // namespace camopt::sizing
