// Geometric limits of a one-tooth-difference cycloid stage, as margins (>= 0 feasible) for sizing.
// Closed forms of the epitrochoid in docs/cycloid.md and the cycloid load-distribution paper,
// eqs. (1)–(4); derivations in docs/cycloid.md, "Geometric limits for sizing".
//
// Notation (as in tooth_profile.h): N = n1 = z + 1 rollers (pins) on the radius a, roller radius ρ,
// eccentricity e, z = n2 teeth. The tooth is generated with a' = a + Δa and ρ' = ρ + Δρ (eqs. 3–4):
// in the disc frame the generating circle's centre traces the curtate epitrochoid
//     X(φ) = a' u(φ) − e u(Nφ)
// and the tooth is its inner offset by ρ'. With λ = e N / a' (the paper's K1) and ψ = (N − 1) φ,
// the curvature of X is
//     κ(ψ) = (1/a') · (1 + N λ² − (N + 1) λ cos ψ) / (1 + λ² − 2 λ cos ψ)^{3/2}.         (C1)
// dκ/d(cos ψ) has the sign of a linear, decreasing function of cos ψ, so the largest curvature (the
// smallest convex radius) sits at
//     cos ψ* = ((2N − 1) λ² − (N − 2)) / ((N + 1) λ),                                  (C2)
// clamped to [−1, 1]. cos ψ* > −1 exactly when λ > λ_s = (N − 2)/(2N − 1), and cos ψ* < 1 for
// every 0 < λ < 1. Substituting (C2) into (C1), the smallest convex radius of X is
//     ρ_min = a' √(27 (N − 1)(1 − λ²) / (N + 1)³)       for λ_s < λ < 1 (flank),        (C3)
//     ρ_min = a' (1 + λ)² / (1 + N λ)                   for λ <= λ_s (tooth tip, ψ = π). (C4)
// The two agree in value and first derivative at λ_s (there cos ψ* = −1 and dκ/d(cos ψ) = 0), so
// the margins are C¹ in the design. No search over φ is needed, so there is no maximiser to freeze for the
// envelope theorem: the Jet derivative of (C3)/(C4) is exact.
//
// Every function is a template over the scalar T (double or ceres::Jet) and throws
// std::invalid_argument for a design that is not a drive (see CheckLimitInputs).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "model/common/scalar.h"
#include "model/cycloid/tooth_profile.h"

