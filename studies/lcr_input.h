// Parsing the lobe cam reducer design, material and load from a study file; shared by every
// study kind that takes an LCR design (lcr_analysis, the lobe_cam_reducer rigidity element, …).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/lcr/life.h"
#include "model/lcr/reducer.h"
#include "studies/archive.h"
#include "studies/bearing_life_io.h"
#include "studies/input.h"
#include "studies/lcr_contact_input.h"
#include "studies/geometry_files.h"
#include "studies/material_input.h"

namespace camopt::studies {

/// One cam side of a lobe cam reducer as the study file gives it, declared once (studies/archive.h).
struct LcrSideInput {
  int lobes = 0, rollers = 0;
  double turret_radius_mm = 0, roller_diameter_mm = 0, roller_length_mm = 0, cam_thickness_mm = 0;
  std::optional<double> cutter_diameter_mm, bore_diameter_mm;
  std::optional<KeywayInput> keyway;
  std::optional<BoltCircleInput> bolt_circle;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("lobes", &lobes, Field().Required().AtLeast(1).Desc("lobes of the cam"));
    a->Visit("rollers", &rollers, Field().Required().AtLeast(2).Desc("rollers of the turret (more than the lobes)"));
    a->Visit("turret_radius_mm", &turret_radius_mm,
             Field().Required().Positive().Unit("mm").Desc("radius of the roller centres' circle"));
    a->Visit("roller_diameter_mm", &roller_diameter_mm, Field().Required().Positive().Unit("mm").Desc("roller diameter"));
    a->Visit("roller_length_mm", &roller_length_mm,
             Field().Required().Positive().Unit("mm").Desc("roller length (1e-6 to 1e6 times the turret radius)"));
    a->Visit("cam_thickness_mm", &cam_thickness_mm,
             Field().Required().Positive().Unit("mm").Desc("cam thickness (1e-6 to 1e6 times the turret radius)"));
    a->Visit("cutter_diameter_mm", &cutter_diameter_mm,
             Field().Positive().Unit("mm").Desc("cutter of the cam profile (absent: the roller diameter)"));
    a->Visit("bore_diameter_mm", &bore_diameter_mm, Field().Positive().Unit("mm").Desc("the cam's bore (absent: none)"));
    a->Visit("keyway", &keyway, Field().Desc("a key slot in the bore (lcr_analysis's geometry files; docs/parts.md)"));
    a->Visit("bolt_circle", &bolt_circle,
             Field().Desc("equal through-holes on a circle about the cam's centre (lcr_analysis's geometry files)"));
  }
  /// The counts of a buildable side (model/lcr/reducer.h CheckDesign).
  static std::vector<CrossFieldRule> CrossFieldRules() {
    return {{{"lobes", "rollers"}, "more rollers than lobes", "more rollers than lobes"},
            {{"lobes", "rollers"}, "lobes and rollers without a common divisor", "no common divisor"},
            {{"lobes", "rollers"},
             "rollers = lobes + 1 (a difference above 1 winds the pitch curve: a self-crossing cam)",
             "rollers − lobes"}};
  }
};

/// A lobe cam reducer's design as the study file gives it (without crowning or bearing ratings).
struct LcrReducerInput {
  double eccentricity_mm = 0;
  LcrSideInput input, output;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("eccentricity_mm", &eccentricity_mm, Field().Required().Positive().Unit("mm").Desc("eccentricity e"));
    a->Visit("input", &input, Field().Required().Desc("the input cam and its rollers"));
    a->Visit("output", &output, Field().Required().Desc("the output cam and its rollers"));
  }
};

