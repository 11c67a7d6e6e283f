// Rolling-bearing life: ISO 281:2007 basic rating life, the equivalent load of a load that varies
// over a revolution and over a duty cycle, Palmgren–Miner damage summation, the static safety
// factor, and a smooth life margin for sizing. Over the scalar T (double or ceres::Jet).
// Units: forces N, speeds rpm, lives in millions of revolutions (_Mrev) or hours (_h).
//
// ISO 281:2007 §5.3 (radial ball) and §6.3 (radial roller bearings): the basic rating life
// L10 = (C/P)^p [10⁶ rev], p = 3 for ball and 10/3 for roller bearings; at a constant speed n,
// L10h = 10⁶ L10 / (60 n) [h]. (The modified life L_nm = a1 a_ISO L10 of §9.3: life_modification.h.)
// A load F(θ) that varies over a revolution has the constant equivalent load of the same life,
//   P = ( (1/2π) ∫₀^{2π} F(θ)^p dθ )^(1/p),
// the revolution-weighted p-mean (the cubic mean for balls). For a duty cycle of lines i with
// time shares t_i and speeds n_i, line i turns a share t_i n_i / Σ t_j n_j of the revolutions, and
// Palmgren–Miner damage summation (Palmgren 1924; Miner 1945) gives 1/L10h = Σ t_i / L10h,i. Both
// routes give the same life (the algebra is in DutyCycleLifeHours's comment; tests/bearing_life_test.cc
// checks it).
//
// A stationary line (n = 0) adds no revolutions and no fatigue damage; it is judged by the static
// safety factor s0 = C0 / P0 instead (C0 and P0 per ISO 76:2006; s0 as the catalogues define it).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/common/argument_check.h"
#include "model/common/scalar.h"

