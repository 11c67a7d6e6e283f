// The modified rating life a_ISO through the studies (docs/life.md, "Modified rating life a_ISO";
// studies/bearing_life_io.h AddModifiedLife): the lubricated examples of lcr_analysis and
// cycloid_ltca with each bearing's fatigue load limit C_u and pitch diameter D_pw and the oil's
// contamination factor e_C. Each row's a_ISO and L_nm_h are recomputed here from the same
// result's own inputs (the oil temperature, the bearing's revolutions and equivalent load, L10h)
// with ISO 281:2007's equations written out independently (eq. 28 for ν1, eqs. 31–36 for a_ISO)
// and the oil's viscosity from ν40 and ν100 by the ASTM D341 (Walther) law. Bad input: exit 2
// naming the JSON path.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/cycloid_ltca_study.h"
#include "studies/lcr_analysis_study.h"
#include "tests/test_util.h"

namespace camopt {
namespace modified_life_study_test {

using camopt::testing::Example;
using camopt::testing::ExpectStudyRejected;

/// The hand calculation repeats the code's arithmetic in another order: a few roundings of pow.
constexpr double kHandCalcRelTol = 1e-9;

// ASTM D341: log10 log10(ν + 0.7) = A − B log10(T_K) through (40 °C, ν40) and (100 °C, ν100).
double WaltherViscosity(double nu40, double nu100, double t_C) {
  const double z40 = std::log10(std::log10(nu40 + 0.7)), z100 = std::log10(std::log10(nu100 + 0.7));
  const double x40 = std::log10(313.15), x100 = std::log10(373.15);
  const double b = (z40 - z100) / (x100 - x40), a = z40 + b * x40;
  return std::pow(10.0, std::pow(10.0, a - b * std::log10(t_C + 273.15))) - 0.7;
}

// ISO 281:2007 eq. 28.
double Nu1(double n, double dpw) {
  return n < 1000 ? 45000 * std::pow(n, -0.83) / std::sqrt(dpw) : 4500 / std::sqrt(n) / std::sqrt(dpw);
}

// ISO 281:2007 eqs. 31–36, κ in [0.1, 4] (κ > 4 taken as 4), capped at 50.
double AIso(bool ball, double kappa, double x) {
  const double k = std::min(kappa, 4.0);
  const double p = k < 0.4 ? 0.054381 : (k < 1 ? 0.19087 : 0.071739);
  double c;
  if (ball) c = k < 0.4 ? 2.2649 : 1.9987;
  else c = k < 0.4 ? 1.3993 : 1.2348;
  const double bracket = ball ? 1 - std::pow(2.5671 - c / std::pow(k, p), 0.83) * std::pow(x, 1.0 / 3)
                              : 1 - (1.5859 - c / std::pow(k, p)) * std::pow(x, 0.4);
  return bracket <= 0 ? 50.0 : std::min(50.0, 0.1 * std::pow(bracket, ball ? -9.3 : -9.185));
}

// Checks one life-table row against the hand calculation; returns its L_nm_h.
double ExpectRowByHand(const nlohmann::json& row, const nlohmann::json& study, double t_C, double input_rpm,
                       double cu, double dpw, double ec) {
  SCOPED_TRACE(row["element"].get<std::string>());
  const double nu = WaltherViscosity(study["lubricant"]["nu40_cSt"], study["lubricant"]["nu100_cSt"], t_C);
  const double n = row["revolutions_per_input_revolution"].get<double>() * input_rpm;
  const double nu1 = Nu1(n, dpw), kappa = nu / nu1;
  EXPECT_GE(kappa, 0.1);
  const double x = ec * cu / row["equivalent_load_N"].get<double>();
  const double a = AIso(row["kind"] == "ball", kappa, x);
  const double l_nm = a * row["L10h"].get<double>();
  EXPECT_NEAR(row["oil_temperature_C"].get<double>(), t_C, 0.0);
  EXPECT_NEAR(row["viscosity_mm2_s"].get<double>(), nu, kHandCalcRelTol * nu);
  EXPECT_NEAR(row["reference_viscosity_mm2_s"].get<double>(), nu1, kHandCalcRelTol * nu1);
  EXPECT_NEAR(row["kappa"].get<double>(), kappa, kHandCalcRelTol * kappa);
  EXPECT_EQ(row["contamination_factor"].get<double>(), ec);
  EXPECT_EQ(row["fatigue_load_limit_N"].get<double>(), cu);
  EXPECT_NEAR(row["a_ISO"].get<double>(), a, 1e-8 * a);
  EXPECT_NEAR(row["L_nm_h"].get<double>(), l_nm, 1e-8 * l_nm);
  return l_nm;
}

const nlohmann::json& Row(const nlohmann::json& life, const std::string& element) {
  for (const auto& r : life["table"])
    if (r["element"] == element) return r;
  throw std::runtime_error("no row " + element);
}

// The LCR example with C_u ≈ C0/8.5 and D_pw of the Palmgren mean diameters (illustrative), e_C 0.5
// (normal cleanliness); no efficiency map (not needed here).
nlohmann::json LcrStudy() {
  nlohmann::json s = Example("lcr_ii_lubricated.json");
  s.erase("efficiency_map");
  for (const char* side : {"input", "output"}) {
    s["reducer"][side]["fatigue_load_limit_N"] = 400;
    s["reducer"][side]["pitch_diameter_mm"] = 8;
  }
  s["reducer"]["eccentric_bearing"]["fatigue_load_limit_N"] = 1300;
  s["reducer"]["eccentric_bearing"]["pitch_diameter_mm"] = 16;
  s["lubricant"]["contamination_factor"] = 0.5;
  return s;
}

nlohmann::json RunLcr(const nlohmann::json& study) {
  const studies::Node root(&study, "lcr.json", "");
  const studies::lcr_analysis::Study st = studies::lcr_analysis::Parse(root);
  return studies::WriteResult(studies::lcr_analysis::Run(st, {"lcr.json", true}));
}

TEST(ModifiedLifeStudy, LcrRowsMatchTheHandCalculation) {
  const nlohmann::json study = LcrStudy();
  const nlohmann::json result = RunLcr(study);
  const nlohmann::json& life = result["life"];
  const double t = result["lubrication"]["oil_temperature_C"], rpm = study["load"]["input_speed_rpm"];
  double shortest = INFINITY;
  for (const char* element : {"input_roller", "output_roller"})
    shortest = std::min(shortest, ExpectRowByHand(Row(life, element), study, t, rpm, 400, 8, 0.5));
  shortest = std::min(shortest, ExpectRowByHand(Row(life, "eccentric_bearing"), study, t, rpm, 1300, 16, 0.5));
  EXPECT_NEAR(life["shortest_L_nm_h"].get<double>(), shortest, 1e-8 * shortest);
  EXPECT_NE(life["model"].get<std::string>().find("a1 a_ISO L10"), std::string::npos);
  EXPECT_EQ(life["model"].get<std::string>().find("not modelled"), std::string::npos);
  // The basic lives are those of the study without the new fields.
  const nlohmann::json plain_study = [] {
    nlohmann::json s = Example("lcr_ii_lubricated.json");
    s.erase("efficiency_map");
    return s;
  }();
  const nlohmann::json plain = RunLcr(plain_study)["life"];
  EXPECT_EQ(plain["shortest_L10h"], life["shortest_L10h"]);
  EXPECT_FALSE(plain.contains("shortest_L_nm_h"));
  EXPECT_FALSE(plain["table"][0].contains("a_ISO"));
  EXPECT_NE(plain["model"].get<std::string>().find("the modified life (a1, a_ISO) is not modelled"),
            std::string::npos);
}

// κ below 0.1 (a pitch diameter so small that ν1 is far above the oil's ν): a_ISO null, the note
// says why, L_nm_h null, and the bearing is not in shortest_L_nm_h.
TEST(ModifiedLifeStudy, KappaBelowTheMethodIsNotExtrapolated) {
  nlohmann::json study = LcrStudy();
  study["reducer"]["eccentric_bearing"]["pitch_diameter_mm"] = 1e-4;
  const nlohmann::json life = RunLcr(study)["life"];
  const nlohmann::json& row = Row(life, "eccentric_bearing");
  EXPECT_LT(row["kappa"].get<double>(), 0.1);
  EXPECT_TRUE(row["a_ISO"].is_null());
  EXPECT_TRUE(row["L_nm_h"].is_null());
  EXPECT_NE(row["a_ISO_note"].get<std::string>().find("below 0.1"), std::string::npos);
  EXPECT_NE(life["shortest_L_nm_bearing"], "eccentric_bearing");
}

TEST(ModifiedLifeStudy, LcrBadInputExits2NamingThePath) {
  // The fields without a lubricant (lcr_ii_life.json: a life, no oil).
  nlohmann::json s = Example("lcr_ii_life.json");
  s["reducer"]["input"]["fatigue_load_limit_N"] = 400;
  s["reducer"]["input"]["pitch_diameter_mm"] = 8;
  ExpectStudyRejected(s, "aiso-no-lubricant", "/reducer/input/fatigue_load_limit_N", "needs the oil: a \"lubricant\"");
  // C_u without D_pw.
  s = LcrStudy();
  s["reducer"]["output"].erase("pitch_diameter_mm");
  ExpectStudyRejected(s, "aiso-no-dpw", "/reducer/output/pitch_diameter_mm", "pitch diameter D_pw");
  // D_pw without C_u.
  s = LcrStudy();
  s["reducer"]["eccentric_bearing"].erase("fatigue_load_limit_N");
  ExpectStudyRejected(s, "aiso-no-cu", "/reducer/eccentric_bearing/fatigue_load_limit_N", "fatigue load limit C_u");
  // No contamination factor.
  s = LcrStudy();
  s["lubricant"].erase("contamination_factor");
  ExpectStudyRejected(s, "aiso-no-ec", "/lubricant/contamination_factor", "contamination factor e_C");
  // A contamination factor with no bearing to use it.
  s = Example("lcr_ii_lubricated.json");
  s["lubricant"]["contamination_factor"] = 0.5;
  ExpectStudyRejected(s, "aiso-ec-alone", "/lubricant/contamination_factor", "none does");
  // e_C outside [0, 1].
  s = LcrStudy();
  s["lubricant"]["contamination_factor"] = 1.5;
  ExpectStudyRejected(s, "aiso-ec-range", "/lubricant/contamination_factor", "1");
}

// The cycloid example: the crank bearing (a cylindrical roller bearing on the 40 mm eccentric,
// D_pw 55 mm as its Palmgren mean diameter, C_u 6500 N) and the ring pins (D_pw 11 mm, C_u 900 N),
// e_C 0.3 (slight contamination); no efficiency map.
TEST(ModifiedLifeStudy, CycloidRowsMatchTheHandCalculation) {
  nlohmann::json study = Example("cycloid_ltca_lubricated.json");
  study.erase("efficiency_map");
  study["crank_bearing"]["fatigue_load_limit_N"] = 6500;
  study["crank_bearing"]["pitch_diameter_mm"] = 55;
  study["pins"]["fatigue_load_limit_N"] = 900;
  study["pins"]["pitch_diameter_mm"] = 11;
  study["lubricant"]["contamination_factor"] = 0.3;
  const studies::Node root(&study, "cycloid.json", "");
  const studies::cycloid_ltca::Study st = studies::cycloid_ltca::Parse(root);
  const nlohmann::json result = studies::WriteResult(studies::cycloid_ltca::Run(st, {"cycloid.json", true}));
  const nlohmann::json& life = result["life"];
  const double t = result["lubrication"]["oil_temperature_C"], rpm = study["load"]["input_speed_rpm"];
  const double crank = ExpectRowByHand(Row(life, "crank_bearing"), study, t, rpm, 6500, 55, 0.3);
  const double pins = ExpectRowByHand(Row(life, "pins"), study, t, rpm, 900, 11, 0.3);
  EXPECT_NEAR(life["shortest_L_nm_h"].get<double>(), std::min(crank, pins), 1e-8 * std::min(crank, pins));
  // The rating blocks of a kind without the modified life refuse the fields as unknown.
  nlohmann::json tuning = Example("cycloid_crowning_tuning_nnm.json");
  tuning["crank_bearing"] = {{"kind", "roller"}, {"dynamic_rating_N", 60000}, {"fatigue_load_limit_N", 6500},
                             {"pitch_diameter_mm", 55}};
  ExpectStudyRejected(tuning, "aiso-tuning", "/crank_bearing/fatigue_load_limit_N", "unknown field");
  // The fields without a lubricant.
  nlohmann::json dry = Example("cycloid_ltca_life.json");
  dry["pins"]["fatigue_load_limit_N"] = 900;
  dry["pins"]["pitch_diameter_mm"] = 11;
  ExpectStudyRejected(dry, "aiso-cycloid-dry", "/pins/fatigue_load_limit_N", "needs the oil");
}

}  // namespace modified_life_study_test
}  // namespace camopt
