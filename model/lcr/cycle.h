// LCR analysis over one input revolution: per-angle series and their extremes, and smooth
// aggregates of the same quantities for optimizers.
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "model/lcr/forces.h"

namespace camopt::lcr {

/// One number per roller per angle, stored flat (one allocation per cycle, not one per angle).
class PerRoller {
 public:
  void Reset(int rollers, int angles) {
    rollers_ = rollers;
    rows_ = 0;
    data_.clear();
    data_.reserve(size_t(rollers) * angles);
  }
  /// Appends one angle's row; returns its first element. @pre Reset was called.
  double* AddRow() {
    ++rows_;
    data_.resize(data_.size() + rollers_);
    return data_.data() + data_.size() - rollers_;
  }
  /// Appends a row of `rollers` numbers, or an empty row to a table reset with 0 rollers.
  void AddRow(const std::vector<double>& row) {
    if (row.size() != size_t(rollers_)) throw std::logic_error("PerRoller::AddRow: row of the wrong size");
    ++rows_;
    data_.insert(data_.end(), row.begin(), row.end());
  }
  size_t size() const { return rows_; }
  /// Row of angle i as a vector (a copy).
  std::vector<double> operator[](size_t i) const {
    return {data_.begin() + i * rollers_, data_.begin() + (i + 1) * rollers_};
  }
  const double* row(size_t i) const { return data_.data() + i * rollers_; }
  /// Every row, one after the other ([i · rollers + k]).
  const std::vector<double>& values() const { return data_; }
  int rollers() const { return rollers_; }

 private:
  int rollers_ = 0;
  size_t rows_ = 0;
  std::vector<double> data_;
};

struct SideSeries {
  std::vector<int> actuating;
  std::vector<double> max_force_N, max_stress_MPa, turret_torque_Nmm;
  PerRoller roller_force_N;  // [angle][roller]
  PerRoller roller_stress_MPa;  // [angle][roller], with Stages::roller_stress (else empty)
};

struct CycleSeries {
  std::vector<double> theta_rad;
  SideSeries input, output;
  std::vector<double> tangential_force_N, radial_force_N, input_torque_Nmm, efficiency;
};

/// Samples θ = 2π i / steps, i = 0 … steps − 1. progress(fraction) is called now and then.
/// Gives exactly (bit for bit) the numbers of AnalyzeAngle at each θ: the per-roller work runs on
/// reused structure-of-arrays buffers (the input turret's centres, which do not move, are computed
/// once), in the order of operations of contact.h and forces.h.
/// Defined in cycle.cc (double only; keeping it out of the header leaves the inlining of the
/// templated Jet paths in the including files as it was).
CycleSeries AnalyzeCycle(const Reducer<double>& r, const Material& material, const LoadCase& load,
                         int steps, const Stages& stages,
                         const std::function<void(double)>& progress = {});

/// The rigid law's loads at any input angles: per θ of theta_rad, roller 0's force on each cam, the
/// eccentric load G and T_in, and roller 0's speed relative to its pin per unit input speed on each
/// cam. Bit for bit AnalyzeAngle(r, material, load, θ, {true, false, true})'s force[0], eccentric_load
/// and input_torque, and RollerSpinRate(r, s, θ, 0) (the file comment of life.h), on AnalyzeCycle's
/// structure-of-arrays path: life.h's SampleBearingLoad under the rigid law. Defined in cycle.cc.
/// @throws std::domain_error when no roller of a turret can carry load at an angle.
struct RollerZeroLoads {
  std::vector<double> input_force_N, output_force_N;      ///< roller 0's, per angle
  std::vector<Vec2<double>> eccentric_load_N;             ///< G
  std::vector<double> input_torque_Nmm;                   ///< T_in = (F_t + μ |F_r|) e
  std::vector<double> input_spin_rate, output_spin_rate;  ///< roller 0's, ψ' |ρ − r_r| / r_r
};
RollerZeroLoads RigidRollerZeroLoads(const Reducer<double>& r, const LoadCase& load,
                                     const std::vector<double>& theta_rad);

/// The rigid law's contacts, roller forces and eccentric load at input angles one after another, on
/// AnalyzeCycle's structure-of-arrays buffers: after At(θ), bit for bit AnalyzeAngle(r, material,
/// load, θ, {true, false, true})'s contacts, force and eccentric_load of each cam, without its
/// per-angle allocations (the vectors are overwritten by the next At). For the lubricated cycle's
/// loads (lubrication.h). r must outlive the sweep. Defined in cycle.cc.
class RigidLoadsSweep {
 public:
  RigidLoadsSweep(const Reducer<double>& r, const LoadCase& load);
  ~RigidLoadsSweep();
  RigidLoadsSweep(const RigidLoadsSweep&) = delete;
  RigidLoadsSweep& operator=(const RigidLoadsSweep&) = delete;
  /// The loads at input angle θ [rad].
  /// @throws std::domain_error when no roller of a turret can carry load there.
  void At(double theta);
  std::vector<RollerContact<double>> input_contacts, output_contacts;
  std::vector<double> input_force_N, output_force_N;
  Vec2<double> eccentric_load_N{0.0, 0.0};  ///< G

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// The pitch-curve curvature κ [1/mm] of roller k of one cam at theta_rad[i], in
/// [i · rollers + k] (rollers = r.side(s).rollers), by AnalyzeCycle's structure-of-arrays contact
/// kernel: bit for bit RollerContacts(r, s, θ)[k].curvature (contact.h), without its per-angle
/// vectors. Defined in cycle.cc.
std::vector<double> CycleCurvatures(const Reducer<double>& r, Side s, const std::vector<double>& theta_rad);

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
/// only to find the region of the optimum, see sizing/lcr_min_size.h). The scale is a fixed
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
