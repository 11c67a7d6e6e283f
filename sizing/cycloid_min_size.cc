#include "sizing/cycloid_min_size.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include <ceres/jet.h>

#include "model/cycloid/geometry_limits.h"
#include "objectives/cycloid_fields.h"
#include "objectives/evaluation_memo.h"
#include "sizing/sizing_driver.h"
#include "sizing/stage_clock.h"
#include "optimizers/first_order.h"

namespace camopt::sizing {
using namespace camopt::objectives;

namespace {

bool IsDriveField(const std::string& name) {
  return name == "eccentricity_mm" || name == "roller_position_radius_mm" || name == "roller_radius_mm" ||
         name == "face_width_mm" || name == "delta_position_um" || name == "delta_radius_um";
}

cycloid::LoadedOptions CycleOptions(cycloid::LoadedOptions o, bool edge) {
  o.keep_pressure = true;  // the derivatives need the converged pressures
  o.crank_slope = false;
  o.edge_margin = edge;
  o.sensitivity_tolerance = CycloidSensitivityTolerance(o);
  return o;
}

using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point since) { return std::chrono::duration<double>(Clock::now() - since).count(); }

// The closed-form values of a drive: objective, curtate, undercut, pin gap, web margins.
template <typename T>
struct ClosedForms {
  T diameter, volume, curtate, undercut, profile_radius, pin_gap, web;
};

template <typename T>
ClosedForms<T> ClosedFormsOf(const cycloid::DriveTpl<T>& d, const CycloidSizingLimits& l) {
  ClosedForms<T> c;
  const T outer = d.roller_position_radius_mm + d.roller_radius_mm;
  c.diameter = T(2.0) * outer;
  c.volume = T(kPi) * outer * outer * d.face_width_mm;
  c.curtate = cycloid::CurtateMargin(d);
  c.profile_radius = cycloid::MinConvexProfileRadius(d);
  c.undercut = c.profile_radius - T(l.min_profile_radius_mm);
  c.pin_gap = cycloid::PinGapMargin(d, l.min_pin_gap_mm);
  c.web = cycloid::WebMargin(d, T(l.bore_radius_mm), l.min_web_mm);
  return c;
}

// The kSizingCrowningFit rows of a drive's face width and a crowning (values and, per variable,
// derivatives: the variables are named, so the derivative of each row is read off its formula).
struct CrowningFit {
  std::array<double, 2> value{1.0, 1.0};
  std::array<std::map<std::string, double>, 2> d;  // by variable name
};

CrowningFit CrowningFitOf(const cycloid::Drive& d, const cycloid::Crowning& c) {
  CrowningFit f;
  const double b = d.face_width_mm;
  using cycloid::CrowningType;
  switch (c.type) {
    case CrowningType::kNone:
      break;
    case CrowningType::kFull:
      f.value[0] = c.radius_mm - 0.5 * b;
      f.d[0] = {{"radius_mm", 1.0}, {"face_width_mm", -0.5}};
      break;
    case CrowningType::kPartial:
      f.value[0] = c.radius_mm - 0.5 * (b - c.flat_length_mm);
      f.d[0] = {{"radius_mm", 1.0}, {"face_width_mm", -0.5}, {"flat_length_mm", 0.5}};
      f.value[1] = b - c.flat_length_mm;
      f.d[1] = {{"face_width_mm", 1.0}, {"flat_length_mm", -1.0}};
      break;
    case CrowningType::kLogarithmic:
      if (c.effective_length_mm > 0) {
        f.value[0] = c.effective_length_mm - b;
        f.d[0] = {{"effective_length_mm", 1.0}, {"face_width_mm", -1.0}};
      }
      f.value[1] = b - c.flat_length_mm;
      f.d[1] = {{"face_width_mm", 1.0}, {"flat_length_mm", -1.0}};
      break;
  }
  return f;
}

// A drive over a Jet whose derivative is along the sizing variable `name` (µm variables: 1e-3 mm).
using J1 = ceres::Jet<double, 1>;
cycloid::DriveTpl<J1> JetDrive(const cycloid::Drive& d, const std::string& name) {
  cycloid::DriveTpl<J1> dj = d.cast<J1>();
  if (name == "eccentricity_mm") dj.eccentricity_mm.v[0] = 1;
  if (name == "roller_position_radius_mm") dj.roller_position_radius_mm.v[0] = 1;
  if (name == "roller_radius_mm") dj.roller_radius_mm.v[0] = 1;
  if (name == "face_width_mm") dj.face_width_mm.v[0] = 1;
  if (name == "delta_position_um") dj.delta_position_mm.v[0] = 1e-3;
  if (name == "delta_radius_um") dj.delta_radius_mm.v[0] = 1e-3;
  return dj;
}

// The life margins m = ln(L10h / H) of the rated bearings (crank bearing, then the pins) over T
// (docs/life.md, "Cycloid"): per duty line i the ring-pin resultants ring[i][k] (crank frame) at the
// sizing's angles φ_k (one mesh period), the pins' loads pin_load[i][k n1 + r] and their spin rates
// pin_weight[k n1 + r] (the same on every line). Crank bearing: |B| over its load period, its
// p-mean per line, n1/n2 revolutions per input revolution; pins: the spin-weighted 10/3-mean, the
// mean spin per input revolution; Palmgren–Miner over the lines (LifeMargin).
template <typename T>
std::vector<T> LifeMarginsOf(const CycloidSizingLife& life, double required_h, const cycloid::Drive& d,
                             const std::vector<std::vector<Vec2<T>>>& ring, const std::vector<std::vector<T>>& pin_load,
                             const std::vector<T>& pin_weight, const std::vector<double>& angles) {
  std::vector<T> out;
  std::vector<DutyCycleLine<T>> crank;
  const double rc = cycloid::CrankBearingRevolutionsPerInputRevolution(d);
  for (size_t i = 0; i < life.lines.size(); ++i) {
    const OperatingLine& l = life.lines[i];
    const std::vector<T> loads =
        cycloid::CrankBearingLoadsOverPeriod<T>(d, life.output, ring[i], angles, l.output_torque_Nmm);
    crank.push_back({l.time_share, T(l.input_speed_rpm * rc), {EquivalentLoad(loads, life.crank_kind)}});
  }
  out.push_back(LifeMargin(T(life.crank_dynamic_N), crank, life.crank_kind, required_h));
  if (life.pins_rated) {
    T spin(0.0);
    for (const T& w : pin_weight) spin += w;
    spin /= double(pin_weight.size());
    std::vector<DutyCycleLine<T>> pins;
    for (size_t i = 0; i < life.lines.size(); ++i)
      pins.push_back({life.lines[i].time_share, T(life.lines[i].input_speed_rpm) * spin,
                      {EquivalentLoad(pin_load[i], pin_weight, BearingKind::kRoller)}});
    out.push_back(LifeMargin(T(life.pins_dynamic_N), pins, BearingKind::kRoller, required_h));
  }
  return out;
}

// The static rows are present (limits.min_static_safety at a static torque, with the life's ratings).
bool StaticRows(const CycloidSizingSpec& s) {
  return s.life && s.limits.min_static_safety > 0 && s.limits.static_torque_Nmm > 0;
}

// P/C0 of every static sample at the static torque (kSizingStatic): the crank bearing's |B| over its
// load period from the ring-pin resultants `ring` (crank frame) at the sizing's angles, then every
// (crank angle, pin) load; each bearing only with a static rating.
template <typename T>
std::vector<T> StaticUtilisationOf(const CycloidSizingLife& life, double static_torque_Nmm, const cycloid::Drive& d,
                                   const std::vector<Vec2<T>>& ring, const std::vector<T>& pin_load,
                                   const std::vector<double>& angles) {
  std::vector<T> out;
  if (life.crank_static_N > 0)
    for (const T& b : cycloid::CrankBearingLoadsOverPeriod<T>(d, life.output, ring, angles, static_torque_Nmm))
      out.push_back(b / life.crank_static_N);
  if (life.pins_rated && life.pins_static_N > 0)
    for (const T& q : pin_load) out.push_back(q / life.pins_static_N);
  return out;
}

// The number of static rows (StaticUtilisationOf's samples).
size_t StaticRowCount(const CycloidSizingSpec& s) {
  if (!StaticRows(s)) return 0;
  const CycloidSizingLife& life = *s.life;
  size_t n = 0;
  if (life.crank_static_N > 0)
    n += size_t(s.angles_per_period) * size_t(cycloid::OutputPinPeriodInMeshPeriods(life.output, s.drive.teeth));
  if (life.pins_rated && life.pins_static_N > 0) n += size_t(s.angles_per_period) * size_t(s.drive.rollers);
  return n;
}

// The lives of a design as cycloid_ltca reports them (LifeOverDutyCycle of each rated bearing).
std::vector<CycloidBearingLife> LivesOf(const CycloidSizingLife& life, const cycloid::Drive& d,
                                        const std::vector<const std::vector<cycloid::MeshLoad>*>& meshes) {
  std::vector<cycloid::BearingLineSamples> crank, pins;
  for (size_t i = 0; i < life.lines.size(); ++i) {
    const OperatingLine& l = life.lines[i];
    const std::vector<double> b = cycloid::CrankBearingLoads(d, life.output, *meshes[i], l.output_torque_Nmm);
    crank.push_back({l.time_share, l.input_speed_rpm, b, std::vector<double>(b.size(), 1.0)});
    if (life.pins_rated) {
      const cycloid::PinLoadSamples p = cycloid::PinBearingLoads(d, *meshes[i]);
      pins.push_back({l.time_share, l.input_speed_rpm, p.load_N, p.spin_rate});
    }
  }
  std::vector<CycloidBearingLife> out;
  auto add = [&](const std::string& name, bool ball, double c, double c0, double revolutions,
                 const std::vector<cycloid::BearingLineSamples>& lines) {
    CycloidBearingLife b;
    b.name = name;
    b.ball = ball;
    b.dynamic_N = c;
    b.static_N = c0;
    b.life = cycloid::LifeOverDutyCycle(c, ball ? BearingKind::kBall : BearingKind::kRoller, revolutions, lines);
    if (c0 > 0) b.s0 = StaticSafetyFactor(c0, std::vector<double>{b.life.max_load_N});
    out.push_back(std::move(b));
  };
  add("crank_bearing", life.crank_kind == BearingKind::kBall, life.crank_dynamic_N, life.crank_static_N,
      cycloid::CrankBearingRevolutionsPerInputRevolution(d), crank);
  if (life.pins_rated) {
    double spin = 0.0;
    for (double w : pins.front().weight) spin += w;
    add("pins", false, life.pins_dynamic_N, life.pins_static_N, spin / double(pins.front().weight.size()), pins);
  }
  return out;
}

// The samples of the output rows: the cycle's angles over the output pins' load period.
size_t OutputSamples(const CycloidSizingSpec& s) {
  if (!s.output) return 0;
  const cycloid::OutputMechanism m{s.output->pins.pins, s.output->pins.pin_circle_radius_mm};
  return size_t(s.angles_per_period) * size_t(cycloid::OutputPinPeriodInMeshPeriods(m, s.drive.teeth));
}

// The hole of the sized eccentricity: r_h = r_c + e + c.
template <typename T>
T OutputHoleRadius(const CycloidSizingOutput& o, const cycloid::DriveTpl<T>& d) {
  return T(o.pins.contact_radius_mm() + o.clearance_mm) + d.eccentricity_mm;
}

// The holes inside the disc's root circle: a' − e − ρ' − (R_w + r_h) (kSizingOutputHoles).
template <typename T>
T OutputHolesMargin(const CycloidSizingOutput& o, const cycloid::DriveTpl<T>& d) {
  return d.roller_position_radius_mm + d.delta_position_mm - d.eccentricity_mm - d.roller_radius_mm -
         d.delta_radius_mm - T(o.pins.pin_circle_radius_mm) - OutputHoleRadius(o, d);
}

// The objective's block name.
const char* ObjectiveName(CycloidSizeObjective o) {
  return o == CycloidSizeObjective::kVolume ? kSizingVolume
         : o == CycloidSizeObjective::kPowerLoss ? kSizingPowerLoss
                                                 : kSizingOuterDiameter;
}

// One disc's output power at the design torque and the lubrication's input speed [W] (0 without).
double OutputPowerW(const CycloidSizingSpec& s) {
  return s.lubrication ? s.design_torque_Nmm * 1e-3 * s.lubrication->input_speed_rpm * 2.0 * kPi / 60.0 / s.drive.teeth
                       : 0.0;
}

// The lubricated losses of a design (spec.lubrication) over T = double or a Jet along one variable:
// the loads of one disc over a revolution's pattern (the design cycle's meshes at the sizing's
// angles, the output pins shifted as LubricationLoadsOverRevolution), `load_of(k, p)` the p-th
// pair's load at angle k and `lag_of(k)` the disc's lag there.
template <typename T, typename LoadOf, typename LagOf>
std::vector<cycloid::MeshLubricationLoadsTpl<T>> LubricationLoadsOf(const CycloidSizingLubrication& l,
                                                                    const cycloid::Drive& d,
                                                                    const cycloid::DriveTpl<T>& dt,
                                                                    const std::vector<double>& angles,
                                                                    const cycloid::CycleResult& dc, double torque_Nmm,
                                                                    const LoadOf& load_of, const LagOf& lag_of) {
  return cycloid::LubricationLoadsOverRevolution<T>(d, l.mechanism, angles, torque_Nmm, [&](size_t k) {
    std::vector<std::pair<int, T>> loads;
    for (size_t p = 0; p < dc.meshes[k].pairs.size(); ++p) loads.push_back({dc.meshes[k].pairs[p].roller, load_of(k, p)});
    return cycloid::LubricationLoadsFrom<T>(dt, l.mechanism, cycloid::UnloadedTca<T>(dt, T(angles[k])), angles[k], loads,
                                            lag_of(k), torque_Nmm);
  });
}

// η = P_out/(P_out + P_loss) of one disc at the design torque, P_loss its mean over `loads`, the
// oil temperature given or the housing's balance (its derivative implicit, model/common/thermal.h).
// `solved`: the balance already solved on values (the derivative pass after the values' pass), so
// the loss is evaluated over T once, at its temperature.
template <typename T>
struct LubricatedValues {
  T efficiency{}, loss_W{}, temperature_C{};
  bool found = false;
  std::string why;
  ThermalPoint<double> balance;  ///< the housing's balance on values (T = double, no given temperature)
};
template <typename T>
LubricatedValues<T> LubricatedOf(const CycloidSizingLubrication& l, const cycloid::DriveTpl<T>& dt, double e_star,
                                 const std::vector<cycloid::MeshLubricationLoadsTpl<T>>& loads, double torque_Nmm,
                                 const ThermalPoint<double>* solved = nullptr) {
  std::optional<cycloid::OutputPinContactTpl<T>> pins;
  if (l.pins)
    pins = cycloid::OutputPinContactTpl<T>{l.pins->pin_radius_mm,
                                          T(l.pins->contact_radius_mm() + l.hole_clearance_mm) + dt.eccentricity_mm,
                                          l.pins->roller_radius_mm};
  const std::vector<cycloid::CrankKinematics<T>> kinematics =
      cycloid::RevolutionKinematics(dt, l.spec, e_star, loads, pins, l.input_speed_rpm);  // once for every t
  const auto loss = [&](const T& t) { return cycloid::MeanLoss(kinematics, l.spec, t); };
  LubricatedValues<T> out;
  if (l.temperature_C) {
    out.temperature_C = T(*l.temperature_C);
    out.loss_W = loss(out.temperature_C);
    out.found = true;
  } else {
    const ThermalPoint<T> p = solved ? OperatingPointOver<T>(loss, l.cooling, *solved)
                                     : SolveOperatingTemperature<T>(loss, l.cooling, l.balance_limit_C);
    if constexpr (std::is_same_v<T, double>) out.balance = p;
    out.found = p.found;
    out.why = p.why;
    out.temperature_C = p.temperature_C;
    out.loss_W = p.loss_W;
  }
  const T output_W(torque_Nmm * 1e-3 * l.input_speed_rpm * 2.0 * kPi / 60.0 / dt.teeth);
  out.efficiency = output_W / (output_W + out.loss_W);
  return out;
}

// The output rows of a design (spec.output; CycloidSizingOutput) over T = double or a Jet along one
// variable: the torsional stiffness [N·m/arcmin] and lost motion [arcmin] at crank 0 from the ring
// lags β(T_r), β(T_r/2), β(0.03 T_r) and the output pins' rotations; per sample (shift r of whole
// mesh periods, angle k of the cycle) the pins' bending stress (the most loaded pin, one disc) and
// the crank bearing's |B| from the ring-pin resultant ring[k] (crank frame); the holes' margin.
template <typename T>
struct OutputRowValues {
  T stiffness, lost_motion;
  std::vector<T> stress, bearing;
};

template <typename T>
OutputRowValues<T> OutputRowsOf(const CycloidSizingOutput& o, const cycloid::DriveTpl<T>& d, double e_star_MPa,
                                double torque_Nmm, const std::vector<double>& angles,
                                const std::vector<Vec2<T>>& ring, const std::array<T, 3>& beta) {
  using std::sqrt;
  cycloid::OutputPinsTpl<T> m;
  m.pins = o.pins.pins;
  m.pin_circle_radius_mm = T(o.pins.pin_circle_radius_mm);
  m.pin_radius_mm = T(o.pins.pin_radius_mm);
  m.hole_radius_mm = OutputHoleRadius(o, d);
  m.roller_radius_mm = T(o.pins.roller_radius_mm);
  m.face_width_mm = d.face_width_mm;
  m.e_star_MPa = T(e_star_MPa);
  OutputRowValues<T> v;
  const double arcmin = 180.0 / kPi * 60.0;
  // Crank 0: pin 0 on the eccentricity (its crank-frame angle −φ n1/n2 = 0), the curve odd.
  std::array<T, 3> theta;
  const double fractions[3] = {1.0, 0.5, 0.03};
  for (int i = 0; i < 3; ++i)
    theta[size_t(i)] = beta[size_t(i)] +
                       cycloid::SolveOutputPins(m, d.eccentricity_mm, T(fractions[i] * torque_Nmm), T(0.0)).rotation_rad;
  v.stiffness = T(0.5e-3 * torque_Nmm / arcmin) / (theta[0] - theta[1]);
  v.lost_motion = T(2.0 * arcmin) * theta[2];
  const int period =
      cycloid::OutputPinPeriodInMeshPeriods(cycloid::OutputMechanism{o.pins.pins, o.pins.pin_circle_radius_mm}, d.teeth);
  const double tau = 2.0 * kPi / d.rollers, n1_over_n2 = double(d.rollers) / double(d.teeth);
  const T span = o.span_mm > 0 ? T(o.span_mm) : d.face_width_mm;
  // One disc at the mid-plane: cantilever M = Q (L − b/2) at the flange, both ends Q L/4 under the
  // disc (Roark, Table 8.1; PinBendingMoment with one load).
  const T arm = o.support == cycloid::PinSupport::kCantilever ? span - T(0.5) * d.face_width_mm : T(0.25) * span;
  for (int r = 0; r < period; ++r)
    for (size_t k = 0; k < angles.size(); ++k) {
      const double phi = angles[k] + r * tau;
      const cycloid::OutputPinLoads<T> p =
          cycloid::SolveOutputPins(m, d.eccentricity_mm, T(torque_Nmm), T(-phi * n1_over_n2));
      size_t top = 0;
      for (size_t j = 1; j < p.force_N.size(); ++j)
        if (Value(p.force_N[j]) > Value(p.force_N[top])) top = j;
      v.stress.push_back(cycloid::PinBendingStress(T(p.force_N[top] * arm), m.pin_radius_mm));
      const Vec2<T> b = cycloid::CrankBearingForce(ring[k], p);
      const T b2 = b.squaredNorm();
      v.bearing.push_back(Value(b2) > 0.0 ? sqrt(b2) : T(0.0));
    }
  return v;
}

}  // namespace

