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

namespace camopt::studies {

/// Adds "verified" and "verification" to result (an object).
void AddVerificationJson(const objectives::Verification& v, nlohmann::json& result);

/// The exit-3 sentence of a verification that does not hold: the limit, where, the accurate
/// value with its error, the limit, and `advice` (what to change). Empty when it holds.
std::string VerificationFailure(const objectives::Verification& v, const std::string& advice);

}  // namespace camopt::studies
