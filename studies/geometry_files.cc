#include "studies/geometry_files.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "cad/dxf.h"
#include "cad/solid.h"
#include "studies/format.h"
#include "studies/provenance.h"

#ifndef CAMOPT_VERSION_STRING
#define CAMOPT_VERSION_STRING "unknown"
#endif

namespace camopt::studies {

namespace {

std::vector<cad::ArcSegment> Reversed(const std::vector<cad::ArcSegment>& chain) {
  std::vector<cad::ArcSegment> r;
  r.reserve(chain.size());
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) r.push_back({it->end, it->start, -it->bulge});
  return r;
}

struct Fit {
  cad::FittedCurve curve;
  double deviation_mm;
};

// The fit aims at 90 % of the tolerance: its check points are discrete, and the largest distance
// between them is up to 0.4 % above the largest at them (found by the dense checks in the tests).
constexpr double kFitTarget = 0.9;
// The pieces whose largest check-point deviation is within 20 % of the largest have it refined to
// the local maximum (golden section, 16 points; cad::FitOptions::refine_share): the reported
// deviation is the largest distance between the arcs and the exact curve to about 1e-7 of it
// (the maximum over 400 000 points of the curve on the examples; 8 points per arc, the
// independent check it replaces, found up to 1 % less).
constexpr double kRefineShare = 0.8;
constexpr int kRefinePoints = 16;

// The larger of two deviations, NaN winning (std::max would hide it).
double Worse(double a, double b) { return b <= a ? a : b; }

Fit FitCurve(const cad::CurveFunction& f, const PlanarCamGeometry& cam, double tol_mm) {
  cad::FitOptions o;
  o.tolerance_mm = kFitTarget * tol_mm;
  o.initial_segments = cam.initial_segments;
  o.refine_share = kRefineShare;
  o.refine_points = kRefinePoints;
  Fit fit{cad::FitBiarcsSymmetric(f, cam.t0, cam.t1, cam.symmetry, cam.centre, o), 0.0};
  fit.deviation_mm = fit.curve.max_deviation_mm;
  return fit;
}

// The finest DXF tolerance relative to the part's size: 1 µm on 10 m (machine tools hold about
// 1e-6 of their travel).
constexpr double kMinRelativeTolerance = 1e-7;

struct SizeAndArea {
  double size_mm;   ///< diagonal of the bounding box of the exact closed curve, from 4096 points
  double area_mm2;  ///< area it encloses
};

// One pass over the exact closed curve at t0 + (t1 − t0) i / 2^13, i = 0 ... 2^13, each point
// evaluated once. The size from the 4096 points of even i (those at (t1 − t0) j / 2^12 to the last
// bit: (t1 − t0)(2j) is (t1 − t0) j scaled by a power of two). The area from the polygons through
// 2^13, 2^12 and 2^11 points (each every other point of the one before) extrapolated twice
// (Romberg: the area the chords cut off is a series in h², h⁴, ... on a smooth curve). On the LCR
// II cams it is within 5e-8 mm² of the closed form (the one polygon of 2^17 points it replaces was
// 1e-4 mm² off, at 16 times the curve evaluations); a jump of the curvature (a motion-law junction
// of a disc cam) leaves an error of order h³ Δκ per junction, about 1e-6 mm².
//
// With S-fold rotational symmetry about c (symmetry S > 1, PlanarCamGeometry::symmetry) the pass
// covers one period with n = 4⌈2^13/(4S)⌉ points: its polygons' sectors about c (S times) are
// the whole curve's polygons of S·n points, its points turned S times give the bounding box.
SizeAndArea ClosedCurveSizeAndArea(const cad::CurveFunction& f, double t0, double t1, int symmetry,
                                   const Vec2<double>& centre) {
  const int s = std::max(1, symmetry);
  // Without symmetry about the origin: the points as evaluated (c = 0, n = 2^13, no turn).
  const Vec2<double> c = s > 1 ? centre : Vec2<double>::Zero().eval();
  const int n = 4 * (((1 << 13) + 4 * s - 1) / (4 * s));
  const double period = (t1 - t0) / s;
  std::vector<Vec2<double>> even;
  even.reserve(size_t(n / 2));
  double a[3] = {0.0, 0.0, 0.0};  // n, n/2, n/4 points
  const Vec2<double> first = f(t0) - c;
  Vec2<double> prev[3] = {first, first, first};
  for (int i = 0; i <= n; ++i) {
    const Vec2<double> p = i == 0 ? first : Vec2<double>(f(t0 + period * i / n) - c);
    if (i % 2 == 0 && i < n) even.push_back(p);
    if (i == 0) continue;
    for (int level = 0; level < 3; ++level) {
      if (i % (1 << level) != 0) continue;
      a[level] += 0.5 * Cross(prev[level], p);
      prev[level] = p;
    }
  }
  // The box of the period's points turned S times (the turn's sign does not matter: all S are
  // taken); S = 1: the points themselves (cos 0 = 1, sin 0 = 0 leave them exact).
  double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
  for (int j = 0; j < s; ++j) {
    const double cs = std::cos(2 * kPi * j / s), sn = std::sin(2 * kPi * j / s);
    for (const Vec2<double>& p : even) {
      const double x = j == 0 ? p.x() : cs * p.x() - sn * p.y(), y = j == 0 ? p.y() : sn * p.x() + cs * p.y();
      lo_x = std::min(lo_x, x), hi_x = std::max(hi_x, x);
      lo_y = std::min(lo_y, y), hi_y = std::max(hi_y, y);
    }
  }
  if (s > 1)
    for (double& v : a) v *= s;
  const double r1 = a[0] + (a[0] - a[1]) / 3.0, r1_half = a[1] + (a[1] - a[2]) / 3.0;
  return {std::hypot(hi_x - lo_x, hi_y - lo_y), std::abs(r1 + (r1 - r1_half) / 15.0)};
}

}  // namespace


