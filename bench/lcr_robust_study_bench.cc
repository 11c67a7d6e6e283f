// Speed of the sizing across tolerances as a user runs it: the example
// studies/examples/lcr_min_size_robust.json (ratio −90, 80 N·m, mean + 3σ of a sub-micrometre
// grade; the nominal sizing, the robust re-solve, the linearised grid check and the Monte-Carlo
// checks of the robust and the nominal best). Its own file: the other robust benchmarks use the
// test helpers, whose namespace clashes with the studies' headers.
// Run: build/camopt_bench --benchmark_filter=LcrRobustStudy
#include <benchmark/benchmark.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "studies/lcr_min_size_study.h"

namespace lcr_robust_study_bench {

using namespace camopt;

void BM_LcrRobustStudy(benchmark::State& state) {
  std::ifstream in(std::string(CAMOPT_SOURCE_DIR) + "/studies/examples/lcr_min_size_robust.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const auto study = studies::lcr_min_size::Parse(studies::Node(&j, "robust.json", ""));
  for (auto _ : state) benchmark::DoNotOptimize(studies::lcr_min_size::Run(study, studies::RunContext("", true)));
}
BENCHMARK(BM_LcrRobustStudy)->Unit(benchmark::kSecond)->Iterations(1)->MeasureProcessCPUTime();

}  // namespace lcr_robust_study_bench
