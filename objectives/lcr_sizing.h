// The LCR sizing problem of one lobe/roller combination: minimise the outer diameter (or, with the
// lubricated losses, the power lost at the sizing's torque and speed: LcrSizeObjective) over the
// eccentricity, both turret radii and the roller diameter, subject to contact stress, roller load,
// undercut, roller gap, pitch-point and (optionally) outer-diameter limits. Built on the LCR pipeline in model/lcr/ (forces.h,
// profile.h, reducer.h); nothing here re-derives its physics.
//
// Variables (mm): e, r_dA, r_dB, d_r, R (R the outer radius, an epigraph variable: the objective
// 2R is smooth, and r_dX + r_rX <= R for both cams replaces the kink of 2 max(r_dX + r_rX)).
// With the power-loss objective R is no longer pushed down: its upper bound is the outer-diameter
// limit's half (LcrLimits::max_outer_diameter_mm) or, without one, the largest outer radius the
// variable box holds (turret radius + roller radius at their upper bounds), so that R stays a
// bounded slack of the envelope rows and r_dX + r_rX <= R <= max/2 is the diameter limit.
// With a catalogue roller the diameter is fixed and the variables are e, r_dA, r_dB, R; with a
// roller per cam (same_roller = false) they are e, r_dA, r_dB, d_rA, d_rB, R.
//
// Cycle maxima enter in one of three forms (LcrConstraintForm):
// - kSamples: one constraint row per (angle sample, roller) of one load period;
// - kAggregate: one row per cam, a log-sum-exp soft maximum over the same samples
//   (lcr::ScaledSoftMax, the one cycle aggregate of model/lcr/cycle.h): for forces
//   F_ref·SoftMax(F/F_ref, k) with F_ref the load limit (over-estimates the sampled maximum by at
//   most F_ref ln(N)/k: conservative); for the stress margin below −SoftMax(−s, k) (under-estimates
//   the smallest margin by at most ln(N)/k). Default k = 200;
// - kActiveSet: one force row per sample of active.force and one stress-margin row per sample of
//   active.stress (each an input angle and a roller). A sample with a window w > 0 is a tracked
//   peak: its row is the roller's largest force (smallest margin) over θ ∈ [θ0 − w, θ0 + w], the
//   maximiser θ* found on values (a 9-point scan refined by golden section) and the row then
//   evaluated at θ* for the scalar T. Its derivative is exact by the envelope theorem (∂q/∂θ = 0
//   at an interior maximum), as for lcr::MaxPitchCurvature. The minimum-size search seeds these
//   peaks from the dense check (objectives/lcr_dense_check.h, driven by sizing/lcr_min_size.h).
// One load period suffices: the input side repeats every 2π/n_A of input angle (the fixed turret
// maps onto itself), the output side every 2π m_A/(n_A m_B) (the output turret turns relative to
// the eccentric by 2π/n_B in that time); and the input cam's roller forces depend only on the input
// turret's geometry (C_A = T_o (m_B/n_B)/((m_A/n_A) Σ a_A²)), the output cam's only on the output's.
//
// The stress limit is written as a Hertz load-capacity margin, which stays finite where the cam is
// undercut (R' <= 0, where p = sqrt(F E*/(π L R')) is not defined):
//     s = (p_lim² R' − F E*/(π L)) / (p_lim² r_r) >= 0,     R' = r_r (1 − r_r κ),
// so s = (R'/r_r)(1 − p²/p_lim²): the same sign as p_lim − p wherever R' > 0, and negative
// (violated) where the cam is undercut.
#pragma once

#include <array>
#include <compare>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/common/bearing_life.h"
#include "model/common/scalar.h"
#include "model/contact/hertz.h"
#include "model/lcr/life.h"
#include "model/lcr/lubrication.h"
#include "model/lcr/reducer.h"
#include "objectives/problem.h"

