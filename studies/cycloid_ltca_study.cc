// Study kind "cycloid_ltca" (studies/cycloid_ltca_study.h): parse, run the LTCA cycle, write.
#include "studies/cycloid_ltca_study.h"
#include "studies/cycloid_parts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

#include "model/cycloid/geometry_limits.h"
#include "model/cycloid/parts.h"
#include "model/cycloid/tooth_profile.h"
#include "model/cycloid/unloaded_tca.h"
#include "studies/cycloid_life.h"
#include "studies/cycloid_study_common.h"
#include "studies/datasheet.h"
#include "studies/format.h"
#include "studies/kind.h"
#include "studies/report.h"
#include "studies/studio_mechanism.h"
#include "studies/work_limits.h"
#include "studies/writers.h"

namespace camopt::studies::cycloid_ltca {

using namespace camopt::cycloid;

namespace {

// "discs", "disc_spacing_mm" and the compliant "output_mechanism" (docs/cycloid.md, "Output
// mechanism"). The output mechanism needs the loaded stage and crank angles that sample whole mesh
// periods uniformly, with the discs' phase 360°/N a whole number of crank steps (each disc's
// ring-pin state is the first disc's at its own crank angle).
void ParseDiscsAndOutput(const Node& root, const Input& in, Study& s) {
  s.discs = in.discs;
  s.disc_spacing_mm = s.drive.face_width_mm;
  if (in.disc_spacing_mm) {
    s.disc_spacing_mm = *in.disc_spacing_mm;
    if (s.disc_spacing_mm < s.drive.face_width_mm)
      root["disc_spacing_mm"].Fail("a spacing of the discs' mid-planes >= the face width " +
                                   Format(s.drive.face_width_mm, 6) + " mm (the discs would overlap)");
  }
  const double stack = (s.discs - 1) * s.disc_spacing_mm + s.drive.face_width_mm;
  const std::optional<OutputSpec> compliant = cycloid_common::ParseCompliantOutput(
      root, in.output_mechanism, s.drive, s.drive.eccentricity_mm, stack,
      "the disc stack (discs - 1) * disc_spacing_mm + face_width_mm");
  if (!compliant) return;
  const OutputSpec& o = *compliant;
  const Node n = root["output_mechanism"];
  if (!s.loaded)
    n.FailWith("the output mechanism needs the loaded stage: analysis.evaluate must include \"loaded\" (or be absent)");
  int periods = 0;
  const Node at = root.Has("analysis") ? root["analysis"] : n;
  if (!cycloid::UniformWholeMeshPeriods(s.crank_angles_rad, s.drive.rollers, &periods))
    at.FailWith("the output mechanism needs crank angles that sample whole mesh periods (360/" +
                std::to_string(s.drive.rollers) + " deg) uniformly: use analysis.crank_angles_per_mesh_period");
  // The disc phase 2π/N in crank steps: n1 · (angles per period) / N must be whole.
  const long steps = long(s.crank_angles_rad.size()) * s.drive.rollers / periods;
  if (steps % s.discs != 0)
    at.FailWith("with " + std::to_string(s.discs) + " discs the crank angles per revolution (" + std::to_string(steps) +
                ") must be a multiple of the discs (each disc is the first one at its own crank angle): use "
                "analysis.crank_angles_per_mesh_period a multiple of " +
                std::to_string(s.discs / std::gcd(s.discs, s.drive.rollers)));
  s.output = o;
}

// "tolerances" and "monte_carlo" (docs/cycloid.md, "Transmission error from tolerances"), in the
// model's units: one disc, and the output pins' and holes' bands only with the output mechanism's
// radii (the pins and holes they move).
void ParseTolerances(const Node& root, const Input& in, Study& s) {
  if (!in.tolerances) {
    if (in.monte_carlo) root["monte_carlo"].Fail("no \"monte_carlo\" without \"tolerances\"");
    return;
  }
  if (s.discs > 1)
    root["discs"].Fail("1 with \"tolerances\" (the transmission error from tolerances is modelled for one disc; "
                       "found " + std::to_string(s.discs) + " discs)");
  const Input::Tolerances& t = *in.tolerances;
  const Node n = root["tolerances"];
  if (!s.output)
    for (const char* f : {"output_pin_position_um", "output_hole_position_um", "output_hole_diameter_um"})
      if (n.Has(f))
        n[f].FailWith(std::string(f) + " needs the output mechanism's pins and holes: output_mechanism with "
                      "pin_radius_mm and hole_radius_mm");
  Study::ToleranceSpec spec;
  cycloid::ToleranceBands& b = spec.bands;
  b.pin_circle_radius_mm = t.pin_circle_radius_um.value_or(0.0) * 1e-3;
  b.pin_diameter_mm = t.pin_diameter_um.value_or(0.0) * 1e-3;
  b.pin_pitch_rad = t.pin_pitch_arcsec.value_or(0.0) * kPi / (180.0 * 3600.0);
  b.eccentricity_mm = t.eccentricity_um.value_or(0.0) * 1e-3;
  b.profile_mm = t.profile_um.value_or(0.0) * 1e-3;
  b.output_pin_position_mm = t.output_pin_position_um.value_or(0.0) * 1e-3;
  b.output_hole_position_mm = t.output_hole_position_um.value_or(0.0) * 1e-3;
  b.output_hole_diameter_mm = t.output_hole_diameter_um.value_or(0.0) * 1e-3;
  if (in.monte_carlo) {
    spec.samples = in.monte_carlo->samples.value_or(0);
    spec.seed = std::uint64_t(in.monte_carlo->seed.value_or(1));
    spec.angle_steps = in.monte_carlo->angle_steps.value_or(0);
  }
  s.tolerances = spec;
}

// "lubricant" and its blocks (docs/lubrication.md): the common part (studies/lubrication_input.h),
// the output mechanism whose pins carry the torque out, and the cycloid's bearings.
std::optional<Study::Lubrication> ParseLubrication(const Node& root, const Input& in, const Study& s) {
  const std::optional<double> speed = in.load ? in.load->input_speed_rpm : std::nullopt;
  const std::optional<LubricationCommon> common =
      ParseLubricationCommon(root, in.lubricant, in.surfaces, in.efficiency_map, speed, root.Has("duty_cycle"));
  if (!common) return std::nullopt;
  const Node node = root["lubricant"];
  if (!s.loaded) node.FailWith("the lubricated losses need the loaded stage: analysis.evaluate must include \"loaded\" (or be absent)");
  if (!root.Has("output_mechanism"))
    node.FailWith("the lubricated losses need \"output_mechanism\" (its pins carry the torque out and load the crank "
                  "bearing): give at least pin_circle_radius_mm");
  if (!cycloid::UniformWholeMeshPeriods(s.crank_angles_rad, s.drive.rollers))
    node.FailWith("the lubricated losses need crank angles that sample whole mesh periods (360/" +
                  std::to_string(s.drive.rollers) + " deg) uniformly (the losses are averaged over the revolution): "
                  "use analysis.crank_angles_per_mesh_period");
  Study::Lubrication l;
  l.common = *common;
  l.spec.oil = common->oil;
  l.spec.friction = common->friction;
  l.spec.composite_roughness_mm = common->composite_roughness_mm;
  l.spec.ring_pins_rotate = common->rollers_rotate;
  l.mechanism = cycloid_common::ParseOutputMechanism(root["output_mechanism"], s.drive, true);
  if (s.output) {
    const cycloid::OutputPins& p = s.output->pins;
    l.pins = cycloid::OutputPinContact{p.pin_radius_mm, p.hole_radius_mm, p.roller_radius_mm};
  }
  const CycloidBearingFrictionInput bearings = in.bearing_friction.value_or(CycloidBearingFrictionInput{});
  l.ring_pins_given = bearings.ring_pins.has_value();
  l.output_rollers_given = bearings.output_rollers.has_value();
  l.crank_given = bearings.crank.has_value();
  if (bearings.ring_pins) l.spec.ring_pin_bearing = bearings.ring_pins->ToBearing();
  if (bearings.output_rollers) l.spec.output_roller_bearing = bearings.output_rollers->ToBearing();
  if (bearings.crank) l.spec.crank_bearing = bearings.crank->ToBearing();
  return l;
}

}  // namespace

namespace {

// "stiffness.segments_Nm", "ratings", "output_bearing" and "external_loads" (docs/ratings.md).
void ParseCatalogue(const Node& root, const Input& in, Study& s) {
  if (in.stiffness) {
    std::tie(s.segment_T1_Nm, s.segment_T2_Nm) = SegmentTorques(root["stiffness"], *in.stiffness);
    s.lost_motion_percent = in.stiffness->lost_motion_percent;
  }
  if (in.ratings) {
    const Node n = root["ratings"];
    s.density_kg_m3 = in.ratings->density_kg_m3;
    if (!s.loaded) n.FailWith("ratings need the loaded stage: analysis.evaluate must include \"loaded\" (or be absent)");
    if (s.discs > 1)
      root["discs"].Fail("1 with ratings (the bearing lives are modelled for one disc; found " +
                         std::to_string(s.discs) + " discs)");
    if (!cycloid::UniformWholeMeshPeriods(s.crank_angles_rad, s.drive.rollers))
      n.FailWith("ratings need crank angles that sample whole mesh periods (360/" + std::to_string(s.drive.rollers) +
                 " deg) uniformly: use analysis.crank_angles_per_mesh_period");
    Study::RatingsSpec r;
    r.in = *in.ratings;
    r.life = cycloid_common::ParseLifeRatings(root, in, s.drive, "ratings: the rated torque is a bearing life",
                                              true);
    if (r.life.crank_bearing.modified || (r.life.pins_rated && r.life.pins.modified))
      r.life.contamination_factor = root["lubricant"]["contamination_factor"].Number();
    if (in.limits) {
      r.limits.contact_stress_MPa = in.limits->contact_stress_MPa;
      r.limits.roller_load_N = in.limits->roller_load_N;
    }
    s.ratings = r;
  }
  std::optional<double> speed;
  if (in.ratings) speed = in.ratings->rated_output_speed_rpm;
  else if (in.load && in.load->input_speed_rpm)
    speed = *in.load->input_speed_rpm * double(s.drive.rollers - s.drive.teeth) / s.drive.teeth;
  s.output_bearing = in.output_bearing;
  s.external_loads = ParseExternalLoads(root, in.output_bearing.has_value(), in.external_loads, speed);
}

}  // namespace

Study Parse(const Node& root) {
  // Every field's type and bounds (the limits are read by the headlines from the study,
  // "study:/limits/…"); what spans fields follows.
  const Input in = Read<Input>(root);
  Study s;
  s.name = in.name;
  if (in.limits) s.contact_stress_limit_MPa = in.limits->contact_stress_MPa;
  s.drive = cycloid_common::MakeDrive(root, in.drive, in.modification);
  s.crowning = cycloid_common::MakeCrowning(root, in.crowning, s.drive.face_width_mm);
  s.geometry = GeometryFileOptionsOf(in.geometry_files);
  if (in.drive.bore_diameter_mm) {
    const double root_diameter = 2 * (s.drive.roller_position_radius_mm - s.drive.eccentricity_mm -
                                      s.drive.roller_radius_mm);
    s.bore_diameter_mm = ParseBoreDiameter(root["drive"]["bore_diameter_mm"], root_diameter, "the disc's root diameter");
  }
  // Lazy stages: ["unloaded"] asks for the unloaded TCA only, which needs no material or load.
  if (in.analysis && in.analysis->evaluate) {
    const std::vector<std::string>& stages = *in.analysis->evaluate;
    s.loaded = std::find(stages.begin(), stages.end(), "loaded") != stages.end();
  }
  if (s.loaded && !in.material) (void)root["material"];  // "missing required field"
  if (in.material) s.material = in.material->ToMaterial();
  if (s.loaded && !in.load) (void)root["load"];
  if (in.load) s.torque_Nm = in.load->torque_Nm;
  s.crank_angles_per_mesh_period = kDefaultCrankAnglesPerMeshPeriod;
  const double period = 2.0 * kPi / s.drive.rollers;
  if (in.analysis) {
    const Input::Analysis& ia = *in.analysis;
    const Node a = root["analysis"];
    if (ia.grid) s.options.profile_cells = (*ia.grid)[0], s.options.axial_cells = (*ia.grid)[1];
    s.options.tolerance = ia.tolerance;
    s.estimate_error = ia.estimate_error;
    const int given = int(bool(ia.crank_angles_deg)) + int(bool(ia.crank_angle_steps)) +
                      int(bool(ia.crank_angles_per_mesh_period));
    if (given > 1)
      a.FailWith("give one of crank_angles_per_mesh_period, crank_angle_steps and crank_angles_deg");
    if (ia.crank_span_deg && !ia.crank_angle_steps)
      a["crank_span_deg"].Fail("crank_span_deg only with crank_angle_steps");
    if (ia.crank_angles_deg) {
      s.crank_angles_per_mesh_period = 0;
      for (const double deg : *ia.crank_angles_deg) s.crank_angles_rad.push_back(deg * kPi / 180.0);
    } else if (ia.crank_angle_steps) {
      s.crank_angles_per_mesh_period = 0;
      s.crank_angles_rad = UniformCrankAngles(*ia.crank_angle_steps, ia.crank_span_deg.value_or(360.0) * kPi / 180.0);
    } else {
      s.crank_angles_per_mesh_period = ia.crank_angles_per_mesh_period.value_or(kDefaultCrankAnglesPerMeshPeriod);
    }
  }
  if (s.crank_angles_per_mesh_period > 0)
    s.crank_angles_rad = UniformCrankAngles(s.crank_angles_per_mesh_period, period);
  if (!s.loaded) s.estimate_error = false;
  ParseDiscsAndOutput(root, in, s);
  if (in.stiffness) {
    Study::StiffnessSpec st;
    st.rated_torque_Nm = in.stiffness->rated_torque_Nm;
    st.crank_angle_deg = in.stiffness->crank_angle_deg.value_or(0.0);
    if (!s.loaded)
      root["stiffness"].FailWith(
          "the torsional curve needs the loaded stage: analysis.evaluate must include \"loaded\" (or be absent)");
    s.stiffness = st;
  }
  ParseTolerances(root, in, s);
  // The bearing life (docs/life.md, "Cycloid"): each duty line is one LTCA cycle at its torque.
  s.life = cycloid_common::ParseLife(root, in, s.drive, s.disc_torque_Nmm(), true);
  if (s.life && s.discs > 1)
    root["discs"].Fail("1 with a bearing life (the life is modelled for one disc; found " + std::to_string(s.discs) +
                       " discs)");
  if (s.life) {
    const Node at = root.Has("duty_cycle") ? root["duty_cycle"] : root["load"]["input_speed_rpm"];
    if (!s.loaded)
      at.FailWith("a life needs the loaded stage: analysis.evaluate must include \"loaded\" (or be absent)");
    if (!cycloid::UniformWholeMeshPeriods(s.crank_angles_rad, s.drive.rollers))
      at.FailWith("a life needs crank angles that sample whole mesh periods (360/" + std::to_string(s.drive.rollers) +
                  " deg) uniformly (the bearings' loads are averaged over their periods): use "
                  "analysis.crank_angles_per_mesh_period");
  }
  s.lubrication = ParseLubrication(root, in, s);
  ParseCatalogue(root, in, s);
  if (in.torsional_dynamics) {
    const Node block = root["torsional_dynamics"];
    if (!s.loaded)
      block.FailWith("the mesh stiffness needs the loaded stage: analysis.evaluate must include \"loaded\" (or be "
                     "absent)");
    s.torsional = ParseTorsionalDynamics(block, *in.torsional_dynamics);
  }
  // The rated bearings' catalogue designations, for bom.csv (validated with their blocks).
  for (const auto& [block, into] : {std::pair<const char*, std::string*>{"crank_bearing", &s.crank_bearing_designation},
                                    {"pins", &s.pin_designation}})
    if (root.Has(block) && root[block].json().is_object() && root[block].Has("designation"))
      *into = root[block]["designation"].String();
  if (in.grinding) {
    try {
      s.grinding = cycloid::FormGrindingWheel(s.drive, in.grinding->wheel_radius_mm, in.grinding->tolerance_um * 1e-3);
      s.grinding_tolerance_um = in.grinding->tolerance_um;
    } catch (const std::invalid_argument& e) {
      root["grinding"]["wheel_radius_mm"].FailWith(e.what());
    }
  }
  s.inspection = in.inspection;
  if (in.measured_profile) {
    const Node n = root["measured_profile"];
    const int k = std::stoi(in.measured_profile->part.substr(5));
    if (k > s.discs)
      n["part"].Fail("a disc of the drive, disc_1 to disc_" + std::to_string(s.discs) + " (discs = " +
                     std::to_string(s.discs) + ")");
    s.measured_disc = k;
    const InspectedPart part = DiscPart(s, k);
    // Covering: no arc between neighbouring points longer than an eighth of a tooth.
    s.measured = ReadMeasuredProfile(n, part, part.profile.length_mm() / (8.0 * s.drive.teeth));
  }
  return s;
}

namespace {

// grinding_wheel.csv (model/cycloid/form_grinding.h).
std::string GrindingCsv(const Study& s) {
  const cycloid::FormWheel& w = *s.grinding;
  std::string out = "# form wheel for '" + s.name + "': axial profile r(y) (the wheel's radius at axial position y), "
                    "centre distance " + Format(w.centre_distance_mm, 12) + " mm, index " +
                    Format(w.index_rad * 180.0 / kPi, 12) + " deg; the polygon through the points is within " +
                    Format(w.residual_form_error_mm * 1e3, 4) + " um of the tooth\n"
                    "y_mm,radius_mm,disc_x_mm,profile_parameter_rad\n";
  char line[160];
  for (size_t i = 0; i < w.y_mm.size(); ++i) {
    std::snprintf(line, sizeof line, "%.12g,%.12g,%.12g,%.12g\n", w.y_mm[i], w.radius_mm[i],
                  w.centre_distance_mm - w.radius_mm[i], w.t[i]);
    out += line;
  }
  return out;
}

}  // namespace

InspectedPart DiscPart(const Study& s, int k) {
  const double gamma = cycloid::DiscPhaseRotationRad(k, s.discs, s.drive.teeth);
  const std::string frame =
      "disc " + std::to_string(k) + " of " + std::to_string(s.discs) +
      ": origin at the disc's centre (its bore), the output-pin holes at R_w (cos, sin)(360 j / Z_w deg); the tooth "
      "profile is the model's disc frame's turned by " + Format(gamma * 180.0 / kPi, 12) +
      " deg (-360 (k - 1) / (N teeth)); disc 1 is the frame of tooth.dxf";
  // 256 table points a tooth: the projection's start within a small part of a tooth.
  return {"disc_" + std::to_string(k), frame,
          "the disc's centre (the bore's axis), the output-pin holes for the angular position",
          profile::ClosedProfile(cycloid::DiscPartProfile(s.drive, k, s.discs), 0.0, 2.0 * kPi, 256 * s.drive.teeth)};
}

nlohmann::ordered_json Input::SchemaRules() {
  // The loaded stage (analysis.evaluate absent or with "loaded") needs the material and the load;
  // a life (a duty cycle or load.input_speed_rpm) the crank bearing, the output mechanism, one disc
  // and the loaded stage, and not both forms of the speed; the compliant output mechanism and the
  // torsional curve the loaded stage.
  // Tolerances: one disc; the output pins' and holes' bands need the output mechanism's radii.
  // The lubricated losses (docs/lubrication.md): the output mechanism and the loaded stage.
  nlohmann::ordered_json rules = nlohmann::ordered_json::parse(R"({"dependentRequired": {"monte_carlo": ["tolerances"]}, "allOf": [
    {"if": {"required": ["tolerances"]}, "then": {"properties": {"discs": {"maximum": 1}}}},
    {"if": {"required": ["tolerances"],
            "properties": {"tolerances": {"anyOf": [{"required": ["output_pin_position_um"]},
                                                    {"required": ["output_hole_position_um"]},
                                                    {"required": ["output_hole_diameter_um"]}]}}},
     "then": {"required": ["output_mechanism"], "properties": {"output_mechanism": {"required": ["pin_radius_mm"]}}}},
    {"if": {"required": ["analysis"],
            "properties": {"analysis": {"required": ["evaluate"],
                                        "properties": {"evaluate": {"not": {"contains": {"enum": ["loaded"]}}}}}}},
     "else": {"required": ["material", "load"]}},
    {"if": {"anyOf": [{"required": ["duty_cycle"]},
                      {"required": ["load"], "properties": {"load": {"required": ["input_speed_rpm"]}}}]},
     "then": {"required": ["crank_bearing", "output_mechanism"],
              "properties": {"analysis": {"properties": {"evaluate": {"contains": {"const": "loaded"}}}},
                             "discs": {"maximum": 1}}}},
    {"if": {"required": ["duty_cycle"]},
     "then": {"properties": {"load": {"not": {"required": ["input_speed_rpm"]}}}}},
    {"if": {"required": ["output_mechanism"], "properties": {"output_mechanism": {"required": ["pin_radius_mm"]}}},
     "then": {"required": ["material", "load"],
              "properties": {"analysis": {"properties": {"evaluate": {"contains": {"const": "loaded"}}}}}}},
    {"if": {"required": ["stiffness"]},
     "then": {"required": ["material", "load"],
              "properties": {"analysis": {"properties": {"evaluate": {"contains": {"const": "loaded"}}}}}}},
    {"if": {"required": ["torsional_dynamics"]},
     "then": {"required": ["material", "load"],
              "properties": {"analysis": {"properties": {"evaluate": {"contains": {"const": "loaded"}}}}}}},
    {"if": {"required": ["lubricant"]},
     "then": {"required": ["output_mechanism"],
              "properties": {"analysis": {"properties": {"evaluate": {"contains": {"const": "loaded"}}}}}}},
    {"if": {"required": ["ratings"]},
     "then": {"required": ["material", "load", "crank_bearing", "output_mechanism"],
              "properties": {"analysis": {"properties": {"evaluate": {"contains": {"const": "loaded"}}}},
                             "discs": {"maximum": 1}}}},
    {"if": {"required": ["external_loads"]}, "then": {"required": ["output_bearing"]}},
    {"if": {"required": ["output_bearing"]}, "then": {"required": ["external_loads"]}}
  ]})");
  AddLubricationSchemaRules(rules);
  // The modified life a_ISO (docs/life.md): a bearing's C_u and D_pw with lubricant.contamination_factor.
  for (const auto& rule : ModifiedLifeSchemaRules({{"crank_bearing"}, {"pins"}})) rules["allOf"].push_back(rule);
  // The measured disc is one of the drive's: disc_k with k <= discs (absent: 1). Each rule holds
  // for every discs <= N, so that together they leave disc_1 … disc_discs.
  for (int n = 1; n < 8; ++n) {
    nlohmann::ordered_json parts = nlohmann::ordered_json::array();
    for (int k = 1; k <= n; ++k) parts.push_back("disc_" + std::to_string(k));
    rules["allOf"].push_back(
        {{"if", {{"properties", {{"discs", {{"maximum", n}}}}}}},
         {"then", {{"properties", {{"measured_profile", {{"properties", {{"part", {{"enum", parts}}}}}}}}}}}});
  }
  return rules;
}

