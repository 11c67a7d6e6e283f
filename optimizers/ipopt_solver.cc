// Ipopt adapter: a TNLP over a Problem. It only translates:
// - infinite bounds become +-2e19 (Ipopt's nlp_*_bound_inf is 1e19);
// - scaling goes to Ipopt as user scaling (x_scaling = 1/scale, g_scaling = 1/scale);
// - lb <= g <= ub rows pass through as they are (Ipopt takes two-sided constraints natively);
// - gradients and the dense constraint Jacobian come from the evaluator (ceres::Jet); the Hessian
//   is Ipopt's limited-memory quasi-Newton approximation;
// - a non-finite model output makes the callback return false, which Ipopt treats as an
//   evaluation error and answers by cutting the step.
#include <cmath>
#include <mutex>
#include <stdexcept>

#include <coin/IpIpoptApplication.hpp>
#include <coin/IpIpoptData.hpp>
#include <coin/IpTNLP.hpp>

#include "optimizers/cancel.h"
#include "optimizers/solver.h"

namespace camopt::optimizers {
namespace {

using Ipopt::Index;
using Ipopt::Number;

double ToIpopt(double bound) {
  if (bound == kInf) return 2e19;
  if (bound == -kInf) return -2e19;
  return bound;
}

bool AllFinite(const std::vector<double>& v) {
  for (double a : v)
    if (!std::isfinite(a)) return false;
  return true;
}

class ProblemTnlp : public Ipopt::TNLP {
 public:
  ProblemTnlp(const objectives::Problem& problem, std::vector<double> x0, int max_model_runs)
      : problem_(problem),
        cache_(problem),
        rows_(objectives::ConstraintRows(problem)),
        x0_(std::move(x0)),
        max_model_runs_(max_model_runs) {}

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag,
                    IndexStyleEnum& index_style) override {
    n = problem_.num_vars();
    m = static_cast<Index>(rows_.size());
    nnz_jac_g = n * m;  // dense
    nnz_h_lag = 0;      // limited-memory Hessian
    index_style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l,
                       Number* g_u) override {
    for (Index i = 0; i < n; ++i) {
      x_l[i] = ToIpopt(problem_.variables[i].lower);
      x_u[i] = ToIpopt(problem_.variables[i].upper);
    }
    for (Index r = 0; r < m; ++r) {
      g_l[r] = ToIpopt(rows_[r].lower);
      g_u[r] = ToIpopt(rows_[r].upper);
    }
    return true;
  }

  bool get_scaling_parameters(Number& obj_scaling, bool& use_x_scaling, Index n,
                              Number* x_scaling, bool& use_g_scaling, Index m,
                              Number* g_scaling) override {
    obj_scaling = 1.0 / problem_.objective_scale;
    use_x_scaling = use_g_scaling = true;
    for (Index i = 0; i < n; ++i) x_scaling[i] = 1.0 / problem_.variables[i].scale;
    for (Index r = 0; r < m; ++r) g_scaling[r] = 1.0 / rows_[r].scale;
    return true;
  }

  bool get_starting_point(Index n, bool init_x, Number* x, bool init_z, Number*, Number*, Index,
                          bool init_lambda, Number*) override {
    if (!init_x || init_z || init_lambda) return false;
    for (Index i = 0; i < n; ++i) x[i] = x0_[i];
    return true;
  }

  bool eval_f(Index n, const Number* x, bool, Number& obj_value) override {
    const auto& y = cache_.Values({x, static_cast<size_t>(n)});
    if (!AllFinite(y)) return false;
    obj_value = Sign() * y[cache_.objective_index()];
    return true;
  }

  bool eval_grad_f(Index n, const Number* x, bool, Number* grad_f) override {
    const auto& jac = cache_.Jacobian({x, static_cast<size_t>(n)});
    if (!AllFinite(cache_.last_values()) || !AllFinite(jac)) return false;
    const int k = cache_.objective_index();
    for (Index i = 0; i < n; ++i) grad_f[i] = Sign() * jac[k * n + i];
    return true;
  }

  bool eval_g(Index n, const Number* x, bool, Index m, Number* g) override {
    const auto& y = cache_.Values({x, static_cast<size_t>(n)});
    if (!AllFinite(y)) return false;
    for (Index r = 0; r < m; ++r) g[r] = y[rows_[r].output_index];
    return true;
  }

