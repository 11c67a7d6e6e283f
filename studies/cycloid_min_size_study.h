// Study kind "cycloid_min_size": the smallest one-tooth-difference cycloid drive for a ratio and a
// torque, its pin circle, pins, eccentricity, face width, profile modifications and crowning sized
// together on the 3D loaded contact (sizing/cycloid_min_size.h; the loaded tooth contact
// analysis of model/cycloid/loaded_tca.h, the closed-form limits of model/cycloid/geometry_limits.h).
//
// The file names each sized quantity by the cycloid_ltca field it sets; "variables" gives each a
// range or a fixed value, "drive" / "modification" / "crowning" the fields that are not variables.
// Before any work the most favourable corner of the ranges is checked against the closed-form
// limits (curtate, undercut, pin gap, web): a box in which every design breaks one is bad input
// (exit 2) naming the bound that would fit. The answer is verified by the accurate model
// (objectives/verification.h); a design that is not verified, or no design, ends with exit 3 and
// the limit that blocks. Beside result.json: best_cycloid_ltca.json (the best design as a
// cycloid_ltca study), the stress over the cycle and the pressure map at the worst angle of the
// best design at the accurate settings.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/cycloid/loaded_tca.h"
#include "sizing/cycloid_min_size.h"
#include "studies/backend_input.h"
#include "studies/archive.h"
#include "studies/cycloid_input.h"
#include "studies/cycloid_life.h"
#include "studies/input.h"
#include "studies/lubrication_input.h"
#include "studies/material_input.h"
#include "studies/ratings.h"
#include "studies/ratings_input.h"
#include "studies/study.h"
#include "studies/torsional_dynamics_input.h"
#include "studies/verification_json.h"

