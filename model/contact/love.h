// Love (1929) surface displacement of an elastic half-space under a uniform pressure on a
// rectangle: the influence coefficient of the cycloid paper's eq. (21), written in the
// cancellation-safe asinh form.
//
// The paper writes each term as (x̄+ξ) ln[((ȳ+η) + r₁)/((ȳ−η) + r₂)]. When ȳ−η is large and
// negative, (ȳ−η) + sqrt((ȳ−η)² + (x̄+ξ)²) is the difference of two nearly equal numbers and
// loses every digit. With ln(t + sqrt(t² + s²)) = asinh(t/|s|) + ln|s| the same term is
// (x̄+ξ)[asinh((ȳ+η)/|x̄+ξ|) − asinh((ȳ−η)/|x̄+ξ|)], and asinh is odd and accurate on both sides.
// Summed over the four corners, the influence is the signed integral of 1/r over the rectangle.
#pragma once

#include <cmath>

#include "model/common/scalar.h"

namespace camopt::contact {

/// asinh(z) = sign(z) log1p(|z| + z²/(1 + sqrt(1 + z²))), accurate for small and large |z| and
/// usable with ceres::Jet (which has no asinh). The sign branch meets continuously at 0.
template <typename T>
T Asinh(const T& z) {
  using std::abs;
  using std::log1p;
  using std::sqrt;
  const T s = abs(z);
  const T r = log1p(s + s * s / (T(1.0) + sqrt(T(1.0) + s * s)));
  return Value(z) < 0.0 ? T(-r) : r;
}
inline double Asinh(double z) { return std::asinh(z); }

/// Signed integral of 1/sqrt(x'² + y'²) over the rectangle with corners (0, 0) and (x, y):
/// x asinh(y/|x|) + y asinh(x/|y|). Odd in x and in y; 0 when x or y is 0 (the limit; the
/// branch only removes the 0·asinh(±∞) form, the two sides meet continuously).
template <typename T>
T LoveCornerIntegral(const T& x, const T& y) {
  using std::abs;
  if (Value(x) == 0.0 || Value(y) == 0.0) return T(0.0);
  return x * Asinh(T(y / abs(x))) + y * Asinh(T(x / abs(y)));
}

/// Normal surface displacement per unit pressure and unit composite modulus at the point
/// (x̄, ȳ) relative to the centre of a loaded rectangle of half-sizes ξ, η [mm]:
/// u = p / (π E*) ∬ dA / r, so the result is u·E*/p [mm]; divide by E* [MPa] and multiply by
/// the cell pressure [MPa] to get millimetres. Cycloid paper eq. (21) with its factor
/// (1−ν₁²)/(πE₁) + (1−ν₂²)/(πE₂) = 1/(π E*).
template <typename T>
T LoveInfluence(const T& x_bar, const T& y_bar, const T& xi, const T& eta) {
  const T x1 = x_bar + xi, x2 = x_bar - xi;
  const T y1 = y_bar + eta, y2 = y_bar - eta;
  return (LoveCornerIntegral(x1, y1) - LoveCornerIntegral(x1, y2) - LoveCornerIntegral(x2, y1) +
          LoveCornerIntegral(x2, y2)) /
         T(kPi);
}

}  // namespace camopt::contact
