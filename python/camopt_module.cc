// The Python module `camopt` (pybind11): studies, their results and sweeps as objects, the models
// of the kinds' designs evaluated at given angles, and the earlier one-call `camopt.run`.
//
//   import camopt
//   s = camopt.Study.load("studies/examples/lcr_ii.json")      # or camopt.Study("lcr_analysis", {...})
//   r = s.run(progress=lambda e: print(e.label, e.fraction))  # Ctrl-C stops it within a second
//   r.verdict; r.headlines; r.result["input_cam"]; r.tables["series"]["efficiency"]  # numpy
//   camopt.Lcr.from_study(s).loads(angles_rad)["input_max_roller_force_N"]
//   camopt.Sweep.load("studies/examples/sweeps/x.json").run().tables["cases"]
//   camopt.run("studies/examples/lcr_ii.json")                # result.json as a dict (as before)
//
// A missing file raises FileNotFoundError, a bad study camopt.StudyError (a ValueError) with .file,
// .path (JSON path), .expected, .found. Everything the module computes goes through the same
// functions as the command line (studies/study.h's RunStudy, studies/sweep.h's RunCommand, the
// model/ functions the kinds call). docs/studies.md ("camopt as a library and from Python")
// describes the API; python/camopt.pyi is its stub.
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "python/camopt_module.h"
#include "studies/input.h"
#include "studies/provenance.h"
#include "studies/report.h"
#include "studies/schemas.h"
#include "studies/study.h"
#include "studies/sweep.h"
#include "studies/sweep_design.h"

namespace py = pybind11;
namespace fs = std::filesystem;
namespace st = camopt::studies;
using nlohmann::json;

namespace {

bool IsNumber(const json& v) { return v.is_number() && !v.is_boolean(); }

// JSON → Python; arrays of numbers become NumPy arrays (int64 when every element is whole).
py::object ToPython(const json& v) {
  if (v.is_null()) return py::none();
  if (v.is_boolean()) return py::bool_(v.get<bool>());
  if (v.is_number_integer()) return py::int_(v.get<long long>());
  if (v.is_number()) return py::float_(v.get<double>());
  if (v.is_string()) return py::str(v.get<std::string>());
  if (v.is_object()) {
    py::dict d;
    for (auto it = v.begin(); it != v.end(); ++it) d[py::str(it.key())] = ToPython(*it);
    return d;
  }
  bool numbers = !v.empty(), whole = true;
  for (const auto& e : v) {
    numbers = numbers && IsNumber(e);
    whole = whole && e.is_number_integer();
  }
  if (numbers && whole) {
    py::array_t<long long> a(static_cast<py::ssize_t>(v.size()));
    auto m = a.mutable_unchecked<1>();
    for (size_t i = 0; i < v.size(); ++i) m(i) = v[i].get<long long>();
    return a;
  }
  if (numbers) {
    py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
    auto m = a.mutable_unchecked<1>();
    for (size_t i = 0; i < v.size(); ++i) m(i) = v[i].get<double>();
    return a;
  }
  py::list l;
  for (const auto& e : v) l.append(ToPython(e));
  return l;
}

std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

// A CSV file of camopt (a header line, then rows) → {column: array}; a column of numbers is a
// float64 array, any other column a list of strings.
py::dict CsvColumns(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  py::dict out;
  // Leading comment lines ('#': the inspection points' and grinding wheel's headers) are not the
  // header row.
  do {
    if (!std::getline(in, line)) return out;
  } while (!line.empty() && line[0] == '#');
  const std::vector<std::string> names = SplitCsvLine(line);
  std::vector<std::vector<std::string>> cols(names.size());
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto cells = SplitCsvLine(line);
    for (size_t c = 0; c < names.size(); ++c) cols[c].push_back(c < cells.size() ? cells[c] : "");
  }
  for (size_t c = 0; c < names.size(); ++c) {
    std::vector<double> values;
    bool numeric = true;
    for (const auto& s : cols[c]) {
      char* end = nullptr;
      const double x = std::strtod(s.c_str(), &end);
      if (s.empty() || *end != '\0') {
        numeric = false;
        break;
      }
      values.push_back(x);
    }
    if (numeric)
      out[py::str(names[c])] = py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
    else
      out[py::str(names[c])] = py::cast(cols[c]);
  }
  return out;
}

