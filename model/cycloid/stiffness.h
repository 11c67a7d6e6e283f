// Torsional stiffness, lost motion and backlash of a cycloid stage at its output, the input held
// (docs/cycloid.md, "Stiffness, lost motion and backlash").
//
// With the crank fixed at φ, a torque T on the output turns the disc against the ring by β(T) (the
// LTCA's disc lag β0 + Δφc: the modifications' free rotation to first contact and the contact
// compliance of the loaded pairs, eqs. 14, 24–25) and the output against the disc by w(T) (the output
// pins' clearance and contact compliance, output_mechanism.h). The output turns by
// θ(T) = β(T) + w(T), positive in the loaded sense. A negative torque loads the other flanks: the
// drive is symmetric about the line of the first roller (rollers at 2πi/n1, a symmetric tooth), so
// the state at (φ, −T) is the mirror image of the state at (−φ, T): θ(φ, −T) = −θ(−φ, |T|), with the
// output pins mirrored likewise (pin angles φ_j → −φ_j). At φ = 0 the curve is odd.
//
// Catalogue definitions (as robot-reducer datasheets state them): torsional stiffness the slope of
// θ(T) between 50% and 100% of the rated torque T_r, (T_r − T_r/2)/(θ(T_r) − θ(T_r/2)), the mean of
// the two directions; lost motion the rotation between +3% and −3% of T_r, θ(0.03 T_r) − θ(−0.03 T_r);
// backlash the free rotation at zero torque, θ(0+) − θ(0−) (β0 on both flanks and the output pins'
// first contact on both sides). The model is frictionless and quasi-static: loading and unloading
// follow the same curve, so its hysteresis loop has no width.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "model/cycloid/loaded_tca.h"
#include "model/cycloid/output_mechanism.h"
#include "model/cycloid/unloaded_tca.h"