double ParseBoreDiameter(const Node& n, double limit_diameter_mm, const std::string& limit_name) {
  const double d = n.Positive();
  const double lo = 1e-3 * limit_diameter_mm, hi = (1 - 2e-3) * limit_diameter_mm;
  if (!(d >= lo && d <= hi))
    n.Fail("a bore diameter between " + Format(lo, 4) + " and " + Format(hi, 4) + " mm (0.1% of " + limit_name +
           " (" + Format(limit_diameter_mm, 4) + " mm) and that diameter less a web of 0.1% each side)");
  return d;
}

Mounting ParseMounting(const Node& parent, const std::optional<KeywayInput>& keyway,
                       const std::optional<BoltCircleInput>& bolt, double bore_mm, double limit_diameter_mm,
                       const std::string& limit_name) {
  Mounting m;
  const double web = 1e-3 * limit_diameter_mm, limit_r = 0.5 * limit_diameter_mm - web;
  const double rb = 0.5 * bore_mm;
  double reach = rb;  // the bore's and keyway's farthest point from the centre
  if (keyway) {
    const Node n = parent["keyway"];
    if (!(bore_mm > 0)) n.FailWith("a keyway needs the part's bore_diameter_mm");
    if (!(keyway->width_mm < 0.999 * bore_mm))
      n["width_mm"].FailWith("a keyway narrower than the bore (" + Format(bore_mm, 6) + " mm): below " +
                             Format(0.999 * bore_mm, 6) + " mm would fit");
    const double hw = 0.5 * keyway->width_mm, bottom = rb + keyway->depth_mm;
    reach = std::hypot(bottom, hw);
    if (!(reach < limit_r))
      n["depth_mm"].FailWith("the keyway's corners reach " + Format(reach, 6) + " mm from the centre, beyond " +
                             limit_name + " less a web (" + Format(limit_r, 6) + " mm): a depth below " +
                             Format(std::sqrt(std::max(0.0, limit_r * limit_r - hw * hw)) - rb, 4) + " mm would fit");
    m.keyway_width_mm = keyway->width_mm;
    m.keyway_depth_mm = keyway->depth_mm;
    m.keyway_angle_rad = keyway->angle_deg * kPi / 180.0;
  }
  if (bolt) {
    const Node n = parent["bolt_circle"];
    const double R = 0.5 * bolt->circle_diameter_mm, rh = 0.5 * bolt->hole_diameter_mm;
    if (!(R + rh < limit_r))
      n["circle_diameter_mm"].FailWith("the holes reach " + Format(R + rh, 6) + " mm from the centre, beyond " +
                                       limit_name + " less a web (" + Format(limit_r, 6) + " mm): a circle below " +
                                       Format(2 * (limit_r - rh), 6) + " mm diameter would fit");
    if (!(R - rh > reach + web))
      n["circle_diameter_mm"].FailWith("the holes come within " + Format(R - rh, 6) + " mm of the centre, inside the "
                                       "bore or keyway (" + Format(reach, 6) + " mm) and a web: a circle above " +
                                       Format(2 * (reach + web + rh), 6) + " mm diameter would fit");
    const double pitch = 2 * R * std::sin(kPi / bolt->holes);
    if (!(pitch > 2 * rh + web))
      n["hole_diameter_mm"].FailWith("neighbouring holes overlap (pitch " + Format(pitch, 6) + " mm): holes below " +
                                     Format(pitch - web, 6) + " mm would fit");
    for (int j = 0; j < bolt->holes; ++j) {
      const double a = bolt->angle_deg * kPi / 180.0 + 2 * kPi * j / bolt->holes;
      m.holes.push_back({R * Vec2<double>(std::cos(a), std::sin(a)), bolt->hole_diameter_mm});
    }
  }
  return m;
}

