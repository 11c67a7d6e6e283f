// The tolerance parts of the LCR study kinds (docs/lcr.md, transmission error): "tolerances" and
// "monte_carlo" declared once, and the "transmission_error" block of result.json; shared by
// lcr_analysis and lcr_min_size.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "model/lcr/transmission_error.h"
#include "studies/archive.h"
#include "studies/input.h"
#include "studies/tolerance_input.h"

namespace camopt::studies {

/// "tolerances": ± bands of the manufacturing errors, declared once (studies/archive.h). Each band is
/// optional (absent: 0, no schema default: an absent block means no transmission error at all).
/// Above 1 mm (1 degree of pitch) the small-deviation geometry is not meant to hold.
struct LcrTolerancesInput {
  std::optional<double> eccentricity_um, turret_radius_um, roller_diameter_um, roller_pitch_arcsec, profile_um,
      bearing_clearance_um;
  template <typename Archive>
  void Serialize(Archive* a) {
    const auto band = [](const char* what) { return ToleranceBandField(what); };
    a->Visit("eccentricity_um", &eccentricity_um, band("± band of the eccentricity e"));
    a->Visit("turret_radius_um", &turret_radius_um, band("± band of each roller's turret radius r_d"));
    a->Visit("roller_diameter_um", &roller_diameter_um, band("± band of each roller's diameter d_r"));
    a->Visit("roller_pitch_arcsec", &roller_pitch_arcsec,
             ToleranceArcsecBandField("± band of each roller's angular position on the turret"));
    a->Visit("profile_um", &profile_um, band("± band of the cam profile's normal deviation"));
    a->Visit("bearing_clearance_um", &bearing_clearance_um,
             band("radial clearance of the bearings, 0 … c"));
  }
};

/// "monte_carlo" (with "tolerances" only): the exact model's Monte-Carlo over the bands. Each field
/// optional with the default in its description (no schema default: the block needs "tolerances").
struct LcrMonteCarloInput {
  std::optional<int> samples, seed, angle_steps;
  std::optional<double> lost_motion_torque_fraction;
  template <typename Archive>
  void Serialize(Archive* a) {
    VisitMonteCarloSamples(a, &samples, &seed);
    a->Visit("angle_steps", &angle_steps,
             Field().AtLeast(4).AtMost(3600, "at most 3600 angle steps")
                 .Desc("input angles of the transmission error over a revolution (absent: 72)"));
    a->Visit("lost_motion_torque_fraction", &lost_motion_torque_fraction,
             Field().In(0.0, 1.0).Desc("the torque ± f T_o of the lost motion, a fraction of the output torque "
                                       "(absent: 0.03)"));
  }
};

struct LcrToleranceSpec {
  lcr::ToleranceBands bands;
  int samples = 0;              ///< "monte_carlo.samples" (0: linear only)
  std::uint64_t seed = 1;       ///< "monte_carlo.seed"
  int angle_steps = 72;         ///< "monte_carlo.angle_steps": angles of the transmission error
  double lost_motion_torque_fraction = 0.03;  ///< "monte_carlo.lost_motion_torque_fraction" of T_o
};

/// The tolerance spec from the declared blocks (tolerances absent: none; "monte_carlo" without
/// "tolerances" is a StudyError naming the path).
std::optional<LcrToleranceSpec> ToToleranceSpec(const std::optional<LcrTolerancesInput>& tolerances,
                                                const std::optional<LcrMonteCarloInput>& monte_carlo, const Node& root);

std::string LoadModelName(lcr::LoadModel m);

/// The "transmission_error" object of result.json: the shared statistics and the lost motion.
struct LcrTransmissionErrorBlock : ToleranceStatisticsBlock {
  std::string model, peak_to_peak;
  int angle_steps = 0;
  double lost_motion_arcmin = 0, lost_motion_p99_arcmin = 0, lost_motion_nominal_arcmin = 0;
  double lost_motion_torque_fraction = 0;
  template <typename Archive>
  void Serialize(Archive* a) {
    ToleranceStatisticsBlock::Serialize(a);
    const Field n = Field().NullWhenNotFinite();
    a->Visit("model", &model, Field());
    a->Visit("angle_steps", &angle_steps, Field().Desc("input angles over one input revolution"));
    a->Visit("lost_motion_arcmin", &lost_motion_arcmin,
             Field(n).Unit("arcmin").Desc("the samples' largest (without samples: the nominal's)"));
    a->Visit("lost_motion_p99_arcmin", &lost_motion_p99_arcmin, Field(n).Unit("arcmin").Desc("their 99th percentile"));
    a->Visit("lost_motion_nominal_arcmin", &lost_motion_nominal_arcmin, Field(n).Unit("arcmin"));
    a->Visit("peak_to_peak", &peak_to_peak, Field().Desc("what the peak-to-peak keys span"));
    a->Visit("lost_motion_torque_fraction", &lost_motion_torque_fraction,
             Field().Desc("± this share of the output torque measures the lost motion"));
  }
};
LcrTransmissionErrorBlock TransmissionErrorBlockOf(const LcrToleranceSpec& spec, const lcr::TransmissionErrorResult& te);

}  // namespace camopt::studies
