// The extruded cam written without a CAD kernel (cad/extrusion.h): its STEP B-rep read back by
// OpenCASCADE and measured against closed-form volumes and areas, its mesh checked for closedness,
// for lying on the exact arcs and for the fall-back when the profile is not star-shaped.
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "cad/extrusion.h"
#include "cad/solid.h"
#include "cad/stl.h"

namespace camopt {
namespace cad_extrusion_test {

constexpr double kPi = 3.14159265358979323846;
// OCCT's volume and area of a B-rep of lines and circles: its integration, not the file, limits it.
constexpr double kMeasureRelTol = 1e-6;

// A closed chain through `corners` with the same bulge on every side.
std::vector<cad::ArcSegment> Chain(const std::vector<Vec2<double>>& corners, double bulge) {
  std::vector<cad::ArcSegment> c;
  for (size_t i = 0; i < corners.size(); ++i) c.push_back({corners[i], corners[(i + 1) % corners.size()], bulge});
  return c;
}

// Area of the circular segment between a chord c and its arc of sweep θ = 4 atan|bulge|:
// r²(θ − sin θ)/2 with r = c / (2 sin(θ/2)).
double SegmentArea(double chord, double bulge) {
  const double theta = 4 * std::atan(std::abs(bulge)), r = chord / (2 * std::sin(theta / 2));
  return r * r * (theta - std::sin(theta)) / 2;
}
double SegmentLength(double chord, double bulge) {
  const double theta = 4 * std::atan(std::abs(bulge)), r = chord / (2 * std::sin(theta / 2));
  return r * theta;
}

// Volume of a closed, outward-oriented mesh by the divergence theorem.
double MeshVolume(const cad::TriangleMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) v += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6;
  return v;
}

struct Case {
  const char* name;
  cad::Extrusion e;
  double area, perimeter;  // of the end face, closed form (bore removed)
};

std::vector<Case> Cases() {
  std::vector<Case> cases;
  const double t = 7.5;
  {  // a circle of radius 10 from four quarter arcs, bore 6 mm off centre
    cad::Extrusion e;
    e.profile = Chain({{10, 0}, {0, 10}, {-10, 0}, {0, -10}}, std::tan(kPi / 8));
    e.bore_centre = Vec2<double>(1.0, -0.5);
    e.bore_diameter_mm = 6;
    e.thickness_mm = t;
    cases.push_back({"circle", e, kPi * (100 - 9), 2 * kPi * 10 + 2 * kPi * 3});
  }
  {  // a square of lines, 20 mm, with a bore of 8 mm
    cad::Extrusion e;
    e.profile = Chain({{-10, -10}, {10, -10}, {10, 10}, {-10, 10}}, 0.0);
    e.bore_diameter_mm = 8;
    e.thickness_mm = t;
    cases.push_back({"square", e, 400 - kPi * 16, 80 + 2 * kPi * 4});
  }
  {  // a diamond whose sides are concave arcs (clockwise in a counter-clockwise chain), no bore
    const double b = -std::tan(kPi / 16), chord = 10 * std::sqrt(2.0);
    cad::Extrusion e;
    e.profile = Chain({{10, 0}, {0, 10}, {-10, 0}, {0, -10}}, b);
    e.thickness_mm = t;
    cases.push_back({"concave diamond", e, 200 - 4 * SegmentArea(chord, b), 4 * SegmentLength(chord, b)});
  }
  {  // convex arcs and lines alternating (a rounded square), bore 5 mm
    const double q = std::tan(kPi / 8);
    cad::Extrusion e;
    const std::vector<Vec2<double>> p = {{10, -8}, {10, 8}, {8, 10}, {-8, 10}, {-10, 8}, {-10, -8}, {-8, -10}, {8, -10}};
    for (int i = 0; i < 8; ++i) e.profile.push_back({p[i], p[(i + 1) % 8], i % 2 == 0 ? 0.0 : q});
    e.bore_diameter_mm = 5;
    e.thickness_mm = t;
    // 20×20 square minus four 2×2 corners plus four quarter discs of radius 2.
    cases.push_back({"rounded square", e, 400 - 16 + 4 * kPi - kPi * 6.25, 4 * 16 + 2 * kPi * 2 + 2 * kPi * 2.5});
  }
  return cases;
}

TEST(ExtrusionStep, ReadsBackAsOneValidSolidWithTheClosedFormVolumeAndArea) {
  for (const Case& c : Cases()) {
    SCOPED_TRACE(c.name);
    const std::string step = cad::StepOfExtrusion(c.e);
    const cad::StepReadBack back = cad::ReadStep(step);
    EXPECT_EQ(back.solids, 1);
    EXPECT_TRUE(back.valid);
    const size_t walls = c.e.profile.size() + (c.e.bore_diameter_mm > 0 ? 2 : 0);
    EXPECT_EQ(back.faces, static_cast<int>(walls + 2));
    const double volume = c.area * c.e.thickness_mm, area = 2 * c.area + c.perimeter * c.e.thickness_mm;
    EXPECT_NEAR(back.volume_mm3 / volume - 1, 0.0, kMeasureRelTol);
    EXPECT_NEAR(back.area_mm2 / area - 1, 0.0, kMeasureRelTol);
    EXPECT_EQ(step, cad::StepOfExtrusion(c.e));  // the same bytes every time
  }
}

TEST(ExtrusionStep, NameIsAStepStringAndTheBoreMustFit) {
  cad::Extrusion e = Cases()[0].e;
  e.name = "it's a \\ cam";
  const std::string step = cad::StepOfExtrusion(e);
  EXPECT_NE(step.find("PRODUCT('it''s a \\\\ cam','it''s a \\\\ cam',"), std::string::npos);
  EXPECT_EQ(cad::ReadStep(step).solids, 1);
  e.bore_diameter_mm = 19;  // centre (1, −0.5): reaches past the radius-10 profile
  EXPECT_THROW(cad::StepOfExtrusion(e), std::invalid_argument);
  EXPECT_THROW(cad::ExtrudeCam(e), std::runtime_error);
  e.bore_diameter_mm = 6;
  e.bore_centre = Vec2<double>(30, 0);  // outside
  EXPECT_THROW(cad::StepOfExtrusion(e), std::invalid_argument);
}

TEST(ExtrusionMesh, ClosedOnTheArcsAndWithinTheDeflection) {
  for (const Case& c : Cases()) {
    SCOPED_TRACE(c.name);
    const double deflection = 0.002;
    const std::optional<cad::TriangleMesh> mesh = cad::MeshExtrusion(c.e, deflection);
    ASSERT_TRUE(mesh.has_value());
    const cad::EdgeCheck edges = cad::CheckEdges(*mesh);
    EXPECT_EQ(edges.free_edges + edges.misoriented_edges + edges.overused_edges, 0);
    // The walls' chords at z = 0 (edges of triangles spanning both ends): their end points lie on
    // the profile or the bore, their midpoints within the deflection of it.
    const double rb = 0.5 * c.e.bore_diameter_mm;
    const auto distance = [&](const Vec2<double>& q) {
      double d = rb > 0 ? std::abs((q - c.e.bore_centre).norm() - rb) : INFINITY;
      for (const cad::ArcSegment& s : c.e.profile) d = std::min(d, cad::DistanceToArc(s, q));
      return d;
    };
    double worst_end = 0, worst_mid = 0;
    int chords = 0;
    for (const auto& t : mesh->triangles) {
      const bool wall = mesh->vertices[t[0]].z() != mesh->vertices[t[1]].z() ||
                        mesh->vertices[t[0]].z() != mesh->vertices[t[2]].z();
      if (!wall) continue;
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d& p = mesh->vertices[t[k]];
        const Eigen::Vector3d& q = mesh->vertices[t[(k + 1) % 3]];
        if (p.z() != 0.0 || q.z() != 0.0) continue;
        const Vec2<double> a(p.x(), p.y()), b(q.x(), q.y());
        worst_end = std::max({worst_end, distance(a), distance(b)});
        worst_mid = std::max(worst_mid, distance(0.5 * (a + b)));
        ++chords;
      }
    }
    EXPECT_GT(chords, 0);
    EXPECT_LT(worst_end, 1e-12);
    EXPECT_LE(worst_mid, deflection * (1 + 1e-9));
    // Its volume: the closed form less the chords' segments, which are at most deflection × perimeter.
    const double volume = c.area * c.e.thickness_mm;
    const double v = MeshVolume(*mesh);
    EXPECT_LE(std::abs(v - volume), deflection * c.perimeter * c.e.thickness_mm) << v << " vs " << volume;
  }
}

