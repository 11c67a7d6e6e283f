// A closed planar profile measured against its exact nominal: inspection points along the exact
// profile, the closest-point projection of measured points, the normal deviation as a smooth
// periodic function of the profile parameter, and the ISO 1101 profile-of-a-line deviation.
//
// The profile is a regular closed curve P(t), t ∈ [t0, t0 + period), given with its unit tangent
// T (direction of increasing t), speed v = |dP/dt| and signed curvature κ (> 0 turning left), so
// that dT/dt = v κ J T (J the +90° rotation). It bounds the material of a part: the outward normal
// n points out of the material (right of T on a counter-clockwise outer profile, left on a
// clockwise one; the sense is found from the enclosed signed area).
//
// Projection. The closest point of P to q makes g(t) = (P(t) − q)·T(t) vanish, with
// g'(t) = v (1 + κ (P − q)·J T) exactly; Newton's steps on g start at the nearest of the profile's
// table samples and are kept inside the bracket of its two neighbours (bisection when a step
// leaves it). The signed normal deviation is d = (q − P(t*))·n (> 0 outside the material).
//
// Normal deviation function. Measured deviations d_i at the parameters t_i are interpolated by the
// periodic cubic spline through them (C², the second derivatives from the cyclic tridiagonal
// system, solved by Sherman–Morrison; de Boor, "A Practical Guide to Splines", ch. IV), evaluated
// over the scalar T (double or ceres::Jet) with its slope d'(t).
//
// ISO 1101:2017 §18.2 (profile of a line): the tolerance zone is bounded by the two lines enveloping
// circles of diameter t_z centred on the theoretically exact profile, i.e. ± t_z/2 along its normal.
// The part's deviation is the width of the smallest such zone, symmetric about the nominal, that
// holds every measured point: 2 max_i |d_i|.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "model/common/geometry.h"
#include "model/common/scalar.h"

namespace camopt::profile {

/// The exact profile at one parameter value.
struct CurvePoint {
  Vec2<double> point{0.0, 0.0};    ///< P(t) [mm]
  Vec2<double> tangent{1.0, 0.0};  ///< unit tangent, direction of increasing t
  double speed = 1.0;              ///< |dP/dt| [mm per unit of t], > 0
  double curvature = 0.0;          ///< signed curvature [1/mm], > 0 turning left
};
using Curve = std::function<CurvePoint(double)>;

/// A normal deviation d(t) [mm] of a profile with its slope d'(t) (nullptr: not asked).
template <typename T>
using NormalDeviation = std::function<T(const T& t, T* slope)>;

/// A curve known by its points only (e.g. the envelope of a flat face) as a Curve: tangent and speed
/// from the fourth-order central difference with step h, the curvature from the fourth-order second
/// difference (truncation O(h⁴), rounding O(ε/h): h = 1e-3 rad gives the normal to about 1e-10 on
/// a smooth curve; at a jump of the curvature, within 2h of it, to O(h Δκ)).
Curve CurveFromPoints(std::function<Vec2<double>(double)> f, double h);

/// A closed profile with its table of samples (the arc length and the projection's start).
class ClosedProfile {
 public:
  /// `curve` over [t0, t0 + period), `samples` table points (>= 16; the finer, the more robust the
  /// projection's start: a few per smallest feature). @pre the curve is regular and simple.
  ClosedProfile(Curve curve, double t0, double period, int samples);

  CurvePoint Eval(double t) const { return curve_(t); }
  /// The outward unit normal (out of the material) at p.
  Vec2<double> OutwardNormal(const CurvePoint& p) const {
    return outward_ * Vec2<double>(p.tangent.y(), -p.tangent.x());
  }
  double t0() const { return t0_; }
  double period() const { return period_; }
  double length_mm() const { return length_; }
  /// Diagonal of the table samples' bounding box [mm].
  double size_mm() const { return size_; }
  /// Arc length from t0 to t ∈ [t0, t0 + period] [mm] (5-point Gauss–Legendre per table interval).
  double ArcLength(double t) const;
  /// The parameter at arc length s ∈ [0, length] from t0 (Newton on the arc length, ds/dt = v).
  double ParameterAt(double s) const;
  /// t wrapped into [t0, t0 + period).
  double Wrap(double t) const;

