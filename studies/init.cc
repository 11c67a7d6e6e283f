#include "studies/init.h"

#include <vector>

#include <nlohmann/json.hpp>

#include "studies/archive.h"
#include "studies/input.h"
#include "studies/kind.h"
#include "studies/study.h"
#include "studies/suggest.h"

namespace camopt::studies {
namespace {

// Every property with a schema "default" that `value` leaves out, added, at every level the study
// has (objects, array items); for the fields a declaration keeps as JSON with a schema of their
// own (a motion segment), whose defaults the echo cannot fill.
void FillDefaults(const nlohmann::ordered_json& schema, nlohmann::ordered_json& value) {
  if (value.is_array() && schema.contains("items")) {
    for (auto& item : value) FillDefaults(schema["items"], item);
    return;
  }
  if (!value.is_object() || !schema.contains("properties")) return;
  for (auto it = schema["properties"].begin(); it != schema["properties"].end(); ++it) {
    if (!value.contains(it.key())) {
      if (it.value().contains("default")) value[it.key()] = it.value()["default"];
      continue;
    }
    FillDefaults(it.value(), value[it.key()]);
  }
}

}  // namespace

InitStudy InitTemplate(const std::string& kind) {
  const KindDescriptor* k = FindKind(kind);
  if (!k) {
    const std::vector<std::string> kinds = StudyKinds();
    std::string known;
    for (const auto& name : kinds) known += (known.empty() ? "" : ", ") + name;
    const std::string near = NearestName(kind, kinds);
    throw StudyError("init " + kind + ": expected a study kind (" + known + "), found " + kind +
                     (near.empty() ? "" : " (did you mean \"" + near + "\"?)"));
  }
  // The kind's example (KindDescriptor::init_example), or a study of its declared defaults alone.
  InitStudy out;
  out.example = k->init_example;
  nlohmann::json example = {{"study", kind}};
  if (!k->init_example.empty()) {
    const auto text = EmbeddedTemplates().find(k->init_example);
    if (text == EmbeddedTemplates().end())
      throw std::logic_error("study kind " + kind + ": no example " + k->init_example + " in studies/examples/");
    example = nlohmann::json::parse(text->second);
  }
  nlohmann::ordered_json study = k->echo(example, "studies/examples/" + out.example + ".json");
  FillDefaults(nlohmann::ordered_json::parse(*DeclaredSchema(kind)), study);
  out.text = study.dump(2) + "\n";
  return out;
}

}  // namespace camopt::studies