std::vector<std::string> CycloidSizingVariableNames() {
  return {"eccentricity_mm", "roller_position_radius_mm", "roller_radius_mm", "face_width_mm",
          "delta_position_um", "delta_radius_um", "coefficient_mm", "effective_length_mm",
          "end_drop_mm", "flat_length_mm", "radius_mm"};
}

std::string CycloidSizingVariableAllowed(const std::string& name, cycloid::CrowningType type) {
  if (IsDriveField(name)) return "";
  return CrowningParameterApplies(name, type).value_or("not a sizing variable");
}

CycloidSizingModel::CycloidSizingModel(CycloidSizingSpec spec) : spec_(std::move(spec)) {
  for (const Variable& v : spec_.variables)
    if (const std::string why = CycloidSizingVariableAllowed(v.name, spec_.crowning.type); !why.empty())
      throw std::invalid_argument("sizing variable " + v.name + ": " + why);
  if (spec_.angles_per_period < 1) throw std::invalid_argument("CycloidSizingModel: angles_per_period < 1");
  if (!(spec_.design_torque_Nmm > 0)) throw std::invalid_argument("CycloidSizingModel: design torque must be > 0");
  if (spec_.objective == CycloidSizeObjective::kPowerLoss && !spec_.lubrication)
    throw std::invalid_argument("CycloidSizingModel: the power-loss objective needs the lubrication");
  angles_ = cycloid::UniformCrankAngles(spec_.angles_per_period, 2.0 * kPi / spec_.drive.rollers);
}

std::pair<cycloid::Drive, cycloid::Crowning> CycloidSizingModel::Design(const std::vector<double>& x) const {
  if (x.size() != spec_.variables.size()) throw std::invalid_argument("CycloidSizingModel: one value per variable");
  cycloid::Drive d = spec_.drive;
  cycloid::Crowning c = spec_.crowning;
  for (size_t j = 0; j < x.size(); ++j) SetCycloidField(spec_.variables[j].name, x[j], d, c);
  return {d, c};
}

