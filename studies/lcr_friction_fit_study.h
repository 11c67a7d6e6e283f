// Study kind "lcr_friction_fit": fits the friction law of model/lcr/friction.h (the paper's eq. 32
// plus a no-load drag) to measured input torques, e.g. the paper's Table 4, by bounded least
// squares with Ceres, with the parameters' covariance. Parse (the Input, checked) → Run → Write.
#pragma once

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/common/material.h"
#include "model/lcr/friction.h"
#include "model/lcr/reducer.h"
#include "optimizers/ceres_fit.h"
#include "studies/archive.h"
#include "studies/input.h"
#include "studies/lcr_input.h"
#include "studies/material_input.h"
#include "studies/study.h"

namespace camopt::studies::lcr_friction_fit {

/// The study file as declared: each field once, in the file's units, with its default, bounds
/// and description (studies/archive.h); `camopt schema lcr_friction_fit` is emitted from it. It is
/// also what Run takes: Parse checks what spans fields and returns it.
struct Input {
  struct Measurement {
    double output_torque_Nm = 0, input_torque_Nm = 0, input_torque_sd_Nm = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("output_torque_Nm", &output_torque_Nm, Field().Required().Positive().Unit("N·m").Desc("the load"));
      a->Visit("input_torque_Nm", &input_torque_Nm,
               Field().Required().Positive().Unit("N·m").Desc("the measured input torque"));
      a->Visit("input_torque_sd_Nm", &input_torque_sd_Nm,
               Field().Required().Positive().Unit("N·m").Desc("its standard deviation (weights the fit)"));
    }
  };
  struct Parameter {
    std::optional<double> initial;
    std::array<double, 2> bounds{0.0, 1.0};
    /// Where the fit starts: `initial`, or the default start clamped into the bounds.
    double Start(double default_start) const {
      return initial.value_or(std::clamp(default_start, bounds[0], bounds[1]));
    }
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("initial", &initial, Field().Desc("start of the fit, within the bounds (absent: the default start "
                                                "clamped into the bounds)"));
      a->Visit("bounds", &bounds, Field().Expect("[lower, upper], two numbers").Desc("[lower, upper], lower < upper"));
    }
    static std::vector<CrossFieldRule> CrossFieldRules() {
      return {{{"bounds"}, "[lower, upper] with lower < upper", "with lower < upper"}};
    }
  };
  struct Parameters {
    Parameter friction_coefficient{std::nullopt, {0.0, 1.0}};
    Parameter drag_torque_Nm{std::nullopt, {0.0, 10.0}};
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("friction_coefficient", &friction_coefficient,
               Field().Desc("μ of the eccentric, the paper's eq. 32 (default start: the paper's μ)"));
      a->Visit("drag_torque_Nm", &drag_torque_Nm, Field().Desc("the no-load drag torque [N·m] (default start: 0)"));
    }
  };
  struct Analysis {
    int angle_steps = 3600;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("angle_steps", &angle_steps, Field().AtLeast(12).Desc("samples of the input revolution in the torque model"));
    }
  };

  /// The fit's verdict: the χ² goodness-of-fit test (the measurements' standard deviations as the
  /// weights; χ² ~ χ²(m − 2) when the model is right).
  struct Limits {
    double chi_square_p_value = 0.05;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("chi_square_p_value", &chi_square_p_value,
               Field().Above(0.0, "a number in (0, 1)").Below(1.0, "a number in (0, 1)").Desc(
                   "the smallest p-value of the chi-square test that passes: the probability, were the model right, "
                   "of a chi-square at least the fit's (docs/optimization.md, friction fit)"));
    }
  };

  std::string study = "lcr_friction_fit", name;
  std::optional<std::string> description;
  LcrReducerInput reducer;
  std::optional<MaterialInput> material;
  std::vector<Measurement> measurements;
  Parameters parameters;
  Analysis analysis;
  Limits limits;

  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Required().Const("lcr_friction_fit").Desc("the study kind"));
    a->Visit("name", &name, Field().Desc("the design's name, in titles"));
    a->Visit("description", &description, Field().Desc("free text"));
    a->Visit("reducer", &reducer, Field().Required().Desc("the lobe cam reducer's design"));
    a->Visit("material", &material, Field().Desc("the cams' and rollers' material (absent: steel)"));
    a->Visit("measurements", &measurements,
             Field().Required().MinItems(3, "at least 3 measurements (2 parameters are fitted)")
                 .Desc("measured input torques under load"));
    a->Visit("parameters", &parameters, Field().Desc("the fitted parameters' starts and bounds"));
    a->Visit("analysis", &analysis, Field().Desc("the torque model's grid"));
    a->Visit("limits", &limits, Field().Desc("the fit's verdict"));
  }
};

