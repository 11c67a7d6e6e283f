// Study kind "lcr_min_size": the smallest lobe cam reducer for a target speed ratio and output
// torque (or, with "objective": "efficiency" and a lubricant, the one that loses least power at
// that torque and the lubricant's speed, within limits.max_outer_diameter_mm when given).
// Enumerates every lobe/roller combination giving the ratio exactly, solves each to the
// optimum of the exact constraints (sizing/lcr_min_size.h), and reports the best design, what
// each binding limit costs in the objective (limit_sensitivity), and one candidate per combination (and catalogue
// roller) with its multistart spread and, when nothing fits, the limits it breaks at its closest
// point. Nothing fitting is an incomplete result (exit code 3, outputs still written).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include <cstddef>
#include <variant>

#include <nlohmann/json.hpp>

#include "sizing/lcr_min_size.h"
#include "sizing/lcr_search.h"
#include "objectives/lcr_robust.h"
#include "sizing/lcr_robust_solve.h"
#include "objectives/lcr_sizing.h"
#include "sizing/lcr_sizing3d.h"
#include "studies/backend_input.h"
#include "studies/bearing_life_io.h"
#include "studies/contact_fatigue_input.h"
#include "studies/archive.h"
#include "studies/input.h"
#include "studies/lcr_contact_input.h"
#include "studies/lcr_input.h"
#include "studies/lcr_tolerance_input.h"
#include "studies/lubrication_input.h"
#include "studies/material_input.h"
#include "studies/ratings.h"
#include "studies/ratings_input.h"
#include "studies/study.h"
#include "studies/verification_json.h"

namespace camopt::studies::lcr_min_size {

/// A roller of "roller_catalogue" as the study or its catalogue file gives it, declared once.
struct CatalogueRollerInput {
  std::optional<std::string> name;
  double diameter_mm = 0, length_mm = 0, load_limit_N = 0;
  std::optional<double> dynamic_rating_N, static_rating_N;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("name", &name, Field().Desc("the roller's name in the results (absent: roller N, its place in the list)"));
    a->Visit("diameter_mm", &diameter_mm, Field().Required().Positive().Unit("mm").Desc("roller diameter d_r"));
    a->Visit("length_mm", &length_mm, Field().Required().Positive().Unit("mm").Desc("roller length"));
    a->Visit("load_limit_N", &load_limit_N,
             Field().Required().In(1e-3, 1e9, "a load limit in [0.001, 1e9] N").Unit("N").Desc(
                 "the roller's load limit (the smaller of it and limits.roller_load_N holds)"));
    a->Visit("dynamic_rating_N", &dynamic_rating_N,
             Field().Positive().Unit("N").Desc("C, the basic dynamic load rating (ISO 281); required with a speed or "
                                               "duty cycle"));
    a->Visit("static_rating_N", &static_rating_N,
             Field().Positive().Unit("N").Desc("C0, the basic static load rating (ISO 76): s0 is reported when given"));
  }
};

/// "roller_catalogue": {"file": "rollers.json"}, a list of rollers in a file of its own.
struct CatalogueFileInput {
  std::string file;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("file", &file,
             Field().Required().Desc("the catalogue's file (a list of rollers), relative to the study file"));
  }
};

/// "roller_catalogue": the list of rollers, or the file that holds it.
using RollerCatalogueInput = std::variant<CatalogueFileInput, std::vector<CatalogueRollerInput>>;

