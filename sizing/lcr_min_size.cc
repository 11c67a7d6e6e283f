#include "sizing/lcr_min_size.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "model/lcr/forces.h"
#include "model/common/geometry.h"
#include "model/contact/hertz.h"
#include "model/lcr/profile.h"
#include "sizing/stage_clock.h"

namespace camopt::sizing {
using namespace camopt::objectives;
namespace {

using optimizers::SolverResult;
using optimizers::SolverStatus;

// A limit binds when the dense-check value is within this fraction of it (lengths: in mm).
constexpr double kBindingFraction = 1e-3;
// Relative move of a limit for its sensitivity (central difference).
constexpr double kSensitivityStep = 5e-3;


// Takes the fresh peaks of `from` into `to`: a fresh peak replaces an old one within its window
// (the same physical peak, re-centred), others are added. Returns whether a peak was added or
// moved by more than 1% of the period.
bool Merge(const LcrSizingSpec& spec, LcrActiveSet& to, const LcrActiveSet& from) {
  bool changed = false;
  for (int side = 0; side < 2; ++side) {
    const double period = LcrLoadPeriod(spec, side == 0 ? lcr::Side::kInput : lcr::Side::kOutput);
    for (auto list : {&LcrActiveSet::force, &LcrActiveSet::stress}) {
      std::vector<LcrSample>& old = (to.*list)[side];
      for (const LcrSample& fresh : (from.*list)[side]) {
        auto same = std::find_if(old.begin(), old.end(), [&](const LcrSample& o) {
          return PhaseDistance(o.theta_rad, fresh.theta_rad, period) < fresh.window_rad;
        });
        if (same == old.end()) {
          old.push_back(fresh);
          changed = true;
        } else {
          changed = changed || PhaseDistance(same->theta_rad, fresh.theta_rad, period) > 0.01 * period;
          *same = fresh;
        }
      }
    }
  }
  return changed;
}

struct Polished {
  SolverResult result;
  std::vector<double> x;
  std::optional<LcrDenseCheck> check;
  LcrActiveSet active;
  int rounds = 0, values = 0, gradients = 0, iterations = 0;
  bool converged = false;
  std::string note;
};

std::optional<LcrDenseCheck> TryCheck(const LcrSizingSpec& exact, const std::vector<double>& x, int steps,
                                      LcrActiveSet* near, std::string& note) {
  try {
    return DenseCheck(exact, LcrDesign(exact, x), steps, near);
  } catch (const std::domain_error& e) {
    note = std::string("degenerate geometry: ") + e.what();
    return std::nullopt;
  }
}

// Step 2 of the header comment from x (a smooth-phase optimum or an earlier polished one).
Polished Polish(const LcrSizingSpec& exact, const LcrMinSizeOptions& o, std::vector<double> x,
                LcrActiveSet active) {
  Polished p;
  LcrSizingSpec tight = LcrTightened(exact);
  tight.form = LcrConstraintForm::kActiveSet;
  LcrActiveSet near;
  if (!TryCheck(exact, x, o.dense_steps, &near, p.note)) return p;
  Merge(exact, active, near);
  for (p.rounds = 1; p.rounds <= o.max_polish_rounds; ++p.rounds) {
    tight.active = active;
    optimizers::SolverOptions so = o.solver;
    so.initial = x;
    p.result = optimizers::Solve(MakeLcrSizingProblem(tight), so);
    p.values += p.result.value_evaluations;
    p.gradients += p.result.gradient_evaluations;
    p.iterations += p.result.iterations;
    p.active = active;
    if (p.result.x.empty()) return p;
    x = p.x = p.result.x;
    p.check = TryCheck(exact, x, o.dense_steps, &near, p.note);
    if (!p.check) return p;
    // With the power-loss objective a design without its lubricated operating point (no thermal
    // equilibrium below the oil's limit on the dense grid) has no objective value: not converged.
    const bool valued = std::isfinite(LcrObjectiveValue(exact, *p.check));
    if (p.result.ok() && p.check->ok() && valued) {
      p.converged = true;
      return p;
    }
    if (!valued && p.note.empty()) p.note = "no lubricated operating point: " + p.check->lubrication_why;
    bool changed = Merge(exact, active, near);
    // The efficiency is a 48-angle mean in the problem against 3600 in the check: raise its limit
    // by the deficit.
    const double deficit = exact.limits.min_efficiency - p.check->mean_efficiency;
    if (exact.limits.min_efficiency > 0 && deficit > 0) {
      tight.limits.min_efficiency += 1.5 * deficit;
      changed = true;
    }
    // The oil temperature likewise (the balance over the same two grids).
    const double excess = p.check->oil_temperature_C - exact.limits.max_oil_temperature_C;
    if (exact.lubrication && std::isfinite(exact.limits.max_oil_temperature_C) && excess > 0) {
      tight.limits.max_oil_temperature_C -= 1.5 * excess;
      changed = true;
    }
    // The life rows sample each cam period at samples_per_period angles (the eccentric bearing's
    // long period more coarsely) against the check's 3600 per revolution: raise the required life
    // by the shortfall (ratio), one and a half times over.
    if (exact.limits.life_h > 0 && p.check->shortest_L10h < exact.limits.life_h) {
      tight.limits.life_h *= std::pow(exact.limits.life_h / p.check->shortest_L10h, 1.5);
      changed = true;
    }
    // The static rows likewise: their largest load is a sampled maximum against the check's finer
    // grid: raise the required s0 by the shortfall (ratio), one and a half times over.
    if (exact.limits.min_static_safety > 0 && p.check->min_static_safety < exact.limits.min_static_safety) {
      tight.limits.min_static_safety *= std::pow(exact.limits.min_static_safety / p.check->min_static_safety, 1.5);
      changed = true;
    }
    if (!changed) return p;
  }
  p.rounds = o.max_polish_rounds;
  return p;
}

// Largest relative violation of a check (0 when it holds; +inf for design problems).
double WorstRelativeViolation(const LcrDenseCheck& c) {
  if (!c.design_problems.empty()) return kInf;
  double worst = 0.0;
  for (const LcrViolation& v : c.violations)
    worst = std::max(worst, v.excess() / std::max(std::abs(v.limit_value), 1.0));
  return worst;
}

// Step 0 of the header comment: the longest life of the combination, and whether it is out of
// reach. Fills out.longest_life_h; when out of reach also out.x, design, check, result and note.
void LongestLife(const LcrSizingSpec& spec, const LcrMinSizeOptions& options, LcrMinSizeOutcome& out) {
  const Problem problem = MakeLcrLongestLifeProblem(spec);
  const size_t t_index = problem.variables.size() - 1;
  optimizers::SolverResult best;
  int values = 0, gradients = 0, iterations = 0;
  for (std::vector<double> x0 : LcrStartingPoints(spec, options.starts)) {
    x0[t_index] = 0.0;
    optimizers::SolverOptions so = options.solver;
    so.initial = x0;
    so.fallback_backend.reset();
    optimizers::SolverResult r = optimizers::Solve(problem, so);
    values += r.value_evaluations;
    gradients += r.gradient_evaluations;
    iterations += r.iterations;
    if (r.ok() && (!best.ok() || r.objective > best.objective)) best = std::move(r);
    // Reached on the rows: the combination cannot be out of reach (that needs both the rows' and
    // the dense check's life below the limit), so the other starts and the check are not needed.
    if (best.ok() && best.objective >= 0) break;
  }
  out.result.value_evaluations = values;  // counted into the size solve's when it follows
  out.result.gradient_evaluations = gradients;
  out.result.iterations = iterations;
  if (!best.ok() || best.objective >= 0) return;
  std::string note;
  const std::optional<LcrDenseCheck> c = TryCheck(spec, best.x, options.dense_steps, nullptr, note);
  if (!c || !std::isfinite(c->shortest_L10h)) return;
  const double rows = spec.limits.life_h * std::exp(best.objective), dense = c->shortest_L10h;
  const double longest = std::max(rows, dense);
  out.longest_life_h = longest;
  const double error = std::abs(rows - dense) / std::min(rows, dense) + 0.01;
  if (!(longest * (1 + error) < spec.limits.life_h)) return;
  out.life_out_of_reach = true;
  out.x = best.x;
  out.design = LcrDesign(spec, best.x);
  out.check = c;
  out.result = best;
  out.result.status = SolverStatus::kInfeasible;
  out.result.value_evaluations = values;
  out.result.gradient_evaluations = gradients;
  out.result.iterations = iterations;
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "the longest life any design of this combination reaches within the variable bounds is %.6g h "
                "(the design with the longest life, ignoring the other limits; within %.2g%%) < the %.6g h limit: "
                "not sized",
                longest, 100 * error, spec.limits.life_h);
  out.note = buf;
  out.result.message = buf;
}

}  // namespace


