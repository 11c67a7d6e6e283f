// First-order optimality (Karush–Kuhn–Tucker) at a design: whether the objective's gradient is a
// non-negative combination of the gradients of the constraints and bounds active there. A backend
// that reports success at a feasible point has not thereby solved the problem (NLopt's SLSQP, for
// one, returns the best feasible point it met, which can be its start when its iterates left the
// feasible set); this check is what "converged" is held to (optimizers/solver.cc).
#pragma once

#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "objectives/problem.h"

namespace camopt::optimizers {

/// Lawson–Hanson non-negative least squares: min |A c − g| subject to c >= 0.
Eigen::VectorXd NonNegativeLeastSquares(const Eigen::MatrixXd& A, const Eigen::VectorXd& g);

struct FirstOrderCheck {
  /// A constraint row or variable bound taken as active, with its multiplier λ >= 0.
  struct Active {
    int output_index = -1;  ///< the evaluator output, or −1 − j for variable j's bound
    bool at_lower = false;  ///< the row (or variable) sits at its lower bound
    std::string name;       ///< the row's name (block[k]) or the variable's name + " bound"
    double multiplier = 0;  ///< λ, in the solver's scaled variables and the rows' own units
  };
  std::vector<Active> active;
  bool any_row = false;  ///< a constraint row (not only a bound) is active
  /// |∇f − Σ_lower λ ∇g + Σ_upper λ ∇g| / |∇f| in the scaled variables x / scale (∇f of the
  /// minimised function, −f when maximising): 0 at a KKT point, 1 when no active constraint
  /// opposes any of the gradient (a point from which the objective still falls inside the
  /// feasible set). NaN when the Jacobian is not finite; 0 when ∇f = 0.
  double residual = 0;
  double gradient_norm = 0;  ///< |∇f| in the scaled variables
  bool finite = false;
};

/// The check at x (unscaled; one evaluation with the Jacobian). A row is active when its value
/// lies within row_tolerance · scale of a finite bound, a variable when within
/// bound_tolerance · max(1, |scale|) of one. The multipliers are the least-squares ones.
FirstOrderCheck CheckFirstOrder(const objectives::Problem& problem, std::span<const double> x,
                                double row_tolerance = 1e-3, double bound_tolerance = 1e-6);

/// The tangent predictor of a parametric re-solve (the first-order sensitivity of a KKT point to
/// its problem's data, Fiacco 1976, Thm. 3.2.2, with the Hessian term dropped): x is a KKT point of
/// `from` whose active set `kkt` holds, and `moved` is the same problem (the same outputs and
/// variables) with some bounds or row definitions changed. The step dz in the scaled variables
/// z = x / scale is the least-norm (least-squares where over-determined) solution of
/// J'_A dz = (b'_A − g'_A(x)) − (b_A − g_A(x)) over the active rows that carry a multiplier or that
/// the move tightens, with the active variable bounds that carry one held (dz_j = 0): each row
/// keeps the distance to its bound it had at x (a row the solver left a little inside stays so).
/// The predicted point x + dx is clipped to the box. A local solver started there continues the
/// same local optimum rather than stalling on the corner of piecewise rows it starts from.
struct ActiveSetPrediction {
  std::vector<double> x;        ///< the predicted point (x itself when nothing moves)
  double objective_change = 0;  ///< ∇f · dx, the first-order change of the objective
  bool finite = false;          ///< both problems' values and the moved one's Jacobian were finite at x
};
ActiveSetPrediction PredictActiveSetStep(const objectives::Problem& from, const objectives::Problem& moved,
                                         std::span<const double> x, const FirstOrderCheck& kkt);

}  // namespace camopt::optimizers
