// Parsing and reporting of the LCR tolerance fields (studies/lcr_tolerance_input.h).
#include "studies/lcr_tolerance_input.h"

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

LcrTransmissionErrorBlock TransmissionErrorBlockOf(const LcrToleranceSpec& spec, const lcr::TransmissionErrorResult& te) {
  LcrTransmissionErrorBlock j;
  j.SetStatistics(te, spec.seed);
  j.model = "compliant contacts (Palmgren) with exact per-roller gaps; TE = output angle minus the "
            "nominal reducer's at the same input angle and torque";
  j.angle_steps = spec.angle_steps;
  j.lost_motion_arcmin = te.lost_motion_arcmin;
  j.lost_motion_p99_arcmin = te.lost_motion_p99_arcmin;
  j.lost_motion_nominal_arcmin = te.lost_motion_nominal_arcmin;
  j.peak_to_peak = "linear_worst_case_arcsec, monte_carlo_max_arcsec and monte_carlo_p99_arcsec are "
                   "peak-to-peak over the input revolution";
  j.lost_motion_torque_fraction = spec.lost_motion_torque_fraction;
  return j;
}

}  // namespace camopt::studies