LcrMinSizeOutcome SolveLcrMinSize(const LcrSizingSpec& spec, const LcrMinSizeOptions& options) {
  LcrMinSizeOutcome out;
  if (spec.limits.life_h > 0 && spec.life) {
    LongestLife(spec, options, out);
    if (out.life_out_of_reach) return out;
  }
  LcrSizingSpec smooth = LcrTightened(spec);
  smooth.form = options.smooth_form;
  const Problem problem = MakeLcrSizingProblem(smooth);
  int values = out.result.value_evaluations, gradients = out.result.gradient_evaluations,
      iterations = out.result.iterations;
  struct Trial {
    SolverResult result;
    std::optional<Polished> polished;
  };
  std::vector<Trial> trials;
  for (const std::vector<double>& x0 : LcrStartingPoints(smooth, options.starts)) {
    optimizers::SolverOptions so = options.solver;
    so.initial = x0;
    Trial t{optimizers::Solve(problem, so), std::nullopt};
    values += t.result.value_evaluations;
    gradients += t.result.gradient_evaluations;
    iterations += t.result.iterations;
    LcrStartOutcome s;
    s.status = t.result.status;
    // An infeasible end of the smooth phase is the closest point the solver found; polishing it
    // toward an optimum has no sense.
    if (!options.polish && !t.result.x.empty()) {
      Polished p;  // the smooth optimum as it is, held to the dense check
      p.result = t.result;
      p.x = t.result.x;
      p.check = TryCheck(spec, p.x, options.dense_steps, nullptr, p.note);
      p.converged = p.result.ok() && p.check && p.check->ok() && std::isfinite(LcrObjectiveValue(spec, *p.check));
      t.polished = p;
      s.converged = p.converged;
      if (s.converged) s.outer_diameter_mm = p.check->outer_diameter_mm, s.objective = LcrObjectiveValue(spec, *p.check);
    } else if (!t.result.x.empty() && t.result.status != SolverStatus::kInfeasible) {
      // A start whose smooth optimum is one an earlier start already reached (to 1e-6 relative)
      // shares that start's polish.
      const Trial* same = nullptr;
      for (const Trial& u : trials) {
        if (!u.polished || u.result.x.size() != t.result.x.size()) continue;
        bool close = true;
        for (size_t i = 0; i < u.result.x.size(); ++i)
          close = close && std::abs(u.result.x[i] - t.result.x[i]) <= 1e-6 * std::max(1.0, std::abs(u.result.x[i]));
        if (close) same = &u;
      }
      if (same) {
        t.polished = same->polished;
      } else {
        t.polished = Polish(spec, options, t.result.x, {});
        values += t.polished->values;
        gradients += t.polished->gradients;
        iterations += t.polished->iterations;
      }
      s.status = t.polished->result.status;
      s.converged = t.polished->converged;
      if (s.converged)
        s.outer_diameter_mm = t.polished->check->outer_diameter_mm,
        s.objective = LcrObjectiveValue(spec, *t.polished->check);
    }
    out.starts.push_back(s);
    trials.push_back(std::move(t));
  }

  // The chosen start: the converged design with the least objective (the smallest, or the one
  // that loses least); else the polished or smooth end point with the smallest violation of the
  // study's limits (the closest point); else the first.
  int best = -1;
  for (size_t i = 0; i < trials.size(); ++i)
    if (out.starts[i].converged && (best < 0 || out.starts[i].objective < out.starts[best].objective))
      best = int(i);
  if (best >= 0) {
    const Polished& p = *trials[best].polished;
    out.result = p.result;
    out.x = p.x;
    out.check = p.check;
    out.converged = true;
    out.polish_rounds = p.rounds;
    out.active = p.active;
  } else {
    double least = kInf;
    for (size_t i = 0; i < trials.size(); ++i) {
      const Trial& t = trials[i];
      SolverResult r = t.polished && !t.polished->x.empty() ? t.polished->result : t.result;
      if (r.x.empty()) continue;
      std::string note;
      std::optional<LcrDenseCheck> c = TryCheck(spec, r.x, options.dense_steps, nullptr, note);
      const double worst = c ? WorstRelativeViolation(*c) : kInf;
      if (best < 0 || worst < least) {
        best = int(i), least = worst;
        out.result = r;
        out.x = r.x;
        out.check = c;
        out.note = note;
        out.polish_rounds = t.polished ? t.polished->rounds : 0;
      }
    }
    if (best < 0) out.result = trials.front().result;
  }
  if (!out.x.empty()) out.design = LcrDesign(spec, out.x);
  out.result.value_evaluations = values;
  out.result.gradient_evaluations = gradients;
  out.result.iterations = iterations;
  return out;
}

