// LCR cam profiles (paper eqs. 4–9 and the tool path P_t), curvature and undercut.
//
// In the cam frame (docs/papers.md §1) the roller-centre trajectory of either cam is
//     X(ψ) = r_d u(ψ) − e u(kψ),   k = n/(n − m),   ψ ∈ [0, 2π),
// (input cam: ψ = (n_A − m_A)θ/m_A; output cam: ψ = n_A (n_B − m_B) θ/(m_A n_B)), so both cams of the
// conjugate cam are drawn in one frame with roller 1 at angle 0 at θ = 0. It is the paper's
// rigid-body transformation written in closed form. The cam profile is its offset by r_r toward
// the cam, the cutter path its offset by (d_r − d_t)/2.
//
// Signed curvature (positive where the centre of curvature is on the cam side):
//     κ(c) = (A² + kB² − AB(1+k)c) / (A² + B² − 2ABc)^{3/2},  A = r_d, B = e k,
// where c = cos(ψ(k−1)) is also the cosine of the angle between a roller and the eccentric
// direction u(θ) in the fixed frame. Undercut where κ r_r > 1.
#pragma once

#include <cmath>
#include <functional>
#include <vector>

#include "model/common/geometry.h"
#include "model/common/profile_deviation.h"
#include "model/common/roots.h"
#include "model/common/scalar.h"
#include "model/lcr/reducer.h"

