// Closed-form limits of the finite-length roller contact (docs/validation.md
// "Crowned rollers and 3D contact"): the straight roller's mid-length pressure against Hertz line
// contact as the roller lengthens (extrapolated in 1/ln(l/b)), the circular crown against the Hertz
// ellipse with the resolution refined in both fidelities, the logarithmic crown's design formula
// (Lundberg's coefficient from the model's own influence operator; the end drop), and AD of the
// circular / partial crowns. Numbers printed, asserted with margins.
#include <algorithm>
#include <array>
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
namespace contact_roller_limits_test {

constexpr double kEStar = 115384.6;  // steel on steel [MPa]

/// Value at x = 0 of the parabola through three points (x_i, r_i) (Newton form).
double ExtrapolateToZero(const std::array<double, 3>& x, const std::array<double, 3>& r) {
  const double d01 = (r[1] - r[0]) / (x[1] - x[0]), d12 = (r[2] - r[1]) / (x[2] - x[1]);
  const double d012 = (d12 - d01) / (x[2] - x[0]);
  return r[0] + d01 * (0 - x[0]) + d012 * (0 - x[0]) * (0 - x[1]);
}

double MidPressure(const std::vector<double>& p) {
  const size_t n = p.size();
  return 0.5 * (p[n / 2 - 1] + p[n / 2]);
}

TEST(RollerSlices, StraightRollerMidPressureExtrapolatesToHertzLine) {
  // q = F/l = 500 N/mm, R' = 5 mm (b = 0.166 mm); l/b = 1.2e3 … 1.2e6. A finite straight roller's
  // ends carry more than F/l, the mid-length less: for a slender strip the displacement of a
  // uniform line load is (q/(π E*)) [2 ln(l/b) + ln(1 − (2y/l)²) + c], so the relative deficit of
  // the mid-length line load falls as 1/ln(l/b). The mid-length pressure / Hertz line of F/l is
  // extrapolated to l/b → ∞ by a parabola in 1/ln(l/b) through three lengths; the error estimate
  // is the change when the three lengths shift by a decade and when the slices double.
  const double rp = 5, q = 500;
  const double b = LineContactHalfWidth(q, 1.0, rp, kEStar);
  const std::array<double, 4> lb{1.2e3, 1.2e4, 1.2e5, 1.2e6};
  double limit_fine = 0, limit_coarse = 0, limit_shifted = 0;
  for (int n : {320, 640}) {
    std::array<double, 4> x{}, r{};
    for (size_t i = 0; i < lb.size(); ++i) {
      const double l = lb[i] * b, f = q * l;
      SliceOptions o;
      o.slices = n;
      const auto s = SolveRollerSlices<double>(f, rp, l, kEStar, [](double) { return 0.0; }, o);
      ASSERT_TRUE(s.converged);
      x[i] = 1 / std::log(lb[i]);
      r[i] = MidPressure(s.pressure_MPa) / LineContactPeakPressure(f, l, rp, kEStar);
      std::printf("straight, %d slices, l/b %.1e: p_mid / Hertz line(F/l) = %.5f\n", n, lb[i], r[i]);
      EXPECT_LT(r[i], 1.0);
      if (i > 0) {
        EXPECT_GT(r[i], r[i - 1]);
      }
    }
    const double upper = ExtrapolateToZero({x[1], x[2], x[3]}, {r[1], r[2], r[3]});
    const double lower = ExtrapolateToZero({x[0], x[1], x[2]}, {r[0], r[1], r[2]});
    std::printf("  extrapolated to l/b -> inf: %.5f (lengths 1.2e4..1.2e6), %.5f (1.2e3..1.2e5)\n", upper, lower);
    if (n == 640) {
      limit_fine = upper;
      limit_shifted = lower;
    } else {
      limit_coarse = upper;
    }
  }
  const double error = std::max(std::abs(limit_fine - limit_shifted), std::abs(limit_fine - limit_coarse));
  std::printf("limit %.5f +- %.5f\n", limit_fine, error);
  EXPECT_LT(error, 0.005);
  EXPECT_NEAR(limit_fine, 1.0, 0.01 - error);
}

TEST(RollerHalfSpace, StraightRollerMidPressureAgainstHertzLineAndTheSlices) {
  // l/b = 120 and 1200: the half_space mid-length pressure against Hertz line of F/l with the grid
  // refined across (nx: the cell-centred sample of the semi-ellipse sits dx/2 off its top) and
  // along (ny); the same deficit as the slices model (it is the finite length, not the grid).
  const double rp = 5, q = 500;
  const double b = LineContactHalfWidth(q, 1.0, rp, kEStar);
  HalfSpaceSolver solver;
  for (double lb : {120.0, 1200.0}) {
    const double l = lb * b, f = q * l, line = LineContactPeakPressure(f, l, rp, kEStar);
    std::vector<double> ratios;
    for (auto [nx, ny] : {std::pair{32, 256}, std::pair{64, 256}, std::pair{64, 1024}}) {
      const auto h = SolveRollerHalfSpace(f, rp, l, kEStar, [](double) { return 0.0; }, nx, ny, 0, solver);
      ASSERT_TRUE(h.converged) << h.message;
      ratios.push_back(MidPressure(h.pressure_along_y) / line);
      std::printf("half_space l/b %.0f %dx%d (dx %.4f dy %.4f mm): p_mid / Hertz line(F/l) %.5f\n", lb, nx, ny, h.dx_mm,
                  h.dy_mm, ratios.back());
    }
    SliceOptions o;
    o.slices = 640;
    const auto s = SolveRollerSlices<double>(f, rp, l, kEStar, [](double) { return 0.0; }, o);
    const double sl = MidPressure(s.pressure_MPa) / line;
    std::printf("  slices 640: %.5f (%+.2f%% vs half_space 64x1024)\n", sl, 100 * (sl / ratios.back() - 1));
    EXPECT_GT(ratios[1], ratios[0]);                      // the peak sample approaches the top
    EXPECT_LT(std::abs(ratios[2] / ratios[1] - 1), 0.001);  // ny does not move the mid-length
    EXPECT_LT(std::abs(sl / ratios.back() - 1), 0.01);
    EXPECT_LT(ratios.back(), 1.0);
  }
}

TEST(RollerContact, CircularCrownIsHertzEllipticalInBothFidelitiesAsTheResolutionRefines) {
  const double f = 2000, rp = 5, l = 20, rc = 300;
  const EllipticalContact e = EllipticalPointContact(f, rp, rc, kEStar);
  ASSERT_LT(e.semi_axis_y, 0.5 * l);
  const auto gap = [&](double y) { return CrowningDrop<double>(CrowningType::kCircular, rc, 0.0, 0.0, 0.0, y); };
  std::vector<double> sl, hs;
  for (int n : {40, 80, 160, 320}) {
    SliceOptions o;
    o.slices = n;
    const auto s = SolveRollerSlices<double>(f, rp, l, kEStar, gap, o);
    ASSERT_TRUE(s.converged);
    EXPECT_FALSE(s.edge_loaded);
    sl.push_back(s.peak_pressure);
    std::printf("circular crown, slices %d (w %.4f mm): peak %.2f MPa, Hertz ellipse %.2f (%+.2f%%)\n", n, s.slice_width,
                s.peak_pressure, e.peak_pressure, 100 * (s.peak_pressure / e.peak_pressure - 1));
    EXPECT_NEAR(s.peak_pressure, e.peak_pressure, 0.02 * e.peak_pressure);
  }
  HalfSpaceSolver solver;
  for (auto [nx, ny] : {std::pair{32, 128}, std::pair{64, 256}, std::pair{128, 512}}) {
    const auto h = SolveRollerHalfSpace(f, rp, l, kEStar, gap, nx, ny, e.semi_axis_x, solver);
    ASSERT_TRUE(h.converged) << h.message;
    EXPECT_FALSE(h.edge_loaded);
    hs.push_back(h.peak_pressure_MPa);
    std::printf("circular crown, half_space %dx%d (dx %.4f dy %.4f mm): peak %.2f MPa (%+.3f%%)\n", nx, ny, h.dx_mm,
                h.dy_mm, h.peak_pressure_MPa, 100 * (h.peak_pressure_MPa / e.peak_pressure - 1));
    EXPECT_NEAR(h.peak_pressure_MPa, e.peak_pressure, 0.02 * e.peak_pressure);
  }
  // Converged: the last refinement moves each by less than 0.5%.
  EXPECT_LT(std::abs(sl[3] / sl[2] - 1), 0.005);
  EXPECT_LT(std::abs(hs[2] / hs[1] - 1), 0.005);
}

// The solver's columns (one SmoothIntegral per distance, edges at (m ± 1/2) w) against Influence
// per entry, whose edges are |y_i - y_j| ± w/2: the same coefficients up to the rounding of the
// edge positions, over half-widths from the series branch (b/far < 0.15) to past the split (b/near
// > 1), in double and in Jet<1> (the Newton Jacobian's derivative in b).
TEST(RollerSlices, ColumnFromEdgeIntegralsEqualsInfluencePerEntry) {
  constexpr double kRelTol = 1e-13;
  using J1 = ceres::Jet<double, 1>;
  const int n = 20;
  const double w = 0.5;
  for (double b : {0.01, 0.06, 0.2, 0.3, 0.9}) {
    std::vector<double> edge;
    std::vector<J1> edge1;
    for (int j : {0, 7, n - 1}) {
      const int count = std::max(j, n - 1 - j) + 1;
      slices_detail::EdgeIntegrals(b, w, count, edge);
      slices_detail::EdgeIntegrals(J1(b, 0), w, count, edge1);
      for (int i = 0; i < n; ++i) {
        const double offset = (i - j) * w;
        const double ref = slices_detail::Influence(offset, w, b, kEStar);
        const J1 ref1 = slices_detail::Influence(J1(offset), J1(w), J1(b, 0), kEStar);
        const double far_log = slices_detail::FarLog(offset, w);
        const double c = slices_detail::InfluenceFromEdges(std::abs(i - j), w, b, kEStar, far_log, edge);
        const J1 c1 = slices_detail::InfluenceFromEdges(std::abs(i - j), w, J1(b, 0), kEStar, J1(far_log), edge1);
        EXPECT_NEAR(c, ref, kRelTol * std::abs(ref)) << b << " " << i << " " << j;
        EXPECT_NEAR(c1.a, ref1.a, kRelTol * std::abs(ref1.a)) << b << " " << i << " " << j;
        EXPECT_NEAR(c1.v[0], ref1.v[0], kRelTol * std::abs(ref1.v[0]) + 1e-300) << b << " " << i << " " << j;
      }
    }
  }
}

TEST(RollerContact, LogarithmicCrownDesignFormula) {
  // R' 5, l 20, F 10 kN (l/b = 120). (1) The coefficient: the gap that lets a uniform line load
  // q = F/l close the contact is u(0) − u(y), u from the model's own influence operator (400
  // slices); over |y| <= 0.375 l it equals f_L ln(1/(1 − (2y/l)²)), f_L = F/(π l E*) (Lundberg):
  // 2 f_L is not the right coefficient. (2) The end: the needed drop at the end slice is finite
  // (≈ f_L (ln(l/b) + c)); Le = 1.01 l gives less (end loaded, singular), Johns–Gohar's effective
  // length Le = l / sqrt(1 − 0.3033 · 2b/l) about the needed value. (3) half_space on converged grids.
  const double f = 10000, rp = 5, l = 20;
  const double b = LineContactHalfWidth(f, l, rp, kEStar), fl = LundbergCoefficient(f, l, kEStar);
  const double le_jg = l / std::sqrt(1 - 0.3033 * 2 * b / l);
  const auto log_drop = [](double y, double le) { return -std::log(1 - std::pow(2 * y / le, 2)); };
  {
    const int n = 400;
    const double w = l / n, q = f / l;
    std::vector<double> u(n, 0.0);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) u[i] += slices_detail::Influence((i - j) * w, w, b, kEStar) * q;
    for (int i = 25; i < n / 2; i += 25) {  // |y| <= 0.375 l
      const double y = (i + 0.5 - 0.5 * n) * w;
      EXPECT_NEAR((u[n / 2] - u[i]) / fl, log_drop(y, l), 0.002 * log_drop(y, l) + 1e-4) << y;
    }
    const double y0 = (0.5 - 0.5 * n) * w, need = (u[n / 2] - u[0]) / fl;
    std::printf("log crown: b %.4f mm, f_L %.6f mm; end-slice drop / f_L: needed %.3f, Le = 1.01 l %.3f, Le_JG = "
                "%.5f l %.3f\n", b, fl, need, log_drop(y0, 1.01 * l), le_jg / l, log_drop(y0, le_jg));
    EXPECT_LT(log_drop(y0, 1.01 * l), 0.85 * need);
    EXPECT_NEAR(log_drop(y0, le_jg), need, 0.03 * need);
  }
  HalfSpaceSolver solver;
  struct Design {
    const char* name;
    double k, le;
  };
  for (const Design d : {Design{"f_L, Le 1.01 l", 1.0, 1.01 * l}, Design{"2 f_L, Le 1.01 l", 2.0, 1.01 * l},
                         Design{"f_L, Le_JG", 1.0, le_jg}}) {
    std::vector<double> ratio, inner;
    for (int ny : {512, 1024, 2048}) {
      const auto h = SolveRollerHalfSpace(f, rp, l, kEStar, [&](double y) {
        return CrowningDrop<double>(CrowningType::kLogarithmic, 0.0, 0.0, d.k * fl, d.le, y);
      }, 32, ny, 0, solver);
      ASSERT_TRUE(h.converged) << h.message;
      const double mid = MidPressure(h.pressure_along_y);
      const double peak = *std::max_element(h.pressure_along_y.begin(), h.pressure_along_y.end());
      ratio.push_back(peak / mid);
      inner.push_back(h.pressure_along_y[int(0.95 * ny)] / mid);  // y ≈ 0.45 l
      std::printf("log crown %s, half_space 32x%d (dy %.4f mm): p_max/p_mid %.4f, p(0.45 l)/p_mid %.4f, end row %.4f\n",
                  d.name, ny, h.dy_mm, ratio.back(), inner.back(), h.pressure_along_y.back() / mid);
    }
    if (d.k == 1.0 && d.le == 1.01 * l) {  // end loaded, singular: grows with every refinement
      EXPECT_GT(ratio[1], 1.2 * ratio[0]);
      EXPECT_GT(ratio[2], 1.2 * ratio[1]);
    } else if (d.k == 2.0) {  // off the ends, the middle is the peak, but the pressure falls by 9% at 0.45 l
      EXPECT_LE(ratio[2], 1.1);
      EXPECT_LT(inner[2], 0.93);
      EXPECT_LT(std::abs(inner[2] / inner[1] - 1), 0.005);
    } else {  // converged (< 0.5% per halving of dy): flat to 0.3% over 0.45 l, a peak 0.2 b from the end
      EXPECT_LT(std::abs(ratio[2] / ratio[1] - 1), 0.005);
      EXPECT_NEAR(inner[2], 1.0, 0.01);
      EXPECT_GT(ratio[2], 1.1);  // the p_max/p_mid <= 1.1 is not met by this formula
      EXPECT_LT(ratio[2], 1.2);
    }
  }
}

