// Bearing life as a sizing limit of lcr_min_size (docs/life.md, "Life as a sizing limit"): the
// rating scaled with roller size against its ISO 281 closed form, the life rows' exact gradients
// against central differences, the rows against the dense computation of lcr_analysis, the sized
// design's lives through lcr_analysis, and bad input.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/common/bearing_life.h"
#include "model/lcr/cycle.h"
#include "model/lcr/life.h"
#include "sizing/lcr_min_size.h"
#include "objectives/lcr_dense_check.h"
#include "objectives/lcr_sizing.h"
#include "tests/test_util.h"

namespace camopt {
namespace lcr_min_size_life_test {

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
  // Twice the diameter at the same length: 2^(29/27) = 2.1054; the length doubled: 2^(7/9) = 1.7145.
  EXPECT_NEAR(ScaledDynamicRating(5000.0, 10.0, 10.0, 20.0, 10.0), 5000.0 * std::exp(29.0 / 27.0 * std::log(2.0)),
              1e-9);
  EXPECT_NEAR(ScaledDynamicRating(5000.0, 10.0, 10.0, 10.0, 20.0), 5000.0 * std::exp(7.0 / 9.0 * std::log(2.0)), 1e-9);
  EXPECT_NEAR(ScaledDynamicRating(5000.0, 10.0, 10.0, 10.0, 10.0), 5000.0, 1e-12);
  EXPECT_NEAR(ScaledStaticRating(5500.0, 10.0, 10.0, 5.0, 20.0), 5500.0, 1e-12);  // ½ · 2
  // A catalogue roller's rating is its own (no reference roller): not scaled.
  EXPECT_EQ(objectives::LcrRollerRatingAt(objectives::LcrRollerRating{3300.0, 3400.0, 0.0, 0.0}, 7.0, 9.0, false),
            3300.0);
}

// Each of `rows` of p's evaluator at x: its exact derivative (ceres::Jet) against central
// differences with step ∛ε·max(1, |x_i|), within kLifeRowGradientTol of max(1, |fd|).
void ExpectRowsMatchCentralDifferences(const objectives::Problem& p, const std::vector<double>& x,
                                       const std::vector<int>& rows) {
  const int n = p.num_vars(), m = p.evaluator->num_outputs();
  std::vector<double> y(m), jac(size_t(m) * n);
  p.evaluator->EvalWithJacobian(x, y, jac);
  for (int row : rows) ASSERT_TRUE(std::isfinite(y[row])) << "row " << row;
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

TEST(LcrMinSizeLife, LifeRowGradientsMatchCentralDifferences) {
  for (bool same_roller : {true, false}) {
    SCOPED_TRACE(same_roller ? "one roller diameter" : "a roller diameter per cam");
    const LcrSizingSpec spec = LifeSpec(same_roller);
    const objectives::Problem p = objectives::MakeLcrSizingProblem(spec);
    std::vector<int> rows;
    for (const auto& block : p.evaluator->blocks())
      if (block.name.size() > 5 && block.name.substr(block.name.size() - 5) == "_life") rows.push_back(block.offset);
    ASSERT_EQ(rows.size(), 3u);  // input roller, output roller, eccentric bearing
    for (const std::vector<double>& x : objectives::LcrStartingPoints(spec, 3))
      ExpectRowsMatchCentralDifferences(p, x, rows);
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

// The dense check keeps its last analyses per thread and reuses one only when the design, the
// angles, the load, the material, the lubrication and the duty cycle are all the same: a change of
// any of them gives the numbers of that input (each against the model function computed here), a
// change of the limits alone gives the same numbers judged against the new limits, and a check
// served from a kept analysis equals the one computed after the kept ones were pushed out.
TEST(LcrMinSizeLife, DenseChecksOfOneDesignUnderOtherInputsAreTheirOwn) {
  const LcrSizingSpec spec = LifeSpec(true);
  const std::vector<double> x = objectives::LcrStartingPoints(spec, 1).front();
  const lcr::Reducer<double> r = objectives::LcrDesign(spec, x);
  const int steps = 720;
  const objectives::LcrDenseCheck base = objectives::DenseCheck(spec, r, steps);
  ASSERT_EQ(base.life.size(), 3u);
  auto largest_force = [&](const LcrSizingSpec& s) {
    const lcr::CycleSeries c = lcr::AnalyzeCycle(r, s.material, {s.output_torque_Nmm, s.friction_coefficient, 0.0},
                                                 steps, lcr::Stages{});
    return std::max(*std::max_element(c.input.max_force_N.begin(), c.input.max_force_N.end()),
                    *std::max_element(c.output.max_force_N.begin(), c.output.max_force_N.end()));
  };
  EXPECT_EQ(std::max(base.max_force_N[0], base.max_force_N[1]), largest_force(spec));
  // Another torque: its own forces (the rigid law is linear in the torque).
  LcrSizingSpec torque = spec;
  torque.output_torque_Nmm *= 1.5;
  const objectives::LcrDenseCheck t = objectives::DenseCheck(torque, r, steps);
  EXPECT_EQ(std::max(t.max_force_N[0], t.max_force_N[1]), largest_force(torque));
  EXPECT_NEAR(t.max_force_N[0], 1.5 * base.max_force_N[0], 1e-9 * base.max_force_N[0]);
  // Another material: its own stresses (p ∝ √E* at the same forces).
  LcrSizingSpec soft = spec;
  soft.material.youngs_modulus_MPa /= 4;
  const objectives::LcrDenseCheck m = objectives::DenseCheck(soft, r, steps);
  EXPECT_NEAR(m.max_stress_MPa[0], 0.5 * base.max_stress_MPa[0], 1e-9 * base.max_stress_MPa[0]);
  // Another duty cycle: the lives of its lines.
  LcrSizingSpec duty = spec;
  duty.life->lines[1].output_torque_Nmm = 60e3;
  const objectives::LcrDenseCheck d = objectives::DenseCheck(duty, r, steps);
  const lcr::LcrBearingLife direct = lcr::BearingLifeOverDutyCycle(
      r, spec.material, {spec.output_torque_Nmm, spec.friction_coefficient, 0.0}, lcr::LoadModel::kRigid,
      lcr::LcrBearing::kEccentric, 20000.0, BearingKind::kBall, duty.life->lines, steps);
  EXPECT_EQ(d.life[2].life.L10h, direct.L10h);
  EXPECT_LT(d.life[2].life.L10h, base.life[2].life.L10h);
  // The limits alone: the same numbers, judged against the new limits.
  LcrSizingSpec strict = spec;
  strict.limits.roller_load_N = 0.5 * std::max(base.max_force_N[0], base.max_force_N[1]);
  strict.limits.life_h = 2 * base.shortest_L10h;
  const objectives::LcrDenseCheck l = objectives::DenseCheck(strict, r, steps);
  EXPECT_EQ(l.max_force_N, base.max_force_N);
  EXPECT_EQ(l.shortest_L10h, base.shortest_L10h);
  std::vector<std::string> broken;
  for (const auto& v : l.violations) broken.push_back(v.limit);
  EXPECT_NE(std::find(broken.begin(), broken.end(), "roller_load_N"), broken.end());
  EXPECT_NE(std::find(broken.begin(), broken.end(), "life_h"), broken.end());
  // The near samples: from a kept analysis (checked a moment ago under other limits) and from a
  // fresh one (after three other designs' checks pushed it out) alike.
  objectives::LcrActiveSet near_first, near_kept, near_fresh;
  LcrSizingSpec near_spec = spec;
  near_spec.limits.roller_load_N = 1.01 * std::max(base.max_force_N[0], base.max_force_N[1]);
  objectives::DenseCheck(spec, r, steps, &near_first);
  const objectives::LcrDenseCheck kept = objectives::DenseCheck(near_spec, r, steps, &near_kept);
  for (double e : {1.01, 1.02, 1.03}) {
    lcr::Reducer<double> other = r;
    other.eccentricity *= e;
    objectives::DenseCheck(spec, other, steps, &near_first);
  }
  const objectives::LcrDenseCheck fresh = objectives::DenseCheck(near_spec, r, steps, &near_fresh);
  EXPECT_EQ(kept.max_stress_MPa, fresh.max_stress_MPa);
  EXPECT_EQ(kept.life.size(), fresh.life.size());
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(near_kept.force[k], near_fresh.force[k]) << k;
    EXPECT_EQ(near_kept.stress[k], near_fresh.stress[k]) << k;
    EXPECT_FALSE(near_kept.force[k].empty()) << k;
  }
}

// The static rows (a momentary torque, LcrLimits::min_static_safety): exact derivatives, and values
// near the dense check's s0 at that torque. The rows' P0max is the log-sum-exp soft maximum of the
// sampled loads (above the largest sample by at most scale ln N / k) on 24 angles of each period,
// the check's the largest of 3600 per revolution.
LcrSizingSpec StaticSpec(bool same_roller) {
  LcrSizingSpec s = LifeSpec(same_roller);
  s.limits.min_static_safety = 1.5;
  s.limits.static_torque_Nmm = 200e3;
  return s;
}

TEST(LcrMinSizeLife, StaticRowGradientsMatchCentralDifferences) {
  for (bool same_roller : {true, false}) {
    SCOPED_TRACE(same_roller ? "one roller diameter" : "a roller diameter per cam");
    const LcrSizingSpec spec = StaticSpec(same_roller);
    const objectives::Problem p = objectives::MakeLcrSizingProblem(spec);
    std::vector<int> rows;
    for (const auto& block : p.evaluator->blocks())
      if (block.name.size() > 7 && block.name.substr(block.name.size() - 7) == "_static") rows.push_back(block.offset);
    ASSERT_EQ(rows.size(), 3u);  // input roller, output roller, eccentric bearing
    for (const std::vector<double>& x : objectives::LcrStartingPoints(spec, 3))
      ExpectRowsMatchCentralDifferences(p, x, rows);
  }
}

TEST(LcrMinSizeLife, StaticRowsAgreeWithTheDenseCheck) {
  const LcrSizingSpec spec = StaticSpec(true);
  const objectives::Problem p = objectives::MakeLcrSizingProblem(spec);
  for (const std::vector<double>& x : objectives::LcrStartingPoints(spec, 3)) {
    std::vector<double> y(p.evaluator->num_outputs());
    p.evaluator->Eval(x, y);
    const objectives::LcrDenseCheck c = objectives::DenseCheck(spec, objectives::LcrDesign(spec, x));
    double least = 1e300;
    for (const auto& b : c.life) {
      int offset = -1;
      for (const auto& block : p.evaluator->blocks())
        if (block.name == b.name + "_static") offset = block.offset;
      ASSERT_GE(offset, 0) << b.name;
      // The check's s0 at 200 N·m: its loads at the largest duty line (80 N·m) scaled by 200/80.
      const double s0 = b.static_rating_N / (b.life.max_load_N * 200.0 / 80.0);
      least = std::min(least, s0);
      const double dense_row = std::log(s0 / spec.limits.min_static_safety);
      std::printf("[ static   ] %s: row %.6f, dense %.6f\n", b.name.c_str(), y[offset], dense_row);
      EXPECT_LE(y[offset], dense_row + 2e-3) << b.name;  // the soft maximum errs on the safe side
      EXPECT_GE(y[offset], dense_row - 0.05) << b.name;  // by at most 5 % of the load here
    }
    EXPECT_NEAR(c.min_static_safety, least, 1e-12 * least);
    const bool named = std::any_of(c.violations.begin(), c.violations.end(),
                                   [](const auto& v) { return v.limit == "min_static_safety"; });
    EXPECT_EQ(named, c.min_static_safety < spec.limits.min_static_safety);  // the check's violation
  }
}

// Runs a study given as json in dir; returns result.json (null json on a non-zero exit).
json RunStudy(const json& study, const std::filesystem::path& dir, int* exit_code, std::string* stderr_text = nullptr) {
  const auto file = dir / "study.json";
  WriteFile(file, study.dump());
  const auto r = RunCamopt("run " + file.string() + " --out " + (dir / "out").string() + " --quiet");
  *exit_code = r.exit_code;
  if (stderr_text) *stderr_text = r.stderr_text;
  if (r.exit_code != 0) return json();
  return json::parse(ReadFile(dir / "out" / "result.json"));
}

// The ratio −90 example with a 2000 h life at 1000 rpm against the same without the limit: the life
// binds (its row is active, the input roller is the shortest-lived bearing), the design is larger,
// raising the limit costs diameter (mm per hour > 0), and lcr_analysis of the sized design computes
// the same lives.
TEST(LcrMinSizeLife, LifeLimitBindsAndCostsDiameter) {
  int code = -1;
  std::string err;
  const auto dir = TempDir("lcr-min-size-life");
  const json res = RunStudy(Example("lcr_min_size_life.json"), dir, &code, &err);
  ASSERT_EQ(code, 0) << err;
  EXPECT_TRUE(res["verified"].get<bool>());
  const json& best = res["best"];
  const json& life = best["life"];
  EXPECT_EQ(life["life_h"].get<double>(), 2000.0);
  EXPECT_GE(life["shortest_L10h"].get<double>(), 2000.0);
  EXPECT_LT(life["shortest_L10h"].get<double>(), 2000.0 * 1.001);  // binds: within 0.1%
  EXPECT_EQ(life["shortest_bearing"], "input_roller");
  const auto& binding = best["binding"];
  EXPECT_NE(std::find(binding.begin(), binding.end(), "input_roller_life"), binding.end()) << binding.dump();
  ASSERT_TRUE(best["limit_sensitivity"].contains("life_h"));
  EXPECT_GT(best["limit_sensitivity"]["life_h"].get<double>(), 0.0);
  for (const json& e : life["table"]) {
    SCOPED_TRACE(e["element"].get<std::string>());
    EXPECT_TRUE(e["pass"].get<bool>());
    EXPECT_EQ(e["L10h"].get<double>(), life[e["element"].get<std::string>() + "_L10h"].get<double>());
    // ISO 281: L10h = 10⁶ (C/P)^(10/3) / (60 n R), n = 1000 rpm, R the revolutions per input revolution.
    const double hand = 1e6 * std::pow(e["dynamic_rating_N"].get<double>() / e["equivalent_load_N"].get<double>(),
                                       10.0 / 3.0) /
                        (60.0 * 1000.0 * e["revolutions_per_input_revolution"].get<double>());
    EXPECT_NEAR(e["L10h"].get<double>(), hand, 1e-9 * hand);
    EXPECT_NEAR(e["s0"].get<double>(), e["static_rating_N"].get<double>() / e["max_load_N"].get<double>(), 1e-12);
  }
  // The eccentric bearing turns n_A/m_A per input revolution.
  const json& ecc = life["table"][2];
  EXPECT_NEAR(ecc["revolutions_per_input_revolution"].get<double>(),
              best["input"]["rollers"].get<double>() / best["input"]["lobes"].get<double>(), 1e-12);
  // The rollers' C scales from the 10 mm x 10 mm, 2700 N reference (ISO 281 6.1.1, same length).
  const double d = best["input"]["roller_diameter_mm"].get<double>();
  EXPECT_NEAR(life["table"][0]["dynamic_rating_N"].get<double>(), 2700.0 * std::pow(d / 10.0, 29.0 / 27.0), 1e-9);

  // Without the limit (the speed and ratings kept): the ratio −90 example's design, whose shortest
  // life is below 2000 h, and a smaller reducer.
  json free = Example("lcr_min_size_life.json");
  free["limits"].erase("life_h");
  const json res0 = RunStudy(free, TempDir("lcr-min-size-life-free"), &code, &err);
  ASSERT_EQ(code, 0) << err;
  EXPECT_LT(res0["best"]["life"]["shortest_L10h"].get<double>(), 2000.0);
  EXPECT_TRUE(res0["best"]["life"]["life_h"].is_null());
  EXPECT_LT(res0["best"]["outer_diameter_mm"].get<double>(), best["outer_diameter_mm"].get<double>() - 1.0);
  EXPECT_FALSE(res0["best"]["limit_sensitivity"].contains("life_h"));
  const json plain = RunStudy(Example("lcr_min_size.json"), TempDir("lcr-min-size-life-plain"), &code, &err);
  ASSERT_EQ(code, 0) << err;
  EXPECT_EQ(res0["best"]["outer_diameter_mm"], plain["best"]["outer_diameter_mm"]);

  // best_lcr_analysis.json carries the speed and the ratings at the sized roller: lcr_analysis
  // computes the same lives (the same functions, the same 3600 steps per revolution).
  const auto r = RunCamopt("run " + (dir / "out" / "best_lcr_analysis.json").string() + " --quiet --out " +
                           (dir / "analysis").string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const json a = json::parse(ReadFile(dir / "analysis" / "result.json"));
  for (const char* key : {"input_roller_L10h", "output_roller_L10h", "eccentric_bearing_L10h", "shortest_L10h"})
    EXPECT_NEAR(a["life"][key].get<double>(), life[key].get<double>(), 1e-9 * life[key].get<double>()) << key;
  // ... and checks the life limit the design was sized for (it was left out: "no limit set").
  EXPECT_EQ(a["life"]["life_h"], Example("lcr_min_size_life.json")["limits"]["life_h"]);
  EXPECT_EQ(a["status"], "limits_met");
}

// A catalogue that carries C and C0: with a life limit, the chosen roller meets it; an entry
// without C is a bad study naming the entry.
TEST(LcrMinSizeLife, CatalogueRatingsAndAnEntryWithoutC) {
  json study = Example("lcr_min_size_catalogue.json");
  study["search"]["max_lobes"] = 14;  // one combination (12/13 + 14/15), five rollers: keep the test short
  study["roller_catalogue"] = json::parse(ReadFile(camopt::testing::SourcePath("studies/examples/needle_rollers.json")));
  study["load"]["input_speed_rpm"] = 1000;
  study["limits"]["life_h"] = 2000;
  int code = -1;
  std::string err;
  const json res = RunStudy(study, TempDir("lcr-min-size-life-cat"), &code, &err);
  ASSERT_EQ(code, 0) << err;
  const json& life = res["best"]["life"];
  EXPECT_GE(life["shortest_L10h"].get<double>(), 2000.0);
  const std::string name = res["best"]["catalogue_roller"];
  for (const json& entry : study["roller_catalogue"])
    if (entry["name"] == name) {
      // The catalogue's own C and C0, not scaled.
      EXPECT_EQ(life["table"][0]["dynamic_rating_N"], entry["dynamic_rating_N"]);
      EXPECT_EQ(life["table"][0]["static_rating_N"], entry["static_rating_N"]);
    }
  study["roller_catalogue"][1].erase("dynamic_rating_N");
  camopt::testing::ExpectStudyRejected(study, "lcr-min-size-life-noC", "/roller_catalogue/1/dynamic_rating_N",
                                       "expected the roller's dynamic load rating C [N] > 0");
}

// A life no design of the combination reaches: exit 3, the message names life_h as the blocking
// limit and the largest life at which the combination fits (sizing::LimitToFit, halving and
// bisecting to 1%), and the study with that life fits.
TEST(LcrMinSizeLife, UnreachableLifeSaysWhichLifeWouldFit) {
  json study = Example("lcr_min_size_life.json");
  study["search"]["max_lobes"] = 14;  // one combination (12/13 + 14/15)
  study["limits"]["life_h"] = 1e5;
  study["optimizer"] = json::parse(R"({"backend": "slsqp", "starts": 1})");  // 1 s instead of 40 (Ipopt)
  int code = -1;
  std::string err;
  RunStudy(study, TempDir("lcr-min-size-life-unreachable"), &code, &err);
  ASSERT_EQ(code, 3) << err;
  const std::string fits = "12/13 + 14/15 fits with life_h = ";
  const size_t at = err.find(fits);
  ASSERT_NE(err.find("life_h blocks most"), std::string::npos) << err;
  ASSERT_NE(at, std::string::npos) << err;
  const double life = std::stod(err.substr(at + fits.size()));
  EXPECT_GE(life, 5e4);
  EXPECT_LT(life, 1e5);
  study["limits"]["life_h"] = life;
  const json res = RunStudy(study, TempDir("lcr-min-size-life-reachable"), &code, &err);
  ASSERT_EQ(code, 0) << err;
  EXPECT_GE(res["best"]["life"]["shortest_L10h"].get<double>(), life);
}

TEST(LcrMinSizeLife, BadInputIsAClearErrorWithExitCode2) {
  struct Case {
    std::string pointer, value, path, words;
  };
  const std::vector<Case> cases = {
      {"/load/input_speed_rpm", "-500", "/load/input_speed_rpm", "expected"},
      {"/duty_cycle", R"([{"output_torque_Nm": 80, "input_speed_rpm": 1000, "time_share": 0.5},
                          {"output_torque_Nm": 40, "input_speed_rpm": -1500, "time_share": 0.5}])",
       "/duty_cycle/1/input_speed_rpm", "expected"},
      {"/duty_cycle", R"([{"output_torque_Nm": 80, "input_speed_rpm": 1000, "time_share": 0.5},
                          {"output_torque_Nm": 40, "input_speed_rpm": 1500, "time_share": 0.3}])",
       "/duty_cycle", "expected time shares summing to 1 (within 1e-6), found 0.8; would fit: each time_share divided by 0.8"},
      {"/limits/life_h", "-1", "/limits/life_h", "expected"},
  };
  for (const auto& c : cases) {
    json study = Example("lcr_min_size_life.json");
    if (c.pointer == "/duty_cycle") study["load"].erase("input_speed_rpm");
    study[json::json_pointer(c.pointer)] = json::parse(c.value);
    camopt::testing::ExpectStudyRejected(study, "lcr-min-size-life-bad", c.path, c.words);
  }
  json study = Example("lcr_min_size_life.json");  // a limit without a speed
  study["load"].erase("input_speed_rpm");
  camopt::testing::ExpectStudyRejected(study, "lcr-min-size-life-nospeed", "/limits/life_h",
                                       "expected load.input_speed_rpm (> 0) or a duty_cycle");
  study = Example("lcr_min_size_life.json");  // a speed without the rollers' rating
  study.erase("rollers");
  camopt::testing::ExpectStudyRejected(study, "lcr-min-size-life-norating", "/rollers",
                                       "expected {\"dynamic_rating_N\", \"reference_diameter_mm\"}");
}


