// cycloid_ltca's catalogue numbers (docs/ratings.md): each rating re-checked by a separate run of
// the kind at that torque (the round trip), the momentary-peak count and the masses by hand, the
// three segments against the run's own torsional curve, joint_model against the headline numbers,
// datasheet.html against result.json, and the bad-input paths.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <regex>

#include <nlohmann/json.hpp>

#include "model/common/geometry.h"
#include "studies/cycloid_ratings.h"
#include "tests/test_util.h"

namespace cycloid_ratings_test {

using camopt::kPi;
namespace t = camopt::testing;

// The catalogue example made fast: 8 angles per mesh period (whole periods), 16 × 16 cells.
nlohmann::json Quick() {
  nlohmann::json s = t::Example("cycloid_catalogue.json");
  s["analysis"]["grid"] = {16, 16};
  s["analysis"]["crank_angles_per_mesh_period"] = 8;
  s["analysis"]["estimate_error"] = false;
  s["geometry_files"] = false;
  return s;
}

struct CliRun {
  int exit_code = -1;
  std::string stderr_text;
  nlohmann::json result;
  std::filesystem::path out;
};

CliRun RunStudy(const nlohmann::json& study, const std::string& tag) {
  const auto dir = t::TempDir("cycloid-ratings-" + tag);
  t::WriteFile(dir / "study.json", study.dump());
  const auto res = t::RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " + (dir / "out").string());
  CliRun r;
  r.exit_code = res.exit_code;
  r.stderr_text = res.stderr_text;
  r.out = dir / "out";
  if (std::filesystem::exists(r.out / "result.json"))
    r.result = nlohmann::json::parse(t::ReadFile(r.out / "result.json"));
  return r;
}

// The same drive at one torque and output speed with a life: a plain cycloid_ltca run (no ratings).
nlohmann::json AtTorque(nlohmann::json s, double torque_Nm, double output_rpm) {
  for (const char* k : {"ratings", "output_bearing", "external_loads", "stiffness", "limits"}) s.erase(k);
  s["load"] = {{"torque_Nm", torque_Nm}, {"input_speed_rpm", output_rpm * 15.0}};
  return s;
}

TEST(CycloidRatings, EachRatingHoldsWhenTheKindIsRunAtThatTorque) {
  const nlohmann::json study = Quick();
  const CliRun run = RunStudy(study, "main");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const nlohmann::json& r = run.result;
  const double rated = r["rated_torque_Nm"].get<double>();
  const double peak = r["peak_torque_Nm"].get<double>();
  const double momentary = r["momentary_torque_Nm"].get<double>();
  EXPECT_GT(rated, 0.0);
  EXPECT_GT(peak, 0.0);
  EXPECT_GT(momentary, 0.0);
  // Rated torque ↔ L10h: the drive run at the rated torque and 15 rpm (225 rpm input) lives 6000 h.
  const CliRun at_rated = RunStudy(AtTorque(study, rated, 15.0), "at-rated");
  ASSERT_EQ(at_rated.exit_code, 0) << at_rated.stderr_text;
  // The search stops at a bracket of kRatingSearchRelTolerance (1e-6) of the torque, and L10 goes
  // as T^(-10/3) for the roller bearings: the life is the rated life within 10/3 · 1e-6 of it.
  EXPECT_NEAR(at_rated.result["life"]["shortest_L10h"].get<double>(), 6000.0, 10.0 / 3.0 * 1e-6 * 6000.0);
  EXPECT_EQ(at_rated.result["life"]["shortest_bearing"], r["ratings"]["rated_by"]);
  // Peak torque: the largest contact stress there is the limit, 2000 MPa.
  const CliRun at_peak = RunStudy(AtTorque(study, peak, 15.0), "at-peak");
  ASSERT_EQ(at_peak.exit_code, 0) << at_peak.stderr_text;
  EXPECT_EQ(r["ratings"]["peak_limited_by"], "limits.contact_stress_MPa");
  // Within the search's bracket, kRatingSearchRelTolerance (1e-6) of the torque: the Hertz peak
  // grows as T^(1/2) at most (less as the contact spreads), so within 0.5e-6 of the limit.
  EXPECT_NEAR(at_peak.result["max_contact_stress_MPa"].get<double>(), 2000.0, 0.5e-6 * 2000.0);
  // Momentary torque: the limiting bearing's s0 = C0 / P0max is 1 there, the other's above.
  const CliRun at_momentary = RunStudy(AtTorque(study, momentary, 15.0), "at-momentary");
  ASSERT_EQ(at_momentary.exit_code, 0) << at_momentary.stderr_text;
  double smallest_s0 = 1e300;
  for (const auto& row : at_momentary.result["life"]["table"]) smallest_s0 = std::min(smallest_s0, row["s0"].get<double>());
  // Within the LTCA contact solver's tolerance (its loads move by ~1e-6 between neighbouring torques).
  EXPECT_NEAR(smallest_s0, 1.0, 1e-5);
  // Momentary peaks allowed: 1e4 / (2 (n R / 60) t) = 1e4 / (2 · (15 · 15 / 60) · 0.05) = 26 666.67.
  EXPECT_NEAR(r["ratings"]["momentary_peaks_allowed"].get<double>(), 1e4 / 0.375, 1e-8);
  // Ordering a designer expects: rated < peak and rated < momentary.
  EXPECT_LT(rated, peak);
  EXPECT_LT(rated, momentary);
}

TEST(CycloidRatings, EstimatedErrorsBoundTheRatingsOfAFinerModel) {
  // Coarse (16 × 16 cells, 8 angles per mesh period) with its error estimate against a finer model
  // (32 × 32, 16 angles): each coarse rating is within its estimated error (plus the finer one's) of
  // the finer rating, and the finer model's estimate is the smaller.
  nlohmann::json coarse = Quick();
  coarse["analysis"]["estimate_error"] = true;
  nlohmann::json fine = coarse;
  fine["analysis"]["grid"] = {32, 32};
  fine["analysis"]["crank_angles_per_mesh_period"] = 16;
  const CliRun c = RunStudy(coarse, "error-coarse"), f = RunStudy(fine, "error-fine");
  ASSERT_EQ(c.exit_code, 0) << c.stderr_text;
  ASSERT_EQ(f.exit_code, 0) << f.stderr_text;
  for (const char* key : {"rated_torque_Nm", "peak_torque_Nm", "momentary_torque_Nm"}) {
    const double tc = c.result[key].get<double>(), tf = f.result[key].get<double>();
    const double ec = c.result["ratings"]["estimated_error"][key].get<double>();
    const double ef = f.result["ratings"]["estimated_error"][key].get<double>();
    std::printf("[ ratings  ] %s: coarse %.3f ± %.3f, fine %.3f ± %.3f N m\n", key, tc, ec, tf, ef);
    EXPECT_LE(std::abs(tc - tf), ec + ef) << key;
    EXPECT_LT(ef, ec) << key;
    EXPECT_GT(ec, 0.0) << key;
  }
}

TEST(CycloidRatings, EstimatedErrorsBoundACrankConvergedRatingWhoseLoadPeakTheStudysAnglesMiss) {
  // 8 mm rollers, no crowning, 20 × 20 cells, 10 000 h at 25 rpm, pins C0 9 kN: the pins' largest
  // static load falls between the 16 angles a period (momentary 1764.6 N·m on them, 1757.5 at 64 and
  // 1757.1 at 128 angles). The ratings with their estimate hold the 64-angle ratings (no estimate)
  // within the estimated error; a crank part from a subset of the 16 angles (|16 − 8|) did not
  // (1764.58 ± 4.88 against 1757.54).
  nlohmann::json s = t::Example("cycloid_catalogue.json");
  s["crowning"] = {{"type", "none"}};
  s["drive"]["roller_radius_mm"] = 8;
  s["pins"]["static_rating_N"] = 9000;
  s["limits"]["contact_stress_MPa"] = 1800;
  s["ratings"]["rated_life_h"] = 10000;
  s["ratings"]["rated_output_speed_rpm"] = 25;
  s["ratings"]["momentary_peaks"]["output_speed_rpm"] = 25;
  s["analysis"]["grid"] = {20, 20};
  s["analysis"]["crank_angles_per_mesh_period"] = 16;
  for (const char* k : {"output_bearing", "external_loads", "stiffness"}) s.erase(k);
  s["geometry_files"] = false;
  nlohmann::json reference = s;
  reference["analysis"]["crank_angles_per_mesh_period"] = 64;
  reference["analysis"]["estimate_error"] = false;
  const CliRun run = RunStudy(s, "crank-16"), ref = RunStudy(reference, "crank-64");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  ASSERT_EQ(ref.exit_code, 0) << ref.stderr_text;
  for (const char* key : {"rated_torque_Nm", "peak_torque_Nm", "momentary_torque_Nm"}) {
    const double v = run.result[key].get<double>(), v_ref = ref.result[key].get<double>();
    const double e = run.result["ratings"]["estimated_error"][key].get<double>();
    std::printf("[ ratings  ] %s: 16 angles %.3f ± %.3f, 64 angles %.3f N m\n", key, v, e, v_ref);
    EXPECT_LE(std::abs(v - v_ref), e) << key;
  }
}

TEST(CycloidRatings, ThreeSegmentsAreTheSlopesOfTheRunsOwnCurve) {
  const CliRun run = RunStudy(Quick(), "segments");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const nlohmann::json& r = run.result;
  // The curve at full precision: joint_model.torsion_curve, [torque N·m, angle rad] from −T_r to T_r
  // (hysteresis.csv holds the same points to fewer digits).
  const double arcmin = 60.0 * 180.0 / kPi;
  std::vector<double> torque, angle;
  for (const auto& p : r["joint_model"]["torsion_curve"]) {
    torque.push_back(p[0].get<double>());
    angle.push_back(p[1].get<double>() * arcmin);
  }
  const size_t n = torque.size();
  ASSERT_EQ(n % 2, 0u);
  auto at = [&](double tq) {
    for (size_t k = n / 2; k < n; ++k)  // 0+ … T_r
      if (std::abs(torque[k] - tq) < 1e-9) return angle[k];
    ADD_FAILURE() << "torque " << tq << " not sampled";
    return 0.0;
  };
  const double zero_plus = angle[n / 2];
  ASSERT_EQ(torque[n / 2], 0.0);
  ASSERT_EQ(torque[n / 2 - 1], 0.0);  // 0− then 0+
  const nlohmann::json& g = r["stiffness_segments"];
  EXPECT_NEAR(g["K1_Nm_per_arcmin"].get<double>(), 70.0 / (at(70) - zero_plus), 1e-9 * g["K1_Nm_per_arcmin"].get<double>());
  EXPECT_NEAR(g["K2_Nm_per_arcmin"].get<double>(), 140.0 / (at(210) - at(70)), 1e-9 * g["K2_Nm_per_arcmin"].get<double>());
  EXPECT_NEAR(g["K3_Nm_per_arcmin"].get<double>(), 140.0 / (at(350) - at(210)), 1e-9 * g["K3_Nm_per_arcmin"].get<double>());
  // Hertzian contacts stiffen with load: K1 < K2 < K3.
  EXPECT_LT(g["K1_Nm_per_arcmin"].get<double>(), g["K2_Nm_per_arcmin"].get<double>());
  EXPECT_LT(g["K2_Nm_per_arcmin"].get<double>(), g["K3_Nm_per_arcmin"].get<double>());
  // Lost motion at ±5%: 17.5 N·m sampled on both branches.
  auto at_signed = [&](double tq) {
    for (size_t k = 0; k < n; ++k)
      if (std::abs(torque[k] - tq) < 1e-9) return angle[k];
    ADD_FAILURE() << "torque " << tq << " not sampled";
    return 0.0;
  };
  EXPECT_NEAR(r["stiffness"]["lost_motion_at_percent_arcmin"].get<double>(), at_signed(17.5) - at_signed(-17.5), 1e-9);
  // joint_model: the same numbers in SI units.
  const nlohmann::json& j = r["joint_model"];
  EXPECT_NEAR(j["stiffness_Nm_per_rad"].get<double>(), r["torsional_stiffness_Nm_per_arcmin"].get<double>() * arcmin,
              1e-9 * j["stiffness_Nm_per_rad"].get<double>());
  EXPECT_NEAR(j["backlash_rad"].get<double>() * arcmin, r["backlash_arcmin"].get<double>(), 1e-12);
  EXPECT_NEAR(j["stiffness_segments"]["K3_Nm_per_rad"].get<double>(), g["K3_Nm_per_arcmin"].get<double>() * arcmin,
              1e-9 * j["stiffness_segments"]["K3_Nm_per_rad"].get<double>());
  EXPECT_EQ(j["ratio"].get<double>(), 15.0);
  // The same curve as hysteresis.csv's loading branch (to the CSV's digits).
  const auto h = t::ReadCsv(t::ReadFile(run.out / "hysteresis.csv"));
  ASSERT_EQ(h.at("output_torque_Nm").size(), 2 * n);
  for (size_t k = 0; k < n; ++k) EXPECT_NEAR(h.at("output_angle_arcmin")[k], angle[k], 1e-6 * std::abs(angle[k]) + 1e-9);
}

TEST(CycloidRatings, MassesOfACircularDiscWithABoreAndHolesAreTheClosedForms) {
  // A "profile" that is a circle of radius 80 mm (4000 sides): area π R², polar moment π R⁴/2;
  // minus a 40 mm bore and 8 holes of radius 11.505 mm on a 50 mm circle (parallel axes).
  camopt::cycloid::Drive d;
  d.teeth = 15, d.rollers = 16, d.roller_position_radius_mm = 90, d.roller_radius_mm = 7.2;
  d.eccentricity_mm = 4.5, d.face_width_mm = 17;
  std::vector<camopt::Vec2<double>> circle;
  const int sides = 4000;
  const double R = 80.0;
  for (int k = 0; k < sides; ++k) circle.emplace_back(R * std::cos(2 * kPi * k / sides), R * std::sin(2 * kPi * k / sides));
  camopt::cycloid::OutputPins pins;
  pins.pins = 8, pins.pin_circle_radius_mm = 50, pins.pin_radius_mm = 7, pins.hole_radius_mm = 11.505;
  const auto m = camopt::studies::cycloid_common::CycloidMasses(d, circle, 1, 17.0, 40.0, &pins, 20.0, 7850.0);
  const double rb = 20.0, rh = 11.505;
  const double area = kPi * R * R - kPi * rb * rb - 8 * kPi * rh * rh;                                        // mm²
  const double polar = kPi * std::pow(R, 4) / 2 - kPi * std::pow(rb, 4) / 2 - 8 * (kPi * std::pow(rh, 4) / 2 + kPi * rh * rh * 2500);
  const double rho = 7850e-9;  // kg/mm³
  // The polygon's area falls short of the circle's by (2π²/3)/sides² of it.
  EXPECT_NEAR(m.disc_kg, rho * area * 17.0, 2e-6 * m.disc_kg);
  EXPECT_NEAR(m.disc_inertia_kgm2, rho * polar * 17.0 * 1e-6, 4e-6 * m.disc_inertia_kgm2);
  // Reflected: m e² i² + J_d with i = 15.
  EXPECT_NEAR(m.reflected_inertia_kgm2, m.disc_kg * 0.0045 * 0.0045 * 225.0 + m.disc_inertia_kgm2, 1e-15);
  EXPECT_NEAR(m.ring_pins_kg, rho * kPi * 7.2 * 7.2 * 17.0 * 16, 1e-12);
  EXPECT_NEAR(m.output_pins_kg, rho * kPi * 49.0 * 20.0 * 8, 1e-12);
}

TEST(CycloidRatings, DatasheetShowsEveryNumberOfResultJsonItNames) {
  const CliRun run = RunStudy(Quick(), "datasheet");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const std::string html = t::ReadFile(run.out / "datasheet.html");
  const std::regex cell("data-source=\"([^\"]+)\">([^<]*)<");
  int numbers = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), cell); it != std::sregex_iterator(); ++it) {
    const std::string pointer = (*it)[1], shown = (*it)[2];
    const nlohmann::json::json_pointer p(pointer);
    ASSERT_TRUE(run.result.contains(p)) << pointer;
    const nlohmann::json& v = run.result.at(p);
    if (!v.is_number()) continue;
    ++numbers;
    // Shown to 6 significant digits (in the unit of the row; the rows here have scale 1).
    const double value = v.get<double>(), read = std::stod(shown);
    EXPECT_NEAR(read, value, 5e-6 * std::abs(value) + 1e-12) << pointer << ": " << shown;
  }
  EXPECT_GE(numbers, 25);
  for (const char* key : {"/rated_torque_Nm", "/peak_torque_Nm", "/momentary_torque_Nm", "/output_bearing/L10h",
                          "/stiffness_segments/K1_Nm_per_arcmin", "/masses/total_kg", "/ratings/rated_life_h"})
    EXPECT_NE(html.find(std::string("data-source=\"") + key + "\""), std::string::npos) << key;
  EXPECT_NE(html.find("<svg"), std::string::npos);
}

