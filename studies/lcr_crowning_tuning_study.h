// Study kind "lcr_crowning_tuning": for a given lobe cam reducer, the logarithmic
// roller crowning per cam that minimises the largest contact pressure over a revolution at the
// design torque (worst over a misalignment range), with the pressure off the contact's ends at an
// overload torque; against uncrowned rollers, each checked with the half_space model.
// The problem is sizing/lcr_crowning_tuning.h; the contact models model/lcr/contact3d*.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/common/sliced_bearing_life.h"
#include "model/lcr/life.h"
#include "sizing/lcr_crowning_tuning.h"
#include "objectives/verification.h"
#include "studies/archive.h"
#include "studies/bearing_life_io.h"
#include "studies/input.h"
#include "studies/lcr_input.h"
#include "studies/material_input.h"
#include "studies/study.h"
#include "studies/verification_json.h"

namespace camopt::studies::lcr_crowning_tuning {

/// The study file as declared: each field once, in the file's units, with its default, bounds and
/// description (studies/archive.h); the reducer (sides with their bearing ratings, no crowning: it is
/// the answer), the material and the duty cycle are the LCR blocks of studies/lcr_input.h and
/// material_input.h. Parse reads it and checks what spans fields; `camopt schema lcr_crowning_tuning`
/// is emitted from it.
struct Input {
  struct Load {
    double output_torque_Nm = 0, overload_torque_Nm = 0, friction_coefficient = 0;
    std::optional<double> input_speed_rpm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("output_torque_Nm", &output_torque_Nm,
               Field().Required().AtLeast(kMinLcrTorqueNm, kMinLcrTorqueExpected).Unit("N·m")
                   .Desc("T_o, the design torque: the pressure it minimises"));
      a->Visit("overload_torque_Nm", &overload_torque_Nm,
               Field().Required().AtLeast(kMinLcrTorqueNm, kMinLcrTorqueExpected).Unit("N·m").Desc(
                   "the overload torque, >= output_torque_Nm: the pressure must stay off the contact's ends at it"));
      a->Visit("friction_coefficient", &friction_coefficient,
               Field().In(0.0, 1.0).Desc("μ of the eccentric, T_in = (F_t + μ F_r) e (the paper's eq. 32)"));
      a->Visit("input_speed_rpm", &input_speed_rpm,
               Field().Positive().Unit("rpm").Desc(
                   "input speed: the bearing lives at the load's torque (a one-line duty cycle; docs/life.md); not "
                   "with duty_cycle"));
    }
  };
  struct Tuning {
    double effective_length_mm = 0;
    std::array<double, 2> coefficient_range_mm{1e-3, 0.05};
    std::vector<double> misalignment_mrad{0.0};
    int curve_points = 12, refine_iterations = 8, angle_steps = 360, slices = 40;
    bool half_space_check = true;
    std::array<int, 2> grid{48, 256};  ///< [nx, ny] of the half_space check
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("effective_length_mm", &effective_length_mm,
               Field().Required().Positive().Unit("mm").Desc(
                   "L_e of Lundberg's logarithmic profile, both cams; above each cam's roller length (L_e <= l_r "
                   "gives an unbounded drop at the roller's ends)"));
      a->Visit("coefficient_range_mm", &coefficient_range_mm,
               Field().Positive("[lo, hi] with 0 < lo < hi").Expect("[lower, upper], two numbers").NamesTheArray().Unit("mm")
                   .Desc("[lo, hi] of the crowning coefficient f scanned, 0 < lo < hi"));
      a->Visit("misalignment_mrad", &misalignment_mrad,
               Field().In(-50.0, 50.0).MinItems(1, "a non-empty list of misalignments [mrad]").Unit("mrad")
                   .Desc("the tilts γ of the roller axis: the worst pressure over them is minimised, off the ends at "
                         "every one"));
      a->Visit("curve_points", &curve_points,
               Field().AtLeast(3).AtMost(60, "at most 60 points").Desc("coefficients of the scan (log-spaced)"));
      a->Visit("refine_iterations", &refine_iterations,
               Field().AtLeast(0).AtMost(40, "at most 40 iterations").Desc("golden-section steps in ln f after the scan"));
      a->Visit("angle_steps", &angle_steps,
               Field().AtLeast(12).AtMost(3600, "at most 3600 angle steps").Desc("samples of the input revolution"));
      a->Visit("slices", &slices,
               Field().AtLeast(4).AtMost(200, "at most 200 slices").Desc("slices along the roller (the slices model)"));
      a->Visit("half_space_check", &half_space_check,
               Field().Desc("check the tuned and the uncrowned rollers with the half_space model (false: not verified)"));
      a->Visit("grid", &grid, GridField());
    }
  };

  std::string study = "lcr_crowning_tuning", name;
  std::optional<std::string> description;
  LcrReducerWithRatingsInput<LcrSideWithRatingsInput> reducer;
  MaterialInput material;
  Load load;
  Tuning tuning;
  LcrDutyCycleInput duty_cycle;

  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Required().Const("lcr_crowning_tuning").Desc("the study kind"));
    a->Visit("name", &name, Field().Desc("the design's name, in titles"));
    a->Visit("description", &description, Field().Desc("free text"));
    a->Visit("reducer", &reducer,
             Field().Required().Desc("the lobe cam reducer's design (no crowning: it is the answer)"));
    a->Visit("material", &material, Field().Required().Desc("the cams' and rollers' elastic material"));
    a->Visit("load", &load, Field().Required().Desc("the design and overload torques"));
    a->Visit("tuning", &tuning, Field().Required().Desc("the crowning's scan, the models' resolution and the check"));
    a->Visit("duty_cycle", &duty_cycle,
             Field().MinItems(1, kDutyCycleNotEmpty).Desc(
                 "lines of the duty cycle for the bearing lives (docs/life.md); the time shares sum to 1 within "
                 "1e-6, at least one speed > 0"));
  }
  /// The life's ratings and one form of the speed.
  static nlohmann::ordered_json SchemaRules() { return {{"allOf", LcrLifeSchemaRules()}}; }
  static std::vector<CrossFieldRule> CrossFieldRules() {
    return {{{"material", "load", "reducer"},
             "the torque within what the output rollers carry at the material's Young's modulus (a soft material "
             "carries less)",
             "a torque the output rollers can carry"},
            {{"load"}, "overload_torque_Nm >= output_torque_Nm", "an overload torque >= output_torque_Nm"},
            {{"tuning"}, "the range of f: 0 < lo < hi", "0 < lo < hi"}};
  }
};

