// Study kind "transmission_rigidity" (studies/transmission_rigidity_study.h): parse the chain,
// evaluate it through model/rigidity/, write.
#include "studies/transmission_rigidity_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "model/lcr/kinematics.h"
#include "model/rigidity/lost_motion.h"
#include "studies/format.h"
#include "studies/kind.h"
#include "studies/lcr_input.h"
#include "studies/report.h"
#include "studies/work_limits.h"
#include "studies/writers.h"

namespace camopt::studies::transmission_rigidity {
namespace {

using rigidity::ElementKind;
using rigidity::ElementSpec;

constexpr double kArcminPerRad = 180.0 * 60.0 / kPi;

// A modulus in MPa from its GPa field: the element's own if given, else the study's "material"
// (required only when an element needs it).
double ModulusMPa(const Node& element, const Node& root, const std::string& key_GPa) {
  if (element.Has(key_GPa)) return 1000.0 * element[key_GPa].Positive();
  return 1000.0 * root["material"][key_GPa].Positive();
}
double ShearMPa(const Node& element, const Node& root) { return ModulusMPa(element, root, "shear_modulus_GPa"); }
double YoungsMPa(const Node& element, const Node& root) { return ModulusMPa(element, root, "youngs_modulus_GPa"); }

// Outer and inner diameter with inner < outer.
std::pair<double, double> Diameters(const Node& e, const std::string& outer_key) {
  const double outer = e[outer_key].Positive();
  const double inner = e.NonNegativeOr("inner_diameter_mm", 0.0);
  if (!(inner < outer)) e["inner_diameter_mm"].Fail("a number < " + outer_key + " (" + Describe(e[outer_key].json()) + ")");
  return {outer, inner};
}

// A lobe cam reducer as a chain element: a gear stage of ratio |r_i| (input on the A side) whose
// own rigidity is the reducer's mean secant torsional stiffness at the output under its load
// (model/rigidity/lcr_stiffness.h) and whose backlash is the dead band of a roller clearance.
ReducerElement ParseReducerElement(const Node& e, const Node& root) {
  ReducerElement x;
  x.reducer = ParseReducer(e["reducer"]);
  if (e.Has("material")) e["material"].CheckKnownFields({"youngs_modulus_GPa", "poisson_ratio"});
  x.material = ParseMaterial(e.Has("material") ? e["material"] : root["material"]);
  const Node load = e["load"];
  load.CheckKnownFields({"output_torque_Nm"});
  x.torque_Nmm = load["output_torque_Nm"].Positive() * 1000.0;
  x.clearance_mm = e.NonNegativeOr("clearance_um", 0.0) / 1000.0;
  // Needle bearing radial stiffness per roller, in series with its contact; absent = rigid.
  x.bearing_N_per_mm = e.Has("needle_bearing_radial_stiffness_N_per_mm")
                           ? e["needle_bearing_radial_stiffness_N_per_mm"].Positive()
                           : 0.0;
  x.angle_steps = e.IntegerOr("angle_steps", 8, 720);
  x.direction = e.StringOr("direction", "forward");
  if (x.direction != "forward" && x.direction != "reverse") e["direction"].Fail("\"forward\" or \"reverse\"");
  // The paper's load sense drives the output along its motion; "reverse" loads the other rollers.
  x.sense = lcr::LoadedArmSign(x.reducer, lcr::Side::kOutput) * (x.direction == "forward" ? 1.0 : -1.0);
  x.where = e.file() + ": " + e.path();
  return x;
}

}  // namespace

nlohmann::ordered_json Input::Element::SchemaRules() {
  using ojson = nlohmann::ordered_json;
  // The fields every element may have; then per kind (as ParseElement checks them) the fields it
  // may have and those it needs.
  const std::vector<std::string> common = {"element", "name", "comment", "backlash_arcmin", "shear_modulus_GPa",
                                           "youngs_modulus_GPa"};
  struct Kind {
    const char* name;
    std::vector<std::string> own, required;
  };
  const std::vector<Kind> kinds = {
      {"shaft_torsion", {"outer_diameter_mm", "inner_diameter_mm", "length_mm"}, {"outer_diameter_mm", "length_mm"}},
      {"shaft_bending",
       {"outer_diameter_mm", "inner_diameter_mm", "pitch_radius_mm", "support", "to_bearing_1_mm", "to_bearing_2_mm",
        "bearing_span_mm", "overhang_mm"},
       {"outer_diameter_mm", "pitch_radius_mm"}},
      {"linear_stiffness", {"stiffness_N_per_mm", "radius_mm"}, {"stiffness_N_per_mm", "radius_mm"}},
      {"chain_span", {"stiffness_N_per_mm", "reference_length_mm", "span_length_mm", "radius_mm"},
       {"stiffness_N_per_mm", "span_length_mm", "radius_mm"}},
      {"belt_span", {"stiffness_N_per_mm", "reference_length_mm", "span_length_mm", "radius_mm"},
       {"stiffness_N_per_mm", "span_length_mm", "radius_mm"}},
      {"pull_rod", {"diameter_mm", "inner_diameter_mm", "length_mm", "lever_radius_mm"},
       {"diameter_mm", "length_mm", "lever_radius_mm"}},
      {"lever", {"length_mm", "tip_stiffness_N_per_mm", "width_mm", "height_mm"}, {"length_mm"}},
      {"coupling", {"rigidity_Nm_per_rad", "rigid"}, {}},
      {"gear_stage", {"ratio", "rigidity_Nm_per_rad", "mesh_stiffness_N_per_mm", "driven_pitch_radius_mm"}, {"ratio"}},
      {"lobe_cam_reducer",
       {"reducer", "material", "load", "clearance_um", "needle_bearing_radial_stiffness_N_per_mm", "angle_steps",
        "direction"},
       {"reducer", "load"}},
  };
  std::set<std::string> every;
  for (const Kind& k : kinds) every.insert(k.own.begin(), k.own.end());
  ojson all = ojson::array();
  for (const Kind& k : kinds) {
    ojson then = ojson::object();
    if (!k.required.empty()) then["required"] = k.required;
    for (const std::string& f : every)
      if (std::find(k.own.begin(), k.own.end(), f) == k.own.end() &&
          std::find(common.begin(), common.end(), f) == common.end())
        then["properties"][f] = false;
    all.push_back({{"if", {{"required", {"element"}}, {"properties", {{"element", {{"const", k.name}}}}}}},
                   {"then", then}});
  }
  // The variants within a kind.
  for (const auto& rule : ojson::parse(R"([
    {"if": {"required": ["element", "support"],
            "properties": {"element": {"const": "shaft_bending"}, "support": {"const": "overhung"}}},
     "then": {"required": ["bearing_span_mm", "overhang_mm"],
              "properties": {"to_bearing_1_mm": false, "to_bearing_2_mm": false}}},
    {"if": {"required": ["element"], "properties": {"element": {"const": "shaft_bending"}},
            "not": {"required": ["support"], "properties": {"support": {"const": "overhung"}}}},
     "then": {"required": ["to_bearing_1_mm", "to_bearing_2_mm"],
              "properties": {"bearing_span_mm": false, "overhang_mm": false}}},
    {"if": {"required": ["element"], "properties": {"element": {"const": "lever"}},
            "not": {"required": ["tip_stiffness_N_per_mm"]}},
     "then": {"required": ["width_mm", "height_mm"]}},
    {"if": {"required": ["element"], "properties": {"element": {"const": "coupling"}}},
     "then": {"anyOf": [{"required": ["rigidity_Nm_per_rad"]},
                        {"required": ["rigid"], "properties": {"rigid": {"const": true}}}]}},
    {"if": {"required": ["element", "mesh_stiffness_N_per_mm"], "properties": {"element": {"const": "gear_stage"}},
            "not": {"required": ["rigidity_Nm_per_rad"]}},
     "then": {"required": ["driven_pitch_radius_mm"]}}
  ])"))
    all.push_back(rule);
  return {{"allOf", all}};
}

nlohmann::ordered_json Input::SchemaRules() {
  // An element takes its modulus from the chain's material unless it gives its own: a shaft in
  // torsion G; a shaft in bending, a pull rod and a lever by its section E; a lobe cam reducer
  // without its own "material" the chain's E and ν. A deflection limit needs the torque it is under.
  return nlohmann::ordered_json::parse(R"({"allOf": [
    {"if": {"required": ["chain"], "properties": {"chain": {"contains": {
              "required": ["element"], "properties": {"element": {"const": "shaft_torsion"}},
              "not": {"required": ["shear_modulus_GPa"]}}}}},
     "then": {"required": ["material"], "properties": {"material": {"required": ["shear_modulus_GPa"]}}}},
    {"if": {"required": ["chain"], "properties": {"chain": {"contains": {
              "required": ["element"],
              "allOf": [{"not": {"required": ["youngs_modulus_GPa"]}},
                        {"anyOf": [{"properties": {"element": {"enum": ["shaft_bending", "pull_rod"]}}},
                                   {"properties": {"element": {"const": "lever"}},
                                    "not": {"required": ["tip_stiffness_N_per_mm"]}}]}]}}}},
     "then": {"required": ["material"], "properties": {"material": {"required": ["youngs_modulus_GPa"]}}}},
    {"if": {"required": ["chain"], "properties": {"chain": {"contains": {
              "required": ["element"], "properties": {"element": {"const": "lobe_cam_reducer"}},
              "not": {"required": ["material"]}}}}},
     "then": {"required": ["material"], "properties": {"material": {"required": ["youngs_modulus_GPa", "poisson_ratio"]}}}},
    {"if": {"required": ["limits"], "properties": {"limits": {"required": ["deflection_deg"]}}},
     "then": {"required": ["load_torque_Nm"]}}
  ]})");
}

