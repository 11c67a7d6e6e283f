// Tests of the lobe cam reducer pipeline: kinematics, profiles, curvature, contact, forces,
// torques, efficiency and Hertz stress, against closed forms, independent constructions,
// invariants and the paper's Table 3.
#include <array>
#include <cmath>
#include <type_traits>
#include <stdexcept>
#include <vector>

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "model/lcr/cycle.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt::lcr {
namespace lcr_test {

using camopt::testing::LcrI;
using camopt::testing::LcrII;
using camopt::testing::LcrIII;
using camopt::testing::Steel;

TEST(LcrKinematics, PaperRatiosAreExact) {
  EXPECT_DOUBLE_EQ(SpeedReductionRatio(LcrI()), -399.0);
  EXPECT_DOUBLE_EQ(SpeedReductionRatio(LcrII()), -90.0);
  EXPECT_DOUBLE_EQ(SpeedReductionRatio(LcrIII()), -24.0);
  // Table 1: the ratio is the inverse of the output speed ratio, for any counts.
  for (auto [ma, na, mb, nb] : {std::array{12, 13, 14, 15}, std::array{7, 10, 9, 11}, std::array{5, 6, 3, 5}}) {
    EXPECT_NEAR(SpeedReductionRatio(ma, na, mb, nb) * OutputSpeedRatio(ma, na, mb, nb), 1.0, 1e-12);
  }
  EXPECT_TRUE(std::isinf(SpeedReductionRatio(12, 13, 12, 13)));
}

// The output turret angle of eq. 2 keeps every output roller on the output cam's pitch curve:
// transform the roller centres into the cam frame by the paper's rigid-body transformation and
// find the nearest point of the closed-form pitch curve.
TEST(LcrProfile, RollersStayOnTheClosedFormPitchCurve) {
  const Reducer<double> r = LcrII();
  for (Side s : {Side::kInput, Side::kOutput}) {
    const auto& c = r.side(s);
    for (double theta : {0.1, 1.3, 2.9, 5.0}) {
      const double cam_angle = CamSpeedRatio(r) * theta;
      const Vec2<double> oc = r.eccentricity * U(theta);
      for (const Vec2<double>& o : RollerCentres(r, s, theta)) {
        const Vec2<double> x = Rotate<double>(o - oc, -cam_angle);
        double best = 1e9, best_psi = 0;
        for (int i = 0; i < 20000; ++i) {
          const double psi = 2 * kPi * i / 20000;
          const double dist = (PitchPoint(c, r.eccentricity, psi) - x).norm();
          if (dist < best) best = dist, best_psi = psi;
        }
        for (double h = 2 * kPi / 20000; h > 1e-14; h *= 0.5)  // refine by pattern search
          for (double step : {-h, h})
            if (double d = (PitchPoint(c, r.eccentricity, best_psi + step) - x).norm(); d < best)
              best = d, best_psi += step;
        EXPECT_LT(best, 1e-7) << "side " << int(s) << " theta " << theta;
      }
    }
  }
}

TEST(LcrProfile, CurvatureMatchesFiniteDifferencesOfTheCurve) {
  const Reducer<double> r = LcrII();
  for (Side s : {Side::kInput, Side::kOutput}) {
    const auto& c = r.side(s);
    const double k = c.pitch_factor();
    for (double psi : {0.0, 0.2, 0.7, 1.9, 3.0}) {
      const double h = 1e-4;
      const Vec2<double> xm = PitchPoint(c, r.eccentricity, psi - h), x0 = PitchPoint(c, r.eccentricity, psi),
                         xp = PitchPoint(c, r.eccentricity, psi + h);
      const Vec2<double> d1 = (xp - xm) / (2 * h), d2 = (xp - 2 * x0 + xm) / (h * h);
      const double numeric = Cross(d1, d2) / std::pow(d1.norm(), 3);
      const double closed = PitchCurvature(c, r.eccentricity, std::cos((k - 1) * psi));
      EXPECT_NEAR(closed, numeric, 1e-5 * std::max(1.0, std::abs(numeric)));
      // The inward normal is the left normal of the counter-clockwise curve.
      const Vec2<double> n = InwardNormal(c, r.eccentricity, psi);
      EXPECT_NEAR(n.dot(Perp<double>(d1) / d1.norm()), 1.0, 1e-8);
    }
  }
}

TEST(LcrProfile, CircleCamLimit) {
  // With a vanishing eccentricity the pitch curve is the turret circle: κ = 1/r_d everywhere,
  // and the cam is a circle of radius r_d − r_r.
  Reducer<double> r = LcrII();
  r.eccentricity = 1e-9;
  for (double c : {-1.0, 0.0, 1.0}) EXPECT_NEAR(PitchCurvature(r.input, r.eccentricity, c), 1.0 / 37.0, 1e-9);
  EXPECT_NEAR(UndercutMargin(r.input, r.eccentricity), 37.0 - 6.0, 1e-6);
  const Vec2<double> p = OffsetPoint(r.input, r.eccentricity, 0.4, 6.0);
  EXPECT_NEAR(p.norm(), 31.0, 1e-6);
}

// Paper §3.2: the contact point is where the transformed cam profile lies at distance r_r from the
// roller centre. Solve that by root finding on the profile and compare with O_k + r_r d_k.
TEST(LcrContact, PitchPointContactsMatchThePapersDistanceCondition) {
  const Reducer<double> r = LcrII();
  for (Side s : {Side::kInput, Side::kOutput}) {
    const auto& c = r.side(s);
    for (double theta : {0.37, 2.2}) {
      const double cam_angle = CamSpeedRatio(r) * theta;
      const Vec2<double> oc = r.eccentricity * U(theta);
      auto profile = [&](double psi) {  // cam profile in the fixed frame
        return Vec2<double>(oc + Rotate<double>(OffsetPoint(c, r.eccentricity, psi, c.roller_radius), cam_angle));
      };
      for (const RollerContact<double>& rc : RollerContacts(r, s, theta)) {
        // Nearest profile point: coarse scan, then Newton on d/dψ |P − O|² = 0 (central differences).
        double best = 1e9, psi = 0;
        for (int i = 0; i < 4000; ++i) {
          const double t = 2 * kPi * i / 4000;
          if (double d = (profile(t) - rc.centre).norm(); d < best) best = d, psi = t;
        }
        auto g = [&](double t) { return (profile(t) - rc.centre).squaredNorm(); };
        for (int it = 0; it < 30; ++it) {
          const double h = 1e-5;
          const double d1 = (g(psi + h) - g(psi - h)) / (2 * h);
          const double d2 = (g(psi + h) - 2 * g(psi) + g(psi - h)) / (h * h);
          if (d2 <= 0) break;
          psi -= d1 / d2;
        }
        EXPECT_NEAR((profile(psi) - rc.centre).norm(), c.roller_radius, 1e-6);
        EXPECT_NEAR((profile(psi) - rc.point).norm(), 0.0, 1e-5);
      }
    }
  }
}

TEST(LcrForces, TorqueBalancesHoldAtEveryAngle) {
  const Reducer<double> r = LcrII();
  const LoadCase load{80000.0, 0.0, 0.0};
  const double ratio = SpeedReductionRatio(r);
  for (int i = 0; i < 50; ++i) {
    const double theta = 0.123 * i;
    const AngleLoads<double> a = AnalyzeAngle(r, Steel(), load, theta);
    double t_out = 0, t_fixed = 0, moment_oc = 0;
    const Vec2<double> oc = r.eccentricity * U(theta);
    Vec2<double> g(0, 0);
    for (auto [side, sign] : {std::pair{&a.output, -1.0}, std::pair{&a.input, 1.0}}) {
      for (size_t k = 0; k < side->force.size(); ++k) {
        const auto& c = side->contacts[k];
        const double torque = side->force[k] * Cross(c.centre, c.direction);
        (sign < 0 ? t_out : t_fixed) += std::abs(torque);
        moment_oc += side->force[k] * Cross<double>(c.point - oc, c.direction);
        g += side->force[k] * c.direction;
        EXPECT_GE(side->force[k], 0.0);
      }
    }
    EXPECT_NEAR(t_out, 80000.0, 1e-6);                                      // output turret (eq. 25)
    EXPECT_NEAR(t_fixed, 80000.0 * 14 * 13 / (15.0 * 12), 1e-6);            // fixed turret (eq. 24)
    EXPECT_NEAR(moment_oc, 0.0, 1e-6);                                      // cam is free to turn on O_c
    EXPECT_NEAR(a.input_torque, 80000.0 / std::abs(ratio), 1e-7);           // power balance, μ = 0
    EXPECT_NEAR(a.efficiency, 1.0, 1e-12);
    EXPECT_NEAR((g - a.eccentric_load).norm(), 0.0, 1e-9);
  }
}

TEST(LcrForces, FrictionLowersEfficiencyAsThePapersModelSays) {
  const Reducer<double> r = LcrII();
  const AngleLoads<double> a = AnalyzeAngle(r, Steel(), {80000.0, 0.05, 0.0}, 0.7);
  const double ideal = 80000.0 / 90.0;
  EXPECT_NEAR(a.input_torque, ideal + 0.05 * std::abs(a.radial_force) * r.eccentricity, 1e-9);
  EXPECT_NEAR(a.efficiency, ideal / a.input_torque, 1e-12);
  EXPECT_LT(a.efficiency, 1.0);
}

// AnalyzeCycle's double fast path (structure-of-arrays buffers, the fixed turret's centres computed
// once) must give AnalyzeAngle's numbers bit for bit at every angle, for every stage set and load.
TEST(LcrCycle, FastPathEqualsAnalyzeAngleBitForBit) {
  const std::vector<LoadCase> loads = {{80000.0, 0.05, 0.0}, {80000.0, 0.0, 30.0}, {0.0, 0.05, 0.0},
                                       {0.0, 0.05, 20.0}, {1.0, 0.0, 0.0}};
  const std::vector<Stages> stage_sets = {{},
                                          {true, false, true},
                                          {true, true, false},
                                          {true, false, false},
                                          {false, false, true},
                                          {false, false, false},
                                          {true, true, true, true},
                                          {true, true, false, true}};
  for (const Reducer<double>& r : {LcrI(), LcrII(), LcrIII()})
    for (const LoadCase& load : loads)
      for (const Stages& stages : stage_sets) {
        const int steps = 97;
        const CycleSeries s = AnalyzeCycle(r, Steel(), load, steps, stages);
        ASSERT_EQ(s.theta_rad.size(), size_t(steps));
        for (int i = 0; i < steps; ++i) {
          const double theta = 2 * kPi * i / steps;
          const AngleLoads<double> a = AnalyzeAngle(r, Steel(), load, theta, stages);
          EXPECT_EQ(s.theta_rad[i], theta);
          for (auto [series, side] : {std::pair{&s.input, &a.input}, std::pair{&s.output, &a.output}}) {
            EXPECT_EQ(series->actuating[i], side->actuating);
            EXPECT_EQ(series->max_force_N[i], side->max_force);
            EXPECT_EQ(series->max_stress_MPa[i], side->max_stress);
            EXPECT_EQ(series->turret_torque_Nmm[i], side->turret_torque);
            EXPECT_EQ(series->roller_force_N[i], side->force);
            // Each roller's stress only where asked for (Stages::roller_stress).
            if (stages.stress && stages.roller_stress) {
              EXPECT_EQ(series->roller_stress_MPa[i], side->stress);
            } else {
              EXPECT_EQ(series->roller_stress_MPa.size(), 0u);
            }
          }
          EXPECT_EQ(s.tangential_force_N[i], a.tangential_force);
          EXPECT_EQ(s.radial_force_N[i], a.radial_force);
          EXPECT_EQ(s.input_torque_Nmm[i], a.input_torque);
          EXPECT_EQ(s.efficiency[i], a.efficiency);
        }
      }
}

// One cam alone (AnalyzeSide: the sizings' per-cam samples) must give AnalyzeAngle's SideLoads of
// that cam bit for bit, values and derivatives, with and without stresses.
template <typename T>
void ExpectSameSide(const SideLoads<T>& one, const SideLoads<T>& both) {
  ASSERT_EQ(one.contacts.size(), both.contacts.size());
  auto same = [](const T& x, const T& y) {
    if constexpr (std::is_same_v<T, double>) {
      EXPECT_EQ(x, y);
    } else {
      EXPECT_EQ(x.a, y.a);
      for (int d = 0; d < x.v.size(); ++d) EXPECT_EQ(x.v[d], y.v[d]) << "derivative " << d;
    }
  };
  for (size_t k = 0; k < one.contacts.size(); ++k) {
    same(one.contacts[k].arm, both.contacts[k].arm);
    same(one.contacts[k].curvature, both.contacts[k].curvature);
    same(one.force[k], both.force[k]);
  }
  ASSERT_EQ(one.stress.size(), both.stress.size());
  for (size_t k = 0; k < one.stress.size(); ++k) same(one.stress[k], both.stress[k]);
  same(one.proportionality, both.proportionality);
  same(one.turret_torque, both.turret_torque);
  same(one.max_force, both.max_force);
  same(one.max_stress, both.max_stress);
  EXPECT_EQ(one.actuating, both.actuating);
}

TEST(LcrForces, OneCamAloneEqualsAnalyzeAngleBitForBit) {
  using J = ceres::Jet<double, 4>;
  for (const Reducer<double>& r : {LcrI(), LcrII(), LcrIII()}) {
    Reducer<J> rj = r.cast<J>();  // derivatives in e, both turret radii and the input roller radius
    rj.eccentricity.v[0] = 1.0;
    rj.input.turret_radius.v[1] = 1.0;
    rj.output.turret_radius.v[2] = 1.0;
    rj.input.roller_radius.v[3] = 1.0;
    for (const LoadCase& load : {LoadCase{80000.0, 0.0, 0.0}, LoadCase{1.0, 0.0, 0.0}, LoadCase{0.0, 0.0, 0.0}})
      for (const Stages& stages : {Stages{true, false, false}, Stages{true, true, false}})
        for (int i = 0; i < 37; ++i) {
          const double theta = 2 * kPi * i / 37 + 0.01;
          const AngleLoads<double> a = AnalyzeAngle(r, Steel(), load, theta, stages);
          const AngleLoads<J> aj = AnalyzeAngle(rj, Steel(), load, J(theta), stages);
          ExpectSameSide(AnalyzeSide(r, Steel(), load, Side::kInput, theta, stages), a.input);
          ExpectSameSide(AnalyzeSide(r, Steel(), load, Side::kOutput, theta, stages), a.output);
          ExpectSameSide(AnalyzeSide(rj, Steel(), load, Side::kInput, J(theta), stages), aj.input);
          ExpectSameSide(AnalyzeSide(rj, Steel(), load, Side::kOutput, J(theta), stages), aj.output);
        }
  }
  // The efficiency needs both cams.
  EXPECT_THROW(AnalyzeSide(LcrII(), Steel(), LoadCase{80000.0, 0.0, 0.0}, Side::kInput, 0.1, Stages{}),
               std::invalid_argument);
}

// Table 3 of the paper: max roller force within 3%, actuating roller counts within 1.
TEST(LcrPaper, Table3ForcesAndActuatingCounts) {
  struct Row { Reducer<double> r; int act_a, act_b; double f_a, f_b; };
  for (const Row& row : {Row{LcrI(), 11, 10, 810, 731}, Row{LcrII(), 7, 7, 960, 720}}) {
    const CycleSeries s = AnalyzeCycle(row.r, Steel(), {80000.0, 0.05, 0.0}, 3600, {});
    const double fa = *std::max_element(s.input.max_force_N.begin(), s.input.max_force_N.end());
    const double fb = *std::max_element(s.output.max_force_N.begin(), s.output.max_force_N.end());
    EXPECT_NEAR(fa, row.f_a, 0.03 * row.f_a);
    EXPECT_NEAR(fb, row.f_b, 0.03 * row.f_b);
    const int ka = *std::max_element(s.input.actuating.begin(), s.input.actuating.end());
    const int kb = *std::max_element(s.output.actuating.begin(), s.output.actuating.end());
    EXPECT_LE(std::abs(ka - row.act_a), 1);
    EXPECT_LE(std::abs(kb - row.act_b), 1);
    EXPECT_GT(UndercutMargin(row.r.input, row.r.eccentricity), 0.0);
    EXPECT_GT(UndercutMargin(row.r.output, row.r.eccentricity), 0.0);
  }
  EXPECT_GT(UndercutMargin(LcrIII().input, LcrIII().eccentricity), 0.0);
  EXPECT_GT(UndercutMargin(LcrIII().output, LcrIII().eccentricity), 0.0);
}

TEST(LcrHertz, ClosedFormExampleOfNotes) {
  // E = 210 GPa, ν = 0.3 on both: E* = 115.4 GPa; F = 1000 N, L = 10 mm, R' = 10 mm: 606 MPa.
  const double e_star = contact::CompositeModulus(210000.0, 0.3, 210000.0, 0.3);
  EXPECT_NEAR(e_star, 115384.6, 0.1);
  EXPECT_NEAR(contact::LineContactPeakPressure(1000.0, 10.0, 10.0, e_star), 606.0, 0.5);
}

TEST(LcrHertz, StageStressEqualsTwoCylinderHertzOnACircleCam) {
  // Nearly circular cam (tiny e): the cam is a circle of radius r_d − r_r, so each loaded roller is
  // a cylinder-on-cylinder contact with 1/R' = 1/r_r + 1/(r_d − r_r).
  Reducer<double> r = LcrII();
  r.eccentricity = 1e-7;
  const AngleLoads<double> a = AnalyzeAngle(r, Steel(), {80000.0, 0.0, 0.0}, 0.3);
  const double r_eff = 1.0 / (1.0 / 6.0 + 1.0 / 31.0);
  int checked = 0;
  for (size_t k = 0; k < a.input.force.size(); ++k) {
    if (a.input.force[k] <= 0) continue;
    const double expected = contact::LineContactPeakPressure(a.input.force[k], 8.0, r_eff,
                                                             Steel().composite_modulus_MPa());
    EXPECT_NEAR(a.input.stress[k], expected, 1e-6 * expected);
    ++checked;
  }
  EXPECT_GT(checked, 3);
}

// AD against central differences for every stage, in all continuous design parameters:
// x = (e, r_dA, r_dB, r_r, roller length, cam thickness).
template <typename T>
Reducer<T> DesignFrom(const std::array<T, 6>& x) {
  Reducer<T> r;
  r.eccentricity = x[0];
  r.input = {12, 13, x[1], x[3], x[4], x[5]};
  r.output = {14, 15, x[2], x[3], x[4], x[5]};
  return r;
}
const std::array<double, 6> kX0 = {2.0, 37.0, 42.0, 6.0, 10.0, 8.0};

TEST(LcrGradients, ProfileAndUndercutStages) {
  auto f = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    const Reducer<T> r = DesignFrom(x);
    std::vector<T> y;
    for (Side s : {Side::kInput, Side::kOutput}) {
      const auto& c = r.side(s);
      const Vec2<T> p = OffsetPoint(c, r.eccentricity, T(0.9), c.roller_radius);
      const Vec2<T> cut = OffsetPoint(c, r.eccentricity, T(2.1), c.roller_radius - T(2.0));
      y.insert(y.end(), {p.x(), p.y(), cut.x(), cut.y(), PitchCurvature(c, r.eccentricity, T(0.3)),
                         UndercutMargin(c, r.eccentricity), SmoothUndercutMargin(c, r.eccentricity),
                         RollerGap(c)});
    }
    y.push_back(OuterDiameter(r));
    return y;
  };
  camopt::testing::ExpectJacobianMatchesCentralDifferences<6>(f, kX0, 1e-6, 1e-9);
}

