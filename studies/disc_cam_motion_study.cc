#include "studies/disc_cam_motion_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "model/disc_cam/residual_spectrum.h"
#include "studies/format.h"
#include "studies/backend_input.h"
#include "studies/kind.h"
#include "studies/report.h"
#include "studies/verification_json.h"
#include "studies/work_limits.h"
#include "studies/writers.h"
#include "studies/archive.h"

namespace camopt::studies::disc_cam_motion {
namespace {

namespace dc = camopt::disc_cam;
using objectives::MotionObjective;
constexpr double kDeg = kPi / 180.0;
constexpr int kMaxFree = 31;

void FillResult(const Study& s, Result& r);

}  // namespace

nlohmann::ordered_json Input::MotionSchema() {
  using oj = nlohmann::ordered_json;
  oj s = disc_cam::Input::MotionSchema(false);
  s["items"]["properties"]["optimize"] = {
      {"type", "object"},
      {"description",
       "design this segment's shape: a B-spline of `control_points` values, degree `degree`, from the segment's start "
       "to its end with the same rise and cam angle, meeting its neighbours' velocity (and acceleration) — not on a "
       "dwell, not next to another designed segment"},
      {"properties",
       {{"law", {{"const", "bspline"}, {"description", "the designed shape's law (B-spline)"}}},
        {"control_points",
         {{"type", "integer"}, {"minimum", 5}, {"maximum", 35},
          {"description", "n + 1 control values: at least 5 (velocity matched) or 7 (acceleration too), at most 31 free "
                          "over the designed segments"}}},
        {"degree", {{"type", "integer"}, {"minimum", 2}, {"maximum", 7}, {"default", 5},
                    {"description", "p, below control_points"}}},
        {"boundary",
         {{"type", "object"},
          {"description", "what the designed shape keeps of its neighbours at both ends (its position always)"},
          {"properties",
           {{"velocity", {{"const", true}, {"default", true},
                          {"description", "match the neighbours' velocity (always: the follower model needs C1)"}}},
            {"acceleration", {{"type", "boolean"}, {"default", true},
                              {"description", "match the neighbours' acceleration too (C2 joints)"}}}}},
          {"additionalProperties", false}}}}},
      {"required", oj::array({"law", "control_points"})},
      {"additionalProperties", false},
      // With the acceleration matched (the default) six values are fixed: at least seven.
      {"if", {{"required", oj::array({"boundary"})},
              {"properties", {{"boundary", {{"required", oj::array({"acceleration"})},
                                            {"properties", {{"acceleration", {{"const", false}}}}}}}}}}},
      {"else", {{"properties", {{"control_points", {{"minimum", 7}}}}}}}};
  // A designed segment is a named law's rise or return.
  oj& items = s["items"];
  if (!items.contains("allOf")) items["allOf"] = oj::array();
  items["allOf"].push_back({{"if", {{"required", oj::array({"law"})},
                                    {"properties", {{"law", {{"enum", {"dwell", "polynomial", "bspline"}}}}}}}},
                            {"then", {{"not", {{"required", oj::array({"optimize"})}}}}}});
  // At least one segment is designed.
  s["contains"] = {{"required", oj::array({"optimize"})}};
  return s;
}

nlohmann::ordered_json Input::SchemaRules() {
  using oj = nlohmann::ordered_json;
  const oj stiffness = {{"required", oj::array({"dynamics"})},
                        {"properties", {{"dynamics", {{"required", oj::array({"follower_stiffness_N_per_mm"})}}}}}};
  auto objective = [](const char* o) {
    return oj{{"required", oj::array({"objective"})}, {"properties", {{"objective", {{"const", o}}}}}};
  };
  return {{"allOf",
           oj::array({
               // The motion's unit by the follower's type (disc_cam's rule).
               disc_cam::FollowerMotionRules()[0],
               disc_cam::FollowerMotionRules()[1],
               // No flat face; an oscillating follower takes no follower loads (disc_cam's rule) nor a stroke in mm.
               {{"properties", {{"follower", {{"properties", {{"type", {{"not", {{"enum", {"translating_flat_faced",
                                                                                             "oscillating_flat_faced"}}}}}}}}}}}}},
               {{"if", disc_cam::FollowerTypeIs({"oscillating_roller", "oscillating_knife_edge"})},
                {"then", {{"allOf", oj::array({disc_cam::Refuse("dynamics"),
                                               {{"properties", {{"limits", disc_cam::Refuse("stroke_mm")}}}}})}}}},
               {{"if", disc_cam::FollowerTypeIs({"translating_knife_edge", "oscillating_knife_edge"})},
                {"then", {{"properties", {{"limits", disc_cam::Refuse("contact_stress_MPa")}}}}}},
               {{"if", disc_cam::FollowerTypeIs({"oscillating_roller", "oscillating_knife_edge"})},
                {"then", {{"properties", {{"limits", disc_cam::Refuse("contact_stress_MPa")}}}}}},
               {{"if", objective("residual_vibration")}, {"then", stiffness}},
               // peak_jerk: the designed segments C2 at their ends and of degree 3 at least.
               {{"if", objective("peak_jerk")},
                {"then",
                 {{"properties",
                   {{"motion",
                     {{"items",
                       {{"properties",
                         {{"optimize",
                           {{"properties",
                             {{"degree", {{"minimum", 3}}},
                              {"boundary", {{"properties", {{"acceleration", {{"const", true}}}}}}}}}}}}}}}}}}}}}},
               {{"if", objective("max_contact_force")}, {"then", {{"required", oj::array({"dynamics"})}}}},
               {{"if", {{"required", oj::array({"limits"})},
                        {"properties", {{"limits", {{"required", oj::array({"no_separation_up_to_rpm"})}}}}}}},
                {"then", stiffness}},
               {{"if", {{"required", oj::array({"analysis"})},
                        {"properties", {{"analysis", {{"required", oj::array({"residual_speeds_rpm"})}}}}}}},
                {"then", objective("residual_vibration")}},
               {{"properties", {{"dynamics", {{"properties", {{"damping_ratio", {{"exclusiveMaximum", 1}}}}}}}}}},
               // The contact-stress limit needs the contact's length, the material and the loads.
               {{"if", {{"required", oj::array({"limits"})},
                        {"properties", {{"limits", {{"required", oj::array({"contact_stress_MPa"})}}}}}}},
                {"then", {{"required", oj::array({"face_width_mm", "material", "dynamics"})}}}},
           })}};
}

Study Parse(const Node& root) {
  const Input in = Read<Input>(root);
  Study s;
  s.name = in.name;
  // The design as a disc_cam study: the kind's own fields out, the designed segments' "optimize"
  // out, the limits disc_cam knows.
  if (!root.json()["motion"].is_array()) root["motion"].Fail("an array of motion segments");
  for (size_t i = 0; i < root.json()["motion"].size(); ++i) {
    const Node seg = root["motion"][i];
    if (!seg.json().is_object() || !seg.Has("optimize")) continue;
    const Node opt = seg["optimize"];
    opt.CheckKnownFields({"law", "control_points", "degree", "boundary"});
    if (!opt.Has("law") || opt["law"].String() != "bspline") opt["law"].Fail("\"bspline\" (the designed shape's law)");
    if (opt.Has("degree") && opt["degree"].Integer(2) > 7) opt["degree"].Fail("a whole number in [2, 7]");
    if (opt["control_points"].Integer(5) > 35) opt["control_points"].Fail("a whole number in [5, 35]");
    if (opt.Has("boundary")) opt["boundary"].CheckKnownFields({"velocity", "acceleration"});
  }
  nlohmann::json d = root.json();
  for (const char* k : {"objective", "optimizer", "analysis"}) d.erase(k);
  d["study"] = "disc_cam";
  if (d.contains("limits") && d["limits"].is_object()) {
    d["limits"].erase("stroke_mm");
    d["limits"].erase("no_separation_up_to_rpm");
  }
  std::vector<int> designed;
  for (size_t i = 0; i < d["motion"].size(); ++i)
    if (d["motion"][i].is_object() && d["motion"][i].contains("optimize")) {
      designed.push_back(int(i));
      d["motion"][i].erase("optimize");
    }
  s.base_json = d;
  {
    nlohmann::json checked = d;
    checked["analysis"] = {{"monte_carlo", false}, {"evaluate", {"profile"}}};
    s.base = disc_cam::Parse(Node(&checked, root.file(), root.path()));
  }
  if (s.base.contact == disc_cam::Study::Contact::kFlatFaced)
    root["follower"]["type"].FailWith(
        "disc_cam_motion designs the motion of a roller or knife-edge follower (translating or oscillating); a flat "
        "face is not supported: use a roller, or study \"disc_cam\" to analyse the flat-faced design");
  const bool oscillating = s.base.cam.follower == dc::FollowerType::kOscillatingRoller;
  s.follower_unit = oscillating ? "deg" : "mm";
  if (designed.empty())
    root["motion"].FailWith("no segment is designed: mark one or more moving segments with \"optimize\": {\"law\": "
                            "\"bspline\", \"control_points\": 10}");
  objectives::DiscCamMotionSpec& spec = s.spec;
  spec.cam = s.base.cam;
  const size_t count = s.base.cam.motion.segments().size();
  for (int i : designed) {
    const auto& ms = s.base.cam.motion.segments()[size_t(i)];
    if (ms.law == motion::MotionLaw::kDwell || ms.law == motion::MotionLaw::kBSpline ||
        ms.law == motion::MotionLaw::kPolynomial || ms.rise == 0.0)
      root["motion"][size_t(i)]["optimize"].FailWith(
          "a designed segment is a rise or return of a named law (its rise and cam angle are kept, the law is the "
          "start): not a dwell, a polynomial or a B-spline");
  }
  for (int i : designed) {
    const Node opt = root["motion"][size_t(i)]["optimize"];
    for (int j : designed)
      if (j != i && (size_t(j) == (size_t(i) + 1) % count || size_t(i) == (size_t(j) + 1) % count))
        opt.FailWith("next to another designed segment (motion/" + std::to_string(j) +
                     "): a designed segment meets fixed neighbours, whose velocity and acceleration it matches");
    objectives::OptimizedSegment o;
    o.segment = i;
    o.control_points = opt["control_points"].Integer(5);
    o.degree = opt.IntegerOr("degree", 2, 5);
    if (opt.Has("boundary")) {
      if (!opt["boundary"].BoolOr("velocity", true))
        opt["boundary"]["velocity"].FailWith("the velocity is always matched (the follower model needs a C1 program): "
                                             "true, or leave it out");
      o.acceleration = opt["boundary"].BoolOr("acceleration", true);
    }
    if (o.degree >= o.control_points)
      opt["degree"].FailWith("a degree below control_points (" + std::to_string(o.control_points) + "), found " +
                             std::to_string(o.degree));
    const int fixed = 2 + 2 * (o.acceleration ? 2 : 1);
    if (o.control_points - fixed < 1)
      opt["control_points"].FailWith("at least " + std::to_string(fixed + 1) + " control points (" +
                                     std::to_string(fixed) + " are fixed by the ends' position, velocity" +
                                     (o.acceleration ? " and acceleration" : "") + "), found " +
                                     std::to_string(o.control_points));
    spec.segments.push_back(o);
  }
  int free = 0;
  for (const auto& o : spec.segments) free += o.control_points - 2 - 2 * (o.acceleration ? 2 : 1);
  if (free > kMaxFree)
    root["motion"].FailWith("at most " + std::to_string(kMaxFree) + " free control values over the designed segments, "
                            "found " + std::to_string(free) + ": fewer control_points");
  // The start: each designed segment as the B-spline through its own law at the Greville abscissae.
  {
    const std::vector<double> x0 = objectives::StartControls(spec);
    spec.cam = objectives::MotionDesign(spec, x0);
  }
  // Objective and what it needs.
  const std::string obj = in.objective;
  if (obj == "peak_jerk")
    for (const auto& o : spec.segments) {
      const Node opt = root["motion"][size_t(o.segment)]["optimize"];
      if (!o.acceleration)
        opt["boundary"]["acceleration"].FailWith("peak_jerk needs the acceleration matched at the ends (an acceleration "
                                                 "jump is an infinite jerk): true, or leave it out");
      if (o.degree < 3)
        opt["degree"].FailWith("peak_jerk needs a degree of at least 3 (a B-spline of degree p has p − 1 continuous "
                               "derivatives: the jerk is finite from 3 up), found " + std::to_string(o.degree));
    }
  spec.objective = obj == "peak_acceleration" ? MotionObjective::kPeakAcceleration
                   : obj == "peak_jerk"       ? MotionObjective::kPeakJerk
                   : obj == "residual_vibration" ? MotionObjective::kResidualVibration
                                                 : MotionObjective::kMaxContactForce;
  const bool stiff = s.base.dynamics && s.base.dynamics->follower_stiffness_N_per_mm;
  if (s.base.dynamics) {
    spec.speed_rpm = s.base.dynamics->speed_rpm;
    spec.loads = s.base.dynamics->loads;
    spec.revolutions = s.base.dynamics->revolutions;
    if (stiff) {
      dc::ContactFollower f;
      f.loads = s.base.dynamics->loads;
      f.follower_stiffness_N_per_mm = *s.base.dynamics->follower_stiffness_N_per_mm;
      f.damping_ratio = s.base.dynamics->damping_ratio;
      if (!(f.damping_ratio < 1.0))
        root["dynamics"]["damping_ratio"].FailWith("below 1 (an underdamped follower) for disc_cam_motion");
      spec.follower = f;
    }
  }
  if (spec.objective == MotionObjective::kResidualVibration) {
    if (!stiff)
      root["objective"].FailWith("residual_vibration needs the follower's dynamics: dynamics.follower_stiffness_N_per_mm "
                                 "(with speed_rpm, follower_mass_kg)");
    bool dwell = false;
    for (const auto& o : spec.segments) {
      const auto& next = spec.cam.motion.segments()[(size_t(o.segment) + 1) % count];
      dwell = dwell || next.law == motion::MotionLaw::kDwell;
    }
    if (!dwell)
      root["objective"].FailWith("residual_vibration is the vibration a designed segment leaves in the dwell after it: "
                                 "no designed segment is followed by a dwell");
  }
  if (spec.objective == MotionObjective::kMaxContactForce && !s.base.dynamics)
    root["objective"].FailWith("max_contact_force needs the follower's loads: a \"dynamics\" block");
  if (in.analysis.residual_speeds_rpm) {
    const auto [lo, hi, n] = *in.analysis.residual_speeds_rpm;
    const Node band = root["analysis"]["residual_speeds_rpm"];
    if (!(lo <= hi)) band.Fail("[lowest, highest, count] with lowest <= highest");
    if (!(n >= 1 && n <= 64 && n == std::floor(n))) band[2].Fail("a whole number of speeds in [1, 64]");
    if (spec.objective != MotionObjective::kResidualVibration)
      band.FailWith("only with objective residual_vibration");
    for (int k = 0; k < int(n); ++k) spec.objective_speeds_rpm.push_back(n == 1 ? lo : lo + (hi - lo) * k / (n - 1));
  } else if (spec.objective == MotionObjective::kResidualVibration) {
    spec.objective_speeds_rpm = {spec.speed_rpm};
  }
  // Limits.
  spec.pressure_angle_deg = s.base.limits.pressure_angle_deg;
  const bool knife = s.base.contact == disc_cam::Study::Contact::kKnifeEdge;
  spec.radius_margin_is_roller = s.base.limits.radius_margin_default && !knife;
  spec.radius_margin_mm = spec.radius_margin_is_roller ? 0.0 : s.base.limits.radius_margin_mm;
  if (s.base.limits.contact_stress_MPa) {
    // disc_cam::Parse has checked that face width, material and the loads are there.
    if (oscillating)
      root["limits"]["contact_stress_MPa"].FailWith("a translating roller follower only (its loads are dynamics')");
    spec.contact_stress_MPa = *s.base.limits.contact_stress_MPa;
    spec.face_width_mm = *s.base.face_width_mm;
    spec.composite_modulus_MPa = s.base.material->composite_modulus_MPa();
  }
  if (in.limits) {
    if (in.limits->stroke_mm) {
      if (oscillating) root["limits"]["stroke_mm"].FailWith("a translating follower only (its unit is mm)");
      spec.stroke_mm = *in.limits->stroke_mm;
    }
    if (in.limits->no_separation_up_to_rpm) {
      if (!stiff)
        root["limits"]["no_separation_up_to_rpm"].FailWith(
            "needs the follower's dynamics: dynamics.follower_stiffness_N_per_mm");
      spec.no_separation_up_to_rpm = *in.limits->no_separation_up_to_rpm;
    }
  }
  spec.separation_speeds = in.analysis.separation_speeds;
  spec.angle_steps = in.analysis.angle_steps;
  spec.accurate_factor = in.analysis.accurate_factor;
  // The dynamic rows' RK4 grid follows the follower's natural frequency: refuse a follower whose
  // grid no run could afford (a stiff train on a feather-light mass, or a crawling cam).
  if (spec.follower) {
    const int steps = objectives::ContactStepsPerRevolution(spec);
    if (steps > 200000)
      root["dynamics"].FailWith(
          "the follower's natural frequency " + Format(spec.follower->NaturalFrequencyRadS() / (2 * kPi), 4) +
          " Hz needs " + Format(double(steps), 3) + " RK4 steps a revolution (64 a natural period at the highest "
          "speed, 8 at the lowest), at most 200000: a heavier follower_mass_kg, a softer follower_stiffness_N_per_mm, "
          "or higher speeds");
  }
  s.backend = optimizers::ToString(ToBackend(in.optimizer.backend));
  optimizers::SolverOptions& so = s.options.solver;
  so.backend = ToBackend(s.backend);
  so.max_evaluations = in.optimizer.max_evaluations;
  so.tolerance = 1e-10;
  so.constraint_tolerance = 1e-7;
  so.max_seconds = 1e9;
  s.options.verify_rounds = in.optimizer.verify_rounds;
  return s;
}

Result Run(const Study& s, const RunContext& ctx) {
  Result r;
  Progress progress("disc_cam_motion", ctx.quiet);
  progress.Update(0.0, "solving");
  r.outcome = sizing::SolveDiscCamMotion(s.spec, s.options, s.base.cam);
  progress.Update(1.0);
  progress.Done();
  const auto& o = r.outcome;
  if (o.x.empty()) {
    r.blocking_message = "the optimizer ended without a design (" + o.result.message +
                         "); relax the limits or give more control points";
  } else if (!std::isfinite(o.check.objective)) {
    r.blocking_message = "the accurate model cannot evaluate the objective at the design: the follower leaves the cam "
                         "(in the dwell after a designed segment, for the residual vibration); add "
                         "limits.no_separation_up_to_rpm, or raise the spring's preload or rate";
  } else if (!o.verified) {
    const objectives::VerifiedLimit* w = o.verification.worst();
    r.blocking_message = w ? "the design is not verified: " + w->limit + " (" + w->where + ") is " +
                                 Format(w->accurate_value, 6) + " against the limit " + Format(w->limit_value, 6) +
                                 " on the accurate model; relax the limit, give more control points or more "
                                 "optimizer.verify_rounds"
                           : "the design is not verified";
  } else if (!o.converged) {
    r.blocking_message = "the optimizer did not converge (" + std::string(optimizers::ToString(o.result.status)) +
                         ", " + o.result.message + "): the design meets the limits but is not known to be optimal; "
                         "give more optimizer.max_evaluations";
  }
  FillResult(s, r);
  return r;
}

nlohmann::json MotionJson(const Study& s, const dc::DiscCam& cam) {
  nlohmann::json m = s.base_json["motion"];
  const double unit = s.follower_unit == "deg" ? 1.0 / kDeg : 1.0;
  double start = 0;
  const auto& segs = cam.motion.segments();
  for (size_t i = 0; i < segs.size(); ++i) {
    for (const auto& o : s.spec.segments) {
      if (size_t(o.segment) != i) continue;
      nlohmann::json pts = nlohmann::json::array();
      for (double c : segs[i].coefficients) pts.push_back((start + c) * unit);
      m[i] = {{"law", "bspline"},
              {"cam_angle_deg", s.base_json["motion"][i]["cam_angle_deg"]},
              {"degree", segs[i].spline_degree},
              {"control_points_" + s.follower_unit, pts}};
    }
    start += segs[i].rise;
  }
  return m;
}

namespace {

// A program's accurate check: its members of best and of start.
void FillCheck(const objectives::MotionAccurate& a, Result::Check& c) {
  c.objective = a.objective;
  c.estimated_error = a.objective_error;
  c.fast_value = a.objective_fast;
  c.at_cam_angle_deg = a.objective_at_deg;
  c.where = a.objective_where;
  if (!a.residuals.empty()) {
    std::vector<Result::Residual>& rs = c.residual_vibration.emplace();
    for (const auto& r : a.residuals) rs.push_back({r.segment, r.speed_rpm, r.amplitude_mm, r.error_mm});
  }
}

}  // namespace

namespace {

// The residual-vibration spectrum (model/disc_cam/residual_spectrum.h) of each designed segment, its
// start law's and the designed one's, against τ = segment time / natural period, with the τ of each
// objective speed marked: the classic chart, for the law as it was and as designed.
struct SpectrumOf {
  std::vector<double> tau;
  struct Segment {
    int index;
    std::string start_law;
    std::vector<double> start, designed;
    std::vector<double> tau_at, start_at, designed_at;  ///< at each speed (the study's, or the band's)
  };
  std::vector<Segment> segments;
};

SpectrumOf Spectrum(const Study& s, const sizing::DiscCamMotionOutcome& o) {
  SpectrumOf sp;
  const double fn = s.spec.follower->NaturalFrequencyRadS() / (2 * kPi), zeta = s.spec.follower->damping_ratio;
  std::vector<double> speeds = s.spec.objective_speeds_rpm;
  if (speeds.empty()) speeds = {s.spec.speed_rpm};
  double hi = 10.0;
  for (const auto& g : s.spec.segments)
    for (double rpm : speeds)
      hi = std::max(hi, 1.5 * s.spec.cam.motion.segments()[size_t(g.segment)].duration / (2 * kPi) / (rpm / 60.0) * fn);
  const int n = 381;
  for (int i = 0; i < n; ++i) sp.tau.push_back(0.5 + (hi - 0.5) * i / (n - 1));
  for (const auto& g : s.spec.segments) {
    const auto& start = s.base.cam.motion.segments()[size_t(g.segment)];
    const auto& designed = o.cam.motion.segments()[size_t(g.segment)];
    SpectrumOf::Segment seg{g.segment, motion::LawName(start.law), dc::ResidualSpectrum(start, zeta, sp.tau),
                            dc::ResidualSpectrum(designed, zeta, sp.tau), {}, {}, {}};
    for (double rpm : speeds) {
      const double tau = start.duration / (2 * kPi) / (rpm / 60.0) * fn;
      seg.tau_at.push_back(tau);
      seg.start_at.push_back(dc::ResidualAmplitudeAt(start, zeta, tau).amplitude);
      seg.designed_at.push_back(dc::ResidualAmplitudeAt(designed, zeta, tau).amplitude);
    }
    sp.segments.push_back(std::move(seg));
  }
  return sp;
}

void AddSpectrum(const Study& s, const sizing::DiscCamMotionOutcome& o, Outputs& out) {
  const SpectrumOf sp = Spectrum(s, o);
  Table t;
  t.Add("tau", sp.tau);
  std::vector<Series> curves;
  PlotOptions po;
  for (const auto& g : sp.segments) {
    const std::string k = std::to_string(g.index);
    t.Add("start_amplitude_per_rise_segment_" + k, g.start);
    t.Add("designed_amplitude_per_rise_segment_" + k, g.designed);
    curves.push_back(Series{"segment " + k + ", start (" + g.start_law + ")", sp.tau, g.start});
    curves.push_back(Series{"segment " + k + ", designed", sp.tau, g.designed});
    for (size_t j = 0; j < g.tau_at.size(); ++j)
      po.points.push_back({"segment " + k + " designed at " + Format(s.spec.objective_speeds_rpm.empty()
                                                                        ? s.spec.speed_rpm
                                                                        : s.spec.objective_speeds_rpm[j]) +
                               " rpm, τ = " + Format(g.tau_at[j]),
                           g.tau_at[j], g.designed_at[j]});
  }
  out.Add("residual_spectrum.csv", ToCsv(t));
  po.title = s.name + ": residual-vibration spectrum (one segment from rest), start and designed (ζ = " +
             Format(s.spec.follower->damping_ratio) + ")";
  po.x_label = "τ = segment time / natural period";
  po.y_label = "residual amplitude / rise";
  out.Add("residual_spectrum.svg", SvgLinePlot(curves, po));
}

}  // namespace

namespace {

// result.json's members (Result's Serialize) from the design's outcome.
void FillResult(const Study& s, Result& r) {
  const sizing::DiscCamMotionOutcome& o = r.outcome;
  const std::string unit = objectives::MotionObjectiveUnit(s.spec.objective, s.follower_unit == "deg" ? "rad" : "mm");
  r.name = s.name;
  r.follower = s.base.in.follower.type;
  r.objective.name = objectives::MotionObjectiveName(s.spec.objective);
  r.objective.unit = unit;
  if (!s.spec.objective_speeds_rpm.empty()) r.objective.speeds_rpm = s.spec.objective_speeds_rpm;
  for (const auto& seg : s.spec.segments)
    r.designed_segments.push_back({seg.segment,
                                   motion::LawName(s.base.cam.motion.segments()[size_t(seg.segment)].law),
                                   seg.control_points,
                                   seg.degree,
                                   {true, seg.acceleration}});
  r.limits.pressure_angle_deg = s.spec.pressure_angle_deg;
  r.limits.radius_margin_mm =
      s.spec.radius_margin_mm + (s.spec.radius_margin_is_roller ? s.spec.cam.roller_radius : 0.0);
  r.limits.stroke_mm = s.spec.stroke_mm;
  r.limits.contact_stress_MPa = s.spec.contact_stress_MPa;
  r.limits.no_separation_up_to_rpm = s.spec.no_separation_up_to_rpm;
  r.verification = VerificationBlock::Of(o.verification);
  r.verified = o.verified;
  if (!o.x.empty()) {
    Result::Best& b = r.best.emplace();
    FillCheck(o.check, b);
    b.motion = MotionJson(s, o.cam);
    if (s.spec.follower) {
      Result::ResidualSpectrum& sp = b.residual_spectrum.emplace();
      sp.model =
          "the classic chart (model/disc_cam/residual_spectrum.h): one segment from rest, base-excited, damping on "
          "the relative motion; exact for the study's follower when damping_ratio is 0, otherwise without the "
          "return spring's share of the damper (a term (1 - r) c S', r = k_f/(k_f + k_s)) and without the vibration "
          "earlier segments leave: best.objective is the whole program's response, verified by CVODE";
      for (const auto& g : Spectrum(s, o).segments)
        sp.segments.push_back({g.index, g.start_law, g.tau_at, g.start_at, g.designed_at});
    }
    // null (NaN): no separation seen up to the limit.
    if (s.spec.no_separation_up_to_rpm)
      b.lowest_separation_rpm = o.check.lowest_separation_rpm > 0 ? o.check.lowest_separation_rpm : NAN;
  }
  FillCheck(o.start, r.start);
  for (const auto& seg : s.spec.segments)
    r.start.laws.push_back(motion::LawName(s.base.cam.motion.segments()[size_t(seg.segment)].law));
  double best_named = kInf;
  std::string best_named_law;
  for (const auto& n : o.named_laws) {
    r.named_laws.push_back({n.segment, n.law, n.value, n.error, std::nullopt});
    if (!std::isfinite(n.value))
      r.named_laws.back().note = "infinite: the law's acceleration jumps (inside it or against a dwell), so does its jerk";
    if (std::isfinite(n.value) && n.value < best_named) best_named = n.value, best_named_law = n.law;
  }
  if (!o.x.empty() && std::isfinite(best_named)) {
    r.best_named_law = Result::BestNamedLaw{best_named_law, best_named};
    // Beats it when the accurate values differ by more than both errors together.
    double err = 0;
    for (const auto& n : o.named_laws)
      if (n.law == best_named_law) err = std::max(err, n.error);
    r.beats_every_named_law = o.check.objective + o.check.objective_error + err < best_named;
  }
  Result::Optimizer& opt = r.optimizer;
  opt.Set(s.backend, o.converged, o.result, s.options.solver.max_evaluations, s.options.verify_rounds,
          o.result.value_evaluations, o.result.gradient_evaluations);
  opt.max_violation = o.result.max_violation;
  opt.rounds = o.rounds;
  opt.gradient_method =
      "exact: forward-mode differentiation of the rows (the dynamic rows: forward sensitivities of the "
      "held-on follower's ODE through its RK4 steps)";
  r.analysis = {s.spec.angle_steps, s.spec.accurate_factor, s.spec.angle_steps * s.spec.accurate_factor};
  if (!r.blocking_message.empty()) r.notes = std::vector<std::string>{r.blocking_message};
}

}  // namespace

void Write(const Study& s, const Result& r, Outputs& out) {
  out.SetResult(r);
  const sizing::DiscCamMotionOutcome& o = r.outcome;
  out.SetStatus(SizingStatus(!o.x.empty(), o.verification.ran, o.verified, o.converged), r.blocking_message);
  if (o.x.empty()) return;
  nlohmann::json best = s.base_json;
  best["name"] = (o.verified ? "designed motion of " : "closest motion (not verified) of ") + s.name;
  best["motion"] = MotionJson(s, o.cam);
  best["analysis"] = {{"angle_steps", std::min(1000000, s.spec.angle_steps * s.spec.accurate_factor)},
                      {"monte_carlo", false}};
  out.AddJson("best_disc_cam.json", best);
  // SVAJ of the designed program against the study's own laws, on the accurate grid.
  const int n = s.spec.angle_steps * s.spec.accurate_factor;
  const double unit = s.follower_unit == "deg" ? 1.0 / kDeg : 1.0;
  const size_t m = static_cast<size_t>(n);
  std::vector<double> th(m), sb(m), vb(m), ab(m), jb(m), ss(m), as(m);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * i / n;
    const motion::Svaj<double> b = o.cam.motion.Evaluate(t), st = s.base.cam.motion.Evaluate(t);
    th[size_t(i)] = 360.0 * i / n;
    sb[size_t(i)] = b.s * unit, vb[size_t(i)] = b.v * unit, ab[size_t(i)] = b.a * unit, jb[size_t(i)] = b.j * unit;
    ss[size_t(i)] = st.s * unit, as[size_t(i)] = st.a * unit;
  }
  Table t;
  t.Add("cam_angle_deg", th);
  t.Add("follower_" + s.follower_unit, sb);
  t.Add("velocity_" + s.follower_unit + "_per_rad", vb);
  t.Add("acceleration_" + s.follower_unit + "_per_rad2", ab);
  t.Add("jerk_" + s.follower_unit + "_per_rad3", jb);
  t.Add("start_follower_" + s.follower_unit, ss);
  t.Add("start_acceleration_" + s.follower_unit + "_per_rad2", as);
  out.Add("svaj.csv", ToCsv(t));
  PlotOptions po;
  po.title = s.name + ": acceleration of the designed program and of the start laws";
  po.x_label = "cam angle [deg]";
  po.y_label = "S'' [" + s.follower_unit + "/rad²]";
  out.Add("acceleration.svg", SvgLinePlot({{"designed", th, ab}, {"start laws", th, as}}, po));
  if (s.spec.follower) AddSpectrum(s, o, out);
}

