// The lubrication blocks of a study ("lubricant", "surfaces", "bearing_friction",
// "efficiency_map") and the "lubrication" block of its result, declared once (studies/archive.h),
// for every kind that computes lubricated losses (docs/lubrication.md).
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/common/bearing_friction.h"
#include "model/common/lubricant.h"
#include "model/common/thermal.h"
#include "model/contact/lubricated_friction.h"
#include "studies/archive.h"
#include "studies/input.h"
#include "studies/report.h"
#include "studies/study.h"

namespace camopt::studies {

/// "lubricant.thermal": the housing's heat balance that sets the oil temperature.
struct ThermalInput {
  double housing_area_m2 = 0;
  double heat_transfer_W_per_m2K = 15.0;
  double ambient_C = 20.0;
  double forced_W_per_K = 0.0;
  double max_oil_temperature_C = 120.0;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("housing_area_m2", &housing_area_m2,
             Field().Required().Positive().Unit("m²").Desc("the housing's outer surface that gives off heat"));
    a->Visit("heat_transfer_W_per_m2K", &heat_transfer_W_per_m2K,
             Field().Positive().Unit("W/(m²·K)").Desc(
                 "convection and radiation together (still air about 10–20; a fan about 30–50)"));
    a->Visit("ambient_C", &ambient_C, Field().In(-60.0, 200.0).Unit("°C").Desc("the air around the housing"));
    a->Visit("forced_W_per_K", &forced_W_per_K,
             Field().NonNegative().Unit("W/K").Desc("an oil cooler or fan's further heat path"));
    a->Visit("max_oil_temperature_C", &max_oil_temperature_C,
             Field().In(-50.0, 300.0).Unit("°C").Desc(
                 "the oil's highest temperature: no equilibrium below it ends the run with exit 3"));
  }
  static std::vector<CrossFieldRule> CrossFieldRules() {
    return {{{"max_oil_temperature_C", "ambient_C"}, "the oil's limit temperature above the ambient",
             "gives off no heat"}};
  }
};

/// "lubricant": the oil (ν40 and ν100 of its data sheet, or an ISO VG grade and base of the built-in
/// table, model/common/lubricant.h kTabulatedOils) and its temperature, given or from the housing's
/// heat balance (exactly one of "temperature_C", "thermal").
struct LubricantInput {
  std::optional<std::string> name;
  std::optional<double> nu40_cSt, nu100_cSt;
  std::optional<int> iso_vg;
  std::optional<std::string> base_oil;
  std::optional<double> pressure_viscosity_1_per_GPa;
  std::optional<double> density_kg_m3;
  std::optional<double> temperature_C;
  std::optional<ThermalInput> thermal;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("name", &name, Field().Desc("the oil's name, in the results"));
    a->Visit("nu40_cSt", &nu40_cSt,
             Field().Positive().Unit("mm²/s").Desc(
                 "kinematic viscosity at 40 °C (the data sheet's; with nu100_cSt, or iso_vg instead)"));
    a->Visit("nu100_cSt", &nu100_cSt,
             Field().Positive().Unit("mm²/s").Desc(
                 "kinematic viscosity at 100 °C, at most nu40_cSt (with it, the ASTM D341 temperature law)"));
    a->Visit("iso_vg", &iso_vg,
             Field().AtLeast(1).Desc("an ISO 3448 viscosity grade (32, 46, 68, 100, 150, 220, 320, 460, 680): the "
                                     "built-in oil of that grade and base_oil, its data sheet's ν40, ν100 and density "
                                     "(not with nu40_cSt, nu100_cSt)"));
    a->Visit("base_oil", &base_oil,
             Field().OneOf({"mineral", "synthetic"}).Desc(
                 "with iso_vg: a mineral gear oil or a synthesized-hydrocarbon (PAO-type) one (absent: mineral)"));
    a->Visit("pressure_viscosity_1_per_GPa", &pressure_viscosity_1_per_GPa,
             Field().In(0.0, 100.0).Unit("1/GPa").Default(20.0).Desc(
                 "Barus' α (absent: 20, typical of mineral oils; the results say it was assumed)"));
    a->Visit("density_kg_m3", &density_kg_m3,
             Field().In(500.0, 2500.0).Unit("kg/m³").Desc(
                 "density at 15 °C (absent: the built-in oil's, else 880, typical of mineral oils)"));
    a->Visit("temperature_C", &temperature_C,
             Field().In(-50.0, 300.0).Unit("°C").Desc("the oil's temperature (not with thermal)"));
    a->Visit("thermal", &thermal,
             Field().Desc("the housing's heat balance: the oil's temperature where it gives off the loss (not with "
                          "temperature_C)"));
  }
  static nlohmann::ordered_json SchemaRules() {
    return nlohmann::ordered_json::parse(R"({
      "allOf": [
        {"properties": {"iso_vg": {"enum": [32, 46, 68, 100, 150, 220, 320, 460, 680]}}},
        {"oneOf": [{"required": ["temperature_C"]}, {"required": ["thermal"]}]},
        {"oneOf": [{"required": ["nu40_cSt", "nu100_cSt"], "not": {"required": ["iso_vg"]}},
                   {"required": ["iso_vg"], "not": {"anyOf": [{"required": ["nu40_cSt"]}, {"required": ["nu100_cSt"]}]}}]},
        {"if": {"not": {"required": ["iso_vg"]}}, "then": {"not": {"required": ["base_oil"]}}}
      ]})");
  }
};

