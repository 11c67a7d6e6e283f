// Up-front limits on the work of a study: one place that estimates, from the sizes in the study
// file, how much a study will compute and how much memory it will hold, before anything runs.
// A study over its cap is refused at once (exit 2) with the estimate and the cap, instead of
// running for hours or exhausting memory. The caps are sized for a laptop (about a minute of
// work and well under 2 GB); --max-work-factor F multiplies every cap for a bigger machine.
//
// Caps per study kind (work units, with F = 1):
//   lcr_analysis (in the kind's file) angle_steps × rollers + profile_points × lobes  ≤ 2e7
//   lcr_friction_fit                angle_steps × rollers + measurements  ≤ 2e7 (in the kind's file)
//   transmission_rigidity           elements ≤ 1000; Σ reducer angle_steps × rollers × 2 ≤ 2e6
//   globoidal_cam (in the kind's file) Σ over speeds of solver steps (≈5000 per revolution) ≤ 1e7; surface points ≤ 1e7
//   cycloid_ltca (in the kind's file) runs (2.25 with the error estimate) × crank angles (a list,
//                                   crank_angle_steps or crank_angles_per_mesh_period) × rollers × cells ≤ 5e7
//   cycloid_crowning_tuning (kind's file) (curve_points + max_evaluations) × 2 × angles × rollers × cells ≤ 5e7
//   cycloid_min_size (kind's file) max_evaluations × (starts + verify_rounds) × (2 + 0.65 variables) ×
//                                   torques × angles × rollers × cells + the accurate checks ≤ 5e8
//   disc_cam (in the kind's file)   angle_steps + MC samples × angle_steps × scales ≤ 2e6
//   disc_cam_min_size (kind's file) max_evaluations × (8 + verify_rounds) × 3 × angle_steps, and the
//                                   accurate checks (1 + verify_rounds) × 3 × dense angles ≤ 1e8
//   lcr_min_size (kind's file)      lobe counts × differences × catalogue rollers × starts × (0.5 +
//                                   samples_per_period/48) + with a 3D contact 30·(slices/20)³ per
//                                   candidate and the half_space verification + robust Monte-Carlo ≤ 2e4
//   lcr_crowning_tuning (kind's file) evaluations × 2 cams × 2 torques × misalignments × 69 × (slices/40)³
//                                   + half_space checks and verification (100 per 48×256 grid)
//                                   + the load stage's angle_steps ≤ 1e5
//   lcr_analysis's 3D contact adds its slices and half_space solves; every fidelity knob of every
//   kind is counted (tests/reliability_test.cc WorkLimits.EveryFidelityKnobOfEveryExampleIsCounted).
//   every kind                      estimated memory ≤ 2 GB
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace camopt::studies {

/// The estimate of one study: `work` in the kind's unit, against `cap` (already × factor).
struct WorkEstimate {
  double work = 0;          ///< estimated work units
  double cap = 0;           ///< the cap for this kind × factor
  double memory_bytes = 0;  ///< estimated peak memory of the results held
  std::string unit;         ///< what one unit is ("roller contact evaluations", …)
  std::string path;         ///< JSON path of the size that dominates ("/analysis/angle_steps")
  std::string detail;       ///< how the estimate was formed ("3600 angle steps × 28 rollers")
};

/// The memory cap with factor 1, in bytes.
constexpr double kMaxMemoryBytes = 2.0e9;

/// Estimates the work of a study from its raw JSON (before the kind parses it; values of the wrong
/// type count as their defaults, the kind reports them). Unknown kinds estimate zero.
WorkEstimate EstimateWork(const nlohmann::json& study, const std::string& file, double factor);

/// The estimate of a kind that reads its declared input (studies/archive.h): the study as read,
/// defaults filled in. It may throw the StudyError its reader throws (the kind's parse would refuse
/// the study with the same message).
using WorkEstimator =
    std::function<WorkEstimate(const nlohmann::json& study, const std::string& file, double factor)>;

/// One term of an estimate: the work it adds, the path that sets it and how it was formed.
struct WorkTerm {
  double work;
  std::string path;
  std::string detail;
};
/// The estimate of a sum of terms, named by its largest one; memory is work × bytes_per_unit.
WorkEstimate LargestTerm(std::vector<WorkTerm> terms, double cap, std::string unit, double bytes_per_unit);
/// A number for an estimate's text ("%.3g").
std::string WorkNumber(double v);

/// Throws a StudyError "FILE: PATH: the study needs about X UNIT (DETAIL), more than the cap of Y;
/// raise the caps with --max-work-factor" when the work or the memory is over its cap × factor.
void CheckWorkLimits(const nlohmann::json& study, const std::string& file, double factor);

/// Throws StudyError unless 1e-6 <= factor <= 1e6 (NaN and infinity would switch every cap off):
/// the CLI's --max-work-factor range, for the Python API and the sweep as well.
void CheckWorkFactor(double factor);

}  // namespace camopt::studies
