// Contact fatigue in the study files (docs/life.md, "Contact fatigue of the cam surfaces"): the
// material's optional S–N point of rolling-contact fatigue, and the result.json block of the
// subsurface stresses under a cam's peak Hertz contact, shared by the study kinds.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "studies/archive.h"
#include "studies/input.h"

namespace camopt::studies {

/// "material.contact_fatigue": N = N_ref (p_ref/p0)^n cycles to 10% failure of a contact of the
/// same geometry at peak Hertz pressure p0 (an L10 point of the material's stress-life curve).
struct ContactFatigueSpec {
  double reference_pressure_MPa = 0;  ///< p_ref > 0
  double reference_cycles = 0;        ///< N_ref > 0, over-rollings of a point at p_ref to 10% failure
  double exponent = 8;                ///< n > 0; default 8: Lundberg–Palmgren's line contact
  bool exponent_given = false;
};

/// "material.contact_fatigue" as the study file gives it, declared once (studies/archive.h).
struct ContactFatigueInput {
  double reference_pressure_MPa = 0, reference_cycles = 0;
  std::optional<double> exponent;  ///< absent: 8 (the result says whether it was given)
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("reference_pressure_MPa", &reference_pressure_MPa,
             Field().Required().Positive().Unit("MPa").Desc("p_ref, the peak Hertz pressure of the S-N point"));
    a->Visit("reference_cycles", &reference_cycles,
             Field().Required().Positive().Desc("N_ref, over-rollings of a point to 10% failure at p_ref"));
    a->Visit("exponent", &exponent,
             Field().Positive().Desc("n of N ∝ p0^-n (absent: 8, Lundberg-Palmgren's line contact)"));
  }
  ContactFatigueSpec ToSpec() const {
    ContactFatigueSpec c;
    c.reference_pressure_MPa = reference_pressure_MPa;
    c.reference_cycles = reference_cycles;
    c.exponent_given = exponent.has_value();
    c.exponent = exponent.value_or(8.0);
    return c;
  }
};

/// "contact_fatigue" of a material node, nullopt when absent.
/// {"reference_pressure_MPa" > 0, "reference_cycles" > 0, "exponent" > 0 (optional, 8)}.
/// @throws StudyError (exit 2) naming the path.
std::optional<ContactFatigueSpec> ParseContactFatigue(const Node& material);

/// The "subsurface" object of a contact of peak pressure p0 [MPa] and half-width b [mm] (a line
/// contact, or the worst slice of a finite-length one) of a material of Poisson's ratio nu:
/// peak_pressure_MPa, half_width_mm, max_shear_MPa (Tresca's τ1) and its depth, max_orthogonal_shear_MPa
/// (Lundberg–Palmgren's τ0) with its depth and offset from the contact's centre line,
/// max_von_mises_MPa and its depth (mm below the surface), and `basis`, the sentence that says
/// which contact these are of. Null when p0 is not finite (an undercut contact) and {} when p0 is 0.
nlohmann::json SubsurfaceJson(double p0_MPa, double b_mm, double nu, const std::string& basis);

}  // namespace camopt::studies
