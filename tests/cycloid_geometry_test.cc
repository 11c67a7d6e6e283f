// Tests of the cycloid tooth geometry, crowning and unloaded TCA (model/cycloid/).
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "model/cycloid/crowning.h"
#include "model/cycloid/output_mechanism.h"
#include "model/cycloid/tooth_profile.h"
#include "model/cycloid/unloaded_tca.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt::cycloid {
namespace cycloid_geometry_test {

// The paper's example (Table 2) with NNM (Table 3): Δa = −16 µm, Δρ = −8 µm.
Drive PaperDrive(bool nnm) {
  return nnm ? camopt::testing::CycloidNnm() : Drive{};  // Drive's defaults are Table 2
}

// Independent construction of the modified tooth: the roller-centre curve X'(t) written out,
// its normal from central differences of sampled points (no analytic derivative), offset by ρ'.
std::vector<Vec2<double>> SampledProfile(const Drive& d, double t_lo, double t_hi, int n) {
  const double a = d.roller_position_radius_mm + d.delta_position_mm;
  const double rho = d.roller_radius_mm + d.delta_radius_mm;
  const double e = d.eccentricity_mm;
  auto x = [&](double t) {
    return Vec2<double>(a * std::cos(t) - e * std::cos(d.rollers * t),
                        a * std::sin(t) - e * std::sin(d.rollers * t));
  };
  std::vector<Vec2<double>> pts;
  const double h = 1e-5;
  for (int k = 0; k <= n; ++k) {
    const double t = t_lo + (t_hi - t_lo) * k / n;
    const Vec2<double> tangent = (x(t + h) - x(t - h)).normalized();
    const Vec2<double> outward(tangent.y(), -tangent.x());  // right of a counter-clockwise curve
    pts.push_back(x(t) - rho * outward);
  }
  return pts;
}

// Roller centre in the disc frame, written independently: the disc centre e u(φ) and its angle
// −φ/n2 + β in the fixed frame; the roller's fixed position expressed in the disc axes.
Vec2<double> RollerInDisc(const Drive& d, int i, double crank, double beta) {
  const double psi = 2.0 * kPi * i / d.rollers;
  const Vec2<double> fixed(d.roller_position_radius_mm * std::cos(psi),
                           d.roller_position_radius_mm * std::sin(psi));
  const Vec2<double> centre(d.eccentricity_mm * std::cos(crank), d.eccentricity_mm * std::sin(crank));
  const double disc_angle = -crank / d.teeth + beta;
  const Vec2<double> rel = fixed - centre;
  const double c = std::cos(disc_angle), s = std::sin(disc_angle);
  return Vec2<double>(c * rel.x() + s * rel.y(), -s * rel.x() + c * rel.y());  // R(−angle) rel
}

// Brute-force signed distance between roller i's circle and the sampled tooth near its contact.
double BruteForceGap(const Drive& d, int i, double crank, double beta) {
  const double t0 = 2.0 * kPi * i / d.rollers + crank / d.teeth;
  const auto pts = SampledProfile(d, t0 - 0.08, t0 + 0.08, 40000);
  const Vec2<double> c = RollerInDisc(d, i, crank, beta);
  double best = 1e300;
  for (const auto& p : pts) best = std::min(best, (p - c).norm());
  return best - d.roller_radius_mm;
}

TEST(CycloidGeometry, UnmodifiedProfileHasZeroBacklash) {
  const Drive d = PaperDrive(false);
  EXPECT_TRUE(CheckDrive(d).empty());
  for (double deg : {0.0, 7.0, 120.0, 300.0, 333.3}) {
    const auto m = UnloadedTca<double>(d, deg * kPi / 180.0);
    int loaded = 0;
    for (const auto& g : m.pairs) {
      if (!g.loaded_flank) continue;
      ++loaded;
      EXPECT_NEAR(g.contact_rotation, 0.0, 1e-12) << deg << " deg, roller " << g.roller;
      EXPECT_NEAR(g.backlash, 0.0, 1e-12);
    }
    EXPECT_GE(loaded, 5) << "about half the rollers are on the loaded flank";
    EXPECT_NEAR(m.rotation, 0.0, 1e-12);
  }
}

TEST(CycloidGeometry, UnmodifiedRollersTouchTheSampledProfile) {
  // Independent: every roller circle touches the sampled unmodified tooth (distance 0).
  const Drive d = PaperDrive(false);
  for (int i : {1, 3, 6, 11}) EXPECT_NEAR(BruteForceGap(d, i, 0.7, 0.0), 0.0, 1e-7) << i;
}

TEST(CycloidGeometry, UnloadedTcaMatchesBruteForceDistance) {
  const Drive d = PaperDrive(true);
  for (double deg : {0.0, 50.0, 120.0}) {
    const double crank = deg * kPi / 180.0;
    const auto m = UnloadedTca<double>(d, crank);
    ASSERT_GE(m.first_contact, 0);
    for (const auto& g : m.pairs) {
      if (!g.loaded_flank || g.backlash > 2e-4) continue;
      // At its own contact rotation the pair touches (distance 0) ...
      EXPECT_NEAR(BruteForceGap(d, g.roller, crank, g.contact_rotation), 0.0, 2e-7)
          << deg << " deg, roller " << g.roller;
      // ... and at the settled disc rotation β0 it has a clearance ≥ 0, about l_i · backlash.
      const double gap = BruteForceGap(d, g.roller, crank, m.rotation);
      EXPECT_GE(gap, -2e-7);
      EXPECT_NEAR(gap, g.arm_mm * g.backlash, 2e-7 + 0.01 * g.arm_mm * g.backlash);
    }
    // The first-contact pair touches at β0.
    EXPECT_NEAR(BruteForceGap(d, m.pairs[m.first_contact].roller, crank, m.rotation), 0.0, 2e-7);
  }
}

TEST(CycloidGeometry, NnmClearanceMatchesTheModificationFormula) {
  // Generating with a' = a + Δa, ρ' = ρ + Δρ moves the tooth outwards by Δa (u(t)·N) − Δρ, so the
  // clearance to the roller at β = 0 is −Δa (u·N) + Δρ to first order in the modification (the
  // second-order term is ~Δa²/R, about 1e-5 mm here).
  const Drive d = PaperDrive(true);
  const double crank = 0.3;
  for (int i : {2, 4, 6}) {
    const double t = NominalParameter(d, i, crank);
    const auto p = ToothProfile<double>(PaperDrive(false), t);
    const double expected = -d.delta_position_mm * U(t).dot(p.normal) + d.delta_radius_mm;
    EXPECT_NEAR(BruteForceGap(d, i, crank, 0.0), expected, 3e-5) << i;
    EXPECT_GT(expected, 0.0) << "NNM has clearance everywhere on this drive";
  }
}

TEST(CycloidGeometry, RatioAndMeshPeriodicity) {
  const Drive d = PaperDrive(true);
  // The roller-centre curve has n2 lobes: X(t + 2π/n2) = R(2π/n2) X(t).
  for (double t : {0.1, 1.3}) {
    const auto p0 = ToothProfile<double>(d, t);
    const auto p1 = ToothProfile<double>(d, t + 2 * kPi / d.teeth);
    const Vec2<double> r = Rotate(p0.point, 2 * kPi / d.teeth);
    EXPECT_NEAR((p1.point - r).norm(), 0.0, 1e-12);
  }
  // The unloaded TE repeats every mesh period 2π/n1 of crank angle, so over a crank revolution
  // the disc turns exactly 2π/n2: the ratio of the drive is n2.
  for (double crank : {0.2, 1.0, 2.5}) {
    const auto m0 = UnloadedTca<double>(d, crank);
    const auto m1 = UnloadedTca<double>(d, crank + 2 * kPi / d.rollers);
    EXPECT_NEAR(m0.rotation, m1.rotation, 1e-12);
  }
  // Kinematics: with zero backlash the roller stays on the curve while the disc turns −φ/n2.
  const Drive u = PaperDrive(false);
  for (double crank : {0.4, 2.0}) {
    const Vec2<double> c = RollerInDisc(u, 3, crank, 0.0);
    const auto p = ToothProfile<double>(u, 2 * kPi * 3 / u.rollers + crank / u.teeth);
    EXPECT_NEAR((c - p.centre).norm(), 0.0, 1e-12);
  }
}

TEST(CycloidGeometry, CrowningDropsMatchTheirFormulas) {
  const double b = 17.0;
  Crowning f;
  f.type = CrowningType::kFull;
  f.radius_mm = 3000;
  Crowning p;
  p.type = CrowningType::kPartial;
  p.radius_mm = 4500;
  p.flat_length_mm = 13.6;
  Crowning l;
  l.type = CrowningType::kLogarithmic;
  l.coefficient_mm = 0.005;
  for (double u : {-8.2875, -7.0, -3.0, 0.0, 2.5, 6.8, 7.5, 8.2875}) {
    EXPECT_NEAR(CrowningDrop(f, b, u), 3000.0 - std::sqrt(3000.0 * 3000.0 - u * u), 1e-12);
    const double s = std::abs(u) > 6.8 ? std::abs(u) - 6.8 : 0.0;
    EXPECT_NEAR(CrowningDrop(p, b, u), 4500.0 - std::sqrt(4500.0 * 4500.0 - s * s), 1e-12);
    EXPECT_NEAR(CrowningDrop(l, b, u), 0.005 * std::log(1.0 / (1.0 - std::pow(2 * u / b, 2))), 1e-15);
    EXPECT_DOUBLE_EQ(CrowningDrop(l, b, u), CrowningDrop(l, b, -u));
  }
  EXPECT_EQ(CrowningDrop(p, b, 6.0), 0.0);  // on the flat
  Crowning none;
  EXPECT_EQ(CrowningDrop(none, b, 8.0), 0.0);
  l.coefficient_mm = 0.0;  // f → 0: no drop, finite even at the outermost cell
  EXPECT_EQ(CrowningDrop(l, b, 8.49), 0.0);
  l.coefficient_mm = 0.005;
  l.effective_length_mm = 25.0;
  EXPECT_NEAR(CrowningDrop(l, b, 8.5), 0.005 * std::log(1.0 / (1.0 - std::pow(17.0 / 25.0, 2))), 1e-15);
  EXPECT_NE(CheckCrowning(l, 30.0), "");  // effective length below the face width
}

TEST(CycloidGeometry, LogarithmicCrowningWithAnEndDropIsFinite) {
  // Fujiwara-Kawase form: a flat of L0, then f ln(1 / (1 - (1 - exp(-zm/f)) s^2)), s from 0 at the
  // flat's end to 1 at L/2 where the drop is zm.
  const double b = 17.0;
  Crowning c;
  c.type = CrowningType::kLogarithmic;
  c.coefficient_mm = 0.002;
  c.end_drop_mm = 0.01;
  c.flat_length_mm = 4.0;
  c.effective_length_mm = 18.0;
  EXPECT_NEAR(CrowningDrop(c, b, 9.0), 0.01, 1e-15);   // the end of L (outside the face; formula only)
  EXPECT_EQ(CrowningDrop(c, b, 1.5), 0.0);             // on the flat
  for (double u : {-8.4, -5.0, 2.5, 7.0, 8.49}) {
    const double s = (std::abs(u) - 2.0) / (9.0 - 2.0);
    const double expected = 0.002 * std::log(1.0 / (1.0 - (1.0 - std::exp(-0.01 / 0.002)) * s * s));
    EXPECT_NEAR(CrowningDrop(c, b, u), expected, 1e-15);
    EXPECT_LT(CrowningDrop(c, b, u), 0.01);
  }
  // A large end drop tends to eq. 7 over the crowned part; a zero coefficient is no crowning.
  c.end_drop_mm = 1.0;
  const double s = (7.0 - 2.0) / 7.0;
  EXPECT_NEAR(CrowningDrop(c, b, 7.0), 0.002 * std::log(1.0 / (1.0 - s * s)), 1e-12);
  c.coefficient_mm = 0.0;
  EXPECT_EQ(CrowningDrop(c, b, 8.0), 0.0);
  c.end_drop_mm = -1e-3;
  EXPECT_NE(CheckCrowning(c, b), "");
}

TEST(CycloidGeometry, InfeasibleDrivesAreReported) {
  Drive d = PaperDrive(false);
  d.eccentricity_mm = 6.0;  // e n1 = 96 > a
  auto issues = CheckDrive(d);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "eccentricity_mm");
  EXPECT_EQ(issues[0].value, 6.0);
  EXPECT_NEAR(issues[0].limit, d.roller_position_radius_mm / 16.0, 1e-12);  // e < a'/N
  EXPECT_NE(issues[0].message.find("16 rollers"), std::string::npos) << issues[0].message;
  d = PaperDrive(false);
  d.rollers = 17;
  issues = CheckDrive(d);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "rollers");
  EXPECT_EQ(issues[0].limit, 16.0);
  d = PaperDrive(false);
  d.roller_radius_mm = 20.0;  // rollers overlap
  issues = CheckDrive(d);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "roller_radius_mm");
  EXPECT_EQ(issues[0].value, 20.0);
  EXPECT_NEAR(issues[0].limit, d.roller_position_radius_mm * std::sin(kPi / 16), 1e-12);  // ρ < a sin(π/N)
}

