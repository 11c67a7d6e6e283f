#include "studies/study.h"

#include <cerrno>
#include <chrono>
#include <ctime>
#include <climits>
#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>
#include <fstream>
#include <set>
#include <iostream>
#include <mutex>
#include <stdexcept>

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "studies/archive.h"
#include "studies/provenance.h"
#include "studies/datasheet.h"
#include "studies/kind.h"
#include "studies/report.h"
#include "studies/schemas.h"
#include "studies/work_limits.h"

namespace camopt::studies {

namespace fs = std::filesystem;

namespace {
std::mutex& ObserverMutex() {
  static std::mutex m;
  return m;
}
std::function<void(const ProgressEvent&)>& Observer() {
  static std::function<void(const ProgressEvent&)> observer;
  return observer;
}
}  // namespace

std::function<void(const ProgressEvent&)> SetProgressObserver(std::function<void(const ProgressEvent&)> observer) {
  std::lock_guard<std::mutex> lock(ObserverMutex());
  std::swap(Observer(), observer);
  return observer;
}

void Progress::Observe(double fraction, const std::string& detail, bool done) {
  std::function<void(const ProgressEvent&)> observer;
  {
    std::lock_guard<std::mutex> lock(ObserverMutex());
    observer = Observer();
  }
  if (!observer) return;
  const auto now = std::chrono::steady_clock::now();
  if (!done && observed_ && now - last_observed_ < std::chrono::milliseconds(100)) return;
  if (done && !observed_) return;  // nothing was reported: no closing report either
  last_observed_ = now;
  observed_ = true;
  ProgressEvent e;
  e.label = label_;
  e.fraction = std::clamp(fraction, 0.0, 1.0);
  e.elapsed_s = std::chrono::duration<double>(now - start_).count();
  if (e.fraction >= 0.01 && e.fraction < 1.0 && e.elapsed_s >= 1.0)
    e.eta_s = e.elapsed_s * (1.0 - e.fraction) / e.fraction;
  e.detail = detail;
  e.done = done;
  observer(e);
}

void Progress::Update(double fraction, const std::string& detail) {
  optimizers::ThrowIfCancelled();
  fraction_ = fraction;
  Observe(fraction, detail, false);
  if (quiet_) return;
  // On a terminal one line is rewritten in place (10 times a second at most); into a file or a
  // pipe, a plain line every 2 seconds and at the end.
  static const bool tty = isatty(2);
  const auto now = std::chrono::steady_clock::now();
  const auto every = tty ? std::chrono::milliseconds(100) : std::chrono::milliseconds(2000);
  if (shown_ && fraction < 1.0 && now - last_ < every) return;
  if (!shown_ && !tty && fraction >= 1.0) return;  // finished before the first line was due
  last_ = now;
  shown_ = true;
  const double f = std::clamp(fraction, 0.0, 1.0);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  char pct[16];
  std::snprintf(pct, sizeof pct, "%5.1f%%", 100.0 * f);
  std::string timing = "  " + ClockText(elapsed) + " elapsed";
  if (f >= 0.01 && f < 1.0 && elapsed >= 1.0) timing += ", ETA " + ClockText(elapsed * (1.0 - f) / f);
  std::cerr << (tty ? "\r" : "") << label_ << ": " << pct << timing << (detail.empty() ? "" : "  ") << detail
            << (tty ? "\033[K" : "\n") << std::flush;
}

std::string ClockText(double seconds) {
  const long s = std::lround(std::max(0.0, std::min(seconds, 3.6e8)));
  char buf[32];
  if (s >= 3600) std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

void Progress::Done() {
  if (observed_) {
    Observe(fraction_, "", true);
    observed_ = false;
  }
  if (quiet_ || !shown_) return;
  static const bool tty = isatty(2);
  if (tty) std::cerr << "\n" << std::flush;
  shown_ = false;
}

namespace {

// Rejects NaN and infinities anywhere in a json tree, naming the path.
void CheckFiniteTree(const nlohmann::json& j, const std::string& path) {
  if (j.is_number_float() && !std::isfinite(j.get<double>()))
    throw NonFiniteResult(path);
  if (j.is_object())
    for (auto it = j.begin(); it != j.end(); ++it) CheckFiniteTree(*it, path + "/" + it.key());
  if (j.is_array())
    for (size_t i = 0; i < j.size(); ++i) CheckFiniteTree(j[i], path + "/" + std::to_string(i));
}

}  // namespace

void Outputs::AddJson(const std::string& name, const nlohmann::json& value) {
  CheckFiniteTree(value, name);
  Add(name, value.dump(2) + "\n");
}

void Outputs::WriteAll(const std::string& dir) const {
  OutputFolder folder(dir);
  folder.Commit(*this);
}

namespace {

// The temporary folder of the run in progress, for the signal thread; the mutex also covers the
// whole Commit, so that an interrupt never lands between writing and renaming.
std::mutex& OutputMutex() {
  static std::mutex m;
  return m;
}
std::string& ActiveTemporary() {
  static std::string path;
  return path;
}

[[noreturn]] void OutputFail(const std::string& what, const std::string& path, int err) {
  throw StudyError("--out " + path + ": " + what + ": " + std::strerror(err));
}

void WriteWholeFile(const std::string& path, const std::string& content) {
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) OutputFail("cannot create " + fs::path(path).filename().string(), path, errno);
  size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      close(fd);
      OutputFail("cannot write " + fs::path(path).filename().string(), path, err);
    }
    done += static_cast<size_t>(n);
  }
  if (close(fd) != 0) OutputFail("cannot write " + fs::path(path).filename().string(), path, errno);
}

