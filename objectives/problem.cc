#include "objectives/problem.h"

#include <algorithm>
#include <set>

namespace camopt::objectives {

Evaluator::Evaluator(int num_vars, std::vector<OutputBlock> blocks)
    : num_vars_(num_vars), num_outputs_(0), blocks_(std::move(blocks)) {
  std::set<std::string> names;
  for (const auto& b : blocks_) {
    if (b.offset != num_outputs_ || b.size < 1)
      throw std::invalid_argument("Evaluator: output block '" + b.name + "' is not contiguous");
    if (!names.insert(b.name).second)
      throw std::invalid_argument("Evaluator: duplicate output block '" + b.name + "'");
    num_outputs_ += b.size;
  }
}

const OutputBlock& Evaluator::block(const std::string& name) const {
  for (const auto& b : blocks_)
    if (b.name == name) return b;
  throw std::out_of_range("no output named '" + name + "'");
}

void Evaluator::Eval(std::span<const double> x, std::span<double> y) const {
  if (static_cast<int>(x.size()) != num_vars_ || static_cast<int>(y.size()) != num_outputs_)
    throw std::invalid_argument("Evaluator::Eval: wrong sizes");
  DoEval(x, y);
}

void Evaluator::EvalWithJacobian(std::span<const double> x, std::span<double> y,
                                 std::span<double> jacobian) const {
  if (static_cast<int>(x.size()) != num_vars_ || static_cast<int>(y.size()) != num_outputs_ ||
      static_cast<int>(jacobian.size()) != num_outputs_ * num_vars_)
    throw std::invalid_argument("Evaluator::EvalWithJacobian: wrong sizes");
  DoEvalWithJacobian(x, y, jacobian);
}

namespace {
// A scale the solvers divide by (Ipopt's user scaling is its reciprocal): within 1e-100..1e100, so
// that neither it nor its reciprocal overflows in the linear algebra (a scale of 5e-324, a stress
// limit given as a denormal, crashed the sparse solver under Ipopt).
bool UsableScale(double s) { return s >= 1e-100 && s <= 1e100; }
}  // namespace

void Problem::Validate() const {
  if (!evaluator) throw std::invalid_argument("problem has no evaluator");
  if (evaluator->num_vars() != num_vars())
    throw std::invalid_argument("problem: evaluator and variables disagree in size");
  for (const auto& v : variables) {
    if (!(v.lower <= v.upper)) throw std::invalid_argument("variable " + v.name + ": lower > upper");
    if (!UsableScale(v.scale)) throw std::invalid_argument("variable " + v.name + ": scale must be in [1e-100, 1e100]");
    if (!std::isfinite(v.initial))
      throw std::invalid_argument("variable " + v.name + ": initial value must be finite");
  }
  if (evaluator->block(objective).size != 1)
    throw std::invalid_argument("objective '" + objective + "' is not a scalar output");
  if (!UsableScale(objective_scale)) throw std::invalid_argument("objective scale must be in [1e-100, 1e100]");
  for (const auto& c : constraints) {
    evaluator->block(c.output);
    if (!(c.lower <= c.upper)) throw std::invalid_argument("constraint " + c.output + ": lower > upper");
    if (!UsableScale(c.scale))
      throw std::invalid_argument("constraint " + c.output + ": scale must be in [1e-100, 1e100]");
  }
}

std::vector<ConstraintRow> ConstraintRows(const Problem& problem) {
  std::vector<ConstraintRow> rows;
  for (const auto& c : problem.constraints) {
    const OutputBlock& b = problem.evaluator->block(c.output);
    for (int k = 0; k < b.size; ++k)
      rows.push_back({b.offset + k, c.lower, c.upper, c.scale,
                      b.size == 1 ? b.name : b.name + "[" + std::to_string(k) + "]"});
  }
  return rows;
}

ProblemCache::ProblemCache(const Problem& problem)
    : problem_(problem),
      objective_index_(problem.evaluator->block(problem.objective).offset),
      y_(problem.evaluator->num_outputs()),
      jac_(problem.evaluator->num_outputs() * problem.evaluator->num_vars()) {}

bool ProblemCache::Same(std::span<const double> x, const std::vector<double>& cached) const {
  return std::equal(x.begin(), x.end(), cached.begin(), cached.end());
}

const std::vector<double>& ProblemCache::Values(std::span<const double> x) {
  if (have_values_ && Same(x, x_values_)) return y_;
  problem_.evaluator->Eval(x, y_);
  ++value_evaluations_;
  x_values_.assign(x.begin(), x.end());
  have_values_ = true;
  have_jacobian_ = false;
  return y_;
}

const std::vector<double>& ProblemCache::Jacobian(std::span<const double> x) {
  if (have_jacobian_ && Same(x, x_jacobian_)) return jac_;
  problem_.evaluator->EvalWithJacobian(x, y_, jac_);
  ++jacobian_evaluations_;
  x_jacobian_.assign(x.begin(), x.end());
  x_values_ = x_jacobian_;
  have_values_ = have_jacobian_ = true;
  return jac_;
}

}  // namespace camopt::objectives
