// Unloaded tooth contact analysis (TCA) of a cycloid stage: for each roller, the disc rotation
// that brings it into contact with its tooth flank, the contact point, the contact normal, the
// moment arm and the backlash. Cycloid load-distribution paper, eqs. (8)–(14).
//
// Eqs. (12) ask for coincident points and collinear normals of roller i and the modified tooth.
// In the disc frame that is one vector equation in (t, β):
//     R(φ/n2 − β) (a u(ψ_i) − e u(φ)) = X'(t) + (ρ − ρ') N(t)
// (the roller centre lies on the normal of the tooth at distance ρ from it), solved by Newton from
// the unmodified contact t_i = ψ_i + φ/n2, β = 0. β > 0 turns the disc counter-clockwise from its
// kinematic position, i.e. against its motion (the disc lags); the rollers that such a turn presses
// are the loaded flank, those with a positive arm l_i = X' × N. Eqs. (13)–(14): the disc settles at
// the first contact, β0 = min_i β_i (the paper's max with its sign), and the backlash of pair i is
// β_i − β0 ≥ 0.
#pragma once

#include <cmath>
#include <vector>

#include "model/common/profile_deviation.h"
#include "model/common/scalar.h"
#include "model/cycloid/tooth_profile.h"

namespace camopt::cycloid {

/// One roller-tooth pair of the unloaded TCA.
template <typename T>
struct PairGeometry {
  int roller = 0;
  bool loaded_flank = false;  ///< arm above the threshold and the contact equations solved
  bool converged = false;     ///< the contact equations solved near the unmodified contact
  T parameter;                ///< t at the contact point [rad]
  T contact_rotation;         ///< β_i [rad]: disc rotation (from kinematic) closing this pair
  T backlash;                 ///< β_i − β0 [rad], eq. (13)
  T arm_mm;                   ///< l_i = X' × N [mm], moment arm about the disc centre, eq. (26)
  Vec2<T> point;              ///< contact point on the tooth, disc frame [mm]
  Vec2<T> normal;             ///< outward tooth normal at the contact (towards the roller)
  T profile_curvature;        ///< signed curvature of the tooth there [1/mm], > 0 convex
  T roller_curvature;         ///< 1/ρ [1/mm]
};

template <typename T>
struct UnloadedMesh {
  T crank_angle;    ///< φ [rad]
  T rotation;       ///< β0 [rad], unloaded transmission error (disc lag), eq. (14)
  int first_contact = -1;  ///< index into pairs of the pair that defines β0
  std::vector<PairGeometry<T>> pairs;  ///< one per roller, in roller order
};

/// Pairs whose arm is below this fraction of the pitch radius e·n2 are left out: their contact
/// point sits at a tooth tip or root where turning the disc cannot close the gap (the Newton
/// system of eq. 12 is singular there, its determinant is proportional to the arm).
constexpr double kMinArmFraction = 0.02;

/// Solves eq. (12) for roller i at crank angle φ [rad] with the tooth of `d` and a roller whose
/// centre, from the disc centre in the fixed frame, is `rel` (a u(ψ_i) − e u(φ) for the nominal
/// drive) and whose radius exceeds the generating circle's ρ' by `drho` (ρ − ρ' nominally): the
/// form a drive with deviations needs (model/cycloid/transmission_error.h). `shape` (nullptr:
/// none) adds a normal deviation d(t) of the tooth profile, a function of the curve parameter
/// (model/common/profile_deviation.h): the roller centre then lies on the normal of X' at the
/// offset ρ − ρ' + d(t), the first-order contact of a circle with the profile moved by d along its
/// normal (the envelope theorem: the distance to the moved profile falls by d at the closest
/// point; the normal's tilt by d'/|P'| changes it only at second order).
template <typename T>
CAMOPT_FLATTEN PairGeometry<T> SolvePairAt(const DriveTpl<T>& d, int i, const T& crank, const Vec2<T>& rel, const T& drho,
                            const profile::NormalDeviation<T>* shape = nullptr) {
  using std::abs;
  using std::sqrt;
  PairGeometry<T> g;
  g.roller = i;
  T t = NominalParameter(d, i, crank);
  T beta(0.0);
  bool converged = false;
  // Newton on F(t, β) = C_i(β) − X'(t) − (ρ − ρ') N(t) = 0. With a Jet, iterating to convergence
  // carries the implicit-function derivatives (the last step is taken at the solution).
  for (int it = 0; it < 30; ++it) {
    const ProfilePoint<T> p = ToothProfile(d, t);
    const Vec2<T> c = Rotate(rel, T(crank / double(d.teeth) - beta));  // as RollerCentreInDisc
    T dn(0.0), dn_t(0.0);
    if (shape) dn = (*shape)(t, &dn_t);
    const T off = drho + dn;
    const Vec2<T> f = c - p.centre - off * p.normal;
    // dF/dβ = −J C;  dF/dt = −|X'_t| T̂ (1 + (ρ − ρ' + d) κ) − d' N  (dN/dt = κ |X'_t| T̂).
    const Vec2<T> fb = -Perp(c);
    const Vec2<T> ft = -p.speed * (T(1.0) + off * p.centre_curvature) * p.tangent - dn_t * p.normal;
    const T det = Cross(ft, fb);
    if (!(abs(Value(det)) > 1e-300)) break;
    // Solve [ft fb] (dt, dβ) = −f by Cramer's rule.
    const T dt = -Cross(f, fb) / det;
    const T db = -Cross(ft, f) / det;
    t += dt;
    beta += db;
    if (!(abs(Value(db)) < 0.5)) break;  // wandered off the tooth: not a contact of this flank
    if (abs(Value(dt)) < 1e-12 && abs(Value(db)) < 1e-12) {
      if (converged) break;  // one more step at the solution for the derivatives
      converged = true;
    }
  }
  // A root far from the unmodified contact belongs to another tooth or flank (Newton can wander
  // there from a tip or root, where the system is nearly singular): not a contact of this pair.
  // Profile modifications are micrometres, so the true root is within a small fraction of a tooth.
  const T t_nominal = NominalParameter(d, i, crank);
  if (converged && (abs(Value(t - t_nominal)) > 0.05 || abs(Value(beta)) > 0.02)) converged = false;
  if (!converged) {  // tip or root: keep the unmodified contact, flagged out of the load path
    t = NominalParameter(d, i, crank);
    beta = T(0.0);
  }
  const ProfilePoint<T> p = ToothProfile(d, t);
  if (shape) {
    // The moved profile Q = P + d N has its own curvature (d'' bends it): from Q's central
    // differences over t (step 1e-4 rad: truncation ~1e-8 and rounding ~1e-9 of the curvature).
    auto moved = [&](const T& u) {
      const ProfilePoint<T> pu = ToothProfile(d, u);
      return Vec2<T>(pu.point + (*shape)(u, nullptr) * pu.normal);
    };
    const T h(1e-4);
    const Vec2<T> qm = moved(t - h), q0 = moved(t), qp = moved(t + h);
    const Vec2<T> d1 = (qp - qm) / (T(2.0) * h), d2 = (qp - T(2.0) * q0 + qm) / (h * h);
    const T speed = sqrt(d1.squaredNorm());
    g.profile_curvature = Cross(d1, d2) / (speed * speed * speed);
  } else {
    g.profile_curvature = p.curvature;
  }
  g.parameter = t;
  g.contact_rotation = beta;
  g.point = shape ? Vec2<T>(p.point + (*shape)(t, nullptr) * p.normal) : p.point;
  g.normal = p.normal;
  g.arm_mm = Cross(p.centre, p.normal);
  g.roller_curvature = T(1.0) / d.roller_radius_mm;
  const double min_arm = kMinArmFraction * Value(d.eccentricity_mm) * d.teeth;
  g.converged = converged;
  g.loaded_flank = converged && Value(g.arm_mm) > min_arm;
  g.backlash = T(0.0);
  return g;
}

/// Solves eq. (12) for roller i of the drive at crank angle φ [rad].
/// `shape`: a normal deviation d(t) of the tooth (nullptr: none; SolvePairAt).
template <typename T>
PairGeometry<T> SolvePair(const DriveTpl<T>& d, int i, const T& crank,
                          const profile::NormalDeviation<T>* shape = nullptr) {
  const T psi = T(2.0 * kPi * i / d.rollers);
  const Vec2<T> rel = d.roller_position_radius_mm * U(psi) - d.eccentricity_mm * U(crank);
  const T drho = d.roller_radius_mm - (d.roller_radius_mm + d.delta_radius_mm);  // ρ − ρ'
  return SolvePairAt(d, i, crank, rel, drho, shape);
}

/// Unloaded TCA at crank angle φ [rad] (eqs. 8–14).
/// @tparam T double or ceres::Jet. β0 is an exact minimum over pairs: where the first-contact
/// pair changes, β0 has a kink (the two candidates are equal there, so it stays continuous).
/// `shape`: a normal deviation d(t) of the tooth, a measured disc (nullptr: none; SolvePairAt).
template <typename T>
UnloadedMesh<T> UnloadedTca(const DriveTpl<T>& d, const T& crank, const profile::NormalDeviation<T>* shape = nullptr) {
  UnloadedMesh<T> m;
  m.crank_angle = crank;
  m.rotation = T(0.0);
  for (int i = 0; i < d.rollers; ++i) m.pairs.push_back(SolvePair(d, i, crank, shape));
  for (size_t k = 0; k < m.pairs.size(); ++k) {
    if (!m.pairs[k].loaded_flank) continue;
    if (m.first_contact < 0 ||
        Value(m.pairs[k].contact_rotation) < Value(m.pairs[m.first_contact].contact_rotation))
      m.first_contact = int(k);
  }
  if (m.first_contact >= 0) m.rotation = m.pairs[m.first_contact].contact_rotation;
  for (auto& g : m.pairs) g.backlash = g.contact_rotation - m.rotation;
  return m;
}

}  // namespace camopt::cycloid
