// The tolerance parts of the LCR study kinds (issue 18): "tolerances", "monte_carlo" and
// "analysis.load_model" parsed once, and the "transmission_error" block of result.json; shared by
// lcr_analysis and lcr_min_size.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "model/lcr/transmission_error.h"
#include "studies/input.h"

namespace camopt::studies {

struct LcrToleranceSpec {
  lcr::ToleranceBands bands;
  int samples = 0;              ///< "monte_carlo.samples" (0: linear only)
  std::uint64_t seed = 1;       ///< "monte_carlo.seed"
  int angle_steps = 72;         ///< "monte_carlo.angle_steps": angles of the transmission error
  double lost_motion_torque_fraction = 0.03;  ///< "monte_carlo.lost_motion_torque_fraction" of T_o
};

/// Reads root["tolerances"] ({"eccentricity_um", "turret_radius_um", "roller_diameter_um",
/// "roller_pitch_arcsec", "profile_um", "bearing_clearance_um"}, ± bands, each optional, ≥ 0) and
/// root["monte_carlo"] ({"samples", "seed", "angle_steps", "lost_motion_torque_fraction"}).
/// Empty when the study has no "tolerances". @throws StudyError naming the JSON path.
std::optional<LcrToleranceSpec> ParseLcrTolerances(const Node& root);

/// "analysis.load_model": "rigid" (default) or "compliant".
lcr::LoadModel ParseLoadModel(const Node& analysis);
std::string LoadModelName(lcr::LoadModel m);

/// The "transmission_error" object of result.json.
nlohmann::json TransmissionErrorJson(const LcrToleranceSpec& spec, const lcr::TransmissionErrorResult& te);

}  // namespace camopt::studies
