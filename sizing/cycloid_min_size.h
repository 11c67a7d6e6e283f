// The smallest one-tooth-difference cycloid drive for a ratio and a torque, sized together with
// its profile modifications and crowning on the 3D loaded contact (model/cycloid/loaded_tca.h).
//
// Variables (each named by the cycloid_ltca field it sets; fixed fields keep their values):
// eccentricity_mm, roller_position_radius_mm (pin circle a), roller_radius_mm (pin ρ),
// face_width_mm, delta_position_um, delta_radius_um (Δa, Δρ) and the crowning's coefficient_mm,
// effective_length_mm, end_drop_mm, flat_length_mm, radius_mm (per its type).
//
// Objective: the ring's outer diameter 2(a + ρ), the volume of the ring-and-disc envelope
// π (a + ρ)² b, or (with spec.lubrication) the lubricated loss of one disc at the design torque and
// input speed, P_loss = P_out (1/η − 1): the most efficient drive within the variables' ranges.
//
// Constraint rows, each with its exact first derivative:
//   kSizingPeakPressure   the peak pressure of every (crank angle, roller) of the design-torque
//                         cycle <= contact_stress_MPa (0 and a zero gradient for a roller that
//                         carries no load; implicit-function derivative, peak cell frozen);
//   kSizingEndDistance    the end distance at every crank angle of the overload cycle >=
//                         min_edge_margin_um (only with an overload torque);
//   kSizingBacklash       the unloaded TE β0 (the disc's free rotation to first contact) at every
//                         angle in [min_backlash_arcsec, max_backlash_arcsec];
//   kSizingLte            the loaded TE's peak-to-peak at the design torque (only when bounded);
//   kSizingCurtate        1 − e N / a' >= min_curtate_margin (geometry_limits.h);
//   kSizingUndercut       the smallest convex radius of the tooth, closed form (C3)/(C4) of
//                         geometry_limits.h, minus min_profile_radius_mm, >= 0;
//   kSizingPinGap         2 a sin(π/N) − 2ρ − min_pin_gap_mm >= 0;
//   kSizingWeb            a' − e − ρ' − bore radius − min_web_mm >= 0 (only with a bore);
//   kSizingCrowningFit    two rows >= 0 that keep the crowning on the face as the face width and
//                         the crowning's parameters move (cycloid::CheckCrowning): logarithmic
//                         L − b (when L is its own field) and b − flat length; full R − b/2;
//                         partial R − (b − flat)/2 and b − flat; 1 where a row does not apply;
//   kSizingLife           one row per rated bearing (crank bearing, then the ring pins when
//                         rated), m = ln(L10h / life_h) >= ln(fast life / life_h) (LifeMargin of
//                         model/common/bearing_life.h; only with limits.life_h): the ISO 281 life
//                         over the duty cycle of the loads the sizing's own cycles give
//                         (model/cycloid/bearing_loads.h), each duty line one cycle at its torque.
//                         Exact derivatives: the pair loads by implicit differentiation, the
//                         contact normals, the disc lag and the pins' spin through the unloaded
//                         TCA with a Jet.
//   kSizingStatic         (limits.min_static_safety at limits.static_torque_Nmm, a momentary torque)
//                         P/C0 of the crank bearing at every sample of its load period and of every
//                         (crank angle, pin) <= 1/s0, on one more cycle at that torque (each bearing
//                         with a static rating; derivatives as the life rows');
//   kSizingStiffness      (with limits.min_torsional_stiffness_Nm_per_arcmin and the compliant output
//                         mechanism) the torsional stiffness, input held at crank 0, between 50% and
//                         100% of the design torque T_r (model/cycloid/stiffness.h's definition; at
//                         crank 0 both directions are equal): (T_r/2)/(θ(T_r) − θ(T_r/2)), θ = β + w,
//                         β the LTCA's disc lag (its derivative by implicit differentiation), w the
//                         output pins' rotation (its Jet derivative through SolveOutputPins);
//   kSizingLostMotion     (limits.max_lost_motion_arcmin) θ(0.03 T_r) − θ(−0.03 T_r) = 2 θ(0.03 T_r) at
//                         crank 0 (the curve is odd there);
//   kSizingOutputPinStress (limits.output_pin_stress_MPa) the output pins' bending stress at every
//                         crank angle of the pins' load period (the mesh period's angles shifted by
//                         whole mesh periods, OutputPinPeriodInMeshPeriods), the largest over the pins
//                         (that pin frozen), one disc: M = Q (L − b/2) (cantilever) or Q L/4 (both
//                         ends), L the span (absent: the face width b);
//   kSizingCrankBearing   (limits.eccentric_bearing_load_N) |B| = |−G − Σ Q_j n_j| at the same angles,
//                         G the ring-pin resultant of the design cycle (crank frame, derivatives as the
//                         life rows'), the output pins solved with clearance and compliance;
//   kSizingOutputHoles    (with the compliant output mechanism) the holes inside the root circle:
//                         a' − e − ρ' − (R_w + r_h) >= 0;
//   kSizingEfficiency     (with spec.lubrication and limits.min_efficiency) η = P_out/(P_out + P_loss)
//                         at the design torque and the input speed, P_loss one disc's mean over a
//                         revolution's pattern (model/cycloid/lubrication.h MeanLoss: the sizing's
//                         angles with the output pins shifted as LubricationLoadsOverRevolution);
//                         exact derivatives: the pair loads and the disc lag by implicit
//                         differentiation, the unloaded contacts, speeds and film with a Jet;
//   kSizingOilTemperature (limits.max_oil_temperature_C, the housing's balance) the oil
//                         temperature of the balance P_loss(t) = k (t − t_amb) (model/common/
//                         thermal.h), its derivative dt/dx = (∂P/∂x)/(k − ∂P/∂t) (implicit), and
//                         with it the loss's and η's.
// The holes follow the sized eccentricity with a fixed radial clearance c: r_h = r_c + e + c
// (CycloidSizingOutput).
// The crank angles sample one mesh period 2π/N uniformly: a peak between two samples is missed by
// the fast model, which is what the verified-optimum loop (objectives/verification.h) catches.
//
// The solve (SolveCycloidMinSize): local solves from several starts, the best converged one
// re-evaluated by the accurate model (twice the cells across and along the contact, twice the
// crank angles; each value's error estimated as its change from the fast settings). A limit holds
// (objectives/verification.h) when the accurate value is within the limit plus its error; the loop
// aims further, at the accurate value itself within the limit (0.1% slack): while a stress,
// edge-margin or backlash value is beyond its limit, that fast limit is tightened (stress: by the
// accurate/fast ratio; edge margin and backlash: by the miss plus 2% of the limit) and the problem
// solved again from the last design, at most `verify_rounds` times. A peak that grows with
// refinement (a straight tooth's edge) has a large estimated error, which would
// otherwise pass a design the accurate model puts above its limit.
#pragma once

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/common/bearing_life.h"
#include "model/common/thermal.h"
#include "model/cycloid/bearing_loads.h"
#include "model/cycloid/loaded_tca.h"
#include "model/cycloid/lubrication.h"
#include "model/cycloid/output_mechanism.h"
#include "objectives/problem.h"
#include "objectives/verification.h"
#include "optimizers/solver.h"
#include "sizing/limit_slope.h"

