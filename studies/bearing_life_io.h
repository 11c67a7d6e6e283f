// A reducer's duty cycle and bearing ratings in, the life table out (docs/life.md): shared by every
// study kind that computes a rating life (lcr_analysis, lcr_min_size, cycloid_ltca).
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "model/common/bearing_life.h"
#include "studies/archive.h"
#include "studies/input.h"

#include <nlohmann/json.hpp>

namespace camopt::studies {

/// One line of a duty cycle as the study file gives it ("duty_cycle": [{…}, …]), in its units.
struct DutyCycleLine {
  double output_torque_Nm = 0, input_speed_rpm = 0, time_share = 0;
};

/// A line's declaration (studies/archive.h); `Words` names the kind's torque and speed for the
/// schema's descriptions (LcrDutyWords, cycloid_common::DutyWords).
template <typename Words>
struct DutyCycleLineInput : DutyCycleLine {
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("output_torque_Nm", &output_torque_Nm, Field().Required().NonNegative().Unit("N·m").Desc(Words::kTorque));
    a->Visit("input_speed_rpm", &input_speed_rpm, Field().Required().NonNegative().Unit("rpm").Desc(Words::kSpeed));
    a->Visit("time_share", &time_share,
             Field().Required().Positive().AtMost(1.0, "a share in (0, 1]").Desc(
                 "the share of the time in this line (the shares sum to 1 within 1e-6)"));
  }
};
/// A kind's "duty_cycle" member: absent, or one line at least (Field::MinItems with this message).
template <typename Words>
using DutyCycleInput = std::optional<std::vector<DutyCycleLineInput<Words>>>;
inline constexpr const char* kDutyCycleNotEmpty = "a non-empty array of duty-cycle lines";

/// The duty cycle of a bearing life (docs/life.md): "load.input_speed_rpm" (> 0, one line at
/// output_torque_Nmm, the study's own torque) or the declared "duty_cycle" `lines` (each line's
/// fields checked as read) with shares summing to 1 within 1e-6 (then divided by their sum) and at
/// least one speed > 0; not both. nullopt when neither is given. `why` (when given) receives the
/// reason a rating is required ("a life is asked: … is given").
/// @throws StudyError naming the JSON path, what was expected and what was found.
std::optional<std::vector<OperatingLine>> ParseDutyCycle(const Node& root, const std::vector<DutyCycleLine>* lines,
                                                         double output_torque_Nmm, std::string* why = nullptr);
template <typename Words>
std::optional<std::vector<OperatingLine>> ParseDutyCycle(const Node& root, const DutyCycleInput<Words>& duty,
                                                         double output_torque_Nmm, std::string* why = nullptr) {
  std::vector<DutyCycleLine> lines;
  if (duty) lines.assign(duty->begin(), duty->end());
  return ParseDutyCycle(root, duty ? &lines : nullptr, output_torque_Nmm, why);
}

/// A bearing's own inputs of the modified rating life (ISO 281:2007 §9.3; docs/life.md, "Modified
/// rating life a_ISO"): its fatigue load limit C_u [N] and pitch diameter D_pw [mm], both > 0.
struct ModifiedLifeRating {
  double fatigue_load_limit_N = 0.0, pitch_diameter_mm = 0.0;
};

/// A rolling bearing's ratings: C [N] (> 0), C0 [N] (0 when not given), ball or roller, and C_u
/// and D_pw of the modified life when given.
struct RollingBearingRating {
  BearingKind kind = BearingKind::kRoller;
  std::string designation;  ///< the catalogue's designation, for the bill of materials (may be empty)
  double dynamic_N = 0.0, static_N = 0.0;
  std::optional<ModifiedLifeRating> modified;
};

/// The descriptions of a rating block's modified-life fields (one text for every kind's schema).
inline constexpr const char* kFatigueLoadLimitDesc =
    "the bearing's fatigue load limit C_u (ISO 281:2007; the catalogue's P_u), for the modified life a_ISO with "
    "pitch_diameter_mm and lubricant.contamination_factor (docs/life.md)";
inline constexpr const char* kPitchDiameterDesc =
    "the bearing's pitch diameter D_pw ≈ (d + D)/2, for the reference viscosity ν1 of the modified life a_ISO "
    "(ISO 281:2007 eq. 28; docs/life.md)";

/// A bearing's inputs of the modified life a_ISO (ISO 281:2007 §9.3; docs/life.md): C_u and D_pw,
/// both or neither (ParseModifiedLifeRating checks the pair, with its message), visited after the
/// ratings.
/// The rule of a kind's "duty_cycle" (ParseDutyCycle): the lines' time shares sum to 1.
inline CrossFieldRule DutyCycleRule() {
  return {{"duty_cycle"}, "the lines' time shares sum to 1 (within 1e-6; docs/life.md)", "time shares summing to 1"};
}

