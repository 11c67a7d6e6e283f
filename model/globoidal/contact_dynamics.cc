#include "model/globoidal/contact_dynamics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>

#include "model/common/cvode.h"
namespace camopt::globoidal {
namespace {

// Per-roller contact data at one cam angle: stiffness, the projection e_φ · n_j, the pressure
// angle and the equivalent radius of eq. (12) [mm].
struct RollerContact {
  double stiffness, swing_dot_normal, pressure_angle, radius;
};

RollerContact Contact(const DynamicsInput& in, int j, double theta) {
  const SurfacePoint<double> p = EvaluateSurface(in.cam, j, ContactArm(in), theta);
  const double inv_r = 1.0 / in.cam.roller_radius + p.working_curvature;
  if (!(inv_r > 0.0) || !std::isfinite(inv_r))
    throw std::domain_error("globoidal contact: the working surface is conformal with or undercut "
                            "by the roller at cam angle " + std::to_string(theta * 180 / kPi) +
                            " deg");
  const ContactMaterial& c = in.contact;
  const double k = contact::PointContactStiffness(1.0 / inv_r, c.composite_modulus_MPa());  // eqs. (11)–(12)
  return {k, p.swing_dir.dot(p.normal), p.pressure_angle, 1.0 / inv_r};
}

// Hertz line contact of the roller's generator along its whole length m (Johnson §4.2:
// p0 = √(F E* / (π m R))): the working surface is the roller's envelope, so they touch along a line.
double LineStress(const DynamicsInput& in, double force, double radius) {
  return force > 0.0 ? contact::LineContactPeakPressure(force, in.cam.roller_length, radius,
                                                        in.contact.composite_modulus_MPa())
                     : 0.0;
}

// The state integrated: the deviation from the kinematic motion, u = ψ − φ_i(θ) and
// w = ψ̇ − φ_i' ω, so that the error control acts on the elastic motion itself.
struct Eval {
  double acc;                     // ψ̈
  double delta[2], delta_rate[2];
  double law[2];                  // ContactLaw: > 0 exactly where roller j carries a force
  double force[2], elastic;
  double radius[2];               // eq. (12) equivalent radius of roller j [mm]
  motion::Svaj<double> kin;
};

// The forces of the rollers in contact (active) follow the smooth contact law; the others carry
// none. With active = law > 0 this is eq. (10) with the no-adhesion clip.
Eval Evaluate(const DynamicsInput& in, double t, double u, double w, const bool active[2]) {
  const double omega = in.cam_speed_rad_s;
  const double theta = in.start_cam_angle_rad + omega * t;
  const double l = ContactArm(in), p = in.cam.direction;
  const ContactMaterial& c = in.contact;
  Eval e{};
  e.kin = in.cam.motion.Evaluate(theta);
  double q = -in.load_torque_Nmm;  // against the first motion, i.e. against ψ
  for (int j = 0; j < 2; ++j) {
    const RollerContact rc = Contact(in, j + 1, theta);
    const double delta = l * p * u * rc.swing_dot_normal;
    const double delta_rate = l * p * w * rc.swing_dot_normal;
    e.delta[j] = delta;
    e.delta_rate[j] = delta_rate;
    e.radius[j] = rc.radius;
    e.law[j] = ContactLaw(delta, delta_rate, rc.stiffness, c.exponent, c.max_damping_Ns_per_mm,
                          c.penetration_depth_mm);
    const double f = active[j] ? e.law[j] : 0.0;
    e.force[j] = f;
    if (delta > 0.0) e.elastic += rc.stiffness * std::pow(delta, c.exponent + 1) / (c.exponent + 1);
    q += p * l * (-f * rc.swing_dot_normal);  // moment of −F n_j about the turret axis, along ψ
  }
  e.acc = q / in.inertia_Nmms2;
  return e;
}

void Check(const DynamicsInput& in) {
  if (!(in.inertia_Nmms2 > 0.0)) throw std::invalid_argument("globoidal dynamics: inertia <= 0");
  if (!(in.end_time_s >= 0.0) || !std::isfinite(in.end_time_s))
    throw std::invalid_argument("globoidal dynamics: bad end time");
  if (!(in.relative_tolerance >= 1e-14 && in.relative_tolerance <= 1e-2))
    throw std::invalid_argument("globoidal dynamics: relative tolerance outside [1e-14, 1e-2]");
  if (!(in.absolute_tolerance > 0.0 && in.absolute_tolerance <= 1e-2))
    throw std::invalid_argument("globoidal dynamics: absolute tolerance outside (0, 1e-2]");
  if (!(in.max_steps >= 1.0)) throw std::invalid_argument("globoidal dynamics: max_steps < 1");
  if (!std::isfinite(in.output_interval_s))
    throw std::invalid_argument("globoidal dynamics: bad output interval");
}

// What CVODE's callbacks see. Exceptions must not cross the C library: the right-hand side and
// the root function catch them, keep them here and return −1 (unrecoverable).
struct Problem {
  const DynamicsInput* in;
  bool active[2];
  std::exception_ptr error;
  long evaluations = 0;
};

int RightHandSide(sunrealtype t, N_Vector y, N_Vector ydot, void* data) {
  Problem& pb = *static_cast<Problem*>(data);
  try {
    const double* v = N_VGetArrayPointer(y);
    const Eval e = Evaluate(*pb.in, t, v[0], v[1], pb.active);
    const double omega = pb.in->cam_speed_rad_s;
    double* d = N_VGetArrayPointer(ydot);
    d[0] = v[1];
    d[1] = e.acc - e.kin.a * omega * omega;
    ++pb.evaluations;
    return std::isfinite(d[1]) ? 0 : 1;  // 1: recoverable, CVODE retries with a smaller step
  } catch (...) {
    pb.error = std::current_exception();
    return -1;
  }
}

// g_j = the contact law of roller j: it changes sign exactly where the force law switches
// (onset and loss of contact, whether by δ reaching 0 or by the damping pulling the force to 0).
int SwitchingFunctions(sunrealtype t, N_Vector y, sunrealtype* g, void* data) {
  Problem& pb = *static_cast<Problem*>(data);
  try {
    const double* v = N_VGetArrayPointer(y);
    const Eval e = Evaluate(*pb.in, t, v[0], v[1], pb.active);
    g[0] = e.law[0];
    g[1] = e.law[1];
    return 0;
  } catch (...) {
    pb.error = std::current_exception();
    return -1;
  }
}

void Require(int flag, const char* what) { RequireCvode(flag, "globoidal dynamics", what); }

std::string Num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

}  // namespace

double RollerStiffness(const DynamicsInput& in, int j, double theta) {
  return Contact(in, j, theta).stiffness;
}

double QuasiStaticForce(const DynamicsInput& in, double theta) {
  const motion::Svaj<double> kin = in.cam.motion.Evaluate(theta);
  const double p = in.cam.direction, w = in.cam_speed_rad_s;
  const double q = in.inertia_Nmms2 * kin.a * w * w + in.load_torque_Nmm;
  const int j = p * q >= 0.0 ? 1 : 2;  // roller 1 pushes along +p, roller 2 along −p
  const RollerContact rc = Contact(in, j, theta);
  return std::abs(q) / (ContactArm(in) * std::abs(rc.swing_dot_normal));
}

double QuasiStaticContactStress(const DynamicsInput& in, double theta) {
  const motion::Svaj<double> kin = in.cam.motion.Evaluate(theta);
  const double q = in.inertia_Nmms2 * kin.a * in.cam_speed_rad_s * in.cam_speed_rad_s + in.load_torque_Nmm;
  const int j = in.cam.direction * q >= 0.0 ? 1 : 2;
  return LineStress(in, QuasiStaticForce(in, theta), Contact(in, j, theta).radius);
}

DynamicsResult SimulateDynamics(const DynamicsInput& in) {
  Check(in);
  DynamicsResult out;
  out.stiffness[0] = RollerStiffness(in, 1, in.start_cam_angle_rad);
  out.stiffness[1] = RollerStiffness(in, 2, in.start_cam_angle_rad);
  const double omega = in.cam_speed_rad_s, l = ContactArm(in), p = in.cam.direction;
  const double theta0 = in.start_cam_angle_rad, t_end = in.end_time_s;
  double u0 = 0.0, w0 = in.initial_swing_rate_rad_s;
  if (in.start_static) {
    const motion::Svaj<double> kin0 = in.cam.motion.Evaluate(theta0);
    const double q = in.inertia_Nmms2 * kin0.a * omega * omega + in.load_torque_Nmm;
    if (q != 0.0) {
      const int j = p * q >= 0.0 ? 1 : 2;
      const RollerContact rc = Contact(in, j, theta0);
      const double f = std::abs(q) / (l * std::abs(rc.swing_dot_normal));
      const double delta = std::pow(f / rc.stiffness, 1.0 / in.contact.exponent);
      u0 = delta / (l * p * rc.swing_dot_normal);
    }
  }

  Problem pb{&in, {false, false}, nullptr, 0};
  {
    // A roller starts in contact where its law is positive, or zero at δ = 0 and about to
    // penetrate: δ̇ > 0, or δ̇ = 0 and δ̈ > 0 under the free motion (both rollers off).
    const Eval e0 = Evaluate(in, 0.0, u0, w0, pb.active);
    const double free_acc = e0.acc - e0.kin.a * omega * omega;  // ẇ with no contact force
    for (int j = 0; j < 2; ++j) {
      const double arm = l * p * Contact(in, j + 1, theta0).swing_dot_normal;  // δ_j = arm · u
      const bool onset = e0.delta[j] == 0.0 &&
                         (e0.delta_rate[j] > 0.0 || (e0.delta_rate[j] == 0.0 && arm * free_acc > 0.0));
      pb.active[j] = e0.law[j] > 0.0 || (e0.law[j] == 0.0 && onset);
    }
  }

  auto record = [&](double t, double u, double w, std::vector<DynamicsSample>* into) -> DynamicsSample {
    const Eval e = Evaluate(in, t, u, w, pb.active);
    DynamicsSample d{};
    d.time_s = t;
    d.cam_angle_rad = theta0 + omega * t;
    d.kin_swing_rad = e.kin.s;
    d.kin_rate_rad_s = e.kin.v * omega;
    d.kin_acc_rad_s2 = e.kin.a * omega * omega;
    d.swing_rad = e.kin.s + u;
    d.swing_rate_rad_s = d.kin_rate_rad_s + w;
    d.swing_acc_rad_s2 = e.acc;
    for (int j = 0; j < 2; ++j) d.penetration_mm[j] = e.delta[j], d.force_N[j] = e.force[j];
    d.energy_Nmm = 0.5 * in.inertia_Nmms2 * d.swing_rate_rad_s * d.swing_rate_rad_s + e.elastic;
    DynamicsPeaks& k = out.peaks;
    k.swing_rate_rad_s = std::max(k.swing_rate_rad_s, std::abs(d.swing_rate_rad_s));
    if (std::abs(d.swing_acc_rad_s2) > k.swing_acc_rad_s2)
      k.swing_acc_rad_s2 = std::abs(d.swing_acc_rad_s2), k.swing_acc_time_s = t;
    k.kin_rate_rad_s = std::max(k.kin_rate_rad_s, std::abs(d.kin_rate_rad_s));
    k.kin_acc_rad_s2 = std::max(k.kin_acc_rad_s2, std::abs(d.kin_acc_rad_s2));
    for (int j = 0; j < 2; ++j) {
      if (d.force_N[j] > k.force_N[j]) k.force_N[j] = d.force_N[j], k.force_time_s[j] = t;
      const double stress = LineStress(in, d.force_N[j], e.radius[j]);
      if (stress > k.contact_stress_MPa[j]) k.contact_stress_MPa[j] = stress, k.contact_stress_time_s[j] = t;
    }
    k.swing_deviation_rad = std::max(k.swing_deviation_rad, std::abs(u));
    k.penetration_mm = std::max({k.penetration_mm, d.penetration_mm[0], d.penetration_mm[1]});
    if (into) into->push_back(d);
    return d;
  };

  const bool every_step = !(in.output_interval_s > 0.0);
  DynamicsSample last = record(0.0, u0, w0, &out.samples);
  if (t_end == 0.0) return out;

  // BDF (orders 1–5) with Newton iterations on a dense 2×2 system. The contact damping makes the
  // problem stiff once the start transient has decayed (the turret then follows the slow forced
  // motion): on the example at 120 rpm, rtol 1e-8, BDF takes 4.9k steps, Adams–Moulton 36k
  // (bench/globoidal_bench.cc, docs/performance.md).
  CvodeSolver sv;
  const double start[2] = {u0, w0};
  StartBdfDense(sv, start, 2, RightHandSide, &pb, in.relative_tolerance, in.absolute_tolerance, SwitchingFunctions,
                2, "globoidal dynamics");
  double* y = N_VGetArrayPointer(sv.y);
  const double h_max = MaxStep(in);
  auto configure = [&]() {
    Require(CVodeSetMaxStep(sv.mem, h_max), "CVodeSetMaxStep");
    Require(CVodeSetStopTime(sv.mem, t_end), "CVodeSetStopTime");
    Require(CVodeSetMaxNumSteps(sv.mem, -1), "CVodeSetMaxNumSteps");  // the run's limit is ours
  };
  configure();

  double t = 0.0;
  long next_output = 1;  // index of the next output time k·output_interval_s
  long counted_steps = 0, counted_fails = 0;
  double h_min = 0.0, h_big = 0.0;
  auto counters = [&](long* steps, long* fails) {
    long nst = 0, netf = 0;
    CVodeGetNumSteps(sv.mem, &nst);
    CVodeGetNumErrTestFails(sv.mem, &netf);
    *steps = nst, *fails = netf;
  };
  while (t < t_end) {
    double t_ret = t;
    const int flag = CVode(sv.mem, t_end, sv.y, &t_ret, CV_ONE_STEP);
    if (pb.error) std::rethrow_exception(pb.error);
    if (flag < 0) {
      const std::string at = " at t = " + Num(t) + " s";
      switch (flag) {
        case CV_TOO_MUCH_ACC:
          throw DynamicsError("relative_tolerance",
                              "the tolerances are below what double precision can deliver" + at +
                                  ": loosen relative_tolerance/absolute_tolerance");
        case CV_ERR_FAILURE:
        case CV_CONV_FAILURE:
          throw DynamicsError("relative_tolerance",
                              "the solver's step shrank to nothing (repeated error-test or "
                              "convergence failures)" + at + ": loosen relative_tolerance (now " +
                                  Num(in.relative_tolerance) + ") or absolute_tolerance (now " +
                                  Num(in.absolute_tolerance) + ")");
        default:
          throw DynamicsError("relative_tolerance", "the integration failed" + at + " (CVODE flag " +
                                                        std::to_string(flag) + ")");
      }
    }
    double h_last = 0.0;
    CVodeGetLastStep(sv.mem, &h_last);
    if (h_last > 0.0) {
      h_min = h_min == 0.0 ? h_last : std::min(h_min, h_last);
      h_big = std::max(h_big, h_last);
    }
    long nst = 0, netf = 0;
    counters(&nst, &netf);
    if (counted_steps + nst > in.max_steps)
      throw DynamicsError("max_steps", "more than " + std::to_string(long(in.max_steps)) + " solver steps by t = " +
                                           Num(t_ret) + " s of " + Num(t_end) +
                                           " s: loosen relative_tolerance (now " +
                                           Num(in.relative_tolerance) +
                                           "), shorten the run or raise max_steps");
    // Peaks over the interval just integrated, [t, t_ret], from the dense output: its end and
    // midpoint, and where the largest of those three is near the largest value so far, the
    // maximum inside the interval by golden-section search (an oscillation peak falls between
    // steps; this makes the peaks independent of where the steps happen to end).
    const DynamicsSample end = record(t_ret, y[0], y[1], nullptr);
    if (t_ret > t) {
      auto at = [&](double tq) {
        Require(CVodeGetDky(sv.mem, tq, 0, sv.dense), "CVodeGetDky");
        const double* yd = N_VGetArrayPointer(sv.dense);
        return record(tq, yd[0], yd[1], nullptr);
      };
      const DynamicsSample mid = at(0.5 * (t + t_ret));
      using Pick = double (*)(const DynamicsSample&, const DynamicsPeaks&);
      const Pick picks[3][2] = {
          {[](const DynamicsSample& d, const DynamicsPeaks&) { return std::abs(d.swing_acc_rad_s2); },
           [](const DynamicsSample&, const DynamicsPeaks& k) { return k.swing_acc_rad_s2; }},
          {[](const DynamicsSample& d, const DynamicsPeaks&) { return d.force_N[0]; },
           [](const DynamicsSample&, const DynamicsPeaks& k) { return k.force_N[0]; }},
          {[](const DynamicsSample& d, const DynamicsPeaks&) { return d.force_N[1]; },
           [](const DynamicsSample&, const DynamicsPeaks& k) { return k.force_N[1]; }}};
      for (const auto& pick : picks) {
        const double top = std::max({pick[0](last, out.peaks), pick[0](mid, out.peaks),
                                     pick[0](end, out.peaks)});
        if (!(top > 0.0) || top < (1 - 1e-3) * pick[1](end, out.peaks)) continue;
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        double a = t, b = t_ret, c = b - g * (b - a), d = a + g * (b - a);
        double fc = pick[0](at(c), out.peaks), fd = pick[0](at(d), out.peaks);
        for (int it = 0; it < 30; ++it) {
          if (fc > fd) {
            b = d, d = c, fd = fc, c = b - g * (b - a), fc = pick[0](at(c), out.peaks);
          } else {
            a = c, c = d, fc = fd, d = a + g * (b - a), fd = pick[0](at(d), out.peaks);
          }
        }
      }
    }
    // Thinned samples for the CSV, interpolated on their grid.
    if (!every_step) {
      for (;; ++next_output) {
        const double to = next_output * in.output_interval_s;
        if (to > t_ret * (1 + 1e-12) || to > t_end * (1 + 1e-12)) break;
        Require(CVodeGetDky(sv.mem, std::min(to, t_ret), 0, sv.dense), "CVodeGetDky");
        const double* yd = N_VGetArrayPointer(sv.dense);
        record(to, yd[0], yd[1], &out.samples);
      }
    }
    if (every_step || (flag == CV_TSTOP_RETURN && out.samples.back().time_s < t_ret))
      out.samples.push_back(end);
    last = end;
    t = t_ret;
    if (flag == CV_ROOT_RETURN) {
      // A contact opens or closes at t: switch that roller's force law and restart the solver
      // there, so that no step spans the switch.
      int found[2] = {0, 0};
      Require(CVodeGetRootInfo(sv.mem, found), "CVodeGetRootInfo");
      for (int j = 0; j < 2; ++j)
        if (found[j] != 0) pb.active[j] = found[j] > 0;
      ++out.events;
      out.event_times_s.push_back(t);
      counted_steps += nst, counted_fails += netf;
      Require(CVodeReInit(sv.mem, t, sv.y), "CVodeReInit");
      configure();
    }
    if (flag == CV_TSTOP_RETURN) break;
  }
  long nst = 0, netf = 0;
  counters(&nst, &netf);
  out.steps = counted_steps + nst;
  out.error_test_failures = counted_fails + netf;
  out.rhs_evaluations = pb.evaluations;
  out.smallest_step_s = h_min;
  out.largest_step_s = h_big;
  return out;
}

}  // namespace camopt::globoidal
