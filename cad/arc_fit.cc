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
  return PointOnArc(a, ArcGeometryOf(a), s);
}

Vec2<double> PointOnArc(const ArcSegment& a, const ArcGeometry& g, double s) {
  if (std::abs(a.bulge) < kStraightBulge) return a.start + s * (a.end - a.start);
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
  // The arc's midpoint is right of the chord for a counter-clockwise arc (bulge > 0), left for a
  // clockwise one; only the side is used. From the bulge's sign when the sagitta, |bulge| c/2, is
  // far above the rounding of the midpoint computed from the centre (about 1e-16 c/|bulge|).
  pr.mid_side = std::abs(a.bulge) > 1e-5 ? -a.bulge : Cross(pr.chord, Vec2<double>(PointOnArc(a, 0.5) - a.start));
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
  auto cross = [&](size_t i, size_t k) {
    const ArcSegment &a = chain[i], &b = chain[k];
    const double d1 = orient(a.start, a.end, b.start), d2 = orient(a.start, a.end, b.end);
    const double d3 = orient(b.start, b.end, a.start), d4 = orient(b.start, b.end, a.end);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
  };
  // Two chords cross (each pair's end points strictly on either side of the other's line) only at a
  // point inside both x-ranges: a sweep over x compares each chord with the chords whose x-range
  // reaches its left end, not with all (a profile's vertical lines meet a few chords each).
  std::vector<size_t> by_left(n);
  std::vector<double> left(n), right(n);
  for (size_t i = 0; i < n; ++i) {
    by_left[i] = i;
    left[i] = std::min(chain[i].start.x(), chain[i].end.x());
    right[i] = std::max(chain[i].start.x(), chain[i].end.x());
  }
  std::sort(by_left.begin(), by_left.end(), [&](size_t a, size_t b) { return left[a] < left[b]; });
  std::vector<size_t> open;  // chords whose x-range may still reach the next left end
  for (const size_t k : by_left) {
    std::erase_if(open, [&](size_t i) { return right[i] < left[k]; });
    for (const size_t i : open) {
      const size_t lo = std::min(i, k), hi = std::max(i, k);
      if (hi - lo < 2 || (lo == 0 && hi == n - 1)) continue;  // neighbours, also through the closing point
      if (cross(lo, hi)) return true;
    }
    open.push_back(k);
  }
  return false;
}

