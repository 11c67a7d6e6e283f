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

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/cycloid/loaded_tca.h"
#include "objectives/cycloid_crowning.h"
#include "objectives/verification.h"
#include "studies/archive.h"
#include "studies/cycloid_input.h"
#include "studies/cycloid_life.h"
#include "studies/input.h"
#include "studies/material_input.h"
#include "studies/study.h"
#include "studies/verification_json.h"

namespace camopt::studies::cycloid_crowning_tuning {

/// Defaults of the "tuning" and "analysis" blocks.
inline constexpr double kDefaultReferenceCoefficientMm = 0.005;  ///< the paper's f (eq. 7, L = B)
inline constexpr int kDefaultCurvePoints = 11;
inline constexpr int kDefaultMaxEvaluations = 30;
inline constexpr double kDefaultSoftmaxTemperatureMPa = 2.0;
inline constexpr int kDefaultCrankAnglesPerMeshPeriod = 6;

/// The study file as declared: each field once, in the file's units, with its default, bounds and
/// description (studies/archive.h); the blocks shared with the other cycloid kinds are those of
/// studies/cycloid_input.h. The file has two forms: the shorthand (tuning.coefficient_mm, COBYLA
/// after a scan) and the general form ("variables" given). "tuning", "optimizer" and "crowning"
/// hold the fields of both forms; which of them a form takes is stated by SchemaRules (one branch
/// per form) and checked in code by Parse with the form's own messages. `camopt schema
/// cycloid_crowning_tuning` is emitted from it.
struct Input {
  struct Load {
    double design_torque_Nm = 0, max_torque_Nm = 0;
    std::optional<double> input_speed_rpm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("design_torque_Nm", &design_torque_Nm,
               Field().Required().Positive().Unit("N·m").Desc(
                   "T, the disc's torque at which the peak contact stress over the mesh period is minimised"));
      a->Visit("max_torque_Nm", &max_torque_Nm,
               Field().Required().Positive().Unit("N·m").Desc(
                   ">= design_torque_Nm; the contact stays off the face ends (tuning.edge_margin_um) up to it"));
      a->Visit("input_speed_rpm", &input_speed_rpm,
               Field().Positive().Unit("rpm").Desc(
                   "input (crank) speed: the tuned design's bearing lives at load.design_torque_Nm (a one-line duty "
                   "cycle; docs/life.md, Cycloid)"));
    }
  };
  /// "tuning": the shorthand's ranges of f and L and the settings of both forms.
  struct Tuning {
    std::optional<std::array<double, 2>> coefficient_mm, effective_length_mm;
    double reference_coefficient_mm = kDefaultReferenceCoefficientMm;
    int curve_points = kDefaultCurvePoints;
    int max_evaluations = kDefaultMaxEvaluations;
    double edge_margin_um = 0;
    /// The general form's (no schema default: the shorthand refuses them).
    std::optional<double> softmax_temperature_MPa, max_lte_peak_to_peak_arcsec, min_unloaded_te_arcsec;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("coefficient_mm", &coefficient_mm,
               Field().Expect("[lower, upper], two numbers").Unit("mm").Desc(
                   "shorthand form (required there): [lower, upper] of the LCM coefficient f (eq. 7, Δ = f ln(1/(1 − "
                   "(2u/L)²))), 0 <= lower < upper"));
      a->Visit("effective_length_mm", &effective_length_mm,
               Field().Expect("[lower, upper], two numbers").Unit("mm").Desc(
                   "shorthand form: [lower, upper] of the effective length L, the face width B <= lower <= upper "
                   "(absent: L = B, or crowning.effective_length_mm)"));
      a->Visit("reference_coefficient_mm", &reference_coefficient_mm,
               Field().NonNegative().Unit("mm").Desc("f to compare with (the paper's, eq. 7 with L = B)"));
      a->Visit("curve_points", &curve_points,
               Field().AtLeast(0).AtMost(200, "at most 200 points").Desc(
                   "points of the uniform scan of f over its range (shorthand: at least 2; general form: 0, no scan, "
                   "or at least 2)"));
      a->Visit("max_evaluations", &max_evaluations,
               Field().AtLeast(1).Desc(
                   "optimizer budget (COBYLA evaluations after the scan; optimizer.max_evaluations wins when given)"));
      a->Visit("edge_margin_um", &edge_margin_um,
               Field().Unit("µm").Desc(
                   "required axial distance of the contact end from the face end at every angle of the "
                   "max_torque_Nm cycle (located within a cell)"));
      a->Visit("softmax_temperature_MPa", &softmax_temperature_MPa,
               Field().Positive().Unit("MPa").Desc(
                   "general form: τ of the smooth peak S = m + τ ln Σ exp((p_k − m)/τ) (0 <= S − max <= τ ln N; "
                   "absent: 2)"));
      a->Visit("max_lte_peak_to_peak_arcsec", &max_lte_peak_to_peak_arcsec,
               Field().Positive().Unit("arcsec").Desc(
                   "general form: upper bound of the loaded TE's peak to peak at the design torque (absent: none)"));
      a->Visit("min_unloaded_te_arcsec", &min_unloaded_te_arcsec,
               Field().Unit("arcsec").Desc(
                   "general form: lower bound of the unloaded TE β0 (eq. 14) at every angle: no roller interferes "
                   "with the tooth at the kinematic position (absent: 0)"));
    }
  };
  /// "variables" (the general form): each tuned field's [lo, hi].
  struct Variables {
    std::optional<std::array<double, 2>> coefficient_mm, effective_length_mm, end_drop_mm, flat_length_mm, radius_mm,
        delta_position_um, delta_radius_um;
    template <typename Archive>
    void Serialize(Archive* a) {
      const auto range = [](const char* what, const char* unit) {
        return Field().Expect("[lower, upper], two numbers").Unit(unit).Desc(
            std::string("[lower, upper] with lower < upper: ") + what);
      };
      a->Visit("coefficient_mm", &coefficient_mm,
               range("the LCM coefficient f (logarithmic; lower >= 0)", "mm"));
      a->Visit("effective_length_mm", &effective_length_mm,
               range("the effective length L (logarithmic; lower >= the face width)", "mm"));
      a->Visit("end_drop_mm", &end_drop_mm,
               range("the largest drop at the face ends (logarithmic; lower > 0, 0 means an unbounded drop)", "mm"));
      a->Visit("flat_length_mm", &flat_length_mm,
               range("the uncrowned middle's length (logarithmic, partial; lower >= 0)", "mm"));
      a->Visit("radius_mm", &radius_mm, range("the crowning radius (full, partial; lower >= 0)", "mm"));
      a->Visit("delta_position_um", &delta_position_um,
               range("Δa, the pins' circle radius modification (upper <= 0: a positive one interferes)", "µm"));
      a->Visit("delta_radius_um", &delta_radius_um,
               range("Δr, the pin radius modification (upper <= 0: a positive one interferes)", "µm"));
    }
    /// At least one variable; each range's bound on one end.
    static nlohmann::ordered_json SchemaRules();
    static std::vector<CrossFieldRule> CrossFieldRules() {
      return {{{"coefficient_mm", "effective_length_mm", "end_drop_mm", "flat_length_mm", "radius_mm",
                "delta_position_um", "delta_radius_um"},
               "each range [lower, upper] with lower < upper",
               "with lo < hi"}};
    }
  };
  struct Optimizer {
    /// No schema default: the general form's is "ipopt", the shorthand's must be given ("cobyla").
    std::optional<std::string> backend;
    std::optional<int> max_evaluations;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("backend", &backend,
               Field().OneOf({"ipopt", "slsqp", "cobyla"}).Desc(
                   "the solver: Ipopt or NLopt's SLSQP with exact gradients, NLopt's COBYLA on values only "
                   "(general form; absent: ipopt); the shorthand takes \"cobyla\" only, and needs it given"));
      a->Visit("max_evaluations", &max_evaluations,
               Field().AtLeast(1).Desc(
                   "Ipopt: iterations; NLopt: evaluations (absent: tuning.max_evaluations)"));
    }
  };
  struct Analysis {
    std::optional<std::array<int, 2>> grid;
    int crank_angles_per_mesh_period = kDefaultCrankAnglesPerMeshPeriod;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("grid", &grid, cycloid_common::GridField().Desc(
          "[profile_cells, axial_cells] of the fast model, 4 to 512 each; the accurate check has twice each"));
      a->Visit("crank_angles_per_mesh_period", &crank_angles_per_mesh_period,
               Field().AtLeast(1).AtMost(1000, "at most 1000").Desc(
                   "uniform crank angles over the mesh period 2π/z₂ (fast model; the accurate check has twice)"));
    }
  };

  std::string study = "cycloid_crowning_tuning", name;
  std::optional<std::string> description;
  cycloid_common::DriveInput drive;
  std::optional<cycloid_common::ModificationInput> modification;
  MaterialInput material;
  Load load;
  std::optional<Tuning> tuning;
  std::optional<Variables> variables;
  std::optional<Optimizer> optimizer;
  std::optional<cycloid_common::CrowningStartInput> crowning;
  Analysis analysis;
  cycloid_common::CycloidDutyCycleInput duty_cycle;
  std::optional<KindedBearingRatingInput<false>> crank_bearing;
  std::optional<BearingRatingInput<false>> pins;
  std::optional<cycloid_common::OutputMechanismInput> output_mechanism;

  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Required().Const("cycloid_crowning_tuning").Desc("the study kind"));
    a->Visit("name", &name, Field().Desc("the design's name, in titles"));
    a->Visit("description", &description, Field().Desc("free text"));
    a->Visit("drive", &drive, Field().Required().Desc("the pin ring and the disc (docs/cycloid.md, \"Geometry\")"));
    a->Visit("modification", &modification,
             Field().Desc("the profile's modifications (general form: the start of those in variables; absent: 0)"));
    a->Visit("material", &material, Field().Required().Desc("the disc's and pins' elastic material"));
    a->Visit("load", &load, Field().Required().Desc("the design and maximum torques (and the speed for the lives)"));
    a->Visit("tuning", &tuning,
             Field().Desc("shorthand form (required there): the ranges of f (and L) and the scan's and COBYLA's "
                          "settings; general form: the settings"));
    a->Visit("variables", &variables,
             Field().Desc("general form (given: this form): the tuned fields, each [lo, hi]; every corner of the "
                          "box must give a valid crowning and a feasible drive"));
    a->Visit("optimizer", &optimizer,
             Field().Desc("general form: any backend; shorthand form: {\"backend\": \"cobyla\"} only"));
    a->Visit("crowning", &crowning,
             Field().Desc("general form: the start crowning (a field that is a variable may be left out; absent: "
                          "none); shorthand form: the logarithmic crowning whose coefficient is tuned (its fixed "
                          "fields; eq. 7's L = B and no end drop when absent)"));
    a->Visit("analysis", &analysis, Field().Desc("the fast model's contact grid and crank angles"));
    cycloid_common::VisitLifeRatings(a, &duty_cycle, &crank_bearing, &pins,
                                     " (one disc); the time shares sum to 1 within 1e-6, at least one speed > 0"
                                     "; each line one LTCA cycle at its torque");
    a->Visit("output_mechanism", &output_mechanism,
             Field().Desc("rigid output pins in the disc's holes (docs/life.md, Cycloid): pin circle radius (inside "
                          "the disc's root radius) and pin count (absent: the continuous limit)"));
  }
  /// The rules of the two forms (one branch each: which fields of tuning, optimizer and crowning a
  /// form takes, a crowning variable only with the crowning type that has it) and of the lives.
  static nlohmann::ordered_json SchemaRules();
  static std::vector<CrossFieldRule> CrossFieldRules() {
    return {{{"tuning", "variables", "drive"}, "the effective length's range starts at or above the face width",
             "lo >= the face width"},
            {{"tuning"}, "the shorthand's range of f: 0 <= lo < hi", "with 0 <= lo < hi"}};
  }
};

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
  double reference_coefficient_mm = kDefaultReferenceCoefficientMm;
  int curve_points = kDefaultCurvePoints;
  int max_evaluations = kDefaultMaxEvaluations;
  double required_edge_margin_um = 0;
  cycloid::LoadedOptions options;
  int crank_angles_per_mesh_period = kDefaultCrankAnglesPerMeshPeriod;

  /// The general form ("variables" given): any crowning's parameters and the modifications, each
  /// variable named by the field it sets, with exact gradients for Ipopt/SLSQP (docs/cycloid.md).
  bool joint = false;
  cycloid::Crowning crowning;                   ///< start values and fixed fields
  std::vector<objectives::Variable> variables;  ///< in their own units (mm, µm for delta_*_um)
  std::string backend = "cobyla";               ///< "ipopt", "slsqp" or "cobyla"
  double temperature_MPa = kDefaultSoftmaxTemperatureMPa;  ///< soft-max temperature of the smooth peak
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

