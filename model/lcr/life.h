// Bearing loads and speeds of the LCR for the rating life (model/common/bearing_life.h, ISO 281):
// the rollers of the two turrets (needle / cam-follower bearings on pins in the turrets) and the
// eccentric bearing that carries the cam on the input shaft's eccentric. docs/life.md, "LCR".
//
// Roller spin (pure rolling on the cam). In the cam frame the turret turns at ψ' = dψ/dθ relative
// to the cam about the pitch point I (Aronhold–Kennedy: I is the instant centre of the turret
// relative to the cam; docs/papers.md §1), so a roller centre O moves at ψ' |I − O|. Rolling without
// sliding at the contact point P = O + r_r d (d = unit(I − O)) gives the roller's angular speed in
// the cam frame ψ' ρ / r_r, ρ = |I − O|, and relative to its pin (the turret)
//     ω_roller / ω_in = ψ' (ρ − r_r) / r_r,     ρ² = r_d² + (e k)² − 2 r_d e k c,
// c the cosine between the roller and the eccentric direction, k = n/(n − m). Over a whole period
// of c, ⟨ρ⟩ = (2/π)(A + B) E(2√(AB)/(A + B)) (A = r_d, B = e k, E the complete elliptic integral of
// the second kind), so a roller turns ψ' (⟨ρ⟩ − r_r)/r_r times per input revolution.
// ψ' = (n_A − m_A)/m_A (input cam), n_A (n_B − m_B)/(m_A n_B) (output cam): the turret's speed
// relative to the cam (kinematics.h). The eccentric bearing turns at ω_in − ω_c = (n_A/m_A) ω_in.
//
// Load periods. Every roller of a turret carries the same load as a function of its phase
// φ (the angle between the eccentric and the roller), which advances at q = 1 (input turret) or
// q = n_A m_B/(m_A n_B) (output turret) per input radian: one load period of a roller is 2π/q of
// input angle (not one input revolution for the output rollers). The eccentric load |G| repeats
// when both turrets' roller patterns do, every 2π lcm(m_A, m_B)/(n_A m_B) of input angle; with a cam
// weight (fixed in the frame) also a whole number of input revolutions must pass. Each bearing's
// load is sampled over its own period so that the p-mean is that of the long-run load.
#pragma once

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "model/common/bearing_life.h"
#include "model/common/scalar.h"
#include "model/lcr/cycle.h"
#include "model/lcr/forces.h"
#include "model/lcr/transmission_error.h"

