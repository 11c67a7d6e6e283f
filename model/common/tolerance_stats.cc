// The shared statistics of a tolerance analysis (model/common/tolerance_stats.h).
#include "model/common/tolerance_stats.h"

#include <algorithm>
#include <cmath>

namespace camopt::tolerance {

std::uint64_t SplitMix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double Uniform01(std::uint64_t& state) { return double(SplitMix64(state) >> 11) * 0x1.0p-53; }

double Percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t i = size_t(std::ceil(q * double(v.size()))) - 1;
  return v[std::min(i, v.size() - 1)];
}

void LinearStatistics(const std::vector<std::vector<double>>& s, const std::vector<double>& band,
                      const std::vector<int>& key, const std::vector<std::string>& keys, Statistics& res) {
  const int na = int(s.size());
  const size_t np = band.size();
  // E[t²] = band²/3 for a uniform deviation (± band, or 0 … band).
  const size_t nk = keys.size();
  std::vector<double> var_key(nk, 0.0);
  double var = 0;
  res.linear_sigma_arcsec.clear();
  for (int i = 0; i < na; ++i) {
    double v = 0, worst_abs = 0;
    for (size_t p = 0; p < np; ++p) {
      const double x = s[i][p] * band[p];
      v += x * x / 3.0;
      var_key[key[p]] += x * x / 3.0 / na;
      worst_abs += std::abs(x);
    }
    var += v / na;
    res.linear_sigma_arcsec.push_back(std::sqrt(v) * kArcsecPerRad);
    res.linear_worst_case_abs_arcsec = std::max(res.linear_worst_case_abs_arcsec, worst_abs * kArcsecPerRad);
  }
  res.linear_rms_arcsec = std::sqrt(var) * kArcsecPerRad;
  // The worst case of the peak-to-peak over the box: the linear TE is separable in the deviations.
  int bi = 0, bj = 0;
  double best = -1;
  for (int i = 0; i < na; ++i)
    for (int j = i + 1; j < na; ++j) {
      double w = 0;
      for (size_t p = 0; p < np; ++p) w += std::abs(s[i][p] - s[j][p]) * band[p];
      if (w > best) best = w, bi = i, bj = j;
    }
  res.linear_worst_case_arcsec = std::max(best, 0.0) * kArcsecPerRad;
  std::vector<double> wc_key(nk, 0.0);
  if (na > 0)
    for (size_t p = 0; p < np; ++p) wc_key[key[p]] += std::abs(s[bi][p] - s[bj][p]) * band[p];
  res.contributions.clear();
  for (size_t k = 0; k < nk; ++k) {
    bool present = false;
    for (int q : key) present = present || q == int(k);
    if (!present) continue;
    res.contributions.push_back({keys[k], wc_key[k] * kArcsecPerRad, std::sqrt(var_key[k]) * kArcsecPerRad,
                                 var > 0 ? var_key[k] / var : 0.0});
  }
}

void MonteCarloStatistics::Add(const std::vector<double>& te, const std::vector<double>& lin) {
  for (size_t i = 0; i < te.size(); ++i) {
    sum_sq_ += te[i] * te[i];
    worst_err_ = std::max(worst_err_, std::abs(te[i] - lin[i]));
  }
  values_ += te.size();
  const double pp = *std::max_element(te.begin(), te.end()) - *std::min_element(te.begin(), te.end());
  if (p2p_.empty() || pp > *std::max_element(p2p_.begin(), p2p_.end())) {
    worst_te_arcsec_.clear();
    for (double x : te) worst_te_arcsec_.push_back(x * kArcsecPerRad);
  }
  for (double x : te) max_abs_arcsec_ = std::max(max_abs_arcsec_, std::abs(x) * kArcsecPerRad);
  p2p_.push_back(pp);
}

void MonteCarloStatistics::Finish(Statistics& res) const {
  res.samples = int(p2p_.size());
  res.worst_sample_te_arcsec = worst_te_arcsec_;
  res.monte_carlo_max_abs_arcsec = max_abs_arcsec_;
  if (p2p_.empty()) return;
  res.monte_carlo_max_arcsec = *std::max_element(p2p_.begin(), p2p_.end()) * kArcsecPerRad;
  res.monte_carlo_p99_arcsec = Percentile(p2p_, 0.99) * kArcsecPerRad;
  res.monte_carlo_rms_arcsec = std::sqrt(sum_sq_ / double(values_)) * kArcsecPerRad;
  const double pp_max = *std::max_element(p2p_.begin(), p2p_.end());
  res.linear_vs_exact_max_error = pp_max > 0 ? worst_err_ / pp_max : 0.0;
}

}  // namespace camopt::tolerance