// The list of the files a run wrote, kept in its output folder: only those are ever replaced. A
// line "NAME/" lists a sub-folder, which follows the same rule (its own list).
constexpr char kManifest[] = ".camopt_manifest";

std::string NotReplaceableAt(const fs::path& dir, int depth) {
  std::error_code ec;
  std::vector<std::string> names;
  bool has_manifest = false;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    // Never a link: is_directory/is_regular_file follow it, the status of the entry itself does not.
    const fs::file_status st = entry.symlink_status(ec);
    if (fs::is_directory(st)) names.push_back(name + "/");
    else if (fs::is_regular_file(st) && name == kManifest) has_manifest = true;
    else if (fs::is_regular_file(st)) names.push_back(name);
    else return "it holds " + name + ", not a file camopt wrote";
  }
  if (ec) return "it cannot be listed: " + ec.message();
  if (names.empty() && !has_manifest) return "";
  // The swap moves the old folder aside and removes it: a folder the user made read-only would
  // be swapped out and then left behind under a temporary name.
  if (access(dir.c_str(), W_OK) != 0) return "it is read-only";
  if (!has_manifest)
    return "it holds files and no " + std::string(kManifest) +
           " list of a camopt result: files of yours, or a result of an older camopt — remove it " +
           "yourself if it is one";
  std::ifstream in(dir / kManifest);
  std::set<std::string> listed;
  for (std::string line; std::getline(in, line);) listed.insert(line);
  for (const std::string& n : names)
    if (!listed.count(n)) return "it holds " + n + ", which camopt did not write";
  // A listed sub-folder (a sweep's cases/, each case's folder) follows the same rule.
  for (const std::string& n : names) {
    if (n.back() != '/') continue;
    if (depth >= 3) return "it holds " + n + ", deeper than camopt writes";
    const std::string why = NotReplaceableAt(dir / n.substr(0, n.size() - 1), depth + 1);
    if (!why.empty()) return "in " + n + ": " + why;
  }
  return "";
}

}  // namespace

std::string NotReplaceable(const fs::path& dir) { return NotReplaceableAt(dir, 0); }

void WriteManifest(const std::string& dir, const std::vector<std::string>& entries) {
  std::string manifest;
  for (const std::string& e : entries) manifest += e + "\n";
  WriteWholeFile((fs::path(dir) / kManifest).string(), manifest);
}

