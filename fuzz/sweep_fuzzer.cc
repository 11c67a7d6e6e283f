// libFuzzer entry point over `camopt sweep` (see fuzz/sweep_target.h; run with
// `bash scripts/fuzz.sh sweep SECONDS`).
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>

#include "fuzz/sweep_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const auto scratch = std::make_unique<camopt::fuzz::SweepScratch>(CAMOPT_EXAMPLES_DIR);
  try {
    const camopt::fuzz::SweepVerdict v = camopt::fuzz::RunSweepText(data, size, *scratch);
    if (!v.defect.empty()) {
      std::fprintf(stderr, "camopt defect: %s\n", v.defect.c_str());
      std::abort();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "camopt defect: an exception escaped camopt sweep: %s\n", e.what());
    std::abort();
  }
  return 0;
}
