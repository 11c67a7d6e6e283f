// Whole parts (studies/parts.h, studies/cycloid_parts.h, cad/extrusion.h): extrusions with holes
// read back by OpenCASCADE against closed forms, their meshes closed and within the deflection, the
// STEP assembly opened as an XDE document (components, part names, placements, volumes), and a
// three-disc cycloid drive's parts placed so that every disc meshes the ring pins at the assembly's
// crank angle — checked with the papers' profile formula and the placements read back from the file.
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cad/extrusion.h"
#include "cad/solid.h"
#include "studies/input.h"
#include "studies/parts.h"
#include "studies/study.h"
#include "test_util.h"

namespace camopt {
namespace {

constexpr double kPi = 3.14159265358979323846;

double MeshVolume(const cad::TriangleMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) v += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6;
  return v;
}

// Every directed edge has exactly one reversed partner: closed and consistently oriented.
bool ClosedAndOriented(const cad::TriangleMesh& m) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& [e, n] : directed) {
    const auto back = directed.find({e.second, e.first});
    if (n != 1 || back == directed.end() || back->second != 1) return false;
  }
  return true;
}

// A disc of radius 30 with a bore of 8 and six holes of 6 on a circle of 15, 5 thick.
cad::Extrusion HoledDisc() {
  cad::Extrusion e;
  e.profile = studies::CircleChain(Vec2<double>::Zero(), 30.0);
  e.bore_diameter_mm = 8.0;
  for (int j = 0; j < 6; ++j)
    e.holes.push_back({15.0 * Vec2<double>(std::cos(2 * kPi * j / 6 + 0.3), std::sin(2 * kPi * j / 6 + 0.3)), 6.0});
  e.thickness_mm = 5.0;
  e.mesh_deflection_mm = 0.002;
  e.name = "holed disc";
  return e;
}

TEST(PartSolids, HolesReadBackWithTheClosedFormsVolumeAndArea) {
  const cad::Extrusion e = HoledDisc();
  const double face = kPi * (30.0 * 30.0 - 4.0 * 4.0 - 6 * 3.0 * 3.0);
  const double volume = face * 5.0, area = 2 * face + 2 * kPi * (30.0 + 4.0 + 6 * 3.0) * 5.0;
  const cad::StepReadBack back = cad::ReadStep(cad::StepOfExtrusion(e));
  EXPECT_EQ(back.solids, 1);
  EXPECT_TRUE(back.valid);
  EXPECT_EQ(back.faces, 2 + 2 + 2 * 7);  // ends, two half walls of the profile, two per hole and bore
  EXPECT_NEAR(back.volume_mm3 / volume - 1, 0.0, 1e-8) << back.volume_mm3 << " vs " << volume;
  EXPECT_NEAR(back.area_mm2 / area - 1, 0.0, 1e-8) << back.area_mm2 << " vs " << area;
}

TEST(PartSolids, HolesOnACircleMeshWithoutTheKernelClosedAndWithinTheDeflection) {
  for (const bool bore : {true, false}) {
    cad::Extrusion e = HoledDisc();
    if (!bore) e.bore_diameter_mm = 0;
    const std::optional<cad::TriangleMesh> mesh = cad::MeshExtrusion(e, e.mesh_deflection_mm);
    ASSERT_TRUE(mesh.has_value()) << "bore " << bore;
    EXPECT_TRUE(ClosedAndOriented(*mesh)) << "bore " << bore;
    const double rb = bore ? 4.0 : 0.0;
    const double exact = kPi * (900.0 - rb * rb - 6 * 9.0) * 5.0;
    // Chords inscribed in every circle: the profile's area short by at most its perimeter times
    // the deflection, each hole's too (the part then larger).
    const double bound = 2 * kPi * (30.0 + rb + 6 * 3.0) * e.mesh_deflection_mm * 5.0;
    EXPECT_LE(std::abs(MeshVolume(*mesh) - exact), bound) << "bore " << bore;
    EXPECT_GT(std::abs(MeshVolume(*mesh) - exact), 0.0);  // the chords are not the arcs
    // Every vertex on a circle of the part (within rounding), none inside the material's faces' interior
    // except the cap's construction points, which lie strictly between the circles.
    int on_profile = 0;
    for (const Eigen::Vector3d& v : mesh->vertices)
      if (std::abs(Vec2<double>(v.x(), v.y()).norm() - 30.0) < 1e-9) ++on_profile;
    EXPECT_GT(on_profile, 2 * 8);
  }
}

