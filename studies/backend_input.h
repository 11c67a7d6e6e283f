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

}  // namespace camopt::studies
