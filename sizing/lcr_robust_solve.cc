#include "sizing/lcr_robust_solve.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace camopt::sizing {
using namespace camopt::objectives;

LcrRobustOutcome SolveLcrRobust(const LcrSizingSpec& spec, const LcrMinSizeOptions& options,
                                const std::vector<double>& x0) {
  LcrRobustOutcome out;
  LcrSizingSpec tight = LcrTightened(spec);
  std::vector<double> x = x0;
  int values = 0, gradients = 0, iterations = 0;
  auto solve = [&](LcrConstraintForm form) {
    tight.form = form;
    optimizers::SolverOptions so = options.solver;
    so.initial = x;
    out.result = optimizers::Solve(MakeLcrSizingProblem(tight), so);
    values += out.result.value_evaluations;
    gradients += out.result.gradient_evaluations;
    iterations += out.result.iterations;
    if (!out.result.x.empty()) x = out.result.x;
  };
  solve(LcrConstraintForm::kAggregate);
  constexpr int kRounds = 4;
  for (out.rounds = 1; out.rounds <= kRounds && !out.result.x.empty(); ++out.rounds) {
    solve(LcrConstraintForm::kSamples);
    if (out.result.x.empty()) break;
    out.x = x;
    out.design = LcrDesign(spec, x);
    try {
      out.dense = DenseCheck(spec, *out.design, options.dense_steps);
      out.grid = RobustGridCheck(spec, *out.design, 4 * spec.samples_per_period);
    } catch (const std::domain_error& e) {
      out.note = std::string("degenerate geometry: ") + e.what();
      break;
    }
    if (out.result.ok() && out.dense->ok() && out.grid->ok()) {
      out.converged = true;
      break;
    }
    // Tighten what the grid found broken by 1.5 times the excess (at most 10% of the limit), and
    // solve again; a failed solve is not tightened further.
    if (!out.result.ok()) break;
    bool changed = false;
    for (const LcrViolation& v : out.grid->violations) {
      const double d = std::min(1.5 * v.excess(), 0.1 * std::max(std::abs(v.limit_value), 1.0));
      if (!(d > 0) || !std::isfinite(d)) continue;
      changed = true;
      if (v.limit == "roller_load_N") tight.limits.roller_load_N -= d;
      if (v.limit == "contact_stress_MPa") tight.limits.contact_stress_MPa -= d;
      if (v.limit == "undercut_margin_mm") tight.limits.undercut_margin_mm += d;
    }
    if (!changed) break;
  }
  out.rounds = std::min(out.rounds, kRounds);
  out.result.value_evaluations = values;
  out.result.gradient_evaluations = gradients;
  out.result.iterations = iterations;
  return out;
}

}  // namespace camopt::sizing
