// The verified-optimum contract of every sizing and tuning study.
//
// An optimizer works on a fast model (slices contact, sampled crank angles); once it stops, the
// best design is re-evaluated by the accurate model at settings whose own error is estimated
// (dense angles, the half-space solver on a refined grid). A limit holds when the accurate value
// is within the limit plus its estimated error. Where it does not, the fast model's limit is
// tightened by the measured excess and the problem solved again (LimitTightening), until every
// limit holds or the round budget ends; then the study ends with exit 3 naming the limit, the
// accurate value and what to change. A design is never reported as `best` at a value its own
// accurate check contradicts.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace camopt::objectives {

/// One limit of a study as the accurate model sees the reported design.
struct VerifiedLimit {
  std::string limit;              ///< the study's limit key ("contact_stress_MPa", "edge_margin", ...)
  std::string where;              ///< which part ("input cam", "output cam", "design torque", ...)
  double limit_value = 0;         ///< the study's own limit
  double accurate_value = 0;      ///< the accurate model's value at the reported design
  double estimated_error = 0;     ///< of accurate_value (>= 0): refinement of its own settings
  double fast_value = 0;          ///< the fast model's value at the same design (NaN: none)
  bool upper = true;              ///< true: value <= limit; false: value >= limit
  /// The accurate value is within the limit plus its estimated error.
  bool holds() const {
    if (!std::isfinite(accurate_value)) return false;
    return upper ? accurate_value <= limit_value + estimated_error
                 : accurate_value >= limit_value - estimated_error;
  }
  /// By how much the accurate value breaks the limit beyond its error (0 when it holds), in the
  /// limit's unit.
  double excess() const {
    if (holds()) return 0;
    if (!std::isfinite(accurate_value)) return INFINITY;
    return upper ? accurate_value - limit_value - estimated_error
                 : limit_value - estimated_error - accurate_value;
  }
};

/// One round of the loop: the fast model's limit before and after.
struct TighteningStep {
  int round = 0;
  std::string limit, where;
  double fast_limit_before = 0, fast_limit_after = 0;
  double accurate_value = 0, limit_value = 0;
};

struct Verification {
  std::string accurate_model;            ///< what the accurate model was, in words with its settings
  std::vector<VerifiedLimit> checks;     ///< every checked limit at the reported design
  std::vector<TighteningStep> history;   ///< the tightening rounds, in order
  int max_rounds = 0;                    ///< the loop's budget
  bool ran = false;                      ///< false: nothing was verified (no design)
  /// Every check holds (and there was a check).
  bool verified() const {
    return ran && std::all_of(checks.begin(), checks.end(), [](const VerifiedLimit& c) { return c.holds(); });
  }
  /// The check that breaks its limit by the largest share of the limit, or nullptr.
  const VerifiedLimit* worst() const {
    const VerifiedLimit* w = nullptr;
    double share = 0;
    for (const VerifiedLimit& c : checks) {
      if (c.holds()) continue;
      const double s = c.excess() / std::max(std::abs(c.limit_value), 1e-12);
      if (!w || s > share) w = &c, share = s;
    }
    return w;
  }
};

/// The fast model's upper limit for the next round, from the ratio of the accurate value to the
/// fast one at the same design: the fast limit is scaled so that, if the ratio stays the same, the
/// accurate value lands on the study's limit (minus a margin of `margin` of it, so that the next
/// round does not land just above). Never loosened beyond the study's own limit.
inline double TightenedUpperLimit(double fast_limit, double study_limit, double fast_value,
                                  double accurate_value, double margin = 1e-3) {
  if (!(accurate_value > 0) || !(fast_value > 0)) return fast_limit * (1 - 0.05);
  const double ratio = accurate_value / fast_value;
  const double next = study_limit * (1 - margin) / ratio;
  return std::min(next, fast_limit * (1 - margin));
}

/// The same for a lower limit of a positive value (a stiffness): scaled so that, with the same
/// ratio, the accurate value lands on the study's limit plus `margin` of it; never loosened.
inline double TightenedLowerLimit(double fast_limit, double study_limit, double fast_value, double accurate_value,
                                  double margin = 1e-3) {
  if (!(accurate_value > 0) || !(fast_value > 0)) return fast_limit * (1 + 0.05);
  const double ratio = accurate_value / fast_value;
  const double next = study_limit * (1 + margin) / ratio;
  return std::max(next, fast_limit * (1 + margin));
}

}  // namespace camopt::objectives
