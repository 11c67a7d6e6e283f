// Reading an elastic material from a study: the one parser every study kind uses.
#pragma once

#include "model/common/material.h"
#include <optional>

#include "studies/archive.h"
#include "studies/contact_fatigue_input.h"
#include "studies/input.h"

namespace camopt::studies {

/// An elastic material as the study file gives it, declared once (studies/archive.h).
struct MaterialInput {
  double youngs_modulus_GPa = 0, poisson_ratio = 0;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("youngs_modulus_GPa", &youngs_modulus_GPa,
             Field()
                 .Required()
                 .In(1e-3, 1e6, "a modulus in [0.001, 1e6] GPa (steel: 206; 0.001 GPa is a soft elastomer)")
                 .Unit("GPa")
                 .Desc("Young's modulus E (steel: 206); from a soft elastomer's 0.001 to 1e6 (beyond, the "
                       "contact solvers cannot converge or overflow)"));
    a->Visit("poisson_ratio", &poisson_ratio, Field().Required().In(0.0, 0.4999).Desc("Poisson's ratio"));
  }
  /// E in MPa, as the models take it.
  Material ToMaterial() const {
    Material m;
    m.youngs_modulus_MPa = youngs_modulus_GPa * 1000.0;
    m.poisson_ratio = poisson_ratio;
    return m;
  }
};

/// A cam's material with its optional S-N point of rolling-contact fatigue (docs/life.md, "Contact
/// life of the cam surfaces"): the LCR kinds' "material".
struct MaterialWithFatigueInput : MaterialInput {
  std::optional<ContactFatigueInput> contact_fatigue;
  template <typename Archive>
  void Serialize(Archive* a) {
    MaterialInput::Serialize(a);
    a->Visit("contact_fatigue", &contact_fatigue,
             Field().Desc("the material's S-N point of rolling-contact fatigue: N = reference_cycles "
                          "(reference_pressure_MPa/p0)^exponent over-rollings of a point at peak Hertz pressure p0 "
                          "to 10% failure (docs/life.md, 'Contact life of the cam surfaces'); needs a speed"));
  }
};

/// {"youngs_modulus_GPa": E in [1e-3, 1e6], "poisson_ratio": ν in [0, 0.4999]} → Material (E in MPa).
/// Other members are left to the caller (a material object may carry fields of other models,
/// e.g. a shear modulus), so the caller checks the known fields.
Material ParseMaterial(const Node& material);

}  // namespace camopt::studies
