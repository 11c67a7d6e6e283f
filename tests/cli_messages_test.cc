// What a new user meets at the command line: a misspelt command, field or enum value gets the
// nearest accepted name; a sweep file given to `camopt run` is named as one; --strict turns a
// failed limit into exit 3.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/suggest.h"
#include "tests/test_util.h"

namespace cli_messages_test {

using camopt::studies::NamesInExpected;
using camopt::studies::NearestName;
using camopt::testing::Example;
using camopt::testing::ReadFile;
using camopt::testing::RunCamopt;
using camopt::testing::SourcePath;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;
using nlohmann::json;

TEST(Suggest, NearestNameWithinAThirdOfTheLength) {
  const std::vector<std::string> laws = {"dwell", "cycloidal", "harmonic", "quintic", "modified_trapezoidal"};
  EXPECT_EQ(NearestName("quntic", laws), "quintic");              // a deletion
  EXPECT_EQ(NearestName("cycloidl", laws), "cycloidal");          // a deletion
  EXPECT_EQ(NearestName("Harmonic", laws), "");                   // only the case differs: not misspelt
  EXPECT_EQ(NearestName("dwlel", laws), "dwell");                 // two neighbours swapped
  EXPECT_EQ(NearestName("linear", laws), "");                     // nothing near
  EXPECT_EQ(NearestName("modified_trapezoid", laws), "modified_trapezoidal");  // 2 of 20
  EXPECT_EQ(NearestName("ab", {"ac", "ad"}), "");                 // a tie: no guess
  EXPECT_EQ(NearestName("", laws), "");
}

TEST(Suggest, NamesInTheExpectedText) {
  EXPECT_EQ(NamesInExpected("one of \"ipopt\", \"slsqp\""), (std::vector<std::string>{"ipopt", "slsqp"}));
  EXPECT_EQ(NamesInExpected("one of factorial, zip, latin_hypercube, sobol"),
            (std::vector<std::string>{"factorial", "zip", "latin_hypercube", "sobol"}));
  EXPECT_EQ(NamesInExpected("a motion law (dwell, cycloidal, quintic)"),
            (std::vector<std::string>{"dwell", "cycloidal", "quintic"}));
  EXPECT_EQ(NamesInExpected("a positive number"), std::vector<std::string>{});
}

TEST(CliMessages, MisspeltEnumValueAndFieldGetTheNearestName) {
  json study = Example("disc_cam_translating.json");
  study["motion"][0]["law"] = "cycloidl";
  camopt::testing::ExpectStudyRejected(study, "law-typo", "/motion/0/law", "(did you mean \"cycloidal\"?)");
  study = Example("disc_cam_translating.json");
  study["follower"]["roller_radus_mm"] = study["follower"]["roller_radius_mm"];
  study["follower"].erase("roller_radius_mm");
  camopt::testing::ExpectStudyRejected(study, "field-typo", "/follower/roller_radus_mm",
                                       "; did you mean \"roller_radius_mm\"?");
}

// `camopt kinds`: one line per kind, its name then what it is for; `--names` the bare list.
TEST(CliMessages, KindsSaysWhatEachKindIsFor) {
  const auto out = std::filesystem::temp_directory_path() / ("camopt-kinds-" + std::to_string(::getpid()));
  ASSERT_EQ(RunCamopt("kinds > " + out.string()).exit_code, 0);
  std::ifstream in(out);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(RunCamopt("kinds --names > " + out.string()).exit_code, 0);
  std::ifstream names_in(out);
  std::vector<std::string> names;
  for (std::string line; std::getline(names_in, line);) names.push_back(line);
  std::filesystem::remove(out);
  ASSERT_GE(names.size(), 11u);
  ASSERT_EQ(lines.size(), names.size());
  for (size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(names[i].find(' '), std::string::npos) << names[i];
    ASSERT_EQ(lines[i].rfind(names[i] + "  ", 0), 0u) << lines[i];
    const std::string what = lines[i].substr(lines[i].find_first_not_of(' ', names[i].size()));
    EXPECT_GT(what.size(), 10u) << lines[i];
    EXPECT_EQ(what.find("camopt study"), std::string::npos) << lines[i];
  }
  const auto at = std::find(names.begin(), names.end(), "transmission_rigidity");
  ASSERT_NE(at, names.end());
  EXPECT_NE(lines[size_t(at - names.begin())].find("torsional rigidity"), std::string::npos);
}

TEST(CliMessages, UnknownCommandAndAFileWithoutACommand) {
  auto r = RunCamopt("runn " + SourcePath("studies/examples/lcr_ii.json"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.stderr_text,
            "camopt: error: unknown command \"runn\" (did you mean \"run\"?); the commands are run, sweep, "
            "init, kinds, schema, serve and export (camopt --help)\n");
  r = RunCamopt("frobnicate");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.stderr_text.find("did you mean"), std::string::npos) << r.stderr_text;
  r = RunCamopt("study.json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("a command comes before the file: `camopt run study.json`"), std::string::npos)
      << r.stderr_text;
}

TEST(CliMessages, ASweepFileGivenToRunIsNamedAsOne) {
  const std::string sweep = SourcePath("studies/sweeps/sweep_cycloid_crowning.json");
  const auto dir = TempDir("run-a-sweep");
  const auto r = RunCamopt("run " + sweep + " --quiet --out " + (dir / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("this is a sweep file"), std::string::npos) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("`camopt sweep " + sweep + " --out DIR`"), std::string::npos) << r.stderr_text;
}

TEST(CliMessages, StrictTurnsAnExceededLimitIntoExit3) {
  const auto dir = TempDir("strict");
  // LCR II's example meets its limits (1500 MPa, 1050 N); a 100 MPa stress limit cannot be met.
  json study = Example("lcr_ii.json");
  study["analysis"]["angle_steps"] = 360;
  WriteFile(dir / "ok.json", study.dump());
  study["limits"]["contact_stress_MPa"] = 100;
  WriteFile(dir / "tight.json", study.dump());
  auto r = RunCamopt("run " + (dir / "ok.json").string() + " --quiet --strict --out " + (dir / "ok").string());
  EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
  r = RunCamopt("run " + (dir / "tight.json").string() + " --quiet --out " + (dir / "t1").string());
  EXPECT_EQ(r.exit_code, 0) << "without --strict a failed limit is reported, not an error";
  r = RunCamopt("run " + (dir / "tight.json").string() + " --quiet --strict --out " + (dir / "t2").string());
  EXPECT_EQ(r.exit_code, 3) << r.stderr_text;
  // Both cams' stresses (1369 and 1215 MPa in LCR II's validation) are over 100 MPa; the forces,
  // undercut margins and roller gaps stay within theirs: 2 of lcr_analysis's 8 limits.
  EXPECT_NE(r.stderr_text.find("camopt: --strict: 2 of 8 limits exceeded: largest contact stress, input cam; "
                               "largest contact stress, output cam\n"),
            std::string::npos)
      << r.stderr_text;
  EXPECT_TRUE(std::filesystem::exists(dir / "t2" / "result.json")) << "the files are written";
}

TEST(CliMessages, SizingSummaryNamesWhatBindsInPlainWordsAndWhatItCosts) {
  const auto dir = TempDir("sizing-summary");
  const std::string out = (dir / "o").string();
  const auto r = RunCamopt("run " + SourcePath("studies/examples/lcr_min_size.json") + " --quiet --out " + out +
                           " > " + (dir / "stdout.txt").string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const json best = json::parse(ReadFile(std::filesystem::path(out) / "result.json"))["best"];
  const std::string text = ReadFile(dir / "stdout.txt");
  // Both cams sit at the 1500 MPa stress limit and nothing else binds (forces, margins and gaps
  // clear of theirs): the plain names of exactly those rows, not the solver's row names.
  ASSERT_NEAR(best["input"]["max_contact_stress_MPa"].get<double>(), 1500, 1.5);
  ASSERT_NEAR(best["output"]["max_contact_stress_MPa"].get<double>(), 1500, 1.5);
  EXPECT_LT(best["max_roller_force_N"].get<double>(), 1050 * 0.99);
  EXPECT_NE(text.find("  binding limits: contact stress, input cam; contact stress, output cam\n"), std::string::npos)
      << text;
  EXPECT_EQ(text.find("stress_margin"), std::string::npos) << text;
  // The cost of the stress limit: 10 MPa times d(outer diameter)/d(limit) of result.json.
  char line[120];
  std::snprintf(line, sizeof line, "  what the binding limits cost: stress limit +10 MPa → %+.3f mm\n",
                10 * best["limit_sensitivity"]["contact_stress_MPa"].get<double>());
  EXPECT_NE(text.find(line), std::string::npos) << line << text;
  EXPECT_LT(best["limit_sensitivity"]["contact_stress_MPa"].get<double>(), 0.0) << "a higher limit, a smaller reducer";
  // binding_limits shaped as the other sizing kinds give it.
  ASSERT_EQ(best["binding_limits"].size(), 1u) << best["binding_limits"];
  EXPECT_EQ(best["binding_limits"][0]["limit"], "contact_stress_MPa");
  EXPECT_EQ(best["binding_limits"][0]["limit_value"], 1500.0);
  EXPECT_EQ(best["binding_limits"][0]["limit_cost"], best["limit_sensitivity"]["contact_stress_MPa"]);
  EXPECT_EQ(best["binding_limits"][0]["unit"], "mm per MPa");
}

TEST(CliMessages, CycloidLtcaLimitsGiveAVerdict) {
  const auto dir = TempDir("cycloid-verdict");
  json study = Example("cycloid_ltca_nnm_lcm.json");
  study["analysis"] = {{"crank_angle_steps", 4}, {"grid", {10, 10}}};
  study["geometry_files"] = false;
  // 1 MPa cannot be met by a loaded drive; 1e7 N cannot be missed. Without an output mechanism
  // the eccentric bearing load is not computed: its limit has no value to check (4 limits, not 5:
  // the two given and the tooth radius and pin gap, checked by default).
  study["limits"] = {{"contact_stress_MPa", 1}, {"roller_load_N", 1e7}, {"eccentric_bearing_load_N", 1e7}};
  WriteFile(dir / "tight.json", study.dump());
  auto r = RunCamopt("run " + (dir / "tight.json").string() + " --quiet --strict --out " + (dir / "t").string() +
                     " > " + (dir / "t.txt").string());
  EXPECT_EQ(r.exit_code, 3) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("camopt: --strict: 1 of 4 limits exceeded: largest contact stress\n"), std::string::npos)
      << r.stderr_text;
  EXPECT_NE(ReadFile(dir / "t.txt").find("  verdict: 1 of 4 limits exceeded: largest contact stress\n"), std::string::npos);
  study["limits"] = {{"contact_stress_MPa", 1e5}};
  WriteFile(dir / "loose.json", study.dump());
  r = RunCamopt("run " + (dir / "loose.json").string() + " --quiet --strict --out " + (dir / "l").string() + " > " +
                (dir / "l.txt").string());
  EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
  // The roller-load limit the kind considers and this study leaves out is named, not taken as met.
  EXPECT_NE(ReadFile(dir / "l.txt").find("  verdict: All 3 limits met; not checked, no limit set: largest roller load\n"),
            std::string::npos)
      << ReadFile(dir / "l.txt");
  study["limits"] = {{"contact_stress_MPa", -5}};
  camopt::testing::ExpectStudyRejected(study, "cycloid-limit", "/limits/contact_stress_MPa", "expected a number > 0");
  study["limits"] = {{"contact_stres_MPa", 1500}};
  camopt::testing::ExpectStudyRejected(study, "cycloid-limit-typo", "/limits/contact_stres_MPa",
                                       "did you mean \"contact_stress_MPa\"?");
}

}  // namespace cli_messages_test
