// Reading an elastic material from a study: the one parser every study kind uses.
#pragma once

#include "model/common/material.h"
#include "studies/input.h"

namespace camopt::studies {

/// {"youngs_modulus_GPa": E > 0, "poisson_ratio": ν in [0, 0.4999]} → Material (E in MPa).
/// Other members are left to the caller (a material object may carry fields of other models,
/// e.g. a shear modulus), so the caller checks the known fields.
Material ParseMaterial(const Node& material);

}  // namespace camopt::studies
