// Whole parts (studies/parts.h, studies/cycloid_parts.h, cad/extrusion.h): extrusions with holes
// read back by OpenCASCADE against closed forms, their meshes closed and within the deflection, the
// STEP assembly opened as an XDE document (components, part names, placements, volumes), and a
// three-disc cycloid drive's parts placed so that every disc meshes the ring pins at the assembly's
// crank angle — checked with the papers' profile formula and the placements read back from the file.
#include <algorithm>
#include <cmath>
#include <cstdio>
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
namespace parts_test {

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

// A keyed bore (DIN 6885-1 hub slot 6 × 2.8 in a 20 mm bore) with and without six bolt holes: OCCT
// reads the STEP solid with the closed form's volume — the circle minus the keyed bore
// π r² + w (r + t2 − x0) − r²(θ − sin θ)/2 (x0 = sqrt(r² − w²/4), θ = 2 asin(w/2r)) minus the holes —
// and the mesh (without the kernel) is closed and within the chords' bound of it.
TEST(PartSolids, KeyedBoreAndBoltCircleReadBackWithTheClosedFormsVolume) {
  for (const bool holes : {false, true}) {
    cad::Extrusion e;
    e.profile = studies::CircleChain(Vec2<double>::Zero(), 30.0);
    e.bore_diameter_mm = 20.0;
    e.keyway_width_mm = 6.0;
    e.keyway_depth_mm = 2.8;
    e.keyway_angle_rad = 0.4;
    e.thickness_mm = 5.0;
    if (holes)
      for (int j = 0; j < 6; ++j)
        e.holes.push_back({20.0 * Vec2<double>(std::cos(kPi / 6 + j * kPi / 3), std::sin(kPi / 6 + j * kPi / 3)), 5.5});
    const double r = 10.0, w = 6.0, x0 = std::sqrt(r * r - 9.0), theta = 2 * std::asin(0.3);
    const double keyed = kPi * r * r + w * (r + 2.8 - x0) - r * r * (theta - std::sin(theta)) / 2;
    const double face = kPi * 900.0 - keyed - (holes ? 6 * kPi * 2.75 * 2.75 : 0.0);
    const cad::StepReadBack back = cad::ReadStep(cad::StepOfExtrusion(e));
    EXPECT_EQ(back.solids, 1);
    EXPECT_TRUE(back.valid) << "holes " << holes;
    EXPECT_EQ(back.faces, 2 + 2 + 4 + (holes ? 12 : 0));
    EXPECT_NEAR(back.volume_mm3 / (face * 5.0) - 1, 0.0, 1e-8) << "holes " << holes;
    const std::optional<cad::TriangleMesh> mesh = cad::MeshExtrusion(e, 0.002);
    ASSERT_TRUE(mesh.has_value()) << "holes " << holes;
    EXPECT_TRUE(ClosedAndOriented(*mesh));
    const double perimeter = 2 * kPi * 30.0 + 2 * kPi * r + 2 * 2.8 + w + (holes ? 6 * 2 * kPi * 2.75 : 0.0);
    EXPECT_LE(std::abs(MeshVolume(*mesh) - face * 5.0), perimeter * 0.002 * 5.0) << "holes " << holes;
  }
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
    "crank_bearing": {"kind": "roller", "dynamic_rating_N": 30000, "designation": "crank bearing X-24"},
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
    std::printf("%s placed as read back: least pin clearance %.6f mm, volume %.6f mm3 (formula %.6f)\n",
                c.part.c_str(), least, c.volume_mm3, disc_volume);
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
    if (it.key().rfind("disc_", 0) == 0) { EXPECT_NEAR(v / disc_volume - 1, 0.0, 1e-6) << it.key(); }
    ++rows;
  }
  EXPECT_EQ(parts["ring_pins"]["count"], n1);
  EXPECT_EQ(parts["crank"]["count"], N);
  EXPECT_EQ(parts["crank"]["designation"], "crank bearing X-24");
  EXPECT_NE(files.at("bom.csv").find(",crank bearing X-24,"), std::string::npos);
  EXPECT_EQ(parts["output_pins"]["count"], Zw);
  while (std::getline(bom, line)) --rows;
  EXPECT_EQ(rows, -1);  // one row per part and the total
}