/// The study file as declared: each field once, in the file's units, with its default, bounds and
/// description (studies/archive.h); the blocks shared with the other LCR kinds are those of
/// studies/lcr_input.h, lcr_contact_input.h, lcr_tolerance_input.h and material_input.h. Parse reads
/// it and checks what spans fields; `camopt schema lcr_min_size` is emitted from it.
struct Input {
  struct Target {
    int speed_ratio = 0;
    double output_torque_Nm = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("speed_ratio", &speed_ratio,
               Field().Required().In(-1e6, 1e6, kRatioText)
                   .Desc("r_i = m_A n_B/(m_A n_B − m_B n_A), matched exactly: a whole number, 2 <= abs(r_i) <= 1e6"));
      a->Visit("output_torque_Nm", &output_torque_Nm,
               Field().Required().AtLeast(kMinLcrTorqueNm, kMinLcrTorqueExpected).Unit("N·m").Desc("T_o, the output torque"));
    }
    static constexpr const char* kRatioText = "a whole-number speed ratio with 2 <= |ratio| <= 1e6";
    /// |ratio| >= 2.
    static nlohmann::ordered_json SchemaRules() {
      return nlohmann::ordered_json::parse(
          R"({"allOf": [{"properties": {"speed_ratio": {"not": {"minimum": -1, "maximum": 1}}}}]})");
    }
  };
  struct Search {
    int max_lobes = 40;
    std::vector<int> roller_lobe_difference{1};
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("max_lobes", &max_lobes,
               Field().AtLeast(1).AtMost(200, "a number of lobes <= 200").Desc("the largest lobe count on either cam"));
      a->Visit("roller_lobe_difference", &roller_lobe_difference,
               Field().AtLeast(1).AtMost(1, "1 (a roller-lobe difference above 1 makes the pitch curve wind several "
                                            "times: a self-crossing cam, see lcr::CheckDesign)")
                   .MinItems(1, "a non-empty list")
                   .Desc("n − m on each cam: only 1 (above 1 the cam self-crosses)"));
    }
  };
  struct Variables {
    std::array<double, 2> eccentricity_mm{}, turret_radius_mm{};
    std::optional<std::array<double, 2>> roller_diameter_mm;
    bool same_roller_on_both_cams = true;
    std::optional<std::array<double, 2>> crowning_coefficient_mm, crowning_radius_mm, crowning_flat_length_mm,
        roller_length_mm, cam_thickness_mm;
    template <typename Archive>
    void Serialize(Archive* a) {
      const char* range = "[lower, upper], two numbers";
      const char* positive = "a [lo, hi] range with lo > 0";
      a->Visit("eccentricity_mm", &eccentricity_mm,
               Field().Required().Positive(positive).Expect(range).NamesTheArray().Unit("mm").Desc("[lower, upper] of the eccentricity e"));
      a->Visit("turret_radius_mm", &turret_radius_mm,
               Field().Required().Positive(positive).Expect(range).NamesTheArray().Unit("mm").Desc(
                   "[lower, upper] of both turret radii r_d"));
      a->Visit("roller_diameter_mm", &roller_diameter_mm,
               Field().Positive(positive).Expect(range).NamesTheArray().Unit("mm").Desc(
                   "[lower, upper] of the roller diameter d_r (one size for both cams unless same_roller_on_both_cams "
                   "is false); required without a roller catalogue"));
      a->Visit("same_roller_on_both_cams", &same_roller_on_both_cams,
               Field().Desc("false: a roller diameter per cam (not with a catalogue)"));
      a->Visit("crowning_coefficient_mm", &crowning_coefficient_mm,
               Field().In(0.0, 1.0, "a [lo, hi] range with 0 <= lo < hi <= 1 mm").Expect(range).NamesTheArray().Unit("mm").Desc(
                   "[lower, upper] of the logarithmic crowning coefficient f of each cam; needs fixed.crowning of type "
                   "logarithmic (0: a straight roller)"));
      a->Visit("crowning_radius_mm", &crowning_radius_mm,
               Field().In(1e-9, 1e6, "a [lo, hi] range with 1e-09 <= lo < hi <= 1e+06 mm").Expect(range).NamesTheArray().Unit("mm").Desc(
                   "[lower, upper] of the crowning radius R of each cam; needs fixed.crowning of type circular or "
                   "partial (its radius_mm is the start) and a 3D contact"));
      a->Visit("crowning_flat_length_mm", &crowning_flat_length_mm,
               Field().In(0.0, 1e6, "a [lo, hi] range with 0 <= lo < hi <= 1e+06 mm").Expect(range).NamesTheArray().Unit("mm").Desc(
                   "[lower, upper] of the flat length L0 of each cam's partial crown; needs fixed.crowning of type "
                   "partial (its flat_length_mm is the start) and a 3D contact"));
      a->Visit("roller_length_mm", &roller_length_mm,
               Field().Positive("a [lo, hi] range with 0 < lo < hi mm").Expect(range).NamesTheArray().Unit("mm").Desc(
                   "[lower, upper] of the roller length of both cams (fixed.roller_length_mm is the start); only with "
                   "a 3D contact (slices or half_space) and without a roller catalogue"));
      a->Visit("cam_thickness_mm", &cam_thickness_mm,
               Field().Positive("a [lo, hi] range with 0 < lo < hi mm").Expect(range).NamesTheArray().Unit("mm").Desc(
                   "[lower, upper] of the thickness of both cams (fixed.cam_thickness_mm is the start); only with a 3D "
                   "contact (slices or half_space)"));
    }
  };
  struct Fixed {
    double cam_thickness_mm = 0;
    std::optional<double> roller_length_mm;
    std::optional<LcrSizedCrowningInput> crowning;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("cam_thickness_mm", &cam_thickness_mm, Field().Required().Positive().Unit("mm").Desc("both cams' thickness"));
      a->Visit("roller_length_mm", &roller_length_mm,
               Field().Positive().Unit("mm").Desc("both cams' roller length; required without a roller catalogue"));
      a->Visit("crowning", &crowning,
               Field().Desc("roller crowning of both cams (docs/lcr.md); with variables.crowning_coefficient_mm a "
                            "logarithmic crown without coefficient_mm (the coefficient is a variable per cam); each "
                            "form takes its own fields only; needs a 3D contact"));
    }
  };
  struct Limits {
    std::optional<double> contact_stress_MPa, roller_load_N;
    double undercut_margin_mm = 0, roller_gap_mm = 0;
    std::optional<double> min_efficiency, life_h, max_oil_temperature_C, max_outer_diameter_mm;
    template <typename Archive>
    void Serialize(Archive* a) {
      // A limit is also its constraint's scale in the solvers: bounded to values a scale can take.
      a->Visit("contact_stress_MPa", &contact_stress_MPa,
               Field().In(1, 1e6, "a stress limit in [1, 1e6] MPa (hardened steel: 1000 to 4000)").Unit("MPa")
                   .Desc("the largest Hertz pressure p_max (absent: none)"));
      a->Visit("roller_load_N", &roller_load_N,
               Field().In(1e-3, 1e9, "a load limit in [0.001, 1e9] N").Unit("N")
                   .Desc("the largest roller force (absent: none)"));
      a->Visit("undercut_margin_mm", &undercut_margin_mm,
               Field().NonNegative().Unit("mm").Desc("smallest 1/κ_max − r_r, the cam's convex radius over the roller's"));
      a->Visit("roller_gap_mm", &roller_gap_mm,
               Field().NonNegative().Unit("mm").Desc("smallest gap between neighbouring rollers, 2 r_d sin(π/n) − d_r"));
      a->Visit("min_efficiency", &min_efficiency,
               Field().In(0.0, 0.999).Desc("the mean efficiency over the revolution: with load.friction_coefficient "
                                           "(the paper's eq. 33), or with a lubricant the lubricated efficiency "
                                           "(docs/lubrication.md; absent: none)"));
      a->Visit("max_oil_temperature_C", &max_oil_temperature_C,
               Field().In(-50.0, 300.0).Unit("°C").Desc(
                   "the oil temperature of the housing's balance at the target torque and load.input_speed_rpm "
                   "(needs lubricant.thermal)"));
      a->Visit("life_h", &life_h,
               Field().Positive().Unit("h").Desc(
                   "the shortest ISO 281 basic rating life L10h of any rated bearing over load.input_speed_rpm or the "
                   "duty_cycle (docs/life.md); needs a speed"));
      a->Visit("max_outer_diameter_mm", &max_outer_diameter_mm,
               Field().In(1e-3, 1e6, "an outer diameter limit in [0.001, 1e6] mm").Unit("mm").Desc(
                   "the largest outer diameter 2 max(r_d + r_r) (absent: none); what bounds the size when the "
                   "objective is the efficiency"));
    }
  };
  struct Load {
    double friction_coefficient = 0;
    std::optional<double> overload_torque_Nm, input_speed_rpm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("friction_coefficient", &friction_coefficient,
               Field().In(0.0, 1.0).Desc("μ of the eccentric, T_in = (F_t + μ F_r) e (the paper's eq. 32): the "
                                         "efficiency"));
      a->Visit("overload_torque_Nm", &overload_torque_Nm,
               Field().Positive().Unit("N·m").Desc(
                   ">= target.output_torque_Nm: the pressure must stay off the contact ends at this torque (needs a "
                   "slices or half_space contact)"));
      a->Visit("input_speed_rpm", &input_speed_rpm,
               Field().Positive().Unit("rpm").Desc(
                   "input speed: the bearing lives at the target torque (a one-line duty cycle; docs/life.md); not "
                   "with duty_cycle"));
    }
  };
  struct Optimizer {
    std::string backend = "ipopt", constraints = "aggregate";
    bool polish = true;
    int samples_per_period = objectives::LcrSizingSpec{}.samples_per_period;
    double sharpness = objectives::LcrSizingSpec{}.sharpness;
    double tolerance = optimizers::SolverOptions{}.tolerance;
    std::optional<int> max_evaluations;
    int starts = sizing::LcrMinSizeOptions{}.starts;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("backend", &backend,
               BackendField({optimizers::Backend::kIpopt, optimizers::Backend::kSlsqp, optimizers::Backend::kMma,
                             optimizers::Backend::kCobyla},
                            /*old_spellings=*/true)
                   .Desc("the NLP solver (a local solve Ipopt ends at its iteration limit is polished by SLSQP); "
                         "nlopt_slsqp, nlopt_mma, nlopt_cobyla: the old spellings, deprecated"));
      a->Visit("constraints", &constraints,
               Field().OneOf({"aggregate", "samples"}).Desc(
                   "form of the smooth phase: the cycle maxima as soft aggregates or one row per angle sample"));
      a->Visit("polish", &polish,
               Field().Desc("polish every smooth optimum to the exact cycle maxima (tracked peaks, "
                            "docs/optimization.md); false only for comparisons"));
      a->Visit("samples_per_period", &samples_per_period,
               Field().AtLeast(4).AtMost(720, "a whole number between 4 and 720").Desc(
                   "angle samples per load period of each cam in the optimizer's problem"));
      a->Visit("sharpness", &sharpness, Field().Positive().Desc("log-sum-exp sharpness of the aggregates"));
      a->Visit("tolerance", &tolerance, Field().In(1e-14, 1e-2).Desc("relative optimality / step tolerance of each start"));
      a->Visit("max_evaluations", &max_evaluations,
               Field().AtLeast(10).AtMost(100000, "a whole number between 10 and 100000").Desc(
                   "per start: Ipopt's iterations, NLopt's evaluations (absent: 200 with ipopt, 3000 with NLopt)"));
      a->Visit("starts", &starts,
               Field().AtLeast(1).AtMost(5, "a number of starts between 1 and 5").Desc("starting points per combination"));
    }
  };
  /// "monte_carlo" of lcr_min_size: the check of the robust and the nominal best designs against the
  /// exact compliant model (the fields of lcr_analysis's, other defaults, no lost motion).
  struct MonteCarlo {
    /// Absent: 200 samples, seed 1, 720 angle steps (no schema default: the block needs tolerances).
    std::optional<int> samples, seed, angle_steps;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("samples", &samples,
               Field().AtLeast(0).AtMost(100000, "at most 100000 samples")
                   .Desc("Monte-Carlo samples of the exact model (absent: 200)"));
      a->Visit("seed", &seed, Field().AtLeast(0).Desc("seed of the samples (absent: 1)"));
      a->Visit("angle_steps", &angle_steps,
               Field().AtLeast(4).AtMost(3600, "at most 3600 angle steps")
                   .Desc("input angles over a revolution (absent: 720)"));
      a->Retired("lost_motion_torque_fraction", "no lost motion in lcr_min_size (lcr_analysis computes it)");
    }
  };
  struct Robust {
    std::string method;
    std::optional<double> k;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("method", &method,
               Field().Required().OneOf({"worst_case", "sigma"}).Desc(
                   "worst_case over the band box, or mean + k sigma with uniform deviations, of the linearised "
                   "constraints"));
      a->Visit("k", &k, Field().In(0.1, 10.0).Desc("sigma only: k of mean + k sigma (absent: 3)"));
    }
    static nlohmann::ordered_json SchemaRules() {  // k belongs to sigma
      return {{"if", {{"properties", {{"method", {{"const", "worst_case"}}}}}}},
              {"then", {{"not", {{"required", {"k"}}}}}}};
    }
  };
  /// "rollers": the ratings of a reference roller, scaled with the sized one (without a catalogue).
  struct Rollers {
    double dynamic_rating_N = 0;
    std::optional<double> static_rating_N;
    double reference_diameter_mm = 0;
    std::optional<double> reference_length_mm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("dynamic_rating_N", &dynamic_rating_N,
               Field().Required().Positive().Unit("N").Desc("C_ref, the reference roller's basic dynamic load rating (ISO 281)"));
      a->Visit("static_rating_N", &static_rating_N,
               Field().Positive().Unit("N").Desc("C0_ref, its basic static load rating (ISO 76): s0 is reported when given"));
      a->Visit("reference_diameter_mm", &reference_diameter_mm,
               Field().Required().Positive().Unit("mm").Desc("d_ref, the reference roller's diameter"));
      a->Visit("reference_length_mm", &reference_length_mm,
               Field().Positive().Unit("mm").Desc("L_ref, its length (absent: fixed.roller_length_mm)"));
    }
  };

  std::string study = "lcr_min_size", name;
  std::optional<std::string> description;
  std::string objective = "outer_diameter";
  Target target;
  Search search;
  Variables variables;
  Fixed fixed;
  Limits limits;
  std::optional<MaterialInput> material;
  Load load;
  Optimizer optimizer;
  std::optional<RollerCatalogueInput> roller_catalogue;
  std::optional<LcrContactOptionsInput> contact;
  std::optional<LcrTolerancesInput> tolerances;
  std::optional<MonteCarlo> monte_carlo;
  std::optional<Robust> robust;
  LcrDutyCycleInput duty_cycle;
  std::optional<Rollers> rollers;
  std::optional<EccentricBearingInput> eccentric_bearing;
  std::optional<LubricantInput> lubricant;
  std::optional<SurfacesInput> surfaces;
  std::optional<LcrBearingFrictionInput> bearing_friction;
  std::optional<SizingRatingsInput> ratings;

  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Required().Const("lcr_min_size").Desc("the study kind"));
    a->Visit("name", &name, Field().Desc("the design's name, copied to the result"));
    a->Visit("description", &description, Field().Desc("free text"));
    a->Visit("target", &target, Field().Required().Desc("the speed ratio and the output torque to size for"));
    a->Visit("search", &search, Field().Desc("the lobe/roller combinations tried"));
    a->Visit("variables", &variables, Field().Required().Desc("the sized quantities' bounds [lower, upper]"));
    a->Visit("fixed", &fixed, Field().Required().Desc("the sizes that are not variables"));
    a->Visit("limits", &limits, Field().Required().Desc("the limits every design must meet"));
    a->Visit("objective", &objective,
             Field().OneOf({"outer_diameter", "efficiency"}, "one of \"outer_diameter\", \"efficiency\"")
                 .Desc("what is minimised: the outer diameter, or (efficiency, with lubricant) the lubricated power "
                       "loss at target.output_torque_Nm and load.input_speed_rpm, the most efficient reducer within "
                       "the ranges and limits (limits.max_outer_diameter_mm bounds its size); the line contact "
                       "model without tolerances (not with a 3D contact or robust)"));
    a->Visit("material", &material,
             Field().Desc("the cams' and rollers' elastic material (absent: steel, E = 206 GPa, ν = 0.3)"));
    a->Visit("load", &load, Field().Desc("the friction, the overload torque and the speed"));
    a->Visit("optimizer", &optimizer, Field().Desc("the local solves of each combination"));
    a->Visit("roller_catalogue", &roller_catalogue, CatalogueField());
    a->Visit("contact", &contact,
             Field().Desc("finite-length roller contact model (docs/lcr.md); slices or half_space: the stress limit "
                          "holds for the slices model, the best design is re-checked with half_space"));
    a->Visit("tolerances", &tolerances,
             Field().Desc("± tolerance bands: the limits held across them (with robust; docs/lcr.md)"));
    a->Visit("monte_carlo", &monte_carlo,
             Field().Desc("Monte-Carlo check of the robust and the nominal best designs against the exact compliant "
                          "model"));
    a->Visit("robust", &robust,
             Field().Desc("the stress, force and undercut limits hold across the tolerances (objectives/lcr_robust.h); "
                          "requires tolerances"));
    a->Visit("duty_cycle", &duty_cycle,
             Field().MinItems(1, kDutyCycleNotEmpty).Desc(
                 "lines of the duty cycle for the bearing lives (docs/life.md); the time shares sum to 1 within "
                 "1e-6, at least one speed > 0"));
    a->Visit("rollers", &rollers,
             Field().Desc("the rollers' ratings without a catalogue: those of a reference roller, scaled with the "
                          "sized diameter and the roller length by ISO 281 (C ∝ D^(29/27) L^(7/9)) and ISO 76 (C0 ∝ "
                          "D L); docs/life.md"));
    a->Visit("eccentric_bearing", &eccentric_bearing,
             Field().Desc("the bearing carrying the cam on the input shaft's eccentric (docs/life.md)"));
    a->Visit("lubricant", &lubricant,
             Field().Desc("the oil: every design's lubricated losses at the target torque and load.input_speed_rpm "
                          "(docs/lubrication.md); limits.min_efficiency then bounds the lubricated efficiency, "
                          "limits.max_oil_temperature_C the housing's oil temperature"));
    a->Visit("surfaces", &surfaces,
             Field().Desc("roughness, friction by regime and the rollers' mounting (with lubricant)"));
    a->Visit("bearing_friction", &bearing_friction,
             Field().Desc("Palmgren's factors of the rollers' and the eccentric's bearings (with lubricant; a bearing "
                          "not given is not modelled)"));
    a->Visit("ratings", &ratings,
             Field().Desc("the rated torque the sized reducer must reach, as lcr_analysis's ratings define it: the "
                          "life rows at that torque and the rated speed (docs/ratings.md, Ratings as sizing limits); "
                          "needs the rollers' ratings, the line contact model without tolerances"));
  }
  /// How "roller_catalogue" is read: its list, given in the study or in its file.
  static Field CatalogueField() {
    return Field().MinItems(1, "a non-empty list of rollers").Expect("a list of rollers or {\"file\": \"…\"}").Desc(
        "rollers tried on each combination instead of a continuous d_r: a list of {name, diameter_mm, length_mm, "
        "load_limit_N, dynamic_rating_N, static_rating_N} (the roller load limit is the smaller of load_limit_N and "
        "limits.roller_load_N; C is required on every entry when a life is asked, C0 gives s0), or {\"file\": \"…\"} "
        "of such a list relative to the study file");
  }
  /// The rules between blocks: the catalogue against the roller length and diameter, the life's
  /// speed and ratings, robust with its tolerances.
  static nlohmann::ordered_json SchemaRules();
  /// The overload against the target, a reachable speed ratio, the duty cycle.
  static std::vector<CrossFieldRule> CrossFieldRules() {
    return {{{"load", "target"}, "load.overload_torque_Nm >= target.output_torque_Nm",
             ">= the target's output_torque_Nm"},
            {{"search", "target"}, "a lobe/roller combination within the search reaches the speed ratio",
             "no lobe/roller combination"},
            DutyCycleRule()};
  }
};

