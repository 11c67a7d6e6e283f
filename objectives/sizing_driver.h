// The loop every sizing study runs, whatever it sizes (lcr_min_size, cycloid_min_size):
//
//   enumerate the candidates (an LCR's lobe/roller combinations with each catalogue roller; a
//   cycloid's tooth count) → solve each (its own starts and polish, in `solve`) → take the
//   smallest feasible one to the accurate model (`verify`: the verified-optimum contract of
//   objectives/verification.h, tightening and re-solving inside it where the kind does) → a
//   candidate whose verification fails is no longer feasible: the next smallest is verified,
//   until one holds or none is left.
//
// The driver owns the order and the bookkeeping; the kind owns its problems (a problem factory
// and its solves behind `solve`), its accurate model (behind `verify`) and its candidates' data.
// One verification per candidate: a candidate is verified at most once.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace camopt::objectives {

struct SizingCandidates {
  int count = 0;
  /// A name for progress ("Z1 = 4, Z2 = 3 ...", "29 teeth").
  std::function<std::string(int)> label;
  /// Solves candidate i (starts, polish); called once per candidate, in order.
  std::function<void(int)> solve;
  /// The size of candidate i when it is feasible now (solved to a design that holds its limits on
  /// the fast model, and not failed by its verification), else empty.
  std::function<std::optional<double>(int)> feasible_size;
  /// Runs the accurate check of candidate i (and the kind's tightening rounds); afterwards
  /// feasible_size(i) says whether it holds.
  std::function<void(int)> verify;
};

struct SizingDriverResult {
  int best = -1;                 ///< the smallest verified feasible candidate, −1 when none
  std::vector<int> verified;     ///< candidates verified, in order (a failed one is followed by the next)
};

/// Runs the loop; progress(fraction, label) is called before each solve and once at the end (may
/// be empty).
SizingDriverResult RunSizingDriver(const SizingCandidates& candidates,
                                   const std::function<void(double, const std::string&)>& progress = nullptr);

}  // namespace camopt::objectives
