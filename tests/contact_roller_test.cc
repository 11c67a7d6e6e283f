// Finite-length roller contact (model/contact/roller_slices.h, roller_half_space.h, crowning.h) and
// the elliptical Hertz contact (hertz.h): closed forms, convergence, AD versus central differences.
// The numbers behind docs/validation.md "Crowned rollers and 3D contact (LCR)".
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "model/contact/crowning.h"
#include "model/contact/hertz.h"
#include "model/contact/roller_half_space.h"
#include "model/contact/roller_slices.h"
#include "tests/test_util.h"

namespace camopt::contact {
namespace contact_roller_test {

constexpr double kEStar = 115384.6;  // steel on steel [MPa]

TEST(EllipticIntegrals, TableValues) {
  // Abramowitz & Stegun table 17.1 (m = 0.5): K = 1.8540746773, E = 1.3506438810.
  const CompleteEllipticIntegrals z = EllipticKE(0.0), h = EllipticKE(0.5);
  EXPECT_NEAR(z.k, kPi / 2, 1e-14);
  EXPECT_NEAR(z.e, kPi / 2, 1e-14);
  EXPECT_NEAR(h.k, 1.8540746773, 1e-9);
  EXPECT_NEAR(h.e, 1.3506438810, 1e-9);
}

TEST(EllipticalHertz, EqualRadiiIsCircularAndApproachIsBoussinesqOfThePressure) {
  const PointContact<double> c = CircularPointContact(1000.0, 10.0, kEStar);
  const EllipticalContact e = EllipticalPointContact(1000.0, 10.0, 10.0, kEStar);
  EXPECT_NEAR(e.peak_pressure, c.peak_pressure, 1e-9 * c.peak_pressure);
  // Independent: δ = (1/(π E*)) ∫∫ p/r dA at the centre; in polar coordinates the radial integral
  // of p0 sqrt(1 − r²/ρ²) is p0 ρ π/4, ρ(φ) the ellipse's radius. And F = (2/3) π a b p0.
  for (double ratio : {3.0, 30.0, 300.0}) {
    const EllipticalContact s = EllipticalPointContact(2000.0, 5.0, 5.0 * ratio, kEStar);
    double integral = 0;
    const int n = 4096;
    for (int i = 0; i < n; ++i) {
      const double phi = 2 * kPi * (i + 0.5) / n;
      const double rho = 1 / std::sqrt(std::pow(std::cos(phi) / s.semi_axis_x, 2) +
                                        std::pow(std::sin(phi) / s.semi_axis_y, 2));
      integral += kPi / 4 * rho * 2 * kPi / n;
    }
    EXPECT_NEAR(s.peak_pressure * integral / (kPi * kEStar), s.approach, 1e-6 * s.approach) << ratio;
    EXPECT_NEAR(2.0 / 3.0 * kPi * s.semi_axis_x * s.semi_axis_y * s.peak_pressure, 2000.0, 1e-6);
    EXPECT_GT(s.semi_axis_y, s.semi_axis_x);  // the long axis along the larger radius
  }
}

/// Crowning + misalignment gap along y for the tests.
template <typename T>
T Gap(CrowningType type, const T& radius, const T& coefficient, const T& le, const T& tilt, const T& y) {
  return CrowningDrop(type, radius, T(0.0), coefficient, le, y) + tilt * y;
}

TEST(RollerSlices, LongStraightRollerMidPressureIsHertzLineAndMatchesHalfSpace) {
  // R' = 5 mm, l = 20 mm, F = 10 kN: l/b = 120. Hertz line contact holds locally (the mid-length
  // strip is Hertz for its own line load, exactly in the slices model, and within 1% in the
  // half-space, contact_validation_test.cc); the mid-length line load is below F/l because the
  // ends carry more (the displacement of a uniform line load falls off as ln(1 − (2y/l)²) towards
  // the ends), in both models alike: mid-length pressure 4.6% below Hertz line of F/l.
  const double f = 10000, rp = 5, l = 20;
  SliceOptions o;
  o.slices = 160;
  const auto s = SolveRollerSlices<double>(f, rp, l, kEStar, [](double) { return 0.0; }, o);
  ASSERT_TRUE(s.converged);
  EXPECT_LT(s.residual, 1e-9);
  const double mid = 0.5 * (s.pressure_MPa[79] + s.pressure_MPa[80]);
  EXPECT_NEAR(mid, LineContactPeakPressure(s.line_load_N_per_mm[80], 1.0, rp, kEStar), 1e-9 * mid);
  HalfSpaceSolver solver;
  const auto h = SolveRollerHalfSpace(f, rp, l, kEStar, [](double) { return 0.0; }, 32, 256, 0, solver);
  const double mid_h = 0.5 * (h.pressure_along_y[127] + h.pressure_along_y[128]);
  const double line = LineContactPeakPressure(f, l, rp, kEStar);
  std::printf("straight: slices mid %.2f half-space mid %.2f line(F/l) %.2f\n", mid, mid_h, line);
  EXPECT_NEAR(mid, mid_h, 0.01 * mid_h);
  EXPECT_LT(mid, line);
  EXPECT_GT(mid, 0.94 * line);
  EXPECT_TRUE(s.edge_loaded);
  EXPECT_TRUE(h.edge_loaded);
  EXPECT_GT(s.peak_pressure, 1.2 * mid);  // the ends carry more
}

TEST(RollerSlices, StraightRollerMidPressureTendsToHertzLineAsTheRollerLengthens) {
  // The mid-length deficit against Hertz line of F/l falls as the roller lengthens (logarithmically:
  // 4.8%, 2.6%, 1.9% at l/b = 120, 1200, 12000 with 80 slices).
  const double rp = 5;
  double previous = 0;
  for (double l : {20.0, 200.0, 2000.0}) {
    const double f = 500.0 * l;  // 500 N/mm, b = 0.166 mm
    SliceOptions o;
    o.slices = 80;
    const auto s = SolveRollerSlices<double>(f, rp, l, kEStar, [](double) { return 0.0; }, o);
    const double ratio = 0.5 * (s.pressure_MPa[39] + s.pressure_MPa[40]) / LineContactPeakPressure(f, l, rp, kEStar);
    EXPECT_GT(ratio, previous);
    EXPECT_LT(ratio, 1.0);
    previous = ratio;
  }
  EXPECT_GT(previous, 0.98);
}

TEST(RollerSlices, StraightRollerEdgePeakGrowsWithResolution) {
  // The pressure at an abrupt end is singular: the end slice's peak grows as the slices shrink
  // (it must be reported with the slice width), the mid-length stays.
  double previous = 0;
  for (int n : {20, 40, 80, 160}) {
    SliceOptions o;
    o.slices = n;
    const auto s = SolveRollerSlices<double>(10000.0, 5.0, 20.0, kEStar, [](double) { return 0.0; }, o);
    EXPECT_TRUE(s.peak_slice == 0 || s.peak_slice == n - 1);
    EXPECT_GT(s.peak_pressure, 1.05 * previous);
    previous = s.peak_pressure;
  }
}

TEST(RollerSlices, CircularCrownInsideTheLengthIsHertzElliptical) {
  const double f = 2000, rp = 5, l = 20, rc = 300;
  const EllipticalContact e = EllipticalPointContact(f, rp, rc, kEStar);
  ASSERT_LT(e.semi_axis_y, 0.5 * l);
  SliceOptions o;
  o.slices = 80;
  const auto s = SolveRollerSlices<double>(f, rp, l, kEStar, [&](double y) {
    return Gap<double>(CrowningType::kCircular, rc, 0, 0, 0, y);
  }, o);
  ASSERT_TRUE(s.converged);
  std::printf("circular: slices %.2f hertz %.2f (a_y %.3f) iterations %d\n", s.peak_pressure, e.peak_pressure,
              e.semi_axis_y, s.iterations);
  EXPECT_NEAR(s.peak_pressure, e.peak_pressure, 0.02 * e.peak_pressure);
  EXPECT_FALSE(s.edge_loaded);
}

TEST(RollerHalfSpace, ClosedForms) {
  HalfSpaceSolver solver;
  const double rp = 5, l = 20;
  {  // circular crown
    const double f = 2000, rc = 300;
    const EllipticalContact e = EllipticalPointContact(f, rp, rc, kEStar);
    const auto h = SolveRollerHalfSpace(f, rp, l, kEStar, [&](double y) {
      return Gap<double>(CrowningType::kCircular, rc, 0, 0, 0, y);
    }, 64, 256, e.semi_axis_x, solver);
    std::printf("circular half-space: %.2f hertz %.2f dx %.4f dy %.4f\n", h.peak_pressure_MPa, e.peak_pressure,
                h.dx_mm, h.dy_mm);
    EXPECT_TRUE(h.converged);
    EXPECT_NEAR(h.peak_pressure_MPa, e.peak_pressure, 0.02 * e.peak_pressure);
    EXPECT_FALSE(h.edge_loaded);
  }
  {  // logarithmic crowns, Le = 1.01 l
    // Lundberg's coefficient f_L = F/(π l E*) for the load: uniform pressure over |y| < Le/2 on an
    // infinite roller, but the roller ends at l < Le with a finite drop, so the end stays loaded:
    // the end row's pressure grows as the grid refines (not converged, edge-loaded).
    // 2 f_L: the pressure leaves the ends (the end row's pressure falls as the grid refines) and is
    // nearly flat: p_max/p_mid <= 1.1 on every grid.
    const double f = 10000, le = 1.01 * l, lundberg = LundbergCoefficient(f, l, kEStar);
    double previous_end = 0;
    for (int ny : {128, 512}) {
      for (double k : {1.0, 2.0}) {
        const auto h = SolveRollerHalfSpace(f, rp, l, kEStar, [&](double y) {
          return Gap<double>(CrowningType::kLogarithmic, 0.0, k * lundberg, le, 0.0, y);
        }, 32, ny, 0, solver);
        const double mid = 0.5 * (h.pressure_along_y[ny / 2 - 1] + h.pressure_along_y[ny / 2]);
        const double peak = *std::max_element(h.pressure_along_y.begin(), h.pressure_along_y.end());
        const double at_04 = h.pressure_along_y[int(0.9 * ny)];  // y ≈ 0.4 l
        std::printf("log k %.0f ny %d: p_max/p_mid %.4f end %.1f p(0.4 l)/p_mid %.3f\n", k, ny, peak / mid,
                    h.pressure_along_y.back(), at_04 / mid);
        if (k == 1.0) {
          EXPECT_TRUE(h.edge_loaded);
          EXPECT_GT(peak / mid, 1.2);
        } else {
          EXPECT_LE(peak / mid, 1.1);
          EXPECT_GT(at_04 / mid, 0.9);
          if (ny == 512) {
            EXPECT_LT(h.pressure_along_y.back(), previous_end);
          }
          previous_end = h.pressure_along_y.back();
        }
      }
    }
  }
}

TEST(RollerSlices, GradientsMatchCentralDifferences) {
  // x = (F, R', l, f_log, γ): peak pressure, approach, the load of slice 5.
  auto fn = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    SliceOptions o;
    o.slices = 24;
    o.tolerance = 1e-13;
    const T le = T(1.1) * x[2];
    const auto s = SolveRollerSlices<T>(x[0], x[1], x[2], kEStar, [&](const T& y) {
      return Gap<T>(CrowningType::kLogarithmic, T(0.0), x[3], le, x[4], y);
    }, o);
    return std::vector<T>{s.peak_pressure, s.approach * T(1000.0), s.line_load_N_per_mm[5]};
  };
  testing::ExpectJacobianMatchesCentralDifferences<5>(fn, {8000.0, 5.0, 20.0, 0.002, 0.0003}, 1e-5, 1e-6);
}

}  // namespace contact_roller_test
}  // namespace camopt::contact

