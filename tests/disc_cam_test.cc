// Disc cam model: the paper's example (Rzine et al., docs/papers.md §2), closed forms, independent
// constructions of the normal, instant centre, pressure angle and curvature, the linearised
// mechanical error against the exact follower motion, and AD gradients.
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "model/common/roots.h"
#include "model/disc_cam/check.h"
#include "model/disc_cam/disc_cam.h"
#include "model/disc_cam/exact_motion.h"
#include "model/disc_cam/mechanical_error.h"
#include "model/disc_cam/summary.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt::disc_cam {
namespace disc_cam_test {

constexpr double kDeg = kPi / 180.0;
using motion::MotionLaw;

// The shared reference designs (tests/reference_designs.h).
using testing::DiscCamOscillatingExample;
using testing::DiscCamPaperExample;

std::vector<double> Angles(int n) {
  std::vector<double> t(n);
  for (int i = 0; i < n; ++i) t[i] = 2 * kPi * (i + 0.37) / n;
  return t;
}

TEST(DiscCam, PaperExampleMaximumRadialDimension) {
  // Paper §5: "The cam profile, which has a maximum radial dimension of 63.525 mm".
  const DiscCam cam = DiscCamPaperExample();
  double rmax = 0.0;
  for (int i = 0; i < 3600; ++i) rmax = std::max(rmax, EvaluateCam(cam, 2 * kPi * i / 3600).radial_dimension);
  EXPECT_NEAR(rmax, 63.525, 5e-4);
  // Closed form in the upper dwell: |C| = sqrt((sqrt(50² − 12²) + 24)² + 12²), A = C − r_f C/|C|.
  const double L = std::sqrt(50.0 * 50.0 - 144.0) + 24.0;
  EXPECT_NEAR(EvaluateCam(cam, 140 * kDeg).radial_dimension, std::sqrt(L * L + 144.0) - 10.0, 1e-12);
  EXPECT_NEAR(rmax, std::sqrt(L * L + 144.0) - 10.0, 1e-12);
}

TEST(DiscCam, BaseCircleInTheLowDwell) {
  for (const DiscCam& cam : {DiscCamPaperExample(), DiscCamOscillatingExample()}) {
    const CamPoint<double> p = EvaluateCam(cam, 330 * kDeg);
    EXPECT_NEAR(p.radial_dimension, 40.0, 1e-12);
    EXPECT_NEAR(p.pitch.norm(), 50.0, 1e-12);
    EXPECT_NEAR(ProfileRadiusOfCurvature(p, cam.roller_radius), 40.0, 1e-9);
    EXPECT_NEAR(p.shift_angle, 0.0, 1e-12);  // normal along O₂A on a circle about O₂
  }
}

// Independent constructions of the normal, Q, φ and κ from the pitch curve C(θ) alone.
void CheckAgainstPitchCurve(const DiscCam& cam) {
  const double h = 1e-5;
  for (double t : Angles(97)) {
    const CamPoint<double> p = EvaluateCam(cam, t);
    const Vec2<double> cp = EvaluateCam(cam, t + h).pitch, cm = EvaluateCam(cam, t - h).pitch;
    const Vec2<double> d1 = (cp - cm) / (2 * h), d2 = (cp - 2 * p.pitch + cm) / (h * h);
    // The normal is perpendicular to the pitch curve and outward (the curve runs CCW).
    EXPECT_NEAR(p.normal.dot(d1) / d1.norm(), 0.0, 1e-8) << t;
    EXPECT_LT(Cross(d1, p.normal), 0.0) << "outward (right of a CCW curve) at " << t;
    EXPECT_NEAR((d1 - p.pitch_d1).norm() / d1.norm(), 0.0, 1e-8) << t;
    // The common normal passes through Q (eq. 4 / eq. 8).
    const Vec2<double> cq = p.pitch - p.instant_centre;
    EXPECT_NEAR(Cross(cq, p.normal) / cq.norm(), 0.0, 1e-10) << t;
    // Pressure angle: the angle between the normal and the roller centre's path.
    const Vec2<double> g = p.follower_dir / p.follower_dir.norm();
    EXPECT_NEAR(std::cos(p.pressure_angle), p.normal.dot(g), 1e-12) << t;
    EXPECT_NEAR(std::sin(p.pressure_angle), Cross(p.normal, g), 1e-12) << t;
    // Curvature of the pitch curve.
    EXPECT_NEAR(p.pitch_curvature, Cross(d1, d2) / std::pow(d1.norm(), 3), 2e-5 * 0.05) << t;
    // The profile is the envelope: its tangent is perpendicular to the normal (no undercut here),
    // and its radius of curvature is that of the pitch curve less the roller radius.
    const Vec2<double> ap = EvaluateCam(cam, t + h).contact, am = EvaluateCam(cam, t - h).contact;
    const Vec2<double> a1 = (ap - am) / (2 * h), a2 = (ap - 2 * p.contact + am) / (h * h);
    EXPECT_NEAR(p.normal.dot(a1) / a1.norm(), 0.0, 1e-8) << t;
    // (Compared as curvatures, which stay finite through inflections.)
    const double kappa_fd = Cross(a1, a2) / std::pow(a1.norm(), 3);
    const double rho_model = ProfileRadiusOfCurvature(p, cam.roller_radius);
    EXPECT_NEAR(kappa_fd, 1.0 / rho_model, 1e-6 + 1e-4 / std::abs(rho_model)) << t;
    // Shift angle (eq. 28) against the triangle O₂AQ with the law of cosines.
    const Vec2<double> ao = -p.contact, aq = p.instant_centre - p.contact;
    const double lam = std::acos(std::clamp(ao.dot(aq) / (ao.norm() * aq.norm()), -1.0, 1.0));
    if (std::abs(1.0 - p.ds) > 0.05 && aq.norm() > 1.0) {
      EXPECT_NEAR(std::abs(p.shift_angle), lam, 1e-7) << t;
    }
  }
}

TEST(DiscCam, TranslatingGeometryAgreesWithThePitchCurve) { CheckAgainstPitchCurve(DiscCamPaperExample()); }
TEST(DiscCam, OscillatingGeometryAgreesWithThePitchCurve) {
  CheckAgainstPitchCurve(DiscCamOscillatingExample());
}

TEST(DiscCam, OscillatingProfileMatchesPaperEquation7) {
  // Eq. (7) literally: A = (QC − r_f) u(θ + α) − q u(θ), with q (8), QC (9), α (10), ξ (11);
  // and eq. (12) for the pressure angle.
  const DiscCam cam = DiscCamOscillatingExample();
  const double f = 100, l = 80, rf = 10;
  const double xi0 = std::acos((l * l + f * f - 50.0 * 50.0) / (2 * l * f));
  for (double t : Angles(53)) {
    const motion::Svaj<double> m = cam.motion.Evaluate(t);
    const double xi = xi0 + m.s;
    const double q = f * m.v / (1 - m.v);
    const double qc = std::sqrt(l * l + (f + q) * (f + q) - 2 * l * (f + q) * std::cos(xi));
    const double alpha = std::asin(l * std::sin(xi) / qc);
    const Vec2<double> a = (qc - rf) * U(t + alpha) - q * U(t);
    const CamPoint<double> p = EvaluateCam(cam, t);
    EXPECT_NEAR((a - p.contact).norm(), 0.0, 1e-10) << t;
    EXPECT_NEAR(p.pressure_angle, kPi / 2 - alpha - xi, 1e-12) << t;
  }
}

TEST(DiscCam, TranslatingProfileMatchesPaperEquation2) {
  const DiscCam cam = DiscCamPaperExample();
  const double e = 12, rf = 10, L0 = std::sqrt(50.0 * 50.0 - e * e);
  for (double t : Angles(53)) {
    const motion::Svaj<double> m = cam.motion.Evaluate(t);
    const double L = L0 + m.s, q = m.v, phi = std::atan((q - e) / L);
    const Vec2<double> a(L * std::cos(t) - e * std::sin(t) - rf * std::cos(t - phi),
                         L * std::sin(t) + e * std::cos(t) - rf * std::sin(t - phi));
    EXPECT_NEAR((a - EvaluateCam(cam, t).contact).norm(), 0.0, 1e-12) << t;
  }
}

TEST(DiscCam, UndercutAgreesWithTheProfileFoldingOver) {
  // A small base circle with a large roller and a fast rise: where κ r_f > 1 the profile's
  // tangent reverses against the pitch curve's (A' = (1 − r_f κ) C').
  DiscCam cam;
  cam.base_radius = 10.0;
  cam.roller_radius = 15.0;
  cam.motion = motion::MotionProgram<double>({{MotionLaw::kCycloidal, 24.0, 60 * kDeg},
                                              {MotionLaw::kCycloidal, -24.0, 60 * kDeg},
                                              {MotionLaw::kDwell, 0.0, 240 * kDeg}});
  const double h = 1e-6;
  int undercut = 0;
  for (double t : Angles(720)) {
    const CamPoint<double> p = EvaluateCam(cam, t);
    const Vec2<double> a1 = (EvaluateCam(cam, t + h).contact - EvaluateCam(cam, t - h).contact);
    const double fold = a1.dot(p.pitch_d1);
    if (std::abs(1 - cam.roller_radius * p.pitch_curvature) < 1e-3) continue;  // at the fold
    EXPECT_EQ(IsUndercut(p, cam.roller_radius), fold < 0) << t;
    undercut += IsUndercut(p, cam.roller_radius);
  }
  EXPECT_GT(undercut, 0);
  for (double t : Angles(720)) EXPECT_FALSE(IsUndercut(EvaluateCam(DiscCamPaperExample(), t), 10.0));
}

// The linearised errors (eqs. 17, 19, 22, 25, 29, 30) are the derivatives of the exact follower
// position on the perturbed cam with respect to each deviation.
void CheckLinearErrorAgainstExact(const DiscCam& cam) {
  const double d = 1e-4;  // 0.1 µm
  for (double t : Angles(37)) {
    const CamPoint<double> p = EvaluateCam(cam, t);
    EXPECT_NEAR(ExactFollowerPosition(cam, {}, t), p.s, 1e-10) << t;
    const double gains[3] = {FollowerError(cam, p, {1.0, 0.0, 0.0}).normal,
                             FollowerError(cam, p, {0.0, 1.0, 0.0}).radial,
                             FollowerError(cam, p, {0.0, 0.0, 1.0}).roller};
    for (int k = 0; k < 3; ++k) {
      Deviations<double> plus, minus;
      double* fp[3] = {&plus.normal, &plus.radial, &plus.roller};
      double* fm[3] = {&minus.normal, &minus.radial, &minus.roller};
      *fp[k] = d;
      *fm[k] = -d;
      const double fd =
          (ExactFollowerPosition(cam, plus, t) - ExactFollowerPosition(cam, minus, t)) / (2 * d);
      EXPECT_NEAR(fd, gains[k], 1e-5 * std::abs(gains[k]) + 1e-9) << "deviation " << k << " at " << t;
    }
  }
}

TEST(DiscCamError, TranslatingLinearErrorIsTheDerivativeOfTheExactMotion) {
  CheckLinearErrorAgainstExact(DiscCamPaperExample());
}
TEST(DiscCamError, OscillatingLinearErrorIsTheDerivativeOfTheExactMotion) {
  CheckLinearErrorAgainstExact(DiscCamOscillatingExample());
}

TEST(DiscCamError, OscillatingExampleAgreesWithTheExactFollowerAngle) {
  // The oscillating example with all deviations at their tolerances (Δn = 5, Δr = 19,
  // Δr_f = 9 µm): the follower angle recomputed by intersecting the roller circle with the
  // perturbed profile differs from the linearised ΔS by second-order terms only.
  const DiscCam cam = DiscCamOscillatingExample();
  const Deviations<double> d{0.005, 0.019, 0.009};
  for (int i = 0; i < 360; ++i) {
    const double t = 2 * kPi * i / 360;
    const CamPoint<double> p = EvaluateCam(cam, t);
    const MechanicalError<double> e = FollowerError(cam, p, d);
    const double linear = e.normal + e.radial + e.roller;
    const double exact = ExactFollowerPosition(cam, d, t) - p.s;
    EXPECT_NEAR(exact, linear, 1e-3 * std::abs(linear)) << t;
    EXPECT_LE(std::abs(exact), e.worst_case * (1 + 1e-3));
  }
}

// The exact follower position against a construction of its own: the outermost follower
// coordinate S at which the roller circle of radius r_f + Δr_f still reaches the perturbed profile,
// S* with min over t of |C(S*, θ) − P(t)| = r (the profile's distance found by a dense scan of
// ±3° and golden sections, S* by bisection). The search the Monte-Carlo runs (a 13-point scan,
// then Brent's method from the best sample and its neighbours, stopped where the parabola
// promises less than 1e-13) agrees with it to the rounding of its trigonometric functions, at
// the tolerance scales the examples use (1, 10 and 100).
void CheckExactPositionAgainstDistance(const DiscCam& cam, const Deviations<double>& tol) {
  const double s0 = InitialFollowerCoordinate(cam);
  const auto centre = [&](double s, double theta) -> Vec2<double> {
    const Vec2<double> u = U(theta);
    if (cam.follower == FollowerType::kTranslatingRoller) return (s0 + s) * u + cam.offset * Perp(u);
    return cam.pivot_distance * u + cam.arm_length * U(theta + kPi - (s0 + s));
  };
  const auto profile = [&](double t, const Deviations<double>& d) -> Vec2<double> {
    const CamPoint<double> p = EvaluateCam(cam, t);
    return p.contact + d.normal * p.normal + d.radial * p.contact / p.radial_dimension;
  };
  const auto distance = [&](const Vec2<double>& c, double theta, const Deviations<double>& d) {
    const double window = 3.0 * kDeg;
    const int n = 240;
    int best = 0;
    double best_d = 1e300;
    for (int k = 0; k <= n; ++k) {
      const double dk = (c - profile(theta - window + 2 * window * k / n, d)).norm();
      if (dk < best_d) best_d = dk, best = k;
    }
    const double h = 2 * window / n, t = theta - window + best * h;
    const GoldenSectionBracket b =
        GoldenSectionMaximize([&](double x) { return -(c - profile(x, d)).norm(); }, t - h, t + h, 200, 1e-10);
    return std::min(best_d, -std::max(b.f1, b.f2));
  };
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  double largest = 0.0;
  for (double scale : {1.0, 10.0, 100.0}) {
    for (int i = 0; i < 12; ++i) {
      const double theta = 2 * kPi * (i + 0.29) / 12;
      const Deviations<double> d{scale * tol.normal * unit(rng), scale * tol.radial * unit(rng),
                                 scale * tol.roller * unit(rng)};
      const double r = cam.roller_radius + d.roller;
      const double nominal = cam.motion.Evaluate(theta).s;
      // Around the linear model's position (eqs. 16–30), half its change either side: inside the
      // roller overlaps the profile, outside it clears it (both asserted).
      const MechanicalError<double> e = FollowerError(cam, EvaluateCam(cam, theta), d);
      const double linear = e.normal + e.radial + e.roller;
      const double span = 0.5 * std::abs(linear) + 1e-6;
      double in = nominal + linear - span, out = nominal + linear + span;
      ASSERT_LT(distance(centre(in, theta), theta, d), r);
      ASSERT_GT(distance(centre(out, theta), theta, d), r);
      for (int it = 0; it < 200 && out - in > 1e-15; ++it) {
        const double mid = 0.5 * (in + out);
        (distance(centre(mid, theta), theta, d) < r ? in : out) = mid;
      }
      const double reference = 0.5 * (in + out);
      const double exact = ExactFollowerPosition(cam, d, theta);
      largest = std::max(largest, std::abs(exact - reference));
      // 2e-13 mm (translating) or rad (oscillating: 1.6e-11 mm at the 80 mm arm); measured
      // 2.5e-14 mm and 2.3e-15 rad, and 4.9e-12 mm and 9.0e-9 rad with the search stopped at 1e-9.
      EXPECT_NEAR(exact, reference, 2e-13) << "scale " << scale << " at " << theta;
    }
  }
  EXPECT_GT(largest, 0.0);  // the two constructions are not the same code
}

TEST(DiscCamError, TranslatingExactPositionIsWhereTheRollerLastReachesTheProfile) {
  CheckExactPositionAgainstDistance(DiscCamPaperExample(), {0.005, 0.019, 0.009});
}
TEST(DiscCamError, OscillatingExactPositionIsWhereTheRollerLastReachesTheProfile) {
  CheckExactPositionAgainstDistance(DiscCamOscillatingExample(), {0.005, 0.019, 0.009});
}

TEST(DiscCamError, PaperExampleCurvesHaveTheShapeOfFig12) {
  // IT6: Δr = 19 µm, Δr_f = 9 µm. Fig. 12 and §5: ΔS_rf = Δr_f / cos φ ≥ Δr_f; the shift angle
  // counteracts the pressure angle, so ΔS_r varies less than ΔS_rf; φ and λ have similar trends;
  // ΔS_wor = ΔS_r + ΔS_rf ≥ ΔS_rms.
  const DiscCam cam = DiscCamPaperExample();
  const Deviations<double> tol{0.0, 0.019, 0.009};
  double wor_max = 0, wor_at = 0, r_max = 0, r_max_without_shift = 0;
  for (int i = 0; i < 3600; ++i) {
    const double t = 2 * kPi * i / 3600;
    const CamPoint<double> p = EvaluateCam(cam, t);
    const MechanicalError<double> e = FollowerError(cam, p, tol);
    EXPECT_GE(e.roller, 0.009 - 1e-15);
    EXPECT_NEAR(e.worst_case, std::abs(e.radial) + std::abs(e.roller), 1e-15);
    EXPECT_LE(e.rms, e.worst_case);
    EXPECT_GE(e.rms * std::sqrt(2.0), e.worst_case - 1e-15);
    // "the ratio cos λ / cos φ stays close to 1"; λ and φ have the same sign while moving.
    const double ratio = std::cos(p.shift_angle) / std::cos(p.pressure_angle);
    EXPECT_GT(ratio, 0.9);
    EXPECT_LT(ratio, 1.1);
    if (std::abs(p.shift_angle) > 1 * kDeg) {
      EXPECT_GT(p.shift_angle * p.ds, 0.0) << t;
    }
    r_max = std::max(r_max, e.radial);
    r_max_without_shift = std::max(r_max_without_shift, 0.019 / std::cos(p.pressure_angle));
    if (e.worst_case > wor_max) wor_max = e.worst_case, wor_at = t;
  }
  // The shift angle counteracts the pressure angle: the peak of ΔS_r is below Δr / cos φ.
  EXPECT_LT(r_max, r_max_without_shift);
  // The extreme lies in the rise or return, where the pressure angle is largest.
  EXPECT_TRUE((wor_at > 0 && wor_at < 120 * kDeg) || (wor_at > 170 * kDeg && wor_at < 290 * kDeg));
  EXPECT_GT(wor_max, 0.028);
}

TEST(DiscCamError, MonteCarloShowsTheLinearModelHoldsAtToleranceScale) {
  const DiscCam cam = DiscCamPaperExample();
  MonteCarloOptions opt;
  opt.samples = 20;
  opt.angle_steps = 90;
  opt.scales = {1.0, 1000.0};
  const auto mc = MonteCarloLinearisation(cam, {0.0, 0.019, 0.009}, opt);
  ASSERT_EQ(mc.size(), 2u);
  // Second-order terms scale with the square of the deviations: relative error grows ~ scale.
  EXPECT_LT(mc[0].relative_difference, 1e-3);
  EXPECT_GT(mc[1].relative_difference, 10 * mc[0].relative_difference);
  EXPECT_EQ(mc[0].within_bound_fraction, 1.0);
  EXPECT_LE(mc[0].bound_exceed, 1e-6);
}

TEST(DiscCamGradients, TranslatingPointMatchesCentralDifferences) {
  auto f = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    const DiscCamTpl<T> cam = DiscCamPaperExample<T>(x[0], x[1], x[2], x[3]);
    std::vector<T> out;
    for (double th : {0.4, 1.3, 2.5, 3.9, 5.8}) {
      const CamPoint<T> p = EvaluateCam(cam, T(th));
      const MechanicalError<T> e = FollowerError(cam, p, Deviations<T>{T(0.0), T(0.019), T(0.009)});
      out.insert(out.end(), {p.contact.x(), p.contact.y(), p.pressure_angle, p.shift_angle,
                             p.pitch_curvature, p.radial_dimension, e.worst_case, e.rms});
    }
    return out;
  };
  camopt::testing::ExpectJacobianMatchesCentralDifferences<4>(f, {40.0, 10.0, 12.0, 24.0}, 1e-6, 1e-9);
}

