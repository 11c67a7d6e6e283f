// The cycloid_ltca fields a tuning or sizing variable may set, in one place: how a variable's value
// (in its own unit: µm for the modifications, mm otherwise) sets the drive or crowning, and the
// LoadedTca::Differentiate parameter it moves with the factor from its unit to mm.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "model/cycloid/crowning.h"
#include "model/cycloid/loaded_tca.h"
#include "model/cycloid/tooth_profile.h"

namespace camopt::objectives {

/// Sets the field `name` of the drive or crowning to value (µm for delta_*_um). Returns false for
/// a name that is not a field.
inline bool SetCycloidField(const std::string& name, double value, cycloid::Drive& d, cycloid::Crowning& c) {
  if (name == "eccentricity_mm") d.eccentricity_mm = value;
  else if (name == "roller_position_radius_mm") d.roller_position_radius_mm = value;
  else if (name == "roller_radius_mm") d.roller_radius_mm = value;
  else if (name == "face_width_mm") d.face_width_mm = value;
  else if (name == "delta_position_um") d.delta_position_mm = value * 1e-3;
  else if (name == "delta_radius_um") d.delta_radius_mm = value * 1e-3;
  else if (name == "coefficient_mm") c.coefficient_mm = value;
  else if (name == "effective_length_mm") c.effective_length_mm = value;
  else if (name == "end_drop_mm") c.end_drop_mm = value;
  else if (name == "flat_length_mm") c.flat_length_mm = value;
  else if (name == "radius_mm") c.radius_mm = value;
  else return false;
  return true;
}

/// A variable's model parameter (LoadedTca::Differentiate) and the factor from its unit to mm.
inline std::pair<std::string, double> CycloidModelParameter(const std::string& name) {
  if (name == "delta_position_um") return {"delta_position_mm", 1e-3};
  if (name == "delta_radius_um") return {"delta_radius_mm", 1e-3};
  return {name, 1.0};
}

/// Whether the crowning parameter `name` (coefficient_mm, effective_length_mm, end_drop_mm,
/// flat_length_mm, radius_mm) shapes a crowning of `type`: "" where it does, else why not;
/// nullopt for a name that is no crowning parameter (model/cycloid/crowning.h: the logarithmic
/// profile's c, L_e, end drop and flat; the full and partial arcs' radius, the partial's flat).
inline std::optional<std::string> CrowningParameterApplies(const std::string& name, cycloid::CrowningType type) {
  using cycloid::CrowningType;
  const bool log = type == CrowningType::kLogarithmic;
  if (name == "coefficient_mm" || name == "effective_length_mm" || name == "end_drop_mm")
    return log ? "" : "a parameter of the logarithmic crowning only";
  if (name == "flat_length_mm")
    return log || type == CrowningType::kPartial ? "" : "a parameter of the logarithmic or partial crowning only";
  if (name == "radius_mm")
    return type == CrowningType::kFull || type == CrowningType::kPartial
               ? ""
               : "a parameter of the full or partial crowning only";
  return std::nullopt;
}

/// The implicit derivatives' CG tolerance: the contact solver's own (the values are no more
/// accurate than that), between 1e-10 and 1e-4. At 1e-4 the 60-angle cycle's gradient (f, Δa, Δρ)
/// costs 1.67× the value, at 1e-6 2.3× (docs/performance.md, "Cycloid drive").
inline double CycloidSensitivityTolerance(const cycloid::LoadedOptions& o) {
  return std::clamp(o.solver_tolerance, 1e-10, 1e-4);
}

}  // namespace camopt::objectives
