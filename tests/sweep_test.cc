// Sweeps (docs/studies.md "Sweeps"): the designs give the cases they promise, the
// Pareto front is the set of non-dominated cases, and through the CLI the merged table is the
// same bytes with 1 or 2 threads and with 2 MPI ranks, failing cases are reported without
// stopping the sweep, and --resume after SIGINT ends with the table of an uninterrupted run.
#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <thread>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/input.h"
#include "studies/sweep.h"
#include "studies/sweep_design.h"
#include "studies/sweep_pareto.h"
#include "studies/sweep_report.h"
#include "studies/report.h"
#include "tests/test_util.h"

extern char** environ;

namespace sweep_test {

namespace fs = std::filesystem;
namespace sw = camopt::studies::sweep;
using camopt::testing::ReadFile;
using camopt::testing::RunCamopt;
using camopt::testing::SourcePath;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;
using nlohmann::json;

// A fast cycloid LTCA sweep (a coarse grid: a few hundredths of a second per case) over the
// crowning coefficient and the torque; `torques` may hold a bad torque (a failing case).
json CycloidSweep(const json& torques, const json& coefficients = {0.002, 0.005, 0.01}) {
  json base = camopt::testing::Example("cycloid_ltca_nnm_lcm.json");
  base["analysis"] = {{"crank_angle_steps", 4}, {"grid", {10, 10}}};
  return {{"sweep", "test"},
          {"base", base},
          {"vary", {{{"path", "/crowning/coefficient_mm"}, {"values", coefficients}},
                    {{"path", "/load/torque_Nm"}, {"values", torques}}}},
          {"outputs", {"/max_contact_stress_MPa", "/lte_peak_to_peak_arcsec"}},
          {"pareto", {{"minimize", {"/max_contact_stress_MPa", "/lte_peak_to_peak_arcsec"}}}}};
}

sw::Sweep ParseText(const fs::path& dir, const json& sweep) {
  WriteFile(dir / "sweep.json", sweep.dump(2));
  return sw::Parse((dir / "sweep.json").string());
}

// ---- Designs ----------------------------------------------------------------------------------

TEST(SweepDesign, FactorialListsEveryCombinationFirstFieldSlowest) {
  const auto dir = TempDir("sweep-factorial");
  json s = CycloidSweep({100, 200});
  s["vary"][1] = {{"path", "/load/torque_Nm"}, {"range", {20, 120}}, {"count", 3}};
  const auto cases = sw::Cases(ParseText(dir, s));
  ASSERT_EQ(cases.size(), 9u);
  EXPECT_EQ(cases[0], (std::vector<json>{0.002, 20.0}));
  EXPECT_EQ(cases[1], (std::vector<json>{0.002, 70.0}));
  EXPECT_EQ(cases[2], (std::vector<json>{0.002, 120.0}));
  EXPECT_EQ(cases[8], (std::vector<json>{0.01, 120.0}));
}

TEST(SweepDesign, ZipLogAndIntegerLevels) {
  const auto dir = TempDir("sweep-zip");
  json s = CycloidSweep({100, 200, 400});
  s["design"] = "zip";
  s["vary"][0] = {{"path", "/crowning/coefficient_mm"}, {"range", {0.001, 0.1}}, {"count", 3}, {"log", true}};
  s["vary"][1] = {{"path", "/load/torque_Nm"}, {"range", {10, 20}}, {"count", 3}, {"integer", true}};
  const auto cases = sw::Cases(ParseText(dir, s));
  ASSERT_EQ(cases.size(), 3u);
  EXPECT_NEAR(cases[1][0].get<double>(), 0.01, 1e-15);  // the geometric mean of 0.001 and 0.1
  EXPECT_EQ(cases[1][1], json(15));
  EXPECT_TRUE(cases[1][1].is_number_integer());
}

TEST(SweepDesign, LatinHypercubeHasOneSampleInEachStratumOfEveryField) {
  const auto dir = TempDir("sweep-lhs");
  json s = CycloidSweep({100});
  s["design"] = "latin_hypercube";
  s["samples"] = 20;
  s["seed"] = 7;
  s["vary"][0] = {{"path", "/crowning/coefficient_mm"}, {"range", {0.0, 0.02}}};
  s["vary"][1] = {{"path", "/load/torque_Nm"}, {"range", {100, 600}}};
  const auto cases = sw::Cases(ParseText(dir, s));
  ASSERT_EQ(cases.size(), 20u);
  const double lo[2] = {0.0, 100}, hi[2] = {0.02, 600};
  for (int d = 0; d < 2; ++d) {
    std::set<int> strata;
    for (const auto& c : cases) strata.insert(int((c[d].get<double>() - lo[d]) / (hi[d] - lo[d]) * 20));
    EXPECT_EQ(strata.size(), 20u) << "field " << d;
  }
  // The same seed gives the same samples; another seed others.
  EXPECT_EQ(sw::Cases(ParseText(dir, s)), cases);
  s["seed"] = 8;
  EXPECT_NE(sw::Cases(ParseText(dir, s)), cases);
}

TEST(SweepDesign, SobolPointsFillTheBoxAndBalanceTheHalves) {
  const auto dir = TempDir("sweep-sobol");
  json s = CycloidSweep({100});
  s["design"] = "sobol";
  s["samples"] = 64;
  s["vary"][0] = {{"path", "/crowning/coefficient_mm"}, {"range", {0.0, 1.0}}};
  s["vary"][1] = {{"path", "/load/torque_Nm"}, {"values", {100, 200, 300, 400}}};
  const auto cases = sw::Cases(ParseText(dir, s));
  ASSERT_EQ(cases.size(), 64u);
  // The first 64 points of a Sobol sequence put exactly 16 in each quarter of each coordinate;
  // skipping the first point (the origin) and taking the 65th instead moves at most one.
  int below_half = 0;
  std::map<int, int> per_value;
  std::set<double> distinct;
  for (const auto& c : cases) {
    const double x = c[0].get<double>();
    EXPECT_GE(x, 0.0);
    EXPECT_LT(x, 1.0);
    below_half += x < 0.5;
    distinct.insert(x);
    ++per_value[c[1].get<int>()];
  }
  EXPECT_EQ(distinct.size(), 64u);
  EXPECT_NEAR(below_half, 32, 1);
  for (const auto& [v, n] : per_value) EXPECT_NEAR(n, 16, 1) << v;
}

// ---- Pareto ------------------------------------------------------------------------------------

TEST(SweepPareto, FrontIsTheNonDominatedOkCases) {
  const auto dir = TempDir("sweep-pareto");
  json s = CycloidSweep({100});
  s["pareto"] = {{"minimize", {"/max_contact_stress_MPa"}}, {"maximize", {"/lte_peak_to_peak_arcsec"}}};
  const sw::Sweep sweep = ParseText(dir, s);
  // (minimize a, maximize b): worked out by hand.
  const std::vector<std::pair<double, double>> points = {
      {1, 1}, {2, 3}, {3, 3}, {2, 2}, {4, 5}, {5, 4}, {1, 1}, {0.5, 0.5}};
  std::vector<sw::CaseRecord> records;
  for (size_t i = 0; i < points.size(); ++i) {
    sw::CaseRecord r;
    r.index = i;
    r.status = "ok";
    r.outputs = {points[i].first, points[i].second};
    records.push_back(r);
  }
  sw::CaseRecord failed;
  failed.index = 8;
  failed.status = "error";
  failed.outputs = {0.0, 100.0};  // would dominate everything, but the case is not ok
  records.push_back(failed);
  sw::CaseRecord missing;
  missing.index = 9;
  missing.status = "ok";
  missing.outputs = {0.1, json()};  // no value: takes no part
  records.push_back(missing);
  // Non-dominated: (1,1) twice (equal points do not dominate each other), (2,3), (4,5), (0.5,0.5).
  EXPECT_EQ(sw::ParetoFront(sweep, records), (std::vector<size_t>{0, 1, 4, 6, 7}));
}

// ---- What shows the front: plots, report.html, the stdout summary -------------------------------

TEST(SweepReport, PlainNamesOfResultPointers) {
  // A kind without headlines: the pointer's words and the unit of the key's suffix.
  EXPECT_EQ(camopt::studies::PlainName("no_such_kind", "/input_cam/max_contact_stress_MPa"),
            "input cam, max contact stress [MPa]");
  EXPECT_EQ(camopt::studies::PlainName("no_such_kind", "/best/stiffness_Nm_per_arcmin"),
            "best, stiffness [N·m/arcmin]");
  EXPECT_EQ(camopt::studies::PlainName("no_such_kind", "/speed_ratio"), "speed ratio");
  EXPECT_EQ(camopt::studies::PlainName("no_such_kind", "/life/shortest_L10h_h"), "life, shortest L10h [h]");
}

TEST(SweepReport, ThreeObjectivesGetAPanelPerPairAndTheSummaryNamesEachBest) {
  const auto dir = TempDir("sweep-report");
  json s = CycloidSweep({100});
  s["sweep"] = "three objectives";
  s["outputs"] = {"/a_mm", "/b_MPa", "/c_h"};
  s["pareto"] = {{"minimize", {"/a_mm", "/b_MPa"}}, {"maximize", {"/c_h"}}};
  const sw::Sweep sweep = ParseText(dir, s);
  // (minimize a, minimize b, maximize c), worked out by hand: case 2 is dominated by case 1;
  // case 4 looks dominated by case 1 in (a, b) but has the largest c; case 5 is not ok.
  const std::vector<std::array<double, 3>> values = {{1, 5, 1}, {2, 2, 1}, {3, 3, 0}, {5, 1, 1}, {4, 4, 9}, {0, 0, 99}};
  std::vector<sw::CaseRecord> records;
  for (size_t i = 0; i < values.size(); ++i) {
    sw::CaseRecord r;
    r.index = i;
    r.status = i == 5 ? "error" : "ok";
    r.message = i == 5 ? "/load/torque_Nm: expected a positive number" : "";
    r.outputs = {values[i][0], values[i][1], values[i][2]};
    records.push_back(r);
  }
  const std::vector<size_t> front = sw::ParetoFront(sweep, records);
  ASSERT_EQ(front, (std::vector<size_t>{0, 1, 3, 4}));

  const auto plots = sw::ParetoPlots(sweep, records, front);
  ASSERT_EQ(plots.size(), 3u);
  EXPECT_EQ(plots[0].first, "pareto.svg");
  EXPECT_EQ(plots[1].first, "pareto_1_3.svg");
  EXPECT_EQ(plots[2].first, "pareto_2_3.svg");
  EXPECT_NE(plots[0].second.find("objectives 1 and 2 of 3"), std::string::npos);
  EXPECT_NE(plots[1].second.find("objectives 1 and 3 of 3"), std::string::npos);
  // Axis titles in plain words with the direction, not JSON pointers.
  EXPECT_NE(plots[1].second.find(">a [mm] (minimize)<"), std::string::npos) << plots[1].second;
  EXPECT_NE(plots[1].second.find(">c [h] (maximize)<"), std::string::npos);
  EXPECT_EQ(plots[1].second.find(">/a_mm"), std::string::npos);
  // Each front case labelled with its number in each panel.
  for (const auto& [file, svg] : plots) {
    SCOPED_TRACE(file);
    const std::string tag = "paint-order=\"stroke\">";  // a point's label, not an axis tick
    for (const char* label : {"0", "1", "3", "4"})
      EXPECT_NE(svg.find(tag + label + "</text>"), std::string::npos) << label;
    EXPECT_EQ(svg.find(tag + "2</text>"), std::string::npos) << "case 2 is not on the front";
  }

  EXPECT_EQ(sw::SweepSummary(sweep, records, front, "out"),
            "camopt: sweep \"three objectives\": 6 cases, 5 ok, 1 error\n"
            "  Pareto front: 4 of 5 ok cases: 0, 1, 3, 4\n"
            "  minimize a [mm]: best 1 (case 0)\n"
            "  minimize b [MPa]: best 1 (case 3)\n"
            "  maximize c [h]: best 9 (case 4)\n"
            "  details: out/report.html\n");

  std::vector<std::vector<json>> cases(6, std::vector<json>{0.005, 100.0});
  const std::string html = sw::SweepHtml(sweep, cases, records, front, plots);
  EXPECT_NE(html.find("5 of 6 cases ok, 1 error"), std::string::npos);
  EXPECT_NE(html.find("/load/torque_Nm: expected a positive number"), std::string::npos);
  EXPECT_NE(html.find("minimize a [mm]; minimize b [MPa]; maximize c [h]"), std::string::npos);
  EXPECT_NE(html.find("pareto_2_3.svg"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);  // self-contained, nothing to run
}

TEST(SweepReport, EachOutputAgainstEachInputOneLinePerLevelOfTheOther) {
  const auto dir = TempDir("sweep-output-plots");
  const sw::Sweep sweep = ParseText(dir, CycloidSweep({100, 200}, {0.002, 0.005}));
  // Cases (coefficient, torque): (0.002, 100), (0.002, 200), (0.005, 100), (0.005, 200); outputs
  // made up by hand; case 3 is not ok and is left out of every plot.
  const std::vector<std::vector<json>> cases = {{0.002, 100.0}, {0.002, 200.0}, {0.005, 100.0}, {0.005, 200.0}};
  std::vector<sw::CaseRecord> records;
  const std::vector<std::array<double, 2>> values = {{1111, 11}, {2222, 22}, {3333, 33}, {4444, 44}};
  for (size_t i = 0; i < 4; ++i) {
    sw::CaseRecord r;
    r.index = i;
    r.status = i == 3 ? "error" : "ok";
    r.outputs = {values[i][0], values[i][1]};
    records.push_back(r);
  }
  const auto plots = sw::OutputPlots(sweep, cases, records);
  ASSERT_EQ(plots.size(), 4u);  // 2 outputs x 2 inputs
  EXPECT_EQ(plots[0].first, "outputs_1_vs_1.svg");
  EXPECT_EQ(plots[1].first, "outputs_1_vs_2.svg");
  EXPECT_EQ(plots[3].first, "outputs_2_vs_2.svg");
  // Stress against the coefficient: a line per torque, named by the other input's level.
  const std::string& a = plots[0].second;
  EXPECT_NE(a.find(">load, torque [N·m] = 100</text>"), std::string::npos) << a;
  EXPECT_NE(a.find(">load, torque [N·m] = 200</text>"), std::string::npos);
  EXPECT_NE(a.find(">crowning, coefficient [mm]</text>"), std::string::npos);  // x axis
  // Case 3 is not ok: the y axis (ticks of 500 over 1111-3333) ends at 3500, not at the 4500 the
  // left-out 4444 would need.
  EXPECT_NE(a.find(">3500</text>"), std::string::npos);
  EXPECT_EQ(a.find(">4500</text>"), std::string::npos);
  const std::string html = sw::SweepHtml(sweep, cases, records, {}, {}, plots);
  EXPECT_NE(html.find("<h2>Outputs against the inputs</h2>"), std::string::npos);
  EXPECT_NE(html.find("<li><code>outputs_2_vs_2.svg</code></li>"), std::string::npos);
}

TEST(SweepCli, ASweepWritesItsReportAndPrintsTheAnswerFirst) {
  const auto dir = TempDir("sweep-summary");
  WriteFile(dir / "s.json", CycloidSweep({100}, {0.002, 0.005}).dump());
  const std::string out = (dir / "o").string();
  const auto r = RunCamopt("sweep " + (dir / "s.json").string() + " --quiet --out " + out + " > " +
                           (dir / "stdout.txt").string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const std::string text = ReadFile(dir / "stdout.txt");
  EXPECT_EQ(text.rfind("camopt: sweep \"test\": 2 cases, 2 ok\n  Pareto front: ", 0), 0u) << text;
  EXPECT_NE(text.find("  details: " + out + "/report.html\n"), std::string::npos) << text;
  const std::string html = ReadFile(fs::path(out) / "report.html");
  EXPECT_NE(html.find("All 2 cases ok"), std::string::npos);
  // Both cases' rows.
  EXPECT_NE(html.find("<td class=\"n\">0.002</td>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"n\">0.005</td>"), std::string::npos);
}

// ---- Bad sweep files -----------------------------------------------------------------------------

TEST(SweepInput, BadSweepFilesExit2WithThePath) {
  const auto dir = TempDir("sweep-bad");
  struct Bad {
    std::string tag, path, words;
    json sweep;
  };
  std::vector<Bad> bad;
  json s = CycloidSweep({100});
  s["vary"][0]["path"] = "/crowing/coefficient_mm";
  bad.push_back({"no-parent", "/vary/0/path", "has no /crowing", s});
  s = CycloidSweep({100});
  s["vary"][1].erase("values");
  bad.push_back({"no-levels", "/vary/1", "either \"values\" or \"range\"", s});
  s = CycloidSweep({100});
  s["design"] = "random";
  bad.push_back({"design", "/design", "expected one of factorial", s});
  s = CycloidSweep({100});
  s["outputs"] = {"max_contact_stress_MPa"};
  bad.push_back({"pointer", "/outputs/0", "expected a JSON pointer", s});
  s = CycloidSweep({100});
  s["base"] = "missing.json";
  bad.push_back({"base", "/base", "missing.json", s});
  s = CycloidSweep({100});
  s["vary"][1] = {{"path", "/load/torque_Nm"}, {"range", {1, 2}}, {"count", 2000000}};
  bad.push_back({"cap", "/vary/1/count", "cap", s});
  for (const Bad& b : bad) {
    SCOPED_TRACE(b.tag);
    const auto file = dir / (b.tag + ".json");
    WriteFile(file, b.sweep.dump());
    const auto r = RunCamopt("sweep " + file.string() + " --quiet --out " + (dir / "out").string());
    EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
    EXPECT_NE(r.stderr_text.find(file.string() + ": " + b.path), std::string::npos) << r.stderr_text;
    EXPECT_NE(r.stderr_text.find(b.words), std::string::npos) << r.stderr_text;
    EXPECT_EQ(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n'), 1) << r.stderr_text;
    EXPECT_FALSE(fs::exists(dir / "out"));
  }
}

TEST(SweepCli, AnOutputFolderHoldingOtherFilesIsRefusedBeforeAnyCase) {
  const auto dir = TempDir("sweep-out");
  WriteFile(dir / "s.json", CycloidSweep({100}).dump());
  fs::create_directories(dir / "mine" / "photos");
  WriteFile(dir / "mine" / "notes.txt", "keep");
  const auto r = RunCamopt("sweep " + (dir / "s.json").string() + " --quiet --out " + (dir / "mine").string());
  EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("not a camopt sweep"), std::string::npos) << r.stderr_text;
  EXPECT_EQ(ReadFile(dir / "mine" / "notes.txt"), "keep");
  EXPECT_FALSE(fs::exists(dir / "mine.camopt-sweep"));
  // A previous sweep's folder is replaced whole.
  ASSERT_EQ(RunCamopt("sweep " + (dir / "s.json").string() + " --quiet --case-outputs --out " + (dir / "o").string()).exit_code, 0);
  WriteFile(dir / "s.json", CycloidSweep({100, 200}).dump());
  ASSERT_EQ(RunCamopt("sweep " + (dir / "s.json").string() + " --quiet --out " + (dir / "o").string()).exit_code, 0);
  EXPECT_FALSE(fs::exists(dir / "o" / "cases"));
  const std::string table = ReadFile(dir / "o" / "cases.csv");
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 7);
}

// A folder of the user's that happens to hold a cases.csv (and a cases/ folder) is not a sweep's:
// only a folder with camopt's manifest of what it wrote, and nothing else, is replaced.
TEST(SweepCli, AUsersCasesCsvIsNotTakenForAPreviousSweep) {
  const auto dir = TempDir("sweep-users-cases");
  WriteFile(dir / "s.json", CycloidSweep({100}).dump());
  fs::create_directories(dir / "mine" / "cases");
  WriteFile(dir / "mine" / "cases.csv", "my,own\n1,2\n");
  WriteFile(dir / "mine" / "report.docx", "a document");
  WriteFile(dir / "mine" / "cases" / "measured.csv", "x\n1\n");
  const auto r = RunCamopt("sweep " + (dir / "s.json").string() + " --quiet --out " + (dir / "mine").string());
  EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("no .camopt_manifest"), std::string::npos) << r.stderr_text;
  EXPECT_EQ(ReadFile(dir / "mine" / "cases.csv"), "my,own\n1,2\n");
  EXPECT_EQ(ReadFile(dir / "mine" / "report.docx"), "a document");
  EXPECT_EQ(ReadFile(dir / "mine" / "cases" / "measured.csv"), "x\n1\n");
  EXPECT_FALSE(fs::exists(dir / "mine.camopt-sweep"));
}

// A previous sweep's folder (with its manifest) that the user added files to is theirs: at the
// top, under cases/ and inside a case's folder; the folder is replaced again once they are gone.
TEST(SweepCli, AFolderWithAManifestButForeignFilesKeepsThem) {
  const auto dir = TempDir("sweep-foreign");
  WriteFile(dir / "s.json", CycloidSweep({100}).dump());
  const std::string sweep = "sweep " + (dir / "s.json").string() + " --quiet --case-outputs --out " + (dir / "o").string();
  ASSERT_EQ(RunCamopt(sweep).exit_code, 0);
  ASSERT_TRUE(fs::exists(dir / "o" / ".camopt_manifest"));
  ASSERT_TRUE(fs::exists(dir / "o" / "cases" / ".camopt_manifest"));
  for (const fs::path& foreign : {dir / "o" / "notes.txt", dir / "o" / "cases" / "notes.txt",
                                  dir / "o" / "cases" / "0000" / "notes.txt"}) {
    SCOPED_TRACE(foreign.string());
    WriteFile(foreign, "keep");
    const auto r = RunCamopt(sweep);
    EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
    EXPECT_NE(r.stderr_text.find("notes.txt, which camopt did not write"), std::string::npos) << r.stderr_text;
    EXPECT_EQ(ReadFile(foreign), "keep");
    fs::remove(foreign);
  }
  EXPECT_EQ(RunCamopt(sweep).exit_code, 0);
}

// A file the user adds to the output folder while a sweep into it runs is kept: the swap refuses
// (exit 2) and says where the sweep's results are.
TEST(SweepCli, AFileAddedWhileTheSweepRunsIsKept) {
  const auto dir = TempDir("sweep-added");
  WriteFile(dir / "s.json", CycloidSweep({100}).dump());
  ASSERT_EQ(RunCamopt("sweep " + (dir / "s.json").string() + " --quiet --out " + (dir / "o").string()).exit_code, 0);
  // A slower sweep (finer grid, more cases) into the same folder, on one thread.
  json slow = CycloidSweep({100, 150, 200, 250, 300, 350}, {0.002, 0.004, 0.006, 0.008, 0.01});
  slow["base"]["analysis"] = {{"crank_angle_steps", 12}, {"grid", {16, 16}}};
  WriteFile(dir / "slow.json", slow.dump());
  const std::string err = (dir / "err.txt").string();
  const std::string cmd = std::string(CAMOPT_BINARY) + " sweep " + (dir / "slow.json").string() +
                          " --quiet --jobs 1 --out " + (dir / "o").string() + " 2> " + err + "; echo $? > " +
                          (dir / "code.txt").string();
  std::thread sweep([cmd] { EXPECT_EQ(std::system(cmd.c_str()), 0); });
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!fs::exists(dir / "o.camopt-sweep" / "checkpoint-0.jsonl") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  WriteFile(dir / "o" / "measurements.csv", "mine");
  sweep.join();
  EXPECT_EQ(ReadFile(dir / "code.txt"), "2\n") << ReadFile(err);
  EXPECT_NE(ReadFile(err).find("changed while the sweep ran"), std::string::npos) << ReadFile(err);
  EXPECT_EQ(ReadFile(dir / "o" / "measurements.csv"), "mine");
  EXPECT_TRUE(fs::exists(dir / "o.camopt-sweep" / "cases.csv")) << "the results are kept where the message says";
}

// A sweep file (or its base study) inside the folder it would replace: refused, the file kept.
TEST(SweepCli, ASweepFileInsideItsOutputFolderIsRefused) {
  const auto dir = TempDir("sweep-inside");
  WriteFile(dir / "s.json", CycloidSweep({100}).dump());
  ASSERT_EQ(RunCamopt("sweep " + (dir / "s.json").string() + " --quiet --out " + (dir / "o").string()).exit_code, 0);
  // Listed in the manifest as if camopt had written it: the folder would be replaceable.
  fs::copy_file(dir / "s.json", dir / "o" / "s.json");
  std::ofstream(dir / "o" / ".camopt_manifest", std::ios::app) << "s.json\n";
  const auto r = RunCamopt("sweep " + (dir / "o" / "s.json").string() + " --quiet --out " + (dir / "o").string());
  EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("is inside the folder this run replaces"), std::string::npos) << r.stderr_text;
  EXPECT_TRUE(fs::exists(dir / "o" / "s.json"));
}