TEST(CycloidGeometry, UnloadedTcaGradientsMatchCentralDifferences) {
  // Inputs: Δa, Δρ [mm], e [mm], crank angle [rad]. Outputs: β_i, l_i, tooth curvature for two
  // loaded pairs, and β0 (at a crank angle away from a switch of the first-contact pair).
  auto f = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    DriveTpl<T> d;
    d.delta_position_mm = x[0];
    d.delta_radius_mm = x[1];
    d.eccentricity_mm = x[2];
    const auto m = UnloadedTca<T>(d, x[3]);
    std::vector<T> out;
    for (int i : {2, 4}) {
      out.push_back(m.pairs[i].contact_rotation * T(1e4));
      out.push_back(m.pairs[i].arm_mm);
      out.push_back(m.pairs[i].profile_curvature);
    }
    out.push_back(m.rotation * T(1e4));
    return out;
  };
  camopt::testing::ExpectJacobianMatchesCentralDifferences<4>(f, {-0.016, -0.008, 4.5, 0.05}, 1e-5,
                                                              1e-7);
}

TEST(CycloidGeometry, CrowningGradientsMatchCentralDifferences) {
  auto f = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    return std::vector<T>{
        CrowningDrop<T>(CrowningType::kLogarithmic, T(0), T(0), x[0], x[2], x[1]),
        CrowningDrop<T>(CrowningType::kFull, x[2] * T(200), T(0), T(0), T(0), x[1]),
        CrowningDrop<T>(CrowningType::kPartial, x[2] * T(200), T(13.6), T(0), T(0), x[1])};
  };
  camopt::testing::ExpectJacobianMatchesCentralDifferences<3>(f, {0.005, 7.3, 17.5}, 1e-6, 1e-10);
}

