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
#include "studies/cycloid_life.h"
#include "studies/cycloid_study_common.h"
#include "studies/input.h"
#include "studies/geometry_files.h"
#include "studies/study.h"

namespace camopt::studies::cycloid_ltca {

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
};

/// @throws StudyError for bad input (exit 2).
Study Parse(const Node& root);
Result Run(const Study& study, const RunContext& ctx);
nlohmann::json ToJson(const Study& study, const Result& result);
/// result.json and the tables, plots and drawings listed above.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::cycloid_ltca