struct ModifiedLifeRatingInput {
  std::optional<double> fatigue_load_limit_N, pitch_diameter_mm;
  template <typename Archive>
  void VisitModifiedLife(Archive* a) {
    a->Visit("fatigue_load_limit_N", &fatigue_load_limit_N, Field().Positive().Unit("N").Desc(kFatigueLoadLimitDesc));
    a->Visit("pitch_diameter_mm", &pitch_diameter_mm, Field().Positive().Unit("mm").Desc(kPitchDiameterDesc));
  }
  /// JSON Schema: the two fields come together.
  static nlohmann::ordered_json SchemaRules() {
    return {{"dependentRequired",
             {{"fatigue_load_limit_N", {"pitch_diameter_mm"}}, {"pitch_diameter_mm", {"fatigue_load_limit_N"}}}}};
  }
};

/// Reads "dynamic_rating_N" > 0 and "static_rating_N" > 0 (optional) from `node`, which may hold
/// other fields (an LCR's reducer side); a missing C is an error that says why it is needed. Reads
/// "fatigue_load_limit_N" and "pitch_diameter_mm" (> 0, both or neither) when `node` has them.
/// @throws StudyError naming the JSON path.
RollingBearingRating ParseRatingValues(const Node& node, BearingKind kind, const std::string& why);

/// Reads "fatigue_load_limit_N" and "pitch_diameter_mm" (> 0, both or neither) of a rating block;
/// nullopt when neither is given. @throws StudyError naming the missing one's JSON path.
std::optional<ModifiedLifeRating> ParseModifiedLifeRating(const Node& node);

/// Fails at `node`/dynamic_rating_N, which is missing: "expected the bearing's dynamic load rating
/// C [N] > 0 (`why`), found nothing".
[[noreturn]] void FailMissingRating(const Node& node, const std::string& why);

/// A rating block of a rolling bearing as the study file gives it ("pins" of the cycloid kinds):
/// C, C0, the catalogue's designation and, with kModifiedLife (the kinds that report a_ISO), C_u
/// and D_pw. C is required (RatingOf says why it is needed).
template <bool kModifiedLife>
struct BearingRatingInput : ModifiedLifeRatingInput {
  std::optional<double> dynamic_rating_N, static_rating_N;
  std::optional<std::string> designation;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("dynamic_rating_N", &dynamic_rating_N,
             Field().Positive().Unit("N").Desc("C, the basic dynamic load rating (ISO 281)"));
    a->Visit("static_rating_N", &static_rating_N,
             Field().Positive().Unit("N").Desc("C₀, the basic static load rating, for the static safety s₀ = C₀ / P₀ "
                                               "(absent: none)"));
    a->Visit("designation", &designation, Field().Desc("the catalogue's designation, in bom.csv (docs/parts.md)"));
    if constexpr (kModifiedLife) VisitModifiedLife(a);
  }
  /// JSON Schema: C is required; C_u and D_pw come together.
  static nlohmann::ordered_json SchemaRules() {
    nlohmann::ordered_json r = {{"required", {"dynamic_rating_N"}}};
    if constexpr (kModifiedLife) r.update(ModifiedLifeRatingInput::SchemaRules());
    return r;
  }
};

/// A rating block with the bearing's kind ("crank_bearing" of the cycloid kinds).
template <bool kModifiedLife>
struct KindedBearingRatingInput : BearingRatingInput<kModifiedLife> {
  std::string kind;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("kind", &kind,
             Field().Required().OneOf({"ball", "roller"}, "one of ball, roller")
                 .Desc("ball or roller bearing (the life exponent p = 3 or 10/3)"));
    BearingRatingInput<kModifiedLife>::Serialize(a);
  }
  static nlohmann::ordered_json SchemaRules() {
    nlohmann::ordered_json r = BearingRatingInput<kModifiedLife>::SchemaRules();
    r["required"] = {"kind", "dynamic_rating_N"};
    return r;
  }
};

