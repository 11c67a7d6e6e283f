// Torsional stiffness of the lobe cam reducer at its output, from the contact compliance of its
// loaded rollers (derivation: docs/lcr_stiffness.md). Input shaft held, torque T on the output.
//
// With the eccentric rigid, the cam can only turn about its centre O_c (δφ_c) and the output
// turret about O (δθ_o). Roller k's contact closes by δ_k = ψ a_k − c (c: a normal clearance,
// 0 for the conjugate profile), with one generalised rotation per turret:
//   fixed turret  ψ_A = −(m_A/n_A) δφ_c,        output turret  ψ_B = δθ_o − (m_B/n_B) δφ_c.
// Equilibrium decouples the two turrets: g_B(ψ_B) = T, g_A(ψ_A) = −ρ T, with
//   g(ψ) = Σ_k F(ψ a_k − c) a_k,   ρ = m_B n_A / (n_B m_A),
// and the output turns by δθ_o = ψ_B − ρ ψ_A: the two turrets' contact sets in series, the fixed
// one carried through the cam like a gear stage (1/K = 1/g_B' + ρ²/g_A').
//
// Contact law: Palmgren's roller approach δ = 3.84·10⁻⁵ Q^0.9 / L^0.8 (mm, N; steel), written
// dimensionally as δ = K_P (Q/E*)^0.9 L^−0.8 with K_P fixed by Palmgren's steel (E = 207 GPa,
// ν = 0.3), so that another E* scales it (Palmgren, Ball and Roller Bearing Engineering, 1959;
// Harris & Kotzalas, Rolling Bearing Analysis, §6). Optionally each roller's needle bearing adds a
// linear radial spring k_b in series with its contact. The eccentric bearing, bodies and shafts are
// not included (see the docs).
#pragma once

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <ceres/jet.h>

#include "model/common/roots.h"
#include "model/common/scalar.h"
#include "model/lcr/contact.h"
#include "model/lcr/reducer.h"

namespace camopt::rigidity {

/// Palmgren's constant 3.84e-5 mm·N^−0.9·mm^0.8 at its steel, E* = 207000/(2(1 − 0.3²)) MPa.
inline double PalmgrenConstant() {
  static const double k = 3.84e-5 * std::pow(Material{207000.0, 0.3}.composite_modulus_MPa(), 0.9);
  return k;
}

/// Normal approach [mm] of a roller line contact of length L [mm] under force Q [N].
template <typename T>
T PalmgrenApproach(const T& force, const T& length, const T& e_star) {
  using std::pow;
  return T(PalmgrenConstant()) * pow(force / e_star, T(0.9)) / pow(length, T(0.8));
}

/// c = E* (L^0.8 / K_P)^(10/9) [N·mm^(−10/9)] of a line contact of length L [mm]: the force at
/// approach δ is c δ^(10/9) (PalmgrenForce). Taken once per spring, not once per roller and step.
template <typename T>
T PalmgrenCoefficient(const T& length, const T& e_star) {
  using std::pow;
  return e_star * pow(pow(length, T(0.8)) / T(PalmgrenConstant()), T(10.0 / 9.0));
}

/// Force [N] at approach δ [mm] of a contact of coefficient c (PalmgrenCoefficient): c δ^(10/9),
/// 0 for δ <= 0 (separated); continuous at 0 with a zero derivative there.
template <typename T>
T PalmgrenForceOf(const T& approach, const T& coefficient) {
  using std::pow;
  const T d = PositivePart(approach);
  // Value branch, harmless: F ∝ δ^(10/9) meets 0 with a zero derivative, so both sides agree to
  // first order; the branch only keeps pow's infinite derivative at δ = 0 out of the Jet.
  if (!(Value(d) > 0)) return T(0.0);
  return coefficient * pow(d, T(10.0 / 9.0));
}

/// Force [N] at approach δ [mm] (inverse of PalmgrenApproach); 0 for δ <= 0 (separated).
/// F = E* (δ L^0.8 / K_P)^(10/9): continuous at 0 with a zero derivative there. The same as
/// PalmgrenForceOf(δ, PalmgrenCoefficient(L, E*)) but for rounding (kept in this order: the
/// cycloid's output-pin contacts and the sizings on them follow its last digits).
template <typename T>
T PalmgrenForce(const T& approach, const T& length, const T& e_star) {
  using std::pow;
  const T d = PositivePart(approach);
  if (!(Value(d) > 0)) return T(0.0);  // as PalmgrenForceOf
  return e_star * pow(d * pow(length, T(0.8)) / T(PalmgrenConstant()), T(10.0 / 9.0));
}

/// One turret as a torsional spring in its generalised rotation ψ [rad].
template <typename T>
struct TurretSpring {
  std::vector<T> arms;  ///< a_k [mm], signed
  T length;             ///< line-contact length [mm]
  T e_star;             ///< composite modulus [MPa]
  T clearance;          ///< normal clearance c [mm] at every roller
  T bearing = T(0.0);   ///< needle-bearing radial stiffness k_b [N/mm] in series; 0 = rigid
  /// Per-roller normal gaps c_k [mm] added to the clearance (manufacturing deviations,
  /// model/lcr/tolerance.h; < 0 is interference, a preload). Empty: none.
  std::vector<T> gaps = {};

