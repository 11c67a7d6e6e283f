// Replays the fuzz corpus (tests/fuzz_corpus/: the examples and minimized inputs that once found
// a defect or hit a limit) through the same target as the libFuzzer binary, on every build: an
// input must either run or be refused with a StudyError, never throw anything else or crash.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "fuzz/fuzz_target.h"

namespace fs = std::filesystem;

namespace fuzz_replay_test {

std::vector<fs::path> CorpusFiles() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(fs::path(CAMOPT_SOURCE_DIR) / "tests/fuzz_corpus"))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(FuzzCorpus, EveryInputRunsOrIsRefusedWithAStudyError) {
  const auto files = CorpusFiles();
  ASSERT_GE(files.size(), 20u);  // the examples at least
  int accepted = 0;
  for (const auto& f : files) {
    SCOPED_TRACE(f.filename().string());
    std::ifstream in(f, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    try {
      accepted += camopt::fuzz::RunStudyText(reinterpret_cast<const uint8_t*>(text.data()),
                                             text.size(), CAMOPT_SOURCE_DIR "/studies/examples/fuzz_input.json");
    } catch (const std::exception& e) {
      ADD_FAILURE() << "not a StudyError: " << e.what();
    }
  }
  // Some inputs pass the small caps and really run (not everything is refused up front).
  EXPECT_GT(accepted, 0);
}

}  // namespace fuzz_replay_test