TEST(LcrGradients, ContactForceStressTorqueEfficiencyStages) {
  auto f = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    const Reducer<T> r = DesignFrom(x);
    const AngleLoads<T> a = AnalyzeAngle(r, Steel(), {80000.0, 0.05, 3.0}, T(0.7));
    std::vector<T> y;
    for (const SideLoads<T>* s : {&a.input, &a.output}) {
      for (size_t k = 0; k < s->force.size(); k += 3) {
        y.push_back(s->contacts[k].arm);
        y.push_back(s->contacts[k].point.x());
        y.push_back(s->contacts[k].curvature);
        y.push_back(s->force[k]);
        y.push_back(s->stress[k]);
      }
      y.push_back(s->max_force);
      y.push_back(s->max_stress);
      y.push_back(s->proportionality);
    }
    y.insert(y.end(), {a.tangential_force, a.radial_force, a.input_torque, a.efficiency});
    return y;
  };
  camopt::testing::ExpectJacobianMatchesCentralDifferences<6>(f, kX0, 1e-6, 1e-7);
}

TEST(LcrGradients, CycleAggregates) {
  auto f = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    const CycleAggregates<T> c = AggregateCycle(DesignFrom(x), Steel(), {80000.0, 0.05, 0.0}, 90);
    return std::vector<T>{c.max_force_input, c.max_force_output, c.max_stress_input,
                          c.max_stress_output, c.min_efficiency, c.mean_input_torque};
  };
  camopt::testing::ExpectJacobianMatchesCentralDifferences<6>(f, kX0, 1e-5, 1e-7);
}