namespace {

// The headline outputs of a cycle, by their result.json names.
std::vector<std::pair<std::string, double>> Headlines(const CycleResult& c) {
  return {{"max_contact_stress_MPa", c.max_pressure_MPa},
          {"lte_peak_to_peak_arcsec", c.lte_peak_to_peak_arcsec},
          {"lte_mean_abs_arcsec", c.lte_mean_abs_arcsec},
          {"gear_ratio_peak_to_peak", c.gear_ratio_peak_to_peak},
          {"max_pair_load_N", c.max_pair_load_N}};
}

// True when the angles are a uniform sampling of whole mesh periods (the cycle is periodic).
bool WholePeriods(const std::vector<double>& a, int rollers) {
  const size_t n = a.size();
  if (n < 3) return false;
  const double step = a[1] - a[0];
  for (size_t k = 1; k < n; ++k)
    if (std::abs(a[k] - a[k - 1] - step) > 1e-9 * std::max(1.0, std::abs(step))) return false;
  const double periods = step * n / (2.0 * kPi / rollers);
  return step > 0 && std::abs(periods - std::round(periods)) < 1e-6 && std::round(periods) >= 1;
}

}  // namespace

// The remaining sampling bias of a periodic series' largest (sign +1) or smallest (sign −1)
// sample y₀: the larger of two estimates of how far the true extreme lies beyond it.
// - A smooth extreme (missed by up to |f''| h²/8: some sample lies within h/2 of it, and f falls
//   by |f''| (h/2)²/2 over that distance): the parabola through y₀ and its neighbours peaks
//   (y₊ − y₋)² / (8 |y₋ − 2y₀ + y₊|) beyond y₀.
// - A kink (a pair entering or leaving contact; missed by O(h)): the rising secant through the two
//   samples before the extreme and the falling secant through the two after, extended, meet
//   above y₀ when the kink lies between y₀ and a neighbour.
// - A jump (`jumps`: a derivative such as the gear ratio jumps where a pair enters or leaves
//   contact; its extreme is the one-sided limit at the jump, missed by O(h)): the series on the
//   near side of the jump continues its trend for up to one step, y₀ minus the nearer neighbour
//   (the smaller of the two drops; the larger one is the jump).
double PeakBias(const std::vector<double>& values, double sign, bool jumps = false) {
  const size_t n = values.size();
  if (n < 5) return 0.0;
  size_t k = 0;
  for (size_t i = 1; i < n; ++i)
    if (sign * values[i] > sign * values[k]) k = i;
  auto y = [&](long d) { return sign * values[size_t((long(k) + d + long(n)) % long(n))]; };
  double bias = 0;
  const double curvature = y(-1) - 2 * y(0) + y(1);  // <= 0 at the largest sample
  if (curvature < 0) bias = (y(1) - y(-1)) * (y(1) - y(-1)) / (-8.0 * curvature);
  // Kink between y₀ and y₊: rising line through y₋, y₀; falling line through y₊, y₊₊.
  {
    const double rise = y(0) - y(-1), fall = y(2) - y(1);
    if (rise > 0 && fall < 0) {
      const double x = (y(1) - fall - y(0)) / (rise - fall);
      if (x >= 0 && x <= 1) bias = std::max(bias, rise * x);
    }
  }
  // Kink between y₋ and y₀: rising line through y₋₋, y₋; falling line through y₀, y₊.
  {
    const double rise = y(-1) - y(-2), fall = y(1) - y(0);
    if (rise > 0 && fall < 0) {
      const double x = (y(0) - y(-1) - rise) / (rise - fall);  // in [-1, 0] when it lies there
      if (x >= -1 && x <= 0) bias = std::max(bias, fall * x);
    }
  }
  if (jumps) bias = std::max(bias, std::min(y(0) - y(-1), y(0) - y(1)));
  return bias;
}

// The sampling bias of a headline of the cycle from its per-angle series (0 for the mean |LTE|,
// an average).
std::vector<double> PeakBiases(const CycleResult& c) {
  std::vector<double> stress, load;
  for (const MeshLoad& m : c.meshes) {
    stress.push_back(m.max_pressure_MPa);
    double l = 0;
    for (const PairLoad& p : m.pairs) l = std::max(l, p.load_N);
    load.push_back(l);
  }
  return {PeakBias(stress, 1), PeakBias(c.lte_arcsec, 1) + PeakBias(c.lte_arcsec, -1), 0.0,
          PeakBias(c.gear_ratio, 1, true) + PeakBias(c.gear_ratio, -1, true), PeakBias(load, 1)};
}

// Crank-angle error of a value at 2N angles from its values at N/2 (when known), N and 2N: the
// difference d = |v(N) − v(2N)| times the geometric tail r/(1 − r) of the observed ratio
// r = d / |v(N/2) − v(N)| (the remaining error if the differences keep shrinking by r), within
// [1, kMaxTailFactor]; kMaxTailFactor when the differences do not shrink or N/2 is not available.
double CrankError(double half, double base, double doubled, bool have_half) {
  const double d = std::abs(base - doubled), d1 = std::abs(half - base);
  double factor = kMaxTailFactor;
  if (have_half && d < d1) {
    const double ratio = d / d1;
    factor = std::clamp(ratio / (1.0 - ratio), 1.0, kMaxTailFactor);
  }
  return factor * d;
}

