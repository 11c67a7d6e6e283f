// Solids and surfaces through OpenCASCADE (OCCT): STEP AP214 files and triangle meshes for STL.
// No OCCT header is included here: the kernel's half (cad/occt.cc) is a module that cad/solid.cc
// opens on first use, so the rest of camopt compiles, links and starts without OCCT.
#pragma once

#include <string>
#include <vector>

#include "cad/arc_fit.h"
#include "cad/extrusion.h"
#include "cad/stl.h"

namespace camopt::cad {

/// The solid's files. (Its volume and area are not measured here: BRepGProp at 1e-9 cost more than
/// the rest of the solid; the study gives the volume in closed form from the exact profile's area,
/// and ReadStep measures a written file's B-rep for the tests.)
struct SolidOutput {
  std::string step;         ///< STEP AP214 file, with a fixed time stamp (same input, same bytes)
  TriangleMesh mesh;        ///< closed mesh of the solid's faces (vertices merged)
  int faces = 0;
};

/// The extruded solid's STEP file (cad/extrusion.h: arc and line faces exactly as in the chain) and
/// mesh (cad/extrusion.h; OCCT's mesher when the profile is not star-shaped about its centre).
/// @throws std::runtime_error when the bore does not fit or no valid solid can be built.
SolidOutput ExtrudeCam(const Extrusion& e);

/// A grid of points on a surface: points[i][j], i along one direction, j along the other [mm].
using PointGrid = std::vector<std::vector<Eigen::Vector3d>>;

/// One B-spline surface for each grid in one STEP AP214 file: OCCT's approximation
/// (GeomAPI_PointsToBSplineSurface::Init, cubic, C2) within `tolerance_mm` of every grid point.
/// The interpolation through every point it replaces wrote a pole per point: the globoidal
/// example's two surfaces 700 689 bytes, now 137 415 at 1 µm, in the same time.
struct SurfaceOutput {
  std::string step;
  double area_mm2 = 0.0;
  int faces = 0;
};
SurfaceOutput BSplineSurfaces(const std::vector<PointGrid>& grids, const std::string& name, double tolerance_mm);

/// The largest distance from `points` to the nearest face of a STEP file's shape (each face's
/// surface, OCCT GeomAPI_ProjectPointOnSurf), for the tests; INFINITY when the file is not read.
double MaxDistanceToStepFaces(const std::string& content, const std::vector<Eigen::Vector3d>& points);

/// What OCCT reads back from a STEP file (content in memory).
struct StepReadBack {
  int solids = 0, shells = 0, faces = 0;
  double volume_mm3 = 0.0, area_mm2 = 0.0;
  bool valid = false;  ///< BRepCheck_Analyzer on the result
};
StepReadBack ReadStep(const std::string& content);

/// An assembly as a CAD program's document reads it (OCCT's XDE: STEPCAFControl_Reader into an
/// XCAF document): the top shape's name, whether it is an assembly, and each component with the
/// name of its occurrence and of the part it refers to, its placement (the location's translation
/// and its turn about +z) and the part's volume and the placed solid's centroid.
struct AssemblyComponent {
  std::string name, part;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double angle_rad = 0.0;
  double axis_tilt = 0.0;  ///< angle between the placed part's z axis and +z [rad]
  double volume_mm3 = 0.0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< of the placed solid, assembly frame
};
struct AssemblyReadBack {
  bool read = false, assembly = false;
  std::string name;
  std::vector<AssemblyComponent> components;
};
AssemblyReadBack ReadStepAssembly(const std::string& content);

}  // namespace camopt::cad
