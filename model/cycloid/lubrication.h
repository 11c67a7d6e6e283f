// The cycloid stage's losses from the lubricant up, at one crank angle: per ring pin and output pin
// the sliding and entraining speeds, the EHL film and λ, the friction by regime, and the rolling
// bearings' losses (docs/lubrication.md). Frames as tooth_profile.h and bearing_loads.h.
//
// Ring pins. In the disc frame the ring turns at 1/n2 per crank radian about the pitch point I
// (bearing_loads.h: I = D + n2 e u(φ), the disc's instant centre relative to the ring). At a
// contact C with the tooth's outward normal N (tangent t = N⊥) a point of the ring moves along t at
//     s = (C − I)·N / n2,
// the roller's centre O = C + ρ N at (O − I)·N / n2 = s + ρ/n2, and the contact point runs along
// the tooth at v_c = (s + ρ/n2) / (1 + ρ κ), κ the tooth's signed curvature there (the roller
// centre's path is the tooth's offset by ρ). A roller turning on its pin (the ring pins as rollers
// or needle-mounted pins) rolls on the tooth: v_s = 0, u_e = |v_c|, the roller turning at |s|/ρ
// relative to its pin (bearing_loads.h RollerSpinRate). A fixed pin slides: v_s = |s|,
// u_e = |s − 2 v_c| / 2.
//
// Output pins. Relative to the output flange the disc translates on a circle of radius e at
// Ω = n1/n2 per crank radian (the disc and the flange turn alike), so a hole of radius r_h = r + e
// around a pin (or a roller on it) of radius r: the contact point on the line of centres turns at Ω
// about the pin, the hole's surface moves at e Ω along the tangent. A pin without roller slides:
// v_s = e Ω, u_e = |e − 2 r| Ω / 2; a roller rolls in the hole: v_s = 0, u_e = |e − r| Ω, the roller
// turning at e Ω / r relative to its pin. The pins' forces are those of the rigid mechanism
// (bearing_loads.h OutputPinResultant); the film's radius the conformal R' = r r_h / (r_h − r).
//
// Crank bearing: Palmgren at n1/n2 of the input speed under |B| (bearing_loads.h CrankBearingForce).
// Film: Pan & Hamrock's line contact (model/contact/ehl.h) on the pair's R' and w' = F/B (B the face
// width); on the same R', w' and u_e every loaded contact with a film also loses 2 u_e F_R to the
// rolling (Poiseuille) force of Goksem & Hargreaves (ehl.h), rolling and sliding contacts alike.
// The loads are the LTCA's (frictionless); the losses are first order in the friction.
#pragma once

#include <cmath>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <vector>

#include "model/common/bearing_friction.h"
#include "model/common/lubricant.h"
#include "model/common/scalar.h"
#include "model/common/thermal.h"
#include "model/contact/ehl.h"
#include "model/contact/lubricated_friction.h"
#include "model/contact/oil_state.h"
#include "model/cycloid/bearing_loads.h"
#include "model/cycloid/loaded_tca.h"
#include "model/cycloid/unloaded_tca.h"