// Crank-angle refinement and estimated discretisation errors of the headline outputs
// (docs/cycloid.md, "Estimated error"). A peak read from samples of step h is biased low by up to
// |f''| h²/8, and a peak-to-peak value collects the bias of both extremes; a subset of the same
// samples cannot see a peak that both miss, a refined set can. So the cycle is run again at the
// same number of angles shifted by half a step; the union (2N uniform angles) is the reported
// cycle. Its crank-angle error is CrankError over N/2 (every second angle), N and 2N, plus the
// remaining bias of its extremes (PeakBias on the 2N series). The grid part is |value(N) −
// value(N) on half the cells each way| (the edge peaks are singular: no order is assumed).
// Reported: their sum.
void RefineAndEstimateErrors(const Study& s, const LoadedTca& tca, Result& r, Progress& progress) {
  if (!s.estimate_error) return;
  const CycleResult base = r.cycle;  // the study's N angles
  const std::vector<double>& angles = s.crank_angles_rad;
  const size_t n = angles.size();
  const bool crank = WholePeriods(angles, s.drive.rollers) && n >= 4;
  CycleResult half;
  bool half_ok = false;
  if (crank && n % 2 == 0) {
    std::vector<double> sub_angles;
    std::vector<MeshLoad> meshes;
    for (size_t k = 0; k < n; k += 2) {
      sub_angles.push_back(angles[k]);
      meshes.push_back(base.meshes[k]);
    }
    half = SummariseCycle(s.drive, std::move(meshes), sub_angles);
    half_ok = true;
  }
  if (crank) {
    const double half_step = 0.5 * (angles[1] - angles[0]);
    std::vector<double> shifted;
    for (double a : angles) shifted.push_back(a + half_step);
    CycleResult sh = RunCycle(tca, s.disc_torque_Nmm(), shifted,
                              [&](double f) { progress.Update(0.5 + 0.4 * f, "half-step-shifted angles"); });
    std::vector<MeshLoad> meshes;
    std::vector<double> both;
    for (size_t k = 0; k < n; ++k) {
      meshes.push_back(base.meshes[k]);
      meshes.push_back(std::move(sh.meshes[k]));
      both.push_back(angles[k]);
      both.push_back(shifted[k]);
    }
    r.cycle = SummariseCycle(s.drive, std::move(meshes), both);
    r.crank_angles_rad = both;
    r.crank_error_angles = int(n);
  } else {
    r.warnings.push_back("crank-angle sampling error not estimated: the angles are not a uniform sampling "
                         "(>= 4 angles) of whole mesh periods");
  }
  LoadedOptions coarse = s.options;
  coarse.profile_cells = std::max(4, s.options.profile_cells / 2);
  coarse.axial_cells = std::max(4, s.options.axial_cells / 2);
  coarse.keep_pressure = false;
  r.coarse_grid = {coarse.profile_cells, coarse.axial_cells};
  const LoadedTca coarse_tca(s.drive, tca.crowning(), s.material, coarse);
  const CycleResult g = RunCycle(coarse_tca, s.disc_torque_Nmm(), angles,
                                 [&](double f) { progress.Update(0.9 + 0.1 * f, "coarse grid"); });
  const auto hf = Headlines(r.cycle), hb = Headlines(base), hg = Headlines(g);
  const auto hh = half_ok ? Headlines(half) : hb;
  const std::vector<double> bias = crank ? PeakBiases(r.cycle) : std::vector<double>(hf.size(), 0.0);
  for (size_t i = 0; i < hf.size(); ++i) {
    const std::string& name = hf[i].first;
    const double e_grid = std::abs(hb[i].second - hg[i].second);
    const double e_crank = crank ? CrankError(hh[i].second, hb[i].second, hf[i].second, half_ok) + bias[i] : 0.0;
    r.error_grid.push_back({name, e_grid});
    if (crank) r.error_crank.push_back({name, e_crank});
    r.estimated_error.push_back({name, e_grid + e_crank});
    const double value = std::abs(hf[i].second);
    if (e_grid + e_crank > kErrorShare * value)
      r.warnings.push_back(name + ": estimated error " + Format(e_grid + e_crank, 3) + " (grid " +
                           Format(e_grid, 3) + ", crank angles " + Format(e_crank, 3) + ") exceeds " +
                           Format(100 * kErrorShare, 3) + "% of its value " + Format(hf[i].second, 4));
  }
}

// A loose compatibility tolerance moves the LTE and GR far more than the stress (measured on the
// paper's examples, docs/cycloid.md): say so in the warnings.
void ToleranceWarning(const Study& s, Result& r) {
  if (s.options.tolerance <= kLooseTolerance) return;
  r.warnings.push_back("analysis.tolerance " + Format(s.options.tolerance, 3) + " is looser than " +
                       Format(kLooseTolerance, 3) + ": on the paper's examples such a tolerance moves " +
                       "lte_peak_to_peak_arcsec and gear_ratio_peak_to_peak by more than " +
                       Format(100 * kToleranceShare, 3) + "% of their values (the stress much less); " +
                       "use 1e-3 (the default) for the transmission error");
}

namespace {

}  // namespace

namespace {

// The output mechanism over the crank bearing's load period (docs/cycloid.md, "Output mechanism"):
// every disc k at its own crank angle φ + 2πk/N, its ring-pin resultant the first disc's at that
// angle (periodic in the crank frame with the mesh period, so a shift of the sampled series), its
// output pins solved with clearance and compliance at the shared output angle −φ/n2, the bearing
// force from its force balance; the pins' bending under every disc's force, the crankshaft's net
// force and couple.
void RunOutputMechanism(const Study& s, Result& r) {
  using namespace camopt::cycloid;
  const OutputSpec& o = *s.output;
  OutputPins pins = o.pins;
  pins.face_width_mm = s.drive.face_width_mm;
  pins.e_star_MPa = r.composite_modulus_MPa;
  const std::vector<double>& a = r.crank_angles_rad;
  const size_t n = a.size();
  int periods = 0;
  if (!UniformWholeMeshPeriods(a, s.drive.rollers, &periods))
    throw std::logic_error("output mechanism: the crank angles are not a uniform sampling of whole mesh periods");
  const double tau = 2.0 * kPi / s.drive.rollers, h = tau * periods / double(n);
  std::vector<Vec2<double>> ring;
  for (const MeshLoad& m : r.cycle.meshes) ring.push_back(RingPinResultantCrankFrame(s.drive, m));
  const long per_rev = long(n) * s.drive.rollers / periods;
  const int load_period = OutputPinPeriodInMeshPeriods(OutputMechanism{pins.pins, pins.pin_circle_radius_mm}, s.drive.teeth);
  const int repeats = load_period / std::gcd(load_period, periods);
  const std::vector<double> z =
      DiscPlanesOnPin(o.support, o.span_mm, s.discs, s.drive.face_width_mm, s.disc_spacing_mm);
  double z_mean = 0.0;
  for (double x : z) z_mean += x / double(z.size());
  const double torque = s.disc_torque_Nmm();
  for (size_t m = 0; m < n * size_t(repeats); ++m) {
    const double phi = a[0] + double(m) * h, output_angle = -phi / s.drive.teeth;
    r.output_angles_rad.push_back(phi);
    std::vector<Result::DiscSample> discs;
    Vec2<double> net(0.0, 0.0), couple(0.0, 0.0);
    for (int k = 0; k < s.discs; ++k) {
      const double phi_k = phi + 2.0 * kPi * k / s.discs;
      const size_t shift = size_t(per_rev / s.discs) * size_t(k);
      Result::DiscSample d;
      d.pins = SolveOutputPins(pins, s.drive.eccentricity_mm, torque, output_angle - phi_k);
      d.bearing_crank_frame = CrankBearingForce(ring[(m + shift) % n], d.pins);
      d.bearing_fixed_frame = Rotate(d.bearing_crank_frame, phi_k);
      net += d.bearing_fixed_frame;
      couple += (z[size_t(k)] - z_mean) * d.bearing_fixed_frame;
      r.max_bearing_load_N = std::max(r.max_bearing_load_N, d.bearing_crank_frame.norm());
      for (double q : d.pins.force_N) r.max_output_pin_force_N = std::max(r.max_output_pin_force_N, q);
      r.max_moment_residual = std::max(r.max_moment_residual, torque > 0 ? d.pins.moment_residual_Nmm / torque : 0.0);
      discs.push_back(std::move(d));
    }
    // Each pin's bending under every disc's force Q_jk n_jk (on the pin, fixed frame).
    double sigma = 0.0;
    for (int j = 0; j < pins.pins; ++j) {
      std::vector<Vec2<double>> f;
      for (int k = 0; k < s.discs; ++k)
        f.push_back(Rotate(Vec2<double>(discs[size_t(k)].pins.force_N[size_t(j)] * discs[size_t(k)].pins.normal[size_t(j)]),
                           phi + 2.0 * kPi * k / s.discs));
      sigma = std::max(sigma, PinBendingStress(PinBendingMoment(o.support, o.span_mm, z, f), pins.pin_radius_mm));
    }
    r.pin_bending_stress_MPa.push_back(sigma);
    r.net_crank_force_N.push_back(net.norm());
    r.crank_couple_Nmm.push_back(couple.norm());
    r.max_bending_stress_MPa = std::max(r.max_bending_stress_MPa, sigma);
    r.max_net_crank_force_N = std::max(r.max_net_crank_force_N, net.norm());
    r.max_couple_Nmm = std::max(r.max_couple_Nmm, couple.norm());
    if (m < n) r.bearing_load_at_ltca_angles_N.push_back(discs[0].bearing_crank_frame.norm());
    r.output.push_back(std::move(discs));
  }
  r.max_contact_pressure_MPa = HoleContactPressure(pins, r.max_output_pin_force_N);
  if (r.max_moment_residual > 1e-9)
    r.warnings.push_back("output mechanism: the moment balance of the output pins closes only to " +
                         Format(r.max_moment_residual, 3) + " of the disc torque");
}

}  // namespace

namespace {

// The losses of the drive (every disc alike: N times one disc's mean over whole mesh periods) over
// the solved meshes `loads`, at an operating point: the oil temperature given or from the housing's
// balance, then the losses at it.
struct LubricatedPoint {
  OilTemperature oil;
  cycloid::CycloidAngleLosses mean;  ///< the drive's mean loss per element [W]; the thinnest film
  double min_lambda_crank_rad = 0;
  double sampling_error_W = 0;       ///< |mean − mean over every other angle|
};
LubricatedPoint LubricatedAt(const Study& s, const std::vector<cycloid::MeshLubricationLoads>& loads, double speed) {
  const Study::Lubrication& l = *s.lubrication;
  const double e_star = s.material.composite_modulus_MPa();
  LubricatedPoint p;
  const std::vector<cycloid::CrankKinematics<double>> kinematics =
      cycloid::RevolutionKinematics(s.drive, l.spec, e_star, loads, l.pins, speed);  // once for every t
  const auto at = [&](double t, LubricatedPoint* fill) {
    const contact::OilState<double> oil = contact::OilStateAt(l.spec.oil, t);
    cycloid::CycloidAngleLosses mean;
    double even = 0.0;
    size_t evens = 0;
    const double n = double(loads.size()), discs = double(s.discs);
    for (size_t k = 0; k < loads.size(); ++k) {
      const cycloid::CycloidAngleLosses x =
          cycloid::LossesAt(kinematics[k], l.spec, oil);
      mean.ring_pins_sliding += discs * x.ring_pins_sliding / n;
      mean.ring_pin_bearings += discs * x.ring_pin_bearings / n;
      mean.output_pins_sliding += discs * x.output_pins_sliding / n;
      mean.output_roller_bearings += discs * x.output_roller_bearings / n;
      mean.crank_bearing += discs * x.crank_bearing / n;
      mean.ring_pins_rolling += discs * x.ring_pins_rolling / n;
      mean.output_pins_rolling += discs * x.output_pins_rolling / n;
      if (k % 2 == 0) even += discs * x.total(), ++evens;
      if (fill && x.min_lambda_pin >= 0 && (mean.min_lambda_pin < 0 || x.min_lambda < mean.min_lambda)) {
        mean.min_lambda = x.min_lambda;
        mean.min_film_mm = x.min_film_mm;
        mean.min_lambda_pin = x.min_lambda_pin;
        mean.min_at_output_pin = x.min_at_output_pin;
        fill->min_lambda_crank_rad = loads[k].crank_angle_rad;
      }
    }
    if (fill) {
      fill->mean = mean;
      fill->sampling_error_W = evens > 0 ? std::abs(mean.total() - even / double(evens)) : 0.0;
    }
    return mean.total();
  };
  p.oil = SolveOilTemperature(l.common, [&](double t) { return at(t, nullptr); });
  at(p.oil.celsius, &p);
  return p;
}

std::vector<cycloid::MeshLubricationLoads> LubricationLoads(const Study& s, const std::vector<MeshLoad>& meshes,
                                                           double disc_torque_Nmm) {
  return cycloid::LubricationLoadsOverRevolution(s.drive, s.lubrication->mechanism, meshes, disc_torque_Nmm);
}

void RunLubrication(const Study& s, const RunContext& ctx, Result& r) {
  const Study::Lubrication& l = *s.lubrication;
  const double speed = l.common.input_speed_rpm;
  const double output_power = s.torque_Nm * speed * 2 * kPi / 60 / s.drive.teeth;
  const LubricatedPoint p = LubricatedAt(s, LubricationLoads(s, r.cycle.meshes, s.disc_torque_Nmm()), speed);
  if (!p.oil.found()) {
    r.lubrication_error = "no thermal equilibrium: " + p.oil.thermal->why;
  } else {
    LubricationResult out = CommonLubricationResult(l.common, p.oil, s.torque_Nm, output_power, p.mean.total());
    out.power_loss_W.ring_pins_sliding = p.mean.ring_pins_sliding;
    out.power_loss_W.ring_pin_bearings = p.mean.ring_pin_bearings;
    out.power_loss_W.output_pins_sliding = p.mean.output_pins_sliding;
    out.power_loss_W.output_roller_bearings = p.mean.output_roller_bearings;
    out.power_loss_W.crank_bearing = p.mean.crank_bearing;
    out.power_loss_W.ring_pins_rolling = p.mean.ring_pins_rolling;
    if (l.pins) out.power_loss_W.output_pins_rolling = p.mean.output_pins_rolling;
    out.power_loss_sampling_error_W = p.sampling_error_W;
    if (p.mean.min_lambda_pin >= 0)
      out.min_film_lambda = {p.mean.min_lambda, p.mean.min_film_mm * 1e3, p.min_lambda_crank_rad * 180 / kPi,
                             p.mean.min_at_output_pin ? "output pin" : "ring pin", RegimeName(p.mean.min_lambda),
                             p.mean.min_lambda_pin};
    // No load: the ring pins and output pins carry nothing; the bearings' M0 remains.
    std::vector<MeshLoad> idle(r.cycle.meshes.size());
    for (size_t k = 0; k < idle.size(); ++k) idle[k].crank_angle_rad = r.cycle.meshes[k].crank_angle_rad;
    const LubricatedPoint none = [&] {
      Study::Lubrication fixed = l;
      fixed.common.temperature_C = p.oil.celsius;  // the same oil temperature
      Study at = s;
      at.lubrication = fixed;
      return LubricatedAt(at, LubricationLoads(at, idle, 0.0), speed);
    }();
    out.no_load_running_torque_Nm = none.mean.total() / (speed * 2 * kPi / 60);
    if (!l.pins) out.not_modelled.push_back("the output pins' contacts (no output_mechanism pin and hole radii)");
    if (l.spec.ring_pins_rotate && !l.ring_pins_given)
      out.not_modelled.push_back("the ring pins' bearings (no bearing_friction.ring_pins)");
    if (l.pins && l.pins->roller_radius_mm > 0 && !l.output_rollers_given)
      out.not_modelled.push_back("the output rollers' bearings (no bearing_friction.output_rollers)");
    if (!l.crank_given) out.not_modelled.push_back("the crank bearing (no bearing_friction.crank)");
    for (double v : {out.efficiency, out.oil_temperature_C, out.power_loss_W.total, out.no_load_running_torque_Nm})
      Finite(v, "lubrication");
    r.lubrication = out;
  }
  if (l.common.map) {
    // One loaded cycle per torque (the study's crank angles, its grid), every speed on it.
    Progress progress("cycloid_ltca efficiency map", ctx.quiet);
    LoadedOptions options = s.options;
    options.keep_pressure = false;
    options.crank_slope = false;
    const LoadedTca tca(s.drive, s.crowning, s.material, options);
    size_t done = 0;
    const size_t total = l.common.map->torque_Nm.size() * l.common.map->speed_rpm.size();
    for (double torque : l.common.map->torque_Nm) {
      const double disc_torque = torque * 1000.0 / s.discs;
      const CycleResult cycle = RunCycle(tca, disc_torque, s.crank_angles_rad, {});
      const std::vector<cycloid::MeshLubricationLoads> loads = LubricationLoads(s, cycle.meshes, disc_torque);
      for (double n : l.common.map->speed_rpm) {
        const LubricatedPoint m = LubricatedAt(s, loads, n);
        const double power = torque * n * 2 * kPi / 60 / s.drive.teeth;
        r.efficiency_map.push_back({torque, n, power > 0 ? power / (power + m.mean.total()) : 0.0, m.mean.total(),
                                    m.oil.celsius, m.mean.min_lambda_pin >= 0 ? m.mean.min_lambda : 0.0,
                                    m.oil.found() ? 1.0 : 0.0});
        progress.Update(double(++done) / double(total), std::to_string(total) + " operating points");
      }
    }
    progress.Done();
  }
}

}  // namespace

