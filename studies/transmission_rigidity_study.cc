// Study kind "transmission_rigidity": the torsional rigidity and backlash of a series chain of
// shafts, gears, chains, belts, pull-rods, levers, couplings (the transmission-rigidity paper, docs/rigidity.md)
// and lobe cam reducers, seen from either end, with each element's share of the compliance and
// the design advice the paper gives by hand (which element dominates, which dimension to change).
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/lcr/kinematics.h"
#include "model/rigidity/chain_elements.h"
#include "model/rigidity/lcr_stiffness.h"
#include "model/rigidity/lost_motion.h"
#include "studies/input.h"
#include "studies/lcr_input.h"
#include "studies/study.h"
#include "studies/writers.h"

namespace camopt::studies {
namespace {

using rigidity::ElementKind;
using rigidity::ElementSpec;

constexpr double kArcminPerRad = 180.0 * 60.0 / kPi;

// Moduli in MPa: the element's own field if given, else the study's "material" (required only
// when an element needs it).
double ShearMPa(const Node& element, const Node& root) {
  if (element.Has("shear_modulus_GPa")) return 1000.0 * element["shear_modulus_GPa"].Positive();
  return 1000.0 * root["material"]["shear_modulus_GPa"].Positive();
}
double YoungsMPa(const Node& element, const Node& root) {
  if (element.Has("youngs_modulus_GPa")) return 1000.0 * element["youngs_modulus_GPa"].Positive();
  return 1000.0 * root["material"]["youngs_modulus_GPa"].Positive();
}

// Outer and inner diameter with inner < outer.
std::pair<double, double> Diameters(const Node& e, const std::string& outer_key) {
  const double outer = e[outer_key].Positive();
  const double inner = e.NonNegativeOr("inner_diameter_mm", 0.0);
  if (!(inner < outer)) e["inner_diameter_mm"].Fail("a number < " + outer_key + " (" + Describe(e[outer_key].json()) + ")");
  return {outer, inner};
}

// One parsed element: its spec, plus extra result fields and files (a reducer's ripple).
struct ParsedElement {
  ElementSpec spec;
  // For a reducer: ∂ln R/∂ln p of its own rigidity w.r.t. its dimensions (its spec's parameters
  // are a precomputed ratio and rigidity, which are not design choices).
  std::vector<std::pair<std::string, double>> own_elasticity;
  nlohmann::json extra;
  std::map<std::string, std::string> files;
};

// A lobe cam reducer as a chain element: a gear stage of ratio |r_i| (input on the A side) whose
// own rigidity is the reducer's mean secant torsional stiffness at the output under its load
// (model/rigidity/lcr_stiffness.h) and whose backlash is the dead band of a roller clearance.
void ParseReducerElement(const Node& e, const Node& root, size_t index, const RunContext& ctx,
                         ParsedElement& parsed) {
  const lcr::Reducer<double> r = ParseReducer(e["reducer"]);
  if (e.Has("material")) e["material"].CheckKnownFields({"youngs_modulus_GPa", "poisson_ratio"});
  const lcr::Material material =
      ParseMaterial(e.Has("material") ? e["material"] : root["material"]);
  const Node load = e["load"];
  load.CheckKnownFields({"output_torque_Nm"});
  const double torque = load["output_torque_Nm"].Positive() * 1000.0;  // N·mm
  const double clearance = e.NonNegativeOr("clearance_um", 0.0) / 1000.0;  // mm
  // Needle bearing radial stiffness per roller, in series with its contact; absent = rigid.
  const double bearing = e.Has("needle_bearing_radial_stiffness_N_per_mm")
                             ? e["needle_bearing_radial_stiffness_N_per_mm"].Positive()
                             : 0.0;
  const int steps = e.IntegerOr("angle_steps", 8, 720);
  const std::string direction = e.StringOr("direction", "forward");
  if (direction != "forward" && direction != "reverse") e["direction"].Fail("\"forward\" or \"reverse\"");
  // The paper's load sense drives the output along its motion; "reverse" loads the other rollers.
  const double sense = lcr::LoadedArmSign(r, lcr::Side::kOutput) * (direction == "forward" ? 1.0 : -1.0);
  const double ratio = std::abs(lcr::SpeedReductionRatio(r));

  rigidity::ReducerStiffnessCycle cycle, reverse;
  std::vector<double> torques, rotations;
  double dead_band = 0;
  try {
    Progress progress("lobe_cam_reducer stiffness", ctx.quiet);
    cycle = rigidity::StiffnessCycle(r, material, sense * torque, clearance, steps, bearing);
    progress.Update(0.4);
    reverse = rigidity::StiffnessCycle(r, material, -sense * torque, clearance, steps, bearing);
    progress.Update(0.6);
    // Lost-motion curve from −T to +T (sense of the load), mean over 36 input angles (the arms
    // repeat with the roller pitch, 13- or 15-fold, so a uniform 10° grid averages them well).
    torques = rigidity::LostMotionTorques(torque);
    rotations = rigidity::LostMotionCurveInSense(r, material, torques, sense, clearance, std::min(steps, 36), bearing);
    dead_band = rigidity::DeadBand(r, clearance, steps);
    progress.Update(1.0);
  } catch (const std::domain_error& err) {
    e.FailWith(std::string("the reducer cannot carry the load: ") + err.what());
  }
  // Lost motion as reducer catalogues define it (±3 % of the rated torque, here the load torque).
  const double lost_motion =
      rigidity::LostMotion(r, material, sense * torque, clearance, std::min(steps, 36), bearing);
  parsed.own_elasticity = rigidity::ReducerStiffnessElasticities(
      r, material, sense * torque, clearance, bearing, std::min(steps, 180));

  ElementSpec& s = parsed.spec;
  s.kind = ElementKind::kFixed;
  s.param_names = {"ratio", "rigidity_Nmm_per_rad"};
  s.params = {ratio, cycle.mean_secant_Nmm_per_rad};
  s.backlash_rad += dead_band;

  const double per_arcmin = kArcminPerRad;  // N·m/rad -> N·m/arcmin divides by this
  nlohmann::json x;
  x["speed_reduction_ratio"] = lcr::SpeedReductionRatio(r);
  x["output_torque_Nm"] = torque / 1000.0;
  x["direction"] = direction;
  x["clearance_um"] = clearance * 1000.0;
  if (bearing > 0) x["needle_bearing_radial_stiffness_N_per_mm"] = bearing;
  x["contact_law"] = "Palmgren line contact, delta = 3.84e-5 Q^0.9 / L^0.8 (steel), scaled by E*";
  x["mean_secant_rigidity_Nm_per_rad"] = cycle.mean_secant_Nmm_per_rad / 1000.0;
  x["mean_secant_rigidity_Nm_per_arcmin"] = cycle.mean_secant_Nmm_per_rad / 1000.0 / per_arcmin;
  x["min_secant_rigidity_Nm_per_rad"] = cycle.min_secant_Nmm_per_rad / 1000.0;
  x["max_secant_rigidity_Nm_per_rad"] = cycle.max_secant_Nmm_per_rad / 1000.0;
  x["secant_ripple"] = cycle.ripple;
  x["mean_tangent_rigidity_Nm_per_rad"] = cycle.mean_tangent_Nmm_per_rad / 1000.0;
  x["min_tangent_rigidity_Nm_per_rad"] = cycle.min_tangent_Nmm_per_rad / 1000.0;
  x["max_tangent_rigidity_Nm_per_rad"] = cycle.max_tangent_Nmm_per_rad / 1000.0;
  x["reverse_mean_secant_rigidity_Nm_per_rad"] = reverse.mean_secant_Nmm_per_rad / 1000.0;
  x["rigidity_at_input_Nm_per_rad"] = cycle.mean_secant_Nmm_per_rad / 1000.0 / (ratio * ratio);
  x["mean_elastic_rotation_arcmin"] = torque / cycle.mean_secant_Nmm_per_rad * per_arcmin;
  x["lost_motion_arcmin_at_3pct_torque"] = lost_motion * per_arcmin;
  x["dead_band_arcmin"] = dead_band * per_arcmin;
  x["max_roller_force_input_N"] = HardMax(cycle.max_force_input_N);
  x["max_roller_force_output_N"] = HardMax(cycle.max_force_output_N);
  parsed.extra = x;

  const std::string stem = "reducer_" + std::to_string(index + 1);
  Table t;
  std::vector<double> deg, rot_arcmin, sec, tan;
  for (size_t i = 0; i < cycle.theta_rad.size(); ++i) {
    deg.push_back(cycle.theta_rad[i] * 180.0 / kPi);
    rot_arcmin.push_back(cycle.rotation_rad[i] * per_arcmin);
    sec.push_back(cycle.secant_Nmm_per_rad[i] / 1000.0);
    tan.push_back(cycle.tangent_Nmm_per_rad[i] / 1000.0);
  }
  t.Add("input_angle_deg", deg);
  t.Add("output_rotation_arcmin", rot_arcmin);
  std::vector<double> el_arcmin;
  for (double v : cycle.elastic_rotation_rad) el_arcmin.push_back(v * per_arcmin);
  t.Add("elastic_rotation_arcmin", el_arcmin);
  t.Add("secant_rigidity_Nm_per_rad", sec);
  t.Add("tangent_rigidity_Nm_per_rad", tan);
  t.Add("max_roller_force_input_N", cycle.max_force_input_N);
  t.Add("max_roller_force_output_N", cycle.max_force_output_N);
  parsed.files[stem + "_stiffness.csv"] = ToCsv(t);
  parsed.files[stem + "_stiffness.svg"] = SvgLinePlot(
      {{"secant", deg, sec}, {"tangent", deg, tan}},
      {"Torsional rigidity at the output over one input turn (" + s.name + ")", "input angle [deg]",
       "rigidity [N·m/rad]"});
  Table lmt;
  std::vector<double> t_nm, r_arcmin;
  for (size_t i = 0; i < torques.size(); ++i) {
    t_nm.push_back(torques[i] / 1000.0);
    r_arcmin.push_back(rotations[i] * per_arcmin);
  }
  lmt.Add("output_torque_Nm", t_nm);
  lmt.Add("output_rotation_arcmin", r_arcmin);
  parsed.files[stem + "_lost_motion.csv"] = ToCsv(lmt);
  parsed.files[stem + "_lost_motion.svg"] = SvgLinePlot(
      {{"mean over the input turn", r_arcmin, t_nm}},
      {"Lost-motion curve, input held (" + s.name + ")", "output rotation [arcmin]", "output torque [N·m]"});
}

ParsedElement ParseElement(const Node& e, const Node& root, size_t index, const RunContext& ctx) {
  ParsedElement parsed;
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
    ParseReducerElement(e, root, index, ctx, parsed);
  } else {
    e["element"].Fail(
        "an element kind (shaft_torsion, shaft_bending, linear_stiffness, chain_span, belt_span, "
        "pull_rod, lever, coupling, gear_stage, lobe_cam_reducer)");
  }
  return parsed;
}

nlohmann::json FiniteOrNull(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

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

void RunTransmissionRigidity(const Node& root, const RunContext& ctx, Outputs& out) {
  root.CheckKnownFields({"study", "name", "description", "material", "chain", "load_torque_Nm", "report_radius_mm"});
  // The chain's material serves every element, so it may hold the fields of any of them.
  if (root.Has("material"))
    root["material"].CheckKnownFields({"shear_modulus_GPa", "youngs_modulus_GPa", "poisson_ratio"});
  const std::string name = root.StringOr("name", "transmission");
  const Node chain = root["chain"];
  const std::vector<Node> nodes = chain.Elements();
  if (nodes.empty()) chain.Fail("a non-empty array of elements");
  std::vector<ElementSpec> specs;
  std::vector<ParsedElement> parsed;
  for (size_t i = 0; i < nodes.size(); ++i) {
    parsed.push_back(ParseElement(nodes[i], root, i, ctx));
    specs.push_back(parsed.back().spec);
  }

  const auto r = rigidity::EvaluateChain<double>(specs);
  if (!(r.compliance_b > 0.0))
    chain.FailWith("every element is rigid: the chain has no compliance to report");
  // Elasticities of the overall rigidity per element parameter; a reducer's are its own times its
  // compliance share (∂ln R/∂ln p = share · ∂ln R_k/∂ln p).
  const auto chain_elasticity = rigidity::RigidityElasticities(specs);
  std::vector<std::vector<std::string>> el_names(specs.size());
  std::vector<std::vector<double>> elasticity(specs.size());
  for (size_t i = 0; i < specs.size(); ++i) {
    if (specs[i].kind == ElementKind::kFixed) {
      for (const auto& [n, v] : rigidity::ChainElasticities(r.share[i], parsed[i].own_elasticity)) {
        el_names[i].push_back(n);
        elasticity[i].push_back(v);
      }
    } else {
      el_names[i] = specs[i].param_names;
      elasticity[i] = chain_elasticity[i];
    }
  }

  nlohmann::json result;
  result["study"] = "transmission_rigidity";
  result["name"] = name;
  result["rigidity_Nm_per_rad"] = Finite(1.0e-3 / r.compliance_b, "rigidity");
  result["rigidity_at_end_b_Nm_per_rad"] = 1.0e-3 / r.compliance_b;
  result["rigidity_at_end_a_Nm_per_rad"] = Finite(1.0e-3 / r.compliance_a, "rigidity at end A");
  result["total_ratio"] = r.total_ratio;
  result["backlash_at_end_b_arcmin"] = r.backlash_b * kArcminPerRad;
  result["backlash_at_end_a_arcmin"] = r.backlash_a * kArcminPerRad;
  if (root.Has("report_radius_mm")) {
    const double rr = root["report_radius_mm"].Positive();
    // Eq. 5 transposed: the linear stiffness at a radius of end B (e.g. at the follower roller).
    result["report_radius_mm"] = rr;
    result["linear_stiffness_at_report_radius_N_per_mm"] = 1.0 / (r.compliance_b * rr * rr);
  }
  if (root.Has("load_torque_Nm")) {
    const double t = root["load_torque_Nm"].Positive();
    result["load_torque_Nm"] = t;
    result["deflection_at_end_b_deg"] = 1000.0 * t * r.compliance_b * 180.0 / kPi;
  }

  Table table;
  std::vector<double> col_idx, col_own, col_at_b, col_share, col_without, col_backlash;
  nlohmann::json elements = nlohmann::json::array();
  for (size_t i = 0; i < specs.size(); ++i) {
    const ElementSpec& s = specs[i];
    const auto link = rigidity::EvaluateElement<double>(s, s.params);
    nlohmann::json e;
    e["index"] = i;
    e["name"] = s.name;
    e["element"] = s.kind_name;
    e["rigidity_Nm_per_rad"] = FiniteOrNull(1.0e-3 / link.compliance);  // null: rigid
    e["rigidity_at_end_b_Nm_per_rad"] = FiniteOrNull(1.0e-3 / r.compliance_at_b[i]);
    e["compliance_share"] = r.share[i];
    // The paper's remark on the stepped shaft: the overall rigidity had this element been
    // ignored (made rigid).
    e["rigidity_if_rigid_Nm_per_rad"] = FiniteOrNull(1.0e-3 / (r.compliance_b - r.compliance_at_b[i]));
    if (s.kind == ElementKind::kGearStage || s.kind == ElementKind::kFixed) e["ratio"] = s.params[0];
    e["backlash_arcmin"] = s.backlash_rad * kArcminPerRad;
    e["backlash_at_end_b_arcmin"] = r.backlash_at_b[i] * kArcminPerRad;
    nlohmann::json el = nlohmann::json::object();
    for (size_t q = 0; q < el_names[i].size(); ++q) el[el_names[i][q]] = elasticity[i][q];
    e["rigidity_elasticity"] = el;
    if (!parsed[i].extra.is_null()) e["reducer"] = parsed[i].extra;
    elements.push_back(e);
    col_idx.push_back(static_cast<double>(i));
    col_own.push_back(1.0e-3 / link.compliance);
    col_at_b.push_back(1.0e-3 / r.compliance_at_b[i]);
    col_share.push_back(r.share[i]);
    col_without.push_back(1.0e-3 / (r.compliance_b - r.compliance_at_b[i]));
    col_backlash.push_back(r.backlash_at_b[i] * kArcminPerRad);
  }
  result["elements"] = elements;

  // The dominant element and its most effective dimension (largest |elasticity| other than a
  // modulus or a gear ratio, which are rarely free choices).
  const int d = r.dominant;
  const ElementSpec& ds = specs[d];
  nlohmann::json dom;
  dom["index"] = d;
  dom["name"] = ds.name;
  dom["element"] = ds.kind_name;
  dom["compliance_share"] = r.share[d];
  std::string advice = ds.name + " (" + ds.kind_name + ") holds " +
                       std::to_string(static_cast<int>(std::lround(100.0 * r.share[d]))) +
                       "% of the compliance: " + KindAdvice(ds.kind_name) + ".";
  int best_q = -1;
  for (size_t q = 0; q < el_names[d].size(); ++q) {
    const std::string& pn = el_names[d][q];
    if (pn.find("modulus") != std::string::npos || pn == "ratio") continue;
    if (best_q < 0 || std::abs(elasticity[d][q]) > std::abs(elasticity[d][best_q])) best_q = static_cast<int>(q);
  }
  if (best_q >= 0) {
    char buf[200];
    std::snprintf(buf, sizeof buf, " Most effective dimension: %s (%+.2f%% overall rigidity per +1%%).",
                  el_names[d][best_q].c_str(), elasticity[d][best_q]);
    advice += buf;
    dom["most_effective_parameter"] = el_names[d][best_q];
    dom["most_effective_parameter_elasticity"] = elasticity[d][best_q];
  }
  dom["advice"] = advice;
  result["dominant"] = dom;
  out.AddJson("result.json", result);

  // CSV: one row per element; infinite rigidities (rigid elements) are written as "inf".
  table.Add("index", col_idx);
  table.Add("rigidity_Nm_per_rad", col_own);
  table.Add("rigidity_at_end_b_Nm_per_rad", col_at_b);
  table.Add("compliance_share", col_share);
  table.Add("rigidity_if_rigid_Nm_per_rad", col_without);
  table.Add("backlash_at_end_b_arcmin", col_backlash);
  out.Add("elements.csv", ToCsv(table));
  for (const ParsedElement& p : parsed)
    for (const auto& [file, content] : p.files) out.Add(file, content);
}

CAMOPT_REGISTER_STUDY("transmission_rigidity", RunTransmissionRigidity);

}  // namespace
}  // namespace camopt::studies
