// Bearing life as a sizing limit of lcr_min_size (docs/life.md, "Life as a sizing limit"): the
// rating scaled with roller size against its ISO 281 closed form, the life rows' exact gradients
// against central differences, the rows against the dense computation of lcr_analysis, the sized
// design's lives through lcr_analysis, and bad input.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/common/bearing_life.h"
#include "model/lcr/life.h"
#include "objectives/lcr_min_size.h"
#include "objectives/lcr_sizing.h"
#include "tests/test_util.h"

namespace camopt {
namespace {

using camopt::testing::Example;
using camopt::testing::ReadFile;
using camopt::testing::RunCamopt;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;
using nlohmann::json;
using objectives::LcrSizingSpec;

// Central differences with step h = ∛ε·max(1, |x|) have truncation and rounding errors of order
// ε^(2/3) ≈ 4e-11 times the scale of the function's third derivative and values; the rows are
// O(1) (logarithms of life), so 1e-6 of max(1, |g|) leaves three decades for curvature.
constexpr double kLifeRowGradientTol = 1e-6;
// The rows sample each cam period at samples_per_period angles (every roller: 24·n samples over a
// roller's period), the dense check 3600 per input revolution; the trapezoidal rule on a load that
// leaves zero linearly errs by O(N^−13/3) in the p-mean (docs/life.md): below 1e-3 in ln L10h.
constexpr double kRowAgainstDenseLogTol = 1e-3;

// The ratio −90 example's best combination (12/13 + 14/15) with a life: two duty lines and an
// eccentric ball bearing; the roller's rating scales from a 10 mm × 10 mm reference roller.
LcrSizingSpec LifeSpec(bool same_roller) {
  LcrSizingSpec s;
  s.lobes_a = 12, s.rollers_a = 13, s.lobes_b = 14, s.rollers_b = 15;
  s.output_torque_Nmm = 80e3;
  s.friction_coefficient = 0.05;
  s.same_roller = same_roller;
  s.limits = {1500.0, 1050.0, 0.5, 1.0, 0.0, 20000.0};
  objectives::LcrLifeSpec life;
  life.lines = {{80e3, 1000.0, 0.7}, {40e3, 1500.0, 0.3}};
  life.roller = {5000.0, 5500.0, 10.0, 10.0};
  life.eccentric = objectives::LcrEccentricRating{true, 20000.0, 15000.0};
  s.life = life;
  return s;
}

TEST(LcrMinSizeLife, ScaledRatingsFollowIso281AndIso76) {
  // Twice the diameter at the same length: 2^(29/27) = 2.1087...; the length doubled: 2^(7/9).
  EXPECT_NEAR(ScaledDynamicRating(5000.0, 10.0, 10.0, 20.0, 10.0), 5000.0 * std::exp(29.0 / 27.0 * std::log(2.0)),
              1e-9);
  EXPECT_NEAR(ScaledDynamicRating(5000.0, 10.0, 10.0, 10.0, 20.0), 5000.0 * std::exp(7.0 / 9.0 * std::log(2.0)), 1e-9);
  EXPECT_NEAR(ScaledDynamicRating(5000.0, 10.0, 10.0, 10.0, 10.0), 5000.0, 1e-12);
  EXPECT_NEAR(ScaledStaticRating(5500.0, 10.0, 10.0, 5.0, 20.0), 5500.0, 1e-12);  // ½ · 2
  // A catalogue roller's rating is its own (no reference roller): not scaled.
  EXPECT_EQ(objectives::LcrRollerRatingAt(objectives::LcrRollerRating{3300.0, 3400.0, 0.0, 0.0}, 7.0, 9.0, false),
            3300.0);
}

TEST(LcrMinSizeLife, LifeRowGradientsMatchCentralDifferences) {
  for (bool same_roller : {true, false}) {
    SCOPED_TRACE(same_roller ? "one roller diameter" : "a roller diameter per cam");
    const LcrSizingSpec spec = LifeSpec(same_roller);
    const objectives::Problem p = objectives::MakeLcrSizingProblem(spec);
    const int n = p.num_vars(), m = p.evaluator->num_outputs();
    std::vector<int> rows;
    for (const auto& block : p.evaluator->blocks())
      if (block.name.size() > 5 && block.name.substr(block.name.size() - 5) == "_life") rows.push_back(block.offset);
    ASSERT_EQ(rows.size(), 3u);  // input roller, output roller, eccentric bearing
    for (const std::vector<double>& x : objectives::LcrStartingPoints(spec, 3)) {
      std::vector<double> y(m), jac(size_t(m) * n);
      p.evaluator->EvalWithJacobian(x, y, jac);
      for (int row : rows) ASSERT_TRUE(std::isfinite(y[row]));
      for (int i = 0; i < n; ++i) {
        const double h = std::cbrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, std::abs(x[i]));
        std::vector<double> xp = x, xm = x, yp(m), ym(m);
        xp[i] += h, xm[i] -= h;
        p.evaluator->Eval(xp, yp);
        p.evaluator->Eval(xm, ym);
        for (int row : rows) {
          const double fd = (yp[row] - ym[row]) / (2 * h), g = jac[size_t(row) * n + i];
          EXPECT_NEAR(g, fd, kLifeRowGradientTol * std::max(1.0, std::abs(fd)))
              << "row " << row << ", variable " << p.variables[i].name;
        }
      }
    }
  }
}

TEST(LcrMinSizeLife, RowsAgreeWithTheDenseLifeOfLcrAnalysis) {
  // The rows (every roller at 24 angles of the cam's period, torque-scaled lines) against the dense
  // check (roller 0 over its own period at 3600 steps per revolution, one force analysis per line
  // at its torque): two routes to ln(L10h / life_h).
  const LcrSizingSpec spec = LifeSpec(true);
  const objectives::Problem p = objectives::MakeLcrSizingProblem(spec);
  const std::vector<double> x = objectives::LcrStartingPoints(spec, 1).front();
  std::vector<double> y(p.evaluator->num_outputs());
  p.evaluator->Eval(x, y);
  const objectives::LcrDenseCheck c = objectives::DenseCheck(spec, objectives::LcrDesign(spec, x));
  ASSERT_EQ(c.life.size(), 3u);
  for (const auto& b : c.life) {
    int offset = -1;
    for (const auto& block : p.evaluator->blocks())
      if (block.name == b.name + "_life") offset = block.offset;
    ASSERT_GE(offset, 0) << b.name;
    EXPECT_NEAR(y[offset], std::log(b.life.L10h / spec.limits.life_h), kRowAgainstDenseLogTol) << b.name;
  }
  // The eccentric bearing turns n_A/m_A per input revolution (model/lcr/life.h).
  EXPECT_NEAR(c.life[2].life.revolutions_per_input_revolution, 13.0 / 12.0, 1e-12);
}
}  // namespace
}  // namespace camopt