  bool eval_jac_g(Index n, const Number* x, bool, Index m, Index, Index* iRow, Index* jCol,
                  Number* values) override {
    if (values == nullptr) {
      for (Index r = 0; r < m; ++r)
        for (Index i = 0; i < n; ++i) {
          iRow[r * n + i] = r;
          jCol[r * n + i] = i;
        }
      return true;
    }
    const auto& jac = cache_.Jacobian({x, static_cast<size_t>(n)});
    if (!AllFinite(cache_.last_values()) || !AllFinite(jac)) return false;
    for (Index r = 0; r < m; ++r)
      for (Index i = 0; i < n; ++i) values[r * n + i] = jac[rows_[r].output_index * n + i];
    return true;
  }

  // Called once per iteration: false stops Ipopt (User_Requested_Stop) when a cancellation was
  // asked for (SolveIpopt then throws Cancelled) or the model-run budget is spent.
  bool intermediate_callback(Ipopt::AlgorithmMode, Index, Number, Number, Number, Number, Number,
                             Number, Number, Number, Index, const Ipopt::IpoptData*,
                             Ipopt::IpoptCalculatedQuantities*) override {
    if (max_model_runs_ > 0 && cache_.value_evaluations() + cache_.jacobian_evaluations() >= max_model_runs_) {
      budget_spent_ = true;
      return false;
    }
    return !CancelRequested();
  }
  bool budget_spent() const { return budget_spent_; }

  void finalize_solution(Ipopt::SolverReturn status, Index n, const Number* x, const Number*,
                         const Number*, Index, const Number*, const Number*, Number,
                         const Ipopt::IpoptData* ip_data,
                         Ipopt::IpoptCalculatedQuantities*) override {
    status_ = status;
    x_.assign(x, x + n);
    iterations_ = ip_data ? ip_data->iter_count() : 0;
  }

  Ipopt::SolverReturn status() const { return status_; }
  const std::vector<double>& x() const { return x_; }
  int iterations() const { return iterations_; }
  const objectives::ProblemCache& cache() const { return cache_; }

 private:
  double Sign() const { return problem_.maximize ? -1.0 : 1.0; }

  const objectives::Problem& problem_;
  objectives::ProblemCache cache_;
  std::vector<objectives::ConstraintRow> rows_;
  std::vector<double> x0_;
  int max_model_runs_ = 0;
  bool budget_spent_ = false;
  Ipopt::SolverReturn status_ = Ipopt::INTERNAL_ERROR;
  std::vector<double> x_;
  int iterations_ = 0;
};

}  // namespace

