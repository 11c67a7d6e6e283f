// A reducer's duty cycle and bearing ratings in, the life table out (docs/life.md): shared by every
// study kind that computes a rating life (lcr_analysis, lcr_min_size, cycloid_ltca).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/common/bearing_life.h"
#include "studies/input.h"

#include <nlohmann/json.hpp>

namespace camopt::studies {

/// The duty cycle of a bearing life (docs/life.md): "load.input_speed_rpm" (> 0, one line at
/// output_torque_Nmm, the study's own torque) or "duty_cycle": [{output_torque_Nm >= 0,
/// input_speed_rpm >= 0, time_share in (0, 1]}, …] with shares summing to 1 within 1e-6 (then
/// divided by their sum) and at least one speed > 0; not both. nullopt when neither is given.
/// `why` (when given) receives the reason a rating is required ("a life is asked: … is given").
/// @throws StudyError naming the JSON path, what was expected and what was found.
std::optional<std::vector<OperatingLine>> ParseDutyCycle(const Node& root, double output_torque_Nmm,
                                                         std::string* why = nullptr);

/// A rolling bearing's ratings: C [N] (> 0), C0 [N] (0 when not given), ball or roller.
struct RollingBearingRating {
  BearingKind kind = BearingKind::kRoller;
  double dynamic_N = 0.0, static_N = 0.0;
};

/// Reads "dynamic_rating_N" > 0 and "static_rating_N" > 0 (optional) from `node`, which may hold
/// other fields (an LCR's reducer side); a missing C is an error that says why it is needed.
/// @throws StudyError naming the JSON path.
RollingBearingRating ParseRatingValues(const Node& node, BearingKind kind, const std::string& why);

/// Reads {"dynamic_rating_N" > 0, "static_rating_N" > 0 (optional)} and, when `with_kind`, "kind":
/// "ball" | "roller" (else `kind`). A missing C is an error that says why it is needed (`why`).
/// @throws StudyError naming the JSON path.
RollingBearingRating ParseBearingRating(const Node& node, bool with_kind, BearingKind kind, const std::string& why);

/// The duty cycle's echo: [{output_torque_Nm, input_speed_rpm, time_share}, …].
nlohmann::json DutyCycleJson(const std::vector<OperatingLine>& lines);

/// One row of a life table (docs/life.md): element, kind, equivalent_load_N, max_load_N,
/// revolutions_per_input_revolution, dynamic_rating_N, L10h (null when infinite), static_rating_N
/// and s0 = C0/P0max when C0 is given, pass against `life_h` (null when no limit, life_h <= 0).
nlohmann::json LifeTableRow(const std::string& element, bool ball, double equivalent_load_N, double max_load_N,
                            double revolutions_per_input_revolution, double dynamic_rating_N,
                            double static_rating_N, double s0, double L10h, double life_h);

}  // namespace camopt::studies