CycloidSizingEvaluation CycloidSizingModel::Evaluate(const std::vector<double>& x, bool with_gradient) {
  const auto [d, c] = Design(x);
  const size_t nv = x.size(), na = angles_.size(), n1 = size_t(d.rollers);
  const bool over = spec_.overload_torque_Nmm > 0;
  CycloidSizingEvaluation e;
  e.x = x;
  // Closed forms (values; their derivatives below with one Jet per variable).
  const ClosedForms<double> cf = ClosedFormsOf(d, spec_.limits);
  e.outer_diameter_mm = cf.diameter;
  e.volume_mm3 = cf.volume;
  e.curtate_margin = cf.curtate;
  e.undercut_margin_mm = cf.undercut;
  e.min_profile_radius_mm = cf.profile_radius;
  e.pin_gap_margin_mm = cf.pin_gap;
  e.web_margin_mm = cf.web;
  const CrowningFit fit = CrowningFitOf(d, c);
  e.crowning_fit_mm = fit.value;
  if (with_gradient) {
    for (int r = 0; r < 2; ++r)
      for (const Variable& v : spec_.variables) {
        const auto it = fit.d[size_t(r)].find(v.name);
        e.d_crowning_fit.push_back(it == fit.d[size_t(r)].end() ? 0.0 : it->second);
      }
  }
  if (with_gradient) {
    using J = J1;
    const bool volume = spec_.objective == CycloidSizeObjective::kVolume;
    for (size_t j = 0; j < nv; ++j) {
      const cycloid::DriveTpl<J> dj = JetDrive(d, spec_.variables[j].name);
      const ClosedForms<J> cj = ClosedFormsOf(dj, spec_.limits);
      // The loss's derivative replaces this below (kPowerLoss).
      e.d_objective.push_back((volume ? cj.volume : cj.diameter).v[0]);
      e.d_curtate.push_back(cj.curtate.v[0]);
      e.d_undercut.push_back(cj.undercut.v[0]);
      e.d_pin_gap.push_back(cj.pin_gap.v[0]);
      e.d_web.push_back(cj.web.v[0]);
      if (spec_.output) e.d_output_holes.push_back(OutputHolesMargin(*spec_.output, dj).v[0]);
    }
  }
  if (spec_.output) e.output_holes_margin_mm = OutputHolesMargin(*spec_.output, d);
  const size_t ns = OutputSamples(spec_);
  e.output_pin_stress_MPa.assign(ns, NAN);
  e.crank_bearing_load_N.assign(ns, NAN);
  // The loaded cycles: only for a drive inside the model's domain (no loop, no pin overlap, no
  // undercut: cycloid::CheckDrive); elsewhere their rows are NaN, which the solvers answer by a
  // shorter step.
  e.pair_peak_MPa.assign(na * n1, NAN);
  e.end_distance_um.assign(over ? na : 0, NAN);
  e.unloaded_te_arcsec.assign(na, NAN);
  e.lte_peak_to_peak_arcsec = e.stress_MPa = e.max_pair_load_N = NAN;
  e.edge_margin_um = over ? NAN : kInf;
  const bool life_rows = spec_.life && spec_.limits.life_h > 0;
  const size_t nl = life_rows ? (spec_.life->pins_rated ? 2 : 1) : 0;
  e.life_margin.assign(nl, NAN);
  const bool static_rows = StaticRows(spec_);
  const size_t n_static = StaticRowCount(spec_);
  e.static_utilisation.assign(n_static, NAN);
  if (static_rows) e.min_static_safety = NAN;
  auto nan_gradients = [&] {
    if (!with_gradient) return;
    e.d_life_margin.assign(nl * nv, NAN);
    e.d_static_utilisation.assign(n_static * nv, NAN);
    e.d_pair_peak.assign(na * n1 * nv, NAN);
    e.d_end_distance.assign((over ? na : 0) * nv, NAN);
    e.d_unloaded_te.assign(na * nv, NAN);
    e.d_lte.assign(nv, NAN);
    if (spec_.output) {
      e.d_stiffness.assign(nv, NAN);
      e.d_lost_motion.assign(nv, NAN);
      e.d_output_pin_stress.assign(ns * nv, NAN);
      e.d_crank_bearing_load.assign(ns * nv, NAN);
    }
    if (spec_.lubrication) {
      e.d_efficiency.assign(nv, NAN);
      e.d_oil_temperature.assign(nv, NAN);
      e.d_power_loss.assign(nv, NAN);
      if (spec_.objective == CycloidSizeObjective::kPowerLoss) e.d_objective.assign(nv, NAN);
    }
  };
  if (!cycloid::CheckDrive(d).empty() || !cycloid::CheckCrowning(c, d.face_width_mm).empty()) {
    e.converged = false;
    nan_gradients();
    return e;
  }
  if (!base_design_) {
    base_design_.emplace(d, c, spec_.material, CycleOptions(spec_.options, false));
    if (over) base_over_.emplace(d, c, spec_.material, CycleOptions(spec_.options, true));
  }
  const cycloid::LoadedTca des = base_design_->WithDesign(d, c);
  std::optional<cycloid::LoadedTca> ovl;
  if (over) ovl.emplace(base_over_->WithDesign(d, c));
  if (!(last_x_ == x && last_design_)) {
    const auto t0 = Clock::now();
    last_x_ = x;
    last_design_ = cycloid::RunCycle(des, spec_.design_torque_Nmm, angles_);
    if (over) last_over_ = cycloid::RunCycle(*ovl, spec_.overload_torque_Nmm, angles_);
    // Each duty line at another torque is one cycle of its own (the contact is nonlinear).
    last_lines_.clear();
    if (spec_.life)
      for (const OperatingLine& l : spec_.life->lines) {
        last_lines_.emplace_back();
        if (l.output_torque_Nmm > 0 && l.output_torque_Nmm != spec_.design_torque_Nmm)
          last_lines_.back() = cycloid::RunCycle(des, l.output_torque_Nmm, angles_);
      }
    last_static_.reset();
    if (static_rows && spec_.limits.static_torque_Nmm != spec_.design_torque_Nmm)
      last_static_ = cycloid::RunCycle(des, spec_.limits.static_torque_Nmm, angles_);
    last_half_.reset();
    last_small_.reset();
    if (spec_.output) {  // the torsional curve at crank 0 (its T_r point is the design cycle's angle 0)
      last_half_ = cycloid::RunCycle(des, 0.5 * spec_.design_torque_Nmm, {0.0});
      last_small_ = cycloid::RunCycle(des, 0.03 * spec_.design_torque_Nmm, {0.0});
    }
    ++evaluations_;
    value_seconds_ += Seconds(t0);
  }
  const cycloid::CycleResult& dc = *last_design_;
  e.stress_MPa = dc.max_pressure_MPa;
  e.lte_peak_to_peak_arcsec = dc.lte_peak_to_peak_arcsec;
  e.max_pair_load_N = dc.max_pair_load_N;
  e.converged = dc.converged;
  std::fill(e.pair_peak_MPa.begin(), e.pair_peak_MPa.end(), 0.0);
  for (size_t k = 0; k < na; ++k) {
    for (const cycloid::PairLoad& p : dc.meshes[k].pairs) e.pair_peak_MPa[k * n1 + size_t(p.roller)] = p.max_pressure_MPa;
    e.unloaded_te_arcsec[k] = dc.meshes[k].unloaded_rotation_rad * cycloid::kArcsecPerRad;
  }
  if (over) {
    const cycloid::CycleResult& mc = *last_over_;
    e.edge_margin_um = mc.end_distance_mm * 1e3;
    for (size_t k = 0; k < na; ++k) e.end_distance_um[k] = mc.meshes[k].end_distance_mm * 1e3;
    e.converged = e.converged && mc.converged;
  }
  // The duty lines' meshes: the design cycle's, a line's own cycle, or unloaded (no torque).
  std::vector<cycloid::MeshLoad> unloaded;
  for (double a : angles_) {
    cycloid::MeshLoad m;
    m.crank_angle_rad = a;
    unloaded.push_back(m);
  }
  std::vector<const std::vector<cycloid::MeshLoad>*> line_meshes;
  if (spec_.life) {
    for (size_t i = 0; i < spec_.life->lines.size(); ++i) {
      const double torque = spec_.life->lines[i].output_torque_Nmm;
      line_meshes.push_back(torque == spec_.design_torque_Nmm ? &dc.meshes
                            : last_lines_[i]                  ? &last_lines_[i]->meshes
                                                              : &unloaded);
      if (last_lines_[i]) e.converged = e.converged && last_lines_[i]->converged;
    }
    e.lives = LivesOf(*spec_.life, d, line_meshes);
    e.shortest_life_h = kInf;
    for (const CycloidBearingLife& b : e.lives) e.shortest_life_h = std::min(e.shortest_life_h, b.life.L10h);
  }
  // The static torque's meshes: one more "line" after the duty lines (the life rows read only
  // theirs); the design cycle's when the torques are equal.
  const size_t static_line = line_meshes.size();
  if (static_rows) {
    line_meshes.push_back(last_static_ ? &last_static_->meshes : &dc.meshes);
    if (last_static_) e.converged = e.converged && last_static_->converged;
  }
  // The life rows over double (their values; the same numbers as e.lives' L10h, in logarithms).
  auto life_inputs = [&](auto zero, const auto& load_of, const auto& lag_of, const auto& unloaded_at,
                         const auto& spin_of, auto& ring, auto& pin_load, auto& pin_weight) {
    using T = decltype(zero);
    ring.assign(line_meshes.size(), {});
    pin_load.assign(line_meshes.size(), std::vector<T>(na * n1, zero));
    pin_weight.assign(na * n1, zero);
    for (size_t k = 0; k < na; ++k) {
      const auto& u = unloaded_at(k);
      for (size_t r = 0; r < n1; ++r) pin_weight[k * n1 + r] = spin_of(u, r, k);
      for (size_t i = 0; i < line_meshes.size(); ++i) {
        const cycloid::MeshLoad& m = (*line_meshes[i])[k];
        std::vector<std::pair<int, T>> loads;
        for (size_t p = 0; p < m.pairs.size(); ++p) {
          loads.push_back({m.pairs[p].roller, load_of(i, k, p)});
          pin_load[i][k * n1 + size_t(m.pairs[p].roller)] = loads.back().second;
        }
        ring[i].push_back(cycloid::RingPinResultantCrankFrame(u.drive, u.mesh, loads, T(angles_[k]), lag_of(i, k)));
      }
    }
  };
  if (life_rows || static_rows) {
    struct U {
      const cycloid::Drive& drive;
      cycloid::UnloadedMesh<double> mesh;
    };
    std::vector<U> meshes_u;
    for (size_t k = 0; k < na; ++k) meshes_u.push_back({d, cycloid::UnloadedTca<double>(d, angles_[k])});
    std::vector<std::vector<Vec2<double>>> ring;
    std::vector<std::vector<double>> pin_load;
    std::vector<double> pin_weight;
    life_inputs(
        0.0, [&](size_t i, size_t k, size_t p) { return (*line_meshes[i])[k].pairs[p].load_N; },
        [&](size_t i, size_t k) { return (*line_meshes[i])[k].rotation_rad; },
        [&](size_t k) -> const U& { return meshes_u[k]; },
        [&, &drive = d](const U& u, size_t r, size_t k) { return cycloid::RollerSpinRate(drive, u.mesh.pairs[r], angles_[k]); }, ring,
        pin_load, pin_weight);
    if (life_rows)
      e.life_margin = LifeMarginsOf<double>(*spec_.life, spec_.limits.life_h, d, ring, pin_load, pin_weight, angles_);
    if (static_rows) {
      e.static_utilisation = StaticUtilisationOf<double>(*spec_.life, spec_.limits.static_torque_Nmm, d,
                                                         ring[static_line], pin_load[static_line], angles_);
      double largest = 0.0;
      for (double u : e.static_utilisation) largest = std::max(largest, u);
      e.min_static_safety = largest > 0 ? 1.0 / largest : kInf;
    }
  }
  // The output rows (values): the design cycle's ring-pin resultants, the torsional curve's lags.
  std::vector<Vec2<double>> ring_design;
  if (spec_.output) {
    for (const cycloid::MeshLoad& m : dc.meshes) ring_design.push_back(cycloid::RingPinResultantCrankFrame(d, m));
    e.converged = e.converged && last_half_->converged && last_small_->converged;
    try {
      const OutputRowValues<double> v = OutputRowsOf<double>(
          *spec_.output, d, spec_.material.composite_modulus_MPa(), spec_.design_torque_Nmm, angles_, ring_design,
          {dc.meshes[0].rotation_rad, last_half_->meshes[0].rotation_rad, last_small_->meshes[0].rotation_rad});
      e.stiffness_Nm_per_arcmin = v.stiffness;
      e.lost_motion_arcmin = v.lost_motion;
      e.output_pin_stress_MPa = v.stress;
      e.crank_bearing_load_N = v.bearing;
      e.max_output_pin_stress_MPa = *std::max_element(v.stress.begin(), v.stress.end());
      e.max_crank_bearing_load_N = *std::max_element(v.bearing.begin(), v.bearing.end());
    } catch (const std::invalid_argument&) {  // a torque the pins cannot carry: NaN rows
      e.converged = false;
    }
  }
  // The lubricated losses (values).
  const double e_star = spec_.material.composite_modulus_MPa();
  ThermalPoint<double> balance;  // solved on values, differentiated below
  if (spec_.lubrication) {
    const CycloidSizingLubrication& l = *spec_.lubrication;
    const LubricatedValues<double> v = LubricatedOf<double>(
        l, d, e_star,
        LubricationLoadsOf<double>(
            l, d, d, angles_, dc, spec_.design_torque_Nmm,
            [&](size_t k, size_t p) { return dc.meshes[k].pairs[p].load_N; },
            [&](size_t k) { return dc.meshes[k].rotation_rad; }),
        spec_.design_torque_Nmm);
    balance = v.balance;
    if (v.found) {
      e.efficiency = v.efficiency;
      e.power_loss_W = v.loss_W;
      e.oil_temperature_C = v.temperature_C;
    } else {
      e.lubrication_why = v.why;
    }
  }
  if (!with_gradient) return e;
  const auto t0 = Clock::now();
  ++gradient_evaluations_;
  std::vector<std::string> params;
  std::vector<double> factor;
  for (const Variable& v : spec_.variables) {
    const auto [p, f] = CycloidModelParameter(v.name);
    params.push_back(p);
    factor.push_back(f);
  }
  e.d_pair_peak.assign(na * n1 * nv, 0.0);
  e.d_unloaded_te.assign(na * nv, 0.0);
  e.d_lte.assign(nv, 0.0);
  e.d_end_distance.assign((over ? na : 0) * nv, 0.0);
  e.d_life_margin.assign(nl * nv, 0.0);
  e.d_static_utilisation.assign(n_static * nv, 0.0);
  if (spec_.lubrication) {
    e.d_efficiency.assign(nv, NAN);
    e.d_oil_temperature.assign(nv, NAN);
    e.d_power_loss.assign(nv, NAN);
  }
  if (spec_.output) {
    e.d_stiffness.assign(nv, NAN);
    e.d_lost_motion.assign(nv, NAN);
    e.d_output_pin_stress.assign(e.output_pin_stress_MPa.size() * nv, NAN);
    e.d_crank_bearing_load.assign(e.crank_bearing_load_N.size() * nv, NAN);
  }
  if (nv > 0) {
    const std::vector<cycloid::CycleDerivative> dd = cycloid::DifferentiateCycle(des, dc, params, 0.0);
    if (spec_.output && std::isfinite(e.stiffness_Nm_per_arcmin)) {
      // The lags' derivatives (implicit, LoadedTca::Differentiate) and the resultants' through the
      // pair loads and the unloaded TCA's normals with a Jet, as the life rows.
      const std::vector<cycloid::CycleDerivative> dh = cycloid::DifferentiateCycle(des, *last_half_, params, 0.0);
      const std::vector<cycloid::CycleDerivative> ds = cycloid::DifferentiateCycle(des, *last_small_, params, 0.0);
      auto jet = [](double value, double slope) {
        J1 t(value);
        t.v[0] = slope;
        return t;
      };
      for (size_t j = 0; j < nv; ++j) {
        const cycloid::DriveTpl<J1> dj = JetDrive(d, spec_.variables[j].name);
        std::vector<Vec2<J1>> ring;
        for (size_t k = 0; k < na; ++k) {
          const cycloid::UnloadedMesh<J1> u = cycloid::UnloadedTca<J1>(dj, J1(angles_[k]));
          std::vector<std::pair<int, J1>> loads;
          for (size_t p = 0; p < dc.meshes[k].pairs.size(); ++p)
            loads.push_back({dc.meshes[k].pairs[p].roller,
                             jet(dc.meshes[k].pairs[p].load_N, dd[j].pair_load_N[k][p] * factor[j])});
          ring.push_back(cycloid::RingPinResultantCrankFrame(
              dj, u, loads, J1(angles_[k]), jet(dc.meshes[k].rotation_rad, dd[j].rotation_rad[k] * factor[j])));
        }
        const OutputRowValues<J1> v = OutputRowsOf<J1>(
            *spec_.output, dj, spec_.material.composite_modulus_MPa(), spec_.design_torque_Nmm, angles_, ring,
            {jet(dc.meshes[0].rotation_rad, dd[j].rotation_rad[0] * factor[j]),
             jet(last_half_->meshes[0].rotation_rad, dh[j].rotation_rad[0] * factor[j]),
             jet(last_small_->meshes[0].rotation_rad, ds[j].rotation_rad[0] * factor[j])});
        e.d_stiffness[j] = v.stiffness.v[0];
        e.d_lost_motion[j] = v.lost_motion.v[0];
        for (size_t r = 0; r < v.stress.size(); ++r) {
          e.d_output_pin_stress[r * nv + j] = v.stress[r].v[0];
          e.d_crank_bearing_load[r * nv + j] = v.bearing[r].v[0];
        }
        e.converged = e.converged && dh[j].converged && ds[j].converged;
      }
    }
    if (spec_.lubrication && std::isfinite(e.efficiency)) {
      // The pair loads' and the lag's derivatives (implicit) as Jets, the rest through the drive's Jet.
      const CycloidSizingLubrication& l = *spec_.lubrication;
      for (size_t j = 0; j < nv; ++j) {
        const cycloid::DriveTpl<J1> dj = JetDrive(d, spec_.variables[j].name);
        const auto jet = [](double value, double slope) {
          J1 t(value);
          t.v[0] = slope;
          return t;
        };
        const LubricatedValues<J1> v = LubricatedOf<J1>(
            l, dj, e_star,
            LubricationLoadsOf<J1>(
                l, d, dj, angles_, dc, spec_.design_torque_Nmm,
                [&](size_t k, size_t p) {
                  return jet(dc.meshes[k].pairs[p].load_N, dd[j].pair_load_N[k][p] * factor[j]);
                },
                [&](size_t k) { return jet(dc.meshes[k].rotation_rad, dd[j].rotation_rad[k] * factor[j]); }),
            spec_.design_torque_Nmm, l.temperature_C ? nullptr : &balance);
        e.d_efficiency[j] = v.efficiency.v[0];
        e.d_oil_temperature[j] = v.temperature_C.v[0];
        e.d_power_loss[j] = v.loss_W.v[0];
      }
    }
    if (spec_.objective == CycloidSizeObjective::kPowerLoss) e.d_objective = e.d_power_loss;
    if (life_rows || static_rows) {
      // dF_i/ds and the lag's derivative of every duty line's cycle (the design cycle's own: dd),
      // and of the static torque's.
      std::vector<std::vector<cycloid::CycleDerivative>> line_dd(line_meshes.size());
      for (size_t i = 0; i < line_meshes.size() && i < last_lines_.size(); ++i)
        if (last_lines_[i] && line_meshes[i] == &last_lines_[i]->meshes)
          line_dd[i] = cycloid::DifferentiateCycle(des, *last_lines_[i], params, 0.0);
      if (static_rows && last_static_)
        line_dd[static_line] = cycloid::DifferentiateCycle(des, *last_static_, params, 0.0);
      auto derivative_of = [&](size_t i) -> const std::vector<cycloid::CycleDerivative>* {
        if (line_meshes[i] == &dc.meshes) return &dd;
        return line_dd[i].empty() ? nullptr : &line_dd[i];
      };
      for (size_t j = 0; j < nv; ++j) {
        const cycloid::DriveTpl<J1> dj = JetDrive(d, spec_.variables[j].name);
        struct UJ {
          const cycloid::DriveTpl<J1>& drive;
          cycloid::UnloadedMesh<J1> mesh;
        };
        std::vector<UJ> meshes_u;
        for (size_t k = 0; k < na; ++k) meshes_u.push_back({dj, cycloid::UnloadedTca<J1>(dj, J1(angles_[k]))});
        std::vector<std::vector<Vec2<J1>>> ring;
        std::vector<std::vector<J1>> pin_load;
        std::vector<J1> pin_weight;
        auto jet = [](double value, double slope) {
          J1 t(value);
          t.v[0] = slope;
          return t;
        };
        life_inputs(
            J1(0.0),
            [&](size_t i, size_t k, size_t p) {
              const auto* di = derivative_of(i);
              return jet((*line_meshes[i])[k].pairs[p].load_N, di ? (*di)[j].pair_load_N[k][p] * factor[j] : 0.0);
            },
            [&](size_t i, size_t k) {
              const auto* di = derivative_of(i);
              return jet((*line_meshes[i])[k].rotation_rad, di ? (*di)[j].rotation_rad[k] * factor[j] : 0.0);
            },
            [&](size_t k) -> const UJ& { return meshes_u[k]; },
            [&](const UJ& u, size_t r, size_t k) { return cycloid::RollerSpinRate(dj, u.mesh.pairs[r], J1(angles_[k])); },
            ring, pin_load, pin_weight);
        if (life_rows) {
          const std::vector<J1> m =
              LifeMarginsOf<J1>(*spec_.life, spec_.limits.life_h, d, ring, pin_load, pin_weight, angles_);
          for (size_t r = 0; r < nl; ++r) e.d_life_margin[r * nv + j] = m[r].v[0];
        }
        if (static_rows) {
          const std::vector<J1> u = StaticUtilisationOf<J1>(*spec_.life, spec_.limits.static_torque_Nmm, d,
                                                            ring[static_line], pin_load[static_line], angles_);
          for (size_t r = 0; r < u.size() && r < n_static; ++r) e.d_static_utilisation[r * nv + j] = u[r].v[0];
        }
      }
      for (const auto& di : line_dd)
        for (const auto& one : di) e.converged = e.converged && one.converged;
    }
    for (size_t j = 0; j < nv; ++j) {
      for (size_t k = 0; k < na; ++k) {
        for (size_t i = 0; i < dc.meshes[k].pairs.size(); ++i)
          e.d_pair_peak[(k * n1 + size_t(dc.meshes[k].pairs[i].roller)) * nv + j] =
              dd[j].pair_max_pressure_MPa[k][i] * factor[j];
        e.d_unloaded_te[k * nv + j] = dd[j].unloaded_rotation_rad[k] * cycloid::kArcsecPerRad * factor[j];
      }
      e.d_lte[j] = dd[j].lte_peak_to_peak_arcsec * factor[j];
      e.converged = e.converged && dd[j].converged;
    }
    if (over) {
      const std::vector<cycloid::CycleDerivative> dm = cycloid::DifferentiateCycle(*ovl, *last_over_, params, 0.0);
      for (size_t j = 0; j < nv; ++j) {
        for (size_t k = 0; k < na; ++k)
          e.d_end_distance[k * nv + j] = dm[j].end_distance_per_angle_mm[k] * 1e3 * factor[j];
        e.converged = e.converged && dm[j].converged;
      }
    }
  }
  gradient_seconds_ += Seconds(t0);
  return e;
}

