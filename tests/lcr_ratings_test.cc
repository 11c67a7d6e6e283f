// lcr_analysis's catalogue numbers (docs/ratings.md): each rating re-checked by the kind run again
// at that torque; the rated torque against the rigid load law's closed form (loads proportional to
// the torque, so L10 ∝ T^(−10/3) exactly); the three segments against the run's own curve; the
// reflected inertia against its formula from the masses; the datasheet.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "studies/archive.h"
#include "studies/ratings.h"
#include "tests/test_util.h"

namespace lcr_ratings_test {

namespace t = camopt::testing;

struct CliRun {
  int exit_code = -1;
  std::string stderr_text;
  nlohmann::json result;
  std::filesystem::path out;
};

CliRun RunStudy(const nlohmann::json& study, const std::string& tag) {
  const auto dir = t::TempDir("lcr-ratings-" + tag);
  t::WriteFile(dir / "study.json", study.dump());
  const auto res = t::RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " + (dir / "out").string());
  CliRun r;
  r.exit_code = res.exit_code;
  r.stderr_text = res.stderr_text;
  r.out = dir / "out";
  if (std::filesystem::exists(r.out / "result.json")) r.result = nlohmann::json::parse(t::ReadFile(r.out / "result.json"));
  return r;
}

nlohmann::json Quick() {
  nlohmann::json s = t::Example("lcr_catalogue.json");
  s["analysis"]["angle_steps"] = 360;
  s["geometry_files"] = false;
  return s;
}

// The same reducer at one torque and speed with a life: a plain lcr_analysis run.
nlohmann::json AtTorque(nlohmann::json s, double torque_Nm, double input_rpm) {
  for (const char* k : {"ratings", "output_bearing", "external_loads", "stiffness"}) s.erase(k);
  s["load"]["output_torque_Nm"] = torque_Nm;
  s["load"]["input_speed_rpm"] = input_rpm;
  return s;
}

TEST(LcrRatings, EachRatingHoldsWhenTheKindIsRunAtThatTorque) {
  const nlohmann::json study = Quick();
  const CliRun run = RunStudy(study, "main");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const nlohmann::json& r = run.result;
  const double ratio = std::abs(r["speed_ratio"].get<double>());
  const double input_rpm = 20.0 * ratio;
  EXPECT_NEAR(r["ratings"]["rated_input_speed_rpm"].get<double>(), input_rpm, 1e-12 * input_rpm);
  const double rated = r["rated_torque_Nm"].get<double>();
  const CliRun at_rated = RunStudy(AtTorque(study, rated, input_rpm), "at-rated");
  ASSERT_EQ(at_rated.exit_code, 0) << at_rated.stderr_text;
  EXPECT_NEAR(at_rated.result["life"]["shortest_L10h"].get<double>(), 2000.0, 1e-9 * 2000.0);
  // The rigid load law: every bearing load ∝ T, so L10 ∝ T^(−10/3) (roller bearings): the life at
  // the example's 80 N·m gives the rated torque in closed form.
  const CliRun at_80 = RunStudy(AtTorque(study, 80.0, input_rpm), "at-80");
  ASSERT_EQ(at_80.exit_code, 0) << at_80.stderr_text;
  const double l80 = at_80.result["life"]["shortest_L10h"].get<double>();
  EXPECT_NEAR(rated, 80.0 * std::pow(l80 / 2000.0, 0.3), 1e-8 * rated);
  // Peak torque: the binding limit is met there.
  const double peak = r["peak_torque_Nm"].get<double>();
  const CliRun at_peak = RunStudy(AtTorque(study, peak, input_rpm), "at-peak");
  ASSERT_EQ(at_peak.exit_code, 0) << at_peak.stderr_text;
  const nlohmann::json& p = at_peak.result;
  const double stress = std::max(p["input_cam"]["max_contact_stress_MPa"].get<double>(),
                                 p["output_cam"]["max_contact_stress_MPa"].get<double>());
  const double force = std::max(p["input_cam"]["max_roller_force_N"].get<double>(),
                                p["output_cam"]["max_roller_force_N"].get<double>());
  if (r["ratings"]["peak_limited_by"] == "limits.contact_stress_MPa") {
    EXPECT_NEAR(stress, 1500.0, 1e-8 * 1500.0);
    EXPECT_LE(force, 1050.0 * (1 + 1e-9));
  } else {
    EXPECT_EQ(r["ratings"]["peak_limited_by"], "limits.roller_load_N");
    EXPECT_NEAR(force, 1050.0, 1e-8 * 1050.0);
    EXPECT_LE(stress, 1500.0 * (1 + 1e-9));
  }
  // Momentary torque: the smallest s0 is 1 there.
  const CliRun at_momentary = RunStudy(AtTorque(study, r["momentary_torque_Nm"].get<double>(), input_rpm), "at-mom");
  ASSERT_EQ(at_momentary.exit_code, 0) << at_momentary.stderr_text;
  double s0 = 1e300;
  for (const auto& row : at_momentary.result["life"]["table"])
    if (row.contains("s0") && row["s0"].is_number()) s0 = std::min(s0, row["s0"].get<double>());
  EXPECT_NEAR(s0, 1.0, 1e-8);
  EXPECT_NEAR(r["ratings"]["momentary_peaks_allowed"].get<double>(), 1e4 / (2 * (20 * ratio / 60) * 0.05),
              1e-9 * r["ratings"]["momentary_peaks_allowed"].get<double>());
}

TEST(LcrRatings, SegmentsInertiaAndDatasheet) {
  const CliRun run = RunStudy(Quick(), "segments");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const nlohmann::json& r = run.result;
  const double arcmin = 60.0 * 180.0 / M_PI;
  std::vector<double> torque, angle;
  for (const auto& p : r["joint_model"]["torsion_curve"]) {
    torque.push_back(p[0].get<double>());
    angle.push_back(p[1].get<double>() * arcmin);
  }
  auto at = [&](double tq) {
    for (size_t k = torque.size() / 2; k < torque.size(); ++k)
      if (std::abs(torque[k] - tq) < 1e-9) return angle[k];
    ADD_FAILURE() << "torque " << tq << " not sampled";
    return 0.0;
  };
  const nlohmann::json& g = r["stiffness_segments"];
  EXPECT_NEAR(g["K1_Nm_per_arcmin"].get<double>(), 16.0 / (at(16) - at(0)), 1e-9 * g["K1_Nm_per_arcmin"].get<double>());
  EXPECT_NEAR(g["K2_Nm_per_arcmin"].get<double>(), 32.0 / (at(48) - at(16)), 1e-9 * g["K2_Nm_per_arcmin"].get<double>());
  EXPECT_NEAR(g["K3_Nm_per_arcmin"].get<double>(), 32.0 / (at(80) - at(48)), 1e-9 * g["K3_Nm_per_arcmin"].get<double>());
  EXPECT_LT(g["K1_Nm_per_arcmin"].get<double>(), g["K3_Nm_per_arcmin"].get<double>());  // Palmgren contacts stiffen
  EXPECT_EQ(r["backlash_arcmin"].get<double>(), 0.0);  // conjugate profiles
  // Reflected inertia from its parts: m e² r_i² + J_c (ω_c/ω_o)², ω_c/ω_in = 1 − 13/12, ω_o/ω_in = 1/r_i.
  const nlohmann::json& m = r["masses"];
  const double ri = r["speed_ratio"].get<double>(), wc = (1.0 - 13.0 / 12.0) * ri;
  EXPECT_NEAR(m["reflected_inertia_kgm2"].get<double>(),
              m["cam_kg"].get<double>() * 4e-6 * ri * ri + m["cam_inertia_kgm2"].get<double>() * wc * wc,
              1e-12 * m["reflected_inertia_kgm2"].get<double>());
  // The cam of two 8 mm profiles near the turret radii (37, 42 mm) less nothing: between the discs
  // of the rollers' inner envelope and the turrets.
  const double rho = 7850e-9;
  EXPECT_GT(m["cam_kg"].get<double>(), rho * 8 * M_PI * (31 * 31 + 36 * 36) * 0.8);
  EXPECT_LT(m["cam_kg"].get<double>(), rho * 8 * M_PI * (37 * 37 + 42 * 42));
  const std::string html = t::ReadFile(run.out / "datasheet.html");
  for (const char* key : {"/rated_torque_Nm", "/stiffness_segments/K2_Nm_per_arcmin", "/output_bearing/L10h",
                          "/masses/cam_kg"})
    EXPECT_NE(html.find(std::string("data-source=\"") + key + "\""), std::string::npos) << key;
  // joint_model is what camopt export reads.
  const auto exported = t::RunCamopt("export " + run.out.string() + " --to json");
  EXPECT_EQ(exported.exit_code, 0) << exported.stderr_text;
}

// The allowable output speed (docs/ratings.md): the output speed at which the housing's balance at
// the rated torque puts the oil at its limit, checked by the kind's own thermal balance
// (SolveOperatingTemperature): LCR II run at the rated torque and just below that speed has its oil
// at 120 °C, just above it has no equilibrium below 120 °C, at 80 % of it runs cooler. The lubricant, surfaces and bearing friction of lcr_ii_lubricated.json.
TEST(LcrRatings, AllowableOutputSpeedPutsTheOilAtItsLimit) {
  nlohmann::json study = Quick();
  const nlohmann::json lub = t::Example("lcr_ii_lubricated.json");
  for (const char* k : {"lubricant", "surfaces", "bearing_friction"}) study[k] = lub[k];
  study["load"]["input_speed_rpm"] = 1500;
  const CliRun run = RunStudy(study, "allowable");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const nlohmann::json& g = run.result["ratings"];
  ASSERT_TRUE(g["allowable_output_speed_rpm"].is_number()) << g["allowable_output_speed"];
  const double n = g["allowable_output_speed_rpm"].get<double>(), rated = run.result["rated_torque_Nm"].get<double>();
  const double ratio = std::abs(run.result["speed_ratio"].get<double>());
  std::printf("[ ratings  ] allowable output speed %.6f rpm at the rated %.4f N m\n", n, rated);
  // Just below the speed the oil settles at the limit; just above there is no equilibrium below it.
  const CliRun hot = RunStudy(AtTorque(study, rated, (1 - 1e-7) * n * ratio), "allowable-at");
  ASSERT_EQ(hot.exit_code, 0) << hot.stderr_text;
  EXPECT_NEAR(hot.result["lubrication"]["oil_temperature_C"].get<double>(), 120.0, 1e-4);
  const CliRun over = RunStudy(AtTorque(study, rated, (1 + 1e-6) * n * ratio), "allowable-over");
  EXPECT_EQ(over.exit_code, 3);
  EXPECT_NE(over.stderr_text.find("no thermal equilibrium"), std::string::npos) << over.stderr_text;
  const CliRun cooler = RunStudy(AtTorque(study, rated, 0.8 * n * ratio), "allowable-cooler");
  ASSERT_EQ(cooler.exit_code, 0) << cooler.stderr_text;
  EXPECT_LT(cooler.result["lubrication"]["oil_temperature_C"].get<double>(), 119.0);
}

// The three torques' estimated sampling errors (|fine − half the input angles|) bound their
// distance from the same ratings on eight times the angles (2880 against the test's 360).
TEST(LcrRatings, EstimatedErrorsBoundTheConvergedRatings) {
  const CliRun fine = RunStudy(Quick(), "error-fine");
  ASSERT_EQ(fine.exit_code, 0) << fine.stderr_text;
  nlohmann::json dense = Quick();
  dense["analysis"]["angle_steps"] = 2880;
  const CliRun converged = RunStudy(dense, "error-converged");
  ASSERT_EQ(converged.exit_code, 0) << converged.stderr_text;
  const nlohmann::json& e = fine.result["ratings"]["estimated_error"];
  EXPECT_NE(e["method"].get<std::string>().find("half the input angles"), std::string::npos);
  for (const char* key : {"rated_torque_Nm", "peak_torque_Nm", "momentary_torque_Nm"}) {
    const double f = fine.result[key].get<double>(), c = converged.result[key].get<double>();
    const double estimate = e[key].get<double>();
    std::printf("[ ratings  ] %s: 360 angles %.9f, 2880 angles %.9f, |difference| %.3e, estimate %.3e\n", key, f, c,
                std::abs(f - c), estimate);
    EXPECT_LE(std::abs(f - c), estimate + 1e-9 * c) << key;
  }
}

// The ratings keys as result.json has them (RatingsKeys, declared once): without a solution every
// torque null and {"error": why} alone; with one, the numbers set (an absent rating null) and only
// keys the result schema declares, every key it requires among them.
TEST(LcrRatings, RatingsKeysWriteTheErrorAloneOrTheDeclaredKeys) {
  namespace st = camopt::studies;
  st::RatingsInput in;
  in.rated_life_h = 6000;
  in.rated_output_speed_rpm = 15;
  st::RatingsKeys failed;
  failed.Set(in, std::nullopt, "no torque reaches the rated life", 30.0, true);
  EXPECT_EQ(st::WriteResult(failed),
            nlohmann::json::parse(R"({"rated_torque_Nm": null, "peak_torque_Nm": null, "momentary_torque_Nm": null,
                                      "ratings": {"error": "no torque reaches the rated life"}})"));

  st::RatingsResult g;
  g.rated_torque_Nm = 120.0;
  g.rated_by = "input_roller";
  g.rated_L10h = 6000.0;
  g.peak_torque_Nm = 300.0;
  g.peak_by = "contact_stress_MPa";
  g.momentary_note = "no static rating";
  g.evaluations = 12;
  g.rated_error_Nm = 0.5;
  st::RatingsKeys ok;
  ok.Set(in, g, "", 30.0, true);
  const nlohmann::json j = st::WriteResult(ok);
  EXPECT_EQ(j["rated_torque_Nm"], 120.0);
  EXPECT_EQ(j["peak_torque_Nm"], 300.0);
  EXPECT_TRUE(j["momentary_torque_Nm"].is_null());
  const nlohmann::json& d = j["ratings"];
  EXPECT_FALSE(d.contains("error"));
  EXPECT_EQ(d["rated_input_speed_rpm"], 450.0);
  EXPECT_EQ(d["peak_limited_by"], "contact_stress_MPa");
  EXPECT_EQ(d["momentary_limited_by"], "no static rating");
  EXPECT_TRUE(d["allowable_output_speed_rpm"].is_null());
  EXPECT_EQ(d["estimated_error"]["rated_torque_Nm"], 0.5);
  EXPECT_TRUE(d["estimated_error"]["peak_torque_Nm"].is_null());
  EXPECT_FALSE(d.contains("momentary_peak"));

  nlohmann::ordered_json schema = nlohmann::ordered_json::object();
  st::RatingsDetails details;
  st::ResultSchemaEmitter::Describe(&details, st::Field(), schema);
  for (const auto& [key, value] : d.items()) EXPECT_TRUE(schema["properties"].contains(key)) << key;
  for (const auto& key : schema["required"]) EXPECT_TRUE(d.contains(key.get<std::string>())) << key;
}

}  // namespace lcr_ratings_test