// Form grinding: the wheel of grinding_wheel.csv, placed at the written centre distance and indexed
// by the written angles, generates in every transverse section the lower envelope of its surface of
// revolution. That envelope is computed here from the file alone — the wheel's surface sampled in
// 3D (axial polygon × turns about its axis), each sample's x kept per y bin — and compared with the
// paper's tooth (Δa, Δρ) over the whole disc: within the stated residual plus the sampling's bound.
TEST(CycloidGrinding, TheWheelsEnvelopeRegeneratesTheModifiedToothWithinTheStatedFormError) {
  nlohmann::json study = ThreeDiscStudy();
  study["discs"] = 1;
  study.erase("disc_spacing_mm");
  study["grinding"] = {{"wheel_radius_mm", 120}, {"tolerance_um", 0.2}};
  studies::RunContext ctx;
  ctx.quiet = true;
  const studies::Outputs out = studies::RunStudy(study, ctx);
  const nlohmann::json g = nlohmann::json::parse(out.files().at("result.json"))["grinding"];
  const double A = g["centre_distance_mm"], residual_mm = double(g["residual_form_error_um"]) * 1e-3;
  EXPECT_LE(residual_mm, 0.2e-3);
  EXPECT_GT(residual_mm, 0.0);
  std::istringstream csv(out.files().at("grinding_wheel.csv"));
  std::string line;
  std::vector<double> ys, rs;
  while (std::getline(csv, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'y') continue;
    double y, r;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf", &y, &r), 2) << line;
    ys.push_back(y);
    rs.push_back(r);
  }
  ASSERT_GT(ys.size(), 50u);
  for (size_t i = 1; i < ys.size(); ++i) ASSERT_GT(ys[i], ys[i - 1]);  // a wheel's axial profile: y increasing
  // The envelope: per y, the least x over the wheel's surface x = A − r(y) cos(θ), z = r(y) sin(θ),
  // θ sampled over ±0.2 rad (the rest of the wheel lies farther out).
  auto wheel_r = [&](double y) {
    const size_t i = std::upper_bound(ys.begin(), ys.end(), y) - ys.begin();
    if (i == 0 || i == ys.size()) return -1.0;
    const double f = (y - ys[i - 1]) / (ys[i] - ys[i - 1]);
    return rs[i - 1] + f * (rs[i] - rs[i - 1]);
  };
  auto envelope_x = [&](double y) {
    double x = INFINITY;
    for (int k = -20; k <= 20; ++k) x = std::min(x, A - wheel_r(y) * std::cos(0.01 * k));
    return x;
  };
  const double a = 60.0 - 0.010, rho_mod = 5.0 + 0.005, e = 2.5;
  const int n1 = 12, n2 = 11;
  const double index = double(g["index_deg"]) * kPi / 180.0;
  EXPECT_NEAR(index, 2 * kPi / n2, 1e-12);
  // Every point of the paper's tooth, taken into its space's frame, against the envelope: the
  // distance along x, times the profile's slope factor, bounds the normal distance from above.
  double worst = 0;
  int checked = 0;
  for (int m = 0; m < 44000; ++m) {
    const Vec2<double> p = PaperProfile(a, rho_mod, e, n1, 2 * kPi * m / 44000);
    const double polar = std::atan2(p.y(), p.x());
    const int k = static_cast<int>(std::lround(polar / index));
    const double back = -k * index;
    const Vec2<double> q(std::cos(back) * p.x() - std::sin(back) * p.y(), std::sin(back) * p.x() + std::cos(back) * p.y());
    if (wheel_r(q.y()) < 0) continue;  // at a lobe's very tip, beyond the wheel's edge sample
    // Normal distance: the envelope near q as a line through two close envelope points.
    const double h = 1e-4;
    const Vec2<double> e0(envelope_x(q.y() - h), q.y() - h), e1(envelope_x(q.y() + h), q.y() + h);
    const Vec2<double> t = (e1 - e0).normalized();
    const Vec2<double> d = q - e0;
    worst = std::max(worst, std::abs(t.x() * d.y() - t.y() * d.x()));
    ++checked;
  }
  EXPECT_GT(checked, 40000);
  std::printf("form error of the wheel's envelope %.4g um (stated %.4g um) over %d points, %zu wheel points\n",
              worst * 1e3, residual_mm * 1e3, checked, ys.size());
  // The envelope's own sampling (θ steps of 0.01 rad at the wheel's ~120 mm: r(1 − cos 0.005) ≈ 1.5 µm at
  // worst between samples, but θ = 0 is sampled, so none) and the tangent line over 2h (< 1e-9 mm).
  EXPECT_LE(worst, residual_mm + 1e-8) << "form error " << worst * 1e3 << " um";
  // A wheel smaller than the space's depth is refused with exit 2 at its field.
  const auto dir = camopt::testing::TempDir("grinding-bad");
  study["grinding"]["wheel_radius_mm"] = 1.0;
  camopt::testing::WriteFile(dir / "g.json", study.dump());
  const auto r = camopt::testing::RunCamopt("run " + (dir / "g.json").string() + " --out " + (dir / "o").string() + " --quiet");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("/grinding/wheel_radius_mm"), std::string::npos) << r.stderr_text;
}

}  // namespace parts_test
}  // namespace camopt
