// Study kind "lcr_crowning_tuning" (issue 12): for a given lobe cam reducer, the logarithmic
// roller crowning per cam that minimises the largest contact pressure over a revolution at the
// design torque (worst over a misalignment range), with the pressure off the contact's ends at an
// overload torque; against uncrowned rollers, each checked with the half_space model.
// The problem is objectives/lcr_crowning_tuning.h; the contact models model/lcr/contact3d*.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "objectives/lcr_crowning_tuning.h"
#include "objectives/verification.h"
#include "studies/input.h"
#include "studies/study.h"

namespace camopt::studies::lcr_crowning_tuning {

struct Study {
  std::string name;
  objectives::LcrCrowningTuningSpec spec;
  bool half_space_check = true;
  int grid_nx = 48, grid_ny = 256;
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
};

/// @throws StudyError for bad input (exit 2).
Study Parse(const Node& root);
Result Run(const Study& study, const RunContext& ctx);
nlohmann::json ToJson(const Study& study, const Result& result);
/// result.json, stress_vs_coefficient.csv/.svg.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::lcr_crowning_tuning