namespace camopt {

/// Ball or roller bearing: selects the life exponent p of ISO 281:2007.
enum class BearingKind { kBall, kRoller };

/// The life exponent p of ISO 281:2007 §5.3 / §6.3: 3 for ball, 10/3 for roller bearings.
inline double LifeExponent(BearingKind kind) { return kind == BearingKind::kBall ? 3.0 : 10.0 / 3.0; }

/// Tolerance on the sum of a duty cycle's time shares: |Σ t_i − 1| <= kTimeShareSumTolerance.
inline constexpr double kTimeShareSumTolerance = 1e-9;

/// One line of a duty cycle: the share of time it runs, its speed, and the bearing's load sampled
/// at N uniform angles θ_k = 2π k / N of one revolution (or one load cycle) of that line.
/// @tparam T double or ceres::Jet (speeds and loads may carry derivatives; shares are data).
template <typename T>
struct DutyCycleLine {
  double time_share = 1.0;   ///< t_i, in [0, 1]; the shares of a duty cycle sum to 1
  T speed_rpm = T(0.0);      ///< n_i [rpm], >= 0
  std::vector<T> loads_N;    ///< F_ik [N], finite, >= 0, at uniform angles; at least one
};

/// One line of a reducer's duty cycle in model units, as a study gives it (output torque, input
/// speed, time share); every reducer kind turns it into its bearings' DutyCycleLines.
struct OperatingLine {
  double output_torque_Nmm = 0.0, input_speed_rpm = 0.0, time_share = 1.0;
  bool operator==(const OperatingLine&) const = default;
};

namespace bearing_life_internal {

// model/common/argument_check.h, its messages starting "bearing life: ".
inline constexpr const char* kWhat = "bearing life";
[[noreturn]] inline void Reject(const std::string& f, const std::string& r, double v) { argument_check::Reject(kWhat, f, r, v); }
template <typename T>
void CheckPositive(const std::string& field, const T& x) { argument_check::Positive(kWhat, field, x); }
template <typename T>
void CheckNonNegative(const std::string& field, const T& x) { argument_check::NonNegative(kWhat, field, x); }

template <typename T>
void CheckLoads(const std::string& field, const std::vector<T>& loads) {
  if (loads.empty()) Reject(field + ".size()", ">= 1", 0.0);
  for (size_t k = 0; k < loads.size(); ++k) CheckNonNegative(field + "[" + std::to_string(k) + "]", loads[k]);
}

/// The largest value of the samples as a double (a constant scale; 0 when every sample is 0).
template <typename T>
double LargestValue(const std::vector<T>& loads) {
  double s = 0.0;
  for (const T& f : loads) s = std::max(s, Value(f));
  return s;
}

/// (1/N) Σ_k (F_k / s)^p for a constant scale s > 0.
template <typename T>
T ScaledMeanOfPower(const std::vector<T>& loads, double scale, double p) {
  using std::pow;
  T sum(0.0);
  for (const T& f : loads) sum += pow(f / scale, p);
  return sum / double(loads.size());
}

}  // namespace bearing_life_internal

/// Checks a duty cycle: at least one line; shares >= 0 summing to 1 within kTimeShareSumTolerance;
/// speeds finite >= 0, at least one > 0 (no revolutions, no rating life); loads finite >= 0.
/// @throws std::invalid_argument naming the field (`duty_cycle[i].speed_rpm`, ...) and its value.
template <typename T>
void ValidateDutyCycle(const std::vector<DutyCycleLine<T>>& lines) {
  using bearing_life_internal::Reject;
  if (lines.empty()) Reject("duty_cycle.size()", ">= 1", 0.0);
  double share_sum = 0.0, speed_max = 0.0;
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string line = "duty_cycle[" + std::to_string(i) + "]";
    const double t = lines[i].time_share;
    if (!(std::isfinite(t) && t >= 0.0 && t <= 1.0)) Reject(line + ".time_share", "in [0, 1]", t);
    share_sum += t;
    bearing_life_internal::CheckNonNegative(line + ".speed_rpm", lines[i].speed_rpm);
    speed_max = std::max(speed_max, Value(lines[i].speed_rpm));
    bearing_life_internal::CheckLoads(line + ".loads_N", lines[i].loads_N);
  }
  if (!(std::abs(share_sum - 1.0) <= kTimeShareSumTolerance))
    Reject("the sum of duty_cycle[*].time_share", "1 (within 1e-9)", share_sum);
  if (!(speed_max > 0.0)) Reject("the largest duty_cycle[*].speed_rpm", "> 0 (no revolutions, no rating life)", 0.0);
}

/// ISO 281:2007 §5.3 / §6.3: the basic rating life L10 = (C/P)^p [10⁶ revolutions].
/// P = 0 gives +∞ (no load, no fatigue).
/// @tparam T double or ceres::Jet.  @param dynamic_rating_N C [N], > 0.
/// @param equivalent_load_N P [N], finite, >= 0.  @param kind ball (p = 3) or roller (p = 10/3).
/// @throws std::invalid_argument for C <= 0 or a negative or non-finite P.
template <typename T>
T BasicRatingLifeMrev(const T& dynamic_rating_N, const T& equivalent_load_N, BearingKind kind) {
  using std::pow;
  bearing_life_internal::CheckPositive("C_N", dynamic_rating_N);
  bearing_life_internal::CheckNonNegative("P_N", equivalent_load_N);
  if (Value(equivalent_load_N) == 0.0) return T(kInf);
  return pow(dynamic_rating_N / equivalent_load_N, LifeExponent(kind));
}

/// ISO 281:2007 §5.3 / §6.3: the basic rating life in operating hours at a constant speed,
/// L10h = 10⁶ L10 / (60 n). n = 0 gives +∞ (no revolutions).
/// @param life_Mrev L10 [10⁶ rev], >= 0.  @param speed_rpm n [rpm], finite, >= 0.
/// @throws std::invalid_argument for a negative life or a negative or non-finite speed.
template <typename T>
T RatingLifeHours(const T& life_Mrev, const T& speed_rpm) {
  const double l = Value(life_Mrev);
  if (!(l >= 0.0)) bearing_life_internal::Reject("L10_Mrev", ">= 0", l);
  bearing_life_internal::CheckNonNegative("speed_rpm", speed_rpm);
  if (Value(speed_rpm) == 0.0) return T(kInf);
  return T(1e6) * life_Mrev / (T(60.0) * speed_rpm);
}