TEST(LcrAggregates, SoftMaximaBoundTheExactOnes) {
  const Reducer<double> r = LcrII();
  const CycleSeries s = AnalyzeCycle(r, Steel(), {80000.0, 0.05, 0.0}, 90, {});
  const CycleAggregates<double> c = AggregateCycle(r, Steel(), {80000.0, 0.05, 0.0}, 90);
  const double fa = *std::max_element(s.input.max_force_N.begin(), s.input.max_force_N.end());
  EXPECT_GE(c.max_force_input, fa);
  EXPECT_LE(c.max_force_input, fa + 1000.0 * std::log(90.0 * 13) / 200);
  const double smooth = SmoothUndercutMargin(r.input, r.eccentricity);
  const double exact = UndercutMargin(r.input, r.eccentricity);
  EXPECT_LE(smooth, exact + 1e-12);
  EXPECT_GT(smooth, exact - 0.05);
}

// Hard cases.
TEST(LcrHardCases, UndercutFlagFlipsExactlyWhereTheMarginCrossesZero) {
  Reducer<double> r = LcrII();
  const double rho = MinConvexPitchRadius(r.input, r.eccentricity);  // independent of r_r
  for (double f : {1 - 1e-9, 1 + 1e-9}) {
    r.input.roller_radius = rho * f;
    const double margin = UndercutMargin(r.input, r.eccentricity);
    EXPECT_EQ(margin < 0, f > 1) << f;
    EXPECT_NEAR(margin, rho * (1 - f), 1e-12);
  }
  // The curvature there is still finite, and the stress stage flags the undercut contact as +inf
  // rather than NaN.
  r.input.roller_radius = rho * 1.01;
  const CycleSeries s = AnalyzeCycle(r, Steel(), {80000.0, 0.05, 0.0}, 720, {});
  for (double p : s.input.max_stress_MPa) EXPECT_FALSE(std::isnan(p));
}