bool AddToManifest(const std::string& dir, const std::string& entry) {
  const fs::path list = fs::path(dir) / kManifest;
  std::error_code ec;
  if (!fs::is_regular_file(fs::symlink_status(list, ec))) return false;
  std::ifstream in(list);
  std::string manifest;
  for (std::string line; std::getline(in, line);) {
    if (line == entry) return true;
    manifest += line + "\n";
  }
  const std::string tmp = list.string() + ".camopt-tmp-" + std::to_string(getpid());
  try {
    if (in.bad()) OutputFail("cannot read", list.string(), errno);
    WriteWholeFile(tmp, manifest + entry + "\n");
    if (rename(tmp.c_str(), list.c_str()) != 0) OutputFail("cannot replace", list.string(), errno);
  } catch (const StudyError& e) {
    fs::remove(tmp, ec);
    // The folder's own list, not an --out the user gave: "DIR: cannot add NAME to its list (…)".
    throw StudyError(dir + ": cannot add " + entry + " to its " + kManifest + " (" + e.what() + ")");
  }
  return true;
}

void CheckNotInside(const std::string& file, const std::string& out, const std::string& what) {
  std::error_code fe, oe;
  const fs::path f = fs::weakly_canonical(fs::absolute(file), fe);
  const fs::path o = fs::weakly_canonical(fs::absolute(out), oe);
  if (fe || oe || o.empty() || !fs::is_directory(o, oe)) return;
  // f is inside o when o is a prefix of f, element by element.
  auto fi = f.begin();
  for (auto oi = o.begin(); oi != o.end(); ++oi, ++fi)
    if (fi == f.end() || *fi != *oi) return;
  throw StudyError("--out " + out + ": the " + what + " " + file + " is inside the folder this run replaces; " +
                   "choose another --out (or copy the file out of it first)");
}

std::string SiblingPrefix(const fs::path& dir) {
  std::string name = dir.filename().string();
  constexpr size_t kSuffixRoom = 32;  // ".camopt-sweep-lock", ".camopt-tmp-" and a pid
  if (name.size() + kSuffixRoom > NAME_MAX) {
    size_t keep = NAME_MAX - kSuffixRoom;
    while (keep > 0 && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80) --keep;  // a UTF-8 start
    name.resize(keep);
  }
  return dir.has_parent_path() ? (dir.parent_path() / name).string() : name;
}

namespace {

// Sibling folders `<dir>.camopt-tmp-<pid>` / `.camopt-old-<pid>` of runs that were killed
// (SIGKILL leaves them: no handler runs) are removed when their process no longer exists.
void RemoveStaleTemporaries(const fs::path& dir) {
  const fs::path parent = dir.has_parent_path() ? dir.parent_path() : fs::path(".");
  const std::string stem = fs::path(SiblingPrefix(dir)).filename().string();
  // readdir and a compare of the raw names: a results folder beside thousands of others (a
  // sweep's, a shared /tmp) is listed at a few instructions per entry, not a path object each.
  DIR* d = opendir(parent.c_str());
  if (d == nullptr) return;
  std::vector<std::string> stale;
  while (const dirent* e = readdir(d)) {
    const char* name = e->d_name;
    if (std::strncmp(name, stem.data(), stem.size()) != 0) continue;
    for (const char* tag : {".camopt-tmp-", ".camopt-old-"}) {
      const size_t tag_size = std::strlen(tag);
      if (std::strncmp(name + stem.size(), tag, tag_size) != 0) continue;
      const std::string digits = name + stem.size() + tag_size;
      if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
      const pid_t pid = static_cast<pid_t>(std::stol(digits));
      if (pid == getpid() || (kill(pid, 0) != 0 && errno == ESRCH)) stale.emplace_back(name);
    }
  }
  closedir(d);
  for (const std::string& name : stale) {
    std::error_code rm;
    fs::remove_all(parent / name, rm);
  }
}

}  // namespace