namespace {

Element ParseElement(const Node& e, const Node& root, size_t index) {
  Element parsed;
  ElementSpec& s = parsed.spec;
  s.kind_name = e["element"].String();
  s.name = e.StringOr("name", s.kind_name + " " + std::to_string(index + 1));
  s.backlash_rad = e.NonNegativeOr("backlash_arcmin", 0.0) / kArcminPerRad;
  auto set = [&](ElementKind kind, std::vector<std::string> names, std::vector<double> values) {
    s.kind = kind;
    s.param_names = std::move(names);
    s.params = std::move(values);
  };
  const std::string& k = s.kind_name;
  // The fields every element may have (docs/studies.md; "comment" is a free note, ignored), plus
  // those of its kind.
  auto check = [&](std::set<std::string> own) {
    own.insert({"element", "name", "comment", "backlash_arcmin", "shear_modulus_GPa", "youngs_modulus_GPa"});
    e.CheckKnownFields(own);
  };
  if (k == "shaft_torsion") {
    check({"outer_diameter_mm", "inner_diameter_mm", "length_mm"});
    const auto [outer, inner] = Diameters(e, "outer_diameter_mm");
    set(ElementKind::kShaftTorsion,
        {"shear_modulus_MPa", "outer_diameter_mm", "inner_diameter_mm", "length_mm"},
        {ShearMPa(e, root), outer, inner, e["length_mm"].Positive()});
  } else if (k == "shaft_bending") {
    const std::string support = e.StringOr("support", "between_bearings");
    if (support == "between_bearings")
      check({"outer_diameter_mm", "inner_diameter_mm", "pitch_radius_mm", "support", "to_bearing_1_mm",
             "to_bearing_2_mm"});
    else if (support == "overhung")
      check({"outer_diameter_mm", "inner_diameter_mm", "pitch_radius_mm", "support", "bearing_span_mm",
             "overhang_mm"});
    const auto [outer, inner] = Diameters(e, "outer_diameter_mm");
    const double r = e["pitch_radius_mm"].Positive();
    if (support == "between_bearings") {
      set(ElementKind::kShaftBending,
          {"youngs_modulus_MPa", "outer_diameter_mm", "inner_diameter_mm", "to_bearing_1_mm",
           "to_bearing_2_mm", "pitch_radius_mm"},
          {YoungsMPa(e, root), outer, inner, e["to_bearing_1_mm"].Positive(),
           e["to_bearing_2_mm"].Positive(), r});
    } else if (support == "overhung") {
      set(ElementKind::kShaftOverhung,
          {"youngs_modulus_MPa", "outer_diameter_mm", "inner_diameter_mm", "bearing_span_mm",
           "overhang_mm", "pitch_radius_mm"},
          {YoungsMPa(e, root), outer, inner, e["bearing_span_mm"].Positive(),
           e["overhang_mm"].Positive(), r});
    } else {
      e["support"].Fail("\"between_bearings\" or \"overhung\"");
    }
  } else if (k == "linear_stiffness") {
    check({"stiffness_N_per_mm", "radius_mm"});
    set(ElementKind::kLinearStiffness, {"stiffness_N_per_mm", "radius_mm"},
        {e["stiffness_N_per_mm"].Positive(), e["radius_mm"].Positive()});
  } else if (k == "chain_span" || k == "belt_span") {
    check({"stiffness_N_per_mm", "reference_length_mm", "span_length_mm", "radius_mm"});
    set(ElementKind::kSpan,
        {"stiffness_N_per_mm", "reference_length_mm", "span_length_mm", "radius_mm"},
        {e["stiffness_N_per_mm"].Positive(), e.PositiveOr("reference_length_mm", 1000.0),
         e["span_length_mm"].Positive(), e["radius_mm"].Positive()});
  } else if (k == "pull_rod") {
    check({"diameter_mm", "inner_diameter_mm", "length_mm", "lever_radius_mm"});
    const auto [outer, inner] = Diameters(e, "diameter_mm");
    set(ElementKind::kPullRod,
        {"youngs_modulus_MPa", "diameter_mm", "inner_diameter_mm", "length_mm", "lever_radius_mm"},
        {YoungsMPa(e, root), outer, inner, e["length_mm"].Positive(),
         e["lever_radius_mm"].Positive()});
  } else if (k == "lever") {
    check({"length_mm", "tip_stiffness_N_per_mm", "width_mm", "height_mm"});
    const double length = e["length_mm"].Positive();
    if (e.Has("tip_stiffness_N_per_mm")) {
      set(ElementKind::kLeverStiffness, {"tip_stiffness_N_per_mm", "length_mm"},
          {e["tip_stiffness_N_per_mm"].Positive(), length});
    } else {
      set(ElementKind::kLeverSection,
          {"youngs_modulus_MPa", "width_mm", "height_mm", "length_mm"},
          {YoungsMPa(e, root), e["width_mm"].Positive(), e["height_mm"].Positive(), length});
    }
  } else if (k == "coupling") {
    check({"rigidity_Nm_per_rad", "rigid"});
    if (e.Has("rigidity_Nm_per_rad")) {
      set(ElementKind::kCoupling, {"rigidity_Nmm_per_rad"},
          {1000.0 * e["rigidity_Nm_per_rad"].Positive()});
    } else if (e.BoolOr("rigid", false)) {
      set(ElementKind::kCoupling, {}, {});
    } else {
      e.FailWith("a coupling needs \"rigidity_Nm_per_rad\" or \"rigid\": true");
    }
  } else if (k == "gear_stage") {
    check({"ratio", "rigidity_Nm_per_rad", "mesh_stiffness_N_per_mm", "driven_pitch_radius_mm"});
    const double ratio = e["ratio"].Positive();
    if (e.Has("rigidity_Nm_per_rad")) {
      set(ElementKind::kGearStage, {"ratio", "mesh_rigidity_Nmm_per_rad"},
          {ratio, 1000.0 * e["rigidity_Nm_per_rad"].Positive()});
    } else if (e.Has("mesh_stiffness_N_per_mm")) {
      set(ElementKind::kGearStage, {"ratio", "mesh_stiffness_N_per_mm", "driven_pitch_radius_mm"},
          {ratio, e["mesh_stiffness_N_per_mm"].Positive(), e["driven_pitch_radius_mm"].Positive()});
    } else {
      set(ElementKind::kGearStage, {"ratio"}, {ratio});
    }
  } else if (k == "lobe_cam_reducer") {
    check({"reducer", "material", "load", "clearance_um", "needle_bearing_radial_stiffness_N_per_mm",
           "angle_steps", "direction"});
    parsed.reducer = ParseReducerElement(e, root);
    s.kind = ElementKind::kFixed;
    s.param_names = {"ratio", "rigidity_Nmm_per_rad"};
  } else {
    e["element"].Fail(
        "an element kind (shaft_torsion, shaft_bending, linear_stiffness, chain_span, belt_span, "
        "pull_rod, lever, coupling, gear_stage, lobe_cam_reducer)");
  }
  return parsed;
}

ReducerResult RunReducer(const ReducerElement& x, bool quiet) {
  ReducerResult res;
  const lcr::Reducer<double>& r = x.reducer;
  const double torque = x.torque_Nmm;
  const int lm_steps = std::min(x.angle_steps, 36);
  res.speed_reduction_ratio = lcr::SpeedReductionRatio(r);
  try {
    Progress progress("lobe_cam_reducer stiffness", quiet);
    res.cycle = rigidity::StiffnessCycle(r, x.material, x.sense * torque, x.clearance_mm, x.angle_steps,
                                         x.bearing_N_per_mm);
    progress.Update(0.4);
    res.reverse = rigidity::StiffnessCycle(r, x.material, -x.sense * torque, x.clearance_mm, x.angle_steps,
                                           x.bearing_N_per_mm);
    progress.Update(0.6);
    // Lost-motion curve from −T to +T (sense of the load), mean over 36 input angles (the arms
    // repeat with the roller pitch, 13- or 15-fold, so a uniform 10° grid averages them well).
    res.torques_Nmm = rigidity::LostMotionTorques(torque);
    res.rotations_rad = rigidity::LostMotionCurveInSense(r, x.material, res.torques_Nmm, x.sense,
                                                         x.clearance_mm, lm_steps, x.bearing_N_per_mm);
    res.dead_band_rad = rigidity::DeadBand(r, x.clearance_mm, x.angle_steps);
    progress.Update(1.0);
  } catch (const std::domain_error& err) {
    throw StudyError(x.where + ": the reducer cannot carry the load: " + err.what());
  }
  // Lost motion as reducer catalogues define it (±3 % of the rated torque, here the load torque).
  res.lost_motion_rad =
      rigidity::LostMotion(r, x.material, x.sense * torque, x.clearance_mm, lm_steps, x.bearing_N_per_mm);
  return res;
}

// The paper's advice for the dominant element, by kind.
std::string KindAdvice(const std::string& kind) {
  static const std::map<std::string, std::string> advice = {
      {"shaft_torsion", "enlarge the diameter (rigidity ~ D^4) or shorten the length under torque"},
      {"shaft_bending", "move the gear or sprocket closer to a bearing, enlarge the shaft, or use a larger pitch radius (R = S r^2)"},
      {"linear_stiffness", "use a larger radius (R = S r^2) or a stiffer element"},
      {"chain_span", "shorten the loaded span, tension the chain, or use larger sprockets (R = S r^2)"},
      {"belt_span", "shorten the loaded span or use larger pulleys (R = S r^2); prefer a chain"},
      {"pull_rod", "enlarge the rod or the lever radius (R = S r^2)"},
      {"lever", "stiffen or shorten the lever"},
      {"coupling", "use a torsionally rigid (membrane or diaphragm) coupling"},
      {"gear_stage", "use larger gears (R = S r^2), or place the long shaft on the high-speed side of the reduction"},
      {"lobe_cam_reducer", "a larger eccentricity (the moment arms grow with it), longer rollers and cam, or stiffer roller bearings"},
  };
  auto it = advice.find(kind);
  return it == advice.end() ? "" : it->second;
}

// result.json's members (Result's Serialize) from the model's numbers, in the file's units.
void FillResult(const Study& study, Result& res) {
  const auto& r = res.chain;
  res.name = study.in.name;
  res.rigidity_Nm_per_rad = 1.0e-3 / r.compliance_b;
  res.rigidity_at_end_b_Nm_per_rad = res.rigidity_Nm_per_rad;
  res.rigidity_at_end_a_Nm_per_rad = 1.0e-3 / r.compliance_a;
  res.total_ratio = r.total_ratio;
  res.backlash_at_end_b_arcmin = r.backlash_b * kArcminPerRad;
  res.backlash_at_end_a_arcmin = r.backlash_a * kArcminPerRad;
  if (study.in.report_radius_mm) {
    // Eq. 5 transposed: the linear stiffness at a radius of end B (e.g. at the follower roller).
    res.report_radius_mm = study.in.report_radius_mm;
    res.linear_stiffness_at_report_radius_N_per_mm =
        rigidity::LinearStiffnessAtRadius(r.compliance_b, *study.in.report_radius_mm);
  }
  if (study.in.load_torque_Nm) {
    res.load_torque_Nm = study.in.load_torque_Nm;
    res.deflection_at_end_b_deg = 1000.0 * *study.in.load_torque_Nm * r.compliance_b * 180.0 / kPi;
  }
  // The verdict: each limit given beside its value (report.html and the summary read them).
  if (const Input::Limits& l = study.in.limits; l.rigidity_Nm_per_rad || l.backlash_arcmin || l.deflection_deg) {
    res.limits = l;
    if (l.rigidity_Nm_per_rad) res.rigidity_ok = res.rigidity_at_end_b_Nm_per_rad >= *l.rigidity_Nm_per_rad;
    if (l.backlash_arcmin) res.backlash_ok = res.backlash_at_end_b_arcmin <= *l.backlash_arcmin;
    if (l.deflection_deg) res.deflection_ok = *res.deflection_at_end_b_deg <= *l.deflection_deg;
    res.limits_ok = res.rigidity_ok.value_or(true) && res.backlash_ok.value_or(true) && res.deflection_ok.value_or(true);
  }
  for (size_t i = 0; i < res.elements.size(); ++i) {
    const ElementResult& er = res.elements[i];
    const ElementSpec& s = er.spec;
    Result::ElementRow e;
    e.index = static_cast<int>(i);
    e.name = s.name;
    e.element = s.kind_name;
    e.rigidity_Nm_per_rad = 1.0e-3 / er.compliance_rad_per_Nmm;  // null: rigid
    e.rigidity_at_end_b_Nm_per_rad = 1.0e-3 / r.compliance_at_b[i];
    e.compliance_share = r.share[i];
    // The paper's remark on the stepped shaft: the overall rigidity had this element been
    // ignored (made rigid).
    e.rigidity_if_rigid_Nm_per_rad = 1.0e-3 / r.compliance_b_if_rigid[i];
    if (s.kind == ElementKind::kGearStage || s.kind == ElementKind::kFixed) e.ratio = s.params[0];
    e.backlash_arcmin = s.backlash_rad * kArcminPerRad;
    e.backlash_at_end_b_arcmin = r.backlash_at_b[i] * kArcminPerRad;
    for (const auto& [n, v] : er.elasticity) e.rigidity_elasticity[n] = v;
    if (er.reducer) {
      const ReducerElement& in = *study.elements[i].reducer;
      const ReducerResult& x = *er.reducer;
      const auto& cycle = x.cycle;
      Result::ReducerRow& j = e.reducer.emplace();
      j.speed_reduction_ratio = x.speed_reduction_ratio;
      j.output_torque_Nm = in.torque_Nmm / 1000.0;
      j.direction = in.direction;
      j.clearance_um = in.clearance_mm * 1000.0;
      if (in.bearing_N_per_mm > 0) j.needle_bearing_radial_stiffness_N_per_mm = in.bearing_N_per_mm;
      j.contact_law = "Palmgren line contact, delta = 3.84e-5 Q^0.9 / L^0.8 (steel), scaled by E*";
      j.mean_secant_rigidity_Nm_per_rad = cycle.mean_secant_Nmm_per_rad / 1000.0;
      j.mean_secant_rigidity_Nm_per_arcmin = cycle.mean_secant_Nmm_per_rad / 1000.0 / kArcminPerRad;
      j.min_secant_rigidity_Nm_per_rad = cycle.min_secant_Nmm_per_rad / 1000.0;
      j.max_secant_rigidity_Nm_per_rad = cycle.max_secant_Nmm_per_rad / 1000.0;
      j.secant_ripple = cycle.ripple;
      j.mean_tangent_rigidity_Nm_per_rad = cycle.mean_tangent_Nmm_per_rad / 1000.0;
      j.min_tangent_rigidity_Nm_per_rad = cycle.min_tangent_Nmm_per_rad / 1000.0;
      j.max_tangent_rigidity_Nm_per_rad = cycle.max_tangent_Nmm_per_rad / 1000.0;
      j.reverse_mean_secant_rigidity_Nm_per_rad = x.reverse.mean_secant_Nmm_per_rad / 1000.0;
      j.rigidity_at_input_Nm_per_rad = x.rigidity_at_input_Nm_per_rad;
      j.mean_elastic_rotation_arcmin = in.torque_Nmm / cycle.mean_secant_Nmm_per_rad * kArcminPerRad;
      j.lost_motion_arcmin_at_3pct_torque = x.lost_motion_rad * kArcminPerRad;
      j.dead_band_arcmin = x.dead_band_rad * kArcminPerRad;
      j.max_roller_force_input_N = HardMax(cycle.max_force_input_N);
      j.max_roller_force_output_N = HardMax(cycle.max_force_output_N);
    }
    res.element_rows.push_back(std::move(e));
  }
  const int d = r.dominant;
  const ElementSpec& ds = res.elements[d].spec;
  res.dominant.index = d;
  res.dominant.name = ds.name;
  res.dominant.element = ds.kind_name;
  res.dominant.compliance_share = r.share[d];
  if (res.most_effective >= 0) {
    const auto& [n, v] = res.elements[d].elasticity[res.most_effective];
    res.dominant.most_effective_parameter = n;
    res.dominant.most_effective_parameter_elasticity = v;
  }
  res.dominant.advice = res.advice;
  res.notes = {"Advice: " + res.advice};  // report.html's notes
}

}  // namespace

