// The kinds of element a transmission chain is built from, each a named parameter vector and
// one templated evaluation to a Link (its compliance, backlash and ratio on its own shaft).
//
// Keeping the parameters as a flat vector lets one generic routine differentiate the chain's
// rigidity with respect to every dimension of every element (ceres::Jet), which is how the
// design advice ("which dimension to change, and by how much it pays") is made automatic.
// Units as in elements.h: mm, N, MPa; rigidity N·mm/rad; backlash rad.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <ceres/jet.h>

#include "model/rigidity/chain.h"
#include "model/rigidity/elements.h"

namespace camopt::rigidity {

enum class ElementKind {
  kShaftTorsion,     ///< [G, D, d, L]
  kShaftBending,     ///< [E, D, d, l1, l2, r]: load between bearings (eq. 8 with R = S r²)
  kShaftOverhung,    ///< [E, D, d, span, overhang, r]: load on an overhang
  kLinearStiffness,  ///< [S, r]
  kSpan,             ///< [S_ref, L_ref, L_span, r]: chain or belt span
  kPullRod,          ///< [E, D, d, L, r]
  kLeverSection,     ///< [E, width, height, length]: rectangular cantilever lever, R = S L²
  kLeverStiffness,   ///< [S_tip, length]
  kCoupling,         ///< [R] given rigidity, or [] for a rigid coupling
  kGearStage,        ///< [N], [N, R_mesh] or [N, S_mesh, r_driven]
  kFixed,            ///< [N, R]: a precomputed element (e.g. a reducer) with its ratio
};

struct ElementSpec {
  ElementKind kind;
  std::string kind_name;                ///< as written in a study ("shaft_torsion", ...)
  std::string name;                     ///< the user's label
  std::vector<std::string> param_names; ///< with units, e.g. "outer_diameter_mm"
  std::vector<double> params;           ///< in model units (MPa, mm, N/mm, N·mm/rad)
  double backlash_rad = 0.0;            ///< on the element's own (driven-side) shaft
};

/// Evaluates one element at parameters p (same layout as spec.params).
template <typename T>
Link<T> EvaluateElement(const ElementSpec& spec, const std::vector<T>& p) {
  Link<T> l;
  l.backlash = T(spec.backlash_rad);
  auto rigidity_to_compliance = [](const T& r) { return T(1.0) / r; };
  switch (spec.kind) {
    case ElementKind::kShaftTorsion:
      l.compliance = rigidity_to_compliance(ShaftTorsionRigidity(p[0], p[1], p[2], p[3]));
      break;
    case ElementKind::kShaftBending:
      l.compliance = rigidity_to_compliance(RigidityFromLinear(
          SimplySupportedStiffness(p[0], BendingMoment(p[1], p[2]), p[3], p[4]), p[5]));
      break;
    case ElementKind::kShaftOverhung:
      l.compliance = rigidity_to_compliance(RigidityFromLinear(
          OverhungStiffness(p[0], BendingMoment(p[1], p[2]), p[3], p[4]), p[5]));
      break;
    case ElementKind::kLinearStiffness:
      l.compliance = rigidity_to_compliance(RigidityFromLinear(p[0], p[1]));
      break;
    case ElementKind::kSpan:
      l.compliance = rigidity_to_compliance(RigidityFromLinear(SpanStiffness(p[0], p[1], p[2]), p[3]));
      break;
    case ElementKind::kPullRod:
      l.compliance = rigidity_to_compliance(RigidityFromLinear(RodStiffness(p[0], p[1], p[2], p[3]), p[4]));
      break;
    case ElementKind::kLeverSection: {
      const T i = p[1] * p[2] * p[2] * p[2] / T(12.0);
      l.compliance = rigidity_to_compliance(RigidityFromLinear(CantileverStiffness(p[0], i, p[3]), p[3]));
      break;
    }
    case ElementKind::kLeverStiffness:
      l.compliance = rigidity_to_compliance(RigidityFromLinear(p[0], p[1]));
      break;
    case ElementKind::kCoupling:
      if (!p.empty()) l.compliance = rigidity_to_compliance(p[0]);
      break;
    case ElementKind::kGearStage:
      l.ratio = p[0];
      if (p.size() == 2) l.compliance = rigidity_to_compliance(p[1]);
      if (p.size() == 3) l.compliance = rigidity_to_compliance(RigidityFromLinear(p[1], p[2]));
      break;
    case ElementKind::kFixed:
      l.ratio = p[0];
      l.compliance = rigidity_to_compliance(p[1]);
      break;
  }
  return l;
}

/// The chain of specs at their own parameters.
template <typename T = double>
ChainResult<T> EvaluateChain(const std::vector<ElementSpec>& specs) {
  std::vector<Link<T>> links;
  links.reserve(specs.size());
  for (const ElementSpec& s : specs) {
    std::vector<T> p(s.params.begin(), s.params.end());
    links.push_back(EvaluateElement<T>(s, p));
  }
  return ComposeChain(links);
}

/// ∂ ln R_B / ∂ ln p for every parameter of every element: the percentage change of the overall
/// rigidity per percent change of the parameter. (The same at end A except for gear ratios,
/// since R_A = R_B / N_tot²: a stage's ratio elasticity at A is that at B minus 2.)
/// Result indexed [element][parameter].
inline std::vector<std::vector<double>> RigidityElasticities(const std::vector<ElementSpec>& specs) {
  using J = ceres::Jet<double, 1>;
  std::vector<std::vector<double>> out(specs.size());
  for (size_t k = 0; k < specs.size(); ++k) {
    for (size_t q = 0; q < specs[k].params.size(); ++q) {
      std::vector<Link<J>> links;
      for (size_t m = 0; m < specs.size(); ++m) {
        std::vector<J> p(specs[m].params.begin(), specs[m].params.end());
        if (m == k) p[q].v[0] = 1.0;
        links.push_back(EvaluateElement<J>(specs[m], p));
      }
      const ChainResult<J> r = ComposeChain(links);
      // R = 1/c, so d ln R / d ln p = -(p / c) dc/dp.
      out[k].push_back(0.0 - specs[k].params[q] * r.compliance_b.v[0] / r.compliance_b.a);
    }
  }
  return out;
}

}  // namespace camopt::rigidity