  struct Projection {
    double t = 0;                 ///< parameter of the closest point
    Vec2<double> foot{0.0, 0.0};  ///< closest point of the profile [mm]
    Vec2<double> normal{0.0, 0.0};  ///< outward unit normal there
    double deviation_mm = 0;      ///< (q − foot)·normal, > 0 outside the material
    double distance_mm = 0;       ///< |q − foot|
  };
  /// The closest point of the profile to q (header comment).
  Projection Project(const Vec2<double>& q) const;

 private:
  double Gauss(double a, double b) const;
  Curve curve_;
  double t0_, period_;
  std::vector<double> table_t_, table_s_;
  std::vector<Vec2<double>> table_p_;
  double length_ = 0, size_ = 0, outward_ = 1;
};

/// One inspection point: the exact profile at arc-length steps.
struct InspectionPoint {
  double t = 0;
  Vec2<double> point{0.0, 0.0}, normal{0.0, 0.0};  ///< on the profile, outward unit normal
};
/// n = ⌈L / spacing⌉ points at arc lengths s_i = i L / n (i = 0 … n − 1) from t0: the arc between
/// neighbours (the last to the first included) is L / n <= spacing. @pre spacing > 0.
std::vector<InspectionPoint> InspectionPoints(const ClosedProfile& profile, double spacing_mm);

/// The periodic cubic spline through (t_i, d_i) (header comment).
class PeriodicSpline {
 public:
  PeriodicSpline() = default;
  /// @pre t strictly increasing, t.back() < t.front() + period, at least 3 knots.
  PeriodicSpline(std::vector<double> t, std::vector<double> d, double period);
  bool empty() const { return t_.empty(); }

  /// d(t) and, when asked, d'(t). @tparam T double or ceres::Jet (the knots are fixed).
  template <typename T>
  T operator()(const T& t, T* slope = nullptr) const {
    using std::floor;
    const double tv = Value(t);
    const double wraps = std::floor((tv - t_[0]) / period_);
    const T u = t - T(wraps * period_);
    const double uv = tv - wraps * period_;
    size_t k = size_t(std::upper_bound(t_.begin(), t_.end(), uv) - t_.begin());
    k = k == 0 ? 0 : k - 1;
    const size_t k1 = (k + 1) % t_.size();
    const double x0 = t_[k], x1 = k + 1 < t_.size() ? t_[k + 1] : t_[0] + period_;
    const double h = x1 - x0;
    const T a = (T(x1) - u) / h, b = (u - T(x0)) / h;
    if (slope)
      *slope = T((d_[k1] - d_[k]) / h) - (T(3.0) * a * a - T(1.0)) * (h * m_[k] / 6.0) +
               (T(3.0) * b * b - T(1.0)) * (h * m_[k1] / 6.0);
    return a * d_[k] + b * d_[k1] + ((a * a * a - a) * m_[k] + (b * b * b - b) * m_[k1]) * (h * h / 6.0);
  }

 private:
  std::vector<double> t_, d_, m_;  ///< knots, values, second derivatives
  double period_ = 0;
};

/// The ISO 1101 profile-of-a-line deviation of measured normal deviations d_i (header comment).
struct ProfileZone {
  double zone_width_mm = 0;  ///< 2 max |d_i|
  double max_mm = 0, min_mm = 0;  ///< largest and smallest signed d_i
  int argmax = -1, argmin = -1;   ///< their indices
  double mean_mm = 0, rms_mm = 0;
};
ProfileZone MeasureZone(const std::vector<double>& deviations_mm);

}  // namespace camopt::profile