// The ratio −90 study at 20 000 h and 3000 rpm (one duty line at 80 N·m; rollers scaled from a
// 10 mm × 10 mm reference of C = 2700 N, an eccentric roller bearing of C = 12 000 N), for one
// combination: the life limit that the full search found no design for on 20/21 + 26/27.
LcrSizingSpec HardLifeSpec(int ma, int mb) {
  LcrSizingSpec s;
  s.lobes_a = ma, s.rollers_a = ma + 1, s.lobes_b = mb, s.rollers_b = mb + 1;
  s.output_torque_Nmm = 80e3;
  s.friction_coefficient = 0.05;
  s.limits = {1500.0, 1050.0, 0.5, 1.0, 0.0, 20000.0};
  objectives::LcrLifeSpec life;
  life.lines = {{80e3, 3000.0, 1.0}};
  life.roller = {2700.0, 2600.0, 10.0, 10.0};
  life.eccentric = objectives::LcrEccentricRating{false, 12000.0, 14000.0};
  s.life = life;
  return s;
}

// A combination whose longest life falls short of the limit is not sized (sizing/lcr_min_size.h,
// step 0): the longest life, other limits ignored, bounds the life of every design that meets the
// geometric rows — held against a grid of such designs, each through the dense check (the lives as
// lcr_analysis computes them, not the rows that were maximised) — and the longest-life problem's
// rows have exact gradients.
TEST(LcrMinSizeLife, ALifeOutOfReachIsBoundedAndNotSized) {
  const LcrSizingSpec spec = HardLifeSpec(20, 26);
  sizing::LcrMinSizeOptions o;
  o.solver.tolerance = 1e-6;
  o.solver.constraint_tolerance = 1e-6;
  const sizing::LcrMinSizeOutcome out = sizing::SolveLcrMinSize(spec, o);
  ASSERT_TRUE(out.longest_life_h.has_value());
  EXPECT_TRUE(out.life_out_of_reach);
  EXPECT_FALSE(out.converged);
  EXPECT_LT(*out.longest_life_h, 20000.0);
  ASSERT_TRUE(out.check.has_value());
  ASSERT_EQ(out.check->violations.size(), 1u);
  EXPECT_EQ(out.check->violations[0].limit, "life_h");

  // Designs over the box (the study's bounds) that meet the geometric rows: undercut margin
  // ≥ 0.5 mm and roller gap ≥ 1 mm on both cams, pitch point r_d − e n/(n − m) ≥ 2% r_d.
  LcrSizingSpec grid_spec = spec;
  grid_spec.limits = {kInf, kInf, 0.5, 1.0, 0.0, 20000.0};
  double longest_on_grid = 0.0;
  int designs = 0;
  for (int i = 0; i < 10; ++i)
    for (double rd : {50.0, 65.0, 80.0})
      for (int j = 0; j < 7; ++j) {
        const double e = 0.5 + 4.5 * i / 9, d = 3.0 + 17.0 * j / 6;
        if (rd * 0.98 - e * spec.rollers_b < 0 || rd * 0.98 - e * spec.rollers_a < 0) continue;
        const std::vector<double> x = {e, rd, rd, d, rd + d / 2};
        objectives::LcrDenseCheck c;
        try {
          c = objectives::DenseCheck(grid_spec, objectives::LcrDesign(grid_spec, x), 720);
        } catch (const std::domain_error&) {
          continue;
        }
        if (!c.design_problems.empty() || std::min(c.undercut_margin_mm[0], c.undercut_margin_mm[1]) < 0.5 ||
            std::min(c.roller_gap_mm[0], c.roller_gap_mm[1]) < 1.0)
          continue;
        ++designs;
        longest_on_grid = std::max(longest_on_grid, c.shortest_L10h);
      }
  ::testing::Test::RecordProperty("longest_on_grid_h", std::to_string(longest_on_grid));
  ::testing::Test::RecordProperty("designs", designs);
  EXPECT_GE(designs, 20);
  EXPECT_GT(longest_on_grid, 0.5 * *out.longest_life_h);  // the grid reaches near the bound...
  EXPECT_LE(longest_on_grid, *out.longest_life_h * 1.01);  // ...and never past it (1%: its sampling)

  // Gradients of the longest-life problem's outputs against central differences.
  const objectives::Problem p = objectives::MakeLcrLongestLifeProblem(spec);
  std::vector<int> every_row(size_t(p.evaluator->num_outputs()));
  for (size_t k = 0; k < every_row.size(); ++k) every_row[k] = int(k);
  for (std::vector<double> x : objectives::LcrStartingPoints(spec, 2)) {
    x.back() = 0.3;  // t
    ExpectRowsMatchCentralDifferences(p, x, every_row);
  }
}