namespace {

// Output layout of the evaluator: [objective][peaks: na·N][end distances: na (overload)]
// [β0: na][LTE p-p][curtate][undercut][pin gap][web (bore)].
struct Layout {
  size_t na = 0, n1 = 0;
  bool over = false, web = false;
  size_t peaks() const { return 1; }
  size_t ends() const { return 1 + na * n1; }
  size_t backlash() const { return ends() + (over ? na : 0); }
  size_t lte() const { return backlash() + na; }
  size_t curtate() const { return lte() + 1; }
  size_t undercut() const { return curtate() + 1; }
  size_t pin_gap() const { return undercut() + 1; }
  size_t web_row() const { return pin_gap() + 1; }
  size_t fit() const { return web_row() + (web ? 1 : 0); }
  size_t life() const { return fit() + 2; }
  size_t statics() const { return life() + lives; }
  size_t stiffness() const { return statics() + static_rows; }
  size_t lost_motion() const { return stiffness() + (stiffness_row ? 1 : 0); }
  size_t pin_stress() const { return lost_motion() + (lost_motion_row ? 1 : 0); }
  size_t bearing() const { return pin_stress() + (pin_stress_rows ? samples : 0); }
  size_t holes() const { return bearing() + (bearing_rows ? samples : 0); }
  size_t efficiency() const { return holes() + (output ? 1 : 0); }
  size_t temperature() const { return efficiency() + (efficiency_row ? 1 : 0); }
  size_t size() const { return temperature() + (temperature_row ? 1 : 0); }
  bool efficiency_row = false, temperature_row = false;  // spec.lubrication with its limits
  size_t lives = 0;  // life rows (limits.life_h): crank bearing, pins
  size_t static_rows = 0;  // kSizingStatic rows (limits.min_static_safety)
  // The output rows (spec.output, each with its limit), samples over the pins' load period.
  bool output = false, stiffness_row = false, lost_motion_row = false, pin_stress_rows = false, bearing_rows = false;
  size_t samples = 0;
};

Layout LayoutOf(const CycloidSizingModel& m) {
  Layout l;
  l.na = m.crank_angles().size();
  l.n1 = size_t(m.spec().drive.rollers);
  l.over = m.spec().overload_torque_Nmm > 0;
  l.web = m.spec().limits.bore_radius_mm > 0;
  if (m.spec().life && m.spec().limits.life_h > 0) l.lives = m.spec().life->pins_rated ? 2 : 1;
  l.static_rows = StaticRowCount(m.spec());
  const CycloidSizingLimits& lim = m.spec().limits;
  l.output = bool(m.spec().output);
  l.stiffness_row = l.output && lim.min_torsional_stiffness_Nm_per_arcmin > 0;
  l.lost_motion_row = l.output && std::isfinite(lim.max_lost_motion_arcmin);
  l.pin_stress_rows = l.output && std::isfinite(lim.output_pin_stress_MPa);
  l.bearing_rows = l.output && std::isfinite(lim.eccentric_bearing_load_N);
  l.samples = OutputSamples(m.spec());
  l.efficiency_row = m.spec().lubrication && lim.min_efficiency > 0;
  l.temperature_row = m.spec().lubrication && !m.spec().lubrication->temperature_C && std::isfinite(lim.max_oil_temperature_C);
  return l;
}

class SizingEvaluator final : public Evaluator {
 public:
  SizingEvaluator(CycloidSizingModel& model, std::function<void(const CycloidSizingEvaluation&)> on_evaluation,
                  OutsideDomain outside)
      : Evaluator(int(model.spec().variables.size()), Blocks(model)),
        model_(model),
        layout_(LayoutOf(model)),
        memory_(8, std::move(on_evaluation)),
        outside_(outside) {}

