// The LCR sizing with the efficiency objective (objectives/lcr_sizing.h LcrSizeObjective::kPowerLoss,
// docs/lubrication.md "Sizing"): the loss row's exact derivatives against central differences, the
// example through the command line against the same study minimising the outer diameter and
// against lcr_analysis on its sized design, its optimality probed by perturbations held to the
// dense check, and the input it refuses.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "objectives/lcr_dense_check.h"
#include "objectives/lcr_sizing.h"
#include "studies/input.h"
#include "studies/lcr_min_size_study.h"
#include "tests/test_util.h"

namespace camopt {
namespace lcr_min_size_efficiency_test {

using camopt::testing::Example;
using camopt::testing::ReadFile;
using camopt::testing::RunCamopt;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;
using nlohmann::json;
using objectives::LcrSizingSpec;

// The ratio −90 combination 12/13 + 14/15 at 80 N·m and 1500 rpm in VG 68 (α 21/GPa), rollers fixed
// (sliding) or rotating on needle bearings, an eccentric bearing; the oil at 50 °C or at the balance of
// a 0.045 m² housing with 20 W/K of forced cooling. The objective is the lubricated loss; no
// efficiency limit, so that the loss is the only lubricated row with a value to match.
LcrSizingSpec LossSpec(bool rotating, bool thermal) {
  LcrSizingSpec s;
  s.lobes_a = 12, s.rollers_a = 13, s.lobes_b = 14, s.rollers_b = 15;
  s.output_torque_Nmm = 80e3;
  s.limits.contact_stress_MPa = 1500;
  s.objective = objectives::LcrSizeObjective::kPowerLoss;
  objectives::LcrSizingLubrication l;
  l.spec.oil.nu40_mm2_s = 68;
  l.spec.oil.nu100_mm2_s = 8.7;
  l.spec.oil.pressure_viscosity_per_MPa = 0.021;
  l.spec.composite_roughness_mm = 0.1e-3 * std::sqrt(2.0);
  l.spec.rollers_rotate = rotating;
  l.spec.roller_bearing = {3.0, 0.0005, 8.0};
  l.spec.eccentric_bearing = {2.0, 0.0003, 16.0};
  l.input_speed_rpm = 1500;
  if (!thermal) l.temperature_C = 50;
  l.cooling = {0.045, 15.0, 20.0, 25.0};
  l.balance_limit_C = 150;
  s.lubrication = l;
  return s;
}

int Offset(const objectives::Problem& p, const std::string& name) {
  for (const auto& b : p.evaluator->blocks())
    if (b.name == name) return b.offset;
  return -1;
}

// The objective row P_loss [W]: its Jet derivative (through the loads, contacts, film, regime blend,
// bearings and, with the balance, the implicit oil temperature) against central differences with
// step ∛ε·max(1, |x_i|) at three starting designs of each mounting and temperature source. The
// truncation and rounding errors are of order ε^(2/3) ≈ 4e-11 of the row's scale (watts) per mm:
// 1e-6 of max(0.01 W/mm, |fd|) leaves room for the balance's own tolerance (1e-9 of the loss).
TEST(LcrMinSizeEfficiency, PowerLossRowDerivativesMatchCentralDifferences) {
  double worst_relative = 0;
  for (bool rotating : {false, true})
    for (bool thermal : {false, true}) {
      SCOPED_TRACE(std::string(rotating ? "rotating" : "fixed") + " rollers, " + (thermal ? "balance" : "50 °C"));
      const LcrSizingSpec spec = LossSpec(rotating, thermal);
      const objectives::Problem p = objectives::MakeLcrSizingProblem(spec);
      ASSERT_EQ(p.objective, "power_loss_W");
      const int row = Offset(p, "power_loss_W");
      ASSERT_GE(row, 0);
      const int n = p.num_vars(), m = p.evaluator->num_outputs();
      for (const std::vector<double>& x : objectives::LcrStartingPoints(spec, 3)) {
        std::vector<double> y(m), jac(size_t(m) * n);
        p.evaluator->EvalWithJacobian(x, y, jac);
        ASSERT_TRUE(std::isfinite(y[row]));
        // The row is the loss over the problem's 48 angles: the dense check's law on the same grid.
        const objectives::LcrDenseCheck c48 =
            objectives::DenseCheck(spec, objectives::LcrDesign(spec, x), spec.efficiency_samples);
        EXPECT_NEAR(y[row], c48.lubricated_loss_W, 1e-9 * c48.lubricated_loss_W);
        EXPECT_GT(y[row], 0.1);  // watts lost at 140 W of output power
        double largest = 0;
        for (int i = 0; i < n; ++i) {
          const double h = std::cbrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, std::abs(x[i]));
          std::vector<double> xp = x, xm = x, yp(m), ym(m);
          xp[i] += h, xm[i] -= h;
          p.evaluator->Eval(xp, yp);
          p.evaluator->Eval(xm, ym);
          const double fd = (yp[row] - ym[row]) / (2 * h), g = jac[size_t(row) * n + i];
          EXPECT_NEAR(g, fd, 1e-6 * std::max(1e-2, std::abs(fd))) << p.variables[i].name;
          worst_relative = std::max(worst_relative, std::abs(g - fd) / std::max(1e-2, std::abs(fd)));
          largest = std::max(largest, std::abs(g));
        }
        EXPECT_GT(largest, 1e-3);  // the loss moves with the design
        EXPECT_EQ(jac[size_t(row) * n + (n - 1)], 0.0);  // R, the outer-radius slack, costs no loss
      }
    }
  std::cout << "power-loss row: largest |jet - central difference| / max(0.01, |fd|) = " << worst_relative << "\n";
}

// With the loss as the objective R no longer shrinks onto the envelope: it is bounded by the
// outer-diameter limit, or without one by the variable box's largest outer radius; without the
// lubrication the objective has nothing to minimise.
TEST(LcrMinSizeEfficiency, OuterRadiusIsBoundedAndTheLubricationRequired) {
  LcrSizingSpec spec = LossSpec(true, true);
  objectives::Problem p = objectives::MakeLcrSizingProblem(spec);
  EXPECT_DOUBLE_EQ(p.variables.back().upper, spec.turret_radius_mm[1] + spec.roller_diameter_mm[1] / 2);
  spec.limits.max_outer_diameter_mm = 110;
  p = objectives::MakeLcrSizingProblem(spec);
  EXPECT_DOUBLE_EQ(p.variables.back().upper, 55.0);
  // The scale: 5% of T_o ω_out = 80 N·m × 1500 rpm · 2π/60 / 90.
  EXPECT_NEAR(p.objective_scale, 0.05 * 80.0 * 1500 * 2 * M_PI / 60 / 90, 1e-9);
  spec.lubrication.reset();
  EXPECT_THROW(objectives::MakeLcrSizingProblem(spec), std::invalid_argument);
}

double OuterDiameter(const json& reducer) {
  double r = 0;
  for (const char* side : {"input", "output"})
    r = std::max(r, reducer[side]["turret_radius_mm"].get<double>() + reducer[side]["roller_diameter_mm"].get<double>() / 2);
  return 2 * r;
}

// The example minimises the lubricated loss; the same study minimising the outer diameter is the
// smallest reducer of those limits. The least-loss design is verified, loses no more and is no
// smaller than the smallest one, and lcr_analysis on its best_lcr_analysis.json (its own loads and
// losses over the same 3600 angles) gives the efficiency and loss the sizing reports. Then its
// optimality on the dense check: every design variable moved by ±0.02%, ±0.2% and ±2% from the
// optimum; no move that the dense check holds (every limit, the outer-diameter limit too) loses
// less, beyond the tolerance below.
TEST(LcrMinSizeEfficiency, TheExampleLosesLeastIsWhatLcrAnalysisReportsAndNoFeasibleMoveLosesLess) {
  const json base = Example("lcr_min_size_efficiency.json");
  ASSERT_EQ(base["objective"], "efficiency");
  const auto dir = TempDir("lcr-eff-sizing");
  json smallest = base;
  smallest.erase("objective");  // the default: the outer diameter
  json result[2];
  for (int k = 0; k < 2; ++k) {
    const std::string tag = k == 0 ? "efficiency" : "diameter";
    WriteFile(dir / (tag + ".json"), (k == 0 ? base : smallest).dump());
    const auto r = RunCamopt("run " + (dir / (tag + ".json")).string() + " --out " + (dir / tag).string() +
                             " > /dev/null");
    ASSERT_EQ(r.exit_code, 0) << tag << ": " << r.stderr_text;
    result[k] = json::parse(ReadFile(dir / tag / "result.json"));
    EXPECT_EQ(result[k]["verified"], true) << tag;
    std::cout << tag << ": " << r.stderr_text;
    if (k == 0) { EXPECT_NE(r.stderr_text.find("minimised the lubricated loss"), std::string::npos) << r.stderr_text; }
  }
  EXPECT_EQ(result[0]["objective"], "efficiency");
  EXPECT_FALSE(result[1].contains("objective"));  // the default's result.json is as it was
  const json &eff = result[0]["best"], &small = result[1]["best"];
  const double eta = eff["mean_efficiency"].get<double>(), loss = eff["power_loss_W"].get<double>();
  std::cout << "efficiency objective: eta " << eta << ", loss " << loss << " W, outer diameter "
            << eff["outer_diameter_mm"] << " mm; outer-diameter objective: eta " << small["mean_efficiency"]
            << ", loss " << small["power_loss_W"] << " W, outer diameter " << small["outer_diameter_mm"] << " mm\n";
  EXPECT_GE(eta, small["mean_efficiency"].get<double>());
  EXPECT_LE(loss, small["power_loss_W"].get<double>());
  EXPECT_GE(eff["outer_diameter_mm"].get<double>(), small["outer_diameter_mm"].get<double>());
  EXPECT_LE(eff["outer_diameter_mm"].get<double>(), base["limits"]["max_outer_diameter_mm"].get<double>());
  for (const json& b : eff["binding_limits"])
    EXPECT_NE(b["unit"].get<std::string>().find("W of loss per"), std::string::npos) << b.dump();

  // lcr_analysis on the written design: another kind's loads, contacts and losses.
  const auto a = RunCamopt("run " + (dir / "efficiency" / "best_lcr_analysis.json").string() + " --quiet --out " +
                           (dir / "analysis").string() + " > /dev/null");
  ASSERT_EQ(a.exit_code, 0) << a.stderr_text;
  const json analysis = json::parse(ReadFile(dir / "analysis" / "result.json"));
  const json& l = analysis["lubrication"];
  EXPECT_NEAR(l["efficiency"].get<double>(), eta, 1e-6);
  EXPECT_NEAR(l["power_loss_W"]["total"].get<double>(), loss, 1e-6);
  EXPECT_NEAR(analysis["outer_diameter_mm"].get<double>(), eff["outer_diameter_mm"].get<double>(), 1e-9);

  // Optimality on the dense check: the design read back from best_lcr_analysis.json.
  const json study = json::parse(ReadFile(dir / "efficiency.json"));
  const studies::lcr_min_size::Study s = studies::lcr_min_size::Parse(studies::Node(&study, "efficiency.json", ""));
  const json red = json::parse(ReadFile(dir / "efficiency" / "best_lcr_analysis.json"))["reducer"];
  LcrSizingSpec spec = s.base;
  spec.lobes_a = red["input"]["lobes"], spec.rollers_a = red["input"]["rollers"];
  spec.lobes_b = red["output"]["lobes"], spec.rollers_b = red["output"]["rollers"];
  std::vector<double> x = {red["eccentricity_mm"].get<double>(), red["input"]["turret_radius_mm"].get<double>(),
                           red["output"]["turret_radius_mm"].get<double>(),
                           red["input"]["roller_diameter_mm"].get<double>(), OuterDiameter(red) / 2};
  const objectives::LcrDenseCheck at = objectives::DenseCheck(spec, objectives::LcrDesign(spec, x));
  ASSERT_TRUE(at.ok());
  EXPECT_NEAR(at.lubricated_loss_W, loss, 1e-9 * loss);
  // The tolerance: the solver's own (optimizer.tolerance, 1e-6 relative). The problem minimises the
  // 48-angle loss and the dense check is the 3600-angle one; a move that the grids' difference
  // turned into a descent of more than this would show here.
  const double tolerance = s.options.solver.tolerance * loss;
  int feasible = 0;
  double least = kInf;
  for (size_t i = 0; i + 1 < x.size(); ++i)
    for (double step : {2e-4, 2e-3, 2e-2})
      for (double sign : {-1.0, 1.0}) {
        std::vector<double> moved = x;
        moved[i] *= 1 + sign * step;
        const lcr::Reducer<double> d = objectives::LcrDesign(spec, moved);
        objectives::LcrDenseCheck c;
        try {
          c = objectives::DenseCheck(spec, d);
        } catch (const std::domain_error&) {
          continue;  // degenerate: not a design
        }
        if (!c.ok() || !std::isfinite(c.lubricated_loss_W)) continue;
        ++feasible;
        least = std::min(least, c.lubricated_loss_W - loss);
        EXPECT_GE(c.lubricated_loss_W, loss - tolerance)
            << "variable " << i << " moved by " << sign * step << ": " << c.lubricated_loss_W << " W";
      }
  std::cout << "optimality: " << feasible << " feasible moves of 24, least change of the loss " << least << " W\n";
  EXPECT_GE(feasible, 6);  // the probe is not empty: several directions stay inside the limits
}

// What the objective needs is refused with the JSON path and what would fit.
TEST(LcrMinSizeEfficiency, WhatTheObjectiveNeedsIsRefused) {
  json s = Example("lcr_min_size_efficiency.json");
  s.erase("lubricant");
  s.erase("surfaces");
  s.erase("bearing_friction");
  camopt::testing::ExpectStudyRejected(s, "lcr-eff-nolub", "/objective", "needs \"lubricant\"");
  s = Example("lcr_min_size_efficiency.json");
  s["objective"] = "volume";
  camopt::testing::ExpectStudyRejected(s, "lcr-eff-unknown", "/objective", "\"outer_diameter\", \"efficiency\"");
  // A 3D contact: the line model only (the crowned example's contact with the lubricated blocks).
  s = Example("lcr_min_size_efficiency.json");
  s["contact"] = Example("lcr_min_size_crowned.json")["contact"];
  camopt::testing::ExpectStudyRejected(s, "lcr-eff-3d", "/objective", "line contact model");
}

}  // namespace lcr_min_size_efficiency_test
}  // namespace camopt
