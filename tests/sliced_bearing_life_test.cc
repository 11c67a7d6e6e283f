// The sliced rating life of a roller bearing (model/common/sliced_bearing_life.h, docs/life.md
// "Sliced roller life under tilt"): a uniform load gives back ISO 281's life for any number of
// slices; a linearly varying load its closed form; the duty cycle as Palmgren–Miner per slice.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "model/common/bearing_life.h"
#include "model/common/sliced_bearing_life.h"

namespace camopt {
namespace sliced_bearing_life_test {

/// A few roundings of pow over the slices.
constexpr double kRelTol = 1e-12;

// One line, one sample: every slice carries loads[k].
SlicedDutyLine OneSample(const std::vector<double>& loads, double speed_rpm, double share = 1.0) {
  return {share, speed_rpm, {loads}, {1.0}};
}

TEST(SlicedLife, UniformLoadGivesBackTheUnslicedLife) {
  const double c = 12000, p = 3000, speed = 750;
  // ISO 281: L10h = 10⁶ (C/P)^(10/3) / (60 n).
  const double iso = 1e6 * std::pow(c / p, 10.0 / 3.0) / (60 * speed);
  for (int n : {1, 2, 7, 40}) {
    SCOPED_TRACE(n);
    const SlicedLife l = SlicedRatingLifeHours(c, {OneSample(std::vector<double>(n, p / n), speed)}, BearingKind::kRoller);
    EXPECT_NEAR(l.L10h, iso, kRelTol * iso);
    EXPECT_NEAR(l.slice_rating_N, c * std::pow(n, -7.0 / 9.0), kRelTol * c);
    EXPECT_NEAR(l.weibull_slope, 27.0 / 20.0, 1e-15);
  }
}

// Q_k = (P/N)(1 + a ξ_k) with ξ = −½, +½ (N = 2), a = ½: L/L_uniform = (mean (1 + a ξ)^(9/2))^(−20/27),
// i.e. ((0.75^4.5 + 1.25^4.5)/2)^(−20/27) (worked out: 0.75^4.5 = 0.2740159, 1.25^4.5 = 2.7295752,
// mean 1.5017955, ln 0.4066614, × −20/27 → e^−0.3012307 = 0.739907).
TEST(SlicedLife, LinearLoadMatchesItsClosedForm) {
  const double c = 12000, p = 3000, speed = 750;
  const double iso = 1e6 * std::pow(c / p, 10.0 / 3.0) / (60 * speed);
  const SlicedLife l = SlicedRatingLifeHours(c, {OneSample({0.75 * p / 2, 1.25 * p / 2}, speed)}, BearingKind::kRoller);
  EXPECT_NEAR(l.L10h / iso, 0.739907, 2e-6);
  const double closed = std::pow(0.5 * (std::pow(0.75, 4.5) + std::pow(1.25, 4.5)), -20.0 / 27.0);
  EXPECT_NEAR(l.L10h / iso, closed, kRelTol);
  EXPECT_EQ(l.worst_slice, 1);
  // Ten slices, a = 0.8: the same closed form over ξ_k = (2k + 1)/10 − 1.
  std::vector<double> q;
  double mean = 0;
  for (int k = 0; k < 10; ++k) {
    const double xi = (2 * k + 1) / 10.0 - 1;
    q.push_back(p / 10 * (1 + 0.8 * xi));
    mean += std::pow(1 + 0.8 * xi, 4.5) / 10;
  }
  const SlicedLife l10 = SlicedRatingLifeHours(c, {OneSample(q, speed)}, BearingKind::kRoller);
  EXPECT_NEAR(l10.L10h / iso, std::pow(mean, -20.0 / 27.0), kRelTol);
}

// An unloaded slice (an edge lifted by the tilt) adds nothing; all unloaded: +∞.
TEST(SlicedLife, UnloadedSlicesAndNoLoad) {
  const double c = 12000, p = 3000, speed = 750;
  const double iso_half = 1e6 * std::pow(c * std::pow(2.0, -7.0 / 9.0) / p, 10.0 / 3.0) / (60 * speed);
  const SlicedLife l = SlicedRatingLifeHours(c, {OneSample({p, 0.0}, speed)}, BearingKind::kRoller);
  EXPECT_NEAR(l.L10h, iso_half, kRelTol * iso_half);  // the loaded half alone, rated C 2^(−7/9)
  EXPECT_TRUE(std::isinf(l.slice_L10h[1]));
  EXPECT_TRUE(std::isinf(SlicedRatingLifeHours(c, {OneSample({0.0, 0.0}, speed)}, BearingKind::kRoller).L10h));
}

// Over a duty cycle each slice's life is Palmgren–Miner over the lines (and the samples of a line
// their revolution-weighted p-mean); a uniform load still gives back DutyCycleLifeHours.
TEST(SlicedLife, DutyCycleWithSamples) {
  const double c = 9000;
  const std::vector<double> f1 = {1000, 2500, 0, 1800}, w1 = {1.0, 0.5, 2.0, 1.0};
  const std::vector<double> f2 = {600, 900, 300, 0}, w2 = {1, 1, 1, 1};
  std::vector<DutyCycleLine<double>> plain = {{0.7, 1200, {EquivalentLoad(f1, w1, BearingKind::kRoller)}},
                                              {0.3, 400, {EquivalentLoad(f2, w2, BearingKind::kRoller)}}};
  const double unsliced = DutyCycleLifeHours(c, plain, BearingKind::kRoller);
  auto split = [](const std::vector<double>& f, int n) {
    std::vector<std::vector<double>> out;
    for (double x : f) out.push_back(std::vector<double>(n, x / n));
    return out;
  };
  const SlicedLife l = SlicedRatingLifeHours(c, {{0.7, 1200, split(f1, 5), w1}, {0.3, 400, split(f2, 5), w2}},
                                             BearingKind::kRoller);
  EXPECT_NEAR(l.L10h, unsliced, kRelTol * unsliced);
}

TEST(SlicedLife, BadInputThrows) {
  EXPECT_THROW(SlicedRatingLifeHours(1000, {}, BearingKind::kRoller), std::invalid_argument);
  EXPECT_THROW(SlicedRatingLifeHours(1000, {{1.0, 100, {{1.0, 2.0}, {1.0}}, {1.0, 1.0}}}, BearingKind::kRoller),
               std::invalid_argument);
}

}  // namespace sliced_bearing_life_test
}  // namespace camopt
