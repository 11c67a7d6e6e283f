// The study registry, the run context and the set of output files of one run.
//
// A study kind declares its Input and its Result (each with a `Serialize`, studies/archive.h) and a
// Run, and registers them once with CAMOPT_REGISTER_KIND (studies/kind.h), with whatever else it has
// (knobs, work estimate, report rows, …); docs/studies.md, "Adding a kind". RunStudy runs it,
// stamps the Result (Outputs::SetResult) and writes result.json.
#pragma once

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "optimizers/cancel.h"
#include "studies/archive.h"
#include "studies/input.h"
#include "studies/status.h"

namespace camopt::studies {

/// A progress line on stderr for long work ("name:  42.0%  0:12 elapsed, ETA 0:17  detail"),
/// rewritten in place on a terminal at most ~10 times a second (a plain line every 2 s into a file
/// or pipe); silent when quiet. The ETA is elapsed·(1 − f)/f, shown once 1% is done and a second
/// has passed (a linear extrapolation: work that is not uniform in the fraction makes it move).
class Progress {
 public:
  Progress(std::string label, bool quiet)
      : label_(std::move(label)), quiet_(quiet), start_(std::chrono::steady_clock::now()) {}
  ~Progress() { Done(); }
  /// fraction in [0, 1]. Throws StudyCancelled when a cancellation was asked for (RequestCancel):
  /// every long stage reports progress, so this is where a run stops.
  void Update(double fraction, const std::string& detail = "");
  void Done();

 private:
  std::string label_;
  bool quiet_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_{};
  std::chrono::steady_clock::time_point last_observed_{};
  bool observed_ = false;
  double fraction_ = 0.0;
  void Observe(double fraction, const std::string& detail, bool done);
};

/// One progress report as an observer sees it: the line's label, the fraction done in [0, 1], the
/// elapsed time and the ETA in seconds (negative while there is none) and the detail text; `done`
/// on the last report of a Progress (Done or destruction after at least one Update).
struct ProgressEvent {
  std::string label;
  double fraction = 0.0;
  double elapsed_s = 0.0;
  double eta_s = -1.0;
  std::string detail;
  bool done = false;
};

/// A process-wide observer of every Progress, whatever `quiet` says (for an embedding program: the
/// Python module's callback, a server's run log). It is called from the thread that calls
/// Update, at most every 100 ms per Progress apart from the first and the last report, and must not
/// throw. An empty function removes it. Returns the previous observer.
std::function<void(const ProgressEvent&)> SetProgressObserver(std::function<void(const ProgressEvent&)> observer);

/// Cooperative cancellation (optimizers/cancel.h): RequestCancel() makes the next
/// Progress::Update and the solvers' next iteration throw StudyCancelled, which every handler of a
/// run lets through (it is not a std::exception): RunStudy, a sweep's cases and its thread pool
/// unwind without writing anything. The Python module asks for it on Ctrl-C.
using StudyCancelled = optimizers::Cancelled;
using optimizers::CancelRequested;
using optimizers::ClearCancel;
using optimizers::RequestCancel;

/// A duration as a person reads it on a progress line: "0:07", "12:34", "1:02:03".
std::string ClockText(double seconds);

struct RunContext {
  RunContext() = default;
  /// The common short form {file, quiet}; the other members keep their defaults.
  RunContext(std::string file, bool quiet_run) : study_file(std::move(file)), quiet(quiet_run) {}