// A design is counted before it is expanded: 1e6 Sobol samples over 11 fields (1.1e7 values, above
// the cap of 1e7) is refused within a second, --dry-run included, naming the cap.
TEST(SweepCli, AHugeSampledDesignIsRefusedBeforeItIsExpanded) {
  const auto dir = TempDir("sweep-huge");
  json s = CycloidSweep({100});
  s["design"] = "sobol";
  s["samples"] = 1000000;
  s["vary"] = json::array();
  for (const char* p : {"/drive/roller_position_radius_mm", "/drive/roller_radius_mm", "/drive/eccentricity_mm",
                        "/drive/face_width_mm", "/modification/delta_position_um", "/modification/delta_radius_um",
                        "/material/youngs_modulus_GPa", "/material/poisson_ratio", "/load/torque_Nm",
                        "/crowning/coefficient_mm", "/crowning/effective_length_mm"}) {
    const json::json_pointer at(p);
    const double v = s["base"].contains(at) ? s["base"][at].get<double>() : 18.0;  // effective length: absent
    s["vary"].push_back({{"path", p}, {"range", {v - 0.01 * std::abs(v) - 1e-3, v + 0.01 * std::abs(v) + 1e-3}}});
  }
  WriteFile(dir / "s.json", s.dump());
  const auto started = std::chrono::steady_clock::now();
  const auto r = RunCamopt("sweep " + (dir / "s.json").string() + " --dry-run");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), 1.0);
  EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("1.1e+07 values, more than the cap of 1e+07"), std::string::npos) << r.stderr_text;
}

