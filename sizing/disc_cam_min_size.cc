#include "sizing/disc_cam_min_size.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <memory>
#include <span>
#include <stdexcept>

#include "model/common/roots.h"
#include "model/contact/hertz.h"
#include "sizing/sizing_driver.h"
#include "sizing/stage_clock.h"

namespace camopt::sizing {
using namespace camopt::objectives;
namespace {

namespace dc = camopt::disc_cam;
constexpr double kDeg = kPi / 180.0;
// The solvers meet the rows to about their constraint tolerance (1e-7 of each row's scale, the
// limit), so the fast limits start this share inside the study's, and each tightening adds it to
// the accurate excess: a solve that lands within its tolerance stays within the study's limit.
constexpr double kTightenMargin = 2e-7;
// A fast limit is moved back toward the study's when its accurate value lands further than this
// share of the limit inside it (an overshoot of an earlier round).
constexpr double kLandingTolerance = 1e-6;
// A limit binds when the accurate value is within this share of it (lengths: in mm).
constexpr double kBindingFraction = 1e-3;
// Relative move of a limit for its cost (central difference of re-solves).
constexpr double kCostStep = 5e-3;
// Peaks of the dense grid within this share of the largest are refined.
constexpr double kRefineShare = 0.01;

template <typename F>
std::pair<double, double> CycleMax(const std::vector<double>& v, double h, bool refine, const F& f) {
  return CircularMaxRefined(v, h, refine, kRefineShare, f);
}

// The fixed sample grid of the fast rows: angles and which samples rise (S' ≥ 0) or return.
struct Grid {
  std::vector<double> theta;
  std::vector<int> rise, ret;
  double s_min = 0.0, s_max = 0.0;  ///< the follower's range over the samples (oscillating: ξ − ξ₀)
};

Grid MakeGrid(const DiscCamSizingSpec& spec) {
  Grid g;
  const int n = spec.angle_steps;
  for (int i = 0; i < n; ++i) {
    const double th = 2 * kPi * i / n;
    g.theta.push_back(th);
    const motion::Svaj<double> m = spec.cam.motion.Evaluate(th);
    (m.v >= 0.0 ? g.rise : g.ret).push_back(i);
    g.s_min = std::min(g.s_min, m.s);
    g.s_max = std::max(g.s_max, m.s);
  }
  return g;
}

template <typename T>
void SetVariables(const DiscCamSizingSpec& spec, std::span<const T> x, dc::DiscCamTpl<T>& cam) {
  for (size_t k = 0; k < spec.which.size(); ++k) {
    switch (spec.which[k]) {
      case DiscCamSizingVariable::kBaseCircle: cam.base_radius = x[k]; break;
      case DiscCamSizingVariable::kOffset: cam.offset = x[k]; break;
      case DiscCamSizingVariable::kRollerRadius: cam.roller_radius = x[k]; break;
      case DiscCamSizingVariable::kPivotDistance: cam.pivot_distance = x[k]; break;
      case DiscCamSizingVariable::kArmLength: cam.arm_length = x[k]; break;
    }
  }
}

// Whether the follower touches the base circle and stays where the model holds: translating
// |e| < r_b + r_f; oscillating |f − l| < r_b + r_f < f + l (eq. 11's ξ₀ defined) and the arm within
// (0, π) from O₃O₂ over the cycle (ξ₀ + S on the samples' range [s_min, s_max]), as CheckDesign.
bool InsideGeometry(const dc::DiscCam& cam, const Grid& g, bool flat_face) {
  if (flat_face) return cam.base_radius > 0.0;  // ρ is defined for any r_b; the rows say the rest
  const double r0 = cam.base_radius + cam.roller_radius;
  if (!(r0 > 0.0 && cam.roller_radius >= 0.0)) return false;  // r_f = 0: a knife edge
  if (cam.follower == dc::FollowerType::kTranslatingRoller) return std::abs(cam.offset) < r0 * (1 - 1e-9);
  const double f = cam.pivot_distance, l = cam.arm_length;
  if (!(f > 0.0 && l > 0.0 && std::abs(f - l) < r0 * (1 - 1e-9) && r0 < (f + l) * (1 - 1e-9))) return false;
  const double xi0 = dc::InitialFollowerCoordinate(cam);
  return xi0 + g.s_min > 0.0 && xi0 + g.s_max < kPi;
}

// The kinetostatic contact force at a point: the translating follower's, or the oscillating arm's.
template <typename T>
T ContactForce(const DiscCamStressModel& m, const dc::CamPoint<T>& p) {
  if (m.arm) return dc::OscillatingRollerLoadAt(p, *m.arm, T(m.omega_rad_per_s)).contact_force;
  return dc::CamLoadAt(p, m.loads, T(m.omega_rad_per_s)).contact_force;
}

struct Context {
  DiscCamSizingSpec spec;
  DiscCamFastLimits fast;
  Grid grid;
  int rise_offset = 0, return_offset = 0, curvature_offset = 0, stress_offset = 0;
};

// The rows of the header comment at x, for double and for ceres::Jet.
template <typename T>
void EvalRows(const Context& c, std::span<const T> x, std::span<T> y) {
  using std::abs;
  const DiscCamSizingSpec& spec = c.spec;
  dc::DiscCamTpl<T> cam = dc::CastCam<T>(spec.cam);
  SetVariables(spec, x, cam);
  y[0] = cam.base_radius;
  const int n = int(c.grid.theta.size());
  dc::DiscCam values = spec.cam;
  {
    std::vector<double> xv(x.size());
    for (size_t k = 0; k < x.size(); ++k) xv[k] = Value(x[k]);
    SetVariables(spec, std::span<const double>(xv), values);
  }
  if (!InsideGeometry(values, c.grid, spec.flat_face)) {
    // Outside the geometry: finite rows far beyond their limits, zero derivatives.
    for (size_t k = 0; k < c.grid.rise.size(); ++k) y[size_t(c.rise_offset) + k] = T(90.0);
    for (size_t k = 0; k < c.grid.ret.size(); ++k) y[size_t(c.return_offset) + k] = T(90.0);
    for (int i = 0; i < n; ++i) y[size_t(c.curvature_offset + i)] = T(1e3);
    if (c.stress_offset > 0)
      for (int i = 0; i < n; ++i) y[size_t(c.stress_offset + i)] = T(1e6);
    return;
  }
  const T margin = (spec.limits.radius_margin_is_roller ? cam.roller_radius : T(spec.limits.radius_margin_mm)) +
                   T(spec.limits.radius_margin_shift_mm + c.fast.radius_margin_extra_mm);
  std::vector<T> phi(static_cast<size_t>(n));
  if (spec.flat_face) {
    // The translating flat face (model/disc_cam/flat_faced.h): φ = 0, ρ = r_b + S + S'' ≥ margin.
    const double scale = std::max(1.0, std::abs(Value(margin)));
    for (int i = 0; i < n; ++i) {
      const dc::FlatFacePoint<T> p = dc::EvaluateFlatFaced(cam.motion, cam.base_radius, T(c.grid.theta[size_t(i)]));
      phi[size_t(i)] = T(0.0);
      y[size_t(c.curvature_offset + i)] = T(1.0) + (margin - p.radius_of_curvature) / T(scale);
      if (c.stress_offset > 0) {
        const DiscCamStressModel& m = *spec.stress;
        const double s = c.fast.contact_stress_MPa;
        y[size_t(c.stress_offset + i)] =
            dc::FlatFaceLoadAt(p, m.loads, T(m.omega_rad_per_s)).contact_force *
                T(m.composite_modulus_MPa / (kPi * m.face_width_mm * s * s)) -
            p.radius_of_curvature;
      }
    }
  }
  for (int i = 0; i < n && !spec.flat_face; ++i) {
    const dc::CamPoint<T> p = dc::EvaluateCam(cam, T(c.grid.theta[size_t(i)]));
    phi[size_t(i)] = p.pressure_angle / T(kDeg);
    y[size_t(c.curvature_offset + i)] = p.pitch_curvature * (cam.roller_radius + margin);
    if (c.stress_offset > 0) {
      const DiscCamStressModel& m = *spec.stress;
      const double s = c.fast.contact_stress_MPa;
      y[size_t(c.stress_offset + i)] = ContactForce(m, p) * T(m.composite_modulus_MPa / (kPi * m.face_width_mm * s * s)) -
                                       dc::RollerCamEffectiveRadius(p, cam.roller_radius);
    }
  }
  for (size_t k = 0; k < c.grid.rise.size(); ++k) y[size_t(c.rise_offset) + k] = phi[size_t(c.grid.rise[k])];
  for (size_t k = 0; k < c.grid.ret.size(); ++k) y[size_t(c.return_offset) + k] = phi[size_t(c.grid.ret[k])];
}

// The cycle's largest contact stress from the samples s (NaN when one sample is not finite), refined
// on the continuous stress p0 as CycleMax does.
template <typename F>
void SetStressMax(DiscCamCycleValues& out, const std::vector<double>& s, bool stress_nan, double h, bool refine,
                  const F& p0) {
  out.stress_evaluated = true;
  if (stress_nan) {
    out.max_contact_stress_MPa = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  std::tie(out.max_contact_stress_MPa, out.at_stress_deg) = CycleMax(s, h, refine, p0);
  out.at_stress_deg /= kDeg;
}

}  // namespace

std::string DiscCamSizingVariableName(DiscCamSizingVariable v) {
  switch (v) {
    case DiscCamSizingVariable::kBaseCircle: return "base_circle_radius_mm";
    case DiscCamSizingVariable::kOffset: return "offset_mm";
    case DiscCamSizingVariable::kRollerRadius: return "roller_radius_mm";
    case DiscCamSizingVariable::kPivotDistance: return "pivot_distance_mm";
    case DiscCamSizingVariable::kArmLength: return "arm_length_mm";
  }
  return "";
}

DiscCamFastLimits StudyFastLimits(const DiscCamSizingSpec& spec) {
  DiscCamFastLimits f;
  f.rise_deg = f.return_deg = spec.limits.pressure_angle_deg * (1 - kTightenMargin);
  f.contact_stress_MPa = spec.limits.contact_stress_MPa * (1 - kTightenMargin);
  f.radius_margin_extra_mm = kTightenMargin * std::max(spec.limits.radius_margin_mm, 1.0);
  return f;
}

dc::DiscCam DiscCamDesign(const DiscCamSizingSpec& spec, const std::vector<double>& x) {
  dc::DiscCam cam = spec.cam;
  SetVariables(spec, std::span<const double>(x), cam);
  return cam;
}

double RadiusMarginOf(const DiscCamSizingSpec& spec, const dc::DiscCam& cam) {
  return (spec.limits.radius_margin_is_roller ? cam.roller_radius : spec.limits.radius_margin_mm) +
         spec.limits.radius_margin_shift_mm;
}

Problem DiscCamSizingProblem(const DiscCamSizingSpec& spec, const DiscCamFastLimits& fast) {
  const bool oscillating = spec.cam.follower == dc::FollowerType::kOscillatingRoller;
  for (DiscCamSizingVariable v : spec.which)
    if (oscillating ? v == DiscCamSizingVariable::kOffset
                    : v == DiscCamSizingVariable::kPivotDistance || v == DiscCamSizingVariable::kArmLength)
      throw std::invalid_argument("disc cam sizing: " + DiscCamSizingVariableName(v) + " is not a variable of " +
                                  (oscillating ? "an oscillating" : "a translating") + " follower");
  if (spec.which.size() != spec.variables.size() || spec.which.empty() ||
      spec.which.front() != DiscCamSizingVariable::kBaseCircle)
    throw std::invalid_argument("disc cam sizing: the base circle must be the first variable");
  if (spec.flat_face && (oscillating || spec.which.size() != 1))
    throw std::invalid_argument("disc cam sizing: a translating flat face has the base circle as its only variable");
  const bool stress = std::isfinite(fast.contact_stress_MPa);
  if (stress && !spec.stress) throw std::invalid_argument("disc cam sizing: a stress limit needs the loads");
  if (stress && oscillating != spec.stress->arm.has_value())
    throw std::invalid_argument(oscillating ? "disc cam sizing: the contact stress of an oscillating follower needs its arm loads"
                                            : "disc cam sizing: the contact stress of a translating follower needs its loads");
  auto c = std::make_shared<Context>();
  c->spec = spec;
  c->fast = fast;
  c->grid = MakeGrid(spec);
  const int n = spec.angle_steps;
  std::vector<OutputBlock> blocks = {{kDiscCamBaseCircle, 0, 1}};
  int at = 1;
  c->rise_offset = at;
  blocks.push_back({kDiscCamPressureRise, at, int(c->grid.rise.size())});
  at += int(c->grid.rise.size());
  c->return_offset = at;
  if (!c->grid.ret.empty()) blocks.push_back({kDiscCamPressureReturn, at, int(c->grid.ret.size())});
  at += int(c->grid.ret.size());
  c->curvature_offset = at;
  blocks.push_back({kDiscCamCurvature, at, n});
  at += n;
  if (stress) {
    c->stress_offset = at;
    blocks.push_back({kDiscCamStress, at, n});
  }
  Problem p;
  p.variables = spec.variables;
  p.evaluator = MakeEvaluator<4>(int(spec.variables.size()), blocks, [c](auto x, auto y) { EvalRows(*c, x, y); });
  p.objective = kDiscCamBaseCircle;
  p.objective_scale = std::max(1.0, spec.variables.front().scale);
  p.constraints.push_back({kDiscCamPressureRise, -fast.rise_deg, fast.rise_deg, spec.limits.pressure_angle_deg});
  if (!c->grid.ret.empty())
    p.constraints.push_back({kDiscCamPressureReturn, -fast.return_deg, fast.return_deg, spec.limits.pressure_angle_deg});
  p.constraints.push_back({kDiscCamCurvature, -kInf, 1.0, 1.0});
  if (stress) p.constraints.push_back({kDiscCamStress, -kInf, 0.0, std::max(1.0, spec.cam.roller_radius)});
  return p;
}

// The translating flat face's cycle (model/disc_cam/flat_faced.h): φ = 0, ρ_min = min (r_b + S + S'')
// refined as the roller's peaks are, the peak stress of the plane on ρ.
DiscCamCycleValues FlatFaceCycle(const DiscCamSizingSpec& spec, const dc::DiscCam& cam, int steps, bool refine) {
  DiscCamCycleValues out;
  const double h = 2 * kPi / steps;
  const bool stress = spec.stress && spec.stress->face_width_mm > 0 && spec.stress->composite_modulus_MPa > 0;
  auto point = [&](double th) { return dc::EvaluateFlatFaced(cam.motion, cam.base_radius, th); };
  auto neg_rho = [&](double th) { return -point(th).radius_of_curvature; };
  auto p0 = [&](double th) {
    const dc::FlatFacePoint<double> p = point(th);
    const DiscCamStressModel& m = *spec.stress;
    const double f = dc::FlatFaceLoadAt(p, m.loads, m.omega_rad_per_s).contact_force;
    return dc::FlatFaceContactStress(p, f, m.face_width_mm, m.composite_modulus_MPa);
  };
  const size_t m = static_cast<size_t>(steps);
  std::vector<double> r(m), s(m);
  bool stress_nan = false;
  for (int i = 0; i < steps; ++i) {
    const dc::FlatFacePoint<double> p = point(i * h);
    out.has_return = out.has_return || p.ds < 0.0;
    r[size_t(i)] = -p.radius_of_curvature;
    out.max_radial_dimension_mm = std::max(out.max_radial_dimension_mm, p.contact.norm());
    if (stress) {
      s[size_t(i)] = p0(i * h);
      stress_nan = stress_nan || !std::isfinite(s[size_t(i)]);
    }
  }
  double at = 0.0;
  std::tie(out.min_radius_of_curvature_mm, at) = CycleMax(r, h, refine, neg_rho);
  out.min_radius_of_curvature_mm = -out.min_radius_of_curvature_mm;
  out.at_curvature_deg = at / kDeg;
  out.max_pitch_curvature_per_mm = out.min_radius_of_curvature_mm > 0 ? 1.0 / out.min_radius_of_curvature_mm : kInf;
  if (stress) SetStressMax(out, s, stress_nan, h, refine, p0);
  return out;
}

DiscCamCycleValues DiscCamCycle(const DiscCamSizingSpec& spec, const dc::DiscCam& cam, int steps, bool refine) {
  if (spec.flat_face) return FlatFaceCycle(spec, cam, steps, refine);
  DiscCamCycleValues out;
  const double h = 2 * kPi / steps;
  const bool stress = spec.stress && spec.stress->face_width_mm > 0 && spec.stress->composite_modulus_MPa > 0;
  auto rises = [&](double th) { return cam.motion.Evaluate(th).v >= 0.0; };
  auto phi_where = [&](bool rise) {
    return [&, rise](double th) {
      const dc::CamPoint<double> p = dc::EvaluateCam(cam, th);
      return rises(th) == rise ? std::abs(p.pressure_angle) / kDeg : -kInf;
    };
  };
  auto kappa = [&](double th) { return dc::EvaluateCam(cam, th).pitch_curvature; };
  auto p0 = [&](double th) {
    const dc::CamPoint<double> p = dc::EvaluateCam(cam, th);
    const DiscCamStressModel& m = *spec.stress;
    const double f = ContactForce(m, p);
    return dc::RollerCamContactStress(p, cam.roller_radius, f, m.face_width_mm, m.composite_modulus_MPa);
  };
  const size_t m = static_cast<size_t>(steps);
  std::vector<double> rise(m), ret(m), k(m), s(m);
  bool stress_nan = false;
  for (int i = 0; i < steps; ++i) {
    const double th = i * h;
    const dc::CamPoint<double> p = dc::EvaluateCam(cam, th);
    const bool up = rises(th);
    out.has_return = out.has_return || !up;
    rise[size_t(i)] = up ? std::abs(p.pressure_angle) / kDeg : -kInf;
    ret[size_t(i)] = up ? -kInf : std::abs(p.pressure_angle) / kDeg;
    k[size_t(i)] = p.pitch_curvature;
    out.max_radial_dimension_mm = std::max(out.max_radial_dimension_mm, p.radial_dimension);
    if (stress) {
      s[size_t(i)] = p0(th);
      stress_nan = stress_nan || !std::isfinite(s[size_t(i)]);
    }
  }
  std::tie(out.max_pressure_rise_deg, out.at_rise_deg) = CycleMax(rise, h, refine, phi_where(true));
  out.at_rise_deg /= kDeg;
  if (out.has_return) {
    std::tie(out.max_pressure_return_deg, out.at_return_deg) = CycleMax(ret, h, refine, phi_where(false));
    out.at_return_deg /= kDeg;
  }
  std::tie(out.max_pitch_curvature_per_mm, out.at_curvature_deg) = CycleMax(k, h, refine, kappa);
  out.at_curvature_deg /= kDeg;
  out.min_radius_of_curvature_mm =
      out.max_pitch_curvature_per_mm > 0 ? 1.0 / out.max_pitch_curvature_per_mm - cam.roller_radius : kInf;
  if (stress) SetStressMax(out, s, stress_nan, h, refine, p0);
  return out;
}

DiscCamAccurateCheck CheckDiscCamDesign(const DiscCamSizingSpec& spec, const dc::DiscCam& cam) {
  DiscCamAccurateCheck c;
  const int n = spec.angle_steps, dense = spec.angle_steps * spec.accurate_factor;
  c.fast = DiscCamCycle(spec, cam, n, false);
  c.dense = DiscCamCycle(spec, cam, dense, false);
  c.accurate = DiscCamCycle(spec, cam, dense, true);
  c.model = "the cycle maxima on " + std::to_string(dense) + " cam angles (" + std::to_string(spec.accurate_factor) +
            " times the fast rows' " + std::to_string(n) + "), each peak within 1% of the largest refined by golden-section "
            "search to 1e-12 rad (error: the change from the dense grid's maximum)";
  auto add = [&](const char* key, const char* where, double fast, double grid, double accurate, double limit, bool upper) {
    VerifiedLimit v;
    v.limit = key;
    v.where = where;
    v.limit_value = limit;
    v.accurate_value = accurate;
    v.estimated_error = std::isfinite(accurate) && std::isfinite(grid) ? std::abs(accurate - grid) : 0.0;
    v.fast_value = fast;
    v.upper = upper;
    c.checks.push_back(v);
  };
  const double alpha = spec.limits.pressure_angle_deg;
  add("pressure_angle_deg", "rise", c.fast.max_pressure_rise_deg, c.dense.max_pressure_rise_deg,
      c.accurate.max_pressure_rise_deg, alpha, true);
  if (c.accurate.has_return)
    add("pressure_angle_deg", "return", c.fast.max_pressure_return_deg, c.dense.max_pressure_return_deg,
        c.accurate.max_pressure_return_deg, alpha, true);
  // A pitch curve without a convex part meets any margin (the verdict's rule); a closed curve
  // always has one, so the value is finite in practice.
  add("radius_margin_mm", "smallest convex radius of curvature of the profile", c.fast.min_radius_of_curvature_mm,
      c.dense.min_radius_of_curvature_mm, c.accurate.min_radius_of_curvature_mm, RadiusMarginOf(spec, cam), false);
  if (std::isfinite(spec.limits.contact_stress_MPa))
    add("contact_stress_MPa", spec.flat_face ? "flat face on cam" : "roller on cam", c.fast.max_contact_stress_MPa, c.dense.max_contact_stress_MPa,
        c.accurate.max_contact_stress_MPa, spec.limits.contact_stress_MPa, true);
  return c;
}

namespace {

// The loop aims at the accurate value itself within the limit (not only within its error).
bool Beyond(const VerifiedLimit& c) {
  return !std::isfinite(c.accurate_value) || (c.upper ? c.accurate_value > c.limit_value : c.accurate_value < c.limit_value);
}

// The fast limit that a check's fast value is held to (rows of that limit), and a pointer to it.
double* FastLimitOf(const VerifiedLimit& c, DiscCamFastLimits& fast) {
  if (c.limit == "pressure_angle_deg") return c.where == "rise" ? &fast.rise_deg : &fast.return_deg;
  if (c.limit == "contact_stress_MPa") return &fast.contact_stress_MPa;
  return nullptr;
}

// How far the fast limit of check c should move so that the accurate value lands kTightenMargin of
// the limit inside it, if the sampled bias (accurate − fast) stays as it is at this design; 0 when
// it need not move: the accurate value is within the limit and either the fast rows are not
// active (another limit or a bound sets the design) or it already lands within kLandingTolerance
// of the target. A fast limit is thus tightened when the accurate value is beyond the limit and
// loosened back when an earlier round overshot (the bias changes as the peak moves on the grid).
double FastLimitMove(const VerifiedLimit& c, const DiscCamFastLimits& fast) {
  if (!std::isfinite(c.accurate_value) || !std::isfinite(c.fast_value)) return 0.0;
  const double scale = std::max(std::abs(c.limit_value), 1.0);
  const double sign = c.upper ? 1.0 : -1.0;
  const double target = c.limit_value - sign * kTightenMargin * scale;
  const double gap = sign * (target - c.accurate_value);  // > 0: room left; < 0: beyond the target
  if (Beyond(c)) return sign * gap;
  const double fast_limit = c.limit == "pressure_angle_deg"   ? (c.where == "rise" ? fast.rise_deg : fast.return_deg)
                            : c.limit == "contact_stress_MPa" ? fast.contact_stress_MPa
                                                              : c.limit_value + fast.radius_margin_extra_mm;
  const bool active = std::abs(c.fast_value - fast_limit) <= kLandingTolerance * scale;
  return active && gap > kLandingTolerance * scale ? sign * gap : 0.0;
}

// One round: every fast limit moves by FastLimitMove. Returns whether one moved; the steps go to
// history.
bool Tighten(const DiscCamAccurateCheck& check, int round, DiscCamFastLimits& fast, std::vector<TighteningStep>* history) {
  bool moved = false;
  for (const VerifiedLimit& c : check.checks) {
    const double move = FastLimitMove(c, fast);
    if (move == 0.0) continue;
    TighteningStep step;
    step.round = round;
    step.limit = c.limit;
    step.where = c.where;
    step.accurate_value = c.accurate_value;
    step.limit_value = c.limit_value;
    if (double* fl = FastLimitOf(c, fast)) {
      step.fast_limit_before = *fl;
      *fl += move;
      step.fast_limit_after = *fl;
    } else {  // the radius margin: a lower limit, held by the extra margin of the curvature rows
      step.fast_limit_before = c.limit_value + fast.radius_margin_extra_mm;
      fast.radius_margin_extra_mm += move;
      step.fast_limit_after = c.limit_value + fast.radius_margin_extra_mm;
    }
    if (history) history->push_back(step);
    moved = true;
  }
  return moved;
}

// The loop's end: nothing beyond its limit and no fast limit left to move.
bool Landed(const DiscCamAccurateCheck& check, const DiscCamFastLimits& fast) {
  return std::none_of(check.checks.begin(), check.checks.end(),
                      [&](const VerifiedLimit& c) { return Beyond(c) || FastLimitMove(c, fast) != 0.0; });
}

}  // namespace

DiscCamMinSizeOutcome SolveDiscCamMinSize(const DiscCamSizingSpec& spec, const DiscCamMinSizeOptions& options) {
  DiscCamMinSizeOutcome out;
  out.fast = StudyFastLimits(spec);
  out.verification.max_rounds = options.verify_rounds;
  int values = 0, gradients = 0, iterations = 0;
  auto solve_from = [&](const DiscCamSizingSpec& sp, const DiscCamFastLimits& fast, const std::vector<double>& x0,
                        bool warm = false) {
    optimizers::SolverOptions so = options.solver;
    so.initial = x0;
    so.ipopt_extended_low_rank = true;  // ≤ 4 variables, rows at every sampled angle (solver.h)
    if (warm) so.barrier_initial = 1e-5, so.bound_push = 1e-6;
    const optimizers::SolverResult r = optimizers::Solve(DiscCamSizingProblem(sp, fast), so);
    values += r.value_evaluations;
    gradients += r.gradient_evaluations;
    iterations += r.iterations;
    return r;
  };
  // Starts: the study's own design, then the largest base circle of the range (the others kept).
  std::vector<std::vector<double>> starts;
  {
    std::vector<double> a;
    for (const Variable& v : spec.variables) a.push_back(std::clamp(v.initial, v.lower, v.upper));
    std::vector<double> b = a;
    b[0] = spec.variables[0].upper;
    starts.push_back(a);
    if (b != a) starts.push_back(b);
  }
  auto take = [&](const optimizers::SolverResult& r) {
    out.result = r;
    out.converged = r.ok();
    out.x = r.x;
    out.cam = DiscCamDesign(spec, r.x);
  };
  bool solved = false;
  auto solve_round0 = [&] {
    int best = -1;
    for (const std::vector<double>& x0 : starts) {
      out.starts.push_back(solve_from(spec, out.fast, x0));
      const optimizers::SolverResult& r = out.starts.back();
      if (r.x.empty()) continue;
      const optimizers::SolverResult* b = best < 0 ? nullptr : &out.starts[size_t(best)];
      // The smallest converged end; else the one with the smallest violation (the closest).
      const bool better = !b || (r.ok() && (!b->ok() || r.objective < b->objective)) ||
                          (!r.ok() && !b->ok() && r.max_violation < b->max_violation);
      if (better) best = int(out.starts.size()) - 1;
    }
    if (best < 0) {
      out.result = out.starts.front();
      return;
    }
    take(out.starts[size_t(best)]);
    solved = true;
  };
  auto check = [&] {
    out.check = CheckDiscCamDesign(spec, out.cam);
    out.verification.accurate_model = out.check.model;
    out.verification.checks = out.check.checks;
    out.verification.ran = true;
  };
  auto verify = [&] {
    for (int round = 0;; ++round) {
      check();
      if (Landed(out.check, out.fast) || round >= options.verify_rounds || !out.result.ok()) return;
      if (!Tighten(out.check, round + 1, out.fast, &out.verification.history)) return;
      ++out.rounds;
      take(solve_from(spec, out.fast, out.x));
    }
  };

  // The sizing driver (sizing/sizing_driver.h) with one candidate: the follower type is given.
  SizingCandidates loop;
  loop.count = 1;
  loop.label = [](int) { return std::string("translating roller follower"); };
  loop.solve = [&](int) { solve_round0(); };
  loop.feasible_size = [&](int) -> std::optional<double> {
    if (!solved || !out.converged) return std::nullopt;
    if (out.verification.ran && !out.verification.verified()) return std::nullopt;
    return out.result.objective;
  };
  loop.verify = [&](int) { verify(); };
  RunSizingDriver(loop);
  // A design that was not feasible on the fast model is still checked: the study reports the
  // closest point with its accurate values.
  if (solved && !out.verification.ran) check();
  out.verified = out.verification.verified() && out.converged &&
                 std::none_of(out.check.checks.begin(), out.check.checks.end(), Beyond);

  // The binding limits and their costs: the study's limit moved by ±h, solved again from the
  // answer with the fast limit moved alike, then verified and tightened as the answer was.
  auto verified_objective = [&](const DiscCamSizingSpec& moved, DiscCamFastLimits fast) {
    optimizers::SolverResult r = solve_from(moved, fast, out.x, true);
    for (int round = 0; r.ok(); ++round) {
      const DiscCamAccurateCheck c = CheckDiscCamDesign(moved, DiscCamDesign(moved, r.x));
      const bool within = std::none_of(c.checks.begin(), c.checks.end(), Beyond);
      if (Landed(c, fast) || round >= options.verify_rounds || !Tighten(c, round + 1, fast, nullptr))
        return within ? r.objective : std::numeric_limits<double>::quiet_NaN();
      r = solve_from(moved, fast, r.x, true);
    }
    return std::numeric_limits<double>::quiet_NaN();
  };
  if (out.verified) {
    for (const VerifiedLimit& c : out.check.checks) {
      const bool binds = c.limit == "radius_margin_mm"
                             ? c.accurate_value <= c.limit_value + kBindingFraction
                             : c.accurate_value >= c.limit_value * (1 - kBindingFraction);
      if (binds && std::find(out.binding.begin(), out.binding.end(), c.limit) == out.binding.end())
        out.binding.push_back(c.limit);
    }
    const StageClock::Scope stage("limit costs");
    for (const std::string& key : out.binding) {
      const double base = key == "pressure_angle_deg"   ? spec.limits.pressure_angle_deg
                          : key == "contact_stress_MPa" ? spec.limits.contact_stress_MPa
                                                        : RadiusMarginOf(spec, out.cam);
      const double h = kCostStep * std::max(std::abs(base), 1.0);
      double rb[2] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
      for (int side = 0; side < 2; ++side) {
        const double d = side == 0 ? -h : h;
        DiscCamSizingSpec moved = spec;
        DiscCamFastLimits f = out.fast;
        if (key == "pressure_angle_deg") moved.limits.pressure_angle_deg += d, f.rise_deg += d, f.return_deg += d;
        if (key == "contact_stress_MPa") moved.limits.contact_stress_MPa += d, f.contact_stress_MPa += d;
        if (key == "radius_margin_mm") moved.limits.radius_margin_shift_mm += d;
        rb[side] = verified_objective(moved, f);
      }
      const LimitSlope slope = SlopeFromReSolves(rb[0], out.result.objective, rb[1], h,
                                                 10 * options.solver.tolerance * std::max(std::abs(out.result.objective), 1.0));
      out.limit_slope[key] = slope;
      if (!slope.sides.empty()) out.limit_cost[key] = slope.slope;
    }
  }
  out.result.value_evaluations = values;
  out.result.gradient_evaluations = gradients;
  out.result.iterations = iterations;
  return out;
}

}  // namespace camopt::sizing