TEST(ExtrusionMesh, AProfileNotStarShapedAboutItsCentreFallsBackToTheKernelsMesh) {
  // An L-shaped profile whose corner region hides from the centre (5, 5) near the inner corner:
  // the fan from the centre folds, MeshExtrusion refuses, ExtrudeCam meshes it with OCCT.
  cad::Extrusion e;
  e.profile = Chain({{0, 0}, {20, 0}, {20, 4}, {4, 4}, {4, 20}, {0, 20}}, 0.0);
  e.bore_centre = Vec2<double>(15, 2);
  e.thickness_mm = 3;
  e.mesh_deflection_mm = 0.01;
  EXPECT_FALSE(cad::MeshExtrusion(e, 0.01).has_value());
  const cad::SolidOutput solid = cad::ExtrudeCam(e);
  const cad::EdgeCheck edges = cad::CheckEdges(solid.mesh);
  EXPECT_EQ(edges.free_edges + edges.misoriented_edges + edges.overused_edges, 0);
  EXPECT_NEAR(MeshVolume(solid.mesh), (80 + 64) * 3.0, 1e-9);
  const cad::StepReadBack back = cad::ReadStep(solid.step);
  EXPECT_TRUE(back.valid);
  EXPECT_NEAR(back.volume_mm3 / ((80 + 64) * 3.0) - 1, 0.0, kMeasureRelTol);
}

}  // namespace cad_extrusion_test
}  // namespace camopt
