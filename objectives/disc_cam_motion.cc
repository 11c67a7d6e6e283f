#include "objectives/disc_cam_motion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>

#include "model/common/roots.h"
#include "model/disc_cam/follower_dynamics.h"

namespace camopt::objectives {
namespace {

namespace dc = camopt::disc_cam;
constexpr double kDeg = kPi / 180.0;
constexpr int kJet = 32;  // Jet size: up to 31 free control values and t
constexpr double kRefineShare = 0.01;
// RK4 steps per natural period of the follower, at least: at the highest speed of the rows, and
// (the scheme's accuracy, far inside its stability limit h ω_n < 2.8) at the lowest.
constexpr double kStepsPerPeriod = 64, kStepsPerPeriodLowest = 8;
// The dynamic force rows: one smooth soft extreme per window of the revolution, not one row per
// RK4 step (thousands of dense rows made Ipopt's KKT solve depend on the heap's layout: the same
// study gave another answer when run twice in one process). κ = kSharpness / force scale bounds
// the soft extreme's gap to the true one by ln(steps per window)/κ, about 0.14% of the scale.
constexpr int kForceWindows = 60;
constexpr double kSharpness = 2000.0;

// The soft minimum −(1/κ) ln Σ exp(−κ F_k) of F over [lo, hi), shifted by its sampled minimum so
// that no exponential overflows (the shift is a constant: the value and derivative are exact).
template <typename T>
T SoftMin(const std::vector<T>& f, size_t lo, size_t hi, double kappa) {
  double m = Value(f[lo]);
  for (size_t k = lo; k < hi; ++k) m = std::min(m, Value(f[k]));
  T sum(0.0);
  using std::exp;
  using std::log;
  for (size_t k = lo; k < hi; ++k) sum += exp(-T(kappa) * (f[k] - T(m)));
  return T(m) - log(sum) / T(kappa);
}

// The windows over `steps` samples: min(steps, kForceWindows) of them, window k being
// [WindowBegin(k), WindowBegin(k + 1)), none empty.
int Windows(size_t steps) { return int(std::min(steps, size_t(kForceWindows))); }
size_t WindowBegin(size_t k, size_t steps) { return k * steps / size_t(Windows(steps)); }

// The u-derivatives (order 1, 2) of every basis function of a B-spline segment at u.
std::vector<std::array<double, 2>> BasisDerivatives(int count, int degree, double u) {
  std::vector<std::array<double, 2>> d(size_t(count), {0.0, 0.0});
  std::vector<double> e(size_t(count), 0.0);
  for (int i = 0; i < count; ++i) {
    e[size_t(i)] = 1.0;
    const motion::Svaj<double> v = motion::internal::BSplineShape(e, degree, u);
    d[size_t(i)] = {v.v, v.a};
    e[size_t(i)] = 0.0;
  }
  return d;
}

// How many values each end fixes beyond its position: velocity, and acceleration when asked.
int Fixed(const OptimizedSegment& o) { return 1 + (o.acceleration ? 1 : 0); }

// The neighbours' u-derivatives the segment must meet at its start and end (θ-derivatives of the
// neighbour times β^r of this segment).
struct EndTargets {
  double start[2], end[2];
};
EndTargets Targets(const dc::DiscCam& cam, const OptimizedSegment& o) {
  const auto& segs = cam.motion.segments();
  const size_t n = segs.size(), s = size_t(o.segment);
  const auto& prev = segs[(s + n - 1) % n];
  const auto& next = segs[(s + 1) % n];
  const double b = segs[s].duration;
  const motion::Svaj<double> pe = motion::MotionSegmentShape(prev, 1.0), ns = motion::MotionSegmentShape(next, 0.0);
  EndTargets t;
  t.start[0] = pe.v / prev.duration * b;
  t.start[1] = pe.a / (prev.duration * prev.duration) * b * b;
  t.end[0] = ns.v / next.duration * b;
  t.end[1] = ns.a / (next.duration * next.duration) * b * b;
  return t;
}

// The segment's control values from its free ones: c_0 = 0, c_n = rise, c_1 (, c_2) and c_{n−1}
// (, c_{n−2}) solved from the targets one order at a time (the r-th derivative at u = 0 involves
// c_0 … c_r only, with c_r's coefficient non-zero; likewise backwards at u = 1).
template <typename T>
std::vector<T> Controls(const dc::DiscCam& cam, const OptimizedSegment& o, const T* free) {
  const int count = o.control_points, n = count - 1, k = Fixed(o);
  const double rise = cam.motion.segments()[size_t(o.segment)].rise;
  const auto d0 = BasisDerivatives(count, o.degree, 0.0), d1 = BasisDerivatives(count, o.degree, 1.0);
  const EndTargets t = Targets(cam, o);
  std::vector<T> c(size_t(count), T(0.0));
  c[size_t(n)] = T(rise);
  for (int i = k + 1; i <= n - k - 1; ++i) c[size_t(i)] = free[i - k - 1];
  for (int r = 1; r <= k; ++r) {
    T acc(t.start[r - 1]);
    for (int i = 0; i < r; ++i) acc -= T(d0[size_t(i)][size_t(r - 1)]) * c[size_t(i)];
    c[size_t(r)] = acc / T(d0[size_t(r)][size_t(r - 1)]);
  }
  for (int r = 1; r <= k; ++r) {
    T acc(t.end[r - 1]);
    for (int i = n - r + 1; i <= n; ++i) acc -= T(d1[size_t(i)][size_t(r - 1)]) * c[size_t(i)];
    c[size_t(n - r)] = acc / T(d1[size_t(n - r)][size_t(r - 1)]);
  }
  return c;
}

template <typename T>
dc::DiscCamTpl<T> DesignOf(const DiscCamMotionSpec& spec, std::span<const T> x) {
  dc::DiscCamTpl<T> cam = dc::CastCam<T>(spec.cam);
  std::vector<motion::MotionSegment<T>> segs = cam.motion.segments();
  size_t at = 0;
  for (const OptimizedSegment& o : spec.segments) {
    std::vector<T> c = Controls<T>(spec.cam, o, x.data() + at);
    at += size_t(o.control_points - 2 - 2 * Fixed(o));
    motion::MotionSegment<T>& s = segs[size_t(o.segment)];
    s = motion::BSplineThrough(c, o.degree, s.duration);
  }
  cam.motion = motion::MotionProgram<T>(std::move(segs));
  return cam;
}

// Samples of the fast rows: the angles, and which lie inside an optimized segment.
struct Samples {
  std::vector<double> theta;
  std::vector<char> optimized;
  std::vector<char> interior;  ///< strictly inside (the ends are fixed: a row there is constant)
};
Samples MakeSamples(const DiscCamMotionSpec& spec, int n) {
  Samples s;
  std::vector<std::pair<double, double>> ranges;
  double start = 0;
  for (size_t i = 0; i < spec.cam.motion.segments().size(); ++i) {
    const double d = spec.cam.motion.segments()[i].duration;
    for (const OptimizedSegment& o : spec.segments)
      if (size_t(o.segment) == i) ranges.push_back({start, start + d});
    start += d;
  }
  for (int i = 0; i < n; ++i) {
    const double th = 2 * kPi * i / n;
    s.theta.push_back(th);
    bool in = false, strict = false;
    for (const auto& [lo, hi] : ranges) {
      in = in || (th >= lo && th <= hi);
      strict = strict || (th > lo + 1e-12 && th < hi - 1e-12);
    }
    s.optimized.push_back(in);
    s.interior.push_back(strict);
  }
  return s;
}

std::vector<double> Durations(const dc::DiscCam& cam) {
  std::vector<double> d;
  for (const auto& s : cam.motion.segments()) d.push_back(s.duration);
  return d;
}

// The dwell start (segment index of the dwell) after each optimized segment, or -1.
int DwellAfter(const DiscCamMotionSpec& spec, const OptimizedSegment& o) {
  const auto& segs = spec.cam.motion.segments();
  const size_t next = (size_t(o.segment) + 1) % segs.size();
  return segs[next].law == motion::MotionLaw::kDwell ? int(next) : -1;
}

// The grid boundary index where segment `seg` starts.
size_t GridIndexOfSegmentStart(const dc::ContactGrid& g, int seg) {
  for (size_t k = 0; k < g.segment.size(); ++k)
    if (g.segment[k] == seg) return k;
  return 0;
}

}  // namespace

int ContactStepsPerRevolution(const DiscCamMotionSpec& spec) {
  double steps = spec.angle_steps;
  if (spec.follower) {
    double top = spec.speed_rpm, low = spec.speed_rpm;
    for (double n : spec.objective_speeds_rpm) top = std::max(top, n), low = std::min(low, n);
    if (spec.no_separation_up_to_rpm) {
      top = std::max(top, *spec.no_separation_up_to_rpm);
      low = std::min(low, *spec.no_separation_up_to_rpm / spec.separation_speeds);
    }
    const double fn = spec.follower->NaturalFrequencyRadS() / (2 * kPi);
    steps = std::max({steps, kStepsPerPeriod * fn / (top / 60.0), kStepsPerPeriodLowest * fn / (low / 60.0)});
  }
  return std::isfinite(steps) && steps < 1e9 ? int(std::ceil(steps)) : 1000000000;
}

namespace {

// The RK4 grid of every response (ContactStepsPerRevolution).
dc::ContactGrid GridFor(const DiscCamMotionSpec& spec) {
  return dc::MakeContactGrid(Durations(spec.cam), ContactStepsPerRevolution(spec));
}

bool DynamicForce(const DiscCamMotionSpec& spec) {
  return spec.objective == MotionObjective::kMaxContactForce && spec.follower.has_value();
}

// The rows' layout.
struct Layout {
  Samples samples;
  dc::ContactGrid grid;
  int nfree = 0;
  int objective_rows = 0, pressure_rows = 0, curvature_rows = 0, stroke_rows = 0, separation_rows = 0;
  int stress_rows = 0;
  double stress_limit_MPa = kInf;
  std::vector<double> separation_rpm;
  bool curvature = false;
};

Layout MakeLayout(const DiscCamMotionSpec& spec) {
  Layout l;
  l.samples = MakeSamples(spec, spec.angle_steps);
  l.nfree = FreeControlCount(spec);
  if (spec.follower) l.grid = GridFor(spec);
  const int n = spec.angle_steps;
  int inside = 0;
  for (char c : l.samples.optimized) inside += c;
  switch (spec.objective) {
    case MotionObjective::kPeakAcceleration:
    case MotionObjective::kPeakJerk: l.objective_rows = 2 * inside; break;
    case MotionObjective::kResidualVibration: {
      int dwells = 0;
      for (const OptimizedSegment& o : spec.segments) dwells += DwellAfter(spec, o) >= 0;
      l.objective_rows = dwells * int(spec.objective_speeds_rpm.size());
      break;
    }
    case MotionObjective::kMaxContactForce:
      l.objective_rows = DynamicForce(spec) ? Windows(l.grid.theta.size() - 1) : n;
      break;
  }
  l.pressure_rows = n;
  l.stress_rows = spec.contact_stress_MPa ? n : 0;
  l.curvature = spec.cam.roller_radius + spec.radius_margin_mm > 0 || spec.radius_margin_is_roller;
  l.curvature_rows = l.curvature ? n : 0;
  int interior = 0;
  for (char c : l.samples.interior) interior += c;
  l.stroke_rows = spec.stroke_mm ? interior : 0;
  if (spec.no_separation_up_to_rpm) {
    for (int j = 1; j <= spec.separation_speeds; ++j)
      l.separation_rpm.push_back(*spec.no_separation_up_to_rpm * j / spec.separation_speeds);
    l.separation_rows = int(l.separation_rpm.size()) * Windows(l.grid.theta.size() - 1);
  }
  return l;
}

// Every row value (before the epigraph's t is subtracted) of a design.
template <typename T>
struct RowValues {
  std::vector<T> objective, pressure_deg, curvature, stroke, separation, stress;
};

template <typename T>
RowValues<T> Rows(const DiscCamMotionSpec& spec, const Layout& l, const dc::DiscCamTpl<T>& cam, double margin_extra) {
  RowValues<T> r;
  const int n = spec.angle_steps;
  const T margin = T(spec.radius_margin_mm + margin_extra) + (spec.radius_margin_is_roller ? cam.roller_radius : T(0.0));
  std::vector<T> cos_phi(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const T th(l.samples.theta[size_t(i)]);
    const dc::CamPoint<T> p = dc::EvaluateCam(cam, th);
    r.pressure_deg.push_back(p.pressure_angle / T(kDeg));
    using std::cos;
    cos_phi[size_t(i)] = cos(p.pressure_angle);
    if (l.curvature) r.curvature.push_back(p.pitch_curvature * (cam.roller_radius + margin));
    if (spec.stroke_mm && l.samples.interior[size_t(i)]) r.stroke.push_back(p.s);
    if (l.stress_rows) {
      const double s = l.stress_limit_MPa;
      const T w(dc::RadPerSecond(spec.speed_rpm));
      r.stress.push_back(dc::CamLoadAt(p, *spec.loads, w).contact_force *
                             T(spec.composite_modulus_MPa / (kPi * spec.face_width_mm * s * s)) -
                         dc::RollerCamEffectiveRadius(p, cam.roller_radius));
    }
    if ((spec.objective == MotionObjective::kPeakAcceleration || spec.objective == MotionObjective::kPeakJerk) &&
        l.samples.optimized[size_t(i)]) {
      const motion::Svaj<T> m = cam.motion.Evaluate(th);
      const T v = spec.objective == MotionObjective::kPeakAcceleration ? m.a : m.j;
      r.objective.push_back(v);
      r.objective.push_back(-v);
    }
    if (spec.objective == MotionObjective::kMaxContactForce && !DynamicForce(spec)) {
      const T w(dc::RadPerSecond(spec.speed_rpm));
      r.objective.push_back(dc::FollowerAxialForce(*spec.loads, p.s, p.d2s, w) / cos_phi[size_t(i)]);
    }
  }
  if (spec.objective == MotionObjective::kResidualVibration) {
    for (double rpm : spec.objective_speeds_rpm) {
      const dc::ContactResponse<T> resp =
          dc::IntegrateInContact(cam.motion, *spec.follower, dc::RadPerSecond(rpm), spec.revolutions, l.grid);
      for (const OptimizedSegment& o : spec.segments) {
        const int d = DwellAfter(spec, o);
        if (d < 0) continue;
        const size_t k = GridIndexOfSegmentStart(l.grid, d);
        r.objective.push_back(dc::ResidualAmplitudeSquared(*spec.follower, resp.s[k], resp.u[k], resp.w[k]));
      }
    }
  }
  if (DynamicForce(spec)) {
    const dc::ContactResponse<T> resp = dc::IntegrateInContact(cam.motion, *spec.follower,
                                                               dc::RadPerSecond(spec.speed_rpm), spec.revolutions, l.grid);
    std::vector<T> minus_f;
    for (size_t k = 0; k + 1 < l.grid.theta.size(); ++k) {
      const dc::CamPoint<T> p = dc::EvaluateCam(cam, T(l.grid.theta[k]));
      using std::cos;
      minus_f.push_back(-resp.axial[k] / cos(p.pressure_angle));
    }
    const size_t steps = minus_f.size();
    const double kappa = kSharpness / std::max(1.0, std::abs(spec.follower->Hold()));
    for (int w = 0; w < Windows(steps); ++w)  // soft max = −soft min of −F
      r.objective.push_back(-SoftMin(minus_f, WindowBegin(size_t(w), steps), WindowBegin(size_t(w) + 1, steps), kappa));
  }
  for (double rpm : l.separation_rpm) {
    const dc::ContactResponse<T> resp =
        dc::IntegrateInContact(cam.motion, *spec.follower, dc::RadPerSecond(rpm), spec.revolutions, l.grid);
    const size_t steps = l.grid.theta.size() - 1;
    const double kappa = kSharpness / std::max(1.0, std::abs(spec.follower->Hold()));
    for (int w = 0; w < Windows(steps); ++w)
      r.separation.push_back(SoftMin(resp.axial, WindowBegin(size_t(w), steps), WindowBegin(size_t(w) + 1, steps), kappa));
  }
  return r;
}

}  // namespace

std::string MotionObjectiveName(MotionObjective o) {
  switch (o) {
    case MotionObjective::kPeakAcceleration: return "peak_acceleration";
    case MotionObjective::kPeakJerk: return "peak_jerk";
    case MotionObjective::kResidualVibration: return "residual_vibration";
    case MotionObjective::kMaxContactForce: return "max_contact_force";
  }
  return "";
}

std::string MotionObjectiveUnit(MotionObjective o, const std::string& unit) {
  switch (o) {
    case MotionObjective::kPeakAcceleration: return unit + "/rad^2";
    case MotionObjective::kPeakJerk: return unit + "/rad^3";
    case MotionObjective::kResidualVibration: return "mm";
    case MotionObjective::kMaxContactForce: return "N";
  }
  return "";
}

int FreeControlCount(const DiscCamMotionSpec& spec) {
  int n = 0;
  for (const OptimizedSegment& o : spec.segments) {
    const int f = o.control_points - 2 - 2 * Fixed(o);
    if (f < 1) throw std::invalid_argument("disc_cam_motion: a segment without free control values");
    n += f;
  }
  return n;
}

std::vector<double> ControlValues(const DiscCamMotionSpec& spec, size_t j, const std::vector<double>& free) {
  return Controls<double>(spec.cam, spec.segments[j], free.data());
}

std::vector<double> StartControls(const DiscCamMotionSpec& spec) {
  std::vector<double> x;
  for (const OptimizedSegment& o : spec.segments) {
    const auto& seg = spec.cam.motion.segments()[size_t(o.segment)];
    // Greville abscissae ξ_i = (t_{i+1} + … + t_{i+p})/p of the clamped uniform knots: a B-spline
    // with c_i = f(ξ_i) reproduces a linear f and approximates a smooth one (de Boor, ch. XI).
    const int count = o.control_points, p = o.degree, k = Fixed(o);
    std::vector<double> t(size_t(count + p + 1));
    for (int i = 0; i <= count + p - 1 + 1 - 1; ++i)
      t[size_t(i)] = i <= p ? 0.0 : i > count - 1 ? 1.0 : double(i - p) / double(count - p);
    for (int i = k + 1; i <= count - 1 - k - 1; ++i) {
      double xi = 0;
      for (int r = 1; r <= p; ++r) xi += t[size_t(i + r)];
      xi /= p;
      x.push_back(motion::MotionSegmentShape(seg, xi).s);
    }
  }
  return x;
}

dc::DiscCam MotionDesign(const DiscCamMotionSpec& spec, const std::vector<double>& x) {
  return DesignOf<double>(spec, std::span<const double>(x));
}

Problem DiscCamMotionProblem(const DiscCamMotionSpec& spec, const MotionFastLimits& fast) {
  Layout l = MakeLayout(spec);
  l.stress_limit_MPa = fast.contact_stress_MPa;
  if (!l.separation_rpm.empty()) {
    for (double rpm : fast.extra_separation_rpm) l.separation_rpm.push_back(rpm);
    l.separation_rows = int(l.separation_rpm.size()) * Windows(l.grid.theta.size() - 1);
  }
  if (l.nfree + 1 > kJet)
    throw std::invalid_argument("disc_cam_motion: more than " + std::to_string(kJet - 1) + " free control values");
  Problem p;
  const std::vector<double> x0 = StartControls(spec);
  double scale = 0;
  for (const OptimizedSegment& o : spec.segments)
    scale = std::max(scale, std::abs(spec.cam.motion.segments()[size_t(o.segment)].rise));
  for (int i = 0; i < l.nfree; ++i) {
    Variable v;
    v.name = "control_" + std::to_string(i);
    v.initial = x0[size_t(i)];
    v.scale = std::max(scale, 1e-6);
    p.variables.push_back(v);
  }
  const double t0 = FastObjective(spec, MotionDesign(spec, x0));
  const double t_start = spec.objective == MotionObjective::kResidualVibration ? t0 * t0 : t0;
  Variable t;
  t.name = "epigraph";
  t.initial = t_start * 1.01 + 1e-12;
  t.lower = spec.objective == MotionObjective::kMaxContactForce ? -kInf : 0.0;
  t.scale = std::isfinite(t_start) ? std::clamp(std::abs(t_start), 1e-12, 1e100) : 1.0;
  p.variables.push_back(t);
  std::vector<OutputBlock> blocks;
  int off = 0;
  auto add = [&](const char* name, int size) {
    if (size > 0) blocks.push_back({name, off, size}), off += size;
  };
  add("epigraph", 1);
  add("objective_rows", l.objective_rows);
  add("pressure_angle_deg", l.pressure_rows);
  add("curvature_ratio", l.curvature_rows);
  add("follower_mm", l.stroke_rows);
  add("axial_force_N", l.separation_rows);
  add("contact_stress_row_mm", l.stress_rows);
  const int nv = l.nfree;
  const DiscCamMotionSpec* sp = &spec;
  const double margin_extra = fast.radius_margin_extra_mm;
  auto eval = [sp, l, nv, margin_extra](auto x, auto y) {
    using T = typename std::remove_cv_t<std::remove_reference_t<decltype(x[0])>>;
    const dc::DiscCamTpl<T> cam = DesignOf<T>(*sp, x.subspan(0, size_t(nv)));
    const T tt = x[size_t(nv)];
    const RowValues<T> r = Rows(*sp, l, cam, margin_extra);
    size_t k = 0;
    y[k++] = tt;
    for (const T& v : r.objective) y[k++] = v - tt;
    for (const T& v : r.pressure_deg) y[k++] = v;
    for (const T& v : r.curvature) y[k++] = v;
    for (const T& v : r.stroke) y[k++] = v;
    for (const T& v : r.separation) y[k++] = v;
    for (const T& v : r.stress) y[k++] = v;
    if (k != y.size()) throw std::logic_error("disc_cam_motion: the rows do not fill their blocks");
  };
  // The smallest Jet that holds the variables (the rows' cost grows with it).
  if (nv + 1 <= 8)
    p.evaluator = MakeEvaluator<8>(nv + 1, blocks, eval);
  else if (nv + 1 <= 16)
    p.evaluator = MakeEvaluator<16>(nv + 1, blocks, eval);
  else
    p.evaluator = MakeEvaluator<kJet>(nv + 1, blocks, eval);
  p.objective = "epigraph";
  p.objective_scale = t.scale;
  if (l.objective_rows) p.constraints.push_back({"objective_rows", -kInf, 0.0, t.scale});
  p.constraints.push_back({"pressure_angle_deg", -fast.pressure_angle_deg, fast.pressure_angle_deg, fast.pressure_angle_deg});
  if (l.curvature_rows) p.constraints.push_back({"curvature_ratio", -kInf, 1.0, 1.0});
  if (l.stroke_rows)
    p.constraints.push_back({"follower_mm", fast.stroke_inset_mm, *spec.stroke_mm - fast.stroke_inset_mm, *spec.stroke_mm});
  if (l.stress_rows) p.constraints.push_back({"contact_stress_row_mm", -kInf, 0.0, std::max(1.0, spec.cam.roller_radius)});
  if (l.separation_rows) {
    const double hold = std::max(1.0, std::abs(spec.follower->Hold()));
    p.constraints.push_back({"axial_force_N", fast.separation_margin_N, kInf, hold});
  }
  return p;
}

double FastObjective(const DiscCamMotionSpec& spec, const dc::DiscCam& cam) {
  Layout l = MakeLayout(spec);
  l.stress_rows = 0;  // the objective only
  const RowValues<double> r = Rows(spec, l, cam, 0.0);
  double v = r.objective.empty() ? 0.0 : *std::max_element(r.objective.begin(), r.objective.end());
  if (spec.objective == MotionObjective::kResidualVibration) v = std::sqrt(std::max(v, 0.0));
  return v;
}

namespace {

// Follower dynamics input of the CVODE model for a design at a speed.
dc::FollowerDynamicsInput CvodeInput(const DiscCamMotionSpec& spec, const dc::DiscCam& cam, double rpm, double tol,
                                     int samples) {
  dc::FollowerDynamicsInput in;
  in.motion = cam.motion;
  in.loads = spec.follower->loads;
  in.follower_stiffness_N_per_mm = spec.follower->follower_stiffness_N_per_mm;
  in.damping_ratio = spec.follower->damping_ratio;
  in.speed_rad_s = dc::RadPerSecond(rpm);
  in.revolutions = spec.revolutions;
  in.relative_tolerance = tol;
  in.absolute_tolerance = tol;
  in.samples = samples;
  return in;
}

// The residual amplitude over the dwell that starts at θ_d [rad] and lasts β [rad]: the free
// damped response e^{−ζω_n τ}(a cos ω_d τ + b sin ω_d τ) fitted to the CVODE samples of x − x_s by
// least squares; A = √(a² + b²) (contact_response.h). NaN when the follower leaves the cam.
double FittedResidual(const DiscCamMotionSpec& spec, const dc::FollowerDynamicsResult& r, double theta_d, double beta,
                      double omega) {
  const dc::ContactFollower& f = *spec.follower;
  const double wn = f.NaturalFrequencyRadS(), z = f.damping_ratio, wd = wn * std::sqrt(1 - z * z);
  const double kf = f.follower_stiffness_N_per_mm, ks = f.loads.spring_rate_N_per_mm;
  double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0;
  int used = 0;
  for (const dc::FollowerDynamicsSample& s : r.samples) {
    const double th = s.cam_angle_deg * kDeg;
    double d = th - theta_d;
    if (d < -1e-12) d += 2 * kPi;
    if (!(d >= -1e-12 && d < beta * (1 - 1e-9))) continue;
    if (s.axial_force_N <= 0) return std::numeric_limits<double>::quiet_NaN();
    const double tau = std::max(d, 0.0) / omega, env = std::exp(-z * wn * tau);
    const double p = env * std::cos(wd * tau), q = env * std::sin(wd * tau);
    const double e = s.follower_mm - (kf * s.cam_follower_mm - f.Hold()) / (kf + ks);
    a11 += p * p, a12 += p * q, a22 += q * q, b1 += p * e, b2 += q * e;
    ++used;
  }
  if (used < 4) return std::numeric_limits<double>::quiet_NaN();
  const double det = a11 * a22 - a12 * a12;
  const double a = (b1 * a22 - b2 * a12) / det, b = (a11 * b2 - a12 * b1) / det;
  return std::hypot(a, b);
}

}  // namespace

MotionAccurate CheckMotionDesign(const DiscCamMotionSpec& spec, const dc::DiscCam& cam, bool objective_only) {
  MotionAccurate out;
  const int n = spec.angle_steps * spec.accurate_factor;
  const double h = 2 * kPi / n;
  const Samples dense = MakeSamples(spec, n);
  const double margin = spec.radius_margin_mm + (spec.radius_margin_is_roller ? cam.roller_radius : 0.0);
  auto inside = [&](double th) {
    double start = 0;
    for (size_t i = 0; i < cam.motion.segments().size(); ++i) {
      const double d = cam.motion.segments()[i].duration;
      for (const OptimizedSegment& o : spec.segments)
        if (size_t(o.segment) == i && th >= start && th <= start + d) return true;
      start += d;
    }
    return false;
  };
  auto wrap = [](double th) { return std::fmod(std::fmod(th, 2 * kPi) + 2 * kPi, 2 * kPi); };
  // A cycle maximum of f on the dense grid and refined; its error: refined − dense.
  auto cycle = [&](const auto& f, double& value, double& error, double& at_deg) {
    std::vector<double> v(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) v[size_t(i)] = f(dense.theta[size_t(i)]);
    const auto [coarse, c_at] = CircularMaxRefined(v, h, false, kRefineShare, f);
    const auto [fine, f_at] = CircularMaxRefined(v, h, true, kRefineShare, [&](double th) { return f(wrap(th)); });
    (void)c_at;
    value = fine;
    error = std::abs(fine - coarse);
    at_deg = f_at / kDeg;
  };
  std::string where;
  // The limits.
  if (!objective_only) {
    double v, e, at;
    cycle([&](double th) { return std::abs(dc::EvaluateCam(cam, th).pressure_angle) / kDeg; }, v, e, at);
    VerifiedLimit c;
    c.limit = "pressure_angle_deg";
    c.where = "largest |pressure angle| at " + std::to_string(at).substr(0, 7) + " deg";
    c.limit_value = spec.pressure_angle_deg, c.accurate_value = v, c.estimated_error = e, c.upper = true;
    out.checks.push_back(c);
  }
  if (!objective_only && cam.roller_radius + margin > 0) {
    double v, e, at;
    cycle([&](double th) { return dc::EvaluateCam(cam, th).pitch_curvature; }, v, e, at);
    // The profile's smallest convex radius 1/κ − r_f against the margin (+∞ when nowhere convex).
    VerifiedLimit c;
    c.limit = "radius_margin_mm";
    c.where = "smallest convex radius of curvature at " + std::to_string(at).substr(0, 7) + " deg";
    const double rho = v > 0 ? 1.0 / v - cam.roller_radius : kInf;
    const double rho_coarse = v - e > 0 ? 1.0 / (v - e) - cam.roller_radius : kInf;
    c.limit_value = margin, c.accurate_value = std::isfinite(rho) ? rho : 1e300;
    c.estimated_error = std::isfinite(rho_coarse) && std::isfinite(rho) ? std::abs(rho_coarse - rho) : 0.0;
    c.upper = false;
    out.checks.push_back(c);
  }
  if (!objective_only && spec.stroke_mm) {
    double hi, ehi, athi, lo, elo, atlo;
    cycle([&](double th) { return cam.motion.Evaluate(th).s; }, hi, ehi, athi);
    cycle([&](double th) { return -cam.motion.Evaluate(th).s; }, lo, elo, atlo);
    VerifiedLimit c;
    c.limit = "stroke_mm";
    c.where = "highest follower position";
    c.limit_value = *spec.stroke_mm, c.accurate_value = hi, c.estimated_error = ehi, c.upper = true;
    out.checks.push_back(c);
    c.where = "lowest follower position (below the base circle: negative)";
    c.limit_value = 0.0, c.accurate_value = -lo, c.estimated_error = elo, c.upper = false;
    out.checks.push_back(c);
  }
  if (!objective_only && spec.contact_stress_MPa) {
    const double w = dc::RadPerSecond(spec.speed_rpm);
    double v, e, at;
    bool undercut_loaded = false;
    cycle([&](double th) {
      const dc::CamPoint<double> p = dc::EvaluateCam(cam, th);
      const double f = dc::CamLoadAt(p, *spec.loads, w).contact_force;
      const double s = dc::RollerCamContactStress(p, cam.roller_radius, f, spec.face_width_mm, spec.composite_modulus_MPa);
      if (!std::isfinite(s)) undercut_loaded = true;
      return std::isfinite(s) ? s : -kInf;
    }, v, e, at);
    VerifiedLimit c;
    c.limit = "contact_stress_MPa";
    c.where = "largest Hertz stress (kinetostatic load at the study's speed) at " + std::to_string(at).substr(0, 7) + " deg";
    c.limit_value = *spec.contact_stress_MPa;
    c.accurate_value = undercut_loaded ? std::numeric_limits<double>::quiet_NaN() : v;
    c.estimated_error = e, c.upper = true;
    out.checks.push_back(c);
  }
  out.model = "kinematics on " + std::to_string(n) + " cam angles (" + std::to_string(spec.accurate_factor) +
              " times the fast rows'), each peak within 1% of the largest refined by golden-section search";
  // The objective.
  switch (spec.objective) {
    case MotionObjective::kPeakAcceleration:
    case MotionObjective::kPeakJerk: {
      const bool acc = spec.objective == MotionObjective::kPeakAcceleration;
      double v, e, at;
      cycle([&](double th) {
        if (!inside(th)) return -kInf;
        const motion::Svaj<double> m = cam.motion.Evaluate(th);
        return std::abs(acc ? m.a : m.j);
      }, v, e, at);
      out.objective = v, out.objective_error = e, out.objective_at_deg = at;
      out.objective_where = std::string("largest |") + (acc ? "S''" : "S'''") + "| on the optimized segments";
      break;
    }
    case MotionObjective::kMaxContactForce: {
      if (!spec.follower) {
        const double w = dc::RadPerSecond(spec.speed_rpm);
        double v, e, at;
        cycle([&](double th) {
          const dc::CamPoint<double> p = dc::EvaluateCam(cam, th);
          return dc::FollowerAxialForce(*spec.loads, p.s, p.d2s, w) / std::cos(p.pressure_angle);
        }, v, e, at);
        out.objective = v, out.objective_error = e, out.objective_at_deg = at;
        out.objective_where = "largest kinetostatic normal contact force";
      } else {
        // CVODE's response on the dense grid: F_a/cos φ at every sample; the error is the change
        // from every factor-th sample (the fast grid's spacing) to all of them.
        const dc::FollowerDynamicsResult r =
            dc::SimulateFollower(CvodeInput(spec, cam, spec.speed_rpm, 1e-10, n));
        double best = -kInf, coarse = -kInf, at = 0;
        for (size_t i = 0; i < r.samples.size(); ++i) {
          const double th = r.samples[i].cam_angle_deg * kDeg;
          const double f = r.samples[i].axial_force_N / std::cos(dc::EvaluateCam(cam, th).pressure_angle);
          if (f > best) best = f, at = r.samples[i].cam_angle_deg;
          if (i % size_t(spec.accurate_factor) == 0) coarse = std::max(coarse, f);
        }
        out.objective = best, out.objective_error = best - coarse, out.objective_at_deg = at;
        out.objective_where = "largest dynamic normal contact force (CVODE, " + std::to_string(n) + " samples)";
      }
      break;
    }
    case MotionObjective::kResidualVibration: {
      double worst = -1, worst_err = 0;
      for (double rpm : spec.objective_speeds_rpm) {
        const double w = dc::RadPerSecond(rpm);
        const dc::FollowerDynamicsResult fine = dc::SimulateFollower(CvodeInput(spec, cam, rpm, 1e-10, n));
        const dc::FollowerDynamicsResult coarse = dc::SimulateFollower(CvodeInput(spec, cam, rpm, 1e-8, n));
        double start = 0;
        std::vector<double> starts;
        for (const auto& s : cam.motion.segments()) starts.push_back(start), start += s.duration;
        for (const OptimizedSegment& o : spec.segments) {
          const int d = DwellAfter(spec, o);
          if (d < 0) continue;
          const double beta = cam.motion.segments()[size_t(d)].duration;
          const double a = FittedResidual(spec, fine, starts[size_t(d)], beta, w);
          const double b = FittedResidual(spec, coarse, starts[size_t(d)], beta, w);
          MotionAccurate::Residual res{o.segment, rpm, a, 0.0, std::abs(a - b)};
          out.residuals.push_back(res);
          if (!std::isfinite(a) || a > worst) {
            worst = std::isfinite(a) ? a : kInf;
            worst_err = std::abs(a - b);
            out.objective_at_deg = starts[size_t(d)] / kDeg;
          }
        }
      }
      out.objective = worst, out.objective_error = worst_err;
      out.objective_where = "largest residual vibration amplitude in the dwell after an optimized segment";
      out.model += "; the response by CVODE (error control 1e-10, contact events) on " + std::to_string(n) +
                   " samples a revolution, the residual amplitude fitted to the dwell's free response (error: "
                   "against CVODE at 1e-8)";
      break;
    }
  }
  // No separation up to a speed: CVODE at 4K speeds; the error is the change from the K fast speeds.
  if (!objective_only && spec.no_separation_up_to_rpm) {
    const int k = 4 * spec.separation_speeds;
    double lowest = kInf, lowest_fast = kInf;
    out.lowest_separation_rpm = 0;
    const Layout l = MakeLayout(spec);
    for (int j = 1; j <= k; ++j) {
      const double rpm = *spec.no_separation_up_to_rpm * j / k;
      const dc::FollowerDynamicsResult r = dc::SimulateFollower(CvodeInput(spec, cam, rpm, 1e-9, 720));
      double v = r.min_axial_force_N;
      if (r.separates) {
        // How far from contact: the smallest force of the follower held on the cam (negative: the
        // cam would have to pull), so that the loop can tighten by a finite excess.
        const dc::ContactResponse<double> held =
            dc::IntegrateInContact(cam.motion, *spec.follower, dc::RadPerSecond(rpm), spec.revolutions, l.grid);
        v = std::min(-1e-9, *std::min_element(held.axial.begin(), held.axial.end()));
        if (out.lowest_separation_rpm == 0) out.lowest_separation_rpm = rpm;
      }
      if (v < lowest) lowest = v, out.weakest_contact_rpm = rpm;
      if (j % 4 == 0) lowest_fast = std::min(lowest_fast, v);
    }
    VerifiedLimit c;
    c.limit = "no_separation_up_to_rpm";
    c.where = "smallest axial force of the follower at " + std::to_string(k) + " speeds up to the limit [N]";
    c.limit_value = 0.0;
    c.accurate_value = lowest;
    // A separation seen is not within an error: the limit fails. Otherwise the error is the speed
    // sampling's (the K fast speeds against all 4K) plus the integration's at the weakest speed:
    // the change from a run at 1e-8. (disc_cam_motion.json: 16.898045 N at 1e-9, 16.898001 at
    // 1e-8; 1e-10 / 1e-11 / 1e-12 converge to 16.8980715: the 1e-9 value is 2.7e-5 N off, the
    // estimate 4.4e-5 N; the sampling part alone was 0.)
    double integration = 0.0;
    if (out.lowest_separation_rpm == 0 && out.weakest_contact_rpm > 0) {
      const dc::FollowerDynamicsResult coarse =
          dc::SimulateFollower(CvodeInput(spec, cam, out.weakest_contact_rpm, 1e-8, 720));
      integration = coarse.separates ? kInf : std::abs(coarse.min_axial_force_N - lowest);
    }
    c.estimated_error = out.lowest_separation_rpm > 0 ? 0.0 : std::abs(lowest_fast - lowest) + integration;
    c.upper = false;
    out.checks.push_back(c);
    out.model += "; separation by CVODE (1e-9, contact events) at " + std::to_string(k) +
                 " speeds, the weakest again at 1e-8 for the integration's error";
  }
  out.objective_fast = FastObjective(spec, cam);
  return out;
}

}  // namespace camopt::objectives
