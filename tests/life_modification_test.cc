// Tests of model/common/life_modification.h: ISO 281:2007 §9.3's life modification factor a_ISO
// (eqs. 31–36) and reference viscosity ν1 (eq. 28). The expected values are hand calculations
// (python3, double precision) written out step by step from the standard's equations, not values
// of the code under test.
#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "model/common/life_modification.h"

namespace camopt {
namespace life_modification_test {

constexpr BearingKind kBall = BearingKind::kBall, kRoller = BearingKind::kRoller;

double A(BearingKind kind, double kappa, double x) {
  const LifeModification m = LifeModificationFactor(kind, kappa, x);
  EXPECT_TRUE(m.computed) << "kappa " << kappa;
  return m.a_iso;
}

// (a) Hand calculations, one per κ band and kind; x = e_C C_u / P.
TEST(LifeModification, BallAgainstHandCalculation) {
  // κ = 0.2 (eq. 31: c = 2.2649, p = 0.054381), x = 0.3:
  //   0.2^0.054381 = 0.9161979426; 2.5671 − 2.2649/0.9161979426 = 0.09503594626;
  //   ^0.83 = 0.1417904431; 0.3^(1/3) = 0.6694329501; bracket 1 − 0.1417904431·0.6694329501
  //   = 0.9050808054; a = 0.1 · 0.9050808054^−9.3 = 0.2528177733.
  EXPECT_NEAR(A(kBall, 0.2, 0.3), 0.2528177732831773, 1e-12);
  // κ = 0.7 (eq. 32: c = 1.9987, p = 0.19087), x = 0.8: 0.7^0.19087 = 0.9341870935; term 0.4275928136;
  //   ^0.83 = 0.4940321701; 0.8^(1/3) = 0.9283177667; bracket 0.5413811591; a = 30.08990526.
  EXPECT_NEAR(A(kBall, 0.7, 0.8), 30.08990525526417, 1e-10);
  // κ = 3 (eq. 33: c = 1.9987, p = 0.071739), x = 0.2: 3^0.071739 = 1.082002344; term 0.7198766454;
  //   ^0.83 = 0.7612445736; 0.2^(1/3) = 0.5848035476; bracket 0.5548214727; a = 23.95381408.
  EXPECT_NEAR(A(kBall, 3.0, 0.2), 23.953814079897846, 1e-10);
  // κ = 1 (eq. 33), x = 0.1: term 2.5671 − 1.9987 = 0.5684; ^0.83 = 0.625695278;
  //   0.1^(1/3) = 0.4641588834; bracket 0.7095779784; a = 2.430517778.
  EXPECT_NEAR(A(kBall, 1.0, 0.1), 2.4305177780348117, 1e-11);
}

TEST(LifeModification, RollerAgainstHandCalculation) {
  // κ = 0.2 (eq. 34: c = 1.3993), x = 0.3: term 1.5859 − 1.3993/0.9161979426 = 0.0586099517;
  //   0.3^0.4 = 0.6178008506; bracket 0.963790722; a = 0.1 · 0.963790722^−9.185 = 0.1403196594.
  EXPECT_NEAR(A(kRoller, 0.2, 0.3), 0.14031965943302968, 1e-12);
  // κ = 0.7 (eq. 35: c = 1.2348), x = 0.8: term 0.2641090991; 0.8^0.4 = 0.9146101039;
  //   bracket 0.7584431495; a = 1.26738027.
  EXPECT_NEAR(A(kRoller, 0.7, 0.8), 1.2673802700279135, 1e-11);
  // κ = 3 (eq. 36), x = 0.2: term 0.4446825095; 0.2^0.4 = 0.5253055609; bracket 0.7664058049;
  //   a = 1.151452574.
  EXPECT_NEAR(A(kRoller, 3.0, 0.2), 1.1514525737372003, 1e-11);
  // κ = 1 (eq. 36), x = 0.1: term 1.5859 − 1.2348 = 0.3511; 0.1^0.4 = 0.3981071706;
  //   bracket 0.8602245724; a = 0.3986485715.
  EXPECT_NEAR(A(kRoller, 1.0, 0.1), 0.39864857151956246, 1e-12);
  // κ = 2, x = 1.5: 2^0.071739 = 1.050982757; term 0.4109996587; 1.5^0.4 = 1.176079023;
  //   bracket 0.5166319231; a = 43.09534167 (below the cap).
  EXPECT_NEAR(A(kRoller, 2.0, 1.5), 43.09534167431199, 1e-9);
}

// (b) The bands meet. At κ = 1 exactly (c/1^p = c for both p). At κ = 0.4 to the constants' five
// digits: c/0.4^p is 2.380616 below and 2.380688 above for balls (3.0e-5 apart), 1.4707918 and
// 1.4707926 for rollers (5e-7 apart); the exponents (0.83, then −9.3 on a bracket near 1 − term·x^⅓)
// magnify a ball's step to ≈ 1e-3 relative at x = 1 (python: 9.7e-4), a roller's to 7.8e-6.
TEST(LifeModification, ContinuousAcrossTheKappaBands) {
  for (double x : {0.1, 0.3, 0.5, 1.0}) {
    for (BearingKind kind : {kBall, kRoller}) {
      const double tol_04 = kind == kBall ? 1.5e-3 : 1e-5;
      const double below = A(kind, std::nextafter(0.4, 0.0), x), at = A(kind, 0.4, x);
      EXPECT_NEAR(below / at, 1.0, tol_04) << "kappa 0.4, x " << x;
      const double below1 = A(kind, std::nextafter(1.0, 0.0), x), at1 = A(kind, 1.0, x);
      EXPECT_NEAR(below1 / at1, 1.0, 1e-9) << "kappa 1, x " << x;
    }
  }
  // The lubrication term itself meets at 0.4 to the constants' digits (5e-5 relative).
  EXPECT_NEAR(2.2649 / std::pow(0.4, 0.054381), 1.9987 / std::pow(0.4, 0.19087), 2.380688 * 5e-5);
}

// (c) Better lubrication and a larger fatigue-load margin give a longer life.
TEST(LifeModification, GrowsWithKappaAndWithLoadMargin) {
  for (BearingKind kind : {kBall, kRoller}) {
    for (double x : {0.02, 0.1, 0.3}) {
      double last = 0.0;
      for (double k = 0.1; k <= 4.0; k *= 1.05) {
        const double a = A(kind, k, x);
        EXPECT_GE(a, last * (1 - 1.5e-3)) << "kappa " << k << " x " << x;  // the 0.4 step, (b)
        last = a;
      }
    }
    for (double k : {0.15, 0.5, 1.5, 4.0}) {
      double last = 0.0;
      for (double x = 0.0; x <= 5.0; x += 0.05) {
        const double a = A(kind, k, x);
        EXPECT_GE(a, last) << "kappa " << k << " x " << x;
        last = a;
      }
    }
  }
  // e_C C_u / P = 0 (no fatigue-load margin) gives the floor 0.1 for both kinds.
  EXPECT_DOUBLE_EQ(A(kBall, 2.0, 0.0), 0.1);
  EXPECT_DOUBLE_EQ(A(kRoller, 2.0, 0.0), 0.1);
}

// (d) The cap, κ > 4, κ < 0.1 and bad input.
TEST(LifeModification, CapClampAndRange) {
  // Ball κ = 1, x = 0.5: bracket 1 − 0.625695278·0.7937005260 = 0.5033853 → 0.1·0.5033853^−9.3 =
  // 59.2 > 50: capped.
  LifeModification m = LifeModificationFactor(kBall, 1.0, 0.5);
  EXPECT_TRUE(m.capped);
  EXPECT_EQ(m.a_iso, 50.0);
  // Past the pole (ball κ = 4, x = 5: bracket 1 − 0.7576090^0.83 · 5^(1/3) = −0.358) and an unloaded
  // bearing (x = +∞): 50.
  EXPECT_EQ(LifeModificationFactor(kBall, 4.0, 5.0).a_iso, 50.0);
  EXPECT_EQ(LifeModificationFactor(kRoller, 4.0, INFINITY).a_iso, 50.0);
  // κ = 10 is taken as 4.
  m = LifeModificationFactor(kRoller, 10.0, 0.2);
  EXPECT_TRUE(m.kappa_clamped);
  EXPECT_EQ(m.kappa_used, 4.0);
  EXPECT_EQ(m.a_iso, LifeModificationFactor(kRoller, 4.0, 0.2).a_iso);
  EXPECT_NE(m.note.find("taken as 4"), std::string::npos);
  // κ = 0.09: outside the method, not extrapolated.
  m = LifeModificationFactor(kBall, 0.09, 0.2);
  EXPECT_FALSE(m.computed);
  EXPECT_TRUE(std::isnan(m.a_iso));
  EXPECT_NE(m.note.find("below 0.1"), std::string::npos);
  EXPECT_TRUE(LifeModificationFactor(kBall, 0.1, 0.2).computed);
  // Bad input names the field.
  auto message = [](auto f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message([] { LifeModificationFactor(kBall, 0.0, 0.2); }).find("kappa"), std::string::npos);
  EXPECT_NE(message([] { LifeModificationFactor(kBall, NAN, 0.2); }).find("kappa"), std::string::npos);
  EXPECT_NE(message([] { LifeModificationFactor(kBall, 1.0, -0.1); }).find("e_C C_u / P"), std::string::npos);
  EXPECT_NE(message([] { LifeModificationFactor(kBall, 1.0, NAN); }).find("e_C C_u / P"), std::string::npos);
  EXPECT_NE(message([] { ReferenceViscosity(0.0, 40.0); }).find("speed_rpm"), std::string::npos);
  EXPECT_NE(message([] { ReferenceViscosity(100.0, -1.0); }).find("pitch_diameter_mm"), std::string::npos);
  EXPECT_NE(message([] { CheckContaminationFactor(1.2); }).find("contamination_factor"), std::string::npos);
  EXPECT_NO_THROW(CheckContaminationFactor(0.0));
  EXPECT_NO_THROW(CheckContaminationFactor(1.0));
}

// (e) ν1 at both branches of eq. 28, and the step between them at n = 1000 r/min.
TEST(LifeModification, ReferenceViscosityBothBranches) {
  // n = 500, D_pw = 40: 45000 · 500^−0.83 · 40^−0.5 = 40.92959191 mm²/s.
  EXPECT_NEAR(ReferenceViscosity(500.0, 40.0), 40.929591909500466, 1e-10);
  // n = 3000, D_pw = 40: 4500 · 3000^−0.5 · 40^−0.5 = 12.99038106 mm²/s.
  EXPECT_NEAR(ReferenceViscosity(3000.0, 40.0), 12.99038105676658, 1e-11);
  // Just below and at 1000 r/min, D_pw = 25: 29.1234533 against 28.4604989 (45000·1000^−0.83 =
  // 145.617 against 4500·1000^−0.5 = 142.302: the branches step by 2.3 %, as the standard writes them).
  EXPECT_NEAR(ReferenceViscosity(999.999, 25.0), 29.12345329613484, 1e-9);
  EXPECT_NEAR(ReferenceViscosity(1000.0, 25.0), 28.460498941515414, 1e-10);
}

}  // namespace life_modification_test
}  // namespace camopt
