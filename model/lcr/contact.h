// LCR contact at one input angle (paper §3.2–3.4, written with the pitch points of docs/papers.md §1).
//
// Every common normal of a cam passes through its pitch point (Aronhold–Kennedy):
//     I = e k u(θ),  k = n/(n − m).
// So the force on the cam from roller k acts along d_k = unit(I − O_k) (into the cam), the contact
// point is O_k + r_r d_k, and the moment arm about the input axis O is a_k = O_k × d_k
// (the paper's e_Ai = r_dA sin α_Ai, with sign). No root finding is needed; the tests cross-check
// the contact points against the paper's distance condition L = r_r solved by root finding.
#pragma once

#include <stdexcept>
#include <utility>
#include <vector>

#include "model/common/geometry.h"
#include "model/common/scalar.h"
#include "model/lcr/kinematics.h"
#include "model/lcr/profile.h"

namespace camopt::lcr {

template <typename T>
struct RollerContact {
  Vec2<T> centre;     // O_k, fixed frame [mm]
  Vec2<T> direction;  // d_k, unit, force on the cam from the roller
  Vec2<T> point;      // contact point O_k + r_r d_k [mm]
  T arm;              // a_k = O_k × d_k [mm], signed
  T curvature;        // pitch-curve curvature κ at this roller [1/mm], signed
};

/// The unit vectors u(2πi/n), i = 0..n−1, of the roller slots of a turret of n > 0 rollers,
/// computed once per thread and n (U's values), not one sincos per roller in every evaluation.
/// The reference holds until the next call with another n (the table may grow): copy to keep.
inline const std::vector<Vec2<double>>& TurretSlots(int n) {
  thread_local std::vector<std::vector<Vec2<double>>> table;  // by n
  if (n <= 0) throw std::invalid_argument("a turret needs at least one roller");
  if (table.size() <= size_t(n)) table.resize(size_t(n) + 1);
  std::vector<Vec2<double>>& slots = table[size_t(n)];
  if (slots.empty()) {
    slots.reserve(size_t(n));
    for (int k = 0; k < n; ++k) slots.push_back(U(2.0 * kPi * k / n));
  }
  return slots;
}

/// Roller centre of a slot on a turret turned by u(θ_o) (given as its cosine and sine):
/// r_d · (u(θ_o) rotating u(2πi/n)), the angle-addition formula. Each centre carries the rounding of
/// one sincos and two products (a few ulp, no accumulation over rollers or angles), instead of one
/// sincos per roller; the values differ from r_d u(2πi/n + θ_o) only in the last digits.
template <typename T>
CAMOPT_FLATTEN Vec2<T> RotatedSlot(const T& turret_radius, const Vec2<double>& slot, const Vec2<T>& turn) {
  return turret_radius * Vec2<T>(turn.x() * slot.x() - turn.y() * slot.y(),
                                 turn.y() * slot.x() + turn.x() * slot.y());
}

/// Roller-centre positions of one turret at input angle θ [rad]. The output turret turns by
/// θ_o = (1 − n_A m_B/(m_A n_B)) θ (one sincos, then RotatedSlot per roller); the fixed turret stands.
template <typename T>
std::vector<Vec2<T>> RollerCentres(const Reducer<T>& r, Side s, const T& theta) {
  const CamSide<T>& c = r.side(s);
  std::vector<Vec2<T>> centres(c.rollers);
  if (c.rollers <= 0) return centres;
  const std::vector<Vec2<double>>& slots = TurretSlots(c.rollers);
  if (s == Side::kInput) {
    for (int i = 0; i < c.rollers; ++i) centres[i] = c.turret_radius * slots[size_t(i)].template cast<T>();
    return centres;
  }
  const Vec2<T> turn = U(T(OutputSpeedRatio(r)) * theta);
  for (int i = 0; i < c.rollers; ++i) centres[i] = RotatedSlot(c.turret_radius, slots[size_t(i)], turn);
  return centres;
}

/// Pitch point I = e k u(θ) of one cam [mm].
template <typename T>
CAMOPT_FLATTEN Vec2<T> PitchPointOfCam(const Reducer<T>& r, Side s, const T& theta) {
  return r.eccentricity * T(r.side(s).pitch_factor()) * U(theta);
}

/// The unit normal d from a roller centre o toward the cam's pitch point, and 1/|pitch − o| (one
/// division for both components and κ): the contact normal of RollerContacts, and its arm Cross(o, d).
template <typename T>
CAMOPT_FLATTEN std::pair<Vec2<T>, T> TowardPitch(const Vec2<T>& pitch, const Vec2<T>& o) {
  const Vec2<T> v = pitch - o;
  const T inv_norm = T(1.0) / v.norm();
  return {v * inv_norm, inv_norm};
}

/// Contact geometry of every roller of one turret at input angle θ.
template <typename T>
std::vector<RollerContact<T>> RollerContacts(const Reducer<T>& r, Side s, const T& theta) {
  const CamSide<T>& c = r.side(s);
  const Vec2<T> pitch = PitchPointOfCam(r, s, theta);
  const Vec2<T> ecc = U(theta);
  const T inv_radius = T(1.0) / c.turret_radius;
  std::vector<RollerContact<T>> out;
  out.reserve(c.rollers);
  for (const Vec2<T>& o : RollerCentres(r, s, theta)) {
    const auto [d, inv_norm] = TowardPitch(pitch, o);
    const T cosine = o.dot(ecc) * inv_radius;
    out.push_back({o, d, o + c.roller_radius * d, Cross(o, d),
                   PitchCurvatureAtPitchDistance(c, r.eccentricity, cosine, inv_norm)});
  }
  return out;
}

/// The sign of a_k on the rollers that carry load. The output turret must be driven along its
/// motion (ω_o = OutputSpeedRatio · ω_in), so the cam pushes it with torque −F a of the sign of ω_o:
/// loaded output rollers have sign(a) = −sign(ω_o). The cam's moment balance about O_c then puts the
/// loaded fixed-turret rollers on the opposite sign.
template <typename T>
double LoadedArmSign(const Reducer<T>& r, Side s) {
  const double output_sign = OutputSpeedRatio(r) > 0 ? -1.0 : 1.0;
  return s == Side::kOutput ? output_sign : -output_sign;
}

}  // namespace camopt::lcr
