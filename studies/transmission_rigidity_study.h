// Study kind "transmission_rigidity": the torsional rigidity and backlash of a series chain of
// shafts, gears, chains, belts, pull-rods, levers, couplings (the transmission-rigidity paper,
// docs/rigidity.md) and lobe cam reducers, seen from either end, with each element's share of the
// compliance and the design advice the paper gives by hand (which element dominates, which
// dimension to change).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/lcr/reducer.h"
#include "model/rigidity/chain.h"
#include "model/rigidity/chain_elements.h"
#include "model/rigidity/lcr_stiffness.h"
#include "studies/input.h"
#include "studies/study.h"

namespace camopt::studies::transmission_rigidity {

/// A lobe_cam_reducer element's own inputs (model units).
struct ReducerElement {
  lcr::Reducer<double> reducer;
  lcr::Material material;
  double torque_Nmm = 0;             ///< output torque (magnitude)
  double clearance_mm = 0;
  double bearing_N_per_mm = 0;       ///< needle bearing radial stiffness; 0 = rigid
  int angle_steps = 720;
  std::string direction = "forward";
  double sense = 1;                  ///< sign of the loaded torque in the model's convention
  std::string where;                 ///< "FILE: PATH" of the element, for load errors
};

struct Element {
  rigidity::ElementSpec spec;  ///< for a reducer, ratio and rigidity are filled by Run
  std::optional<ReducerElement> reducer;
};

struct Study {
  std::string name;
  std::vector<Element> elements;
  std::optional<double> report_radius_mm;
  std::optional<double> load_torque_Nm;
  std::string chain_where;  ///< "FILE: PATH" of the chain, for an all-rigid chain
};

/// What a reducer element reports besides its chain numbers.
struct ReducerResult {
  double speed_reduction_ratio = 0;  ///< signed, as the LCR model defines it
  rigidity::ReducerStiffnessCycle cycle;    ///< under the load, in its sense
  rigidity::ReducerStiffnessCycle reverse;  ///< under the load in the other sense
  std::vector<double> torques_Nmm, rotations_rad;  ///< lost-motion curve, in the load sense
  double dead_band_rad = 0;
  double lost_motion_rad = 0;        ///< between ±3 % of the load torque
  double rigidity_at_input_Nm_per_rad = 0;  ///< its own rigidity seen from its input shaft
};

struct ElementResult {
  rigidity::ElementSpec spec;        ///< with a reducer's ratio and rigidity filled in
  double compliance_rad_per_Nmm = 0; ///< own compliance (0: rigid)
  /// ∂ln R/∂ln p of the chain's rigidity for each named parameter of the element.
  std::vector<std::pair<std::string, double>> elasticity;
  std::optional<ReducerResult> reducer;
};

struct Result {
  rigidity::ChainResult<double> chain;
  std::optional<double> linear_stiffness_at_report_radius_N_per_mm;
  std::optional<double> deflection_at_end_b_rad;  ///< under load_torque_Nm
  std::vector<ElementResult> elements;
  int most_effective = -1;  ///< index into the dominant element's elasticity, −1 for none
  std::string advice;
};

/// @throws StudyError for bad input (exit 2).
Study Parse(const Node& root);
/// @throws StudyError when a reducer cannot carry its load or every element is rigid.
Result Run(const Study& study, const RunContext& ctx);
nlohmann::json ToJson(const Study& study, const Result& result);
/// result.json, elements.csv and, per reducer k, reducer_k_stiffness.csv/.svg and
/// reducer_k_lost_motion.csv/.svg.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::transmission_rigidity