namespace camopt::studies::cycloid_min_size {

/// Defaults of the "optimizer" block.
inline constexpr int kDefaultStarts = 2;
inline constexpr int kDefaultMaxEvaluations = 200;
inline constexpr int kDefaultVerifyRounds = 3;
/// Defaults of the "analysis" block (as cycloid_crowning_tuning).
inline constexpr int kDefaultCrankAnglesPerMeshPeriod = 6;

/// The study file as declared: each field once, in the file's units, with its default, bounds and
/// description (studies/archive.h); the blocks shared with the other cycloid kinds are those of
/// studies/cycloid_input.h. Parse reads it, checks what spans fields (the box of the ranges against
/// the closed-form limits among them) and converts it (Study); `camopt schema cycloid_min_size` is
/// emitted from it.
struct Input {
  struct Target {
    std::optional<int> teeth;
    std::optional<double> speed_ratio;  ///< a whole number >= 2, checked by Parse (its message says what would fit)
    double design_torque_Nm = 0;
    std::optional<double> overload_torque_Nm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Retired("misalignment_mrad",
                 "the cycloid contact model has no misalignment (model/cycloid/loaded_tca.h: disc and pins are "
                 "parallel; only the crowning shapes the load along the face); remove the field, and keep the "
                 "contact off the face ends at a higher overload_torque_Nm instead");
      a->Visit("teeth", &teeth, Field().AtLeast(2).Desc("z, the disc's teeth (z + 1 pins); or speed_ratio"));
      a->Visit("speed_ratio", &speed_ratio,
               Field().Schema({{"type", "integer"}, {"minimum", 2}}).Desc(
                   "the reduction z of the drive with the ring fixed and the output from the disc (the output "
                   "turns the other way); the same number as teeth, instead of it"));
      a->Visit("design_torque_Nm", &design_torque_Nm,
               Field().Required().Positive().Unit("N·m").Desc("on the disc (the output torque)"));
      a->Visit("overload_torque_Nm", &overload_torque_Nm,
               Field().Positive().Unit("N·m").Desc(
                   ">= design_torque_Nm; the contact stays off the face ends up to it (absent: no overload cycle)"));
    }
    static nlohmann::ordered_json SchemaRules() {
      return {{"oneOf", {{{"required", {"teeth"}}}, {{"required", {"speed_ratio"}}}}}};
    }
    static std::vector<CrossFieldRule> CrossFieldRules() {
      return {{{"overload_torque_Nm", "design_torque_Nm"}, "overload_torque_Nm >= design_torque_Nm",
               "a torque >= design_torque_Nm"}};
    }
  };
  /// "variables": each sized field a number (fixed), [lo, hi] (a range, starting at its middle) or
  /// {"range": [lo, hi], "start": value}, read by Parse (the schema of each: VariableSchema).
  struct Variables {
    nlohmann::json eccentricity_mm, roller_position_radius_mm, roller_radius_mm, face_width_mm, delta_position_um,
        delta_radius_um, coefficient_mm, effective_length_mm, end_drop_mm, flat_length_mm, radius_mm;
    /// Each sized field with the block that holds it when fixed ("drive", "modification",
    /// "crowning"), in the order of the members above.
    static constexpr std::array<std::pair<const char*, const char*>, 11> kSized = {{
        {"drive", "eccentricity_mm"},
        {"drive", "roller_position_radius_mm"},
        {"drive", "roller_radius_mm"},
        {"drive", "face_width_mm"},
        {"modification", "delta_position_um"},
        {"modification", "delta_radius_um"},
        {"crowning", "coefficient_mm"},
        {"crowning", "effective_length_mm"},
        {"crowning", "end_drop_mm"},
        {"crowning", "flat_length_mm"},
        {"crowning", "radius_mm"}}};
    template <typename Archive>
    void Serialize(Archive* a) {
      nlohmann::json* members[kSized.size()] = {&eccentricity_mm,  &roller_position_radius_mm, &roller_radius_mm,
                                                &face_width_mm,    &delta_position_um,         &delta_radius_um,
                                                &coefficient_mm,   &effective_length_mm,       &end_drop_mm,
                                                &flat_length_mm,   &radius_mm};
      for (size_t i = 0; i < kSized.size(); ++i)
        a->Visit(kSized[i].second, members[i], Field().Schema(VariableSchema(kSized[i].second)));
    }
    static nlohmann::ordered_json SchemaRules() { return {{"minProperties", 1}}; }
    /// The schema of one sized field (with its description).
    static nlohmann::ordered_json VariableSchema(const std::string& name);
  };
  /// "drive": the fixed drive fields (those not in variables).
  struct Drive {
    std::optional<double> eccentricity_mm, roller_position_radius_mm, roller_radius_mm, face_width_mm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("eccentricity_mm", &eccentricity_mm, Field().Positive().Unit("mm").Desc("e, the crank's eccentricity"));
      a->Visit("roller_position_radius_mm", &roller_position_radius_mm,
               Field().Positive().Unit("mm").Desc("a, the radius of the pins' circle"));
      a->Visit("roller_radius_mm", &roller_radius_mm, Field().Positive().Unit("mm").Desc("ρ, of each pin"));
      a->Visit("face_width_mm", &face_width_mm, Field().Positive().Unit("mm").Desc("b, the disc's width"));
    }
  };
  struct Limits {
    static constexpr double kFullTurnArcsec = 360.0 * 3600.0;
    double contact_stress_MPa = 0;
    std::optional<double> min_edge_margin_um, min_curtate_margin;
    double min_profile_radius_mm = 0, min_pin_gap_mm = 0, min_backlash_arcsec = 0;
    std::optional<double> max_backlash_arcsec, max_lte_peak_to_peak_arcsec, bore_diameter_mm, min_web_mm, life_h;
    std::optional<double> min_torsional_stiffness_Nm_per_arcmin, max_lost_motion_arcmin, output_pin_stress_MPa,
        eccentric_bearing_load_N;
    std::optional<double> min_efficiency, max_oil_temperature_C;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("contact_stress_MPa", &contact_stress_MPa,
               Field().Required().In(1, 1e6, "a stress limit in [1, 1e6] MPa (hardened steel: 1000 to 4000)")
                   .Unit("MPa").Desc("peak pressure over the design-torque cycle"));
      a->Visit("min_edge_margin_um", &min_edge_margin_um,
               Field().Unit("µm").Desc(
                   "end distance of the contact from the face ends over the overload cycle (needs "
                   "target.overload_torque_Nm); absent: 0"));
      a->Visit("min_curtate_margin", &min_curtate_margin,
               Field().AtLeast(0, "a number in [0, 1) (1 - e (z + 1) / a')").Below(1, "a number in [0, 1) (1 - e (z + 1) / a')")
                   .Desc("1 - e (z + 1) / a' (absent: 0.05)"));
      a->Visit("min_profile_radius_mm", &min_profile_radius_mm,
               Field().NonNegative().Unit("mm").Desc("smallest convex radius of the tooth (0: no undercut)"));
      a->Visit("min_pin_gap_mm", &min_pin_gap_mm, Field().NonNegative().Unit("mm").Desc("clearance between neighbouring pins"));
      // A backlash is an angle of the output: at most a full turn (360° = 1 296 000 arcsec).
      a->Visit("min_backlash_arcsec", &min_backlash_arcsec,
               Field().NonNegative().AtMost(kFullTurnArcsec, "at most a full turn, 1296000 arcsec").Unit("arcsec")
                   .Desc("unloaded TE at every angle"));
      a->Visit("max_backlash_arcsec", &max_backlash_arcsec,
               Field().Positive().AtMost(kFullTurnArcsec, "at most a full turn, 1296000 arcsec").Unit("arcsec")
                   .Desc("> min_backlash_arcsec (absent: none)"));
      a->Visit("max_lte_peak_to_peak_arcsec", &max_lte_peak_to_peak_arcsec,
               Field().Positive().Unit("arcsec").Desc("the loaded transmission error's peak to peak (absent: none)"));
      a->Visit("bore_diameter_mm", &bore_diameter_mm,
               Field().Positive().Unit("mm").Desc("the disc's central bore (absent: none)"));
      a->Visit("min_web_mm", &min_web_mm,
               Field().NonNegative().Unit("mm").Desc(
                   "web between the tooth roots and the bore (needs bore_diameter_mm; absent: 0)"));
      a->Visit("life_h", &life_h,
               Field().Positive().Unit("h").Desc(
                   "shortest ISO 281 L10h of any rated bearing over the duty cycle (needs load.input_speed_rpm or "
                   "duty_cycle; docs/life.md, Cycloid; absent: none)"));
      const std::string needs = " (needs output_mechanism with pin_radius_mm and hole_radius_mm; absent: none)";
      a->Visit("min_torsional_stiffness_Nm_per_arcmin", &min_torsional_stiffness_Nm_per_arcmin,
               Field().Positive().Unit("N·m/arcmin").Desc(
                   "torsional stiffness at the output, input held at crank 0, between 50% and 100% of "
                   "design_torque_Nm (cycloid_ltca's torsional_stiffness_Nm_per_arcmin)" + needs));
      a->Visit("max_lost_motion_arcmin", &max_lost_motion_arcmin,
               Field().Positive().Unit("arcmin").Desc(
                   "lost motion between +-3% of design_torque_Nm at crank 0 (cycloid_ltca's lost_motion_arcmin)" +
                   needs));
      a->Visit("output_pin_stress_MPa", &output_pin_stress_MPa,
               Field().Positive().Unit("MPa").Desc("output-pin bending stress over the pins' load period" + needs));
      a->Visit("eccentric_bearing_load_N", &eccentric_bearing_load_N,
               Field().Positive().Unit("N").Desc(
                   "largest eccentric (crank) bearing load over the pins' load period, the output pins with "
                   "clearance and compliance" + needs));
      a->Visit("min_efficiency", &min_efficiency,
               Field().In(0.0, 1.0).Desc(
                   "the lubricated efficiency at design_torque_Nm and load.input_speed_rpm, a revolution's mean "
                   "(needs lubricant; docs/lubrication.md)"));
      a->Visit("max_oil_temperature_C", &max_oil_temperature_C,
               Field().In(-50.0, 300.0).Unit("°C").Desc(
                   "the oil temperature of the housing's balance at design_torque_Nm (needs lubricant.thermal)"));
    }
    static nlohmann::ordered_json SchemaRules() {
      return {{"dependentRequired", {{"min_web_mm", {"bore_diameter_mm"}}}}};
    }
  };
  struct Analysis {
    std::optional<std::array<int, 2>> grid;
    int crank_angles_per_mesh_period = kDefaultCrankAnglesPerMeshPeriod;
    double tolerance = cycloid::LoadedOptions{}.tolerance;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("grid", &grid, cycloid_common::GridField().Desc(
          "[profile_cells, axial_cells] of the fast model, 4 to 512 each; the accurate check has twice each"));
      a->Visit("crank_angles_per_mesh_period", &crank_angles_per_mesh_period,
               Field().AtLeast(1).AtMost(1000, "at most 1000").Desc("of the fast model; the accurate check has twice"));
      a->Visit("tolerance", &tolerance, Field().Positive().Desc("relative compatibility residual of the LTCA"));
    }
  };
  struct Optimizer {
    std::string backend = "ipopt";
    int starts = kDefaultStarts, max_evaluations = kDefaultMaxEvaluations, verify_rounds = kDefaultVerifyRounds;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("backend", &backend, BackendField({optimizers::Backend::kIpopt, optimizers::Backend::kSlsqp}).Desc("the solver: Ipopt or NLopt's SLSQP"));
      a->Visit("starts", &starts, Field().AtLeast(1).AtMost(10, "at most 10 starts").Desc("starts of the solver"));
      a->Visit("max_evaluations", &max_evaluations,
               Field().AtLeast(1).AtMost(10000, "at most 10000").Desc("per solve: Ipopt iterations, SLSQP evaluations"));
      a->Visit("verify_rounds", &verify_rounds,
               Field().AtLeast(0).AtMost(10, "at most 10 rounds").Desc("rounds of the accurate model's verification"));
    }
  };
  struct Load {
    std::optional<double> input_speed_rpm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("input_speed_rpm", &input_speed_rpm,
               Field().Positive().Unit("rpm").Desc(
                   "input (crank) speed: the bearing lives at target.design_torque_Nm (a one-line duty cycle; "
                   "docs/life.md, Cycloid)"));
    }
  };

  std::string study = "cycloid_min_size", name;
  std::optional<std::string> description;
  Target target;
  Variables variables;
  std::optional<Drive> drive;
  std::optional<cycloid_common::ModificationInput> modification;
  std::optional<cycloid_common::CrowningStartInput> crowning;
  Limits limits;
  std::string objective = "outer_diameter";
  MaterialInput material;
  Analysis analysis;
  Optimizer optimizer;
  std::optional<Load> load;
  cycloid_common::CycloidDutyCycleInput duty_cycle;
  std::optional<KindedBearingRatingInput<false>> crank_bearing;
  std::optional<BearingRatingInput<false>> pins;
  std::optional<cycloid_common::CompliantOutputMechanismInput> output_mechanism;
  std::optional<LubricantInput> lubricant;
  std::optional<SurfacesInput> surfaces;
  std::optional<CycloidBearingFrictionInput> bearing_friction;
  std::optional<SizingRatingsInput> ratings;
  std::optional<TorsionalDynamicsInput> torsional_dynamics;

  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Required().Const("cycloid_min_size").Desc("the study kind"));
    a->Visit("name", &name, Field().Desc("the design's name, in titles"));
    a->Visit("description", &description, Field().Desc("free text"));
    a->Visit("target", &target, Field().Required().Desc("the ratio and the torques"));
    a->Visit("variables", &variables,
             Field().Required().Desc("the sized fields, named as in cycloid_ltca; at least one a range"));
    a->Visit("drive", &drive, Field().Desc("fixed drive fields (not in variables)"));
    a->Visit("modification", &modification, Field().Desc("fixed modifications (not in variables; absent: 0)"));
    a->Visit("crowning", &crowning,
             Field().Desc("the crowning type and its fixed fields (a field in variables is left out here); none "
                          "when absent"));
    a->Visit("limits", &limits, Field().Required().Desc("what the sized drive must meet"));
    a->Visit("objective", &objective,
             Field().OneOf({"outer_diameter", "volume", "efficiency"}, "one of \"outer_diameter\", \"volume\", \"efficiency\"")
                 .Desc("what is minimised: 2 (a + ρ), π (a + ρ)² b, or (efficiency, with lubricant) the lubricated loss "
                       "at design_torque_Nm and load.input_speed_rpm: the most efficient drive within the ranges"));
    a->Visit("material", &material, Field().Required().Desc("the disc's and pins' elastic material"));
    a->Visit("analysis", &analysis, Field().Desc("the fast model's contact grid, crank angles and tolerance"));
    a->Visit("optimizer", &optimizer, Field().Desc("the solver, its starts and budget, the verification"));
    a->Visit("load", &load, Field().Desc("the input speed, for the bearing lives"));
    cycloid_common::VisitLifeRatings(a, &duty_cycle, &crank_bearing, &pins,
                                     "; the time shares sum to 1 within 1e-6, at least one speed > 0"
                                     "; each line one cycle of the sizing at its torque");
    a->Visit("output_mechanism", &output_mechanism,
             Field().Desc("output pins in the disc's holes, as cycloid_ltca's: pin circle radius (inside the disc's "
                          "root radius) and pin count (absent: the continuous limit), rigid for the life (docs/life.md, "
                          "Cycloid); with pin_radius_mm and hole_radius_mm the mechanism with clearance and compliance "
                          "for the stiffness, lost motion, output-pin stress and crank-bearing load: the pins fixed, the holes "
                          "made for the sized eccentricity with the start's radial clearance hole_radius_mm - "
                          "pin_radius_mm (or roller_radius_mm) - e (docs/cycloid.md, Output mechanism)"));
    a->Visit("lubricant", &lubricant,
             Field().Desc("the oil: the lubricated efficiency and oil temperature of each design at design_torque_Nm "
                          "and load.input_speed_rpm (needs output_mechanism; docs/lubrication.md), limited by "
                          "limits.min_efficiency and limits.max_oil_temperature_C"));
    a->Visit("surfaces", &surfaces,
             Field().Desc("roughness, friction by regime and the ring pins' mounting (with lubricant)"));
    a->Visit("bearing_friction", &bearing_friction,
             Field().Desc("Palmgren's factors of the ring pins', output rollers' and crank bearings (with lubricant; a "
                          "bearing not given is not modelled)"));
    a->Visit("ratings", &ratings,
             Field().Desc("the rated torque the sized drive must reach, as cycloid_ltca's ratings define it: the life "
                          "rows over one cycle at that torque and the rated speed, and the momentary torque's static "
                          "rows over one more (docs/ratings.md, Ratings as sizing limits); needs crank_bearing and "
                          "output_mechanism"));
    a->Visit("torsional_dynamics", &torsional_dynamics,
             Field().Desc("the sized drive's torsional dynamics, as cycloid_ltca's (docs/torsional_dynamics.md): run on "
                          "the verified design by cycloid_ltca's model and carried into best_cycloid_ltca.json; its "
                          "max_dynamic_factor is a limit of the verification (a design above it is not verified, exit "
                          "3; the optimizer does not steer by it)"));
  }
  /// The rules between blocks: each sized field once (in variables or its block), the drive's
  /// fields somewhere, the crowning's fields by its type, a life's blocks.
  static nlohmann::ordered_json SchemaRules();
  /// The ranges against their starts, the face width and the pin count (a plausible drive in the
  /// whole box).
  static std::vector<CrossFieldRule> CrossFieldRules() {
    return {{{"variables"}, "a variable's start within its range", "a start within the range"},
            {{"crowning", "variables", "drive"},
             "a logarithmic crowning's effective length can reach the face width within its range",
             "below the face width"},
            {{"target", "variables", "drive"},
             "the pin count against the eccentricity and pin circle ranges: not too curtate at the most favourable "
             "corner",
             "too curtate"},
            {{"target", "variables", "drive"},
             "the pin count against the eccentricity and pin circle ranges: a shortening coefficient e z₂ / R_p in "
             "0.05 to 1 in the whole box",
             "shortening coefficient"}};
  }
};

