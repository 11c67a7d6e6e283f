// What the reducers' tolerance analyses share in the study files (docs/lcr.md and docs/cycloid.md,
// transmission error): the declaration of a tolerance band and of the Monte-Carlo's samples and
// seed, and the statistics' part of the "transmission_error" object of result.json
// (model/common/tolerance_stats.h).
#pragma once

#include <cstdint>
#include <map>
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

/// The statistics' keys of result.json's "transmission_error", the same for every reducer: the
/// linear worst case, largest |TE| and RMS, the Monte-Carlo's samples, seed, maximum and 99th
/// percentile of the peak-to-peak, RMS (null without samples), largest |TE| and the linear model's
/// largest error (absent without samples), and the contributions per tolerance key. A reducer's
/// block derives from it and adds its own keys after ToleranceStatisticsBlock::Serialize.
struct ToleranceStatisticsBlock {
  struct Contribution {
    double worst_case_arcsec = 0, rms_arcsec = 0, variance_share = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      const Field n = Field().NullWhenNotFinite();
      a->Visit("worst_case_arcsec", &worst_case_arcsec, Field(n).Unit("arcsec").Desc("its part of the linear worst case"));
      a->Visit("rms_arcsec", &rms_arcsec, Field(n).Unit("arcsec").Desc("its part of the linear RMS"));
      a->Visit("variance_share", &variance_share, Field(n).Desc("its share of the linear variance"));
    }
  };
  double linear_worst_case_arcsec = 0, linear_worst_case_abs_arcsec = 0, linear_rms_arcsec = 0;
  int monte_carlo_samples = 0;
  std::uint64_t monte_carlo_seed = 1;
  std::optional<double> monte_carlo_max_arcsec, monte_carlo_p99_arcsec, monte_carlo_rms_arcsec,
      monte_carlo_max_abs_arcsec, linear_vs_exact_max_error;
  std::map<std::string, Contribution> contributions;

  /// The keys from the analysis' statistics and the samples' seed.
  void SetStatistics(const tolerance::Statistics& te, std::uint64_t seed);
  template <typename Archive>
  void Serialize(Archive* a) {
    const Field n = Field().NullWhenNotFinite();
    const Field sampled = Field().NullWhenAbsent().NullWhenNotFinite();
    a->Visit("linear_worst_case_arcsec", &linear_worst_case_arcsec,
             Field(n).Unit("arcsec").Desc("the linear model's worst peak-to-peak over the tolerance box"));
    a->Visit("linear_worst_case_abs_arcsec", &linear_worst_case_abs_arcsec,
             Field(n).Unit("arcsec").Desc("the linear model's worst |TE| over the box"));
    a->Visit("linear_rms_arcsec", &linear_rms_arcsec, Field(n).Unit("arcsec").Desc("over the angles and the bands"));
    a->Visit("monte_carlo_samples", &monte_carlo_samples, Field());
    a->Visit("monte_carlo_seed", &monte_carlo_seed, Field());
    a->Visit("monte_carlo_max_arcsec", &monte_carlo_max_arcsec,
             Field(sampled).Unit("arcsec").Desc("the samples' largest peak-to-peak (null: no samples)"));
    a->Visit("monte_carlo_p99_arcsec", &monte_carlo_p99_arcsec,
             Field(sampled).Unit("arcsec").Desc("their 99th percentile (null: no samples)"));
    a->Visit("monte_carlo_rms_arcsec", &monte_carlo_rms_arcsec,
             Field(sampled).Unit("arcsec").Desc("the samples' RMS TE (null: no samples)"));
    a->Visit("monte_carlo_max_abs_arcsec", &monte_carlo_max_abs_arcsec,
             Field(n).Unit("arcsec").Desc("with samples: their largest |TE|"));
    a->Visit("linear_vs_exact_max_error", &linear_vs_exact_max_error,
             Field(n).Desc("with samples: the linear model's largest error over the largest peak-to-peak"));
    a->Visit("contributions", &contributions, Field().Desc("by tolerance key"));
  }
};

}  // namespace camopt::studies