TEST(PartSolids, HolesOffAPatternGoToTheKernelsMesherAndBadHolesAreRefused) {
  cad::Extrusion e = HoledDisc();
  e.holes[2].diameter_mm = 5.0;  // no longer one pattern
  EXPECT_FALSE(cad::MeshExtrusion(e, 0.002).has_value());
  const cad::SolidOutput solid = cad::ExtrudeCam(e);
  EXPECT_TRUE(ClosedAndOriented(solid.mesh));
  const double exact = kPi * (900.0 - 16.0 - 5 * 9.0 - 6.25) * 5.0;
  EXPECT_NEAR(MeshVolume(solid.mesh) / exact - 1, 0.0, 1e-3);
  cad::Extrusion overlap = HoledDisc();
  overlap.holes.push_back({overlap.holes[0].centre + Vec2<double>(2.0, 0.0), 3.0});
  EXPECT_THROW(cad::StepOfExtrusion(overlap), std::invalid_argument);
  cad::Extrusion outside = HoledDisc();
  outside.holes.push_back({Vec2<double>(29.0, 0.0), 4.0});
  EXPECT_THROW(cad::StepOfExtrusion(outside), std::invalid_argument);
}

// Two parts, three placements: OCCT's XDE reads an assembly whose components carry the names, the
// parts and the placements written, and a placed part's centroid is R(angle) c + origin.
TEST(PartAssembly, XdeReadsComponentsWithTheirPlacements) {
  cad::Extrusion ring;
  ring.profile = studies::CircleChain(Vec2<double>::Zero(), 10.0);
  ring.bore_diameter_mm = 12.0;
  ring.thickness_mm = 4.0;
  ring.name = "ring";
  cad::Extrusion cam;  // off-centre: its centroid moves with the turn
  cam.profile = studies::CircleChain(Vec2<double>(3.0, 0.0), 5.0);
  cam.thickness_mm = 6.0;
  cam.name = "eccentric";
  const std::vector<cad::Placement> placements = {
      {"ring A", 0, Eigen::Vector3d(0, 0, 0), 0.0},
      {"ring B", 0, Eigen::Vector3d(25.0, -4.0, 10.0), 1.1},
      {"eccentric 1", 1, Eigen::Vector3d(-7.0, 2.0, 3.0), 2.5}};
  const std::string step = cad::StepAssembly("two parts", {ring, cam}, placements);
  const cad::AssemblyReadBack back = cad::ReadStepAssembly(step);
  ASSERT_TRUE(back.read);
  EXPECT_TRUE(back.assembly);
  EXPECT_EQ(back.name, "two parts");
  ASSERT_EQ(back.components.size(), 3u);
  const double ring_volume = kPi * (100.0 - 36.0) * 4.0, cam_volume = kPi * 25.0 * 6.0;
  for (size_t k = 0; k < 3; ++k) {
    const cad::AssemblyComponent& c = back.components[k];
    const cad::Placement& p = placements[k];
    EXPECT_EQ(c.name, p.name);
    EXPECT_EQ(c.part, p.part == 0 ? "ring" : "eccentric");
    EXPECT_NEAR((c.origin - p.origin).norm(), 0.0, 1e-9) << p.name;
    EXPECT_NEAR(std::remainder(c.angle_rad - p.angle_rad, 2 * kPi), 0.0, 1e-12) << p.name;
    EXPECT_NEAR(c.axis_tilt, 0.0, 1e-12);
    EXPECT_NEAR(c.volume_mm3 / (p.part == 0 ? ring_volume : cam_volume) - 1, 0.0, 1e-8) << p.name;
    const Eigen::Vector3d local = p.part == 0 ? Eigen::Vector3d(0, 0, 2.0) : Eigen::Vector3d(3.0, 0, 3.0);
    const Eigen::Vector3d want = Eigen::AngleAxisd(p.angle_rad, Eigen::Vector3d::UnitZ()) * local + p.origin;
    EXPECT_NEAR((c.centroid - want).norm(), 0.0, 1e-7) << p.name;
  }
}

// ---- a three-disc cycloid drive ------------------------------------------------------------------

