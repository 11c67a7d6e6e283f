#include "optimizers/solver.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "optimizers/first_order.h"

namespace camopt::optimizers {

const char* ToString(SolverStatus status) {
  switch (status) {
    case SolverStatus::kConverged: return "converged";
    case SolverStatus::kInfeasible: return "stopped_infeasible";
    case SolverStatus::kIterationLimit: return "iteration_limit";
    case SolverStatus::kNotStationary: return "not_stationary";
    case SolverStatus::kFailed: return "failed";
  }
  return "failed";
}

const char* ToString(Backend backend) {
  switch (backend) {
    case Backend::kIpopt: return "ipopt";
    case Backend::kSlsqp: return "slsqp";
    case Backend::kMma: return "mma";
    case Backend::kCobyla: return "cobyla";
  }
  return "ipopt";
}

std::vector<Backend> Backends() { return {Backend::kIpopt, Backend::kSlsqp, Backend::kMma, Backend::kCobyla}; }

std::optional<Backend> BackendFromName(std::string_view name, bool* deprecated) {
  if (deprecated) *deprecated = false;
  for (Backend b : Backends()) {
    if (name == ToString(b)) return b;
    if (b != Backend::kIpopt && name == std::string("nlopt_") + ToString(b)) {
      if (deprecated) *deprecated = true;
      return b;
    }
  }
  return std::nullopt;
}

namespace {
SolverResult SolveWith(const objectives::Problem& problem, const SolverOptions& options) {
  if (options.backend == Backend::kIpopt) return SolveIpopt(problem, options);
  return SolveNlopt(problem, options);
}
}  // namespace

namespace {
SolverResult SolveAndPolish(const objectives::Problem& problem, const SolverOptions& options);
}  // namespace

// A converged result is held to first-order optimality (optimizers/first_order.h). When no
// constraint within 1% of its scale from its bound opposes more than half of the objective's
// gradient, the backend is resumed once from its end point (SLSQP restarts its quasi-Newton model
// there; on the contact models' piecewise-smooth rows it can stop by its objective-change test
// short of the optimum). The result is reported as not stationary when, after that, nothing lies
// within 1% of its bound (the design is inside the feasible set, where the objective still falls),
// or not even the constraints within 10% of their scale explain half of the gradient: a gross stop
// (NLopt's SLSQP returning the start, the only feasible point it met), not a kink of a discretised
// maximum at its bound whose other pieces lie a few percent away. (A cycloid sizing whose SLSQP
// stopped by its objective-change test with the stress 5.6% below its limit and nothing else near
// a bound was reported converged by the 10% window alone.)
constexpr double kResumeWindow = 1e-2;  // of a row's scale
constexpr double kStatusWindow = 1e-1;
constexpr double kStationaryResidual = 0.5;  // |∇f − Σλ∇g| / |∇f|

SolverResult Solve(const objectives::Problem& problem, const SolverOptions& options) {
  SolverResult r = SolveAndPolish(problem, options);
  if (!r.ok()) return r;
  FirstOrderCheck near = CheckFirstOrder(problem, r.x, kResumeWindow);
  r.first_order_residual = near.residual;
  if (!(r.first_order_residual > kStationaryResidual)) return r;
  SolverOptions o = options;
  o.initial = r.x;
  SolverResult again = SolveAndPolish(problem, o);
  again.value_evaluations += r.value_evaluations;
  again.gradient_evaluations += r.gradient_evaluations;
  again.iterations += r.iterations;
  const bool no_worse = problem.maximize ? again.objective >= r.objective : again.objective <= r.objective;
  if (again.ok() && no_worse) {
    near = CheckFirstOrder(problem, again.x, kResumeWindow);
    again.first_order_residual = near.residual;
    again.message = "resumed after a stop short of first-order optimality: " + again.message;
    r = std::move(again);
  } else {
    r.value_evaluations = again.value_evaluations;
    r.gradient_evaluations = again.gradient_evaluations;
    r.iterations = again.iterations;
  }
  if (r.first_order_residual > kStationaryResidual &&
      (near.active.empty() || CheckFirstOrder(problem, r.x, kStatusWindow).residual > kStationaryResidual))
    r.status = SolverStatus::kNotStationary;
  return r;
}

namespace {
// The backend, and the fallback backend from its last point when it stopped stuck.
SolverResult SolveAndPolish(const objectives::Problem& problem, const SolverOptions& options) {
  problem.Validate();
  SolverResult first = SolveWith(problem, options);
  const bool stuck = first.status == SolverStatus::kIterationLimit || first.status == SolverStatus::kInfeasible;
  if (!stuck || !options.fallback_backend || *options.fallback_backend == options.backend || first.x.empty())
    return first;
  SolverOptions o = options;
  o.backend = *options.fallback_backend;
  o.fallback_backend.reset();
  o.max_evaluations = options.fallback_max_evaluations;
  o.initial = first.x;
  SolverResult second = SolveWith(problem, o);
  SolverResult& out = second.ok() ? second : first;
  out.value_evaluations = first.value_evaluations + second.value_evaluations;
  out.gradient_evaluations = first.gradient_evaluations + second.gradient_evaluations;
  out.iterations = first.iterations + second.iterations;
  out.message = second.ok() ? std::string(ToString(options.backend)) + " stopped (" + first.message + "); " +
                                  ToString(o.backend) + " polished its last point: " + second.message
                            : first.message + " (the " + ToString(o.backend) + " polish did not converge: " +
                                  second.message + ")";
  return out;
}
}  // namespace

SolverResult SolveMultistart(const objectives::Problem& problem, const SolverOptions& options,
                             const std::vector<std::vector<double>>& starts) {
  if (starts.empty()) return Solve(problem, options);
  SolverResult best;
  bool have = false;
  int values = 0, gradients = 0, iterations = 0;
  for (const auto& x0 : starts) {
    if (x0.size() != problem.variables.size())
      throw std::invalid_argument("multistart: a starting point has the wrong size");
    SolverOptions o = options;
    o.initial = x0;
    const SolverResult r = Solve(problem, o);
    values += r.value_evaluations;
    gradients += r.gradient_evaluations;
    iterations += r.iterations;
    const bool better = r.ok() && (!best.ok() || (problem.maximize ? r.objective > best.objective
                                                                   : r.objective < best.objective));
    if (!have || better) best = r;
    have = true;
  }
  best.value_evaluations = values;
  best.gradient_evaluations = gradients;
  best.iterations = iterations;
  return best;
}

std::vector<double> InitialPoint(const objectives::Problem& problem, const SolverOptions& options) {
  if (!options.initial.empty() && options.initial.size() != problem.variables.size())
    throw std::invalid_argument("initial point has the wrong size");
  std::vector<double> x(problem.variables.size());
  for (size_t i = 0; i < x.size(); ++i) {
    const auto& v = problem.variables[i];
    x[i] = std::clamp(options.initial.empty() ? v.initial : options.initial[i], v.lower, v.upper);
  }
  return x;
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
    // A variable held at a bound binds like a constraint (a designer wants to see it).
    if (viol <= constraint_tolerance && std::isfinite(v.lower) && (x[i] - v.lower) / v.scale < 1e-6)
      result.active.push_back(v.name + " lower bound");
    if (viol <= constraint_tolerance && std::isfinite(v.upper) && (v.upper - x[i]) / v.scale < 1e-6)
      result.active.push_back(v.name + " upper bound");
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