  /// The normal gap of roller k [mm].
  T Gap(size_t k) const { return gaps.empty() ? clearance : clearance + gaps[k]; }

  /// The contact's coefficient c of PalmgrenForceOf [N·mm^(−10/9)].
  T Coefficient() const { return PalmgrenCoefficient(length, e_star); }

  /// One roller at a closure δ [mm] of contact and bearing in series: its force [N] and its
  /// contact's own approach δ_P [mm] (δ without a bearing spring).
  struct Roller {
    T force, approach;
  };
  /// δ = δ_P + F(δ_P)/k_b with F(δ_P) = c δ_P^(10/9) (c: Coefficient()). The residual is convex and
  /// increasing in the contact approach δ_P, so Newton from δ_P = δ (residual >= 0) descends
  /// monotonically to the root; then one Newton step in T gives exact first derivatives (implicit
  /// function theorem).
  Roller RollerAt(const T& closure, const T& c) const {
    // Value branches, harmless: a separated roller carries nothing, and the force leaves 0 with a
    // zero derivative (first contact is C¹, see PalmgrenForce); bearing == 0 means "no bearing
    // spring", a model choice, never a design value crossing 0.
    if (!(Value(closure) > 0)) return {T(0.0), T(0.0)};
    if (Value(bearing) == 0.0) return {PalmgrenForceOf(closure, c), closure};
    const double dv = Value(closure), kb = Value(bearing), cv = Value(c);
    double dc = dv;
    for (int it = 0; it < 100; ++it) {
      const double f = PalmgrenForceOf(dc, cv);
      const double h = dc + f / kb - dv;
      const double next = dc - h / (1.0 + (10.0 / 9.0) * f / (dc * kb));
      const bool done = std::abs(next - dc) <= 1e-15 * dv;
      dc = next;
      if (done) break;
    }
    const T dct(dc);
    const T f = PalmgrenForceOf(dct, c);
    const T dcn = dct - (dct + f / bearing - closure) / (T(1.0) + T(10.0 / 9.0) * f / (dct * bearing));
    return {PalmgrenForceOf(dcn, c), dcn};
  }
  /// Force of one roller [N] at a closure δ [mm] (RollerAt).
  T RollerForce(const T& closure) const { return RollerAt(closure, Coefficient()).force; }
  /// dF/dδ of a loaded roller q (RollerAt): the contact's (10/9) F/δ_P in series with k_b.
  T RigidityOf(const Roller& q) const {
    const T kc = T(10.0 / 9.0) * q.force / q.approach;
    if (Value(bearing) == 0.0) return kc;
    return T(1.0) / (T(1.0) / kc + T(1.0) / bearing);
  }
  /// dF/dδ of one roller at a closure δ [mm] (RigidityOf; 0 when separated).
  T RollerRigidity(const T& closure, const T& c) const {
    // Continuous at first contact: (10/9) F/δ ∝ δ^(1/9) → 0.
    if (!(Value(closure) > 0)) return T(0.0);
    return RigidityOf(RollerAt(closure, c));
  }
  T RollerRigidity(const T& closure) const { return RollerRigidity(closure, Coefficient()); }

