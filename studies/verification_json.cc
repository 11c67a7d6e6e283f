#include "studies/verification_json.h"

#include <cmath>

#include "studies/format.h"
#include "studies/study.h"
#include "studies/archive.h"

namespace camopt::studies {

void AddVerificationJson(const objectives::Verification& v, nlohmann::json& result) {
  nlohmann::json checks = nlohmann::json::array(), steps = nlohmann::json::array();
  for (const objectives::VerifiedLimit& c : v.checks)
    checks.push_back({{"limit", c.limit},
                      {"where", c.where},
                      {"limit_value", Finite(c.limit_value, "verification limit")},
                      {"accurate_value", NumberOrNull(c.accurate_value)},
                      {"estimated_error", NumberOrNull(c.estimated_error)},
                      {"fast_value", NumberOrNull(c.fast_value)},
                      {"upper", c.upper},
                      {"holds", c.holds()}});
  for (const objectives::TighteningStep& t : v.history)
    steps.push_back({{"round", t.round},
                     {"limit", t.limit},
                     {"where", t.where},
                     {"fast_limit_before", NumberOrNull(t.fast_limit_before)},
                     {"fast_limit_after", NumberOrNull(t.fast_limit_after)},
                     {"accurate_value", NumberOrNull(t.accurate_value)},
                     {"limit_value", NumberOrNull(t.limit_value)}});
  result["verified"] = v.verified();
  result["verification"] = {{"accurate_model", v.accurate_model},
                            {"rounds", int(v.history.size())},
                            {"max_rounds", v.max_rounds},
                            {"checks", checks},
                            {"tightening", steps}};
}

void AddLimitSlopeJson(const objectives::LimitSlope* slope, nlohmann::json& entry) {
  const bool has = slope && !slope->sides.empty();
  entry["re_solve_slope"] = has ? NumberOrNull(slope->slope) : nlohmann::json(nullptr);
  entry["re_solve_sides"] = has ? nlohmann::json(slope->sides) : nlohmann::json(nullptr);
  entry["re_solve_step"] = slope ? NumberOrNull(slope->step) : nlohmann::json(nullptr);
  entry["re_solve_left_slope"] = slope ? NumberOrNull(slope->left) : nlohmann::json(nullptr);
  entry["re_solve_right_slope"] = slope ? NumberOrNull(slope->right) : nlohmann::json(nullptr);
  entry["kink"] = slope && slope->kink;
  entry["headline"] = has ? "re_solve_slope" : "limit_cost";
}

std::string VerificationFailure(const objectives::Verification& v, const std::string& advice) {
  if (v.verified()) return "";
  if (!v.ran) return "the design could not be verified by the accurate model" + (advice.empty() ? "" : ": " + advice);
  const objectives::VerifiedLimit* w = v.worst();
  if (!w) return "";
  std::string s = "not verified: " + w->limit + (w->where.empty() ? "" : " (" + w->where + ")") +
                  " is " + Format(w->accurate_value, 5) + " +- " + Format(w->estimated_error, 2) +
                  " by the accurate model (" + v.accurate_model + ") against the limit " +
                  Format(w->limit_value, 5);
  if (!v.history.empty()) s += " after " + std::to_string(v.history.size()) + " tightening rounds";
  if (!advice.empty()) s += ": " + advice;
  return s;
}

}  // namespace camopt::studies
