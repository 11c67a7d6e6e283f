// The catalogue numbers of a cycloid drive (docs/ratings.md), as cycloid_ltca reports them: rated
// torque for a rated life at a rated output speed, peak torque from the contact limits, momentary
// torque from the bearings' static capacity, the parts' masses and the inertia reflected to the
// output. Every torque is solved with the LTCA at that torque (the load sharing changes with the
// torque), never scaled.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "model/cycloid/loaded_tca.h"
#include "model/cycloid/output_mechanism.h"
#include "studies/cycloid_life.h"
#include "studies/ratings_input.h"

namespace camopt::studies::cycloid_common {

/// The limits the peak torque is read from (the study's "limits"); absent: not a limit.
struct PeakLimits {
  std::optional<double> contact_stress_MPa, pair_load_N;
};

/// One torque's answers, from one LTCA cycle over the study's crank angles.
struct TorquePoint {
  double torque_Nm = 0;
  double shortest_L10h = 0;       ///< at the rated output speed
  std::string shortest;           ///< the element with it
  double max_contact_stress_MPa = 0, max_pair_load_N = 0;
  double crank_bearing_max_load_N = 0, pins_max_load_N = 0;  ///< for s0 (0: pins not rated)
};

struct RatingsResult {
  double rated_torque_Nm = 0;
  std::string rated_by;            ///< the bearing whose L10 is the rated life at it
  double rated_L10h = 0;           ///< the shortest L10 recomputed at rated_torque_Nm
  std::optional<double> peak_torque_Nm;
  std::string peak_by, peak_note;
  std::optional<double> momentary_torque_Nm;
  std::string momentary_by, momentary_note;
  std::optional<double> momentary_peaks_allowed;
  int ltca_cycles = 0;
  /// Discretisation errors of the three torques (set by the study when it estimates errors).
  std::optional<double> rated_error_Nm, peak_error_Nm, momentary_error_Nm;
  bool error_crank_estimated = false;
};

/// Solves the ratings of a one-disc drive: `life` the study's ratings of the crank bearing (and
/// pins), `ratio` input turns per output turn, `angles` the study's crank angles (whole mesh
/// periods), `start_torque_Nm` where the searches start (the study's load). `progress` gets the
/// LTCA cycles done.
/// @throws std::invalid_argument when a rating has no torque that reaches it (the message says why).
RatingsResult SolveRatings(const RatingsInput& in, const PeakLimits& limits, const LifeSpec& life,
                           const cycloid::LoadedTca& tca, const std::vector<double>& angles, double ratio,
                           double start_torque_Nm, const std::function<void(const std::string&)>& progress = nullptr);

/// Masses and inertias from the geometry: volume × density of each part modelled.
struct PartMasses {
  double disc_kg = 0, disc_inertia_kgm2 = 0;  ///< one disc, about its own centre
  double ring_pins_kg = 0, output_pins_kg = 0, total_kg = 0;
  double reflected_inertia_kgm2 = 0;          ///< at the output: N (m e² i² + J_d)
  double outer_diameter_mm = 0, width_mm = 0;
  std::string includes;                       ///< what the masses and the inertia are of
};

/// `profile` the disc's closed profile [mm] (counter-clockwise or not), `bore_mm` its bore diameter
/// (0: none), `output` the output pins and holes (nullptr: no holes), `pin_length_mm` the ring pins'
/// length (the discs' stack).
PartMasses CycloidMasses(const cycloid::Drive& d, const std::vector<Vec2<double>>& profile, int discs,
                         double stack_width_mm, double bore_mm, const cycloid::OutputPins* output,
                         double output_pin_length_mm, double density_kg_m3);

}  // namespace camopt::studies::cycloid_common