GeometryFileOptions GeometryFileOptionsOf(const GeometryFiles& files) {
  GeometryFileOptions o;
  const std::optional<GeometryFilesInput> in = Enabled(files);
  o.write = in.has_value();
  if (!in) return o;
  o.dxf_tolerance_um = in->dxf_tolerance_um;
  o.stl_ascii = in->stl_format == "ascii";
  o.step = in->step;
  o.assembly_crank_angle_deg = in->assembly_crank_angle_deg;
  return o;
}

GeometryFilesBlock GeometryFilesOf(const GeometryFileOptions& options,
                                   const std::vector<std::pair<std::string, const PlanarCamFit*>>& parts) {
  if (!options.write) return GeometryFilesOff{};
  std::map<std::string, PlanarFitSummary> j;
  for (const auto& [name, fit] : parts) j[name] = fit->summary;
  return j;
}

std::string StlFile(const cad::TriangleMesh& mesh, const std::string& name, const GeometryFileOptions& o) {
  return o.stl_ascii ? cad::AsciiStl(mesh, name) : cad::BinaryStl(mesh, name);
}

namespace {

// The solid's bore, keyway, holes and thickness (the profile is the fit's).
cad::Extrusion ExtrusionOf(const PlanarCamGeometry& cam) {
  cad::Extrusion e;
  e.bore_centre = cam.centre;
  e.bore_diameter_mm = cam.bore_diameter_mm;
  e.keyway_width_mm = cam.mounting.keyway_width_mm;
  e.keyway_depth_mm = cam.mounting.keyway_depth_mm;
  e.keyway_angle_rad = cam.mounting.keyway_angle_rad;
  for (const cad::Hole& h : cam.mounting.holes) e.holes.push_back({cam.centre + h.centre, h.diameter_mm});
  e.thickness_mm = cam.thickness_mm;
  return e;
}

}  // namespace

