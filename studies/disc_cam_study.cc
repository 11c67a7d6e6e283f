// Study kind "disc_cam": a disc cam with an offset translating or an oscillating roller follower
// (Rzine et al., NOTES.md §2). Profile, pressure and shift angles, curvature and undercut over a
// cam revolution; the mechanical error from the tolerances (worst case and RMS, eqs. 31–32); a
// Monte-Carlo check of the linearised error against the exact follower motion.
// Outputs: result.json, series.csv, SVAJ / angle / error plots (SVG), profile.svg, profile.dxf.
#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>

#include "model/disc_cam/check.h"
#include "model/disc_cam/disc_cam.h"
#include "model/disc_cam/exact_motion.h"
#include "model/disc_cam/mechanical_error.h"
#include "model/motion/motion_program.h"
#include "studies/format.h"
#include "studies/motion_input.h"
#include "studies/study.h"
#include "studies/writers.h"

namespace camopt::studies {
namespace {

using disc_cam::CamPoint;
using disc_cam::DiscCam;
using disc_cam::FollowerType;
using motion::MotionLaw;

constexpr double kDeg = kPi / 180.0;

struct McRequest {
  bool enabled = true;
  disc_cam::MonteCarloOptions options;
};

struct DiscCamStudy {
  std::string name;
  DiscCam cam;
  disc_cam::Deviations<double> tolerances;  // mm
  int angle_steps = 3600;
  McRequest mc;
};

// The JSON path and message of a design issue (model units → the file's units).
[[noreturn]] void FailOn(const disc_cam::DesignIssue& issue, const DiscCam& cam, const Node& root) {
  using disc_cam::IssueKind;
  const bool osc = cam.follower == FollowerType::kOscillatingRoller;
  const double deg = issue.cam_angle_rad / kDeg;
  switch (issue.kind) {
    case IssueKind::kOffsetTooLarge:
      root["follower"]["offset_mm"].FailWith(
          "the offset " + Format(issue.value) +
          " mm must be smaller than base circle + roller radius (" + Format(issue.upper) + " mm)");
    case IssueKind::kArmCannotReach:
      root["follower"]["arm_length_mm"].FailWith(
          "the arm cannot reach the base circle: need |pivot distance − arm length| < base circle "
          "+ roller radius < pivot distance + arm length (" + Format(issue.lower) + " < " +
          Format(issue.value) + " < " + Format(issue.upper) + ")");
    case IssueKind::kInsideBaseCircle:
      root["motion"].FailWith("the follower goes inside the base circle at cam angle " +
                              Format(deg) + " deg (S = " +
                              Format(osc ? issue.value / kDeg : issue.value) +
                              (osc ? " deg)" : " mm)"));
    case IssueKind::kArmOutOfRange:
      root["motion"].FailWith("the follower arm leaves (0, 180) deg from the cam centre line at "
                              "cam angle " + Format(deg) + " deg");
    case IssueKind::kJams:
      root["motion"].FailWith("infeasible design: the pressure angle reaches " +
                              Format(issue.value / kDeg) + " deg at cam angle " + Format(deg) +
                              " deg (the follower would jam)");
  }
  root.FailWith("unknown design issue");
}

DiscCamStudy Parse(const Node& root) {
  root.CheckKnownFields({"study", "name", "description", "follower", "base_circle_radius_mm", "motion",
                         "tolerances", "analysis"});
  DiscCamStudy s;
  s.name = root.StringOr("name", "disc cam");
  DiscCam& cam = s.cam;

  const Node follower = root["follower"];
  const std::string type = follower["type"].String();
  if (type == "translating_roller") {
    follower.CheckKnownFields({"type", "offset_mm", "roller_radius_mm"});
    cam.follower = FollowerType::kTranslatingRoller;
    cam.offset = follower.NumberOr("offset_mm", 0.0);
  } else if (type == "oscillating_roller") {
    follower.CheckKnownFields({"type", "roller_radius_mm", "pivot_distance_mm", "arm_length_mm"});
    cam.follower = FollowerType::kOscillatingRoller;
    cam.pivot_distance = follower["pivot_distance_mm"].Positive();
    cam.arm_length = follower["arm_length_mm"].Positive();
  } else {
    follower["type"].Fail("\"translating_roller\" or \"oscillating_roller\"");
  }
  cam.roller_radius = follower["roller_radius_mm"].Positive();
  cam.base_radius = root["base_circle_radius_mm"].Positive();
  for (const auto& issue : disc_cam::CheckGeometry(cam)) FailOn(issue, cam, root);

  // Motion program: rise in mm (translating) or degrees (oscillating); durations in degrees.
  const bool oscillating = cam.follower == FollowerType::kOscillatingRoller;
  MotionInputSpec spec;
  spec.subject = "follower";
  if (oscillating) {
    spec.rise_key = "rise_deg", spec.rise_scale = kDeg, spec.unit = "deg";
    spec.misplaced_key = "rise_mm";
    spec.misplaced_hint = "a oscillating follower's rise is an angle: use rise_deg";
  } else {
    spec.rise_key = "rise_mm", spec.rise_scale = 1.0, spec.unit = "mm";
    spec.misplaced_key = "rise_deg";
    spec.misplaced_hint = "a translating follower's rise is a length: use rise_mm";
  }
  cam.motion = ParseMotionProgram(root["motion"], spec);

  if (root.Has("tolerances")) {
    const Node t = root["tolerances"];
    t.CheckKnownFields({"profile_radial_um", "roller_radius_um", "profile_normal_um"});
    s.tolerances.radial = t.NonNegativeOr("profile_radial_um", 0.0) * 1e-3;
    s.tolerances.roller = t.NonNegativeOr("roller_radius_um", 0.0) * 1e-3;
    s.tolerances.normal = t.NonNegativeOr("profile_normal_um", 0.0) * 1e-3;
  }
  if (root.Has("analysis")) {
    const Node a = root["analysis"];
    a.CheckKnownFields({"angle_steps", "monte_carlo"});
    s.angle_steps = a.IntegerOr("angle_steps", 36, 3600);
    if (s.angle_steps > 1000000) a["angle_steps"].Fail("a whole number <= 1000000");
    if (a.Has("monte_carlo")) {
      const Node m = a["monte_carlo"];
      if (m.json().is_boolean()) {
        s.mc.enabled = m.Bool();
      } else {
        m.CheckKnownFields({"samples", "angle_steps", "seed", "scales"});
        s.mc.options.samples = m.IntegerOr("samples", 1, s.mc.options.samples);
        s.mc.options.angle_steps = m.IntegerOr("angle_steps", 36, s.mc.options.angle_steps);
        s.mc.options.seed = static_cast<uint64_t>(m.IntegerOr("seed", 0, 1));
        if (m.Has("scales")) {
          s.mc.options.scales.clear();
          for (const Node& k : m["scales"].Elements()) s.mc.options.scales.push_back(k.Positive());
          if (s.mc.options.scales.empty()) m["scales"].Fail("a non-empty array of numbers > 0");
        }
        if (double(s.mc.options.samples) * s.mc.options.angle_steps * s.mc.options.scales.size() >
            1e8)
          m.FailWith("samples × angle_steps × scales must stay below 1e8");
      }
    }
  }
  if (s.tolerances.radial == 0 && s.tolerances.roller == 0 && s.tolerances.normal == 0)
    s.mc.enabled = false;
  return s;
}

// Cam-angle intervals [deg] where flag is set, on a uniform grid of n points over 360°.
nlohmann::json Intervals(const std::vector<bool>& flag) {
  nlohmann::json out = nlohmann::json::array();
  const size_t n = flag.size();
  for (size_t i = 0; i < n; ++i) {
    if (!flag[i] || (i > 0 && flag[i - 1])) continue;
    size_t j = i;
    while (j + 1 < n && flag[j + 1]) ++j;
    out.push_back({360.0 * i / n, 360.0 * j / n});
  }
  return out;
}

void Run(const Node& root, const RunContext& ctx, Outputs& out) {
  const DiscCamStudy s = Parse(root);
  const DiscCam& cam = s.cam;
  const bool osc = cam.follower == FollowerType::kOscillatingRoller;
  // Follower errors in µm at the roller centre: ΔS [mm] for a translating follower, l·Δξ for an
  // oscillating one (Δξ [rad] is reported separately in arc seconds).
  const double to_um = disc_cam::RollerCentreMmPerFollowerUnit(cam) * 1e3;
  const double to_arcsec = 180.0 / kPi * 3600.0;
  const int n = s.angle_steps;

  std::vector<CamPoint<double>> pts(n);
  std::vector<disc_cam::MechanicalError<double>> err(n);
  std::vector<double> jerk(n);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * i / n;
    pts[i] = disc_cam::EvaluateCam(cam, t);
    jerk[i] = cam.motion.Evaluate(t).j;
    err[i] = disc_cam::FollowerError(cam, pts[i], s.tolerances);
  }
  if (const auto issues = disc_cam::CheckDesign(cam, n); !issues.empty())
    FailOn(issues.front(), cam, root);