struct Study {
  std::string name;
  /// Teeth, rollers, torques, material, the fast model's grid and angles, the variables (bounds and
  /// starts in their own units), the fixed fields (in spec.drive / spec.crowning), the limits and the
  /// objective: what sizing::SolveCycloidMinSize is given.
  sizing::CycloidSizingSpec spec;
  sizing::CycloidMinSizeOptions options;  ///< without the progress callback (set by Run)
  double design_torque_Nm = 0, overload_torque_Nm = 0;  ///< as in the file (0: no overload)
  bool ratio_given = false;          ///< target.speed_ratio (else target.teeth)
  double bore_diameter_mm = 0;       ///< limits.bore_diameter_mm (0: none)
  std::string backend = "ipopt";     ///< as in the file: "ipopt" or "slsqp"
  /// "lubricant", "surfaces", "bearing_friction" as read (the best design's cycloid_ltca study takes
  /// them); none without lubricant.
  LubricationEcho<CycloidBearingFrictionInput> lubrication_blocks;
  /// "ratings": the rated point the life rows hold (spec.life's one line, spec.limits.life_h).
  std::optional<SizingRatingsInput> ratings;
  /// "torsional_dynamics" as read (none: not asked): the best design's cycloid_ltca study takes it.
  std::optional<TorsionalDynamicsInput> torsional_dynamics;
};

