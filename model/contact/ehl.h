// Elastohydrodynamic (EHL) film thickness of lubricated contacts, isothermal and smooth-surfaced,
// over the scalar T. Units: lengths mm, speeds mm/s, forces N, moduli and pressures MPa, dynamic
// viscosity MPa·s, pressure–viscosity coefficient 1/MPa.
//
// The regression formulas use Hamrock's reduced modulus E' = 2 E* (2/E' = (1 − ν₁²)/E₁ +
// (1 − ν₂²)/E₂; E* as in model/common/material.h) and the mean entraining speed u = (u₁ + u₂)/2 of
// the two surfaces relative to the contact. Dimensionless groups, R the effective radius in the
// entraining (rolling) direction:
//   U = η0 u / (E' R),   G = α E'.
// Line contact (Pan & Hamrock 1989, J. Tribol. 111, 246–251), W' = w' / (E' R), w' load per length:
//   h_min / R = 1.714 W'^−0.128 U^0.694 G^0.568,   h_c / R = 2.922 W'^−0.166 U^0.692 G^0.470.
// Elliptical contact (Hamrock & Dowson 1977, J. Lubr. Technol. 99, 264–276), W = w / (E' R_x²),
// R_x along the entraining direction, R_y across it, ellipticity k = a/b ≈ 1.0339 (R_y/R_x)^0.636:
//   h_min / R_x = 3.63 U^0.68 G^0.49 W^−0.073 (1 − e^(−0.68 k)),
//   h_c   / R_x = 2.69 U^0.67 G^0.53 W^−0.067 (1 − 0.61 e^(−0.73 k)).
// Both were fitted to numerical solutions for steel-like materials (G of a few thousand) and
// bearing-like loads and speeds; the film parameter λ = h_min / √(Rq₁² + Rq₂²) then places a contact
// in boundary (λ < 1), mixed (1–3) or full-film (λ > 3) lubrication.
// Rolling (Poiseuille) force of a line contact, the resistance of the pressure-driven flow in the
// inlet that each surface feels against its motion (Goksem & Hargreaves 1978, J. Lubr. Technol.
// 100, 346–352, isothermal form), per unit length:
//   F_R / L = 4.318 (G U)^0.658 W'^0.0126 R / α.
// The power it takes is F_R (u₁ + u₂) = 2 u F_R: the Poiseuille shear acts on both surfaces in the
// same sense, against the entraining motion (model/contact/lubricated_friction.h RollingLoss). The
// constants were cross-checked against independent public implementations of the formula (its
// thermal form reduces to these at zero thermal loading); the 1978 paper itself was not at hand.
#pragma once

#include <cmath>

#include "model/common/scalar.h"

namespace camopt::contact {

/// Central and minimum film thickness [mm].
template <typename T>
struct EhlFilm {
  T central;
  T minimum;
};

/// The powers of U (so of η0 alone) in the line contact's films and rolling force below: a change of
/// viscosity alone scales each by (η0'/η0)^exponent, which lets a temperature sweep compute the
/// other powers once per contact (model/lcr/lubrication.h).
inline constexpr double kLineCentralFilmSpeedExponent = 0.692;
inline constexpr double kLineMinimumFilmSpeedExponent = 0.694;
inline constexpr double kLineRollingForceSpeedExponent = 0.658;

/// Line contact (Pan & Hamrock 1989). `eta0` [MPa·s] at the inlet's temperature and ambient
/// pressure, `entraining_speed` u [mm/s] > 0, `r_eff` R [mm] (1/R = 1/R₁ + 1/R₂), `load_per_length`
/// w' [N/mm] > 0, `e_star` Hertz's E* [MPa], `alpha` [1/MPa].
template <typename T>
CAMOPT_FLATTEN EhlFilm<T> LineContactFilm(const T& eta0, const T& entraining_speed, const T& r_eff, const T& load_per_length,
                           const T& e_star, const T& alpha) {
  using std::pow;
  const T e_prime = T(2.0) * e_star;
  const T u = eta0 * entraining_speed / (e_prime * r_eff);
  const T g = alpha * e_prime;
  const T w = load_per_length / (e_prime * r_eff);
  return {r_eff * T(2.922) * pow(w, T(-0.166)) * pow(u, T(kLineCentralFilmSpeedExponent)) * pow(g, T(0.470)),
          r_eff * T(1.714) * pow(w, T(-0.128)) * pow(u, T(kLineMinimumFilmSpeedExponent)) * pow(g, T(0.568))};
}

/// Hamrock & Dowson's ellipticity k = a/b ≈ 1.0339 (R_y/R_x)^0.636 (R_y ≥ R_x: the contact is
/// longer across the entraining direction).
template <typename T>
T HamrockDowsonEllipticity(const T& r_x, const T& r_y) {
  using std::pow;
  return T(1.0339) * pow(r_y / r_x, T(0.636));
}

/// Elliptical contact (Hamrock & Dowson 1977): `r_x` the effective radius along the entraining
/// direction, `r_y` across it [mm], `load` w [N] > 0; the rest as LineContactFilm.
template <typename T>
EhlFilm<T> EllipticalContactFilm(const T& eta0, const T& entraining_speed, const T& r_x, const T& r_y,
                                 const T& load, const T& e_star, const T& alpha) {
  using std::exp;
  using std::pow;
  const T e_prime = T(2.0) * e_star;
  const T u = eta0 * entraining_speed / (e_prime * r_x);
  const T g = alpha * e_prime;
  const T w = load / (e_prime * r_x * r_x);
  const T k = HamrockDowsonEllipticity(r_x, r_y);
  return {r_x * T(2.69) * pow(u, T(0.67)) * pow(g, T(0.53)) * pow(w, T(-0.067)) *
              (T(1.0) - T(0.61) * exp(T(-0.73) * k)),
          r_x * T(3.63) * pow(u, T(0.68)) * pow(g, T(0.49)) * pow(w, T(-0.073)) * (T(1.0) - exp(T(-0.68) * k))};
}

/// The rolling (Poiseuille) force per unit length of a line contact [N/mm] (Goksem & Hargreaves
/// 1978, header): arguments as LineContactFilm; R/α [mm·MPa] gives N/mm.
template <typename T>
CAMOPT_FLATTEN T LineContactRollingForcePerLength(const T& eta0, const T& entraining_speed, const T& r_eff, const T& load_per_length,
                                   const T& e_star, const T& alpha) {
  using std::pow;
  if (!(Value(alpha) > 0.0)) return T(0.0);  // no pressure–viscosity rise: no film (G = 0), no force
  const T e_prime = T(2.0) * e_star;
  const T u = eta0 * entraining_speed / (e_prime * r_eff);
  const T g = alpha * e_prime;
  const T w = load_per_length / (e_prime * r_eff);
  return T(4.318) * pow(g * u, T(kLineRollingForceSpeedExponent)) * pow(w, T(0.0126)) * r_eff / alpha;
}

/// Composite roughness √(Rq₁² + Rq₂²) [the unit of the Rq given].
template <typename T>
T CompositeRoughness(const T& rq1, const T& rq2) {
  using std::sqrt;
  return sqrt(rq1 * rq1 + rq2 * rq2);
}

/// Film parameter λ = h_min / σ, σ the composite roughness (same unit as h_min).
template <typename T>
T FilmParameter(const T& h_min, const T& composite_roughness) {
  return h_min / composite_roughness;
}

}  // namespace camopt::contact