 protected:
  void DoEval(std::span<const double> x, std::span<double> y) const override { Fill(Get(x, false), y); }
  void DoEvalWithJacobian(std::span<const double> x, std::span<double> y, std::span<double> jac) const override {
    const CycloidSizingEvaluation& e = Get(x, true);
    Fill(e, y);
    const size_t nv = size_t(num_vars());
    const Layout& l = layout_;
    for (size_t j = 0; j < nv; ++j) {
      jac[j] = e.d_objective[j];
      for (size_t s = 0; s < l.na * l.n1; ++s) jac[(l.peaks() + s) * nv + j] = e.d_pair_peak[s * nv + j];
      if (l.over)
        for (size_t k = 0; k < l.na; ++k) jac[(l.ends() + k) * nv + j] = e.d_end_distance[k * nv + j];
      for (size_t k = 0; k < l.na; ++k) jac[(l.backlash() + k) * nv + j] = e.d_unloaded_te[k * nv + j];
      jac[l.lte() * nv + j] = e.d_lte[j];
      jac[l.curtate() * nv + j] = e.d_curtate[j];
      jac[l.undercut() * nv + j] = e.d_undercut[j];
      jac[l.pin_gap() * nv + j] = e.d_pin_gap[j];
      if (l.web) jac[l.web_row() * nv + j] = e.d_web[j];
      for (size_t r = 0; r < 2; ++r) jac[(l.fit() + r) * nv + j] = e.d_crowning_fit[r * nv + j];
      for (size_t r = 0; r < l.lives; ++r) jac[(l.life() + r) * nv + j] = e.d_life_margin[r * nv + j];
      for (size_t r = 0; r < l.static_rows; ++r)
        jac[(l.statics() + r) * nv + j] = e.d_static_utilisation[r * nv + j];
      if (l.stiffness_row) jac[l.stiffness() * nv + j] = e.d_stiffness[j];
      if (l.lost_motion_row) jac[l.lost_motion() * nv + j] = e.d_lost_motion[j];
      for (size_t r = 0; l.pin_stress_rows && r < l.samples; ++r)
        jac[(l.pin_stress() + r) * nv + j] = e.d_output_pin_stress[r * nv + j];
      for (size_t r = 0; l.bearing_rows && r < l.samples; ++r)
        jac[(l.bearing() + r) * nv + j] = e.d_crank_bearing_load[r * nv + j];
      if (l.output) jac[l.holes() * nv + j] = e.d_output_holes[j];
      if (l.efficiency_row) jac[l.efficiency() * nv + j] = e.d_efficiency[j];
      if (l.temperature_row) jac[l.temperature() * nv + j] = e.d_oil_temperature[j];
    }
    if (outside_ == OutsideDomain::kPenalty)
      for (double& v : jac)
        if (!std::isfinite(v)) v = 0.0;
  }

 private:
  static std::vector<OutputBlock> Blocks(const CycloidSizingModel& m) {
    const Layout l = LayoutOf(m);
    std::vector<OutputBlock> b = {{ObjectiveName(m.spec().objective), 0, 1},
                                  {kSizingPeakPressure, int(l.peaks()), int(l.na * l.n1)}};
    if (l.over) b.push_back({kSizingEndDistance, int(l.ends()), int(l.na)});
    b.push_back({kSizingBacklash, int(l.backlash()), int(l.na)});
    b.push_back({kSizingLte, int(l.lte()), 1});
    b.push_back({kSizingCurtate, int(l.curtate()), 1});
    b.push_back({kSizingUndercut, int(l.undercut()), 1});
    b.push_back({kSizingPinGap, int(l.pin_gap()), 1});
    if (l.web) b.push_back({kSizingWeb, int(l.web_row()), 1});
    b.push_back({kSizingCrowningFit, int(l.fit()), 2});
    if (l.lives > 0) b.push_back({kSizingLife, int(l.life()), int(l.lives)});
    if (l.static_rows > 0) b.push_back({kSizingStatic, int(l.statics()), int(l.static_rows)});
    if (l.stiffness_row) b.push_back({kSizingStiffness, int(l.stiffness()), 1});
    if (l.lost_motion_row) b.push_back({kSizingLostMotion, int(l.lost_motion()), 1});
    if (l.pin_stress_rows) b.push_back({kSizingOutputPinStress, int(l.pin_stress()), int(l.samples)});
    if (l.bearing_rows) b.push_back({kSizingCrankBearing, int(l.bearing()), int(l.samples)});
    if (l.output) b.push_back({kSizingOutputHoles, int(l.holes()), 1});
    if (l.efficiency_row) b.push_back({kSizingEfficiency, int(l.efficiency()), 1});
    if (l.temperature_row) b.push_back({kSizingOilTemperature, int(l.temperature()), 1});
    return b;
  }
  void Fill(const CycloidSizingEvaluation& e, std::span<double> y) const {
    const Layout& l = layout_;
    const CycloidSizeObjective objective = model_.spec().objective;
    y[0] = objective == CycloidSizeObjective::kVolume      ? e.volume_mm3
           : objective == CycloidSizeObjective::kPowerLoss ? e.power_loss_W
                                                           : e.outer_diameter_mm;
    // No thermal equilibrium (or no contact): a loss far beyond any design's for SLSQP's line search.
    if (outside_ == OutsideDomain::kPenalty && objective == CycloidSizeObjective::kPowerLoss && !std::isfinite(y[0]))
      y[0] = 1e3 * OutputPowerW(model_.spec());
    for (size_t s = 0; s < l.na * l.n1; ++s) y[l.peaks() + s] = e.pair_peak_MPa[s];
    if (l.over)
      for (size_t k = 0; k < l.na; ++k) y[l.ends() + k] = e.end_distance_um[k];
    for (size_t k = 0; k < l.na; ++k) y[l.backlash() + k] = e.unloaded_te_arcsec[k];
    y[l.lte()] = e.lte_peak_to_peak_arcsec;
    y[l.curtate()] = e.curtate_margin;
    y[l.undercut()] = e.undercut_margin_mm;
    y[l.pin_gap()] = e.pin_gap_margin_mm;
    if (l.web) y[l.web_row()] = e.web_margin_mm;
    for (size_t r = 0; r < 2; ++r) y[l.fit() + r] = e.crowning_fit_mm[r];
    for (size_t r = 0; r < l.lives; ++r) y[l.life() + r] = e.life_margin[r];
    for (size_t r = 0; r < l.static_rows; ++r) y[l.statics() + r] = e.static_utilisation[r];
    if (l.stiffness_row) y[l.stiffness()] = e.stiffness_Nm_per_arcmin;
    if (l.lost_motion_row) y[l.lost_motion()] = e.lost_motion_arcmin;
    for (size_t r = 0; l.pin_stress_rows && r < l.samples; ++r) y[l.pin_stress() + r] = e.output_pin_stress_MPa[r];
    for (size_t r = 0; l.bearing_rows && r < l.samples; ++r) y[l.bearing() + r] = e.crank_bearing_load_N[r];
    if (l.output) y[l.holes()] = e.output_holes_margin_mm;
    if (l.efficiency_row) y[l.efficiency()] = e.efficiency;
    if (l.temperature_row) y[l.temperature()] = e.oil_temperature_C;
    // No thermal equilibrium below the oil's limit: as hot as the limit and no efficiency.
    if (outside_ == OutsideDomain::kPenalty && model_.spec().lubrication && !std::isfinite(e.efficiency)) {
      if (l.efficiency_row) y[l.efficiency()] = 0.0;
      if (l.temperature_row) y[l.temperature()] = model_.spec().lubrication->balance_limit_C + 100.0;
    }
    if (outside_ == OutsideDomain::kPenalty && !std::isfinite(e.stress_MPa)) {
      if (l.stiffness_row) y[l.stiffness()] = -1e6;
      if (l.lost_motion_row) y[l.lost_motion()] = 1e6;
      for (size_t r = 0; l.pin_stress_rows && r < l.samples; ++r) y[l.pin_stress() + r] = 1e9;
      for (size_t r = 0; l.bearing_rows && r < l.samples; ++r) y[l.bearing() + r] = 1e9;
      for (size_t r = 0; r < l.lives; ++r) y[l.life() + r] = -100.0;  // e^-100 of the required life
      for (size_t r = 0; r < l.static_rows; ++r) y[l.statics() + r] = 1e6;
      for (size_t s = 0; s < l.na * l.n1; ++s) y[l.peaks() + s] = 1e6;
      if (l.over)
        for (size_t k = 0; k < l.na; ++k) y[l.ends() + k] = -1e4;
      for (size_t k = 0; k < l.na; ++k) y[l.backlash() + k] = -1e4;
      y[l.lte()] = 1e6;
    }
  }
  const CycloidSizingEvaluation& Get(std::span<const double> x, bool gradient) const {
    const std::vector<double> key(x.begin(), x.end());
    return memory_.Get(
        key, [&](const CycloidSizingEvaluation& m) { return !gradient || !m.d_objective.empty() || key.empty(); },
        [&] { return model_.Evaluate(key, gradient); });
  }

  CycloidSizingModel& model_;
  Layout layout_;
  mutable EvaluationMemo<CycloidSizingEvaluation> memory_;
  OutsideDomain outside_;
};

}  // namespace

