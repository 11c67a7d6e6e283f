#include "model/globoidal/check.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace camopt::globoidal {

namespace {
constexpr double kDeg = kPi / 180.0;
}  // namespace

std::vector<DesignIssue> CheckGeometry(const GloboidalCam<double>& cam) {
  std::vector<DesignIssue> issues;
  const auto lim = RollerAxisLimits(cam);
  if (!(lim.l2 > 0.0))
    issues.push_back({"roller_length",
                      "the roller (length " + IssueNumber(cam.roller_length) +
                          " mm) reaches past the turret axis: need m/2 < R_e = " + IssueNumber(cam.pitch_radius) +
                          " mm; a roller length below " + IssueNumber(2.0 * cam.pitch_radius) + " mm would fit",
                      cam.roller_length, 2.0 * cam.pitch_radius});
  // The trajectory stays on the turret's side of the cam axis, C − l₁ cos φ > 0 for every φ, when
  // C > l₁; the roller's radius is added so that the roller itself stays clear.
  if (!(cam.center_distance > lim.l1 + cam.roller_radius))
    issues.push_back({"center_distance",
                      "the rollers reach the cam axis: need C > l₁ + R = " + IssueNumber(lim.l1 + cam.roller_radius) +
                          " mm (l₁ = R_e + m/2 + e, eq. 8), found C = " + IssueNumber(cam.center_distance) +
                          " mm; a center distance above " + IssueNumber(lim.l1 + cam.roller_radius) +
                          " mm would fit",
                      cam.center_distance, lim.l1 + cam.roller_radius});
  if (!(RibThickness(cam) > 0.0)) {
    const double chord = 2.0 * lim.l2 * std::sin(cam.roller_angle / 2);
    std::string fix = "a roller radius below l₂ sin(β/2) = " + IssueNumber(chord / 2) + " mm";
    if (lim.l2 > 0.0 && cam.roller_radius < lim.l2)
      fix = "a roller angle above " + IssueNumber(2.0 * std::asin(cam.roller_radius / lim.l2) / kDeg) + " deg, or " + fix;
    issues.push_back({"roller_angle",
                      "the two rollers overlap (no rib between them): need 2 l₂ sin(β/2) > 2R, found " +
                          IssueNumber(chord) + " mm ≤ " + IssueNumber(2 * cam.roller_radius) + " mm; " + fix +
                          " would fit",
                      chord, 2 * cam.roller_radius});
  }
  return issues;
}

std::vector<DesignIssue> CheckSwing(const GloboidalCam<double>& cam) {
  double lo = 0, hi = 0;
  for (int i = 0; i < 3600; ++i) {
    const double v = cam.motion.Evaluate(2 * kPi * i / 3600).s;
    lo = std::min(lo, v), hi = std::max(hi, v);
  }
  if (lo < -1e-9 || std::abs(hi - cam.swing) > 1e-6) {
    const bool below = lo < -1e-9;
    return {{"motion",
             "the swing must run from 0 to swing_deg = " + IssueNumber(cam.swing / kDeg) +
                 " deg (rise first, in the first motion's direction); it runs from " + IssueNumber(lo / kDeg) +
                 " to " + IssueNumber(hi / kDeg) + " deg: " +
                 (below ? std::string("start with the rise, so that the turret never swings below its start")
                        : "rises that sum to " + IssueNumber(cam.swing / kDeg) + " deg (or swing_deg = " +
                              IssueNumber(hi / kDeg) + ") would fit"),
             below ? lo : hi, below ? 0.0 : cam.swing}};
  }
  return {};
}

std::vector<DesignIssue> CheckContactArm(const DynamicsInput& in) {
  if (!(in.contact_arm_mm > 0.0)) return {};
  const auto lim = RollerAxisLimits(in.cam);
  if (in.contact_arm_mm < lim.l2 || in.contact_arm_mm > lim.l1)
    return {{"contact_arm_mm",
             "expected a length in [l₂, l₁] = [" + IssueNumber(lim.l2) + ", " + IssueNumber(lim.l1) +
                 "] mm (the contact arm lies on the roller), found " + IssueNumber(in.contact_arm_mm) + " mm",
             in.contact_arm_mm, in.contact_arm_mm < lim.l2 ? lim.l2 : lim.l1}};
  return {};
}

