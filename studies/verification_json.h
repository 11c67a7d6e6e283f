// result.json's form of the verified-optimum contract (objectives/verification.h), one writer for
// every sizing and tuning kind:
//   "verified": true | false,
//   "verification": {"accurate_model": "...", "rounds": n, "max_rounds": m,
//     "checks": [{"limit", "where", "limit_value", "accurate_value", "estimated_error",
//                 "fast_value", "upper", "holds"}, ...],
//     "tightening": [{"round", "limit", "where", "fast_limit_before", "fast_limit_after",
//                     "accurate_value", "limit_value"}, ...]}
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "objectives/verification.h"
#include "sizing/limit_slope.h"
#include "studies/archive.h"

namespace camopt::studies {

/// The "verification" block above, declared (studies/archive.h) for the kinds whose result is: a
/// member `VerificationBlock verification` of their Result, filled with Of (or NotRun).
struct VerificationBlock {
  struct Check {
    std::string limit, where;
    double limit_value = 0, accurate_value = 0, estimated_error = 0, fast_value = 0;
    bool upper = true, holds = false;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("limit", &limit, Field().Desc("the study's limit key"));
      a->Visit("where", &where, Field().Desc("which part, torque or misalignment"));
      a->Visit("limit_value", &limit_value, Field().Desc("the study's own limit"));
      a->Visit("accurate_value", &accurate_value,
               Field().NullWhenNotFinite().Desc("the accurate model's value at the reported design"));
      a->Visit("estimated_error", &estimated_error, Field().NullWhenNotFinite().Desc("of accurate_value (>= 0)"));
      a->Visit("fast_value", &fast_value, Field().NullWhenNotFinite().Desc("the fast model's value at the same design"));
      a->Visit("upper", &upper, Field().Desc("true: value <= limit; false: value >= limit"));
      a->Visit("holds", &holds, Field().Desc("the accurate value is within the limit plus its estimated error"));
    }
  };
  struct Step {
    int round = 0;
    std::string limit, where;
    double fast_limit_before = 0, fast_limit_after = 0, accurate_value = 0, limit_value = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("round", &round, Field());
      a->Visit("limit", &limit, Field());
      a->Visit("where", &where, Field());
      a->Visit("fast_limit_before", &fast_limit_before, Field().NullWhenNotFinite().Desc("the fast model's limit"));
      a->Visit("fast_limit_after", &fast_limit_after, Field().NullWhenNotFinite().Desc("tightened for the next round"));
      a->Visit("accurate_value", &accurate_value, Field().NullWhenNotFinite());
      a->Visit("limit_value", &limit_value, Field().NullWhenNotFinite());
    }
  };
  std::optional<std::string> accurate_model;  ///< null: the check was not run (`note` says why)
  std::optional<int> rounds, max_rounds;
  std::optional<std::vector<Check>> checks;
  std::optional<std::vector<Step>> tightening;
  std::optional<std::string> note;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("accurate_model", &accurate_model,
             Field().NullWhenAbsent().Desc("what the accurate model was, with its settings (null: not run)"));
    a->Visit("rounds", &rounds, Field().Desc("tightening rounds run"));
    a->Visit("max_rounds", &max_rounds, Field().Desc("the loop's budget"));
    a->Visit("checks", &checks, Field().Desc("every checked limit at the reported design"));
    a->Visit("tightening", &tightening, Field().Desc("the tightening rounds, in order"));
    a->Visit("note", &note, Field().Desc("why the check was not run"));
  }
  /// The block of a verification that ran (or was attempted).
  static VerificationBlock Of(const objectives::Verification& v);
  /// The block of a check not run: accurate_model null, `note` saying why.
  static VerificationBlock NotRun(std::string note);
};

/// Adds "verified" and "verification" to result (an object).
void AddVerificationJson(const objectives::Verification& v, nlohmann::json& result);

