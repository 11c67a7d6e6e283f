// result.json's form of the verified-optimum contract (objectives/verification.h), one writer for
// every sizing and tuning kind:
//   "verified": true | false,
//   "verification": {"accurate_model": "...", "rounds": n, "max_rounds": m,
//     "checks": [{"limit", "where", "limit_value", "accurate_value", "estimated_error",
//                 "fast_value", "upper", "holds"}, ...],
//     "tightening": [{"round", "limit", "where", "fast_limit_before", "fast_limit_after",
//                     "accurate_value", "limit_value"}, ...]}
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "objectives/verification.h"
#include "sizing/limit_slope.h"

namespace camopt::studies {

/// Adds "verified" and "verification" to result (an object).
void AddVerificationJson(const objectives::Verification& v, nlohmann::json& result);

/// A binding limit's verified re-solve slope (sizing/limit_slope.h) into its `binding_limits`
/// entry: re_solve_slope (null when no side solved or it was not computed), re_solve_sides
/// ("central", "left", "right"; null), re_solve_step, re_solve_left_slope / re_solve_right_slope,
/// kink, and `headline`: which of limit_cost and re_solve_slope to quote ("re_solve_slope" whenever
/// it exists: it is what moving the limit does).
void AddLimitSlopeJson(const objectives::LimitSlope* slope, nlohmann::json& entry);

/// The exit-3 sentence of a verification that does not hold: the limit, where, the accurate
/// value with its error, the limit, and `advice` (what to change). Empty when it holds.
std::string VerificationFailure(const objectives::Verification& v, const std::string& advice);

}  // namespace camopt::studies
