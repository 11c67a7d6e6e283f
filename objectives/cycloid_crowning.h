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
