// Hertz contact closed forms (Johnson, Contact Mechanics, ch. 4), over the scalar T.
// Units: forces N, lengths mm, moduli and pressures MPa (N/mm²).
#pragma once

#include <cmath>

#include "model/common/material.h"
#include "model/common/scalar.h"

namespace camopt::contact {

/// The composite modulus E* has one home, model/common/material.h.
using camopt::CompositeModulus;

/// Line (two-cylinder, plane-strain) contact: load F over length L, effective radius R'
/// (1/R' = 1/R₁ + 1/R₂, a concave radius negative). p_max = sqrt(F E* / (π L R')).
template <typename T>
T LineContactPeakPressure(const T& force, const T& length, const T& r_eff, const T& e_star) {
  using std::sqrt;
  return sqrt(force * e_star / (T(kPi) * length * r_eff));
}

/// Line contact half-width b = sqrt(4 F R' / (π L E*)).
template <typename T>
T LineContactHalfWidth(const T& force, const T& length, const T& r_eff, const T& e_star) {
  using std::sqrt;
  return sqrt(T(4.0) * force * r_eff / (T(kPi) * length * e_star));
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

}  // namespace camopt::contact
