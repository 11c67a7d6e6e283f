// The rating life of a roller bearing whose load is not uniform along the rollers (tilt, crowning):
// ISO/TS 16281:2008's idea, the roller cut into slices along its length, each slice rated as a
// short roller and the slices' lives combined as the weakest link of a Weibull population
// (docs/life.md, "Sliced roller life under tilt"). Double only.
//
// Slice k of N equal slices of width w = L/N (L the loaded length of the roller):
//   rating        C_k = C (w/L)^(7/9)                      (ISO 281:2007 §6.1.1, C ∝ L_we^(7/9))
//   load          Q_k(θ), the slice's share of the roller load at each sample
//   life          L_k over the duty cycle: P_ki the revolution-weighted p-mean of Q_k over line i,
//                 then Palmgren–Miner over the lines (model/common/bearing_life.h)
//   combination   1/L^e = Σ_k 1/L_k^e                        (weakest link, Weibull slope e)
//
// The slope e. At a uniform load Q_k = P/N every slice has L_k = (C_k/(P/N))^p = L N^(2p/9) and
// Σ_k L_k^−e = L^−e N^(1 − 2pe/9): the sliced life equals the unsliced L = (C/P)^p for every N
// exactly when p e = 9/2. Lundberg and Palmgren's line contact has p = 4 and e = 9/8 (their C ∝
// L^(7/9) follows from it: 7/9 = 1 − 1/(pe)); ISO 281 keeps C ∝ L^(7/9) with p = 10/3, and the
// slope that keeps its own length rule (a longer roller at the same load per unit length lasts
// (L'/L)^(−2p/9) as long, the volume effect of a slope 9/(2p)) is e = 9/(2p) = 27/20. With e = 9/8
// and p = 10/3 a uniformly loaded roller would not give back ISO 281's life (its life would
// depend on N as N^(2p/9 − 1/e) = N^(−4/27)). So e = 9/(2p): 27/20 for rollers (p = 10/3).
// Then, per line, L/L_uniform = (mean_k (Q_k/Q̄)^(9/2))^(−1/e) for a load shape held over the cycle.
#pragma once

#include <cmath>
#include <stdexcept>
#include <vector>

#include "model/common/bearing_life.h"

namespace camopt {

/// One line of a duty cycle for the sliced life: time share, the bearing's speed [rpm], and at
/// each sample of the load period the load of every slice [N] (loads[sample][slice]) with the
/// sample's weight (the bearing's revolutions over it, as EquivalentLoad(loads, weights) takes).
struct SlicedDutyLine {
  double time_share = 1.0, speed_rpm = 0.0;
  std::vector<std::vector<double>> loads;
  std::vector<double> weights;
};

struct SlicedLife {
  double L10h = 0.0;              ///< the roller's life, +inf without load
  std::vector<double> slice_L10h; ///< each slice's life (+inf for an unloaded slice)
  int worst_slice = -1;           ///< the slice of the shortest life (-1 without load)
  double slice_rating_N = 0.0;    ///< C_k = C N^(−7/9)
  double weibull_slope = 0.0;     ///< e = 9/(2p)
};

/// The sliced life of a roller bearing of rating C over a duty cycle (file comment).
/// @pre every sample has the same number N ≥ 1 of slices; lines as ValidateDutyCycle accepts.
/// @throws std::invalid_argument for bad lines or ragged slices.
inline SlicedLife SlicedRatingLifeHours(double dynamic_rating_N, const std::vector<SlicedDutyLine>& lines,
                                        BearingKind kind) {
  if (lines.empty() || lines[0].loads.empty() || lines[0].loads[0].empty())
    throw std::invalid_argument("sliced life: no slices");
  const size_t n = lines[0].loads[0].size();
  for (const SlicedDutyLine& l : lines) {
    if (l.loads.size() != l.weights.size() || l.loads.empty()) throw std::invalid_argument("sliced life: one weight per sample");
    for (const auto& q : l.loads)
      if (q.size() != n) throw std::invalid_argument("sliced life: every sample needs the same slices");
  }
  const double p = LifeExponent(kind);
  SlicedLife out;
  out.weibull_slope = 9.0 / (2.0 * p);
  out.slice_rating_N = dynamic_rating_N * std::pow(double(n), -7.0 / 9.0);
  double sum = 0.0, shortest = kInf;
  for (size_t k = 0; k < n; ++k) {
    std::vector<DutyCycleLine<double>> d;
    for (const SlicedDutyLine& l : lines) {
      std::vector<double> q(l.loads.size());
      for (size_t i = 0; i < q.size(); ++i) q[i] = l.loads[i][k];
      d.push_back({l.time_share, l.speed_rpm, {EquivalentLoad(q, l.weights, kind)}});
    }
    const double lk = DutyCycleLifeHours(out.slice_rating_N, d, kind);
    out.slice_L10h.push_back(lk);
    if (std::isfinite(lk)) sum += std::pow(lk, -out.weibull_slope);
    if (lk < shortest) shortest = lk, out.worst_slice = int(k);
  }
  out.L10h = sum > 0 ? std::pow(sum, -1.0 / out.weibull_slope) : kInf;
  return out;
}

}  // namespace camopt
