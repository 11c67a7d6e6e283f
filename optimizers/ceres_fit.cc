// Ceres adapter: one CostFunction over the evaluator's residual block, bounds as Ceres parameter
// bounds (finite sides only), covariance by ceres::Covariance (dense SVD, so a rank-deficient
// Jacobian is detected instead of producing garbage).
#include "optimizers/ceres_fit.h"
#include "optimizers/cancel.h"

#include <cmath>
#include <stdexcept>

#include <ceres/ceres.h>
#include <ceres/covariance.h>

namespace camopt::optimizers {
namespace {

class EvaluatorCost : public ceres::CostFunction {
 public:
  EvaluatorCost(const objectives::Evaluator& evaluator, const objectives::OutputBlock& block,
                int* count)
      : evaluator_(evaluator), block_(block), count_(count),
        y_(evaluator.num_outputs()), jac_(evaluator.num_outputs() * evaluator.num_vars()) {
    set_num_residuals(block.size);
    mutable_parameter_block_sizes()->push_back(evaluator.num_vars());
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const int n = evaluator_.num_vars();
    std::span<const double> x(parameters[0], n);
    ++*count_;
    if (jacobians && jacobians[0])
      evaluator_.EvalWithJacobian(x, y_, jac_);
    else
      evaluator_.Eval(x, y_);
    for (int k = 0; k < block_.size; ++k) {
      residuals[k] = y_[block_.offset + k];
      if (!std::isfinite(residuals[k])) return false;
      if (jacobians && jacobians[0])
        for (int i = 0; i < n; ++i) {
          jacobians[0][k * n + i] = jac_[(block_.offset + k) * n + i];
          if (!std::isfinite(jacobians[0][k * n + i])) return false;
        }
    }
    return true;
  }

 private:
  const objectives::Evaluator& evaluator_;
  objectives::OutputBlock block_;
  int* count_;
  mutable std::vector<double> y_, jac_;
};

}  // namespace

FitResult SolveLeastSquares(const LeastSquaresProblem& problem, int max_iterations) {
  if (!problem.evaluator) throw std::invalid_argument("least squares: no evaluator");
  const int n = static_cast<int>(problem.variables.size());
  if (problem.evaluator->num_vars() != n)
    throw std::invalid_argument("least squares: evaluator and variables disagree in size");
  const objectives::OutputBlock block = problem.evaluator->block(problem.residuals);

  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) {
    const auto& v = problem.variables[i];
    if (!(v.lower <= v.upper)) throw std::invalid_argument("variable " + v.name + ": lower > upper");
    x[i] = std::clamp(v.initial, v.lower, v.upper);
  }

  FitResult result;
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem cp(problem_options);
  cp.AddResidualBlock(new EvaluatorCost(*problem.evaluator, block, &result.residual_evaluations),
                      nullptr, x.data());
  for (int i = 0; i < n; ++i) {
    if (std::isfinite(problem.variables[i].lower))
      cp.SetParameterLowerBound(x.data(), i, problem.variables[i].lower);
    if (std::isfinite(problem.variables[i].upper))
      cp.SetParameterUpperBound(x.data(), i, problem.variables[i].upper);
  }

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = max_iterations;
  options.function_tolerance = 1e-14;
  options.gradient_tolerance = 1e-14;
  options.parameter_tolerance = 1e-12;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &cp, &summary);
  ThrowIfCancelled();
  result.message = summary.message;
  result.iterations = static_cast<int>(summary.iterations.size());

  for (double v : x)
    if (!std::isfinite(v)) return result;  // kFailed, no design
  if (summary.termination_type == ceres::FAILURE || !summary.IsSolutionUsable()) return result;
  result.x = x;
  result.status = summary.termination_type == ceres::CONVERGENCE ? SolverStatus::kConverged
                                                                 : SolverStatus::kIterationLimit;
  std::vector<double> y(problem.evaluator->num_outputs());
  problem.evaluator->Eval(x, y);
  result.residuals.assign(y.begin() + block.offset, y.begin() + block.offset + block.size);
  for (double r : result.residuals) result.cost += 0.5 * r * r;

  ceres::Covariance::Options cov_options;
  cov_options.algorithm_type = ceres::DENSE_SVD;
  ceres::Covariance covariance(cov_options);
  std::vector<std::pair<const double*, const double*>> blocks = {{x.data(), x.data()}};
  if (covariance.Compute(blocks, &cp)) {
    result.covariance.resize(n * n);
    covariance.GetCovarianceBlock(x.data(), x.data(), result.covariance.data());
    for (int i = 0; i < n; ++i) result.standard_errors.push_back(std::sqrt(result.covariance[i * n + i]));
  }
  return result;
}

double FitResult::Correlation(size_t i, size_t j) const {
  const size_t n = x.size();
  return covariance[i * n + j] / std::sqrt(covariance[i * n + i] * covariance[j * n + j]);
}

double FitResult::PropagatedStandardDeviation(const std::vector<double>& gradient) const {
  const size_t n = x.size();
  double variance = 0.0;
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) variance += gradient[i] * covariance[i * n + j] * gradient[j];
  return std::sqrt(variance);
}

}  // namespace camopt::optimizers
