// Study kind "globoidal_cam": a globoidal cam with an oscillating, dual-stopping (two-roller)
// turret (Ge, Wang & Zhang; docs/globoidal.md). Geometry over a cam revolution (eqs. 1–9: roller
// angles, trajectory and working surfaces, pressure angle, undercut, contact radius), the
// quasi-static roller force, the Adams-style contact dynamics at the requested cam speeds
// (eqs. 10–14; CVODE with error control and contact events), and the working surfaces exported as a CSV point cloud and an ASCII STL mesh.
// Outputs: result.json, series.csv, dynamics_<rpm>rpm.csv, SVG plots, working_surfaces.csv,
// working_surfaces.stl.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/globoidal/check.h"
#include "model/globoidal/contact_dynamics.h"
#include "model/globoidal/globoidal.h"
#include "model/motion/motion_program.h"
#include "studies/archive.h"
#include "studies/input.h"
#include "studies/geometry_files.h"
#include "studies/motion_input.h"
#include "studies/study.h"

namespace camopt::studies::globoidal_cam {

/// The study file as declared: each field once, in the file's units, with its default, bounds
/// and description (studies/archive.h). Parse reads it, checks what spans fields, and converts it
/// to the model's units (Study); `camopt schema globoidal_cam` is emitted from it.
struct Input {
  struct Cam {
    double center_distance_mm = 0, roller_radius_mm = 0, pitch_radius_mm = 0, roller_length_mm = 0,
           clearance_mm = 0, roller_angle_deg = 0, swing_deg = 0;
    std::string first_motion = "clockwise";
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("center_distance_mm", &center_distance_mm,
               Field().Required().Positive().Unit("mm").Desc("C, between the cam axis and the turret axis"));
      a->Visit("roller_radius_mm", &roller_radius_mm,
               Field().Required().Positive().Unit("mm").Desc("R, of each roller (1e-6 to 1e6 times C)"));
      a->Visit("pitch_radius_mm", &pitch_radius_mm,
               Field().Required().Positive().Unit("mm").Desc("R_e, turret axis to the roller's base end"));
      a->Visit("roller_length_mm", &roller_length_mm,
               Field().Required().Positive().Unit("mm").Desc("m, the roller's length along its axis"));
      a->Visit("clearance_mm", &clearance_mm,
               Field().Required().NonNegative().Unit("mm").Desc("e, between the roller and the turret"));
      a->Visit("roller_angle_deg", &roller_angle_deg,
               Field().Required().Positive().Below(180, "an angle in (0, 180) deg").Unit("deg")
                   .Desc("β, between the two rollers of a pair"));
      a->Visit("swing_deg", &swing_deg,
               Field().Required().Positive().Below(90, "an angle in (0, 90) deg").Unit("deg")
                   .Desc("φ_f, the turret's swing (its motion's rise)"));
      a->Visit("first_motion", &first_motion,
               Field().OneOf({"clockwise", "anticlockwise"}).Desc("direction of the turret's first motion"));
    }
  };
  struct Load {
    double turret_torque_Nm = 0.0, turret_inertia_kgm2 = 0.01;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("turret_torque_Nm", &turret_torque_Nm,
               Field().Unit("N·m").Desc("constant load on the turret, against its motion"));
      a->Visit("turret_inertia_kgm2", &turret_inertia_kgm2,
               Field().Positive().Unit("kg·m²").Desc("the turret's moment of inertia J"));
    }
  };
  struct Contact {
    /// The new names (GPa, poisson_ratio) and their old ones (MPa, poisson): one of each pair.
    std::optional<double> cam_youngs_modulus_GPa, roller_youngs_modulus_GPa, cam_poisson_ratio,
        roller_poisson_ratio, cam_modulus_MPa, roller_modulus_MPa, cam_poisson, roller_poisson;
    double exponent = globoidal::ContactMaterial{}.exponent;
    double max_damping_Ns_per_mm = globoidal::ContactMaterial{}.max_damping_Ns_per_mm;
    double penetration_depth_mm = globoidal::ContactMaterial{}.penetration_depth_mm;
    std::optional<double> contact_arm_mm;
    template <typename Archive>
    void Serialize(Archive* a) {
      const globoidal::ContactMaterial m;
      for (const auto& [side, E, nu, old_E, old_nu, default_E, default_nu] :
           {std::tuple{"cam", &cam_youngs_modulus_GPa, &cam_poisson_ratio, &cam_modulus_MPa, &cam_poisson,
                       m.cam_modulus_MPa, m.cam_poisson},
            std::tuple{"roller", &roller_youngs_modulus_GPa, &roller_poisson_ratio, &roller_modulus_MPa,
                       &roller_poisson, m.roller_modulus_MPa, m.roller_poisson}}) {
        const std::string s = side;
        a->Visit((s + "_youngs_modulus_GPa").c_str(), E,
                 Field().Positive().Unit("GPa").Default(default_E / 1000.0).Desc(s + "'s Young's modulus"));
        a->Visit((s + "_poisson_ratio").c_str(), nu,
                 Field().In(0.0, 0.499).Default(default_nu).Desc(s + "'s Poisson's ratio"));
        a->Visit((s + "_modulus_MPa").c_str(), old_E,
                 Field().Positive().Unit("MPa").Desc("old name: " + s + "'s Young's modulus in MPa (use " + s +
                                                     "_youngs_modulus_GPa)"));
        a->Visit((s + "_poisson").c_str(), old_nu,
                 Field().In(0.0, 0.499).Desc("old name of " + s + "_poisson_ratio"));
      }
      a->Alias("cam_youngs_modulus_GPa", "cam_modulus_MPa");
      a->Alias("roller_youngs_modulus_GPa", "roller_modulus_MPa");
      a->Alias("cam_poisson_ratio", "cam_poisson");
      a->Alias("roller_poisson_ratio", "roller_poisson");
      a->Visit("exponent", &exponent, Field().In(1.0, 3.0).Desc("e of the contact law F = K δ^e (eq. 10)"));
      a->Visit("max_damping_Ns_per_mm", &max_damping_Ns_per_mm,
               Field().NonNegative().Unit("N·s/mm").Desc("C_max, the full contact damping (eq. 14)"));
      a->Visit("penetration_depth_mm", &penetration_depth_mm,
               Field().Positive().Unit("mm").Desc("d, the penetration of full damping (eq. 14)"));
      a->Visit("contact_arm_mm", &contact_arm_mm,
               Field().Positive().Unit("mm").Desc("l_c, turret axis to the contact point, in [l₂, l₁] (absent: R_e)"));
    }
    static std::vector<CrossFieldRule> CrossFieldRules() {
      return {{{"contact_arm_mm"}, "l_c on the roller: in [l₂, l₁] of the cam's geometry (CheckContactArm)",
               "expected a length in [l₂, l₁]"}};
    }
  };
  struct Dynamics {
    std::vector<double> cam_speeds_rpm;
    std::optional<double> end_time_s;
    double relative_tolerance = 1e-8, absolute_tolerance = 1e-10;
    int max_steps = 20000000;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Retired("time_step_s",
                 "no longer used: the dynamics run with error control (CVODE); give "
                 "\"relative_tolerance\" (e.g. 1e-8) and \"absolute_tolerance\" (e.g. 1e-10) instead");
      // 0.01 rpm (a revolution in 100 minutes) to 1e5 rpm: the simulated time of a revolution
      // and its solver steps stay countable (the work estimate).
      a->Visit("cam_speeds_rpm", &cam_speeds_rpm,
               Field().In(0.01, 1e5).Unit("rpm").Desc("cam speeds to simulate, one run each"));
      a->Visit("end_time_s", &end_time_s,
               Field().Positive().Unit("s").Desc("simulated time per speed (absent: one cam revolution)"));
      a->Visit("relative_tolerance", &relative_tolerance,
               Field().Positive().In(1e-13, 1e-3,
                                     "a relative tolerance in [1e-13, 1e-3] (tighter is beyond double precision, "
                                     "looser cannot resolve the contact oscillation)")
                   .Desc("CVODE's local relative error control"));
      a->Visit("absolute_tolerance", &absolute_tolerance,
               Field().Positive().In(1e-16, 1e-4,
                                     "an absolute tolerance in [1e-16, 1e-4] rad (on the deviation ψ − φ_i and its rate)")
                   .Unit("rad, rad/s").Desc("CVODE's absolute error control on ψ − φ_i and its rate"));
      a->Visit("max_steps", &max_steps,
               Field().AtLeast(1).AtMost(200000000, "a whole number <= 2e8").Desc("accepted solver steps per speed, at most"));
    }
    static std::vector<CrossFieldRule> CrossFieldRules() {
      return {{{"max_steps", "end_time_s", "cam_speeds_rpm"},
               "max_steps covers the simulated time at every speed (a step spans at most 0.5° of cam)",
               "the run needs at least"}};
    }
  };
  struct Analysis {
    int angle_steps = 720, axis_steps = 7;
    std::optional<std::vector<std::string>> evaluate;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("angle_steps", &angle_steps,
               Field().AtLeast(36).AtMost(200000).Desc("cam angles of the geometry survey over a revolution"));
      a->Visit("axis_steps", &axis_steps,
               Field().AtLeast(2).AtMost(1000).Desc("points along the roller axis of the geometry survey"));
      a->Visit("evaluate", &evaluate,
               Field().OneOf({"geometry", "dynamics", "export"})
                   .Desc("the stages to run (absent: all; the geometry always runs)"));
    }
  };
  struct Export {
    bool stl = true, point_cloud = true;
    int angle_steps = 360, axis_steps = 6;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("stl", &stl, Field().Desc("write working_surfaces.stl (and .step)"));
      a->Visit("point_cloud", &point_cloud, Field().Desc("write working_surfaces.csv"));
      a->Visit("angle_steps", &angle_steps, Field().AtLeast(36).Desc("cam angles of the exported surfaces"));
      a->Visit("axis_steps", &axis_steps, Field().AtLeast(2).Desc("points along the roller axis of the exported surfaces"));
    }
    static std::vector<CrossFieldRule> CrossFieldRules() {
      return {{{"angle_steps", "axis_steps"}, "angle_steps × axis_steps below 4e6 (the exported points)",
               "must stay below 4e6"}};
    }
  };

  /// The limits of the verdict (docs/globoidal.md "Limits and verdict").
  struct Limits {
    double pressure_angle_deg = 45.0;
    std::optional<double> contact_stress_MPa;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("pressure_angle_deg", &pressure_angle_deg,
               Field().Positive().Below(89, "a pressure angle > 0 and < 89 deg (the jam limit)").Unit("deg")
                   .Desc("largest |α| allowed over the cycle (Rothbart's 45° for a follower on a pivot, the turret)"));
      a->Visit("contact_stress_MPa", &contact_stress_MPa,
               Field().Positive().Unit("MPa").Desc(
                   "largest Hertz contact stress allowed in the dynamics (absent: not checked; it depends on the "
                   "material)"));
    }
  };

  std::string study = "globoidal_cam", name = "globoidal cam";
  std::optional<std::string> description;
  Cam cam;
  nlohmann::json motion;
  Load load;
  Contact contact;
  Dynamics dynamics;
  Analysis analysis;
  Export export_;
  Limits limits;
  GeometryFiles geometry_files = true;

  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Required().Const("globoidal_cam").Desc("the study kind"));
    a->Visit("name", &name, Field().Desc("the design's name, in titles"));
    a->Visit("description", &description, Field().Desc("free text"));
    a->Visit("cam", &cam, Field().Required().Desc("the cam and the turret (Ge, Wang & Zhang, eqs. 1–9)"));
    a->Visit("motion", &motion, Field().Required().Schema(MotionSchema()).Desc(
        "the turret's swing over one cam revolution: segments whose cam angles sum to 360"));
    a->Visit("load", &load, Field().Desc("the turret's load"));
    a->Visit("contact", &contact, Field().Desc("the contact law of the dynamics (eqs. 10–14)"));
    a->Visit("dynamics", &dynamics, Field().Desc("the contact dynamics at the given cam speeds"));
    a->Visit("analysis", &analysis, Field().Desc("the geometry survey's grid and the stages to run"));
    a->Visit("export", &export_, Field().Desc("the working surfaces as a point cloud and a mesh"));
    a->Visit("limits", &limits, Field().Desc("the limits of the verdict; each has a default or is not checked"));
    a->Visit("geometry_files", &geometry_files,
             Field().Desc(
                 "geometry files (docs/studies.md 'Geometry files'); false: no STL/STEP of the working "
                 "surfaces (whatever export.stl says; the point cloud stays)"));
  }
  /// The schema of a "motion" segment (read by ParseMotionProgram, shared with disc_cam).
  static nlohmann::ordered_json MotionSchema();
  /// The motion's rules, and the turret torque a Hertz contact carries.
  static std::vector<CrossFieldRule> CrossFieldRules() {
    std::vector<CrossFieldRule> rules = MotionRules();
    rules.push_back({{"load", "contact", "cam"},
                     "the turret torque's static contact penetration (F/K)^(1/e) at the start angle below a tenth of "
                     "the roller radius (the Hertz law's range)",
                     "static contact penetration"});
    return rules;
  }
};

