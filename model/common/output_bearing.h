// The output bearing of a precision reducer (the cross-roller or four-point-contact bearing that
// carries the output flange) rated as the reducer catalogues rate it: averaged duty loads, the
// dynamic equivalent radial load with a tilting moment, the L10 life in hours, the life under
// oscillating motion, the static equivalent load and safety factor, and the tilt under a moment.
// Over the scalar T (double or ceres::Jet) where a sizing may want derivatives.
//
// Sources (definitions cited, not copied; equation numbers as printed in each document):
//   [HDL-CSF] Harmonic Drive LLC, "CSF & CSG Series, Cup Type Component Sets & Housed Units",
//             catalogue, section "Output Bearing Ratings / Output Bearing Life": average radial and
//             axial loads eq. (11), (12), average output speed eq. (13), X and Y "list 2", life
//             eq. (15), P_C eq. (16), oscillating life eq. (18) with θ = oscillating angle / 2.
//   [HDL-FHA] Harmonic Drive LLC, "FHA-C series" manual, ch. 2 "Guidelines for sizing": formulas
//             (1)–(10) (M_max, F_rav, F_aav, N_av, X/Y, P_C, L_B-10, L_OC, P_0, f_s).
//   [HDL-CSF3] Harmonic Drive LLC, "CSF-3 series" manual, §2-7 formula (8): oscillating life with
//             n_1 = reciprocating oscillations per minute and θ = oscillating angle / 2.
//   [HDAG-SHG] Harmonic Drive AG, "SHG series" engineering data (1021387, 12/2018), §4.7:
//             eq. 42.1 (L10 with exponent B, table 42.4: B = 10/3 cross-roller, 3 four-point),
//             eq. 42.2 (n_av = Σ|n_i| t_i / (Σ t_i + t_p), pause time t_p included), eq. 44.1
//             (L_OC with 180/φ, φ the oscillating angle, "one oscillation means 2φ").
//   [THK-CRR] THK, "Cross-Roller Ring Series", catalogue No. 382-3E, "Rated Life" and "Static Safety
//             Factor": P_C = X (F_r + 2M/d_p) + Y F_a (table 2; X = Y = 0.67 also when F_r = M = 0),
//             P_0 = X_0 (F_r + 2M/d_p) + Y_0 F_a with X_0 = 1, Y_0 = 0.44, f_S = C_0 / P_0.
//   [IKO-CRB] IKO crossed roller bearings, catalogue eq. (1) (P_r, table 5) and eq. (2) (P_0r):
//             the same X/Y and 0.44 as [THK-CRR].
// The loads and the life law are ISO 281's (model/common/bearing_life.h): the duty averages are the
// revolution-weighted B-means of each load component, and the life is BasicRatingLifeMrev /
// RatingLifeHours with C/(f_w P_C).
//
// Units: forces N, tilting moments N·m, pitch diameter d_p mm (so 2M/d_p = 2000 M/d_p N), speeds
// rpm, times in any unit (only their ratios enter), lives in hours, angles in degrees or arcmin as
// named. Loads and speeds are signed as a duty cycle gives them; the catalogues average |F| and |n|,
// so the sign (direction) does not enter.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/common/argument_check.h"
#include "model/common/bearing_life.h"
#include "model/common/scalar.h"

