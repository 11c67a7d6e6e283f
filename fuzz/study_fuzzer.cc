// libFuzzer entry point over the study runner (see fuzz/fuzz_target.h; run with scripts/fuzz.sh).
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    camopt::fuzz::RunStudyText(data, size, CAMOPT_EXAMPLES_DIR "/fuzz_input.json");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "camopt defect: exception other than StudyError: %s\n", e.what());
    std::abort();
  }
  return 0;
}