/// A [lower, upper] range of the study with lower <= upper ("[lower, upper] with lower <= upper" at `n`).
std::array<double, 2> OrderedRange(const std::array<double, 2>& range, const Node& n);

using CatalogueRoller = sizing::LcrCatalogueRoller;

/// The search (sizing/lcr_search.h: ratio, lobe and difference ranges, the shared problem `base`,
/// the catalogue, the solver options, the finite-length contact of studies/lcr_min_size_contact.h)
/// and what the study adds around it.
struct Study : sizing::LcrSearchSpec {
  std::string name;
  double output_torque_Nmm = 0;
  objectives::LcrConstraintForm form = objectives::LcrConstraintForm::kAggregate;  ///< as written
  /// "tolerances" + "robust" (+ "monte_carlo"): studies/lcr_min_size_robust.cc. Null: nominal only.
  std::shared_ptr<const objectives::LcrRobustRule> robust;
  int mc_samples = 200, mc_angle_steps = 720;
  std::uint64_t mc_seed = 1;
  /// "lubricant", "surfaces", "bearing_friction" as read (best_lcr_analysis.json takes them); none
  /// without lubricant.
  LubricationEcho<LcrBearingFrictionInput> lubrication_blocks;
  /// "ratings": the rated point the life rows hold (base.life's one line, base.limits.life_h).
  std::optional<SizingRatingsInput> ratings;
};

