// Study kind "cycloid_min_size": the smallest one-tooth-difference cycloid drive for a ratio and a
// torque, its pin circle, pins, eccentricity, face width, profile modifications and crowning sized
// together on the 3D loaded contact (objectives/cycloid_min_size.h; the loaded tooth contact
// analysis of model/cycloid/loaded_tca.h, the closed-form limits of model/cycloid/geometry_limits.h).
//
// The file names each sized quantity by the cycloid_ltca field it sets; "variables" gives each a
// range or a fixed value, "drive" / "modification" / "crowning" the fields that are not variables.
// Before any work the most favourable corner of the ranges is checked against the closed-form
// limits (curtate, undercut, pin gap, web): a box in which every design breaks one is bad input
// (exit 2) naming the bound that would fit. The answer is verified by the accurate model
// (objectives/verification.h); a design that is not verified, or no design, ends with exit 3 and
// the limit that blocks. Beside result.json: best_cycloid_ltca.json (the best design as a
// cycloid_ltca study), the stress over the cycle and the pressure map at the worst angle of the
// best design at the accurate settings.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/cycloid/loaded_tca.h"
#include "objectives/cycloid_min_size.h"
#include "studies/input.h"
#include "studies/study.h"

namespace camopt::studies::cycloid_min_size {

/// Defaults of the "optimizer" block.
inline constexpr int kDefaultStarts = 2;
inline constexpr int kDefaultMaxEvaluations = 200;
inline constexpr int kDefaultVerifyRounds = 3;
/// Defaults of the "analysis" block (as cycloid_crowning_tuning).
inline constexpr int kDefaultCrankAnglesPerMeshPeriod = 6;

struct Study {
  std::string name;
  /// Teeth, rollers, torques, material, the fast model's grid and angles, the variables (bounds and
  /// starts in their own units), the fixed fields (in spec.drive / spec.crowning), the limits and the
  /// objective: what objectives::SolveCycloidMinSize is given.
  objectives::CycloidSizingSpec spec;
  objectives::CycloidMinSizeOptions options;  ///< without the progress callback (set by Run)
  double design_torque_Nm = 0, overload_torque_Nm = 0;  ///< as in the file (0: no overload)
  bool ratio_given = false;          ///< target.speed_ratio (else target.teeth)
  double bore_diameter_mm = 0;       ///< limits.bore_diameter_mm (0: none)
  std::string backend = "ipopt";     ///< as in the file: "ipopt" or "slsqp"
};

struct Result {
  objectives::CycloidMinSizeOutcome outcome;
  /// The best design's cycle at the design torque on the accurate settings (cells and crank angles
  /// twice the study's): the stress plot and the pressure map. Empty when there is no design.
  cycloid::CycleResult best_cycle;
  std::vector<double> best_cycle_angles_rad;
  /// Not empty when the answer is not what was asked (exit 3): the limit that blocks, its value and
  /// what would fit.
  std::string blocking_message;
  std::vector<std::string> warnings;  ///< result.json "warnings" (the run's own)
  double seconds = 0;  ///< wall time of the run (stderr summary only, never in a file)
};

/// @throws StudyError for bad input (exit 2).
Study Parse(const Node& root);
Result Run(const Study& study, const RunContext& ctx);
nlohmann::json ToJson(const Study& study, const Result& result);
/// The best design as a complete cycloid_ltca study (the accurate settings, the design torque);
/// null when there is no design.
nlohmann::json BestCycloidLtcaStudy(const Study& study, const Result& result);
/// result.json, best_cycloid_ltca.json, stress_over_cycle.csv/.svg, pressure_map.svg; marks the
/// outputs incomplete (exit 3) when the answer is not verified or there is none.
void Write(const Study& study, const Result& result, Outputs& out);
/// Lines for the terminal: outer diameter, what each binding limit costs, the time split.
std::string Summary(const Study& study, const Result& result);

}  // namespace camopt::studies::cycloid_min_size