py::handle g_study_error;  // camopt.StudyError (a reference kept for the life of the process)

std::string FsPath(const py::object& path) {
  return py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>();
}

[[noreturn]] void RaiseFileNotFound(const std::string& path) {
  PyErr_SetObject(PyExc_FileNotFoundError, py::make_tuple(ENOENT, "No such file or directory", path).ptr());
  throw py::error_already_set();
}

py::dict ResultDict(const st::Outputs& outputs);

// ---- The interruptible run ---------------------------------------------------------------------

std::mutex& RunMutex() {
  static std::mutex m;
  return m;
}

// True on a run's worker thread (where the progress callback runs): a run started there would
// wait for the run that calls it.
thread_local bool t_in_run = false;

// The progress observer of one run: calls the Python callback with the GIL taken; the first
// exception it raises is kept (and cancels the run), later reports are dropped.
class ProgressBridge {
 public:
  explicit ProgressBridge(py::object callback) : callback_(std::move(callback)) {}
  void operator()(const st::ProgressEvent& e) {
    if (failed_.load()) return;
    py::gil_scoped_acquire gil;
    try {
      callback_(e);
    } catch (py::error_already_set& err) {
      error_.emplace(std::move(err));
      failed_ = true;
      st::RequestCancel();
    }
  }
  std::optional<py::error_already_set>& error() { return error_; }

 private:
  py::object callback_;
  std::atomic<bool> failed_{false};
  std::optional<py::error_already_set> error_;
};

}  // namespace

namespace camopt::python {

void RunInterruptibly(const std::function<void()>& work, const py::object& progress) {
  if (t_in_run) throw std::runtime_error("camopt: a run cannot be started from a progress callback");
  std::unique_lock<std::mutex> run_lock(RunMutex(), std::defer_lock);
  {
    py::gil_scoped_release release;
    run_lock.lock();
  }
  st::ClearCancel();
  std::shared_ptr<ProgressBridge> bridge;
  std::function<void(const st::ProgressEvent&)> previous;
  if (!progress.is_none()) {
    bridge = std::make_shared<ProgressBridge>(progress);
    previous = st::SetProgressObserver([bridge](const st::ProgressEvent& e) { (*bridge)(e); });
  }
  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  std::exception_ptr error;
  std::thread worker([&] {
    t_in_run = true;
    try {
      work();
    } catch (...) {
      error = std::current_exception();
    }
    const std::lock_guard<std::mutex> lock(m);
    done = true;
    cv.notify_all();
  });
  std::optional<py::error_already_set> interrupt;
  for (;;) {
    bool finished = false;
    {
      py::gil_scoped_release release;
      std::unique_lock<std::mutex> lock(m);
      finished = cv.wait_for(lock, std::chrono::milliseconds(50), [&] { return done; });
    }
    if (finished) break;
    // Python's handlers run here (only in the main thread): Ctrl-C raises KeyboardInterrupt.
    if (!interrupt && PyErr_CheckSignals() != 0) {
      interrupt.emplace();  // takes the exception out of the error indicator
      st::RequestCancel();
    }
  }
  {
    py::gil_scoped_release release;
    worker.join();
  }
  if (bridge) {
    // The run's observer comes back here and is destroyed with the GIL held.
    std::function<void(const st::ProgressEvent&)> ours = st::SetProgressObserver(std::move(previous));
  }
  st::ClearCancel();
  if (interrupt) throw std::move(*interrupt);
  if (bridge && bridge->error()) throw std::move(*bridge->error());
  if (error) std::rethrow_exception(error);
}

// The parts of a StudyError; for a message built without a Node ("FILE: /PATH: rest"), taken from
// the message.
[[noreturn]] void RaiseStudyError(const st::StudyError& e, const std::string& study_file) {
  std::string file = e.file().empty() ? study_file : e.file(), path = e.path(), expected = e.expected(), found = e.found();
  const std::string msg = e.what();
  if (path.empty()) {
    const size_t p = msg.find(": /");
    if (p != std::string::npos) {
      file = msg.substr(0, p);
      const size_t q = msg.find(": ", p + 2);
      path = msg.substr(p + 2, q == std::string::npos ? std::string::npos : q - p - 2);
      std::string rest = q == std::string::npos ? "" : msg.substr(q + 2);
      const size_t f = rest.rfind(", found ");
      if (rest.rfind("expected ", 0) == 0 && f != std::string::npos) {
        expected = rest.substr(9, f - 9);
        found = rest.substr(f + 8);
      } else {
        expected = rest;
      }
    }
  }
  py::object err = g_study_error(msg);
  err.attr("file") = file;
  err.attr("path") = path;
  err.attr("expected") = expected;
  err.attr("found") = found;
  PyErr_SetObject(g_study_error.ptr(), err.ptr());
  throw py::error_already_set();
}

StudyData ToStudy(const py::object& study) {
  if (py::isinstance<StudyData>(study)) return study.cast<StudyData>();
  StudyData s;
  try {
    if (py::isinstance<py::dict>(study)) {
      s.file = "<dict>";
      const std::string text = py::module_::import("json").attr("dumps")(study).cast<std::string>();
      s.study = st::ParseStudyText(text, s.file, st::CurrentInputLimits().max_depth);
    } else {
      s.file = FsPath(study);
      std::error_code ec;
      if (!fs::exists(s.file, ec)) RaiseFileNotFound(s.file);
      const std::string text = st::ReadFileCapped(s.file, st::CurrentInputLimits().max_file_bytes, "file");
      s.study = st::ParseStudyText(text, s.file, st::CurrentInputLimits().max_depth);
      s.sha256 = st::Sha256Hex(text);
    }
    st::CheckStudy(s.study, s.file);
  } catch (const st::StudyError& e) {
    RaiseStudyError(e, s.file);
  }
  return s;
}

}  // namespace camopt::python

