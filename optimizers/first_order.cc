#include "optimizers/first_order.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

namespace camopt::optimizers {

Eigen::VectorXd NonNegativeLeastSquares(const Eigen::MatrixXd& A, const Eigen::VectorXd& g) {
  const int k = int(A.cols());
  Eigen::VectorXd c = Eigen::VectorXd::Zero(k);
  std::vector<bool> passive(size_t(k), false);
  const double tol = 1e-12 * std::max(1.0, A.norm() * g.norm());
  for (int outer = 0; outer < 3 * k + 3; ++outer) {
    const Eigen::VectorXd w = A.transpose() * (g - A * c);
    int j = -1;
    for (int i = 0; i < k; ++i)
      if (!passive[size_t(i)] && w(i) > tol && (j < 0 || w(i) > w(j))) j = i;
    if (j < 0) break;
    passive[size_t(j)] = true;
    for (int inner = 0; inner < 3 * k + 3; ++inner) {
      std::vector<int> p;
      for (int i = 0; i < k; ++i)
        if (passive[size_t(i)]) p.push_back(i);
      Eigen::MatrixXd Ap(A.rows(), Eigen::Index(p.size()));
      for (size_t i = 0; i < p.size(); ++i) Ap.col(Eigen::Index(i)) = A.col(p[i]);
      const Eigen::VectorXd sp = Ap.colPivHouseholderQr().solve(g);
      Eigen::VectorXd s = Eigen::VectorXd::Zero(k);
      for (size_t i = 0; i < p.size(); ++i) s(p[i]) = sp(Eigen::Index(i));
      bool positive = true;
      for (int i : p) positive = positive && s(i) > 0;
      if (positive) {
        c = s;
        break;
      }
      double alpha = 1;
      for (int i : p)
        if (s(i) <= 0) alpha = std::min(alpha, c(i) / (c(i) - s(i)));
      c += alpha * (s - c);
      for (int i : p)
        if (c(i) <= tol) passive[size_t(i)] = false, c(i) = 0;
    }
  }
  return c;
}

FirstOrderCheck CheckFirstOrder(const objectives::Problem& p, std::span<const double> x, double row_tolerance,
                                double bound_tolerance) {
  FirstOrderCheck out;
  const int n = p.num_vars();
  const int m = p.evaluator->num_outputs();
  std::vector<double> y(static_cast<size_t>(m)), jac(static_cast<size_t>(m) * static_cast<size_t>(n));
  if (p.evaluator->has_jacobian()) {
    p.evaluator->EvalWithJacobian(x, y, jac);
  } else {
    // A value-only evaluator (its solver is derivative-free): central differences of its values,
    // one-sided at a bound, step cbrt(eps) max(1, |x_j|) kept inside the box.
    p.evaluator->Eval(x, y);
    std::vector<double> xp(x.begin(), x.end()), yp(static_cast<size_t>(m)), ym(static_cast<size_t>(m));
    for (int j = 0; j < n; ++j) {
      const objectives::Variable& v = p.variables[size_t(j)];
      const double h = std::cbrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, std::abs(x[size_t(j)]));
      const double up = std::min(x[size_t(j)] + h, v.upper), down = std::max(x[size_t(j)] - h, v.lower);
      if (!(up > down)) continue;
      xp[size_t(j)] = up;
      p.evaluator->Eval(xp, yp);
      xp[size_t(j)] = down;
      p.evaluator->Eval(xp, ym);
      xp[size_t(j)] = x[size_t(j)];
      for (int i = 0; i < m; ++i)
        jac[size_t(i) * size_t(n) + size_t(j)] = (yp[size_t(i)] - ym[size_t(i)]) / (up - down);
    }
  }
  for (double v : jac)
    if (!std::isfinite(v)) {
      out.residual = std::numeric_limits<double>::quiet_NaN();
      return out;
    }
  out.finite = true;
  const int obj = p.evaluator->block(p.objective).offset;
  for (const objectives::ConstraintRow& r : objectives::ConstraintRows(p)) {
    const double v = y[size_t(r.output_index)];
    const double tol = row_tolerance * r.scale;
    const bool at_upper = std::isfinite(r.upper) && std::abs(v - r.upper) <= tol;
    const bool at_lower = std::isfinite(r.lower) && std::abs(v - r.lower) <= tol;
    if (at_upper) out.active.push_back({r.output_index, false, r.name, 0.0});
    // An equality (or a row whose two bounds are both near) takes a multiplier of either sign.
    if (at_lower && (!at_upper || r.lower == r.upper)) out.active.push_back({r.output_index, true, r.name, 0.0});
  }
  out.any_row = !out.active.empty();
  for (int j = 0; j < n; ++j) {
    const objectives::Variable& v = p.variables[size_t(j)];
    const double tol = bound_tolerance * std::max(1.0, std::abs(v.scale));
    const bool at_upper = std::abs(x[size_t(j)] - v.upper) <= tol;
    const bool at_lower = std::abs(x[size_t(j)] - v.lower) <= tol;
    if (at_upper) out.active.push_back({-1 - j, false, v.name + " bound", 0.0});
    if (at_lower && (!at_upper || v.lower == v.upper)) out.active.push_back({-1 - j, true, v.name + " bound", 0.0});
  }
  // In the scaled variables z = x / s (d/dz = s d/dx): ∇f = Σ_lower λ ∇g − Σ_upper λ ∇g, λ >= 0.
  const double sense = p.maximize ? -1.0 : 1.0;
  Eigen::MatrixXd A(n, Eigen::Index(out.active.size()));
  Eigen::VectorXd g(n);
  for (int j = 0; j < n; ++j) {
    const double s = p.variables[size_t(j)].scale;
    g(j) = sense * s * jac[size_t(obj) * size_t(n) + size_t(j)];
    for (size_t i = 0; i < out.active.size(); ++i) {
      const FirstOrderCheck::Active& a = out.active[i];
      const double sign = a.at_lower ? 1.0 : -1.0;
      A(j, Eigen::Index(i)) = a.output_index >= 0 ? sign * s * jac[size_t(a.output_index) * size_t(n) + size_t(j)]
                                                  : (a.output_index == -1 - j ? sign * s : 0.0);
    }
  }
  out.gradient_norm = g.norm();
  if (out.gradient_norm == 0.0) return out;
  const Eigen::VectorXd lambda =
      out.active.empty() ? Eigen::VectorXd() : NonNegativeLeastSquares(A, g);
  for (size_t i = 0; i < out.active.size(); ++i) out.active[i].multiplier = lambda(Eigen::Index(i));
  out.residual = (out.active.empty() ? g : Eigen::VectorXd(g - A * lambda)).norm() / out.gradient_norm;
  return out;
}

