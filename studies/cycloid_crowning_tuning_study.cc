// Study kind "cycloid_crowning_tuning" (studies/cycloid_crowning_tuning_study.h): parse, scan,
// tune through sizing/cycloid_crowning_tuning.h (the problems of objectives/cycloid_crowning.h),
// verify on the accurate model, write.
#include "studies/cycloid_crowning_tuning_study.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "optimizers/solver.h"
#include "sizing/cycloid_crowning_tuning.h"
#include "studies/cycloid_study_common.h"
#include "studies/backend_input.h"
#include "studies/kind.h"
#include "studies/report.h"
#include "studies/verification_json.h"
#include "studies/work_limits.h"
#include "studies/writers.h"

namespace camopt::studies::cycloid_crowning_tuning {

using objectives::CrowningEvaluation;

namespace {

using ojson = nlohmann::ordered_json;

// The fields of "tuning", "optimizer" and "crowning" each form takes.
const std::set<std::string> kShorthandTuning = {"coefficient_mm",  "effective_length_mm", "reference_coefficient_mm",
                                                "curve_points",    "max_evaluations",     "edge_margin_um"};
const std::set<std::string> kGeneralTuning = {"reference_coefficient_mm", "curve_points",
                                              "max_evaluations",          "edge_margin_um",
                                              "softmax_temperature_MPa",  "max_lte_peak_to_peak_arcsec",
                                              "min_unloaded_te_arcsec"};
const std::set<std::string> kShorthandCrowning = {"type", "effective_length_mm", "end_drop_mm", "flat_length_mm"};

// What the form (the shorthand, or "variables" given) allows in the blocks both forms share, with
// the form's own messages; runs before the declaration reads the blocks (its bounds hold for both
// forms: the shorthand's are tighter).
void CheckForm(const Node& root) {
  if (root.Has("variables")) {
    const Node v = root["variables"];
    if (!v.json().is_object() || v.json().empty()) v.Fail("an object of variables {\"field\": [lo, hi], ...}");
    const std::vector<std::string> known = objectives::TuningVariableNames();
    v.CheckKnownFields(std::set<std::string>(known.begin(), known.end()));
    if (root.Has("tuning")) root["tuning"].CheckKnownFields(kGeneralTuning);
    return;
  }
  if (root.Has("optimizer")) {
    const Node o = root["optimizer"];
    o.CheckKnownFields({"backend", "max_evaluations"});
    if (o["backend"].String() != "cobyla")
      o["backend"].Fail("\"cobyla\" (the tuning.coefficient_mm shorthand is value-only; use \"variables\" for gradients)");
  }
  if (root.Has("tuning")) {
    const Node t = root["tuning"];
    t.CheckKnownFields(kShorthandTuning);
    if (t.Has("curve_points")) t["curve_points"].Integer(2);
  }
  if (root.Has("crowning")) {
    const Node c = root["crowning"];
    c.CheckKnownFields(kShorthandCrowning);
    if (c["type"].String() != "logarithmic") c["type"].Fail("\"logarithmic\"");
    if (c.Has("effective_length_mm")) c["effective_length_mm"].Positive();
  }
}

// A declared range [lo, hi] as Node::Range reads it (lo <= hi).
std::pair<double, double> RangeOf(const Node& n, const std::array<double, 2>& r) {
  if (!(r[0] <= r[1])) n.Fail("[lower, upper] with lower <= upper");
  return {r[0], r[1]};
}

const std::optional<std::array<double, 2>>& VariableRange(const Input::Variables& v, const std::string& name) {
  if (name == "coefficient_mm") return v.coefficient_mm;
  if (name == "effective_length_mm") return v.effective_length_mm;
  if (name == "end_drop_mm") return v.end_drop_mm;
  if (name == "flat_length_mm") return v.flat_length_mm;
  if (name == "radius_mm") return v.radius_mm;
  if (name == "delta_position_um") return v.delta_position_um;
  return v.delta_radius_um;
}

std::optional<double> CrowningStart(const std::optional<cycloid_common::CrowningStartInput>& c,
                                    const std::string& name) {
  if (!c) return std::nullopt;
  if (name == "coefficient_mm") return c->coefficient_mm;
  if (name == "effective_length_mm") return c->effective_length_mm;
  if (name == "end_drop_mm") return c->end_drop_mm;
  if (name == "flat_length_mm") return c->flat_length_mm;
  if (name == "radius_mm") return c->radius_mm;
  return std::nullopt;
}

// "analysis": the contact grid and the crank-angle sampling, the same for both study forms.
void ParseAnalysis(const Input::Analysis& a, Study& s) {
  if (a.grid) s.options.profile_cells = (*a.grid)[0], s.options.axial_cells = (*a.grid)[1];
  s.crank_angles_per_mesh_period = a.crank_angles_per_mesh_period;
}

// The paper's coefficient the tuning is compared with (eq. 7, L = B) must be a valid crowning.
void CheckReferenceCoefficient(const Node& root, double coefficient_mm, double face_width_mm) {
  cycloid::Crowning c;
  c.type = cycloid::CrowningType::kLogarithmic;
  c.coefficient_mm = coefficient_mm;
  if (const std::string why = cycloid::CheckCrowning(c, face_width_mm); !why.empty())
    root["tuning"]["reference_coefficient_mm"].FailWith(why);
}

// The general form: the variables (their ranges against the crowning type, the face width and the
// modifications' sign; every corner of the box a valid crowning and a feasible drive), the start
// crowning, the optimizer and the general form's tuning settings.
void ParseJoint(const Node& root, const Input& in, Study& s) {
  s.joint = true;
  const Node v = root["variables"];
  std::set<std::string> names;
  for (const auto& [key, _] : v.json().items()) names.insert(key);
  s.crowning = cycloid_common::MakeCrowningStart(root, in.crowning, names);
  // The variables in a fixed order (TuningVariableNames), whatever the file's order.
  for (const std::string& name : objectives::TuningVariableNames()) {
    const std::optional<std::array<double, 2>>& range = VariableRange(*in.variables, name);
    if (!range) continue;
    const Node r = v[name];
    if (const std::string why = objectives::TuningVariableAllowed(name, s.crowning.type); !why.empty())
      r.FailWith("cannot be tuned with this crowning: " + why);
    const auto [lo, hi] = RangeOf(r, *range);
    if (!(hi > lo)) r.Fail("a range [lo, hi] with lo < hi");
    objectives::Variable var;
    var.name = name;
    var.lower = lo;
    var.upper = hi;
    var.scale = hi - lo;
    // Start: the field's value in "crowning"/"modification" when given, else the range's middle.
    double start = 0.5 * (lo + hi);
    const bool modification = name == "delta_position_um" || name == "delta_radius_um";
    if (modification) {
      start = 1e3 * (name == "delta_position_um" ? s.drive.delta_position_mm : s.drive.delta_radius_mm);
    } else if (const std::optional<double> given = CrowningStart(in.crowning, name)) {
      start = *given;
    }
    var.initial = std::clamp(start, lo, hi);
    if (name == "coefficient_mm" && lo < 0) r.Fail("a range with lo >= 0");
    if (name == "effective_length_mm" && lo < s.drive.face_width_mm) r.Fail("a range with lo >= the face width");
    if (name == "end_drop_mm" && !(lo > 0)) r.Fail("a range with lo > 0 (0 means an unbounded drop)");
    if ((name == "flat_length_mm" || name == "radius_mm") && lo < 0) r.Fail("a range with lo >= 0");
    if (modification && hi > 0) r.Fail("a range with hi <= 0 (a positive modification interferes)");
    s.variables.push_back(var);
  }
  // Every corner of the box must give a valid crowning and a feasible drive (else an evaluation
  // inside it could fail).
  for (size_t corner = 0; corner < (size_t(1) << s.variables.size()); ++corner) {
    cycloid::Drive d = s.drive;
    cycloid::Crowning c = s.crowning;
    for (size_t j = 0; j < s.variables.size(); ++j) {
      const objectives::Variable& var = s.variables[j];
      const double x = (corner >> j) & 1 ? var.upper : var.lower;
      if (var.name == "delta_position_um") d.delta_position_mm = 1e-3 * x;
      if (var.name == "delta_radius_um") d.delta_radius_mm = 1e-3 * x;
      if (var.name == "coefficient_mm") c.coefficient_mm = x;
      if (var.name == "effective_length_mm") c.effective_length_mm = x;
      if (var.name == "end_drop_mm") c.end_drop_mm = x;
      if (var.name == "flat_length_mm") c.flat_length_mm = x;
      if (var.name == "radius_mm") c.radius_mm = x;
    }
    if (const auto issues = cycloid::CheckDrive(d); !issues.empty())
      v.FailWith("a corner of the variables' ranges gives an infeasible drive: " + issues.front().message);
    if (const std::string why = cycloid::CheckCrowning(c, s.drive.face_width_mm); !why.empty())
      v.FailWith("a corner of the variables' ranges gives an invalid crowning: " + why);
  }
  {
    cycloid::Crowning c = s.crowning;
    for (const auto& var : s.variables) {
      if (var.name == "coefficient_mm") c.coefficient_mm = var.initial;
      if (var.name == "effective_length_mm") c.effective_length_mm = var.initial;
      if (var.name == "end_drop_mm") c.end_drop_mm = var.initial;
      if (var.name == "flat_length_mm") c.flat_length_mm = var.initial;
      if (var.name == "radius_mm") c.radius_mm = var.initial;
    }
    if (const std::string why = cycloid::CheckCrowning(c, s.drive.face_width_mm); !why.empty())
      root["crowning"].FailWith(why);
    s.crowning = c;
  }
  const Input::Tuning t = in.tuning.value_or(Input::Tuning{});
  if (in.tuning) CheckReferenceCoefficient(root, t.reference_coefficient_mm, s.drive.face_width_mm);
  s.backend = in.optimizer && in.optimizer->backend ? *in.optimizer->backend : "ipopt";
  // optimizer.max_evaluations wins over tuning.max_evaluations when both are given.
  s.max_evaluations = in.optimizer && in.optimizer->max_evaluations ? *in.optimizer->max_evaluations
                                                                     : t.max_evaluations;
  s.length_lo_mm = s.length_hi_mm = s.drive.face_width_mm;
  s.reference_coefficient_mm = t.reference_coefficient_mm;
  s.curve_points = t.curve_points;
  if (s.curve_points == 1) root["tuning"]["curve_points"].Fail("0 or at least 2 points");
  s.required_edge_margin_um = t.edge_margin_um;
  s.temperature_MPa = t.softmax_temperature_MPa.value_or(kDefaultSoftmaxTemperatureMPa);
  s.max_lte_peak_to_peak_arcsec = t.max_lte_peak_to_peak_arcsec.value_or(kInf);
  s.min_unloaded_te_arcsec = t.min_unloaded_te_arcsec.value_or(0.0);
}

// The shorthand: "tuning.coefficient_mm" (and optionally effective_length_mm) with COBYLA; the
// optional "crowning" holds the tuned logarithmic crowning's fixed fields.
void ParseShorthand(const Node& root, const Input& in, Study& s) {
  if (!in.tuning) (void)root["tuning"];  // "missing required field"
  const Input::Tuning& t = *in.tuning;
  const Node tuning = root["tuning"];
  if (!t.coefficient_mm) (void)tuning["coefficient_mm"];
  std::tie(s.coefficient_lo_mm, s.coefficient_hi_mm) = RangeOf(tuning["coefficient_mm"], *t.coefficient_mm);
  if (s.coefficient_lo_mm < 0 || !(s.coefficient_hi_mm > s.coefficient_lo_mm))
    tuning["coefficient_mm"].Fail("a range [lo, hi] with 0 <= lo < hi");
  s.tune_length = bool(t.effective_length_mm);
  s.length_lo_mm = s.length_hi_mm = s.drive.face_width_mm;
  if (s.tune_length) {
    std::tie(s.length_lo_mm, s.length_hi_mm) = RangeOf(tuning["effective_length_mm"], *t.effective_length_mm);
    if (s.length_lo_mm < s.drive.face_width_mm)
      tuning["effective_length_mm"].Fail("a range with lo >= the face width");
    s.tune_length = s.length_hi_mm > s.length_lo_mm;
  }
  // "crowning": the logarithmic form whose coefficient is tuned; its other fields stay fixed.
  if (in.crowning) {
    const Node c = root["crowning"];
    s.shape.type = cycloid::CrowningType::kLogarithmic;
    s.shape.end_drop_mm = in.crowning->end_drop_mm.value_or(0.0);
    s.shape.flat_length_mm = in.crowning->flat_length_mm.value_or(0.0);
    if (in.crowning->effective_length_mm) {
      if (t.effective_length_mm)
        c["effective_length_mm"].Fail("no value here when tuning.effective_length_mm is given");
      s.length_lo_mm = s.length_hi_mm = *in.crowning->effective_length_mm;
      if (s.length_lo_mm < s.drive.face_width_mm) c["effective_length_mm"].Fail("a length >= the face width");
    }
    s.shape.effective_length_mm = s.length_lo_mm;
    if (const std::string why = cycloid::CheckCrowning(s.shape, s.drive.face_width_mm); !why.empty())
      c.FailWith(why);
  }
  // Every corner of the ranges the tuning may try must be a valid crowning (else an evaluation
  // inside them could fail), and so must the reference it is compared with.
  {
    cycloid::Crowning probe = s.shape;
    probe.type = cycloid::CrowningType::kLogarithmic;
    // (CheckCrowning's bounds are one per field: the corners of each range alone suffice.)
    probe.effective_length_mm = s.length_lo_mm;
    for (const double coefficient : {s.coefficient_lo_mm, s.coefficient_hi_mm}) {
      probe.coefficient_mm = coefficient;
      if (const std::string why = cycloid::CheckCrowning(probe, s.drive.face_width_mm); !why.empty())
        tuning["coefficient_mm"].FailWith("an end of the range gives an invalid crowning: " + why);
    }
    probe.coefficient_mm = s.coefficient_lo_mm;
    for (const double length : {s.length_lo_mm, s.length_hi_mm}) {
      probe.effective_length_mm = length;
      if (const std::string why = cycloid::CheckCrowning(probe, s.drive.face_width_mm); !why.empty() && s.tune_length)
        tuning["effective_length_mm"].FailWith("an end of the range gives an invalid crowning: " + why);
    }
  }
  CheckReferenceCoefficient(root, t.reference_coefficient_mm, s.drive.face_width_mm);
  s.reference_coefficient_mm = t.reference_coefficient_mm;
  s.curve_points = t.curve_points;
  // optimizer.max_evaluations wins over tuning.max_evaluations, as in the general form.
  s.max_evaluations = in.optimizer && in.optimizer->max_evaluations ? *in.optimizer->max_evaluations
                                                                     : t.max_evaluations;
  s.required_edge_margin_um = t.edge_margin_um;
}

}  // namespace

Input ReadInput(const Node& root) {
  archive_detail::NameCollector names;
  Input{}.Serialize(&names);
  root.CheckKnownFields(names.names);
  CheckForm(root);
  return Read<Input>(root);
}

Study Parse(const Node& root) {
  const Input in = ReadInput(root);
  Study s;
  s.name = in.name;
  s.drive = cycloid_common::MakeDrive(root, in.drive, in.modification);
  s.material = in.material.ToMaterial();
  if (in.load.max_torque_Nm < in.load.design_torque_Nm) root["load"]["max_torque_Nm"].Fail("a torque >= design_torque_Nm");
  s.design_torque_Nm = in.load.design_torque_Nm;
  s.max_torque_Nm = in.load.max_torque_Nm;
  // The tuned design's bearing lives (docs/life.md, "Cycloid"); the one-line form runs at the
  // design torque.
  s.life = cycloid_common::ParseLife(root, in, s.drive, s.design_torque_Nm * 1000.0);
  if (in.variables) ParseJoint(root, in, s);
  else ParseShorthand(root, in, s);
  ParseAnalysis(in.analysis, s);
  return s;
}

ojson Input::Variables::SchemaRules() {
  // The bound of one end of a range (prefixItems): lower >= 0 for f, the flat and the radius,
  // lower > 0 for the end drop, upper <= 0 for the modifications.
  const ojson lower_non_negative = ojson::array({{{"minimum", 0}}});
  const ojson upper_non_positive =
      ojson::array({ojson::object(), {{"maximum", 0}, {"description", "hi <= 0 (a positive modification interferes)"}}});
  ojson p = ojson::object();
  p["coefficient_mm"]["prefixItems"] = lower_non_negative;
  p["end_drop_mm"]["prefixItems"] =
      ojson::array({{{"exclusiveMinimum", 0}, {"description", "lo > 0 (0 means an unbounded drop)"}}});
  p["flat_length_mm"]["prefixItems"] = lower_non_negative;
  p["radius_mm"]["prefixItems"] = lower_non_negative;
  p["delta_position_um"]["prefixItems"] = upper_non_positive;
  p["delta_radius_um"]["prefixItems"] = upper_non_positive;
  return {{"minProperties", 1}, {"allOf", ojson::array({{{"properties", p}}})}};
}

ojson Input::SchemaRules() {
  // The general form ("variables" given): no shorthand range in tuning, curve_points 0 or >= 2; a
  // crowning variable needs the crowning type that has it, and each type's fields are given in
  // "crowning" or are variables.
  ojson general_rules = ojson::array();
  const std::vector<std::pair<const char*, std::vector<const char*>>> variable_types = {
      {"coefficient_mm", {"logarithmic"}},
      {"effective_length_mm", {"logarithmic"}},
      {"end_drop_mm", {"logarithmic"}},
      {"flat_length_mm", {"logarithmic", "partial"}},
      {"radius_mm", {"full", "partial"}}};
  for (const auto& [name, types] : variable_types)
    general_rules.push_back(
        {{"if", {{"properties", {{"variables", {{"required", {name}}}}}}}},
         {"then", {{"required", {"crowning"}}, {"properties", {{"crowning", {{"properties", {{"type", {{"enum", types}}}}}}}}}}}});
  const std::vector<std::pair<const char*, const char*>> type_fields = {
      {"full", "radius_mm"}, {"partial", "radius_mm"}, {"partial", "flat_length_mm"}, {"logarithmic", "coefficient_mm"}};
  for (const auto& [type, field] : type_fields)
    general_rules.push_back(
        {{"if", {{"required", {"crowning"}}, {"properties", {{"crowning", {{"properties", {{"type", {{"enum", {type}}}}}}}}}}}},
         {"then", {{"anyOf", {{{"properties", {{"crowning", {{"required", {field}}}}}}},
                              {{"properties", {{"variables", {{"required", {field}}}}}}}}}}}});
  const ojson general = {
      {"required", {"variables"}},
      {"properties",
       {{"tuning",
         {{"properties",
           {{"coefficient_mm", false},
            {"effective_length_mm", false},
            {"curve_points", {{"not", {{"const", 1}}}, {"description", "0 (no curve) or at least 2"}}}}}}}}},
      {"allOf", general_rules}};
  // The shorthand: tuning with coefficient_mm (lower >= 0) and the shorthand's settings only,
  // curve_points >= 2; optimizer.backend "cobyla" given; the crowning logarithmic with its fixed
  // fields only (effective_length_mm > 0, not with tuning.effective_length_mm).
  const ojson shorthand = {
      {"required", {"tuning"}},
      {"not", {{"required", {"variables"}}}},
      {"properties",
       {{"tuning",
         {{"required", {"coefficient_mm"}},
          {"properties",
           {{"coefficient_mm", {{"items", {{"minimum", 0}}}}},
            {"effective_length_mm", {{"items", {{"exclusiveMinimum", 0}}}}},
            {"curve_points", {{"minimum", 2}}},
            {"softmax_temperature_MPa", false},
            {"max_lte_peak_to_peak_arcsec", false},
            {"min_unloaded_te_arcsec", false}}}}},
        {"optimizer", {{"required", {"backend"}}, {"properties", {{"backend", {{"const", "cobyla"}}}}}}},
        {"crowning",
         {{"properties",
           {{"type", {{"const", "logarithmic"}}},
            {"effective_length_mm",
             {{"exclusiveMinimum", 0}, {"description", ">= the face width; not with tuning.effective_length_mm"}}},
            {"coefficient_mm", false},
            {"radius_mm", false}}}}}}},
      {"allOf",
       {{{"if", {{"properties", {{"crowning", {{"required", {"effective_length_mm"}}}}}}, {"required", {"crowning"}}}},
         {"then", {{"properties", {{"tuning", {{"not", {{"required", {"effective_length_mm"}}}}}}}}}}}}}};
  // A life (a speed or a duty cycle) needs the crank bearing and the output mechanism; one speed form.
  const ojson life = ojson::parse(R"([
    {"if": {"anyOf": [{"required": ["duty_cycle"]},
                      {"required": ["load"], "properties": {"load": {"required": ["input_speed_rpm"]}}}]},
     "then": {"required": ["crank_bearing", "output_mechanism"]}},
    {"if": {"required": ["duty_cycle"]},
     "then": {"properties": {"load": {"not": {"required": ["input_speed_rpm"]}}}}}])");
  return {{"oneOf", {general, shorthand}}, {"allOf", life}};
}