namespace camopt {

/// The radial-load limit of the X/Y choice: F_a/(F_r + 2M/d_p) <= 1.5 gives X = 1, Y = 0.45, above
/// it X = Y = 0.67 ([HDL-CSF] list 2, [THK-CRR] table 2, [IKO-CRB] table 5).
inline constexpr double kOutputBearingAxialRatioLimit = 1.5;
/// The static axial factor Y_0 of a cross-roller bearing ([THK-CRR], [IKO-CRB] eq. (2), [HDL-FHA] (9)).
inline constexpr double kOutputBearingStaticAxialFactor = 0.44;

/// A reducer's output bearing as its catalogue gives it.
struct OutputBearing {
  double dynamic_rating_N = 0.0;    ///< C [N], basic dynamic load rating, > 0
  double static_rating_N = 0.0;     ///< C_0 [N], basic static load rating, > 0
  double pitch_diameter_mm = 0.0;   ///< d_p [mm], pitch circle diameter of the rolling elements, > 0
  /// Cross-roller (kRoller, B = 10/3) or four-point / angular-contact ball (kBall, B = 3)
  /// ([HDAG-SHG] table 42.4).
  BearingKind kind = BearingKind::kRoller;
  /// K_B [N·m/arcmin], the catalogue's moment stiffness; 0 when the catalogue gives none.
  double moment_stiffness_Nm_per_arcmin = 0.0;
};

/// One line of the output's duty cycle ([HDL-CSF] figure 7: a time t_i at output speed n_i under
/// the loads F_r,i, F_a,i, M_i). A line at speed 0 is time at standstill: it turns no revolutions,
/// adds nothing to the averaged loads, and lowers N_av (its time counts, as [HDAG-SHG] eq. 42.2's
/// pause time t_p). Its loads still count for the static check.
/// @tparam T double or ceres::Jet (speeds and loads may carry derivatives; times are data).
template <typename T>
struct OutputBearingLine {
  double time_share = 1.0;    ///< t_i, finite, >= 0 (seconds or a share: only ratios enter)
  T speed_rpm = T(0.0);       ///< n_i [rpm] output speed, finite (|n_i| enters)
  T radial_N = T(0.0);        ///< F_r,i [N], finite (|F_r,i| enters)
  T axial_N = T(0.0);         ///< F_a,i [N], finite (|F_a,i| enters)
  T moment_Nm = T(0.0);       ///< M_i [N·m] tilting moment, finite (|M_i| enters)
};

/// The averages of a duty cycle that the life formula takes.
template <typename T>
struct OutputBearingAverages {
  T radial_N;    ///< F_rav [N]
  T axial_N;     ///< F_aav [N]
  T moment_Nm;   ///< M_av [N·m]
  T speed_rpm;   ///< N_av [rpm]
};

namespace output_bearing_internal {

// model/common/argument_check.h, its messages starting "output bearing: ".
inline constexpr const char* kWhat = "output bearing";
[[noreturn]] inline void Reject(const std::string& f, const std::string& r, double v) { argument_check::Reject(kWhat, f, r, v); }
inline void CheckPositive(const std::string& field, double v) { argument_check::Positive(kWhat, field, v); }
template <typename T>
void CheckNonNegative(const std::string& field, const T& x) { argument_check::NonNegative(kWhat, field, x); }
template <typename T>
void CheckFinite(const std::string& field, const T& x) { argument_check::Finite(kWhat, field, x); }

inline void CheckBearing(const OutputBearing& b) {
  CheckPositive("C_N (dynamic_rating_N)", b.dynamic_rating_N);
  CheckPositive("C0_N (static_rating_N)", b.static_rating_N);
  CheckPositive("d_p_mm (pitch_diameter_mm)", b.pitch_diameter_mm);
  const double k = b.moment_stiffness_Nm_per_arcmin;
  if (!(std::isfinite(k) && k >= 0.0)) Reject("K_B_Nm_per_arcmin (moment_stiffness_Nm_per_arcmin)", "finite and >= 0 (0: not given)", k);
}

inline void CheckLoadFactor(double load_factor) {
  if (!(std::isfinite(load_factor) && load_factor >= 1.0))
    Reject("f_w (load_factor)", "finite and >= 1 (the catalogues' table: 1 to 3)", load_factor);
}

/// |x| through IfThenElse (one visible branch; the kink at 0 is the catalogues' |F|).
template <typename T>
T Magnitude(const T& x) {
  return IfThenElse(Compare::kLess, x, 0.0, T(-x), x);
}

/// Checks the lines: at least one; times finite >= 0 with a positive sum; speeds and loads finite.
template <typename T>
void CheckLines(const std::vector<OutputBearingLine<T>>& lines) {
  if (lines.empty()) Reject("duty_cycle.size()", ">= 1", 0.0);
  double time_sum = 0.0;
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string line = "duty_cycle[" + std::to_string(i) + "]";
    CheckNonNegative(line + ".time_share", lines[i].time_share);
    time_sum += lines[i].time_share;
    CheckFinite(line + ".speed_rpm", lines[i].speed_rpm);
    CheckFinite(line + ".radial_N", lines[i].radial_N);
    CheckFinite(line + ".axial_N", lines[i].axial_N);
    CheckFinite(line + ".moment_Nm", lines[i].moment_Nm);
  }
  if (!(time_sum > 0.0)) Reject("the sum of duty_cycle[*].time_share", "> 0", time_sum);
}

/// The weighted B-mean ( Σ w_i |x_i|^B / W )^(1/B), scaled by the largest |x_i| of a weighted line
/// (a constant) so that |x|^B cannot overflow. 0 (zero derivative) when every weighted |x_i| is 0.
template <typename T>
T WeightedPowerMean(const std::vector<T>& magnitudes, const std::vector<T>& weights, const T& weight_sum, double b) {
  using std::pow;
  double s = 0.0;
  for (size_t i = 0; i < magnitudes.size(); ++i)
    if (Value(weights[i]) > 0.0) s = std::max(s, Value(magnitudes[i]));
  if (s == 0.0) return T(0.0);
  T sum(0.0);
  for (size_t i = 0; i < magnitudes.size(); ++i) sum += weights[i] * pow(magnitudes[i] / s, b);
  return T(s) * pow(sum / weight_sum, 1.0 / b);
}

}  // namespace output_bearing_internal

