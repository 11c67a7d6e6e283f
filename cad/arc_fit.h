// Bi-arc fitting of a smooth planar curve to a stated tolerance, for the geometry files (DXF arcs,
// STEP arc edges). Geometry for output only, over double: it lives in cad/ rather than model/
// (model/ holds the physics, templated over the AD scalar) and is shared by the DXF and STEP
// writers and by every cam kind.
//
// The curve is given as a function of its parameter (the model's exact profile, e.g.
// lcr::OffsetPoint or cycloid::ToothProfile), not as sampled points: the fit is checked against
// the function evaluated between the fitted end points, so the deviation it reports is the
// distance from the exact curve, not from a polyline through samples.
//
// Bi-arc (two tangent-continuous arcs between two points with given tangents), equal-tangent-length
// choice d₁ = d₂ = d: with v = P₁ − P₀, t = T₀ + T₁,
//     d = (−v·t + sqrt((v·t)² + 2(1 − T₀·T₁) v·v)) / (2(1 − T₀·T₁)),
// joint J = (P₀ + d T₀ + P₁ − d T₁)/2. The interval is halved until every check point of the
// exact curve lies within the tolerance of the two arcs.
#pragma once

#include <functional>
#include <vector>

#include "model/common/geometry.h"
#include "model/common/scalar.h"

namespace camopt::cad {

/// One arc from start to end; bulge = tan(sweep/4), > 0 counter-clockwise, 0 a straight segment
/// (the DXF LWPOLYLINE convention).
struct ArcSegment {
  Vec2<double> start, end;
  double bulge = 0.0;
};

/// Centre, radius and start angle / signed sweep of an arc with a non-zero bulge.
struct ArcGeometry {
  Vec2<double> centre;
  double radius = 0.0;
  double start_angle = 0.0;  ///< [rad]
  double sweep = 0.0;        ///< signed [rad], > 0 counter-clockwise
};
ArcGeometry ArcGeometryOf(const ArcSegment& a);

/// Point at fraction s ∈ [0, 1] of the arc (by angle; by length for a straight segment).
Vec2<double> PointOnArc(const ArcSegment& a, double s);
/// The same with g = ArcGeometryOf(a) given (many points of one arc).
Vec2<double> PointOnArc(const ArcSegment& a, const ArcGeometry& g, double s);

/// Unit tangent at fraction s ∈ [0, 1] in the direction start → end.
Vec2<double> TangentOnArc(const ArcSegment& a, double s);

/// Distance from p to the arc (to its nearer end point outside the arc's sweep).
double DistanceToArc(const ArcSegment& a, const Vec2<double>& p);

/// Signed area enclosed by a closed chain of arcs [mm²] (> 0 counter-clockwise): the polygon of
/// the end points plus each arc's circular segment.
double EnclosedArea(const std::vector<ArcSegment>& chain);

/// Whether the chords of a closed chain cross each other (an undercut profile loops over itself;
/// such a profile bounds no solid). A sweep over x: about O(n log n) for a profile.
bool ChainCrossesItself(const std::vector<ArcSegment>& chain);

using CurveFunction = std::function<Vec2<double>(double)>;

struct FitOptions {
  double tolerance_mm = 1e-3;     ///< largest allowed distance from the exact curve
  int initial_segments = 64;      ///< uniform parameter intervals to start from
  int check_points = 32;          ///< exact-curve points checked inside each fitted interval
  int max_depth = 24;             ///< halvings of one interval at most
  int max_arcs = 20000;           ///< no more halving once the chain would pass this many arcs
  /// The kept pieces whose largest check-point deviation is at least this share of the largest
  /// of all have it refined to the local maximum of the distance (golden-section search between
  /// the check points either side of it); 0: none. The deviation between check points exceeds
  /// the one at them by up to a few 0.1 %.
  double refine_share = 0.0;
  int refine_points = 12;         ///< exact-curve points of each refinement
};

/// A fitted chain of arcs and how far it is from the exact curve.
struct FittedCurve {
  std::vector<ArcSegment> arcs;
  double max_deviation_mm = 0.0;  ///< largest distance of a checked (or refined) exact point from the arcs
  long checked_points = 0;        ///< exact-curve points the deviation was measured on
  bool within_tolerance = true;   ///< false where max_depth or max_arcs stopped the halving
  /// FitBiarcsSymmetric: the number of turned copies of one fitted period that make the chain (1:
  /// the whole curve fitted), and the largest mismatch of the curve's symmetry found at its check
  /// points [mm] (included in max_deviation_mm).
  int symmetry = 1;
  double symmetry_error_mm = 0.0;
};

/// Fits bi-arcs to curve(t), t ∈ [t0, t1]; a closed curve (curve(t1) = curve(t0)) gives a closed
/// chain whose last end point is exactly its first start point. Tangents by central differences
/// of the curve function.
FittedCurve FitBiarcs(const CurveFunction& curve, double t0, double t1, const FitOptions& options);

/// Fits a closed curve with S-fold rotational symmetry about `centre` (S = `symmetry`): advancing
/// the parameter by T = (t1 − t0)/S turns the curve by ±2π/S about it. One period [t0, t0 + T] is
/// fitted (FitBiarcs, options.initial_segments over the whole curve, divided among the periods)
/// and the chain closed with S − 1 turned copies of its arcs, each period's last end point the
/// next period's first start point. The symmetry is checked before: at 16 points of each other
/// period against the first period's points turned; the largest mismatch is added to the reported
/// deviation, and where it exceeds 1e-3 of the tolerance (or S < 2, or the turn is not ±2π/S) the
/// whole curve is fitted instead (symmetry = 1 in the result). An LCR cam's profile, pitch curve
/// and cutter path with rollers = lobes + 1 are `lobes`-fold symmetric (lcr/profile.h).
FittedCurve FitBiarcsSymmetric(const CurveFunction& curve, double t0, double t1, int symmetry,
                               const Vec2<double>& centre, const FitOptions& options);

/// Largest distance from the exact curve, evaluated at `samples` uniform parameter values over
/// [t0, t1], to the nearest arc of the chain (an independent, brute-force check of a fit).
double MaxDistanceToChain(const CurveFunction& curve, double t0, double t1, int samples,
                          const std::vector<ArcSegment>& chain);

}  // namespace camopt::cad
