#include "model/disc_cam/follower_dynamics.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>

#include "model/common/cvode.h"
namespace camopt::disc_cam {
namespace {

constexpr double kDeg = kPi / 180.0;

// Whether a step whose force is a0, a1, a2 at its start, middle and end (all three already
// recorded) may hold, between those samples, an extreme beyond `extreme`, the largest (sign +1)
// or smallest (sign −1) so far; such a step is refined by golden-section search on CVODE's dense
// output (42 interpolations). The parabola through the samples locates the step's extreme: where
// it does not curve toward the extreme, or its vertex lies outside the step (an eighth of the
// step of slack at either end), the step is monotone toward an end already recorded. Otherwise the vertex value
// predicts the extreme; it departs from the solution's polynomial by O(h³), far less than the
// curvature term |a0 − 2a1 + a2| / 4 (the steps are at most 1/40 of the natural period), added
// as the margin: refined when the prediction plus that margin reaches past the extreme so far.
// The earlier test (every step with a sample within 1e-3 of the force range) refined 34 % of a
// revolution's steps of disc_cam_jump's follower (every step of a rising stretch and of a dwell's
// ripple) to the same extremes.
bool MayHoldExtreme(double a0, double a1, double a2, double sign, double extreme, double span) {
  const double b0 = sign * a0, b1 = sign * a1, b2 = sign * a2, e = sign * extreme;
  const double curvature = b0 - 2 * b1 + b2;  // < 0: the parabola peaks (toward the extreme)
  if (!(curvature < 0) || std::abs(b0 - b2) > -2.5 * curvature) return false;
  const double vertex = b1 - (b2 - b0) * (b2 - b0) / (8 * curvature);
  return vertex + 0.25 * std::abs(curvature) + 1e-12 * span > e;
}

struct Model {
  const FollowerDynamicsInput* in;
  double mass;     // [kg · 1e-3]: m ẍ[mm/s²] · 1e-3 = F [N]
  double damping;  // c [N·s/mm]
  double hold;     // F₀ + P + W [N]
  bool contact = true;
  std::exception_ptr error;
};

// The state integrated is the follower's deflection from the cam, u = x − S, and its rate
// w = ẋ − Ṡ: the error control acts on the elastic motion, and the switching functions are the
// state itself (no cancellation of S − x near a contact event).
struct State {
  double s, x;    // S and x [mm]
  double axial;   // F_a = −k_f u − c w while in contact (may be < 0 before the event is located) [N]
  double dw;      // ẇ = ẍ − S̈ [mm/s²]
};

State Evaluate(const Model& md, double t, double u, double uw) {
  const FollowerDynamicsInput& in = *md.in;
  const double w = in.speed_rad_s;
  const motion::Svaj<double> k = in.motion.Evaluate(w * t);
  State st;
  st.s = k.s;
  st.x = u + k.s;
  st.axial = -in.follower_stiffness_N_per_mm * u - md.damping * uw;
  const double push = md.contact ? st.axial : 0.0;
  st.dw = (push - in.loads.spring_rate_N_per_mm * st.x - md.hold) / md.mass - k.a * w * w;
  return st;
}

int RightHandSide(sunrealtype t, N_Vector y, N_Vector ydot, void* data) {
  Model& md = *static_cast<Model*>(data);
  try {
    const double* v = N_VGetArrayPointer(y);
    double* d = N_VGetArrayPointer(ydot);
    d[0] = v[1];
    d[1] = Evaluate(md, t, v[0], v[1]).dw;
    return std::isfinite(d[1]) ? 0 : 1;
  } catch (...) {
    md.error = std::current_exception();
    return -1;
  }
}

// g₀ = F_a (contact lost where it falls through 0), g₁ = S − x (contact back where the mass reaches
// the cam again); the mode says which of them switches.
int Switching(sunrealtype t, N_Vector y, sunrealtype* g, void* data) {
  Model& md = *static_cast<Model*>(data);
  try {
    const double* v = N_VGetArrayPointer(y);
    const State st = Evaluate(md, t, v[0], v[1]);
    g[0] = st.axial;
    g[1] = -v[0];
    return 0;
  } catch (...) {
    md.error = std::current_exception();
    return -1;
  }
}

void Require(int flag, const char* what) { RequireCvode(flag, "follower dynamics", what); }

}  // namespace

FollowerDynamicsResult SimulateFollower(const FollowerDynamicsInput& in) {
  const FollowerLoads& f = in.loads;
  if (!(f.mass_kg > 0.0)) throw std::invalid_argument("follower dynamics: mass must be > 0");
  if (!(in.follower_stiffness_N_per_mm > 0.0))
    throw std::invalid_argument("follower dynamics: follower stiffness must be > 0");
  if (!(f.spring_rate_N_per_mm >= 0.0)) throw std::invalid_argument("follower dynamics: spring rate must be >= 0");
  if (!(in.damping_ratio >= 0.0)) throw std::invalid_argument("follower dynamics: damping ratio must be >= 0");
  if (!(in.speed_rad_s > 0.0)) throw std::invalid_argument("follower dynamics: speed must be > 0");
  if (in.revolutions < 1 || in.samples < 2) throw std::invalid_argument("follower dynamics: revolutions, samples");
  if (in.motion.segments().empty()) throw std::invalid_argument("follower dynamics: no motion");

  Model md{&in, f.mass_kg * 1e-3, 0.0, f.spring_preload_N + f.external_load_N + f.weight_N, true, nullptr};
  const double k_total = in.follower_stiffness_N_per_mm + f.spring_rate_N_per_mm;
  md.damping = 2.0 * in.damping_ratio * std::sqrt(k_total * md.mass);
  const double omega_n = std::sqrt(k_total / md.mass);
  FollowerDynamicsResult out;
  out.natural_frequency_Hz = omega_n / (2 * kPi);

  const double w = in.speed_rad_s, period = in.motion.Period() / w;  // one revolution [s]
  const double t_end = period * in.revolutions, t_last = period * (in.revolutions - 1);
  // Static equilibrium on the cam at θ = 0 (S' and S'' taken as they are there).
  const motion::Svaj<double> k0 = in.motion.Evaluate(0.0);
  const double u0 = (in.follower_stiffness_N_per_mm * k0.s - md.hold) / k_total - k0.s, w0 = 0.0;

  // The dwells, for the residual vibration: [start, end) cam angles [rad] of each kDwell segment.
  std::vector<std::pair<double, double>> dwells;
  {
    double start = 0.0;
    for (const auto& seg : in.motion.segments()) {
      if (seg.law == motion::MotionLaw::kDwell) dwells.push_back({start, start + seg.duration});
      start += seg.duration;
    }
  }
  auto angle_deg = [&](double t) {
    const double a = std::fmod(w * (t - t_last), in.motion.Period()) / kDeg;
    return a < 0 ? a + 360.0 : a;
  };
  auto in_dwell = [&](double t) {
    const double a = std::fmod(w * t, in.motion.Period());
    for (const auto& [lo, hi] : dwells)
      if (a >= lo && a < hi) return true;
    return false;
  };
  bool first_min = true, first_max = true;
  // The quantities of the last revolution at one state.
  auto record = [&](double t, double u, double uw) {
    if (t < t_last * (1 - 1e-12)) return;
    const State st = Evaluate(md, t, u, uw);
    const double x = st.x;
    const double axial = md.contact ? std::max(st.axial, 0.0) : 0.0;  // ≤ 0 only at a located loss
    if (first_min || axial < out.min_axial_force_N)
      out.min_axial_force_N = axial, out.min_axial_force_cam_angle_deg = angle_deg(t), first_min = false;
    if (first_max || axial > out.max_axial_force_N)
      out.max_axial_force_N = axial, out.max_axial_force_cam_angle_deg = angle_deg(t), first_max = false;
    if (in_dwell(t)) {
      const double x_static = (in.follower_stiffness_N_per_mm * st.s - md.hold) / k_total;
      if (std::abs(x - x_static) > out.residual_vibration_mm)
        out.residual_vibration_mm = std::abs(x - x_static), out.residual_vibration_cam_angle_deg = angle_deg(t);
    }
  };

  CvodeSolver sv;
  const double start[2] = {u0, w0};
  // Adams–Moulton, not BDF: the follower on its stiffness is a lightly damped oscillator, which
  // BDF above order 2 damps and so resolves with small steps. Measured on a 3-4-5 rise (1 kg,
  // k_f 100 and 1500 N/mm, ζ 0.05, 300 and 600 rpm) at 1e-9: 1.5–2.9 times fewer steps, and the
  // force extremes within 2e-8 of a 1e-12 run for both methods (Adams 0.3–7 µN, BDF 1–5 µN).
  StartBdfDense(sv, start, 2, RightHandSide, &md, in.relative_tolerance, in.absolute_tolerance, Switching, 2,
                "follower dynamics", CV_ADAMS);
  double* y = N_VGetArrayPointer(sv.y);
  // At most 0.5° of cam and a 40th of the natural period per step, so that no contact opens and
  // closes unseen within a step and the dense output resolves the vibration.
  const double h_max = std::min(0.5 * kDeg / w, 2 * kPi / omega_n / 40.0);
  auto configure = [&]() {
    Require(CVodeSetMaxStep(sv.mem, h_max), "CVodeSetMaxStep");
    Require(CVodeSetStopTime(sv.mem, t_end), "CVodeSetStopTime");
    Require(CVodeSetMaxNumSteps(sv.mem, -1), "CVodeSetMaxNumSteps");
  };
  configure();

  auto dense = [&](double tq) {
    Require(CVodeGetDky(sv.mem, tq, 0, sv.dense), "CVodeGetDky");
    const double* yd = N_VGetArrayPointer(sv.dense);
    return std::pair<double, double>{yd[0], yd[1]};
  };
  // Golden section on [a, b] for the extreme of pick (larger is better) on the dense output.
  auto refine = [&](double a, double b, auto pick) {
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    auto value = [&](double tq) {
      const auto [x, v] = dense(tq);
      record(tq, x, v);
      return pick(tq, x, v);
    };
    double c = b - g * (b - a), d = a + g * (b - a), fc = value(c), fd = value(d);
    for (int it = 0; it < 40; ++it) {
      if (fc > fd) b = d, d = c, fd = fc, c = b - g * (b - a), fc = value(c);
      else a = c, c = d, fc = fd, d = a + g * (b - a), fd = value(d);
    }
  };
  auto axial_of = [&](double tq, double u, double uw) {
    return md.contact ? std::max(Evaluate(md, tq, u, uw).axial, 0.0) : 0.0;
  };
  auto vibration_of = [&](double tq, double u, double uw) {
    if (!in_dwell(tq)) return 0.0;
    const State st = Evaluate(md, tq, u, uw);
    return std::abs(st.x - (in.follower_stiffness_N_per_mm * st.s - md.hold) / k_total);
  };

  record(0.0, u0, w0);
  double t = 0.0;
  long counted = 0;
  int next_sample = 0;  // samples k of the last revolution at t_last + k·period/samples
  auto sample = [&](double tq, double u, double uw) {
    const State st = Evaluate(md, tq, u, uw);
    const motion::Svaj<double> k = in.motion.Evaluate(w * tq);
    out.samples.push_back({angle_deg(tq), st.s, st.x, md.contact ? std::max(st.axial, 0.0) : 0.0,
                           FollowerAxialForce(f, k.s, k.a, w)});
  };
  while (t < t_end) {
    double t_ret = t;
    const int flag = CVode(sv.mem, t_end, sv.y, &t_ret, CV_ONE_STEP);
    if (md.error) std::rethrow_exception(md.error);
    if (flag < 0)
      throw std::runtime_error("follower dynamics: the integration failed at t = " + std::to_string(t) +
                               " s (CVODE flag " + std::to_string(flag) + "): loosen the tolerances");
    long nst = 0;
    CVodeGetNumSteps(sv.mem, &nst);
    if (counted + nst > in.max_steps)
      throw std::runtime_error("follower dynamics: more than " + std::to_string(in.max_steps) + " solver steps");
    record(t_ret, y[0], y[1]);
    for (; next_sample < in.samples; ++next_sample) {
      const double tq = t_last + period * next_sample / in.samples;
      if (tq > t_ret) break;
      if (tq < t) continue;  // before this step: only at the very start (t_last = 0)
      const auto [xs, vs] = tq == t_ret ? std::pair<double, double>{y[0], y[1]} : dense(tq);
      sample(tq, xs, vs);
    }
    if (t_ret > t && t_ret >= t_last) {
      const double lo = std::max(t, t_last);
      const auto [xm, vm] = dense(0.5 * (lo + t_ret));
      record(0.5 * (lo + t_ret), xm, vm);
      // Refine where a step holds a value near the extremes so far.
      const auto [x_lo, v_lo] = dense(lo);  // interpolated once, used by every test below
      const double a_lo = axial_of(lo, x_lo, v_lo), a_mid = axial_of(0.5 * (lo + t_ret), xm, vm),
                   a_hi = axial_of(t_ret, y[0], y[1]);
      const double span = std::max(1.0, std::abs(out.max_axial_force_N - out.min_axial_force_N));
      if (MayHoldExtreme(a_lo, a_mid, a_hi, -1.0, out.min_axial_force_N, span))
        refine(lo, t_ret, [&](double tq, double x, double v) { return -axial_of(tq, x, v); });
      if (MayHoldExtreme(a_lo, a_mid, a_hi, 1.0, out.max_axial_force_N, span))
        refine(lo, t_ret, axial_of);
      if (!dwells.empty() && (in_dwell(lo) || in_dwell(t_ret)) &&
          std::max(vibration_of(lo, x_lo, v_lo), vibration_of(t_ret, y[0], y[1])) >
              (1 - 1e-2) * out.residual_vibration_mm)
        refine(lo, t_ret, vibration_of);
    }
    t = t_ret;
    if (flag == CV_ROOT_RETURN) {
      int found[2] = {0, 0};
      Require(CVodeGetRootInfo(sv.mem, found), "CVodeGetRootInfo");
      bool switched = false;
      if (md.contact && found[0] < 0) {
        md.contact = false, switched = true;
        if (t >= t_last && !out.separates) out.separates = true, out.first_separation_cam_angle_deg = angle_deg(t);
      } else if (!md.contact && found[1] > 0) {
        md.contact = true, switched = true;
      }
      if (switched) {
        ++out.events;
        counted += nst;
        Require(CVodeReInit(sv.mem, t, sv.y), "CVodeReInit");
        configure();
      }
    }
    if (flag == CV_TSTOP_RETURN) break;
  }
  long nst = 0;
  CVodeGetNumSteps(sv.mem, &nst);
  out.steps = counted + nst;
  // Separation shows as a zero force; a contact lost during the last revolution's first instant
  // (or carried over from the previous one) also counts.
  if (out.min_axial_force_N <= 0.0 && !out.separates) {
    out.separates = true;
    out.first_separation_cam_angle_deg = out.min_axial_force_cam_angle_deg;
  }
  return out;
}

DynamicJumpSpeed FindDynamicJumpSpeed(FollowerDynamicsInput in, double upper_rad_s, int scan_steps,
                                      double relative_width) {
  if (!(upper_rad_s > 0) || !std::isfinite(upper_rad_s) || scan_steps < 1 || !(relative_width > 0))
    throw std::invalid_argument("dynamic jump speed: needs an upper speed > 0, scan steps >= 1 and a width > 0");
  DynamicJumpSpeed out;
  out.scan_step_rad_s = upper_rad_s / scan_steps;
  auto separates = [&](double w) {
    in.speed_rad_s = w;
    ++out.runs;
    return SimulateFollower(in).separates;
  };
  double lo = 0.0, hi = 0.0;
  for (int k = 1; k <= scan_steps && !out.found; ++k) {
    const double w = k * out.scan_step_rad_s;
    if (separates(w)) out.found = true, hi = w;
    else lo = w;
  }
  if (!out.found) {
    out.lower_rad_s = lo;
    return out;
  }
  while (hi - lo > relative_width * hi) {
    const double mid = 0.5 * (lo + hi);
    (separates(mid) ? hi : lo) = mid;
  }
  out.speed_rad_s = hi;
  out.lower_rad_s = lo;
  return out;
}

FollowerDynamicsInput ArmAsFollower(const ArmDynamicsInput& in) {
  const ArmLoads& a = in.loads;
  if (!(a.inertia_kg_m2 > 0.0)) throw std::invalid_argument("arm dynamics: the arm's inertia must be > 0");
  if (!(in.arm_stiffness_N_m_per_rad > 0.0)) throw std::invalid_argument("arm dynamics: the arm stiffness must be > 0");
  if (!(a.spring_rate_N_m_per_rad >= 0.0)) throw std::invalid_argument("arm dynamics: spring rate must be >= 0");
  FollowerDynamicsInput f;
  f.motion = in.motion;
  f.loads.mass_kg = a.inertia_kg_m2 * 1e3;  // m [kg]·10⁻³·ẍ = J ψ̈: ψ plays x in "mm"
  f.loads.spring_rate_N_per_mm = a.spring_rate_N_m_per_rad;
  f.loads.spring_preload_N = a.spring_preload_N_m;
  f.loads.external_load_N = a.external_moment_N_m;
  f.loads.weight_N = 0.0;
  f.follower_stiffness_N_per_mm = in.arm_stiffness_N_m_per_rad;
  f.damping_ratio = in.damping_ratio;
  f.speed_rad_s = in.speed_rad_s;
  f.revolutions = in.revolutions;
  f.relative_tolerance = in.relative_tolerance;
  f.absolute_tolerance = in.absolute_tolerance;
  f.max_steps = in.max_steps;
  f.samples = in.samples;
  return f;
}

ArmDynamicsResult SimulateArm(const ArmDynamicsInput& in) {
  const FollowerDynamicsResult f = SimulateFollower(ArmAsFollower(in));
  ArmDynamicsResult out;
  out.natural_frequency_Hz = f.natural_frequency_Hz;
  out.min_contact_moment_N_m = f.min_axial_force_N;
  out.min_contact_moment_cam_angle_deg = f.min_axial_force_cam_angle_deg;
  out.max_contact_moment_N_m = f.max_axial_force_N;
  out.max_contact_moment_cam_angle_deg = f.max_axial_force_cam_angle_deg;
  out.separates = f.separates;
  out.first_separation_cam_angle_deg = f.first_separation_cam_angle_deg;
  out.residual_vibration_rad = f.residual_vibration_mm;
  out.residual_vibration_cam_angle_deg = f.residual_vibration_cam_angle_deg;
  out.samples.reserve(f.samples.size());
  for (const FollowerDynamicsSample& q : f.samples)
    out.samples.push_back({q.cam_angle_deg, q.cam_follower_mm, q.follower_mm, q.axial_force_N, q.kinetostatic_force_N});
  out.steps = f.steps;
  out.events = f.events;
  return out;
}

DynamicJumpSpeed FindArmDynamicJumpSpeed(const ArmDynamicsInput& in, double upper_rad_s, int scan_steps,
                                         double relative_width) {
  return FindDynamicJumpSpeed(ArmAsFollower(in), upper_rad_s, scan_steps, relative_width);
}

}  // namespace camopt::disc_cam
