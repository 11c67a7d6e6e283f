// See contact_fatigue_input.h.
#include "studies/contact_fatigue_input.h"

#include <cmath>

#include "model/contact/subsurface.h"

namespace camopt::studies {

std::optional<ContactFatigueSpec> ParseContactFatigue(const Node& material) {
  if (!material.Has("contact_fatigue")) return std::nullopt;
  return Read<ContactFatigueInput>(material["contact_fatigue"]).ToSpec();
}

SubsurfaceOut SubsurfaceOf(double p0_MPa, double b_mm, double nu, const std::string& basis) {
  if (!std::isfinite(p0_MPa)) return nullptr;
  if (!(p0_MPa > 0 && b_mm > 0)) return NoSubsurface{};
  const contact::LineSubsurfaceMaxima<double> m = contact::LineContactSubsurfaceMaxima(p0_MPa, b_mm, nu);
  SubsurfaceBlock j;
  j.peak_pressure_MPa = p0_MPa;
  j.half_width_mm = b_mm;
  j.max_shear_MPa = m.max_shear.value;
  j.max_shear_depth_mm = m.max_shear.depth;
  j.max_orthogonal_shear_MPa = m.max_orthogonal_shear.value;
  j.max_orthogonal_shear_depth_mm = m.max_orthogonal_shear.depth;
  j.max_orthogonal_shear_offset_mm = std::abs(m.max_orthogonal_shear.x);
  j.max_von_mises_MPa = m.max_von_mises.value;
  j.max_von_mises_depth_mm = m.max_von_mises.depth;
  j.poisson_ratio = nu;
  j.basis = basis;
  return j;
}

}  // namespace camopt::studies
