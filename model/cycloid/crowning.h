// Longitudinal (axial) crowning of the cycloid gear tooth: the material removed at axial position
// u from the face centre. Cycloid load-distribution paper, eqs. (5)–(7); added to the initial
// separation of each contact cell, eqs. (17)–(19).
//
//   FCM (full):        Δf(u) = R_f − sqrt(R_f² − u²)                                   eq. (5)
//   PCM (partial):     Δp(u) = R_p − sqrt(R_p² − (|u| − L0/2)²) for |u| > L0/2, else 0  eq. (6)
//   LCM (logarithmic): Δl(u) = f ln(1 / (1 − (2u/L)²)),  |u| < L/2                    eq. (7)
//
// Eq. (7) with L = the face width B has an unbounded drop at the face ends: the end cell of a grid
// of q axial cells sees f·ln(1/(1 − (1 − 1/q)²)) ≈ f·ln(q/2), which grows as the cells shrink, so
// no grid-converged optimum exists for that form (docs/cycloid.md). Two finite-drop forms:
//   - LCM with an effective length L > B (drop f·ln(1/(1 − (B/L)²)) at the face ends);
//   - the logarithmic profile with a prescribed end drop z_m (the three-parameter form of
//     Fujiwara & Kawase, NTN Technical Review 75, 2007, written here from the formula): a flat
//     centre of length L0, then with s = (|u| − L0/2)/(L/2 − L0/2) ∈ [0, 1]
//       Δ(u) = f ln(1 / (1 − (1 − e^(−z_m/f)) s²)),
//     equal to z_m at the end of the effective length (s = 1) and tending to eq. (7) as z_m → ∞.
//     end_drop_mm = 0 selects eq. (7) (no prescribed drop).
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
#include "model/contact/crowning.h"

namespace camopt::cycloid {

enum class CrowningType { kNone, kFull, kPartial, kLogarithmic };

/// Crowning parameters [mm]. effective_length_mm = 0 means the face width.
struct Crowning {
  CrowningType type = CrowningType::kNone;
  double radius_mm = 0;            ///< R_f (full) or R_p (partial)
  double flat_length_mm = 0;       ///< L0 (partial)
  double coefficient_mm = 0;       ///< f (logarithmic)
  double effective_length_mm = 0;  ///< L (logarithmic); >= face width; 0 = face width
  double end_drop_mm = 0;          ///< z_m (logarithmic), the drop at |u| = L/2; 0 = unbounded (eq. 7)
};

/// Whether the peak contact pressure of a tooth with this crowning is singular at the face ends:
/// a straight face, or a partially crowned one, loads the end of a finite line contact, whose
/// pressure peak grows without bound as the cells along the face shrink (the end effect of
/// finite-length cylinders in contact; measured on a straight ratio-24 tooth: 1349, 1398, 1441 MPa
/// at 16², 48², 64² cells). Full and logarithmic crowning relieve the ends smoothly and their peak
/// converges under refinement (docs/cycloid.md, error estimates).
inline bool EdgePeakIsSingular(CrowningType type) {
  return type == CrowningType::kNone || type == CrowningType::kPartial;
}

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
      // Far beyond any crowning (a few µm), and a bound the drop's logarithm keeps finite in: the
      // same 1e6 × the part's size as every other length of a study (1e300 made the gaps infinite).
      if (!(c.coefficient_mm <= 1e6 * face_width_mm))
        return "logarithmic crowning coefficient must be at most 1e6 times the face width";
      if (!(c.end_drop_mm <= 1e6 * face_width_mm)) return "end drop must be at most 1e6 times the face width";
      if (!(c.effective_length_mm <= 1e6 * face_width_mm))
        return "effective length must be at most 1e6 times the face width";
      if (!(c.effective_length_mm == 0 || c.effective_length_mm >= face_width_mm))
        return "effective length must be >= the face width";
      if (!(c.end_drop_mm >= 0)) return "end drop must be >= 0";
      if (!(c.flat_length_mm >= 0 && c.flat_length_mm < face_width_mm))
        return "flat length must be in [0, face width)";
      return "";
  }
  return "unknown crowning type";
}

/// Crowning drop [mm] at axial position u [mm] from the face centre (eqs. 5–7).
/// @pre |u| < face_width/2 for LCM with L = face width (the drop is infinite at the edge itself;
///      cell centres are always inside). Over T so that the coefficient can carry derivatives.
template <typename T>
T CrowningDrop(CrowningType type, const T& radius, const T& flat_length, const T& coefficient,
               const T& effective_length, const T& u, const T& end_drop = T(0.0)) {
  // The formulas have one home, model/contact/crowning.h.
  const contact::CrowningType t = type == CrowningType::kFull        ? contact::CrowningType::kCircular
                                  : type == CrowningType::kPartial     ? contact::CrowningType::kPartial
                                  : type == CrowningType::kLogarithmic ? contact::CrowningType::kLogarithmic
                                                                       : contact::CrowningType::kNone;
  return contact::CrowningDrop(t, radius, flat_length, coefficient, effective_length, u, end_drop);
}

/// Crowning drop [mm] for the parameters of c on a face of width face_width_mm.
inline double CrowningDrop(const Crowning& c, double face_width_mm, double u_mm) {
  const double length = c.effective_length_mm > 0 ? c.effective_length_mm : face_width_mm;
  return CrowningDrop<double>(c.type, c.radius_mm, c.flat_length_mm, c.coefficient_mm, length, u_mm,
                              c.end_drop_mm);
}

}  // namespace camopt::cycloid
