// `camopt sweep SWEEP.json --out DIR`: one base study run over many cases (docs/studies.md,
// "Sweeps"). A case is the base study with the sweep's variations written into it by JSON
// pointer; it runs in-process through the study registry (RunStudy), on a pool of threads and,
// in a build with MPI, on every rank of `mpirun -n N`. Cases are numbered in the order the design
// lists them and assigned to ranks round-robin by that number, so the merged table is the same
// whatever the number of threads or ranks. Every finished case is appended to a checkpoint at
// once; `--resume` continues an interrupted sweep from it. The merged folder (cases.csv,
// pareto.csv, pareto*.svg, report.html, result.json, cases/NNNN/ on request) is moved in whole at
// the end. This file parses the sweep and runs its cases; the parts are apart, as OpenMDAO keeps
// its case generators, drivers and recorders apart: studies/sweep_design.h generates the cases
// (the designs of experiments), studies/sweep_checkpoint.h keeps the partial folder and its
// checkpoints, studies/sweep_pareto.h finds the non-dominated front and studies/sweep_report.h
// makes the front's plots, the page and the stdout summary.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "studies/study.h"

namespace camopt::studies::sweep {

/// One field that varies: its JSON pointer into the base study and its levels.
struct Variation {
  std::string path;                   ///< JSON pointer into the study ("/target/speed_ratio")
  std::vector<nlohmann::json> values;  ///< explicit levels, or the `count` levels of a range
  bool has_range = false;             ///< a [lo, hi] range (sampled continuously by lhs/sobol)
  double lo = 0, hi = 0;
  bool log = false;                   ///< levels and samples evenly spaced in log(value)
  bool integer = false;               ///< levels and samples rounded to whole numbers
};

/// One column of results: a JSON pointer into the case's result.json.
struct OutputColumn {
  std::string path;
};

struct Sweep {
  std::string name;
  std::string file;        ///< the sweep file (messages)
  std::string study_file;  ///< the base study's file: relative paths in the study resolve from it
  nlohmann::json base;     ///< the base study with "set" applied
  std::vector<Variation> vary;
  std::string design = "factorial";  ///< factorial | zip | latin_hypercube | sobol
  int samples = 0;                   ///< latin_hypercube and sobol
  uint64_t seed = 1;                 ///< latin_hypercube
  std::vector<OutputColumn> outputs;
  std::vector<size_t> minimize, maximize;  ///< Pareto objectives: indices into outputs
  bool case_outputs = false;               ///< keep every case's result folder (cases/NNNN/)
};

/// Reads and checks a sweep file. Throws StudyError "FILE: PATH: expected X, found Y".
/// `max_cases` caps the number of cases (a sweep file is refused at once when over it).
Sweep Parse(const std::string& file, double max_cases = 1e6);
/// The same for a sweep file's JSON already read (the studio's editor text), named `file`: a
/// relative base study is found beside that name, the messages name it.
Sweep ParseJson(const nlohmann::json& doc, const std::string& file, double max_cases = 1e6);
/// The checks `camopt sweep` makes before its first case, with its messages: the file (ParseJson)
/// and the expansion of its design into cases. Returns the number of cases.
/// @throws StudyError as `camopt sweep` reports it (exit 2).
size_t CheckSweep(const nlohmann::json& doc, const std::string& file);

/// The study of one case: the base with the case's values written in.
nlohmann::json CaseStudy(const Sweep& sweep, const std::vector<nlohmann::json>& inputs);

/// What one case gave: status "ok", "incomplete" (ran, but not converged or no feasible design:
/// exit 3 of `camopt run`), "error" (the case's study is refused: exit 2) or "failed" (a camopt
/// defect or out of memory); the message says why; outputs one value per output column (null
/// where result.json has no such value).
struct CaseRecord {
  size_t index = 0;
  std::string status, message;
  std::vector<nlohmann::json> outputs;
  nlohmann::json ToJson() const;
  /// Throws std::exception on a malformed record.
  static CaseRecord FromJson(const nlohmann::json& j);
};

/// Runs one case in-process (thread-safe). `files`, when given, receives the case's output files.
CaseRecord RunCase(const Sweep& sweep, size_t index, const std::vector<nlohmann::json>& inputs,
                   const RunContext& ctx, Outputs* files);

/// cases.csv: one row per record (sorted by case number), columns case, the inputs, status, the
/// outputs, message.
std::string CasesCsv(const Sweep& sweep, const std::vector<std::vector<nlohmann::json>>& cases,
                     const std::vector<CaseRecord>& records);


/// What the CLI's signal thread prints after "interrupted" while a sweep runs: how to resume it
/// ("" when no sweep runs).
std::string InterruptHint();

/// The command line of `camopt sweep`.
struct Options {
  std::string file, out;
  /// The sweep's JSON when it is not read from `file` (the Python module's camopt.Sweep(dict)):
  /// `file` then only names it in messages, and a relative base study is found beside that name.
  std::optional<nlohmann::json> doc;
  int jobs = 0;  ///< threads per rank; 0: the cores of this machine shared among its ranks
  bool dry_run = false, resume = false, quiet = false, case_outputs = false;
  double max_work_factor = 1.0;
  /// Print the summary table and the not-ok cases (stdout, stderr); the Python module does not.
  bool summary = true;
};

/// Runs the command; returns the process exit code (0 every case ok, 3 some case not ok, 2 bad
/// sweep file or output folder). Prints its own messages on stderr.
int RunCommand(const Options& options);

}  // namespace camopt::studies::sweep
