#include "objectives/lcr_dense_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

#include "model/common/geometry.h"
#include "model/contact/hertz.h"
#include "model/lcr/cycle.h"
#include "model/lcr/forces.h"
#include "model/lcr/profile.h"

namespace camopt::objectives {
namespace {

// The solvers meet constraints to about their tolerance (1e-6 scaled), so they are given limits
// tightened by more than that; the dense check holds the design to the study's own limits.
constexpr double kLimitMargin = 1e-5;      // relative, on stress, load and efficiency limits
constexpr double kLengthMargin_mm = 1e-4;  // on gap and undercut limits (0.1 µm)
// Active-set selection: samples whose local maximum in angle lies within this fraction of the
// limit (or of the current maximum when that is lower), the largest kActivePeaks per cam.
constexpr double kNearFraction = 0.03;
constexpr int kActivePeaks = 4;

LcrSizingSpec Tightened(const LcrSizingSpec& spec) {
  LcrSizingSpec t = spec;
  t.limits.contact_stress_MPa *= 1 - kLimitMargin;
  t.limits.roller_load_N *= 1 - kLimitMargin;
  t.limits.roller_gap_mm += kLengthMargin_mm;
  t.limits.undercut_margin_mm += kLengthMargin_mm;
  if (t.limits.min_efficiency > 0) t.limits.min_efficiency *= 1 + kLimitMargin;
  if (std::isfinite(t.limits.max_oil_temperature_C)) t.limits.max_oil_temperature_C -= 1e-4;  // °C
  if (t.limits.life_h > 0) t.limits.life_h *= 1 + kLimitMargin;
  t.limits.max_outer_diameter_mm *= 1 - kLimitMargin;
  return t;
}

}  // namespace

double LcrViolation::excess() const {
  const bool upper = limit == "contact_stress_MPa" || limit == "roller_load_N" ||
                     limit == "max_oil_temperature_C" || limit == "max_outer_diameter_mm";  // lower: the rest
  return upper ? value - limit_value : limit_value - value;
}

namespace {

// The limit-free part of a dense check: what the design, the load and the models give before any
// limit is applied. A sizing checks one design under specs that differ only in their limits (each
// limit's cost is a re-solve from the best design with that limit moved) and checks its best more
// than once, so each thread keeps its last kKeptAnalyses and reuses one whose every input is equal
// (the same computation, so the same numbers).
struct AnalysisKey {
  lcr::Reducer<double> r;
  int steps = 0;
  bool roller_stress = false;
  lcr::Material material;
  double output_torque_Nmm = 0.0, friction_coefficient = 0.0;
  std::optional<LcrSizingLubrication> lubrication;
  std::optional<LcrLifeSpec> life;
  bool operator==(const AnalysisKey&) const = default;
};

/// A roller's local maximum in angle of its force or stress: (value, (angle index, roller)).
using Peak = std::pair<double, std::pair<int, int>>;

struct Analysis {
  LcrDenseCheck c;  ///< every number of the check but min_static_safety; no violations
  /// With roller_stress, per cam and quantity (0 force, 1 stress): every (angle, roller) value q > 0
  /// that is at least its neighbours in angle, in the order of the angles, then the rollers (the
  /// near samples are chosen from them once the limits are known).
  std::array<std::array<std::vector<Peak>, 2>, 2> maxima;
};

constexpr size_t kKeptAnalyses = 3;

Analysis Analyze(const LcrSizingSpec& spec, const lcr::Reducer<double>& r, int steps, bool roller_stress) {
  Analysis a;
  LcrDenseCheck& c = a.c;
  c.outer_diameter_mm = lcr::OuterDiameter(r);
  for (int k = 0; k < 2; ++k) {
    const lcr::CamSide<double>& side = k == 0 ? r.input : r.output;
    c.undercut_margin_mm[k] = lcr::UndercutMargin(side, r.eccentricity);
    c.roller_gap_mm[k] = lcr::RollerGap(side);
    c.pitch_clearance_mm[k] = side.turret_radius - r.eccentricity * side.pitch_factor();
  }
  const lcr::LoadCase load{spec.output_torque_Nmm, spec.friction_coefficient, 0.0};
  // The cycle on AnalyzeCycle's fast path: bit for bit AnalyzeAngle's numbers at each angle
  // (model/lcr/cycle.h), without its per-angle vectors.
  lcr::Stages stages;
  stages.roller_stress = roller_stress;
  const lcr::CycleSeries series = lcr::AnalyzeCycle(r, spec.material, load, steps, stages);
  double eta = 0.0;
  for (int i = 0; i < steps; ++i) eta += series.efficiency[size_t(i)];
  c.mean_efficiency = eta / steps;
  for (int k = 0; k < 2; ++k) {
    const lcr::SideSeries& side = k == 0 ? series.input : series.output;
    const lcr::CamSide<double>& cam = k == 0 ? r.input : r.output;
    int peak_angle = -1;  // the first angle of the largest stress (the half-width's)
    for (int i = 0; i < steps; ++i) {
      if (side.max_stress_MPa[size_t(i)] > c.max_stress_MPa[k]) {
        c.max_stress_MPa[k] = side.max_stress_MPa[size_t(i)];
        peak_angle = i;
      }
      c.max_force_N[k] = std::max(c.max_force_N[k], side.max_force_N[size_t(i)]);
    }
    if (peak_angle >= 0) {
      // The roller at the peak, as lcr::AnalyzeAngle has it there (the same bits).
      const lcr::AngleLoads<double> at = lcr::AnalyzeAngle(r, spec.material, load, 2 * kPi * peak_angle / steps);
      const lcr::SideLoads<double>& sl = k == 0 ? at.input : at.output;
      for (size_t j = 0; j < sl.stress.size(); ++j)
        if (sl.stress[j] == sl.max_stress && std::isfinite(sl.max_stress)) {
          const double r_eff = cam.roller_radius * (1.0 - cam.roller_radius * sl.contacts[j].curvature);
          c.peak_half_width_mm[k] = contact::LineContactHalfWidth(sl.force[j], cam.contact_length(), r_eff,
                                                                  spec.material.composite_modulus_MPa());
          break;
        }
    }
  }
  if (spec.lubrication) {
    const LcrSizingLubrication& l = *spec.lubrication;
    const lcr::RigidLubricatedPoint<double> p =
        lcr::LubricatedRigidCycle(r, spec.material, spec.output_torque_Nmm, l.spec, l.input_speed_rpm, l.temperature_C,
                                  l.cooling, l.balance_limit_C, steps);
    c.mean_efficiency = p.found ? p.efficiency : NAN;
    c.oil_temperature_C = p.found ? p.oil_C : NAN;
    c.lubricated_loss_W = p.found ? p.loss_W : NAN;
    c.lubrication_why = p.why;
  }
  if (spec.life) {
    // Every rated bearing (docs/life.md, "Life as a sizing limit"): the lcr_analysis computation of
    // the same design at `steps` samples per input revolution (rigid law, no cam weight).
    const LcrLifeSpec& life = *spec.life;
    struct Member {
      const char* name;
      lcr::LcrBearing bearing;
    };
    std::vector<Member> members = {{"input_roller", lcr::LcrBearing::kInputRoller},
                                   {"output_roller", lcr::LcrBearing::kOutputRoller}};
    if (life.eccentric) members.push_back({"eccentric_bearing", lcr::LcrBearing::kEccentric});
    for (const Member& m : members) {
      LcrBearingLifeCheck b;
      b.name = m.name;
      if (m.bearing == lcr::LcrBearing::kEccentric) {
        b.ball = life.eccentric->ball;
        b.dynamic_rating_N = life.eccentric->dynamic_N;
        b.static_rating_N = life.eccentric->static_N;
      } else {
        const lcr::CamSide<double>& cam = m.bearing == lcr::LcrBearing::kInputRoller ? r.input : r.output;
        b.dynamic_rating_N = LcrRollerRatingAt(life.roller, 2 * cam.roller_radius, cam.roller_length, false);
        if (life.roller.static_N > 0)
          b.static_rating_N = LcrRollerRatingAt(life.roller, 2 * cam.roller_radius, cam.roller_length, true);
      }
      const BearingKind kind = b.ball ? BearingKind::kBall : BearingKind::kRoller;
      b.life = lcr::BearingLifeOverDutyCycle(r, spec.material, load, lcr::LoadModel::kRigid, m.bearing,
                                             b.dynamic_rating_N, kind, life.lines, steps);
      if (b.static_rating_N > 0 && b.life.max_load_N > 0) b.s0 = b.static_rating_N / b.life.max_load_N;
      c.shortest_L10h = std::min(c.shortest_L10h, b.life.L10h);
      c.life.push_back(std::move(b));
    }
  }
  for (const DesignIssue& p : lcr::CheckDesign(r)) c.design_problems.push_back(p.field + ": " + p.message);
  if (roller_stress) {
    const int n[2] = {r.input.rollers, r.output.rollers};
    for (int k = 0; k < 2; ++k)
      for (int quantity = 0; quantity < 2; ++quantity) {
        const lcr::SideSeries& side = k == 0 ? series.input : series.output;
        const std::vector<double>& v = quantity == 0 ? side.roller_force_N.values() : side.roller_stress_MPa.values();
        std::vector<Peak>& peaks = a.maxima[size_t(k)][size_t(quantity)];
        for (int i = 0; i < steps; ++i) {
          const double* before = &v[size_t(i == 0 ? steps - 1 : i - 1) * n[k]];
          const double* here = &v[size_t(i) * n[k]];
          const double* after = &v[size_t(i + 1 == steps ? 0 : i + 1) * n[k]];
          for (int j = 0; j < n[k]; ++j) {
            const double q = here[j];
            if (q > 0 && q >= before[j] && q >= after[j]) peaks.push_back({q, {i, j}});
          }
        }
      }
  }
  return a;
}

/// Analyze, or the thread's kept analysis of the same inputs.
std::shared_ptr<const Analysis> KeptAnalysis(const LcrSizingSpec& spec, const lcr::Reducer<double>& r, int steps,
                                             bool roller_stress) {
  thread_local std::deque<std::pair<AnalysisKey, std::shared_ptr<const Analysis>>> kept;
  AnalysisKey key{r, steps, roller_stress, spec.material, spec.output_torque_Nmm, spec.friction_coefficient,
                  spec.lubrication, spec.life};
  for (const auto& [k, a] : kept)
    if (k == key) return a;
  auto a = std::make_shared<const Analysis>(Analyze(spec, r, steps, roller_stress));
  if (kept.size() == kKeptAnalyses) kept.pop_front();
  kept.emplace_back(std::move(key), a);
  return a;
}

}  // namespace

LcrDenseCheck DenseCheck(const LcrSizingSpec& spec, const lcr::Reducer<double>& r, int steps,
                         LcrActiveSet* near) {
  const std::shared_ptr<const Analysis> analysis = KeptAnalysis(spec, r, steps, near != nullptr);
  LcrDenseCheck c = analysis->c;
  const LcrLimits& lim = spec.limits;

  auto upper = [&](const char* key, double value, double limit) {
    if (!(value <= limit)) c.violations.push_back({key, value, limit});
  };
  auto lower = [&](const char* key, double value, double limit) {
    if (!(value >= limit)) c.violations.push_back({key, value, limit});
  };
  upper("contact_stress_MPa", std::max(c.max_stress_MPa[0], c.max_stress_MPa[1]), lim.contact_stress_MPa);
  upper("roller_load_N", std::max(c.max_force_N[0], c.max_force_N[1]), lim.roller_load_N);
  lower("undercut_margin_mm", std::min(c.undercut_margin_mm[0], c.undercut_margin_mm[1]), lim.undercut_margin_mm);
  lower("roller_gap_mm", std::min(c.roller_gap_mm[0], c.roller_gap_mm[1]), lim.roller_gap_mm);
  if (std::isfinite(lim.max_outer_diameter_mm))
    upper("max_outer_diameter_mm", c.outer_diameter_mm, lim.max_outer_diameter_mm);
  if (lim.min_efficiency > 0) lower("min_efficiency", c.mean_efficiency, lim.min_efficiency);
  if (spec.lubrication && std::isfinite(lim.max_oil_temperature_C))
    upper("max_oil_temperature_C", c.oil_temperature_C, lim.max_oil_temperature_C);
  if (spec.life) {
    if (lim.life_h > 0) lower("life_h", c.shortest_L10h, lim.life_h);
    if (lim.min_static_safety > 0 && lim.static_torque_Nmm > 0) {
      double line_torque = 0.0;
      for (const lcr::LcrDutyLine& l : spec.life->lines) line_torque = std::max(line_torque, l.output_torque_Nmm);
      for (const LcrBearingLifeCheck& b : c.life)
        if (b.static_rating_N > 0 && b.life.max_load_N > 0 && line_torque > 0)
          c.min_static_safety = std::min(
              c.min_static_safety, b.static_rating_N / (b.life.max_load_N * lim.static_torque_Nmm / line_torque));
      lower("min_static_safety", c.min_static_safety, lim.min_static_safety);
    }
  }

  if (near) {
    // Per cam and quantity: the rollers' local maxima in angle within kNearFraction of the limit
    // (or of the largest value, when that is lower; the largest alone without a limit), one per
    // phase of the load period (equal phases are the same peak on another roller), at most
    // kActivePeaks, each tracked over an eighth of the period either side.
    for (int k = 0; k < 2; ++k) {
      const double period = LcrLoadPeriod(spec, k == 0 ? lcr::Side::kInput : lcr::Side::kOutput);
      for (int quantity = 0; quantity < 2; ++quantity) {
        // The rollers' local maxima (Analyze) that reach the threshold, in their order.
        const double limit = quantity == 0 ? lim.roller_load_N : lim.contact_stress_MPa;
        const double vmax = quantity == 0 ? c.max_force_N[k] : c.max_stress_MPa[k];
        const double threshold = std::isfinite(limit) ? (1 - kNearFraction) * std::min(limit, vmax) : vmax;
        std::vector<Peak> peaks;
        for (const Peak& p : analysis->maxima[size_t(k)][size_t(quantity)])
          if (p.first >= threshold) peaks.push_back(p);
        std::sort(peaks.begin(), peaks.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
        std::vector<LcrSample> chosen;
        for (const auto& [q, ij] : peaks) {
          const double theta = 2 * kPi * ij.first / steps;
          const bool seen = std::any_of(chosen.begin(), chosen.end(), [&](const LcrSample& o) {
            return PhaseDistance(o.theta_rad, theta, period) < period / 8;
          });
          if (!seen) chosen.push_back({theta, ij.second, period / 8});
          if (int(chosen.size()) == kActivePeaks) break;
        }
        (quantity == 0 ? near->force : near->stress)[k] = std::move(chosen);
      }
    }
  }
  return c;
}

LcrSizingSpec LcrTightened(const LcrSizingSpec& spec) { return Tightened(spec); }

double LcrObjectiveValue(const LcrSizingSpec& spec, const LcrDenseCheck& check) {
  return spec.objective == LcrSizeObjective::kPowerLoss ? check.lubricated_loss_W : check.outer_diameter_mm;
}

Verification VerifyLcrLineDesign(const LcrSizingSpec& spec, const lcr::Reducer<double>& r, int steps) {
  Verification v;
  v.ran = true;
  v.accurate_model = "line contact, exact cycle on " + std::to_string(2 * steps) + " input angles (error: the change from " +
                     std::to_string(steps) + ")";
  const LcrDenseCheck a = DenseCheck(spec, r, steps), b = DenseCheck(spec, r, 2 * steps);
  const LcrLimits& lim = spec.limits;
  const char* cams[2] = {"input cam", "output cam"};
  auto add = [&](const char* key, const char* where, double coarse, double fine, double limit, bool upper) {
    VerifiedLimit c;
    c.limit = key;
    c.where = where;
    c.limit_value = limit;
    c.accurate_value = fine;
    c.estimated_error = std::abs(fine - coarse);
    c.fast_value = coarse;
    c.upper = upper;
    v.checks.push_back(c);
  };
  for (int k = 0; k < 2; ++k) {
    if (std::isfinite(lim.contact_stress_MPa))
      add("contact_stress_MPa", cams[k], a.max_stress_MPa[k], b.max_stress_MPa[k], lim.contact_stress_MPa, true);
    if (std::isfinite(lim.roller_load_N))
      add("roller_load_N", cams[k], a.max_force_N[k], b.max_force_N[k], lim.roller_load_N, true);
    add("undercut_margin_mm", cams[k], a.undercut_margin_mm[k], b.undercut_margin_mm[k], lim.undercut_margin_mm, false);
    add("roller_gap_mm", cams[k], a.roller_gap_mm[k], b.roller_gap_mm[k], lim.roller_gap_mm, false);
  }
  if (std::isfinite(lim.max_outer_diameter_mm))
    add("max_outer_diameter_mm", "2 max(turret radius + roller radius)", a.outer_diameter_mm, b.outer_diameter_mm,
        lim.max_outer_diameter_mm, true);
  if (lim.min_efficiency > 0)
    add("min_efficiency", spec.lubrication ? "lubricated, mean over the cycle" : "mean over the cycle", a.mean_efficiency,
        b.mean_efficiency, lim.min_efficiency, false);
  if (spec.lubrication && std::isfinite(lim.max_oil_temperature_C))
    add("max_oil_temperature_C", "the housing's balance", a.oil_temperature_C, b.oil_temperature_C,
        lim.max_oil_temperature_C, true);
  if (lim.life_h > 0)
    for (size_t i = 0; i < a.life.size(); ++i)
      if (std::isfinite(b.life[i].life.L10h))  // a bearing without load (+∞) has nothing to check
        add("life_h", a.life[i].name.c_str(), a.life[i].life.L10h, b.life[i].life.L10h, lim.life_h, false);
  if (lim.min_static_safety > 0 && lim.static_torque_Nmm > 0 && std::isfinite(b.min_static_safety))
    add("min_static_safety", "s0 at the momentary torque, every bearing with a static rating", a.min_static_safety,
        b.min_static_safety, lim.min_static_safety, false);
  return v;
}

}  // namespace camopt::objectives
