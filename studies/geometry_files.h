// Geometry files of a planar cam (DXF with arcs, STEP solid, STL mesh) and the shared
// "geometry_files" block of a study, for every cam kind (lcr_analysis, cycloid_ltca, disc_cam;
// globoidal_cam uses the same options for its surfaces):
//
//   "geometry_files": { "dxf_tolerance_um": 1,        // largest distance of the DXF/STEP arcs
//                                                      // from the model's exact profile
//                       "stl_format": "binary",        // or "ascii"
//                       "step": true }                 // write the STEP solids/surfaces
//   "geometry_files": false                              // none at all: no arc fit, no DXF/STEP/STL
//                                                        // (a sweep of analyses); result.json
//                                                        // says {"written": false}
//
// The fitting error, measured against the exact profile function (not the sampled points), goes
// to result.json under "geometry_files".
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "cad/arc_fit.h"
#include "cad/bspline.h"
#include "cad/extrusion.h"
#include "cad/stl.h"
#include "studies/archive.h"
#include "studies/input.h"
#include "studies/study.h"

namespace camopt::studies {

struct GeometryFileOptions {
  bool write = true;  ///< false: "geometry_files": false, no geometry files and no fit
  double dxf_tolerance_um = 1.0;
  bool stl_ascii = false;
  bool step = true;
  double assembly_crank_angle_deg = 0.0;  ///< the crank angle assembly.step shows (docs/parts.md)
};

/// The object form of the "geometry_files" block, declared once (studies/archive.h).
struct GeometryFilesInput {
  double dxf_tolerance_um = 1.0;
  std::string stl_format = "binary";
  bool step = true;
  double assembly_crank_angle_deg = 0.0;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("dxf_tolerance_um", &dxf_tolerance_um,
             Field().In(0.01, 1000.0).Unit("µm").Desc("largest distance of the DXF/STEP arcs from the exact profile"));
    a->Visit("stl_format", &stl_format, Field().OneOf({"binary", "ascii"}).Desc("STL encoding"));
    a->Visit("step", &step, Field().Desc("write the STEP solids or surfaces"));
    a->Visit("assembly_crank_angle_deg", &assembly_crank_angle_deg,
             Field().In(-3600.0, 3600.0).Unit("deg").Desc(
                 "the crank angle at which assembly.step places the parts (cycloid_ltca; docs/parts.md)"));
  }
};

/// "keyway": a hub's key slot in the bore (DIN 6885-1 gives width and depth t2 by shaft diameter).
struct KeywayInput {
  double width_mm = 0, depth_mm = 0, angle_deg = 0;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("width_mm", &width_mm, Field().Required().Positive().Unit("mm").Desc("the slot's width, below the bore"));
    a->Visit("depth_mm", &depth_mm,
             Field().Required().Positive().Unit("mm").Desc(
                 "the slot's depth beyond the bore's radius at its centre line (the hub's t2)"));
    a->Visit("angle_deg", &angle_deg,
             Field().In(-360.0, 360.0).Unit("deg").Desc("the slot's direction in the part's frame (absent: 0, along +x)"));
  }
};

/// "bolt_circle": equal through-holes on a circle about the part's centre.
struct BoltCircleInput {
  int holes = 0;
  double circle_diameter_mm = 0, hole_diameter_mm = 0, angle_deg = 0;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("holes", &holes, Field().Required().AtLeast(2).AtMost(360, "at most 360 holes").Desc("number of holes"));
    a->Visit("circle_diameter_mm", &circle_diameter_mm,
             Field().Required().Positive().Unit("mm").Desc("the holes' pitch circle diameter"));
    a->Visit("hole_diameter_mm", &hole_diameter_mm, Field().Required().Positive().Unit("mm").Desc("each hole's diameter"));
    a->Visit("angle_deg", &angle_deg,
             Field().In(-360.0, 360.0).Unit("deg").Desc("the first hole's angle in the part's frame (absent: 0, on +x)"));
  }
};

/// The rule between a part's bore, keyway and bolt circle and its profile (ParseMounting), for
/// the CrossFieldRules of the object that holds them.
inline CrossFieldRule MountingRule() {
  return {{"keyway", "bolt_circle", "bore_diameter_mm"},
          "a keyway narrower than the bore, its corners inside the part's profile circle less a web; the bolt "
          "circle's holes inside that circle, clear of the bore and keyway and of each other",
          "would fit"};
}

/// A part's bore features beyond the plain bore: the keyway and the bolt circle's holes.
struct Mounting {
  std::vector<cad::Hole> holes;
  double keyway_width_mm = 0, keyway_depth_mm = 0, keyway_angle_rad = 0;
};

