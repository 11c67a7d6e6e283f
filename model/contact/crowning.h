// Crowning drop formulas: the material removed from a roller (or a tooth face) at axial position y
// from its mid-length. One home for the cycloid tooth crowning (model/cycloid/crowning.h) and the
// LCR roller crowning (model/lcr/contact3d.h); over the scalar T so that the parameters can carry
// derivatives.
//
//   circular:     R − sqrt(R² − y²)                                       (cycloid paper eq. 5)
//   partial:      flat over |y| ≤ L0/2, then R − sqrt(R² − s²), s = |y| − L0/2   (eq. 6)
//   logarithmic:  f ln(1 / (1 − (2y/Le)²)), |y| < Le/2                    (eq. 7, Lundberg's form)
//   logarithmic with a prescribed end drop z_m and a flat centre L0 (Fujiwara & Kawase, NTN
//   Technical Review 75, 2007, written from the formula): s = (|y| − L0/2)/(Le/2 − L0/2),
//     f ln(1 / (1 − (1 − e^(−z_m/f)) s²)), equal to z_m at s = 1.
//
// Lundberg's form with Le equal to the contact length has an unbounded drop at the ends: the end
// cell of a grid sees f·ln(L/(2·dy)), which grows as the cells shrink (docs/lcr.md,
// docs/cycloid.md). The LCR rollers therefore require Le > l_r (finite drop f ln(1/(1 − (l/Le)²))).
#pragma once

#include <cmath>

#include "model/common/scalar.h"

namespace camopt::contact {

enum class CrowningType { kNone, kCircular, kPartial, kLogarithmic };

/// Crowning drop [mm] at axial position y [mm] from the mid-length. radius: R (circular, partial);
/// flat_length: L0 (partial; logarithmic with an end drop); coefficient: f and effective_length: Le
/// (logarithmic); end_drop: z_m (0 = Lundberg's unbounded form).
/// @pre |y| < Le/2 for the logarithmic form, |y| − L0/2 < R for the circular ones.
template <typename T>
CAMOPT_FLATTEN T CrowningDrop(CrowningType type, const T& radius, const T& flat_length, const T& coefficient,
               const T& effective_length, const T& y, const T& end_drop = T(0.0)) {
  using std::abs;
  using std::exp;
  using std::log;
  using std::sqrt;
  switch (type) {
    case CrowningType::kNone:
      return T(0.0);
    case CrowningType::kCircular:
      // R − sqrt(R² − y²) written as y² / (R + sqrt(R² − y²)): no cancellation for R ≫ y.
      return y * y / (radius + sqrt(radius * radius - y * y));
    case CrowningType::kPartial: {
      const T s = PositivePart(T(abs(y) - T(0.5) * flat_length));  // zero on the flat
      return s * s / (radius + sqrt(radius * radius - s * s));
    }
    case CrowningType::kLogarithmic: {
      const T half_flat = T(0.5) * flat_length;
      const T r = PositivePart(T(abs(y) - half_flat)) / (T(0.5) * effective_length - half_flat);
      if (!(Value(end_drop) > 0.0)) return -coefficient * log(T(1.0) - r * r);
      if (!(Value(coefficient) > 0.0)) return T(0.0);
      return -coefficient * log(T(1.0) - (T(1.0) - exp(-end_drop / coefficient)) * r * r);
    }
  }
  return T(0.0);
}

/// Lundberg's coefficient for a uniform load along a contact of length l: a uniform line load
/// q = F/l displaces the half-space along the line by (q/(π E*)) ln(1 − (2y/l)²) + const (the far
/// field of the strip), so the gap f ln(1/(1 − (2y/l)²)) with f = F/(π l E*) closes it.
template <typename T>
T LundbergCoefficient(const T& force, const T& length, const T& e_star) {
  return force / (T(kPi) * length * e_star);
}

}  // namespace camopt::contact
