// A study kind, described once. Everything camopt knows of a kind — its input and its result
// (each declared with a Serialize, studies/archive.h), how it runs, its fidelity knobs, its work
// estimate, its report rows and datasheet, the blocks it computes on request, the example `camopt
// init` starts from and the studio's drawing of it — is one KindDescriptor, registered once with
// CAMOPT_REGISTER_KIND. `camopt kinds`, `run`, `check`, `schema`, `init`, `--convergence`, the work
// limits, report.html, datasheet.html, the status and the studio all read the registry.
//
// The smallest kind is an Input, a Result and a Run (tests/test_kind.cc):
//
//   Result Run(const Input& in, const RunContext& ctx);
//   CAMOPT_REGISTER_KIND(Kind<Input, Result>{.name = "my_kind", .title = "camopt study: …", .run = Run});
//
// The rest is optional and named where the kind has it (designated initialisers, in the order of
// Kind's members): `.parse` for the checks between fields (returning the Input itself, or a
// model-unit Study made from it where a kind still has one), the files beside result.json
// by `.write`, `.summary` on stderr, `.knobs`, `.estimate`, `.report`, `.datasheet`, `.asked`,
// `.init_example`, `.mechanism`, and for a sizing kind `.sizing_of` and `.start_study`.
#pragma once

#include <functional>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

#include "studies/archive.h"
#include "studies/datasheet.h"
#include "studies/input.h"
#include "studies/report.h"
#include "studies/status.h"
#include "studies/study.h"
#include "studies/work_limits.h"
#include "sizing/stage_clock.h"

