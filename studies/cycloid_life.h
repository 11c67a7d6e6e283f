// The bearing lives of a cycloid drive over a duty cycle, as the cycloid study kinds report them
// (docs/life.md, "Cycloid"): cycloid_ltca for its drive, cycloid_crowning_tuning for the tuned one.
#pragma once

#include <optional>
#include <string>
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

/// result.json "life": `ELEMENT_L10h`, shortest_L10h, shortest_bearing, the duty cycle, the output
/// mechanism and the table (the rows of lcr_min_size's best.life.table); with `l.oil` the modified
/// life of the bearings given C_u and D_pw in their rows and shortest_L_nm_h (AddModifiedLife).
nlohmann::json LifeJson(const LifeSpec& spec, const LifeResult& l);
/// The JSON Schema of LifeJson's object, for a declared result's raw "life" member (its
/// `ELEMENT_L10h` keys vary with the drive, so further properties are allowed).
nlohmann::ordered_json LifeJsonSchema();

}  // namespace camopt::studies::cycloid_common