/// The equivalent load of a load varying over one revolution: the revolution-weighted p-mean
///   P = ( (1/2π) ∫ F(θ)^p dθ )^(1/p)  ≈  ( (1/N) Σ_k F(θ_k)^p )^(1/p),  θ_k = 2π k / N.
/// Quadrature: the uniform-sample mean is the trapezoidal rule on a periodic integrand. For a
/// smooth periodic load it is spectrally accurate: exact when F^p is a trigonometric polynomial of
/// degree < N (F = F0 (1 + a cos θ) with p = 3 from N = 4 on), and with error O(e^{−σN}) when F^p
/// is analytic in a strip |Im θ| < σ (any F > 0 smooth). For a load that is zero over part of the
/// cycle (a roller out of contact), the error is set by how the load leaves zero: F rising
/// linearly from 0 at the ends of the loaded arc makes F^p ~ (θ − θ0)₊^p, whose Fourier
/// coefficients fall as |m|^−(p+1), and the error in the mean of F^p is O(N^−(p+1)) (N^−4 for
/// balls, N^−13/3 for rollers); a load that jumps at an end (by Δ in F^p) adds an error below
/// |Δ|/N per jump — first order, the case where N matters. The relative error of P is 1/p of the
/// relative error of the mean of F^p. At P = 0 (every sample 0) the p-mean is not differentiable
/// (it is a norm at the origin); there it returns 0 with zero derivative.
/// @param loads_N F(θ_k) [N] at uniform angles, finite, >= 0, at least one.
/// @throws std::invalid_argument for no samples or a negative or non-finite sample.
template <typename T>
T EquivalentLoad(const std::vector<T>& loads_N, BearingKind kind) {
  using std::pow;
  bearing_life_internal::CheckLoads("loads_N", loads_N);
  const double p = LifeExponent(kind);
  // Scaled by the largest sample (a constant), so F^p cannot overflow: P = s (mean (F/s)^p)^(1/p).
  const double s = bearing_life_internal::LargestValue(loads_N);
  if (s == 0.0) return T(0.0);
  return T(s) * pow(bearing_life_internal::ScaledMeanOfPower(loads_N, s, p), 1.0 / p);
}

/// The equivalent load of a load sampled at angles where the bearing does not turn uniformly: the
/// revolution-weighted p-mean with weights w_k ∝ dφ_k, the bearing's rotation over sample k,
///   P = ( ∫ F^p dφ / ∫ dφ )^(1/p)  ≈  ( Σ_k w_k F_k^p / Σ_k w_k )^(1/p).
/// The rating life counts revolutions (ISO 281:2007 §5.3 / §6.3: L10 in 10⁶ revolutions), so where
/// the speed varies over the load cycle (an LCR roller rolling on its cam) each load counts by the
/// revolutions turned under it, not by the time or input angle spent under it. With w_k = dφ/dθ at
/// uniform θ_k the quadrature is EquivalentLoad's (the trapezoidal rule on the periodic w F^p).
/// Equal weights give EquivalentLoad. Loads and weights may carry derivatives (W = T: weights that
/// depend on the design, as a roller's spin rate in a sizing) or the weights be data (W = double).
/// @param loads_N F_k [N], finite, >= 0, at least one.  @param weights w_k, finite, >= 0, one per
/// load, not all 0.
/// @throws std::invalid_argument for mismatched sizes, a negative or non-finite load or weight, or
/// weights that are all 0.
template <typename T, typename W>
T EquivalentLoad(const std::vector<T>& loads_N, const std::vector<W>& weights, BearingKind kind) {
  using std::pow;
  bearing_life_internal::CheckLoads("loads_N", loads_N);
  if (weights.size() != loads_N.size())
    bearing_life_internal::Reject("weights.size()", "loads_N.size() (" + std::to_string(loads_N.size()) + ")",
                                  double(weights.size()));
  W weight_sum(0.0);
  for (size_t k = 0; k < weights.size(); ++k) {
    bearing_life_internal::CheckNonNegative("weights[" + std::to_string(k) + "]", weights[k]);
    weight_sum += weights[k];
  }
  if (!(Value(weight_sum) > 0.0)) bearing_life_internal::Reject("the sum of weights", "> 0", Value(weight_sum));
  const double p = LifeExponent(kind);
  const double s = bearing_life_internal::LargestValue(loads_N);
  if (s == 0.0) return T(0.0);
  T sum(0.0);
  for (size_t k = 0; k < loads_N.size(); ++k) sum += weights[k] * pow(loads_N[k] / s, p);
  return T(s) * pow(sum / weight_sum, 1.0 / p);
}

