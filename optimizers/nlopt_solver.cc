// NLopt adapter: translates a Problem into nlopt::opt and back. It only translates:
// - variables are scaled (the solver sees z = x / scale), bounds pass through (NLopt takes
//   +-HUGE_VAL as "no bound", which is what kInf is);
// - every constraint row lb <= g <= ub becomes the inequalities (g - ub)/s <= 0 and
//   (lb - g)/s <= 0 for its finite sides; lb == ub becomes an equality. MMA takes no equalities
//   (and stalls on an equality written as two inequalities: no interior), so with equalities MMA
//   runs inside NLopt's AUGLAG, which moves the constraints into an augmented Lagrangian and
//   gives MMA bound-constrained subproblems (AUGLAG_EQ, keeping inequalities in MMA, stalled on
//   HS71 at 17.59);
// - gradients come from the evaluator's exact Jacobian (ceres::Jet); COBYLA asks for none.
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <nlopt.hpp>

#include "optimizers/cancel.h"
#include "optimizers/solver.h"

namespace camopt::optimizers {
namespace {

struct Row {
  int output;
  double sign;    // +1: (g - bound)/s <= 0; -1: (bound - g)/s <= 0
  double bound;
  double scale;
};

class NonFiniteOutput : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Context {
  const objectives::Problem* problem;
  objectives::ProblemCache* cache;
  std::vector<double> scale;  // variable scales
  std::vector<Row> rows;      // constraint rows of one kind (inequality or equality)
  std::vector<double> x;      // unscaled work vector

