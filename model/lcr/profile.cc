// See profile.h.
#include "model/lcr/profile.h"

namespace camopt::lcr {

std::vector<Vec2<double>> SampleCurve(const CamSide<double>& side, double eccentricity, double offset, int n) {
  std::vector<Vec2<double>> pts(n);
  for (int i = 0; i < n; ++i) pts[i] = OffsetPoint(side, eccentricity, 2 * kPi * i / n, offset);
  return pts;
}

std::function<Vec2<double>(double)> OffsetCurve(const CamSide<double>& side, double eccentricity, double offset) {
  return [side, eccentricity, offset](double psi) { return OffsetPoint(side, eccentricity, psi, offset); };
}

std::function<Vec2<double>(double)> PitchCurve(const CamSide<double>& side, double eccentricity) {
  return [side, eccentricity](double psi) { return PitchPoint(side, eccentricity, psi); };
}

}  // namespace camopt::lcr
