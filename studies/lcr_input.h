// Parsing the lobe cam reducer design, material and load from a study file; shared by every
// study kind that takes an LCR design (lcr_analysis, the lobe_cam_reducer rigidity element, …).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/lcr/life.h"
#include "model/lcr/reducer.h"
#include "studies/bearing_life_io.h"
#include "studies/input.h"
#include "studies/material_input.h"

namespace camopt::studies {

/// Reads {"eccentricity_mm", "input": {...}, "output": {...}}; each side has lobes, rollers,
/// turret_radius_mm, roller_diameter_mm, roller_length_mm, cam_thickness_mm. Checks the design
/// (lobes < rollers, rollers that overlap, …) and throws StudyError naming the JSON path.
/// allow_crowning: the sides may carry a "crowning" object (kinds with the finite-length contact).
/// allow_bearing_ratings: the sides may carry the rollers' "dynamic_rating_N" / "static_rating_N"
/// and the reducer an "eccentric_bearing" (kinds with the bearing life; read by the kind, checked
/// here to be > 0 wherever given).
lcr::Reducer<double> ParseReducer(const Node& reducer, bool allow_crowning = false, bool allow_bearing_ratings = false);

/// Optional cutter diameter per side ("cutter_diameter_mm", default the roller diameter);
/// must be > 0 and <= the roller diameter.
double ParseCutterDiameter(const Node& side, double roller_diameter);

/// The ratings of an eccentric bearing {"dynamic_rating_N" > 0, "static_rating_N" > 0 (optional),
/// "kind": "ball" | "roller"}: C, C0 (0 when not given) and whether it is a ball bearing.
struct EccentricBearingRating {
  double dynamic_N = 0.0, static_N = 0.0;
  bool ball = false;
};
EccentricBearingRating ParseEccentricBearing(const Node& node);

}  // namespace camopt::studies
