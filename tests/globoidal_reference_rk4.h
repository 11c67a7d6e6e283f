// An independent reference for the globoidal contact dynamics (tests and benchmarks only):
// classical RK4 at a fixed, tiny step on the turret swing ψ itself (not the deviation that the
// solver integrates), with the clipped force law ImpactForce and no event handling, and the peaks
// taken at every step. It shares only the geometry and the contact law with the model.
#pragma once

#include <algorithm>
#include <cmath>

#include "model/globoidal/contact_dynamics.h"

namespace camopt::globoidal::testing {

struct ReferencePeaks {
  double swing_acc_rad_s2 = 0, force_N[2] = {0, 0};
  double swing_acc_time_s = 0;
  long steps = 0;
};

/// Runs `in` over [0, in.end_time_s] with RK4 at step h (start at the static deflection when
/// in.start_static).
inline ReferencePeaks ReferenceRk4(const DynamicsInput& in, double h) {
  const double omega = in.cam_speed_rad_s, l = ContactArm(in), p = in.cam.direction;
  const double theta0 = in.start_cam_angle_rad;
  const ContactMaterial& c = in.contact;
  struct Acc {
    double acc, force[2];
  };
  auto acc = [&](double t, double psi, double rate) {
    const double theta = theta0 + omega * t;
    const motion::Svaj<double> kin = in.cam.motion.Evaluate(theta);
    Acc a{0, {0, 0}};
    double q = -in.load_torque_Nmm;
    for (int j = 0; j < 2; ++j) {
      const SurfacePoint<double> sp = EvaluateSurface(in.cam, j + 1, l, theta);
      const double n = sp.swing_dir.dot(sp.normal);
      const double k = RollerStiffness(in, j + 1, theta);
      const double f = ImpactForce(l * p * (psi - kin.s) * n, l * p * (rate - kin.v * omega) * n, k,
                                   c.exponent, c.max_damping_Ns_per_mm, c.penetration_depth_mm);
      a.force[j] = f;
      q += p * l * (-f * n);
    }
    a.acc = q / in.inertia_Nmms2;
    return a;
  };
  const motion::Svaj<double> kin0 = in.cam.motion.Evaluate(theta0);
  double psi = kin0.s, rate = kin0.v * omega + in.initial_swing_rate_rad_s;
  if (in.start_static) {
    const double q = in.inertia_Nmms2 * kin0.a * omega * omega + in.load_torque_Nmm;
    if (q != 0.0) {
      const int j = p * q >= 0.0 ? 1 : 2;
      const SurfacePoint<double> sp = EvaluateSurface(in.cam, j, l, theta0);
      const double n = sp.swing_dir.dot(sp.normal);
      const double f = std::abs(q) / (l * std::abs(n));
      psi += std::pow(f / RollerStiffness(in, j, theta0), 1.0 / c.exponent) / (l * p * n);
    }
  }
  ReferencePeaks out;
  auto keep = [&](double t, const Acc& a) {
    if (std::abs(a.acc) > out.swing_acc_rad_s2) out.swing_acc_rad_s2 = std::abs(a.acc), out.swing_acc_time_s = t;
    for (int j = 0; j < 2; ++j) out.force_N[j] = std::max(out.force_N[j], a.force[j]);
  };
  const long n = std::lround(std::ceil(in.end_time_s / h - 1e-9));
  Acc k1 = acc(0.0, psi, rate);
  keep(0.0, k1);
  for (long i = 0; i < n; ++i) {
    const double t = i * h;
    const double p2 = psi + 0.5 * h * rate, r2 = rate + 0.5 * h * k1.acc;
    const Acc k2 = acc(t + 0.5 * h, p2, r2);
    const double p3 = psi + 0.5 * h * r2, r3 = rate + 0.5 * h * k2.acc;
    const Acc k3 = acc(t + 0.5 * h, p3, r3);
    const double p4 = psi + h * r3, r4 = rate + h * k3.acc;
    const Acc k4 = acc(t + h, p4, r4);
    psi += h / 6.0 * (rate + 2 * r2 + 2 * r3 + r4);
    rate += h / 6.0 * (k1.acc + 2 * k2.acc + 2 * k3.acc + k4.acc);
    k1 = acc(t + h, psi, rate);
    keep(t + h, k1);
  }
  out.steps = n;
  return out;
}

}  // namespace camopt::globoidal::testing