/// The run's answer: result.json as declared (`camopt schema cycloid_crowning_tuning --result`),
/// then the model's numbers the files are drawn from.
struct Result {
  struct Optimizer {
    std::string backend, status, method;
    int evaluations = 0, gradient_evaluations = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("backend", &backend, Field().Desc("the optimizer"));
      a->Visit("status", &status, Field().Desc("the optimizer's end"));
      a->Visit("evaluations", &evaluations, Field());
      a->Visit("gradient_evaluations", &gradient_evaluations, Field());
      a->Visit("method", &method, Field());
    }
  };
  struct CurvePoint {
    double coefficient_mm = 0, max_contact_stress_MPa = 0, edge_margin_at_max_torque_um = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("coefficient_mm", &coefficient_mm, Field().Unit("mm"));
      a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa, Field().Unit("MPa"));
      a->Visit("edge_margin_at_max_torque_um", &edge_margin_at_max_torque_um, Field().Unit("µm"));
    }
  };

  std::string study = "cycloid_crowning_tuning", name;
  Optimizer optimizer;
  std::map<std::string, double> tuned_values, error_values;  ///< result.json's tuned, estimated_error
  double tuned_coefficient_mm = 0, tuned_effective_length_mm = 0, end_drop_mm = 0, flat_length_mm = 0;
  double tuned_max_contact_stress_MPa = 0, tuned_edge_margin_at_max_torque_um = 0;
  double reference_coefficient_mm = 0, reference_max_contact_stress_MPa = 0, reference_edge_margin_at_max_torque_um = 0;
  double design_torque_Nm = 0, max_torque_Nm = 0;
  int crank_angles_per_mesh_period = 0;
  double axial_cell_mm = 0;
  std::vector<CurvePoint> curve_points;  ///< result.json's curve
  std::optional<std::string> crowning_type;
  std::optional<double> softmax_temperature_MPa, tuned_smooth_max_contact_stress_MPa, tuned_lte_peak_to_peak_arcsec;
  std::optional<double> tuned_max_pair_load_N, tuned_min_unloaded_te_arcsec, min_unloaded_te_arcsec;
  std::optional<double> start_max_contact_stress_MPa, start_edge_margin_at_max_torque_um;
  std::optional<cycloid_common::LifeBlock> life_json;  ///< result.json's life
  bool verified = false;
  VerificationBlock verification_block;  ///< result.json's verification
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Const("cycloid_crowning_tuning"));
    a->Visit("name", &name, Field().Desc("the design's name"));
    a->Visit("optimizer", &optimizer, Field());
    a->Visit("tuned", &tuned_values, Field().Desc("each tuned variable, named by the field it sets"));
    a->Visit("estimated_error", &error_values, Field().Desc("the accurate model's error estimate of each tuned output"));
    a->Visit("warnings", &warnings, Field());
    a->Visit("search_status", &status, Field().Desc("the search's end (`status` is the answer's)"));
    a->Visit("feasible", &feasible, Field().Desc("a point met the edge margin").Decides(RunFact::kFeasible));
    a->Visit("tuned_coefficient_mm", &tuned_coefficient_mm, Field().Unit("mm"));
    a->Visit("tuned_effective_length_mm", &tuned_effective_length_mm, Field().Unit("mm"));
    a->Visit("end_drop_mm", &end_drop_mm, Field().Unit("mm"));
    a->Visit("flat_length_mm", &flat_length_mm, Field().Unit("mm"));
    a->Visit("tuned_max_contact_stress_MPa", &tuned_max_contact_stress_MPa,
             Field().Unit("MPa").Desc("the accurate model's, at the design torque"));
    a->Visit("tuned_edge_margin_at_max_torque_um", &tuned_edge_margin_at_max_torque_um,
             Field().Unit("µm").Desc("the accurate model's"));
    a->Visit("tuned_max_contact_stress_fast_model_MPa", &fast_stress_MPa, Field().Unit("MPa"));
    a->Visit("tuned_edge_margin_at_max_torque_fast_model_um", &fast_edge_margin_um, Field().Unit("µm"));
    a->Visit("reference_coefficient_mm", &reference_coefficient_mm, Field().Unit("mm"));
    a->Visit("reference_max_contact_stress_MPa", &reference_max_contact_stress_MPa, Field().Unit("MPa"));
    a->Visit("reference_edge_margin_at_max_torque_um", &reference_edge_margin_at_max_torque_um, Field().Unit("µm"));
    a->Visit("design_torque_Nm", &design_torque_Nm, Field().Unit("N·m"));
    a->Visit("max_torque_Nm", &max_torque_Nm, Field().Unit("N·m"));
    a->Visit("crank_angles_per_mesh_period", &crank_angles_per_mesh_period, Field());
    a->Visit("axial_cell_mm", &axial_cell_mm, Field().Unit("mm"));
    a->Visit("evaluations", &evaluations, Field().Desc("model evaluations, scan and reference included"));
    a->Visit("curve", &curve_points, Field().Desc("the scan"));
    a->Visit("crowning_type", &crowning_type, Field().Desc("the general form's crowning"));
    a->Visit("softmax_temperature_MPa", &softmax_temperature_MPa, Field().Unit("MPa"));
    a->Visit("tuned_smooth_max_contact_stress_MPa", &tuned_smooth_max_contact_stress_MPa, Field().Unit("MPa"));
    a->Visit("tuned_lte_peak_to_peak_arcsec", &tuned_lte_peak_to_peak_arcsec, Field().Unit("arcsec"));
    a->Visit("tuned_max_pair_load_N", &tuned_max_pair_load_N, Field().Unit("N"));
    a->Visit("tuned_min_unloaded_te_arcsec", &tuned_min_unloaded_te_arcsec, Field().Unit("arcsec"));
    a->Visit("min_unloaded_te_arcsec", &min_unloaded_te_arcsec, Field().Unit("arcsec"));
    a->Visit("start_max_contact_stress_MPa", &start_max_contact_stress_MPa, Field().Unit("MPa"));
    a->Visit("start_edge_margin_at_max_torque_um", &start_edge_margin_at_max_torque_um, Field().Unit("µm"));
    a->Visit("life", &life_json,
             Field().Desc("the tuned design's bearing lives, when asked"));
    a->Visit("verified", &verified, Field().Desc("the accurate model confirms the tuning (a view of `status`)"));
    a->Visit("verification", &verification_block, Field().Desc("the accurate model's checks"));
  }

  // Not in result.json (bar the members visited above: warnings, status, feasible, evaluations, the
  // fast model's stress and margin): the model's numbers.
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

/// The declared input of the study at `root` (its known fields, then each form's fields of tuning,
/// optimizer and crowning with the form's messages, then the declaration): what Parse, the work
/// estimate and the fidelity knobs read. @throws StudyError for bad input (exit 2).
Input ReadInput(const Node& root);
/// @throws StudyError for bad input (exit 2).
Study Parse(const Node& root);
Result Run(const Study& study, const RunContext& ctx);
/// result.json's members of `result` (its Serialize) from its model numbers; Run ends with it.
void FillResult(const Study& study, Result& result);
/// result.json, stress_vs_coefficient.csv/.svg, history.csv, edge_margin_vs_coefficient.svg.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::cycloid_crowning_tuning