/// "lubricant" of the kinds that report the bearings' modified life a_ISO (lcr_analysis,
/// cycloid_ltca; docs/life.md): the oil and its cleanliness, the contamination factor e_C.
struct LubricantWithContaminationInput : LubricantInput {
  std::optional<double> contamination_factor;
  template <typename Archive>
  void Serialize(Archive* a) {
    LubricantInput::Serialize(a);
    a->Visit("contamination_factor", &contamination_factor,
             Field().In(0.0, 1.0).Desc(
                 "e_C of ISO 281:2007 (Table 13), for the modified life a_ISO of the bearings whose rating blocks give "
                 "fatigue_load_limit_N and pitch_diameter_mm (docs/life.md). Guide values for D_pw < 100 mm / >= 100 "
                 "mm: extreme cleanliness 1 / 1; high cleanliness 0.8-0.6 / 0.9-0.8; normal 0.6-0.5 / 0.8-0.6; "
                 "slight contamination 0.5-0.3 / 0.6-0.4; typical contamination 0.3-0.1 / 0.4-0.2; severe 0.1-0 / "
                 "0.1-0; very severe 0 / 0"));
  }
};

/// "surfaces": the roughness of the contacting surfaces, the friction of the regimes and how the
/// rollers are mounted.
struct SurfacesInput {
  double roughness_rq_um = 0.2;
  std::optional<double> cam_roughness_rq_um;
  double boundary_friction = 0.1, full_film_friction = 0.03;
  std::string rollers = "rotating";
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("roughness_rq_um", &roughness_rq_um,
             Field().Positive().Unit("µm").Desc("Rq of the rollers (and of the cams without cam_roughness_rq_um)"));
    a->Visit("cam_roughness_rq_um", &cam_roughness_rq_um,
             Field().Positive().Unit("µm").Desc("Rq of the cams (absent: roughness_rq_um)"));
    a->Visit("boundary_friction", &boundary_friction,
             Field().In(0.0, 1.0).Desc("μ where the film parameter λ ≤ 1 (steel on steel, mineral oil: 0.08–0.12)"));
    a->Visit("full_film_friction", &full_film_friction,
             Field().In(0.0, 1.0).Desc("μ where λ ≥ 3, the EHL traction (0.02–0.06); blended between"));
    a->Visit("rollers", &rollers,
             Field().OneOf({"rotating", "fixed"}, "one of \"rotating\", \"fixed\"").Desc(
                 "the LCR's rollers or the cycloid's ring pins turning in their bearings (rolling on the cam or "
                 "disc) or fixed (sliding)"));
  }
};

