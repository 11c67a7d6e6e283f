// Elastic materials and the composite (contact) modulus E*: the one home of both.
// Units: moduli in MPa (N/mm²). Hertz's E* (Johnson, Contact Mechanics, eq. 4.22):
//   1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂.
#pragma once

#include "model/common/scalar.h"

namespace camopt {

/// Composite modulus E* of two isotropic bodies.
/// @tparam T double or ceres::Jet.
/// @param e1,e2 Young's moduli [MPa], > 0.  @param nu1,nu2 Poisson's ratios, in [0, 0.5).
/// @return E* [MPa].
template <typename T>
T CompositeModulus(const T& e1, const T& nu1, const T& e2, const T& nu2) {
  return T(1.0) / ((T(1.0) - nu1 * nu1) / e1 + (T(1.0) - nu2 * nu2) / e2);
}

/// An isotropic elastic material (steel by default).
struct Material {
  double youngs_modulus_MPa = 206000.0;  ///< E [MPa]
  double poisson_ratio = 0.3;            ///< ν

  /// E* of two bodies of this material in contact: E / (2 (1 − ν²)).
  double composite_modulus_MPa() const {
    return CompositeModulus(youngs_modulus_MPa, poisson_ratio, youngs_modulus_MPa, poisson_ratio);
  }
  /// E* of this body against another.
  double composite_modulus_MPa(const Material& other) const {
    return CompositeModulus(youngs_modulus_MPa, poisson_ratio, other.youngs_modulus_MPa,
                            other.poisson_ratio);
  }
  bool operator==(const Material&) const = default;
};

}  // namespace camopt
