// Tests of the geometric limits of a cycloid stage (model/cycloid/geometry_limits.h): the closed
// forms against the published case, against curves sampled and measured without any derivative
// (circles through three neighbouring points), their Jet gradients against central differences,
// and the rejection of designs that are not drives.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "model/cycloid/geometry_limits.h"
#include "model/cycloid/tooth_profile.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt::cycloid {
namespace cycloid_geometry_limits_test {

// A 3-point circle on points ~1e-3 mm apart is exact to O(h²) and loses ~1e-7 to rounding; the
// sampled maximum is biased by |κ''| h²/8 ~ 1e-9 relative. Radii of 0.5–20 mm: 1e-5 mm is ample.
constexpr double kThreePointTolMm = 1e-5;
// Points per tooth for the sampled curves.
constexpr int kSamplesPerTooth = 20000;
// Closed form against the same closed form written another way (rounding only).
constexpr double kClosedFormTol = 1e-12;
// AD against central differences (step ∛ε·max(1,|x|), truncation ~ε^{2/3}·|f'''|): smooth points.
constexpr double kGradRelTol = 1e-6;
constexpr double kGradAbsTol = 1e-8;
// Straddling the tip/flank switch λ_s the margin is C¹ but not C²: the central difference is off
// by ~h·|jump of f''| ~ 1e-5 there (h ~ 6e-6 mm, f'' ~ N²/a ~ 10 /mm; observed 6e-6 relative).
constexpr double kGradAtSwitchRelTol = 1e-4;
// The two branches' Jet slopes a hair either side of the switch (1e-9 in λ apart): C¹ means equal.
constexpr double kSlopeJoinRelTol = 1e-7;

// The published rigid-body case (docs/cycloid.md): 18 pins, 17 lobes, R 42.5, e 1.3, r 2.5 mm.
Drive PublishedDrive() {
  Drive d;
  d.teeth = 17;
  d.rollers = 18;
  d.roller_position_radius_mm = 42.5;
  d.eccentricity_mm = 1.3;
  d.roller_radius_mm = 2.5;
  return d;
}

// The drive with e set so that λ = e N / a' takes the given value.
Drive WithRatio(Drive d, double lambda) {
  d.eccentricity_mm = lambda * (d.roller_position_radius_mm + d.delta_position_mm) / d.rollers;
  return d;
}

// Signed curvature of the circle through three points [1/mm], > 0 for a left (counter-clockwise)
// turn: 2 (b − a) × (c − b) / (|b − a| |c − b| |c − a|). No derivative of the curve is used.
double ThreePointCurvature(const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c) {
  const Vec2<double> ab = b - a, bc = c - b, ac = c - a;
  return 2.0 * Cross(ab, bc) / (ab.norm() * bc.norm() * ac.norm());
}

struct SampledExtreme {
  double min_convex_radius_mm;  // 1 / (largest 3-point curvature)
  double phase_rad;             // where, folded into [0, π/(N − 1)]
};

// Smallest convex radius of a closed counter-clockwise curve sampled over one tooth [0, 2π/z].
template <typename Curve>
SampledExtreme SampledMinConvexRadius(const Drive& d, const Curve& curve) {
  const double period = 2.0 * kPi / d.teeth, h = period / kSamplesPerTooth;
  double best = -kInf, where = 0.0;
  for (int k = 0; k < kSamplesPerTooth; ++k) {
    const double t = k * h;
    const double kappa = ThreePointCurvature(curve(t - h), curve(t), curve(t + h));
    if (kappa > best) best = kappa, where = t;
  }
  // Fold into [0, π/(N − 1)]: κ depends on cos((N − 1) t) only.
  const double psi = std::remainder(d.teeth * where, 2.0 * kPi);
  return {1.0 / best, std::abs(psi) / d.teeth};
}

// The generating curve written out from its definition (docs/cycloid.md) with a' = a + Δa: no shared code.
Vec2<double> CentreCurvePoint(const Drive& d, double phi) {
  const double a = d.roller_position_radius_mm + d.delta_position_mm, e = d.eccentricity_mm;
  const int n = d.rollers;
  return {a * std::cos(phi) - e * std::cos(n * phi), a * std::sin(phi) - e * std::sin(n * phi)};
}

TEST(CycloidGeometryLimits, PublishedCaseSmallestConvexProfileRadius) {
  const Drive d = PublishedDrive();
  // Design-notes §4: smallest convex profile radius 6.678 mm (3 decimals quoted).
  EXPECT_NEAR(MinConvexProfileRadius(d), 6.678, 1e-3);
  EXPECT_NEAR(UndercutMargin(d), 6.678, 1e-3);
  EXPECT_NEAR(UndercutMargin(d, 1.0), 5.678, 1e-3);
  // λ = 0.5506 > λ_s = 16/35: the sharpest point is on the flank, ψ* = arccos(−0.5152).
  const double lambda = 1.3 * 18 / 42.5;
  const double c = (35.0 * lambda * lambda - 16.0) / (19.0 * lambda);
  EXPECT_NEAR(CosAtMinConvexRadius(d), c, kClosedFormTol);
  EXPECT_GT(c, -1.0);
  // (C3) is (C1) at (C2): the curvature at φ* written directly.
  EXPECT_NEAR(MinConvexCentreRadius(d), 1.0 / CentreCurvature(d, PhaseAtMinConvexRadius(d)),
              kClosedFormTol);
  std::printf("published case: rho_min(X) %.6f mm, profile %.6f mm, lambda %.6f, cos psi* %.6f\n",
              MinConvexCentreRadius(d), MinConvexProfileRadius(d), lambda, c);
}

TEST(CycloidGeometryLimits, CurvatureClosedFormEqualsToothProfile) {
  // (C1) against the curvature ToothProfile computes from X' and X'' (modified tooth included).
  for (const Drive& d : {PublishedDrive(), camopt::testing::CycloidNnm()}) {
    for (int k = 0; k <= 50; ++k) {
      const double t = 2.0 * kPi / d.teeth * k / 50.0 + 0.01;
      const double ours = CentreCurvature(d, t), theirs = ToothProfile(d, t).centre_curvature;
      EXPECT_NEAR(ours, theirs, kClosedFormTol * std::max(1.0, std::abs(theirs))) << "t " << t;
    }
  }
}

// Drives on each branch of the closed form: flank (C3), tip (C4), near the switch, near the
// undercut boundary, near the curtate limit, and with a large profile modification.
std::vector<std::pair<std::string, Drive>> SampledCases() {
  std::vector<std::pair<std::string, Drive>> cases;
  cases.push_back({"published", PublishedDrive()});
  cases.push_back({"paper NNM", camopt::testing::CycloidNnm()});
  const double lambda_s = 16.0 / 35.0;
  cases.push_back({"tip branch", WithRatio(PublishedDrive(), 0.3)});
  cases.push_back({"below switch", WithRatio(PublishedDrive(), lambda_s - 1e-3)});
  cases.push_back({"above switch", WithRatio(PublishedDrive(), lambda_s + 1e-3)});
  cases.push_back({"near curtate", WithRatio(PublishedDrive(), 0.99)});
  Drive modified = PublishedDrive();
  modified.delta_position_mm = -0.4;
  modified.delta_radius_mm = 0.3;
  cases.push_back({"large modification", modified});
  Drive small_z = PublishedDrive();
  small_z.teeth = 3;
  small_z.rollers = 4;
  small_z.roller_position_radius_mm = 20.0;
  small_z.eccentricity_mm = 3.0;  // λ = 0.6 > λ_s = 2/7
  small_z.roller_radius_mm = 1.0;
  cases.push_back({"z = 3", small_z});
  return cases;
}

TEST(CycloidGeometryLimits, CentreCurveRadiusMatchesThreePointCircles) {
  for (const auto& [name, d] : SampledCases()) {
    const SampledExtreme s =
        SampledMinConvexRadius(d, [&drive = d](double t) { return CentreCurvePoint(drive, t); });
    EXPECT_NEAR(MinConvexCentreRadius(d), s.min_convex_radius_mm, kThreePointTolMm) << name;
    std::printf("%-18s rho_min(X): closed form %.9f mm, 3-point %.9f mm, diff %.1e\n",
                name.c_str(), MinConvexCentreRadius(d), s.min_convex_radius_mm,
                MinConvexCentreRadius(d) - s.min_convex_radius_mm);
    // The sharpest point is where (C2) puts it: the 3-point circle there has the sampled minimum
    // radius. (Its phase is ill-conditioned where the peak is flat, near the tip/flank switch.)
    const double phi = PhaseAtMinConvexRadius(d), h = 2.0 * kPi / d.teeth / kSamplesPerTooth;
    const double kappa_at = ThreePointCurvature(
        CentreCurvePoint(d, phi - h), CentreCurvePoint(d, phi), CentreCurvePoint(d, phi + h));
    EXPECT_NEAR(1.0 / kappa_at, s.min_convex_radius_mm, kThreePointTolMm) << name;
    if (name == "published") {
      EXPECT_NEAR(phi, s.phase_rad, 3.0 * h);
    }
  }
}

TEST(CycloidGeometryLimits, ProfileRadiusMatchesThreePointCirclesOnToothProfilePoints) {
  // The tooth itself: ToothProfile(d, t).point = X'(t) − ρ' N(t), with a' = a + Δa, ρ' = ρ + Δρ.
  for (const auto& [name, d] : SampledCases()) {
    if (MinConvexProfileRadius(d) <= 0.0) continue;  // undercut: the offset has a swallowtail
    const SampledExtreme s =
        SampledMinConvexRadius(d, [&drive = d](double t) { return ToothProfile(drive, t).point; });
    EXPECT_NEAR(MinConvexProfileRadius(d), s.min_convex_radius_mm, kThreePointTolMm) << name;
    std::printf("%-18s profile: closed form %.9f mm, 3-point %.9f mm, diff %.1e\n", name.c_str(),
                MinConvexProfileRadius(d), s.min_convex_radius_mm,
                MinConvexProfileRadius(d) - s.min_convex_radius_mm);
  }
}

TEST(CycloidGeometryLimits, RootRadiusIsTheSampledProfileMinimumDistance) {
  for (const auto& [name, d] : SampledCases()) {
    if (MinConvexProfileRadius(d) <= 0.0) continue;
    double min_r = kInf;
    for (int k = 0; k < kSamplesPerTooth; ++k) {
      const double t = 2.0 * kPi / d.teeth * k / kSamplesPerTooth;
      min_r = std::min(min_r, ToothProfile(d, t).point.norm());
    }
    EXPECT_NEAR(RootRadius(d), min_r, 1e-9) << name;  // the minimum sits on the sample t = 0
    EXPECT_NEAR(WebMargin(d, 10.0, 2.0), min_r - 10.0 - 2.0, 1e-9) << name;
  }
}

TEST(CycloidGeometryLimits, PinGapIsTheDistanceBetweenNeighbouringPins) {
  for (const auto& [name, d] : SampledCases()) {
    const double a = d.roller_position_radius_mm;
    const Vec2<double> p0(a, 0.0), p1(a * std::cos(2.0 * kPi / d.rollers),
                                      a * std::sin(2.0 * kPi / d.rollers));
    EXPECT_NEAR(PinGapMargin(d, 0.5), (p1 - p0).norm() - 2.0 * d.roller_radius_mm - 0.5, 1e-12)
        << name;
  }
  // The published case: 2·42.5·sin(10°) − 5 = 9.760 mm.
  EXPECT_NEAR(PinGapMargin(PublishedDrive()), 85.0 * std::sin(kPi / 18.0) - 5.0, 1e-12);
}

TEST(CycloidGeometryLimits, UndercutMarginAgreesWithCheckDrive) {
  // Either side of the undercut boundary the sampled check of tooth_profile.h agrees in sign.
  for (Drive d : {PublishedDrive(), camopt::testing::CycloidNnm()}) {
    const double rho_max = MinConvexCentreRadius(d) - d.delta_radius_mm;  // margin 0 at ρ = this
    d.roller_radius_mm = rho_max - 0.01;
    d.face_width_mm = 10.0;
    if (PinGapMargin(d) > 0.0) {
      EXPECT_TRUE(CheckDrive(d).empty());
    }
    EXPECT_NEAR(UndercutMargin(d), 0.01, 1e-12);
    d.roller_radius_mm = rho_max + 0.01;
    EXPECT_NEAR(UndercutMargin(d), -0.01, 1e-12);
    const auto issues = CheckDrive(d);
    ASSERT_FALSE(issues.empty());
    const std::string& why = issues.front().message;
    EXPECT_TRUE(why.find("undercut") != std::string::npos ||
                why.find("overlap") != std::string::npos)
        << why;
    // The sampled sharpest radius (the issue's limit on ρ') agrees with the closed form (C3)/(C4).
    if (why.find("undercut") != std::string::npos) {
      EXPECT_NEAR(issues.front().limit, MinConvexCentreRadius(d), 1e-3);
    }
  }
}

TEST(CycloidGeometryLimits, CurtateLimit) {
  // e = a/N is exactly representable here: 48/16 = 3.
  Drive d = PublishedDrive();
  d.teeth = 15;
  d.rollers = 16;
  d.roller_position_radius_mm = 48.0;
  d.roller_radius_mm = 1.0;
  d.eccentricity_mm = 3.0;
  EXPECT_EQ(CurtateMargin(d), 0.0);
  EXPECT_EQ(MinConvexCentreRadius(d), 0.0);  // the cusp
  EXPECT_LT(UndercutMargin(d), 0.0);
  // The published drive at e = R/N: zero to rounding.
  EXPECT_NEAR(CurtateMargin(WithRatio(PublishedDrive(), 1.0)), 0.0, 1e-15);
  // Approaching it, (C3) ∝ √(1 − λ²) → 0: the undercut margin fails before the curtate one does.
  double previous = kInf;
  for (int k = 1; k <= 8; ++k) {
    const double lambda = 1.0 - std::pow(10.0, -k);
    const Drive dk = WithRatio(d, lambda);
    const double r = MinConvexCentreRadius(dk);
    EXPECT_LT(r, previous) << "lambda " << lambda;
    const double l = dk.eccentricity_mm * 16.0 / 48.0;  // the λ the design actually has
    EXPECT_NEAR(r, 48.0 * std::sqrt(27.0 * 15.0 * (1.0 - l * l) / (17.0 * 17.0 * 17.0)),
                1e-12 * 48.0)
        << "lambda " << lambda;
    EXPECT_GT(CurtateMargin(dk), 0.0);
    if (k >= 3) {
      EXPECT_LT(UndercutMargin(dk), 0.0) << "lambda " << lambda;  // r < ρ = 1 mm
    }
    previous = r;
  }
  EXPECT_LT(previous, 1e-3 * 48.0);
  // Past the limit X has loops: the curtate margin is negative.
  EXPECT_LT(CurtateMargin(WithRatio(d, 1.01)), 0.0);
}

// The drive of `base` with (e, a, ρ, Δa, Δρ) = x, over the scalar T.
template <typename T>
DriveTpl<T> WithVariables(const Drive& base, const std::array<T, 5>& x) {
  DriveTpl<T> d;
  d.teeth = base.teeth;
  d.rollers = base.rollers;
  d.face_width_mm = T(base.face_width_mm);
  d.eccentricity_mm = x[0];
  d.roller_position_radius_mm = x[1];
  d.roller_radius_mm = x[2];
  d.delta_position_mm = x[3];
  d.delta_radius_mm = x[4];
  return d;
}

// The margins as a function of (e, a, ρ, Δa, Δρ) for the gradient checks.
template <typename T>
std::vector<T> Margins(const Drive& base, const std::array<T, 5>& x) {
  const DriveTpl<T> d = WithVariables(base, x);
  return {CurtateMargin(d),       UndercutMargin(d, 0.5), MinConvexProfileRadius(d),
          PinGapMargin(d, 1.0),   WebMargin(d, T(12.0), 3.0), RootRadius(d),
          MinConvexCentreRadius(d)};
}

std::array<double, 5> Variables(const Drive& d) {
  return {d.eccentricity_mm, d.roller_position_radius_mm, d.roller_radius_mm,
          d.delta_position_mm, d.delta_radius_mm};
}

TEST(CycloidGeometryLimits, GradientsMatchCentralDifferences) {
  for (const auto& [name, d0] : SampledCases()) {
    Drive d = d0;
    if (d.delta_position_mm == 0.0) d.delta_position_mm = -0.016, d.delta_radius_mm = -0.008;
    SCOPED_TRACE(name);
    camopt::testing::ExpectJacobianMatchesCentralDifferences<5>(
        [&](const auto& x) { return Margins(d, x); }, Variables(d), kGradRelTol, kGradAbsTol);
  }
}

TEST(CycloidGeometryLimits, GradientsAtTheUndercutBoundaryAndTheBranchSwitch) {
  // At the undercut boundary (margin ±1e-3 mm): the sharpest point φ*(e, a') moves with the design
  // and its derivative is in the closed form; check d φ* as well.
  for (double offset : {-1e-3, 1e-3}) {
    Drive d = PublishedDrive();
    d.roller_radius_mm = MinConvexCentreRadius(d) - offset;
    ASSERT_NEAR(UndercutMargin(d), offset, 1e-12);
    SCOPED_TRACE("undercut margin " + std::to_string(offset));
    camopt::testing::ExpectJacobianMatchesCentralDifferences<5>(
        [&](const auto& x) {
          auto m = Margins(d, x);
          m.push_back(PhaseAtMinConvexRadius(WithVariables(d, x)));
          return m;
        },
        Variables(d), kGradRelTol, kGradAbsTol);
  }
  // Exactly at the tip/flank switch λ_s = (N − 2)/(2N − 1) the central difference straddles both
  // branches; the closed forms join with equal slopes (C¹).
  const Drive at_switch = WithRatio(PublishedDrive(), 16.0 / 35.0);
  EXPECT_NEAR(CosAtMinConvexRadius(at_switch), -1.0, 1e-12);
  camopt::testing::ExpectJacobianMatchesCentralDifferences<5>(
      [&](const auto& x) { return Margins(at_switch, x); }, Variables(at_switch),
      kGradAtSwitchRelTol, kGradAbsTol);
  // One-sided: the tip form (C4) just below λ_s and the flank form (C3) just above have the same
  // slope in every variable.
  using J = ceres::Jet<double, 5>;
  auto jet_radius = [](const Drive& d) {
    std::array<J, 5> x;
    const auto v = Variables(d);
    for (int i = 0; i < 5; ++i) x[i] = J(v[i], i);
    return Margins(d, x)[6];  // MinConvexCentreRadius
  };
  const J below = jet_radius(WithRatio(PublishedDrive(), 16.0 / 35.0 - 1e-9));
  const J above = jet_radius(WithRatio(PublishedDrive(), 16.0 / 35.0 + 1e-9));
  for (int i = 0; i < 5; ++i) {
    EXPECT_NEAR(below.v[i], above.v[i], kSlopeJoinRelTol * std::max(1.0, std::abs(above.v[i])))
        << "variable " << i;
  }
}

// Expects f() to throw std::invalid_argument whose message names `what`.
template <typename F>
void ExpectInvalid(const F& f, const std::string& what) {
  try {
    f();
    ADD_FAILURE() << "no exception; expected one naming " << what;
  } catch (const std::invalid_argument& ex) {
    EXPECT_NE(std::string(ex.what()).find(what), std::string::npos) << ex.what();
  }
}

TEST(CycloidGeometryLimits, BadInputThrowsInvalidArgument) {
  const auto all = [](const Drive& d) {
    (void)CurtateMargin(d);
    (void)UndercutMargin(d);
    (void)PinGapMargin(d);
    (void)WebMargin(d, 5.0, 1.0);
    (void)RootRadius(d);
    (void)CentreCurvature(d, 0.1);
  };
  const auto each = [](const Drive& d, const std::string& what) {
    ExpectInvalid([&] { (void)CurtateMargin(d); }, what);
    ExpectInvalid([&] { (void)MinConvexCentreRadius(d); }, what);
    ExpectInvalid([&] { (void)UndercutMargin(d); }, what);
    ExpectInvalid([&] { (void)PinGapMargin(d); }, what);
    ExpectInvalid([&] { (void)WebMargin(d, 5.0, 1.0); }, what);
    ExpectInvalid([&] { (void)CentreCurvature(d, 0.1); }, what);
    ExpectInvalid([&] { (void)PhaseAtMinConvexRadius(d); }, what);
  };
  EXPECT_NO_THROW(all(PublishedDrive()));
  for (double e : {0.0, -1.3, std::nan("")}) {
    Drive d = PublishedDrive();
    d.eccentricity_mm = e;
    each(d, "eccentricity_mm");
  }
  for (double a : {0.0, -42.5}) {
    Drive d = PublishedDrive();
    d.roller_position_radius_mm = a;
    each(d, "roller_position_radius_mm");
  }
  {
    Drive d = PublishedDrive();
    d.roller_radius_mm = 0.0;
    each(d, "roller_radius_mm");
    d = PublishedDrive();
    d.delta_radius_mm = -2.5;
    each(d, "rho + delta_rho");
  }
  for (int z : {1, 0, -3}) {
    Drive d = PublishedDrive();
    d.teeth = z;
    d.rollers = z + 1;
    each(d, "at least 2 teeth");
  }
  Drive d = PublishedDrive();
  d.rollers = 17;
  each(d, "teeth + 1");
  // A Jet design is checked on its values.
  using J = ceres::Jet<double, 1>;
  DriveTpl<J> dj;
  dj.teeth = 17;
  dj.rollers = 18;
  dj.roller_position_radius_mm = J(42.5);
  dj.roller_radius_mm = J(2.5);
  dj.eccentricity_mm = J(-1.0, 0);
  ExpectInvalid([&] { (void)UndercutMargin(dj); }, "eccentricity_mm");
}

}  // namespace cycloid_geometry_limits_test
}  // namespace camopt::cycloid
