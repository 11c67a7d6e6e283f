#include "studies/material_input.h"

namespace camopt::studies {

Material ParseMaterial(const Node& node) {
  Material m;
  m.youngs_modulus_MPa = node["youngs_modulus_GPa"].Positive() * 1000.0;
  m.poisson_ratio = node["poisson_ratio"].NumberIn(0.0, 0.4999);
  return m;
}

}  // namespace camopt::studies
