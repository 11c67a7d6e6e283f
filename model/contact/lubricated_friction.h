// Friction of a lubricated contact by lubrication regime, and the loss it dissipates, over the
// scalar T.
//
// The regime follows the film parameter λ = h_min / σ (model/contact/ehl.h): boundary below λ = 1,
// full film above λ = 3, mixed between (the usual classification by film parameter, e.g. Hamrock,
// Schmid & Jacobson, Fundamentals of Fluid Film Lubrication, 2004). The coefficient blends a boundary coefficient μ_b and a full-film
// (EHL traction) coefficient μ_f over the mixed band with the quintic smoothstep s (C², so that a
// sizing's derivatives stay continuous):
//   μ(λ) = μ_f + (μ_b − μ_f) (1 − s(x)),  x = (λ − 1)/(3 − 1) clamped to [0, 1],
//   s(x) = 6x⁵ − 15x⁴ + 10x³.
// This blend is a stated modelling choice (the regime borders and the two coefficients are the
// inputs; between them the share of the load carried by asperities is taken to fall smoothly from
// one to zero), not a law fitted to measurements; μ_b ≈ 0.08–0.12 for steel on steel with mineral
// oil, μ_f ≈ 0.02–0.06 for EHL traction at moderate slide-to-roll ratios are typical values.
// The sliding loss of a contact is P = μ F |v_s| (F the normal load, v_s the sliding speed); the
// rolling (Poiseuille) loss P = F_R (u₁ + u₂) = 2 u F_R (F_R of model/contact/ehl.h, u the mean
// entraining speed).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "model/common/scalar.h"

namespace camopt::contact {

/// The regime borders of the film parameter λ.
inline constexpr double kBoundaryLambda = 1.0;
inline constexpr double kFullFilmLambda = 3.0;

/// The two coefficients of the blend.
struct RegimeFriction {
  double boundary = 0.1;    ///< μ_b, λ ≤ 1
  double full_film = 0.03;  ///< μ_f, λ ≥ 3
  bool operator==(const RegimeFriction&) const = default;

  void Validate() const {
    if (!(boundary >= 0.0 && boundary <= 1.0 && full_film >= 0.0 && full_film <= 1.0))
      throw std::invalid_argument("friction: expected coefficients in [0, 1], found boundary " +
                                  std::to_string(boundary) + ", full film " + std::to_string(full_film));
  }
};

/// The quintic smoothstep s(x) = 6x⁵ − 15x⁴ + 10x³ on [0, 1] (0 below, 1 above): C² at both ends.
template <typename T>
CAMOPT_FLATTEN T QuinticSmoothstep(const T& x) {
  // The pieces join with value and two derivatives (s(0) = 0, s(1) = 1, s' = s'' = 0 at both ends).
  return IfThenElse(Compare::kLessEqual, x, 0.0, T(0.0),
                    IfThenElse(Compare::kGreaterEqual, x, 1.0, T(1.0),
                               T(x * x * x * (x * (x * T(6.0) - T(15.0)) + T(10.0)))));
}

/// The share of the load carried by asperity contact in the blend, 1 − s((λ − 1)/2): 1 in the
/// boundary regime, 0 in full film.
template <typename T>
T BoundaryShare(const T& lambda) {
  return T(1.0) - QuinticSmoothstep((lambda - T(kBoundaryLambda)) / T(kFullFilmLambda - kBoundaryLambda));
}

/// μ(λ) of the blend.
template <typename T>
T FrictionCoefficient(const RegimeFriction& law, const T& lambda) {
  return T(law.full_film) + T(law.boundary - law.full_film) * BoundaryShare(lambda);
}

/// The power a contact dissipates by sliding, μ F |v_s| [N·mm/s for N and mm/s; 1e-3 W].
template <typename T>
T SlidingLoss(const T& mu, const T& normal_load, const T& sliding_speed) {
  using std::abs;
  return mu * normal_load * abs(sliding_speed);
}

/// The power the rolling (Poiseuille) force F_R takes from a contact whose surfaces move at the mean
/// entraining speed u: F_R on each surface against its motion, 2 u F_R [N·mm/s for N and mm/s].
template <typename T>
T RollingLoss(const T& rolling_force, const T& entraining_speed) {
  using std::abs;
  return T(2.0) * rolling_force * abs(entraining_speed);
}

}  // namespace camopt::contact
