// The shared "transmission_error" statistics of result.json (studies/tolerance_input.h).
#include "studies/tolerance_input.h"

#include <initializer_list>
#include <utility>

namespace camopt::studies {

void ToleranceStatisticsBlock::SetStatistics(const tolerance::Statistics& te, std::uint64_t seed) {
  linear_worst_case_arcsec = te.linear_worst_case_arcsec;
  linear_worst_case_abs_arcsec = te.linear_worst_case_abs_arcsec;
  linear_rms_arcsec = te.linear_rms_arcsec;
  monte_carlo_samples = te.samples;
  monte_carlo_seed = seed;
  monte_carlo_max_arcsec = monte_carlo_p99_arcsec = monte_carlo_rms_arcsec = std::nullopt;  // null
  if (te.samples > 0) {
    monte_carlo_max_arcsec = te.monte_carlo_max_arcsec;
    monte_carlo_p99_arcsec = te.monte_carlo_p99_arcsec;
    monte_carlo_rms_arcsec = te.monte_carlo_rms_arcsec;
    monte_carlo_max_abs_arcsec = te.monte_carlo_max_abs_arcsec;
    linear_vs_exact_max_error = te.linear_vs_exact_max_error;
  }
  contributions.clear();
  for (const auto& k : te.contributions) contributions[k.key] = {k.worst_case_arcsec, k.rms_arcsec, k.variance_share};
}

}  // namespace camopt::studies