Problem CycloidSizingProblem(CycloidSizingModel& model, const CycloidFastLimits& fast,
                             std::function<void(const CycloidSizingEvaluation&)> on_evaluation,
                             OutsideDomain outside) {
  const CycloidSizingSpec& s = model.spec();
  Problem p;
  p.variables = s.variables;
  p.evaluator = std::make_unique<SizingEvaluator>(model, std::move(on_evaluation), outside);
  const bool volume = s.objective == CycloidSizeObjective::kVolume;
  p.objective = ObjectiveName(s.objective);
  const double outer = s.drive.roller_position_radius_mm + s.drive.roller_radius_mm;
  p.objective_scale = s.objective == CycloidSizeObjective::kPowerLoss ? 0.05 * OutputPowerW(s)  // 5% of the power
                      : volume ? kPi * outer * outer * s.drive.face_width_mm
                               : 2.0 * outer;
  const double stress_scale = std::isfinite(fast.contact_stress_MPa) ? fast.contact_stress_MPa : 1000.0;
  p.constraints.push_back({kSizingPeakPressure, -kInf, fast.contact_stress_MPa, stress_scale});
  if (s.overload_torque_Nmm > 0) p.constraints.push_back({kSizingEndDistance, fast.min_edge_margin_um, kInf, 100.0});
  p.constraints.push_back({kSizingBacklash, fast.min_backlash_arcsec, fast.max_backlash_arcsec, 10.0});
  if (std::isfinite(s.limits.max_lte_peak_to_peak_arcsec))
    p.constraints.push_back({kSizingLte, -kInf, s.limits.max_lte_peak_to_peak_arcsec, 10.0});
  p.constraints.push_back({kSizingCurtate, s.limits.min_curtate_margin, kInf, 0.1});
  p.constraints.push_back({kSizingUndercut, 0.0, kInf, 1.0});
  p.constraints.push_back({kSizingPinGap, 0.0, kInf, 1.0});
  if (s.limits.bore_radius_mm > 0) p.constraints.push_back({kSizingWeb, 0.0, kInf, 1.0});
  p.constraints.push_back({kSizingCrowningFit, 0.0, kInf, 1.0});
  if (s.life && s.limits.life_h > 0)  // ln(L10h / life_h) >= ln(fast life / life_h): O(1) over decades
    p.constraints.push_back({kSizingLife, std::log(std::max(fast.life_h, s.limits.life_h) / s.limits.life_h), kInf, 1.0});
  if (StaticRows(s))  // P/C0 <= 1/s0 at every sample: order one
    p.constraints.push_back({kSizingStatic, -kInf, 1.0 / std::max(fast.min_static_safety, s.limits.min_static_safety),
                             1.0 / s.limits.min_static_safety});
  if (s.output) {
    const CycloidSizingLimits& l = s.limits;
    if (l.min_torsional_stiffness_Nm_per_arcmin > 0)
      p.constraints.push_back({kSizingStiffness, fast.min_torsional_stiffness_Nm_per_arcmin, kInf,
                               l.min_torsional_stiffness_Nm_per_arcmin});
    if (std::isfinite(l.max_lost_motion_arcmin))
      p.constraints.push_back({kSizingLostMotion, -kInf, fast.max_lost_motion_arcmin, l.max_lost_motion_arcmin});
    if (std::isfinite(l.output_pin_stress_MPa))
      p.constraints.push_back({kSizingOutputPinStress, -kInf, fast.output_pin_stress_MPa, l.output_pin_stress_MPa});
    if (std::isfinite(l.eccentric_bearing_load_N))
      p.constraints.push_back({kSizingCrankBearing, -kInf, fast.eccentric_bearing_load_N, l.eccentric_bearing_load_N});
    p.constraints.push_back({kSizingOutputHoles, 0.0, kInf, 1.0});
  }
  if (s.lubrication && s.limits.min_efficiency > 0)  // scaled by the loss's share 1 − η
    p.constraints.push_back({kSizingEfficiency, fast.min_efficiency, kInf, std::max(0.01 * (1.0 - s.limits.min_efficiency), 1e-4)});
  if (s.lubrication && !s.lubrication->temperature_C && std::isfinite(s.limits.max_oil_temperature_C))
    p.constraints.push_back({kSizingOilTemperature, -kInf, fast.max_oil_temperature_C, 10.0});
  return p;
}

CycloidAccurateCheck CheckCycloidDesign(const CycloidSizingSpec& spec, const cycloid::Drive& drive,
                                        const cycloid::Crowning& crowning) {
  CycloidAccurateCheck out;
  CycloidSizingSpec fixed = spec;
  fixed.drive = drive;
  fixed.crowning = crowning;
  fixed.variables.clear();
  out.fast = CycloidSizingModel(fixed).Evaluate({}, false);
  CycloidSizingSpec fine = fixed;
  fine.options.profile_cells *= 2;
  fine.options.axial_cells *= 2;
  fine.angles_per_period *= 2;
  out.accurate = CycloidSizingModel(fine).Evaluate({}, false);
  const CycloidSizingEvaluation &f = out.fast, &a = out.accurate;
  auto min_of = [](const std::vector<double>& v) { return v.empty() ? kInf : *std::min_element(v.begin(), v.end()); };
  auto max_of = [](const std::vector<double>& v) { return v.empty() ? -kInf : *std::max_element(v.begin(), v.end()); };
  out.stress_error_MPa = std::abs(a.stress_MPa - f.stress_MPa);
  out.edge_margin_error_um = std::isfinite(a.edge_margin_um) ? std::abs(a.edge_margin_um - f.edge_margin_um) : 0.0;
  // β0 comes from a Newton solve closed to 1e-12 rad (unloaded_tca.h, 2e-7″), and an optimizer
  // that drives Δa, Δρ to a full tooth leaves it a little below its bound (its constraint
  // tolerance). The resolution taken: 1e-3″ (4.8e-9 rad: 0.5 nm of play at a 100 mm pin circle),
  // zero backlash for any purpose, and the verified loop's own slack for a limit of 0.
  constexpr double kUnloadedTeResolutionArcsec = 1e-3;
  out.backlash_error_arcsec = std::max({std::abs(min_of(a.unloaded_te_arcsec) - min_of(f.unloaded_te_arcsec)),
                                        std::abs(max_of(a.unloaded_te_arcsec) - max_of(f.unloaded_te_arcsec)),
                                        kUnloadedTeResolutionArcsec});
  out.lte_error_arcsec = std::abs(a.lte_peak_to_peak_arcsec - f.lte_peak_to_peak_arcsec);
  if (spec.life) out.life_error_h = std::abs(a.shortest_life_h - f.shortest_life_h);
  if (StaticRows(spec)) out.static_safety_error = std::abs(a.min_static_safety - f.min_static_safety);
  if (spec.output) {
    out.stiffness_error = std::abs(a.stiffness_Nm_per_arcmin - f.stiffness_Nm_per_arcmin);
    out.lost_motion_error_arcmin = std::abs(a.lost_motion_arcmin - f.lost_motion_arcmin);
    out.output_pin_stress_error_MPa = std::abs(a.max_output_pin_stress_MPa - f.max_output_pin_stress_MPa);
    out.crank_bearing_error_N = std::abs(a.max_crank_bearing_load_N - f.max_crank_bearing_load_N);
  }
  if (spec.lubrication) {
    out.efficiency_error = std::abs(a.efficiency - f.efficiency);
    out.oil_temperature_error_C = std::abs(a.oil_temperature_C - f.oil_temperature_C);
  }
  std::ostringstream m;
  m << "3D half-space LTCA on " << fine.options.profile_cells << " x " << fine.options.axial_cells
    << " cells per pair at " << fine.angles_per_period << " crank angles per mesh period; each value's error "
    << "is its change from " << spec.options.profile_cells << " x " << spec.options.axial_cells << " cells at "
    << spec.angles_per_period << " angles";
  out.model = m.str();
  const CycloidSizingLimits& l = spec.limits;
  auto add = [&](const std::string& limit, const std::string& where, double limit_value, double accurate,
                 double error, double fast, bool upper) {
    VerifiedLimit c;
    c.limit = limit;
    c.where = where;
    c.limit_value = limit_value;
    c.accurate_value = accurate;
    c.estimated_error = error;
    c.fast_value = fast;
    c.upper = upper;
    out.checks.push_back(c);
  };
  if (std::isfinite(l.contact_stress_MPa))
    add("contact_stress_MPa", "design torque", l.contact_stress_MPa, a.stress_MPa, out.stress_error_MPa, f.stress_MPa,
        true);
  if (spec.overload_torque_Nmm > 0)
    add("min_edge_margin_um", "overload torque", l.min_edge_margin_um, a.edge_margin_um, out.edge_margin_error_um,
        f.edge_margin_um, false);
  add("min_backlash_arcsec", "unloaded, every crank angle", l.min_backlash_arcsec, min_of(a.unloaded_te_arcsec),
      out.backlash_error_arcsec, min_of(f.unloaded_te_arcsec), false);
  if (std::isfinite(l.max_backlash_arcsec))
    add("max_backlash_arcsec", "unloaded, every crank angle", l.max_backlash_arcsec, max_of(a.unloaded_te_arcsec),
        out.backlash_error_arcsec, max_of(f.unloaded_te_arcsec), true);
  if (std::isfinite(l.max_lte_peak_to_peak_arcsec))
    add("max_lte_peak_to_peak_arcsec", "design torque", l.max_lte_peak_to_peak_arcsec, a.lte_peak_to_peak_arcsec,
        out.lte_error_arcsec, f.lte_peak_to_peak_arcsec, true);
  if (spec.life && l.life_h > 0)
    add("life_h", "shortest L10h over the duty cycle", l.life_h, a.shortest_life_h, out.life_error_h, f.shortest_life_h,
        false);
  if (StaticRows(spec))
    add("min_static_safety", "s0 at the momentary torque (crank bearing, pins with C0)", l.min_static_safety,
        a.min_static_safety, out.static_safety_error, f.min_static_safety, false);
  if (spec.output) {
    if (l.min_torsional_stiffness_Nm_per_arcmin > 0)
      add("min_torsional_stiffness_Nm_per_arcmin", "crank 0, 50-100% of the design torque",
          l.min_torsional_stiffness_Nm_per_arcmin, a.stiffness_Nm_per_arcmin, out.stiffness_error,
          f.stiffness_Nm_per_arcmin, false);
    if (std::isfinite(l.max_lost_motion_arcmin))
      add("max_lost_motion_arcmin", "crank 0, +-3% of the design torque", l.max_lost_motion_arcmin,
          a.lost_motion_arcmin, out.lost_motion_error_arcmin, f.lost_motion_arcmin, true);
    if (std::isfinite(l.output_pin_stress_MPa))
      add("output_pin_stress_MPa", "design torque, the output pins' load period", l.output_pin_stress_MPa,
          a.max_output_pin_stress_MPa, out.output_pin_stress_error_MPa, f.max_output_pin_stress_MPa, true);
    if (std::isfinite(l.eccentric_bearing_load_N))
      add("eccentric_bearing_load_N", "design torque, the output pins' load period", l.eccentric_bearing_load_N,
          a.max_crank_bearing_load_N, out.crank_bearing_error_N, f.max_crank_bearing_load_N, true);
    add("output_holes_fit_mm", "holes inside the root circle", 0.0, a.output_holes_margin_mm, 0.0,
        f.output_holes_margin_mm, false);
  }
  if (spec.lubrication && l.min_efficiency > 0)
    add("min_efficiency", "design torque at the input speed, a revolution's mean", l.min_efficiency, a.efficiency,
        out.efficiency_error, f.efficiency, false);
  if (spec.lubrication && !spec.lubrication->temperature_C && std::isfinite(l.max_oil_temperature_C))
    add("max_oil_temperature_C", "the housing's balance at the design torque", l.max_oil_temperature_C,
        a.oil_temperature_C, out.oil_temperature_error_C, f.oil_temperature_C, true);
  // Closed forms: exact, no discretisation.
  add("min_curtate_margin", "generating curve", l.min_curtate_margin, a.curtate_margin, 0.0, f.curtate_margin, false);
  add("min_profile_radius_mm", "tooth profile", l.min_profile_radius_mm, a.min_profile_radius_mm, 0.0,
      f.min_profile_radius_mm, false);
  add("min_pin_gap_mm", "neighbouring pins", l.min_pin_gap_mm, a.pin_gap_margin_mm + l.min_pin_gap_mm, 0.0,
      f.pin_gap_margin_mm + l.min_pin_gap_mm, false);
  if (l.bore_radius_mm > 0)
    add("min_web_mm", "disc web", l.min_web_mm, a.web_margin_mm + l.min_web_mm, 0.0, f.web_margin_mm + l.min_web_mm,
        false);
  return out;
}