/// The duty cycle's time-mean speed n̄ = Σ t_i n_i [rpm]: revolutions per minute over the spectrum.
/// @throws std::invalid_argument as ValidateDutyCycle.
template <typename T>
T DutyCycleMeanSpeed(const std::vector<DutyCycleLine<T>>& lines) {
  ValidateDutyCycle(lines);
  T n(0.0);
  for (const auto& line : lines) n += line.time_share * line.speed_rpm;
  return n;
}

/// The equivalent load over a duty cycle: the revolution-weighted p-mean over every angle of every
/// line, line i weighted by its share of the revolutions w_i = t_i n_i / n̄:
///   P = ( Σ_i w_i · (1/N_i) Σ_k F_ik^p )^(1/p).
/// With n̄ from DutyCycleMeanSpeed, L10h = 10⁶ (C/P)^p / (60 n̄) is the life of the duty cycle.
/// The quadrature error per line is EquivalentLoad's. P = 0 (every sample 0) has zero derivative.
/// @throws std::invalid_argument as ValidateDutyCycle.
template <typename T>
T DutyCycleEquivalentLoad(const std::vector<DutyCycleLine<T>>& lines, BearingKind kind) {
  using std::pow;
  const T n_mean = DutyCycleMeanSpeed(lines);
  const double p = LifeExponent(kind);
  double s = 0.0;
  for (const auto& line : lines) s = std::max(s, bearing_life_internal::LargestValue(line.loads_N));
  if (s == 0.0) return T(0.0);
  T weighted(0.0);
  for (const auto& line : lines)
    weighted += line.time_share * line.speed_rpm * bearing_life_internal::ScaledMeanOfPower(line.loads_N, s, p);
  return T(s) * pow(weighted / n_mean, 1.0 / p);
}

namespace bearing_life_internal {

/// Palmgren–Miner damage rate per hour over the duty cycle, divided by (s/C)^p:
///   D_h = Σ_i t_i / L10h,i = Σ_i t_i · 60 n_i (P_i/C)^p / 10⁶ = (s/C)^p · R,
///   R = (60/10⁶) Σ_i t_i n_i (1/N_i) Σ_k (F_ik/s)^p,
/// with s the largest load sample (a constant scale). Returns R; s through `scale`.
template <typename T>
T ScaledMinerDamageRate(const std::vector<DutyCycleLine<T>>& lines, BearingKind kind, double* scale) {
  const double p = LifeExponent(kind);
  double s = 0.0;
  for (const auto& line : lines) s = std::max(s, LargestValue(line.loads_N));
  *scale = s;
  T r(0.0);
  if (s == 0.0) return r;
  for (const auto& line : lines) r += line.time_share * line.speed_rpm * ScaledMeanOfPower(line.loads_N, s, p);
  return T(60.0 / 1e6) * r;
}

}  // namespace bearing_life_internal

