// The disc_cam study with a flat-faced and a knife-edge follower (docs/disc_cam.md): expected values
// written out here from the cycloidal law S = h (u − sin(2πu)/(2π)), S' = (h/β)(1 − cos 2πu),
// S'' = (2πh/β²) sin 2πu (Norton, Design of Machinery §8.5), never taken from the code under test;
// the knife edge against the roller's pitch curve of the same cam; bad combinations refused with
// exit 2 and the JSON path.
#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/disc_cam_study.h"
#include "studies/report.h"
#include "studies/study.h"
#include "tests/test_util.h"

namespace camopt {
namespace disc_cam_follower_types_test {

using camopt::testing::Example;
using nlohmann::json;
using studies::Node;
namespace disc_study = studies::disc_cam;

constexpr double kPiHere = 3.14159265358979323846;
constexpr double kH = 24.0, kBeta = 120 * kPiHere / 180;  // the examples' rise and its cam angle

struct Ran {
  disc_study::Study study;
  disc_study::Result result;
  json out;
};
Ran ParseAndRun(const json& file) {
  const Node root(&file, "study.json", "");
  Ran r{disc_study::Parse(root), {}, {}};
  studies::RunContext ctx;
  ctx.quiet = true;
  r.result = disc_study::Run(r.study, ctx);
  r.out = studies::WriteResult(r.result);
  return r;
}

// S, S', S'' of the examples' program (cycloidal rise over 120°, dwell to 170°, cycloidal return
// to 290°, dwell), written out from the law.
struct Svaj3 {
  double s, v, a;
};
Svaj3 Program(double th) {
  const double k = 2 * kPiHere;
  auto rise = [&](double u) {
    return Svaj3{kH * (u - std::sin(k * u) / k), kH / kBeta * (1 - std::cos(k * u)), k * kH / (kBeta * kBeta) * std::sin(k * u)};
  };
  if (th < kBeta) return rise(th / kBeta);
  if (th < 170 * kPiHere / 180) return {kH, 0, 0};
  if (th < 290 * kPiHere / 180) {
    const Svaj3 r = rise((th - 170 * kPiHere / 180) / kBeta);
    return {kH - r.s, -r.v, -r.a};
  }
  return {0, 0, 0};
}

// ρ_min = min (r_b + S + S'') by a dense scan of the closed form (10× the study's grid).
double HandMinRho(double rb) {
  double best = 1e300;
  for (int i = 0; i < 36000; ++i) {
    const Svaj3 p = Program(2 * kPiHere * i / 36000);
    best = std::min(best, rb + p.s + p.a);
  }
  return best;
}

TEST(DiscCamFlatFacedStudy, FaceWidthRadiusLoadsAndStressByHand) {
  const Ran ran = ParseAndRun(Example("disc_cam_flat_faced.json"));
  const json& j = ran.out;
  EXPECT_EQ(j["follower"], "translating_flat_faced");
  // The contact runs S' off the axis: the cycloid's peak velocity 2h/β on each side.
  const double vmax = 2 * kH / kBeta;  // 22.918 mm
  EXPECT_NEAR(j["flat_face"]["contact_offset_mm"]["max"].get<double>(), vmax, 1e-9);
  EXPECT_NEAR(j["flat_face"]["contact_offset_mm"]["min"].get<double>(), -vmax, 1e-9);
  EXPECT_NEAR(j["flat_face"]["face_width_needed_mm"].get<double>(), 2 * vmax, 1e-9);  // max S' − min S'
  EXPECT_NEAR(j["flat_face"]["face_width_needed_centred_mm"].get<double>(), 2 * vmax, 1e-9);
  EXPECT_TRUE(j["flat_face"]["face_width_ok"].get<bool>());  // 50 mm ≥ 45.84 mm
  // ρ_min = 27.2032 mm (on the grid within the scan's resolution: ρ is flat at its minimum).
  const double rho = HandMinRho(40.0);
  EXPECT_NEAR(rho, 27.2032, 1e-4);
  EXPECT_NEAR(j["flat_face"]["min_radius_of_curvature_mm"].get<double>(), rho, 1e-5);
  EXPECT_TRUE(j["flat_face"]["radius_margin_ok"].get<bool>());
  EXPECT_FALSE(j["flat_face"]["cusp"].get<bool>());
  EXPECT_EQ(j["pressure_angle_deg"]["max"].get<double>(), 0.0);
  EXPECT_TRUE(j["limits_ok"].get<bool>());
  // At 60° (mid-rise, S'' = 0): F_y = k S + F₀ + m g = 2·12 + 60 + 0.8·9.80665 N, the camshaft
  // torque F_y S' = F_y · 2h/β (the moment of −F_y u at A about the cam axis).
  const auto& L = *ran.result.loads;
  const int i60 = 600;
  const double fy = 2.0 * 12.0 + 60.0 + 0.8 * 9.80665;
  EXPECT_NEAR(L.contact_force_N[i60], fy, 1e-9);
  EXPECT_NEAR(L.camshaft_torque_Nm[i60], fy * vmax * 1e-3, 1e-9);
  // Hertz at 60°: a plane on a cylinder of radius ρ = r_b + h/2 (S'' = 0), p₀ = sqrt(F E*/(π w ρ)),
  // E* = E/(2(1 − ν²)), w = 12 mm.
  const double e_star = 206000.0 / (2 * (1 - 0.09));
  EXPECT_NEAR(L.contact_stress_MPa[i60], std::sqrt(fy * e_star / (kPiHere * 12.0 * (40.0 + 12.0))), 1e-9);
  // Kinetostatic jump speed: the follower leaves where m S'' ω² + k S + F₀ + m g = 0, S'' < 0, i.e.
  // ω² = min (k S + F₀ + m g)/(−m S''·1e-3); by the same dense scan.
  double w2 = 1e300;
  for (int i = 0; i < 36000; ++i) {
    const Svaj3 p = Program(2 * kPiHere * i / 36000);
    if (p.a < 0) w2 = std::min(w2, (2.0 * p.s + 60.0 + 0.8 * 9.80665) / (-0.8 * p.a * 1e-3));
  }
  EXPECT_NEAR(j["dynamics"]["jump_speed_rpm"].get<double>(), std::sqrt(w2) * 60 / (2 * kPiHere), 0.05);
}

TEST(DiscCamFlatFacedStudy, TooSmallABaseCircleFailsTheVerdictWithTheNumbers) {
  // r_b = 5 mm: ρ = 5 + S + S'' < 0 on the rise (at 90°: 5 + h (3/4 + 1/(2π)) − 2πh/β² = −7.56 mm).
  json study = Example("disc_cam_flat_faced.json");
  study["base_circle_radius_mm"] = 5;
  study.erase("dynamics");
  study.erase("material");
  study["limits"].erase("contact_stress_MPa");
  study.erase("limits");
  const Ran ran = ParseAndRun(study);
  const json& ff = ran.out["flat_face"];
  const double rho90 = 5.0 + kH * (0.75 + 1 / (2 * kPiHere)) - 2 * kPiHere * kH / (kBeta * kBeta);
  EXPECT_LT(rho90, 0.0);
  EXPECT_NEAR(ff["min_radius_of_curvature_mm"].get<double>(), HandMinRho(5.0), 1e-5);
  EXPECT_LE(ff["min_radius_of_curvature_mm"].get<double>(), rho90);
  EXPECT_EQ(ff["radius_margin_limit_mm"].get<double>(), 0.0);  // the default: a convex cam
  EXPECT_FALSE(ff["radius_margin_ok"].get<bool>());
  EXPECT_TRUE(ff["cusp"].get<bool>());
  EXPECT_FALSE(ff["cusp_cam_angle_deg"].empty());
  EXPECT_FALSE(ran.out["limits_ok"].get<bool>());
  // Tolerances without a roller are refused at the file's field (the mechanical error rolls a
  // roller on the profile), not run to an answer without its asked-for tolerance analysis.
  json tol = Example("disc_cam_flat_faced.json");
  tol["tolerances"] = {{"profile_radial_um", 19}};
  try {
    (void)ParseAndRun(tol);
    ADD_FAILURE() << "tolerances on a flat-faced follower were accepted";
  } catch (const camopt::studies::StudyError& e) {
    EXPECT_NE(std::string(e.what()).find("/tolerances"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("roller followers only"), std::string::npos) << e.what();
  }
  // A face narrower than the contact's travel (40 < 2·2h/β = 45.84 mm) fails too.
  json narrow = Example("disc_cam_flat_faced.json");
  narrow["follower"]["face_width_mm"] = 40;
  const Ran n = ParseAndRun(narrow);
  EXPECT_FALSE(n.out["flat_face"]["face_width_ok"].get<bool>());
  EXPECT_FALSE(n.out["limits_ok"].get<bool>());
}

TEST(DiscCamKnifeEdgeStudy, ProfileIsTheRollerPitchCurve) {
  // The roller example (r_b 40, r_f 10, e 12) and a knife edge on a 50 mm base circle: the knife's
  // profile is the roller's pitch curve, point by point; its smallest radius the pitch curve's.
  json roller = Example("disc_cam_translating.json");
  roller["analysis"] = {{"angle_steps", 3600}, {"evaluate", {"profile"}}};
  json knife = Example("disc_cam_knife_edge.json");
  knife["base_circle_radius_mm"] = 50;
  const Ran r = ParseAndRun(roller), k = ParseAndRun(knife);
  const auto &rs = r.result.series, &ks = k.result.series;
  ASSERT_EQ(rs.pitch_x_mm.size(), ks.contact_x_mm.size());
  for (size_t i = 0; i < rs.pitch_x_mm.size(); ++i) {
    EXPECT_NEAR(ks.contact_x_mm[i], rs.pitch_x_mm[i], 1e-9) << i;
    EXPECT_NEAR(ks.contact_y_mm[i], rs.pitch_y_mm[i], 1e-9) << i;
    EXPECT_NEAR(ks.pressure_angle_deg[i], rs.pressure_angle_deg[i], 1e-9) << i;
  }
  // The roller's profile radius is ρ_pitch − r_f: the knife's is ρ_pitch.
  EXPECT_NEAR(k.result.min_radius_of_curvature_mm->value, r.result.min_radius_of_curvature_mm->value + 10.0, 1e-9);
  EXPECT_FALSE(k.result.undercut);
  EXPECT_EQ(k.out["limits"]["radius_margin_mm"].get<double>(), 0.0);  // default: no roller
  // On the base circle the knife sits at sqrt(r_b² − e²) on its axis (eq. 5 with r_f = 0), so
  // φ = −atan(e/L₀) there.
  EXPECT_NEAR(ks.pressure_angle_deg[3000], -std::atan(12.0 / std::sqrt(2500.0 - 144.0)) * 180 / kPiHere, 1e-9);
  EXPECT_FALSE(k.out.contains("dynamics"));
  EXPECT_FALSE(k.out.contains("worst_case_error_um"));
}

// The oscillating flat-faced example (f = 100, d = 10, r_b = 40 mm; a cycloidal 10° swing over 120°,
// dwell 50°, return 120°, dwell 70°) against an envelope built here from the arm alone: at cam angle θ
// (coordinates fixed on the cam, the pivot at f u(θ)) the arm leaves the pivot at angle ξ = ξ₀ + S
// from the line to the cam centre, sin ξ₀ = (r_b + d)/f, and the face is the line parallel to the arm
// d from the pivot on the cam's side. The contact is the intersection of the face lines at θ ± δ; the
// radius of curvature the circumradius of three neighbouring contacts; the pressure angle the angle
// between the face's normal and the velocity of the arm's point at the contact.
struct Line {
  double px, py, dx, dy;  // a point and a unit direction
};
std::pair<double, double> Intersect(const Line& a, const Line& b) {
  const double den = a.dx * b.dy - a.dy * b.dx;
  const double t = ((b.px - a.px) * b.dy - (b.py - a.py) * b.dx) / den;
  return {a.px + t * a.dx, a.py + t * a.dy};
}

TEST(DiscCamOscillatingFlatFacedStudy, ProfileFaceLengthPressureAngleAndRadiusAgainstTheEnvelope) {
  json study = Example("disc_cam_oscillating_flat_faced.json");
  const Ran ran = ParseAndRun(study);
  const auto& t = ran.result.series;
  ASSERT_TRUE(ran.result.flat_face.has_value());
  const auto& F = *ran.result.flat_face;
  const double f = 100, d = 10, rb = 40, deg = kPiHere / 180;
  // Program() is written for the 24 mm examples; the swing here is 10°: scale its S by (10° in rad)/24.
  const double scale = 10 * deg / kH;
  auto face = [&](double th) {
    const double xi = std::asin((rb + d) / f) + scale * Program(th).s;
    const double ox = f * std::cos(th), oy = f * std::sin(th);
    const double ax = std::cos(th + kPiHere - xi), ay = std::sin(th + kPiHere - xi);
    double mx = -ay, my = ax;
    if (mx * -ox + my * -oy < 0) mx = -mx, my = -my;
    return std::pair<Line, std::pair<double, double>>{Line{ox + d * mx, oy + d * my, ax, ay}, {mx, my}};
  };
  const int n = int(t.cam_angle_deg.size());
  ASSERT_EQ(n, 3600);
  double worst_point = 0, worst_rho = 0, worst_phi = 0, worst_ell = 0, ell_max = -1e300, ell_min = 1e300;
  for (int i = 0; i < n; i += 7) {
    const double th = 2 * kPiHere * i / n, delta = 1e-5;
    const auto [x, y] = Intersect(face(th - delta).first, face(th + delta).first);
    worst_point = std::max(worst_point, std::hypot(x - t.contact_x_mm[i], y - t.contact_y_mm[i]));
    const auto [line, m] = face(th);
    // ℓ: from the foot of the pivot's perpendicular along the arm.
    const double ell = (x - line.px) * line.dx + (y - line.py) * line.dy;
    worst_ell = std::max(worst_ell, std::abs(ell - F.contact_offset_mm[i]));
    // The pressure angle: the arm's point at the contact moves perpendicular to O₃A.
    const double ox = f * std::cos(th), oy = f * std::sin(th);
    const double rx = x - ox, ry = y - oy, rn = std::hypot(rx, ry);
    const double phi = std::acos(std::abs(m.first * -ry / rn + m.second * rx / rn)) / deg;
    worst_phi = std::max(worst_phi, std::abs(phi - t.pressure_angle_deg[i]));
    // ρ: the circumradius of the contacts at θ − ε, θ, θ + ε (ε = 0.2°), on the convex profile.
    const double eps = 0.2 * deg;
    const auto p0 = Intersect(face(th - eps - delta).first, face(th - eps + delta).first);
    const auto p2 = Intersect(face(th + eps - delta).first, face(th + eps + delta).first);
    const double a = std::hypot(p0.first - x, p0.second - y), b = std::hypot(p2.first - x, p2.second - y),
                 c = std::hypot(p2.first - p0.first, p2.second - p0.second);
    const double area2 = std::abs((x - p0.first) * (p2.second - p0.second) - (y - p0.second) * (p2.first - p0.first));
    worst_rho = std::max(worst_rho, std::abs(a * b * c / (2 * area2) - F.radius_of_curvature_mm[i]) /
                                        F.radius_of_curvature_mm[i]);
  }
  for (int i = 0; i < 36000; ++i) {  // the face's travel on a grid 10× the study's
    const double th = 2 * kPiHere * i / 36000;
    const auto [x, y] = Intersect(face(th - 1e-5).first, face(th + 1e-5).first);
    const Line line = face(th).first;
    const double ell = (x - line.px) * line.dx + (y - line.py) * line.dy;
    ell_max = std::max(ell_max, ell), ell_min = std::min(ell_min, ell);
  }
  EXPECT_LT(worst_point, 1e-5);  // mm
  EXPECT_LT(worst_ell, 1e-5);
  EXPECT_LT(worst_phi, 1e-6);    // deg
  EXPECT_LT(worst_rho, 1e-4);    // relative
  const json& ff = ran.out["flat_face"];
  EXPECT_NEAR(ff["arm_angle_on_base_circle_deg"].get<double>(), 30.0, 1e-12);  // asin(50/100)
  // The study's grid (3600) finds the travel to the scan's resolution (ℓ is flat at its extremes).
  EXPECT_NEAR(ff["contact_on_face_mm"]["max"].get<double>(), ell_max, 1e-4);
  EXPECT_NEAR(ff["contact_on_face_mm"]["min"].get<double>(), ell_min, 1e-4);
  EXPECT_NEAR(ff["face_length_needed_mm"].get<double>(), ell_max - ell_min, 2e-4);
  EXPECT_TRUE(ff["face_width_ok"].get<bool>());  // 60 mm ≥ 29.56 mm
  // On the base circle (θ in the last dwell) ℓ = f cos ξ₀ and φ = atan(d/ℓ).
  EXPECT_NEAR(F.contact_offset_mm[3500], f * std::cos(30 * deg), 1e-9);
  EXPECT_NEAR(t.pressure_angle_deg[3500], std::atan(d / (f * std::cos(30 * deg))) / deg, 1e-9);
  EXPECT_NEAR(t.radial_dimension_mm[3500], rb, 1e-9);
  EXPECT_FALSE(ff["cusp"].get<bool>());
  EXPECT_TRUE(ran.out["limits_ok"].get<bool>());
  // A 25 mm face is shorter than the 29.56 mm the contact runs over.
  study["follower"]["face_width_mm"] = 25;
  const Ran short_face = ParseAndRun(study);
  EXPECT_FALSE(short_face.out["flat_face"]["face_width_ok"].get<bool>());
  EXPECT_FALSE(short_face.out["limits_ok"].get<bool>());
}

// The report's headline of the smallest radius of curvature names the face's own formula: ρ = h + h_φφ
// for the face on an arm, r_b + S + S'' for the translating face (each row only for its follower).
TEST(DiscCamOscillatingFlatFacedStudy, ReportNamesTheRadiusFormulaOfTheFollower) {
  auto labels = [](const std::string& example) {
    const json file = Example(example);
    const Ran ran = ParseAndRun(file);
    std::string all;
    for (const auto& row : studies::EvaluateHeadlines("disc_cam", file, ran.out).rows) all += row.label + "\n";
    return all;
  };
  const std::string arm = labels("disc_cam_oscillating_flat_faced.json");
  EXPECT_NE(arm.find("h + h_φφ (flat face on an arm)"), std::string::npos) << arm;
  EXPECT_EQ(arm.find("r_b + S + S''"), std::string::npos) << arm;
  const std::string translating = labels("disc_cam_flat_faced.json");
  EXPECT_NE(translating.find("r_b + S + S'' (flat face)"), std::string::npos) << translating;
  EXPECT_EQ(translating.find("h + h_φφ"), std::string::npos) << translating;
}

// The arm's loads at 300 rpm (J = 0.002 kg·m², k = 20 N·m/rad, M₀ = 3 N·m): the contact force from the
// moment about the pivot written out here, M = J S'' ω² + k S + M₀ over the arm ℓ of the envelope built
// above; the camshaft torque as the moment of that force about the cam centre, A × (F m) (not the power
// balance the code uses); the jump speed by bisection on min F; the Hertz stress of a plane on ρ.
TEST(DiscCamOscillatingFlatFacedStudy, ArmLoadsAgainstTheMomentAboutThePivot) {
  const Ran ran = ParseAndRun(Example("disc_cam_oscillating_flat_faced.json"));
  ASSERT_TRUE(ran.result.loads.has_value());
  const auto& L = *ran.result.loads;
  const auto& F = *ran.result.flat_face;
  const double f = 100, d = 10, rb = 40, deg = kPiHere / 180, scale = 10 * deg / kH;
  const double J = 0.002, k = 20, m0 = 3, omega = 300 * 2 * kPiHere / 60;
  auto face = [&](double th) {
    const double xi = std::asin((rb + d) / f) + scale * Program(th).s;
    const double ox = f * std::cos(th), oy = f * std::sin(th);
    const double ax = std::cos(th + kPiHere - xi), ay = std::sin(th + kPiHere - xi);
    double mx = -ay, my = ax;
    if (mx * -ox + my * -oy < 0) mx = -mx, my = -my;
    return std::pair<Line, std::pair<double, double>>{Line{ox + d * mx, oy + d * my, ax, ay}, {mx, my}};
  };
  auto force = [&](double th, double w) {  // [N], and the contact point
    const auto [x, y] = Intersect(face(th - 1e-5).first, face(th + 1e-5).first);
    const Line line = face(th).first;
    const double ell = (x - line.px) * line.dx + (y - line.py) * line.dy;
    const Svaj3 p = Program(th);
    const double moment = J * scale * p.a * w * w + k * scale * p.s + m0;
    return std::tuple<double, double, double>{moment / (ell * 1e-3), x, y};
  };
  double worst_f = 0, worst_t = 0;
  for (int i = 0; i < 3600; i += 9) {
    const double th = 2 * kPiHere * i / 3600;
    const auto [fc, x, y] = force(th, omega);
    worst_f = std::max(worst_f, std::abs(fc - L.contact_force_N[i]) / std::abs(fc));
    const auto m = face(th).second;
    const double torque = (x * fc * m.second - y * fc * m.first) * 1e-3;  // A × (F m) [N·m]
    worst_t = std::max(worst_t, std::abs(torque - L.camshaft_torque_Nm[i]));
  }
  EXPECT_LT(worst_f, 1e-6);
  EXPECT_LT(worst_t, 1e-6);  // N·m (the torque reaches 0.80 N·m)
  // On the base circle: F = M₀/(f cos ξ₀) = 3/(0.1 cos 30°) = 34.641 N.
  EXPECT_NEAR(L.contact_force_N[3500], m0 / (0.1 * std::cos(30 * deg)), 1e-9);
  // The jump speed: bisection on the speed where min F over 36 000 angles reaches 0.
  auto min_force = [&](double w) {
    double lo = 1e300;
    for (int i = 0; i < 36000; ++i) lo = std::min(lo, std::get<0>(force(2 * kPiHere * i / 36000, w)));
    return lo;
  };
  double a = omega, b = 10 * omega;
  ASSERT_GT(min_force(a), 0.0);
  ASSERT_LT(min_force(b), 0.0);
  for (int it = 0; it < 40; ++it) (min_force(0.5 * (a + b)) > 0 ? a : b) = 0.5 * (a + b);
  const json& aj = ran.out["arm_dynamics"];
  EXPECT_NEAR(aj["jump_speed_rpm"].get<double>(), 0.5 * (a + b) * 60 / (2 * kPiHere), 1e-3 * aj["jump_speed_rpm"].get<double>());
  // Hertz, plane on ρ: p₀ = sqrt(F E*/(π w ρ)) at the reported peak, E* = E/(2(1 − ν²)).
  const int ip = int(std::lround(aj["at_max_contact_stress_cam_angle_deg"].get<double>() * 10));
  const double e_star = 206000 / (2 * (1 - 0.09));
  EXPECT_NEAR(aj["max_contact_stress_MPa"].get<double>(),
              std::sqrt(L.contact_force_N[ip] * e_star / (kPiHere * 12 * F.radius_of_curvature_mm[ip])), 1e-9);
  EXPECT_TRUE(aj["separation_ok"].get<bool>());
  EXPECT_TRUE(aj["contact_stress_ok"].get<bool>());
  EXPECT_TRUE(ran.out["limits_ok"].get<bool>());
}

// A 20° swing over 120° makes the profile concave on the rise: ρ_min < 0, a cusp, the verdict fails.
TEST(DiscCamOscillatingFlatFacedStudy, AConcaveProfileIsACuspAndFailsTheVerdict) {
  json study = Example("disc_cam_oscillating_flat_faced.json");
  study["motion"][0]["rise_deg"] = 20;
  study["motion"][2]["rise_deg"] = -20;
  const Ran ran = ParseAndRun(study);
  const json& ff = ran.out["flat_face"];
  EXPECT_LT(ff["min_radius_of_curvature_mm"].get<double>(), 0.0);
  EXPECT_TRUE(ff["cusp"].get<bool>());
  EXPECT_FALSE(ff["radius_margin_ok"].get<bool>());
  EXPECT_FALSE(ran.out["limits_ok"].get<bool>());
}

struct BadCase {
  const char* name;
  const char* example;
  const char* patch;  // a JSON merge patch applied to the example
  const char* path;   // the JSON path the message must name
  const char* words;  // and a phrase it must contain
};
void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }
class DiscCamFollowerTypesBadInput : public ::testing::TestWithParam<BadCase> {};
TEST_P(DiscCamFollowerTypesBadInput, ExitCode2AndTheJsonPath) {
  const BadCase& c = GetParam();
  json study = Example(c.example);
  study.merge_patch(json::parse(c.patch));
  camopt::testing::ExpectStudyRejected(study, std::string("disc-cam-types-") + c.name, c.path, c.words);
}
const char* kF = "disc_cam_flat_faced.json";
const char* kK = "disc_cam_knife_edge.json";
const char* kO = "disc_cam_oscillating_flat_faced.json";
INSTANTIATE_TEST_SUITE_P(
    Cases, DiscCamFollowerTypesBadInput,
    ::testing::Values(
        BadCase{"flat_roller", kF, R"({"follower": {"roller_radius_mm": 10}})", "/follower/roller_radius_mm",
                "unknown field"},
        BadCase{"flat_offset", kF, R"({"follower": {"offset_mm": 5}})", "/follower/offset_mm", "unknown field"},
        BadCase{"flat_error_stage", kF, R"({"analysis": {"evaluate": ["profile", "error"]}})", "/analysis/evaluate/1",
                "roller followers only"},
        BadCase{"flat_cutter", kF, R"({"cutter_radius_mm": 5})", "/cutter_radius_mm", "roller follower only"},
        BadCase{"flat_inside", kF, R"({"motion": [{"law": "cycloidal", "rise_mm": -10, "cam_angle_deg": 180},
            {"law": "cycloidal", "rise_mm": 10, "cam_angle_deg": 180}]})", "/motion", "inside the base circle"},
        BadCase{"knife_roller", kK, R"({"follower": {"roller_radius_mm": 10}})", "/follower/roller_radius_mm",
                "unknown field"},
        BadCase{"knife_face", kK, R"({"follower": {"face_width_mm": 10}})", "/follower/face_width_mm",
                "unknown field"},
        BadCase{"knife_stress", kK,
                R"({"limits": {"contact_stress_MPa": 1000}, "face_width_mm": 10,
                    "material": {"youngs_modulus_GPa": 206, "poisson_ratio": 0.3},
                    "dynamics": {"speed_rpm": 100, "follower_mass_kg": 1}})",
                "/limits/contact_stress_MPa", "at a point"},
        BadCase{"knife_cutter", kK, R"({"cutter_radius_mm": 5})", "/cutter_radius_mm", "roller follower only"},
        BadCase{"knife_oscillating_dynamics", kK,
                R"({"follower": {"type": "oscillating_knife_edge", "offset_mm": null, "pivot_distance_mm": 100,
                    "arm_length_mm": 80}, "motion": [{"law": "cycloidal", "rise_deg": 20, "cam_angle_deg": 120},
                    {"law": "dwell", "cam_angle_deg": 50}, {"law": "cycloidal", "rise_deg": -20, "cam_angle_deg": 120},
                    {"law": "dwell", "cam_angle_deg": 70}], "dynamics": {"speed_rpm": 100, "follower_mass_kg": 1}})",
                "/dynamics", "translating followers only"},
        BadCase{"min_size_knife", "disc_cam_min_size.json",
                R"({"follower": {"type": "translating_knife_edge", "roller_radius_mm": null},
                    "variables": {"roller_radius_mm": [4, 16]}})", "/variables/roller_radius_mm",
                "not a variable of a knife-edge"},
        BadCase{"min_size_flat", "disc_cam_min_size.json",
                R"({"follower": {"type": "translating_flat_faced", "roller_radius_mm": null, "offset_mm": null}})",
                "/variables/offset_mm", "base circle alone"},
        BadCase{"arm_face_arm_length", kO, R"({"follower": {"arm_length_mm": 80}})", "/follower/arm_length_mm",
                "unknown field"},
        BadCase{"arm_face_without_pivot", kO, R"({"follower": {"pivot_distance_mm": null}})",
                "/follower/pivot_distance_mm", "missing required field"},
        BadCase{"arm_face_short_pivot", kO, R"({"follower": {"pivot_distance_mm": 45}})",
                "/follower/pivot_distance_mm", "cannot touch the base circle"},
        BadCase{"arm_face_fast_arm", kO, R"({"motion": [{"law": "cycloidal", "rise_deg": 60, "cam_angle_deg": 30},
            {"law": "dwell", "cam_angle_deg": 150}, {"law": "cycloidal", "rise_deg": -60, "cam_angle_deg": 30},
            {"law": "dwell", "cam_angle_deg": 150}]})", "/motion", "as fast as the cam"},
        BadCase{"arm_face_dynamics", kO, R"({"dynamics": {"speed_rpm": 100, "follower_mass_kg": 1}})", "/dynamics",
                "takes \"arm_dynamics\""},
        BadCase{"arm_face_stage", kO, R"({"analysis": {"evaluate": ["error"]}})", "/analysis/evaluate/0",
                "roller followers only"},
        BadCase{"arm_face_stress_without_loads", kO, R"({"arm_dynamics": null})", "/limits/contact_stress_MPa",
                "arm_dynamics"},
        BadCase{"translating_arm_dynamics", kF, R"({"arm_dynamics": {"speed_rpm": 100, "arm_inertia_kg_m2": 0.01}})",
                "/arm_dynamics", "for oscillating followers (a pivoted arm) only"},
        BadCase{"translating_face_offset", kF, R"({"follower": {"face_offset_mm": 3}})", "/follower/face_offset_mm",
                "unknown field"},
        BadCase{"roller_without_radius", kK, R"({"follower": {"type": "translating_roller"}})",
                "/follower/roller_radius_mm", "missing required field"}));

}  // namespace disc_cam_follower_types_test
}  // namespace camopt
