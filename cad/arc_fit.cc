#include "cad/arc_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace camopt::cad {

namespace {

constexpr double kStraightBulge = 1e-12;

struct Biarc {
  ArcSegment first, second;
  bool ok = false;
};

// Arc from a with start tangent ta to b.
ArcSegment ArcFromStartTangent(const Vec2<double>& a, const Vec2<double>& ta, const Vec2<double>& b) {
  const Vec2<double> c = b - a;
  const double alpha = std::atan2(Cross(ta, c), ta.dot(c));
  return {a, b, std::tan(alpha / 2)};
}

// Arc from a to b with end tangent tb.
ArcSegment ArcFromEndTangent(const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& tb) {
  const Vec2<double> c = b - a;
  const double alpha = std::atan2(Cross(c, tb), c.dot(tb));
  return {a, b, std::tan(alpha / 2)};
}

Biarc MakeBiarc(const Vec2<double>& p0, const Vec2<double>& t0, const Vec2<double>& p1,
                const Vec2<double>& t1) {
  Biarc b;
  const Vec2<double> v = p1 - p0;
  const double vv = v.dot(v);
  if (!(vv > 0)) return b;
  const double one_minus = 1.0 - t0.dot(t1);
  double d;
  if (one_minus < 1e-12) {
    const double vt = v.dot(t1);
    if (!(std::abs(vt) > 1e-12 * std::sqrt(vv))) return b;
    d = vv / (4 * vt);
  } else {
    const double vt = v.dot(t0 + t1);
    d = (-vt + std::sqrt(vt * vt + 2 * one_minus * vv)) / (2 * one_minus);
  }
  if (!(d > 0) || !std::isfinite(d)) return b;
  const Vec2<double> joint = 0.5 * (p0 + d * t0 + p1 - d * t1);
  b.first = ArcFromStartTangent(p0, t0, joint);
  b.second = ArcFromEndTangent(joint, p1, t1);
  // A bi-arc sweeping more than a half turn per arc is not a fit of a short curve piece.
  b.ok = std::abs(b.first.bulge) < 1.0 && std::abs(b.second.bulge) < 1.0;
  return b;
}

double DistanceToSegment(const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& p) {
  const Vec2<double> c = b - a;
  const double cc = c.dot(c);
  const double s = cc > 0 ? std::clamp((p - a).dot(c) / cc, 0.0, 1.0) : 0.0;
  return (a + s * c - p).norm();
}

}  // namespace

ArcGeometry ArcGeometryOf(const ArcSegment& a) {
  ArcGeometry g;
  const Vec2<double> c = a.end - a.start;
  const double len = c.norm();
  const double b = a.bulge;
  g.sweep = 4 * std::atan(b);
  g.radius = len * (1 + b * b) / (4 * std::abs(b));
  const double d = 0.5 * len * (1 - b * b) / (2 * b);  // signed distance of the centre, left of the chord
  g.centre = 0.5 * (a.start + a.end) + Perp(Vec2<double>(c / len)) * d;
  const Vec2<double> r0 = a.start - g.centre;
  g.start_angle = std::atan2(r0.y(), r0.x());
  return g;
}

Vec2<double> PointOnArc(const ArcSegment& a, double s) {
  if (std::abs(a.bulge) < kStraightBulge) return a.start + s * (a.end - a.start);
  const ArcGeometry g = ArcGeometryOf(a);
  if (s <= 0) return a.start;
  if (s >= 1) return a.end;
  return g.centre + g.radius * U(g.start_angle + s * g.sweep);
}

Vec2<double> TangentOnArc(const ArcSegment& a, double s) {
  if (std::abs(a.bulge) < kStraightBulge) return (a.end - a.start).normalized();
  const ArcGeometry g = ArcGeometryOf(a);
  const Vec2<double> t = Perp(U(g.start_angle + s * g.sweep));
  return g.sweep > 0 ? t : Vec2<double>(-t);
}