namespace {

using camopt::python::RaiseStudyError;
using camopt::python::RunInterruptibly;
using camopt::python::StudyData;

// ---- Results -----------------------------------------------------------------------------------

py::dict Tables(const std::map<std::string, std::string>& files) {
  py::dict tables;
  for (const auto& [name, content] : files)
    if (name.size() > 4 && name.compare(name.size() - 4, 4, ".csv") == 0)
      tables[py::str(name.substr(0, name.size() - 4))] = CsvColumns(content);
  return tables;
}

// The result of a run (a study's or a sweep's): result.json, the tables, the verdict and the
// headline numbers, the output files in memory and the folder they were written to.
struct Result {
  std::string kind;
  py::object verdict = py::none();
  bool limits_met = true;
  std::string status;  ///< result.json's "status" (studies/status.h), "" for a sweep
  py::list headlines;
  py::dict result, tables;
  py::list files, warnings;
  py::object out = py::none(), incomplete = py::none();
  std::map<std::string, std::string> contents;
};

// `result`: the run's result.json as JSON (Outputs::result), or nullptr to read it from `files`
// (a sweep's folder).
Result MakeResult(const json& study, std::map<std::string, std::string> files, const std::string& incomplete,
                  const std::string& out, const json* result = nullptr) {
  Result r;
  r.kind = study.value("study", std::string());
  json rj = json::object();
  if (result) rj = *result;
  else if (const auto it = files.find("result.json"); it != files.end()) rj = json::parse(it->second, nullptr, false);
  if (rj.is_object()) {
    r.result = ToPython(rj).cast<py::dict>();
    if (rj.contains("warnings") && rj["warnings"].is_array())
      for (const auto& w : rj["warnings"]) r.warnings.append(w.is_string() ? w.get<std::string>() : w.dump());
    if (!r.kind.empty()) {
      const st::HeadlineTable table = st::EvaluateHeadlines(r.kind, study, rj);
      r.verdict = py::str(st::VerdictOf(table, rj));
      if (rj.contains("status") && rj["status"].is_string()) r.status = rj["status"].get<std::string>();
      r.limits_met = table.exceeded.empty() && !table.no_design;
      const std::vector<st::Headline>* declared = st::FindHeadlines(r.kind);
      for (const st::HeadlineRow& row : table.rows) {
        py::dict h;
        h["label"] = row.label;
        h["value"] = py::none();
        h["unit"] = "";
        if (declared)
          for (const st::Headline& d : *declared)
            if (d.label == row.label) {
              const json::json_pointer p(d.pointer);
              if (rj.contains(p) && rj.at(p).is_number()) h["value"] = rj.at(p).get<double>();
              h["unit"] = d.unit;
              h["pointer"] = d.pointer;
            }
        h["text"] = row.value;
        h["limit"] = row.limit;
        h["status"] = row.status;
        r.headlines.append(h);
      }
    }
  }
  r.tables = Tables(files);
  for (const auto& [name, content] : files) r.files.append(name);
  if (!incomplete.empty()) r.incomplete = py::str(incomplete);
  if (!out.empty()) r.out = py::str(out);
  r.contents = std::move(files);
  return r;
}

// Runs a study (interruptibly); with `out`, writes the folder as `camopt run --out` does.
st::Outputs RunOutputs(const StudyData& s, const std::string& out, bool quiet, double max_work_factor,
                       const py::object& progress) {
  st::RunContext ctx;
  ctx.study_file = s.file;
  ctx.quiet = quiet;
  ctx.max_work_factor = max_work_factor;
  ctx.study_sha256 = s.sha256;
  st::Outputs outputs;
  try {
    // Checked before any work; an uncommitted folder's temporary sibling is removed by its
    // destructor (a cancelled run leaves `out` as it was).
    std::unique_ptr<st::OutputFolder> folder;
    if (!out.empty()) folder = std::make_unique<st::OutputFolder>(out);
    RunInterruptibly(
        [&] {
          outputs = st::RunStudy(s.study, ctx);
          if (folder) folder->Commit(outputs);
        },
        progress);
  } catch (const st::StudyError& e) {
    RaiseStudyError(e, s.file);
  }
  return outputs;
}

py::dict ResultDict(const st::Outputs& outputs) {
  const auto& files = outputs.files();
  py::dict result;
  if (outputs.result()) result = ToPython(*outputs.result()).cast<py::dict>();
  result["series"] = Tables(files);
  py::list names;
  for (const auto& [name, content] : files) names.append(name);
  result["files"] = names;
  if (!outputs.incomplete().empty()) result["incomplete"] = outputs.incomplete();
  return result;
}

// camopt.run (the first API, kept): result.json as a dict plus "series", "files", "incomplete".
py::dict Run(const py::object& study, const py::object& out, bool quiet, double max_work_factor) {
  namespace st = camopt::studies;
  StudyData s;
  try {
    if (py::isinstance<py::dict>(study)) {
      s.file = "<dict>";
      const std::string text = py::module_::import("json").attr("dumps")(study).cast<std::string>();
      s.study = st::ParseStudyText(text, s.file, st::CurrentInputLimits().max_depth);
    } else {
      s.file = FsPath(study);
      const std::string text = st::ReadFileCapped(s.file, st::CurrentInputLimits().max_file_bytes, "file");
      s.study = st::ParseStudyText(text, s.file, st::CurrentInputLimits().max_depth);
      s.sha256 = st::Sha256Hex(text);
    }
  } catch (const st::StudyError& e) {
    RaiseStudyError(e, s.file);
  }
  return ResultDict(RunOutputs(s, out.is_none() ? "" : FsPath(out), quiet, max_work_factor, py::none()));
}

// ---- Sweeps ------------------------------------------------------------------------------------

struct SweepData {
  std::string file;
  std::optional<json> doc;  ///< a sweep given as a dict (its relative base study from the current folder)
  st::sweep::Sweep sweep;
  std::vector<std::vector<json>> cases;  ///< each case's values, in the order of sweep.vary
};

SweepData LoadSweep(const py::object& path) {
  SweepData s;
  s.file = FsPath(path);
  std::error_code ec;
  if (!fs::exists(s.file, ec)) RaiseFileNotFound(s.file);
  try {
    s.sweep = st::sweep::Parse(s.file);
    s.cases = st::sweep::Cases(s.sweep);
  } catch (const st::StudyError& e) {
    RaiseStudyError(e, s.file);
  }
  return s;
}

// A sweep from a dict (as a sweep file's JSON) or from the path of a sweep file. A dict is named
// "<dict>" in messages as if it were a file in the current folder: a relative base study is found
// from there.
SweepData ToSweep(const py::object& spec) {
  if (!py::isinstance<py::dict>(spec)) return LoadSweep(spec);
  SweepData s;
  s.file = (fs::current_path() / "<dict>").string();
  try {
    const std::string text = py::module_::import("json").attr("dumps")(spec).cast<std::string>();
    s.doc = st::ParseStudyText(text, "<dict>", st::CurrentInputLimits().max_depth);
    s.sweep = st::sweep::ParseJson(*s.doc, s.file);
    s.cases = st::sweep::Cases(s.sweep);
  } catch (const st::StudyError& e) {
    RaiseStudyError(e, "<dict>");
  }
  return s;
}

// The case table: a list of {"case": index, varied input's JSON pointer: value} per case, the
// columns of cases.csv before the results.
py::list CaseTable(const SweepData& s) {
  py::list rows;
  const py::object loads = py::module_::import("json").attr("loads");
  for (size_t c = 0; c < s.cases.size(); ++c) {
    py::dict row;
    row["case"] = c;
    const auto& values = s.cases[c];
    for (size_t i = 0; i < values.size() && i < s.sweep.vary.size(); ++i)
      row[py::str(s.sweep.vary[i].path)] = loads(values[i].dump());
    rows.append(row);
  }
  return rows;
}

std::string ReadWhole(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

Result RunSweep(const SweepData& s, const py::object& out, int jobs, bool quiet, double max_work_factor,
                const py::object& progress) {
  // Without `out`, the sweep runs into a temporary folder that is read and removed.
  py::object tmp = py::none();
  std::string folder;
  if (out.is_none()) {
    tmp = py::module_::import("tempfile").attr("mkdtemp")(py::arg("prefix") = "camopt-sweep-");
    folder = (fs::path(tmp.cast<std::string>()) / "sweep").string();
  } else {
    folder = FsPath(out);
  }
  st::sweep::Options o;
  o.file = s.file;
  o.doc = s.doc;
  o.out = folder;
  o.jobs = jobs;
  o.quiet = quiet;
  o.max_work_factor = max_work_factor;
  o.summary = false;
  int code = 1;
  const auto cleanup = [&] {
    if (!tmp.is_none()) py::module_::import("shutil").attr("rmtree")(tmp, py::arg("ignore_errors") = true);
  };
  try {
    RunInterruptibly([&] { code = st::sweep::RunCommand(o); }, progress);
  } catch (...) {
    cleanup();
    throw;
  }
  if (code == 2 || code == 1) {
    cleanup();
    if (code == 2)
      RaiseStudyError(st::StudyError(s.file + ": the sweep did not run (camopt's message is on stderr)"), s.file);
    throw std::runtime_error(s.file + ": internal error while running the sweep (camopt's message is on stderr)");
  }
  std::map<std::string, std::string> files;
  for (const auto& e : fs::directory_iterator(folder))
    if (e.is_regular_file() && e.path().filename().string()[0] != '.')
      files[e.path().filename().string()] = ReadWhole(e.path());
  cleanup();
  Result r = MakeResult(json::object(), std::move(files), code == 3 ? "some cases are not ok (see tables['cases'])" : "",
                        out.is_none() ? "" : folder);
  r.kind = "sweep";
  // The verdict over the cases, as the sweep's report says it ("All 3 cases ok").
  const py::dict result = r.result;
  r.verdict = result.contains("verdict") ? py::object(result["verdict"]) : py::object(py::none());
  return r;
}

}  // namespace

PYBIND11_MODULE(camopt, m) {
  using camopt::python::ToStudy;
  m.doc() = "camopt: design optimisation of cam reducers and cam mechanisms (studies, results, sweeps "
            "and the kinds' models from Python)";
  m.attr("__version__") = camopt::studies::CamoptVersion();
  // pybind11 loads NumPy's C API on the first array it makes, inside a function-local static whose
  // guard is held while numpy is imported — and the import releases the GIL. Two threads whose
  // first camopt call makes an array then deadlock: one holds the guard and waits for the GIL, the
  // other holds the GIL and waits for the guard. Loaded here, once, under Python's import lock.
  (void)py::detail::npy_api::get();
  g_study_error = py::handle(PyErr_NewExceptionWithDoc("camopt.StudyError",
                                "A bad study: .file, .path (JSON path), .expected, .found name the fault.",
                                PyExc_ValueError, nullptr));
  m.attr("StudyError") = py::reinterpret_borrow<py::object>(g_study_error);
  // A cancellation nobody in this process asked for from Python (it cannot happen through the
  // module's own runs, which raise the KeyboardInterrupt that caused it).
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const st::StudyCancelled&) {
      PyErr_SetString(PyExc_KeyboardInterrupt, "camopt: the run was cancelled");
    }
  });

  py::class_<st::ProgressEvent>(m, "ProgressEvent",
                                "One progress report of a run: label, fraction in [0, 1], elapsed_s, eta_s "
                                "(None while unknown), detail, done (the last report of that label).")
      .def_readonly("label", &st::ProgressEvent::label)
      .def_readonly("fraction", &st::ProgressEvent::fraction)
      .def_readonly("elapsed_s", &st::ProgressEvent::elapsed_s)
      .def_property_readonly("eta_s",
                             [](const st::ProgressEvent& e) -> py::object {
                               return e.eta_s < 0 ? py::object(py::none()) : py::object(py::float_(e.eta_s));
                             })
      .def_readonly("detail", &st::ProgressEvent::detail)
      .def_readonly("done", &st::ProgressEvent::done)
      .def("__repr__", [](const st::ProgressEvent& e) {
        return "ProgressEvent(" + e.label + ", " + std::to_string(e.fraction) + (e.done ? ", done)" : ")");
      });

  py::class_<Result>(m, "Result",
                     "What a run gave: result.json as a dict, the CSV outputs as {table: {column: array}}, "
                     "the verdict over the kind's limits and its headline numbers, the output files.")
      .def_readonly("kind", &Result::kind)
      .def_readonly("verdict", &Result::verdict)
      .def_readonly("limits_met", &Result::limits_met)
      .def_readonly("status", &Result::status,
                    "the answer's one status (result.json \"status\"): optimal_verified, feasible_verified, "
                    "infeasible, not_verifiable, not_converged, limits_met or limits_exceeded")
      .def_readonly("headlines", &Result::headlines)
      .def_readonly("result", &Result::result)
      .def_readonly("tables", &Result::tables)
      .def_readonly("files", &Result::files)
      .def_readonly("warnings", &Result::warnings)
      .def_readonly("out", &Result::out)
      .def_readonly("incomplete", &Result::incomplete)
      .def(
          "text",
          [](const Result& r, const std::string& name) {
            const auto it = r.contents.find(name);
            if (it == r.contents.end()) throw py::key_error(name);
            return py::bytes(it->second);
          },
          py::arg("name"), "The bytes of one output file (e.g. 'report.html').")
      .def("__getitem__", [](const Result& r, const py::object& key) { return r.result[key]; })
      .def("__repr__", [](const Result& r) {
        return "<camopt.Result " + r.kind + ": " + (r.verdict.is_none() ? std::string("-") : r.verdict.cast<std::string>()) +
               ">";
      });

  py::class_<StudyData>(m, "Study", "A checked study of one kind, from a file or a dict.")
      .def(py::init([](const std::string& kind, const py::dict& fields) {
             py::dict d = fields.attr("copy")();  // the caller's dict is left alone
             if (d.contains("study") && d["study"].cast<std::string>() != kind) {
               RaiseStudyError(st::StudyError("<dict>: /study: expected \"" + kind + "\" (the kind given), found \"" +
                                              d["study"].cast<std::string>() + "\""),
                               "<dict>");
             }
             d["study"] = kind;
             return ToStudy(d);
           }),
           py::arg("kind"), py::arg("fields"),
           "A study of `kind` from a dict of its fields (\"study\" may be left out). Raises camopt.StudyError.")
      .def_static(
          "load", [](const py::object& path) { return ToStudy(path); }, py::arg("path"),
          "Reads and checks a study file. Raises FileNotFoundError, camopt.StudyError.")
      .def_property_readonly("kind", &StudyData::kind)
      .def_property_readonly("name", [](const StudyData& s) { return s.study.value("name", std::string()); })
      .def_readonly("file", &StudyData::file)
      .def("to_dict", [](const StudyData& s) { return ToPython(s.study); }, "The study as a dict (a copy).")
      .def(
          "run",
          [](const StudyData& s, const py::object& out, const py::object& progress, bool quiet, double max_work_factor) {
            const std::string folder = out.is_none() ? "" : FsPath(out);
            st::Outputs o = RunOutputs(s, folder, quiet, max_work_factor, progress);
            const std::string incomplete = o.incomplete();
            return MakeResult(s.study, o.files(), incomplete, folder, o.result());
          },
          py::arg("out") = py::none(), py::arg("progress") = py::none(), py::arg("quiet") = true,
          py::arg("max_work_factor") = 1.0,
          "Runs the study and returns a camopt.Result. out=FOLDER also writes the files there, as\n"
          "`camopt run --out FOLDER` would (all at once at the end: a cancelled run leaves FOLDER as it\n"
          "was). progress(event) is called with camopt.ProgressEvent reports (at most every 100 ms per\n"
          "stage); an exception it raises stops the run and is raised here. Ctrl-C stops the run within\n"
          "a second and raises KeyboardInterrupt. Raises camopt.StudyError for a study over its work\n"
          "limits.")
      .def("__repr__", [](const StudyData& s) { return "<camopt.Study " + s.kind() + " from " + s.file + ">"; });

  py::class_<SweepData>(m, "Sweep", "A checked sweep (`camopt sweep`): a base study run over many cases.")
      .def(py::init(&ToSweep), py::arg("sweep"),
           "A sweep from a dict (a sweep file's JSON; a relative \"base\" is found from the current folder)\n"
           "or from the path of a sweep file. Raises FileNotFoundError, camopt.StudyError.")
      .def_static("load", &LoadSweep, py::arg("path"),
                  "Reads and checks a sweep file. Raises FileNotFoundError, camopt.StudyError.")
      .def_readonly("file", &SweepData::file)
      .def_property_readonly("name", [](const SweepData& s) { return s.sweep.name; })
      .def_property_readonly("cases", &CaseTable,
                             "The cases: a list of {'case': index, input's JSON pointer: value}, one per case,\n"
                             "as cases.csv numbers them (pandas.DataFrame(sweep.cases) makes a table of it).")
      .def("__len__", [](const SweepData& s) { return s.cases.size(); }, "The number of cases.")
      .def("run", &RunSweep, py::arg("out") = py::none(), py::arg("jobs") = 0, py::arg("quiet") = true,
           py::arg("max_work_factor") = 1.0, py::arg("progress") = py::none(),
           "Runs every case (jobs threads; 0: the machine's cores) and returns a camopt.Result: result.json\n"
           "of the sweep, tables['cases'] (and tables['pareto']). out=FOLDER keeps the folder as `camopt\n"
           "sweep --out FOLDER` does (a Ctrl-C keeps its finished cases for `camopt sweep --resume`);\n"
           "without it, a temporary folder is used and removed. Ctrl-C raises KeyboardInterrupt.")
      .def("__repr__", [](const SweepData& s) { return "<camopt.Sweep " + s.sweep.name + " from " + s.file + ">"; });

  m.def("run", &Run, py::arg("study"), py::arg("out") = py::none(), py::arg("quiet") = true,
        py::arg("max_work_factor") = 1.0,
        "Runs a study (a dict, or the path of a study file) and returns result.json as a dict:\n"
        "arrays of numbers as NumPy arrays, plus 'series' (every CSV output as {column: array}),\n"
        "'files' (the names of the outputs) and, when the result is not what was asked (not\n"
        "converged, nothing feasible), 'incomplete' with the reason. With out=FOLDER the files are\n"
        "also written there, as `camopt run --out FOLDER` would. Raises camopt.StudyError for a bad\n"
        "study (also for a missing file). Ctrl-C raises KeyboardInterrupt. camopt.Study is the\n"
        "object form.");
  m.def("kinds", &camopt::studies::StudyKinds, "The study kinds this build knows.");
  m.def(
      "schema",
      [](const std::string& kind, bool result) {
        try {
          return py::module_::import("json").attr("loads")(result ? camopt::studies::StudyResultSchema(kind)
                                                                  : camopt::studies::StudySchema(kind));
        } catch (const camopt::studies::StudyError& e) {
          RaiseStudyError(e, "");
        }
      },
      py::arg("kind"), py::arg("result") = false,
      "The JSON Schema (draft 2020-12) of a study kind, as a dict; with result=True, of its result.json\n"
      "(camopt.StudyError for a kind whose result is not declared yet).");
  camopt::python::AddModels(m);
}
