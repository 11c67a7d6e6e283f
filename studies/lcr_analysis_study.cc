// Study kind "lcr_analysis": analyse one lobe cam reducer over an input revolution.
// Stages run only as the study asks ("analysis.evaluate"): profile, undercut, forces, stress,
// efficiency. Outputs: result.json, series.csv, SVG plots and drawings, DXF profiles with cutter paths.
// Parse → Run → Write (studies/lcr_analysis_study.h); the physics is model/lcr/.
#include "studies/lcr_analysis_study.h"

#include "studies/bearing_life_io.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cmath>
#include <numeric>
#include <set>
#include <tuple>

#include "model/common/sliced_bearing_life.h"
#include "model/contact/hertz.h"
#include "model/lcr/contact_fatigue.h"
#include "model/lcr/friction.h"
#include "model/lcr/life.h"
#include "model/lcr/profile.h"
#include "model/lcr/sliced_life.h"
#include "model/common/polygon.h"
#include "model/rigidity/lcr_stiffness.h"
#include "studies/contact_fatigue_input.h"
#include "studies/datasheet.h"
#include "studies/format.h"
#include "studies/kind.h"
#include "studies/lcr_input.h"
#include "studies/material_input.h"
#include "studies/report.h"
#include "studies/studio_mechanism.h"
#include "studies/work_limits.h"
#include "studies/writers.h"

namespace camopt::studies::lcr_analysis {
namespace {

using lcr::Side;

double Max(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }
double Min(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }
double Mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / v.size(); }
template <typename I>
int MaxI(const std::vector<I>& v) { return *std::max_element(v.begin(), v.end()); }
template <typename I>
int MinI(const std::vector<I>& v) { return *std::min_element(v.begin(), v.end()); }

Polyline ToPolyline(const std::vector<Vec2<double>>& pts, const Vec2<double>& shift = {0, 0},
                    double rotation = 0) {
  Polyline out;
  for (const auto& p : pts) {
    const Vec2<double> q = Rotate(p, rotation) + shift;
    out.emplace_back(q.x(), q.y());
  }
  return out;
}

// Cam profile, pitch curve and cutter path of one cam in the cam frame (for DXF).
Drawing CamDrawing(const lcr::Reducer<double>& r, Side s, double cutter_radius, int points,
                   const std::string& title) {
  const auto& c = r.side(s);
  Drawing d;
  d.title = title;
  Drawing::Layer profile{"CAM_PROFILE", "#000000", {}, {}, true, 1.5};
  Drawing::Layer pitch{"PITCH_CURVE", "#888888", {}, {}, true, 0.7};
  // Dashed: with a cutter of the roller's size its path is the pitch curve, which stays visible.
  Drawing::Layer cutter{"CUTTER_PATH", "#d62728", {}, {}, true, 0.7, "6,4"};
  profile.polylines.push_back(ToPolyline(lcr::SampleCurve(c, r.eccentricity, c.roller_radius, points)));
  pitch.polylines.push_back(ToPolyline(lcr::SampleCurve(c, r.eccentricity, 0.0, points)));
  cutter.polylines.push_back(
      ToPolyline(lcr::SampleCurve(c, r.eccentricity, c.roller_radius - cutter_radius, points)));
  d.layers = {profile, pitch, cutter};
  double r_min = INFINITY, r_max = 0;
  for (const auto& [x, y] : profile.polylines.front()) {
    r_min = std::min(r_min, std::hypot(x, y));
    r_max = std::max(r_max, std::hypot(x, y));
  }
  char line[200];
  std::snprintf(line, sizeof line, "%d lobes, %d rollers; eccentricity %g mm; turret radius %g mm", c.lobes,
                c.rollers, r.eccentricity, c.turret_radius);
  d.dimensions.push_back(line);
  std::snprintf(line, sizeof line, "roller diameter %g mm; cam thickness %g mm; cutter diameter %g mm",
                2 * c.roller_radius, c.cam_thickness, 2 * cutter_radius);
  d.dimensions.push_back(line);
  std::snprintf(line, sizeof line, "profile radius from the cam centre %.3f to %.3f mm (sampled)", r_min, r_max);
  d.dimensions.push_back(line);
  return d;
}

// The geometry files of one cam: exact profile, pitch curve and cutter path as curve functions.
PlanarCamGeometry CamGeometry(const Study& st, Side s) {
  const lcr::Reducer<double>& r = st.reducer;
  const lcr::CamSide<double>& c = r.side(s);
  const bool input = s == Side::kInput;
  const double e = r.eccentricity, rr = c.roller_radius;
  const double cutter = input ? st.cutter_radius_input_mm : st.cutter_radius_output_mm;
  PlanarCamGeometry g;
  g.file_stem = input ? "input_cam" : "output_cam";
  g.design_name = st.name;
  g.cam_name = input ? "input cam" : "output cam";
  g.profile = lcr::OffsetCurve(c, e, rr);
  g.pitch = lcr::PitchCurve(c, e);
  if (input ? st.cutter_input_given : st.cutter_output_given) {
    g.cutter = lcr::OffsetCurve(c, e, rr - cutter);
    g.cutter_diameter_mm = 2 * cutter;
  } else {
    g.cutter_note = "omitted: the cutter equals the roller, so its path is the pitch curve (layer PITCH_CURVE)";
  }
  g.initial_segments = 8 * c.rollers;
  // With rollers = lobes + 1 the pitch factor k = rollers is whole and X(ψ + 2π/lobes) turns X(ψ)
  // by 2π/lobes (profile.h: u(kψ + 2πk/lobes) = u(kψ + 2π + 2π/lobes)); so do its offsets.
  if (c.rollers == c.lobes + 1) g.symmetry = c.lobes;
  g.thickness_mm = c.cam_thickness;
  g.bore_diameter_mm = input ? st.bore_diameter_input_mm : st.bore_diameter_output_mm;
  g.mounting = input ? st.mounting_input : st.mounting_output;
  return g;
}

}  // namespace

Drawing AssemblyDrawing(const lcr::Reducer<double>& r, Side s, const lcr::AngleLoads<double>* loads,
                        int points, const std::string& title) {
  const auto& c = r.side(s);
  const Vec2<double> centre(r.eccentricity, 0.0);
  Drawing d;
  d.title = title;
  Drawing::Layer cam{"CAM_PROFILE", "#000000", {}, {}, true, 1.5};
  Drawing::Layer free_rollers{"ROLLERS", "#1f77b4", {}, {}, true, 1.0};
  Drawing::Layer loaded{"LOADED_ROLLERS", "#d62728", {}, {}, true, 1.5};
  Drawing::Layer axes{"AXES", "#888888", {}, {}, true, 0.7};
  cam.polylines.push_back(ToPolyline(lcr::SampleCurve(c, r.eccentricity, c.roller_radius, points), centre));
  const auto contacts = lcr::RollerContacts(r, s, 0.0);
  for (size_t k = 0; k < contacts.size(); ++k) {
    const Circle circle{contacts[k].centre.x(), contacts[k].centre.y(), Value(c.roller_radius)};
    const bool is_loaded =
        loads && (s == Side::kInput ? loads->input.force : loads->output.force)[k] > 0;
    (is_loaded ? loaded : free_rollers).circles.push_back(circle);
    d.labels.push_back({circle.x, circle.y, std::to_string(k + 1), is_loaded ? "#d62728" : "#1f77b4"});
  }
  axes.circles.push_back({0.0, 0.0, 0.6});
  axes.circles.push_back({centre.x(), centre.y(), 0.6});
  d.layers = {cam, free_rollers, loaded, axes};
  return d;
}

