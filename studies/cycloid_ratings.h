// The catalogue numbers of a cycloid drive (docs/ratings.md), as cycloid_ltca reports them: the
// model the ratings are solved on (studies/ratings.h) — an LTCA cycle at each trial torque, as the
// load sharing changes with the torque — and the parts' masses and the inertia reflected to the
// output.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "model/cycloid/loaded_tca.h"
#include "model/cycloid/output_mechanism.h"
#include "studies/cycloid_life.h"
#include "studies/ratings.h"

namespace camopt::studies::cycloid_common {

/// The ratings' model at output torque `torque_Nm` (studies/ratings.h): one LTCA cycle over
/// `angles` (whole mesh periods) and the rated bearings' lives at the rated output speed (`ratio`
/// input turns per output turn) over it; `life` the study's rated elements (its lines unused).
/// @throws std::invalid_argument when the LTCA does not converge at that torque.
RatingPoint CycloidRatingPoint(const RatingsInput& in, const LifeSpec& life, const cycloid::LoadedTca& tca,
                               const std::vector<double>& angles, double ratio, double torque_Nm);

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
