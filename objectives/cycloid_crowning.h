// The logarithmic crowning of a cycloid drive as an optimization problem: choose the crowning
// coefficient f (and, as an option, its effective length L) that minimises the peak contact stress
// over the mesh cycle at a design torque, subject to the contact pattern staying off the face
// edges at a maximum torque.
//
// Each evaluation solves a complementarity problem per loaded pair and takes a maximum over cells
// and crank angles: the objective is non-smooth in f (and slightly grid-quantised), so the problem
// is value-only (a derivative-free solver such as COBYLA drives it; asking for a Jacobian throws).
// The constraint is the end distance of model/cycloid (axial distance of the contact end from the
// face end, located within a cell, negative and bounded when the pressure indicates contact beyond
// the end; continuous in f and converging with the grid, docs/cycloid.md), named edge margin here
// and in the study's result. It replaced the edge-row clearance, whose zero moved with the cell.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/cycloid/loaded_tca.h"
#include "objectives/problem.h"

namespace camopt::objectives {

/// One judged crowning.
struct CrowningEvaluation {
  double coefficient_mm = 0;  ///< f of the logarithmic crowning (negative requests are taken as 0)
  double length_mm = 0;       ///< its effective length L
  double stress_MPa = 0;      ///< max contact stress over the design-torque cycle
  double edge_margin_um = 0;  ///< min end distance [µm] over the max-torque cycle
  int pairs = 0;              ///< max pairs in contact over the design-torque cycle
};

/// The two mesh cycles that judge a crowning: the design torque (stress) and the maximum torque
/// (edge margin), over the same crank angles. An evaluation depends on its arguments only (bit for
/// bit, whatever was evaluated before: the LTCA is pure, its solver caches change only the cost).
class CycloidCrowningModel {
 public:
  /// @param design_torque_Nmm, max_torque_Nmm disc torques [N·mm]; crank angles [rad].
  /// `shape` gives the logarithmic crowning's fields that are not tuned (end drop, flat length;
  /// its coefficient and effective length are replaced by Evaluate's arguments).
  CycloidCrowningModel(const cycloid::Drive& drive, const cycloid::Material& material,
                       const cycloid::LoadedOptions& options, double design_torque_Nmm,
                       double max_torque_Nmm, std::vector<double> crank_angles_rad,
                       const cycloid::Crowning& shape = {});

  /// Runs both cycles with a logarithmic crowning of coefficient f [mm] and length L [mm].
  CrowningEvaluation Evaluate(double coefficient_mm, double length_mm);
  int evaluations() const { return evaluations_; }
  const cycloid::Drive& drive() const { return drive_; }

 private:
  cycloid::Drive drive_;
  cycloid::LoadedTca design_, maximum_;
  cycloid::Crowning shape_;
  double design_torque_Nmm_, max_torque_Nmm_;
  std::vector<double> angles_;
  int evaluations_ = 0;
};

/// The evaluation with the lowest stress among those with edge_margin_um >= required_margin_um
/// (the first one on a tie), or none.
std::optional<CrowningEvaluation> LowestFeasibleStress(const std::vector<CrowningEvaluation>& evaluations,
                                                       double required_margin_um);
/// The evaluation with the largest edge margin (the first one on a tie). @pre not empty.
CrowningEvaluation LargestEdgeMargin(const std::vector<CrowningEvaluation>& evaluations);

/// Bounds and scaling of the crowning problem.
struct CycloidCrowningSpec {
  double coefficient_lo_mm = 0, coefficient_hi_mm = 0;
  double initial_coefficient_mm = 0;
  /// L is a variable when true (bounds [length_lo_mm, length_hi_mm], starting at length_lo_mm);
  /// otherwise it is fixed at length_lo_mm.
  bool tune_length = false;
  double length_lo_mm = 0, length_hi_mm = 0;
  double required_edge_margin_um = 0;  ///< edge_margin_um >= this
  double stress_scale_MPa = 1;         ///< typical stress (the solver sees stress / scale)
};

/// Output names of the problem's evaluator.
inline constexpr const char* kCrowningStress = "max_contact_stress_MPa";
inline constexpr const char* kCrowningEdgeMargin = "edge_margin_um";

/// The problem over x = [f] or [f, L]: minimise kCrowningStress subject to kCrowningEdgeMargin >=
/// spec.required_edge_margin_um. The evaluator runs the model once per distinct point (a point
/// asked for again, e.g. for a solver's final assessment, is answered from memory) and calls
/// on_evaluation (may be empty) after each run. `model` must outlive the problem.
Problem CycloidCrowningProblem(CycloidCrowningModel& model, const CycloidCrowningSpec& spec,
                               std::function<void(const CrowningEvaluation&)> on_evaluation);

}  // namespace camopt::objectives