namespace {

// Optional "bore_diameter_mm" of a cam, inside the smallest profile diameter (ParseBoreDiameter).
double SmallestProfileRadius(const lcr::Reducer<double>& r, Side s) {
  const lcr::CamSide<double>& c = r.side(s);
  double rmin = kInf;
  for (int i = 0; i < 720; ++i)
    rmin = std::min(rmin, lcr::OffsetPoint(c, r.eccentricity, 2 * kPi * i / 720, c.roller_radius).norm());
  return rmin;
}

double ParseBoreDiameter(const Node& side, const lcr::Reducer<double>& r, Side s) {
  if (!side.Has("bore_diameter_mm")) return 0.0;
  return studies::ParseBoreDiameter(side["bore_diameter_mm"], 2 * SmallestProfileRadius(r, s),
                                    "the cam's smallest profile diameter");
}

// The finite-length contact model of each cam (studies/lcr_contact_input.h, model/lcr/contact3d_cycle.h).
void RunContact3D(const Study& st, Result& res) {
  for (Side s : {Side::kInput, Side::kOutput}) {
    const auto& crowning = s == Side::kInput ? st.contact.input_crowning : st.contact.output_crowning;
    lcr::Contact3DCycleSide c = lcr::AnalyzeCycleContact3D(st.reducer, s, res.series, st.material.composite_modulus_MPa(),
                                                          crowning, st.contact.options);
    CamResult& j = s == Side::kInput ? res.input_cam : res.output_cam;
    j.max_contact_stress_MPa = c.max_contact_stress_MPa;
    // The subsurface stresses of the peak: the worst slice as a line contact of its own peak
    // pressure, b = 2 p0 R'/E* (model/contact/hertz.h), R' of the contact that sets the peak.
    j.peak_half_width_mm = 0;
    if (c.worst_angle >= 0 && std::isfinite(c.max_contact_stress_MPa)) {
      const double e_star = st.material.composite_modulus_MPa();
      j.peak_half_width_mm = contact::LineContactHalfWidthFromPeakPressure(
          c.max_contact_stress_MPa, c.stress_radius_mm[size_t(c.worst_angle)], e_star);
      const lcr::ContactModel m = st.contact.options.model;
      char where[120];
      std::snprintf(where, sizeof where, "roller %d at input angle %.6g deg", c.worst_roller,
                    res.series.theta_rad[size_t(c.worst_angle)] * 180 / kPi);
      j.subsurface_basis =
          m == lcr::ContactModel::kLine
              ? std::string("Hertz line contact of the cam's peak pressure (") + where +
                    "), frictionless, homogeneous half-spaces (Johnson 1985, eq. 4.50 ff.)"
              : std::string(m == lcr::ContactModel::kSlices ? "the worst slice of the slices model"
                                                            : "the half_space model's peak pressure") +
                    " (" + where + ") taken as a line contact of that peak pressure and half-width b = 2 p0 R'/E* "
                    "(plane strain under the peak; frictionless, homogeneous half-spaces, Johnson 1985 eq. 4.50 ff.)";
    }
    if (!c.converged)
      res.notes.push_back(std::string(s == Side::kInput ? "input" : "output") +
                          " cam: a contact solve did not converge (see docs/lcr.md)");
    (s == Side::kInput ? res.contact_input : res.contact_output) = std::move(c);
  }
}

// A bearing's ratings from `node` (a reducer side or "eccentric_bearing"): C required when a life
// is asked, C0 optional (s0 is reported when given).
BearingRating ParseRating(const Node& node, BearingKind kind, const std::string& why) {
  const RollingBearingRating r = ParseRatingValues(node, kind, why);
  BearingRating b;
  b.kind = r.kind;
  b.dynamic_N = r.dynamic_N;
  b.static_N = r.static_N;
  b.modified = r.modified;
  return b;
}

// "load.input_speed_rpm" or "duty_cycle" (docs/life.md); nullopt when neither is given.
std::optional<LifeSpec> ParseLife(const Input& in, const Node& root, const lcr::LoadCase& load) {
  std::string why;
  std::optional<std::vector<lcr::LcrDutyLine>> lines = ParseDutyCycle(root, in.duty_cycle, load.output_torque_Nmm, &why);
  if (!lines) return std::nullopt;
  LifeSpec life;
  life.lines = std::move(*lines);
  life.from_duty_cycle = in.duty_cycle.has_value();
  const Node reducer = root["reducer"];
  life.input_roller = ParseRating(reducer["input"], BearingKind::kRoller, why);
  life.output_roller = ParseRating(reducer["output"], BearingKind::kRoller, why);
  if (in.reducer.eccentric_bearing) {
    const EccentricBearingInput& eb = *in.reducer.eccentric_bearing;
    life.eccentric = ParseRating(reducer["eccentric_bearing"], eb.kind == "ball" ? BearingKind::kBall : BearingKind::kRoller,
                                 why);
  }
  if (life.input_roller.modified || life.output_roller.modified || (life.eccentric && life.eccentric->modified))
    life.contamination_factor = in.lubricant->contamination_factor;  // CheckModifiedLifeInputs: given
  return life;
}

// The modified life's inputs across blocks (CheckModifiedLifeInputs): the rating blocks that give
// C_u and D_pw need the lubricant's contamination factor, and it needs one of them.
void CheckModifiedLife(const Input& in, const Node& root) {
  std::vector<Node> rated;
  const Node reducer = root["reducer"];
  if (in.reducer.input.fatigue_load_limit_N || in.reducer.input.pitch_diameter_mm) rated.push_back(reducer["input"]);
  if (in.reducer.output.fatigue_load_limit_N || in.reducer.output.pitch_diameter_mm) rated.push_back(reducer["output"]);
  if (in.reducer.eccentric_bearing &&
      (in.reducer.eccentric_bearing->fatigue_load_limit_N || in.reducer.eccentric_bearing->pitch_diameter_mm))
    rated.push_back(reducer["eccentric_bearing"]);
  // Both or neither of C_u and D_pw per block first (ParseRatingValues' message names the missing one).
  for (const Node& node : rated) ParseModifiedLifeRating(node);
  CheckModifiedLifeInputs(root, rated);
}

// The finite-length contact (studies/lcr_contact_input.h): the rollers' crowning, checked against
// their length, and the "contact" object; crowned rollers need a model other than line.
LcrContactInput ContactOf(const Input& in, const Node& root, const lcr::Reducer<double>& reducer) {
  LcrContactInput out;
  bool crowned = false;
  for (Side s : {Side::kInput, Side::kOutput}) {
    const LcrRatedSideInput& side = s == Side::kInput ? in.reducer.input : in.reducer.output;
    if (!side.crowning) continue;
    const char* name = s == Side::kInput ? "input" : "output";
    auto& c = s == Side::kInput ? out.input_crowning : out.output_crowning;
    c = ParseRollerCrowning(root["reducer"][name]["crowning"], Value(reducer.side(s).roller_length));
    crowned = crowned || c.type != contact::CrowningType::kNone;
  }
  if (in.contact) {
    out.given = true;
    out.options = ToContactOptions(*in.contact, root["contact"]);
  }
  if (crowned && out.options.model == lcr::ContactModel::kLine) {
    if (in.contact && in.contact->model) root["contact"]["model"].Fail("slices or half_space with crowned rollers (the line model ignores crowning)");
    root.FailWith("crowned rollers need \"contact\": {\"model\": \"slices\" or \"half_space\"} (the line model ignores crowning)");
  }
  return out;
}

// The peak contact pressure of each cam at a duty line's torque, by the study's load model and,
// when the study has a "contact" object, its contact model (as the stress stage computes it).
std::array<double, 2> PeakPressures(const Study& st, double torque_Nmm) {
  if (!(torque_Nmm > 0)) return {0.0, 0.0};
  lcr::LoadCase load = st.load;
  load.output_torque_Nmm = torque_Nmm;
  const lcr::Stages stages{true, true, false};
  const lcr::CycleSeries series =
      st.load_model == lcr::LoadModel::kCompliant
          ? lcr::AnalyzeCycleCompliant(st.reducer, st.material, load, st.angle_steps, stages)
          : lcr::AnalyzeCycle(st.reducer, st.material, load, st.angle_steps, stages);
  std::array<double, 2> p{Max(series.input.max_stress_MPa), Max(series.output.max_stress_MPa)};
  if (st.contact.given)
    for (Side s : {Side::kInput, Side::kOutput}) {
      const auto& crowning = s == Side::kInput ? st.contact.input_crowning : st.contact.output_crowning;
      p[s == Side::kInput ? 0 : 1] = lcr::AnalyzeCycleContact3D(st.reducer, s, series, st.material.composite_modulus_MPa(),
                                                                crowning, st.contact.options)
                                         .max_contact_stress_MPa;
    }
  return p;
}

// The contact lives of the cams' tracks (docs/life.md, "Contact fatigue of the cam surfaces";
// model/lcr/contact_fatigue.h): the peak pressure of each line, N_c over-rollings per input
// revolution, the material's S–N point and Palmgren–Miner over the lines.
std::vector<CamContactLifeResult> CamContactLives(const Study& st) {
  const ContactFatigueSpec& cf = *st.contact_fatigue;
  std::vector<std::array<double, 2>> peaks;
  for (const DutyLine& line : st.life->lines) peaks.push_back(PeakPressures(st, line.output_torque_Nmm));
  std::vector<CamContactLifeResult> out;
  for (Side s : {Side::kInput, Side::kOutput}) {
    CamContactLifeResult c;
    c.name = s == Side::kInput ? "input_cam_contact" : "output_cam_contact";
    c.passes_per_input_revolution = lcr::ContactPassesPerInputRevolution(st.reducer, s);
    for (const auto& p : peaks) c.line_peak_pressure_MPa.push_back(p[s == Side::kInput ? 0 : 1]);
    const lcr::CamContactLife l =
        lcr::CamContactLifeOverDutyCycle(c.line_peak_pressure_MPa, st.life->lines, c.passes_per_input_revolution,
                                         cf.reference_pressure_MPa, cf.reference_cycles, cf.exponent);
    c.equivalent_pressure_MPa = l.equivalent_pressure_MPa;
    c.L10h = l.L10h;
    out.push_back(std::move(c));
  }
  return out;
}

// The sliced life of the rollers of cam s (docs/life.md, "Sliced roller life under tilt"): the
// slices model's load per slice at each sample of the roller's load period, for every duty line.
BearingLifeResult::Sliced SlicedRollerLife(const Study& st, Side s, const BearingRating& rating) {
  const auto& crowning = s == Side::kInput ? st.contact.input_crowning : st.contact.output_crowning;
  std::vector<SlicedDutyLine> lines;
  BearingLifeResult::Sliced out;
  out.slices = st.contact.options.slices;
  std::vector<double> y;
  for (const DutyLine& line : st.life->lines) {
    lcr::LoadCase load = st.load;
    load.output_torque_Nmm = line.output_torque_Nmm;
    lcr::RollerSliceSamples x = lcr::SampleRollerSliceLoads(st.reducer, st.material, load, st.load_model, s,
                                                            st.angle_steps, crowning, st.contact.options.misalignment_rad,
                                                            st.contact.options.slices);
    out.converged = out.converged && x.converged;
    out.edge_loaded = out.edge_loaded || x.edge_loaded;
    y = x.y_mm;
    lines.push_back({line.time_share, line.input_speed_rpm * x.revolutions_per_input_revolution, std::move(x.loads),
                     std::move(x.weights)});
  }
  const SlicedLife l = SlicedRatingLifeHours(rating.dynamic_N, lines, rating.kind);
  out.L10h = l.L10h;
  out.slice_rating_N = l.slice_rating_N;
  out.weibull_slope = l.weibull_slope;
  if (l.worst_slice >= 0) {
    out.worst_slice_y_mm = y[size_t(l.worst_slice)];
    out.worst_slice_L10h = l.slice_L10h[size_t(l.worst_slice)];
  }
  const SlicedDutyLine& first = lines.front();
  for (int k = 0; k < out.slices; ++k) {
    std::vector<double> q(first.loads.size());
    for (size_t i = 0; i < q.size(); ++i) q[i] = first.loads[i][size_t(k)];
    out.slice_equivalent_load_N.push_back(EquivalentLoad(q, first.weights, rating.kind));
  }
  return out;
}

// The bearing lives over the duty cycle (docs/life.md, "LCR"): for each line a force analysis at its
// torque over each bearing's load period (model/lcr/life.h), the revolution-weighted equivalent load
// per line, Palmgren–Miner over the lines (model/common/bearing_life.h).
LifeResult RunLife(const Study& st, const std::string& file) {
  const LifeSpec& spec = *st.life;
  const lcr::Reducer<double>& r = st.reducer;
  struct Member {
    const char* name;
    lcr::LcrBearing bearing;
    const BearingRating* rating;
  };
  std::vector<Member> members = {{"input_roller", lcr::LcrBearing::kInputRoller, &spec.input_roller},
                                 {"output_roller", lcr::LcrBearing::kOutputRoller, &spec.output_roller}};
  if (spec.eccentric) members.push_back({"eccentric_bearing", lcr::LcrBearing::kEccentric, &*spec.eccentric});
  LifeResult out;
  double output_energy = 0.0, input_energy = 0.0;  // per unit time, up to the same constant
  const double ratio = std::abs(lcr::SpeedReductionRatio(r));
  try {
    for (const DutyLine& line : spec.lines) {
      // The eccentric's load period also gives the mean input torque of the line.
      lcr::LoadCase load = st.load;
      load.output_torque_Nmm = line.output_torque_Nmm;
      const lcr::BearingLoadSamples ecc = lcr::SampleBearingLoad(r, st.material, load, st.load_model,
                                                                 lcr::LcrBearing::kEccentric, st.angle_steps);
      out.line_mean_input_torque_Nm.push_back(ecc.mean_input_torque_Nmm / 1000.0);
      output_energy += line.time_share * line.input_speed_rpm * line.output_torque_Nmm / ratio;
      input_energy += line.time_share * line.input_speed_rpm * ecc.mean_input_torque_Nmm;
    }
    out.efficiency_energy_mean = input_energy > 0 ? output_energy / input_energy : 0.0;
    for (const DutyLine& line : spec.lines) out.mean_input_speed_rpm += line.time_share * line.input_speed_rpm;
    out.shortest_L10h = kInf;
    for (const Member& m : members) {
      // One home for a bearing's life over the duty cycle (model/lcr/life.h), shared with the
      // dense check of lcr_min_size.
      const lcr::LcrBearingLife l = lcr::BearingLifeOverDutyCycle(r, st.material, st.load, st.load_model, m.bearing,
                                                                  m.rating->dynamic_N, m.rating->kind, spec.lines,
                                                                  st.angle_steps);
      BearingLifeResult b;
      b.name = m.name;
      b.rating = *m.rating;
      b.revolutions_per_input_revolution = l.revolutions_per_input_revolution;
      b.line_equivalent_load_N = l.line_equivalent_load_N;
      b.mean_speed_rpm = l.mean_speed_rpm;
      b.equivalent_load_N = l.equivalent_load_N;
      b.L10_Mrev = l.L10_Mrev;
      b.L10h = l.L10h;
      b.max_load_N = l.max_load_N;
      if (b.rating.static_N > 0) b.s0 = StaticSafetyFactor(b.rating.static_N, std::vector<double>{b.max_load_N});
      if (m.bearing != lcr::LcrBearing::kEccentric && st.contact.given &&
          st.contact.options.model != lcr::ContactModel::kLine)
        b.sliced = SlicedRollerLife(st, m.bearing == lcr::LcrBearing::kInputRoller ? Side::kInput : Side::kOutput,
                                    *m.rating);
      if (b.L10h < out.shortest_L10h || out.shortest.empty()) out.shortest_L10h = b.L10h, out.shortest = b.name;
      out.bearings.push_back(std::move(b));
    }
    if (st.contact_fatigue) out.cam_contacts = CamContactLives(st);
  } catch (const std::domain_error& e) {
    throw StudyError(file + ": /reducer: infeasible geometry: " + e.what());
  }
  return out;
}

// "lubricant" and its blocks (docs/lubrication.md): the common part (studies/lubrication_input.h)
// and the LCR's bearings.
std::optional<Study::Lubrication> ParseLubrication(const Input& in, const Node& root) {
  const std::optional<double> speed = in.load ? in.load->input_speed_rpm : std::nullopt;
  std::optional<LubricationCommon> common = ParseLubricationCommon(root, in.lubricant, in.surfaces, in.efficiency_map,
                                                                   speed, in.duty_cycle.has_value());
  if (!common) return std::nullopt;
  Study::Lubrication l;
  l.common = *common;
  l.spec.oil = common->oil;
  l.spec.friction = common->friction;
  l.spec.composite_roughness_mm = common->composite_roughness_mm;
  l.spec.rollers_rotate = common->rollers_rotate;
  const LcrBearingFrictionInput bearings = in.bearing_friction.value_or(LcrBearingFrictionInput{});
  l.rollers_bearing_given = bearings.rollers.has_value();
  l.eccentric_bearing_given = bearings.eccentric.has_value();
  l.spec.roller_bearing = bearings.rollers ? bearings.rollers->ToBearing() : PalmgrenBearing{0.0, 0.0, 1.0};
  l.spec.eccentric_bearing = bearings.eccentric ? bearings.eccentric->ToBearing() : PalmgrenBearing{0.0, 0.0, 1.0};
  return l;
}

// The lubricated losses at an operating point: the oil temperature given or from the housing's heat
// balance, then the losses at it.
struct OperatingPoint {
  OilTemperature oil;
  lcr::CycleLubrication cycle;
};
OperatingPoint LubricatedPoint(const Study& st, const lcr::CycleLoads& loads, double speed_rpm) {
  const Study::Lubrication& l = *st.lubrication;
  const std::vector<lcr::AngleKinematics<double>> kinematics =
      lcr::CycleKinematics(st.reducer, st.material, loads, l.spec, speed_rpm);
  const auto at = [&](double t) { return lcr::LubricatedCycle(st.reducer, loads, kinematics, l.spec, speed_rpm, t); };
  OperatingPoint p;
  p.oil = SolveOilTemperature(l.common, [&](double t) { return at(t).mean.total(); });
  p.cycle = at(p.oil.celsius);
  return p;
}

// The oil at the bearings for their modified life a_ISO: e_C and the viscosity at the lubricated
// operating point's temperature (the losses' housing balance or the given temperature).
ModifiedLifeOil ModifiedLifeOilOf(const Study& st, const Result& res) {
  ModifiedLifeOil oil;
  oil.contamination_factor = *st.life->contamination_factor;
  if (!res.lubrication) {
    oil.missing = res.lubrication_error.empty() ? "the lubricated losses were not computed" : res.lubrication_error;
    return oil;
  }
  oil.temperature_C = res.lubrication->oil_temperature_C;
  oil.viscosity_mm2_s = res.lubrication->viscosity_cSt;  // the oil's at that temperature (ASTM D341)
  return oil;
}

void RunLubrication(const Study& st, const RunContext& ctx, Result& res) {
  const Study::Lubrication& l = *st.lubrication;
  const lcr::Reducer<double>& r = st.reducer;
  const double speed = l.common.input_speed_rpm;
  Progress progress("lcr_analysis lubrication", ctx.quiet);
  try {
    const lcr::CycleLoads loads = lcr::SampleCycleLoads(r, st.material, st.load, st.load_model, st.angle_steps);
    const OperatingPoint p = LubricatedPoint(st, loads, speed);
    if (!p.oil.found()) {
      res.lubrication_error = "no thermal equilibrium: " + p.oil.thermal->why;
    } else {
      const lcr::CycleLubrication& c = p.cycle;
      LubricationResult out =
          CommonLubricationResult(l.common, p.oil, st.load.output_torque_Nmm / 1000, c.output_power_W, c.mean.total());
      out.power_loss_W.sliding_input_cam = c.mean.sliding_input;
      out.power_loss_W.sliding_output_cam = c.mean.sliding_output;
      out.power_loss_W.roller_bearings_input = c.mean.roller_bearings_input;
      out.power_loss_W.roller_bearings_output = c.mean.roller_bearings_output;
      out.power_loss_W.eccentric_bearing = c.mean.eccentric_bearing;
      out.power_loss_W.rolling_input_cam = c.mean.rolling_input;
      out.power_loss_W.rolling_output_cam = c.mean.rolling_output;
      out.power_loss_sampling_error_W = c.sampling_error_W;
      // The running torque without load, at the same speed and oil temperature.
      lcr::LoadCase idle = st.load;
      idle.output_torque_Nmm = 0.0;
      const lcr::CycleLubrication no_load = lcr::LubricatedCycle(
          r, st.material, lcr::SampleCycleLoads(r, st.material, idle, lcr::LoadModel::kRigid, st.angle_steps), l.spec,
          speed, p.oil.celsius);
      out.no_load_running_torque_Nm = no_load.mean.total() / (speed * 2 * kPi / 60);
      if (c.mean.min_lambda_roller >= 0)
        out.min_film_lambda = {c.mean.min_lambda, c.mean.min_film_mm * 1e3, c.min_lambda_theta_rad * 180 / kPi,
                               c.mean.min_lambda_side == 0 ? "input cam" : "output cam", RegimeName(c.mean.min_lambda),
                               c.mean.min_lambda_roller};
      if (!l.rollers_bearing_given && l.spec.rollers_rotate)
        out.not_modelled.push_back("the rollers' bearings (no bearing_friction.rollers)");
      if (!l.eccentric_bearing_given) out.not_modelled.push_back("the eccentric bearing (no bearing_friction.eccentric)");
      for (double v : {out.efficiency, out.oil_temperature_C, out.power_loss_W.total, out.no_load_running_torque_Nm})
        Finite(v, "lubrication");
      res.lubrication = out;
    }
    if (l.common.map) {
      const int steps = std::min(st.angle_steps, 360);
      size_t done = 0;
      const size_t total = l.common.map->torque_Nm.size() * l.common.map->speed_rpm.size();
      for (double torque : l.common.map->torque_Nm) {
        lcr::LoadCase load = st.load;
        load.output_torque_Nmm = torque * 1000;
        const lcr::LoadModel model = torque > 0 ? st.load_model : lcr::LoadModel::kRigid;
        const lcr::CycleLoads map_loads = lcr::SampleCycleLoads(r, st.material, load, model, steps);
        for (double n : l.common.map->speed_rpm) {
          const OperatingPoint m = LubricatedPoint(st, map_loads, n);
          res.efficiency_map.push_back({torque, n, m.cycle.efficiency, m.cycle.mean.total(), m.oil.celsius,
                                        m.cycle.mean.min_lambda_roller >= 0 ? m.cycle.mean.min_lambda : 0.0,
                                        m.oil.found() ? 1.0 : 0.0});
          progress.Update(double(++done) / double(total), std::to_string(total) + " operating points");
        }
      }
    }
  } catch (const std::domain_error& e) {
    throw StudyError(ctx.study_file + ": /reducer: infeasible geometry: " + e.what());
  }
  progress.Done();
}

}  // namespace

