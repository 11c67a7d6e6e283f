// The exact follower motion on a manufactured (perturbed) cam, by an independent construction:
// the roller is pressed on the perturbed profile, so at each cam angle its position is the
// outermost one at which the roller circle still touches a profile point,
//   S_exact(θ) = max over profile parameters t of  S at which |C(S, θ) − P(t)| = r_f + Δr_f,
//   P(t) = A(t) + Δn n(t) + Δr A(t)/|A(t)|      (A, n of the nominal cam at parameter t),
// the larger root of a quadratic (translating) or of a circle–circle intersection (oscillating).
// It uses neither the pressure angle nor the instant centre, so it checks the linearised
// errors of mechanical_error.h (eqs. 16–32), and a Monte-Carlo run shows where they hold.
#pragma once

#include <cstdint>
#include <vector>

#include "model/disc_cam/disc_cam.h"
#include "model/disc_cam/mechanical_error.h"

namespace camopt::disc_cam {

/// What ExactFollowerPosition's search at one cam angle needs of the nominal cam, whatever the
/// deviations: the cam angle, the nominal follower coordinate there (oscillating arm) and the
/// nominal profile at the coarse scan's parameters. A Monte-Carlo run builds it once per angle.
struct ExactSearchNominal {
  static constexpr int kScan = 12;  ///< scan intervals over the window
  double theta = 0.0, window_rad = 0.0;
  double follower_coordinate = 0.0;  ///< S(θ) of the motion program
  double initial_coordinate = 0.0;   ///< InitialFollowerCoordinate
  Vec2<double> u = Vec2<double>::Zero();  ///< U(θ)
  std::vector<CamContact<double>> scan;  ///< the profile's contact at θ − window + k·2window/kScan, k = 0 … kScan
};
ExactSearchNominal NominalForExactSearch(const DiscCam& cam, double theta, double window_rad = 3.0 * kPi / 180.0);

/// Follower coordinate S (mm or rad, on the motion program's scale) on the perturbed cam at cam
/// angle theta [rad]. The contact is searched within ±window_rad of the nominal contact parameter.
/// Returns NaN when no profile point in the window can touch the roller (never in practice).
double ExactFollowerPosition(const DiscCam& cam, const Deviations<double>& d, double theta,
                             double window_rad = 3.0 * kPi / 180.0);
/// The same search from its nominal part built beforehand (the same operations, the same bits).
double ExactFollowerPosition(const DiscCam& cam, const Deviations<double>& d, const ExactSearchNominal& nominal);

struct MonteCarloOptions {
  int samples = 200;            ///< per tolerance scale
  int angle_steps = 360;        ///< cam angles per sample
  uint64_t seed = 1;
  std::vector<double> scales = {1.0, 10.0, 100.0};  ///< tolerance multipliers
};

/// One tolerance scale of a Monte-Carlo run. Deviations are drawn uniformly within ±(scale ×
/// tolerance), independently; the exact motion is recomputed and compared with the linear one.
struct MonteCarloScale {
  double scale = 1.0;
  double max_linear = 0.0;          ///< max |ΔS_linear| over samples and angles (mm or rad)
  double max_exact = 0.0;           ///< max |ΔS_exact|
  double max_difference = 0.0;      ///< max |ΔS_exact − ΔS_linear|
  double at_cam_angle_rad = 0.0;    ///< where max_difference occurred
  double relative_difference = 0.0; ///< max_difference / max_linear
  double bound_exceed = 0.0;        ///< max (|ΔS_exact| − ΔS_wor(θ)) (≤ 0 when the bound holds)
  double within_bound_fraction = 0.0;  ///< fraction of samples with |ΔS_exact| ≤ ΔS_wor everywhere
  double sample_rms = 0.0;          ///< RMS of ΔS_exact over samples at the angle of max RMS bound
  double predicted_rms = 0.0;       ///< the linear model's RMS for uniform deviations there
};

/// @param tolerances the ± tolerances (mm). @pre the cam has no undercut.
std::vector<MonteCarloScale> MonteCarloLinearisation(const DiscCam& cam,
                                                     const Deviations<double>& tolerances,
                                                     const MonteCarloOptions& options);

}  // namespace camopt::disc_cam