TEST(LcrHardCases, TinyEccentricityGivesFiniteResults) {
  Reducer<double> r = LcrII();
  r.eccentricity = 1e-6;
  const CycleSeries s = AnalyzeCycle(r, Steel(), {80000.0, 0.05, 0.0}, 360, {});
  for (size_t i = 0; i < s.theta_rad.size(); ++i) {
    EXPECT_TRUE(std::isfinite(s.input.max_force_N[i]));
    EXPECT_TRUE(std::isfinite(s.input.max_stress_MPa[i]));
    EXPECT_TRUE(std::isfinite(s.efficiency[i]));
    EXPECT_GT(s.efficiency[i], 0.0);
  }
}

TEST(LcrHardCases, LcrIAtTenthDegreeStepsIsFinite) {
  const CycleSeries s = AnalyzeCycle(LcrI(), Steel(), {80000.0, 0.05, 0.0}, 3600, {});
  for (size_t i = 0; i < s.theta_rad.size(); ++i) {
    ASSERT_TRUE(std::isfinite(s.input.max_stress_MPa[i]) && std::isfinite(s.output.max_stress_MPa[i]));
    ASSERT_TRUE(std::isfinite(s.input_torque_Nmm[i]) && std::isfinite(s.efficiency[i]));
  }
}

