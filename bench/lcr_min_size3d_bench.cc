// Speed of lcr_min_size with crowned rollers and the 3D contact (target <= 5 s): the
// example studies/examples/lcr_min_size_crowned.json (ratio −90, 80 N·m, crowning coefficients as
// variables, 1 mrad, overload 120 N·m; 4 lobe combinations, then the half_space re-check), and
// one combination of it (max_lobes 14). Run: build/camopt_bench --benchmark_filter=MinSize3D
#include <benchmark/benchmark.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "studies/lcr_min_size_study.h"

namespace lcr_min_size3d_bench {

using namespace camopt;

nlohmann::json Crowned(int max_lobes) {
  std::ifstream in(std::string(CAMOPT_SOURCE_DIR) + "/studies/examples/lcr_min_size_crowned.json");
  nlohmann::json j = nlohmann::json::parse(in);
  j["search"]["max_lobes"] = max_lobes;
  return j;
}

void BM_MinSize3DCrowned(benchmark::State& state) {
  const nlohmann::json j = Crowned(int(state.range(0)));
  const auto study = studies::lcr_min_size::Parse(studies::Node(&j, "crowned.json", ""));
  for (auto _ : state) benchmark::DoNotOptimize(studies::lcr_min_size::Run(study, studies::RunContext("", true)));
}
BENCHMARK(BM_MinSize3DCrowned)->Arg(14)->Arg(40)->Unit(benchmark::kSecond)->Iterations(1)->MeasureProcessCPUTime();

}  // namespace lcr_min_size3d_bench
