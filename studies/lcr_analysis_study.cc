// Study kind "lcr_analysis": analyse one lobe cam reducer over an input revolution.
// Stages run only as the study asks ("analysis.evaluate"): profile, undercut, forces, stress,
// efficiency. Outputs: result.json, series.csv, SVG plots and drawings, DXF profiles with cutter paths.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <set>

#include "model/lcr/cycle.h"
#include "studies/lcr_input.h"
#include "studies/study.h"
#include "studies/writers.h"

namespace camopt::studies {
namespace {

using lcr::Side;

double Max(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }
double Min(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }
double Mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / v.size(); }
template <typename I>
int MaxI(const std::vector<I>& v) { return *std::max_element(v.begin(), v.end()); }
template <typename I>
int MinI(const std::vector<I>& v) { return *std::min_element(v.begin(), v.end()); }

struct Request {
  bool profile = true, undercut = true, forces = true, stress = true, efficiency = true;
};

Request ParseEvaluate(const Node& analysis) {
  Request q;
  if (!analysis.Has("evaluate")) return q;
  q = {false, false, false, false, false};
  const std::set<std::string> known = {"profile", "undercut", "forces", "stress", "efficiency"};
  for (const Node& n : analysis["evaluate"].Elements()) {
    const std::string s = n.String();
    if (!known.count(s)) n.Fail("one of profile, undercut, forces, stress, efficiency");
    if (s == "profile") q.profile = true;
    if (s == "undercut") q.undercut = true;
    if (s == "forces") q.forces = true;
    if (s == "stress") q.stress = q.forces = true;
    if (s == "efficiency") q.efficiency = q.forces = true;
  }
  return q;
}

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
  Drawing::Layer cutter{"CUTTER_PATH", "#d62728", {}, {}, true, 0.7};
  profile.polylines.push_back(ToPolyline(lcr::SampleCurve(c, r.eccentricity, c.roller_radius, points)));
  pitch.polylines.push_back(ToPolyline(lcr::SampleCurve(c, r.eccentricity, 0.0, points)));
  cutter.polylines.push_back(
      ToPolyline(lcr::SampleCurve(c, r.eccentricity, c.roller_radius - cutter_radius, points)));
  d.layers = {profile, pitch, cutter};
  return d;
}

// Assembled view at input angle 0: the cam (centre at e u(0), not yet turned) with its rollers,
// loaded rollers in red.
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
  }
  axes.circles.push_back({0.0, 0.0, 0.6});
  axes.circles.push_back({centre.x(), centre.y(), 0.6});
  d.layers = {cam, free_rollers, loaded, axes};
  return d;
}

