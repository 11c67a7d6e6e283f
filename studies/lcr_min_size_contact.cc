// See lcr_min_size_contact.h.
#include "studies/lcr_min_size_contact.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "model/contact/hertz.h"
#include "studies/contact_fatigue_input.h"
#include "studies/format.h"
#include "studies/lcr_contact_input.h"
#include "studies/lcr_min_size_study.h"
#include "studies/archive.h"

namespace camopt::studies::lcr_min_size {

std::optional<sizing::LcrSizing3DSpec> ParseContact3D(const Input& in, const Node& root, double roller_length_mm,
                                                          bool catalogue) {
  const Input::Variables& v = in.variables;
  const Node vars = root["variables"], fixed = root["fixed"];
  const bool has_var = v.crowning_coefficient_mm || v.crowning_radius_mm || v.crowning_flat_length_mm;
  const bool has_length_var = v.roller_length_mm || v.cam_thickness_mm;
  const bool has_contact = in.contact.has_value(), has_crown = in.fixed.crowning.has_value(),
             has_over = in.load.overload_torque_Nm.has_value();
  if (!has_contact && !has_crown && !has_var && !has_length_var && !has_over) return std::nullopt;
  sizing::LcrSizing3DSpec s;
  if (has_contact) s.contact = ToContactOptions(*in.contact, root["contact"]);
  // The roller length variable's upper end is the longest roller the crowning must fit.
  double longest = roller_length_mm;
  if (v.roller_length_mm) {
    const Node n = vars["roller_length_mm"];
    if (catalogue) n.Fail("no roller length variable with a roller catalogue (the catalogue gives the lengths)");
    s.roller_length_range_mm = OrderedRange(*v.roller_length_mm, n);
    longest = std::max(longest, (*s.roller_length_range_mm)[1]);
  }
  if (v.cam_thickness_mm) s.cam_thickness_range_mm = OrderedRange(*v.cam_thickness_mm, vars["cam_thickness_mm"]);
  if (has_crown)
    s.crowning = ParseRollerCrowning(fixed["crowning"], longest, !v.crowning_coefficient_mm);
  using contact::CrowningType;
  // A crowning variable of the fixed crowning's type (its bounds are the declaration's).
  const auto range = [&](const std::optional<std::array<double, 2>>& value, const char* name,
                         std::initializer_list<CrowningType> types,
                         const char* want) -> std::optional<std::array<double, 2>> {
    if (!value) return std::nullopt;
    const Node n = vars[name];
    if (!has_crown || std::find(types.begin(), types.end(), s.crowning.type) == types.end())
      n.Fail(std::string("a range only with fixed.crowning ") + want + " (its fixed value is the start)");
    return OrderedRange(*value, n);
  };
  // A coefficient of 0 is a straight roller: a design a user may want inside the range.
  s.coefficient_range_mm = range(v.crowning_coefficient_mm, "crowning_coefficient_mm", {CrowningType::kLogarithmic},
                                 "{\"type\": \"logarithmic\", \"effective_length_mm\": Le}");
  s.radius_range_mm = range(v.crowning_radius_mm, "crowning_radius_mm", {CrowningType::kCircular, CrowningType::kPartial},
                            "{\"type\": \"circular\" or \"partial\", \"radius_mm\": R, ...}");
  s.flat_length_range_mm = range(v.crowning_flat_length_mm, "crowning_flat_length_mm", {CrowningType::kPartial},
                                 "{\"type\": \"partial\", \"radius_mm\": R, \"flat_length_mm\": L0}");
  // Every point of the ranges must fit the longest roller: the smallest radius over the longest
  // crowned length (the shortest flat), the longest flat.
  if (s.radius_range_mm || s.flat_length_range_mm) {
    lcr::RollerCrowning<double> worst = s.crowning;
    if (s.radius_range_mm) worst.radius = (*s.radius_range_mm)[0];
    if (s.flat_length_range_mm) worst.flat_length = (*s.flat_length_range_mm)[0];
    std::string problem = lcr::CheckRollerCrowning(worst, longest);
    if (problem.empty() && s.flat_length_range_mm) {
      worst.flat_length = (*s.flat_length_range_mm)[1];
      problem = lcr::CheckRollerCrowning(worst, std::min(longest, roller_length_mm));
    }
    if (!problem.empty())
      vars[s.radius_range_mm ? "crowning_radius_mm" : "crowning_flat_length_mm"].Fail(
          "a range the crowning fits at both ends: " + problem);
  }
  if (has_over) {
    s.overload_torque_Nmm = *in.load.overload_torque_Nm * 1000.0;
    if (!(s.overload_torque_Nmm >= in.target.output_torque_Nm * 1000.0))
      root["load"]["overload_torque_Nm"].Fail("an overload torque >= the target's output_torque_Nm");
  }
  if (s.contact.model == lcr::ContactModel::kLine) {
    // Under the line model the stress only falls as a roller or cam gets longer and nothing else
    // depends on the length: a length variable would sit at its upper bound (docs/studies.md).
    const std::string why = has_crown || has_var ? "crowned rollers"
                            : has_over           ? "an overload torque"
                            : has_length_var     ? "roller length or cam thickness variables"
                                                 : "";
    if (!why.empty()) {
      const std::string want = "slices or half_space with " + why + " (the line model ignores them)";
      if (has_contact && in.contact->model) root["contact"]["model"].Fail(want);
      root.FailWith(std::string("\"contact\": {\"model\": ...} must be ") + want);
    }
    return std::nullopt;  // "contact": {"model": "line"}: the fast path
  }
  return s;
}

void AddContact3DJson(const Study& s, Result& r) {
  const sizing::LcrSizing3DSpec& c3 = *s.contact3d;
  Result::Json& res = r.json;
  Result::Json::ContactBlock& block = res.contact.emplace();
  block.model = ContactModelName(c3.contact.model);
  block.slices = c3.contact.slices;
  block.misalignment_mrad = c3.contact.misalignment_rad * 1e3;
  block.crowning = CrowningInputOf(c3.crowning);
  block.crowning_variable = bool(c3.coefficient_range_mm || c3.radius_range_mm || c3.flat_length_range_mm);
  block.length_variables = {bool(c3.roller_length_range_mm), bool(c3.cam_thickness_range_mm)};
  if (c3.overload_torque_Nmm > 0) block.overload_torque_Nm = c3.overload_torque_Nmm / 1000;
  for (size_t i = 0; i < r.candidates.size(); ++i) {
    const auto& o3 = r.candidates[i].outcome3d;
    if (o3 && r.candidates[i].pruned()) res.candidates[i].line_model_outer_diameter_mm = o3->line_outer_diameter_mm;
    if (!o3 || !r.candidates[i].feasible()) continue;
    res.candidates[i].input.crowning = CrowningInputOf(o3->crowning[0]);
    res.candidates[i].output.crowning = CrowningInputOf(o3->crowning[1]);
    res.candidates[i].line_model_outer_diameter_mm = o3->line_outer_diameter_mm;
  }
  if (r.best < 0) return;
  const sizing::LcrMinSize3DOutcome& b = *r.candidates[r.best].outcome3d;
  Result::Json::NominalBest& best = std::get<Result::Json::NominalBest>(res.best);
  Result::Json::BestSide* best_sides[2] = {&best.input, &best.output};
  Result::Json::Contact3DBest& contact = best.contact.emplace();
  contact.line_model_outer_diameter_mm = b.line_outer_diameter_mm;
  for (int k = 0; k < 2; ++k) {
    best_sides[k]->sizes.crowning = CrowningInputOf(b.crowning[k]);
    if (!b.contact) continue;
    const lcr::Contact3DCycleSide& d = b.contact->design[k];
    Result::Json::Contact3DSide side;
    side.max_contact_stress_MPa = d.max_contact_stress_MPa;
    side.edge_loaded = d.edge_loaded;
    side.slice_width_mm = d.slice_width_mm;
    side.interpolation_error_MPa = d.interpolation_error_MPa;
    if (d.worst_angle >= 0 && std::isfinite(d.max_contact_stress_MPa)) {
      // The worst slice as a line contact of its own peak pressure, b = 2 p0 R'/E* (model/contact/hertz.h).
      const double b_mm = contact::LineContactHalfWidthFromPeakPressure(
          d.max_contact_stress_MPa, d.stress_radius_mm[size_t(d.worst_angle)], s.base.material.composite_modulus_MPa());
      side.subsurface = SubsurfaceOf(d.max_contact_stress_MPa, b_mm, s.base.material.poisson_ratio,
                                       "the worst slice of the slices model taken as a line contact of its peak "
                                       "pressure and half-width b = 2 p0 R'/E* (frictionless, homogeneous "
                                       "half-spaces, Johnson 1985 eq. 4.50 ff.)");
    }
    if (c3.overload_torque_Nmm > 0) {
      side.overload_edge_margin = b.contact->overload_edge_margin[k];
      side.overload_edge_loaded = b.contact->overload_edge_loaded[k];
    } else {
      side.edge_margin = b.contact->overload_edge_margin[k];  // at the design torque
    }
    (k == 0 ? contact.input : contact.output) = side;
  }
  if (r.half_space) {
    const sizing::LcrHalfSpaceCheck& h = *r.half_space;
    Result::Json::HalfSpaceCheck& j = best.half_space_check.emplace();
    j.cell_dx_mm = h.cell_dx_mm, j.cell_dy_mm = h.cell_dy_mm, j.converged = h.converged;
    j.grid = {c3.contact.grid_nx, c3.contact.grid_ny};
    for (int k = 0; k < 2; ++k) {
      Result::Json::HalfSpaceCheck::Side& side = k == 0 ? j.input : j.output;
      side.half_space_MPa = h.half_space_MPa[k];
      side.slices_MPa = h.slices_MPa[k];
      side.slices_minus_half_space_percent = h.difference_percent[k];
      side.edge_loaded = h.edge_loaded[k];
    }
  }
}

void AddContact3DAnalysis(const Study& s, const Candidate& best, nlohmann::json& a) {
  const sizing::LcrSizing3DSpec& c3 = *s.contact3d;
  a["contact"] = {{"model", ContactModelName(c3.contact.model)},
                  {"slices", c3.contact.slices},
                  {"grid", {c3.contact.grid_nx, c3.contact.grid_ny}},
                  {"misalignment_mrad", c3.contact.misalignment_rad * 1e3}};
  if (!best.outcome3d) return;
  a["reducer"]["input"]["crowning"] = WriteJson(CrowningInputOf(best.outcome3d->crowning[0]));
  a["reducer"]["output"]["crowning"] = WriteJson(CrowningInputOf(best.outcome3d->crowning[1]));
}

}  // namespace camopt::studies::lcr_min_size
