// The partial folder of a sweep and its checkpoints (docs/studies.md, "Sweeps"). A sweep runs into
// `<out>.camopt-sweep`, beside a lock `<out>.camopt-sweep-lock`; each rank appends its finished
// cases to `checkpoint-RANK.jsonl` there, a header line with the sweep's fingerprint first, one
// JSON line per case after it (CaseRecord::ToJson). `--resume` reads them back; the merged folder
// replaces --out at the end (studies/sweep.cc).
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "studies/sweep.h"

namespace camopt::studies::sweep {

/// An existing --out is replaced only when it is empty or holds a previous camopt result and
/// nothing else (studies/study.h, NotReplaceable: the rule of every writer). Throws StudyError
/// otherwise (`dir` as given on the command line).
void CheckReplaceable(const std::filesystem::path& out, const std::string& dir);

/// The partial folder of a sweep into `out`: `<out>.camopt-sweep`.
std::filesystem::path PartialFolder(const std::filesystem::path& out);

/// 64-bit FNV-1a of a text, as 16 hex digits: the fingerprint of a sweep in its checkpoint.
std::string Fingerprint(const std::string& text);

/// The checkpoints' header line: the fingerprint of the base study, the cases, the output
/// columns and case_outputs. A checkpoint with another header is another sweep's.
std::string CheckpointHeader(const Sweep& sweep, const std::vector<std::vector<nlohmann::json>>& cases);

/// The checkpoint file of one rank: checkpoint-RANK.jsonl.
std::string CheckpointName(int rank);

/// The checkpoint of one rank: a header line with the sweep's fingerprint, then one line per
/// finished case, each written with one write() as soon as the case ends (an interrupt loses
/// only the cases under way; a line cut short is ignored on resume).
class Checkpoint {
 public:
  Checkpoint(const std::filesystem::path& file, const std::string& header);
  Checkpoint(const Checkpoint&) = delete;
  Checkpoint& operator=(const Checkpoint&) = delete;
  ~Checkpoint();
  /// Thread-safe; throws StudyError when the line cannot be written.
  void Append(const CaseRecord& r);

 private:
  void Write(const std::string& line);
  int fd_ = -1;
  std::mutex mutex_;
};

/// The finished cases of every checkpoint in the partial folder (records of cases beyond n_cases
/// or with another number of outputs, and lines cut short, are left out). Throws StudyError when
/// a checkpoint's header is not `header`.
std::map<size_t, CaseRecord> ReadCheckpoints(const std::filesystem::path& partial, const std::string& header,
                                             size_t n_cases, size_t n_outputs);

/// Prepares the partial folder on rank 0: without `resume` an earlier one is removed (and said
/// so unless quiet); with it, its checkpoints are read and the case folders cut short removed.
/// Returns the cases already done. `given` is --out as given (messages). Throws StudyError.
std::map<size_t, CaseRecord> OpenPartialFolder(const std::filesystem::path& partial, const std::string& given,
                                               const Sweep& sweep, const std::string& header, size_t n_cases,
                                               bool resume, bool quiet);

/// Removes the checkpoints from the partial folder (once the merged files are written).
void RemoveCheckpoints(const std::filesystem::path& partial);

/// The name of a case's folder under cases/: its number, at least 4 digits, as wide as the
/// largest number.
std::string CaseFolderName(size_t index, size_t n_cases);

/// An advisory lock (flock) on `<out>.camopt-sweep-lock`, held while a sweep runs into out; the
/// file goes when the sweep ends. A killed sweep's lock is released by the kernel.
class SweepLock {
 public:
  SweepLock() = default;
  SweepLock(const SweepLock&) = delete;
  SweepLock& operator=(const SweepLock&) = delete;
  ~SweepLock();
  /// Throws StudyError when another sweep holds the lock (`given` is --out as given).
  void Take(const std::filesystem::path& out, const std::string& given);

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace camopt::studies::sweep