  std::string study_file;
  bool quiet = false;
  /// Multiplies every work cap of studies/work_limits.h (--max-work-factor).
  double max_work_factor = 1.0;
  /// SHA-256 of the study as read (RunStudyFile: the file's bytes); empty: RunStudy takes that of
  /// the study's compact JSON text (nlohmann::json::dump()), e.g. for a study given as a dict.
  std::string study_sha256;
  /// --strict: a verified design not proven optimal, or an analysis over a limit, ends with exit 3
  /// (studies/status.h, ExitCode).
  bool strict = false;
};

/// Files a study produces, kept in memory until the whole run succeeded, then written together:
/// results are written whole or not at all.
/// One phase of a run and what it took: the process's CPU time (user + system, every thread) and
/// the wall time, in seconds (`camopt run --timings`, scripts/time_examples.py).
struct PhaseTime {
  std::string name;
  double cpu_s = 0.0, wall_s = 0.0;
};

/// The process's CPU time so far [s] (user + system, every thread: CLOCK_PROCESS_CPUTIME_ID).
double ProcessCpuSeconds();
/// A monotonic wall clock [s].
double WallSeconds();

/// Runs f() and appends its time to `phases` as `name`; returns what f returns.
template <typename F>
auto Timed(std::vector<PhaseTime>& phases, const char* name, F&& f) {
  const double cpu = ProcessCpuSeconds(), wall = WallSeconds();
  struct Record {
    std::vector<PhaseTime>& phases;
    const char* name;
    double cpu, wall;
    ~Record() { phases.push_back({name, ProcessCpuSeconds() - cpu, WallSeconds() - wall}); }
  } record{phases, name, cpu, wall};
  return f();
}

class Outputs {
 public:
  void Add(const std::string& name, std::string content) { files_[name] = std::move(content); }
  void AddJson(const std::string& name, const nlohmann::json& value);
  const std::map<std::string, std::string>& files() const { return files_; }

  /// result.json, from the kind's declared Result (WriteResult) with the members that decide the
  /// status (CollectRunFacts): RunStudy reads the status from them, adds its stamp (status,
  /// version, hash, warnings) and writes the file once. @throws NonFiniteResult (WriteResult).
  template <typename R>
  void SetResult(const R& result) {
    SetResultJson(WriteResult(result), CollectRunFacts(result));
  }
  /// result.json as JSON with its facts (SetResult; RunStudy's stamped result).
  void SetResultJson(nlohmann::json result, RunFacts facts = {}) {
    result_ = std::move(result);
    facts_ = std::move(facts);
  }
  /// result.json as JSON (after RunStudy: as written, stamp included), or nullptr when the run
  /// made none.
  const nlohmann::json* result() const { return result_ ? &*result_ : nullptr; }
  nlohmann::json* result() { return result_ ? &*result_ : nullptr; }
  const RunFacts& run_facts() const { return facts_; }
  /// Writes every file into dir at once (an OutputFolder: temporary sibling folder, one rename).
  void WriteAll(const std::string& dir) const;

  /// The status of the answer (studies/status.h), set by a sizing or tuning kind (SizingStatus)
  /// or by an analysis whose solver did not converge; RunStudy sets an analysis' from the limits of
  /// its verdict. `reason` says why when the answer is not what was asked (the blocking limit,
  /// what would fix it), or what a verified answer did not prove.
  void SetStatus(Status status, std::string reason = "") {
    status_ = status;
    status_reason_ = std::move(reason);
  }
  const std::optional<Status>& status() const { return status_; }
  const std::string& status_reason() const { return status_reason_; }
  /// The phases of the run so far (parse, solve, files, …), in order.
  std::vector<PhaseTime>& phases() { return phases_; }
  const std::vector<PhaseTime>& phases() const { return phases_; }
  /// Why the answer is not what was asked (a status of exit code 3 without --strict), "" when it is.
  std::string incomplete() const {
    if (!status_ || ExitCode(*status_, false) == 0) return "";
    return std::string(StatusName(*status_)) + (status_reason_.empty() ? "" : ": " + status_reason_);
  }

