// The thermal operating point of a lubricated drive: the oil temperature t at which the heat the
// housing gives off equals the power lost,
//   g(t) = P_loss(t) − k A (t − t_amb) = 0,
// P_loss(t) from the losses at the oil's viscosity at t (model/common/lubricant.h), k A the
// housing's heat-transfer coefficient times its area (convection and radiation together, plus any
// forced cooling as a further W/K). g(t_amb) = P_loss ≥ 0; when g stays positive up to the oil's
// limit there is no equilibrium below it, and the solve says so instead of returning a number.
// Solved by the Illinois variant of regula falsi on the bracket [t_amb, t_max] (superlinear, never
// leaves the bracket); the residual g at the answer is returned with it.
//
// Derivatives: with the losses depending on parameters p (a design's sizes, a torque), the solve
// runs on values and the answer carries dt/dp = −(∂g/∂p)/(∂g/∂t) (implicit function theorem), ∂g/∂p
// from the loss evaluated over the scalar T at the answer, ∂g/∂t by a central difference of values.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

#include "model/common/scalar.h"

namespace camopt {

/// The housing's heat path to the ambient.
struct HousingCooling {
  double area_m2 = 0.1;
  double heat_transfer_W_per_m2K = 15.0;  ///< still air, convection and radiation together
  double forced_W_per_K = 0.0;            ///< a fan or an oil cooler, if any
  double ambient_C = 20.0;
  bool operator==(const HousingCooling&) const = default;

  double conductance_W_per_K() const { return area_m2 * heat_transfer_W_per_m2K + forced_W_per_K; }
};

template <typename T>
struct ThermalPoint {
  bool found = false;   ///< an equilibrium within [ambient, limit] with |residual| ≤ tolerance × loss
  T temperature_C{};    ///< the oil temperature
  T loss_W{};           ///< P_loss at it
  double residual_W = 0.0;  ///< g at the answer
  double slope_W_per_K = 0.0;  ///< ∂g/∂t at the answer (central difference of values)
  int evaluations = 0;
  std::string why;      ///< when not found
};

/// The operating point over T from a solve on values (`solved`, found): t + dt with
/// dt = −g_T(t)/g'(t), whose value part is −g_value/g' ≈ 0 and whose derivative part is
/// −(∂g/∂p)/g'(t); the loss at the answer moves with it, dP/dp = ∂P/∂p + P'(t) dt/dp, P' = g' + k A.
/// One evaluation of `loss_W` over T: what a sizing's derivative pass costs once the values' pass
/// has solved the balance.
template <typename T, typename Loss>
ThermalPoint<T> OperatingPointOver(const Loss& loss_W, const HousingCooling& cooling,
                                   const ThermalPoint<double>& solved) {
  ThermalPoint<T> out;
  out.found = solved.found;
  out.why = solved.why;
  out.residual_W = solved.residual_W;
  out.slope_W_per_K = solved.slope_W_per_K;
  out.evaluations = solved.evaluations + 1;
  if (!solved.found) return out;
  const double k = cooling.conductance_W_per_K(), t = solved.temperature_C;
  const T loss_T = loss_W(T(t));
  const T g_T = loss_T - T(k * (t - cooling.ambient_C));
  out.temperature_C = T(t) - (g_T - T(Value(g_T))) / T(solved.slope_W_per_K);
  out.loss_W = loss_T + T(solved.slope_W_per_K + k) * (out.temperature_C - T(t));
  return out;
}

/// Solves g(t) = 0 for the oil temperature. `loss_W(t)`: the power lost at oil temperature t, a
/// callable taking T and returning T (its parameters, captured, may be Jets). `limit_C`: the oil's
/// highest allowed temperature. Stops when |g| ≤ rel_tolerance × P_loss.
template <typename T, typename Loss>
ThermalPoint<T> SolveOperatingTemperature(const Loss& loss_W, const HousingCooling& cooling, double limit_C,
                                          double rel_tolerance = 1e-9, int max_evaluations = 100) {
  ThermalPoint<T> out;
  const double k = cooling.conductance_W_per_K(), t_amb = cooling.ambient_C;
  double last_t = NAN, last_loss = NAN;  // the loss at the last t evaluated
  const auto g = [&](double t) {
    ++out.evaluations;
    last_t = t;
    last_loss = Value(loss_W(T(t)));
    return last_loss - k * (t - t_amb);
  };
  if (!(k > 0.0) || !(limit_C > t_amb)) {
    out.why = "no heat path: expected a housing conductance > 0 W/K and an oil limit above the ambient";
    return out;
  }
  double lo = t_amb, hi = limit_C, g_lo = g(lo), g_hi = g(hi);
  if (!std::isfinite(g_lo) || !std::isfinite(g_hi)) {
    out.why = "the loss is not finite between the ambient and the oil's limit";
    return out;
  }
  if (g_lo <= 0.0) {  // no loss: the oil stays at the ambient
    lo = hi = t_amb;
    g_hi = g_lo;
  } else if (g_hi > 0.0) {
    out.why = "no equilibrium below the oil's limit of " + std::to_string(limit_C) + " °C: the housing gives off " +
              std::to_string(k * (limit_C - t_amb)) + " W there against a loss of " +
              std::to_string(g_hi + k * (limit_C - t_amb)) + " W";
    return out;
  }
  double t = hi, g_t = g_hi;
  int side = 0;
  while (lo < hi && out.evaluations < max_evaluations) {
    t = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
    g_t = g(t);
    const double loss = g_t + k * (t - t_amb);
    if (std::abs(g_t) <= rel_tolerance * std::max(loss, 1e-300)) break;
    if (g_t > 0.0) {
      lo = t, g_lo = g_t;
      if (side == -1) g_hi *= 0.5;  // Illinois: the stale end's value halved
      side = -1;
    } else {
      hi = t, g_hi = g_t;
      if (side == 1) g_lo *= 0.5;
      side = 1;
    }
  }
  const double loss_value = last_t == t ? last_loss : g_t + k * (t - t_amb);
  out.residual_W = g_t;
  if (!(std::abs(g_t) <= rel_tolerance * std::max(loss_value, 1e-300)) && lo < hi) {
    out.why = "the temperature did not converge in " + std::to_string(max_evaluations) + " evaluations (residual " +
              std::to_string(g_t) + " W)";
    return out;
  }
  out.temperature_C = T(t);
  out.loss_W = T(loss_value);
  const double h = 1e-4 * std::max(1.0, std::abs(t));
  out.slope_W_per_K = (g(t + h) - g(t - h)) / (2.0 * h);
  if constexpr (!std::is_same_v<T, double>) return OperatingPointOver<T>(loss_W, cooling, ThermalPoint<double>{
      true, t, loss_value, out.residual_W, out.slope_W_per_K, out.evaluations, {}});
  out.found = true;
  return out;
}

}  // namespace camopt