/// The fitted model at one measurement (result.json's measurements[i]).
struct Row {
  double output_torque_Nm = 0, measured_input_torque_Nm = 0, measured_sd_Nm = 0;  ///< the measurement
  double fitted_input_torque_Nm = 0;
  std::optional<double> fitted_input_torque_sd_Nm;  ///< sqrt(gᵀ C g); none without a covariance
  double residual_Nm = 0, weighted_residual = 0;
  double fitted_efficiency = 0, measured_efficiency = 0;
  double paper_input_torque_Nm = 0;  ///< with the paper's μ and no drag
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("output_torque_Nm", &output_torque_Nm, Field().Unit("N·m").Desc("the measurement's output torque"));
    a->Visit("measured_input_torque_Nm", &measured_input_torque_Nm, Field().Unit("N·m"));
    a->Visit("measured_sd_Nm", &measured_sd_Nm, Field().Unit("N·m").Desc("its standard deviation"));
    a->Visit("fitted_input_torque_Nm", &fitted_input_torque_Nm, Field().Unit("N·m").Desc("the fitted model's"));
    a->Visit("fitted_input_torque_sd_Nm", &fitted_input_torque_sd_Nm,
             Field().NullWhenAbsent().Unit("N·m").Desc("its standard deviation from the parameters' covariance (null: none)"));
    a->Visit("residual_Nm", &residual_Nm, Field().Unit("N·m").Desc("fitted − measured"));
    a->Visit("weighted_residual", &weighted_residual, Field().Desc("the residual over the measured standard deviation"));
    a->Visit("fitted_efficiency", &fitted_efficiency, Field());
    a->Visit("measured_efficiency", &measured_efficiency, Field());
    a->Visit("input_torque_with_mu_0.05_no_drag_Nm", &paper_input_torque_Nm,
             Field().Unit("N·m").Desc("the model with the paper's friction coefficient and no drag"));
  }
};

/// The run's answer: result.json as declared (`camopt schema lcr_friction_fit --result`), then what
/// the files are drawn from.
struct Result {
  /// A fitted parameter.
  struct FittedParameter {
    double value = 0;
    std::optional<double> standard_error;
    bool at_bound = false;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("value", &value, Field().Desc("the fitted value"));
      a->Visit("standard_error", &standard_error, Field().Desc("from the covariance, when it exists"));
      a->Visit("at_bound", &at_bound, Field().Desc("the value is at a bound of the parameter"));
    }
  };
  struct Parameters {
    FittedParameter friction_coefficient, drag_torque_Nm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("friction_coefficient", &friction_coefficient, Field().Desc("μ of the rollers' contacts"));
      a->Visit("drag_torque_Nm", &drag_torque_Nm, Field().Desc("the no-load drag at the input [N·m]"));
    }
  };
  struct Solver {
    std::string message;
    int iterations = 0, residual_evaluations = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("message", &message, Field().Desc("Ceres' summary"));
      a->Visit("iterations", &iterations, Field());
      a->Visit("residual_evaluations", &residual_evaluations, Field());
    }
  };

  std::string study = "lcr_friction_fit", name, fit_status, model;
  double speed_ratio = 0;
  lcr::CycleInputTorque per_output_torque;  ///< t_ideal, t_friction
  Parameters parameters;
  std::optional<std::array<std::array<double, 2>, 2>> covariance;  ///< of (μ, T_drag)
  std::optional<double> correlation;        ///< of μ and T_drag, when the covariance exists
  std::optional<std::vector<std::string>> notes;
  double chi_square = 0;
  int degrees_of_freedom = 0;
  double reduced_chi_square = 0, chi_square_p_value = 0, chi_square_p_value_limit = 0;  ///< NaN: no dof
  std::vector<Row> rows;                    ///< one per measurement
  Solver solver;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Const("lcr_friction_fit"));
    a->Visit("name", &name, Field().Desc("the design's name"));
    a->Visit("fit_status", &fit_status, Field().Desc("the least-squares solver's end (`status` is the answer's)"));
    a->Visit("model", &model, Field().Desc("the fitted torque model"));
    a->Visit("speed_ratio", &speed_ratio, Field().Desc("the reducer's, signed"));
    a->Visit("ideal_input_torque_per_output_torque", &per_output_torque.ideal,
             Field().Desc("input torque per output torque without friction"));
    a->Visit("friction_input_torque_per_output_torque_and_mu", &per_output_torque.friction,
             Field().Desc("input torque per output torque and unit friction coefficient"));
    a->Visit("parameters", &parameters, Field().Desc("the fitted parameters"));
    a->Visit("covariance", &covariance,
             Field().NullWhenAbsent().Desc("of (μ, drag torque [N·m]); null when the Jacobian is rank deficient"));
    a->Visit("correlation", &correlation, Field().Desc("of μ and the drag torque, with the covariance"));
    a->Visit("notes", &notes, Field().Desc("remarks for the report"));
    a->Visit("chi_square", &chi_square, Field().Desc("Σ weighted residual²"));
    a->Visit("degrees_of_freedom", &degrees_of_freedom, Field().Desc("measurements − 2"));
    a->Visit("reduced_chi_square", &reduced_chi_square, Field().NullWhenNotFinite().Desc("χ² / dof (null: no dof)"));
    a->Visit("chi_square_p_value", &chi_square_p_value,
             Field().NullWhenNotFinite().Desc("P(χ²(dof) ≥ χ²): the model within the measurements' deviations (null: no dof)"));
    a->Visit("chi_square_p_value_limit", &chi_square_p_value_limit, Field().Desc("the study's least p-value"));
    a->Visit("measurements", &rows, Field().Desc("the model at each measurement"));
    a->Visit("solver", &solver, Field().Desc("the least-squares solve"));
  }

  // Not in result.json:
  optimizers::FitResult fit;                ///< x = (μ, T_drag [N·m])
  bool friction_coefficient_at_bound = false, drag_torque_at_bound = false;
  std::vector<double> line_output_torque_Nm, line_input_torque_Nm;  ///< the fitted line, plotted
};

/// The study as read, with the checks between fields (the design, the parameters' bounds and
/// starts). @throws StudyError (exit 2) naming the JSON path of bad input.
Input Parse(const Node& root);
/// @throws StudyError for an infeasible design, std::runtime_error when the fit fails.
Result Run(const Input& in, const RunContext& ctx);
/// result.json, fit.csv, fit.svg.
void Write(const Input& in, const Result& result, Outputs& out);

}  // namespace camopt::studies::lcr_friction_fit