  auto arg_max = [&](auto f) {
    int best = 0;
    for (int i = 1; i < n; ++i)
      if (f(i) > f(best)) best = i;
    return best;
  };
  auto arg_min = [&](auto f) { return arg_max([&](int i) { return -f(i); }); };
  auto angle_deg = [&](int i) { return 360.0 * i / n; };

  nlohmann::json r;
  r["study"] = "disc_cam";
  r["name"] = s.name;
  r["follower"] = osc ? "oscillating_roller" : "translating_roller";
  r["angle_steps"] = n;
  const int i_rmax = arg_max([&](int i) { return pts[i].radial_dimension; });
  const int i_rmin = arg_min([&](int i) { return pts[i].radial_dimension; });
  r["max_radial_dimension_mm"] = pts[i_rmax].radial_dimension;
  r["max_radial_dimension_at_cam_angle_deg"] = angle_deg(i_rmax);
  r["min_radial_dimension_mm"] = pts[i_rmin].radial_dimension;
  const int i_pmax = arg_max([&](int i) { return pts[i].pressure_angle; });
  const int i_pmin = arg_min([&](int i) { return pts[i].pressure_angle; });
  r["pressure_angle_deg"] = {{"min", pts[i_pmin].pressure_angle / kDeg},
                             {"at_min_cam_angle_deg", angle_deg(i_pmin)},
                             {"max", pts[i_pmax].pressure_angle / kDeg},
                             {"at_max_cam_angle_deg", angle_deg(i_pmax)}};
  const int i_lmax = arg_max([&](int i) { return pts[i].shift_angle; });
  const int i_lmin = arg_min([&](int i) { return pts[i].shift_angle; });
  r["shift_angle_deg"] = {{"min", pts[i_lmin].shift_angle / kDeg},
                          {"max", pts[i_lmax].shift_angle / kDeg}};
  auto ratio = [&](int i) { return std::cos(pts[i].shift_angle) / std::cos(pts[i].pressure_angle); };
  r["cos_shift_over_cos_pressure"] = {{"min", ratio(arg_min(ratio))}, {"max", ratio(arg_max(ratio))}};

