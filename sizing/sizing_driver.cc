#include "sizing/sizing_driver.h"

#include "sizing/stage_clock.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace camopt::sizing {

SizingDriverResult RunSizingDriver(const SizingCandidates& c,
                                   const std::function<void(double, const std::string&)>& progress) {
  if ((!c.solve && !c.solve_within) || !c.feasible_size || !c.verify)
    throw std::invalid_argument("RunSizingDriver: missing hooks");
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const size_t n = size_t(std::max(c.count, 0));
  SizingDriverResult out;
  out.pruned.assign(n, std::nullopt);
  out.calls.assign(n, 0);
  // A candidate's state: not started, stopped at a lower bound (out.pruned), solved to the end.
  std::vector<bool> solved(n, false), checked(n, false);
  int started = 0;
  bool ended = false;  // the end of the solves was reported
  const auto end_of_solves = [&] {
    if (progress && !ended) progress(1.0, std::to_string(c.count) + " candidates");
    ended = true;
  };
  // The key the next step goes by: not started −∞, pruned its lower bound, solved its size (none
  // when infeasible). Ties: an unsolved candidate before a solved one (its size may equal the
  // bound), then the lower index (the loop without pruning took the first of equal sizes).
  const auto key = [&](size_t i) -> std::optional<double> {
    if (!solved[i]) return out.calls[i] == 0 ? -kInf : *out.pruned[i];
    return c.feasible_size(int(i));
  };
  const auto before = [&](size_t i, double ki, size_t j, double kj) {
    if (ki != kj) return ki < kj;
    if (solved[i] != solved[j]) return !solved[i];
    return i < j;
  };
  for (;;) {
    int pick = -1;
    double pick_key = 0;
    for (size_t i = 0; i < n; ++i) {
      const std::optional<double> k = key(i);
      if (k && (pick < 0 || before(i, *k, size_t(pick), pick_key))) pick = int(i), pick_key = *k;
    }
    if (pick < 0) {
      end_of_solves();
      out.best = -1;  // none left
      break;
    }
    const size_t p = size_t(pick);
    if (!solved[p]) {
      // Advance it until its lower bound passes the next smallest key (any state), or to the end.
      double bound = kInf;
      for (size_t i = 0; i < n; ++i) {
        if (i == p) continue;
        const std::optional<double> k = key(i);
        if (k && *k < bound) bound = *k;
      }
      const bool first = out.calls[p] == 0;
      if (progress)
        progress(double(started) / c.count,
                 (c.label ? c.label(pick) : std::to_string(pick + 1)) + (first ? "" : " (continued)"));
      if (first) ++started;
      ++out.calls[p];
      std::optional<double> lower;
      if (c.solve_within)
        lower = c.solve_within(pick, bound);
      else
        c.solve(pick);
      out.pruned[p] = lower;
      solved[p] = !lower;
      continue;
    }
    out.best = pick;
    if (checked[p]) break;  // checked and holds, and no other can be smaller: the answer
    end_of_solves();
    checked[p] = true;
    out.verified.push_back(pick);
    const StageClock::Scope stage("verification");
    c.verify(pick);
  }
  return out;
}

}  // namespace camopt::sizing
