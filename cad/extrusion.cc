#include "cad/extrusion.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <stdexcept>
#include <string_view>

namespace camopt::cad {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The mesh's chord deviation grows with the part above this share of its size (see MeshDeflection).
constexpr double kMeshRelativeDeflection = 4e-6;
// Largest turn of one chord [rad] (the OCCT mesher's angular deflection the files had before).
constexpr double kMaxChordTurn = 0.1;

double Cross(const Vec2<double>& a, const Vec2<double>& b) { return a.x() * b.y() - a.y() * b.x(); }

// Chords of one arc (or line): its start point and the interior points (the end is the next arc's
// start). Each chord's sagitta is at most `deflection` and its turn at most kMaxChordTurn; seen
// from `centre` each spans at most kMaxChordTurn too, so that the end faces' triangles between the
// profile and the bore stay short (a square's side was one chord, and its fan to the bore crossed
// the bore).
void AppendChords(const ArcSegment& a, double deflection, const Vec2<double>& centre, std::vector<Vec2<double>>& points) {
  points.push_back(a.start);
  const Vec2<double> u = a.start - centre, v = a.end - centre;
  const double seen = std::abs(std::atan2(Cross(u, v), u.dot(v)));
  int n = static_cast<int>(std::ceil(seen / kMaxChordTurn - 1e-9));
  const bool arc = std::abs(a.bulge) >= 1e-12;
  const ArcGeometry g = arc ? ArcGeometryOf(a) : ArcGeometry{};
  if (arc) {
    const double ratio = std::min(1.0, deflection / g.radius);  // sagitta r(1 − cos(Δ/2)) <= deflection
    const double step = std::min(kMaxChordTurn, 2.0 * std::acos(1.0 - ratio));
    n = std::max(n, static_cast<int>(std::ceil(std::abs(g.sweep) / step - 1e-9)));
  }
  for (int k = 1; k < n; ++k) points.push_back(arc ? PointOnArc(a, g, double(k) / n) : PointOnArc(a, double(k) / n));
}

// The size of the part: the diagonal of its end points' bounding box.
double Diagonal(const std::vector<ArcSegment>& chain) {
  if (chain.empty()) return 0.0;
  Vec2<double> lo = chain.front().start, hi = lo;
  for (const ArcSegment& a : chain)
    for (const Vec2<double>& p : {a.start, a.end}) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).norm();
}

}  // namespace

std::vector<ArcSegment> BoreChain(const Extrusion& e) {
  if (!(e.bore_diameter_mm > 0)) return {};
  const double rb = 0.5 * e.bore_diameter_mm;
  const Vec2<double> c = e.bore_centre;
  if (!(e.keyway_width_mm > 0)) {
    const Vec2<double> a = c + Vec2<double>(rb, 0.0), b = c - Vec2<double>(rb, 0.0);
    return {{a, b, 1.0}, {b, a, 1.0}};
  }
  const Vec2<double> u(std::cos(e.keyway_angle_rad), std::sin(e.keyway_angle_rad)), v(-u.y(), u.x());
  const double hw = 0.5 * e.keyway_width_mm;
  const double x0 = std::sqrt(std::max(0.0, rb * rb - hw * hw)), xd = rb + e.keyway_depth_mm;
  const Vec2<double> A = c + x0 * u - hw * v, B = c + xd * u - hw * v, C = c + xd * u + hw * v, D = c + x0 * u + hw * v;
  // The bore's arc from D counter-clockwise round to A: a sweep of 2π − 2 asin(hw/rb).
  const double sweep = 2 * kPi - 2 * std::asin(hw / rb);
  return {{D, A, std::tan(sweep / 4)}, {A, B, 0.0}, {B, C, 0.0}, {C, D, 0.0}};
}