namespace {

// The three-segment stiffness and the lost motion at the study's percentage, from the loading
// branch of the torsional curve (docs/ratings.md).
void RunSegments(const Study& s, Result& r) {
  std::vector<camopt::TorsionPoint> curve;  // the loading branch, −T_r … 0−, 0+ … T_r
  for (const cycloid::TorsionPoint& p : r.torsion->points)
    curve.push_back({p.torque_Nmm / 1000.0, p.output_angle_rad * kArcminPerRad});
  const double tr = s.stiffness->rated_torque_Nm;
  r.segments = ThreeSegmentTorsionalStiffness(curve, s.segment_T1_Nm, s.segment_T2_Nm, tr);
  r.lost_motion_user_rad = LostMotionArcmin(curve, tr, s.lost_motion_percent / 100.0) / kArcminPerRad;
}

// Ratings, the output bearing and the parts' masses (docs/ratings.md).
// The allowable output speed at the rated torque (docs/ratings.md): one LTCA cycle of `tca` at that
// torque, its lubricated losses at a trial speed and the oil's limit (RatingsResult's note says
// why when the study has no housing balance).
void AllowableSpeed(const Study& s, const LoadedTca& tca, double ratio, RatingsResult& g) {
  if (!s.lubrication) return;  // the default note: no lubricant
  if (s.lubrication->common.temperature_C) {
    g.allowable_speed_note = "not computed: the oil's temperature is given (lubricant.temperature_C); the allowable "
                             "speed is the housing balance's thermal limit: give lubricant.thermal instead";
    return;
  }
  const double torque_Nmm = g.rated_torque_Nm * 1000.0;  // one disc (ratings need discs = 1)
  const CycleResult c = RunCycle(tca, torque_Nmm, s.crank_angles_rad);
  if (!c.converged) {
    g.allowable_speed_note = "not computed: the LTCA did not converge at the rated torque";
    return;
  }
  const std::vector<cycloid::MeshLubricationLoads> loads = LubricationLoads(s, c.meshes, torque_Nmm);
  Study at = s;
  SolveAllowableSpeed(
      [&](double n, double t) {
        at.lubrication->common.temperature_C = t;
        return LubricatedAt(at, loads, n).mean.total();
      },
      s.lubrication->common.cooling, s.lubrication->common.max_oil_temperature_C, ratio,
      s.ratings->in.rated_output_speed_rpm * ratio, g);
}

void RunCatalogue(const Study& s, const RunContext& ctx, Result& r) {
  if (s.stiffness || s.ratings) {
    const double stack = s.discs > 1 ? s.disc_spacing_mm * (s.discs - 1) + s.drive.face_width_mm : s.drive.face_width_mm;
    std::vector<Vec2<double>> profile;
    const int samples = 400 * s.drive.teeth;
    for (int k = 0; k < samples; ++k)
      profile.push_back(ToothProfile<double>(s.drive, 2.0 * kPi * k / samples).point);
    r.masses = cycloid_common::CycloidMasses(s.drive, profile, s.discs, stack, s.bore_diameter_mm,
                                             s.output ? &s.output->pins : nullptr,
                                             s.output ? s.output->span_mm : 0.0, s.density_kg_m3);
  }
  if (s.ratings) {
    LoadedOptions options = s.options;
    options.keep_pressure = false;
    options.crank_slope = false;
    const LoadedTca tca(s.drive, s.crowning, s.material, options);
    Progress progress("cycloid_ltca ratings", ctx.quiet);
    int step = 0;
    const double ratio = double(s.drive.teeth) / double(s.drive.rollers - s.drive.teeth);
    auto solve = [&](const LoadedTca& t, const std::vector<double>& angles, const std::string& what,
                     const RatingsResult* near = nullptr) {
      return SolveRatings(
          s.ratings->in, s.ratings->limits,
          [&](double torque_Nm) {
            ++step;
            progress.Update(std::min(0.95, 0.01 * step), what + std::to_string(step) + " LTCA cycles");
            return cycloid_common::CycloidRatingPoint(s.ratings->in, s.ratings->life, t, angles, ratio, torque_Nm);
          },
          ratio, std::max(s.torque_Nm, 1.0), near);
    };
    try {
      // With the error estimate on a uniform sampling (>= 4 angles) of whole mesh periods the ratings
      // are solved on the refined angles, the study's N and the N shifted by half a step, as the
      // headlines are (RefineAndEstimateErrors): a peak of a pin's or the crank bearing's load that
      // every one of the N angles misses (and so every subset of them) is then seen, and the kind run
      // at a rated torque reproduces its rating. Their error: |refined − N angles| (crank angles) +
      // |N angles − the same on half the cells each way| (grid) + the search's bracket.
      const std::vector<double>& angles = s.crank_angles_rad;
      const bool refine = s.estimate_error && WholePeriods(angles, s.drive.rollers) && angles.size() >= 4;
      std::vector<double> refined;
      if (refine) {
        const double half_step = 0.5 * (angles[1] - angles[0]);
        for (double a : angles) refined.push_back(a), refined.push_back(a + half_step);
      }
      r.ratings = solve(tca, refine ? refined : angles, "");
      AllowableSpeed(s, tca, ratio, *r.ratings);
      if (s.estimate_error) {
        LoadedOptions coarse = options;
        coarse.profile_cells = std::max(4, options.profile_cells / 2);
        coarse.axial_cells = std::max(4, options.axial_cells / 2);
        const LoadedTca coarse_tca(s.drive, s.crowning, s.material, coarse);
        std::optional<RatingsResult> at_n;
        // Each search starts from its neighbour's rating (SolveRatings' `near`): the N angles' from
        // the refined ones, the coarse grid's from the N angles'.
        if (refine) at_n = solve(tca, angles, "the study's crank angles: ", &*r.ratings);
        const RatingsResult g = solve(coarse_tca, angles, "coarse grid: ", at_n ? &*at_n : &*r.ratings);
        RatingsResult& f = *r.ratings;
        auto error = [&](double fine, std::optional<double> n_angles, std::optional<double> grid) {
          const double v_n = n_angles.value_or(fine);
          return (n_angles ? std::abs(fine - v_n) : 0.0) + (grid ? std::abs(v_n - *grid) : 0.0) +
                 kRatingSearchRelTolerance * fine;
        };
        f.rated_error_Nm = error(f.rated_torque_Nm, at_n ? std::optional<double>(at_n->rated_torque_Nm) : std::nullopt,
                                 g.rated_torque_Nm);
        if (f.peak_torque_Nm && g.peak_torque_Nm)
          f.peak_error_Nm = error(*f.peak_torque_Nm, at_n ? at_n->peak_torque_Nm : std::nullopt, g.peak_torque_Nm);
        if (f.momentary_torque_Nm && g.momentary_torque_Nm)
          f.momentary_error_Nm =
              error(*f.momentary_torque_Nm, at_n ? at_n->momentary_torque_Nm : std::nullopt, g.momentary_torque_Nm);
        f.error_crank_estimated = at_n.has_value();
        f.evaluations += g.evaluations + (at_n ? at_n->evaluations : 0);
      }
    } catch (const std::invalid_argument& e) {
      r.ratings_failed = e.what();
      r.warnings.push_back(std::string("ratings not solved: ") + e.what());
    }
    progress.Done();
  }
  if (s.output_bearing) {
    r.output_bearing = TrySolveOutputBearing(*s.output_bearing, s.external_loads, &r.output_bearing_failed);
    if (!r.output_bearing) r.warnings.push_back("output bearing not rated: " + r.output_bearing_failed);
  }
}

// The ring-pin mesh as the torsional model's spring (docs/torsional_dynamics.md): at the crank
// angles θ_k = k·(2π/n1)/N of one mesh period, each disc's LTCA at T/discs and its crank angle
// θ_k + 2πd/discs, its tangent stiffness dT/dβ = 1/(dβ/dT) by the LTCA's implicit derivative of the
// loaded TE β = β0 + Δφc with respect to the torque (LoadedTca::Differentiate, contact sets
// frozen), the discs in parallel (one output angle): k = Σ k_d, and the static TE the stiffness-
// weighted mean δ_s = Σ k_d β_d / k (the linearised discs' torques sum to T at δ = δ_s).
// A state the study's cycle already solved at that torque and crank phase (φ mod 2π/n1 within
// 1e-9 rad: the drive's symmetry, RunCycle) is differentiated as it is, not solved again; it
// differs from a fresh solve only within the LTCA's tolerances (its warm start).
MeshTable CycloidMeshTable(const Study& s, const LoadedTca& tca, const CycleResult& cycle,
                           const std::vector<double>& cycle_angles_rad, const RunContext& ctx) {
  const TorsionalDynamicsInput& in = s.torsional->in;
  MeshTable t;
  t.period_rad = 2.0 * kPi / s.drive.rollers;
  t.ratio = double(s.drive.teeth);  // input (crank) turns per output turn, ring fixed: n2
  t.torque_Nm = in.load_torque_Nm.value_or(s.torque_Nm);
  t.source = "the ring-pin mesh of the LTCA at the reference torque, each disc's dT/d(beta) by the LTCA's implicit "
             "derivative of its loaded TE with respect to the torque, the discs in parallel; the output pins' and "
             "bearings' compliance not included";
  t.meshes = {{"ring_pins", 1.0}};
  const int n = in.angles_per_mesh_period;
  const double disc_torque_Nmm = t.torque_Nm * 1000.0 / s.discs;
  const bool reuse = disc_torque_Nmm == s.disc_torque_Nmm() && tca.options().keep_pressure &&
                     cycle.meshes.size() == cycle_angles_rad.size();
  auto phase = [&](double angle) {
    const double p = std::fmod(angle, t.period_rad);
    return p < 0 ? p + t.period_rad : p;
  };
  // The cycle's solved state at the phase of `angle`, or null.
  auto solved_at = [&](double angle) -> const MeshLoad* {
    if (!reuse) return nullptr;
    const double want = phase(angle);
    for (size_t i = 0; i < cycle.meshes.size(); ++i) {
      const MeshLoad& m = cycle.meshes[i];
      if (m.symmetric_source != -1 || !m.converged) continue;
      const double dp = std::abs(phase(cycle_angles_rad[i]) - want);
      if (std::min(dp, t.period_rad - dp) <= 1e-9) return &m;
    }
    return nullptr;
  };
  Progress progress("cycloid_ltca mesh stiffness", ctx.quiet);
  for (int k = 0; k < n; ++k) {
    const double theta = t.period_rad * k / n;
    double ksum = 0.0, kbeta = 0.0;
    for (int d = 0; d < s.discs; ++d) {
      const double angle = theta + 2.0 * kPi * d / s.discs;
      const MeshLoad* known = solved_at(angle);
      const MeshLoad fresh = known != nullptr ? MeshLoad{} : tca.Solve(disc_torque_Nmm, angle);
      const MeshLoad& m = known != nullptr ? *known : fresh;
      if (!m.converged)
        throw std::runtime_error("torsional dynamics: the LTCA did not converge at crank angle " +
                                 Format(theta * 180 / kPi, 6) + " deg: " + m.message);
      const LoadedTca::Derivative der = tca.Differentiate(m, "torque_Nmm");
      if (!der.converged || !(der.rotation_rad > 0))
        throw std::runtime_error("torsional dynamics: no mesh stiffness at crank angle " + Format(theta * 180 / kPi, 6) +
                                 " deg (the torque derivative did not converge)");
      const double kd = 1.0 / der.rotation_rad / 1000.0;  // [N·m/rad]
      ksum += kd;
      kbeta += kd * m.rotation_rad;
    }
    t.angles_rad.push_back(theta);
    t.stiffness_Nm_per_rad.push_back(ksum);
    t.static_te_rad.push_back(kbeta / ksum);
    progress.Update(double(k + 1) / n, std::to_string(n) + " crank angles");
  }
  progress.Done();
  return t;
}

}  // namespace

