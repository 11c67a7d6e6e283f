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
#include <vector>

#include <nlohmann/json.hpp>

#include "model/globoidal/check.h"
#include "model/globoidal/contact_dynamics.h"
#include "model/globoidal/globoidal.h"
#include "model/motion/motion_program.h"
#include "studies/input.h"
#include "studies/geometry_files.h"
#include "studies/study.h"

namespace camopt::studies::globoidal_cam {

/// The study file, parsed and validated (CheckDesign passed), in model units.
struct Study {
  std::string name;
  globoidal::DynamicsInput dyn;  ///< the cam, the contact material, the load and the inertia
  std::vector<double> speeds_rpm;
  double end_time_s = -1.0;  ///< ≤ 0: one cam revolution
  double relative_tolerance = 1e-8;   ///< CVODE's local error control (dynamics)
  double absolute_tolerance = 1e-10;  ///< [rad, rad/s] on ψ − φ_i and its rate
  int max_steps = 20000000;           ///< accepted solver steps per speed
  int angle_steps = 720;
  int axis_steps = 7;
  int export_angle_steps = 360;
  int export_axis_steps = 6;
  bool export_stl = true, export_point_cloud = true;
  GeometryFileOptions geometry;  ///< "geometry_files": STL format, STEP surfaces
  /// The stages asked for ("analysis.evaluate"; all when absent). The geometry always runs (the
  /// other stages need it); without "dynamics" no load, contact material or speeds are needed and
  /// none are simulated; without "export" no surfaces are built.
  bool dynamics_stage = true, export_stage = true;
  bool evaluate_given = false;
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
  double max_quasi_static_force_N = 0.0, max_swing_deviation_deg = 0.0, max_penetration_mm = 0.0;
  std::vector<double> quasi_static_force_N;         ///< on the analysis grid
  /// The thinned samples for the CSV and the plots (the peaks above do not come from them).
  std::vector<globoidal::DynamicsSample> samples;
};

/// Every number the kind reports.
struct Result {
  globoidal::AxisLimits<double> roller_axis_limits_mm;
  /// φ₀ of rollers 1, 2 at the top and the bottom dead point [deg], eq. (7).
  std::array<double, 2> initial_angle_top_deg, initial_angle_bottom_deg;
  std::array<std::array<double, 2>, 2> roller_angle_range_deg;  ///< [roller][min, max]
  double rib_thickness_at_l2_mm = 0.0;
  globoidal::CycleSurvey survey;  ///< extremes in model units (rad, mm)
  bool undercut = false;
  double contact_arm_mm = 0.0;

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
/// result.json.
nlohmann::json ToJson(const Study& study, const Result& result);
/// result.json, series.csv, dynamics CSVs, SVG plots, working_surfaces.csv/.stl.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::globoidal_cam