// DriveTpl::cast and OutputPinsTpl::cast: every member carried over, the integers as they are, a Jet
// drive from a double one with zero derivatives, and the values back.
TEST(CycloidGeometry, CastCarriesEveryMemberBetweenScalars) {
  using J = ceres::Jet<double, 2>;
  Drive d;
  d.teeth = 29;
  d.rollers = 30;
  d.roller_position_radius_mm = 61.5;
  d.roller_radius_mm = 3.25;
  d.eccentricity_mm = 1.75;
  d.face_width_mm = 9.5;
  d.delta_position_mm = 0.012;
  d.delta_radius_mm = -0.004;
  const DriveTpl<J> dj = d.cast<J>();
  const double* in[] = {&d.roller_position_radius_mm, &d.roller_radius_mm, &d.eccentricity_mm,
                        &d.face_width_mm, &d.delta_position_mm, &d.delta_radius_mm};
  const J* jet[] = {&dj.roller_position_radius_mm, &dj.roller_radius_mm, &dj.eccentricity_mm,
                    &dj.face_width_mm, &dj.delta_position_mm, &dj.delta_radius_mm};
  EXPECT_EQ(dj.teeth, 29);
  EXPECT_EQ(dj.rollers, 30);
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(jet[k]->a, *in[k]) << k;
    EXPECT_EQ(jet[k]->v.norm(), 0.0) << k;
  }
  DriveTpl<J> seeded = dj;
  seeded.eccentricity_mm.v[0] = 1.0;
  const Drive back = seeded.cast<double>();
  const double* out[] = {&back.roller_position_radius_mm, &back.roller_radius_mm, &back.eccentricity_mm,
                         &back.face_width_mm, &back.delta_position_mm, &back.delta_radius_mm};
  for (int k = 0; k < 6; ++k) EXPECT_EQ(*out[k], *in[k]) << k;
  EXPECT_EQ(back.teeth, 29);
  EXPECT_EQ(back.rollers, 30);

  OutputPins m;
  m.pins = 10;
  m.pin_circle_radius_mm = 40.0;
  m.pin_radius_mm = 4.0;
  m.hole_radius_mm = 7.5;
  m.roller_radius_mm = 5.0;
  m.face_width_mm = 9.5;
  m.e_star_MPa = 113000.0;
  m.linear_stiffness_N_per_mm = 2.5e5;
  const OutputPins mb = m.cast<J>().cast<double>();
  EXPECT_EQ(mb.pins, 10);
  EXPECT_EQ(mb.pin_circle_radius_mm, 40.0);
  EXPECT_EQ(mb.pin_radius_mm, 4.0);
  EXPECT_EQ(mb.hole_radius_mm, 7.5);
  EXPECT_EQ(mb.roller_radius_mm, 5.0);
  EXPECT_EQ(mb.face_width_mm, 9.5);
  EXPECT_EQ(mb.e_star_MPa, 113000.0);
  EXPECT_EQ(mb.linear_stiffness_N_per_mm, 2.5e5);
}

}  // namespace cycloid_geometry_test
}  // namespace camopt::cycloid
