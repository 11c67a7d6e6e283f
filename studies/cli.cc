// camopt's command line, as a function (studies/main.cc calls it; the mutation fuzzer
// fuzz/mutation_fuzzer.cc calls it in a forked child, so that it exercises exactly the CLI). The
// command line: `camopt run STUDY.json [--out DIR] [--quiet] [--max-work-factor F]
// [--convergence] [--strict] [--progress json]`, `camopt serve [--port P] [--host H [--allow-remote]] [FOLDER]`
// (the studio, studies/serve.h), `camopt kinds`, `camopt schema KIND` (the JSON Schema of a study kind),
// `camopt init KIND [--out FILE]` (a complete study to start from, studies/init.h),
// `camopt export RESULT_DIR --to mujoco|modelica|json [--out DIR] [--name NAME]` (the reducer of a
// result as a simulator's joint, studies/export.h),
// `camopt --version`, `camopt sweep SWEEP.json --out DIR [--jobs N] [--dry-run] [--resume]`
// (studies/sweep.h). A successful run prints a short summary of the headline numbers of
// result.json on stdout.
// Exit codes, by cause:
//   0   success
//   2   something the user can fix: the study file, the arguments, the output folder (with the
//       operating system's reason), a study over its work limits (docs/reliability.md)
//   3   the study ran to the end but its result is not what was asked (not converged, nothing
//       fits; with --strict, a limit of the kind's verdict exceeded); the files are written and
//       stderr says why
//   1   a defect of camopt ("internal error")
//   130 interrupted by SIGINT or SIGTERM (the temporary output folder is removed)
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <exception>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <new>
#include <thread>

#include <pthread.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <glog/logging.h>
#include <nlohmann/json.hpp>

#include "studies/cli.h"
#include "studies/convergence.h"
#include "studies/export.h"
#include "studies/provenance.h"
#include "studies/report.h"
#include "studies/archive.h"
#include "studies/init.h"
#include "studies/schemas.h"
#include "studies/serve.h"
#include "studies/study.h"
#include "studies/suggest.h"
#include "studies/sweep.h"

