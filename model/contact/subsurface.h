// Subsurface stresses under a frictionless Hertz contact and a contact-fatigue life law, over the
// scalar T (double or ceres::Jet). Units: lengths mm, pressures and stresses MPa; compressive
// stresses negative; z is the depth below the surface (z > 0 into the solid).
//
// Line contact (plane strain, half-width b, peak pressure p0): McEwen (1949) as in Johnson, Contact
// Mechanics (1985), eq. 4.50 ff. (McEwen's m, n everywhere; their limit on the axis x = 0).
// Circular contact (radius a): Johnson eq. 3.45 (on the axis r = 0).
// Elliptical contact (semi-axes a ≥ b along x and y): the stresses on the z axis, after Thomas &
// Hoersch (1930) and Johnson §3.7, written here with Carlson's symmetric integral R_D instead of
// incomplete Legendre integrals (derivation in docs/life.md, "Contact fatigue"). They reduce to
// eq. 3.45 at a = b and to the line contact as a/b → ∞ (tests/subsurface_stress_test.cc).
// Life: the stress-life law L ∝ p0^−n and the Lundberg–Palmgren (1947) relation, docs/life.md.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include <ceres/jet.h>

#include "model/common/roots.h"
#include "model/common/scalar.h"

namespace camopt::contact {

/// Normal stresses on the symmetry axis of a contact (principal stresses there) [MPa].
template <typename T>
struct AxisStresses {
  T sigma_x, sigma_y, sigma_z;
};

/// In-plane stresses of the plane-strain line contact at (x, z) [MPa].
template <typename T>
struct PlaneStresses {
  T sigma_x, sigma_z, tau_xz;
};

/// A maximum of a stress measure: its value [MPa] at depth z [mm] and, off the axis, x [mm].
template <typename T>
struct StressPeak {
  T value, depth, x;
};

namespace subsurface_internal {

inline void CheckPoissonRatio(double nu) {
  if (!(nu >= 0.0 && nu < 0.5)) throw std::invalid_argument("subsurface stress: Poisson's ratio must be in [0, 0.5)");
}

/// The maximiser of f on [lo, hi]: the best of 64 uniform samples, then golden section to a
/// bracket of 1e-12 (of the scaled position) between its neighbours. The scan makes the search
/// robust to a function that is not unimodal on [lo, hi] as long as its global maximum is the only
/// maximum within one sample spacing (the line contact's von Mises stress on the axis first falls
/// from its surface value 0.4 p0 to a minimum near 0.05 b before it rises to 0.56 p0).
template <typename F>
double ArgMax(const F& f, double lo, double hi) {
  const int n = 64;
  const double h = (hi - lo) / n;
  int best = 0;
  double best_value = f(lo);
  for (int i = 1; i <= n; ++i) {
    const double v = f(lo + i * h);
    if (v > best_value) best = i, best_value = v;
  }
  const double a = lo + std::max(best - 1, 0) * h, b = lo + std::min(best + 1, n) * h;
  const GoldenSectionBracket br = GoldenSectionMaximize(f, a, b, 200, 1e-12);
  return 0.5 * (br.lo + br.hi);
}

/// Largest half difference of three principal stresses (Tresca's shear).
template <typename T>
T MaxShear(const AxisStresses<T>& s) {
  using std::abs;
  const T a = abs(s.sigma_x - s.sigma_y), b = abs(s.sigma_y - s.sigma_z), c = abs(s.sigma_z - s.sigma_x);
  return T(0.5) * IfThenElse(Compare::kGreater, a, b, IfThenElse(Compare::kGreater, a, c, a, c),
                             IfThenElse(Compare::kGreater, b, c, b, c));
}

template <typename T>
T VonMises(const AxisStresses<T>& s) {
  using std::sqrt;
  const T a = s.sigma_x - s.sigma_y, b = s.sigma_y - s.sigma_z, c = s.sigma_z - s.sigma_x;
  return sqrt(T(0.5) * (a * a + b * b + c * c));
}

/// The largest `measure` of a contact's axis stresses `stresses(p0, s, z)` (s its semi-width or
/// radius): the maximiser of z/s on (0, 2] at p0 = s = 1 (ArgMax, in double), the stress there in T
/// (value ∝ p0, depth ∝ s).
template <typename T, typename Stresses, typename Measure>
StressPeak<T> AxisPeak(const T& p0, const T& scale, const Stresses& stresses, const Measure& measure) {
  const double zeta = ArgMax([&](double z) { return measure(stresses(1.0, 1.0, z)); }, 1e-6, 2.0);
  const T z = scale * zeta;
  return {measure(stresses(p0, scale, z)), z, T(0.0)};
}

}  // namespace subsurface_internal

/// Carlson's symmetric elliptic integral of the second kind,
/// R_D(x, y, z) = (3/2) ∫₀^∞ dt / ((t + x)^½ (t + y)^½ (t + z)^(3/2)),
/// x, y ≥ 0 (at most one zero), z > 0; by the duplication theorem with the fifth-order series
/// (Carlson, Numer. Algorithms 10 (1995) 13–26, §2; Numerical Recipes 2nd ed. §6.11, rd).
/// The iteration count depends on values only, so a Jet's derivative is that of the same series.
template <typename T>
T CarlsonRD(T x, T y, T z) {
  using std::abs;
  using std::sqrt;
  const double kErrTol = 5e-4;  // relative error ~ kErrTol^6 / (1 − kErrTol) ≈ 1.6e-20 (Carlson 1995 eq. 2.15)
  T sum = T(0.0);
  double factor = 1.0;
  T ave = T(1.0), dx = T(0.0), dy = T(0.0), dz = T(0.0);
  for (int it = 0; it < 100; ++it) {
    const T sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
    const T lambda = sx * (sy + sz) + sy * sz;
    sum += factor / (sz * (z + lambda));
    factor *= 0.25;
    x = T(0.25) * (x + lambda);
    y = T(0.25) * (y + lambda);
    z = T(0.25) * (z + lambda);
    ave = T(0.2) * (x + y + T(3.0) * z);
    dx = (ave - x) / ave;
    dy = (ave - y) / ave;
    dz = (ave - z) / ave;
    if (std::max({abs(Value(dx)), abs(Value(dy)), abs(Value(dz))}) <= kErrTol) break;
  }
  const double c1 = 3.0 / 14.0, c2 = 1.0 / 6.0, c3 = 9.0 / 22.0, c4 = 3.0 / 26.0, c5 = 0.25 * c3, c6 = 1.5 * c4;
  const T ea = dx * dy, eb = dz * dz, ec = ea - eb, ed = ea - T(6.0) * eb, ee = ed + ec + ec;
  const T series = T(1.0) + ed * (T(-c1) + T(c5) * ed - T(c6) * dz * ee) +
                   dz * (T(c2) * ee + dz * (T(-c3) * ec + dz * T(c4) * ea));
  return T(3.0) * sum + factor * series / (ave * sqrt(ave));
}

// ---- Line contact -------------------------------------------------------------------------------

/// Line contact, stresses on the axis x = 0 at depth z > 0 (Johnson eq. 4.50 ff. at x = 0; plane strain
/// σ_y = ν(σ_x + σ_z)): σ_x = −(p0/b)((b² + 2z²)/√(b² + z²) − 2z), σ_z = −p0 b/√(b² + z²).
/// @param p0 peak pressure [MPa], b half-width [mm], z depth [mm], nu Poisson's ratio.
template <typename T>
AxisStresses<T> LineContactAxisStresses(const T& p0, const T& b, const T& z, double nu) {
  using std::sqrt;
  subsurface_internal::CheckPoissonRatio(nu);
  const T r = sqrt(b * b + z * z);
  const T sx = -(p0 / b) * ((b * b + T(2.0) * z * z) / r - T(2.0) * z);
  const T sz = -p0 * b / r;
  return {sx, T(nu) * (sx + sz), sz};
}

/// Line contact, in-plane stresses at (x, z), z > 0 (McEwen 1949; Johnson eq. 4.50 ff.):
/// m² = ½(√((b² − x² + z²)² + 4x²z²) + (b² − x² + z²)), n² = ½(√(…) − (b² − x² + z²)),
/// n with the sign of x; σ_x = −(p0/b)(m(1 + (z² + n²)/(m² + n²)) − 2z), σ_z = −(p0/b) m (1 − (z² + n²)/(m² + n²)),
/// τ_xz = (p0/b) n (m² − z²)/(m² + n²).
template <typename T>
PlaneStresses<T> LineContactStresses(const T& p0, const T& b, const T& x, const T& z) {
  using std::sqrt;
  const T q = b * b - x * x + z * z;
  const T root = sqrt(q * q + T(4.0) * x * x * z * z);
  const T m = sqrt(T(0.5) * (root + q));
  const T n2 = T(0.5) * (root - q);
  // n² ≥ 0 analytically; at x = 0 it is 0 and its square root has no derivative, but n enters
  // only τ_xz (which is odd in x) and as n², so the axis is reached through n² alone there.
  const T n_abs = IfThenElse(Compare::kGreater, n2, 0.0, sqrt(IfThenElse(Compare::kGreater, n2, 0.0, n2, T(1.0))), T(0.0));
  const T n = IfThenElse(Compare::kLess, x, 0.0, -n_abs, n_abs);
  const T mn = m * m + n2;
  const T s = (z * z + n2) / mn;
  return {-(p0 / b) * (m * (T(1.0) + s) - T(2.0) * z), -(p0 / b) * m * (T(1.0) - s), (p0 / b) * n * (m * m - z * z) / mn};
}

/// Line contact, the largest principal shear τ1 = (σ_x − σ_z)/2 (on the axis): closed form. Setting
/// d/dζ[ζ − ζ²/√(1 + ζ²)] = 0 (ζ = z/b, the axis stresses above) gives ζ⁴ + ζ² − 1 = 0, ζ² = 1/φ,
/// φ = (1 + √5)/2: depth b/√φ = 0.78615 b, value p0 φ^(−5/2) = 0.30028 p0 (Johnson: 0.30 p0 at 0.78 b).
template <typename T>
StressPeak<T> LineContactMaxPrincipalShear(const T& p0, const T& b) {
  const double phi = 0.5 * (1.0 + std::sqrt(5.0));
  return {p0 * std::pow(phi, -2.5), b / std::sqrt(phi), T(0.0)};
}

/// Line contact, the largest orthogonal shear |τ_xz| (Lundberg–Palmgren's τ0) over the half-plane:
/// nested golden sections on the scaled stresses (x/b in (0, 3], z/b in (0, 2]), then evaluated in T
/// at the maximiser (envelope theorem: the derivative of the value is the partial derivative there;
/// value ∝ p0 and position ∝ b exactly, so these derivatives are exact). Johnson (1985): 0.25 p0 at
/// z = 0.5 b, x = ±0.87 b.
template <typename T>
StressPeak<T> LineContactMaxOrthogonalShear(const T& p0, const T& b) {
  using subsurface_internal::ArgMax;
  const auto tau = [](double x, double z) { return LineContactStresses(1.0, 1.0, x, z).tau_xz; };
  const auto best_over_x = [&](double z) { return tau(ArgMax([&](double x) { return tau(x, z); }, 1e-6, 3.0), z); };
  const double zeta = ArgMax(best_over_x, 1e-6, 2.0);
  const double xi = ArgMax([&](double x) { return tau(x, zeta); }, 1e-6, 3.0);
  const T z = b * zeta, x = b * xi;
  return {LineContactStresses(p0, b, x, z).tau_xz, z, x};
}

/// Line contact, the largest von Mises stress (on the axis, plane strain with ν): golden section on
/// z/b in (0, 2], evaluated in T there (value ∝ p0, depth ∝ b). ν = 0.3: 0.5575 p0 at 0.7043 b.
template <typename T>
StressPeak<T> LineContactMaxVonMises(const T& p0, const T& b, double nu) {
  return subsurface_internal::AxisPeak(
      p0, b, [nu](const auto& p, const auto& s, const auto& z) { return LineContactAxisStresses(p, s, z, nu); },
      [](const auto& s) { return subsurface_internal::VonMises(s); });
}

/// The three subsurface maxima of a line contact that a fatigue check compares: the largest
/// principal shear τ1 (Tresca; 0.30028 p0 at 0.78615 b), the largest orthogonal shear |τ_xz|
/// (Lundberg–Palmgren's τ0; 0.25 p0 at 0.5 b, x = ±0.866 b) and the largest von Mises stress
/// (0.5575 p0 at 0.7043 b for ν = 0.3), each with its depth (docs/life.md, "Contact fatigue").
template <typename T>
struct LineSubsurfaceMaxima {
  StressPeak<T> max_shear, max_orthogonal_shear, max_von_mises;
};

/// @param p0 peak pressure [MPa], b half-width [mm], nu Poisson's ratio of the (common) material.
template <typename T>
LineSubsurfaceMaxima<T> LineContactSubsurfaceMaxima(const T& p0, const T& b, double nu) {
  return {LineContactMaxPrincipalShear(p0, b), LineContactMaxOrthogonalShear(p0, b), LineContactMaxVonMises(p0, b, nu)};
}

// ---- Circular and elliptical point contact -------------------------------------------------------

/// Circular contact of radius a, stresses on the axis r = 0 at depth z > 0 (Johnson eq. 3.45):
/// σ_r = σ_θ = −p0(1 + ν)(1 − (z/a) atan(a/z)) + ½ p0 (1 + z²/a²)⁻¹, σ_z = −p0 (1 + z²/a²)⁻¹.
template <typename T>
AxisStresses<T> CircularContactAxisStresses(const T& p0, const T& a, const T& z, double nu) {
  using std::atan;
  subsurface_internal::CheckPoissonRatio(nu);
  const T s = T(1.0) / (T(1.0) + z * z / (a * a));
  const T sr = -p0 * T(1.0 + nu) * (T(1.0) - (z / a) * atan(a / z)) + T(0.5) * p0 * s;
  return {sr, sr, -p0 * s};
}

/// Elliptical contact, semi-axes a (along x) ≥ b (along y), peak pressure p0: stresses on the z
/// axis at depth z > 0. From Love's potentials of the Hertz pressure (Johnson §3.2 and
/// §3.7), ψ = (π a b p0/2) ∫_λ^∞ (1 − z²/w) dw/Δ(w), Δ = √((a² + w)(b² + w) w), λ = z²:
///   σ_x = (1/2π)(2ν ψ_z − z ψ_xx − (1 − 2ν) ψ1_xx),  σ_y likewise,  σ_z = (1/2π)(ψ_z − z ψ_zz),
/// with, for A = a² + z², B = b² + z², C = π a b p0/2,
///   ψ_z = −2zC I_z, ψ_xx = −2C I_x, ψ_yy = −2C I_y, ψ_zz = 2C(I_x + I_y),
///   ψ1_xx = 2C(J_x − z I_x), ψ1_yy = 2C(J_y − z I_y),
///   I_x = ⅔R_D(z², B, A), I_y = ⅔R_D(z², A, B), I_z = ⅔R_D(A, B, z²),
///   J_x = 2/(√A(√A + √B)), J_y = 2/(√B(√A + √B)).
/// (I_x = ∫_λ^∞ dw/((a² + w)Δ) etc.; J_x = ∫_λ^∞ √w dw/((a² + w)Δ), elementary.)
template <typename T>
AxisStresses<T> EllipticalContactAxisStresses(const T& p0, const T& a, const T& b, const T& z, double nu) {
  using std::sqrt;
  subsurface_internal::CheckPoissonRatio(nu);
  const T lam = z * z, A = a * a + lam, B = b * b + lam;
  const T c = T(0.5 * kPi) * a * b * p0;
  const T ix = T(2.0 / 3.0) * CarlsonRD(lam, B, A), iy = T(2.0 / 3.0) * CarlsonRD(lam, A, B);
  const T iz = T(2.0 / 3.0) * CarlsonRD(A, B, lam);
  const T sa = sqrt(A), sb = sqrt(B);
  const T jx = T(2.0) / (sa * (sa + sb)), jy = T(2.0) / (sb * (sa + sb));
  const T psi_z = T(-2.0) * z * c * iz, psi_xx = T(-2.0) * c * ix, psi_yy = T(-2.0) * c * iy;
  const T psi_zz = -(psi_xx + psi_yy);
  const T psi1_xx = T(2.0) * c * (jx - z * ix), psi1_yy = T(2.0) * c * (jy - z * iy);
  const T k = T(1.0 / (2.0 * kPi));
  return {k * (T(2.0 * nu) * psi_z - z * psi_xx - T(1.0 - 2.0 * nu) * psi1_xx),
          k * (T(2.0 * nu) * psi_z - z * psi_yy - T(1.0 - 2.0 * nu) * psi1_yy), k * (psi_z - z * psi_zz)};
}

/// Circular contact, the largest principal shear on the axis, τ1 = (σ_r − σ_z)/2: golden section on
/// z/a in (0, 2], evaluated in T there (value ∝ p0, depth ∝ a). Johnson (1985): 0.31 p0 at 0.48 a (ν 0.3).
template <typename T>
StressPeak<T> CircularContactMaxPrincipalShear(const T& p0, const T& a, double nu) {
  return subsurface_internal::AxisPeak(
      p0, a, [nu](const auto& p, const auto& s, const auto& z) { return CircularContactAxisStresses(p, s, z, nu); },
      [](const auto& s) { return subsurface_internal::MaxShear(s); });
}

namespace subsurface_internal {

/// The maximiser ζ = z/b of a measure of the elliptical contact's axis stresses at p0 = b = 1,
/// a/b = ratio: a 64-sample scan and golden section on (0, 2.5], then Newton steps on ∂f/∂ζ = 0.
/// The golden section leaves the maximiser uncertain by ~√ε (the maximum is flat), which leaves
/// ∂f/∂z ≠ 0 there and breaks the envelope theorem at the 1e-6 level in the derivative w.r.t. a/b;
/// the Newton steps (the slope by a Jet, its derivative by a central difference of the slope) put
/// the slope at rounding level.
template <typename Measure>
double EllipticalAxisArgMax(const Measure& measure, double ratio, double nu) {
  const auto f = [&measure, nu, ratio](const auto& zeta) {
    using S = std::decay_t<decltype(zeta)>;
    return measure(EllipticalContactAxisStresses(S(1.0), S(ratio), S(1.0), zeta, nu));
  };
  double zeta = ArgMax(f, 1e-6, 2.5);
  using J1 = ceres::Jet<double, 1>;
  const auto slope = [&f](double t) { return f(J1(t, 0)).v[0]; };
  for (int it = 0; it < 4; ++it) {
    const double d = 1e-5, g = slope(zeta), curvature = (slope(zeta + d) - slope(zeta - d)) / (2.0 * d);
    if (!(curvature < 0.0)) break;
    const double step = -g / curvature;
    if (!(std::abs(step) < 1e-3)) break;
    zeta += step;
  }
  return zeta;
}

inline double CheckedAxisRatio(double a, double b) {
  const double ratio = a / b;
  if (!(ratio >= 1.0)) throw std::invalid_argument("elliptical contact: the semi-axes must satisfy a >= b");
  return ratio;
}

/// The largest `measure` of the axis stresses on the z axis of an elliptical contact (a ≥ b): the
/// maximiser of z/b in double (EllipticalAxisArgMax), the stress there in T.
template <typename T, typename Measure>
StressPeak<T> EllipticalAxisPeak(const T& p0, const T& a, const T& b, double nu, Measure measure) {
  const double zeta = EllipticalAxisArgMax(measure, CheckedAxisRatio(Value(a), Value(b)), nu);
  const T z = b * zeta;
  return {measure(EllipticalContactAxisStresses(p0, a, b, z, nu)), z, T(0.0)};
}

}  // namespace subsurface_internal

/// Elliptical contact (a ≥ b), the largest principal shear on the z axis (the largest half
/// difference of σ_x, σ_y, σ_z): the maximiser of z/b by subsurface_internal::EllipticalAxisArgMax,
/// the stress evaluated in T there. At fixed a/b the value is ∝ p0 and the depth ∝ b; the
/// derivative of the value w.r.t. a and b is exact (envelope theorem), that of the depth w.r.t. a/b
/// is not carried (the maximiser is a double).
template <typename T>
StressPeak<T> EllipticalContactMaxPrincipalShear(const T& p0, const T& a, const T& b, double nu) {
  return subsurface_internal::EllipticalAxisPeak(p0, a, b, nu, [](const auto& s) { return subsurface_internal::MaxShear(s); });
}

/// Elliptical contact (a ≥ b), the largest von Mises stress on the z axis (σ_x, σ_y, σ_z are the
/// principal stresses there): as EllipticalContactMaxPrincipalShear. At a = b it is twice the
/// principal shear (σ_x = σ_y on the axis of a circular contact); as a/b → ∞ it tends to the line
/// contact's (LineContactMaxVonMises; ν 0.3: 0.5575 p0 at 0.7043 b).
template <typename T>
StressPeak<T> EllipticalContactMaxVonMises(const T& p0, const T& a, const T& b, double nu) {
  return subsurface_internal::EllipticalAxisPeak(p0, a, b, nu, [](const auto& s) { return subsurface_internal::VonMises(s); });
}

/// A maximum of a stress measure at a depth below the surface, its position along the surface not
/// given [MPa, mm].
template <typename T>
struct DepthPeak {
  T value, depth;
};

/// Elliptical contact (a ≥ b, b along the rolling direction y), the largest orthogonal shear
/// |τ_yz| (Lundberg–Palmgren's τ0) and its depth z0, by Lundberg & Palmgren's closed form (Acta
/// Polytechnica, Mech. Eng. Ser. 1(3), 1947; as in Harris & Kotzalas, Rolling Bearing Analysis,
/// ch. on subsurface stresses) in the auxiliary parameter t ≥ 1:
///   (b/a)² = (t² − 1)(2t − 1),  τ0/p0 = √(2t − 1) / (2t(t + 1)),  z0/b = 1 / ((t + 1)√(2t − 1)).
/// b/a → 0 (t → 1) gives the line contact's 0.25 p0 at 0.5 b. t by Newton from t = 1 + b/a (the
/// cubic is convex for t ≥ 1 and that start lies right of the root, so the iterates fall
/// monotonically), then one Newton step in T: the derivative w.r.t. a and b is that of the root.
/// Independent of ν (the orthogonal shear of a frictionless Hertz contact).
template <typename T>
DepthPeak<T> EllipticalContactMaxOrthogonalShear(const T& p0, const T& a, const T& b) {
  using std::sqrt;
  const double k = subsurface_internal::CheckedAxisRatio(Value(a), Value(b));
  const double k2 = 1.0 / (k * k);  // (b/a)²
  const auto g = [k2](double t) { return (t * t - 1.0) * (2.0 * t - 1.0) - k2; };
  const auto dg = [](double t) { return 6.0 * t * t - 2.0 * t - 2.0; };
  double t = 1.0 + 1.0 / k;
  for (int it = 0; it < 100; ++it) {
    const double step = g(t) / dg(t);
    t -= step;
    if (!(std::abs(step) > 1e-15 * t)) break;
  }
  const T ba = b / a;
  const T tt = T(t) + (ba * ba - T(k2)) / T(dg(t));  // exact first derivative of the root
  const T s = sqrt(T(2.0) * tt - T(1.0));
  return {p0 * s / (T(2.0) * tt * (tt + T(1.0))), b / ((tt + T(1.0)) * s)};
}

// ---- Contact-fatigue life -----------------------------------------------------------------------

/// Stress-life law of rolling contact fatigue: L / L_ref = (p0_ref / p0)^n at the same geometry,
/// material, lubrication and number of stress cycles per revolution. n is the material's
/// stress-life exponent on the peak pressure (Lundberg–Palmgren: n = 9 for point, 8 for line
/// contact, see LundbergPalmgrenLifeRatio; ISO 281's p = 10/3 for rollers means n = 20/3).
/// @pre p0, p0_ref > 0, n > 0.
template <typename T>
T StressLifeRatio(const T& p0, const T& p0_ref, double n) {
  using std::pow;
  return pow(p0_ref / p0, n);
}

/// The exponents of Lundberg & Palmgren (Acta Polytechnica, Mech. Eng. Series 1(3), 1947):
/// ln(1/S) ∝ τ0^c N^e V / z0^h with V ∝ a z0 l (a: the contact's extent across the rolling
/// direction, l: the track length), so at a given survival S, N ∝ (τ0^−c z0^(h−1) a^−1)^(1/e).
struct LundbergPalmgrenExponents {
  double c = 31.0 / 3.0;  ///< stress exponent
  double h = 7.0 / 3.0;   ///< depth exponent
  double e = 10.0 / 9.0;  ///< Weibull slope (10/9 point contact; 9/8 line contact)
};

/// Lundberg–Palmgren life ratio of two contacts on the same track length and material:
/// L / L_ref = ((τ0/τ0_ref)^−c (z0/z0_ref)^(h−1) (a/a_ref)^−1)^(1/e), with τ0 the largest orthogonal
/// shear amplitude, z0 its depth, a the contact's extent across the rolling direction.
template <typename T>
T LundbergPalmgrenLifeRatio(const T& tau0, const T& z0, const T& width, const T& tau0_ref, const T& z0_ref,
                            const T& width_ref, const LundbergPalmgrenExponents& ex = {}) {
  using std::pow;
  return pow(pow(tau0 / tau0_ref, -ex.c) * pow(z0 / z0_ref, ex.h - 1.0) * (width_ref / width), 1.0 / ex.e);
}

}  // namespace camopt::contact
