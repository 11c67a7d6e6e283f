// Study kind "lcr_min_size": the smallest lobe cam reducer for a target speed ratio and output
// torque. Enumerates every lobe/roller combination giving the ratio exactly, solves the continuous
// sizing problem of each (objectives/lcr_sizing.h) with the backend asked for, checks every
// converged design with the dense cycle analysis that lcr_analysis runs (3600 input angles), and
// reports the best design plus one candidate per combination with what binds or blocks it.
// With a roller catalogue, each catalogue roller is tried on each combination (diameter fixed,
// its length and load limit used).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "model/lcr/cycle.h"
#include "model/lcr/kinematics.h"
#include "model/lcr/profile.h"
#include "objectives/lcr_sizing.h"
#include "optimizers/solver.h"
#include "studies/lcr_input.h"
#include "studies/study.h"
#include "studies/writers.h"

namespace camopt::studies {
namespace {

using objectives::LcrSizingSpec;
using optimizers::SolverStatus;

constexpr int kVerifySteps = 3600;  // lcr_analysis' default angle grid
constexpr double kLimitMargin = 1e-5;       // relative, on stress and load limits
constexpr double kLengthMargin_mm = 1e-4;   // on gap and undercut limits (0.1 µm)

struct CatalogueRoller {
  std::string name;
  double diameter_mm, length_mm, load_limit_N;
};

struct Study {
  std::string name;
  long ratio = 0;
  double output_torque_Nmm = 0;
  int max_lobes = 40;
  std::vector<int> differences{1};
  LcrSizingSpec base;
  double friction = 0.0;
  std::vector<CatalogueRoller> catalogue;
  optimizers::SolverOptions solver;
  int starts = 3;
};

std::array<double, 2> PositiveRange(const Node& n) {
  const auto [lo, hi] = n.Range();
  if (!(lo > 0)) n.Fail("a [lo, hi] range with lo > 0");
  return {lo, hi};
}

std::vector<CatalogueRoller> ParseCatalogue(const Node& n) {
  std::vector<CatalogueRoller> out;
  const std::vector<Node> items = n.Elements();
  if (items.empty()) n.Fail("a non-empty list of rollers");
  for (const Node& item : items) {
    item.CheckKnownFields({"name", "diameter_mm", "length_mm", "load_limit_N"});
    CatalogueRoller r;
    r.name = item.StringOr("name", "roller " + std::to_string(out.size() + 1));
    r.diameter_mm = item["diameter_mm"].Positive();
    r.length_mm = item["length_mm"].Positive();
    r.load_limit_N = item["load_limit_N"].Positive();
    out.push_back(r);
  }
  return out;
}

Study Parse(const Node& root, const RunContext& ctx) {
  Study s;
  s.name = root.StringOr("name", "");
  const Node target = root["target"];
  target.CheckKnownFields({"speed_ratio", "output_torque_Nm"});
  const Node ratio = target["speed_ratio"];
  const double rv = ratio.Number();
  if (rv != std::round(rv) || std::abs(rv) < 2 || std::abs(rv) > 1e6)
    ratio.Fail("a whole-number speed ratio with 2 <= |ratio| <= 1e6");
  s.ratio = static_cast<long>(rv);
  s.output_torque_Nmm = target["output_torque_Nm"].Positive() * 1000.0;

  if (root.Has("search")) {
    const Node search = root["search"];
    search.CheckKnownFields({"max_lobes", "roller_lobe_difference"});
    s.max_lobes = search.IntegerOr("max_lobes", 1, 40);
    if (s.max_lobes > 200) search["max_lobes"].Fail("a number of lobes <= 200");
    if (search.Has("roller_lobe_difference")) {
      s.differences.clear();
      for (const Node& d : search["roller_lobe_difference"].Elements()) {
        const int v = d.Integer(1);
        if (v != 1)
          d.Fail("1 (a roller-lobe difference above 1 makes the pitch curve wind several times: a "
                 "self-crossing cam, see lcr::CheckDesign)");
        s.differences.push_back(v);
      }
      if (s.differences.empty()) search["roller_lobe_difference"].Fail("a non-empty list");
    }
  }

  LcrSizingSpec& b = s.base;
  const Node vars = root["variables"];
  vars.CheckKnownFields({"eccentricity_mm", "turret_radius_mm", "roller_diameter_mm", "same_roller_on_both_cams"});
  b.eccentricity_mm = PositiveRange(vars["eccentricity_mm"]);
  b.turret_radius_mm = PositiveRange(vars["turret_radius_mm"]);
  if (vars.Has("roller_diameter_mm")) b.roller_diameter_mm = PositiveRange(vars["roller_diameter_mm"]);
  b.same_roller = vars.BoolOr("same_roller_on_both_cams", true);

  const Node fixed = root["fixed"];
  fixed.CheckKnownFields({"cam_thickness_mm", "roller_length_mm"});
  b.cam_thickness_mm = fixed["cam_thickness_mm"].Positive();
  if (root.Has("roller_catalogue")) {
    Node cat = root["roller_catalogue"];
    nlohmann::json loaded;
    if (cat.json().is_object()) {
      // {"file": "rollers.json"}, relative to the study file.
      cat.CheckKnownFields({"file"});
      const Node file = cat["file"];
      std::filesystem::path p(file.String());
      if (p.is_relative()) p = std::filesystem::path(ctx.study_file).parent_path() / p;
      loaded = LoadStudyFile(p.string());
      s.catalogue = ParseCatalogue(Node(&loaded, p.string(), ""));
    } else {
      s.catalogue = ParseCatalogue(cat);
    }
  } else {
    b.roller_length_mm = fixed["roller_length_mm"].Positive();
    if (!vars.Has("roller_diameter_mm")) vars["roller_diameter_mm"];  // throws "missing field"
  }

  if (!b.same_roller && !s.catalogue.empty())
    vars["same_roller_on_both_cams"].Fail("true with a roller catalogue (each catalogue roller is used on both cams)");

  const Node limits = root["limits"];
  limits.CheckKnownFields({"contact_stress_MPa", "roller_load_N", "undercut_margin_mm", "roller_gap_mm", "min_efficiency"});
  b.limits.contact_stress_MPa = limits.PositiveOr("contact_stress_MPa", kInf);
  b.limits.roller_load_N = limits.PositiveOr("roller_load_N", kInf);
  b.limits.undercut_margin_mm = limits.NonNegativeOr("undercut_margin_mm", 0.0);
  b.limits.roller_gap_mm = limits.NonNegativeOr("roller_gap_mm", 0.0);
  if (limits.Has("min_efficiency")) b.limits.min_efficiency = limits["min_efficiency"].NumberIn(0.0, 0.999);
  if (root.Has("material")) root["material"].CheckKnownFields({"youngs_modulus_GPa", "poisson_ratio"});
  b.material = root.Has("material") ? ParseMaterial(root["material"]) : lcr::Material{};
  if (root.Has("load")) root["load"].CheckKnownFields({"friction_coefficient"});
  b.output_torque_Nmm = s.output_torque_Nmm;
  if (root.Has("load")) s.friction = root["load"].NonNegativeOr("friction_coefficient", 0.0);
  b.friction_coefficient = s.friction;

  if (root.Has("optimizer")) {
    const Node o = root["optimizer"];
    o.CheckKnownFields({"backend", "constraints", "samples_per_period", "sharpness", "tolerance", "max_evaluations",
                        "starts"});
    s.solver.backend = o.StringOr("backend", "ipopt");
    const auto backends = optimizers::Backends();
    if (std::find(backends.begin(), backends.end(), s.solver.backend) == backends.end())
      o["backend"].Fail("one of ipopt, nlopt_slsqp, nlopt_mma, nlopt_cobyla");
    const std::string form = o.StringOr("constraints", "aggregate");
    if (form != "aggregate" && form != "samples") o["constraints"].Fail("\"aggregate\" or \"samples\"");
    b.form = form == "samples" ? objectives::LcrConstraintForm::kSamples
                               : objectives::LcrConstraintForm::kAggregate;
    b.samples_per_period = o.IntegerOr("samples_per_period", 4, b.samples_per_period);
    if (b.samples_per_period > 720) o["samples_per_period"].Fail("a whole number between 4 and 720");
    if (o.Has("sharpness")) b.sharpness = o["sharpness"].Positive();
    if (o.Has("tolerance")) s.solver.tolerance = o["tolerance"].NumberIn(1e-14, 1e-2);
    // Ipopt counts iterations (one gradient each), NLopt evaluations: Ipopt converges in 10–50
    // iterations here, and a start that needs hundreds is a degenerate one that other starts cover.
    s.solver.max_evaluations = o.IntegerOr("max_evaluations", 10, s.solver.backend == "ipopt" ? 200 : 3000);
    if (s.solver.max_evaluations > 100000) o["max_evaluations"].Fail("a whole number between 10 and 100000");
    s.starts = o.IntegerOr("starts", 1, s.starts);
    if (s.starts > 5) o["starts"].Fail("a number of starts between 1 and 5");
  }
  if (!root.Has("optimizer")) s.solver.max_evaluations = 200;  // ipopt, as above
  s.solver.max_seconds = 10.0;  // per local solve
  return s;
}

// Exact (dense-grid) numbers of a design, as lcr_analysis reports them.
struct Check {
  double outer_diameter_mm, max_stress_MPa[2], max_force_N[2], undercut_margin_mm[2], gap_mm[2];
  double pitch_clearance_mm[2], mean_efficiency;
  bool ok = false;
  std::vector<std::string> failures;
};

Check Verify(const lcr::Reducer<double>& r, const Study& s, const objectives::LcrLimits& limits) {
  Check c{};
  c.outer_diameter_mm = lcr::OuterDiameter(r);
  for (int k = 0; k < 2; ++k) {
    const auto& side = k == 0 ? r.input : r.output;
    c.undercut_margin_mm[k] = lcr::UndercutMargin(side, r.eccentricity);
    c.gap_mm[k] = lcr::RollerGap(side);
    c.pitch_clearance_mm[k] = side.turret_radius - r.eccentricity * side.pitch_factor();
  }
  const lcr::LoadCase load{s.output_torque_Nmm, s.friction, 0.0};
  const lcr::CycleSeries series = lcr::AnalyzeCycle(r, s.base.material, load, kVerifySteps, {});
  for (int k = 0; k < 2; ++k) {
    const auto& ss = k == 0 ? series.input : series.output;
    c.max_stress_MPa[k] = *std::max_element(ss.max_stress_MPa.begin(), ss.max_stress_MPa.end());
    c.max_force_N[k] = *std::max_element(ss.max_force_N.begin(), ss.max_force_N.end());
  }
  double eta = 0;
  for (double v : series.efficiency) eta += v;
  c.mean_efficiency = eta / series.efficiency.size();
  const char* side[2] = {"input", "output"};
  for (int k = 0; k < 2; ++k) {
    if (!(c.max_stress_MPa[k] <= limits.contact_stress_MPa))
      c.failures.push_back(std::string(side[k]) + " contact stress");
    if (!(c.max_force_N[k] <= limits.roller_load_N)) c.failures.push_back(std::string(side[k]) + " roller load");
    if (!(c.undercut_margin_mm[k] >= limits.undercut_margin_mm))
      c.failures.push_back(std::string(side[k]) + " undercut margin");
    if (!(c.gap_mm[k] >= limits.roller_gap_mm)) c.failures.push_back(std::string(side[k]) + " roller gap");
  }
  if (!(c.mean_efficiency >= limits.min_efficiency)) c.failures.push_back("mean efficiency");
  const auto problems = lcr::CheckDesign(r);
  if (!problems.empty()) c.failures.push_back("design check: " + problems.front().message);
  c.ok = c.failures.empty();
  return c;
}

// Constraint row names without the sample index, each once.
std::vector<std::string> Unique(const std::vector<std::string>& rows) {
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (const std::string& row : rows) {
    const std::string base = row.substr(0, row.find('['));
    if (seen.insert(base).second) out.push_back(base);
  }
  return out;
}

struct Candidate {
  objectives::LobeCombination combo{};
  const CatalogueRoller* roller = nullptr;
  optimizers::SolverResult result;
  std::optional<lcr::Reducer<double>> design;
  std::optional<Check> check;
  int passes = 0;
  std::string note;  // why a converged design has no dense check
  bool feasible() const { return check && check->ok; }
};

// Solves one candidate; when the dense check finds a sampled maximum exceeded between samples,
// tightens that limit by the excess and solves again from the previous optimum (at most 3 passes).
Candidate SolveCandidate(const Study& s, const objectives::LobeCombination& combo,
                         const CatalogueRoller* roller) {
  Candidate cand;
  cand.combo = combo;
  cand.roller = roller;
  LcrSizingSpec spec = s.base;
  spec.lobes_a = combo.lobes_a;
  spec.rollers_a = combo.rollers_a;
  spec.lobes_b = combo.lobes_b;
  spec.rollers_b = combo.rollers_b;
  objectives::LcrLimits limits = spec.limits;
  if (roller) {
    spec.fixed_roller_diameter_mm = roller->diameter_mm;
    spec.roller_length_mm = roller->length_mm;
    limits.roller_load_N = std::min(limits.roller_load_N, roller->load_limit_N);
  }
  // The solvers meet constraints to about their tolerance (1e-6 scaled), so they are given limits
  // tightened by more than that; the dense check then holds the design to the study's own limits.
  spec.limits.contact_stress_MPa = limits.contact_stress_MPa * (1 - kLimitMargin);
  spec.limits.roller_load_N = limits.roller_load_N * (1 - kLimitMargin);
  spec.limits.roller_gap_mm = limits.roller_gap_mm + kLengthMargin_mm;
  spec.limits.undercut_margin_mm = limits.undercut_margin_mm + kLengthMargin_mm;
  if (limits.min_efficiency > 0) spec.limits.min_efficiency = limits.min_efficiency * (1 + kLimitMargin);
  std::vector<double> start;
  for (cand.passes = 1; cand.passes <= 3; ++cand.passes) {
    const objectives::Problem problem = objectives::MakeLcrSizingProblem(spec);
    // First pass: several starts (local optima exist); refinement passes: from the last optimum.
    cand.result = optimizers::SolveMultistart(
        problem, s.solver, start.empty() ? objectives::LcrStartingPoints(spec, s.starts)
                                    : std::vector<std::vector<double>>{start});
    if (cand.result.x.empty()) return cand;
    cand.design = objectives::LcrDesign(spec, cand.result.x);
    if (!cand.result.ok()) return cand;
    if (const auto problems = lcr::CheckDesign(*cand.design); !problems.empty()) {
      cand.note = "design check: " + problems.front().field + ": " + problems.front().message;
      return cand;
    }
    try {
      cand.check = Verify(*cand.design, s, limits);
    } catch (const std::domain_error& e) {
      cand.note = std::string("degenerate geometry: ") + e.what();
      return cand;
    }
    if (cand.check->ok) return cand;
    // Tighten the sampled limits by what the dense grid found between samples.
    double excess_stress = 1.0, excess_force = 1.0;
    for (int k = 0; k < 2; ++k) {
      excess_stress = std::max(excess_stress, cand.check->max_stress_MPa[k] / limits.contact_stress_MPa);
      excess_force = std::max(excess_force, cand.check->max_force_N[k] / limits.roller_load_N);
    }
    // The efficiency is sampled at 48 angles against 3600: raise its limit by the deficit.
    const double deficit = std::max(0.0, limits.min_efficiency - cand.check->mean_efficiency);
    if (excess_stress <= 1.0 && excess_force <= 1.0 && deficit <= 0.0) return cand;  // not sampling
    spec.limits.contact_stress_MPa /= excess_stress * (1.0 + 1e-4);
    spec.limits.roller_load_N /= excess_force * (1.0 + 1e-4);
    spec.limits.min_efficiency += deficit * 1.5;
    start = cand.result.x;
  }
  cand.passes = 3;
  return cand;
}

nlohmann::json SideJson(const lcr::CamSide<double>& c) {
  return {{"lobes", c.lobes}, {"rollers", c.rollers}, {"turret_radius_mm", c.turret_radius},
          {"roller_diameter_mm", 2 * c.roller_radius}, {"roller_length_mm", c.roller_length},
          {"cam_thickness_mm", c.cam_thickness}};
}

nlohmann::json CandidateJson(const Candidate& c) {
  nlohmann::json j;
  j["input"] = {{"lobes", c.combo.lobes_a}, {"rollers", c.combo.rollers_a}};
  j["output"] = {{"lobes", c.combo.lobes_b}, {"rollers", c.combo.rollers_b}};
  if (c.roller) j["catalogue_roller"] = c.roller->name;
  std::string status = optimizers::ToString(c.result.status);
  if (c.result.ok() && !c.feasible()) status = "fails_dense_check";
  j["status"] = status;
  j["feasible"] = c.feasible();
  j["solver_message"] = c.result.message;
  if (!c.note.empty()) j["note"] = c.note;
  j["evaluations"] = {{"values", c.result.value_evaluations},
                      {"gradients", c.result.gradient_evaluations},
                      {"iterations", c.result.iterations},
                      {"passes", c.passes}};
  j["binding"] = Unique(c.result.active);
  j["violated"] = Unique(c.result.violated);
  if (c.design) {
    j["outer_diameter_mm"] = lcr::OuterDiameter(*c.design);
    j["eccentricity_mm"] = c.design->eccentricity;
    j["input"] = SideJson(c.design->input);
    j["output"] = SideJson(c.design->output);
  }
  if (c.check) {
    j["max_contact_stress_MPa"] = std::max(c.check->max_stress_MPa[0], c.check->max_stress_MPa[1]);
    j["max_roller_force_N"] = std::max(c.check->max_force_N[0], c.check->max_force_N[1]);
    j["undercut_margin_mm"] = std::min(c.check->undercut_margin_mm[0], c.check->undercut_margin_mm[1]);
    if (!c.check->failures.empty()) j["dense_check_failures"] = c.check->failures;
  }
  return j;
}

void RunLcrMinSize(const Node& root, const RunContext& ctx, Outputs& out) {
  root.CheckKnownFields({"study", "name", "description", "target", "search", "variables", "fixed", "limits", "material", "load", "optimizer", "roller_catalogue"});
  const Study s = Parse(root, ctx);
  const auto combos = objectives::LobeCombinations(s.ratio, s.max_lobes, s.differences);
  if (combos.empty())
    throw StudyError(ctx.study_file + ": /target/speed_ratio: no lobe/roller combination with at most " +
                     std::to_string(s.max_lobes) + " lobes gives the ratio " + std::to_string(s.ratio) +
                     " exactly");

  std::vector<std::pair<objectives::LobeCombination, const CatalogueRoller*>> jobs;
  for (const auto& c : combos) {
    if (s.catalogue.empty()) jobs.push_back({c, nullptr});
    for (const auto& r : s.catalogue) jobs.push_back({c, &r});
  }
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<Candidate> candidates;
  {
    Progress progress("lcr_min_size", ctx.quiet);
    for (size_t i = 0; i < jobs.size(); ++i) {
      const auto& [c, r] = jobs[i];
      progress.Update(double(i) / jobs.size(),
                      std::to_string(c.lobes_a) + "/" + std::to_string(c.rollers_a) + " + " +
                          std::to_string(c.lobes_b) + "/" + std::to_string(c.rollers_b) +
                          (r ? " " + r->name : ""));
      candidates.push_back(SolveCandidate(s, c, r));
    }
    progress.Update(1.0, std::to_string(jobs.size()) + " candidates");
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const Candidate* best = nullptr;
  int values = 0, gradients = 0;
  for (const auto& c : candidates) {
    values += c.result.value_evaluations;
    gradients += c.result.gradient_evaluations;
    if (c.feasible() && (!best || c.check->outer_diameter_mm < best->check->outer_diameter_mm)) best = &c;
  }

  nlohmann::json res;
  res["study"] = "lcr_min_size";
  res["name"] = s.name;
  res["target"] = {{"speed_ratio", s.ratio}, {"output_torque_Nm", s.output_torque_Nmm / 1000}};
  res["optimizer"] = {{"backend", s.solver.backend},
                      {"constraints", s.base.form == objectives::LcrConstraintForm::kSamples ? "samples" : "aggregate"},
                      {"samples_per_period", s.base.samples_per_period},
                      {"sharpness", s.base.sharpness},
                      {"starts", s.starts},
                      {"value_evaluations", values},
                      {"gradient_evaluations", gradients},
                      {"seconds", seconds}};
  nlohmann::json cj = nlohmann::json::array();
  for (const auto& c : candidates) cj.push_back(CandidateJson(c));
  res["candidates"] = cj;
  if (best) {
    const lcr::Reducer<double>& r = *best->design;
    const Check& k = *best->check;
    nlohmann::json b;
    b["eccentricity_mm"] = r.eccentricity;
    b["outer_diameter_mm"] = k.outer_diameter_mm;
    b["speed_ratio"] = lcr::SpeedReductionRatio(r);
    b["max_contact_stress_MPa"] = std::max(k.max_stress_MPa[0], k.max_stress_MPa[1]);
    b["max_roller_force_N"] = std::max(k.max_force_N[0], k.max_force_N[1]);
    b["undercut_margin_mm"] = std::min(k.undercut_margin_mm[0], k.undercut_margin_mm[1]);
    b["roller_gap_mm"] = std::min(k.gap_mm[0], k.gap_mm[1]);
    b["mean_efficiency"] = k.mean_efficiency;
    b["input"] = SideJson(r.input);
    b["output"] = SideJson(r.output);
    b["input"]["max_contact_stress_MPa"] = k.max_stress_MPa[0];
    b["output"]["max_contact_stress_MPa"] = k.max_stress_MPa[1];
    b["input"]["max_roller_force_N"] = k.max_force_N[0];
    b["output"]["max_roller_force_N"] = k.max_force_N[1];
    b["input"]["undercut_margin_mm"] = k.undercut_margin_mm[0];
    b["output"]["undercut_margin_mm"] = k.undercut_margin_mm[1];
    b["input"]["roller_gap_mm"] = k.gap_mm[0];
    b["output"]["roller_gap_mm"] = k.gap_mm[1];
    if (best->roller) b["catalogue_roller"] = best->roller->name;
    b["binding"] = Unique(best->result.active);
    res["best"] = b;
    // The best design as an lcr_analysis study, ready for `camopt run`.
    nlohmann::json a;
    a["study"] = "lcr_analysis";
    a["name"] = "best of " + (s.name.empty() ? std::string("lcr_min_size") : s.name);
    a["reducer"] = {{"eccentricity_mm", r.eccentricity}, {"input", SideJson(r.input)}, {"output", SideJson(r.output)}};
    a["material"] = {{"youngs_modulus_GPa", s.base.material.youngs_modulus_MPa / 1000},
                     {"poisson_ratio", s.base.material.poisson_ratio}};
    a["load"] = {{"output_torque_Nm", s.output_torque_Nmm / 1000}, {"friction_coefficient", s.friction}};
    nlohmann::json lim = nlohmann::json::object();
    if (std::isfinite(s.base.limits.contact_stress_MPa)) lim["contact_stress_MPa"] = s.base.limits.contact_stress_MPa;
    const double load_limit = best->roller ? std::min(s.base.limits.roller_load_N, best->roller->load_limit_N)
                                           : s.base.limits.roller_load_N;
    if (std::isfinite(load_limit)) lim["roller_load_N"] = load_limit;
    a["limits"] = lim;
    a["analysis"] = {{"angle_steps", kVerifySteps}};
    out.AddJson("best_lcr_analysis.json", a);
  } else {
    res["best"] = nullptr;
    res["notes"] = {"no combination gives a design that satisfies every limit; see candidates for what "
                    "binds or blocks each"};
  }
  out.AddJson("result.json", res);

  // One row per candidate that has a design (no NaN cells); the rest are in result.json.
  Table t;
  std::vector<double> ma, mb, dr, od, ecc, feas;
  for (const auto& c : candidates) {
    if (!c.design) continue;
    ma.push_back(c.combo.lobes_a);
    mb.push_back(c.combo.lobes_b);
    dr.push_back(2 * c.design->input.roller_radius);
    od.push_back(lcr::OuterDiameter(*c.design));
    ecc.push_back(c.design->eccentricity);
    feas.push_back(c.feasible() ? 1.0 : 0.0);
  }
  t.Add("input_lobes", ma);
  t.Add("output_lobes", mb);
  t.Add("roller_diameter_mm", dr);
  t.Add("eccentricity_mm", ecc);
  t.Add("outer_diameter_mm", od);
  t.Add("feasible", feas);
  out.Add("candidates.csv", ToCsv(t));
}

CAMOPT_REGISTER_STUDY("lcr_min_size", RunLcrMinSize);

}  // namespace
}  // namespace camopt::studies