// The hard life limit through the CLI (Ipopt, as the example): the same answer as the full search
// of every combination gave before combinations out of reach were skipped (12/13 + 14/15 at
// 167.675 mm, measured with Ipopt and with SLSQP: 224 s and 2.8 s of CPU), the other three
// combinations out of reach with their longest lives below the limit.
TEST(LcrMinSizeLife, AHardLifeLimitSkipsTheCombinationsOutOfReach) {
  json study = Example("lcr_min_size_life.json");
  study["limits"]["life_h"] = 20000;
  study["load"]["input_speed_rpm"] = 3000;
  int code = -1;
  std::string err;
  const json res = RunStudy(study, TempDir("lcr-min-size-life-hard"), &code, &err);
  ASSERT_EQ(code, 0) << err;
  EXPECT_EQ(res["status"], "optimal_verified");
  EXPECT_NEAR(res["best"]["outer_diameter_mm"].get<double>(), 167.675, 0.01);
  EXPECT_EQ(res["best"]["input"]["lobes"], 12);
  EXPECT_EQ(res["best"]["output"]["lobes"], 14);
  int out_of_reach = 0;
  for (const json& c : res["candidates"]) {
    if (c["status"] == "life_out_of_reach") {
      ++out_of_reach;
      EXPECT_LT(c["longest_life_h"].get<double>(), 20000.0);
      EXPECT_FALSE(c["feasible"].get<bool>());
      EXPECT_EQ(c["violations"][0]["limit"], "life_h");
    } else {
      EXPECT_FALSE(c.contains("longest_life_h")) << c.dump();  // a start reached the limit
    }
  }
  EXPECT_EQ(out_of_reach, 3);
}

}  // namespace lcr_min_size_life_test
}  // namespace camopt