CycleSurvey SurveyCycle(const GloboidalCam<double>& cam, double contact_arm_mm, int angle_steps,
                        int axis_steps) {
  const auto lim = RollerAxisLimits(cam);
  std::vector<double> samples;
  for (int i = 0; i < angle_steps; ++i) samples.push_back(2 * kPi * i / angle_steps);
  double start = 0;
  for (const auto& seg : cam.motion.segments()) {
    for (int q = 0; q < 64; ++q) samples.push_back(start + seg.duration * (q + 0.5) / 64);
    start += seg.duration;
  }
  auto update = [](Extreme& x, double v, bool larger, double t, double l, int j) {
    if (!x.set || (larger ? v > x.value : v < x.value)) x = {v, t, l, j, true};
  };
  CycleSurvey s;
  for (int j = 0; j < 2; ++j) {
    s.grid.roller_angle[j].resize(angle_steps);
    s.grid.pressure_angle_at_l1[j].resize(angle_steps);
    s.grid.pressure_angle_at_l2[j].resize(angle_steps);
    s.grid.contact_radius[j].resize(angle_steps);
  }
  s.grid.min_undercut_margin.assign(angle_steps, 1e300);
  for (size_t i = 0; i < samples.size(); ++i) {
    const double t = samples[i];
    const bool on_grid = i < size_t(angle_steps);  // the uniform grid comes first
    for (int j = 1; j <= 2; ++j) {
      for (int k = 0; k < axis_steps; ++k) {
        const double l = AxisGridPoint(lim, k, axis_steps);
        const SurfacePoint<double> p = EvaluateSurface(cam, j, l, t);
        update(s.max_abs_pressure_angle, std::abs(p.pressure_angle), true, t, l, j);
        update(s.min_undercut_margin, p.undercut_margin, false, t, l, j);
        update(s.min_offset_jacobian, p.offset_jacobian, false, t, l, j);
        if (on_grid) {
          if (k == 0) s.grid.pressure_angle_at_l2[j - 1][i] = p.pressure_angle;
          if (k == axis_steps - 1) s.grid.pressure_angle_at_l1[j - 1][i] = p.pressure_angle;
          s.grid.min_undercut_margin[i] = std::min(s.grid.min_undercut_margin[i], p.undercut_margin);
          s.grid.roller_angle[j - 1][i] = p.angle.phi;
        }
      }
      const SurfacePoint<double> pc = EvaluateSurface(cam, j, contact_arm_mm, t);
      if (on_grid) s.grid.contact_radius[j - 1][i] = pc.contact_radius;
      if (pc.contact_radius > 0) {
        update(s.min_contact_radius, pc.contact_radius, false, t, contact_arm_mm, j);
      } else {
        s.conformal = true;
      }
    }
  }
  return s;
}

std::vector<DesignIssue> CheckDesign(const DynamicsInput& in, int angle_steps, int axis_steps) {
  std::vector<DesignIssue> issues = CheckGeometry(in.cam);
  if (!issues.empty()) return issues;
  const auto swing = CheckSwing(in.cam);
  issues.insert(issues.end(), swing.begin(), swing.end());
  const auto arm = CheckContactArm(in);
  issues.insert(issues.end(), arm.begin(), arm.end());
  const CycleSurvey survey = SurveyCycle(in.cam, ContactArm(in), angle_steps, axis_steps);
  if (!(survey.max_abs_pressure_angle.value < kJamPressureAngle))
    issues.push_back({"motion",
                      "infeasible design: the pressure angle reaches " +
                          IssueNumber(survey.max_abs_pressure_angle.value / kDeg) + " deg at cam angle " +
                          IssueNumber(survey.max_abs_pressure_angle.cam_angle_rad / kDeg) +
                          " deg (the turret would jam; the limit is " + IssueNumber(kJamPressureAngle / kDeg) +
                          " deg): a longer cam angle for that motion segment lowers it",
                      survey.max_abs_pressure_angle.value, kJamPressureAngle,
                      survey.max_abs_pressure_angle.cam_angle_rad});
  return issues;
}

}  // namespace camopt::globoidal
