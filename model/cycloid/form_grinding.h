// Form grinding of a cycloid disc's tooth spaces (docs/parts.md, "Form grinding"): the wheel's axial
// profile and machine settings that reproduce the modified tooth (Δa, Δρ; tooth_profile.h, eqs. 3–4),
// and the residual form error of the profile the wheel generates.
//
// Set-up. The disc is ground one tooth space at a time, the space centred on the line at angle 0 of
// the disc frame (the root point P(0) = (a' − e − ρ', 0), where roller 0 sits at crank angle 0), then
// indexed by 2π/n2. The wheel, a body of revolution, turns about an axis parallel to the space's
// tangent y, at the centre distance A from the disc's axis along x, and traverses along the disc's
// axis z. In the plane z = z₀ of the wheel's axis its surface is the curve x = A − r_w(y), r_w its
// axial profile (radius at axial position y); off that plane it is farther out
// (x = A − sqrt(r_w² − (z − z₀)²)), so the traverse generates exactly x = A − r_w(y) in every transverse
// section (the form-grinding principle for straight spur profiles: the wheel's axial section is the
// tooth space's transverse section; Litvin & Fuentes, Gear Geometry and Applied Theory, 2nd ed.,
// §§ 1.3, 6 — the envelope of a surface of revolution translated along a line perpendicular to its
// axis). The wheel therefore reproduces the space if, and only if, the space between the
// neighbouring lobes' tips (polar angles ±π/n2, where the profile is symmetric) is a function x(y):
// y increasing monotonically along it; an overhanging flank cannot be reached.
//
// Axial profile. r_w(y) = A − x(y) with A = x_root + R_w (the wheel's largest radius R_w reaches the
// root), sampled at points such that the polygon through them — what a CNC dresser follows — is
// within `tolerance` of the exact curve (each chord's sagitta checked at its midpoint and quarter
// points by the exact projection's distance). The residual form error is the largest distance from
// the exact tooth to that polygon, reported with the points. The wheel's concave radii are the
// lobes' convex radii (curvature > 0 on the disc): a dressing roll must be smaller than the least.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/cycloid/tooth_profile.h"

