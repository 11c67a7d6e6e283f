// Tests of the half-space contact solver: Love's coefficients, the DC-FFT convolution, the
// Polonsky–Keer iteration against the dense active-set reference, and the hard cases (barely
// touching, zero load, a gap that never closes, huge and tiny loads, bad input).
// Closed-form validation (Hertz point and line contact) is in contact_validation_test.cc.
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <thread>
#include <tuple>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "model/contact/half_space.h"
#include "model/contact/hertz.h"
#include "model/contact/love.h"
#include "model/contact/reference_gaps.h"
#include "tests/test_util.h"

namespace camopt::contact {
namespace contact_half_space_test {

constexpr double kEStar = 115384.6;  // steel on steel, E = 210 GPa, ν = 0.3 [MPa]

// The paper's eq. (21) exactly as printed (ratios of logarithms), for E* = 1 / π factor kept.
// Well-conditioned only where every t + sqrt(t² + s²) has t > 0.
double PaperLiteralInfluence(double x, double y, double xi, double eta) {
  auto q = [](double t, double s) { return t + std::sqrt(t * t + s * s); };
  const double xp = x + xi, xm = x - xi, yp = y + eta, ym = y - eta;
  return (xp * std::log(q(yp, xp) / q(ym, xp)) + yp * std::log(q(xp, yp) / q(xm, yp)) +
          xm * std::log(q(ym, xm) / q(yp, xm)) + ym * std::log(q(xm, ym) / q(xp, ym))) /
         kPi;
}

bool AllFinite(const ContactSolution& s) {
  for (double p : s.pressure_MPa)
    if (!std::isfinite(p) || p < 0) return false;
  return std::isfinite(s.approach_mm) && std::isfinite(s.load_N) &&
         std::isfinite(s.max_pressure_MPa);
}

Grid HertzGrid(int n, double force = 100.0, double r = 10.0) {
  const double a = CircularPointContact(force, r, kEStar).radius;
  return CenteredGrid(n, n, 1.5 * a, 1.5 * a);
}

// ---- Love's coefficients -------------------------------------------------------------------

TEST(ContactLove, CentreOfSquareMatchesClosedForm) {
  // ∬ over a square of side 2a of 1/r from its centre = 8 a asinh(1).
  const double a = 0.3;
  EXPECT_NEAR(LoveInfluence(0.0, 0.0, a, a), 8 * a * std::asinh(1.0) / kPi, 1e-14);
}

TEST(ContactLove, AgreesWithThePapersFormWhereThatIsWellConditioned) {
  for (const auto& [x, y] : {std::array<double, 2>{0.37, 0.52}, {1.3, 0.2}, {0.25, 2.0}}) {
    const double ours = LoveInfluence(x, y, 0.1, 0.15);
    EXPECT_NEAR(ours, PaperLiteralInfluence(x, y, 0.1, 0.15), 1e-13 * ours) << x << ", " << y;
  }
}

TEST(ContactLove, FarFieldIsPointLoadInEveryQuadrant) {
  // Far away the cell acts as a point force 4ξη: u·E* = 4ξη/(π r), relative error O((ξ/r)²).
  // The negative quadrants are where the printed form of eq. (21) cancels.
  const double xi = 0.01, eta = 0.02;
  for (const auto& [x, y] : {std::array<double, 2>{3.0, -4.0}, {-30.0, -40.0}, {-5.0, 2.0}}) {
    const double r = std::hypot(x, y), point = 4 * xi * eta / (kPi * r);
    EXPECT_NEAR(LoveInfluence(x, y, xi, eta), point, 1e-5 * point) << x << ", " << y;
  }
}

TEST(ContactLove, SymmetricUnderReflectionAndSwap) {
  const double v = LoveInfluence(0.3, -0.7, 0.1, 0.2);
  EXPECT_NEAR(LoveInfluence(-0.3, -0.7, 0.1, 0.2), v, 1e-15);
  EXPECT_NEAR(LoveInfluence(0.3, 0.7, 0.1, 0.2), v, 1e-15);
  EXPECT_NEAR(LoveInfluence(-0.7, 0.3, 0.2, 0.1), v, 1e-15);
}

TEST(ContactLove, GradientMatchesCentralDifferences) {
  auto f = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    return std::vector<T>{LoveInfluence(x[0], x[1], x[2], x[3])};
  };
  testing::ExpectJacobianMatchesCentralDifferences<4>(f, {0.33, -0.21, 0.1, 0.05});
  testing::ExpectJacobianMatchesCentralDifferences<4>(f, {0.02, 0.01, 0.1, 0.05});
}

// ---- DC-FFT convolution --------------------------------------------------------------------

TEST(ContactDisplacement, FftMatchesDirectSum) {
  for (const auto& [nx, ny] : {std::array<int, 2>{13, 7}, {1, 9}, {8, 1}, {1, 1}}) {
    const Grid g = CenteredGrid(nx, ny, 1.0, 0.6);
    std::vector<double> p(g.cells());
    for (int i = 0; i < g.cells(); ++i) p[i] = 1.0 + std::fmod(37.0 * i, 11.0);
    const auto u_fft = Displacement(g, p, kEStar);
    const auto u_dense = DisplacementDense(g, p, kEStar);
    double u_max = 0;
    for (double v : u_dense) u_max = std::max(u_max, std::abs(v));
    for (int i = 0; i < g.cells(); ++i)
      EXPECT_NEAR(u_fft[i], u_dense[i], 1e-12 * u_max) << nx << "x" << ny << " cell " << i;
  }
}

TEST(ContactDisplacement, RateByCellHeightMatchesCentralDifferencesOfTheDirectSum) {
  // The grid stretched along y at fixed cell pressures (rows of a face width): the Jet derivative
  // of Love's kernel against central differences of the direct sum on grids dy ± h.
  constexpr double kRelTol = 1e-6;  // step 1e-5 dy: truncation ~1e-10, rounding ~1e-11 relative
  for (const auto& [nx, ny] : {std::array<int, 2>{13, 7}, {6, 11}, {1, 5}}) {
    const Grid g = CenteredGrid(nx, ny, 0.4, 3.0);
    std::vector<double> p(g.cells(), 0.0);
    for (int i = 0; i < g.cells(); ++i)
      if (i % 3 != 1) p[i] = 100.0 + std::fmod(37.0 * i, 11.0) * 50.0;  // some cells unloaded
    const std::vector<double> rate = DisplacementRateByCellHeight(g, p, kEStar);
    const double h = 1e-5 * g.dy;
    auto at = [&](double s) {
      Grid m = g;
      m.dy += s * h;
      m.y0 = -0.5 * m.ny * m.dy;
      return DisplacementDense(m, p, kEStar);
    };
    const std::vector<double> plus = at(1), minus = at(-1);
    double scale = 0;
    for (int i = 0; i < g.cells(); ++i) scale = std::max(scale, std::abs(plus[i] - minus[i]) / (2 * h));
    ASSERT_GT(scale, 0.0);
    for (int i = 0; i < g.cells(); ++i)
      EXPECT_NEAR(rate[i], (plus[i] - minus[i]) / (2 * h), kRelTol * scale) << nx << "x" << ny << " cell " << i;
  }
}

// ---- CG against the dense reference --------------------------------------------------------

// The recorded FFT plans (model/contact/fft_wisdom.inc) are accepted by this FFTW; the test below
// then solves through them (40 × 40 is one of the recorded shapes) against the dense reference.
TEST(ContactSolver, RecordedFftPlansAreImported) { EXPECT_TRUE(FftWisdomImported()); }

TEST(ContactSolver, DenseAndCgAgreeOn40x40) {
  const Grid g = HertzGrid(40);
  const auto h = SphereGap(g, 10.0);
  HalfSpaceSolver solver;
  const auto cg = solver.SolveForLoad(g, h, 100.0, kEStar);
  const auto dense = SolveDenseForLoad(g, h, 100.0, kEStar);
  ASSERT_TRUE(cg.converged) << cg.message;
  ASSERT_TRUE(dense.converged) << dense.message;
  EXPECT_EQ(cg.cells_in_contact, dense.cells_in_contact);
  for (int i = 0; i < g.cells(); ++i)
    EXPECT_NEAR(cg.pressure_MPa[i], dense.pressure_MPa[i], 1e-6 * dense.max_pressure_MPa) << i;
  EXPECT_NEAR(cg.approach_mm, dense.approach_mm, 1e-7 * dense.approach_mm);
  EXPECT_NEAR(cg.load_N, 100.0, 1e-10 * 100.0);
  EXPECT_NEAR(dense.load_N, 100.0, 1e-10 * 100.0);
}

TEST(ContactSolver, DenseAndCgAgreeOnAnOffCentreRectangularGridUnderApproachControl) {
  // A sphere off the grid centre on a 24 × 17 grid of unequal cells.
  Grid g;
  g.nx = 24;
  g.ny = 17;
  g.dx = 0.02;
  g.dy = 0.03;
  g.x0 = -0.2;
  g.y0 = -0.3;
  const auto h = SphereGap(g, 8.0, 0.03, -0.05);
  const double approach = 0.002;
  HalfSpaceSolver solver;
  const auto cg = solver.SolveForApproach(g, h, approach, kEStar);
  const auto dense = SolveDenseForApproach(g, h, approach, kEStar);
  ASSERT_TRUE(cg.converged) << cg.message;
  ASSERT_TRUE(dense.converged) << dense.message;
  EXPECT_EQ(cg.cells_in_contact, dense.cells_in_contact);
  EXPECT_NEAR(cg.load_N, dense.load_N, 1e-6 * dense.load_N);
  for (int i = 0; i < g.cells(); ++i)
    EXPECT_NEAR(cg.pressure_MPa[i], dense.pressure_MPa[i], 1e-6 * dense.max_pressure_MPa) << i;
}

TEST(ContactSolver, DenseAndCgAgreeOnARoughSurfaceWithManyIslands) {
  // A wavy gap with several separate contact spots, partly below zero (interference at δ = 0):
  // the active set changes much more than on a Hertz contact.
  const Grid g = CenteredGrid(26, 22, 1.0, 0.8);
  std::vector<double> h(g.cells());
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const double x = g.x_centre_mm(ix), y = g.y_centre_mm(iy);
      h[iy * g.nx + ix] = 1e-3 * (std::sin(7.1 * x + 0.3) * std::cos(5.3 * y - 0.2) +
                                  0.4 * std::sin(13.7 * x * y + 1.1) + 0.3 * x * x) -
                          2e-4;
    }
  HalfSpaceSolver solver;
  for (double load : {5.0, 200.0}) {
    const auto cg = solver.SolveForLoad(g, h, load, kEStar);
    const auto dense = SolveDenseForLoad(g, h, load, kEStar);
    ASSERT_TRUE(cg.converged) << cg.message;
    ASSERT_TRUE(dense.converged) << dense.message;
    EXPECT_EQ(cg.cells_in_contact, dense.cells_in_contact) << load;
    for (int i = 0; i < g.cells(); ++i)
      EXPECT_NEAR(cg.pressure_MPa[i], dense.pressure_MPa[i], 1e-5 * dense.max_pressure_MPa)
          << load << " cell " << i;
    EXPECT_NEAR(cg.approach_mm, dense.approach_mm, 1e-6 * std::abs(dense.approach_mm)) << load;
    const auto by_approach = solver.SolveForApproach(g, h, dense.approach_mm, kEStar);
    const auto dense_approach = SolveDenseForApproach(g, h, dense.approach_mm, kEStar);
    EXPECT_NEAR(by_approach.load_N, load, 1e-5 * load);
    EXPECT_NEAR(dense_approach.load_N, load, 1e-8 * load);
  }
}

