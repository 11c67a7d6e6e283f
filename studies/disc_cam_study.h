// Study kind "disc_cam": a disc cam with an offset translating or an oscillating roller follower
// (Rzine et al., docs/disc_cam.md). Profile, pressure and shift angles, curvature and undercut over
// a cam revolution; the mechanical error from the tolerances (worst case and RMS, eqs. 31–32); a
// Monte-Carlo check of the linearised error against the exact follower motion.
// Outputs: result.json, series.csv, SVAJ / angle / error plots (SVG), profile.svg, profile.dxf.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/disc_cam/disc_cam.h"
#include "model/common/material.h"
#include "model/disc_cam/exact_motion.h"
#include "model/disc_cam/kinetostatics.h"
#include "model/disc_cam/mechanical_error.h"
#include "model/motion/motion_program.h"
#include "studies/geometry_files.h"
#include "studies/input.h"
#include "studies/study.h"

namespace camopt::studies::disc_cam {

/// The study file, parsed and validated (CheckDesign passed), in model units.
struct Study {
  std::string name;
  camopt::disc_cam::DiscCam cam;
  camopt::disc_cam::Deviations<double> tolerances;  ///< [mm]
  int angle_steps = 3600;
  bool monte_carlo = true;  ///< off when asked or when every tolerance is zero
  camopt::disc_cam::MonteCarloOptions monte_carlo_options;
  /// The stages asked for ("analysis.evaluate"; all when absent). The profile always runs;
  /// without "error" (or "monte_carlo") no tolerances are needed and the mechanical error is not
  /// computed.
  bool error_stage = true;
  bool evaluate_given = false;
  /// Geometry files: cam thickness and bore of the solid [mm] (no STEP/STL without a thickness),
  /// a cutter radius for a cutter-path layer (0: none given), "geometry_files" options.
  double cam_thickness_mm = 0, bore_diameter_mm = 0, cutter_radius_mm = 0;
  GeometryFileOptions geometry;

  /// The limits of the verdict ("limits"; docs/disc_cam.md "Limits and verdict"). A limit not
  /// given takes its default (recorded in *_default): the pressure angle 30° translating / 45°
  /// oscillating, the radius margin the roller radius; the contact stress has no default.
  struct Limits {
    double pressure_angle_deg = 30.0;
    bool pressure_angle_default = true;
    double radius_margin_mm = 0.0;
    bool radius_margin_default = true;
    std::optional<double> contact_stress_MPa;  ///< no default: needs a material's strength
  } limits;
  /// Contact length of roller and cam [mm] and their material (both bodies), for the Hertz stress.
  std::optional<double> face_width_mm;
  std::optional<Material> material;
  /// Kinetostatic follower loads ("dynamics"; translating roller follower only).
  struct Dynamics {
    double speed_rpm = 0.0;
    std::string follower_axis = "vertical_above_cam";
    camopt::disc_cam::FollowerLoads loads;
  };
  std::optional<Dynamics> dynamics;
};

/// A value and the cam angle where it is reached.
struct AtAngle {
  double value = 0.0;
  double cam_angle_deg = 0.0;
};

struct MinMax {
  double min = 0.0, max = 0.0;
};

/// One tolerance scale of the Monte-Carlo check, in the units of result.json (µm at the roller
/// centre).
struct MonteCarloRow {
  double scale, max_linear_um, max_exact_um, max_difference_um, relative_difference;
  double at_cam_angle_deg, within_worst_case_fraction, worst_case_exceeded_by_um;
  double sample_rms_um, linear_rms_uniform_um;
};

/// Every number the kind reports. "Follower unit" is mm (translating) or deg (oscillating);
/// errors are at the roller centre in µm (l·Δξ for an oscillating follower).
struct Result {
  bool oscillating = false;
  std::string follower_unit;  ///< "mm" or "deg"

  /// Series over the analysis grid (the columns of series.csv).
  struct Series {
    std::vector<double> cam_angle_deg;
    std::vector<double> follower, velocity_per_rad, acceleration_per_rad2, jerk_per_rad3;
    std::vector<double> pressure_angle_deg, shift_angle_deg, radial_dimension_mm;
    std::vector<double> contact_x_mm, contact_y_mm, pitch_x_mm, pitch_y_mm, q_mm;
    std::vector<double> pitch_curvature_per_mm;
    std::vector<double> error_radial_um, error_roller_um, error_normal_um, error_worst_case_um,
        error_rms_um;
  } series;

  AtAngle max_radial_dimension_mm;
  double min_radial_dimension_mm = 0.0;
  AtAngle min_pressure_angle_deg, max_pressure_angle_deg;
  MinMax shift_angle_deg, cos_shift_over_cos_pressure;
  std::optional<AtAngle> min_radius_of_curvature_mm;          ///< convex parts; none when none
  std::optional<AtAngle> min_concave_radius_of_curvature_mm;  ///< concave parts
  bool undercut = false;
  std::vector<std::pair<double, double>> undercut_cam_angle_deg;  ///< [from, to] intervals

  AtAngle max_worst_case_error_um, max_rms_error_um;
  double min_worst_case_error_um = 0.0;
  MinMax radial_error_um, roller_error_um, normal_error_um;
  std::optional<AtAngle> max_worst_case_error_arcsec;  ///< oscillating only
  std::optional<double> max_rms_error_arcsec;          ///< oscillating only

  /// Largest |φ| where the follower rises or dwells (S' ≥ 0) and where it returns (S' < 0).
  AtAngle max_pressure_angle_rise_deg;
  std::optional<AtAngle> max_pressure_angle_return_deg;

  /// Kinetostatic loads (Study::dynamics given; model/disc_cam/kinetostatics.h).
  struct Loads {
    AtAngle min_contact_force_N, max_contact_force_N;
    AtAngle max_abs_camshaft_torque_Nm;     ///< largest |T|
    double min_camshaft_torque_Nm = 0.0, max_camshaft_torque_Nm = 0.0;  ///< signed range
    double jump_speed_rpm = 0.0;  ///< +infinity when the follower never decelerates
    double weight_N = 0.0;
    /// Peak Hertz stress (face width and material given); stress_finite false when a loaded
    /// point of the profile is undercut.
    bool stress_evaluated = false, stress_finite = true;
    AtAngle max_contact_stress_MPa;
    std::vector<double> contact_force_N, camshaft_torque_Nm, contact_stress_MPa;  ///< series
  };
  std::optional<Loads> loads;

  std::vector<motion::JointContinuity> joints;
  double peak_velocity = 0.0, peak_acceleration = 0.0, peak_jerk = 0.0;  ///< follower unit/rad^k

  enum class MonteCarlo { kOff, kSkippedUndercut, kDone } monte_carlo = MonteCarlo::kOff;
  bool error_evaluated = false;  ///< the mechanical-error stage ran (the error fields are set)
  std::vector<MonteCarloRow> monte_carlo_rows;
  PlanarCamFit profile_files;  ///< the cam's geometry files (arcs of the exact profile)
};

/// Parses and validates a "disc_cam" study. @throws StudyError (exit 2) naming the JSON path.
Study Parse(const Node& root);
/// Evaluates the cam over the analysis grid, the mechanical error and the Monte-Carlo check.
Result Run(const Study& study, const RunContext& ctx);
/// result.json.
nlohmann::json ToJson(const Study& study, const Result& result);
/// result.json, series.csv, the SVG plots, profile.svg and profile.dxf.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::disc_cam
