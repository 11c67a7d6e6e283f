// The output-pin (pin-and-hole) mechanism of a cycloid stage with hole clearance and contact
// compliance, the eccentric (crank) bearing's load from the disc's force balance, the output pins'
// bending stress and the hole–pin contact pressure, for one or several discs (docs/cycloid.md,
// "Output mechanism").
//
// Frames as bearing_loads.h: crank angle φ, disc centre D = e u(φ), the crank frame turns with the
// crank (x along u(φ)); every vector below is in a disc's crank frame, measured from its centre D.
//
// Geometry. Z_w pins of radius r_w on the output flange's circle R_w, each in a hole of radius r_h
// of the disc (a roller of radius r_r on the pin, when given, is what touches the hole: the contact
// radius r_c is r_r, else r_w). The output turns by θ_o (−φ/n2 for a rigid drive), so pin j sits at
// the crank-frame angle φ_j = 2πj/Z_w + θ_o − φ (−φ n1/n2 + 2πj/Z_w for disc 0, as bearing_loads.h):
//   pin centre  P_j = R_w u(φ_j) − e x̂,   hole centre H_j(w) = R_w u(φ_j − w),
// w the disc's rotation against the output (the output pins' share of the lost motion). With
// v_j = H_j − P_j, the pin presses the hole wall where the two circles overlap,
//   approach δ_j = |v_j| − (r_h − r_c),   normal n_j = v_j/|v_j|,
// with the radial clearance c = r_h − r_c − e at w = 0 (δ_j(0) = −c for every pin). The pin's force
// on the disc is −Q_j n_j along the line through P_j, Q_j = F(δ_j) (0 when δ_j <= 0: only pins whose
// gap closes carry load), and its moment about D is M_j = −Q_j (P_j × n_j). To first order in w,
// δ_j = R_w w sin φ_j − c and n_j = x̂, M_j = Q_j R_w sin φ_j: with c = 0 and a linear law (equal
// stiffness k) Q_j = k R_w w max(0, sin φ_j), the sine law of bearing_loads.h (Blagojević et al.
// 2011, Gorla et al. 2008), whose moment balance Σ Q_j R_w sin φ_j = T fixes w. We solve the exact
// geometry (no linearisation): Σ_j M_j(w) = T by a safeguarded Newton on the bracketed root (M is
// non-decreasing in w), and report the residual.
//
// Contact law: Palmgren's line-contact approach δ = 3.84·10⁻⁵ Q^0.9 / L^0.8 (N, mm; steel),
// scaled to the study's E* (model/rigidity/lcr_stiffness.h, Palmgren 1959; Harris & Kotzalas,
// Rolling Bearing Analysis, §6), L the disc's face width; or a linear spring k [N/mm] (closed forms,
// tests). Peak contact pressure of the pin (or roller) inside its hole, an internal line contact
// (Hertz's two-cylinder contact with the hole's radius negative, as model/contact/hertz.h: Johnson,
// Contact Mechanics, 1985, ch. 4; Roark, Formulas for Stress and Strain, 7th ed., Table 14.1, a
// cylinder in a cylindrical socket):
//   p_max = sqrt(Q E* / (π L R')),   1/R' = 1/r_c − 1/r_h.
//
// Crank bearing. The disc is in equilibrium under the ring-pin forces (resultant G, crank frame),
// the output pins' forces and the bearing's force B (frictionless, through D):
//   B = −G + Σ_j Q_j n_j.
//
// Pin bending (the pin as a beam of diameter d = 2 r_w, Roark, Formulas for Stress and Strain, 7th
// ed., Table 8.1: concentrated loads on a cantilever and on a simply supported beam; σ = M/Z with
// Z = π d³/32). Each disc k loads the pin with the force Q_jk n_jk (fixed frame) at its mid-plane
// z_k from the flange (cantilever, fixed at z = 0) or from one support (both ends, span L):
//   cantilever:  M(z) = Σ_{z_k > z} F_k (z_k − z),
//   both ends:   M(z) = R_0 z − Σ_{z_k < z} F_k (z − z_k),  R_0 = Σ_k F_k (L − z_k)/L.
// |M(z)| is convex between load points (the norm of an affine vector function), so its maximum is at
// z = 0 (cantilever) or at a load point; σ_max = 32 max|M| / (π d³).
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <ceres/jet.h>