// "stiffness", "ratings", "output_bearing" and "external_loads" (docs/ratings.md).
void ParseCatalogue(const Input& in, const Node& root, Study& st) {
  if (in.stiffness) {
    if (!in.material) (void)root["material"];  // "missing required field": the contacts' compliance
    Study::StiffnessSpec k;
    k.rated_torque_Nm = in.stiffness->rated_torque_Nm;
    std::tie(k.T1_Nm, k.T2_Nm) = SegmentTorques(root["stiffness"], *in.stiffness);
    k.lost_motion_percent = in.stiffness->lost_motion_percent;
    st.stiffness = k;
  }
  if (in.ratings) {
    if (!in.material) (void)root["material"];
    if (!in.load) (void)root["load"];
    Study::RatingsSpec r;
    r.in = *in.ratings;
    st.density_kg_m3 = in.ratings->density_kg_m3;
    const std::string why = "ratings: the rated torque is the rollers' bearing life";
    const Node reducer = root["reducer"];
    r.life.input_roller = ParseRating(reducer["input"], BearingKind::kRoller, why);
    r.life.output_roller = ParseRating(reducer["output"], BearingKind::kRoller, why);
    if (in.reducer.eccentric_bearing)
      r.life.eccentric = ParseRating(reducer["eccentric_bearing"],
                                     in.reducer.eccentric_bearing->kind == "ball" ? BearingKind::kBall : BearingKind::kRoller,
                                     why);
    if (r.life.input_roller.modified || r.life.output_roller.modified || (r.life.eccentric && r.life.eccentric->modified))
      r.life.contamination_factor = in.lubricant->contamination_factor;  // CheckModifiedLifeInputs: given
    if (in.limits) {
      r.limits.contact_stress_MPa = in.limits->contact_stress_MPa;
      r.limits.roller_load_N = in.limits->roller_load_N;
    }
    st.ratings = r;
  }
  std::optional<double> speed;
  if (in.ratings) speed = in.ratings->rated_output_speed_rpm;
  else if (in.load && in.load->input_speed_rpm)
    speed = *in.load->input_speed_rpm / std::abs(lcr::SpeedReductionRatio(st.reducer));
  st.output_bearing = in.output_bearing;
  st.external_loads = ParseExternalLoads(root, in.output_bearing.has_value(), in.external_loads, speed);
}

Study Parse(const Node& root) {
  // Every field's type and bounds (the limits' margins are read by the report's headlines from the
  // study, "study:/limits/…"); what spans fields follows.
  const Input in = Read<Input>(root);
  Study st;
  st.name = in.name;
  st.reducer = ToReducer(in.reducer.Design(), root["reducer"]);
  const Input::Analysis analysis = in.analysis.value_or(Input::Analysis{});
  st.angle_steps = analysis.angle_steps;
  st.profile_points = analysis.profile_points;
  if (analysis.evaluate) {
    Evaluate& q = st.evaluate;
    q = {false, false, false, false, false};
    for (const std::string& stage : *analysis.evaluate) {
      if (stage == "profile") q.profile = true;
      if (stage == "undercut") q.undercut = true;
      if (stage == "forces") q.forces = true;
      if (stage == "stress") q.stress = q.forces = true;
      if (stage == "efficiency") q.efficiency = q.forces = true;
    }
  }
  st.load_model = analysis.load_model == "compliant" ? lcr::LoadModel::kCompliant : lcr::LoadModel::kRigid;
  // Lazy stages: the material is needed by the stress stage only, the load by the force stages
  // (forces, stress, efficiency); a profile/undercut study needs neither (checked when given).
  // The compliant load model and the transmission error (Palmgren contacts) need both.
  st.tolerances = ToToleranceSpec(in.tolerances, in.monte_carlo, root);
  const bool compliant =
      st.load_model == lcr::LoadModel::kCompliant || st.tolerances.has_value() || in.measured_profile.has_value();
  if ((st.evaluate.stress || compliant) && !in.material) (void)root["material"];  // "missing required field"
  if (in.material) {
    st.material = in.material->ToMaterial();
    if (in.material->contact_fatigue) st.contact_fatigue = in.material->contact_fatigue->ToSpec();
  }
  if ((st.evaluate.forces || compliant) && !in.load) (void)root["load"];
  if (in.load) {
    const Node load_node = root["load"];
    st.load.output_torque_Nmm = in.load->output_torque_Nm * 1000.0;
    st.load.friction_coefficient = in.load->friction_coefficient;
    st.load.cam_weight_N = in.load->cam_weight_N;
    CheckCarriedTorque(st.reducer, st.material.youngs_modulus_MPa, st.load.output_torque_Nmm,
                       load_node["output_torque_Nm"]);
    if (st.load_model == lcr::LoadModel::kCompliant && !(st.load.output_torque_Nmm > 0))
      load_node["output_torque_Nm"].Fail("a torque > 0 for \"load_model\": \"compliant\"");
    if (st.tolerances && !(st.load.output_torque_Nmm > 0))
      load_node["output_torque_Nm"].Fail("a torque > 0 for the transmission error under \"tolerances\"");
    if (in.measured_profile && !(st.load.output_torque_Nmm > 0))
      load_node["output_torque_Nm"].Fail("a torque > 0 for the measured cam's transmission error (\"measured_profile\")");
  }
  if (in.limits) {
    st.life_limit_h = in.limits->life_h.value_or(0.0);
    st.contact_stress_limit_MPa = in.limits->contact_stress_MPa.value_or(kInf);
    st.roller_load_limit_N = in.limits->roller_load_N.value_or(kInf);
  }
  const Node reducer_node = root["reducer"];
  st.cutter_radius_input_mm = ParseCutterDiameter(reducer_node["input"], 2 * st.reducer.input.roller_radius) / 2;
  st.cutter_radius_output_mm = ParseCutterDiameter(reducer_node["output"], 2 * st.reducer.output.roller_radius) / 2;
  st.cutter_input_given = st.cutter_radius_input_mm != st.reducer.input.roller_radius;
  st.cutter_output_given = st.cutter_radius_output_mm != st.reducer.output.roller_radius;
  st.bore_diameter_input_mm = ParseBoreDiameter(reducer_node["input"], st.reducer, Side::kInput);
  st.bore_diameter_output_mm = ParseBoreDiameter(reducer_node["output"], st.reducer, Side::kOutput);
  for (Side side : {Side::kInput, Side::kOutput}) {
    const bool input = side == Side::kInput;
    const LcrSideInput& si = input ? in.reducer.input : in.reducer.output;
    if (si.keyway || si.bolt_circle)
      (input ? st.mounting_input : st.mounting_output) =
          ParseMounting(reducer_node[input ? "input" : "output"], si.keyway, si.bolt_circle,
                        input ? st.bore_diameter_input_mm : st.bore_diameter_output_mm,
                        2 * SmallestProfileRadius(st.reducer, side), "the cam's smallest profile diameter");
  }
  st.geometry = GeometryFileOptionsOf(in.geometry_files);
  st.contact = ContactOf(in, root, st.reducer);
  CheckModifiedLife(in, root);
  st.life = ParseLife(in, root, st.load);
  if (st.contact_fatigue && !st.life)
    root["material"]["contact_fatigue"].Fail(
        "a speed with it (\"load.input_speed_rpm\" or \"duty_cycle\"): a contact life in hours needs one");
  if (st.life_limit_h > 0 && !st.life)
    root["limits"]["life_h"].Fail("a speed with it (\"load.input_speed_rpm\" or \"duty_cycle\"): a life in hours needs one");
  st.lubrication = ParseLubrication(in, root);
  ParseCatalogue(in, root, st);
  if (in.torsional_dynamics) {
    if (!in.material) (void)root["material"];  // "missing required field": the contacts' compliance
    if (!in.load) (void)root["load"];
    const Node block = root["torsional_dynamics"];
    const double torque = in.torsional_dynamics->load_torque_Nm.value_or(in.load->output_torque_Nm);
    if (!(torque > 0))
      block.FailWith("the mesh stiffness is the contacts' at a torque > 0: give load.output_torque_Nm > 0 or "
                     "torsional_dynamics.load_torque_Nm");
    st.torsional = ParseTorsionalDynamics(block, *in.torsional_dynamics);
  }
  st.inspection = in.inspection;
  if (in.measured_profile) {
    st.measured_side = in.measured_profile->part == "input_cam" ? Side::kInput : Side::kOutput;
    const InspectedPart part = CamPart(st, st.measured_side);
    // Covering: no arc between neighbouring points longer than 1/64 of the profile.
    st.measured = ReadMeasuredProfile(root["measured_profile"], part, part.profile.length_mm() / 64.0);
  }
  return st;
}

InspectedPart CamPart(const Study& st, Side side) {
  const lcr::CamSide<double>& c = st.reducer.side(side);
  const bool input = side == Side::kInput;
  const std::string name = input ? "input_cam" : "output_cam";
  return {name,
          "the " + std::string(input ? "input" : "output") + " cam's frame (as " + name +
              ".dxf): origin at the cam's centre (its bore, on the eccentric), x axis the model's at input angle 0",
          "the cam's centre (the bore's axis)",
          profile::ClosedProfile(lcr::CamProfileCurve(c, st.reducer.eccentricity, c.roller_radius), 0.0, 2.0 * kPi,
                                 512 * c.rollers)};
}

