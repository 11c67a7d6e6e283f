#include "studies/verification_json.h"

#include <cmath>

#include "studies/format.h"
#include "studies/study.h"
#include "studies/archive.h"

namespace camopt::studies {

VerificationBlock VerificationBlock::Of(const objectives::Verification& v) {
  VerificationBlock b;
  b.accurate_model = v.accurate_model;
  b.rounds = int(v.history.size());
  b.max_rounds = v.max_rounds;
  b.checks.emplace();
  for (const objectives::VerifiedLimit& c : v.checks)
    b.checks->push_back({c.limit, c.where, c.limit_value, c.accurate_value, c.estimated_error, c.fast_value, c.upper,
                         c.holds()});
  b.tightening.emplace();
  for (const objectives::TighteningStep& t : v.history)
    b.tightening->push_back({t.round, t.limit, t.where, t.fast_limit_before, t.fast_limit_after, t.accurate_value,
                             t.limit_value});
  return b;
}

VerificationBlock VerificationBlock::NotRun(std::string note) {
  VerificationBlock b;
  b.note = std::move(note);
  return b;
}

void AddVerificationJson(const objectives::Verification& v, nlohmann::json& result) {
  result["verified"] = v.verified();
  result["verification"] = WriteResult(VerificationBlock::Of(v));
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
