// The bearing lives of a cycloid drive over a duty cycle, as the cycloid study kinds report them
// (docs/life.md, "Cycloid"): cycloid_ltca for its drive, cycloid_crowning_tuning for the tuned one.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/common/bearing_life.h"
#include "model/cycloid/bearing_loads.h"
#include "model/cycloid/loaded_tca.h"
#include "studies/bearing_life_io.h"
#include "studies/cycloid_study_common.h"

namespace camopt::studies::cycloid_common {

/// One rated element's life over the duty cycle.
struct ElementLife {
  std::string name;  ///< "crank_bearing", "pins"
  RollingBearingRating rating;
  cycloid::BearingLifeOverCycle life;
  double s0 = 0.0;   ///< C0 / largest load (when C0 is given)
};

struct LifeResult {
  std::vector<ElementLife> elements;
  double shortest_L10h = 0.0;
  std::string shortest;
  double mean_input_speed_rpm = 0.0;
  int crank_bearing_samples = 0;  ///< samples of the crank bearing's load period per line
  /// The oil at the lubricated operating point, when some bearing's modified life a_ISO is asked.
  std::optional<ModifiedLifeOil> oil;
};

/// The lives over spec's duty cycle: each line one LTCA cycle of `tca` at its torque on
/// crank_angles_rad (uniform over whole mesh periods; cycloid::UniformWholeMeshPeriods) — the
/// contact is nonlinear, so no scaling between lines; a line at `solved_torque_Nmm` reuses
/// `solved_meshes` when given (the study's own cycle). The crank bearing's load |B| over its load
/// period (model/cycloid/bearing_loads.h), the ring pins' loads and spin over one roller's period,
/// each line's revolution-weighted equivalent load, Palmgren–Miner over the lines.
LifeResult RunLife(const LifeSpec& spec, const cycloid::LoadedTca& tca, const std::vector<double>& crank_angles_rad,
                   double solved_torque_Nmm = 0.0, const std::vector<cycloid::MeshLoad>* solved_meshes = nullptr);

/// The output mechanism whose pin forces load the crank bearing in a life block: pin count (or
/// "continuous") and circle radius, and the model in words (cycloid_ltca, cycloid_crowning_tuning)
/// or whether the circle is inside the sized disc's root (cycloid_min_size).
struct LifeOutputMechanism {
  std::variant<int, std::string> pin_count = 0;  ///< a whole number, or "continuous"
  /// pin_count of `pins` output pins (0: the continuous limit).
  static std::variant<int, std::string> PinCount(int pins) {
    if (pins > 0) return pins;
    return std::string("continuous");
  }
  double pin_circle_radius_mm = 0;
  std::optional<std::string> model;
  std::optional<bool> inside_root_radius;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("pin_count", &pin_count, Field().Desc("the output pins, or \"continuous\" (the continuous limit)"));
    a->Visit("pin_circle_radius_mm", &pin_circle_radius_mm, Field().Unit("mm").Desc("R_w"));
    a->Visit("model", &model, Field().Desc("the pins' force law"));
    a->Visit("inside_root_radius", &inside_root_radius,
             Field().Desc("a sizing's: the pins' circle is inside the sized disc's root radius"));
  }
};

/// What every cycloid life block has: the crank bearing's and the pins' L10h, the shortest, the
/// table (the rows of every kind's life table) and the duty cycle.
struct CycloidLives {
  double shortest_L10h = 0;
  std::string shortest_bearing;
  double crank_bearing_L10h = 0;
  std::optional<double> pins_L10h;
  std::vector<LifeTableRow> table;
  std::vector<DutyCycleEcho> duty_cycle;

  /// The element's L10h to its key: crank_bearing_L10h or pins_L10h.
  void SetElementLife(const std::string& element, double L10h) {
    (element == "pins" ? pins_L10h.emplace() : crank_bearing_L10h) = L10h;
  }
  template <typename Archive>
  void Serialize(Archive* a) {
    const Field hours = Field().NullWhenNotFinite().Unit("h");
    a->Visit("shortest_L10h", &shortest_L10h, Field(hours).Desc("null: unlimited"));
    a->Visit("shortest_bearing", &shortest_bearing, Field().Desc("crank_bearing or pins"));
    a->Visit("crank_bearing_L10h", &crank_bearing_L10h, Field(hours).Desc("null: unlimited"));
    a->Visit("pins_L10h", &pins_L10h, Field(hours).Desc("with rated pins (null: unlimited)"));
    a->Visit("table", &table, Field().Desc("report.html's and datasheet.html's rows"));
    a->Visit("duty_cycle", &duty_cycle, Field());
  }
};

/// result.json's "life" of cycloid_ltca and cycloid_crowning_tuning (docs/life.md, "Cycloid"):
/// the crank bearing's and the pins' L10h, the shortest, the table (the rows of every kind's life
/// table), the duty cycle and the output mechanism; with `l.oil` the modified life of the bearings
/// given C_u and D_pw (AddModifiedLife) and the shortest of those.
struct LifeBlock : CycloidLives {
  std::optional<double> shortest_L_nm_h;
  std::optional<std::variant<std::string, std::nullptr_t>> shortest_L_nm_bearing;  ///< with a lubricant
  double mean_input_speed_rpm = 0;
  LifeOutputMechanism output_mechanism;
  int crank_bearing_samples_per_line = 0;
  std::optional<double> efficiency_energy_mean;  ///< never set: null (the efficiency is lubrication's)
  std::string efficiency, model;
  std::optional<std::string> design;  ///< cycloid_crowning_tuning: which design the lives are of
  template <typename Archive>
  void Serialize(Archive* a) {
    CycloidLives::Serialize(a);
    const Field hours = Field().NullWhenNotFinite().Unit("h");
    a->Visit("shortest_L_nm_h", &shortest_L_nm_h,
             Field(hours).Desc("with a lubricant: the shortest modified life computed (null: none)"));
    a->Visit("shortest_L_nm_bearing", &shortest_L_nm_bearing, Field().Desc("with a lubricant: its bearing (null: none)"));
    a->Visit("mean_input_speed_rpm", &mean_input_speed_rpm, Field().Unit("rpm"));
    a->Visit("output_mechanism", &output_mechanism, Field());
    a->Visit("crank_bearing_samples_per_line", &crank_bearing_samples_per_line, Field());
    a->Visit("efficiency_energy_mean", &efficiency_energy_mean, Field().NullWhenAbsent().Desc("null: see efficiency"));
    a->Visit("efficiency", &efficiency, Field().Desc("where the efficiency is"));
    a->Visit("model", &model, Field());
    a->Visit("design", &design, Field().Desc("which design the lives are of"));
  }
};
LifeBlock LifeBlockOf(const LifeSpec& spec, const LifeResult& l);

/// cycloid_min_size's best.life: the accurate model's lives of the sized design, as LifeBlock's,
/// with the limit (life_h) and each row's pass/fail against it.
struct SizingLifeBlock : CycloidLives {
  std::optional<double> life_h;
  LifeOutputMechanism output_mechanism;
  std::string efficiency, model;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("life_h", &life_h, Field().NullWhenAbsent().Unit("h").Desc("limits.life_h (null: none)"));
    CycloidLives::Serialize(a);
    a->Visit("output_mechanism", &output_mechanism, Field());
    a->Visit("efficiency", &efficiency, Field().Desc("where the efficiency is"));
    a->Visit("model", &model, Field());
  }
};

}  // namespace camopt::studies::cycloid_common