/// The basic rating life of a duty cycle in hours by Palmgren–Miner: 1/L10h = Σ_i t_i / L10h,i,
/// L10h,i = 10⁶ (C/P_i)^p / (60 n_i), P_i the line's EquivalentLoad. Summing the damage rates,
///   Σ_i t_i 60 n_i P_i^p / (10⁶ C^p) = 60 n̄ / (10⁶ C^p) · Σ_i (t_i n_i / n̄) P_i^p
///                                    = 60 n̄ P^p / (10⁶ C^p),
/// with P = DutyCycleEquivalentLoad and n̄ = DutyCycleMeanSpeed: the same life as
/// RatingLifeHours(BasicRatingLifeMrev(C, P), n̄). Zero damage (every load 0) gives +∞.
/// @param dynamic_rating_N C [N], > 0.
/// @throws std::invalid_argument for C <= 0 and as ValidateDutyCycle.
template <typename T>
T DutyCycleLifeHours(const T& dynamic_rating_N, const std::vector<DutyCycleLine<T>>& lines, BearingKind kind) {
  using std::pow;
  bearing_life_internal::CheckPositive("C_N", dynamic_rating_N);
  ValidateDutyCycle(lines);
  double s = 0.0;
  const T r = bearing_life_internal::ScaledMinerDamageRate(lines, kind, &s);
  if (Value(r) == 0.0) return T(kInf);
  return pow(dynamic_rating_N / s, LifeExponent(kind)) / r;
}

/// A reducer bearing's life over its duty cycle (docs/life.md, "LCR" and "Cycloid").
struct BearingLifeOverCycle {
  double revolutions_per_input_revolution = 0.0;  ///< R, the bearing's revolutions per input revolution
  std::vector<double> line_equivalent_load_N;     ///< P_i, revolution-weighted over line i's load period
  double equivalent_load_N = 0.0;                 ///< P = (Σ t_i n_i P_i^p / Σ t_i n_i)^(1/p)
  double max_load_N = 0.0;                        ///< the largest load of any line (for s0)
  double mean_speed_rpm = 0.0;                    ///< the bearing's: R Σ t_i n_i
  double L10_Mrev = 0.0, L10h = 0.0;              ///< ISO 281 over the duty cycle; +∞ without load
};

/// Palmgren–Miner over the lines at the bearing's speeds n_i R from out's P_i and R: the bearing's
/// lines (t_i, n_i R, {P_i}), its mean speed (DutyCycleMeanSpeed), P (DutyCycleEquivalentLoad),
/// L10 = (C/P)^p and L10h (DutyCycleLifeHours). `time_share` and `input_speed_rpm` are the lines'
/// t_i and n_i, in the order of out.line_equivalent_load_N.
inline void CombineDutyCycleLines(double dynamic_rating_N, BearingKind kind, const std::vector<double>& time_share,
                                  const std::vector<double>& input_speed_rpm, BearingLifeOverCycle& out) {
  std::vector<DutyCycleLine<double>> d;
  for (size_t i = 0; i < time_share.size(); ++i)
    d.push_back({time_share[i], input_speed_rpm[i] * out.revolutions_per_input_revolution, {out.line_equivalent_load_N[i]}});
  out.mean_speed_rpm = DutyCycleMeanSpeed(d);
  out.equivalent_load_N = DutyCycleEquivalentLoad(d, kind);
  out.L10_Mrev = BasicRatingLifeMrev(dynamic_rating_N, out.equivalent_load_N, kind);
  out.L10h = DutyCycleLifeHours(dynamic_rating_N, d, kind);
}

/// A life margin for sizing: m = ln(L10h / L10h_required), >= 0 when the duty cycle's life
/// (DutyCycleLifeHours) reaches the required hours. In logarithms it is smooth wherever some load
/// is positive, of order one over decades of life, and linear in ln C and in ln of each line's
/// equivalent load: ∂m/∂ln C = p, ∂m/∂ln P_i = −p · (line i's share of the damage). Computed as
///   m = p ln(C/s) − ln R − ln L10h_required   (s, R of the Miner sum; no overflow).
/// Zero damage (every load 0) gives +∞ with zero derivative.
/// @param dynamic_rating_N C [N], > 0.  @param required_life_h L10h_required [h], > 0.
/// @throws std::invalid_argument for C <= 0, a required life <= 0, and as ValidateDutyCycle.
template <typename T>
T LifeMargin(const T& dynamic_rating_N, const std::vector<DutyCycleLine<T>>& lines, BearingKind kind,
             double required_life_h) {
  using std::log;
  bearing_life_internal::CheckPositive("C_N", dynamic_rating_N);
  bearing_life_internal::CheckPositive("required_life_h", required_life_h);
  ValidateDutyCycle(lines);
  double s = 0.0;
  const T r = bearing_life_internal::ScaledMinerDamageRate(lines, kind, &s);
  if (Value(r) == 0.0) return T(kInf);
  return LifeExponent(kind) * log(dynamic_rating_N / s) - log(r) - T(std::log(required_life_h));
}