namespace {

// Crank angles of the measured disc's kinematic transmission error: per mesh period, over one
// output revolution (a feature of a few millimetres on a tooth is passed by the contact in a few
// hundredths of a mesh period).
constexpr int kMeasuredAnglesPerMeshPeriod = 64;
// The loaded TCA of a measured disc: 8 crank angles per mesh period over one output revolution
// (the contact point moves about 1 mm along the tooth per mesh period on the NNM drive).
constexpr int kMeasuredLoadedAnglesPerMeshPeriod = 8;

// The measured disc's kinematic output (model/cycloid/transmission_error.h, the profile deviation
// d(t) in the ring-pin contacts) beside the nominal's, over one output revolution of the disc's
// own crank angle φ + 2π(k − 1)/N.
CycloidMeasured MeasuredDisc(const Study& s, Result& r) {
  const MeasuredProfile& m = *s.measured;
  const int k = s.measured_disc;
  CycloidMeasured j;
  static_cast<MeasuredBlock&>(j) = MeasuredOf(m, DiscPart(s, k));
  const cycloid::OutputPins* pins = s.output ? &s.output->pins : nullptr;
  std::vector<double> crank =
      cycloid::TransmissionErrorAngles(s.drive, kMeasuredAnglesPerMeshPeriod * s.drive.rollers * s.drive.teeth);
  const double phase = 2.0 * kPi * (k - 1) / s.discs;
  for (double& c : crank) c += phase;
  cycloid::Deviations<double> none, dev;
  const profile::PeriodicSpline shape = m.shape;
  dev.profile_shape = [shape](const double& t, double* slope) { return shape(t, slope); };
  const cycloid::KinematicCurves nominal = cycloid::KinematicOutput(s.drive, pins, none, crank);
  const cycloid::KinematicCurves measured = cycloid::KinematicOutput(s.drive, pins, dev, crank);
  auto range = [](const std::vector<double>& v) {
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    return std::pair<double, double>(*lo, *hi);
  };
  std::vector<double> te, bl_nom, bl_meas;
  int no_contact = 0, jammed = 0;
  for (size_t i = 0; i < crank.size(); ++i) {
    te.push_back(measured.forward_rad[i] - nominal.forward_rad[i]);
    bl_nom.push_back(nominal.forward_rad[i] - nominal.reverse_rad[i]);
    bl_meas.push_back(measured.forward_rad[i] - measured.reverse_rad[i]);
    no_contact += measured.forward_pair[i] < 0;
    jammed += bl_meas.back() < 0;
  }
  const double as = cycloid::kArcsecPerRad, am = as / 60.0;
  const auto [ln_lo, ln_hi] = range(nominal.forward_rad);
  const auto [lm_lo, lm_hi] = range(measured.forward_rad);
  const auto [bn_lo, bn_hi] = range(bl_nom);
  const auto [bm_lo, bm_hi] = range(bl_meas);
  auto mean = [](const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / double(v.size()); };
  CycloidMeasured::Kinematic& kin = j.kinematic;
  kin.model = "the rigid kinematic output of model/cycloid/transmission_error.h with the measured normal deviation "
              "d(t) in every ring-pin contact (the roller centre on the tooth's normal at rho - rho' + d(t))";
  kin.crank_angles = long(crank.size());
  kin.crank_angles_over = "one output revolution (teeth crank turns) of this disc's own crank angle phi + 360 (k - "
                          "1) / N deg, " + std::to_string(kMeasuredAnglesPerMeshPeriod) + " per mesh period";
  kin.transmission_error = MeasuredTransmissionError::Of(
      te, as, "the measured disc's output angle less the nominal's at the same crank angle, forward torque (> 0: the "
              "output ahead)");
  kin.output_lag_peak_to_peak_arcsec = {(ln_hi - ln_lo) * as, (lm_hi - lm_lo) * as};
  kin.backlash_max_arcmin = {bn_hi * am, bm_hi * am};
  kin.backlash_min_arcmin = {bn_lo * am, bm_lo * am};
  kin.backlash_mean_arcmin = {mean(bl_nom) * am, mean(bl_meas) * am};
  kin.lost_motion_kinematic_arcmin = {bn_hi * am, bm_hi * am};
  kin.lost_motion_note = "rigid parts: the output's free turn from the forward to the reverse contact, the largest "
                         "backlash; the elastic part (stiffness block) is not computed for the measured disc";
  kin.angles_without_contact = no_contact;
  kin.jammed_angles = jammed;
  if (no_contact > 0)
    r.warnings.push_back("measured_profile: at " + std::to_string(no_contact) +
                         " crank angles no ring pin touches the measured disc's loaded flank");
  if (jammed > 0)
    r.warnings.push_back("measured_profile: the measured disc interferes with the pins (negative backlash) at " +
                         std::to_string(jammed) + " crank angles: the rigid model turns the output to first contact");
  if (s.loaded) {
    // The loaded TCA with the measured tooth (LoadedTca::SetProfileDeviation), over one output
    // revolution of this disc's crank angle, beside the nominal disc on the same angles.
    std::vector<double> angles = cycloid::TransmissionErrorAngles(
        s.drive, kMeasuredLoadedAnglesPerMeshPeriod * s.drive.rollers * s.drive.teeth);
    for (double& c : angles) c += phase;
    cycloid::LoadedOptions o = s.options;
    o.crank_slope = false;
    o.keep_pressure = false;
    const LoadedTca nominal_tca(s.drive, s.crowning, s.material, o);
    o.reuse_symmetric_angles = false;
    LoadedTca measured_tca(s.drive, s.crowning, s.material, o);
    measured_tca.SetProfileDeviation(dev.profile_shape);
    const CycleResult cn = RunCycle(nominal_tca, s.disc_torque_Nmm(), angles);
    const CycleResult cm = RunCycle(measured_tca, s.disc_torque_Nmm(), angles);
    CycloidMeasured::Loaded& lo = j.loaded.emplace();
    lo.model = "the loaded TCA (model/cycloid/loaded_tca.h) with the measured tooth in every pair's unloaded "
               "contact (arms, backlash, the moved profile's curvature in the Hertz gaps)";
    lo.crank_angles = long(angles.size());
    lo.crank_angles_over = "one output revolution of this disc's own crank angle, " +
                           std::to_string(kMeasuredLoadedAnglesPerMeshPeriod) + " per mesh period";
    lo.disc_torque_Nm = s.disc_torque_Nmm() / 1000.0;
    lo.max_contact_stress_MPa = {cn.max_pressure_MPa, cm.max_pressure_MPa};
    lo.max_pair_load_N = {cn.max_pair_load_N, cm.max_pair_load_N};
    lo.lte_peak_to_peak_arcsec = {cn.lte_peak_to_peak_arcsec, cm.lte_peak_to_peak_arcsec};
    lo.converged = cm.converged && cn.converged;
    if (!cm.converged) r.warnings.push_back("measured_profile: the loaded TCA of the measured disc did not converge at some angle");
    if (s.life && cm.converged && cn.converged) {
      // The lives as made: the duty cycle on the measured disc's loaded TCA, beside the nominal
      // disc's on the same angles (each line one cycle; the study's torque reuses the cycle above).
      const cycloid_common::LifeResult ln = cycloid_common::RunLife(*s.life, nominal_tca, angles, s.disc_torque_Nmm(), &cn.meshes);
      const cycloid_common::LifeResult lm = cycloid_common::RunLife(*s.life, measured_tca, angles, s.disc_torque_Nmm(), &cm.meshes);
      CycloidMeasured::Loaded::Life& life = lo.life.emplace();
      for (size_t i = 0; i < lm.elements.size() && i < ln.elements.size(); ++i)
        life.L10h[lm.elements[i].name] = {ln.elements[i].life.L10h, lm.elements[i].life.L10h};
      life.shortest_L10h = {ln.shortest_L10h, lm.shortest_L10h};
      life.shortest = {ln.shortest, lm.shortest};
      life.crank_angles_over = "the loaded results' angles (the study's life runs on its own angles: compare the "
                               "two columns here)";
    }
    j.not_computed = {{std::string(s.life ? "" : "the measured disc's bearing lives (no life asked), ") +
                           "elastic lost motion, gear ratio and output-mechanism loads",
                       "the stiffness and output-mechanism stages run on the nominal disc only"}};
  } else {
    j.not_computed = {{"the loaded results of the measured disc (largest contact stress, pair loads, loaded "
                       "transmission error)",
                       "analysis.evaluate is [\"unloaded\"]: no material or load"}};
  }
  return j;
}

}  // namespace

Result Run(const Study& s, const RunContext& ctx) {
  Result r;
  if (s.loaded) {
    LoadedTca tca(s.drive, s.crowning, s.material, s.options);
    r.crank_angles_rad = s.crank_angles_rad;
    {
      Progress progress("cycloid_ltca", ctx.quiet);
      const double share = s.estimate_error ? 0.5 : 1.0;
      r.cycle = RunCycle(tca, s.disc_torque_Nmm(), s.crank_angles_rad,
                         [&](double f) { progress.Update(share * f); });
      RefineAndEstimateErrors(s, tca, r, progress);
      progress.Done();
    }
    r.composite_modulus_MPa = tca.e_star_MPa();
    ToleranceWarning(s, r);
    if (s.torsional) {
      try {
        r.torsional = RunTorsionalDynamics(*s.torsional, CycloidMeshTable(s, tca, r.cycle, r.crank_angles_rad, ctx),
                                           ctx, "cycloid_ltca");
        for (const std::string& w : r.torsional->warnings) r.warnings.push_back(w);
      } catch (const StudyError&) {
        throw;  // bad input found by the run: exit 2
      } catch (const std::exception& e) {  // a mesh the model refuses (k <= 0), an LTCA or an integration that did not converge
        r.torsional_failed = e.what();
        r.warnings.push_back(std::string("torsional dynamics not solved: ") + e.what());
      }
    }
  }
  if (!s.loaded) r.crank_angles_rad = s.crank_angles_rad;
  const int n1 = s.drive.rollers;
  const size_t n = r.crank_angles_rad.size();
  r.backlash_arcsec.assign(n1, std::vector<double>(n, 0.0));
  for (size_t k = 0; k < n; ++k) {
    const UnloadedMesh<double> u = UnloadedTca<double>(s.drive, r.crank_angles_rad[k]);
    r.unloaded_te_arcsec.push_back(u.rotation * kArcsecPerRad);
    for (const auto& g : u.pairs)
      r.backlash_arcsec[g.roller][k] = g.loaded_flank ? g.backlash * kArcsecPerRad : -1.0;
  }
  if (!r.cycle.converged) {
    for (const auto& m : r.cycle.meshes)
      if (!m.converged) {
        r.warning = "not converged at crank angle " + Format(m.crank_angle_rad * 180 / kPi, 4) + " deg: " + m.message;
        break;
      }
  }
  // Tooth drawing: the modified profile of the whole disc and the rollers at crank angle 0.
  const int samples = 40 * s.drive.teeth;
  for (int k = 0; k < samples; ++k)
    r.tooth_profile.push_back(ToothProfile<double>(s.drive, 2.0 * kPi * k / samples).point);
  for (int i = 0; i < n1; ++i) r.roller_centres.push_back(RollerCentreInDisc<double>(s.drive, i, 0.0, 0.0));
  {
    // Geometry files of the disc: its true modified profile (eqs. 3–4) fitted with arcs.
    PlanarCamGeometry g;
    g.file_stem = "tooth";
    g.design_name = s.name;
    g.cam_name = "cycloid disc (modified profile)";
    g.profile = [d = s.drive](double t) { return ToothProfile<double>(d, t).point; };
    // The cutter path: the generating circle's (the grinding wheel's) centre X'(t), radius ρ'.
    g.cutter = [d = s.drive](double t) { return ToothProfile<double>(d, t).centre; };
    g.cutter_diameter_mm = 2.0 * (s.drive.roller_radius_mm + s.drive.delta_radius_mm);
    g.initial_segments = 8 * n1;
    g.symmetry = s.drive.teeth;  // one tooth turned (eqs. 3–4 with z_c = z_d + 1: checked by the fit)
    g.thickness_mm = s.drive.face_width_mm;
    g.bore_diameter_mm = s.bore_diameter_mm;
    for (const auto& c : r.roller_centres) g.rollers.push_back({c, s.drive.roller_radius_mm});
    r.tooth_files = FitPlanarCam(g, s.geometry);
    if (r.tooth_files.files && r.tooth_files.solid) {
      cycloid_common::CycloidPartsInput parts;
      parts.design_name = s.name;
      parts.drive = s.drive;
      parts.discs = s.discs;
      parts.disc_spacing_mm = s.disc_spacing_mm;
      parts.bore_diameter_mm = s.bore_diameter_mm;
      const double stack = (s.discs - 1) * s.disc_spacing_mm + s.drive.face_width_mm;
      parts.output_pin_length_mm = stack;
      if (s.output) {
        parts.pins = s.output->pins;
        parts.output_pin_length_mm = s.output->span_mm;
      }
      parts.density_kg_m3 = s.density_kg_m3;
      parts.material = "steel (E " + Format(s.material.youngs_modulus_MPa, 6) + " MPa)";
      parts.crank_angle_rad = s.geometry.assembly_crank_angle_deg * kPi / 180.0;
      parts.crank_bearing_designation = s.crank_bearing_designation;
      parts.pin_designation = s.pin_designation;
      r.parts = cycloid_common::CycloidParts(parts, r.tooth_files);
    }
  }
  if (s.output) {
    try {
      RunOutputMechanism(s, r);
    } catch (const std::invalid_argument& e) {
      r.output_failed = e.what();
      r.warnings.push_back(std::string("output mechanism not solved: ") + e.what());
    }
  }
  if (s.stiffness) {
    LoadedOptions options = s.options;
    options.keep_pressure = false;
    options.crank_slope = false;
    const LoadedTca tca(s.drive, s.crowning, s.material, options);
    std::optional<OutputPins> pins;
    if (s.output) {
      pins = s.output->pins;
      pins->face_width_mm = s.drive.face_width_mm;
      pins->e_star_MPa = tca.e_star_MPa();
    }
    try {
      const double tr = s.stiffness->rated_torque_Nm;
      r.torsion = TorsionalCurve(tca, pins ? &*pins : nullptr, s.stiffness->crank_angle_deg * kPi / 180.0,
                                 tr * 1000.0, s.discs,
                                 {s.segment_T1_Nm / tr, s.segment_T2_Nm / tr, s.lost_motion_percent / 100.0});
      RunSegments(s, r);
    } catch (const std::invalid_argument& e) {
      r.torsion_failed = e.what();
      r.warnings.push_back(std::string("torsional curve not solved: ") + e.what());
    }
  }
  if (s.life) {
    LoadedOptions options = s.options;
    options.keep_pressure = false;
    options.crank_slope = false;
    const LoadedTca tca(s.drive, s.crowning, s.material, options);
    r.life = cycloid_common::RunLife(*s.life, tca, r.crank_angles_rad, s.disc_torque_Nmm(), &r.cycle.meshes);
  }
  if (s.lubrication) RunLubrication(s, ctx, r);
  RunCatalogue(s, ctx, r);
  if (r.life && s.life->contamination_factor) {
    // The oil at the bearings for their modified life a_ISO: the lubricated operating point's.
    ModifiedLifeOil oil;
    oil.contamination_factor = *s.life->contamination_factor;
    if (r.lubrication) {
      oil.temperature_C = r.lubrication->oil_temperature_C;
      oil.viscosity_mm2_s = r.lubrication->viscosity_cSt;  // the oil's at that temperature (ASTM D341)
    } else {
      oil.missing = r.lubrication_error.empty() ? "the lubricated losses were not computed" : r.lubrication_error;
    }
    r.life->oil = oil;
  }
  if (s.inspection && s.geometry.write) {
    for (int k = 1; k <= s.discs; ++k) {
      const InspectedPart part = DiscPart(s, k);
      long points = 0;
      r.inspection_files.push_back(
          {part.name, InspectionCsv(s.name, part, s.inspection->spacing_mm, s.inspection->tolerance_um, &points)});
      r.inspection_points.push_back({part.name, points});
    }
  }
  if (s.measured) r.measured = MeasuredDisc(s, r);
  if (s.tolerances) {
    // The kinematic transmission error from the tolerances (model/cycloid/transmission_error.h).
    const Study::ToleranceSpec& t = *s.tolerances;
    Progress progress("cycloid_ltca transmission error", ctx.quiet);
    cycloid::TransmissionErrorOptions o;
    o.angle_steps = t.angle_steps;
    o.samples = t.samples;
    o.seed = t.seed;
    o.progress = [&](double f) { progress.Update(f, std::to_string(t.samples) + " Monte-Carlo samples"); };
    try {
      r.transmission_error =
          cycloid::AnalyzeTransmissionError(s.drive, s.output ? &s.output->pins : nullptr, t.bands, o);
    } catch (const std::domain_error& e) {
      throw StudyError(ctx.study_file + ": /tolerances: the toleranced drive has no contact: " + e.what());
    }
    progress.Done();
    const cycloid::TransmissionErrorResult& te = *r.transmission_error;
    if (te.jammed_samples > 0)
      r.warnings.push_back("transmission error: " + std::to_string(te.jammed_samples) + " of " +
                           std::to_string(te.samples) + " Monte-Carlo samples jam at some crank angle (a pin "
                           "interferes with the disc or its hole beyond the play: the rigid model turns the output "
                           "to the first contact; a preloaded, elastic drive turns less)");
    if (te.samples > 0 && te.linear_vs_exact_max_error > 0.1)
      r.warnings.push_back("transmission error: the linear estimate's largest error is " +
                           Format(100 * te.linear_vs_exact_max_error, 3) +
                           "% of the largest Monte-Carlo peak-to-peak (the contact passes to other pins within "
                           "the bands): use the Monte-Carlo numbers");
  }
  FillResult(s, r);
  return r;
}