void RunLcrAnalysis(const Node& root, const RunContext& ctx, Outputs& out) {
  root.CheckKnownFields({"study", "name", "description", "reducer", "material", "load", "limits", "analysis"});
  const lcr::Reducer<double> r = ParseReducer(root["reducer"]);
  root["material"].CheckKnownFields({"youngs_modulus_GPa", "poisson_ratio"});
  const lcr::Material material = ParseMaterial(root["material"]);
  const Node load_node = root["load"];
  load_node.CheckKnownFields({"output_torque_Nm", "friction_coefficient", "cam_weight_N"});
  lcr::LoadCase load;
  load.output_torque_Nmm = load_node["output_torque_Nm"].NonNegative() * 1000.0;
  load.friction_coefficient = load_node.NonNegativeOr("friction_coefficient", 0.0);
  load.cam_weight_N = load_node.NonNegativeOr("cam_weight_N", 0.0);
  const Node analysis = root.Has("analysis") ? root["analysis"] : root;
  if (root.Has("analysis")) analysis.CheckKnownFields({"angle_steps", "profile_points", "evaluate"});
  const int steps = root.Has("analysis") ? analysis.IntegerOr("angle_steps", 12, 3600) : 3600;
  const int points = root.Has("analysis") ? analysis.IntegerOr("profile_points", 100, 3600) : 3600;
  const Request q = root.Has("analysis") ? ParseEvaluate(analysis) : Request{};
  double stress_limit = kInf, force_limit = kInf;
  if (root.Has("limits")) {
    root["limits"].CheckKnownFields({"contact_stress_MPa", "roller_load_N"});
    stress_limit = root["limits"].PositiveOr("contact_stress_MPa", kInf);
    force_limit = root["limits"].PositiveOr("roller_load_N", kInf);
  }
  const Node reducer_node = root["reducer"];
  const double cutter_a = ParseCutterDiameter(reducer_node["input"], 2 * r.input.roller_radius) / 2;
  const double cutter_b = ParseCutterDiameter(reducer_node["output"], 2 * r.output.roller_radius) / 2;

  nlohmann::json res;
  res["study"] = "lcr_analysis";
  res["name"] = root.StringOr("name", "");
  res["speed_ratio"] = lcr::SpeedReductionRatio(r);
  res["cam_speed_ratio"] = lcr::CamSpeedRatio(r);
  res["output_speed_ratio"] = lcr::OutputSpeedRatio(r);
  res["outer_diameter_mm"] = lcr::OuterDiameter(r);
  res["angle_steps"] = steps;
  std::vector<std::string> notes;

  // Undercut: cheap and needed by the stress stage's validity.
  bool any_undercut = false;
  for (Side s : {Side::kInput, Side::kOutput}) {
    const auto& c = r.side(s);
    nlohmann::json& j = res[s == Side::kInput ? "input_cam" : "output_cam"];
    j["lobes"] = c.lobes;
    j["rollers"] = c.rollers;
    j["roller_gap_mm"] = lcr::RollerGap(c);
    j["pitch_point_radius_mm"] = r.eccentricity * c.pitch_factor();
    if (q.undercut || q.stress) {
      const double rho = lcr::MinConvexPitchRadius(c, r.eccentricity);
      const double margin = rho - c.roller_radius;
      const double cutter = s == Side::kInput ? cutter_a : cutter_b;
      j["min_pitch_curve_radius_mm"] = rho;
      j["min_convex_cam_radius_mm"] = margin;
      j["undercut_margin_mm"] = margin;
      j["undercut"] = margin < 0;
      j["cutter_diameter_mm"] = 2 * cutter;
      j["min_cutter_path_radius_mm"] = rho - (c.roller_radius - cutter);
      any_undercut = any_undercut || margin < 0;
    }
  }
  if (any_undercut)
    notes.push_back("undercut: the roller is larger than the smallest convex pitch-curve radius; "
                    "the cam cannot be cut to this profile and contact stresses are not valid");

  lcr::CycleSeries series;
  if (q.forces) {
    Progress progress("lcr_analysis", ctx.quiet);
    lcr::Stages stages{true, q.stress, q.efficiency};
    try {
      series = lcr::AnalyzeCycle(r, material, load, steps, stages,
                                 [&](double f) { progress.Update(f, std::to_string(steps) + " angles"); });
    } catch (const std::domain_error& e) {
      throw StudyError(ctx.study_file + ": /reducer: infeasible geometry: " + e.what());
    }
    progress.Done();
    for (Side s : {Side::kInput, Side::kOutput}) {
      const lcr::SideSeries& ss = s == Side::kInput ? series.input : series.output;
      nlohmann::json& j = res[s == Side::kInput ? "input_cam" : "output_cam"];
      j["actuating_rollers_max"] = MaxI(ss.actuating);
      j["actuating_rollers_min"] = MinI(ss.actuating);
      j["max_roller_force_N"] = Max(ss.max_force_N);
      if (std::isfinite(force_limit)) {
        j["roller_load_limit_N"] = force_limit;
        j["roller_load_ok"] = Max(ss.max_force_N) <= force_limit;
      }
      if (q.stress) {
        const double p = Max(ss.max_stress_MPa);
        if (std::isfinite(p)) {
          j["max_contact_stress_MPa"] = p;
          if (std::isfinite(stress_limit)) {
            j["contact_stress_limit_MPa"] = stress_limit;
            j["contact_stress_ok"] = p <= stress_limit;
          }
        } else {
          j["max_contact_stress_MPa"] = nullptr;  // a loaded roller sits on an undercut point
        }
        j["contact_length_mm"] = r.side(s).contact_length();
      }
    }
    res["fixed_turret_torque_Nm"] = Mean(series.input.turret_torque_Nmm) / 1000.0;
    res["output_torque_Nm"] = load.output_torque_Nmm / 1000.0;
    if (q.efficiency) {
      res["input_torque_Nm"] = {{"mean", Mean(series.input_torque_Nmm) / 1000},
                                {"max", Max(series.input_torque_Nmm) / 1000},
                                {"min", Min(series.input_torque_Nmm) / 1000},
                                {"ideal", load.output_torque_Nmm / std::abs(lcr::SpeedReductionRatio(r)) / 1000}};
      res["efficiency"] = {{"mean", Mean(series.efficiency)},
                           {"min", Min(series.efficiency)},
                           {"max", Max(series.efficiency)}};
      res["eccentric_load_N"] = {{"tangential_max", Max(series.tangential_force_N)},
                                 {"radial_max_abs", std::max(Max(series.radial_force_N), -Min(series.radial_force_N))}};
      res["friction_coefficient"] = load.friction_coefficient;
      if (load.output_torque_Nmm == 0)
        notes.push_back(load.cam_weight_N > 0
                            ? "zero output torque: efficiency is 0 (the cam weight still loads the eccentric)"
                            : "zero output torque: efficiency is its limit as the torque tends to 0 "
                              "(the model is linear in the torque)");
    }
    // CSV series.
    Table t;
    std::vector<double> deg(series.theta_rad.size());
    for (size_t i = 0; i < deg.size(); ++i) deg[i] = series.theta_rad[i] * 180 / kPi;
    t.Add("input_angle_deg", deg);
    auto as_double = [](const std::vector<int>& v) { return std::vector<double>(v.begin(), v.end()); };
    t.Add("input_actuating_rollers", as_double(series.input.actuating));
    t.Add("output_actuating_rollers", as_double(series.output.actuating));
    t.Add("input_max_roller_force_N", series.input.max_force_N);
    t.Add("output_max_roller_force_N", series.output.max_force_N);
    if (q.stress) {
      t.Add("input_max_contact_stress_MPa", series.input.max_stress_MPa);
      t.Add("output_max_contact_stress_MPa", series.output.max_stress_MPa);
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
    out.Add("forces.svg", SvgLinePlot({{"input cam (fixed turret)", deg, series.input.max_force_N},
                                       {"output cam (output turret)", deg, series.output.max_force_N}},
                                      {"Largest roller force over the input revolution", "input angle [deg]",
                                       "roller force [N]"}));
    if (q.stress && !any_undercut)
      out.Add("contact_stress.svg",
              SvgLinePlot({{"input cam", deg, series.input.max_stress_MPa},
                           {"output cam", deg, series.output.max_stress_MPa}},
                          {"Largest Hertz contact stress", "input angle [deg]", "contact stress [MPa]"}));
    if (q.efficiency)
      out.Add("efficiency.svg", SvgLinePlot({{"efficiency", deg, series.efficiency}},
                                            {"Efficiency (paper's friction model)", "input angle [deg]",
                                             "efficiency [-]"}));
  }

  if (q.profile) {
    std::optional<lcr::AngleLoads<double>> at_zero;
    if (q.forces) at_zero = lcr::AnalyzeAngle(r, material, load, 0.0, {true, false, false});
    for (Side s : {Side::kInput, Side::kOutput}) {
      const std::string which = s == Side::kInput ? "input" : "output";
      const double cutter = s == Side::kInput ? cutter_a : cutter_b;
      const Drawing cam = CamDrawing(r, s, cutter, points, which + " cam: profile, pitch curve, cutter path");
      out.Add(which + "_cam.dxf", ToDxf(cam));
      out.Add(which + "_cam.svg", SvgDrawing(cam));
      out.Add(which + "_assembly.svg",
              SvgDrawing(AssemblyDrawing(r, s, at_zero ? &*at_zero : nullptr, points,
                                         which + " cam and rollers at input angle 0 (loaded rollers red)")));
    }
  }
  res["notes"] = notes;
  out.AddJson("result.json", res);
}

CAMOPT_REGISTER_STUDY("lcr_analysis", RunLcrAnalysis);

}  // namespace
}  // namespace camopt::studies