namespace camopt::sizing {
// The sizing loops speak the objectives' vocabulary (problems, limits, the verification contract).
using namespace camopt::objectives;

inline constexpr const char* kSizingOuterDiameter = "outer_diameter_mm";
inline constexpr const char* kSizingVolume = "envelope_volume_mm3";
inline constexpr const char* kSizingPowerLoss = "power_loss_W";
inline constexpr const char* kSizingPeakPressure = "pair_peak_pressure_MPa";
inline constexpr const char* kSizingEndDistance = "end_distance_at_overload_um";
inline constexpr const char* kSizingBacklash = "unloaded_te_arcsec";
inline constexpr const char* kSizingLte = "lte_peak_to_peak_arcsec";
inline constexpr const char* kSizingCurtate = "curtate_margin";
inline constexpr const char* kSizingUndercut = "undercut_margin_mm";
inline constexpr const char* kSizingPinGap = "pin_gap_margin_mm";
inline constexpr const char* kSizingWeb = "web_margin_mm";
inline constexpr const char* kSizingCrowningFit = "crowning_fit_mm";
inline constexpr const char* kSizingLife = "life_margin";
inline constexpr const char* kSizingStiffness = "torsional_stiffness_Nm_per_arcmin";
inline constexpr const char* kSizingLostMotion = "lost_motion_arcmin";
inline constexpr const char* kSizingOutputPinStress = "output_pin_stress_MPa";
inline constexpr const char* kSizingCrankBearing = "eccentric_bearing_load_N";
inline constexpr const char* kSizingOutputHoles = "output_holes_margin_mm";
inline constexpr const char* kSizingEfficiency = "efficiency";
inline constexpr const char* kSizingOilTemperature = "oil_temperature_C";
inline constexpr const char* kSizingStatic = "static_utilisation";

/// Field names a sizing variable may have.
std::vector<std::string> CycloidSizingVariableNames();
/// "" when `name` may be a sizing variable with this crowning type, else why not.
std::string CycloidSizingVariableAllowed(const std::string& name, cycloid::CrowningType type);

/// kPowerLoss: the lubricated loss of one disc [W] at the design torque and the input speed
/// (spec.lubrication), the least loss being the highest efficiency at that output power.
enum class CycloidSizeObjective { kOuterDiameter, kVolume, kPowerLoss };

/// The study's limits (the `limits` object of cycloid_min_size, same names).
struct CycloidSizingLimits {
  double contact_stress_MPa = kInf;      ///< peak pressure over the design-torque cycle
  double min_edge_margin_um = 0;         ///< end distance over the overload cycle (with an overload)
  double min_curtate_margin = 0.05;      ///< 1 − e N / a'
  double min_profile_radius_mm = 0;      ///< smallest convex radius of the tooth (no undercut: 0)
  double min_pin_gap_mm = 0;             ///< clearance between neighbouring pins
  double min_backlash_arcsec = 0;        ///< β0 at every angle (no interference at assembly)
  double max_backlash_arcsec = kInf;     ///< β0 at every angle (backlash bound)
  double max_lte_peak_to_peak_arcsec = kInf;
  double bore_radius_mm = 0;             ///< the disc's central bore; 0: no web row
  double min_web_mm = 0;                 ///< web between the tooth root and the bore
  double life_h = 0;                     ///< shortest L10h of any rated bearing; 0: no life row
  /// s0 = C0/P0max of the crank bearing and the pins (those with a static rating) at
  /// static_torque_Nmm, a momentary torque on the disc (one more cycle there); 0: no rows. Needs
  /// spec.life (its ratings and output mechanism).
  double min_static_safety = 0, static_torque_Nmm = 0;
  /// With the compliant output mechanism (CycloidSizingSpec::output); 0 / kInf: no row.
  double min_torsional_stiffness_Nm_per_arcmin = 0;
  double max_lost_motion_arcmin = kInf;
  double output_pin_stress_MPa = kInf;
  double eccentric_bearing_load_N = kInf;
  /// With the lubricated losses (CycloidSizingSpec::lubrication); 0 / kInf: no row.
  double min_efficiency = 0;
  double max_oil_temperature_C = kInf;  ///< the housing's balance only
};

/// The lubricated losses of a sizing (model/cycloid/lubrication.h) at the design torque and the
/// input speed, the oil temperature given or from the housing's balance (model/common/thermal.h).
struct CycloidSizingLubrication {
  cycloid::CycloidLubricationSpec spec;
  cycloid::OutputMechanism mechanism;  ///< the rigid output pins whose forces load the pins and the crank bearing
  /// The output pins' contacts (absent: not modelled); the holes follow the sized eccentricity,
  /// r_h = r + e + hole_clearance_mm (r the pin's or its roller's radius), as CycloidSizingOutput's.
  std::optional<cycloid::OutputPinContact> pins;
  double hole_clearance_mm = 0;
  double input_speed_rpm = 0;
  std::optional<double> temperature_C;  ///< given; absent: the housing's balance
  HousingCooling cooling;
  double balance_limit_C = 120;  ///< the balance is sought below it (the oil's limit)
};

/// The output mechanism with clearance and compliance of a sizing (model/cycloid/output_mechanism.h):
/// the pins fixed, the holes made for the sized eccentricity with a fixed radial clearance,
/// r_h = r_c + e + c (pins.hole_radius_mm is not used). The pins' face width and E* follow the design.
struct CycloidSizingOutput {
  cycloid::OutputPins pins;
  double clearance_mm = 0;  ///< c = r_h − r_c − e
  cycloid::PinSupport support = cycloid::PinSupport::kCantilever;
  double span_mm = 0;  ///< the pin's span; 0: the face width (it follows a sized face width)
};

/// The bearing life of a sizing (docs/life.md, "Cycloid"): the duty cycle (output torque = the
/// disc's), the crank bearing's ratings, the ring pins' (optional) and the output mechanism (fixed:
/// not a sizing variable).
struct CycloidSizingLife {
  std::vector<OperatingLine> lines;
  BearingKind crank_kind = BearingKind::kBall;
  double crank_dynamic_N = 0, crank_static_N = 0;
  bool pins_rated = false;
  double pins_dynamic_N = 0, pins_static_N = 0;
  cycloid::OutputMechanism output;
};

/// One rated bearing's life at a design.
struct CycloidBearingLife {
  std::string name;  ///< "crank_bearing", "pins"
  bool ball = false;
  double dynamic_N = 0, static_N = 0, s0 = 0;
  cycloid::BearingLifeOverCycle life;
};

struct CycloidSizingSpec {
  cycloid::Drive drive;             ///< teeth, rollers, and the start (or fixed) value of every field
  cycloid::Crowning crowning;       ///< its type, start (or fixed) values
  cycloid::Material material;
  /// The fast model's grid and tolerances (the accurate model refines them). Its contact solves
  /// run the plain Polonsky–Keer iteration: with the preconditioned one (the LTCA's default) the
  /// paper and ratio-29 examples end "stopped_infeasible" (the fast model's edge margin a little
  /// beyond its limit at the last point) and the datasheet example with an eccentric-bearing
  /// limit at a 2.9% larger diameter: both iterations meet their 1e-4 tolerance, the optimizers
  /// follow the difference in the last digits (docs/performance.md).
  cycloid::LoadedOptions options = [] {
    cycloid::LoadedOptions o;
    o.precondition_solves = false;
    return o;
  }();
  double design_torque_Nmm = 0;     ///< on the disc
  double overload_torque_Nmm = 0;   ///< 0: no overload cycle, no edge rows
  int angles_per_period = 6;        ///< crank angles over one mesh period 2π/N
  /// Names from CycloidSizingVariableNames, in their own units (µm for delta_*_um), bounds and
  /// start; every listed variable varies (a fixed field is not listed).
  std::vector<Variable> variables;
  CycloidSizingLimits limits;
  CycloidSizeObjective objective = CycloidSizeObjective::kOuterDiameter;
  /// The speed or duty cycle and the ratings: lives reported; with limits.life_h, one row each.
  std::optional<CycloidSizingLife> life;
  /// The output pins with clearance and compliance: the stiffness, lost motion, output-pin stress
  /// and crank-bearing load (reported; with their limits, rows).
  std::optional<CycloidSizingOutput> output;
  /// The lubricated losses: the efficiency and oil temperature reported; with their limits, rows.
  std::optional<CycloidSizingLubrication> lubrication;
};

/// One design as the fast (or, in CycloidAccurateCheck, the accurate) model sees it.
struct CycloidSizingEvaluation {
  std::vector<double> x;
  double outer_diameter_mm = 0, volume_mm3 = 0;
  double stress_MPa = 0;               ///< exact maximum over the design cycle's samples
  std::vector<double> pair_peak_MPa;   ///< per (angle, roller), angle-major (0: roller unloaded)
  double edge_margin_um = kInf;        ///< min end distance over the overload cycle (kInf: none)
  std::vector<double> end_distance_um; ///< per angle of the overload cycle
  std::vector<double> unloaded_te_arcsec;  ///< β0 per angle
  double lte_peak_to_peak_arcsec = 0;
  double max_pair_load_N = 0;
  double curtate_margin = 0, undercut_margin_mm = 0, pin_gap_margin_mm = 0, web_margin_mm = 0;
  double min_profile_radius_mm = 0;    ///< smallest convex radius of the tooth itself
  std::array<double, 2> crowning_fit_mm{};  ///< the two kSizingCrowningFit rows
  bool converged = true;
  /// With gradients, [row][variable] for the vector blocks, [variable] for the scalars.
  std::vector<double> d_pair_peak, d_end_distance, d_unloaded_te, d_lte;
  std::vector<double> d_objective, d_curtate, d_undercut, d_pin_gap, d_web;
  std::vector<double> d_crowning_fit;  ///< [row][variable], 2 rows
  std::vector<CycloidBearingLife> lives;  ///< crank bearing, then pins (with spec.life)
  double shortest_life_h = kInf;          ///< shortest L10h of lives
  std::vector<double> life_margin;        ///< ln(L10h / life_h) per bearing (with limits.life_h)
  std::vector<double> d_life_margin;      ///< [row][variable]
  /// With limits.min_static_safety: P/C0 per sample (crank bearing's load period, then every
  /// (crank angle, pin)) at the static torque, and the smallest s0 = 1/max of them.
  std::vector<double> static_utilisation, d_static_utilisation;  ///< d: [row][variable]
  double min_static_safety = kInf;
  /// With spec.output (kNaN when the cycles are not solved): the torsional curve at crank 0 and the
  /// output mechanism over the pins' load period (angle-major: shift r, then the cycle's angle k).
  double stiffness_Nm_per_arcmin = NAN, lost_motion_arcmin = NAN;
  std::vector<double> output_pin_stress_MPa, crank_bearing_load_N;
  double max_output_pin_stress_MPa = NAN, max_crank_bearing_load_N = NAN;
  double output_holes_margin_mm = 0;
  std::vector<double> d_stiffness, d_lost_motion, d_output_holes;         ///< [variable]
  std::vector<double> d_output_pin_stress, d_crank_bearing_load;          ///< [row][variable]
  /// With spec.lubrication (kNaN outside the model's domain or without a thermal equilibrium).
  double efficiency = NAN, power_loss_W = NAN, oil_temperature_C = NAN;  ///< one disc's loss
  std::string lubrication_why;  ///< why there is no efficiency (no equilibrium below the oil's limit)
  std::vector<double> d_efficiency, d_oil_temperature, d_power_loss;  ///< [variable]
};

/// The two cycles (design and overload torque) and the closed-form limits of a design x. Pure:
/// an evaluation depends on its arguments only.
class CycloidSizingModel {
 public:
  /// @throws std::invalid_argument for an unknown or disallowed variable name.
  explicit CycloidSizingModel(CycloidSizingSpec spec);
  CycloidSizingEvaluation Evaluate(const std::vector<double>& x, bool with_gradient);
  /// The drive and crowning that x sets.
  std::pair<cycloid::Drive, cycloid::Crowning> Design(const std::vector<double>& x) const;
  const CycloidSizingSpec& spec() const { return spec_; }
  const std::vector<double>& crank_angles() const { return angles_; }
  int evaluations() const { return evaluations_; }
  int gradient_evaluations() const { return gradient_evaluations_; }
  double value_seconds() const { return value_seconds_; }        ///< CPU time of the cycles
  double gradient_seconds() const { return gradient_seconds_; }  ///< of their derivatives

