// The shared blocks of the cycloid study kinds (studies/cycloid_input.h): the crowning's rules by
// type and the schemas of the bearing-life blocks.
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

namespace {
ojson RatingProperties(bool modified_life) {
  ojson p = {{"dynamic_rating_N",
              {{"description", "C, the basic dynamic load rating (ISO 281) [N]"}, {"type", "number"}, {"exclusiveMinimum", 0}}},
             {"static_rating_N",
              {{"description", "C₀, the basic static load rating, for the static safety s₀ = C₀ / P₀ (absent: none) [N]"},
               {"type", "number"},
               {"exclusiveMinimum", 0}}},
             {"designation",
              {{"description", "the catalogue's designation, in bom.csv (docs/parts.md)"}, {"type", "string"}}}};
  if (modified_life) {
    p["fatigue_load_limit_N"] = {{"description", std::string(kFatigueLoadLimitDesc) + " [N]"},
                                 {"type", "number"},
                                 {"exclusiveMinimum", 0}};
    p["pitch_diameter_mm"] = {{"description", std::string(kPitchDiameterDesc) + " [mm]"},
                              {"type", "number"},
                              {"exclusiveMinimum", 0}};
  }
  return p;
}

// A rating block's schema around its properties; C_u and D_pw come together (ParseModifiedLifeRating).
ojson RatingBlock(const ojson& properties, const ojson& required, bool modified_life) {
  ojson s = {{"type", "object"}, {"properties", properties}, {"required", required}, {"additionalProperties", false}};
  if (modified_life)
    s["dependentRequired"] = {{"fatigue_load_limit_N", {"pitch_diameter_mm"}},
                              {"pitch_diameter_mm", {"fatigue_load_limit_N"}}};
  return s;
}
}  // namespace

ojson CrankBearingSchema(bool modified_life) {
  ojson p = {{"kind", {{"description", "ball or roller bearing (the life exponent p = 3 or 10/3)"},
                       {"enum", {"ball", "roller"}}}}};
  const ojson ratings = RatingProperties(modified_life);
  for (auto it = ratings.begin(); it != ratings.end(); ++it) p[it.key()] = it.value();
  return RatingBlock(p, {"kind", "dynamic_rating_N"}, modified_life);
}

ojson PinRatingSchema(bool modified_life) {
  return RatingBlock(RatingProperties(modified_life), {"dynamic_rating_N"}, modified_life);
}

}  // namespace camopt::studies::cycloid_common