  /// g(ψ) = Σ F(ψ a_k − c) a_k [N·mm].
  T Torque(const T& psi) const {
    const T c = Coefficient();
    T s(0.0);
    for (size_t k = 0; k < arms.size(); ++k) s += RollerAt(psi * arms[k] - Gap(k), c).force * arms[k];
    return s;
  }
  /// g'(ψ) = Σ F'(δ_k) a_k² [N·mm/rad].
  T Rigidity(const T& psi) const {
    const T c = Coefficient();
    T s(0.0);
    for (size_t k = 0; k < arms.size(); ++k) s += RollerRigidity(psi * arms[k] - Gap(k), c) * arms[k] * arms[k];
    return s;
  }
  /// g(ψ) and g'(ψ) in one pass over the rollers, each roller's force found once: the same sums,
  /// term by term, as Torque and Rigidity.
  std::pair<T, T> TorqueAndRigidity(const T& psi) const {
    const T c = Coefficient();
    T g(0.0), k(0.0);
    for (size_t i = 0; i < arms.size(); ++i) {
      const T closure = psi * arms[i] - Gap(i);
      if (!(Value(closure) > 0)) continue;  // no force, no rigidity (RollerAt, RollerRigidity)
      const Roller q = RollerAt(closure, c);
      g += q.force * arms[i];
      k += RigidityOf(q) * arms[i] * arms[i];
    }
    return {g, k};
  }
  /// Force of every roller at ψ [N].
  std::vector<T> Forces(const T& psi) const {
    const T c = Coefficient();
    std::vector<T> f;
    for (size_t k = 0; k < arms.size(); ++k) f.push_back(RollerAt(psi * arms[k] - Gap(k), c).force);
    return f;
  }
  /// Largest force among the rollers at ψ [N].
  T MaxForce(const T& psi) const { return HardMax(Forces(psi)); }

  /// ψ with g(ψ) = torque. Without clearance the law is a power of ψ on each side of 0, so
  /// ψ = sign(T) (|T| / (E* (L^0.8/K_P)^(10/9) Σ_{sign a = sign T} |a|^(19/9)))^0.9 exactly.
  /// With clearance or a bearing spring: bracketed bisection in double, then one Newton step in T, which carries
  /// the exact first derivatives (implicit function theorem). T = 0 returns 0 (the middle of the
  /// dead band). @throws std::domain_error when no roller can carry a torque of this sign.
  T Rotation(const T& torque) const {
    using std::abs;
    using std::pow;
    const double tv = Value(torque);
    if (!gaps.empty()) return RotationWithGaps(torque);
    if (tv == 0.0) return T(0.0);
    const double sign = tv > 0 ? 1.0 : -1.0;
    double amax = 0.0;
    for (const T& a : arms) amax = std::max(amax, sign * Value(a));
    if (!(amax > 0)) throw std::domain_error("no roller of the turret can carry this torque");
    // Value branches on the load sense and on which rollers carry it (first contact), harmless: a
    // roller joins the loaded set when its arm crosses 0, where its term |a|^(19/9) and that
    // term's derivative are both 0, so the sum is C¹ across the change of set. T = 0 (above) is
    // the middle of the dead band, not a load case. The bracketing below is in double only; the
    // derivatives come from the Newton step in T at the end.
    if (Value(clearance) == 0.0 && Value(bearing) == 0.0) {
      T sum(0.0);
      for (const T& a : arms)
        if (sign * Value(a) > 0) sum += pow(T(sign) * a, T(19.0 / 9.0));
      const T c = Coefficient();
      return T(sign) * pow(abs(torque) / (c * sum), T(0.9));
    }
    // g is monotone increasing; bracket on the loaded side beyond the dead band c/amax, then
    // Newton safeguarded by bisection.
    const TurretSpring<double> s = ToDouble();
    const double target = std::abs(tv);
    double lo = Value(clearance) / amax, hi = 2.0 * lo + 1e-6;
    auto g = [&](double psi) { return sign * s.Torque(sign * psi); };
    for (int it = 0; it < 2000 && g(hi) < target; ++it) {
      lo = hi;
      hi *= 2.0;
    }
    // The Newton iteration asks for g and g' at the same ψ: both from one pass.
    double at = std::numeric_limits<double>::quiet_NaN(), slope = 0.0;
    const double psi = SafeguardedNewtonIncreasing(
        [&](double x) {
          const auto [gx, kx] = s.TorqueAndRigidity(sign * x);
          at = x, slope = kx;
          return sign * gx;
        },
        [&](double x) { return x == at ? slope : s.Rigidity(sign * x); }, target, lo, hi, 200, 1e-14, 1e-15);
    const T psi0(sign * psi);
    return psi0 - (Torque(psi0) - torque) / Rigidity(psi0);
  }