struct Result {
  /// The ratio and the torques sized for.
  struct Target {
    int teeth = 0, rollers = 0, speed_ratio = 0;
    double design_torque_Nm = 0;
    std::optional<double> overload_torque_Nm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("teeth", &teeth, Field().Desc("z, the disc's teeth"));
      a->Visit("rollers", &rollers, Field().Desc("z + 1, the ring's pins"));
      a->Visit("speed_ratio", &speed_ratio,
               Field().Desc("the reduction z (ring fixed, output from the disc, turning the other way)"));
      a->Visit("design_torque_Nm", &design_torque_Nm, Field().Unit("N·m").Desc("on the disc"));
      a->Visit("overload_torque_Nm", &overload_torque_Nm,
               Field().Unit("N·m").Desc("the overload cycle's torque, when the study gives one"));
    }
  };
  /// A sized field: its range and its start, in the field's own unit (µm for the modifications).
  struct VariableRow {
    std::string name;
    double lower = 0, upper = 0, start = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("name", &name, Field().Desc("the cycloid_ltca field it sets"));
      a->Visit("lower", &lower, Field().Desc("the range's lower bound [mm, or µm for delta_*_um]"));
      a->Visit("upper", &upper, Field().Desc("the range's upper bound [mm, or µm for delta_*_um]"));
      a->Visit("start", &start, Field().Desc("the first start [mm, or µm for delta_*_um]"));
    }
  };
  /// The sized drive, as cycloid_ltca's "drive".
  struct Drive {
    int teeth = 0, rollers = 0;
    double roller_position_radius_mm = 0, roller_radius_mm = 0, eccentricity_mm = 0, face_width_mm = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("teeth", &teeth, Field().Desc("z, the disc's teeth"));
      a->Visit("rollers", &rollers, Field().Desc("z + 1, the pins"));
      a->Visit("roller_position_radius_mm", &roller_position_radius_mm, Field().Unit("mm").Desc("a, the pins' circle"));
      a->Visit("roller_radius_mm", &roller_radius_mm, Field().Unit("mm").Desc("ρ, of each pin"));
      a->Visit("eccentricity_mm", &eccentricity_mm, Field().Unit("mm").Desc("e, the crank's eccentricity"));
      a->Visit("face_width_mm", &face_width_mm, Field().Unit("mm").Desc("b, the disc's width"));
    }
  };
  /// The sized profile modifications, as cycloid_ltca's "modification".
  struct Modification {
    double delta_position_um = 0, delta_radius_um = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("delta_position_um", &delta_position_um, Field().Unit("µm").Desc("Δa, of the pins' circle radius"));
      a->Visit("delta_radius_um", &delta_radius_um, Field().Unit("µm").Desc("Δr, of the pin radius"));
    }
  };
  /// A variable the optimum presses against a bound of its range (within 0.1% of the range).
  struct AtBound {
    std::string name, bound;
    double value = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("name", &name, Field().Desc("the variable"));
      a->Visit("bound", &bound, Field().OneOf({"lower", "upper"}));
      a->Visit("value", &value, Field().Desc("the bound [mm, or µm for delta_*_um]"));
    }
  };
  /// One model's values at the reported design (the accurate or the fast settings).
  struct Model {
    double max_contact_stress_MPa = 0, max_pair_load_N = 0;
    std::optional<double> edge_margin_at_overload_um, backlash_min_arcsec, backlash_max_arcsec;
    double lte_peak_to_peak_arcsec = 0;
    std::optional<double> torsional_stiffness_Nm_per_arcmin, lost_motion_arcmin, output_pin_bending_stress_MPa,
        eccentric_bearing_load_N;
    std::optional<double> efficiency, power_loss_W, oil_temperature_C;
    std::optional<std::string> lubrication_error;
    bool converged = true;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa,
               Field().Unit("MPa").Desc("peak pressure over the design-torque cycle"));
      a->Visit("max_pair_load_N", &max_pair_load_N, Field().Unit("N").Desc("largest load of a tooth pair"));
      a->Visit("edge_margin_at_overload_um", &edge_margin_at_overload_um,
               Field().Unit("µm").Desc("with an overload torque: the contact's least end distance from the face ends"));
      a->Visit("backlash_min_arcsec", &backlash_min_arcsec,
               Field().Unit("arcsec").Desc("the smallest unloaded TE β0 over the angles (when computed)"));
      a->Visit("backlash_max_arcsec", &backlash_max_arcsec,
               Field().Unit("arcsec").Desc("the largest unloaded TE β0 over the angles (when computed)"));
      a->Visit("lte_peak_to_peak_arcsec", &lte_peak_to_peak_arcsec,
               Field().Unit("arcsec").Desc("the loaded transmission error's peak to peak"));
      const std::string output = "with output_mechanism's pin_radius_mm and hole_radius_mm (null: not solved): ";
      a->Visit("torsional_stiffness_Nm_per_arcmin", &torsional_stiffness_Nm_per_arcmin,
               Field().NullWhenNotFinite().Unit("N·m/arcmin").Desc(
                   output + "the torsional stiffness between 50% and 100% of the design torque, crank 0"));
      a->Visit("lost_motion_arcmin", &lost_motion_arcmin,
               Field().NullWhenNotFinite().Unit("arcmin").Desc(output + "the lost motion between ±3% of it"));
      a->Visit("output_pin_bending_stress_MPa", &output_pin_bending_stress_MPa,
               Field().NullWhenNotFinite().Unit("MPa").Desc(output + "the output pins' largest bending stress"));
      a->Visit("eccentric_bearing_load_N", &eccentric_bearing_load_N,
               Field().NullWhenNotFinite().Unit("N").Desc(output + "the largest eccentric (crank) bearing load"));
      const std::string oil = "with lubricant, at the design torque and input speed (null: not computed): ";
      a->Visit("efficiency", &efficiency,
               Field().NullWhenNotFinite().Desc(oil + "the lubricated efficiency, a revolution's mean"));
      a->Visit("power_loss_W", &power_loss_W, Field().NullWhenNotFinite().Unit("W").Desc(oil + "one disc's loss"));
      a->Visit("oil_temperature_C", &oil_temperature_C,
               Field().NullWhenNotFinite().Unit("°C").Desc(oil + "the oil temperature"));
      a->Visit("lubrication_error", &lubrication_error,
               Field().Desc("with lubricant: why the lubricated losses were not computed"));
      a->Visit("converged", &converged, Field().Desc("every contact of both cycles converged"));
    }
  };
  /// The estimated error of the accurate values: |accurate − fast| (objectives/verification.h).
  struct EstimatedError {
    double max_contact_stress_MPa = 0, backlash_arcsec = 0, lte_peak_to_peak_arcsec = 0;
    std::optional<double> edge_margin_at_overload_um;
    std::optional<double> torsional_stiffness_Nm_per_arcmin, lost_motion_arcmin, output_pin_bending_stress_MPa,
        eccentric_bearing_load_N, efficiency, oil_temperature_C;
    std::optional<double> shortest_L10h, min_static_safety;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa, Field().Unit("MPa"));
      a->Visit("backlash_arcsec", &backlash_arcsec, Field().Unit("arcsec"));
      a->Visit("lte_peak_to_peak_arcsec", &lte_peak_to_peak_arcsec, Field().Unit("arcsec"));
      a->Visit("edge_margin_at_overload_um", &edge_margin_at_overload_um,
               Field().Unit("µm").Desc("with an overload torque"));
      const std::string output = "with output_mechanism's pin_radius_mm and hole_radius_mm (null: not solved)";
      a->Visit("torsional_stiffness_Nm_per_arcmin", &torsional_stiffness_Nm_per_arcmin,
               Field().NullWhenNotFinite().Unit("N·m/arcmin").Desc(output));
      a->Visit("lost_motion_arcmin", &lost_motion_arcmin, Field().NullWhenNotFinite().Unit("arcmin").Desc(output));
      a->Visit("output_pin_bending_stress_MPa", &output_pin_bending_stress_MPa,
               Field().NullWhenNotFinite().Unit("MPa").Desc(output));
      a->Visit("eccentric_bearing_load_N", &eccentric_bearing_load_N,
               Field().NullWhenNotFinite().Unit("N").Desc(output));
      a->Visit("efficiency", &efficiency, Field().NullWhenNotFinite().Desc("with lubricant (null: not computed)"));
      a->Visit("oil_temperature_C", &oil_temperature_C,
               Field().NullWhenNotFinite().Unit("°C").Desc("with lubricant (null: not computed)"));
      a->Visit("shortest_L10h", &shortest_L10h, Field().Unit("h").Desc("with the bearing lives"));
      a->Visit("min_static_safety", &min_static_safety,
               Field().NullWhenNotFinite().Desc("with ratings.momentary_torque_Nm: of s0 at the momentary torque"));
    }
  };
  /// With lubricant: where the lubricated values of `accurate` and `fast` were computed.
  struct Lubrication {
    double input_speed_rpm = 0, output_torque_Nm = 0;
    std::string temperature_source, model;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("input_speed_rpm", &input_speed_rpm, Field().Unit("rpm").Desc("load.input_speed_rpm"));
      a->Visit("output_torque_Nm", &output_torque_Nm, Field().Unit("N·m").Desc("the design torque"));
      a->Visit("temperature_source", &temperature_source,
               Field().OneOf({"given", "thermal balance"}).Desc("the oil's temperature: lubricant.temperature_C or "
                                                                "the housing's heat balance"));
      a->Visit("model", &model, Field().Desc("the loss model, in words"));
    }
  };
  /// The reported design: the best one, or the closest when it is not verified.
  struct Best {
    double outer_diameter_mm = 0, envelope_volume_mm3 = 0;
    Drive drive;
    Modification modification;
    cycloid_common::CrowningInput crowning;  ///< as cycloid_ltca's "crowning" (cycloid_common::CrowningInputOf)
    std::map<std::string, double> variables;
    std::vector<AtBound> variables_at_bounds;
    double curtate_margin = 0, undercut_margin_mm = 0, min_profile_radius_mm = 0, pin_gap_margin_mm = 0;
    std::optional<double> web_margin_mm;
    Model accurate, fast;
    std::optional<double> output_holes_margin_mm;
    std::optional<Lubrication> lubrication;
    EstimatedError estimated_error;
    std::string accurate_model;
    std::optional<cycloid_common::SizingLifeBlock> life;
    std::optional<SizedRatingsBlock> ratings;
    std::optional<OrError<TorsionalDynamicsBlock>> torsional_dynamics;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("outer_diameter_mm", &outer_diameter_mm, Field().Unit("mm").Desc("2 (a + ρ) of drive"));
      a->Visit("envelope_volume_mm3", &envelope_volume_mm3, Field().Unit("mm³").Desc("π (a + ρ)² b"));
      a->Visit("drive", &drive, Field().Desc("every cycloid_ltca drive field"));
      a->Visit("modification", &modification, Field().Desc("the profile modifications"));
      a->Visit("crowning", &crowning, Field().Desc("the crowning, its type and fields"));
      a->Visit("variables", &variables,
               Field().Desc("the optimizer's value of each variable, by name [mm, or µm for delta_*_um]"));
      a->Visit("variables_at_bounds", &variables_at_bounds,
               Field().Desc("the variables at a bound of their range (widening it may shrink the drive)"));
      a->Visit("curtate_margin", &curtate_margin,
               Field().Desc("1 − e (z + 1) / a' (closed form; >= min_curtate_margin holds)"));
      a->Visit("undercut_margin_mm", &undercut_margin_mm,
               Field().Unit("mm").Desc("ρ_min − ρ' − min_profile_radius_mm: not undercut when >= 0 (closed form)"));
      a->Visit("min_profile_radius_mm", &min_profile_radius_mm,
               Field().Unit("mm").Desc("the tooth's smallest convex radius of curvature, ρ_min − ρ'"));
      a->Visit("pin_gap_margin_mm", &pin_gap_margin_mm,
               Field().Unit("mm").Desc("2 a sin(π/N) − 2ρ − min_pin_gap_mm: the pins clear when >= 0 (closed form)"));
      a->Visit("web_margin_mm", &web_margin_mm,
               Field().Unit("mm").Desc(
                   "with a bore: (a' − e − ρ') − bore radius − min_web_mm, >= 0 holds (closed form)"));
      a->Visit("accurate", &accurate,
               Field().Desc("the accurate model's values (twice the cells each way and twice the crank angles)"));
      a->Visit("fast", &fast, Field().Desc("the fast model's values (the optimizer's)"));
      a->Visit("output_holes_margin_mm", &output_holes_margin_mm,
               Field().Unit("mm").Desc("with the compliant output mechanism: the holes' fit in the disc"));
      a->Visit("lubrication", &lubrication, Field().Desc("with lubricant: the operating point of the lubricated values"));
      a->Visit("estimated_error", &estimated_error, Field().Desc("of the accurate values, key by key, in their units"));
      a->Visit("accurate_model", &accurate_model, Field().Desc("the accurate model, in words"));
      a->Visit("life", &life,
               Field().Desc("with a speed or duty cycle: the accurate model's bearing lives"));
      a->Visit("ratings", &ratings, Field().Desc("with ratings: the rated and momentary torques checked"));
      a->Visit("torsional_dynamics", &torsional_dynamics,
               Field().Desc("with torsional_dynamics: cycloid_ltca's block for the reported design, or its error"));
    }
  };
  /// One start's solve in the first round.
  struct StartOutcome {
    std::string status, message;
    double objective = 0, max_violation = 0, first_order_residual = 0;
    int evaluations = 0, gradient_evaluations = 0, iterations = 0;
    std::vector<double> x;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("status", &status, Field().Desc("the solver's end"));
      a->Visit("message", &message, Field().Desc("the backend's own words"));
      a->Visit("objective", &objective,
               Field().NullWhenNotFinite().Desc("at its end [mm, mm³ or W of loss, as objective]"));
      a->Visit("max_violation", &max_violation,
               Field().NullWhenNotFinite().Desc("largest constraint violation (scaled)"));
      a->Visit("first_order_residual", &first_order_residual,
               Field().NullWhenNotFinite().Desc(
                   "the first-order optimality residual (0 at a KKT point; null: not computed)"));
      a->Visit("evaluations", &evaluations, Field().Desc("model runs for values"));
      a->Visit("gradient_evaluations", &gradient_evaluations, Field().Desc("model runs with exact derivatives"));
      a->Visit("iterations", &iterations, Field().Desc("backend iterations (Ipopt), else evaluations"));
      a->Visit("x", &x, Field().NullWhenNotFinite().Desc("the end point, in the order of variables"));
    }
  };
  /// The solves (SolveSummary: the model runs are LTCA runs), the starts and each start's solve.
  struct Optimizer : SolveSummary {
    int starts = 0;
    std::vector<std::string> binding_rows;
    std::vector<StartOutcome> start_outcomes;
    template <typename Archive>
    void Serialize(Archive* a) {
      SolveSummary::Serialize(a);
      a->Visit("starts", &starts, Field().Desc("starts of the solver"));
      a->Visit("binding_rows", &binding_rows, Field().Desc("the constraint rows active at the answer"));
      a->Visit("start_outcomes", &start_outcomes, Field().Desc("each start's solve in the first round"));
    }
  };
  /// The contact settings of a model, as cycloid_ltca's "analysis".
  struct Settings {
    std::array<int, 2> grid{};
    int crank_angles_per_mesh_period = 0;
    double tolerance = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("grid", &grid, Field().Desc("[profile_cells, axial_cells]"));
      a->Visit("crank_angles_per_mesh_period", &crank_angles_per_mesh_period, Field().Desc("uniform crank angles"));
      a->Visit("tolerance", &tolerance, Field().Desc("relative compatibility residual of the LTCA"));
    }
  };
  /// The fast model's settings and the accurate ones.
  struct Analysis : Settings {
    Settings accurate;
    template <typename Archive>
    void Serialize(Archive* a) {
      Settings::Serialize(a);
      a->Visit("accurate", &accurate,
               Field().Desc("the verification's and the plots' (twice the cells each way, twice the crank angles)"));
    }
  };

  // result.json (studies/archive.h): Run fills these members (FillResult), Write writes them.
  std::string study = "cycloid_min_size", name;
  Target target;
  std::string objective = "outer_diameter";
  std::vector<VariableRow> variables;
  bool verified = false;
  VerificationBlock verification;
  std::optional<Best> best;
  std::vector<BindingLimit> binding_limits;
  Optimizer optimizer;
  Analysis analysis;
  std::optional<std::vector<std::string>> notes;
  std::vector<std::string> warnings;  ///< the run's own (RunStudy adds the implausible inputs')
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Const("cycloid_min_size").Desc("the study kind"));
    a->Visit("name", &name, Field().Desc("the study's name"));
    a->Visit("target", &target, Field().Desc("the ratio and the torques sized for"));
    a->Visit("objective", &objective,
             Field().OneOf({"outer_diameter", "volume", "efficiency"}).Desc("what was minimised"));
    a->Visit("variables", &variables, Field().Desc("the sized fields, their ranges and starts"));
    a->Visit("verified", &verified,
             Field().Desc("the accurate model holds every limit at the reported design (a view of status)"));
    a->Visit("verification", &verification,
             Field().Desc("each limit's check on the accurate model and the tightening rounds "
                          "(studies/verification_json.h)"));
    a->Visit("best", &best,
             Field().NullWhenAbsent().Desc("the reported design (the closest when not verified; null: no design)"));
    a->Visit("binding_limits", &binding_limits, Field().Desc("each limit that binds at the optimum and what it costs"));
    a->Visit("optimizer", &optimizer, Field().Desc("the solves (counts only: no times, two runs write the same file)"));
    a->Visit("analysis", &analysis, Field().Desc("the fast model's settings and the accurate ones"));
    a->Visit("notes", &notes, Field().Desc("why the answer is not what was asked, when it is not"));
    a->Visit("warnings", &warnings, Field().Desc("the run's warnings"));
  }
  // Not in result.json: the sizing's outcome and the best design's cycle, which the other files
  // are drawn from.
  sizing::CycloidMinSizeOutcome outcome;
  /// The best design's cycle at the design torque on the accurate settings (cells and crank angles
  /// twice the study's): the stress plot and the pressure map. Empty when there is no design.
  cycloid::CycleResult best_cycle;
  std::vector<double> best_cycle_angles_rad;
  /// Not empty when the answer is not what was asked (exit 3): the limit that blocks, its value and
  /// what would fit.
  std::string blocking_message;
  /// With "torsional_dynamics": cycloid_ltca's "torsional_dynamics" object for the reported design
  /// (or {"error": why}); none without.
  std::optional<OrError<TorsionalDynamicsBlock>> torsional;
  double seconds = 0;  ///< wall time of the run (stderr summary only, never in a file)
};

/// @throws StudyError for bad input (exit 2).
Study Parse(const Node& root);
/// Sizes the drive and fills result.json's members of Result (FillResult).
Result Run(const Study& study, const RunContext& ctx);
/// The best design as a complete cycloid_ltca study (the accurate settings, the design torque);
/// null when there is no design.
nlohmann::json BestCycloidLtcaStudy(const Study& study, const Result& result);
/// The start design (every field's start or fixed value, spec.drive and spec.crowning) as a
/// complete cycloid_ltca study, made as BestCycloidLtcaStudy makes the best one.
nlohmann::json StartCycloidLtcaStudy(const Study& study);
/// result.json, best_cycloid_ltca.json, stress_over_cycle.csv/.svg, pressure_map.svg; marks the
/// outputs incomplete (exit 3) when the answer is not verified or there is none.
void Write(const Study& study, const Result& result, Outputs& out);
/// Lines for the terminal: outer diameter, what each binding limit costs, the time split.
std::string Summary(const Study& study, const Result& result);

}  // namespace camopt::studies::cycloid_min_size
