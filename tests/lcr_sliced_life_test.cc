// The sliced life of the LCR's rollers under the 3D contact's tilt and crowning (lcr_analysis with
// a "contact" model and a speed; model/lcr/sliced_life.h, docs/life.md "Sliced roller life under
// tilt"): the reported life recombined by hand from the reported slice loads, and the tilt's effect.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/lcr_analysis_study.h"
#include "studies/lcr_crowning_tuning_study.h"
#include "tests/test_util.h"

namespace camopt {
namespace lcr_sliced_life_test {

using camopt::testing::ReadFile;
using camopt::testing::SourcePath;

nlohmann::json TiltStudy(double misalignment_mrad) {
  nlohmann::json s = nlohmann::json::parse(ReadFile(SourcePath("studies/examples/lcr_ii_crowned.json")));
  s["analysis"]["angle_steps"] = 144;
  s["contact"]["slices"] = 12;
  s["contact"]["misalignment_mrad"] = misalignment_mrad;
  s["load"]["input_speed_rpm"] = 1000;
  for (const char* side : {"input", "output"}) {
    s["reducer"][side]["dynamic_rating_N"] = 3300;
    s["reducer"][side]["static_rating_N"] = 3400;
  }
  return s;
}

nlohmann::json RunJson(const nlohmann::json& s) {
  const studies::Node root(&s, "s.json", "");
  const auto st = studies::lcr_analysis::Parse(root);
  return studies::WriteResult(studies::lcr_analysis::Run(st, {"s.json", true}));
}

// One duty line: slice k lives L_k = 10⁶ (C_k/P_k)^(10/3) / (60 n R), C_k = C·12^(−7/9), and the
// roller 1/L^(27/20) = Σ 1/L_k^(27/20) (the slices' equivalent loads as reported).
TEST(LcrSlicedLife, ReportedLifeRecombinedByHand) {
  const nlohmann::json j = RunJson(TiltStudy(0.5));
  const nlohmann::json& life = j["life"];
  for (const char* name : {"input_roller", "output_roller"}) {
    SCOPED_TRACE(name);
    const nlohmann::json& b = life[name];
    const nlohmann::json& sl = b["sliced"];
    const double ck = 3300 * std::pow(12.0, -7.0 / 9.0);
    EXPECT_NEAR(sl["slice_rating_N"].get<double>(), ck, 1e-12 * ck);
    const double speed = 1000 * b["revolutions_per_input_revolution"].get<double>();
    double sum = 0, total = 0;
    for (double pk : sl["slice_equivalent_load_N"].get<std::vector<double>>()) {
      total += pk;
      if (pk > 0) sum += std::pow(1e6 * std::pow(ck / pk, 10.0 / 3.0) / (60 * speed), -27.0 / 20.0);
    }
    const double expected = std::pow(sum, -20.0 / 27.0);
    EXPECT_NEAR(sl["L10h"].get<double>(), expected, 1e-10 * expected);
    EXPECT_EQ(life[std::string(name) + "_sliced_L10h"], sl["L10h"]);
    // The slices' p-means add up to at least the roller's (Minkowski: the p-mean of a sum is at
    // most the sum of the p-means), the same loads cut along the roller.
    EXPECT_GE(total, b["equivalent_load_N"].get<double>() * (1 - 1e-12));
    EXPECT_EQ(sl["misalignment_mrad"].get<double>(), 0.5);
  }
}

// More tilt loads one end more: the sliced life falls, the unsliced one (ISO 281 on the roller's
// total load) does not change.
TEST(LcrSlicedLife, TiltShortensTheSlicedLifeOnly) {
  const nlohmann::json a = RunJson(TiltStudy(0.0))["life"], b = RunJson(TiltStudy(1.0))["life"];
  for (const char* name : {"input_roller", "output_roller"}) {
    SCOPED_TRACE(name);
    EXPECT_EQ(a[std::string(name) + "_L10h"], b[std::string(name) + "_L10h"]);
    EXPECT_LT(b[std::string(name) + "_sliced_L10h"].get<double>(), a[std::string(name) + "_sliced_L10h"].get<double>());
  }
  EXPECT_FALSE(a.contains("eccentric_bearing_sliced_L10h"));
}

// lcr_crowning_tuning with a speed: the tuned design's lives are those lcr_analysis computes for
// the same design (tuned crowning, each misalignment, the tuning's angle steps and slices).
TEST(LcrSlicedLife, TuningReportsTheTunedDesignsLives) {
  nlohmann::json t = nlohmann::json::parse(ReadFile(SourcePath("studies/examples/lcr_crowning_tuning.json")));
  t["tuning"]["curve_points"] = 3;
  t["tuning"]["refine_iterations"] = 1;
  t["tuning"]["angle_steps"] = 72;
  t["tuning"]["slices"] = 10;
  t["tuning"]["half_space_check"] = false;
  t["load"]["input_speed_rpm"] = 1000;
  for (const char* side : {"input", "output"}) t["reducer"][side]["dynamic_rating_N"] = 3300;
  const studies::Node troot(&t, "t.json", "");
  const auto tst = studies::lcr_crowning_tuning::Parse(troot);
  const nlohmann::json tj = studies::WriteResult(studies::lcr_crowning_tuning::Run(tst, {"t.json", true}));
  ASSERT_TRUE(tj.contains("life"));
  const nlohmann::json& life = tj["life"];
  ASSERT_EQ(life["sliced"].size(), 2u);  // 0 and 1 mrad
  for (size_t g = 0; g < 2; ++g) {
    const double mrad = life["sliced"][g]["misalignment_mrad"].get<double>();
    SCOPED_TRACE(mrad);
    nlohmann::json a = nlohmann::json::parse(ReadFile(SourcePath("studies/examples/lcr_ii_crowned.json")));
    a["analysis"] = {{"angle_steps", 72}, {"evaluate", {"forces", "stress"}}};
    a["contact"] = {{"model", "slices"}, {"slices", 10}, {"misalignment_mrad", mrad}};
    a["load"]["input_speed_rpm"] = 1000;
    for (const char* side : {"input", "output"}) {
      a["reducer"][side]["dynamic_rating_N"] = 3300;
      a["reducer"][side]["crowning"]["coefficient_mm"] = tj[side]["crowning"]["coefficient_mm"];
    }
    const nlohmann::json aj = RunJson(a);
    const nlohmann::json& al = aj["life"];
    for (const char* name : {"input_roller", "output_roller"}) {
      const double sliced = life["sliced"][g][std::string(name) + "_sliced_L10h"].get<double>();
      EXPECT_NEAR(sliced, al[std::string(name) + "_sliced_L10h"].get<double>(), 1e-12 * sliced) << name;
      EXPECT_NEAR(life[std::string(name) + "_L10h"].get<double>(), al[std::string(name) + "_L10h"].get<double>(),
                  1e-12 * sliced)
          << name;
    }
  }
  EXPECT_EQ(life["table"].size(), 6u);  // two rollers, each sliced at two misalignments
}

}  // namespace lcr_sliced_life_test
}  // namespace camopt
