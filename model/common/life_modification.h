// The modified rating life of ISO 281:2007 §9: L_nm = a1 a_ISO L10, with the life modification
// factor a_ISO of §9.3 from the viscosity ratio κ = ν/ν1 and the fatigue-load term e_C C_u / P.
// Over double (a result beside the basic life; no sizing differentiates it).
//
// Reference viscosity (ISO 281:2007 §9.3, eq. 28 and its Figure), n the bearing's speed
// [r/min], D_pw its pitch diameter [mm]:
//   ν1 = 45000 n^−0.83 D_pw^−0.5   for n < 1000 r/min,
//   ν1 = 4500  n^−0.5  D_pw^−0.5   for n ≥ 1000 r/min.
// The two branches do not meet at n = 1000 r/min: 45000·1000^−0.83 = 145.62 against
// 4500·1000^−0.5 = 142.30 (times D_pw^−0.5), a step of 2.3 % down across n = 1000. The standard's
// equations are used as written; the step is not smoothed.
//
// Life modification factor (ISO 281:2007 §9.3; x = e_C C_u / P):
//   radial ball bearings   (eqs. 31–33): a_ISO = 0.1 [1 − (2.5671 − c/κ^p)^0.83 x^(1/3)]^−9.3,
//   radial roller bearings (eqs. 34–36): a_ISO = 0.1 [1 − (1.5859 − c/κ^p) x^0.4]^−9.185,
// with (c, p) by the range of κ:
//                      ball c    roller c   p
//   0.1 ≤ κ < 0.4      2.2649    1.3993     0.054381
//   0.4 ≤ κ < 1        1.9987    1.2348     0.19087
//   1   ≤ κ ≤ 4        1.9987    1.2348     0.071739
// The constants make the bands meet at κ = 0.4 to their five digits (c/κ^p: 2.38062 against
// 2.38069 for balls, 3.0e-5 apart; 1.470792 against 1.470793 for rollers, 5e-7 apart; the 9.3th
// power makes a ball's a_ISO step by up to 0.1 % there) and exactly at κ = 1 (c/1^p = c). a_ISO is limited to 50 (§9.3), and taken as 50
// where the bracket is <= 0 (x so large that the formula's pole is passed). κ > 4 is taken as 4
// (§9.3: no further benefit is credited). κ < 0.1 is outside the method (§9.3): no value
// is extrapolated; the result says why.
//
// a1 = 1: the life at 90 % reliability (ISO 281:2007 §9: a1 = 1 for 90 % reliability). Other reliabilities are not
// modelled.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "model/common/argument_check.h"
#include "model/common/bearing_life.h"

