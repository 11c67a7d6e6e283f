// Study kind "disc_cam_min_size": the smallest base circle of a disc cam with a translating roller
// follower for its motion program, under the disc_cam limits (pressure angle on the rise and on
// the return, radius margin against undercut, contact stress), with the base circle radius, the
// offset and the roller radius as variables (objectives/disc_cam_min_size.h).
//
// The file is a disc_cam study (docs/studies.md "disc_cam"; its design is the start and gives every
// value that is not a variable) plus "variables" ({"base_circle_radius_mm": [lo, hi], "offset_mm":
// [lo, hi], "roller_radius_mm": [lo, hi]}, the base circle required), an optional "optimizer" and
// an "analysis" of the sizing's own (the fast rows' angle count and the accurate grid's factor).
// The answer is verified by the accurate model (objectives/verification.h); a design that is not
// verified, or none, ends with exit 3 and the limit that blocks. Beside result.json:
// best_disc_cam.json (the best design as a disc_cam study), series.csv and pressure_angle.svg (the
// best design on the accurate grid).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "objectives/disc_cam_min_size.h"
#include "studies/disc_cam_study.h"
#include "studies/input.h"
#include "studies/study.h"

namespace camopt::studies::disc_cam_min_size {

inline constexpr int kDefaultAngleSteps = 360;
inline constexpr int kDefaultAccurateFactor = 8;
inline constexpr int kDefaultMaxEvaluations = 500;
inline constexpr int kDefaultVerifyRounds = 4;

struct Study {
  std::string name;
  disc_cam::Study base;      ///< the disc_cam study (its design is the start)
  nlohmann::json base_json;  ///< its file text, for best_disc_cam.json
  objectives::DiscCamSizingSpec spec;
  objectives::DiscCamMinSizeOptions options;
  std::string backend = "ipopt";  ///< as in the file: "ipopt" or "slsqp"
};

struct Result {
  objectives::DiscCamMinSizeOutcome outcome;
  /// Not empty when the answer is not what was asked (exit 3): what blocks and what would help.
  std::string blocking_message;
};

/// @throws StudyError for bad input (exit 2) with the JSON path.
Study Parse(const Node& root);
Result Run(const Study& study, const RunContext& ctx);
nlohmann::json ToJson(const Study& study, const Result& result);
/// The best design as a complete disc_cam study; null when there is no design.
nlohmann::json BestDiscCamStudy(const Study& study, const Result& result);
/// result.json, best_disc_cam.json, series.csv, pressure_angle.svg; marks the outputs incomplete
/// (exit 3) when the answer is not verified or there is none.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::disc_cam_min_size