  // Curvature: the profile's radius where the pitch curve is convex, its magnitude where concave;
  // undercut where κ r_f > 1 (model/disc_cam/disc_cam.h).
  std::vector<bool> undercut(n);
  std::optional<double> min_convex, min_concave;
  std::optional<double> min_convex_at, min_concave_at;
  for (int i = 0; i < n; ++i) {
    const double k = pts[i].pitch_curvature;
    undercut[i] = disc_cam::IsUndercut(pts[i], cam.roller_radius);
    const double rho = disc_cam::ProfileRadiusOfCurvature(pts[i], cam.roller_radius);
    if (k > 0) {
      if (!min_convex || rho < *min_convex) min_convex = rho, min_convex_at = angle_deg(i);
    } else if (k < 0) {
      if (!min_concave || -rho < *min_concave) min_concave = -rho, min_concave_at = angle_deg(i);
    }
  }
  const bool any_undercut = std::find(undercut.begin(), undercut.end(), true) != undercut.end();
  r["min_radius_of_curvature_mm"] = min_convex ? nlohmann::json(*min_convex) : nlohmann::json();
  r["min_radius_of_curvature_at_cam_angle_deg"] =
      min_convex_at ? nlohmann::json(*min_convex_at) : nlohmann::json();
  r["min_concave_radius_of_curvature_mm"] =
      min_concave ? nlohmann::json(*min_concave) : nlohmann::json();
  r["min_concave_radius_at_cam_angle_deg"] =
      min_concave_at ? nlohmann::json(*min_concave_at) : nlohmann::json();
  r["undercut"] = any_undercut;
  r["undercut_cam_angle_deg"] = Intervals(undercut);

  // Mechanical error (eqs. 16–32).
  r["tolerances_um"] = {{"profile_radial", s.tolerances.radial * 1e3},
                        {"roller_radius", s.tolerances.roller * 1e3},
                        {"profile_normal", s.tolerances.normal * 1e3}};
  const int i_wor = arg_max([&](int i) { return err[i].worst_case; });
  const int i_rms = arg_max([&](int i) { return err[i].rms; });
  r["worst_case_error_um"] = {{"max", err[i_wor].worst_case * to_um},
                              {"at_cam_angle_deg", angle_deg(i_wor)},
                              {"min", err[arg_min([&](int i) { return err[i].worst_case; })].worst_case * to_um}};
  r["rms_error_um"] = {{"max", err[i_rms].rms * to_um}, {"at_cam_angle_deg", angle_deg(i_rms)}};
  auto component = [&](auto get) {
    const int a = arg_max(get), b = arg_min(get);
    return nlohmann::json{{"max", get(a) * to_um}, {"min", get(b) * to_um}};
  };
  r["error_components_um"] = {
      {"radial", component([&](int i) { return err[i].radial; })},
      {"roller", component([&](int i) { return err[i].roller; })},
      {"normal", component([&](int i) { return err[i].normal; })}};
  if (osc) {
    r["worst_case_error_arcsec"] = {{"max", err[i_wor].worst_case * to_arcsec},
                                    {"at_cam_angle_deg", angle_deg(i_wor)}};
    r["rms_error_arcsec"] = {{"max", err[i_rms].rms * to_arcsec}};
  }

