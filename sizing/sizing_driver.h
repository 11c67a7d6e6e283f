// The loop every sizing study runs, whatever it sizes (lcr_min_size, cycloid_min_size):
//
//   enumerate the candidates (an LCR's lobe/roller combinations with each catalogue roller; a
//   cycloid's tooth count) → solve each (its own starts and polish, in `solve`) → take the
//   smallest feasible one to the accurate model (`verify`: the verified-optimum contract of
//   objectives/verification.h, tightening and re-solving inside it where the kind does) → a
//   candidate whose verification fails is no longer feasible: the next smallest is verified,
//   until one holds or none is left.
//
// Branch and bound (optional, `solve_within`): a kind whose solve runs in steps that only add
// constraints (the LCR 3D polish: each round adds tracked contacts and force rows, so each round's
// optimum is a relaxation of the next) may stop a candidate once a step's optimum, a lower bound of
// its final size, exceeds a bound the driver gives. The driver then always advances the candidate
// with the smallest key (not yet started: −∞; stopped: its lower bound; solved: its size) until the
// smallest key is a solved candidate, which it verifies as above. A stopped ("pruned") candidate
// whose lower bound is not above the smallest solved size — e.g. after the verification raised the
// best's size or failed it — is continued, so the answer is the one of the loop without pruning
// when the lower bounds hold: a candidate is verified only when its size is below every other
// candidate's lower bound. With local solvers a step's optimum is a lower bound only as far as the
// local optima are global ones (the usual assumption of branch and bound over local solves).
//
// The driver owns the order and the bookkeeping; the kind owns its problems (a problem factory
// and its solves behind `solve`), its accurate model (behind `verify`) and its candidates' data.
// One verification per candidate: a candidate is verified at most once.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace camopt::sizing {

struct SizingCandidates {
  int count = 0;
  /// A name for progress ("Z1 = 4, Z2 = 3 ...", "29 teeth").
  std::function<std::string(int)> label;
  /// Solves candidate i (starts, polish); called once per candidate, in order. Not needed when
  /// solve_within is given.
  std::function<void(int)> solve;
  /// Optional, replaces solve (branch and bound): solves candidate i on its first call, continues
  /// it where it stopped on later calls; may stop once a lower bound of its size exceeds `bound`
  /// and then returns that lower bound, else solves to the end and returns nothing. Each call takes
  /// at least one step; finitely many calls solve a candidate to the end.
  std::function<std::optional<double>(int i, double bound)> solve_within;
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
  /// Per candidate: the lower bound of its size when it was left pruned (not solved to the end:
  /// the bound exceeds the best's size), else empty.
  std::vector<std::optional<double>> pruned;
  std::vector<int> calls;        ///< per candidate: solve or solve_within calls (1 + continuations)
};

/// Runs the loop; progress(fraction, label) is called before each solve or continuation (fraction:
/// the share of candidates started before it) and once at the end (may be empty).
SizingDriverResult RunSizingDriver(const SizingCandidates& candidates,
                                   const std::function<void(double, const std::string&)>& progress = nullptr);

}  // namespace camopt::sizing