 private:
  std::map<std::string, std::string> files_;
  std::optional<nlohmann::json> result_;
  RunFacts facts_;
  std::optional<Status> status_;
  std::string status_reason_;
  std::vector<PhaseTime> phases_;
};

/// Thrown by RunStudyFile after the outputs were written when the run's status gives exit code 3
/// (studies/status.h; with RunContext::strict, also a verified design not proven optimal or an
/// analysis over a limit); what() is the status and its reason.
/// The answer of a run as its status (studies/status.h) and the reason that goes with it.
struct RunAnswer {
  Status status = Status::kLimitsMet;
  std::string reason;
  std::vector<PhaseTime> phases;  ///< read, checks, parse, solve (then a sizing's verification, limit costs), files, status, report, write
  std::shared_ptr<const nlohmann::json> result;  ///< result.json as written (null: none)
};

class StudyIncomplete : public std::runtime_error {
 public:
  explicit StudyIncomplete(RunAnswer answer)
      : std::runtime_error(std::string(StatusName(answer.status)) + (answer.reason.empty() ? "" : ": " + answer.reason)),
        answer_(std::move(answer)) {}
  const RunAnswer& answer() const { return answer_; }

 private:
  RunAnswer answer_;
};

/// --out as a folder path ("out/" is "out"), for every writer (OutputFolder, the sweep); throws
/// StudyError on ".", "..", "/" or nothing.
std::filesystem::path OutFolderPath(const std::string& dir);

/// The path the siblings camopt makes beside an output folder `dir` start with (the temporary
/// `.camopt-tmp-<pid>`, the set-aside `.camopt-old-<pid>`, a sweep's `.camopt-sweep` and its
/// `-lock`): `dir` itself, its name cut (at a UTF-8 character's start) to leave 32 bytes within
/// NAME_MAX, so that a folder name of up to 255 bytes can still take results.
std::string SiblingPrefix(const std::filesystem::path& dir);

/// The output folder of one run, filled all at once. The constructor checks that `dir` can take
/// results and creates the sibling temporary folder `<dir>.camopt-tmp-<pid>` (so a bad --out is
/// reported before any work, with the operating system's reason, as a StudyError: exit 2);
/// Commit writes every file there and swaps the folder in with one rename, the previous run
/// staying in place until that rename. An existing `dir` is replaced only when NotReplaceable
/// allows it, checked here and again at the swap: camopt never deletes files it did not write.
/// Destroying an uncommitted OutputFolder removes the temporary folder.
class OutputFolder {
 public:
  explicit OutputFolder(const std::string& dir);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;
  void Commit(const Outputs& outputs);
  const std::string& temporary() const { return tmp_; }