 private:
  CycloidSizingSpec spec_;
  std::vector<double> angles_;
  int evaluations_ = 0, gradient_evaluations_ = 0;
  double value_seconds_ = 0, gradient_seconds_ = 0;
  std::vector<double> last_x_;
  std::optional<cycloid::CycleResult> last_design_, last_over_;
  std::vector<std::optional<cycloid::CycleResult>> last_lines_;  // duty lines at other torques
  std::optional<cycloid::CycleResult> last_half_, last_small_;   // crank 0 at T_r/2, 0.03 T_r (spec.output)
  std::optional<cycloid::CycleResult> last_static_;              // the static torque's (limits.min_static_safety)
  // The first design's models: every later one is WithDesign of these (shared solver caches).
  std::optional<cycloid::LoadedTca> base_design_, base_over_;
};

/// The fast limits the solver is given (the study's, tightened by the verified-optimum loop).
struct CycloidFastLimits {
  double contact_stress_MPa = kInf;
  double min_edge_margin_um = 0;
  double min_backlash_arcsec = 0;
  double max_backlash_arcsec = kInf;
  double life_h = 0;  ///< the life rows' required L10h (>= limits.life_h)
  double min_static_safety = 0;  ///< the static rows' required s0 (>= limits.min_static_safety)
  double min_torsional_stiffness_Nm_per_arcmin = 0, max_lost_motion_arcmin = kInf, output_pin_stress_MPa = kInf,
         eccentric_bearing_load_N = kInf;
  double min_efficiency = 0, max_oil_temperature_C = kInf;
};

/// What the LTCA rows say at a design outside the model's domain (a looped or undercut tooth,
/// overlapping pins, a crowning off the face: cycloid::CheckDrive, CheckCrowning), where there is
/// no contact to analyse. kNaN: not-a-number, which Ipopt answers by a shorter step. kPenalty:
/// finite values that break their rows by far (peaks 1e6 MPa, end distances and β0 −1e4, LTE
/// 1e6 arcsec; zero derivatives), which SLSQP's merit line search rejects (it stops at a NaN).
enum class OutsideDomain { kNaN, kPenalty };

/// Minimise the objective subject to the rows above with `fast` in place of the study's
/// contact-stress, edge-margin and backlash limits. `model` must outlive the problem.
Problem CycloidSizingProblem(CycloidSizingModel& model, const CycloidFastLimits& fast,
                             std::function<void(const CycloidSizingEvaluation&)> on_evaluation = nullptr,
                             OutsideDomain outside = OutsideDomain::kNaN);

/// The accurate model's values at a design (cells ×2 both ways, crank angles ×2) with each
/// value's estimated error (|accurate − fast settings|), and the limits checked against them.
struct CycloidAccurateCheck {
  CycloidSizingEvaluation fast, accurate;
  double stress_error_MPa = 0, edge_margin_error_um = 0, backlash_error_arcsec = 0, lte_error_arcsec = 0;
  double life_error_h = 0;  ///< |accurate − fast| of the shortest L10h
  double static_safety_error = 0;  ///< |accurate − fast| of the smallest s0 at the static torque
  /// |accurate − fast| of the output rows (with spec.output)
  double stiffness_error = 0, lost_motion_error_arcmin = 0, output_pin_stress_error_MPa = 0,
         crank_bearing_error_N = 0;
  double efficiency_error = 0, oil_temperature_error_C = 0;  ///< with spec.lubrication
  std::string model;   ///< in words, with its settings
  std::vector<VerifiedLimit> checks;
};
CycloidAccurateCheck CheckCycloidDesign(const CycloidSizingSpec& spec, const cycloid::Drive& drive,
                                        const cycloid::Crowning& crowning);

struct CycloidMinSizeOptions {
  /// backend ("ipopt", "slsqp"), tolerances, budgets; Ipopt without a fallback backend gets SLSQP
  /// as its fallback (it polishes Ipopt's last point when Ipopt ends at its iteration limit).
  optimizers::SolverOptions solver;
  int starts = 2;                     ///< starting points: the variables' own, then box points
  int verify_rounds = 3;              ///< tightening rounds of the verified-optimum loop
  std::function<void(double fraction, const std::string& stage)> progress;
  /// Each binding limit's cost re-solved at the limit ± 1% (CycloidMinSizeOutcome::limit_slope).
  bool re_solve_limit_costs = true;
  /// The fast limits to start from (a re-solve starts from the answer's tightened ones); absent:
  /// the study's.
  std::optional<CycloidFastLimits> fast_start;
};

struct CycloidMinSizeOutcome {
  bool converged = false;             ///< the last solve converged (the optimizer's own test)
  bool verified = false;              ///< every limit holds on the accurate model
  std::vector<double> x;              ///< the reported design's variables (empty: no design)
  cycloid::Drive drive;
  cycloid::Crowning crowning;
  optimizers::SolverResult result;    ///< the last solve (evaluation counts summed over all)
  CycloidAccurateCheck check;         ///< at the reported design
  Verification verification;
  /// Limits that bind at the optimum (study limit key → d(objective)/d(limit), in the objective's
  /// unit per unit of the limit), from the KKT multipliers of the active rows.
  std::map<std::string, double> limit_cost;
  /// |∇f − Σ λ ∇g| / |∇f| of those multipliers (0 at an exact KKT point; NaN: none computed).
  double limit_cost_residual = std::numeric_limits<double>::quiet_NaN();
  /// The same limits' costs from verified re-solves at the limit ± 1% from the answer (sizing/
  /// limit_slope.h): central where both sides solve, one-sided otherwise, kinks flagged.
  std::map<std::string, LimitSlope> limit_slope;
  std::vector<optimizers::SolverResult> starts;   ///< each start's solve in the first round
  int evaluations = 0, gradient_evaluations = 0;
  double value_seconds = 0, gradient_seconds = 0, verification_seconds = 0;
};

/// @throws std::invalid_argument for a spec the model refuses.
CycloidMinSizeOutcome SolveCycloidMinSize(const CycloidSizingSpec& spec, const CycloidMinSizeOptions& options);

}  // namespace camopt::sizing