namespace {

// The accurate model of the verified-optimum contract (objectives/verification.h): the tuned
// design at twice the crank angles (the study's N and the same shifted by half a step) on a grid
// with twice the cells each way. Its own error is estimated by the refinement: |value(2N) −
// value(N)| on the refined grid (crank angles) plus |value(N) on the refined grid − value(N) on
// the study's grid| (the fast model's own value at the same angles). No order is assumed.
struct Accurate {
  double stress_MPa = 0, stress_error_MPa = 0;
  double margin_um = 0, margin_error_um = 0;
  double lte_peak_to_peak_arcsec = 0;
  std::string model;  ///< in words, with its settings
};

Accurate AccurateEvaluation(const Study& s, const cycloid::Drive& drive, const cycloid::Crowning& crowning,
                            double fast_stress_MPa, double fast_margin_um) {
  const sizing::StageClock::Scope stage("verification");  // `camopt run --timings`
  cycloid::LoadedOptions fine = s.options;
  fine.profile_cells = 2 * s.options.profile_cells;
  fine.axial_cells = 2 * s.options.axial_cells;
  fine.crank_slope = false;  // no gear ratio in the tuning
  const int n = s.crank_angles_per_mesh_period;
  const double period = 2.0 * kPi / s.drive.rollers;
  // The study's N angles and the N shifted by half a step, interleaved (each solve warm-started
  // from its half-step neighbour): value(N) is that one run's on the study's angles (`base`).
  std::vector<double> both;
  std::vector<size_t> base;
  for (double a : cycloid::UniformCrankAngles(n, period)) {
    base.push_back(both.size());
    both.push_back(a);
    both.push_back(a + 0.5 * period / n);
  }
  objectives::CycloidTuningModel on_both(drive, crowning, s.material, fine, s.design_torque_Nm * 1000.0,
                                         s.max_torque_Nm * 1000.0, both, {}, s.temperature_MPa);
  const objectives::TuningEvaluation a = on_both.Evaluate({}, false);
  const objectives::TuningEvaluation b = on_both.EvaluatedOn(base);
  Accurate r;
  r.stress_MPa = a.stress_MPa;
  r.margin_um = a.edge_margin_um;
  r.lte_peak_to_peak_arcsec = a.lte_peak_to_peak_arcsec;
  r.stress_error_MPa = std::abs(a.stress_MPa - b.stress_MPa) + std::abs(b.stress_MPa - fast_stress_MPa);
  r.margin_error_um = std::abs(a.edge_margin_um - b.edge_margin_um) + std::abs(b.edge_margin_um - fast_margin_um);
  r.model = "half-space LTCA at " + std::to_string(2 * n) + " crank angles per mesh period (the study's " +
            std::to_string(n) + " and the same shifted by half a step) on a " + std::to_string(fine.profile_cells) +
            " x " + std::to_string(fine.axial_cells) + " grid; error: the difference to " + std::to_string(n) +
            " angles plus the difference of the " + std::to_string(fine.profile_cells) + " x " +
            std::to_string(fine.axial_cells) + " and the study's grid at " + std::to_string(n) + " angles";
  return r;
}

// The run's `status` sentence from the optimizer's status at its final point (docs/studies.md):
// the same words for both forms. It speaks of the optimizer's end point; `feasible` speaks of the
// reported design (the best feasible point evaluated), so "stopped at an infeasible point" with
// feasible = true means: the optimizer's last point violates a constraint, an earlier one did not.
std::string RunStatus(const optimizers::SolverResult& solved) {
  switch (solved.status) {
    case optimizers::SolverStatus::kIterationLimit: return "max_evaluations reached";
    case optimizers::SolverStatus::kFailed: return "optimizer stopped: " + solved.message;
    case optimizers::SolverStatus::kInfeasible: return "optimizer stopped at an infeasible point";
    case optimizers::SolverStatus::kNotStationary:
      return "optimizer stopped where the stress still falls inside the limits (not a first-order optimum)";
    case optimizers::SolverStatus::kConverged: break;
  }
  return "converged";
}

Result RunJoint(const Study& s, const RunContext& ctx) {
  const std::vector<double> angles =
      cycloid::UniformCrankAngles(s.crank_angles_per_mesh_period, 2.0 * kPi / s.drive.rollers);
  std::vector<std::string> names;
  std::vector<double> start;
  for (const auto& v : s.variables) {
    names.push_back(v.name);
    start.push_back(v.initial);
  }
  objectives::CycloidTuningModel model(s.drive, s.crowning, s.material, s.options, s.design_torque_Nm * 1000.0,
                                       s.max_torque_Nm * 1000.0, angles, names, s.temperature_MPa);
  objectives::CycloidCrowningModel paper(s.drive, s.material, s.options, s.design_torque_Nm * 1000.0,
                                         s.max_torque_Nm * 1000.0, angles);
  Result r;
  r.backend = s.backend;
  Progress progress("cycloid_crowning_tuning", ctx.quiet);
  const double length = s.crowning.effective_length_mm > 0 ? s.crowning.effective_length_mm : s.drive.face_width_mm;
  // 1. The stress-versus-f curve when f is a variable (the others at their start values). The
  //    optimizer does not start from it: the tuned design does not depend on the scan.
  const auto fpos = std::find(names.begin(), names.end(), "coefficient_mm");
  if (fpos != names.end() && s.curve_points >= 2) {
    const size_t j = size_t(fpos - names.begin());
    const auto& var = s.variables[j];
    for (int k = 0; k < s.curve_points; ++k) {
      std::vector<double> x = start;
      x[j] = var.lower + (var.upper - var.lower) * k / (s.curve_points - 1);
      const objectives::TuningEvaluation e = model.Evaluate(x, false);
      r.curve.push_back({x[j], length, e.stress_MPa, e.edge_margin_um, e.pairs});
      progress.Update(0.3 * (k + 1) / s.curve_points, "scan f = " + Format(x[j] * 1e3, 4) + " um");
    }
  }
  r.reference = paper.Evaluate(s.reference_coefficient_mm, s.drive.face_width_mm);
  const int scan_runs = model.evaluations();
  // 2. The optimizer from the start values (sizing/cycloid_crowning_tuning.h).
  sizing::CycloidJointTuningSpec spec;
  spec.problem.variables = s.variables;
  spec.problem.required_end_distance_um = s.required_edge_margin_um;
  spec.problem.max_lte_peak_to_peak_arcsec = s.max_lte_peak_to_peak_arcsec;
  spec.problem.min_unloaded_te_arcsec = s.min_unloaded_te_arcsec;
  spec.problem.stress_scale_MPa = 1000.0;
  spec.backend = ToBackend(s.backend);
  spec.max_evaluations = s.max_evaluations;
  sizing::CycloidJointTuningOutcome solve =
      sizing::TuneCycloidCrowningJoint(model, spec, start, [&](const objectives::TuningEvaluation& e) {
        progress.Update(std::min(1.0, 0.3 + 0.7 * double(model.evaluations() - scan_runs) / (s.max_evaluations + 1)),
                        cycloid_common::Fixed(e.stress_MPa, 0) + " MPa, end distance " +
                            cycloid_common::Fixed(e.edge_margin_um, 1) + " um");
      });
  r.solver_status = optimizers::ToString(solve.solved.status);
  r.status = RunStatus(solve.solved);
  progress.Done();
  r.solver_evaluations = model.evaluations() - scan_runs;
  r.solver_gradient_evaluations = model.gradient_evaluations();
  r.joint_history = std::move(solve.history);
  r.feasible = solve.feasible;
  r.joint_best = solve.best;
  const auto [drive, crowning] = model.Design(r.joint_best.x);
  r.best = {crowning.coefficient_mm, crowning.effective_length_mm > 0 ? crowning.effective_length_mm : s.drive.face_width_mm,
            r.joint_best.stress_MPa, r.joint_best.edge_margin_um, r.joint_best.pairs};
  for (size_t j = 0; j < names.size(); ++j) r.tuned.push_back({names[j], r.joint_best.x[j]});
  r.evaluations = model.evaluations() + paper.evaluations();
  r.tuned_drive = drive;
  r.tuned_crowning = crowning;
  return r;
}

Result RunShorthand(const Study& s, const RunContext& ctx) {
  const std::vector<double> angles =
      cycloid::UniformCrankAngles(s.crank_angles_per_mesh_period, 2.0 * kPi / s.drive.rollers);
  objectives::CycloidCrowningModel model(s.drive, s.material, s.options, s.design_torque_Nm * 1000.0,
                                         s.max_torque_Nm * 1000.0, angles, s.shape);
  // The paper's form (eq. 7, L = B) for the reference coefficient.
  objectives::CycloidCrowningModel paper(s.drive, s.material, s.options, s.design_torque_Nm * 1000.0,
                                         s.max_torque_Nm * 1000.0, angles);
  Result r;
  Progress progress("cycloid_crowning_tuning", ctx.quiet);
  // 1. The stress-versus-f curve (at L = the lower length bound).
  for (int k = 0; k < s.curve_points; ++k) {
    const double f = s.coefficient_lo_mm + (s.coefficient_hi_mm - s.coefficient_lo_mm) * k / (s.curve_points - 1);
    r.curve.push_back(model.Evaluate(f, s.length_lo_mm));
    progress.Update(0.5 * (k + 1) / s.curve_points, "scan f = " + Format(f * 1e3, 4) + " um");
  }
  r.reference = paper.Evaluate(s.reference_coefficient_mm, s.drive.face_width_mm);
  // 2. Start from the best feasible scan point (else the one with the largest margin).
  const CrowningEvaluation start = objectives::LowestFeasibleStress(r.curve, s.required_edge_margin_um)
                                       .value_or(objectives::LargestEdgeMargin(r.curve));

  objectives::CycloidCrowningSpec spec;
  spec.coefficient_lo_mm = s.coefficient_lo_mm;
  spec.coefficient_hi_mm = s.coefficient_hi_mm;
  spec.initial_coefficient_mm = start.coefficient_mm;
  spec.tune_length = s.tune_length;
  spec.length_lo_mm = s.length_lo_mm;
  spec.length_hi_mm = s.length_hi_mm;
  spec.required_edge_margin_um = s.required_edge_margin_um;
  spec.stress_scale_MPa = std::max(1.0, start.stress_MPa);
  // 3. COBYLA from there (sizing/cycloid_crowning_tuning.h); the best feasible point seen anywhere.
  int runs = 0;
  sizing::CycloidShorthandTuningOutcome solve = sizing::TuneCycloidCrowningShorthand(
      model, spec, s.max_evaluations, r.curve, start, [&](const CrowningEvaluation& e) {
        progress.Update(std::min(1.0, 0.5 + 0.5 * double(++runs) / (s.max_evaluations + 1)),
                        "f = " + Format(e.coefficient_mm * 1e3, 4) + " um, " +
                            cycloid_common::Fixed(e.stress_MPa, 0) + " MPa");
      });
  r.history = std::move(solve.history);
  r.status = RunStatus(solve.solved);
  progress.Done();
  r.feasible = solve.feasible;
  r.best = solve.best;
  r.evaluations = model.evaluations() + paper.evaluations();
  r.backend = "cobyla";
  r.solver_status = optimizers::ToString(solve.solved.status);
  r.solver_evaluations = int(r.history.size());
  r.tuned.push_back({"coefficient_mm", r.best.coefficient_mm});
  if (s.tune_length) r.tuned.push_back({"effective_length_mm", r.best.length_mm});
  cycloid::Crowning tuned = s.shape;
  tuned.coefficient_mm = r.best.coefficient_mm;
  tuned.effective_length_mm = r.best.length_mm;
  r.tuned_drive = s.drive;
  r.tuned_crowning = tuned;
  return r;
}

}  // namespace

