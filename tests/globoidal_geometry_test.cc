// Globoidal cam geometry: the paper's printed numbers (eqs. 7–9, the modified-sine law), the
// working surface against independent constructions (distance to the roller axis, the meshing
// condition with a finite-difference relative velocity, the envelope property, a closed-form
// normal and pressure angle), degenerate dwells that reduce to a plane and a cone, curvature
// checked by finite differences of the surfaces, and AD gradients of every geometry output.
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "model/globoidal/check.h"
#include "model/globoidal/globoidal.h"
#include "model/globoidal/paper_example.h"
#include "tests/test_util.h"

namespace camopt::globoidal {
namespace globoidal_geometry_test {

constexpr double kDeg = kPi / 180.0;

template <typename T>
GloboidalCam<T> PaperCam(const T& c = T(45.0), const T& r = T(4.0), const T& re = T(22.0),
                         const T& beta = T(45.0 * kDeg), const T& swing = T(20.0 * kDeg)) {
  return PaperExampleCam<T>(c, r, re, beta, swing);
}

double Distance(const Vec3<double>& x, const Vec3<double>& a, const Vec3<double>& dir) {
  const Vec3<double> v = x - a;
  return (v - v.dot(dir) * dir).norm();
}

TEST(GloboidalPaper, RollerAxisLimitsEqs8And9) {
  const auto cam = PaperCam<double>();
  const auto lim = RollerAxisLimits(cam);
  EXPECT_DOUBLE_EQ(lim.l1, 22.0 + 2.5 + 1.0);  // 25.5 mm
  EXPECT_DOUBLE_EQ(lim.l2, 22.0 - 2.5);        // 19.5 mm
}

TEST(GloboidalPaper, InitialAnglesEq7) {
  const double b = 45 * kDeg, f = 20 * kDeg;
  EXPECT_NEAR(InitialAngle(b, f, 1, 1) / kDeg, 12.5, 1e-12);
  EXPECT_NEAR(InitialAngle(b, f, 2, 1) / kDeg, -32.5, 1e-12);
  EXPECT_NEAR(InitialAngle(b, f, 1, -1) / kDeg, 32.5, 1e-12);
  EXPECT_NEAR(InitialAngle(b, f, 2, -1) / kDeg, -12.5, 1e-12);
  // The bottom dead point is the top one swung by φ_f, and the rollers are β apart.
  for (int j = 1; j <= 2; ++j)
    EXPECT_NEAR(InitialAngle(b, f, j, -1) - InitialAngle(b, f, j, 1), f, 1e-15);
  EXPECT_NEAR(InitialAngle(b, f, 1, 1) - InitialAngle(b, f, 2, 1), b, 1e-15);
}

TEST(GloboidalPaper, ModifiedSineProgram) {
  const auto cam = PaperCam<double>();
  EXPECT_NEAR(cam.motion.Period(), 2 * kPi, 1e-12);
  EXPECT_NEAR(cam.motion.NetRise(), 0.0, 1e-15);
  // Peak acceleration of the rise: Ca φ_f / θ_f1², Ca = 4π²/(4 + π) ≈ 5.528 (docs/papers.md §5).
  double amax = 0, vmax = 0;
  for (int i = 0; i <= 6000; ++i) {
    const auto s = cam.motion.Evaluate(60.0 * kDeg * i / 6000);
    amax = std::max(amax, std::abs(s.a));
    vmax = std::max(vmax, std::abs(s.v));
  }
  const double b = 60 * kDeg, f = 20 * kDeg;
  EXPECT_NEAR(amax * b * b / f, 5.528, 5e-4);
  EXPECT_NEAR(vmax * b / f, 1.760, 5e-4);  // Cv = 4π/(4 + π) ≈ 1.760
  // Swing reaches φ_f at the end of the rise, returns to 0 after the return.
  EXPECT_NEAR(cam.motion.Evaluate(90 * kDeg).s, f, 1e-12);
  EXPECT_NEAR(cam.motion.Evaluate(300 * kDeg).s, 0.0, 1e-12);
}

TEST(GloboidalGeometry, RollerAnglesKeepBetaAndAreSymmetric) {
  for (int p : {1, -1}) {
    auto cam = PaperCam<double>();
    cam.direction = p;
    double lo1 = 1e9, hi1 = -1e9, lo2 = 1e9, hi2 = -1e9;
    for (int i = 0; i < 720; ++i) {
      const double t = 2 * kPi * i / 720;
      const auto a1 = RollerAngleAt(cam, 1, t), a2 = RollerAngleAt(cam, 2, t);
      EXPECT_NEAR(a1.phi - a2.phi, 45 * kDeg, 1e-12);
      EXPECT_NEAR(a1.dphi, a2.dphi, 1e-15);
      lo1 = std::min(lo1, a1.phi), hi1 = std::max(hi1, a1.phi);
      lo2 = std::min(lo2, a2.phi), hi2 = std::max(hi2, a2.phi);
    }
    // Paper §2.2: the upper roller's bottom dead point mirrors the lower roller's top one.
    EXPECT_NEAR(lo1, -hi2, 1e-9);
    EXPECT_NEAR(hi1, -lo2, 1e-9);
    EXPECT_NEAR(hi1 - lo1, 20 * kDeg, 1e-9);
    EXPECT_NEAR(lo1 / kDeg, 12.5, 1e-7);
  }
}

// p = −1 is the mirror image (z → −z) of p = +1 with the rollers' roles swapped: roller 2 of the
// anticlockwise cam is roller 1 of the clockwise one, mirrored, and vice versa.
TEST(GloboidalGeometry, AnticlockwiseIsTheMirrorImage) {
  auto cw = PaperCam<double>();
  auto ccw = PaperCam<double>();
  ccw.direction = -1;
  for (double tdeg : {10.0, 30.0, 90.0, 150.0, 200.0, 300.0})
    for (int j = 1; j <= 2; ++j)
      for (double l : {19.5, 25.5}) {
        const auto a = EvaluateSurface(cw, j, l, tdeg * kDeg);
        const auto b = EvaluateSurface(ccw, 3 - j, l, tdeg * kDeg);
        const Vec3<double> m(a.working.x(), a.working.y(), -a.working.z());
        EXPECT_LT((b.working - m).norm(), 1e-12) << tdeg << " " << j;
        EXPECT_NEAR(b.undercut_margin, a.undercut_margin, 1e-12);
        EXPECT_NEAR(b.contact_radius, a.contact_radius, 1e-9);
        EXPECT_NEAR(std::abs(b.pressure_angle), std::abs(a.pressure_angle), 1e-12);
      }
}

TEST(GloboidalGeometry, TrajectoryIsTheRuledSurfaceOfEq5) {
  const auto cam = PaperCam<double>();
  for (double t : {0.1, 1.0, 2.5, 4.0}) {
    const auto a = RollerAngleAt(cam, 1, t);
    const Vec3<double> p0(45 * std::sin(t), 45 * std::cos(t), 0.0);
    const Vec3<double> q(-std::cos(a.phi) * std::sin(t), -std::cos(a.phi) * std::cos(t),
                         std::sin(a.phi));
    for (double l : {19.5, 22.0, 25.5}) {
      EXPECT_LT((TrajectoryPoint(cam, a.phi, l, t) - (p0 + l * q)).norm(), 1e-12);
      EXPECT_LT((EvaluateSurface(cam, 1, l, t).axis_point - (p0 + l * q)).norm(), 1e-12);
    }
  }
}

// The working point is R from the roller axis with its foot at r(l, θ); its normal is normal to
// the roller axis and to the relative velocity of the roller (finite differences of eq. 4 over θ).
TEST(GloboidalGeometry, WorkingSurfaceMeshingCondition) {
  const auto cam = PaperCam<double>();
  const double h = 1e-6;
  for (int j = 1; j <= 2; ++j) {
    for (double tdeg : {0.0, 17.0, 30.0, 47.0, 90.0, 150.0, 187.5, 230.0, 300.0}) {
      const double t = tdeg * kDeg;
      for (double l : {19.5, 22.0, 25.5}) {
        const auto sp = EvaluateSurface(cam, j, l, t);
        const Vec3<double> foot = TrajectoryPoint(cam, sp.angle.phi, l, t);
        EXPECT_NEAR(Distance(sp.working, foot, sp.axis_dir), 4.0, 1e-12);
        EXPECT_NEAR((sp.working - foot).norm(), 4.0, 1e-12);
        const Vec3<double> vrel =
            (TrajectoryPoint(cam, RollerAngleAt(cam, j, t + h).phi, l, t + h) -
             TrajectoryPoint(cam, RollerAngleAt(cam, j, t - h).phi, l, t - h)) / (2 * h);
        EXPECT_NEAR(sp.normal.dot(vrel) / vrel.norm(), 0.0, 1e-8) << j << " " << tdeg << " " << l;
        EXPECT_NEAR(sp.normal.dot(sp.axis_dir), 0.0, 1e-14);
        // Closed form: n ∝ σ (d e_φ − l φ' e_a), σ = −1 for roller 1, +1 for roller 2.
        const double d = 45 - l * std::cos(sp.angle.phi);
        Vec3<double> n = d * sp.swing_dir - l * sp.angle.dphi * sp.turret_axis;
        n = (j == 1 ? -1.0 : 1.0) * n.normalized();
        EXPECT_LT((n - sp.normal).norm(), 1e-12);
        EXPECT_NEAR(sp.pressure_angle, std::atan(l * sp.angle.dphi / d), 1e-12);
        EXPECT_NEAR(sp.pressure_angle, PressureAngleClosedForm(cam, sp.angle, l), 1e-12);
      }
    }
  }
}

// Envelope: neighbouring positions of the roller never reach inside the working surface of a cam
// without undercut, and the rib lies on the normal side (the two working surfaces face each other).
TEST(GloboidalGeometry, RollersDoNotCutTheWorkingSurface) {
  const auto cam = PaperCam<double>();
  for (int j = 1; j <= 2; ++j) {
    for (double tdeg = 0; tdeg < 360; tdeg += 7.5) {
      const double t = tdeg * kDeg;
      const auto sp = EvaluateSurface(cam, j, 22.0, t);
      ASSERT_GT(sp.undercut_margin, 0.0);
      for (double dt = -0.2; dt <= 0.2; dt += 0.01) {
        const auto a = RollerAngleAt(cam, j, t + dt);
        const Vec3<double> base = TrajectoryPoint(cam, a.phi, 0.0, t + dt);
        const Vec3<double> dir = TrajectoryPoint(cam, a.phi, 1.0, t + dt) - base;
        EXPECT_GT(Distance(sp.working, base, dir.normalized()), 4.0 - 1e-9)
            << j << " " << tdeg << " " << dt;
      }
    }
  }
  // Rib between the rollers: roller 1's working point lies toward roller 2 and vice versa.
  const auto s1 = EvaluateSurface(cam, 1, 22.0, 1.0), s2 = EvaluateSurface(cam, 2, 22.0, 1.0);
  EXPECT_LT(s1.normal.dot(s1.swing_dir), 0.0);
  EXPECT_GT(s2.normal.dot(s2.swing_dir), 0.0);
}

TEST(GloboidalGeometry, PressureAngleVanishesInDwellsAndPeaksInTheRise) {
  const auto cam = PaperCam<double>();
  for (double tdeg : {70.0, 100.0, 119.0, 260.0, 300.0, 359.0})
    for (int j = 1; j <= 2; ++j)
      EXPECT_NEAR(EvaluateSurface(cam, j, 25.5, tdeg * kDeg).pressure_angle, 0.0, 1e-12);
  EXPECT_GT(EvaluateSurface(cam, 1, 25.5, 30 * kDeg).pressure_angle, 0.0);
  EXPECT_LT(EvaluateSurface(cam, 1, 25.5, 187.5 * kDeg).pressure_angle, 0.0);
}

// Degenerate case 1: both rollers at φ = 0 for the whole turn (β = 0, no swing). The roller axis
// sweeps the plane z = 0; the working surfaces are the planes z = ∓R, flat, undercut-free, and the
// contact radius of eq. (12) is the roller radius.
TEST(GloboidalGeometry, DwellAtZeroIsAPlane) {
  GloboidalCam<double> cam;
  cam.roller_angle = 0.0;
  cam.swing = 0.0;
  cam.motion = motion::MotionProgram<double>({{motion::MotionLaw::kDwell, 0.0, 2 * kPi}});
  for (double t : {0.0, 1.0, 3.0})
    for (double l : {19.5, 25.5}) {
      const auto s1 = EvaluateSurface(cam, 1, l, t), s2 = EvaluateSurface(cam, 2, l, t);
      EXPECT_NEAR(s1.working.z(), -4.0, 1e-12);
      EXPECT_NEAR(s2.working.z(), 4.0, 1e-12);
      EXPECT_NEAR(s1.kappa1, 0.0, 1e-14);
      EXPECT_NEAR(s1.kappa2, 0.0, 1e-14);
      EXPECT_NEAR(s1.contact_radius, 4.0, 1e-12);
      EXPECT_NEAR(s1.offset_jacobian, 1.0, 1e-12);
    }
}

// Degenerate case 2: a dwell at φ = φ_c: the roller axis sweeps a cone about the cam axis. Its
// principal curvatures are 0 (along the ruling) and −(n·ρ̂)/ρ around the axis (ρ the distance to
// the cam axis, ρ̂ its unit vector); the working surface is again a surface of revolution with
// curvature −(n·ρ̂_W)/ρ_W across the roller.
TEST(GloboidalGeometry, DwellIsACone) {
  GloboidalCam<double> cam;
  cam.roller_angle = 50 * kDeg;
  cam.swing = 0.0;
  cam.motion = motion::MotionProgram<double>({{motion::MotionLaw::kDwell, 0.0, 2 * kPi}});
  for (int j = 1; j <= 2; ++j)
    for (double t : {0.3, 2.0})
      for (double l : {19.5, 25.5}) {
        const auto s = EvaluateSurface(cam, j, l, t);
        const Vec3<double> rho_hat(std::sin(t), std::cos(t), 0.0);
        const double rho = 45 - l * std::cos(s.angle.phi);
        const double k = -s.normal.dot(rho_hat) / rho;
        EXPECT_NEAR(std::max(k, 0.0), s.kappa1, 1e-12);
        EXPECT_NEAR(std::min(k, 0.0), s.kappa2, 1e-12);
        const double rho_w = std::hypot(s.working.x(), s.working.y());
        const Vec3<double> rho_w_hat(s.working.x() / rho_w, s.working.y() / rho_w, 0.0);
        EXPECT_NEAR(s.working_curvature, -s.normal.dot(rho_w_hat) / rho_w, 1e-12);
        EXPECT_NEAR(s.pressure_angle, 0.0, 1e-15);
      }
}

// Curvature by finite differences of the surfaces themselves: the area ratio of the working and
// trajectory surfaces is det(I − R S), and the normal curvature of the working surface across the
// roller is −dn·dW/|dW|² along that direction.
TEST(GloboidalGeometry, CurvatureMatchesFiniteDifferences) {
  const auto cam = PaperCam<double>();
  const double h = 1e-5;
  for (int j = 1; j <= 2; ++j)
    for (double tdeg : {20.0, 45.0, 160.0, 200.0, 80.0})
      for (double l : {19.5, 25.5}) {
        const double t = tdeg * kDeg;
        const auto s = EvaluateSurface(cam, j, l, t);
        auto at = [&](double dl, double dt) { return EvaluateSurface(cam, j, l + dl, t + dt); };
        const Vec3<double> wl = (at(h, 0).working - at(-h, 0).working) / (2 * h);
        const Vec3<double> wt = (at(0, h).working - at(0, -h).working) / (2 * h);
        const double ratio = wl.cross(wt).dot(s.normal) / s.axis_dir.cross(s.r_theta).dot(s.normal);
        EXPECT_NEAR(ratio, s.offset_jacobian, 1e-6) << j << " " << tdeg << " " << l;
        // The working surface's own normal (finite differences) is the offset direction n.
        EXPECT_NEAR(std::abs(wl.cross(wt).normalized().dot(s.normal)), 1.0, 1e-9);
        // Direction across the roller in (l, θ) coordinates: W_l a + W_θ b ∥ n × r_l.
        const Vec3<double> tdir = s.normal.cross(s.axis_dir);
        const double a11 = wl.dot(wl), a12 = wl.dot(wt), a22 = wt.dot(wt);
        const double b1 = tdir.dot(wl), b2 = tdir.dot(wt), det = a11 * a22 - a12 * a12;
        const double ca = (a22 * b1 - a12 * b2) / det, cb = (a11 * b2 - a12 * b1) / det;
        const double e = 1e-5;
        const auto sp = at(e * ca, e * cb), sm = at(-e * ca, -e * cb);
        const Vec3<double> dw = sp.working - sm.working, dn = sp.normal - sm.normal;
        EXPECT_NEAR(-dn.dot(dw) / dw.squaredNorm(), s.working_curvature,
                    1e-5 * std::max(1.0, std::abs(s.working_curvature)))
            << j << " " << tdeg << " " << l;
      }
}

// A roller much larger than the rib's curvature radius folds the working surface: the margin goes
// negative, and a neighbouring roller position then cuts into the surface (the envelope test).
TEST(GloboidalGeometry, UndercutIsDetected) {
  auto cam = PaperCam<double>(45.0, 4.0, 22.0, 45 * kDeg, 20 * kDeg);
  // Fast swing: 20° over 15° of cam angle.
  cam.motion = RiseDwellReturnDwell(motion::MotionLaw::kModifiedSine, 20 * kDeg, 15 * kDeg,
                                    105 * kDeg, 135 * kDeg, 105 * kDeg);
  cam.roller_radius = 12.0;
  double worst = 1e9, worst_t = 0;
  int worst_j = 1;
  for (int j = 1; j <= 2; ++j)
    for (int i = 0; i < 3600; ++i) {
      const double t = 2 * kPi * i / 3600;
      const double m = EvaluateSurface(cam, j, 25.5, t).undercut_margin;
      if (m < worst) worst = m, worst_t = t, worst_j = j;
    }
  ASSERT_LT(worst, 0.0);
  const auto sp = EvaluateSurface(cam, worst_j, 25.5, worst_t);
  double dmin = 1e9;
  for (double dt = -0.1; dt <= 0.1; dt += 0.0005) {
    const auto a = RollerAngleAt(cam, worst_j, worst_t + dt);
    const Vec3<double> base = TrajectoryPoint(cam, a.phi, 0.0, worst_t + dt);
    const Vec3<double> dir = TrajectoryPoint(cam, a.phi, 1.0, worst_t + dt) - base;
    dmin = std::min(dmin, Distance(sp.working, base, dir.normalized()));
  }
  EXPECT_LT(dmin, 12.0 - 1e-6);
  // The paper's design is free of undercut everywhere on the surface.
  const auto paper = PaperCam<double>();
  for (int j = 1; j <= 2; ++j)
    for (int i = 0; i < 720; ++i)
      for (double l : {19.5, 25.5})
        EXPECT_GT(EvaluateSurface(paper, j, l, 2 * kPi * i / 720).undercut_margin, 0.0);
}

// AD gradients (C, R, R_e, β, φ_f, l, θ) of every geometry output, in the rise, the dwell and the
// return.
TEST(GloboidalGeometry, GradientsMatchCentralDifferences) {
  for (int j = 1; j <= 2; ++j)
    for (double tdeg : {25.0, 100.0, 170.0}) {
      auto f = [j](const auto& x) {
        using T = std::decay_t<decltype(x[0])>;
        const auto cam = PaperCam<T>(x[0], x[1], x[2], x[3], x[4]);
        const auto s = EvaluateSurface(cam, j, x[5], x[6]);
        const auto lim = RollerAxisLimits(cam);
        return std::vector<T>{s.working.x(), s.working.y(), s.working.z(), s.normal.x(),
                              s.pressure_angle, s.kappa1, s.kappa2, s.undercut_margin,
                              s.offset_jacobian, s.working_curvature, s.contact_radius,
                              s.angle.phi, lim.l1, lim.l2,
                              InitialAngle(x[3], x[4], j, 1)};
      };
      camopt::testing::ExpectJacobianMatchesCentralDifferences<7>(
          f, {45.0, 4.0, 22.0, 45 * kDeg, 20 * kDeg, 23.0, tdeg * kDeg}, 2e-5, 1e-7);
    }
}

// CheckDesign: one test per kind of issue, each on the paper's design broken in one way.
DynamicsInput PaperInput(const GloboidalCam<double>& cam = PaperCam<double>()) {
  DynamicsInput in;
  in.cam = cam;
  return in;
}

const DesignIssue* Find(const std::vector<DesignIssue>& issues, const std::string& words) {
  for (const auto& i : issues)
    if (i.message.find(words) != std::string::npos) return &i;
  return nullptr;
}

TEST(GloboidalCheckDesign, ThePaperDesignIsFeasible) {
  EXPECT_TRUE(CheckDesign(PaperInput(), 720, 7).empty());
  // Rib at l₂ = 19.5 mm between rollers 45° apart, R = 4 mm.
  EXPECT_NEAR(RibThickness(PaperCam<double>()), 2 * 19.5 * std::sin(22.5 * kDeg) - 8.0, 1e-12);
}

TEST(GloboidalCheckDesign, RollerPastTheTurretAxis) {
  auto cam = PaperCam<double>();
  cam.roller_length = 50.0;  // m/2 = 25 > R_e = 22
  const auto issues = CheckDesign(PaperInput(cam), 72, 3);
  ASSERT_FALSE(issues.empty());
  EXPECT_EQ(issues[0].field, "roller_length");
  EXPECT_EQ(issues[0].value, 50.0);
  EXPECT_EQ(issues[0].limit, 44.0);  // 2 R_e
  EXPECT_NE(issues[0].message.find("below 44 mm"), std::string::npos) << issues[0].message;
}

TEST(GloboidalCheckDesign, RollersReachTheCamAxis) {
  const auto issues = CheckDesign(PaperInput(PaperCam<double>(28.0)), 72, 3);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "center_distance");
  EXPECT_EQ(issues[0].value, 28.0);
  EXPECT_EQ(issues[0].limit, 25.5 + 4.0);  // l₁ + R
}

TEST(GloboidalCheckDesign, RollersOverlap) {
  const auto cam = PaperCam<double>(45.0, 4.0, 22.0, 20 * kDeg);
  const auto issues = CheckDesign(PaperInput(cam), 72, 3);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "roller_angle");
  EXPECT_NEAR(issues[0].value, 2 * 19.5 * std::sin(10 * kDeg), 1e-12);
  EXPECT_EQ(issues[0].limit, 8.0);
  // The rib opens for 2 l₂ sin(β/2) > 2R: β > 2 asin(4/19.5) = 23.67° (by hand: asin 0.20513 =
  // 11.837°), or R < l₂ sin(10°) = 3.386 mm.
  EXPECT_NE(issues[0].message.find("roller angle above 23.67"), std::string::npos) << issues[0].message;
  EXPECT_NE(issues[0].message.find("roller radius below l₂ sin(β/2) = 3.386"), std::string::npos) << issues[0].message;
  EXPECT_LT(RibThickness(cam), 0.0);
}