namespace camopt::objectives {

// ---------------------------------------------------------------------------------------------
// Joint tuning of the profile modifications and any crowning's parameters with exact gradients
//. Variables are named by the field they set: the crowning's coefficient_mm,
// effective_length_mm, radius_mm, flat_length_mm, end_drop_mm [mm] and the modifications
// delta_position_um, delta_radius_um [µm]; what is not a variable keeps its start value.
//
// Outputs of the evaluator:
//   kTuningSmoothStress  the soft-max of the pairs' peak stresses over the design-torque cycle
//                        (cycloid::SmoothPeakPressure, temperature τ; bias 0 … τ ln N above the
//                        exact maximum, N = (angle, pair) terms) — the objective;
//   kTuningEndDistance   the end distance [µm] at every crank angle of the maximum-torque cycle
//                        (one constraint row per angle: smooth where the exact minimum switches);
//   kTuningLte           LTE peak-to-peak [arcsec] at the design torque (may be bounded);
//   kTuningBacklash      the unloaded TE β0 [arcsec] at every crank angle: the disc's rotation to
//                        first contact, >= 0 when no roller interferes with the modified tooth at
//                        the kinematic position (the assembly / backlash condition; without it
//                        the stress is lowest for a tooth fuller than the rollers' envelope).
// Values and exact first derivatives (implicit differentiation at the converged states,
// cycloid::DifferentiateCycle): value-only solvers (COBYLA) run DoEval only.
//
// Epigraph form (CycloidTuningSpec::epigraph, for the gradient solvers): the peak over crank
// angles and contact cells is non-smooth and its soft-max with a small temperature is stiff, so
// gradient methods stall on it. Instead the problem gets one more variable t (kTuningPeakBound,
// MPa, scaled by stress_scale_MPa) and minimises t subject to
//   kTuningStressExcess  p_(k,r) − t <= 0 for every crank angle k of the design cycle and every
//                        roller r (angle-major, n1 rows per angle): the peak pressure of roller
//                        r's pair at angle k (0 when it carries no load), with its exact gradient
//                        (peak cell frozen, cycloid::CycleDerivative::pair_max_pressure_MPa).
// Every row is smooth where the pair's peak cell stays put; at the optimum t is the exact maximum
// over the samples.
// ---------------------------------------------------------------------------------------------

inline constexpr const char* kTuningSmoothStress = "smooth_max_contact_stress_MPa";
inline constexpr const char* kTuningEndDistance = "end_distance_at_max_torque_um";
inline constexpr const char* kTuningLte = "lte_peak_to_peak_arcsec";
inline constexpr const char* kTuningBacklash = "unloaded_te_arcsec";
inline constexpr const char* kTuningPeakBound = "peak_stress_bound_MPa";
inline constexpr const char* kTuningStressExcess = "pair_peak_minus_bound_MPa";

/// Field names a tuning variable may have (per crowning type: see TuningVariableAllowed).
std::vector<std::string> TuningVariableNames();
/// "" when `name` may be tuned for this crowning type, else why not.
std::string TuningVariableAllowed(const std::string& name, cycloid::CrowningType type);

/// One judged design of the joint tuning.
struct TuningEvaluation {
  std::vector<double> x;                ///< the variables, in their own units
  double smooth_stress_MPa = 0;         ///< soft-max over the design cycle
  double stress_MPa = 0;                ///< exact maximum over the design cycle
  double edge_margin_um = 0;            ///< min end distance over the max-torque cycle [µm]
  std::vector<double> end_distance_um;  ///< per angle of the max-torque cycle
  std::vector<double> unloaded_te_arcsec;  ///< β0 per angle (the design cycle's angles)
  double lte_peak_to_peak_arcsec = 0;   ///< design cycle
  double max_pair_load_N = 0;           ///< design cycle
  int pairs = 0;
  bool converged = true;
  /// With gradients: d/dx of smooth stress, exact stress, LTE p-p (per variable), and of the end
  /// distance per angle (angle-major: [angle][variable]).
  std::vector<double> d_smooth_stress, d_stress, d_lte, d_end_distance, d_unloaded_te;
  /// The peak pressure of every (angle, roller) of the design cycle [MPa], angle-major (n1 per
  /// angle; 0 when the roller's pair carries no load), and with gradients its derivatives
  /// ([sample][variable]).
  std::vector<double> pair_peak_MPa, d_pair_peak;
};

/// The two mesh cycles of the joint tuning (design and maximum torque) over the same crank angles.
/// Pure: an evaluation depends on its arguments only.
class CycloidTuningModel {
 public:
  /// `drive` and `crowning` hold the start values (and every field that is not a variable).
  CycloidTuningModel(const cycloid::Drive& drive, const cycloid::Crowning& crowning,
                     const cycloid::Material& material, const cycloid::LoadedOptions& options,
                     double design_torque_Nmm, double max_torque_Nmm, std::vector<double> crank_angles_rad,
                     std::vector<std::string> variables, double temperature_MPa);