namespace {

// An arc prepared for many distance queries: its circle, and the side of its chord its midpoint is
// on. The arc is the part of its circle on that side of the chord line (for any sweep in (0, 2π)),
// so a point's radial projection onto the circle lies on the arc exactly when it is on that side:
// no angle is computed per query.
struct ArcProbe {
  Vec2<double> start, end, centre, chord;
  double radius = 0.0, mid_side = 0.0;
  bool straight = true;
  // Every point of the arc lies within `reach` of the chord's midpoint: half the chord (a minor
  // arc's farthest points are its ends) or the sagitta |bulge| c/2 (a major arc's is its midpoint).
  Vec2<double> chord_mid;
  double reach = 0.0;
};

ArcProbe ProbeOf(const ArcSegment& a) {
  ArcProbe pr;
  pr.start = a.start;
  pr.end = a.end;
  pr.chord = a.end - a.start;
  pr.straight = std::abs(a.bulge) < kStraightBulge;
  pr.chord_mid = 0.5 * (a.start + a.end);
  pr.reach = 0.5 * pr.chord.norm() * std::max(1.0, std::abs(a.bulge)) * (1 + 1e-12);
  if (pr.straight) return pr;
  const ArcGeometry g = ArcGeometryOf(a);
  pr.centre = g.centre;
  pr.radius = g.radius;
  pr.mid_side = Cross(pr.chord, Vec2<double>(PointOnArc(a, 0.5) - a.start));
  return pr;
}

double Distance(const ArcProbe& a, const Vec2<double>& p) {
  if (a.straight) return DistanceToSegment(a.start, a.end, p);
  const Vec2<double> r = p - a.centre;
  const double rn = r.norm();
  if (!(rn > 0)) return a.radius;  // the centre: every point of the arc is one radius away
  const Vec2<double> q = a.centre + r * (a.radius / rn);
  const double side = Cross(a.chord, Vec2<double>(q - a.start));
  if (side == 0.0 || (side > 0) == (a.mid_side > 0)) return std::abs(rn - a.radius);
  return std::min((p - a.start).norm(), (p - a.end).norm());
}

}  // namespace

double DistanceToArc(const ArcSegment& a, const Vec2<double>& p) { return Distance(ProbeOf(a), p); }

double EnclosedArea(const std::vector<ArcSegment>& chain) {
  double area = 0.0;
  for (const ArcSegment& a : chain) {
    area += 0.5 * Cross(a.start, a.end);
    if (std::abs(a.bulge) < kStraightBulge) continue;
    const ArcGeometry g = ArcGeometryOf(a);
    // Circular segment between chord and arc, signed with the sweep.
    const double th = g.sweep;
    area += 0.5 * g.radius * g.radius * (th - std::sin(th));
  }
  return area;
}