TEST(ContactSolver, OneCellAndOneRowGrids) {
  // 1 × 1: the single cell carries the load, δ = h + p K₀₀ / E*.
  const Grid one = CenteredGrid(1, 1, 0.05, 0.1);
  const auto s = HalfSpaceSolver().SolveForLoad(one, {0.002}, 3.0, kEStar);
  const double p = 3.0 / one.cell_area_mm2();
  EXPECT_NEAR(s.pressure_MPa[0], p, 1e-12 * p);
  EXPECT_NEAR(s.approach_mm, 0.002 + p * LoveInfluence(0.0, 0.0, 0.05, 0.1) / kEStar, 1e-15);
  // 1 × 30 and 30 × 1: the same problem transposed gives the same pressures.
  const Grid column = CenteredGrid(1, 30, 0.05, 0.3), row = CenteredGrid(30, 1, 0.3, 0.05);
  std::vector<double> h(30);
  for (int i = 0; i < 30; ++i) h[i] = std::pow(column.y_centre_mm(i), 2) / 20.0;
  HalfSpaceSolver solver;
  const auto a = solver.SolveForLoad(column, h, 10.0, kEStar);
  const auto b = solver.SolveForLoad(row, h, 10.0, kEStar);
  const auto d = SolveDenseForLoad(row, h, 10.0, kEStar);
  for (int i = 0; i < 30; ++i) {
    EXPECT_NEAR(a.pressure_MPa[i], b.pressure_MPa[i], 1e-6 * b.max_pressure_MPa);
    EXPECT_NEAR(b.pressure_MPa[i], d.pressure_MPa[i], 1e-6 * d.max_pressure_MPa);
  }
}

