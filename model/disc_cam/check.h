// Feasibility of a disc cam design: the follower can be placed on the base circle, and over one
// cam revolution it stays outside the base circle, an oscillating arm stays on its side of the
// cam centre line, and the pressure angle stays below the jam limit. Returns DesignIssues
// (model/common/design_issue.h) on the fields "offset", "arm_length" and "motion"; a study maps
// them to the JSON paths of its inputs (studies/design_issue_paths.h).
#pragma once

#include <cmath>
#include <vector>

#include "model/common/design_issue.h"
#include "model/common/scalar.h"
#include "model/disc_cam/disc_cam.h"

namespace camopt::disc_cam {

/// Pressure angle at which the follower is taken to jam [rad] (89°).
inline constexpr double kJamPressureAngle = 89.0 * (kPi / 180.0);
/// Pressure angle above which a study warns [rad] (45°, docs/disc_cam.md "Pressure angle
/// warning"): the contact force exceeds √2 × the force that drives the follower and the side thrust
/// equals it; the design works but is close to the self-locking that kJamPressureAngle refuses.
inline constexpr double kHighPressureAngle = 45.0 * (kPi / 180.0);

/// The follower inside the base circle at cam angle theta (S < 0): field "motion", value S,
/// limit 0 [mm, or rad for an oscillating follower].
inline DesignIssue InsideBaseCircleIssue(double s, double theta, bool oscillating) {
  const double deg = kPi / 180.0;
  return {"motion",
          "the follower goes inside the base circle at cam angle " + IssueNumber(theta / deg) + " deg (S = " +
              IssueNumber(oscillating ? s / deg : s) + (oscillating ? " deg" : " mm") +
              "): the motion must keep S >= 0 over the whole cycle (no fall deeper than the rises before it, "
              "no polynomial segment that dips below its start)",
          s, 0.0, theta};
}

/// Placement of the follower on the base circle (does not look at the motion program). Fields:
/// "offset" (translating: |e| >= r_b + r_f, value e, limit r_b + r_f [mm]) and "arm_length"
/// (oscillating: need |f − l| < r_b + r_f < f + l, value r_b + r_f, limit the bound broken [mm]).
template <typename T>
std::vector<DesignIssue> CheckGeometry(const DiscCamTpl<T>& cam) {
  std::vector<DesignIssue> issues;
  const double rf = Value(cam.roller_radius);
  const double r0 = Value(cam.base_radius) + rf;
  if (cam.follower == FollowerType::kTranslatingRoller) {
    const double e = Value(cam.offset);
    if (!(std::abs(e) < r0))
      issues.push_back({"offset",
                        "the offset " + IssueNumber(e) + " mm must be smaller than base circle + roller radius (" +
                            IssueNumber(r0) + " mm): an offset of less than " + IssueNumber(r0) +
                            " mm either way, or a base circle radius above " + IssueNumber(std::abs(e) - rf) +
                            " mm, would fit",
                        e, r0});
  } else {
    const double f = Value(cam.pivot_distance), l = Value(cam.arm_length);
    if (!(r0 > std::abs(f - l) && r0 < f + l))
      issues.push_back({"arm_length",
                        "the arm cannot reach the base circle: need |pivot distance − arm length| < base circle "
                        "+ roller radius < pivot distance + arm length (" +
                            IssueNumber(std::abs(f - l)) + " < " + IssueNumber(r0) + " < " + IssueNumber(f + l) +
                            "): an arm length between " + IssueNumber(std::abs(f - r0)) + " and " +
                            IssueNumber(f + r0) + " mm would reach it",
                        r0, r0 > std::abs(f - l) ? f + l : std::abs(f - l)});
  }
  return issues;
}

/// CheckGeometry, then the cycle on angle_steps equally spaced cam angles θᵢ = 2π i/n: the first
/// angle of each kind of issue, in the order met (at one angle: inside, arm range, jam), each on
/// the field "motion" with its cam angle:
///   - S < 0, the follower goes inside the base circle (InsideBaseCircleIssue), below
///     S = −1e-9 r_b (translating, mm) or −1e-9 rad (oscillating);
///   - oscillating: ξ₀ + S leaves (0, π), the arm crosses the cam centre line; value ξ₀ + S,
///     limit 0 or π [rad];
///   - |φ| ≥ kJamPressureAngle or φ not finite: the follower jams; value φ, limit
///     kJamPressureAngle [rad].
template <typename T>
std::vector<DesignIssue> CheckDesign(const DiscCamTpl<T>& cam, int angle_steps) {
  std::vector<DesignIssue> issues = CheckGeometry(cam);
  if (!issues.empty()) return issues;
  const double deg = kPi / 180.0;
  const bool osc = cam.follower == FollowerType::kOscillatingRoller;
  const double xi0 = Value(InitialFollowerCoordinate(cam));
  const double inside_tol = -1e-9 * (osc ? 1.0 : Value(cam.base_radius));
  bool seen[3] = {false, false, false};
  for (int i = 0; i < angle_steps; ++i) {
    const double theta = 2 * kPi * i / angle_steps;
    const CamPoint<T> p = EvaluateCam(cam, T(theta));
    const double s = Value(p.s), phi = Value(p.pressure_angle);
    if (s < inside_tol && !seen[0]) {
      seen[0] = true;
      issues.push_back(InsideBaseCircleIssue(s, theta, osc));
    }
    if (osc && !(xi0 + s > 0.0 && xi0 + s < kPi) && !seen[1]) {
      seen[1] = true;
      const bool over = !(xi0 + s < kPi);
      issues.push_back({"motion",
                        "the follower arm leaves (0, 180) deg from the cam centre line at cam angle " +
                            IssueNumber(theta / deg) + " deg (it reaches " + IssueNumber((xi0 + s) / deg) +
                            " deg from a start at " + IssueNumber(xi0 / deg) + " deg): " +
                            (over ? "a rise of less than " + IssueNumber((kPi - xi0) / deg)
                                  : "a fall of less than " + IssueNumber(xi0 / deg)) +
                            " deg from the start would keep it on its side",
                        xi0 + s, over ? kPi : 0.0, theta});
    }
    if ((!(std::abs(phi) < kJamPressureAngle) || !std::isfinite(phi)) && !seen[2]) {
      seen[2] = true;
      issues.push_back({"motion",
                        "infeasible design: the pressure angle reaches " + IssueNumber(phi / deg) +
                            " deg at cam angle " + IssueNumber(theta / deg) +
                            " deg (the follower would jam; the limit is " + IssueNumber(kJamPressureAngle / deg) +
                            " deg): a larger base circle, or a longer cam angle for that rise, lowers it",
                        phi, kJamPressureAngle, theta});
    }
  }
  return issues;
}

}  // namespace camopt::disc_cam
