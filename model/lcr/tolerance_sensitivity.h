// First-order sensitivities of an LCR's roller forces and stress margins to its manufacturing
// deviations (model/lcr/tolerance.h, ToleranceParameters in transmission_error.h), in closed form
// over the design's scalar T (double or a Jet: the caller's Jet then carries ∂²q/∂x∂t exactly).
// The robust sizing rows (objectives/lcr_robust.h) weight these by their tolerance rule.
//
// A roller's force under deviations t is the rigid-law force plus the compliant model's change,
// F_k(t) = F_k^rigid + [F_k^c(t) − F_k^c(0)]; its stress margin is the line-contact margin
// s = 1 − r_r κ − F/(c r_r) at that force with the roller's own radius r_r + Δr_k (the curvature
// at the contact kept nominal). S_p = ∂q/∂t_p at t = 0.
// Linearising the compliant turret (lcr_stiffness.h; arms nominal, no gaps at t = 0):
//   dF_k = F'_k (a_k dψ − dc_k),   dψ = Σ_j F'_j a_j dc_j / Σ_j F'_j a_j²,
// F'_k the contact rigidity at the nominal closure ψ a_k, and the gap's first-order change from
// tolerance.h's c_k = (x_k − X(ψ*))·n_out − Δr_k − δ (the foot point's move is second order, the
// roller centre lies on the pitch curve): dc_k = ν_k·(dO_k − dC) − dr_k − dδ with ν_k = −d_k the
// outward normal at the roller centre (the common normal through the pitch point, contact.h),
//   ∂c_k/∂e = −ν_k·u(θ), ∂c_k/∂r_d = ν_k·u(slot_k), ∂c_k/∂β_k = r_d ν_k·u⊥(slot_k),
//   ∂c_k/∂clearance = −ν_k·G/|G|, ∂c_k/∂r_r,k = ∂c_k/∂δ = −1.
// tests/lcr_robust_test.cc checks them against ceres::Jet through lcr::CompliantAtAngle.
#pragma once

#include <cmath>
#include <vector>

#include "model/common/geometry.h"
#include "model/common/scalar.h"
#include "model/contact/hertz.h"
#include "model/lcr/contact.h"
#include "model/lcr/forces.h"
#include "model/lcr/transmission_error.h"
#include "model/rigidity/lcr_stiffness.h"