PlanarCamFit FitPlanarCam(const PlanarCamGeometry& cam, const GeometryFileOptions& options) {
  PlanarCamFit f;
  f.cam = cam;
  if (!options.write) return f;
  // No tolerance finer than kMinRelativeTolerance of the part's size (the diagonal of the exact
  // profile's bounding box): the arcs, hence the solid's and the mesh's work, then stay those of a
  // part of ten metres at 1 µm, whatever the size.
  double tol_mm = options.dxf_tolerance_um * 1e-3;
  const SizeAndArea exact = ClosedCurveSizeAndArea(cam.profile, cam.t0, cam.t1, cam.symmetry, cam.centre);
  const double size = exact.size_mm;
  const bool raised = std::isfinite(size) && kMinRelativeTolerance * size > tol_mm;
  if (raised) tol_mm = kMinRelativeTolerance * size;
  const double tol_um = tol_mm * 1e3;
  f.tolerance_mm = tol_mm;
  Fit profile = FitCurve(cam.profile, cam, tol_mm);
  // Counter-clockwise outer profile (positive area) for the solid and for readers that expect it.
  const bool reversed = cad::EnclosedArea(profile.curve.arcs) < 0;
  if (reversed) profile.curve.arcs = Reversed(profile.curve.arcs);
  f.profile = profile.curve;
  f.max_deviation_mm = profile.deviation_mm;
  f.checked_points = profile.curve.checked_points;
  std::vector<std::string> layers = {"CAM_PROFILE"};
  // A further curve (pitch curve, cutter path) on its own layer, its deviation counted.
  auto add_curve = [&](const cad::CurveFunction& curve, cad::FittedCurve& into, const char* layer) {
    const Fit fit = FitCurve(curve, cam, tol_mm);
    into = fit.curve;
    f.max_deviation_mm = Worse(f.max_deviation_mm, fit.deviation_mm);
    f.checked_points += fit.curve.checked_points;
    layers.push_back(layer);
  };
  if (cam.pitch) add_curve(cam.pitch, f.pitch, "PITCH_CURVE");
  PlanarFitSummary& j = f.summary;
  if (cam.cutter) {
    add_curve(cam.cutter, f.cutter, "CUTTER_PATH");
    j.cutter_diameter_mm = cam.cutter_diameter_mm;
  } else if (!cam.cutter_note.empty()) {
    j.cutter_path = cam.cutter_note;
  }
  if (!cam.rollers.empty()) layers.push_back("ROLLERS");
  if (cam.bore_diameter_mm > 0) layers.push_back("BORE");
  if (!cam.mounting.holes.empty()) layers.push_back("HOLES");
  layers.push_back("CENTRE_MARKS");
  layers.push_back("TEXT");
  f.profile_area_mm2 = exact.area_mm2;
  // A curve the fit cannot follow within the tolerance (absurd sizes, non-finite points): no files.
  f.files = std::isfinite(f.max_deviation_mm) && f.max_deviation_mm <= tol_mm && f.profile.within_tolerance;
  if (!f.files) {
    j.not_written = "the curves could not be fitted within " + Format(tol_um, 4) +
                       " um (largest deviation " + Format(f.max_deviation_mm * 1e3, 4) + " um, " +
                       std::to_string(f.profile.arcs.size()) + " arcs)";
    j.dxf_max_deviation_um = f.max_deviation_mm * 1e3;  // null when not finite
    j.dxf_tolerance_um = tol_um;
    return f;
  }

  j.dxf = cam.file_stem + ".dxf";
  j.dxf_layers = layers;
  j.dxf_tolerance_um = tol_um;
  if (raised)
    j.dxf_tolerance_note = "geometry_files.dxf_tolerance_um " + Format(options.dxf_tolerance_um, 4) +
                              " is below " + Format(kMinRelativeTolerance, 3) + " of the part's size (" +
                              Format(size * 1e-3, 4) + " m): " + Format(tol_um, 4) + " um used";
  j.dxf_max_deviation_um = f.max_deviation_mm * 1e3;
  j.dxf_deviation_check_points = f.checked_points;
  j.dxf_within_tolerance = f.max_deviation_mm <= tol_mm;
  j.profile_arcs = long(f.profile.arcs.size());
  if (f.profile.symmetry > 1) j.profile_symmetry = f.profile.symmetry;
  j.profile_area_mm2 = f.profile_area_mm2;
  f.solid = cam.thickness_mm > 0;
  if (f.solid && cad::ChainCrossesItself(f.profile.arcs)) {
    f.solid = false;
    j.solid = "not written: the profile crosses itself (undercut), it bounds no solid";
  } else if (f.solid) {
    // The STEP walls of a long profile as a closed cubic B-spline fitted to the exact curve at the
    // same target as the arcs (cad/bspline.h), when it has fewer poles than there are arcs.
    if (options.step && f.profile.arcs.size() > 64) {
      std::optional<cad::ClosedCubic> s =
          cad::FitClosedCubic(cam.profile, cam.t0, cam.t1, cam.symmetry, 8 * std::max(1, cam.symmetry),
                              kFitTarget * tol_mm, static_cast<int>(f.profile.arcs.size()) - 1);
      if (s) {
        if (reversed) std::reverse(s->poles.begin(), s->poles.end());
        j.step_profile_spline_poles = long(s->poles.size());
        j.step_max_deviation_um = s->max_deviation_mm * 1e3;
        j.step_deviation_check_points = long(s->checked_points);
        f.spline = std::move(s);
      }
    }
    double bore_area = std::abs(cad::EnclosedArea(cad::BoreChain(ExtrusionOf(cam))));
    for (const cad::Hole& h : cam.mounting.holes) bore_area += kPi * 0.25 * h.diameter_mm * h.diameter_mm;
    j.thickness_mm = cam.thickness_mm;
    j.bore_diameter_mm = cam.bore_diameter_mm;
    if (cam.mounting.keyway_width_mm > 0)
      j.keyway = PlanarFitSummary::Keyway{cam.mounting.keyway_width_mm, cam.mounting.keyway_depth_mm,
                                          cam.mounting.keyway_angle_rad * 180.0 / kPi};
    if (!cam.mounting.holes.empty()) {
      std::vector<PlanarFitSummary::Hole>& holes = j.holes.emplace();
      for (const cad::Hole& h : cam.mounting.holes) holes.push_back({h.centre.x(), h.centre.y(), h.diameter_mm});
    }
    j.solid_volume_mm3 = (f.profile_area_mm2 - bore_area) * cam.thickness_mm;
    if (options.step) j.step = cam.file_stem + ".step";
    j.stl = cam.file_stem + ".stl";
    j.stl_format = options.stl_ascii ? "ascii" : "binary";
  } else {
    j.solid = "not written: no cam thickness given (cam_thickness_mm)";
  }
  return f;
}