// The verified-optimum loop (objectives/verification.h): solve on the fast model, re-evaluate the
// tuned design with the accurate one, and while the accurate edge margin breaks the study's limit
// by more than its error, raise the fast model's required margin by the measured excess (plus
// kMarginStepUm) and solve again from the last design, at most kVerificationRounds times. The
// reported stress and margin are the accurate values; the fast ones stay beside them.
// The tuned design's bearing lives on the accurate model's settings (AccurateEvaluation: the
// grid doubled both ways, 2n crank angles per mesh period, uniform over the mesh period as the
// bearings' load periods need), each duty line one LTCA cycle at its torque.
cycloid_common::LifeResult TunedLife(const Study& s, const Result& r) {
  cycloid::LoadedOptions fine = s.options;
  fine.profile_cells = 2 * s.options.profile_cells;
  fine.axial_cells = 2 * s.options.axial_cells;
  fine.crank_slope = false;
  fine.keep_pressure = false;
  const cycloid::LoadedTca tca(r.tuned_drive, r.tuned_crowning, s.material, fine);
  const std::vector<double> angles =
      cycloid::UniformCrankAngles(2 * s.crank_angles_per_mesh_period, 2.0 * kPi / s.drive.rollers);
  return cycloid_common::RunLife(*s.life, tca, angles);
}

