// The solver-facing side of a Problem: options, a status that says what happened, and one entry
// point that dispatches to the adapters (NLopt, Ipopt). Each adapter only translates: bounds and
// infinities, scaling, constraint splitting, gradients from the evaluator's Jacobian.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "objectives/problem.h"

namespace camopt::optimizers {

enum class SolverStatus {
  kConverged,       ///< the backend reports success and the final design satisfies every constraint
  kInfeasible,      ///< the backend stopped at a design that violates a constraint ("stopped_infeasible":
                    ///< about that end point only; a study reporting the best feasible point it saw
                    ///< may still have one — its own `feasible` says so)
  kIterationLimit,  ///< evaluation/iteration/time limit reached (design feasible or not: see violation)
  kNotStationary,   ///< "not_stationary": the backend reported success at a feasible design where the
                    ///< objective still falls inside the feasible set (optimizers/first_order.h), also
                    ///< after one resumption from there
  kFailed,          ///< numerical failure or a non-finite model output; no design is reported
};
const char* ToString(SolverStatus status);

/// The optimizers camopt drives: Ipopt (interior point with exact first derivatives and a
/// limited-memory Hessian) and NLopt's SLSQP and MMA (exact first derivatives) and COBYLA (values
/// only).
enum class Backend { kIpopt, kSlsqp, kMma, kCobyla };
/// A backend's one spelling, in studies, result.json and messages alike: "ipopt", "slsqp", "mma",
/// "cobyla".
const char* ToString(Backend backend);
/// The backend of a spelling. The old spellings "nlopt_slsqp", "nlopt_mma" and "nlopt_cobyla" are
/// accepted (*deprecated is then set); nullopt: no backend is spelt so.
std::optional<Backend> BackendFromName(std::string_view name, bool* deprecated = nullptr);
/// Every backend, in the enum's order.
std::vector<Backend> Backends();

struct SolverOptions {
  Backend backend = Backend::kIpopt;
  double tolerance = 1e-8;             ///< relative optimality / step tolerance
  double constraint_tolerance = 1e-6;  ///< on scaled constraints, also used to judge feasibility
  int max_evaluations = 3000;          ///< NLopt: evaluations; Ipopt: iterations
  /// Ipopt only: also stop, as at the iteration limit, once this many model runs (values and
  /// Jacobians, its line searches' trial points included) are spent; <= 0: no such limit.
  int max_model_runs = 0;
  double max_seconds = 60.0;
  /// Ipopt only; 0 (the default) leaves Ipopt's own test alone. k > 0: Ipopt also stops, as
  /// converged, once k consecutive iterations meet every constraint within constraint_tolerance
  /// (scaled) and change the objective by less than `stall_change` (relative) — Ipopt's acceptable
  /// level with the optimality part left out. For problems whose constraints are only piecewise
  /// smooth (a discretised contact model), where the multipliers, and with them Ipopt's
  /// optimality error, jump from one iteration to the next at a kink although the design no longer
  /// moves (docs/optimization.md).
  int stall_iterations = 0;
  /// The stall test's constraint violation (largest over the rows, in the rows' own units, as
  /// Ipopt measures it): the model's noise level on the constraints. <= 0: constraint_tolerance.
  double stall_violation = 0;
  /// The stall test's objective change per iteration (relative, Ipopt's
  /// acceptable_obj_change_tol); <= 0: `tolerance`. On a piecewise-smooth model the iterates
  /// circle a kink at the level of its switching, so a change finer than the answer is judged to
  /// (the verification's slack) is never reached although the design no longer moves.
  double stall_change = 0;
  /// Ipopt's initial barrier parameter (mu_init, with the monotone barrier update); <= 0: Ipopt's
  /// defaults (adaptive update). A small value suits a start close to an active constraint or
  /// to many epigraph rows at once, which the default barrier pushes far away first. NLopt ignores it.
  double barrier_initial = 0;
  /// Ipopt's bound_push and bound_frac (how far the start is moved into the interior of its
  /// bounds and constraint slacks); <= 0: Ipopt's default (1e-2). NLopt ignores it.
  double bound_push = 0;
  /// Ipopt's limited-memory Hessian in the augmented system as extra rows and columns (its
  /// limited_memory_aug_solver "extended") instead of Sherman–Morrison, which solves the system
  /// 2 × (history) more times per factorization. For a few variables and hundreds of rows the
  /// solves are most of the run: disc_cam_min_size_oscillating 0.79 → 0.43 s, disc_cam_motion
  /// 2.66 → 2.13 s, answers within the solver tolerance. Off by default: the cycloid sizings,
  /// which follow the solves' last digits, end elsewhere with it (paper: a start stopped
  /// infeasible). NLopt ignores it.
  bool ipopt_extended_low_rank = false;
  /// Starting point (unscaled); empty: the variables' own initial values. Clamped to the bounds.
  std::vector<double> initial;
  /// When the backend stops at its iteration limit (or stalls infeasible), its last point is
  /// polished by this backend (same tolerances, its own evaluation budget); none: no fallback.
  /// The result is the fallback's when it converges, else the first backend's. Its message says
  /// which backend finished.
  std::optional<Backend> fallback_backend;
  int fallback_max_evaluations = 3000;
};

struct SolverResult {
  SolverStatus status = SolverStatus::kFailed;
  std::string message;          ///< the backend's own words
  std::vector<double> x;        ///< the final design (unscaled); empty when status is kFailed
  double objective = 0.0;       ///< unscaled, at x
  double max_violation = 0.0;   ///< largest constraint violation at x, in scaled units
  std::vector<std::string> violated;  ///< constraint rows violated at x
  std::vector<std::string> active;    ///< constraint rows at a bound at x (within 1e-3 scaled),
                                      ///< and variables at a bound ("x lower bound")
  int value_evaluations = 0;    ///< model runs for values only (double)
  int gradient_evaluations = 0; ///< model runs with exact first derivatives (ceres::Jet)
  int iterations = 0;           ///< backend iterations where it reports them (Ipopt), else evaluations
  /// First-order optimality residual at x (optimizers/first_order.h), computed for a converged
  /// result; NaN otherwise.
  double first_order_residual = std::numeric_limits<double>::quiet_NaN();
  bool ok() const { return status == SolverStatus::kConverged; }
};

/// Solves problem (Validate()d first) with the backend named in options.
/// @throws std::invalid_argument for an unknown backend or an invalid problem.
SolverResult Solve(const objectives::Problem& problem, const SolverOptions& options);

SolverResult SolveNlopt(const objectives::Problem& problem, const SolverOptions& options);
SolverResult SolveIpopt(const objectives::Problem& problem, const SolverOptions& options);

/// Local solves from several starting points (each a full variable vector, unscaled); returns the
/// converged result with the lowest objective (or, when none converged, the first start's result),
/// with the evaluation counts of all starts summed. An empty list solves from the problem's own
/// initial point.
SolverResult SolveMultistart(const objectives::Problem& problem, const SolverOptions& options,
                             const std::vector<std::vector<double>>& starts);

/// The starting point of a solve: options.initial or the variables' initial values, in bounds.
std::vector<double> InitialPoint(const objectives::Problem& problem, const SolverOptions& options);

namespace internal {
/// Fills status-independent fields of result at x: objective, violation, active/violated rows.
/// Returns false when an output at x is not finite.
bool Assess(const objectives::Problem& problem, const std::vector<double>& x,
            double constraint_tolerance, SolverResult& result);
}  // namespace internal

}  // namespace camopt::optimizers