void WritePlanarCamFiles(const PlanarCamFit& f, const GeometryFileOptions& options, Outputs& out) {
  if (!f.files) return;
  const PlanarCamGeometry& cam = f.cam;
  cad::DxfDocument dxf;
  dxf.AddLayer("CAM_PROFILE", 7);
  dxf.AddChain("CAM_PROFILE", f.profile.arcs, true);
  if (cam.pitch) {
    dxf.AddLayer("PITCH_CURVE", 8);
    dxf.AddChain("PITCH_CURVE", f.pitch.arcs, true);
  }
  if (cam.cutter) {
    dxf.AddLayer("CUTTER_PATH", 1);
    dxf.AddChain("CUTTER_PATH", f.cutter.arcs, true);
  }
  if (!cam.rollers.empty()) {
    dxf.AddLayer("ROLLERS", 5);
    for (const auto& [c, r] : cam.rollers) dxf.AddCircle("ROLLERS", c, r);
  }
  if (cam.bore_diameter_mm > 0) {
    dxf.AddLayer("BORE", 7);
    if (cam.mounting.keyway_width_mm > 0)
      dxf.AddChain("BORE", cad::BoreChain(ExtrusionOf(cam)), true);
    else
      dxf.AddCircle("BORE", cam.centre, 0.5 * cam.bore_diameter_mm);
  }
  if (!cam.mounting.holes.empty()) {
    dxf.AddLayer("HOLES", 7);
    for (const cad::Hole& h : cam.mounting.holes) dxf.AddCircle("HOLES", cam.centre + h.centre, 0.5 * h.diameter_mm);
  }
  // Centre marks (cam axis, and each roller) and the text block below the drawing.
  dxf.AddLayer("CENTRE_MARKS", 3);
  double ymin = cam.centre.y(), xmin = cam.centre.x(), size = 0.0;
  for (const auto& a : f.profile.arcs) {
    ymin = std::min(ymin, a.start.y());
    xmin = std::min(xmin, a.start.x());
    size = std::max(size, (a.start - cam.centre).norm());
  }
  for (const auto& [c, r] : cam.rollers) ymin = std::min(ymin, c.y() - r), xmin = std::min(xmin, c.x() - r);
  const double mark = std::max(1.0, 0.08 * size);
  dxf.AddCentreMark("CENTRE_MARKS", cam.centre, mark);
  for (const auto& [c, r] : cam.rollers) dxf.AddCentreMark("CENTRE_MARKS", c, std::min(mark, r));
  for (const cad::Hole& h : cam.mounting.holes)
    dxf.AddCentreMark("CENTRE_MARKS", cam.centre + h.centre, std::min(mark, 0.75 * h.diameter_mm));
  dxf.AddLayer("TEXT", 7);
  const double h = std::max(1.0, 0.04 * size);
  const std::vector<std::string> lines = {
      cam.design_name + ": " + cam.cam_name,
      "units: mm (INSUNITS 4); curves: arcs within " + Format(f.tolerance_mm * 1e3, 4) +
          " um of the exact profile (largest found " + Format(f.max_deviation_mm * 1e3, 3) + " um)",
      cam.cutter ? "cutter path: cutter diameter " + Format(cam.cutter_diameter_mm, 6) + " mm"
                 : "cutter path: " + (cam.cutter_note.empty() ? std::string("none") : cam.cutter_note),
      "camopt " + CamoptVersion()};
  for (size_t i = 0; i < lines.size(); ++i)
    dxf.AddText("TEXT", Vec2<double>(xmin, ymin - (2.0 + 1.6 * (i + 1)) * h), h, lines[i]);
  out.Add(cam.file_stem + ".dxf", dxf.ToString());

  if (!f.solid) return;
  cad::Extrusion e = ExtrusionOf(cam);
  e.profile = f.profile.arcs;
  e.profile_spline = f.spline;
  e.name = cam.design_name + " " + cam.cam_name;
  e.step = options.step;
  cad::SolidOutput solid = cad::ExtrudeCam(e);
  if (options.step) out.Add(cam.file_stem + ".step", std::move(solid.step));
  out.Add(cam.file_stem + ".stl", StlFile(solid.mesh, e.name, options));
}

}  // namespace camopt::studies