namespace {

void CheckChain(const Extrusion& e) {
  if (e.profile.size() < 2) throw std::invalid_argument("the profile needs at least two arcs");
  const double size = Diagonal(e.profile);
  for (size_t i = 0; i < e.profile.size(); ++i) {
    const ArcSegment& a = e.profile[i];
    const ArcSegment& b = e.profile[(i + 1) % e.profile.size()];
    if (!((a.end - b.start).norm() <= 1e-9 * std::max(1.0, size)))
      throw std::invalid_argument("the profile's arcs do not form a closed chain");
    if (!std::isfinite(a.bulge) || !a.start.allFinite()) throw std::invalid_argument("the profile is not finite");
  }
  if (!(e.thickness_mm > 0) || !std::isfinite(e.thickness_mm)) throw std::invalid_argument("the thickness must be > 0");
  if (e.keyway_width_mm > 0) {
    const double rb = 0.5 * e.bore_diameter_mm;
    if (!(rb > 0)) throw std::invalid_argument("a keyway needs a bore");
    if (!(e.keyway_width_mm < 2 * rb * 0.999) || !(e.keyway_depth_mm > 0) || !std::isfinite(e.keyway_depth_mm))
      throw std::invalid_argument("the keyway must be narrower than the bore and deeper than 0");
    // Its bottom corners inside the profile with room to spare.
    const std::vector<ArcSegment> bore = BoreChain(e);
    for (const Vec2<double>& corner : {bore[1].end, bore[2].end}) {
      double nearest = INFINITY;
      for (const ArcSegment& a : e.profile) nearest = std::min(nearest, DistanceToArc(a, corner));
      if (!(nearest > 1e-3 * rb) || !((corner - e.bore_centre).norm() < Diagonal(e.profile)))
        throw std::invalid_argument("the keyway reaches the profile");
    }
    for (const Hole& h : e.holes)
      for (size_t k = 1; k < 4; ++k)
        if (!(DistanceToArc(bore[k], h.centre) > 0.5 * h.diameter_mm))
          throw std::invalid_argument("a hole cuts the keyway");
  }
  // The bore and the holes: each inside the profile, clear of it and of each other.
  std::vector<Hole> circles;
  if (e.bore_diameter_mm > 0) circles.push_back({e.bore_centre, e.bore_diameter_mm});
  for (const Hole& h : e.holes) {
    if (!(h.diameter_mm > 0) || !std::isfinite(h.diameter_mm) || !h.centre.allFinite())
      throw std::invalid_argument("a hole's diameter must be finite and > 0");
    circles.push_back(h);
  }
  for (size_t k = 0; k < circles.size(); ++k) {
    const Vec2<double> c = circles[k].centre;
    const double rb = 0.5 * circles[k].diameter_mm;
    const char* what = k == 0 && e.bore_diameter_mm > 0 ? "the bore" : "a hole";
    double nearest = INFINITY;
    for (const ArcSegment& a : e.profile) nearest = std::min(nearest, DistanceToArc(a, c));
    // Inside: the winding number about the centre of a chord polygon within a quarter of the
    // centre's distance of the arcs (it cannot pass the centre, so it winds as the arcs do).
    std::vector<Vec2<double>> poly;
    if (nearest > rb * (1 + 1e-9) && std::isfinite(nearest))
      for (const ArcSegment& a : e.profile) AppendChords(a, 0.25 * nearest, c, poly);
    double turn = 0.0;  // left 0 (refused below) when the centre is not clear of the profile
    for (size_t i = 0; i < poly.size(); ++i) {
      const Vec2<double> u = poly[i] - c, v = poly[(i + 1) % poly.size()] - c;
      turn += std::atan2(Cross(u, v), u.dot(v));
    }
    if (!(nearest > rb * (1 + 1e-9)) || std::abs(turn - 2 * kPi) > 1e-6) {
      char buf[240];
      std::snprintf(buf, sizeof buf,
                    "%s (diameter %.6g mm at %.6g, %.6g) does not lie inside the profile (nearest profile point %.6g mm "
                    "from its centre)",
                    what, circles[k].diameter_mm, c.x(), c.y(), nearest);
      throw std::invalid_argument(buf);
    }
    for (size_t m = 0; m < k; ++m) {
      const double gap = (circles[m].centre - c).norm() - 0.5 * (circles[m].diameter_mm + circles[k].diameter_mm);
      if (!(gap > 1e-9 * std::max(1.0, size))) {
        char buf[240];
        std::snprintf(buf, sizeof buf, "%s (diameter %.6g mm at %.6g, %.6g) overlaps another hole or the bore (gap %.6g mm)",
                      what, circles[k].diameter_mm, c.x(), c.y(), gap);
        throw std::invalid_argument(buf);
      }
    }
  }
}

// ---- STEP (ISO 10303-21 exchange structure, AP214 entities) ---------------------------------

// A REAL of ISO 10303-21 §6.3.2: always with a decimal point and an upper-case exponent ("1.",
// "2.5", "1.E-07"); the shortest digits that read back as the same double (std::to_chars). Kept as
// text for the entities that repeat it (a vertex's x and y at both ends of the extrusion).
struct Real {
  explicit Real(double v) {
    if (!std::isfinite(v)) throw std::invalid_argument("a STEP coordinate is not finite");
    if (v == 0.0) {  // also −0
      c[0] = '0', c[1] = '.', n = 2;
      return;
    }
    const std::to_chars_result r = std::to_chars(c, c + sizeof c - 1, v);
    n = static_cast<int>(r.ptr - c);
    // The exponent, if any, is among the last 5 characters ("e-308"); a '.' only before it.
    int e = n;
    for (int i = n - 1; i >= std::max(0, n - 5); --i)
      if (c[i] == 'e') e = i;
    if (e < n) c[e] = 'E';
    if (!std::memchr(c, '.', e)) {  // "1e-07" → "1.E-07", "25" → "25."
      std::memmove(c + e + 1, c + e, n - e);
      c[e] = '.';
      ++n;
    }
  }
  char c[40];
  int n = 0;
};

// The file being written: its head, then the DATA section's entities numbered in the order added,
// each written into the file's text as it is made (17 000 entities for a cam of 700 arcs: no
// temporaries per entity, no copy of the text).
class StepData {
 public:
  // `expected_size`: room made up front [characters], the text grows past it if need be.
  StepData(std::string_view head, size_t expected_size) : buf_(std::max(expected_size, head.size()), '\0') {
    Put(head);
  }
  int Add(const std::string& body) {
    const int id = Open(body.size());
    Put(body);
    Close();
    return id;
  }
  static std::string Ref(int id) {
    std::string s(1, '#');
    s += std::to_string(id);
    return s;
  }
  // head #ref tail, e.g. VERTEX_POINT('',#12)
  int Wrap(std::string_view head, int ref, std::string_view tail) {
    const int id = Open(head.size() + tail.size());
    Put(head);
    PutRef(ref);
    Put(tail);
    Close();
    return id;
  }
  // head #ref1,#ref2 tail, e.g. LINE('',#12,#3)
  int Wrap(std::string_view head, int ref1, int ref2, std::string_view tail) {
    const int id = Open(head.size() + tail.size());
    Put(head);
    PutRef(ref1);
    Put(',');
    PutRef(ref2);
    Put(tail);
    Close();
    return id;
  }
  // head #ref,real tail, e.g. CIRCLE('',#12,2.5)
  int Wrap(std::string_view head, int ref, const Real& r, std::string_view tail) {
    const int id = Open(head.size() + tail.size());
    Put(head);
    PutRef(ref);
    Put(',');
    Put(r);
    Put(tail);
    Close();
    return id;
  }
  int Point(const Real& x, const Real& y, const Real& z) { return Triple("CARTESIAN_POINT('',(", x, y, z); }
  int Point(double x, double y, double z) { return Point(Real(x), Real(y), Real(z)); }
  int Direction(double x, double y, double z) { return Triple("DIRECTION('',(", Real(x), Real(y), Real(z)); }
  int Axis(int point, int axis, int ref) {
    const int id = Open(32);
    Put("AXIS2_PLACEMENT_3D('',");
    PutRef(point);
    Put(',');
    PutRef(axis);
    Put(',');
    PutRef(ref);
    Put(')');
    Close();
    return id;
  }
  // The knots of `spans` segments of degree p: multiplicities p+1, then `inner` at each joint, then
  // p+1; then `between`, then the knot values 0.,1.,…,spans. Quadratic segments meeting at double
  // knots (the arcs' rational walls) or cubic spans at single knots (a closed cubic's runs).
  static void AppendKnots(std::string& body, int spans, char end, char inner, std::string_view between) {
    body += end;
    for (int k = 1; k < spans; ++k) body += ',', body += inner;
    body += ',', body += end;
    body += between;
    for (int k = 0; k <= spans; ++k) {
      if (k) body += ',';
      const Real r(k);
      body.append(r.c, size_t(r.n));
    }
  }
  // The references `(#a,#b,…` of a curve's poles, or `((#a0,#at),(#b0,#bt),…` of a wall's (bottom
  // and top curve's poles in pairs), without the closing parenthesis.
  static void AppendPoles(std::string& body, const std::vector<int>& poles) {
    for (size_t i = 0; i < poles.size(); ++i) {
      if (i) body += ',';
      body += Ref(poles[i]);
    }
  }
  static void AppendPolePairs(std::string& body, const std::vector<int>& poles0, const std::vector<int>& polest) {
    for (size_t i = 0; i < poles0.size(); ++i) {
      if (i) body += ',';
      body += '(';
      body += Ref(poles0[i]);
      body += ',';
      body += Ref(polest[i]);
      body += ')';
    }
  }
  // A rational quadratic B-spline curve (ISO 10303-42 complex instance) of `segments` segments
  // meeting at double knots, through the points `poles` with `weights`.
  int RationalQuadraticCurve(const std::vector<int>& poles, const std::vector<double>& weights, int segments) {
    std::string body = "( BOUNDED_CURVE() B_SPLINE_CURVE(2,(";
    AppendPoles(body, poles);
    body += "),.UNSPECIFIED.,.F.,.F.) B_SPLINE_CURVE_WITH_KNOTS((";
    AppendKnots(body, segments, '3', '2', "),(");
    body += "),.UNSPECIFIED.) CURVE() GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_CURVE((";
    for (size_t i = 0; i < weights.size(); ++i) {
      if (i) body += ',';
      const Real r(weights[i]);
      body.append(r.c, size_t(r.n));
    }
    body += ")) REPRESENTATION_ITEM('') )";
    return Add(body);
  }
  // The wall over a rational quadratic B-spline run: degree 2 along the run, 1 across the
  // thickness, its poles those of the bottom and top curves (`poles0`, `polest`).
  int RationalQuadraticWall(const std::vector<int>& poles0, const std::vector<int>& polest,
                            const std::vector<double>& weights, int segments) {
    std::string body = "( BOUNDED_SURFACE() B_SPLINE_SURFACE(2,1,(";
    AppendPolePairs(body, poles0, polest);
    body += "),.UNSPECIFIED.,.F.,.F.,.F.) B_SPLINE_SURFACE_WITH_KNOTS((";
    AppendKnots(body, segments, '3', '2', "),(2,2),(");
    body += "),(0.,1.),.UNSPECIFIED.) GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_SURFACE((";
    for (size_t i = 0; i < weights.size(); ++i) {
      if (i) body += ',';
      const Real r(weights[i]);
      body += '(';
      body.append(r.c, size_t(r.n));
      body += ',';
      body.append(r.c, size_t(r.n));
      body += ')';
    }
    body += ")) REPRESENTATION_ITEM('') SURFACE() )";
    return Add(body);
  }
  // A non-rational clamped cubic B-spline curve of `spans` spans through `poles` (spans + 3).
  int CubicCurve(const std::vector<int>& poles, int spans) {
    std::string body = "B_SPLINE_CURVE_WITH_KNOTS('',3,(";
    AppendPoles(body, poles);
    body += "),.UNSPECIFIED.,.F.,.F.,(";
    AppendKnots(body, spans, '4', '1', "),(");
    body += "),.UNSPECIFIED.)";
    return Add(body);
  }
  // The wall over a clamped cubic run: degree 3 along the run, 1 across the thickness.
  int CubicWall(const std::vector<int>& poles0, const std::vector<int>& polest, int spans) {
    std::string body = "B_SPLINE_SURFACE_WITH_KNOTS('',3,1,(";
    AppendPolePairs(body, poles0, polest);
    body += "),.UNSPECIFIED.,.F.,.F.,.F.,(";
    AppendKnots(body, spans, '4', '1', "),(2,2),(");
    body += "),(0.,1.),.UNSPECIFIED.)";
    return Add(body);
  }
  int Edge(int from, int to, int curve, bool same_sense) {
    const int id = Open(32);
    Put("EDGE_CURVE('',");
    PutRef(from);
    Put(',');
    PutRef(to);
    Put(',');
    PutRef(curve);
    Put(same_sense ? std::string_view(",.T.)") : std::string_view(",.F.)"));
    Close();
    return id;
  }
  // An edge loop of (edge, orientation) pairs, as a FACE_OUTER_BOUND or FACE_BOUND.
  int Bound(const std::vector<std::pair<int, bool>>& edges, bool outer) {
    return Bound(edges.data(), edges.size(), outer);
  }
  int Bound(std::initializer_list<std::pair<int, bool>> edges, bool outer) {
    return Bound(edges.begin(), edges.size(), outer);
  }
  int Bound(const std::pair<int, bool>* edges, size_t count, bool outer) {
    const int first = next_;
    for (size_t i = 0; i < count; ++i) {
      Open(32);
      Put("ORIENTED_EDGE('',*,*,");
      PutRef(edges[i].first);
      Put(edges[i].second ? std::string_view(",.T.)") : std::string_view(",.F.)"));
      Close();
    }
    const int loop = Open(16 + kRefChars * count);
    Put("EDGE_LOOP('',(");
    for (int id = first; id < loop; ++id) {
      if (id > first) Put(',');
      PutRef(id);
    }
    Put("))");
    Close();
    return Wrap(outer ? "FACE_OUTER_BOUND(''," : "FACE_BOUND(''," , loop, ",.T.)");
  }
  int Face(const std::vector<int>& bounds, int surface, bool same_sense) {
    return Face(bounds.data(), bounds.size(), surface, same_sense);
  }
  // A face of one bound.
  int Face(int bound, int surface, bool same_sense) { return Face(&bound, 1, surface, same_sense); }
  // The text, ended with `tail`.
  std::string Finish(std::string_view tail) {
    Reserve(tail.size());
    Put(tail);
    buf_.resize(len_);
    return std::move(buf_);
  }