nlohmann::ordered_json Input::SchemaRules() {
  // The stress stage needs the material, the force stages (forces, stress, efficiency) the load,
  // the tolerances and the compliant load model both; a life (a duty cycle or load.input_speed_rpm)
  // the rollers' dynamic ratings, and not both forms of the speed; the cams' contact life and the
  // life limit a speed.
  nlohmann::ordered_json rules = nlohmann::ordered_json::parse(R"({"dependentRequired": {"monte_carlo": ["tolerances"]}, "allOf": [
    {"if": {"required": ["analysis"],
            "properties": {"analysis": {"required": ["evaluate"],
                                        "properties": {"evaluate": {"not": {"contains": {"enum": ["stress"]}}}}}}},
     "else": {"required": ["material"]}},
    {"if": {"required": ["analysis"],
            "properties": {"analysis": {"required": ["evaluate"],
                                        "properties": {"evaluate": {"not": {"contains": {"enum": ["forces", "stress", "efficiency"]}}}}}}},
     "else": {"required": ["load"]}},
    {"if": {"required": ["tolerances"]}, "then": {"required": ["material", "load"]}},
    {"if": {"required": ["measured_profile"]},
     "then": {"required": ["material", "load"],
              "properties": {"load": {"properties": {"output_torque_Nm": {"exclusiveMinimum": 0}}}}}},
    {"if": {"required": ["analysis"],
            "properties": {"analysis": {"required": ["load_model"], "properties": {"load_model": {"const": "compliant"}}}}},
     "then": {"required": ["material", "load"],
              "properties": {"load": {"properties": {"output_torque_Nm": {"exclusiveMinimum": 0}}}}}},
    {"if": {"anyOf": [{"required": ["material"], "properties": {"material": {"required": ["contact_fatigue"]}}},
                      {"required": ["limits"], "properties": {"limits": {"required": ["life_h"]}}}]},
     "then": {"anyOf": [{"required": ["duty_cycle"]},
                        {"required": ["load"], "properties": {"load": {"required": ["input_speed_rpm"]}}}]}}
  ]})");
  // The life's ratings and one form of the speed (shared with lcr_crowning_tuning), before the last.
  nlohmann::ordered_json& all = rules["allOf"];
  for (const auto& rule : LcrLifeSchemaRules()) all.insert(all.end() - 1, rule);
  AddLubricationSchemaRules(rules);  // the lubrication blocks (docs/lubrication.md)
  // The catalogue blocks (docs/ratings.md): the ratings need the material, the load and the rollers'
  // ratings; the torsional curve the material; the output bearing and its loads each other.
  for (const auto& rule : nlohmann::ordered_json::parse(R"([
    {"if": {"required": ["ratings"]},
     "then": {"required": ["material", "load"],
              "properties": {"reducer": {"properties": {"input": {"required": ["dynamic_rating_N"]},
                                                        "output": {"required": ["dynamic_rating_N"]}}}}}},
    {"if": {"required": ["stiffness"]}, "then": {"required": ["material"]}},
    {"if": {"required": ["torsional_dynamics"]}, "then": {"required": ["material", "load"]}},
    {"if": {"required": ["external_loads"]}, "then": {"required": ["output_bearing"]}},
    {"if": {"required": ["output_bearing"]}, "then": {"required": ["external_loads"]}}
  ])"))
    rules["allOf"].push_back(rule);
  // A crowned roller or a misalignment needs a contact model that sees it (the line model, also
  // the one of an absent "contact" or "model", ignores both).
  for (const auto& rule : nlohmann::ordered_json::parse(R"([
    {"if": {"required": ["reducer"], "properties": {"reducer": {"required": ["input"], "properties": {"input": {
              "required": ["crowning"], "properties": {"crowning": {
                "required": ["type"], "not": {"properties": {"type": {"const": "none"}}}}}}}}}},
     "then": {"required": ["contact"], "properties": {"contact": {
                "required": ["model"], "properties": {"model": {"enum": ["slices", "half_space"]}}}}}},
    {"if": {"required": ["reducer"], "properties": {"reducer": {"required": ["output"], "properties": {"output": {
              "required": ["crowning"], "properties": {"crowning": {
                "required": ["type"], "not": {"properties": {"type": {"const": "none"}}}}}}}}}},
     "then": {"required": ["contact"], "properties": {"contact": {
                "required": ["model"], "properties": {"model": {"enum": ["slices", "half_space"]}}}}}},
    {"if": {"required": ["contact"], "properties": {"contact": {
              "required": ["misalignment_mrad"], "properties": {"misalignment_mrad": {"not": {"const": 0}}}}}},
     "then": {"properties": {"contact": {
                "required": ["model"], "properties": {"model": {"enum": ["slices", "half_space"]}}}}}}
  ])"))
    rules["allOf"].push_back(rule);
  // The modified life a_ISO (docs/life.md): a bearing's C_u and D_pw with lubricant.contamination_factor.
  for (const auto& rule : ModifiedLifeSchemaRules(
           {{"reducer", "input"}, {"reducer", "output"}, {"reducer", "eccentric_bearing"}}))
    rules["allOf"].push_back(rule);
  return rules;
}


namespace {

// The torsional curve and its catalogue numbers (docs/ratings.md, docs/lcr_stiffness.md): the mean
// output rotation over the input revolution at torques −T_r … T_r, input held, conjugate profiles
// (no clearance: the curve is continuous at 0).
void RunStiffness(const Study& st, Result& res) {
  const Study::StiffnessSpec& k = *st.stiffness;
  const double tr = k.rated_torque_Nm;
  std::vector<double> f = {0.03, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0,
                           k.T1_Nm / tr, k.T2_Nm / tr, k.lost_motion_percent / 100.0};
  std::sort(f.begin(), f.end());
  f.erase(std::unique(f.begin(), f.end(), [](double a, double b) { return std::abs(a - b) <= 1e-12; }), f.end());
  std::vector<double> torques_Nm;
  for (auto it = f.rbegin(); it != f.rend(); ++it) torques_Nm.push_back(-*it * tr);
  torques_Nm.push_back(0.0);
  for (double x : f) torques_Nm.push_back(x * tr);
  std::vector<double> torques_Nmm;
  for (double t : torques_Nm) torques_Nmm.push_back(t * 1000.0);
  const std::vector<double> angle = rigidity::LostMotionCurve(st.reducer, st.material, torques_Nmm, 0.0, st.angle_steps);
  std::vector<camopt::TorsionPoint> curve;
  for (size_t i = 0; i < torques_Nm.size(); ++i) {
    if (torques_Nm[i] == 0.0) res.torsion_curve.push_back({0.0, angle[i]});  // 0− and 0+: no clearance
    res.torsion_curve.push_back({torques_Nm[i], angle[i]});
  }
  for (const auto& [t, a] : res.torsion_curve) curve.push_back({t, a * kArcminPerRad});
  auto at = [&](double t) { return TorsionAngleAt(curve, t) / kArcminPerRad; };
  res.stiffness_Nm_per_rad = 0.5 * (0.5 * tr / (at(tr) - at(0.5 * tr)) + 0.5 * tr / (at(-0.5 * tr) - at(-tr)));
  res.lost_motion_rad = LostMotionArcmin(curve, tr, 0.03) / kArcminPerRad;
  res.lost_motion_user_rad = LostMotionArcmin(curve, tr, k.lost_motion_percent / 100.0) / kArcminPerRad;
  res.segments = ThreeSegmentTorsionalStiffness(curve, k.T1_Nm, k.T2_Nm, tr);
}

// The cam's mass and inertia: both cam profiles (the roller-offset curves, 400 points a lobe) less
// their bores, each over its cam thickness; reflected to the output: the cam's centre orbits at the
// input speed (m e² r_i²), the cam turns at ω_c (J_c (ω_c/ω_o)²).
void RunMasses(const Study& st, Result& res) {
  const lcr::Reducer<double>& r = st.reducer;
  const double rho = st.density_kg_m3 * 1e-9;  // kg/mm³
  double m = 0, j = 0;                          // kg, kg·mm²
  for (Side s : {Side::kInput, Side::kOutput}) {
    const lcr::CamSide<double>& c = r.side(s);
    PolygonMoments pm = PolygonAreaAndPolarMoment(lcr::SampleCurve(c, r.eccentricity, c.roller_radius, 400 * c.lobes));
    const double bore = (s == Side::kInput ? st.bore_diameter_input_mm : st.bore_diameter_output_mm) / 2.0;
    pm.area -= kPi * bore * bore;
    pm.polar -= kPi * std::pow(bore, 4) / 2.0;
    m += rho * pm.area * c.cam_thickness;
    j += rho * pm.polar * c.cam_thickness;
  }
  res.cam_kg = m;
  res.cam_inertia_kgm2 = j * 1e-6;
  const double ri = lcr::SpeedReductionRatio(r), wc = lcr::CamSpeedRatio(r) / lcr::OutputSpeedRatio(r);
  const double e_m = r.eccentricity * 1e-3;
  res.reflected_inertia_kgm2 = m * e_m * e_m * ri * ri + res.cam_inertia_kgm2 * wc * wc;
}

// The ratings (studies/ratings.h) on the rigid or compliant force analysis at each trial torque and
// the rollers' lives at the rated speed, and the output bearing.
// The allowable output speed at the rated torque (docs/ratings.md): the lubricated losses of the
// load model's forces at that torque, at a trial speed and the oil's limit (RatingsResult's note
// says why when the study has no housing balance).
void AllowableSpeed(const Study& st, double ratio, RatingsResult& g) {
  if (!st.lubrication) return;  // the default note: no lubricant
  const Study::Lubrication& l = *st.lubrication;
  if (l.common.temperature_C) {
    g.allowable_speed_note = "not computed: the oil's temperature is given (lubricant.temperature_C); the allowable "
                             "speed is the housing balance's thermal limit: give lubricant.thermal instead";
    return;
  }
  lcr::LoadCase load = st.load;
  load.output_torque_Nmm = g.rated_torque_Nm * 1000.0;
  const lcr::CycleLoads loads = lcr::SampleCycleLoads(st.reducer, st.material, load, st.load_model, st.angle_steps);
  SolveAllowableSpeed(
      [&](double n, double t) {
        const std::vector<lcr::AngleKinematics<double>> kinematics =
            lcr::CycleKinematics(st.reducer, st.material, loads, l.spec, n);
        return lcr::LubricatedCycle(st.reducer, loads, kinematics, l.spec, n, t).mean.total();
      },
      l.common.cooling, l.common.max_oil_temperature_C, ratio, st.ratings->in.rated_output_speed_rpm * ratio, g);
}

// The rollers' contacts as the torsional model's spring (docs/torsional_dynamics.md): the tangent
// torsional rigidity dT/dδθ_o of both turrets in series at the torque (model/rigidity/
// lcr_stiffness.h, DeflectAtAngle, exact by the implicit function theorem) and the output rotation
// there as the static TE, over one period of the contact pattern. The period: both turrets'
// roller patterns repeat every 2π lcm(m_A, m_B)/(n_A m_B) of input angle (model/lcr/life.h,
// LoadPeriodRad, the eccentric's); a finer period P/q (q <= 64) is taken when the stiffness and the
// rotation repeat after it to 1e-9 at 16 test angles (the largest such q is the true one).
MeshTable LcrMeshTable(const Study& st) {
  const TorsionalDynamicsInput& in = st.torsional->in;
  const lcr::Reducer<double>& r = st.reducer;
  MeshTable t;
  t.ratio = std::abs(lcr::SpeedReductionRatio(r));
  t.torque_Nm = in.load_torque_Nm.value_or(st.load.output_torque_Nmm / 1000.0);
  const double torque_Nmm = t.torque_Nm * 1000.0;
  auto at = [&](double theta) { return rigidity::DeflectAtAngle<double>(r, st.material, theta, torque_Nmm, 0.0); };
  const double p0 = lcr::LoadPeriodRad(r, lcr::LcrBearing::kEccentric, false);
  int q_best = 1;
  for (int q = 64; q >= 2 && q_best == 1; --q) {
    bool repeats = true;
    for (int j = 0; j < 16 && repeats; ++j) {
      const double theta = p0 * (j + 0.37) / 16.0;
      const auto a = at(theta), b = at(theta + p0 / q);
      repeats = std::abs(a.tangent_rigidity - b.tangent_rigidity) <= 1e-9 * std::abs(a.tangent_rigidity) &&
                std::abs(a.output_rotation - b.output_rotation) <= 1e-9 * std::abs(a.output_rotation);
    }
    if (repeats) q_best = q;
  }
  t.period_rad = p0 / q_best;
  t.source = "the tangent torsional rigidity of both turrets' Palmgren roller contacts in series at the reference "
             "torque, input held (docs/lcr_stiffness.md); the eccentric bearing, bodies and shafts not included";
  // Each turret's mesh: the input turret's roller pattern advances one roller pitch every 2π/n_A,
  // the output turret's every 2π m_A/(n_A m_B) of input angle (its rollers' phase rate q, model/lcr/
  // life.h, over its n_B rollers): n_A and n_A m_B/m_A mesh periods per input revolution.
  const double per_rev = 2.0 * kPi / t.period_rad;
  t.meshes = {{"input_turret", double(r.input.rollers) / per_rev},
              {"output_turret", double(r.input.rollers) * r.output.lobes / double(r.input.lobes) / per_rev}};
  const double fastest = std::max(t.meshes[0].second, t.meshes[1].second);
  const int n = in.angles_per_mesh_period * int(std::ceil(fastest - 1e-9));
  double sense = 0.0;
  for (int k = 0; k < n; ++k) {
    const double theta = t.period_rad * k / n;
    const auto d = at(theta);
    t.angles_rad.push_back(theta);
    t.stiffness_Nm_per_rad.push_back(d.tangent_rigidity / 1000.0);
    t.static_te_rad.push_back(d.output_rotation);
    sense += d.output_rotation;
  }
  if (sense < 0)  // the output turns against the torque's sign convention: the twist in the load's sense
    for (double& x : t.static_te_rad) x = -x;
  return t;
}

void RunCatalogue(const Study& st, const RunContext& ctx, Result& res) {
  if (st.stiffness || st.ratings) RunMasses(st, res);
  if (st.stiffness) RunStiffness(st, res);
  if (st.ratings) {
    const double ratio = std::abs(lcr::SpeedReductionRatio(st.reducer));
    Progress progress("lcr_analysis ratings", ctx.quiet);
    int step = 0;
    // The model at a torque on `steps` input angles (the study's, or half of them for the error).
    auto at_steps = [&](int steps) {
      return [&, steps](double torque_Nm) {
      ++step;
      progress.Update(std::min(0.95, 0.02 * step), std::to_string(step) + " analyses");
      Study c = st;
      c.angle_steps = steps;
      c.load.output_torque_Nmm = torque_Nm * 1000.0;
      LifeSpec life = st.ratings->life;
      life.lines = {lcr::LcrDutyLine{c.load.output_torque_Nmm, st.ratings->in.rated_output_speed_rpm * ratio, 1.0}};
      c.life = life;
      c.contact_fatigue.reset();
      c.contact.given = false;  // the rollers' line contact: the sliced 3D life is not a rating
      const lcr::CycleSeries series =
          st.load_model == lcr::LoadModel::kCompliant
              ? lcr::AnalyzeCycleCompliant(st.reducer, st.material, c.load, steps, {true, true, false})
              : lcr::AnalyzeCycle(st.reducer, st.material, c.load, steps, {true, true, false});
      RatingPoint p;
      for (const lcr::SideSeries* ss : {&series.input, &series.output}) {
        p.max_contact_stress_MPa = std::max(p.max_contact_stress_MPa, Max(ss->max_stress_MPa));
        p.max_roller_load_N = std::max(p.max_roller_load_N, Max(ss->max_force_N));
        p.max_contact_stress_vertex_MPa = std::max(p.max_contact_stress_vertex_MPa, ParabolicPeak(ss->max_stress_MPa));
        p.max_roller_load_vertex_N = std::max(p.max_roller_load_vertex_N, ParabolicPeak(ss->max_force_N));
      }
      const LifeResult l = RunLife(c, ctx.study_file);
      p.shortest_L10h = l.shortest_L10h;
      p.shortest = l.shortest;
      for (const BearingLifeResult& b : l.bearings) p.statics.push_back({b.name, b.rating.static_N, b.max_load_N});
      return p;
      };
    };
    try {
      const double start = std::max(1.0, st.load.output_torque_Nmm / 1000.0);
      res.ratings = SolveRatings(st.ratings->in, st.ratings->limits, at_steps(st.angle_steps), ratio, start);
      // The sampling error of the three torques: each solved again on every other input angle (the
      // loads' peaks and the lives' equivalent loads are sampled over the revolution), |fine − half|.
      const int half = st.angle_steps / 2;
      if (half >= 12) {
        const RatingsResult h =
            SolveRatings(st.ratings->in, st.ratings->limits, at_steps(half), ratio, start, &*res.ratings);
        RatingsResult& f = *res.ratings;
        auto error = [](double fine, double coarse) {
          return std::abs(fine - coarse) + kRatingSearchRelTolerance * fine;
        };
        f.rated_error_Nm = error(f.rated_torque_Nm, h.rated_torque_Nm);
        if (f.peak_torque_Nm && h.peak_torque_Nm)
          f.peak_error_Nm = error(*f.peak_torque_Nm, *h.peak_torque_Nm) + f.peak_sampling_error_Nm.value_or(0.0);
        if (f.momentary_torque_Nm && h.momentary_torque_Nm)
          f.momentary_error_Nm = error(*f.momentary_torque_Nm, *h.momentary_torque_Nm);
        f.error_method = "|fine - half the input angles (analysis.angle_steps / 2)|, each rating solved again, + the "
                         "search's bracket (1e-6 of the torque); the peak torque's plus |on the sampled maxima - on "
                         "their parabolic vertices|";
        f.evaluations += h.evaluations;
      }
      AllowableSpeed(st, ratio, *res.ratings);
    } catch (const std::invalid_argument& e) {
      res.ratings_failed = e.what();
      res.notes.push_back(std::string("ratings not solved: ") + e.what());
    }
    progress.Done();
  }
  if (st.output_bearing) {
    res.output_bearing = TrySolveOutputBearing(*st.output_bearing, st.external_loads, &res.output_bearing_failed);
    if (!res.output_bearing) res.notes.push_back("output bearing not rated: " + res.output_bearing_failed);
  }
}

}  // namespace

