// Study kind "disc_cam_min_size": the smallest base circle of a disc cam with a translating or an
// oscillating roller follower for its motion program, under the disc_cam limits (pressure angle on
// the rise and on the return, radius margin against undercut, contact stress), with the base circle
// radius, the offset (translating) or the pivot distance and arm length (oscillating), and the roller
// radius as variables (sizing/disc_cam_min_size.h).
//
// The file is a disc_cam study (docs/studies.md "disc_cam"; its design is the start and gives every
// value that is not a variable) plus "variables" ({"base_circle_radius_mm": [lo, hi], "offset_mm":
// [lo, hi], "roller_radius_mm": [lo, hi]}, the base circle required), an optional "optimizer" and
// an "analysis" of the sizing's own (the fast rows' angle count and the accurate grid's factor).
// The answer is verified by the accurate model (objectives/verification.h); a design that is not
// verified, or none, ends with exit 3 and the limit that blocks. Beside result.json:
// best_disc_cam.json (the best design as a disc_cam study), series.csv and pressure_angle.svg (the
// best design on the accurate grid), profile.svg (the sized cam over the start design).
#pragma once

#include <array>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "sizing/disc_cam_min_size.h"
#include "studies/archive.h"
#include "studies/disc_cam_study.h"
#include "studies/input.h"
#include "studies/study.h"

namespace camopt::studies::disc_cam_min_size {

inline constexpr int kDefaultAngleSteps = 360;
inline constexpr int kDefaultAccurateFactor = 8;
inline constexpr int kDefaultMaxEvaluations = 500;
inline constexpr int kDefaultVerifyRounds = 4;

/// The study file as declared (studies/archive.h): the disc_cam design (its parts declared by
/// disc_cam::Input; the start design) with the sizing's own analysis, variables and optimizer.
/// Parse reads it and hands the design to disc_cam::Parse; `camopt schema disc_cam_min_size` is
/// emitted from it.
struct Input {
  struct Analysis {
    int angle_steps = kDefaultAngleSteps, accurate_factor = kDefaultAccurateFactor;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("angle_steps", &angle_steps,
               Field().AtLeast(36).AtMost(100000).Desc("cam angles of the fast rows (the optimizer's constraints)"));
      a->Visit("accurate_factor", &accurate_factor,
               Field().AtLeast(2).AtMost(64).Desc("the accurate model's grid is this many times finer"));
    }
  };
  /// The sized quantities: [lower, upper] each, lower <= upper (equal: a fixed value).
  struct Variables {
    std::array<double, 2> base_circle_radius_mm{};
    std::optional<std::array<double, 2>> offset_mm, roller_radius_mm, pivot_distance_mm, arm_length_mm;
    template <typename Archive>
    void Serialize(Archive* a) {
      const char* range = "[lower, upper], two numbers";
      a->Visit("base_circle_radius_mm", &base_circle_radius_mm,
               Field().Required().Positive().Expect(range).Unit("mm").Desc(
                   "[lower, upper] of the base circle radius, lower <= upper (equal: a fixed value)"));
      a->Visit("offset_mm", &offset_mm,
               Field().Expect(range).Unit("mm").Desc(
                   "[lower, upper] of the follower's offset, lower <= upper (absent: the start's, fixed); a "
                   "translating follower only"));
      a->Visit("roller_radius_mm", &roller_radius_mm,
               Field().Positive().Expect(range).Unit("mm").Desc(
                   "[lower, upper] of the roller radius, lower <= upper (absent: the start's, fixed)"));
      a->Visit("pivot_distance_mm", &pivot_distance_mm,
               Field().Positive().Expect(range).Unit("mm").Desc(
                   "[lower, upper] of f, cam centre to the arm's pivot, lower <= upper (absent: the start's, fixed); an "
                   "oscillating follower only"));
      a->Visit("arm_length_mm", &arm_length_mm,
               Field().Positive().Expect(range).Unit("mm").Desc(
                   "[lower, upper] of l, pivot to the roller centre, lower <= upper (absent: the start's, fixed); an "
                   "oscillating follower only"));
    }
  };
  struct Optimizer {
    std::string backend = "ipopt";
    int max_evaluations = kDefaultMaxEvaluations, verify_rounds = kDefaultVerifyRounds;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("backend", &backend,
               Field().OneOf({"ipopt", "slsqp"}, "one of \"ipopt\", \"slsqp\"").Desc("the NLP solver (slsqp: NLopt's)"));
      a->Visit("max_evaluations", &max_evaluations,
               Field().AtLeast(1).AtMost(10000).Desc("per solve (Ipopt: iterations; SLSQP: evaluations)"));
      a->Visit("verify_rounds", &verify_rounds,
               Field().AtLeast(0).AtMost(10).Desc("tightening rounds of the verification loop"));
    }
  };

  disc_cam::Input design;  ///< its study and analysis are not visited: the sizing's own
  Analysis analysis;
  Variables variables;
  Optimizer optimizer;
  std::string study = "disc_cam_min_size";

  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Required().Const("disc_cam_min_size").Desc("the study kind"));
    design.SerializeDesign(a, /*sizing=*/true);
    a->Visit("analysis", &analysis, Field().Desc("the sizing's angle grids"));
    design.SerializeGeometry(a);
    a->Visit("variables", &variables,
             Field().Required().Desc("the sized quantities (docs/disc_cam.md 'Smallest base circle'); the base "
                                     "circle is the objective and always a variable"));
    a->Visit("optimizer", &optimizer, Field().Desc("the optimizer and the verification loop"));
  }
};

struct Study {
  std::string name;
  disc_cam::Study base;      ///< the disc_cam study (its design is the start)
  nlohmann::json base_json;  ///< its file text, for best_disc_cam.json
  objectives::DiscCamSizingSpec spec;
  objectives::DiscCamMinSizeOptions options;
  std::string backend = "ipopt";  ///< as in the file: "ipopt" or "slsqp"
};

struct Result {
  objectives::DiscCamMinSizeOutcome outcome;
  /// Not empty when the answer is not what was asked (exit 3): what blocks and what would help.
  std::string blocking_message;
};

/// @throws StudyError for bad input (exit 2) with the JSON path.
Study Parse(const Node& root);
Result Run(const Study& study, const RunContext& ctx);
nlohmann::json ToJson(const Study& study, const Result& result);
/// The best design as a complete disc_cam study; null when there is no design.
nlohmann::json BestDiscCamStudy(const Study& study, const Result& result);
/// The start design (each variable's start, the study's values clamped to their ranges) as a
/// complete disc_cam study, made as BestDiscCamStudy makes the best one (the studio draws the two).
nlohmann::json StartDiscCamStudy(const Study& study);
/// result.json, best_disc_cam.json, series.csv, pressure_angle.svg, profile.svg; marks the outputs incomplete
/// (exit 3) when the answer is not verified or there is none.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::disc_cam_min_size