TEST(DiscCamGradients, OscillatingPointMatchesCentralDifferences) {
  auto f = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    const DiscCamTpl<T> cam = DiscCamOscillatingExample<T>(x[0], x[1], x[2], x[3], x[4]);
    std::vector<T> out;
    for (double th : {0.4, 1.3, 2.5, 3.9, 5.8}) {
      const CamPoint<T> p = EvaluateCam(cam, T(th));
      const MechanicalError<T> e = FollowerError(cam, p, Deviations<T>{T(0.0), T(0.019), T(0.009)});
      out.insert(out.end(), {p.contact.x(), p.contact.y(), p.pressure_angle, p.shift_angle,
                             p.pitch_curvature, p.radial_dimension, e.worst_case, e.rms});
    }
    return out;
  };
  camopt::testing::ExpectJacobianMatchesCentralDifferences<5>(
      f, {40.0, 10.0, 100.0, 80.0, 20 * kDeg}, 1e-6, 1e-9);
}

TEST(DiscCamSummary, AggregatesAgreeWithThePaperExampleAndUndercut) {
  const CamSummary<double> s = SummarizeCam(DiscCamPaperExample(), Deviations<double>{0.0, 0.019, 0.009}, 3600);
  EXPECT_NEAR(s.max_radial_dimension, 63.525, 5e-4);
  EXPECT_GT(s.curvature_margin, 0.0);  // no undercut
  EXPECT_GE(s.soft_max_abs_pressure_angle, s.max_abs_pressure_angle);
  EXPECT_LE(s.soft_max_abs_pressure_angle, s.max_abs_pressure_angle + std::log(3600.0) / 50.0);
  EXPECT_LE(s.max_rms_error, s.max_worst_case_error);
}

