// The LCR sizing problem: the one file where the LCR pipeline is instantiated for
// ceres::Jet<double, 5> (keep heavy instantiations in few translation units).
#include "objectives/lcr_sizing.h"

#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <type_traits>

#include "model/common/roots.h"
#include "model/contact/hertz.h"
#include "model/lcr/cycle.h"
#include "model/lcr/forces.h"
#include "model/lcr/kinematics.h"
#include "model/lcr/life.h"
#include "model/lcr/profile.h"
#include "objectives/lcr_robust.h"

namespace camopt::objectives {
namespace {

constexpr int kJetSize = 6;       // e, r_dA, r_dB, d_rA, d_rB, R at most
constexpr int kJetSizeSmall = 4;  // e, r_dA, r_dB, R: the catalogue's rollers fix d_r

// The evaluator of f at the smallest Jet size that holds num_vars variables: a catalogue sizing's
// Jacobian carries 4 derivative parts, not 6 (each Jet operation costs about in proportion).
template <typename F>
std::unique_ptr<Evaluator> MakeLcrEvaluator(int num_vars, std::vector<OutputBlock> blocks, F f) {
  if (num_vars <= kJetSizeSmall) return MakeEvaluator<kJetSizeSmall>(num_vars, std::move(blocks), std::move(f));
  return MakeEvaluator<kJetSize>(num_vars, std::move(blocks), std::move(f));
}

struct Layout {
  int rollers;       // roller-diameter variables: 0 (catalogue), 1 (same roller), 2 (one per cam)
  int radius_index;  // index of R
};

Layout LayoutOf(const LcrSizingSpec& spec) {
  const int rollers = spec.fixed_roller_diameter_mm ? 0 : (spec.same_roller ? 1 : 2);
  return {rollers, 3 + rollers};
}

// Load period of one cam in input angle [rad] (see the header).
double Period(const LcrSizingSpec& s, lcr::Side side) {
  return side == lcr::Side::kInput ? 2 * kPi / s.rollers_a
                                   : 2 * kPi * s.lobes_a / (double(s.rollers_a) * s.lobes_b);
}

template <typename T>
lcr::Reducer<T> Design(const LcrSizingSpec& s, std::span<const T> x) {
  const Layout l = LayoutOf(s);
  const T rr_a = l.rollers > 0 ? x[3] / T(2.0) : T(*s.fixed_roller_diameter_mm / 2.0);
  const T rr_b = l.rollers == 2 ? x[4] / T(2.0) : rr_a;
  lcr::Reducer<T> r;
  r.eccentricity = x[0];
  r.input = {s.lobes_a, s.rollers_a, x[1], rr_a, T(s.roller_length_mm), T(s.cam_thickness_mm)};
  r.output = {s.lobes_b, s.rollers_b, x[2], rr_b, T(s.roller_length_mm), T(s.cam_thickness_mm)};
  return r;
}

// Reference force of the soft maximum [N]: the load limit, or 1 kN without one.
double ForceReference(const LcrSizingSpec& s) {
  return std::isfinite(s.limits.roller_load_N) ? s.limits.roller_load_N : 1000.0;
}

// The life rows are present (header, LcrLimits::life_h).
bool LifeRows(const LcrSizingSpec& s) { return s.limits.life_h > 0 && s.life.has_value(); }

// The static rows (header, LcrLimits::min_static_safety): which bearings have one.
bool StaticRows(const LcrSizingSpec& s) {
  return s.limits.min_static_safety > 0 && s.limits.static_torque_Nmm > 0 && s.life.has_value();
}
bool RollerStaticRows(const LcrSizingSpec& s) { return StaticRows(s) && s.life->roller.static_N > 0; }
bool EccentricStaticRow(const LcrSizingSpec& s) {
  return StaticRows(s) && s.life->eccentric && s.life->eccentric->static_N > 0;
}

// The oil temperature's row: the housing's balance with a finite limit.
bool TemperatureRow(const LcrSizingSpec& s) {
  return s.lubrication && !s.lubrication->temperature_C && std::isfinite(s.limits.max_oil_temperature_C);
}

// The power-loss objective's row.
bool PowerLossObjective(const LcrSizingSpec& s) { return s.objective == LcrSizeObjective::kPowerLoss; }

// Block sizes, in the order the evaluator writes them.
std::vector<OutputBlock> Blocks(const LcrSizingSpec& s) {
  std::vector<std::pair<std::string, int>> sizes = {
      {"outer_diameter_bound_mm", 1}, {"input_envelope_mm", 1},     {"output_envelope_mm", 1},
      {"input_roller_gap_mm", 1},     {"output_roller_gap_mm", 1},  {"input_undercut_margin_mm", 1},
      {"output_undercut_margin_mm", 1}, {"input_pitch_clearance_mm", 1},
      {"output_pitch_clearance_mm", 1}};
  const bool samples = s.form == LcrConstraintForm::kSamples;
  const bool active = s.form == LcrConstraintForm::kActiveSet;
  const int na = samples ? s.samples_per_period * s.rollers_a : 1;
  const int nb = samples ? s.samples_per_period * s.rollers_b : 1;
  sizes.push_back({"input_roller_force_N", active ? int(s.active.force[0].size()) : na});
  sizes.push_back({"output_roller_force_N", active ? int(s.active.force[1].size()) : nb});
  if (std::isfinite(s.limits.contact_stress_MPa)) {
    sizes.push_back({"input_stress_margin", active ? int(s.active.stress[0].size()) : na});
    sizes.push_back({"output_stress_margin", active ? int(s.active.stress[1].size()) : nb});
  }
  if (s.limits.min_efficiency > 0) sizes.push_back({"mean_efficiency", 1});
  if (TemperatureRow(s)) sizes.push_back({"oil_temperature_C", 1});
  if (LifeRows(s)) {
    sizes.push_back({"input_roller_life", 1});
    sizes.push_back({"output_roller_life", 1});
    if (s.life->eccentric) sizes.push_back({"eccentric_bearing_life", 1});
  }
  if (RollerStaticRows(s)) {
    sizes.push_back({"input_roller_static", 1});
    sizes.push_back({"output_roller_static", 1});
  }
  if (EccentricStaticRow(s)) sizes.push_back({"eccentric_bearing_static", 1});
  if (PowerLossObjective(s)) sizes.push_back({"power_loss_W", 1});
  std::vector<OutputBlock> blocks;
  int offset = 0;
  for (const auto& [name, size] : sizes) {
    blocks.push_back({name, offset, size});
    offset += size;
  }
  return blocks;
}

// Hertz capacity margin of a contact (header, LcrStressMargin).
template <typename T>
T StressMargin(const LcrSizingSpec& s, const lcr::CamSide<T>& cam, const T& force, const T& curvature) {
  return LcrStressMargin(s, cam.contact_length(), cam.roller_radius, force, curvature);
}

template <typename T>
lcr::SideLoads<T> SideAt(const LcrSizingSpec& s, const lcr::Reducer<T>& r, lcr::Side side, double theta) {
  const lcr::LoadCase load{s.output_torque_Nmm, 0.0, 0.0};
  return lcr::AnalyzeSide(r, s.material, load, side, T(theta), lcr::Stages{true, false, false});
}

// Force (stress = false) or stress margin of roller k at θ.
template <typename T>
T SampleValue(const LcrSizingSpec& s, const lcr::Reducer<T>& r, lcr::Side side, double theta, int k, bool stress) {
  const lcr::SideLoads<T> sl = SideAt(s, r, side, theta);
  return stress ? StressMargin(s, r.side(side), sl.force[k], sl.contacts[k].curvature) : sl.force[k];
}

// θ* of a sample: θ0 without a window, else the angle of the largest force (smallest margin) of
// its roller in θ0 ± window, on values only: the best of 9 samples, then Brent's method in the
// bracket of its neighbours started from the three (a smooth peak in a handful of evaluations) to
// 1e-5 of the sample step.
double PeakAngle(const LcrSizingSpec& s, const lcr::Reducer<double>& r, lcr::Side side, const LcrSample& a,
                 bool stress) {
  if (!(a.window_rad > 0)) return a.theta_rad;
  auto f = [&](double t) {
    const double v = SampleValue(s, r, side, t, a.roller, stress);
    return stress ? -v : v;
  };
  constexpr int n = 8;
  const double lo0 = a.theta_rad - a.window_rad, step = 2 * a.window_rad / n;
  std::array<double, n + 1> fs;
  int best = 0;
  for (int i = 0; i <= n; ++i) {
    fs[size_t(i)] = f(lo0 + i * step);
    if (fs[size_t(i)] > fs[size_t(best)]) best = i;
  }
  const int left = std::max(best - 1, 0), right = std::min(best + 1, n);
  const double x = lo0 + best * step;
  BrentStart start{x, fs[size_t(best)], x, fs[size_t(best)], x, fs[size_t(best)]};
  if (left < best && best < right) {  // both neighbours: the better second
    const bool l = fs[size_t(left)] >= fs[size_t(right)];
    const int second = l ? left : right, third = l ? right : left;
    start.w = lo0 + second * step, start.fw = fs[size_t(second)];
    start.v = lo0 + third * step, start.fv = fs[size_t(third)];
  } else {  // at an end of the window: one neighbour, no parabola yet
    const int other = best == left ? right : left;
    start.w = start.v = lo0 + other * step, start.fw = start.fv = fs[size_t(other)];
  }
  return BrentMaximize(f, lo0 + left * step, lo0 + right * step, start, 40, 1e-5 * step).first;
}

// Roller forces and Hertz capacity margins of one cam over its load period (kSamples,
// kAggregate: every roller at samples_per_period angles).
template <typename T>
void SideSamples(const LcrSizingSpec& s, const lcr::Reducer<T>& r, lcr::Side side,
                 std::vector<T>& force, std::vector<T>& margin, std::vector<bool>& loaded) {
  const lcr::CamSide<T>& cam = r.side(side);
  const double period = Period(s, side);
  for (int i = 0; i < s.samples_per_period; ++i) {
    const lcr::SideLoads<T> sl = SideAt(s, r, side, period * i / s.samples_per_period);
    const LcrRobustIncrements<T> inc = s.robust ? RobustIncrements(s, r, side, period * i / s.samples_per_period, sl)
                                                : LcrRobustIncrements<T>{};
    for (size_t k = 0; k < sl.force.size(); ++k) {
      force.push_back(s.robust ? sl.force[k] + inc.force[k] : sl.force[k]);
      loaded.push_back(Value(sl.force[k]) > 0);
      if (std::isfinite(s.limits.contact_stress_MPa))
        margin.push_back(s.robust ? StressMargin(s, cam, sl.force[k], sl.contacts[k].curvature) + inc.margin[k]
                                  : StressMargin(s, cam, sl.force[k], sl.contacts[k].curvature));
    }
  }
}

// kActiveSet rows of one cam (header): the peaks are found on the double design.
template <typename T>
void ActiveSamples(const LcrSizingSpec& s, const lcr::Reducer<T>& r, lcr::Side side, std::vector<T>& force,
                   std::vector<T>& margin) {
  const int i = side == lcr::Side::kInput ? 0 : 1;
  const lcr::Reducer<double> rd = r.template cast<double>();
  for (const LcrSample& a : s.active.force[i])
    force.push_back(SampleValue(s, r, side, PeakAngle(s, rd, side, a, false), a.roller, false));
  if (std::isfinite(s.limits.contact_stress_MPa))
    for (const LcrSample& a : s.active.stress[i])
      margin.push_back(SampleValue(s, r, side, PeakAngle(s, rd, side, a, true), a.roller, true));
}

// Samples of the eccentric bearing's load over its load period (lcr::LoadPeriodRad, no cam weight:
// m_A/gcd(m_A, m_B) input cam periods): samples_per_period per input cam period, at most 8 periods'
// worth (the dense check, objectives/lcr_dense_check.h, holds the result to the limit).
int EccentricSamples(const LcrSizingSpec& s) {
  const int periods = s.lobes_a / std::gcd(s.lobes_a, s.lobes_b);
  return s.samples_per_period * std::min(periods, 8);
}

// The life margins ln(L10h / life_h) of the rated bearings (docs/life.md, "Life as a sizing
// limit"): input roller, output roller, eccentric bearing (when rated).
// Rollers: the forces and spin rates of every roller at the samples_per_period angles of the cam's
// load period are roller 0's at uniform phases over its whole load period (roller k's phase is
// roller 0's shifted by k/n of that period; model/lcr/life.h), so their revolution-weighted
// p-mean (EquivalentLoad with the spin rates ψ'|ρ − r_r|/r_r as weights, both carrying
// derivatives) is the equivalent load P of one period, and the mean spin rate R the revolutions per
// input revolution. The rigid load law is linear in the output torque (forces.h: C_A, C_B ∝ T_o), so
// duty line i has P_i = P·T_i/T_o at speed R n_i; Palmgren–Miner over the lines and C at the roller's
// size give LifeMargin (model/common/bearing_life.h): one smooth row per bearing, in logarithms.
// With the static rows (LcrLimits::min_static_safety) also ln(C0 / (s0_min P0max)) of each bearing
// with a static rating, P0max the soft maximum of the same sampled loads (the aggregate force
// rows' log-sum-exp: smooth, and above the largest sample, so the row errs on the safe side; the
// dense check holds the true maximum on its own grid).
template <typename T>
void LifeMargins(const LcrSizingSpec& s, const lcr::Reducer<T>& r, std::vector<T>& out, std::vector<T>& statics) {
  const auto largest = [&](const std::vector<T>& v) { return lcr::ScaledSoftMax(v, ForceReference(s), s.sharpness); };
  const auto static_row = [&](const T& c0, const T& p0) {
    return log(c0) - log(T(s.limits.min_static_safety * s.limits.static_torque_Nmm / s.output_torque_Nmm) * p0);
  };
  const LcrLifeSpec& life = *s.life;
  const lcr::LoadCase load{s.output_torque_Nmm, 0.0, 0.0};
  auto margin = [&](const T& p_design, const T& revolutions, const T& rating, BearingKind kind) {
    std::vector<DutyCycleLine<T>> lines;
    for (const lcr::LcrDutyLine& l : life.lines)
      lines.push_back({l.time_share, T(l.input_speed_rpm) * revolutions,
                       {p_design * T(l.output_torque_Nmm / s.output_torque_Nmm)}});
    // No damage (every line without torque) is an infinite life: a large finite margin (e^50 times
    // the required life) with zero derivative, so that the solvers see a finite row.
    const T m = LifeMargin(rating, lines, kind, s.limits.life_h);
    return std::isfinite(Value(m)) ? m : T(50.0);
  };
  for (lcr::Side side : {lcr::Side::kInput, lcr::Side::kOutput}) {
    const double period = Period(s, side);
    std::vector<T> loads, spin;
    for (int i = 0; i < s.samples_per_period; ++i) {
      const T theta(period * i / s.samples_per_period);
      const lcr::SideLoads<T> sl = SideAt(s, r, side, Value(theta));
      for (size_t k = 0; k < sl.force.size(); ++k) {
        loads.push_back(sl.force[k]);
        spin.push_back(lcr::RollerSpinRate(r, side, theta, int(k)));
      }
    }
    T revolutions(0.0);
    for (const T& w : spin) revolutions += w;
    revolutions /= T(double(spin.size()));
    const lcr::CamSide<T>& cam = r.side(side);
    const T rating = LcrRollerRatingAt(life.roller, T(2.0) * cam.roller_radius, cam.roller_length, false);
    if (LifeRows(s))
      out.push_back(margin(EquivalentLoad(loads, spin, BearingKind::kRoller), revolutions, rating, BearingKind::kRoller));
    if (RollerStaticRows(s))
      statics.push_back(static_row(LcrRollerRatingAt(life.roller, T(2.0) * cam.roller_radius, cam.roller_length, true),
                                   largest(loads)));
  }
  if (life.eccentric) {
    // |G| over its load period (model/lcr/life.h); the bearing turns n_A/m_A per input revolution.
    const double period = 2 * kPi * double(std::lcm(s.lobes_a, s.lobes_b)) / (double(s.rollers_a) * s.lobes_b);
    const int n = EccentricSamples(s);
    const lcr::Stages stages{true, false, true};
    std::vector<T> loads;
    for (int i = 0; i < n; ++i)
      loads.push_back(lcr::AnalyzeAngle(r, s.material, load, T(period * i / n), stages).eccentric_load.norm());
    const BearingKind kind = life.eccentric->ball ? BearingKind::kBall : BearingKind::kRoller;
    if (LifeRows(s))
      out.push_back(margin(EquivalentLoad(loads, kind), T(double(s.rollers_a) / s.lobes_a),
                           T(life.eccentric->dynamic_N), kind));
    if (EccentricStaticRow(s)) statics.push_back(static_row(T(life.eccentric->static_N), largest(loads)));
  }
}

template <typename T>
void Evaluate(const LcrSizingSpec& s, std::span<const T> x, std::span<T> y) {
  const Layout l = LayoutOf(s);
  const lcr::Reducer<T> r = Design(s, x);
  const T radius = x[l.radius_index];
  size_t o = 0;
  y[o++] = T(2.0) * radius;
  y[o++] = r.input.turret_radius + r.input.roller_radius - radius;
  y[o++] = r.output.turret_radius + r.output.roller_radius - radius;
  y[o++] = lcr::RollerGap(r.input);
  y[o++] = lcr::RollerGap(r.output);
  // Exact margin 1/κ_max − r_r; the maximiser of κ is found on values, so its derivative is exact
  // by the envelope theorem (lcr::MaxPitchCurvature).
  y[o++] = lcr::UndercutMargin(r.input, r.eccentricity);
  y[o++] = lcr::UndercutMargin(r.output, r.eccentricity);
  if (s.robust) y[o - 2] += RobustUndercutIncrement(*s.robust), y[o - 1] += RobustUndercutIncrement(*s.robust);
  for (const lcr::CamSide<T>* c : {&r.input, &r.output})
    y[o++] = c->turret_radius * T(1.0 - s.pitch_clearance_fraction) -
             r.eccentricity * T(c->pitch_factor());
  const bool aggregate = s.form == LcrConstraintForm::kAggregate;
  const bool stress = std::isfinite(s.limits.contact_stress_MPa);
  std::vector<T> force[2], margin[2];
  std::vector<bool> loaded[2];
  T efficiency(0.0), oil_C(0.0), loss_W(0.0);
  std::vector<T> life, statics;
  try {
    if (LifeRows(s) || StaticRows(s)) LifeMargins(s, r, life, statics);
    if (s.form == LcrConstraintForm::kActiveSet) {
      ActiveSamples(s, r, lcr::Side::kInput, force[0], margin[0]);
      ActiveSamples(s, r, lcr::Side::kOutput, force[1], margin[1]);
    } else {
      SideSamples(s, r, lcr::Side::kInput, force[0], margin[0], loaded[0]);
      SideSamples(s, r, lcr::Side::kOutput, force[1], margin[1], loaded[1]);
    }
    if (s.lubrication && (s.limits.min_efficiency > 0 || TemperatureRow(s) || PowerLossObjective(s))) {
      // The lubricated operating point over the same angles (model/lcr/lubrication.h); no thermal
      // equilibrium below the oil's limit: not-a-number rows, which the solvers answer by a shorter step.
      const LcrSizingLubrication& lub = *s.lubrication;
      // Over a Jet the housing's balance is solved on values first (the same design in double),
      // and the Jets' losses are evaluated once, at its temperature.
      std::optional<ThermalPoint<double>> balance;
      if constexpr (!std::is_same_v<T, double>) {
        if (!lub.temperature_C) {
          std::vector<double> xv;
          for (const T& xi : x) xv.push_back(Value(xi));
          balance = lcr::LubricatedRigidCycle(Design(s, std::span<const double>(xv)), s.material, s.output_torque_Nmm,
                                              lub.spec, lub.input_speed_rpm, lub.temperature_C, lub.cooling, lub.balance_limit_C,
                                              s.efficiency_samples)
                        .balance;
        }
      }
      const lcr::RigidLubricatedPoint<T> p =
          lcr::LubricatedRigidCycle(r, s.material, s.output_torque_Nmm, lub.spec, lub.input_speed_rpm, lub.temperature_C,
                                    lub.cooling, lub.balance_limit_C, s.efficiency_samples, balance ? &*balance : nullptr);
      efficiency = p.found ? p.efficiency : T(std::numeric_limits<double>::quiet_NaN());
      oil_C = p.found ? p.oil_C : T(std::numeric_limits<double>::quiet_NaN());
      loss_W = p.found ? p.loss_W : T(std::numeric_limits<double>::quiet_NaN());
    } else if (s.limits.min_efficiency > 0) {
      // The efficiency mixes both cams' loads (and |F_r|), so it has no short period: a full
      // revolution. Mean of the per-angle efficiency, as lcr_analysis reports it.
      const lcr::LoadCase load{s.output_torque_Nmm, s.friction_coefficient, 0.0};
      const lcr::Stages stages{true, false, true};
      for (int i = 0; i < s.efficiency_samples; ++i)
        efficiency += lcr::AnalyzeAngle(r, s.material, load, T(2 * kPi * i / s.efficiency_samples), stages)
                          .efficiency;
      efficiency /= T(double(s.efficiency_samples));
    }
  } catch (const std::domain_error&) {
    // No roller can carry load (degenerate geometry): a non-finite output that the adapters
    // turn into an evaluation error.
    for (; o < y.size(); ++o) y[o] = T(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  // No sample carries load (a torque so small the forces underflow): the same evaluation error.
  if (aggregate && (force[0].empty() || force[1].empty())) {
    for (; o < y.size(); ++o) y[o] = T(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  for (int side = 0; side < 2; ++side) {
    if (!aggregate) {
      for (const T& f : force[side]) y[o++] = f;
    } else {
      // Soft maximum on forces relative to a fixed reference (the load limit). A data-dependent
      // reference (the current maximum) would make the aggregate kink where the largest sample
      // changes, and its Jet derivative would omit d(ref)/dx.
      y[o++] = lcr::ScaledSoftMax(force[side], ForceReference(s), s.sharpness);
    }
  }
  for (int side = 0; side < 2 && stress; ++side) {
    if (!aggregate) {
      for (const T& m : margin[side]) y[o++] = m;
    } else {
      // Soft minimum over loaded contacts only; at an unloaded contact the margin is 1 − r_r κ,
      // far above the minimum, so a roller entering or leaving the loaded set carries negligible
      // weight (e^{−k Δ}) and the aggregate stays continuous to that order.
      std::vector<T> m;
      for (size_t k = 0; k < margin[side].size(); ++k)
        if (loaded[side][k]) m.push_back(-margin[side][k]);
      y[o++] = -lcr::ScaledSoftMax(m, 1.0, s.sharpness);
    }
  }
  if (s.limits.min_efficiency > 0) y[o++] = efficiency;
  if (TemperatureRow(s)) y[o++] = oil_C;
  for (const T& m : life) y[o++] = m;
  for (const T& m : statics) y[o++] = m;
  if (PowerLossObjective(s)) y[o++] = loss_W;
}

}  // namespace

double LcrLoadPeriod(const LcrSizingSpec& spec, lcr::Side side) { return Period(spec, side); }

lcr::Reducer<double> LcrDesign(const LcrSizingSpec& spec, std::span<const double> x) {
  return Design<double>(spec, x);
}

double LcrOutputPowerW(const LcrSizingSpec& spec) {
  if (!spec.lubrication) return 0.0;
  const double ratio = lcr::OutputSpeedRatio(spec.lobes_a, spec.rollers_a, spec.lobes_b, spec.rollers_b);
  const double omega_out = spec.lubrication->input_speed_rpm * 2.0 * kPi / 60.0 * std::abs(ratio);
  return spec.output_torque_Nmm * 1e-3 * omega_out;
}

Problem MakeLcrSizingProblem(const LcrSizingSpec& spec) {
  if (spec.lobes_a < 1 || spec.rollers_a <= spec.lobes_a || spec.lobes_b < 1 ||
      spec.rollers_b <= spec.lobes_b)
    throw std::invalid_argument("LCR sizing: invalid lobe/roller counts");
  if (spec.samples_per_period < 2) throw std::invalid_argument("LCR sizing: samples_per_period < 2");
  if (spec.robust && spec.form == LcrConstraintForm::kActiveSet)
    throw std::invalid_argument("LCR sizing: robust rows need the samples or aggregate form");
  if (PowerLossObjective(spec) && !spec.lubrication)
    throw std::invalid_argument("LCR sizing: the power-loss objective needs the lubrication");
  if (spec.form == LcrConstraintForm::kActiveSet)
    for (int side = 0; side < 2; ++side) {
      const int n = side == 0 ? spec.rollers_a : spec.rollers_b;
      const bool stress = std::isfinite(spec.limits.contact_stress_MPa);
      if (spec.active.force[side].empty() || (stress && spec.active.stress[side].empty()))
        throw std::invalid_argument("LCR sizing: an active set needs at least one sample per cam");
      for (const auto* list : {&spec.active.force[side], &spec.active.stress[side]})
        for (const LcrSample& a : *list)
          if (a.roller < 0 || a.roller >= n) throw std::invalid_argument("LCR sizing: roller index out of range");
    }
  const Layout l = LayoutOf(spec);
  Problem p;
  const std::vector<double> x0 = LcrStartingPoints(spec, 1).front();
  const double e0 = x0[0], ra0 = x0[1], rb0 = x0[2], d0 = l.rollers > 0 ? x0[3] : 0.0;
  p.variables.push_back({"eccentricity_mm", spec.eccentricity_mm[0], spec.eccentricity_mm[1], e0, 1.0});
  p.variables.push_back({"input_turret_radius_mm", spec.turret_radius_mm[0], spec.turret_radius_mm[1], ra0, 10.0});
  p.variables.push_back({"output_turret_radius_mm", spec.turret_radius_mm[0], spec.turret_radius_mm[1], rb0, 10.0});
  if (l.rollers == 1)
    p.variables.push_back({"roller_diameter_mm", spec.roller_diameter_mm[0], spec.roller_diameter_mm[1], d0, 5.0});
  for (const char* side : {"input", "output"})
    if (l.rollers == 2)
      p.variables.push_back({std::string(side) + "_roller_diameter_mm", spec.roller_diameter_mm[0],
                             spec.roller_diameter_mm[1], d0, 5.0});
  // R's upper bound: the outer-diameter limit's half; with the power-loss objective (which does not
  // push R down) at most the largest outer radius of the variable box, so that R stays bounded.
  double r_max = spec.limits.max_outer_diameter_mm / 2;
  if (PowerLossObjective(spec))
    r_max = std::min(r_max, spec.turret_radius_mm[1] +
                                spec.fixed_roller_diameter_mm.value_or(spec.roller_diameter_mm[1]) / 2);
  p.variables.push_back({"outer_radius_mm", 0.0, r_max, std::min(x0.back(), r_max), 10.0});

  const LcrSizingSpec s = spec;
  p.evaluator = MakeLcrEvaluator(p.num_vars(), Blocks(spec), [s](auto x, auto y) { Evaluate(s, x, y); });
  if (PowerLossObjective(spec)) {
    p.objective = "power_loss_W";
    p.objective_scale = 0.05 * LcrOutputPowerW(spec);  // 5% of the power, as cycloid_min_size's
    if (!(p.objective_scale > 0)) throw std::invalid_argument("LCR sizing: the power-loss objective needs power");
  } else {
    p.objective = "outer_diameter_bound_mm";
    p.objective_scale = 100.0;
  }
  p.constraints = {{"input_envelope_mm", -kInf, 0.0, 10.0},
                   {"output_envelope_mm", -kInf, 0.0, 10.0},
                   {"input_roller_gap_mm", spec.limits.roller_gap_mm, kInf, 1.0},
                   {"output_roller_gap_mm", spec.limits.roller_gap_mm, kInf, 1.0},
                   {"input_undercut_margin_mm", spec.limits.undercut_margin_mm, kInf, 1.0},
                   {"output_undercut_margin_mm", spec.limits.undercut_margin_mm, kInf, 1.0},
                   {"input_pitch_clearance_mm", 0.0, kInf, 10.0},
                   {"output_pitch_clearance_mm", 0.0, kInf, 10.0}};
  if (std::isfinite(spec.limits.roller_load_N)) {
    p.constraints.push_back({"input_roller_force_N", -kInf, spec.limits.roller_load_N, spec.limits.roller_load_N});
    p.constraints.push_back({"output_roller_force_N", -kInf, spec.limits.roller_load_N, spec.limits.roller_load_N});
  }
  if (std::isfinite(spec.limits.contact_stress_MPa)) {
    p.constraints.push_back({"input_stress_margin", 0.0, kInf, 1.0});
    p.constraints.push_back({"output_stress_margin", 0.0, kInf, 1.0});
  }
  if (spec.limits.min_efficiency > 0)  // the lubricated one scaled by its loss share 1 − η
    p.constraints.push_back({"mean_efficiency", spec.limits.min_efficiency, kInf,
                             spec.lubrication ? std::max(1.0 - spec.limits.min_efficiency, 1e-3) : 0.1});
  if (TemperatureRow(spec))
    p.constraints.push_back({"oil_temperature_C", -kInf, spec.limits.max_oil_temperature_C, 10.0});
  if (LifeRows(spec)) {
    // ln(L10h / life_h) >= 0: order one (a factor e of life per unit), scale 1.
    p.constraints.push_back({"input_roller_life", 0.0, kInf, 1.0});
    p.constraints.push_back({"output_roller_life", 0.0, kInf, 1.0});
    if (spec.life->eccentric) p.constraints.push_back({"eccentric_bearing_life", 0.0, kInf, 1.0});
  }
  // ln(C0 / (s0_min P0max)) >= 0: order one, scale 1, as the life rows.
  if (RollerStaticRows(spec)) {
    p.constraints.push_back({"input_roller_static", 0.0, kInf, 1.0});
    p.constraints.push_back({"output_roller_static", 0.0, kInf, 1.0});
  }
  if (EccentricStaticRow(spec)) p.constraints.push_back({"eccentric_bearing_static", 0.0, kInf, 1.0});
  return p;
}

Problem MakeLcrLongestLifeProblem(const LcrSizingSpec& spec) {
  if (!LifeRows(spec)) throw std::invalid_argument("LCR longest life: no life limit");
  // The relaxation: the life rows and geometry only (a kAggregate spec without stress, load and
  // efficiency limits has one force row per cam, computed and not constrained).
  LcrSizingSpec s = spec;
  s.limits.contact_stress_MPa = kInf;
  s.limits.roller_load_N = kInf;
  s.limits.min_efficiency = 0.0;
  s.limits.min_static_safety = 0.0;
  s.limits.max_oil_temperature_C = kInf;
  s.limits.max_outer_diameter_mm = kInf;
  s.objective = LcrSizeObjective::kOuterDiameter;
  s.form = LcrConstraintForm::kAggregate;
  s.robust = nullptr;
  Problem sizing = MakeLcrSizingProblem(s);
  const Layout l = LayoutOf(s);
  const int n_full = sizing.evaluator->num_outputs();
  const char* geometric[] = {"input_roller_gap_mm",      "output_roller_gap_mm", "input_undercut_margin_mm",
                             "output_undercut_margin_mm", "input_pitch_clearance_mm", "output_pitch_clearance_mm"};
  std::vector<std::string> lives = {"input_roller_life", "output_roller_life"};
  if (s.life->eccentric) lives.push_back("eccentric_bearing_life");
  std::vector<int> picked;  // full-output index of each screen output after t
  std::vector<OutputBlock> blocks = {{"shortest_life_margin", 0, 1}};
  for (const char* g : geometric) {
    picked.push_back(sizing.evaluator->block(g).offset);
    blocks.push_back({g, int(blocks.size()), 1});
  }
  for (const std::string& b : lives) {
    picked.push_back(sizing.evaluator->block(b).offset);
    blocks.push_back({b + "_excess", int(blocks.size()), 1});
  }
  const int t_index = l.radius_index, first_life = 1 + int(std::size(geometric));
  Problem p;
  p.variables = sizing.variables;
  // t: a factor e^±50 of life spans any design the box holds.
  p.variables[size_t(t_index)] = {"shortest_life_margin", -50.0, 50.0, 0.0, 1.0};
  p.evaluator = MakeLcrEvaluator(
      p.num_vars(), blocks, [s, picked, t_index, n_full, first_life](auto x, auto y) {
        using T = typename decltype(y)::value_type;
        std::vector<T> all(size_t(n_full), T(0.0));
        Evaluate(s, x, std::span<T>(all));  // x[t_index] only enters the envelope rows, unused here
        const T t = x[size_t(t_index)];
        y[0] = t;
        for (size_t i = 0; i < picked.size(); ++i)
          y[i + 1] = int(i + 1) >= first_life ? all[size_t(picked[i])] - t : all[size_t(picked[i])];
      });
  p.objective = "shortest_life_margin";
  p.objective_scale = 1.0;
  p.maximize = true;
  for (const Constraint& c : sizing.constraints)
    for (const char* g : geometric)
      if (c.output == g) p.constraints.push_back(c);
  for (const std::string& b : lives) p.constraints.push_back({b + "_excess", 0.0, kInf, 1.0});
  return p;
}

std::vector<std::vector<double>> LcrStartingPoints(const LcrSizingSpec& spec, int count) {
  const Layout l = LayoutOf(spec);
  const auto mid = [](const std::array<double, 2>& b) { return 0.5 * (b[0] + b[1]); };
  const double d0 = spec.fixed_roller_diameter_mm.value_or(mid(spec.roller_diameter_mm));
  const double k_max = std::max(double(spec.rollers_a) / (spec.rollers_a - spec.lobes_a),
                                double(spec.rollers_b) / (spec.rollers_b - spec.lobes_b));
  // Each turret where the rollers have room (gap limit with some to spare), the eccentricity where
  // the pitch point e n/(n − m) sits at a fraction of the smaller turret radius (the optima of the
  // −90 study lie at 0.5–0.7). Start i varies both.
  const double pitch_fraction[] = {0.5, 0.3, 0.7, 0.4, 0.6};
  const double room_factor[] = {1.3, 1.1, 1.6, 1.2, 1.45};
  std::vector<std::vector<double>> starts;
  for (int i = 0; i < count; ++i) {
    const int j = i % 5;
    auto turret0 = [&](int n) {
      const double room = room_factor[j] * (d0 + std::max(spec.limits.roller_gap_mm, 0.0)) /
                          (2 * std::sin(kPi / n));
      return std::clamp(room, spec.turret_radius_mm[0], spec.turret_radius_mm[1]);
    };
    const double ra = turret0(spec.rollers_a), rb = turret0(spec.rollers_b);
    const double e = std::clamp(pitch_fraction[j] * std::min(ra, rb) / k_max, spec.eccentricity_mm[0],
                                spec.eccentricity_mm[1]);
    std::vector<double> x = {e, ra, rb};
    for (int k = 0; k < l.rollers; ++k) x.push_back(d0);
    x.push_back(std::max(ra, rb) + d0 / 2);
    starts.push_back(x);
  }
  return starts;
}

std::vector<LobeCombination> LobeCombinations(long target_ratio, int max_lobes,
                                              const std::vector<int>& differences) {
  std::vector<LobeCombination> out;
  for (int ma = 1; ma <= max_lobes; ++ma)
    for (int da : differences)
      for (int mb = 1; mb <= max_lobes; ++mb)
        for (int db : differences) {
          const long na = ma + da, nb = mb + db;
          const long num = long(ma) * nb, den = long(ma) * nb - long(mb) * na;
          if (da < 1 || db < 1 || den == 0 || num != target_ratio * den) continue;
          if (std::gcd(long(ma), na) != 1 || std::gcd(long(mb), nb) != 1) continue;
          out.push_back({ma, int(na), mb, int(nb)});
        }
  return out;
}

}  // namespace camopt::objectives