using Candidate = sizing::LcrCandidate;

/// result.json's blocks of the best design (Result::Json; at namespace scope so that their default
/// member initializers are complete where std::optional and std::variant test them).
/// A cam side of a candidate: its counts, and of a feasible candidate or a closest point its
/// sizes (with a 3D contact, of a feasible one the crowning sized for its rollers).
struct CandidateSide {
  int lobes = 0, rollers = 0;
  std::optional<double> turret_radius_mm, roller_diameter_mm, roller_length_mm, cam_thickness_mm;
  std::optional<LcrCrowningInput> crowning;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("lobes", &lobes, Field().Desc("the cam's lobes"));
    a->Visit("rollers", &rollers, Field().Desc("the rollers of its turret"));
    a->Visit("turret_radius_mm", &turret_radius_mm, Field().Unit("mm").Desc("turret radius r_d"));
    a->Visit("roller_diameter_mm", &roller_diameter_mm, Field().Unit("mm").Desc("roller diameter d_r"));
    a->Visit("roller_length_mm", &roller_length_mm, Field().Unit("mm").Desc("roller length"));
    a->Visit("cam_thickness_mm", &cam_thickness_mm, Field().Unit("mm").Desc("cam thickness"));
    a->Visit("crowning", &crowning,
             Field().Desc("3D contact: the crowning sized for the cam's rollers (type and its parameters)"));
  }
};

