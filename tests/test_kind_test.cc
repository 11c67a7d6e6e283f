// A kind added with an Input, a Result, a Run and one registration (tests/test_kind.cc, linked into
// camopt_with_test_kind) gets everything a kind has: it is listed by `camopt kinds`, `camopt init`
// writes a study of it, `camopt schema` prints its input's and its result's JSON Schema, `camopt run`
// checks its input (exit 2 naming the field), runs it and writes result.json and report.html, and the
// studio lists, checks, draws (as not supported) and runs it. Its numbers are checked against
// Hertz's line contact written out here.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/test_util.h"
// After Eigen (through test_util.h): tests/studio_child.h brings httplib.h.
#include "tests/studio_child.h"

namespace test_kind_test {

namespace fs = std::filesystem;
using camopt::testing::ReadFile;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;
using nlohmann::json;

struct Ran {
  int exit_code = -1;
  std::string out, err;
};

// camopt_with_test_kind ARGS, its stdout and stderr captured.
Ran Cli(const std::string& args) {
  static int calls = 0;
  const fs::path dir = TempDir("test-kind-cli-" + std::to_string(++calls));
  const std::string cmd = std::string(CAMOPT_TEST_KIND_BINARY) + " " + args + " > " + (dir / "out").string() +
                          " 2> " + (dir / "err").string();
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, ReadFile(dir / "out"), ReadFile(dir / "err")};
}

// Hertz's line contact of a roller of radius R and length L on a flat under F, both bodies of
// modulus E and Poisson ratio ν: E* = E / (2 (1 − ν²)), b = √(4 F R / (π L E*)), p0 = 2 F / (π b L)
// (Johnson, Contact Mechanics, eq. 4.45 and 4.46).
struct Hertz {
  double p0_MPa, b_mm;
};
Hertz LineContact(double F, double L, double R, double E, double nu) {
  const double e_star = E / (2 * (1 - nu * nu));
  const double b = std::sqrt(4 * F * R / (M_PI * L * e_star));
  return {2 * F / (M_PI * b * L), b};
}

TEST(TestKind, IsListedAndHasInitAndBothSchemas) {
  const Ran kinds = Cli("kinds");
  ASSERT_EQ(kinds.exit_code, 0) << kinds.err;
  EXPECT_NE(kinds.out.find("test_line_contact"), std::string::npos) << kinds.out;
  EXPECT_NE(kinds.out.find("a roller on a flat (the test kind)"), std::string::npos) << kinds.out;

  const fs::path dir = TempDir("test-kind-init");
  const Ran init = Cli("init test_line_contact --out " + (dir / "s.json").string());
  ASSERT_EQ(init.exit_code, 0) << init.err;
  const json study = json::parse(ReadFile(dir / "s.json"));
  EXPECT_EQ(study["study"], "test_line_contact");
  // Every declared default spelled out (the Input's member initialisers).
  EXPECT_EQ(study["force_N"], 1000.0);
  EXPECT_EQ(study["length_mm"], 10.0);
  EXPECT_EQ(study["roller_radius_mm"], 5.0);
  EXPECT_EQ(study["youngs_modulus_MPa"], 206000.0);
  EXPECT_EQ(study["poisson_ratio"], 0.3);

  const Ran in = Cli("schema test_line_contact");
  ASSERT_EQ(in.exit_code, 0) << in.err;
  const json input_schema = json::parse(in.out);
  EXPECT_EQ(input_schema["properties"]["force_N"]["default"], 1000.0);
  EXPECT_EQ(input_schema["properties"]["force_N"]["exclusiveMinimum"], 0.0);
  EXPECT_NE(input_schema["properties"]["force_N"]["description"].get<std::string>().find("[N]"), std::string::npos)
      << input_schema["properties"]["force_N"];
  EXPECT_EQ(input_schema["additionalProperties"], false);

  const Ran out = Cli("schema test_line_contact --result");
  ASSERT_EQ(out.exit_code, 0) << out.err;
  const json result_schema = json::parse(out.out);
  for (const char* key : {"max_contact_stress_MPa", "half_width_mm", "status", "camopt_version"})
    EXPECT_TRUE(result_schema["properties"].contains(key)) << key;
  const json& required = result_schema["required"];
  EXPECT_NE(std::find(required.begin(), required.end(), "max_contact_stress_MPa"), required.end()) << required;
}