namespace {

// Starting points: the variables' own, then points across the box (fractions of each range),
// each pulled towards the first along the segment between them (halving) until it lies inside
// the model's domain (a NaN at its start stops Ipopt).
std::vector<std::vector<double>> Starts(const CycloidSizingModel& model, int count) {
  const CycloidSizingSpec& s = model.spec();
  auto inside = [&](const std::vector<double>& x) {
    const auto [d, c] = model.Design(x);
    return cycloid::CheckDrive(d).empty() && cycloid::CheckCrowning(c, d.face_width_mm).empty();
  };
  std::vector<std::vector<double>> starts;
  std::vector<double> x0;
  for (const Variable& v : s.variables) x0.push_back(std::clamp(v.initial, v.lower, v.upper));
  starts.push_back(x0);
  const double fractions[] = {0.75, 0.25, 0.5, 0.9, 0.1};
  for (int k = 1; k < count && k <= 5; ++k) {
    std::vector<double> x;
    for (const Variable& v : s.variables)
      x.push_back(std::isfinite(v.lower) && std::isfinite(v.upper) ? v.lower + fractions[k - 1] * (v.upper - v.lower)
                                                                   : v.initial);
    for (int halving = 0; halving < 30 && !inside(x) && inside(x0); ++halving)
      for (size_t j = 0; j < x.size(); ++j) x[j] = 0.5 * (x[j] + x0[j]);
    starts.push_back(x);
  }
  return starts;
}

// The limit key of a constraint row (its block name) and whether the row sits at its lower bound.
std::string LimitKeyOf(const std::string& block, bool at_lower) {
  if (block == kSizingPeakPressure) return "contact_stress_MPa";
  if (block == kSizingEndDistance) return "min_edge_margin_um";
  if (block == kSizingBacklash) return at_lower ? "min_backlash_arcsec" : "max_backlash_arcsec";
  if (block == kSizingLte) return "max_lte_peak_to_peak_arcsec";
  if (block == kSizingCurtate) return "min_curtate_margin";
  if (block == kSizingUndercut) return "min_profile_radius_mm";
  if (block == kSizingPinGap) return "min_pin_gap_mm";
  if (block == kSizingWeb) return "min_web_mm";
  if (block == kSizingCrowningFit) return "crowning_on_the_face";
  if (block == kSizingLife) return "life_h";
  if (block == kSizingStatic) return "min_static_safety";
  if (block == kSizingStiffness) return "min_torsional_stiffness_Nm_per_arcmin";
  if (block == kSizingLostMotion) return "max_lost_motion_arcmin";
  if (block == kSizingOutputPinStress) return "output_pin_stress_MPa";
  if (block == kSizingCrankBearing) return "eccentric_bearing_load_N";
  if (block == kSizingOutputHoles) return "output_holes_fit_mm";
  if (block == kSizingEfficiency) return "min_efficiency";
  if (block == kSizingOilTemperature) return "max_oil_temperature_C";
  return block;
}

// d(objective)/d(limit) at x from the KKT conditions of min f subject to the rows: with the
// multipliers λ >= 0 of the active rows and bounds, ∇f = Σ −λ_i ∇g_i over rows at their upper
// bound (and variables at theirs) + Σ λ_i ∇g_i over rows at their lower bound, solved for λ >= 0
// in the least-squares sense (in the solver's scaled variables). The optimum moves by −λ_i per unit
// of an upper bound and by +λ_i per unit of a lower one; the rows of one limit add up. A row counts
// as active within 1e-3 of its scale; where the multipliers then leave the stationarity residual
// above 1e-2 (a row the solver left a little short of its bound, which the fit needs), the active
// set is widened to 1e-2 and 3e-2 of the scales, and the fit with the smallest residual is kept
// (`residual` says how well it holds: the paper drive's end-distance row sits 0.3% short of its
// bound; without it the stress row's multiplier came out half the re-solve slope).
std::map<std::string, double> LimitCosts(const Problem& p, const std::vector<double>& x, double& residual,
                                         std::optional<optimizers::FirstOrderCheck>& answer) {
  std::map<std::string, double> out;
  residual = std::numeric_limits<double>::quiet_NaN();
  if (p.num_vars() == 0) return out;
  std::optional<optimizers::FirstOrderCheck> best;
  for (const double tolerance : {1e-3, 1e-2, 3e-2}) {
    optimizers::FirstOrderCheck kkt = optimizers::CheckFirstOrder(p, x, tolerance);
    if (!kkt.finite || !kkt.any_row) continue;
    if (!best || kkt.residual < best->residual) best = std::move(kkt);
    if (best->residual <= 1e-2) break;
  }
  if (!best) return out;
  residual = best->residual;
  for (const optimizers::FirstOrderCheck::Active& a : best->active)
    if (a.output_index >= 0)
      out[LimitKeyOf(a.name.substr(0, a.name.find('[')), a.at_lower)] += (a.at_lower ? 1.0 : -1.0) * a.multiplier;
  answer = std::move(best);
  return out;
}

// The Ipopt fallback of a limit-cost re-solve: at most this many model runs (and its SLSQP polish
// half as many evaluations).
constexpr int kReSolveModelRuns = 120;

// A limit key's field in the study's limits and the fast limit that follows it (nullptr: the
// closed forms and the LTE, exact or report-only, have none).
struct LimitField {
  const char* key;
  double CycloidSizingLimits::*study;
  double CycloidFastLimits::*fast;
};
constexpr LimitField kLimitFields[] = {
    {"contact_stress_MPa", &CycloidSizingLimits::contact_stress_MPa, &CycloidFastLimits::contact_stress_MPa},
    {"min_edge_margin_um", &CycloidSizingLimits::min_edge_margin_um, &CycloidFastLimits::min_edge_margin_um},
    {"min_backlash_arcsec", &CycloidSizingLimits::min_backlash_arcsec, &CycloidFastLimits::min_backlash_arcsec},
    {"max_backlash_arcsec", &CycloidSizingLimits::max_backlash_arcsec, &CycloidFastLimits::max_backlash_arcsec},
    {"max_lte_peak_to_peak_arcsec", &CycloidSizingLimits::max_lte_peak_to_peak_arcsec, nullptr},
    {"min_curtate_margin", &CycloidSizingLimits::min_curtate_margin, nullptr},
    {"min_profile_radius_mm", &CycloidSizingLimits::min_profile_radius_mm, nullptr},
    {"min_pin_gap_mm", &CycloidSizingLimits::min_pin_gap_mm, nullptr},
    {"min_web_mm", &CycloidSizingLimits::min_web_mm, nullptr},
    {"life_h", &CycloidSizingLimits::life_h, &CycloidFastLimits::life_h},
    {"min_static_safety", &CycloidSizingLimits::min_static_safety, &CycloidFastLimits::min_static_safety},
    {"min_torsional_stiffness_Nm_per_arcmin", &CycloidSizingLimits::min_torsional_stiffness_Nm_per_arcmin,
     &CycloidFastLimits::min_torsional_stiffness_Nm_per_arcmin},
    {"max_lost_motion_arcmin", &CycloidSizingLimits::max_lost_motion_arcmin, &CycloidFastLimits::max_lost_motion_arcmin},
    {"output_pin_stress_MPa", &CycloidSizingLimits::output_pin_stress_MPa, &CycloidFastLimits::output_pin_stress_MPa},
    {"eccentric_bearing_load_N", &CycloidSizingLimits::eccentric_bearing_load_N,
     &CycloidFastLimits::eccentric_bearing_load_N},
    {"min_efficiency", &CycloidSizingLimits::min_efficiency, &CycloidFastLimits::min_efficiency},
    {"max_oil_temperature_C", &CycloidSizingLimits::max_oil_temperature_C, &CycloidFastLimits::max_oil_temperature_C},
};
const LimitField* FindLimitField(const std::string& key) {
  for (const LimitField& f : kLimitFields)
    if (key == f.key) return &f;
  return nullptr;
}
double* StudyLimitOf(CycloidSizingLimits& l, const std::string& key) {
  const LimitField* f = FindLimitField(key);
  return f ? &(l.*(f->study)) : nullptr;
}
double* FastLimitOf(CycloidFastLimits& l, const std::string& key) {
  const LimitField* f = FindLimitField(key);
  return f && f->fast ? &(l.*(f->fast)) : nullptr;
}
// The step of a limit's re-solves: 1% of its value, or for a limit of 0 (a margin, a gap) a small
// amount in its own unit.
double LimitStep(const std::string& key, double value) {
  if (key == "min_efficiency") return 0.01 * (1.0 - value);  // 1% of the loss's share
  if (value != 0) return 0.01 * std::abs(value);
  if (key == "min_edge_margin_um" || key == "min_backlash_arcsec") return 0.1;
  if (key == "min_curtate_margin") return 1e-3;
  return 1e-3;  // mm: a profile radius, pin gap or web
}

}  // namespace