TEST(DiscCamGradients, SummaryMatchesCentralDifferences) {
  auto f = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    const DiscCamTpl<T> cam = DiscCamPaperExample<T>(x[0], x[1], x[2], x[3]);
    const CamSummary<T> s = SummarizeCam(cam, Deviations<T>{T(0.0), T(0.019), T(0.009)}, 360);
    return std::vector<T>{s.max_radial_dimension, s.max_abs_pressure_angle,
                          s.soft_max_abs_pressure_angle, s.curvature_margin,
                          s.max_worst_case_error, s.max_rms_error};
  };
  camopt::testing::ExpectJacobianMatchesCentralDifferences<4>(f, {40.0, 10.0, 12.0, 24.0}, 1e-5, 1e-9);
}

// CheckDesign: one test per kind of issue, each on a design that breaks exactly that rule.
const DesignIssue* Find(const std::vector<DesignIssue>& issues, const std::string& words) {
  for (const auto& i : issues)
    if (i.message.find(words) != std::string::npos) return &i;
  return nullptr;
}

TEST(DiscCamCheckDesign, TheExamplesAreFeasible) {
  EXPECT_TRUE(CheckDesign(DiscCamPaperExample(), 3600).empty());
  EXPECT_TRUE(CheckDesign(DiscCamOscillatingExample(), 3600).empty());
}