TEST(SweepCli, DryRunPrintsTheNumberOfCases) {
  const auto dir = TempDir("sweep-dry");
  WriteFile(dir / "s.json", CycloidSweep({100, 200, 300, 400}).dump());
  const std::string out = (dir / "stdout.txt").string();
  const auto r = RunCamopt("sweep " + (dir / "s.json").string() + " --dry-run > " + out);
  EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(ReadFile(out), "12 cases\n");
  EXPECT_FALSE(fs::exists(dir / "s"));
  // The examples parse, with the counts their files describe.
  for (const auto& [name, n] : {std::pair<std::string, size_t>{"sweep_lcr_ratios.json", 9},
                                {"sweep_cycloid_crowning.json", 15}}) {
    SCOPED_TRACE(name);
    EXPECT_EQ(sw::Cases(sw::Parse(SourcePath("studies/sweeps/" + name))).size(), n);
  }
}

// In one process (the Python module, a fuzzer) each sweep's --max-work-factor scales the default
// file cap, not the previous sweep's: three dry runs at 0.01 all read the 848-byte example (at
// 16 MiB × 0.01³ = 16 B the third would refuse it), and the cap is the default again after.
TEST(SweepCli, WorkFactorsOfSweepsInOneProcessDoNotCompound) {
  const size_t before = camopt::studies::CurrentInputLimits().max_file_bytes;
  for (int i = 0; i < 3; ++i) {
    SCOPED_TRACE(i);
    sw::Options o;
    o.file = SourcePath("studies/sweeps/sweep_cycloid_crowning.json");
    o.out = (TempDir("sweep-factor") / "out").string();
    o.dry_run = true;
    o.quiet = true;
    o.max_work_factor = 0.01;
    ::testing::internal::CaptureStdout();
    const int code = sw::RunCommand(o);
    EXPECT_EQ(::testing::internal::GetCapturedStdout(), "15 cases\n");
    EXPECT_EQ(code, 0);
  }
  EXPECT_EQ(camopt::studies::CurrentInputLimits().max_file_bytes, before);
  EXPECT_EQ(camopt::studies::FileBytesForWorkFactor(1), size_t{16} << 20);
  EXPECT_EQ(camopt::studies::FileBytesForWorkFactor(0.5), size_t{8} << 20);
}

