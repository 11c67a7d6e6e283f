// The cycloid sizing problem (objectives/cycloid_min_size.h): every constraint row's exact
// derivative against central differences of converged evaluations, and the verified solve.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "model/cycloid/geometry_limits.h"
#include "objectives/cycloid_min_size.h"
#include "tests/reference_designs.h"

namespace camopt::objectives {
namespace {

// Central differences of converged cycles (compatibility 1e-11, CG 1e-12) against the implicit
// derivatives (CG 1e-10): measured agreement 1e-6 or better on the LTCA rows; the closed forms
// agree to rounding.
constexpr double kRowRelTol = 1e-5;

cycloid::LoadedOptions Tight() {
  cycloid::LoadedOptions o;
  o.profile_cells = 12;
  o.axial_cells = 12;
  o.tolerance = 1e-11;
  o.solver_tolerance = 1e-12;
  o.rough_solver_tolerance = 0;
  o.max_iterations = 400;
  return o;
}

CycloidSizingSpec PaperSpec() {
  CycloidSizingSpec s;
  s.drive = camopt::testing::CycloidNnm();
  s.crowning.type = cycloid::CrowningType::kLogarithmic;
  s.crowning.coefficient_mm = 0.004;
  s.crowning.effective_length_mm = 18.7;
  s.crowning.end_drop_mm = 0.006;
  s.design_torque_Nmm = 350.0e3;
  s.overload_torque_Nmm = 600.0e3;
  s.angles_per_period = 3;
  s.options = Tight();
  s.limits.contact_stress_MPa = 1500;
  s.limits.bore_radius_mm = 40;
  s.limits.min_web_mm = 5;
  s.variables = {{"eccentricity_mm", 1.0, 6.0, 4.5, 1.0},
                 {"roller_position_radius_mm", 40.0, 110.0, 90.0, 10.0},
                 {"roller_radius_mm", 2.0, 10.0, 7.2, 1.0},
                 {"face_width_mm", 10.0, 30.0, 17.0, 10.0},
                 {"effective_length_mm", 10.0, 40.0, 18.7, 10.0},
                 {"delta_position_um", -40.0, 0.0, -16.0, 10.0},
                 {"delta_radius_um", -40.0, 0.0, -8.0, 10.0},
                 {"coefficient_mm", 0.0, 0.02, 0.004, 0.001}};
  return s;
}

TEST(CycloidMinSize, EveryRowsDerivativeMatchesCentralDifferences) {
  CycloidSizingSpec spec = PaperSpec();
  CycloidSizingModel model(spec);
  CycloidFastLimits fast;
  fast.contact_stress_MPa = 1500;
  Problem p = CycloidSizingProblem(model, fast);
  const int n = p.num_vars(), m = p.evaluator->num_outputs();
  std::vector<double> x;
  for (const Variable& v : spec.variables) x.push_back(v.initial);
  std::vector<double> y(m), jac(size_t(m) * n);
  p.evaluator->EvalWithJacobian(x, y, jac);
  for (int j = 0; j < n; ++j) {
    const double h = 1e-5 * spec.variables[size_t(j)].scale;
    std::vector<double> xp = x, xm = x, yp(m), ym(m);
    xp[size_t(j)] += h;
    xm[size_t(j)] -= h;
    p.evaluator->Eval(xp, yp);
    p.evaluator->Eval(xm, ym);
    for (const OutputBlock& b : p.evaluator->blocks()) {
      double scale = 0;
      for (int r = b.offset; r < b.offset + b.size; ++r) scale = std::max(scale, std::abs(yp[r] - ym[r]) / (2 * h));
      for (int r = b.offset; r < b.offset + b.size; ++r) {
        const double fd = (yp[r] - ym[r]) / (2 * h);
        EXPECT_NEAR(jac[size_t(r) * n + j], fd, kRowRelTol * scale + 1e-12)
            << b.name << "[" << r - b.offset << "] by " << spec.variables[size_t(j)].name;
      }
    }
  }
  // The rows are not all flat: the stress rows move with every geometric variable.
  const OutputBlock& peaks = p.evaluator->block(kSizingPeakPressure);
  for (int j = 0; j < 4; ++j) {
    double largest = 0;
    for (int r = peaks.offset; r < peaks.offset + peaks.size; ++r) largest = std::max(largest, std::abs(jac[size_t(r) * n + j]));
    EXPECT_GT(largest, 1.0) << spec.variables[size_t(j)].name;
  }
}

}  // namespace
}  // namespace camopt::objectives

