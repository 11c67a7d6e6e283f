// An extruded planar cam written without a CAD kernel: its STEP AP214 B-rep (the walls, the planes
// at both ends and the bore's two half-cylinders; ISO 10303-42 entities in an ISO 10303-21 file) and
// its closed triangle mesh for STL. A chain of up to 64 arcs and lines has a wall per arc (a
// cylinder) or line (a plane), as the OCCT extrusion gave them (cad/occt.cc); a longer one a wall
// per run of 64, each the run as a rational quadratic B-spline surface (every arc one or more
// segments of it, exactly: Piegl & Tiller, The NURBS Book, §7.3), a third of the text for the
// cycloid disc's 690 arcs. Either way the faces are the chain's arcs and lines exactly. A long
// profile that comes with a closed cubic B-spline of fewer poles (cad/bspline.h, fitted to the
// exact curve within the same tolerance) has that spline's walls instead: a tenth of the file for
// the cycloid discs (docs/parts.md "File sizes"). The kernel is left for what needs it
// (reading files back in the tests, B-spline surfaces of other shapes, and the mesh of a profile
// the fast triangulation below cannot take).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cad/arc_fit.h"
#include "cad/bspline.h"
#include "cad/stl.h"

namespace camopt::cad {

/// A circular through-hole of an extruded part [mm].
struct Hole {
  Vec2<double> centre = Vec2<double>::Zero();
  double diameter_mm = 0.0;
};

/// A planar cam extruded along +z: outer profile (a closed, counter-clockwise chain of arcs in the
/// xy plane) minus an optional circular bore and further circular holes (a disc's output-pin holes,
/// a bolt circle).
struct Extrusion {
  std::vector<ArcSegment> profile;     ///< closed chain [mm]
  Vec2<double> bore_centre = Vec2<double>::Zero();  ///< also the cam's centre without a bore
  double bore_diameter_mm = 0.0;       ///< 0: no bore
  std::vector<Hole> holes;             ///< each inside the profile, clear of the bore and each other
  /// A keyway in the bore (a hub's key slot, DIN 6885-1): width, and depth beyond the bore's radius
  /// at the slot's centre line (the slot's bottom at bore radius + depth), along `keyway_angle_rad`
  /// from the centre. 0: a plain bore.
  double keyway_width_mm = 0.0, keyway_depth_mm = 0.0, keyway_angle_rad = 0.0;
  double thickness_mm = 10.0;
  /// The profile as a closed cubic B-spline (FitClosedCubic of the exact curve, counter-clockwise),
  /// if one was fitted: the STEP walls are this spline's where SplineWalls says so; the mesh and the
  /// checks of the chain stay the arcs'.
  std::optional<ClosedCubic> profile_spline;
  std::string name = "cam";            ///< product name in the STEP file
  double mesh_deflection_mm = 0.002;   ///< STL chord deviation from the solid's faces
  bool step = true;                    ///< false: no STEP file (SolidOutput::step stays empty)
};

/// The bore's contour as a closed chain counter-clockwise about the bore's centre: two half circles,
/// or with a keyway the bore's arc outside the slot and the slot's three sides. Empty: no bore.
std::vector<ArcSegment> BoreChain(const Extrusion& e);

/// The mesh's chord deviation: Extrusion::mesh_deflection_mm, raised above 4e-6 of the profile's
/// bounding-box diagonal (the triangle count then stays that of a part of about half a metre,
/// whatever its size: a 5 m cam at a fixed 2 µm took 85 s and 4.8 GB to mesh).
double MeshDeflection(const Extrusion& e);

/// The closed mesh of the extrusion: each arc cut into chords whose sagitta is at most `deflection`
/// (whose turn, and the angle it spans seen from the centre, are at most 0.1 rad), the walls two triangles per chord, the end faces triangulated
/// by merging the profile and the bore (or a fan from the centre without a bore) in polar angle
/// about the bore's centre. nullopt when that triangulation is not valid — a triangle not
/// counter-clockwise, i.e. the profile is not star-shaped about the centre: with every triangle
/// counter-clockwise the triangles cover the face exactly once (their indicator functions sum to
/// the boundary's winding number, 1 inside, 0 outside), which is the check.
/// `chain_checked`: StepOfExtrusion has accepted `e` already (its checks of the chain and the bore
/// are not repeated).
std::optional<TriangleMesh> MeshExtrusion(const Extrusion& e, double deflection, bool chain_checked = false);

/// Whether the STEP walls are `profile_spline`'s: a chain longer than one wall of arcs takes
/// (64) and a spline of fewer poles than the chain has arcs (a rational quadratic B-spline through
/// the arcs has two poles per arc). Otherwise a wall per arc or line, or per run of 64 of them.
bool SplineWalls(const Extrusion& e);

/// The STEP AP214 file of the extrusion (a MANIFOLD_SOLID_BREP in millimetres), with a fixed time
/// stamp: the same extrusion gives the same bytes. Throws std::invalid_argument when the bore or a
/// hole does not lie inside the profile with room to spare, two of them overlap, or the chain is
/// not closed.
std::string StepOfExtrusion(const Extrusion& e);

/// One placed occurrence of a part in an assembly: the part's frame moved to `origin` [mm] and
/// turned by `angle_rad` about +z.
struct Placement {
  std::string name;            ///< occurrence name, e.g. "disc_2" or "ring_pin 7"
  size_t part = 0;             ///< index into the assembly's parts
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double angle_rad = 0.0;
};

/// A STEP AP214 assembly (ISO 10303-214 product structure): a product per part (its B-rep as
/// StepOfExtrusion writes it, in its own frame), a top product `name`, and for each placement a
/// NEXT_ASSEMBLY_USAGE_OCCURRENCE with a CONTEXT_DEPENDENT_SHAPE_REPRESENTATION whose
/// ITEM_DEFINED_TRANSFORMATION maps the part's frame to its place — the structure CAD programs open
/// as an assembly tree. Fixed time stamp: the same input gives the same bytes.
std::string StepAssembly(const std::string& name, const std::vector<Extrusion>& parts,
                         const std::vector<Placement>& placements);

/// A text as the contents of a STEP string (ISO 10303-21 §6.4.3, between its apostrophes).
std::string StepString(const std::string& text);

}  // namespace camopt::cad
