// Study kind "disc_cam_motion": the shape of one or more rises of a disc cam's motion program
// designed for an objective — the least peak acceleration, peak jerk, residual vibration (at a
// speed or over a band) or largest contact force — under the disc_cam limits (pressure angle,
// radius margin), a stroke and no separation of the follower up to a speed
// (objectives/disc_cam_motion.h, sizing/disc_cam_motion.h).
//
// The file is a disc_cam design (follower, base circle, motion, dynamics) whose motion marks the
// designed segments with "optimize": {"law": "bspline", "control_points": n, "degree": p,
// "boundary": {"velocity": true, "acceleration": true}}; the segment's own law is the start and a
// reference. The answer is verified by the accurate model (dense kinematics, CVODE dynamics); a
// design not verified ends with exit 3. Beside result.json: best_disc_cam.json (the best program
// as a disc_cam study that `camopt run` accepts as it is), svaj.csv and svaj.svg (the best law
// against the start law).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sizing/disc_cam_motion.h"
#include "studies/archive.h"
#include "studies/backend_input.h"
#include "studies/disc_cam_min_size_study.h"
#include "studies/disc_cam_study.h"
#include "studies/input.h"
#include "studies/study.h"
#include "studies/verification_json.h"

namespace camopt::studies::disc_cam_motion {

struct Input {
  struct Limits {
    std::optional<double> pressure_angle_deg, radius_margin_mm, contact_stress_MPa, stroke_mm, no_separation_up_to_rpm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("pressure_angle_deg", &pressure_angle_deg,
               Field().AtLeast(1.0, "a pressure angle >= 1 and < 89 deg (the jam limit)")
                   .Below(89.0, "a pressure angle >= 1 and < 89 deg (the jam limit)").Unit("deg")
                   .Desc("largest |φ| allowed over the cycle (absent: 30 translating, 45 oscillating)"));
      a->Visit("radius_margin_mm", &radius_margin_mm,
               Field().NonNegative().Unit("mm").Desc(
                   "the profile's smallest convex radius of curvature at least this (absent: the roller radius; a "
                   "knife edge: 0)"));
      a->Visit("contact_stress_MPa", &contact_stress_MPa,
               Field().Positive().Unit("MPa").Desc(
                   "peak Hertz stress between roller and cam under the kinetostatic load at dynamics.speed_rpm; needs "
                   "face_width_mm, material and dynamics; a translating roller follower only"));
      a->Visit("stroke_mm", &stroke_mm,
               Field().Positive().Unit("mm").Desc(
                   "the follower stays within [0, stroke] over the cycle: a designed rise neither dips below the "
                   "base circle nor overshoots (absent: not limited); a translating follower only"));
      a->Visit("no_separation_up_to_rpm", &no_separation_up_to_rpm,
               Field().Positive().Unit("rpm").Desc(
                   "the follower keeps contact at every cam speed up to this (needs dynamics.follower_stiffness_N_per_mm)"));
    }
  };
  struct Analysis {
    int angle_steps = 720, accurate_factor = 8, separation_speeds = 8;
    std::optional<std::array<double, 3>> residual_speeds_rpm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("angle_steps", &angle_steps,
               Field().AtLeast(36).AtMost(100000).Desc("cam angles of the fast rows (the optimizer's constraints)"));
      a->Visit("accurate_factor", &accurate_factor,
               Field().AtLeast(2).AtMost(64).Desc("the accurate model's grid is this many times finer"));
      a->Visit("separation_speeds", &separation_speeds,
               Field().AtLeast(1).AtMost(64).Desc(
                   "speeds of the no-separation rows up to limits.no_separation_up_to_rpm (the accurate check uses "
                   "four times as many)"));
      a->Visit("residual_speeds_rpm", &residual_speeds_rpm,
               Field().Positive().Expect("[lowest, highest, count], lowest <= highest, count a whole number >= 1")
                   .Unit("rpm").Desc("objective residual_vibration: the speed band [lowest, highest, count] whose "
                                     "largest residual amplitude is minimised (absent: dynamics.speed_rpm alone)"));
    }
  };
  /// The optimizer and the verification loop: disc_cam_min_size's block (the same solvers, budget and rounds).
  using Optimizer = disc_cam_min_size::Input::Optimizer;

  std::string study = "disc_cam_motion", name = "disc cam motion";
  std::optional<std::string> description;
  disc_cam::Input::Follower follower;
  double base_circle_radius_mm = 0.0;
  nlohmann::json motion;
  std::string objective;
  std::optional<Limits> limits;
  std::optional<disc_cam::Input::Dynamics> dynamics;
  std::optional<double> face_width_mm;
  std::optional<MaterialInput> material;
  Analysis analysis;
  Optimizer optimizer;

  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Required().Const("disc_cam_motion").Desc("the study kind"));
    a->Visit("name", &name, Field().Desc("the design's name, in titles"));
    a->Visit("description", &description, Field().Desc("free text"));
    a->Visit("follower", &follower,
             Field().Required().Desc("the follower: a translating or oscillating roller or knife edge"));
    a->Visit("base_circle_radius_mm", &base_circle_radius_mm,
             Field().Required().Positive().Unit("mm").Desc("r_b, the base circle of the cam profile"));
    a->Visit("motion", &motion,
             Field().Required().Schema(MotionSchema()).Desc(
                 "the follower's motion over one cam revolution, as disc_cam's; the designed segments carry "
                 "\"optimize\" (their own law is the start and the reference)"));
    a->Visit("objective", &objective,
             Field().Required()
                 .OneOf({"peak_acceleration", "peak_jerk", "residual_vibration", "max_contact_force"})
                 .Desc("what the designed segments minimise (docs/disc_cam.md 'Motion design')"));
    a->Visit("limits", &limits, Field().Desc("limits of the design; a limit not given takes its default"));
    a->Visit("dynamics", &dynamics,
             Field().Desc("the follower's loads and dynamics at the cam speed, as disc_cam's (translating followers); "
                          "residual_vibration and no_separation_up_to_rpm need follower_stiffness_N_per_mm, "
                          "max_contact_force the loads"));
    a->Visit("face_width_mm", &face_width_mm,
             Field().Positive().Unit("mm").Desc("contact length of roller and cam along the camshaft, for the Hertz stress"));
    a->Visit("material", &material, Field().Desc("follower and cam (both), for the Hertz stress"));
    a->Visit("analysis", &analysis, Field().Desc("the fast rows' and the accurate model's grids"));
    a->Visit("optimizer", &optimizer, Field().Desc("the optimizer and the verification loop"));
  }
  /// disc_cam's motion schema with "optimize" on a segment.
  static nlohmann::ordered_json MotionSchema();
  /// What each objective and limit needs, the followers taken: Parse refuses the same.
  static nlohmann::ordered_json SchemaRules();
  static std::vector<CrossFieldRule> CrossFieldRules() { return MotionRules(); }
};