ActiveSetPrediction PredictActiveSetStep(const objectives::Problem& from, const objectives::Problem& p,
                                         std::span<const double> x, const FirstOrderCheck& kkt) {
  ActiveSetPrediction out;
  out.x.assign(x.begin(), x.end());
  const int n = p.num_vars();
  const int m = p.evaluator->num_outputs();
  if (n == 0 || !p.evaluator->has_jacobian() || from.num_vars() != n || from.evaluator->num_outputs() != m) return out;
  std::vector<double> y(static_cast<size_t>(m)), y0(static_cast<size_t>(m)),
      jac(static_cast<size_t>(m) * static_cast<size_t>(n));
  p.evaluator->EvalWithJacobian(x, y, jac);
  from.evaluator->Eval(x, y0);
  for (size_t i = 0; i < y.size(); ++i)
    if (!std::isfinite(y[i]) || !std::isfinite(y0[i])) return out;
  for (double v : jac)
    if (!std::isfinite(v)) return out;
  out.finite = true;
  std::vector<const objectives::ConstraintRow*> by_output(static_cast<size_t>(m), nullptr),
      from_output(static_cast<size_t>(m), nullptr);
  const std::vector<objectives::ConstraintRow> rows = objectives::ConstraintRows(p), from_rows = objectives::ConstraintRows(from);
  for (const objectives::ConstraintRow& r : rows) by_output[size_t(r.output_index)] = &r;
  for (const objectives::ConstraintRow& r : from_rows) from_output[size_t(r.output_index)] = &r;
  // The free variables (an active bound with a multiplier is held) and the rows kept at their bound.
  std::vector<bool> held(static_cast<size_t>(n), false);
  struct Kept {
    int output;
    double change;  // (b' − g'(x)) − (b − g(x))
  };
  std::vector<Kept> kept;
  for (const FirstOrderCheck::Active& a : kkt.active) {
    if (a.output_index < 0) {
      if (a.multiplier > 0) held[size_t(-1 - a.output_index)] = true;
      continue;
    }
    const objectives::ConstraintRow* r = a.output_index < m ? by_output[size_t(a.output_index)] : nullptr;
    const objectives::ConstraintRow* r0 = a.output_index < m ? from_output[size_t(a.output_index)] : nullptr;
    if (!r || !r0) continue;
    const double bound = a.at_lower ? r->lower : r->upper, bound0 = a.at_lower ? r0->lower : r0->upper;
    if (!std::isfinite(bound) || !std::isfinite(bound0)) continue;
    const double change = (bound - y[size_t(a.output_index)]) - (bound0 - y0[size_t(a.output_index)]);
    const bool tightened = a.at_lower ? change > 0 : change < 0;
    if (a.multiplier > 0 || tightened) kept.push_back({a.output_index, change});
  }
  std::vector<int> free;
  for (int j = 0; j < n; ++j)
    if (!held[size_t(j)]) free.push_back(j);
  if (kept.empty() || free.empty()) return out;
  auto jacobian = [&](int output, int j) { return jac[size_t(output) * size_t(n) + size_t(j)]; };
  auto solve = [&]() -> Eigen::VectorXd {
    Eigen::MatrixXd J(Eigen::Index(kept.size()), Eigen::Index(free.size()));
    Eigen::VectorXd r(Eigen::Index(kept.size()));
    for (size_t i = 0; i < kept.size(); ++i) {
      // Each row in units of its scale, so that an over-determined set is fitted row by row alike.
      const double row_scale = by_output[size_t(kept[i].output)]->scale;
      r(Eigen::Index(i)) = kept[i].change / row_scale;
      for (size_t k = 0; k < free.size(); ++k)
        J(Eigen::Index(i), Eigen::Index(k)) = jacobian(kept[i].output, free[k]) * p.variables[size_t(free[k])].scale / row_scale;
    }
    return J.completeOrthogonalDecomposition().solve(r);
  };
  Eigen::VectorXd dz = solve();
  // A row the step would carry past its bound (to first order) joins the kept rows at its bound:
  // a piecewise maximum's other pieces, or a row a little outside the active window.
  for (int round = 0; round < 4 && dz.allFinite(); ++round) {
    bool added = false;
    for (const objectives::ConstraintRow& row : rows) {
      bool in = false;
      for (const Kept& k : kept) in = in || k.output == row.output_index;
      if (in) continue;
      double v = y[size_t(row.output_index)];
      for (size_t k = 0; k < free.size(); ++k)
        v += jacobian(row.output_index, free[k]) * dz(Eigen::Index(k)) * p.variables[size_t(free[k])].scale;
      if (std::isfinite(row.upper) && v > row.upper) {
        kept.push_back({row.output_index, row.upper - y[size_t(row.output_index)]});
        added = true;
      } else if (std::isfinite(row.lower) && v < row.lower) {
        kept.push_back({row.output_index, row.lower - y[size_t(row.output_index)]});
        added = true;
      }
    }
    if (!added) break;
    dz = solve();
  }
  if (!dz.allFinite()) return out;
  const int obj = p.evaluator->block(p.objective).offset;
  for (size_t k = 0; k < free.size(); ++k) {
    const int j = free[k];
    const objectives::Variable& v = p.variables[size_t(j)];
    const double moved = std::clamp(x[size_t(j)] + dz(Eigen::Index(k)) * v.scale, v.lower, v.upper);
    out.objective_change += jac[size_t(obj) * size_t(n) + size_t(j)] * (moved - x[size_t(j)]);
    out.x[size_t(j)] = moved;
  }
  return out;
}

}  // namespace camopt::optimizers
