// Study kind "globoidal_cam": a globoidal cam with an oscillating, dual-stopping (two-roller)
// turret (Ge, Wang & Zhang; NOTES.md §5). Geometry over a cam revolution (eqs. 1–9: roller angles,
// trajectory and working surfaces, pressure angle, undercut, contact radius), the quasi-static
// roller force, the Adams-style contact dynamics at the requested cam speeds (eqs. 10–14), and the
// working surfaces exported as a CSV point cloud and an ASCII STL mesh.
// Outputs: result.json, series.csv, dynamics_<rpm>rpm.csv, SVG plots, working_surfaces.csv,
// working_surfaces.stl.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <stdexcept>

#include "model/globoidal/contact_dynamics.h"
#include "model/globoidal/globoidal.h"
#include "model/motion/motion_program.h"
#include "studies/study.h"
#include "studies/writers.h"

namespace camopt::studies {
namespace {

using globoidal::DynamicsInput;
using globoidal::GloboidalCam;
using globoidal::SurfacePoint;
using globoidal::Vec3;

constexpr double kDeg = kPi / 180.0;

struct GloboidalStudy {
  std::string name;
  DynamicsInput dyn;  // carries the cam, the contact material, the load and the inertia
  std::vector<double> speeds_rpm;
  double end_time_s = -1.0;  // ≤ 0: one cam revolution
  double time_step_s = 1e-5;
  int angle_steps = 720;
  int axis_steps = 7;
  int export_angle_steps = 360;
  int export_axis_steps = 6;
  bool export_stl = true, export_point_cloud = true;
};

std::string Format(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

GloboidalStudy Parse(const Node& root) {
  root.CheckKnownFields({"study", "name", "cam", "motion", "load", "contact", "dynamics",
                          "analysis", "export"});
  GloboidalStudy s;
  s.name = root.StringOr("name", "globoidal cam");
  GloboidalCam<double>& cam = s.dyn.cam;

  const Node c = root["cam"];
  c.CheckKnownFields({"center_distance_mm", "roller_radius_mm", "pitch_radius_mm",
                       "roller_length_mm", "clearance_mm", "roller_angle_deg", "swing_deg",
                       "first_motion"});
  cam.center_distance = c["center_distance_mm"].Positive();
  cam.roller_radius = c["roller_radius_mm"].Positive();
  cam.pitch_radius = c["pitch_radius_mm"].Positive();
  cam.roller_length = c["roller_length_mm"].Positive();
  cam.clearance = c["clearance_mm"].NonNegative();
  cam.roller_angle = c["roller_angle_deg"].Positive() * kDeg;
  if (cam.roller_angle >= kPi) c["roller_angle_deg"].Fail("an angle in (0, 180) deg");
  cam.swing = c["swing_deg"].Positive() * kDeg;
  if (cam.swing >= kPi / 2) c["swing_deg"].Fail("an angle in (0, 90) deg");
  const std::string first = c.StringOr("first_motion", "clockwise");
  if (first == "clockwise") {
    cam.direction = 1;
  } else if (first == "anticlockwise") {
    cam.direction = -1;
  } else {
    c["first_motion"].Fail("\"clockwise\" or \"anticlockwise\"");
  }
  const auto lim = globoidal::RollerAxisLimits(cam);
  if (!(lim.l2 > 0.0))
    c["roller_length_mm"].FailWith("the roller (length " + Format(cam.roller_length) +
                                   " mm) reaches past the turret axis: need m/2 < R_e");
  // Largest roller angle from the oz-plane: the trajectory must stay on the turret's side of the
  // cam axis, C − l₁ cos φ > 0 for every φ; it suffices that C > l₁.
  if (!(cam.center_distance > lim.l1 + cam.roller_radius))
    c["center_distance_mm"].FailWith(
        "the rollers reach the cam axis: need C > l₁ + R = " + Format(lim.l1 + cam.roller_radius) +
        " mm (l₁ = R_e + m/2 + e, eq. 8)");
  // The rib between the two rollers: its thickness at the turret-side end of the rollers.
  const double rib = 2.0 * lim.l2 * std::sin(cam.roller_angle / 2) - 2.0 * cam.roller_radius;
  if (!(rib > 0.0))
    c["roller_angle_deg"].FailWith("the two rollers overlap (no rib between them): need "
                                   "2 l₂ sin(β/2) > 2R, found " +
                                   Format(2.0 * lim.l2 * std::sin(cam.roller_angle / 2)) +
                                   " mm ≤ " + Format(2 * cam.roller_radius) + " mm");

  // Motion: the turret swing φ_i, rising by +φ_f in the first motion's direction.
  const Node motion_node = root["motion"];
  std::vector<motion::MotionSegment<double>> segments;
  std::string laws;
  for (const auto& n : motion::LawNames()) laws += (laws.empty() ? "" : ", ") + n;
  for (const Node& seg : motion_node.Elements()) {
    seg.CheckKnownFields({"law", "rise_deg", "cam_angle_deg"});
    const auto law = motion::LawFromName(seg["law"].String());
    if (!law) seg["law"].Fail("a motion law (" + laws + ")");
    motion::MotionSegment<double> m;
    m.law = *law;
    m.duration = seg["cam_angle_deg"].Positive() * kDeg;
    if (*law == motion::MotionLaw::kDwell) {
      if (seg.Has("rise_deg") && seg["rise_deg"].Number() != 0.0)
        seg["rise_deg"].FailWith("a dwell has no rise");
    } else {
      m.rise = seg["rise_deg"].Number() * kDeg;
      if (m.rise == 0.0) seg["rise_deg"].Fail("a non-zero rise (use a dwell for no motion)");
    }
    segments.push_back(m);
  }
  cam.motion = motion::MotionProgram<double>(segments);
  if (const auto issue = motion::CheckProgram(cam.motion, 2 * kPi, /*must_return=*/true, 1e-6)) {
    if (issue->segment < 0 && issue->message.find("does not return") != std::string::npos)
      motion_node.FailWith("the turret does not return: rises sum to " +
                           Format(cam.motion.NetRise() / kDeg) + " deg, expected 0");
    if (issue->segment < 0) motion_node.FailWith(issue->message);
    const std::string field = issue->field == "rise" ? "rise_deg" : issue->field;
    motion_node[issue->segment][field].FailWith(issue->message);
  }
  // The swing must run between the dead points 0 and φ_f (eq. 7 places them).
  double lo = 0, hi = 0;
  for (int i = 0; i < 3600; ++i) {
    const double v = cam.motion.Evaluate(2 * kPi * i / 3600).s;
    lo = std::min(lo, v), hi = std::max(hi, v);
  }
  if (lo < -1e-9 || std::abs(hi - cam.swing) > 1e-6)
    motion_node.FailWith("the swing must run from 0 to swing_deg = " + Format(cam.swing / kDeg) +
                         " deg (rise first, in the first motion's direction); it runs from " +
                         Format(lo / kDeg) + " to " + Format(hi / kDeg) + " deg");

  if (root.Has("load")) {
    const Node l = root["load"];
    l.CheckKnownFields({"turret_torque_Nm", "turret_inertia_kgm2"});
    s.dyn.load_torque_Nmm = l.NumberOr("turret_torque_Nm", 0.0) * 1e3;
    s.dyn.inertia_Nmms2 = l.PositiveOr("turret_inertia_kgm2", 0.01) * 1e3;
  }
  if (root.Has("contact")) {
    const Node k = root["contact"];
    k.CheckKnownFields({"cam_modulus_MPa", "cam_poisson", "roller_modulus_MPa", "roller_poisson",
                         "exponent", "max_damping_Ns_per_mm", "penetration_depth_mm",
                         "contact_arm_mm"});
    auto& m = s.dyn.contact;
    m.cam_modulus_MPa = k.PositiveOr("cam_modulus_MPa", m.cam_modulus_MPa);
    m.roller_modulus_MPa = k.PositiveOr("roller_modulus_MPa", m.roller_modulus_MPa);
    if (k.Has("cam_poisson")) m.cam_poisson = k["cam_poisson"].NumberIn(0.0, 0.499);
    if (k.Has("roller_poisson")) m.roller_poisson = k["roller_poisson"].NumberIn(0.0, 0.499);
    if (k.Has("exponent")) m.exponent = k["exponent"].NumberIn(1.0, 3.0);
    m.max_damping_Ns_per_mm = k.NonNegativeOr("max_damping_Ns_per_mm", m.max_damping_Ns_per_mm);
    m.penetration_depth_mm = k.PositiveOr("penetration_depth_mm", m.penetration_depth_mm);
    if (k.Has("contact_arm_mm")) {
      s.dyn.contact_arm_mm = k["contact_arm_mm"].Positive();
      if (s.dyn.contact_arm_mm < lim.l2 || s.dyn.contact_arm_mm > lim.l1)
        k["contact_arm_mm"].Fail("a length in [l₂, l₁] = [" + Format(lim.l2) + ", " +
                                 Format(lim.l1) + "] mm");
    }
  }
  if (root.Has("dynamics")) {
    const Node d = root["dynamics"];
    d.CheckKnownFields({"cam_speeds_rpm", "end_time_s", "time_step_s"});
    if (d.Has("cam_speeds_rpm"))
      for (const Node& v : d["cam_speeds_rpm"].Elements()) s.speeds_rpm.push_back(v.Positive());
    if (d.Has("end_time_s")) s.end_time_s = d["end_time_s"].Positive();
    s.time_step_s = d.PositiveOr("time_step_s", s.time_step_s);
    if (s.time_step_s > 1e-3) d["time_step_s"].Fail("a time step ≤ 1e-3 s");
    for (size_t i = 0; i < s.speeds_rpm.size(); ++i) {
      const double t_end = s.end_time_s > 0 ? s.end_time_s : 60.0 / s.speeds_rpm[i];
      if (t_end / s.time_step_s > 2e7)
        d.FailWith("more than 2e7 time steps at " + Format(s.speeds_rpm[i]) +
                   " rpm: shorten end_time_s or enlarge time_step_s");
    }
  }
  if (root.Has("analysis")) {
    const Node a = root["analysis"];
    a.CheckKnownFields({"angle_steps", "axis_steps"});
    s.angle_steps = a.IntegerOr("angle_steps", 36, s.angle_steps);
    if (s.angle_steps > 200000) a["angle_steps"].Fail("a whole number <= 200000");
    s.axis_steps = a.IntegerOr("axis_steps", 2, s.axis_steps);
    if (s.axis_steps > 1000) a["axis_steps"].Fail("a whole number <= 1000");
  }
  if (root.Has("export")) {
    const Node e = root["export"];
    e.CheckKnownFields({"stl", "point_cloud", "angle_steps", "axis_steps"});
    s.export_stl = e.BoolOr("stl", true);
    s.export_point_cloud = e.BoolOr("point_cloud", true);
    s.export_angle_steps = e.IntegerOr("angle_steps", 36, s.export_angle_steps);
    s.export_axis_steps = e.IntegerOr("axis_steps", 2, s.export_axis_steps);
    if (double(s.export_angle_steps) * s.export_axis_steps > 4e6)
      e.FailWith("angle_steps × axis_steps must stay below 4e6");
  }
  return s;
}

// ASCII STL of one grid surface per roller (open surfaces, not a closed solid): each grid cell
// as two triangles, oriented so that the facet normal is the working-surface normal (out of the
// rib, toward the roller: −n).
void AppendStlSurface(std::ostringstream& os, const std::vector<std::vector<Vec3<double>>>& pts,
                      const std::vector<std::vector<Vec3<double>>>& normals) {
  auto facet = [&](const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c,
                   const Vec3<double>& want) {
    Vec3<double> n = (b - a).cross(c - a);
    const double len = n.norm();
    if (!(len > 0)) return;  // degenerate cell
    n /= len;
    const bool flip = n.dot(want) < 0;
    const Vec3<double>& p1 = flip ? c : b;
    const Vec3<double>& p2 = flip ? b : c;
    if (flip) n = -n;
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "  facet normal %.7e %.7e %.7e\n    outer loop\n      vertex %.9e %.9e %.9e\n"
                  "      vertex %.9e %.9e %.9e\n      vertex %.9e %.9e %.9e\n    endloop\n"
                  "  endfacet\n",
                  n.x(), n.y(), n.z(), a.x(), a.y(), a.z(), p1.x(), p1.y(), p1.z(), p2.x(), p2.y(),
                  p2.z());
    os << buf;
  };
  const size_t na = pts.size(), nl = pts[0].size();
  for (size_t i = 0; i < na; ++i) {
    const size_t k = (i + 1) % na;  // closes the surface around the cam
    for (size_t m = 0; m + 1 < nl; ++m) {
      const Vec3<double> want = -(normals[i][m] + normals[k][m + 1]);
      facet(pts[i][m], pts[k][m], pts[k][m + 1], want);
      facet(pts[i][m], pts[k][m + 1], pts[i][m + 1], want);
    }
  }
}

void Run(const Node& root, const RunContext& ctx, Outputs& out) {
  const GloboidalStudy s = Parse(root);
  const GloboidalCam<double>& cam = s.dyn.cam;
  const auto lim = globoidal::RollerAxisLimits(cam);
  const double arm = s.dyn.contact_arm_mm > 0 ? s.dyn.contact_arm_mm : cam.pitch_radius;
  const int n = s.angle_steps, na = s.axis_steps;
  auto angle_deg = [&](int i) { return 360.0 * i / n; };
  auto theta = [&](int i) { return 2 * kPi * i / n; };
  auto axis_l = [&](int k) { return lim.l2 + (lim.l1 - lim.l2) * k / (na - 1); };

  // Geometry over the grid: pressure angle, undercut margin, contact radius.
  struct Extreme {
    double value = 0;
    double cam_angle_deg = 0, axis_mm = 0;
    int roller = 1;
    bool set = false;
  };
  Extreme alpha_max, margin_min, jac_min, rcontact_min;
  std::vector<double> alpha[2][2], margin(n, 1e300), rcontact[2], phi[2];
  for (int j = 0; j < 2; ++j) {
    for (int e = 0; e < 2; ++e) alpha[j][e].resize(n);
    rcontact[j].resize(n);
    phi[j].resize(n);
  }
  auto update = [](Extreme& x, double v, bool larger, double t, double l, int j) {
    if (!x.set || (larger ? v > x.value : v < x.value)) x = {v, t, l, j, true};
  };
  for (int i = 0; i < n; ++i) {
    for (int j = 1; j <= 2; ++j) {
      for (int k = 0; k < na; ++k) {
        const double l = axis_l(k);
        const SurfacePoint<double> p = globoidal::EvaluateSurface(cam, j, l, theta(i));
        if (k == 0) alpha[j - 1][1][i] = p.pressure_angle;
        if (k == na - 1) alpha[j - 1][0][i] = p.pressure_angle;
        margin[i] = std::min(margin[i], p.undercut_margin);
        phi[j - 1][i] = p.angle.phi;
      }
      rcontact[j - 1][i] = globoidal::EvaluateSurface(cam, j, arm, theta(i)).contact_radius;
    }
  }
  // Extremes on the uniform grid and on 64 samples inside every segment, so that a short
  // segment is never stepped over.
  std::vector<double> samples;
  for (int i = 0; i < n; ++i) samples.push_back(theta(i));
  {
    double start = 0;
    for (const auto& seg : cam.motion.segments()) {
      for (int q = 0; q < 64; ++q) samples.push_back(start + seg.duration * (q + 0.5) / 64);
      start += seg.duration;
    }
  }
  bool conformal = false;
  for (const double t : samples) {
    for (int j = 1; j <= 2; ++j) {
      for (int k = 0; k < na; ++k) {
        const double l = axis_l(k);
        const SurfacePoint<double> p = globoidal::EvaluateSurface(cam, j, l, t);
        update(alpha_max, std::abs(p.pressure_angle), true, t / kDeg, l, j);
        update(margin_min, p.undercut_margin, false, t / kDeg, l, j);
        update(jac_min, p.offset_jacobian, false, t / kDeg, l, j);
      }
      const SurfacePoint<double> pc = globoidal::EvaluateSurface(cam, j, arm, t);
      if (pc.contact_radius > 0) {
        update(rcontact_min, pc.contact_radius, false, t / kDeg, arm, j);
      } else {
        conformal = true;
      }
    }
  }
  const bool undercut = margin_min.value <= 0.0;
  if (!(alpha_max.value < 89.0 * kDeg))
    root["motion"].FailWith("infeasible design: the pressure angle reaches " +
                            Format(alpha_max.value / kDeg) + " deg at cam angle " +
                            Format(alpha_max.cam_angle_deg) + " deg (the turret would jam)");

  nlohmann::json r;
  r["study"] = "globoidal_cam";
  r["name"] = s.name;
  r["angle_steps"] = n;
  r["axis_steps"] = na;
  r["roller_axis_limits_mm"] = {{"l1", lim.l1}, {"l2", lim.l2}};
  const double b = cam.roller_angle, f = cam.swing;
  r["initial_angles_deg"] = {
      {"top_dead_point", {{"roller_1", globoidal::InitialAngle(b, f, 1, 1) / kDeg},
                          {"roller_2", globoidal::InitialAngle(b, f, 2, 1) / kDeg}}},
      {"bottom_dead_point", {{"roller_1", globoidal::InitialAngle(b, f, 1, -1) / kDeg},
                             {"roller_2", globoidal::InitialAngle(b, f, 2, -1) / kDeg}}}};
  auto range = [&](const std::vector<double>& v) {
    return nlohmann::json::array({*std::min_element(v.begin(), v.end()) / kDeg,
                                  *std::max_element(v.begin(), v.end()) / kDeg});
  };
  r["roller_angle_range_deg"] = {{"roller_1", range(phi[0])}, {"roller_2", range(phi[1])}};
  r["rib_thickness_at_l2_mm"] = 2.0 * lim.l2 * std::sin(b / 2) - 2.0 * cam.roller_radius;
  r["max_pressure_angle_deg"] = alpha_max.value / kDeg;
  r["max_pressure_angle_at"] = {{"cam_angle_deg", alpha_max.cam_angle_deg},
                                {"axis_mm", alpha_max.axis_mm},
                                {"roller", alpha_max.roller}};
  r["undercut"] = undercut;
  r["min_undercut_margin"] = margin_min.value;
  r["min_undercut_margin_at"] = {{"cam_angle_deg", margin_min.cam_angle_deg},
                                 {"axis_mm", margin_min.axis_mm},
                                 {"roller", margin_min.roller}};
  r["min_offset_area_ratio"] = jac_min.value;
  r["contact_arm_mm"] = arm;
  r["conformal_contact"] = conformal;
  if (rcontact_min.set) {
    r["min_contact_radius_mm"] = rcontact_min.value;
    r["min_contact_radius_at"] = {{"cam_angle_deg", rcontact_min.cam_angle_deg},
                                  {"roller", rcontact_min.roller}};
  }

  // Motion program: continuity and peak coefficients.
  nlohmann::json joints = nlohmann::json::array();
  for (const auto& jc : motion::CheckContinuity(cam.motion, 1e-7))
    joints.push_back({{"after_segment", jc.segment},
                      {"cam_angle_deg", jc.cam_angle_rad / kDeg},
                      {"continuity", jc.order < 0 ? std::string("discontinuous")
                                                  : "C" + std::to_string(jc.order)}});
  std::vector<motion::Svaj<double>> svaj(n);
  double vmax = 0, amax = 0, jmax = 0;
  for (int i = 0; i < n; ++i) {
    svaj[i] = cam.motion.Evaluate(theta(i));
    vmax = std::max(vmax, std::abs(svaj[i].v));
    amax = std::max(amax, std::abs(svaj[i].a));
    jmax = std::max(jmax, std::abs(svaj[i].j));
  }
  r["motion"] = {{"joints", joints},
                 {"peak_velocity_deg_per_rad", vmax / kDeg},
                 {"peak_acceleration_deg_per_rad2", amax / kDeg},
                 {"peak_jerk_deg_per_rad3", jmax / kDeg}};

  // Quasi-static forces and dynamics per speed.
  r["load"] = {{"turret_torque_Nm", s.dyn.load_torque_Nmm * 1e-3},
               {"turret_inertia_kgm2", s.dyn.inertia_Nmms2 * 1e-3}};
  const double e_star = s.dyn.contact.composite_modulus_MPa();
  r["effective_modulus_MPa"] = e_star;
  Table table;
  std::vector<double> th(n);
  for (int i = 0; i < n; ++i) th[i] = angle_deg(i);
  auto col = [&](auto fn) {
    std::vector<double> v(n);
    for (int i = 0; i < n; ++i) v[i] = fn(i);
    return v;
  };
  table.Add("cam_angle_deg", th);
  table.Add("swing_deg", col([&](int i) { return svaj[i].s / kDeg; }));
  table.Add("swing_velocity_deg_per_rad", col([&](int i) { return svaj[i].v / kDeg; }));
  table.Add("swing_acceleration_deg_per_rad2", col([&](int i) { return svaj[i].a / kDeg; }));
  table.Add("swing_jerk_deg_per_rad3", col([&](int i) { return svaj[i].j / kDeg; }));
  table.Add("roller_1_angle_deg", col([&](int i) { return phi[0][i] / kDeg; }));
  table.Add("roller_2_angle_deg", col([&](int i) { return phi[1][i] / kDeg; }));
  table.Add("pressure_angle_roller_1_at_l1_deg", col([&](int i) { return alpha[0][0][i] / kDeg; }));
  table.Add("pressure_angle_roller_1_at_l2_deg", col([&](int i) { return alpha[0][1][i] / kDeg; }));
  table.Add("pressure_angle_roller_2_at_l1_deg", col([&](int i) { return alpha[1][0][i] / kDeg; }));
  table.Add("pressure_angle_roller_2_at_l2_deg", col([&](int i) { return alpha[1][1][i] / kDeg; }));
  table.Add("min_undercut_margin", margin);
  table.Add("contact_radius_roller_1_mm", rcontact[0]);
  table.Add("contact_radius_roller_2_mm", rcontact[1]);

  nlohmann::json speeds = nlohmann::json::array();
  std::vector<Series> force_plots;
  if (!s.speeds_rpm.empty() && (undercut || conformal)) {
    r["dynamics"] = {{"skipped", undercut ? "the working surface is undercut"
                                          : "the contact is conformal (no Hertz radius)"}};
  } else {
    Progress progress("globoidal_cam dynamics", ctx.quiet);
    for (size_t k = 0; k < s.speeds_rpm.size(); ++k) {
      const double rpm = s.speeds_rpm[k];
      progress.Update(double(k) / s.speeds_rpm.size(), Format(rpm) + " rpm");
      DynamicsInput in = s.dyn;
      in.cam_speed_rad_s = rpm * 2 * kPi / 60;
      in.end_time_s = s.end_time_s > 0 ? s.end_time_s : 60.0 / rpm;
      in.time_step_s = s.time_step_s;
      in.output_every = std::max(1, int(std::lround(in.end_time_s / in.time_step_s / 2000)));
      globoidal::DynamicsResult dr;
      try {
        dr = globoidal::SimulateDynamics(in);
      } catch (const std::domain_error& e) {
        speeds.push_back({{"cam_speed_rpm", rpm}, {"failed", e.what()}});
        continue;
      }
      const std::string tag = Format(rpm) + "rpm";
      // Quasi-static force over the revolution at this speed.
      std::vector<double> qs = col([&](int i) { return globoidal::QuasiStaticForce(in, theta(i)); });
      table.Add("quasi_static_force_" + tag + "_N", qs);
      double vk = 0, vd = 0, ak = 0, ad = 0, f1 = 0, f2 = 0, dev = 0, dmax = 0;
      for (const auto& x : dr.samples) {
        vk = std::max(vk, std::abs(x.kin_rate_rad_s));
        vd = std::max(vd, std::abs(x.swing_rate_rad_s));
        ak = std::max(ak, std::abs(x.kin_acc_rad_s2));
        ad = std::max(ad, std::abs(x.swing_acc_rad_s2));
        f1 = std::max(f1, x.force_N[0]);
        f2 = std::max(f2, x.force_N[1]);
        dev = std::max(dev, std::abs(x.swing_rad - x.kin_swing_rad));
        dmax = std::max({dmax, x.penetration_mm[0], x.penetration_mm[1]});
      }
      speeds.push_back({{"cam_speed_rpm", rpm},
                        {"end_time_s", in.end_time_s},
                        {"time_step_s", in.time_step_s},
                        {"steps", dr.steps},
                        {"peak_turret_velocity_kinematic_rad_s", vk},
                        {"peak_turret_velocity_dynamic_rad_s", vd},
                        {"peak_turret_acceleration_kinematic_rad_s2", ak},
                        {"peak_turret_acceleration_dynamic_rad_s2", ad},
                        {"max_force_roller_1_N", f1},
                        {"max_force_roller_2_N", f2},
                        {"max_quasi_static_force_N", *std::max_element(qs.begin(), qs.end())},
                        {"max_swing_deviation_deg", dev / kDeg},
                        {"max_penetration_mm", dmax}});
      Table dt;
      auto dcol = [&](auto fn) {
        std::vector<double> v;
        for (const auto& x : dr.samples) v.push_back(fn(x));
        return v;
      };
      using Sample = globoidal::DynamicsSample;
      dt.Add("time_s", dcol([](const Sample& x) { return x.time_s; }));
      dt.Add("cam_angle_deg", dcol([](const Sample& x) { return x.cam_angle_rad / kDeg; }));
      dt.Add("swing_deg", dcol([](const Sample& x) { return x.swing_rad / kDeg; }));
      dt.Add("swing_rate_rad_s", dcol([](const Sample& x) { return x.swing_rate_rad_s; }));
      dt.Add("swing_acc_rad_s2", dcol([](const Sample& x) { return x.swing_acc_rad_s2; }));
      dt.Add("kinematic_swing_deg", dcol([](const Sample& x) { return x.kin_swing_rad / kDeg; }));
      dt.Add("kinematic_rate_rad_s", dcol([](const Sample& x) { return x.kin_rate_rad_s; }));
      dt.Add("kinematic_acc_rad_s2", dcol([](const Sample& x) { return x.kin_acc_rad_s2; }));
      dt.Add("penetration_roller_1_mm", dcol([](const Sample& x) { return x.penetration_mm[0]; }));
      dt.Add("penetration_roller_2_mm", dcol([](const Sample& x) { return x.penetration_mm[1]; }));
      dt.Add("force_roller_1_N", dcol([](const Sample& x) { return x.force_N[0]; }));
      dt.Add("force_roller_2_N", dcol([](const Sample& x) { return x.force_N[1]; }));
      out.Add("dynamics_" + tag + ".csv", ToCsv(dt));
      {
        PlotOptions o;
        o.title = s.name + ": contact forces at " + Format(rpm) + " rpm";
        o.x_label = "cam angle [deg]";
        o.y_label = "force [N]";
        out.Add("contact_forces_" + tag + ".svg",
                SvgLinePlot({{"quasi-static", th, qs},
                             {"roller 1", dt.columns[1], dt.columns[10]},
                             {"roller 2", dt.columns[1], dt.columns[11]}},
                            o));
      }
      {
        // The paper's Figs. 6–7: turret velocity and acceleration against time.
        PlotOptions o;
        o.title = s.name + ": turret velocity at " + Format(rpm) + " rpm";
        o.x_label = "time [s]";
        o.y_label = "angular velocity [rad/s]";
        out.Add("turret_velocity_" + tag + ".svg",
                SvgLinePlot({{"dynamic", dt.columns[0], dt.columns[3]},
                             {"modified sine", dt.columns[0], dt.columns[6]}},
                            o));
        o.title = s.name + ": turret acceleration at " + Format(rpm) + " rpm";
        o.y_label = "angular acceleration [rad/s²]";
        out.Add("turret_acceleration_" + tag + ".svg",
                SvgLinePlot({{"dynamic", dt.columns[0], dt.columns[4]},
                             {"modified sine", dt.columns[0], dt.columns[7]}},
                            o));
      }
    }
    progress.Update(1.0);
    progress.Done();
    r["dynamics"] = {{"contact_model", "F = K δ^e + step(δ, 0, 0, d, C_max) δ̇ (eqs. 10–14), RK4"},
                     {"speeds", speeds}};
  }

  // Surface export.
  if (s.export_point_cloud || s.export_stl) {
    const int ne = s.export_angle_steps, ml = s.export_axis_steps;
    std::ostringstream stl;
    Table cloud;
    std::vector<double> cr, cl, ct, cx, cy, cz, cnx, cny, cnz;
    if (s.export_stl) stl << "solid globoidal_working_surfaces\n";
    for (int j = 1; j <= 2; ++j) {
      std::vector<std::vector<Vec3<double>>> pts(ne), nrm(ne);
      for (int i = 0; i < ne; ++i) {
        for (int k = 0; k < ml; ++k) {
          const double l = lim.l2 + (lim.l1 - lim.l2) * k / (ml - 1);
          const SurfacePoint<double> p =
              globoidal::EvaluateSurface(cam, j, l, 2 * kPi * i / ne);
          pts[i].push_back(p.working);
          nrm[i].push_back(p.normal);
          cr.push_back(j), cl.push_back(l), ct.push_back(360.0 * i / ne);
          cx.push_back(p.working.x()), cy.push_back(p.working.y()), cz.push_back(p.working.z());
          // Outward normal of the rib (toward the roller).
          cnx.push_back(-p.normal.x()), cny.push_back(-p.normal.y()), cnz.push_back(-p.normal.z());
        }
      }
      if (s.export_stl) AppendStlSurface(stl, pts, nrm);
    }
    if (s.export_stl) {
      stl << "endsolid globoidal_working_surfaces\n";
      out.Add("working_surfaces.stl", stl.str());
    }
    if (s.export_point_cloud) {
      cloud.Add("roller", cr);
      cloud.Add("axis_mm", cl);
      cloud.Add("cam_angle_deg", ct);
      cloud.Add("x_mm", cx);
      cloud.Add("y_mm", cy);
      cloud.Add("z_mm", cz);
      cloud.Add("normal_x", cnx);
      cloud.Add("normal_y", cny);
      cloud.Add("normal_z", cnz);
      out.Add("working_surfaces.csv", ToCsv(cloud));
    }
    r["surface_export"] = {{"frame", "cam frame oxyz, oz the cam axis, mm; θ = 0 at the start of the "
                                     "first motion"},
                           {"angle_steps", ne},
                           {"axis_steps", ml},
                           {"stl", s.export_stl ? "working_surfaces.stl" : ""},
                           {"point_cloud", s.export_point_cloud ? "working_surfaces.csv" : ""}};
  }
  out.AddJson("result.json", r);
  out.Add("series.csv", ToCsv(table));

  auto series = [&](const std::string& label, const std::vector<double>& y) {
    return Series{label, th, y};
  };
  const char* names[4] = {"displacement", "velocity", "acceleration", "jerk"};
  for (int k = 0; k < 4; ++k) {
    PlotOptions o;
    o.title = s.name + ": turret swing " + names[k];
    o.x_label = "cam angle [deg]";
    o.y_label = table.names[1 + k];
    out.Add(std::string("svaj_") + names[k] + ".svg",
            SvgLinePlot({series(names[k], table.columns[1 + k])}, o));
  }
  {
    PlotOptions o;
    o.title = s.name + ": pressure angle";
    o.x_label = "cam angle [deg]";
    o.y_label = "pressure angle [deg]";
    out.Add("pressure_angle.svg",
            SvgLinePlot({series("roller 1 at l1", table.columns[7]),
                         series("roller 1 at l2", table.columns[8]),
                         series("roller 2 at l1", table.columns[9]),
                         series("roller 2 at l2", table.columns[10])},
                        o));
  }
}

}  // namespace

CAMOPT_REGISTER_STUDY("globoidal_cam", Run);

}  // namespace camopt::studies