/// The catalogue's tilting moment of loads applied off the bearing ([HDL-FHA] formula (1),
/// [HDL-CSF] "maximum load moment"): M = F_r (L_r + R) + F_a L_a, with L_r, L_a the load's lever
/// arms and R the bearing's offset from the output face, in mm; the result in N·m.
/// @throws std::invalid_argument for a non-finite force or arm.
template <typename T>
T CatalogueTiltingMomentNm(const T& radial_N, const T& axial_N, double radial_arm_mm, double offset_mm,
                           double axial_arm_mm) {
  using output_bearing_internal::CheckFinite;
  CheckFinite("F_r_N (radial_N)", radial_N);
  CheckFinite("F_a_N (axial_N)", axial_N);
  CheckFinite("L_r_mm (radial_arm_mm)", radial_arm_mm);
  CheckFinite("R_mm (offset_mm)", offset_mm);
  CheckFinite("L_a_mm (axial_arm_mm)", axial_arm_mm);
  return (radial_N * (radial_arm_mm + offset_mm) + axial_N * axial_arm_mm) / 1000.0;
}

/// The duty-cycle averages of [HDL-CSF] eq. (11)–(13) / [HDL-FHA] formulas (2)–(4), with the
/// exponent B of [HDAG-SHG] table 42.4 (10/3 cross-roller, 3 four-point):
///   F_rav = [ Σ |n_i| t_i |F_r,i|^B / Σ |n_i| t_i ]^(1/B),  F_aav and M_av likewise,
///   N_av  = Σ |n_i| t_i / Σ t_i.
/// Each load is weighted by the revolutions turned under it (ISO 281's equivalent load of a varying
/// load, model/common/bearing_life.h), so a line at speed 0 adds nothing to the averages while its
/// time still counts in N_av. M_av is the B-mean of the lines' moments; the catalogues form the
/// moment from the averaged forces, M = F_rav (L_r + R) + F_aav L_a (P_C of [HDL-CSF] eq. (16)). The
/// two agree when one line carries the load or the moment arms are common and the loads
/// proportional; otherwise the catalogue's form is larger (the B-mean of a sum is at most the sum of
/// the B-means, Minkowski) — pass that moment on every line to reproduce the catalogue exactly.
/// @throws std::invalid_argument for no lines, a negative or non-finite time, times summing to 0, a
/// non-finite speed or load, or no revolutions at all (every line with time has speed 0: no rating
/// life is defined, judge the bearing by OutputBearingStaticSafetyFactor).
template <typename T>
OutputBearingAverages<T> OutputBearingAverageLoads(const std::vector<OutputBearingLine<T>>& lines, BearingKind kind) {
  using output_bearing_internal::Magnitude;
  output_bearing_internal::CheckLines(lines);
  const size_t n = lines.size();
  std::vector<T> weights(n), radial(n), axial(n), moment(n);
  T weight_sum(0.0);
  double time_sum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    weights[i] = lines[i].time_share * Magnitude(lines[i].speed_rpm);
    weight_sum += weights[i];
    time_sum += lines[i].time_share;
    radial[i] = Magnitude(lines[i].radial_N);
    axial[i] = Magnitude(lines[i].axial_N);
    moment[i] = Magnitude(lines[i].moment_Nm);
  }
  if (!(Value(weight_sum) > 0.0))
    output_bearing_internal::Reject("the sum of duty_cycle[*].time_share * |speed_rpm|",
                                    "> 0 (every line is at standstill: no revolutions, no rating life; "
                                    "use the static safety factor)",
                                    Value(weight_sum));
  const double b = LifeExponent(kind);
  using output_bearing_internal::WeightedPowerMean;
  return {WeightedPowerMean(radial, weights, weight_sum, b), WeightedPowerMean(axial, weights, weight_sum, b),
          WeightedPowerMean(moment, weights, weight_sum, b), weight_sum / time_sum};
}