// result.json's members (Result's Serialize) from the model's numbers, in the file's units.
void FillResult(const Study& s, Result& r) {
  r.curve_points.clear();
  for (const auto& e : r.curve) r.curve_points.push_back({e.coefficient_mm, e.stress_MPa, e.edge_margin_um});
  for (const auto& [name, value] : r.tuned) r.tuned_values[name] = value;
  for (const auto& [name, value] : r.estimated_error) r.error_values[name] = value;
  r.optimizer = {r.backend, r.solver_status,
                 s.joint ? (s.backend == "cobyla" ? "NLopt LN_COBYLA on the smooth peak stress (values only)"
                            : s.backend == "slsqp" ? "NLopt LD_SLSQP with exact gradients (implicit differentiation)"
                                                   : "Ipopt with exact gradients (implicit differentiation)")
                         : "NLopt LN_COBYLA from the best feasible point of a scan",
                 r.solver_evaluations, r.solver_gradient_evaluations};
  r.name = s.name;
  r.tuned_coefficient_mm = r.best.coefficient_mm;
  r.tuned_effective_length_mm = r.best.length_mm;
  r.end_drop_mm = s.shape.end_drop_mm;
  r.flat_length_mm = s.shape.flat_length_mm;
  r.tuned_max_contact_stress_MPa = r.best.stress_MPa;
  r.tuned_edge_margin_at_max_torque_um = r.best.edge_margin_um;
  r.reference_coefficient_mm = s.reference_coefficient_mm;
  r.reference_max_contact_stress_MPa = r.reference.stress_MPa;
  r.reference_edge_margin_at_max_torque_um = r.reference.edge_margin_um;
  r.design_torque_Nm = s.design_torque_Nm;
  r.max_torque_Nm = s.max_torque_Nm;
  r.crank_angles_per_mesh_period = s.crank_angles_per_mesh_period;
  r.axial_cell_mm = s.drive.face_width_mm / s.options.axial_cells;
  if (s.joint) {
    const objectives::TuningEvaluation& b = r.joint_best;
    r.crowning_type = cycloid_common::CrowningTypeName(s.crowning.type);
    r.softmax_temperature_MPa = s.temperature_MPa;
    r.tuned_smooth_max_contact_stress_MPa = b.smooth_stress_MPa;
    r.tuned_lte_peak_to_peak_arcsec = r.accurate_lte_peak_to_peak_arcsec;
    r.tuned_max_pair_load_N = b.max_pair_load_N;
    if (!b.unloaded_te_arcsec.empty())
      r.tuned_min_unloaded_te_arcsec = *std::min_element(b.unloaded_te_arcsec.begin(), b.unloaded_te_arcsec.end());
    r.min_unloaded_te_arcsec = s.min_unloaded_te_arcsec;
    if (!r.joint_history.empty()) {
      const objectives::TuningEvaluation& a = r.joint_history.front();
      r.start_max_contact_stress_MPa = a.stress_MPa;
      r.start_edge_margin_at_max_torque_um = a.edge_margin_um;
    }
  }
  if (r.life) {
    r.life_json = cycloid_common::LifeBlockOf(*s.life, *r.life);
    r.life_json->design = "the tuned design (tuned crowning and modifications) on the accurate model's grid and "
                          "crank angles";
  }
  r.verified = r.verification.verified();
  r.verification_block = VerificationBlock::Of(r.verification);
}