fs::path OutFolderPath(const std::string& dir) {
  fs::path out = fs::path(dir).lexically_normal();
  if (out.has_parent_path() && !out.has_filename()) out = out.parent_path();  // "out/"
  if (out.empty() || out == "." || out == ".." || out == "/" || out.filename() == "..")
    throw StudyError("--out " + dir + ": expected a folder name for the results, found " +
                     (dir.empty() ? std::string("nothing") : dir));
  return out;
}

OutputFolder::OutputFolder(const std::string& dir) {
  fs::path out = OutFolderPath(dir);
  // A symbolic link to a folder: the results go to the folder it names (a rename onto the link
  // would fail, "not a folder").
  struct stat st {};
  std::error_code link_ec;
  if (lstat(out.c_str(), &st) == 0 && S_ISLNK(st.st_mode) && fs::is_directory(out, link_ec))
    out = fs::canonical(out, link_ec);
  dir_ = out.string();
  if (lstat(dir_.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode))
      throw StudyError("--out " + dir + ": exists and is not a folder");
    const std::string why = NotReplaceable(out);
    if (!why.empty())
      throw StudyError("--out " + dir + ": the folder is not a camopt result camopt may replace (" + why +
                       "); choose a new or empty folder");
  } else if (errno != ENOENT) {
    OutputFail("cannot use the folder", dir, errno);
  }
  const fs::path parent = out.has_parent_path() ? out.parent_path() : fs::path(".");
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) throw StudyError("--out " + dir + ": cannot create " + parent.string() + ": " + ec.message());
  RemoveStaleTemporaries(out);
  const std::string tmp = SiblingPrefix(out) + ".camopt-tmp-" + std::to_string(getpid());
  fs::remove_all(tmp, ec);  // left by an earlier process with the same id
  if (mkdir(tmp.c_str(), 0755) != 0) OutputFail("cannot create a folder next to it", dir, errno);
  std::lock_guard<std::mutex> lock(OutputMutex());
  tmp_ = tmp;
  ActiveTemporary() = tmp_;
}

OutputFolder::~OutputFolder() {
  std::lock_guard<std::mutex> lock(OutputMutex());
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(tmp_, ec);
  }
  if (ActiveTemporary() == tmp_) ActiveTemporary().clear();
}

void WriteFilesInto(const std::string& dir, const Outputs& outputs) {
  // A name "sub/file" (one level: e.g. inspection/disc_1.csv) goes into a sub-folder with its own
  // list of the files camopt wrote there (NotReplaceable reads it when the folder is replaced).
  std::map<std::string, std::vector<std::string>> sub;
  for (const auto& [name, content] : outputs.files()) {
    if (const size_t slash = name.find('/'); slash != std::string::npos) {
      const std::string folder = name.substr(0, slash);
      if (!sub.count(folder) && mkdir((fs::path(dir) / folder).c_str(), 0755) != 0 && errno != EEXIST)
        OutputFail("cannot create " + folder, dir, errno);
      sub[folder].push_back(name.substr(slash + 1));
    }
    WriteWholeFile((fs::path(dir) / name).string(), content);
  }
  for (const auto& [folder, names] : sub) WriteManifest((fs::path(dir) / folder).string(), names);
}

std::vector<std::string> ManifestEntries(const Outputs& outputs) {
  std::vector<std::string> entries;
  for (const auto& [name, content] : outputs.files()) {
    const size_t slash = name.find('/');
    std::string e = slash == std::string::npos ? name : name.substr(0, slash + 1);
    if (entries.empty() || entries.back() != e) entries.push_back(std::move(e));
  }
  return entries;
}