TEST(LcrHardCases, ZeroOutputTorque) {
  const Reducer<double> r = LcrII();
  const AngleLoads<double> zero = AnalyzeAngle(r, Steel(), {0.0, 0.05, 0.0}, 0.5);
  const AngleLoads<double> some = AnalyzeAngle(r, Steel(), {1000.0, 0.05, 0.0}, 0.5);
  EXPECT_EQ(zero.input.max_force, 0.0);
  EXPECT_EQ(zero.input.max_stress, 0.0);
  EXPECT_EQ(zero.input_torque, 0.0);
  EXPECT_NEAR(zero.efficiency, some.efficiency, 1e-12);  // the limit T_o → 0⁺ (model is linear)
  const AngleLoads<double> heavy_cam = AnalyzeAngle(r, Steel(), {0.0, 0.05, 5.0}, 0.5);
  EXPECT_EQ(heavy_cam.efficiency, 0.0);
}

TEST(LcrHardCases, RollerOnTheLoadLineCarriesNothing) {
  // At θ = 0 roller 1 of the fixed turret lies on the line through O and the pitch point: a = 0.
  const AngleLoads<double> a = AnalyzeAngle(LcrII(), Steel(), {80000.0, 0.05, 0.0}, 0.0);
  EXPECT_NEAR(a.input.contacts[0].arm, 0.0, 1e-12);
  EXPECT_EQ(a.input.force[0], 0.0);
  EXPECT_EQ(a.input.stress[0], 0.0);
  int loaded = 0;
  for (double f : a.input.force) loaded += f > 0;
  EXPECT_EQ(a.input.actuating, loaded);
  // Its neighbours on both sides are symmetric: one carries load, the other not.
  EXPECT_NEAR(std::abs(a.input.contacts[1].arm), std::abs(a.input.contacts[12].arm), 1e-9);
}

