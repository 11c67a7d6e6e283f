// Hertz contact closed forms (Johnson, Contact Mechanics, ch. 4), over the scalar T.
// Units: forces N, lengths mm, moduli and pressures MPa (N/mm²).
#pragma once

#include <algorithm>
#include <cmath>

#include "model/common/material.h"
#include "model/common/roots.h"
#include "model/common/scalar.h"

namespace camopt::contact {

/// The composite modulus E* has one home, model/common/material.h.
using camopt::CompositeModulus;

/// Line (two-cylinder, plane-strain) contact: load F over length L, effective radius R'
/// (1/R' = 1/R₁ + 1/R₂, a concave radius negative). p_max² = F E* / (π L R').
template <typename T>
T LineContactPeakPressureSquared(const T& force, const T& length, const T& r_eff, const T& e_star) {
  return force * e_star / (T(kPi) * length * r_eff);
}

/// p_max = sqrt(LineContactPeakPressureSquared): the square root is monotonic and correctly
/// rounded, so the largest p_max of several contacts is exactly the root of the largest square
/// (one root per maximum instead of one per contact, model/lcr/cycle.cc).
template <typename T>
T LineContactPeakPressure(const T& force, const T& length, const T& r_eff, const T& e_star) {
  using std::sqrt;
  return sqrt(LineContactPeakPressureSquared(force, length, r_eff, e_star));
}

/// Line contact half-width b = sqrt(4 F R' / (π L E*)).
template <typename T>
T LineContactHalfWidth(const T& force, const T& length, const T& r_eff, const T& e_star) {
  using std::sqrt;
  return sqrt(T(4.0) * force * r_eff / (T(kPi) * length * e_star));
}

/// Line contact half-width from its peak pressure, b = 2 p_max R'/E*: the ratio of
/// LineContactHalfWidth and LineContactPeakPressure (b²/p_max² = 4 R'²/E*², F and L cancel), so it
/// holds for a slice of a finite-length contact too (model/contact/roller_slices.h: b_j, p0_j).
template <typename T>
T LineContactHalfWidthFromPeakPressure(const T& peak_pressure, const T& r_eff, const T& e_star) {
  return T(2.0) * peak_pressure * r_eff / e_star;
}

/// Line contact: the load per unit effective radius at which the peak pressure reaches p_max,
/// F / R' = π L p_max² / E* (the inverse of LineContactPeakPressure; a capacity margin for sizing).
template <typename T>
T LineContactLoadPerRadius(const T& peak_pressure, const T& length, const T& e_star) {
  return T(kPi) * length * peak_pressure * peak_pressure / e_star;
}

/// Circular point contact (sphere of effective radius R on a flat):
/// a = (3 F R / (4 E*))^(1/3), p0 = 3F/(2πa²), approach δ = a²/R.
template <typename T>
struct PointContact {
  T radius;        // contact radius a [mm]
  T peak_pressure; // p0 [MPa]
  T approach;      // δ [mm]
};

template <typename T>
PointContact<T> CircularPointContact(const T& force, const T& r_eff, const T& e_star) {
  using std::cbrt;
  const T a = cbrt(T(3.0) * force * r_eff / (T(4.0) * e_star));
  return {a, T(3.0) * force / (T(2.0 * kPi) * a * a), a * a / r_eff};
}

/// Hertz point-contact stiffness: F = K δ^(3/2) with K = (4/3) √R E* (R effective radius [mm],
/// E* [MPa]; K in N/mm^1.5). Follows from a = √(R δ) and F = 4 E* a³ / (3 R).
template <typename T>
T PointContactStiffness(const T& r_eff, const T& e_star) {
  using std::sqrt;
  return T(4.0) / T(3.0) * sqrt(r_eff) * e_star;
}

/// Complete elliptic integrals K(m) and E(m) of the first and second kind, parameter m = e²
/// (0 <= m < 1), by the arithmetic–geometric mean (Abramowitz & Stegun 17.6).
struct CompleteEllipticIntegrals {
  double k = 0, e = 0;
};

inline CompleteEllipticIntegrals EllipticKE(double m) {
  double a = 1.0, b = std::sqrt(1.0 - m), c2 = m, sum = 0.5 * c2, power = 0.5;
  for (int n = 0; n < 40 && std::abs(a - b) > 1e-16 * a; ++n) {
    const double c = 0.5 * (a - b);
    const double next_b = std::sqrt(a * b);
    a = 0.5 * (a + b);
    b = next_b;
    power *= 2.0;
    sum += power * c * c;
  }
  const double k = kPi / (2.0 * a);
  return {k, k * (1.0 - sum)};
}

/// Elliptical point contact (Johnson §4.2): gap A x² + B y² with A = 1/(2 R_x), B = 1/(2 R_y)
/// (R_x, R_y the effective radii of relative curvature in the two principal directions).
/// Semi-axes a_x, a_y (the longer one along the larger radius), peak pressure
/// p0 = 3F/(2π a_x a_y), approach δ. With the major semi-axis a, minor b, e² = 1 − b²/a²:
///   B/A (large over small curvature) = ((a/b)² E(e) − K(e)) / (K(e) − E(e)),
///   A_small = p0 b (K − E)/(E* a² e²),  δ = p0 b K(e)/E*.
/// e is found by bisection; equal radii give the circular contact.
struct EllipticalContact {
  double semi_axis_x = 0, semi_axis_y = 0;  // [mm]
  double peak_pressure = 0;                 // p0 [MPa]
  double approach = 0;                      // δ [mm]
  double eccentricity_squared = 0;          // e² of the contact ellipse
};

inline EllipticalContact EllipticalPointContact(double force, double r_x, double r_y, double e_star) {
  const double r_large = std::max(r_x, r_y), r_small = std::min(r_x, r_y);
  const double ratio = r_large / r_small;  // = B/A
  EllipticalContact out;
  if (ratio <= 1.0 + 1e-12) {
    const PointContact<double> c = CircularPointContact(force, 2.0 / (1.0 / r_x + 1.0 / r_y), e_star);
    out.semi_axis_x = out.semi_axis_y = c.radius;
    out.peak_pressure = c.peak_pressure;
    out.approach = c.approach;
    return out;
  }
  const auto curvature_ratio = [](double m) {
    const CompleteEllipticIntegrals ke = EllipticKE(m);
    return (ke.e / (1.0 - m) - ke.k) / (ke.k - ke.e);
  };
  const RootBracket br = BisectIncreasing(curvature_ratio, ratio, 1e-8, 1.0 - 1e-15, 200, 1e-15);
  const double m = br.mid();
  const CompleteEllipticIntegrals ke = EllipticKE(m);
  const double g = e_star * m / (2.0 * r_large * (ke.k - ke.e));  // p0 b / a²
  const double a = std::cbrt(3.0 * force / (2.0 * kPi * g));
  const double b = a * std::sqrt(1.0 - m);
  out.peak_pressure = g * a * a / b;
  out.approach = out.peak_pressure * b * ke.k / e_star;
  out.eccentricity_squared = m;
  out.semi_axis_x = r_x >= r_y ? a : b;
  out.semi_axis_y = r_x >= r_y ? b : a;
  return out;
}

}  // namespace camopt::contact
