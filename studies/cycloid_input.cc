// The shared blocks of the cycloid study kinds (studies/cycloid_input.h): the crowning's rules by
// type and the schemas of the bearing-life blocks.
#include "studies/cycloid_input.h"

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

ojson DutyCycleSchema() {
  return {{"type", "array"},
          {"minItems", 1},
          {"items",
           {{"type", "object"},
            {"properties",
             {{"output_torque_Nm",
               {{"description", "the disc's torque in this line (one disc) [N·m]"}, {"type", "number"}, {"minimum", 0}}},
              {"input_speed_rpm",
               {{"description", "the input (crank) speed in this line [rpm]"}, {"type", "number"}, {"minimum", 0}}},
              {"time_share",
               {{"description", "the share of the time in this line (the shares sum to 1 within 1e-6)"},
                {"type", "number"},
                {"exclusiveMinimum", 0},
                {"maximum", 1}}}}},
            {"required", {"output_torque_Nm", "input_speed_rpm", "time_share"}},
            {"additionalProperties", false}}}};
}

namespace {
ojson RatingProperties() {
  return {{"dynamic_rating_N",
           {{"description", "C, the basic dynamic load rating (ISO 281) [N]"}, {"type", "number"}, {"exclusiveMinimum", 0}}},
          {"static_rating_N",
           {{"description", "C₀, the basic static load rating, for the static safety s₀ = C₀ / P₀ (absent: none) [N]"},
            {"type", "number"},
            {"exclusiveMinimum", 0}}}};
}
}  // namespace

ojson CrankBearingSchema() {
  ojson p = {{"kind", {{"description", "ball or roller bearing (the life exponent p = 3 or 10/3)"},
                       {"enum", {"ball", "roller"}}}}};
  const ojson ratings = RatingProperties();
  for (auto it = ratings.begin(); it != ratings.end(); ++it) p[it.key()] = it.value();
  return {{"type", "object"}, {"properties", p}, {"required", {"kind", "dynamic_rating_N"}}, {"additionalProperties", false}};
}

ojson PinRatingSchema() {
  return {{"type", "object"},
          {"properties", RatingProperties()},
          {"required", {"dynamic_rating_N"}},
          {"additionalProperties", false}};
}

}  // namespace camopt::studies::cycloid_common