/// The ratings a typed block at `node` gives, its kind `kind` (a block with a kind: its own): C is
/// required (missing: an error that says why, `why`), C_u and D_pw both or neither.
/// @throws StudyError naming the JSON path.
template <bool kModifiedLife>
RollingBearingRating RatingOf(const BearingRatingInput<kModifiedLife>& in, const Node& node, BearingKind kind,
                              const std::string& why) {
  RollingBearingRating r;
  r.kind = kind;
  if (!in.dynamic_rating_N) FailMissingRating(node, why);
  r.dynamic_N = *in.dynamic_rating_N;
  r.static_N = in.static_rating_N.value_or(0.0);
  if constexpr (kModifiedLife) r.modified = ParseModifiedLifeRating(node);
  r.designation = in.designation.value_or("");
  return r;
}
template <bool kModifiedLife>
RollingBearingRating RatingOf(const KindedBearingRatingInput<kModifiedLife>& in, const Node& node,
                              const std::string& why) {
  return RatingOf(static_cast<const BearingRatingInput<kModifiedLife>&>(in), node,
                  in.kind == "ball" ? BearingKind::kBall : BearingKind::kRoller, why);
}

/// The modified life's inputs across blocks: a rating block with fatigue_load_limit_N and
/// pitch_diameter_mm (`rated`: those blocks) needs "lubricant" (the oil's viscosity at its
/// temperature) with "contamination_factor"; a "lubricant.contamination_factor" needs such a block.
/// @throws StudyError naming the JSON path and what is missing.
void CheckModifiedLifeInputs(const Node& root, const std::vector<Node>& rated);

/// The JSON Schema rules of CheckModifiedLifeInputs (two entries for the root's "allOf"): a rating
/// block at one of `rated_blocks` (paths of keys from the root, {"reducer", "input"}, …) with
/// fatigue_load_limit_N needs lubricant.contamination_factor, which needs such a block.
nlohmann::ordered_json ModifiedLifeSchemaRules(const std::vector<std::vector<std::string>>& rated_blocks);

/// The oil at the bearings for the modified life: its viscosity ν [mm²/s] at the operating point's
/// temperature, or why there is none (the lubricated result's error).
struct ModifiedLifeOil {
  double contamination_factor = 0.0;
  double temperature_C = NAN, viscosity_mm2_s = NAN;
  std::string missing;  ///< non-empty: no oil temperature, a_ISO not computed
};

/// One row of a life table (docs/life.md; result.json's `life.table` of every kind with lives,
/// report.html's and datasheet.html's life rows): a rated bearing, a roller rated by slices, or a
/// cam contact, with its modified life when asked. Every number that is not finite is null (an
/// unloaded bearing's life, a modified life not computed).
struct LifeTableRow {
  std::string element, kind;
  std::optional<double> equivalent_load_N, max_load_N, revolutions_per_input_revolution, dynamic_rating_N;
  double L10h = 0;
  std::optional<bool> pass;
  std::optional<double> static_rating_N, s0;
  std::optional<std::vector<double>> line_equivalent_load_N;
  std::optional<double> mean_speed_rpm, L10_Mrev;
  // The modified life (AddModifiedLife).
  std::optional<double> pitch_diameter_mm, fatigue_load_limit_N, contamination_factor, oil_temperature_C,
      viscosity_mm2_s, reference_viscosity_mm2_s, kappa, a_ISO, L_nm_h;
  std::optional<std::string> a_ISO_note;
  // A cam contact's surface life (lcr_analysis with material.contact_fatigue).
  std::optional<double> equivalent_pressure_MPa, max_pressure_MPa, contacts_per_input_revolution,
      reference_pressure_MPa;
  template <typename Archive>
  void Serialize(Archive* a) {
    const Field number = Field().NullWhenNotFinite();
    a->Visit("element", &element, Field().Desc("the bearing or contact (with _sliced: its roller rated by slices)"));
    a->Visit("kind", &kind, Field().Desc("ball, roller, roller sliced (ISO/TS 16281) or cam contact"));
    a->Visit("equivalent_load_N", &equivalent_load_N, Field(number).Unit("N").Desc("P over the duty cycle"));
    a->Visit("max_load_N", &max_load_N, Field(number).Unit("N").Desc("the largest load of any line"));
    a->Visit("revolutions_per_input_revolution", &revolutions_per_input_revolution, Field(number));
    a->Visit("dynamic_rating_N", &dynamic_rating_N, Field(number).Unit("N").Desc("C"));
    a->Visit("L10h", &L10h, Field(number).Unit("h").Desc("null: unlimited"));
    a->Visit("pass", &pass, Field().NullWhenAbsent().Desc("L10h against limits.life_h (null: no life limit)"));
    a->Visit("static_rating_N", &static_rating_N, Field(number).Unit("N").Desc("C0, when given"));
    a->Visit("s0", &s0, Field(number).Desc("static safety C0 / largest load, with a static rating (null: no load)"));
    a->Visit("line_equivalent_load_N", &line_equivalent_load_N, Field(number).Unit("N").Desc("P_i of each line"));
    a->Visit("mean_speed_rpm", &mean_speed_rpm, Field(number).Unit("rpm").Desc("the bearing's"));
    a->Visit("L10_Mrev", &L10_Mrev, Field(number).Unit("Mrev"));
    a->Visit("pitch_diameter_mm", &pitch_diameter_mm, Field(number).Unit("mm").Desc("D_pw (modified life)"));
    a->Visit("fatigue_load_limit_N", &fatigue_load_limit_N, Field(number).Unit("N").Desc("C_u (modified life)"));
    a->Visit("contamination_factor", &contamination_factor, Field(number).Desc("e_C (modified life)"));
    a->Visit("oil_temperature_C", &oil_temperature_C, Field(number).Unit("°C").Desc("null: none"));
    a->Visit("viscosity_mm2_s", &viscosity_mm2_s, Field(number).Unit("mm²/s").Desc("ν at the oil temperature"));
    a->Visit("reference_viscosity_mm2_s", &reference_viscosity_mm2_s,
             Field(number).Unit("mm²/s").Desc("ν1 at the mean speed (null: not computed)"));
    a->Visit("kappa", &kappa, Field(number).Desc("ν/ν1 (null: not computed)"));
    a->Visit("a_ISO", &a_ISO, Field(number).Desc("the life modification factor (null: not computed)"));
    a->Visit("L_nm_h", &L_nm_h, Field(number).Unit("h").Desc("the modified life a1 a_ISO L10h (null: not computed)"));
    a->Visit("a_ISO_note", &a_ISO_note, Field().Desc("why a_ISO is not computed or capped"));
    a->Visit("equivalent_pressure_MPa", &equivalent_pressure_MPa, Field(number).Unit("MPa").Desc("a cam contact's"));
    a->Visit("max_pressure_MPa", &max_pressure_MPa, Field(number).Unit("MPa").Desc("a cam contact's peak"));
    a->Visit("contacts_per_input_revolution", &contacts_per_input_revolution, Field(number));
    a->Visit("reference_pressure_MPa", &reference_pressure_MPa, Field(number).Unit("MPa"));
  }
};

