// Study kind "lcr_friction_fit": fits friction parameters of the LCR to measured input torques
// (e.g. Table 4 of the paper) by bounded least squares with Ceres, and reports the fitted values,
// residuals and their uncertainty (ceres::Covariance).
//
// The friction model is model/lcr/friction.h (the paper's eq. 32 plus a no-load drag):
//     T_in(T_o) = T_drag + T_o (t_ideal + μ t_friction),
// with t_ideal, t_friction the mean F_t e and |F_r| e per unit output torque from the LCR pipeline.
// Residuals are weighted by the measurements' standard deviations, so (J^T J)^-1 is the parameter
// covariance when those deviations are the measurement errors.
#include <cmath>

#include "model/lcr/cycle.h"
#include "model/lcr/friction.h"
#include "model/lcr/kinematics.h"
#include "optimizers/ceres_fit.h"
#include "studies/lcr_input.h"
#include "studies/study.h"
#include "studies/writers.h"

namespace camopt::studies {
namespace {

struct Measurement {
  double output_torque_Nm, input_torque_Nm, sd_Nm;
};

struct Parameter {
  double initial, lower, upper;
};

Parameter ParseParameter(const Node& parent, const std::string& key, Parameter fallback) {
  if (!parent.Has(key)) return fallback;
  const Node p = parent[key];
  p.CheckKnownFields({"initial", "bounds"});
  Parameter out = fallback;
  if (p.Has("bounds")) {
    const auto [lo, hi] = p["bounds"].Range();
    out.lower = lo, out.upper = hi;
  }
  out.initial = p.NumberOr("initial", std::clamp(fallback.initial, out.lower, out.upper));
  if (out.initial < out.lower || out.initial > out.upper)
    p["initial"].Fail("a number within the bounds [" + std::to_string(out.lower) + ", " +
                      std::to_string(out.upper) + "]");
  return out;
}

void RunLcrFrictionFit(const Node& root, const RunContext& ctx, Outputs& out) {
  root.CheckKnownFields({"study", "name", "description", "reducer", "material", "measurements", "parameters", "analysis"});
  const lcr::Reducer<double> r = ParseReducer(root["reducer"]);
  if (root.Has("material")) root["material"].CheckKnownFields({"youngs_modulus_GPa", "poisson_ratio"});
  const lcr::Material material = root.Has("material") ? ParseMaterial(root["material"]) : lcr::Material{};
  std::vector<Measurement> data;
  const Node meas = root["measurements"];
  for (const Node& m : meas.Elements()) {
    m.CheckKnownFields({"output_torque_Nm", "input_torque_Nm", "input_torque_sd_Nm"});
    data.push_back({m["output_torque_Nm"].Positive(), m["input_torque_Nm"].Positive(),
                    m["input_torque_sd_Nm"].Positive()});
  }
  if (data.size() < 3) meas.Fail("at least 3 measurements (2 parameters are fitted)");
  if (root.Has("analysis")) root["analysis"].CheckKnownFields({"angle_steps"});
  const int steps = root.Has("analysis") ? root["analysis"].IntegerOr("angle_steps", 12, 3600) : 3600;
  Parameter mu{lcr::kPaperFrictionCoefficient, 0.0, 1.0}, drag{0.0, 0.0, 10.0};
  if (root.Has("parameters")) {
    root["parameters"].CheckKnownFields({"friction_coefficient", "drag_torque_Nm"});
    mu = ParseParameter(root["parameters"], "friction_coefficient", mu);
    drag = ParseParameter(root["parameters"], "drag_torque_Nm", drag);
  }

  // Pipeline: loads on the eccentric per unit output torque (1 N·mm), no friction.
  lcr::CycleSeries series;
  try {
    Progress progress("lcr_friction_fit", ctx.quiet);
    series = lcr::AnalyzeCycle(r, material, {1.0, 0.0, 0.0}, steps, {true, false, true},
                               [&](double f) { progress.Update(f); });
  } catch (const std::domain_error& e) {
    throw StudyError(ctx.study_file + ": /reducer: infeasible geometry: " + e.what());
  }
  const lcr::CycleInputTorque unit =
      lcr::MeanInputTorquePerOutputTorque(series.tangential_force_N, series.radial_force_N, r.eccentricity);
  const double ratio = std::abs(lcr::SpeedReductionRatio(r));

  optimizers::LeastSquaresProblem p;
  p.variables = {{"friction_coefficient", mu.lower, mu.upper, mu.initial, 0.1},
                 {"drag_torque_Nm", drag.lower, drag.upper, drag.initial, 0.1}};
  const int m = static_cast<int>(data.size());
  p.evaluator = objectives::MakeEvaluator<2>(
      2, {{"weighted_residuals", 0, m}}, [data, unit](auto x, auto res) {
        using T = std::decay_t<decltype(x[0])>;
        for (size_t i = 0; i < data.size(); ++i) {
          const T model = lcr::MeanInputTorque(unit, T(data[i].output_torque_Nm), x[0], x[1]);
          res[i] = (model - T(data[i].input_torque_Nm)) / T(data[i].sd_Nm);
        }
      });
  p.residuals = "weighted_residuals";
  const optimizers::FitResult fit = optimizers::SolveLeastSquares(p);
  if (fit.x.empty())
    throw std::runtime_error("friction fit failed: " + fit.message);

  nlohmann::json res;
  res["study"] = "lcr_friction_fit";
  res["name"] = root.StringOr("name", "");
  res["status"] = optimizers::ToString(fit.status);
  res["model"] = "T_in = drag_torque + mean[(F_t + mu |F_r|) e] (paper eq. 32 plus a no-load drag)";
  res["speed_ratio"] = lcr::SpeedReductionRatio(r);
  res["ideal_input_torque_per_output_torque"] = unit.ideal;
  res["friction_input_torque_per_output_torque_and_mu"] = unit.friction;
  const char* names[2] = {"friction_coefficient", "drag_torque_Nm"};
  for (int i = 0; i < 2; ++i) {
    nlohmann::json j;
    j["value"] = fit.x[i];
    if (!fit.standard_errors.empty()) j["standard_error"] = fit.standard_errors[i];
    const auto& v = p.variables[i];
    j["at_bound"] = fit.x[i] <= v.lower + 1e-12 || fit.x[i] >= v.upper - 1e-12;
    res["parameters"][names[i]] = j;
  }
  if (!fit.covariance.empty()) {
    res["covariance"] = {{fit.covariance[0], fit.covariance[1]}, {fit.covariance[2], fit.covariance[3]}};
    res["correlation"] = fit.covariance[1] / std::sqrt(fit.covariance[0] * fit.covariance[3]);
  } else {
    res["covariance"] = nullptr;
    res["notes"] = {"the Jacobian is rank deficient at the fit: no covariance"};
  }
  const double chi2 = 2 * fit.cost;
  const int dof = m - 2;
  res["chi_square"] = chi2;
  res["degrees_of_freedom"] = dof;
  res["reduced_chi_square"] = dof > 0 ? nlohmann::json(chi2 / dof) : nlohmann::json(nullptr);
  nlohmann::json rows = nlohmann::json::array();
  Table t;
  std::vector<double> to, tin, tfit, resid, eta_meas, eta_fit;
  for (int i = 0; i < m; ++i) {
    const double model = lcr::MeanInputTorque(unit, data[i].output_torque_Nm, fit.x[0], fit.x[1]);
    const double paper_model =
        lcr::MeanInputTorque(unit, data[i].output_torque_Nm, lcr::kPaperFrictionCoefficient, 0.0);
    nlohmann::json row_sd = nullptr;
    if (!fit.covariance.empty()) {
      // Standard deviation of the fitted torque: sqrt(gᵀ C g), g = ∂T_in/∂(μ, T_drag) by AD.
      using J2 = ceres::Jet<double, 2>;
      const J2 t_in = lcr::MeanInputTorque(unit, J2(data[i].output_torque_Nm), J2(fit.x[0], 0),
                                           J2(fit.x[1], 1));
      const double g0 = t_in.v[0], g1 = t_in.v[1];
      const auto& c = fit.covariance;
      row_sd = std::sqrt(g0 * g0 * c[0] + 2 * g0 * g1 * c[1] + g1 * g1 * c[3]);
    }
    rows.push_back({{"output_torque_Nm", data[i].output_torque_Nm},
                    {"fitted_input_torque_sd_Nm", row_sd},
                    {"measured_input_torque_Nm", data[i].input_torque_Nm},
                    {"measured_sd_Nm", data[i].sd_Nm},
                    {"fitted_input_torque_Nm", model},
                    {"residual_Nm", model - data[i].input_torque_Nm},
                    {"weighted_residual", fit.residuals[i]},
                    {"fitted_efficiency", lcr::Efficiency(data[i].output_torque_Nm, model, ratio)},
                    {"measured_efficiency", lcr::Efficiency(data[i].output_torque_Nm, data[i].input_torque_Nm, ratio)},
                    {"input_torque_with_mu_0.05_no_drag_Nm", paper_model}});
    to.push_back(data[i].output_torque_Nm);
    tin.push_back(data[i].input_torque_Nm);
    tfit.push_back(model);
    resid.push_back(model - data[i].input_torque_Nm);
  }
  res["measurements"] = rows;
  res["solver"] = {{"message", fit.message}, {"iterations", fit.iterations},
                   {"residual_evaluations", fit.residual_evaluations}};
  out.AddJson("result.json", res);
  t.Add("output_torque_Nm", to);
  t.Add("measured_input_torque_Nm", tin);
  t.Add("fitted_input_torque_Nm", tfit);
  t.Add("residual_Nm", resid);
  out.Add("fit.csv", ToCsv(t));
  std::vector<double> line_x, line_y;
  const double tmax = *std::max_element(to.begin(), to.end()) * 1.1;
  for (int i = 0; i <= 20; ++i) {
    line_x.push_back(tmax * i / 20);
    line_y.push_back(lcr::MeanInputTorque(unit, line_x.back(), fit.x[0], fit.x[1]));
  }
  out.Add("fit.svg", SvgLinePlot({{"fitted model", line_x, line_y}, {"measured", to, tin}},
                                 {"Input torque against output torque", "output torque [N·m]",
                                  "input torque [N·m]"}));
}

CAMOPT_REGISTER_STUDY("lcr_friction_fit", RunLcrFrictionFit);

}  // namespace
}  // namespace camopt::studies
