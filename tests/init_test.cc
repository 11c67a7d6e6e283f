// `camopt init KIND`: for every kind the written study runs (exit 0) and its verdict names every
// limit the kind considers that the template does not set; for a kind declared once
// it spells out every field of the kind's schema that has a default (checked against the emitted
// JSON Schema, a different archive of the declaration than the writer's), at every nesting level.
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/archive.h"
#include "studies/init.h"
#include "studies/kind.h"
#include "studies/study.h"
#include "tests/test_util.h"
#include "tests/verdict_check.h"

namespace camopt {
namespace init_test {

using camopt::testing::ReadFile;
using camopt::testing::RunCamopt;
using camopt::testing::TempDir;
using nlohmann::json;

// Every property of an object schema that has a "default" is in `study` (recursively into the
// objects the study holds); the pointers of those missing are appended to `missing`.
void DefaultsPresent(const json& schema, const json& study, const std::string& at, std::vector<std::string>& missing) {
  if (!schema.contains("properties") || !study.is_object()) return;
  for (const auto& [name, sub] : schema["properties"].items()) {
    const std::string p = at + "/" + name;
    if (!study.contains(name)) {
      if (sub.contains("default")) missing.push_back(p);
      continue;
    }
    DefaultsPresent(sub, study[name], p, missing);
  }
}

TEST(Init, EveryKindsStudyRunsAndDeclaredKindsSpellOutEveryDefault) {
  const auto dir = TempDir("init-every-kind");
  for (const std::string& kind : studies::StudyKinds()) {
    SCOPED_TRACE(kind);
    const auto file = dir / (kind + ".json");
    const auto wrote = RunCamopt("init " + kind + " --out " + file.string());
    ASSERT_EQ(wrote.exit_code, 0) << wrote.stderr_text;
    const json study = json::parse(ReadFile(file));
    EXPECT_EQ(study["study"], kind);
    // A kind whose limits have defaults that depend on the design writes them out (disc_cam).
    if (kind == "disc_cam") {
      ASSERT_TRUE(study.contains("limits")) << "disc_cam's template has no limits";
      for (const char* limit : {"pressure_angle_deg", "radius_margin_mm", "contact_stress_MPa"})
        EXPECT_TRUE(study["limits"].contains(limit)) << limit;
    }
    std::vector<std::string> missing;
    DefaultsPresent(json::parse(*studies::DeclaredSchema(kind)), study, "", missing);
    EXPECT_TRUE(missing.empty()) << "fields with a default not written: " << ::testing::PrintToString(missing);
    EXPECT_NE(wrote.stderr_text.find("every field and default spelled out"), std::string::npos);
    const auto ran = RunCamopt("run " + file.string() + " --quiet --out " + (dir / (kind + "_out")).string());
    EXPECT_EQ(ran.exit_code, 0) << ran.stderr_text;
    EXPECT_TRUE(std::filesystem::exists(dir / (kind + "_out") / "result.json"));
    // A verdict over the limits this template sets names every other limit the kind considers.
    camopt::testing::ExpectVerdictNamesUnsetLimits(kind, study, json::parse(ReadFile(dir / (kind + "_out") / "result.json")),
                                                   ReadFile(dir / (kind + "_out") / "report.html"));
  }
}

TEST(Init, UnknownKindAndAnExistingFileAreRefusedWithExit2) {
  const auto dir = TempDir("init-refused");
  auto res = RunCamopt("init lcr_anlysis");
  EXPECT_EQ(res.exit_code, 2);
  EXPECT_NE(res.stderr_text.find("did you mean \"lcr_analysis\""), std::string::npos) << res.stderr_text;
  const auto file = dir / "mine.json";
  camopt::testing::WriteFile(file, "{\"study\": \"lcr_analysis\"}");
  res = RunCamopt("init disc_cam --out " + file.string());
  EXPECT_EQ(res.exit_code, 2);
  EXPECT_NE(res.stderr_text.find("exists"), std::string::npos) << res.stderr_text;
  EXPECT_EQ(ReadFile(file), "{\"study\": \"lcr_analysis\"}");  // untouched
  res = RunCamopt("inti disc_cam");
  EXPECT_EQ(res.exit_code, 2);
  EXPECT_NE(res.stderr_text.find("did you mean \"init\""), std::string::npos) << res.stderr_text;
}

}  // namespace init_test
}  // namespace camopt