namespace {

void AddToothDrawing(const Study& s, const Result& r, Outputs& out) {
  Drawing drawing;
  drawing.title = "Cycloid gear (disc frame) and rollers at crank angle 0";
  Drawing::Layer disc{"disc", "black", {}, {}, true, 1.0};
  Polyline pl;
  for (const auto& p : r.tooth_profile) pl.push_back({p.x(), p.y()});
  disc.polylines.push_back(pl);
  Drawing::Layer rollers{"rollers", "blue", {}, {}, true, 1.0};
  for (size_t i = 0; i < r.roller_centres.size(); ++i) {
    const auto& c = r.roller_centres[i];
    rollers.circles.push_back({c.x(), c.y(), s.drive.roller_radius_mm});
    drawing.labels.push_back({c.x(), c.y(), std::to_string(i + 1), "blue"});
  }
  drawing.layers = {disc, rollers};
  // The main dimensions a shop reads (the disc's radii from its sampled profile).
  const cycloid::Drive& dr = s.drive;
  double r_min = INFINITY, r_max = 0;
  for (const auto& [x, y] : pl) r_min = std::min(r_min, std::hypot(x, y)), r_max = std::max(r_max, std::hypot(x, y));
  char line[240];
  std::snprintf(line, sizeof line, "%d teeth, %d rollers; pin circle diameter %g mm; roller diameter %g mm; eccentricity %g mm",
                dr.teeth, dr.rollers, 2 * dr.roller_position_radius_mm, 2 * dr.roller_radius_mm, dr.eccentricity_mm);
  drawing.dimensions.push_back(line);
  std::snprintf(line, sizeof line, "modifications Δa %g mm, Δρ %g mm; face width %g mm; disc radius %.3f to %.3f mm (sampled)",
                dr.delta_position_mm, dr.delta_radius_mm, dr.face_width_mm, r_min, r_max);
  drawing.dimensions.push_back(line);
  out.Add("tooth.svg", SvgDrawing(drawing));
  WritePlanarCamFiles(r.tooth_files, s.geometry, out);
  if (!r.parts.parts.empty()) WriteParts(r.parts, s.geometry, out);
  if (s.grinding) out.Add("grinding_wheel.csv", GrindingCsv(s));
  for (const auto& [name, csv] : r.inspection_files) out.Add("inspection/" + name + ".csv", csv);
}

Table BacklashTable(const Study& s, const Result& r, const std::vector<double>& col_angle) {
  Table backlash;
  backlash.Add("crank_angle_deg", col_angle);
  for (int i = 0; i < s.drive.rollers; ++i)
    backlash.Add("backlash_roller_" + std::to_string(i + 1) + "_arcsec", r.backlash_arcsec[i]);
  return backlash;
}

// per_angle.csv (`table`), backlash.csv and lte.svg, for the unloaded and the loaded evaluation;
// returns the plot options (crank-angle axis) for the loaded evaluation's further plots.
PlotOptions WriteTransmissionErrorFiles(const Study& s, const Result& r, const Table& table,
                                        const std::vector<double>& col_angle, const std::string& title,
                                        const std::vector<Series>& lines, Outputs& out) {
  out.Add("per_angle.csv", ToCsv(table));
  out.Add("backlash.csv", ToCsv(BacklashTable(s, r, col_angle)));
  PlotOptions po;
  po.x_label = "crank angle [deg]";
  po.title = title;
  po.y_label = "transmission error [arcsec]";
  out.Add("lte.svg", SvgLinePlot(lines, po));
  return po;
}

// transmission_error.csv and .svg (with "tolerances"): per crank angle over one output revolution,
// the nominal drive's lag and backlash, the linear σ and the worst Monte-Carlo sample's TE.
void WriteToleranceFiles(const Result& r, Outputs& out) {
  if (!r.transmission_error) return;
  const cycloid::TransmissionErrorResult& te = *r.transmission_error;
  std::vector<double> deg, lag, backlash;
  for (size_t i = 0; i < te.crank_angle_rad.size(); ++i) {
    deg.push_back(te.crank_angle_rad[i] * 180.0 / kPi);
    lag.push_back(te.nominal_lag_rad[i] * kArcsecPerRad);
    backlash.push_back(te.nominal_backlash_rad[i] * kArcsecPerRad);
  }
  Table t;
  t.Add("crank_angle_deg", deg);
  t.Add("nominal_lag_arcsec", lag);
  t.Add("nominal_backlash_arcsec", backlash);
  t.Add("linear_te_sigma_arcsec", te.linear_sigma_arcsec);
  if (!te.worst_sample_te_arcsec.empty()) t.Add("worst_sample_te_arcsec", te.worst_sample_te_arcsec);
  out.Add("transmission_error.csv", ToCsv(t));
  std::vector<Series> lines = {{"linear σ", deg, te.linear_sigma_arcsec}};
  if (!te.worst_sample_te_arcsec.empty()) lines.push_back({"worst Monte-Carlo sample", deg, te.worst_sample_te_arcsec});
  PlotOptions po;
  po.title = "Transmission error from the tolerances (one output revolution)";
  po.x_label = "crank angle [deg]";
  po.y_label = "output angle error [arcsec]";
  out.Add("transmission_error.svg", SvgLinePlot(lines, po));
}

void WriteUnloaded(const Study& s, const Result& r, Outputs& out) {
  out.SetResult(r);
  std::vector<double> col_angle;
  for (double a : s.crank_angles_rad) col_angle.push_back(a * 180.0 / kPi);
  Table table;
  table.Add("crank_angle_deg", col_angle);
  table.Add("unloaded_te_arcsec", r.unloaded_te_arcsec);
  WriteTransmissionErrorFiles(s, r, table, col_angle, "Unloaded transmission error",
                              {{"unloaded", col_angle, r.unloaded_te_arcsec}}, out);
  AddToothDrawing(s, r, out);
  WriteToleranceFiles(r, out);
}

}  // namespace

