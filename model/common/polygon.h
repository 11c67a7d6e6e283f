// Area properties of a closed polygon (a sampled profile): for the masses and inertias of parts.
#pragma once

#include <vector>

#include "model/common/geometry.h"

namespace camopt {

/// Area and polar second moment about the origin of a closed simple polygon (Green's theorem:
/// A = ½ Σ c_i, J = (1/12) Σ c_i (x_i² + x_i x_{i+1} + x_{i+1}² + y_i² + y_i y_{i+1} + y_{i+1}²),
/// c_i = x_i y_{i+1} − x_{i+1} y_i), either orientation.
struct PolygonMoments {
  double area = 0.0, polar = 0.0;
};
inline PolygonMoments PolygonAreaAndPolarMoment(const std::vector<Vec2<double>>& p) {
  double a = 0, j = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec2<double>& u = p[i];
    const Vec2<double>& v = p[(i + 1) % p.size()];
    const double c = u.x() * v.y() - v.x() * u.y();
    a += c;
    j += c * (u.x() * u.x() + u.x() * v.x() + v.x() * v.x() + u.y() * u.y() + u.y() * v.y() + v.y() * v.y());
  }
  return {a < 0 ? -a / 2.0 : a / 2.0, j < 0 ? -j / 12.0 : j / 12.0};
}

}  // namespace camopt
