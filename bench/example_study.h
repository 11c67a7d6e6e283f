// Runs an example study of studies/examples as `camopt run` does (parse, run, the files in memory)
// once per benchmark iteration.
#pragma once

#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include "studies/input.h"
#include "studies/study.h"

namespace camopt::bench {

inline void RunExampleStudy(benchmark::State& state, const char* name) {
  // The source tree (CAMOPT_SOURCE_DIR, set by CMake: __FILE__ is relative under ccache).
  const std::string file =
      (std::filesystem::path(CAMOPT_SOURCE_DIR) / "studies/examples" / name).string();
  const nlohmann::json j = studies::LoadStudyFile(file);
  studies::RunContext ctx;
  ctx.study_file = file;
  ctx.quiet = true;
  for (auto _ : state) benchmark::DoNotOptimize(studies::RunStudy(j, ctx));
}

}  // namespace camopt::bench