/// The study as Run takes it: the file as declared (`in`, in the file's units) and, checked
/// (CheckDesign passed), what the model is built from and the stages to run.
struct Study {
  Input in;
  globoidal::DynamicsInput dyn;  ///< the cam, the contact material, the load and the inertia (model units)
  /// The cam speeds simulated: dynamics.cam_speeds_rpm, none without the dynamics stage.
  std::vector<double> speeds_rpm;
  bool export_stl = true, export_point_cloud = true;  ///< export's files, when that stage runs and files are on
  GeometryFileOptions geometry;  ///< "geometry_files": STL format, STEP surfaces
  /// The stages asked for ("analysis.evaluate"; all when absent). The geometry always runs (the
  /// other stages need it); without "dynamics" no load, contact material or speeds are needed and
  /// none are simulated; without "export" no surfaces are built.
  bool dynamics_stage = true, export_stage = true;
  bool pressure_angle_limit_default = true;  ///< limits.pressure_angle_deg not in the study
  /// dynamics.end_time_s, or one cam revolution at `rpm` [s].
  double EndTime(double rpm) const { return in.dynamics.end_time_s ? *in.dynamics.end_time_s : 60.0 / rpm; }
};

/// The dynamics at one cam speed, in the units of result.json.
struct SpeedResult {
  double cam_speed_rpm = 0.0;
  std::string failed;  ///< why the simulation stopped; empty when it ran
  double end_time_s = 0.0;
  long steps = 0, rhs_evaluations = 0;  ///< accepted solver steps, right-hand-side evaluations
  int events = 0;                       ///< contact onsets/losses located
  double smallest_step_s = 0.0, largest_step_s = 0.0;
  double peak_turret_velocity_kinematic_rad_s = 0.0, peak_turret_velocity_dynamic_rad_s = 0.0;
  double peak_turret_acceleration_kinematic_rad_s2 = 0.0;
  double peak_turret_acceleration_dynamic_rad_s2 = 0.0;
  double max_force_roller_1_N = 0.0, max_force_roller_2_N = 0.0;
  /// The largest Hertz line-contact stress of either roller over every solver step
  /// (globoidal::DynamicsPeaks::contact_stress_MPa) and the cam angle where it is [deg, 0–360).
  double max_contact_stress_MPa = 0.0, max_contact_stress_cam_angle_deg = 0.0;
  double max_quasi_static_force_N = 0.0, max_swing_deviation_deg = 0.0, max_penetration_mm = 0.0;
  std::vector<double> quasi_static_force_N;         ///< on the analysis grid
  /// The thinned samples for the CSV and the plots (the peaks above do not come from them).
  std::vector<globoidal::DynamicsSample> samples;
};

