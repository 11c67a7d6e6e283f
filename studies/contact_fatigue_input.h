// Contact fatigue in the study files (docs/life.md, "Contact fatigue of the cam surfaces"): the
// material's optional S–N point of rolling-contact fatigue, and the result.json block of the
// subsurface stresses under a cam's peak Hertz contact, shared by the study kinds.
#pragma once

#include <optional>
#include <string>
#include <variant>

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
/// contact, or the worst slice of a finite-length one) of a material of Poisson's ratio nu
/// (Johnson 1985, eq. 4.50 ff.): Tresca's τ1, Lundberg–Palmgren's τ0 and the von Mises stress,
/// each with its depth below the surface, and `basis`, the sentence that says which contact these
/// are of.
struct SubsurfaceBlock {
  double peak_pressure_MPa = 0, half_width_mm = 0, max_shear_MPa = 0, max_shear_depth_mm = 0,
         max_orthogonal_shear_MPa = 0, max_orthogonal_shear_depth_mm = 0, max_orthogonal_shear_offset_mm = 0,
         max_von_mises_MPa = 0, max_von_mises_depth_mm = 0, poisson_ratio = 0;
  std::string basis;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("peak_pressure_MPa", &peak_pressure_MPa, Field().Unit("MPa").Desc("p0"));
    a->Visit("half_width_mm", &half_width_mm, Field().Unit("mm").Desc("b of the line contact"));
    a->Visit("max_shear_MPa", &max_shear_MPa, Field().Unit("MPa").Desc("Tresca's largest shear τ1 below the surface"));
    a->Visit("max_shear_depth_mm", &max_shear_depth_mm, Field().Unit("mm").Desc("its depth"));
    a->Visit("max_orthogonal_shear_MPa", &max_orthogonal_shear_MPa,
             Field().Unit("MPa").Desc("Lundberg–Palmgren's orthogonal shear amplitude τ0"));
    a->Visit("max_orthogonal_shear_depth_mm", &max_orthogonal_shear_depth_mm, Field().Unit("mm").Desc("its depth"));
    a->Visit("max_orthogonal_shear_offset_mm", &max_orthogonal_shear_offset_mm,
             Field().Unit("mm").Desc("its distance from the contact's centre line"));
    a->Visit("max_von_mises_MPa", &max_von_mises_MPa, Field().Unit("MPa").Desc("the largest von Mises stress"));
    a->Visit("max_von_mises_depth_mm", &max_von_mises_depth_mm, Field().Unit("mm").Desc("its depth"));
    a->Visit("poisson_ratio", &poisson_ratio, Field().Desc("the material's ν"));
    a->Visit("basis", &basis, Field().Desc("which contact these are of"));
  }
};
/// A contact with no load: the empty object {}.
struct NoSubsurface {
  template <typename Archive>
  void Serialize(Archive*) {}
};
/// The subsurface stresses, {} when p0 is 0, null when p0 is not finite (an undercut contact).
using SubsurfaceOut = std::variant<SubsurfaceBlock, NoSubsurface, std::nullptr_t>;
SubsurfaceOut SubsurfaceOf(double p0_MPa, double b_mm, double nu, const std::string& basis);

}  // namespace camopt::studies
