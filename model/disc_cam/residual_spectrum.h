// Residual-vibration spectrum of a motion segment: the amplitude of the free vibration a rise leaves
// in a linear one-degree-of-freedom follower when it comes to rest in the following dwell, as a
// function of τ = T/T_n, the segment's duration in time over the follower's natural period (the
// classic cam design chart: Norton, Cam Design and Manufacturing Handbook, ch. 10, the single-DOF
// lumped model and its residual vibration; Koster, Vibrations of Cam Mechanisms (1974), and Rothbart,
// Cam Design Handbook, the chapters on cam system dynamics, plot these spectra for the rest-in-rest
// laws; the closed forms below are derived here from the integral, not copied).
//
// Model (base-excited single-DOF, damping on the relative motion): the cam imposes y(t), the
// follower's mass moves x, z = x − y:
//   z̈ + 2ζω_n ż + ω_n² z = −ÿ(t),   z(0) = ż(0) = 0 (at rest in the dwell before the segment).
// After the segment (t ≥ T, y constant) the follower rings freely, z = C e^{−ζω_n t} sin(ω_d t + φ),
// ω_d = ω_n √(1 − ζ²). The residual amplitude is the envelope at the segment's end,
// A = C e^{−ζω_n T} = √(z_T² + ((ż_T + ζω_n z_T)/ω_d)²) (for ζ = 0 the amplitude of the ringing).
// Duhamel's integral gives it exactly as a Fourier–Laplace transform of the segment's acceleration;
// with y = h N(u), u = t/T, ω_n T = 2πτ and c = 2πτ(−ζ + i√(1 − ζ²)), after one integration by parts
// (which also takes in the velocity steps of a segment that does not start or end at rest, as
// impulses of ÿ between the dwells),
//   A/|h| = e^{−2πζτ} |∫₀¹ N'(u) e^{−c u} du| / √(1 − ζ²).
// Closed forms (derived from this integral with N' of the law):
//   cycloidal (N' = 1 − cos 2πu), ζ = 0:       A/h = |sin πτ| / (πτ |τ² − 1|)   (1/2 at τ = 1; zeros at τ = 2, 3, …)
//   simple harmonic (N' = (π/2) sin πu), ζ = 0: A/h = |cos πτ| / |4τ² − 1|     (π/4 at τ = 1/2; zeros at τ = 3/2, 5/2, …)
// For the 1-DOF follower of model/disc_cam/follower_dynamics.h (k_f in series with the mass, return
// spring k_s), the deflection from the static position x_s = (k_f S − F)/(k_f + k_s) obeys the same
// equation with ÿ scaled by r = k_f/(k_f + k_s) (exactly when ζ = 0; with ζ > 0 the damper adds a term
// (1 − r) c Ṡ), so the residual vibration there is r |h| A/h at ω_n = √((k_f + k_s)/m).
//
// The integral is evaluated by adaptive Gauss–Kronrod (7–15) quadrature on the complex integrand
// (any MotionSegment: named laws, polynomials, B-splines; kinks of N' are isolated by bisection).
#pragma once

#include <vector>

#include "model/motion/motion_program.h"

namespace camopt::disc_cam {

/// A residual amplitude A/|h| and the quadrature's error estimate on it (Σ |K15 − G7| over the
/// accepted intervals, an upper estimate of the error of the Kronrod sum).
struct ResidualAmplitude {
  double amplitude = 0.0;
  double error = 0.0;
};

/// A/|h| at one ratio τ = T/T_n > 0 for damping ratio 0 <= zeta < 1, to an absolute error of about
/// `tolerance` on A/|h|. @throws std::invalid_argument for a dwell (or zero rise), τ <= 0, ζ outside
/// [0, 1), or a segment of zero duration; std::runtime_error when the quadrature cannot reach the
/// tolerance.
ResidualAmplitude ResidualAmplitudeAt(const motion::MotionSegment<double>& seg, double zeta, double tau,
                                      double tolerance = 1e-11);

/// The spectrum: A/|h| at each τ of `tau` (ResidualAmplitudeAt with its default tolerance).
std::vector<double> ResidualSpectrum(const motion::MotionSegment<double>& seg, double zeta,
                                     const std::vector<double>& tau);

/// A local minimum of the spectrum (a zero when its amplitude is within the quadrature's error of 0).
struct SpectrumMinimum {
  double tau = 0.0;
  double amplitude = 0.0;
  bool zero = false;  ///< amplitude <= zero_tolerance
};

/// The local minima of A/|h| over [tau_lo, tau_hi]: bracketed on `samples` equally spaced τ and
/// refined by golden section to a τ-width of 1e-10 (tau_hi − tau_lo); `zero` when the minimum is
/// below zero_tolerance. Minima at the ends of the range are not reported.
std::vector<SpectrumMinimum> ResidualSpectrumMinima(const motion::MotionSegment<double>& seg, double zeta,
                                                    double tau_lo, double tau_hi, int samples,
                                                    double zero_tolerance = 1e-7);

}  // namespace camopt::disc_cam