TEST(DiscCamCheckDesign, OffsetBeyondBaseCircleAndRoller) {
  const auto issues = CheckDesign(DiscCamPaperExample(40.0, 10.0, 55.0), 360);
  ASSERT_EQ(issues.size(), 1u);  // the geometry fails: the cycle is not evaluated
  EXPECT_EQ(issues[0].field, "offset");
  EXPECT_EQ(issues[0].value, 55.0);
  EXPECT_EQ(issues[0].limit, 50.0);  // r_b + r_f
  // The fix: |e| < 50 mm, or r_b > |e| − r_f = 45 mm.
  EXPECT_NE(issues[0].message.find("less than 50 mm"), std::string::npos) << issues[0].message;
  EXPECT_NE(issues[0].message.find("above 45 mm"), std::string::npos) << issues[0].message;
  EXPECT_TRUE(CheckGeometry(DiscCamPaperExample(40.0, 10.0, -49.0)).empty());
}

TEST(DiscCamCheckDesign, ArmThatCannotReachTheBaseCircle) {
  // f = 100, l = 20: the roller centre stays ≥ 80 mm from the cam centre, the base circle + roller
  // is 50 mm.
  const auto issues = CheckDesign(DiscCamOscillatingExample(40.0, 10.0, 100.0, 20.0), 360);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "arm_length");
  EXPECT_EQ(issues[0].value, 50.0);
  EXPECT_EQ(issues[0].limit, 80.0);  // |f − l|, the bound broken
  // |f − l| < 50 < f + l with f = 100 holds for 50 < l < 150.
  EXPECT_NE(issues[0].message.find("between 50 and 150 mm"), std::string::npos) << issues[0].message;
  // Too far the other way: f + l = 45 < 50.
  const auto other = CheckGeometry(DiscCamOscillatingExample(40.0, 10.0, 25.0, 20.0));
  ASSERT_EQ(other.size(), 1u);
  EXPECT_EQ(other[0].field, "arm_length");
  EXPECT_EQ(other[0].limit, 45.0);
}

