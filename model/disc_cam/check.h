// Feasibility of a disc cam design: the follower can be placed on the base circle, and over one
// cam revolution it stays outside the base circle, an oscillating arm stays on its side of the
// cam centre line, and the pressure angle stays below the jam limit. Returns named issues; a study
// maps each kind to the JSON path of its input and writes the message in its own units.
#pragma once

#include <cmath>
#include <vector>

#include "model/common/scalar.h"
#include "model/disc_cam/disc_cam.h"

namespace camopt::disc_cam {

/// Pressure angle at which the follower is taken to jam [rad] (89°).
inline constexpr double kJamPressureAngle = 89.0 * (kPi / 180.0);
/// Pressure angle above which a study warns [rad] (45°, docs/disc_cam.md "Pressure angle
/// warning"): the contact force exceeds √2 × the force that drives the follower and the side thrust
/// equals it; the design works but is close to the self-locking that kJamPressureAngle refuses.
inline constexpr double kHighPressureAngle = 45.0 * (kPi / 180.0);

enum class IssueKind {
  /// Translating: |e| ≥ r_b + r_f, the follower cannot touch the base circle.
  /// value = e, upper = r_b + r_f [mm].
  kOffsetTooLarge,
  /// Oscillating: the arm cannot reach the base circle, need |f − l| < r_b + r_f < f + l.
  /// value = r_b + r_f, lower = |f − l|, upper = f + l [mm].
  kArmCannotReach,
  /// S < 0 somewhere: the follower goes inside the base circle. value = S [mm or rad].
  kInsideBaseCircle,
  /// Oscillating: ξ₀ + S leaves (0, π), the arm crosses the cam centre line. value = ξ₀ + S [rad].
  kArmOutOfRange,
  /// |φ| ≥ kJamPressureAngle or φ not finite: the follower jams. value = φ [rad].
  kJams,
};

/// One issue of a design; cam_angle is where over the cycle it is first met (cycle issues).
struct DesignIssue {
  IssueKind kind;
  double value = 0.0;
  double lower = 0.0, upper = 0.0;
  double cam_angle_rad = 0.0;
};

/// Placement of the follower on the base circle (does not look at the motion program).
template <typename T>
std::vector<DesignIssue> CheckGeometry(const DiscCamTpl<T>& cam) {
  std::vector<DesignIssue> issues;
  const double r0 = Value(cam.base_radius) + Value(cam.roller_radius);
  if (cam.follower == FollowerType::kTranslatingRoller) {
    const double e = Value(cam.offset);
    if (!(std::abs(e) < r0)) issues.push_back({IssueKind::kOffsetTooLarge, e, 0.0, r0, 0.0});
  } else {
    const double f = Value(cam.pivot_distance), l = Value(cam.arm_length);
    if (!(r0 > std::abs(f - l) && r0 < f + l))
      issues.push_back({IssueKind::kArmCannotReach, r0, std::abs(f - l), f + l, 0.0});
  }
  return issues;
}

/// CheckGeometry, then the cycle on angle_steps equally spaced cam angles θᵢ = 2π i/n: the first
/// angle of each kind of issue, in the order met (at one angle: inside, arm range, jam).
/// The follower counts as inside the base circle below S = −1e-9 r_b (translating, mm) or
/// −1e-9 rad (oscillating).
template <typename T>
std::vector<DesignIssue> CheckDesign(const DiscCamTpl<T>& cam, int angle_steps) {
  std::vector<DesignIssue> issues = CheckGeometry(cam);
  if (!issues.empty()) return issues;
  const bool osc = cam.follower == FollowerType::kOscillatingRoller;
  const double xi0 = Value(InitialFollowerCoordinate(cam));
  const double inside_tol = -1e-9 * (osc ? 1.0 : Value(cam.base_radius));
  bool seen[3] = {false, false, false};
  auto add = [&](int slot, IssueKind kind, double value, double theta) {
    if (seen[slot]) return;
    seen[slot] = true;
    issues.push_back({kind, value, 0.0, 0.0, theta});
  };
  for (int i = 0; i < angle_steps; ++i) {
    const double theta = 2 * kPi * i / angle_steps;
    const CamPoint<T> p = EvaluateCam(cam, T(theta));
    const double s = Value(p.s), phi = Value(p.pressure_angle);
    if (s < inside_tol) add(0, IssueKind::kInsideBaseCircle, s, theta);
    if (osc && !(xi0 + s > 0.0 && xi0 + s < kPi)) add(1, IssueKind::kArmOutOfRange, xi0 + s, theta);
    if (!(std::abs(phi) < kJamPressureAngle) || !std::isfinite(phi))
      add(2, IssueKind::kJams, phi, theta);
  }
  return issues;
}

}  // namespace camopt::disc_cam