TEST(ContactSolver, LoadAndApproachControlAreInverse) {
  const Grid g = HertzGrid(32);
  const auto h = SphereGap(g, 10.0);
  HalfSpaceSolver solver({1e-10, 2000});
  const auto by_load = solver.SolveForLoad(g, h, 100.0, kEStar);
  const auto by_approach = solver.SolveForApproach(g, h, by_load.approach_mm, kEStar);
  ASSERT_TRUE(by_approach.converged);
  EXPECT_NEAR(by_approach.load_N, 100.0, 1e-6 * 100.0);
  EXPECT_EQ(by_approach.cells_in_contact, by_load.cells_in_contact);
}

TEST(ContactSolver, SolutionSatisfiesTheComplementarityConditions) {
  // Independent check with the dense convolution: u + h = δ where p > 0, u + h ≥ δ elsewhere.
  const Grid g = HertzGrid(24);
  const auto h = SphereGap(g, 10.0, 0.01, 0.0);
  HalfSpaceSolver solver;
  const auto s = solver.SolveForLoad(g, h, 100.0, kEStar);
  const auto u = DisplacementDense(g, s.pressure_MPa, kEStar);
  for (int i = 0; i < g.cells(); ++i) {
    if (s.pressure_MPa[i] > 0)
      EXPECT_NEAR(u[i] + h[i], s.approach_mm, 1e-6 * s.approach_mm) << i;
    else
      EXPECT_GE(u[i] + h[i], s.approach_mm * (1 - 1e-6)) << i;
  }
}

// The preconditioned CG (SolverOptions::precondition, the default) and the plain Polonsky–Keer
// iteration against the dense active-set reference on three shapes: a Hertz point contact, a
// crowned line contact (cylinder R = 20 mm, length 4 mm, crowning drop 0.003 mm at the ends)
// and two separate patches (two spheres of different radius and height). Named tolerances:
// pressure within kPressureTol of the peak, approach within kApproachTol, and the complementarity
// conditions checked with the direct-sum displacement (u + h − δ within kGapTol · δ on the
// contact, ≥ −kGapTol · δ off it), all at the solver tolerance 1e-8.
TEST(ContactSolver, PreconditionedAndPlainCgMatchTheDenseReferenceOnThreeShapes) {
  constexpr double kPressureTol = 1e-6, kApproachTol = 1e-7, kGapTol = 1e-6;
  struct Case {
    const char* name;
    Grid grid;
    std::vector<double> gap;
    double load_N;
  };
  std::vector<Case> cases;
  {
    const Grid g = HertzGrid(32);
    cases.push_back({"hertz point", g, SphereGap(g, 10.0), 100.0});
  }
  {
    const Grid g = CenteredGrid(16, 64, 0.15, 2.0);
    std::vector<double> h = CylinderGap(g, 20.0);
    for (int iy = 0; iy < g.ny; ++iy)
      for (int ix = 0; ix < g.nx; ++ix) {
        const double y = g.y_centre_mm(iy);
        h[iy * g.nx + ix] += 0.003 * (y / 2.0) * (y / 2.0);  // parabolic crowning
      }
    cases.push_back({"crowned line", g, h, 150.0});
  }
  {
    const Grid g = CenteredGrid(40, 24, 1.0, 0.6);
    const auto a = SphereGap(g, 10.0, -0.5, 0.0), b = SphereGap(g, 6.0, 0.45, 0.1);
    std::vector<double> h(g.cells());
    for (int i = 0; i < g.cells(); ++i) h[i] = std::min(a[i], b[i] + 2e-4);
    cases.push_back({"two patches", g, h, 150.0});
  }
  for (const Case& c : cases) {
    const auto dense = SolveDenseForLoad(c.grid, c.gap, c.load_N, kEStar);
    ASSERT_TRUE(dense.converged) << c.name << ": " << dense.message;
    int iterations[2] = {0, 0};
    for (bool precondition : {true, false}) {
      SolverOptions options;
      options.precondition = precondition;
      HalfSpaceSolver solver(options);
      const auto cg = solver.SolveForLoad(c.grid, c.gap, c.load_N, kEStar);
      ASSERT_TRUE(cg.converged) << c.name << ": " << cg.message;
      iterations[precondition ? 0 : 1] = cg.iterations;
      EXPECT_EQ(cg.cells_in_contact, dense.cells_in_contact) << c.name << " " << precondition;
      EXPECT_NEAR(cg.load_N, c.load_N, 1e-10 * c.load_N);
      for (int i = 0; i < c.grid.cells(); ++i)
        EXPECT_NEAR(cg.pressure_MPa[i], dense.pressure_MPa[i], kPressureTol * dense.max_pressure_MPa)
            << c.name << " " << precondition << " cell " << i;
      EXPECT_NEAR(cg.approach_mm, dense.approach_mm, kApproachTol * std::abs(dense.approach_mm))
          << c.name << " " << precondition;
      const auto u = DisplacementDense(c.grid, cg.pressure_MPa, kEStar);
      const double scale = std::abs(cg.approach_mm);
      for (int i = 0; i < c.grid.cells(); ++i) {
        const double gap = u[i] + c.gap[i] - cg.approach_mm;
        if (cg.pressure_MPa[i] > 0)
          EXPECT_NEAR(gap, 0.0, kGapTol * scale) << c.name << " " << precondition << " cell " << i;
        else
          EXPECT_GE(gap, -kGapTol * scale) << c.name << " " << precondition << " cell " << i;
      }
    }
    // The point of the preconditioner: fewer iterations to the same tolerance.
    EXPECT_LT(iterations[0], iterations[1]) << c.name;
  }
}

