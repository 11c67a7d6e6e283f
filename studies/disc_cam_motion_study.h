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

#include <nlohmann/json.hpp>

#include "sizing/disc_cam_motion.h"
#include "studies/archive.h"
#include "studies/disc_cam_min_size_study.h"
#include "studies/disc_cam_study.h"
#include "studies/input.h"
#include "studies/study.h"

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

struct Result {
  sizing::DiscCamMotionOutcome outcome;
  std::string blocking_message;
};

Study Parse(const Node& root);
Result Run(const Study& study, const RunContext& ctx);
nlohmann::json ToJson(const Study& study, const Result& result);
/// The best program as the "motion" list of a disc_cam study.
nlohmann::json MotionJson(const Study& study, const camopt::disc_cam::DiscCam& cam);
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::disc_cam_motion
