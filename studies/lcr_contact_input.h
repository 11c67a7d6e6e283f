// Parsing the finite-length contact of the LCR (docs/lcr.md, "Crowned rollers and 3D contact"): the top-level "contact" object
// {model: line | slices | half_space, slices: N, grid: [nx, ny], misalignment_mrad: γ} and the
// per-side roller "crowning" objects under reducer.input / reducer.output. Shared by lcr_analysis
// (and the sizing kinds later).
#pragma once

#include <array>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "model/lcr/contact3d.h"
#include "studies/archive.h"
#include "studies/input.h"

namespace camopt::studies {

/// A roller's "crowning" as the study file gives it, declared once (studies/archive.h): the axial
/// profile of the roller (docs/lcr.md, "Crowned rollers and 3D contact"). Each type takes its own
/// fields only; ParseRollerCrowning checks them against the type and the roller length.
struct LcrCrowningInput {
  std::string type;
  std::optional<double> radius_mm, flat_length_mm, coefficient_mm, effective_length_mm;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("type", &type,
             Field().Required().OneOf({"none", "circular", "partial", "logarithmic"},
                                      "one of none, circular, partial, logarithmic")
                 .Desc("none; circular (one arc over the roller); partial (a flat middle and circular ends); "
                       "logarithmic (Lundberg's profile)"));
    a->Visit("radius_mm", &radius_mm,
             Field().Positive().Unit("mm").Desc("circular, partial: the crown radius R_c"));
    a->Visit("flat_length_mm", &flat_length_mm,
             Field().NonNegative().Unit("mm").Desc("partial: the straight middle's length L_f, below the roller length"));
    a->Visit("coefficient_mm", &coefficient_mm,
             Field().NonNegative().Unit("mm").Desc("logarithmic: the coefficient of Lundberg's drop"));
    a->Visit("effective_length_mm", &effective_length_mm,
             Field().Positive().Unit("mm").Desc("logarithmic: the effective length L_e, longer than the roller"));
  }
  /// Each type's fields required, the fields of the other types refused.
  static nlohmann::ordered_json SchemaRules();
};

/// The crowning of rollers that are sized (lcr_min_size's fixed.crowning): as LcrCrowningInput, but a
/// logarithmic crown's coefficient_mm may be left out (a sizing variable then).
struct LcrSizedCrowningInput : LcrCrowningInput {
  /// Each type's fields required (a logarithmic crown's effective length only), the fields of the
  /// other types refused.
  static nlohmann::ordered_json SchemaRules();
};

/// "grid" of the half_space model (contact, tuning): [nx, ny] cells, at least 8 each way, at most
/// [256, 1024].
inline Field GridField() {
  return Field().Expect("[nx, ny]").AtLeast(8).ItemsAtMost({256, 1024}, "a grid of at most [256, 1024]")
      .Desc("[nx, ny] cells of the half-space grid (across rolling, along the roller), at least 8 each way, at most "
            "[256, 1024]");
}

/// The "contact" object: the finite-length roller contact model (docs/lcr.md, "Crowned rollers and
/// 3D contact"), declared once. ToContactOptions converts it (misalignment needs a model other than
/// line).
struct LcrContactOptionsInput {
  /// Absent: line, unless the study's crowning or misalignment asks for another (no schema default).
  std::optional<std::string> model;
  int slices = lcr::ContactModelOptions{}.slices;
  std::array<int, 2> grid{lcr::ContactModelOptions{}.grid_nx, lcr::ContactModelOptions{}.grid_ny};  ///< [nx, ny]
  double misalignment_mrad = 0.0;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("model", &model,
             Field().OneOf({"line", "slices", "half_space"}, "one of line, slices, half_space")
                 .Desc("line: Hertz line contact, ignores crowning and misalignment (absent: line); slices: the "
                       "roller as independent slices; half_space: the elastic half-space on a grid (docs/lcr.md)"));
    a->Visit("slices", &slices,
             Field().AtLeast(4).AtMost(200, "at most 200 slices")
                 .Desc("slices along the roller; at least 4 so that the pressure along the roller is resolved "
                       "(docs/lcr.md)"));
    a->Visit("grid", &grid, GridField());
    a->Visit("misalignment_mrad", &misalignment_mrad,
             Field().In(-50.0, 50.0, "a misalignment within ±50 mrad").Unit("mrad")
                 .Desc("γ, the tilt of the roller axis against the cam axis (slices or half_space only)"));
  }
};

struct LcrContactInput {
  bool given = false;  // the study has a "contact" object
  lcr::ContactModelOptions options;
  lcr::RollerCrowning<double> input_crowning, output_crowning;
};

/// One roller "crowning" object, checked against the roller length. coefficient_given = false:
/// a logarithmic crown's coefficient_mm may be absent (a sizing variable), 0 then.
lcr::RollerCrowning<double> ParseRollerCrowning(const Node& n, double roller_length, bool coefficient_given = true);

/// A roller crowning as its "crowning" object declares it: the type and that type's fields
/// (ParseRollerCrowning reads it back), for result.json and the study files a sizing writes.
LcrCrowningInput CrowningInputOf(const lcr::RollerCrowning<double>& c);

/// The "contact" object read as declared (the checks between its fields follow).
lcr::ContactModelOptions ToContactOptions(const LcrContactOptionsInput& in, const Node& contact);

/// "line", "slices" or "half_space".
const char* ContactModelName(lcr::ContactModel m);

}  // namespace camopt::studies
