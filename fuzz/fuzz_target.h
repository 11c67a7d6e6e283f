// The fuzz target over the study runner, shared by the libFuzzer binary (fuzz/study_fuzzer.cc,
// CMake option CAMOPT_FUZZ) and the corpus replay test (tests/fuzz_replay_test.cc) that runs on
// every normal build. One input is the text of a study file; it is parsed and run with small work
// caps, the outputs kept in memory (nothing is written). A StudyError is the expected answer to a
// bad input; any other exception, a crash or a sanitizer report is a camopt defect.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "studies/input.h"
#include "studies/study.h"

namespace camopt::fuzz {

/// Work caps of a fuzzed run: factor on every cap of studies/work_limits.h (a run stays under
/// about a tenth of a second), and the largest input read.
constexpr double kFuzzWorkFactor = 1e-3;
constexpr size_t kFuzzMaxBytes = 64 * 1024;

/// Runs one input. `study_file` names it in messages and anchors relative catalogue paths.
/// Returns true when the input was accepted and run, false when refused with a StudyError;
/// anything else propagates (the fuzzer turns it into a crash report).
inline bool RunStudyText(const uint8_t* data, size_t size, const std::string& study_file) {
  if (size > kFuzzMaxBytes) return false;
  const std::string text(reinterpret_cast<const char*>(data), size);
  studies::RunContext ctx;
  ctx.study_file = study_file;
  ctx.quiet = true;
  ctx.max_work_factor = kFuzzWorkFactor;
  try {
    const nlohmann::json study =
        studies::ParseStudyText(text, study_file, studies::CurrentInputLimits().max_depth);
    const studies::Outputs outputs = studies::RunStudy(study, ctx);
    return true;
  } catch (const studies::StudyError&) {
    return false;
  }
}

}  // namespace camopt::fuzz
