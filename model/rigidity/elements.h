// Rigidity of transmission elements: closed forms of the transmission-rigidity paper
// (docs/papers.md §4, docs/rigidity.md) plus two textbook beam cases, over the scalar T.
//
// Units: lengths mm, forces N, moduli MPa (N/mm²). A linear stiffness is in N/mm, a torsional
// rigidity in N·mm/rad (divide by 1000 for N·m/rad). "Rigidity" is angular, "stiffness" linear,
// as in the paper.
#pragma once

#include <cmath>

#include "model/common/scalar.h"

namespace camopt::rigidity {

/// Polar second moment of a hollow circular section, π(D⁴ − d⁴)/32 [mm⁴].
template <typename T>
T PolarMoment(const T& outer_d, const T& inner_d) {
  return T(kPi) * (outer_d * outer_d * outer_d * outer_d - inner_d * inner_d * inner_d * inner_d) /
         T(32.0);
}

/// Bending second moment of a hollow circular section, J = π(D⁴ − d⁴)/64 [mm⁴] (paper, eq. 8).
template <typename T>
T BendingMoment(const T& outer_d, const T& inner_d) {
  return PolarMoment(outer_d, inner_d) / T(2.0);
}

/// Torsional rigidity of a (hollow) circular shaft, R = π G (D⁴ − d⁴) / (32 L) (paper, eq. 1).
/// @param shear_modulus G [MPa]; diameters and length [mm]. Returns N·mm/rad.
template <typename T>
T ShaftTorsionRigidity(const T& shear_modulus, const T& outer_d, const T& inner_d,
                       const T& length) {
  return shear_modulus * PolarMoment(outer_d, inner_d) / length;
}

/// Torsional rigidity of a linear stiffness S acting tangentially at radius r: R = S r²
/// (paper, eqs. 3–5; the same for gear teeth, chains, belts, pull-rods, levers and shaft bending,
/// independent of the pressure angle, eq. 7). S [N/mm], r [mm]; returns N·mm/rad.
template <typename T>
T RigidityFromLinear(const T& stiffness, const T& radius) {
  return stiffness * radius * radius;
}

/// The linear stiffness at radius r of a torsional compliance c (eq. 5 transposed, S = R / r²
/// with R = 1/c): 1/(c r²). c [rad/(N·mm)], r [mm] -> N/mm.
template <typename T>
T LinearStiffnessAtRadius(const T& compliance, const T& radius) {
  return T(1.0) / (compliance * radius * radius);
}

/// Lateral stiffness at a load point of a simply supported shaft of constant section,
/// S = 3 E J L / (l₁² l₂²), L = l₁ + l₂ (paper, eq. 8). E [MPa], J [mm⁴], l₁, l₂ [mm] -> N/mm.
template <typename T>
T SimplySupportedStiffness(const T& youngs_modulus, const T& j, const T& l1, const T& l2) {
  return T(3.0) * youngs_modulus * j * (l1 + l2) / (l1 * l1 * l2 * l2);
}

/// Lateral stiffness at the tip of an overhang a beyond a bearing span L (load outside the
/// supports, constant section): δ/F = a² (L + a) / (3 E J) (Roark, beam with overhang, the tip
/// deflection under an end load). Not in the paper, which treats only loads between bearings.
template <typename T>
T OverhungStiffness(const T& youngs_modulus, const T& j, const T& span, const T& overhang) {
  return T(3.0) * youngs_modulus * j / (overhang * overhang * (span + overhang));
}

/// Tip stiffness of a cantilever of length L and second moment I: S = 3 E I / L³.
template <typename T>
T CantileverStiffness(const T& youngs_modulus, const T& i, const T& length) {
  return T(3.0) * youngs_modulus * i / (length * length * length);
}

/// Axial stiffness of a bar in tension or compression, S = E A / L (pull- or push-rod).
/// A is the (hollow) circular section π(D² − d²)/4.
template <typename T>
T RodStiffness(const T& youngs_modulus, const T& outer_d, const T& inner_d, const T& length) {
  const T area = T(kPi) * (outer_d * outer_d - inner_d * inner_d) / T(4.0);
  return youngs_modulus * area / length;
}

/// Stiffness of a loaded chain or belt span: inversely proportional to its length (paper,
/// "Chains and Belts"). stiffness_ref [N/mm] is the stiffness of a span of length ref_length.
template <typename T>
T SpanStiffness(const T& stiffness_ref, const T& ref_length, const T& span_length) {
  return stiffness_ref * ref_length / span_length;
}

}  // namespace camopt::rigidity
