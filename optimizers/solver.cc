#include "optimizers/solver.h"

#include <cmath>
#include <stdexcept>

namespace camopt::optimizers {

const char* ToString(SolverStatus status) {
  switch (status) {
    case SolverStatus::kConverged: return "converged";
    case SolverStatus::kInfeasible: return "infeasible";
    case SolverStatus::kIterationLimit: return "iteration_limit";
    case SolverStatus::kFailed: return "failed";
  }
  return "failed";
}

std::vector<std::string> Backends() {
  return {"ipopt", "nlopt_slsqp", "nlopt_mma", "nlopt_cobyla"};
}

SolverResult Solve(const objectives::Problem& problem, const SolverOptions& options) {
  problem.Validate();
  const std::string& b = options.backend;
  if (b == "ipopt") return SolveIpopt(problem, options);
  if (b == "nlopt_slsqp" || b == "nlopt_mma" || b == "nlopt_cobyla" || b == "slsqp" ||
      b == "mma" || b == "cobyla")
    return SolveNlopt(problem, options);
  throw std::invalid_argument("unknown optimizer backend '" + b + "'");
}

namespace internal {

bool Assess(const objectives::Problem& problem, const std::vector<double>& x,
            double constraint_tolerance, SolverResult& result) {
  for (double v : x)
    if (!std::isfinite(v)) return false;
  std::vector<double> y(problem.evaluator->num_outputs());
  problem.evaluator->Eval(x, y);
  for (double v : y)
    if (!std::isfinite(v)) return false;
  result.objective = y[problem.evaluator->block(problem.objective).offset];
  result.max_violation = 0.0;
  result.violated.clear();
  result.active.clear();
  // Bounds on variables count as constraints too (a backend may step slightly outside).
  for (int i = 0; i < problem.num_vars(); ++i) {
    const auto& v = problem.variables[i];
    const double viol = std::max(v.lower - x[i], x[i] - v.upper) / v.scale;
    if (viol > constraint_tolerance) result.violated.push_back(v.name + " bound");
    result.max_violation = std::max(result.max_violation, viol);
  }
  for (const auto& row : objectives::ConstraintRows(problem)) {
    const double g = y[row.output_index];
    const double viol = std::max(row.lower - g, g - row.upper) / row.scale;
    result.max_violation = std::max(result.max_violation, viol);
    if (viol > constraint_tolerance)
      result.violated.push_back(row.name);
    else if (viol > -1e-3)
      result.active.push_back(row.name);
  }
  return true;
}

}  // namespace internal
}  // namespace camopt::optimizers
