// Hertz contact closed forms (Johnson, Contact Mechanics, ch. 4), over the scalar T.
// Units: forces N, lengths mm, moduli and pressures MPa (N/mm²).
#pragma once

#include <cmath>

#include "model/common/scalar.h"

namespace camopt::contact {

/// Composite modulus E*: 1/E* = (1−ν₁²)/E₁ + (1−ν₂²)/E₂.
template <typename T>
T CompositeModulus(const T& e1, const T& nu1, const T& e2, const T& nu2) {
  return T(1.0) / ((T(1.0) - nu1 * nu1) / e1 + (T(1.0) - nu2 * nu2) / e2);
}

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

}  // namespace camopt::contact
