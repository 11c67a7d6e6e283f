#include "sizing/lcr_search.h"

#include <algorithm>

#include "sizing/sizing_driver.h"

namespace camopt::sizing {
using namespace camopt::objectives;

std::string LobeCombinationName(const LobeCombination& c) {
  return std::to_string(c.lobes_a) + "/" + std::to_string(c.rollers_a) + " + " + std::to_string(c.lobes_b) +
         "/" + std::to_string(c.rollers_b);
}

LcrSearchOutcome SearchLcrMinSize(const LcrSearchSpec& s,
                                  const std::function<void(double, const std::string&)>& progress) {
  LcrSearchOutcome res;
  for (const auto& c : LobeCombinations(s.ratio, s.max_lobes, s.differences)) {
    if (s.catalogue.empty()) res.candidates.push_back({c, -1, {}, {}, {}, {}, {}});
    for (size_t r = 0; r < s.catalogue.size(); ++r) res.candidates.push_back({c, int(r), {}, {}, {}, {}, {}});
  }
  SizingCandidates loop;
  loop.count = int(res.candidates.size());
  loop.label = [&](int i) {
    const LcrCandidate& c = res.candidates[size_t(i)];
    return LobeCombinationName(c.combo) + (c.roller >= 0 ? " " + s.catalogue[c.roller].name : "");
  };
  const auto make_spec = [&](LcrCandidate& c) {
    c.spec = s.base;
    c.spec.lobes_a = c.combo.lobes_a;
    c.spec.rollers_a = c.combo.rollers_a;
    c.spec.lobes_b = c.combo.lobes_b;
    c.spec.rollers_b = c.combo.rollers_b;
    if (c.roller >= 0) {
      const LcrCatalogueRoller& r = s.catalogue[c.roller];
      c.spec.fixed_roller_diameter_mm = r.diameter_mm;
      c.spec.roller_length_mm = r.length_mm;
      c.spec.limits.roller_load_N = std::min(c.spec.limits.roller_load_N, r.load_limit_N);
      if (c.spec.life) c.spec.life->roller = {r.dynamic_rating_N, r.static_rating_N, 0.0, 0.0};  // the catalogue's own
    }
  };
  if (s.contact3d) {
    // Branch and bound: a candidate's 3D polish stops once a round's outer diameter exceeds the
    // bound the driver gives, and goes on when the driver needs it (sizing/lcr_sizing3d.h).
    loop.solve_within = [&](int i, double bound) -> std::optional<double> {
      LcrCandidate& c = res.candidates[size_t(i)];
      const bool first = !c.outcome3d;
      if (first) make_spec(c);
      const int values = first ? 0 : c.outcome.result.value_evaluations,
                gradients = first ? 0 : c.outcome.result.gradient_evaluations;
      if (c.outcome3d && c.outcome3d->paused)
        ContinueLcrMinSize3D(c.spec, s.options, *c.outcome3d, bound);
      else
        c.outcome3d = SolveLcrMinSize3D(c.spec, *s.contact3d, s.options, bound);
      c.outcome = c.outcome3d->outcome;
      res.value_evaluations += c.outcome.result.value_evaluations - values;
      res.gradient_evaluations += c.outcome.result.gradient_evaluations - gradients;
      if (c.outcome3d->paused) return c.outcome3d->paused->lower_bound_mm;
      return std::nullopt;
    };
  } else {
    loop.solve = [&](int i) {
      LcrCandidate& c = res.candidates[size_t(i)];
      make_spec(c);
      c.outcome = SolveLcrMinSize(c.spec, s.options);
      res.value_evaluations += c.outcome.result.value_evaluations;
      res.gradient_evaluations += c.outcome.result.gradient_evaluations;
    };
  }
  // The driver's "size" is the objective's value on the dense check: the outer diameter, or the
  // lubricated loss with the efficiency objective (the 3D path sizes the outer diameter only).
  loop.feasible_size = [&](int i) -> std::optional<double> {
    const LcrCandidate& c = res.candidates[size_t(i)];
    if (!c.feasible()) return std::nullopt;
    return LcrObjectiveValue(c.spec, *c.outcome.check);
  };
  loop.verify = [&](int i) {
    LcrCandidate& b = res.candidates[size_t(i)];
    if (s.contact3d) {
      const int values = b.outcome3d->outcome.result.value_evaluations,
                gradients = b.outcome3d->outcome.result.gradient_evaluations;
      LcrHalfSpaceCheck h;
      b.verification = VerifyLcrMinSize3D(b.spec, *s.contact3d, s.options, *b.outcome3d, &h);
      b.outcome = b.outcome3d->outcome;
      res.value_evaluations += b.outcome.result.value_evaluations - values;
      res.gradient_evaluations += b.outcome.result.gradient_evaluations - gradients;
      if (b.verification->ran) b.half_space = h;
    } else {
      b.verification = VerifyLcrLineDesign(b.spec, *b.outcome.design, s.options.dense_steps);
    }
  };
  res.best = RunSizingDriver(loop, progress).best;
  if (res.best >= 0 && s.contact3d) {
    // The limit sensitivities re-solve the line problem: not done for the 3D contact.
    res.half_space = res.candidates[res.best].half_space;
  } else if (res.best >= 0) {
    const LcrCandidate& b = res.candidates[res.best];
    res.limit_slope = LimitSlopes(b.spec, s.options, b.outcome);
    for (const auto& [key, slope] : res.limit_slope)
      if (!slope.sides.empty()) res.limit_sensitivity[key] = slope.slope;
  }
  return res;
}

}  // namespace camopt::sizing
