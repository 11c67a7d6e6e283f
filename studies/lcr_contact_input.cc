#include "studies/lcr_contact_input.h"

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

namespace camopt::studies {

lcr::RollerCrowning<double> ParseRollerCrowning(const Node& n, double roller_length, bool coefficient_given) {
  n.CheckKnownFields({"type", "radius_mm", "flat_length_mm", "coefficient_mm", "effective_length_mm"});
  lcr::RollerCrowning<double> c;
  const std::string type = n["type"].String();
  // Each form takes its own fields only (a field of another form would be silently ignored).
  if (type == "none") n.CheckKnownFields({"type"});
  if (type == "circular") n.CheckKnownFields({"type", "radius_mm"});
  if (type == "partial") n.CheckKnownFields({"type", "radius_mm", "flat_length_mm"});
  if (type == "logarithmic") n.CheckKnownFields({"type", "coefficient_mm", "effective_length_mm"});
  if (type == "none") {
    c.type = contact::CrowningType::kNone;
  } else if (type == "circular") {
    c.type = contact::CrowningType::kCircular;
    c.radius = n["radius_mm"].Positive();
  } else if (type == "partial") {
    c.type = contact::CrowningType::kPartial;
    c.radius = n["radius_mm"].Positive();
    c.flat_length = n["flat_length_mm"].NonNegative();
  } else if (type == "logarithmic") {
    c.type = contact::CrowningType::kLogarithmic;
    c.coefficient = coefficient_given ? n["coefficient_mm"].NonNegative() : n.NonNegativeOr("coefficient_mm", 0.0);
    c.effective_length = n["effective_length_mm"].Positive();
  } else {
    n["type"].Fail("one of none, circular, partial, logarithmic");
  }
  const std::string problem = lcr::CheckRollerCrowning(c, roller_length);
  if (!problem.empty()) n.FailWith(problem + " (roller length " + std::to_string(roller_length) + " mm)");
  return c;
}

LcrCrowningInput CrowningInputOf(const lcr::RollerCrowning<double>& c) {
  LcrCrowningInput j;
  switch (c.type) {
    case contact::CrowningType::kNone: j.type = "none"; break;
    case contact::CrowningType::kCircular: j.type = "circular", j.radius_mm = c.radius; break;
    case contact::CrowningType::kPartial: j.type = "partial", j.radius_mm = c.radius, j.flat_length_mm = c.flat_length; break;
    case contact::CrowningType::kLogarithmic:
      j.type = "logarithmic", j.coefficient_mm = c.coefficient, j.effective_length_mm = c.effective_length;
      break;
  }
  return j;
}

const char* ContactModelName(lcr::ContactModel m) {
  switch (m) {
    case lcr::ContactModel::kLine: return "line";
    case lcr::ContactModel::kSlices: return "slices";
    case lcr::ContactModel::kHalfSpace: return "half_space";
  }
  return "line";
}

namespace {
// The crowning's rules by type; coefficient_required: a logarithmic crown needs its coefficient.
nlohmann::ordered_json CrowningRules(bool coefficient_required) {
  const std::vector<const char*> logarithmic =
      coefficient_required ? std::vector<const char*>{"coefficient_mm", "effective_length_mm"}
                           : std::vector<const char*>{"effective_length_mm"};
  // type → (the fields it requires, the fields it refuses)
  const std::vector<std::tuple<const char*, std::vector<const char*>, std::vector<const char*>>> types = {
      {"circular", {"radius_mm"}, {}},
      {"partial", {"radius_mm", "flat_length_mm"}, {}},
      {"logarithmic", logarithmic, {}},
      {"none", {}, {"radius_mm", "flat_length_mm", "coefficient_mm", "effective_length_mm"}},
      {"circular", {}, {"flat_length_mm", "coefficient_mm", "effective_length_mm"}},
      {"partial", {}, {"coefficient_mm", "effective_length_mm"}},
      {"logarithmic", {}, {"radius_mm", "flat_length_mm"}},
  };
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  for (const auto& [type, required, refused] : types) {
    nlohmann::ordered_json then = nlohmann::ordered_json::object();
    if (!required.empty()) then["required"] = required;
    for (const char* f : refused) then["properties"][f] = false;
    all.push_back({{"if", {{"properties", {{"type", {{"const", type}}}}}}}, {"then", then}});
  }
  return {{"allOf", all}};
}
}  // namespace

nlohmann::ordered_json LcrCrowningInput::SchemaRules() { return CrowningRules(true); }

nlohmann::ordered_json LcrSizedCrowningInput::SchemaRules() { return CrowningRules(false); }

lcr::ContactModelOptions ToContactOptions(const LcrContactOptionsInput& in, const Node& c) {
  lcr::ContactModelOptions o;
  const std::string model = in.model.value_or("line");
  o.model = model == "slices"       ? lcr::ContactModel::kSlices
            : model == "half_space" ? lcr::ContactModel::kHalfSpace
                                    : lcr::ContactModel::kLine;
  o.slices = in.slices;
  o.grid_nx = in.grid[0];
  o.grid_ny = in.grid[1];
  o.misalignment_rad = in.misalignment_mrad * 1e-3;
  if (o.model == lcr::ContactModel::kLine && o.misalignment_rad != 0) {
    const std::string want = "slices or half_space with misalignment_mrad (the line model ignores it)";
    if (c.Has("model")) c["model"].Fail(want);
    c.FailWith("model must be " + want);
  }
  return o;
}

}  // namespace camopt::studies
