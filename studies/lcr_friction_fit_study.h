// Study kind "lcr_friction_fit": fits the friction law of model/lcr/friction.h (the paper's eq. 32
// plus a no-load drag) to measured input torques, e.g. the paper's Table 4, by bounded least
// squares with Ceres, with the parameters' covariance. Parse → Run → ToJson / Write.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/common/material.h"
#include "model/lcr/friction.h"
#include "model/lcr/reducer.h"
#include "optimizers/ceres_fit.h"
#include "studies/input.h"
#include "studies/study.h"

namespace camopt::studies::lcr_friction_fit {

struct Measurement {
  double output_torque_Nm = 0, input_torque_Nm = 0, sd_Nm = 0;
};

/// A fitted parameter: start value and bounds.
struct Parameter {
  double initial = 0, lower = 0, upper = 0;
};

/// What the study file says, parsed and validated.
struct Study {
  std::string name;
  lcr::Reducer<double> reducer;
  Material material;
  std::vector<Measurement> measurements;  ///< at least 3
  int angle_steps = 3600;
  Parameter friction_coefficient{lcr::kPaperFrictionCoefficient, 0.0, 1.0};
  Parameter drag_torque_Nm{0.0, 0.0, 10.0};
};

/// The fitted model at one measurement.
struct Row {
  double fitted_input_torque_Nm = 0;
  std::optional<double> fitted_input_torque_sd_Nm;  ///< sqrt(gᵀ C g); none without a covariance
  double residual_Nm = 0, weighted_residual = 0;
  double fitted_efficiency = 0, measured_efficiency = 0;
  double paper_input_torque_Nm = 0;  ///< with the paper's μ and no drag
};

struct Result {
  double speed_ratio = 0;
  lcr::CycleInputTorque per_output_torque;  ///< t_ideal, t_friction
  optimizers::FitResult fit;                ///< x = (μ, T_drag [N·m])
  bool friction_coefficient_at_bound = false, drag_torque_at_bound = false;
  std::optional<double> correlation;        ///< of μ and T_drag, when the covariance exists
  double chi_square = 0;
  int degrees_of_freedom = 0;
  std::vector<Row> rows;                    ///< one per measurement
  std::vector<double> line_output_torque_Nm, line_input_torque_Nm;  ///< the fitted line, plotted
};

/// @throws StudyError (exit 2) naming the JSON path of bad input.
Study Parse(const Node& root);
/// @throws StudyError for an infeasible design, std::runtime_error when the fit fails.
Result Run(const Study& study, const RunContext& ctx);
nlohmann::json ToJson(const Study& study, const Result& result);
/// result.json, fit.csv, fit.svg.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::lcr_friction_fit
