// The dense check of an LCR design against a sizing's limits: the cycle maxima of contact stress
// and roller force on lcr_analysis' grid of input angles over the full cycle, the exact undercut
// margin (lcr::UndercutMargin) and roller gap, the mean efficiency and the rated bearings' lives —
// the accurate model against which every LCR sizing (sizing/lcr_min_size.h, lcr_robust_solve.h,
// lcr_sizing3d.h) holds its designs, and the verified-optimum contract of a line-model design.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "model/lcr/reducer.h"
#include "objectives/lcr_sizing.h"
#include "objectives/verification.h"

namespace camopt::objectives {

/// A limit exceeded at a design, named by the study's limit key.
struct LcrViolation {
  std::string limit;      ///< "contact_stress_MPa", "roller_load_N", "undercut_margin_mm",
                          ///< "roller_gap_mm", "min_efficiency", "max_oil_temperature_C", "life_h",
                          ///< "max_outer_diameter_mm", "min_static_safety"
  double value = 0.0;     ///< the design's worst value of that quantity (both cams)
  double limit_value = 0.0;
  /// By how much, in the limit's unit, positive: value − limit for upper limits, limit − value
  /// for lower ones.
  double excess() const;
};

/// One rated bearing's life at a design (docs/life.md, "Life as a sizing limit").
struct LcrBearingLifeCheck {
  std::string name;               ///< "input_roller", "output_roller", "eccentric_bearing"
  bool ball = false;
  double dynamic_rating_N = 0.0;  ///< C at the design's roller size
  double static_rating_N = 0.0;   ///< C0; 0 when not given
  lcr::LcrBearingLife life;       ///< loads, revolutions, L10h over the duty cycle
  double s0 = kInf;               ///< C0 / largest load (+∞ without C0 or load)
};

/// A design's numbers on the dense grid (as lcr_analysis computes them) and the limits it breaks.
struct LcrDenseCheck {
  double outer_diameter_mm = 0.0;
  std::array<double, 2> max_stress_MPa{}, max_force_N{}, undercut_margin_mm{}, roller_gap_mm{},
      pitch_clearance_mm{};  ///< [0] input cam, [1] output cam
  /// Half-width b [mm] of the Hertz line contact that sets max_stress_MPa (its subsurface stresses,
  /// docs/life.md "Contact fatigue of the cam surfaces"); 0 without load or on an undercut contact.
  std::array<double, 2> peak_half_width_mm{};
  /// The mean efficiency over the revolution: eq. 33's, or with spec.lubrication the lubricated one
  /// (model/lcr/lubrication.h LubricatedRigidCycle over the same angles; NaN without a thermal
  /// equilibrium below the oil's limit, lubrication_why saying so).
  double mean_efficiency = 0.0;
  double oil_temperature_C = NAN;  ///< with spec.lubrication: given or the housing's balance
  double lubricated_loss_W = NAN;  ///< with spec.lubrication: the mean loss
  std::string lubrication_why;
  /// With spec.life: every rated bearing's life, `steps` samples per input revolution over its load
  /// period and each duty line at its torque (lcr::BearingLifeOverDutyCycle, the rigid law);
  /// shortest_L10h the least of them (+∞ without spec.life).
  std::vector<LcrBearingLifeCheck> life;
  double shortest_L10h = kInf;
  /// With limits.min_static_safety: the smallest s0 = C0/P0max of the bearings with a static rating at
  /// limits.static_torque_Nmm (each max load scaled from its duty line of largest torque: the rigid
  /// law's loads are proportional to the torque); +∞ without.
  double min_static_safety = kInf;
  std::vector<LcrViolation> violations;
  std::vector<std::string> design_problems;  ///< lcr::CheckDesign, "field: message"
  bool ok() const { return violations.empty() && design_problems.empty(); }
};

/// The dense check of design r against spec.limits (the study's own limits) over `steps` input
/// angles of the full cycle with the spec's torque, friction and material. When near is given it
/// receives the samples that come near a limit (step 2 of sizing/lcr_min_size.h's header comment), sorted by angle.
/// @throws std::domain_error for a degenerate design (no roller of a turret carries load).
LcrDenseCheck DenseCheck(const LcrSizingSpec& spec, const lcr::Reducer<double>& r, int steps = 3600,
                         LcrActiveSet* near = nullptr);

/// The value of spec.objective at a checked design, on the dense grid: the outer diameter [mm]
/// (kOuterDiameter) or the lubricated loss [W] (kPowerLoss; NaN without a thermal equilibrium).
/// What the sizing compares its starts and candidates by.
double LcrObjectiveValue(const LcrSizingSpec& spec, const LcrDenseCheck& check);

/// The verified-optimum contract (objectives/verification.h) of a line-model design: the accurate
/// model is the dense check on 2·steps input angles (the reported values), its error the change
/// from `steps` angles (a refinement, not a subset: the finer set has every other angle new). Per
/// cam: contact stress and roller force (upper limits, when finite), undercut margin and roller gap
/// (lower limits, exact: no angle sampling); the outer diameter when it is limited (exact); the
/// mean efficiency when it is a limit; each rated
/// bearing's L10h when life_h is a limit (lower, its error the change from `steps` samples per
/// revolution to 2·steps). The line
/// model's own tightening rounds are the polish rounds of SolveLcrMinSize (tracked peaks join until
/// the dense check holds), so this check only reports.
Verification VerifyLcrLineDesign(const LcrSizingSpec& spec, const lcr::Reducer<double>& r, int steps = 3600);

/// spec with the limits the solvers are given: tightened by a little more than their constraint
/// tolerance (the dense check holds the design to the study's own limits).
LcrSizingSpec LcrTightened(const LcrSizingSpec& spec);

}  // namespace camopt::objectives
