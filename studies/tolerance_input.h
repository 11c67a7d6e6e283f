// What the reducers' tolerance analyses share in the study files (docs/lcr.md and docs/cycloid.md,
// transmission error): the declaration of a tolerance band and of the Monte-Carlo's samples and
// seed, and the statistics' part of the "transmission_error" object of result.json
// (model/common/tolerance_stats.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "model/common/tolerance_stats.h"
#include "studies/archive.h"

namespace camopt::studies {

/// A ± band in µm: optional (absent: 0), at most 1 mm (the small-deviation geometry).
inline Field ToleranceBandField(const std::string& what) {
  return Field().NonNegative().AtMost(1000.0, "a band of at most 1000 µm").Unit("µm").Desc(what + " (absent: 0)");
}

/// An angular ± band in arcsec: optional (absent: 0), at most a degree.
inline Field ToleranceArcsecBandField(const std::string& what) {
  return Field().NonNegative().AtMost(3600.0, "a band of at most 3600 arcsec").Unit("arcsec").Desc(what + " (absent: 0)");
}

/// "monte_carlo.samples" and "monte_carlo.seed", declared once for every kind with tolerances.
template <typename Archive>
void VisitMonteCarloSamples(Archive* a, std::optional<int>* samples, std::optional<int>* seed) {
  a->Visit("samples", samples,
           Field().AtLeast(0).AtMost(100000, "at most 100000 samples")
               .Desc("Monte-Carlo samples of the exact model (absent: 0, the linear estimate only)"));
  a->Visit("seed", seed, Field().AtLeast(0).Desc("seed of the samples (absent: 1)"));
}

/// The statistics' keys of "transmission_error": the linear worst case, largest |TE| and RMS, the
/// Monte-Carlo's samples, seed, maximum and 99th percentile of the peak-to-peak, RMS, largest |TE|
/// and the linear model's largest error (null without samples), and the contributions per key.
nlohmann::json ToleranceStatisticsJson(const tolerance::Statistics& te, std::uint64_t seed);

}  // namespace camopt::studies