void MoveFolderIn(const std::string& tmp, const std::string& dir) {
  // One rename makes the new results visible: an atomic exchange with the previous folder when
  // there is one (Linux renameat2), a plain rename otherwise.
  if (rename(tmp.c_str(), dir.c_str()) != 0) {
    if (errno != ENOTEMPTY && errno != EEXIST) OutputFail("cannot move the results in", dir, errno);
    if (renameat2(AT_FDCWD, tmp.c_str(), AT_FDCWD, dir.c_str(), RENAME_EXCHANGE) != 0) {
      // No exchange on this file system: move the old folder aside, then the new one in.
      const std::string old = SiblingPrefix(dir) + ".camopt-old-" + std::to_string(getpid());
      if (rename(dir.c_str(), old.c_str()) != 0)
        OutputFail("cannot move the previous results aside", dir, errno);
      if (rename(tmp.c_str(), dir.c_str()) != 0) {
        const int err = errno;
        rename(old.c_str(), dir.c_str());
        OutputFail("cannot move the results in", dir, err);
      }
      std::error_code ec;
      fs::remove_all(old, ec);
      return;
    }
    std::error_code ec;
    fs::remove_all(tmp, ec);  // now the previous run
  }
}

void OutputFolder::Commit(const Outputs& outputs) {
  std::lock_guard<std::mutex> lock(OutputMutex());
  const std::vector<std::string> manifest = ManifestEntries(outputs);
  try {
    WriteFilesInto(tmp_, outputs);
    WriteManifest(tmp_, manifest);
  } catch (const StudyError& e) {
    // The message names the folder the user gave, not the temporary sibling (a full disk, a quota).
    std::string m = e.what();
    for (size_t at = m.find(tmp_); at != std::string::npos; at = m.find(tmp_, at + dir_.size()))
      m.replace(at, tmp_.size(), dir_);
    throw StudyError(m);
  }
  // Checked again at the swap: files a user added to the folder while the study ran are theirs.
  struct stat st {};
  if (lstat(dir_.c_str(), &st) == 0) {
    const std::string why = S_ISDIR(st.st_mode) ? NotReplaceable(dir_) : "it is no longer a folder";
    if (!why.empty())
      throw StudyError("--out " + dir_ + ": the folder changed while the study ran (" + why +
                       "); nothing was replaced, choose a new or empty folder");
  }
  MoveFolderIn(tmp_, dir_);
  committed_ = true;
}

void RemoveTemporaryOutputForInterrupt() {
  std::lock_guard<std::mutex> lock(OutputMutex());
  if (!ActiveTemporary().empty()) {
    std::error_code ec;
    fs::remove_all(ActiveTemporary(), ec);
    ActiveTemporary().clear();
  }
}

std::string CheckCommonFields(const Node& root) {
  if (!root.json().is_object()) root.Fail("a study object");
  if (!root.Has("study") && root.Has("sweep") && root.Has("vary"))
    root.FailWith("this is a sweep file (it has \"sweep\" and \"vary\", no \"study\"): run it with "
                  "`camopt sweep " + root.file() + " --out DIR`");
  const Node kind_node = root["study"];
  const std::string kind = kind_node.String();
  if (!FindKind(kind)) {
    std::string known;
    for (const auto& k : StudyKinds()) known += (known.empty() ? "" : ", ") + k;
    kind_node.Fail("a known study kind (" + known + ")");
  }
  // Every kind takes a name and a description (free text; the schemas say "type": "string").
  for (const char* text : {"name", "description"})
    if (root.Has(text)) root[text].String();
  return kind;
}

void CheckStudy(const nlohmann::json& study, const std::string& file) {
  const Node root(&study, file, "");
  const std::string kind = CheckCommonFields(root);
  FindKind(kind)->check(root);
}