TEST(CycloidRatings, BadCatalogueInputIsRejectedWithItsPath) {
  nlohmann::json s = Quick();
  s["stiffness"]["segments_Nm"] = {210, 70};
  t::ExpectStudyRejected(s, "segments-order", "/stiffness/segments_Nm", "0 < T1 < T2 < rated_torque_Nm");
  s = Quick();
  s.erase("output_bearing");
  t::ExpectStudyRejected(s, "loads-without-bearing", "/external_loads", "need an output_bearing");
  s = Quick();
  s["external_loads"][0]["time_share"] = 0.5;
  t::ExpectStudyRejected(s, "shares", "/external_loads", "sum to 1");
  s = Quick();
  s.erase("crank_bearing");
  t::ExpectStudyRejected(s, "no-crank-bearing", "/crank_bearing", "ratings");
}

// The allowable output speed (docs/ratings.md): the output speed at which the housing's balance at
// the rated torque puts the oil at its limit. Checked by the kind's own thermal balance
// (SolveOperatingTemperature, a different root search): the drive run at the rated torque and just
// below that speed has its oil at 120 °C, just above it has no equilibrium below 120 °C, at 80 % of
// the speed it runs cooler. The lubricant, surfaces and
// bearing friction of cycloid_ltca_lubricated.json (the same drive); the output rollers' friction
// dropped (this drive's output pins have no rollers).
TEST(CycloidRatings, AllowableOutputSpeedPutsTheOilAtItsLimit) {
  nlohmann::json study = Quick();
  const nlohmann::json lub = t::Example("cycloid_ltca_lubricated.json");
  for (const char* k : {"lubricant", "surfaces", "bearing_friction"}) study[k] = lub[k];
  study["bearing_friction"].erase("output_rollers");
  study["load"]["input_speed_rpm"] = 300;
  const CliRun run = RunStudy(study, "allowable");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const nlohmann::json& g = run.result["ratings"];
  ASSERT_TRUE(g["allowable_output_speed_rpm"].is_number()) << g["allowable_output_speed"];
  const double n = g["allowable_output_speed_rpm"].get<double>(), rated = run.result["rated_torque_Nm"].get<double>();
  std::printf("[ ratings  ] allowable output speed %.6f rpm at the rated %.4f N m\n", n, rated);
  nlohmann::json at = AtTorque(study, rated, n);
  // Just below the speed the oil settles at the limit; just above there is no equilibrium below it.
  at["load"]["input_speed_rpm"] = (1 - 1e-7) * n * 15.0;
  const CliRun hot = RunStudy(at, "allowable-at");
  ASSERT_EQ(hot.exit_code, 0) << hot.stderr_text;
  EXPECT_NEAR(hot.result["lubrication"]["oil_temperature_C"].get<double>(), 120.0, 1e-4);
  at["load"]["input_speed_rpm"] = (1 + 1e-6) * n * 15.0;
  const CliRun over = RunStudy(at, "allowable-over");
  EXPECT_EQ(over.exit_code, 3);
  EXPECT_NE(over.stderr_text.find("no thermal equilibrium"), std::string::npos) << over.stderr_text;
  at["load"]["input_speed_rpm"] = 0.8 * n * 15.0;
  const CliRun cooler = RunStudy(at, "allowable-cooler");
  ASSERT_EQ(cooler.exit_code, 0) << cooler.stderr_text;
  EXPECT_LT(cooler.result["lubrication"]["oil_temperature_C"].get<double>(), 119.0);
  // A given oil temperature has no balance: no speed, and the note says what would give one.
  study["lubricant"].erase("thermal");
  study["lubricant"]["temperature_C"] = 60;
  const CliRun fixed = RunStudy(study, "allowable-fixed");
  ASSERT_EQ(fixed.exit_code, 0) << fixed.stderr_text;
  EXPECT_TRUE(fixed.result["ratings"]["allowable_output_speed_rpm"].is_null());
  EXPECT_NE(fixed.result["ratings"]["allowable_output_speed"].get<std::string>().find("lubricant.thermal"),
            std::string::npos);
}

}  // namespace cycloid_ratings_test
