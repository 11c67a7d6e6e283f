// Parsing the finite-length contact of the LCR (issue 12): the top-level "contact" object
// {model: line | slices | half_space, slices: N, grid: [nx, ny], misalignment_mrad: γ} and the
// per-side roller "crowning" objects under reducer.input / reducer.output. Shared by lcr_analysis
// (and the sizing kinds later).
#pragma once

#include "model/lcr/contact3d.h"
#include "studies/input.h"

namespace camopt::studies {

struct LcrContactInput {
  bool given = false;  // the study has a "contact" object
  lcr::ContactModelOptions options;
  lcr::RollerCrowning<double> input_crowning, output_crowning;
};

/// Reads root["contact"] and root["reducer"][side]["crowning"]; checks each crowning against its
/// roller length. Crowning or misalignment with model "line" (the default) is a StudyError (exit
/// 2: the line model ignores them).
LcrContactInput ParseLcrContact(const Node& root, const lcr::Reducer<double>& reducer);

/// "line", "slices" or "half_space".
const char* ContactModelName(lcr::ContactModel m);

}  // namespace camopt::studies