void SettleStatus(const std::string& kind, const nlohmann::json& study, Outputs& outputs) {
  if (!outputs.result()) {
    if (!outputs.status()) outputs.SetStatus(Status::kLimitsMet);
    return;
  }
  const nlohmann::json& r = *outputs.result();
  const RunFacts& facts = outputs.run_facts();
  const std::string& why = facts.warning;
  if (!outputs.status() && facts.converged == false)
    outputs.SetStatus(Status::kNotConverged, kind + ": not converged" + (why.empty() ? "" : ": " + why));
  if (!outputs.status() && facts.feasible == false)
    outputs.SetStatus(Status::kInfeasible, kind + ": no feasible design" + (why.empty() ? "" : ": " + why));
  const HeadlineTable table = EvaluateHeadlines(kind, study, r);
  if (!outputs.status() && table.exceeded.empty()) outputs.SetStatus(Status::kLimitsMet);
  if (!outputs.status())
    outputs.SetStatus(Status::kLimitsExceeded, VerdictLine(table, Status::kLimitsExceeded, ""));
  // Asked means answered: a block the study asks for and result.json lacks is an incomplete
  // answer, never exit 0 (a sizing without a design is already exit 3: its blocks have nothing
  // to be computed on).
  if (const std::vector<std::string> missing = MissingAnswers(kind, study, r);
      !missing.empty() && ExitCode(*outputs.status(), false) == 0) {
    std::string list;
    for (const std::string& m : missing) list += (list.empty() ? "" : ", ") + m;
    outputs.SetStatus(Status::kNotConverged, kind + ": asked for but not computed: " + list +
                                                 (why.empty() ? "" : " (" + why + ")"));
  }
  // A verified answer whose own headlines break a limit would say two things: the verdict's
  // limits are the ones the verification must have checked.
  if (IsVerified(*outputs.status()) && !table.exceeded.empty())
    outputs.SetStatus(Status::kNotVerifiable,
                      "the verification passed but " + VerdictLine(table, Status::kLimitsExceeded, "") +
                          " (the accurate check and the headline limits disagree: a camopt defect, please report it)");
}

Outputs RunStudy(const nlohmann::json& study, const RunContext& ctx) {
  const Node root(&study, ctx.study_file, "");
  const std::string kind = CheckCommonFields(root);
  const KindDescriptor& described = *FindKind(kind);
  Outputs outputs;
  const std::vector<std::string> implausible = Timed(outputs.phases(), "checks", [&] {
    CheckWorkLimits(study, ctx.study_file, ctx.max_work_factor);
    return PlausibilityWarnings(study);
  });
  if (!ctx.quiet)
    for (const auto& w : implausible) std::cerr << "camopt: warning: " << ctx.study_file << ": " << w << "\n";
  try {
    described.run(root, ctx, outputs);  // timed as its phases parse, solve and files
  } catch (const NonFiniteResult& e) {
    throw StudyError(ctx.study_file + ": /: expected values the models can compute, found a " +
                     "study whose result " + e.what() + " is not a finite number (check for " +
                     "extreme sizes, such as 1e308 mm or 1e-6 mm)");
  }
  // The one status of the answer (SettleStatus), stamped on the result, which is then written once.
  const double status_cpu = ProcessCpuSeconds(), status_wall = WallSeconds();
  // Every kind declares its result (studies/archive.h) and hands it over with Outputs::SetResult;
  // a result.json written as text would bypass the status and the stamp.
  if (outputs.files().count("result.json"))
    throw std::logic_error("study kind " + kind + " wrote result.json itself: hand its declared Result to "
                           "Outputs::SetResult");
  if (nlohmann::json* result = outputs.result()) {
    SettleStatus(kind, study, outputs);
    // Provenance and the warnings, the same fields for every kind (studies/provenance.h), added
    // to the result itself: result.json is written once.
    nlohmann::json& stamped = *result;
    stamped["status"] = StatusName(*outputs.status());
    if (!outputs.status_reason().empty()) stamped["status_reason"] = outputs.status_reason();
    else stamped.erase("status_reason");
    // "verified" is a view of the status: a kind that verifies cannot say it beside exit 3.
    if (stamped.contains("verified")) stamped["verified"] = IsVerified(*outputs.status());
    stamped["camopt_version"] = CamoptVersion();
    stamped["study_sha256"] = ctx.study_sha256.empty() ? Sha256Hex(study.dump()) : ctx.study_sha256;
    nlohmann::json& warnings = stamped["warnings"];
    if (!warnings.is_array()) warnings = nlohmann::json::array();
    for (const auto& w : implausible) warnings.push_back(w);
    outputs.AddJson("result.json", stamped);
  }
  if (!outputs.status()) outputs.SetStatus(Status::kLimitsMet);
  outputs.phases().push_back({"status", ProcessCpuSeconds() - status_cpu, WallSeconds() - status_wall});
  Timed(outputs.phases(), "report", [&] {
    AddDatasheet(kind, outputs);
    AddReport(kind, study, outputs);  // last: it shows every other file
  });
  return outputs;
}