  // Motion program: continuity at the joints and peak derivatives.
  const nlohmann::json joints = JointsJson(motion::CheckContinuity(cam.motion, 1e-7));
  const double unit = osc ? 1.0 / kDeg : 1.0;  // follower unit: mm or deg
  double vmax = 0, amax = 0, jmax = 0;
  for (int i = 0; i < n; ++i) {
    vmax = std::max(vmax, std::abs(pts[i].ds));
    amax = std::max(amax, std::abs(pts[i].d2s));
    jmax = std::max(jmax, std::abs(jerk[i]));
  }
  const std::string fu = osc ? "deg" : "mm";
  r["motion"] = {{"joints", joints},
                 {"peak_velocity_" + fu + "_per_rad", vmax * unit},
                 {"peak_acceleration_" + fu + "_per_rad2", amax * unit},
                 {"peak_jerk_" + fu + "_per_rad3", jmax * unit}};

  // Monte-Carlo check of the linearisation against the exact follower motion.
  if (s.mc.enabled && !any_undercut) {
    Progress progress("disc_cam monte carlo", ctx.quiet);
    std::vector<disc_cam::MonteCarloScale> mc;
    for (size_t k = 0; k < s.mc.options.scales.size(); ++k) {
      progress.Update(double(k) / s.mc.options.scales.size(),
                      "tolerance scale " + Format(s.mc.options.scales[k]));
      disc_cam::MonteCarloOptions o = s.mc.options;
      o.scales = {s.mc.options.scales[k]};
      const auto one = disc_cam::MonteCarloLinearisation(cam, s.tolerances, o);
      mc.insert(mc.end(), one.begin(), one.end());
    }
    progress.Update(1.0);
    progress.Done();
    nlohmann::json scales = nlohmann::json::array();
    for (const auto& m : mc) {
      scales.push_back({{"scale", m.scale},
                        {"max_linear_um", m.max_linear * to_um},
                        {"max_exact_um", m.max_exact * to_um},
                        {"max_difference_um", m.max_difference * to_um},
                        {"relative_difference", m.relative_difference},
                        {"at_cam_angle_deg", m.at_cam_angle_rad / kDeg},
                        {"within_worst_case_fraction", m.within_bound_fraction},
                        {"worst_case_exceeded_by_um", std::max(0.0, m.bound_exceed) * to_um},
                        {"sample_rms_um", m.sample_rms * to_um},
                        {"linear_rms_uniform_um", m.predicted_rms * to_um}});
    }
    r["monte_carlo"] = {{"samples", s.mc.options.samples},
                        {"angle_steps", s.mc.options.angle_steps},
                        {"seed", s.mc.options.seed},
                        {"distribution", "uniform within ±scale × tolerance, independent"},
                        {"scales", scales}};
  } else if (s.mc.enabled) {
    r["monte_carlo"] = {{"skipped", "the profile is undercut"}};
  }
  out.AddJson("result.json", r);

