// The lobe cam reducer's losses from the lubricant up: per roller–cam contact the sliding and
// entraining speeds, the EHL film and λ, the friction by regime, and the rolling bearings' losses,
// summed into the power lost and the efficiency at one input angle (docs/lubrication.md).
//
// Kinematics in the cam frame (the file comment of life.h): the turret turns relative to the cam at
// ψ' ω_in about the pitch point I, so a roller centre O moves at v_O = ψ' ρ ω_in, ρ = |I − O|, normal
// to I − O. The contact point P = O + r_r d (d = unit(I − O)) follows the normal of the pitch curve,
// which turns at κ v_O (κ the pitch curve's signed curvature, contact.h), so P runs along the cam at
//     v_c = v_O (1 − r_r κ)                         (1/κ − r_r the cam's own radius at P).
// A roller turning on its pin (needle-mounted) rolls on the cam without sliding: both surfaces
// move at v_c relative to P, so
//     v_s = 0,  u_e = |v_c|,  the roller turning at ψ' |ρ − r_r| / r_r relative to its pin.
// A roller fixed in the turret is a point of the turret: P moves at ψ' (ρ − r_r) ω_in relative to
// the cam (|I − P| = ρ − r_r), which is the sliding speed; relative to P its surface moves at
// v_O (1 − r_r/ρ) − v_c and the cam's at −v_c, so
//     v_s = ψ' |ρ − r_r| ω_in,  u_e = |v_O (1 + r_r/ρ − 2 r_r κ)| / 2.
//
// Losses at one angle (first order in the friction: the loads are those of the frictionless law,
// forces.h or the compliant contacts, as the rest of the analysis uses them):
//   sliding        μ(λ) F v_s per contact (model/contact/lubricated_friction.h), fixed rollers only;
//   rolling        2 u F_R per loaded contact with a film, F_R Goksem & Hargreaves' rolling
//                  (Poiseuille) force on the same R' and w' (model/contact/ehl.h), fixed and rotating
//                  rollers alike;
//   roller bearings Palmgren M0 + M1 (model/common/bearing_friction.h) at the roller's speed, every
//                   roller of a turret turning (M0), its contact load as P1 (M1); rotating rollers only;
//   eccentric       Palmgren at the eccentric bearing's speed n_A/m_A ω_in with |G| as P1.
// The film: Pan & Hamrock's line-contact minimum film (model/contact/ehl.h) on R' = r_r (1 − r_r κ)
// (the radius of the Hertz stress, forces.h) and w' = F / L, η0 at the oil's temperature. Not
// modelled: seal drag and churning (stated in the results).
// P_in = P_out + Σ losses defines the input power; the tests check the sliding speeds against the
// bodies' rigid velocities and the losses against the statics with friction forces.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "model/common/bearing_friction.h"
#include "model/common/lubricant.h"
#include "model/common/scalar.h"
#include "model/common/thermal.h"
#include "model/contact/ehl.h"
#include "model/contact/lubricated_friction.h"
#include "model/contact/oil_state.h"
#include "model/lcr/contact.h"
#include "model/lcr/life.h"