double ProcessCpuSeconds() { return sizing::ProcessCpuSeconds(); }
double WallSeconds() { return sizing::WallSeconds(); }

RunAnswer RunStudyFile(const std::string& file, const std::string& out_dir, const RunContext& ctx) {
  RunContext c = ctx;
  c.study_file = file;
  const InputLimits& limits = CurrentInputLimits();
  std::vector<PhaseTime> read;
  std::string text;
  const nlohmann::json study = Timed(read, "read", [&] {
    text = ReadFileCapped(file, limits.max_file_bytes, "file");
    return ParseStudyText(text, file, limits.max_depth);
  });
  c.study_sha256 = Sha256Hex(text);
  CheckNotInside(file, out_dir, "study file");
  OutputFolder folder(out_dir);  // a bad --out is reported before the work
  Outputs outputs = RunStudy(study, c);
  outputs.phases().insert(outputs.phases().begin(), read.front());
  Timed(outputs.phases(), "write", [&] { folder.Commit(outputs); });
  const RunAnswer answer{*outputs.status(), outputs.status_reason(), outputs.phases(),
                         outputs.result() ? std::make_shared<const nlohmann::json>(*outputs.result()) : nullptr};
  if (ExitCode(answer.status, ctx.strict) != 0) throw StudyIncomplete(answer);
  return answer;
}

namespace {
std::string KnownKinds() {
  std::string known;
  for (const auto& k : StudyKinds()) known += (known.empty() ? "" : ", ") + k;
  return known;
}
}  // namespace

const std::string& StudySchema(const std::string& kind) {
  // Every kind is declared once (studies/kind.h): its schema is emitted from the declaration.
  if (const std::string* declared = DeclaredSchema(kind)) return *declared;
  throw StudyError("schema " + kind + ": expected a known study kind (" + KnownKinds() + "), found " + kind);
}

const std::string& StudyResultSchema(const std::string& kind) {
  if (const std::string* declared = DeclaredResultSchema(kind)) return *declared;
  throw StudyError("schema " + kind + " --result: expected a known study kind (" + KnownKinds() + "), found " + kind);
}

void AddRunStampToResultSchema(nlohmann::ordered_json& schema) {
  // What RunStudy adds to every kind's result.json (above): the one status and its reason, the
  // version and the study's hash, the warnings.
  nlohmann::ordered_json& p = schema["properties"];
  nlohmann::ordered_json statuses = nlohmann::ordered_json::array();
  for (Status st : kAllStatuses)
    statuses.push_back(StatusName(st));
  p["status"] = {{"description", "the answer's one status, from which the exit code, the verdict and `verified` follow (docs/studies.md)"},
                 {"enum", statuses}};
  p["status_reason"] = {{"description", "why the answer is not what was asked, or what a verified answer did not prove"},
                        {"type", "string"}};
  p["camopt_version"] = {{"description", "the camopt that wrote the result"}, {"type", "string"}};
  p["study_sha256"] = {{"description", "SHA-256 of the study file as read"}, {"type", "string"}};
  p["warnings"] = {{"description", "the run's warnings, also printed on stderr"},
                   {"type", "array"}, {"items", {{"type", "string"}}}};
  nlohmann::ordered_json& required = schema["required"];
  for (const char* always : {"status", "camopt_version", "study_sha256", "warnings"})
    if (std::find(required.begin(), required.end(), always) == required.end()) required.push_back(always);
  // additionalProperties after the properties, for the reader
  if (schema.contains("additionalProperties")) {
    nlohmann::ordered_json closed = std::move(schema["additionalProperties"]);
    schema.erase("additionalProperties");
    schema["additionalProperties"] = std::move(closed);
  }
}

double Finite(double value, const std::string& what) {
  if (!std::isfinite(value)) throw NonFiniteResult(what);
  return value;
}

}  // namespace camopt::studies