// The cycloid tooth from the paper's formulas (Appl. Sci. 2020, 10, 4859, eqs. 1–4), written here:
// X' = a' u(t) − e u(n1 t), the profile X' − ρ' N with N the right-hand normal of X'.
Vec2<double> PaperProfile(double a, double rho, double e, int n1, double t) {
  const Vec2<double> x(a * std::cos(t) - e * std::cos(n1 * t), a * std::sin(t) - e * std::sin(n1 * t));
  const Vec2<double> d(-a * std::sin(t) + e * n1 * std::sin(n1 * t), a * std::cos(t) - e * n1 * std::cos(n1 * t));
  const Vec2<double> normal = Vec2<double>(d.y(), -d.x()).normalized();
  return x - rho * normal;
}

nlohmann::json ThreeDiscStudy() {
  return nlohmann::json::parse(R"({
    "study": "cycloid_ltca", "name": "three discs",
    "drive": {"teeth": 11, "rollers": 12, "roller_position_radius_mm": 60, "roller_radius_mm": 5,
              "eccentricity_mm": 2.5, "face_width_mm": 10, "bore_diameter_mm": 24},
    "modification": {"delta_position_um": -10, "delta_radius_um": 5},
    "material": {"youngs_modulus_GPa": 206, "poisson_ratio": 0.3},
    "load": {"torque_Nm": 60},
    "discs": 3, "disc_spacing_mm": 11,
    "output_mechanism": {"pins": 6, "pin_circle_radius_mm": 32, "pin_radius_mm": 4, "hole_radius_mm": 6.52,
                         "pin_support": "both_ends", "pin_span_mm": 40},
    "geometry_files": {"assembly_crank_angle_deg": 37},
    "analysis": {"crank_angles_per_mesh_period": 3, "grid": [8, 8]}
  })");
}

