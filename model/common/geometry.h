// Planar geometry over the scalar T (double or ceres::Jet), in the notation of docs/papers.md §1:
// u(a) = (cos a, sin a), J rotates by +90°, a × b = a_x b_y − a_y b_x.
#pragma once

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

namespace camopt {

template <typename T>
using Vec2 = Eigen::Matrix<T, 2, 1>;

/// Unit vector at angle a [rad].
template <typename T>
Vec2<T> U(const T& a) {
  using std::cos;
  using std::sin;
  return Vec2<T>(cos(a), sin(a));
}

/// Rotation by +90°.
template <typename T>
Vec2<T> Perp(const Vec2<T>& v) {
  return Vec2<T>(-v.y(), v.x());
}

/// Scalar cross product a × b.
template <typename T>
T Cross(const Vec2<T>& a, const Vec2<T>& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// Rotation of v by angle a [rad].
template <typename T>
Vec2<T> Rotate(const Vec2<T>& v, const T& a) {
  using std::cos;
  using std::sin;
  const T c = cos(a), s = sin(a);
  return Vec2<T>(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

/// Circular distance of two angles a, b [rad] modulo a period [rad]: in [0, period / 2].
inline double PhaseDistance(double a, double b, double period) {
  const double d = std::fmod(std::abs(a - b), period);
  return std::min(d, period - d);
}

}  // namespace camopt