/// The dynamic equivalent radial load of a cross-roller output bearing ([HDL-CSF] eq. (16),
/// [HDL-FHA] formula (6), [THK-CRR] "dynamic equivalent radial load", [IKO-CRB] eq. (1)):
///   P_C = X (F_r + 2M/d_p) + Y F_a,  X = 1, Y = 0.45 when F_a/(F_r + 2M/d_p) <= 1.5,
///                                    X = Y = 0.67 otherwise (also when F_r = M = 0 < F_a).
/// The two branches meet at the limit (both 1.675 (F_r + 2M/d_p)): P_C is continuous with a kink.
/// The comparison is made as F_a <= 1.5 (F_r + 2M/d_p), so F_r = M = 0 needs no division.
/// @param radial_N F_r (or F_rav) [N], >= 0.  @param axial_N F_a (or F_aav) [N], >= 0.
/// @param moment_Nm M (or M_av) [N·m], >= 0.  @param pitch_diameter_mm d_p [mm], > 0.
/// @throws std::invalid_argument for a negative or non-finite load or a non-positive d_p.
template <typename T>
T DynamicEquivalentRadialLoad(const T& radial_N, const T& axial_N, const T& moment_Nm, double pitch_diameter_mm) {
  using output_bearing_internal::CheckNonNegative;
  CheckNonNegative("F_r_N (radial_N)", radial_N);
  CheckNonNegative("F_a_N (axial_N)", axial_N);
  CheckNonNegative("M_Nm (moment_Nm)", moment_Nm);
  output_bearing_internal::CheckPositive("d_p_mm (pitch_diameter_mm)", pitch_diameter_mm);
  const T r = radial_N + 2000.0 * moment_Nm / pitch_diameter_mm;
  return IfThenElse(Compare::kLessEqual, axial_N, T(kOutputBearingAxialRatioLimit * r), T(r + 0.45 * axial_N),
                    T(0.67 * r + 0.67 * axial_N));
}

/// P_C of the duty cycle: DynamicEquivalentRadialLoad of OutputBearingAverageLoads.
/// @throws std::invalid_argument as OutputBearingAverageLoads and for a bad bearing.
template <typename T>
T OutputBearingEquivalentLoad(const OutputBearing& bearing, const std::vector<OutputBearingLine<T>>& lines) {
  output_bearing_internal::CheckBearing(bearing);
  const OutputBearingAverages<T> avg = OutputBearingAverageLoads(lines, bearing.kind);
  return DynamicEquivalentRadialLoad(avg.radial_N, avg.axial_N, avg.moment_Nm, bearing.pitch_diameter_mm);
}

/// The output bearing's rating life in hours ([HDL-CSF] eq. (15), [HDL-FHA] formula (7),
/// [HDAG-SHG] eq. 42.1):  L10 = 10⁶ / (60 N_av) · (C / (f_w P_C))^B  [h],
/// ISO 281's L10h (RatingLifeHours of BasicRatingLifeMrev(C, f_w P_C)) at the mean speed N_av.
/// P_C = 0 (no load) gives +∞. This form takes P_C and N_av as computed elsewhere (for instance
/// with the catalogue's moment from the averaged forces, CatalogueTiltingMomentNm).
/// @param equivalent_load_N P_C [N], >= 0.  @param mean_speed_rpm N_av [rpm], > 0.
/// @param load_factor f_w >= 1 (catalogue table: 1–1.2 smooth, 1.2–1.5 normal, 1.5–3 shocks).
/// @throws std::invalid_argument for a bad bearing, a negative or non-finite P_C, N_av not > 0, or
/// f_w < 1 or non-finite.
template <typename T>
T OutputBearingLifeHours(const OutputBearing& bearing, const T& equivalent_load_N, const T& mean_speed_rpm,
                         double load_factor) {
  output_bearing_internal::CheckBearing(bearing);
  output_bearing_internal::CheckLoadFactor(load_factor);
  output_bearing_internal::CheckNonNegative("P_C_N (equivalent_load_N)", equivalent_load_N);
  output_bearing_internal::CheckPositive("N_av_rpm (mean_speed_rpm)", Value(mean_speed_rpm));
  return RatingLifeHours(
      BasicRatingLifeMrev(T(bearing.dynamic_rating_N), T(load_factor * equivalent_load_N), bearing.kind),
      mean_speed_rpm);
}

