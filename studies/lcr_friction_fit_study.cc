// Study kind "lcr_friction_fit": fits friction parameters of the LCR to measured input torques
// (e.g. Table 4 of the paper) by bounded least squares with Ceres, and reports the fitted values,
// residuals and their uncertainty (ceres::Covariance).
//
// The friction model is model/lcr/friction.h (the paper's eq. 32 plus a no-load drag):
//     T_in(T_o) = T_drag + T_o (t_ideal + μ t_friction),
// with t_ideal, t_friction the mean F_t e and |F_r| e per unit output torque from the LCR pipeline.
// Residuals are weighted by the measurements' standard deviations, so (J^T J)^-1 is the parameter
// covariance when those deviations are the measurement errors.
#include "studies/lcr_friction_fit_study.h"

#include <algorithm>
#include <cmath>

#include <boost/math/special_functions/gamma.hpp>

#include "model/lcr/cycle.h"
#include "model/lcr/kinematics.h"
#include "objectives/problem.h"
#include "studies/format.h"
#include "studies/kind.h"
#include "studies/lcr_input.h"
#include "studies/material_input.h"
#include "studies/report.h"
#include "studies/work_limits.h"
#include "studies/writers.h"

namespace camopt::studies::lcr_friction_fit {
namespace {

// The friction coefficient starts at the paper's μ, the drag at none (each clamped into its bounds).
constexpr double kStartFriction = lcr::kPaperFrictionCoefficient, kStartDrag = 0.0;

// A parameter's bounds and start: equal bounds leave nothing to fit (and Ceres refuses them with an
// opaque message); a start within the bounds.
void CheckParameter(const Input::Parameter& in, double default_start, const Node& root, const char* key) {
  const auto node = [&](const char* field) { return root["parameters"][key][field]; };
  const double lower = in.bounds[0], upper = in.bounds[1];
  if (!(lower < upper)) node("bounds").Fail("[lower, upper] with lower < upper");
  const double start = in.Start(default_start);
  if (start < lower || start > upper)
    node("initial").Fail("a number within the bounds [" + std::to_string(lower) + ", " + std::to_string(upper) + "]");
}

bool AtBound(double x, const Input::Parameter& p) { return x <= p.bounds[0] + 1e-12 || x >= p.bounds[1] - 1e-12; }

}  // namespace

Input Parse(const Node& root) {
  Input in = Read<Input>(root);
  (void)ToReducer(in.reducer, root["reducer"]);
  CheckParameter(in.parameters.friction_coefficient, kStartFriction, root, "friction_coefficient");
  CheckParameter(in.parameters.drag_torque_Nm, kStartDrag, root, "drag_torque_Nm");
  return in;
}

Result Run(const Input& in, const RunContext& ctx) {
  const lcr::Reducer<double> r = ReducerOf(in.reducer);
  const std::vector<Input::Measurement>& data = in.measurements;
  // Pipeline: loads on the eccentric per unit output torque (1 N·mm), no friction.
  lcr::CycleSeries series;
  try {
    Progress progress("lcr_friction_fit", ctx.quiet);
    series = lcr::AnalyzeCycle(r, in.material ? in.material->ToMaterial() : Material{}, {1.0, 0.0, 0.0},
                               in.analysis.angle_steps, {true, false, true},
                               [&](double f) { progress.Update(f); });
  } catch (const std::domain_error& e) {
    throw StudyError(ctx.study_file + ": /reducer: infeasible geometry: " + e.what());
  }
  Result res;
  res.per_output_torque =
      lcr::MeanInputTorquePerOutputTorque(series.tangential_force_N, series.radial_force_N, r.eccentricity);
  const lcr::CycleInputTorque unit = res.per_output_torque;
  res.speed_ratio = lcr::SpeedReductionRatio(r);
  const double ratio = std::abs(res.speed_ratio);

  const Input::Parameter& mu = in.parameters.friction_coefficient;
  const Input::Parameter& drag = in.parameters.drag_torque_Nm;
  const double mu0 = mu.Start(kStartFriction), drag0 = drag.Start(kStartDrag);
  optimizers::LeastSquaresProblem p;
  p.variables = {{"friction_coefficient", mu.bounds[0], mu.bounds[1], mu0, 0.1},
                 {"drag_torque_Nm", drag.bounds[0], drag.bounds[1], drag0, 0.1}};
  const int m = static_cast<int>(data.size());
  // A measurement whose weighted residual at the start is not a number, or one whose square is not
  // (a torque of 1e308, a standard deviation of 1e-320), is the study's, not the fit's.
  for (int i = 0; i < m; ++i) {
    const double r0 = (lcr::MeanInputTorque(unit, data[i].output_torque_Nm, mu0, drag0) - data[i].input_torque_Nm) /
                      data[i].input_torque_sd_Nm;
    if (!(std::abs(r0) <= 1e100))  // its square must stay a number too
      throw StudyError(ctx.study_file + ": /measurements/" + std::to_string(i) +
                       ": expected a measurement whose weighted residual (model - measured) / input_torque_sd_Nm "
                       "is within ±1e100, found " + (std::isfinite(r0) ? Format(r0, 4) : std::string("one that is not a finite number")) +
                       " (check for extreme values such as 1e308 or 1e-300)");
  }
  p.evaluator = objectives::MakeEvaluator<2>(
      2, {{"weighted_residuals", 0, m}}, [data, unit](auto x, auto residuals) {
        using T = std::decay_t<decltype(x[0])>;
        for (size_t i = 0; i < data.size(); ++i) {
          const T model = lcr::MeanInputTorque(unit, T(data[i].output_torque_Nm), x[0], x[1]);
          residuals[i] = (model - T(data[i].input_torque_Nm)) / T(data[i].input_torque_sd_Nm);
        }
      });
  p.residuals = "weighted_residuals";
  res.fit = optimizers::SolveLeastSquares(p);
  const optimizers::FitResult& fit = res.fit;
  if (fit.x.empty())
    throw std::runtime_error("friction fit failed: " + fit.message);
  res.friction_coefficient_at_bound = AtBound(fit.x[0], mu);
  res.drag_torque_at_bound = AtBound(fit.x[1], drag);
  if (!fit.covariance.empty())
    res.correlation = fit.Correlation(0, 1);
  res.chi_square = 2 * fit.cost;
  res.degrees_of_freedom = m - 2;
  for (int i = 0; i < m; ++i) {
    Row row;
    row.fitted_input_torque_Nm = lcr::MeanInputTorque(unit, data[i].output_torque_Nm, fit.x[0], fit.x[1]);
    row.paper_input_torque_Nm =
        lcr::MeanInputTorque(unit, data[i].output_torque_Nm, lcr::kPaperFrictionCoefficient, 0.0);
    if (!fit.covariance.empty()) {
      // Standard deviation of the fitted torque, with g = ∂T_in/∂(μ, T_drag) by AD.
      using J2 = ceres::Jet<double, 2>;
      const J2 t_in = lcr::MeanInputTorque(unit, J2(data[i].output_torque_Nm), J2(fit.x[0], 0),
                                           J2(fit.x[1], 1));
      row.fitted_input_torque_sd_Nm = fit.PropagatedStandardDeviation({t_in.v[0], t_in.v[1]});
    }
    row.output_torque_Nm = data[i].output_torque_Nm;
    row.measured_input_torque_Nm = data[i].input_torque_Nm;
    row.measured_sd_Nm = data[i].input_torque_sd_Nm;
    row.residual_Nm = row.fitted_input_torque_Nm - data[i].input_torque_Nm;
    row.weighted_residual = fit.residuals[i];
    row.fitted_efficiency = lcr::Efficiency(data[i].output_torque_Nm, row.fitted_input_torque_Nm, ratio);
    row.measured_efficiency = lcr::Efficiency(data[i].output_torque_Nm, data[i].input_torque_Nm, ratio);
    res.rows.push_back(row);
  }
  // result.json's members (Result's Serialize).
  res.name = in.name;
  res.fit_status = optimizers::ToString(fit.status);  // "status" is the answer's one status (studies/status.h)
  res.model = "T_in = drag_torque + mean[(F_t + mu |F_r|) e] (paper eq. 32 plus a no-load drag)";
  Result::FittedParameter* fitted[2] = {&res.parameters.friction_coefficient, &res.parameters.drag_torque_Nm};
  const bool at_bound[2] = {res.friction_coefficient_at_bound, res.drag_torque_at_bound};
  for (int i = 0; i < 2; ++i) {
    fitted[i]->value = fit.x[i];
    if (!fit.standard_errors.empty()) fitted[i]->standard_error = fit.standard_errors[i];
    fitted[i]->at_bound = at_bound[i];
  }
  if (!fit.covariance.empty())
    res.covariance = std::array<std::array<double, 2>, 2>{
        {{fit.covariance[0], fit.covariance[1]}, {fit.covariance[2], fit.covariance[3]}}};
  else
    res.notes = std::vector<std::string>{"the Jacobian is rank deficient at the fit: no covariance"};
  const int dof = res.degrees_of_freedom;
  res.reduced_chi_square = dof > 0 ? res.chi_square / dof : NAN;
  // The chi-square test: P(χ²(dof) ≥ χ²) = Q(dof/2, χ²/2), the regularized upper incomplete gamma.
  res.chi_square_p_value = dof > 0 ? boost::math::gamma_q(0.5 * dof, 0.5 * res.chi_square) : NAN;
  res.chi_square_p_value_limit = in.limits.chi_square_p_value;
  res.solver = {fit.message, fit.iterations, fit.residual_evaluations};
  double tmax = 0;
  for (const Input::Measurement& d : data) tmax = std::max(tmax, d.output_torque_Nm);
  tmax *= 1.1;
  for (int i = 0; i <= 20; ++i) {
    res.line_output_torque_Nm.push_back(tmax * i / 20);
    res.line_input_torque_Nm.push_back(
        lcr::MeanInputTorque(unit, res.line_output_torque_Nm.back(), fit.x[0], fit.x[1]));
  }
  return res;
}

void Write(const Input& in, const Result& res, Outputs& out) {
  out.SetResult(res);
  if (res.fit.status != optimizers::SolverStatus::kConverged)
    out.SetStatus(Status::kNotConverged, std::string("the fit stopped: ") + optimizers::ToString(res.fit.status));
  std::vector<double> to, tin, tsd, tfit, resid;
  for (size_t i = 0; i < res.rows.size(); ++i) {
    to.push_back(in.measurements[i].output_torque_Nm);
    tin.push_back(in.measurements[i].input_torque_Nm);
    tsd.push_back(in.measurements[i].input_torque_sd_Nm);
    tfit.push_back(res.rows[i].fitted_input_torque_Nm);
    resid.push_back(res.rows[i].residual_Nm);
  }
  Table t;
  t.Add("output_torque_Nm", to);
  t.Add("measured_input_torque_Nm", tin);
  t.Add("fitted_input_torque_Nm", tfit);
  t.Add("residual_Nm", resid);
  out.Add("fit.csv", ToCsv(t));
  out.Add("fit.svg", SvgLinePlot({{"fitted model", res.line_output_torque_Nm, res.line_input_torque_Nm},
                                  {"measured (± standard deviation)", to, tin, tsd, SeriesStyle::kMarkers}},
                                 {"Input torque against output torque", "output torque [N·m]",
                                  "input torque [N·m]"}));
}

namespace {
// Fidelity for `camopt run --convergence` (studies/convergence.h): the angle grid of the model's
// mean input torque (Ceres' tolerances are fixed).
Fidelity Knobs(const nlohmann::json&) {
  Fidelity f;
  f.knobs.push_back({"angle_steps", {"/analysis/angle_steps"}, Input::Analysis{}.angle_steps, 2, true, 0,
                     "samples of the input revolution in the torque model"});
  f.headlines = {"/parameters/friction_coefficient/value", "/parameters/drag_torque_Nm/value",
                 "/chi_square"};
  return f;
}

// The work limit (studies/work_limits.h): the torque model's angle grid over every roller (the
// model runs once, at a unit torque; the fit scales it), and the measurements.
WorkEstimate EstimateWork(const nlohmann::json& study, const std::string& file, double factor) {
  const Input in = Read<Input>(Node(&study, file, ""));
  const double steps = in.analysis.angle_steps;
  const double rollers = in.reducer.input.rollers + in.reducer.output.rollers;
  return LargestTerm({{steps * rollers, "/analysis/angle_steps",
                       WorkNumber(steps) + " angle steps × " + WorkNumber(rollers) + " rollers"},
                      {double(in.measurements.size()), "/measurements", "measurements"}},
                     2e7 * factor, "roller contact evaluations", 64);
}

CAMOPT_REGISTER_KIND(Kind<Input, Result>{
    .name = "lcr_friction_fit",
    .title = "camopt study: friction coefficient and drag of a lobe cam reducer fitted to measured input torques",
    .run = Run, .parse = Parse, .write = Write, .knobs = Knobs, .estimate = EstimateWork,
    .report = std::vector<Headline>{
        {"friction coefficient", "/parameters/friction_coefficient/value", "", "", NAN, true,
         "/parameters/friction_coefficient/standard_error"},
        {"no-load drag torque", "/parameters/drag_torque_Nm/value", "N·m", "", NAN, true,
         "/parameters/drag_torque_Nm/standard_error"},
        {"chi-square test p-value (the model within the measurements' standard deviations)", "/chi_square_p_value", "",
         "/chi_square_p_value_limit", NAN, false},
        {"reduced chi-square", "/reduced_chi_square", ""},
        {"degrees of freedom", "/degrees_of_freedom", ""},
        {"solver status", "/status", ""},
    },
    .init_example = "lcr_friction_fit"});
}  // namespace

}  // namespace camopt::studies::lcr_friction_fit
