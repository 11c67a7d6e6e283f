// Study kind cycloid_min_size (studies/cycloid_min_size_study.h): the refusals of bad input with
// their JSON paths and the bound that would fit (computed here from the closed forms of the
// epitrochoid, docs/cycloid.md, not by the code under test), the
// examples' work and the best design as a cycloid_ltca study, and an end-to-end run of a small
// study through the command line.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/cycloid_ltca_study.h"
#include "studies/cycloid_min_size_study.h"
#include "studies/input.h"
#include "studies/study.h"
#include "studies/work_limits.h"
#include "studies/format.h"
#include "tests/test_util.h"

namespace camopt {
namespace cycloid_min_size_study_test {

using nlohmann::json;
using testing::Example;
using testing::ReadFile;
using testing::RunCamopt;
using testing::TempDir;
using testing::WriteFile;

constexpr double kPiHere = 3.14159265358979323846;

// A small study of its own (10 pins): three geometric variables and the crowning coefficient,
// coarse grids, one start. Its ranges hold the answer well inside (the stress binds).
json SmallStudy() {
  return json::parse(R"({
    "study": "cycloid_min_size",
    "name": "small test drive",
    "target": {"teeth": 9, "design_torque_Nm": 40, "overload_torque_Nm": 60},
    "variables": {
      "eccentricity_mm": [1.0, 4.0],
      "roller_position_radius_mm": [25, 60],
      "roller_radius_mm": [2, 9],
      "coefficient_mm": [0, 0.01]
    },
    "drive": {"face_width_mm": 10},
    "modification": {"delta_position_um": -10},
    "crowning": {"type": "logarithmic", "effective_length_mm": 11},
    "limits": {"contact_stress_MPa": 1200},
    "material": {"youngs_modulus_GPa": 206, "poisson_ratio": 0.3},
    "analysis": {"grid": [10, 10], "crank_angles_per_mesh_period": 3},
    "optimizer": {"starts": 1, "max_evaluations": 25}
  })");
}

// The StudyError of the parse (as `camopt run` checks a study before running it); "" when accepted.
studies::StudyError ParseError(const json& study) {
  try {
    studies::CheckStudy(study, "s.json");
  } catch (const studies::StudyError& e) {
    return e;
  }
  return studies::StudyError("");
}

void ExpectRefused(const json& study, const std::string& path, const std::string& words) {
  const studies::StudyError e = ParseError(study);
  const std::string what = e.what();
  ASSERT_FALSE(what.empty()) << "accepted, expected a refusal at " << path;
  EXPECT_EQ(e.path(), path) << what;
  EXPECT_EQ(what.rfind("s.json: " + path + ": ", 0), 0u) << what;
  EXPECT_NE(what.find(words), std::string::npos) << what;
}

// Smallest convex radius of the generating curve (docs/cycloid.md), written out here.
double CentreRadius(double e, double a_mod, int rollers) {
  const double n = rollers, lambda = e * n / a_mod, lambda_s = (n - 2) / (2 * n - 1);
  if (lambda <= lambda_s) return a_mod * (1 + lambda) * (1 + lambda) / (1 + n * lambda);
  return a_mod * std::sqrt(27 * (n - 1) * (1 - lambda * lambda) / ((n + 1) * (n + 1) * (n + 1)));
}

std::string G(double v, int digits) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

TEST(CycloidMinSizeStudy, ExamplesAndTheSmallStudyParse) {
  for (const char* name : {"cycloid_min_size_paper.json", "cycloid_min_size_ratio29.json"}) {
    SCOPED_TRACE(name);
    EXPECT_STREQ(ParseError(Example(name)).what(), "");
  }
  EXPECT_STREQ(ParseError(SmallStudy()).what(), "");
}

TEST(CycloidMinSizeStudy, ParsedSpecHasTheFileValues) {
  const json j = Example("cycloid_min_size_paper.json");
  const studies::Node root(&j, "paper.json", "");
  const auto s = studies::cycloid_min_size::Parse(root);
  EXPECT_EQ(s.spec.drive.teeth, 15);
  EXPECT_EQ(s.spec.drive.rollers, 16);
  EXPECT_DOUBLE_EQ(s.spec.design_torque_Nmm, 350e3);
  EXPECT_DOUBLE_EQ(s.spec.overload_torque_Nmm, 550e3);
  EXPECT_DOUBLE_EQ(s.spec.drive.face_width_mm, 17);  // fixed in variables
  EXPECT_DOUBLE_EQ(s.spec.crowning.effective_length_mm, 18.7);
  EXPECT_EQ(s.spec.crowning.type, cycloid::CrowningType::kLogarithmic);
  // Six ranges, in CycloidSizingVariableNames order, with the starts of the file (µm for Δa, Δρ).
  ASSERT_EQ(s.spec.variables.size(), 6u);
  std::map<std::string, objectives::Variable> v;
  for (const auto& x : s.spec.variables) v[x.name] = x;
  EXPECT_DOUBLE_EQ(v.at("roller_radius_mm").initial, 7.2);
  EXPECT_DOUBLE_EQ(v.at("delta_position_um").lower, -30);
  EXPECT_DOUBLE_EQ(v.at("delta_position_um").initial, -16);
  EXPECT_DOUBLE_EQ(s.spec.drive.delta_position_mm, -0.016);  // the start, in mm
  EXPECT_DOUBLE_EQ(s.spec.drive.roller_position_radius_mm, 90);
  EXPECT_DOUBLE_EQ(s.spec.limits.contact_stress_MPa, 1309);
  EXPECT_DOUBLE_EQ(s.spec.limits.min_curtate_margin, 0.05);  // the default
  EXPECT_EQ(s.spec.angles_per_period, 4);
  EXPECT_EQ(s.spec.options.profile_cells, 16);
  EXPECT_EQ(s.options.solver.backend, optimizers::Backend::kIpopt);
  // speed_ratio z is the same drive as teeth z; the fixed face width comes from "drive".
  const json r = Example("cycloid_min_size_ratio29.json");
  const auto s29 = studies::cycloid_min_size::Parse(studies::Node(&r, "r.json", ""));
  EXPECT_EQ(s29.spec.drive.teeth, 29);
  EXPECT_EQ(s29.spec.drive.rollers, 30);
  EXPECT_DOUBLE_EQ(s29.spec.drive.face_width_mm, 8);
  EXPECT_DOUBLE_EQ(s29.spec.overload_torque_Nmm, 40e3);
  EXPECT_EQ(s29.options.solver.backend, optimizers::Backend::kSlsqp);
  EXPECT_DOUBLE_EQ(s29.spec.limits.bore_radius_mm, 0);  // no bore: no web row
  // A range without a start starts at its middle; the bore diameter gives the bore radius.
  json small = SmallStudy();
  small["limits"]["bore_diameter_mm"] = 10;
  const auto ss = studies::cycloid_min_size::Parse(studies::Node(&small, "s.json", ""));
  EXPECT_DOUBLE_EQ(ss.spec.drive.eccentricity_mm, 0.5 * (1.0 + 4.0));
  EXPECT_DOUBLE_EQ(ss.spec.drive.roller_radius_mm, 0.5 * (2.0 + 9.0));
  EXPECT_DOUBLE_EQ(ss.spec.limits.bore_radius_mm, 5);
  EXPECT_DOUBLE_EQ(ss.spec.drive.delta_position_mm, -0.010);  // modification.delta_position_um
}

TEST(CycloidMinSizeStudy, ImpossibleRatiosAreRefusedWithTheNearestThatFits) {
  json s = SmallStudy();
  s["target"].erase("teeth");
  s["target"]["speed_ratio"] = 14.6;
  ExpectRefused(s, "/target/speed_ratio", "15 would fit");
  s["target"]["speed_ratio"] = 1;
  ExpectRefused(s, "/target/speed_ratio", "2 would fit");
  s["target"]["speed_ratio"] = -15;
  ExpectRefused(s, "/target/speed_ratio", "15 would fit");
  s["target"]["speed_ratio"] = 15;
  EXPECT_STREQ(ParseError(s).what(), "");
  s["target"]["teeth"] = 15;
  ExpectRefused(s, "/target", "not both");
}

TEST(CycloidMinSizeStudy, AnEmptyRangeIsRefusedWithTheRangeThatFits) {
  json s = SmallStudy();
  s["variables"]["roller_radius_mm"] = {5, 3};
  ExpectRefused(s, "/variables/roller_radius_mm", "[3, 5] would fit");
  s["variables"]["roller_radius_mm"] = {{"range", {2, 6}}, {"start", 7}};
  ExpectRefused(s, "/variables/roller_radius_mm/start", "a start within the range [2, 6]");
  // lo = hi is a fixed value, not a variable.
  s["variables"]["roller_radius_mm"] = {4, 4};
  const auto parsed = studies::cycloid_min_size::Parse(studies::Node(&s, "s.json", ""));
  EXPECT_DOUBLE_EQ(parsed.spec.drive.roller_radius_mm, 4);
  for (const auto& v : parsed.spec.variables) EXPECT_NE(v.name, "roller_radius_mm");
}

TEST(CycloidMinSizeStudy, ARangeWhereEveryDesignIsCurtateIsRefusedBeforeAnyWork) {
  // 10 pins, e >= 2.4 mm and a <= 25 mm: at the best corner 1 - 2.4 * 10 / 25 = 0.04 < 0.05; the
  // eccentricity that fits there is (1 - 0.05) 25 / 10 = 2.375 mm; the pin circle 2.4 * 10 / 0.95.
  json s = SmallStudy();
  s["modification"]["delta_position_um"] = 0;
  s["variables"]["eccentricity_mm"] = {2.4, 3};
  s["variables"]["roller_position_radius_mm"] = {20, 25};
  ExpectRefused(s, "/variables/eccentricity_mm/0", "an eccentricity of at most " + G(0.95 * 25 / 10, 5) + " mm");
  ExpectRefused(s, "/variables/eccentricity_mm/0", "a pin circle radius of at least " + G(2.4 * 10 / 0.95, 5));
  // With a smaller required margin the same corner fits.
  s["limits"]["min_curtate_margin"] = 0.03;
  EXPECT_STREQ(ParseError(s).what(), "") << "1 - 2.4 * 10 / 25 = 0.04 >= 0.03";
}

TEST(CycloidMinSizeStudy, ARangeWhereEveryToothIsUndercutIsRefusedWithThePinRadiusThatFits) {
  // 10 pins, e = 2.2 mm, a = 25 mm (lambda 0.88): the tooth's smallest radius is (C3) minus rho.
  json s = SmallStudy();
  s["modification"]["delta_position_um"] = 0;
  s["variables"]["eccentricity_mm"] = {2.2, 2.5};
  s["variables"]["roller_position_radius_mm"] = {20, 25};
  const double centre = CentreRadius(2.2, 25, 10);
  ASSERT_GT(centre, 0.5);
  ASSERT_LT(centre, 7);
  s["variables"]["roller_radius_mm"] = {centre + 0.2, centre + 1};
  ExpectRefused(s, "/variables/roller_radius_mm/0", "a pin radius of at most " + G(centre, 5) + " mm would fit");
  s["variables"]["roller_radius_mm"] = {centre - 0.2, centre + 1};
  EXPECT_STREQ(ParseError(s).what(), "");
  // A required tooth radius: the pins must be smaller by it.
  s["limits"]["min_profile_radius_mm"] = 0.5;
  ExpectRefused(s, "/variables/roller_radius_mm/0", "a pin radius of at most " + G(centre - 0.5, 5) + " mm would fit");
}

TEST(CycloidMinSizeStudy, OverlappingPinsAndANoRoomBoreAreRefusedWithWhatFits) {
  json s = SmallStudy();
  // 10 pins on a <= 25 mm: 2 a sin(pi/10) = 15.45 mm, so pins of rho >= 8 mm overlap everywhere.
  s["variables"]["roller_position_radius_mm"] = {20, 25};
  s["variables"]["roller_radius_mm"] = {8, 9};
  ExpectRefused(s, "/variables/roller_radius_mm/0",
                "a pin radius of at most " + G(25 * std::sin(kPiHere / 10), 5) + " mm");
  s = SmallStudy();
  // The root radius a' - e - rho' at the best corner (a = 60, da = -10 um, e = 1, rho = 2):
  // 60 - 0.01 - 1 - 2 = 56.99 mm; a bore of 110 mm with a 5 mm web does not fit; 2 (56.99 - 5) does.
  s["limits"]["bore_diameter_mm"] = 110;
  s["limits"]["min_web_mm"] = 5;
  ExpectRefused(s, "/limits/bore_diameter_mm", "a bore of at most " + G(2 * (56.99 - 5), 5) + " mm diameter");
  s["limits"]["bore_diameter_mm"] = 100;
  EXPECT_STREQ(ParseError(s).what(), "");
}

TEST(CycloidMinSizeStudy, FieldsAndCombinationsTheModelDoesNotHaveAreRefused) {
  json s = SmallStudy();
  s["target"]["misalignment_mrad"] = 1;
  ExpectRefused(s, "/target/misalignment_mrad", "no misalignment");
  s = SmallStudy();
  s["variables"]["face_width_mm"] = {8, 12};
  ExpectRefused(s, "/drive/face_width_mm", "given twice");
  s = SmallStudy();
  s["variables"]["radius_mm"] = {100, 200};
  ExpectRefused(s, "/variables/radius_mm", "logarithmic");
  s = SmallStudy();
  s["crowning"] = {{"type", "none"}};
  ExpectRefused(s, "/variables/coefficient_mm", "a parameter of the logarithmic crowning only");
  s = SmallStudy();
  s["drive"].erase("face_width_mm");
  ExpectRefused(s, "/variables", "missing face_width_mm");
  s = SmallStudy();
  s["target"].erase("overload_torque_Nm");
  s["limits"]["min_edge_margin_um"] = 1;
  ExpectRefused(s, "/limits/min_edge_margin_um", "overload_torque_Nm");
  s = SmallStudy();
  s["limits"]["min_web_mm"] = 1;
  ExpectRefused(s, "/limits/min_web_mm", "bore_diameter_mm");
  s = SmallStudy();
  s["target"]["overload_torque_Nm"] = 30;
  ExpectRefused(s, "/target/overload_torque_Nm", "a torque >= design_torque_Nm");
  s = SmallStudy();
  s["variables"] = {{"eccentricity_mm", 2}, {"roller_position_radius_mm", 40}, {"roller_radius_mm", 3}};
  s["crowning"]["coefficient_mm"] = 0.005;
  ExpectRefused(s, "/variables", "nothing to size");
  s = SmallStudy();
  s["variables"]["delta_radius_um"] = {-5, 5};
  ExpectRefused(s, "/variables/delta_radius_um/1", "an upper bound <= 0");
  s = SmallStudy();
  s["optimizer"]["backend"] = "cobyla";
  ExpectRefused(s, "/optimizer/backend", "one of \"ipopt\", \"slsqp\"");
  // The datasheet limits need the compliant output mechanism; its holes must take the pins' orbit
  // at the start's eccentricity and its span the largest face width.
  const json datasheet = Example("cycloid_min_size_datasheet.json");
  s = datasheet;
  s.erase("output_mechanism");
  ExpectRefused(s, "/limits/min_torsional_stiffness_Nm_per_arcmin", "output_mechanism with pins");
  s = datasheet;
  s["output_mechanism"].erase("pin_radius_mm");
  s["output_mechanism"].erase("hole_radius_mm");
  s["output_mechanism"].erase("pin_support");
  s["output_mechanism"].erase("pin_span_mm");
  ExpectRefused(s, "/limits/min_torsional_stiffness_Nm_per_arcmin", "clearance and compliance");
  s = datasheet;
  s["output_mechanism"]["hole_radius_mm"] = 10.9;  // < 7 + 4 (the start's e)
  ExpectRefused(s, "/output_mechanism/hole_radius_mm", "a hole radius >= pin_radius_mm + e");
  s = datasheet;
  s["output_mechanism"]["pin_span_mm"] = 20;  // < the largest face width 25
  ExpectRefused(s, "/output_mechanism/pin_span_mm", "the largest face width = 25 mm");
}

// Through the command line: exit 2, one line naming the file and the path, nothing written.
TEST(CycloidMinSizeStudy, BadInputExitsTwoWithOneLine) {
  json s = SmallStudy();
  s["variables"]["roller_radius_mm"] = {5, 3};
  testing::ExpectStudyRejected(s, "cms-range", "/variables/roller_radius_mm", "[3, 5] would fit");
}

// Each example passes the work caps, and its estimate grows with the optimizer's budget.
TEST(CycloidMinSizeStudy, WorkEstimateCountsTheBudgetAndTheVariables) {
  for (const char* name : {"cycloid_min_size_paper.json", "cycloid_min_size_ratio29.json"}) {
    EXPECT_NO_THROW(studies::CheckWorkLimits(Example(name), name, 1.0)) << name;
    json s = Example(name);
    s["optimizer"]["max_evaluations"] = 100;
    json more = s;
    more["optimizer"]["max_evaluations"] = 1000;
    EXPECT_GT(studies::EstimateWork(more, name, 1.0).work, 5 * studies::EstimateWork(s, name, 1.0).work);
    json fixed = s;
    fixed["variables"]["eccentricity_mm"] = 1.0;
    EXPECT_LT(studies::EstimateWork(fixed, name, 1.0).work, studies::EstimateWork(s, name, 1.0).work);
  }
}

// The lubricated sizing (docs/lubrication.md, Sizing): cycloid_min_size_lubricated.json with and
// without its limits.min_efficiency. With it the limit binds, the accurate model meets it, and the
// drive is larger and more efficient than the same sizing without it (what the efficiency costs);
// best_cycloid_ltca.json through cycloid_ltca (its own loads, per-element losses and thermal
// balance) gives the efficiency and the oil temperature of the sizing's accurate model.
TEST(CycloidMinSizeStudy, AMinEfficiencyThatBindsCostsSizeIsVerifiedAndIsWhatCycloidLtcaReports) {
  const json base = Example("cycloid_min_size_lubricated.json");
  ASSERT_EQ(base["limits"]["min_efficiency"], 0.75);
  const auto dir = TempDir("cms-lubricated");
  json free = base;
  free["limits"].erase("min_efficiency");
  WriteFile(dir / "limited.json", base.dump());
  WriteFile(dir / "free.json", free.dump());
  json result[2];
  for (int k = 0; k < 2; ++k) {
    const std::string tag = k == 0 ? "limited" : "free";
    const auto res = RunCamopt("run " + (dir / (tag + ".json")).string() + " --quiet --out " + (dir / tag).string() +
                               " > /dev/null");
    ASSERT_EQ(res.exit_code, 0) << tag << ": " << res.stderr_text;
    result[k] = json::parse(ReadFile(dir / tag / "result.json"));
    EXPECT_EQ(result[k]["verified"], true) << tag;
  }
  const json& limited = result[0]["best"];
  const json& unlimited = result[1]["best"];
  bool binds = false;
  for (const json& b : result[0]["binding_limits"]) binds = binds || b["limit"] == "min_efficiency";
  EXPECT_TRUE(binds) << result[0]["binding_limits"].dump();
  bool checked = false;
  for (const json& c : result[0]["verification"]["checks"])
    if (c["limit"] == "min_efficiency") checked = c["holds"].get<bool>();
  EXPECT_TRUE(checked);
  const double eta = limited["accurate"]["efficiency"], eta_error = limited["estimated_error"]["efficiency"];
  EXPECT_GE(eta + eta_error, 0.75);
  EXPECT_NEAR(eta, 0.75, 1e-3);  // binding
  EXPECT_LT(eta_error, 1e-4);
  // Without the limit: smaller, and below the limit it would have had to meet.
  EXPECT_LT(unlimited["outer_diameter_mm"].get<double>(), limited["outer_diameter_mm"].get<double>());
  EXPECT_LT(unlimited["accurate"]["efficiency"].get<double>(), 0.75);
  // The oil runs warmer where more is lost (the same housing).
  EXPECT_GT(unlimited["accurate"]["oil_temperature_C"].get<double>(), limited["accurate"]["oil_temperature_C"].get<double>());
  // cycloid_ltca on the best design at the accurate settings.
  const auto ltca = RunCamopt("run " + (dir / "limited" / "best_cycloid_ltca.json").string() + " --quiet --out " +
                              (dir / "ltca").string() + " > /dev/null");
  ASSERT_EQ(ltca.exit_code, 0) << ltca.stderr_text;
  const json ltca_result = json::parse(ReadFile(dir / "ltca" / "result.json"));
  const json l = ltca_result["lubrication"];
  // With a lubricant the life block points to the efficiency instead of calling the drive frictionless.
  EXPECT_EQ(ltca_result["life"]["efficiency"].get<std::string>().rfind("lubrication.efficiency", 0), 0u)
      << ltca_result["life"]["efficiency"];
  // Two code paths over the same drive: the LTCA's contact solves differ within their tolerance.
  EXPECT_NEAR(l["efficiency"].get<double>(), eta, 5e-5);
  EXPECT_NEAR(l["oil_temperature_C"].get<double>(), limited["accurate"]["oil_temperature_C"].get<double>(), 0.05);
  EXPECT_NEAR(l["power_loss_W"]["total"].get<double>(), limited["accurate"]["power_loss_W"].get<double>(), 0.01);
  // The efficiency as the objective (no efficiency limit): the most efficient drive within the
  // ranges, more efficient than the one sized for least diameter at η >= 0.75, verified.
  json most = free;
  most["objective"] = "efficiency";
  WriteFile(dir / "most.json", most.dump());
  const auto m = RunCamopt("run " + (dir / "most.json").string() + " --quiet --out " + (dir / "most").string() +
                           " > /dev/null");
  ASSERT_EQ(m.exit_code, 0) << m.stderr_text;
  const json efficient = json::parse(ReadFile(dir / "most" / "result.json"));
  EXPECT_EQ(efficient["verified"], true);
  EXPECT_EQ(efficient["objective"], "efficiency");
  EXPECT_GT(efficient["best"]["accurate"]["efficiency"].get<double>(), eta + 1e-3);
}

// A housing that cannot give off the sized design's loss below the oil's limit: exit 3 naming the
// lubricated losses, the efficiency null with the reason beside it.
TEST(CycloidMinSizeStudy, NoThermalEquilibriumAtTheSizedDesignExitsThree) {
  json s = Example("cycloid_min_size_lubricated.json");
  s["optimizer"] = {{"backend", "slsqp"}, {"starts", 1}};
  const json res = camopt::testing::RunSizingWithoutThermalEquilibrium(s, "cms-lub-hot");
  EXPECT_TRUE(res["best"]["accurate"]["efficiency"].is_null());
  EXPECT_NE(res["best"]["accurate"]["lubrication_error"].get<std::string>().find("no equilibrium"), std::string::npos);
}

// Lubrication blocks the sizing cannot use are refused before any work: an oil-temperature limit
// with a given temperature, a limit on the losses without a lubricant.
TEST(CycloidMinSizeStudy, LubricationWithoutWhatItNeedsIsRefused) {
  const json base = Example("cycloid_min_size_lubricated.json");
  json s = base;
  s["lubricant"].erase("thermal");
  s["lubricant"]["temperature_C"] = 60;
  s["limits"]["max_oil_temperature_C"] = 80;
  testing::ExpectStudyRejected(s, "cms-lub-t", "/limits/max_oil_temperature_C", "thermal");
  s = base;
  s.erase("lubricant");
  s.erase("surfaces");
  s.erase("bearing_friction");
  testing::ExpectStudyRejected(s, "cms-lub-none", "/limits/min_efficiency", "lubricant");
}

// End to end through the command line on the small study: exit 0, verified, the accurate stress
// within its limit plus its error, the outer diameter 2 (a + rho) of the reported drive, and
// best_cycloid_ltca.json a cycloid_ltca study of that drive that runs (exit 0) and parses to it.
TEST(CycloidMinSizeStudy, EachDatasheetLimitBindsIsVerifiedAndIsWhatCycloidLtcaReports) {
  // The datasheet example with one of its four output limits at a time (and the contact stress):
  // the limit binds (the result names it, the accurate value lands on it within 1%), the accurate
  // model meets it, and best_cycloid_ltca.json run through cycloid_ltca (its own torsional curve,
  // output mechanism and crank-bearing force balance, model/cycloid/stiffness.h and
  // output_mechanism.h) reports the same four numbers as the sizing's accurate model.
  const json base = Example("cycloid_min_size_datasheet.json");
  const struct {
    const char* limit;
    double value;
    const char* result_key;
  } cases[] = {{"min_torsional_stiffness_Nm_per_arcmin", 420.0, "torsional_stiffness_Nm_per_arcmin"},
               {"max_lost_motion_arcmin", 2.3, "lost_motion_arcmin"},
               {"output_pin_stress_MPa", 440.0, "output_pin_bending_stress_MPa"},
               {"eccentric_bearing_load_N", 11500.0, "eccentric_bearing_load_N"}};
  const auto dir = TempDir("cms-datasheet");
  for (const auto& c : cases) {
    json study = base;
    study["limits"] = {{"contact_stress_MPa", 1500}, {c.limit, c.value}};
    const std::string tag = c.limit;
    WriteFile(dir / (tag + ".json"), study.dump());
    const auto res = RunCamopt("run " + (dir / (tag + ".json")).string() + " --quiet --out " + (dir / tag).string() +
                               " > /dev/null");
    ASSERT_EQ(res.exit_code, 0) << tag << ": " << res.stderr_text;
    const json r = json::parse(ReadFile(dir / tag / "result.json"));
    EXPECT_EQ(r["verified"], true) << tag;
    bool binds = false;
    for (const json& b : r["binding_limits"]) binds = binds || b["limit"] == c.limit;
    EXPECT_TRUE(binds) << tag << " is not among " << r["binding_limits"].dump();
    bool checked = false;
    for (const json& k : r["verification"]["checks"])
      if (k["limit"] == c.limit) {
        checked = true;
        EXPECT_TRUE(k["holds"].get<bool>()) << tag;
      }
    EXPECT_TRUE(checked) << tag;
    const double accurate = r["best"]["accurate"][c.result_key];
    const bool upper = std::string(c.limit) != "min_torsional_stiffness_Nm_per_arcmin";
    EXPECT_LE(upper ? accurate : c.value, upper ? c.value : accurate) << tag;  // met
    EXPECT_NEAR(accurate, c.value, 0.01 * c.value) << tag;                    // binding
    // cycloid_ltca on the best design (the accurate settings) reports the same values.
    const auto ltca = RunCamopt("run " + (dir / tag / "best_cycloid_ltca.json").string() + " --quiet --out " +
                                (dir / (tag + "-ltca")).string() + " > /dev/null");
    ASSERT_EQ(ltca.exit_code, 0) << tag << ": " << ltca.stderr_text;
    const json l = json::parse(ReadFile(dir / (tag + "-ltca") / "result.json"));
    for (const char* key : {"torsional_stiffness_Nm_per_arcmin", "lost_motion_arcmin", "output_pin_bending_stress_MPa",
                            "eccentric_bearing_load_N"}) {
      const double sized = r["best"]["accurate"][key];
      // Two runs of the same crowned-tooth LTCA by two code paths: equal within the contact
      // solves' tolerance (the crank bearing's load, a sum over the pins' load period, 4e-6).
      EXPECT_NEAR(l[key].get<double>(), sized, 1e-5 * sized) << tag << ": " << key;
    }
  }
}

TEST(CycloidMinSizeStudy, SmallStudyEndToEnd) {
  const auto dir = TempDir("cms-e2e");
  const json study = SmallStudy();
  WriteFile(dir / "study.json", study.dump());
  const auto res = RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " + (dir / "out").string() +
                             " > /dev/null");
  ASSERT_EQ(res.exit_code, 0) << res.stderr_text;
  const json r = json::parse(ReadFile(dir / "out" / "result.json"));
  EXPECT_EQ(r["verified"], true);
  const json& b = r["best"];
  ASSERT_TRUE(b.is_object());
  const double a = b["drive"]["roller_position_radius_mm"], rho = b["drive"]["roller_radius_mm"];
  EXPECT_NEAR(b["outer_diameter_mm"].get<double>(), 2 * (a + rho), 1e-9 * (a + rho));
  const double limit = study["limits"]["contact_stress_MPa"];
  EXPECT_LE(b["accurate"]["max_contact_stress_MPa"].get<double>(),
            limit + b["estimated_error"]["max_contact_stress_MPa"].get<double>());
  EXPECT_GE(b["estimated_error"]["max_contact_stress_MPa"].get<double>(), 0.0);
  // The design lies in the ranges; the fixed fields are the file's.
  EXPECT_GE(a, 25.0);
  EXPECT_LE(a, 60.0);
  EXPECT_DOUBLE_EQ(b["drive"]["face_width_mm"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(b["modification"]["delta_position_um"].get<double>(), -10.0);
  EXPECT_EQ(b["drive"]["teeth"], 9);
  EXPECT_EQ(b["drive"]["rollers"], 10);
  // The curtate and undercut margins of the reported drive, from the closed forms written out here.
  const double e = b["drive"]["eccentricity_mm"];
  const double a_mod = a - 0.010;
  EXPECT_NEAR(b["curtate_margin"].get<double>(), 1 - e * 10 / a_mod, 1e-9);
  EXPECT_GE(b["curtate_margin"].get<double>(), 0.05 - 1e-6);
  EXPECT_NEAR(b["min_profile_radius_mm"].get<double>(), CentreRadius(e, a_mod, 10) - rho, 1e-9);
  for (const char* file : {"best_cycloid_ltca.json", "stress_over_cycle.csv", "stress_over_cycle.svg",
                           "pressure_map.svg", "sized_disc.svg", "report.html"})
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / file)) << file;
  // The sized disc drawn over the start: both designs' 10 pins (9 teeth + 1), the sized pin circle.
  const std::string disc = ReadFile(dir / "out" / "sized_disc.svg");
  size_t circles = 0;
  for (size_t at = disc.find("<circle"); at != std::string::npos; at = disc.find("<circle", at + 1)) ++circles;
  EXPECT_EQ(circles, 20u);
  EXPECT_NE(disc.find("start design: disc profile"), std::string::npos);
  EXPECT_NE(disc.find("sized: disc profile"), std::string::npos);
  EXPECT_NE(disc.find("sized " + studies::Format(2 * a, 5) + " mm"), std::string::npos) << "pin circle diameter 2a";
  // The stress plot's series: one row per accurate crank angle (twice the study's per period).
  const auto csv = testing::ReadCsv(ReadFile(dir / "out" / "stress_over_cycle.csv"));
  ASSERT_EQ(csv.at("max_contact_stress_MPa").size(), 6u);