namespace {

// Set by CliMain once a cancelled run has unwound (its temporary folders removed, a sweep's
// threads joined).
std::atomic<bool> g_unwound{false};

// SIGINT and SIGTERM are blocked in every thread and taken by one thread with sigwait: it asks
// the run to stop (the cooperative cancellation of studies/study.h, as the Python module's
// Ctrl-C does), gives it up to a second to unwind, then removes the temporary output folder
// (not possible in a signal handler) and ends the process, whatever the solvers are doing at
// that moment.
void StartSignalThread() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  std::thread([set] {
    int sig = 0;
    sigwait(&set, &sig);
    camopt::studies::RequestCancel();
    for (int i = 0; i < 100 && !g_unwound.load(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    camopt::studies::RemoveTemporaryOutputForInterrupt();
    std::string message = "\ncamopt: interrupted\n";
    const std::string hint = camopt::studies::sweep::InterruptHint();
    if (!hint.empty()) message += "camopt: " + hint + "\n";
    if (write(2, message.data(), message.size()) < 0) {}
    _exit(130);
  }).detach();
}

// --progress json: every progress report as one JSON line on stderr (label, fraction, elapsed_s,
// eta_s, detail, done), whatever --quiet says, for a program that runs camopt as a child and shows
// its progress (`camopt serve` reads them). One write per line, under a lock: lines of reports
// from different threads never interleave.
void InstallJsonProgress() {
  static std::mutex mutex;
  camopt::studies::SetProgressObserver([](const camopt::studies::ProgressEvent& e) {
    nlohmann::json j = {{"label", e.label}, {"fraction", std::isfinite(e.fraction) ? e.fraction : 0.0},
                        {"elapsed_s", e.elapsed_s}, {"eta_s", std::isfinite(e.eta_s) ? e.eta_s : -1.0},
                        {"detail", e.detail}, {"done", e.done}};
    const std::string line = j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
    std::lock_guard<std::mutex> lock(mutex);
    if (write(2, line.data(), line.size()) < 0) {}
  });
}

// The answer first: the verdict over the kind's limits and its headline numbers with units and
// limits, the same list report.html shows (studies/report.h, EvaluateHeadlines). A kind without
// registered headlines: the headline numbers of result.json, one "key: value" line each (at most
// 24): first the top-level numbers, flags and short strings, then from the objects one level down
// the extremes and verdicts (max…, min…, mean…, …_ok, feasible, converged).
void PrintSummary(const std::string& out_dir, const std::string& study_file, const camopt::studies::RunAnswer& answer) {
  if (!answer.result || !answer.result->is_object()) return;
  const nlohmann::json& r = *answer.result;
  std::cout << "camopt: " << r.value("study", std::string("study"));
  if (r.contains("name") && r["name"].is_string()) std::cout << " \"" << r["name"].get<std::string>() << "\"";
  std::cout << "\n";
  std::ifstream study_in(study_file);
  nlohmann::json study = nlohmann::json::parse(study_in, nullptr, false);
  if (study.is_discarded()) study = nlohmann::json::object();
  const camopt::studies::HeadlineTable table =
      camopt::studies::EvaluateHeadlines(r.value("study", std::string()), study, r);
  if (table.registered) {
    std::cout << "  verdict: " << camopt::studies::VerdictLine(table, answer.status, answer.reason) << "\n";
    for (const camopt::studies::HeadlineRow& row : table.rows) {
      std::cout << "  " << row.label << ": " << row.value;
      if (!row.limit.empty()) std::cout << " (limit " << row.limit << ": " << row.status << ")";
      std::cout << "\n";
    }
    if (r.contains("warnings") && r["warnings"].is_array() && !r["warnings"].empty())
      std::cout << "  warnings: " << r["warnings"].size() << " (see result.json)\n";
    std::cout << "  details: " << (std::filesystem::path(out_dir) / "report.html").string() << "\n";
    return;
  }
  constexpr int kMaxLines = 24;
  int lines = 0;
  bool cut = false;
  const auto show = [&](const std::string& key, const nlohmann::json& v) {
    if (lines >= kMaxLines) {
      cut = true;
      return;
    }
    std::cout << "  " << key << ": " << v.dump() << "\n";
    ++lines;
  };
  const auto scalar = [](const nlohmann::json& v) {
    return v.is_number() || v.is_boolean() || (v.is_string() && v.get<std::string>().size() <= 40);
  };
  const auto headline = [](const std::string& k) {
    const auto ends = [&](const std::string& s) {
      return k.size() >= s.size() && k.compare(k.size() - s.size(), s.size(), s) == 0;
    };
    return k.rfind("max", 0) == 0 || k.rfind("min", 0) == 0 || k.rfind("mean", 0) == 0 || ends("_ok") ||
           k == "feasible" || k == "converged";
  };
  for (auto it = r.begin(); it != r.end(); ++it) {
    const std::string& key = it.key();
    if (key == "study" || key == "name" || key == "camopt_version" || key == "study_sha256") continue;
    if (scalar(*it)) show(key, *it);
  }
  for (auto it = r.begin(); it != r.end(); ++it)
    if (it->is_object())
      for (auto jt = it->begin(); jt != it->end(); ++jt)
        if (scalar(*jt) && !jt->is_string() && headline(jt.key())) show(it.key() + "." + jt.key(), *jt);
  if (cut) std::cout << "  ... (the rest in result.json)\n";
  if (r.contains("warnings") && r["warnings"].is_array() && !r["warnings"].empty())
    std::cout << "  warnings: " << r["warnings"].size() << " (see result.json)\n";
}

}  // namespace

namespace camopt::studies {

namespace {
int RunCommandLine(int argc, char** argv);
}  // namespace

int CliMain(int argc, char** argv) {
  StartSignalThread();
  try {
    return RunCommandLine(argc, argv);
  } catch (const StudyCancelled&) {
    // Only the signal thread asks for a cancellation here: it ends the process with exit code 130.
    g_unwound = true;
    for (;;) pause();
  }
}

namespace {

// `--timings`: one line on stderr, "camopt: timings (CPU s / wall s): read 0.001 / 0.001, …; total".
void PrintTimings(const std::vector<camopt::studies::PhaseTime>& phases) {
  double cpu = 0.0, wall = 0.0;
  std::string line;
  char buf[160];
  for (const auto& p : phases) {
    std::snprintf(buf, sizeof buf, "%s%s %.3f / %.3f", line.empty() ? "" : ", ", p.name.c_str(), p.cpu_s, p.wall_s);
    line += buf;
    cpu += p.cpu_s;
    wall += p.wall_s;
  }
  std::snprintf(buf, sizeof buf, "; total %.3f / %.3f", cpu, wall);
  std::cerr << "camopt: timings (CPU s / wall s): " << line << buf << "\n";
}

int RunCommandLine(int argc, char** argv) {
  CLI::App app{"camopt: design optimisation of cam reducers and cam mechanisms"};
  std::string study_file, out_dir;
  bool quiet = false, convergence = false, strict = false, timings = false;
  double work_factor = 1.0;
  // A factor in [1e-6, 1e6]; NaN passes CLI::Range (its comparisons are false) and would switch
  // every cap off, so the check is written out.
  const CLI::Validator factor_range(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0' || !std::isfinite(v) || v < 1e-6 || v > 1e6)
          return "expected a number between 1e-6 and 1e6, found " + text;
        return "";
      },
      "FACTOR in [1e-6, 1e6]");
  CLI::App* run = app.add_subcommand("run", "Analyse or size the design described in a study file");
  run->add_option("study", study_file, "Study file (JSON)")->required();
  run->add_option("--out,-o", out_dir, "Output folder (default: results/<study file stem>)");
  run->add_flag("--quiet,-q", quiet, "No progress lines on stderr");
  run->add_flag("--strict", strict,
                "Exit 3 when a limit of the kind's verdict is exceeded (for scripts and CI pipelines)");
  run->add_flag("--timings", timings,
                "Print where the run's time went on stderr: read, checks, parse, solve (a sizing's verification "
                "and limit costs apart), files, status, report, write (CPU and wall seconds; "
                "scripts/time_examples.py)");
  run->add_flag("--convergence", convergence,
                "Also run each fidelity knob refined and coarsened: convergence.json, "
                "convergence_*.svg and a table on stdout (docs/performance.md)");
  run->add_option("--max-work-factor", work_factor,
                  "Multiply every work, memory and file-size cap by this factor (default 1; "
                  "see docs/reliability.md)")
      ->check(factor_range);
  std::string files_inside;
  run->add_option("--files-inside", files_inside,
                  "Refuse files the study names (a roller catalogue) outside this folder (camopt serve "
                  "passes its folder)");
  std::string progress_format;
  run->add_option("--progress", progress_format,
                  "json: every progress report as one JSON line on stderr, also with --quiet (for "
                  "programs that run camopt, such as `camopt serve`)")
      ->check(CLI::IsMember({"json"}));
  camopt::studies::ServeOptions serve_options;
  CLI::App* serve = app.add_subcommand(
      "serve", "Start the studio: a local web app to edit, run and see the studies of a folder (docs/studio.md)");
  serve->add_option("folder", serve_options.folder, "Folder of study files (default: the current folder)");
  serve->add_option("--port,-p", serve_options.port, "TCP port (default 8765; 0: a free port)")
      ->check(CLI::Range(0, 65535));
  serve->add_option("--host", serve_options.host,
                    "Address to listen on (default 127.0.0.1: this machine only)");
  serve->add_flag("--allow-remote", serve_options.allow_remote,
                  "Allow a --host beyond this machine: every request then needs the token printed at start");
  serve->add_option("--request-timeout", serve_options.request_timeout_s,
                    "Seconds a connection has to send a whole request once begun (default 10); slower "
                    "clients are disconnected")
      ->check(CLI::Range(0.1, 3600.0));
  serve->add_option("--web", serve_options.web_dir,
                    "Folder of the front end's files (default: next to the program, or share/camopt/web)");
  CLI::App* kinds = app.add_subcommand("kinds", "List the study kinds this build knows, each with what it is for");
  bool kinds_names_only = false;
  kinds->add_flag("--names", kinds_names_only, "The names only, one per line (for scripts)");
  camopt::studies::sweep::Options sweep;
  CLI::App* sweep_cmd = app.add_subcommand("sweep", "Run a study over many cases (docs/studies.md)");
  sweep_cmd->add_option("sweep", sweep.file, "Sweep file (JSON)")->required();
  sweep_cmd->add_option("--out,-o", sweep.out, "Output folder");
  sweep_cmd->add_option("--jobs,-j", sweep.jobs, "Threads per process (default: all cores)")->check(CLI::Range(1, 4096));
  sweep_cmd->add_flag("--dry-run", sweep.dry_run, "Print the number of cases and stop");
  sweep_cmd->add_flag("--resume", sweep.resume, "Continue an interrupted sweep from its checkpoint");
  sweep_cmd->add_flag("--case-outputs", sweep.case_outputs, "Keep every case's result folder");
  sweep_cmd->add_flag("--quiet,-q", sweep.quiet, "No progress lines on stderr");
  sweep_cmd->add_option("--max-work-factor", sweep.max_work_factor, "As for run")->check(factor_range);
  sweep_cmd->add_option("--files-inside", files_inside, "As for run (the sweep's base and the cases' files)");
  std::string sweep_progress;
  sweep_cmd->add_option("--progress", sweep_progress, "As for run")->check(CLI::IsMember({"json"}));
  std::string schema_kind;
  CLI::App* schema = app.add_subcommand("schema", "Print the JSON Schema of a study kind");
  schema->add_option("kind", schema_kind, "Study kind (see `camopt kinds`)")->required();
  bool schema_table = false;
  schema->add_flag("--table", schema_table, "Print the fields as a Markdown table (docs/studies.md)");
  bool schema_result = false;
  schema->add_flag("--result", schema_result, "The schema of the kind's result.json instead of its study file");
  std::string init_kind, init_out;
  CLI::App* init = app.add_subcommand(
      "init", "Write a complete study of a kind to start from, every default spelled out (docs/studies.md)");
  init->add_option("kind", init_kind, "Study kind (see `camopt kinds`)")->required();
  init->add_option("--out,-o", init_out, "Study file to write (default: standard output); never overwritten");
  camopt::studies::ExportRequest export_request;
  CLI::App* export_cmd = app.add_subcommand(
      "export", "Write the reducer of a result as a simulator's joint: MuJoCo MJCF, Modelica or JSON (docs/export.md)");
  export_cmd->add_option("result", export_request.result,
                         "Result folder of `camopt run` (a cycloid_ltca or lcr_analysis study), or its result.json")
      ->required();
  export_cmd->add_option("--to", export_request.to, "mujoco (MJCF .xml), modelica (.mo package) or json (joint.json)")
      ->required();
  export_cmd->add_option("--out,-o", export_request.out, "Output folder (default: RESULT_DIR/export)");
  export_cmd->add_option("--name", export_request.name,
                         "Name of the joint in the files (default: the result folder's name)");
  app.set_version_flag("--version", "camopt " + camopt::studies::CamoptVersion());
  app.require_subcommand(0, 1);