/// Palmgren's factors of one bearing (model/common/bearing_friction.h).
struct PalmgrenInput {
  double f0 = 0, f1 = 0, mean_diameter_mm = 0;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("f0", &f0, Field().Required().In(0.0, 100.0).Desc("Palmgren's lubrication factor (oil bath: 1.5–4)"));
    a->Visit("f1", &f1, Field().Required().In(0.0, 1.0).Desc("Palmgren's load factor (roller bearings: 2e-4–5e-4)"));
    a->Visit("mean_diameter_mm", &mean_diameter_mm, Field().Required().Positive().Unit("mm").Desc("dm = (d + D)/2"));
  }
  PalmgrenBearing ToBearing() const { return {f0, f1, mean_diameter_mm}; }
};

/// "bearing_friction" of an LCR: the rollers' and the eccentric's bearings; a bearing not given
/// adds no loss (the results list it as not modelled).
struct LcrBearingFrictionInput {
  std::optional<PalmgrenInput> rollers, eccentric;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("rollers", &rollers, Field().Desc("each roller's needle bearing (rotating rollers)"));
    a->Visit("eccentric", &eccentric, Field().Desc("the cam's bearing on the input shaft's eccentric"));
  }
};

/// "bearing_friction" of a cycloid drive: the ring pins' (rotating pins), the output pins' rollers'
/// and the crank (eccentric) bearing's; a bearing not given adds no loss (listed as not modelled).
struct CycloidBearingFrictionInput {
  std::optional<PalmgrenInput> ring_pins, output_rollers, crank;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("ring_pins", &ring_pins, Field().Desc("each ring pin's roller bearing (rotating pins)"));
    a->Visit("output_rollers", &output_rollers,
             Field().Desc("each output pin's roller bearing (output_mechanism.roller_radius_mm)"));
    a->Visit("crank", &crank, Field().Desc("the disc's bearing on the crank (each disc's)"));
  }
};

/// The limits on the lubricated losses, visited by a kind's "limits" after its own.
struct LubricationLimitsInput {
  std::optional<double> min_efficiency, max_oil_temperature_C, min_film_lambda;
  template <typename Archive>
  void VisitLubricationLimits(Archive* a) {
    a->Visit("min_efficiency", &min_efficiency,
             Field().In(0.0, 1.0).Desc("the lubricated efficiency's lower limit (needs lubricant)"));
    a->Visit("max_oil_temperature_C", &max_oil_temperature_C,
             Field().In(-50.0, 300.0).Unit("°C").Desc("the oil temperature's upper limit (needs lubricant)"));
    a->Visit("min_film_lambda", &min_film_lambda,
             Field().Positive().Desc("the least film parameter λ's lower limit (needs lubricant)"));
  }
};

/// "efficiency_map": the operating points of efficiency_map.csv.
struct EfficiencyMapInput {
  std::vector<double> torque_Nm, speed_rpm;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("torque_Nm", &torque_Nm,
             Field().Required().NonNegative().MinItems(1).Unit("N·m").Desc("output torques of the map"));
    a->Visit("speed_rpm", &speed_rpm, Field().Required().Positive().MinItems(1).Unit("rpm").Desc("input speeds of the map"));
  }
};

/// The lubricant of the model from the declaration (ν in mm²/s, α in 1/MPa).
/// `source` (when given) receives where ν40, ν100 and the density come from: "given", or the built-in
/// oil's data sheet.
Lubricant ToLubricant(const LubricantInput& in, const Node& node, std::string* source = nullptr);
/// The housing's heat path.
HousingCooling ToCooling(const ThermalInput& in);
/// σ = √(Rq_roller² + Rq_cam²) [mm].
double CompositeRoughnessMm(const SurfacesInput& in);

/// What every kind's lubrication takes from the study, in model units.
struct LubricationCommon {
  Lubricant oil;
  std::string oil_source = "given";  ///< ToLubricant's `source`
  bool alpha_given = false;
  contact::RegimeFriction friction;
  double composite_roughness_mm = 0;
  bool rollers_rotate = true;  ///< "surfaces.rollers"
  double input_speed_rpm = 0;
  std::optional<double> temperature_C;  ///< given; else the thermal balance
  HousingCooling cooling;
  double max_oil_temperature_C = 120;
  std::optional<EfficiencyMapInput> map;
};

