#include "studies/globoidal_cam_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "cad/solid.h"
#include "studies/design_issue_paths.h"
#include "studies/format.h"
#include "studies/kind.h"
#include "studies/motion_input.h"
#include "studies/report.h"
#include "studies/work_limits.h"
#include "studies/writers.h"

namespace camopt::studies::globoidal_cam {
namespace {

using globoidal::DynamicsInput;
using globoidal::GloboidalCam;
using globoidal::SurfacePoint;
using globoidal::Vec3;

constexpr double kDeg = kPi / 180.0;

// The mesh of one grid surface per roller (open surfaces, not a closed solid): each grid cell as
// two triangles, oriented so that the facet normal is the working-surface normal (out of the rib,
// toward the roller: −n); the surface closes around the cam (the last angle joins the first).
void AppendSurfaceMesh(cad::TriangleMesh& mesh, const std::vector<std::vector<Vec3<double>>>& pts,
                       const std::vector<std::vector<Vec3<double>>>& normals) {
  const size_t na = pts.size(), nl = pts[0].size();
  const int base = static_cast<int>(mesh.vertices.size());
  for (size_t i = 0; i < na; ++i)
    for (size_t m = 0; m < nl; ++m) mesh.vertices.push_back(pts[i][m]);
  auto id = [&](size_t i, size_t m) { return base + static_cast<int>(i * nl + m); };
  auto facet = [&](int a, int b, int c, const Vec3<double>& want) {
    const Vec3<double>& pa = mesh.vertices[a];
    const Vec3<double> n = (mesh.vertices[b] - pa).cross(mesh.vertices[c] - pa);
    if (!(n.norm() > 0)) return;  // degenerate cell
    if (n.dot(want) < 0) std::swap(b, c);
    mesh.triangles.push_back({a, b, c});
  };
  for (size_t i = 0; i < na; ++i) {
    const size_t k = (i + 1) % na;
    for (size_t m = 0; m + 1 < nl; ++m) {
      const Vec3<double> want = -(normals[i][m] + normals[k][m + 1]);
      facet(id(i, m), id(k, m), id(k, m + 1), want);
      facet(id(i, m), id(k, m + 1), id(i, m + 1), want);
    }
  }
}

std::string SpeedTag(double rpm) { return Format(rpm) + "rpm"; }

}  // namespace

nlohmann::ordered_json Input::MotionSchema() {
  using oj = nlohmann::ordered_json;
  oj laws = oj::array(), moving = oj::array();
  const std::string dwell = motion::LawName(motion::MotionLaw::kDwell);
  for (const std::string& law : motion::LawNames())
    if (law != motion::LawName(motion::MotionLaw::kPolynomial) && law != motion::LawName(motion::MotionLaw::kBSpline)) {
      laws.push_back(law);
      if (law != dwell) moving.push_back(law);
    }
  // A moving law swings the turret (rise_deg given, not 0); a dwell does not (0 when given).
  const oj rules = oj::array(
      {{{"if", {{"properties", {{"law", {{"enum", moving}}}}}, {"required", {"law"}}}},
        {"then", {{"required", {"rise_deg"}}, {"properties", {{"rise_deg", {{"not", {{"const", 0}}}}}}}}}},
       {{"if", {{"properties", {{"law", {{"const", dwell}}}}}, {"required", {"law"}}}},
        {"then", {{"properties", {{"rise_deg", {{"const", 0}}}}}}}}});
  return {{"type", "array"},
          {"minItems", 1},
          {"items",
           {{"type", "object"},
            {"properties",
             {{"law", {{"description", "the motion law of the segment"}, {"enum", laws}}},
              {"rise_deg", {{"description", "the segment's swing (none for a dwell) [deg]"}, {"type", "number"}}},
              {"cam_angle_deg",
               {{"description", "the cam angle the segment spans [deg]"}, {"type", "number"}, {"exclusiveMinimum", 0}}}}},
            {"required", {"law", "cam_angle_deg"}},
            {"additionalProperties", false},
            {"allOf", rules}}}};
}

// The checks that span fields (the geometry, the motion against the swing, the contact arm, the
// steps a speed needs, the stages against their inputs, the load against the contact law) and
// the conversion of the declared input to model units.
Study Parse(const Node& root) {
  Study s;
  s.in = Read<Input>(root);
  const Input& in = s.in;
  GloboidalCam<double>& cam = s.dyn.cam;
  const Node c = root["cam"];
  cam.center_distance = in.cam.center_distance_mm;
  cam.roller_radius = PlausibleLength(c["roller_radius_mm"], cam.center_distance, "the center distance");
  cam.pitch_radius = in.cam.pitch_radius_mm;
  cam.roller_length = in.cam.roller_length_mm;
  cam.clearance = in.cam.clearance_mm;
  cam.roller_angle = in.cam.roller_angle_deg * kDeg;
  cam.swing = in.cam.swing_deg * kDeg;
  cam.direction = in.cam.first_motion == "clockwise" ? 1 : -1;
  FailOnFirst(globoidal::CheckGeometry(cam), root, GloboidalIssuePaths());

  // Motion: the turret swing φ_i, rising by +φ_f in the first motion's direction, between the
  // dead points 0 and φ_f (eq. 7 places them).
  MotionInputSpec spec;
  spec.rise_key = "rise_deg", spec.rise_scale = kDeg, spec.unit = "deg", spec.subject = "turret";
  cam.motion = ParseMotionProgram(root["motion"], spec);
  FailOnFirst(globoidal::CheckSwing(cam), root, GloboidalIssuePaths());

  s.dyn.load_torque_Nmm = in.load.turret_torque_Nm * 1e3;
  s.dyn.inertia_Nmms2 = in.load.turret_inertia_kgm2 * 1e3;
  // Young's moduli in GPa and "poisson_ratio" as in every other kind; the earlier names
  // (*_modulus_MPa, *_poisson) stay accepted as aliases (docs/studies.md, "Units"; the declaration
  // refuses both names of a pair).
  const Input::Contact& kc = in.contact;
  auto& m = s.dyn.contact;
  if (kc.cam_modulus_MPa) m.cam_modulus_MPa = *kc.cam_modulus_MPa;
  if (kc.cam_youngs_modulus_GPa) m.cam_modulus_MPa = *kc.cam_youngs_modulus_GPa * 1000.0;
  if (kc.roller_modulus_MPa) m.roller_modulus_MPa = *kc.roller_modulus_MPa;
  if (kc.roller_youngs_modulus_GPa) m.roller_modulus_MPa = *kc.roller_youngs_modulus_GPa * 1000.0;
  m.cam_poisson = kc.cam_poisson.value_or(kc.cam_poisson_ratio.value_or(m.cam_poisson));
  m.roller_poisson = kc.roller_poisson.value_or(kc.roller_poisson_ratio.value_or(m.roller_poisson));
  m.exponent = kc.exponent;
  m.max_damping_Ns_per_mm = kc.max_damping_Ns_per_mm;
  m.penetration_depth_mm = kc.penetration_depth_mm;
  if (kc.contact_arm_mm) {
    s.dyn.contact_arm_mm = *kc.contact_arm_mm;
    FailOnFirst(globoidal::CheckContactArm(s.dyn), root, GloboidalIssuePaths());
  }

  const Input::Dynamics& d = in.dynamics;
  s.speeds_rpm = d.cam_speeds_rpm;
  for (const double rpm : s.speeds_rpm) {
    // The solver's step is at most 0.5° of cam: a run shorter than max_steps of those.
    DynamicsInput probe = s.dyn;
    probe.cam_speed_rad_s = rpm * 2 * kPi / 60;
    probe.end_time_s = s.EndTime(rpm);
    const double least = probe.end_time_s / globoidal::MaxStep(probe);
    if (least > d.max_steps)
      root["dynamics"].FailWith("at " + Format(rpm) + " rpm the run needs at least " + Format(std::ceil(least)) +
                                " steps (a step spans at most 0.5° of cam), more than max_steps = " +
                                std::to_string(d.max_steps) + ": shorten end_time_s or raise max_steps");
  }
  if (in.analysis.evaluate) {
    s.dynamics_stage = s.export_stage = false;
    for (const std::string& stage : *in.analysis.evaluate) {
      s.dynamics_stage = s.dynamics_stage || stage == "dynamics";
      s.export_stage = s.export_stage || stage == "export";
    }
    // A stage asked for needs its inputs; the ones not asked for are not run.
    if (s.dynamics_stage && s.speeds_rpm.empty()) {
      const Node speeds = root["dynamics"]["cam_speeds_rpm"];  // "missing" when absent
      speeds.Fail("at least one cam speed (analysis.evaluate asks for the dynamics)");
    }
    if (!s.dynamics_stage) s.speeds_rpm.clear();
  }
  s.pressure_angle_limit_default = !(root.Has("limits") && root["limits"].Has("pressure_angle_deg"));
  s.export_stl = in.export_.stl;
  s.export_point_cloud = in.export_.point_cloud;
  if (double(in.export_.angle_steps) * in.export_.axis_steps > 4e6)
    root["export"].FailWith("angle_steps × axis_steps must stay below 4e6");
  if (!s.export_stage) s.export_stl = s.export_point_cloud = false;  // not asked for
  s.geometry = GeometryFileOptionsOf(in.geometry_files);
  // "geometry_files": false: no STL/STEP of the surfaces, whatever export.stl says (a sweep can
  // switch them off in any base study); the point cloud is data and stays.
  if (!s.geometry.write) s.export_stl = false;
  // Every check, with the jam limit over the analysis grid.
  FailOnFirst(globoidal::CheckDesign(s.dyn, in.analysis.angle_steps, in.analysis.axis_steps), root, GloboidalIssuePaths());
  // A torque no contact can carry: the Hertz law (eq. 11) holds for penetrations small against
  // the radii; under the turret torque alone the static penetration δ = (F/K)^(1/n) at the start
  // angle must stay below a tenth of the roller radius (the paper example: see docs/globoidal.md).
  if (!s.speeds_rpm.empty() && s.dyn.load_torque_Nmm != 0.0) {
    DynamicsInput probe = s.dyn;
    probe.cam_speed_rad_s = 0.0;
    const double theta0 = probe.start_cam_angle_rad;
    double force = 0, k = 0;
    try {
      force = globoidal::QuasiStaticForce(probe, theta0);
      k = std::min(globoidal::RollerStiffness(probe, 1, theta0), globoidal::RollerStiffness(probe, 2, theta0));
    } catch (const std::domain_error&) {
      return s;  // no Hertz contact at the start angle: the dynamics stage reports it per speed
    }
    const double n = probe.contact.exponent, allowed = 0.1 * s.dyn.cam.roller_radius;
    const double delta = std::pow(force / k, 1.0 / n);
    if (!(delta <= allowed)) {
      const double t_max = std::abs(s.dyn.load_torque_Nmm) * 1e-3 * k * std::pow(allowed, n) / force;
      root["load"]["turret_torque_Nm"].Fail(
          "a torque whose static contact penetration stays below a tenth of the roller radius (" + Format(allowed, 4) +
          " mm; at most " + Format(t_max, 4) + " N·m here): it gives " + Format(delta, 4) +
          " mm, outside the Hertz contact law");
    }
  }
  return s;
}

namespace {

// result.json's members (Result's Serialize) from the model's numbers, in the file's units.
void FillResult(const Study& s, Result& r) {
  r.name = s.in.name;
  r.angle_steps = s.in.analysis.angle_steps;
  r.axis_steps = s.in.analysis.axis_steps;
  r.roller_axis_range_mm = {r.roller_axis_limits_mm.l1, r.roller_axis_limits_mm.l2};
  r.initial_angles_deg.top_dead_point = {r.initial_angle_top_deg[0], r.initial_angle_top_deg[1]};
  r.initial_angles_deg.bottom_dead_point = {r.initial_angle_bottom_deg[0], r.initial_angle_bottom_deg[1]};
  r.roller_angle_ranges_deg = {r.roller_angle_range_deg[0], r.roller_angle_range_deg[1]};
  const auto& alpha = r.survey.max_abs_pressure_angle;
  const auto& margin = r.survey.min_undercut_margin;
  const auto& rcontact = r.survey.min_contact_radius;
  r.max_pressure_angle_deg = alpha.value / kDeg;
  // "warnings" only when there is one (RunStudy adds the list to every result.json).
  if (alpha.value > globoidal::kHighPressureAngle)
    r.warnings = std::vector<std::string>{
        "the pressure angle reaches " + Format(alpha.value / kDeg) + " deg, above the " +
        Format(globoidal::kHighPressureAngle / kDeg) +
        " deg warning limit (docs/globoidal.md): large side thrust on the turret, near jamming"};
  r.max_pressure_angle_at = {alpha.cam_angle_rad / kDeg, alpha.axis_mm, alpha.roller};
  r.min_undercut_margin = margin.value;
  r.min_undercut_margin_at = {margin.cam_angle_rad / kDeg, margin.axis_mm, margin.roller};
  r.min_offset_area_ratio = r.survey.min_offset_jacobian.value;
  r.conformal_contact = r.survey.conformal;
  if (rcontact.set) {
    r.min_contact_radius_mm = rcontact.value;
    r.min_contact_radius_at = Result::At{rcontact.cam_angle_rad / kDeg, std::nullopt, rcontact.roller};
  }
  r.motion.joints = JointRows(r.joints);
  r.motion.peak_velocity_deg_per_rad = r.peak_velocity_deg_per_rad;
  r.motion.peak_acceleration_deg_per_rad2 = r.peak_acceleration_deg_per_rad2;
  r.motion.peak_jerk_deg_per_rad3 = r.peak_jerk_deg_per_rad3;
  if (!s.geometry.write) r.geometry_files = GeometryFilesOf(s.geometry, {});
  if (s.in.analysis.evaluate) {
    r.evaluated = std::vector<std::string>{"geometry"};
    if (s.dynamics_stage) r.evaluated->push_back("dynamics");
    if (s.export_stage) r.evaluated->push_back("export");
  }
  if (s.dynamics_stage) {
    r.load = Result::Load{s.dyn.load_torque_Nmm * 1e-3, s.dyn.inertia_Nmms2 * 1e-3};
    r.effective_modulus = r.effective_modulus_MPa;
  }
  if (!s.dynamics_stage) {
    // not asked for: no dynamics entry at all
  } else if (!r.dynamics_skipped.empty()) {
    r.dynamics = Result::Dynamics{r.dynamics_skipped, std::nullopt, std::nullopt, std::nullopt};
  } else {
    std::vector<Result::SpeedRow> speeds;
    for (const SpeedResult& x : r.speeds) {
      Result::SpeedRow row;
      row.cam_speed_rpm = x.cam_speed_rpm;
      if (!x.failed.empty()) {
        row.failed = x.failed;
        speeds.push_back(std::move(row));
        continue;
      }
      row.end_time_s = x.end_time_s;
      row.relative_tolerance = s.in.dynamics.relative_tolerance;
      row.absolute_tolerance = s.in.dynamics.absolute_tolerance;
      row.steps = x.steps;
      row.rhs_evaluations = x.rhs_evaluations;
      row.contact_events = x.events;
      row.smallest_step_s = x.smallest_step_s;
      row.largest_step_s = x.largest_step_s;
      row.peak_turret_velocity_kinematic_rad_s = x.peak_turret_velocity_kinematic_rad_s;
      row.peak_turret_velocity_dynamic_rad_s = x.peak_turret_velocity_dynamic_rad_s;
      row.peak_turret_acceleration_kinematic_rad_s2 = x.peak_turret_acceleration_kinematic_rad_s2;
      row.peak_turret_acceleration_dynamic_rad_s2 = x.peak_turret_acceleration_dynamic_rad_s2;
      row.max_force_roller_1_N = x.max_force_roller_1_N;
      row.max_force_roller_2_N = x.max_force_roller_2_N;
      row.max_contact_stress_MPa = x.max_contact_stress_MPa;
      row.max_contact_stress_at_cam_angle_deg = x.max_contact_stress_cam_angle_deg;
      row.max_quasi_static_force_N = x.max_quasi_static_force_N;
      row.max_swing_deviation_deg = x.max_swing_deviation_deg;
      row.max_penetration_mm = x.max_penetration_mm;
      speeds.push_back(std::move(row));
    }
    // The largest contact stress over the speeds run, for the verdict.
    const SpeedResult* worst = nullptr;
    for (const SpeedResult& x : r.speeds)
      if (x.failed.empty() && (!worst || x.max_contact_stress_MPa > worst->max_contact_stress_MPa)) worst = &x;
    if (worst) {
      r.max_contact_stress_MPa = worst->max_contact_stress_MPa;
      r.max_contact_stress_at = Result::StressAt{worst->cam_speed_rpm, worst->max_contact_stress_cam_angle_deg};
      r.contact_stress_model =
          "Hertz line contact along the roller length: p0 = sqrt(F E* / (pi m R)), R the eq. (12) radius "
          "at that instant (docs/globoidal.md \"Limits and verdict\")";
    }
    r.dynamics = Result::Dynamics{std::nullopt, "F = K δ^e + step(δ, 0, 0, d, C_max) δ̇ (eqs. 10–14)",
                                  "CVODE (BDF, variable step and order), contact onset "
                                  "and loss located as events; peaks over every step",
                                  std::move(speeds)};
  }
  // The verdict (docs/globoidal.md "Limits and verdict"): each limit beside its value.
  r.limits.pressure_angle_deg = s.in.limits.pressure_angle_deg;
  if (s.pressure_angle_limit_default) r.limits.defaults.push_back("pressure_angle_deg");
  r.pressure_angle_ok = alpha.value / kDeg <= s.in.limits.pressure_angle_deg;
  bool ok = r.pressure_angle_ok && !r.undercut && r.rib_thickness_at_l2_mm >= 0.0;
  if (s.in.limits.contact_stress_MPa) {
    r.limits.contact_stress_MPa = *s.in.limits.contact_stress_MPa;
    if (r.max_contact_stress_MPa) {
      r.contact_stress_ok = *r.max_contact_stress_MPa <= *s.in.limits.contact_stress_MPa;
      ok = ok && *r.contact_stress_ok;
    } else {
      r.notes = std::vector<std::string>{
          "limits.contact_stress_MPa is not checked: the contact stress comes from the dynamics, "
          "which did not run (no cam speed, not asked for, or skipped)"};
    }
  }
  r.limits_ok = ok;
  if (s.export_point_cloud || s.export_stl)
    r.surface_export = Result::SurfaceExport{
        "cam frame oxyz, oz the cam axis, mm; θ = 0 at the start of the first motion",
        s.in.export_.angle_steps,
        s.in.export_.axis_steps,
        s.export_stl ? "working_surfaces.stl" : "",
        s.geometry.stl_ascii ? "ascii" : "binary",
        s.export_stl && s.geometry.step ? "working_surfaces.step" : "",
        s.geometry.dxf_tolerance_um,
        "not written: the two working surfaces are open bands (the rib's crest and root surfaces are not "
        "modelled), so they close no solid",
        s.export_point_cloud ? "working_surfaces.csv" : ""};
}

}  // namespace

Result Run(const Study& s, const RunContext& ctx) {
  const GloboidalCam<double>& cam = s.dyn.cam;
  const auto lim = globoidal::RollerAxisLimits(cam);
  const double arm = globoidal::ContactArm(s.dyn);
  const int n = s.in.analysis.angle_steps, na = s.in.analysis.axis_steps;
  auto theta = [&](int i) { return 2 * kPi * i / n; };
  auto col = [&](auto fn) {
    std::vector<double> v(n);
    for (int i = 0; i < n; ++i) v[i] = fn(i);
    return v;
  };

  Result r;
  r.roller_axis_limits_mm = lim;
  const double b = cam.roller_angle, f = cam.swing;
  for (int j = 1; j <= 2; ++j) {
    r.initial_angle_top_deg[j - 1] = globoidal::InitialAngle(b, f, j, 1) / kDeg;
    r.initial_angle_bottom_deg[j - 1] = globoidal::InitialAngle(b, f, j, -1) / kDeg;
  }
  r.rib_thickness_at_l2_mm = globoidal::RibThickness(cam);
  r.contact_arm_mm = arm;

  // Geometry over the cycle (model/globoidal/check.h; Parse checked the jam limit on it): the
  // extremes, and on the analysis grid the pressure angle at both ends of the roller axis, the
  // undercut margin, the roller angle and the contact radius at the contact arm.
  r.survey = globoidal::SurveyCycle(cam, arm, n, na);
  const auto& g = r.survey.grid;
  auto& t = r.series;
  for (int j = 0; j < 2; ++j) {
    const std::vector<double>& phi = g.roller_angle[j];
    r.roller_angle_range_deg[j] = {*std::min_element(phi.begin(), phi.end()) / kDeg,
                                   *std::max_element(phi.begin(), phi.end()) / kDeg};
    t.roller_angle_deg[j] = col([&](int i) { return phi[i] / kDeg; });
    t.pressure_angle_deg[j][0] = col([&](int i) { return g.pressure_angle_at_l1[j][i] / kDeg; });
    t.pressure_angle_deg[j][1] = col([&](int i) { return g.pressure_angle_at_l2[j][i] / kDeg; });
    t.contact_radius_mm[j] = g.contact_radius[j];
  }
  t.min_undercut_margin = g.min_undercut_margin;
  r.undercut = r.survey.min_undercut_margin.value <= 0.0;

  // Motion program: continuity and peak coefficients.
  r.joints = motion::CheckContinuity(cam.motion, 1e-7);
  const std::vector<motion::Svaj<double>> svaj = SampleMotion(cam.motion, n);
  const MotionPeaks peaks = PeakDerivatives(svaj);
  r.peak_velocity_deg_per_rad = peaks.velocity / kDeg;
  r.peak_acceleration_deg_per_rad2 = peaks.acceleration / kDeg;
  r.peak_jerk_deg_per_rad3 = peaks.jerk / kDeg;
  t.cam_angle_deg = col([&](int i) { return 360.0 * i / n; });
  t.swing_deg = col([&](int i) { return svaj[i].s / kDeg; });
  t.swing_velocity_deg_per_rad = col([&](int i) { return svaj[i].v / kDeg; });
  t.swing_acceleration_deg_per_rad2 = col([&](int i) { return svaj[i].a / kDeg; });
  t.swing_jerk_deg_per_rad3 = col([&](int i) { return svaj[i].j / kDeg; });

  // Quasi-static forces and dynamics per speed (the "dynamics" stage).
  r.effective_modulus_MPa = s.dyn.contact.composite_modulus_MPa();
  const bool conformal = r.survey.conformal;
  if (!s.dynamics_stage) {
    // not asked for
  } else if (!s.speeds_rpm.empty() && (r.undercut || conformal)) {
    r.dynamics_skipped = r.undercut ? "the working surface is undercut"
                                    : "the contact is conformal (no Hertz radius)";
  } else {
    Progress progress("globoidal_cam dynamics", ctx.quiet);
    for (size_t k = 0; k < s.speeds_rpm.size(); ++k) {
      const double rpm = s.speeds_rpm[k];
      progress.Update(double(k) / s.speeds_rpm.size(), Format(rpm) + " rpm");
      DynamicsInput in = s.dyn;
      in.cam_speed_rad_s = rpm * 2 * kPi / 60;
      in.end_time_s = s.EndTime(rpm);
      in.relative_tolerance = s.in.dynamics.relative_tolerance;
      in.absolute_tolerance = s.in.dynamics.absolute_tolerance;
      in.max_steps = s.in.dynamics.max_steps;
      in.output_interval_s = in.end_time_s / 2000;  // the CSV's samples; not the peaks
      SpeedResult sr;
      sr.cam_speed_rpm = rpm;
      globoidal::DynamicsResult dr;
      try {
        dr = globoidal::SimulateDynamics(in);
      } catch (const std::domain_error& e) {
        sr.failed = e.what();
        r.speeds.push_back(std::move(sr));
        continue;
      } catch (const globoidal::DynamicsError& e) {
        // Settings that cannot work: exit 2, naming the setting to change.
        const std::string field = e.setting() == "max_steps" ? "max_steps" : "relative_tolerance";
        throw StudyError(ctx.study_file + ": /dynamics/" + field + ": at " + Format(rpm) +
                         " rpm: " + e.what());
      }
      sr.end_time_s = in.end_time_s;
      sr.steps = dr.steps;
      sr.rhs_evaluations = dr.rhs_evaluations;
      sr.events = dr.events;
      sr.smallest_step_s = dr.smallest_step_s;
      sr.largest_step_s = dr.largest_step_s;
      // Quasi-static force over the revolution at this speed.
      sr.quasi_static_force_N = col([&](int i) { return globoidal::QuasiStaticForce(in, theta(i)); });
      // Peaks over every accepted solver step, step midpoint and contact event.
      const globoidal::DynamicsPeaks& pk = dr.peaks;
      sr.peak_turret_velocity_kinematic_rad_s = pk.kin_rate_rad_s;
      sr.peak_turret_velocity_dynamic_rad_s = pk.swing_rate_rad_s;
      sr.peak_turret_acceleration_kinematic_rad_s2 = pk.kin_acc_rad_s2;
      sr.peak_turret_acceleration_dynamic_rad_s2 = pk.swing_acc_rad_s2;
      sr.max_force_roller_1_N = pk.force_N[0];
      sr.max_force_roller_2_N = pk.force_N[1];
      const int js = pk.contact_stress_MPa[1] > pk.contact_stress_MPa[0] ? 1 : 0;
      sr.max_contact_stress_MPa = pk.contact_stress_MPa[js];
      sr.max_contact_stress_cam_angle_deg =
          std::fmod((in.start_cam_angle_rad + in.cam_speed_rad_s * pk.contact_stress_time_s[js]) / kDeg, 360.0);
      sr.max_quasi_static_force_N =
          *std::max_element(sr.quasi_static_force_N.begin(), sr.quasi_static_force_N.end());
      sr.max_swing_deviation_deg = pk.swing_deviation_rad / kDeg;
      sr.max_penetration_mm = pk.penetration_mm;
      sr.samples = std::move(dr.samples);
      r.speeds.push_back(std::move(sr));
    }
    progress.Update(1.0);
    progress.Done();
  }

  // Working surfaces to export.
  if (s.export_point_cloud || s.export_stl) {
    const int ne = s.in.export_.angle_steps, ml = s.in.export_.axis_steps;
    for (int k = 0; k < ml; ++k) r.surface_axis_mm.push_back(globoidal::AxisGridPoint(lim, k, ml));
    for (int j = 1; j <= 2; ++j) {
      auto& pts = r.surface_points[j - 1];
      auto& nrm = r.surface_normals[j - 1];
      pts.resize(ne), nrm.resize(ne);
      for (int i = 0; i < ne; ++i) {
        for (int k = 0; k < ml; ++k) {
          const SurfacePoint<double> p =
              globoidal::EvaluateSurface(cam, j, r.surface_axis_mm[k], 2 * kPi * i / ne);
          pts[i].push_back(p.working);
          nrm[i].push_back(p.normal);
        }
      }
    }
  }
  FillResult(s, r);
  return r;
}

void Write(const Study& s, const Result& r, Outputs& out) {
  out.SetResult(r);
  const auto& t = r.series;
  const auto& th = t.cam_angle_deg;

  Table table;
  table.Add("cam_angle_deg", th);
  table.Add("swing_deg", t.swing_deg);
  table.Add("swing_velocity_deg_per_rad", t.swing_velocity_deg_per_rad);
  table.Add("swing_acceleration_deg_per_rad2", t.swing_acceleration_deg_per_rad2);
  table.Add("swing_jerk_deg_per_rad3", t.swing_jerk_deg_per_rad3);
  table.Add("roller_1_angle_deg", t.roller_angle_deg[0]);
  table.Add("roller_2_angle_deg", t.roller_angle_deg[1]);
  table.Add("pressure_angle_roller_1_at_l1_deg", t.pressure_angle_deg[0][0]);
  table.Add("pressure_angle_roller_1_at_l2_deg", t.pressure_angle_deg[0][1]);
  table.Add("pressure_angle_roller_2_at_l1_deg", t.pressure_angle_deg[1][0]);
  table.Add("pressure_angle_roller_2_at_l2_deg", t.pressure_angle_deg[1][1]);
  table.Add("min_undercut_margin", t.min_undercut_margin);
  table.Add("contact_radius_roller_1_mm", t.contact_radius_mm[0]);
  table.Add("contact_radius_roller_2_mm", t.contact_radius_mm[1]);

  for (const SpeedResult& x : r.speeds) {
    if (!x.failed.empty()) continue;
    const std::string tag = SpeedTag(x.cam_speed_rpm);
    table.Add("quasi_static_force_" + tag + "_N", x.quasi_static_force_N);
    Table dt;
    auto dcol = [&](auto fn) {
      std::vector<double> v;
      for (const auto& smp : x.samples) v.push_back(fn(smp));
      return v;
    };
    using Sample = globoidal::DynamicsSample;
    dt.Add("time_s", dcol([](const Sample& q) { return q.time_s; }));
    dt.Add("cam_angle_deg", dcol([](const Sample& q) { return q.cam_angle_rad / kDeg; }));
    dt.Add("swing_deg", dcol([](const Sample& q) { return q.swing_rad / kDeg; }));
    dt.Add("swing_rate_rad_s", dcol([](const Sample& q) { return q.swing_rate_rad_s; }));
    dt.Add("swing_acc_rad_s2", dcol([](const Sample& q) { return q.swing_acc_rad_s2; }));
    dt.Add("kinematic_swing_deg", dcol([](const Sample& q) { return q.kin_swing_rad / kDeg; }));
    dt.Add("kinematic_rate_rad_s", dcol([](const Sample& q) { return q.kin_rate_rad_s; }));
    dt.Add("kinematic_acc_rad_s2", dcol([](const Sample& q) { return q.kin_acc_rad_s2; }));
    dt.Add("penetration_roller_1_mm", dcol([](const Sample& q) { return q.penetration_mm[0]; }));
    dt.Add("penetration_roller_2_mm", dcol([](const Sample& q) { return q.penetration_mm[1]; }));
    dt.Add("force_roller_1_N", dcol([](const Sample& q) { return q.force_N[0]; }));
    dt.Add("force_roller_2_N", dcol([](const Sample& q) { return q.force_N[1]; }));
    out.Add("dynamics_" + tag + ".csv", ToCsv(dt));
    const std::string at = Format(x.cam_speed_rpm) + " rpm";
    {
      PlotOptions o;
      o.title = s.in.name + ": contact forces at " + at;
      o.x_label = "cam angle [deg]";
      o.y_label = "force [N]";
      out.Add("contact_forces_" + tag + ".svg",
              SvgLinePlot({{"quasi-static", th, x.quasi_static_force_N},
                           {"roller 1", dt.columns[1], dt.columns[10]},
                           {"roller 2", dt.columns[1], dt.columns[11]}},
                          o));
    }
    {
      // The paper's Figs. 6–7: turret velocity and acceleration against time.
      PlotOptions o;
      o.title = s.in.name + ": turret velocity at " + at;
      o.x_label = "time [s]";
      o.y_label = "angular velocity [rad/s]";
      out.Add("turret_velocity_" + tag + ".svg",
              SvgLinePlot({{"dynamic", dt.columns[0], dt.columns[3]},
                           {"modified sine", dt.columns[0], dt.columns[6]}},
                          o));
      o.title = s.in.name + ": turret acceleration at " + at;
      o.y_label = "angular acceleration [rad/s²]";
      out.Add("turret_acceleration_" + tag + ".svg",
              SvgLinePlot({{"dynamic", dt.columns[0], dt.columns[4]},
                           {"modified sine", dt.columns[0], dt.columns[7]}},
                          o));
    }
  }
  out.Add("series.csv", ToCsv(table));

  // Surface export: a point cloud with the rib's outward normal (toward the roller), and STL.
  if (s.export_point_cloud || s.export_stl) {
    const int ne = s.in.export_.angle_steps;
    cad::TriangleMesh mesh;
    std::vector<cad::PointGrid> grids;
    std::vector<double> cr, cl, ct, cx, cy, cz, cnx, cny, cnz;
    for (int j = 1; j <= 2; ++j) {
      const auto& pts = r.surface_points[j - 1];
      const auto& nrm = r.surface_normals[j - 1];
      for (int i = 0; i < ne; ++i) {
        for (size_t k = 0; k < r.surface_axis_mm.size(); ++k) {
          const Vec3<double>& p = pts[i][k];
          const Vec3<double>& nv = nrm[i][k];
          cr.push_back(j), cl.push_back(r.surface_axis_mm[k]), ct.push_back(360.0 * i / ne);
          cx.push_back(p.x()), cy.push_back(p.y()), cz.push_back(p.z());
          cnx.push_back(-nv.x()), cny.push_back(-nv.y()), cnz.push_back(-nv.z());
        }
      }
      if (s.export_stl) {
        AppendSurfaceMesh(mesh, pts, nrm);
        cad::PointGrid grid(pts.begin(), pts.end());
        grid.push_back(pts.front());  // closed around the cam
        grids.push_back(std::move(grid));
      }
    }
    if (s.export_stl) {
      out.Add("working_surfaces.stl", StlFile(mesh, "globoidal_working_surfaces", s.geometry));
      // Each working surface as one cubic B-spline surface within the geometry files' tolerance of
      // its grid points (OCCT's approximation).
      if (s.geometry.step)
        out.Add("working_surfaces.step",
                cad::BSplineSurfaces(grids, s.in.name + " working surfaces", s.geometry.dxf_tolerance_um * 1e-3).step);
    }
    if (s.export_point_cloud) {
      Table cloud;
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
  }

  // Over time at the first cam speed simulated (the others scale as ω, ω², ω³).
  AddSvajPlots(out, s.in.name + ": turret swing", "deg", th,
               {&t.swing_deg, &t.swing_velocity_deg_per_rad, &t.swing_acceleration_deg_per_rad2,
                &t.swing_jerk_deg_per_rad3},
               s.speeds_rpm.empty() ? 0.0 : s.speeds_rpm.front());
  {
    auto series = [&](const std::string& label, const std::vector<double>& y) {
      return Series{label, th, y};
    };
    PlotOptions o;
    o.title = s.in.name + ": pressure angle";
    o.x_label = "cam angle [deg]";
    o.y_label = "pressure angle [deg]";
    std::vector<double> all;
    for (const auto& roller : t.pressure_angle_deg)
      for (const std::vector<double>& at : roller) all.insert(all.end(), at.begin(), at.end());
    o.guides = PressureAngleLimitLines(s.in.limits.pressure_angle_deg, all);
    out.Add("pressure_angle.svg",
            SvgLinePlot({series("roller 1 at l1", t.pressure_angle_deg[0][0]),
                         series("roller 1 at l2", t.pressure_angle_deg[0][1]),
                         series("roller 2 at l1", t.pressure_angle_deg[1][0]),
                         series("roller 2 at l2", t.pressure_angle_deg[1][1])},
                        o));
  }
}

namespace {

// The declared input of a study, for the estimates below that run before Parse.
Input ReadInput(const nlohmann::json& study, const std::string& file) { return Read<Input>(Node(&study, file, "")); }

// Fidelity for `camopt run --convergence` (studies/convergence.h): the analysis grid of the
// geometry and, when the dynamics run, CVODE's tolerances. The variants skip the surface export.
Fidelity Knobs(const nlohmann::json& study) {
  const Input in = ReadInput(study, "");
  const Input defaults;
  Fidelity f;
  f.knobs.push_back({"angle_steps", {"/analysis/angle_steps"}, defaults.analysis.angle_steps, 2, true, 0,
                     "cam angles of the geometry survey (extrema are sampled)"});
  f.knobs.push_back({"axis_steps", {"/analysis/axis_steps"}, defaults.analysis.axis_steps, 2, true, 0,
                     "points along the roller axis of the geometry survey"});
  f.headlines = {"/max_pressure_angle_deg", "/min_undercut_margin", "/min_contact_radius_mm"};
  const auto& evaluate = in.analysis.evaluate;
  const bool dynamics = !evaluate || std::find(evaluate->begin(), evaluate->end(), "dynamics") != evaluate->end();
  if (dynamics && !in.dynamics.cam_speeds_rpm.empty()) {
    f.knobs.push_back({"relative_tolerance", {"/dynamics/relative_tolerance"}, defaults.dynamics.relative_tolerance,
                       0.1, false, 0, "CVODE's relative tolerance"});
    f.knobs.push_back({"absolute_tolerance", {"/dynamics/absolute_tolerance"}, defaults.dynamics.absolute_tolerance,
                       0.1, false, 0, "CVODE's absolute tolerance [rad, rad/s]"});
    for (size_t i = 0; i < in.dynamics.cam_speeds_rpm.size(); ++i) {
      const std::string p = "/dynamics/speeds/" + std::to_string(i) + "/";
      f.headlines.push_back(p + "peak_turret_acceleration_dynamic_rad_s2");
      f.headlines.push_back(p + "max_force_roller_1_N");
      f.headlines.push_back(p + "max_penetration_mm");
    }
  }
  f.variant_overrides["/export/stl"] = false;
  f.variant_overrides["/export/point_cloud"] = false;
  return f;
}

// The work limit (studies/work_limits.h): the dynamics run on CVODE with error control, about
// 5000 accepted steps per cam revolution at the default tolerance (docs/globoidal.md), never more
// than max_steps per speed; the geometry survey's grid; the exported surface points.
WorkEstimate EstimateWork(const nlohmann::json& study, const std::string& file, double factor) {
  const Input in = ReadInput(study, file);
  const Input::Dynamics& d = in.dynamics;
  constexpr double kStepsPerRevolution = 5000, kStepsPerSecond = 1e4;
  double steps = 0;
  for (const double rpm : d.cam_speeds_rpm) {
    const double revolutions = d.end_time_s ? *d.end_time_s * rpm / 60.0 : 1.0;
    // A slow cam under a light load: the steps follow the simulated time, not the revolutions
    // (the paper cam at 1 N·m: 6.3k steps per simulated second from 1 to 0.1 rpm).
    const double seconds = d.end_time_s ? *d.end_time_s : 60.0 / rpm;
    steps += std::min(std::max(revolutions * kStepsPerRevolution, seconds * kStepsPerSecond), double(d.max_steps));
  }
  const Input::Analysis& a = in.analysis;
  const Input::Export& x = in.export_;
  return LargestTerm(
      {{steps, "/dynamics",
        WorkNumber(double(d.cam_speeds_rpm.size())) + " cam speeds, the larger of " +
            WorkNumber(kStepsPerRevolution) + " solver steps per revolution and " + WorkNumber(kStepsPerSecond) +
            " per simulated second"},
       {double(a.angle_steps) * a.axis_steps, "/analysis/angle_steps",
        WorkNumber(a.angle_steps) + " angle steps × " + WorkNumber(a.axis_steps) + " axis steps"},
       {double(x.angle_steps) * x.axis_steps, "/export/angle_steps",
        WorkNumber(x.angle_steps) + " × " + WorkNumber(x.axis_steps) + " surface points"}},
      1e7 * factor, "time steps and surface points", 150);
}

CAMOPT_REGISTER_KIND(Kind<Input, Result, Study>{
    .name = "globoidal_cam",
    .title = "camopt study: globoidal cam indexer: pressure angle, undercut, rib thickness, contact stress and roller forces at speed",
    .run = Run, .parse = Parse, .write = Write, .knobs = Knobs, .estimate = EstimateWork,
    .report = std::vector<Headline>{
        {"largest pressure angle", "/max_pressure_angle_deg", "deg", "/limits/pressure_angle_deg"},
        {"largest contact stress (dynamics, line contact)", "/max_contact_stress_MPa", "MPa", "/limits/contact_stress_MPa"},
        {"smallest contact radius", "/min_contact_radius_mm", "mm"},
        {"smallest undercut margin", "/min_undercut_margin", "", "", 0.0, false},
        {"undercut", "/undercut", ""},
        {"rib thickness at l2", "/rib_thickness_at_l2_mm", "mm", "", 0.0, false},
        {"largest force on roller 1 (first speed)", "/dynamics/speeds/0/max_force_roller_1_N", "N"},
        {"largest quasi-static force (first speed)", "/dynamics/speeds/0/max_quasi_static_force_N", "N"},
    },
    .asked = std::vector<AskedBlock>{
        {{"/dynamics"}, "/dynamics", "the dynamics", {"dynamics"}},
        {{"/export/stl", "/export/point_cloud"}, "/surface_export", "the surface export", {"export"}},
    },
    .init_example = "globoidal_cam_paper"});
}  // namespace

}  // namespace camopt::studies::globoidal_cam