namespace camopt {

/// The largest a_ISO the standard credits (ISO 281:2007 §9.3).
inline constexpr double kMaxLifeModificationFactor = 50.0;
/// The viscosity ratio range of the method (ISO 281:2007 §9.3): below kMinViscosityRatio it
/// does not apply; above kMaxViscosityRatio κ is taken as kMaxViscosityRatio.
inline constexpr double kMinViscosityRatio = 0.1, kMaxViscosityRatio = 4.0;
/// The speed where ν1's two branches of ISO 281:2007 eq. 28 change [r/min].
inline constexpr double kReferenceViscosityBranchSpeed_rpm = 1000.0;

namespace life_modification_internal {

// model/common/argument_check.h, its messages starting "modified life: ".
inline constexpr const char* kWhat = "modified life";
[[noreturn]] inline void Reject(const std::string& f, const std::string& r, double v) { argument_check::Reject(kWhat, f, r, v); }
inline void CheckPositive(const std::string& field, double v) { argument_check::Positive(kWhat, field, v); }

}  // namespace life_modification_internal

/// The reference kinematic viscosity ν1 [mm²/s] for adequate lubrication (ISO 281:2007 §9.3,
/// eq. 28): 45000 n^−0.83 D_pw^−0.5 below 1000 r/min, 4500 n^−0.5 D_pw^−0.5 from it on.
/// @param speed_rpm n, the bearing's speed (inner relative to outer ring) [r/min], finite > 0.
/// @param pitch_diameter_mm D_pw [mm], finite > 0.
/// @throws std::invalid_argument naming the field.
inline double ReferenceViscosity(double speed_rpm, double pitch_diameter_mm) {
  life_modification_internal::CheckPositive("speed_rpm", speed_rpm);
  life_modification_internal::CheckPositive("pitch_diameter_mm", pitch_diameter_mm);
  const double d = std::pow(pitch_diameter_mm, -0.5);
  if (speed_rpm < kReferenceViscosityBranchSpeed_rpm) return 45000.0 * std::pow(speed_rpm, -0.83) * d;
  return 4500.0 * std::pow(speed_rpm, -0.5) * d;
}

/// a_ISO and how it was reached.
struct LifeModification {
  bool computed = false;       ///< false: κ below the method's range (value is NaN)
  double a_iso = NAN;          ///< the factor, in [0.1, 50] when computed
  double kappa_used = NAN;     ///< κ as the formula took it (4 for κ > 4)
  bool kappa_clamped = false;  ///< κ > 4 taken as 4
  bool capped = false;         ///< the formula gave more than 50 (or its bracket was <= 0): 50
  std::string note;            ///< why not computed, or what was clamped; empty otherwise
};

/// The life modification factor a_ISO of ISO 281:2007 §9.3 (eqs. 31–33 for radial ball, 34–36
/// for radial roller bearings) from the viscosity ratio κ = ν/ν1 and x = e_C C_u / P.
/// κ < 0.1: not computed (the note says why); κ > 4: taken as 4; a_ISO <= 50.
/// @param kappa κ, finite > 0.  @param ec_cu_over_p x, >= 0 (+∞ for an unloaded bearing: 50).
/// @throws std::invalid_argument naming the field for a non-finite or non-positive κ or a
/// negative or NaN x.
inline LifeModification LifeModificationFactor(BearingKind kind, double kappa, double ec_cu_over_p) {
  life_modification_internal::CheckPositive("kappa", kappa);
  if (!(ec_cu_over_p >= 0.0)) life_modification_internal::Reject("e_C C_u / P", ">= 0", ec_cu_over_p);
  LifeModification out;
  if (kappa < kMinViscosityRatio) {
    std::ostringstream os;
    os.precision(4);
    os << "kappa = " << kappa << " is below 0.1, outside ISO 281:2007's method (9.3): a_ISO not computed";
    out.note = os.str();
    return out;
  }
  out.computed = true;
  out.kappa_clamped = kappa > kMaxViscosityRatio;
  const double k = std::min(kappa, kMaxViscosityRatio);
  out.kappa_used = k;
  const bool ball = kind == BearingKind::kBall;
  // (c, p) of the κ band (eqs. 31–36).
  double c = 0.0, p = 0.0;
  if (k < 0.4) {
    c = ball ? 2.2649 : 1.3993;
    p = 0.054381;
  } else if (k < 1.0) {
    c = ball ? 1.9987 : 1.2348;
    p = 0.19087;
  } else {
    c = ball ? 1.9987 : 1.2348;
    p = 0.071739;
  }
  const double lub = (ball ? 2.5671 : 1.5859) - c / std::pow(k, p);
  const double bracket = ball ? 1.0 - std::pow(lub, 0.83) * std::cbrt(ec_cu_over_p)
                              : 1.0 - lub * std::pow(ec_cu_over_p, 0.4);
  const double a = bracket > 0.0 ? 0.1 * std::pow(bracket, ball ? -9.3 : -9.185) : kInf;
  out.capped = !(a <= kMaxLifeModificationFactor);
  out.a_iso = std::min(a, kMaxLifeModificationFactor);
  if (out.kappa_clamped) {
    std::ostringstream os;
    os.precision(4);
    os << "kappa = " << kappa << " above 4 taken as 4 (ISO 281:2007 9.3)";
    out.note = os.str();
  }
  if (out.capped) out.note += std::string(out.note.empty() ? "" : "; ") + "a_ISO limited to 50 (ISO 281:2007 9.3)";
  return out;
}

/// The contamination factor e_C's range (ISO 281:2007 §9.3, Table 13: 1 for extreme
/// cleanliness down to 0 for very severe contamination).
/// @throws std::invalid_argument unless e_C is in [0, 1].
inline void CheckContaminationFactor(double e_c) {
  if (!(e_c >= 0.0 && e_c <= 1.0)) life_modification_internal::Reject("contamination_factor", "in [0, 1]", e_c);
}

}  // namespace camopt