Study Parse(const Node& root) {
  // The declaration's checks: every field's type, bounds and choices, unknown fields refused. The
  // elements' values are read below per kind, with the rules between fields.
  Study s;
  s.in = Read<Input>(root);
  const Input& in = s.in;
  const Node chain = root["chain"];
  s.chain_where = chain.file() + ": " + chain.path();
  const std::vector<Node> nodes = chain.Elements();
  if (nodes.empty()) chain.Fail("a non-empty array of elements");
  for (size_t i = 0; i < nodes.size(); ++i) s.elements.push_back(ParseElement(nodes[i], root, i));
  if (in.limits.deflection_deg && !in.load_torque_Nm)
    root["limits"]["deflection_deg"].FailWith("a deflection limit needs the torque it is under: give load_torque_Nm");
  return s;
}

Result Run(const Study& study, const RunContext& ctx) {
  Result res;
  std::vector<ElementSpec> specs;
  std::vector<std::vector<std::pair<std::string, double>>> own(study.elements.size());
  for (size_t i = 0; i < study.elements.size(); ++i) {
    const Element& e = study.elements[i];
    ElementResult er;
    er.spec = e.spec;
    if (e.reducer) {
      const ReducerElement& x = *e.reducer;
      er.reducer = RunReducer(x, ctx.quiet);
      // Its own rigidity is a precomputed ratio and rigidity (not design choices): its
      // elasticities are those of its own dimensions.
      er.spec.params = {std::abs(er.reducer->speed_reduction_ratio), er.reducer->cycle.mean_secant_Nmm_per_rad};
      er.reducer->rigidity_at_input_Nm_per_rad = rigidity::RigidityThroughRatio(
          er.reducer->cycle.mean_secant_Nmm_per_rad / 1000.0, er.spec.params[0]);
      er.spec.backlash_rad += er.reducer->dead_band_rad;
      own[i] = rigidity::ReducerStiffnessElasticities(x.reducer, x.material, x.sense * x.torque_Nmm,
                                                      x.clearance_mm, x.bearing_N_per_mm,
                                                      std::min(x.angle_steps, 180));
    }
    specs.push_back(er.spec);
    res.elements.push_back(std::move(er));
  }

  res.chain = rigidity::EvaluateChain<double>(specs);
  const auto& r = res.chain;
  if (!(r.compliance_b > 0.0))
    throw StudyError(study.chain_where + ": every element is rigid: the chain has no compliance to report");
  // An element of (nearly) zero modulus or size makes the compliance infinite and its shares NaN:
  // no element dominates, and nothing the chain reports is a number.
  if (!std::isfinite(r.compliance_b) || r.dominant < 0 || r.dominant >= static_cast<int>(specs.size()))
    throw StudyError(study.chain_where + ": expected a chain whose compliance is a finite number, found " +
                     (std::isfinite(r.compliance_b) ? "shares that are not numbers" : "an infinite compliance") +
                     " (an element is infinitely soft: check for extreme moduli or sizes, such as 5e-324 GPa or 1e-300 mm)");
  // Elasticities of the overall rigidity per element parameter; a reducer's come from its own
  // through the chain rule (model/rigidity/lost_motion.h).
  const auto chain_elasticity = rigidity::RigidityElasticities(specs);
  for (size_t i = 0; i < specs.size(); ++i) {
    ElementResult& er = res.elements[i];
    er.compliance_rad_per_Nmm = rigidity::EvaluateElement<double>(specs[i], specs[i].params).compliance;
    if (specs[i].kind == ElementKind::kFixed) {
      er.elasticity = rigidity::ChainElasticities(r.share[i], own[i]);
    } else {
      for (size_t q = 0; q < specs[i].param_names.size(); ++q)
        er.elasticity.push_back({specs[i].param_names[q], chain_elasticity[i][q]});
    }
  }

  // The dominant element and its most effective dimension (largest |elasticity| other than a
  // modulus or a gear ratio, which are rarely free choices).
  const int d = r.dominant;
  const ElementSpec& ds = specs[d];
  const auto& el = res.elements[d].elasticity;
  res.advice = ds.name + " (" + ds.kind_name + ") holds " +
               std::to_string(static_cast<int>(std::lround(100.0 * r.share[d]))) +
               "% of the compliance: " + KindAdvice(ds.kind_name) + ".";
  int best_q = -1;
  for (size_t q = 0; q < el.size(); ++q) {
    const std::string& pn = el[q].first;
    if (pn.find("modulus") != std::string::npos || pn == "ratio") continue;
    if (best_q < 0 || std::abs(el[q].second) > std::abs(el[best_q].second)) best_q = static_cast<int>(q);
  }
  if (best_q >= 0) {
    char buf[200];
    std::snprintf(buf, sizeof buf, " Most effective dimension: %s (%+.2f%% overall rigidity per +1%%).",
                  el[best_q].first.c_str(), el[best_q].second);
    res.advice += buf;
  }
  res.most_effective = best_q;
  FillResult(study, res);
  return res;
}

