// Closed uniform cubic B-splines: the compact form of a long profile in the STEP files. A cam's
// exact profile is smooth, and a cubic B-spline with single (C²) knots interpolating it at uniform
// parameter steps h is within O(h⁴) of it, where a chain of arcs is within O(h³): at the same
// tolerance the spline has a fraction of the arcs' poles (a rational quadratic B-spline through
// the arcs takes two per arc). The STEP writer (cad/extrusion.cc) uses it for a profile of more
// arcs than one wall takes when it has fewer poles than the arcs; the DXF keeps the arcs (machine
// tools cut arcs).
//
// Convention: N poles P_0 … P_{N−1}, knots at the integers, periodic. Span i (parameter u in
// [i, i+1)) is
//     S(i + s) = [(1−s)³ P_{i−1} + (3s³ − 6s² + 4) P_i + (−3s³ + 3s² + 3s + 1) P_{i+1} + s³ P_{i+2}] / 6
// (indices mod N; Piegl & Tiller, The NURBS Book, 2nd ed., §2.2 and eq. 3.7 on uniform knots), so
// the point at knot i is (P_{i−1} + 4 P_i + P_{i+1}) / 6.
#pragma once

#include <optional>
#include <vector>

#include "cad/arc_fit.h"

namespace camopt::cad {

/// A closed uniform cubic B-spline and how far it is from the curve it was fitted to.
struct ClosedCubic {
  std::vector<Vec2<double>> poles;  ///< N poles, periodic uniform knots [mm]
  double max_deviation_mm = 0.0;    ///< largest |C(t) − S(t)| at the checked points
  long checked_points = 0;          ///< exact-curve points the deviation was measured on
};

/// S(u), u ∈ [0, N) (taken mod N).
Vec2<double> PointOnClosedCubic(const ClosedCubic& s, double u);

/// The closed cubic B-spline interpolating the closed curve C(t), t ∈ [t0, t1] (C(t1) = C(t0)), at
/// N points at uniform steps of its arc length (knot i at the arc length i L/N): P = A⁻¹ Q for the
/// circulant A = (1, 4, 1)/6, whose inverse has the entries √3 r^|k|, r = √3 − 2 (exact to rounding
/// with |k| ≤ 30). N is a multiple of `symmetry` (the curve's rotational symmetry, 1 if none), at
/// least `min_spans`, and raised (once by the h⁴ law of the error, then by steps of a period or
/// 2 %: the error is not monotone in N) until the largest
/// distance from the spline's points to the exact curve (the foot of the perpendicular found by
/// Gauss-Newton steps) at 16 points of every span is within `target_mm`. nullopt when more than
/// `max_poles` poles would be needed (a curve whose curvature jumps converges slowly) or a point is
/// not finite.
std::optional<ClosedCubic> FitClosedCubic(const CurveFunction& curve, double t0, double t1, int symmetry,
                                          int min_spans, double target_mm, int max_poles);

/// Spans [a, b) of a closed cubic (0 ≤ a < b ≤ a + N) as a clamped cubic B-spline over the knots
/// a (×4), a+1, …, b−1, b (×4): its b − a + 3 poles, the first S(a) and the last S(b) (Boehm's knot
/// insertion of a and b twice each; The NURBS Book §5.2). The same curve, for a STEP
/// B_SPLINE_CURVE_WITH_KNOTS.
std::vector<Vec2<double>> ClampedSpans(const ClosedCubic& s, int a, int b);

/// The spline turned by `angle_rad` about the origin (a B-spline is affine invariant: its poles turned).
ClosedCubic Rotated(const ClosedCubic& s, double angle_rad);

}  // namespace camopt::cad