Result Run(const Study& s, const RunContext& ctx) {
  Study fast = s;
  objectives::Verification v;
  v.max_rounds = kVerificationRounds;
  v.ran = true;
  int evaluations = 0;
  for (int round = 0;; ++round) {
    Result r = s.joint ? RunJoint(fast, ctx) : RunShorthand(fast, ctx);
    evaluations += r.evaluations;
    const Accurate acc = AccurateEvaluation(s, r.tuned_drive, r.tuned_crowning, r.best.stress_MPa, r.best.edge_margin_um);
    v.accurate_model = acc.model;
    objectives::VerifiedLimit stress;
    stress.limit = "max_contact_stress_MPa";
    stress.where = "design torque, the reported tuned_max_contact_stress_MPa";
    stress.limit_value = acc.stress_MPa;  // reported: the accurate value itself
    stress.accurate_value = acc.stress_MPa;
    stress.estimated_error = acc.stress_error_MPa;
    stress.fast_value = r.best.stress_MPa;
    stress.upper = true;
    objectives::VerifiedLimit margin;
    margin.limit = "edge_margin_um";
    margin.where = "max torque";
    margin.limit_value = s.required_edge_margin_um;
    margin.accurate_value = acc.margin_um;
    margin.estimated_error = acc.margin_error_um;
    margin.fast_value = r.best.edge_margin_um;
    margin.upper = false;
    v.checks = {stress, margin};
    const bool last = round >= kVerificationRounds;
    if (v.verified() || last || !r.feasible) {
      r.fast_stress_MPa = r.best.stress_MPa;
      r.fast_edge_margin_um = r.best.edge_margin_um;
      r.best.stress_MPa = acc.stress_MPa;
      r.best.edge_margin_um = acc.margin_um;
      r.accurate_lte_peak_to_peak_arcsec = acc.lte_peak_to_peak_arcsec;
      r.estimated_error = {{"tuned_max_contact_stress_MPa", acc.stress_error_MPa},
                           {"tuned_edge_margin_at_max_torque_um", acc.margin_error_um}};
      if (acc.stress_error_MPa > 0.05 * acc.stress_MPa)
        r.warnings.push_back("tuned_max_contact_stress_MPa: estimated discretisation error " +
                             Format(acc.stress_error_MPa, 3) + " MPa exceeds 5% of the value (refine analysis.grid or "
                             "analysis.crank_angles_per_mesh_period)");
      r.evaluations = evaluations;
      r.verification = v;
      if (s.life) r.life = TunedLife(s, r);
      FillResult(s, r);
      return r;
    }
    objectives::TighteningStep step;
    step.round = round + 1;
    step.limit = margin.limit;
    step.where = margin.where;
    step.fast_limit_before = fast.required_edge_margin_um;
    step.fast_limit_after = fast.required_edge_margin_um + margin.excess() + kMarginStepUm;
    step.accurate_value = margin.accurate_value;
    step.limit_value = margin.limit_value;
    v.history.push_back(step);
    fast.required_edge_margin_um = step.fast_limit_after;
    // Solve again from the last design (the general form; the shorthand starts from its scan).
    for (size_t j = 0; j < fast.variables.size() && j < r.joint_best.x.size(); ++j)
      fast.variables[j].initial = r.joint_best.x[j];
  }
}

