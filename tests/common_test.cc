// Tests of the foundation: scalar helpers, study input errors, writers, the CLI contract.
#include <map>
#include <array>
#include <chrono>
#include <filesystem>
#include <thread>
#include <type_traits>
#include <cmath>
#include <iostream>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cad/dxf.h"
#include "model/common/geometry.h"
#include "model/common/scalar.h"
#include "studies/input.h"
#include "studies/study.h"
#include "studies/sweep.h"
#include "studies/writers.h"
#include "tests/test_util.h"

namespace camopt {
namespace common_test {

TEST(Scalar, SoftMaxBoundsTheMaximum) {
  const std::vector<double> x = {1.0, 3.0, 2.5, -4.0};
  for (double k : {1.0, 10.0, 100.0}) {
    const double s = SoftMax(x, k);
    EXPECT_GE(s, 3.0);
    EXPECT_LE(s, 3.0 + std::log(4.0) / k);
    const double m = SoftMin(x, k);
    EXPECT_LE(m, -4.0);
    EXPECT_GE(m, -4.0 - std::log(4.0) / k);
  }
}

// The maximum of no samples has no value: refused, not read past the end (a sizing cycle with no
// loaded sample ended in a segmentation fault).
TEST(Scalar, MaximaOfNoSamplesAreRefused) {
  const std::vector<double> none;
  EXPECT_THROW(SoftMax(none, 10.0), std::invalid_argument);
  EXPECT_THROW(SoftMin(none, 10.0), std::invalid_argument);
  EXPECT_THROW(HardMax(none), std::invalid_argument);
  EXPECT_THROW(HardMin(none), std::invalid_argument);
  EXPECT_EQ(HardMax(std::vector<double>{2.0}), 2.0);
}

TEST(Scalar, SoftMaxGradientMatchesCentralDifferences) {
  auto f = [](const auto& v) {
    using T = std::decay_t<decltype(v[0])>;
    std::vector<T> x(v.begin(), v.end());
    return std::vector<T>{SoftMax(x, 5.0), SoftMin(x, 5.0)};
  };
  camopt::testing::ExpectJacobianMatchesCentralDifferences<3>(f, {0.3, 0.5, 0.1});
}

TEST(Geometry, RotateAndCross) {
  const Vec2<double> a(1.0, 0.0);
  const Vec2<double> b = Rotate(a, kPi / 2);
  EXPECT_NEAR(b.x(), 0.0, 1e-15);
  EXPECT_NEAR(b.y(), 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(Cross(a, b), 1.0);
  EXPECT_DOUBLE_EQ(Perp(a).y(), 1.0);
}

TEST(StudyInput, ErrorsNameFilePathExpectedAndFound) {
  const nlohmann::json j = nlohmann::json::parse(R"({"a": {"b": "x", "n": -1, "k": 2.5}})");
  const studies::Node root(&j, "s.json", "");
  try {
    root["a"]["b"].Positive();
    FAIL() << "no error";
  } catch (const studies::StudyError& e) {
    EXPECT_EQ(std::string(e.what()), "s.json: /a/b: expected a number > 0, found a string \"x\"");
  }
  try {
    root["a"]["missing"];
    FAIL() << "no error";
  } catch (const studies::StudyError& e) {
    EXPECT_EQ(std::string(e.what()), "s.json: /a/missing: missing required field");
  }
  EXPECT_THROW(root["a"]["n"].NonNegative(), studies::StudyError);
  EXPECT_THROW(root["a"]["k"].Integer(1), studies::StudyError);
  EXPECT_EQ(root["a"].NumberOr("absent", 7.0), 7.0);
}

TEST(StudyRunner, UnknownKindIsAStudyError) {
  const nlohmann::json j = nlohmann::json::parse(R"({"study": "no_such_kind"})");
  studies::RunContext ctx;
  ctx.study_file = "x.json";
  try {
    studies::RunStudy(j, ctx);
    FAIL() << "no error";
  } catch (const studies::StudyError& e) {
    EXPECT_NE(std::string(e.what()).find("x.json: /study: expected a known study kind"),
              std::string::npos)
        << e.what();
  }
}

TEST(Progress, LineShowsElapsedTimeAndClockTextReads) {
  using camopt::studies::ClockText;
  EXPECT_EQ(ClockText(0), "0:00");
  EXPECT_EQ(ClockText(7.4), "0:07");
  EXPECT_EQ(ClockText(754), "12:34");
  EXPECT_EQ(ClockText(3723), "1:02:03");
  EXPECT_EQ(ClockText(-5), "0:00");
  // The first line is shown at once (stderr is not a terminal under ctest): label, percentage,
  // elapsed time; no ETA before a second has passed.
  std::ostringstream captured;
  std::streambuf* old = std::cerr.rdbuf(captured.rdbuf());
  {
    camopt::studies::Progress p("demo", false);
    p.Update(0.25, "case 1");
  }
  std::cerr.rdbuf(old);
  const std::string line = captured.str();
  EXPECT_NE(line.find("demo:  25.0%  0:00 elapsed  case 1"), std::string::npos) << line;
  EXPECT_EQ(line.find("ETA"), std::string::npos) << line;
}

TEST(Progress, ObserverSeesEveryProgressEvenQuietAndIsThrottled) {
  std::vector<camopt::studies::ProgressEvent> seen;
  auto previous = camopt::studies::SetProgressObserver(
      [&seen](const camopt::studies::ProgressEvent& e) { seen.push_back(e); });
  {
    camopt::studies::Progress p("quiet work", true);
    p.Update(0.1, "first");
    for (int i = 0; i < 1000; ++i) p.Update(0.2, "at once");  // within 100 ms of the first
  }
  camopt::studies::SetProgressObserver(previous);
  ASSERT_EQ(seen.size(), 2u);  // the first report and the closing one
  EXPECT_EQ(seen[0].label, "quiet work");
  EXPECT_DOUBLE_EQ(seen[0].fraction, 0.1);
  EXPECT_EQ(seen[0].detail, "first");
  EXPECT_FALSE(seen[0].done);
  EXPECT_LT(seen[0].eta_s, 0.0);  // no ETA before a second has passed
  EXPECT_TRUE(seen[1].done);
  EXPECT_DOUBLE_EQ(seen[1].fraction, 0.2);
  // Removed: nothing more is seen.
  { camopt::studies::Progress p("after", true); p.Update(0.5); }
  EXPECT_EQ(seen.size(), 2u);
}

// The cooperative cancellation (studies/study.h): Progress::Update throws StudyCancelled, which
// is no std::exception (handlers of errors let it through); a study run and a sweep's thread pool
// unwind with it (no std::terminate from a joinable thread), and nothing is written.
TEST(Cancel, ProgressUpdateThrowsStudyCancelledWhichIsNoStdException) {
  static_assert(!std::is_base_of_v<std::exception, camopt::studies::StudyCancelled>);
  camopt::studies::Progress p("cancelled", true);
  p.Update(0.1);
  camopt::studies::RequestCancel();
  EXPECT_THROW(p.Update(0.2), camopt::studies::StudyCancelled);
  camopt::studies::ClearCancel();
  EXPECT_NO_THROW(p.Update(0.3));
}

TEST(Cancel, AStudyAndASweepUnwindAndWriteNothing) {
  const auto dir = camopt::testing::TempDir("cancel");
  nlohmann::json s = camopt::testing::Example("lcr_ii.json");
  s["analysis"] = {{"angle_steps", 360}};
  camopt::studies::RequestCancel();
  EXPECT_THROW(camopt::studies::RunStudy(s, camopt::studies::RunContext("lcr_ii.json", true)),
               camopt::studies::StudyCancelled);
  camopt::studies::ClearCancel();
  EXPECT_NO_THROW(camopt::studies::RunStudy(s, camopt::studies::RunContext("lcr_ii.json", true)));
  // A sweep of eight cases on two threads, cancelled from another thread while it runs.
  nlohmann::json base = camopt::testing::Example("cycloid_ltca_nnm_none.json");
  // 100 distinct phases (no angle repeats a phase): about a second a case, running when cancelled.
  base["analysis"] = {{"crank_angles_per_mesh_period", 100}};
  camopt::testing::WriteFile(dir / "base.json", base.dump());
  nlohmann::json sweep = {{"sweep", "cancelled"},
                          {"base", "base.json"},
                          {"vary", {{{"path", "/load/torque_Nm"}, {"values", {100, 200, 300, 400, 500, 600, 700, 800}}}}},
                          {"outputs", {"/max_contact_stress_MPa"}}};
  camopt::testing::WriteFile(dir / "sweep.json", sweep.dump());
  camopt::studies::sweep::Options o;
  o.file = (dir / "sweep.json").string();
  o.out = (dir / "out").string();
  o.jobs = 2;
  o.quiet = true;
  o.summary = false;
  std::thread canceller([] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    camopt::studies::RequestCancel();
  });
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_THROW(camopt::studies::sweep::RunCommand(o), camopt::studies::StudyCancelled);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  canceller.join();
  camopt::studies::ClearCancel();
  EXPECT_LT(seconds, 5.0);
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(Outputs, RejectsNonFiniteNumbers) {
  studies::Outputs out;
  nlohmann::json j;
  j["a"]["b"] = std::nan("");
  EXPECT_THROW(out.AddJson("r.json", j), std::runtime_error);
}

TEST(Writers, CsvHasHeaderAndRows) {
  studies::Table t;
  t.Add("x_mm", {1, 2});
  t.Add("y_N", {3.5, 4});
  EXPECT_EQ(studies::ToCsv(t), "x_mm,y_N\n1,3.5\n2,4\n");
}

TEST(Writers, DxfHasPolylineAndEof) {
  // The DXF writer is cad::DxfDocument now (dxflib's output had invalid owner handles).
  cad::DxfDocument d;
  d.AddLayer("PROFILE", 7);
  d.AddChain("PROFILE", {{Vec2<double>(0, 0), Vec2<double>(1, 0), 0.0}, {Vec2<double>(1, 0), Vec2<double>(1, 1), 0.0}},
             false);
  const std::string dxf = d.ToString();
  EXPECT_NE(dxf.find("POLYLINE"), std::string::npos);
  EXPECT_NE(dxf.find("PROFILE"), std::string::npos);
  EXPECT_NE(dxf.find("EOF"), std::string::npos);
}

TEST(Cli, MissingFileAndBadJsonExitWithCode2) {
  const auto dir = camopt::testing::TempDir("cli-bad");
  const std::string out = " --out " + (dir / "out").string();
  auto r = camopt::testing::RunCamopt("run " + (dir / "nope.json").string() + " --quiet" + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("nope.json"), std::string::npos);
  camopt::testing::WriteFile(dir / "bad.json", "{ \"study\": ");
  r = camopt::testing::RunCamopt("run " + (dir / "bad.json").string() + " --quiet" + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("expected valid JSON"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "out")) << "the output folder given is not created";
}

}  // namespace common_test
}  // namespace camopt

namespace camopt {
namespace common_test {

// Every study kind rejects a misspelt top-level field instead of silently ignoring it.
// `--timings`: one line with every phase of the run in order, each CPU and wall time >= 0, and the
// total their sum; the solve of a real analysis takes time. Without the flag, no such line.
TEST(Cli, TimingsSayWhereTheRunsTimeWent) {
  const auto dir = camopt::testing::TempDir("timings");
  nlohmann::json s = nlohmann::json::parse(camopt::testing::ReadFile(camopt::testing::SourcePath("studies/examples/lcr_ii.json")));
  s["analysis"]["angle_steps"] = 720;
  camopt::testing::WriteFile(dir / "s.json", s.dump());
  const auto r = camopt::testing::RunCamopt("run " + (dir / "s.json").string() + " --quiet --timings --out " +
                                            (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const std::string key = "camopt: timings (CPU s / wall s): ";
  const size_t at = r.stderr_text.find(key);
  ASSERT_NE(at, std::string::npos) << r.stderr_text;
  const std::string line = r.stderr_text.substr(at + key.size(), r.stderr_text.find('\n', at) - at - key.size());
  std::vector<std::string> names;
  double cpu_sum = 0.0, solve = 0.0, total = -1.0;
  std::istringstream parts(line);
  std::string part;
  while (std::getline(parts, part, ',')) {
    if (const size_t semi = part.find("; total "); semi != std::string::npos) {
      total = std::stod(part.substr(semi + 8));
      part = part.substr(0, semi);
    }
    std::istringstream p(part);
    std::string name, slash;
    double cpu = -1, wall = -1;
    p >> name >> cpu >> slash >> wall;
    EXPECT_GE(cpu, 0.0) << part;
    EXPECT_GE(wall, 0.0) << part;
    names.push_back(name);
    cpu_sum += cpu;
    if (name == "solve") solve = cpu;
  }
  EXPECT_EQ(names, (std::vector<std::string>{"read", "checks", "parse", "solve", "files", "status", "report", "write"}))
      << line;
  EXPECT_NEAR(total, cpu_sum, 0.0011 * names.size()) << line;  // each printed to 1 ms
  EXPECT_GT(solve, 0.0) << line;
  const auto quiet = camopt::testing::RunCamopt("run " + (dir / "s.json").string() + " --quiet --out " +
                                                (dir / "out2").string());
  EXPECT_EQ(quiet.stderr_text.find(key), std::string::npos) << quiet.stderr_text;
}

// A sizing's `--timings` line splits its solve: the verification by the accurate model and the
// re-solves that price the binding limits are phases of their own right after "solve", and the
// total is still the sum of every phase (disc_cam_min_size.json verifies and prices two limits).
TEST(Cli, TimingsOfASizingSplitTheVerificationAndTheLimitCostsOutOfTheSolve) {
  const auto dir = camopt::testing::TempDir("timings-sizing");
  const auto r = camopt::testing::RunCamopt("run " + camopt::testing::SourcePath("studies/examples/disc_cam_min_size.json") +
                                            " --quiet --timings --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const std::string key = "camopt: timings (CPU s / wall s): ";
  const size_t at = r.stderr_text.find(key);
  ASSERT_NE(at, std::string::npos) << r.stderr_text;
  std::string line = r.stderr_text.substr(at + key.size(), r.stderr_text.find('\n', at) - at - key.size());
  const size_t semi = line.find("; total ");
  ASSERT_NE(semi, std::string::npos) << line;
  const double total = std::stod(line.substr(semi + 8));
  line = line.substr(0, semi);
  std::vector<std::string> names;
  std::map<std::string, double> cpu;
  double sum = 0.0;
  for (size_t from = 0; from <= line.size();) {
    const size_t comma = std::min(line.find(", ", from), line.size());
    const std::string part = line.substr(from, comma - from);  // "limit costs 0.155 / 0.155"
    const size_t slash = part.rfind(" / "), space = part.rfind(' ', slash - 1);
    ASSERT_NE(slash, std::string::npos) << part;
    names.push_back(part.substr(0, space));
    cpu[names.back()] = std::stod(part.substr(space + 1, slash - space - 1));
    EXPECT_GE(cpu[names.back()], 0.0) << part;
    sum += cpu[names.back()];
    from = comma + 2;
  }
  EXPECT_EQ(names, (std::vector<std::string>{"read", "checks", "parse", "solve", "verification", "limit costs", "files",
                                             "status", "report", "write"}))
      << line;
  EXPECT_GT(cpu["verification"], 0.0) << line;
  EXPECT_GT(cpu["limit costs"], 0.0) << line;
  EXPECT_NEAR(total, sum, 0.0011 * names.size()) << line;
}

TEST(Cli, EveryKindRejectsAnUnknownTopLevelField) {
  int kinds = 0;
  for (const auto& entry : std::filesystem::directory_iterator(camopt::testing::SourcePath("studies/examples"))) {
    nlohmann::json study = nlohmann::json::parse(camopt::testing::ReadFile(entry.path()));
    if (!study.is_object() || !study.contains("study")) continue;  // e.g. a roller catalogue
    study["nmae"] = "typo";
    camopt::testing::ExpectStudyRejected(study, "unknown-" + entry.path().stem().string(), "/nmae",
                                         "unknown field");
    ++kinds;
  }
  EXPECT_GE(kinds, 8);
}

}  // namespace common_test
}  // namespace camopt