TEST(DiscCamCheckDesign, FollowerInsideTheBaseCircle) {
  DiscCam cam = DiscCamPaperExample();
  cam.motion = motion::MotionProgram<double>({{MotionLaw::kCycloidal, -10.0, kPi},
                                              {MotionLaw::kCycloidal, 10.0, kPi}});
  const auto issues = CheckDesign(cam, 360);
  const DesignIssue* inside = Find(issues, "inside the base circle");
  ASSERT_NE(inside, nullptr);
  EXPECT_EQ(inside, &issues[0]);
  EXPECT_EQ(inside->field, "motion");
  EXPECT_LT(inside->value, 0.0);
  ASSERT_TRUE(inside->cam_angle_rad.has_value());
  EXPECT_NEAR(*inside->cam_angle_rad, 2 * kPi / 360, 1e-15);  // the first sample after θ = 0
}

TEST(DiscCamCheckDesign, ArmCrossingTheCamCentreLine) {
  // ξ₀ = acos((80² + 100² − 50²)/(2·80·100)) ≈ 29.7°: a rise of 160° takes ξ past 180°.
  const auto issues = CheckDesign(DiscCamOscillatingExample(40.0, 10.0, 100.0, 80.0, 160 * kDeg), 360);
  const DesignIssue* arm = Find(issues, "leaves (0, 180) deg");
  ASSERT_NE(arm, nullptr);
  EXPECT_EQ(arm->field, "motion");
  EXPECT_EQ(arm->limit, kPi);
  const double xi0 = std::acos((80.0 * 80 + 100.0 * 100 - 50.0 * 50) / (2 * 80.0 * 100));
  EXPECT_GE(arm->value, kPi);
  EXPECT_LE(arm->value, xi0 + 160 * kDeg + 1e-12);
}