 private:
  // Room for the entity's number, " = ", references and the ";\n" on top of `extra` characters.
  static constexpr size_t kRefChars = 12;  // ",#" and up to 10 digits
  int Face(const int* bounds, size_t count, int surface, bool same_sense) {
    const int id = Open(32 + kRefChars * count);
    Put("ADVANCED_FACE('',(");
    for (size_t i = 0; i < count; ++i) {
      if (i) Put(',');
      PutRef(bounds[i]);
    }
    Put("),");
    PutRef(surface);
    Put(same_sense ? std::string_view(",.T.)") : std::string_view(",.F.)"));
    Close();
    return id;
  }
  // Starts entity #id with room for `extra` more characters than 4 references and 2 REALs.
  int Open(size_t extra) {
    Reserve(extra + 4 * kRefChars + 2 * sizeof(Real::c) + 16);
    const int id = next_++;
    PutRef(id);
    Put(" = ");
    return id;
  }
  void Close() { Put(";\n"); }
  void Reserve(size_t extra) {
    if (len_ + extra > buf_.size()) buf_.resize(std::max(len_ + extra, 2 * buf_.size()));
  }
  void Put(char c) { buf_[len_++] = c; }
  void Put(std::string_view s) {
    std::memcpy(buf_.data() + len_, s.data(), s.size());
    len_ += s.size();
  }
  void Put(const Real& r) { Put(std::string_view(r.c, r.n)); }
  void PutRef(int id) {
    char* p = buf_.data() + len_;
    *p = '#';
    len_ = std::to_chars(p + 1, p + kRefChars, id).ptr - buf_.data();
  }
  int Triple(std::string_view head, const Real& x, const Real& y, const Real& z) {
    const int id = Open(head.size() + sizeof(Real::c) + 8);
    Put(head);
    Put(x);
    Put(',');
    Put(y);
    Put(',');
    Put(z);
    Put("))");
    Close();
    return id;
  }
  std::string buf_;  // the text is buf_[0, len_); the rest is room
  size_t len_ = 0;
  int next_ = 1;
};

// A run of the chain's arcs and lines as one rational quadratic B-spline, exactly: each arc (cut
// into pieces of at most 90° turn) is one segment with poles at its ends and at the crossing of its
// end tangents, whose weight is cos(half the turn); a line is a segment with its midpoint as the
// middle pole, weight 1 (Piegl & Tiller, The NURBS Book, 2nd ed., §7.3). The segments meet at
// double knots, so the curve passes through every joint of the chain.
struct RationalQuadratic {
  std::vector<Vec2<double>> poles;  ///< 2 segments + 1
  std::vector<double> weights;
  int segments = 0;
};

RationalQuadratic ChainAsRationalQuadratic(const ArcSegment* arcs, size_t count) {
  RationalQuadratic c;
  c.poles.push_back(arcs[0].start);
  c.weights.push_back(1.0);
  for (size_t i = 0; i < count; ++i) {
    const ArcSegment& a = arcs[i];
    if (std::abs(a.bulge) < 1e-12) {
      c.poles.push_back(0.5 * (a.start + a.end));
      c.weights.push_back(1.0);
      c.poles.push_back(a.end);
      c.weights.push_back(1.0);
      ++c.segments;
      continue;
    }
    const ArcGeometry g = ArcGeometryOf(a);
    const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(g.sweep) / (0.5 * kPi) - 1e-9)));
    const double half = 0.5 * g.sweep / pieces, cos_half = std::cos(half);
    Vec2<double> from = a.start;
    for (int k = 1; k <= pieces; ++k) {
      const Vec2<double> to = k == pieces ? a.end : PointOnArc(a, g, double(k) / pieces);
      // |mid − centre| = r cos(half), |pole − centre| = r / cos(half).
      c.poles.push_back(g.centre + (0.5 * (from + to) - g.centre) / (cos_half * cos_half));
      c.weights.push_back(cos_half);
      c.poles.push_back(to);
      c.weights.push_back(1.0);
      ++c.segments;
      from = to;
    }
  }
  return c;
}