namespace camopt::objectives {

enum class LcrConstraintForm { kSamples, kAggregate, kActiveSet };

/// One (input angle, roller) sample of a cam for LcrConstraintForm::kActiveSet.
struct LcrSample {
  double theta_rad = 0.0;   ///< input angle θ0
  int roller = 0;           ///< roller index k of that cam's turret
  double window_rad = 0.0;  ///< 0: the row is at θ0; > 0: the peak over θ0 ± window
  auto operator<=>(const LcrSample&) const = default;
};

/// The samples of kActiveSet, per cam ([0] input, [1] output) and quantity.
struct LcrActiveSet {
  std::array<std::vector<LcrSample>, 2> force, stress;
};

struct LcrRobustRule;  // objectives/lcr_robust.h

struct LcrLimits {
  double contact_stress_MPa = kInf;
  double roller_load_N = kInf;
  double undercut_margin_mm = 0.0;
  double roller_gap_mm = 0.0;
  /// Mean efficiency over the cycle (fraction); 0: no constraint. Without LcrSizingSpec::lubrication
  /// the mean of the paper's eq. 33 with friction_coefficient; with it the lubricated efficiency
  /// P_out/(P_out + P_loss) of model/lcr/lubrication.h.
  double min_efficiency = 0.0;
  /// Shortest ISO 281 basic rating life L10h of any rated bearing [h] over LcrLifeSpec's duty cycle;
  /// 0: no constraint (docs/life.md, "Life as a sizing limit").
  double life_h = 0.0;
  /// The smallest static safety s0 = C0/P0max (ISO 76) of every bearing of LcrLifeSpec with a static
  /// rating at static_torque_Nmm (a momentary torque); 0: no constraint. The rigid law's loads are
  /// proportional to the torque: P0max there is the output torque's times static_torque_Nmm / T_o.
  double min_static_safety = 0.0;
  double static_torque_Nmm = 0.0;
  /// The oil temperature of the housing's balance [°C] (with lubrication and its cooling); kInf: none.
  double max_oil_temperature_C = kInf;
  /// The largest outer diameter 2 max(r_dX + r_rX) [mm]: the upper bound 2R of the outer-radius
  /// variable (its envelope rows hold the design inside it); kInf: none. What a designer who
  /// minimises the loss (LcrSizeObjective::kPowerLoss) bounds the reducer's size with.
  double max_outer_diameter_mm = kInf;
};

/// What the sizing minimises: the outer diameter 2R, or the lubricated power lost P_loss [W] at the
/// output torque and the input speed of LcrSizingSpec::lubrication (model/lcr/lubrication.h
/// LubricatedRigidCycle, at the given oil temperature or the housing's balance): at a fixed output
/// power P_out, minimising P_loss maximises η = P_out/(P_out + P_loss).
enum class LcrSizeObjective { kOuterDiameter, kPowerLoss };

/// The rollers' ratings. Fixed (a catalogue roller: reference_diameter_mm = 0) or scaled with the
/// roller's diameter and length from a reference roller of the same design by ISO 281 / ISO 76
/// (ScaledDynamicRating, ScaledStaticRating of model/common/bearing_life.h).
struct LcrRollerRating {
  double dynamic_N = 0.0;             ///< C [N] of the reference (or catalogue) roller, > 0
  double static_N = 0.0;              ///< C0 [N]; 0: not given (no s0)
  double reference_diameter_mm = 0.0; ///< D_ref; 0: the rating is the roller's own (not scaled)
  double reference_length_mm = 0.0;   ///< L_ref
  bool operator==(const LcrRollerRating&) const = default;
};

/// The eccentric bearing (fixed ratings, its size is not a sizing variable).
struct LcrEccentricRating {
  bool ball = false;  ///< ball (p = 3) or roller (p = 10/3) bearing
  double dynamic_N = 0.0, static_N = 0.0;
  bool operator==(const LcrEccentricRating&) const = default;
};

/// What the bearing lives are computed from (docs/life.md): the duty cycle and the ratings.
struct LcrLifeSpec {
  std::vector<lcr::LcrDutyLine> lines;  ///< time shares summing to 1
  LcrRollerRating roller;
  std::optional<LcrEccentricRating> eccentric;
  bool operator==(const LcrLifeSpec&) const = default;
};

/// The lubricated losses of a sizing (model/lcr/lubrication.h LubricatedRigidCycle): at the output
/// torque and the input speed, the oil temperature given or from the housing's balance.
struct LcrSizingLubrication {
  lcr::LubricationSpec spec;
  double input_speed_rpm = 0;
  std::optional<double> temperature_C;  ///< given; absent: the housing's balance
  HousingCooling cooling;
  double balance_limit_C = 120;         ///< the balance is sought below it (the oil's limit)
  bool operator==(const LcrSizingLubrication&) const = default;
};

/// One continuous sizing problem.
struct LcrSizingSpec {
  int lobes_a = 0, rollers_a = 0, lobes_b = 0, rollers_b = 0;
  std::array<double, 2> eccentricity_mm{0.5, 5.0};
  std::array<double, 2> turret_radius_mm{15.0, 80.0};
  std::array<double, 2> roller_diameter_mm{3.0, 20.0};
  std::optional<double> fixed_roller_diameter_mm;  ///< catalogue roller: d_r is not a variable
  bool same_roller = true;  ///< one d_r for both cams; false: d_rA and d_rB (ignored when fixed)
  double roller_length_mm = 10.0;
  double cam_thickness_mm = 8.0;
  lcr::Material material;
  double output_torque_Nmm = 0.0;
  double friction_coefficient = 0.0;  ///< μ of the efficiency (paper eq. 32)
  LcrLimits limits;
  LcrConstraintForm form = LcrConstraintForm::kAggregate;
  int samples_per_period = 24;  ///< angle samples over one load period of each cam
  double sharpness = 200.0;     ///< log-sum-exp sharpness for kAggregate (dimensionless)
  /// kActiveSet: the samples that get rows; every force list must not be empty, nor every stress
  /// list when the stress limit is finite.
  LcrActiveSet active;
  int efficiency_samples = 48;  ///< input angles over a full revolution for the mean efficiency
  /// Smallest pitch-point clearance r_d − e n/(n − m), as a fraction of r_d (the pitch curve must
  /// not loop; see lcr::CheckDesign).
  double pitch_clearance_fraction = 0.02;
  /// Tolerances and the rule by which the force, stress and undercut rows hold across them
  /// (objectives/lcr_robust.h); null: the nominal design. Shared, immutable, by every copy of a spec.
  std::shared_ptr<const LcrRobustRule> robust;
  /// The duty cycle and ratings of the bearing lives; with limits.life_h > 0 the life rows.
  std::optional<LcrLifeSpec> life;
  /// The lubricated losses: limits.min_efficiency bounds their efficiency (not eq. 33's), and
  /// limits.max_oil_temperature_C the balance's oil temperature.
  std::optional<LcrSizingLubrication> lubrication;
  /// kPowerLoss needs lubrication.
  LcrSizeObjective objective = LcrSizeObjective::kOuterDiameter;
};

/// The output power T_o ω_out [W] of spec's combination at its lubrication's input speed (0 without
/// lubrication): the reference of the power-loss objective's scale.
double LcrOutputPowerW(const LcrSizingSpec& spec);

/// The roller's dynamic (static = false) or static rating [N] at roller diameter d and length L
/// [mm]: LcrRollerRating's fixed value, or scaled from its reference roller.
template <typename T>
T LcrRollerRatingAt(const LcrRollerRating& rating, const T& diameter_mm, const T& length_mm, bool static_rating) {
  const double c = static_rating ? rating.static_N : rating.dynamic_N;
  if (!(rating.reference_diameter_mm > 0)) return T(c);
  return static_rating
             ? ScaledStaticRating(c, rating.reference_diameter_mm, rating.reference_length_mm, diameter_mm, length_mm)
             : ScaledDynamicRating(c, rating.reference_diameter_mm, rating.reference_length_mm, diameter_mm, length_mm);
}

/// The Hertz capacity margin s = (R' − F/c)/r_r of the header for a roller of radius r_r [mm] and
/// contact length L [mm] under force F [N] at pitch-curve curvature κ [1/mm].
template <typename T>
CAMOPT_FLATTEN T LcrStressMargin(const LcrSizingSpec& s, const T& length, const T& roller_radius, const T& force,
                  const T& curvature) {
  const T capacity_per_radius = contact::LineContactLoadPerRadius(
      T(s.limits.contact_stress_MPa), length, T(s.material.composite_modulus_MPa()));
  const T r_eff = roller_radius * (T(1.0) - roller_radius * curvature);
  return (r_eff - force / capacity_per_radius) / roller_radius;
}

/// Load period of one cam [rad of input angle]: the input cam's configuration repeats every
/// 2π/n_A (roller k taking the place of roller k ± 1), the output cam's every 2π m_A/(n_A m_B).
double LcrLoadPeriod(const LcrSizingSpec& spec, lcr::Side side);

/// The design of a variable vector x (of the problem built from spec).
lcr::Reducer<double> LcrDesign(const LcrSizingSpec& spec, std::span<const double> x);

/// Builds the problem: variables with bounds and scales, the evaluator, objective
/// "outer_diameter_bound_mm" (kOuterDiameter, scale 100 mm) or "power_loss_W" (kPowerLoss, scale
/// 5% of LcrOutputPowerW, as cycloid_min_size's) and constraints. The initial point is a
/// heuristic, not feasible in general (both backends start from infeasible points).
/// Output blocks (each also usable for reporting):
///   outer_diameter_bound_mm (2R), input_envelope_mm / output_envelope_mm (r_d + r_r − R <= 0),
///   input_roller_gap_mm / output_roller_gap_mm, input_undercut_margin_mm / output_...,
///   input_pitch_clearance_mm / output_... (r_d − e k − fraction r_d >= 0),
///   input_roller_force_N / output_... (samples, soft max, or the active samples in their order), input_stress_margin / output_...
///   (the dimensionless Hertz capacity margin above, samples or soft min; present when the stress
///   limit is finite), mean_efficiency (mean of lcr::AnalyzeAngle's η over efficiency_samples
///   angles of a full revolution, or with spec.lubrication the lubricated η over them; present when
///   limits.min_efficiency > 0), oil_temperature_C (with spec.lubrication's balance and a finite
///   limits.max_oil_temperature_C), input_roller_life / output_roller_life / eccentric_bearing_life
///   (ln(L10h / life_h), with a life limit), input_roller_static / output_roller_static /
///   eccentric_bearing_static (ln(C0 / (min_static_safety P0max)), P0max the largest sampled load at
///   the output torque times static_torque_Nmm / output_torque_Nmm; with
///   limits.min_static_safety and spec.life, each bearing with a static rating), power_loss_W (last; kPowerLoss only: the
///   lubricated loss P_loss over the same efficiency_samples angles, not-a-number without a thermal
///   equilibrium below the oil's limit).
/// @throws std::invalid_argument for kPowerLoss without spec.lubrication.
Problem MakeLcrSizingProblem(const LcrSizingSpec& spec);

/// The longest-life problem of one combination, a bound solved before the size (sizing/lcr_min_size.h):
/// maximise t, the smallest life margin ln(L10h / life_h) of the rated bearings, over the sizing's
/// variables with t in the place of R, subject only to the geometric rows (roller gap, undercut margin,
/// pitch-point clearance); the stress, load and efficiency limits and the outer diameter are left
/// out, so the problem is a relaxation: no design of the combination that meets every limit lives
/// longer than its maximum. Needs limits.life_h > 0 and spec.life. Outputs: shortest_life_margin
/// (t, the objective), the six geometric rows of MakeLcrSizingProblem, and input_roller_life_excess,
/// output_roller_life_excess, eccentric_bearing_life_excess (the margin minus t, >= 0). The
/// variable vector is the sizing problem's layout (LcrDesign reads it; its last entry is t).
Problem MakeLcrLongestLifeProblem(const LcrSizingSpec& spec);

/// count starting points for the sizing problem of spec (the first is the problem's own initial
/// point): heuristics that put the rollers where they have room and the pitch point at a fraction
/// of the turret radius, varied from one start to the next. Not feasible in general.
std::vector<std::vector<double>> LcrStartingPoints(const LcrSizingSpec& spec, int count);

/// Every (m_A, m_B) with n = m + difference on each cam and ratio m_A n_B/(m_A n_B − m_B n_A)
/// exactly equal to target (integer arithmetic), lobes <= max_lobes, lobes and rollers coprime.
struct LobeCombination {
  int lobes_a, rollers_a, lobes_b, rollers_b;
};
std::vector<LobeCombination> LobeCombinations(long target_ratio, int max_lobes,
                                              const std::vector<int>& differences);

}  // namespace camopt::objectives
