#include "studies/lcr_input.h"

#include <algorithm>
#include <cmath>

#include "studies/design_issue_paths.h"
#include "studies/format.h"

namespace camopt::studies {

namespace {

// A side's design from its declared fields.
lcr::CamSide<double> SideOf(const LcrSideInput& in) {
  lcr::CamSide<double> c;
  c.lobes = in.lobes;
  c.rollers = in.rollers;
  c.turret_radius = in.turret_radius_mm;
  c.roller_radius = in.roller_diameter_mm / 2;
  c.roller_length = in.roller_length_mm;
  c.cam_thickness = in.cam_thickness_mm;
  return c;
}

// The checks between a side's fields: lengths on the turret's scale.
void CheckSide(const LcrSideInput& in, const Node& s) {
  for (const char* key : {"roller_diameter_mm", "roller_length_mm", "cam_thickness_mm"})
    PlausibleLength(s[key], in.turret_radius_mm, "the turret radius");
}

lcr::Reducer<double> Checked(const lcr::Reducer<double>& r, const Node& node) {
  FailOnFirst(lcr::CheckDesign(r), node, LcrIssuePaths());  // "input.rollers" -> /reducer/input/rollers
  return r;
}

}  // namespace

lcr::Reducer<double> ReducerOf(const LcrReducerInput& in) {
  lcr::Reducer<double> r;
  r.eccentricity = in.eccentricity_mm;
  r.input = SideOf(in.input);
  r.output = SideOf(in.output);
  return r;
}

lcr::Reducer<double> ToReducer(const LcrReducerInput& in, const Node& node) {
  CheckSide(in.input, node["input"]);
  CheckSide(in.output, node["output"]);
  return Checked(ReducerOf(in), node);
}

lcr::Reducer<double> ParseReducer(const Node& node) { return ToReducer(Read<LcrReducerInput>(node), node); }

double ParseCutterDiameter(const Node& side, double roller_diameter) {
  if (!side.Has("cutter_diameter_mm")) return roller_diameter;
  const Node n = side["cutter_diameter_mm"];
  const double d = n.Positive();
  if (d > roller_diameter)
    n.Fail("a cutter diameter <= the roller diameter (" + std::to_string(roller_diameter) + " mm)");
  return d;
}

nlohmann::ordered_json LcrLifeSchemaRules() {
  return nlohmann::ordered_json::parse(R"([
    {"if": {"anyOf": [{"required": ["duty_cycle"]},
                      {"required": ["load"], "properties": {"load": {"required": ["input_speed_rpm"]}}}]},
     "then": {"properties": {"reducer": {"properties": {"input": {"required": ["dynamic_rating_N"]},
                                                         "output": {"required": ["dynamic_rating_N"]}}}}}},
    {"if": {"required": ["duty_cycle"]},
     "then": {"properties": {"load": {"not": {"required": ["input_speed_rpm"]}}}}}
  ])");
}

void CheckCarriedTorque(const lcr::Reducer<double>& reducer, double youngs_modulus_MPa, double torque_Nmm,
                        const Node& torque_node) {
  const lcr::CamSide<double>& out = reducer.output;
  const double projected = 2 * out.roller_radius * out.roller_length;
  const double t_max_Nmm = youngs_modulus_MPa * projected * out.rollers * out.turret_radius;
  if (!(torque_Nmm <= t_max_Nmm))
    torque_node.Fail("a torque the output rollers can carry (at most " + Format(t_max_Nmm / 1000, 4) +
                     " N·m: their least force over the roller's projected area reaches the Young's modulus there)");
}

}  // namespace camopt::studies
