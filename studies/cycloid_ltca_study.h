// Study kind "cycloid_ltca": loaded tooth contact analysis of a cycloid stage over the crank
// angles (model/cycloid/, docs/cycloid.md). Outputs result.json, per_angle.csv, backlash.csv,
// lte.svg, gear_ratio.svg, contact_stress.svg, pressure_map.svg (every contacting pair at the
// angle of the maximum stress), pressure_max.csv and a tooth drawing (tooth.svg, tooth.dxf).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/common/geometry.h"
#include "model/cycloid/crowning.h"
#include "model/cycloid/loaded_tca.h"
#include "model/cycloid/output_mechanism.h"
#include "model/cycloid/stiffness.h"
#include "studies/cycloid_life.h"
#include "studies/cycloid_study_common.h"
#include "studies/input.h"
#include "studies/geometry_files.h"
#include "studies/study.h"

namespace camopt::studies::cycloid_ltca {

/// The output mechanism with clearance and compliance (model/cycloid/output_mechanism.h): the
/// "output_mechanism" object with pin_radius_mm and hole_radius_mm.
struct OutputSpec {
  cycloid::OutputPins pins;  ///< face width and E* filled from the drive and the material
  cycloid::PinSupport support = cycloid::PinSupport::kCantilever;
  double span_mm = 0;        ///< the pin's span (cantilever: flange to free end)
};

struct Study {
  std::string name;
  cycloid::Drive drive;
  cycloid::Crowning crowning;
  cycloid::Material material;
  double torque_Nm = 0;  ///< on the disc, as in the file
  cycloid::LoadedOptions options;
  std::vector<double> crank_angles_rad;
  /// Uniform samples of one mesh period 2π/n1 (0 when the file gives crank_angle_steps or
  /// crank_angles_deg instead).
  int crank_angles_per_mesh_period = 0;
  /// analysis.estimate_error: the refinement runs (the half-step-shifted crank angles, whose union
  /// with the study's angles is the doubled set reported, and the coarse grid) and the errors.
  bool estimate_error = true;
  /// analysis.evaluate: false when only the unloaded TCA is asked (["unloaded"]): no material, load
  /// or contact solves; the loaded stage ("loaded", the default) includes the unloaded one.
  bool loaded = true;
  double bore_diameter_mm = 0;   ///< drive.bore_diameter_mm: bore of the disc's solid, 0 = none
  GeometryFileOptions geometry;  ///< "geometry_files"
  /// The bearing life (load.input_speed_rpm or duty_cycle, the ratings, the output mechanism;
  /// docs/life.md, "Cycloid"); nullopt: no life asked, result.json without "life".
  std::optional<cycloid_common::LifeSpec> life;
  /// "output_mechanism" with the pins' and holes' radii; nullopt: no output-mechanism outputs.
  std::optional<OutputSpec> output;
  /// "stiffness": {"rated_torque_Nm", "crank_angle_deg"}: the torsional curve (model/cycloid/stiffness.h).
  struct StiffnessSpec {
    double rated_torque_Nm = 0, crank_angle_deg = 0;
  };
  std::optional<StiffnessSpec> stiffness;
  int discs = 1;                 ///< "discs": N, phased by 360°/N about the crank, each carrying T/N
  double disc_spacing_mm = 0;    ///< "disc_spacing_mm": mid-plane to mid-plane (default the face width)
  /// The torque on each disc [N·mm]: load.torque_Nm (the output torque) over the discs (equal split
  /// of identical discs).
  double disc_torque_Nmm() const { return torque_Nm * 1000.0 / discs; }
};

using cycloid_common::ElementLife;
using cycloid_common::LifeResult;

/// Default samples per mesh period: peak-to-peak LTE and GR need >= 20 (docs/cycloid.md).
inline constexpr int kDefaultCrankAnglesPerMeshPeriod = 32;
/// Largest factor on |v(N) − v(2N)| in the crank-angle error (no shrinking of the differences
/// observed); the smallest is 1 (docs/cycloid.md, "Estimated error").
inline constexpr double kMaxTailFactor = 4.0;
/// A headline output whose estimated error exceeds this share of its value gets a warning.
inline constexpr double kErrorShare = 0.05;

/// analysis.tolerance above this moves the peak-to-peak LTE or GR of the paper's examples by more
/// than kToleranceShare of its value (measured: docs/cycloid.md, "Solver tolerance"): a warning.
inline constexpr double kLooseTolerance = 0.1;
inline constexpr double kToleranceShare = 0.05;

struct Result {
  /// Per angle (meshes) and over the cycle, at crank_angles_rad: the study's angles, or their
  /// union with the half-step-shifted set (twice as many) when the crank angles were refined.
  cycloid::CycleResult cycle;
  std::vector<double> crank_angles_rad;  ///< the angles of `cycle` (and of the per-angle outputs)
  double composite_modulus_MPa = 0;
  /// Unloaded backlash [arcsec] per roller (outer index) and crank angle; −1 off the loaded flank.
  std::vector<std::vector<double>> backlash_arcsec;
  std::string warning;          ///< the first angle that did not converge, or empty
  /// Estimated discretisation error of each headline output (by its result.json name, its unit):
  /// the sum of the grid and crank-angle parts; empty when not estimated.
  std::vector<std::pair<std::string, double>> estimated_error, error_grid, error_crank;
  std::array<int, 2> coarse_grid{0, 0};  ///< the grid of the error run
  /// Angles of the coarser sampling the crank-angle error compares with (the study's own, when
  /// the reported cycle is the doubled set); 0: not estimated.
  int crank_error_angles = 0;
  std::vector<std::string> warnings;     ///< headline errors above kErrorShare, and the like
  std::vector<double> unloaded_te_arcsec;    ///< β0 per crank angle (both stages)
  std::vector<Vec2<double>> tooth_profile;   ///< the modified profile of the whole disc [mm]
  std::vector<Vec2<double>> roller_centres;  ///< in the disc frame at crank angle 0 [mm]
  PlanarCamFit tooth_files;  ///< the disc's geometry files (arcs of the modified profile)
  std::optional<LifeResult> life;
  /// The output mechanism over the crank bearing's load period (output_angles_rad), per disc k:
  /// the disc's own solve at its crank angle φ + 2πk/N.
  struct DiscSample {
    cycloid::OutputPinLoads<double> pins;
    Vec2<double> bearing_crank_frame{0.0, 0.0};  ///< B on the disc, the disc's crank frame
    Vec2<double> bearing_fixed_frame{0.0, 0.0};
  };
  std::vector<double> output_angles_rad;
  std::vector<std::vector<DiscSample>> output;  ///< [angle][disc]
  std::vector<double> net_crank_force_N;        ///< |Σ_k B_k| per angle (the crankshaft's net radial load)
  std::vector<double> crank_couple_Nmm;         ///< |Σ_k (z_k − z̄) B_k| per angle
  std::vector<double> pin_bending_stress_MPa;   ///< per angle, the largest over the pins
  double max_output_pin_force_N = 0, max_contact_pressure_MPa = 0, max_bearing_load_N = 0,
         max_bending_stress_MPa = 0, max_net_crank_force_N = 0, max_couple_Nmm = 0, max_moment_residual = 0;
  std::optional<cycloid::TorsionCurve> torsion;       ///< with "stiffness"
  /// Why the output mechanism or the torsional curve could not be solved (a torque the output pins
  /// cannot carry); empty when solved. Their result keys are then null, and `warnings` says why.
  std::string output_failed, torsion_failed;
  std::vector<double> bearing_load_at_ltca_angles_N;  ///< |B| of disc 1 at crank_angles_rad (per_angle.csv)
};

/// @throws StudyError for bad input (exit 2).
Study Parse(const Node& root);
Result Run(const Study& study, const RunContext& ctx);
nlohmann::json ToJson(const Study& study, const Result& result);
/// result.json and the tables, plots and drawings listed above.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::cycloid_ltca