namespace {

// Input angles of the measured cam's transmission error over one input revolution.
constexpr int kMeasuredAngleSteps = 720;

// The measured cam in the compliant model (model/lcr/transmission_error.h: the measured normal
// deviation d(ψ) in every roller's gap of that cam) beside the nominal reducer.
LcrMeasured MeasuredCam(const Study& st, Result& res) {
  const MeasuredProfile& m = *st.measured;
  const Side side = st.measured_side;
  LcrMeasured j;
  static_cast<MeasuredBlock&>(j) = MeasuredOf(m, CamPart(st, side));
  const lcr::Reducer<double>& r = st.reducer;
  lcr::Deviations<double> dev;
  const profile::PeriodicSpline shape = m.shape;
  dev.profile_shape[lcr::SideIndex(side)] = [shape](const double& t, double* slope) { return shape(t, slope); };
  const double torque = st.load.output_torque_Nmm;
  const double sense = lcr::LoadedArmSign(r, Side::kOutput);
  const double fraction = st.tolerances ? st.tolerances->lost_motion_torque_fraction : 0.03;
  const double t_lm = fraction * torque;
  std::vector<double> te, lm_nom, lm_meas, rot_nom, rot_meas;
  double force_nom = 0, force_meas = 0, stress_nom = 0, stress_meas = 0;
  const lcr::CamSide<double>& cam = r.side(side);
  const double e_star = st.material.composite_modulus_MPa(), rr = cam.roller_radius;
  const profile::Curve profile_curve = lcr::CamProfileCurve(cam, r.eccentricity, rr);
  // The curvature of the moved profile Q = P + d n at ψ (convex positive: the profile runs
  // counter-clockwise about the cam), from central differences over ψ (step 1e-4 rad).
  auto moved_curvature = [&](double psi) {
    auto q = [&](double u) {
      const profile::CurvePoint c = profile_curve(u);
      return Vec2<double>(c.point + shape(u) * Vec2<double>(c.tangent.y(), -c.tangent.x()));
    };
    const double h = 1e-4;
    const Vec2<double> qm = q(psi - h), q0 = q(psi), qp = q(psi + h);
    const Vec2<double> d1 = (qp - qm) / (2 * h), d2 = (qp - 2.0 * q0 + qm) / (h * h);
    return Cross(d1, d2) / std::pow(d1.norm(), 3);
  };
  auto hertz = [&](double f, double inv_r) {
    return inv_r > 0 ? contact::LineContactPeakPressure(f, cam.contact_length(), 1.0 / inv_r, e_star) : kInf;
  };
  try {
    for (int i = 0; i < kMeasuredAngleSteps; ++i) {
      const double th = 2.0 * kPi * i / kMeasuredAngleSteps;
      const Vec2<double> dir = lcr::EccentricLoadDirection(r, st.material, torque, th);
      auto at = [&](double t, const lcr::Deviations<double>* d) {
        return lcr::CompliantAtAngle<double>(r, st.material, th, sense * t, d, dir);
      };
      const lcr::CompliantAngle<double> nom = at(torque, nullptr), meas = at(torque, &dev);
      rot_nom.push_back(nom.output_rotation);
      rot_meas.push_back(meas.output_rotation);
      te.push_back(meas.output_rotation - nom.output_rotation);
      lm_nom.push_back(sense * (at(t_lm, nullptr).output_rotation - at(-t_lm, nullptr).output_rotation));
      lm_meas.push_back(sense * (at(t_lm, &dev).output_rotation - at(-t_lm, &dev).output_rotation));
      const auto& fn = side == Side::kInput ? nom.force_input : nom.force_output;
      const auto& fm = side == Side::kInput ? meas.force_input : meas.force_output;
      for (double f : fn) force_nom = std::max(force_nom, f);
      for (double f : fm) force_meas = std::max(force_meas, f);
      // Hertz line contact on each loaded roller of the measured cam: the nominal's on the pitch
      // curve's κ (1/R' = 1/r_r + κ/(1 − r_r κ), as AnalyzeCycleCompliant), the measured one on the
      // moved profile's curvature at the roller's foot point ψ* (found as RollerGaps finds it).
      const double phi = lcr::CamSpeedRatio(r) * th;
      const double turn = side == Side::kInput ? 0.0 : lcr::OutputSpeedRatio(r) * th;
      const auto contacts = lcr::RollerContacts(r, side, th);
      for (size_t k = 0; k < contacts.size(); ++k) {
        if (fn[k] > 0) stress_nom = std::max(stress_nom, hertz(fn[k], 1.0 / rr + contacts[k].curvature /
                                                                            (1.0 - rr * contacts[k].curvature)));
        if (!(fm[k] > 0)) continue;
        const double slot = 2.0 * kPi * double(k) / cam.rollers;
        const Vec2<double> o = cam.turret_radius * U(slot + turn) - r.eccentricity * U(th);
        double foot = 0;
        (void)lcr::PitchCurveDistance<double>(cam, r.eccentricity, Rotate(o, -phi), slot + turn - phi, &foot);
        stress_meas = std::max(stress_meas, hertz(fm[k], 1.0 / rr + moved_curvature(foot)));
      }
    }
  } catch (const std::domain_error& e) {
    j.not_computed = {{"the transmission error and lost motion of the measured cam",
                       std::string("the compliant model cannot carry the torque: ") + e.what()}};
    res.notes.push_back(std::string("measured_profile: ") + e.what());
    return j;
  }
  auto range = [](const std::vector<double>& v) {
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    return std::pair<double, double>(*lo, *hi);
  };
  const double as = tolerance::kArcsecPerRad, am = as / 60.0;
  const auto [rn_lo, rn_hi] = range(rot_nom);
  const auto [rm_lo, rm_hi] = range(rot_meas);
  LcrMeasured::Compliant& c = j.compliant.emplace();
  c.model = "the compliant load sharing of model/lcr/transmission_error.h (Palmgren contacts, input held) with the "
            "measured normal deviation d(psi) in every roller's gap of the measured cam";
  c.angles = kMeasuredAngleSteps;
  c.output_torque_Nm = torque / 1000.0;
  c.transmission_error = MeasuredTransmissionError::Of(
      te, as, "the output angle of the reducer with the measured cam less the nominal's at the same input angle and "
              "torque (input held)");
  c.output_rotation_peak_to_peak_arcsec = {(rn_hi - rn_lo) * as, (rm_hi - rm_lo) * as};
  c.lost_motion_arcmin = {*std::max_element(lm_nom.begin(), lm_nom.end()) * am,
                          *std::max_element(lm_meas.begin(), lm_meas.end()) * am};
  c.lost_motion_torque_Nm = t_lm / 1000.0;
  c.max_roller_force_N = {force_nom, force_meas};
  c.max_contact_stress_MPa = {stress_nom, stress_meas};
  c.contact_stress_note = "Hertz line contact of each loaded roller of the measured cam at the load torque, on "
                          "the measured profile's curvature (the moved profile P + d n differentiated over psi) "
                          "with the compliant model's forces; the nominal's on the exact profile";
  j.not_computed = {{"the lives, efficiency and the 3D (crowned) contact of the measured cam",
                     "those stages run on the nominal cams"}};
  return j;
}

}  // namespace

Result Run(const Study& st, const RunContext& ctx) {
  const lcr::Reducer<double>& r = st.reducer;
  const Evaluate& q = st.evaluate;
  Result res;
  res.speed_ratio = lcr::SpeedReductionRatio(r);
  res.cam_speed_ratio = lcr::CamSpeedRatio(r);
  res.output_speed_ratio = lcr::OutputSpeedRatio(r);
  res.outer_diameter_mm = lcr::OuterDiameter(r);

  // Undercut: cheap and needed by the stress stage's validity.
  res.undercut_evaluated = q.undercut || q.stress;
  for (Side s : {Side::kInput, Side::kOutput}) {
    const auto& c = r.side(s);
    CamResult& j = s == Side::kInput ? res.input_cam : res.output_cam;
    j.lobes = c.lobes;
    j.rollers = c.rollers;
    j.roller_gap_mm = lcr::RollerGap(c);
    j.pitch_point_radius_mm = lcr::PitchPointRadius(c, r.eccentricity);
    if (res.undercut_evaluated) {
      const double cutter = s == Side::kInput ? st.cutter_radius_input_mm : st.cutter_radius_output_mm;
      j.min_pitch_curve_radius_mm = lcr::MinConvexPitchRadius(c, r.eccentricity);
      j.undercut_margin_mm = lcr::MinConvexOffsetRadius(c, r.eccentricity, c.roller_radius);
      j.cutter_diameter_mm = 2 * cutter;
      j.min_cutter_path_radius_mm = lcr::MinConvexOffsetRadius(c, r.eccentricity, c.roller_radius - cutter);
      res.any_undercut = res.any_undercut || j.undercut_margin_mm < 0;
    }
  }
  if (res.any_undercut)
    res.notes.push_back("undercut: the roller is larger than the smallest convex pitch-curve radius; "
                        "the cam cannot be cut to this profile and contact stresses are not valid");

  if (q.forces) {
    const int steps = st.angle_steps;
    Progress progress("lcr_analysis", ctx.quiet);
    lcr::Stages stages{true, q.stress, q.efficiency};
    try {
      auto update = [&](double f) { progress.Update(f, std::to_string(steps) + " angles"); };
      res.series = st.load_model == lcr::LoadModel::kCompliant
                       ? lcr::AnalyzeCycleCompliant(r, st.material, st.load, steps, stages, update)
                       : lcr::AnalyzeCycle(r, st.material, st.load, steps, stages, update);
    } catch (const std::domain_error& e) {
      throw StudyError(ctx.study_file + ": /reducer: infeasible geometry: " + e.what());
    }
    progress.Done();
    const lcr::CycleSeries& series = res.series;
    for (Side s : {Side::kInput, Side::kOutput}) {
      const lcr::SideSeries& ss = s == Side::kInput ? series.input : series.output;
      CamResult& j = s == Side::kInput ? res.input_cam : res.output_cam;
      j.actuating_rollers_max = MaxI(ss.actuating);
      j.actuating_rollers_min = MinI(ss.actuating);
      j.max_roller_force_N = Max(ss.max_force_N);
      if (q.stress) {
        j.max_contact_stress_MPa = Max(ss.max_stress_MPa);
        j.contact_length_mm = r.side(s).contact_length();
        // The contact of the peak pressure, for its subsurface stresses (model/lcr/contact_fatigue.h).
        const lcr::PeakContact pk = lcr::FindPeakLineContact(r, s, series, st.material.composite_modulus_MPa());
        j.peak_half_width_mm = pk.half_width_mm;
        if (pk.angle >= 0) {
          char where[120];
          std::snprintf(where, sizeof where, "roller %d at input angle %.6g deg", pk.roller,
                        series.theta_rad[size_t(pk.angle)] * 180 / kPi);
          j.subsurface_basis = std::string("Hertz line contact of the cam's peak pressure (") + where +
                               "), frictionless, homogeneous half-spaces (Johnson 1985, eq. 4.50 ff.)";
        }
      }
    }
    res.fixed_turret_torque_Nm = Mean(series.input.turret_torque_Nmm) / 1000.0;
    if (q.efficiency) {
      res.input_torque_mean_Nm = Mean(series.input_torque_Nmm) / 1000;
      res.input_torque_max_Nm = Max(series.input_torque_Nmm) / 1000;
      res.input_torque_min_Nm = Min(series.input_torque_Nmm) / 1000;
      res.input_torque_ideal_Nm = lcr::IdealInputTorque(st.load.output_torque_Nmm, res.speed_ratio) / 1000;
      res.efficiency_mean = Mean(series.efficiency);
      res.efficiency_min = Min(series.efficiency);
      res.efficiency_max = Max(series.efficiency);
      res.eccentric_tangential_max_N = Max(series.tangential_force_N);
      res.eccentric_radial_max_abs_N = std::max(Max(series.radial_force_N), -Min(series.radial_force_N));
      if (st.load.output_torque_Nmm == 0)
        res.notes.push_back(st.load.cam_weight_N > 0
                                ? "zero output torque: efficiency is 0 (the cam weight still loads the eccentric)"
                                : "zero output torque: efficiency is its limit as the torque tends to 0 "
                                  "(the model is linear in the torque)");
    }
    if (q.stress && st.contact.given && !res.any_undercut) RunContact3D(st, res);
    if (q.profile) res.loads_at_zero = lcr::AnalyzeAngle(r, st.material, st.load, 0.0, {true, false, false});
  }
  if (st.life) res.life = RunLife(st, ctx.study_file);
  RunCatalogue(st, ctx, res);
  if (st.torsional) {
    try {
      res.torsional = RunTorsionalDynamics(*st.torsional, LcrMeshTable(st), ctx, "lcr_analysis");
      for (const std::string& w : res.torsional->warnings) res.notes.push_back(w);
    } catch (const StudyError&) {
      throw;  // bad input found by the run: exit 2
    } catch (const std::exception& e) {  // a mesh the model refuses (k <= 0), an integration that did not converge
      res.torsional_failed = e.what();
      res.notes.push_back(std::string("torsional dynamics not solved: ") + e.what());
    }
  }
  if (st.lubrication) RunLubrication(st, ctx, res);
  if (res.life && st.life->contamination_factor) res.life->oil = ModifiedLifeOilOf(st, res);
  if (q.profile) {
    res.input_cam_files = FitPlanarCam(CamGeometry(st, Side::kInput), st.geometry);
    res.output_cam_files = FitPlanarCam(CamGeometry(st, Side::kOutput), st.geometry);
  }
  if (st.inspection && st.geometry.write) {
    for (Side side : {Side::kInput, Side::kOutput}) {
      const InspectedPart part = CamPart(st, side);
      long points = 0;
      res.inspection_files.push_back(
          {part.name, InspectionCsv(st.name, part, st.inspection->spacing_mm, st.inspection->tolerance_um, &points)});
      res.inspection_points.push_back({part.name, points});
    }
  }
  if (st.measured) res.measured = MeasuredCam(st, res);
  if (st.tolerances) {
    const LcrToleranceSpec& t = *st.tolerances;
    Progress progress("lcr_analysis transmission error", ctx.quiet);
    lcr::TransmissionErrorOptions o;
    o.output_torque_Nmm = st.load.output_torque_Nmm;
    o.lost_motion_torque_Nmm = t.lost_motion_torque_fraction * st.load.output_torque_Nmm;
    o.angle_steps = t.angle_steps;
    o.samples = t.samples;
    o.seed = t.seed;
    o.progress = [&](double f) { progress.Update(f, std::to_string(t.samples) + " Monte-Carlo samples"); };
    try {
      res.transmission_error = lcr::AnalyzeTransmissionError(r, st.material, t.bands, o);
    } catch (const std::domain_error& e) {
      throw StudyError(ctx.study_file + ": /tolerances: the toleranced reducer cannot carry the load: " + e.what());
    }
    progress.Done();
  }
  FillResult(st, res);
  return res;
}