TEST(LcrHardCases, HugeRatioKeepsTheBalances) {
  // 49/50 and 50/51 lobes/rollers: r_i = −2499.
  Reducer<double> r = camopt::testing::MakeLcr(0.5, 49, 50, 60, 50, 51, 64, 6, 5, 4);
  EXPECT_DOUBLE_EQ(SpeedReductionRatio(r), -2499.0);
  EXPECT_TRUE(CheckDesign(r).empty());
  for (double theta : {0.0, 0.01, 1.0, 4.0}) {
    const AngleLoads<double> a = AnalyzeAngle(r, Steel(), {80000.0, 0.0, 0.0}, theta);
    EXPECT_NEAR(a.input_torque, 80000.0 / 2499.0, 1e-9);  // power balance, μ = 0
    EXPECT_TRUE(std::isfinite(a.input.max_stress) && std::isfinite(a.output.max_stress));
    EXPECT_GT(a.input.actuating, 10);
  }
}

TEST(LcrDesignChecks, RejectsImpossibleDesigns) {
  Reducer<double> r = LcrII();
  EXPECT_TRUE(CheckDesign(r).empty());
  r.input.roller_radius = 9.0;  // 2·37·sin(π/13) = 17.7 < 18
  ASSERT_FALSE(CheckDesign(r).empty());
  EXPECT_EQ(CheckDesign(r)[0].field, "input.roller_diameter_mm");
  EXPECT_EQ(CheckDesign(r)[0].value, 18.0);
  EXPECT_NEAR(CheckDesign(r)[0].limit, 2 * 37 * std::sin(kPi / 13), 1e-12);  // d_r < 2 r_d sin(π/n)
  r = LcrII();
  r.output.lobes = 15;
  ASSERT_FALSE(CheckDesign(r).empty());
  EXPECT_EQ(CheckDesign(r)[0].field, "output.rollers");
  EXPECT_EQ(CheckDesign(r)[0].limit, 16.0);  // lobes + 1
  r = LcrII();
  r.eccentricity = 3.0;  // pitch point 3·13 = 39 > 37
  const auto loop = CheckDesign(r);
  ASSERT_FALSE(loop.empty());
  EXPECT_EQ(loop[0].field, "input.turret_radius_mm");
  EXPECT_EQ(loop[0].limit, 39.0);
  // e·13/1 < 37: the eccentricity must be below 37/13 = 2.84615 mm.
  EXPECT_NE(loop[0].message.find("below 2.84615 mm"), std::string::npos) << loop[0].message;
}

}  // namespace lcr_test
}  // namespace camopt::lcr