std::map<std::string, double> LimitSensitivity(const LcrSizingSpec& spec, const LcrMinSizeOptions& options,
                                               const LcrMinSizeOutcome& outcome) {
  std::map<std::string, double> out;
  for (const auto& [key, s] : LimitSlopes(spec, options, outcome))
    if (!s.sides.empty()) out[key] = s.slope;
  return out;
}

std::map<std::string, LimitSlope> LimitSlopes(const LcrSizingSpec& spec, const LcrMinSizeOptions& options,
                                              const LcrMinSizeOutcome& outcome) {
  std::map<std::string, LimitSlope> out;
  if (!outcome.converged || !outcome.check) return out;
  const StageClock::Scope stage("limit costs");
  const LcrDenseCheck& c = *outcome.check;
  const LcrLimits& l = spec.limits;
  struct Entry {
    const char* key;
    double LcrLimits::*field;
    bool binds;
  };
  const double stress = std::max(c.max_stress_MPa[0], c.max_stress_MPa[1]);
  const double force = std::max(c.max_force_N[0], c.max_force_N[1]);
  const double undercut = std::min(c.undercut_margin_mm[0], c.undercut_margin_mm[1]);
  const double gap = std::min(c.roller_gap_mm[0], c.roller_gap_mm[1]);
  const Entry entries[] = {
      {"contact_stress_MPa", &LcrLimits::contact_stress_MPa,
       std::isfinite(l.contact_stress_MPa) && stress >= l.contact_stress_MPa * (1 - kBindingFraction)},
      {"roller_load_N", &LcrLimits::roller_load_N,
       std::isfinite(l.roller_load_N) && force >= l.roller_load_N * (1 - kBindingFraction)},
      {"undercut_margin_mm", &LcrLimits::undercut_margin_mm, undercut <= l.undercut_margin_mm + kBindingFraction},
      {"roller_gap_mm", &LcrLimits::roller_gap_mm, gap <= l.roller_gap_mm + kBindingFraction},
      {"min_efficiency", &LcrLimits::min_efficiency,
       l.min_efficiency > 0 && c.mean_efficiency <= l.min_efficiency * (1 + kBindingFraction)},
      {"life_h", &LcrLimits::life_h, l.life_h > 0 && c.shortest_L10h <= l.life_h * (1 + kBindingFraction)},
      {"min_static_safety", &LcrLimits::min_static_safety,
       l.min_static_safety > 0 && c.min_static_safety <= l.min_static_safety * (1 + kBindingFraction)},
      {"max_oil_temperature_C", &LcrLimits::max_oil_temperature_C,
       spec.lubrication && std::isfinite(l.max_oil_temperature_C) &&
           c.oil_temperature_C >= l.max_oil_temperature_C - kBindingFraction * std::max(std::abs(l.max_oil_temperature_C), 1.0)},
      {"max_outer_diameter_mm", &LcrLimits::max_outer_diameter_mm,
       std::isfinite(l.max_outer_diameter_mm) && c.outer_diameter_mm >= l.max_outer_diameter_mm * (1 - kBindingFraction)},
  };
  const double f0 = LcrObjectiveValue(spec, c);
  for (const Entry& e : entries) {
    if (!e.binds) continue;
    const double base = l.*(e.field);
    // The lubricated efficiency's headroom is its loss share 1 − η: 2 × kSensitivityStep of it.
    const double h = e.field == &LcrLimits::min_efficiency && spec.lubrication
                         ? 2 * kSensitivityStep * (1 - base)
                         : std::max(std::abs(base), 1.0) * kSensitivityStep;
    double f[2] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()}, at[2] = {base - h, base + h};
    for (int s = 0; s < 2; ++s) {
      if (at[s] <= 0 && e.field != &LcrLimits::undercut_margin_mm) continue;
      LcrSizingSpec moved = spec;
      moved.limits.*(e.field) = at[s];
      const Polished p = Polish(moved, options, outcome.x, outcome.active);
      if (p.converged) f[s] = LcrObjectiveValue(spec, *p.check);
    }
    out[e.key] = SlopeFromReSolves(f[0], f0, f[1], h, 10 * options.solver.tolerance * std::max(std::abs(f0), 1.0));
  }
  return out;
}

