// What the two source files of the Python module share (python/camopt_module.cc: studies, results,
// sweeps and the interruptible run; python/camopt_models.cc: the model objects).
#pragma once

#include <functional>
#include <string>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include "studies/input.h"

namespace camopt::python {

namespace py = pybind11;

/// A study as the module holds it: the parsed JSON, the file it came from ("<dict>" for a dict)
/// and the SHA-256 of the file's bytes ("" for a dict: RunStudy takes that of the JSON).
struct StudyData {
  nlohmann::json study;
  std::string file;
  std::string sha256;
  std::string kind() const { return study.is_object() ? study.value("study", std::string()) : std::string(); }
};

/// A camopt.Study, a dict or a path (str or os.PathLike) as a checked study. Raises
/// FileNotFoundError for a missing file and camopt.StudyError for a bad study.
StudyData ToStudy(const py::object& study);

/// Raises camopt.StudyError with .file, .path, .expected, .found.
[[noreturn]] void RaiseStudyError(const studies::StudyError& e, const std::string& study_file);

/// Runs `work` on a thread of its own with the GIL released, one run at a time per process (the
/// cancellation flag and the progress observer are process-wide). The calling thread wakes every
/// 50 ms to run Python's signal handlers: on Ctrl-C (KeyboardInterrupt), or when the progress
/// callback raises, it asks the run to stop (studies::RequestCancel), waits for the worker to
/// unwind and raises that exception. `progress` (None or a callable) receives every
/// camopt.ProgressEvent of the run. Exceptions of `work` are rethrown here (with the GIL held).
void RunInterruptibly(const std::function<void()>& work, const py::object& progress);

/// Registers camopt.Lcr and camopt.CycloidDrive (python/camopt_models.cc).
void AddModels(py::module_& m);

}  // namespace camopt::python
