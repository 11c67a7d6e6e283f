// The pitch-curve curvature at every roller of one cam over a cycle, by AnalyzeCycle's
// structure-of-arrays contact kernel (cycle.cc): bit for bit RollerContacts(r, s, θ)[k].curvature
// (contact.h), without the per-angle vectors of RollerContacts.
#pragma once

#include <vector>

#include "model/lcr/reducer.h"

namespace camopt::lcr {

/// κ [1/mm] of roller k at theta_rad[i] in [i * rollers + k] (rollers = r.side(s).rollers).
std::vector<double> CycleCurvatures(const Reducer<double>& r, Side s, const std::vector<double>& theta_rad);

}  // namespace camopt::lcr
