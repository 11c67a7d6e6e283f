// The designs of experiments of a sweep (docs/studies.md, "Sweeps"): the cases a sweep runs and
// their order, factorial, zip, latin_hypercube or sobol over the sweep's variations. As OpenMDAO
// separates its case generators from its drivers and recorders, the cases are generated here,
// run by studies/sweep.cc, checkpointed by studies/sweep_checkpoint.h and their Pareto front
// found by studies/sweep_pareto.h.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "studies/sweep.h"

namespace camopt::studies::sweep {

/// The `count` levels of a variation's range, evenly spaced (in log(value) when v.log), the last
/// exactly v.hi, rounded to whole numbers when v.integer.
std::vector<nlohmann::json> RangeLevels(const Variation& v, int count);

/// The cases of the design, in order: for each case, one value per variation.
std::vector<std::vector<nlohmann::json>> Cases(const Sweep& sweep);

}  // namespace camopt::studies::sweep
