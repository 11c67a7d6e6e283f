// What a binding limit costs, by re-solving: the sized objective at the study's limit moved by ±h,
// each re-solve verified as the answer was. On a piecewise-smooth sizing (a peak over crank angles
// changing its angle, a row becoming active) the KKT multiplier is the one-sided derivative of the
// active piece only; the re-solve slope is what moving the limit does (design-notes §2).
#pragma once

#include <cmath>
#include <limits>
#include <string>

namespace camopt::sizing {

struct LimitSlope {
  double step = 0;  ///< h, in the limit's unit
  /// (f(L) − f(L − h))/h and (f(L + h) − f(L))/h; NaN where that side found no verified design
  double left = std::numeric_limits<double>::quiet_NaN(), right = std::numeric_limits<double>::quiet_NaN();
  /// Central (f(L + h) − f(L − h))/2h where both sides solved, else the side that did; NaN if none.
  double slope = std::numeric_limits<double>::quiet_NaN();
  std::string sides;  ///< "central", "left", "right", or "" when neither side solved
  /// The two sides' slopes differ by more than their errors (the objective's solver tolerance over
  /// h each) plus 10% of the larger (the curvature of a smooth problem over ±h changes a slope by
  /// f''·h, a few percent at h = 1% of the limit): the cost is not one number there.
  bool kink = false;
  /// One side was re-solved and its slope confirmed the KKT multiplier's cost
  /// (ReSolveConfirmsMultiplier), so the other side was not solved.
  bool confirms_multiplier = false;
};

/// Which way raising a limit moves a minimised objective: a lower limit (≥ L) tightens, so the
/// optimum can only rise; an upper limit (≤ L) loosens, so it can only fall.
enum class LimitSense { kUnknown, kLower, kUpper };

/// The slope from the verified objectives at L − h, L and L + h (NaN: no verified design there);
/// `objective_tolerance` is the objective's absolute uncertainty from the solver's tolerances.
/// With the limit's sense known, a side whose slope has the sign no optimum can have (a tightened
/// limit that lowered the minimum) beyond its error is a kink too: the three solves ended on
/// different local optima (a corner of piecewise rows), so their differences are no derivative.
inline LimitSlope SlopeFromReSolves(double f_minus, double f0, double f_plus, double h, double objective_tolerance,
                                    LimitSense sense = LimitSense::kUnknown) {
  LimitSlope s;
  s.step = h;
  if (!(h > 0) || !std::isfinite(f0)) return s;
  if (std::isfinite(f_minus)) s.left = (f0 - f_minus) / h;
  if (std::isfinite(f_plus)) s.right = (f_plus - f0) / h;
  if (std::isfinite(s.left) && std::isfinite(s.right)) {
    s.slope = (f_plus - f_minus) / (2 * h);
    s.sides = "central";
    const double error = 2 * objective_tolerance / h;  // each side's
    s.kink = std::abs(s.right - s.left) > 2 * error + 0.1 * std::max(std::abs(s.left), std::abs(s.right));
    if (sense != LimitSense::kUnknown) {
      const double sign = sense == LimitSense::kLower ? 1.0 : -1.0;
      s.kink = s.kink || sign * s.left < -error || sign * s.right < -error;
    }
  } else if (std::isfinite(s.left)) {
    s.slope = s.left;
    s.sides = "left";
  } else if (std::isfinite(s.right)) {
    s.slope = s.right;
    s.sides = "right";
  }
  return s;
}

/// Whether a one-sided re-solve slope confirms the cost the KKT multiplier gives: the two agree
/// within the side's error (2 · objective_tolerance / h) plus 10% of the larger -- the test the two
/// sides of a central slope are held to -- and, with the limit's sense known, the side has a sign
/// an optimum can have. The multiplier is the derivative of the piece the answer's active set
/// holds; a verified re-solve on one side that agrees with it shows that piece is what moving the
/// limit does there. The other side can still hold a kink that only its own re-solve would show.
inline bool ReSolveConfirmsMultiplier(double one_sided, double multiplier, double h, double objective_tolerance,
                                      LimitSense sense = LimitSense::kUnknown) {
  if (!std::isfinite(one_sided) || !std::isfinite(multiplier) || !(h > 0)) return false;
  const double error = 2 * objective_tolerance / h;
  if (sense != LimitSense::kUnknown && (sense == LimitSense::kLower ? 1.0 : -1.0) * one_sided < -error) return false;
  return std::abs(one_sided - multiplier) <= 2 * error + 0.1 * std::max(std::abs(one_sided), std::abs(multiplier));
}

}  // namespace camopt::sizing
