// The robust parts of study kind "lcr_min_size" (docs/lcr.md, "Sizing across tolerances"):
// "tolerances" (as lcr_analysis reads them, studies/lcr_tolerance_input.h), "robust":
// {"method": "worst_case" | "sigma", "k"} and
// "monte_carlo": {"samples", "seed", "angle_steps"}. Every candidate is solved again with the
// robust rows (objectives/lcr_robust.h) from its nominal optimum; result.json's "best" is the
// smallest robust design, "nominal_best" the study without tolerances, and both carry the
// Monte-Carlo check against the exact model.
#include <algorithm>
#include <cmath>

#include "model/lcr/kinematics.h"
#include "studies/lcr_min_size_study.h"
#include "studies/verification_json.h"
#include "studies/lcr_tolerance_input.h"
#include "studies/report.h"

namespace camopt::studies::lcr_min_size {
namespace {

// The robust best's cam side: its counts, turret radius and roller diameter.
Result::Json::CandidateSide Side(const lcr::CamSide<double>& c) {
  Result::Json::CandidateSide r;
  r.lobes = c.lobes, r.rollers = c.rollers;
  r.turret_radius_mm = c.turret_radius;
  r.roller_diameter_mm = 2 * c.roller_radius;
  return r;
}

Result::Json::MonteCarloCheck MonteCarloOf(const objectives::LcrMonteCarloCheck& c) {
  Result::Json::MonteCarloCheck j;
  j.samples = c.samples, j.seed = c.seed, j.angle_steps = c.angle_steps;
  j.violating_samples = c.violating, j.violating_fraction = c.violating_fraction;
  j.max_roller_force_N = c.max_force_N, j.max_contact_stress_MPa = c.max_stress_MPa;
  j.min_undercut_margin_mm = c.min_undercut_margin_mm;
  j.worst_sample = c.worst_sample, j.worst_sample_relative_excess = c.worst_relative_excess;
  return j;
}

}  // namespace

void ParseRobust(const Input& in, const Node& root, Study& s) {
  // "monte_carlo" without "tolerances" is refused here (ToToleranceSpec).
  const std::optional<LcrToleranceSpec> tol = ToToleranceSpec(in.tolerances, std::nullopt, root);
  if (!in.robust) {
    if (tol) root["tolerances"].Fail("no \"tolerances\" without \"robust\" in lcr_min_size");
    return;
  }
  const Node r = root["robust"];
  if (!tol) r.Fail("\"robust\" with \"tolerances\" beside it");
  auto rule = std::make_shared<objectives::LcrRobustRule>();
  rule->bands = tol->bands;
  if (!rule->bands.any()) root["tolerances"].Fail("at least one tolerance band > 0");
  if (in.robust->method == "worst_case") {
    rule->method = objectives::LcrRobustMethod::kWorstCase;
    if (in.robust->k) r["k"].Fail("no \"k\" with \"worst_case\" (k belongs to \"sigma\")");
  } else {
    rule->method = objectives::LcrRobustMethod::kSigma;
    rule->k = in.robust->k.value_or(3.0);
  }
  if (s.form != objectives::LcrConstraintForm::kAggregate)
    root["optimizer"]["constraints"].Fail("\"aggregate\" with \"robust\" (the robust solve picks its own forms)");
  s.robust = rule;
  s.base.robust = nullptr;  // the nominal search stays nominal; RunRobust sets it per candidate
  if (in.monte_carlo) {
    s.mc_samples = in.monte_carlo->samples.value_or(s.mc_samples);
    s.mc_seed = std::uint64_t(in.monte_carlo->seed.value_or(1));
    s.mc_angle_steps = in.monte_carlo->angle_steps.value_or(s.mc_angle_steps);
  }
}

void RunRobust(const Study& s, Result& res, const RunContext& ctx) {
  Progress progress("lcr_min_size robust", ctx.quiet);
  res.robust.assign(res.candidates.size(), {});
  for (size_t i = 0; i < res.candidates.size(); ++i) {
    const Candidate& c = res.candidates[i];
    progress.Update(double(i) / (res.candidates.size() + 1), "robust solve " + std::to_string(i + 1));
    if (!c.feasible()) continue;  // no nominal optimum to start from
    objectives::LcrSizingSpec spec = c.spec;
    spec.robust = s.robust;
    res.robust[i] = sizing::SolveLcrRobust(spec, s.options, c.outcome.x);
    const auto& o = res.robust[i];
    if (o.converged && (res.robust_best < 0 || lcr::OuterDiameter(*o.design) <
                                                   lcr::OuterDiameter(*res.robust[res.robust_best].design)))
      res.robust_best = int(i);
  }
  progress.Update(double(res.candidates.size()) / (res.candidates.size() + 1), "Monte-Carlo checks");
  auto check = [&](int i, const lcr::Reducer<double>& design) {
    objectives::LcrSizingSpec spec = res.candidates[i].spec;
    spec.robust = s.robust;
    return objectives::MonteCarloCheck(spec, design, s.mc_samples, s.mc_seed, s.mc_angle_steps);
  };
  // monte_carlo.samples 0: the linearised robust rows only, no Monte-Carlo check (no sample, no
  // extremes to report).
  const bool monte_carlo = s.mc_samples > 0;
  if (res.best >= 0 && monte_carlo) res.nominal_mc = check(res.best, *res.candidates[res.best].outcome.design);
  if (res.robust_best >= 0) {
    if (monte_carlo) res.robust_mc = check(res.robust_best, *res.robust[res.robust_best].design);
    res.robust_verification = objectives::VerifyLcrLineDesign(res.candidates[res.robust_best].spec,
                                                              *res.robust[res.robust_best].design, s.options.dense_steps);
  }
  progress.Update(1.0, "robust done");
}

void RobustJson(const Study& s, Result& r) {
  Result::Json& res = r.json;
  const objectives::LcrRobustRule& rule = *s.robust;
  Result::Json::RobustBlock& rj = res.robust.emplace();
  rj.method = rule.method == objectives::LcrRobustMethod::kWorstCase ? "worst_case" : "sigma";
  if (rule.method == objectives::LcrRobustMethod::kSigma) rj.k = rule.k;
  const lcr::ToleranceBands& b = rule.bands;
  rj.tolerances.eccentricity_um = b.eccentricity_mm * 1e3;
  rj.tolerances.turret_radius_um = b.turret_radius_mm * 1e3;
  rj.tolerances.roller_diameter_um = b.roller_diameter_mm * 1e3;
  rj.tolerances.roller_pitch_arcsec = b.roller_pitch_rad * 180.0 / kPi * 3600.0;
  rj.tolerances.profile_um = b.profile_mm * 1e3;
  rj.tolerances.bearing_clearance_um = b.bearing_clearance_mm * 1e3;
  rj.model = "roller force = rigid-law force + change of the compliant (Palmgren) load sharing under the "
             "deviations; linearised sensitivities in the optimizer (worst case over the band box, or mean + "
             "k sigma with uniform deviations), exact compliant model in the Monte-Carlo check";
  for (size_t i = 0; i < r.robust.size(); ++i) {
    const auto& o = r.robust[i];
    Result::Json::RobustBlock::CandidateSolve j;
    j.candidate = int(i), j.converged = o.converged, j.rounds = o.rounds;
    if (!r.candidates[i].feasible()) j.status = "no nominal optimum";
    else j.status = o.converged ? "converged" : optimizers::ToString(o.result.status);
    if (o.design) j.outer_diameter_mm = lcr::OuterDiameter(*o.design);
    if (!o.note.empty()) j.note = o.note;
    rj.candidates.push_back(std::move(j));
  }
  if (r.best >= 0) {
    Result::Json::NominalBest nominal = std::get<Result::Json::NominalBest>(res.best);
    if (r.nominal_mc) nominal.monte_carlo = MonteCarloOf(*r.nominal_mc);
    res.nominal_best = std::move(nominal);
  } else {
    res.nominal_best = nullptr;
  }
  if (r.robust_best < 0) {
    res.best = nullptr;
    res.verified = false;
    res.verification = VerificationBlock::NotRun("no robust design to verify");
    return;
  }
  if (r.robust_verification) {
    res.verified = r.robust_verification->verified();
    res.verification = VerificationBlock::Of(*r.robust_verification);
  }
  const sizing::LcrRobustOutcome& o = r.robust[r.robust_best];
  const lcr::Reducer<double>& d = *o.design;
  const objectives::LcrDenseCheck& k = *o.dense;
  const objectives::LcrRobustCheck& g = *o.grid;
  Result::Json::RobustBest bj;
  bj.eccentricity_mm = d.eccentricity;
  bj.outer_diameter_mm = k.outer_diameter_mm;
  bj.speed_ratio = lcr::SpeedReductionRatio(d);
  bj.input = Side(d.input);
  bj.output = Side(d.output);
  bj.nominal = {std::max(k.max_stress_MPa[0], k.max_stress_MPa[1]), std::max(k.max_force_N[0], k.max_force_N[1]),
                std::min(k.undercut_margin_mm[0], k.undercut_margin_mm[1]),
                std::min(k.roller_gap_mm[0], k.roller_gap_mm[1]), k.mean_efficiency};
  bj.robust_linear = {g.max_stress_MPa, g.min_stress_margin, g.max_force_N, g.undercut_margin_mm, g.steps_per_period};
  for (const std::string& row : o.result.active) {
    const std::string base = row.substr(0, row.find('['));
    if (std::find(bj.binding.begin(), bj.binding.end(), base) == bj.binding.end()) bj.binding.push_back(base);
  }
  if (r.robust_mc) bj.monte_carlo = MonteCarloOf(*r.robust_mc);
  res.best = std::move(bj);
  if (r.best >= 0)
    res.robust->outer_diameter_increase_mm = k.outer_diameter_mm - r.candidates[r.best].outcome.check->outer_diameter_mm;
}

}  // namespace camopt::studies::lcr_min_size