// ---- Running: the same table whatever the threads or ranks --------------------------------------

int RunShell(const std::string& cmd) {
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(SweepRun, OneAndTwoThreadsAndTwoRanksGiveByteIdenticalTables) {
  const auto dir = TempDir("sweep-identical");
  WriteFile(dir / "s.json", CycloidSweep({100, 350, 600}).dump());
  const std::string sweep = (dir / "s.json").string();
  std::vector<std::string> outs;
  for (int jobs : {1, 2}) {
    const auto out = dir / ("j" + std::to_string(jobs));
    const auto r = RunCamopt("sweep " + sweep + " --quiet --jobs " + std::to_string(jobs) + " --out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
    outs.push_back(out.string());
  }
#ifdef CAMOPT_MPIEXEC
  {
    const auto out = dir / "mpi2";
    const std::string cmd = std::string(CAMOPT_MPIEXEC) +
                            " --allow-run-as-root --oversubscribe -n 2 " + CAMOPT_BINARY +
                            " sweep " + sweep + " --quiet --jobs 1 --out " + out.string() + " 2> " +
                            (dir / "mpi.err").string();
    ASSERT_EQ(RunShell(cmd), 0) << ReadFile(dir / "mpi.err");
    outs.push_back(out.string());
  }
#else
  std::cerr << "built without MPI (CAMOPT_MPI off): the 2-rank run is not compared\n";
#endif
  const std::string table = ReadFile(fs::path(outs[0]) / "cases.csv");
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 10);  // header + 9 cases
  EXPECT_EQ(table.rfind("case,/crowning/coefficient_mm,/load/torque_Nm,status,", 0), 0u) << table;
  for (size_t k = 1; k < outs.size(); ++k) {
    SCOPED_TRACE(outs[k]);
    for (const char* file : {"cases.csv", "pareto.csv", "pareto.svg", "report.html", "result.json"})
      EXPECT_EQ(ReadFile(fs::path(outs[k]) / file), ReadFile(fs::path(outs[0]) / file)) << file;
  }
  // Each row's numbers are those of the case's study run alone (here case 4: 0.005 mm, 350 Nm).
  json study = CycloidSweep({350})["base"];
  study["crowning"]["coefficient_mm"] = 0.005;
  WriteFile(dir / "case4.json", study.dump());
  ASSERT_EQ(RunCamopt("run " + (dir / "case4.json").string() + " --quiet --out " + (dir / "c4").string()).exit_code, 0);
  const json alone = json::parse(ReadFile(dir / "c4" / "result.json"));
  char row[200];
  std::snprintf(row, sizeof row, "\n4,0.005,350,ok,%.10g,%.10g,\n", alone["max_contact_stress_MPa"].get<double>(),
                alone["lte_peak_to_peak_arcsec"].get<double>());
  EXPECT_NE(table.find(row), std::string::npos) << row << table;
  EXPECT_FALSE(fs::exists(dir / "j1.camopt-sweep"));
}

TEST(SweepRun, LcrMinSizeCasesOnTwoThreadsMatchOneThread) {
  // lcr_min_size solves with Ipopt, whose MUMPS is not thread-safe: the solves take turns.
  const auto dir = TempDir("sweep-lcr");
  json s = json::parse(ReadFile(SourcePath("studies/sweeps/sweep_lcr_ratios.json")));
  s["base"] = SourcePath("studies/examples/lcr_min_size.json");
  s["vary"][0]["values"] = {-35, -45};
  s["vary"][1] = {{"path", "/target/output_torque_Nm"}, {"values", {20, 120}}};
  s["set"] = {{"/search/max_lobes", 26}};
  WriteFile(dir / "s.json", s.dump());
  for (int jobs : {1, 2}) {
    const auto r = RunCamopt("sweep " + (dir / "s.json").string() + " --quiet --jobs " +
                             std::to_string(jobs) + " --out " + (dir / ("j" + std::to_string(jobs))).string());
    EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
  }
#ifdef CAMOPT_MPIEXEC
  // Under mpirun, MPI is initialised in the process that also holds the sequential MUMPS and its
  // stand-in MPI functions (studies/sweep_world.cc): the solves must give the same table.
  const std::string cmd = std::string(CAMOPT_MPIEXEC) + " --allow-run-as-root --oversubscribe -n 2 " +
                          CAMOPT_BINARY + " sweep " + (dir / "s.json").string() +
                          " --quiet --jobs 1 --out " + (dir / "mpi2").string() + " 2> " + (dir / "mpi.err").string();
  EXPECT_EQ(RunShell(cmd), 0) << ReadFile(dir / "mpi.err");
#endif
  const std::string one = ReadFile(dir / "j1" / "cases.csv");
  EXPECT_EQ(ReadFile(dir / "j2" / "cases.csv"), one);
#ifdef CAMOPT_MPIEXEC
  EXPECT_EQ(ReadFile(dir / "mpi2" / "cases.csv"), one);
#endif
  EXPECT_EQ(std::count(one.begin(), one.end(), '\n'), 5) << one;
  EXPECT_EQ(one.find(",error,"), std::string::npos) << one;
}

TEST(SweepRun, FailingCasesAreReportedAndTheSweepFinishes) {
  const auto dir = TempDir("sweep-failing");
  json s = CycloidSweep({100, -5, 350}, {0.005});  // a negative torque is refused by the kind
  s["vary"].push_back({{"path", "/drive/eccentricity_mm"}, {"values", {4.5, 1e308}}});
  WriteFile(dir / "s.json", s.dump());
  const auto r = RunCamopt("sweep " + (dir / "s.json").string() + " --quiet --jobs 2 --case-outputs --out " +
                           (dir / "out").string());
  EXPECT_EQ(r.exit_code, 3) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("4 of 6 cases are not ok"), std::string::npos) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("case 2 (error): "), std::string::npos) << r.stderr_text;
  const std::string table = ReadFile(dir / "out" / "cases.csv");
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 7) << table;
  EXPECT_NE(table.find("\n0,0.005,100,4.5,ok,"), std::string::npos) << table;
  EXPECT_NE(table.find("\n2,0.005,-5,4.5,error,,,"), std::string::npos) << table;
  EXPECT_NE(table.find("/load/torque_Nm"), std::string::npos) << table;
  const json summary = json::parse(ReadFile(dir / "out" / "result.json"));
  EXPECT_EQ(summary["status_counts"]["ok"], 2);
  EXPECT_EQ(summary["cases_not_ok"].size(), 4u);
  // Per-case folders for the cases that ran; none for the refused ones.
  EXPECT_TRUE(fs::exists(dir / "out" / "cases" / "0000" / "result.json"));
  EXPECT_FALSE(fs::exists(dir / "out" / "cases" / "0002"));
  EXPECT_FALSE(fs::exists(dir / "out.camopt-sweep"));
  // A misspelt varied field: every case is refused by the kind, with the field's path.
  s = CycloidSweep({100});
  s["vary"][0]["path"] = "/crowning/coefficent_mm";
  WriteFile(dir / "typo.json", s.dump());
  const auto t = RunCamopt("sweep " + (dir / "typo.json").string() + " --quiet --out " + (dir / "typo").string());
  EXPECT_EQ(t.exit_code, 3) << t.stderr_text;
  EXPECT_NE(ReadFile(dir / "typo" / "cases.csv").find("/crowning/coefficent_mm: unknown field"), std::string::npos);
}