bool ChainCrossesItself(const std::vector<ArcSegment>& chain) {
  const size_t n = chain.size();
  auto orient = [](const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c) {
    return Cross(Vec2<double>(b - a), Vec2<double>(c - a));
  };
  for (size_t i = 0; i < n; ++i)
    for (size_t k = i + 2; k < n; ++k) {
      if (i == 0 && k == n - 1) continue;  // neighbours through the closing point
      const ArcSegment &a = chain[i], &b = chain[k];
      const double d1 = orient(a.start, a.end, b.start), d2 = orient(a.start, a.end, b.end);
      const double d3 = orient(b.start, b.end, a.start), d4 = orient(b.start, b.end, a.end);
      if (((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0)
        return true;
    }
  return false;
}

FittedCurve FitBiarcs(const CurveFunction& curve, double t0, double t1, const FitOptions& o) {
  FittedCurve fit;
  const double span = t1 - t0;
  const double h = 1e-6 * std::max(1.0, std::abs(span));
  auto tangent = [&](double t) {
    const Vec2<double> d = curve(t + h) - curve(t - h);
    return Vec2<double>(d / d.norm());
  };
  struct Piece {
    double ta, tb;
    int depth;
  };
  std::vector<Piece> stack;
  const int n0 = std::max(2, o.initial_segments);
  for (int i = n0 - 1; i >= 0; --i) stack.push_back({t0 + span * i / n0, t0 + span * (i + 1) / n0, 0});
  const Vec2<double> first_point = curve(t0);
  const Vec2<double> last_point = curve(t1);
  const bool closed = (first_point - last_point).norm() < 1e-9 * std::max(1.0, first_point.norm());
  while (!stack.empty()) {
    const Piece p = stack.back();
    stack.pop_back();
    const Vec2<double> pa = curve(p.ta), pb = p.tb == t1 && closed ? first_point : curve(p.tb);
    const Biarc b = MakeBiarc(pa, tangent(p.ta), pb, tangent(p.tb));
    double worst = std::numeric_limits<double>::infinity();
    if (b.ok) {
      worst = 0.0;
      const ArcProbe first = ProbeOf(b.first), second = ProbeOf(b.second);
      for (int k = 1; k < o.check_points; ++k) {
        const Vec2<double> q = curve(p.ta + (p.tb - p.ta) * k / o.check_points);
        worst = std::max(worst, std::min(Distance(first, q), Distance(second, q)));
      }
    }
    const size_t planned = fit.arcs.size() + 2 * (stack.size() + 1);
    if (!(worst <= o.tolerance_mm) && p.depth < o.max_depth && planned + 2 <= size_t(o.max_arcs)) {
      const double tm = 0.5 * (p.ta + p.tb);
      stack.push_back({tm, p.tb, p.depth + 1});
      stack.push_back({p.ta, tm, p.depth + 1});
      continue;
    }
    if (!b.ok) {  // degenerate at the depth limit: a straight segment
      fit.arcs.push_back({pa, pb, 0.0});
      double w = 0.0;
      for (int k = 1; k < o.check_points; ++k)
        w = std::max(w, DistanceToSegment(pa, pb, curve(p.ta + (p.tb - p.ta) * k / o.check_points)));
      worst = w;
    } else {
      fit.arcs.push_back(b.first);
      fit.arcs.push_back(b.second);
    }
    fit.checked_points += o.check_points - 1;
    if (!(worst <= fit.max_deviation_mm)) fit.max_deviation_mm = worst;  // NaN and ∞ stay visible
    if (!(worst <= o.tolerance_mm)) fit.within_tolerance = false;
  }
  return fit;
}

double MaxDistanceToChain(const CurveFunction& curve, double t0, double t1, int samples,
                          const std::vector<ArcSegment>& chain) {
  // Chain arcs are in parameter order: search a window around the last nearest arc, then
  // everything when the window's best is not small (robust for any chain, fast for fitted ones).
  double worst = 0.0;
  size_t hint = 0;
  const size_t n = chain.size();
  std::vector<ArcProbe> probes;
  probes.reserve(n);
  for (const ArcSegment& a : chain) probes.push_back(ProbeOf(a));
  for (int i = 0; i <= samples; ++i) {
    const Vec2<double> q = curve(t0 + (t1 - t0) * i / samples);
    double best = std::numeric_limits<double>::infinity();
    size_t best_k = hint;
    for (size_t w = 0; w < std::min<size_t>(n, 32); ++w) {
      const size_t k = (hint + n - 8 + w) % n;
      // An arc whose every point is farther than the best so far cannot be nearer: skipped
      // (same order, so the same nearest arc as computing every distance).
      const double far = best + probes[k].reach;
      if (std::isfinite(best) && (q - probes[k].chord_mid).squaredNorm() > far * far * (1 + 1e-12)) continue;
      const double dist = Distance(probes[k], q);
      if (dist < best) best = dist, best_k = k;
    }
    if (best > 1e-2 && n <= 4096) {  // far from the window: every arc (bounded work)
      for (size_t k = 0; k < n; ++k) {
        const double dist = Distance(probes[k], q);
        if (dist < best) best = dist, best_k = k;
      }
    }
    hint = best_k;
    if (!(best <= worst)) worst = best;
  }
  return worst;
}

}  // namespace camopt::cad