namespace camopt::cycloid {

/// Throws std::invalid_argument unless the design is a one-tooth-difference drive whose limits
/// are defined: z = teeth >= 2, rollers = z + 1, e > 0, a > 0, ρ > 0, a' = a + Δa > 0,
/// ρ' = ρ + Δρ > 0 (values, all finite).
/// @tparam T double or ceres::Jet (only the values are checked).
template <typename T>
void CheckLimitInputs(const DriveTpl<T>& d) {
  auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  const double a = Value(d.roller_position_radius_mm), rho = Value(d.roller_radius_mm);
  const double e = Value(d.eccentricity_mm);
  if (d.teeth < 2)
    throw std::invalid_argument("cycloid limits: the disc needs at least 2 teeth (z = " +
                                std::to_string(d.teeth) + ")");
  if (d.rollers != d.teeth + 1)
    throw std::invalid_argument("cycloid limits: rollers must be teeth + 1 (got " +
                                std::to_string(d.rollers) + " rollers, " +
                                std::to_string(d.teeth) + " teeth)");
  if (!positive(e))
    throw std::invalid_argument("cycloid limits: eccentricity_mm must be > 0 (got " +
                                std::to_string(e) + ")");
  if (!positive(a))
    throw std::invalid_argument("cycloid limits: roller_position_radius_mm must be > 0 (got " +
                                std::to_string(a) + ")");
  if (!positive(rho))
    throw std::invalid_argument("cycloid limits: roller_radius_mm must be > 0 (got " +
                                std::to_string(rho) + ")");
  if (!positive(a + Value(d.delta_position_mm)))
    throw std::invalid_argument(
        "cycloid limits: the modified roller position a + delta_a must be > 0");
  if (!positive(rho + Value(d.delta_radius_mm)))
    throw std::invalid_argument(
        "cycloid limits: the modified roller radius rho + delta_rho must be > 0");
}

/// λ = e N / a' (the paper's K1), dimensionless. @pre CheckLimitInputs(d) passes.
template <typename T>
T GeneratingRatio(const DriveTpl<T>& d) {
  return d.eccentricity_mm * T(double(d.rollers)) /
         (d.roller_position_radius_mm + d.delta_position_mm);
}

/// Curtate margin 1 − e N / a' (dimensionless, >= 0 feasible): the generating curve X has no loop
/// when λ = e N / a' < 1 (docs/cycloid.md). With Δa = 0 this is 1 − e (z + 1) / a; with Δa it is
/// the condition on the curve that generates the tooth, as in CheckDrive.
/// @tparam T double or ceres::Jet. @throws std::invalid_argument see CheckLimitInputs.
template <typename T>
T CurtateMargin(const DriveTpl<T>& d) {
  CheckLimitInputs(d);
  return T(1.0) - GeneratingRatio(d);
}

/// Signed curvature of the generating curve X(φ) = a' u(φ) − e u(Nφ) at φ [rad], closed form
/// (C1) [1/mm], > 0 where X is convex. Equals ToothProfile(d, φ).centre_curvature.
/// @tparam T double or ceres::Jet. @throws std::invalid_argument see CheckLimitInputs.
template <typename T>
T CentreCurvature(const DriveTpl<T>& d, const T& phi) {
  using std::cos;
  using std::pow;
  CheckLimitInputs(d);
  const T a = d.roller_position_radius_mm + d.delta_position_mm;
  const T lambda = GeneratingRatio(d);
  const double n = d.rollers;
  const T c = cos(T(n - 1.0) * phi);
  const T num = T(1.0) + T(n) * lambda * lambda - T(n + 1.0) * lambda * c;
  const T den = T(1.0) + lambda * lambda - T(2.0) * lambda * c;
  return num / (a * pow(den, 1.5));
}

/// cos ψ* of the sharpest convex point of X, (C2) clamped to [−1, 1]; ψ* = (N − 1) φ*.
/// @tparam T double or ceres::Jet. @throws std::invalid_argument see CheckLimitInputs.
template <typename T>
T CosAtMinConvexRadius(const DriveTpl<T>& d) {
  CheckLimitInputs(d);
  const T lambda = GeneratingRatio(d);
  const double n = d.rollers;
  const T c = (T(2.0 * n - 1.0) * lambda * lambda - T(n - 2.0)) / (T(n + 1.0) * lambda);
  return IfThenElse(Compare::kLess, c, -1.0, T(-1.0),
                    IfThenElse(Compare::kGreater, c, 1.0, T(1.0), c));
}

/// Curve parameter φ* in [0, π/(N − 1)] [rad] of the sharpest convex point of X (one of the
/// 2(N − 1) symmetric copies per turn): φ* = arccos(cos ψ*) / (N − 1).
/// At the clamped ends the phase is a constant (π/(N − 1) at the tip, 0 past the curtate limit);
/// acos is taken only strictly inside, where its derivative is finite.
template <typename T>
T PhaseAtMinConvexRadius(const DriveTpl<T>& d) {
  using std::acos;
  const T c = CosAtMinConvexRadius(d);
  const double n = d.rollers;
  const T c_inside = IfThenElse(Compare::kLess, std::abs(Value(c)), 1.0, c, T(0.0));
  const T inside = acos(c_inside) / T(n - 1.0);
  return IfThenElse(Compare::kLessEqual, c, -1.0, T(kPi / (n - 1.0)),
                    IfThenElse(Compare::kGreaterEqual, c, 1.0, T(0.0), inside));
}

/// Smallest convex radius of curvature of the generating (roller-centre) curve X [mm]:
/// (C3) on the flank for λ_s < λ < 1, (C4) at the tooth tip for λ <= λ_s, λ_s = (N − 2)/(2N − 1).
/// Tends to 0 as λ → 1 (the cusp at the curtate limit). Past it (λ >= 1, CurtateMargin < 0) X has
/// loops and this returns the radius inside the loop, a' (λ − 1)² / (N λ − 1) (ψ = 0); the tooth is
/// then unusable whatever this says, so read it together with CurtateMargin.
/// @tparam T double or ceres::Jet. @throws std::invalid_argument see CheckLimitInputs.
template <typename T>
T MinConvexCentreRadius(const DriveTpl<T>& d) {
  using std::sqrt;
  CheckLimitInputs(d);
  const T a = d.roller_position_radius_mm + d.delta_position_mm;
  const T lambda = GeneratingRatio(d);
  const double n = d.rollers;
  const double lambda_s = (n - 2.0) / (2.0 * n - 1.0);
  const T tip = a * (T(1.0) + lambda) * (T(1.0) + lambda) / (T(1.0) + T(n) * lambda);
  const T loop = a * (lambda - T(1.0)) * (lambda - T(1.0)) / (T(n) * lambda - T(1.0));
  // (C3) is used only for λ < 1; past that its radicand is set to 0 (and the value discarded)
  // rather than going negative.
  const T one_minus_l2 =
      IfThenElse(Compare::kLess, lambda, 1.0, T(1.0) - lambda * lambda, T(0.0));
  const T flank = a * sqrt(T(27.0 * (n - 1.0) / ((n + 1.0) * (n + 1.0) * (n + 1.0))) *
                           one_minus_l2);
  return IfThenElse(Compare::kLessEqual, lambda, lambda_s, tip,
                    IfThenElse(Compare::kLess, lambda, 1.0, flank, loop));
}

/// Smallest convex radius of the tooth profile itself [mm]: the profile is the inner offset of X
/// by ρ', so its radius is ρ_min − ρ' (docs/cycloid.md). Published case (18 pins, 17 lobes,
/// a = 42.5 mm, e = 1.3 mm, ρ = 2.5 mm): 6.678 mm.
/// @tparam T double or ceres::Jet. @throws std::invalid_argument see CheckLimitInputs.
template <typename T>
T MinConvexProfileRadius(const DriveTpl<T>& d) {
  return MinConvexCentreRadius(d) - (d.roller_radius_mm + d.delta_radius_mm);
}

/// Undercut margin ρ_min − ρ' − min_profile_radius_mm [mm], >= 0 feasible: the tooth is not
/// undercut while every convex radius of X exceeds the generating radius ρ' (docs/cycloid.md);
/// min_profile_radius_mm > 0 asks for a blunter tooth than that. Meaningful with CurtateMargin > 0.
/// @tparam T double or ceres::Jet. @throws std::invalid_argument see CheckLimitInputs.
template <typename T>
T UndercutMargin(const DriveTpl<T>& d, double min_profile_radius_mm = 0.0) {
  return MinConvexProfileRadius(d) - T(min_profile_radius_mm);
}

/// Pin gap margin 2 a sin(π/N) − 2ρ − min_gap_mm [mm], >= 0 feasible: neighbouring rollers, on
/// the pin circle a at the pitch angle 2π/N, clear each other by at least min_gap_mm
/// (docs/cycloid.md). The rollers are the unmodified ones (a, ρ): Δa, Δρ only shape the tooth.
/// @tparam T double or ceres::Jet. @throws std::invalid_argument see CheckLimitInputs.
template <typename T>
T PinGapMargin(const DriveTpl<T>& d, double min_gap_mm = 0.0) {
  CheckLimitInputs(d);
  return T(2.0 * std::sin(kPi / d.rollers)) * d.roller_position_radius_mm -
         T(2.0) * d.roller_radius_mm - T(min_gap_mm);
}

/// Root radius of the tooth profile, min over φ of |P(φ)| = a' − e − ρ' [mm]. Exact: the profile
/// point is P = X − ρ' N̂ with |N̂| = 1, and |X| >= a' − e (triangle inequality), so
/// |P| >= |X| − ρ' >= a' − e − ρ', with equality at φ = 0 where X = (a' − e, 0) and N̂ is radial.
/// @tparam T double or ceres::Jet. @throws std::invalid_argument see CheckLimitInputs.
template <typename T>
T RootRadius(const DriveTpl<T>& d) {
  CheckLimitInputs(d);
  return d.roller_position_radius_mm + d.delta_position_mm - d.eccentricity_mm -
         (d.roller_radius_mm + d.delta_radius_mm);
}

/// Web margin (a' − e − ρ') − bore_radius_mm − min_web_mm [mm], >= 0 feasible: the disc's ring of
/// material between its central bore (the eccentric bearing seat) and the tooth roots is at least
/// min_web_mm thick. Output-pin holes in the web are not counted.
/// @param bore_radius_mm radius of the disc's central bore [mm] (may be a design variable).
/// @tparam T double or ceres::Jet. @throws std::invalid_argument see CheckLimitInputs.
template <typename T>
T WebMargin(const DriveTpl<T>& d, const T& bore_radius_mm, double min_web_mm) {
  return RootRadius(d) - bore_radius_mm - T(min_web_mm);
}

}  // namespace camopt::cycloid
