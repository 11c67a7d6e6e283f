// A main() for a libFuzzer entry point in a build without libFuzzer: runs
// LLVMFuzzerTestOneInput once on each file named on the command line (a file that is a folder:
// on each file in it, in name order) and prints how many ran. A defect aborts, as under the
// fuzzer; exit 2 when a file cannot be read or none is given. The corpus replays of ctest
// (FuzzCorpus.*) run the sweep and request targets through it on every normal build.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  // Absolute paths: a target may change the working folder (the studio's runs do, in a child).
  for (int i = 1; i < argc; ++i) {
    std::error_code ec;
    if (fs::is_directory(argv[i], ec)) {
      std::vector<fs::path> in;
      for (const auto& e : fs::directory_iterator(argv[i]))
        if (e.is_regular_file()) in.push_back(fs::absolute(e.path()));
      std::sort(in.begin(), in.end());
      files.insert(files.end(), in.begin(), in.end());
    } else {
      files.push_back(fs::absolute(argv[i]));
    }
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: %s FILE_OR_FOLDER...\n", argc > 0 ? argv[0] : "replay");
    return 2;
  }
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "cannot read %s\n", f.c_str());
      return 2;
    }
    std::stringstream s;
    s << in.rdbuf();
    const std::string text = s.str();
    std::fprintf(stderr, "replay: %s\n", f.filename().c_str());
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(text.data()), text.size());
  }
  std::printf("%zu inputs, no defect\n", files.size());
  return 0;
}
