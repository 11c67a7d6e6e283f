// `camopt run --convergence` (studies/convergence.h): the error estimator against a closed form of
// known order, every example study on coarse settings (shape of convergence.json, the study's own
// result unchanged), and the CLI.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <vector>
#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/convergence.h"
#include "studies/kind.h"
#include "studies/study.h"
#include "tests/test_util.h"

namespace camopt {
namespace convergence_test {

using nlohmann::json;
using testing::Example;
using testing::ReadFile;
using testing::RunCamopt;
using testing::SourcePath;
using testing::TempDir;
using testing::WriteFile;

constexpr double kPi = 3.14159265358979323846;

// The composite trapezoid rule for ∫₀^{π/2} sin x dx = 1 has an error c h² + O(h⁴): Richardson
// with order 2 must estimate the error of the middle run to O(h²) of itself.
double Trapezoid(int n) {
  const double h = kPi / 2 / n;
  double s = 0.5 * (std::sin(0.0) + std::sin(kPi / 2));
  for (int i = 1; i < n; ++i) s += std::sin(i * h);
  return s * h;
}

TEST(Convergence, RichardsonMatchesTheClosedFormErrorOfAKnownOrder) {
  const std::vector<double> v = {Trapezoid(8), Trapezoid(16), Trapezoid(32)};
  const double true_error = std::abs(v[1] - 1.0);
  const studies::ErrorEstimate e = studies::EstimateKnobError(v, 1, 2.0, 2.0);
  EXPECT_EQ(e.method, "richardson");
  EXPECT_NEAR(e.error, true_error, 0.01 * true_error);
  EXPECT_NEAR(e.extrapolated, 1.0, 0.01 * true_error);
  EXPECT_NEAR(e.observed_order, 2.0, 0.01);
  // Order unknown: the difference to the finest run, which underestimates by 1/(1 − 2^-2).
  const studies::ErrorEstimate d = studies::EstimateKnobError(v, 1, 2.0, 0.0);
  EXPECT_EQ(d.method, "difference_to_finest");
  EXPECT_NEAR(d.error, 0.75 * true_error, 0.01 * true_error);
  // Refinement skipped: the difference to the coarser run.
  const studies::ErrorEstimate c = studies::EstimateKnobError({v[0], v[1], NAN}, 1, 2.0, 2.0);
  EXPECT_EQ(c.method, "difference_to_coarser");
  EXPECT_NEAR(c.error, std::abs(v[0] - v[1]), 1e-15);
}

// A coarse copy of an example: small grids and budgets, so that every example runs its knobs in
// a few seconds. The fields set here are the kinds' own (docs/studies.md).
json Coarse(json s) {
  const std::string kind = s["study"];
  if (kind == "lcr_analysis" || kind == "lcr_friction_fit") s["analysis"]["angle_steps"] = 360;
  if (kind == "lcr_min_size") {
    s["optimizer"]["starts"] = 1;
    s["optimizer"]["samples_per_period"] = 8;
    s["optimizer"]["tolerance"] = 1e-6;
    s["search"]["max_lobes"] = 14;
    if (s.contains("contact")) s["contact"]["slices"] = 10;  // the 3D sizing examples
  }
  if (kind == "cycloid_ltca") {
    s["analysis"] = {{"crank_angles_per_mesh_period", 4}, {"grid", {8, 8}}, {"estimate_error", false}};
  }
  if (kind == "cycloid_crowning_tuning") {
    s["analysis"] = {{"crank_angles_per_mesh_period", 2}, {"grid", {8, 8}}};
    s["tuning"]["curve_points"] = 3;
    s["tuning"]["max_evaluations"] = 4;
  }
  if (kind == "cycloid_min_size") {
    s["analysis"] = {{"crank_angles_per_mesh_period", 2}, {"grid", {8, 8}}};
    s["optimizer"]["starts"] = 1;
    s["optimizer"]["max_evaluations"] = 4;
    s["optimizer"]["verify_rounds"] = 0;
  }
  if (kind == "lcr_crowning_tuning") {
    s["tuning"]["curve_points"] = 3;
    s["tuning"]["refine_iterations"] = 1;
    s["tuning"]["angle_steps"] = 36;
    s["tuning"]["slices"] = 10;
    s["tuning"]["grid"] = {16, 32};
  }
  if (kind == "disc_cam") {
    s["analysis"]["angle_steps"] = 360;
    s["analysis"]["monte_carlo"] = {{"samples", 8}, {"angle_steps", 72}, {"scales", {1}}};
  }
  if (kind == "globoidal_cam") {
    s["analysis"] = {{"angle_steps", 72}, {"axis_steps", 3}};
    s["dynamics"] = {{"cam_speeds_rpm", {600}}, {"end_time_s", 0.02}, {"relative_tolerance", 1e-6},
                     {"absolute_tolerance", 1e-8}};
    s["export"] = {{"stl", false}, {"point_cloud", false}};
  }
  // The tolerance analyses at 20 Monte-Carlo samples (200 and 300 in the examples): each knob's
  // runs repeat the whole analysis, and every sample is a run of the exact model.
  if ((kind == "cycloid_ltca" || kind == "lcr_analysis") && s.contains("monte_carlo"))
    s["monte_carlo"]["samples"] = 20;
  if (kind == "transmission_rigidity")
    for (auto& e : s["chain"])
      if (e["element"] == "lobe_cam_reducer") e["angle_steps"] = 72;
  return s;
}

// The example files of studies/examples (the roller catalogue is not a study), sorted.
std::vector<std::string> ConvergenceExamples() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(SourcePath("studies/examples"))) {
    if (entry.path().extension() != ".json") continue;
    if (!Example(entry.path().filename().string()).is_object()) continue;
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// Every example: the study's own files are those of a plain run; convergence.json has one entry
// per knob with three runs (each timed or skipped with a reason) and, per headline, three values
// and a non-negative error estimate of the study's setting. One test per example, so that each has
// its own time limit and ctest runs them in parallel (one test over all examples reached the
// 600 s limit on a loaded machine once the 3D and robust sizing examples were added).
class ConvergenceOfExample : public ::testing::TestWithParam<std::string> {};

TEST_P(ConvergenceOfExample, CoarseSettings) {
  const std::string name = GetParam();
  const json study = Coarse(Example(name));
  studies::RunContext ctx;
  ctx.quiet = true;
  ctx.study_file = SourcePath("studies/examples/" + name);  // relative files (catalogues) resolve beside it
  const studies::ConvergenceRun run = studies::RunConvergence(study, ctx);
  const studies::Outputs plain = studies::RunStudy(study, ctx);
  ASSERT_TRUE(run.own.files().count("result.json"));
  EXPECT_EQ(run.own.files().at("result.json"), plain.files().at("result.json"))
      << "the study's own result is that of its settings";
  const json& r = run.report;
  EXPECT_EQ(r["study"], study["study"]);
  ASSERT_TRUE(r["headlines"].is_array());
  EXPECT_FALSE(r["headlines"].empty());
  ASSERT_TRUE(r["knobs"].is_array());
  if (r["knobs"].empty()) {
    EXPECT_TRUE(r["no_knob"].is_string());
  }
  for (const json& k : r["knobs"]) {
    SCOPED_TRACE(k["name"].get<std::string>());
    ASSERT_EQ(k["runs"].size(), 3u);
    EXPECT_EQ(k["runs"][1]["setting"], "study");
    for (const json& run_j : k["runs"])
      EXPECT_TRUE(run_j.contains("wall_time_s") != run_j.contains("skipped")) << run_j.dump();
    EXPECT_TRUE(k["runs"][1].contains("wall_time_s"));
    for (const auto& [h, o] : k["outputs"].items()) {
      ASSERT_EQ(o["values"].size(), 3u) << h;
      EXPECT_EQ(o["values"][1], r["study_run"]["values"][h]) << h;
      if (o["method"] != "none") {
        EXPECT_GE(o["estimated_error"].get<double>(), 0.0) << h;
        // The difference to the finest run, recomputed from the values in the file.
        if (o["method"] == "difference_to_finest") {
          EXPECT_DOUBLE_EQ(o["estimated_error"].get<double>(),
                           std::abs(o["values"][1].get<double>() - o["values"][2].get<double>()))
              << h;
        }
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryExample, ConvergenceOfExample, ::testing::ValuesIn(ConvergenceExamples()),
                         [](const auto& example) {
                           std::string n = example.param.substr(0, example.param.size() - 5);
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

// Every study kind has an example, and most examples' kinds declare fidelity knobs on the coarse
// settings the test above runs (read from the kinds' declarations, not by running them).
TEST(Convergence, EveryKindHasAnExampleAndMostDeclareKnobs) {
  size_t examples = 0, kinds_with_knobs = 0;
  std::set<std::string> kinds;
  for (const std::string& name : ConvergenceExamples()) {
    const json study = Coarse(Example(name));
    const std::string kind = study["study"].get<std::string>();
    kinds.insert(kind);
    const studies::FidelityOf* fidelity = studies::FindFidelity(kind);
    if (fidelity != nullptr && !(*fidelity)(study).knobs.empty()) ++kinds_with_knobs;
    ++examples;
  }
  EXPECT_GE(examples, 19u);
  EXPECT_EQ(kinds.size(), studies::StudyKinds().size()) << "every study kind has an example";
  EXPECT_GE(kinds_with_knobs, 15u);
}

// Through the CLI: the same result.json as a plain run, convergence.json and the error plots next
// to it, the table on stdout; --quiet keeps stderr empty.
TEST(Convergence, CommandLine) {
  const auto dir = TempDir("convergence-cli");
  json study = Example("lcr_ii.json");
  study["analysis"]["angle_steps"] = 360;
  WriteFile(dir / "study.json", study.dump());
  const auto plain = RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " + (dir / "plain").string());
  ASSERT_EQ(plain.exit_code, 0) << plain.stderr_text;
  const auto res = RunCamopt("run " + (dir / "study.json").string() + " --quiet --convergence --out " +
                             (dir / "conv").string() + " > " + (dir / "table.txt").string());
  ASSERT_EQ(res.exit_code, 0) << res.stderr_text;
  EXPECT_EQ(res.stderr_text, "");
  EXPECT_EQ(ReadFile(dir / "conv" / "result.json"), ReadFile(dir / "plain" / "result.json"));
  const json c = json::parse(ReadFile(dir / "conv" / "convergence.json"));
  ASSERT_EQ(c["knobs"].size(), 1u);
  EXPECT_EQ(c["knobs"][0]["name"], "angle_steps");
  EXPECT_EQ(c["knobs"][0]["runs"][0]["value"], 180);
  EXPECT_EQ(c["knobs"][0]["runs"][2]["value"], 720);
  for (const json& p : c["plots"]) EXPECT_TRUE(std::filesystem::exists(dir / "conv" / p.get<std::string>()));
  EXPECT_FALSE(c["plots"].empty());
  const std::string table = ReadFile(dir / "table.txt");
  EXPECT_NE(table.find("knob angle_steps"), std::string::npos) << table;
  EXPECT_NE(table.find("/output_cam/max_contact_stress_MPa"), std::string::npos) << table;

  // Progress on stderr without --quiet.
  const auto loud = RunCamopt("run " + (dir / "study.json").string() + " --convergence --out " +
                              (dir / "conv").string() + " > /dev/null");
  ASSERT_EQ(loud.exit_code, 0) << loud.stderr_text;
  EXPECT_NE(loud.stderr_text.find("convergence: run 3/3"), std::string::npos) << loud.stderr_text;
}

// A refinement over the work limits is skipped and recorded, the study still runs.
TEST(Convergence, RefinementOverTheWorkLimitIsSkipped) {
  json study = Example("cycloid_ltca_nnm_none.json");
  study["analysis"] = {{"crank_angles_per_mesh_period", 4}, {"grid", {64, 64}}, {"estimate_error", false}};
  // The work cap of cycloid_ltca is 5e7 cell solves (docs/reliability.md), estimated as 4 angles
  // × 16 rollers × cells: 64×64 is 2.6e5, 128×128 is 1.05e6; a factor 0.01 lets only the first pass.
  studies::RunContext ctx;
  ctx.quiet = true;
  ctx.max_work_factor = 0.01;
  const studies::ConvergenceRun run = studies::RunConvergence(study, ctx);
  const json* grid = nullptr;
  for (const json& k : run.report["knobs"])
    if (k["name"] == "grid") grid = &k;
  ASSERT_NE(grid, nullptr);
  EXPECT_TRUE((*grid)["runs"][2].contains("skipped")) << grid->dump();
  EXPECT_NE((*grid)["runs"][2]["skipped"].get<std::string>().find("work"), std::string::npos) << grid->dump();
  EXPECT_TRUE((*grid)["runs"][0].contains("wall_time_s"));
  EXPECT_EQ((*grid)["outputs"]["/max_contact_stress_MPa"]["method"], "difference_to_coarser");
}

}  // namespace convergence_test
}  // namespace camopt
