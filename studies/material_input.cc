#include "studies/material_input.h"

namespace camopt::studies {

Material ParseMaterial(const Node& node) {
  MaterialInput in;
  JsonReader reader(node);  // the fields alone: the caller checks the object's known fields
  in.Serialize(&reader);
  return in.ToMaterial();
}

}  // namespace camopt::studies