namespace camopt::studies {

struct LoadedRun;  // studies/studio_mechanism.h

/// The studio's drawing of a study of the kind at one input angle (studies/studio_mechanism.h
/// describes the JSON); `run` the loaded run of the study, when there is one.
using MechanismView = nlohmann::json (*)(const nlohmann::json& study, double input_angle_deg, int points,
                                         const LoadedRun* run);
/// A sizing kind's start design as a study of its analysis kind (`sizing_of`), from the sizing study
/// and its run's optimum study (null when not run); a JSON string says why there is none.
using StartStudyOf = nlohmann::json (*)(const Node& root, const nlohmann::json& optimum);

/// One kind as the registry holds it (type-erased from a Kind of any Input, Result and Study).
struct KindDescriptor {
  std::string name, title;
  /// Parse, solve and files, each timed as a phase of outputs (RunStudy).
  std::function<void(const Node& root, const RunContext& ctx, Outputs& outputs)> run;
  /// The parse alone: every check of the file, nothing run (CheckStudy).
  std::function<void(const Node& root)> check;
  std::function<std::string()> input_schema, result_schema;  ///< JSON Schema texts (DeclaredSchema)
  DeclaredEcho echo = nullptr;
  std::vector<std::string> (*run_fact_keys)() = nullptr;
  FidelityOf fidelity;  ///< empty: no knob
  WorkEstimator estimate;  ///< empty: no cap
  std::optional<std::vector<Headline>> report;  ///< none: every top-level number of result.json
  std::optional<DatasheetSpec> datasheet;
  std::vector<AskedBlock> asked;
  std::string init_example;  ///< a file of studies/examples/ without .json ("": the declared defaults)
  MechanismView mechanism = nullptr;
  std::string sizing_of;  ///< the analysis kind whose studies a sizing kind's designs are
  StartStudyOf start_study = nullptr;
};

/// How a kind is written (see the top of this file). StudyT is what Run takes: the Input itself,
/// or a model-unit struct that `parse` makes from it.
template <typename InputT, typename ResultT, typename StudyT = InputT>
struct Kind {
  const char* name = "";
  const char* title = "";
  ResultT (*run)(const StudyT&, const RunContext&) = nullptr;
  StudyT (*parse)(const Node& root) = nullptr;  ///< absent: Read<InputT> (StudyT must be InputT)
  void (*write)(const StudyT&, const ResultT&, Outputs&) = nullptr;  ///< absent: result.json alone
  std::string (*summary)(const StudyT&, const ResultT&) = nullptr;    ///< on stderr unless quiet
  Fidelity (*knobs)(const nlohmann::json& study) = nullptr;
  WorkEstimate (*estimate)(const nlohmann::json& study, const std::string& file, double factor) = nullptr;
  std::optional<std::vector<Headline>> report = std::nullopt;
  std::optional<DatasheetSpec> datasheet = std::nullopt;
  std::vector<AskedBlock> asked = {};
  const char* init_example = "";
  MechanismView mechanism = nullptr;
  const char* sizing_of = "";
  StartStudyOf start_study = nullptr;
};

/// Registers a kind; returns true (for a static). A second kind of the same name is a defect
/// (std::logic_error at start-up).
bool RegisterKind(KindDescriptor kind);
/// The kind registered as `name`, or nullptr.
const KindDescriptor* FindKind(const std::string& name);

/// The JSON Schema texts of a kind's study file (`camopt schema KIND`) and of its result.json
/// (`--result`), emitted once; nullptr for an unknown kind.
const std::string* DeclaredSchema(const std::string& kind);
const std::string* DeclaredResultSchema(const std::string& kind);
/// The kind's fidelity knobs (KindDescriptor::fidelity), or nullptr when it has none.
const FidelityOf* FindFidelity(const std::string& kind);
/// The top-level result.json keys of a kind marked Field::Decides (empty for an unknown kind).
std::vector<std::string> DeclaredRunFactKeys(const std::string& kind);

namespace kind_detail {
template <typename InputT, typename StudyT>
StudyT ParseOrRead(StudyT (*parse)(const Node&), const Node& root) {
  if (parse) return parse(root);
  if constexpr (std::is_same_v<StudyT, InputT>) return Read<InputT>(root);
  else throw std::logic_error("a kind whose Run takes a Study of its own names its parse");
}
}  // namespace kind_detail

/// The registry's form of a Kind: its name, schemas and echo from the declarations, its run as
/// Timed phases "parse", "solve" and "files".
template <typename InputT, typename ResultT, typename StudyT>
KindDescriptor Describe(const Kind<InputT, ResultT, StudyT>& k) {
  KindDescriptor d;
  d.name = k.name;
  d.title = k.title;
  d.run = [run = k.run, parse = k.parse, write = k.write, summary = k.summary](
              const Node& root, const RunContext& ctx, Outputs& out) {
    auto& phases = out.phases();
    const StudyT study = Timed(phases, "parse", [&] { return kind_detail::ParseOrRead<InputT>(parse, root); });
    // A sizing's verification and limit costs (sizing/stage_clock.h) out of "solve", after it.
    struct Stages {
      std::vector<PhaseTime>& phases;
      Stages(std::vector<PhaseTime>& p) : phases(p) { sizing::StageClock::Start(); }
      ~Stages() { (void)sizing::StageClock::Stop(); }
      void Split() {
        const size_t solve = phases.size() - 1;
        for (const sizing::StageTime& t : sizing::StageClock::Stop()) {
          phases[solve].cpu_s -= t.cpu_s, phases[solve].wall_s -= t.wall_s;
          phases.push_back({t.name, t.cpu_s, t.wall_s});
        }
      }
    } stages{phases};
    const ResultT result = Timed(phases, "solve", [&] { return run(study, ctx); });
    stages.Split();
    Timed(phases, "files", [&] {
      if (write) write(study, result, out);
      else out.SetResult(result);
    });
    if (summary && !ctx.quiet) std::cerr << summary(study, result);
  };
  d.check = [parse = k.parse](const Node& root) { (void)kind_detail::ParseOrRead<InputT>(parse, root); };
  d.input_schema = [name = d.name, title = d.title] { return EmitSchema<InputT>(name, title).dump(2) + "\n"; };
  d.result_schema = [name = d.name, title = d.title] {
    return EmitResultSchema<ResultT>(name, "result.json of the " + title).dump(2) + "\n";
  };
  d.echo = [](const nlohmann::json& study, const std::string& file) {
    return WriteJson(Read<InputT>(Node(&study, file, "")));
  };
  d.run_fact_keys = &RunFactKeys<ResultT>;
  if (k.knobs) d.fidelity = k.knobs;
  if (k.estimate) d.estimate = k.estimate;
  d.report = k.report;
  d.datasheet = k.datasheet;
  d.asked = k.asked;
  d.init_example = k.init_example;
  d.mechanism = k.mechanism;
  d.sizing_of = k.sizing_of;
  d.start_study = k.start_study;
  return d;
}

}  // namespace camopt::studies

#define CAMOPT_KIND_CONCAT_INNER(a, b) a##b
#define CAMOPT_KIND_CONCAT(a, b) CAMOPT_KIND_CONCAT_INNER(a, b)
/// Registers a kind, written as a Kind<Input, Result[, Study]>{…} (the top of this file).
#define CAMOPT_REGISTER_KIND(...)                                               \
  static const bool CAMOPT_KIND_CONCAT(camopt_kind_registered_, __COUNTER__) = \
      ::camopt::studies::RegisterKind(::camopt::studies::Describe(__VA_ARGS__))
