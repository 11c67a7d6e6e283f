// Motion-law library: boundary values, derivatives against central differences, textbook peak
// coefficients, continuity at segment joints, and program checks.
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "model/motion/motion_law.h"
#include "model/motion/motion_program.h"
#include "tests/test_util.h"

namespace camopt::motion {
namespace motion_test {

const MotionLaw kRiseLaws[] = {MotionLaw::kCycloidal,         MotionLaw::kSimpleHarmonic,
                               MotionLaw::kModifiedSine,      MotionLaw::kModifiedTrapezoid,
                               MotionLaw::kPolynomial345,     MotionLaw::kPolynomial4567,
                               MotionLaw::kQuadraticParabola};

struct Peaks {
  double cv, ca, cj;
};

Peaks SampledPeaks(MotionLaw law) {
  Peaks p{0, 0, 0};
  for (int k = 0; k <= 200000; ++k) {
    const Svaj<double> n = NormalizedLaw(law, k / 200000.0);
    p.cv = std::max(p.cv, std::abs(n.v));
    p.ca = std::max(p.ca, std::abs(n.a));
    p.cj = std::max(p.cj, std::abs(n.j));
  }
  return p;
}

TEST(MotionLaw, RisesFromZeroToOneWithZeroEndVelocity) {
  for (MotionLaw law : kRiseLaws) {
    const Svaj<double> a = NormalizedLaw(law, 0.0), b = NormalizedLaw(law, 1.0);
    EXPECT_NEAR(a.s, 0.0, 1e-14) << LawName(law);
    EXPECT_NEAR(b.s, 1.0, 1e-14) << LawName(law);
    EXPECT_NEAR(a.v, 0.0, 1e-13) << LawName(law);
    EXPECT_NEAR(b.v, 0.0, 1e-13) << LawName(law);
    // Symmetric laws pass the half rise at mid-time.
    EXPECT_NEAR(NormalizedLaw(law, 0.5).s, 0.5, 1e-14) << LawName(law);
  }
}

TEST(MotionLaw, DerivativesMatchCentralDifferences) {
  const double h = 1e-5;
  for (MotionLaw law : kRiseLaws) {
    for (double u = 0.01; u < 1.0; u += 0.0173) {
      const Svaj<double> n = NormalizedLaw(law, u), p = NormalizedLaw(law, u + h),
                         m = NormalizedLaw(law, u - h);
      EXPECT_NEAR(n.v, (p.s - m.s) / (2 * h), 1e-7) << LawName(law) << " u=" << u;
      EXPECT_NEAR(n.a, (p.v - m.v) / (2 * h), 1e-6) << LawName(law) << " u=" << u;
      // The modified trapezoid's jerk jumps at its piece joints (u = k/8): skip those.
      if (std::abs(u * 8 - std::round(u * 8)) > 1e-3) {
        EXPECT_NEAR(n.j, (p.a - m.a) / (2 * h), 1e-4) << LawName(law) << " u=" << u;
      }
    }
  }
}

double Poly4567PeakAcceleration() {
  const double u = (5.0 - std::sqrt(5.0)) / 10.0;
  return 420.0 * u * u * (1 - u) * (1 - u) * (1 - 2 * u);
}

TEST(MotionLaw, PeakCoefficientsAreTheTextbookValues) {
  // Norton, Cam Design and Manufacturing Handbook, Table 3-2 (and closed forms where they exist).
  const double pi = kPi;
  struct Row {
    MotionLaw law;
    double cv, ca, cj;  // cj < 0: not compared (infinite or undefined at the ends)
  };
  const Row rows[] = {
      {MotionLaw::kCycloidal, 2.0, 2 * pi, 4 * pi * pi},
      {MotionLaw::kSimpleHarmonic, pi / 2, pi * pi / 2, -1},
      {MotionLaw::kModifiedSine, 1.7596, 5.5280, 69.466},
      {MotionLaw::kModifiedTrapezoid, 2.0, 4.8881, 61.426},
      {MotionLaw::kPolynomial345, 1.875, 10.0 / std::sqrt(3.0), 60.0},
      // Peak acceleration at the jerk root u* = (5 − √5)/10: 420u*²(1 − u*)²(1 − 2u*) ≈ 7.5132.
      {MotionLaw::kPolynomial4567, 2.1875, Poly4567PeakAcceleration(), 52.5},
  };
  for (const Row& r : rows) {
    const Peaks p = SampledPeaks(r.law);
    EXPECT_NEAR(p.cv, r.cv, 1e-4) << LawName(r.law);
    EXPECT_NEAR(p.ca, r.ca, 1e-4) << LawName(r.law);
    if (r.cj > 0) {
      EXPECT_NEAR(p.cj, r.cj, 2e-3) << LawName(r.law);
    }
  }
  EXPECT_NEAR(SampledPeaks(MotionLaw::kModifiedSine).ca, 4 * pi * pi / (4 + pi), 1e-9);
  EXPECT_NEAR(SampledPeaks(MotionLaw::kModifiedTrapezoid).ca, 8 * pi / (2 + pi), 1e-9);
}

// The quadratic parabola written out here: s = 2u² up to the middle, 1 − 2(1 − u)² after.
TEST(MotionLaw, QuadraticParabolaIsTheConstantAccelerationLaw) {
  for (double u = 0.0; u <= 1.0; u += 1.0 / 64) {
    const Svaj<double> n = NormalizedLaw(MotionLaw::kQuadraticParabola, u);
    const double s = u <= 0.5 ? 2 * u * u : 1 - 2 * (1 - u) * (1 - u);
    EXPECT_NEAR(n.s, s, 1e-15) << u;
    EXPECT_NEAR(n.a, u <= 0.5 ? 4.0 : -4.0, 0.0) << u;
  }
  // v continuous at the middle (2 from both sides), a jumps by 8 there: C¹ inside the law.
  const double eps = 1e-12;
  EXPECT_NEAR(NormalizedLaw(MotionLaw::kQuadraticParabola, 0.5 - eps).v, 2.0, 1e-11);
  EXPECT_NEAR(NormalizedLaw(MotionLaw::kQuadraticParabola, 0.5 + eps).v, 2.0, 1e-11);
}

// The characteristic values the library states (Characteristics) against the sampled maxima of
// the law itself and against the values VDI 2143 Blatt 1 and Norton's Table 3-2 print (3-4
// significant digits there: compared to 5e-4).
TEST(MotionLaw, StatedCharacteristicValuesAreTheSampledAndPublishedOnes) {
  const double inf = std::numeric_limits<double>::infinity();
  struct Row {
    MotionLaw law;
    double cv, ca, cj;  // published; inf: the acceleration jumps
  };
  const Row rows[] = {
      {MotionLaw::kQuadraticParabola, 2.0, 4.0, inf},     {MotionLaw::kSimpleHarmonic, 1.571, 4.935, inf},
      {MotionLaw::kPolynomial345, 1.875, 5.774, 60.0},    {MotionLaw::kCycloidal, 2.0, 6.283, 39.48},
      {MotionLaw::kModifiedTrapezoid, 2.0, 4.888, 61.43}, {MotionLaw::kModifiedSine, 1.760, 5.528, 69.47},
      {MotionLaw::kPolynomial4567, 2.1875, 7.513, 52.5},
  };
  for (const Row& r : rows) {
    const auto c = Characteristics(r.law);
    ASSERT_TRUE(c.has_value()) << LawName(r.law);
    const Peaks p = SampledPeaks(r.law);
    EXPECT_NEAR(c->cv, p.cv, 1e-8) << LawName(r.law);
    EXPECT_NEAR(c->ca, p.ca, 1e-8) << LawName(r.law);
    EXPECT_NEAR(c->cv, r.cv, 5e-4) << LawName(r.law);
    EXPECT_NEAR(c->ca, r.ca, 5e-4) << LawName(r.law);
    if (std::isinf(r.cj)) {
      EXPECT_TRUE(std::isinf(c->cj)) << LawName(r.law);
      // Infinite: the acceleration jumps at the start (against a dwell: a(0) ≠ 0).
      EXPECT_GT(std::abs(NormalizedLaw(r.law, 0.0).a), 1.0) << LawName(r.law);
    } else {
      EXPECT_NEAR(c->cj, p.cj, 1e-6 * r.cj) << LawName(r.law);
      EXPECT_NEAR(c->cj, r.cj, 5e-3) << LawName(r.law);
    }
  }
  for (MotionLaw law : {MotionLaw::kDwell, MotionLaw::kPolynomial, MotionLaw::kBSpline})
    EXPECT_FALSE(Characteristics(law).has_value()) << LawName(law);
}

TEST(MotionLaw, PiecewiseLawsAreC2InsideTheSegment) {
  // Modified sine and modified trapezoid are built from pieces: s, v, a continuous at u = k/8.
  for (MotionLaw law : {MotionLaw::kModifiedSine, MotionLaw::kModifiedTrapezoid}) {
    for (int k = 1; k < 8; ++k) {
      const double u = k / 8.0, eps = 1e-12;
      const Svaj<double> a = NormalizedLaw(law, u - eps), b = NormalizedLaw(law, u + eps);
      EXPECT_NEAR(a.s, b.s, 1e-11) << LawName(law) << " k=" << k;
      EXPECT_NEAR(a.v, b.v, 1e-10) << LawName(law) << " k=" << k;
      EXPECT_NEAR(a.a, b.a, 1e-9) << LawName(law) << " k=" << k;
    }
  }
}

TEST(MotionLaw, NamesRoundTrip) {
  for (const std::string& name : LawNames()) {
    const auto law = LawFromName(name);
    ASSERT_TRUE(law.has_value()) << name;
    EXPECT_EQ(LawName(*law), name);
  }
  EXPECT_FALSE(LawFromName("parabolic").has_value());
}

MotionProgram<double> DoubleDwell(MotionLaw law) {
  const double d = kPi / 180;
  return MotionProgram<double>({{law, 24.0, 120 * d},
                                {MotionLaw::kDwell, 0.0, 50 * d},
                                {law, -24.0, 120 * d},
                                {MotionLaw::kDwell, 0.0, 70 * d}});
}

TEST(MotionProgram, ScalesTheLawToRiseAndDuration) {
  const auto prog = DoubleDwell(MotionLaw::kCycloidal);
  const double b = 120 * kPi / 180;
  // Mid-rise: S = h/2, S' = Cv h/β with Cv = 2; mid-return likewise with negative sign.
  const Svaj<double> mid = prog.Evaluate(60 * kPi / 180);
  EXPECT_NEAR(mid.s, 12.0, 1e-12);
  EXPECT_NEAR(mid.v, 2 * 24 / b, 1e-12);
  const Svaj<double> quarter = prog.Evaluate(30 * kPi / 180);
  EXPECT_NEAR(quarter.a, 2 * kPi * 24 / (b * b), 1e-10);  // Ca h/β² at u = 1/4
  EXPECT_NEAR(prog.Evaluate(145 * kPi / 180).s, 24.0, 1e-12);
  EXPECT_NEAR(prog.Evaluate(230 * kPi / 180).s, 12.0, 1e-12);
  EXPECT_NEAR(prog.Evaluate(230 * kPi / 180).v, -2 * 24 / b, 1e-12);
  EXPECT_NEAR(prog.Evaluate(330 * kPi / 180).s, 0.0, 1e-12);
  // Periodic.
  EXPECT_NEAR(prog.Evaluate(60 * kPi / 180 + 2 * kPi).s, 12.0, 1e-11);
  EXPECT_NEAR(prog.Evaluate(60 * kPi / 180 - 4 * kPi).s, 12.0, 1e-11);
}

TEST(MotionProgram, IndexingProgramAccumulatesItsNetRise) {
  // A globoidal turret indexes: the rise does not return, each cycle adds it.
  const double d = kPi / 180;
  MotionProgram<double> prog({{MotionLaw::kModifiedSine, 45 * d, 120 * d},
                              {MotionLaw::kDwell, 0.0, 240 * d}});
  EXPECT_NEAR(prog.Evaluate(2 * kPi + 60 * d).s, 45 * d + 22.5 * d, 1e-12);
  EXPECT_FALSE(CheckProgram(prog, 2 * kPi, /*must_return=*/false).has_value());
  EXPECT_TRUE(CheckProgram(prog, 2 * kPi, /*must_return=*/true).has_value());
  for (const auto& j : CheckContinuity(prog)) EXPECT_GE(j.order, 2) << "joint " << j.segment;
}

TEST(MotionProgram, ContinuityAtJoints) {
  // Cycloidal, modified sine/trapezoid, 3-4-5 and 4-5-6-7 against dwells: C² at every joint
  // (4-5-6-7 even C³); simple harmonic: the acceleration jumps (C¹ only).
  for (MotionLaw law : {MotionLaw::kCycloidal, MotionLaw::kModifiedSine,
                        MotionLaw::kModifiedTrapezoid, MotionLaw::kPolynomial345,
                        MotionLaw::kPolynomial4567}) {
    const auto joints = CheckContinuity(DoubleDwell(law));
    ASSERT_EQ(joints.size(), 4u);
    for (const auto& j : joints) EXPECT_GE(j.order, 2) << LawName(law) << " joint " << j.segment;
    for (const auto& j : joints) {
      if (law == MotionLaw::kPolynomial4567) {
        EXPECT_EQ(j.order, 3);
      }
      if (law == MotionLaw::kPolynomial345) {
        EXPECT_EQ(j.order, 2);  // jerk 60 h/β³ jumps to 0
      }
    }
  }
  const auto shm = CheckContinuity(DoubleDwell(MotionLaw::kSimpleHarmonic));
  for (const auto& j : shm) {
    EXPECT_EQ(j.order, 1);
    EXPECT_NEAR(j.jump_a, kPi * kPi / 2 * 24 / std::pow(120 * kPi / 180, 2), 1e-9);
  }
  // An indexing program (no return) wraps into the next cycle, which starts at the net rise.
  const double d = kPi / 180;
  MotionProgram<double> open({{MotionLaw::kCycloidal, 10.0, 180 * d},
                              {MotionLaw::kDwell, 0.0, 180 * d}});
  EXPECT_EQ(CheckContinuity(open).back().order, 2);  // wraps to the next (indexing) cycle
}

TEST(MotionProgram, RejectsBadPrograms) {
  const double d = kPi / 180;
  EXPECT_FALSE(CheckProgram(DoubleDwell(MotionLaw::kCycloidal), 2 * kPi, true).has_value());
  {
    MotionProgram<double> p({{MotionLaw::kCycloidal, 24.0, 120 * d},
                             {MotionLaw::kCycloidal, -24.0, 120 * d},
                             {MotionLaw::kDwell, 0.0, 100 * d}});
    const auto issue = CheckProgram(p, 2 * kPi, true);
    ASSERT_TRUE(issue.has_value());
    EXPECT_EQ(issue->segment, -1);
    EXPECT_NE(issue->message.find("sum to 340"), std::string::npos) << issue->message;
  }
  {
    MotionProgram<double> p({{MotionLaw::kCycloidal, 24.0, 180 * d},
                             {MotionLaw::kCycloidal, -20.0, 180 * d}});
    const auto issue = CheckProgram(p, 2 * kPi, true);
    ASSERT_TRUE(issue.has_value());
    EXPECT_NE(issue->message.find("does not return"), std::string::npos) << issue->message;
  }
  {
    MotionProgram<double> p({{MotionLaw::kDwell, 3.0, 360 * d}});
    const auto issue = CheckProgram(p, 2 * kPi, true);
    ASSERT_TRUE(issue.has_value());
    EXPECT_EQ(issue->segment, 0);
    EXPECT_EQ(issue->field, "rise");
  }
  {
    MotionProgram<double> p({{MotionLaw::kCycloidal, 5.0, -10 * d},
                             {MotionLaw::kCycloidal, -5.0, 370 * d}});
    const auto issue = CheckProgram(p, 2 * kPi, true);
    ASSERT_TRUE(issue.has_value());
    EXPECT_EQ(issue->segment, 0);
    EXPECT_EQ(issue->field, "cam_angle_deg");
  }
}

TEST(MotionProgram, DerivativesWithRespectToRiseAndDurationMatchCentralDifferences) {
  // Outputs S, S', S'' at fixed cam angles as functions of (rise, rise duration, dwell duration).
  auto f = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    const T dwell2 = T(2 * kPi) - x[1] * T(2.0) - x[2];
    MotionProgram<T> p({{MotionLaw::kModifiedSine, x[0], x[1]},
                        {MotionLaw::kDwell, T(0.0), x[2]},
                        {MotionLaw::kPolynomial4567, -x[0], x[1]},
                        {MotionLaw::kDwell, T(0.0), dwell2}});
    std::vector<T> out;
    for (double th : {0.3, 1.1, 2.5, 3.7, 5.9}) {
      const Svaj<T> m = p.Evaluate(T(th));
      out.insert(out.end(), {m.s, m.v, m.a});
    }
    return out;
  };
  camopt::testing::ExpectJacobianMatchesCentralDifferences<3>(f, {24.0, 2.0, 0.9}, 1e-6, 1e-7);
}

// General polynomial segments (PolynomialThrough). The issue's check: three 5th-order segments
// with (θ, S, S', S'') = (0°, 0, 0, 0), (120°, 120, 1, 0), (240°, 240, 1, 0), (360°, 360, 0, 0),
// S' per degree: each reproduces its boundary values to 1e-12, the program is C² at every joint,
// and the middle segment is exactly the straight line S = θ (constant velocity, no acceleration).
TEST(MotionPolynomial, DwellConstantVelocityDwellThroughFifthOrderSegments) {
  const double d = kPi / 180;
  const double v = 1.0 / d;  // 1 per degree, in per rad
  using B = BoundaryState<double>;
  const B p0{0.0, {0.0, 0.0}}, p1{120.0, {v, 0.0}}, p2{240.0, {v, 0.0}}, p3{360.0, {0.0, 0.0}};
  const MotionSegment<double> a = PolynomialThrough(p0, p1, 120 * d), b = PolynomialThrough(p1, p2, 120 * d),
                              c = PolynomialThrough(p2, p3, 120 * d);
  EXPECT_EQ(a.coefficients.size(), 5u);  // c₁ … c₅: degree 5
  const MotionProgram<double> prog({a, b, c});
  const B* ends[4] = {&p0, &p1, &p2, &p3};
  for (int k = 0; k < 3; ++k) {
    for (int side = 0; side < 2; ++side) {
      // Just inside the segment (the program picks the segment on θ), and at its exact ends
      // through the segment's own shape.
      const MotionSegment<double>& seg = k == 0 ? a : k == 1 ? b : c;
      const Svaj<double> sh = MotionSegmentShape(seg, double(side));
      const B& want = *ends[k + side];
      const double b1 = seg.duration;
      EXPECT_NEAR(ends[k]->position + sh.s, want.position, 1e-12) << k << side;
      EXPECT_NEAR(sh.v / b1, want.derivatives[0], 1e-12) << k << side;
      EXPECT_NEAR(sh.a / (b1 * b1), want.derivatives[1], 1e-12) << k << side;
    }
  }
  // The middle segment: S = θ in degrees, S' = 1/deg, S'' = 0 everywhere on it.
  for (double deg = 120; deg < 240; deg += 0.7) {
    const Svaj<double> s = prog.Evaluate(deg * d);
    EXPECT_NEAR(s.s, deg, 1e-12 * 240);
    EXPECT_NEAR(s.v, v, 1e-12 * v);
    EXPECT_NEAR(s.a, 0.0, 1e-12 * v);
    EXPECT_NEAR(s.j, 0.0, 1e-12 * v);
  }
  // The first segment by hand: P(0) = P'(0) = P''(0) = 0 leave c₃u³ + c₄u⁴ + c₅u⁵ with
  // c₃ + c₄ + c₅ = 120 (S), 3c₃ + 4c₄ + 5c₅ = 120 (S'β = 1/deg × 120°), 6c₃ + 12c₄ + 20c₅ = 0:
  // c₃ = 720, c₄ = −960, c₅ = 360, and S(60°) = P(1/2) = 90 − 60 + 11.25 = 41.25.
  const auto& co = a.coefficients;
  EXPECT_NEAR(co[0], 0.0, 1e-12);
  EXPECT_NEAR(co[1], 0.0, 1e-12);
  EXPECT_NEAR(co[2], 720.0, 1e-10);
  EXPECT_NEAR(co[3], -960.0, 1e-10);
  EXPECT_NEAR(co[4], 360.0, 1e-10);
  EXPECT_NEAR(prog.Evaluate(60 * d).s, 41.25, 1e-12);
  // C² at the two inner joints and at the wrap-around (the next cycle starts at the net rise 360).
  for (const auto& j : CheckContinuity(prog)) EXPECT_GE(j.order, 2) << "joint " << j.segment;
}

// Degrees 3 and 7: position and velocity at both ends give a cubic, with acceleration and jerk a
// 7th-order polynomial; both pass through every given value (to 1e-12 of its size), also with
// unequal numbers of conditions at the two ends (degree 4) and a segment that returns to its start.
TEST(MotionPolynomial, EveryDegreeReproducesItsBoundaryValues) {
  using B = BoundaryState<double>;
  struct Case {
    B start, end;
    double beta;
    size_t coefficients;
  };
  const Case cases[] = {{{0.0, {0.3}}, {5.0, {-0.2}}, 1.1, 3},
                        {{1.0, {0.5, -2.0, 10.0}}, {-3.0, {1.0, 4.0, -20.0}}, 0.7, 7},
                        {{2.0, {0.0, 1.0}}, {4.0, {3.0}}, 2.0, 4},
                        {{2.0, {1.0}}, {2.0, {-1.0}}, 1.5, 3}};
  for (const Case& c : cases) {
    const MotionSegment<double> seg = PolynomialThrough(c.start, c.end, c.beta);
    ASSERT_EQ(seg.coefficients.size(), c.coefficients);
    EXPECT_NEAR(seg.rise, c.end.position - c.start.position, 1e-15);
    for (int side = 0; side < 2; ++side) {
      const B& want = side == 0 ? c.start : c.end;
      const Svaj<double> sh = MotionSegmentShape(seg, double(side));
      EXPECT_NEAR(c.start.position + sh.s, want.position, 1e-12 * std::max(1.0, std::abs(want.position)));
      const double got[3] = {sh.v / c.beta, sh.a / (c.beta * c.beta), sh.j / (c.beta * c.beta * c.beta)};
      for (size_t k = 0; k < want.derivatives.size(); ++k)
        EXPECT_NEAR(got[k], want.derivatives[k], 1e-12 * std::max(1.0, std::abs(want.derivatives[k])))
            << "degree " << c.coefficients << " side " << side << " derivative " << k + 1;
    }
  }
  // A polynomial returning to its start is a moving segment without a net rise: accepted.
  const MotionSegment<double> back = PolynomialThrough(cases[3].start, cases[3].end, cases[3].beta);
  const MotionSegment<double> rest{MotionLaw::kDwell, 0.0, 2 * kPi - 1.5};
  EXPECT_FALSE(CheckProgram(MotionProgram<double>({back, rest}), 2 * kPi, true).has_value());
}

// B-spline segments (de Boor, A Practical Guide to Splines): with as many control values as the
// degree + 1 (no interior knot) the clamped B-spline is the Bézier curve, Σ C(p,i) uᶦ(1−u)ᵖ⁻ⁱ cᵢ,
// written out here with its derivatives from the Bernstein form's difference rule.
TEST(MotionBSpline, WithoutInteriorKnotsItIsTheBezierCurve) {
  const std::vector<double> c = {0.0, 1.0, 4.0, -2.0, 7.0, 10.0};  // degree 5
  const int p = 5;
  const MotionSegment<double> seg = BSplineThrough(c, p, 2.0);
  EXPECT_EQ(seg.rise, 10.0);
  auto binom = [](int n, int k) {
    double r = 1;
    for (int j = 1; j <= k; ++j) r = r * (n - k + j) / j;
    return r;
  };
  // The r-th derivative of a Bézier curve of degree p: p!/(p−r)! Σ Δʳcᵢ B_{i,p−r}(u).
  auto bezier = [&](std::vector<double> d, int r, double u) {
    double scale = 1;
    for (int k = 0; k < r; ++k) {
      for (size_t i = 0; i + 1 < d.size(); ++i) d[i] = d[i + 1] - d[i];
      d.pop_back();
      scale *= p - k;
    }
    const int q = p - r;
    double sum = 0;
    for (int i = 0; i <= q; ++i) sum += binom(q, i) * std::pow(u, i) * std::pow(1 - u, q - i) * d[size_t(i)];
    return scale * sum;
  };
  for (double u : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    const Svaj<double> q = MotionSegmentShape(seg, u);
    EXPECT_NEAR(q.s, bezier(c, 0, u), 1e-12) << u;
    EXPECT_NEAR(q.v, bezier(c, 1, u), 1e-11) << u;
    EXPECT_NEAR(q.a, bezier(c, 2, u), 1e-10) << u;
    EXPECT_NEAR(q.j, bezier(c, 3, u), 1e-9) << u;
  }
}

// Degree 1 on uniform knots interpolates its control values at the knots i/n; a general one
// (8 values, degree 5: two interior knots) starts and ends at its first and last values, tangent to
// the control polygon (S'(0) = p (c₁ − c₀)/t_{p+1}, t_{p+1} = 1/(n − p + 1)), its derivatives
// agree with central differences of the one below across the interior knots, and three repeated
// values at each end make S' and S'' zero there (the dwell-to-dwell rise a designer draws).
TEST(MotionBSpline, InterpolationTangencyAndDerivatives) {
  const std::vector<double> lin = {0.0, 2.0, 3.0, 7.0, 5.0};
  const MotionSegment<double> l = BSplineThrough(lin, 1, 1.0);
  for (size_t i = 0; i < lin.size(); ++i)
    EXPECT_NEAR(MotionSegmentShape(l, double(i) / 4.0).s, lin[i], 1e-12) << i;
  const std::vector<double> c = {0.0, 0.0, 0.0, 5.0, 15.0, 20.0, 20.0, 20.0};
  const int p = 5, n = 7;
  const MotionSegment<double> seg = BSplineThrough(c, p, 1.0);
  const Svaj<double> start = MotionSegmentShape(seg, 0.0), end = MotionSegmentShape(seg, 1.0);
  EXPECT_NEAR(start.s, 0.0, 1e-12);
  EXPECT_NEAR(end.s, 20.0, 1e-12);
  for (const Svaj<double>& q : {start, end}) {
    EXPECT_NEAR(q.v, 0.0, 1e-10);
    EXPECT_NEAR(q.a, 0.0, 1e-9);
  }
  const std::vector<double> tilted = {0.0, 1.0, 0.0, 5.0, 15.0, 20.0, 20.0, 20.0};
  EXPECT_NEAR(MotionSegmentShape(BSplineThrough(tilted, p, 1.0), 0.0).v, p * 1.0 * (n - p + 1), 1e-10);
  const double h = 1e-5;
  for (double u : {0.05, 1.0 / 3.0, 0.4, 2.0 / 3.0, 0.9}) {  // 1/3 and 2/3 are the interior knots
    const Svaj<double> q = MotionSegmentShape(seg, u), lo = MotionSegmentShape(seg, u - h),
                       hi = MotionSegmentShape(seg, u + h);
    EXPECT_NEAR(q.v, (hi.s - lo.s) / (2 * h), 1e-6 * std::max(1.0, std::abs(q.v))) << u;
    EXPECT_NEAR(q.a, (hi.v - lo.v) / (2 * h), 1e-5 * std::max(1.0, std::abs(q.a))) << u;
    EXPECT_NEAR(q.j, (hi.a - lo.a) / (2 * h), 1e-4 * std::max(1.0, std::abs(q.j))) << u;
  }
  // A degree-5 spline is C⁴ across its simple interior knots: the jerk is continuous there.
  EXPECT_NEAR(MotionSegmentShape(seg, 1.0 / 3.0 - 1e-9).j, MotionSegmentShape(seg, 1.0 / 3.0 + 1e-9).j, 1e-4);
}

}  // namespace motion_test
}  // namespace camopt::motion
