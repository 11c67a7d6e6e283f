// Validation of the half-space contact solver against closed forms (docs/papers.md §1, model/contact/
// hertz.h): Hertz point contact of a sphere on a flat, and the mid-face of a long straight roller
// against Hertz line contact; and the edge peak of that roller growing as the axial cells shrink.
// The numbers behind docs/validation.md ("Half-space contact solver") come from
// bench/contact_bench.cc; here they are asserted with margins.
#include <array>
#include <cmath>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "model/contact/half_space.h"
#include "model/contact/hertz.h"
#include "model/contact/measures.h"
#include "model/contact/reference_gaps.h"
#include "tests/test_util.h"

namespace camopt::contact {
namespace contact_validation_test {

constexpr double kEStar = 115384.6;  // steel on steel [MPa]

TEST(ContactHertz, NotesSteelExampleOfLineContact) {
  // docs/papers.md §1: E = 210 GPa, ν = 0.3 both, F = 1000 N, L = 10 mm, R' = 10 mm → E* = 115.4 GPa,
  // p_max ≈ 606 MPa.
  const double e_star = CompositeModulus(210000.0, 0.3, 210000.0, 0.3);
  EXPECT_NEAR(e_star, 115384.6, 0.1);
  EXPECT_NEAR(LineContactPeakPressure(1000.0, 10.0, 10.0, e_star), 606.0, 0.5);
}

TEST(ContactHertz, ClosedFormGradientsMatchCentralDifferences) {
  auto f = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    const auto point = CircularPointContact(x[0], x[2], x[3]);
    return std::vector<T>{LineContactPeakPressure(x[0], x[1], x[2], x[3]),
                          LineContactHalfWidth(x[0], x[1], x[2], x[3]), point.radius,
                          point.peak_pressure, point.approach};
  };
  testing::ExpectJacobianMatchesCentralDifferences<4>(f, {1000.0, 10.0, 10.0, 115384.6});
}

struct PointResult {
  double p0_error, a_error, approach_error;  // relative, signed
};

PointResult SolvePoint(int n) {
  const double r = 10.0, force = 100.0;
  const auto hz = CircularPointContact(force, r, kEStar);
  const Grid g = CenteredGrid(n, n, 1.5 * hz.radius, 1.5 * hz.radius);
  const auto s = HalfSpaceSolver().SolveForLoad(g, SphereGap(g, r), force, kEStar);
  EXPECT_TRUE(s.converged) << s.message;
  EXPECT_FALSE(s.contact_at_grid_edge);
  return {s.max_pressure_MPa / hz.peak_pressure - 1, CircularContactRadius(g, s) / hz.radius - 1,
          s.approach_mm / hz.approach - 1};
}

TEST(ContactHertz, PointContactOn40x40) {
  const auto e = SolvePoint(40);
  EXPECT_LT(std::abs(e.p0_error), 0.005);
  EXPECT_LT(std::abs(e.a_error), 0.01);
  EXPECT_LT(std::abs(e.approach_error), 0.005);
}

TEST(ContactHertz, PointContactErrorsFallWithTheCellSize) {
  // Cell-centred collocation: the peak error is second order in the cell size.
  const auto coarse = SolvePoint(16), mid = SolvePoint(32), fine = SolvePoint(64);
  EXPECT_LT(std::abs(mid.p0_error), 0.5 * std::abs(coarse.p0_error));
  EXPECT_LT(std::abs(fine.p0_error), 0.5 * std::abs(mid.p0_error));
  EXPECT_LT(std::abs(fine.p0_error), 0.001);
  EXPECT_LT(std::abs(fine.a_error), 0.005);
  EXPECT_LT(std::abs(fine.approach_error), 0.001);
}

// A straight roller R = 10 mm, L = 10 mm, W = 1000 N on a flat: grid ±2b across, the roller's
// length along. Hertz line contact holds locally: with the mid-face line load w the mid-face
// peak and half-width follow Hertz for w. In the 3D half-space the line load is not uniform
// (the ends carry more, the middle less than W/L), so against W/L the mid-face is lower.
struct RollerResult {
  double w_mid_over_mean, p_mid_vs_local, b_mid_vs_local, p_mid_vs_mean, edge_peak;
};

RollerResult SolveRoller(int nx, int ny) {
  const double r = 10.0, length = 10.0, force = 1000.0;
  const double b = LineContactHalfWidth(force, length, r, kEStar);
  const Grid g = CenteredGrid(nx, ny, 2.0 * b, 0.5 * length);
  const auto s = HalfSpaceSolver().SolveForLoad(g, CylinderGap(g, r), force, kEStar);
  EXPECT_TRUE(s.converged) << s.message;
  EXPECT_FALSE(s.contact_at_x_edge);
  const int mid = ny / 2;
  const double w = RowLineLoad(g, s, mid);
  return {w / (force / length),
          RowPeakPressure(g, s, mid) / LineContactPeakPressure(w, 1.0, r, kEStar) - 1,
          RowHalfWidth(g, s, mid) / LineContactHalfWidth(w, 1.0, r, kEStar) - 1,
          RowPeakPressure(g, s, mid) / LineContactPeakPressure(force, length, r, kEStar) - 1,
          s.max_pressure_MPa};
}

TEST(ContactHertz, LongRollerMidFaceFollowsHertzLineContact) {
  const auto e = SolveRoller(32, 64);
  EXPECT_LT(std::abs(e.p_mid_vs_local), 0.01);
  EXPECT_LT(std::abs(e.b_mid_vs_local), 0.02);
  // The mid-face carries less than the mean line load, so its peak is below Hertz for W/L,
  // but not by much on a roller 95 half-widths long.
  EXPECT_LT(e.w_mid_over_mean, 1.0);
  EXPECT_GT(e.w_mid_over_mean, 0.85);
  EXPECT_LT(e.p_mid_vs_mean, 0.0);
  EXPECT_GT(e.p_mid_vs_mean, -0.08);
}

TEST(ContactHertz, StraightRollerEdgePeakGrowsAsAxialCellsShrink) {
  // The pressure at an abrupt end is singular (∝ d^(-1/2) in the distance d from the end), so
  // the edge cell's mean pressure grows without bound as dy shrinks, about as dy^(-1/2), while
  // the mid-face value stays put. Every edge number must carry its dy.
  double previous = 0, mid_first = 0;
  for (int ny : {32, 64, 128, 256}) {
    const auto e = SolveRoller(32, ny);
    if (previous > 0) {
      const double growth = e.edge_peak / previous;  // per halving of dy
      EXPECT_GT(growth, 1.1) << ny;
      EXPECT_LT(growth, std::sqrt(2.0) * 1.02) << ny;
      EXPECT_NEAR(e.p_mid_vs_mean, mid_first, 0.01) << ny;
    } else {
      mid_first = e.p_mid_vs_mean;
    }
    previous = e.edge_peak;
  }
}

}  // namespace contact_validation_test
}  // namespace camopt::contact
