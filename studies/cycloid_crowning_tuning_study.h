// Study kind "cycloid_crowning_tuning": the logarithmic crowning coefficient f (and, as an option,
// its effective length L) that minimises the peak contact stress over the mesh cycle at a design
// torque, subject to the contact pattern staying off the face edges at a maximum torque.
//
// Method. The mesh repeats every 2π/n1 of crank angle (up to a relabelling of the rollers), so one
// mesh period sampled uniformly stands for the cycle. A scan of f over its bounds gives the
// stress-versus-f curve; COBYLA (bounded, derivative-free, inequality constraints handled directly;
// optimizers/ through NLopt) then refines from the best feasible point of the scan. The general
// form ("variables") gives Ipopt and SLSQP the epigraph of the peak (minimise t with every
// (angle, roller) peak <= t, exact gradients), COBYLA the soft-max. The problems are
// objectives/cycloid_crowning.h. After the optimizer, the tuned design is verified
// (objectives/verification.h): re-evaluated at twice the crank angles on a grid with twice the
// cells, the edge margin's limit re-checked within its estimated error, the fast model's required
// margin raised and the problem solved again while it does not hold (kVerificationRounds); the
// reported stress and margin are the accurate values.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/cycloid/loaded_tca.h"
#include "objectives/cycloid_crowning.h"
#include "objectives/verification.h"
#include "studies/cycloid_life.h"
#include "studies/input.h"
#include "studies/study.h"

namespace camopt::studies::cycloid_crowning_tuning {

struct Study {
  std::string name;
  cycloid::Drive drive;
  cycloid::Material material;
  double design_torque_Nm = 0, max_torque_Nm = 0;  ///< as in the file (disc torques)
  double coefficient_lo_mm = 0, coefficient_hi_mm = 0;
  bool tune_length = false;             ///< L a variable (its range is not a single value)
  double length_lo_mm = 0, length_hi_mm = 0;  ///< both the face width when L is not given
  /// The tuned logarithmic crowning's fixed fields ("crowning": end_drop_mm, flat_length_mm;
  /// effective_length_mm fixes L); the defaults are the paper's eq. 7.
  cycloid::Crowning shape{cycloid::CrowningType::kLogarithmic};
  double reference_coefficient_mm = 0.005;
  int curve_points = 11;
  int max_evaluations = 30;
  double required_edge_margin_um = 0;
  cycloid::LoadedOptions options;
  int crank_angles_per_mesh_period = 6;

  /// The general form ("variables" given): any crowning's parameters and the modifications, each
  /// variable named by the field it sets, with exact gradients for Ipopt/SLSQP (issue 13).
  bool joint = false;
  cycloid::Crowning crowning;                   ///< start values and fixed fields
  std::vector<objectives::Variable> variables;  ///< in their own units (mm, µm for delta_*_um)
  std::string backend = "cobyla";               ///< "ipopt", "slsqp" or "cobyla"
  double temperature_MPa = 2.0;                 ///< soft-max temperature of the smooth peak
  double max_lte_peak_to_peak_arcsec = kInf;    ///< optional bound
  /// The unloaded TE β0 >= this at every angle (no roller interferes with the tooth at the
  /// kinematic position: the assembly/backlash condition); "tuning.min_unloaded_te_arcsec".
  double min_unloaded_te_arcsec = 0;
  /// The tuned design's bearing lives ("load.input_speed_rpm" or "duty_cycle", "crank_bearing",
  /// "pins", "output_mechanism", as in cycloid_ltca; docs/life.md, "Cycloid"); nullopt: none asked.
  /// The tuning's objective does not change.
  std::optional<cycloid_common::LifeSpec> life;
};

/// Rounds of the verified-optimum loop (objectives/verification.h): how often the fast model's
/// required edge margin may be raised and the problem solved again.
inline constexpr int kVerificationRounds = 3;
/// Added to the measured excess when the fast model's required edge margin is raised [µm].
inline constexpr double kMarginStepUm = 0.5;

struct Result {
  std::vector<objectives::CrowningEvaluation> curve;    ///< the scan (L = length_lo_mm)
  std::vector<objectives::CrowningEvaluation> history;  ///< the optimizer's evaluations, in order
  objectives::CrowningEvaluation reference;             ///< f = reference, L = face width
  objectives::CrowningEvaluation best;  ///< best feasible point seen (else the scan's start)
  bool feasible = false;
  std::string status;                   ///< "converged", "max_evaluations reached", or why stopped
  int evaluations = 0;                  ///< model evaluations, scan and reference included

  /// Optimizer report: backend, its status word, model runs (values) and gradient runs.
  std::string backend = "cobyla";
  std::string solver_status;
  int solver_evaluations = 0, solver_gradient_evaluations = 0;
  /// Every tuned variable by name at the best point (the general form: the variables; the
  /// shorthand: coefficient_mm and, when tuned, effective_length_mm).
  std::vector<std::pair<std::string, double>> tuned;
  /// The general form: the optimizer's evaluations in order and the best one.
  std::vector<objectives::TuningEvaluation> joint_history;
  objectives::TuningEvaluation joint_best;
  /// Discretisation error of the reported (accurate) tuned stress and edge margin, by name.
  std::vector<std::pair<std::string, double>> estimated_error;
  /// The tuned design (drive with its modifications, crowning).
  cycloid::Drive tuned_drive;
  cycloid::Crowning tuned_crowning;
  /// The fast model's (the optimizer's) values at the tuned design; `best` holds the accurate ones.
  double fast_stress_MPa = 0, fast_edge_margin_um = 0;
  double accurate_lte_peak_to_peak_arcsec = 0;
  objectives::Verification verification;
  std::vector<std::string> warnings;
  /// The tuned design's lives on the accurate model's grid and angles (when Study::life).
  std::optional<cycloid_common::LifeResult> life;
};

/// @throws StudyError for bad input (exit 2).
Study Parse(const Node& root);
Result Run(const Study& study, const RunContext& ctx);
nlohmann::json ToJson(const Study& study, const Result& result);
/// result.json, stress_vs_coefficient.csv/.svg, history.csv, edge_margin_vs_coefficient.svg.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::cycloid_crowning_tuning
