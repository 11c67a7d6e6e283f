// The Python module `camopt` (pybind11): run a study from a dict or a file and get its result as
// a dict, with series as NumPy arrays; list the kinds and their JSON Schemas.
//
//   import camopt
//   r = camopt.run("studies/examples/lcr_ii.json")       # or camopt.run({...}), out="folder"
//   r["input_cam"]["max_contact_stress_MPa"]; r["series"]["series"]["efficiency"]  # numpy array
//   camopt.kinds(); camopt.schema("lcr_analysis"); camopt.__version__
//
// A bad study raises camopt.StudyError (a ValueError) with .file, .path (JSON path), .expected,
// .found; a study over its work limits too. Everything the module computes goes through
// studies/study.h's RunStudy, exactly as the command line does.
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "studies/input.h"
#include "studies/provenance.h"
#include "studies/schemas.h"
#include "studies/study.h"

namespace py = pybind11;
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
  if (!std::getline(in, line)) return out;
  const std::vector<std::string> names = SplitCsvLine(line);
  std::vector<std::vector<std::string>> cols(names.size());
  while (std::getline(in, line)) {
    if (line.empty()) continue;
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

// The parts of a StudyError; for a message built without a Node ("FILE: /PATH: rest"), taken from
// the message.
[[noreturn]] void RaiseStudyError(const camopt::studies::StudyError& e, const std::string& study_file) {
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

py::dict Run(const py::object& study, const py::object& out, bool quiet, double max_work_factor) {
  namespace st = camopt::studies;
  st::RunContext ctx;
  ctx.quiet = quiet;
  ctx.max_work_factor = max_work_factor;
  json parsed;
  std::string text;
  try {
    if (py::isinstance<py::dict>(study)) {
      ctx.study_file = "<dict>";
      text = py::module_::import("json").attr("dumps")(study).cast<std::string>();
      parsed = st::ParseStudyText(text, ctx.study_file, st::CurrentInputLimits().max_depth);
    } else {
      ctx.study_file = py::str(py::module_::import("os").attr("fspath")(study)).cast<std::string>();
      text = st::ReadFileCapped(ctx.study_file, st::CurrentInputLimits().max_file_bytes, "file");
      parsed = st::ParseStudyText(text, ctx.study_file, st::CurrentInputLimits().max_depth);
      ctx.study_sha256 = st::Sha256Hex(text);
    }
    st::Outputs outputs;
    {
      std::unique_ptr<st::OutputFolder> folder;
      if (!out.is_none())
        folder = std::make_unique<st::OutputFolder>(py::str(py::module_::import("os").attr("fspath")(out)));
      py::gil_scoped_release release;
      outputs = st::RunStudy(parsed, ctx);
      if (folder) folder->Commit(outputs);
    }
    const auto& files = outputs.files();
    py::dict result;
    const auto r = files.find("result.json");
    if (r != files.end()) result = ToPython(json::parse(r->second)).cast<py::dict>();
    py::dict series;
    for (const auto& [name, content] : files)
      if (name.size() > 4 && name.compare(name.size() - 4, 4, ".csv") == 0)
        series[py::str(name.substr(0, name.size() - 4))] = CsvColumns(content);
    result["series"] = series;
    py::list names;
    for (const auto& [name, content] : files) names.append(name);
    result["files"] = names;
    if (!outputs.incomplete().empty()) result["incomplete"] = outputs.incomplete();
    return result;
  } catch (const st::StudyError& e) {
    RaiseStudyError(e, ctx.study_file);
  }
}

}  // namespace

PYBIND11_MODULE(camopt, m) {
  m.doc() = "camopt: design optimisation of cam reducers and cam mechanisms (run studies from Python)";
  m.attr("__version__") = camopt::studies::CamoptVersion();
  g_study_error = py::handle(PyErr_NewExceptionWithDoc("camopt.StudyError",
                                "A bad study: .file, .path (JSON path), .expected, .found name the fault.",
                                PyExc_ValueError, nullptr));
  m.attr("StudyError") = py::reinterpret_borrow<py::object>(g_study_error);
  m.def("run", &Run, py::arg("study"), py::arg("out") = py::none(), py::arg("quiet") = true,
        py::arg("max_work_factor") = 1.0,
        "Runs a study (a dict, or the path of a study file) and returns result.json as a dict:\n"
        "arrays of numbers as NumPy arrays, plus 'series' (every CSV output as {column: array}),\n"
        "'files' (the names of the outputs) and, when the result is not what was asked (not\n"
        "converged, nothing feasible), 'incomplete' with the reason. With out=FOLDER the files are\n"
        "also written there, as `camopt run --out FOLDER` would. Raises camopt.StudyError for a bad\n"
        "study.");
  m.def("kinds", &camopt::studies::StudyKinds, "The study kinds this build knows.");
  m.def(
      "schema",
      [](const std::string& kind) {
        try {
          return py::module_::import("json").attr("loads")(camopt::studies::StudySchema(kind));
        } catch (const camopt::studies::StudyError& e) {
          RaiseStudyError(e, "");
        }
      },
      py::arg("kind"), "The JSON Schema (draft 2020-12) of a study kind, as a dict.");
}