  // best_cycloid_ltca.json: the cycloid_ltca parser reads back the reported drive and crowning...
  const json ltca = json::parse(ReadFile(dir / "out" / "best_cycloid_ltca.json"));
  const auto parsed = studies::cycloid_ltca::Parse(studies::Node(&ltca, "best_cycloid_ltca.json", ""));
  EXPECT_EQ(parsed.drive.teeth, 9);
  EXPECT_DOUBLE_EQ(parsed.drive.roller_position_radius_mm, a);
  EXPECT_DOUBLE_EQ(parsed.drive.roller_radius_mm, rho);
  EXPECT_DOUBLE_EQ(parsed.drive.eccentricity_mm, e);
  EXPECT_DOUBLE_EQ(parsed.drive.delta_position_mm, -0.010);
  EXPECT_DOUBLE_EQ(parsed.torque_Nm, 40.0);
  EXPECT_EQ(parsed.crowning.type, cycloid::CrowningType::kLogarithmic);
  EXPECT_DOUBLE_EQ(parsed.crowning.coefficient_mm, b["crowning"]["coefficient_mm"].get<double>());
  EXPECT_DOUBLE_EQ(parsed.crowning.effective_length_mm, 11.0);
  // ... and `camopt run` runs it; its peak stress (the accurate settings, refined once more by its
  // error estimate) is the sizing's accurate stress within both errors.
  const auto run = RunCamopt("run " + (dir / "out" / "best_cycloid_ltca.json").string() + " --quiet --out " +
                             (dir / "ltca").string() + " > /dev/null");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const json lr = json::parse(ReadFile(dir / "ltca" / "result.json"));
  EXPECT_NEAR(lr["max_contact_stress_MPa"].get<double>(), b["accurate"]["max_contact_stress_MPa"].get<double>(),
              lr["estimated_error"]["max_contact_stress_MPa"].get<double>() +
                  b["estimated_error"]["max_contact_stress_MPa"].get<double>() + 1.0);