std::optional<double> LimitToFit(const LcrSizingSpec& spec, const LcrMinSizeOptions& options,
                                 const std::string& key, std::optional<double> near, int* solves) {
  double LcrLimits::*field = nullptr;
  if (key == "contact_stress_MPa") field = &LcrLimits::contact_stress_MPa;
  if (key == "roller_load_N") field = &LcrLimits::roller_load_N;
  if (key == "life_h") field = &LcrLimits::life_h;
  const double limit = field ? spec.limits.*field : 0.0;
  if (!field || !std::isfinite(limit) || !(limit > 0)) return std::nullopt;
  LcrMinSizeOptions o = options;
  o.starts = 1;
  o.solver.max_evaluations = std::min(o.solver.max_evaluations, 300);
  // Worked in "how far the limit is moved": u = value / limit for an upper limit (stress, load),
  // limit / value for the lower limit life_h, so that u > 1 always loosens it. u = 1 is known not to
  // fit (the search just failed there); 64 is the farthest tried.
  const bool lower = field == &LcrLimits::life_h;
  auto value_at = [&](double u) { return lower ? limit / u : limit * u; };
  int count = 0;
  auto fits = [&](double u) {
    LcrSizingSpec moved = spec;
    moved.limits.*field = value_at(u);
    ++count;
    return SolveLcrMinSize(moved, o).converged;
  };
  constexpr double kFarthest = 64, kTolerance = 0.01;
  // The first trial: just past the limit's value at the closest point when it is known (the
  // closest point minimises the violation, so the limit moved there fits or nearly), else 2.
  bool from_near = false;
  double hi = 2;
  if (near && std::isfinite(*near) && *near > 0) {
    const double u_near = lower ? limit / *near : *near / limit;
    if (u_near > 1) hi = std::min(u_near * (1 + kTolerance), kFarthest), from_near = true;
  }
  // Then the bracket [lo, hi], lo not fitting and hi fitting: stepped from the first trial by 1.01,
  // 1.02, 1.04, … (each step squared, at most 2) from a near value, doubled otherwise.
  double lo = 1;
  if (fits(hi)) {
    for (double down = 1 + kTolerance; from_near && hi / down > 1; down *= down) {
      const double trial = hi / down;
      if (!fits(trial)) {
        lo = trial;
        break;
      }
      hi = trial;
    }
  } else {
    for (double up = from_near ? 1 + kTolerance : 2;; up = from_near ? std::min(up * up, 2.0) : 2) {
      lo = hi;
      if (lo >= kFarthest) {
        if (solves) *solves = count;
        return std::nullopt;
      }
      hi = std::min(lo * up, kFarthest);
      if (fits(hi)) break;
    }
  }
  while (hi - lo > kTolerance * hi) {
    const double mid = 0.5 * (lo + hi);
    (fits(mid) ? hi : lo) = mid;
  }
  if (solves) *solves = count;
  return value_at(hi);
}

}  // namespace camopt::sizing
