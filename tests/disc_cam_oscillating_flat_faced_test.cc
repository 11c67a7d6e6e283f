// Oscillating flat-faced follower (model/disc_cam/oscillating_flat_faced.h) against an independent
// numerical envelope built here from the mechanism itself: the pivot O₃ = f u(θ), the arm along
// u(θ + π − ξ), the face the line at distance d from the pivot toward the cam; the contact as the
// intersection of two neighbouring face lines, the cam inside every face's half-plane, the radius of
// curvature from three profile points, the contact's place on the face and the pressure angle from
// the geometry of the arm.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "model/disc_cam/oscillating_flat_faced.h"

namespace camopt {
namespace disc_cam_oscillating_flat_faced_test {

constexpr double kPiHere = 3.14159265358979323846;
constexpr double kDegHere = kPiHere / 180.0;
constexpr double kBeta = 120 * kDegHere;  // the swing's cam angle
double kH = 10 * kDegHere;               // a 10° cycloidal swing (20° in the concave case)
constexpr double kF = 100.0, kD = 10.0, kRb = 40.0;

motion::MotionProgram<double> Program() {
  using motion::MotionLaw;
  return motion::MotionProgram<double>({{MotionLaw::kCycloidal, kH, kBeta},
                                        {MotionLaw::kDwell, 0.0, 50 * kDegHere},
                                        {MotionLaw::kCycloidal, -kH, kBeta},
                                        {MotionLaw::kDwell, 0.0, 70 * kDegHere}});
}

disc_cam::OscillatingFlatFaced Cam(double rb = kRb) {
  disc_cam::OscillatingFlatFaced c;
  c.base_radius = rb;
  c.pivot_distance = kF;
  c.face_offset = kD;
  c.motion = Program();
  return c;
}

// The arm angle, written out: ξ₀ = asin((r_b + d)/f) (the face tangent to the base circle: its
// distance from O₂ is f sin ξ₀ − d = r_b) plus the cycloidal S(θ).
double Xi(double th, double rb = kRb) {
  th = std::fmod(th + 4 * kPiHere, 2 * kPiHere);
  auto cyc = [](double u) { return kH * (u - std::sin(2 * kPiHere * u) / (2 * kPiHere)); };
  double s = 0.0;
  if (th < kBeta) s = cyc(th / kBeta);
  else if (th < 170 * kDegHere) s = kH;
  else if (th < 290 * kDegHere) s = kH - cyc((th - 170 * kDegHere) / kBeta);
  return std::asin((rb + kD) / kF) + s;
}

// The face line at θ as (unit normal toward the cam m, c) with {P : P · m = c}: the pivot
// O₃ = f u(θ), the arm w = u(θ + π − ξ), m = J w, the line (P − O₃) · m = d.
struct Line {
  Vec2<double> m;
  double c;
};
Line Face(double th, double rb = kRb) {
  const Vec2<double> o3(kF * std::cos(th), kF * std::sin(th));
  const double a = th + kPiHere - Xi(th, rb);
  const Vec2<double> m(-std::sin(a), std::cos(a));
  return {m, o3.dot(m) + kD};
}
Vec2<double> Meet(const Line& a, const Line& b) {
  const double det = a.m.x() * b.m.y() - a.m.y() * b.m.x();
  return Vec2<double>((a.c * b.m.y() - b.c * a.m.y()) / det, (a.m.x() * b.c - b.m.x() * a.c) / det);
}

TEST(DiscCamOscillatingFlatFaced, ContactIsTheEnvelopeOfTheFaceLines) {
  const disc_cam::OscillatingFlatFaced cam = Cam();
  EXPECT_TRUE(disc_cam::CheckOscillatingFlatFaced(cam, 3600).empty());
  const double d = 1e-5;
  for (int i = 0; i < 360; ++i) {
    const double th = 2 * kPiHere * i / 360 + 0.003;  // off the segment joints
    const disc_cam::OscillatingFlatFacePoint p = disc_cam::EvaluateOscillatingFlatFaced(cam, th);
    const Vec2<double> e = Meet(Face(th - d), Face(th + d));
    EXPECT_NEAR((p.contact - e).norm(), 0.0, 1e-6) << "theta " << i << " deg";
    // On its own face, and the cam (convex here) inside every face's half-plane: the face never
    // cuts the cam (the half-plane beyond the face, seen from the cam, is P · m ≥ c).
    const Line own = Face(th);
    EXPECT_NEAR(p.contact.dot(own.m), own.c, 1e-9);
    for (int j = 0; j < 360; j += 7) {
      const Line other = Face(2 * kPiHere * j / 360);
      EXPECT_GE(p.contact.dot(other.m), other.c - 1e-9) << i << " against " << j;
    }
    // Where the contact lies on the face, from the pivot's foot along the arm, and the pressure
    // angle between the face normal and the contact point's velocity (⟂ O₃A).
    const Vec2<double> o3(kF * std::cos(th), kF * std::sin(th));
    const double a = th + kPiHere - Xi(th);
    const Vec2<double> w(std::cos(a), std::sin(a));
    EXPECT_NEAR(p.contact_on_face, (p.contact - o3).dot(w), 1e-9);
    const Vec2<double> r = p.contact - o3, vel(-r.y(), r.x());
    EXPECT_NEAR(p.pressure_angle, std::acos(std::abs(vel.dot(own.m)) / vel.norm()), 1e-9);
  }
  // On the base circle (the last dwell) the contact is on it.
  EXPECT_NEAR(disc_cam::EvaluateOscillatingFlatFaced(cam, 330 * kDegHere).contact.norm(), kRb, 1e-9);
}

TEST(DiscCamOscillatingFlatFaced, RadiusOfCurvatureFromThreeProfilePoints) {
  const disc_cam::OscillatingFlatFaced cam = Cam();
  const double h = 1e-3;
  for (int i = 1; i < 36; ++i) {
    const double th = 2 * kPiHere * i / 36 + 0.01;
    auto A = [&](double t) { return disc_cam::EvaluateOscillatingFlatFaced(cam, t).contact; };
    const Vec2<double> a = A(th - h), b = A(th), c = A(th + h);
    const double cross = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    const double r = (b - a).norm() * (c - b).norm() * (c - a).norm() / (2 * std::abs(cross));
    const double rho = disc_cam::EvaluateOscillatingFlatFaced(cam, th).radius_of_curvature;
    const double a_arm = th + kPiHere - Xi(th);
    EXPECT_GT(cross, 0.0) << "counter-clockwise at " << th / kDegHere;
    EXPECT_GT((c - a).dot(Vec2<double>(std::cos(a_arm), std::sin(a_arm))), 0.0) << "forward along the face";
    EXPECT_NEAR(r, rho, 1e-4 * rho) << "theta " << th / kDegHere;
  }
  // In a dwell the profile is a circle about O₂ of radius f sin ξ − d: r_b, and f sin(ξ₀ + h) − d on top.
  EXPECT_NEAR(disc_cam::EvaluateOscillatingFlatFaced(cam, 330 * kDegHere).radius_of_curvature, kRb, 1e-9);
  EXPECT_NEAR(disc_cam::EvaluateOscillatingFlatFaced(cam, 145 * kDegHere).radius_of_curvature,
              kF * std::sin(std::asin(0.5) + kH) - kD, 1e-9);
}

TEST(DiscCamOscillatingFlatFaced, ASwingTooLargeForTheBaseCircleIsConcave) {
  // A 20° swing on the same base circle: ρ < 0 on the rise (about −19.6 mm near 76°); there the
  // contact runs backward along the face's direction w = u(θ + π − ξ) (dA/dθ = ρ (1 − ξ') w: the
  // envelope folds back, a cusp), with |ρ| the circumradius of three profile points.
  kH = 20 * kDegHere;
  disc_cam::OscillatingFlatFaced cam = Cam();
  cam.motion = motion::MotionProgram<double>({{motion::MotionLaw::kCycloidal, kH, kBeta},
                                               {motion::MotionLaw::kDwell, 0.0, 50 * kDegHere},
                                               {motion::MotionLaw::kCycloidal, -kH, kBeta},
                                               {motion::MotionLaw::kDwell, 0.0, 70 * kDegHere}});
  const double th = 76 * kDegHere, h = 1e-3;
  auto A = [&](double t) { return disc_cam::EvaluateOscillatingFlatFaced(cam, t).contact; };
  const Vec2<double> a = A(th - h), b = A(th), c = A(th + h);
  const double cross = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
  const double r = (b - a).norm() * (c - b).norm() * (c - a).norm() / (2 * std::abs(cross));
  const double rho = disc_cam::EvaluateOscillatingFlatFaced(cam, th).radius_of_curvature;
  const double a_arm = th + kPiHere - Xi(th);
  const Vec2<double> w(std::cos(a_arm), std::sin(a_arm));
  EXPECT_LT(rho, -15.0);
  EXPECT_LT((c - a).dot(w), 0.0);
  EXPECT_NE(cross, 0.0);
  EXPECT_NEAR(r, -rho, 1e-4 * r);
  // The envelope point still is where neighbouring faces meet.
  const Vec2<double> e = Meet(Face(th - 1e-5), Face(th + 1e-5));
  EXPECT_NEAR((b - e).norm(), 0.0, 1e-6);
  kH = 10 * kDegHere;
}

TEST(DiscCamOscillatingFlatFaced, InfeasibleDesigns) {
  disc_cam::OscillatingFlatFaced c = Cam();
  c.pivot_distance = 45.0;  // r_b + d = 50 > f
  EXPECT_NE(disc_cam::CheckOscillatingFlatFaced(c, 360).find("cannot touch"), std::string::npos);
  c = Cam();
  c.motion = motion::MotionProgram<double>({{motion::MotionLaw::kCycloidal, 60 * kDegHere, 30 * kDegHere},
                                            {motion::MotionLaw::kCycloidal, -60 * kDegHere, 330 * kDegHere}});
  // ξ' peaks at 2h/β = 2·60/30 = 4 > 1: the arm outruns the cam.
  EXPECT_NE(disc_cam::CheckOscillatingFlatFaced(c, 360).find("as fast as the cam"), std::string::npos);
}

}  // namespace disc_cam_oscillating_flat_faced_test
}  // namespace camopt
