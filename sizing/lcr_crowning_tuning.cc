#include "sizing/lcr_crowning_tuning.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/common/roots.h"

namespace camopt::sizing {

namespace {

lcr::RollerCrowning<double> LogCrown(double f, double le) {
  lcr::RollerCrowning<double> c;
  c.type = contact::CrowningType::kLogarithmic;
  c.coefficient = f;
  c.effective_length = le;
  return c;
}

}  // namespace

LcrCrowningCheck CheckLcrCrowning(const LcrCrowningTuningSpec& spec, lcr::Side side,
                                  const lcr::RollerCrowning<double>& crowning, lcr::ContactModel model,
                                  std::vector<lcr::Contact3DCycleSide>* details, int grid_nx, int grid_ny) {
  const double e_star = spec.material.composite_modulus_MPa();
  lcr::LoadCase over = spec.design_load;
  over.output_torque_Nmm = spec.overload_torque_Nmm;
  const lcr::Stages stages{true, false, false};
  const auto design = lcr::AnalyzeCycle(spec.reducer, spec.material, spec.design_load, spec.angle_steps, stages);
  const auto overload = lcr::AnalyzeCycle(spec.reducer, spec.material, over, spec.angle_steps, stages);
  LcrCrowningCheck out;
  for (double gamma : spec.misalignments_rad) {
    lcr::ContactModelOptions o;
    o.model = model;
    o.slices = spec.slices;
    o.misalignment_rad = gamma;
    o.grid_nx = grid_nx;
    o.grid_ny = grid_ny;
    const auto d = lcr::AnalyzeCycleContact3D(spec.reducer, side, design, e_star, crowning, o);
    const auto v = lcr::AnalyzeCycleContact3D(spec.reducer, side, overload, e_star, crowning, o);
    out.design_MPa.push_back(d.max_contact_stress_MPa);
    out.overload_MPa.push_back(v.max_contact_stress_MPa);
    out.design_edge.push_back(d.edge_loaded);
    out.overload_edge.push_back(v.edge_loaded);
    out.worst_design_MPa = std::max(out.worst_design_MPa, d.max_contact_stress_MPa);
    out.edge_free_at_overload = out.edge_free_at_overload && !v.edge_loaded;
    if (details) details->push_back(d), details->push_back(v);
  }
  return out;
}

std::array<LcrCrowningSideResult, 2> TuneLcrCrowning(const LcrCrowningTuningSpec& spec) {
  const auto [lo, hi] = spec.coefficient_range_mm;
  if (!(lo > 0 && hi > lo)) throw std::invalid_argument("crowning tuning: need 0 < lo < hi");
  std::array<LcrCrowningSideResult, 2> out;
  for (lcr::Side side : {lcr::Side::kInput, lcr::Side::kOutput}) {
    const int k = side == lcr::Side::kInput ? 0 : 1;
    const double le = spec.effective_length_mm[k];
    if (!(le > spec.reducer.side(side).roller_length))
      throw std::invalid_argument("crowning tuning: effective length must exceed the roller length");
    LcrCrowningSideResult& res = out[k];
    // The quantity minimised: the worst design pressure, +inf where the overload reaches an end.
    const double total = 2.0 * (std::max(spec.curve_points, 3) + spec.refine_iterations + 2);
    const auto cost = [&](double f) {
      ++res.evaluations;
      if (spec.progress) spec.progress(std::min(1.0, (k * total / 2 + res.evaluations) / total));
      const LcrCrowningCheck c = CheckLcrCrowning(spec, side, LogCrown(f, le), lcr::ContactModel::kSlices);
      return std::pair{c.worst_design_MPa, c.edge_free_at_overload};
    };
    int best = -1;
    const int n = std::max(spec.curve_points, 3);
    for (int i = 0; i < n; ++i) {
      const double f = lo * std::pow(hi / lo, double(i) / (n - 1));
      const auto [p, ok] = cost(f);
      res.curve_coefficient_mm.push_back(f);
      res.curve_worst_design_MPa.push_back(p);
      res.curve_edge_free_at_overload.push_back(ok);
      if (ok && (best < 0 || p < res.curve_worst_design_MPa[best])) best = i;
    }
    res.feasible = best >= 0;
    if (!res.feasible) {
      res.coefficient_mm = hi;  // the strongest crown of the range; still edge-loaded
    } else {
      const double a = std::log(res.curve_coefficient_mm[std::max(best - 1, 0)]);
      const double b = std::log(res.curve_coefficient_mm[std::min(best + 1, n - 1)]);
      const auto g = GoldenSectionMaximize(
          [&](double x) {
            const auto [p, ok] = cost(std::exp(x));
            return ok ? -p : -kInf;
          },
          a, b, spec.refine_iterations);
      const double x = g.f1 >= g.f2 ? g.x1 : g.x2;
      const double fx = std::max(g.f1, g.f2);
      res.coefficient_mm = -fx < res.curve_worst_design_MPa[best] ? std::exp(x) : res.curve_coefficient_mm[best];
    }
    res.tuned = CheckLcrCrowning(spec, side, LogCrown(res.coefficient_mm, le), lcr::ContactModel::kSlices);
    res.uncrowned = CheckLcrCrowning(spec, side, {}, lcr::ContactModel::kSlices);
  }
  return out;
}

}  // namespace camopt::sizing