  // Series.
  Table table;
  std::vector<double> th(n);
  for (int i = 0; i < n; ++i) th[i] = angle_deg(i);
  auto col = [&](auto f) {
    std::vector<double> c(n);
    for (int i = 0; i < n; ++i) c[i] = f(i);
    return c;
  };
  table.Add("cam_angle_deg", th);
  table.Add("follower_" + fu, col([&](int i) { return pts[i].s * unit; }));
  table.Add("velocity_" + fu + "_per_rad", col([&](int i) { return pts[i].ds * unit; }));
  table.Add("acceleration_" + fu + "_per_rad2", col([&](int i) { return pts[i].d2s * unit; }));
  table.Add("jerk_" + fu + "_per_rad3", col([&](int i) { return jerk[i] * unit; }));
  table.Add("pressure_angle_deg", col([&](int i) { return pts[i].pressure_angle / kDeg; }));
  table.Add("shift_angle_deg", col([&](int i) { return pts[i].shift_angle / kDeg; }));
  table.Add("radial_dimension_mm", col([&](int i) { return pts[i].radial_dimension; }));
  table.Add("contact_x_mm", col([&](int i) { return pts[i].contact.x(); }));
  table.Add("contact_y_mm", col([&](int i) { return pts[i].contact.y(); }));
  table.Add("pitch_x_mm", col([&](int i) { return pts[i].pitch.x(); }));
  table.Add("pitch_y_mm", col([&](int i) { return pts[i].pitch.y(); }));
  table.Add("q_mm", col([&](int i) { return pts[i].q; }));
  table.Add("pitch_curvature_per_mm", col([&](int i) { return pts[i].pitch_curvature; }));
  table.Add("error_radial_um", col([&](int i) { return err[i].radial * to_um; }));
  table.Add("error_roller_um", col([&](int i) { return err[i].roller * to_um; }));
  table.Add("error_normal_um", col([&](int i) { return err[i].normal * to_um; }));
  table.Add("error_worst_case_um", col([&](int i) { return err[i].worst_case * to_um; }));
  table.Add("error_rms_um", col([&](int i) { return err[i].rms * to_um; }));
  out.Add("series.csv", ToCsv(table));

  auto series = [&](const std::string& label, const std::vector<double>& y) {
    return Series{label, th, y};
  };
  AddSvajPlots(out, s.name + ": follower", th,
               {table.names[1], table.names[2], table.names[3], table.names[4]},
               {&table.columns[1], &table.columns[2], &table.columns[3], &table.columns[4]});
  {
    PlotOptions o;
    o.title = s.name + ": pressure angle and shift angle (paper Fig. 12a)";
    o.x_label = "cam angle [deg]";
    o.y_label = "angle [deg]";
    out.Add("angles.svg", SvgLinePlot({series("pressure angle φ", table.columns[5]),
                                       series("shift angle λ", table.columns[6])},
                                      o));
  }
  {
    PlotOptions o;
    o.title = s.name + ": follower error (paper Fig. 12b)";
    o.x_label = "cam angle [deg]";
    o.y_label = osc ? "error at the roller centre, l·Δξ [µm]" : "follower error ΔS [µm]";
    std::vector<Series> ss = {series("ΔS_r (radial)", table.columns[14]),
                              series("ΔS_rf (roller)", table.columns[15])};
    if (s.tolerances.normal > 0) ss.push_back(series("ΔS_n (normal)", table.columns[16]));
    ss.push_back(series("ΔS_wor (worst case)", table.columns[17]));
    ss.push_back(series("ΔS_rms", table.columns[18]));
    out.Add("error.svg", SvgLinePlot(ss, o));
  }

  // Profile drawing: cam profile, pitch curve, base circle, and the follower at θ = 0.
  Drawing d;
  d.title = s.name + ": cam profile";
  Drawing::Layer profile{"profile", "black", {}, {}, true, 1.5};
  Drawing::Layer pitch{"pitch_curve", "steelblue", {}, {}, true, 0.7};
  Drawing::Layer base{"base_circle", "gray", {}, {}, true, 0.5};
  Drawing::Layer follower{"follower", "firebrick", {}, {}, false, 0.7};
  Polyline pp, pc;
  for (int i = 0; i < n; ++i) {
    pp.emplace_back(pts[i].contact.x(), pts[i].contact.y());
    pc.emplace_back(pts[i].pitch.x(), pts[i].pitch.y());
  }
  profile.polylines.push_back(pp);
  pitch.polylines.push_back(pc);
  base.circles.push_back({0.0, 0.0, cam.base_radius});
  base.circles.push_back({0.0, 0.0, 0.5});
  follower.circles.push_back({pts[0].pitch.x(), pts[0].pitch.y(), cam.roller_radius});
  if (osc) {
    const Vec2<double> o3 = cam.pivot_distance * U(0.0);
    follower.polylines.push_back({{o3.x(), o3.y()}, {pts[0].pitch.x(), pts[0].pitch.y()}});
    follower.circles.push_back({o3.x(), o3.y(), 1.5});
  } else {
    const Vec2<double> c = pts[0].pitch, u = U(0.0);
    const Vec2<double> a = c + 0.5 * cam.base_radius * u;
    follower.polylines.push_back({{c.x(), c.y()}, {a.x(), a.y()}});
  }
  d.layers = {profile, pitch, base, follower};
  out.Add("profile.svg", SvgDrawing(d));
  Drawing dxf;
  dxf.title = d.title;
  dxf.layers = {profile, pitch};
  out.Add("profile.dxf", ToDxf(dxf));
}

}  // namespace

CAMOPT_REGISTER_STUDY("disc_cam", Run);

}  // namespace camopt::studies
