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
#include <vector>

#include <nlohmann/json.hpp>

#include "sizing/disc_cam_min_size.h"
#include "studies/backend_input.h"
#include "studies/archive.h"
#include "studies/disc_cam_study.h"
#include "studies/input.h"
#include "studies/study.h"
#include "studies/verification_json.h"

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
               BackendField({optimizers::Backend::kIpopt, optimizers::Backend::kSlsqp}).Desc("the NLP solver (slsqp: NLopt's)"));
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
  /// disc_cam's rules of the design by the follower (disc_cam::DesignSchemaRules) and the variables
  /// each follower has.
  static nlohmann::ordered_json SchemaRules();
  static std::vector<CrossFieldRule> CrossFieldRules() { return disc_cam::Input::CrossFieldRules(); }
};

struct Study {
  std::string name;
  disc_cam::Study base;      ///< the disc_cam study (its design is the start)
  nlohmann::json base_json;  ///< its file text, for best_disc_cam.json
  sizing::DiscCamSizingSpec spec;
  sizing::DiscCamMinSizeOptions options;
  std::string backend = "ipopt";  ///< as in the file: "ipopt" or "slsqp"
};

/// The run's answer: result.json as declared (its `Serialize`; `camopt schema disc_cam_min_size
/// --result` is emitted from it), then the sizing's outcome the other files are drawn from.
struct Result {
  /// A sized quantity: its range and its start (the study's value clamped into the range).
  struct VariableRow {
    std::string name;
    double lower = 0, upper = 0, start = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("name", &name, Field().Desc("the variable's key in variables"));
      a->Visit("lower", &lower, Field().Unit("mm"));
      a->Visit("upper", &upper, Field().Unit("mm"));
      a->Visit("start", &start, Field().Unit("mm").Desc("the study's value clamped into [lower, upper]"));
    }
  };
  /// The limits applied.
  struct Limits {
    double pressure_angle_deg = 0;
    std::vector<std::string> defaults;
    double radius_margin_mm = 0;
    std::optional<std::string> radius_margin_follows;
    std::optional<double> contact_stress_MPa;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("pressure_angle_deg", &pressure_angle_deg,
               Field().Unit("deg").Desc("the largest |φ| allowed, on the rise and on the return"));
      a->Visit("defaults", &defaults, Field().Desc("the limits the study did not give (their defaults apply)"));
      a->Visit("radius_margin_mm", &radius_margin_mm,
               Field().Unit("mm").Desc("the profile's smallest convex radius of curvature at least this (the default, the "
                                       "roller radius: its value at the best design, else at the start)"));
      a->Visit("radius_margin_follows", &radius_margin_follows,
               Field().Desc("with the default margin: the variable it follows (roller_radius_mm)"));
      a->Visit("contact_stress_MPa", &contact_stress_MPa, Field().Unit("MPa").Desc("the peak Hertz stress, when limited"));
    }
  };
  /// A design's pressure angles.
  struct PressureAngles {
    double max_rise = 0, at_max_rise_cam_angle_deg = 0;
    std::optional<double> max_return, at_max_return_cam_angle_deg;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("max_rise", &max_rise, Field().Unit("deg").Desc("the largest |φ| where S' >= 0 (dwells included)"));
      a->Visit("at_max_rise_cam_angle_deg", &at_max_rise_cam_angle_deg, Field().Unit("deg"));
      a->Visit("max_return", &max_return, Field().Unit("deg").Desc("the largest |φ| where S' < 0, when there is a return"));
      a->Visit("at_max_return_cam_angle_deg", &at_max_return_cam_angle_deg, Field().Unit("deg"));
    }
  };
  /// A design's values over the cycle, by one model (the accurate or the fast one).
  struct Cycle {
    PressureAngles pressure_angle_deg;
    double min_radius_of_curvature_mm = 0, at_min_radius_of_curvature_cam_angle_deg = 0;
    double max_radial_dimension_mm = 0;
    std::optional<double> max_contact_stress_MPa, at_max_contact_stress_cam_angle_deg;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("pressure_angle_deg", &pressure_angle_deg, Field().Desc("on the rise and on the return"));
      a->Visit("min_radius_of_curvature_mm", &min_radius_of_curvature_mm,
               Field().NullWhenNotFinite().Unit("mm").Desc(
                   "the profile's smallest convex radius of curvature (roller: ρ_pitch − r_roller; flat face: r_b + S + "
                   "S''; null: no convex part)"));
      a->Visit("at_min_radius_of_curvature_cam_angle_deg", &at_min_radius_of_curvature_cam_angle_deg, Field().Unit("deg"));
      a->Visit("max_radial_dimension_mm", &max_radial_dimension_mm, Field().Unit("mm").Desc("the profile's largest radius"));
      a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa,
               Field().NullWhenNotFinite().Unit("MPa").Desc(
                   "the peak Hertz stress, with the loads (null: loaded on an undercut profile)"));
      a->Visit("at_max_contact_stress_cam_angle_deg", &at_max_contact_stress_cam_angle_deg, Field().Unit("deg"));
    }
  };
  /// A difference of the accurate values and another model's, key by key.
  struct CycleError {
    double pressure_angle_rise_deg = 0;
    std::optional<double> pressure_angle_return_deg;
    double min_radius_of_curvature_mm = 0;
    std::optional<double> max_contact_stress_MPa;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("pressure_angle_rise_deg", &pressure_angle_rise_deg, Field().Unit("deg"));
      a->Visit("pressure_angle_return_deg", &pressure_angle_return_deg, Field().Unit("deg").Desc("when there is a return"));
      a->Visit("min_radius_of_curvature_mm", &min_radius_of_curvature_mm, Field().NullWhenNotFinite().Unit("mm"));
      a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa,
               Field().NullWhenNotFinite().Unit("MPa").Desc("with the loads"));
    }
  };
  /// A variable of the best design at a bound of its range.
  struct AtBound {
    std::string name, bound;
    double value = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("name", &name, Field().Desc("the variable"));
      a->Visit("bound", &bound, Field().OneOf({"lower", "upper"}));
      a->Visit("value", &value, Field().Unit("mm").Desc("the bound"));
    }
  };
  /// The best design (the closest one when it is not verified).
  struct Best {
    double base_circle_radius_mm = 0;
    std::optional<double> pivot_distance_mm, arm_length_mm, offset_mm, roller_radius_mm, prime_circle_radius_mm;
    std::vector<AtBound> variables_at_bounds;
    Cycle accurate, fast;
    CycleError estimated_error, fast_model_error;
    std::string accurate_model;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("base_circle_radius_mm", &base_circle_radius_mm, Field().Unit("mm").Desc("r_b, the objective"));
      a->Visit("pivot_distance_mm", &pivot_distance_mm, Field().Unit("mm").Desc("oscillating follower: f"));
      a->Visit("arm_length_mm", &arm_length_mm, Field().Unit("mm").Desc("oscillating follower: l"));
      a->Visit("offset_mm", &offset_mm, Field().Unit("mm").Desc("translating roller or knife edge: e"));
      a->Visit("roller_radius_mm", &roller_radius_mm, Field().Unit("mm").Desc("r_f (not a flat face)"));
      a->Visit("prime_circle_radius_mm", &prime_circle_radius_mm, Field().Unit("mm").Desc("r_b + r_f (not a flat face)"));
      a->Visit("variables_at_bounds", &variables_at_bounds, Field().Desc("the variables at a bound of their range"));
      a->Visit("accurate", &accurate, Field().Desc("the accurate model's values (the dense grid, every peak refined)"));
      a->Visit("fast", &fast, Field().Desc("the fast model's (the optimizer's sampled angles)"));
      a->Visit("estimated_error", &estimated_error, Field().Desc("of the accurate values: how far refining the peaks moved them from the dense grid's"));
      a->Visit("fast_model_error", &fast_model_error, Field().Desc("of the fast model: accurate − fast"));
      a->Visit("accurate_model", &accurate_model, Field().Desc("the accurate model, in words"));
    }
  };
  /// One start's first solve.
  struct StartOutcome {
    std::string status;
    std::optional<double> base_circle_radius_mm;
    double max_violation = 0, first_order_residual = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("status", &status, Field().Desc("the solver's end"));
      a->Visit("base_circle_radius_mm", &base_circle_radius_mm,
               Field().NullWhenAbsent().Unit("mm").Desc("the objective at its end (null: no design)"));
      a->Visit("max_violation", &max_violation, Field().Desc("the largest constraint violation (scaled)"));
      a->Visit("first_order_residual", &first_order_residual,
               Field().NullWhenNotFinite().Desc("the first-order optimality residual (null: not computed, the solve did not "
                                                "converge)"));
    }
  };
  /// The solves (SolveSummary), the answer's violation and active rows, the tightening rounds and
  /// each start's first solve.
  struct Optimizer : SolveSummary {
    double max_violation = 0;
    std::vector<std::string> binding_rows;
    int rounds = 0;
    std::vector<StartOutcome> start_outcomes;
    template <typename Archive>
    void Serialize(Archive* a) {
      SolveSummary::Serialize(a);
      a->Visit("max_violation", &max_violation, Field().Desc("the largest constraint violation at the answer (scaled)"));
      a->Visit("binding_rows", &binding_rows, Field().Desc("the constraint rows and variable bounds active at the answer"));
      a->Visit("rounds", &rounds, Field().Desc("solves after the first (tightening rounds)"));
      a->Visit("start_outcomes", &start_outcomes, Field().Desc("each start's first solve"));
    }
  };
  struct Analysis {
    int angle_steps = 0, accurate_factor = 0, accurate_angle_steps = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("angle_steps", &angle_steps, Field().Desc("cam angles of the fast rows"));
      a->Visit("accurate_factor", &accurate_factor, Field().Desc("the accurate grid is this many times finer"));
      a->Visit("accurate_angle_steps", &accurate_angle_steps, Field().Desc("cam angles of the accurate grid"));
    }
  };

  std::string study = "disc_cam_min_size", name, follower, objective = "base_circle_radius_mm";
  std::vector<VariableRow> variables;
  Limits limits;
  VerificationBlock verification;
  bool verified = false;
  std::optional<Best> best;
  std::vector<std::string> binding;
  std::vector<BindingLimit> binding_limits;
  Optimizer optimizer;
  Analysis analysis;
  std::optional<std::vector<std::string>> notes;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Const("disc_cam_min_size"));
    a->Visit("name", &name, Field().Desc("the design's name"));
    a->Visit("follower", &follower, Field().Desc("the follower's type"));
    a->Visit("objective", &objective, Field().Const("base_circle_radius_mm").Desc("what is minimised"));
    a->Visit("variables", &variables, Field().Desc("the sized quantities, the base circle first"));
    a->Visit("limits", &limits, Field().Desc("the limits applied"));
    a->Visit("verification", &verification,
             Field().Desc("each limit's check on the accurate model and the tightening rounds (studies/verification_json.h)"));
    a->Visit("verified", &verified, Field().Desc("the accurate values are within the limits at the design (a view of status: "
                                         "optimal_verified or feasible_verified)"));
    a->Visit("best", &best, Field().NullWhenAbsent().Desc("the best design (null: no design)"));
    a->Visit("binding", &binding, Field().Desc("the limits that bind at the answer, by key"));
    a->Visit("binding_limits", &binding_limits, Field().Desc("what each binding limit costs"));
    a->Visit("optimizer", &optimizer, Field().Desc("the solves"));
    a->Visit("analysis", &analysis, Field().Desc("the grids"));
    a->Visit("notes", &notes, Field().Desc("why the answer is not what was asked, when it is not"));
  }

  // Not in result.json: the sizing's outcome (model units) the other files are drawn from.
  sizing::DiscCamMinSizeOutcome outcome;
  /// Not empty when the answer is not what was asked (exit 3): what blocks and what would help.
  std::string blocking_message;
};

/// @throws StudyError for bad input (exit 2) with the JSON path.
Study Parse(const Node& root);
Result Run(const Study& study, const RunContext& ctx);
/// The best design as a complete disc_cam study; null when there is no design.
nlohmann::json BestDiscCamStudy(const Study& study, const Result& result);
/// The start design (each variable's start, the study's values clamped to their ranges) as a
/// complete disc_cam study, made as BestDiscCamStudy makes the best one (the studio draws the two).
nlohmann::json StartDiscCamStudy(const Study& study);
/// result.json, best_disc_cam.json, series.csv, pressure_angle.svg, profile.svg; marks the outputs incomplete
/// (exit 3) when the answer is not verified or there is none.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::disc_cam_min_size
