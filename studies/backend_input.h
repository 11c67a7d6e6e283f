// The optimizer's "backend" field of a sizing study, declared once for every kind: one spelling
// across kinds ("ipopt", "slsqp", "mma", "cobyla", optimizers::ToString(Backend)). lcr_min_size's
// old spellings "nlopt_slsqp", "nlopt_mma" and "nlopt_cobyla" are still accepted there, so that no
// study breaks, with a deprecation warning on stderr and in result.json's "warnings"
// (PlausibilityWarnings, studies/provenance.cc); result.json writes the one spelling.
#pragma once

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "optimizers/solver.h"
#include "studies/archive.h"

namespace camopt::studies {

/// The field of a backend among `allowed`, with the deprecated old spellings of those backends when
/// `old_spellings` (lcr_min_size, the one kind that had them); the error names the spellings only.
inline Field BackendField(std::initializer_list<optimizers::Backend> allowed, bool old_spellings = false) {
  std::vector<std::string> names, deprecated;
  for (optimizers::Backend b : allowed) {
    names.push_back(optimizers::ToString(b));
    if (old_spellings && b != optimizers::Backend::kIpopt) deprecated.push_back(std::string("nlopt_") + optimizers::ToString(b));
  }
  const std::string expected = "one of \"" + [&] {
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : "\", \"") + n;
    return text;
  }() + "\"";
  names.insert(names.end(), deprecated.begin(), deprecated.end());
  return Field().OneOf(names, expected);
}

/// The backend of a name BackendField accepted.
inline optimizers::Backend ToBackend(const std::string& name) {
  if (const auto b = optimizers::BackendFromName(name)) return *b;
  throw std::logic_error("not a backend: " + name);
}

/// The deprecation warning of an old spelling at `path` (none for a current one).
inline std::optional<std::string> BackendSpellingWarning(const std::string& name, const std::string& path) {
  bool deprecated = false;
  const auto b = optimizers::BackendFromName(name, &deprecated);
  if (!b || !deprecated) return std::nullopt;
  return path + ": \"" + name + "\" is the old spelling of \"" + optimizers::ToString(*b) +
         "\" (accepted, deprecated: write \"" + optimizers::ToString(*b) + "\")";
}

/// result.json's "optimizer" keys of every sizing whose answer the accurate model verifies
/// (cycloid_min_size, disc_cam_min_size, disc_cam_motion): the backend, how the last solve ended,
/// the budgets and the model runs. Each kind's block derives from it and visits its own keys after
/// these.
struct SolveSummary {
  std::string backend;
  bool converged = false;
  std::string status, message;
  int max_evaluations = 0, verify_rounds = 0, evaluations = 0, gradient_evaluations = 0;
  /// The last solve's end (`last`), whether the sizing counts it converged, the budgets and the
  /// model runs summed over every solve.
  void Set(const std::string& backend_name, bool sizing_converged, const optimizers::SolverResult& last,
           int max_evaluations_per_solve, int verify_round_budget, int value_runs, int gradient_runs) {
    backend = backend_name;
    converged = sizing_converged;
    status = optimizers::ToString(last.status);
    message = last.message;
    max_evaluations = max_evaluations_per_solve;
    verify_rounds = verify_round_budget;
    evaluations = value_runs;
    gradient_evaluations = gradient_runs;
  }
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("backend", &backend, Field().OneOf({"ipopt", "slsqp"}).Desc("the NLP solver (slsqp: NLopt's)"));
    a->Visit("converged", &converged, Field().Desc("the last solve converged (the optimizer's own test)"));
    a->Visit("status", &status, Field().Desc("the last solve's end"));
    a->Visit("message", &message, Field().Desc("the backend's own words"));
    a->Visit("max_evaluations", &max_evaluations, Field().Desc("the budget of each solve"));
    a->Visit("verify_rounds", &verify_rounds, Field().Desc("the verification loop's budget"));
    a->Visit("evaluations", &evaluations, Field().Desc("model runs for values, summed over every solve"));
    a->Visit("gradient_evaluations", &gradient_evaluations,
             Field().Desc("model runs with exact derivatives, summed over every solve"));
  }
};

}  // namespace camopt::studies
