// Flat-faced translating follower (model/disc_cam/flat_faced.h) against the envelope of the face
// lines computed here: the contact point as the intersection of two neighbouring face lines, the
// profile inside every face's half-plane, the radius of curvature from three profile points, the
// face width from the cycloidal law's peak velocity 2h/β (Norton, Design of Machinery §8.9).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "model/disc_cam/flat_faced.h"

namespace camopt {
namespace disc_cam_flat_faced_test {

constexpr double kPiHere = 3.14159265358979323846;
constexpr double kDegHere = kPiHere / 180.0;
constexpr double kH = 24.0, kBeta = 120 * kDegHere;

motion::MotionProgram<double> Program() {
  using motion::MotionLaw;
  return motion::MotionProgram<double>({{MotionLaw::kCycloidal, kH, kBeta},
                                        {MotionLaw::kDwell, 0.0, 50 * kDegHere},
                                        {MotionLaw::kCycloidal, -kH, kBeta},
                                        {MotionLaw::kDwell, 0.0, 70 * kDegHere}});
}

// The follower displacement of the program, written out here from the cycloidal law
// S = h (u − sin(2πu)/(2π)) (rise over [0, 120°], dwell to 170°, return to 290°, dwell).
double S(double th) {
  th = std::fmod(th + 4 * kPiHere, 2 * kPiHere);
  auto cyc = [](double u) { return kH * (u - std::sin(2 * kPiHere * u) / (2 * kPiHere)); };
  if (th < kBeta) return cyc(th / kBeta);
  if (th < 170 * kDegHere) return kH;
  if (th < 290 * kDegHere) return kH - cyc((th - 170 * kDegHere) / kBeta);
  return 0.0;
}

// The face line at θ: {P : P · u(θ) = r_b + S(θ)}; two of them meet at the solution of a 2×2 system.
Vec2<double> Meet(double rb, double a, double b) {
  const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b);
  const double ra = rb + S(a), r2 = rb + S(b), det = ca * sb - sa * cb;
  return Vec2<double>((ra * sb - r2 * sa) / det, (ca * r2 - cb * ra) / det);
}

TEST(DiscCamFlatFaced, ContactIsTheEnvelopeOfTheFaceLines) {
  const double rb = 40.0, d = 1e-4;
  const motion::MotionProgram<double> prog = Program();
  for (int i = 0; i < 360; ++i) {
    const double th = 2 * kPiHere * i / 360;
    const disc_cam::FlatFacePoint<double> p = disc_cam::EvaluateFlatFaced(prog, rb, th);
    const Vec2<double> e = Meet(rb, th - d, th + d);
    // The neighbouring lines meet within O(d²) of the envelope point (segment joints: O(d)).
    EXPECT_NEAR((p.contact - e).norm(), 0.0, 1e-5) << "theta " << i << " deg";
    // On its own face line, and inside every other face's half-plane (a convex cam, ρ > 0 here).
    EXPECT_NEAR(p.contact.dot(U(th)), rb + S(th), 1e-9);
    for (int j = 0; j < 360; j += 7) {
      const double ph = 2 * kPiHere * j / 360;
      EXPECT_LE(p.contact.dot(U(ph)), rb + S(ph) + 1e-9) << i << " against " << j;
    }
  }
}

TEST(DiscCamFlatFaced, RadiusOfCurvatureFromThreeProfilePoints) {
  const double rb = 40.0, h = 1e-3;
  const motion::MotionProgram<double> prog = Program();
  for (int i = 1; i < 36; ++i) {
    const double th = 2 * kPiHere * i / 36 + 0.01;  // off the segment joints
    auto A = [&](double t) { return disc_cam::EvaluateFlatFaced(prog, rb, t).contact; };
    const Vec2<double> a = A(th - h), b = A(th), c = A(th + h);
    // Circumradius of the triangle abc: |ab||bc||ca| / (2 |ab × ac|).
    const double cross = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    const double r = (b - a).norm() * (c - b).norm() * (c - a).norm() / (2 * std::abs(cross));
    const double rho = disc_cam::EvaluateFlatFaced(prog, rb, th).radius_of_curvature;
    EXPECT_NEAR(r, rho, 1e-4 * rho) << "theta " << th / kDegHere;
  }
}

TEST(DiscCamFlatFaced, FaceWidthAndCusp) {
  // The contact runs S' off the axis: the cycloid's peak velocity 2h/β each way (u = 1/2 of the rise
  // at 60°, of the return at 230°, both on the 3600-angle grid).
  const disc_cam::FlatFaceCycle c = disc_cam::SummarizeFlatFaced(Program(), 40.0, 3600);
  EXPECT_NEAR(c.max_offset_mm, 2 * kH / kBeta, 1e-9);
  EXPECT_NEAR(c.min_offset_mm, -2 * kH / kBeta, 1e-9);
  EXPECT_NEAR(c.face_width_needed_mm(), 4 * kH / kBeta, 1e-9);
  EXPECT_GT(c.min_radius_of_curvature_mm, 0.0);
  // A small base circle: ρ = r_b + S + S'' with S'' = (2πh/β²) sin 2πu; at u = 3/4 of the rise
  // (90°) S = h (3/4 + 1/(2π)), S'' = −2πh/β²: ρ = 5 + 21.82 − 34.38 < 0, a cusp.
  const disc_cam::FlatFaceCycle small = disc_cam::SummarizeFlatFaced(Program(), 5.0, 3600);
  const double rho90 = 5.0 + kH * (0.75 + 1 / (2 * kPiHere)) - 2 * kPiHere * kH / (kBeta * kBeta);
  EXPECT_LT(rho90, 0.0);
  EXPECT_LE(small.min_radius_of_curvature_mm, rho90 + 1e-9);
  EXPECT_NEAR(disc_cam::EvaluateFlatFaced(Program(), 5.0, 90 * kDegHere).radius_of_curvature, rho90, 1e-9);
}

}  // namespace disc_cam_flat_faced_test
}  // namespace camopt