namespace camopt::cycloid {

struct TorsionPoint {
  double torque_Nmm = 0;         ///< on the output (all discs)
  double ring_rad = 0;           ///< β, the disc against the ring (signed with the torque)
  double output_pins_rad = 0;    ///< w, the output against the disc (signed)
  double output_angle_rad = 0;   ///< θ = β + w
};

struct TorsionCurve {
  std::vector<TorsionPoint> points;  ///< ascending torque, −T_r … −0, +0 … T_r
  double stiffness_Nmm_per_rad = 0;  ///< mean of the two directions' 50–100% slopes
  double stiffness_positive_Nmm_per_rad = 0, stiffness_negative_Nmm_per_rad = 0;
  double lost_motion_rad = 0;        ///< θ(0.03 T_r) − θ(−0.03 T_r)
  double backlash_rad = 0;           ///< θ(0+) − θ(0−)
  /// Shares of the 50–100% rotation (both directions) taken by the ring pins and the output pins.
  double ring_share = 0, output_pins_share = 0;
  int contact_solves = 0;
};

/// Torque fractions of T_r on each side (the curve's sampling; 0.03, 0.5 and 1 among them), with
/// `extra` fractions in (0, 1) merged in (the three-segment stiffness's T1/T_r and T2/T_r, a lost
/// motion's percentage), ascending and without repeats.
inline std::vector<double> TorsionFractions(const std::vector<double>& extra = {}) {
  std::vector<double> f = {0.03, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
  for (double x : extra)
    if (x > 0.0 && x < 1.0) f.push_back(x);
  std::sort(f.begin(), f.end());
  f.erase(std::unique(f.begin(), f.end(), [](double a, double b) { return std::abs(a - b) <= 1e-12; }), f.end());
  return f;
}

/// The output angle against the output torque from −T_r to T_r at crank angle φ [rad], each of
/// `discs` discs carrying T/discs (equal split); `pins` the output mechanism (nullptr: rigid
/// output); `extra_fractions` of T_r sampled besides TorsionFractions(). Header comment for the
/// definitions.
/// @throws std::invalid_argument for T_r <= 0 or discs < 1.
inline TorsionCurve TorsionalCurve(const LoadedTca& tca, const OutputPins* pins, double crank,
                                   double rated_torque_Nmm, int discs, const std::vector<double>& extra_fractions = {}) {
  if (!(rated_torque_Nmm > 0.0 && std::isfinite(rated_torque_Nmm)) || discs < 1)
    throw std::invalid_argument("torsional curve: the rated torque must be > 0 and discs >= 1");
  const Drive& d = tca.drive();
  const double n1_over_n2 = double(d.rollers) / double(d.teeth);
  // Pin 0's crank-frame angle at φ (disc 0) and its mirror.
  const double pin0 = -crank * n1_over_n2, pin0_mirror = -pin0;
  auto side = [&](double sign, double fraction, TorsionCurve& c) {
    const double t = fraction * rated_torque_Nmm;
    const double phi = sign > 0 ? crank : -crank;
    TorsionPoint p;
    p.torque_Nmm = sign * t;
    if (t > 0) {
      const MeshLoad m = tca.Solve(t / discs, phi);
      c.contact_solves += m.contact_solves;
      p.ring_rad = sign * m.rotation_rad;
    } else {
      p.ring_rad = sign * UnloadedTca<double>(d, phi).rotation;  // first contact, β0
    }
    if (pins) {
      // At zero torque the output pins' first contact: a vanishing torque (1e-12 T_r).
      const double q = t > 0 ? t / discs : 1e-12 * rated_torque_Nmm;
      p.output_pins_rad = sign * SolveOutputPins(*pins, d.eccentricity_mm, q, sign > 0 ? pin0 : pin0_mirror).rotation_rad;
    }
    p.output_angle_rad = p.ring_rad + p.output_pins_rad;
    return p;
  };
  TorsionCurve c;
  const std::vector<double> f = TorsionFractions(extra_fractions);
  for (auto it = f.rbegin(); it != f.rend(); ++it) c.points.push_back(side(-1.0, *it, c));
  c.points.push_back(side(-1.0, 0.0, c));
  c.points.push_back(side(1.0, 0.0, c));
  for (double x : f) c.points.push_back(side(1.0, x, c));
  auto at = [&](double torque) -> const TorsionPoint& {
    for (const TorsionPoint& p : c.points)
      if (std::abs(p.torque_Nmm - torque) <= 1e-12 * rated_torque_Nmm) return p;
    throw std::logic_error("torsional curve: a sampled torque is missing");
  };
  const size_t zero = f.size();  // index of 0− (0+ follows)
  const TorsionPoint &pf = at(rated_torque_Nmm), &ph = at(0.5 * rated_torque_Nmm);
  const TorsionPoint &nf = at(-rated_torque_Nmm), &nh = at(-0.5 * rated_torque_Nmm);
  c.stiffness_positive_Nmm_per_rad = 0.5 * rated_torque_Nmm / (pf.output_angle_rad - ph.output_angle_rad);
  c.stiffness_negative_Nmm_per_rad = 0.5 * rated_torque_Nmm / (nh.output_angle_rad - nf.output_angle_rad);
  c.stiffness_Nmm_per_rad = 0.5 * (c.stiffness_positive_Nmm_per_rad + c.stiffness_negative_Nmm_per_rad);
  c.lost_motion_rad = at(0.03 * rated_torque_Nmm).output_angle_rad - at(-0.03 * rated_torque_Nmm).output_angle_rad;
  c.backlash_rad = c.points[zero + 1].output_angle_rad - c.points[zero].output_angle_rad;
  const double ring = (pf.ring_rad - ph.ring_rad) + (nh.ring_rad - nf.ring_rad);
  const double out = (pf.output_pins_rad - ph.output_pins_rad) + (nh.output_pins_rad - nf.output_pins_rad);
  c.ring_share = ring / (ring + out);
  c.output_pins_share = out / (ring + out);
  return c;
}

}  // namespace camopt::cycloid