  // A first word that is no command: say so, and which command was meant.
  if (argc >= 2 && argv[1][0] != '-') {
    const std::string word = argv[1];
    const std::vector<std::string> commands = {"run", "sweep", "kinds", "schema", "init", "serve", "export"};
    if (std::find(commands.begin(), commands.end(), word) == commands.end()) {
      if (word.size() > 5 && word.compare(word.size() - 5, 5, ".json") == 0) {
        std::cerr << "camopt: error: a command comes before the file: `camopt run " << word
                  << "` (a study) or `camopt sweep " << word << " --out DIR` (a sweep)\n";
        return 2;
      }
      const std::string near = camopt::studies::NearestName(word, commands);
      std::cerr << "camopt: error: unknown command \"" << word << "\""
                << (near.empty() ? "" : " (did you mean \"" + near + "\"?)")
                << "; the commands are run, sweep, init, kinds, schema, serve and export (camopt --help)\n";
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    // Every user error has the same first words on stderr (docs/reliability.md, exit codes).
    std::cerr << "camopt: error: " << e.what() << "\n"
              << "Run with --help for more information.\n";
    return 2;
  }

  // Ceres logs through Google logging: nothing of it reaches stderr under --quiet, and only
  // errors otherwise (our own messages say what failed, with context).
  FLAGS_logtostderr = false;
  FLAGS_minloglevel = quiet ? google::GLOG_FATAL : google::GLOG_ERROR;
  FLAGS_stderrthreshold = quiet ? google::GLOG_FATAL : google::GLOG_ERROR;

  if (sweep_cmd->parsed()) {
    FLAGS_minloglevel = FLAGS_stderrthreshold = google::GLOG_FATAL;  // cases run quietly
    if (sweep_progress == "json") InstallJsonProgress();
    camopt::studies::CurrentInputLimits().files_inside = files_inside;
    return camopt::studies::sweep::RunCommand(sweep);
  }
  if (serve->parsed()) return camopt::studies::ServeMain(serve_options);
  if (kinds->parsed()) {
    // One line per kind: its name, then what it is for (its schema's title, without the
    // "camopt study: " every title starts with).
    const std::vector<std::string> names = camopt::studies::StudyKinds();
    size_t width = 0;
    for (const auto& k : names) width = std::max(width, k.size());
    for (const auto& k : names) {
      if (kinds_names_only) {
        std::cout << k << "\n";
        continue;
      }
      const auto declared = nlohmann::json::parse(camopt::studies::StudySchema(k), nullptr, false);
      std::string what = declared.is_object() && declared.contains("title") && declared["title"].is_string()
                             ? declared["title"].get<std::string>()
                             : "";
      const std::string prefix = "camopt study: ";
      if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
      std::cout << k << std::string(width - k.size() + 2, ' ') << what << "\n";
    }
    return 0;
  }
  if (schema->parsed()) {
    try {
      const std::string& text = schema_result ? camopt::studies::StudyResultSchema(schema_kind)
                                              : camopt::studies::StudySchema(schema_kind);
      if (schema_table)
        std::cout << camopt::studies::SchemaFieldTable(nlohmann::ordered_json::parse(text), schema_result);
      else
        std::cout << text;
      return 0;
    } catch (const camopt::studies::StudyError& e) {
      std::cerr << "camopt: error: " << e.what() << "\n";
      return 2;
    }
  }
  if (init->parsed()) {
    try {
      const camopt::studies::InitStudy study = camopt::studies::InitTemplate(init_kind);
      if (init_out.empty()) {
        std::cout << study.text;
        return 0;
      }
      if (std::filesystem::exists(init_out)) {
        std::cerr << "camopt: error: --out: " << init_out
                  << " exists; expected a new file name (init never overwrites a study)\n";
        return 2;
      }
      std::ofstream file(init_out, std::ios::binary);
      file << study.text;
      file.close();
      if (!file) {
        std::cerr << "camopt: error: --out: cannot write " << init_out << "\n";
        std::filesystem::remove(init_out);
        return 2;
      }
      std::cerr << "camopt: wrote " << init_out << ", the " << init_kind
                << (study.example.empty() ? " study of the declared defaults" : " example " + study.example)
                << " with every field and default spelled out; change the design, then: camopt run " << init_out
                << "\n";
      return 0;
    } catch (const camopt::studies::StudyError& e) {
      std::cerr << "camopt: error: " << e.what() << "\n";
      return 2;
    }
  }
  if (export_cmd->parsed()) {
    if (export_cmd->count("--out") > 0 && export_request.out.empty()) {
      std::cerr << "camopt: error: --out: expected a folder name for the export, found nothing\n";
      return 2;
    }
    try {
      const camopt::studies::ExportAnswer written = camopt::studies::RunExport(export_request);
      std::cerr << "camopt: wrote " << written.file << "\n";
      return 0;
    } catch (const camopt::studies::StudyError& e) {
      std::cerr << "camopt: error: " << e.what() << "\n";
      return 2;
    } catch (const std::exception& e) {
      std::cerr << "camopt: internal error while exporting " << export_request.result << ": " << e.what()
                << " (a camopt defect; please report it with the result folder)\n";
      return 1;
    }
  }
  if (!run->parsed()) {
    std::cerr << app.help();
    return 2;
  }
  if (run->count("--out") > 0 && out_dir.empty()) {
    std::cerr << "camopt: error: --out: expected a folder name for the results, found nothing\n";
    return 2;
  }
  if (out_dir.empty())
    out_dir = (std::filesystem::path("results") / std::filesystem::path(study_file).stem()).string();
  if (progress_format == "json") InstallJsonProgress();
  camopt::studies::CurrentInputLimits().files_inside = files_inside;
  try {
    camopt::studies::RunContext ctx;
    ctx.quiet = quiet;
    ctx.max_work_factor = work_factor;
    auto& limits = camopt::studies::CurrentInputLimits();
    limits.max_file_bytes = camopt::studies::FileBytesForWorkFactor(work_factor);
    ctx.strict = strict;
    camopt::studies::RunAnswer answer;
    if (convergence)
      camopt::studies::RunConvergenceFile(study_file, out_dir, ctx);
    else
      answer = camopt::studies::RunStudyFile(study_file, out_dir, ctx);
    if (!quiet) std::cerr << "camopt: results written to " << out_dir << "\n";
    if (!convergence) PrintSummary(out_dir, study_file, answer);  // --convergence prints its own table
    if (timings && !convergence) PrintTimings(answer.phases);
    return 0;
  } catch (const camopt::studies::StudyIncomplete& e) {
    // One status gives the exit code, this line and the verdict (studies/status.h).
    const camopt::studies::Status status = e.answer().status;
    if (camopt::studies::ExitCode(status, false) == 0)
      std::cerr << "camopt: --strict: " << e.answer().reason << "\n";  // exit 3 only because of --strict
    else
      std::cerr << "camopt: finished, but the results do not meet what was asked: " << e.what() << "\n";
    if (!quiet) std::cerr << "camopt: results written to " << out_dir << "\n";
    if (!convergence) PrintSummary(out_dir, study_file, e.answer());
    if (timings && !convergence) PrintTimings(e.answer().phases);
    return 3;
  } catch (const camopt::studies::StudyError& e) {
    std::cerr << "camopt: error: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "camopt: error: " << study_file
              << ": out of memory (the work limits did not foresee this study's size; "
                 "please report it)\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "camopt: internal error while running " << study_file << ": " << e.what()
              << " (a camopt defect; please report it with the study file)\n";
    return 1;
  }
}

}  // namespace

}  // namespace camopt::studies