 private:
  std::string dir_, tmp_;
  bool committed_ = false;
};

/// The one output-folder rule of every writer (`camopt run`, `camopt sweep`, the studio's runs,
/// the Python API): why an existing folder must not be replaced, or "" when it may be. It may be
/// when it is empty, or when it holds the list `.camopt_manifest` of a previous camopt run and
/// nothing else than what that list names — files, and sub-folders (a line "NAME/") that follow
/// the same rule. A user's file, a link, a file added after the run: the folder is theirs.
std::string NotReplaceable(const std::filesystem::path& dir);

/// Writes the list of what a run put into `dir` (file names; "NAME/" for a sub-folder with its
/// own list), which makes `dir` replaceable by the next run (NotReplaceable).
void WriteManifest(const std::string& dir, const std::vector<std::string>& entries);

/// Adds `entry` (a file name, or "NAME/" for a sub-folder with its own list) to the list of what
/// camopt wrote in `dir`, so that the next run into `dir` may replace it (`camopt export` adds its
/// folder export/ to the result's list). The list is replaced whole (a temporary file, one
/// rename). Returns false, writing nothing, when `dir` has no list (not a camopt result).
bool AddToManifest(const std::string& dir, const std::string& entry);

/// Throws StudyError (exit 2) when `file` (a study, a sweep, its base) lies inside the existing
/// folder `out` that a run would replace: the run would delete its own input.
void CheckNotInside(const std::string& file, const std::string& out, const std::string& what);

/// Writes every file of `outputs` into the existing folder `dir` (StudyError with the operating
/// system's reason otherwise). OutputFolder::Commit and the sweep's merged output use it.
void WriteFilesInto(const std::string& dir, const Outputs& outputs);
/// The entries of a folder's list for `outputs`: each file, and "sub/" once for the files of a
/// sub-folder (which WriteFilesInto lists in the sub-folder itself).
std::vector<std::string> ManifestEntries(const Outputs& outputs);

/// Replaces `dir` by the complete folder `tmp` with one rename (an atomic exchange when `dir`
/// exists; the previous folder is then removed). StudyError with the operating system's reason.
void MoveFolderIn(const std::string& tmp, const std::string& dir);

/// For the CLI's signal thread: removes the temporary folder of the run in progress (waiting for a
/// Commit under way to finish, so that `--out` is left either old or new, never mixed).
void RemoveTemporaryOutputForInterrupt();

/// The registered study kinds, sorted (studies/kind.h).
std::vector<std::string> StudyKinds();

/// The checks every kind shares before its own: a study object, a known "study" kind, and "name"
/// and "description" strings when given (StudyError otherwise). Returns the kind.
std::string CheckCommonFields(const Node& root);

/// Checks a study as `camopt run` does before running it (CheckCommonFields, then the kind's
/// Parse), without running it: StudyError (exit 2) for what the run would refuse as bad input.
/// The work limits (studies/work_limits.h) are not checked. tests/schema_parser_agreement_test.cc
/// compares it with the kind's JSON Schema.
void CheckStudy(const nlohmann::json& study, const std::string& file);

/// A fidelity setting of a study kind, refined and coarsened by `camopt run --convergence`
/// (studies/convergence.h).
struct FidelityKnob {
  std::string name;                ///< e.g. "angle_steps"
  std::vector<std::string> paths;  ///< JSON pointers in the study file, all set together
  nlohmann::json default_value;    ///< the kind's value when the file does not give it (number or array)
  double refine = 2;               ///< refined = value × refine, coarsened = value / refine (0.1: ÷10)
  bool integer = false;            ///< whole numbers (rounded)
  /// The error of an output goes as h^order with h ∝ 1/refine per refinement (Richardson);
  /// 0: not known (the error is the difference to the finest run).
  double order = 0;
  std::string note;                ///< what the knob is, for convergence.json
};

/// What `--convergence` varies and reads for one study (it may depend on the file: stages asked,
/// speeds, elements).
struct Fidelity {
  std::vector<FidelityKnob> knobs;
  std::vector<std::string> headlines;  ///< JSON pointers into result.json
  std::string no_knob;                 ///< why there is no knob, when knobs is empty
  /// Settings applied to the refined and coarsened runs only (e.g. switch a kind's own error
  /// estimate off): they change the cost, not the headline outputs.
  nlohmann::json variant_overrides = nlohmann::json::object();  ///< JSON pointer → value
};

using FidelityOf = std::function<Fidelity(const nlohmann::json& study)>;

/// Runs the study in file: parses, checks the work limits, dispatches on "study", writes into
/// out_dir (checked first); returns the answer's status. Throws StudyError for bad input (exit 2),
/// StudyIncomplete after writing a result whose status gives exit 3 (ctx.strict included), and
/// std::exception for other failures.
RunAnswer RunStudyFile(const std::string& file, const std::string& out_dir, const RunContext& ctx);

/// The one status of a run's answer (studies/status.h), from its typed facts and its result
/// (Outputs::SetResult): a sizing or tuning kind has set its own; a result whose facts say it did
/// not converge (or found nothing feasible) gets that, with the kind's own warning as the reason;
/// an analysis gets its verdict's (EvaluateHeadlines over the kind's limits); an asked-for block
/// the result lacks is not_converged; a verified answer over a headline limit not_verifiable.
void SettleStatus(const std::string& kind, const nlohmann::json& study, Outputs& outputs);

/// Runs an already parsed study, returning its outputs without writing them. result.json gets
/// "camopt_version", "study_sha256" and "warnings" (the kind's own and PlausibilityWarnings of
/// studies/provenance.h, also printed on stderr unless ctx.quiet).
Outputs RunStudy(const nlohmann::json& study, const RunContext& ctx);

/// A json number that is never NaN or infinite: throws NonFiniteResult naming the field
/// otherwise, so no non-finite number can reach a result file.
double Finite(double value, const std::string& what);

}  // namespace camopt::studies

