// Normalised cam motion laws: a rise of 1 over a unit interval of the normalised time u ∈ [0, 1],
// with displacement, velocity, acceleration and jerk (SVAJ) as derivatives with respect to u.
//
// The laws are those of the cam-design textbooks (Norton, "Cam Design and Manufacturing
// Handbook", ch. 3; Rothbart, "Cam Design Handbook"), written here from their defining
// acceleration shapes. They know nothing about any cam: a MotionProgram (motion_program.h)
// scales them into segments of a follower displacement program for disc or globoidal cams.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/common/scalar.h"

namespace camopt::motion {

enum class MotionLaw {
  kDwell,
  kCycloidal,
  kSimpleHarmonic,
  kModifiedSine,
  kModifiedTrapezoid,
  kPolynomial345,
  kPolynomial4567,
  /// Constant acceleration +4 over the first half, −4 over the second (VDI 2143 "quadratische
  /// Parabel"): the lowest peak acceleration of any rest-in-rest law, with acceleration jumps at
  /// the ends and in the middle.
  kQuadraticParabola,
  /// A polynomial through given boundary values (PolynomialThrough, motion_program.h); its shape
  /// is carried by the segment's coefficients, not by NormalizedLaw.
  kPolynomial,
  /// A B-spline through control values (BSplineThrough, motion_program.h); its shape is carried
  /// by the segment's coefficients and degree, not by NormalizedLaw.
  kBSpline,
};

/// A rest-in-rest law's characteristic values (VDI 2143 Blatt 1, "Kennwerte"; Norton, Cam Design
/// and Manufacturing Handbook, Table 3-2): the maxima of |N'|, |N''|, |N'''| over u ∈ [0, 1], in closed
/// form where one exists. cj is +∞ where the acceleration jumps (inside the law or against a
/// dwell at its ends).
struct LawCharacteristics {
  double cv = 0.0, ca = 0.0, cj = 0.0;
};

/// The characteristic values of a normalised rest-in-rest law; nothing for a dwell, a polynomial
/// through boundary values or a B-spline (their shape is the segment's).
std::optional<LawCharacteristics> Characteristics(MotionLaw law);

/// Displacement and its first three derivatives.
template <typename T>
struct Svaj {
  T s, v, a, j;
};

/// The study-file name of a law ("cycloidal", "modified_sine", "poly_345", ...).
std::string LawName(MotionLaw law);
/// The law named name, or nothing when the name is unknown.
std::optional<MotionLaw> LawFromName(const std::string& name);
/// Every law name, for error messages.
std::vector<std::string> LawNames();

/// The normalised law: s(0) = 0, s(1) = 1 (0 for a dwell), derivatives with respect to u.
/// kPolynomial has no normalised form (zeros here): MotionSegmentShape evaluates it.
/// @tparam T double or ceres::Jet. @param u normalised time, [0, 1].
/// Piecewise laws pick their piece on the value of u; pieces meet with continuous s, v, a
/// (C² for modified sine and modified trapezoid), so the derivative is right at the joints.
template <typename T>
CAMOPT_FLATTEN Svaj<T> NormalizedLaw(MotionLaw law, const T& u) {
  using std::cos;
  using std::sin;
  const T pi(kPi);
  switch (law) {
    case MotionLaw::kDwell:
    case MotionLaw::kPolynomial:  // its shape is the segment's (MotionSegmentShape)
    case MotionLaw::kBSpline:
      return {T(0.0), T(0.0), T(0.0), T(0.0)};
    case MotionLaw::kCycloidal: {
      // s = u − sin(2πu)/(2π): Cv = 2, Ca = 2π, Cj = 4π².
      const T w = T(2.0) * pi;
      return {u - sin(w * u) / w, T(1.0) - cos(w * u), w * sin(w * u), w * w * cos(w * u)};
    }
    case MotionLaw::kSimpleHarmonic: {
      // s = (1 − cos πu)/2: Cv = π/2, Ca = π²/2; acceleration jumps at both ends.
      return {(T(1.0) - cos(pi * u)) / T(2.0), pi / T(2.0) * sin(pi * u),
              pi * pi / T(2.0) * cos(pi * u), -pi * pi * pi / T(2.0) * sin(pi * u)};
    }
    case MotionLaw::kModifiedSine: {
      // Sine acceleration of period 1/2 on the first and last eighth, of period 3/2 between;
      // k = 1/(4 + π), Ca = 4π²k ≈ 5.528.
      const T k = T(1.0) / (T(4.0) + pi);
      const double uv = Value(u);
      if (uv <= 0.125 || uv >= 0.875) {
        const T w = T(4.0) * pi;
        const T c = IfThenElse(Compare::kLessEqual, uv, 0.125, T(0.0), T(4.0));  // 4k: the middle piece's rise
        return {k * (c + pi * u - sin(w * u) / T(4.0)), k * pi * (T(1.0) - cos(w * u)),
                k * T(4.0) * pi * pi * sin(w * u), k * T(16.0) * pi * pi * pi * cos(w * u)};
      }
      const T w = T(4.0) * pi / T(3.0);
      const T arg = pi / T(3.0) + w * u;
      return {k * (T(2.0) + pi * u - T(2.25) * sin(arg)), k * pi * (T(1.0) - T(3.0) * cos(arg)),
              k * T(4.0) * pi * pi * sin(arg), k * T(4.0) * pi * pi * w * cos(arg)};
    }
    case MotionLaw::kModifiedTrapezoid: {
      // Acceleration: sine ramps over eighths, constant plateaus over quarters;
      // k = 1/(2 + π), Ca = 8πk ≈ 4.888.
      const T k = T(1.0) / (T(2.0) + pi);
      const T w = T(4.0) * pi;
      const double uv = Value(u);
      if (uv <= 0.125) {
        return {k * (T(2.0) * u - sin(w * u) / (T(2.0) * pi)), T(2.0) * k * (T(1.0) - cos(w * u)),
                T(8.0) * pi * k * sin(w * u), T(32.0) * pi * pi * k * cos(w * u)};
      }
      if (uv <= 0.375) {
        return {k * (T(4.0) * pi * u * u + (T(2.0) - pi) * u + (pi * pi - T(8.0)) / (T(16.0) * pi)),
                k * (T(8.0) * pi * u + T(2.0) - pi), T(8.0) * pi * k, T(0.0)};
      }
      if (uv <= 0.625) {
        return {k * (T(2.0) * u + T(2.0) * pi * u + sin(w * u) / (T(2.0) * pi) - pi / T(2.0)),
                k * (T(2.0) + T(2.0) * pi + T(2.0) * cos(w * u)), -T(8.0) * pi * k * sin(w * u),
                -T(32.0) * pi * pi * k * cos(w * u)};
      }
      if (uv <= 0.875) {
        return {k * (-T(4.0) * pi * u * u + (T(2.0) + T(7.0) * pi) * u +
                     (T(8.0) - T(33.0) * pi * pi) / (T(16.0) * pi)),
                k * (-T(8.0) * pi * u + T(2.0) + T(7.0) * pi), -T(8.0) * pi * k, T(0.0)};
      }
      return {k * (T(2.0) * u - sin(w * u) / (T(2.0) * pi) + pi), T(2.0) * k * (T(1.0) - cos(w * u)),
              T(8.0) * pi * k * sin(w * u), T(32.0) * pi * pi * k * cos(w * u)};
    }
    case MotionLaw::kPolynomial345: {
      // s = 10u³ − 15u⁴ + 6u⁵.
      const T u2 = u * u, u3 = u2 * u;
      return {u3 * (T(10.0) - T(15.0) * u + T(6.0) * u2), T(30.0) * u2 * (T(1.0) - u) * (T(1.0) - u),
              T(60.0) * u * (T(1.0) - T(3.0) * u + T(2.0) * u2),
              T(60.0) * (T(1.0) - T(6.0) * u + T(6.0) * u2)};
    }
    case MotionLaw::kPolynomial4567: {
      // s = 35u⁴ − 84u⁵ + 70u⁶ − 20u⁷.
      const T u2 = u * u, u3 = u2 * u, u4 = u3 * u;
      return {u4 * (T(35.0) - T(84.0) * u + T(70.0) * u2 - T(20.0) * u3),
              u3 * (T(140.0) - T(420.0) * u + T(420.0) * u2 - T(140.0) * u3),
              u2 * (T(420.0) - T(1680.0) * u + T(2100.0) * u2 - T(840.0) * u3),
              u * (T(840.0) - T(5040.0) * u + T(8400.0) * u2 - T(4200.0) * u3)};
    }
    case MotionLaw::kQuadraticParabola: {
      // s = 2u² for u <= 1/2, 1 − 2(1 − u)² after: Cv = 2, Ca = 4; the jerk is 0 between the
      // acceleration jumps at u = 0, 1/2 and 1 (infinite there).
      if (Value(u) <= 0.5) return {T(2.0) * u * u, T(4.0) * u, T(4.0), T(0.0)};
      const T w = T(1.0) - u;
      return {T(1.0) - T(2.0) * w * w, T(4.0) * w, T(-4.0), T(0.0)};
    }
  }
  return {T(0.0), T(0.0), T(0.0), T(0.0)};
}

}  // namespace camopt::motion