void Write(const Study& s, const Result& r, Outputs& out) {
  out.SetResult(r);
  // Without a feasible coefficient, result.json's "feasible": false gives "infeasible" (RunStudy).
  if (r.feasible) {
    const bool converged = r.status == "converged";
    out.SetStatus(SizingStatus(true, r.verification.ran, r.verification.verified(), converged),
                  r.verification.verified()
                      ? (converged ? "" : "the coefficient's search stopped: " + r.status)
                      : VerificationFailure(r.verification,
                                            "raise tuning.edge_margin_um in the fast model, refine analysis.grid "
                                            "or allow more crowning (a larger coefficient_mm range)"));
  }
  Table table;
  std::vector<double> cf, cs, cm;
  for (const auto& e : r.curve) {
    cf.push_back(e.coefficient_mm * 1e3);
    cs.push_back(e.stress_MPa);
    cm.push_back(e.edge_margin_um);
  }
  // The coefficient in mm, as in the study file and result.json (the plots show µm).
  std::vector<double> cf_mm, hf_mm;
  for (const auto& e : r.curve) cf_mm.push_back(e.coefficient_mm);
  for (const auto& e : r.history) hf_mm.push_back(e.coefficient_mm);
  table.Add("coefficient_mm", cf_mm);
  table.Add("max_contact_stress_MPa", cs);
  table.Add("edge_margin_at_max_torque_um", cm);
  Table hist;
  std::vector<double> hl, hs, hm;
  if (s.joint) {
    // One column per variable (its own unit), then the outputs.
    for (size_t j = 0; j < s.variables.size(); ++j) {
      std::vector<double> col;
      for (const auto& e : r.joint_history) col.push_back(e.x[j]);
      hist.Add(s.variables[j].name, col);
    }
    std::vector<double> ss, grad;
    for (const auto& e : r.joint_history) {
      ss.push_back(e.smooth_stress_MPa);
      hs.push_back(e.stress_MPa);
      hm.push_back(e.edge_margin_um);
      grad.push_back(e.d_smooth_stress.empty() ? 0.0 : 1.0);
    }
    hist.Add("smooth_max_contact_stress_MPa", ss);
    hist.Add("max_contact_stress_MPa", hs);
    hist.Add("edge_margin_at_max_torque_um", hm);
    hist.Add("with_gradient", grad);
  }
  for (const auto& e : r.history) {
    hl.push_back(e.length_mm);
    hs.push_back(e.stress_MPa);
    hm.push_back(e.edge_margin_um);
  }
  if (!s.joint) {
    hist.Add("coefficient_mm", hf_mm);
    hist.Add("effective_length_mm", hl);
    hist.Add("max_contact_stress_MPa", hs);
    hist.Add("edge_margin_at_max_torque_um", hm);
  }
  out.Add("history.csv", ToCsv(hist));
  if (r.curve.empty()) return;  // the general form without f among its variables (or no scan)
  out.Add("stress_vs_coefficient.csv", ToCsv(table));
  PlotOptions po;
  po.title = "Peak contact stress over the mesh at the design torque";
  po.x_label = "LCM coefficient f [um]";
  po.y_label = "peak contact stress [MPa]";
  po.points = {{"tuned", r.best.coefficient_mm * 1e3, r.best.stress_MPa},
               {"paper f", s.reference_coefficient_mm * 1e3, r.reference.stress_MPa}};
  out.Add("stress_vs_coefficient.svg", SvgLinePlot({{"peak contact stress", cf, cs}}, po));
  po.title = "Edge margin at the maximum torque (>= 0: off the face edges)";
  po.y_label = "edge margin [um]";
  po.guides = {{"required edge margin", s.required_edge_margin_um}};
  po.points = {{"tuned", r.best.coefficient_mm * 1e3, r.best.edge_margin_um},
               {"paper f", s.reference_coefficient_mm * 1e3, r.reference.edge_margin_um}};
  out.Add("edge_margin_vs_coefficient.svg", SvgLinePlot({{"edge margin", cf, cm}}, po));
}

