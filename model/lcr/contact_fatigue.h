// Contact fatigue of the LCR's cam surfaces (docs/life.md, "Contact fatigue of the cam surfaces"):
// the peak Hertz contact of a cam over a revolution (whose half-width gives the subsurface stresses
// of model/contact/subsurface.h), and how often a point of the cam's track is over-rolled.
//
// Over-rolling count. In the cam frame the turret turns at ψ' relative to the cam (life.h:
// TurretSpeedRelativeToCam; ψ' = (n_A − m_A)/m_A for the input cam, n_A (n_B − m_B)/(m_A n_B) for
// the output cam), so each of the n rollers of the turret goes ψ' times round the cam's closed
// track per input revolution and a point of the track is over-rolled
//     N_c = n ψ'   times per input revolution
// (LCR II: 13/12 on the input cam, 15·13/180 = 13/12 on the output cam).
//
// Life of the track (stress-life law, model/contact/subsurface.h StressLifeRatio): a point
// over-rolled at peak pressure p0 fails (10%) after N(p0) = N_ref (p_ref/p0)^n over-rollings; over a
// duty cycle of lines (time share t_i, input speed n_i [rpm], the cam's peak pressure p_i at that
// line's torque) Palmgren–Miner gives the damage per hour Σ_i t_i 60 n_i N_c / N(p_i), so
//     L10h = N_ref p_ref^n / (60 N_c Σ_i t_i n_i p_i^n) = N_ref (p_ref/p_eq)^n / (60 n̄ N_c),
// p_eq = (Σ t_i n_i p_i^n / Σ t_i n_i)^(1/n), n̄ = Σ t_i n_i. Every over-rolling is counted at the
// cam's peak pressure of its line: the most loaded point of the track, which every roller passes
// at that pressure when the load shares of the rollers repeat with their phase (conservative where
// they do not).
#pragma once

#include <cmath>
#include <stdexcept>
#include <vector>

#include "model/contact/hertz.h"
#include "model/lcr/contact.h"
#include "model/lcr/cycle.h"
#include "model/lcr/life.h"

namespace camopt::lcr {

/// The contact that sets a cam's largest Hertz line pressure over the sampled revolution.
struct PeakContact {
  int angle = -1, roller = -1;  ///< index into series.theta_rad, roller of the turret (-1: no load)
  double force_N = 0.0;
  double effective_radius_mm = 0.0;  ///< R' = r_r (1 − r_r κ) across rolling (forces.h)
  double pressure_MPa = 0.0;         ///< p0 of the Hertz line contact; +inf on an undercut contact
  double half_width_mm = 0.0;        ///< b = sqrt(4 F R'/(π L E*)) (0 on an undercut contact)
};

/// The peak line contact of cam s in series (the forces of AnalyzeCycle or AnalyzeCycleCompliant,
/// roller_force_N per angle): the loaded contact of the largest p0 = sqrt(F E*/(π L R')), the first
/// of equal ones in angle and roller order.
inline PeakContact FindPeakLineContact(const Reducer<double>& r, Side s, const CycleSeries& series, double e_star) {
  const CamSide<double>& cam = r.side(s);
  const SideSeries& ss = s == Side::kInput ? series.input : series.output;
  const double length = cam.contact_length(), rr = cam.roller_radius;
  PeakContact best;
  for (size_t i = 0; i < series.theta_rad.size(); ++i) {
    const std::vector<RollerContact<double>> rc = RollerContacts(r, s, series.theta_rad[i]);
    const double* f = ss.roller_force_N.row(i);
    for (size_t k = 0; k < rc.size(); ++k) {
      if (!(f[k] > 0)) continue;
      const double r_eff = rr * (1.0 - rr * rc[k].curvature);
      const double p = r_eff > 0 ? contact::LineContactPeakPressure(f[k], length, r_eff, e_star) : kInf;
      if (p > best.pressure_MPa) {
        best = {int(i), int(k), f[k], r_eff, p, 0.0};
        if (std::isfinite(p)) best.half_width_mm = contact::LineContactHalfWidth(f[k], length, r_eff, e_star);
      }
    }
  }
  return best;
}

/// N_c = n ψ': the times a point of cam s's track is over-rolled per input revolution (file comment).
inline double ContactPassesPerInputRevolution(const Reducer<double>& r, Side s) {
  return r.side(s).rollers * TurretSpeedRelativeToCam(r, s);
}

/// The life of a cam's track over a duty cycle (file comment). peak_MPa[i]: the cam's peak
/// pressure at line i's torque; passes: N_c; p_ref, cycles_ref, exponent: the material's S–N point.
struct CamContactLife {
  double equivalent_pressure_MPa = 0.0;  ///< p_eq (0 without load)
  double L10h = 0.0;                     ///< +inf without load, 0 with an undercut (infinite) pressure
};

/// @pre lines as ValidateDutyCycle accepts them (shares summing to 1, some speed > 0), peak_MPa of
/// the same size, each ≥ 0; passes, p_ref, cycles_ref, exponent > 0.
inline CamContactLife CamContactLifeOverDutyCycle(const std::vector<double>& peak_MPa,
                                                  const std::vector<LcrDutyLine>& lines, double passes,
                                                  double p_ref, double cycles_ref, double exponent) {
  if (peak_MPa.size() != lines.size()) throw std::invalid_argument("cam contact life: one peak pressure per line");
  double speed = 0.0, weighted = 0.0;  // Σ t_i n_i and Σ t_i n_i (p_i/p_ref)^n
  for (size_t i = 0; i < lines.size(); ++i) {
    const double w = lines[i].time_share * lines[i].input_speed_rpm;
    speed += w;
    if (w > 0 && peak_MPa[i] > 0) weighted += w * std::pow(peak_MPa[i] / p_ref, exponent);
  }
  CamContactLife out;
  if (!(weighted > 0)) {
    out.L10h = kInf;
    return out;
  }
  out.equivalent_pressure_MPa = p_ref * std::pow(weighted / speed, 1.0 / exponent);
  out.L10h = std::isfinite(weighted) ? cycles_ref / (60.0 * passes * weighted) : 0.0;
  return out;
}

}  // namespace camopt::lcr