#include "model/common/geometry.h"
#include "model/common/roots.h"
#include "model/common/scalar.h"
#include "model/rigidity/lcr_stiffness.h"

namespace camopt::cycloid {

/// How the output pins are held by the output flange.
enum class PinSupport { kCantilever, kBothEnds };

/// The output-pin mechanism with clearance and compliance (header comment). Lengths in mm.
/// @tparam T double or ceres::Jet.
template <typename T>
struct OutputPinsTpl {
  int pins = 8;                     ///< Z_w, >= 3
  T pin_circle_radius_mm = T(0.0);  ///< R_w
  T pin_radius_mm = T(0.0);         ///< r_w (the beam)
  T hole_radius_mm = T(0.0);        ///< r_h, >= r_c + e
  T roller_radius_mm = T(0.0);      ///< r_r of a roller on the pin (0: none, the pin touches the hole)
  T face_width_mm = T(0.0);         ///< L, the contact length (the disc's thickness)
  T e_star_MPa = T(0.0);            ///< composite modulus of pin (roller) and disc
  /// > 0: a linear contact spring [N/mm] instead of Palmgren's law (closed forms, tests).
  T linear_stiffness_N_per_mm = T(0.0);

  /// r_c: the radius that touches the hole.
  T contact_radius_mm() const { return Value(roller_radius_mm) > 0.0 ? roller_radius_mm : pin_radius_mm; }
  /// c = r_h − r_c − e, the radial clearance of every pin at w = 0.
  T clearance_mm(const T& eccentricity_mm) const { return hole_radius_mm - contact_radius_mm() - eccentricity_mm; }

