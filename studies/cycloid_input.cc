// The shared blocks of the cycloid study kinds (studies/cycloid_input.h): the crowning's rules by
// type.
#include "studies/cycloid_input.h"

#include "studies/bearing_life_io.h"

namespace camopt::studies::cycloid_common {

using ojson = nlohmann::ordered_json;

const std::vector<CrowningTypeFields>& CrowningTypes() {
  static const std::vector<CrowningTypeFields> types = {
      {"none", {}, {"radius_mm", "flat_length_mm", "coefficient_mm", "effective_length_mm", "end_drop_mm"}},
      {"full", {"radius_mm"}, {"flat_length_mm", "coefficient_mm", "effective_length_mm", "end_drop_mm"}},
      {"partial", {"radius_mm", "flat_length_mm"}, {"coefficient_mm", "effective_length_mm", "end_drop_mm"}},
      {"logarithmic", {"coefficient_mm"}, {"radius_mm"}},
  };
  return types;
}

namespace {
ojson CrowningRules(bool with_required) {
  ojson all = ojson::array();
  for (const auto& [type, required, refused] : CrowningTypes()) {
    ojson then = ojson::object();
    if (with_required && !required.empty()) then["required"] = required;
    for (const char* f : refused) then["properties"][f] = false;
    all.push_back({{"if", {{"properties", {{"type", {{"const", type}}}}}}}, {"then", then}});
  }
  return {{"allOf", all}};
}
}  // namespace

ojson CrowningInput::SchemaRules() { return CrowningRules(true); }
ojson CrowningStartInput::SchemaRules() { return CrowningRules(false); }

}  // namespace camopt::studies::cycloid_common
