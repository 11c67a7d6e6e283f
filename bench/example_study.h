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

/// The example's path in the source tree (CAMOPT_SOURCE_DIR, set by CMake: __FILE__ is relative
/// under ccache).
inline std::string ExamplePath(const char* name) {
  return (std::filesystem::path(CAMOPT_SOURCE_DIR) / "studies/examples" / name).string();
}

/// The example with `edit` applied to its JSON (a variant that is not an example itself).
template <typename Edit>
inline void RunExampleVariant(benchmark::State& state, const char* name, Edit edit) {
  const std::string file = ExamplePath(name);
  nlohmann::json j = studies::LoadStudyFile(file);
  edit(j);
  studies::RunContext ctx;
  ctx.study_file = file;
  ctx.quiet = true;
  for (auto _ : state) benchmark::DoNotOptimize(studies::RunStudy(j, ctx));
}

inline void RunExampleStudy(benchmark::State& state, const char* name) {
  const std::string file = ExamplePath(name);
  const nlohmann::json j = studies::LoadStudyFile(file);
  studies::RunContext ctx;
  ctx.study_file = file;
  ctx.quiet = true;
  for (auto _ : state) benchmark::DoNotOptimize(studies::RunStudy(j, ctx));
}

}  // namespace camopt::bench
