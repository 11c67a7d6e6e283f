// Speed of the line-model LCR sizing (docs/performance.md, "LCR sizing"):
//   build/camopt_bench --benchmark_filter="LcrMinSize(Example|LifeExample|HardLife)"
// The examples as `camopt run` runs them (parse, every combination, the verification, the files in
// memory), and the life example with a limit that removes most combinations: 20 000 h at 3000 rpm
// (Ipopt; one of four combinations reaches that life, the others are out of reach: docs/life.md,
// "A life out of reach is not sized").
#include <benchmark/benchmark.h>

#include "bench/example_study.h"

namespace camopt {
namespace lcr_min_size_bench {

void BM_LcrMinSizeExample(benchmark::State& state) { bench::RunExampleStudy(state, "lcr_min_size.json"); }
void BM_LcrMinSizeLifeExample(benchmark::State& state) { bench::RunExampleStudy(state, "lcr_min_size_life.json"); }
void BM_LcrMinSizeHardLife(benchmark::State& state) {
  bench::RunExampleVariant(state, "lcr_min_size_life.json", [](nlohmann::json& j) {
    j["limits"]["life_h"] = 20000;
    j["load"]["input_speed_rpm"] = 3000;
  });
}
BENCHMARK(BM_LcrMinSizeExample)->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();
BENCHMARK(BM_LcrMinSizeLifeExample)->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();
BENCHMARK(BM_LcrMinSizeHardLife)->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();

}  // namespace lcr_min_size_bench
}  // namespace camopt
