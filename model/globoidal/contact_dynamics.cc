#include "model/globoidal/contact_dynamics.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace camopt::globoidal {
namespace {

// Per-roller contact data at one cam angle: stiffness and the projection e_φ · n_j.
struct RollerContact {
  double stiffness, swing_dot_normal, pressure_angle;
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
  return {k, p.swing_dir.dot(p.normal), p.pressure_angle};
}

struct State {
  double psi, rate;
};

struct Eval {
  double acc;
  double delta[2], force[2], elastic;
};

Eval Evaluate(const DynamicsInput& in, double t, const State& s) {
  const double omega = in.cam_speed_rad_s;
  const double theta = in.start_cam_angle_rad + omega * t;
  const motion::Svaj<double> kin = in.cam.motion.Evaluate(theta);
  const double l = ContactArm(in), p = in.cam.direction;
  const ContactMaterial& c = in.contact;
  Eval e{};
  double q = -in.load_torque_Nmm;  // against the first motion, i.e. against ψ
  for (int j = 0; j < 2; ++j) {
    const RollerContact rc = Contact(in, j + 1, theta);
    const double delta = l * p * (s.psi - kin.s) * rc.swing_dot_normal;
    const double delta_rate = l * p * (s.rate - kin.v * omega) * rc.swing_dot_normal;
    const double f = ImpactForce(delta, delta_rate, rc.stiffness, c.exponent,
                                 c.max_damping_Ns_per_mm, c.penetration_depth_mm);
    e.delta[j] = delta;
    e.force[j] = f;
    if (delta > 0.0) e.elastic += rc.stiffness * std::pow(delta, c.exponent + 1) / (c.exponent + 1);
    q += p * l * (-f * rc.swing_dot_normal);  // moment of −F n_j about the turret axis, along ψ
  }
  e.acc = q / in.inertia_Nmms2;
  return e;
}

void Check(const DynamicsInput& in) {
  if (!(in.inertia_Nmms2 > 0.0)) throw std::invalid_argument("globoidal dynamics: inertia <= 0");
  if (!(in.time_step_s > 0.0) || !(in.end_time_s >= 0.0))
    throw std::invalid_argument("globoidal dynamics: bad time step or end time");
  if (in.end_time_s / in.time_step_s > 5e7)
    throw std::invalid_argument("globoidal dynamics: more than 5e7 steps");
  if (in.output_every < 1) throw std::invalid_argument("globoidal dynamics: output_every < 1");
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

DynamicsResult SimulateDynamics(const DynamicsInput& in) {
  Check(in);
  DynamicsResult out;
  out.stiffness[0] = RollerStiffness(in, 1, in.start_cam_angle_rad);
  out.stiffness[1] = RollerStiffness(in, 2, in.start_cam_angle_rad);
  const double omega = in.cam_speed_rad_s, l = ContactArm(in), p = in.cam.direction;
  const double theta0 = in.start_cam_angle_rad;
  const motion::Svaj<double> kin0 = in.cam.motion.Evaluate(theta0);
  State s{kin0.s, kin0.v * omega + in.initial_swing_rate_rad_s};
  if (in.start_static) {
    const double q = in.inertia_Nmms2 * kin0.a * omega * omega + in.load_torque_Nmm;
    if (q != 0.0) {
      const int j = p * q >= 0.0 ? 1 : 2;
      const RollerContact rc = Contact(in, j, theta0);
      const double f = std::abs(q) / (l * std::abs(rc.swing_dot_normal));
      const double delta = std::pow(f / rc.stiffness, 1.0 / in.contact.exponent);
      s.psi += delta / (l * p * rc.swing_dot_normal);
    }
  }
  const double h = in.time_step_s;
  const long n = std::lround(std::ceil(in.end_time_s / h - 1e-9));
  auto record = [&](double t, const State& st) {
    const Eval e = Evaluate(in, t, st);
    const motion::Svaj<double> kin = in.cam.motion.Evaluate(theta0 + omega * t);
    DynamicsSample d{};
    d.time_s = t;
    d.cam_angle_rad = theta0 + omega * t;
    d.swing_rad = st.psi;
    d.swing_rate_rad_s = st.rate;
    d.swing_acc_rad_s2 = e.acc;
    d.kin_swing_rad = kin.s;
    d.kin_rate_rad_s = kin.v * omega;
    d.kin_acc_rad_s2 = kin.a * omega * omega;
    for (int j = 0; j < 2; ++j) d.penetration_mm[j] = e.delta[j], d.force_N[j] = e.force[j];
    d.energy_Nmm = 0.5 * in.inertia_Nmms2 * st.rate * st.rate + e.elastic;
    out.samples.push_back(d);
  };
  record(0.0, s);
  for (long i = 0; i < n; ++i) {
    const double t = i * h;
    const Eval k1 = Evaluate(in, t, s);
    const State s2{s.psi + 0.5 * h * s.rate, s.rate + 0.5 * h * k1.acc};
    const Eval k2 = Evaluate(in, t + 0.5 * h, s2);
    const State s3{s.psi + 0.5 * h * s2.rate, s.rate + 0.5 * h * k2.acc};
    const Eval k3 = Evaluate(in, t + 0.5 * h, s3);
    const State s4{s.psi + h * s3.rate, s.rate + h * k3.acc};
    const Eval k4 = Evaluate(in, t + h, s4);
    s.psi += h / 6.0 * (s.rate + 2 * s2.rate + 2 * s3.rate + s4.rate);
    s.rate += h / 6.0 * (k1.acc + 2 * k2.acc + 2 * k3.acc + k4.acc);
    if (!std::isfinite(s.psi) || !std::isfinite(s.rate))
      throw std::runtime_error("globoidal dynamics: the integration diverged (time step too large?)");
    if ((i + 1) % in.output_every == 0 || i + 1 == n) record((i + 1) * h, s);
  }
  out.steps = static_cast<int>(n);
  return out;
}

}  // namespace camopt::globoidal