  /// Rotation with per-roller gaps: g(ψ) = Σ F(ψ a_k − c_k) a_k is non-decreasing in ψ over the
  /// whole line (interference preloads rollers of both signs of a), so the root is bracketed by
  /// doubling steps from ψ = 0 in the direction of the residual, found by safeguarded Newton on
  /// values, and finished by one Newton step in T (implicit function theorem). Any torque,
  /// including 0 (the preloaded rest position; in a dead band of pure clearance the point where
  /// the band's rollers are about to touch is not unique, and the bracket's end is returned).
  /// @throws std::domain_error when the torque cannot be carried.
  T RotationWithGaps(const T& torque) const {
    const TurretSpring<double> s = ToDouble();
    const double target = Value(torque);
    double amax = 0.0;
    for (double a : s.arms) amax = std::max(amax, std::abs(a));
    double gmax = 0.0;
    for (size_t k = 0; k < s.arms.size(); ++k) gmax = std::max(gmax, std::abs(s.Gap(k)));
    // Every closure ψ a_k − c_k is below 1 µm of approach at |ψ| = (|c|max + 1e-3)/a_max... start
    // there and double outward until the residual changes sign.
    double step = (gmax + 1e-3) / amax;
    double lo = -step, hi = step;
    for (int it = 0; it < 200 && s.Torque(lo) > target; ++it) lo -= (step *= 2.0);
    step = (gmax + 1e-3) / amax;
    for (int it = 0; it < 200 && s.Torque(hi) < target; ++it) hi += (step *= 2.0);
    if (!(s.Torque(lo) <= target && s.Torque(hi) >= target))
      throw std::domain_error("no roller of the turret can carry this torque");
    // SafeguardedNewtonIncreasing works on a positive variable: y = ψ − lo + w, w the bracket width.
    const double w = hi - lo;
    double at = std::numeric_limits<double>::quiet_NaN(), slope_at = 0.0;  // g' beside g (Rotation)
    const double y = SafeguardedNewtonIncreasing(
        [&](double v) {
          const auto [gv, kv] = s.TorqueAndRigidity(v + lo - w);
          at = v, slope_at = kv;
          return gv;
        },
        [&](double v) { return v == at ? slope_at : s.Rigidity(v + lo - w); }, target, w, 2.0 * w, 200, 1e-15, 1e-15);
    const T psi0(y + lo - w);
    const T slope = Rigidity(psi0);
    if (!(Value(slope) > 0)) return psi0;  // inside a dead band: no rigidity, no derivative
    return psi0 - (Torque(psi0) - torque) / slope;
  }