// The largest number of the chain's arcs in one wall face (the file then has a face per this many
// arcs instead of a face per arc: a tenth of the text for a profile of hundreds of arcs).
constexpr size_t kArcsPerWall = 64;
// The largest number of a closed cubic's spans in one wall face.
constexpr int kSpansPerWall = 256;

}  // namespace

bool SplineWalls(const Extrusion& e) {
  return e.profile_spline && e.profile.size() > kArcsPerWall && e.profile_spline->poles.size() >= 4 &&
         e.profile_spline->poles.size() < e.profile.size();
}

namespace {

}  // namespace

double MeshDeflection(const Extrusion& e) {
  return std::max(e.mesh_deflection_mm, kMeshRelativeDeflection * Diagonal(e.profile));
}

namespace {

// Triangles between two closed loops of points seen from `c`, each counter-clockwise and turning
// monotonically about c (star-shaped about it), the inner loop inside the outer or a single point
// (a fan): a merge of the two in polar angle. False when a loop does not turn monotonically or a
// triangle is not counter-clockwise — the triangles then would not tile the ring (with every
// triangle counter-clockwise they cover it exactly once: their indicator functions sum to the
// boundary's winding number).
bool MergeRing(const std::vector<Vec2<double>>& pts, const std::vector<int>& outer, const std::vector<int>& inner,
               const Vec2<double>& c, std::vector<std::array<int, 3>>& cap) {
  const auto ccw = [&](int a, int b, int d) { return Cross(pts[b] - pts[a], pts[d] - pts[a]) > 0; };
  // Unwrapped polar angles of a loop from its point of least angle in [0, 2π).
  auto unwrap = [&](const std::vector<int>& loop, std::vector<double>& alpha, int& first) {
    const int n = static_cast<int>(loop.size());
    first = 0;
    double least = INFINITY;
    for (int i = 0; i < n; ++i) {
      const Vec2<double> d = pts[loop[i]] - c;
      double t = std::atan2(d.y(), d.x());
      if (t < 0) t += 2 * kPi;
      if (t < least) least = t, first = i;
    }
    alpha.assign(n + 1, least);
    for (int k = 1; k <= n; ++k) {
      const Vec2<double> u = pts[loop[(first + k - 1) % n]] - c, v = pts[loop[(first + k) % n]] - c;
      const double turn = std::atan2(Cross(u, v), u.dot(v));
      if (!(turn > 0)) return false;
      alpha[k] = alpha[k - 1] + turn;
    }
    return std::abs(alpha[n] - alpha[0] - 2 * kPi) <= 1e-9;
  };
  std::vector<double> ao, ai;
  int fo = 0, fi = 0;
  if (!unwrap(outer, ao, fo)) return false;
  const int n = static_cast<int>(outer.size());
  if (inner.size() == 1) {
    for (int i = 0; i < n; ++i) {
      const int a = outer[i], b = outer[(i + 1) % n];
      if (!ccw(inner[0], a, b)) return false;
      cap.push_back({inner[0], a, b});
    }
    return true;
  }
  if (!unwrap(inner, ai, fi)) return false;
  const int m = static_cast<int>(inner.size());
  // Both from the outer loop's first angle: the inner loop's angles shifted by −2π when they start
  // above it, and its start moved to its last point at or below it.
  while (ai[0] > ao[0]) {
    for (double& x : ai) x -= 2 * kPi;
  }
  int shift = 0;
  while (shift < m && ai[shift + 1] <= ao[0]) ++shift;
  int i = 0, j = 0;
  auto inner_at = [&](int k) { return inner[(fi + shift + k) % m]; };
  std::vector<double> aj(m + 1);
  for (int k = 0; k <= m; ++k) {
    const int idx = shift + k;
    aj[k] = idx <= m ? ai[idx] : ai[idx - m] + 2 * kPi;
  }
  while (i < n || j < m) {
    const int oi = outer[(fo + i) % n], ij = inner_at(j);
    if (j == m || (i < n && ao[i + 1] <= aj[j + 1])) {
      const int on = outer[(fo + i + 1) % n];
      if (!ccw(ij, oi, on)) return false;
      cap.push_back({ij, oi, on});
      ++i;
    } else {
      const int in = inner_at(j + 1);
      if (!ccw(ij, oi, in)) return false;
      cap.push_back({ij, oi, in});
      ++j;
    }
  }
  return true;
}

// Points of a circle counter-clockwise from angle `from`, `count` of them.
void AppendCircle(const Vec2<double>& c, double r, double from, int count, std::vector<Vec2<double>>& pts,
                  std::vector<int>& loop) {
  for (int k = 0; k < count; ++k) {
    const double t = from + 2 * kPi * k / count;
    loop.push_back(static_cast<int>(pts.size()));
    pts.push_back(c + r * Vec2<double>(std::cos(t), std::sin(t)));
  }
}

// Chords per full turn of a circle of radius r within the deflection and kMaxChordTurn.
int CircleChords(double r, double deflection) {
  const double step = std::min(kMaxChordTurn, 2.0 * std::acos(1.0 - std::min(1.0, deflection / r)));
  return std::max(8, static_cast<int>(std::ceil(2 * kPi / step - 1e-9)));
}

}  // namespace