/// Reads `parent`'s optional "keyway" and "bolt_circle" (declared by KeywayInput and
/// BoltCircleInput, read as `keyway` and `bolt`) for a part of bore `bore_mm` (0: none) whose
/// profile keeps outside the circle of `limit_diameter_mm` (named `limit_name`): a keyway needs the
/// bore and stays inside that circle; the holes stay inside it, clear of the bore and keyway and
/// of each other (a web of 0.1 % of the limit each side). @throws StudyError naming the field and
/// what would fit.
Mounting ParseMounting(const Node& parent, const std::optional<KeywayInput>& keyway,
                       const std::optional<BoltCircleInput>& bolt, double bore_mm, double limit_diameter_mm,
                       const std::string& limit_name);

/// The root block "geometry_files" of a study: true (absent: the defaults), false (none at all) or
/// the settings.
using GeometryFiles = BoolOr<GeometryFilesInput>;

/// What a study's "geometry_files" asks for, as the writers take it.
GeometryFileOptions GeometryFileOptionsOf(const GeometryFiles& files);

/// The optional bore of a part at `n` (a "bore_diameter_mm" field, > 0): between 1e-3 and
/// 1 − 2e-3 times `limit_diameter_mm` (the diameter the bore must stay inside, named by
/// `limit_name`, e.g. "the disc's root diameter"), so that the part keeps a bore a shop can drill
/// and a web its solid model can close. Fails with the range that would fit.
double ParseBoreDiameter(const Node& n, double limit_diameter_mm, const std::string& limit_name);

/// One planar cam as its geometry files see it. Curves are functions of a parameter over
/// [t0, t1] (closed curves), in the cam frame [mm].
struct PlanarCamGeometry {
  std::string file_stem;   ///< "input_cam" → input_cam.dxf, input_cam.step, input_cam.stl
  std::string design_name; ///< the study's name (text block, STEP product)
  std::string cam_name;    ///< "input cam", "cycloid disc", ...
  cad::CurveFunction profile;
  cad::CurveFunction pitch;   ///< roller-centre curve; empty: none
  cad::CurveFunction cutter;  ///< cutter-centre path; empty: none (see cutter_note)
  double cutter_diameter_mm = 0.0;
  std::string cutter_note;    ///< why there is no cutter path layer
  double t0 = 0.0, t1 = 2 * kPi;
  int initial_segments = 64;
  /// Rotational symmetry of the curves about `centre`: advancing t by (t1 − t0)/symmetry turns
  /// every curve by ±2π/symmetry. Fits and size/area then evaluate one period (checked:
  /// cad::FitBiarcsSymmetric); 1: none.
  int symmetry = 1;
  Vec2<double> centre = Vec2<double>::Zero();  ///< cam axis
  std::vector<std::pair<Vec2<double>, double>> rollers;  ///< circles drawn on a ROLLERS layer
  double thickness_mm = 10.0;
  double bore_diameter_mm = 0.0;  ///< 0: no bore
  Mounting mounting;              ///< keyway and bolt-circle holes (the solid's and the DXF's)
};

