// The geometry files' share of an analysis study: each example run in process as `camopt run` does
// (parse, run, every file in memory) with its DXF/STEP/STL and with "geometry_files": false; the
// difference is the files' cost (docs/performance.md, 'Geometry files').
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include "studies/input.h"
#include "studies/study.h"

namespace geometry_bench {

using namespace camopt;

void RunExample(benchmark::State& state, const char* name, bool files) {
  const std::string file =
      (std::filesystem::path(CAMOPT_SOURCE_DIR) / "studies/examples" / name).string();
  nlohmann::json j = studies::LoadStudyFile(file);
  if (!files) j["geometry_files"] = false;
  studies::RunContext ctx;
  ctx.study_file = file;
  ctx.quiet = true;
  for (auto _ : state) benchmark::DoNotOptimize(studies::RunStudy(j, ctx));
}

void BM_StudyWithFiles(benchmark::State& state, const char* name) { RunExample(state, name, true); }
void BM_StudyWithoutFiles(benchmark::State& state, const char* name) { RunExample(state, name, false); }

BENCHMARK_CAPTURE(BM_StudyWithFiles, lcr_ii, "lcr_ii.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StudyWithoutFiles, lcr_ii, "lcr_ii.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StudyWithFiles, cycloid_ltca_nnm_none, "cycloid_ltca_nnm_none.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StudyWithoutFiles, cycloid_ltca_nnm_none, "cycloid_ltca_nnm_none.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StudyWithFiles, disc_cam_translating, "disc_cam_translating.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StudyWithoutFiles, disc_cam_translating, "disc_cam_translating.json")->Unit(benchmark::kMillisecond);

}  // namespace geometry_bench