namespace {

// result.json's catalogue numbers (docs/ratings.md), as cycloid_ltca's: ratings, output_bearing,
// stiffness and stiffness_segments, masses, joint_model.
void FillCatalogue(const Study& st, const Result& res, Result::Json& j) {
  const double ratio = std::abs(lcr::SpeedReductionRatio(st.reducer));
  if (st.ratings) {
    j.ratings.Set(st.ratings->in, res.ratings, res.ratings_failed, ratio, true);
  }
  if (res.output_bearing) j.output_bearing = OutputBearingBlock::Of(*st.output_bearing, *res.output_bearing);
  else if (st.output_bearing) j.output_bearing = StageError{res.output_bearing_failed};
  if (st.stiffness || st.ratings)
    j.masses = Result::Json::Masses{
        st.density_kg_m3, res.cam_kg, res.cam_inertia_kgm2, res.outer_diameter_mm, res.reflected_inertia_kgm2,
        "the cam (both profiles less their bores, each over its thickness); not the rollers, turrets, eccentric "
        "shaft, bearings or housing. Reflected inertia: the cam's orbit m e^2 r_i^2 and spin J_c (w_c/w_o)^2, at "
        "the output"};
  if (st.stiffness && res.segments) {
    const Study::StiffnessSpec& k = *st.stiffness;
    const ThreeSegmentStiffness& g = *res.segments;
    j.torsional_stiffness_Nm_per_arcmin = res.stiffness_Nm_per_rad / kArcminPerRad;
    j.lost_motion_arcmin = res.lost_motion_rad * kArcminPerRad;
    j.backlash_arcmin = 0.0;
    j.stiffness = Result::Json::Stiffness{
        k.rated_torque_Nm, k.lost_motion_percent, res.lost_motion_user_rad * kArcminPerRad, 0.0,
        "input held; output angle: the mean over the input revolution of the output turret's rotation under the "
        "rollers' Palmgren line contacts (docs/lcr_stiffness.md); conjugate profiles: no clearance, so no backlash; "
        "stiffness: mean of the two senses' slopes between 50% and 100% of the rated torque; frictionless: no "
        "hysteresis width"};
    j.stiffness_segments = Result::Json::StiffnessSegments{
        k.T1_Nm, k.T2_Nm, k.rated_torque_Nm, g.k1_Nm_per_arcmin, g.k2_Nm_per_arcmin, g.k3_Nm_per_arcmin,
        "loading branch from 0: K1 = T1 / (angle(T1) - angle(0)), K2 = (T2 - T1) / (angle(T2) - angle(T1)), K3 = "
        "(T_r - T2) / (angle(T_r) - angle(T2))"};
    JointModelBlock& joint = j.joint_model.emplace();
    for (const auto& [t, a] : res.torsion_curve) joint.torsion_curve.push_back({t, a});
    joint.ratio = ratio;
    joint.rated_torque_Nm = k.rated_torque_Nm;
    joint.stiffness_Nm_per_rad = res.stiffness_Nm_per_rad;
    joint.stiffness_segments = {k.T1_Nm, k.T2_Nm, g.k1_Nm_per_arcmin * kArcminPerRad, g.k2_Nm_per_arcmin * kArcminPerRad,
                                g.k3_Nm_per_arcmin * kArcminPerRad};
    joint.lost_motion_rad = res.lost_motion_rad;
    joint.reflected_inertia_kgm2 = res.reflected_inertia_kgm2;
    joint.inertia_includes = "the cam's orbit and spin (masses.includes)";
    joint.damping_note = "not modelled: the contact model is quasi-static and frictionless";
    joint.friction_note = "not modelled in the joint (the LCR's losses are in the efficiency stage and lubrication)";
    if (res.lubrication) joint.efficiency = res.lubrication->efficiency;
    joint.SetTilt(st.output_bearing);
  }
}

// One cam's keys: input_cam or output_cam.
Result::Json::Cam CamJson(const Study& st, const Result& res, Side s) {
  const Evaluate& q = st.evaluate;
  const CamResult& c = s == Side::kInput ? res.input_cam : res.output_cam;
  Result::Json::Cam cj;
  cj.lobes = c.lobes;
  cj.rollers = c.rollers;
  cj.roller_gap_mm = c.roller_gap_mm;
  cj.pitch_point_radius_mm = c.pitch_point_radius_mm;
  if (res.undercut_evaluated) {
    cj.min_pitch_curve_radius_mm = c.min_pitch_curve_radius_mm;
    cj.min_convex_cam_radius_mm = c.undercut_margin_mm;
    cj.undercut_margin_mm = c.undercut_margin_mm;
    cj.undercut = c.undercut_margin_mm < 0;
    cj.cutter_diameter_mm = c.cutter_diameter_mm;
    cj.min_cutter_path_radius_mm = c.min_cutter_path_radius_mm;
  }
  if (!q.forces) return cj;
  cj.actuating_rollers_max = c.actuating_rollers_max;
  cj.actuating_rollers_min = c.actuating_rollers_min;
  cj.max_roller_force_N = c.max_roller_force_N;
  if (std::isfinite(st.roller_load_limit_N)) {
    cj.roller_load_limit_N = st.roller_load_limit_N;
    cj.roller_load_ok = c.max_roller_force_N <= st.roller_load_limit_N;
  }
  if (q.stress) {
    const double p = c.max_contact_stress_MPa;
    cj.max_contact_stress_MPa = p;  // null when not finite: a loaded roller sits on an undercut point
    if (std::isfinite(p) && std::isfinite(st.contact_stress_limit_MPa)) {
      cj.contact_stress_limit_MPa = st.contact_stress_limit_MPa;
      cj.contact_stress_ok = p <= st.contact_stress_limit_MPa;
    }
    cj.contact_length_mm = c.contact_length_mm;
    if (c.peak_half_width_mm > 0 || !std::isfinite(p))
      cj.subsurface = SubsurfaceOf(p, c.peak_half_width_mm, st.material.poisson_ratio, c.subsurface_basis);
    const auto& c3 = s == Side::kInput ? res.contact_input : res.contact_output;
    if (c3) {
      const lcr::ContactModel m = st.contact.options.model;
      cj.contact_model = ContactModelName(m);
      cj.edge_loaded = c3->edge_loaded;
      if (c3->worst_angle >= 0) cj.worst_input_angle_deg = res.series.theta_rad[c3->worst_angle] * 180 / kPi;
      if (m != lcr::ContactModel::kLine) {
        cj.slice_width_mm = c3->slice_width_mm;
        cj.interpolation_error_MPa = c3->interpolation_error_MPa;
      }
      if (m == lcr::ContactModel::kHalfSpace) {
        cj.cell_size_mm = std::array<double, 2>{c3->cell_dx_mm, c3->cell_dy_mm};
        cj.slices_max_contact_stress_MPa = c3->slices_peak_at_worst_MPa;
      }
    }
  }
  return cj;
}

// result.json's "life": the bearings' and the cams' contact lives over the duty cycle.
LifeBlock LifeBlockOf(const Study& st, const LifeResult& l) {
  const LifeSpec& spec = *st.life;
  LifeBlock lj;
  lj.shortest_L10h = l.shortest_L10h;
  lj.shortest_bearing = l.shortest;
  auto slot = [&lj](const std::string& name) -> LifeBlock::Bearing& {
    if (name == "input_roller") return lj.input_roller;
    if (name == "output_roller") return lj.output_roller;
    return lj.eccentric_bearing.emplace();
  };
  for (const BearingLifeResult& b : l.bearings) {
    (b.name == "input_roller"    ? lj.input_roller_L10h
     : b.name == "output_roller" ? lj.output_roller_L10h
                                 : lj.eccentric_bearing_L10h.emplace()) = b.L10h;
    if (b.sliced) {
      if (b.name == "eccentric_bearing") throw std::logic_error("lcr_analysis life: the eccentric bearing is not sliced");
      (b.name == "input_roller" ? lj.input_roller_sliced_L10h : lj.output_roller_sliced_L10h) = b.sliced->L10h;
    }
  }
  lj.mean_input_speed_rpm = l.mean_input_speed_rpm;
  lj.efficiency_energy_mean = l.efficiency_energy_mean;
  for (size_t i = 0; i < spec.lines.size(); ++i) {
    LifeBlock::DutyLine d;
    d.output_torque_Nm = spec.lines[i].output_torque_Nmm / 1000.0;
    d.input_speed_rpm = spec.lines[i].input_speed_rpm;
    d.time_share = spec.lines[i].time_share;
    d.mean_input_torque_Nm = l.line_mean_input_torque_Nm[i];
    lj.duty_cycle.push_back(d);
  }
  for (const BearingLifeResult& b : l.bearings) {
    LifeBlock::Bearing& bj = slot(b.name);
    bj.kind = b.rating.kind == BearingKind::kBall ? "ball" : "roller";
    bj.life_exponent = LifeExponent(b.rating.kind);
    bj.dynamic_rating_N = b.rating.dynamic_N;
    if (b.rating.static_N > 0) {
      bj.static_rating_N = b.rating.static_N;
      bj.s0 = b.s0;
    }
    bj.revolutions_per_input_revolution = b.revolutions_per_input_revolution;
    bj.mean_speed_rpm = b.mean_speed_rpm;
    bj.equivalent_load_N = b.equivalent_load_N;
    bj.line_equivalent_load_N = b.line_equivalent_load_N;
    bj.max_load_N = b.max_load_N;
    bj.L10_Mrev = b.L10_Mrev;
    bj.L10h = b.L10h;
    if (b.sliced) {
      const BearingLifeResult::Sliced& sl = *b.sliced;
      LifeBlock::Sliced& sj = bj.sliced.emplace();
      sj.L10h = sl.L10h;
      sj.slices = sl.slices;
      sj.misalignment_mrad = st.contact.options.misalignment_rad * 1e3;
      sj.slice_rating_N = sl.slice_rating_N;
      sj.weibull_slope = sl.weibull_slope;
      sj.worst_slice_y_mm = sl.worst_slice_y_mm;
      sj.worst_slice_L10h = sl.worst_slice_L10h;
      sj.slice_equivalent_load_N = sl.slice_equivalent_load_N;
      sj.edge_loaded = sl.edge_loaded;
      sj.converged = sl.converged;
      sj.model = "ISO/TS 16281's idea: the roller cut into slices along its length, the load per slice from the "
                 "slices contact model (crowning, misalignment) at each sample, each slice rated C (w/L)^(7/9) (ISO "
                 "281 6.1.1), slice lives over the duty cycle combined as 1/L^e = sum 1/L_k^e with e = 9/(2p), which "
                 "gives back ISO 281 for a uniform load (docs/life.md)";
    }
  }
  lj.model = "ISO 281:2007 basic rating life L10 of each bearing over the duty cycle (Palmgren-Miner), "
             "loads revolution-weighted over each bearing's load period; every roller of a turret carries "
             "the same load over its period; " + ModifiedLifeModelText(l.oil.has_value());
  // The cams' contact lives (docs/life.md, "Contact fatigue of the cam surfaces"): separate from
  // the bearings' shortest_L10h.
  for (const CamContactLifeResult& c : l.cam_contacts)
    (c.name == "input_cam_contact" ? lj.input_cam_contact_L10h : lj.output_cam_contact_L10h) = c.L10h;
  if (!l.cam_contacts.empty()) {
    const ContactFatigueSpec& cf = *st.contact_fatigue;
    LifeBlock::ContactLife& cl = lj.contact_life.emplace();
    cl.reference_pressure_MPa = cf.reference_pressure_MPa;
    cl.reference_cycles = cf.reference_cycles;
    cl.exponent = cf.exponent;
    cl.exponent_source = cf.exponent_given ? "given" : "default: Lundberg-Palmgren line contact, n = 8";
    cl.pressure_model = st.contact.given ? ContactModelName(st.contact.options.model) : "line";
    for (const CamContactLifeResult& c : l.cam_contacts)
      (c.name == "input_cam_contact" ? cl.input_cam_contact : cl.output_cam_contact) =
          LifeBlock::CamContact{c.passes_per_input_revolution, c.line_peak_pressure_MPa, c.equivalent_pressure_MPa,
                                c.L10h};
    cl.model =
        "stress-life law of the material, N = N_ref (p_ref/p0)^n over-rollings of a point of the cam's track to 10% "
        "failure, Palmgren-Miner over the duty cycle; every over-rolling counted at the cam's peak Hertz pressure of "
        "its line (n rollers times the turret's turns relative to the cam per input revolution); assumes the same "
        "contact geometry, material, heat treatment and lubrication as the reference, no fatigue limit, subsurface "
        "(not surface) initiated fatigue; not part of shortest_L10h (docs/life.md)";
  }
  // One row per element, the same keys as lcr_min_size's best.life.table (report.html's life table).
  const double limit = st.life_limit_h;
  if (limit > 0) lj.life_h = limit;
  double shortest_nm_h = kInf;  // the modified lives computed (a bearing with C_u and D_pw, kappa >= 0.1)
  std::string shortest_nm;
  for (const BearingLifeResult& b : l.bearings) {
    LifeTableRow e = BearingLifeRow(b.name, b.rating.kind == BearingKind::kBall, b.equivalent_load_N, b.max_load_N,
                                    b.revolutions_per_input_revolution, b.rating.dynamic_N, b.rating.static_N, b.s0,
                                    b.L10h, limit);
    if (l.oil && b.rating.modified) {
      const double l_nm = AddModifiedLife(e, b.rating.kind, *b.rating.modified, *l.oil, b.mean_speed_rpm,
                                          b.equivalent_load_N, b.L10h);
      if (!std::isnan(l_nm) && (shortest_nm.empty() || l_nm < shortest_nm_h)) shortest_nm_h = l_nm, shortest_nm = b.name;
    }
    lj.table.push_back(e);
    if (b.sliced) {
      LifeTableRow es = e;
      es.element = b.name + "_sliced";
      es.kind = "roller, sliced (ISO/TS 16281)";
      es.L10h = b.sliced->L10h;
      if (limit > 0) es.pass = b.sliced->L10h >= limit;
      lj.table.push_back(es);
    }
  }
  for (const CamContactLifeResult& c : l.cam_contacts) {
    double peak = 0;
    for (double p : c.line_peak_pressure_MPa) peak = std::max(peak, p);
    LifeTableRow row;
    row.element = c.name;
    row.kind = "cam contact";
    row.equivalent_pressure_MPa = c.equivalent_pressure_MPa;
    row.max_pressure_MPa = peak;
    row.contacts_per_input_revolution = c.passes_per_input_revolution;
    row.reference_pressure_MPa = st.contact_fatigue->reference_pressure_MPa;
    row.L10h = c.L10h;
    if (limit > 0) row.pass = c.L10h >= limit;
    lj.table.push_back(row);
  }
  if (l.oil) {
    lj.shortest_L_nm_h = shortest_nm.empty() ? NAN : shortest_nm_h;
    if (shortest_nm.empty()) lj.shortest_L_nm_bearing = nullptr;
    else lj.shortest_L_nm_bearing = shortest_nm;
  }
  return lj;
}

}  // namespace