namespace camopt::lcr {

/// How the lubricated losses of an LCR are computed (model units).
struct LubricationSpec {
  Lubricant oil;
  contact::RegimeFriction friction;
  double composite_roughness_mm = 0.2e-3 * std::sqrt(2.0);  ///< σ = √(Rq_roller² + Rq_cam²)
  bool rollers_rotate = true;  ///< needle-mounted rollers (rolling) or fixed ones (sliding)
  bool rolling_loss = true;    ///< the contacts' EHL rolling (Poiseuille) loss (false: left out)
  PalmgrenBearing roller_bearing;     ///< every roller's bearing (rotating rollers)
  PalmgrenBearing eccentric_bearing;  ///< the cam's bearing on the eccentric
  bool operator==(const LubricationSpec&) const = default;
};

/// The speeds of one roller–cam contact per unit input speed [mm per rad of input angle]; × ω_in
/// [rad/s] gives mm/s.
template <typename T>
struct ContactSpeeds {
  T sliding{};      ///< |v_s|
  T entraining{};   ///< u_e = |u_roller + u_cam| / 2 relative to the contact point
  T roller_spin{};  ///< the roller's speed relative to its pin per unit input speed [-] (0 when fixed)
};

/// The speeds at `contact`, a contact of side `s` of r (RollerContacts at the same angle).
template <typename T>
CAMOPT_FLATTEN ContactSpeeds<T> RollerContactSpeeds(const Reducer<T>& r, Side s, const RollerContact<T>& contact, const T& theta,
                                     bool rollers_rotate) {
  using std::abs;
  const T rr = r.side(s).roller_radius;
  const T rho = (PitchPointOfCam(r, s, theta) - contact.centre).norm();
  const T psi(std::abs((s == Side::kInput ? 0.0 : OutputSpeedRatio(r)) - CamSpeedRatio(r)));  // ψ'
  const T v_o = psi * rho;
  ContactSpeeds<T> out;
  if (rollers_rotate) {
    out.sliding = T(0.0);
    out.entraining = abs(v_o * (T(1.0) - rr * contact.curvature));
    out.roller_spin = psi * abs(rho - rr) / rr;
  } else {
    out.sliding = psi * abs(rho - rr);
    out.entraining = abs(v_o * (T(1.0) + rr / rho - T(2.0) * rr * contact.curvature)) * T(0.5);
    out.roller_spin = T(0.0);
  }
  return out;
}

/// The power lost at one input angle, by element [W].
template <typename T>
struct AngleLosses {
  T sliding_input{}, sliding_output{};                ///< the fixed rollers' sliding on each cam
  T roller_bearings_input{}, roller_bearings_output{};  ///< the rotating rollers' bearings
  T rolling_input{}, rolling_output{};                  ///< the contacts' EHL rolling loss on each cam
  T eccentric_bearing{};
  T min_lambda{};        ///< λ of the loaded contact with the thinnest film
  int min_lambda_side = 0, min_lambda_roller = -1;  ///< 0 input, 1 output; roller index
  T min_film_mm{};       ///< h_min there
  T total() const {
    return sliding_input + sliding_output + roller_bearings_input + roller_bearings_output + rolling_input +
           rolling_output + eccentric_bearing;
  }
};

/// What the losses at one input angle take from the loads and the kinematics, apart from the oil's
/// temperature (LossesAtAngle in two steps, so that a sweep over the temperature computes it once):
/// each loaded contact's film and rolling loss at unit viscosity η0 = 1 MPa·s (both are a power of
/// η0 alone, model/contact/ehl.h) and its sliding power per unit μ; each roller bearing's speed and
/// load-dependent loss; the eccentric bearing's.
template <typename T>
struct AngleKinematics {
  struct Contact {
    int side = 0, roller = 0;
    bool film = false;        ///< an entraining motion on a convex contact (else boundary friction)
    T film_unit_mm{};         ///< h_min at η0 = 1 MPa·s (0 without a film)
    T rolling_unit_W{};       ///< 2 u F_R at η0 = 1 MPa·s [W] (0 without a film or without the loss)
    T sliding_per_mu_W{};     ///< F |v_s| [W per unit μ] (fixed rollers)
  };
  struct Bearing {
    int side = 0;
    PalmgrenAtSpeed<T> at;
  };
  std::vector<Contact> contacts;  ///< the loaded contacts
  std::vector<Bearing> bearings;  ///< every roller's bearing (rotating rollers)
  PalmgrenAtSpeed<T> eccentric;
};

using contact::OilState;

/// The temperature-free part of the losses at input angle θ under the frictionless loads `loads`
/// (AnalyzeAngle with forces, or the compliant loads) at input speed n_in [rpm]. `e_star` is the
/// material's E* [MPa]. Unloaded contacts carry no film (λ taken over the loaded ones).
template <typename T>
AngleKinematics<T> KinematicsAtAngle(const Reducer<T>& r, const LubricationSpec& spec, double e_star,
                                     const std::vector<RollerContact<T>>& input_contacts,
                                     const std::vector<T>& input_force_N,
                                     const std::vector<RollerContact<T>>& output_contacts,
                                     const std::vector<T>& output_force_N, const T& eccentric_load_N, const T& theta,
                                     const T& input_speed_rpm) {
  AngleKinematics<T> out;
  const T omega = input_speed_rpm * T(2.0 * kPi / 60.0);  // rad/s
  const T alpha(spec.oil.pressure_viscosity_per_MPa);
  // A contact whose load is at the rounding level of the largest (the frictionless law's zero, e.g.
  // a roller on the line of symmetry, computed as ±1e-13 N) carries no film: its rolling loss, which
  // hardly depends on the load (w'^0.0126), would otherwise come and go with the rounding.
  double largest = 0.0;
  for (const auto* forces : {&input_force_N, &output_force_N})
    for (const T& f : *forces) largest = std::max(largest, Value(f));
  const double no_load = 1e-9 * largest;
  out.contacts.reserve(input_contacts.size() + output_contacts.size());
  if (spec.rollers_rotate) out.bearings.reserve(input_contacts.size() + output_contacts.size());
  for (int side = 0; side < 2; ++side) {
    const Side s = side == 0 ? Side::kInput : Side::kOutput;
    const auto& contacts = side == 0 ? input_contacts : output_contacts;
    const auto& forces = side == 0 ? input_force_N : output_force_N;
    const CamSide<T>& cam = r.side(s);
    const T length = cam.contact_length();
    for (size_t k = 0; k < contacts.size(); ++k) {
      const ContactSpeeds<T> v = RollerContactSpeeds(r, s, contacts[k], theta, spec.rollers_rotate);
      const T f = forces[k];
      if (spec.rollers_rotate)
        out.bearings.push_back({side, PalmgrenAt(spec.roller_bearing, T(v.roller_spin * input_speed_rpm),
                                                 IfThenElse(Compare::kGreater, f, 0.0, f, T(0.0)))});
      if (!(Value(f) > no_load)) continue;
      typename AngleKinematics<T>::Contact c;
      c.side = side;
      c.roller = int(k);
      const T r_eff = cam.roller_radius * (T(1.0) - cam.roller_radius * contacts[k].curvature);
      const T u = v.entraining * omega;  // mm/s
      // No entraining motion (or an undercut contact, r_eff ≤ 0): no film, boundary friction.
      c.film = Value(u) > 1e-12 && Value(r_eff) > 0.0;
      const T unit(1.0);  // η0 = 1 MPa·s
      if (c.film) c.film_unit_mm = contact::LineContactFilm(unit, u, r_eff, T(f / length), T(e_star), alpha).minimum;
      if (c.film && spec.rolling_loss)
        c.rolling_unit_W =
            contact::RollingLoss(
                T(contact::LineContactRollingForcePerLength(unit, u, r_eff, T(f / length), T(e_star), alpha) * length),
                u) *
            T(1e-3);
      if (!spec.rollers_rotate) c.sliding_per_mu_W = contact::SlidingLoss(T(1.0), f, T(v.sliding * omega)) * T(1e-3);
      out.contacts.push_back(c);
    }
  }
  const T n_ecc = input_speed_rpm * T(double(r.input.rollers) / r.input.lobes);
  out.eccentric = PalmgrenAt(spec.eccentric_bearing, n_ecc, eccentric_load_N);
  return out;
}

/// The losses of `k` with the oil in state `oil` (contact::OilStateAt).
template <typename T>
CAMOPT_FLATTEN AngleLosses<T> LossesAt(const AngleKinematics<T>& k, const LubricationSpec& spec, const OilState<T>& oil) {
  AngleLosses<T> out;
  for (const auto& b : k.bearings)
    (b.side == 0 ? out.roller_bearings_input : out.roller_bearings_output) +=
        PalmgrenPowerLoss(spec.roller_bearing, b.at, oil.nu, oil.nu_2_3) * T(1e-3);
  bool any = false;
  for (const auto& c : k.contacts) {
    const T h = c.film ? T(c.film_unit_mm * oil.film_scale) : T(0.0);
    if (c.film && spec.rolling_loss)
      (c.side == 0 ? out.rolling_input : out.rolling_output) += c.rolling_unit_W * oil.rolling_scale;
    const T lambda = contact::FilmParameter(h, T(spec.composite_roughness_mm));
    if (!any || Value(lambda) < Value(out.min_lambda)) {
      out.min_lambda = lambda;
      out.min_film_mm = h;
      out.min_lambda_side = c.side;
      out.min_lambda_roller = c.roller;
      any = true;
    }
    if (!spec.rollers_rotate)
      (c.side == 0 ? out.sliding_input : out.sliding_output) +=
          contact::FrictionCoefficient(spec.friction, lambda) * c.sliding_per_mu_W;
  }
  out.eccentric_bearing = PalmgrenPowerLoss(spec.eccentric_bearing, k.eccentric, oil.nu, oil.nu_2_3) * T(1e-3);
  return out;
}

/// The losses at input angle θ under the frictionless loads `loads` (AnalyzeAngle with forces, or
/// the compliant loads) at input speed n_in [rpm] and oil temperature t_oil [°C]: KinematicsAtAngle,
/// then LossesAt. `e_star` is the material's E* [MPa].
template <typename T>
AngleLosses<T> LossesAtAngle(const Reducer<T>& r, const LubricationSpec& spec, double e_star,
                             const std::vector<RollerContact<T>>& input_contacts, const std::vector<T>& input_force_N,
                             const std::vector<RollerContact<T>>& output_contacts,
                             const std::vector<T>& output_force_N, const T& eccentric_load_N, const T& theta,
                             const T& input_speed_rpm, const T& oil_C) {
  return LossesAt(KinematicsAtAngle(r, spec, e_star, input_contacts, input_force_N, output_contacts, output_force_N,
                                    eccentric_load_N, theta, input_speed_rpm),
                  spec, contact::OilStateAt(spec.oil, oil_C));
}

/// The frictionless loads over an input revolution, computed once for every speed and oil temperature.
struct CycleLoads {
  std::vector<double> theta_rad;
  std::vector<std::vector<RollerContact<double>>> input_contacts, output_contacts;
  std::vector<std::vector<double>> input_force_N, output_force_N;
  std::vector<double> eccentric_load_N;  ///< |G|
  double output_torque_Nmm = 0;
};

/// The loads of r at `steps` equally spaced input angles under the load model `model` (life.h
/// LoadsAtAngle; the eccentric's μ of `load` plays no part in them).
/// @throws std::domain_error when a turret cannot carry the torque.
inline CycleLoads SampleCycleLoads(const Reducer<double>& r, const Material& material, const LoadCase& load,
                                   LoadModel model, int steps) {
  CycleLoads out;
  out.output_torque_Nmm = load.output_torque_Nmm;
  for (int i = 0; i < steps; ++i) {
    const double theta = 2.0 * kPi * i / steps;
    const LcrAngleLoads a = LoadsAtAngle(r, material, load, model, theta);
    out.theta_rad.push_back(theta);
    out.input_contacts.push_back(RollerContacts(r, Side::kInput, theta));
    out.output_contacts.push_back(RollerContacts(r, Side::kOutput, theta));
    out.input_force_N.push_back(a.input_force_N);
    out.output_force_N.push_back(a.output_force_N);
    out.eccentric_load_N.push_back(a.eccentric_load_N.norm());
  }
  return out;
}

/// The losses over an input revolution at one operating point.
struct CycleLubrication {
  AngleLosses<double> mean;         ///< each element's mean over the angles [W]; λ the cycle's least
  double min_lambda_theta_rad = 0;  ///< the input angle of the least λ
  double output_power_W = 0;        ///< T_o ω_o
  double efficiency = 0;            ///< P_out / (P_out + mean loss); 0 without output torque
  double kinematic_viscosity_mm2_s = 0;
  /// |mean loss over every angle − mean over every other angle|: the sampling's error estimate [W]
  /// (the mean of a smooth periodic function converges faster than the halved grid's change).
  double sampling_error_W = 0;
};

/// KinematicsAtAngle at every angle of `loads` at input speed n_in [rpm]: computed once for every
/// oil temperature.
inline std::vector<AngleKinematics<double>> CycleKinematics(const Reducer<double>& r, const Material& material,
                                                            const CycleLoads& loads, const LubricationSpec& spec,
                                                            double input_speed_rpm) {
  std::vector<AngleKinematics<double>> out;
  const double e_star = material.composite_modulus_MPa();
  for (size_t i = 0; i < loads.theta_rad.size(); ++i)
    out.push_back(KinematicsAtAngle(r, spec, e_star, loads.input_contacts[i], loads.input_force_N[i],
                                    loads.output_contacts[i], loads.output_force_N[i], loads.eccentric_load_N[i],
                                    loads.theta_rad[i], input_speed_rpm));
  return out;
}

/// The losses over the sampled revolution `loads` (its kinematics `kinematics` at input speed n_in
/// [rpm], CycleKinematics) at oil temperature [°C].
inline CycleLubrication LubricatedCycle(const Reducer<double>& r, const CycleLoads& loads,
                                        const std::vector<AngleKinematics<double>>& kinematics,
                                        const LubricationSpec& spec, double input_speed_rpm, double oil_C) {
  CycleLubrication out;
  const size_t steps = loads.theta_rad.size();
  const OilState<double> oil = contact::OilStateAt(spec.oil, oil_C);
  bool first = true;
  double even_total = 0.0;
  size_t evens = 0;
  for (size_t i = 0; i < steps; ++i) {
    const double theta = loads.theta_rad[i];
    const AngleLosses<double> l = LossesAt(kinematics[i], spec, oil);
    const double n = double(steps);
    out.mean.sliding_input += l.sliding_input / n;
    out.mean.sliding_output += l.sliding_output / n;
    out.mean.roller_bearings_input += l.roller_bearings_input / n;
    out.mean.roller_bearings_output += l.roller_bearings_output / n;
    out.mean.rolling_input += l.rolling_input / n;
    out.mean.rolling_output += l.rolling_output / n;
    out.mean.eccentric_bearing += l.eccentric_bearing / n;
    if (i % 2 == 0) even_total += l.total(), ++evens;
    if (l.min_lambda_roller >= 0 && (first || l.min_lambda < out.mean.min_lambda)) {
      out.mean.min_lambda = l.min_lambda;
      out.mean.min_film_mm = l.min_film_mm;
      out.mean.min_lambda_side = l.min_lambda_side;
      out.mean.min_lambda_roller = l.min_lambda_roller;
      out.min_lambda_theta_rad = theta;
      first = false;
    }
  }
  const double loss = out.mean.total();
  out.sampling_error_W = evens > 0 ? std::abs(loss - even_total / double(evens)) : 0.0;
  const double omega_out = input_speed_rpm * 2.0 * kPi / 60.0 * std::abs(OutputSpeedRatio(r));
  out.output_power_W = loads.output_torque_Nmm * 1e-3 * omega_out;
  out.efficiency = out.output_power_W > 0.0 ? out.output_power_W / (out.output_power_W + loss) : 0.0;
  out.kinematic_viscosity_mm2_s = oil.nu;
  return out;
}

/// The losses over the sampled revolution `loads` at input speed n_in [rpm] and oil temperature [°C].
inline CycleLubrication LubricatedCycle(const Reducer<double>& r, const Material& material, const CycleLoads& loads,
                                        const LubricationSpec& spec, double input_speed_rpm, double oil_C) {
  return LubricatedCycle(r, loads, CycleKinematics(r, material, loads, spec, input_speed_rpm), spec, input_speed_rpm,
                         oil_C);
}

/// LubricatedCycle of the loads at `load`'s torque over `steps` angles.
inline CycleLubrication LubricatedCycle(const Reducer<double>& r, const Material& material, const LoadCase& load,
                                        LoadModel model, const LubricationSpec& spec, double input_speed_rpm,
                                        double oil_C, int steps) {
  return LubricatedCycle(r, material, SampleCycleLoads(r, material, load, model, steps), spec, input_speed_rpm, oil_C);
}

/// An LCR's lubricated operating point over T (double or ceres::Jet: the sizing's derivatives):
/// the rigid, frictionless loads at `steps` equally spaced input angles (AnalyzeAngle), the mean of
/// LossesAtAngle over them at the oil temperature given or of the housing's balance (model/common/
/// thermal.h, its derivative implicit), and η = P_out/(P_out + P_loss). `solved`: the balance of the
/// same design already solved on values, so that the losses over T are evaluated once, at its
/// temperature (the derivatives' pass costs one loss evaluation instead of the solve's dozen).
template <typename T>
struct RigidLubricatedPoint {
  T efficiency{}, loss_W{}, oil_C{};
  bool found = false;  ///< false: no thermal equilibrium below the limit (`why`)
  std::string why;
  ThermalPoint<double> balance;  ///< the housing's balance on values (T = double, no given temperature)
};
template <typename T>
RigidLubricatedPoint<T> LubricatedRigidCycle(const Reducer<T>& r, const Material& material, double output_torque_Nmm,
                                             const LubricationSpec& spec, double input_speed_rpm,
                                             std::optional<double> temperature_C, const HousingCooling& cooling,
                                             double limit_C, int steps,
                                             const ThermalPoint<double>* solved = nullptr) {
  const LoadCase load{output_torque_Nmm, 0.0, 0.0};
  const double e_star = material.composite_modulus_MPa();
  std::vector<AngleKinematics<T>> kinematics;  // once for every temperature; the loads are not kept
  kinematics.reserve(size_t(steps));
  if constexpr (std::is_same_v<T, double>) {
    RigidLoadsSweep loads(r, load);  // AnalyzeAngle's numbers on the cycle's buffers (cycle.h)
    for (int i = 0; i < steps; ++i) {
      const double theta = 2.0 * kPi * i / steps;
      loads.At(theta);
      kinematics.push_back(KinematicsAtAngle(r, spec, e_star, loads.input_contacts, loads.input_force_N,
                                             loads.output_contacts, loads.output_force_N,
                                             loads.eccentric_load_N.norm(), theta, input_speed_rpm));
    }
  } else {
    for (int i = 0; i < steps; ++i) {
      const T theta(2.0 * kPi * i / steps);
      const AngleLoads<T> a = AnalyzeAngle(r, material, load, theta, {true, false, true});  // G needs the last stage
      kinematics.push_back(KinematicsAtAngle(r, spec, e_star, a.input.contacts, a.input.force, a.output.contacts,
                                             a.output.force, a.eccentric_load.norm(), theta, T(input_speed_rpm)));
    }
  }
  const auto loss = [&](const T& t) {
    const OilState<T> oil = contact::OilStateAt(spec.oil, t);
    T sum(0.0);
    for (const AngleKinematics<T>& k : kinematics) sum += LossesAt(k, spec, oil).total();
    return sum / T(double(kinematics.size()));
  };
  RigidLubricatedPoint<T> out;
  if (temperature_C) {
    out.oil_C = T(*temperature_C);
    out.loss_W = loss(out.oil_C);
    out.found = true;
  } else {
    const ThermalPoint<T> p =
        solved ? OperatingPointOver<T>(loss, cooling, *solved) : SolveOperatingTemperature<T>(loss, cooling, limit_C);
    if constexpr (std::is_same_v<T, double>) out.balance = p;
    out.found = p.found;
    out.why = p.why;
    out.oil_C = p.temperature_C;
    out.loss_W = p.loss_W;
  }
  const double omega_out = input_speed_rpm * 2.0 * kPi / 60.0 * std::abs(OutputSpeedRatio(r));
  const T output_W(output_torque_Nmm * 1e-3 * omega_out);
  out.efficiency = output_W / (output_W + out.loss_W);
  return out;
}

}  // namespace camopt::lcr