void Write(const Study& study, const Result& res, Outputs& out) {
  out.SetResult(res);
  const auto& r = res.chain;
  // CSV: one row per element; infinite rigidities (rigid elements) are written as "inf".
  Table table;
  std::vector<double> col_idx, col_own, col_at_b, col_share, col_without, col_backlash;
  for (size_t i = 0; i < res.elements.size(); ++i) {
    col_idx.push_back(static_cast<double>(i));
    col_own.push_back(1.0e-3 / res.elements[i].compliance_rad_per_Nmm);
    col_at_b.push_back(1.0e-3 / r.compliance_at_b[i]);
    col_share.push_back(r.share[i]);
    col_without.push_back(1.0e-3 / r.compliance_b_if_rigid[i]);
    col_backlash.push_back(r.backlash_at_b[i] * kArcminPerRad);
  }
  table.Add("index", col_idx);
  table.Add("rigidity_Nm_per_rad", col_own);
  table.Add("rigidity_at_end_b_Nm_per_rad", col_at_b);
  table.Add("compliance_share", col_share);
  table.Add("rigidity_if_rigid_Nm_per_rad", col_without);
  table.Add("backlash_at_end_b_arcmin", col_backlash);
  out.Add("elements.csv", ToCsv(table));

  // The chain as the paper's designer reads it: each element's share of the compliance at end b
  // (the dominant one red) with the advice, and each element's backlash at end b against the limit.
  std::vector<Bar> shares, backlash;
  double backlash_sum = 0;
  for (size_t i = 0; i < res.elements.size(); ++i) {
    const std::string& name = res.elements[i].spec.name;
    shares.push_back({name, 100.0 * r.share[i],
                      std::isfinite(col_at_b[i]) ? Format(100.0 * r.share[i], 3) + " % (" + Format(col_at_b[i], 4) +
                                                       " N·m/rad at end b)"
                                                 : "rigid",
                      static_cast<int>(i) == r.dominant});
    backlash.push_back({name, col_backlash[i], Format(col_backlash[i], 3) + " arcmin"});
    backlash_sum += col_backlash[i];
  }
  BarChartOptions so;
  so.title = "Share of the compliance at end b: " + study.in.name;
  so.x_label = "share of the chain's compliance [%]";
  so.notes = {"Advice: " + res.advice};
  out.Add("compliance_share.svg", SvgBarChart(shares, so));
  if (backlash_sum > 0) {
    const double limit = study.in.limits.backlash_arcmin.value_or(NAN);
    backlash.push_back({"whole chain", backlash_sum, Format(backlash_sum, 3) + " arcmin",
                        std::isfinite(limit) && backlash_sum > limit});
    BarChartOptions bo;
    bo.title = "Backlash at end b: " + study.in.name;
    bo.x_label = "backlash seen at end b [arcmin]";
    bo.guides = {{"backlash limit", limit}};
    out.Add("backlash.svg", SvgBarChart(backlash, bo));
  }

  for (size_t i = 0; i < res.elements.size(); ++i) {
    if (!res.elements[i].reducer) continue;
    const ReducerResult& x = *res.elements[i].reducer;
    const auto& cycle = x.cycle;
    const std::string& name = res.elements[i].spec.name;
    const std::string stem = "reducer_" + std::to_string(i + 1);
    Table t;
    std::vector<double> deg, rot_arcmin, sec, tan;
    for (size_t k = 0; k < cycle.theta_rad.size(); ++k) {
      deg.push_back(cycle.theta_rad[k] * 180.0 / kPi);
      rot_arcmin.push_back(cycle.rotation_rad[k] * kArcminPerRad);
      sec.push_back(cycle.secant_Nmm_per_rad[k] / 1000.0);
      tan.push_back(cycle.tangent_Nmm_per_rad[k] / 1000.0);
    }
    t.Add("input_angle_deg", deg);
    t.Add("output_rotation_arcmin", rot_arcmin);
    std::vector<double> el_arcmin;
    for (double v : cycle.elastic_rotation_rad) el_arcmin.push_back(v * kArcminPerRad);
    t.Add("elastic_rotation_arcmin", el_arcmin);
    t.Add("secant_rigidity_Nm_per_rad", sec);
    t.Add("tangent_rigidity_Nm_per_rad", tan);
    t.Add("max_roller_force_input_N", cycle.max_force_input_N);
    t.Add("max_roller_force_output_N", cycle.max_force_output_N);
    out.Add(stem + "_stiffness.csv", ToCsv(t));
    out.Add(stem + "_stiffness.svg",
            SvgLinePlot({{"secant", deg, sec}, {"tangent", deg, tan}},
                        {"Torsional rigidity at the output over one input turn (" + name + ")",
                         "input angle [deg]", "rigidity [N·m/rad]"}));
    Table lmt;
    std::vector<double> t_nm, r_arcmin;
    for (size_t k = 0; k < x.torques_Nmm.size(); ++k) {
      t_nm.push_back(x.torques_Nmm[k] / 1000.0);
      r_arcmin.push_back(x.rotations_rad[k] * kArcminPerRad);
    }
    lmt.Add("output_torque_Nm", t_nm);
    lmt.Add("output_rotation_arcmin", r_arcmin);
    out.Add(stem + "_lost_motion.csv", ToCsv(lmt));
    out.Add(stem + "_lost_motion.svg",
            SvgLinePlot({{"mean over the input turn", r_arcmin, t_nm}},
                        {"Lost-motion curve, input held (" + name + ")", "output rotation [arcmin]",
                         "output torque [N·m]"}));
  }
}

