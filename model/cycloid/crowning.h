// Longitudinal (axial) crowning of the cycloid gear tooth: the material removed at axial position
// u from the face centre. Cycloid load-distribution paper, eqs. (5)–(7); added to the initial
// separation of each contact cell, eqs. (17)–(19).
//
//   FCM (full):        Δf(u) = R_f − sqrt(R_f² − u²)                                   eq. (5)
//   PCM (partial):     Δp(u) = R_p − sqrt(R_p² − (|u| − L0/2)²) for |u| > L0/2, else 0  eq. (6)
//   LCM (logarithmic): Δl(u) = f ln(1 / (1 − (2u/L)²)),  |u| < L/2                    eq. (7)
//
// Where the paper's discretised forms (eqs. 18–19) differ from eqs. (5)–(7) we follow eqs. (5)–(7)
// evaluated at the cell centres: eq. (18) applies the full-circle drop R_p − sqrt(R_p² − u²) beyond
// the flat (a step at |u| = L0/2, not a circle tangent to the flat as eq. (6) and the text define),
// and eq. (19)'s index form (2j − 1)/(q + 1) − 1 is not symmetric about the face centre.
// See docs/cycloid.md.
#pragma once

#include <cmath>
#include <string>

#include "model/common/scalar.h"

namespace camopt::cycloid {

enum class CrowningType { kNone, kFull, kPartial, kLogarithmic };

/// Crowning parameters [mm]. effective_length_mm = 0 means the face width.
struct Crowning {
  CrowningType type = CrowningType::kNone;
  double radius_mm = 0;            ///< R_f (full) or R_p (partial)
  double flat_length_mm = 0;       ///< L0 (partial)
  double coefficient_mm = 0;       ///< f (logarithmic)
  double effective_length_mm = 0;  ///< L (logarithmic); >= face width; 0 = face width
};

/// Checks crowning parameters against the face width; "" or the reason they are invalid.
inline std::string CheckCrowning(const Crowning& c, double face_width_mm) {
  switch (c.type) {
    case CrowningType::kNone:
      return "";
    case CrowningType::kFull:
      if (!(c.radius_mm > 0.5 * face_width_mm)) return "crowning radius must exceed half the face width";
      return "";
    case CrowningType::kPartial:
      if (!(c.flat_length_mm >= 0 && c.flat_length_mm <= face_width_mm))
        return "flat length must be in [0, face width]";
      if (!(c.radius_mm > 0.5 * (face_width_mm - c.flat_length_mm)))
        return "crowning radius must exceed half the crowned length";
      return "";
    case CrowningType::kLogarithmic:
      if (!(c.coefficient_mm >= 0)) return "logarithmic crowning coefficient must be >= 0";
      if (!(c.effective_length_mm == 0 || c.effective_length_mm >= face_width_mm))
        return "effective length must be >= the face width";
      return "";
  }
  return "unknown crowning type";
}

/// Crowning drop [mm] at axial position u [mm] from the face centre (eqs. 5–7).
/// @pre |u| < face_width/2 for LCM with L = face width (the drop is infinite at the edge itself;
///      cell centres are always inside). Over T so that the coefficient can carry derivatives.
template <typename T>
T CrowningDrop(CrowningType type, const T& radius, const T& flat_length, const T& coefficient,
               const T& effective_length, const T& u) {
  using std::abs;
  using std::log;
  using std::sqrt;
  switch (type) {
    case CrowningType::kNone:
      return T(0.0);
    case CrowningType::kFull:
      // R − sqrt(R² − u²) written as u² / (R + sqrt(R² − u²)): no cancellation for R ≫ u.
      return u * u / (radius + sqrt(radius * radius - u * u));
    case CrowningType::kPartial: {
      const T s = PositivePart(T(abs(u) - T(0.5) * flat_length));  // zero on the flat
      return s * s / (radius + sqrt(radius * radius - s * s));
    }
    case CrowningType::kLogarithmic: {
      const T r = T(2.0) * u / effective_length;
      return -coefficient * log(T(1.0) - r * r);  // log1p-free: r² ≤ (1 − 1/q)² in use
    }
  }
  return T(0.0);
}

/// Crowning drop [mm] for the parameters of c on a face of width face_width_mm.
inline double CrowningDrop(const Crowning& c, double face_width_mm, double u_mm) {
  const double length = c.effective_length_mm > 0 ? c.effective_length_mm : face_width_mm;
  return CrowningDrop<double>(c.type, c.radius_mm, c.flat_length_mm, c.coefficient_mm, length, u_mm);
}

}  // namespace camopt::cycloid
