// Parsing and reporting of the LCR tolerance fields (studies/lcr_tolerance_input.h).
#include "studies/lcr_tolerance_input.h"

#include <initializer_list>
#include <iterator>
#include <utility>
#include <vector>

#include "studies/study.h"

namespace camopt::studies {

std::optional<LcrToleranceSpec> ParseLcrTolerances(const Node& root) {
  if (!root.Has("tolerances")) {
    if (root.Has("monte_carlo")) root["monte_carlo"].Fail("no \"monte_carlo\" without \"tolerances\"");
    return std::nullopt;
  }
  const Node t = root["tolerances"];
  // One row per band, in lcr::ToleranceKeys() order: the field it sets, the conversion of the
  // file's unit to the model's (value · scale / divisor), and the largest band accepted. A
  // tolerance of a micrometre's size against parts of tens of millimetres: above 1 mm the
  // small-deviation geometry (foot points found from the nominal ones) is not meant to hold.
  struct Band {
    double lcr::ToleranceBands::*field;
    double scale, divisor, max;
    const char* max_text;
  };
  constexpr const char* kMaxUm = "a band of at most 1000 µm";
  const Band bands[] = {{&lcr::ToleranceBands::eccentricity_mm, 1e-3, 1.0, 1000.0, kMaxUm},
                        {&lcr::ToleranceBands::turret_radius_mm, 1e-3, 1.0, 1000.0, kMaxUm},
                        {&lcr::ToleranceBands::roller_diameter_mm, 1e-3, 1.0, 1000.0, kMaxUm},
                        {&lcr::ToleranceBands::roller_pitch_rad, kPi, 180.0 * 3600.0, 3600.0,
                         "a band of at most 3600 arcsec"},
                        {&lcr::ToleranceBands::profile_mm, 1e-3, 1.0, 1000.0, kMaxUm},
                        {&lcr::ToleranceBands::bearing_clearance_mm, 1e-3, 1.0, 1000.0, kMaxUm}};
  const std::vector<std::string>& keys = lcr::ToleranceKeys();
  t.CheckKnownFields({keys.begin(), keys.end()});
  LcrToleranceSpec s;
  for (size_t i = 0; i < std::size(bands); ++i)
    s.bands.*bands[i].field = t.NonNegativeOr(keys[i], 0.0) * bands[i].scale / bands[i].divisor;
  for (size_t i = 0; i < std::size(bands); ++i)
    if (t.Has(keys[i]) && t[keys[i]].Number() > bands[i].max) t[keys[i]].Fail(bands[i].max_text);
  if (root.Has("monte_carlo")) {
    const Node m = root["monte_carlo"];
    m.CheckKnownFields({"samples", "seed", "angle_steps", "lost_motion_torque_fraction"});
    s.samples = m.IntegerOr("samples", 0, 0);
    if (s.samples > 100000) m["samples"].Fail("at most 100000 samples");
    s.seed = std::uint64_t(m.IntegerOr("seed", 0, 1));
    s.angle_steps = m.IntegerOr("angle_steps", 4, 72);
    if (s.angle_steps > 3600) m["angle_steps"].Fail("at most 3600 angle steps");
    if (m.Has("lost_motion_torque_fraction"))
      s.lost_motion_torque_fraction = m["lost_motion_torque_fraction"].NumberIn(0.0, 1.0);
  }
  return s;
}

lcr::LoadModel ParseLoadModel(const Node& analysis) {
  if (!analysis.Has("load_model")) return lcr::LoadModel::kRigid;
  const std::string m = analysis["load_model"].String();
  if (m == "rigid") return lcr::LoadModel::kRigid;
  if (m == "compliant") return lcr::LoadModel::kCompliant;
  analysis["load_model"].Fail("\"rigid\" or \"compliant\"");
  return lcr::LoadModel::kRigid;
}

std::string LoadModelName(lcr::LoadModel m) { return m == lcr::LoadModel::kRigid ? "rigid" : "compliant"; }

nlohmann::json TransmissionErrorJson(const LcrToleranceSpec& spec, const lcr::TransmissionErrorResult& te) {
  nlohmann::json j;
  j["model"] = "compliant contacts (Palmgren) with exact per-roller gaps; TE = output angle minus the "
               "nominal reducer's at the same input angle and torque";
  j["angle_steps"] = spec.angle_steps;
  // Fields of the result under their own names.
  using Field = std::pair<const char*, double lcr::TransmissionErrorResult::*>;
  using R = lcr::TransmissionErrorResult;
  auto copy = [&](std::initializer_list<Field> fields) {
    for (const auto& [key, field] : fields) j[key] = te.*field;
  };
  copy({{"linear_worst_case_arcsec", &R::linear_worst_case_arcsec},
        {"linear_worst_case_abs_arcsec", &R::linear_worst_case_abs_arcsec},
        {"linear_rms_arcsec", &R::linear_rms_arcsec},
        {"lost_motion_arcmin", &R::lost_motion_arcmin},
        {"lost_motion_p99_arcmin", &R::lost_motion_p99_arcmin},
        {"lost_motion_nominal_arcmin", &R::lost_motion_nominal_arcmin}});
  j["monte_carlo_samples"] = te.samples;
  j["monte_carlo_seed"] = spec.seed;
  if (te.samples > 0) {
    copy({{"monte_carlo_max_arcsec", &R::monte_carlo_max_arcsec},
          {"monte_carlo_p99_arcsec", &R::monte_carlo_p99_arcsec},
          {"monte_carlo_rms_arcsec", &R::monte_carlo_rms_arcsec},
          {"monte_carlo_max_abs_arcsec", &R::monte_carlo_max_abs_arcsec},
          {"linear_vs_exact_max_error", &R::linear_vs_exact_max_error}});
  } else {
    for (const char* k : {"monte_carlo_max_arcsec", "monte_carlo_p99_arcsec", "monte_carlo_rms_arcsec"}) j[k] = nullptr;
  }
  j["peak_to_peak"] = "linear_worst_case_arcsec, monte_carlo_max_arcsec and monte_carlo_p99_arcsec are "
                      "peak-to-peak over the input revolution";
  j["lost_motion_torque_fraction"] = spec.lost_motion_torque_fraction;
  nlohmann::json c = nlohmann::json::object();
  for (const auto& k : te.contributions)
    c[k.key] = {{"worst_case_arcsec", k.worst_case_arcsec}, {"rms_arcsec", k.rms_arcsec}, {"variance_share", k.variance_share}};
  j["contributions"] = c;
  return j;
}

}  // namespace camopt::studies