  /// Runs both cycles at x (in the variables' units); with_gradient adds the derivatives (the
  /// cycles of the previous call are reused when x is the same point).
  TuningEvaluation Evaluate(const std::vector<double>& x, bool with_gradient);
  /// The last Evaluate's values (no gradients) on these of its crank angles only (indices into
  /// crank_angles()): what a cycle over those angles reports, each angle's solve as the last
  /// cycle made it (warm-started from its neighbour in crank_angles(), so equal to a run over
  /// the subset alone to the contact solver's tolerance). For an error estimate by angle
  /// refinement from one run of the finer set.
  /// @throws std::logic_error before any evaluation; std::out_of_range for an index past the angles.
  TuningEvaluation EvaluatedOn(const std::vector<size_t>& angle_indices) const;
  /// The drive and crowning that x sets.
  std::pair<cycloid::Drive, cycloid::Crowning> Design(const std::vector<double>& x) const;
  const std::vector<std::string>& variables() const { return variables_; }
  const std::vector<double>& crank_angles() const { return angles_; }
  const cycloid::Drive& drive() const { return drive_; }
  /// Cycle runs (each both torques) and derivative runs.
  int evaluations() const { return evaluations_; }
  int gradient_evaluations() const { return gradient_evaluations_; }

 private:
  cycloid::Drive drive_;
  cycloid::Crowning crowning_;
  cycloid::LoadedTca design_, maximum_;
  double design_torque_Nmm_, max_torque_Nmm_;
  std::vector<double> angles_;
  std::vector<std::string> variables_;
  double temperature_MPa_;
  int evaluations_ = 0, gradient_evaluations_ = 0;
  // The last point's cycles: a gradient asked at the point just valued reuses them.
  std::vector<double> last_x_;
  std::optional<cycloid::CycleResult> last_design_, last_max_;
};

struct CycloidTuningSpec {
  std::vector<Variable> variables;       ///< names as the model's, bounds, start, scale
  double required_end_distance_um = 0;   ///< every angle's end distance >= this
  double max_lte_peak_to_peak_arcsec = kInf;  ///< LTE p-p <= this (kInf: unbounded)
  double min_unloaded_te_arcsec = 0;     ///< every angle's β0 >= this (-kInf: unbounded)
  double stress_scale_MPa = 1000;
  /// The epigraph form (above): variable kTuningPeakBound appended to `variables`, starting at
  /// initial_peak_bound_MPa (e.g. the start design's exact maximum).
  bool epigraph = false;
  double initial_peak_bound_MPa = 0;
};

/// Minimise kTuningSmoothStress (epigraph: kTuningPeakBound subject to kTuningStressExcess <= 0) subject to kTuningEndDistance >= required (per angle),
/// kTuningBacklash >= min (per angle, when finite) and, when bounded, kTuningLte <= max. Each distinct point runs once per kind (values / gradients; a
/// gradient run also answers values); on_evaluation is called after each model run.
Problem CycloidTuningProblem(CycloidTuningModel& model, const CycloidTuningSpec& spec,
                             std::function<void(const TuningEvaluation&)> on_evaluation);

}  // namespace camopt::objectives