namespace {

std::string Summary(const Study& s, const Result& r) {
  const sizing::DiscCamMotionOutcome& o = r.outcome;
  std::ostringstream m;
  if (o.x.empty()) return "disc_cam_motion: no design\n";
  m << "disc_cam_motion: " << objectives::MotionObjectiveName(s.spec.objective) << " " << Format(o.check.objective, 6)
    << " ± " << Format(o.check.objective_error, 2) << " "
    << objectives::MotionObjectiveUnit(s.spec.objective, s.follower_unit == "deg" ? "rad" : "mm") << " (start "
    << Format(o.start.objective, 6) << ")" << (o.verified ? ", verified" : ", not verified") << "\n";
  return m.str();
}

Fidelity Knobs(const nlohmann::json&) {
  const Input defaults;
  Fidelity f;
  f.knobs.push_back({"angle_steps", {"/analysis/angle_steps"}, defaults.analysis.angle_steps, 2, true, 0,
                     "cam angles of the fast rows (the accurate grid is accurate_factor times as fine)"});
  f.headlines = {"/best/objective"};
  return f;
}

// The work limit: every solve's iterations × the rows (the dynamic ones: RK4 steps × speeds), and
// the accurate checks (CVODE runs).
WorkEstimate EstimateWork(const nlohmann::json& study, const std::string& file, double factor) {
  const Input in = Read<Input>(Node(&study, file, ""));
  const double steps = in.analysis.angle_steps, budget = std::max(1, in.optimizer.max_evaluations);
  const double solves = 1 + in.optimizer.verify_rounds;
  return LargestTerm({{budget * solves * 3 * steps * 8, "/optimizer/max_evaluations",
                       WorkNumber(budget) + " iterations × " + WorkNumber(solves) + " solves × 3 evaluations × " +
                           WorkNumber(steps) + " angle steps × 8 speeds"},
                      {solves * 10 * steps * in.analysis.accurate_factor, "/analysis/accurate_factor",
                       WorkNumber(solves) + " accurate checks × 10 × " +
                           WorkNumber(steps * in.analysis.accurate_factor) + " cam angles"}},
                     1e9 * factor, "cam angle evaluations", 16);
}

CAMOPT_REGISTER_KIND(Kind<Input, Result, Study>{
    .name = "disc_cam_motion",
    .title = "camopt study: the shape of a disc cam's rises designed for the least peak acceleration, "
              "jerk, residual vibration or contact force",
    .run = Run, .parse = Parse, .write = Write, .summary = Summary, .knobs = Knobs, .estimate = EstimateWork,
    .report = std::vector<Headline>{
        {"objective (accurate)", "/best/objective", "", "", NAN, true, "/best/estimated_error"},
        {"objective of the start laws (accurate)", "/start/objective", ""},
        {"objective of the best named law", "/best_named_law/objective", ""},
        {"beats every named law", "/beats_every_named_law", ""},
        {"verified", "/verified", ""},
    },
    .init_example = "disc_cam_motion"});
}  // namespace

}  // namespace camopt::studies::disc_cam_motion