// Lines of case records in the partial folder's checkpoints.
int CheckpointedCases(const fs::path& partial) {
  int n = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(partial, ec)) {
    const std::string text = ReadFile(e.path());
    n += static_cast<int>(std::count(text.begin(), text.end(), '\n')) - 1;
  }
  return n;
}

// Starts `camopt sweep SWEEP --quiet --jobs JOBS --out OUT` in the background and waits until at
// least `cases` cases are checkpointed. Returns its pid, or -1 (and the exit status in *status)
// when it ended first.
pid_t StartSweepUntilCheckpointed(const std::string& sweep, const fs::path& out, const char* jobs, int cases,
                                  int* status, const fs::path& stderr_file = {}) {
  std::string bin = CAMOPT_BINARY;
  std::vector<std::string> args = {bin, "sweep", sweep, "--quiet", "--jobs", jobs, "--out", out.string()};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!stderr_file.empty())
    posix_spawn_file_actions_addopen(&actions, 2, stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int spawned = posix_spawn(&pid, bin.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  const fs::path partial = out.string() + ".camopt-sweep";
  for (int k = 0; k < 6000 && CheckpointedCases(partial) < cases; ++k) {
    if (waitpid(pid, status, WNOHANG) == pid) return -1;
    usleep(5000);
  }
  return pid;
}

// Two sweeps into the same --out: the second one deleted the first's partial folder and one of
// them ended with a confusing error. Now the second is refused at once while the first runs.
TEST(SweepRun, ASecondSweepIntoTheSameFolderIsRefusedWhileTheFirstRuns) {
  const auto dir = TempDir("sweep-lock");
  json s = CycloidSweep({100, 200, 300, 400}, {0.001, 0.005, 0.02});
  s["base"]["analysis"] = {{"crank_angle_steps", 12}, {"grid", {16, 16}}};
  WriteFile(dir / "s.json", s.dump());
  const std::string sweep = (dir / "s.json").string();
  const auto out = dir / "out";
  const fs::path partial = out.string() + ".camopt-sweep";
  int status = 0;
  const pid_t pid = StartSweepUntilCheckpointed(sweep, out, "1", 1, &status);
  ASSERT_GT(pid, 0) << "the first sweep ended before the second could start";
  const auto second = RunCamopt("sweep " + sweep + " --quiet --jobs 1 --out " + out.string());
  EXPECT_EQ(second.exit_code, 2) << second.stderr_text;
  EXPECT_NE(second.stderr_text.find("another sweep is running"), std::string::npos) << second.stderr_text;
  EXPECT_TRUE(fs::exists(partial)) << "the first sweep's partial folder stays";
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the first sweep finishes";
  EXPECT_TRUE(fs::exists(out / "cases.csv"));
  EXPECT_FALSE(fs::exists(out.string() + ".camopt-sweep-lock"));
}

TEST(SweepRun, ResumeAfterSigintFinishesWithTheTableOfAnUninterruptedRun) {
  const auto dir = TempDir("sweep-resume");
  // 12 cases (4 torques x 3 tolerances): enough to interrupt after 3 and leave most undone.
  json s = CycloidSweep({100, 200, 300, 400}, {0.001, 0.005, 0.02});
  s["base"]["analysis"] = {{"crank_angle_steps", 12}, {"grid", {16, 16}}};
  s["case_outputs"] = true;
  WriteFile(dir / "s.json", s.dump());
  const std::string sweep = (dir / "s.json").string();
  ASSERT_EQ(RunCamopt("sweep " + sweep + " --quiet --jobs 1 --out " + (dir / "whole").string()).exit_code, 0);

  // Interrupted once a few cases are checkpointed, before the 12 are done.
  const auto out = dir / "cut";
  const fs::path partial = out.string() + ".camopt-sweep";
  int status = 0;
  pid_t pid = StartSweepUntilCheckpointed(sweep, out, "2", 3, &status, dir / "cut.err");
  ASSERT_GT(pid, 0) << "the sweep ended before it could be interrupted";
  kill(pid, SIGINT);
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  // The interrupt says where the finished cases are and how to go on.
  const std::string err = ReadFile(dir / "cut.err");
  EXPECT_NE(err.find("interrupted"), std::string::npos) << err;
  EXPECT_NE(err.find("kept in " + partial.string()), std::string::npos) << err;
  EXPECT_NE(err.find("--out " + out.string() + " --resume` runs only the others"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(out));
  const int checkpointed = CheckpointedCases(partial);
  EXPECT_GE(checkpointed, 3);
  EXPECT_LT(checkpointed, 12);

  const auto r = RunCamopt("sweep " + sweep + " --resume --jobs 2 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("resuming: "), std::string::npos) << r.stderr_text;
  for (const char* file : {"cases.csv", "pareto.csv", "pareto.svg", "result.json", "cases/0011/result.json",
                           "cases/0000/per_angle.csv"})
    EXPECT_EQ(ReadFile(out / file), ReadFile(dir / "whole" / file)) << file;
  EXPECT_FALSE(fs::exists(partial));
  int folders = 0;
  for (const auto& e : fs::directory_iterator(out / "cases")) {
    if (e.path().filename() == ".camopt_manifest") continue;  // the list of the case folders
    EXPECT_EQ(e.path().filename().string().size(), 4u) << e.path();
    ++folders;
  }
  EXPECT_EQ(folders, 12);
  // The manifest lists exactly those folders: the next sweep may replace them.
  const std::string listed = ReadFile(out / "cases" / ".camopt_manifest");
  EXPECT_EQ(std::count(listed.begin(), listed.end(), '\n'), 12);
  // A resume of a different sweep is refused, naming the checkpoint.
  pid = StartSweepUntilCheckpointed(sweep, out, "2", 1, &status);
  ASSERT_GT(pid, 0) << "the sweep ended before it could be interrupted";
  kill(pid, SIGINT);
  waitpid(pid, &status, 0);
  s["outputs"].push_back("/max_pair_load_N");
  WriteFile(dir / "s.json", s.dump());
  const auto other = RunCamopt("sweep " + sweep + " --resume --quiet --out " + out.string());
  EXPECT_EQ(other.exit_code, 2) << other.stderr_text;
  EXPECT_NE(other.stderr_text.find("checkpoint of another sweep"), std::string::npos) << other.stderr_text;
}

}  // namespace sweep_test