// The lives of a design (docs/life.md, "Life as a sizing limit"): `<bearing>_L10h` per bearing,
// shortest_L10h, and a table per element (load, C, L10h, s0, pass/fail against life_h).
struct SizingLife {
  std::optional<double> life_h;
  double shortest_L10h = 0;
  std::string shortest_bearing;
  double input_roller_L10h = 0, output_roller_L10h = 0;
  std::optional<double> eccentric_bearing_L10h;
  std::vector<DutyCycleEcho> duty_cycle;
  std::vector<LifeTableRow> table;
  std::string rating_rule, model;
  template <typename Archive>
  void Serialize(Archive* a) {
    const Field hours = Field().NullWhenNotFinite().Unit("h");
    a->Visit("life_h", &life_h, Field().NullWhenAbsent().Unit("h").Desc("the life limit (null: none)"));
    a->Visit("shortest_L10h", &shortest_L10h, Field(hours).Desc("the shortest L10h of any rated bearing"));
    a->Visit("shortest_bearing", &shortest_bearing, Field());
    a->Visit("input_roller_L10h", &input_roller_L10h, Field(hours).Desc("null: unlimited"));
    a->Visit("output_roller_L10h", &output_roller_L10h, Field(hours).Desc("null: unlimited"));
    a->Visit("eccentric_bearing_L10h", &eccentric_bearing_L10h, Field(hours).Desc("with its rating (null: unlimited)"));
    a->Visit("duty_cycle", &duty_cycle, Field());
    a->Visit("table", &table, Field().Desc("report.html's and datasheet.html's rows"));
    a->Visit("rating_rule", &rating_rule, Field().Desc("how the sized rollers' C and C0 follow their size"));
    a->Visit("model", &model, Field());
  }
};
/// The best design's cam side: its sizes (CandidateSide's members, with a 3D contact its
/// crowning), the dense check's extremes and the subsurface stresses under its peak.
struct BestSide {
  CandidateSide sizes;  ///< its members are the side's own
  double max_contact_stress_MPa = 0, max_roller_force_N = 0, undercut_margin_mm = 0, roller_gap_mm = 0;
  std::optional<SubsurfaceOut> subsurface;
  template <typename Archive>
  void Serialize(Archive* a) {
    sizes.Serialize(a);
    a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa,
             Field().NullWhenNotFinite().Unit("MPa").Desc("the cam's peak Hertz pressure in the dense check"));
    a->Visit("max_roller_force_N", &max_roller_force_N,
             Field().NullWhenNotFinite().Unit("N").Desc("the cam's largest roller force"));
    a->Visit("undercut_margin_mm", &undercut_margin_mm,
             Field().NullWhenNotFinite().Unit("mm").Desc("1/κ_max − r_r of the cam"));
    a->Visit("roller_gap_mm", &roller_gap_mm,
             Field().NullWhenNotFinite().Unit("mm").Desc("the gap between neighbouring rollers"));
    a->Visit("subsurface", &subsurface,
             Field().Desc(
                 "the subsurface stresses under the cam's peak pressure (as lcr_analysis gives them; null: an "
                 "undercut peak)"));
  }
};
/// With a 3D contact, a cam's 3D peak and edge check.
struct Contact3DSide {
  double max_contact_stress_MPa = 0;
  bool edge_loaded = false;
  double slice_width_mm = 0, interpolation_error_MPa = 0;
  std::optional<SubsurfaceOut> subsurface;
  std::optional<double> overload_edge_margin, edge_margin;
  std::optional<bool> overload_edge_loaded;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa,
             Field().NullWhenNotFinite().Unit("MPa").Desc("the slices model's peak pressure over the cycle"));
    a->Visit("edge_loaded", &edge_loaded, Field().Desc("the pressure reaches the roller's end"));
    a->Visit("slice_width_mm", &slice_width_mm, Field().NullWhenNotFinite().Unit("mm"));
    a->Visit("interpolation_error_MPa", &interpolation_error_MPa,
             Field().NullWhenNotFinite().Unit("MPa").Desc("of the peak read between slices"));
    a->Visit("subsurface", &subsurface,
             Field().Desc(
                 "the worst slice taken as a line contact of its peak pressure: its subsurface stresses"));
    a->Visit("overload_edge_margin", &overload_edge_margin,
             Field().NullWhenNotFinite().Desc("with load.overload_torque_Nm: the end margin at that torque"));
    a->Visit("overload_edge_loaded", &overload_edge_loaded, Field().Desc("with it: edge-loaded at that torque"));
    a->Visit("edge_margin", &edge_margin,
             Field().NullWhenNotFinite().Desc("without it: the end margin at the design torque"));
  }
};
struct Contact3DBest {
  double line_model_outer_diameter_mm = 0;
  std::optional<Contact3DSide> input, output;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("line_model_outer_diameter_mm", &line_model_outer_diameter_mm,
             Field().Unit("mm").Desc("the line model's optimum of the same combination"));
    a->Visit("input", &input, Field().Desc("the input cam (with the 3D cycle)"));
    a->Visit("output", &output, Field().Desc("the output cam"));
  }
};
/// With a half_space contact model: its check of the slices model's peaks.
struct HalfSpaceCheck {
  struct Side {
    double half_space_MPa = 0, slices_MPa = 0, slices_minus_half_space_percent = 0;
    bool edge_loaded = false;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("half_space_MPa", &half_space_MPa, Field().NullWhenNotFinite().Unit("MPa"));
      a->Visit("slices_MPa", &slices_MPa, Field().NullWhenNotFinite().Unit("MPa"));
      a->Visit("slices_minus_half_space_percent", &slices_minus_half_space_percent,
               Field().NullWhenNotFinite().Unit("%"));
      a->Visit("edge_loaded", &edge_loaded, Field());
    }
  };
  double cell_dx_mm = 0, cell_dy_mm = 0;
  bool converged = false;
  std::vector<int> grid;
  Side input, output;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("cell_dx_mm", &cell_dx_mm, Field().Unit("mm"));
    a->Visit("cell_dy_mm", &cell_dy_mm, Field().Unit("mm"));
    a->Visit("converged", &converged, Field());
    a->Visit("grid", &grid, Field().Desc("[nx, ny] cells"));
    a->Visit("input", &input, Field());
    a->Visit("output", &output, Field());
  }
};
/// The Monte-Carlo check of a design against the exact compliant model (robust sizing).
struct MonteCarloCheck {
  int samples = 0;
  std::uint64_t seed = 0;
  int angle_steps = 0, violating_samples = 0;
  double violating_fraction = 0, max_roller_force_N = 0, max_contact_stress_MPa = 0, min_undercut_margin_mm = 0;
  int worst_sample = 0;
  double worst_sample_relative_excess = 0;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("samples", &samples, Field());
    a->Visit("seed", &seed, Field());
    a->Visit("angle_steps", &angle_steps, Field());
    a->Visit("violating_samples", &violating_samples, Field().Desc("samples that break a limit"));
    a->Visit("violating_fraction", &violating_fraction, Field());
    a->Visit("max_roller_force_N", &max_roller_force_N, Field().Unit("N"));
    a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa, Field().NullWhenNotFinite().Unit("MPa"));
    a->Visit("min_undercut_margin_mm", &min_undercut_margin_mm, Field().Unit("mm"));
    a->Visit("worst_sample", &worst_sample, Field().Desc("the sample with the largest relative excess (−1: none)"));
    a->Visit("worst_sample_relative_excess", &worst_sample_relative_excess,
             Field().Desc("its largest (value − limit)/limit (<= 0: holds)"));
  }
};
/// The best design of a sizing without tolerances (and a robust study's nominal best).
struct NominalBest {
  double eccentricity_mm = 0, outer_diameter_mm = 0, speed_ratio = 0;
  double max_contact_stress_MPa = 0, max_roller_force_N = 0, undercut_margin_mm = 0, roller_gap_mm = 0,
         mean_efficiency = 0;
  std::string efficiency_model;
  std::optional<double> oil_temperature_C, power_loss_W;
  std::optional<std::string> lubrication_error;
  BestSide input, output;
  std::optional<std::string> catalogue_roller;
  std::vector<std::string> binding, binding_names;
  std::map<std::string, double> limit_sensitivity;
  std::optional<std::vector<std::string>> limit_costs;
  std::vector<BindingLimit> binding_limits;
  std::optional<std::string> limit_sensitivity_note;
  std::optional<SizingLife> life;
  std::optional<SizedRatingsBlock> ratings;
  std::optional<Contact3DBest> contact;
  std::optional<HalfSpaceCheck> half_space_check;
  std::optional<MonteCarloCheck> monte_carlo;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("eccentricity_mm", &eccentricity_mm, Field().Unit("mm").Desc("the eccentricity e"));
    a->Visit("outer_diameter_mm", &outer_diameter_mm, Field().Unit("mm").Desc("the outer diameter 2 max(r_d + r_r)"));
    a->Visit("speed_ratio", &speed_ratio, Field().Desc("the design's speed ratio"));
    a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa,
             Field().NullWhenNotFinite().Unit("MPa").Desc("the largest Hertz pressure of both cams in the dense check"));
    a->Visit("max_roller_force_N", &max_roller_force_N,
             Field().NullWhenNotFinite().Unit("N").Desc("the largest roller force"));
    a->Visit("undercut_margin_mm", &undercut_margin_mm,
             Field().NullWhenNotFinite().Unit("mm").Desc("the smaller cam's 1/κ_max − r_r"));
    a->Visit("roller_gap_mm", &roller_gap_mm,
             Field().NullWhenNotFinite().Unit("mm").Desc("the smallest gap between rollers"));
    a->Visit("mean_efficiency", &mean_efficiency,
             Field().NullWhenNotFinite().Desc("the mean efficiency over the revolution (null: not computed)"));
    a->Visit("efficiency_model", &efficiency_model,
             Field().Desc("eq. 33 with the friction coefficient, or lubricated"));
    a->Visit("oil_temperature_C", &oil_temperature_C,
             Field().NullWhenNotFinite().Unit("°C").Desc("with lubricant: the housing's oil temperature"));
    a->Visit("power_loss_W", &power_loss_W,
             Field().NullWhenNotFinite().Unit("W").Desc("with lubricant: the lubricated power loss"));
    a->Visit("lubrication_error", &lubrication_error,
             Field().Desc("with lubricant: why the lubricated losses were not computed"));
    a->Visit("input", &input, Field().Desc("the input cam"));
    a->Visit("output", &output, Field().Desc("the output cam"));
    a->Visit("catalogue_roller", &catalogue_roller, Field().Desc("with a catalogue: the roller's name"));
    a->Visit("binding", &binding, Field().Desc("the constraint rows active at the optimum"));
    a->Visit("binding_names", &binding_names, Field().Desc("the binding limits in words"));
    a->Visit("limit_sensitivity", &limit_sensitivity,
             Field().NullWhenNotFinite().Desc(
                 "d(objective)/d(limit) by limit key [mm, or W of loss, per unit of the limit]"));
    a->Visit("limit_costs", &limit_costs, Field().Desc("what each binding limit costs, in words"));
    a->Visit("binding_limits", &binding_limits, Field().Desc("each binding limit, its value and its cost"));
    a->Visit("limit_sensitivity_note", &limit_sensitivity_note,
             Field().Desc("3D contact: why the limit costs are not computed"));
    a->Visit("life", &life, Field().Desc("with a speed or duty cycle: the bearing lives (docs/life.md)"));
    a->Visit("ratings", &ratings, Field().Desc("with ratings: the sized design's ratings (docs/ratings.md)"));
    a->Visit("contact", &contact,
             Field().Desc("3D contact: the 3D peaks, edge margins and the line model's outer diameter"));
    a->Visit("half_space_check", &half_space_check,
             Field().Desc("3D contact on half_space: the half-space model's check of the slices model's peaks"));
    a->Visit("monte_carlo", &monte_carlo,
             Field().Desc("a robust study's nominal best: its Monte-Carlo check against the exact compliant model"));
  }
};
/// With robust: the smallest robust design, its nominal extremes, the linearised robust rows'
/// extremes and its Monte-Carlo check.
struct RobustBest {
  struct Nominal {
    double max_contact_stress_MPa = 0, max_roller_force_N = 0, undercut_margin_mm = 0, roller_gap_mm = 0,
           mean_efficiency = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa, Field().NullWhenNotFinite().Unit("MPa"));
      a->Visit("max_roller_force_N", &max_roller_force_N, Field().NullWhenNotFinite().Unit("N"));
      a->Visit("undercut_margin_mm", &undercut_margin_mm, Field().NullWhenNotFinite().Unit("mm"));
      a->Visit("roller_gap_mm", &roller_gap_mm, Field().NullWhenNotFinite().Unit("mm"));
      a->Visit("mean_efficiency", &mean_efficiency, Field().NullWhenNotFinite());
    }
  };
  struct Linear {
    double max_contact_stress_MPa = 0, min_stress_margin = 0, max_roller_force_N = 0, undercut_margin_mm = 0;
    int steps_per_period = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa, Field().NullWhenNotFinite().Unit("MPa"));
      a->Visit("min_stress_margin", &min_stress_margin, Field().NullWhenNotFinite());
      a->Visit("max_roller_force_N", &max_roller_force_N, Field().NullWhenNotFinite().Unit("N"));
      a->Visit("undercut_margin_mm", &undercut_margin_mm, Field().NullWhenNotFinite().Unit("mm"));
      a->Visit("steps_per_period", &steps_per_period, Field());
    }
  };
  double eccentricity_mm = 0, outer_diameter_mm = 0, speed_ratio = 0;
  CandidateSide input, output;
  Nominal nominal;
  Linear robust_linear;
  std::vector<std::string> binding;
  std::optional<MonteCarloCheck> monte_carlo;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("eccentricity_mm", &eccentricity_mm, Field().Unit("mm").Desc("the eccentricity e"));
    a->Visit("outer_diameter_mm", &outer_diameter_mm, Field().Unit("mm").Desc("the outer diameter 2 max(r_d + r_r)"));
    a->Visit("speed_ratio", &speed_ratio, Field().Desc("the design's speed ratio"));
    a->Visit("input", &input, Field().Desc("the input cam: counts, turret radius and roller diameter"));
    a->Visit("output", &output, Field().Desc("the output cam"));
    a->Visit("nominal", &nominal, Field().Desc("the nominal dense check's extremes"));
    a->Visit("robust_linear", &robust_linear, Field().Desc("the linearised robust constraints' extremes"));
    a->Visit("binding", &binding, Field().Desc("the robust constraint rows active at the optimum"));
    a->Visit("monte_carlo", &monte_carlo, Field().Desc("its Monte-Carlo check against the exact compliant model"));
  }
};