namespace camopt::lcr {

/// The deviations that move one cam's rollers (side index 0: input cam, 1: output cam): the
/// eccentricity and the bearing clearance (the cam centre), and that cam's turret radius, rollers,
/// pitch errors and profile.
inline std::vector<ToleranceParameter> SideToleranceParameters(const Reducer<double>& r, const ToleranceBands& b,
                                                               int side) {
  std::vector<ToleranceParameter> out;
  for (const ToleranceParameter& p : ToleranceParameters(r, b))
    if (p.key == 0 || p.key == 5 || p.side == side) out.push_back(p);
  return out;
}

/// The torque one turret reacts [N·mm] at output torque `output_torque_Nmm` (forward sense).
inline double ReactedTurretTorque(const Reducer<double>& r, double output_torque_Nmm, Side side) {
  const double t = LoadedArmSign(r, Side::kOutput) * output_torque_Nmm;
  return side == Side::kOutput ? t : -rigidity::FixedTurretTorqueRatio(r) * t;
}

/// S_p of every roller's force [N per model unit] and stress margin of one cam at θ, [roller][p],
/// over the deviations `params` that move that cam (SideToleranceParameters).
template <typename T>
struct ToleranceSensitivities {
  std::vector<ToleranceParameter> params;
  std::vector<std::vector<T>> force, margin;
};

/// Sensitivities of cam `side` at input angle θ [rad] of design r loaded to `output_torque_Nmm`,
/// from its rigid-law loads sl at θ (AnalyzeAngle). `margin` is left empty when
/// `stress_limit_MPa` is not finite (no stress row).
template <typename T>
ToleranceSensitivities<T> RollerToleranceSensitivities(const Reducer<T>& r, const Material& material,
                                                       double output_torque_Nmm, double stress_limit_MPa,
                                                       const ToleranceBands& bands, Side side, double theta,
                                                       const SideLoads<T>& sl) {
  const int si = SideIndex(side);
  const Reducer<double> rd = r.template cast<double>();
  const CamSide<T>& cam = r.side(side);
  const int n = cam.rollers;
  ToleranceSensitivities<T> out;
  out.params = SideToleranceParameters(rd, bands, si);
  const size_t np = out.params.size();
  // The nominal compliant turret (no gaps: closed-form ψ) and each roller's contact rigidity F'_k.
  rigidity::TurretSpring<T> spring{{}, cam.contact_length(), T(material.composite_modulus_MPa()), T(0.0), T(0.0)};
  for (const auto& c : sl.contacts) spring.arms.push_back(c.arm);
  const T psi = spring.Rotation(T(ReactedTurretTorque(rd, output_torque_Nmm, side)));
  std::vector<T> rigidity(n);
  T sum(0.0);
  for (int k = 0; k < n; ++k) {
    rigidity[k] = spring.RollerRigidity(psi * spring.arms[k]);
    sum += rigidity[k] * spring.arms[k] * spring.arms[k];
  }
  // ∂c_k/∂t_p (header): −d_k is the outward normal at the roller centre, fixed frame.
  const Vec2<T> load_dir = EccentricLoadDirection(r, material, output_torque_Nmm, theta);
  const double turn = side == Side::kInput ? 0.0 : OutputSpeedRatio(rd) * theta;
  const Vec2<T> ecc = U(T(theta));
  std::vector<std::vector<T>> gap(n, std::vector<T>(np, T(0.0)));
  for (int k = 0; k < n; ++k) {
    const Vec2<T> normal = -sl.contacts[k].direction;
    const Vec2<T> slot = U(T(2.0 * kPi * k / n + turn));
    for (size_t p = 0; p < np; ++p) {
      const ToleranceParameter& q = out.params[p];
      switch (q.key) {
        case 0: gap[k][p] = -normal.dot(ecc); break;
        case 1: gap[k][p] = normal.dot(slot); break;
        case 2: gap[k][p] = T(q.roller == k ? -1.0 : 0.0); break;
        case 3: gap[k][p] = q.roller == k ? cam.turret_radius * normal.dot(Perp(slot)) : T(0.0); break;
        case 4: gap[k][p] = T(-1.0); break;
        case 5: gap[k][p] = -normal.dot(load_dir); break;
      }
    }
  }
  // dψ = Σ F'_j a_j dc_j / Σ F'_j a_j², dF_k = F'_k (a_k dψ − dc_k).
  out.force.assign(n, std::vector<T>(np, T(0.0)));
  for (size_t p = 0; p < np; ++p) {
    T num(0.0);
    for (int j = 0; j < n; ++j) num += rigidity[j] * spring.arms[j] * gap[j][p];
    const T dpsi = num / sum;
    for (int k = 0; k < n; ++k) out.force[k][p] = rigidity[k] * (spring.arms[k] * dpsi - gap[k][p]);
  }
  if (!std::isfinite(stress_limit_MPa)) return out;
  // s = 1 − r_r κ − F/(c r_r) (LcrStressMargin, c the capacity per radius): ∂s/∂F = −1/(c r_r),
  // ∂s/∂r_r = −κ + F/(c r_r²) for the roller's own radius.
  const T capacity = contact::LineContactLoadPerRadius(T(stress_limit_MPa), cam.contact_length(),
                                                       T(material.composite_modulus_MPa()));
  const T rr = cam.roller_radius;
  out.margin.assign(n, std::vector<T>(np, T(0.0)));
  for (int k = 0; k < n; ++k)
    for (size_t p = 0; p < np; ++p) {
      out.margin[k][p] = -out.force[k][p] / (capacity * rr);
      const ToleranceParameter& q = out.params[p];
      if (q.key == 2 && q.roller == k)
        out.margin[k][p] += -sl.contacts[k].curvature + sl.force[k] / (capacity * rr * rr);
    }
  return out;
}

}  // namespace camopt::lcr