/// The ratings of a cam side's roller bearings (C, C0), visited after the side's own fields.
struct LcrRollerRatingsInput {
  std::optional<double> dynamic_rating_N, static_rating_N;
  template <typename Archive>
  void VisitRatings(Archive* a) {
    a->Visit("dynamic_rating_N", &dynamic_rating_N,
             Field().Positive().Unit("N").Desc(
                 "the roller bearing's basic dynamic load rating C (ISO 281); required when a life is asked "
                 "(docs/life.md)"));
    a->Visit("static_rating_N", &static_rating_N,
             Field().Positive().Unit("N").Desc(
                 "the roller bearing's basic static load rating C0 (ISO 76); s0 is reported when given"));
  }
};

/// A cam side of the kinds with the bearing lives but no crowning (lcr_crowning_tuning, whose answer
/// is the crowning): the design and the roller bearings' ratings.
struct LcrSideWithRatingsInput : LcrSideInput, LcrRollerRatingsInput {
  template <typename Archive>
  void Serialize(Archive* a) {
    LcrSideInput::Serialize(a);
    VisitRatings(a);
  }
};

/// A cam side of the kinds with the finite-length contact and the bearing lives (lcr_analysis): the
/// design, the rollers' crowning, their bearing's ratings and its modified-life inputs.
struct LcrRatedSideInput : LcrSideInput, LcrRollerRatingsInput, ModifiedLifeRatingInput {
  /// The modified life's two fields come together; the keyway of lcr_analysis's geometry files
  /// needs the bore (the other kinds write no part and ignore both).
  static nlohmann::ordered_json SchemaRules() {
    nlohmann::ordered_json r = ModifiedLifeRatingInput::SchemaRules();
    r["dependentRequired"]["keyway"] = {"bore_diameter_mm"};
    return r;
  }
  static std::vector<CrossFieldRule> CrossFieldRules() {
    std::vector<CrossFieldRule> rules = LcrSideInput::CrossFieldRules();
    rules.push_back(MountingRule());
    return rules;
  }
  std::optional<LcrCrowningInput> crowning;
  template <typename Archive>
  void Serialize(Archive* a) {
    LcrSideInput::Serialize(a);
    a->Visit("crowning", &crowning,
             Field().Desc("the rollers' crowning (docs/lcr.md); each form takes its own fields only (absent: "
                          "straight rollers); a crowning other than none needs a contact model other than line"));
    VisitRatings(a);
    VisitModifiedLife(a);
  }
};

/// "eccentric_bearing": the bearing carrying the cam on the input shaft's eccentric (docs/life.md).
struct EccentricBearingInput {
  double dynamic_rating_N = 0;
  std::optional<double> static_rating_N;
  std::string kind;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("dynamic_rating_N", &dynamic_rating_N,
             Field().Required().Positive().Unit("N").Desc("basic dynamic load rating C (ISO 281)"));
    a->Visit("static_rating_N", &static_rating_N,
             Field().Positive().Unit("N").Desc("basic static load rating C0 (ISO 76); s0 is reported when given"));
    a->Visit("kind", &kind,
             Field().Required().OneOf({"ball", "roller"}, "one of ball, roller")
                 .Desc("ball or roller bearing (the life exponent p = 3 or 10/3)"));
  }
};

/// lcr_analysis's "eccentric_bearing": the ratings and the modified-life inputs.
struct RatedEccentricBearingInput : EccentricBearingInput, ModifiedLifeRatingInput {
  using ModifiedLifeRatingInput::SchemaRules;
  template <typename Archive>
  void Serialize(Archive* a) {
    EccentricBearingInput::Serialize(a);
    VisitModifiedLife(a);
  }
};