struct Study {
  std::string name;
  disc_cam::Study base;      ///< the design with the study's own laws
  nlohmann::json base_json;  ///< its disc_cam file text, for best_disc_cam.json
  objectives::DiscCamMotionSpec spec;
  sizing::DiscCamMotionOptions options;
  std::string backend = "ipopt";
  std::string follower_unit = "mm";  ///< "mm" or "deg" (the file's rise unit)
};

/// The run's answer: result.json as declared (its `Serialize`; `camopt schema disc_cam_motion
/// --result` is emitted from it), then the design's outcome the other files are drawn from.
struct Result {
  struct Objective {
    std::string name, unit;
    std::optional<std::vector<double>> speeds_rpm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("name", &name, Field().OneOf({"peak_acceleration", "peak_jerk", "residual_vibration", "max_contact_force"})
                                  .Desc("what the designed segments minimise"));
      a->Visit("unit", &unit, Field().Desc("the objective's unit"));
      a->Visit("speeds_rpm", &speeds_rpm,
               Field().Unit("rpm").Desc("residual_vibration: the speeds whose largest residual amplitude is minimised"));
    }
  };
  struct Boundary {
    bool velocity = true, acceleration = true;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("velocity", &velocity, Field().Desc("the neighbours' velocity matched (always)"));
      a->Visit("acceleration", &acceleration, Field().Desc("the neighbours' acceleration matched too"));
    }
  };
  /// A segment whose shape is designed.
  struct DesignedSegment {
    int segment = 0;
    std::string start_law;
    int control_points = 0, degree = 0;
    Boundary boundary;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("segment", &segment, Field().Desc("its index in motion"));
      a->Visit("start_law", &start_law, Field().Desc("its own law: the start and the reference"));
      a->Visit("control_points", &control_points, Field().Desc("n + 1 control values of its B-spline"));
      a->Visit("degree", &degree, Field().Desc("p, of its B-spline"));
      a->Visit("boundary", &boundary, Field().Desc("what it keeps of its neighbours at both ends"));
    }
  };
  /// The limits applied.
  struct Limits {
    double pressure_angle_deg = 0, radius_margin_mm = 0;
    std::optional<double> stroke_mm, contact_stress_MPa, no_separation_up_to_rpm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("pressure_angle_deg", &pressure_angle_deg, Field().Unit("deg").Desc("the largest |φ| allowed over the cycle"));
      a->Visit("radius_margin_mm", &radius_margin_mm,
               Field().Unit("mm").Desc("the profile's smallest convex radius of curvature at least this"));
      a->Visit("stroke_mm", &stroke_mm, Field().Unit("mm").Desc("the follower within [0, stroke], when limited"));
      a->Visit("contact_stress_MPa", &contact_stress_MPa, Field().Unit("MPa").Desc("the peak Hertz stress, when limited"));
      a->Visit("no_separation_up_to_rpm", &no_separation_up_to_rpm,
               Field().Unit("rpm").Desc("contact kept at every speed up to this, when limited"));
    }
  };
  /// The residual vibration in the dwell after a designed segment, at one speed.
  struct Residual {
    int segment = 0;
    double speed_rpm = 0, amplitude_mm = 0, estimated_error_mm = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("segment", &segment, Field().Desc("the designed segment the dwell follows"));
      a->Visit("speed_rpm", &speed_rpm, Field().Unit("rpm"));
      a->Visit("amplitude_mm", &amplitude_mm,
               Field().NullWhenNotFinite().Unit("mm").Desc("the free vibration's amplitude (null: the follower leaves the cam)"));
      a->Visit("estimated_error_mm", &estimated_error_mm, Field().NullWhenNotFinite().Unit("mm"));
    }
  };
  /// A program's objective by the accurate model (the verifying CVODE run for the dynamics).
  struct Check {
    double objective = 0, estimated_error = 0, fast_value = 0, at_cam_angle_deg = 0;
    std::string where;
    std::optional<std::vector<Residual>> residual_vibration;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("objective", &objective,
               Field().NullWhenNotFinite().Desc("the objective by the accurate model, in objective.unit (null: it cannot "
                                                "be evaluated)"));
      a->Visit("estimated_error", &estimated_error, Field().NullWhenNotFinite().Desc("of the objective"));
      a->Visit("fast_value", &fast_value, Field().NullWhenNotFinite().Desc("the fast model's (the optimizer's) value"));
      a->Visit("at_cam_angle_deg", &at_cam_angle_deg,
               Field().Unit("deg").Desc("where the objective is (the residual vibration: the dwell's start)"));
      a->Visit("where", &where, Field().Desc("where it is, in words"));
      a->Visit("residual_vibration", &residual_vibration,
               Field().Desc("residual_vibration: per dwell after a designed segment and speed"));
    }
  };
  /// A designed segment's residual-vibration spectrum at the objective's speeds.
  struct SpectrumSegment {
    int segment = 0;
    std::string start_law;
    std::vector<double> tau_at_speeds, start_amplitude_per_rise, designed_amplitude_per_rise;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("segment", &segment, Field().Desc("its index in motion"));
      a->Visit("start_law", &start_law, Field().Desc("its own law"));
      a->Visit("tau_at_speeds", &tau_at_speeds, Field().Desc("τ = segment time / natural period at each speed"));
      a->Visit("start_amplitude_per_rise", &start_amplitude_per_rise,
               Field().Desc("the start law's residual amplitude over the rise, at each speed"));
      a->Visit("designed_amplitude_per_rise", &designed_amplitude_per_rise,
               Field().Desc("the designed shape's, at each speed"));
    }
  };
  struct ResidualSpectrum {
    std::string model;
    std::vector<SpectrumSegment> segments;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("model", &model, Field().Desc("the spectrum's model and what it leaves out"));
      a->Visit("segments", &segments, Field().Desc("one per designed segment"));
    }
  };
  /// The designed program.
  struct Best : Check {
    nlohmann::json motion;
    std::optional<ResidualSpectrum> residual_spectrum;
    std::optional<double> lowest_separation_rpm;
    template <typename Archive>
    void Serialize(Archive* a) {
      Check::Serialize(a);
      a->Visit("motion", &motion,
               Field().Schema({{"type", "array"}}).Desc("the designed program as a disc_cam study's motion list"));
      a->Visit("residual_spectrum", &residual_spectrum,
               Field().Desc("with the follower's dynamics: the classic residual-vibration chart at the objective's speeds"));
      a->Visit("lowest_separation_rpm", &lowest_separation_rpm,
               Field().NullWhenNotFinite().Unit("rpm").Desc(
                   "with limits.no_separation_up_to_rpm: the lowest speed the follower leaves the cam (null: none up to "
                   "the limit)"));
    }
  };
  /// The study's own program.
  struct Start : Check {
    std::vector<std::string> laws;
    template <typename Archive>
    void Serialize(Archive* a) {
      Check::Serialize(a);
      a->Visit("laws", &laws, Field().Desc("the designed segments' own laws"));
    }
  };
  /// A named law on a designed segment, by the same accurate model.
  struct NamedLaw {
    int segment = 0;
    std::string law;
    double objective = 0, estimated_error = 0;
    std::optional<std::string> note;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("segment", &segment, Field().Desc("its index in motion"));
      a->Visit("law", &law, Field().Desc("the law"));
      a->Visit("objective", &objective, Field().NullWhenNotFinite().Desc("the objective with it (null: infinite)"));
      a->Visit("estimated_error", &estimated_error, Field().NullWhenNotFinite().Desc("of the objective"));
      a->Visit("note", &note, Field().Desc("why the objective is infinite, when it is"));
    }
  };
  struct BestNamedLaw {
    std::string law;
    double objective = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("law", &law, Field().Desc("the named law with the least finite objective"));
      a->Visit("objective", &objective, Field().Desc("its objective"));
    }
  };
  /// The solves (SolveSummary), the answer's violation, the tightening rounds and how the
  /// gradients are computed.
  struct Optimizer : SolveSummary {
    double max_violation = 0;
    int rounds = 0;
    std::string gradient_method;
    template <typename Archive>
    void Serialize(Archive* a) {
      SolveSummary::Serialize(a);
      a->Visit("max_violation", &max_violation, Field().Desc("the largest constraint violation at the answer (scaled)"));
      a->Visit("rounds", &rounds, Field().Desc("solves after the first (tightening rounds)"));
      a->Visit("gradient_method", &gradient_method, Field().Desc("how the gradients are computed"));
    }
  };
  /// The fast rows' and the accurate check's grids: disc_cam_min_size's block.
  using Analysis = disc_cam_min_size::Result::Analysis;

  std::string study = "disc_cam_motion", name, follower;
  Objective objective;
  std::vector<DesignedSegment> designed_segments;
  Limits limits;
  VerificationBlock verification;
  bool verified = false;
  std::optional<Best> best;
  Start start;
  std::vector<NamedLaw> named_laws;
  std::optional<BestNamedLaw> best_named_law;
  std::optional<bool> beats_every_named_law;
  Optimizer optimizer;
  Analysis analysis;
  std::optional<std::vector<std::string>> notes;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Const("disc_cam_motion"));
    a->Visit("name", &name, Field().Desc("the design's name"));
    a->Visit("follower", &follower, Field().Desc("the follower's type"));
    a->Visit("objective", &objective, Field().Desc("what is minimised"));
    a->Visit("designed_segments", &designed_segments, Field().Desc("the segments whose shape is designed"));
    a->Visit("limits", &limits, Field().Desc("the limits applied"));
    a->Visit("verification", &verification,
             Field().Desc("each limit's check on the accurate model and the tightening rounds (studies/verification_json.h)"));
    a->Visit("verified", &verified,
             Field().Desc("the accurate model meets every limit at the design (a view of status: optimal_verified or "
                          "feasible_verified)"));
    a->Visit("best", &best, Field().NullWhenAbsent().Desc("the designed program (null: no design)"));
    a->Visit("start", &start, Field().Desc("the study's own laws by the same accurate model"));
    a->Visit("named_laws", &named_laws, Field().Desc("every named law of the library on each designed segment"));
    a->Visit("best_named_law", &best_named_law, Field().Desc("with a design: the named law with the least finite objective"));
    a->Visit("beats_every_named_law", &beats_every_named_law,
             Field().Desc("with best_named_law: the design's objective is below it by more than both errors together"));
    a->Visit("optimizer", &optimizer, Field().Desc("the solves"));
    a->Visit("analysis", &analysis, Field().Desc("the grids"));
    a->Visit("notes", &notes, Field().Desc("why the answer is not what was asked, when it is not"));
  }

  // Not in result.json: the design's outcome (model units) the other files are drawn from.
  sizing::DiscCamMotionOutcome outcome;
  std::string blocking_message;
};

Study Parse(const Node& root);
Result Run(const Study& study, const RunContext& ctx);
/// The best program as the "motion" list of a disc_cam study.
nlohmann::json MotionJson(const Study& study, const camopt::disc_cam::DiscCam& cam);
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::disc_cam_motion