/// What result.json says of one planar part's geometry files (FitPlanarCam): the fit's tolerance
/// and deviation, the DXF's layers, and with a thickness the solid's STEP/STL, or why a file is
/// not written.
struct PlanarFitSummary {
  struct Keyway {
    double width_mm = 0, depth_mm = 0, angle_deg = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("width_mm", &width_mm, Field().Unit("mm"));
      a->Visit("depth_mm", &depth_mm, Field().Unit("mm"));
      a->Visit("angle_deg", &angle_deg, Field().Unit("°"));
    }
  };
  struct Hole {
    double x_mm = 0, y_mm = 0, diameter_mm = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("x_mm", &x_mm, Field().Unit("mm").Desc("centre, in the part's frame"));
      a->Visit("y_mm", &y_mm, Field().Unit("mm"));
      a->Visit("diameter_mm", &diameter_mm, Field().Unit("mm"));
    }
  };
  std::optional<double> cutter_diameter_mm;
  std::optional<std::string> cutter_path, not_written;
  double dxf_max_deviation_um = 0, dxf_tolerance_um = 0;
  std::optional<std::string> dxf;
  std::optional<std::vector<std::string>> dxf_layers;
  std::optional<std::string> dxf_tolerance_note;
  std::optional<long> dxf_deviation_check_points;
  std::optional<bool> dxf_within_tolerance;
  std::optional<long> profile_arcs;
  std::optional<int> profile_symmetry;
  std::optional<double> profile_area_mm2;
  std::optional<std::string> solid;
  std::optional<long> step_profile_spline_poles;
  std::optional<double> step_max_deviation_um;
  std::optional<long> step_deviation_check_points;
  std::optional<double> thickness_mm, bore_diameter_mm;
  std::optional<Keyway> keyway;
  std::optional<std::vector<Hole>> holes;
  std::optional<double> solid_volume_mm3;
  std::optional<std::string> step, stl, stl_format;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("cutter_diameter_mm", &cutter_diameter_mm, Field().Unit("mm").Desc("with a cutter path: the cutter"));
    a->Visit("cutter_path", &cutter_path, Field().Desc("why there is no cutter path"));
    a->Visit("not_written", &not_written, Field().Desc("why no file is written (the curves could not be fitted)"));
    a->Visit("dxf_max_deviation_um", &dxf_max_deviation_um,
             Field().NullWhenNotFinite().Unit("µm").Desc("the arcs' largest distance from the exact curves"));
    a->Visit("dxf_tolerance_um", &dxf_tolerance_um, Field().Unit("µm").Desc("the fit's tolerance"));
    a->Visit("dxf", &dxf, Field().Desc("the DXF file"));
    a->Visit("dxf_layers", &dxf_layers, Field().Desc("its layers"));
    a->Visit("dxf_tolerance_note", &dxf_tolerance_note,
             Field().Desc("when the tolerance asked for was raised to a part's relative floor"));
    a->Visit("dxf_deviation_check_points", &dxf_deviation_check_points,
             Field().Desc("points at which the deviation was measured"));
    a->Visit("dxf_within_tolerance", &dxf_within_tolerance, Field());
    a->Visit("profile_arcs", &profile_arcs, Field().Desc("arcs of the profile"));
    a->Visit("profile_symmetry", &profile_symmetry, Field().Desc("the profile's rotational symmetry, when > 1"));
    a->Visit("profile_area_mm2", &profile_area_mm2, Field().Unit("mm²").Desc("of the exact profile"));
    a->Visit("solid", &solid, Field().Desc("why no solid (STEP, STL) is written"));
    a->Visit("step_profile_spline_poles", &step_profile_spline_poles,
             Field().Desc("the STEP walls' closed cubic B-spline, when it has fewer poles than the profile arcs"));
    a->Visit("step_max_deviation_um", &step_max_deviation_um, Field().Unit("µm").Desc("its largest deviation"));
    a->Visit("step_deviation_check_points", &step_deviation_check_points, Field());
    a->Visit("thickness_mm", &thickness_mm, Field().Unit("mm"));
    a->Visit("bore_diameter_mm", &bore_diameter_mm, Field().Unit("mm"));
    a->Visit("keyway", &keyway, Field());
    a->Visit("holes", &holes, Field());
    a->Visit("solid_volume_mm3", &solid_volume_mm3, Field().Unit("mm³"));
    a->Visit("step", &step, Field().Desc("the STEP file"));
    a->Visit("stl", &stl, Field().Desc("the STL file"));
    a->Visit("stl_format", &stl_format, Field().OneOf({"ascii", "binary"}));
  }
};

/// result.json's "geometry_files" when they are switched off.
struct GeometryFilesOff {
  bool written = false;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("written", &written, Field().Desc("false: geometry_files is false"));
  }
};
/// result.json's "geometry_files": each part's summary by its name, or {"written": false}.
using GeometryFilesBlock = std::variant<std::map<std::string, PlanarFitSummary>, GeometryFilesOff>;

/// A cam's curves fitted with arcs (in Run: cheap) and what result.json says about them.
struct PlanarCamFit {
  PlanarCamGeometry cam;
  cad::FittedCurve profile, pitch, cutter;  ///< profile counter-clockwise
  /// The profile as a closed cubic B-spline for the STEP walls (counter-clockwise, within the same
  /// tolerance of the exact curve), when it has fewer poles than the profile has arcs.
  std::optional<cad::ClosedCubic> spline;
  double tolerance_mm = 0.0;                ///< used: dxf_tolerance_um, or 1e-7 of a larger part
  double max_deviation_mm = 0.0;            ///< over profile, pitch and cutter path
  long checked_points = 0;
  double profile_area_mm2 = 0.0;            ///< of the exact profile
  bool files = false;                       ///< fitted within the tolerance: the files are written
  bool solid = false;                       ///< STEP/STL written (a thickness, no undercut)
  PlanarFitSummary summary;                 ///< the entry for result.json
};

/// Fits the curves and measures the fit against the exact curve functions (nothing when
/// options.write is false: files = false, an empty summary).
PlanarCamFit FitPlanarCam(const PlanarCamGeometry& cam, const GeometryFileOptions& options);

/// result.json's "geometry_files": each part's summary by its name, or {"written": false} when the
/// files are switched off.
GeometryFilesBlock GeometryFilesOf(const GeometryFileOptions& options,
                                   const std::vector<std::pair<std::string, const PlanarCamFit*>>& parts);

/// Writes `STEM.dxf`, and `STEM.step` (when asked) and `STEM.stl` when the cam has a thickness,
/// into `out`. The solid is built by OpenCASCADE from the fitted arcs.
void WritePlanarCamFiles(const PlanarCamFit& fit, const GeometryFileOptions& options, Outputs& out);

/// STL file content in the chosen format.
std::string StlFile(const cad::TriangleMesh& mesh, const std::string& name, const GeometryFileOptions& options);


}  // namespace camopt::studies