namespace {

// Fidelity for `camopt run --convergence` (studies/convergence.h): crank angles, contact grid and
// the optimizer's evaluation budget (its tolerances are fixed); the defaults are the declaration's.
Fidelity Knobs(const nlohmann::json& study) {
  const Input defaults;
  const cycloid::LoadedOptions grid;
  Fidelity f;
  // The general form reads its budget from optimizer.max_evaluations.
  const bool joint = study.is_object() && study.contains("variables");
  f.knobs.push_back({"crank_angles_per_mesh_period", {"/analysis/crank_angles_per_mesh_period"},
                     defaults.analysis.crank_angles_per_mesh_period, 2, true, 0, "uniform crank angles per mesh period"});
  f.knobs.push_back({"grid", {"/analysis/grid"}, {grid.profile_cells, grid.axial_cells}, 2, true, 0,
                     "contact cells across the profile and along the face"});
  const int budget = Input::Tuning{}.max_evaluations;
  if (joint)
    f.knobs.push_back({"max_evaluations", {"/optimizer/max_evaluations"}, budget, 2, true, 0,
                       "optimizer budget (NLopt: evaluations; Ipopt: iterations)"});
  else
    f.knobs.push_back({"max_evaluations", {"/tuning/max_evaluations"}, budget, 2, true, 0,
                       "COBYLA evaluations after the scan"});
  f.headlines = {"/tuned_coefficient_mm", "/tuned_max_contact_stress_MPa",
                 "/reference_max_contact_stress_MPa"};
  return f;
}

// The work limit (studies/work_limits.h): 2 torques × (the scan's points + the optimizer's
// evaluations) × crank angles × rollers × grid cells. In the general form each evaluation is a
// value run and its gradient, which costs about 0.65 value runs per variable (measured: 1.9× for 3
// variables, since then 1.67×, docs/performance.md, "Cycloid drive"; the estimate keeps the
// margin). The verification of the tuned design: both torques on twice the angles and four times
// the cells, and the study's own settings beside them, up to kVerificationRounds rounds.
WorkEstimate EstimateWork(const nlohmann::json& study, const std::string& file, double factor) {
  const Input in = ReadInput(Node(&study, file, ""));
  const Input::Tuning t = in.tuning.value_or(Input::Tuning{});
  const double rollers = in.drive.rollers;
  const std::array<int, 2> grid = in.analysis.grid.value_or(cycloid_common::DefaultGrid());
  const double cells = double(grid[0]) * grid[1];
  const double angles = in.analysis.crank_angles_per_mesh_period;
  // optimizer.max_evaluations wins over tuning.max_evaluations (Parse) in both forms.
  const double budget =
      in.optimizer && in.optimizer->max_evaluations ? *in.optimizer->max_evaluations : t.max_evaluations;
  double variables = 0;
  if (in.variables)
    for (const auto& v : study.at("variables")) variables += v.is_array() ? 1 : 0;
  const double evaluations = t.curve_points + budget * (in.variables ? 1.0 + 0.65 * variables : 1.0);
  const double verification = kVerificationRounds * 2 * (1 + 2 * 4) * angles * rollers * cells;
  return LargestTerm({{2 * evaluations * angles * rollers * cells, "/analysis/grid",
                       "2 torques × " + WorkNumber(evaluations) + " evaluations × " + WorkNumber(angles) +
                           " crank angles × " + WorkNumber(rollers) + " rollers × " + WorkNumber(cells) +
                           " grid cells"},
                      {verification, "/analysis/grid",
                       "verification: up to 3 rounds × 2 torques on twice the angles and cells"}},
                     5e7 * factor, "contact cell solves", 1);
}

CAMOPT_REGISTER_KIND(Kind<Input, Result, Study>{
    .name = "cycloid_crowning_tuning",
    .title = "camopt study: crowning (and modification) tuning of a cycloid drive",
    .run = Run, .parse = Parse, .write = Write, .knobs = Knobs, .estimate = EstimateWork,
    .report = std::vector<Headline>{
        {"tuned LCM coefficient", "/tuned_coefficient_mm", "mm"},
        {"peak contact stress, tuned", "/tuned_max_contact_stress_MPa", "MPa"},
        {"peak contact stress, paper's coefficient", "/reference_max_contact_stress_MPa", "MPa"},
        {"edge margin at the maximum torque, tuned", "/tuned_edge_margin_at_max_torque_um", "um",
         "study:/tuning/edge_margin_um", 0.0, false},
        {"edge margin at the maximum torque, paper's coefficient", "/reference_edge_margin_at_max_torque_um", "um",
         "study:/tuning/edge_margin_um", 0.0, false},
        {"smallest unloaded transmission error (backlash), tuned", "/tuned_min_unloaded_te_arcsec", "arcsec",
         "/min_unloaded_te_arcsec", NAN, false},
        {"shortest bearing life L10h, tuned design", "/life/shortest_L10h", "h"},
        {"coefficient search", "/search_status", ""},
    },
    .init_example = "cycloid_crowning_tuning_nnm"});
}  // namespace

}  // namespace camopt::studies::cycloid_crowning_tuning