/// Every number the kind reports: result.json as declared (its `Serialize`; `camopt schema
/// globoidal_cam --result`), then the model's numbers the CSV, SVG and surface files are drawn from.
struct Result {
  struct PerRoller {
    double roller_1 = 0, roller_2 = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("roller_1", &roller_1, Field().Unit("deg"));
      a->Visit("roller_2", &roller_2, Field().Unit("deg"));
    }
  };
  struct DeadPoints {
    PerRoller top_dead_point, bottom_dead_point;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("top_dead_point", &top_dead_point, Field().Desc("φ₀ of each roller, eq. (7)"));
      a->Visit("bottom_dead_point", &bottom_dead_point, Field().Desc("φ₀ of each roller, eq. (7)"));
    }
  };
  struct RollerRanges {
    std::array<double, 2> roller_1{}, roller_2{};
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("roller_1", &roller_1, Field().Unit("deg").Desc("[min, max]"));
      a->Visit("roller_2", &roller_2, Field().Unit("deg").Desc("[min, max]"));
    }
  };
  struct AxisRange {
    double l1 = 0, l2 = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("l1", &l1, Field().Unit("mm").Desc("the working surface's inner end on the roller axis"));
      a->Visit("l2", &l2, Field().Unit("mm").Desc("its outer end"));
    }
  };
  /// Where an extreme is.
  struct At {
    double cam_angle_deg = 0;
    std::optional<double> axis_mm;
    int roller = 1;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("cam_angle_deg", &cam_angle_deg, Field().Unit("deg"));
      a->Visit("axis_mm", &axis_mm, Field().Unit("mm").Desc("along the roller axis"));
      a->Visit("roller", &roller, Field().Desc("1 or 2"));
    }
  };
  struct MotionSummary {
    std::vector<JointRow> joints;
    double peak_velocity_deg_per_rad = 0, peak_acceleration_deg_per_rad2 = 0, peak_jerk_deg_per_rad3 = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("joints", &joints, Field().Desc("the motion program's joints and their continuity"));
      a->Visit("peak_velocity_deg_per_rad", &peak_velocity_deg_per_rad, Field().Unit("deg/rad"));
      a->Visit("peak_acceleration_deg_per_rad2", &peak_acceleration_deg_per_rad2, Field().Unit("deg/rad²"));
      a->Visit("peak_jerk_deg_per_rad3", &peak_jerk_deg_per_rad3, Field().Unit("deg/rad³"));
    }
  };
  struct Load {
    double turret_torque_Nm = 0, turret_inertia_kgm2 = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("turret_torque_Nm", &turret_torque_Nm, Field().Unit("N·m"));
      a->Visit("turret_inertia_kgm2", &turret_inertia_kgm2, Field().Unit("kg·m²"));
    }
  };
  /// One cam speed's simulation: every member but the speed is absent when it `failed`.
  struct SpeedRow {
    double cam_speed_rpm = 0;
    std::optional<std::string> failed;
    std::optional<double> end_time_s, relative_tolerance, absolute_tolerance;
    std::optional<long> steps, rhs_evaluations;
    std::optional<int> contact_events;
    std::optional<double> smallest_step_s, largest_step_s;
    std::optional<double> peak_turret_velocity_kinematic_rad_s, peak_turret_velocity_dynamic_rad_s;
    std::optional<double> peak_turret_acceleration_kinematic_rad_s2, peak_turret_acceleration_dynamic_rad_s2;
    std::optional<double> max_force_roller_1_N, max_force_roller_2_N, max_contact_stress_MPa;
    std::optional<double> max_contact_stress_at_cam_angle_deg, max_quasi_static_force_N;
    std::optional<double> max_swing_deviation_deg, max_penetration_mm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("cam_speed_rpm", &cam_speed_rpm, Field().Unit("rpm"));
      a->Visit("failed", &failed, Field().Desc("why the simulation stopped, when it did"));
      a->Visit("end_time_s", &end_time_s, Field().Unit("s"));
      a->Visit("relative_tolerance", &relative_tolerance, Field().Desc("CVODE's"));
      a->Visit("absolute_tolerance", &absolute_tolerance, Field().Desc("CVODE's"));
      a->Visit("steps", &steps, Field().Desc("accepted solver steps"));
      a->Visit("rhs_evaluations", &rhs_evaluations, Field());
      a->Visit("contact_events", &contact_events, Field().Desc("contact onsets and losses located"));
      a->Visit("smallest_step_s", &smallest_step_s, Field().Unit("s"));
      a->Visit("largest_step_s", &largest_step_s, Field().Unit("s"));
      a->Visit("peak_turret_velocity_kinematic_rad_s", &peak_turret_velocity_kinematic_rad_s, Field().Unit("rad/s"));
      a->Visit("peak_turret_velocity_dynamic_rad_s", &peak_turret_velocity_dynamic_rad_s, Field().Unit("rad/s"));
      a->Visit("peak_turret_acceleration_kinematic_rad_s2", &peak_turret_acceleration_kinematic_rad_s2,
               Field().Unit("rad/s²"));
      a->Visit("peak_turret_acceleration_dynamic_rad_s2", &peak_turret_acceleration_dynamic_rad_s2,
               Field().Unit("rad/s²"));
      a->Visit("max_force_roller_1_N", &max_force_roller_1_N, Field().Unit("N"));
      a->Visit("max_force_roller_2_N", &max_force_roller_2_N, Field().Unit("N"));
      a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa, Field().Unit("MPa"));
      a->Visit("max_contact_stress_at_cam_angle_deg", &max_contact_stress_at_cam_angle_deg, Field().Unit("deg"));
      a->Visit("max_quasi_static_force_N", &max_quasi_static_force_N, Field().Unit("N"));
      a->Visit("max_swing_deviation_deg", &max_swing_deviation_deg, Field().Unit("deg"));
      a->Visit("max_penetration_mm", &max_penetration_mm, Field().Unit("mm"));
    }
  };
  /// The dynamics: `skipped` (why not run), or the contact model and each speed's simulation.
  struct Dynamics {
    std::optional<std::string> skipped, contact_model, integrator;
    std::optional<std::vector<SpeedRow>> speeds;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("skipped", &skipped, Field().Desc("why the dynamics were not run (undercut or conformal contact)"));
      a->Visit("contact_model", &contact_model, Field());
      a->Visit("integrator", &integrator, Field());
      a->Visit("speeds", &speeds, Field().Desc("one per cam speed"));
    }
  };
  struct StressAt {
    double cam_speed_rpm = 0, cam_angle_deg = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("cam_speed_rpm", &cam_speed_rpm, Field().Unit("rpm"));
      a->Visit("cam_angle_deg", &cam_angle_deg, Field().Unit("deg"));
    }
  };
  struct LimitsOut {
    double pressure_angle_deg = 0;
    std::vector<std::string> defaults;
    std::optional<double> contact_stress_MPa;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("pressure_angle_deg", &pressure_angle_deg, Field().Unit("deg").Desc("the largest pressure angle"));
      a->Visit("defaults", &defaults, Field().Desc("the limits the study did not give (their defaults apply)"));
      a->Visit("contact_stress_MPa", &contact_stress_MPa, Field().Unit("MPa").Desc("the largest contact stress"));
    }
  };
  struct SurfaceExport {
    std::string frame;
    int angle_steps = 0, axis_steps = 0;
    std::string stl, stl_format, step;
    double step_tolerance_um = 0;
    std::string solid, point_cloud;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("frame", &frame, Field());
      a->Visit("angle_steps", &angle_steps, Field());
      a->Visit("axis_steps", &axis_steps, Field());
      a->Visit("stl", &stl, Field().Desc("the STL file (empty: none)"));
      a->Visit("stl_format", &stl_format, Field().OneOf({"ascii", "binary"}));
      a->Visit("step", &step, Field().Desc("the STEP file (empty: none)"));
      a->Visit("step_tolerance_um", &step_tolerance_um, Field().Unit("µm"));
      a->Visit("solid", &solid, Field());
      a->Visit("point_cloud", &point_cloud, Field().Desc("the point cloud's CSV (empty: none)"));
    }
  };

  std::string study = "globoidal_cam", name;
  int angle_steps = 0, axis_steps = 0;
  AxisRange roller_axis_range_mm;           ///< result.json's roller_axis_limits_mm
  DeadPoints initial_angles_deg;
  RollerRanges roller_angle_ranges_deg;     ///< result.json's roller_angle_range_deg
  double rib_thickness_at_l2_mm = 0.0;
  double max_pressure_angle_deg = 0;
  std::optional<std::vector<std::string>> warnings;
  At max_pressure_angle_at, min_undercut_margin_at;
  bool undercut = false;
  double min_undercut_margin = 0, min_offset_area_ratio = 0;
  double contact_arm_mm = 0.0;
  bool conformal_contact = false;
  std::optional<double> min_contact_radius_mm;
  std::optional<At> min_contact_radius_at;
  MotionSummary motion;
  std::optional<GeometryFilesBlock> geometry_files;
  std::optional<std::vector<std::string>> evaluated;
  std::optional<Load> load;
  std::optional<double> effective_modulus;  ///< result.json's effective_modulus_MPa, with the dynamics
  std::optional<Dynamics> dynamics;
  std::optional<double> max_contact_stress_MPa;
  std::optional<StressAt> max_contact_stress_at;
  std::optional<std::string> contact_stress_model;
  LimitsOut limits;
  bool pressure_angle_ok = false;
  std::optional<bool> contact_stress_ok;
  std::optional<std::vector<std::string>> notes;
  bool limits_ok = false;
  std::optional<SurfaceExport> surface_export;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Const("globoidal_cam"));
    a->Visit("name", &name, Field().Desc("the cam's name"));
    a->Visit("angle_steps", &angle_steps, Field().Desc("cam angles of the analysis grid"));
    a->Visit("axis_steps", &axis_steps, Field().Desc("points along the roller axis"));
    a->Visit("roller_axis_limits_mm", &roller_axis_range_mm, Field().Desc("the working surface along the roller axis"));
    a->Visit("initial_angles_deg", &initial_angles_deg, Field());
    a->Visit("roller_angle_range_deg", &roller_angle_ranges_deg, Field());
    a->Visit("rib_thickness_at_l2_mm", &rib_thickness_at_l2_mm, Field().Unit("mm").Desc("< 0: the rib is cut through"));
    a->Visit("max_pressure_angle_deg", &max_pressure_angle_deg, Field().Unit("deg"));
    a->Visit("warnings", &warnings, Field());
    a->Visit("max_pressure_angle_at", &max_pressure_angle_at, Field());
    a->Visit("undercut", &undercut, Field().Desc("the working surface is undercut somewhere"));
    a->Visit("min_undercut_margin", &min_undercut_margin, Field().Desc("min 1 − R κ₁ (≤ 0: undercut)"));
    a->Visit("min_undercut_margin_at", &min_undercut_margin_at, Field());
    a->Visit("min_offset_area_ratio", &min_offset_area_ratio, Field().Desc("min area ratio working/trajectory surface"));
    a->Visit("contact_arm_mm", &contact_arm_mm, Field().Unit("mm"));
    a->Visit("conformal_contact", &conformal_contact, Field().Desc("the contact radius at the arm is ≤ 0 somewhere"));
    a->Visit("min_contact_radius_mm", &min_contact_radius_mm, Field().Unit("mm").Desc("eq. (12) at the contact arm, where > 0"));
    a->Visit("min_contact_radius_at", &min_contact_radius_at, Field());
    a->Visit("motion", &motion, Field());
    a->Visit("geometry_files", &geometry_files, Field().Desc("the geometry files not written, and why"));
    a->Visit("evaluated", &evaluated, Field().Desc("the stages run, when analysis.evaluate is given"));
    a->Visit("load", &load, Field().Desc("with the dynamics"));
    a->Visit("effective_modulus_MPa", &effective_modulus, Field().Unit("MPa").Desc("with the dynamics"));
    a->Visit("dynamics", &dynamics, Field().Desc("when asked for"));
    a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa, Field().Unit("MPa").Desc("over the speeds run"));
    a->Visit("max_contact_stress_at", &max_contact_stress_at, Field());
    a->Visit("contact_stress_model", &contact_stress_model, Field());
    a->Visit("limits", &limits, Field().Desc("the verdict's limits"));
    a->Visit("pressure_angle_ok", &pressure_angle_ok, Field());
    a->Visit("contact_stress_ok", &contact_stress_ok, Field().Desc("with a stress limit and the dynamics run"));
    a->Visit("notes", &notes, Field());
    a->Visit("limits_ok", &limits_ok, Field());
    a->Visit("surface_export", &surface_export, Field().Desc("with the surfaces exported"));
  }

  // Not in result.json: the model's numbers (rib_thickness_at_l2_mm, undercut and contact_arm_mm
  // above are both).
  globoidal::AxisLimits<double> roller_axis_limits_mm;
  /// φ₀ of rollers 1, 2 at the top and the bottom dead point [deg], eq. (7).
  std::array<double, 2> initial_angle_top_deg, initial_angle_bottom_deg;
  std::array<std::array<double, 2>, 2> roller_angle_range_deg;  ///< [roller][min, max]
  globoidal::CycleSurvey survey;  ///< extremes in model units (rad, mm)

  /// Series over the analysis grid (the columns of series.csv); angles in deg.
  struct Series {
    std::vector<double> cam_angle_deg, swing_deg, swing_velocity_deg_per_rad,
        swing_acceleration_deg_per_rad2, swing_jerk_deg_per_rad3;
    std::array<std::vector<double>, 2> roller_angle_deg;
    /// pressure_angle_deg[roller][0 at l₁, 1 at l₂]
    std::array<std::array<std::vector<double>, 2>, 2> pressure_angle_deg;
    std::vector<double> min_undercut_margin;
    std::array<std::vector<double>, 2> contact_radius_mm;
  } series;

  std::vector<motion::JointContinuity> joints;
  double peak_velocity_deg_per_rad = 0.0, peak_acceleration_deg_per_rad2 = 0.0,
         peak_jerk_deg_per_rad3 = 0.0;

  double effective_modulus_MPa = 0.0;
  /// Why the dynamics were not run (undercut or conformal contact); empty when they were.
  std::string dynamics_skipped;
  std::vector<SpeedResult> speeds;

  /// Working surfaces for export: points[roller][angle][axis] [mm] and the unit normals from
  /// the roller axis into the rib; empty when nothing is exported.
  std::array<std::vector<std::vector<globoidal::Vec3<double>>>, 2> surface_points, surface_normals;
  std::vector<double> surface_axis_mm;
};

/// Parses and validates a "globoidal_cam" study. @throws StudyError (exit 2) naming the JSON path.
Study Parse(const Node& root);
/// Geometry over the cycle, the dynamics at every speed and the surfaces to export.
Result Run(const Study& study, const RunContext& ctx);
/// result.json, series.csv, dynamics CSVs, SVG plots, working_surfaces.csv/.stl.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::globoidal_cam
