// Geometry files: bi-arc fitting against closed forms, and the STEP solids of the
// cam kinds read back with OpenCASCADE and compared with closed-form areas and volumes. The DXF
// and STL files are checked by independent readers in tests/geometry_files_test.py.
#include <array>
#include <cmath>
#include <cstdlib>
#include <sys/wait.h>
#include <filesystem>
#include <functional>
#include <cstdint>
#include <cstring>
#include <map>
#include <cstdio>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cad/arc_fit.h"
#include "cad/dxf.h"
#include "cad/solid.h"
#include "cad/stl.h"
#include "studies/cycloid_ltca_study.h"
#include "studies/disc_cam_study.h"
#include "studies/globoidal_cam_study.h"
#include "studies/lcr_analysis_study.h"
#include "tests/test_util.h"

namespace camopt {
namespace cad_test {

using camopt::testing::ReadFile;
using camopt::testing::SourcePath;
using nlohmann::json;

// A STEP solid from a closed-form area and perimeter: 0.1 % (the bound for the volume).
constexpr double kSolidRelTol = 1e-3;

json Example(const std::string& name) { return json::parse(ReadFile(SourcePath("studies/examples/" + name))); }

// ∫₀^{2π} f(t) dt for a smooth periodic f by the trapezoid rule (spectrally accurate).
template <typename F>
double PeriodicIntegral(F f, int n = 20000) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += f(2 * kPi * i / n);
  return s * 2 * kPi / n;
}

// Area and perimeter of the curve X(t) = A u(t) − B u(k t) (k − 1 a non-zero integer):
// ½∮ X × X' = π(A² + k B²) (the cross terms are cos((k − 1)t)), |X'|² = A² + k²B² − 2kAB cos((k − 1)t).
struct AreaLength {
  double area, length;
};
AreaLength Trochoid(double A, double B, double k) {
  const double length =
      PeriodicIntegral([&](double t) { return std::sqrt(A * A + k * k * B * B - 2 * k * A * B * std::cos((k - 1) * t)); });
  return {kPi * (A * A + k * B * B), length};
}

// Inner parallel curve at distance d of a regular closed curve (Steiner): A − dL + πd², L − 2πd.
AreaLength InnerOffset(const AreaLength& c, double d) {
  return {c.area - d * c.length + kPi * d * d, c.length - 2 * kPi * d};
}

TEST(ArcFit, QuarterCircle) {
  // Bulge tan(θ/4) for a 90° counter-clockwise arc of radius 2 about the origin.
  const cad::ArcSegment a{Vec2<double>(2, 0), Vec2<double>(0, 2), std::tan(kPi / 8)};
  const cad::ArcGeometry g = cad::ArcGeometryOf(a);
  EXPECT_NEAR(g.radius, 2.0, 1e-12);
  EXPECT_NEAR(g.centre.norm(), 0.0, 1e-12);
  EXPECT_NEAR(g.sweep, kPi / 2, 1e-12);
  const Vec2<double> mid = cad::PointOnArc(a, 0.5);
  EXPECT_NEAR(mid.x(), std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(mid.y(), std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(cad::DistanceToArc(a, Vec2<double>(3, 3)), 3 * std::sqrt(2.0) - 2, 1e-12);
  EXPECT_NEAR(cad::DistanceToArc(a, Vec2<double>(0, -1)), std::sqrt(5.0), 1e-12);  // outside: end point
  // Circular segment between chord and arc: r²(θ − sin θ)/2 plus the chord's triangle with the origin.
  const cad::ArcSegment b{Vec2<double>(0, 2), Vec2<double>(-2, 0), std::tan(kPi / 8)};
  const cad::ArcSegment c{Vec2<double>(-2, 0), Vec2<double>(0, -2), std::tan(kPi / 8)};
  const cad::ArcSegment d{Vec2<double>(0, -2), Vec2<double>(2, 0), std::tan(kPi / 8)};
  EXPECT_NEAR(cad::EnclosedArea({a, b, c, d}), 4 * kPi, 1e-12);
}

// The refinement of the largest check-point deviations finds the largest distance of the arcs from
// the curve: on an ellipse and on a curve of varying curvature (a limaçon), the brute-force
// maximum over 400 001 points of the curve (1/200 of the spacing of the fit's check points on
// average) is no more than 1e-6 of it above the refined value, which is at least the check
// points' own; the arcs and the check points' count are those of the fit without it.
TEST(ArcFit, RefinedDeviationIsTheLargestDistance) {
  const cad::CurveFunction ellipse = [](double t) { return Vec2<double>(30 * std::cos(t), 20 * std::sin(t)); };
  const cad::CurveFunction limacon = [](double t) {
    const double r = 25 + 8 * std::cos(t);
    return Vec2<double>(r * std::cos(t), r * std::sin(t));
  };
  for (const cad::CurveFunction& curve : {ellipse, limacon}) {
    cad::FitOptions o;
    o.tolerance_mm = 0.9e-3;
    const cad::FittedCurve plain = cad::FitBiarcs(curve, 0.0, 2 * kPi, o);
    o.refine_share = 0.8;
    o.refine_points = 16;
    const cad::FittedCurve refined = cad::FitBiarcs(curve, 0.0, 2 * kPi, o);
    ASSERT_EQ(refined.arcs.size(), plain.arcs.size());
    for (size_t i = 0; i < plain.arcs.size(); ++i) {
      EXPECT_EQ(refined.arcs[i].start, plain.arcs[i].start);
      EXPECT_EQ(refined.arcs[i].bulge, plain.arcs[i].bulge);
    }
    EXPECT_GE(refined.max_deviation_mm, plain.max_deviation_mm);
    EXPECT_GT(refined.checked_points, plain.checked_points);
    EXPECT_LE(refined.checked_points, plain.checked_points + long(plain.arcs.size()) / 2 * o.refine_points);
    const double dense = cad::MaxDistanceToChain(curve, 0.0, 2 * kPi, 400000, plain.arcs);
    EXPECT_LE(dense, refined.max_deviation_mm * (1 + 1e-6));
    EXPECT_GE(dense, refined.max_deviation_mm * (1 - 1e-6));  // it is a distance found on the curve
  }
}

TEST(ArcFit, EllipseWithinToleranceEverywhere) {
  const double ax = 30, by = 20;
  const cad::CurveFunction ellipse = [&](double t) { return Vec2<double>(ax * std::cos(t), by * std::sin(t)); };
  cad::FitOptions o;
  o.tolerance_mm = 1e-3;
  const cad::FittedCurve fit = cad::FitBiarcs(ellipse, 0.0, 2 * kPi, o);
  ASSERT_FALSE(fit.arcs.empty());
  EXPECT_TRUE(fit.within_tolerance);
  EXPECT_LE(fit.max_deviation_mm, o.tolerance_mm);
  // Closed, tangent-continuous chain.
  EXPECT_EQ(fit.arcs.back().end, fit.arcs.front().start);
  for (size_t i = 0; i < fit.arcs.size(); ++i) {
    const cad::ArcSegment& p = fit.arcs[i];
    const cad::ArcSegment& q = fit.arcs[(i + 1) % fit.arcs.size()];
    EXPECT_EQ(p.end, q.start);
    EXPECT_NEAR(cad::TangentOnArc(p, 1.0).dot(cad::TangentOnArc(q, 0.0)), 1.0, 1e-9) << i;
  }
  // Independent brute-force check on 200 001 points of the ellipse: within the tolerance (plus
  // the sampling of the fit's own check, at most a few per cent of it).
  EXPECT_LE(cad::MaxDistanceToChain(ellipse, 0.0, 2 * kPi, 200000, fit.arcs), 1.05 * o.tolerance_mm);
  // Area πab: the arcs stay within 1 µm of a curve of length ~159 mm, so within 0.16 mm².
  EXPECT_NEAR(cad::EnclosedArea(fit.arcs), kPi * ax * by, 159 * o.tolerance_mm);
  // Arcs, not chords: far fewer than a 1 µm polyline would need (~2000 chords).
  EXPECT_LT(fit.arcs.size(), 400u);
}

// A closed chain of chords through the points (bulge 0: ChainCrossesItself looks at the chords).
std::vector<cad::ArcSegment> Polygon(const std::vector<Vec2<double>>& p) {
  std::vector<cad::ArcSegment> chain;
  for (size_t i = 0; i < p.size(); ++i) chain.push_back({p[i], p[(i + 1) % p.size()], 0.0});
  return chain;
}
std::vector<Vec2<double>> Polar(int n, const std::function<double(double)>& r) {
  std::vector<Vec2<double>> p;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * (i + 0.5) / n;
    p.emplace_back(r(t) * std::cos(t), r(t) * std::sin(t));
  }
  return p;
}
// Every pair of non-neighbouring chords: the end points of each strictly on either side of the
// other's line (the reference for the sweep).
bool CrossesByEveryPair(const std::vector<Vec2<double>>& p) {
  const size_t n = p.size();
  auto side = [](const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c) {
    const double v = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    return v > 0 ? 1 : (v < 0 ? -1 : 0);
  };
  for (size_t i = 0; i < n; ++i)
    for (size_t k = i + 2; k < n; ++k) {
      if (i == 0 && k == n - 1) continue;
      const Vec2<double>&a = p[i], &b = p[(i + 1) % n], &c = p[k], &d = p[(k + 1) % n];
      if (side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0) return true;
    }
  return false;
}

// Limaçons r = b + a cos t: an inner loop (the chain crosses itself where the loop closes) exactly
// when a > b; a regular polygon and the star polygon {7/3} (whose edges cross by construction).
TEST(ArcFit, ChainCrossesItselfOnKnownShapes) {
  EXPECT_FALSE(cad::ChainCrossesItself(Polygon(Polar(2000, [](double t) { return 2 + std::cos(t); }))));
  EXPECT_TRUE(cad::ChainCrossesItself(Polygon(Polar(2000, [](double t) { return 1 + 2 * std::cos(t); }))));
  EXPECT_FALSE(cad::ChainCrossesItself(Polygon(Polar(7, [](double) { return 1.0; }))));
  std::vector<Vec2<double>> star;
  for (int i = 0; i < 7; ++i) star.emplace_back(std::cos(2 * kPi * 3 * i / 7), std::sin(2 * kPi * 3 * i / 7));
  EXPECT_TRUE(cad::ChainCrossesItself(Polygon(star)));
}

// Random closed polygons (3 to 40 vertices, some on a coarse lattice for touching and collinear
// chords) against every pair checked.
TEST(ArcFit, ChainCrossesItselfAgreesWithEveryPair) {
  std::srand(7);
  int crossing = 0, simple = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int n = 3 + std::rand() % 38;
    const bool lattice = trial % 3 == 0;
    std::vector<Vec2<double>> p;
    // Star-shaped with a random radius per vertex (often simple) or random points (often not).
    const bool star_shaped = trial % 2 == 0;
    for (int i = 0; i < n; ++i) {
      const double u = double(std::rand()) / RAND_MAX, v = double(std::rand()) / RAND_MAX;
      if (lattice) p.emplace_back(std::floor(5 * u), std::floor(5 * v));
      else if (star_shaped) {
        const double t = 2 * kPi * (i + 0.5 * u) / n;
        p.emplace_back((1 + v) * std::cos(t), (1 + v) * std::sin(t));
      } else p.emplace_back(u, v);
    }
    const bool expected = CrossesByEveryPair(p);
    (expected ? crossing : simple) += 1;
    EXPECT_EQ(cad::ChainCrossesItself(Polygon(p)), expected) << "trial " << trial;
  }
  // Both answers occur often enough for the comparison to mean something.
  EXPECT_GT(crossing, 300);
  EXPECT_GT(simple, 300);
}

// A sweep writes STEP files from several threads at once; OCCT's STEP translator keeps process-wide
// state, and unguarded this failed in CI ("STEP transfer failed"). Every thread must get the same
// file as a lone call and the closed-form volume of a 20 mm disc with a 6 mm bore, 5 mm thick.
// An LCR pitch curve X(t) = A u(t) − B u(13t) (rollers 13, lobes 12) is 12-fold symmetric: one
// period fitted and turned must be as close to the whole exact curve as the fit says, and a curve
// that is not symmetric, or a wrong order, must be fitted whole.
TEST(ArcFit, SymmetricFitTurnsOnePeriodAndChecksTheSymmetry) {
  const double A = 37, B = 1.5, k = 13;
  const cad::CurveFunction lcr = [&](double t) {
    return Vec2<double>(A * std::cos(t) - B * std::cos(k * t), A * std::sin(t) - B * std::sin(k * t));
  };
  const cad::CurveFunction clockwise = [&](double t) { return lcr(-t); };
  cad::FitOptions o;
  o.tolerance_mm = 0.9e-3;
  o.initial_segments = 104;
  o.refine_share = 0.8;
  o.refine_points = 16;
  const cad::FittedCurve whole = cad::FitBiarcs(lcr, 0.0, 2 * kPi, o);
  for (const cad::CurveFunction& curve : {lcr, clockwise}) {
    const cad::FittedCurve fit = cad::FitBiarcsSymmetric(curve, 0.0, 2 * kPi, 12, Vec2<double>::Zero(), o);
    EXPECT_EQ(fit.symmetry, 12);
    ASSERT_EQ(fit.arcs.size() % 12, 0u);
    EXPECT_TRUE(fit.within_tolerance);
    EXPECT_LE(fit.max_deviation_mm, o.tolerance_mm);
    EXPECT_LT(fit.symmetry_error_mm, 1e-12);
    // Connected and closed to the bit, tangent-continuous across the periods' joints too.
    for (size_t i = 0; i < fit.arcs.size(); ++i) {
      const cad::ArcSegment &p = fit.arcs[i], &q = fit.arcs[(i + 1) % fit.arcs.size()];
      EXPECT_EQ(p.end, q.start) << i;
      EXPECT_NEAR(cad::TangentOnArc(p, 1.0).dot(cad::TangentOnArc(q, 0.0)), 1.0, 1e-9) << i;
    }
    // The reported deviation (measured on one period) is the largest over the whole curve: an
    // independent check on 400 000 points of all twelve periods.
    const double dense = cad::MaxDistanceToChain(curve, 0.0, 2 * kPi, 400000, fit.arcs);
    EXPECT_LE(dense, fit.max_deviation_mm * (1 + 1e-6));
    EXPECT_GE(dense, fit.max_deviation_mm * (1 - 1e-3));
    std::printf("12-fold fit: %zu arcs, reported %.8f um, 400 000 points %.8f um; whole-curve fit %zu arcs, %.8f um; "
                "check points %ld / %ld\n",
                fit.arcs.size(), fit.max_deviation_mm * 1e3, dense * 1e3, whole.arcs.size(), whole.max_deviation_mm * 1e3,
                fit.checked_points, whole.checked_points);
    EXPECT_NEAR(cad::EnclosedArea(fit.arcs), cad::EnclosedArea(whole.arcs) * (curve(1e-3).y() > 0 ? 1 : -1),
                2 * kPi * A * o.tolerance_mm);
    // A twelfth of the curve evaluations, about.
    EXPECT_LT(fit.checked_points, whole.checked_points / 6);
  }
  // 10 nm of asymmetry (above 1e-3 of the tolerance): the whole curve is fitted.
  const cad::CurveFunction bumped = [&](double t) { return Vec2<double>(lcr(t) * (1 + 1e-5 / A * std::cos(t))); };
  const cad::FittedCurve bumped_fit = cad::FitBiarcsSymmetric(bumped, 0.0, 2 * kPi, 12, Vec2<double>::Zero(), o);
  EXPECT_EQ(bumped_fit.symmetry, 1);
  EXPECT_EQ(bumped_fit.arcs.size(), cad::FitBiarcs(bumped, 0.0, 2 * kPi, o).arcs.size());
  // A wrong order (a period's turn is not 2π/5), or a wrong centre: fitted whole, as FitBiarcs.
  for (const auto& [order, centre] : {std::pair{5, Vec2<double>::Zero().eval()}, std::pair{12, Vec2<double>(0.5, 0.0)}}) {
    const cad::FittedCurve f = cad::FitBiarcsSymmetric(lcr, 0.0, 2 * kPi, order, centre, o);
    EXPECT_EQ(f.symmetry, 1) << order;
    ASSERT_EQ(f.arcs.size(), whole.arcs.size()) << order;
    EXPECT_EQ(f.arcs.front().start, whole.arcs.front().start);
    EXPECT_EQ(f.max_deviation_mm, whole.max_deviation_mm);
  }
}

TEST(StepSolid, ConcurrentWritersGiveTheSameFileAsOneWriter) {
  const double q = std::tan(kPi / 8);
  cad::Extrusion e;
  e.profile = {{Vec2<double>(10, 0), Vec2<double>(0, 10), q},
               {Vec2<double>(0, 10), Vec2<double>(-10, 0), q},
               {Vec2<double>(-10, 0), Vec2<double>(0, -10), q},
               {Vec2<double>(0, -10), Vec2<double>(10, 0), q}};
  e.bore_diameter_mm = 6.0;
  e.thickness_mm = 5.0;
  e.mesh_deflection_mm = 0.01;
  const std::string lone = cad::ExtrudeCam(e).step;
  constexpr int kThreads = 4, kRepeats = 3;
  std::vector<std::string> step(kThreads * kRepeats);
  std::vector<std::string> error(kThreads);
  std::vector<std::thread> pool;
  for (int t = 0; t < kThreads; ++t) {
    pool.emplace_back([&, t] {
      try {
        for (int r = 0; r < kRepeats; ++r) step[t * kRepeats + r] = cad::ExtrudeCam(e).step;
      } catch (const std::exception& x) {
        error[t] = x.what();
      }
    });
  }
  for (std::thread& th : pool) th.join();
  for (int t = 0; t < kThreads; ++t) EXPECT_EQ(error[t], "") << "thread " << t;
  for (const std::string& s : step) EXPECT_EQ(s, lone);
  // The product name is the one given, not OCCT's "cam <counter>" that followed earlier writes.
  EXPECT_NE(lone.find("PRODUCT('cam','cam',"), std::string::npos);
  const cad::StepReadBack back = cad::ReadStep(lone);
  EXPECT_EQ(back.solids, 1);
  EXPECT_NEAR(back.volume_mm3 / (kPi * (100.0 - 9.0) * 5.0) - 1, 0.0, kSolidRelTol);
}

// A chain of more than 64 arcs and lines is written as rational B-spline walls (a face per 64 of
// them) that are the arcs exactly: a triangle of side 40 mm offset by 6 mm (each side cut into 22
// lines, each corner a 120° arc, cut by the writer into two of 60°), read back by OpenCASCADE, has
// the closed form's volume and area to the integration's accuracy, and the file is a fraction of
// the one-face-per-arc file of the same chain with its lines as arcs.
TEST(StepSolid, ManyArcsBecomeExactBSplineWalls) {
  const double side = 40.0, r = 6.0, t = 5.0;
  const Vec2<double> corner[3] = {{0, 0}, {side, 0}, {side / 2, side * std::sqrt(3.0) / 2}};
  cad::Extrusion e;
  for (int k = 0; k < 3; ++k) {
    const Vec2<double> a = corner[k], b = corner[(k + 1) % 3], u = (b - a).normalized(), out(u.y(), -u.x());
    for (int j = 0; j < 22; ++j)
      e.profile.push_back({a + r * out + (b - a) * (j / 22.0), a + r * out + (b - a) * ((j + 1) / 22.0), 0.0});
    const Vec2<double> v = (corner[(k + 2) % 3] - b).normalized(), out2(v.y(), -v.x());
    e.profile.push_back({b + r * out, b + r * out2, std::tan(2 * kPi / 3 / 4)});  // 120° counter-clockwise
  }
  e.bore_centre = Vec2<double>(side / 2, side * std::sqrt(3.0) / 6);
  e.bore_diameter_mm = 8.0;
  e.thickness_mm = t;
  ASSERT_EQ(e.profile.size(), 69u);
  const std::string step = cad::StepOfExtrusion(e);
  EXPECT_NE(step.find("RATIONAL_B_SPLINE_SURFACE"), std::string::npos);
  EXPECT_EQ(step.find("CYLINDRICAL_SURFACE('',#"), step.rfind("CYLINDRICAL_SURFACE('',#"));  // the bore's only
  const double tri = side * side * std::sqrt(3.0) / 4, bore = kPi * 16.0;
  const double area_face = tri + 3 * side * r + kPi * r * r - bore;
  const double volume = area_face * t, area = 2 * area_face + (3 * side + 2 * kPi * r + 2 * kPi * 4.0) * t;
  const cad::StepReadBack back = cad::ReadStep(step);
  EXPECT_EQ(back.solids, 1);
  EXPECT_TRUE(back.valid);
  EXPECT_NEAR(back.volume_mm3 / volume - 1, 0.0, 1e-8) << back.volume_mm3 << " vs " << volume;
  EXPECT_NEAR(back.area_mm2 / area - 1, 0.0, 1e-8) << back.area_mm2 << " vs " << area;
  // The same chain, 64 at a time no longer: 7 arcs of a regular polygon of 7 sides stay cylinders.
  cad::Extrusion few;
  for (int k = 0; k < 7; ++k)
    few.profile.push_back({Vec2<double>(20 * std::cos(2 * kPi * k / 7), 20 * std::sin(2 * kPi * k / 7)),
                           Vec2<double>(20 * std::cos(2 * kPi * (k + 1) / 7), 20 * std::sin(2 * kPi * (k + 1) / 7)),
                           std::tan(2 * kPi / 7 / 4)});
  const std::string small = cad::StepOfExtrusion(few);
  EXPECT_EQ(small.find("B_SPLINE"), std::string::npos);
  const cad::StepReadBack circle = cad::ReadStep(small);
  EXPECT_NEAR(circle.volume_mm3 / (kPi * 400.0 * 10.0) - 1, 0.0, 1e-8);
}

TEST(Stl, BinaryLayoutAndEdgeCheck) {
  // A tetrahedron, outward oriented: closed; one face flipped: misoriented; one face removed: free.
  cad::TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  const cad::EdgeCheck ok = cad::CheckEdges(m);
  EXPECT_EQ(ok.free_edges + ok.misoriented_edges + ok.overused_edges, 0);
  const std::string bin = cad::BinaryStl(m, "tet");
  EXPECT_EQ(bin.size(), 84u + 50u * 4);
  EXPECT_NE(bin.compare(0, 5, "solid"), 0);  // a binary STL never starts like an ASCII one
  EXPECT_EQ(static_cast<unsigned char>(bin[80]), 4u);
  EXPECT_EQ(cad::AsciiStl(m, "tet").rfind("solid tet\n", 0), 0u);
  cad::TriangleMesh flipped = m;
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  EXPECT_EQ(cad::CheckEdges(flipped).misoriented_edges, 3);
  cad::TriangleMesh open = m;
  open.triangles.pop_back();
  EXPECT_EQ(cad::CheckEdges(open).free_edges, 3);
}

TEST(Dxf, HeaderDeclaresMillimetresAndHandlesAreUnique) {
  cad::DxfDocument d;
  d.AddLayer("A", 1);
  d.AddChain("A", {{Vec2<double>(0, 0), Vec2<double>(1, 0), 0.5}, {Vec2<double>(1, 0), Vec2<double>(0, 0), 0.5}}, true);
  d.AddText("A", Vec2<double>(0, -2), 1.0, "x");
  const std::string s = d.ToString();
  EXPECT_NE(s.find("$INSUNITS\n70\n4\n"), std::string::npos);
  EXPECT_NE(s.find("$MEASUREMENT\n70\n1\n"), std::string::npos);
  EXPECT_NE(s.find("LWPOLYLINE"), std::string::npos);
  EXPECT_NE(s.find("\n42\n0.5\n"), std::string::npos);
  // Every handle (group 5 or 105) once.
  std::istringstream in(s);
  std::string code, value;
  std::set<std::string> handles;
  int count = 0;
  while (std::getline(in, code) && std::getline(in, value))
    if (code == "5" || code == "105") handles.insert(value), ++count;
  EXPECT_EQ(static_cast<int>(handles.size()), count);
  EXPECT_GT(count, 20);
}

// Every DXF number as printf's "%.12g" (the reference here: the C library's printf, not
// std::to_chars): random magnitudes across the integer path's range and past its ends, the
// roundings up to the next power of ten, and exact halfway cases (dyadic numbers whose 13th
// significant digit is their last, a 5: ties go to the even digit).
TEST(Dxf, NumbersAsPrintfG12) {
  auto expect_same = [](double v) {
    char ours[40], printf_text[40];
    *cad::FormatG12(ours, v) = '\0';
    std::snprintf(printf_text, sizeof printf_text, "%.12g", v);
    EXPECT_STREQ(ours, printf_text) << "value " << std::hexfloat << v;
    return std::string(printf_text);
  };
  std::uint64_t state = 12345;
  auto next = [&state] {  // splitmix64
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  for (int i = 0; i < 200000; ++i) {
    const double u = double(next() >> 11) / double(1ULL << 53);
    const double v = std::pow(10.0, -11.0 + 24.0 * u);  // 1e-11 ... 1e13
    expect_same(i % 2 ? v : -v);
  }
  for (int k = -12; k <= 13; ++k) {
    const double p = std::pow(10.0, k);
    for (double v : {p, std::nextafter(p, 0.0), std::nextafter(p, 1e300), p * (1 - 5e-13), p * (1 - 4e-13)})
      expect_same(v);
  }
  // n / 2^k = n 5^k / 10^k: with n odd and n 5^k of 13 digits, its 13th significant digit is its
  // last, a 5: halfway between two 12-digit values.
  int ties = 0;
  for (int k = 1; k <= 17; ++k) {
    std::uint64_t five_k = 1;
    for (int i = 0; i < k; ++i) five_k *= 5;
    const std::uint64_t lo = (1000000000000ULL + five_k - 1) / five_k, hi = (10000000000000ULL - 1) / five_k;
    for (int i = 0; i < 200 && hi > lo; ++i) {
      const std::uint64_t n = (lo + next() % (hi - lo)) | 1;
      if (n > hi) continue;
      const double v = std::ldexp(double(n), -k);
      expect_same(v);
      expect_same(-v);
      ++ties;
    }
  }
  EXPECT_GT(ties, 2000);
}

// The LCR II input cam's STEP solid read back by OpenCASCADE has the volume
// (profile area − bore area) × thickness within 0.1 %, the profile area in closed form.
TEST(GeometryFiles, LcrIIStepSolidsReadBack) {
  json study = Example("lcr_ii.json");
  study["analysis"]["evaluate"] = {"profile", "undercut"};
  const studies::Node root(&study, "lcr_ii.json", "");
  const studies::lcr_analysis::Study st = studies::lcr_analysis::Parse(root);
  const studies::lcr_analysis::Result res = studies::lcr_analysis::Run(st, {"lcr_ii.json", true});
  studies::Outputs out;
  studies::lcr_analysis::Write(st, res, out);
  const json j = studies::WriteResult(res);
  for (const char* side : {"input", "output"}) {
    const json& s = study["reducer"][side];
    const double R = s["turret_radius_mm"], e = study["reducer"]["eccentricity_mm"];
    const double k = double(s["rollers"]) / (double(s["rollers"]) - double(s["lobes"]));
    const double r = double(s["roller_diameter_mm"]) / 2, t = s["cam_thickness_mm"];
    const double bore = double(s["bore_diameter_mm"]) / 2;
    const AreaLength profile = InnerOffset(Trochoid(R, e, k), r);
    const double volume = (profile.area - kPi * bore * bore) * t;
    const double area = 2 * (profile.area - kPi * bore * bore) + (profile.length + 2 * kPi * bore) * t;
    const std::string stem = std::string(side) + "_cam";
    ASSERT_TRUE(out.files().count(stem + ".step")) << stem;
    const cad::StepReadBack back = cad::ReadStep(out.files().at(stem + ".step"));
    EXPECT_EQ(back.solids, 1) << stem;
    EXPECT_TRUE(back.valid) << stem;
    EXPECT_NEAR(back.volume_mm3 / volume - 1, 0.0, kSolidRelTol) << stem;
    EXPECT_NEAR(back.area_mm2 / area - 1, 0.0, kSolidRelTol) << stem;
    std::printf("%s: STEP volume %.3f mm³, closed form %.3f mm³ (rel. diff %.2e); area %.3f / %.3f mm²\n",
                stem.c_str(), back.volume_mm3, volume, back.volume_mm3 / volume - 1, back.area_mm2, area);
    const json& g = j["geometry_files"][stem];
    EXPECT_LE(double(g["dxf_max_deviation_um"]), double(g["dxf_tolerance_um"]));
    // The extrapolated polygon areas against the closed form (Steiner's offset of the trochoid).
    EXPECT_NEAR(double(g["profile_area_mm2"]), profile.area, 2e-7) << stem;
    // No cutter given: no cutter layer, and a note saying why.
    EXPECT_TRUE(g.contains("cutter_path"));
    EXPECT_EQ(out.files().at(stem + ".dxf").find("CUTTER_PATH"), std::string::npos);
  }
}

// A study name with a line break, apostrophes, a backslash and a non-ASCII letter: it went into
// the DXF text, the ASCII STL's "solid" line and the STEP strings unescaped (an independent DXF
// reader failed with "missing ENDSEC"; the apostrophe ended the STEP string).
TEST(GeometryFiles, AnyStudyNameGivesWellFormedFiles) {
  json study = Example("lcr_ii.json");
  study["name"] = "line one\nline 'two' \\ Getriebe \u00fc";
  study["analysis"]["evaluate"] = {"profile", "undercut"};
  study["geometry_files"] = {{"stl_format", "ascii"}};
  const studies::Node root(&study, "lcr_ii.json", "");
  const studies::lcr_analysis::Study st = studies::lcr_analysis::Parse(root);
  const studies::lcr_analysis::Result res = studies::lcr_analysis::Run(st, {"lcr_ii.json", true});
  studies::Outputs out;
  studies::lcr_analysis::Write(st, res, out);
  const std::string& dxf = out.files().at("input_cam.dxf");
  // Group codes and values alternate line by line: every odd line is a whole number.
  std::istringstream in(dxf);
  std::string code, value;
  int pairs = 0, sections = 0, ends = 0;
  while (std::getline(in, code) && std::getline(in, value)) {
    ASSERT_FALSE(code.empty());
    char* end = nullptr;
    std::strtol(code.c_str(), &end, 10);
    ASSERT_EQ(*end, '\0') << "line pair " << pairs << ": '" << code << "' is not a group code";
    if (code == "0" && value == "SECTION") ++sections;
    if (code == "0" && value == "ENDSEC") ++ends;
    ++pairs;
  }
  EXPECT_EQ(sections, ends);
  EXPECT_GT(sections, 2);
  EXPECT_NE(dxf.find("line one line 'two'"), std::string::npos);
  const std::string& stl = out.files().at("input_cam.stl");
  EXPECT_EQ(stl.substr(0, stl.find('\n')).find(' ', 6), std::string::npos) << "the solid name is one token";
  EXPECT_EQ(stl.substr(0, 6), "solid ");
  const std::string& step = out.files().at("input_cam.step");
  EXPECT_NE(step.find("line one line ''two'' \\\\ Getriebe \\X2\\00FC\\X0\\"), std::string::npos);
  const cad::StepReadBack back = cad::ReadStep(step);
  EXPECT_EQ(back.solids, 1);
  EXPECT_TRUE(back.valid);
}

TEST(GeometryFiles, LcrCutterPathLayerWhenACutterIsGiven) {
  json study = Example("lcr_ii.json");
  study["analysis"]["evaluate"] = {"profile"};
  study["reducer"]["input"]["cutter_diameter_mm"] = 10;
  study["geometry_files"] = {{"dxf_tolerance_um", 5}, {"step", false}, {"stl_format", "ascii"}};
  const studies::Node root(&study, "lcr_ii.json", "");
  const studies::lcr_analysis::Study st = studies::lcr_analysis::Parse(root);
  const studies::lcr_analysis::Result res = studies::lcr_analysis::Run(st, {"lcr_ii.json", true});
  studies::Outputs out;
  studies::lcr_analysis::Write(st, res, out);
  EXPECT_NE(out.files().at("input_cam.dxf").find("CUTTER_PATH"), std::string::npos);
  EXPECT_EQ(out.files().at("output_cam.dxf").find("CUTTER_PATH"), std::string::npos);
  EXPECT_FALSE(out.files().count("input_cam.step"));
  EXPECT_EQ(out.files().at("input_cam.stl").rfind("solid ", 0), 0u);
  const json g = studies::WriteResult(res)["geometry_files"];
  EXPECT_EQ(g["input_cam"]["cutter_diameter_mm"], 10.0);
  EXPECT_LE(double(g["input_cam"]["dxf_max_deviation_um"]), 5.0);
  // A coarser tolerance, fewer arcs.
  EXPECT_LT(int(g["input_cam"]["profile_arcs"]), 400);
}

TEST(GeometryFiles, BadToleranceIsAnInputError) {
  json study = Example("lcr_ii.json");
  study["geometry_files"] = {{"dxf_tolerance_um", 0}};
  const studies::Node root(&study, "lcr_ii.json", "");
  EXPECT_THROW(studies::lcr_analysis::Parse(root), studies::StudyError);
  study["geometry_files"] = {{"stl_format", "obj"}};
  EXPECT_THROW(studies::lcr_analysis::Parse(studies::Node(&study, "lcr_ii.json", "")), studies::StudyError);
  study.erase("geometry_files");
  study["reducer"]["input"]["bore_diameter_mm"] = 70;  // larger than the cam
  EXPECT_THROW(studies::lcr_analysis::Parse(studies::Node(&study, "lcr_ii.json", "")), studies::StudyError);
}

TEST(GeometryFiles, CycloidNnmDiscStepSolid) {
  json study = Example("cycloid_ltca_nnm_none.json");
  study["analysis"] = {{"crank_angles_deg", {0}}, {"grid", {8, 8}}, {"estimate_error", false}};
  const studies::Node root(&study, "nnm.json", "");
  const auto st = studies::cycloid_ltca::Parse(root);
  const auto res = studies::cycloid_ltca::Run(st, {"nnm.json", true});
  studies::Outputs out;
  studies::cycloid_ltca::Write(st, res, out);
  const json& d = study["drive"];
  const double a = double(d["roller_position_radius_mm"]) + double(study["modification"]["delta_position_um"]) * 1e-3;
  const double rho = double(d["roller_radius_mm"]) + double(study["modification"]["delta_radius_um"]) * 1e-3;
  const AreaLength profile = InnerOffset(Trochoid(a, d["eccentricity_mm"], d["rollers"]), rho);
  const double bore = double(d["bore_diameter_mm"]) / 2, t = d["face_width_mm"];
  const double volume = (profile.area - kPi * bore * bore) * t;
  const cad::StepReadBack back = cad::ReadStep(out.files().at("tooth.step"));
  EXPECT_EQ(back.solids, 1);
  EXPECT_TRUE(back.valid);
  EXPECT_NEAR(back.volume_mm3 / volume - 1, 0.0, kSolidRelTol);
  std::printf("cycloid disc: STEP volume %.3f mm³, closed form %.3f mm³ (rel. diff %.2e)\n", back.volume_mm3,
              volume, back.volume_mm3 / volume - 1);
  const json g = studies::WriteResult(res)["geometry_files"]["tooth"];
  EXPECT_LE(double(g["dxf_max_deviation_um"]), 1.0);
}

TEST(GeometryFiles, DiscCamStepSolidAndCutterPath) {
  json study = Example("disc_cam_translating.json");
  study["analysis"] = {{"angle_steps", 3600}, {"evaluate", {"profile"}}};
  study["bore_diameter_mm"] = 20;
  const studies::Node root(&study, "disc.json", "");
  const auto st = studies::disc_cam::Parse(root);
  const auto res = studies::disc_cam::Run(st, {"disc.json", true});
  studies::Outputs out;
  studies::disc_cam::Write(st, res, out);
  // Area of the model's profile points (3600, the polygon's chords cut off < 1e-6 of it).
  const auto& xs = res.series.contact_x_mm;
  const auto& ys = res.series.contact_y_mm;
  double area = 0.0;
  for (size_t i = 0; i < xs.size(); ++i) {
    const size_t k = (i + 1) % xs.size();
    area += 0.5 * (xs[i] * ys[k] - xs[k] * ys[i]);
  }
  const double bore = double(study["bore_diameter_mm"]) / 2, t = study["cam_thickness_mm"];
  const double volume = (std::abs(area) - kPi * bore * bore) * t;
  const cad::StepReadBack back = cad::ReadStep(out.files().at("profile.step"));
  EXPECT_EQ(back.solids, 1);
  EXPECT_TRUE(back.valid);
  EXPECT_NEAR(back.volume_mm3 / volume - 1, 0.0, kSolidRelTol);
  std::printf("disc cam: STEP volume %.3f mm³, from the profile points %.3f mm³ (rel. diff %.2e)\n",
              back.volume_mm3, volume, back.volume_mm3 / volume - 1);
  EXPECT_NE(out.files().at("profile.dxf").find("CUTTER_PATH"), std::string::npos);
  const json g = studies::WriteResult(res)["geometry_files"]["profile"];
  EXPECT_LE(double(g["dxf_max_deviation_um"]), 1.0);
  EXPECT_EQ(g["cutter_diameter_mm"], 2 * double(study["cutter_radius_mm"]));
}

// Every STEP solid the examples write, read back by OpenCASCADE: one valid solid whose volume is
// result.json's (exact profile area − bore area) × thickness within 0.1 %. Stages cut to the
// geometry (profile / unloaded), which is what the files depend on.
TEST(GeometryFiles, EveryExampleStepSolidReadsBack) {
  int solids = 0;
  for (const auto& entry : std::filesystem::directory_iterator(SourcePath("studies/examples"))) {
    if (entry.path().extension() != ".json") continue;
    json study = json::parse(ReadFile(entry.path()));
    if (!study.is_object() || !study.contains("study")) continue;
    const std::string kind = study["study"];
    const std::string name = entry.path().filename().string();
    studies::Outputs out;
    json j;
    const studies::Node root(&study, name, "");
    if (kind == "lcr_analysis") {
      study["analysis"]["evaluate"] = {"profile"};
      const auto st = studies::lcr_analysis::Parse(root);
      const auto res = studies::lcr_analysis::Run(st, {name, true});
      studies::lcr_analysis::Write(st, res, out);
      j = studies::WriteResult(res);
    } else if (kind == "cycloid_ltca") {
      study["analysis"] = {{"evaluate", {"unloaded"}}, {"crank_angles_deg", {0}}};
      study.erase("duty_cycle");  // a bearing life needs the loaded stage; the geometry does not
      if (study.contains("load")) study["load"].erase("input_speed_rpm");
      study.erase("torsional_dynamics");  // the mesh stiffness is the loaded contact's
      study.erase("stiffness");         // the torsional curve and the output mechanism's loads need
      study.erase("output_mechanism");  // the loaded stage too
      study.erase("discs");
      for (const char* catalogue : {"ratings", "output_bearing", "external_loads"})
        study.erase(catalogue);   // the ratings need the loaded stage; the output bearing is not drawn
      study.erase("tolerances");  // the transmission error from tolerances: not the geometry
      study.erase("monte_carlo");
      for (const char* lubrication : {"lubricant", "surfaces", "bearing_friction", "efficiency_map"})
        study.erase(lubrication);  // the lubricated losses need the loaded stage
      if (study.contains("limits"))
        for (const char* limit : {"min_efficiency", "max_oil_temperature_C", "min_film_lambda"}) study["limits"].erase(limit);
      const auto st = studies::cycloid_ltca::Parse(root);
      const auto res = studies::cycloid_ltca::Run(st, {name, true});
      studies::cycloid_ltca::Write(st, res, out);
      j = studies::WriteResult(res);
    } else if (kind == "disc_cam") {
      study["analysis"] = {{"evaluate", {"profile"}}};
      const auto st = studies::disc_cam::Parse(root);
      const auto res = studies::disc_cam::Run(st, {name, true});
      studies::disc_cam::Write(st, res, out);
      j = studies::WriteResult(res);
    } else {
      continue;
    }
    ASSERT_TRUE(j.contains("geometry_files")) << name;
    for (const auto& [part, g] : j["geometry_files"].items()) {
      EXPECT_LE(double(g["dxf_max_deviation_um"]), double(g["dxf_tolerance_um"])) << name << " " << part;
      EXPECT_TRUE(out.files().count(g["dxf"].get<std::string>())) << name << " " << part;
      if (!g.contains("step")) continue;
      const cad::StepReadBack back = cad::ReadStep(out.files().at(g["step"].get<std::string>()));
      EXPECT_EQ(back.solids, 1) << name << " " << part;
      EXPECT_TRUE(back.valid) << name << " " << part;
      EXPECT_NEAR(back.volume_mm3 / double(g["solid_volume_mm3"]) - 1, 0.0, kSolidRelTol) << name << " " << part;
      ++solids;
    }
  }
  EXPECT_GE(solids, 8);  // 2 LCR examples × 2 cams, 4 cycloid discs, 2 disc cams
}

// The globoidal cam's working surfaces: binary STL by default (two open bands: only their rims are
// free edges, none misoriented) and two B-spline surfaces in STEP whose area matches the mesh's.
TEST(GeometryFiles, GloboidalSurfacesBinaryStlAndStep) {
  json study = Example("globoidal_cam_paper.json");
  study["analysis"]["evaluate"] = {"geometry", "export"};
  const studies::Node root(&study, "glob.json", "");
  const auto st = studies::globoidal_cam::Parse(root);
  const auto res = studies::globoidal_cam::Run(st, {"glob.json", true});
  studies::Outputs out;
  studies::globoidal_cam::Write(st, res, out);
  const std::string& stl = out.files().at("working_surfaces.stl");
  ASSERT_GE(stl.size(), 84u);
  EXPECT_NE(stl.compare(0, 5, "solid"), 0);
  uint32_t n = 0;
  std::memcpy(&n, stl.data() + 80, 4);
  const size_t na = res.surface_points[0].size(), nl = res.surface_points[0][0].size();
  EXPECT_EQ(n, 2 * na * (nl - 1) * 2);
  EXPECT_EQ(stl.size(), 84u + 50u * n);
  // Independent edge count on the file's float coordinates.
  std::map<std::pair<std::array<float, 3>, std::array<float, 3>>, int> directed;
  for (uint32_t t = 0; t < n; ++t) {
    std::array<std::array<float, 3>, 3> v;
    for (int k = 0; k < 3; ++k) std::memcpy(v[k].data(), stl.data() + 84 + 50 * t + 12 + 12 * k, 12);
    for (int k = 0; k < 3; ++k) ++directed[{v[k], v[(k + 1) % 3]}];
  }
  long free_edges = 0, misoriented = 0;
  for (const auto& [e, c] : directed) {
    const auto back = directed.find({e.second, e.first});
    if (back == directed.end()) ++free_edges;
    else if (c != 1 || back->second != 1) ++misoriented;
  }
  EXPECT_EQ(free_edges, static_cast<long>(2 * 2 * na));  // the two rims of each band
  EXPECT_EQ(misoriented, 0);
  // STEP: two B-spline faces; their area against the grid's triangles (chordal, slightly less).
  double mesh_area = 0.0;
  for (const auto& grid : res.surface_points)
    for (size_t i = 0; i < na; ++i)
      for (size_t m = 0; m + 1 < nl; ++m) {
        const auto& a = grid[i][m];
        const auto& b = grid[(i + 1) % na][m];
        const auto& c = grid[(i + 1) % na][m + 1];
        const auto& d = grid[i][m + 1];
        mesh_area += 0.5 * ((b - a).cross(c - a)).norm() + 0.5 * ((c - a).cross(d - a)).norm();
      }
  const cad::StepReadBack back = cad::ReadStep(out.files().at("working_surfaces.step"));
  EXPECT_EQ(back.faces, 2);
  EXPECT_EQ(back.solids, 0);
  EXPECT_NEAR(back.area_mm2 / mesh_area - 1, 0.0, 1e-3);
  // The approximated surfaces within the 1 µm tolerance of every grid point (OCCT's projection of
  // each point on the faces read back), in a fifth of the interpolation's file.
  std::vector<Eigen::Vector3d> grid_points;
  for (const auto& grid : res.surface_points)
    for (const auto& row : grid)
      for (const auto& p : row) grid_points.emplace_back(p.x(), p.y(), p.z());
  const double far = cad::MaxDistanceToStepFaces(out.files().at("working_surfaces.step"), grid_points);
  std::printf("globoidal surfaces: %zu grid points within %.4f um of the STEP faces; %zu bytes\n",
              grid_points.size(), far * 1e3, out.files().at("working_surfaces.step").size());
  EXPECT_LE(far, 1e-3 * (1 + 1e-6));
  EXPECT_LT(out.files().at("working_surfaces.step").size(), 200000u);
  std::printf("globoidal: STEP surface area %.3f mm², grid triangles %.3f mm² (rel. diff %.2e)\n", back.area_mm2,
              mesh_area, back.area_mm2 / mesh_area - 1);
}

// The kernel's half is a module opened on first use (cad/solid.cc): the program does not load
// OpenCASCADE's libraries to start, the build's program finds the module beside it and writes the
// globoidal cam's B-spline surfaces, and a copy of the program without it fails with a message
// that names the module and where it was looked for, writing no folder.
TEST(GeometryFiles, OcctIsAModuleFoundBesideTheProgramAndNamedWhenMissing) {
  const auto dir = camopt::testing::TempDir("occt-module");
  const std::string ldd = dir.string() + "/ldd.txt";
  ASSERT_EQ(std::system(("ldd " + std::string(CAMOPT_BINARY) + " > " + ldd).c_str()), 0);
  const std::string libraries = ReadFile(ldd);
  EXPECT_NE(libraries.find("libc.so"), std::string::npos) << libraries;
  EXPECT_EQ(libraries.find("libTK"), std::string::npos) << libraries;

  const std::string study = SourcePath("studies/examples/globoidal_cam_paper.json");
  const camopt::testing::CliResult built =
      camopt::testing::RunCamopt("run " + study + " --quiet --out " + (dir / "built").string());
  ASSERT_EQ(built.exit_code, 0) << built.stderr_text;
  EXPECT_GT(std::filesystem::file_size(dir / "built" / "working_surfaces.step"), 1000u);

  const auto alone = dir / "alone";
  std::filesystem::create_directories(alone);
  std::filesystem::copy_file(CAMOPT_BINARY, alone / "camopt");
  const std::string err = (dir / "alone.txt").string();
  const int status = std::system(((alone / "camopt").string() + " run " + study + " --quiet --out " +
                                  (alone / "out").string() + " 2> " + err).c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_NE(WEXITSTATUS(status), 0);
  const std::string message = ReadFile(err);
  EXPECT_NE(message.find("libcamopt_occt.so"), std::string::npos) << message;
  EXPECT_NE(message.find((alone / "libcamopt_occt.so").lexically_normal().string()), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists(alone / "out"));
}

}  // namespace cad_test
}  // namespace camopt