void FillResult(const Study& st, Result& res) {
  const Evaluate& q = st.evaluate;
  Result::Json& j = res.json;
  j.name = st.name;
  j.speed_ratio = res.speed_ratio;
  j.cam_speed_ratio = res.cam_speed_ratio;
  j.output_speed_ratio = res.output_speed_ratio;
  j.outer_diameter_mm = res.outer_diameter_mm;
  j.angle_steps = st.angle_steps;
  j.load_model = LoadModelName(st.load_model);
  j.input_cam = CamJson(st, res, Side::kInput);
  j.output_cam = CamJson(st, res, Side::kOutput);
  if (q.forces) {
    j.fixed_turret_torque_Nm = res.fixed_turret_torque_Nm;
    // The paper's force model: the roller forces are frictionless and the friction enters the input
    // torque only (T_in = (F_t + μ F_r) e), so the three members' torques balance without it.
    if (st.load.friction_coefficient > 0)
      j.fixed_turret_torque_model =
          "from the frictionless roller forces (the paper's model): the friction moment of the input torque is "
          "not in it, so input, output and fixed-turret torques balance only up to the friction terms";
    j.output_torque_Nm = st.load.output_torque_Nmm / 1000.0;
    if (q.efficiency) {
      j.input_torque_Nm = Result::Json::InputTorque{res.input_torque_mean_Nm, res.input_torque_max_Nm,
                                                    res.input_torque_min_Nm, res.input_torque_ideal_Nm};
      j.efficiency = Result::Json::Efficiency{res.efficiency_mean, res.efficiency_min, res.efficiency_max};
      j.eccentric_load_N = Result::Json::EccentricLoad{res.eccentric_tangential_max_N, res.eccentric_radial_max_abs_N};
      j.friction_coefficient = st.load.friction_coefficient;
    }
  }
  if (st.contact.given) {
    Result::Json::Contact c;
    c.model = ContactModelName(st.contact.options.model);
    c.misalignment_mrad = st.contact.options.misalignment_rad * 1e3;
    if (st.contact.options.model != lcr::ContactModel::kLine) c.slices = st.contact.options.slices;
    if (st.contact.options.model == lcr::ContactModel::kHalfSpace)
      c.grid = std::array<int, 2>{st.contact.options.grid_nx, st.contact.options.grid_ny};
    j.contact = c;
  }
  if (res.transmission_error) j.transmission_error = TransmissionErrorBlockOf(*st.tolerances, *res.transmission_error);
  if (res.life) j.life = LifeBlockOf(st, *res.life);
  j.lubrication = StageBlock(res.lubrication, bool(st.lubrication), res.lubrication_error);
  FillCatalogue(st, res, j);
  if (res.torsional && st.torsional) j.torsional_dynamics = TorsionalDynamicsBlock::Of(*st.torsional, *res.torsional);
  else if (st.torsional) j.torsional_dynamics = StageError{res.torsional_failed};
  j.notes = res.notes;
  if (res.input_cam_files && res.output_cam_files)
    j.geometry_files =
        GeometryFilesOf(st.geometry, {{"input_cam", &*res.input_cam_files}, {"output_cam", &*res.output_cam_files}});
  if (st.inspection) {
    j.inspection = InspectionOf(st.inspection->spacing_mm, st.inspection->tolerance_um, res.inspection_points,
                                st.geometry.write, "each cam's centre (its bore); each file's header states its frame");
  }
  j.measured = res.measured;
}

namespace {
// Pressure along the roller at each cam's worst contact: roller_pressure.csv and .svg.
void WriteRollerPressure(const Study& st, const Result& res, Outputs& out) {
  std::vector<Series> curves;
  Table t;
  for (const auto& [name, c3] : {std::pair{"input", &*res.contact_input}, std::pair{"output", &*res.contact_output}}) {
    if (c3->worst_angle < 0) continue;
    const double angle = res.series.theta_rad[c3->worst_angle] * 180 / kPi;
    t.Add(std::string(name) + "_y_mm", c3->worst_y_mm);
    t.Add(std::string(name) + "_pressure_MPa", c3->worst_pressure_MPa);
    char label[160];
    std::snprintf(label, sizeof label, "%s cam, roller %d at input angle %.2f deg", name, c3->worst_roller, angle);
    curves.push_back({label, c3->worst_y_mm, c3->worst_pressure_MPa});
  }
  if (curves.empty()) return;
  out.Add("roller_pressure.csv", ToCsv(t));
  out.Add("roller_pressure.svg",
          SvgLinePlot(curves, {std::string("Contact pressure along the roller at the worst angle (") +
                                   ContactModelName(st.contact.options.model) + " model)",
                               "position along the roller from its mid-length [mm]", "contact pressure [MPa]"}));
}
}  // namespace

void Write(const Study& st, const Result& res, Outputs& out) {
  const lcr::Reducer<double>& r = st.reducer;
  const Evaluate& q = st.evaluate;
  if (q.forces) {
    const lcr::CycleSeries& series = res.series;
    Table t;
    std::vector<double> deg(series.theta_rad.size());
    for (size_t i = 0; i < deg.size(); ++i) deg[i] = series.theta_rad[i] * 180 / kPi;
    t.Add("input_angle_deg", deg);
    auto as_double = [](const std::vector<int>& v) { return std::vector<double>(v.begin(), v.end()); };
    t.Add("input_actuating_rollers", as_double(series.input.actuating));
    t.Add("output_actuating_rollers", as_double(series.output.actuating));
    t.Add("input_max_roller_force_N", series.input.max_force_N);
    t.Add("output_max_roller_force_N", series.output.max_force_N);
    if (q.stress && !res.contact_input) {
      t.Add("input_max_contact_stress_MPa", series.input.max_stress_MPa);
      t.Add("output_max_contact_stress_MPa", series.output.max_stress_MPa);
    }
    if (res.contact_input && res.contact_output) {
      for (const auto& [name, c3] : {std::pair{"input", &*res.contact_input}, std::pair{"output", &*res.contact_output}}) {
        t.Add(std::string(name) + "_max_contact_stress_MPa", c3->max_stress_MPa);
        t.Add(std::string(name) + "_stress_roller_force_N", c3->stress_force_N);
        t.Add(std::string(name) + "_stress_roller_radius_mm", c3->stress_radius_mm);
      }
    }
    auto nm = [](std::vector<double> v) { for (double& x : v) x /= 1000; return v; };
    t.Add("fixed_turret_torque_Nm", nm(series.input.turret_torque_Nmm));
    t.Add("output_torque_Nm", nm(series.output.turret_torque_Nmm));
    if (q.efficiency) {
      t.Add("eccentric_tangential_force_N", series.tangential_force_N);
      t.Add("eccentric_radial_force_N", series.radial_force_N);
      t.Add("input_torque_Nm", nm(series.input_torque_Nmm));
      t.Add("efficiency", series.efficiency);
    }
    out.Add("series.csv", ToCsv(t));
    PlotOptions forces{"Largest roller force over the input revolution", "input angle [deg]",
                       "largest roller force [N]"};
    forces.guides = {{"roller load limit", st.roller_load_limit_N}};
    out.Add("forces.svg", SvgLinePlot({{"input cam (fixed turret)", deg, series.input.max_force_N},
                                       {"output cam (output turret)", deg, series.output.max_force_N}},
                                      forces));
    if (res.contact_input && res.contact_output) WriteRollerPressure(st, res, out);
    if (q.stress && !res.any_undercut) {
      PlotOptions stress{"Largest Hertz contact stress", "input angle [deg]", "contact stress [MPa]"};
      stress.guides = {{"contact stress limit", st.contact_stress_limit_MPa}};
      out.Add("contact_stress.svg",
              SvgLinePlot({{"input cam", deg, res.contact_input ? res.contact_input->max_stress_MPa : series.input.max_stress_MPa},
                           {"output cam", deg, res.contact_output ? res.contact_output->max_stress_MPa : series.output.max_stress_MPa}},
                          stress));
    }
    if (q.efficiency)
      out.Add("efficiency.svg", SvgLinePlot({{"efficiency", deg, series.efficiency}},
                                            {"Efficiency (paper's friction model)", "input angle [deg]",
                                             "efficiency [-]"}));
  }
  if (!res.efficiency_map.empty()) WriteEfficiencyMap(res.efficiency_map, st.lubrication->common.map->torque_Nm, out);
  if (res.transmission_error) {
    const lcr::TransmissionErrorResult& te = *res.transmission_error;
    Table t;
    std::vector<double> deg(te.theta_rad.size()), windup(te.theta_rad.size());
    for (size_t i = 0; i < deg.size(); ++i) {
      deg[i] = te.theta_rad[i] * 180 / kPi;
      windup[i] = te.nominal_rotation_rad[i] * 180 / kPi * 3600;
    }
    t.Add("input_angle_deg", deg);
    t.Add("nominal_windup_arcsec", windup);
    t.Add("linear_te_sigma_arcsec", te.linear_sigma_arcsec);
    if (!te.worst_sample_te_arcsec.empty()) t.Add("worst_sample_te_arcsec", te.worst_sample_te_arcsec);
    out.Add("transmission_error.csv", ToCsv(t));
    std::vector<Series> lines = {{"linear σ", deg, te.linear_sigma_arcsec}};
    if (!te.worst_sample_te_arcsec.empty()) lines.push_back({"worst Monte-Carlo sample", deg, te.worst_sample_te_arcsec});
    out.Add("transmission_error.svg", SvgLinePlot(lines, {"Transmission error from the tolerances", "input angle [deg]",
                                                          "output angle error [arcsec]"}));
  }
  if (q.profile) {
    const int points = st.profile_points;
    for (Side s : {Side::kInput, Side::kOutput}) {
      const std::string which = s == Side::kInput ? "input" : "output";
      const double cutter = s == Side::kInput ? st.cutter_radius_input_mm : st.cutter_radius_output_mm;
      const Drawing cam = CamDrawing(r, s, cutter, points, which + " cam: profile, pitch curve, cutter path");
      const std::optional<PlanarCamFit>& files = s == Side::kInput ? res.input_cam_files : res.output_cam_files;
      if (files) WritePlanarCamFiles(*files, st.geometry, out);
      out.Add(which + "_cam.svg", SvgDrawing(cam));
      out.Add(which + "_assembly.svg",
              SvgDrawing(AssemblyDrawing(r, s, res.loads_at_zero ? &*res.loads_at_zero : nullptr, points,
                                         which + " cam and rollers at input angle 0 (loaded rollers red)")));
    }
  }
  out.SetResult(res);
  for (const auto& [name, csv] : res.inspection_files) out.Add("inspection/" + name + ".csv", csv);
  if (!res.torsion_curve.empty()) {
    // The torsional curve (docs/ratings.md): hysteresis.csv and .svg, as cycloid_ltca's.
    std::vector<double> torque, angle;
    for (const auto& [t, a] : res.torsion_curve) torque.push_back(t), angle.push_back(a * kArcminPerRad);
    Table t;
    t.Add("output_torque_Nm", torque);
    t.Add("output_angle_arcmin", angle);
    out.Add("hysteresis.csv", ToCsv(t));
    PlotOptions po;
    po.x_label = "output torque [N m]";
    po.y_label = "output angle [arcmin]";
    po.title = "Output angle against output torque, input held (mean over the input revolution)";
    out.Add("hysteresis.svg", SvgLinePlot({{"output angle", torque, angle}}, po));
  }
  if (st.ratings && !res.ratings)
    out.SetStatus(Status::kNotConverged, "ratings not solved (null in result.json): " + res.ratings_failed);
  if (res.torsional) WriteTorsionalDynamics(*res.torsional, out);
  if (st.torsional && !res.torsional)
    out.SetStatus(Status::kNotConverged, "torsional dynamics not solved: " + res.torsional_failed);
}