TEST(ContactSolver, PressureIsSymmetricForASymmetricGap) {
  const Grid g = HertzGrid(30);
  const auto s = HalfSpaceSolver().SolveForLoad(g, SphereGap(g, 10.0), 100.0, kEStar);
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const double p = s.pressure_MPa[iy * g.nx + ix];
      EXPECT_NEAR(p, s.pressure_MPa[iy * g.nx + (g.nx - 1 - ix)], 1e-6 * s.max_pressure_MPa);
      EXPECT_NEAR(p, s.pressure_MPa[ix * g.nx + iy], 1e-6 * s.max_pressure_MPa);
    }
}

TEST(ContactSolver, ACommonGapOffsetOnlyShiftsTheApproach) {
  const Grid g = HertzGrid(32);
  const auto h = SphereGap(g, 10.0);
  auto shifted = h;
  for (double& v : shifted) v += 1000.0;
  HalfSpaceSolver solver;
  const auto a = solver.SolveForLoad(g, h, 100.0, kEStar);
  const auto b = solver.SolveForLoad(g, shifted, 100.0, kEStar);
  EXPECT_NEAR(b.approach_mm - 1000.0, a.approach_mm, 1e-12);
  for (int i = 0; i < g.cells(); ++i)
    EXPECT_NEAR(a.pressure_MPa[i], b.pressure_MPa[i], 1e-9 * a.max_pressure_MPa);
  const auto c = solver.SolveForApproach(g, shifted, a.approach_mm + 1000.0, kEStar);
  EXPECT_NEAR(c.load_N, 100.0, 1e-6 * 100.0);
}

TEST(ContactSolver, WarmStartGivesTheSameAnswer) {
  const Grid g = HertzGrid(32);
  HalfSpaceSolver solver;
  const auto first = solver.SolveForLoad(g, SphereGap(g, 10.0), 100.0, kEStar);
  const auto h2 = SphereGap(g, 10.0, 0.3 * g.dx, 0.1 * g.dy);
  const auto cold = solver.SolveForLoad(g, h2, 120.0, kEStar);
  const auto warm = solver.SolveForLoad(g, h2, 120.0, kEStar, first.pressure_MPa);
  ASSERT_TRUE(warm.converged);
  for (int i = 0; i < g.cells(); ++i)
    EXPECT_NEAR(warm.pressure_MPa[i], cold.pressure_MPa[i], 1e-6 * cold.max_pressure_MPa);
  // An unusable start (wrong size) is ignored.
  const auto ignored = solver.SolveForLoad(g, h2, 120.0, kEStar, std::vector<double>(3, 1.0));
  EXPECT_EQ(ignored.iterations, cold.iterations);
}

TEST(ContactSolver, CachedSolverMatchesAFreshOneAcrossGrids) {
  HalfSpaceSolver reused;
  for (int n : {20, 33, 20, 41}) {
    const Grid g = HertzGrid(n);
    const auto h = SphereGap(g, 10.0);
    const auto a = reused.SolveForLoad(g, h, 100.0, kEStar * (n == 33 ? 2.0 : 1.0));
    const auto b = HalfSpaceSolver().SolveForLoad(g, h, 100.0, kEStar * (n == 33 ? 2.0 : 1.0));
    EXPECT_EQ(a.pressure_MPa, b.pressure_MPa) << n;
    EXPECT_EQ(a.approach_mm, b.approach_mm) << n;
  }
}