/// The lubrication blocks of a study: nullopt without "lubricant", after refusing (exit 2) the
/// blocks and limits that need it ("surfaces", `bearing_friction_key`, "efficiency_map",
/// limits.min_efficiency, …). `speed` is load.input_speed_rpm; `duty_cycle` whether the study gives
/// one (the losses are computed at one speed). @throws StudyError naming the JSON path.
std::optional<LubricationCommon> ParseLubricationCommon(const Node& root, const std::optional<LubricantInput>& lubricant,
                                                        const std::optional<SurfacesInput>& surfaces,
                                                        const std::optional<EfficiencyMapInput>& map,
                                                        std::optional<double> speed, bool duty_cycle);

/// limits.max_oil_temperature_C needs the housing's balance: refused beside lubricant.temperature_C.
void CheckOilTemperatureLimit(const Node& root, const std::optional<double>& limit, const LubricationCommon& c);
/// A sizing's lubricated operating point (objectives::LcrSizingLubrication,
/// sizing::CycloidSizingLubrication) from the common blocks: the oil, friction and roughness of its
/// spec, the speed, a given oil temperature, the cooling and the balance's limit; a limit on the oil
/// temperature (`max_oil_temperature_limit`, limits.max_oil_temperature_C) beside a given
/// temperature is refused (exit 2). The kind sets the rest (bearings, which rollers rotate).
template <typename SizingLubrication>
SizingLubrication SizingLubricationOf(const Node& root, const std::optional<double>& max_oil_temperature_limit,
                                      const LubricationCommon& c) {
  CheckOilTemperatureLimit(root, max_oil_temperature_limit, c);
  SizingLubrication l;
  l.spec.oil = c.oil;
  l.spec.friction = c.friction;
  l.spec.composite_roughness_mm = c.composite_roughness_mm;
  l.input_speed_rpm = c.input_speed_rpm;
  l.temperature_C = c.temperature_C;
  l.cooling = c.cooling;
  l.balance_limit_C = c.max_oil_temperature_C;
  return l;
}
/// A sizing kind's "lubricant", "surfaces" and "bearing_friction" as declared (BearingFriction: the
/// kind's), for the best design's analysis study (best_cycloid_ltca.json, best_lcr_analysis.json):
/// WriteTo writes each given block with every field the sizing used, defaults spelled out.
template <typename BearingFriction>
struct LubricationEcho {
  std::optional<LubricantInput> lubricant;
  std::optional<SurfacesInput> surfaces;
  std::optional<BearingFriction> bearing_friction;
  void WriteTo(nlohmann::json& study) const {
    if (lubricant) study["lubricant"] = WriteJson(*lubricant);
    if (surfaces) study["surfaces"] = WriteJson(*surfaces);
    if (bearing_friction) study["bearing_friction"] = WriteJson(*bearing_friction);
  }
};

