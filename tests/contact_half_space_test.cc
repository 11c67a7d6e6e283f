// Tests of the half-space contact solver: Love's coefficients, the DC-FFT convolution, the
// Polonsky–Keer iteration against the dense active-set reference, and Hertz closed forms.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "model/contact/half_space.h"
#include "model/contact/hertz.h"
#include "model/contact/love.h"

namespace camopt::contact {
namespace {

constexpr double kEStar = 115384.6;  // steel on steel, E = 210 GPa, ν = 0.3 [MPa]

// Gap of a sphere of radius R on a flat (paraboloid), centred at the origin.
std::vector<double> SphereGap(const Grid& g, double r) {
  std::vector<double> h(g.cells());
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const double x = g.x_centre_mm(ix), y = g.y_centre_mm(iy);
      h[iy * g.nx + ix] = (x * x + y * y) / (2 * r);
    }
  return h;
}

TEST(ContactLove, CentreOfSquareMatchesClosedForm) {
  // ∬ over a square of side 2a of 1/r from its centre = 8 a asinh(1).
  const double a = 0.3;
  EXPECT_NEAR(LoveInfluence(0.0, 0.0, a, a), 8 * a * std::asinh(1.0) / kPi, 1e-14);
}

TEST(ContactLove, FarFieldIsPointLoad) {
  // Far away the cell acts as a point force p·4ξη: u·E* = 4ξη/(π r).
  const double xi = 0.01, eta = 0.02, x = 3.0, y = -4.0;
  const double r = std::hypot(x, y);
  EXPECT_NEAR(LoveInfluence(x, y, xi, eta), 4 * xi * eta / (kPi * r), 1e-6 * 4 * xi * eta / r);
}

TEST(ContactDisplacement, FftMatchesDirectSum) {
  const Grid g = CenteredGrid(13, 7, 1.0, 0.6);
  std::vector<double> p(g.cells());
  for (int i = 0; i < g.cells(); ++i) p[i] = std::fmod(37.0 * i, 11.0);
  const auto u_fft = Displacement(g, p, kEStar);
  const auto u_dense = DisplacementDense(g, p, kEStar);
  double u_max = 0;
  for (double v : u_dense) u_max = std::max(u_max, std::abs(v));
  for (int i = 0; i < g.cells(); ++i) EXPECT_NEAR(u_fft[i], u_dense[i], 1e-12 * u_max) << i;
}

TEST(ContactSolver, HertzPointContact) {
  const double r = 10.0, force = 100.0;
  const auto hz = CircularPointContact(force, r, kEStar);
  const Grid g = CenteredGrid(40, 40, 1.5 * hz.radius, 1.5 * hz.radius);
  HalfSpaceSolver solver;
  const auto s = solver.SolveForLoad(g, SphereGap(g, r), force, kEStar);
  ASSERT_TRUE(s.converged) << s.message;
  EXPECT_NEAR(s.load_N, force, 1e-9 * force);
  EXPECT_NEAR(s.max_pressure_MPa, hz.peak_pressure, 0.03 * hz.peak_pressure);
  EXPECT_NEAR(std::sqrt(s.contact_area_mm2 / kPi), hz.radius, 0.05 * hz.radius);
  EXPECT_NEAR(s.approach_mm, hz.approach, 0.03 * hz.approach);
}

TEST(ContactSolver, DenseAndCgAgreeOn40x40) {
  const double r = 10.0, force = 100.0;
  const auto hz = CircularPointContact(force, r, kEStar);
  const Grid g = CenteredGrid(40, 40, 1.5 * hz.radius, 1.5 * hz.radius);
  const auto h = SphereGap(g, r);
  HalfSpaceSolver solver;
  const auto cg = solver.SolveForLoad(g, h, force, kEStar);
  const auto dense = SolveDenseForLoad(g, h, force, kEStar);
  ASSERT_TRUE(cg.converged);
  ASSERT_TRUE(dense.converged);
  EXPECT_EQ(cg.cells_in_contact, dense.cells_in_contact);
  for (int i = 0; i < g.cells(); ++i)
    EXPECT_NEAR(cg.pressure_MPa[i], dense.pressure_MPa[i], 1e-6 * dense.max_pressure_MPa) << i;
  EXPECT_NEAR(cg.approach_mm, dense.approach_mm, 1e-7 * dense.approach_mm);
}

}  // namespace
}  // namespace camopt::contact
