// The result schemas of the kinds whose result.json is declared (studies/archive.h,
// `camopt schema KIND --result`): every JSON pointer the rest of camopt reads from a result — the
// report's headline rows, their limits and error estimates, the asked-for blocks of the status,
// the convergence headlines of each example — names a member the schema declares, so that a
// renamed result field fails here and not in a user's report or sweep. (That each example's
// result.json validates against the schema is checked by an independent validator, jsonschema, in
// python/tests/test_schemas.py.)
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/archive.h"
#include "studies/datasheet.h"
#include "studies/ratings.h"
#include "studies/report.h"
#include "studies/schemas.h"
#include "studies/status.h"
#include "studies/study.h"
#include "tests/test_util.h"

namespace camopt::studies {
namespace result_schema_test {

using nlohmann::ordered_json;

// Whether the JSON pointer `pointer` names a member the schema allows: each token a declared
// property, an array index into `items`, or a key of an object of `additionalProperties`.
bool Declares(const ordered_json& schema, const std::string& pointer) {
  const ordered_json* s = &schema;
  size_t at = 1;
  while (at <= pointer.size() && pointer.size() > 1) {
    const size_t end = std::min(pointer.find('/', at), pointer.size());
    const std::string token = pointer.substr(at, end - at);
    if (s->contains("properties") && (*s)["properties"].contains(token)) {
      s = &(*s)["properties"][token];
    } else if (s->contains("items") && !token.empty() &&
               token.find_first_not_of("0123456789") == std::string::npos) {
      s = &(*s)["items"];
    } else if (s->contains("additionalProperties") && (*s)["additionalProperties"].is_object()) {
      s = &(*s)["additionalProperties"];
    } else {
      return false;
    }
    at = end + 1;
  }
  return true;
}

ordered_json ResultSchemaOf(const std::string& kind) { return ordered_json::parse(StudyResultSchema(kind)); }

TEST(ResultSchema, DeclaredKindsAreKnownKindsAndUndeclaredOnesSaySo) {
  const std::vector<std::string> declared = KindsWithDeclaredResult();
  ASSERT_FALSE(declared.empty());
  const std::vector<std::string> kinds = StudyKinds();
  for (const std::string& k : declared) EXPECT_NE(std::find(kinds.begin(), kinds.end(), k), kinds.end()) << k;
  for (const std::string& k : kinds) {
    if (std::find(declared.begin(), declared.end(), k) != declared.end()) continue;
    try {
      (void)StudyResultSchema(k);
      ADD_FAILURE() << k << ": a schema for an undeclared result";
    } catch (const StudyError& e) {
      EXPECT_NE(std::string(e.what()).find("not declared yet"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW((void)StudyResultSchema("no_such_kind"), StudyError);
}

TEST(ResultSchema, TheMatcherFollowsPropertiesItemsAndMaps) {
  const ordered_json s = ResultSchemaOf("transmission_rigidity");
  EXPECT_TRUE(Declares(s, "/rigidity_Nm_per_rad"));
  EXPECT_TRUE(Declares(s, "/elements/3/reducer/dead_band_arcmin"));
  EXPECT_TRUE(Declares(s, "/elements/0/rigidity_elasticity/outer_diameter_mm"));
  EXPECT_TRUE(Declares(s, "/status"));
  EXPECT_FALSE(Declares(s, "/rigidity_Nm_per_radian"));
  EXPECT_FALSE(Declares(s, "/elements/x/name"));
  EXPECT_FALSE(Declares(s, "/dominant/advice/0"));
}

TEST(ResultSchema, EveryPointerIntoAResultNamesADeclaredMember) {
  for (const std::string& kind : KindsWithDeclaredResult()) {
    SCOPED_TRACE(kind);
    const ordered_json s = ResultSchemaOf(kind);
    int checked = 0;
    if (const std::vector<Headline>* headlines = FindHeadlines(kind)) {
      for (const Headline& h : *headlines) {
        EXPECT_TRUE(Declares(s, h.pointer)) << h.label << ": " << h.pointer;
        if (!h.error_pointer.empty()) {
          EXPECT_TRUE(Declares(s, h.error_pointer)) << h.label << ": " << h.error_pointer;
        }
        if (!h.limit_pointer.empty() && h.limit_pointer.rfind("study:", 0) != 0) {
          EXPECT_TRUE(Declares(s, h.limit_pointer)) << h.label << ": " << h.limit_pointer;
        }
        ++checked;
      }
    }
    for (const AskedBlock& b : AskedBlocks(kind)) {
      EXPECT_TRUE(Declares(s, b.answer)) << b.what << ": " << b.answer;
      if (!b.reason.empty()) {
        EXPECT_TRUE(Declares(s, b.reason)) << b.what << ": " << b.reason;
      }
      ++checked;
    }
    // The convergence headlines of every example of the kind (they depend on the study).
    const FidelityOf* fidelity = FindFidelity(kind);
    for (const auto& entry : std::filesystem::directory_iterator(camopt::testing::SourcePath("studies/examples"))) {
      if (entry.path().extension() != ".json") continue;
      const nlohmann::json study = camopt::testing::Example(entry.path().filename().string());
      if (!study.is_object() || study.value("study", "") != kind || !fidelity) continue;
      for (const std::string& p : (*fidelity)(study).headlines) {
        EXPECT_TRUE(Declares(s, p)) << entry.path().filename() << ": " << p;
        ++checked;
      }
    }
    EXPECT_GT(checked, 0);
  }
}

// datasheet.html's shared rows (the ratings and the output bearing, studies/ratings.h) and the
// life table it reads name members of lcr_analysis's result: its raw blocks list those keys.
TEST(ResultSchema, LcrAnalysisDeclaresTheDatasheetsRatingsRows) {
  const ordered_json s = ResultSchemaOf("lcr_analysis");
  int checked = 0;
  for (const DatasheetSection& section : RatingsDatasheetSections())
    for (const DatasheetRow& row : section.rows) {
      EXPECT_TRUE(Declares(s, row.pointer)) << section.title << ": " << row.pointer;
      if (!row.why_pointer.empty()) {
        EXPECT_TRUE(Declares(s, row.why_pointer)) << section.title << ": " << row.why_pointer;
      }
      ++checked;
    }
  for (const char* p : {"/life/table/0/L10h", "/life/table/0/element", "/life/life_h", "/masses/includes",
                        "/stiffness/lost_motion_at_percent_arcmin", "/stiffness_segments/K3_Nm_per_arcmin",
                        "/joint_model/tilt_stiffness_Nm_per_rad", "/lubrication/efficiency"}) {
    EXPECT_TRUE(Declares(s, p)) << p;
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

}  // namespace result_schema_test
}  // namespace camopt::studies