CycloidMinSizeOutcome SolveCycloidMinSize(const CycloidSizingSpec& spec, const CycloidMinSizeOptions& options) {
  CycloidMinSizeOutcome out;
  CycloidSizingModel model(spec);
  CycloidFastLimits fast;
  fast.contact_stress_MPa = spec.limits.contact_stress_MPa;
  fast.min_edge_margin_um = spec.limits.min_edge_margin_um;
  fast.min_backlash_arcsec = spec.limits.min_backlash_arcsec;
  fast.max_backlash_arcsec = spec.limits.max_backlash_arcsec;
  fast.life_h = spec.limits.life_h;
  fast.min_static_safety = spec.limits.min_static_safety;
  fast.min_torsional_stiffness_Nm_per_arcmin = spec.limits.min_torsional_stiffness_Nm_per_arcmin;
  fast.max_lost_motion_arcmin = spec.limits.max_lost_motion_arcmin;
  fast.output_pin_stress_MPa = spec.limits.output_pin_stress_MPa;
  fast.eccentric_bearing_load_N = spec.limits.eccentric_bearing_load_N;
  fast.min_efficiency = spec.limits.min_efficiency;
  fast.max_oil_temperature_C = spec.limits.max_oil_temperature_C;
  if (options.fast_start) fast = *options.fast_start;
  out.verification.max_rounds = options.verify_rounds;
  const int starts = std::max(1, options.starts);
  const double steps = double(starts + options.verify_rounds + 1);
  auto progress = [&](double done, const std::string& stage) {
    if (options.progress) options.progress(std::min(1.0, done / steps), stage);
  };
  const OutsideDomain outside = options.solver.backend == optimizers::Backend::kIpopt ? OutsideDomain::kNaN : OutsideDomain::kPenalty;

  // One round of solves with the current fast limits: round 0 from every start, later rounds from
  // the last design. The smallest converged end point (else the first with a design) is kept.
  auto solve_round = [&](int round) {
    Problem problem = CycloidSizingProblem(model, fast, nullptr, outside);
    optimizers::SolverResult best;
    bool have = false;
    const bool ipopt_backend = options.solver.backend == optimizers::Backend::kIpopt;
    const std::vector<std::vector<double>> points =
        round == 0 ? Starts(model, starts) : std::vector<std::vector<double>>{out.x};
    for (size_t s = 0; s < points.size(); ++s) {
      progress(round == 0 ? double(s) : double(starts + round - 1),
               round == 0 ? "start " + std::to_string(s + 1) + " of " + std::to_string(points.size())
                          : "verification round " + std::to_string(round));
      optimizers::SolverOptions so = options.solver;
      so.initial = points[s];
      // Ipopt may cycle on the kinks of the rows (a peak cell or a loaded pair switching) until its
      // iteration limit: SLSQP polishes its last point then (as the LCR sizing does).
      if (ipopt_backend && !so.fallback_backend) so.fallback_backend = optimizers::Backend::kSlsqp;
      optimizers::SolverResult r = optimizers::Solve(problem, so);
      out.evaluations += r.value_evaluations;
      out.gradient_evaluations += r.gradient_evaluations;
      if (round == 0) out.starts.push_back(r);
      const bool better = r.ok() && (!have || !best.ok() || r.objective < best.objective);
      const bool first = !have && !r.x.empty();
      if (better || first) {
        best = r;
        have = true;
      }
    }
    // Ipopt's answer is a stall point of its acceptable test (the size settled within
    // stall_change, the rows within stall_violation): SLSQP from it settles the active set to the
    // solver's tolerances, so the design and the multipliers of its limit costs are a KKT point's
    // (SLSQP takes a start as it is; Ipopt's barrier would push it back inside first).
    if (have && best.ok() && ipopt_backend) {
      optimizers::SolverOptions polish = options.solver;
      polish.backend = optimizers::Backend::kSlsqp;
      polish.fallback_backend.reset();
      polish.initial = best.x;
      optimizers::SolverResult p = optimizers::Solve(problem, polish);
      out.evaluations += p.value_evaluations;
      out.gradient_evaluations += p.gradient_evaluations;
      const double settled = std::max(options.solver.stall_change, options.solver.tolerance) * std::max(std::abs(best.objective), 1.0);
      if (p.ok() && p.objective <= best.objective + settled) {
        p.message = best.message + "; slsqp polished its stall point: " + p.message;
        p.value_evaluations += best.value_evaluations;
        p.gradient_evaluations += best.gradient_evaluations;
        p.iterations += best.iterations;
        best = p;
      }
    }
    out.result = best;
    if (!have) return false;
    out.converged = best.ok();
    out.x = best.x;
    std::tie(out.drive, out.crowning) = model.Design(best.x);
    return true;
  };
  auto check = [&](int round) {
    progress(double(starts + round), "verifying");
    const auto t0 = Clock::now();
    out.check = CheckCycloidDesign(spec, out.drive, out.crowning);
    out.verification_seconds += Seconds(t0);
    out.verification.accurate_model = out.check.model;
    out.verification.checks = out.check.checks;
    out.verification.ran = true;
  };
  // The loop aims at the accurate value itself within the limit (0.1% slack), not only within the
  // limit plus its estimated error: a peak that grows with refinement (a straight tooth's edge) has
  // a large error that would otherwise pass a design the accurate model puts above it.
  // The life (a smooth integral of the loads, its error small) is tightened whenever it does not
  // hold within its error, not only beyond the slack.
  auto beyond = [](const VerifiedLimit& c) {
    const double slack = 1e-3 * std::max(std::abs(c.limit_value), 1.0);
    if ((c.limit == "life_h" || c.limit == "min_efficiency" || c.limit == "max_oil_temperature_C") && !c.holds())
      return true;
    // The output rows: the pins' stress is exact on both models at a sample they share (error 0),
    // so a row the solver leaves a constraint tolerance beyond its limit is tightened too; the
    // static rows' s0 (its error small, as the crank bearing's load over the cycle) likewise.
    if ((c.limit == "output_pin_stress_MPa" || c.limit == "eccentric_bearing_load_N" ||
         c.limit == "max_lost_motion_arcmin" || c.limit == "min_torsional_stiffness_Nm_per_arcmin" ||
         c.limit == "min_static_safety") &&
        !c.holds())
      return true;
    return !std::isfinite(c.accurate_value) ||
           (c.upper ? c.accurate_value > c.limit_value + slack : c.accurate_value < c.limit_value - slack);
  };
  auto fast_limit = [&](const VerifiedLimit& c) -> double* { return FastLimitOf(fast, c.limit); };
  // The verification of the solved design: check; while a tightenable limit is beyond, tighten
  // its fast limit, solve again from the last design and check again.
  auto verify = [&] {
    for (int round = 0;; ++round) {
      check(round);
      bool aim = true;
      for (const VerifiedLimit& c : out.check.checks) aim = aim && !(fast_limit(c) && beyond(c));
      if ((out.verification.verified() && aim) || round >= options.verify_rounds || !out.result.ok()) return;
      bool moved = false;
      for (const VerifiedLimit& c : out.check.checks) {
        double* fl = fast_limit(c);
        if (!fl || !beyond(c)) continue;
        TighteningStep step;
        step.round = round + 1;
        step.limit = c.limit;
        step.where = c.where;
        step.accurate_value = c.accurate_value;
        step.limit_value = c.limit_value;
        step.fast_limit_before = *fl;
        const double miss = c.upper ? c.accurate_value - c.limit_value : c.limit_value - c.accurate_value;
        if (c.limit == "contact_stress_MPa" || c.limit == "output_pin_stress_MPa" ||
            c.limit == "eccentric_bearing_load_N" || c.limit == "max_lost_motion_arcmin")
          *fl = TightenedUpperLimit(*fl, c.limit_value, c.fast_value, c.accurate_value);
        else if (c.limit == "min_torsional_stiffness_Nm_per_arcmin" || c.limit == "min_static_safety")
          *fl = TightenedLowerLimit(*fl, c.limit_value, c.fast_value, c.accurate_value);
        else if (c.limit == "life_h")  // by the accurate shortfall, 1.5 times, and 0.1% more (as lcr_min_size)
          *fl *= std::pow(c.limit_value / std::max(c.accurate_value, 1e-9 * c.limit_value), 1.5) * 1.001;
        else if (c.limit == "min_efficiency" || c.limit == "max_oil_temperature_C")  // smooth: 1.5 times the miss
          *fl += (c.upper ? -1.5 : 1.5) * (std::isfinite(miss) ? miss : 0.1 * std::abs(c.limit_value));
        else if (c.upper)
          *fl -= miss + 0.02 * std::max(std::abs(c.limit_value), 1.0);
        else
          *fl += miss + 0.02 * std::max(std::abs(c.limit_value), 1.0);
        step.fast_limit_after = *fl;
        out.verification.history.push_back(step);
        moved = true;
      }
      if (!moved) return;
      if (!solve_round(round + 1)) {
        out.verification.ran = false;
        return;
      }
    }
  };

  // The sizing driver (sizing/sizing_driver.h) with one candidate: the tooth count is given.
  SizingCandidates loop;
  loop.count = 1;
  loop.label = [&](int) { return std::to_string(spec.drive.teeth) + " teeth"; };
  bool solved = false;
  loop.solve = [&](int) { solved = solve_round(0); };
  loop.feasible_size = [&](int) -> std::optional<double> {
    if (!solved || !out.converged || out.x.empty()) return std::nullopt;
    if (out.verification.ran && !out.verified) return std::nullopt;
    return out.result.objective;
  };
  loop.verify = [&](int) {
    verify();
    out.verified = out.verification.verified();
  };
  RunSizingDriver(loop);
  // A design that was solved but not feasible on the fast model is still checked: the study
  // reports the closest point with the accurate values.
  if (solved && !out.verification.ran && !out.x.empty()) check(0);
  out.verified = out.verification.verified();
  std::optional<optimizers::FirstOrderCheck> answer_kkt;  // the answer's active set and multipliers
  std::optional<Problem> answer;  // the answer's problem, from which each re-solve's start is predicted
  if (out.converged && !out.x.empty()) {
    answer.emplace(CycloidSizingProblem(model, fast, nullptr, outside));
    out.limit_cost = LimitCosts(*answer, out.x, out.limit_cost_residual, answer_kkt);
    // The life row's bound is ln(fast life / life_h): its multiplier is per unit of ln, d/dH = 1/H.
    if (auto it = out.limit_cost.find("life_h"); it != out.limit_cost.end()) it->second /= fast.life_h;
    // The static rows' bound is 1/s0: d/ds0 = −1/s0² of the multiplier per unit of that bound.
    if (auto it = out.limit_cost.find("min_static_safety"); it != out.limit_cost.end())
      it->second *= -1.0 / (fast.min_static_safety * fast.min_static_safety);
  }
  // Each binding limit re-solved at L ± h from the answer, with the fast limits it ended with moved
  // alike (by the same ratio for a limit of a positive quantity, by h for a margin), verified and
  // tightened as the answer was; only a verified converged re-solve counts.
  if (options.re_solve_limit_costs && out.verified && out.converged) {
    const StageClock::Scope stage("limit costs");
    const double f0 = out.result.objective;
    const double tolerance = 10 * options.solver.tolerance * std::max(std::abs(f0), 1.0);
    for (const auto& [key, cost] : out.limit_cost) {
      CycloidSizingSpec base = spec;
      double* limit = StudyLimitOf(base.limits, key);
      if (!limit || !std::isfinite(*limit)) continue;
      for (size_t i = 0; i < base.variables.size() && i < out.x.size(); ++i) base.variables[i].initial = out.x[i];
      const double h = LimitStep(key, *limit);
      double f[2] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
      const LimitSense sense = key.rfind("min_", 0) == 0 || key == "life_h" ? LimitSense::kLower : LimitSense::kUpper;
      // The side that loosens the limit first (the answer stays feasible there); the other side
      // only when that one did not solve or its slope does not confirm the multiplier.
      const int order[2] = {sense == LimitSense::kLower ? 0 : 1, sense == LimitSense::kLower ? 1 : 0};
      bool confirmed = false;
      for (const int side : order) {
        if (side == order[1]) {
          const double one_sided = side == 1 ? (f0 - f[0]) / h : (f[1] - f0) / h;
          confirmed = ReSolveConfirmsMultiplier(one_sided, cost, h, tolerance, sense);
          if (confirmed) break;
        }
        const double d = side == 0 ? -h : h;
        CycloidSizingSpec moved = base;
        const double value = *StudyLimitOf(moved.limits, key);
        if (value + d < 0 && value >= 0 && key != "min_edge_margin_um") continue;  // a limit below 0 means nothing
        *StudyLimitOf(moved.limits, key) = value + d;
        CycloidFastLimits start = fast;
        if (double* fl = FastLimitOf(start, key))
          *fl = value != 0 && (key != "min_edge_margin_um" && key != "min_backlash_arcsec" && key != "max_backlash_arcsec")
                    ? *fl * (value + d) / value
                    : *fl + d;
        // The re-solve starts from the answer moved along its active set to the moved limit
        // (optimizers::PredictActiveSetStep): started at the answer itself SLSQP often stopped at
        // once on the corner of piecewise rows the answer sits on (the paper drive at 1322 MPa
        // stayed at 147.78 mm), and the Ipopt search that followed ended on another local optimum
        // now and then, so that the two sides' differences were no derivative.
        double predicted_change = 0;
        bool predicted = false;
        if (answer && answer_kkt) {
          CycloidSizingModel moved_model(moved);
          const Problem to = CycloidSizingProblem(moved_model, start, nullptr, OutsideDomain::kPenalty);
          const optimizers::ActiveSetPrediction step = optimizers::PredictActiveSetStep(*answer, to, out.x, *answer_kkt);
          if (step.finite) {
            for (size_t i = 0; i < moved.variables.size() && i < step.x.size(); ++i) moved.variables[i].initial = step.x[i];
            predicted_change = step.objective_change;
            predicted = true;
          }
        }
        CycloidMinSizeOptions again = options;
        again.starts = 1;
        // SLSQP from the predicted point: it takes a start as it is. A re-solve that stopped
        // short (most often a little outside an edge row, a minimum over pairs and cells with a
        // kink where the contact reaches the face end), or did not move the size although the
        // prediction did, is solved by Ipopt from the same start.
        again.solver.backend = optimizers::Backend::kSlsqp;
        again.solver.fallback_backend.reset();
        again.re_solve_limit_costs = false;
        again.fast_start = start;
        again.progress = nullptr;
        progress(steps, "limit cost of " + key + (side == 0 ? " (-)" : " (+)"));
        CycloidMinSizeOutcome r = SolveCycloidMinSize(moved, again);
        // Stayed: ended at the answer's size although its binding limit moved (and, from a
        // predicted start, although the prediction moved it).
        const bool stayed = std::abs(r.result.objective - f0) <= tolerance && (!predicted || std::abs(predicted_change) > tolerance);
        if (!(r.verified && r.converged) || stayed) {
          out.evaluations += r.evaluations;
          out.gradient_evaluations += r.gradient_evaluations;
          again.solver = options.solver;
          again.solver.backend = optimizers::Backend::kIpopt;
          again.solver.fallback_backend.reset();
          // Warm-started from the predicted point (a small fixed barrier, the start kept near its
          // bounds): Ipopt ends in 11-30 iterations there, against 53-89 with its defaults, which
          // push the start into the interior first (cycloid_min_size_ratio29.json's three
          // fallbacks). From the answer itself the same settings had moved the re-solved sizes
          // and slowed two examples (docs/performance.md). Where it ends at all it takes under 60
          // model runs; one that needs more than kReSolveModelRuns has left the answer's
          // neighbourhood (a tightened efficiency limit took 210 iterations and 1100 runs, 7-10 s,
          // to fail), and its side is reported missing instead.
          again.solver.barrier_initial = 1e-5;
          again.solver.bound_push = 1e-6;
          again.solver.max_model_runs = kReSolveModelRuns;
          again.solver.fallback_max_evaluations = std::min(again.solver.fallback_max_evaluations, kReSolveModelRuns / 2);
          CycloidMinSizeOutcome ipopt = SolveCycloidMinSize(moved, again);
          if ((ipopt.verified && ipopt.converged) || !(r.verified && r.converged)) r = std::move(ipopt);
        }
        out.evaluations += r.evaluations;
        out.gradient_evaluations += r.gradient_evaluations;
        if (r.verified && r.converged) f[side] = r.result.objective;
      }
      out.limit_slope[key] = SlopeFromReSolves(f[0], f0, f[1], h, tolerance, sense);
      out.limit_slope[key].confirms_multiplier = confirmed;
    }
  }
  out.value_seconds = model.value_seconds();
  out.gradient_seconds = model.gradient_seconds();
  progress(steps, "done");
  return out;
}

}  // namespace camopt::sizing
