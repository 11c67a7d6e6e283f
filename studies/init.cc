#include "studies/init.h"

#include <vector>

#include <nlohmann/json.hpp>

#include "studies/archive.h"
#include "studies/input.h"
#include "studies/study.h"
#include "studies/suggest.h"

namespace camopt::studies {
namespace {

// Every property with a schema "default" that `value` leaves out, added, at every level the study
// has (objects, array items); for the fields a declaration keeps as JSON with a schema of their
// own (a motion segment, analysis.monte_carlo's object form), whose defaults the echo cannot fill.
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
  for (const auto& [name, text] : EmbeddedTemplates()) {
    const nlohmann::json example = nlohmann::json::parse(text);
    if (example.value("study", "") != kind) continue;
    InitStudy out;
    out.example = name;
    if (const DeclaredEcho echo = FindDeclaredEcho(kind)) {
      nlohmann::ordered_json study = echo(example, "studies/examples/" + name + ".json");
      if (const std::string* schema = DeclaredSchema(kind)) FillDefaults(nlohmann::ordered_json::parse(*schema), study);
      out.text = study.dump(2) + "\n";
      out.every_default = true;
    } else {
      out.text = text;
    }
    return out;
  }
  const std::vector<std::string> kinds = StudyKinds();
  std::string known;
  for (const auto& k : kinds) known += (known.empty() ? "" : ", ") + k;
  const std::string near = NearestName(kind, kinds);
  throw StudyError("init " + kind + ": expected a study kind (" + known + "), found " + kind +
                   (near.empty() ? "" : " (did you mean \"" + near + "\"?)"));
}

}  // namespace camopt::studies
