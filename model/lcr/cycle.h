// LCR analysis over one input revolution: per-angle series and their extremes, and smooth
// aggregates of the same quantities for optimizers.
#pragma once

#include <cmath>
#include <functional>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "model/lcr/forces.h"

namespace camopt::lcr {

struct SideSeries {
  std::vector<int> actuating;
  std::vector<double> max_force_N, max_stress_MPa, turret_torque_Nmm;
  std::vector<std::vector<double>> roller_force_N;  // [angle][roller]
};

struct CycleSeries {
  std::vector<double> theta_rad;
  SideSeries input, output;
  std::vector<double> tangential_force_N, radial_force_N, input_torque_Nmm, efficiency;
};

namespace internal {

/// Reusable per-turret buffers of the double fast path of AnalyzeCycle, in structure-of-arrays
/// form so that the per-roller square roots and divisions of one turret run several at a time.
struct TurretBuffers {
  std::vector<double> cx, cy;            // roller centres O_k [mm]
  std::vector<double> arm, dx, dy, kappa;  // a_k, d_k, κ_k (contact.h's RollerContact, without the point)
  std::vector<double> loaded;            // PositivePart(sign · a_k)
  std::vector<double> stress;            // Hertz p_max [MPa]
};

inline void Resize(TurretBuffers& b, int n) {
  for (auto* v : {&b.cx, &b.cy, &b.arm, &b.dx, &b.dy, &b.kappa, &b.loaded, &b.stress}) v->resize(n);
}

/// Roller centres of one turret at θ into b.cx, b.cy: the same expression as RollerCentres.
inline void FillCentres(TurretBuffers& b, const Reducer<double>& r, Side s, double theta) {
  const CamSide<double>& c = r.side(s);
  const double turn = s == Side::kInput ? 0.0 : OutputSpeedRatio(r) * theta;
  for (int i = 0; i < c.rollers; ++i) {
    const Vec2<double> o = c.turret_radius * U(double(2.0 * kPi * i / c.rollers) + turn);
    b.cx[i] = o.x(), b.cy[i] = o.y();
  }
}

/// The per-roller loop of FillContacts over plain arrays (restrict: no aliasing, so it vectorises).
inline void ContactKernel(const CamSide<double> c, double e, double px, double py, double ex, double ey,
                          double sign, int n, const double* __restrict cx, const double* __restrict cy,
                          double* __restrict arm, double* __restrict dx, double* __restrict dy,
                          double* __restrict kappa, double* __restrict loaded) {
  const double rd = c.turret_radius;
  for (int k = 0; k < n; ++k) {
    const double vx = px - cx[k], vy = py - cy[k];
    const double norm = std::sqrt(vx * vx + vy * vy);
    const double ux = vx / norm, uy = vy / norm;
    dx[k] = ux, dy[k] = uy;
    const double a = cx[k] * uy - cy[k] * ux;
    arm[k] = a;
    const double sa = sign * a;
    loaded[k] = sa > 0.0 ? sa : 0.0;  // PositivePart
    kappa[k] = PitchCurvature(c, e, (cx[k] * ex + cy[k] * ey) / rd);
  }
}

/// FillStresses' Hertz stress of every roller into p (0 where unloaded, +∞ on an undercut part of
/// the pitch curve), branch-free over plain arrays so that it vectorises.
inline void StressKernel(int n, const double* __restrict force, const double* __restrict kappa,
                         double roller_radius, double length, double e_star, double* __restrict p) {
  // The square roots on every lane first (NaN where r_eff <= 0: discarded below), then the choice.
  for (int k = 0; k < n; ++k) {
    const double r_eff = roller_radius * (1.0 - roller_radius * kappa[k]);
    p[k] = contact::LineContactPeakPressure(force[k], length, r_eff, e_star);
  }
  for (int k = 0; k < n; ++k) {
    if (!(force[k] > 0)) {
      p[k] = 0.0;  // p → 0 continuously as F → 0
    } else if (!(roller_radius * (1.0 - roller_radius * kappa[k]) > 0)) {
      p[k] = kInf;  // the roller sits on an undercut part of the pitch curve
    }
  }
}

/// The contact geometry of RollerContacts (same operations in the same order, so the same bits),
/// written as plain loops over arrays that the compiler vectorises.
inline void FillContacts(TurretBuffers& b, const Reducer<double>& r, Side s, const Vec2<double>& ecc,
                         double sign) {
  const CamSide<double>& c = r.side(s);
  const Vec2<double> pitch = r.eccentricity * double(c.pitch_factor()) * ecc;  // PitchPointOfCam
  ContactKernel(c, r.eccentricity, pitch.x(), pitch.y(), ecc.x(), ecc.y(), sign, c.rollers, b.cx.data(),
                b.cy.data(), b.arm.data(), b.dx.data(), b.dy.data(), b.kappa.data(), b.loaded.data());
}

}  // namespace internal

/// Samples θ = 2π i / steps, i = 0 … steps − 1. progress(fraction) is called now and then.
/// Gives exactly (bit for bit) the numbers of AnalyzeAngle at each θ: the per-roller work runs on
/// reused structure-of-arrays buffers (the input turret's centres, which do not move, are computed
/// once), in the order of operations of contact.h and forces.h.
inline CycleSeries AnalyzeCycle(const Reducer<double>& r, const Material& material,
                                const LoadCase& load, int steps, const Stages& stages,
                                const std::function<void(double)>& progress = {}) {
  CycleSeries s;
  s.theta_rad.reserve(steps);
  for (SideSeries* series : {&s.input, &s.output}) {
    series->actuating.reserve(steps);
    series->max_force_N.reserve(steps);
    series->max_stress_MPa.reserve(steps);
    series->turret_torque_Nmm.reserve(steps);
    series->roller_force_N.reserve(steps);
  }
  for (auto* v : {&s.tangential_force_N, &s.radial_force_N, &s.input_torque_Nmm, &s.efficiency})
    v->reserve(steps);
  const bool any_stage = stages.forces || stages.stress || stages.efficiency;

  internal::TurretBuffers buf_a, buf_b;
  internal::Resize(buf_a, r.input.rollers);
  internal::Resize(buf_b, r.output.rollers);
  if (any_stage) internal::FillCentres(buf_a, r, Side::kInput, 0.0);  // the fixed turret stands
  const double sign_a = LoadedArmSign(r, Side::kInput), sign_b = LoadedArmSign(r, Side::kOutput);
  const double ratio_b = double(r.output.lobes) / r.output.rollers;
  const double ratio_a = double(r.input.lobes) / r.input.rollers;
  const double tol_a = 1e-9 * r.input.turret_radius, tol_b = 1e-9 * r.output.turret_radius;
  const double e_star = material.composite_modulus_MPa();
  const double ratio = std::abs(SpeedReductionRatio(r));
  const double mu = load.friction_coefficient;

  for (int i = 0; i < steps; ++i) {
    const double theta = 2 * kPi * i / steps;
    s.theta_rad.push_back(theta);
    if (!any_stage) {  // contacts only: nothing of the series depends on them
      AngleLoads<double> a = AnalyzeAngle(r, material, load, theta, stages);
      for (auto [series, side] : {std::pair{&s.input, &a.input}, std::pair{&s.output, &a.output}}) {
        series->actuating.push_back(side->actuating);
        series->max_force_N.push_back(side->max_force);
        series->max_stress_MPa.push_back(side->max_stress);
        series->turret_torque_Nmm.push_back(side->turret_torque);
        series->roller_force_N.push_back(std::move(side->force));
      }
      s.tangential_force_N.push_back(a.tangential_force);
      s.radial_force_N.push_back(a.radial_force);
      s.input_torque_Nmm.push_back(a.input_torque);
      s.efficiency.push_back(a.efficiency);
    } else {
      const Vec2<double> u = U(theta);
      internal::FillCentres(buf_b, r, Side::kOutput, theta);
      internal::FillContacts(buf_a, r, Side::kInput, u, sign_a);
      internal::FillContacts(buf_b, r, Side::kOutput, u, sign_b);
      double sum_a = 0.0, sum_b = 0.0;  // SumLoadedArmSquares
      for (double a : buf_a.loaded) sum_a += a * a;
      for (double a : buf_b.loaded) sum_b += a * a;
      if (!(sum_a > 0) || !(sum_b > 0))
        throw std::domain_error("no roller of a turret can carry load at this input angle");
      const double c_b = load.output_torque_Nmm / sum_b;
      const double c_a = c_b * ratio_b * sum_b / (ratio_a * sum_a);
      for (auto [series, buf, cam, c, tol] :
           {std::tuple{&s.input, &buf_a, &r.input, c_a, tol_a},
            std::tuple{&s.output, &buf_b, &r.output, c_b, tol_b}}) {
        // FillForces
        const size_t n = buf->loaded.size();
        std::vector<double> force(n);
        int actuating = 0;
        double max_force = 0.0, torque = 0.0;
        for (size_t k = 0; k < n; ++k) {
          const double a = buf->loaded[k];
          force[k] = c * a;
          torque += force[k] * a;
          if (a > tol) ++actuating;
          if (force[k] > max_force) max_force = force[k];
        }
        // FillStresses
        double max_stress = 0.0;
        if (stages.stress) {
          internal::StressKernel(int(n), force.data(), buf->kappa.data(), cam->roller_radius, cam->contact_length(),
                       e_star, buf->stress.data());
          for (size_t k = 0; k < n; ++k)
            if (buf->stress[k] > max_stress) max_stress = buf->stress[k];
        }
        series->actuating.push_back(actuating);
        series->max_force_N.push_back(max_force);
        series->max_stress_MPa.push_back(max_stress);
        series->turret_torque_Nmm.push_back(torque);
        series->roller_force_N.push_back(std::move(force));
      }
      double tangential = 0.0, radial = 0.0, input_torque = 0.0, efficiency = 0.0;
      if (stages.efficiency) {
        const bool unloaded = load.output_torque_Nmm == 0.0;
        Vec2<double> per_torque(0.0, 0.0);
        const double unit_b = 1.0 / sum_b;
        const double unit_a = unit_b * ratio_b * sum_b / (ratio_a * sum_a);
        for (auto [buf, c] : {std::pair{&buf_a, unit_a}, std::pair{&buf_b, unit_b}})
          for (size_t k = 0; k < buf->loaded.size(); ++k)
            per_torque += c * buf->loaded[k] * Vec2<double>(buf->dx[k], buf->dy[k]);
        const Vec2<double> g = load.output_torque_Nmm * per_torque + Vec2<double>(0.0, -load.cam_weight_N);
        tangential = -g.dot(Perp(u));
        radial = g.dot(u);
        input_torque = InputTorque(tangential, radial, mu, r.eccentricity);
        if (!unloaded) {
          efficiency = Efficiency(load.output_torque_Nmm, input_torque, ratio);
        } else if (load.cam_weight_N > 0) {
          efficiency = 0.0;
        } else {
          const double unit_torque = InputTorque(-per_torque.dot(Perp(u)), per_torque.dot(u), mu, r.eccentricity);
          efficiency = Efficiency(1.0, unit_torque, ratio);
        }
      }
      s.tangential_force_N.push_back(tangential);
      s.radial_force_N.push_back(radial);
      s.input_torque_Nmm.push_back(input_torque);
      s.efficiency.push_back(efficiency);
    }
    if (progress && (i % 256 == 0 || i + 1 == steps)) progress(double(i + 1) / steps);
  }
  return s;
}

/// The one cycle aggregate of the LCR (used by AggregateCycle and by the sizing problem of
/// objectives/lcr_sizing.h): a log-sum-exp soft maximum taken on x/scale with dimensionless
/// sharpness k,
///     ScaledSoftMax(x) = scale · SoftMax(x/scale, k),
/// so max(x) <= ScaledSoftMax(x) <= max(x) + scale·ln(N)/k. The bias is largest when the N samples
/// are all equal and far smaller when one sample dominates; its bound per sample count, in units of
/// the scale, for the default k = 200:
///
///   | N samples          | 24     | 90     | 360    | 624 (24 × 26 rollers) | 3600   |
///   | ln(N)/k            | 0.0159 | 0.0225 | 0.0294 | 0.0322                | 0.0409 |
///
/// (for a 1000 MPa scale, up to 16–41 MPa; the minimum-size search therefore uses the aggregate
/// only to find the region of the optimum, see objectives/lcr_min_size.h). The scale is a fixed
/// number (not the current maximum), so the aggregate is one smooth function of the design and its
/// AD gradient is exact.
/// A sample of +∞ (the Hertz stress of a contact on an undercut part of the pitch curve, see
/// forces.h) makes the aggregate +∞ with a zero derivative, never NaN.
/// @tparam T double or ceres::Jet. @pre x not empty, scale > 0, sharpness > 0.
template <typename T>
T ScaledSoftMax(const std::vector<T>& x, double scale, double sharpness) {
  for (const T& v : x)
    if (Value(v) == kInf) return T(kInf);
  std::vector<T> scaled(x.size());
  for (size_t i = 0; i < x.size(); ++i) scaled[i] = x[i] / T(scale);
  return T(scale) * SoftMax(scaled, sharpness);
}

/// Cycle aggregates over `steps` input angles, for optimizers: ScaledSoftMax of the roller force
/// and contact stress of each cam, soft minimum of the efficiency (scale 1), and the mean input
/// torque.
struct AggregateOptions {
  double force_scale_N = 1000.0;
  double stress_scale_MPa = 1000.0;
  double sharpness = 200.0;
};

template <typename T>
struct CycleAggregates {
  T max_force_input{}, max_force_output{};    // [N]
  T max_stress_input{}, max_stress_output{};  // [MPa]; +∞ when a loaded contact is undercut
  T min_efficiency{}, mean_input_torque{};    // fraction, [N·mm]
};

template <typename T>
CycleAggregates<T> AggregateCycle(const Reducer<T>& r, const Material& material, const LoadCase& load,
                                  int steps, const AggregateOptions& options = {}) {
  std::vector<T> fa, fb, sa, sb, eta, tin;
  for (int i = 0; i < steps; ++i) {
    const AngleLoads<T> a = AnalyzeAngle(r, material, load, T(2 * kPi * i / steps));
    for (const auto& [dst, src] : {std::pair{&fa, &a.input.force}, std::pair{&fb, &a.output.force}})
      dst->insert(dst->end(), src->begin(), src->end());
    for (const auto& [dst, src] : {std::pair{&sa, &a.input.stress}, std::pair{&sb, &a.output.stress}})
      for (const T& v : *src)
        if (Value(v) > 0) dst->push_back(v);
    eta.push_back(-a.efficiency);
    tin.push_back(a.input_torque);
  }
  CycleAggregates<T> out;
  out.max_force_input = ScaledSoftMax(fa, options.force_scale_N, options.sharpness);
  out.max_force_output = ScaledSoftMax(fb, options.force_scale_N, options.sharpness);
  out.max_stress_input = sa.empty() ? T(0.0) : ScaledSoftMax(sa, options.stress_scale_MPa, options.sharpness);
  out.max_stress_output = sb.empty() ? T(0.0) : ScaledSoftMax(sb, options.stress_scale_MPa, options.sharpness);
  out.min_efficiency = -ScaledSoftMax(eta, 1.0, options.sharpness);
  T sum(0.0);
  for (const T& t : tin) sum += t;
  out.mean_input_torque = sum / T(double(steps));
  return out;
}

}  // namespace camopt::lcr
