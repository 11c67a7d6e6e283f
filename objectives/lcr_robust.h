// LCR sizing that holds across manufacturing tolerances: the robust rows of the sizing
// problem (objectives/lcr_sizing.h, LcrSizingSpec::robust), their linearised grid check, and the
// Monte-Carlo check of a design against the exact model. The robust solve of one combination is
// sizing/lcr_robust_solve.h.
//
// Model. The tolerances act through the compliant load sharing of model/lcr/transmission_error.h
// (per-roller normal gaps from the exact geometry, Palmgren contacts; the only model in which they
// act): a roller's force under deviations t is the sizing's rigid-law force plus the compliant
// model's change, F_k(t) = F_k^rigid + [F_k^c(t) − F_k^c(0)], and its stress margin is
// LcrStressMargin at that force with the roller's own radius r_r + Δr_k (the curvature at the
// contact kept nominal). Linearised: q(t) ≈ q + Σ_p S_p t_p with S_p = ∂q/∂t_p at t = 0.
// The undercut margin moves only with the cam profile's normal offset δ (the cam is cut to the
// nominal pitch curve at the offset r_r − δ; eccentricity, turrets and rollers are assembled
// around it): margin − δ_band (worst case), margin − k δ_band/√3 (sigma).
//
// Rule, per row (upper limits: force; lower limits: stress margin, undercut margin):
// - worst_case: the extreme of the linear q over the tolerance box: Σ |S_p| b_p on the ± bands,
//   and max(0, S c) on the bearing clearance (0 … c);
// - sigma: mean + k σ of the linear q with every deviation uniform: ± bands mean 0 and
//   σ² = b²/3, the clearance mean c/2 and σ² = c²/12; W = Σ μ_p S_p ± k (Σ σ_p² S_p²)^½.
// Both W are positively homogeneous of degree 1 in S, so W = Σ_p w_p S_p with w_p = ∂W/∂S_p
// (sign(S_p) b_p, or μ_p + k σ_p² S_p / σ_W) and ∇_x W = Σ_p w_p ∇_x S_p (Euler: Σ_p S_p ∇w_p = 0).
// The sensitivities are written in closed form over the design's scalar, so the problem's own Jet
// carries their exact derivatives (the mixed second-order terms ∂²q/∂x∂t) without nested Jets.
// The sensitivities S_p are physics: model/lcr/tolerance_sensitivity.h (closed form over the
// design's scalar, checked against ceres::Jet through lcr::CompliantAtAngle in tests/lcr_robust_test.cc).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "model/lcr/forces.h"
#include "model/lcr/tolerance_sensitivity.h"
#include "model/lcr/transmission_error.h"
#include "objectives/lcr_dense_check.h"
#include "objectives/lcr_sizing.h"

namespace camopt::objectives {

enum class LcrRobustMethod { kWorstCase, kSigma };

/// Tolerances and the rule by which the sizing limits hold across them.
struct LcrRobustRule {
  lcr::ToleranceBands bands;
  LcrRobustMethod method = LcrRobustMethod::kWorstCase;
  double k = 3.0;  ///< kSigma: the limits hold at mean + k σ of the linearised quantity
};

/// Per roller of one cam at one angle: what the rule adds to the force row [N] and to the stress
/// margin row (dimensionless; empty without a stress limit).
template <typename T>
struct LcrRobustIncrements {
  std::vector<T> force, margin;
};

/// The increments of every roller of one cam at input angle θ [rad] (the rule applied to
/// lcr::RollerToleranceSensitivities), from the rigid-law loads sl
/// of design r at θ (the sizing's own, lcr::AnalyzeAngle). T: double or ceres::Jet<double, 6>
/// (the sizing problem's Jet). @pre spec.robust.
template <typename T>
LcrRobustIncrements<T> RobustIncrements(const LcrSizingSpec& spec, const lcr::Reducer<T>& r, lcr::Side side,
                                        double theta, const lcr::SideLoads<T>& sl);

/// What the rule adds to the undercut margin [mm] (≤ 0).
double RobustUndercutIncrement(const LcrRobustRule& rule);

/// The linearised robust quantities of a design on a grid of `steps_per_period` angles per load
/// period of each cam (offset by half a step from the problem's samples).
struct LcrRobustCheck {
  double max_force_N = 0;        ///< largest robust roller force, both cams
  double min_stress_margin = 0;  ///< smallest robust stress margin over loaded contacts (≥ 0 holds)
  double max_stress_MPa = 0;     ///< the Hertz stress at that margin's force and roller
  double undercut_margin_mm = 0; ///< smallest robust undercut margin
  int steps_per_period = 0;
  std::vector<LcrViolation> violations;  ///< against spec.limits
  bool ok() const { return violations.empty(); }
};
LcrRobustCheck RobustGridCheck(const LcrSizingSpec& spec, const lcr::Reducer<double>& r, int steps_per_period);

/// Monte-Carlo check of a design against the exact model: `samples` sets of deviations (uniform in
/// each band, clearance 0 … c; lcr::SampleDeviations), each solved at `angle_steps` input angles of
/// a revolution with the compliant model (which rollers touch re-solved), forces F^rigid + F^c(t) −
/// F^c(0), Hertz stress with each roller's own radius, undercut margin with each cam's offset.
struct LcrMonteCarloCheck {
  int samples = 0, angle_steps = 0;
  std::uint64_t seed = 1;
  int violating = 0;                ///< samples that break any limit
  double violating_fraction = 0;
  /// Worst over samples and angles: force [N], stress [MPa], undercut margin [mm].
  double max_force_N = 0, max_stress_MPa = 0, min_undercut_margin_mm = 0;
  int worst_sample = -1;            ///< index of the sample with the largest relative excess (−1: none)
  double worst_relative_excess = 0; ///< its largest (value − limit)/limit over the limits (≤ 0: holds)
};
LcrMonteCarloCheck MonteCarloCheck(const LcrSizingSpec& spec, const lcr::Reducer<double>& r, int samples,
                                   std::uint64_t seed, int angle_steps);

}  // namespace camopt::objectives
