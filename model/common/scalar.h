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
#include <type_traits>
#include <vector>

#include <ceres/jet.h>

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

/// Select a or b on the value of a condition. Use only where the two branches meet continuously
/// (or where the kink is intended and documented); the derivative is that of the chosen branch.
template <typename T>
T IfThenElse(bool condition, const T& a, const T& b) {
  return condition ? a : b;
}

/// max(0, x) with its one-sided derivative (0 at x <= 0). Continuous, kink at 0.
template <typename T>
T PositivePart(const T& x) {
  return Value(x) > 0.0 ? x : T(0.0);
}

/// Smooth maximum of samples: log-sum-exp with sharpness k (units 1/[x]).
/// Bound: max(x) <= SoftMax(x) <= max(x) + ln(N)/k. Shifted by the exact max, so it never
/// overflows, and its gradient is a softmax-weighted average of the samples' gradients.
template <typename T>
T SoftMax(const std::vector<T>& x, double k) {
  using std::exp;
  using std::log;
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
  size_t imax = 0;
  for (size_t i = 1; i < x.size(); ++i)
    if (Value(x[i]) > Value(x[imax])) imax = i;
  return x[imax];
}

template <typename T>
T HardMin(const std::vector<T>& x) {
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