/// The basic dynamic radial load rating of a roller scaled from a reference roller of the same
/// design (internal geometry, material, make) by ISO 281:2007 §6.1.1 (radial roller bearings),
/// C_r = b_m f_c (i L_we cos α)^(7/9) Z^(3/4) D_we^(29/27): with b_m, f_c, i, α and Z held,
///   C = C_ref (D/D_ref)^(29/27) (L/L_ref)^(7/9).
/// D and L stand for the rolling element's diameter and length; for a cam-follower roller they are
/// the roller's outer diameter and length (its needles scale with it). Smooth in D and L.
/// @param reference_rating_N C_ref [N], > 0.  @param reference_diameter_mm D_ref, > 0.
/// @param reference_length_mm L_ref, > 0.  @param diameter_mm D, > 0.  @param length_mm L, > 0.
template <typename T>
T ScaledDynamicRating(double reference_rating_N, double reference_diameter_mm, double reference_length_mm,
                      const T& diameter_mm, const T& length_mm) {
  using std::pow;
  return T(reference_rating_N) * pow(diameter_mm / reference_diameter_mm, 29.0 / 27.0) *
         pow(length_mm / reference_length_mm, 7.0 / 9.0);
}

/// The basic static radial load rating scaled likewise by ISO 76:2006 (radial roller bearings),
/// C_0r = 44 (1 − D_we cos α / D_pw) i Z L_we D_we cos α, with the factor (1 − D_we cos α / D_pw)
/// held (D_pw grows with D_we):  C0 = C0_ref (D/D_ref)(L/L_ref).
template <typename T>
T ScaledStaticRating(double reference_rating_N, double reference_diameter_mm, double reference_length_mm,
                     const T& diameter_mm, const T& length_mm) {
  return T(reference_rating_N) * (diameter_mm / reference_diameter_mm) * (length_mm / reference_length_mm);
}

/// The static safety factor s0 = C0 / P0max (C0, P0 per ISO 76:2006), P0max the largest static
/// equivalent load of the samples (for a purely radial load on a radial bearing, the largest
/// radial force). The derivative is that of the largest sample (HardMax, a subgradient at ties);
/// a sizing constraint on s0 can use SoftMax (model/common/scalar.h) of the samples instead.
/// Every sample 0 gives +∞.
/// @param static_rating_N C0 [N], > 0.  @param loads_N static equivalent loads [N], finite, >= 0.
/// @throws std::invalid_argument for C0 <= 0, no samples, or a negative or non-finite sample.
template <typename T>
T StaticSafetyFactor(const T& static_rating_N, const std::vector<T>& loads_N) {
  bearing_life_internal::CheckPositive("C0_N", static_rating_N);
  bearing_life_internal::CheckLoads("loads_N", loads_N);
  const T p0 = HardMax(loads_N);
  if (Value(p0) == 0.0) return T(kInf);
  return static_rating_N / p0;
}

/// s0 over a duty cycle: C0 over the largest load of any line (stationary lines included).
/// @throws std::invalid_argument for C0 <= 0 and as ValidateDutyCycle.
template <typename T>
T StaticSafetyFactor(const T& static_rating_N, const std::vector<DutyCycleLine<T>>& lines) {
  ValidateDutyCycle(lines);
  std::vector<T> all;
  for (const auto& line : lines) all.insert(all.end(), line.loads_N.begin(), line.loads_N.end());
  return StaticSafetyFactor(static_rating_N, all);
}

}  // namespace camopt