  /// The same mechanism over another scalar (ScalarCast per member; cf. DriveTpl::cast).
  template <typename U>
  OutputPinsTpl<U> cast() const {
    OutputPinsTpl<U> m;
    m.pins = pins;
    m.pin_circle_radius_mm = ScalarCast<U>(pin_circle_radius_mm);
    m.pin_radius_mm = ScalarCast<U>(pin_radius_mm);
    m.hole_radius_mm = ScalarCast<U>(hole_radius_mm);
    m.roller_radius_mm = ScalarCast<U>(roller_radius_mm);
    m.face_width_mm = ScalarCast<U>(face_width_mm);
    m.e_star_MPa = ScalarCast<U>(e_star_MPa);
    m.linear_stiffness_N_per_mm = ScalarCast<U>(linear_stiffness_N_per_mm);
    return m;
  }
};
using OutputPins = OutputPinsTpl<double>;

/// Empty when the mechanism is usable with this eccentricity; otherwise why not (a field named).
inline std::string CheckOutputPins(const OutputPins& m, double eccentricity_mm) {
  auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (m.pins < 3) return "pins: at least 3 output pins (found " + std::to_string(m.pins) + ")";
  if (!positive(m.pin_circle_radius_mm)) return "pin_circle_radius_mm must be finite and > 0";
  if (!positive(m.pin_radius_mm)) return "pin_radius_mm must be finite and > 0";
  if (!(m.roller_radius_mm >= 0.0 && std::isfinite(m.roller_radius_mm))) return "roller_radius_mm must be >= 0";
  if (m.roller_radius_mm > 0.0 && !(m.roller_radius_mm > m.pin_radius_mm))
    return "roller_radius_mm must exceed pin_radius_mm (a roller on the pin)";
  if (!positive(m.face_width_mm) || !positive(m.e_star_MPa)) return "face width and E* must be > 0";
  // Zero clearance (the rigid W-mechanism, every pin touching its hole) is a design: a hole given
  // as r_w + e in decimals may come out a rounding below it (11.7 − 7.2 − 4.5 = −8.9e-16 mm).
  if (!(m.clearance_mm(eccentricity_mm) >= -1e-12 * std::max(1.0, std::abs(m.hole_radius_mm))))
    return "hole_radius_mm must be >= contact radius + e";
  return {};
}

/// The largest rotation of a disc against the output that SolveOutputPins searches [rad].
inline constexpr double kMaxOutputPinRotation = 0.1;

/// The output pins of one disc at one crank angle (crank frame, from the disc centre).
template <typename T>
struct OutputPinLoads {
  T rotation_rad = T(0.0);          ///< w, the disc's rotation against the output
  std::vector<T> force_N;           ///< Q_j, per pin (0 off contact)
  std::vector<T> approach_mm;       ///< δ_j (negative: the gap left)
  std::vector<Vec2<T>> normal;      ///< n_j (the pin's force on the disc is −Q_j n_j)
  std::vector<T> angle_rad;         ///< φ_j
  Vec2<T> resultant_N = Vec2<T>(T(0.0), T(0.0));  ///< Σ −Q_j n_j, the pins' force on the disc
  T moment_Nmm = T(0.0);            ///< Σ M_j at the solution
  double moment_residual_Nmm = 0.0; ///< |Σ M_j − T| (double), the check of the solve
  int iterations = 0;
  int pins_in_contact = 0;
};

namespace output_detail {

/// Palmgren or linear: the force at approach δ (0 for δ <= 0).
template <typename T, typename S>
T ContactForce(const OutputPinsTpl<S>& m, const T& approach) {
  if (Value(m.linear_stiffness_N_per_mm) > 0.0) return T(m.linear_stiffness_N_per_mm) * PositivePart(approach);
  return rigidity::PalmgrenForce(approach, T(m.face_width_mm), T(m.e_star_MPa));
}

/// Σ_j M_j at rotation w, filling `out` when given. W is the scalar of w (and of the result), S of
/// the parameters.
template <typename W, typename S>
W Moment(const OutputPinsTpl<S>& m, const S& eccentricity_mm, const S& pin0_angle_rad, const W& w,
         OutputPinLoads<W>* out) {
  using std::sqrt;
  const W rw(m.pin_circle_radius_mm), e(eccentricity_mm);
  const W reach = W(m.hole_radius_mm) - W(m.contact_radius_mm());
  W total(0.0);
  if (out) *out = OutputPinLoads<W>{};
  for (int j = 0; j < m.pins; ++j) {
    const W phi = W(pin0_angle_rad) + W(2.0 * kPi * j / m.pins);
    const Vec2<W> p = rw * camopt::U(phi) - Vec2<W>(e, W(0.0));
    const Vec2<W> h = rw * camopt::U(W(phi - w));
    const Vec2<W> v = h - p;
    const W dist = sqrt(v.squaredNorm());
    const Vec2<W> n = v / dist;
    const W delta = dist - reach;
    const W q = ContactForce(m, delta);
    const W mj = -q * Cross(p, n);
    total += mj;
    if (out) {
      out->force_N.push_back(q);
      out->approach_mm.push_back(delta);
      out->normal.push_back(n);
      out->angle_rad.push_back(phi);
      out->resultant_N -= q * n;
      if (Value(q) > 0.0) ++out->pins_in_contact;
    }
  }
  return total;
}

}  // namespace output_detail

/// Solves the output pins of one disc under the disc torque T [N·mm] (the pins' moment on the disc,
/// +T; the ring pins' is −T): Σ_j M_j(w) = T for w >= 0 (header comment). `pin0_angle_rad` is φ_0,
/// the crank-frame angle of pin 0 (2π·0/Z_w + θ_o − φ). T = 0 gives w = 0 and no load. With a
/// Jet, w's derivative is the implicit one at the converged w (one Newton step at the root), the
/// contact set frozen.
/// @tparam T double or ceres::Jet.
/// @throws std::invalid_argument when CheckOutputPins fails, T < 0, or T needs w > kMaxOutputPinRotation.
template <typename T>
OutputPinLoads<T> SolveOutputPins(const OutputPinsTpl<T>& m, const T& eccentricity_mm, const T& torque_Nmm,
                                  const T& pin0_angle_rad) {
  using J = ceres::Jet<double, 1>;
  const OutputPinsTpl<double> md = m.template cast<double>();
  const double e = Value(eccentricity_mm), torque = Value(torque_Nmm), phi0 = Value(pin0_angle_rad);
  if (const std::string why = CheckOutputPins(md, e); !why.empty())
    throw std::invalid_argument("output pins: " + why);
  if (!(torque >= 0.0 && std::isfinite(torque)))
    throw std::invalid_argument("output pins: the disc torque must be finite and >= 0");
  OutputPinLoads<T> out;
  if (torque == 0.0) {
    output_detail::Moment(m, eccentricity_mm, pin0_angle_rad, T(0.0), &out);
    return out;
  }
  auto f = [&](double w) { return output_detail::Moment(md, e, phi0, w, (OutputPinLoads<double>*)nullptr); };
  auto slope = [&](double w) {
    return output_detail::Moment(md, e, phi0, J(w, 0), (OutputPinLoads<J>*)nullptr).v[0];
  };
  // Bracket: every pin is free up to w = c/R_w (its gap closes by at most R_w w to first order);
  // then double until the moment exceeds T.
  const double c = md.clearance_mm(e), rw = md.pin_circle_radius_mm;
  double lo = std::max(c / rw, 1e-15), hi = std::max(2.0 * lo, 1e-9);
  for (int k = 0; k < 100 && f(lo) >= torque; ++k) lo *= 0.5;  // second-order closure before c/R_w
  // The moment rises with w while the pins press deeper; beyond a tenth of a radian the pins
  // would have sunk millimetres into the disc: a torque they cannot carry.
  int it = 0;
  while (f(hi) < torque && hi < kMaxOutputPinRotation) lo = hi, hi = std::min(2.0 * hi, kMaxOutputPinRotation), ++it;
  if (!(f(hi) >= torque))
    throw std::invalid_argument("output pins: the disc torque " + std::to_string(torque) +
                                " N mm needs a rotation of the disc against the output above " +
                                std::to_string(kMaxOutputPinRotation) + " rad (the pins cannot carry it)");
  const double w = SafeguardedNewtonIncreasing(f, slope, torque, lo, hi, 200, 1e-15, 1e-15);
  const double residual = std::abs(f(w) - torque);
  if constexpr (std::is_same_v<T, double>) {
    output_detail::Moment(m, eccentricity_mm, pin0_angle_rad, w, &out);
    out.rotation_rad = w;
  } else {
    // Implicit derivative: w_T = w − (M(w; p) − T)/M'(w) with w a constant: its value is w (to the
    // residual) and its derivative −(∂M/∂p − ∂T/∂p)/M'.
    const T m_at = output_detail::Moment(m, eccentricity_mm, pin0_angle_rad, T(w), (OutputPinLoads<T>*)nullptr);
    const T wt = T(w) - (m_at - torque_Nmm) / T(slope(w));
    output_detail::Moment(m, eccentricity_mm, pin0_angle_rad, wt, &out);
    out.rotation_rad = wt;
  }
  out.moment_Nmm = output_detail::Moment(m, eccentricity_mm, pin0_angle_rad, out.rotation_rad,
                                         (OutputPinLoads<T>*)nullptr);
  out.moment_residual_Nmm = residual;
  out.iterations = it;
  return out;
}

/// The crank bearing's force on the disc in the crank frame, B = −G + Σ_j Q_j n_j: G the ring-pin
/// resultant (crank frame), `pins` the solved output pins.
template <typename T>
Vec2<T> CrankBearingForce(const Vec2<T>& ring_resultant_crank_frame, const OutputPinLoads<T>& pins) {
  return -(ring_resultant_crank_frame + pins.resultant_N);
}

/// Peak pressure [MPa] of a pin (or roller) of radius r_c in a hole of radius r_h under Q [N] over
/// the length L: internal line contact, 1/R' = 1/r_c − 1/r_h (header comment).
template <typename T>
T HoleContactPressure(const OutputPinsTpl<T>& m, const T& force_N) {
  using std::sqrt;
  const T r_eff = T(1.0) / (T(1.0) / m.contact_radius_mm() - T(1.0) / m.hole_radius_mm);
  if (!(Value(force_N) > 0.0)) return T(0.0);  // no load: 0 (sqrt's derivative is infinite at 0)
  return sqrt(force_N * m.e_star_MPa / (T(kPi) * m.face_width_mm * r_eff));
}

/// Axial positions [mm] of the discs' mid-planes on an output pin: N discs of face width B at the
/// pitch s. Cantilever (fixed at z = 0, free end at z = L): the stack ends at the free end,
/// z_k = L − B/2 − (N − 1 − k) s. Both ends (supports at 0 and L): the stack centred, z_k = L/2 +
/// (k − (N − 1)/2) s.
/// @throws std::invalid_argument when the stack, (N − 1) s + B, does not fit in L.
inline std::vector<double> DiscPlanesOnPin(PinSupport support, double span_mm, int discs, double face_width_mm,
                                           double pitch_mm) {
  const double stack = (discs - 1) * pitch_mm + face_width_mm;
  if (!(span_mm >= stack * (1.0 - 1e-12)))
    throw std::invalid_argument("output pins: the pin span is shorter than the disc stack");
  std::vector<double> z;
  for (int k = 0; k < discs; ++k)
    z.push_back(support == PinSupport::kCantilever ? span_mm - 0.5 * face_width_mm - (discs - 1 - k) * pitch_mm
                                                   : 0.5 * span_mm + (k - 0.5 * (discs - 1)) * pitch_mm);
  return z;
}

/// The largest bending moment [N·mm] of a pin under forces F_k (fixed frame, N) at the axial
/// positions z_k [mm] (header comment).
/// @tparam T double or ceres::Jet (the active point frozen).
template <typename T>
T PinBendingMoment(PinSupport support, double span_mm, const std::vector<double>& z, const std::vector<Vec2<T>>& f) {
  using std::sqrt;
  std::vector<double> points = z;
  if (support == PinSupport::kCantilever) points.push_back(0.0);
  Vec2<T> r0(T(0.0), T(0.0));
  if (support == PinSupport::kBothEnds)
    for (size_t k = 0; k < z.size(); ++k) r0 += f[k] * T((span_mm - z[k]) / span_mm);
  T best(0.0);
  double best_value = -1.0;
  for (double x : points) {
    Vec2<T> moment(T(0.0), T(0.0));
    if (support == PinSupport::kCantilever) {
      for (size_t k = 0; k < z.size(); ++k)
        if (z[k] > x) moment += f[k] * T(z[k] - x);
    } else {
      moment = r0 * T(x);
      for (size_t k = 0; k < z.size(); ++k)
        if (z[k] < x) moment -= f[k] * T(x - z[k]);
    }
    const T m2 = moment.squaredNorm();
    if (Value(m2) > best_value) best_value = Value(m2), best = m2;
  }
  return best_value > 0.0 ? sqrt(best) : T(0.0);
}

/// Bending stress [MPa] of a solid pin of radius r_w [mm] under the moment M [N·mm]: 32 M/(π d³).
template <typename T>
T PinBendingStress(const T& moment_Nmm, const T& pin_radius_mm) {
  const T d = T(2.0) * pin_radius_mm;
  return T(32.0) * moment_Nmm / (T(kPi) * d * d * d);
}

}  // namespace camopt::cycloid