TEST(GloboidalCheckDesign, SwingThatMissesTheDeadPoint) {
  auto cam = PaperCam<double>();
  cam.motion = RiseDwellReturnDwell(motion::MotionLaw::kModifiedSine, 15 * kDeg, 60 * kDeg,
                                    60 * kDeg, 135 * kDeg, 105 * kDeg);
  const auto issues = CheckDesign(PaperInput(cam), 72, 3);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "motion");
  EXPECT_NEAR(issues[0].value, 15 * kDeg, 1e-9);  // the sampled top of the swing
  EXPECT_EQ(issues[0].limit, 20 * kDeg);
  EXPECT_NE(issues[0].message.find("runs from 0 to 15 deg"), std::string::npos) << issues[0].message;
}

TEST(GloboidalCheckDesign, ContactArmOffTheRoller) {
  DynamicsInput in = PaperInput();
  in.contact_arm_mm = 30.0;
  const auto issues = CheckDesign(in, 72, 3);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "contact_arm_mm");
  EXPECT_EQ(issues[0].value, 30.0);
  EXPECT_EQ(issues[0].limit, 25.5);  // l₁, the bound passed
  EXPECT_NE(issues[0].message.find("[19.5, 25.5] mm"), std::string::npos) << issues[0].message;
  // The default arm is the roller middle R_e.
  EXPECT_EQ(ContactArm(PaperInput()), 22.0);
  EXPECT_EQ(ContactArm(in), 30.0);
}