/// The output bearing's rating life in hours of a duty cycle: OutputBearingLifeHours at P_C of the
/// averaged loads (OutputBearingAverageLoads, DynamicEquivalentRadialLoad) and at N_av.
/// @throws std::invalid_argument for a bad bearing, f_w < 1 or non-finite, and as
/// OutputBearingAverageLoads (a duty cycle with no revolutions has no rating life).
template <typename T>
T OutputBearingLifeHours(const OutputBearing& bearing, const std::vector<OutputBearingLine<T>>& lines,
                         double load_factor) {
  output_bearing_internal::CheckBearing(bearing);
  output_bearing_internal::CheckLoadFactor(load_factor);
  const OutputBearingAverages<T> avg = OutputBearingAverageLoads(lines, bearing.kind);
  const T p = DynamicEquivalentRadialLoad(avg.radial_N, avg.axial_N, avg.moment_Nm, bearing.pitch_diameter_mm);
  return OutputBearingLifeHours(bearing, p, avg.speed_rpm, load_factor);
}

/// The output bearing's life under oscillating motion ([HDL-CSF] eq. (18), [HDL-FHA] formula (8),
/// [HDL-CSF3] formula (8)):  L_OC = 10⁶ / (60 n_1) · (90/θ) · (C / (f_w P_C))^B  [h],
/// with n_1 the round-trip oscillations per minute and θ HALF the oscillating angle: Harmonic Drive
/// LLC defines θ as "oscillating angle / 2" (the swing from the centre to one end). One round trip
/// then turns 4θ degrees = θ/90 revolution, so L_OC is ISO 281's L10h at the equivalent speed
/// n_1 θ/90 rpm. Harmonic Drive AG's [HDAG-SHG] eq. 44.1 writes the same life as 180/φ with φ = 2θ
/// the whole oscillating angle ("one oscillation means 2φ"): pass θ = φ/2. Both catalogues warn
/// that below about 5° (whole angle) fretting may occur; that is not modelled.
/// P_C = 0 gives +∞.
/// @param equivalent_load_N P_C [N], >= 0 (OutputBearingEquivalentLoad of the oscillating duty).
/// @param oscillations_per_min n_1 [cpm], > 0.  @param half_angle_deg θ [deg], > 0.
/// @throws std::invalid_argument for a bad bearing or f_w, a negative P_C, or n_1, θ not > 0.
template <typename T>
T OscillatingOutputBearingLifeHours(const OutputBearing& bearing, const T& equivalent_load_N, double load_factor,
                                    double oscillations_per_min, double half_angle_deg) {
  output_bearing_internal::CheckBearing(bearing);
  output_bearing_internal::CheckLoadFactor(load_factor);
  output_bearing_internal::CheckNonNegative("P_C_N (equivalent_load_N)", equivalent_load_N);
  output_bearing_internal::CheckPositive("n_1 (oscillations_per_min)", oscillations_per_min);
  output_bearing_internal::CheckPositive("theta_deg (half_angle_deg, half the oscillating angle)", half_angle_deg);
  return RatingLifeHours(
      BasicRatingLifeMrev(T(bearing.dynamic_rating_N), T(load_factor * equivalent_load_N), bearing.kind),
      T(oscillations_per_min * half_angle_deg / 90.0));
}

