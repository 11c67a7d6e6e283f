// Transmission error of a cycloid stage from manufacturing tolerances: the kinematic (unloaded,
// rigid) output angle over one output revolution of a drive whose parts deviate from nominal, its
// linearisation by exact derivatives (ceres::Jet) and a Monte-Carlo run of the exact model
// (docs/cycloid.md, "Transmission error from tolerances").
//
// Deviations. The disc is cut to the nominal tooth (a' = a + Δa, ρ' = ρ + Δρ, e, eqs. 3–4); around
// it the pins' circle is a + δa, pin i has the radius ρ + δρ_i and sits at the angle ψ_i + δψ_i,
// the crank's eccentricity is e + δe, and the disc's profile is moved by δn along its outward
// normal (equidistant; > 0 adds material). Output pin j sits on the flange at
// (R_w + δr_j) u(α_j) + δt_j u⊥(α_j), α_j = 2πj/Z_w, hole j in the disc at
// (R_w + δr'_j) u(α_j) + δt'_j u⊥(α_j) with the radius r_h + δr_h,j.
//
// Ring pins (the unloaded TCA, model/cycloid/unloaded_tca.h, eqs. 12–14, with these parts): in the
// disc frame roller i's centre R(φ/n2 − β)((a + δa) u(ψ_i + δψ_i) − (e + δe) u(φ)) lies on the
// tooth's normal at X'(t) + (ρ + δρ_i − ρ' + δn) N(t); δρ_i and δn enter only through that sum, so
// a uniform pin oversize is exactly a profile offset. Under a forward output torque the disc turns
// (β, counter-clockwise from its kinematic angle −φ/n2) until the first pin on the loaded flank
// (arm l_i = X' × N > 0.02 e n2) touches: β0 = min_i β_i; a reverse torque closes the other flank
// (l_i < −0.02 e n2) at β0 = max_i β_i. To first order pair i closes at
//     δβ_i = (N_i · δC_i − δ(ρ_i − ρ'))/l_i                                              (TE1)
// (δC_i the roller centre's move in the disc frame), so a pin oversize or a profile offset δ
// turns the output by −δ/l of the pair in contact — the form of Blanche & Yang's result (1989)
// for the backlash of a cycloid drive with machining tolerances.
//
// Output pins (the pin-and-hole mechanism of model/cycloid/output_mechanism.h, rigid): the output
// turns by w against the disc until the first pin meets its hole's wall. In the disc frame pin j's
// centre is R(w) p_j − R(−θ_d) D (θ_d = −φ/n2 + β0 the disc's angle, D = (e + δe) u(φ) its
// centre) and hole j's centre h_j; pin j touches when |R(w) p_j − R(−θ_d) D − h_j| = r_h + δr_h,j −
// r_c. Forward, the pins whose distance grows with w (slope > 0.05 R_w) close at w_j > 0 and
// w0 = min_j w_j; reverse, the others, w0 = max_j w_j. Without the mechanism's radii the output is
// rigid (w = 0).
//
// The output angle is θ_o = −φ/n2 + β0 + w0; the transmission error TE(φ) its change from the
// nominal drive's at the same crank angle; the backlash at φ θ_o(forward) − θ_o(reverse). β0 and
// w0 are exact minima over pairs and pins: their derivatives are those of the pair and pin in
// contact (a kink where the contact passes to another), which is what the Jet carries.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "model/common/geometry.h"
#include "model/common/profile_deviation.h"
#include "model/common/scalar.h"
#include "model/common/tolerance_stats.h"
#include "model/cycloid/output_mechanism.h"
#include "model/cycloid/tooth_profile.h"
#include "model/cycloid/unloaded_tca.h"