/// The "lubrication" block of result.json, declared once.
struct LubricationResult {
  struct Oil {
    std::string name;
    double nu40_cSt = 0, nu100_cSt = 0, density_kg_m3 = 0, pressure_viscosity_1_per_GPa = 0;
    std::string pressure_viscosity_source;
    std::string source;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("name", &name, Field().Desc("the oil"));
      a->Visit("source", &source,
               Field().Desc("where ν40, ν100 and the density come from: given, or the built-in oil's data sheet"));
      a->Visit("nu40_cSt", &nu40_cSt, Field().Unit("mm²/s"));
      a->Visit("nu100_cSt", &nu100_cSt, Field().Unit("mm²/s"));
      a->Visit("density_kg_m3", &density_kg_m3, Field().Unit("kg/m³").Desc("at 15 °C"));
      a->Visit("pressure_viscosity_1_per_GPa", &pressure_viscosity_1_per_GPa, Field().Unit("1/GPa").Desc("Barus' α"));
      a->Visit("pressure_viscosity_source", &pressure_viscosity_source, Field().Desc("given or assumed"));
    }
  };
  /// The mean loss per element; the elements of the kind's mechanism only (an LCR has no ring pins).
  struct Losses {
    double total = 0;
    std::optional<double> sliding_input_cam, sliding_output_cam, rolling_input_cam, rolling_output_cam,
        roller_bearings_input, roller_bearings_output, eccentric_bearing;
    std::optional<double> ring_pins_sliding, ring_pins_rolling, ring_pin_bearings, output_pins_sliding,
        output_pins_rolling, output_roller_bearings, crank_bearing;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("total", &total, Field().Unit("W"));
      a->Visit("sliding_input_cam", &sliding_input_cam, Field().Unit("W").Desc("LCR: μ(λ) F v_s on the input cam"));
      a->Visit("sliding_output_cam", &sliding_output_cam, Field().Unit("W").Desc("LCR: on the output cam"));
      a->Visit("rolling_input_cam", &rolling_input_cam,
               Field().Unit("W").Desc("LCR: the EHL rolling (Poiseuille) loss 2 u F_R on the input cam"));
      a->Visit("rolling_output_cam", &rolling_output_cam, Field().Unit("W").Desc("LCR: on the output cam"));
      a->Visit("roller_bearings_input", &roller_bearings_input,
               Field().Unit("W").Desc("LCR: Palmgren, every roller of the fixed turret"));
      a->Visit("roller_bearings_output", &roller_bearings_output, Field().Unit("W").Desc("LCR: of the output turret"));
      a->Visit("eccentric_bearing", &eccentric_bearing, Field().Unit("W").Desc("LCR: the cam's bearing on the eccentric"));
      a->Visit("ring_pins_sliding", &ring_pins_sliding, Field().Unit("W").Desc("cycloid: μ(λ) F v_s at the ring pins"));
      a->Visit("ring_pins_rolling", &ring_pins_rolling,
               Field().Unit("W").Desc("cycloid: the EHL rolling (Poiseuille) loss 2 u F_R at the ring pins"));
      a->Visit("ring_pin_bearings", &ring_pin_bearings, Field().Unit("W").Desc("cycloid: the rotating ring pins' bearings"));
      a->Visit("output_pins_sliding", &output_pins_sliding, Field().Unit("W").Desc("cycloid: pins sliding in the holes"));
      a->Visit("output_pins_rolling", &output_pins_rolling,
               Field().Unit("W").Desc("cycloid: the rolling loss at the output pins' contacts"));
      a->Visit("output_roller_bearings", &output_roller_bearings,
               Field().Unit("W").Desc("cycloid: the output pins' rollers' bearings"));
      a->Visit("crank_bearing", &crank_bearing, Field().Unit("W").Desc("cycloid: the discs' bearings on the crank"));
    }
  };
  struct Film {
    double value = 0, film_um = 0, input_angle_deg = 0;
    std::string contact, regime;
    int index = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("value", &value, Field().Desc("λ = h_min / σ, the least over the loaded contacts and the angles"));
      a->Visit("film_um", &film_um, Field().Unit("µm").Desc("h_min there (Pan & Hamrock 1989)"));
      a->Visit("regime", &regime, Field().Desc("boundary (λ ≤ 1), mixed or full_film (λ ≥ 3)"));
      a->Visit("contact", &contact, Field().Desc("input cam, output cam (LCR); ring pin, output pin (cycloid)"));
      a->Visit("index", &index, Field().Desc("the roller's or pin's index at that angle"));
      a->Visit("input_angle_deg", &input_angle_deg, Field().Unit("°").Desc("the input (crank) angle"));
    }
  };
  Oil oil;
  std::string temperature_source;
  double oil_temperature_C = 0, viscosity_cSt = 0;
  std::optional<double> thermal_residual_W, heat_path_W_per_K;
  double input_speed_rpm = 0, output_torque_Nm = 0, output_power_W = 0, input_power_W = 0, efficiency = 0;
  Losses power_loss_W;
  double power_loss_sampling_error_W = 0;
  double no_load_running_torque_Nm = 0;
  Film min_film_lambda;
  std::string rollers;
  std::vector<std::string> not_modelled;
  std::optional<std::string> efficiency_map_file;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("oil", &oil, Field());
    a->Visit("temperature_source", &temperature_source, Field().Desc("given or thermal balance"));
    a->Visit("oil_temperature_C", &oil_temperature_C, Field().Unit("°C"));
    a->Visit("thermal_residual_W", &thermal_residual_W,
             Field().Unit("W").Desc("loss − heat given off at the oil temperature (thermal balance only)"));
    a->Visit("heat_path_W_per_K", &heat_path_W_per_K, Field().Unit("W/K").Desc("k A + forced (thermal balance only)"));
    a->Visit("viscosity_cSt", &viscosity_cSt, Field().Unit("mm²/s").Desc("at the oil temperature"));
    a->Visit("input_speed_rpm", &input_speed_rpm, Field().Unit("rpm"));
    a->Visit("output_torque_Nm", &output_torque_Nm, Field().Unit("N·m"));
    a->Visit("output_power_W", &output_power_W, Field().Unit("W"));
    a->Visit("input_power_W", &input_power_W, Field().Unit("W").Desc("output power + the losses"));
    a->Visit("efficiency", &efficiency, Field().Desc("output power / input power over the revolution"));
    a->Visit("power_loss_W", &power_loss_W, Field().Desc("the mean loss over the revolution, per element"));
    a->Visit("power_loss_sampling_error_W", &power_loss_sampling_error_W,
             Field().Unit("W").Desc("|mean over every angle − mean over every other angle|: the angle grid's error estimate"));
    a->Visit("no_load_running_torque_Nm", &no_load_running_torque_Nm,
             Field().Unit("N·m").Desc("the input torque without output torque, at the same speed and oil temperature"));
    a->Visit("min_film_lambda", &min_film_lambda, Field());
    a->Visit("rollers", &rollers, Field().Desc("rotating or fixed"));
    a->Visit("not_modelled", &not_modelled, Field().Desc("losses the efficiency does not contain"));
    a->Visit("efficiency_map_file", &efficiency_map_file, Field().Desc("the map's CSV, when asked"));
  }
};