TEST(RollerContact, LogarithmicCrownDesignedForItsLoadIsFlat) {
  // The requirement: "a logarithmic crown designed for its load gives a nearly flat pressure along the
  // length (p_max / p_mid <= 1.1 with half_space on a converged grid)". The design rule, stated
  // before any number is seen: Fujiwara & Kawase's criterion (the crown that minimises the peak
  // pressure at the design load) on Lundberg's form with the Johns–Gohar effective length, over
  // the load coefficient K1 of f = K1 F/(π l E*) (DesignLogCrownForLoad, on a 32 × 512 grid). The
  // designed crown is then re-solved on finer grids. Same contact as above: R' 5, l 20, F 10 kN.
  const double f = 10000, rp = 5, l = 20;
  const double b = LineContactHalfWidth(f, l, rp, kEStar), fl = LundbergCoefficient(f, l, kEStar);
  const double le_jg = l / std::sqrt(1 - 0.3033 * 2 * b / l);
  HalfSpaceSolver solver;
  const LogCrownDesign d = DesignLogCrownForLoad(f, rp, l, kEStar, le_jg, 32, 512, 1.0, 2.0, 0.002, solver);
  std::printf("log crown designed for 10 kN: K1 %.4f, f %.6f mm (f_L %.6f), peak %.1f MPa on 32x512, %d solves\n",
              d.k1, d.coefficient_mm, fl, d.peak_pressure_MPa, d.solves);
  EXPECT_GT(d.k1, 1.0 + 0.002);  // interior: Lundberg's K1 = 1 leaves the end peak (test above)
  EXPECT_LT(d.k1, 2.0 - 0.002);
  std::vector<double> ratio;
  for (const std::array<int, 2> g : {std::array<int, 2>{32, 1024}, std::array<int, 2>{32, 2048}, std::array<int, 2>{64, 2048}}) {
    const int ny = g[1];
    const auto h = SolveRollerHalfSpace(f, rp, l, kEStar, [&](double y) {
      return CrowningDrop<double>(CrowningType::kLogarithmic, 0.0, 0.0, d.coefficient_mm, le_jg, y);
    }, g[0], ny, 0, solver);
    ASSERT_TRUE(h.converged) << h.message;
    const double mid = MidPressure(h.pressure_along_y);
    const double peak = *std::max_element(h.pressure_along_y.begin(), h.pressure_along_y.end());
    double lo = peak, hi = 0;  // over |y| <= 0.45 l
    for (int i = 0; i < ny; ++i)
      if (std::abs(h.y_mm[i]) <= 0.45 * l) lo = std::min(lo, h.pressure_along_y[i]), hi = std::max(hi, h.pressure_along_y[i]);
    ratio.push_back(peak / mid);
    std::printf("designed log crown, half_space %dx%d (dx %.4f, dy %.4f mm): p_mid %.1f MPa, p_max/p_mid %.4f, "
                "over |y| <= 0.45 l p/p_mid in [%.4f, %.4f], end row %.4f, edge loaded %d\n",
                g[0], ny, h.dx_mm, h.dy_mm, mid, peak / mid, lo / mid, hi / mid, h.pressure_along_y.back() / mid,
                int(h.edge_loaded));
    EXPECT_LE(peak / mid, 1.1);                     // the bound
    EXPECT_GT(lo / mid, 0.95);                      // nearly flat: within 5% of the middle over 0.45 l
    EXPECT_LT(hi / mid, 1.05);
  }
  EXPECT_LT(std::abs(ratio[1] / ratio[0] - 1), 0.005);  // converged in dy
  EXPECT_LT(std::abs(ratio[2] / ratio[1] - 1), 0.005);  // and in dx
  // The slices model on the same crown: its peak against the half_space peak (issue: within 3%).
  SliceOptions o;
  o.slices = 160;
  const auto s = SolveRollerSlices<double>(f, rp, l, kEStar, [&](double y) {
    return CrowningDrop<double>(CrowningType::kLogarithmic, 0.0, 0.0, d.coefficient_mm, le_jg, y);
  }, o);
  ASSERT_TRUE(s.converged);
  std::printf("designed log crown, slices 160: peak %.1f MPa, p_max/p_mid %.4f (half_space peak %.1f MPa)\n",
              s.peak_pressure, s.peak_pressure / MidPressure(s.pressure_MPa), d.peak_pressure_MPa);
  EXPECT_NEAR(s.peak_pressure, d.peak_pressure_MPa, 0.03 * d.peak_pressure_MPa);
}