/// The search's outcome (sizing/lcr_search.h: the candidates, the best, the limit slopes, the
/// evaluations, the 3D half-space check) and what the study adds around it.
struct Result : sizing::LcrSearchOutcome {
  double seconds = 0;  ///< wall time of the search (summary only, never in result.json)
  /// When nothing fits: the limit that blocks most, the closest candidate, and the value of that
  /// limit that its closest point needs.
  std::string blocking_message;
  /// With Study::robust: the robust solve of every candidate (same order), the smallest converged
  /// one, and the Monte-Carlo checks of the robust and the nominal best designs.
  std::vector<sizing::LcrRobustOutcome> robust;
  int robust_best = -1;
  std::optional<objectives::LcrMonteCarloCheck> robust_mc, nominal_mc;
  /// With Study::robust: the accurate check of the robust best design (its nominal limits).
  std::optional<objectives::Verification> robust_verification;

  /// result.json, declared (studies/archive.h): Run fills it (FillResult; AddContact3DJson and
  /// RobustJson add their parts).
  struct Json {
    using CandidateSide = lcr_min_size::CandidateSide;
    using SizingLife = lcr_min_size::SizingLife;
    using BestSide = lcr_min_size::BestSide;
    using Contact3DSide = lcr_min_size::Contact3DSide;
    using Contact3DBest = lcr_min_size::Contact3DBest;
    using HalfSpaceCheck = lcr_min_size::HalfSpaceCheck;
    using MonteCarloCheck = lcr_min_size::MonteCarloCheck;
    using NominalBest = lcr_min_size::NominalBest;
    using RobustBest = lcr_min_size::RobustBest;
    struct Target {
      long speed_ratio = 0;
      double output_torque_Nm = 0;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("speed_ratio", &speed_ratio, Field().Desc("the study's target speed ratio r_i"));
        a->Visit("output_torque_Nm", &output_torque_Nm, Field().Unit("N·m").Desc("the study's output torque T_o"));
      }
    };
    struct Optimizer {
      std::string backend, constraints;
      bool polish = true;
      int samples_per_period = 0;
      double sharpness = 0;
      int starts = 0, value_evaluations = 0, gradient_evaluations = 0;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("backend", &backend, Field().OneOf({"ipopt", "slsqp", "mma", "cobyla"}).Desc("the NLP solver"));
        a->Visit("constraints", &constraints,
                 Field().OneOf({"aggregate", "samples"}).Desc("form of the smooth phase's cycle maxima"));
        a->Visit("polish", &polish, Field().Desc("every smooth optimum polished to the exact cycle maxima"));
        a->Visit("samples_per_period", &samples_per_period, Field().Desc("angle samples per load period"));
        a->Visit("sharpness", &sharpness, Field().Desc("log-sum-exp sharpness of the aggregates"));
        a->Visit("starts", &starts, Field().Desc("starting points per combination"));
        a->Visit("value_evaluations", &value_evaluations, Field().Desc("objective and constraint evaluations, all solves"));
        a->Visit("gradient_evaluations", &gradient_evaluations, Field().Desc("gradient evaluations, all solves"));
      }
    };
    /// One candidate (lobe/roller combination, and catalogue roller) as solved.
    struct CandidateRow {
      struct Evaluations {
        int values = 0, gradients = 0, iterations = 0, polish_rounds = 0;
        template <typename Archive>
        void Serialize(Archive* a) {
          a->Visit("values", &values, Field());
          a->Visit("gradients", &gradients, Field());
          a->Visit("iterations", &iterations, Field());
          a->Visit("polish_rounds", &polish_rounds, Field());
        }
      };
      struct Start {
        std::string status;
        std::optional<double> outer_diameter_mm, power_loss_W;
        template <typename Archive>
        void Serialize(Archive* a) {
          a->Visit("status", &status, Field());
          a->Visit("outer_diameter_mm", &outer_diameter_mm, Field().Unit("mm"));
          a->Visit("power_loss_W", &power_loss_W, Field().Unit("W").Desc("efficiency objective: the loss"));
        }
      };
      struct ClosestPoint {
        double eccentricity_mm = 0;
        CandidateSide input, output;
        template <typename Archive>
        void Serialize(Archive* a) {
          a->Visit("eccentricity_mm", &eccentricity_mm, Field().Unit("mm"));
          a->Visit("input", &input, Field());
          a->Visit("output", &output, Field());
        }
      };
      struct Violation {
        std::string limit;
        double value = 0, limit_value = 0, excess = 0;
        template <typename Archive>
        void Serialize(Archive* a) {
          a->Visit("limit", &limit, Field());
          a->Visit("value", &value, Field().NullWhenNotFinite());
          a->Visit("limit_value", &limit_value, Field().NullWhenNotFinite());
          a->Visit("excess", &excess, Field().NullWhenNotFinite());
        }
      };
      CandidateSide input, output;
      std::optional<std::string> catalogue_roller, note;
      std::string status, solver_message;
      bool feasible = false;
      std::optional<double> longest_life_h, outer_diameter_lower_bound_mm, line_model_outer_diameter_mm;
      Evaluations evaluations;
      std::vector<Start> starts;
      std::optional<double> multistart_spread_mm, multistart_spread_W;
      std::vector<std::string> binding, violated;
      std::optional<double> outer_diameter_mm, eccentricity_mm, max_contact_stress_MPa, max_roller_force_N,
          undercut_margin_mm, shortest_L10h, power_loss_W, mean_efficiency;
      std::optional<ClosestPoint> closest_point;
      std::optional<std::vector<Violation>> violations;
      std::optional<std::vector<std::string>> design_problems;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("input", &input, Field().Desc("the input cam: its lobes and rollers, and of a feasible candidate its sizes"));
        a->Visit("output", &output, Field().Desc("the output cam, as input"));
        a->Visit("catalogue_roller", &catalogue_roller, Field().Desc("with a catalogue: the roller's name"));
        a->Visit("status", &status,
                 Field().Desc("converged, pruned, life_out_of_reach, fails_dense_check, failed, or the solver's status"));
        a->Visit("feasible", &feasible, Field().Desc("converged and verified: a design that meets the limits"));
        a->Visit("solver_message", &solver_message, Field());
        a->Visit("note", &note, Field());
        a->Visit("longest_life_h", &longest_life_h,
                 Field().Unit("h").Desc("life_out_of_reach: the longest life the combination reaches"));
        a->Visit("evaluations", &evaluations, Field());
        a->Visit("outer_diameter_lower_bound_mm", &outer_diameter_lower_bound_mm,
                 Field().Unit("mm").Desc("pruned: the polish round's outer diameter that exceeded the best design's"));
        a->Visit("line_model_outer_diameter_mm", &line_model_outer_diameter_mm,
                 Field().Unit("mm").Desc("3D contact: the line model's optimum"));
        a->Visit("starts", &starts, Field().Desc("every start of the multistart"));
        a->Visit("multistart_spread_mm", &multistart_spread_mm,
                 Field().Unit("mm").Desc("the spread of the converged starts' outer diameters"));
        a->Visit("multistart_spread_W", &multistart_spread_W,
                 Field().Unit("W").Desc("efficiency objective: the spread of their losses"));
        a->Visit("binding", &binding, Field().Desc("the constraint rows active at the optimum"));
        a->Visit("violated", &violated, Field().Desc("the constraint rows violated"));
        a->Visit("outer_diameter_mm", &outer_diameter_mm, Field().Unit("mm").Desc("feasible: the outer diameter"));
        a->Visit("eccentricity_mm", &eccentricity_mm, Field().Unit("mm").Desc("feasible: the eccentricity"));
        a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa,
                 Field().NullWhenNotFinite().Unit("MPa").Desc("feasible: the peak Hertz pressure of both cams"));
        a->Visit("max_roller_force_N", &max_roller_force_N,
                 Field().NullWhenNotFinite().Unit("N").Desc("feasible: the largest roller force"));
        a->Visit("undercut_margin_mm", &undercut_margin_mm,
                 Field().NullWhenNotFinite().Unit("mm").Desc("feasible: the smaller cam's 1/κ_max − r_r"));
        a->Visit("shortest_L10h", &shortest_L10h,
                 Field().NullWhenNotFinite().Unit("h").Desc("feasible, with lives: the shortest L10h"));
        a->Visit("power_loss_W", &power_loss_W,
                 Field().NullWhenNotFinite().Unit("W").Desc("feasible, efficiency objective: the lubricated loss"));
        a->Visit("mean_efficiency", &mean_efficiency,
                 Field().NullWhenNotFinite().Desc("feasible, efficiency objective"));
        a->Visit("closest_point", &closest_point, Field().Desc("not feasible: where the search came closest"));
        a->Visit("violations", &violations, Field().Desc("not feasible: the limits broken at the closest point"));
        a->Visit("design_problems", &design_problems, Field().Desc("not feasible: the design's structural problems"));
      }
    };
    /// With a 3D contact: the contact model of the study, the sizing's, and the crowning sized.
    struct ContactBlock {
      struct LengthVariables {
        bool roller_length_mm = false, cam_thickness_mm = false;
        template <typename Archive>
        void Serialize(Archive* a) {
          a->Visit("roller_length_mm", &roller_length_mm, Field().Desc("the rollers' length is a variable"));
          a->Visit("cam_thickness_mm", &cam_thickness_mm, Field().Desc("the cams' thickness is a variable"));
        }
      };
      std::string model, sizing_model = "slices";
      int slices = 0;
      double misalignment_mrad = 0;
      LcrCrowningInput crowning;
      bool crowning_variable = false;
      LengthVariables length_variables;
      std::optional<double> overload_torque_Nm;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("model", &model, Field().Desc("the contact model of the study (slices or half_space)"));
        a->Visit("sizing_model", &sizing_model, Field().Const("slices").Desc("the model of the sizing's stress rows"));
        a->Visit("slices", &slices, Field().Desc("slices along the roller"));
        a->Visit("misalignment_mrad", &misalignment_mrad, Field().Unit("mrad").Desc("the roller's tilt"));
        a->Visit("crowning", &crowning, Field().Desc("fixed.crowning: its type and parameters"));
        a->Visit("crowning_variable", &crowning_variable, Field().Desc("a crowning parameter is a variable"));
        a->Visit("length_variables", &length_variables, Field().Desc("which lengths are variables"));
        a->Visit("overload_torque_Nm", &overload_torque_Nm,
                 Field().Unit("N·m").Desc("load.overload_torque_Nm: the edge check's torque"));
      }
    };
    /// With robust: the method, the tolerances and every candidate's robust solve.
    struct RobustBlock {
      struct CandidateSolve {
        int candidate = 0;
        bool converged = false;
        int rounds = 0;
        std::string status;
        std::optional<double> outer_diameter_mm;
        std::optional<std::string> note;
        template <typename Archive>
        void Serialize(Archive* a) {
          a->Visit("candidate", &candidate, Field().Desc("the index into candidates"));
          a->Visit("converged", &converged, Field());
          a->Visit("rounds", &rounds, Field().Desc("robust rounds (the linearisation moved with the design)"));
          a->Visit("status", &status, Field().Desc("converged, no nominal optimum, or the solver's status"));
          a->Visit("outer_diameter_mm", &outer_diameter_mm, Field().Unit("mm").Desc("the robust design's"));
          a->Visit("note", &note, Field());
        }
      };
      /// The bands the robust rows used (every one, 0 where the study gave none).
      struct Bands {
        double eccentricity_um = 0, turret_radius_um = 0, roller_diameter_um = 0, roller_pitch_arcsec = 0,
               profile_um = 0, bearing_clearance_um = 0;
        template <typename Archive>
        void Serialize(Archive* a) {
          a->Visit("eccentricity_um", &eccentricity_um, Field().Unit("µm"));
          a->Visit("turret_radius_um", &turret_radius_um, Field().Unit("µm"));
          a->Visit("roller_diameter_um", &roller_diameter_um, Field().Unit("µm"));
          a->Visit("roller_pitch_arcsec", &roller_pitch_arcsec, Field().Unit("arcsec"));
          a->Visit("profile_um", &profile_um, Field().Unit("µm"));
          a->Visit("bearing_clearance_um", &bearing_clearance_um, Field().Unit("µm"));
        }
      };
      std::string method;
      std::optional<double> k;
      Bands tolerances;
      std::string model;
      std::vector<CandidateSolve> candidates;
      std::optional<double> outer_diameter_increase_mm;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("method", &method, Field().OneOf({"worst_case", "sigma"}).Desc("robust.method"));
        a->Visit("k", &k, Field().Desc("sigma: k of mean + k sigma"));
        a->Visit("tolerances", &tolerances, Field().Desc("the ± bands of the study's tolerances (0: none given)"));
        a->Visit("model", &model, Field().Desc("the robust rows' model"));
        a->Visit("candidates", &candidates, Field().Desc("every candidate's robust solve, in the candidates' order"));
        a->Visit("outer_diameter_increase_mm", &outer_diameter_increase_mm,
                 Field().Unit("mm").Desc("the robust best's outer diameter over the nominal best's"));
      }
    };
    std::string study = "lcr_min_size", name;
    Target target;
    std::optional<std::string> objective;
    Optimizer optimizer;
    std::vector<CandidateRow> candidates;
    bool verified = false;
    VerificationBlock verification;
    std::variant<NominalBest, RobustBest, std::nullptr_t> best = nullptr;  ///< null when nothing fits
    std::optional<std::variant<NominalBest, std::nullptr_t>> nominal_best;
    std::optional<std::vector<std::string>> notes;
    std::optional<ContactBlock> contact;
    std::optional<RobustBlock> robust;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("study", &study, Field().Const("lcr_min_size").Desc("the study kind"));
      a->Visit("name", &name, Field().Desc("the study's name"));
      a->Visit("target", &target, Field().Desc("the speed ratio and output torque sized for"));
      a->Visit("objective", &objective,
               Field().Const("efficiency").Desc("what was minimised, with the efficiency objective only (absent: the "
                                                "outer diameter)"));
      a->Visit("optimizer", &optimizer, Field().Desc("the solver settings and the evaluations of all solves"));
      a->Visit("candidates", &candidates,
               Field().Desc("one per lobe/roller combination (and catalogue roller), in the order solved"));
      a->Visit("verified", &verified,
               Field().Desc("the accurate model holds the best design's limits (objectives/verification.h)"));
      a->Visit("verification", &verification,
               Field().Desc("the accurate model's check of the best design, or when nothing fits of the candidate "
                            "that failed it"));
      a->Visit("best", &best,
               Field().Desc("the best design (with robust: the smallest robust design), null when nothing fits"));
      a->Visit("nominal_best", &nominal_best,
               Field().Desc("with robust: the best design of the study without tolerances, with its Monte-Carlo "
                            "check (null: none)"));
      a->Visit("notes", &notes, Field().Desc("when nothing fits: the limit that blocks most and what would fit"));
      a->Visit("contact", &contact, Field().Desc("with a 3D contact: the contact model and the crowning sized"));
      a->Visit("robust", &robust,
               Field().Desc("with robust: the method, the tolerances and every candidate's robust solve"));
    }
  };
  Json json;
  template <typename Archive>
  void Serialize(Archive* a) {
    json.Serialize(a);
  }
};

