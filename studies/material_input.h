// Reading an elastic material from a study: the one parser every study kind uses.
#pragma once

#include "model/common/material.h"
#include "studies/archive.h"
#include "studies/input.h"

namespace camopt::studies {

/// An elastic material as the study file gives it, declared once (studies/archive.h).
struct MaterialInput {
  double youngs_modulus_GPa = 0, poisson_ratio = 0;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("youngs_modulus_GPa", &youngs_modulus_GPa,
             Field().Required().Positive().Unit("GPa").Desc("Young's modulus E (steel: 206)"));
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

/// {"youngs_modulus_GPa": E > 0, "poisson_ratio": ν in [0, 0.4999]} → Material (E in MPa).
/// Other members are left to the caller (a material object may carry fields of other models,
/// e.g. a shear modulus), so the caller checks the known fields.
Material ParseMaterial(const Node& material);

}  // namespace camopt::studies
