// Ceres adapter for fitting: bounded nonlinear least squares, min 1/2 sum r_k(x)^2 with
// lower <= x <= upper, where the residuals r are one output block of an Evaluator (exact Jacobian
// by ceres::Jet). After the solve, ceres::Covariance gives the parameter covariance (J^T J)^-1.
// Nothing here knows about cams.
#pragma once

#include <string>
#include <vector>

#include "objectives/problem.h"
#include "optimizers/solver.h"

namespace camopt::optimizers {

struct LeastSquaresProblem {
  std::vector<objectives::Variable> variables;  ///< scale is not used: Ceres scales by Jacobi
  std::unique_ptr<objectives::Evaluator> evaluator;
  std::string residuals;  ///< name of the output block holding the (weighted) residuals
};

struct FitResult {
  SolverStatus status = SolverStatus::kFailed;
  std::string message;
  std::vector<double> x;           ///< fitted parameters; empty when status is kFailed
  std::vector<double> residuals;   ///< at x
  double cost = 0.0;               ///< 1/2 sum r^2 at x
  /// (J^T J)^-1 at x, row-major n x n: the covariance when residuals are weighted by their
  /// standard deviations. Empty when the Jacobian is rank deficient.
  std::vector<double> covariance;
  /// sqrt of the covariance diagonal (same condition); empty when not available.
  std::vector<double> standard_errors;
  int iterations = 0;
  int residual_evaluations = 0;  ///< Ceres always asks for the Jacobian with the residuals

  /// Correlation coefficient of parameters i and j, C_ij / sqrt(C_ii C_jj).
  /// @pre covariance is not empty.
  double Correlation(size_t i, size_t j) const;
  /// Standard deviation of a derived quantity q(x) to first order, sqrt(gᵀ C g), with g = ∂q/∂x
  /// at x (one entry per parameter). @pre covariance is not empty.
  double PropagatedStandardDeviation(const std::vector<double>& gradient) const;
};

/// @throws std::invalid_argument for an inconsistent problem.
FitResult SolveLeastSquares(const LeastSquaresProblem& problem, int max_iterations = 200);

}  // namespace camopt::optimizers
