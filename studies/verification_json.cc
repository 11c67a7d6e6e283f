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

LimitSlopeResult MakeLimitSlopeResult(const sizing::LimitSlope* slope) {
  LimitSlopeResult r;
  const bool has = slope && !slope->sides.empty();
  if (has) {
    r.re_solve_slope = slope->slope;
    r.re_solve_sides = slope->sides;
  }
  if (slope) {
    r.re_solve_step = slope->step;
    r.re_solve_left_slope = slope->left;
    r.re_solve_right_slope = slope->right;
  }
  r.kink = slope && slope->kink;
  r.re_solve_confirms_limit_cost = slope && slope->confirms_multiplier;
  r.headline = has ? "re_solve_slope" : "limit_cost";
  return r;
}

void AddLimitSlopeJson(const sizing::LimitSlope* slope, nlohmann::json& entry) {
  const nlohmann::json members = WriteResult(MakeLimitSlopeResult(slope));
  for (auto it = members.begin(); it != members.end(); ++it) entry[it.key()] = it.value();
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