FittedCurve FitBiarcs(const CurveFunction& curve, double t0, double t1, const FitOptions& o) {
  FittedCurve fit;
  const double span = t1 - t0;
  const double h = 1e-6 * std::max(1.0, std::abs(span));
  // A piece's end: its parameter, the curve point and unit tangent there. Each end is evaluated
  // once and shared by the two pieces that meet at it (and by a piece and its halves); the values
  // are those of evaluating at the same parameter again.
  struct End {
    double t;
    Vec2<double> point, tangent;
  };
  const Vec2<double> first_point = curve(t0);
  const Vec2<double> last_point = curve(t1);
  const bool closed = (first_point - last_point).norm() < 1e-9 * std::max(1.0, first_point.norm());
  auto end_at = [&](double t) {
    const Vec2<double> d = curve(t + h) - curve(t - h);
    return End{t, curve(t), Vec2<double>(d / d.norm())};
  };
  struct Piece {
    End a, b;
    int depth;
  };
  std::vector<Piece> stack;
  const int n0 = std::max(2, o.initial_segments);
  {
    std::vector<End> ends(n0 + 1);
    for (int i = 0; i <= n0; ++i) ends[i] = end_at(t0 + span * i / n0);
    for (int i = n0 - 1; i >= 0; --i) stack.push_back({ends[i], ends[i + 1], 0});
  }
  // Check points in bit-reversed order (the middle first, then the quarters, ...): a piece that
  // will be halved is given up at its first point outside the tolerance, which is usually found
  // among the first few; the largest deviation of a kept piece does not depend on the order.
  std::vector<int> order;
  order.reserve(o.check_points);
  for (int step = o.check_points; step >= 1; step /= 2)
    for (int k = step; k < o.check_points; k += step)
      if (std::find(order.begin(), order.end(), k) == order.end()) order.push_back(k);
  for (int k = 1; k < o.check_points; ++k)
    if (std::find(order.begin(), order.end(), k) == order.end()) order.push_back(k);
  // The kept bi-arcs: parameter interval, largest check-point deviation and where, first arc.
  struct Kept {
    double ta, tb, worst;
    int worst_k;
    size_t arc;
  };
  std::vector<Kept> kept;
  while (!stack.empty()) {
    const Piece p = stack.back();
    stack.pop_back();
    const double ta = p.a.t, tb = p.b.t;
    // A closed curve's last end is its first point (the chain closes exactly).
    const Vec2<double>&pa = p.a.point, &pb = tb == t1 && closed ? first_point : p.b.point;
    const Biarc b = MakeBiarc(pa, p.a.tangent, pb, p.b.tangent);
    const size_t planned = fit.arcs.size() + 2 * (stack.size() + 1);
    const bool can_halve = p.depth < o.max_depth && planned + 2 <= size_t(o.max_arcs);
    double worst = std::numeric_limits<double>::infinity();
    int worst_k = 0;  // the check point of the largest deviation
    if (b.ok) {
      worst = 0.0;
      const ArcProbe first = ProbeOf(b.first), second = ProbeOf(b.second);
      for (const int k : order) {
        const Vec2<double> q = curve(ta + (tb - ta) * k / o.check_points);
        // The distance to the nearer arc; the other arc's is not computed when every point of it
        // is farther than the one found (then it is not the smaller: the same minimum).
        const bool first_half = 2 * k < o.check_points;
        const ArcProbe &near = first_half ? first : second, &other = first_half ? second : first;
        const double d_near = Distance(near, q);
        const double far = d_near + other.reach;
        const bool other_farther =
            std::isfinite(d_near) && (q - other.chord_mid).squaredNorm() > far * far * (1 + 1e-9);
        const double d = other_farther ? d_near : std::min(Distance(first, q), Distance(second, q));
        if (d > worst) worst = d, worst_k = k;
        if (can_halve && !(worst <= o.tolerance_mm)) break;  // halved whatever the other points give
      }
    }
    if (!(worst <= o.tolerance_mm) && can_halve) {
      const End m = end_at(0.5 * (ta + tb));
      stack.push_back({m, p.b, p.depth + 1});
      stack.push_back({p.a, m, p.depth + 1});
      continue;
    }
    if (!b.ok) {  // degenerate at the depth limit: a straight segment
      fit.arcs.push_back({pa, pb, 0.0});
      double w = 0.0;
      for (int k = 1; k < o.check_points; ++k)
        w = std::max(w, DistanceToSegment(pa, pb, curve(ta + (tb - ta) * k / o.check_points)));
      worst = w;
    } else {
      kept.push_back({ta, tb, worst, worst_k, fit.arcs.size()});
      fit.arcs.push_back(b.first);
      fit.arcs.push_back(b.second);
    }
    fit.checked_points += o.check_points - 1;
    if (!(worst <= fit.max_deviation_mm)) fit.max_deviation_mm = worst;  // NaN and ∞ stay visible
    if (!(worst <= o.tolerance_mm)) fit.within_tolerance = false;
  }
  if (o.refine_share > 0 && std::isfinite(fit.max_deviation_mm)) {
    // Golden-section search (Kiefer 1953) for the largest distance between the check points either
    // side of a piece's largest one (the distance is smooth and has one maximum there); every
    // point's distance counts, the search only chooses where to look.
    const double largest = fit.max_deviation_mm;
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    for (const Kept& piece : kept) {
      if (!(piece.worst > 0 && piece.worst >= o.refine_share * largest)) continue;
      const ArcProbe first = ProbeOf(fit.arcs[piece.arc]), second = ProbeOf(fit.arcs[piece.arc + 1]);
      auto distance = [&](double s) {
        const Vec2<double> q = curve(piece.ta + (piece.tb - piece.ta) * s);
        return std::min(Distance(first, q), Distance(second, q));
      };
      double lo = double(piece.worst_k - 1) / o.check_points, hi = double(piece.worst_k + 1) / o.check_points;
      double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
      double f1 = distance(x1), f2 = distance(x2), found = std::max(f1, f2);
      for (int i = 2; i < o.refine_points; ++i) {
        if (f1 >= f2) {
          hi = x2, x2 = x1, f2 = f1;
          x1 = hi - g * (hi - lo), f1 = distance(x1);
        } else {
          lo = x1, x1 = x2, f1 = f2;
          x2 = lo + g * (hi - lo), f2 = distance(x2);
        }
        found = std::max(found, std::max(f1, f2));
      }
      fit.checked_points += o.refine_points;
      if (!(found <= fit.max_deviation_mm)) fit.max_deviation_mm = found;
    }
  }
  return fit;
}