namespace {

// The declared input of a study, for the knobs and the estimate below, which run before Parse.
Input ReadInput(const nlohmann::json& study, const std::string& file) { return Read<Input>(Node(&study, file, "")); }

// Fidelity for `camopt run --convergence` (studies/convergence.h): the angle grid of the force
// stages (the maxima are sampled: no order assumed). The profile and undercut stages have none.
Fidelity Knobs(const nlohmann::json& study) {
  const Input in = ReadInput(study, "");
  const Input::Analysis a = in.analysis.value_or(Input::Analysis{});
  const Input::Analysis defaults;
  Fidelity f;
  bool forces = true;
  if (a.evaluate) {
    forces = false;
    for (const std::string& e : *a.evaluate) forces = forces || e == "forces" || e == "stress" || e == "efficiency";
  }
  if (forces)
    f.knobs.push_back({"angle_steps", {"/analysis/angle_steps"}, defaults.angle_steps, 2, true, 0,
                       "samples of the input revolution (cycle maxima and means)"});
  else
    f.no_knob = "profile and undercut only: closed forms and root finding, no setting to refine";
  // The finite-length contact (docs/lcr.md, "Crowned rollers and 3D contact"): slice count, and
  // the half_space grid.
  const std::string model = in.contact ? in.contact->model.value_or("line") : "line";
  if (forces && in.contact && in.contact->model && model != "line") {
    const lcr::ContactModelOptions contact_defaults;
    f.knobs.push_back({"contact_slices", {"/contact/slices"}, contact_defaults.slices, 2, true, 0,
                       "slices along the roller (the slices model; an edge peak grows with it)"});
    if (model == "half_space")
      f.knobs.push_back({"contact_grid", {"/contact/grid"}, {contact_defaults.grid_nx, contact_defaults.grid_ny}, 2,
                         true, 0, "half_space cells across rolling and along the roller"});
  }
  f.headlines = {"/input_cam/max_roller_force_N", "/output_cam/max_roller_force_N",
                 "/input_cam/max_contact_stress_MPa", "/output_cam/max_contact_stress_MPa",
                 "/efficiency/mean", "/input_torque_Nm/max", "/input_cam/undercut_margin_mm",
                 "/output_cam/undercut_margin_mm"};
  if (in.tolerances) {  // the transmission error's own angle grid
    f.knobs.push_back({"monte_carlo_angle_steps", {"/monte_carlo/angle_steps"}, LcrToleranceSpec{}.angle_steps, 2, true,
                       0, "input angles of the transmission error (peak-to-peak and lost-motion maxima are sampled)"});
    for (const char* h : {"/transmission_error/linear_worst_case_arcsec", "/transmission_error/monte_carlo_max_arcsec",
                          "/transmission_error/lost_motion_arcmin"})
      f.headlines.push_back(h);
  }
  return f;
}

// The work limit (studies/work_limits.h): angle_steps × rollers + profile_points × lobes, the
// finite-length contact's slices and half_space solves, the transmission error's Monte-Carlo and the
// bearing lives' load periods ≤ 2e7 roller contact evaluations.
WorkEstimate EstimateWork(const nlohmann::json& study, const std::string& file, double factor) {
  const Input in = ReadInput(study, file);
  const Input::Analysis a = in.analysis.value_or(Input::Analysis{});
  const LcrRatedReducerInput& red = in.reducer;
  const double rollers = double(red.input.rollers) + red.output.rollers;
  const double lobes = double(red.input.lobes) + red.output.lobes;
  const double steps = a.angle_steps;
  std::vector<WorkTerm> terms = {{steps * rollers, "/analysis/angle_steps",
                                  WorkNumber(steps) + " angle steps × " + WorkNumber(rollers) + " rollers"}};
  const double points = a.profile_points;
  terms.push_back({points * lobes, "/analysis/profile_points",
                   WorkNumber(points) + " profile points × " + WorkNumber(lobes) + " lobes"});
  if (in.contact && in.contact->model && *in.contact->model != "line") {
    // The finite-length contact: per cam, a table of 65 slices solves (13 forces × 5 radii) and 4
    // exact ones, a solve of N slices costing about (N/40)³ of a 40-slice one (≈0.6 ms, about
    // 1e4 roller contact evaluations); the half_space model adds 4 DC-FFT solves per cam of about
    // nx·ny·20 units (a 64×256 grid ≈ 0.1 s).
    const double slices = in.contact->slices;
    terms.push_back({2 * 69 * 1e4 * std::pow(slices / 40.0, 3), "/contact/slices",
                     "2 cams × 69 slices solves of " + WorkNumber(slices) + " slices"});
    if (*in.contact->model == "half_space") {
      const double cells = double(in.contact->grid[0]) * in.contact->grid[1];
      terms.push_back({2 * 4 * cells * 20, "/contact/grid",
                       "2 cams × 4 half_space solves on " + WorkNumber(cells) + " cells"});
    }
  }
  if (in.tolerances) {
    // Transmission error: per Monte-Carlo sample, angle and roller about two contact evaluations'
    // time (gap foot point + compliant solves, measured 6 µs per roller and angle).
    const LcrMonteCarloInput mc = in.monte_carlo.value_or(LcrMonteCarloInput{});
    const double samples = mc.samples.value_or(0), mc_steps = mc.angle_steps.value_or(72);
    terms.push_back({2.0 * (samples + 8.0) * mc_steps * rollers, "/monte_carlo/samples",
                     WorkNumber(samples) + " Monte-Carlo samples × " + WorkNumber(mc_steps) + " angles × " +
                         WorkNumber(rollers) + " rollers × 2"});
  }
  const bool duty = in.duty_cycle.has_value();
  if (duty || (in.load && in.load->input_speed_rpm)) {
    // Bearing life (docs/life.md): per duty-cycle line, one force analysis per sample over each
    // bearing's load period (model/lcr/life.h): an input revolution (input roller), 2π m_A n_B/(n_A m_B)
    // (output roller) and the eccentric's 2π lcm(m_A, m_B)/(n_A m_B), a whole number of revolutions
    // when the cam has a weight — at angle_steps samples per revolution.
    const auto count = [](int n) { return (long long)std::clamp(double(n), 1.0, 1e6); };
    const long long ma = count(red.input.lobes), na = count(red.input.rollers);
    const long long mb = count(red.output.lobes), nb = count(red.output.rollers);
    const long long l = std::lcm(ma, mb), d = na * mb, g = std::gcd(l, d);
    const bool weight = in.load && in.load->cam_weight_N > 0;
    const double ecc_revs = weight ? double(l / g) : double(l) / double(d);
    const double revs = 1.0 + double(ma * nb) / double(d) + ecc_revs;
    const double lines =
        duty ? std::max<double>(1, double(in.duty_cycle->size())) : 1.0;
    terms.push_back({lines * revs * steps * rollers, duty ? "/duty_cycle" : "/load/input_speed_rpm",
                     WorkNumber(lines) + " duty-cycle lines × " + WorkNumber(revs) +
                         " revolutions of bearing load periods × " + WorkNumber(steps) + " angle steps × " +
                         WorkNumber(rollers) + " rollers"});
  }
  return LargestTerm(terms, 2e7 * factor, "roller contact evaluations", 64);
}

// datasheet.html (studies/datasheet.h): with "stiffness" or "ratings".
DatasheetSpec LcrDatasheet() {
  const std::vector<DatasheetSection> ratings = RatingsDatasheetSections();  // ratings, output bearing
  return {"/masses",
          {{"Reducer", {{"speed reduction ratio r_i", "/speed_ratio", ""}}},
           ratings[0],
           StiffnessDatasheetSection(),
           {"Efficiency",
            {{"mean efficiency (eq. 33)", "/efficiency/mean", ""},
             {"lubricated efficiency", "/lubrication/efficiency", ""}}},
           ratings[1],
           {"Dimensions and mass",
            {{"outer diameter", "/masses/outer_diameter_mm", "mm"},
             {"mass of the cam", "/masses/cam_kg", "kg"},
             {"inertia at the output (reflected)", "/masses/reflected_inertia_kgm2", "kg·m²"},
             {"what the masses include", "/masses/includes", ""}}}},
          {"hysteresis.svg", "forces.svg"}};
}

CAMOPT_REGISTER_KIND(Kind<Input, Result, Study>{
    .name = "lcr_analysis",
    .title = "camopt study: lobe cam reducer analysis: roller forces, contact stress, undercut, efficiency and bearing life over a revolution",
    .run = Run, .parse = Parse, .write = Write, .knobs = Knobs, .estimate = EstimateWork,
    .report = WithLubricationHeadlines(JoinHeadlines({{
        {"largest contact stress, input cam", "/input_cam/max_contact_stress_MPa", "MPa", "/input_cam/contact_stress_limit_MPa"},
        {"largest contact stress, output cam", "/output_cam/max_contact_stress_MPa", "MPa", "/output_cam/contact_stress_limit_MPa"},
        {"largest roller force, input cam", "/input_cam/max_roller_force_N", "N", "/input_cam/roller_load_limit_N"},
        {"largest roller force, output cam", "/output_cam/max_roller_force_N", "N", "/output_cam/roller_load_limit_N"},
        {"undercut margin, input cam", "/input_cam/undercut_margin_mm", "mm", "study:/limits/undercut_margin_mm", 0.0, false},
        {"undercut margin, output cam", "/output_cam/undercut_margin_mm", "mm", "study:/limits/undercut_margin_mm", 0.0, false},
        {"gap between rollers, input cam", "/input_cam/roller_gap_mm", "mm", "study:/limits/roller_gap_mm", 0.0, false},
        {"gap between rollers, output cam", "/output_cam/roller_gap_mm", "mm", "study:/limits/roller_gap_mm", 0.0, false},
        {"outer diameter", "/outer_diameter_mm", "mm"},
        {"speed ratio", "/speed_ratio", ""},
        {"mean efficiency (eq. 33, load.friction_coefficient)", "/efficiency/mean", ""},
        {"largest input torque", "/input_torque_Nm/max", "N·m"},
        {"shortest bearing life L10h", "/life/shortest_L10h", "h", "study:/limits/life_h", NAN, false},
        {"input cam contact life L10h", "/life/input_cam_contact_L10h", "h", "study:/limits/life_h", NAN, false},
        {"output cam contact life L10h", "/life/output_cam_contact_L10h", "h", "study:/limits/life_h", NAN, false},
        {"torsional stiffness (50-100% of rated)", "/torsional_stiffness_Nm_per_arcmin", "N m/arcmin"},
        {"lost motion (±3% of rated)", "/lost_motion_arcmin", "arcmin"},
    }, RatingsHeadlines(), TorsionalDynamicsHeadlines()})),
    .datasheet = LcrDatasheet(),
    .asked = std::vector<AskedBlock>{
        {{"/contact"}, "/contact", "the 3D roller contact"},
        {{"/tolerances"}, "/transmission_error", "the tolerance analysis"},
        {{"/duty_cycle", "/load/input_speed_rpm"}, "/life", "the bearing lives"},
        {{"/lubricant"}, "/lubrication", "the lubricated losses"},
        {{"/ratings"}, "/ratings", "the ratings"},
        {{"/output_bearing"}, "/output_bearing", "the output bearing's life"},
    },
    .init_example = "lcr_ii",
    .mechanism = LcrMechanismAt});
}  // namespace

}  // namespace camopt::studies::lcr_analysis