/// The static equivalent radial load ([HDL-FHA] formula (9), [THK-CRR] "static equivalent radial
/// load", [IKO-CRB] eq. (2)):  P_0 = F_rmax + 2 M_max / d_p + 0.44 F_amax.
/// @param radial_N F_rmax [N], >= 0.  @param axial_N F_amax [N], >= 0.  @param moment_Nm M_max
/// [N·m], >= 0.  @param pitch_diameter_mm d_p [mm], > 0.
/// @throws std::invalid_argument for a negative or non-finite load or a non-positive d_p.
template <typename T>
T StaticEquivalentRadialLoad(const T& radial_N, const T& axial_N, const T& moment_Nm, double pitch_diameter_mm) {
  using output_bearing_internal::CheckNonNegative;
  CheckNonNegative("F_rmax_N (radial_N)", radial_N);
  CheckNonNegative("F_amax_N (axial_N)", axial_N);
  CheckNonNegative("M_max_Nm (moment_Nm)", moment_Nm);
  output_bearing_internal::CheckPositive("d_p_mm (pitch_diameter_mm)", pitch_diameter_mm);
  return radial_N + 2000.0 * moment_Nm / pitch_diameter_mm + kOutputBearingStaticAxialFactor * axial_N;
}

/// The largest |F_r|, |F_a| and |M| of every line (standstill lines included), each taken on its
/// own as the catalogues take F_rmax, F_amax, M_max; speed_rpm of the result is unused (0).
/// @throws std::invalid_argument as the lines' check of OutputBearingAverageLoads.
template <typename T>
OutputBearingLine<T> OutputBearingMaximumLoads(const std::vector<OutputBearingLine<T>>& lines) {
  using output_bearing_internal::Magnitude;
  output_bearing_internal::CheckLines(lines);
  std::vector<T> fr, fa, m;
  for (const auto& line : lines) {
    fr.push_back(Magnitude(line.radial_N));
    fa.push_back(Magnitude(line.axial_N));
    m.push_back(Magnitude(line.moment_Nm));
  }
  OutputBearingLine<T> max;
  max.time_share = 0.0;
  max.radial_N = HardMax(fr);
  max.axial_N = HardMax(fa);
  max.moment_Nm = HardMax(m);
  return max;
}

/// The static safety factor f_s = C_0 / P_0 ([HDL-FHA] formula (10), [THK-CRR] "static safety
/// factor"), P_0 of the duty cycle's maxima (OutputBearingMaximumLoads). Guide values: [HDL-FHA]
/// f_s > 1.5 normal, > 2 shocks, > 3 precise positioning; [THK-CRR] recommends 7 or more for life.
/// Every load 0 gives +∞.
/// @throws std::invalid_argument for a bad bearing and as OutputBearingMaximumLoads.
template <typename T>
T OutputBearingStaticSafetyFactor(const OutputBearing& bearing, const std::vector<OutputBearingLine<T>>& lines) {
  output_bearing_internal::CheckBearing(bearing);
  const OutputBearingLine<T> max = OutputBearingMaximumLoads(lines);
  const T p0 = StaticEquivalentRadialLoad(max.radial_N, max.axial_N, max.moment_Nm, bearing.pitch_diameter_mm);
  if (Value(p0) == 0.0) return T(kInf);
  return T(bearing.static_rating_N) / p0;
}

/// The output flange's tilt under a tilting moment from the catalogue's moment stiffness K_B
/// (Harmonic Drive and Nabtesco rate it in N·m/arcmin, "moment rigidity"): γ = M / K_B [arcmin],
/// linear (the catalogues' K_B is a secant over the rated moment range).
/// @param moment_Nm M [N·m], finite (the sign is the tilt's direction).
/// @throws std::invalid_argument for a bad bearing, no K_B given (0), or a non-finite moment.
template <typename T>
T OutputBearingTiltArcmin(const OutputBearing& bearing, const T& moment_Nm) {
  output_bearing_internal::CheckBearing(bearing);
  if (!(bearing.moment_stiffness_Nm_per_arcmin > 0.0))
    output_bearing_internal::Reject("K_B_Nm_per_arcmin (moment_stiffness_Nm_per_arcmin)",
                                    "> 0 to compute a tilt (the catalogue gives none)",
                                    bearing.moment_stiffness_Nm_per_arcmin);
  output_bearing_internal::CheckFinite("M_Nm (moment_Nm)", moment_Nm);
  return moment_Nm / bearing.moment_stiffness_Nm_per_arcmin;
}

}  // namespace camopt
