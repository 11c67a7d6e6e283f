#include "studies/init.h"

#include <vector>

#include <nlohmann/json.hpp>

#include "studies/archive.h"
#include "studies/input.h"
#include "studies/study.h"
#include "studies/suggest.h"

namespace camopt::studies {

InitStudy InitTemplate(const std::string& kind) {
  for (const auto& [name, text] : EmbeddedTemplates()) {
    const nlohmann::json example = nlohmann::json::parse(text);
    if (example.value("study", "") != kind) continue;
    InitStudy out;
    out.example = name;
    if (const DeclaredEcho echo = FindDeclaredEcho(kind)) {
      out.text = echo(example, "studies/examples/" + name + ".json").dump(2) + "\n";
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
