// The statistics of a transmission error from manufacturing tolerances, shared by the reducers'
// tolerance analyses (model/lcr/transmission_error.h, model/cycloid/transmission_error.h).
//
// Each deviation t_p is uniform in its band: ± b_p, or 0 … b_p for a one-sided one (a clearance);
// either way E[t²] = b²/3. The linear model TE(θ_i) ≈ Σ_p S_p(θ_i) t_p (S_p exact derivatives) is
// separable in the deviations, so its worst case over the box of bands is exact:
//   peak-to-peak   max_{i,j} Σ_p |S_p(θ_i) − S_p(θ_j)| b_p,     largest |TE|   max_i Σ_p |S_p(θ_i)| b_p,
// its RMS over the angles and the distribution sqrt(mean_i Σ_p S_p(θ_i)² b_p²/3), and each tolerance
// key's part of it (its worst-case share at the pair of angles that makes the peak-to-peak, its
// RMS, its share of the variance). The Monte-Carlo run draws the deviations from SplitMix64
// (fixed, portable: runs are byte-identical), evaluates the exact model and reports the sample
// peak-to-peaks' maximum and 99th percentile, the RMS and the linear model's largest error.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "model/common/scalar.h"

namespace camopt::tolerance {

inline constexpr double kArcsecPerRad = 180.0 / kPi * 3600.0;

/// SplitMix64 step (Steele, Lea & Flood 2014): the next 64 random bits from the state.
std::uint64_t SplitMix64(std::uint64_t& state);
/// Uniform in [0, 1) with 53 random bits.
double Uniform01(std::uint64_t& state);
/// The q-quantile of v by the nearest rank (0 for an empty v).
double Percentile(std::vector<double> v, double q);

struct Contribution {
  std::string key;
  double worst_case_arcsec = 0;  ///< its part of the linear worst-case peak-to-peak
  double rms_arcsec = 0;         ///< its part of the linear RMS (root of its variance)
  double variance_share = 0;     ///< fraction of the linear variance
};

/// What both reducers report (header comment); a reducer's result adds its own fields.
struct Statistics {
  std::vector<double> linear_sigma_arcsec;  ///< per angle, RMS of the linear TE
  double linear_worst_case_arcsec = 0;      ///< peak-to-peak over the angles, worst over the box
  double linear_worst_case_abs_arcsec = 0;  ///< max |TE|, worst over the box
  double linear_rms_arcsec = 0;             ///< RMS over angles and the tolerance distribution
  int samples = 0;
  double monte_carlo_max_arcsec = 0, monte_carlo_p99_arcsec = 0;  ///< sample peak-to-peak
  double monte_carlo_rms_arcsec = 0;
  double monte_carlo_max_abs_arcsec = 0;
  /// Largest |exact − linear| TE over samples and angles, over the largest sample peak-to-peak.
  double linear_vs_exact_max_error = 0;
  std::vector<Contribution> contributions;
  std::vector<double> worst_sample_te_arcsec;  ///< TE(θ) of the sample with the largest peak-to-peak
};

/// The linear part of `out` from the sensitivities s[i][p] = ∂TE(θ_i)/∂t_p [rad per unit of t_p],
/// the bands b_p and each deviation's key (an index into `keys`); contributions for the keys present,
/// in the order of `keys`.
void LinearStatistics(const std::vector<std::vector<double>>& s, const std::vector<double>& band,
                      const std::vector<int>& key, const std::vector<std::string>& keys, Statistics& out);

/// LinearStatistics of a reducer's deviations, each carrying its band and key (`p.band`, `p.key`).
template <typename Parameter>
void LinearStatisticsOf(const std::vector<std::vector<double>>& s, const std::vector<Parameter>& params,
                        const std::vector<std::string>& keys, Statistics& out) {
  std::vector<double> band;
  std::vector<int> key;
  for (const Parameter& p : params) band.push_back(p.band), key.push_back(p.key);
  LinearStatistics(s, band, key, keys, out);
}

/// The Monte-Carlo part: Add each sample's exact TE(θ_i) [rad] and the linear model's at the same
/// deviations, then Finish.
class MonteCarloStatistics {
 public:
  void Add(const std::vector<double>& te_rad, const std::vector<double>& linear_rad);
  /// Fills the Monte-Carlo fields of `out` (samples, max, p99, RMS, largest |TE|, the linear
  /// model's error, the worst sample's TE).
  void Finish(Statistics& out) const;
  /// The peak-to-peak of each sample so far [rad].
  const std::vector<double>& peak_to_peak_rad() const { return p2p_; }

 private:
  std::vector<double> p2p_, worst_te_arcsec_;
  double sum_sq_ = 0, worst_err_ = 0, max_abs_arcsec_ = 0;
  size_t values_ = 0;
};

/// The Monte-Carlo run of a tolerance analysis (header comment), the same for every reducer:
/// `samples` draws from SplitMix64 started at `seed`; `draw(state, values)` returns a sample's
/// deviations (and their values t_p, in the order of s's columns), `exact(deviations, te)` fills the
/// exact TE(θ_i) − nominal [rad] at that sample and returns a per-sample quantity of the reducer's
/// own (its worst backlash or lost motion), which are returned in order. Each sample's linear TE
/// Σ_p s[i][p] t_p goes beside its exact one into the statistics of `out`.
template <typename Draw, typename Exact>
std::vector<double> RunMonteCarlo(int samples, std::uint64_t seed, const std::vector<std::vector<double>>& s,
                                  Draw&& draw, Exact&& exact, const std::function<void(double)>& progress,
                                  Statistics& out) {
  MonteCarloStatistics mc;
  std::vector<double> per_sample;
  std::uint64_t state = seed;
  std::vector<double> values;
  const size_t na = s.size();
  for (int m = 0; m < samples; ++m) {
    const auto dev = draw(state, &values);
    std::vector<double> te(na), lin(na);
    per_sample.push_back(exact(dev, te));
    for (size_t i = 0; i < na; ++i)
      for (size_t p = 0; p < s[i].size(); ++p) lin[i] += s[i][p] * values[p];
    mc.Add(te, lin);
    if (progress) progress(double(m + 1) / samples);
  }
  mc.Finish(out);
  return per_sample;
}

}  // namespace camopt::tolerance
