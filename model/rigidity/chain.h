// A transmission as a series chain of compliant elements and gear stages
// (the transmission-rigidity paper, docs/papers.md §4, eqs. 2 and 6; docs/rigidity.md).
//
// The chain runs from end A (e.g. the motor) to end B (e.g. the cam or the payload). Every link
// sits on one shaft and has a compliance (1/rigidity, rad per N·mm) and a backlash (rad) measured
// on that shaft. A gear stage of ratio N = ω_before/ω_after (N > 1: reduction towards B) changes
// the shaft: its own compliance and backlash are measured on its driven (B-side) shaft, and
// everything before it is carried to its driven shaft by
//   compliance / N²  (eq. 6: the rigidity 'transmitted' by gearing is multiplied by the ratio
//                     squared, so a reduction raises it and a step-up lowers it),
//   backlash / N     (the paper: "the backlash transmitted by gearing is directly proportional
//                     to the gear ratio", Z_i/Z_o per stage).
// The whole chain seen from end A is the same chain seen from B with every stage undone:
//   compliance_A = compliance_B · N_tot²,  backlash_A = backlash_B · N_tot.
#pragma once

#include <vector>

#include "model/common/scalar.h"

namespace camopt::rigidity {

/// One element of a chain, as seen on its own (driven-side) shaft.
template <typename T>
struct Link {
  T compliance = T(0.0);  ///< 1/rigidity [rad/(N·mm)]; 0 for a rigid element
  T backlash = T(0.0);    ///< lost motion [rad] on its own shaft
  T ratio = T(1.0);       ///< ω_before / ω_after; 1 for anything but a gear stage
};

template <typename T>
struct ChainResult {
  T compliance_b;                       ///< total compliance seen at end B [rad/(N·mm)]
  T compliance_a;                       ///< total compliance seen at end A
  T backlash_b;                         ///< total backlash seen at end B [rad]
  T backlash_a;                         ///< total backlash seen at end A [rad]
  T total_ratio;                        ///< N_tot = ω_A / ω_B
  std::vector<T> compliance_at_b;       ///< each link's compliance referred to end B
  std::vector<T> share;                 ///< each link's share of the total compliance
  std::vector<T> backlash_at_b;         ///< each link's backlash referred to end B [rad]
  /// The total compliance at end B had link i been rigid (the paper's remark on the stepped
  /// shaft: what ignoring an element would have predicted).
  std::vector<T> compliance_b_if_rigid;
  int dominant = -1;                    ///< index of the link with the largest share
};

/// Combines links in series (eq. 2) through the gear stages among them (eq. 6).
/// @pre every ratio > 0, every compliance and backlash >= 0, at least one link.
template <typename T>
ChainResult<T> ComposeChain(const std::vector<Link<T>>& links) {
  const size_t n = links.size();
  ChainResult<T> r;
  r.compliance_at_b.resize(n);
  r.backlash_at_b.resize(n);
  r.share.resize(n);
  r.compliance_b_if_rigid.resize(n);
  // Walk from end B towards A, carrying the product of the ratios of the stages passed.
  T scale(1.0);  // Π N_j over stages after link k
  r.compliance_b = T(0.0);
  r.backlash_b = T(0.0);
  for (size_t i = n; i-- > 0;) {
    const Link<T>& l = links[i];
    // A stage's own compliance and backlash sit on its driven shaft: after its own ratio.
    r.compliance_at_b[i] = l.compliance / (scale * scale);
    r.backlash_at_b[i] = l.backlash / scale;
    r.compliance_b += r.compliance_at_b[i];
    r.backlash_b += r.backlash_at_b[i];
    scale *= l.ratio;
  }
  r.total_ratio = scale;
  r.compliance_a = r.compliance_b * scale * scale;
  r.backlash_a = r.backlash_b * scale;
  double best = -1.0;
  for (size_t i = 0; i < n; ++i) {
    r.compliance_b_if_rigid[i] = r.compliance_b - r.compliance_at_b[i];
    // A chain of rigid links only has zero compliance: every share is then 0 (a value branch on a
    // degenerate case, where a share is undefined; the study rejects such a chain). The dominant
    // link is an argmax in double: nothing differentiates it.
    r.share[i] = Value(r.compliance_b) > 0.0 ? r.compliance_at_b[i] / r.compliance_b : T(0.0);
    if (Value(r.share[i]) > best) {
      best = Value(r.share[i]);
      r.dominant = static_cast<int>(i);
    }
  }
  return r;
}

/// A rigidity R (any unit) seen through a gear stage of ratio N from its fast side: R / N² (eq. 6
/// read backwards: the rigidity at the driving shaft of a reduction).
template <typename T>
T RigidityThroughRatio(const T& rigidity, const T& ratio) {
  return rigidity / (ratio * ratio);
}

}  // namespace camopt::rigidity