  // The same study again writes the same result.json (no times in the files).
  const auto again = RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " + (dir / "out2").string() +
                               " > /dev/null");
  ASSERT_EQ(again.exit_code, 0) << again.stderr_text;
  EXPECT_EQ(ReadFile(dir / "out" / "result.json"), ReadFile(dir / "out2" / "result.json"));
}

// A stress limit no design of the ranges can meet: exit 3, result.json written, one line naming
// the blocking limit, its value and the value that would fit.
TEST(CycloidMinSizeStudy, AnUnreachableStressLimitExitsThree) {
  const auto dir = TempDir("cms-exit3");
  json study = SmallStudy();
  study["limits"]["contact_stress_MPa"] = 300;
  study["optimizer"]["max_evaluations"] = 10;
  study["optimizer"]["verify_rounds"] = 1;
  WriteFile(dir / "study.json", study.dump());
  const auto res = RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " + (dir / "out").string() +
                             " > /dev/null");
  ASSERT_EQ(res.exit_code, 3) << res.stderr_text;
  EXPECT_NE(res.stderr_text.find("contact_stress_MPa"), std::string::npos) << res.stderr_text;
  EXPECT_NE(res.stderr_text.find("fits with contact_stress_MPa = "), std::string::npos) << res.stderr_text;
  const json r = json::parse(ReadFile(dir / "out" / "result.json"));
  EXPECT_EQ(r["verified"], false);
  ASSERT_TRUE(r["notes"].is_array());
}

}  // namespace cycloid_min_size_study_test
}  // namespace camopt
