// Study kind "lcr_crowning_tuning" (issue 12): for a given lobe cam reducer, the logarithmic
// roller crowning per cam that minimises the largest contact pressure over a revolution at the
// design torque (worst over a misalignment range), with the pressure off the contact's ends at an
// overload torque; against uncrowned rollers, each checked with the half_space model.
// The problem is objectives/lcr_crowning_tuning.h; the contact models model/lcr/contact3d*.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/common/sliced_bearing_life.h"
#include "model/lcr/life.h"
#include "objectives/lcr_crowning_tuning.h"
#include "objectives/verification.h"
#include "studies/input.h"
#include "studies/lcr_input.h"
#include "studies/study.h"

namespace camopt::studies::lcr_crowning_tuning {

/// The lives of the tuned design, asked by "load.input_speed_rpm" or "duty_cycle" (docs/life.md,
/// "Sliced roller life under tilt"): the rollers' ratings, the eccentric bearing's when given.
struct LifeSpec {
  std::vector<lcr::LcrDutyLine> lines;
  std::array<double, 2> dynamic_rating_N{0, 0}, static_rating_N{0, 0};  ///< [0] input, [1] output rollers
  std::optional<EccentricBearingRating> eccentric;
};

struct Study {
  std::string name;
  objectives::LcrCrowningTuningSpec spec;
  bool half_space_check = true;
  int grid_nx = 48, grid_ny = 256;
  std::optional<LifeSpec> life;
};

/// The tuned design's lives: ISO 281 per bearing, and each roller sliced at every misalignment.
struct LifeResult {
  std::array<lcr::LcrBearingLife, 2> rollers;
  std::optional<lcr::LcrBearingLife> eccentric;
  std::vector<std::array<SlicedLife, 2>> sliced;  ///< per misalignment of the tuning
};

struct SideCheck {
  objectives::LcrCrowningCheck slices, half_space;
  std::vector<double> half_space_dy_mm;  // per misalignment (design torque)
};

struct Result {
  std::array<objectives::LcrCrowningSideResult, 2> tuned;
  std::array<SideCheck, 2> tuned_check, uncrowned_check;  // half_space part empty when not asked
  /// The tuned crowning checked by the accurate model (objectives/verification.h): not run when
  /// the half_space check is off.
  objectives::Verification verification;
  std::optional<LifeResult> life;  ///< with a speed or a duty cycle
};

/// @throws StudyError for bad input (exit 2).
Study Parse(const Node& root);
Result Run(const Study& study, const RunContext& ctx);
nlohmann::json ToJson(const Study& study, const Result& result);
/// result.json, stress_vs_coefficient.csv/.svg.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::lcr_crowning_tuning