  TurretSpring<double> ToDouble() const {
    TurretSpring<double> s;
    for (const T& a : arms) s.arms.push_back(Value(a));
    s.length = Value(length);
    s.e_star = Value(e_star);
    s.clearance = Value(clearance);
    s.bearing = Value(bearing);
    for (const T& g : gaps) s.gaps.push_back(Value(g));
    return s;
  }
};

/// ρ = m_B n_A / (n_B m_A): the fixed turret reacts −ρ T when the output carries T.
template <typename T>
double FixedTurretTorqueRatio(const lcr::Reducer<T>& r) {
  return double(r.output.lobes) * r.input.rollers / (double(r.output.rollers) * r.input.lobes);
}

template <typename T>
struct ReducerDeflection {
  T output_rotation;  ///< δθ_o [rad], input held
  T first_contact;    ///< δθ_o where the first rollers touch in the sense of T (0 without clearance)
  T elastic_rotation; ///< output_rotation − first_contact: the part the contacts' compliance makes
  T psi_input, psi_output;
  T tangent_rigidity;  ///< dT/dδθ_o [N·mm/rad]
  T max_force_input, max_force_output;  ///< [N]
};

/// The reducer at input angle θ [rad] under output torque T [N·mm] (signed: the forward sense
/// of the paper's load is T = LoadedArmSign(r, Side::kOutput)·|T|), input shaft held.
template <typename T>
ReducerDeflection<T> DeflectAtAngle(const lcr::Reducer<T>& r, const lcr::Material& material,
                                    const T& theta, const T& torque, const T& clearance,
                                    const T& bearing_stiffness = T(0.0)) {
  const T e_star(material.composite_modulus_MPa());
  TurretSpring<T> a{{}, r.input.contact_length(), e_star, clearance, bearing_stiffness};
  TurretSpring<T> b{{}, r.output.contact_length(), e_star, clearance, bearing_stiffness};
  for (const auto& c : lcr::RollerContacts(r, lcr::Side::kInput, theta)) a.arms.push_back(c.arm);
  for (const auto& c : lcr::RollerContacts(r, lcr::Side::kOutput, theta)) b.arms.push_back(c.arm);
  const double rho = FixedTurretTorqueRatio(r);
  ReducerDeflection<T> d;
  d.psi_output = b.Rotation(torque);
  d.psi_input = a.Rotation(T(-rho) * torque);
  d.output_rotation = d.psi_output - T(rho) * d.psi_input;
  // First contact in the sense of T: ψ_B = c/max(sign·a_B), ψ_A = −c/max(−sign·a_A).
  // The sense of T picks which rollers lead: first_contact jumps at T = 0 across the dead band
  // (the backlash is a real discontinuity, not smoothed). Away from T = 0 the sign is locally
  // constant, so the derivatives are exact; HardMax takes the leading roller's (corner where two tie).
  const double sign = IfThenElse(Compare::kGreaterEqual, torque, 0.0, 1.0, -1.0);
  std::vector<T> lead_a, lead_b;
  for (const T& x : a.arms) lead_a.push_back(T(-sign) * x);
  for (const T& x : b.arms) lead_b.push_back(T(sign) * x);
  d.first_contact = T(sign) * (clearance / HardMax(lead_b) + T(rho) * clearance / HardMax(lead_a));
  d.elastic_rotation = d.output_rotation - d.first_contact;
  d.tangent_rigidity =
      T(1.0) / (T(1.0) / b.Rigidity(d.psi_output) + T(rho * rho) / a.Rigidity(d.psi_input));
  d.max_force_input = a.MaxForce(d.psi_input);
  d.max_force_output = b.MaxForce(d.psi_output);
  return d;
}

/// Over one input revolution (θ = 2π i/steps): the output deflection per angle, and summaries.
/// Secant rigidities are T over the elastic rotation (measured from first contact), so that a
/// clearance shows as backlash (DeadBand) and not as compliance.
struct ReducerStiffnessCycle {
  std::vector<double> theta_rad, rotation_rad, elastic_rotation_rad;
  std::vector<double> secant_Nmm_per_rad, tangent_Nmm_per_rad;
  std::vector<double> max_force_input_N, max_force_output_N;
  double mean_secant_Nmm_per_rad = 0;  ///< T / mean elastic δθ_o: the stiffness of the mean deflection
  double min_secant_Nmm_per_rad = 0, max_secant_Nmm_per_rad = 0;
  double mean_tangent_Nmm_per_rad = 0, min_tangent_Nmm_per_rad = 0, max_tangent_Nmm_per_rad = 0;
  double ripple = 0;  ///< (max − min)/mean of the secant stiffness
};

inline ReducerStiffnessCycle StiffnessCycle(const lcr::Reducer<double>& r,
                                            const lcr::Material& material, double torque_Nmm,
                                            double clearance_mm, int steps,
                                            double bearing_N_per_mm = 0.0) {
  ReducerStiffnessCycle c;
  double sum_rot = 0, sum_tan = 0;
  for (int i = 0; i < steps; ++i) {
    const double theta = 2 * kPi * i / steps;
    const auto d = DeflectAtAngle<double>(r, material, theta, torque_Nmm, clearance_mm, bearing_N_per_mm);
    c.theta_rad.push_back(theta);
    c.rotation_rad.push_back(d.output_rotation);
    c.elastic_rotation_rad.push_back(d.elastic_rotation);
    c.secant_Nmm_per_rad.push_back(torque_Nmm / d.elastic_rotation);
    c.tangent_Nmm_per_rad.push_back(d.tangent_rigidity);
    c.max_force_input_N.push_back(d.max_force_input);
    c.max_force_output_N.push_back(d.max_force_output);
    sum_rot += d.elastic_rotation;
    sum_tan += d.tangent_rigidity;
  }
  c.mean_secant_Nmm_per_rad = torque_Nmm / (sum_rot / steps);
  c.min_secant_Nmm_per_rad = HardMin(c.secant_Nmm_per_rad);
  c.max_secant_Nmm_per_rad = HardMax(c.secant_Nmm_per_rad);
  c.mean_tangent_Nmm_per_rad = sum_tan / steps;
  c.min_tangent_Nmm_per_rad = HardMin(c.tangent_Nmm_per_rad);
  c.max_tangent_Nmm_per_rad = HardMax(c.tangent_Nmm_per_rad);
  c.ripple = (c.max_secant_Nmm_per_rad - c.min_secant_Nmm_per_rad) / c.mean_secant_Nmm_per_rad;
  return c;
}

/// Lost-motion curve: mean output rotation over the revolution for each torque in `torques`
/// (signed, N·mm), input held. Returns rotations in rad.
inline std::vector<double> LostMotionCurve(const lcr::Reducer<double>& r,
                                           const lcr::Material& material,
                                           const std::vector<double>& torques,
                                           double clearance_mm, int steps,
                                           double bearing_N_per_mm = 0.0) {
  std::vector<double> out;
  for (double t : torques) {
    double s = 0;
    for (int i = 0; i < steps; ++i)
      s += DeflectAtAngle<double>(r, material, 2 * kPi * i / steps, t, clearance_mm, bearing_N_per_mm)
               .output_rotation;
    out.push_back(s / steps);
  }
  return out;
}

/// The dead band of the mean lost-motion curve: the rotation between the first contact in one
/// sense and in the other, Σ over turrets of c/max(a) in each sense, averaged over the revolution.
/// 0 without clearance.
inline double DeadBand(const lcr::Reducer<double>& r, double clearance_mm, int steps) {
  if (clearance_mm == 0.0) return 0.0;
  const double rho = FixedTurretTorqueRatio(r);
  double s = 0;
  for (int i = 0; i < steps; ++i) {
    const double theta = 2 * kPi * i / steps;
    for (const auto& [side, weight] : {std::pair{lcr::Side::kOutput, 1.0}, std::pair{lcr::Side::kInput, rho}}) {
      double pos = 0, neg = 0;
      for (const auto& c : lcr::RollerContacts(r, side, theta)) {
        pos = std::max(pos, c.arm);
        neg = std::max(neg, -c.arm);
      }
      s += weight * (clearance_mm / pos + clearance_mm / neg);
    }
  }
  return s / steps;
}

}  // namespace camopt::rigidity

