// The LCR sizing over its candidates: every lobe/roller combination of the ratio
// (objectives::LobeCombinations) with each catalogue roller (or the study's roller), solved — the
// line model by SolveLcrMinSize, a finite-length contact by SolveLcrMinSize3D with branch and bound
// (a candidate's polish stops once a round's outer diameter exceeds the best's size, and goes on
// when the best's verification raises it past that round) — then the smallest feasible one checked
// by the accurate model (line: the exact cycle on the dense grid, VerifyLcrLineDesign; 3D: the
// half-space model on a refined grid, tightening and re-solving where it breaks a limit,
// VerifyLcrMinSize3D); one that fails is dropped and the next smallest checked, until one holds or
// none is left (the shared loop, sizing/sizing_driver.h). Then, for the line model, the verified
// re-solve slopes of the answer's limits (LimitSlopes).
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "objectives/lcr_dense_check.h"
#include "objectives/lcr_sizing.h"
#include "objectives/verification.h"
#include "sizing/lcr_min_size.h"
#include "sizing/lcr_sizing3d.h"
#include "sizing/limit_slope.h"

namespace camopt::sizing {
// The sizing loops speak the objectives' vocabulary (problems, limits, the verification contract).
using namespace camopt::objectives;

/// A catalogue roller as the sizing uses it.
struct LcrCatalogueRoller {
  std::string name;
  double diameter_mm = 0, length_mm = 0, load_limit_N = 0;
  /// The roller's ratings C and C0 [N] as the catalogue gives them (0: not given); C is required
  /// when a life is asked (load.input_speed_rpm or duty_cycle).
  double dynamic_rating_N = 0, static_rating_N = 0;
};

/// What the search sizes: the candidates (ratio, lobe and difference ranges, catalogue), the
/// problem every candidate shares (base) and how each is solved.
struct LcrSearchSpec {
  long ratio = 0;
  int max_lobes = 40;
  std::vector<int> differences{1};
  LcrSizingSpec base;  ///< bounds, fixed sizes, material, load and the study's limits
  std::vector<LcrCatalogueRoller> catalogue;
  LcrMinSizeOptions options;
  /// The finite-length contact (crowning, misalignment, overload); empty: the line model.
  std::optional<LcrSizing3DSpec> contact3d;
};

struct LcrCandidate {
  LobeCombination combo{};
  int roller = -1;    ///< index into LcrSearchSpec::catalogue, −1 without a catalogue
  LcrSizingSpec spec;  ///< what was solved (counts, roller, the study's limits)
  LcrMinSizeOutcome outcome;
  std::optional<LcrMinSize3DOutcome> outcome3d;  ///< with LcrSearchSpec::contact3d
  /// The accurate model's check (objectives/verification.h), of the candidates that were chosen
  /// as best at some point: one that fails it is not feasible.
  std::optional<Verification> verification;
  std::optional<LcrHalfSpaceCheck> half_space;  ///< 3D: the verification's study-grid numbers
  bool feasible() const { return outcome.converged && (!verification || verification->verified()); }
  /// 3D: its polish stopped at the best's size (branch and bound; outcome3d->paused has the lower
  /// bound): not solved to the end, not feasible.
  bool pruned() const { return outcome3d && outcome3d->paused; }
};

struct LcrSearchOutcome {
  std::vector<LcrCandidate> candidates;
  int best = -1;  ///< index of the feasible candidate with the least objective, −1 when nothing fits
  /// d(objective)/d(limit) of the best design [mm of outer diameter, or W of loss with the efficiency
  /// objective, per unit of the limit], by limit key (line model only).
  std::map<std::string, double> limit_sensitivity;
  /// The same re-solves with both sides (sizing/limit_slope.h): the binding limits' re-solve slopes.
  std::map<std::string, LimitSlope> limit_slope;
  int value_evaluations = 0, gradient_evaluations = 0;
  std::optional<LcrHalfSpaceCheck> half_space;  ///< best design, with LcrSearchSpec::contact3d
};

/// "Z1/z1 + Z2/z2": a combination's lobes and rollers per stage.
std::string LobeCombinationName(const LobeCombination& c);

/// Runs the search; progress(fraction, candidate) as the sizing loop reports it (may be empty).
LcrSearchOutcome SearchLcrMinSize(const LcrSearchSpec& spec,
                                  const std::function<void(double, const std::string&)>& progress = nullptr);

}  // namespace camopt::sizing