SolverResult SolveIpopt(const objectives::Problem& problem, const SolverOptions& options) {
  problem.Validate();
  // Debian's Ipopt 3.11 solves with the sequential MUMPS, which is not thread-safe (Ipopt's own
  // maintainers say so; Ipopt 3.14 added the same lock): one Ipopt solve at a time per process.
  // Threads of a sweep (studies/sweep.cc) therefore take turns here; MPI ranks do not.
  static std::mutex ipopt_mutex;
  const std::lock_guard<std::mutex> ipopt_lock(ipopt_mutex);
  Ipopt::SmartPtr<ProblemTnlp> tnlp = new ProblemTnlp(problem, InitialPoint(problem, options), options.max_model_runs);
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetIntegerValue("print_level", 0);
  app->Options()->SetStringValue("sb", "yes");
  app->Options()->SetStringValue("hessian_approximation", "limited-memory");
  if (options.ipopt_extended_low_rank) app->Options()->SetStringValue("limited_memory_aug_solver", "extended");
  app->Options()->SetStringValue("nlp_scaling_method", "user-scaling");
  app->Options()->SetNumericValue("tol", options.tolerance);
  app->Options()->SetNumericValue("constr_viol_tol", options.constraint_tolerance);
  app->Options()->SetIntegerValue("max_iter", options.max_evaluations);
  // The restoration phase ends at a stationary point of its own problem (least infeasibility near
  // the point it started from) to 1e-3 instead of `tol`: an infeasible combination (no design meets
  // the limits) is then reported in tens of iterations instead of hundreds spent polishing the
  // infeasibility's minimiser, which the fallback polish and the other starts settle anyway; a
  // restoration that reduces the infeasibility returns to the main phase as before (Ipopt's
  // required_infeasibility_reduction). Measured: lcr_min_size_lubricated.json 24 → 7 s, the other
  // Ipopt examples' answers unchanged (docs/performance.md).
  app->Options()->SetNumericValue("resto.tol", std::max(1e-3, options.tolerance));
  app->Options()->SetNumericValue("max_cpu_time", options.max_seconds);
  // A start near the optimum (warm start): a small fixed initial barrier, and the start kept
  // close to its bounds instead of pushed into the interior.
  if (options.barrier_initial > 0) {
    app->Options()->SetStringValue("mu_strategy", "monotone");
    app->Options()->SetNumericValue("mu_init", options.barrier_initial);
  }
  if (options.bound_push > 0) {
    app->Options()->SetNumericValue("bound_push", options.bound_push);
    app->Options()->SetNumericValue("bound_frac", options.bound_push);
  }
  if (options.stall_iterations > 0) {
    app->Options()->SetIntegerValue("acceptable_iter", options.stall_iterations);
    app->Options()->SetNumericValue("acceptable_tol", 1e19);           // optimality error: not tested
    app->Options()->SetNumericValue("acceptable_dual_inf_tol", 1e19);  // (it jumps at a kink)
    app->Options()->SetNumericValue("acceptable_compl_inf_tol", 1e19);  // (part of optimality)
    app->Options()->SetNumericValue(
        "acceptable_constr_viol_tol",
        options.stall_violation > 0 ? options.stall_violation : options.constraint_tolerance);
    app->Options()->SetNumericValue("acceptable_obj_change_tol",
                                     options.stall_change > 0 ? options.stall_change : options.tolerance);
  }

  SolverResult result;
  // No options file: Initialize() would read ./ipopt.opt from the working folder, whose options
  // override those above, so a file lying where camopt runs would change its answers unseen.
  if (app->Initialize(std::string()) != Ipopt::Solve_Succeeded) {
    result.message = "ipopt: initialisation failed";
    return result;
  }
  const Ipopt::ApplicationReturnStatus code = app->OptimizeTNLP(tnlp);
  ThrowIfCancelled();
  result.message = "ipopt application status " + std::to_string(static_cast<int>(code));
  result.value_evaluations = tnlp->cache().value_evaluations();
  result.gradient_evaluations = tnlp->cache().jacobian_evaluations();
  result.iterations = tnlp->iterations();

  const std::vector<double>& x = tnlp->x();
  if (x.size() != static_cast<size_t>(problem.num_vars()) ||
      !internal::Assess(problem, x, options.constraint_tolerance, result)) {
    result.status = SolverStatus::kFailed;
    return result;
  }
  const bool feasible = result.max_violation <= options.constraint_tolerance;
  switch (code) {
    case Ipopt::Solve_Succeeded:
    case Ipopt::Solved_To_Acceptable_Level:
    case Ipopt::Feasible_Point_Found:
      result.status = feasible ? SolverStatus::kConverged : SolverStatus::kInfeasible;
      break;
    case Ipopt::Infeasible_Problem_Detected:
      result.status = SolverStatus::kInfeasible;
      break;
    case Ipopt::Maximum_Iterations_Exceeded:
    case Ipopt::Maximum_CpuTime_Exceeded:
      result.status = SolverStatus::kIterationLimit;
      break;
    case Ipopt::User_Requested_Stop:  // the model-run budget (a cancellation threw above)
      result.status = tnlp->budget_spent() ? SolverStatus::kIterationLimit : SolverStatus::kFailed;
      if (tnlp->budget_spent()) result.message += " (model-run budget spent)";
      break;
    default:
      // Restoration failure (Ipopt could not reduce the violation: reported as infeasible),
      // too-small search direction, errors: a feasible end point is still not a converged one.
      result.status = feasible ? SolverStatus::kFailed : SolverStatus::kInfeasible;
      break;
  }
  if (result.status == SolverStatus::kFailed) return result;  // no design presented
  result.x = x;
  return result;
}

}  // namespace camopt::optimizers