TEST(ContactSolver, SolversInTwoThreadsAgreeWithOneThread) {
  const Grid g = HertzGrid(36);
  const auto h = SphereGap(g, 10.0);
  const auto reference = HalfSpaceSolver().SolveForLoad(g, h, 100.0, kEStar);
  std::vector<ContactSolution> out(2);
  std::vector<std::thread> threads;
  for (int k = 0; k < 2; ++k)
    threads.emplace_back([&, k] {
      HalfSpaceSolver solver;  // plans are created concurrently here
      for (int rep = 0; rep < 3; ++rep) out[k] = solver.SolveForLoad(g, h, 100.0, kEStar);
    });
  for (auto& t : threads) t.join();
  for (const auto& s : out) EXPECT_EQ(s.pressure_MPa, reference.pressure_MPa);
}

// A solve warm-started from a previous solution reuses that solution's displacement (a per-thread
// memo) instead of convolving again; the answer must be the same bits as on a thread that never
// saw the start (empty memo), and a Displacement of a solved pressure likewise.
TEST(ContactSolver, WarmStartFromTheLastSolutionIsBitIdenticalWithAnEmptyMemo) {
  const Grid g = HertzGrid(30);
  const auto h1 = SphereGap(g, 10.0);
  const auto h2 = SphereGap(g, 10.0, 0.2 * g.dx, 0.1 * g.dy);
  HalfSpaceSolver rough(SolverOptions{1e-2, 2000});
  HalfSpaceSolver fine(SolverOptions{1e-6, 2000});
  const auto start = rough.SolveForLoad(g, h1, 100.0, kEStar);  // memo now holds start's u
  const auto warm = fine.SolveForLoad(g, h2, 110.0, kEStar, start.pressure_MPa);
  const auto u_warm = fine.Displacement(g, warm.pressure_MPa, kEStar);
  ContactSolution other;
  std::vector<double> u_other;
  std::thread([&] {  // a new thread: its memo is empty
    HalfSpaceSolver fresh(SolverOptions{1e-6, 2000});
    other = fresh.SolveForLoad(g, h2, 110.0, kEStar, start.pressure_MPa);
    u_other = HalfSpaceSolver().Displacement(g, other.pressure_MPa, kEStar);
  }).join();
  ASSERT_TRUE(warm.converged);
  EXPECT_EQ(warm.pressure_MPa, other.pressure_MPa);
  EXPECT_EQ(warm.approach_mm, other.approach_mm);
  EXPECT_EQ(warm.iterations, other.iterations);
  EXPECT_EQ(u_warm, u_other);
  // A different modulus must not be answered from the memo: u scales with 1/E*.
  const auto u_half = fine.Displacement(g, warm.pressure_MPa, 2.0 * kEStar);
  for (int i = 0; i < g.cells(); ++i) EXPECT_NEAR(u_half[i], 0.5 * u_warm[i], 1e-12 * std::abs(u_warm[i]) + 1e-18);
}

TEST(ContactSolver, ReportsTheCellSizesItUsed) {
  const Grid g = CenteredGrid(10, 20, 0.5, 2.0);
  const auto s = HalfSpaceSolver().SolveForLoad(g, CylinderGap(g, 5.0), 50.0, kEStar);
  EXPECT_DOUBLE_EQ(s.dx_mm, 0.1);
  EXPECT_DOUBLE_EQ(s.dy_mm, 0.2);
  EXPECT_NEAR(s.contact_area_mm2, s.cells_in_contact * 0.02, 1e-15);
  EXPECT_TRUE(s.contact_at_y_edge);  // a straight roller loads its end rows
  EXPECT_FALSE(s.contact_at_x_edge);
}

// ---- Hard cases ----------------------------------------------------------------------------

TEST(ContactHardCases, SingleTouchingCellCarriesTheWholeLoad) {
  // One cell at zero gap, all others 1 mm away: the load goes through that cell alone and the
  // approach is its own displacement, p·K₀₀/E*.
  const Grid g = CenteredGrid(9, 7, 0.45, 0.35);
  std::vector<double> h(g.cells(), 1.0);
  const int centre = 3 * 9 + 4;
  h[centre] = 0.0;
  const double load = 5.0;
  for (bool dense : {false, true}) {
    const auto s = dense ? SolveDenseForLoad(g, h, load, kEStar)
                         : HalfSpaceSolver().SolveForLoad(g, h, load, kEStar);
    ASSERT_TRUE(s.converged) << s.message;
    EXPECT_EQ(s.cells_in_contact, 1);
    EXPECT_EQ(s.max_pressure_cell, centre);
    const double p = load / g.cell_area_mm2();
    EXPECT_NEAR(s.pressure_MPa[centre], p, 1e-12 * p);
    EXPECT_NEAR(s.approach_mm, p * LoveInfluence(0.0, 0.0, 0.05, 0.05) / kEStar, 1e-12);
  }
}

TEST(ContactHardCases, BarelyTouchingSphereLoadsOneCell) {
  // Odd grid: a cell centre sits under the sphere's tip. A load far below what reaches the
  // neighbours' gap leaves a single cell in contact.
  const Grid g = HertzGrid(41);
  const auto s = HalfSpaceSolver().SolveForLoad(g, SphereGap(g, 10.0), 1e-6, kEStar);
  ASSERT_TRUE(s.converged) << s.message;
  EXPECT_TRUE(AllFinite(s));
  EXPECT_EQ(s.cells_in_contact, 1);
  EXPECT_EQ(s.max_pressure_cell, 20 * 41 + 20);
  EXPECT_NEAR(s.load_N, 1e-6, 1e-15);
}

