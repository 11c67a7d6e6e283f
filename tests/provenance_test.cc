// Provenance (camopt_version, the study's SHA-256, --version), plausibility warnings,
// the stdout summary, a clean output folder and a bad --out found before the work.
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/archive.h"
#include "studies/kind.h"
#include "studies/provenance.h"
#include "tests/test_util.h"

namespace provenance_test {

namespace fs = std::filesystem;
using camopt::studies::PlausibilityWarnings;
using camopt::studies::Sha256Hex;
using camopt::testing::Example;
using camopt::testing::ReadFile;
using camopt::testing::RunCamopt;
using camopt::testing::SourcePath;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;
using nlohmann::json;

// stdout of a command (stderr left alone) and its exit code.
std::pair<int, std::string> Capture(const std::string& cmd) {
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf{};
  size_t n = 0;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

// FIPS 180-2 appendix B and the empty message (published test vectors).
TEST(Sha256, PublishedTestVectors) {
  EXPECT_EQ(Sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(Sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(Sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(Sha256Hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, AgreesWithCoreutilsAtEveryPaddingLength) {
  const auto dir = TempDir("sha");
  for (size_t n : {55, 56, 63, 64, 65, 119, 120, 128}) {
    std::string text;
    for (size_t i = 0; i < n; ++i) text += char('a' + i % 26);
    WriteFile(dir / "t", text);
    const auto [code, out] = Capture("sha256sum " + (dir / "t").string());
    ASSERT_EQ(code, 0);
    EXPECT_EQ(Sha256Hex(text), out.substr(0, 64)) << n << " bytes";
  }
}

TEST(Provenance, ResultRecordsVersionAndTheStudyFilesSha256) {
  const auto dir = TempDir("provenance");
  json s = Example("lcr_ii.json");
  s["analysis"]["angle_steps"] = 360;
  WriteFile(dir / "s.json", s.dump(1));
  const auto [code, summary] =
      Capture(std::string(CAMOPT_BINARY) + " run " + (dir / "s.json").string() + " --quiet --out " +
              (dir / "o").string());
  ASSERT_EQ(code, 0);
  const json r = json::parse(ReadFile(dir / "o" / "result.json"));
  const auto [sc, sum] = Capture("sha256sum " + (dir / "s.json").string());
  ASSERT_EQ(sc, 0);
  EXPECT_EQ(r["study_sha256"], sum.substr(0, 64));
  const auto [vc, version] = Capture(std::string(CAMOPT_BINARY) + " --version");
  EXPECT_EQ(vc, 0);
  EXPECT_EQ(version, "camopt " + r["camopt_version"].get<std::string>() + "\n");
  EXPECT_EQ(r["warnings"], json::array());
  // The summary on stdout: the kind and name, the verdict, then the kind's headline numbers with
  // units and limits (6 significant digits), as report.html lists them.
  EXPECT_EQ(summary.rfind("camopt: lcr_analysis \"LCR II\"\n  verdict: All 8 limits met\n", 0), 0u) << summary;
  char line[160];
  std::snprintf(line, sizeof line, "  largest contact stress, input cam: %.6g MPa (limit ≤ 1500 MPa: pass)\n",
                r["input_cam"]["max_contact_stress_MPa"].get<double>());
  EXPECT_NE(summary.find(line), std::string::npos) << summary;
  EXPECT_NE(summary.find("  speed ratio: -90\n"), std::string::npos) << summary;
  EXPECT_LE(std::count(summary.begin(), summary.end(), '\n'), 27) << summary;
}

TEST(Provenance, SummaryVerdictNamesTheExceededLimits) {
  // LCR II's input cam peaks at 1369 MPa and its output cam at 1215 MPa (docs/validation.md): a
  // 1300 MPa limit is exceeded on the input cam alone; the verdict names it, and its row says fail.
  const auto dir = TempDir("summary_verdict");
  json s = Example("lcr_ii.json");
  s["analysis"]["angle_steps"] = 360;
  s["limits"]["contact_stress_MPa"] = 1300;
  WriteFile(dir / "s.json", s.dump(1));
  const auto [code, summary] =
      Capture(std::string(CAMOPT_BINARY) + " run " + (dir / "s.json").string() + " --quiet --out " +
              (dir / "o").string());
  ASSERT_EQ(code, 0);
  EXPECT_NE(summary.find("  verdict: 1 of 8 limits exceeded: largest contact stress, input cam\n"), std::string::npos)
      << summary;
  EXPECT_NE(summary.find("(limit ≤ 1300 MPa: fail)"), std::string::npos) << summary;
}

TEST(Plausibility, TheIssuesExamplesAreFlaggedAndTheExamplesAreNot) {
  json s = Example("lcr_ii.json");
  s["material"]["youngs_modulus_GPa"] = 206000;
  s["load"]["friction_coefficient"] = 1.5;
  auto w = PlausibilityWarnings(s);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0].rfind("/load/friction_coefficient: ", 0), 0u) << w[0];
  EXPECT_EQ(w[1].rfind("/material/youngs_modulus_GPa: ", 0), 0u) << w[1];
  EXPECT_NE(w[1].find("looks like MPa"), std::string::npos) << w[1];
  json g = Example("globoidal_cam_paper.json");
  g["dynamics"]["cam_speeds_rpm"] = {600, 1e6};
  w = PlausibilityWarnings(g);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("/dynamics/cam_speeds_rpm/1: a speed of 1e+06 rpm", 0), 0u) << w[0];
  g = Example("globoidal_cam_paper.json");
  g["contact"].erase("cam_youngs_modulus_GPa");
  g["contact"]["cam_modulus_MPa"] = 206;  // GPa under the old MPa key
  w = PlausibilityWarnings(g);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("looks like GPa"), std::string::npos) << w[0];
  for (const auto& e : fs::directory_iterator(SourcePath("studies/examples"))) {
    SCOPED_TRACE(e.path().string());
    EXPECT_TRUE(PlausibilityWarnings(json::parse(ReadFile(e.path()))).empty());
  }
}

TEST(Plausibility, A206000GPaModulusWarnsOnStderrAndInResultJson) {
  const auto dir = TempDir("plausible");
  json s = Example("lcr_ii.json");
  s["analysis"]["angle_steps"] = 360;
  s["material"]["youngs_modulus_GPa"] = 206000;
  WriteFile(dir / "s.json", s.dump());
  auto r = RunCamopt("run " + (dir / "s.json").string() + " --out " + (dir / "o").string() + " > /dev/null");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("camopt: warning: " + (dir / "s.json").string() +
                               ": /material/youngs_modulus_GPa: a Young's modulus of 206000 GPa"),
            std::string::npos)
      << r.stderr_text;
  const json result = json::parse(ReadFile(dir / "o" / "result.json"));
  ASSERT_EQ(result["warnings"].size(), 1u);
  EXPECT_EQ(result["warnings"][0].get<std::string>().rfind("/material/youngs_modulus_GPa: ", 0), 0u);
  // --quiet: the warning is in result.json only.
  r = RunCamopt("run " + (dir / "s.json").string() + " --quiet --out " + (dir / "o").string() + " > /dev/null");
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.stderr_text, "");
}