/// The reducer of lcr_analysis: the design, per side the crowning and the roller bearings' ratings,
/// and the eccentric's bearing (with the modified-life inputs). lcr_crowning_tuning's is the same
/// with sides without crowning (Side = LcrSideWithRatingsInput) and the ratings only.
template <typename Side, typename Eccentric = EccentricBearingInput>
struct LcrReducerWithRatingsInput {
  double eccentricity_mm = 0;
  Side input, output;
  std::optional<Eccentric> eccentric_bearing;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("eccentricity_mm", &eccentricity_mm, Field().Required().Positive().Unit("mm").Desc("eccentricity e"));
    a->Visit("input", &input, Field().Required().Desc("the input cam (fixed turret) and its rollers"));
    a->Visit("output", &output, Field().Required().Desc("the output cam (output turret) and its rollers"));
    a->Visit("eccentric_bearing", &eccentric_bearing,
             Field().Desc("the bearing carrying the cam on the input shaft's eccentric (docs/life.md)"));
  }
  /// The design alone.
  LcrReducerInput Design() const {
    LcrReducerInput d;
    d.eccentricity_mm = eccentricity_mm;
    d.input = static_cast<const LcrSideInput&>(input);
    d.output = static_cast<const LcrSideInput&>(output);
    return d;
  }
};
using LcrRatedReducerInput = LcrReducerWithRatingsInput<LcrRatedSideInput, RatedEccentricBearingInput>;

/// The model's reducer of a declared one (the file's units are the model's, mm): the conversion
/// alone, for a design ToReducer has checked.
lcr::Reducer<double> ReducerOf(const LcrReducerInput& in);

/// The design of a reducer read from `node` as LcrReducerInput: the checks between fields (more
/// rollers than lobes, lengths on the turret's scale, lcr::CheckDesign) with ParseReducer's
/// messages. @throws StudyError naming the JSON path.
lcr::Reducer<double> ToReducer(const LcrReducerInput& in, const Node& node);

/// Reads {"eccentricity_mm", "input": {...}, "output": {...}} (LcrReducerInput) and checks the
/// design (lobes < rollers, rollers that overlap, …); throws StudyError naming the JSON path.
lcr::Reducer<double> ParseReducer(const Node& reducer);

/// The smallest torque an LCR study takes [N·m]: a micro-newton-metre, far below any reducer's
/// load, and above what the models resolve (at 1e-300 N·m the contact forces underflow: the
/// sizing's cycle had no loaded contact and the tuning's contact grids collapsed).
inline constexpr double kMinLcrTorqueNm = 1e-6;
inline constexpr const char* kMinLcrTorqueExpected = "a torque of at least 1e-6 N·m";

/// Fails `torque_node` (exit 2) when `torque_Nmm` is more than the output rollers can carry: their
/// forces balance it on arms no longer than the turret radius, so the largest carries at least
/// T / (n R); a contact is no wider than the roller, so its mean pressure is at least that force
/// over the roller's projected area d L. Above the Young's modulus (a strain of one) no contact
/// model applies (a torque of 1e308 reached the contact solvers as infinite forces).
void CheckCarriedTorque(const lcr::Reducer<double>& reducer, double youngs_modulus_MPa, double torque_Nmm,
                        const Node& torque_node);

/// Optional cutter diameter per side ("cutter_diameter_mm", default the roller diameter);
/// must be > 0 and <= the roller diameter.
double ParseCutterDiameter(const Node& side, double roller_diameter);

/// The ratings of an eccentric bearing (EccentricBearingInput): C, C0 (0 when not given) and
/// whether it is a ball bearing.
struct EccentricBearingRating {
  double dynamic_N = 0.0, static_N = 0.0;
  bool ball = false;
};

/// An LCR kind's "duty_cycle" (read by ParseDutyCycle, studies/bearing_life_io.h): lines of output
/// torque T_o [N·m], input speed [rpm] and time share.
struct LcrDutyWords {
  static constexpr const char* kTorque = "the output torque T_o in this line";
  static constexpr const char* kSpeed = "the input speed in this line";
};
using LcrDutyCycleInput = DutyCycleInput<LcrDutyWords>;

/// The rules of JSON Schema between an LCR kind's life fields (two entries of the root's "allOf"): a
/// life (a duty cycle or load.input_speed_rpm) needs both cams' reducer.*.dynamic_rating_N, and the
/// speed is given one way (a duty cycle without load.input_speed_rpm).
nlohmann::ordered_json LcrLifeSchemaRules();

}  // namespace camopt::studies