std::optional<TriangleMesh> MeshExtrusion(const Extrusion& e, double deflection, bool chain_checked) {
  if (!chain_checked) CheckChain(e);
  if (!(deflection > 0) || !std::isfinite(deflection)) throw std::invalid_argument("the mesh deflection must be > 0");
  const Vec2<double> c = e.bore_centre;
  std::vector<Vec2<double>> pts;
  std::vector<int> outer;
  {
    std::vector<Vec2<double>> chords;
    for (const ArcSegment& a : e.profile) AppendChords(a, deflection, c, chords);
    for (const Vec2<double>& p : chords) outer.push_back(static_cast<int>(pts.size())), pts.push_back(p);
  }
  const bool bore = e.bore_diameter_mm > 0;
  const double rb = 0.5 * e.bore_diameter_mm;
  std::vector<std::array<int, 3>> cap;
  std::vector<std::vector<int>> inner_walls;  // loops whose walls face their axis (bore, holes)
  if (e.holes.empty()) {
    std::vector<int> inner;
    if (bore && e.keyway_width_mm > 0) {
      std::vector<Vec2<double>> chords;
      for (const ArcSegment& a : BoreChain(e)) AppendChords(a, deflection, c, chords);
      for (const Vec2<double>& p : chords) inner.push_back(static_cast<int>(pts.size())), pts.push_back(p);
      inner_walls.push_back(inner);
    } else if (bore) {
      AppendCircle(c, rb, 0.0, CircleChords(rb, deflection), pts, inner);
      inner_walls.push_back(inner);
    } else {
      inner.push_back(static_cast<int>(pts.size()));
      pts.push_back(c);
    }
    if (!MergeRing(pts, outer, inner, c, cap)) return std::nullopt;
  } else {
    // Holes of one diameter equally spaced on a circle about the centre (a disc's output-pin
    // holes, a bolt circle): a ring between the profile and a circle M outside the holes, merged
    // about the centre, and one sector per hole (from the bore, or the centre, to M, between the
    // holes' mid-angles) merged about the hole's centre. Anything else: the kernel's mesher.
    const int z = static_cast<int>(e.holes.size());
    const double rh = 0.5 * e.holes[0].diameter_mm;
    const Vec2<double> d0 = e.holes[0].centre - c;
    const double R = d0.norm(), a0 = std::atan2(d0.y(), d0.x());
    if (z < 3 || !(R > 0)) return std::nullopt;
    for (int j = 0; j < z; ++j) {
      const Vec2<double> want = c + R * Vec2<double>(std::cos(a0 + 2 * kPi * j / z), std::sin(a0 + 2 * kPi * j / z));
      if ((e.holes[j].centre - want).norm() > 1e-9 * R || std::abs(e.holes[j].diameter_mm - 2 * rh) > 1e-12 * rh)
        return std::nullopt;
    }
    double nearest = INFINITY;
    for (int k : outer) nearest = std::min(nearest, (pts[k] - c).norm());
    const double half = kPi / z;
    // A keyed bore: the sectors start at a circle K between the keyway's reach and the holes, and
    // the ring between K and the keyed bore is merged about the centre.
    const bool keyed = bore && e.keyway_width_mm > 0;
    std::vector<int> keyed_loop;
    double r_in = bore ? rb : 0.0;
    if (keyed) {
      std::vector<Vec2<double>> chords;
      for (const ArcSegment& a : BoreChain(e)) AppendChords(a, deflection, c, chords);
      double reach = 0;
      for (const Vec2<double>& p : chords) {
        reach = std::max(reach, (p - c).norm());
        keyed_loop.push_back(static_cast<int>(pts.size()));
        pts.push_back(p);
      }
      r_in = 0.5 * (reach + R - rh);
      if (!(r_in > reach)) return std::nullopt;
    }
    // Each sector must see its inner arc and keep its hole clear of its sides.
    if (!(R + rh < nearest) || !(rh < R * std::sin(half)) || !(r_in < R * std::cos(half)) || !(r_in < R - rh))
      return std::nullopt;
    const double rm = 0.5 * (R + rh + nearest);
    const double from = a0 - half;
    // Every chord of a sector's boundary spans at most kMaxChordTurn seen from its hole's centre
    // (so that the merge's fans reach only the hole's edges they see): on M a turn of at most
    // kMaxChordTurn (rm − R)/rm about the centre, on the bore kMaxChordTurn (R − rb)/rb, and the
    // sides cut into pieces of at most kMaxChordTurn R sin(π/z) / 2.
    auto per_sector = [&](double r, double dist) {
      const int by_deflection = (CircleChords(r, deflection) + z - 1) / z;
      const int by_view = static_cast<int>(std::ceil(2 * half * r / (kMaxChordTurn * dist) - 1e-9));
      return std::max(by_deflection, by_view);
    };
    const int qm = per_sector(rm, rm - R);
    std::vector<int> ring_m;
    AppendCircle(c, rm, from, qm * z, pts, ring_m);
    if (!MergeRing(pts, outer, ring_m, c, cap)) return std::nullopt;
    std::vector<int> ring_b;
    int qb = 0;
    if (bore) {
      qb = per_sector(r_in, R - r_in);
      AppendCircle(c, r_in, from, qb * z, pts, ring_b);
      if (keyed) {
        if (!MergeRing(pts, ring_b, keyed_loop, c, cap)) return std::nullopt;
        inner_walls.push_back(keyed_loop);
      } else {
        inner_walls.push_back(ring_b);
      }
    } else {
      ring_b.push_back(static_cast<int>(pts.size()));
      pts.push_back(c);
    }
    // The sides' inner points, from the bore, K or the centre out to M: side j at angle from + 2πj/z.
    const int pieces = std::max(1, static_cast<int>(std::ceil((rm - r_in) / (0.5 * kMaxChordTurn * R * std::sin(half)))));
    std::vector<std::vector<int>> sides(z);
    for (int j = 0; j < z; ++j) {
      const Vec2<double> u(std::cos(from + 2 * kPi * j / z), std::sin(from + 2 * kPi * j / z));
      for (int k = 1; k < pieces; ++k) {
        sides[j].push_back(static_cast<int>(pts.size()));
        pts.push_back(c + (r_in + (rm - r_in) * k / pieces) * u);
      }
    }
    for (int j = 0; j < z; ++j) {
      // The sector counter-clockwise: out along its first side, along M, in along its second
      // side, back along the bore clockwise (or through the centre).
      std::vector<int> loop;
      loop.push_back(bore ? ring_b[(j * qb) % (qb * z)] : ring_b[0]);
      loop.insert(loop.end(), sides[j].begin(), sides[j].end());
      for (int k = 0; k <= qm; ++k) loop.push_back(ring_m[(j * qm + k) % (qm * z)]);
      loop.insert(loop.end(), sides[(j + 1) % z].rbegin(), sides[(j + 1) % z].rend());
      if (bore)
        for (int k = qb; k > 0; --k) loop.push_back(ring_b[(j * qb + k) % (qb * z)]);
      std::vector<int> hole;
      AppendCircle(e.holes[j].centre, rh, 0.0, CircleChords(rh, deflection), pts, hole);
      inner_walls.push_back(hole);
      if (!MergeRing(pts, loop, hole, e.holes[j].centre, cap)) return std::nullopt;
    }
  }
  TriangleMesh mesh;
  const int ring = static_cast<int>(pts.size());
  for (double zz : {0.0, e.thickness_mm})
    for (const Vec2<double>& p : pts) mesh.vertices.emplace_back(p.x(), p.y(), zz);
  for (const auto& t : cap) {
    mesh.triangles.push_back({t[0], t[2], t[1]});                       // z = 0, facing −z
    mesh.triangles.push_back({t[0] + ring, t[1] + ring, t[2] + ring});  // z = thickness, facing +z
  }
  // Walls: the profile counter-clockwise faces out; the bore and holes, counter-clockwise, face
  // their axes.
  const int n = static_cast<int>(outer.size());
  for (int i = 0; i < n; ++i) {
    const int a = outer[i], b = outer[(i + 1) % n];
    mesh.triangles.push_back({a, b, b + ring});
    mesh.triangles.push_back({a, b + ring, a + ring});
  }
  for (const std::vector<int>& loop : inner_walls) {
    const int m = static_cast<int>(loop.size());
    for (int j = 0; j < m; ++j) {
      const int a = loop[j], b = loop[(j + 1) % m];
      mesh.triangles.push_back({b, a, a + ring});
      mesh.triangles.push_back({b, a + ring, b + ring});
    }
  }
  // Points only the cap uses twice (the centre of a fan) stay; unused points cannot occur.
  return mesh;
}