namespace camopt::cycloid {

struct FormWheel {
  double wheel_radius_mm = 0;      ///< R_w, at the space's root
  double centre_distance_mm = 0;   ///< A, wheel axis to disc axis
  double root_x_mm = 0;            ///< x of the root point
  double tip_x_mm = 0, tip_y_mm = 0;  ///< the lobe tips bounding the space (±tip_y)
  double edge_radius_mm = 0;       ///< r_w at the tips
  double least_radius_mm = 0;      ///< the wheel's smallest radius (the space's outermost point)
  double width_mm = 0;             ///< 2 tip_y: the wheel's width at its edges
  double index_rad = 0;            ///< 2π/n2 per tooth space
  double least_concave_radius_mm = 0;  ///< the wheel's sharpest concave radius (a lobe's least convex one)
  double residual_form_error_mm = 0;   ///< exact tooth to the dressed polygon, largest
  std::vector<double> y_mm, radius_mm, t;  ///< the axial profile's points (and their profile parameter)
};

namespace form_grinding_detail {
// Distance from p to the segment [a, b].
inline double SegmentDistance(const Vec2<double>& p, const Vec2<double>& a, const Vec2<double>& b) {
  const Vec2<double> ab = b - a;
  const double s = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - a - s * ab).norm();
}
// The parameter t in (0, π/n2·2) where the profile's polar angle reaches `angle`, by bisection on the
// polar angle (monotone over the half tooth: the profile is star-shaped about the disc's centre).
inline double ParameterAtAngle(const Drive& d, double angle) {
  double lo = 0.0, hi = 2.0 * kPi / d.teeth;
  auto polar = [&](double t) {
    const Vec2<double> p = ToothProfile<double>(d, t).point;
    return std::atan2(p.y(), p.x());
  };
  for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
    const double mid = 0.5 * (lo + hi);
    (polar(mid) < angle ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}
}  // namespace form_grinding_detail

/// The form wheel for the drive's modified tooth with a largest radius `wheel_radius_mm` and a
/// dressing polygon within `tolerance_mm`. Throws std::invalid_argument (a message naming the
/// field) when the wheel is too small for the space's depth or the space overhangs.
inline FormWheel FormGrindingWheel(const Drive& d, double wheel_radius_mm, double tolerance_mm) {
  using form_grinding_detail::SegmentDistance;
  if (!(tolerance_mm > 0)) throw std::invalid_argument("tolerance_um must be > 0");
  FormWheel w;
  w.index_rad = 2.0 * kPi / d.teeth;
  const double t_tip = form_grinding_detail::ParameterAtAngle(d, kPi / d.teeth);
  const Vec2<double> root = ToothProfile<double>(d, 0.0).point, tip = ToothProfile<double>(d, t_tip).point;
  w.root_x_mm = root.x();
  w.tip_x_mm = tip.x();
  w.tip_y_mm = tip.y();
  w.width_mm = 2.0 * tip.y();
  // The space from tip to tip: −t_tip … t_tip; y must increase along it (no overhang).
  const int probe = 4000;
  double least_radius = INFINITY, x_max = tip.x();
  for (int k = 0; k <= probe; ++k) {
    const double t = -t_tip + 2.0 * t_tip * k / probe;
    const ProfilePoint<double> p = ToothProfile<double>(d, t);
    x_max = std::max(x_max, p.point.x());
    if (!(p.tangent.y() > 0))
      throw std::invalid_argument("the tooth space overhangs at its flank (the profile turns back along the wheel's "
                                  "axis at " + std::to_string(p.point.x()) + ", " + std::to_string(p.point.y()) +
                                  " mm): a form wheel cannot reach it; generate it instead (the cutter path)");
    if (p.curvature > 0) least_radius = std::min(least_radius, 1.0 / p.curvature);
  }
  w.least_concave_radius_mm = least_radius;
  // The wheel reaches from the root (its largest radius) out to the space's outermost point.
  const double depth = x_max - root.x();
  if (!(wheel_radius_mm > depth))
    throw std::invalid_argument("wheel_radius_mm " + std::to_string(wheel_radius_mm) +
                                " mm does not exceed the tooth space's depth " + std::to_string(depth) +
                                " mm (root to the space's outermost point along its centre line): a larger wheel "
                                "would fit");
  w.wheel_radius_mm = wheel_radius_mm;
  w.centre_distance_mm = root.x() + wheel_radius_mm;
  w.edge_radius_mm = w.centre_distance_mm - tip.x();
  w.least_radius_mm = w.centre_distance_mm - x_max;
  // Points: bisect each parameter interval until the chord is within the tolerance of the curve
  // (checked at the interval's quarter, middle and three-quarter points).
  std::vector<double> ts = {-t_tip};
  const double limit = 0.5 * tolerance_mm;  // the midpoint checks, with a margin for between them
  auto chord_error = [&](double t0, double t1) {
    const Vec2<double> a = ToothProfile<double>(d, t0).point, b = ToothProfile<double>(d, t1).point;
    double e = 0;
    for (double f : {0.25, 0.5, 0.75}) e = std::max(e, SegmentDistance(ToothProfile<double>(d, t0 + f * (t1 - t0)).point, a, b));
    return e;
  };
  // Depth-first, left to right.
  std::vector<std::pair<double, double>> todo = {{-t_tip, t_tip}};
  while (!todo.empty()) {
    const auto [t0, t1] = todo.back();
    todo.pop_back();
    if (chord_error(t0, t1) > limit && t1 - t0 > 1e-9) {
      const double m = 0.5 * (t0 + t1);
      todo.push_back({m, t1});
      todo.push_back({t0, m});
    } else {
      ts.push_back(t1);
    }
  }
  for (double t : ts) {
    const Vec2<double> p = ToothProfile<double>(d, t).point;
    w.t.push_back(t);
    w.y_mm.push_back(p.y());
    w.radius_mm.push_back(w.centre_distance_mm - p.x());
  }
  // Residual: the exact tooth's largest distance from the polygon, on 64 points per chord.
  double worst = 0;
  for (size_t i = 0; i + 1 < ts.size(); ++i) {
    const Vec2<double> a = ToothProfile<double>(d, ts[i]).point, b = ToothProfile<double>(d, ts[i + 1]).point;
    for (int k = 1; k < 64; ++k)
      worst = std::max(worst, SegmentDistance(ToothProfile<double>(d, ts[i] + (ts[i + 1] - ts[i]) * k / 64.0).point, a, b));
  }
  w.residual_form_error_mm = worst;
  return w;
}

}  // namespace camopt::cycloid