namespace camopt::contact {
namespace contact_roller_test {

// Convergence of the two fidelities on LCR II's worst output contact at 80 N·m (F = 835 N,
// R' = 2.02 mm, l = 8 mm, the example's crown f = 0.01 mm, Le = 10.5 mm): the numbers behind
// docs/validation.md "Crowned rollers and 3D contact" (times printed, never asserted).
TEST(RollerContactConvergence, SliceCountAndGridForStraightAndCrownedRollers) {
  const double f = 835.0, rp = 2.02, l = 8.0;
  HalfSpaceSolver solver;
  struct Case {
    const char* name;
    double coefficient, tilt;
  };
  for (const Case c : {Case{"straight", 0.0, 0.0}, Case{"crowned", 0.01, 0.0}, Case{"crowned 0.5 mrad", 0.01, 5e-4}}) {
    const auto gap = [&](const auto& y) {
      using T = std::decay_t<decltype(y)>;
      return Gap<T>(CrowningType::kLogarithmic, T(0.0), T(c.coefficient), T(10.5), T(c.tilt), y);
    };
    std::vector<double> slice_peaks, grid_peaks;
    for (int n : {10, 20, 40, 80, 160}) {
      SliceOptions o;
      o.slices = n;
      const auto t0 = std::chrono::steady_clock::now();
      const auto s = SolveRollerSlices<double>(f, rp, l, kEStar, gap, o);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      ASSERT_TRUE(s.converged);
      std::printf("%s slices %3d (w %.3f mm): peak %.1f MPa edge %d  %.2f ms\n", c.name, n, Value(s.slice_width),
                  s.peak_pressure, s.edge_loaded, ms);
      slice_peaks.push_back(s.peak_pressure);
    }
    for (auto [nx, ny] : {std::pair{24, 64}, std::pair{32, 128}, std::pair{48, 256}, std::pair{64, 512}}) {
      const auto t0 = std::chrono::steady_clock::now();
      const auto h = SolveRollerHalfSpace(f, rp, l, kEStar, gap, nx, ny, 0, solver);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      ASSERT_TRUE(h.converged) << h.message;
      std::printf("%s half_space %dx%d (dx %.4f dy %.4f mm): peak %.1f MPa edge %d  %.1f ms\n", c.name, nx, ny,
                  h.dx_mm, h.dy_mm, h.peak_pressure_MPa, h.edge_loaded, ms);
      grid_peaks.push_back(h.peak_pressure_MPa);
    }
    if (c.coefficient == 0) {  // edge peaks grow as the resolution refines (reported with w, dy)
      for (size_t i = 1; i < slice_peaks.size(); ++i) EXPECT_GT(slice_peaks[i], slice_peaks[i - 1]);
      for (size_t i = 1; i < grid_peaks.size(); ++i) EXPECT_GT(grid_peaks[i], grid_peaks[i - 1]);
    } else {  // converged, and the slices model (40 slices) within 3% of the finest grid
      const double fine = grid_peaks.back();
      EXPECT_LT(std::abs(grid_peaks[2] / fine - 1), 0.005);
      EXPECT_LT(std::abs(slice_peaks[3] / slice_peaks[4] - 1), 0.005);
      EXPECT_LT(std::abs(slice_peaks[2] / fine - 1), 0.03);
      std::printf("%s: slices(40) vs half_space(64x512): %+.2f%%\n", c.name, 100 * (slice_peaks[2] / fine - 1));
    }
  }
}

}  // namespace contact_roller_test
}  // namespace camopt::contact
