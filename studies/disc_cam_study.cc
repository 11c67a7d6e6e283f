#include "studies/disc_cam_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "model/disc_cam/check.h"
#include "model/disc_cam/flat_faced.h"
#include "model/disc_cam/oscillating_flat_faced.h"
#include "studies/design_issue_paths.h"
#include "studies/format.h"
#include "studies/kind.h"
#include "studies/material_input.h"
#include "studies/motion_input.h"
#include "studies/report.h"
#include "studies/studio_mechanism.h"
#include "studies/work_limits.h"
#include "studies/writers.h"

namespace camopt::studies::disc_cam {
namespace {

namespace dc = camopt::disc_cam;
using dc::CamPoint;
using dc::DiscCam;
using dc::FollowerType;

constexpr double kDeg = kPi / 180.0;
// Default pressure-angle limits [deg]: 30° for a translating and 45° for an oscillating roller
// follower (Rothbart, Cam Design Handbook, ch. 6 "pressure angle"; Norton, Design of Machinery,
// §8.8: "keep the pressure angle between about ±30° for a translating roller follower").
constexpr double kDefaultPressureAngleTranslatingDeg = 30.0;
constexpr double kDefaultPressureAngleOscillatingDeg = 45.0;

// Cam-angle intervals [deg] where flag is set, on a uniform grid of n points over 360°.
std::vector<std::pair<double, double>> Intervals(const std::vector<bool>& flag) {
  std::vector<std::pair<double, double>> out;
  const size_t n = flag.size();
  for (size_t i = 0; i < n; ++i) {
    if (!flag[i] || (i > 0 && flag[i - 1])) continue;
    size_t j = i;
    while (j + 1 < n && flag[j + 1]) ++j;
    out.push_back({360.0 * i / n, 360.0 * j / n});
  }
  return out;
}

// The value (or its cam angle) of an extreme that may not exist: NaN (null in result.json) when not.
double AtAngleOrNaN(const std::optional<AtAngle>& x, bool angle) {
  if (!x) return NAN;
  return angle ? x->cam_angle_deg : x->value;
}

// The model of an oscillating flat-faced follower (model/disc_cam/oscillating_flat_faced.h) of a study.
dc::OscillatingFlatFaced OscillatingFlatFace(const Study& s) {
  dc::OscillatingFlatFaced c;
  c.base_radius = s.cam.base_radius;
  c.pivot_distance = s.cam.pivot_distance;
  c.face_offset = s.face_offset_mm;
  c.motion = s.cam.motion;
  return c;
}

// An oscillating flat face's feasibility over the analysis grid (CheckOscillatingFlatFaced): the face
// must reach the base circle (named at the pivot distance), the arm stay in (0, 180) deg and turn
// slower than the cam (named at the motion).
void CheckOscillatingFlatFace(const Study& s, const Node& root) {
  const dc::OscillatingFlatFaced c = OscillatingFlatFace(s);
  const std::string issue = dc::CheckOscillatingFlatFaced(c, s.in.analysis.angle_steps);
  if (issue.empty()) return;
  if (!(c.base_radius + c.face_offset < c.pivot_distance))
    root["follower"]["pivot_distance_mm"].FailWith(issue + " (" + Format(c.base_radius) + " + " + Format(c.face_offset) +
                                                   " = " + Format(c.base_radius + c.face_offset) + " mm, pivot distance " +
                                                   Format(c.pivot_distance) + " mm)");
  root["motion"].FailWith(issue + " (docs/disc_cam.md, 'Oscillating flat-faced follower')");
}

// Arg max / arg min over a uniform grid of n cam angles over 360°, the angle of a grid index, and a
// column of the grid (the series of result.json and series.csv).
struct Grid {
  int n;
  template <typename F>
  int ArgMax(F f) const {
    int best = 0;
    for (int i = 1; i < n; ++i)
      if (f(i) > f(best)) best = i;
    return best;
  }
  template <typename F>
  int ArgMin(F f) const {
    return ArgMax([&](int i) { return -f(i); });
  }
  double AngleDeg(int i) const { return 360.0 * i / n; }
  template <typename F>
  std::vector<double> Col(F f) const {
    std::vector<double> c(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) c[size_t(i)] = f(i);
    return c;
  }
};

}  // namespace

MotionInputSpec FollowerMotionSpec(bool oscillating) {
  MotionInputSpec spec;
  spec.subject = "follower";
  spec.allow_polynomial = true;
  if (oscillating) {
    spec.rise_key = "rise_deg", spec.rise_scale = kDeg, spec.unit = "deg";
    spec.misplaced_key = "rise_mm";
    spec.misplaced_hint = "a oscillating follower's rise is an angle: use rise_deg";
  } else {
    spec.rise_key = "rise_mm", spec.rise_scale = 1.0, spec.unit = "mm";
    spec.misplaced_key = "rise_deg";
    spec.misplaced_hint = "a translating follower's rise is a length: use rise_mm";
  }
  return spec;
}

nlohmann::ordered_json FollowerMotionRules() {
  return {FollowerRiseRule(FollowerMotionSpec(false), FollowerMotionSpec(true),
                           {"translating_roller", "translating_knife_edge", "translating_flat_faced"}),
          FollowerRiseRule(FollowerMotionSpec(true), FollowerMotionSpec(false),
                           {"oscillating_roller", "oscillating_knife_edge", "oscillating_flat_faced"})};
}

nlohmann::ordered_json Input::MotionSchema(bool /*sizing*/) {
  // disc_cam_min_size sizes translating and oscillating followers alike: the same schema.
  return studies::MotionSchema({FollowerMotionSpec(false), FollowerMotionSpec(true)},
                               {"translating follower", "oscillating follower"}, false);
}

nlohmann::ordered_json Refuse(const std::string& field) {
  return {{"not", {{"required", nlohmann::ordered_json::array({field})}}}};
}

nlohmann::ordered_json Input::Follower::SchemaRules() {
  using oj = nlohmann::ordered_json;
  const oj is_roller = {{"properties", {{"type", {{"enum", RollerTypes()}}}}}};
  const oj is_flat = {{"properties", {{"type", {{"enum", {"translating_flat_faced", "oscillating_flat_faced"}}}}}}};
  const oj is_flat_arm = {{"properties", {{"type", {{"const", "oscillating_flat_faced"}}}}}};
  const oj radius = {{"if", is_roller}, {"then", {{"required", oj::array({"roller_radius_mm"})}}},
                     {"else", Refuse("roller_radius_mm")}};
  const oj face = {{"if", is_flat}, {"else", Refuse("face_width_mm")}};
  const oj face_offset = {{"if", is_flat_arm}, {"else", Refuse("face_offset_mm")}};
  // An oscillating follower sits on a pivot (its arm's length unless a flat face touches the cam);
  // a translating one has an axis offset, which a flat face does not take.
  const oj is_oscillating = {{"properties", {{"type", {{"enum", {"oscillating_roller", "oscillating_knife_edge",
                                                                   "oscillating_flat_faced"}}}}}}};
  const oj is_translating_flat = {{"properties", {{"type", {{"const", "translating_flat_faced"}}}}}};
  const oj pivot = {{"if", is_oscillating},
                    {"then", {{"allOf", oj::array({{{"required", oj::array({"pivot_distance_mm"})}},
                                                   Refuse("offset_mm")})},
                              {"if", is_flat_arm},
                              {"then", Refuse("arm_length_mm")},
                              {"else", {{"required", oj::array({"arm_length_mm"})}}}}},
                    {"else", {{"allOf", oj::array({Refuse("pivot_distance_mm"), Refuse("arm_length_mm")})}}}};
  const oj offset = {{"if", is_translating_flat}, {"then", Refuse("offset_mm")}};
  return {{"allOf", oj::array({radius, face, face_offset, pivot, offset})}};
}

nlohmann::ordered_json FollowerTypeIs(const std::vector<std::string>& types) {
  return {{"required", nlohmann::ordered_json::array({"follower"})},
          {"properties", {{"follower", {{"properties", {{"type", {{"enum", types}}}}}}}}}};
}


nlohmann::ordered_json DesignSchemaRules() {
  using oj = nlohmann::ordered_json;
  const std::vector<std::string> oscillating = {"oscillating_roller", "oscillating_knife_edge",
                                                "oscillating_flat_faced"};
  // Without a roller: no cutter path of a roller's size.
  const oj no_roller = {{"if", FollowerTypeIs({"translating_knife_edge", "oscillating_knife_edge",
                                               "translating_flat_faced", "oscillating_flat_faced"})},
                        {"then", Refuse("cutter_radius_mm")}};
  // A knife edge: a point contact, no contact-stress limit.
  const oj knife = {{"if", FollowerTypeIs({"translating_knife_edge", "oscillating_knife_edge"})},
                    {"then", {{"properties", {{"limits", Refuse("contact_stress_MPa")}}}}}};
  // The arm's loads: oscillating followers only; their follower loads: translating followers only.
  const oj arm = {{"if", FollowerTypeIs({"translating_roller", "translating_knife_edge", "translating_flat_faced"})},
                  {"then", Refuse("arm_dynamics")}};
  const oj translating_loads = {{"if", FollowerTypeIs(oscillating)}, {"then", Refuse("dynamics")}};
  // The contact-stress limit needs the contact's length, the material and the contact force (the
  // follower's loads, or the arm's).
  const oj stress_limit = {
      {"if", {{"required", oj::array({"limits"})},
              {"properties", {{"limits", {{"required", oj::array({"contact_stress_MPa"})}}}}}}},
      {"then",
       {{"required", oj::array({"face_width_mm", "material"})},
        {"if", FollowerTypeIs(oscillating)},
        {"then", {{"required", oj::array({"arm_dynamics"})}}},
        {"else", {{"required", oj::array({"dynamics"})}}}}}};
  const oj keyway = {{"dependentRequired", {{"keyway", oj::array({"bore_diameter_mm"})}}}};
  oj all = oj::array({no_roller, knife, arm, translating_loads, stress_limit, keyway});
  for (const oj& rule : FollowerMotionRules()) all.push_back(rule);
  return all;
}

std::vector<CrossFieldRule> Input::CrossFieldRules() {
  std::vector<CrossFieldRule> rules = MotionRules();
  rules.push_back(MountingRule());
  return rules;
}

nlohmann::ordered_json Input::SchemaRules() {
  using oj = nlohmann::ordered_json;
  // Without a roller the profile stage only and no tolerances (the mechanical error rolls a roller
  // on the profile).
  const oj profile_only = {{"items", {{"const", "profile"}}}};
  const oj no_roller = {
      {"if", FollowerTypeIs({"translating_knife_edge", "oscillating_knife_edge", "translating_flat_faced",
                             "oscillating_flat_faced"})},
      {"then", {{"properties", {{"analysis", {{"properties", {{"evaluate", profile_only}}}}}}},
                {"not", {{"required", oj::array({"tolerances"})}}}}}};
  // The error stages need the tolerances.
  const oj error_stage = {
      {"if", {{"required", oj::array({"analysis"})},
              {"properties",
               {{"analysis",
                 {{"required", oj::array({"evaluate"})},
                  {"properties", {{"evaluate", {{"contains", {{"enum", {"error", "monte_carlo"}}}}}}}}}}}}}},
      {"then", {{"required", oj::array({"tolerances"})}}}};
  oj all = DesignSchemaRules();
  all.push_back(no_roller);
  all.push_back(error_stage);
  return {{"allOf", all}};
}

// The checks that span fields (the follower's fields by its type, lengths against the base
// circle, the motion, the stages and the contact-stress limit against their inputs, the design
// over the cycle) and the conversion of the declared input to model units.
namespace {
Study ParseDesign(const Node& root);
}  // namespace

Study Parse(const Node& root) {
  Study s = ParseDesign(root);
  const Input& in = s.in;
  if (in.measured_profile) {
    const InspectedPart part = CamPart(s);
    // Covering: no arc between neighbouring points longer than 1/64 of the profile.
    s.measured = ReadMeasuredProfile(root["measured_profile"], part, part.profile.length_mm() / 64.0);
  }
  return s;
}

InspectedPart CamPart(const Study& s) {
  const DiscCam& cam = s.cam;
  profile::Curve curve;
  if (s.contact == Study::Contact::kFlatFaced && cam.follower == FollowerType::kOscillatingRoller) {
    curve = profile::CurveFromPoints(
        [c = OscillatingFlatFace(s)](double th) { return dc::EvaluateOscillatingFlatFaced(c, th).contact; }, 1e-3);
  } else if (s.contact == Study::Contact::kFlatFaced) {
    curve = profile::CurveFromPoints(
        [cam](double th) { return dc::EvaluateFlatFaced(cam.motion, cam.base_radius, th).contact; }, 1e-3);
  } else {
    // The roller's (or knife edge's) contact A = C − r_f n: exact normal n of the pitch curve C,
    // dA/dθ = |C'| (1 − r_f κ) T, curvature κ/(1 − r_f κ) (κ > 0 convex), turned to the left-positive
    // sign of the direction of increasing θ.
    curve = [cam](double th) {
      const CamPoint<double> p = dc::EvaluateCam(cam, th);
      profile::CurvePoint c;
      c.point = p.contact;
      const double v = p.pitch_d1.norm(), shrink = 1.0 - cam.roller_radius * p.pitch_curvature;
      c.tangent = p.pitch_d1 / v;
      c.speed = v * std::abs(shrink);
      const double left = Cross(c.tangent, p.normal) < 0 ? 1.0 : -1.0;  // outward normal on the right: ccw
      c.curvature = left * p.pitch_curvature / shrink;
      return c;
    };
  }
  return {"profile",
          "the cam frame of profile.dxf: origin at the cam's axis of rotation, the profile point at parameter theta "
          "the one in contact at cam angle theta",
          "the cam's axis of rotation (its bore)", profile::ClosedProfile(curve, 0.0, 2.0 * kPi, 4096)};
}

namespace {

Study ParseDesign(const Node& root) {
  Study s;
  s.in = Read<Input>(root);
  const Input& in = s.in;
  DiscCam& cam = s.cam;

  const Node follower = root["follower"];
  const std::string& type = in.follower.type;
  const bool oscillating = type.rfind("oscillating_", 0) == 0;
  s.contact = type.ends_with("_roller")       ? Study::Contact::kRoller
              : type.ends_with("_knife_edge") ? Study::Contact::kKnifeEdge
                                              : Study::Contact::kFlatFaced;
  const bool roller = s.contact == Study::Contact::kRoller;
  const bool flat = s.contact == Study::Contact::kFlatFaced;
  if (flat && oscillating) {
    // Its base circle, motion and pivot distance (model/disc_cam/oscillating_flat_faced.h), no arm length:
    // the face, not a roller, touches the cam.
    follower.CheckKnownFields({"type", "pivot_distance_mm", "face_offset_mm", "face_width_mm"});
    cam.follower = FollowerType::kOscillatingRoller;
    cam.pivot_distance = follower["pivot_distance_mm"].Positive();  // required: "missing required field"
    s.face_offset_mm = in.follower.face_offset_mm.value_or(0.0);
  } else if (flat) {
    follower.CheckKnownFields({"type", "face_width_mm"});
    cam.follower = FollowerType::kTranslatingRoller;  // its base circle and motion only
  } else if (!oscillating) {
    if (roller) follower.CheckKnownFields({"type", "offset_mm", "roller_radius_mm"});
    else follower.CheckKnownFields({"type", "offset_mm"});
    cam.follower = FollowerType::kTranslatingRoller;
    cam.offset = in.follower.offset_mm.value_or(0.0);
  } else {
    if (roller) follower.CheckKnownFields({"type", "roller_radius_mm", "pivot_distance_mm", "arm_length_mm"});
    else follower.CheckKnownFields({"type", "pivot_distance_mm", "arm_length_mm"});
    cam.follower = FollowerType::kOscillatingRoller;
    cam.pivot_distance = follower["pivot_distance_mm"].Positive();  // required: "missing required field"
    cam.arm_length = follower["arm_length_mm"].Positive();
  }
  cam.base_radius = in.base_circle_radius_mm;
  // A knife edge is the roller model with r_f = 0 (its profile is the pitch curve); a flat face has
  // no roller.
  cam.roller_radius =
      roller ? PlausibleLength(follower["roller_radius_mm"], cam.base_radius, "the base circle radius") : 0.0;
  if (in.follower.face_width_mm)
    s.follower_face_width_mm = PlausibleLength(follower["face_width_mm"], cam.base_radius, "the base circle radius");
  if (in.follower.face_offset_mm && !std::isfinite(*in.follower.face_offset_mm))
    follower["face_offset_mm"].Fail("a finite length");
  if (!flat)
    FailOnFirst(dc::CheckGeometry(cam), root, DiscCamIssuePaths());
  // Without a roller: no mechanical error (Rzine et al.'s eqs. 16–32 and the exact-motion check
  // roll a roller of radius r_f + Δr_f on the profile: the stages and the tolerances are refused)
  // and no cutter path of a roller's size.
  const std::string no_roller = flat ? "a flat-faced follower" : "a knife-edge follower";
  if (!roller && in.cutter_radius_mm)
    root["cutter_radius_mm"].FailWith("a cutter path is written for a roller follower only (its radius r_t <= r_f), "
                                      "not for " + no_roller + ": remove \"cutter_radius_mm\"");
  if (!roller && in.tolerances)
    root["tolerances"].FailWith("the tolerance analysis (the mechanical error of Rzine et al., which rolls a roller on "
                                "the profile) is computed for roller followers only, not for " + no_roller +
                                ": remove \"tolerances\" (docs/disc_cam.md)");
  if (!roller && in.analysis.evaluate)
    for (size_t i = 0; i < in.analysis.evaluate->size(); ++i)
      if ((*in.analysis.evaluate)[i] != "profile")
        root["analysis"]["evaluate"][i].FailWith(
            "the stage \"" + (*in.analysis.evaluate)[i] + "\" (the mechanical error of Rzine et al.) is computed for "
            "roller followers only, not for " + no_roller + ": evaluate [\"profile\"] only (docs/disc_cam.md)");

  // Motion program: rise in mm (translating) or degrees (oscillating); durations in degrees.
  cam.motion = ParseMotionProgram(root["motion"], FollowerMotionSpec(oscillating));

  s.geometry = GeometryFileOptionsOf(in.geometry_files);
  if (in.cam_thickness_mm)
    s.cam_thickness_mm = PlausibleLength(root["cam_thickness_mm"], cam.base_radius, "the base circle radius");
  if (in.cutter_radius_mm) {
    s.cutter_radius_mm = *in.cutter_radius_mm;
    if (s.cutter_radius_mm > cam.roller_radius)
      root["cutter_radius_mm"].Fail("a cutter radius <= the roller radius (" + Format(cam.roller_radius, 6) + " mm)");
  }
  if (in.bore_diameter_mm)
    s.bore_diameter_mm = ParseBoreDiameter(root["bore_diameter_mm"], 2 * cam.base_radius, "the base circle diameter");
  if (in.keyway || in.bolt_circle)
    s.mounting = ParseMounting(root, in.keyway, in.bolt_circle, s.bore_diameter_mm, 2 * cam.base_radius,
                               "the base circle diameter");
  if (in.tolerances) {
    s.tolerances.radial = in.tolerances->profile_radial_um * 1e-3;
    s.tolerances.roller = in.tolerances->roller_radius_um * 1e-3;
    s.tolerances.normal = in.tolerances->profile_normal_um * 1e-3;
  }
  // Limits of the verdict; defaults are the textbook rules (docs/disc_cam.md "Limits and verdict").
  s.limits.pressure_angle_deg = oscillating ? kDefaultPressureAngleOscillatingDeg : kDefaultPressureAngleTranslatingDeg;
  s.limits.radius_margin_mm = cam.roller_radius;  // 0 without a roller: a convex flat-faced cam
  const Input::Limits limits = in.limits.value_or(Input::Limits{});
  if (limits.pressure_angle_deg) {
    s.limits.pressure_angle_deg = *limits.pressure_angle_deg;
    s.limits.pressure_angle_default = false;
  }
  if (limits.radius_margin_mm) {
    s.limits.radius_margin_mm = *limits.radius_margin_mm;
    s.limits.radius_margin_default = false;
  }
  if (in.face_width_mm)
    s.face_width_mm = PlausibleLength(root["face_width_mm"], cam.base_radius, "the base circle radius");
  if (in.material) s.material = in.material->ToMaterial();
  if (in.dynamics) {
    if (oscillating && flat)
      root["dynamics"].FailWith(
          "the kinetostatic loads of \"dynamics\" are implemented for translating followers only: an oscillating "
          "flat-faced follower's arm takes \"arm_dynamics\" (its moment of inertia and the moments about its pivot)");
    if (oscillating)
      root["dynamics"].FailWith(
          "the follower loads of \"dynamics\" (mass, spring force, load along a line) are for translating "
          "followers only: an oscillating follower's arm takes \"arm_dynamics\" (its moment of inertia about the "
          "pivot, spring rate and moments), or use follower.type \"translating_" +
          type.substr(std::string("oscillating_").size()) + "\"");
    const Input::Dynamics& d = *in.dynamics;
    Study::Dynamics dyn;
    dyn.speed_rpm = d.speed_rpm;
    dyn.loads.mass_kg = d.follower_mass_kg;
    dyn.loads.spring_rate_N_per_mm = d.spring_rate_N_per_mm;
    dyn.loads.spring_preload_N = d.spring_preload_N;
    dyn.loads.external_load_N = d.external_load_N;
    dyn.follower_axis = d.follower_axis;
    dyn.follower_stiffness_N_per_mm = d.follower_stiffness_N_per_mm;
    dyn.damping_ratio = d.damping_ratio;
    dyn.revolutions = d.revolutions;
    // The weight along the follower axis, toward the cam: a follower above the cam presses on it.
    if (dyn.follower_axis == "vertical_above_cam") dyn.loads.weight_N = dyn.loads.mass_kg * dc::kStandardGravity;
    else if (dyn.follower_axis == "vertical_below_cam") dyn.loads.weight_N = -dyn.loads.mass_kg * dc::kStandardGravity;
    else dyn.loads.weight_N = 0.0;  // horizontal
    s.dynamics = dyn;
  }
  if (in.arm_dynamics) {
    if (!oscillating)
      root["arm_dynamics"].FailWith("the arm's loads are for oscillating followers (a pivoted arm) only: a translating "
                                    "follower takes \"dynamics\" (mass, spring, load); remove \"arm_dynamics\"");
    Study::ArmDynamics a;
    a.speed_rpm = in.arm_dynamics->speed_rpm;
    a.loads.inertia_kg_m2 = in.arm_dynamics->arm_inertia_kg_m2;
    a.loads.spring_rate_N_m_per_rad = in.arm_dynamics->spring_rate_N_m_per_rad;
    a.loads.spring_preload_N_m = in.arm_dynamics->spring_preload_N_m;
    a.loads.external_moment_N_m = in.arm_dynamics->external_moment_N_m;
    a.arm_stiffness_N_m_per_rad = in.arm_dynamics->arm_stiffness_N_m_per_rad;
    a.damping_ratio = in.arm_dynamics->damping_ratio;
    a.revolutions = in.arm_dynamics->revolutions;
    s.arm_dynamics = a;
  }
  if (limits.contact_stress_MPa) {
    const Node l = root["limits"]["contact_stress_MPa"];
    if (s.contact == Study::Contact::kKnifeEdge)
      l.FailWith("a knife-edge follower touches the cam at a point (no Hertz line contact to check): remove the "
                 "contact-stress limit, or use a roller or flat-faced follower");
    s.limits.contact_stress_MPa = *limits.contact_stress_MPa;
    std::string missing;
    for (const auto& [absent, what] : {std::pair{!s.face_width_mm, "face_width_mm (the contact length of roller and cam)"},
                                       std::pair{!s.material, "material (youngs_modulus_GPa, poisson_ratio)"},
                                       oscillating
                                           ? std::pair{!s.arm_dynamics, "arm_dynamics (the contact force: speed_rpm, "
                                                                        "arm_inertia_kg_m2, spring)"}
                                           : std::pair{!s.dynamics, "dynamics (the contact force: speed_rpm, "
                                                                    "follower_mass_kg, spring)"}})
      if (absent) missing += (missing.empty() ? "" : ", ") + std::string(what);
    if (!missing.empty()) l.FailWith("the contact stress cannot be checked without " + missing + ": add them or remove the limit");
  }
  dc::MonteCarloOptions& mc = s.monte_carlo_options;
  if (const std::optional<Input::MonteCarlo> o = Enabled(in.analysis.monte_carlo)) {
    mc.samples = o->samples;
    mc.angle_steps = o->angle_steps;
    mc.seed = static_cast<uint64_t>(o->seed);
    mc.scales = o->scales;
    if (double(mc.samples) * mc.angle_steps * mc.scales.size() > 1e8)
      root["analysis"]["monte_carlo"].FailWith("samples × angle_steps × scales must stay below 1e8");
  } else {
    s.monte_carlo = false;
  }
  if (in.analysis.evaluate) {
    // Lazy stages: the profile always runs; "error" adds the mechanical error, "monte_carlo"
    // the error and its Monte-Carlo check. A stage asked for needs its inputs (the tolerances).
    bool error = false, mc_asked = false;
    for (const std::string& stage : *in.analysis.evaluate) {
      if (stage == "error") error = true;
      else if (stage == "monte_carlo") error = mc_asked = true;
    }
    if (error) (void)root["tolerances"];  // "missing required field" when absent
    s.error_stage = error;
    if (!mc_asked) s.monte_carlo = false;
  }
  if (s.tolerances.radial == 0 && s.tolerances.roller == 0 && s.tolerances.normal == 0)
    s.monte_carlo = false;
  if (!roller) s.error_stage = s.monte_carlo = false;  // the profile only (refused above when asked)
  // Feasibility over the cycle, on the analysis grid.
  if (flat && oscillating) {
    CheckOscillatingFlatFace(s, root);
    return s;
  }
  const auto issues = flat ? dc::CheckFlatFaced(cam.motion, cam.base_radius, s.in.analysis.angle_steps)
                           : dc::CheckDesign(cam, s.in.analysis.angle_steps);
  FailOnFirst(issues, root, DiscCamIssuePaths());
  return s;
}

}  // namespace

// The geometry files of the cam: exact profile, pitch curve and cutter path as functions of θ.
PlanarCamFit FitGeometryFiles(const Study& s) {
  const DiscCam& cam = s.cam;
  PlanarCamGeometry g;
  g.file_stem = "profile";
  g.design_name = s.in.name;
  g.cam_name = "disc cam";
  if (s.contact == Study::Contact::kFlatFaced && cam.follower == FollowerType::kOscillatingRoller) {
    // The envelope of the face lines on the arm; no roller, so no pitch curve or cutter path.
    g.profile = [c = OscillatingFlatFace(s)](double th) { return dc::EvaluateOscillatingFlatFaced(c, th).contact; };
    g.cutter_note = "omitted: a flat-faced follower has no roller, so no pitch curve or roller-sized cutter path";
  } else if (s.contact == Study::Contact::kFlatFaced) {
    // The exact profile, the envelope of the face lines; no roller, so no pitch curve or cutter path.
    g.profile = [cam](double th) { return dc::EvaluateFlatFaced(cam.motion, cam.base_radius, th).contact; };
    g.cutter_note = "omitted: a flat-faced follower has no roller, so no pitch curve or roller-sized cutter path";
  } else if (s.contact == Study::Contact::kKnifeEdge) {
    // The profile is the pitch curve (r_f = 0): one curve, on the profile layer.
    g.profile = [cam](double th) { return dc::EvaluateCam(cam, th).contact; };
    g.cutter_note = "omitted: a knife-edge follower's profile is its pitch curve; no cutter path is written";
  } else {
    g.profile = [cam](double th) { return dc::EvaluateCam(cam, th).contact; };
    g.pitch = [cam](double th) { return dc::EvaluateCam(cam, th).pitch; };
  }
  if (s.contact != Study::Contact::kRoller) {
  } else if (s.cutter_radius_mm > 0 && s.cutter_radius_mm != cam.roller_radius) {
    g.cutter = [cam, rt = s.cutter_radius_mm](double th) {
      const CamPoint<double> p = dc::EvaluateCam(cam, th);
      return Vec2<double>(p.pitch + (cam.roller_radius - rt) * (p.contact - p.pitch) / cam.roller_radius);
    };
    g.cutter_diameter_mm = 2 * s.cutter_radius_mm;
  } else {
    g.cutter_note = s.cutter_radius_mm > 0
                        ? "omitted: the cutter equals the roller, so its path is the pitch curve (layer PITCH_CURVE)"
                        : "no cutter_radius_mm given: a cutter of the roller's size follows the pitch curve "
                          "(layer PITCH_CURVE)";
  }
  g.initial_segments = 128;
  g.thickness_mm = s.cam_thickness_mm;
  g.bore_diameter_mm = s.bore_diameter_mm;
  g.mounting = s.mounting;
  return FitPlanarCam(g, s.geometry);
}

// The oscillating arm on its train stiffness (model/disc_cam/follower_dynamics.h, SimulateArm): the
// response at the speed, the normal contact force at the cam M_a/lever(θ) at its samples (lever_m:
// the normal's lever arm about the pivot [m] at a cam angle [rad]), and the dynamic jump speed
// searched as the translating follower's.
template <typename Lever>
void ArmResponse(const Study& s, Result::Loads& L, const Lever& lever_m) {
  if (!s.arm_dynamics || !s.arm_dynamics->arm_stiffness_N_m_per_rad) return;
  const Study::ArmDynamics& a = *s.arm_dynamics;
  const double omega = dc::RadPerSecond(a.speed_rpm);
  dc::ArmDynamicsInput in;
  in.motion = s.cam.motion;
  in.loads = a.loads;
  in.arm_stiffness_N_m_per_rad = *a.arm_stiffness_N_m_per_rad;
  in.damping_ratio = a.damping_ratio;
  in.revolutions = a.revolutions;
  in.speed_rad_s = omega;
  L.arm_response = dc::SimulateArm(in);
  bool first = true;
  for (const dc::ArmDynamicsSample& q : L.arm_response->samples) {
    const double f = q.contact_moment_N_m / lever_m(q.cam_angle_deg * kDeg);
    L.arm_contact_force_N.push_back(f);
    if (first || f < L.min_dynamic_contact_force_N.value) L.min_dynamic_contact_force_N = {f, q.cam_angle_deg};
    if (first || f > L.max_dynamic_contact_force_N.value) L.max_dynamic_contact_force_N = {f, q.cam_angle_deg};
    first = false;
  }
  // The extremes of the moment are located between samples: the force there counts too.
  for (const auto& [m, at] : {std::pair{L.arm_response->min_contact_moment_N_m, L.arm_response->min_contact_moment_cam_angle_deg},
                             std::pair{L.arm_response->max_contact_moment_N_m, L.arm_response->max_contact_moment_cam_angle_deg}}) {
    const double f = m / lever_m(at * kDeg);
    if (f < L.min_dynamic_contact_force_N.value) L.min_dynamic_contact_force_N = {f, at};
    if (f > L.max_dynamic_contact_force_N.value) L.max_dynamic_contact_force_N = {f, at};
  }
  const double reach = std::max(a.speed_rpm, std::isfinite(L.jump_speed_rpm) ? L.jump_speed_rpm : 0.0);
  L.dynamic_jump_upper_rpm = 1.5 * reach;
  L.dynamic_jump = dc::FindArmDynamicJumpSpeed(in, dc::RadPerSecond(L.dynamic_jump_upper_rpm));
  if (L.arm_response->separates && (!L.dynamic_jump->found || L.dynamic_jump->speed_rad_s > omega)) {
    const int runs = L.dynamic_jump->runs;
    L.dynamic_jump_upper_rpm = a.speed_rpm;
    L.dynamic_jump = dc::FindArmDynamicJumpSpeed(in, omega);
    L.dynamic_jump->runs += runs;
  }
}

// The loads' extremes over the grid (contact force, camshaft torque and stress series filled) and,
// with a follower stiffness, the dynamic response and jump speed (the follower's motion only: the
// same for every contact type).
void FinishLoads(const Study& s, Result::Loads& L) {
  const int n = static_cast<int>(L.contact_force_N.size());
  const dc::DiscCam& cam = s.cam;
  const Grid g{n};  // arg max/min and angles over the grid
  const bool stress = L.stress_evaluated;
  const auto& f = L.contact_force_N;
  const auto& tq = L.camshaft_torque_Nm;
  const int i_fmin = g.ArgMin([&](int i) { return f[i]; }), i_fmax = g.ArgMax([&](int i) { return f[i]; });
  L.min_contact_force_N = {f[i_fmin], g.AngleDeg(i_fmin)};
  L.max_contact_force_N = {f[i_fmax], g.AngleDeg(i_fmax)};
  const int i_tabs = g.ArgMax([&](int i) { return std::abs(tq[i]); });
  L.max_abs_camshaft_torque_Nm = {std::abs(tq[i_tabs]), g.AngleDeg(i_tabs)};
  L.min_camshaft_torque_Nm = tq[g.ArgMin([&](int i) { return tq[i]; })];
  L.max_camshaft_torque_Nm = tq[g.ArgMax([&](int i) { return tq[i]; })];
  if (stress) {
    const int i_p = g.ArgMax([&](int i) { return L.contact_stress_MPa[i]; });
    L.max_contact_stress_MPa = {L.contact_stress_MPa[i_p], g.AngleDeg(i_p)};
  }
  // The follower on its own stiffness (model/disc_cam/follower_dynamics.h): the response at the
  // speed, and the lowest speed at which it leaves the cam, searched up to 1.5 times the larger
  // of the speed and the kinetostatic jump speed.
  if (s.dynamics && s.dynamics->follower_stiffness_N_per_mm) {
    const double omega = dc::RadPerSecond(s.dynamics->speed_rpm);
    dc::FollowerDynamicsInput fin;
    fin.motion = cam.motion;
    fin.loads = s.dynamics->loads;
    fin.follower_stiffness_N_per_mm = *s.dynamics->follower_stiffness_N_per_mm;
    fin.damping_ratio = s.dynamics->damping_ratio;
    fin.revolutions = s.dynamics->revolutions;
    fin.speed_rad_s = omega;
    L.response = dc::SimulateFollower(fin);
    const double reach = std::max(s.dynamics->speed_rpm, std::isfinite(L.jump_speed_rpm) ? L.jump_speed_rpm : 0.0);
    L.dynamic_jump_upper_rpm = 1.5 * reach;
    L.dynamic_jump = dc::FindDynamicJumpSpeed(fin, dc::RadPerSecond(L.dynamic_jump_upper_rpm));
    // A separation at the speed itself that the scan stepped over (a resonance band narrower than
    // its step): search below the speed, so that the two answers agree.
    if (L.response->separates && (!L.dynamic_jump->found || L.dynamic_jump->speed_rad_s > omega)) {
      const int runs = L.dynamic_jump->runs;
      L.dynamic_jump_upper_rpm = s.dynamics->speed_rpm;
      L.dynamic_jump = dc::FindDynamicJumpSpeed(fin, omega);
      L.dynamic_jump->runs += runs;
    }
  }
}

Result RunFlatFaced(const Study& s);
Result RunOscillatingFlatFaced(const Study& s);

// The residual-vibration spectrum of each moving segment (model/disc_cam/residual_spectrum.h) with
// the follower's natural frequency and damping ratio from the response, and r = k_f/(k_f + k).
std::optional<Result::Spectrum> ResidualSpectrumOf(const Study& s, const Result& r) {
  if (!r.loads) return std::nullopt;
  double fn = 0.0, speed_rpm = 0.0, zeta = 0.0, ratio = 0.0;
  if (r.loads->response) {
    fn = r.loads->response->natural_frequency_Hz, speed_rpm = s.dynamics->speed_rpm, zeta = s.dynamics->damping_ratio;
    ratio = *s.dynamics->follower_stiffness_N_per_mm /
            (*s.dynamics->follower_stiffness_N_per_mm + s.dynamics->loads.spring_rate_N_per_mm);
  } else if (r.loads->arm_response) {
    fn = r.loads->arm_response->natural_frequency_Hz, speed_rpm = s.arm_dynamics->speed_rpm;
    zeta = s.arm_dynamics->damping_ratio;
    ratio = *s.arm_dynamics->arm_stiffness_N_m_per_rad /
            (*s.arm_dynamics->arm_stiffness_N_m_per_rad + s.arm_dynamics->loads.spring_rate_N_m_per_rad);
  } else {
    return std::nullopt;
  }
  if (!(zeta < 1.0)) return std::nullopt;  // critically damped: no ringing (a note says so)
  Result::Spectrum sp;
  sp.zeta = zeta;
  sp.stiffness_ratio = ratio;
  for (int i = 0; i < kSpectrumPoints; ++i)
    sp.tau.push_back(kSpectrumTauLow + (kSpectrumTauHigh - kSpectrumTauLow) * i / (kSpectrumPoints - 1));
  const double omega = dc::RadPerSecond(speed_rpm);
  const double unit = r.oscillating ? 1.0 / kDeg : 1.0;  // follower unit
  const auto& segs = s.cam.motion.segments();
  for (size_t k = 0; k < segs.size(); ++k) {
    const motion::MotionSegment<double>& seg = segs[k];
    if (seg.law == motion::MotionLaw::kDwell || !(std::abs(seg.rise) > 0.0)) continue;
    Result::SpectrumSegment row;
    row.index = int(k);
    row.law = motion::LawName(seg.law);
    row.tau = seg.duration / omega * fn;  // T/T_n = (β/ω) f_n
    const dc::ResidualAmplitude a = dc::ResidualAmplitudeAt(seg, zeta, row.tau);
    row.amplitude = a.amplitude;
    row.amplitude_error = a.error;
    row.predicted_residual = ratio * std::abs(seg.rise) * a.amplitude * unit;
    row.spectrum = dc::ResidualSpectrum(seg, zeta, sp.tau);
    row.minima = dc::ResidualSpectrumMinima(seg, zeta, kSpectrumTauLow, kSpectrumTauHigh, kSpectrumPoints);
    sp.segments.push_back(std::move(row));
  }
  return sp;
}

Result RunCam(const Study& s, const RunContext& ctx);

namespace {

// The follower's displacement error of the measured cam: at cam angle θ the follower touches the
// profile point of parameter θ, moved by d(θ) along its normal; to first order (Rzine et al.
// eqs. 17, 22, model/disc_cam/mechanical_error.h) ΔS = d/cos φ (translating roller or knife edge),
// d/(l cos φ) (oscillating), and ΔS = d for a translating flat face (its normal is the line of
// motion). Over the study's analysis grid.
DiscCamMeasured MeasuredCam(const Study& s, const Result& r) {
  const MeasuredProfile& m = *s.measured;
  DiscCamMeasured j;
  static_cast<MeasuredBlock&>(j) = MeasuredOf(m, CamPart(s));
  const DiscCam& cam = s.cam;
  const bool oscillating = cam.follower == FollowerType::kOscillatingRoller;
  if (s.contact == Study::Contact::kFlatFaced && oscillating) {
    j.not_computed = {{"the follower's displacement error and the contact stress of the measured cam",
                       "the oscillating flat face's error gain (the contact's distance along the face) is not "
                       "modelled for a measured profile yet"}};
    return j;
  }
  const double unit = oscillating ? 180.0 / kPi * 3600.0 : 1000.0;  // arcsec or µm
  double lo = INFINITY, hi = -INFINITY, lo_at = 0, hi_at = 0, s_lo = INFINITY, s_hi = -INFINITY, n_lo = INFINITY,
         n_hi = -INFINITY;
  const int n = s.in.analysis.angle_steps;
  for (int i = 0; i < n; ++i) {
    const double th = 2.0 * kPi * i / n;
    const double d = m.shape(th);
    double error = d, follower = 0;
    if (s.contact == Study::Contact::kFlatFaced) {
      follower = cam.motion.Evaluate(th).s;
    } else {
      const CamPoint<double> p = dc::EvaluateCam(cam, th);
      dc::Deviations<double> dev;
      dev.normal = d;
      error = dc::FollowerError(cam, p, dev).normal;
      follower = p.s;
    }
    if (error < lo) lo = error, lo_at = th;
    if (error > hi) hi = error, hi_at = th;
    s_lo = std::min(s_lo, follower + error);
    s_hi = std::max(s_hi, follower + error);
    n_lo = std::min(n_lo, follower);
    n_hi = std::max(n_hi, follower);
  }
  DiscCamMeasured::Follower& f = j.follower.emplace();
  f.model = s.contact == Study::Contact::kFlatFaced
                ? "first order: the translating flat face moves by d(theta), the deviation at the contact"
                : "first order (Rzine et al. eqs. 17, 22): the follower moves by d(theta)/cos(pressure angle) "
                  "(translating) or d/(l cos) (oscillating), d the deviation at the point in contact at theta";
  f.angles = n;
  (oscillating ? f.displacement_error_max_arcsec : f.displacement_error_max_um) = hi * unit;
  f.displacement_error_max_at_cam_angle_deg = hi_at * 180.0 / kPi;
  (oscillating ? f.displacement_error_min_arcsec : f.displacement_error_min_um) = lo * unit;
  f.displacement_error_min_at_cam_angle_deg = lo_at * 180.0 / kPi;
  (oscillating ? f.displacement_error_peak_to_peak_arcsec : f.displacement_error_peak_to_peak_um) = (hi - lo) * unit;
  (r.follower_unit == "deg" ? f.follower_range_deg : f.follower_range_mm) =
      NominalMeasured{oscillating ? (n_hi - n_lo) * 180.0 / kPi : n_hi - n_lo,
                      oscillating ? (s_hi - s_lo) * 180.0 / kPi : s_hi - s_lo};
  j.not_computed = {{"the follower's dynamics with the measured motion (contact force, jump)",
                     "the loads are the nominal motion's; the measured error's inertia m dS'' w^2 is left out"}};
  if (r.loads && r.loads->stress_evaluated && s.contact == Study::Contact::kRoller &&
      r.loads->contact_force_N.size() == size_t(n)) {
    // The Hertz stress on the moved profile Q = A + d n (A the contact point, n its outward
    // normal): its curvature from central differences over θ (step 1e-4 rad), convex positive,
    // 1/R' = 1/r_f + κ_Q; the contact force the nominal's (first order).
    const double e_star = s.material->composite_modulus_MPa();
    auto moved = [&](double th) {
      const CamPoint<double> p = dc::EvaluateCam(cam, th);
      return Vec2<double>(p.contact + m.shape(th) * p.normal);
    };
    double p_max = 0, p_at = 0;
    for (int i = 0; i < n; ++i) {
      const double th = 2.0 * kPi * i / n, h = 1e-4, force = r.loads->contact_force_N[size_t(i)];
      if (!(force > 0)) continue;
      const CamPoint<double> p = dc::EvaluateCam(cam, th);
      const Vec2<double> qm = moved(th - h), q0 = moved(th), qp = moved(th + h);
      const Vec2<double> d1 = (qp - qm) / (2 * h), d2 = (qp - 2.0 * q0 + qm) / (h * h);
      const double ccw = Cross(p.pitch_d1, p.normal) < 0 ? 1.0 : -1.0;  // outward normal on the right: ccw
      const double kappa = ccw * Cross(d1, d2) / std::pow(d1.norm(), 3);
      const double inv_r = 1.0 / cam.roller_radius + kappa;
      const double stress = inv_r > 0 ? std::sqrt(force * e_star * inv_r / (kPi * *s.face_width_mm)) : INFINITY;
      if (stress > p_max) p_max = stress, p_at = th;
    }
    DiscCamMeasured::Contact& c = j.contact.emplace();
    c.model = "Hertz line contact of the roller on the measured profile's curvature (the moved profile Q = A + d n "
              "differentiated over the cam angle), the nominal motion's contact force";
    c.max_contact_stress_MPa = {r.loads->max_contact_stress_MPa.value, p_max};
    c.at_max_contact_stress_cam_angle_deg = {r.loads->max_contact_stress_MPa.cam_angle_deg, p_at * 180.0 / kPi};
  } else {
    j.not_computed.push_back({"the contact stress of the measured cam",
                              "no contact stress in this study (a roller follower with face_width_mm, material and "
                              "loads: dynamics or arm_dynamics)"});
  }
  return j;
}

// Fills Result::json, result.json's members (defined below the Run* functions).
void FillResult(const Study& s, Result& r);

}  // namespace

Result Run(const Study& s, const RunContext& ctx) {
  Result r = RunCam(s, ctx);
  r.residual_spectrum = ResidualSpectrumOf(s, r);
  if (s.in.inspection && s.geometry.write) {
    const InspectedPart part = CamPart(s);
    long points = 0;
    r.inspection_files.push_back(
        {part.name, InspectionCsv(s.in.name, part, s.in.inspection->spacing_mm, s.in.inspection->tolerance_um, &points)});
    r.inspection_points.push_back({part.name, points});
  }
  if (s.measured) r.measured = MeasuredCam(s, r);
  FillResult(s, r);
  return r;
}

Result RunCam(const Study& s, const RunContext& ctx) {
  if (s.contact == Study::Contact::kFlatFaced && s.cam.follower == FollowerType::kOscillatingRoller)
    return RunOscillatingFlatFaced(s);
  if (s.contact == Study::Contact::kFlatFaced) return RunFlatFaced(s);
  const DiscCam& cam = s.cam;
  const bool osc = cam.follower == FollowerType::kOscillatingRoller;
  // Follower errors in µm at the roller centre: ΔS [mm] for a translating follower, l·Δξ for an
  // oscillating one (Δξ [rad] is reported separately in arc seconds).
  const double to_um = dc::RollerCentreMmPerFollowerUnit(cam) * 1e3;
  const double to_arcsec = 180.0 / kPi * 3600.0;
  const double unit = osc ? 1.0 / kDeg : 1.0;  // follower unit: mm or deg
  const int n = s.in.analysis.angle_steps;

  std::vector<CamPoint<double>> pts(n);
  std::vector<dc::MechanicalError<double>> err(n);
  const std::vector<motion::Svaj<double>> svaj = SampleMotion(cam.motion, n);
  for (int i = 0; i < n; ++i) {
    pts[i] = dc::EvaluateCam(cam, 2 * kPi * i / n);
    if (s.error_stage) err[i] = dc::FollowerError(cam, pts[i], s.tolerances);
  }

  const Grid g{n};  // arg max/min, angles and columns over the grid

  Result r;
  r.oscillating = osc;
  r.follower_unit = osc ? "deg" : "mm";
  auto& t = r.series;
  t.cam_angle_deg = g.Col([&](int i) { return g.AngleDeg(i); });
  t.follower = g.Col([&](int i) { return pts[i].s * unit; });
  t.velocity_per_rad = g.Col([&](int i) { return pts[i].ds * unit; });
  t.acceleration_per_rad2 = g.Col([&](int i) { return pts[i].d2s * unit; });
  t.jerk_per_rad3 = g.Col([&](int i) { return svaj[i].j * unit; });
  t.pressure_angle_deg = g.Col([&](int i) { return pts[i].pressure_angle / kDeg; });
  t.shift_angle_deg = g.Col([&](int i) { return pts[i].shift_angle / kDeg; });
  t.radial_dimension_mm = g.Col([&](int i) { return pts[i].radial_dimension; });
  t.contact_x_mm = g.Col([&](int i) { return pts[i].contact.x(); });
  t.contact_y_mm = g.Col([&](int i) { return pts[i].contact.y(); });
  t.pitch_x_mm = g.Col([&](int i) { return pts[i].pitch.x(); });
  t.pitch_y_mm = g.Col([&](int i) { return pts[i].pitch.y(); });
  t.q_mm = g.Col([&](int i) { return pts[i].q; });
  t.pitch_curvature_per_mm = g.Col([&](int i) { return pts[i].pitch_curvature; });
  if (s.error_stage) {
    t.error_radial_um = g.Col([&](int i) { return err[i].radial * to_um; });
    t.error_roller_um = g.Col([&](int i) { return err[i].roller * to_um; });
    t.error_normal_um = g.Col([&](int i) { return err[i].normal * to_um; });
    t.error_worst_case_um = g.Col([&](int i) { return err[i].worst_case * to_um; });
    t.error_rms_um = g.Col([&](int i) { return err[i].rms * to_um; });
  }

  const int i_rmax = g.ArgMax([&](int i) { return pts[i].radial_dimension; });
  const int i_rmin = g.ArgMin([&](int i) { return pts[i].radial_dimension; });
  r.max_radial_dimension_mm = {pts[i_rmax].radial_dimension, g.AngleDeg(i_rmax)};
  r.min_radial_dimension_mm = pts[i_rmin].radial_dimension;
  const int i_pmax = g.ArgMax([&](int i) { return pts[i].pressure_angle; });
  const int i_pmin = g.ArgMin([&](int i) { return pts[i].pressure_angle; });
  r.min_pressure_angle_deg = {pts[i_pmin].pressure_angle / kDeg, g.AngleDeg(i_pmin)};
  r.max_pressure_angle_deg = {pts[i_pmax].pressure_angle / kDeg, g.AngleDeg(i_pmax)};
  // Pressure angle on the rise (and dwells, S' >= 0) and on the return (S' < 0), as |φ|.
  for (int i = 0; i < n; ++i) {
    const AtAngle a{std::abs(pts[i].pressure_angle) / kDeg, g.AngleDeg(i)};
    if (pts[i].ds >= 0.0) {
      if (a.value > r.max_pressure_angle_rise_deg.value) r.max_pressure_angle_rise_deg = a;
    } else if (!r.max_pressure_angle_return_deg || a.value > r.max_pressure_angle_return_deg->value) {
      r.max_pressure_angle_return_deg = a;
    }
  }
  const int i_lmax = g.ArgMax([&](int i) { return pts[i].shift_angle; });
  const int i_lmin = g.ArgMin([&](int i) { return pts[i].shift_angle; });
  r.shift_angle_deg = {pts[i_lmin].shift_angle / kDeg, pts[i_lmax].shift_angle / kDeg};
  auto ratio = [&](int i) { return dc::RadialErrorRatio(pts[i]); };
  r.cos_shift_over_cos_pressure = {ratio(g.ArgMin(ratio)), ratio(g.ArgMax(ratio))};

  // Curvature: the profile's radius where the pitch curve is convex, its magnitude where concave;
  // undercut where κ r_f > 1 (model/disc_cam/disc_cam.h).
  std::vector<bool> undercut(n);
  for (int i = 0; i < n; ++i) {
    const double k = pts[i].pitch_curvature;
    undercut[i] = dc::IsUndercut(pts[i], cam.roller_radius);
    const double rho = dc::ProfileRadiusOfCurvature(pts[i], cam.roller_radius);
    auto& convex = r.min_radius_of_curvature_mm;
    auto& concave = r.min_concave_radius_of_curvature_mm;
    if (k > 0) {
      if (!convex || rho < convex->value) convex = AtAngle{rho, g.AngleDeg(i)};
    } else if (k < 0) {
      if (!concave || -rho < concave->value) concave = AtAngle{-rho, g.AngleDeg(i)};
    }
  }
  r.undercut = std::find(undercut.begin(), undercut.end(), true) != undercut.end();
  r.undercut_cam_angle_deg = Intervals(undercut);

  // The loads over the cycle: contact force and camshaft torque at each point from `load_at`, the
  // roller's Hertz stress where a roller, a face width and a material are given (a knife edge is a
  // point); jump speed and spring from the kind of follower.
  const auto loads_over = [&](auto load_at) {
    Result::Loads L;
    const bool stress = s.face_width_mm && s.material && s.contact == Study::Contact::kRoller;
    const double e_star = stress ? s.material->composite_modulus_MPa() : 0.0;
    L.stress_evaluated = stress;
    for (int i = 0; i < n; ++i) {
      const auto c = load_at(pts[i]);
      L.contact_force_N.push_back(c.contact_force);
      L.camshaft_torque_Nm.push_back(c.camshaft_torque * 1e-3);
      if (stress) {
        const double p = dc::RollerCamContactStress(pts[i], cam.roller_radius, c.contact_force, *s.face_width_mm, e_star);
        if (!std::isfinite(p)) L.stress_finite = false;
        L.contact_stress_MPa.push_back(std::isfinite(p) ? p : 0.0);
      }
    }
    return L;
  };
  // Kinetostatic loads at the given speed (model/disc_cam/kinetostatics.h).
  if (s.dynamics) {
    const double omega = dc::RadPerSecond(s.dynamics->speed_rpm);
    Result::Loads L = loads_over([&](const CamPoint<double>& p) { return dc::CamLoadAt(p, s.dynamics->loads, omega); });
    L.weight_N = s.dynamics->loads.weight_N;
    L.jump_speed_rpm = dc::Rpm(dc::JumpSpeed(pts, s.dynamics->loads));
    L.spring = dc::RequiredSpringOver(pts, s.dynamics->loads, omega);
    FinishLoads(s, L);
    r.loads = std::move(L);
  }
  // The arm's loads of an oscillating roller or knife edge (model/disc_cam/kinetostatics.h,
  // OscillatingRollerLoadAt): the moment balance about the pivot, F_c = M/(n · dC/dξ).
  if (s.arm_dynamics) {
    const double omega = dc::RadPerSecond(s.arm_dynamics->speed_rpm);
    Result::Loads L = loads_over(
        [&](const CamPoint<double>& p) { return dc::OscillatingRollerLoadAt(p, s.arm_dynamics->loads, omega); });
    L.jump_speed_rpm = dc::Rpm(dc::ArmJumpSpeedOver(pts, s.arm_dynamics->loads));
    L.spring = dc::ArmRequiredSpringOver(pts, s.arm_dynamics->loads, omega);
    FinishLoads(s, L);
    // The normal's lever arm about the pivot, n · dC/dξ (OscillatingRollerLoadAt) [m].
    ArmResponse(s, L, [&](double theta) {
      const CamPoint<double> p = dc::EvaluateCam(cam, theta);
      return p.normal.dot(p.follower_dir) * 1e-3;
    });
    r.loads = std::move(L);
  }

  // Mechanical error (eqs. 16–32), when asked for.
  r.error_evaluated = s.error_stage;
  if (s.error_stage) {
    const int i_wor = g.ArgMax([&](int i) { return err[i].worst_case; });
    const int i_rms = g.ArgMax([&](int i) { return err[i].rms; });
    r.max_worst_case_error_um = {err[i_wor].worst_case * to_um, g.AngleDeg(i_wor)};
    r.min_worst_case_error_um =
        err[g.ArgMin([&](int i) { return err[i].worst_case; })].worst_case * to_um;
    r.max_rms_error_um = {err[i_rms].rms * to_um, g.AngleDeg(i_rms)};
    auto component = [&](auto get) {
      const int a = g.ArgMax(get), b = g.ArgMin(get);
      return MinMax{get(b) * to_um, get(a) * to_um};
    };
    r.radial_error_um = component([&](int i) { return err[i].radial; });
    r.roller_error_um = component([&](int i) { return err[i].roller; });
    r.normal_error_um = component([&](int i) { return err[i].normal; });
    if (osc) {
      r.max_worst_case_error_arcsec = AtAngle{err[i_wor].worst_case * to_arcsec, g.AngleDeg(i_wor)};
      r.max_rms_error_arcsec = err[i_rms].rms * to_arcsec;
    }
  }

  // Motion program: continuity at the joints and peak derivatives.
  r.joints = motion::CheckContinuity(cam.motion, 1e-7);
  const MotionPeaks peaks = PeakDerivatives(svaj);
  r.peak_velocity = peaks.velocity * unit;
  r.peak_acceleration = peaks.acceleration * unit;
  r.peak_jerk = peaks.jerk * unit;

  // Monte-Carlo check of the linearisation against the exact follower motion.
  if (s.monte_carlo && r.undercut) {
    r.monte_carlo = Result::MonteCarlo::kSkippedUndercut;
  } else if (s.monte_carlo) {
    r.monte_carlo = Result::MonteCarlo::kDone;
    const auto& scales = s.monte_carlo_options.scales;
    Progress progress("disc_cam monte carlo", ctx.quiet);
    for (size_t k = 0; k < scales.size(); ++k) {
      progress.Update(double(k) / scales.size(), "tolerance scale " + Format(scales[k]));
      dc::MonteCarloOptions o = s.monte_carlo_options;
      o.scales = {scales[k]};
      for (const auto& m : dc::MonteCarloLinearisation(cam, s.tolerances, o))
        r.monte_carlo_rows.push_back({m.scale, m.max_linear * to_um, m.max_exact * to_um,
                                      m.max_difference * to_um, m.relative_difference,
                                      m.at_cam_angle_rad / kDeg, m.within_bound_fraction,
                                      std::max(0.0, m.bound_exceed) * to_um,
                                      m.sample_rms * to_um, m.predicted_rms * to_um});
    }
    progress.Update(1.0);
    progress.Done();
  }
  r.profile_files = FitGeometryFiles(s);
  return r;
}

// A translating flat-faced follower (model/disc_cam/flat_faced.h): the contact A(θ) on the envelope
// of the face lines, where it runs on the face (S'), the radius of curvature ρ = r_b + S + S'', the
// pressure angle 0, the loads with F_c = F_y and T = F_y S', the Hertz stress of the face on ρ.
Result RunFlatFaced(const Study& s) {
  const DiscCam& cam = s.cam;
  const int n = s.in.analysis.angle_steps;
  std::vector<dc::FlatFacePoint<double>> pts(n);
  const std::vector<motion::Svaj<double>> svaj = SampleMotion(cam.motion, n);
  for (int i = 0; i < n; ++i) pts[i] = dc::EvaluateFlatFaced(cam.motion, cam.base_radius, 2 * kPi * i / n);
  const Grid g{n};  // arg max/min, angles and columns over the grid

  Result r;
  r.follower_unit = "mm";
  auto& t = r.series;
  t.cam_angle_deg = g.Col([&](int i) { return g.AngleDeg(i); });
  t.follower = g.Col([&](int i) { return pts[i].s; });
  t.velocity_per_rad = g.Col([&](int i) { return pts[i].ds; });
  t.acceleration_per_rad2 = g.Col([&](int i) { return pts[i].d2s; });
  t.jerk_per_rad3 = g.Col([&](int i) { return svaj[i].j; });
  t.pressure_angle_deg = std::vector<double>(n, 0.0);
  t.radial_dimension_mm = g.Col([&](int i) { return pts[i].contact.norm(); });
  t.contact_x_mm = g.Col([&](int i) { return pts[i].contact.x(); });
  t.contact_y_mm = g.Col([&](int i) { return pts[i].contact.y(); });

  const int i_rmax = g.ArgMax([&](int i) { return t.radial_dimension_mm[i]; });
  r.max_radial_dimension_mm = {t.radial_dimension_mm[i_rmax], g.AngleDeg(i_rmax)};
  r.min_radial_dimension_mm = t.radial_dimension_mm[g.ArgMin([&](int i) { return t.radial_dimension_mm[i]; })];
  r.min_pressure_angle_deg = r.max_pressure_angle_deg = r.max_pressure_angle_rise_deg = {0.0, 0.0};

  Result::FlatFace F;
  F.contact_offset_mm = g.Col([&](int i) { return pts[i].contact_offset; });
  F.radius_of_curvature_mm = g.Col([&](int i) { return pts[i].radius_of_curvature; });
  const int i_omax = g.ArgMax([&](int i) { return F.contact_offset_mm[i]; });
  const int i_omin = g.ArgMin([&](int i) { return F.contact_offset_mm[i]; });
  F.max_contact_offset_mm = {F.contact_offset_mm[i_omax], g.AngleDeg(i_omax)};
  F.min_contact_offset_mm = {F.contact_offset_mm[i_omin], g.AngleDeg(i_omin)};
  const int i_rho = g.ArgMin([&](int i) { return F.radius_of_curvature_mm[i]; });
  F.min_radius_of_curvature_mm = {F.radius_of_curvature_mm[i_rho], g.AngleDeg(i_rho)};
  std::vector<bool> cusp(n);
  for (int i = 0; i < n; ++i) cusp[i] = !(F.radius_of_curvature_mm[i] > 0.0);
  F.cusp_cam_angle_deg = Intervals(cusp);
  r.min_radius_of_curvature_mm = F.min_radius_of_curvature_mm;

  if (s.dynamics) {
    Result::Loads L;
    const double omega = dc::RadPerSecond(s.dynamics->speed_rpm);
    L.weight_N = s.dynamics->loads.weight_N;
    const bool stress = s.face_width_mm && s.material;
    const double e_star = stress ? s.material->composite_modulus_MPa() : 0.0;
    L.stress_evaluated = stress;
    for (int i = 0; i < n; ++i) {
      const dc::CamLoad<double> c = dc::FlatFaceLoadAt(pts[i], s.dynamics->loads, omega);
      L.contact_force_N.push_back(c.contact_force);
      L.camshaft_torque_Nm.push_back(c.camshaft_torque * 1e-3);
      if (stress) {
        const double p = dc::FlatFaceContactStress(pts[i], c.contact_force, *s.face_width_mm, e_star);
        if (!std::isfinite(p)) L.stress_finite = false;
        L.contact_stress_MPa.push_back(std::isfinite(p) ? p : 0.0);
      }
    }
    L.jump_speed_rpm = dc::Rpm(dc::JumpSpeed(pts, s.dynamics->loads));
    L.spring = dc::RequiredSpringOver(pts, s.dynamics->loads, dc::RadPerSecond(s.dynamics->speed_rpm));
    FinishLoads(s, L);
    r.loads = std::move(L);
  }
  r.flat_face = std::move(F);
  r.joints = motion::CheckContinuity(cam.motion, 1e-7);
  const MotionPeaks peaks = PeakDerivatives(svaj);
  r.peak_velocity = peaks.velocity;
  r.peak_acceleration = peaks.acceleration;
  r.peak_jerk = peaks.jerk;
  r.profile_files = FitGeometryFiles(s);
  return r;
}

// An oscillating flat-faced follower (model/disc_cam/oscillating_flat_faced.h): the contact on the
// envelope of the face lines, where it runs along the face (ℓ = f cos ξ/(1 − ξ')), the pressure angle
// atan(d/ℓ), the radius of curvature ρ = h + h_φφ (a flat face needs ρ > 0). No loads: "dynamics" is
// refused for an oscillating follower.
Result RunOscillatingFlatFaced(const Study& s) {
  const dc::OscillatingFlatFaced c = OscillatingFlatFace(s);
  const Grid g{s.in.analysis.angle_steps};
  const int n = g.n;
  std::vector<dc::OscillatingFlatFacePoint> pts(static_cast<size_t>(n));
  const std::vector<motion::Svaj<double>> svaj = SampleMotion(c.motion, n);
  for (int i = 0; i < n; ++i) pts[size_t(i)] = dc::EvaluateOscillatingFlatFaced(c, 2 * kPi * i / n);
  auto at = [&](int i) -> const dc::OscillatingFlatFacePoint& { return pts[size_t(i)]; };
  const double unit = 1.0 / kDeg;  // the follower unit: deg

  Result r;
  r.oscillating = true;
  r.follower_unit = "deg";
  auto& t = r.series;
  t.cam_angle_deg = g.Col([&](int i) { return g.AngleDeg(i); });
  t.follower = g.Col([&](int i) { return svaj[size_t(i)].s * unit; });
  t.velocity_per_rad = g.Col([&](int i) { return svaj[size_t(i)].v * unit; });
  t.acceleration_per_rad2 = g.Col([&](int i) { return svaj[size_t(i)].a * unit; });
  t.jerk_per_rad3 = g.Col([&](int i) { return svaj[size_t(i)].j * unit; });
  t.pressure_angle_deg = g.Col([&](int i) { return at(i).pressure_angle / kDeg; });
  t.radial_dimension_mm = g.Col([&](int i) { return at(i).contact.norm(); });
  t.contact_x_mm = g.Col([&](int i) { return at(i).contact.x(); });
  t.contact_y_mm = g.Col([&](int i) { return at(i).contact.y(); });

  const int i_rmax = g.ArgMax([&](int i) { return t.radial_dimension_mm[size_t(i)]; });
  r.max_radial_dimension_mm = {t.radial_dimension_mm[size_t(i_rmax)], g.AngleDeg(i_rmax)};
  r.min_radial_dimension_mm = t.radial_dimension_mm[size_t(g.ArgMin([&](int i) { return t.radial_dimension_mm[size_t(i)]; }))];
  const int i_pmax = g.ArgMax([&](int i) { return at(i).pressure_angle; });
  const int i_pmin = g.ArgMin([&](int i) { return at(i).pressure_angle; });
  r.min_pressure_angle_deg = {at(i_pmin).pressure_angle / kDeg, g.AngleDeg(i_pmin)};
  r.max_pressure_angle_deg = {at(i_pmax).pressure_angle / kDeg, g.AngleDeg(i_pmax)};
  // |φ| on the rise (and dwells, ξ' >= 0) and on the return, as for a roller.
  for (int i = 0; i < n; ++i) {
    const AtAngle a{std::abs(at(i).pressure_angle) / kDeg, g.AngleDeg(i)};
    if (at(i).dxi >= 0.0) {
      if (a.value > r.max_pressure_angle_rise_deg.value) r.max_pressure_angle_rise_deg = a;
    } else if (!r.max_pressure_angle_return_deg || a.value > r.max_pressure_angle_return_deg->value) {
      r.max_pressure_angle_return_deg = a;
    }
  }

  Result::FlatFace F;
  F.contact_offset_mm = g.Col([&](int i) { return at(i).contact_on_face; });
  F.radius_of_curvature_mm = g.Col([&](int i) { return at(i).radius_of_curvature; });
  const int i_omax = g.ArgMax([&](int i) { return F.contact_offset_mm[size_t(i)]; });
  const int i_omin = g.ArgMin([&](int i) { return F.contact_offset_mm[size_t(i)]; });
  F.max_contact_offset_mm = {F.contact_offset_mm[size_t(i_omax)], g.AngleDeg(i_omax)};
  F.min_contact_offset_mm = {F.contact_offset_mm[size_t(i_omin)], g.AngleDeg(i_omin)};
  const int i_rho = g.ArgMin([&](int i) { return F.radius_of_curvature_mm[size_t(i)]; });
  F.min_radius_of_curvature_mm = {F.radius_of_curvature_mm[size_t(i_rho)], g.AngleDeg(i_rho)};
  std::vector<bool> cusp(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) cusp[size_t(i)] = !(F.radius_of_curvature_mm[size_t(i)] > 0.0);
  F.cusp_cam_angle_deg = Intervals(cusp);
  r.min_radius_of_curvature_mm = F.min_radius_of_curvature_mm;
  r.flat_face = std::move(F);

  // The arm's loads at the speed (model/disc_cam/oscillating_flat_faced.h): F = M/ℓ, T = M S'.
  if (s.arm_dynamics) {
    Result::Loads L;
    const double omega = dc::RadPerSecond(s.arm_dynamics->speed_rpm);
    const bool stress = s.face_width_mm && s.material;
    const double e_star = stress ? s.material->composite_modulus_MPa() : 0.0;
    L.stress_evaluated = stress;
    for (int i = 0; i < n; ++i) {
      const dc::ArmLoad a = dc::OscillatingFlatFaceLoadAt(c, at(i), s.arm_dynamics->loads, omega);
      L.contact_force_N.push_back(a.contact_force_N);
      L.camshaft_torque_Nm.push_back(a.camshaft_torque_N_m);
      if (stress) {
        const double p = dc::OscillatingFlatFaceContactStress(at(i), a.contact_force_N, *s.face_width_mm, e_star);
        if (!std::isfinite(p)) L.stress_finite = false;
        L.contact_stress_MPa.push_back(std::isfinite(p) ? p : 0.0);
      }
    }
    L.jump_speed_rpm = dc::Rpm(dc::OscillatingFlatFaceJumpSpeed(c, pts, s.arm_dynamics->loads));
    const auto& f = L.contact_force_N;
    const auto& tq = L.camshaft_torque_Nm;
    const int i_fmin = g.ArgMin([&](int i) { return f[size_t(i)]; }), i_fmax = g.ArgMax([&](int i) { return f[size_t(i)]; });
    L.min_contact_force_N = {f[size_t(i_fmin)], g.AngleDeg(i_fmin)};
    L.max_contact_force_N = {f[size_t(i_fmax)], g.AngleDeg(i_fmax)};
    const int i_tabs = g.ArgMax([&](int i) { return std::abs(tq[size_t(i)]); });
    L.max_abs_camshaft_torque_Nm = {std::abs(tq[size_t(i_tabs)]), g.AngleDeg(i_tabs)};
    L.min_camshaft_torque_Nm = tq[size_t(g.ArgMin([&](int i) { return tq[size_t(i)]; }))];
    L.max_camshaft_torque_Nm = tq[size_t(g.ArgMax([&](int i) { return tq[size_t(i)]; }))];
    if (stress) {
      const int i_p = g.ArgMax([&](int i) { return L.contact_stress_MPa[size_t(i)]; });
      L.max_contact_stress_MPa = {L.contact_stress_MPa[size_t(i_p)], g.AngleDeg(i_p)};
    }
    // The face's lever arm about the pivot is ℓ (OscillatingFlatFaceLoadAt) [m].
    ArmResponse(s, L, [&](double theta) { return dc::EvaluateOscillatingFlatFaced(c, theta).contact_on_face * 1e-3; });
    r.loads = std::move(L);
  }

  r.joints = motion::CheckContinuity(c.motion, 1e-7);
  const MotionPeaks peaks = PeakDerivatives(svaj);
  r.peak_velocity = peaks.velocity * unit;
  r.peak_acceleration = peaks.acceleration * unit;
  r.peak_jerk = peaks.jerk * unit;
  r.profile_files = FitGeometryFiles(s);
  return r;
}

namespace {

// result.json's members (Result::json) from the study and the model's numbers, in the order the
// former ToJson computed them (notes keep their order).
void FillResult(const Study& s, Result& r) {
  Result::Json& j = r.json;
  const auto note = [&](std::string text) {
    if (!j.notes) j.notes.emplace();
    j.notes->push_back(std::move(text));
  };
  j.name = s.in.name;
  j.follower = s.in.follower.type;
  const bool flat = s.contact == Study::Contact::kFlatFaced;
  j.angle_steps = s.in.analysis.angle_steps;
  j.max_radial_dimension_mm = r.max_radial_dimension_mm.value;
  j.max_radial_dimension_at_cam_angle_deg = r.max_radial_dimension_mm.cam_angle_deg;
  j.min_radial_dimension_mm = r.min_radial_dimension_mm;
  Result::Json::PressureAngle& pa = j.pressure_angle_deg;
  pa.min = r.min_pressure_angle_deg.value;
  pa.at_min_cam_angle_deg = r.min_pressure_angle_deg.cam_angle_deg;
  pa.max = r.max_pressure_angle_deg.value;
  pa.at_max_cam_angle_deg = r.max_pressure_angle_deg.cam_angle_deg;
  // "warnings" only when there is one (RunStudy adds the list to every result.json).
  if (const double worst = std::max(std::abs(r.min_pressure_angle_deg.value), std::abs(r.max_pressure_angle_deg.value));
      worst > dc::kHighPressureAngle / kDeg)
    j.warnings = std::vector<std::string>{
        "the pressure angle reaches " + Format(worst) + " deg, above the " + Format(dc::kHighPressureAngle / kDeg) +
        " deg warning limit (docs/disc_cam.md): large side thrust on the follower, near jamming"};
  // The limits: the value, the limit and pass/fail side by side, as lcr_analysis writes them
  // (docs/disc_cam.md "Limits and verdict").
  const double pa_limit = s.limits.pressure_angle_deg;
  bool geometry_ok = true;  // the pressure angle and radius limits (and a flat face's width)
  // The pressure angle on the rise and on the return against its limit (a roller, a knife edge, a
  // flat face on an arm).
  auto pressure_angle_limits = [&] {
    pa.max_rise = r.max_pressure_angle_rise_deg.value;
    pa.at_max_rise_cam_angle_deg = r.max_pressure_angle_rise_deg.cam_angle_deg;
    if (r.max_pressure_angle_return_deg) {
      pa.max_return = r.max_pressure_angle_return_deg->value;
      pa.at_max_return_cam_angle_deg = r.max_pressure_angle_return_deg->cam_angle_deg;
    }
    pa.limit = pa_limit;
    pa.rise_ok = r.max_pressure_angle_rise_deg.value <= pa_limit;
    pa.return_ok = !r.max_pressure_angle_return_deg || r.max_pressure_angle_return_deg->value <= pa_limit;
    return *pa.rise_ok && *pa.return_ok;
  };
  // A flat face's convexity: ρ_min against the margin and where the profile has cusps.
  const auto add_radius_and_cusps = [&](const Result::FlatFace& F, Result::Json::FlatFace& ff) {
    ff.min_radius_of_curvature_mm = F.min_radius_of_curvature_mm.value;
    ff.min_radius_of_curvature_at_cam_angle_deg = F.min_radius_of_curvature_mm.cam_angle_deg;
    ff.radius_margin_limit_mm = s.limits.radius_margin_mm;
    ff.radius_margin_ok = F.min_radius_of_curvature_mm.value > s.limits.radius_margin_mm;
    ff.cusp = !F.cusp_cam_angle_deg.empty();
    for (const auto& [from, to] : F.cusp_cam_angle_deg) ff.cusp_cam_angle_deg.push_back({from, to});
  };
  const auto range = [](const AtAngle& max, const AtAngle& min) {
    return Result::Json::Range{max.value, max.cam_angle_deg, min.value, min.cam_angle_deg};
  };
  const bool flat_arm = flat && s.cam.follower == FollowerType::kOscillatingRoller;
  if (flat_arm) {
    // The flat face on an arm: the pressure angle atan(d/ℓ) against its limit, ρ = h + h_φφ above the
    // margin (a convex cam), the face long enough for the contact's travel min ℓ … max ℓ.
    const Result::FlatFace& F = *r.flat_face;
    const bool pa_ok = pressure_angle_limits();
    const double needed = F.max_contact_offset_mm.value - F.min_contact_offset_mm.value;
    Result::Json::FlatFace& ff = j.flat_face.emplace();
    ff.pivot_distance_mm = s.cam.pivot_distance;
    ff.face_offset_mm = s.face_offset_mm;
    ff.arm_angle_on_base_circle_deg = dc::InitialArmAngle(OscillatingFlatFace(s)) / kDeg;
    ff.contact_on_face_mm = range(F.max_contact_offset_mm, F.min_contact_offset_mm);
    ff.face_length_needed_mm = needed;
    add_radius_and_cusps(F, ff);
    if (s.follower_face_width_mm) {
      ff.face_width_mm = *s.follower_face_width_mm;
      ff.face_width_ok = *s.follower_face_width_mm >= needed;
      geometry_ok = *ff.face_width_ok;
    }
    geometry_ok = geometry_ok && pa_ok && ff.radius_margin_ok;
  } else if (flat) {
    // The flat face: no pressure-angle limit (φ = 0), the radius ρ = r_b + S + S'' above the margin
    // (a convex cam: the face cannot follow ρ ≤ 0), the face wide enough for the contact's travel.
    const Result::FlatFace& F = *r.flat_face;
    pa.note = "0 everywhere: the common normal of a flat face perpendicular to the line of motion is the line "
              "of motion";
    const double rise_side = std::max(0.0, F.max_contact_offset_mm.value);
    const double return_side = std::max(0.0, -F.min_contact_offset_mm.value);
    Result::Json::FlatFace& ff = j.flat_face.emplace();
    ff.contact_offset_mm = range(F.max_contact_offset_mm, F.min_contact_offset_mm);
    ff.face_needed_rise_side_mm = rise_side;
    ff.face_needed_return_side_mm = return_side;
    ff.face_width_needed_mm = rise_side + return_side;
    ff.face_width_needed_centred_mm = 2 * std::max(rise_side, return_side);
    add_radius_and_cusps(F, ff);
    if (s.follower_face_width_mm) {
      ff.face_width_mm = *s.follower_face_width_mm;
      ff.face_width_ok = *s.follower_face_width_mm >= 2 * std::max(rise_side, return_side);
      geometry_ok = *ff.face_width_ok;
    }
    geometry_ok = geometry_ok && ff.radius_margin_ok;
    if (s.limits.pressure_angle_default == false)
      note("limits.pressure_angle_deg is not checked: a flat face's pressure angle is 0");
  } else {
    pressure_angle_limits();
    j.shift_angle_deg = Result::Json::MinMax{r.shift_angle_deg.min, r.shift_angle_deg.max};
    j.cos_shift_over_cos_pressure =
        Result::Json::MinMax{r.cos_shift_over_cos_pressure.min, r.cos_shift_over_cos_pressure.max};
    // null (NaN) when there is no convex (concave) part.
    j.min_radius_of_curvature_mm = AtAngleOrNaN(r.min_radius_of_curvature_mm, false);
    j.min_radius_of_curvature_at_cam_angle_deg = AtAngleOrNaN(r.min_radius_of_curvature_mm, true);
    j.min_concave_radius_of_curvature_mm = AtAngleOrNaN(r.min_concave_radius_of_curvature_mm, false);
    j.min_concave_radius_at_cam_angle_deg = AtAngleOrNaN(r.min_concave_radius_of_curvature_mm, true);
    // ρ_pitch − r_f (the profile's smallest convex radius) against the margin; no convex part: met.
    j.radius_margin_limit_mm = s.limits.radius_margin_mm;
    j.radius_margin_ok = !r.min_radius_of_curvature_mm || r.min_radius_of_curvature_mm->value >= s.limits.radius_margin_mm;
    j.undercut = r.undercut;
    j.undercut_cam_angle_deg.emplace();
    for (const auto& [from, to] : r.undercut_cam_angle_deg) j.undercut_cam_angle_deg->push_back({from, to});
    geometry_ok = *pa.rise_ok && *pa.return_ok && *j.radius_margin_ok;
  }

  if (s.in.analysis.evaluate) {
    j.evaluated = std::vector<std::string>{"profile"};
    if (s.error_stage) j.evaluated->push_back("error");
    if (s.monte_carlo) j.evaluated->push_back("monte_carlo");
  }
  if (r.error_evaluated) {
    j.tolerances_um = Result::Json::Tolerances{s.tolerances.radial * 1e3, s.tolerances.roller * 1e3,
                                               s.tolerances.normal * 1e3};
    Result::Json::WorstCase& wc = j.worst_case_error_um.emplace();
    wc.max = r.max_worst_case_error_um.value;
    wc.at_cam_angle_deg = r.max_worst_case_error_um.cam_angle_deg;
    wc.min = r.min_worst_case_error_um;
    j.rms_error_um = Result::Json::Peak{r.max_rms_error_um.value, r.max_rms_error_um.cam_angle_deg};
    const auto min_max = [](const MinMax& m) { return Result::Json::MinMax{m.min, m.max}; };
    j.error_components_um = Result::Json::ErrorComponents{min_max(r.radial_error_um), min_max(r.roller_error_um),
                                                          min_max(r.normal_error_um)};
    if (r.max_worst_case_error_arcsec)
      j.worst_case_error_arcsec =
          Result::Json::Peak{r.max_worst_case_error_arcsec->value, r.max_worst_case_error_arcsec->cam_angle_deg};
    if (r.max_rms_error_arcsec) j.rms_error_arcsec = Result::Json::Max{*r.max_rms_error_arcsec};
  }

  bool loads_ok = true;
  // The loads' extremes over the cycle and the kinetostatic jump speed (null, with a note, when
  // nothing decelerates the follower); returns whether contact holds.
  const auto add_extremes = [&](const Result::Loads& L, Result::Json::Loads& o, const char* never_jumps) {
    o.min_contact_force_N = L.min_contact_force_N.value;
    o.at_min_contact_force_cam_angle_deg = L.min_contact_force_N.cam_angle_deg;
    o.max_contact_force_N = L.max_contact_force_N.value;
    o.at_max_contact_force_cam_angle_deg = L.max_contact_force_N.cam_angle_deg;
    o.separation_ok = L.min_contact_force_N.value > 0.0;
    o.max_camshaft_torque_Nm = L.max_abs_camshaft_torque_Nm.value;
    o.at_max_camshaft_torque_cam_angle_deg = L.max_abs_camshaft_torque_Nm.cam_angle_deg;
    o.camshaft_torque_range_Nm = {L.min_camshaft_torque_Nm, L.max_camshaft_torque_Nm};
    o.jump_speed_rpm = L.jump_speed_rpm;  // null when not finite
    if (!std::isfinite(L.jump_speed_rpm)) note(never_jumps);
    return L.min_contact_force_N.value > 0.0;
  };
  // The peak Hertz stress and its limit; returns whether the limit holds (true without one). Not
  // evaluated, a note says why when the study gave the stress's inputs.
  const auto add_stress = [&](const Result::Loads& L, Result::Json::Loads& o, bool face) {
    if (!L.stress_evaluated) {
      if (s.contact == Study::Contact::kKnifeEdge && (s.face_width_mm || s.material))
        note("no contact stress: a knife edge touches the cam at a point (not a Hertz line contact)");
      else if (s.face_width_mm || s.material)
        note("no contact stress: it needs both face_width_mm and material");
      return true;
    }
    const char* cusp_note = face ? "max_contact_stress_MPa is null: the face is loaded at a cusp of the profile (ρ <= 0)"
                                 : "max_contact_stress_MPa is null: the roller is loaded on an undercut part of the profile";
    o.face_width_mm = *s.face_width_mm;
    o.composite_modulus_MPa = s.material->composite_modulus_MPa();
    if (L.stress_finite) {
      o.max_contact_stress_MPa = L.max_contact_stress_MPa.value;
      o.at_max_contact_stress_cam_angle_deg = L.max_contact_stress_MPa.cam_angle_deg;
    } else {
      o.max_contact_stress_MPa = NAN;  // null: a loaded point of the profile is undercut (a cusp)
      note(cusp_note);
    }
    if (!s.limits.contact_stress_MPa) return true;
    o.contact_stress_limit_MPa = *s.limits.contact_stress_MPa;
    o.contact_stress_ok = L.stress_finite && L.max_contact_stress_MPa.value <= *s.limits.contact_stress_MPa;
    return *o.contact_stress_ok;
  };
  // The residual-vibration spectrum (model/disc_cam/residual_spectrum.h), per moving segment.
  const auto add_spectrum = [&](Result::Json::Loads& o, bool with_response, double zeta) {
    if (!with_response) return;
    if (!r.residual_spectrum) {
      note("no residual_spectrum: the follower is critically damped (damping_ratio " + Format(zeta) +
           "), it does not ring");
      return;
    }
    const Result::Spectrum& sp = *r.residual_spectrum;
    Result::Json::Spectrum& out = o.residual_spectrum.emplace();
    out.damping_ratio = sp.zeta;
    out.stiffness_ratio = sp.stiffness_ratio;
    out.tau_range = {kSpectrumTauLow, kSpectrumTauHigh};
    out.points = kSpectrumPoints;
    for (const Result::SpectrumSegment& g : sp.segments) {
      Result::Json::SpectrumSegment& seg = out.segments.emplace_back();
      seg.segment = g.index;
      seg.law = g.law;
      seg.tau = g.tau;
      seg.amplitude_per_rise = g.amplitude;
      seg.amplitude_error = g.amplitude_error;
      (r.oscillating ? seg.predicted_residual_vibration_deg : seg.predicted_residual_vibration_mm) = g.predicted_residual;
      for (const dc::SpectrumMinimum& m : g.minima) seg.minima.push_back({m.tau, m.amplitude, m.zero});
    }
  };
  const auto add_jump = [&](const Result::Loads& L, Result::Json::Loads& o, const char* who) {
    const dc::DynamicJumpSpeed& js = *L.dynamic_jump;
    o.dynamic_jump_speed_rpm = js.found ? dc::Rpm(js.speed_rad_s) : NAN;  // null: not found
    o.dynamic_jump_search = Result::Json::JumpSearch{
        L.dynamic_jump_upper_rpm,
        dc::Rpm(js.scan_step_rad_s),
        {dc::Rpm(js.lower_rad_s), js.found ? dc::Rpm(js.speed_rad_s) : L.dynamic_jump_upper_rpm},
        js.runs};
    if (!js.found)
      note(std::string("dynamic_jump_speed_rpm is null: the ") + who + " holds the cam at every speed scanned up to " +
           Format(L.dynamic_jump_upper_rpm) + " rpm");
  };
  if (r.loads && s.arm_dynamics) {
    // The arm of an oscillating follower: contact force (M/ℓ on a flat face, M/(n · dC/dξ) on a roller),
    // camshaft torque, jump speed, stress.
    const Result::Loads& L = *r.loads;
    const dc::ArmLoads& a = s.arm_dynamics->loads;
    Result::Json::ArmDynamics& aj = j.arm_dynamics.emplace();
    aj.speed_rpm = s.arm_dynamics->speed_rpm;
    aj.arm_inertia_kg_m2 = a.inertia_kg_m2;
    aj.spring_rate_N_m_per_rad = a.spring_rate_N_m_per_rad;
    aj.spring_preload_N_m = a.spring_preload_N_m;
    aj.external_moment_N_m = a.external_moment_N_m;
    if (!flat_arm) {
      // What keeps the arm on the cam up to the speed: the smallest M₀ with this rate, the smallest
      // rate with this M₀ (null: no rate does, the deficit is on the base circle).
      aj.min_spring_preload_N_m = L.spring.min_preload_N;
      aj.min_spring_rate_N_m_per_rad = L.spring.min_rate_N_per_mm;  // null when not finite
    }
    loads_ok = add_extremes(L, aj, flat_arm ? "jump_speed_rpm is null: the arm never decelerates, so no speed lifts the face off the cam"
                                            : "jump_speed_rpm is null: the arm never decelerates, so no speed lifts the roller off the cam");
    loads_ok = add_stress(L, aj, flat_arm) && loads_ok;
    if (L.arm_response) {
      // The arm on its train stiffness (follower_dynamics.h, SimulateArm): the translating response's
      // keys with moments about the pivot, and the normal contact force at the cam.
      const dc::ArmDynamicsResult& ar = *L.arm_response;
      const Study::ArmDynamics& ad = *s.arm_dynamics;
      Result::Json::ArmResponse& rj = aj.response.emplace();
      rj.arm_stiffness_N_m_per_rad = *ad.arm_stiffness_N_m_per_rad;
      rj.damping_ratio = ad.damping_ratio;
      rj.revolutions = ad.revolutions;
      rj.natural_frequency_Hz = ar.natural_frequency_Hz;
      rj.min_contact_moment_N_m = ar.min_contact_moment_N_m;
      rj.at_min_contact_moment_cam_angle_deg = ar.min_contact_moment_cam_angle_deg;
      rj.max_contact_moment_N_m = ar.max_contact_moment_N_m;
      rj.at_max_contact_moment_cam_angle_deg = ar.max_contact_moment_cam_angle_deg;
      rj.min_contact_force_N = L.min_dynamic_contact_force_N.value;
      rj.at_min_contact_force_cam_angle_deg = L.min_dynamic_contact_force_N.cam_angle_deg;
      rj.max_contact_force_N = L.max_dynamic_contact_force_N.value;
      rj.at_max_contact_force_cam_angle_deg = L.max_dynamic_contact_force_N.cam_angle_deg;
      rj.separates = ar.separates;
      if (ar.separates) rj.first_separation_cam_angle_deg = ar.first_separation_cam_angle_deg;  // else null
      rj.residual_vibration_deg = ar.residual_vibration_rad / kDeg;
      rj.at_residual_vibration_cam_angle_deg = ar.residual_vibration_cam_angle_deg;
      rj.solver_steps = ar.steps;
      rj.contact_events = ar.events;
      add_jump(L, aj, "arm");
      loads_ok = loads_ok && !ar.separates;
    }
    add_spectrum(aj, L.arm_response.has_value(), s.arm_dynamics->damping_ratio);
  } else if (r.loads) {
    const Result::Loads& L = *r.loads;
    const auto& d = *s.dynamics;
    Result::Json::Dynamics& dj = j.dynamics.emplace();
    dj.speed_rpm = d.speed_rpm;
    dj.follower_mass_kg = d.loads.mass_kg;
    dj.spring_rate_N_per_mm = d.loads.spring_rate_N_per_mm;
    dj.spring_preload_N = d.loads.spring_preload_N;
    dj.external_load_N = d.loads.external_load_N;
    dj.follower_axis = d.follower_axis;
    dj.weight_toward_cam_N = L.weight_N;
    // What keeps contact up to the speed: the smallest preload with this rate, the smallest rate
    // with this preload (null: no rate does, the deficit is on the base circle).
    dj.min_spring_preload_N = L.spring.min_preload_N;
    dj.min_spring_rate_N_per_mm = L.spring.min_rate_N_per_mm;  // null when not finite
    loads_ok = add_extremes(L, dj, "jump_speed_rpm is null: the follower never decelerates, so no speed lifts it off the cam");
    if (L.response) {
      const dc::FollowerDynamicsResult& fr = *L.response;
      Result::Json::FollowerResponse& rj = dj.response.emplace();
      rj.follower_stiffness_N_per_mm = *d.follower_stiffness_N_per_mm;
      rj.damping_ratio = d.damping_ratio;
      rj.revolutions = d.revolutions;
      rj.natural_frequency_Hz = fr.natural_frequency_Hz;
      rj.min_axial_force_N = fr.min_axial_force_N;
      rj.at_min_axial_force_cam_angle_deg = fr.min_axial_force_cam_angle_deg;
      rj.max_axial_force_N = fr.max_axial_force_N;
      rj.at_max_axial_force_cam_angle_deg = fr.max_axial_force_cam_angle_deg;
      rj.separates = fr.separates;
      if (fr.separates) rj.first_separation_cam_angle_deg = fr.first_separation_cam_angle_deg;  // else null
      rj.residual_vibration_mm = fr.residual_vibration_mm;
      rj.at_residual_vibration_cam_angle_deg = fr.residual_vibration_cam_angle_deg;
      rj.solver_steps = fr.steps;
      rj.contact_events = fr.events;
      add_jump(L, dj, "follower");
      loads_ok = loads_ok && !fr.separates;
    }
    add_spectrum(dj, L.response.has_value(), d.damping_ratio);
    loads_ok = add_stress(L, dj, flat) && loads_ok;
  } else if (s.contact == Study::Contact::kKnifeEdge && (s.face_width_mm || s.material)) {
    note("no contact stress: a knife edge touches the cam at a point (not a Hertz line contact)");
  } else if (s.face_width_mm || s.material) {
    note(r.oscillating ? "no contact force and no contact stress: they need \"arm_dynamics\" (speed, arm "
                         "inertia, spring)"
                       : "no contact force and no contact stress: they need \"dynamics\" (speed, mass, spring)");
  }

  // The verdict: every limit met, and which limits are the defaults.
  Result::Json::Limits& lim = j.limits;
  if (s.limits.pressure_angle_default) lim.defaults.push_back("pressure_angle_deg");
  if (s.limits.radius_margin_default) lim.defaults.push_back("radius_margin_mm");
  lim.radius_margin_mm = s.limits.radius_margin_mm;
  if (flat && !flat_arm) {
    if (s.limits.pressure_angle_default) lim.defaults.erase(lim.defaults.begin());
    if (s.follower_face_width_mm) lim.face_width_mm = *s.follower_face_width_mm;
  } else {
    lim.pressure_angle_deg = pa_limit;
    if (flat_arm && s.follower_face_width_mm) lim.face_width_mm = *s.follower_face_width_mm;
  }
  if (r.loads) lim.min_contact_force_N = 0.0;
  if (s.limits.contact_stress_MPa) lim.contact_stress_MPa = *s.limits.contact_stress_MPa;
  j.limits_ok = geometry_ok && loads_ok;

  j.motion.joints = JointRows(r.joints);
  if (r.follower_unit == "deg") {
    j.motion.peak_velocity_deg_per_rad = r.peak_velocity;
    j.motion.peak_acceleration_deg_per_rad2 = r.peak_acceleration;
    j.motion.peak_jerk_deg_per_rad3 = r.peak_jerk;
  } else {
    j.motion.peak_velocity_mm_per_rad = r.peak_velocity;
    j.motion.peak_acceleration_mm_per_rad2 = r.peak_acceleration;
    j.motion.peak_jerk_mm_per_rad3 = r.peak_jerk;
  }

  if (r.monte_carlo == Result::MonteCarlo::kDone) {
    const auto& o = s.monte_carlo_options;
    Result::Json::MonteCarlo& mc = j.monte_carlo.emplace();
    mc.samples = o.samples;
    mc.angle_steps = o.angle_steps;
    mc.seed = o.seed;
    mc.distribution = "uniform within ±scale × tolerance, independent";
    mc.scales = r.monte_carlo_rows;
  } else if (r.monte_carlo == Result::MonteCarlo::kSkippedUndercut) {
    j.monte_carlo.emplace().skipped = "the profile is undercut";
  }
  j.geometry_files = GeometryFilesOf(s.geometry, {{"profile", &r.profile_files}});
  if (s.in.inspection) {
    j.inspection = InspectionOf(s.in.inspection->spacing_mm, s.in.inspection->tolerance_um, r.inspection_points,
                                s.geometry.write,
                                "the cam's axis of rotation (its bore); the file's header states its frame");
  }
  j.measured = r.measured;
}

}  // namespace

void Write(const Study& s, const Result& r, Outputs& out) {
  out.SetResult(r);
  WritePlanarCamFiles(r.profile_files, s.geometry, out);
  for (const auto& [name, csv] : r.inspection_files) out.Add("inspection/" + name + ".csv", csv);
  const DiscCam& cam = s.cam;
  const auto& t = r.series;
  const std::string& fu = r.follower_unit;

  Table table;
  table.Add("cam_angle_deg", t.cam_angle_deg);
  table.Add("follower_" + fu, t.follower);
  table.Add("velocity_" + fu + "_per_rad", t.velocity_per_rad);
  table.Add("acceleration_" + fu + "_per_rad2", t.acceleration_per_rad2);
  table.Add("jerk_" + fu + "_per_rad3", t.jerk_per_rad3);
  const bool flat = r.flat_face.has_value();
  const bool flat_arm = flat && r.oscillating;
  if (flat) {
    // A flat face: no pitch curve, instant centre or shift angle; the pressure angle is 0 (on an arm
    // atan(d/ℓ)).
    if (flat_arm) table.Add("pressure_angle_deg", t.pressure_angle_deg);
    table.Add("radial_dimension_mm", t.radial_dimension_mm);
    table.Add("contact_x_mm", t.contact_x_mm);
    table.Add("contact_y_mm", t.contact_y_mm);
    table.Add("contact_offset_on_face_mm", r.flat_face->contact_offset_mm);
    table.Add("radius_of_curvature_mm", r.flat_face->radius_of_curvature_mm);
  } else {
    table.Add("pressure_angle_deg", t.pressure_angle_deg);
    table.Add("shift_angle_deg", t.shift_angle_deg);
    table.Add("radial_dimension_mm", t.radial_dimension_mm);
    table.Add("contact_x_mm", t.contact_x_mm);
    table.Add("contact_y_mm", t.contact_y_mm);
    table.Add("pitch_x_mm", t.pitch_x_mm);
    table.Add("pitch_y_mm", t.pitch_y_mm);
    table.Add("q_mm", t.q_mm);
    table.Add("pitch_curvature_per_mm", t.pitch_curvature_per_mm);
  }
  if (r.error_evaluated) {
    table.Add("error_radial_um", t.error_radial_um);
    table.Add("error_roller_um", t.error_roller_um);
    table.Add("error_normal_um", t.error_normal_um);
    table.Add("error_worst_case_um", t.error_worst_case_um);
    table.Add("error_rms_um", t.error_rms_um);
  }
  if (r.loads) {
    table.Add("contact_force_N", r.loads->contact_force_N);
    table.Add("camshaft_torque_Nm", r.loads->camshaft_torque_Nm);
    if (r.loads->stress_evaluated) table.Add("contact_stress_MPa", r.loads->contact_stress_MPa);
  }
  out.Add("series.csv", ToCsv(table));

  const auto& th = t.cam_angle_deg;
  AddSvajPlots(out, s.in.name + ": follower", r.follower_unit, th,
               {&t.follower, &t.velocity_per_rad, &t.acceleration_per_rad2, &t.jerk_per_rad3},
               s.dynamics ? s.dynamics->speed_rpm : 0.0);
  auto series = [&](const std::string& label, const std::vector<double>& y) {
    return Series{label, th, y};
  };
  if (flat_arm) {
    PlotOptions o;
    o.title = s.in.name + ": flat face on an arm: contact along the face ℓ, radius of curvature, pressure angle";
    o.x_label = "cam angle [deg]";
    o.y_label = "[mm], [deg]";
    o.guides = PressureAngleLimitLines(s.limits.pressure_angle_deg, t.pressure_angle_deg);
    o.guides.push_back({"radius margin [mm]", s.limits.radius_margin_mm});
    out.Add("flat_face.svg", SvgLinePlot({series("contact along the face ℓ [mm]", r.flat_face->contact_offset_mm),
                                          series("radius of curvature ρ [mm]", r.flat_face->radius_of_curvature_mm),
                                          series("pressure angle atan(d/ℓ) [deg]", t.pressure_angle_deg)},
                                         o));
  } else if (flat) {
    PlotOptions o;
    o.title = s.in.name + ": flat face: contact offset S' and radius of curvature r_b + S + S''";
    o.x_label = "cam angle [deg]";
    o.y_label = "[mm]";
    o.guides = {{"radius margin", s.limits.radius_margin_mm}};
    out.Add("flat_face.svg", SvgLinePlot({series("contact offset on the face S' [mm]", r.flat_face->contact_offset_mm),
                                          series("radius of curvature ρ [mm]", r.flat_face->radius_of_curvature_mm)},
                                         o));
  } else {
    PlotOptions o;
    o.title = s.in.name + ": pressure angle and shift angle";
    o.x_label = "cam angle [deg]";
    o.y_label = "angle [deg]";
    o.guides = PressureAngleLimitLines(s.limits.pressure_angle_deg, t.pressure_angle_deg);
    out.Add("angles.svg", SvgLinePlot({series("pressure angle φ", t.pressure_angle_deg),
                                       series("shift angle λ", t.shift_angle_deg)},
                                      o));
  }
  if (r.error_evaluated) {
    PlotOptions o;
    o.title = s.in.name + ": follower error";
    o.x_label = "cam angle [deg]";
    o.y_label = r.oscillating ? "error at the roller centre, l·Δξ [µm]" : "follower error ΔS [µm]";
    std::vector<Series> ss = {series("ΔS_r (radial)", t.error_radial_um),
                              series("ΔS_rf (roller)", t.error_roller_um)};
    if (s.tolerances.normal > 0) ss.push_back(series("ΔS_n (normal)", t.error_normal_um));
    ss.push_back(series("ΔS_wor (worst case)", t.error_worst_case_um));
    ss.push_back(series("ΔS_rms", t.error_rms_um));
    out.Add("error.svg", SvgLinePlot(ss, o));
  }

  if (r.loads) {
    PlotOptions o;
    o.title = s.in.name + ": contact force and camshaft torque at " +
              Format(s.dynamics ? s.dynamics->speed_rpm : s.arm_dynamics->speed_rpm) + " rpm";
    o.x_label = "cam angle [deg]";
    o.y_label = "force [N], torque [N·m]";
    out.Add("loads.svg", SvgLinePlot({series("contact force F_c [N]", r.loads->contact_force_N),
                                      series("camshaft torque T [N·m]", r.loads->camshaft_torque_Nm)},
                                     o));
  }
  if (r.loads && r.loads->response) {
    const auto& smp = r.loads->response->samples;
    Table rt;
    std::vector<double> angle, cam_mm, follower_mm, axial, kinetostatic;
    for (const dc::FollowerDynamicsSample& q : smp) {
      angle.push_back(q.cam_angle_deg);
      cam_mm.push_back(q.cam_follower_mm);
      follower_mm.push_back(q.follower_mm);
      axial.push_back(q.axial_force_N);
      kinetostatic.push_back(q.kinetostatic_force_N);
    }
    rt.Add("cam_angle_deg", angle);
    rt.Add("cam_follower_mm", cam_mm);
    rt.Add("follower_mass_mm", follower_mm);
    rt.Add("axial_force_N", axial);
    rt.Add("kinetostatic_axial_force_N", kinetostatic);
    out.Add("follower_response.csv", ToCsv(rt));
    PlotOptions o;
    o.title = s.in.name + ": follower axial force at " + Format(s.dynamics->speed_rpm) + " rpm, last of " +
              std::to_string(s.dynamics->revolutions) + " revolutions";
    o.x_label = "cam angle [deg]";
    o.y_label = "axial force at the roller [N]";
    out.Add("follower_response.svg", SvgLinePlot({Series{"dynamic (k_f = " + Format(*s.dynamics->follower_stiffness_N_per_mm) +
                                                             " N/mm)", angle, axial},
                                                  Series{"kinetostatic (rigid follower)", angle, kinetostatic}},
                                                 o));
  }

  if (r.loads && r.loads->arm_response) {
    const auto& smp = r.loads->arm_response->samples;
    const Study::ArmDynamics& ad = *s.arm_dynamics;
    Table rt;
    std::vector<double> angle, cam_deg, arm_deg, moment, kinetostatic;
    for (const dc::ArmDynamicsSample& q : smp) {
      angle.push_back(q.cam_angle_deg);
      cam_deg.push_back(q.cam_arm_rad / kDeg);
      arm_deg.push_back(q.arm_rad / kDeg);
      moment.push_back(q.contact_moment_N_m);
      kinetostatic.push_back(q.kinetostatic_moment_N_m);
    }
    rt.Add("cam_angle_deg", angle);
    rt.Add("cam_arm_deg", cam_deg);
    rt.Add("arm_inertia_deg", arm_deg);
    rt.Add("contact_moment_N_m", moment);
    rt.Add("kinetostatic_contact_moment_N_m", kinetostatic);
    rt.Add("contact_force_N", r.loads->arm_contact_force_N);
    out.Add("arm_response.csv", ToCsv(rt));
    PlotOptions o;
    o.title = s.in.name + ": the arm's contact moment at " + Format(ad.speed_rpm) + " rpm, last of " +
              std::to_string(ad.revolutions) + " revolutions";
    o.x_label = "cam angle [deg]";
    o.y_label = "contact moment about the pivot [N·m]";
    out.Add("arm_response.svg",
            SvgLinePlot({Series{"dynamic (k_f = " + Format(*ad.arm_stiffness_N_m_per_rad) + " N·m/rad)", angle, moment},
                         Series{"kinetostatic (rigid arm)", angle, kinetostatic}},
                        o));
  }
  if (r.residual_spectrum && !r.residual_spectrum->segments.empty()) {
    // The classic chart: A/|h| against τ = T/T_n per moving segment, the study's τ marked.
    const Result::Spectrum& sp = *r.residual_spectrum;
    Table st;
    st.Add("tau", sp.tau);
    std::vector<Series> curves;
    PlotOptions o;
    for (const Result::SpectrumSegment& g : sp.segments) {
      const std::string name = "segment " + std::to_string(g.index) + " (" + g.law + ")";
      st.Add("amplitude_per_rise_segment_" + std::to_string(g.index), g.spectrum);
      curves.push_back(Series{name, sp.tau, g.spectrum});
      o.points.push_back({name + " at the speed, τ = " + Format(g.tau), g.tau, g.amplitude});
    }
    // The operating τ of each segment in a file of its own (the spectrum's columns share one τ grid).
    out.Add("residual_spectrum.csv", ToCsv(st));
    Table op;
    std::vector<double> idx, tau, amp;
    for (const Result::SpectrumSegment& g : sp.segments)
      idx.push_back(g.index), tau.push_back(g.tau), amp.push_back(g.amplitude);
    op.Add("segment", idx);
    op.Add("tau_at_speed", tau);
    op.Add("amplitude_per_rise_at_speed", amp);
    out.Add("residual_spectrum_operating.csv", ToCsv(op));
    o.title = s.in.name + ": residual-vibration spectrum (ζ = " + Format(sp.zeta) + ")";
    o.x_label = "τ = segment time / natural period";
    o.y_label = "residual amplitude / rise";
    out.Add("residual_spectrum.svg", SvgLinePlot(curves, o));
  }

  // Profile drawing: cam profile, pitch curve, base circle, and the follower at θ = 0.
  Drawing d;
  d.title = s.in.name + ": cam profile";
  Drawing::Layer profile{"profile", "black", {}, {}, true, 1.5};
  Drawing::Layer pitch{"pitch_curve", "steelblue", {}, {}, true, 0.7};
  Drawing::Layer base{"base_circle", "gray", {}, {}, true, 0.5};
  Drawing::Layer follower{"follower", "firebrick", {}, {}, false, 0.7};
  Polyline pp, pc;
  for (size_t i = 0; i < th.size(); ++i) {
    pp.emplace_back(t.contact_x_mm[i], t.contact_y_mm[i]);
    if (!flat) pc.emplace_back(t.pitch_x_mm[i], t.pitch_y_mm[i]);
  }
  profile.polylines.push_back(pp);
  base.circles.push_back({0.0, 0.0, cam.base_radius});
  base.circles.push_back({0.0, 0.0, 0.5});
  const bool knife = s.contact == Study::Contact::kKnifeEdge;
  if (flat_arm) {
    // The arm and its face at θ = 0: the pivot O₃, the perpendicular d to the face, the face over the
    // contact's travel min ℓ … max ℓ (or the length given, from min ℓ).
    const Result::FlatFace& F = *r.flat_face;
    const dc::OscillatingFlatFacePoint p0 = dc::EvaluateOscillatingFlatFaced(OscillatingFlatFace(s), 0.0);
    const Vec2<double> along = -U(p0.theta - p0.xi), foot = p0.pivot - s.face_offset_mm * p0.normal;
    const double lo = F.min_contact_offset_mm.value,
                 hi = s.follower_face_width_mm ? lo + *s.follower_face_width_mm : F.max_contact_offset_mm.value;
    const Vec2<double> a = foot + lo * along, b = foot + hi * along;
    follower.polylines.push_back({{a.x(), a.y()}, {b.x(), b.y()}});
    follower.polylines.push_back({{p0.pivot.x(), p0.pivot.y()}, {foot.x(), foot.y()}});
    follower.circles.push_back({p0.pivot.x(), p0.pivot.y(), 1.5});
    d.layers = {profile, base, follower};
    char line[200];
    std::snprintf(line, sizeof line,
                  "base circle diameter %g mm; oscillating flat-faced follower, pivot distance %g mm, face offset %g mm, "
                  "face length needed %.3f mm",
                  2 * cam.base_radius, cam.pivot_distance, s.face_offset_mm,
                  F.max_contact_offset_mm.value - F.min_contact_offset_mm.value);
    d.dimensions.push_back(line);
    double r_min = INFINITY, r_max = 0;
    for (const auto& [x, y] : pp) r_min = std::min(r_min, std::hypot(x, y)), r_max = std::max(r_max, std::hypot(x, y));
    std::snprintf(line, sizeof line, "profile radius from the cam centre %.3f to %.3f mm (sampled)", r_min, r_max);
    d.dimensions.push_back(line);
    out.Add("profile.svg", SvgDrawing(d));
    return;
  }
  if (flat) {
    // The face at θ = 0: the line x = r_b + S(0) over the width needed (or the face given), and the stem.
    const Result::FlatFace& F = *r.flat_face;
    const double half = s.follower_face_width_mm ? *s.follower_face_width_mm / 2
                                                  : std::max({F.max_contact_offset_mm.value, -F.min_contact_offset_mm.value,
                                                              0.1 * cam.base_radius});
    const double x0 = cam.base_radius + t.follower[0];
    follower.polylines.push_back({{x0, -half}, {x0, half}});
    follower.polylines.push_back({{x0, 0.0}, {x0 + 0.5 * cam.base_radius, 0.0}});
    d.layers = {profile, base, follower};
    char line[200];
    std::snprintf(line, sizeof line, "base circle diameter %g mm; flat-faced follower, face width needed %.3f mm",
                  2 * cam.base_radius, F.max_contact_offset_mm.value - F.min_contact_offset_mm.value);
    d.dimensions.push_back(line);
    double r_min = INFINITY, r_max = 0;
    for (const auto& [x, y] : pp) r_min = std::min(r_min, std::hypot(x, y)), r_max = std::max(r_max, std::hypot(x, y));
    std::snprintf(line, sizeof line, "profile radius from the cam centre %.3f to %.3f mm (sampled)", r_min, r_max);
    d.dimensions.push_back(line);
    out.Add("profile.svg", SvgDrawing(d));
    return;
  }
  if (!knife) pitch.polylines.push_back(pc);  // a knife edge's pitch curve is its profile
  const Vec2<double> c0(t.pitch_x_mm[0], t.pitch_y_mm[0]);  // roller centre at θ = 0
  if (!knife) follower.circles.push_back({c0.x(), c0.y(), cam.roller_radius});
  if (r.oscillating) {
    const Vec2<double> o3 = dc::FollowerPivot(cam, 0.0);
    follower.polylines.push_back({{o3.x(), o3.y()}, {c0.x(), c0.y()}});
    follower.circles.push_back({o3.x(), o3.y(), 1.5});
  } else {
    const Vec2<double> a = c0 + 0.5 * cam.base_radius * U(0.0);
    follower.polylines.push_back({{c0.x(), c0.y()}, {a.x(), a.y()}});
  }
  if (knife) d.layers = {profile, base, follower};
  else d.layers = {profile, pitch, base, follower};
  // The main dimensions a shop reads (the profile's radii from its sampled points).
  double r_min = INFINITY, r_max = 0;
  for (const auto& [x, y] : pp) r_min = std::min(r_min, std::hypot(x, y)), r_max = std::max(r_max, std::hypot(x, y));
  char line[200];
  if (knife)
    std::snprintf(line, sizeof line, "base circle diameter %g mm; knife-edge follower; %s", 2 * cam.base_radius,
                  r.oscillating ? "oscillating follower" : ("offset " + Format(cam.offset) + " mm").c_str());
  else
    std::snprintf(line, sizeof line, "base circle diameter %g mm; roller diameter %g mm; %s", 2 * cam.base_radius,
                  2 * cam.roller_radius,
                  r.oscillating ? "oscillating follower" : ("offset " + Format(cam.offset) + " mm").c_str());
  d.dimensions.push_back(line);
  std::snprintf(line, sizeof line, "profile radius from the cam centre %.3f to %.3f mm (sampled)", r_min, r_max);
  d.dimensions.push_back(line);
  out.Add("profile.svg", SvgDrawing(d));
}

namespace {

// The declared input of a study, for the estimates below that run before Parse.
Input ReadInput(const nlohmann::json& study, const std::string& file) { return Read<Input>(Node(&study, file, "")); }

// Fidelity for `camopt run --convergence` (studies/convergence.h): the angle grid and, when the
// Monte-Carlo check runs, its sample count and grid.
Fidelity Knobs(const nlohmann::json& study) {
  const Input in = ReadInput(study, "");
  const Input defaults;
  const Input::MonteCarlo mc_defaults;
  Fidelity f;
  f.knobs.push_back({"angle_steps", {"/analysis/angle_steps"}, defaults.analysis.angle_steps, 2, true, 0,
                     "samples of the revolution (extrema are sampled)"});
  // An object or absent: the knobs set its fields (`true` or `false` has none to set).
  bool mc_on = std::holds_alternative<Input::MonteCarlo>(in.analysis.monte_carlo) ||
               !study.contains("analysis") || !study["analysis"].contains("monte_carlo");
  if (in.analysis.evaluate) {
    const auto& ev = *in.analysis.evaluate;
    mc_on = mc_on && std::find(ev.begin(), ev.end(), "monte_carlo") != ev.end();
  }
  if (mc_on) {
    f.knobs.push_back({"monte_carlo_samples", {"/analysis/monte_carlo/samples"}, mc_defaults.samples, 2, true, 0,
                       "Monte-Carlo samples per scale"});
    f.knobs.push_back({"monte_carlo_angle_steps", {"/analysis/monte_carlo/angle_steps"}, mc_defaults.angle_steps, 2,
                       true, 0,
                       "angle grid of each Monte-Carlo sample"});
  }
  f.headlines = {"/pressure_angle_deg/max", "/min_radius_of_curvature_mm", "/max_radial_dimension_mm",
                 "/worst_case_error_um/max", "/rms_error_um/max",
                 "/monte_carlo/scales/0/max_exact_um", "/monte_carlo/scales/0/relative_difference"};
  return f;
}

// The work limit (studies/work_limits.h): the analysis grid and, unless switched off, the
// Monte-Carlo samples × their grid × the tolerance scales (cam angle evaluations).
WorkEstimate EstimateWork(const nlohmann::json& study, const std::string& file, double factor) {
  const Input in = ReadInput(study, file);
  const Input::Analysis& a = in.analysis;
  std::vector<WorkTerm> terms = {
      {double(a.angle_steps), "/analysis/angle_steps", WorkNumber(a.angle_steps) + " angle steps"}};
  if (const std::optional<Input::MonteCarlo> on = Enabled(a.monte_carlo)) {
    const Input::MonteCarlo& mc = *on;
    const double n_scales = double(mc.scales.size());
    terms.push_back({double(mc.samples) * mc.angle_steps * n_scales, "/analysis/monte_carlo",
                     WorkNumber(mc.samples) + " samples × " + WorkNumber(mc.angle_steps) + " angle steps × " +
                         WorkNumber(n_scales) + " scales"});
  }
  return LargestTerm(terms, 2e6 * factor, "cam angle evaluations", 200);
}

CAMOPT_REGISTER_KIND(Kind<Input, Result, Study>{
    .name = "disc_cam",
    .title = "camopt study: disc cam with a roller, knife-edge or flat-faced follower",
    .run = Run, .parse = Parse, .write = Write, .knobs = Knobs, .estimate = EstimateWork,
    .report = std::vector<Headline>{
        // The signed extremes of φ (the limit holds |φ| on the rise and on the return, the rows after).
        {"pressure angle φ, most positive (signed)", "/pressure_angle_deg/max", "deg"},
        {"pressure angle φ, most negative (signed)", "/pressure_angle_deg/min", "deg"},
        {"largest pressure angle, rise", "/pressure_angle_deg/max_rise", "deg", "/pressure_angle_deg/limit"},
        {"largest pressure angle, return", "/pressure_angle_deg/max_return", "deg", "/pressure_angle_deg/limit"},
        {"smallest radius of curvature (ρ_pitch − r_roller)", "/min_radius_of_curvature_mm", "mm", "/radius_margin_limit_mm",
         NAN, false},
        {"undercut", "/undercut", ""},
        // ρ's formula by the face's follower: translating ρ = r_b + S + S'', on an arm ρ = h + h_φφ
        // (model/disc_cam/flat_faced.h, oscillating_flat_faced.h); each row shown for its own follower.
        {"smallest radius of curvature r_b + S + S'' (flat face)", "/flat_face/min_radius_of_curvature_mm", "mm",
         "/flat_face/radius_margin_limit_mm", NAN, false, "", "/flat_face/face_width_needed_centred_mm"},
        {"smallest radius of curvature h + h_φφ (flat face on an arm)", "/flat_face/min_radius_of_curvature_mm", "mm",
         "/flat_face/radius_margin_limit_mm", NAN, false, "", "/flat_face/face_length_needed_mm"},
        {"face width needed, centred on the axis (flat face)", "/flat_face/face_width_needed_centred_mm", "mm",
         "/flat_face/face_width_mm"},
        {"face length needed (flat face on an arm)", "/flat_face/face_length_needed_mm", "mm", "/flat_face/face_width_mm"},
        {"smallest contact force (separation)", "/dynamics/min_contact_force_N", "N", "", 0.0, false},
        {"largest contact force", "/dynamics/max_contact_force_N", "N"},
        {"largest contact stress", "/dynamics/max_contact_stress_MPa", "MPa", "/dynamics/contact_stress_limit_MPa"},
        {"jump speed (kinetostatic)", "/dynamics/jump_speed_rpm", "rpm"},
        {"jump speed (dynamic, flexible follower)", "/dynamics/dynamic_jump_speed_rpm", "rpm", "/dynamics/speed_rpm", NAN, false},
        {"smallest axial force (dynamic)", "/dynamics/response/min_axial_force_N", "N"},
        {"residual vibration", "/dynamics/response/residual_vibration_mm", "mm"},
        {"largest camshaft torque", "/dynamics/max_camshaft_torque_Nm", "N·m"},
        {"smallest spring preload keeping contact up to the speed", "/dynamics/min_spring_preload_N", "N"},
        {"smallest contact force on the arm's face (separation)", "/arm_dynamics/min_contact_force_N", "N", "", 0.0, false},
        {"largest contact stress (arm's face)", "/arm_dynamics/max_contact_stress_MPa", "MPa",
         "/arm_dynamics/contact_stress_limit_MPa"},
        {"jump speed (arm, kinetostatic)", "/arm_dynamics/jump_speed_rpm", "rpm"},
        {"jump speed (arm, dynamic, flexible train)", "/arm_dynamics/dynamic_jump_speed_rpm", "rpm", "/arm_dynamics/speed_rpm",
         NAN, false},
        {"smallest contact force on the arm (dynamic)", "/arm_dynamics/response/min_contact_force_N", "N"},
        {"residual vibration (arm)", "/arm_dynamics/response/residual_vibration_deg", "deg"},
        {"largest camshaft torque (arm)", "/arm_dynamics/max_camshaft_torque_Nm", "N·m"},
        {"largest radial dimension", "/max_radial_dimension_mm", "mm"},
        {"worst-case follower error", "/worst_case_error_um/max", "µm"},
        {"largest rms follower error", "/rms_error_um/max", "µm"},
    },
    .asked = std::vector<AskedBlock>{
        {{"/dynamics"}, "/dynamics", "the follower dynamics"},
        {{"/arm_dynamics"}, "/arm_dynamics", "the arm's loads"},
        {{"/tolerances"}, "/worst_case_error_um", "the tolerance analysis", {"error", "monte_carlo"}},
    },
    .init_example = "disc_cam_dynamics",
    .mechanism = DiscCamMechanismAt});
}  // namespace

}  // namespace camopt::studies::disc_cam