TEST(RollerSlices, CircularAndPartialCrownGradientsMatchCentralDifferences) {
  // x = (F, R', R, L0, γ [mrad]; scaled so that the central-difference step h = 6e-6 max(1, |x|) is
  // small against it): peak, approach, the slice loads at 1/4 and 1/2 of the length, with the
  // pattern inside the length (a contact set smaller than the roller: free slices at the ends).
  for (const CrowningType type : {CrowningType::kCircular, CrowningType::kPartial}) {
    auto fn = [type](const auto& x) {
      using T = std::decay_t<decltype(x[0])>;
      SliceOptions o;
      o.slices = 32;
      o.tolerance = 1e-13;
      const auto s = SolveRollerSlices<T>(x[0], x[1], T(20.0), kEStar, [&](const T& y) {
        return CrowningDrop<T>(type, x[2], x[3], T(0.0), T(0.0), y) + x[4] * T(1e-3) * y;
      }, o);
      return std::vector<T>{s.peak_pressure, s.approach * T(1000.0), s.line_load_N_per_mm[8],
                            s.line_load_N_per_mm[16]};
    };
    testing::ExpectJacobianMatchesCentralDifferences<5>(fn, {3000.0, 5.0, 300.0, 4.0, 0.2}, 1e-5, 1e-6);
  }
}

}  // namespace contact_roller_limits_test
}  // namespace camopt::contact