TEST(ContactHardCases, ZeroLoadGivesZeroPressureAndTouchingApproach) {
  const Grid g = HertzGrid(16);
  auto h = SphereGap(g, 10.0);
  for (double& v : h) v += 0.01;
  HalfSpaceSolver solver;
  for (double load : {0.0, -3.0}) {
    for (bool dense : {false, true}) {
      const auto s = dense ? SolveDenseForLoad(g, h, load, kEStar)
                           : solver.SolveForLoad(g, h, load, kEStar);
      EXPECT_TRUE(s.converged);
      EXPECT_TRUE(AllFinite(s));
      EXPECT_EQ(s.cells_in_contact, 0);
      EXPECT_EQ(s.load_N, 0.0);
      EXPECT_EQ(s.max_pressure_cell, -1);
      EXPECT_DOUBLE_EQ(s.approach_mm, *std::min_element(h.begin(), h.end()));
      EXPECT_EQ(s.message.empty(), load == 0.0);
    }
  }
}

TEST(ContactHardCases, GapThatNeverClosesUnderApproachControl) {
  const Grid g = HertzGrid(16);
  auto h = SphereGap(g, 10.0);
  for (double& v : h) v += 0.01;  // the closest point is 10 µm away
  HalfSpaceSolver solver;
  for (double approach : {-1.0, 0.0, 0.005, 0.01}) {
    const auto s = solver.SolveForApproach(g, h, approach, kEStar);
    EXPECT_TRUE(s.converged);
    EXPECT_TRUE(s.message.empty());
    EXPECT_EQ(s.load_N, 0.0);
    EXPECT_EQ(s.cells_in_contact, 0);
    EXPECT_EQ(s.approach_mm, approach);
    const auto d = SolveDenseForApproach(g, h, approach, kEStar);
    EXPECT_EQ(d.load_N, 0.0);
  }
  // A deep approach fills the grid, finite.
  const auto deep = solver.SolveForApproach(g, h, 10.0, kEStar);
  EXPECT_TRUE(deep.converged);
  EXPECT_TRUE(AllFinite(deep));
  EXPECT_EQ(deep.cells_in_contact, g.cells());
  // Just past touching, a little load appears.
  const auto s = solver.SolveForApproach(g, h, 0.0101, kEStar);
  EXPECT_GT(s.load_N, 0.0);
  EXPECT_TRUE(AllFinite(s));
}

TEST(ContactHardCases, HugeLoadFillsTheGridAndStaysFinite) {
  const Grid g = HertzGrid(24);
  const auto h = SphereGap(g, 10.0);
  for (double load : {1e6, 1e12, 1e30}) {
    const auto s = HalfSpaceSolver().SolveForLoad(g, h, load, kEStar);
    ASSERT_TRUE(s.converged) << s.message;
    EXPECT_TRUE(AllFinite(s));
    EXPECT_NEAR(s.load_N, load, 1e-9 * load);
    EXPECT_EQ(s.cells_in_contact, g.cells());
    EXPECT_TRUE(s.contact_at_x_edge);
    EXPECT_TRUE(s.contact_at_y_edge);
  }
}

TEST(ContactHardCases, TinyLoadsGoThroughOneFiniteCell) {
  // At tiny loads a single cell (the grid has a cell centred under the tip) carries the load,
  // p = W/(dx dy), with no underflow to zero or NaN.
  const Grid g = HertzGrid(21);
  const auto h = SphereGap(g, 10.0);
  HalfSpaceSolver solver;
  for (double load : {1e-12, 1e-30}) {
    const auto s = solver.SolveForLoad(g, h, load, kEStar);
    ASSERT_TRUE(s.converged);
    EXPECT_TRUE(AllFinite(s));
    EXPECT_NEAR(s.max_pressure_MPa, load / g.cell_area_mm2(), 1e-9 * load / g.cell_area_mm2());
  }
}

TEST(ContactHardCases, FlatPunchIsFiniteWithEdgePeaks) {
  const Grid g = CenteredGrid(20, 20, 1.0, 1.0);
  const std::vector<double> h(g.cells(), 0.0);
  const auto s = HalfSpaceSolver().SolveForLoad(g, h, 1000.0, kEStar);
  ASSERT_TRUE(s.converged);
  EXPECT_TRUE(AllFinite(s));
  EXPECT_EQ(s.cells_in_contact, g.cells());
  // Corners carry more than the centre (the rigid punch's edge singularity).
  EXPECT_GT(s.pressure_MPa[0], 2.0 * s.pressure_MPa[10 * 20 + 10]);
}

TEST(ContactHardCases, IterationLimitIsReportedNotHidden) {
  const Grid g = HertzGrid(32);
  HalfSpaceSolver solver({1e-8, 2});
  const auto s = solver.SolveForLoad(g, SphereGap(g, 10.0), 100.0, kEStar);
  EXPECT_FALSE(s.converged);
  EXPECT_FALSE(s.message.empty());
  EXPECT_EQ(s.iterations, 2);
  EXPECT_TRUE(AllFinite(s));
  EXPECT_NEAR(s.load_N, 100.0, 1e-9 * 100.0);  // the load is met at every iteration
}

TEST(ContactHardCases, BadInputThrowsWithAClearMessage) {
  const Grid g = CenteredGrid(4, 4, 1.0, 1.0);
  const std::vector<double> h(16, 0.0);
  HalfSpaceSolver solver;
  auto expect_throw = [](auto&& call, const std::string& needle) {
    try {
      call();
      ADD_FAILURE() << "no exception, expected one mentioning " << needle;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  expect_throw([&] { solver.SolveForLoad(g, std::vector<double>(15, 0.0), 1.0, kEStar); },
               "gap_mm has 15 entries");
  auto nan_gap = h;
  nan_gap[5] = std::nan("");
  expect_throw([&] { solver.SolveForLoad(g, nan_gap, 1.0, kEStar); }, "gap_mm[5]");
  expect_throw([&] { solver.SolveForLoad(g, h, std::nan(""), kEStar); }, "load_N");
  expect_throw([&] { solver.SolveForApproach(g, h, kInf, kEStar); }, "approach_mm");
  expect_throw([&] { solver.SolveForLoad(g, h, 1.0, 0.0); }, "E*");
  expect_throw([&] { SolveDenseForLoad(g, h, 1.0, -5.0); }, "E*");
  Grid bad = g;
  bad.dx = 0;
  expect_throw([&] { solver.SolveForLoad(bad, h, 1.0, kEStar); }, "cell sizes");
  bad = g;
  bad.nx = 0;
  expect_throw([&] { solver.SolveForLoad(bad, {}, 1.0, kEStar); }, "at least one cell");
  expect_throw([&] { CenteredGrid(3, 3, -1.0, 1.0); }, "cell sizes");
  const Grid big = CenteredGrid(65, 64, 1.0, 1.0);
  expect_throw([&] { SolveDenseForLoad(big, std::vector<double>(big.cells(), 0.0), 1.0, kEStar); },
               "exceed its limit");
}

}  // namespace contact_half_space_test
}  // namespace camopt::contact