  std::span<const double> Unscale(const double* z) {
    for (size_t i = 0; i < x.size(); ++i) x[i] = z[i] * scale[i];
    return x;
  }
};

void CheckFinite(const std::vector<double>& v) {
  for (double a : v)
    if (!std::isfinite(a)) throw nlopt::forced_stop();
}

double Objective(unsigned n, const double* z, double* grad, void* data) {
  if (CancelRequested()) throw nlopt::forced_stop();  // SolveNlopt throws Cancelled after optimize
  auto& c = *static_cast<Context*>(data);
  const auto x = c.Unscale(z);
  const int k = c.cache->objective_index();
  const double sign = c.problem->maximize ? -1.0 : 1.0;
  const double s = sign / c.problem->objective_scale;
  if (grad) {
    const auto& jac = c.cache->Jacobian(x);
    CheckFinite(c.cache->last_values());
    for (unsigned i = 0; i < n; ++i) grad[i] = s * jac[k * n + i] * c.scale[i];
  } else {
    CheckFinite(c.cache->Values(x));
  }
  return s * c.cache->last_values()[k];
}

void Constraints(unsigned m, double* result, unsigned n, const double* z, double* grad,
                 void* data) {
  if (CancelRequested()) throw nlopt::forced_stop();
  auto& c = *static_cast<Context*>(data);
  const auto x = c.Unscale(z);
  const std::vector<double>* jac = nullptr;
  if (grad) {
    jac = &c.cache->Jacobian(x);
    CheckFinite(c.cache->last_values());
  } else {
    CheckFinite(c.cache->Values(x));
  }
  const auto& y = c.cache->last_values();
  for (unsigned r = 0; r < m; ++r) {
    const Row& row = c.rows[r];
    const double s = row.sign / row.scale;
    result[r] = s * (y[row.output] - row.bound);
    if (grad)
      for (unsigned i = 0; i < n; ++i) grad[r * n + i] = s * (*jac)[row.output * n + i] * c.scale[i];
  }
}

nlopt::algorithm Algorithm(Backend backend) {
  if (backend == Backend::kSlsqp) return nlopt::LD_SLSQP;
  if (backend == Backend::kMma) return nlopt::LD_MMA;
  if (backend == Backend::kCobyla) return nlopt::LN_COBYLA;
  throw std::invalid_argument(std::string("not an NLopt backend: ") + ToString(backend));
}

}  // namespace

// NLopt's constraint tolerances are aimed at a tenth of the tolerance the result is judged by:
// SLSQP and MMA stop with violations of the order of their tolerance.
constexpr double kAim = 0.1;

SolverResult SolveNlopt(const objectives::Problem& problem, const SolverOptions& options) {
  problem.Validate();
  const nlopt::algorithm algorithm = Algorithm(options.backend);
  const unsigned n = problem.num_vars();
  objectives::ProblemCache cache(problem);

  Context ineq{&problem, &cache, {}, {}, std::vector<double>(n)};
  Context eq = ineq;
  std::vector<double> lb(n), ub(n), z(n);
  const std::vector<double> x0 = InitialPoint(problem, options);
  for (unsigned i = 0; i < n; ++i) {
    const auto& v = problem.variables[i];
    ineq.scale.push_back(v.scale);
    lb[i] = v.lower / v.scale;
    ub[i] = v.upper / v.scale;
    z[i] = x0[i] / v.scale;
  }
  eq.scale = ineq.scale;
  for (const auto& r : objectives::ConstraintRows(problem)) {
    if (r.lower == r.upper) {
      eq.rows.push_back({r.output_index, 1.0, r.upper, r.scale});
      continue;
    }
    if (std::isfinite(r.upper)) ineq.rows.push_back({r.output_index, 1.0, r.upper, r.scale});
    if (std::isfinite(r.lower)) ineq.rows.push_back({r.output_index, -1.0, r.lower, r.scale});
  }

  const bool augmented = algorithm == nlopt::LD_MMA && !eq.rows.empty();
  nlopt::opt opt(augmented ? nlopt::AUGLAG : algorithm, n);
  if (augmented) {
    nlopt::opt local(algorithm, n);
    local.set_xtol_rel(options.tolerance);
    local.set_ftol_rel(options.tolerance);
    local.set_maxeval(std::max(50, options.max_evaluations / 3));
    opt.set_local_optimizer(local);
  }
  opt.set_lower_bounds(lb);
  opt.set_upper_bounds(ub);
  opt.set_min_objective(Objective, &ineq);
  if (!ineq.rows.empty())
    opt.add_inequality_mconstraint(Constraints, &ineq,
                                   std::vector<double>(ineq.rows.size(), kAim * options.constraint_tolerance));
  if (!eq.rows.empty())
    opt.add_equality_mconstraint(Constraints, &eq,
                                 std::vector<double>(eq.rows.size(), kAim * options.constraint_tolerance));
  opt.set_xtol_rel(options.tolerance);
  opt.set_ftol_rel(options.tolerance);
  opt.set_maxeval(options.max_evaluations);
  opt.set_maxtime(options.max_seconds);

  SolverResult result;
  double fz = 0.0;
  nlopt::result code = nlopt::FAILURE;
  bool roundoff = false;
  try {
    code = opt.optimize(z, fz);
    result.message = "nlopt result code " + std::to_string(static_cast<int>(code));
  } catch (const nlopt::roundoff_limited&) {
    roundoff = true;
    result.message = "nlopt: roundoff limited";
  } catch (const nlopt::forced_stop&) {
    result.message = "non-finite model output; optimization stopped";
    code = nlopt::FORCED_STOP;
  } catch (const std::exception& e) {
    result.message = std::string("nlopt: ") + e.what();
    code = nlopt::FAILURE;
  }
  ThrowIfCancelled();  // a cancelled solve has no result: the caller unwinds
  result.value_evaluations = cache.value_evaluations();
  result.gradient_evaluations = cache.jacobian_evaluations();
  result.iterations = opt.get_numevals();

  std::vector<double> x(n);
  for (unsigned i = 0; i < n; ++i) x[i] = z[i] * ineq.scale[i];
  const bool finite = internal::Assess(problem, x, options.constraint_tolerance, result);
  if (!finite || code == nlopt::FORCED_STOP || (code < 0 && !roundoff)) {
    result.status = SolverStatus::kFailed;
    return result;  // x stays empty: never a NaN design as a result
  }
  result.x = x;
  const bool feasible = result.max_violation <= options.constraint_tolerance;
  if (code == nlopt::MAXEVAL_REACHED || code == nlopt::MAXTIME_REACHED)
    result.status = SolverStatus::kIterationLimit;
  else
    result.status = feasible ? SolverStatus::kConverged : SolverStatus::kInfeasible;
  return result;
}

}  // namespace camopt::optimizers
