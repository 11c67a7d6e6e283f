// An optimization problem as data: design variables with bounds and scaling, one evaluator that
// computes a set of named outputs (for double and, with exact first derivatives, for
// ceres::Jet), an objective that is one of those outputs, and constraints lb <= output <= ub on
// others. Infinite bounds are real infinities (kInf); the solver adapters in optimizers/ translate
// them (and the scaling) into what each backend wants. Nothing here knows about cams.
//
// The evaluator contract follows Drake's EvaluatorBase: a public Eval that checks sizes, a
// protected DoEval per scalar kind, and one generic DoEvalGeneric<T> written once (see
// FunctionEvaluator below, which does the ceres::Jet seeding).
#pragma once

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <ceres/jet.h>

#include "model/common/scalar.h"

namespace camopt::objectives {

/// A design variable. Bounds may be +-kInf. The solver sees x / scale, so choose scale as the
/// typical magnitude of the variable (in its own unit).
struct Variable {
  std::string name;
  double lower = -kInf;
  double upper = kInf;
  double initial = 0.0;
  double scale = 1.0;
};

/// A contiguous block of named outputs of an evaluator: a scalar (size 1) or one value per sample.
struct OutputBlock {
  std::string name;
  int offset = 0;
  int size = 1;
};

/// Computes outputs y(x) and, on request, the dense Jacobian dy/dx (row-major, outputs x vars).
class Evaluator {
 public:
  Evaluator(int num_vars, std::vector<OutputBlock> blocks);
  virtual ~Evaluator() = default;

  int num_vars() const { return num_vars_; }
  int num_outputs() const { return num_outputs_; }
  const std::vector<OutputBlock>& blocks() const { return blocks_; }
  /// The block with this name; throws std::out_of_range when absent.
  const OutputBlock& block(const std::string& name) const;

  /// y has num_outputs() entries.
  void Eval(std::span<const double> x, std::span<double> y) const;
  /// jacobian has num_outputs() * num_vars() entries, row-major.
  void EvalWithJacobian(std::span<const double> x, std::span<double> y,
                        std::span<double> jacobian) const;
  /// false for a value-only evaluator (a derivative-free solver drives it; EvalWithJacobian
  /// throws): first-order checks then difference its values (optimizers/first_order.h).
  virtual bool has_jacobian() const { return true; }

 protected:
  virtual void DoEval(std::span<const double> x, std::span<double> y) const = 0;
  virtual void DoEvalWithJacobian(std::span<const double> x, std::span<double> y,
                                  std::span<double> jacobian) const = 0;

 private:
  int num_vars_;
  int num_outputs_;
  std::vector<OutputBlock> blocks_;
};

/// An evaluator from one generic callable f(std::span<const T> x, std::span<T> y), instantiated
/// for double and for ceres::Jet<double, N>. N >= num_vars: a problem with fewer variables seeds
/// only the first num_vars derivative parts (so one Jet size serves several variants of a model).
template <int N, typename F>
class FunctionEvaluator final : public Evaluator {
 public:
  FunctionEvaluator(int num_vars, std::vector<OutputBlock> blocks, F f)
      : Evaluator(num_vars, std::move(blocks)), f_(std::move(f)) {
    if (num_vars > N) throw std::invalid_argument("FunctionEvaluator: more variables than Jet size");
  }

 protected:
  void DoEval(std::span<const double> x, std::span<double> y) const override { f_(x, y); }

  void DoEvalWithJacobian(std::span<const double> x, std::span<double> y,
                          std::span<double> jacobian) const override {
    using J = ceres::Jet<double, N>;
    const int n = num_vars(), m = num_outputs();
    std::vector<J> xj(n), yj(m);
    for (int i = 0; i < n; ++i) xj[i] = J(x[i], i);
    f_(std::span<const J>(xj), std::span<J>(yj));
    for (int k = 0; k < m; ++k) {
      y[k] = yj[k].a;
      for (int i = 0; i < n; ++i) jacobian[k * n + i] = yj[k].v[i];
    }
  }

 private:
  F f_;
};

template <int N, typename F>
std::unique_ptr<Evaluator> MakeEvaluator(int num_vars, std::vector<OutputBlock> blocks, F f) {
  return std::make_unique<FunctionEvaluator<N, F>>(num_vars, std::move(blocks), std::move(f));
}

/// lower <= output <= upper for every entry of a named output block; scale is its typical
/// magnitude (the solver sees output / scale).
struct Constraint {
  std::string output;
  double lower = -kInf;
  double upper = kInf;
  double scale = 1.0;
};

/// Minimise (or maximise) one scalar output subject to constraints on others.
struct Problem {
  std::vector<Variable> variables;
  std::unique_ptr<Evaluator> evaluator;
  std::string objective;      ///< name of a size-1 output block
  double objective_scale = 1.0;
  bool maximize = false;
  std::vector<Constraint> constraints;

  int num_vars() const { return static_cast<int>(variables.size()); }
  /// Throws std::invalid_argument for inconsistent sizes, unknown outputs, lb > ub, a scale outside
  /// [1e-100, 1e100].
  void Validate() const;
};

/// The constraint rows a solver sees: one row per output entry of each constraint.
struct ConstraintRow {
  int output_index;  ///< index into the evaluator's outputs
  double lower;
  double upper;
  double scale;
  std::string name;  ///< block name, with [k] for a sample of a vector block
};
std::vector<ConstraintRow> ConstraintRows(const Problem& problem);

/// Evaluates a problem with a one-point cache (solvers ask for f, g and their gradients at the
/// same x in separate calls) and counts how often the model ran.
class ProblemCache {
 public:
  explicit ProblemCache(const Problem& problem);

  /// Outputs at x (runs the double evaluation unless x is cached).
  const std::vector<double>& Values(std::span<const double> x);
  /// Outputs and row-major Jacobian at x (runs the Jet evaluation unless cached).
  const std::vector<double>& Jacobian(std::span<const double> x);
  const std::vector<double>& last_values() const { return y_; }

  int objective_index() const { return objective_index_; }
  int value_evaluations() const { return value_evaluations_; }
  int jacobian_evaluations() const { return jacobian_evaluations_; }

 private:
  bool Same(std::span<const double> x, const std::vector<double>& cached) const;

  const Problem& problem_;
  int objective_index_;
  std::vector<double> x_values_, x_jacobian_;
  std::vector<double> y_, jac_;
  bool have_values_ = false, have_jacobian_ = false;
  int value_evaluations_ = 0, jacobian_evaluations_ = 0;
};

}  // namespace camopt::objectives