TEST(CycloidParts, ThreeDiscsMeshThePinsAtTheAssemblysCrankAngleAndWeighWhatTheirVolumesSay) {
  const nlohmann::json study = ThreeDiscStudy();
  studies::RunContext ctx;
  ctx.quiet = true;
  const studies::Outputs out = studies::RunStudy(study, ctx);
  const auto& files = out.files();
  for (const char* f : {"disc_1.step", "disc_2.step", "disc_3.step", "ring_pins.step", "output_pins.step", "crank.step",
                        "housing.step", "assembly.step", "bom.csv", "disc_3.dxf", "disc_3.stl"})
    EXPECT_TRUE(files.count(f)) << f;
  const nlohmann::json result = nlohmann::json::parse(files.at("result.json"));
  ASSERT_TRUE(result.contains("parts")) << result.dump().substr(0, 300);

  const double a = 60.0 - 0.010, rho_mod = 5.0 + 0.005, e = 2.5, B = 10.0, s = 11.0;
  const int n1 = 12, n2 = 11, N = 3, Zw = 6;
  const double phi = 37.0 * kPi / 180.0;
  // The disc's face area from the formula, densely (a polygon of 240 000 points: its area is short
  // of the curve's by ~1e-12 of it), minus bore and holes.
  double area = 0, perimeter = 0;
  const int dense = 240000;
  Vec2<double> prev = PaperProfile(a, rho_mod, e, n1, 0.0);
  for (int k = 1; k <= dense; ++k) {
    const Vec2<double> p = PaperProfile(a, rho_mod, e, n1, 2 * kPi * k / dense);
    area += 0.5 * (prev.x() * p.y() - prev.y() * p.x());
    perimeter += (p - prev).norm();
    prev = p;
  }
  // The STEP solid is the arcs' (within geometry_files.dxf_tolerance_um, 1 µm by default, of the
  // exact profile): its face differs from the exact one by at most the perimeter times that.
  const double arcs_bound = perimeter * 1e-3 * B;
  const double disc_volume = (area - kPi * 12.0 * 12.0 - Zw * kPi * 6.52 * 6.52) * B;

  const cad::AssemblyReadBack back = cad::ReadStepAssembly(files.at("assembly.step"));
  ASSERT_TRUE(back.read);
  EXPECT_TRUE(back.assembly);
  std::map<std::string, int> per_part;
  for (const auto& c : back.components) ++per_part[c.part];
  EXPECT_EQ(per_part["disc_1"], 1);
  EXPECT_EQ(per_part["disc_2"], 1);
  EXPECT_EQ(per_part["disc_3"], 1);
  EXPECT_EQ(per_part["ring_pins"], n1);
  EXPECT_EQ(per_part["output_pins"], Zw);
  EXPECT_EQ(per_part["crank"], N);
  EXPECT_EQ(per_part["housing"], 1);
  std::vector<Vec2<double>> pins;
  for (const auto& c : back.components)
    if (c.part == "ring_pins") pins.push_back(Vec2<double>(c.origin.x(), c.origin.y()));
  ASSERT_EQ(pins.size(), size_t(n1));

  for (const auto& c : back.components) {
    if (c.part.rfind("disc_", 0) != 0) continue;
    const int k = std::stoi(c.part.substr(5));
    const double phi_k = phi + 2 * kPi * (k - 1) / N;
    // Placement: centre on the eccentric at its phase, stacked, turned with the output.
    EXPECT_NEAR(c.origin.x(), e * std::cos(phi_k), 1e-9) << c.part;
    EXPECT_NEAR(c.origin.y(), e * std::sin(phi_k), 1e-9) << c.part;
    EXPECT_NEAR(c.origin.z(), (k - 1) * s, 1e-9) << c.part;
    EXPECT_NEAR(std::remainder(c.angle_rad + phi / n2, 2 * kPi), 0.0, 1e-12) << c.part;
    EXPECT_NEAR(c.volume_mm3, disc_volume, arcs_bound) << c.part;
    EXPECT_NEAR(c.volume_mm3 / disc_volume - 1, 0.0, 1e-5) << c.part;
    // The disc as placed meshes every ring pin: each pin centre, taken into the disc's part frame
    // with the placement read back and then into the paper's frame by −γ_k = 2π(k − 1)/(N n2), is
    // at least ρ from the tooth (no overlap), and the closest is within the modification's
    // clearance (tens of µm) — with the phase wrong by a lobe's fraction the pins would cut
    // millimetres into the disc.
    const double gamma = -2 * kPi * (k - 1) / (N * n2);
    double least = INFINITY;
    for (const Vec2<double>& pin : pins) {
      const Vec2<double> rel = pin - Vec2<double>(c.origin.x(), c.origin.y());
      const double back_turn = -c.angle_rad - gamma;
      const Vec2<double> q(std::cos(back_turn) * rel.x() - std::sin(back_turn) * rel.y(),
                           std::sin(back_turn) * rel.x() + std::cos(back_turn) * rel.y());
      // Distance to the exact profile: dense samples, then golden-section refinement around the best.
      double best_t = 0, best = INFINITY;
      for (int m = 0; m < 20000; ++m) {
        const double t = 2 * kPi * m / 20000;
        const double d = (PaperProfile(a, rho_mod, e, n1, t) - q).norm();
        if (d < best) best = d, best_t = t;
      }
      double lo = best_t - 2 * kPi / 20000, hi = best_t + 2 * kPi / 20000;
      for (int it = 0; it < 80; ++it) {
        const double m1 = lo + (hi - lo) * 0.382, m2 = lo + (hi - lo) * 0.618;
        if ((PaperProfile(a, rho_mod, e, n1, m1) - q).norm() < (PaperProfile(a, rho_mod, e, n1, m2) - q).norm())
          hi = m2;
        else
          lo = m1;
      }
      least = std::min(least, (PaperProfile(a, rho_mod, e, n1, 0.5 * (lo + hi)) - q).norm() - 5.0);
    }
    EXPECT_GE(least, -1e-6) << c.part << ": a pin cuts into the disc by " << -least << " mm";
    EXPECT_LE(least, 0.05) << c.part << ": no pin within 50 um of the tooth";
  }
  // The BOM: mass = volume × density for every part (the independent disc volume for the discs).
  std::istringstream bom(files.at("bom.csv"));
  std::string line;
  std::getline(bom, line);
  EXPECT_EQ(line.rfind("part,count,description,material,thickness_mm,volume_mm3,mass_kg", 0), 0u);
  int rows = 0;
  const nlohmann::json& parts = result["parts"]["parts"];
  for (auto it = parts.begin(); it != parts.end(); ++it) {
    const double v = it.value()["volume_mm3"], m = it.value()["mass_kg"];
    EXPECT_NEAR(m, v * 7850.0 * 1e-9, 1e-12 * m) << it.key();
    if (it.key().rfind("disc_", 0) == 0) EXPECT_NEAR(v / disc_volume - 1, 0.0, 1e-6) << it.key();
    ++rows;
  }
  EXPECT_EQ(parts["ring_pins"]["count"], n1);
  EXPECT_EQ(parts["crank"]["count"], N);
  EXPECT_EQ(parts["output_pins"]["count"], Zw);
  while (std::getline(bom, line)) --rows;
  EXPECT_EQ(rows, -1);  // one row per part and the total
}

}  // namespace
}  // namespace camopt