// The backend has one spelling across kinds ("slsqp"); lcr_min_size's old "nlopt_slsqp" still runs,
// to the same answer, with a deprecation warning on stderr and in result.json, which writes the
// one spelling.
TEST(Units, TheOldBackendSpellingRunsTheSameSizingWithADeprecationWarning) {
  const auto dir = TempDir("backend_spelling");
  json now = Example("lcr_min_size_catalogue.json");
  ASSERT_EQ(now["optimizer"]["backend"], "slsqp");
  now["roller_catalogue"]["file"] = SourcePath("studies/examples/" + now["roller_catalogue"]["file"].get<std::string>());
  json old = now;
  old["optimizer"]["backend"] = "nlopt_slsqp";
  WriteFile(dir / "now.json", now.dump());
  WriteFile(dir / "old.json", old.dump());
  const auto a = RunCamopt("run " + (dir / "now.json").string() + " --out " + (dir / "a").string() + " > /dev/null");
  const auto b = RunCamopt("run " + (dir / "old.json").string() + " --out " + (dir / "b").string() + " > /dev/null");
  ASSERT_EQ(a.exit_code, 0) << a.stderr_text;
  ASSERT_EQ(b.exit_code, 0) << b.stderr_text;
  EXPECT_EQ(a.stderr_text.find("deprecated"), std::string::npos) << a.stderr_text;
  EXPECT_NE(b.stderr_text.find("camopt: warning: " + (dir / "old.json").string() +
                               ": /optimizer/backend: \"nlopt_slsqp\" is the old spelling of \"slsqp\""),
            std::string::npos)
      << b.stderr_text;
  json ra = json::parse(ReadFile(dir / "a" / "result.json"));
  json rb = json::parse(ReadFile(dir / "b" / "result.json"));
  EXPECT_EQ(rb["optimizer"]["backend"], "slsqp");
  ASSERT_EQ(rb["warnings"].size(), 1u);
  EXPECT_NE(rb["warnings"][0].get<std::string>().find("deprecated"), std::string::npos);
  // The same answer: only the warning and the study's own hash differ.
  for (json* r : {&ra, &rb}) {
    r->erase("warnings");
    r->erase("study_sha256");
  }
  EXPECT_EQ(ra, rb);
}