namespace camopt::cycloid {

/// The deviations of a drive's parts from nominal [mm, rad] (header comment). Per-part vectors may
/// be empty (all 0).
template <typename T>
struct Deviations {
  T pin_circle_radius = T(0.0);  ///< δa
  T eccentricity = T(0.0);       ///< δe
  T profile = T(0.0);            ///< δn, outward normal offset of the disc's profile
  std::vector<T> pin_radius, pin_angle;                       ///< δρ_i, δψ_i per ring pin
  std::vector<T> output_pin_radial, output_pin_tangential;    ///< δr_j, δt_j per output pin
  std::vector<T> hole_radial, hole_tangential, hole_radius;   ///< δr'_j, δt'_j, δr_h,j per hole
  /// A normal deviation of the disc's profile that varies along it, d(t) of the curve parameter t
  /// of ToothProfile (disc frame), added to `profile` (a measured disc,
  /// model/common/profile_deviation.h; SolvePairAt states the contact it enters); empty: none.
  profile::NormalDeviation<T> profile_shape;
};

/// Pins whose distance to their hole's centre grows more slowly with w than this fraction of R_w
/// are left out (they close far later than the others, the equation is nearly singular there).
constexpr double kMinPinSlopeFraction = 0.05;

/// The output angle's departure from the kinematic −φ/n2 at one crank angle.
template <typename T>
struct OutputLag {
  T ring_rad = T(0.0);    ///< β0, the disc against the ring
  T pins_rad = T(0.0);    ///< w0, the output against the disc
  T total_rad = T(0.0);   ///< β0 + w0
  int pair = -1;          ///< the ring pin in contact (-1: none on this flank)
  int pin = -1;           ///< the output pin in contact (-1: rigid output or none)
};

namespace te_detail {
template <typename T>
T At(const std::vector<T>& v, int i) {
  return v.empty() ? T(0.0) : v[size_t(i)];
}
}  // namespace te_detail

/// The output lag of the drive `d` (its output pins `pins`, nullptr: a rigid output) with the
/// deviations `dev` at crank angle φ [rad], `sense` +1 under a forward output torque (the loaded
/// flank, as UnloadedTca), −1 under a reverse one. `only_pair` / `only_pin` >= 0: evaluate that pair
/// and pin alone (the ones in contact, for the derivatives). @tparam T double or ceres::Jet.
template <typename T>
OutputLag<T> KinematicLag(const Drive& d, const OutputPins* pins, const Deviations<T>& dev, double crank, int sense,
                          int only_pair = -1, int only_pin = -1) {
  using std::abs;
  using std::sqrt;
  using te_detail::At;
  OutputLag<T> out;
  DriveTpl<T> tooth = d.cast<T>();  // the disc as cut, the profile moved by δn (ρ' − δn)
  tooth.delta_radius_mm = tooth.delta_radius_mm - dev.profile;
  const T a = T(d.roller_position_radius_mm) + dev.pin_circle_radius;
  const T e = T(d.eccentricity_mm) + dev.eccentricity;
  const T crank_t(crank);
  const double min_arm = kMinArmFraction * d.eccentricity_mm * d.teeth;
  bool found = false;
  for (int i = 0; i < d.rollers; ++i) {
    if (only_pair >= 0 && i != only_pair) continue;
    // Pairs on the other flank are not solved (the arm of the unmodified contact says which).
    const ProfilePoint<double> p0 = ToothProfile(d, NominalParameter(d, i, crank));
    if (only_pair < 0 && sense * Cross(p0.centre, p0.normal) < 0.5 * min_arm) continue;
    const T psi = T(2.0 * kPi * i / d.rollers) + At(dev.pin_angle, i);
    const Vec2<T> rel = a * U(psi) - e * U(crank_t);
    const T drho = T(d.roller_radius_mm) + At(dev.pin_radius, i) - (tooth.roller_radius_mm + tooth.delta_radius_mm);
    const PairGeometry<T> g = SolvePairAt(tooth, i, crank_t, rel, drho, dev.profile_shape ? &dev.profile_shape : nullptr);
    if (!(g.converged && sense * Value(g.arm_mm) > min_arm)) continue;
    if (!found || sense * Value(g.contact_rotation) < sense * Value(out.ring_rad)) {
      out.ring_rad = g.contact_rotation;
      out.pair = i;
      found = true;
    }
  }
  out.total_rad = out.ring_rad;
  if (!pins) return out;
  // The output pins: first contact of a pin with its hole's wall as the output turns by w.
  const T theta_d = T(-crank / d.teeth) + out.ring_rad;
  const Vec2<T> centre = e * U(T(crank) - theta_d);  // R(−θ_d) D, the disc's centre seen in the disc frame
  const T rc(pins->contact_radius_mm()), rw(pins->pin_circle_radius_mm);
  bool pin_found = false;
  for (int j = 0; j < pins->pins; ++j) {
    if (only_pin >= 0 && j != only_pin) continue;
    const T alpha(2.0 * kPi * j / pins->pins);
    const Vec2<T> u = U(alpha), v = Perp(u);
    const Vec2<T> p = (rw + At(dev.output_pin_radial, j)) * u + At(dev.output_pin_tangential, j) * v;
    const Vec2<T> h = (rw + At(dev.hole_radial, j)) * u + At(dev.hole_tangential, j) * v;
    const T reach = T(pins->hole_radius_mm) + At(dev.hole_radius, j) - rc;
    // g(w) = |R(w) p − q|² − reach², q = centre + h; g'(w) = 2 (R(w) p − q)·(R(w) p)⊥.
    const Vec2<T> q = centre + h;
    auto gap = [&](const T& w, T* slope) {
      const Vec2<T> rp = Rotate(p, w), x = rp - q;
      *slope = T(2.0) * x.dot(Perp(rp));
      return x.squaredNorm() - reach * reach;
    };
    T s0;
    const T g0 = gap(T(0.0), &s0);
    const double dist0 = std::sqrt(std::max(Value(g0) + Value(reach) * Value(reach), 1e-300));
    if (!(sense * Value(s0) / (2.0 * dist0) > kMinPinSlopeFraction * Value(rw))) continue;
    T w = -g0 / s0;
    bool converged = false;
    for (int it = 0; it < 30; ++it) {
      T s;
      const T gv = gap(w, &s);
      const T dw = -gv / s;
      w += dw;
      if (!(abs(Value(w)) < 0.5)) break;
      if (abs(Value(dw)) < 1e-16 + 1e-13 * abs(Value(w))) {
        if (converged) break;  // one more step at the root for the derivatives
        converged = true;
      }
    }
    if (!converged) continue;
    if (!pin_found || sense * Value(w) < sense * Value(out.pins_rad)) {
      out.pins_rad = w;
      out.pin = j;
      pin_found = true;
    }
  }
  out.total_rad = out.ring_rad + out.pins_rad;
  return out;
}

/// Tolerance bands: ± half-widths, uniform (as the LCR's, model/lcr/transmission_error.h).
struct ToleranceBands {
  double pin_circle_radius_mm = 0, pin_diameter_mm = 0, pin_pitch_rad = 0, eccentricity_mm = 0, profile_mm = 0,
         output_pin_position_mm = 0, output_hole_position_mm = 0, output_hole_diameter_mm = 0;
  bool any() const {
    return pin_circle_radius_mm > 0 || pin_diameter_mm > 0 || pin_pitch_rad > 0 || eccentricity_mm > 0 ||
           profile_mm > 0 || output_pin_position_mm > 0 || output_hole_position_mm > 0 || output_hole_diameter_mm > 0;
  }
  bool output_side() const {
    return output_pin_position_mm > 0 || output_hole_position_mm > 0 || output_hole_diameter_mm > 0;
  }
};

/// The tolerance keys of the study files, in this order (contributions are reported by key).
inline const std::vector<std::string>& ToleranceKeys() {
  static const std::vector<std::string> keys = {
      "pin_circle_radius_um", "pin_diameter_um",        "pin_pitch_arcsec",       "eccentricity_um",
      "profile_um",           "output_pin_position_um", "output_hole_position_um", "output_hole_diameter_um"};
  return keys;
}

/// One scalar deviation: its key, which pin or hole, which component (0 radial, 1 tangential), its
/// band (model units; a diameter's band is taken as the radius's, half of it).
struct ToleranceParameter {
  int key = 0;
  int index = -1;
  int component = 0;
  double band = 0;
};

/// Every non-zero deviation of the bands (per pin or hole where the tolerance is).
std::vector<ToleranceParameter> ToleranceParameters(const Drive& d, const OutputPins* pins, const ToleranceBands& b);

/// Adds `value` to the deviation that parameter p names.
template <typename T>
void AddDeviation(Deviations<T>& dev, const Drive& d, const OutputPins* pins, const ToleranceParameter& p,
                  const T& value) {
  auto per = [&](std::vector<T>& v, int n) {
    if (v.empty()) v.assign(size_t(n), T(0.0));
    v[size_t(p.index)] += value;
  };
  const int z = pins ? pins->pins : 0;
  switch (p.key) {
    case 0: dev.pin_circle_radius += value; break;
    case 1: per(dev.pin_radius, d.rollers); break;
    case 2: per(dev.pin_angle, d.rollers); break;
    case 3: dev.eccentricity += value; break;
    case 4: dev.profile += value; break;
    case 5: per(p.component == 0 ? dev.output_pin_radial : dev.output_pin_tangential, z); break;
    case 6: per(p.component == 0 ? dev.hole_radial : dev.hole_tangential, z); break;
    case 7: per(dev.hole_radius, z); break;
  }
}

struct TransmissionErrorOptions {
  int angle_steps = 0;      ///< crank angles over one output revolution (n2 crank turns); 0: 8 per mesh period
  int samples = 0;          ///< Monte-Carlo samples (0: linear only)
  std::uint64_t seed = 1;
  std::function<void(double)> progress;  ///< fraction done of the Monte-Carlo run
};

/// The shared statistics (model/common/tolerance_stats.h) over one output revolution, and the
/// cycloid's own: the crank angles, the nominal lag, the backlash.
struct TransmissionErrorResult : tolerance::Statistics {
  std::vector<double> crank_angle_rad;
  std::vector<double> nominal_lag_rad;       ///< β0 + w0 of the nominal drive (its unloaded TE + the holes' play)
  std::vector<double> nominal_backlash_rad;  ///< per angle, nominal drive
  double backlash_nominal_arcmin = 0;  ///< max over the angles, nominal drive
  double backlash_arcmin = 0;          ///< max over the angles, worst Monte-Carlo sample (nominal if none)
  double backlash_p99_arcmin = 0;
  int parameters = 0;                  ///< scalar deviations
  /// Monte-Carlo samples that jam at some crank angle: the forward contact below the reverse one
  /// (ring pins or output pins), i.e. interference the rigid parts cannot take up; their TE is
  /// the rigid model's free rotation to first contact (a preloaded, elastic drive turns less).
  int jammed_samples = 0;
};

/// ∂(β0 + w0)/∂t_p at crank angle φ (forward) for every parameter, by ceres::Jet through the pair
/// and the pin in contact in the nominal drive (`nominal`, KinematicLag with no deviations); the
/// other deviations do not move the lag while they stay out of contact (exactly 0).
std::vector<double> LagSensitivities(const Drive& d, const OutputPins* pins, const std::vector<ToleranceParameter>& params,
                                     double crank, const OutputLag<double>& nominal);

/// Linear (Jet) and Monte-Carlo transmission error over one output revolution.
/// @throws std::domain_error when the nominal drive has no pair (or pin) in contact at some angle.
TransmissionErrorResult AnalyzeTransmissionError(const Drive& d, const OutputPins* pins, const ToleranceBands& bands,
                                                 const TransmissionErrorOptions& options);

/// One Monte-Carlo sample's deviations (uniform in each band), from a SplitMix64 state.
Deviations<double> SampleDeviations(const Drive& d, const OutputPins* pins,
                                    const std::vector<ToleranceParameter>& params, std::uint64_t& state,
                                    std::vector<double>* values = nullptr);

/// The crank angles of the analysis: `steps` over one output revolution (0: 8 per mesh period).
std::vector<double> TransmissionErrorAngles(const Drive& d, int steps);

/// The output lag of one set of deviations at the crank angles, both flanks (exact model).
struct KinematicCurves {
  std::vector<double> forward_rad, reverse_rad;  ///< β0 + w0 under a forward / reverse torque
  std::vector<int> forward_pair;                 ///< the ring pin in contact, forward (-1: none)
};
KinematicCurves KinematicOutput(const Drive& d, const OutputPins* pins, const Deviations<double>& dev,
                                const std::vector<double>& crank);

/// TE(φ) [rad] of one set of deviations at the crank angles (exact model).
std::vector<double> ExactTransmissionError(const Drive& d, const OutputPins* pins, const Deviations<double>& dev,
                                           const std::vector<double>& crank);

}  // namespace camopt::cycloid
