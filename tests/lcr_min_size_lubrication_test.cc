// The LCR sizing against its lubricated losses (objectives/lcr_sizing.h with spec.lubrication,
// docs/lubrication.md "Sizing"): the efficiency and oil-temperature rows' exact derivatives
// against central differences, the rows against the dense check, and the example through the
// command line with and without its min_efficiency, checked by lcr_analysis on the sized design.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "objectives/lcr_dense_check.h"
#include "objectives/lcr_sizing.h"
#include "tests/test_util.h"

namespace camopt {
namespace lcr_min_size_lubrication_test {

using camopt::testing::Example;
using camopt::testing::ReadFile;
using camopt::testing::RunCamopt;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;
using nlohmann::json;
using objectives::LcrSizingSpec;

// The ratio −90 combination 12/13 + 14/15 at 80 N·m and 1500 rpm in VG 68 (α 21/GPa), rollers
// fixed (sliding: the film and the regime blend set the loss) or rotating on needle bearings, an
// eccentric bearing; the oil temperature given or from a 0.045 m² housing with 20 W/K of forced cooling.
LcrSizingSpec LubricatedSpec(bool rotating, bool thermal) {
  LcrSizingSpec s;
  s.lobes_a = 12, s.rollers_a = 13, s.lobes_b = 14, s.rollers_b = 15;
  s.output_torque_Nmm = 80e3;
  s.limits.contact_stress_MPa = 1500;
  s.limits.min_efficiency = 0.5;
  if (thermal) s.limits.max_oil_temperature_C = 90;
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

// The rows' derivatives (ceres::Jet through the loads, contacts, film, regime blend and, with the
// balance, the implicit temperature) against central differences with step ∛ε·max(1, |x_i|):
// truncation and rounding of order ε^(2/3) of the rows' scale, so 1e-6 of max(1e-2, |fd|).
TEST(LcrMinSizeLubrication, RowDerivativesMatchCentralDifferences) {
  for (bool rotating : {false, true})
    for (bool thermal : {false, true}) {
      SCOPED_TRACE(std::string(rotating ? "rotating" : "fixed") + " rollers, " + (thermal ? "balance" : "50 °C"));
      const LcrSizingSpec spec = LubricatedSpec(rotating, thermal);
      const objectives::Problem p = objectives::MakeLcrSizingProblem(spec);
      std::vector<int> rows = {Offset(p, "mean_efficiency")};
      if (thermal) rows.push_back(Offset(p, "oil_temperature_C"));
      EXPECT_EQ(Offset(p, "oil_temperature_C") >= 0, thermal);  // a given temperature is no row
      ASSERT_GE(rows[0], 0);
      const int n = p.num_vars(), m = p.evaluator->num_outputs();
      for (const std::vector<double>& x : objectives::LcrStartingPoints(spec, 2)) {
        std::vector<double> y(m), jac(size_t(m) * n);
        p.evaluator->EvalWithJacobian(x, y, jac);
        for (int row : rows) ASSERT_TRUE(std::isfinite(y[row])) << row;
        EXPECT_GT(y[rows[0]], 0.1);  // sliding rollers at a start: 0.15 to 0.23
        EXPECT_LT(y[rows[0]], 1.0);
        double largest = 0;
        for (int i = 0; i < n; ++i) {
          const double h = std::cbrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, std::abs(x[i]));
          std::vector<double> xp = x, xm = x, yp(m), ym(m);
          xp[i] += h, xm[i] -= h;
          p.evaluator->Eval(xp, yp);
          p.evaluator->Eval(xm, ym);
          for (int row : rows) {
            const double fd = (yp[row] - ym[row]) / (2 * h), g = jac[size_t(row) * n + i];
            EXPECT_NEAR(g, fd, 1e-6 * std::max(1e-2, std::abs(fd))) << "row " << row << ", " << p.variables[i].name;
          }
          largest = std::max(largest, std::abs(jac[size_t(rows[0]) * n + i]));
        }
        EXPECT_GT(largest, 1e-4);  // the efficiency moves with the design
      }
    }
}

// The row (48 angles) and the dense check (3600) are the same law on two grids: within 1e-3 of
// each other; the dense check's temperature satisfies the housing's balance.
TEST(LcrMinSizeLubrication, RowsAgreeWithTheDenseCheck) {
  const LcrSizingSpec spec = LubricatedSpec(false, true);
  const objectives::Problem p = objectives::MakeLcrSizingProblem(spec);
  const std::vector<double> x = objectives::LcrStartingPoints(spec, 1).front();
  std::vector<double> y(p.evaluator->num_outputs());
  p.evaluator->Eval(x, y);
  const objectives::LcrDenseCheck c = objectives::DenseCheck(spec, objectives::LcrDesign(spec, x));
  EXPECT_NEAR(y[Offset(p, "mean_efficiency")], c.mean_efficiency, 1e-3);
  EXPECT_NEAR(y[Offset(p, "oil_temperature_C")], c.oil_temperature_C, 0.5);
  const double k = 0.045 * 15.0 + 20.0;
  EXPECT_NEAR(c.lubricated_loss_W, k * (c.oil_temperature_C - 25.0), 1e-6 * c.lubricated_loss_W);
}

// The example with and without its efficiency limit: with it the limit binds and holds (the
// verification's check), the reducer is larger and more efficient and its oil cooler; lcr_analysis
// on best_lcr_analysis.json (its own loads and losses over the same 3600 angles) gives the same
// efficiency and temperature.
TEST(LcrMinSizeLubrication, AMinEfficiencyThatBindsCostsSizeAndIsWhatLcrAnalysisReports) {
  const json base = Example("lcr_min_size_lubricated.json");
  ASSERT_EQ(base["limits"]["min_efficiency"], 0.94);
  const auto dir = TempDir("lcr-lub-sizing");
  json free = base;
  free["limits"].erase("min_efficiency");
  json result[2];
  for (int k = 0; k < 2; ++k) {
    const std::string tag = k == 0 ? "limited" : "free";
    WriteFile(dir / (tag + ".json"), (k == 0 ? base : free).dump());
    const auto r = RunCamopt("run " + (dir / (tag + ".json")).string() + " --quiet --out " + (dir / tag).string() +
                             " > /dev/null");
    ASSERT_EQ(r.exit_code, 0) << tag << ": " << r.stderr_text;
    result[k] = json::parse(ReadFile(dir / tag / "result.json"));
    EXPECT_EQ(result[k]["verified"], true) << tag;
  }
  const json &limited = result[0]["best"], &unlimited = result[1]["best"];
  EXPECT_EQ(limited["efficiency_model"], "lubricated (docs/lubrication.md)");
  bool binds = false;
  for (const json& b : limited["binding_limits"]) binds = binds || b["limit"] == "min_efficiency";
  EXPECT_TRUE(binds) << limited["binding_limits"].dump();
  bool held = false;
  for (const json& c : result[0]["verification"]["checks"])
    if (c["limit"] == "min_efficiency") held = c["holds"].get<bool>();
  EXPECT_TRUE(held);
  EXPECT_GE(limited["mean_efficiency"].get<double>(), 0.94);
  EXPECT_NEAR(limited["mean_efficiency"].get<double>(), 0.94, 1e-3);
  EXPECT_LT(unlimited["mean_efficiency"].get<double>(), 0.94);
  EXPECT_GT(limited["outer_diameter_mm"].get<double>(), unlimited["outer_diameter_mm"].get<double>());
  EXPECT_LT(limited["oil_temperature_C"].get<double>(), unlimited["oil_temperature_C"].get<double>());
  const auto a = RunCamopt("run " + (dir / "limited" / "best_lcr_analysis.json").string() + " --quiet --out " +
                           (dir / "analysis").string() + " > /dev/null");
  ASSERT_EQ(a.exit_code, 0) << a.stderr_text;
  const json l = json::parse(ReadFile(dir / "analysis" / "result.json"))["lubrication"];
  EXPECT_NEAR(l["efficiency"].get<double>(), limited["mean_efficiency"].get<double>(), 1e-9);
  EXPECT_NEAR(l["oil_temperature_C"].get<double>(), limited["oil_temperature_C"].get<double>(), 1e-6);
}

// A housing that cannot give off the loss below the oil's limit: the sized design has no lubricated
// operating point, and the run says so with exit 3 (never exit 0 without the asked-for losses).
TEST(LcrMinSizeLubrication, NoThermalEquilibriumAtTheSizedDesignExitsThree) {
  const json res = camopt::testing::RunSizingWithoutThermalEquilibrium(Example("lcr_min_size_lubricated.json"), "lcr-lub-hot");
  EXPECT_TRUE(res["best"]["oil_temperature_C"].is_null());
  EXPECT_NE(res["best"]["lubrication_error"].get<std::string>().find("no equilibrium"), std::string::npos);
}

// Without a lubricant min_efficiency stays eq. 33's; an oil-temperature limit needs the balance.
TEST(LcrMinSizeLubrication, WhatTheLimitsNeedIsRefusedOrSaid) {
  json s = Example("lcr_min_size_lubricated.json");
  s["lubricant"].erase("thermal");
  s["lubricant"]["temperature_C"] = 60;
  s["limits"]["max_oil_temperature_C"] = 80;
  camopt::testing::ExpectStudyRejected(s, "lcr-lub-t", "/limits/max_oil_temperature_C", "thermal");
  s = Example("lcr_min_size_lubricated.json");
  s.erase("lubricant");
  s.erase("surfaces");
  s.erase("bearing_friction");
  s["limits"]["max_oil_temperature_C"] = 80;
  camopt::testing::ExpectStudyRejected(s, "lcr-lub-none", "/limits/max_oil_temperature_C", "lubricant");
}

}  // namespace lcr_min_size_lubrication_test
}  // namespace camopt
