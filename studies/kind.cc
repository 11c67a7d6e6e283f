#include "studies/kind.h"

#include <map>
#include <mutex>
#include <stdexcept>

namespace camopt::studies {
namespace {

std::map<std::string, KindDescriptor>& Kinds() {
  static std::map<std::string, KindDescriptor> kinds;
  return kinds;
}

// A schema text emitted on first use and kept (the emitters walk a whole declaration).
const std::string* Emitted(const std::string& kind, bool result) {
  static std::map<std::pair<std::string, bool>, std::string> texts;
  static std::mutex mutex;
  const KindDescriptor* k = FindKind(kind);
  if (!k) return nullptr;
  const std::lock_guard<std::mutex> lock(mutex);
  auto [text, fresh] = texts.try_emplace({kind, result});
  if (fresh) text->second = result ? k->result_schema() : k->input_schema();
  return &text->second;
}

}  // namespace

bool RegisterKind(KindDescriptor kind) {
  if (!kind.run || kind.name.empty()) throw std::logic_error("study kind registered without a name or a Run");
  const std::string name = kind.name;
  if (!Kinds().emplace(name, std::move(kind)).second)
    throw std::logic_error("study kind " + name + " registered twice");
  return true;
}

const KindDescriptor* FindKind(const std::string& name) {
  const auto it = Kinds().find(name);
  return it == Kinds().end() ? nullptr : &it->second;
}

std::vector<std::string> StudyKinds() {
  std::vector<std::string> names;
  for (const auto& [name, kind] : Kinds()) names.push_back(name);
  return names;
}

const std::string* DeclaredSchema(const std::string& kind) { return Emitted(kind, false); }
const std::string* DeclaredResultSchema(const std::string& kind) { return Emitted(kind, true); }

const FidelityOf* FindFidelity(const std::string& kind) {
  const KindDescriptor* k = FindKind(kind);
  return k && k->fidelity ? &k->fidelity : nullptr;
}

std::vector<std::string> DeclaredRunFactKeys(const std::string& kind) {
  const KindDescriptor* k = FindKind(kind);
  return k ? k->run_fact_keys() : std::vector<std::string>{};
}

}  // namespace camopt::studies