namespace {

// The tooth's and the pins' closed-form geometric limits (model/cycloid/geometry_limits.h, eqs.
// C3/C4 and the pin pitch): exact, no grid; the verdict's defaults (no undercut, no overlap). Then
// the blocks both stages write: geometry files, parts, grinding, the transmission error from the
// tolerances, inspection and the measured disc.
void FillCommon(const Study& s, Result& r) {
  r.min_profile_radius_mm = Finite(cycloid::MinConvexProfileRadius(s.drive), "profile radius");
  r.pin_gap_mm = Finite(cycloid::PinGapMargin(s.drive), "pin gap");
  r.geometry_files = GeometryFilesOf(s.geometry, {{"tooth", &r.tooth_files}});
  if (!r.parts.parts.empty()) r.parts_json = PartsOf(r.parts, s.geometry);
  if (s.grinding) {
    const cycloid::FormWheel& w = *s.grinding;
    Result::GrindingOut g;
    for (int k = 0; k < s.drive.teeth; ++k) g.index_angles_deg.push_back(360.0 * k / s.drive.teeth);
    g.file = "grinding_wheel.csv";
    g.wheel_radius_mm = w.wheel_radius_mm;
    g.centre_distance_mm = w.centre_distance_mm;
    g.wheel_width_mm = w.width_mm;
    g.edge_radius_mm = w.edge_radius_mm;
    g.least_radius_mm = w.least_radius_mm;
    g.root_x_mm = w.root_x_mm;
    g.tip_x_mm = w.tip_x_mm;
    g.index_deg = w.index_rad * 180.0 / kPi;
    g.least_concave_radius_mm = w.least_concave_radius_mm;
    g.residual_form_error_um = w.residual_form_error_mm * 1e3;
    g.tolerance_um = s.grinding_tolerance_um;
    g.points = int(w.y_mm.size());
    g.note = "one tooth space per pass, traversed along the disc's axis at the centre distance, then indexed; "
             "disc k of N is indexed from its phase -360 (k - 1)/(N teeth) deg (docs/parts.md)";
    r.grinding = g;
  }
  // "transmission_error" (with "tolerances"): the shared statistics (studies/tolerance_input.h) and
  // the cycloid's own keys.
  if (r.transmission_error) {
    const cycloid::TransmissionErrorResult& te = *r.transmission_error;
    Result::TransmissionErrorBlock& j = r.transmission_error_json.emplace();
    j.SetStatistics(te, s.tolerances->seed);
    j.model = "kinematic (unloaded, rigid): the first ring pin to touch the disc on the loaded flank and the first "
              "output pin to touch its hole set the output angle; TE = output angle minus the nominal drive's at "
              "the same crank angle";
    j.output_mechanism = s.output ? "pins in holes with clearance (first contact)"
                                  : "rigid (no pin and hole radii given: no play, no output tolerances)";
    j.distribution = "each deviation uniform in its ± band (a diameter's band is half on the radius); position "
                     "bands apply to the radial and the tangential component each; linear: exact derivatives "
                     "(ceres::Jet) of the pair and pin in contact";
    j.angle_steps = int(te.crank_angle_rad.size());
    j.crank_span_deg = 360.0 * s.drive.teeth;
    j.parameters = te.parameters;
    j.jammed_samples = te.jammed_samples;
    j.backlash_arcmin = te.backlash_arcmin;
    j.backlash_p99_arcmin = te.backlash_p99_arcmin;
    j.backlash_nominal_arcmin = te.backlash_nominal_arcmin;
    j.peak_to_peak = "linear_worst_case_arcsec, monte_carlo_max_arcsec and monte_carlo_p99_arcsec are peak-to-peak "
                     "over one output revolution; backlash: output angle forward minus reverse (both flanks, "
                     "rigid), the largest over the revolution";
  }
  if (s.inspection) {
    r.inspection = InspectionOf(s.inspection->spacing_mm, s.inspection->tolerance_um, r.inspection_points,
                                s.geometry.write, "each disc's centre (its bore); each file's header states its frame");
  }
  r.measured_json = r.measured;
}

// result.json's catalogue numbers (docs/ratings.md): rated_torque_Nm, peak_torque_Nm,
// momentary_torque_Nm and "ratings"; "output_bearing"; "stiffness_segments"; "masses"; and
// "joint_model", the parameters `camopt export` turns into a simulator's joint.
void FillCatalogue(const Study& s, Result& r) {
  if (s.ratings) {
    r.ratings_keys.Set(s.ratings->in, r.ratings, r.ratings_failed,
                       double(s.drive.teeth) / double(s.drive.rollers - s.drive.teeth), s.estimate_error);
  }
  if (r.output_bearing) r.output_bearing_json = OutputBearingBlock::Of(*s.output_bearing, *r.output_bearing);
  else if (s.output_bearing) r.output_bearing_json = StageError{r.output_bearing_failed};
  const double arcmin = kArcminPerRad;
  if (r.segments) {
    const ThreeSegmentStiffness& g = *r.segments;
    Result::StiffnessSegmentsOut o;
    o.T1_Nm = s.segment_T1_Nm;
    o.T2_Nm = s.segment_T2_Nm;
    o.rated_torque_Nm = s.stiffness->rated_torque_Nm;
    o.K1_Nm_per_arcmin = Finite(g.k1_Nm_per_arcmin, "K1");
    o.K2_Nm_per_arcmin = Finite(g.k2_Nm_per_arcmin, "K2");
    o.K3_Nm_per_arcmin = Finite(g.k3_Nm_per_arcmin, "K3");
    o.definitions = "loading branch from 0+ (after the backlash): K1 = T1 / (angle(T1) - angle(0+)), K2 = (T2 - "
                    "T1) / (angle(T2) - angle(T1)), K3 = (T_r - T2) / (angle(T_r) - angle(T2))";
    r.stiffness_segments = o;
    // r.segments comes with r.torsion (RunSegments), so "stiffness" is there.
    if (r.stiffness) {
      r.stiffness->lost_motion_percent = s.lost_motion_percent;
      r.stiffness->lost_motion_at_percent_arcmin = Finite(r.lost_motion_user_rad * arcmin, "lost motion");
    }
  }
  if (s.stiffness || s.ratings) {
    const cycloid_common::PartMasses& m = r.masses;
    r.masses_out = Result::MassesOut{s.density_kg_m3, m.disc_kg, m.disc_inertia_kgm2, m.ring_pins_kg,
                                     m.output_pins_kg, m.total_kg, m.outer_diameter_mm, m.width_mm,
                                     m.reflected_inertia_kgm2, m.includes};
  }
  if (r.torsion && r.segments) {
    const cycloid::TorsionCurve& c = *r.torsion;
    const ThreeSegmentStiffness& g = *r.segments;
    JointModelBlock& joint = r.joint_model.emplace();
    for (const cycloid::TorsionPoint& p : c.points) joint.torsion_curve.push_back({p.torque_Nmm / 1000.0, p.output_angle_rad});
    if (r.lubrication) {
      // The lubricated operating point: its efficiency and the no-load running torque (at the input,
      // reflected to the output through the ratio for the joint's friction).
      const LubricationResult& l = *r.lubrication;
      joint.efficiency = l.efficiency;
      joint.friction_torque_Nm =
          l.no_load_running_torque_Nm * double(s.drive.teeth) / double(s.drive.rollers - s.drive.teeth);
      joint.loss_table.push_back(
          {l.input_speed_rpm * 2.0 * kPi / 60.0, l.efficiency, l.efficiency, l.no_load_running_torque_Nm});
    }
    joint.ratio = double(s.drive.teeth) / double(s.drive.rollers - s.drive.teeth);
    joint.rated_torque_Nm = s.stiffness->rated_torque_Nm;
    joint.stiffness_Nm_per_rad = Finite(c.stiffness_Nmm_per_rad / 1000.0, "stiffness");
    joint.stiffness_segments = {s.segment_T1_Nm, s.segment_T2_Nm, g.k1_Nm_per_arcmin * kArcminPerRad,
                                g.k2_Nm_per_arcmin * kArcminPerRad, g.k3_Nm_per_arcmin * kArcminPerRad};
    joint.backlash_rad = c.backlash_rad;
    joint.lost_motion_rad = c.lost_motion_rad;
    joint.reflected_inertia_kgm2 = r.masses.reflected_inertia_kgm2;
    joint.inertia_includes = r.masses.includes;
    joint.damping_note = "not modelled: the contact model is quasi-static and frictionless (no hysteresis width)";
    joint.friction_note = r.lubrication ? "the lubricated no-load running torque at the load's speed and oil "
                                          "temperature, reflected to the output; loss_table's backward efficiency "
                                          "repeats the forward one (the model computes the input-driving direction)"
                                        : "not modelled without a lubricant (frictionless)";
    joint.SetTilt(s.output_bearing);
  }
}

// The loaded stage's per-angle table and headlines.
void FillLoaded(const Study& s, Result& r) {
  const CycleResult& cycle = r.cycle;
  const std::vector<double>& angles = r.crank_angles_rad;
  r.per_angle.clear();
  for (size_t k = 0; k < cycle.meshes.size(); ++k) {
    const MeshLoad& m = cycle.meshes[k];
    std::vector<Result::PairLoadOut> loads;
    for (const PairLoad& p : m.pairs)
      loads.push_back({p.roller + 1, Finite(p.load_N, "load"), Finite(p.max_pressure_MPa, "pressure"),
                       Finite(p.approach_mm * 1e3, "approach"), p.arm_mm});
    Result::PerAngle a;
    a.crank_angle_deg = angles[k] * 180.0 / kPi;
    a.max_contact_stress_MPa = Finite(m.max_pressure_MPa, "max stress");
    a.pairs_in_contact = m.pairs_in_contact;
    a.lte_arcsec = Finite(cycle.lte_arcsec[k], "lte");
    a.unloaded_te_arcsec = Finite(m.unloaded_rotation_rad * kArcsecPerRad, "ute");
    a.gear_ratio = Finite(cycle.gear_ratio.at(k), "gear ratio");
    a.converged = m.converged;
    a.loads = std::move(loads);
    r.per_angle.push_back(std::move(a));
  }
  std::map<std::string, double> errors, by_grid, by_crank;
  for (const auto& [k, v] : r.estimated_error) errors[k] = Finite(v, "error");
  for (const auto& [k, v] : r.error_grid) by_grid[k] = Finite(v, "error");
  for (const auto& [k, v] : r.error_crank) by_crank[k] = Finite(v, "error");
  Result::ErrorSources sources;
  if (s.estimate_error) {
    sources.grid = Result::GridErrorSource{r.coarse_grid, int(s.crank_angles_rad.size()), by_grid};
    if (r.crank_error_angles > 0)
      sources.crank_angles = Result::CrankErrorSource{r.crank_error_angles, int(r.crank_angles_rad.size()),
                                                      "half-step-shifted set; error |N - 2N| of the 2N value", by_crank};
    sources.warning_share = kErrorShare;
  }
  r.torque_Nm = s.torque_Nm;
  r.max_contact_stress_MPa = Finite(cycle.max_pressure_MPa, "max stress");
  r.max_contact_stress_crank_angle_deg = angles[cycle.max_pressure_index] * 180.0 / kPi;
  r.lte_peak_to_peak_arcsec = Finite(cycle.lte_peak_to_peak_arcsec, "lte p2p");
  r.lte_mean_abs_arcsec = Finite(cycle.lte_mean_abs_arcsec, "lte mean");
  r.gear_ratio_nominal = double(s.drive.teeth);
  r.gear_ratio_peak_to_peak = Finite(cycle.gear_ratio_peak_to_peak, "gr p2p");
  r.max_pairs_in_contact = cycle.max_pairs_in_contact;
  r.max_pair_load_N = Finite(cycle.max_pair_load_N, "max pair load");
  r.crank_angles_per_mesh_period = s.crank_angles_per_mesh_period;
  r.crank_angles_used = int(angles.size());
  r.crank_angles_refined = r.crank_angles_rad.size() > s.crank_angles_rad.size();
  r.axial_cell_mm = s.drive.face_width_mm / s.options.axial_cells;
  r.grid = std::array<int, 2>{s.options.profile_cells, s.options.axial_cells};
  r.composite_modulus_out = r.composite_modulus_MPa;
  r.contact_solves = cycle.contact_solves;
  r.converged = cycle.converged;
  r.warning_out = r.warning;
  r.error_values = errors;
  r.estimated_error_sources = sources;
  r.warnings_out = r.warnings;
  FillCommon(s, r);
  if (r.life) r.life_json = cycloid_common::LifeBlockOf(*s.life, *r.life);
  if (s.discs > 1) {
    r.discs = s.discs;
    r.disc_torque_Nm = s.disc_torque_Nmm() / 1000.0;
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();  // null in result.json
  if (s.stiffness && !r.torsion) r.torsional_stiffness_Nm_per_arcmin = r.lost_motion_arcmin = r.backlash_arcmin = nan;
  if (s.output && !r.output_failed.empty()) {
    r.max_ring_pin_force_N = r.max_output_pin_force_out = r.eccentric_bearing_load_N =
        r.output_pin_bending_stress_MPa = r.output_pin_contact_pressure_MPa = nan;
    r.output_mechanism = Result::OutputMechanismOut{};
    r.output_mechanism->error = r.output_failed;
  }
  if (r.torsion) {
    const cycloid::TorsionCurve& c = *r.torsion;
    const double arcmin = 60.0 * 180.0 / kPi;
    r.torsional_stiffness_Nm_per_arcmin = Finite(c.stiffness_Nmm_per_rad / 1000.0 / arcmin, "stiffness");
    r.lost_motion_arcmin = Finite(c.lost_motion_rad * arcmin, "lost motion");
    r.backlash_arcmin = Finite(c.backlash_rad * arcmin, "backlash");
    Result::StiffnessOut o;
    o.rated_torque_Nm = s.stiffness->rated_torque_Nm;
    o.crank_angle_deg = s.stiffness->crank_angle_deg;
    o.stiffness_positive_Nm_per_arcmin = c.stiffness_positive_Nmm_per_rad / 1000.0 / arcmin;
    o.stiffness_negative_Nm_per_arcmin = c.stiffness_negative_Nmm_per_rad / 1000.0 / arcmin;
    o.ring_pins_share = c.ring_share;
    o.output_pins_share = c.output_pins_share;
    o.output_pins = s.output ? "compliant (output_mechanism)" : "rigid (no pin and hole radii given)";
    o.contact_solves = c.contact_solves;
    o.hysteresis_width_arcmin = 0.0;
    o.definitions =
        "input held at crank_angle_deg; output angle = disc against ring (LTCA: beta0 + deflection) + output "
        "against disc (output pins); stiffness: mean of the two directions' slopes between 50% and 100% of the "
        "rated torque; lost motion: angle(+3%) - angle(-3%); backlash: angle(0+) - angle(0-); frictionless: "
        "loading and unloading coincide (hysteresis width 0)";
    r.stiffness = o;
  }
  if (s.output && r.output_failed.empty()) {
    const OutputSpec& o = *s.output;
    r.max_ring_pin_force_N = Finite(cycle.max_pair_load_N, "max ring-pin force");
    r.max_output_pin_force_out = Finite(r.max_output_pin_force_N, "max output-pin force");
    r.eccentric_bearing_load_N = Finite(r.max_bearing_load_N, "eccentric bearing load");
    r.output_pin_bending_stress_MPa = Finite(r.max_bending_stress_MPa, "pin bending stress");
    r.output_pin_contact_pressure_MPa = Finite(r.max_contact_pressure_MPa, "pin contact pressure");
    const double rc = o.pins.contact_radius_mm();
    Result::OutputMechanismOut om;
    om.pins = o.pins.pins;
    om.pin_circle_radius_mm = o.pins.pin_circle_radius_mm;
    om.pin_radius_mm = o.pins.pin_radius_mm;
    om.hole_radius_mm = o.pins.hole_radius_mm;
    om.contact_radius_mm = rc;
    om.clearance_mm = o.pins.hole_radius_mm - rc - s.drive.eccentricity_mm;
    om.pin_support = o.support == cycloid::PinSupport::kCantilever ? "cantilever" : "both_ends";
    om.pin_span_mm = o.span_mm;
    om.disc_planes_mm =
        cycloid::DiscPlanesOnPin(o.support, o.span_mm, s.discs, s.drive.face_width_mm, s.disc_spacing_mm);
    om.disc_spacing_mm = s.disc_spacing_mm;
    om.discs = s.discs;
    om.disc_torque_Nm = s.disc_torque_Nmm() / 1000.0;
    om.load_period_crank_deg = r.output_angles_rad.size() * (r.output_angles_rad.size() > 1
                                   ? (r.output_angles_rad[1] - r.output_angles_rad[0]) * 180.0 / kPi : 0.0);
    om.samples = int(r.output_angles_rad.size());
    om.max_net_crank_force_N = r.max_net_crank_force_N;
    om.max_crank_couple_Nmm = r.max_couple_Nmm;
    om.max_moment_residual_relative = r.max_moment_residual;
    om.model =
        "pins in the disc's holes with clearance (hole - contact radius - e) and Palmgren line-contact compliance, "
        "exact geometry, solved for the disc's rotation against the output (sum of the pins' moments = disc torque); "
        "eccentric bearing load from the disc's force balance (ring-pin forces along the LTCA's contact normals + "
        "output-pin forces); pin bending 32 M / (pi d^3) as a beam (Roark, Table 8.1); hole-pin pressure: internal "
        "Hertz line contact, 1/R' = 1/r_contact - 1/r_hole";
    om.disc_split =
        "each disc carries the output torque / discs (identical discs, equal split assumed); disc k runs at crank "
        "angle phi + 360 k / discs deg";
    if (o.pins.roller_radius_mm > 0) om.roller_radius_mm = o.pins.roller_radius_mm;
    r.output_mechanism = om;
  }
  FillCatalogue(s, r);
  r.lubrication_json = StageBlock(r.lubrication, bool(s.lubrication), r.lubrication_error);
  // With a lubricant the drive has an efficiency: the life block points to it instead of calling
  // the model frictionless.
  if (r.life && s.lubrication)
    r.life_json->efficiency = "lubrication.efficiency (the lubricated losses, docs/lubrication.md)";
  if (r.torsional && s.torsional) r.torsional_dynamics = TorsionalDynamicsBlock::Of(*s.torsional, *r.torsional);
  else if (s.torsional) r.torsional_dynamics = StageError{r.torsional_failed};
}

// The unloaded TCA only (analysis.evaluate ["unloaded"]).
void FillUnloaded(const Study& s, Result& r) {
  r.per_angle.clear();
  double lo = 0, hi = 0;
  for (size_t k = 0; k < r.unloaded_te_arcsec.size(); ++k) {
    const double te = Finite(r.unloaded_te_arcsec[k], "ute");
    lo = k == 0 ? te : std::min(lo, te);
    hi = k == 0 ? te : std::max(hi, te);
    Result::PerAngle a;
    a.crank_angle_deg = s.crank_angles_rad[k] * 180.0 / kPi;
    a.unloaded_te_arcsec = te;
    r.per_angle.push_back(std::move(a));
  }
  r.evaluated = std::vector<std::string>{"unloaded"};
  r.unloaded_te_peak_to_peak_arcsec = hi - lo;
  r.crank_angles_per_mesh_period = s.crank_angles_per_mesh_period;
  FillCommon(s, r);
}

}  // namespace

void FillResult(const Study& s, Result& r) {
  r.name = s.name;
  if (s.loaded) FillLoaded(s, r);
  else FillUnloaded(s, r);
}

namespace {

// output_mechanism.csv (over the crank bearing's load period: every disc's bearing load, its
// direction from the disc's eccentricity, the disc's rotation against the output, its output
// pins' forces; the crankshaft's net force and couple; the pins' bending stress) and
// eccentric_bearing_load.svg.
void WriteOutputMechanism(const Study& s, const Result& r, Outputs& out) {
  Table t;
  std::vector<double> angle;
  for (double a : r.output_angles_rad) angle.push_back(a * 180.0 / kPi);
  t.Add("crank_angle_deg", angle);
  std::vector<Series> lines;
  for (int k = 0; k < s.discs; ++k) {
    const std::string tag = s.discs > 1 ? "_disc_" + std::to_string(k + 1) : "";
    std::vector<double> load, dir, rot, qmax, count;
    for (const auto& row : r.output) {
      const Result::DiscSample& d = row[size_t(k)];
      load.push_back(d.bearing_crank_frame.norm());
      dir.push_back(std::atan2(d.bearing_crank_frame.y(), d.bearing_crank_frame.x()) * 180.0 / kPi);
      rot.push_back(d.pins.rotation_rad * kArcsecPerRad);
      qmax.push_back(*std::max_element(d.pins.force_N.begin(), d.pins.force_N.end()));
      count.push_back(d.pins.pins_in_contact);
    }
    t.Add("eccentric_bearing_load" + tag + "_N", load);
    t.Add("eccentric_bearing_direction" + tag + "_deg", dir);
    t.Add("output_pin_rotation" + tag + "_arcsec", rot);
    t.Add("max_output_pin_force" + tag + "_N", qmax);
    t.Add("output_pins_in_contact" + tag, count);
    lines.push_back({s.discs > 1 ? "disc " + std::to_string(k + 1) : "eccentric bearing", angle, load});
  }
  if (s.discs > 1) {
    t.Add("net_crank_force_N", r.net_crank_force_N);
    t.Add("crank_couple_Nmm", r.crank_couple_Nmm);
  }
  t.Add("output_pin_bending_stress_MPa", r.pin_bending_stress_MPa);
  for (int j = 0; j < s.output->pins.pins; ++j) {
    std::vector<double> q;
    for (const auto& row : r.output) q.push_back(row[0].pins.force_N[size_t(j)]);
    t.Add("output_pin_" + std::to_string(j + 1) + (s.discs > 1 ? "_disc_1" : "") + "_force_N", q);
  }
  out.Add("output_mechanism.csv", ToCsv(t));
  PlotOptions po;
  po.x_label = "crank angle [deg]";
  po.y_label = "eccentric bearing load [N]";
  po.title = "Eccentric (crank) bearing load over its load period";
  out.Add("eccentric_bearing_load.svg", SvgLinePlot(lines, po));
}

// hysteresis.csv (the output angle against the output torque, −T_r → T_r loading and back
// unloading, the same curve in this frictionless model, with each element's part) and
// hysteresis.svg.
void WriteTorsion(const Result& r, Outputs& out) {
  const double arcmin = 60.0 * 180.0 / kPi;
  std::vector<double> branch, torque, angle, ring, pins;
  const auto& p = r.torsion->points;
  auto add = [&](int b, const cycloid::TorsionPoint& x) {
    branch.push_back(b);
    torque.push_back(x.torque_Nmm / 1000.0);
    angle.push_back(x.output_angle_rad * arcmin);
    ring.push_back(x.ring_rad * arcmin);
    pins.push_back(x.output_pins_rad * arcmin);
  };
  for (const auto& x : p) add(0, x);
  for (auto it = p.rbegin(); it != p.rend(); ++it) add(1, *it);
  Table t;
  t.Add("branch_loading_0_unloading_1", branch);
  t.Add("output_torque_Nm", torque);
  t.Add("output_angle_arcmin", angle);
  t.Add("ring_pins_arcmin", ring);
  t.Add("output_pins_arcmin", pins);
  out.Add("hysteresis.csv", ToCsv(t));
  PlotOptions po;
  po.x_label = "output torque [N m]";
  po.y_label = "output angle [arcmin]";
  po.title = "Output angle against output torque, input held (frictionless: no hysteresis width)";
  std::vector<double> x(torque.begin(), torque.begin() + long(p.size())), y(angle.begin(), angle.begin() + long(p.size()));
  out.Add("hysteresis.svg", SvgLinePlot({{"output angle", x, y}}, po));
}

}  // namespace

void Write(const Study& s, const Result& r, Outputs& out) {
  if (!s.loaded) return WriteUnloaded(s, r, out);
  const CycleResult& cycle = r.cycle;
  const int n1 = s.drive.rollers;
  const size_t n = r.crank_angles_rad.size();
  out.SetResult(r);
  if (!r.efficiency_map.empty()) WriteEfficiencyMap(r.efficiency_map, s.lubrication->common.map->torque_Nm, out);

  Table table;
  std::vector<double> col_angle, col_lte, col_ute, col_gr, col_p, col_pairs;
  std::vector<std::vector<double>> col_load(n1, std::vector<double>(n, 0.0)), col_pmax = col_load;
  for (size_t k = 0; k < cycle.meshes.size(); ++k) {
    const MeshLoad& m = cycle.meshes[k];
    for (const PairLoad& p : m.pairs) {
      col_load[p.roller][k] = p.load_N;
      col_pmax[p.roller][k] = p.max_pressure_MPa;  // the peak of the pair's half-space pressure field
    }
    col_angle.push_back(r.crank_angles_rad[k] * 180.0 / kPi);
    col_lte.push_back(cycle.lte_arcsec[k]);
    col_ute.push_back(m.unloaded_rotation_rad * kArcsecPerRad);
    col_gr.push_back(cycle.gear_ratio.at(k));
    col_p.push_back(m.max_pressure_MPa);
    col_pairs.push_back(m.pairs_in_contact);
  }
  table.Add("crank_angle_deg", col_angle);
  table.Add("lte_arcsec", col_lte);
  table.Add("unloaded_te_arcsec", col_ute);
  table.Add("gear_ratio", col_gr);
  table.Add("max_contact_stress_MPa", col_p);
  table.Add("pairs_in_contact", col_pairs);
  for (int i = 0; i < n1; ++i) table.Add("load_roller_" + std::to_string(i + 1) + "_N", col_load[i]);
  if (s.output && r.output_failed.empty()) table.Add("eccentric_bearing_load_N", r.bearing_load_at_ltca_angles_N);
  // Each pair's own peak pressure (0 off contact), after every other column: the row's largest is
  // max_contact_stress_MPa.
  for (int i = 0; i < n1; ++i) table.Add("max_pressure_roller_" + std::to_string(i + 1) + "_MPa", col_pmax[i]);
  PlotOptions po = WriteTransmissionErrorFiles(s, r, table, col_angle, "Loaded transmission error",
                                               {{"loaded", col_angle, col_lte}, {"unloaded", col_angle, col_ute}}, out);
  po.title = "Instantaneous gear ratio";
  po.y_label = "gear ratio [-]";
  po.guides = {{"nominal ratio", double(s.drive.teeth)}};
  out.Add("gear_ratio.svg", SvgLinePlot({{"instantaneous gear ratio", col_angle, col_gr}}, po));
  po.guides.clear();
  po.title = "Maximum contact stress";
  po.y_label = "contact stress [MPa]";
  if (s.contact_stress_limit_MPa) po.guides = {{"contact stress limit", *s.contact_stress_limit_MPa}};
  out.Add("contact_stress.svg", SvgLinePlot({{"largest over the rollers", col_angle, col_p}}, po));
  const MeshLoad& worst = cycle.meshes[cycle.max_pressure_index];
  out.Add("pressure_map.svg",
          cycloid_common::PressureMapsSvg(
              worst, "Contact pressure at crank angle " + Format(worst.crank_angle_rad * 180 / kPi, 4) + " deg"));
  // The pressure field of the worst pair as a long table (x across, y along the face).
  Table pmap;
  std::vector<double> cr, cx, cy, cp;
  for (const PairLoad& p : worst.pairs)
    for (int iy = 0; iy < p.grid.ny; ++iy)
      for (int ix = 0; ix < p.grid.nx; ++ix) {
        cr.push_back(p.roller + 1);
        cx.push_back(p.grid.x0 + (ix + 0.5) * p.grid.dx);
        cy.push_back(p.grid.y0 + (iy + 0.5) * p.grid.dy);
        cp.push_back(p.pressure_MPa[size_t(iy) * p.grid.nx + ix]);
      }
  pmap.Add("roller", cr);
  pmap.Add("x_mm", cx);
  pmap.Add("y_mm", cy);
  pmap.Add("pressure_MPa", cp);
  out.Add("pressure_max.csv", ToCsv(pmap));

  if (s.output && r.output_failed.empty()) WriteOutputMechanism(s, r, out);
  // The output mechanism was asked for: without its outputs the answer is not what was asked.
  if (s.output && !r.output_failed.empty())
    out.SetStatus(Status::kNotConverged, "output mechanism not solved (its outputs are null in result.json): " +
                                             r.output_failed);
  if (r.torsion) WriteTorsion(r, out);
  if (r.torsional) WriteTorsionalDynamics(*r.torsional, out);
  if (s.torsional && !r.torsional)
    out.SetStatus(Status::kNotConverged, "torsional dynamics not solved: " + r.torsional_failed);
  if (s.ratings && !r.ratings)
    out.SetStatus(Status::kNotConverged, "ratings not solved (null in result.json): " + r.ratings_failed);
  AddToothDrawing(s, r, out);
  WriteToleranceFiles(r, out);
}

namespace {

// The declared input of a study, for the knobs and the estimate below, which run before Parse.
Input ReadInput(const nlohmann::json& study, const std::string& file) { return Read<Input>(Node(&study, file, "")); }

// Fidelity for `camopt run --convergence` (studies/convergence.h): crank-angle sampling (the one
// the file uses; explicit angles have none), contact grid and compatibility tolerance. The
// variants run as the study does (with analysis.estimate_error on, the reported headlines are those
// of the refined, doubled crank-angle set, so a variant without it would not compare like with like).
Fidelity Knobs(const nlohmann::json& study) {
  const Input in = ReadInput(study, "");
  const Input::Analysis a = in.analysis.value_or(Input::Analysis{});
  Fidelity f;
  if (a.crank_angle_steps)
    f.knobs.push_back({"crank_angle_steps", {"/analysis/crank_angle_steps"}, 0, 2, true, 0,
                       "uniform crank angles over crank_span_deg"});
  else if (!a.crank_angles_deg)
    f.knobs.push_back({"crank_angles_per_mesh_period", {"/analysis/crank_angles_per_mesh_period"},
                       kDefaultCrankAnglesPerMeshPeriod, 2, true, 0, "uniform crank angles per mesh period"});
  const cycloid::LoadedOptions defaults;
  f.knobs.push_back({"grid", {"/analysis/grid"}, {defaults.profile_cells, defaults.axial_cells}, 2, true, 0,
                     "contact cells across the profile and along the face"});
  f.knobs.push_back({"tolerance", {"/analysis/tolerance"}, defaults.tolerance, 0.1, false, 0,
                     "relative compatibility residual of the contact solver"});
  f.headlines = {"/max_contact_stress_MPa", "/lte_peak_to_peak_arcsec", "/lte_mean_abs_arcsec",
                 "/gear_ratio_peak_to_peak", "/max_pair_load_N"};
  if (in.tolerances) {  // the transmission error's own crank angles (over one output revolution)
    f.knobs.push_back({"monte_carlo_angle_steps", {"/monte_carlo/angle_steps"}, 8 * in.drive.rollers * in.drive.teeth, 2,
                       true, 0, "crank angles of the transmission error (peak-to-peak and backlash maxima are sampled)"});
    for (const char* h : {"/transmission_error/linear_worst_case_arcsec", "/transmission_error/monte_carlo_max_arcsec",
                          "/transmission_error/backlash_arcmin"})
      f.headlines.push_back(h);
  }
  return f;
}

// The work limit (studies/work_limits.h): runs (2.25 with the error estimate: the shifted angles
// once more and a grid of a quarter of the cells) × crank angles (a list, crank_angle_steps or
// crank_angles_per_mesh_period) × rollers × contact cells ≤ 5e7.
WorkEstimate EstimateWork(const nlohmann::json& study, const std::string& file, double factor) {
  const Input in = ReadInput(study, file);
  const Input::Analysis a = in.analysis.value_or(Input::Analysis{});
  const double rollers = in.drive.rollers;
  const std::array<int, 2> grid = a.grid.value_or(cycloid_common::DefaultGrid());
  const double cells = double(grid[0]) * grid[1];
  // Every way of giving the angles counts: a list, uniform steps, or samples per mesh period (60
  // when absent: the estimate's reference, above the default 32).
  const double angles = a.crank_angles_deg ? double(a.crank_angles_deg->size())
                        : a.crank_angle_steps ? double(*a.crank_angle_steps)
                                              : double(a.crank_angles_per_mesh_period.value_or(60));
  // The path named is the factor furthest above its reference (60 angles, 40×40 cells).
  const std::string angles_path = a.crank_angles_deg                ? "/analysis/crank_angles_deg"
                                  : a.crank_angle_steps             ? "/analysis/crank_angle_steps"
                                  : !a.crank_angles_per_mesh_period ? "/analysis"
                                                                    : "/analysis/crank_angles_per_mesh_period";
  const std::string path = a.grid && cells / 1600.0 >= angles / 60.0 ? "/analysis/grid" : angles_path;
  const double runs = a.estimate_error ? 2.25 : 1.0;
  std::vector<WorkTerm> terms = {{runs * angles * rollers * cells, path,
                                  WorkNumber(runs) + " runs × " + WorkNumber(angles) + " crank angles × " +
                                      WorkNumber(rollers) + " rollers × " + WorkNumber(cells) + " grid cells"}};
  if (in.torsional_dynamics) {
    // The mesh-stiffness table: one LTCA solve and its torque derivative per angle and disc (about
    // two solves), as the cycle's angles.
    const double n = in.torsional_dynamics->angles_per_mesh_period;
    terms.push_back({2.0 * n * in.discs * rollers * cells, "/torsional_dynamics/angles_per_mesh_period",
                     WorkNumber(n) + " crank angles × " + WorkNumber(in.discs) + " discs × 2 solves × " +
                         WorkNumber(rollers) + " rollers × " + WorkNumber(cells) + " grid cells"});
  }
  if (in.tolerances) {
    // The transmission error from tolerances: per sample (and the nominal and linear passes) and
    // crank angle, both flanks' contact solves of the ring pins and output pins, each about one
    // contact cell solve's time.
    const Input::MonteCarlo mc = in.monte_carlo.value_or(Input::MonteCarlo{});
    const double samples = mc.samples.value_or(0);
    const double steps = mc.angle_steps ? double(*mc.angle_steps) : 8.0 * rollers * std::max(1, in.drive.teeth);
    const double pins = in.output_mechanism ? double(in.output_mechanism->pins.value_or(0)) : 0.0;
    terms.push_back({(samples + 3.0) * steps * 2.0 * (rollers + pins), "/monte_carlo/samples",
                     WorkNumber(samples) + " Monte-Carlo samples × " + WorkNumber(steps) + " crank angles × 2 flanks × " +
                         WorkNumber(rollers + pins) + " pins"});
  }
  return LargestTerm(terms, 5e7 * factor, "contact cell solves", 24);
}

// datasheet.html (studies/datasheet.h): with "stiffness" or "ratings".
DatasheetSpec CycloidDatasheet() {
  const std::vector<DatasheetSection> ratings = RatingsDatasheetSections();  // ratings, output bearing
  DatasheetSpec d{"/masses",
     {{"Reducer", {{"reduction ratio", "/gear_ratio_nominal", ""}}},
      ratings[0],
      StiffnessDatasheetSection(),
      {"Accuracy",
       {{"loaded transmission error, peak to peak", "/lte_peak_to_peak_arcsec", "arcsec"},
        {"angular transmission accuracy from the tolerances (linear worst case)",
         "/transmission_error/linear_worst_case_arcsec", "arcsec"}}},
      {"Efficiency",
       {{"efficiency at the load's torque and speed", "/lubrication/efficiency", "", 1.0,
         "/joint_model/friction_note"},
        {"no-load running torque (input)", "/lubrication/no_load_running_torque_Nm", "N·m"}}},
      ratings[1],
      {"Dimensions and mass",
       {{"outer diameter (over the ring pins)", "/masses/outer_diameter_mm", "mm"},
        {"width (discs' stack)", "/masses/width_mm", "mm"},
        {"mass of one disc", "/masses/disc_kg", "kg"},
        {"mass of the parts modelled", "/masses/total_kg", "kg"},
        {"inertia at the output (reflected)", "/masses/reflected_inertia_kgm2", "kg·m²"},
        {"what the masses include", "/masses/includes", ""}}}},
     {"hysteresis.svg", "lte.svg"}};
  return d;
}

CAMOPT_REGISTER_KIND(Kind<Input, Result, Study>{
    .name = "cycloid_ltca",
    .title = "camopt study: loaded tooth contact analysis of a cycloid drive: pin loads, contact pressure and transmission error",
    .run = Run, .parse = Parse, .write = Write, .knobs = Knobs, .estimate = EstimateWork,
    .report = WithLubricationHeadlines(JoinHeadlines({{
        {"largest contact stress", "/max_contact_stress_MPa", "MPa", "study:/limits/contact_stress_MPa", NAN, true,
         "/estimated_error/max_contact_stress_MPa"},
        {"at crank angle", "/max_contact_stress_crank_angle_deg", "deg"},
        {"largest roller load", "/max_pair_load_N", "N", "study:/limits/roller_load_N", NAN, true, "/estimated_error/max_pair_load_N"},
        {"mean |loaded transmission error|", "/lte_mean_abs_arcsec", "arcsec", "", NAN, true,
         "/estimated_error/lte_mean_abs_arcsec"},
        {"loaded transmission error, peak to peak", "/lte_peak_to_peak_arcsec", "arcsec", "", NAN, true,
         "/estimated_error/lte_peak_to_peak_arcsec"},
        {"gear ratio, peak to peak", "/gear_ratio_peak_to_peak", "", "", NAN, true, "/estimated_error/gear_ratio_peak_to_peak"},
        {"most rollers in contact", "/max_pairs_in_contact", ""},
        {"largest ring-pin force", "/max_ring_pin_force_N", "N"},
        {"largest output-pin force", "/max_output_pin_force_N", "N"},
        {"smallest tooth radius", "/min_profile_radius_mm", "mm", "study:/limits/min_profile_radius_mm", 0.0, false},
        {"gap between pins", "/pin_gap_mm", "mm", "study:/limits/min_pin_gap_mm", 0.0, false},
        {"eccentric bearing load, largest", "/eccentric_bearing_load_N", "N", "study:/limits/eccentric_bearing_load_N"},
        {"output-pin bending stress", "/output_pin_bending_stress_MPa", "MPa", "study:/limits/output_pin_stress_MPa"},
        {"output-pin contact pressure", "/output_pin_contact_pressure_MPa", "MPa", "study:/limits/output_pin_contact_pressure_MPa"},
        {"torsional stiffness (50-100% of rated)", "/torsional_stiffness_Nm_per_arcmin", "N m/arcmin"},
        {"lost motion (±3% of rated)", "/lost_motion_arcmin", "arcmin"},
        {"backlash", "/backlash_arcmin", "arcmin"},
        {"shortest bearing life L10h", "/life/shortest_L10h", "h"},
        {"crank bearing life L10h", "/life/crank_bearing_L10h", "h"},
        {"ring pin life L10h", "/life/pins_L10h", "h"},
    }, RatingsHeadlines(), TorsionalDynamicsHeadlines(), {{"converged", "/converged", ""}}})),
    .datasheet = CycloidDatasheet(),
    .asked = std::vector<AskedBlock>{
        {{"/output_mechanism/hole_radius_mm"}, "/output_mechanism", "the output mechanism with clearance (pin forces, eccentric-bearing load, lost motion)"},
        {{"/stiffness"}, "/stiffness", "the torsional stiffness"},
        {{"/tolerances"}, "/transmission_error", "the tolerance analysis"},
        {{"/duty_cycle", "/load/input_speed_rpm"}, "/life", "the bearing lives"},
        {{"/lubricant"}, "/lubrication", "the lubricated losses"},
        {{"/ratings"}, "/ratings", "the ratings"},
        {{"/output_bearing"}, "/output_bearing", "the output bearing's life"},
    },
    .init_example = "cycloid_ltca_nnm_lcm",
    .mechanism = CycloidMechanismAt});
}  // namespace

}  // namespace camopt::studies::cycloid_ltca
