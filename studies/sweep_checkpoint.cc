#include "studies/sweep_checkpoint.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "studies/input.h"
#include "studies/study.h"

namespace camopt::studies::sweep {

namespace fs = std::filesystem;
using nlohmann::json;

void CheckReplaceable(const fs::path& out, const std::string& dir) {
  struct stat st {};
  if (lstat(out.c_str(), &st) != 0) return;
  if (!S_ISDIR(st.st_mode)) throw StudyError("--out " + dir + ": exists and is not a folder");
  // The rule of every writer (studies/study.h): a previous camopt result, listed in its manifest.
  const std::string why = NotReplaceable(out);
  if (!why.empty())
    throw StudyError("--out " + dir + ": the folder is not a camopt sweep result camopt may replace (" + why +
                     "); choose a new or empty folder");
}

fs::path PartialFolder(const fs::path& out) { return SiblingPrefix(out) + ".camopt-sweep"; }

std::string Fingerprint(const std::string& text) {
  uint64_t h = 14695981039346656037ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

std::string CheckpointHeader(const Sweep& s, const std::vector<std::vector<json>>& cases) {
  json header_json = {{"base", s.base}, {"cases", cases}, {"outputs", json::array()},
                      {"case_outputs", s.case_outputs}};
  for (const OutputColumn& c : s.outputs) header_json["outputs"].push_back(c.path);
  return json({{"sweep_fingerprint", Fingerprint(header_json.dump())}}).dump();
}

std::string CheckpointName(int rank) { return "checkpoint-" + std::to_string(rank) + ".jsonl"; }

Checkpoint::Checkpoint(const fs::path& file, const std::string& header) {
  fd_ = open(file.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw StudyError("--out: cannot create the checkpoint " + file.string() + ": " + std::strerror(errno));
  if (lseek(fd_, 0, SEEK_END) == 0) Write(header + "\n");
  else Write("\n");  // ends a line cut short by an interrupt (an empty line is skipped)
}

Checkpoint::~Checkpoint() {
  if (fd_ >= 0) close(fd_);
}

void Checkpoint::Append(const CaseRecord& r) {
  const std::lock_guard<std::mutex> lock(mutex_);
  Write(r.ToJson().dump() + "\n");
}

void Checkpoint::Write(const std::string& line) {
  size_t done = 0;
  while (done < line.size()) {
    const ssize_t n = write(fd_, line.data() + done, line.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw StudyError(std::string("cannot write the checkpoint: ") + std::strerror(errno));
    done += static_cast<size_t>(n);
  }
}

std::map<size_t, CaseRecord> ReadCheckpoints(const fs::path& partial, const std::string& header,
                                             size_t n_cases, size_t n_outputs) {
  std::map<size_t, CaseRecord> done;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(partial, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("checkpoint-", 0) != 0) continue;
    std::istringstream in(ReadFileCapped(e.path().string(), size_t{1} << 34, "checkpoint"));
    std::string line;
    if (!std::getline(in, line) || line != header)
      throw StudyError("--resume: " + e.path().string() +
                       " is the checkpoint of another sweep (the sweep file or its base study "
                       "changed); run without --resume to start again");
    while (std::getline(in, line)) {
      if (line.empty()) continue;
      try {
        CaseRecord r = CaseRecord::FromJson(json::parse(line));
        if (r.index < n_cases && r.outputs.size() == n_outputs) done.emplace(r.index, std::move(r));
      } catch (const std::exception&) {
        // a line cut short by an interrupt: that case runs again
      }
    }
  }
  return done;
}

std::map<size_t, CaseRecord> OpenPartialFolder(const fs::path& partial, const std::string& given, const Sweep& s,
                                               const std::string& header, size_t n_cases, bool resume,
                                               bool quiet) {
  std::map<size_t, CaseRecord> done;
  std::error_code ec;
  const bool had_partial = fs::exists(partial, ec);
  if (had_partial && !resume) {
    if (!quiet)
      std::cerr << "camopt: " << partial.string()
                << " holds an interrupted sweep; starting again (--resume continues it)\n";
    fs::remove_all(partial, ec);
  }
  if (resume && !had_partial && !quiet)
    std::cerr << "camopt: nothing to resume in " << partial.string() << "; starting\n";
  fs::create_directories(partial / (s.case_outputs ? "cases" : ""), ec);
  if (ec) throw StudyError("--out " + given + ": cannot create " + partial.string() + ": " + ec.message());
  if (resume) {
    done = ReadCheckpoints(partial, header, n_cases, s.outputs.size());
    // Case folders being written when the sweep was interrupted (OutputFolder's temporary
    // siblings): their cases were not checkpointed and run again.
    for (const auto& e : fs::directory_iterator(partial / "cases", ec))
      if (e.path().filename().string().find(".camopt-tmp-") != std::string::npos)
        fs::remove_all(e.path(), ec);
  }
  return done;
}

void RemoveCheckpoints(const fs::path& partial) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(partial, ec))
    if (e.path().filename().string().rfind("checkpoint-", 0) == 0) fs::remove(e.path(), ec);
}

std::string CaseFolderName(size_t index, size_t n_cases) {
  const int width = std::max<int>(4, static_cast<int>(std::to_string(n_cases - 1).size()));
  char buf[32];
  std::snprintf(buf, sizeof buf, "%0*zu", width, index);
  return buf;
}

SweepLock::~SweepLock() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());
  ::close(fd_);
}

void SweepLock::Take(const fs::path& out, const std::string& given) {
  path_ = SiblingPrefix(out) + ".camopt-sweep-lock";
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw StudyError("--out " + given + ": cannot create the lock " + path_ + ": " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    throw StudyError("--out " + given + ": another sweep is running into this folder (it holds " + path_ +
                     "); wait for it to end or choose another folder");
  }
}

}  // namespace camopt::studies::sweep