namespace {

// The work limit (studies/work_limits.h): one unit per closed-form element; a lobe cam reducer
// solves its rollers' load sharing at every angle step in both load directions. The chain's length
// is capped before the elements are read.
WorkEstimate EstimateWork(const nlohmann::json& study, const std::string& file, double factor) {
  const auto chain = study.find("chain");
  const double elements = chain != study.end() && chain->is_array() ? double(chain->size()) : 0.0;
  if (elements > 1000 * factor)
    throw StudyError(file + ": /chain: the chain has " + WorkNumber(elements) + " elements, more than the cap of " +
                     WorkNumber(1000 * factor) + "; raise the caps with --max-work-factor");
  const Input in = Read<Input>(Node(&study, file, ""));
  std::vector<WorkTerm> terms;
  for (size_t i = 0; i < in.chain.size(); ++i) {
    const Input::Element& e = in.chain[i];
    if (e.element != "lobe_cam_reducer" || !e.reducer) {
      terms.push_back({1.0, "/chain/" + std::to_string(i), "one element"});
      continue;
    }
    const double rollers = e.reducer->input.rollers + e.reducer->output.rollers;
    const double steps = e.angle_steps.value_or(720);
    terms.push_back({2 * steps * rollers, "/chain/" + std::to_string(i) + "/angle_steps",
                     "2 load directions × " + WorkNumber(steps) + " angle steps × " + WorkNumber(rollers) + " rollers"});
  }
  return LargestTerm(terms, 2e6 * factor, "roller load-sharing solves", 200);
}

// Fidelity for `camopt run --convergence` (studies/convergence.h): the angle grid of every lobe
// cam reducer in the chain (together); the other elements are closed forms.
Fidelity Knobs(const nlohmann::json& study) {
  Fidelity f;
  std::vector<std::string> paths;
  if (study.contains("chain") && study["chain"].is_array())
    for (size_t i = 0; i < study["chain"].size(); ++i)
      if (study["chain"][i].value("element", "") == "lobe_cam_reducer") {
        paths.push_back("/chain/" + std::to_string(i) + "/angle_steps");
        f.headlines.push_back("/elements/" + std::to_string(i) + "/reducer/mean_secant_rigidity_Nm_per_rad");
      }
  if (!paths.empty())
    f.knobs.push_back({"reducer_angle_steps", paths, 720, 2, true, 0,
                       "input angles of each reducer's stiffness cycle"});
  else
    f.no_knob = "closed-form elements only: nothing to refine";
  f.headlines.insert(f.headlines.begin(), {"/rigidity_Nm_per_rad", "/rigidity_at_end_a_Nm_per_rad"});
  return f;
}

CAMOPT_REGISTER_KIND(Kind<Input, Result, Study>{
    .name = "transmission_rigidity",
    .title = "camopt study: torsional rigidity, backlash and deflection of a drive train from its elements",
    .run = Run, .parse = Parse, .write = Write, .knobs = Knobs, .estimate = EstimateWork,
    .report = std::vector<Headline>{
        {"torsional rigidity at end b", "/rigidity_at_end_b_Nm_per_rad", "N·m/rad", "/limits/rigidity_Nm_per_rad", NAN,
         false},
        {"torsional rigidity at end a", "/rigidity_at_end_a_Nm_per_rad", "N·m/rad"},
        {"backlash at end b", "/backlash_at_end_b_arcmin", "arcmin", "/limits/backlash_arcmin"},
        {"backlash at end a", "/backlash_at_end_a_arcmin", "arcmin"},
        {"deflection at end b", "/deflection_at_end_b_deg", "deg", "/limits/deflection_deg"},
        {"total ratio", "/total_ratio", ""},
        {"most compliant element", "/dominant/name", ""},
        {"its share of the compliance", "/dominant/compliance_share", ""},
    },
    .asked = std::vector<AskedBlock>{
        {{"/load_torque_Nm"}, "/deflection_at_end_b_deg", "the deflection under load"},
        {{"/report_radius_mm"}, "/linear_stiffness_at_report_radius_N_per_mm", "the stiffness at the radius"},
    },
    .init_example = "rigidity_gearbox"});
}  // namespace

}  // namespace camopt::studies::transmission_rigidity
