// Study plumbing shared by the kinds that drive a follower with a motion program (disc_cam,
// globoidal_cam): parsing the "motion" array, the joints' continuity report, the program sampled
// over a cam revolution, and the four SVAJ plots.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/motion/motion_program.h"
#include "studies/archive.h"
#include "studies/input.h"
#include "studies/study.h"

namespace camopt::studies {

/// How a kind writes its follower's rise in the study file.
struct MotionInputSpec {
  std::string rise_key;        ///< "rise_mm" or "rise_deg"
  double rise_scale = 1.0;     ///< model units per file unit: 1 (mm) or π/180 (deg → rad)
  std::string unit;            ///< "mm" or "deg", in messages
  std::string subject;         ///< "follower" or "turret", in messages
  /// A rise key in the other unit that is rejected with `misplaced_hint` ("" for none: then it
  /// is an unknown field like any other).
  std::string misplaced_key, misplaced_hint;
  /// Accept "law": "polynomial" segments with "boundary": {"start": {…}, "end": {…}}: `position_UNIT`
  /// and `velocity_UNIT_per_deg` required, `acceleration_UNIT_per_deg2` and `jerk_UNIT_per_deg3`
  /// optional (docs/disc_cam.md "Polynomial segments").
  bool allow_polynomial = false;
};

/// Parses a "motion" array of `{law, RISE_KEY, cam_angle_deg}` (or, with spec.allow_polynomial,
/// `{"law": "polynomial", cam_angle_deg, boundary}`) into a program that covers one cam revolution
/// and returns to its start. Every boundary value of a polynomial segment must continue its
/// neighbours (position from the program so far, derivatives from the segment before or after).
/// Throws StudyError naming the segment and field, and for a discontinuity the two values.
motion::MotionProgram<double> ParseMotionProgram(const Node& motion, const MotionInputSpec& spec);

/// The rules of a "motion" array that JSON Schema cannot state, as ParseMotionProgram checks them:
/// the cam angles sum to 360°, the rises return the follower to its start, a B-spline has more
/// control points than its degree, a polynomial segment continues its neighbours. For the
/// CrossFieldRules of the object that holds "motion".
std::vector<CrossFieldRule> MotionRules();

/// The root-level rules of a follower kind's "motion" (MotionSchema of both specs) by follower
/// type, as ParseMotionProgram holds them: with a follower of `types` (the "follower" object's
/// "type") each segment uses `spec`'s unit only (the other unit's rise, boundary keys and control
/// points refused), a moving law has a non-zero rise and a dwell none (0 when given).
nlohmann::ordered_json FollowerRiseRule(const MotionInputSpec& spec, const MotionInputSpec& other,
                                        const std::vector<std::string>& types);

/// The JSON Schema of a "motion" array as ParseMotionProgram reads it, for a kind whose follower
/// may be any of `specs` (one per follower type; their rise keys side by side, the polynomial
/// segments' boundary keys in either unit): the laws (polynomial when specs[0].allow_polynomial),
/// each rise key described with `rise_notes` (same order), and with `rise_rules` the rise by law in
/// the schema (a moving law has a non-zero rise, a dwell none or 0; one rise key only).
nlohmann::ordered_json MotionSchema(const std::vector<MotionInputSpec>& specs,
                                    const std::vector<std::string>& rise_notes, bool rise_rules);

/// The program at n equally spaced cam angles θᵢ = 2π i/n (model units).
std::vector<motion::Svaj<double>> SampleMotion(const motion::MotionProgram<double>& program, int n);

/// Largest |S'|, |S''|, |S'''| over samples (model units per rad^k).
struct MotionPeaks {
  double velocity = 0.0, acceleration = 0.0, jerk = 0.0;
};
MotionPeaks PeakDerivatives(const std::vector<motion::Svaj<double>>& samples);

/// A joint of the motion program as result.json writes it: the segment it follows, its cam angle
/// and its continuity ("C0".."C3" or "discontinuous").
struct JointRow {
  int after_segment = 0;
  double cam_angle_deg = 0;
  std::string continuity;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("after_segment", &after_segment, Field().Desc("the segment the joint follows (0-based)"));
    a->Visit("cam_angle_deg", &cam_angle_deg, Field().Unit("°").Desc("where it is"));
    a->Visit("continuity", &continuity, Field().Desc("C0 … C3: S and its derivatives up to that order continuous there; "
                                                     "or discontinuous"));
  }
};
std::vector<JointRow> JointRows(const std::vector<motion::JointContinuity>& joints);

/// svaj.svg: displacement S, velocity, acceleration and jerk stacked over the cam angle [deg],
/// the derivatives per degree of cam (columns are per radian, as series.csv has them); with a cam
/// speed (speed_rpm > 0) also svaj_time.svg, the same over the time of one revolution [ms] with
/// the derivatives per second. `unit` is S's unit ("mm", "deg"); titles start with `title`.
void AddSvajPlots(Outputs& out, const std::string& title, const std::string& unit,
                  const std::vector<double>& cam_angle_deg,
                  const std::array<const std::vector<double>*, 4>& per_rad, double speed_rpm);

}  // namespace camopt::studies