namespace camopt::lcr {

/// Numerator A² + kB² − AB(1+k)c of the pitch-curve curvature κ(c) (A = r_d, B = e k).
template <typename T>
CAMOPT_FLATTEN T PitchCurvatureNumerator(const CamSide<T>& side, const T& eccentricity, const T& c) {
  const double k = side.pitch_factor();
  const T A = side.turret_radius;
  const T B = eccentricity * T(k);
  return A * A + T(k) * B * B - A * B * T(1.0 + k) * c;
}

/// Pitch-curve curvature κ [1/mm] as a function of c ∈ [−1, 1].
template <typename T>
CAMOPT_FLATTEN T PitchCurvature(const CamSide<T>& side, const T& eccentricity, const T& c) {
  using std::sqrt;
  const double k = side.pitch_factor();
  const T A = side.turret_radius;
  const T B = eccentricity * T(k);
  const T den = A * A + B * B - T(2.0) * A * B * c;
  return PitchCurvatureNumerator(side, eccentricity, c) / (den * sqrt(den));
}

/// κ at a roller whose centre O lies at distance ρ = |I − O| from the cam's pitch point I = e k u(θ),
/// given 1/ρ: by the law of cosines the denominator's A² + B² − 2ABc is ρ² (c the cosine between
/// O and u(θ)), so κ = num · (1/ρ)³ — no square root or division of its own when the contact
/// geometry already has 1/ρ (contact.h). Equal to PitchCurvature up to rounding.
template <typename T>
T PitchCurvatureAtPitchDistance(const CamSide<T>& side, const T& eccentricity, const T& c,
                                const T& inv_distance) {
  return PitchCurvatureNumerator(side, eccentricity, c) * (inv_distance * inv_distance * inv_distance);
}

/// Pitch curve point X(ψ) in the cam frame.
template <typename T>
Vec2<T> PitchPoint(const CamSide<T>& side, const T& eccentricity, const T& psi) {
  return side.turret_radius * U(psi) - eccentricity * U(T(side.pitch_factor()) * psi);
}

/// Unit normal of the pitch curve at ψ pointing into the cam.
template <typename T>
Vec2<T> InwardNormal(const CamSide<T>& side, const T& eccentricity, const T& psi) {
  const T k(side.pitch_factor());
  const Vec2<T> v = eccentricity * k * U(k * psi) - side.turret_radius * U(psi);
  return v / v.norm();
}

/// Point of the curve offset from the pitch curve by `offset` into the cam (cam profile for
/// offset = r_r, cutter-centre path for offset = r_r − r_t).
template <typename T>
Vec2<T> OffsetPoint(const CamSide<T>& side, const T& eccentricity, const T& psi, const T& offset) {
  return PitchPoint(side, eccentricity, psi) + offset * InwardNormal(side, eccentricity, psi);
}

/// The cam profile (inward offset of the pitch curve by `offset`, the roller radius) as a closed
/// curve of ψ ∈ [0, 2π) in the cam frame (the geometry files'), for inspection and measured cams
/// (model/common/profile_deviation.h): with X' = r_d J u(ψ) − e k J u(kψ), X'' = −r_d u(ψ) +
/// e k² u(kψ), v = |X'|, κ = X' × X''/v³ and T = X'/v, the offset P = X + r J T has
/// dP/dψ = v (1 − r κ) T and the curvature κ/(1 − r κ). @pre no undercut (r κ < 1 everywhere).
inline camopt::profile::Curve CamProfileCurve(const CamSide<double>& side, double eccentricity, double offset) {
  return [side, eccentricity, offset](double psi) {
    const double k = side.pitch_factor(), rd = side.turret_radius, e = eccentricity;
    const Vec2<double> d1 = rd * Perp(U(psi)) - e * k * Perp(U(k * psi));
    const Vec2<double> d2 = -rd * U(psi) + e * k * k * U(k * psi);
    const double v = d1.norm(), kappa = Cross(d1, d2) / (v * v * v);
    camopt::profile::CurvePoint c;
    c.tangent = d1 / v;
    c.point = PitchPoint(side, eccentricity, psi) + offset * Perp(c.tangent);
    c.speed = v * std::abs(1.0 - offset * kappa);  // |.|: an undercut loop keeps a positive arc length
    c.curvature = kappa / (1.0 - offset * kappa);
    return c;
  };
}

// The double curves' evaluations (drawings, geometry files' fits), compiled in profile.cc at the
// build's optimisation: the study files that call them are compiled lighter (CMakeLists.txt).

/// Sampled closed curve (n points, ψ = 2πi/n) at the given inward offset [mm].
std::vector<Vec2<double>> SampleCurve(const CamSide<double>& side, double eccentricity, double offset, int n);

/// ψ ↦ OffsetPoint(side, eccentricity, ψ, offset).
std::function<Vec2<double>(double)> OffsetCurve(const CamSide<double>& side, double eccentricity, double offset);

/// ψ ↦ PitchPoint(side, eccentricity, ψ).
std::function<Vec2<double>(double)> PitchCurve(const CamSide<double>& side, double eccentricity);

/// The c ∈ [−1, 1] where κ(c) is largest (the sharpest convex point), found on values only:
/// a 201-point scan refined by golden section. Used with the envelope theorem below.
template <typename T>
double ArgMaxCurvature(const CamSide<T>& side, const T& eccentricity) {
  const CamSide<double> s = side.template cast<double>();
  const double e = Value(eccentricity);
  auto f = [&](double c) { return PitchCurvature(s, e, c); };
  const int n = 200;
  int best = 0;
  double best_v = f(-1.0);
  for (int i = 1; i <= n; ++i) {
    const double v = f(-1.0 + 2.0 * i / n);
    if (v > best_v) best_v = v, best = i;
  }
  const GoldenSectionBracket b = GoldenSectionMaximize(
      f, -1.0 + 2.0 * std::max(best - 1, 0) / n, -1.0 + 2.0 * std::min(best + 1, n) / n, 60);
  const double c = 0.5 * (b.lo + b.hi);
  // The ends of the interval are candidates too (the maximum is often at c = −1).
  double arg = c, val = f(c);
  for (double end : {-1.0, 1.0})
    if (f(end) > val) arg = end, val = f(end);
  return arg;
}

/// Largest pitch-curve curvature κ_max [1/mm]. Its derivative is exact by the envelope theorem:
/// at the maximiser c*, dκ_max/dp = ∂κ/∂p (c* is found on values; c = ±1 does not depend on p).
template <typename T>
T MaxPitchCurvature(const CamSide<T>& side, const T& eccentricity) {
  return PitchCurvature(side, eccentricity, T(ArgMaxCurvature(side, eccentricity)));
}

/// Smallest convex radius of the pitch curve, 1/κ_max [mm].
template <typename T>
T MinConvexPitchRadius(const CamSide<T>& side, const T& eccentricity) {
  return T(1.0) / MaxPitchCurvature(side, eccentricity);
}

/// Smallest convex radius of the curve offset by `offset` into the cam from the pitch curve,
/// 1/κ_max − offset [mm]: the cam profile for offset = r_r, the cutter-centre path for
/// offset = r_r − r_t.
template <typename T>
T MinConvexOffsetRadius(const CamSide<T>& side, const T& eccentricity, const T& offset) {
  return MinConvexPitchRadius(side, eccentricity) - offset;
}

/// Distance of the pitch point from the input axis, e·n/(n − m) [mm].
template <typename T>
T PitchPointRadius(const CamSide<T>& side, const T& eccentricity) {
  return eccentricity * T(side.pitch_factor());
}

/// Undercut margin 1/κ_max − r_r [mm]: negative means the roller (and any cutter with d_t ≤ d_r,
/// whose path is offset by r_r − r_t and whose radius is r_t) undercuts the cam.
template <typename T>
T UndercutMargin(const CamSide<T>& side, const T& eccentricity) {
  return MinConvexPitchRadius(side, eccentricity) - side.roller_radius;
}

/// Smooth undercut margin for optimizers: 1/SoftMax_k(κ(c_i)) − r_r over n samples of c
/// (c_i = cos(πi/(n−1)), denser near c = ±1). Never above the sampled exact margin; the soft max
/// over-estimates κ by at most ln(n)/k, so the margin is low by at most ≈ ρ² ln(n)/k
/// (ρ = 1/κ_max). Sharpness k in mm (units of 1/κ): the default 1e4 mm gives Δκ ≤ 4.2e-4 /mm.
template <typename T>
T SmoothUndercutMargin(const CamSide<T>& side, const T& eccentricity, int samples = 64,
                       double sharpness_mm = 1e4) {
  std::vector<T> kappa(samples);
  for (int i = 0; i < samples; ++i)
    kappa[i] = PitchCurvature(side, eccentricity, T(std::cos(kPi * i / (samples - 1))));
  return T(1.0) / SoftMax(kappa, sharpness_mm) - side.roller_radius;
}

}  // namespace camopt::lcr