namespace camopt::cycloid {

/// The output pins' contact geometry (rigid mechanism with its hole radius). @tparam T double or
/// ceres::Jet (a sizing's holes follow its eccentricity: r_h = r + e + c).
template <typename T>
struct OutputPinContactTpl {
  double pin_radius_mm = 0;     ///< r_w, or the roller on it when roller_radius_mm > 0
  T hole_radius_mm{};           ///< r_h
  double roller_radius_mm = 0;  ///< 0: no roller (the pin slides in the hole)
  double contact_radius_mm() const { return roller_radius_mm > 0 ? roller_radius_mm : pin_radius_mm; }
};
using OutputPinContact = OutputPinContactTpl<double>;

/// How the lubricated losses of a cycloid stage are computed (model units).
struct CycloidLubricationSpec {
  Lubricant oil;
  contact::RegimeFriction friction;
  double composite_roughness_mm = 0.2e-3 * std::sqrt(2.0);
  bool ring_pins_rotate = true;
  bool rolling_loss = true;  ///< the contacts' EHL rolling (Poiseuille) loss (false: left out)
  PalmgrenBearing ring_pin_bearing{0.0, 0.0, 1.0};       ///< f0 = f1 = 0: no loss
  PalmgrenBearing output_roller_bearing{0.0, 0.0, 1.0};
  PalmgrenBearing crank_bearing{0.0, 0.0, 1.0};
};

/// Speeds of a contact per crank radian [mm/rad] and the spin of its roller relative to its pin [-].
template <typename T>
struct PinSpeeds {
  T sliding{}, entraining{}, spin{};
};

/// The ring pin's speeds at the unloaded TCA's contact `g` (disc frame) at crank angle φ.
template <typename T>
PinSpeeds<T> RingPinSpeeds(const DriveTpl<T>& d, const PairGeometry<T>& g, const T& crank, bool rotating) {
  using std::abs;
  const T n2(double(d.teeth));
  const T rho = d.roller_radius_mm;
  const T s = (g.point - PitchPointInDisc(d, crank, T(0.0))).dot(g.normal) / n2;
  const T travel = (s + rho / n2) / (T(1.0) + rho * g.profile_curvature);
  PinSpeeds<T> out;
  if (rotating) {
    out.entraining = abs(travel);
    out.spin = abs(s) / rho;
  } else {
    out.sliding = abs(s);
    out.entraining = abs(s - T(2.0) * travel) * T(0.5);
  }
  return out;
}

/// An output pin's speeds per crank radian (header comment).
template <typename T>
PinSpeeds<T> OutputPinSpeeds(const DriveTpl<T>& d, const OutputPinContactTpl<T>& p) {
  using std::abs;
  const T omega(double(d.rollers) / d.teeth);
  const T e = d.eccentricity_mm;
  PinSpeeds<T> out;
  if (p.roller_radius_mm > 0) {
    out.entraining = abs(e - T(p.roller_radius_mm)) * omega;
    out.spin = e * omega / T(p.roller_radius_mm);
  } else {
    out.sliding = e * omega;
    out.entraining = abs(e - T(2.0 * p.pin_radius_mm)) * omega * T(0.5);
  }
  return out;
}
inline PinSpeeds<double> OutputPinSpeeds(const Drive& d, const OutputPinContact& p) {
  return OutputPinSpeeds<double>(d, p);
}

/// The power lost at one crank angle by one disc, by element [W], and the thinnest film.
template <typename T>
struct CycloidAngleLossesTpl {
  T ring_pins_sliding{}, ring_pin_bearings{}, output_pins_sliding{}, output_roller_bearings{}, crank_bearing{};
  T ring_pins_rolling{}, output_pins_rolling{};  ///< the contacts' EHL rolling (Poiseuille) loss
  double min_lambda = 0, min_film_mm = 0;
  int min_lambda_pin = -1;       ///< -1: no loaded contact
  bool min_at_output_pin = false;  ///< the pin is an output pin (else a ring pin)
  T total() const {
    return ring_pins_sliding + ring_pin_bearings + output_pins_sliding + output_roller_bearings + crank_bearing +
           ring_pins_rolling + output_pins_rolling;
  }
};
using CycloidAngleLosses = CycloidAngleLossesTpl<double>;

/// What the losses at one crank angle need of a solved mesh, computed once for every speed and oil
/// temperature: the unloaded TCA's contacts, the pairs' loads and radii per ring pin (R' =
/// 1/(1/ρ + κ) of the unloaded contact, as the LTCA's pairs), the output pins' forces of the rigid
/// mechanism and the crank bearing's load |B|.
template <typename T>
struct MeshLubricationLoadsTpl {
  double crank_angle_rad = 0;
  UnloadedMesh<T> unloaded;
  std::vector<T> ring_pin_load_N, ring_pin_r_eff_mm;  ///< per roller (0: unloaded)
  std::vector<T> output_pin_load_N;                   ///< per output pin (empty: continuous limit)
  Vec2<T> ring_resultant_crank_frame{T(0.0), T(0.0)}; ///< Σ −F_i N_i (bearing_loads.h)
  T crank_bearing_load_N{};
};
using MeshLubricationLoads = MeshLubricationLoadsTpl<double>;

/// `x` with the output pins taken at crank angle `output_crank_rad` under the disc torque: their
/// forces and the crank bearing's load (the ring pins' part of `x` kept).
template <typename T>
void SetOutputPins(const OutputMechanism& m, int teeth, double disc_torque_Nmm, double output_crank_rad,
                   MeshLubricationLoadsTpl<T>& x) {
  const T q = OutputPinResultant<T>(m, teeth, T(disc_torque_Nmm), T(output_crank_rad), &x.output_pin_load_N);
  x.crank_bearing_load_N = CrankBearingForce(x.ring_resultant_crank_frame, q).norm();
}

/// The loads of one disc at crank angle φ from its unloaded TCA `u`, the pairs' loads (roller,
/// load) and the disc's lag, under the disc torque [N·mm] with the output mechanism `m`, the output
/// pins taken `output_shift_rad` of crank angle later.
template <typename T>
MeshLubricationLoadsTpl<T> LubricationLoadsFrom(const DriveTpl<T>& d, const OutputMechanism& m, UnloadedMesh<T> u,
                                                double crank, const std::vector<std::pair<int, T>>& loads,
                                                const T& rotation, double disc_torque_Nmm, double output_shift_rad = 0.0) {
  MeshLubricationLoadsTpl<T> out;
  out.crank_angle_rad = crank;
  out.ring_pin_load_N.assign(size_t(d.rollers), T(0.0));
  out.ring_pin_r_eff_mm.assign(size_t(d.rollers), T(0.0));
  for (const auto& [roller, load] : loads) {
    const PairGeometry<T>& g = u.pairs.at(size_t(roller));
    out.ring_pin_load_N.at(size_t(roller)) = load;
    out.ring_pin_r_eff_mm.at(size_t(roller)) = T(1.0) / (g.roller_curvature + g.profile_curvature);
  }
  out.ring_resultant_crank_frame = RingPinResultantCrankFrame(d, u, loads, T(crank), rotation);
  out.unloaded = std::move(u);
  SetOutputPins(m, d.teeth, disc_torque_Nmm, crank + output_shift_rad, out);
  return out;
}

/// The loads of one disc at `mesh` under the disc torque [N·mm] with the output mechanism `m`, the
/// output pins taken `output_shift_rad` of crank angle later: the ring pins' state repeats every
/// mesh period (rollers relabelled), the output pins' pattern every OutputPinPeriodInMeshPeriods,
/// so a whole revolution's mean takes every mesh at the shifts of LubricationLoadsOverRevolution
/// (as CrankBearingLoadsOverPeriod, bearing_loads.h).
inline MeshLubricationLoads LubricationLoadsAt(const Drive& d, const OutputMechanism& m, const MeshLoad& mesh,
                                               double disc_torque_Nmm, double output_shift_rad = 0.0) {
  std::vector<std::pair<int, double>> loads;
  for (const PairLoad& p : mesh.pairs) loads.push_back({p.roller, p.load_N});
  return LubricationLoadsFrom<double>(d, m, UnloadedTca<double>(d, mesh.crank_angle_rad), mesh.crank_angle_rad,
                                      loads, mesh.rotation_rad, disc_torque_Nmm, output_shift_rad);
}

/// How many times the meshes at `angles` (whole mesh periods sampled uniformly) repeat with the
/// output pins shifted by the sampled span until their pattern repeats, and that span [rad].
/// @throws std::invalid_argument for angles that do not sample whole mesh periods uniformly.
inline std::pair<int, double> OutputPinShifts(const Drive& d, const OutputMechanism& m, const std::vector<double>& angles) {
  int periods = 0;
  if (!UniformWholeMeshPeriods(angles, d.rollers, &periods))
    throw std::invalid_argument("lubrication: the crank angles must sample whole mesh periods uniformly");
  const int pin_period = OutputPinPeriodInMeshPeriods(m, d.teeth);
  return {pin_period / std::gcd(pin_period, periods), periods * 2.0 * kPi / d.rollers};
}

/// The loads of one disc over a whole revolution's pattern from meshes that sample whole mesh
/// periods uniformly (UniformWholeMeshPeriods): every mesh with the output pins at each shift of
/// whole sampled spans until their pattern repeats (OutputPinShifts). Over T, `at(k)` gives the
/// k-th mesh's loads (output pins unshifted). @throws std::invalid_argument otherwise.
template <typename T, typename MeshAt>
std::vector<MeshLubricationLoadsTpl<T>> LubricationLoadsOverRevolution(const Drive& d, const OutputMechanism& m,
                                                                       const std::vector<double>& angles,
                                                                       double disc_torque_Nmm, const MeshAt& at) {
  const auto [repeats, span] = OutputPinShifts(d, m, angles);
  std::vector<MeshLubricationLoadsTpl<T>> out;
  for (size_t k = 0; k < angles.size(); ++k) out.push_back(at(k));
  // The ring pins' part of each mesh once; only the output pins move with the shift.
  for (int r = 1; r < repeats; ++r)
    for (size_t k = 0; k < angles.size(); ++k) {
      MeshLubricationLoadsTpl<T> x = out[k];
      SetOutputPins(m, d.teeth, disc_torque_Nmm, angles[k] + r * span, x);
      out.push_back(std::move(x));
    }
  return out;
}
inline std::vector<MeshLubricationLoads> LubricationLoadsOverRevolution(const Drive& d, const OutputMechanism& m,
                                                                        const std::vector<MeshLoad>& meshes,
                                                                        double disc_torque_Nmm) {
  std::vector<double> angles;
  for (const MeshLoad& mesh : meshes) angles.push_back(mesh.crank_angle_rad);
  return LubricationLoadsOverRevolution<double>(d, m, angles, disc_torque_Nmm, [&](size_t k) {
    return LubricationLoadsAt(d, m, meshes[k], disc_torque_Nmm);
  });
}

/// What the losses of one disc at one crank angle take from its loads and kinematics, apart from
/// the oil's temperature (computed once for a sweep over it, model/contact/oil_state.h): each loaded
/// contact's film and rolling loss at η0 = 1 MPa·s and its sliding power per unit μ; each bearing's
/// speed and load-dependent part.
template <typename T>
struct CrankKinematics {
  struct Contact {
    bool output = false;  ///< an output pin (else a ring pin)
    int pin = 0;
    bool film = false;     ///< an entraining motion on a convex or conformal contact
    T film_unit_mm{};      ///< h_min at η0 = 1 MPa·s (0 without a film)
    T rolling_unit_W{};    ///< 2 u F_R at η0 = 1 MPa·s [W] (0 without a film or the loss)
    bool slides = false;   ///< the pin slides on its contact (not on a rolling bearing)
    T sliding_per_mu_W{};  ///< F |v_s| [W per unit μ] (0 where the pin rolls)
  };
  std::vector<Contact> contacts;  ///< the loaded contacts, ring pins first
  std::vector<PalmgrenAtSpeed<T>> ring_pin_bearings, output_roller_bearings;
  PalmgrenAtSpeed<T> crank;
};

/// The temperature-free part of the losses of one disc at one crank angle (its loads `x`) at input
/// speed n_in [rpm]. `pins` absent: the output pins' contacts are not modelled (no radii given).
template <typename T>
CrankKinematics<T> KinematicsAtCrankAngle(const DriveTpl<T>& d, const CycloidLubricationSpec& spec, double e_star,
                                          const MeshLubricationLoadsTpl<T>& x,
                                          const std::optional<OutputPinContactTpl<T>>& pins, double input_speed_rpm) {
  CrankKinematics<T> out;
  const T crank(x.crank_angle_rad);
  const T omega(input_speed_rpm * 2.0 * kPi / 60.0), n_in(input_speed_rpm);
  const T alpha(spec.oil.pressure_viscosity_per_MPa), e(e_star);
  const T width = d.face_width_mm;
  const T unit(1.0);  // η0 = 1 MPa·s
  const auto contact = [&](const T& force, const T& r_eff, const PinSpeeds<T>& v, int pin, bool output, bool slides) {
    typename CrankKinematics<T>::Contact c;
    c.output = output;
    c.pin = pin;
    c.slides = slides;
    const T u_e = v.entraining * omega;
    c.film = u_e > T(1e-12) && r_eff > T(0.0);
    if (c.film) c.film_unit_mm = contact::LineContactFilm<T>(unit, u_e, r_eff, force / width, e, alpha).minimum;
    if (c.film && spec.rolling_loss)
      c.rolling_unit_W =
          contact::RollingLoss(
              T(contact::LineContactRollingForcePerLength<T>(unit, u_e, r_eff, force / width, e, alpha) * width), u_e) *
          T(1e-3);
    if (slides) c.sliding_per_mu_W = contact::SlidingLoss(T(1.0), force, T(v.sliding * omega)) * T(1e-3);
    out.contacts.push_back(c);
  };
  // Ring pins: every roller turns (M0), the loaded ones carry their pair's load.
  for (int i = 0; i < d.rollers; ++i) {
    const PinSpeeds<T> v = RingPinSpeeds(d, x.unloaded.pairs.at(size_t(i)), crank, spec.ring_pins_rotate);
    const T& f = x.ring_pin_load_N[size_t(i)];
    if (spec.ring_pins_rotate) out.ring_pin_bearings.push_back(PalmgrenAt(spec.ring_pin_bearing, T(v.spin * n_in), f));
    if (!(f > T(0.0))) continue;
    contact(f, x.ring_pin_r_eff_mm[size_t(i)], v, i, false, !spec.ring_pins_rotate);
  }
  // Output pins (the rigid mechanism's forces).
  if (pins) {
    const PinSpeeds<T> v = OutputPinSpeeds(d, *pins);
    const T r(pins->contact_radius_mm()), rh = pins->hole_radius_mm;
    const T conformal = rh > r ? r * rh / (rh - r) : T(0.0);
    for (size_t j = 0; j < x.output_pin_load_N.size(); ++j) {
      const T& f = x.output_pin_load_N[j];
      if (pins->roller_radius_mm > 0)
        out.output_roller_bearings.push_back(PalmgrenAt(spec.output_roller_bearing, T(v.spin * n_in), f));
      if (!(f > T(0.0))) continue;
      contact(f, conformal, v, int(j), true, pins->roller_radius_mm <= 0);
    }
  }
  out.crank = PalmgrenAt(spec.crank_bearing, T(input_speed_rpm * double(d.rollers) / d.teeth), x.crank_bearing_load_N);
  return out;
}

/// The losses of `k` with the oil in state `oil` (contact::OilStateAt).
template <typename T>
CycloidAngleLossesTpl<T> LossesAt(const CrankKinematics<T>& k, const CycloidLubricationSpec& spec,
                                  const contact::OilState<T>& oil) {
  CycloidAngleLossesTpl<T> out;
  for (const auto& b : k.ring_pin_bearings)
    out.ring_pin_bearings += PalmgrenPowerLoss(spec.ring_pin_bearing, b, oil.nu, oil.nu_2_3) * T(1e-3);
  for (const auto& b : k.output_roller_bearings)
    out.output_roller_bearings += PalmgrenPowerLoss(spec.output_roller_bearing, b, oil.nu, oil.nu_2_3) * T(1e-3);
  for (const auto& c : k.contacts) {
    const T h = c.film ? T(c.film_unit_mm * oil.film_scale) : T(0.0);
    if (c.film && spec.rolling_loss)
      (c.output ? out.output_pins_rolling : out.ring_pins_rolling) += c.rolling_unit_W * oil.rolling_scale;
    const T lambda = contact::FilmParameter(h, T(spec.composite_roughness_mm));
    if (out.min_lambda_pin < 0 || Value(lambda) < out.min_lambda) {
      out.min_lambda = Value(lambda);
      out.min_film_mm = Value(h);
      out.min_lambda_pin = c.pin;
      out.min_at_output_pin = c.output;
    }
    if (c.slides)
      (c.output ? out.output_pins_sliding : out.ring_pins_sliding) +=
          contact::FrictionCoefficient(spec.friction, lambda) * c.sliding_per_mu_W;
  }
  out.crank_bearing = PalmgrenPowerLoss(spec.crank_bearing, k.crank, oil.nu, oil.nu_2_3) * T(1e-3);
  return out;
}

/// The losses of one disc at one crank angle (its loads `x`), at input speed n_in [rpm] and oil
/// temperature [°C]: KinematicsAtCrankAngle, then LossesAt. `pins` absent: the output pins' contacts
/// are not modelled (no radii given).
/// @tparam T double or ceres::Jet (the design's and the temperature's derivatives).
template <typename T>
CycloidAngleLossesTpl<T> LossesAtCrankAngle(const DriveTpl<T>& d, const CycloidLubricationSpec& spec, double e_star,
                                            const MeshLubricationLoadsTpl<T>& x,
                                            const std::optional<OutputPinContactTpl<T>>& pins, double input_speed_rpm,
                                            const T& oil_C) {
  return LossesAt(KinematicsAtCrankAngle(d, spec, e_star, x, pins, input_speed_rpm), spec,
                  contact::OilStateAt(spec.oil, oil_C));
}

inline CycloidAngleLosses LossesAtCrankAngle(const Drive& d, const CycloidLubricationSpec& spec, double e_star,
                                             const MeshLubricationLoads& x, const std::optional<OutputPinContact>& pins,
                                             double input_speed_rpm, double oil_C) {
  return LossesAtCrankAngle<double>(d, spec, e_star, x, pins, input_speed_rpm, oil_C);
}

/// KinematicsAtCrankAngle at every crank angle of `loads` (a whole revolution's pattern,
/// LubricationLoadsOverRevolution) at input speed n_in [rpm]: once for every oil temperature.
template <typename T>
std::vector<CrankKinematics<T>> RevolutionKinematics(const DriveTpl<T>& d, const CycloidLubricationSpec& spec,
                                                     double e_star, const std::vector<MeshLubricationLoadsTpl<T>>& loads,
                                                     const std::optional<OutputPinContactTpl<T>>& pins,
                                                     double input_speed_rpm) {
  std::vector<CrankKinematics<T>> out;
  for (const auto& x : loads) out.push_back(KinematicsAtCrankAngle(d, spec, e_star, x, pins, input_speed_rpm));
  return out;
}

/// One disc's mean power loss [W] over a revolution's kinematics (RevolutionKinematics) at oil
/// temperature [°C].
template <typename T>
T MeanLoss(const std::vector<CrankKinematics<T>>& kinematics, const CycloidLubricationSpec& spec, const T& oil_C) {
  const contact::OilState<T> oil = contact::OilStateAt(spec.oil, oil_C);
  T sum(0.0);
  for (const auto& k : kinematics) sum += LossesAt(k, spec, oil).total();
  return kinematics.empty() ? sum : sum / T(double(kinematics.size()));
}

}  // namespace camopt::cycloid