/// The oil temperature of an operating point: the given one, or the housing's balance against
/// `loss_W(t)` (model/common/thermal.h); `thermal` holds the solve (found, residual, why).
struct OilTemperature {
  double celsius = 0;
  std::optional<ThermalPoint<double>> thermal;
  bool found() const { return !thermal || thermal->found; }
};
OilTemperature SolveOilTemperature(const LubricationCommon& l, const std::function<double(double)>& loss_W);

/// The parts of the "lubrication" result every kind fills alike: the oil, the temperature and its
/// source, the powers and the efficiency from the output power and the total loss.
LubricationResult CommonLubricationResult(const LubricationCommon& l, const OilTemperature& t, double output_torque_Nm,
                                          double output_power_W, double total_loss_W);

/// The JSON Schema rules of the lubrication blocks (entries for the root's "dependentRequired" and
/// "allOf"), with `bearing_friction_key` the kind's bearing block.
void AddLubricationSchemaRules(nlohmann::ordered_json& rules);

/// efficiency_map.csv (torque, speed, efficiency, loss, oil temperature, λ, thermal equilibrium per
/// row) and efficiency_map.svg (η over the speed, a line per torque of `torques`).
void WriteEfficiencyMap(const std::vector<std::array<double, 7>>& rows, const std::vector<double>& torques,
                        Outputs& out);

/// The report's rows of the "lubrication" block (shown when the result has it), after `rows`.
std::vector<Headline> WithLubricationHeadlines(std::vector<Headline> rows);

/// "boundary", "mixed" or "full_film" by the borders of model/contact/lubricated_friction.h.
std::string RegimeName(double lambda);


}  // namespace camopt::studies