std::string StepString(const std::string& text) {
  // An apostrophe and a backslash doubled, control bytes as spaces, and every other non-ASCII
  // character of the UTF-8 text as \X2\hhhh\X0\ (UCS-2; a character beyond it, or an invalid
  // byte, as '?').
  std::string out;
  char buf[8];
  bool in_x2 = false;
  auto close_x2 = [&] {
    if (in_x2) out += "\\X0\\";
    in_x2 = false;
  };
  for (size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      close_x2();
      if (c == '\'') out += "''";
      else if (c == '\\') out += "\\\\";
      else out += (c < 0x20 || c == 0x7f) ? ' ' : char(c);
      ++i;
      continue;
    }
    const int n = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 1;
    unsigned code = n == 2 ? c & 0x1F : n == 3 ? c & 0x0F : c & 0x07;
    bool valid = n > 1 && i + n <= text.size();
    for (int k = 1; valid && k < n; ++k) {
      const unsigned char d = static_cast<unsigned char>(text[i + k]);
      valid = (d & 0xC0) == 0x80;
      code = (code << 6) | (d & 0x3F);
    }
    if (!valid || code > 0xFFFF) {
      close_x2();
      out += '?';
      i += valid ? n : 1;
      continue;
    }
    if (!in_x2) out += "\\X2\\", in_x2 = true;
    std::snprintf(buf, sizeof buf, "%04X", code);
    out += buf;
    i += n;
  }
  close_x2();
  return out;
}

