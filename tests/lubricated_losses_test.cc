// Friction by lubrication regime (model/contact/lubricated_friction.h), Palmgren's bearing loss
// (model/common/bearing_friction.h) and the thermal operating point (model/common/thermal.h): closed
// forms, metamorphic relations and derivatives against central differences.
#include "model/common/bearing_friction.h"
#include "model/common/thermal.h"
#include "model/contact/lubricated_friction.h"

#include <array>
#include <cmath>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "model/common/lubricant.h"
#include "model/common/material.h"
#include "model/contact/ehl.h"
#include "tests/test_util.h"

namespace camopt {
namespace lubricated_losses_test {

using J1 = ceres::Jet<double, 1>;

TEST(RegimeFriction, BoundaryAndFullFilmAtTheBordersAndSmoothBetween) {
  const contact::RegimeFriction law{0.1, 0.03};
  EXPECT_DOUBLE_EQ(contact::FrictionCoefficient(law, 0.3), 0.1);
  EXPECT_DOUBLE_EQ(contact::FrictionCoefficient(law, 1.0), 0.1);
  EXPECT_DOUBLE_EQ(contact::FrictionCoefficient(law, 3.0), 0.03);
  EXPECT_DOUBLE_EQ(contact::FrictionCoefficient(law, 7.0), 0.03);
  // Midway (λ = 2, x = 1/2): s = 6/32 − 15/16 + 10/8 = 1/2, the mean of the two.
  EXPECT_NEAR(contact::FrictionCoefficient(law, 2.0), 0.065, 1e-15);
  // Falls monotonically through the mixed band.
  for (int i = 0; i < 199; ++i) {
    const double l = 1.0 + 0.01 * i;
    EXPECT_LT(contact::FrictionCoefficient(law, l + 0.01), contact::FrictionCoefficient(law, l)) << l;
  }
  // C¹ and C² at the borders: the first derivative is 0 on both sides, and the one-sided second
  // differences inside the band vanish as the step does (s'' = 60x − 180x² + 120x³ → 0).
  for (double border : {1.0, 3.0})
    for (double side : {-1e-9, 1e-9}) {
      const J1 mu = contact::FrictionCoefficient(law, J1(border + side, 0));
      EXPECT_NEAR(mu.v[0], 0.0, 1e-12) << border << side;
    }
  const auto d1 = [&](double l) { return contact::FrictionCoefficient(law, J1(l, 0)).v[0]; };
  EXPECT_NEAR((d1(1.0 + 1e-4) - d1(1.0)) / 1e-4, 0.0, 0.07 * 1e-2);
  // The derivative in the band against a central difference.
  auto f = [&](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    return std::vector<T>{contact::FrictionCoefficient(law, x[0])};
  };
  for (double l : {1.3, 2.0, 2.7}) testing::ExpectJacobianMatchesCentralDifferences<1>(f, {l});
}

// A thicker oil at the same temperature raises λ and lowers the mixed-regime friction; μ → 0 gives
// no sliding loss.
TEST(RegimeFriction, AThickerOilRaisesLambdaAndLowersTheMixedFriction) {
  const double e_star = CompositeModulus(206000.0, 0.3, 206000.0, 0.3);
  const double sigma = contact::CompositeRoughness(0.1e-3, 0.1e-3);  // Rq 0.1 µm each (ground)
  const contact::RegimeFriction law{0.1, 0.03};
  double previous_lambda = 0.0, previous_mu = 1.0;
  for (double nu40 : {22.0, 46.0, 68.0, 100.0, 150.0}) {
    Lubricant oil;
    oil.nu40_mm2_s = nu40;
    oil.nu100_mm2_s = nu40 / 7.5;
    const double eta0 = oil.DynamicViscosityAt(60.0);
    const auto film = contact::LineContactFilm(eta0, 3000.0, 8.0, 400.0, e_star, 0.02);
    const double lambda = contact::FilmParameter(film.minimum, sigma);
    const double mu = contact::FrictionCoefficient(law, lambda);
    EXPECT_GT(lambda, previous_lambda) << nu40;
    EXPECT_LE(mu, previous_mu) << nu40;
    previous_lambda = lambda;
    previous_mu = mu;
  }
  // The sweep crossed the mixed band (λ from about 0.9 to 3.7: "lowers" was tested, not only "not
  // higher"), and ends in full film.
  EXPECT_DOUBLE_EQ(previous_mu, 0.03);
  EXPECT_DOUBLE_EQ(contact::SlidingLoss(0.0, 1000.0, 250.0), 0.0);
  EXPECT_DOUBLE_EQ(contact::SlidingLoss(0.05, 1000.0, -250.0), 12500.0);  // N·mm/s = 12.5 W
}

TEST(PalmgrenBearing, MomentsAndLossByHand) {
  const PalmgrenBearing b{2.0, 0.0005, 20.0};
  // ν 68 mm²/s at 1500 rpm: ν n = 102 000; M0 = 1e-7 × 2 × 102000^(2/3) × 20³.
  const double m0 = 1e-7 * 2.0 * std::pow(102000.0, 2.0 / 3.0) * 8000.0;
  EXPECT_NEAR(PalmgrenLoadIndependentMoment(b, 68.0, 1500.0), m0, 1e-12 * m0);
  EXPECT_NEAR(PalmgrenLoadDependentMoment(b, 3000.0), 0.0005 * 3000.0 * 20.0, 1e-12);
  const double loss = (m0 + 30.0) * 1500.0 * 2.0 * kPi / 60.0;
  EXPECT_NEAR(PalmgrenPowerLoss(b, 68.0, 1500.0, 3000.0), loss, 1e-9 * loss);
  EXPECT_NEAR(PalmgrenPowerLoss(b, 68.0, -1500.0, 3000.0), loss, 1e-9 * loss);  // either direction
  // Below ν n = 2000 the moment is held at its value there (Palmgren's 160e-7 f0 dm³ is 0.8% above).
  const double held = 1e-7 * 2.0 * std::pow(2000.0, 2.0 / 3.0) * 8000.0;
  EXPECT_NEAR(PalmgrenLoadIndependentMoment(b, 10.0, 50.0), held, 1e-12 * held);
  EXPECT_NEAR(held / (160e-7 * 2.0 * 8000.0), 0.992, 1e-3);
  auto f = [&](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    return std::vector<T>{PalmgrenPowerLoss(b, x[0], x[1], x[2]) * T(1e-3)};
  };
  testing::ExpectJacobianMatchesCentralDifferences<3>(f, {68.0, 1500.0, 3000.0});
  // M0 from the powers ν^(2/3), n^(2/3) given: the same numbers as above on both sides of ν n = 2000.
  const auto p23 = [](double x) { return std::pow(x, 2.0 / 3.0); };
  EXPECT_NEAR(PalmgrenLoadIndependentMoment(b, 68.0, p23(68.0), 1500.0, p23(1500.0)), m0, 1e-12 * m0);
  EXPECT_NEAR(PalmgrenLoadIndependentMoment(b, 10.0, p23(10.0), 50.0, p23(50.0)), held, 1e-12 * held);
}

TEST(OperatingTemperature, LinearLossMatchesTheClosedForm) {
  // P(t) = a − b (t − t_amb): t* = t_amb + a / (kA + b).
  const HousingCooling cooling{0.2, 15.0, 0.0, 20.0};  // kA = 3 W/K
  const double a = 150.0, b = 0.4;
  const auto point = SolveOperatingTemperature<double>([&](double t) { return a - b * (t - 20.0); }, cooling, 150.0);
  ASSERT_TRUE(point.found) << point.why;
  EXPECT_NEAR(point.temperature_C, 20.0 + a / (3.0 + b), 1e-9);
  EXPECT_LE(std::abs(point.residual_W), 1e-9 * point.loss_W);
  EXPECT_LT(point.evaluations, 20);
}

// A loss falling with the oil's viscosity (a drag ∝ ν^(2/3), as Palmgren's M0) plus a constant.
double ViscousLoss(double t, double drag_W_at_40, double constant_W) {
  Lubricant oil;
  return drag_W_at_40 * std::pow(oil.KinematicViscosityAt(t) / 68.0, 2.0 / 3.0) + constant_W;
}

TEST(OperatingTemperature, ALargerHousingRunsCoolerAndTooMuchLossIsSaid) {
  double previous = 1e9;
  for (double area : {0.05, 0.1, 0.2, 0.4}) {
    const HousingCooling cooling{area, 15.0, 0.0, 25.0};
    const auto point =
        SolveOperatingTemperature<double>([&](double t) { return ViscousLoss(t, 80.0, 20.0); }, cooling, 120.0);
    ASSERT_TRUE(point.found) << area << ": " << point.why;
    EXPECT_LT(point.temperature_C, previous) << area;
    // The balance holds at the answer, checked here from the loss itself.
    EXPECT_NEAR(ViscousLoss(point.temperature_C, 80.0, 20.0), cooling.conductance_W_per_K() * (point.temperature_C - 25.0),
                1e-6 * point.loss_W);
    previous = point.temperature_C;
  }
  // 0.02 m² at 15 W/m²K gives off 28.5 W at 120 °C, below the 60 W the drive loses there.
  const auto hot = SolveOperatingTemperature<double>([&](double t) { return ViscousLoss(t, 80.0, 50.0); },
                                                     HousingCooling{0.02, 15.0, 0.0, 25.0}, 120.0);
  EXPECT_FALSE(hot.found);
  EXPECT_NE(hot.why.find("no equilibrium below the oil's limit"), std::string::npos) << hot.why;
}

TEST(OperatingTemperature, DerivativesOfTheFixedPointMatchCentralDifferences) {
  const HousingCooling cooling{0.1, 15.0, 0.0, 25.0};
  // x = {drag at 40 °C [W], constant loss [W]}: the temperature and the loss at it.
  auto f = [&](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    const auto loss = [&](const T& t) {
      const Lubricant oil;
      using std::pow;
      return x[0] * pow(oil.KinematicViscosityAt(t) / T(68.0), T(2.0 / 3.0)) + x[1];
    };
    const auto point = SolveOperatingTemperature<T>(loss, cooling, 150.0, 1e-13);
    EXPECT_TRUE(point.found) << point.why;
    return std::vector<T>{point.temperature_C, point.loss_W};
  };
  testing::ExpectJacobianMatchesCentralDifferences<2>(f, {80.0, 20.0}, 1e-5, 1e-7);
}

// The derivative pass of a sizing: the balance solved once on values, the loss evaluated over the
// Jet once at its temperature (OperatingPointOver), against the same central differences.
TEST(OperatingTemperature, OneJetEvaluationAtTheSolvedPointGivesTheSameDerivatives) {
  const HousingCooling cooling{0.1, 15.0, 0.0, 25.0};
  const auto loss_of = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    return [x](const T& t) {
      const Lubricant oil;
      using std::pow;
      return x[0] * pow(oil.KinematicViscosityAt(t) / T(68.0), T(2.0 / 3.0)) + x[1];
    };
  };
  int jet_evaluations = 0;
  auto f = [&](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    const std::array<double, 2> xv{Value(x[0]), Value(x[1])};
    const ThermalPoint<double> solved = SolveOperatingTemperature<double>(loss_of(xv), cooling, 150.0, 1e-13);
    EXPECT_TRUE(solved.found) << solved.why;
    EXPECT_LT(solved.slope_W_per_K, 0.0);  // g' = P'(t) − kA < 0: a stable balance (the loss falls as the oil thins)
    const auto loss = loss_of(x);
    const auto counted = [&](const T& t) {
      if constexpr (!std::is_same_v<T, double>) ++jet_evaluations;
      return loss(t);
    };
    const ThermalPoint<T> point = OperatingPointOver<T>(counted, cooling, solved);
    EXPECT_TRUE(point.found);
    EXPECT_NEAR(Value(point.temperature_C), solved.temperature_C, 1e-9);
    return std::vector<T>{point.temperature_C, point.loss_W};
  };
  testing::ExpectJacobianMatchesCentralDifferences<2>(f, {80.0, 20.0}, 1e-5, 1e-7);
  EXPECT_EQ(jet_evaluations, 1);
}

}  // namespace lubricated_losses_test
}  // namespace camopt