/// A binding limit's verified re-solve slope (sizing/limit_slope.h) into its `binding_limits`
/// entry: re_solve_slope (null when no side solved or it was not computed), re_solve_sides
/// ("central", "left", "right"; null), re_solve_step, re_solve_left_slope / re_solve_right_slope,
/// kink, and `headline`: which of limit_cost and re_solve_slope to quote ("re_solve_slope" whenever
/// it exists: it is what moving the limit does).
void AddLimitSlopeJson(const sizing::LimitSlope* slope, nlohmann::json& entry);

struct LimitSlopeResult {
  double re_solve_slope = std::numeric_limits<double>::quiet_NaN();
  std::optional<std::string> re_solve_sides;
  double re_solve_step = std::numeric_limits<double>::quiet_NaN();
  double re_solve_left_slope = std::numeric_limits<double>::quiet_NaN();
  double re_solve_right_slope = std::numeric_limits<double>::quiet_NaN();
  bool kink = false;
  bool re_solve_confirms_limit_cost = false;
  std::string headline = "limit_cost";
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("re_solve_slope", &re_solve_slope,
             Field().NullWhenNotFinite().Desc("the objective's slope against the limit from verified re-solves with the "
                                              "limit moved (null: no side solved, or not computed)"));
    a->Visit("re_solve_sides", &re_solve_sides,
             Field().NullWhenAbsent().Desc("which re-solves it is from: central, left or right (null: none)"));
    a->Visit("re_solve_step", &re_solve_step,
             Field().NullWhenNotFinite().Desc("the limit's move, in its unit (null: not computed)"));
    a->Visit("re_solve_left_slope", &re_solve_left_slope,
             Field().NullWhenNotFinite().Desc("the slope from the lowered limit alone (null: none)"));
    a->Visit("re_solve_right_slope", &re_solve_right_slope,
             Field().NullWhenNotFinite().Desc("the slope from the raised limit alone (null: none)"));
    a->Visit("kink", &kink, Field().Desc("the two sides' slopes disagree beyond their errors"));
    a->Visit("re_solve_confirms_limit_cost", &re_solve_confirms_limit_cost,
             Field().Desc("one side was re-solved and its slope agrees with limit_cost (the KKT multiplier) within "
                          "its error and 10%, so the other side was not solved (a kink on that side would not show)"));
    a->Visit("headline", &headline,
             Field().OneOf({"re_solve_slope", "limit_cost"}).Desc("which of the two to quote (re_solve_slope whenever it exists)"));
  }
};

/// The re-solve members of a binding limit's declared entry; `slope` null: not computed.
LimitSlopeResult MakeLimitSlopeResult(const sizing::LimitSlope* slope);

/// A limit that binds at a sizing's answer and what it costs: an entry of the sizing kinds'
/// `binding_limits`. limit_cost is d(objective)/d(limit) in `unit` (the objective's unit per the
/// limit's): from the solver's multipliers where the kind has them, else itself the re-solve slope.
struct BindingLimit {
  std::string limit;
  double limit_value = 0, limit_cost = 0;
  std::string unit;
  LimitSlopeResult slope;  ///< its members are the entry's own
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("limit", &limit, Field().Desc("the study's limit key"));
    a->Visit("limit_value", &limit_value, Field().NullWhenNotFinite().Desc("the study's limit, in its unit"));
    a->Visit("limit_cost", &limit_cost,
             Field().Desc("d(objective)/d(limit) in unit, from the solver's multipliers where the kind has them, "
                          "else the re-solve slope (negative: relaxing the limit shrinks the design)"));
    a->Visit("unit", &unit, Field().Desc("of limit_cost: the objective's unit per the limit's"));
    slope.Serialize(a);
  }
};

/// The exit-3 sentence of a verification that does not hold: the limit, where, the accurate
/// value with its error, the limit, and `advice` (what to change). Empty when it holds.
std::string VerificationFailure(const objectives::Verification& v, const std::string& advice);

}  // namespace camopt::studies