namespace {

// The entities a file's parts share: the application context and protocol, the product and
// product-definition contexts, and the geometric context with its units (millimetres); each made
// when the first part needs it, so that a file of one part lists them in the order it always had.
struct StepContext {
  int app = 0, pctx = 0, dctx = 0, ctx = 0;
};

StepData NewStepFile(const std::string& name, const char* description, size_t expected_size) {
  return StepData("ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('" + std::string(description) + "'),'2;1');\n"
                  "FILE_NAME('" + name + "','2000-01-01T00:00:00',(''),(''),'camopt','camopt','');\n"
                  "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n",
                  expected_size);
}

StepContext AddApplication(StepData& d) {
  StepContext c;
  c.app = d.Add("APPLICATION_CONTEXT('core data for automotive mechanical design processes')");
  d.Add("APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000," + StepData::Ref(c.app) + ")");
  c.pctx = d.Add("PRODUCT_CONTEXT(''," + StepData::Ref(c.app) + ",'mechanical')");
  return c;
}

// A product and its definition (AP214, automotive_design); `category` 'part' or 'assembly'.
struct ProductIds {
  int definition = 0, shape = 0;
};
ProductIds AddProduct(StepData& d, StepContext& c, const std::string& name, const char* category) {
  ProductIds p;
  const int product = d.Add("PRODUCT('" + name + "','" + name + "','',(" + StepData::Ref(c.pctx) + "))");
  const int formation = d.Add("PRODUCT_DEFINITION_FORMATION('',''," + StepData::Ref(product) + ")");
  if (!c.dctx) c.dctx = d.Add("PRODUCT_DEFINITION_CONTEXT('part definition'," + StepData::Ref(c.app) + ",'design')");
  p.definition = d.Add("PRODUCT_DEFINITION('design',''," + StepData::Ref(formation) + "," + StepData::Ref(c.dctx) + ")");
  p.shape = d.Add("PRODUCT_DEFINITION_SHAPE(''," + std::string("''") + "," + StepData::Ref(p.definition) + ")");
  d.Add("PRODUCT_RELATED_PRODUCT_CATEGORY('" + std::string(category) + "',$,(" + StepData::Ref(product) + "))");
  if (!c.ctx) {
    const int mm = d.Add("( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) )");
    const int rad = d.Add("( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) )");
    const int sr = d.Add("( NAMED_UNIT(*) SI_UNIT($,.STERADIAN.) SOLID_ANGLE_UNIT() )");
    const int unc = d.Add("UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07)," + StepData::Ref(mm) +
                          ",'distance_accuracy_value','confusion accuracy')");
    c.ctx = d.Add("( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((" + StepData::Ref(unc) +
                  ")) GLOBAL_UNIT_ASSIGNED_CONTEXT((" + StepData::Ref(mm) + "," + StepData::Ref(rad) + "," +
                  StepData::Ref(sr) + ")) REPRESENTATION_CONTEXT('','3D') )");
  }
  return p;
}

// One extruded part: its product, B-rep and shape representation (whose first item is the part's
// frame, `origin`).
struct PartIds {
  int definition = 0, rep = 0, origin = 0;
};
PartIds AddExtrusion(StepData& d, StepContext& ctx_ids, const Extrusion& e, const std::string& name) {
  const ProductIds product = AddProduct(d, ctx_ids, name, "part");
  const double t = e.thickness_mm;
  const int dz = d.Direction(0, 0, 1), dx = d.Direction(1, 0, 0);
  const int up = d.Wrap("VECTOR('',", dz, ",1.)");
  const size_t n = e.profile.size();
  const Real zero(0.0), top_z(t);
  // The walls: one face per arc or line (a cylinder or a plane), or, for a chain of more than
  // kArcsPerWall of them, one face per run of kArcsPerWall (the extrusion of the run as a rational
  // B-spline, exactly the same arcs). A wall starts at each `first[w]` of the chain.
  const size_t per_wall = n > kArcsPerWall ? kArcsPerWall : 1;
  // Or, where the extrusion carries a closed cubic of fewer poles than the chain has arcs, the
  // walls are that spline's (ProfileAsSpline): runs of at most kSpansPerWall spans, two at least.
  const ClosedCubic* spline = SplineWalls(e) ? &*e.profile_spline : nullptr;
  std::vector<size_t> first;
  std::vector<std::vector<Vec2<double>>> clamped;
  std::vector<int> spans;
  if (spline) {
    const int poles = static_cast<int>(spline->poles.size());
    const int runs = std::max(2, (poles + kSpansPerWall - 1) / kSpansPerWall);
    for (int w = 0; w < runs; ++w) {
      const int a = w * poles / runs, b = (w + 1) * poles / runs;
      clamped.push_back(ClampedSpans(*spline, a, b));
      spans.push_back(b - a);
    }
  } else {
    for (size_t i = 0; i < n; i += per_wall) first.push_back(i);
  }
  const size_t walls_n = spline ? clamped.size() : first.size();
  // Vertices at the walls' start points, at z = 0 and z = t; the vertical edge through each.
  std::vector<int> v0(walls_n), vt(walls_n), vertical(walls_n);
  std::vector<Real> start_x, start_y;
  start_x.reserve(walls_n), start_y.reserve(walls_n);
  for (size_t w = 0; w < walls_n; ++w) {
    const Vec2<double>& p = spline ? clamped[w].front() : e.profile[first[w]].start;
    start_x.emplace_back(p.x()), start_y.emplace_back(p.y());
    const int p0 = d.Point(start_x[w], start_y[w], zero), pt = d.Point(start_x[w], start_y[w], top_z);
    v0[w] = d.Wrap("VERTEX_POINT('',", p0, ")");
    vt[w] = d.Wrap("VERTEX_POINT('',", pt, ")");
    const int line = d.Wrap("LINE('',", p0, up, ")");
    vertical[w] = d.Edge(v0[w], vt[w], line, true);
  }
  // Each wall: its edge at both ends and its face, facing out of the solid.
  std::vector<int> bottom(walls_n), top(walls_n), faces;
  std::vector<int> walls;
  for (size_t w = 0; w < walls_n; ++w) {
    const size_t k = (w + 1) % walls_n;
    int surface = 0;
    bool outward = true;
    if (spline) {
      std::vector<int> poles0, polest;
      poles0.reserve(clamped[w].size()), polest.reserve(clamped[w].size());
      for (const Vec2<double>& p : clamped[w]) {
        const Real x(p.x()), y(p.y());
        poles0.push_back(d.Point(x, y, zero));
        polest.push_back(d.Point(x, y, top_z));
      }
      bottom[w] = d.Edge(v0[w], v0[k], d.CubicCurve(poles0, spans[w]), true);
      top[w] = d.Edge(vt[w], vt[k], d.CubicCurve(polest, spans[w]), true);
      // S(u, v) = C(u) + v t ẑ: its normal C'(u) × ẑ is right of travel, out of a counter-clockwise curve.
      surface = d.CubicWall(poles0, polest, spans[w]);
      const int bound = d.Bound({{bottom[w], true}, {vertical[k], true}, {top[w], false}, {vertical[w], false}}, true);
      walls.push_back(d.Face(bound, surface, outward));
      continue;
    }
    const ArcSegment& a = e.profile[first[w]];
    if (per_wall > 1) {
      const size_t count = std::min(per_wall, n - first[w]);
      const RationalQuadratic c = ChainAsRationalQuadratic(&e.profile[first[w]], count);
      std::vector<int> poles0, polest;
      poles0.reserve(c.poles.size()), polest.reserve(c.poles.size());
      for (const Vec2<double>& p : c.poles) {
        const Real x(p.x()), y(p.y());
        poles0.push_back(d.Point(x, y, zero));
        polest.push_back(d.Point(x, y, top_z));
      }
      const int curve0 = d.RationalQuadraticCurve(poles0, c.weights, c.segments);
      bottom[w] = d.Edge(v0[w], v0[k], curve0, true);
      top[w] = d.Edge(vt[w], vt[k], d.RationalQuadraticCurve(polest, c.weights, c.segments), true);
      // S(u, v) = C(u) + v t ẑ: its normal C'(u) × ẑ is right of travel, out of a counter-clockwise chain.
      surface = d.RationalQuadraticWall(poles0, polest, c.weights, c.segments);
    } else if (std::abs(a.bulge) < 1e-12) {
      const Vec2<double> u = (a.end - a.start).normalized();
      const int dir = d.Direction(u.x(), u.y(), 0.0);
      const int normal = d.Direction(u.y(), -u.x(), 0.0);  // right of travel: out of a CCW chain
      const int vec = d.Wrap("VECTOR('',", dir, ",1.)");
      const int p0 = d.Point(start_x[w], start_y[w], zero), pt = d.Point(start_x[w], start_y[w], top_z);
      bottom[w] = d.Edge(v0[w], v0[k], d.Wrap("LINE('',", p0, vec, ")"), true);
      top[w] = d.Edge(vt[w], vt[k], d.Wrap("LINE('',", pt, vec, ")"), true);
      surface = d.Wrap("PLANE('',", d.Axis(p0, normal, dir), ")");
    } else {
      const ArcGeometry g = ArcGeometryOf(a);
      const bool ccw = g.sweep > 0;  // the circle runs counter-clockwise about +z
      const Real cx(g.centre.x()), cy(g.centre.y());
      const int c0 = d.Axis(d.Point(cx, cy, zero), dz, dx);
      const int ct = d.Axis(d.Point(cx, cy, top_z), dz, dx);
      const Real r(g.radius);
      bottom[w] = d.Edge(v0[w], v0[k], d.Wrap("CIRCLE('',", c0, r, ")"), ccw);
      top[w] = d.Edge(vt[w], vt[k], d.Wrap("CIRCLE('',", ct, r, ")"), ccw);
      surface = d.Wrap("CYLINDRICAL_SURFACE('',", c0, r, ")");
      outward = ccw;  // a counter-clockwise arc of a counter-clockwise chain has the solid inside it
    }
    // Seen from outside: along the bottom edge, up at its end, back along the top, down.
    const int bound = d.Bound({{bottom[w], true}, {vertical[k], true}, {top[w], false}, {vertical[w], false}}, true);
    walls.push_back(d.Face(bound, surface, outward));
  }
  // The bore (a keyed bore's arc and slot) and the holes: each an inner chain counter-clockwise about
  // its centre (a hole two half circles), a wall per arc or line facing its axis.
  std::vector<std::vector<std::pair<int, bool>>> inner_bottom, inner_top;
  std::vector<std::vector<ArcSegment>> chains;
  if (e.bore_diameter_mm > 0) chains.push_back(BoreChain(e));
  for (const Hole& h : e.holes) {
    const double r = 0.5 * h.diameter_mm;
    const Vec2<double> a = h.centre + Vec2<double>(r, 0.0), b = h.centre - Vec2<double>(r, 0.0);
    chains.push_back({{a, b, 1.0}, {b, a, 1.0}});
  }
  for (const std::vector<ArcSegment>& chain : chains) {
    const size_t m = chain.size();
    std::vector<int> iv0(m), ivt(m), side(m), arc0(m), arct(m);
    for (size_t k = 0; k < m; ++k) {
      const Real x(chain[k].start.x()), y(chain[k].start.y());
      const int p0 = d.Point(x, y, zero), pt = d.Point(x, y, top_z);
      iv0[k] = d.Wrap("VERTEX_POINT('',", p0, ")");
      ivt[k] = d.Wrap("VERTEX_POINT('',", pt, ")");
      side[k] = d.Edge(iv0[k], ivt[k], d.Wrap("LINE('',", p0, up, ")"), true);
    }
    struct {
      Vec2<double> centre = Vec2<double>::Zero();
      double radius = 0;
      int bottom = 0, top = 0, surface = 0;
    } circle;
    for (size_t k = 0; k < m; ++k) {
      const ArcSegment& a = chain[k];
      const size_t n1 = (k + 1) % m;
      int surface = 0;
      bool same = false;
      if (std::abs(a.bulge) < 1e-12) {
        const Vec2<double> u = (a.end - a.start).normalized();
        const int dir = d.Direction(u.x(), u.y(), 0.0);
        const int normal = d.Direction(-u.y(), u.x(), 0.0);  // left of travel: towards the hole's axis
        const int vec = d.Wrap("VECTOR('',", dir, ",1.)");
        const int p0 = d.Point(a.start.x(), a.start.y(), 0.0), pt = d.Point(a.start.x(), a.start.y(), t);
        arc0[k] = d.Edge(iv0[k], iv0[n1], d.Wrap("LINE('',", p0, vec, ")"), true);
        arct[k] = d.Edge(ivt[k], ivt[n1], d.Wrap("LINE('',", pt, vec, ")"), true);
        surface = d.Wrap("PLANE('',", d.Axis(p0, normal, dir), ")");
        same = true;
      } else {
        const ArcGeometry g = ArcGeometryOf(a);  // counter-clockwise about its centre
        // Arcs of one circle (a hole's two halves) share its circles and its cylinder.
        if (!(circle.surface && (g.centre - circle.centre).norm() <= 1e-12 * g.radius &&
              std::abs(g.radius - circle.radius) <= 1e-12 * g.radius)) {
          const Real cx(g.centre.x()), cy(g.centre.y()), r(g.radius);
          const int c0 = d.Axis(d.Point(cx, cy, zero), dz, dx), ct = d.Axis(d.Point(cx, cy, top_z), dz, dx);
          circle = {g.centre, g.radius, d.Wrap("CIRCLE('',", c0, r, ")"), d.Wrap("CIRCLE('',", ct, r, ")"),
                    d.Wrap("CYLINDRICAL_SURFACE('',", c0, r, ")")};
        }
        arc0[k] = d.Edge(iv0[k], iv0[n1], circle.bottom, g.sweep > 0);
        arct[k] = d.Edge(ivt[k], ivt[n1], circle.top, g.sweep > 0);
        surface = circle.surface;
        same = false;  // the solid is outside the circle: the face's normal points to its axis
      }
      // Seen from the axis (the solid's outside): back along the bottom edge, up at its start,
      // along the top edge, down at its end.
      const int bound = d.Bound({{arc0[k], false}, {side[k], true}, {arct[k], true}, {side[n1], false}}, true);
      walls.push_back(d.Face(bound, surface, same));
    }
    // The end faces' inner loops: clockwise seen from their outside (below for z = 0).
    std::vector<std::pair<int, bool>> b0, bt;
    for (size_t k = 0; k < m; ++k) b0.push_back({arc0[k], true});
    for (size_t k = m; k-- > 0;) bt.push_back({arct[k], false});
    inner_bottom.push_back(b0);
    inner_top.push_back(bt);
  }
  // The end faces: z = 0 faces −z (its profile loop reversed), z = t faces +z.
  std::vector<std::pair<int, bool>> loop0, loopt;
  for (size_t w = walls_n; w-- > 0;) loop0.push_back({bottom[w], false});
  for (size_t w = 0; w < walls_n; ++w) loopt.push_back({top[w], true});
  const int plane0 = d.Add("PLANE(''," + StepData::Ref(d.Axis(d.Point(0, 0, 0), dz, dx)) + ")");
  const int planet = d.Add("PLANE(''," + StepData::Ref(d.Axis(d.Point(0, 0, t), dz, dx)) + ")");
  std::vector<int> b0 = {d.Bound(loop0, true)}, bt = {d.Bound(loopt, true)};
  for (size_t k = 0; k < inner_bottom.size(); ++k) {
    b0.push_back(d.Bound(inner_bottom[k], false));
    bt.push_back(d.Bound(inner_top[k], false));
  }
  faces.push_back(d.Face(b0, plane0, false));
  faces.push_back(d.Face(bt, planet, true));
  faces.insert(faces.end(), walls.begin(), walls.end());
  std::string list;
  for (int f : faces) {
    if (!list.empty()) list += ',';
    list += StepData::Ref(f);
  }
  const int shell = d.Add("CLOSED_SHELL('',(" + list + "))");
  const int brep = d.Add("MANIFOLD_SOLID_BREP(''," + StepData::Ref(shell) + ")");
  PartIds ids;
  ids.definition = product.definition;
  ids.origin = d.Axis(d.Point(0, 0, 0), dz, dx);
  ids.rep = d.Add("ADVANCED_BREP_SHAPE_REPRESENTATION('',(" + StepData::Ref(ids.origin) + "," + StepData::Ref(brep) +
                  ")," + StepData::Ref(ctx_ids.ctx) + ")");
  d.Add("SHAPE_DEFINITION_REPRESENTATION(" + StepData::Ref(product.shape) + "," + StepData::Ref(ids.rep) + ")");
  return ids;
}

size_t ExpectedStepSize(const Extrusion& e) { return 1300 * e.profile.size() + 2500 * e.holes.size() + 8192; }

}  // namespace

