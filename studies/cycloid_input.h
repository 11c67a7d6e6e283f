// The blocks of a cycloid study file that several cycloid kinds share (cycloid_ltca,
// cycloid_crowning_tuning, cycloid_min_size), each declared once (studies/archive.h): the drive,
// the profile modification, the crowning, the contact grid, the output mechanism and the schemas
// of the bearing-life blocks (read by studies/bearing_life_io.h). The checks across fields (a
// one-tooth difference, a plausible drive, a crowning that fits the face) are in
// studies/cycloid_study_common.h.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/cycloid/loaded_tca.h"
#include "studies/archive.h"
#include "studies/bearing_life_io.h"

namespace camopt::studies::cycloid_common {

/// "drive": the pin ring and the disc (docs/cycloid.md, "Geometry").
struct DriveInput {
  int teeth = 0, rollers = 0;
  double roller_position_radius_mm = 0, roller_radius_mm = 0, eccentricity_mm = 0, face_width_mm = 0;
  std::optional<double> bore_diameter_mm;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("teeth", &teeth, Field().Required().AtLeast(2).Desc("z₁, the disc's teeth"));
    a->Visit("rollers", &rollers,
             Field().Required().AtLeast(3).Desc("z₂, the ring's pins (rollers): teeth + 1 (a one-tooth difference)"));
    a->Visit("roller_position_radius_mm", &roller_position_radius_mm,
             Field().Required().Positive().Unit("mm").Desc("R_p, the radius of the pins' circle"));
    a->Visit("roller_radius_mm", &roller_radius_mm, Field().Required().Positive().Unit("mm").Desc("r_p, of each pin"));
    a->Visit("eccentricity_mm", &eccentricity_mm,
             Field().Required().Positive().Unit("mm").Desc("e, of the crank (shortening coefficient e z₂ / R_p in 0.05 to 1)"));
    a->Visit("face_width_mm", &face_width_mm, Field().Required().Positive().Unit("mm").Desc("b, the disc's width"));
    a->Visit("bore_diameter_mm", &bore_diameter_mm,
             Field().Positive().Unit("mm").Desc(
                 "the disc's central bore in its solid model (cycloid_ltca's geometry files; accepted by the other "
                 "cycloid kinds so that a drive block can be shared); absent: none"));
  }
  static std::vector<CrossFieldRule> CrossFieldRules() {
    return {{{"teeth", "rollers"}, "rollers = teeth + 1 (a one-tooth difference)", "teeth + 1"}};
  }
};

/// "modification": the profile's equidistant and offset corrections [µm] (docs/cycloid.md).
struct ModificationInput {
  /// Absent: 0 (no schema default: cycloid_min_size may size the field in "variables" instead).
  std::optional<double> delta_position_um, delta_radius_um;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("delta_position_um", &delta_position_um,
             Field().Unit("µm").Desc("Δa, modification of the pins' circle radius (negative: backlash; absent: 0)"));
    a->Visit("delta_radius_um", &delta_radius_um,
             Field().Unit("µm").Desc("Δr, modification of the pin radius (positive: backlash; absent: 0)"));
  }
};

/// "crowning": the axial modification of the teeth, by type (docs/cycloid.md, "Crowning"). The
/// fields of a type are required (cycloid_ltca); those of other types are refused.
struct CrowningInput {
  std::string type;
  std::optional<double> radius_mm, flat_length_mm, coefficient_mm, effective_length_mm, end_drop_mm;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("type", &type,
             Field().Required().OneOf({"none", "full", "partial", "logarithmic"})
                 .Desc("none; full (a circular arc over the face); partial (a flat middle and circular ends); "
                       "logarithmic (Lundberg's profile)"));
    a->Visit("radius_mm", &radius_mm,
             Field().Positive().Unit("mm").Desc("full, partial: the crowning radius (more than half the crowned length)"));
    a->Visit("flat_length_mm", &flat_length_mm,
             Field().NonNegative().Unit("mm").Desc("partial, logarithmic (absent: 0): the uncrowned middle's length"));
    a->Visit("coefficient_mm", &coefficient_mm,
             Field().NonNegative().Unit("mm").Desc("logarithmic: the coefficient of the logarithmic drop"));
    a->Visit("effective_length_mm", &effective_length_mm,
             Field().NonNegative().Unit("mm")
                 .Desc("logarithmic: the crowned length L, >= the face width (absent or 0: the face width)"));
    a->Visit("end_drop_mm", &end_drop_mm,
             Field().NonNegative().Unit("mm")
                 .Desc("logarithmic: the largest drop at the face ends (absent or 0: unbounded)"));
  }
  /// Each type's fields: required ones, the others of other types refused.
  static nlohmann::ordered_json SchemaRules();
};

/// Each crowning type with the fields it requires and the fields it refuses (the one table behind
/// the crowning blocks' rules and the sizing kinds' rules on crowning variables).
struct CrowningTypeFields {
  const char* type;
  std::vector<const char*> required, refused;
};
const std::vector<CrowningTypeFields>& CrowningTypes();

/// "crowning" of a study that tunes or sizes some of its fields (cycloid_min_size,
/// cycloid_crowning_tuning): the same fields, none required here (a field the study varies is left
/// out; the kind's rules say which it needs).
struct CrowningStartInput : CrowningInput {
  /// The fields of other types refused.
  static nlohmann::ordered_json SchemaRules();
};

/// "analysis.grid"'s default: the model's cells (cycloid::LoadedOptions, 40 × 40).
inline std::array<int, 2> DefaultGrid() {
  const cycloid::LoadedOptions o;
  return {o.profile_cells, o.axial_cells};
}

