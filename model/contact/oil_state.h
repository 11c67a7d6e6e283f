// The oil's state at one temperature as the lubricated losses take it, split from the contacts'
// and bearings' temperature-free parts: ν and ν^(2/3) (Palmgren's M0, model/common/bearing_friction.h)
// and the powers of η0 by which the line contact's minimum film and rolling force scale
// (model/contact/ehl.h: both are a power of η0 alone at a given speed, load and radius). A sweep over
// the oil's temperature (the housing's heat balance) then evaluates each contact's formulas once, at
// η0 = 1 MPa·s, and multiplies (model/lcr/lubrication.h, model/cycloid/lubrication.h).
#pragma once

#include <cmath>

#include "model/common/lubricant.h"
#include "model/common/scalar.h"
#include "model/contact/ehl.h"

namespace camopt::contact {

template <typename T>
struct OilState {
  T nu{}, nu_2_3{};  ///< ν [mm²/s] and ν^(2/3)
  T film_scale{};     ///< η0^0.694: h_min at η0 over h_min at 1 MPa·s
  T rolling_scale{};  ///< η0^0.658: the rolling force's
};

template <typename T>
CAMOPT_FLATTEN OilState<T> OilStateAt(const Lubricant& oil, const T& oil_C) {
  using std::cbrt;
  using std::pow;
  OilState<T> o;
  o.nu = oil.KinematicViscosityAt(oil_C);
  o.nu_2_3 = cbrt(o.nu * o.nu);
  const T eta0 = oil.DynamicViscosityAt(oil_C);
  o.film_scale = pow(eta0, T(kLineMinimumFilmSpeedExponent));
  o.rolling_scale = pow(eta0, T(kLineRollingForceSpeedExponent));
  return o;
}

}  // namespace camopt::contact