/// A bearing's row: element, kind, equivalent_load_N, max_load_N, revolutions_per_input_revolution,
/// dynamic_rating_N, L10h, static_rating_N and s0 = C0/P0max when C0 is given, pass against
/// `life_h` (null when no limit, life_h <= 0).
LifeTableRow BearingLifeRow(const std::string& element, bool ball, double equivalent_load_N, double max_load_N,
                            double revolutions_per_input_revolution, double dynamic_rating_N, double static_rating_N,
                            double s0, double L10h, double life_h);

/// Adds the modified life L_nm = a1 a_ISO L10 (ISO 281:2007 §9.3, a1 = 1;
/// model/common/life_modification.h) to a bearing's life-table row: mean_speed_rpm,
/// pitch_diameter_mm, fatigue_load_limit_N, contamination_factor, oil_temperature_C,
/// viscosity_mm2_s, reference_viscosity_mm2_s (ν1 at the bearing's mean speed), kappa = ν/ν1,
/// a_ISO and L_nm_h (null when not computed, with a_ISO_note saying why; L_nm_h null when infinite).
/// @return L_nm_h; NaN when a_ISO is not computed.
double AddModifiedLife(LifeTableRow& row, BearingKind kind, const ModifiedLifeRating& rating,
                       const ModifiedLifeOil& oil, double mean_speed_rpm, double equivalent_load_N, double L10h);

/// What the life block's "model" string says of the modified life: that it is not modelled (no
/// bearing gives C_u and D_pw) or how it is computed.
std::string ModifiedLifeModelText(bool computed);

/// One line of a life block's duty cycle, as the study gave it.
struct DutyCycleEcho {
  double output_torque_Nm = 0, input_speed_rpm = 0, time_share = 0;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("output_torque_Nm", &output_torque_Nm, Field().Unit("N·m"));
    a->Visit("input_speed_rpm", &input_speed_rpm, Field().Unit("rpm"));
    a->Visit("time_share", &time_share, Field());
  }
};
std::vector<DutyCycleEcho> DutyCycleEchoOf(const std::vector<OperatingLine>& lines);
/// The duty cycle as a study file gives it (a sizing's best-design study): [{output_torque_Nm,
/// input_speed_rpm, time_share}, …].
nlohmann::json DutyCycleJson(const std::vector<OperatingLine>& lines);

}  // namespace camopt::studies