/// "analysis.grid": [profile_cells, axial_cells] of the contact.
inline Field GridField() {
  return Field().Expect("an array [profile_cells, axial_cells]").AtLeast(4).AtMost(512, "at most 512 cells each way")
      .Default(nlohmann::json(DefaultGrid()))
      .Desc("[profile_cells, axial_cells]: contact cells across the profile and along the face, 4 to 512 each");
}

/// "output_mechanism" of the bearing life: rigid output pins in the disc's holes (docs/life.md,
/// "Cycloid").
struct OutputMechanismInput {
  std::optional<int> pin_count;
  double pin_circle_radius_mm = 0;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("pin_count", &pin_count, Field().AtLeast(3).Desc("output pin count Z_w (absent: the continuous limit)"));
    a->Visit("pin_circle_radius_mm", &pin_circle_radius_mm,
             Field().Required().Positive().Unit("mm").Desc("R_w, the output pins' circle, inside the disc's root radius"));
  }
};

/// "output_mechanism" of cycloid_ltca and cycloid_min_size: rigid pins for the life, or, with
/// pin_radius_mm and hole_radius_mm, the mechanism with clearance and compliance (docs/cycloid.md,
/// "Output mechanism"; read by cycloid_common::ParseCompliantOutputPins).
struct CompliantOutputMechanismInput {
  std::optional<int> pins, pin_count;
  double pin_circle_radius_mm = 0;
  std::optional<double> pin_radius_mm, hole_radius_mm, roller_radius_mm;
  std::optional<std::string> pin_support;
  std::optional<double> pin_span_mm;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("pins", &pins, Field().AtLeast(3).Desc("output pin count Z_w (absent: the continuous limit, rigid pins only)"));
    a->Visit("pin_count", &pin_count, Field().AtLeast(3).Desc("older name of pins"));
    a->Visit("pin_circle_radius_mm", &pin_circle_radius_mm,
             Field().Required().Positive().Unit("mm").Desc("R_w, the pins' circle, inside the disc's root radius"));
    a->Visit("pin_radius_mm", &pin_radius_mm, Field().Positive().Unit("mm").Desc("r_w, the pin (the beam)"));
    a->Visit("hole_radius_mm", &hole_radius_mm,
             Field().Positive().Unit("mm").Desc(
                 "r_h >= contact radius + e; R_w + r_h below the root radius; 2 r_h below the holes' pitch"));
    a->Visit("roller_radius_mm", &roller_radius_mm,
             Field().Positive().Unit("mm").Desc("a roller on each pin, > pin_radius_mm: it touches the hole (absent: none)"));
    a->Visit("pin_support", &pin_support,
             Field().OneOf({"cantilever", "both_ends"}, "one of \"cantilever\", \"both_ends\"")
                 .Desc("the pin fixed at the flange (cantilever, when absent) or supported at both ends"));
    a->Visit("pin_span_mm", &pin_span_mm,
             Field().Positive().Unit("mm").Desc(
                 "the pin's free length or span, >= the disc stack (discs - 1) * disc_spacing_mm + face width "
                 "(absent: the stack)"));
  }
  static nlohmann::ordered_json SchemaRules() {
    return {{"not", {{"required", {"pins", "pin_count"}}}},
            {"dependentRequired",
             {{"pin_radius_mm", {"hole_radius_mm", "pins"}},
              {"hole_radius_mm", {"pin_radius_mm", "pins"}},
              {"roller_radius_mm", {"pin_radius_mm"}},
              {"pin_support", {"pin_radius_mm"}},
              {"pin_span_mm", {"pin_radius_mm"}}}}};
  }
  static std::vector<CrossFieldRule> CrossFieldRules() {
    return {{{"roller_radius_mm", "pin_radius_mm"}, "a roller on the pin is larger than the pin",
             "a roller radius > pin_radius_mm"},
            {{"pins", "pin_count", "hole_radius_mm", "pin_circle_radius_mm"},
             "the holes do not overlap: 2 hole_radius_mm below their pitch 2 R_w sin(π/Z_w)",
             "holes that do not overlap"}};
  }
};

/// A cycloid kind's "duty_cycle" (read by ParseDutyCycle, studies/bearing_life_io.h): lines of the
/// disc's torque [N·m], the crank's speed [rpm] and the time share.
struct DutyWords {
  static constexpr const char* kTorque = "the disc's torque in this line (one disc)";
  static constexpr const char* kSpeed = "the input (crank) speed in this line";
};
using CycloidDutyCycleInput = DutyCycleInput<DutyWords>;
/// The bearing-life blocks every cycloid kind takes (docs/life.md, Cycloid): "duty_cycle" (its
/// description ends with `each_line`, what one line runs), "crank_bearing" and "pins" (a
/// KindedBearingRatingInput and a BearingRatingInput, studies/bearing_life_io.h; with the modified
/// life's C_u and D_pw in the kinds that report a_ISO).
template <typename Archive, typename CrankBearing, typename Pins>
void VisitLifeRatings(Archive* a, CycloidDutyCycleInput* duty_cycle, std::optional<CrankBearing>* crank_bearing,
                      std::optional<Pins>* pins, const std::string& each_line) {
  a->Visit("duty_cycle", duty_cycle,
           Field().MinItems(1, kDutyCycleNotEmpty).Desc(
               "lines of the duty cycle for the bearing lives (docs/life.md, Cycloid): output_torque_Nm is the "
               "disc's torque" + each_line));
  a->Visit("crank_bearing", crank_bearing,
           Field().Desc("the crank (eccentric) bearing carrying the disc: ISO 281 ratings (docs/life.md, Cycloid)"));
  a->Visit("pins", pins,
           Field().Desc("the ring pins as rolling elements (a roller on a needle or roller sleeve): ratings per pin, "
                        "p = 10/3 (docs/life.md, Cycloid)"));
}

}  // namespace camopt::studies::cycloid_common
