// Scalar helpers shared by every stage of the pipeline.
//
// Every stage is a template over the scalar T (double or ceres::Jet). A raw `if` on a T value
// looks at the value only and silently puts a kink in the function, so branches go through the
// helpers here, and maxima/minima over a cycle have a smooth form with a documented sharpness.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include <ceres/jet.h>

#include "model/common/build_flags.h"

/// Marks a small model function that runs per angle or per roller over Jets: GCC otherwise calls
/// `ceres::Jet` products and Eigen's assignments of a Jet's derivative part out of line in it.
/// `flatten` inlines every call in the function's body; without FMA (no -march) the operations,
/// and so the numbers, are the same (docs/development.md, "Small model functions over Jets").
/// Only in optimised builds without the sanitizers: under ASan's instrumentation the inlined
/// Jet<32> motion laws took a single compile of objectives/disc_cam_motion.cc past 10 minutes and
/// 2.7 GB.
#if defined(__OPTIMIZE__) && !defined(CAMOPT_SANITIZED_BUILD)
#define CAMOPT_FLATTEN [[gnu::flatten]]
#else
#define CAMOPT_FLATTEN
#endif

namespace camopt {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// The value part of a scalar: the number itself for double, the real part of a Jet.
inline double Value(double x) { return x; }
template <typename S, int N>
double Value(const ceres::Jet<S, N>& x) { return Value(x.a); }

template <typename T>
struct IsJet : std::false_type {};
template <typename S, int N>
struct IsJet<ceres::Jet<S, N>> : std::true_type {};

/// Converts a scalar to another scalar type: to double it keeps the value (drops derivatives),
/// to a Jet it gives a constant.
template <typename To, typename From>
To ScalarCast(const From& x) {
  if constexpr (std::is_same_v<To, double>) {
    return Value(x);
  } else {
    return To(x);
  }
}

/// The comparison IfThenElse makes between two scalars.
enum class Compare { kLess, kLessEqual, kGreater, kGreaterEqual, kEqual, kNotEqual };

/// then_value if `lhs op rhs` holds on the values (real parts) of lhs and rhs, else else_value.
/// The comparison sits in the call, so every branch on a T is one visible place. The result
/// carries the derivative of the chosen branch only: use it where the branches meet continuously
/// (a min, a max, a piecewise law whose pieces join) or where the jump is physical and documented.
/// @tparam L, R double or a Jet; @tparam T the result scalar.
template <typename L, typename R, typename T>
T IfThenElse(Compare op, const L& lhs, const R& rhs, const T& then_value, const T& else_value) {
  const double l = Value(lhs), r = Value(rhs);
  bool holds = false;
  switch (op) {
    case Compare::kLess: holds = l < r; break;
    case Compare::kLessEqual: holds = l <= r; break;
    case Compare::kGreater: holds = l > r; break;
    case Compare::kGreaterEqual: holds = l >= r; break;
    case Compare::kEqual: holds = l == r; break;
    case Compare::kNotEqual: holds = l != r; break;
  }
  return holds ? then_value : else_value;
}

/// max(0, x) with its one-sided derivative (0 at x <= 0). Continuous, kink at 0.
template <typename T>
T PositivePart(const T& x) {
  return IfThenElse(Compare::kGreater, x, 0.0, x, T(0.0));
}

/// Smooth maximum of samples: log-sum-exp with sharpness k (units 1/[x]).
/// Bound: max(x) <= SoftMax(x) <= max(x) + ln(N)/k. Shifted by the exact max, so it never
/// overflows, and its gradient is a softmax-weighted average of the samples' gradients.
template <typename T>
T SoftMax(const std::vector<T>& x, double k) {
  using std::exp;
  using std::log;
  if (x.empty()) throw std::invalid_argument("SoftMax: no samples");
  size_t imax = 0;
  for (size_t i = 1; i < x.size(); ++i)
    if (Value(x[i]) > Value(x[imax])) imax = i;
  const T m = x[imax];
  T s(0.0);
  for (const T& xi : x) s += exp(k * (xi - m));
  return m + log(s) / k;
}

/// Smooth minimum: -SoftMax(-x). min(x) - ln(N)/k <= SoftMin(x) <= min(x).
template <typename T>
T SoftMin(const std::vector<T>& x, double k) {
  std::vector<T> neg(x.size());
  for (size_t i = 0; i < x.size(); ++i) neg[i] = -x[i];
  return -SoftMax(neg, k);
}

/// Exact maximum; the derivative is that of the largest sample (a subgradient).
template <typename T>
T HardMax(const std::vector<T>& x) {
  if (x.empty()) throw std::invalid_argument("HardMax: no samples");
  size_t imax = 0;
  for (size_t i = 1; i < x.size(); ++i)
    if (Value(x[i]) > Value(x[imax])) imax = i;
  return x[imax];
}

template <typename T>
T HardMin(const std::vector<T>& x) {
  if (x.empty()) throw std::invalid_argument("HardMin: no samples");
  size_t imin = 0;
  for (size_t i = 1; i < x.size(); ++i)
    if (Value(x[i]) < Value(x[imin])) imin = i;
  return x[imin];
}

/// True when every value and every derivative part of x is finite.
inline bool IsFinite(double x) { return std::isfinite(x); }
template <typename S, int N>
bool IsFinite(const ceres::Jet<S, N>& x) {
  if (!IsFinite(x.a)) return false;
  for (int i = 0; i < N; ++i)
    if (!IsFinite(x.v[i])) return false;
  return true;
}

}  // namespace camopt
