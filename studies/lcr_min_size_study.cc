// Study kind "lcr_min_size" (see lcr_min_size_study.h): parse, size through sizing/lcr_search.h
// (every combination and catalogue roller, the accurate check of the answer), write.
#include "studies/lcr_min_size_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "model/lcr/kinematics.h"
#include "studies/contact_fatigue_input.h"
#include "studies/kind.h"
#include "studies/lcr_analysis_study.h"
#include "studies/lcr_input.h"
#include "studies/format.h"
#include "studies/lcr_min_size_contact.h"
#include "studies/ratings.h"
#include "studies/report.h"
#include "studies/verification_json.h"
#include "studies/work_limits.h"
#include "studies/writers.h"
#include "studies/archive.h"

namespace camopt::studies::lcr_min_size {
namespace {

using objectives::LcrConstraintForm;
using objectives::LcrSizingSpec;
using objectives::LcrLimits;

// The catalogue's rollers as read from `list` (the study's "roller_catalogue" or its file), each
// with the dynamic rating a life needs (`life_why` non-empty).
std::vector<CatalogueRoller> CatalogueRollers(const std::vector<CatalogueRollerInput>& entries, const Node& list,
                                              const std::string& life_why) {
  std::vector<CatalogueRoller> out;
  for (size_t i = 0; i < entries.size(); ++i) {
    const CatalogueRollerInput& in = entries[i];
    CatalogueRoller r;
    r.name = in.name.value_or("roller " + std::to_string(out.size() + 1));
    r.diameter_mm = in.diameter_mm;
    r.length_mm = in.length_mm;
    r.load_limit_N = in.load_limit_N;
    if (!life_why.empty() && !in.dynamic_rating_N) {
      const Node item = list[i];
      const std::string path = item.path() + "/dynamic_rating_N";
      const std::string expected = "the roller's dynamic load rating C [N] > 0, as its catalogue gives it (" + life_why + ")";
      throw StudyError(item.file() + ": " + path + ": expected " + expected + ", found nothing; would fit: \"dynamic_rating_N\" "
                           "(and \"static_rating_N\" for s0) on every catalogue entry, or no speed and no life limit",
                       item.file(), path, expected, "nothing");
    }
    r.dynamic_rating_N = in.dynamic_rating_N.value_or(0.0);
    r.static_rating_N = in.static_rating_N.value_or(0.0);
    out.push_back(r);
  }
  return out;
}

// The life of the sizing (docs/life.md, "Life as a sizing limit"): the duty cycle, the rollers'
// ratings ("rollers" without a catalogue: a reference roller whose rating scales with the sized
// diameter; a catalogue: each entry's own) and the optional "eccentric_bearing". nullopt when no
// speed and no duty cycle is given.
std::optional<objectives::LcrLifeSpec> ParseLife(const Input& in, const Node& root, const objectives::LcrSizingSpec& b,
                                                 bool catalogue, const std::vector<lcr::LcrDutyLine>* lines,
                                                 const std::string& why) {
  // The ratings' fields are checked whenever given; they are used with a speed or a duty cycle.
  if (catalogue && in.rollers)
    root["rollers"].FailWith("no \"rollers\" ratings with a roller catalogue (each catalogue entry gives its "
                             "dynamic_rating_N and static_rating_N)");
  objectives::LcrLifeSpec life;
  if (in.rollers) {
    const Input::Rollers& r = *in.rollers;
    life.roller.dynamic_N = r.dynamic_rating_N;
    life.roller.static_N = r.static_rating_N.value_or(0.0);
    life.roller.reference_diameter_mm = r.reference_diameter_mm;
    life.roller.reference_length_mm = r.reference_length_mm.value_or(b.roller_length_mm);
  } else if (lines && !catalogue) {
    const std::string path = "/rollers";
    const std::string expected = "{\"dynamic_rating_N\", \"reference_diameter_mm\"} (the rating of a reference roller, "
                                 "scaled with the sized roller diameter; " + why + ")";
    throw StudyError(root.file() + ": " + path + ": expected " + expected +
                         ", found nothing; would fit: e.g. \"rollers\": {\"dynamic_rating_N\": 2700, "
                         "\"reference_diameter_mm\": 10} (the catalogue C of a 10 mm roller of the study's length)",
                     root.file(), path, expected, "nothing");
  }
  if (in.eccentric_bearing) {
    const EccentricBearingInput& e = *in.eccentric_bearing;
    life.eccentric = objectives::LcrEccentricRating{e.kind == "ball", e.dynamic_rating_N, e.static_rating_N.value_or(0.0)};
  }
  if (!lines) return std::nullopt;
  life.lines = *lines;
  return life;
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

// A constraint row's plain name for the summary and the report ("input_stress_margin_3d" →
// "contact stress (3D), input cam"); result.json's `binding` keeps the row names scripts use.
std::string PlainLimitName(const std::string& row) {
  static const std::map<std::string, std::string> kNames = {
      {"outer_diameter_bound_mm", "outer diameter bound"},
      {"roller_gap_mm", "gap between rollers"},
      {"undercut_margin_mm", "undercut margin"},
      {"pitch_clearance_mm", "pitch clearance"},
      {"roller_force_N", "roller force"},
      {"stress_margin", "contact stress"},
      {"stress_margin_3d", "contact stress (3D contact)"},
      {"mean_efficiency", "mean efficiency"},
      {"roller_life", "roller life"},
      {"eccentric_bearing_life", "eccentric bearing life"},
      {"roller_static", "roller static safety at the momentary torque"},
      {"eccentric_bearing_static", "eccentric bearing static safety at the momentary torque"}};
  std::string side, rest = row;
  for (const char* s : {"input", "output"})
    if (row.rfind(std::string(s) + "_", 0) == 0) {
      side = std::string(", ") + s + " cam";
      rest = row.substr(std::string(s).size() + 1);
    }
  const auto it = kNames.find(rest);
  std::string name = it != kNames.end() ? it->second : rest;
  if (it == kNames.end()) std::replace(name.begin(), name.end(), '_', ' ');
  return name + side;
}

std::vector<std::string> PlainLimitNames(const std::vector<std::string>& rows, const LcrSizingSpec& spec) {
  std::vector<std::string> out;
  for (const std::string& row : rows) {
    // The rows that define the outer diameter (the objective) bind at every optimum: not limits.
    if (row == "outer_radius_mm" || row == "input_envelope_mm" || row == "output_envelope_mm") continue;
    // R at its upper bound: the outer-diameter limit when there is one (else, with the efficiency
    // objective, the variable box's largest outer radius, which the envelope rows never reach).
    if (row == "outer_radius_mm upper bound" && !std::isfinite(spec.limits.max_outer_diameter_mm)) continue;
    const std::string name = row == "outer_radius_mm upper bound" ? "outer diameter limit" : PlainLimitName(row);
    if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
  }
  return out;
}


Result::Json::SizingLife LifeOf(const objectives::LcrSizingSpec& spec, const objectives::LcrDenseCheck& k) {
  Result::Json::SizingLife lj;
  const double limit = spec.limits.life_h;
  if (limit > 0) lj.life_h = limit;
  lj.shortest_L10h = k.shortest_L10h;
  const auto shortest = std::min_element(k.life.begin(), k.life.end(),
                                          [](const auto& a, const auto& b) { return a.life.L10h < b.life.L10h; });
  lj.shortest_bearing = shortest->name;
  for (const auto& b : k.life)
    (b.name == "input_roller"    ? lj.input_roller_L10h
     : b.name == "output_roller" ? lj.output_roller_L10h
                                 : lj.eccentric_bearing_L10h.emplace()) = b.life.L10h;
  lj.duty_cycle = DutyCycleEchoOf(spec.life->lines);
  for (const auto& b : k.life)
    lj.table.push_back(BearingLifeRow(b.name, b.ball, b.life.equivalent_load_N, b.life.max_load_N,
                                      b.life.revolutions_per_input_revolution, b.dynamic_rating_N, b.static_rating_N,
                                      b.s0, b.life.L10h, limit));
  lj.rating_rule = spec.life->roller.reference_diameter_mm > 0
                       ? "roller C = C_ref (d/d_ref)^(29/27) (L/L_ref)^(7/9) (ISO 281:2007 6.1.1), C0 = C0_ref (d/d_ref)(L/L_ref) (ISO 76)"
                       : "roller C, C0 as the catalogue gives them";
  lj.model = "ISO 281:2007 basic rating life L10 over the duty cycle (Palmgren-Miner), loads of the rigid law "
             "revolution-weighted over each bearing's load period, computed as lcr_analysis does (docs/life.md)";
  return lj;
}

std::string StatusOf(const Candidate& c) {
  if (c.feasible()) return "converged";
  if (c.outcome.life_out_of_reach) return "life_out_of_reach";
  const auto& r = c.outcome.result;
  if (r.ok() && c.outcome.check && !c.outcome.check->ok()) return "fails_dense_check";
  if (r.ok()) return "failed";  // converged solve without a dense check (degenerate geometry)
  return optimizers::ToString(r.status);
}

// The efficiency objective (objectives::LcrSizeObjective::kPowerLoss).
bool MinimisesLoss(const Study& s) { return s.base.objective == objectives::LcrSizeObjective::kPowerLoss; }

Result::Json::CandidateSide SideRow(const lcr::CamSide<double>& c) {
  Result::Json::CandidateSide r;
  r.lobes = c.lobes;
  r.rollers = c.rollers;
  r.turret_radius_mm = c.turret_radius;
  r.roller_diameter_mm = 2 * c.roller_radius;
  r.roller_length_mm = c.roller_length;
  r.cam_thickness_mm = c.cam_thickness;
  return r;
}

nlohmann::json SideJson(const lcr::CamSide<double>& c) { return WriteResult(SideRow(c)); }

Result::Json::CandidateRow CandidateRow(const Study& s, const Candidate& c) {
  const auto& o = c.outcome;
  Result::Json::CandidateRow j;
  j.input.lobes = c.combo.lobes_a;
  j.input.rollers = c.combo.rollers_a;
  j.output.lobes = c.combo.lobes_b;
  j.output.rollers = c.combo.rollers_b;
  if (c.roller >= 0) j.catalogue_roller = s.catalogue[c.roller].name;
  j.status = c.pruned() ? "pruned" : StatusOf(c);
  j.feasible = c.feasible();
  j.solver_message = o.result.message;
  if (!o.note.empty()) j.note = o.note;
  j.longest_life_h = o.longest_life_h;
  j.evaluations = {o.result.value_evaluations, o.result.gradient_evaluations, o.result.iterations, o.polish_rounds};
  if (c.pruned()) {
    // Branch and bound (sizing/sizing_driver.h): not solved to the end, no design to report.
    j.outer_diameter_lower_bound_mm = c.outcome3d->paused->lower_bound_mm;
    j.note = "pruned: a polish round's outer diameter (outer_diameter_lower_bound_mm) already exceeds the best "
             "design's; each round adds constraints, so the candidate's optimum can only be larger";
    return j;
  }
  // Multistart: every start's outcome; the spread of the converged objective values (outer
  // diameters, or with the efficiency objective the losses).
  const bool loss = MinimisesLoss(s);
  double lo = kInf, hi = -kInf;
  for (const auto& st : o.starts) {
    Result::Json::CandidateRow::Start& sj = j.starts.emplace_back();
    sj.status = st.converged ? "converged" : optimizers::ToString(st.status);
    if (st.converged) {
      sj.outer_diameter_mm = st.outer_diameter_mm;
      if (loss) sj.power_loss_W = st.objective;
      lo = std::min(lo, st.objective);
      hi = std::max(hi, st.objective);
    }
  }
  if (hi >= lo) (loss ? j.multistart_spread_W : j.multistart_spread_mm) = hi - lo;
  j.binding = Unique(o.result.active);
  j.violated = Unique(o.result.violated);
  if (o.design && c.feasible()) {
    const auto& k = *o.check;
    j.outer_diameter_mm = k.outer_diameter_mm;
    j.eccentricity_mm = o.design->eccentricity;
    j.input = SideRow(o.design->input);
    j.output = SideRow(o.design->output);
    j.max_contact_stress_MPa = std::max(k.max_stress_MPa[0], k.max_stress_MPa[1]);
    j.max_roller_force_N = std::max(k.max_force_N[0], k.max_force_N[1]);
    j.undercut_margin_mm = std::min(k.undercut_margin_mm[0], k.undercut_margin_mm[1]);
    if (!k.life.empty()) j.shortest_L10h = k.shortest_L10h;
    if (loss) {
      j.power_loss_W = k.lubricated_loss_W;
      j.mean_efficiency = k.mean_efficiency;
    }
  } else if (o.design) {
    // Not a result: the point where the search came closest, and what it breaks there.
    j.closest_point = {o.design->eccentricity, SideRow(o.design->input), SideRow(o.design->output)};
    if (o.check) {
      j.violations.emplace();
      for (const auto& x : o.check->violations) j.violations->push_back({x.limit, x.value, x.limit_value, x.excess()});
      if (!o.check->design_problems.empty()) j.design_problems = o.check->design_problems;
    }
  }
  return j;
}

// What blocks when nothing fits: the candidate whose worst relative violation at its closest
// point is least (an undercut contact counts as infinite), that violation's limit, and, for a
// stress or load limit, the value at which that candidate fits (sizing::LimitToFit).
std::string BlockingMessage(const Study& s, const Result& r) {
  // A candidate that converged on the fast model but failed the accurate model's check: that
  // check's words (the limit, the accurate value, what to change).
  for (const Candidate& c : r.candidates)
    if (c.verification && c.verification->ran && !c.verification->verified()) {
      const objectives::VerifiedLimit* w = c.verification->worst();
      const bool edge = w && w->limit.find("edge") != std::string::npos;
      return sizing::LobeCombinationName(c.combo) + " converged on the fast model but is " +
             VerificationFailure(*c.verification,
                                 edge ? "edge-loaded: crown the rollers more (a larger crowning range or effective "
                                        "length), or lower the misalignment"
                                      : "refine contact.slices, or raise the limit");
    }
  const Candidate* closest = nullptr;
  const objectives::LcrViolation* worst = nullptr;
  double least = kInf;
  for (const Candidate& c : r.candidates) {
    if (!c.outcome.check) continue;
    const objectives::LcrViolation* w = nullptr;
    double rel = 0;
    for (const auto& v : c.outcome.check->violations) {
      const double e = v.excess() / std::max(std::abs(v.limit_value), 1.0);
      if (!w || e > rel) w = &v, rel = e;
    }
    if (w && (!closest || rel < least)) closest = &c, worst = w, least = rel;
  }
  if (!closest) return "no design meets the limits, and no candidate reached a point that the dense check could assess";
  if (worst->limit == "edge_margin" || worst->limit == "overload_edge_margin") {
    const bool straight = s.contact3d && s.contact3d->crowning.type == contact::CrowningType::kNone;
    const std::string torque = worst->limit == "edge_margin" ? "design" : "overload";
    std::ostringstream m;
    m.precision(4);
    m << "edge-loaded: the pressure reaches the rollers' ends at the " << torque << " torque for every design ("
      << sizing::LobeCombinationName(closest->combo) << ": end margin " << worst->value << ", needs > 0); "
      << (straight ? "crown the rollers (fixed.crowning with variables.crowning_coefficient_mm)"
                   : "allow more crowning (a wider crowning range, a longer effective length) or less misalignment");
    return m.str();
  }
  std::ostringstream m;
  m.precision(4);
  m << "no design meets the limits: " << worst->limit << " blocks most; ";
  // Searched from the value at the closest point: the closest point minimises the violation.
  const std::optional<double> fit = sizing::LimitToFit(closest->spec, s.options, worst->limit, worst->value);
  if (fit) {
    m << sizing::LobeCombinationName(closest->combo) << " fits with " << worst->limit << " = " << *fit << " (limit "
      << worst->limit_value << ")";
  } else if (std::isfinite(worst->value)) {
    m << "at the closest point of " << sizing::LobeCombinationName(closest->combo) << " it is " << worst->value << " (limit "
      << worst->limit_value << ")";
  } else {
    m << "the closest point of " << sizing::LobeCombinationName(closest->combo) << " has an undercut contact";
  }
  return m.str();
}

}  // namespace

void ParseSizingLubrication(const Input& in, const Node& root, Study& s);
void FillResult(const Study& s, Result& result);

Study Parse(const Node& root) {
  // Every field's type and bounds; what spans fields follows.
  const Input in = Read<Input>(root);
  Study s;
  s.name = in.name;
  if (std::abs(in.target.speed_ratio) < 2) root["target"]["speed_ratio"].Fail(Input::Target::kRatioText);
  s.ratio = in.target.speed_ratio;
  s.output_torque_Nmm = in.target.output_torque_Nm * 1000.0;
  // A life (docs/life.md): a speed or a duty cycle; its ratings are read below.
  std::string life_why;
  std::optional<std::vector<lcr::LcrDutyLine>> duty = ParseDutyCycle(root, in.duty_cycle, s.output_torque_Nmm, &life_why);
  // "ratings" (docs/ratings.md, Ratings as sizing limits): the rated point as the life rows' one line.
  s.ratings = in.ratings;
  if (in.ratings) {
    CheckSizingRatingsAlone(root, in.limits.life_h.has_value(), in.duty_cycle.has_value());
    duty = std::vector<lcr::LcrDutyLine>{in.ratings->RatedLine(double(s.ratio))};
    life_why = "a rated torque is asked: ratings is given";
  }
  s.max_lobes = in.search.max_lobes;
  s.differences = in.search.roller_lobe_difference;

  LcrSizingSpec& b = s.base;
  const Input::Variables& v = in.variables;
  const Node vars = root["variables"];
  b.eccentricity_mm = OrderedRange(v.eccentricity_mm, vars["eccentricity_mm"]);
  b.turret_radius_mm = OrderedRange(v.turret_radius_mm, vars["turret_radius_mm"]);
  if (v.roller_diameter_mm) b.roller_diameter_mm = OrderedRange(*v.roller_diameter_mm, vars["roller_diameter_mm"]);
  b.same_roller = v.same_roller_on_both_cams;

  const Node fixed = root["fixed"];
  b.cam_thickness_mm = in.fixed.cam_thickness_mm;
  if (in.roller_catalogue) {
    const Node cat = root["roller_catalogue"];
    if (const auto* f = std::get_if<CatalogueFileInput>(&*in.roller_catalogue)) {
      // {"file": "rollers.json"}, relative to the study file.
      const Node file = cat["file"];
      std::filesystem::path p(f->file);
      if (p.is_relative()) p = std::filesystem::path(root.file()).parent_path() / p;
      // A file that cannot be read is named by the study's JSON path; the entries' own errors by the
      // catalogue file's.
      nlohmann::json loaded;
      try {
        loaded = LoadStudyFile(p.string());
      } catch (const StudyError& e) {
        file.FailWith(e.what());
      }
      const Node list(&loaded, p.string(), "");
      std::vector<CatalogueRollerInput> entries;
      JsonReader::ReadValue(list, &entries, Input::CatalogueField());
      s.catalogue = CatalogueRollers(entries, list, life_why);
    } else {
      s.catalogue = CatalogueRollers(std::get<std::vector<CatalogueRollerInput>>(*in.roller_catalogue), cat, life_why);
    }
  } else {
    if (!in.fixed.roller_length_mm) (void)fixed["roller_length_mm"];  // "missing required field"
    b.roller_length_mm = *in.fixed.roller_length_mm;
    if (!v.roller_diameter_mm) (void)vars["roller_diameter_mm"];  // "missing required field"
  }

  if (!b.same_roller && !s.catalogue.empty())
    vars["same_roller_on_both_cams"].Fail("true with a roller catalogue (each catalogue roller is used on both cams)");
  if (!s.catalogue.empty() && in.fixed.roller_length_mm)
    fixed["roller_length_mm"].FailWith("no fixed roller length with a roller catalogue (the catalogue gives the lengths)");

  const Input::Limits& limits = in.limits;
  b.limits.contact_stress_MPa = limits.contact_stress_MPa.value_or(kInf);
  b.limits.roller_load_N = limits.roller_load_N.value_or(kInf);
  b.limits.undercut_margin_mm = limits.undercut_margin_mm;
  b.limits.roller_gap_mm = limits.roller_gap_mm;
  if (limits.min_efficiency) b.limits.min_efficiency = *limits.min_efficiency;
  b.limits.life_h = in.ratings ? in.ratings->rated_life_h : limits.life_h.value_or(0.0);
  if (in.ratings && in.ratings->momentary_torque_Nm) {
    // The momentary torque (docs/ratings.md, Ratings as sizing limits): every bearing with a static
    // rating keeps s0 >= momentary_static_safety there; the rollers' and the eccentric's C0 are needed.
    b.limits.min_static_safety = in.ratings->momentary_static_safety;
    b.limits.static_torque_Nmm = *in.ratings->momentary_torque_Nm * 1000.0;
  }
  b.limits.max_outer_diameter_mm = limits.max_outer_diameter_mm.value_or(kInf);
  if (b.limits.life_h > 0 && !duty)
    root["limits"]["life_h"].FailWith("a life limit needs the speed: expected load.input_speed_rpm (> 0) or a duty_cycle "
                                      "beside limits.life_h, found neither");
  b.material = in.material ? in.material->ToMaterial() : lcr::Material{};
  b.output_torque_Nmm = s.output_torque_Nmm;
  b.friction_coefficient = in.load.friction_coefficient;

  const Input::Optimizer& o = in.optimizer;
  optimizers::SolverOptions& solver = s.options.solver;
  solver.backend = ToBackend(o.backend);
  // Few variables against rows at every sampled angle (optimizers/solver.h): measured on the seven
  // Ipopt examples, 2–12 % less CPU (lcr_min_size 0.40 → 0.35 s), answers within 3e-7 of themselves.
  solver.ipopt_extended_low_rank = true;
  s.form = o.constraints == "samples" ? LcrConstraintForm::kSamples : LcrConstraintForm::kAggregate;
  s.options.polish = o.polish;
  b.samples_per_period = o.samples_per_period;
  b.sharpness = o.sharpness;
  solver.tolerance = o.tolerance;
  // Ipopt counts iterations (one gradient each), NLopt evaluations: Ipopt converges in 10–50
  // iterations here, and a start that needs hundreds is a degenerate one that other starts cover.
  solver.max_evaluations = o.max_evaluations.value_or(solver.backend == optimizers::Backend::kIpopt ? 200 : 3000);
  s.options.starts = o.starts;
  solver.max_seconds = 10.0;  // per local solve
  // A local solve that Ipopt ends at its iteration limit is polished by SLSQP from Ipopt's last
  // point (Ipopt may cycle on the kinks of tracked maxima; SLSQP's active set settles them).
  if (solver.backend == optimizers::Backend::kIpopt) solver.fallback_backend = optimizers::Backend::kSlsqp;
  double longest = b.roller_length_mm;
  for (const CatalogueRoller& r : s.catalogue) longest = std::max(longest, r.length_mm);
  s.contact3d = ParseContact3D(in, root, s.catalogue.empty() ? b.roller_length_mm : longest, !s.catalogue.empty());
  s.options.smooth_form = s.form;

  if (objectives::LobeCombinations(s.ratio, s.max_lobes, s.differences).empty())
    throw StudyError(root.file() + ": /target/speed_ratio: no lobe/roller combination with at most " +
                     std::to_string(s.max_lobes) + " lobes gives the ratio " + std::to_string(s.ratio) +
                     " exactly");
  b.life = ParseLife(in, root, b, !s.catalogue.empty(), duty ? &*duty : nullptr, life_why);
  if (b.limits.min_static_safety > 0) {
    // The momentary torque's static rows need C0: the rollers' (every catalogue entry's) or the eccentric's.
    if (!s.catalogue.empty()) {
      for (const CatalogueRoller& r : s.catalogue)
        if (!(r.static_rating_N > 0))
          root["roller_catalogue"].FailWith("static_rating_N on every entry with ratings.momentary_torque_Nm (each "
                                            "catalogue roller's s0 at the momentary torque)");
    } else if (!(b.life && b.life->roller.static_N > 0) &&
               !(b.life && b.life->eccentric && b.life->eccentric->static_N > 0)) {
      root["ratings"]["momentary_torque_Nm"].FailWith(
          "a momentary torque needs a static rating to hold: rollers.static_rating_N or "
          "eccentric_bearing.static_rating_N, found neither");
    }
  }
  ParseRobust(in, root, s);
  // The efficiency objective: the lubricated loss of the line model's nominal design
  // (objectives/lcr_sizing.h LcrSizeObjective::kPowerLoss).
  if (in.objective == "efficiency") {
    if (!in.lubricant)
      root["objective"].FailWith("the efficiency objective needs \"lubricant\" (the oil whose losses it minimises) "
                                 "and load.input_speed_rpm; would fit: \"outer_diameter\", or a \"lubricant\" block");
    if (s.contact3d || s.robust)
      root["objective"].FailWith(std::string("the efficiency objective is sized on the line contact model without "
                                             "tolerances: not with ") +
                                 (s.contact3d ? "a 3D \"contact\" (or fixed.crowning, overload, crowning or length "
                                                "variables)"
                                              : "\"robust\"") +
                                 "; would fit: \"outer_diameter\", or remove that block");
  }
  // The life rows and checks are those of the line model's nominal design (objectives/lcr_sizing.h).
  if (b.life && (s.contact3d || s.robust))
    (in.ratings ? root["ratings"]
     : duty->size() == 1 && !in.duty_cycle ? root["load"]["input_speed_rpm"] : root["duty_cycle"])
        .FailWith(std::string("bearing lives are sized on the line contact model without tolerances: no speed or duty "
                              "cycle together with ") + (s.contact3d ? "a 3D \"contact\"" : "\"robust\"") +
                  " (remove one of the two)");
  // The robust rows (objectives/lcr_robust.h) linearise the line-model stress margin; with the
  // finite-length contact they would check a stress the 3D constraint does not use.
  if (s.robust && s.contact3d)
    root["robust"].Fail("no \"robust\" block together with a 3D \"contact\" (robust sizing uses the line "
                        "contact model; remove one of the two)");
  ParseSizingLubrication(in, root, s);
  if (in.objective == "efficiency") s.base.objective = objectives::LcrSizeObjective::kPowerLoss;
  return s;
}

// "lubricant" and its blocks (docs/lubrication.md) as lcr_analysis reads them, at the target torque
// and load.input_speed_rpm (a speed also asks for the lives, so the line model without tolerances):
// limits.min_efficiency then bounds the lubricated efficiency, limits.max_oil_temperature_C (with
// lubricant.thermal) the housing's oil temperature. Without a lubricant min_efficiency is eq. 33's.
void ParseSizingLubrication(const Input& in, const Node& root, Study& s) {
  if (!in.lubricant) {
    for (const char* block : {"surfaces", "bearing_friction"})
      if (root.Has(block))
        root[block].FailWith(std::string("\"") + block + "\" needs \"lubricant\" (the oil whose losses it sets)");
    if (in.limits.max_oil_temperature_C)
      root["limits"]["max_oil_temperature_C"].FailWith("a limit on the oil temperature needs \"lubricant\" with its "
                                                       "\"thermal\" balance");
    return;
  }
  const std::optional<LubricationCommon> common = ParseLubricationCommon(
      root, in.lubricant, in.surfaces, std::nullopt, in.load.input_speed_rpm, in.duty_cycle.has_value());
  auto l = SizingLubricationOf<objectives::LcrSizingLubrication>(root, in.limits.max_oil_temperature_C, *common);
  l.spec.rollers_rotate = common->rollers_rotate;
  const LcrBearingFrictionInput bearings = in.bearing_friction.value_or(LcrBearingFrictionInput{});
  l.spec.roller_bearing = bearings.rollers ? bearings.rollers->ToBearing() : PalmgrenBearing{0.0, 0.0, 1.0};
  l.spec.eccentric_bearing = bearings.eccentric ? bearings.eccentric->ToBearing() : PalmgrenBearing{0.0, 0.0, 1.0};
  s.base.lubrication = l;
  s.base.limits.max_oil_temperature_C = in.limits.max_oil_temperature_C.value_or(kInf);
  s.lubrication_blocks = {in.lubricant, in.surfaces, in.bearing_friction};
}

std::array<double, 2> OrderedRange(const std::array<double, 2>& range, const Node& n) {
  if (!(range[0] <= range[1])) n.Fail("[lower, upper] with lower <= upper");
  return range;
}

nlohmann::ordered_json Input::SchemaRules() {
  // Robust sizing needs its tolerances (and the tolerances are only for it) and the aggregate
  // constraints (it picks its own forms), the Monte-Carlo the tolerances; a catalogue gives the rollers' lengths and diameters (else fixed.roller_length_mm
  // and variables.roller_diameter_mm), and with a life their ratings (else "rollers"); a life limit
  // needs a speed, given one way; a life is sized on the line model without tolerances.
  return nlohmann::ordered_json::parse(R"({
    "dependentRequired": {"robust": ["tolerances"], "tolerances": ["robust"], "monte_carlo": ["tolerances"],
                          "surfaces": ["lubricant"], "bearing_friction": ["lubricant"],
                          "lubricant": ["material", "load"]},
    "allOf": [
      {"if": {"required": ["robust"]},
       "then": {"properties": {"optimizer": {"properties": {"constraints": {"const": "aggregate"}}}}}},
      {"if": {"anyOf": [
         {"required": ["fixed"], "properties": {"fixed": {"required": ["crowning"]}}},
         {"required": ["variables"], "properties": {"variables": {"anyOf": [
           {"required": ["crowning_coefficient_mm"]}, {"required": ["crowning_radius_mm"]},
           {"required": ["crowning_flat_length_mm"]}, {"required": ["roller_length_mm"]},
           {"required": ["cam_thickness_mm"]}]}}},
         {"required": ["load"], "properties": {"load": {"required": ["overload_torque_Nm"]}}}]},
       "then": {"required": ["contact"], "properties": {"contact": {
         "required": ["model"], "properties": {"model": {"enum": ["slices", "half_space"]}}}}}},
      {"if": {"required": ["contact"], "properties": {"contact": {
         "required": ["misalignment_mrad"], "properties": {"misalignment_mrad": {"not": {"const": 0}}}}}},
       "then": {"properties": {"contact": {
         "required": ["model"], "properties": {"model": {"enum": ["slices", "half_space"]}}}}}},
      {"if": {"anyOf": [{"required": ["robust"]},
                        {"required": ["objective"], "properties": {"objective": {"const": "efficiency"}}}]},
       "then": {"not": {"required": ["contact"], "properties": {"contact": {
         "required": ["model"], "properties": {"model": {"enum": ["slices", "half_space"]}}}}}}},
      {"if": {"required": ["objective"], "properties": {"objective": {"const": "efficiency"}}},
       "then": {"not": {"required": ["robust"]}}},
      {"if": {"required": ["variables"], "properties": {"variables": {"required": ["crowning_coefficient_mm"]}}},
       "then": {"required": ["fixed"], "properties": {"fixed": {"required": ["crowning"], "properties": {"crowning": {
         "required": ["type"], "properties": {"type": {"const": "logarithmic"}}}}}}}},
      {"if": {"required": ["variables"], "properties": {"variables": {"required": ["crowning_radius_mm"]}}},
       "then": {"required": ["fixed"], "properties": {"fixed": {"required": ["crowning"], "properties": {"crowning": {
         "required": ["type"], "properties": {"type": {"enum": ["circular", "partial"]}}}}}}}},
      {"if": {"required": ["variables"], "properties": {"variables": {"required": ["crowning_flat_length_mm"]}}},
       "then": {"required": ["fixed"], "properties": {"fixed": {"required": ["crowning"], "properties": {"crowning": {
         "required": ["type"], "properties": {"type": {"const": "partial"}}}}}}}},
      {"if": {"required": ["fixed"],
              "properties": {"fixed": {"required": ["crowning"], "properties": {"crowning": {
                "required": ["type"], "properties": {"type": {"const": "logarithmic"}}}}}},
              "not": {"required": ["variables"], "properties": {"variables": {"required": ["crowning_coefficient_mm"]}}}},
       "then": {"properties": {"fixed": {"properties": {"crowning": {"required": ["coefficient_mm"]}}}}}},
      {"if": {"required": ["lubricant"]},
       "then": {"required": ["load"], "properties": {"load": {"required": ["input_speed_rpm"]}}}},
      {"if": {"required": ["objective"], "properties": {"objective": {"const": "efficiency"}}},
       "then": {"required": ["lubricant"]}},
      {"if": {"required": ["limits"], "properties": {"limits": {"required": ["max_oil_temperature_C"]}}},
       "then": {"required": ["lubricant"], "properties": {"lubricant": {"required": ["thermal"]}}}},
      {"if": {"required": ["roller_catalogue"]},
       "then": {"properties": {"fixed": {"not": {"required": ["roller_length_mm"]}},
                               "variables": {"not": {"required": ["roller_length_mm"]}}}},
       "else": {"properties": {"fixed": {"required": ["roller_length_mm"]},
                               "variables": {"required": ["roller_diameter_mm"]}}}},
      {"if": {"required": ["limits"], "properties": {"limits": {"required": ["life_h"]}}},
       "then": {"anyOf": [{"required": ["duty_cycle"]},
                          {"required": ["load"], "properties": {"load": {"required": ["input_speed_rpm"]}}}]}},
      {"if": {"required": ["duty_cycle"]},
       "then": {"properties": {"load": {"not": {"required": ["input_speed_rpm"]}}}}},
      {"if": {"required": ["ratings", "roller_catalogue"],
              "properties": {"ratings": {"required": ["momentary_torque_Nm"]}}},
       "then": {"properties": {"roller_catalogue": {"oneOf": [
         {"type": "object"}, {"type": "array", "items": {"required": ["static_rating_N"]}}]}}}},
      {"if": {"required": ["ratings"], "properties": {"ratings": {"required": ["momentary_torque_Nm"]}},
              "not": {"required": ["roller_catalogue"]}},
       "then": {"anyOf": [{"required": ["rollers"], "properties": {"rollers": {"required": ["static_rating_N"]}}},
                          {"required": ["eccentric_bearing"],
                           "properties": {"eccentric_bearing": {"required": ["static_rating_N"]}}}]}},
      {"if": {"required": ["ratings"]},
       "then": {"not": {"anyOf": [{"required": ["duty_cycle"]},
                                  {"required": ["limits"], "properties": {"limits": {"required": ["life_h"]}}}]}}},
      {"if": {"anyOf": [{"required": ["duty_cycle"]}, {"required": ["ratings"]},
                        {"required": ["load"], "properties": {"load": {"required": ["input_speed_rpm"]}}}]},
       "then": {"allOf": [
         {"not": {"required": ["contact"],
                  "properties": {"contact": {"required": ["model"],
                                             "properties": {"model": {"enum": ["slices", "half_space"]}}}}}},
         {"not": {"required": ["robust"]}},
         {"if": {"required": ["roller_catalogue"]},
          "then": {"properties": {"roller_catalogue": {"oneOf": [
            {"type": "object"}, {"type": "array", "items": {"required": ["dynamic_rating_N"]}}]}}},
          "else": {"required": ["rollers"]}}]}},
      {"if": {"required": ["roller_catalogue"]}, "then": {"not": {"required": ["rollers"]}}}
    ]})");
}

Result Run(const Study& s, const RunContext& ctx) {
  Result res;
  const auto t0 = std::chrono::steady_clock::now();
  {
    // The search over the candidates and the accurate check of the answer (sizing/lcr_search.h).
    Progress progress("lcr_min_size", ctx.quiet);
    static_cast<sizing::LcrSearchOutcome&>(res) =
        sizing::SearchLcrMinSize(s, [&](double f, const std::string& what) { progress.Update(f, what); });
  }
  if (res.best < 0) res.blocking_message = BlockingMessage(s, res);
  if (s.robust) RunRobust(s, res, ctx);
  FillResult(s, res);
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

// What each binding limit costs in the objective, one line per limit ("stress limit +10 MPa →
// -0.458 mm" of outer diameter, or "→ -0.0123 W of loss" with the efficiency objective), from the
// limit sensitivities (re-solves of the line problem).
std::vector<std::string> LimitCosts(const Study& s, const Result& result) {
  struct Shown {
    const char* key;
    const char* label;
    double step;
    const char* unit;
  };
  const Shown shown[] = {{"contact_stress_MPa", "stress limit", 10, "MPa"},
                         {"roller_load_N", "roller load limit", 10, "N"},
                         {"undercut_margin_mm", "undercut margin", 0.1, "mm"},
                         {"roller_gap_mm", "roller gap", 0.1, "mm"},
                         {"min_efficiency", "efficiency limit", 0.01, ""},
                         {"life_h", "life limit", 1000, "h"},
                         {"min_static_safety", "static safety at the momentary torque", 0.1, ""},
                         {"max_outer_diameter_mm", "outer diameter limit", 1, "mm"}};
  const bool loss = MinimisesLoss(s);
  std::vector<std::string> lines;
  char buf[200];
  for (const Shown& sh : shown) {
    const auto it = result.limit_sensitivity.find(sh.key);
    if (it == result.limit_sensitivity.end()) continue;
    if (loss)
      std::snprintf(buf, sizeof buf, "%s +%g%s%s → %+.4g W of loss", sh.label, sh.step, *sh.unit ? " " : "", sh.unit,
                    it->second * sh.step);
    else
      std::snprintf(buf, sizeof buf, "%s +%g%s%s → %+.3f mm", sh.label, sh.step, *sh.unit ? " " : "", sh.unit,
                    it->second * sh.step);
    lines.push_back(buf);
  }
  return lines;
}

void FillResult(const Study& s, Result& result) {
  Result::Json& res = result.json;
  res.name = s.name;
  res.target.speed_ratio = s.ratio;
  res.target.output_torque_Nm = s.output_torque_Nmm / 1000;
  // What was minimised: written for the efficiency objective only (absent: the outer diameter, so
  // that a default study's result.json stays as it was).
  if (MinimisesLoss(s)) res.objective = "efficiency";
  res.optimizer.backend = optimizers::ToString(s.options.solver.backend);
  res.optimizer.constraints = s.form == LcrConstraintForm::kSamples ? "samples" : "aggregate";
  res.optimizer.polish = s.options.polish;
  res.optimizer.samples_per_period = s.base.samples_per_period;
  res.optimizer.sharpness = s.base.sharpness;
  res.optimizer.starts = s.options.starts;
  res.optimizer.value_evaluations = result.value_evaluations;
  res.optimizer.gradient_evaluations = result.gradient_evaluations;
  res.candidates.clear();
  for (const auto& c : result.candidates) res.candidates.push_back(CandidateRow(s, c));
  // The verified-optimum contract: of the best design, or, when nothing fits, of the candidate
  // that failed its check.
  const objectives::Verification* verification = nullptr;
  if (result.best >= 0) verification = result.candidates[result.best].verification ? &*result.candidates[result.best].verification : nullptr;
  else
    for (const Candidate& c : result.candidates)
      if (c.verification && !verification) verification = &*c.verification;
  if (verification) {
    res.verified = verification->verified();
    res.verification = VerificationBlock::Of(*verification);
  } else {
    res.verified = false;
    res.verification = VerificationBlock::NotRun("no design to verify");
  }
  if (result.best < 0) {
    res.best = nullptr;
    res.notes = std::vector<std::string>{result.blocking_message};
    if (s.contact3d) AddContact3DJson(s, result);
    if (s.robust) RobustJson(s, result);
    return;
  }
  const Candidate& best = result.candidates[result.best];
  const lcr::Reducer<double>& r = *best.outcome.design;
  const objectives::LcrDenseCheck& k = *best.outcome.check;
  Result::Json::NominalBest b;
  b.eccentricity_mm = r.eccentricity;
  b.outer_diameter_mm = k.outer_diameter_mm;
  b.speed_ratio = lcr::SpeedReductionRatio(r);
  b.max_contact_stress_MPa = std::max(k.max_stress_MPa[0], k.max_stress_MPa[1]);
  b.max_roller_force_N = std::max(k.max_force_N[0], k.max_force_N[1]);
  b.undercut_margin_mm = std::min(k.undercut_margin_mm[0], k.undercut_margin_mm[1]);
  b.roller_gap_mm = std::min(k.roller_gap_mm[0], k.roller_gap_mm[1]);
  b.mean_efficiency = k.mean_efficiency;
  if (s.base.lubrication) {  // the lubricated operating point (docs/lubrication.md)
    b.efficiency_model = "lubricated (docs/lubrication.md)";
    b.oil_temperature_C = k.oil_temperature_C;
    b.power_loss_W = k.lubricated_loss_W;
    if (!k.lubrication_why.empty()) b.lubrication_error = k.lubrication_why;
  } else {
    b.efficiency_model = "eq. 33 with load.friction_coefficient";
  }
  Result::Json::BestSide* sides[2] = {&b.input, &b.output};
  const lcr::CamSide<double>* cams[2] = {&r.input, &r.output};
  for (int i = 0; i < 2; ++i) {
    Result::Json::BestSide& side = *sides[i];
    side.sizes = SideRow(*cams[i]);
    side.max_contact_stress_MPa = k.max_stress_MPa[i];
    side.max_roller_force_N = k.max_force_N[i];
    side.undercut_margin_mm = k.undercut_margin_mm[i];
    side.roller_gap_mm = k.roller_gap_mm[i];
    if (k.peak_half_width_mm[i] > 0 || !std::isfinite(k.max_stress_MPa[i]))
      side.subsurface = SubsurfaceOf(
          k.max_stress_MPa[i], k.peak_half_width_mm[i], s.base.material.poisson_ratio,
          "Hertz line contact of the cam's peak pressure in the dense check, frictionless, homogeneous "
          "half-spaces (Johnson 1985, eq. 4.50 ff.)");
  }
  if (best.roller >= 0) b.catalogue_roller = s.catalogue[best.roller].name;
  b.binding = Unique(best.outcome.result.active);
  b.binding_names = PlainLimitNames(Unique(best.outcome.result.active), best.spec);
  for (const auto& [key, v] : result.limit_sensitivity) b.limit_sensitivity[key] = v;
  if (!result.limit_sensitivity.empty()) b.limit_costs = LimitCosts(s, result);
  // The same as cycloid_min_size and disc_cam_min_size give it: limit, its value, its cost.
  for (const auto& [key, cost] : result.limit_sensitivity) {
    const LcrLimits& l = best.spec.limits;
    const std::map<std::string, std::pair<double, std::string>> values = {
        {"contact_stress_MPa", {l.contact_stress_MPa, "MPa"}}, {"roller_load_N", {l.roller_load_N, "N"}},
        {"undercut_margin_mm", {l.undercut_margin_mm, "mm"}},  {"roller_gap_mm", {l.roller_gap_mm, "mm"}},
        {"min_efficiency", {l.min_efficiency, "1"}},          {"life_h", {l.life_h, "h"}},
        {"min_static_safety", {l.min_static_safety, "1"}},
        {"max_oil_temperature_C", {l.max_oil_temperature_C, "°C"}},
        {"max_outer_diameter_mm", {l.max_outer_diameter_mm, "mm"}}};
    const auto it = values.find(key);
    BindingLimit entry;
    entry.limit = key;
    entry.limit_value = it != values.end() ? it->second.first : NAN;
    entry.limit_cost = cost;
    entry.unit = std::string(MinimisesLoss(s) ? "W of loss" : "mm") + " per " +
                 (it != values.end() ? it->second.second : std::string("unit"));
    // The cost is itself the re-solve slope here (LimitSlopes): the same number, with its sides.
    entry.slope = MakeLimitSlopeResult(result.limit_slope.count(key) ? &result.limit_slope.at(key) : nullptr);
    b.binding_limits.push_back(std::move(entry));
  }
  if (s.contact3d)
    b.limit_sensitivity_note =
        "not computed for a sizing on the 3D contact: each limit's cost would take two more verified 3D "
        "sizings; move the limit in the study and run it again";
  if (!k.life.empty()) b.life = LifeOf(best.spec, k);
  if (s.ratings && !k.life.empty()) {
    // The rigid law's loads are proportional to the torque, so each bearing's
    // L10(T) = L10(T_r) (T_r/T)^p (ISO 281 eq. 1, p = 3 ball, 10/3 roller) and its rated torque is
    // T_r (L10(T_r)/L_r)^(1/p); the design's is the smallest.
    std::optional<double> rated;
    std::string by;
    for (const auto& bl : k.life) {
      const double t = s.ratings->rated_torque_Nm *
                       std::pow(bl.life.L10h / s.ratings->rated_life_h, 1.0 / (bl.ball ? 3.0 : 10.0 / 3.0));
      if (std::isfinite(t) && (!rated || t < *rated)) rated = t, by = bl.name;
    }
    // Met as the verification holds them: every check of that limit, the accurate value within its
    // estimated error (one verdict for the exit code, `verified` and these flags).
    auto holds = [&](const std::string& limit) {
      bool any = false, all = true;
      if (best.verification)
        for (const objectives::VerifiedLimit& c : best.verification->checks)
          if (c.limit == limit) any = true, all = all && c.holds();
      return any && all;
    };
    const bool momentary_met = !s.ratings->momentary_torque_Nm || holds("min_static_safety");
    SizedRatingsBlock ratings = SizedRatingsOf(*s.ratings, double(s.ratio), k.shortest_L10h,
                                               holds("life_h") && momentary_met, rated, by, "no rated bearing is loaded");
    if (s.ratings->momentary_torque_Nm) {
      // The momentary torque: P0max ∝ T (rigid law), so each bearing's s0 = s at
      // T_line C0 / (s P0max(T_line)), T_line the rated line's torque; the design's is the smallest.
      const double line = s.ratings->rated_torque_Nm, need = s.ratings->momentary_static_safety;
      std::optional<double> momentary;
      std::string mby;
      for (const auto& bl : k.life)
        if (bl.static_rating_N > 0 && bl.life.max_load_N > 0) {
          const double t = line * bl.static_rating_N / (need * bl.life.max_load_N);
          if (!momentary || t < *momentary) momentary = t, mby = bl.name;
        }
      ratings.SetMomentary(*s.ratings->momentary_torque_Nm, need, k.min_static_safety, momentary, mby, std::nullopt,
                           momentary_met);
    }
    b.ratings = std::move(ratings);
  }
  res.best = b;
  if (s.contact3d) AddContact3DJson(s, result);
  if (s.robust) RobustJson(s, result);
}

namespace {

// A design of one candidate (its spec: counts, roller, limits) as an lcr_analysis study: the
// reducer, the study's material, load and limits, on the dense check's grid.
nlohmann::json LcrAnalysisStudyOf(const Study& s, const LcrSizingSpec& spec, const lcr::Reducer<double>& r,
                                  const std::string& prefix) {
  nlohmann::json a;
  a["study"] = "lcr_analysis";
  a["name"] = prefix + (s.name.empty() ? std::string("lcr_min_size") : s.name);
  a["reducer"] = {{"eccentricity_mm", r.eccentricity}, {"input", SideJson(r.input)}, {"output", SideJson(r.output)}};
  a["material"] = {{"youngs_modulus_GPa", s.base.material.youngs_modulus_MPa / 1000},
                   {"poisson_ratio", s.base.material.poisson_ratio}};
  a["load"] = {{"output_torque_Nm", s.output_torque_Nmm / 1000}, {"friction_coefficient", s.base.friction_coefficient}};
  nlohmann::json lim = nlohmann::json::object();
  if (std::isfinite(spec.limits.contact_stress_MPa)) lim["contact_stress_MPa"] = spec.limits.contact_stress_MPa;
  if (std::isfinite(spec.limits.roller_load_N)) lim["roller_load_N"] = spec.limits.roller_load_N;
  lim["undercut_margin_mm"] = spec.limits.undercut_margin_mm;
  lim["roller_gap_mm"] = spec.limits.roller_gap_mm;
  // The life the design was sized for, so that re-running it checks that limit too (with the speed
  // and the ratings written below).
  if (spec.limits.life_h > 0) lim["life_h"] = spec.limits.life_h;
  if (spec.lubrication) {  // the lubricated losses at the sizing's speed (written with the lives below)
    s.lubrication_blocks.WriteTo(a);
    a["load"]["input_speed_rpm"] = spec.lubrication->input_speed_rpm;
    if (spec.limits.min_efficiency > 0) lim["min_efficiency"] = spec.limits.min_efficiency;
    if (std::isfinite(spec.limits.max_oil_temperature_C)) lim["max_oil_temperature_C"] = spec.limits.max_oil_temperature_C;
  }
  a["limits"] = lim;
  a["analysis"] = {{"angle_steps", s.options.dense_steps}};
  return a;
}

}  // namespace

nlohmann::json StartLcrAnalysisStudy(const Study& s, const nlohmann::json& optimum) {
  const nlohmann::json& red = optimum.at("reducer");
  const nlohmann::json &in = red.at("input"), &out = red.at("output");
  LcrSizingSpec spec = s.base;
  spec.lobes_a = in.at("lobes").get<int>();
  spec.rollers_a = in.at("rollers").get<int>();
  spec.lobes_b = out.at("lobes").get<int>();
  spec.rollers_b = out.at("rollers").get<int>();
  // With a catalogue, the roller the optimum has (as the candidate's spec was made in Run).
  for (const CatalogueRoller& c : s.catalogue)
    if (std::abs(c.diameter_mm - in.at("roller_diameter_mm").get<double>()) <= 1e-9 * c.diameter_mm &&
        std::abs(c.length_mm - in.at("roller_length_mm").get<double>()) <= 1e-9 * c.length_mm) {
      spec.fixed_roller_diameter_mm = c.diameter_mm;
      spec.roller_length_mm = c.length_mm;
      spec.limits.roller_load_N = std::min(spec.limits.roller_load_N, c.load_limit_N);
      break;
    }
  const std::vector<double> x0 = objectives::LcrStartingPoints(spec, 1).front();
  return LcrAnalysisStudyOf(s, spec, objectives::LcrDesign(spec, x0), "start of ");
}

namespace {

// sized_assembly.svg: the sized reducer's input cam and rollers at input angle 0 (as lcr_analysis
// draws its assembly) over the start of the best combination's solve, dashed grey — the part the
// sizing made beside the one it started from.
void AddSizedAssembly(const Study& s, const nlohmann::json& best, Outputs& out) {
  const nlohmann::json start = StartLcrAnalysisStudy(s, best);
  // The geometry alone (the start study need not carry what a whole analysis reads, e.g. ratings).
  auto reducer_of = [](const nlohmann::json& study, const std::string& file) {
    const Node node = Node(&study, file, "")["reducer"];
    return ToReducer(Read<LcrRatedReducerInput>(node).Design(), node);
  };
  const lcr::Reducer<double> sized = reducer_of(best, "best_lcr_analysis.json");
  const lcr::Reducer<double> first = reducer_of(start, "the start design");
  const int points = 720;
  Drawing d = lcr_analysis::AssemblyDrawing(sized, lcr::Side::kInput, nullptr, points,
                                            s.name + ": the sized input cam and rollers over the start design");
  // The layers by their plain names (the DXF's CAM_PROFILE is "cam profile").
  auto plain = [](std::string name) {
    for (char& c : name) c = c == '_' ? ' ' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return name;
  };
  std::vector<Drawing::Layer> layers;
  for (Drawing::Layer l : lcr_analysis::AssemblyDrawing(first, lcr::Side::kInput, nullptr, points, "").layers) {
    if (l.polylines.empty() && l.circles.empty()) continue;
    l.name = "start design: " + plain(l.name);
    l.color = "#999999";
    l.dash = "6,4";
    l.stroke_width = 0.8;
    layers.push_back(l);
  }
  for (Drawing::Layer l : d.layers)
    if (!l.polylines.empty() || !l.circles.empty()) {
      l.name = "sized: " + plain(l.name);
      layers.push_back(l);
    }
  d.layers = layers;
  d.labels.clear();
  d.dimensions = {"eccentricity: start " + Format(first.eccentricity, 5) + " mm, sized " + Format(sized.eccentricity, 5) +
                      " mm",
                  "input roller diameter: start " + Format(2 * first.input.roller_radius, 5) + " mm, sized " +
                      Format(2 * sized.input.roller_radius, 5) + " mm"};
  out.Add("sized_assembly.svg", SvgDrawing(d));
}

}  // namespace

void Write(const Study& s, const Result& result, Outputs& out) {
  out.SetResult(result);
  if (result.best >= 0) {
    // The best design as an lcr_analysis study, ready for `camopt run`.
    const Candidate& best = result.candidates[result.best];
    nlohmann::json a = LcrAnalysisStudyOf(s, best.spec, *best.outcome.design, "best of ");
    if (best.spec.life && best.outcome.check) {
      // The speed or duty cycle and the ratings at the design's roller size: lcr_analysis then
      // computes the same lives (docs/life.md).
      const auto& life = *best.spec.life;
      if (life.lines.size() == 1 && life.lines[0].output_torque_Nmm == s.output_torque_Nmm) {
        a["load"]["input_speed_rpm"] = life.lines[0].input_speed_rpm;
      } else {
        nlohmann::json lines = nlohmann::json::array();
        for (const lcr::LcrDutyLine& l : life.lines)
          lines.push_back({{"output_torque_Nm", l.output_torque_Nmm / 1000.0},
                           {"input_speed_rpm", l.input_speed_rpm},
                           {"time_share", l.time_share}});
        a["duty_cycle"] = lines;
      }
      for (const auto& b : best.outcome.check->life) {
        nlohmann::json& where = b.name == "input_roller"    ? a["reducer"]["input"]
                                : b.name == "output_roller" ? a["reducer"]["output"]
                                                            : a["reducer"]["eccentric_bearing"];
        where["dynamic_rating_N"] = b.dynamic_rating_N;
        if (b.static_rating_N > 0) where["static_rating_N"] = b.static_rating_N;
        if (b.name == "eccentric_bearing") where["kind"] = b.ball ? "ball" : "roller";
      }
    }
    if (s.ratings)  // lcr_analysis solves the design's ratings (docs/ratings.md)
      a["ratings"] = {{"rated_life_h", s.ratings->rated_life_h},
                      {"rated_output_speed_rpm", s.ratings->rated_output_speed_rpm},
                      {"momentary_static_safety", s.ratings->momentary_static_safety}};
    if (s.contact3d) AddContact3DAnalysis(s, best, a);
    out.AddJson("best_lcr_analysis.json", a);
    AddSizedAssembly(s, a, out);
  }
  // The best candidate is feasible: its solve converged and the accurate model verified it
  // (Candidate::feasible); one without a check is not verifiable.
  if (result.best < 0) {
    out.SetStatus(Status::kInfeasible, result.blocking_message);
  } else if (s.robust && result.robust_best < 0) {
    out.SetStatus(Status::kInfeasible, "no design meets the limits across the tolerances (see result.json robust.candidates)");
  } else {
    const Candidate& best = result.candidates[result.best];
    out.SetStatus(SizingStatus(true, best.verification && best.verification->ran,
                               best.verification && best.verification->verified(), best.outcome.converged),
                  best.verification ? "" : "the best design was not checked by the accurate model");
  }

  // One row per feasible candidate (an infeasible one has no outer diameter to show).
  const bool loss = MinimisesLoss(s);
  Table t;
  std::vector<double> ma, mb, dr, od, ecc, feas, pl;
  for (const auto& c : result.candidates) {
    if (!c.feasible()) continue;
    const lcr::Reducer<double>& d = *c.outcome.design;
    ma.push_back(c.combo.lobes_a);
    mb.push_back(c.combo.lobes_b);
    dr.push_back(2 * d.input.roller_radius);
    od.push_back(lcr::OuterDiameter(d));
    ecc.push_back(d.eccentricity);
    feas.push_back(1.0);
    pl.push_back(c.outcome.check->lubricated_loss_W);
  }
  t.Add("input_lobes", ma);
  t.Add("output_lobes", mb);
  t.Add("roller_diameter_mm", dr);
  t.Add("eccentricity_mm", ecc);
  t.Add("outer_diameter_mm", od);
  if (loss) t.Add("power_loss_W", pl);
  t.Add("feasible", feas);
  out.Add("candidates.csv", ToCsv(t));
  // The answer at a glance: outer diameter of each feasible lobe combination, the smallest marked.
  PlotOptions po{loss ? "Outer diameter of each feasible lobe combination's least-loss design"
                      : "Smallest outer diameter of each feasible lobe combination",
                 "input cam lobes [-]", "outer diameter [mm]"};
  if (result.best >= 0) {
    const Candidate& best = result.candidates[result.best];
    po.points = {{(loss ? "least loss: " : "smallest: ") + sizing::LobeCombinationName(best.combo), double(best.combo.lobes_a),
                  lcr::OuterDiameter(*best.outcome.design)}};
  }
  // Candidates pruned by the branch and bound (3D): their lower bounds, a second series.
  std::vector<double> pruned_lobes, pruned_bound;
  for (const auto& c : result.candidates)
    if (c.pruned()) {
      pruned_lobes.push_back(c.combo.lobes_a);
      pruned_bound.push_back(c.outcome3d->paused->lower_bound_mm);
    }
  std::vector<Series> series = {{"feasible candidates", ma, od, {}, SeriesStyle::kMarkers}};
  if (!pruned_lobes.empty())
    series.push_back({"pruned candidates: lower bound", pruned_lobes, pruned_bound, {}, SeriesStyle::kMarkers});
  out.Add("outer_diameter.svg", SvgLinePlot(series, po));
}

std::string Summary(const Study& s, const Result& result) {
  std::ostringstream m;
  char buf[200];
  if (result.best < 0) return "";
  const Candidate& b = result.candidates[result.best];
  const objectives::LcrDenseCheck& k = *b.outcome.check;
  if (MinimisesLoss(s))
    std::snprintf(buf, sizeof buf,
                  "lcr_min_size: minimised the lubricated loss: best %s, loss %.4g W (efficiency %.5f), outer "
                  "diameter %.3f mm (%zu candidates, %.2f s)\n",
                  sizing::LobeCombinationName(b.combo).c_str(), k.lubricated_loss_W, k.mean_efficiency, k.outer_diameter_mm,
                  result.candidates.size(), result.seconds);
  else
    std::snprintf(buf, sizeof buf,
                  "lcr_min_size: minimised the outer diameter: best %s, outer diameter %.3f mm (%zu candidates, "
                  "%.2f s)\n",
                  sizing::LobeCombinationName(b.combo).c_str(), k.outer_diameter_mm, result.candidates.size(), result.seconds);
  m << buf;
  for (const std::string& line : LimitCosts(s, result)) m << "lcr_min_size: " << line << "\n";
  return m.str();
}

namespace {

// The declared input of a study, for the knobs and the estimate below, which run before Parse.
Input ReadInput(const nlohmann::json& study, const std::string& file) { return Read<Input>(Node(&study, file, "")); }

// Fidelity for `camopt run --convergence` (studies/convergence.h): the optimizer's tolerance and
// the angle samples of the smooth phase (the reported numbers come from the 3600-angle check);
// with the finite-length contact also the slice count of the slices model, which sets the 3D
// stress rows and the check (an edge peak of straight rollers grows with it).
Fidelity Knobs(const nlohmann::json& study) {
  const Input in = ReadInput(study, "");
  const Input::Optimizer defaults;
  Fidelity f;
  f.knobs.push_back({"optimizer_tolerance", {"/optimizer/tolerance"}, defaults.tolerance, 0.1, false, 0,
                     "relative optimality / step tolerance of each start"});
  f.knobs.push_back({"samples_per_period", {"/optimizer/samples_per_period"}, defaults.samples_per_period, 2, true, 0,
                     "angle samples per load period in the optimizer's problem"});
  if (in.contact && in.contact->model && *in.contact->model != "line")
    f.knobs.push_back({"contact_slices", {"/contact/slices"}, LcrContactOptionsInput{}.slices, 2, true, 0,
                       "slices along the roller (the slices model of the stress rows and the check)"});
  f.headlines = {"/best/outer_diameter_mm", "/best/eccentricity_mm", "/best/max_contact_stress_MPa",
                 "/best/max_roller_force_N", "/best/mean_efficiency"};
  if (in.objective == "efficiency") f.headlines.push_back("/best/power_loss_W");
  return f;
}

// The work limit (studies/work_limits.h), in local optimizations of the line model (24 samples per
// load period, ~30 ms) ≤ 2e4: lobe counts × differences × catalogue rollers × starts, the 3D polish
// and verification, the duty cycle's lines, the search for the limit that would fit, the robust
// Monte-Carlo.
WorkEstimate EstimateWork(const nlohmann::json& study, const std::string& file, double factor) {
  const Input in = ReadInput(study, file);
  const double lobes = in.search.max_lobes;
  const double n_diffs = double(in.search.roller_lobe_difference.size());
  const double starts = in.optimizer.starts;
  double rollers = 1;
  const auto* list = in.roller_catalogue ? std::get_if<std::vector<CatalogueRollerInput>>(&*in.roller_catalogue) : nullptr;
  const auto* cat = in.roller_catalogue ? std::get_if<CatalogueFileInput>(&*in.roller_catalogue) : nullptr;
  if (list) rollers = std::max<double>(1, double(list->size()));
  if (cat) {
    // The catalogue file is checked here (regular file, size cap) so that /dev/zero or a huge
    // file is refused with the JSON path that names it, before any work.
    std::filesystem::path p(cat->file);
    if (p.is_relative()) p = std::filesystem::path(file).parent_path() / p;
    std::error_code ec;
    // A missing file is the kind's to report (after its own checks of the study).
    if (std::filesystem::exists(p, ec)) {
      try {
        const nlohmann::json loaded = LoadStudyFile(p.string());
        rollers = std::max<double>(1, loaded.is_array() || loaded.is_object() ? double(loaded.size()) : 0.0);
      } catch (const StudyError& e) {
        throw StudyError(file + ": /roller_catalogue/file: " + e.what());
      }
    }
  }
  // A local optimization of the line model (24 samples per load period) is the unit (~30 ms); its
  // cost grows with the samples. Under the finite-length contact each candidate adds the 3D polish
  // (about 30 units at 20 slices, a slices solve costing ∝ N³) and the best design's verification
  // (half_space solves on the grid and on twice it each way: ≈ 40 units at 48×128).
  const double samples = in.optimizer.samples_per_period;
  const double per_start = 0.5 + 0.5 * samples / 24.0;
  const double combos = lobes * n_diffs * rollers;
  std::vector<WorkTerm> terms = {{combos * starts * per_start, "/search/max_lobes",
                                  WorkNumber(lobes) + " lobe counts × " + WorkNumber(n_diffs) +
                                      " roller-lobe differences × " + WorkNumber(rollers) + " catalogue rollers × " +
                                      WorkNumber(starts) + " starts × " + WorkNumber(per_start) +
                                      " (samples per period)"}};
  const bool three_d = (in.contact && in.contact->model && *in.contact->model != "line") || in.fixed.crowning;
  if (three_d) {
    const double slices = in.contact ? in.contact->slices : LcrContactOptionsInput{}.slices;
    terms.push_back({combos * 30 * std::pow(slices / 20.0, 3), "/contact/slices",
                     WorkNumber(combos) + " candidates × 3D polish with " + WorkNumber(slices) + " slices"});
    const std::array<int, 2> g = in.contact.value_or(LcrContactOptionsInput{}).grid;
    const double cells = double(g[0]) * g[1];
    terms.push_back({40 * 5 * cells / (48.0 * 128.0), "/contact/grid",
                     "half_space verification on " + WorkNumber(cells) + " cells and four times as many"});
  }
  // Bearing lives (docs/life.md): every dense check computes each rated bearing's life per duty
  // line, one force analysis per angle of its load period (about a third of a unit per line and
  // polish round of a start; a study's lines multiply it).
  const double duty_lines = in.duty_cycle ? double(in.duty_cycle->size()) : 0.0;
  if (duty_lines > 1)
    terms.push_back({combos * starts * per_start * duty_lines, "/duty_cycle",
                     WorkNumber(combos) + " candidates × " + WorkNumber(starts) + " starts × " +
                         WorkNumber(duty_lines) +
                         " duty-cycle lines (each line's bearing lives in every dense check)"});
  // When nothing fits, the message names the limit that would fit (sizing::LimitToFit: 2-4 solves
  // of the closest combination from its closest point's value; 13 at most by doubling, about 17 when
  // that value is far off), each up to 8 polish rounds of an infeasible problem, measured at about 4
  // units a round and start; a converged result prices its binding limits with fewer re-solves than
  // that. Counted always (13): whether anything fits is not known before the search.
  terms.push_back({13 * 8 * 4 * starts * per_start, "/limits",
                   "if nothing fits: up to 13 solves × 8 polish rounds × " + WorkNumber(starts) +
                       " starts to find the limit that would fit"});
  if (in.robust) {
    // Two Monte-Carlo checks (robust and nominal best): a sample of 720 angles ≈ 36 ms ≈ 1 unit.
    const Input::MonteCarlo mc = in.monte_carlo.value_or(Input::MonteCarlo{});
    const double mc_samples = mc.samples.value_or(200), mc_steps = mc.angle_steps.value_or(720);
    terms.push_back({2 * mc_samples * mc_steps / 720.0, "/monte_carlo/samples",
                     "2 × " + WorkNumber(mc_samples) + " Monte-Carlo samples × " + WorkNumber(mc_steps) + " angles"});
  }
  return LargestTerm(terms, 2e4 * factor, "local optimizations", 1000);
}

// The studio's start design: the start of the lobe combination the run chose (its optimum's counts)
// as an lcr_analysis study.
nlohmann::json StartStudy(const Node& root, const nlohmann::json& optimum) {
  const Study s = Parse(root);
  if (!optimum.is_object()) return "the start depends on the lobe combination the run chooses: run the study";
  try {
    return StartLcrAnalysisStudy(s, optimum);
  } catch (const nlohmann::json::exception&) {
    return "the optimum's study has no reducer counts";
  }
}

CAMOPT_REGISTER_KIND(Kind<Input, Result, Study>{
    .name = "lcr_min_size",
    .title = "camopt study: smallest lobe cam reducer for a ratio and torque",
    .run = Run, .parse = Parse, .write = Write, .summary = Summary, .knobs = Knobs, .estimate = EstimateWork,
    .report = std::vector<Headline>{
        // What was minimised: result.json's "objective" is written for the efficiency objective only.
        {"smallest outer diameter", "/best/outer_diameter_mm", "mm", "", NAN, true, "", "", "/objective"},
        {"objective", "/objective", ""},
        {"outer diameter", "/best/outer_diameter_mm", "mm", "study:/limits/max_outer_diameter_mm", NAN, true, "",
         "/objective"},
        {"input cam lobes", "/best/input/lobes", ""},
        {"output cam lobes", "/best/output/lobes", ""},
        {"eccentricity", "/best/eccentricity_mm", "mm"},
        {"roller diameter", "/best/input/roller_diameter_mm", "mm"},
        {"largest contact stress", "/best/max_contact_stress_MPa", "MPa", "study:/limits/contact_stress_MPa"},
        {"largest roller force", "/best/max_roller_force_N", "N", "study:/limits/roller_load_N"},
        {"undercut margin", "/best/undercut_margin_mm", "mm", "study:/limits/undercut_margin_mm", 0.0, false},
        {"gap between rollers", "/best/roller_gap_mm", "mm", "study:/limits/roller_gap_mm", 0.0, false},
        {"mean efficiency", "/best/mean_efficiency", "", "study:/limits/min_efficiency", NAN, false},
        {"oil temperature (lubricated)", "/best/oil_temperature_C", "°C", "study:/limits/max_oil_temperature_C", NAN, true},
        {"lubricated loss", "/best/power_loss_W", "W"},
        {"shortest bearing life L10h", "/best/life/shortest_L10h", "h", "study:/limits/life_h", NAN, false},
        {"bearing life L10h at the rated torque and speed", "/best/ratings/L10h_at_required_torque", "h",
         "study:/ratings/rated_life_h", NAN, false},
        {"rated torque (the rigid law's lives)", "/best/ratings/rated_torque_Nm", "N m", "study:/ratings/rated_torque_Nm",
         NAN, false},
        {"static safety s0 at the momentary torque", "/best/ratings/s0_at_required_momentary_torque", "",
         "/best/ratings/momentary_static_safety", NAN, false},
        {"momentary torque (the rigid law's static loads)", "/best/ratings/momentary_torque_Nm", "N m",
         "study:/ratings/momentary_torque_Nm", NAN, false},
        {"binding limits", "/best/binding_names", ""},
        {"what the binding limits cost", "/best/limit_costs", ""},
        {"limit costs", "/best/limit_sensitivity_note", ""},
    },
    .asked = std::vector<AskedBlock>{
        {{"/duty_cycle", "/load/input_speed_rpm"}, "/best/life", "the sized design's bearing lives"},
        {{"/robust"}, "/robust", "the robust sizing"},
        {{"/contact"}, "/best/contact", "the sized design's 3D roller contact"},
        {{"/lubricant"}, "/best/oil_temperature_C", "the sized design's lubricated losses",
         {}, "/best/lubrication_error"},
    },
    .init_example = "lcr_min_size",
    .sizing_of = "lcr_analysis",
    .start_study = StartStudy});
}  // namespace

}  // namespace camopt::studies::lcr_min_size