namespace camopt::contact {
namespace contact_half_space_test {

TEST(HalfSpaceSensitivity, MatchesCentralDifferencesOfTheLoadControlledSolve) {
  // A crowned roller on a 24 x 24 grid: the gap depends on s through a crown scale and a tilt, the
  // load through dW/ds. The frozen-set sensitivity against central differences of full solves.
  const Grid g = CenteredGrid(24, 24, 0.3, 6.0);
  auto gap = [&](double s) {
    std::vector<double> h(size_t(g.cells()));
    for (int iy = 0; iy < g.ny; ++iy)
      for (int ix = 0; ix < g.nx; ++ix) {
        const double x = g.x_centre_mm(ix), y = g.y_centre_mm(iy);
        h[size_t(iy) * g.nx + ix] = x * x / (2 * 5.0) * (1.0 + 0.3 * s) + (1.0 + s) * 2e-4 * y * y + s * 1e-4 * y;
      }
    return h;
  };
  auto load = [](double s) { return 1500.0 + 400.0 * s; };
  HalfSpaceSolver solver(SolverOptions{1e-13, 5000});
  const double e_star = 113000.0;
  const ContactSolution base = solver.SolveForLoad(g, gap(0.0), load(0.0), e_star);
  ASSERT_TRUE(base.converged);
  const double h = 1e-5;
  const std::vector<double> g0 = gap(0.0), g1 = gap(1.0);
  std::vector<double> dgap(g0.size());
  for (size_t k = 0; k < g0.size(); ++k) dgap[k] = g1[k] - g0[k];  // linear in s
  const HalfSpaceSolver::Sensitivity d = solver.SensitivityForLoad(g, base.pressure_MPa, dgap, 400.0, e_star);
  ASSERT_TRUE(d.converged);
  const ContactSolution plus = solver.SolveForLoad(g, gap(h), load(h), e_star);
  const ContactSolution minus = solver.SolveForLoad(g, gap(-h), load(-h), e_star);
  ASSERT_EQ(plus.cells_in_contact, base.cells_in_contact);  // the set does not change over ±h
  ASSERT_EQ(minus.cells_in_contact, base.cells_in_contact);
  const double fd_approach = (plus.approach_mm - minus.approach_mm) / (2 * h);
  EXPECT_NEAR(d.approach_mm, fd_approach, 1e-5 * std::abs(fd_approach));
  double total = 0;
  for (double v : d.pressure_MPa) total += v * g.cell_area_mm2();
  EXPECT_NEAR(total, 400.0, 1e-8 * 400.0);
  const size_t peak = size_t(base.max_pressure_cell);
  for (size_t k : {peak, size_t(12 * 24 + 12), size_t(3 * 24 + 12)}) {
    const double fd = (plus.pressure_MPa[k] - minus.pressure_MPa[k]) / (2 * h);
    EXPECT_NEAR(d.pressure_MPa[k], fd, 1e-4 * std::abs(fd) + 1e-3) << k;
  }
}

TEST(HalfSpaceSensitivity, AStartChangesTheCostNotTheAnswer) {
  // The load sensitivity (dW = 1, dh = 0) of a crowned roller at 1500 N, started from itself, from
  // the one at 1000 N (a smaller contact set) and from a field of NaN: the same answer to the
  // CG's tolerance, the exact start converged at once, the unusable one ignored (same bits).
  const Grid g = CenteredGrid(24, 24, 0.3, 6.0);
  std::vector<double> gap(size_t(g.cells()));
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const double x = g.x_centre_mm(ix), y = g.y_centre_mm(iy);
      gap[size_t(iy) * g.nx + ix] = x * x / (2 * 5.0) + 2e-4 * y * y;
    }
  HalfSpaceSolver solver(SolverOptions{1e-12, 5000});
  const double e_star = 113000.0;
  const ContactSolution heavy = solver.SolveForLoad(g, gap, 1500.0, e_star);
  const ContactSolution light = solver.SolveForLoad(g, gap, 1000.0, e_star);
  ASSERT_TRUE(heavy.converged && light.converged);
  ASSERT_GT(heavy.cells_in_contact, light.cells_in_contact);
  const std::vector<double> zero(gap.size(), 0.0);
  const double tol = 1e-8;
  const auto plain = solver.SensitivityForLoad(g, heavy.pressure_MPa, zero, 1.0, e_star, tol);
  const auto from_light = solver.SensitivityForLoad(g, light.pressure_MPa, zero, 1.0, e_star, tol);
  ASSERT_TRUE(plain.converged && from_light.converged);
  const auto same = solver.SensitivityForLoad(g, heavy.pressure_MPa, zero, 1.0, e_star, tol, &plain.pressure_MPa);
  const auto near = solver.SensitivityForLoad(g, heavy.pressure_MPa, zero, 1.0, e_star, tol, &from_light.pressure_MPa);
  const std::vector<double> nan(gap.size(), std::nan(""));
  const auto bad = solver.SensitivityForLoad(g, heavy.pressure_MPa, zero, 1.0, e_star, tol, &nan);
  EXPECT_TRUE(same.converged && near.converged && bad.converged);
  EXPECT_EQ(same.iterations, 0);
  EXPECT_LE(near.iterations, plain.iterations);
  EXPECT_EQ(bad.iterations, plain.iterations);
  EXPECT_EQ(bad.approach_mm, plain.approach_mm);
  // The CG's residual tolerance 1e-8 bounds the answers' difference far below 1e-6.
  for (const auto* s : {&same, &near}) {
    EXPECT_NEAR(s->approach_mm, plain.approach_mm, 1e-6 * std::abs(plain.approach_mm));
    double total = 0, diff = 0, norm = 0;
    for (size_t k = 0; k < gap.size(); ++k) {
      total += s->pressure_MPa[k] * g.cell_area_mm2();
      diff = std::max(diff, std::abs(s->pressure_MPa[k] - plain.pressure_MPa[k]));
      norm = std::max(norm, std::abs(plain.pressure_MPa[k]));
    }
    EXPECT_NEAR(total, 1.0, 1e-10);
    EXPECT_LE(diff, 1e-6 * norm);
  }
}

TEST(HalfSpaceSensitivity, AdjointGivesEachFunctionalOfTheFixedLoadSensitivity) {
  // A crowned roller at 1500 N: for a peak-cell functional and a two-cell functional g, the adjoint
  // u = M g gives gᵀdp = −uᵀdh for every gap change dh at fixed load; checked against the forward
  // sensitivities of three unrelated gap changes (crown scale, tilt, a bump) and, for the peak,
  // against central differences of full solves at fixed load.
  const Grid g = CenteredGrid(24, 24, 0.3, 6.0);
  auto gap = [&](double crown, double tilt, double bump) {
    std::vector<double> h(size_t(g.cells()));
    for (int iy = 0; iy < g.ny; ++iy)
      for (int ix = 0; ix < g.nx; ++ix) {
        const double x = g.x_centre_mm(ix), y = g.y_centre_mm(iy);
        h[size_t(iy) * g.nx + ix] = x * x / (2 * 5.0) * (1.0 + crown) + 2e-4 * y * y + tilt * 1e-4 * y +
                                    bump * 1e-3 * std::exp(-(x - 0.05) * (x - 0.05) / 0.01 - y * y / 2.0);
      }
    return h;
  };
  HalfSpaceSolver solver(SolverOptions{1e-13, 5000});
  const double e_star = 113000.0, load = 1500.0;
  const ContactSolution base = solver.SolveForLoad(g, gap(0, 0, 0), load, e_star);
  ASSERT_TRUE(base.converged);
  const size_t peak = size_t(base.max_pressure_cell);
  std::vector<double> g_peak(size_t(g.cells()), 0.0), g_two(size_t(g.cells()), 0.0);
  g_peak[peak] = 1.0;
  g_two[peak] = 0.7;
  g_two[peak + 3 * g.nx] = -1.3;  // three rows off the peak, inside the contact
  ASSERT_GT(base.pressure_MPa[peak + 3 * g.nx], 0.0);
  const double tol = 1e-12;
  const std::vector<double> h0 = gap(0, 0, 0);
  for (const std::vector<double>* functional : {&g_peak, &g_two}) {
    const HalfSpaceSolver::Sensitivity u = solver.AdjointOfFunctional(g, base.pressure_MPa, *functional, e_star, tol);
    ASSERT_TRUE(u.converged);
    double sum_u = 0;
    for (double v : u.pressure_MPa) sum_u += v;
    EXPECT_NEAR(sum_u, 0.0, 1e-9 * std::abs(u.pressure_MPa[peak]));
    for (const auto& [crown, tilt, bump] : {std::tuple{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}) {
      const std::vector<double> h1 = gap(crown, tilt, bump);
      std::vector<double> dh(h0.size());
      for (size_t k = 0; k < dh.size(); ++k) dh[k] = h1[k] - h0[k];  // linear in each
      const auto dp = solver.SensitivityForLoad(g, base.pressure_MPa, dh, 0.0, e_star, tol);
      ASSERT_TRUE(dp.converged);
      double forward = 0, adjoint = 0, scale = 0;
      for (size_t k = 0; k < dh.size(); ++k) {
        forward += (*functional)[k] * dp.pressure_MPa[k];
        adjoint -= u.pressure_MPa[k] * dh[k];
        scale = std::max(scale, std::abs(dp.pressure_MPa[k]));
      }
      EXPECT_NEAR(adjoint, forward, 1e-9 * scale) << crown << " " << tilt << " " << bump;
      if (functional == &g_peak && bump == 1.0) {
        // the bump's effect on the peak cell at fixed load by central differences of full solves
        const double s = 1e-5;
        const ContactSolution plus = solver.SolveForLoad(g, gap(0, 0, s), load, e_star);
        const ContactSolution minus = solver.SolveForLoad(g, gap(0, 0, -s), load, e_star);
        ASSERT_EQ(plus.cells_in_contact, base.cells_in_contact);
        ASSERT_EQ(minus.cells_in_contact, base.cells_in_contact);
        const double fd = (plus.pressure_MPa[peak] - minus.pressure_MPa[peak]) / (2 * s);
        EXPECT_NEAR(adjoint, fd, 1e-4 * std::abs(fd) + 1e-3);
      }
    }
  }
  EXPECT_THROW(solver.AdjointOfFunctional(g, base.pressure_MPa, {1.0}, e_star), std::invalid_argument);
}

}  // namespace contact_half_space_test
}  // namespace camopt::contact
