// The fuzz target over `camopt sweep`, shared by the libFuzzer binary (fuzz/sweep_fuzzer.cc,
// CMake option CAMOPT_FUZZ) and the corpus replay test (tests/fuzz_replay_test.cc) that runs on
// every normal build. One input is the text of a sweep file. It is written into a scratch folder
// laid out like the source tree (SCRATCH/sweeps/fuzz_sweep.json beside SCRATCH/examples, which
// links to every example, so the examples' relative `base` paths resolve) and run in-process as
//   camopt sweep SCRATCH/sweeps/fuzz_sweep.json --out SCRATCH/out --quiet --jobs 1
//                --max-work-factor 1e-3
// Exit 0, 2 or 3 is an answer. A defect is exit 1 (an exception other than StudyError, out of
// memory), a case whose status is `failed` (the same two inside a case), a refusal that leaves
// the output folder or its partial folder behind, or a crash or sanitizer report (the fuzzer's).
#pragma once

#include <stdlib.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "studies/sweep.h"

namespace camopt::fuzz {

/// Work caps of a fuzzed sweep (the factor on every cap of studies/work_limits.h, the case count
/// included) and the largest input run.
constexpr double kSweepFuzzWorkFactor = 1e-3;
constexpr size_t kSweepFuzzMaxBytes = 64 * 1024;

/// The scratch folder of the sweep target (removed when destroyed).
class SweepScratch {
 public:
  /// `examples`: the folder of example studies the scratch links to.
  explicit SweepScratch(const std::filesystem::path& examples) {
    namespace fs = std::filesystem;
    std::string pattern = (fs::temp_directory_path() / "camopt-fuzz-sweep-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a scratch folder for the sweep fuzzer");
    root_ = pattern;
    fs::create_directories(root_ / "sweeps");
    fs::create_directories(root_ / "examples");
    for (const auto& e : fs::directory_iterator(examples))
      if (e.is_regular_file()) fs::create_symlink(fs::absolute(e.path()), root_ / "examples" / e.path().filename());
  }
  ~SweepScratch() {
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  SweepScratch(const SweepScratch&) = delete;
  SweepScratch& operator=(const SweepScratch&) = delete;

  const std::filesystem::path& root() const { return root_; }

 private:
  std::filesystem::path root_;
};

/// What one sweep input gave: its exit code and, when it is a defect, why ("" otherwise).
struct SweepVerdict {
  int code = 0;
  std::string defect;
};

/// Runs one input in `scratch` (one input at a time per scratch).
inline SweepVerdict RunSweepText(const uint8_t* data, size_t size, const SweepScratch& scratch) {
  namespace fs = std::filesystem;
  SweepVerdict v;
  if (size > kSweepFuzzMaxBytes) return v;
  const fs::path file = scratch.root() / "sweeps" / "fuzz_sweep.json", out = scratch.root() / "out";
  {
    std::ofstream f(file, std::ios::binary | std::ios::trunc);
    f.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  std::error_code ec;
  fs::remove_all(out, ec);
  studies::sweep::Options o;
  o.file = file.string();
  o.out = out.string();
  o.jobs = 1;
  o.quiet = true;
  o.summary = false;
  o.max_work_factor = kSweepFuzzWorkFactor;
  v.code = studies::sweep::RunCommand(o);
  const fs::path partial = out.string() + ".camopt-sweep";
  if (v.code == 1) {
    v.defect = "exit 1 (an exception other than a refusal, or out of memory)";
  } else if (v.code == 2) {
    if (fs::exists(out) || fs::exists(partial)) v.defect = "a refused sweep left its output or partial folder";
  } else if (v.code == 0 || v.code == 3) {
    std::ifstream in(out / "result.json");
    std::stringstream s;
    s << in.rdbuf();
    const nlohmann::json summary = nlohmann::json::parse(s.str(), nullptr, false);
    const nlohmann::json failed =
        summary.is_object() ? summary.value("/status_counts/failed"_json_pointer, nlohmann::json()) : nlohmann::json();
    if (!failed.is_number_integer()) v.defect = "exit " + std::to_string(v.code) + " without a readable result.json";
    else if (failed.get<long>() != 0)
      v.defect = "a case failed: " + summary.value("/cases_not_ok"_json_pointer, nlohmann::json()).dump().substr(0, 400);
  } else {
    v.defect = "exit " + std::to_string(v.code);
  }
  fs::remove_all(out, ec);
  fs::remove_all(partial, ec);
  return v;
}

}  // namespace camopt::fuzz