namespace camopt::rigidity {

/// ∂ln K/∂ln p of the reducer's mean secant stiffness K over `steps` input angles (the same
/// definition as StiffnessCycle) with respect to its free dimensions, by ceres::Jet: the
/// eccentricity, both turret radii, both line-contact lengths (roller length and cam thickness
/// scaled together) and, when present, the needle bearings' stiffness. The roller diameter does not
/// enter: the arms do not depend on it (every normal passes through the pitch point) and Palmgren's
/// law is independent of the radii.
inline std::vector<std::pair<std::string, double>> ReducerStiffnessElasticities(
    const lcr::Reducer<double>& r, const lcr::Material& material, double torque_Nmm,
    double clearance_mm, double bearing_N_per_mm, int steps) {
  using J = ceres::Jet<double, 6>;
  auto seeded = [](double v, int k) {
    J x(v);
    x.v[k] = v;  // d/dλ of v·λ at λ = 1: derivatives come out per unit of ln p
    return x;
  };
  lcr::Reducer<J> rj = r.cast<J>();
  rj.eccentricity = seeded(r.eccentricity, 0);
  rj.input.turret_radius = seeded(r.input.turret_radius, 1);
  rj.output.turret_radius = seeded(r.output.turret_radius, 2);
  rj.input.roller_length = seeded(r.input.roller_length, 3);
  rj.input.cam_thickness = seeded(r.input.cam_thickness, 3);
  rj.output.roller_length = seeded(r.output.roller_length, 4);
  rj.output.cam_thickness = seeded(r.output.cam_thickness, 4);
  const J bearing = bearing_N_per_mm > 0 ? seeded(bearing_N_per_mm, 5) : J(0.0);
  J sum(0.0);
  for (int i = 0; i < steps; ++i)
    sum += DeflectAtAngle<J>(rj, material, J(2 * kPi * i / steps), J(torque_Nmm), J(clearance_mm), bearing)
               .elastic_rotation;
  // K = T / mean rotation, so ∂ln K = −∂ln(mean rotation).
  std::vector<std::pair<std::string, double>> out = {
      {"eccentricity_mm", -sum.v[0] / sum.a},
      {"input.turret_radius_mm", -sum.v[1] / sum.a},
      {"output.turret_radius_mm", -sum.v[2] / sum.a},
      {"input.contact_length_mm", -sum.v[3] / sum.a},
      {"output.contact_length_mm", -sum.v[4] / sum.a},
  };
  if (bearing_N_per_mm > 0) out.push_back({"needle_bearing_radial_stiffness_N_per_mm", -sum.v[5] / sum.a});
  return out;
}

}  // namespace camopt::rigidity
