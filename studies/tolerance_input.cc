// The shared "transmission_error" statistics of result.json (studies/tolerance_input.h).
#include "studies/tolerance_input.h"

#include <initializer_list>
#include <utility>

namespace camopt::studies {

nlohmann::json ToleranceStatisticsJson(const tolerance::Statistics& te, std::uint64_t seed) {
  nlohmann::json j;
  using Member = std::pair<const char*, double tolerance::Statistics::*>;
  using R = tolerance::Statistics;
  auto copy = [&](std::initializer_list<Member> fields) {
    for (const auto& [key, field] : fields) j[key] = te.*field;
  };
  copy({{"linear_worst_case_arcsec", &R::linear_worst_case_arcsec},
        {"linear_worst_case_abs_arcsec", &R::linear_worst_case_abs_arcsec},
        {"linear_rms_arcsec", &R::linear_rms_arcsec}});
  j["monte_carlo_samples"] = te.samples;
  j["monte_carlo_seed"] = seed;
  if (te.samples > 0) {
    copy({{"monte_carlo_max_arcsec", &R::monte_carlo_max_arcsec},
          {"monte_carlo_p99_arcsec", &R::monte_carlo_p99_arcsec},
          {"monte_carlo_rms_arcsec", &R::monte_carlo_rms_arcsec},
          {"monte_carlo_max_abs_arcsec", &R::monte_carlo_max_abs_arcsec},
          {"linear_vs_exact_max_error", &R::linear_vs_exact_max_error}});
  } else {
    for (const char* k : {"monte_carlo_max_arcsec", "monte_carlo_p99_arcsec", "monte_carlo_rms_arcsec"}) j[k] = nullptr;
  }
  nlohmann::json c = nlohmann::json::object();
  for (const auto& k : te.contributions)
    c[k.key] = {{"worst_case_arcsec", k.worst_case_arcsec}, {"rms_arcsec", k.rms_arcsec}, {"variance_share", k.variance_share}};
  j["contributions"] = c;
  return j;
}

}  // namespace camopt::studies
