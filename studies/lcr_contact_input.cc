#include "studies/lcr_contact_input.h"

#include <cmath>
#include <string>

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

const char* ContactModelName(lcr::ContactModel m) {
  switch (m) {
    case lcr::ContactModel::kLine: return "line";
    case lcr::ContactModel::kSlices: return "slices";
    case lcr::ContactModel::kHalfSpace: return "half_space";
  }
  return "line";
}

LcrContactInput ParseLcrContact(const Node& root, const lcr::Reducer<double>& reducer) {
  LcrContactInput in;
  bool crowned = false;
  const Node red = root["reducer"];
  for (const char* side : {"input", "output"}) {
    const Node s = red[side];
    if (!s.Has("crowning")) continue;
    auto& c = std::string(side) == "input" ? in.input_crowning : in.output_crowning;
    c = ParseRollerCrowning(s["crowning"], Value(reducer.side(std::string(side) == "input" ? lcr::Side::kInput
                                                                                      : lcr::Side::kOutput)
                                                    .roller_length));
    crowned = crowned || c.type != contact::CrowningType::kNone;
  }
  if (root.Has("contact")) {
    in.given = true;
    in.options = ParseContactOptions(root["contact"]);
  }
  if (crowned && in.options.model == lcr::ContactModel::kLine) {
    if (in.given && root["contact"].Has("model")) root["contact"]["model"].Fail("slices or half_space with crowned rollers (the line model ignores crowning)");
    root.FailWith("crowned rollers need \"contact\": {\"model\": \"slices\" or \"half_space\"} (the line model ignores crowning)");
  }
  return in;
}

lcr::ContactModelOptions ParseContactOptions(const Node& c) {
  LcrContactInput in;
  {
    c.CheckKnownFields({"model", "slices", "grid", "misalignment_mrad"});
    const std::string model = c.StringOr("model", "line");
    if (model == "line") {
      in.options.model = lcr::ContactModel::kLine;
    } else if (model == "slices") {
      in.options.model = lcr::ContactModel::kSlices;
    } else if (model == "half_space") {
      in.options.model = lcr::ContactModel::kHalfSpace;
    } else {
      c["model"].Fail("one of line, slices, half_space");
    }
    in.options.slices = c.IntegerOr("slices", 4, 40);
    if (in.options.slices > 200) c["slices"].Fail("at most 200 slices");
    if (c.Has("grid")) {
      const auto e = c["grid"].Elements();
      if (e.size() != 2) c["grid"].Fail("[nx, ny]");
      in.options.grid_nx = e[0].Integer(8);
      in.options.grid_ny = e[1].Integer(8);
      if (in.options.grid_nx > 256) e[0].Fail("at most 256");
      if (in.options.grid_ny > 1024) e[1].Fail("at most 1024");
    }
    in.options.misalignment_rad = c.NumberOr("misalignment_mrad", 0.0) * 1e-3;
    if (std::abs(in.options.misalignment_rad) > 0.05) c["misalignment_mrad"].Fail("a misalignment within ±50 mrad");
    if (in.options.model == lcr::ContactModel::kLine && in.options.misalignment_rad != 0) {
      const std::string want = "slices or half_space with misalignment_mrad (the line model ignores it)";
      if (c.Has("model")) c["model"].Fail(want);
      c.FailWith("model must be " + want);
    }
  }
  return in.options;
}

}  // namespace camopt::studies
