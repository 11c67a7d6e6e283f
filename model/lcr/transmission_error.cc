// AnalyzeTransmissionError (declared in transmission_error.h): sensitivities by ceres::Jet over
// chunks of eight deviations, and the Monte-Carlo run of the exact model.
#include "model/lcr/transmission_error.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <ceres/jet.h>

namespace camopt::lcr {
namespace {

using tolerance::kArcsecPerRad;
using tolerance::Percentile;
using tolerance::Uniform01;

Vec2<double> LoadDirection(const Reducer<double>& r, const Material& material, double torque_Nmm, double theta) {
  return EccentricLoadDirection(r, material, torque_Nmm, theta);
}

}  // namespace

CycleSeries AnalyzeCycleCompliant(const Reducer<double>& r, const Material& material, const LoadCase& load,
                                  int steps, const Stages& stages, const std::function<void(double)>& progress) {
  CycleSeries s;
  const double sense = LoadedArmSign(r, Side::kOutput);
  const double e_star = material.composite_modulus_MPa();
  const double ratio = std::abs(SpeedReductionRatio(r));
  for (auto [series, cam] : {std::pair{&s.input, &r.input}, std::pair{&s.output, &r.output}})
    series->roller_force_N.Reset(cam->rollers, steps);
  for (int i = 0; i < steps; ++i) {
    const double theta = 2 * kPi * i / steps;
    s.theta_rad.push_back(theta);
    const CompliantAngle<double> c = CompliantAtAngle<double>(r, material, theta, sense * load.output_torque_Nmm, nullptr);
    Vec2<double> g(0.0, -load.cam_weight_N);
    for (auto [series, side, forces] : {std::tuple{&s.input, Side::kInput, &c.force_input},
                                        std::tuple{&s.output, Side::kOutput, &c.force_output}}) {
      const CamSide<double>& cam = r.side(side);
      const auto contacts = RollerContacts(r, side, theta);
      int actuating = 0;
      double max_force = 0, torque = 0, max_stress = 0;
      for (size_t k = 0; k < contacts.size(); ++k) {
        const double f = (*forces)[k];
        actuating += f > 0;  // Palmgren: exactly 0 once separated
        max_force = std::max(max_force, f);
        torque += f * contacts[k].arm;
        g += f * contacts[k].direction;
        if (stages.stress && f > 0) {
          const double r_eff = cam.roller_radius * (1.0 - cam.roller_radius * contacts[k].curvature);
          max_stress = std::max(max_stress, r_eff > 0 ? contact::LineContactPeakPressure(f, cam.contact_length(), r_eff, e_star)
                                                      : kInf);
        }
      }
      series->roller_force_N.AddRow(*forces);
      series->actuating.push_back(actuating);
      series->max_force_N.push_back(max_force);
      series->max_stress_MPa.push_back(max_stress);
      series->turret_torque_Nmm.push_back(std::abs(torque));
    }
    double tangential = 0, radial = 0, input_torque = 0, efficiency = 0;
    if (stages.efficiency) {
      const Vec2<double> u = U(theta);
      tangential = -g.dot(Perp(u));
      radial = g.dot(u);
      input_torque = InputTorque(tangential, radial, load.friction_coefficient, r.eccentricity);
      efficiency = Efficiency(load.output_torque_Nmm, input_torque, ratio);
    }
    s.tangential_force_N.push_back(tangential);
    s.radial_force_N.push_back(radial);
    s.input_torque_Nmm.push_back(input_torque);
    s.efficiency.push_back(efficiency);
    if (progress && (i % 64 == 0 || i + 1 == steps)) progress(double(i + 1) / steps);
  }
  return s;
}

std::vector<ToleranceParameter> ToleranceParameters(const Reducer<double>& r, const ToleranceBands& b) {
  std::vector<ToleranceParameter> p;
  if (b.eccentricity_mm > 0) p.push_back({0, 0, -1, b.eccentricity_mm});
  if (b.turret_radius_mm > 0)
    for (int s : {0, 1}) p.push_back({1, s, -1, b.turret_radius_mm});
  if (b.roller_diameter_mm > 0)
    for (int s : {0, 1})
      for (int k = 0; k < (s == 0 ? r.input.rollers : r.output.rollers); ++k)
        p.push_back({2, s, k, 0.5 * b.roller_diameter_mm});
  if (b.roller_pitch_rad > 0)
    for (int s : {0, 1})
      for (int k = 0; k < (s == 0 ? r.input.rollers : r.output.rollers); ++k)
        p.push_back({3, s, k, b.roller_pitch_rad});
  if (b.profile_mm > 0)
    for (int s : {0, 1}) p.push_back({4, s, -1, b.profile_mm});
  if (b.bearing_clearance_mm > 0) p.push_back({5, 0, -1, b.bearing_clearance_mm});
  return p;
}

Deviations<double> SampleDeviations(const Reducer<double>& r, const std::vector<ToleranceParameter>& params,
                                    std::uint64_t& state, std::vector<double>* values) {
  Deviations<double> dev;
  if (values) values->clear();
  for (const ToleranceParameter& p : params) {
    const double u = Uniform01(state);
    const double v = p.key == 5 ? u * p.band : (2.0 * u - 1.0) * p.band;
    AddDeviation(dev, r, p, v);
    if (values) values->push_back(v);
  }
  return dev;
}

std::vector<double> ExactTransmissionError(const Reducer<double>& r, const Material& material,
                                           const Deviations<double>& dev, double torque_Nmm,
                                           const std::vector<double>& theta) {
  const double t = LoadedArmSign(r, Side::kOutput) * torque_Nmm;
  std::vector<double> te;
  for (double th : theta) {
    const Vec2<double> dir = LoadDirection(r, material, torque_Nmm, th);
    te.push_back(CompliantAtAngle<double>(r, material, th, t, &dev, dir).output_rotation -
                 CompliantAtAngle<double>(r, material, th, t, nullptr).output_rotation);
  }
  return te;
}

TransmissionErrorResult AnalyzeTransmissionError(const Reducer<double>& r, const Material& material,
                                                 const ToleranceBands& bands,
                                                 const TransmissionErrorOptions& o) {
  using J = ceres::Jet<double, 8>;
  TransmissionErrorResult res;
  const int na = o.angle_steps;
  const double sense = LoadedArmSign(r, Side::kOutput);
  const double torque = sense * o.output_torque_Nmm, torque_lm = sense * o.lost_motion_torque_Nmm;
  const std::vector<ToleranceParameter> params = ToleranceParameters(r, bands);
  const size_t np = params.size();
  std::vector<Vec2<double>> dir(na);
  std::vector<std::vector<double>> s(na, std::vector<double>(np, 0.0));  // S_p(θ_i) [rad per unit]
  std::vector<double> lm_nominal(na);
  for (int i = 0; i < na; ++i) {
    const double th = 2 * kPi * i / na;
    res.theta_rad.push_back(th);
    dir[i] = LoadDirection(r, material, o.output_torque_Nmm, th);
    res.nominal_rotation_rad.push_back(CompliantAtAngle<double>(r, material, th, torque, nullptr).output_rotation);
    lm_nominal[i] = sense * (CompliantAtAngle<double>(r, material, th, torque_lm, nullptr).output_rotation -
                             CompliantAtAngle<double>(r, material, th, -torque_lm, nullptr).output_rotation);
    for (size_t c0 = 0; c0 < np; c0 += 8) {
      Deviations<J> dev;
      for (size_t j = c0; j < std::min(np, c0 + 8); ++j) AddDeviation(dev, r, params[j], J(0.0, int(j - c0)));
      const J rot = CompliantAtAngle<J>(r, material, th, torque, &dev, dir[i]).output_rotation;
      for (size_t j = c0; j < std::min(np, c0 + 8); ++j) s[i][j] = rot.v[j - c0];
    }
  }
  res.lost_motion_nominal_arcmin = *std::max_element(lm_nominal.begin(), lm_nominal.end()) * kArcsecPerRad / 60;

  // Linear model (model/common/tolerance_stats.h): uniform deviations, E[t²] = band²/3 (the
  // clearance, uniform on 0 … c, too); the worst case of the separable linear peak-to-peak.
  tolerance::LinearStatisticsOf(s, params, ToleranceKeys(), res);

  // Monte-Carlo with the exact model.
  const std::vector<double> lm = tolerance::RunMonteCarlo(
      o.samples, o.seed, s,
      [&](std::uint64_t& state, std::vector<double>* values) { return SampleDeviations(r, params, state, values); },
      [&](const Deviations<double>& dev, std::vector<double>& te) {
        double lm_max = -kInf;
        for (int i = 0; i < na; ++i) {
          const double th = res.theta_rad[i];
          te[i] = CompliantAtAngle<double>(r, material, th, torque, &dev, dir[i]).output_rotation -
                  res.nominal_rotation_rad[i];
          if (torque_lm != 0.0)
            lm_max = std::max(lm_max, sense * (CompliantAtAngle<double>(r, material, th, torque_lm, &dev, dir[i]).output_rotation -
                                               CompliantAtAngle<double>(r, material, th, -torque_lm, &dev, dir[i]).output_rotation));
        }
        return lm_max;
      },
      o.progress, res);
  if (o.samples > 0) {
    if (torque_lm != 0.0) {
      res.lost_motion_arcmin = *std::max_element(lm.begin(), lm.end()) * kArcsecPerRad / 60;
      res.lost_motion_p99_arcmin = Percentile(lm, 0.99) * kArcsecPerRad / 60;
    }
  } else {
    res.lost_motion_arcmin = res.lost_motion_p99_arcmin = res.lost_motion_nominal_arcmin;
  }
  return res;
}

}  // namespace camopt::lcr