TEST(DiscCamCheckDesign, PressureAngleAtTheJamLimit) {
  DiscCam cam = DiscCamPaperExample();
  cam.motion = motion::MotionProgram<double>({{MotionLaw::kCycloidal, 80.0, 1 * kDeg},
                                              {MotionLaw::kCycloidal, -80.0, 359 * kDeg}});
  const auto issues = CheckDesign(cam, 3600);
  const DesignIssue* jam = Find(issues, "would jam");
  ASSERT_NE(jam, nullptr);
  EXPECT_EQ(jam->field, "motion");
  EXPECT_GE(std::abs(jam->value), 89 * kDeg);
  EXPECT_EQ(jam->limit, kJamPressureAngle);
  EXPECT_LT(jam->cam_angle_rad.value(), 1 * kDeg);  // within the 1° rise
  EXPECT_NEAR(kJamPressureAngle, 89 * kDeg, 1e-15);
}

TEST(DiscCamMechanicalError, RadialErrorRatioOnTheBaseCircle) {
  // Translating, low dwell: λ = 0 and cos φ = L₀/(r_b + r_f), L₀ = sqrt(50² − 12²).
  const CamPoint<double> p = EvaluateCam(DiscCamPaperExample(), 330 * kDeg);
  EXPECT_NEAR(RadialErrorRatio(p), 50.0 / std::sqrt(50.0 * 50.0 - 144.0), 1e-12);
}

TEST(DiscCam, OscillatingPivotAndArm) {
  // The pivot sits at distance f from the cam centre and the roller centre at l from the pivot.
  const DiscCam cam = DiscCamOscillatingExample();
  for (double t : {0.0, 1.0, 4.0}) {
    const Vec2<double> o3 = FollowerPivot(cam, t);
    EXPECT_NEAR(o3.norm(), 100.0, 1e-12);
    EXPECT_NEAR((EvaluateCam(cam, t).pitch - o3).norm(), 80.0, 1e-12);
  }
}

TEST(DiscCamMechanicalError, RollerCentreDisplacementPerFollowerUnit) {
  EXPECT_EQ(RollerCentreMmPerFollowerUnit(DiscCamPaperExample()), 1.0);
  EXPECT_EQ(RollerCentreMmPerFollowerUnit(DiscCamOscillatingExample()), 80.0);  // the arm length l
}

}  // namespace disc_cam_test
}  // namespace camopt::disc_cam