TEST(TestKind, RunsChecksItsInputAndWritesItsResultAndReport) {
  const fs::path dir = TempDir("test-kind-run");
  const double F = 2500, L = 12, R = 8, E = 210000, nu = 0.28;
  WriteFile(dir / "s.json", json{{"study", "test_line_contact"}, {"name", "roller 8"}, {"force_N", F},
                                 {"length_mm", L}, {"roller_radius_mm", R}, {"youngs_modulus_MPa", E},
                                 {"poisson_ratio", nu}}.dump(2));
  const Ran run = Cli("run " + (dir / "s.json").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json result = json::parse(ReadFile(dir / "out" / "result.json"));
  const Hertz h = LineContact(F, L, R, E, nu);
  EXPECT_NEAR(result["max_contact_stress_MPa"].get<double>(), h.p0_MPa, 1e-9 * h.p0_MPa);  // 854.9 MPa
  EXPECT_NEAR(result["half_width_mm"].get<double>(), h.b_mm, 1e-9 * h.b_mm);
  EXPECT_EQ(result["name"], "roller 8");
  EXPECT_EQ(result["status"], "limits_met");
  // Every key of result.json is in its schema, and every key the schema says is always there is.
  const json schema = json::parse(Cli("schema test_line_contact --result").out);
  for (auto it = result.begin(); it != result.end(); ++it)
    EXPECT_TRUE(schema["properties"].contains(it.key())) << it.key();
  for (const json& key : schema["required"]) EXPECT_TRUE(result.contains(key.get<std::string>())) << key;
  // The report shows the result's numbers (a kind without report rows: its top-level numbers).
  const std::string report = ReadFile(dir / "out" / "report.html");
  EXPECT_NE(report.find("max_contact_stress_MPa"), std::string::npos);
  char p0[32];
  std::snprintf(p0, sizeof p0, "%.6g", h.p0_MPa);
  EXPECT_NE(report.find(p0), std::string::npos) << p0;

  // Bad input: the field, what was expected and what was found, exit 2, nothing written.
  WriteFile(dir / "bad.json", R"({"study": "test_line_contact", "force_N": -1})");
  const Ran bad = Cli("run " + (dir / "bad.json").string() + " --out " + (dir / "bad").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("/force_N"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir / "bad"));
  WriteFile(dir / "unknown.json", R"({"study": "test_line_contact", "forse_N": 1})");
  const Ran unknown = Cli("run " + (dir / "unknown.json").string() + " --out " + (dir / "unknown").string());
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("force_N"), std::string::npos) << unknown.err;  // what would fit
}

TEST(TestKind, HasAStudioEntry) {
  const fs::path dir = TempDir("test-kind-studio");
  const std::string study = R"({"study": "test_line_contact", "name": "s", "force_N": 1500})";
  WriteFile(dir / "s.json", study);
  camopt::testing::StudioChild studio(dir, {}, "/dev/null", CAMOPT_TEST_KIND_BINARY);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  auto kinds = c.Get("/api/kinds");
  ASSERT_TRUE(kinds);
  const json listed = json::parse(kinds->body);
  EXPECT_NE(std::find(listed.begin(), listed.end(), "test_line_contact"), listed.end()) << listed;
  auto schema = c.Get("/api/schema/test_line_contact");
  ASSERT_TRUE(schema);
  EXPECT_EQ(schema->status, 200);
  EXPECT_TRUE(json::parse(schema->body)["properties"].contains("force_N"));
  auto valid = c.Post("/api/validate", study, "application/json");
  ASSERT_TRUE(valid);
  EXPECT_EQ(json::parse(valid->body)["ok"], true) << valid->body;
  auto invalid = c.Post("/api/validate", R"({"study": "test_line_contact", "force_N": 0})", "application/json");
  ASSERT_TRUE(invalid);
  EXPECT_EQ(json::parse(invalid->body)["ok"], false) << invalid->body;
  auto drawn = c.Post("/api/mechanism", study, "application/json");
  ASSERT_TRUE(drawn);
  EXPECT_EQ(json::parse(drawn->body)["supported"], false) << drawn->body;  // no drawing declared
  auto started = c.Post("/api/runs", R"({"path": "s.json"})", "application/json");
  ASSERT_TRUE(started);
  ASSERT_EQ(started->status, 201) << started->body;
  const int id = json::parse(started->body)["id"].get<int>();
  json status;
  for (int k = 0; k < 600; ++k) {  // up to a minute
    auto polled = c.Get(("/api/runs/" + std::to_string(id)).c_str());
    ASSERT_TRUE(polled);
    status = json::parse(polled->body);
    if (status["finished"] == true) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_EQ(status["state"], "done") << status;
  const json result = json::parse(ReadFile(dir / status["out"].get<std::string>() / "result.json"));
  const Hertz h = LineContact(1500, 10, 5, 206000, 0.3);
  EXPECT_NEAR(result["max_contact_stress_MPa"].get<double>(), h.p0_MPa, 1e-9 * h.p0_MPa);
}

}  // namespace test_kind_test
