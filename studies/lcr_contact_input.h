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

/// The "contact" object itself (model, slices, grid, misalignment_mrad; misalignment with model
/// "line" is a StudyError).
lcr::ContactModelOptions ParseContactOptions(const Node& contact);

/// One roller "crowning" object, checked against the roller length. coefficient_given = false:
/// a logarithmic crown's coefficient_mm may be absent (a sizing variable), 0 then.
lcr::RollerCrowning<double> ParseRollerCrowning(const Node& n, double roller_length, bool coefficient_given = true);

/// "line", "slices" or "half_space".
const char* ContactModelName(lcr::ContactModel m);

}  // namespace camopt::studies