TEST(GloboidalCheckDesign, PressureAngleAtTheJamLimit) {
  auto cam = PaperCam<double>();
  cam.motion = RiseDwellReturnDwell(motion::MotionLaw::kModifiedSine, 20 * kDeg, 0.5 * kDeg,
                                    119.5 * kDeg, 135 * kDeg, 105 * kDeg);
  const auto issues = CheckDesign(PaperInput(cam), 720, 7);
  const DesignIssue* jam = Find(issues, "would jam");
  ASSERT_NE(jam, nullptr);
  EXPECT_EQ(jam->field, "motion");
  EXPECT_GE(jam->value, 89 * kDeg);
  EXPECT_LT(jam->cam_angle_rad.value(), 0.5 * kDeg);  // within the short rise
}

TEST(GloboidalCheckDesign, SurveyFindsTheClosedFormPressureAngle) {
  // The survey's largest |α| is at least the closed form's at any sampled point.
  const auto cam = PaperCam<double>();
  const CycleSurvey s = SurveyCycle(cam, 22.0, 720, 7);
  ASSERT_TRUE(s.max_abs_pressure_angle.set);
  const RollerAngle<double> a = RollerAngleAt(cam, 1, 30 * kDeg);  // middle of the rise
  EXPECT_GE(s.max_abs_pressure_angle.value, std::abs(PressureAngleClosedForm(cam, a, 25.5)) - 1e-12);
  EXPECT_GT(s.min_undercut_margin.value, 0.0);
  EXPECT_FALSE(s.conformal);
  // The grid series: roller angles of eq. (1) and the closed-form pressure angle at l₁ and l₂.
  ASSERT_EQ(s.grid.roller_angle[0].size(), 720u);
  for (int i : {0, 60, 100, 400}) {
    const double t = 2 * kPi * i / 720;
    for (int j = 1; j <= 2; ++j) {
      const RollerAngle<double> r = RollerAngleAt(cam, j, t);
      EXPECT_NEAR(s.grid.roller_angle[j - 1][i], r.phi, 1e-12);
      EXPECT_NEAR(std::abs(s.grid.pressure_angle_at_l1[j - 1][i]),
                  std::abs(PressureAngleClosedForm(cam, r, 25.5)), 1e-9);
      EXPECT_NEAR(std::abs(s.grid.pressure_angle_at_l2[j - 1][i]),
                  std::abs(PressureAngleClosedForm(cam, r, 19.5)), 1e-9);
    }
    EXPECT_GE(s.grid.min_undercut_margin[i], s.min_undercut_margin.value);
  }
}

}  // namespace globoidal_geometry_test
}  // namespace camopt::globoidal