std::string StepOfExtrusion(const Extrusion& e) {
  CheckChain(e);
  const std::string name = StepString(e.name);
  // About 1200 characters per arc of a short chain (its wall, edges, vertices and their geometry), 500
  // in the B-spline walls of a long one; the text grows past this if need be.
  StepData d = NewStepFile(name, "camopt extruded cam", ExpectedStepSize(e));
  StepContext c = AddApplication(d);
  AddExtrusion(d, c, e, name);
  return d.Finish("ENDSEC;\nEND-ISO-10303-21;\n");
}

std::string StepAssembly(const std::string& raw_name, const std::vector<Extrusion>& parts,
                         const std::vector<Placement>& placements) {
  size_t expected = 8192;
  for (const Extrusion& e : parts) {
    CheckChain(e);
    expected += ExpectedStepSize(e);
  }
  const std::string name = StepString(raw_name);
  StepData d = NewStepFile(name, "camopt assembly", expected + 1200 * placements.size());
  StepContext c = AddApplication(d);
  std::vector<PartIds> ids;
  for (const Extrusion& e : parts) ids.push_back(AddExtrusion(d, c, e, StepString(e.name)));
  const ProductIds top = AddProduct(d, c, name, "assembly");
  // The assembly's own representation: its frame and each occurrence's placement in it.
  const int dz = d.Direction(0, 0, 1), dx = d.Direction(1, 0, 0);
  const int top_origin = d.Axis(d.Point(0, 0, 0), dz, dx);
  std::vector<int> axes;
  std::string items = StepData::Ref(top_origin);
  for (const Placement& p : placements) {
    if (p.part >= parts.size()) throw std::invalid_argument("an assembly placement names no part");
    if (!p.origin.allFinite() || !std::isfinite(p.angle_rad)) throw std::invalid_argument("a placement is not finite");
    const int ref = d.Direction(std::cos(p.angle_rad), std::sin(p.angle_rad), 0.0);
    axes.push_back(d.Axis(d.Point(p.origin.x(), p.origin.y(), p.origin.z()), dz, ref));
    items += "," + StepData::Ref(axes.back());
  }
  const int top_rep = d.Add("SHAPE_REPRESENTATION('',(" + items + ")," + StepData::Ref(c.ctx) + ")");
  d.Add("SHAPE_DEFINITION_REPRESENTATION(" + StepData::Ref(top.shape) + "," + StepData::Ref(top_rep) + ")");
  // Each occurrence (ISO 10303-214 assembly structure): the usage of the part's definition in the
  // assembly's, and the transformation from the part's frame to its placement.
  for (size_t k = 0; k < placements.size(); ++k) {
    const Placement& p = placements[k];
    const std::string occurrence = StepString(p.name);
    const int nauo = d.Add("NEXT_ASSEMBLY_USAGE_OCCURRENCE('" + std::to_string(k + 1) + "','" + occurrence + "','',"
                           + StepData::Ref(top.definition) + "," + StepData::Ref(ids[p.part].definition) + ",$)");
    const int shape = d.Add("PRODUCT_DEFINITION_SHAPE('" + occurrence + "',''," + StepData::Ref(nauo) + ")");
    const int transform = d.Add("ITEM_DEFINED_TRANSFORMATION('',''," + StepData::Ref(ids[p.part].origin) + "," +
                                StepData::Ref(axes[k]) + ")");
    const int relation = d.Add("( REPRESENTATION_RELATIONSHIP('',''," + StepData::Ref(ids[p.part].rep) + "," +
                               StepData::Ref(top_rep) + ") REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(" +
                               StepData::Ref(transform) + ") SHAPE_REPRESENTATION_RELATIONSHIP() )");
    d.Add("CONTEXT_DEPENDENT_SHAPE_REPRESENTATION(" + StepData::Ref(relation) + "," + StepData::Ref(shape) + ")");
  }
  return d.Finish("ENDSEC;\nEND-ISO-10303-21;\n");
}

}  // namespace camopt::cad
