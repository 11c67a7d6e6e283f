// Parsing and reporting of the LCR tolerance fields (studies/lcr_tolerance_input.h).
#include "studies/lcr_tolerance_input.h"

#include "studies/study.h"

namespace camopt::studies {

std::optional<LcrToleranceSpec> ParseLcrTolerances(const Node& root) {
  if (!root.Has("tolerances")) {
    if (root.Has("monte_carlo")) root["monte_carlo"].Fail("no \"monte_carlo\" without \"tolerances\"");
    return std::nullopt;
  }
  const Node t = root["tolerances"];
  t.CheckKnownFields({"eccentricity_um", "turret_radius_um", "roller_diameter_um", "roller_pitch_arcsec",
                      "profile_um", "bearing_clearance_um"});
  LcrToleranceSpec s;
  s.bands.eccentricity_mm = t.NonNegativeOr("eccentricity_um", 0.0) * 1e-3;
  s.bands.turret_radius_mm = t.NonNegativeOr("turret_radius_um", 0.0) * 1e-3;
  s.bands.roller_diameter_mm = t.NonNegativeOr("roller_diameter_um", 0.0) * 1e-3;
  s.bands.roller_pitch_rad = t.NonNegativeOr("roller_pitch_arcsec", 0.0) * kPi / (180.0 * 3600.0);
  s.bands.profile_mm = t.NonNegativeOr("profile_um", 0.0) * 1e-3;
  s.bands.bearing_clearance_mm = t.NonNegativeOr("bearing_clearance_um", 0.0) * 1e-3;
  // A tolerance of a micrometre's size against parts of tens of millimetres: above 1 mm the
  // small-deviation geometry (foot points found from the nominal ones) is not meant to hold.
  for (const char* key : {"eccentricity_um", "turret_radius_um", "roller_diameter_um", "profile_um",
                          "bearing_clearance_um"})
    if (t.Has(key) && t[key].Number() > 1000.0) t[key].Fail("a band of at most 1000 µm");
  if (t.Has("roller_pitch_arcsec") && t["roller_pitch_arcsec"].Number() > 3600.0)
    t["roller_pitch_arcsec"].Fail("a band of at most 3600 arcsec");
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
  j["linear_worst_case_arcsec"] = te.linear_worst_case_arcsec;
  j["linear_worst_case_abs_arcsec"] = te.linear_worst_case_abs_arcsec;
  j["linear_rms_arcsec"] = te.linear_rms_arcsec;
  j["monte_carlo_samples"] = te.samples;
  j["monte_carlo_seed"] = spec.seed;
  if (te.samples > 0) {
    j["monte_carlo_max_arcsec"] = te.monte_carlo_max_arcsec;
    j["monte_carlo_p99_arcsec"] = te.monte_carlo_p99_arcsec;
    j["monte_carlo_rms_arcsec"] = te.monte_carlo_rms_arcsec;
    j["monte_carlo_max_abs_arcsec"] = te.monte_carlo_max_abs_arcsec;
    j["linear_vs_exact_max_error"] = te.linear_vs_exact_max_error;
  } else {
    for (const char* k : {"monte_carlo_max_arcsec", "monte_carlo_p99_arcsec", "monte_carlo_rms_arcsec"}) j[k] = nullptr;
  }
  j["peak_to_peak"] = "linear_worst_case_arcsec, monte_carlo_max_arcsec and monte_carlo_p99_arcsec are "
                      "peak-to-peak over the input revolution";
  j["lost_motion_torque_fraction"] = spec.lost_motion_torque_fraction;
  j["lost_motion_arcmin"] = te.lost_motion_arcmin;
  j["lost_motion_p99_arcmin"] = te.lost_motion_p99_arcmin;
  j["lost_motion_nominal_arcmin"] = te.lost_motion_nominal_arcmin;
  nlohmann::json c = nlohmann::json::object();
  for (const auto& k : te.contributions)
    c[k.key] = {{"worst_case_arcsec", k.worst_case_arcsec}, {"rms_arcsec", k.rms_arcsec}, {"variance_share", k.variance_share}};
  j["contributions"] = c;
  return j;
}

}  // namespace camopt::studies
