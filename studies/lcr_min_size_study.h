// Study kind "lcr_min_size": the smallest lobe cam reducer for a target speed ratio and output
// torque. Enumerates every lobe/roller combination giving the ratio exactly, solves each to the
// optimum of the exact constraints (sizing/lcr_min_size.h), and reports the best design, what
// each binding limit costs (limit_sensitivity), and one candidate per combination (and catalogue
// roller) with its multistart spread and, when nothing fits, the limits it breaks at its closest
// point. Nothing fitting is an incomplete result (exit code 3, outputs still written).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sizing/lcr_min_size.h"
#include "objectives/lcr_robust.h"
#include "sizing/lcr_robust_solve.h"
#include "objectives/lcr_sizing.h"
#include "sizing/lcr_sizing3d.h"
#include "studies/input.h"
#include "studies/study.h"

namespace camopt::studies::lcr_min_size {

struct CatalogueRoller {
  std::string name;
  double diameter_mm = 0, length_mm = 0, load_limit_N = 0;
  /// The roller's ratings C and C0 [N] as the catalogue gives them (0: not given); C is required
  /// when a life is asked (load.input_speed_rpm or duty_cycle).
  double dynamic_rating_N = 0, static_rating_N = 0;
};

struct Study {
  std::string name;
  long ratio = 0;
  double output_torque_Nmm = 0;
  int max_lobes = 40;
  std::vector<int> differences{1};
  objectives::LcrSizingSpec base;  ///< bounds, fixed sizes, material, load and the study's limits
  std::vector<CatalogueRoller> catalogue;
  objectives::LcrMinSizeOptions options;
  objectives::LcrConstraintForm form = objectives::LcrConstraintForm::kAggregate;  ///< as written
  /// The finite-length contact (crowning, misalignment, overload; studies/lcr_min_size_contact.h);
  /// empty: the line model.
  std::optional<objectives::LcrSizing3DSpec> contact3d;
  /// "tolerances" + "robust" (+ "monte_carlo"): studies/lcr_min_size_robust.cc. Null: nominal only.
  std::shared_ptr<const objectives::LcrRobustRule> robust;
  int mc_samples = 200, mc_angle_steps = 720;
  std::uint64_t mc_seed = 1;
};

struct Candidate {
  objectives::LobeCombination combo{};
  int roller = -1;  ///< index into Study::catalogue, −1 without a catalogue
  objectives::LcrSizingSpec spec;  ///< what was solved (counts, roller, the study's limits)
  objectives::LcrMinSizeOutcome outcome;
  std::optional<objectives::LcrMinSize3DOutcome> outcome3d;  ///< with Study::contact3d
  /// The accurate model's check (objectives/verification.h), of the candidates that were chosen
  /// as best at some point: one that fails it is not feasible.
  std::optional<objectives::Verification> verification;
  std::optional<objectives::LcrHalfSpaceCheck> half_space;  ///< 3D: the verification's study-grid numbers
  bool feasible() const { return outcome.converged && (!verification || verification->verified()); }
};

struct Result {
  std::vector<Candidate> candidates;
  int best = -1;  ///< index of the smallest feasible candidate, −1 when nothing fits
  /// d(outer diameter)/d(limit) of the best design [mm per unit of the limit], by limit key.
  std::map<std::string, double> limit_sensitivity;
  int value_evaluations = 0, gradient_evaluations = 0;
  std::optional<objectives::LcrHalfSpaceCheck> half_space;  ///< best design, with Study::contact3d
  double seconds = 0;  ///< wall time of the search (summary only, never in result.json)
  /// When nothing fits: the limit that blocks most, the closest candidate, and the value of that
  /// limit that its closest point needs.
  std::string blocking_message;
  /// With Study::robust: the robust solve of every candidate (same order), the smallest converged
  /// one, and the Monte-Carlo checks of the robust and the nominal best designs.
  std::vector<objectives::LcrRobustOutcome> robust;
  int robust_best = -1;
  std::optional<objectives::LcrMonteCarloCheck> robust_mc, nominal_mc;
  /// With Study::robust: the accurate check of the robust best design (its nominal limits).
  std::optional<objectives::Verification> robust_verification;
};

/// @throws StudyError for bad input (exit 2).
Study Parse(const Node& root);
/// The robust parts (studies/lcr_min_size_robust.cc): "tolerances", "robust", "monte_carlo" into s;
/// the robust solves and checks into r; "best" (robust), "nominal_best" and "robust" into res.
void ParseRobust(const Node& root, Study& s);
void RunRobust(const Study& s, Result& r, const RunContext& ctx);
void RobustJson(const Study& s, const Result& r, nlohmann::json& res);
Result Run(const Study& study, const RunContext& ctx);
nlohmann::json ToJson(const Study& study, const Result& result);
/// result.json, candidates.csv, outer_diameter.svg, best_lcr_analysis.json (when something fits);
/// marks the outputs incomplete (exit code 3) when nothing fits.
void Write(const Study& study, const Result& result, Outputs& out);
/// Lines for the terminal: best outer diameter, time, and what each binding limit costs
/// ("contact stress limit +10 MPa → −0.13 mm").
std::string Summary(const Study& study, const Result& result);

}  // namespace camopt::studies::lcr_min_size
