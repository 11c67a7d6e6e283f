// Parsing and reporting of the LCR tolerance fields (studies/lcr_tolerance_input.h).
#include "studies/lcr_tolerance_input.h"

#include <initializer_list>
#include <iterator>
#include <utility>
#include <vector>

#include "studies/study.h"

namespace camopt::studies {

std::optional<LcrToleranceSpec> ToToleranceSpec(const std::optional<LcrTolerancesInput>& tolerances,
                                                const std::optional<LcrMonteCarloInput>& monte_carlo,
                                                const Node& root) {
  if (!tolerances) {
    if (monte_carlo || root.Has("monte_carlo")) root["monte_carlo"].Fail("no \"monte_carlo\" without \"tolerances\"");
    return std::nullopt;
  }
  // The file's units to the model's: µm to mm, arcsec to rad.
  const LcrTolerancesInput& t = *tolerances;
  LcrToleranceSpec s;
  s.bands.eccentricity_mm = t.eccentricity_um.value_or(0.0) * 1e-3;
  s.bands.turret_radius_mm = t.turret_radius_um.value_or(0.0) * 1e-3;
  s.bands.roller_diameter_mm = t.roller_diameter_um.value_or(0.0) * 1e-3;
  s.bands.roller_pitch_rad = t.roller_pitch_arcsec.value_or(0.0) * kPi / (180.0 * 3600.0);
  s.bands.profile_mm = t.profile_um.value_or(0.0) * 1e-3;
  s.bands.bearing_clearance_mm = t.bearing_clearance_um.value_or(0.0) * 1e-3;
  if (monte_carlo) {
    s.samples = monte_carlo->samples.value_or(0);
    s.seed = std::uint64_t(monte_carlo->seed.value_or(1));
    s.angle_steps = monte_carlo->angle_steps.value_or(72);
    s.lost_motion_torque_fraction = monte_carlo->lost_motion_torque_fraction.value_or(0.03);
  }
  return s;
}

std::string LoadModelName(lcr::LoadModel m) { return m == lcr::LoadModel::kRigid ? "rigid" : "compliant"; }

nlohmann::json TransmissionErrorJson(const LcrToleranceSpec& spec, const lcr::TransmissionErrorResult& te) {
  nlohmann::json j;
  j["model"] = "compliant contacts (Palmgren) with exact per-roller gaps; TE = output angle minus the "
               "nominal reducer's at the same input angle and torque";
  j["angle_steps"] = spec.angle_steps;
  // Fields of the result under their own names.
  using Member = std::pair<const char*, double lcr::TransmissionErrorResult::*>;
  using R = lcr::TransmissionErrorResult;
  auto copy = [&](std::initializer_list<Member> fields) {
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
