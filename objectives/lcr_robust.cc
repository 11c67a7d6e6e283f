// The robust rows and checks of objectives/lcr_robust.h.
#include "objectives/lcr_robust.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <ceres/jet.h>

#include "model/contact/hertz.h"
#include "model/lcr/profile.h"

namespace camopt::objectives {
namespace {

bool OneSided(const lcr::ToleranceParameter& p) { return p.key == 5; }  // clearance 0 … c

// w = ∂W/∂S of a row with sensitivities S (header); sign +1 for an upper limit, −1 for a lower.
std::vector<double> Weights(const LcrRobustRule& rule, const std::vector<lcr::ToleranceParameter>& params,
                            const std::vector<double>& s, double sign) {
  std::vector<double> w(params.size(), 0.0);
  if (rule.method == LcrRobustMethod::kWorstCase) {
    for (size_t p = 0; p < params.size(); ++p) {
      const double y = sign * s[p];
      if (OneSided(params[p]))
        w[p] = y > 0 ? params[p].band : 0.0;
      else
        w[p] = y > 0 ? params[p].band : (y < 0 ? -params[p].band : 0.0);
    }
    return w;
  }
  double var = 0;
  std::vector<double> sigma2(params.size());
  for (size_t p = 0; p < params.size(); ++p) {
    const double b = params[p].band;
    sigma2[p] = OneSided(params[p]) ? b * b / 12.0 : b * b / 3.0;
    var += sigma2[p] * s[p] * s[p];
  }
  const double sd = std::sqrt(var);
  for (size_t p = 0; p < params.size(); ++p) {
    const double mean = OneSided(params[p]) ? 0.5 * params[p].band : 0.0;
    w[p] = mean + (sd > 0 ? rule.k * sigma2[p] * sign * s[p] / sd : 0.0);
  }
  return w;
}

// Roller radius with the deviation of roller k of cam `si` (none when the vector is empty).
template <typename S>
S RollerRadius(const S& nominal, const lcr::Deviations<S>& dev, int si, int k) {
  return dev.roller_radius[si].empty() ? nominal : nominal + dev.roller_radius[si][k];
}

template <typename T>
std::vector<double> Values(const std::vector<T>& v) {
  std::vector<double> out;
  for (const T& x : v) out.push_back(Value(x));
  return out;
}

}  // namespace

template <typename T>
LcrRobustIncrements<T> RobustIncrements(const LcrSizingSpec& spec, const lcr::Reducer<T>& r, lcr::Side side,
                                        double theta, const lcr::SideLoads<T>& sl) {
  const lcr::ToleranceSensitivities<T> s =
      lcr::RollerToleranceSensitivities(r, spec.material, spec.output_torque_Nmm, spec.limits.contact_stress_MPa,
                                        spec.robust->bands, side, theta, sl);
  LcrRobustIncrements<T> inc;
  // W = Σ w_p S_p with w = ∂W/∂S at the values (header): exact value and exact gradient.
  auto apply = [&](const std::vector<T>& row, double sign) {
    const std::vector<double> w = Weights(*spec.robust, s.params, Values(row), sign);
    T sum(0.0);
    for (size_t p = 0; p < row.size(); ++p)
      if (w[p] != 0.0) sum += w[p] * row[p];
    return sum;
  };
  for (const auto& row : s.force) inc.force.push_back(apply(row, 1.0));
  for (const auto& row : s.margin) inc.margin.push_back(apply(row, -1.0));
  return inc;
}

template LcrRobustIncrements<double> RobustIncrements(const LcrSizingSpec&, const lcr::Reducer<double>&, lcr::Side,
                                                      double, const lcr::SideLoads<double>&);
template LcrRobustIncrements<ceres::Jet<double, 6>> RobustIncrements(const LcrSizingSpec&,
                                                                     const lcr::Reducer<ceres::Jet<double, 6>>&,
                                                                     lcr::Side, double,
                                                                     const lcr::SideLoads<ceres::Jet<double, 6>>&);
template LcrRobustIncrements<ceres::Jet<double, 4>> RobustIncrements(const LcrSizingSpec&,
                                                                     const lcr::Reducer<ceres::Jet<double, 4>>&,
                                                                     lcr::Side, double,
                                                                     const lcr::SideLoads<ceres::Jet<double, 4>>&);

double RobustUndercutIncrement(const LcrRobustRule& rule) {
  const double b = rule.bands.profile_mm;
  return rule.method == LcrRobustMethod::kWorstCase ? -b : -rule.k * b / std::sqrt(3.0);
}

LcrRobustCheck RobustGridCheck(const LcrSizingSpec& spec, const lcr::Reducer<double>& r, int steps) {
  LcrRobustCheck c;
  c.steps_per_period = steps;
  c.min_stress_margin = kInf;
  c.undercut_margin_mm = kInf;
  const bool stress = std::isfinite(spec.limits.contact_stress_MPa);
  const lcr::LoadCase load{spec.output_torque_Nmm, 0.0, 0.0};
  for (lcr::Side side : {lcr::Side::kInput, lcr::Side::kOutput}) {
    const lcr::CamSide<double>& cam = r.side(side);
    c.undercut_margin_mm = std::min(c.undercut_margin_mm, lcr::UndercutMargin(cam, r.eccentricity) +
                                                              RobustUndercutIncrement(*spec.robust));
    const double period = LcrLoadPeriod(spec, side);
    for (int i = 0; i < steps; ++i) {
      const double theta = period * (i + 0.5) / steps;
      const lcr::SideLoads<double> sl = lcr::AnalyzeSide(r, spec.material, load, side, theta, lcr::Stages{true, false, false});
      const LcrRobustIncrements<double> inc = RobustIncrements(spec, r, side, theta, sl);
      for (int k = 0; k < cam.rollers; ++k) {
        c.max_force_N = std::max(c.max_force_N, sl.force[k] + inc.force[k]);
        if (!stress || !(sl.force[k] > 0)) continue;
        const double m = LcrStressMargin(spec, cam.contact_length(), cam.roller_radius, sl.force[k],
                                         sl.contacts[k].curvature) + inc.margin[k];
        if (m < c.min_stress_margin) {
          // The margin is (R'/r_r)(1 − p²/p_lim²): the stress it stands for.
          c.min_stress_margin = m;
          const double r_eff = cam.roller_radius * (1.0 - cam.roller_radius * sl.contacts[k].curvature);
          const double q = 1.0 - m * cam.roller_radius / r_eff;
          c.max_stress_MPa = r_eff > 0 && q >= 0 ? spec.limits.contact_stress_MPa * std::sqrt(q) : kInf;
        }
      }
    }
  }
  const LcrLimits& l = spec.limits;
  if (c.max_force_N > l.roller_load_N) c.violations.push_back({"roller_load_N", c.max_force_N, l.roller_load_N});
  if (stress && c.min_stress_margin < 0)
    c.violations.push_back({"contact_stress_MPa", c.max_stress_MPa, l.contact_stress_MPa});
  if (c.undercut_margin_mm < l.undercut_margin_mm)
    c.violations.push_back({"undercut_margin_mm", c.undercut_margin_mm, l.undercut_margin_mm});
  if (!stress) c.min_stress_margin = 0;
  return c;
}

LcrMonteCarloCheck MonteCarloCheck(const LcrSizingSpec& spec, const lcr::Reducer<double>& r, int samples,
                                   std::uint64_t seed, int angle_steps) {
  LcrMonteCarloCheck c;
  c.samples = samples;
  c.seed = seed;
  c.angle_steps = angle_steps;
  c.min_undercut_margin_mm = kInf;
  const LcrLimits& l = spec.limits;
  const double e_star = spec.material.composite_modulus_MPa();
  const double torque = lcr::LoadedArmSign(r, lcr::Side::kOutput) * spec.output_torque_Nmm;
  const lcr::LoadCase load{spec.output_torque_Nmm, 0.0, 0.0};
  struct Angle {
    double theta;
    Vec2<double> dir;
    lcr::AngleLoads<double> rigid;
    lcr::CompliantAngle<double> nominal;
  };
  std::vector<Angle> angles;
  for (int i = 0; i < angle_steps; ++i) {
    const double th = 2 * kPi * i / angle_steps;
    angles.push_back({th, lcr::EccentricLoadDirection(r, spec.material, spec.output_torque_Nmm, th),
                      lcr::AnalyzeAngle(r, spec.material, load, th, lcr::Stages{true, false, false}),
                      lcr::CompliantAtAngle<double>(r, spec.material, th, torque, nullptr)});
  }
  const double undercut[2] = {lcr::UndercutMargin(r.input, r.eccentricity), lcr::UndercutMargin(r.output, r.eccentricity)};
  const std::vector<lcr::ToleranceParameter> params = lcr::ToleranceParameters(r, spec.robust->bands);
  std::uint64_t state = seed;
  for (int m = 0; m < samples; ++m) {
    const lcr::Deviations<double> dev = lcr::SampleDeviations(r, params, state);
    double f_max = 0, p_max = 0, u_min = kInf;
    for (int si = 0; si < 2; ++si) u_min = std::min(u_min, undercut[si] + dev.profile[si]);
    for (const Angle& a : angles) {
      const lcr::CompliantAngle<double> cd = lcr::CompliantAtAngle<double>(r, spec.material, a.theta, torque, &dev, a.dir);
      for (int si = 0; si < 2; ++si) {
        const lcr::CamSide<double>& cam = si == 0 ? r.input : r.output;
        const lcr::SideLoads<double>& rigid = si == 0 ? a.rigid.input : a.rigid.output;
        const std::vector<double>& fd = si == 0 ? cd.force_input : cd.force_output;
        const std::vector<double>& f0 = si == 0 ? a.nominal.force_input : a.nominal.force_output;
        for (int k = 0; k < cam.rollers; ++k) {
          const double f = rigid.force[k] + fd[k] - f0[k];
          f_max = std::max(f_max, f);
          if (!(f > 0)) continue;
          const double rr = RollerRadius(cam.roller_radius, dev, si, k);
          const double r_eff = rr * (1.0 - rr * rigid.contacts[k].curvature);
          p_max = std::max(p_max, r_eff > 0 ? contact::LineContactPeakPressure(f, cam.contact_length(), r_eff, e_star) : kInf);
        }
      }
    }
    c.max_force_N = std::max(c.max_force_N, f_max);
    c.max_stress_MPa = std::max(c.max_stress_MPa, p_max);
    c.min_undercut_margin_mm = std::min(c.min_undercut_margin_mm, u_min);
    double excess = -kInf;
    if (std::isfinite(l.roller_load_N)) excess = std::max(excess, (f_max - l.roller_load_N) / l.roller_load_N);
    if (std::isfinite(l.contact_stress_MPa)) excess = std::max(excess, (p_max - l.contact_stress_MPa) / l.contact_stress_MPa);
    excess = std::max(excess, (l.undercut_margin_mm - u_min) / std::max(l.undercut_margin_mm, 1.0));
    c.violating += excess > 0;
    if (c.worst_sample < 0 || excess > c.worst_relative_excess) c.worst_sample = m, c.worst_relative_excess = excess;
  }
  c.violating_fraction = samples > 0 ? double(c.violating) / samples : 0.0;
  return c;
}

}  // namespace camopt::objectives