FittedCurve FitBiarcsSymmetric(const CurveFunction& curve, double t0, double t1, int symmetry,
                               const Vec2<double>& centre, const FitOptions& o) {
  const int s_order = symmetry;
  if (s_order < 2) return FitBiarcs(curve, t0, t1, o);
  const double period = (t1 - t0) / s_order;
  // The turn of one period, from the first point: ±2π/S (which sign is the curve's).
  const Vec2<double> a0 = curve(t0) - centre, a1 = curve(t0 + period) - centre;
  const double turn = std::atan2(Cross(a0, a1), a0.dot(a1));
  const double expected = 2 * kPi / s_order;
  if (!(std::abs(std::abs(turn) - expected) < 1e-6 * expected)) return FitBiarcs(curve, t0, t1, o);
  const double sign = turn > 0 ? 1.0 : -1.0;
  std::vector<Vec2<double>> rotation(s_order);  // (cos, sin) of the turn of period j
  for (int j = 0; j < s_order; ++j) {
    const double angle = sign * expected * j;
    rotation[j] = Vec2<double>(std::cos(angle), std::sin(angle));
  }
  auto turned = [&](const Vec2<double>& p, int j) {
    const Vec2<double> d = p - centre, r = rotation[size_t(j)];
    return Vec2<double>(centre.x() + r.x() * d.x() - r.y() * d.y(), centre.y() + r.y() * d.x() + r.x() * d.y());
  };
  // The symmetry checked at 16 points of every period (not at the period's ends, which the fit's
  // ends are checked by: a copy's end is the next copy's start).
  constexpr int kChecks = 16;
  double mismatch = 0.0;
  for (int k = 0; k < kChecks; ++k) {
    const double s = period * (k + 0.5) / kChecks;
    const Vec2<double> p = curve(t0 + s);
    for (int j = 1; j < s_order; ++j) {
      const double d = (curve(t0 + j * period + s) - turned(p, j)).norm();
      if (!(d <= mismatch)) mismatch = d;  // NaN stays visible
    }
  }
  if (!(mismatch <= 1e-3 * o.tolerance_mm)) return FitBiarcs(curve, t0, t1, o);
  FitOptions one = o;
  one.initial_segments = std::max(2, (o.initial_segments + s_order - 1) / s_order);
  one.max_arcs = std::max(2, o.max_arcs / s_order);
  FittedCurve fit = FitBiarcs(curve, t0, t0 + period, one);
  const std::vector<ArcSegment> lobe = std::move(fit.arcs);
  fit.arcs.clear();
  fit.arcs.reserve(lobe.size() * size_t(s_order));
  for (int j = 0; j < s_order; ++j)
    for (const ArcSegment& a : lobe) fit.arcs.push_back({turned(a.start, j), turned(a.end, j), a.bulge});
  // Connected to the bit: each period's last end point is the next period's first start point
  // (they differ by the rounding of the turns), the last period's the chain's first.
  for (int j = 1; j < s_order; ++j) fit.arcs[size_t(j) * lobe.size() - 1].end = fit.arcs[size_t(j) * lobe.size()].start;
  fit.arcs.back().end = fit.arcs.front().start;
  fit.symmetry = s_order;
  fit.symmetry_error_mm = mismatch;
  fit.checked_points += long(kChecks) * (s_order - 1);
  fit.max_deviation_mm += mismatch;
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
  // Blocks of 8 consecutive arcs, each in a disc: every point of arc j of block b lies within
  // |mid_j − c_b| + reach_j ≤ R_b of its centre c_b (the mean of the chord midpoints), so
  // dist(q, arc j) ≥ |q − c_b| − R_b. A block farther than the best so far (by a margin far above
  // the rounding of these distances) holds no arc the test of each arc would not skip, and is
  // skipped as a whole: the same arcs' distances are compared, the same nearest arc found.
  constexpr size_t kBlock = 8;
  const size_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<Vec2<double>> block_centre(blocks, Vec2<double>::Zero());
  std::vector<double> block_radius(blocks, 0.0);
  for (size_t b = 0; b < blocks; ++b) {
    const size_t lo = b * kBlock, hi = std::min(n, lo + kBlock);
    for (size_t k = lo; k < hi; ++k) block_centre[b] += probes[k].chord_mid;
    block_centre[b] /= double(hi - lo);
    for (size_t k = lo; k < hi; ++k)
      block_radius[b] = std::max(block_radius[b], (probes[k].chord_mid - block_centre[b]).norm() + probes[k].reach);
    block_radius[b] = block_radius[b] * (1 + 1e-9) + 1e-12 * block_centre[b].norm();
  }
  const size_t m = std::min<size_t>(n, 32);  // window: arcs hint − 8 ... hint + 23 (cyclic)
  for (int i = 0; i <= samples; ++i) {
    const Vec2<double> q = curve(t0 + (t1 - t0) * i / samples);
    double best = std::numeric_limits<double>::infinity();
    size_t best_k = hint, best_w = m;
    // An arc whose every point is farther than the best so far cannot be nearer: skipped. The
    // nearest arc is the one of least distance, the first in window order among equal ones,
    // whatever the order the window is searched in; the last nearest arc (window position 8) is
    // searched first, so that the others are mostly skipped.
    auto visit = [&](size_t w, size_t k) {
      const ArcProbe& pr = probes[k];
      if (std::isfinite(best)) {
        const double far = best + pr.reach;
        if ((q - pr.chord_mid).squaredNorm() > far * far * (1 + 1e-12)) return;
      }
      const double dist = Distance(pr, q);
      if (dist < best || (dist == best && w < best_w)) best = dist, best_k = k, best_w = w;
    };
    auto block_far = [&](size_t b) {
      if (!std::isfinite(best)) return false;
      const double far = best + block_radius[b];
      return (q - block_centre[b]).squaredNorm() > far * far * (1 + 1e-9);
    };
    if (n >= 8) {
      const size_t start = hint >= 8 ? hint - 8 : hint + n - 8;  // (hint + n − 8) mod n, hint < n
      const size_t first = m > 8 ? 8 : 0;
      visit(first, (start + first) % n);
      // The window block by block: the arcs k ... of block k / kBlock in it, unless it is far.
      for (size_t w = 0, k = start; w < m;) {
        const size_t block = k / kBlock;
        const size_t run = std::min(m - w, std::min(n, (block + 1) * kBlock) - k);
        if (!block_far(block))
          for (size_t j = 0; j < run; ++j)
            if (w + j != first) visit(w + j, k + j);
        w += run, k += run;
        if (k == n) k = 0;
      }
    } else {
      for (size_t w = 0; w < m; ++w) visit(w, (hint + n - 8 + w) % n);
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