/// The lives of the tuned design, asked by "load.input_speed_rpm" or "duty_cycle" (docs/life.md,
/// "Sliced roller life under tilt"): the rollers' ratings, the eccentric bearing's when given.
struct LifeSpec {
  std::vector<lcr::LcrDutyLine> lines;
  std::array<double, 2> dynamic_rating_N{0, 0}, static_rating_N{0, 0};  ///< [0] input, [1] output rollers
  std::optional<EccentricBearingRating> eccentric;
};

/// The study as Run takes it: the file as declared (`in`) and, checked, the tuning problem in model
/// units and the lives' inputs.
struct Study {
  Input in;
  sizing::LcrCrowningTuningSpec spec;
  std::optional<LifeSpec> life;
};

/// The tuned design's lives: ISO 281 per bearing, and each roller sliced at every misalignment.
struct LifeResult {
  std::array<lcr::LcrBearingLife, 2> rollers;
  std::optional<lcr::LcrBearingLife> eccentric;
  std::vector<std::array<SlicedLife, 2>> sliced;  ///< per misalignment of the tuning
};

struct SideCheck {
  sizing::LcrCrowningCheck slices, half_space;
  std::vector<double> half_space_dy_mm;  // per misalignment (design torque)
};

/// The run's answer: result.json as declared (`camopt schema lcr_crowning_tuning --result`), then
/// the model's numbers the CSV and SVG files are drawn from.
struct Result {
  /// The peak pressures at one misalignment.
  struct CheckRow {
    double misalignment_mrad = 0, design_max_contact_stress_MPa = 0, overload_max_contact_stress_MPa = 0;
    bool design_edge_loaded = false, overload_edge_loaded = false;
    std::optional<double> cell_dy_mm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("misalignment_mrad", &misalignment_mrad, Field().Unit("mrad"));
      a->Visit("design_max_contact_stress_MPa", &design_max_contact_stress_MPa, Field().Unit("MPa"));
      a->Visit("design_edge_loaded", &design_edge_loaded, Field().Desc("the peak at the design torque is at a roller end"));
      a->Visit("overload_max_contact_stress_MPa", &overload_max_contact_stress_MPa, Field().Unit("MPa"));
      a->Visit("overload_edge_loaded", &overload_edge_loaded, Field().Desc("the same at the overload torque"));
      a->Visit("cell_dy_mm", &cell_dy_mm, Field().Unit("mm").Desc("half_space: the cells' size along the roller"));
    }
  };
  /// A crowning checked by both contact models.
  struct Checked {
    std::vector<CheckRow> slices;
    std::optional<std::vector<CheckRow>> half_space;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("slices", &slices, Field().Desc("the slices model, per misalignment"));
      a->Visit("half_space", &half_space, Field().Desc("the half_space model, per misalignment (with its check)"));
    }
  };
  struct Crowning {
    std::string type = "logarithmic";
    double coefficient_mm = 0, effective_length_mm = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("type", &type, Field().Const("logarithmic"));
      a->Visit("coefficient_mm", &coefficient_mm, Field().Unit("mm").Desc("the tuned LCM coefficient f"));
      a->Visit("effective_length_mm", &effective_length_mm, Field().Unit("mm"));
    }
  };
  /// One cam's tuning.
  struct Side {
    Crowning crowning;
    bool feasible = false;
    int evaluations = 0;
    Checked tuned, uncrowned;
    std::optional<std::array<int, 2>> half_space_grid;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("crowning", &crowning, Field().Desc("the tuned crowning"));
      a->Visit("feasible", &feasible, Field().Desc("some coefficient keeps the pressure off the ends at overload"));
      a->Visit("evaluations", &evaluations, Field().Desc("contact cycles solved by the tuning"));
      a->Visit("tuned", &tuned, Field().Desc("the tuned crowning's peaks"));
      a->Visit("uncrowned", &uncrowned, Field().Desc("straight rollers' peaks, for comparison"));
      a->Visit("half_space_grid", &half_space_grid, Field().Desc("the half_space check's cells [nx, ny]"));
    }
  };
  struct SlicedRow {
    double misalignment_mrad = 0, input_roller_sliced_L10h = 0, output_roller_sliced_L10h = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("misalignment_mrad", &misalignment_mrad, Field().Unit("mrad"));
      a->Visit("input_roller_sliced_L10h", &input_roller_sliced_L10h, Field().NullWhenNotFinite().Unit("h"));
      a->Visit("output_roller_sliced_L10h", &output_roller_sliced_L10h, Field().NullWhenNotFinite().Unit("h"));
    }
  };
  /// The tuned design's bearing lives (with a speed or a duty cycle).
  struct Life {
    double input_roller_L10h = 0, output_roller_L10h = 0;
    std::optional<double> eccentric_bearing_L10h;
    double shortest_L10h = 0;
    std::string shortest_bearing;
    std::vector<SlicedRow> sliced;
    std::vector<DutyCycleEcho> duty_cycle;
    std::optional<double> life_h;  ///< always null: the tuning has no life limit
    std::vector<LifeTableRow> table;  ///< pass always null: no life limit in a tuning
    std::string model;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("input_roller_L10h", &input_roller_L10h, Field().NullWhenNotFinite().Unit("h"));
      a->Visit("output_roller_L10h", &output_roller_L10h, Field().NullWhenNotFinite().Unit("h"));
      a->Visit("eccentric_bearing_L10h", &eccentric_bearing_L10h, Field().NullWhenNotFinite().Unit("h"));
      a->Visit("shortest_L10h", &shortest_L10h, Field().NullWhenNotFinite().Unit("h").Desc("sliced lives not included"));
      a->Visit("shortest_bearing", &shortest_bearing, Field());
      a->Visit("sliced", &sliced, Field().Desc("each roller sliced with its tuned crowning, per misalignment"));
      a->Visit("duty_cycle", &duty_cycle, Field());
      a->Visit("life_h", &life_h, Field().NullWhenAbsent().Unit("h").Desc("the life limit: none in a tuning"));
      a->Visit("table", &table, Field().Desc("report.html's rows"));
      a->Visit("model", &model, Field());
    }
  };

  std::string study = "lcr_crowning_tuning", name;
  double design_torque_Nm = 0, overload_torque_Nm = 0;
  int slices = 0, angle_steps = 0;
  Side input, output;
  bool verified = false;
  VerificationBlock verification_block;  ///< result.json's "verification"
  std::optional<double> max_edge_pressure_share, max_edge_pressure_share_error, edge_pressure_share_limit;
  std::optional<std::string> max_edge_pressure_share_where;
  std::optional<Life> life_block;  ///< result.json's "life"
  std::vector<std::string> notes;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Const("lcr_crowning_tuning"));
    a->Visit("name", &name, Field().Desc("the design's name"));
    a->Visit("design_torque_Nm", &design_torque_Nm, Field().Unit("N·m"));
    a->Visit("overload_torque_Nm", &overload_torque_Nm, Field().Unit("N·m"));
    a->Visit("slices", &slices, Field().Desc("slices along each roller"));
    a->Visit("angle_steps", &angle_steps, Field().Desc("input angles of the contact cycles"));
    a->Visit("input", &input, Field().Desc("the input cam's tuning"));
    a->Visit("output", &output, Field().Desc("the output cam's tuning"));
    a->Visit("verified", &verified, Field().Desc("the accurate model confirms the tuning (a view of `status`)"));
    a->Visit("verification", &verification_block, Field().Desc("the accurate model's checks"));
    a->Visit("max_edge_pressure_share", &max_edge_pressure_share,
             Field().Desc("the largest roller-end share of the peak pressure the accurate model finds (with its check)"));
    a->Visit("max_edge_pressure_share_error", &max_edge_pressure_share_error, Field().Desc("its estimated error"));
    a->Visit("max_edge_pressure_share_where", &max_edge_pressure_share_where, Field());
    a->Visit("edge_pressure_share_limit", &edge_pressure_share_limit, Field());
    a->Visit("life", &life_block, Field().Desc("the tuned design's bearing lives, with a speed or a duty cycle"));
    a->Visit("notes", &notes, Field());
  }

  // Not in result.json: the model's numbers.
  std::array<sizing::LcrCrowningSideResult, 2> tuned;
  std::array<SideCheck, 2> tuned_check, uncrowned_check;  // half_space part empty when not asked
  /// The tuned crowning checked by the accurate model (objectives/verification.h): not run when
  /// the half_space check is off.
  objectives::Verification verification;
  std::optional<LifeResult> life;  ///< with a speed or a duty cycle
};

/// @throws StudyError for bad input (exit 2).
Study Parse(const Node& root);
Result Run(const Study& study, const RunContext& ctx);
/// result.json, stress_vs_coefficient.csv/.svg.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::lcr_crowning_tuning