namespace camopt::lcr {

/// The bearings of the LCR whose life is computed.
enum class LcrBearing { kInputRoller, kOutputRoller, kEccentric };

/// Roller forces, eccentric load and input torque at one input angle, under either load model.
struct LcrAngleLoads {
  std::vector<double> input_force_N, output_force_N;  ///< per roller of each turret
  Vec2<double> eccentric_load_N{0.0, 0.0};            ///< G, the cam's force on the eccentric
  double input_torque_Nmm = 0.0;                      ///< T_in = (F_t + μ |F_r|) e
};

/// The loads at input angle θ [rad]: the rigid law of forces.h (AnalyzeAngle) or the compliant
/// contacts of transmission_error.h (CompliantAtAngle), the eccentric load G = Σ F_k d_k + weight
/// and T_in as in AnalyzeCycleCompliant. At zero output torque the roller forces are 0.
/// @throws std::domain_error when a turret cannot carry the torque.
inline LcrAngleLoads LoadsAtAngle(const Reducer<double>& r, const Material& material, const LoadCase& load,
                                  LoadModel model, double theta) {
  LcrAngleLoads out;
  if (model == LoadModel::kRigid || load.output_torque_Nmm == 0.0) {
    const AngleLoads<double> a = AnalyzeAngle(r, material, load, theta, {true, false, true});
    out.input_force_N = a.input.force;
    out.output_force_N = a.output.force;
    out.eccentric_load_N = a.eccentric_load;
    out.input_torque_Nmm = a.input_torque;
    return out;
  }
  const double sense = LoadedArmSign(r, Side::kOutput);
  const CompliantAngle<double> c = CompliantAtAngle<double>(r, material, theta, sense * load.output_torque_Nmm, nullptr);
  out.input_force_N = c.force_input;
  out.output_force_N = c.force_output;
  Vec2<double> g(0.0, -load.cam_weight_N);
  for (auto [side, forces] : {std::pair{Side::kInput, &c.force_input}, std::pair{Side::kOutput, &c.force_output}}) {
    const auto contacts = RollerContacts(r, side, theta);
    for (size_t k = 0; k < contacts.size(); ++k) g += (*forces)[k] * contacts[k].direction;
  }
  out.eccentric_load_N = g;
  const Vec2<double> u = U(theta);
  out.input_torque_Nmm = InputTorque(-g.dot(Perp(u)), g.dot(u), load.friction_coefficient, r.eccentricity);
  return out;
}

/// ψ' = |dψ/dθ|: the turret's speed relative to the cam per unit input speed (kinematics.h).
inline double TurretSpeedRelativeToCam(const Reducer<double>& r, Side s) {
  const double turret = s == Side::kInput ? 0.0 : OutputSpeedRatio(r);
  return std::abs(turret - CamSpeedRatio(r));
}

/// Roller k's speed relative to its pin per unit input speed at input angle θ: ψ' |ρ − r_r| / r_r
/// (see the file comment), over the scalar T (the sizing's rows differentiate it through e, r_d, r_r).
/// ψ' is kinematic (lobe and roller counts only). |ρ − r_r| is smooth where ρ > r_r, which holds
/// wherever the pitch curve does not loop round the roller (lcr::CheckDesign's pitch-point clearance).
template <typename T>
CAMOPT_FLATTEN T RollerSpinRate(const Reducer<T>& r, Side s, const T& theta, int roller) {
  using std::abs;
  const CamSide<T>& c = r.side(s);
  const T rho = (PitchPointOfCam(r, s, theta) - RollerCentres(r, s, theta)[size_t(roller)]).norm();
  const T psi_prime(std::abs((s == Side::kInput ? 0.0 : OutputSpeedRatio(r)) - CamSpeedRatio(r)));
  return psi_prime * abs(rho - c.roller_radius) / c.roller_radius;
}

/// The bearing's speed relative to its seat per unit input speed at input angle θ (for the
/// rollers, roller 0 of the turret): ψ' |ρ − r_r| / r_r for a roller (see the file comment),
/// n_A/m_A for the eccentric bearing.
inline double BearingSpinRate(const Reducer<double>& r, LcrBearing b, double theta) {
  if (b == LcrBearing::kEccentric) return double(r.input.rollers) / r.input.lobes;
  return RollerSpinRate(r, b == LcrBearing::kInputRoller ? Side::kInput : Side::kOutput, theta, 0);
}

/// The input angle [rad] over which the bearing's load repeats (see the file comment): 2π for an
/// input roller, 2π m_A n_B/(n_A m_B) for an output roller, 2π lcm(m_A, m_B)/(n_A m_B) for the
/// eccentric bearing, times the smallest whole factor that makes it a whole number of input
/// revolutions when the cam has a weight.
inline double LoadPeriodRad(const Reducer<double>& r, LcrBearing b, bool cam_weight) {
  const long ma = r.input.lobes, na = r.input.rollers, mb = r.output.lobes, nb = r.output.rollers;
  if (b == LcrBearing::kInputRoller) return 2 * kPi;
  if (b == LcrBearing::kOutputRoller) return 2 * kPi * double(ma * nb) / double(na * mb);
  // Period / 2π = lcm(m_A, m_B) / (n_A m_B) = num/den in lowest terms; with a weight, num turns.
  const long l = std::lcm(ma, mb), d = na * mb, g = std::gcd(l, d);
  const long num = l / g, den = d / g;
  return 2 * kPi * (cam_weight ? double(num) : double(num) / double(den));
}

/// Loads of one bearing sampled over its load period, with the spin rate at each sample.
struct BearingLoadSamples {
  double period_rad = 0.0;         ///< input angle sampled, [0, period)
  std::vector<double> load_N;      ///< radial load at θ_k = period k / N
  std::vector<double> spin_rate;   ///< bearing speed / input speed at θ_k
  double mean_input_torque_Nmm = 0.0;  ///< mean T_in over the samples (eccentric only)
};

/// Number of samples over a period: steps per input revolution, at least 12.
inline int SamplesOverPeriod(double period_rad, int steps_per_revolution) {
  return std::max(12, int(std::ceil(steps_per_revolution * period_rad / (2 * kPi) - 1e-9)));
}

/// The bearing's load over its load period at `steps_per_revolution` samples per input revolution:
/// roller 0's force (every roller of a turret carries the same load over its period), or |G| for the
/// eccentric bearing. The loads come from one force analysis per sample at this load case (no
/// scaling from another torque: the compliant model is not linear in the torque); under the rigid
/// law on the structure-of-arrays path of cycle.h (RigidRollerZeroLoads: the same numbers as
/// LoadsAtAngle and BearingSpinRate, a fraction of the work).
/// @throws std::domain_error when a turret cannot carry the torque.
inline BearingLoadSamples SampleBearingLoad(const Reducer<double>& r, const Material& material, const LoadCase& load,
                                            LoadModel model, LcrBearing b, int steps_per_revolution) {
  BearingLoadSamples out;
  out.period_rad = LoadPeriodRad(r, b, load.cam_weight_N > 0);
  const int n = SamplesOverPeriod(out.period_rad, steps_per_revolution);
  double torque_sum = 0.0;
  if (model == LoadModel::kRigid || load.output_torque_Nmm == 0.0) {  // LoadsAtAngle's rigid branch
    std::vector<double> theta(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) theta[size_t(k)] = out.period_rad * k / n;
    const RollerZeroLoads z = RigidRollerZeroLoads(r, load, theta);
    for (size_t k = 0; k < size_t(n); ++k) {
      double f = 0.0;
      if (b == LcrBearing::kInputRoller) f = z.input_force_N[k];
      if (b == LcrBearing::kOutputRoller) f = z.output_force_N[k];
      if (b == LcrBearing::kEccentric) f = z.eccentric_load_N[k].norm();
      out.load_N.push_back(std::max(f, 0.0));
      out.spin_rate.push_back(b == LcrBearing::kInputRoller    ? z.input_spin_rate[k]
                              : b == LcrBearing::kOutputRoller ? z.output_spin_rate[k]
                                                               : BearingSpinRate(r, b, theta[k]));
      torque_sum += z.input_torque_Nmm[k];
    }
    out.mean_input_torque_Nmm = torque_sum / n;
    return out;
  }
  for (int k = 0; k < n; ++k) {
    const double theta = out.period_rad * k / n;
    const LcrAngleLoads a = LoadsAtAngle(r, material, load, model, theta);
    double f = 0.0;
    if (b == LcrBearing::kInputRoller) f = a.input_force_N[0];
    if (b == LcrBearing::kOutputRoller) f = a.output_force_N[0];
    if (b == LcrBearing::kEccentric) f = a.eccentric_load_N.norm();
    out.load_N.push_back(std::max(f, 0.0));
    out.spin_rate.push_back(BearingSpinRate(r, b, theta));
    torque_sum += a.input_torque_Nmm;
  }
  out.mean_input_torque_Nmm = torque_sum / n;
  return out;
}

/// One line of a duty cycle in model units: output torque, input speed, time share.
using LcrDutyLine = OperatingLine;

/// A bearing's life over a duty cycle (docs/life.md, "LCR"); R is the mean spin rate over the
/// load period.
using LcrBearingLife = BearingLifeOverCycle;

/// The life of one bearing of r over the duty cycle: per line one force analysis per sample at the
/// line's torque over the bearing's load period (SampleBearingLoad), the revolution-weighted
/// equivalent load P_i, and Palmgren–Miner over the lines with speeds t_i n_i R
/// (DutyCycleLifeHours of model/common/bearing_life.h). `load` gives friction and cam weight; its
/// torque is replaced by each line's. The lines are checked as ValidateDutyCycle does.
/// @throws std::domain_error when a turret cannot carry the torque; std::invalid_argument for bad lines.
inline LcrBearingLife BearingLifeOverDutyCycle(const Reducer<double>& r, const Material& material, LoadCase load,
                                               LoadModel model, LcrBearing b, double dynamic_rating_N,
                                               BearingKind kind, const std::vector<LcrDutyLine>& lines,
                                               int steps_per_revolution) {
  LcrBearingLife out;
  for (const LcrDutyLine& line : lines) {
    load.output_torque_Nmm = line.output_torque_Nmm;
    const BearingLoadSamples x = SampleBearingLoad(r, material, load, model, b, steps_per_revolution);
    out.line_equivalent_load_N.push_back(EquivalentLoad(x.load_N, x.spin_rate, kind));
    out.max_load_N = std::max(out.max_load_N, *std::max_element(x.load_N.begin(), x.load_N.end()));
    double spin = 0.0;
    for (double w : x.spin_rate) spin += w;
    out.revolutions_per_input_revolution = spin / double(x.spin_rate.size());  // kinematic: every line alike
  }
  std::vector<double> shares, speeds;
  for (const LcrDutyLine& line : lines) shares.push_back(line.time_share), speeds.push_back(line.input_speed_rpm);
  CombineDutyCycleLines(dynamic_rating_N, kind, shares, speeds, out);
  return out;
}

}  // namespace camopt::lcr
