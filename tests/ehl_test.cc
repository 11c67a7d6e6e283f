// The lubricant's viscosity laws (model/common/lubricant.h) and the EHL film formulas
// (model/contact/ehl.h): each against an evaluation written here in SI units from the published
// formula, their scaling laws, and their derivatives against central differences.
#include "model/common/lubricant.h"
#include "model/contact/ehl.h"
#include "model/contact/lubricated_friction.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "model/common/material.h"
#include "tests/test_util.h"

namespace camopt {
namespace ehl_test {

// ASTM D341 written as the chart reads it: Z = log10 log10(ν + 0.7) is a straight line in
// log10 T_K through the two data-sheet points, so at t it is the linear interpolation (or
// extrapolation) of Z in log10 T_K.
double ChartViscosity(double nu40, double nu100, double t_C) {
  const auto z = [](double nu) { return std::log10(std::log10(nu + 0.7)); };
  const double x40 = std::log10(313.15), x100 = std::log10(373.15), x = std::log10(t_C + 273.15);
  const double zt = z(nu40) + (z(nu100) - z(nu40)) * (x - x40) / (x100 - x40);
  return std::pow(10.0, std::pow(10.0, zt)) - 0.7;
}

TEST(Lubricant, WaltherPassesThroughItsTwoPointsAndIsTheChartsStraightLine) {
  Lubricant oil;  // ISO VG 68: 68 and 8.6 mm²/s
  EXPECT_NEAR(oil.KinematicViscosityAt(40.0), 68.0, 1e-10);
  EXPECT_NEAR(oil.KinematicViscosityAt(100.0), 8.6, 1e-12);
  for (double t : {-10.0, 0.0, 20.0, 60.0, 70.0, 80.0, 120.0, 150.0}) {
    const double chart = ChartViscosity(68.0, 8.6, t);
    EXPECT_NEAR(oil.KinematicViscosityAt(t), chart, 1e-10 * chart) << t << " °C";
  }
  // Thinner as it warms.
  for (double t = -10.0; t < 150.0; t += 5.0)
    EXPECT_LT(oil.KinematicViscosityAt(t + 5.0), oil.KinematicViscosityAt(t)) << t;
}

TEST(Lubricant, DynamicViscosityIsDensityTimesKinematicInTheProjectsUnits) {
  Lubricant oil;
  // At 40 °C by hand: ρ = 880 (1 − 6.5e-4 × 25) = 865.7 kg/m³; η = 865.7 × 68e-6 m²/s
  // = 0.0588676 Pa·s = 5.88676e-8 MPa·s.
  EXPECT_NEAR(oil.DensityAt(40.0), 865.7, 1e-9);
  EXPECT_NEAR(oil.DynamicViscosityAt(40.0), 5.88676e-8, 1e-14);
  // Barus: α = 20 GPa⁻¹ at 1 GPa multiplies η0 by e^20.
  EXPECT_NEAR(BarusViscosity(1.0, 0.02, 1000.0), std::exp(20.0), 1e-6);
}

TEST(Lubricant, ValidateNamesWhatIsOutsideTheLaws) {
  Lubricant oil;
  EXPECT_NO_THROW(oil.Validate());
  oil.nu100_mm2_s = 80.0;  // thicker when hot: no Walther law of an oil
  EXPECT_THROW(oil.Validate(), std::invalid_argument);
  oil = Lubricant();
  oil.pressure_viscosity_per_MPa = 0.5;  // 500 GPa⁻¹
  EXPECT_THROW(oil.Validate(), std::invalid_argument);
  oil = Lubricant();
  oil.density15_kg_m3 = 0.0;
  EXPECT_THROW(oil.Validate(), std::invalid_argument);
}

// The published formulas evaluated in SI units (m, Pa, Pa·s, m/s, N, N/m), from Hamrock's E'.
struct SiFilm {
  double central_m, minimum_m;
};

SiFilm HamrockDowsonSi(double eta0_Pa_s, double u_m_s, double rx_m, double ry_m, double w_N, double e1_Pa, double nu1,
                       double e2_Pa, double nu2, double alpha_per_Pa) {
  const double e_prime = 2.0 / ((1 - nu1 * nu1) / e1_Pa + (1 - nu2 * nu2) / e2_Pa);
  const double U = eta0_Pa_s * u_m_s / (e_prime * rx_m), G = alpha_per_Pa * e_prime, W = w_N / (e_prime * rx_m * rx_m);
  const double k = 1.0339 * std::pow(ry_m / rx_m, 0.636);
  return {rx_m * 2.69 * std::pow(U, 0.67) * std::pow(G, 0.53) * std::pow(W, -0.067) * (1 - 0.61 * std::exp(-0.73 * k)),
          rx_m * 3.63 * std::pow(U, 0.68) * std::pow(G, 0.49) * std::pow(W, -0.073) * (1 - std::exp(-0.68 * k))};
}

SiFilm PanHamrockSi(double eta0_Pa_s, double u_m_s, double r_m, double w_N_per_m, double e1_Pa, double nu1, double e2_Pa,
                    double nu2, double alpha_per_Pa) {
  const double e_prime = 2.0 / ((1 - nu1 * nu1) / e1_Pa + (1 - nu2 * nu2) / e2_Pa);
  const double U = eta0_Pa_s * u_m_s / (e_prime * r_m), G = alpha_per_Pa * e_prime, W = w_N_per_m / (e_prime * r_m);
  return {r_m * 2.922 * std::pow(W, -0.166) * std::pow(U, 0.692) * std::pow(G, 0.470),
          r_m * 1.714 * std::pow(W, -0.128) * std::pow(U, 0.694) * std::pow(G, 0.568)};
}

// Three contacts: a roller on a cam (line), a crowned roller (elliptical, long across the rolling
// direction) and a ball-like contact of steel on bronze (nearly circular).
TEST(EhlFilm, FormulasAgreeWithAnSiEvaluationOfThePublishedOnes) {
  const double e_steel = 206000.0, e_bronze = 110000.0;
  {
    // Line: R = 8 mm, 400 N/mm, u = 2 m/s, η0 = 0.05 Pa·s, α = 20 GPa⁻¹, steel on steel.
    const double e_star = CompositeModulus(e_steel, 0.3, e_steel, 0.3);
    const auto film = contact::LineContactFilm(5e-8, 2000.0, 8.0, 400.0, e_star, 0.02);
    const SiFilm si = PanHamrockSi(0.05, 2.0, 8e-3, 400e3, e_steel * 1e6, 0.3, e_steel * 1e6, 0.3, 2e-8);
    EXPECT_NEAR(film.minimum * 1e-3, si.minimum_m, 1e-12 * si.minimum_m);
    EXPECT_NEAR(film.central * 1e-3, si.central_m, 1e-12 * si.central_m);
    // Of the order EHL gives such a contact (tenths of a micrometre), the minimum below the centre.
    EXPECT_GT(film.minimum, 1e-5);
    EXPECT_LT(film.minimum, 1e-3);
    EXPECT_LT(film.minimum, film.central);
  }
  {
    // Crowned roller: R_x = 6 mm, R_y = 400 mm (k ≈ 14.9), 2 kN, u = 3 m/s.
    const double e_star = CompositeModulus(e_steel, 0.3, e_steel, 0.3);
    const auto film = contact::EllipticalContactFilm(3e-8, 3000.0, 6.0, 400.0, 2000.0, e_star, 0.018);
    const SiFilm si = HamrockDowsonSi(0.03, 3.0, 6e-3, 0.4, 2000.0, e_steel * 1e6, 0.3, e_steel * 1e6, 0.3, 1.8e-8);
    EXPECT_NEAR(film.minimum * 1e-3, si.minimum_m, 1e-12 * si.minimum_m);
    EXPECT_NEAR(film.central * 1e-3, si.central_m, 1e-12 * si.central_m);
  }
  {
    // Near-circular, steel on bronze: R_x = 5 mm, R_y = 6 mm, 300 N, u = 1 m/s.
    const double e_star = CompositeModulus(e_steel, 0.3, e_bronze, 0.34);
    const auto film = contact::EllipticalContactFilm(8e-8, 1000.0, 5.0, 6.0, 300.0, e_star, 0.022);
    const SiFilm si =
        HamrockDowsonSi(0.08, 1.0, 5e-3, 6e-3, 300.0, e_steel * 1e6, 0.3, e_bronze * 1e6, 0.34, 2.2e-8);
    EXPECT_NEAR(film.minimum * 1e-3, si.minimum_m, 1e-12 * si.minimum_m);
    EXPECT_NEAR(film.central * 1e-3, si.central_m, 1e-12 * si.central_m);
  }
}

// A published worked example (a problem in the style of Stachowiak & Batchelor, Engineering
// Tribology, ch. 7, as posted with its answer at tutorbin.com, "A steel ball starts rolling from rest
// down a steel plate inclined at 45°"): a steel ball, d = 30 mm, ρ = 7800 kg/m³, E = 210 GPa,
// ν = 0.3, rolls without sliding down an oiled steel plate (η0 = 50 cP, α = 2.2e-8 m²/N) from rest;
// the minimum film after 1 cm and 1 m of rolling is printed as 0.059 and 0.281 µm. The problem's
// book writes Hamrock & Dowson's formula on the reduced radius R' = (1/R_x + 1/R_y)⁻¹ = r/2 (for
// both radii, so k = 1.0339) and takes the entraining speed as the mean of the two bodies' speeds
// in the plate's frame, u = v/2; this test feeds its function those conventions. (camopt's own
// calls use Hamrock & Dowson's R_x and the contact frame's mean speed, u = v: 0.127 and 0.608 µm
// for this case; the difference is the conventions, not the formula — docs/validation.md.)
TEST(EhlFilm, APublishedWorkedExampleInItsOwnConventions) {
  const double pi = 3.14159265358979323846, g = 9.81, r = 15.0;           // mm
  const double mass_kg = 7800.0 * 4.0 / 3.0 * pi * std::pow(r * 1e-3, 3);  // 0.1103 kg
  const double load_N = mass_kg * g * std::cos(pi / 4);                    // the normal load on the incline
  const double e_star = CompositeModulus(210000.0, 0.3, 210000.0, 0.3);
  const double printed_um[] = {0.059, 0.281};
  const double distance_m[] = {0.01, 1.0};
  for (int i = 0; i < 2; ++i) {
    // Rolling without sliding from rest: v² = 2 g s sin 45° / (1 + I/(m r²)), I = 2/5 m r².
    const double v_mm_s = 1e3 * std::sqrt(2.0 * g * distance_m[i] * std::sin(pi / 4) / 1.4);
    const auto film = contact::EllipticalContactFilm(5e-8, v_mm_s / 2, r / 2, r / 2, load_N, e_star, 0.022);
    // Within one unit of the printed answer's last digit (0.0587 and 0.2812 µm).
    EXPECT_NEAR(film.minimum * 1e3, printed_um[i], 0.0005) << distance_m[i];
  }
}

// Goksem & Hargreaves' rolling force per length, evaluated in SI (m, Pa, Pa·s, m/s, N/m): E' =
// 226 GPa, R = 10 mm, η0 = 0.05 Pa·s, α = 2e-8 m²/N, u = 5 m/s, w' = 1e5 N/m.
TEST(EhlFilm, RollingForceAgreesWithAnSiEvaluationAndScalesAsItsExponents) {
  const double e_prime = 2.26e11, r = 0.01, eta = 0.05, alpha = 2e-8, u = 5.0, w = 1e5;
  const double U = eta * u / (e_prime * r), G = alpha * e_prime, W = w / (e_prime * r);
  const double si_N_per_m = 4.318 * std::pow(G * U, 0.658) * std::pow(W, 0.0126) * r / alpha;  // 135.93 N/m
  const auto force = [&](double speed_mm_s, double load_N_per_mm) {
    return contact::LineContactRollingForcePerLength(eta * 1e-6, speed_mm_s, r * 1e3, load_N_per_mm, e_prime / 2e6,
                                                     alpha * 1e6);
  };
  EXPECT_NEAR(force(u * 1e3, w * 1e-3) * 1e3, si_N_per_m, 1e-12 * si_N_per_m);
  EXPECT_NEAR(si_N_per_m, 135.93, 0.01);
  // F_R grows as (η0 u)^0.658 and hardly with load (w'^0.0126); its power 2 u F_R as u^1.658.
  EXPECT_NEAR(force(2 * u * 1e3, w * 1e-3) / force(u * 1e3, w * 1e-3), std::pow(2.0, 0.658), 1e-12);
  EXPECT_NEAR(force(u * 1e3, 2 * w * 1e-3) / force(u * 1e3, w * 1e-3), std::pow(2.0, 0.0126), 1e-12);
  const double p1 = contact::RollingLoss(force(u * 1e3, 100.0), u * 1e3), p2 = contact::RollingLoss(force(2 * u * 1e3, 100.0), 2 * u * 1e3);
  EXPECT_NEAR(p2 / p1, std::pow(2.0, 1.658), 1e-12);
  EXPECT_NEAR(p1, 2 * u * 1e3 * force(u * 1e3, 100.0), 1e-12 * p1);
  // No pressure–viscosity rise (α = 0): no film and no rolling force.
  EXPECT_EQ(contact::LineContactRollingForcePerLength(5e-8, 5000.0, 10.0, 100.0, 113000.0, 0.0), 0.0);
}

TEST(EhlFilm, ScalesAsTheFormulasExponentsSay) {
  const double e_star = CompositeModulus(206000.0, 0.3, 206000.0, 0.3);
  const auto line = [&](double eta, double u, double w) { return contact::LineContactFilm(eta, u, 8.0, w, e_star, 0.02); };
  const auto a = line(5e-8, 2000.0, 400.0);
  // Film grows with η0 u: doubling the speed (or the viscosity) multiplies h_min by 2^0.694.
  EXPECT_NEAR(line(5e-8, 4000.0, 400.0).minimum / a.minimum, std::pow(2.0, 0.694), 1e-12);
  EXPECT_NEAR(line(1e-7, 2000.0, 400.0).minimum / a.minimum, std::pow(2.0, 0.694), 1e-12);
  // Barely with load: doubling it multiplies h_min by 2^−0.128.
  EXPECT_NEAR(line(5e-8, 2000.0, 800.0).minimum / a.minimum, std::pow(2.0, -0.128), 1e-12);
  const auto ell = [&](double u, double w) { return contact::EllipticalContactFilm(5e-8, u, 6.0, 60.0, w, e_star, 0.02); };
  const auto b = ell(2000.0, 1000.0);
  EXPECT_NEAR(ell(4000.0, 1000.0).minimum / b.minimum, std::pow(2.0, 0.68), 1e-12);
  EXPECT_NEAR(ell(2000.0, 2000.0).minimum / b.minimum, std::pow(2.0, -0.073), 1e-12);
  // A contact longer across the rolling direction (larger k) holds a thicker film, toward the
  // line contact's side-leakage-free limit: (1 − e^(−0.68k)) → 1.
  EXPECT_GT(contact::EllipticalContactFilm(5e-8, 2000.0, 6.0, 600.0, 1000.0, e_star, 0.02).minimum, b.minimum);
  EXPECT_NEAR(contact::HamrockDowsonEllipticity(5.0, 5.0), 1.0339, 1e-15);
}

TEST(EhlFilm, FilmParameterFromTheCompositeRoughness) {
  // h_min 0.5 µm over Rq 0.3 and 0.4 µm: σ = 0.5 µm, λ = 1 (the boundary–mixed border).
  EXPECT_NEAR(contact::CompositeRoughness(0.3e-3, 0.4e-3), 0.5e-3, 1e-18);
  EXPECT_NEAR(contact::FilmParameter(0.5e-3, contact::CompositeRoughness(0.3e-3, 0.4e-3)), 1.0, 1e-12);
}

// x = {η0 [mPa·s], u [m/s], R or R_x [mm], w' [N/mm] or w [kN], t [°C]}: scaled so that each is of
// order one to a hundred (the central-difference step is ∛ε·max(1, |x|)).
TEST(EhlFilm, GradientsMatchCentralDifferences) {
  const double e_star = CompositeModulus(206000.0, 0.3, 206000.0, 0.3);
  auto f = [&](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    const auto line = contact::LineContactFilm(x[0] * T(1e-9), x[1] * T(1000.0), x[2], x[3], T(e_star), T(0.02));
    const auto ell =
        contact::EllipticalContactFilm(x[0] * T(1e-9), x[1] * T(1000.0), x[2], T(8.0) * x[2], x[3] * T(5.0), T(e_star), T(0.02));
    const T rolling = contact::LineContactRollingForcePerLength(x[0] * T(1e-9), x[1] * T(1000.0), x[2], x[3],
                                                                T(e_star), T(0.02));
    // Scaled to µm (films) and N/m (the rolling force) so that the outputs are of order one.
    return std::vector<T>{line.minimum * T(1e3), line.central * T(1e3), ell.minimum * T(1e3), ell.central * T(1e3),
                          rolling * T(1e3)};
  };
  testing::ExpectJacobianMatchesCentralDifferences<4>(f, {50.0, 2.0, 8.0, 400.0});
  auto g = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    const Lubricant oil;
    // ν [mm²/s] and η0 [mPa·s] against temperature.
    return std::vector<T>{oil.KinematicViscosityAt(x[0]), oil.DynamicViscosityAt(x[0]) * T(1e9)};
  };
  testing::ExpectJacobianMatchesCentralDifferences<1>(g, {55.0});
}

}  // namespace ehl_test
}  // namespace camopt