/// @throws StudyError for bad input (exit 2).
Study Parse(const Node& root);
/// The robust parts (studies/lcr_min_size_robust.cc): "tolerances", "robust", "monte_carlo" into s;
/// the robust solves and checks into r; "best" (robust), "nominal_best" and "robust" into r.json.
void ParseRobust(const Input& in, const Node& root, Study& s);
void RunRobust(const Study& s, Result& r, const RunContext& ctx);
void RobustJson(const Study& s, Result& r);
/// Solves every combination and fills result.json's members (Result::json).
Result Run(const Study& study, const RunContext& ctx);
/// result.json, candidates.csv, outer_diameter.svg, best_lcr_analysis.json (when something fits);
/// marks the outputs incomplete (exit code 3) when nothing fits.
void Write(const Study& study, const Result& result, Outputs& out);
/// The start of the best combination's solve (the first smooth-phase start, LcrStartingPoints)
/// as an lcr_analysis study, made as best_lcr_analysis.json is: the combination (and catalogue
/// roller) read from `optimum`, the run's best_lcr_analysis.json. @throws nlohmann::json::exception
/// when `optimum` lacks its reducer's counts or roller.
nlohmann::json StartLcrAnalysisStudy(const Study& study, const nlohmann::json& optimum);
/// Lines for the terminal: what was minimised, the best outer diameter (and loss), time, and what
/// each binding limit costs ("stress limit +10 MPa → −0.13 mm", or in W of loss).
std::string Summary(const Study& study, const Result& result);

}  // namespace camopt::studies::lcr_min_size