TEST(Units, GloboidalModulusInGPaOrUnderItsOldMPaNameGivesTheSameResult) {
  const auto dir = TempDir("units");
  json gpa = Example("globoidal_cam_paper.json");
  gpa["analysis"] = {{"evaluate", {"geometry", "dynamics"}}, {"angle_steps", 72}, {"axis_steps", 3}};
  gpa["dynamics"]["cam_speeds_rpm"] = {600};
  gpa["dynamics"]["end_time_s"] = 0.02;
  gpa["contact"]["cam_youngs_modulus_GPa"] = 210;
  json mpa = gpa;
  mpa["contact"].erase("cam_youngs_modulus_GPa");
  mpa["contact"].erase("cam_poisson_ratio");
  mpa["contact"]["cam_modulus_MPa"] = 210000;
  mpa["contact"]["cam_poisson"] = 0.3;
  json results[2];
  int k = 0;
  for (const json* s : {&gpa, &mpa}) {
    WriteFile(dir / "s.json", s->dump());
    const auto r = RunCamopt("run " + (dir / "s.json").string() + " --quiet --out " + (dir / "o").string() + " > /dev/null");
    ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
    results[k++] = json::parse(ReadFile(dir / "o" / "result.json"));
  }
  EXPECT_EQ(results[0]["effective_modulus_MPa"], results[1]["effective_modulus_MPa"]);
  // 1 / (2 (1 − ν²) / E) with E = 210000 and 206000 MPa: E* = 1/((1−0.09)/210000 + (1−0.09)/206000).
  EXPECT_NEAR(results[0]["effective_modulus_MPa"].get<double>(), 1.0 / (0.91 / 210000 + 0.91 / 206000), 1e-6);
  json both = gpa;
  both["contact"]["cam_modulus_MPa"] = 210000;
  camopt::testing::ExpectStudyRejected(both, "both-names", "/contact/cam_modulus_MPa", "not both");
}

// The issue's case: a run at 600 and 120 rpm, then one at 300 rpm into the same folder, leaves
// exactly the second run's files.
TEST(Output, TheFolderHoldsExactlyThisRunsFiles) {
  const auto dir = TempDir("clean-out");
  json s = Example("globoidal_cam_paper.json");
  s["analysis"] = {{"angle_steps", 72}, {"axis_steps", 3}};
  s["export"] = {{"stl", false}, {"point_cloud", false}};
  std::set<std::string> names[2];
  for (int k = 0; k < 2; ++k) {
    s["dynamics"]["cam_speeds_rpm"] = k == 0 ? json{600, 120} : json{300};
    WriteFile(dir / "s.json", s.dump());
    const auto r = RunCamopt("run " + (dir / "s.json").string() + " --quiet --out " + (dir / "o").string() + " > /dev/null");
    ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
    for (const auto& e : fs::directory_iterator(dir / "o")) names[k].insert(e.path().filename().string());
  }
  bool saw600 = false;
  for (const auto& n : names[0]) saw600 = saw600 || n.find("600rpm") != std::string::npos;
  EXPECT_TRUE(saw600) << "the first run writes files per speed";
  for (const auto& n : names[1]) {
    EXPECT_EQ(n.find("600rpm"), std::string::npos) << n;
    EXPECT_EQ(n.find("120rpm"), std::string::npos) << n;
  }
  bool saw300 = false;
  for (const auto& n : names[1]) saw300 = saw300 || n.find("300rpm") != std::string::npos;
  EXPECT_TRUE(saw300);
  // Nothing else beside the folder (no temporary or old folders left).
  std::set<std::string> beside;
  for (const auto& e : fs::directory_iterator(dir)) beside.insert(e.path().filename().string());
  EXPECT_EQ(beside, (std::set<std::string>{"o", "s.json"}));
}

TEST(Output, AnUnwritableFolderIsFoundBeforeTheWork) {
  const auto dir = TempDir("unwritable");
  WriteFile(dir / "file", "x");
  // lcr_min_size runs for seconds; the refusal comes at once, with the OS's reason.
  const std::string study = SourcePath("studies/examples/lcr_min_size.json");
  for (const fs::path& out : {dir / "file" / "sub", fs::path("/proc/camopt-cannot-write-here")}) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto r = RunCamopt("run " + study + " --quiet --out " + out.string());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
    EXPECT_LT(seconds, 1.0) << r.stderr_text;
    EXPECT_NE(r.stderr_text.find("--out " + out.string() + ": "), std::string::npos) << r.stderr_text;
    EXPECT_EQ(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n'), 1) << r.stderr_text;
  }
}

TEST(Cli, SchemaAndKinds) {
  auto [code, out] = Capture(std::string(CAMOPT_BINARY) + " schema lcr_analysis");
  EXPECT_EQ(code, 0);
  ASSERT_NE(camopt::studies::DeclaredSchema("lcr_analysis"), nullptr);
  EXPECT_EQ(out, *camopt::studies::DeclaredSchema("lcr_analysis"));  // emitted from the declaration
  const json schema = json::parse(out);
  EXPECT_EQ(schema["$schema"], "https://json-schema.org/draft/2020-12/schema");
  std::tie(code, out) = Capture(std::string(CAMOPT_BINARY) + " schema nope 2>/dev/null");
  EXPECT_EQ(code, 2);
  std::tie(code, out) = Capture(std::string(CAMOPT_BINARY) + " 2>/dev/null");
  EXPECT_EQ(code, 2);
}

}  // namespace provenance_test
