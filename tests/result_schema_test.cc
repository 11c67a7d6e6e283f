// The result schemas of the kinds whose result.json is declared (studies/archive.h,
// `camopt schema KIND --result`): every JSON pointer the rest of camopt reads from a result — the
// report's headline rows, their limits and error estimates, the asked-for blocks of the status,
// the convergence headlines of each example — names a member the schema declares, so that a
// renamed result field fails here and not in a user's report or sweep. (That each example's
// result.json validates against the schema is checked by an independent validator, jsonschema, in
// python/tests/test_result_examples.py.)
#include <algorithm>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/archive.h"
#include "studies/datasheet.h"
#include "studies/kind.h"
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
// property, an array index into `items`, or a key of an object of `additionalProperties`; in a
// member that is one of several blocks (oneOf: a stage's result or its error), in one of them.
bool Declares(const ordered_json& schema, const std::string& pointer) {
  if (pointer.size() <= 1) return true;
  if (schema.contains("oneOf"))
    for (const ordered_json& branch : schema["oneOf"])
      if (Declares(branch, pointer)) return true;
  const size_t end = std::min(pointer.find('/', 1), pointer.size());
  const std::string token = pointer.substr(1, end - 1), rest = pointer.substr(end);
  if (schema.contains("properties") && schema["properties"].contains(token))
    return Declares(schema["properties"][token], rest);
  if (schema.contains("items") && !token.empty() && token.find_first_not_of("0123456789") == std::string::npos)
    return Declares(schema["items"], rest);
  if (schema.contains("additionalProperties") && schema["additionalProperties"].is_object())
    return Declares(schema["additionalProperties"], rest);
  return false;
}

ordered_json ResultSchemaOf(const std::string& kind) { return ordered_json::parse(StudyResultSchema(kind)); }

TEST(ResultSchema, EveryKindHasOneAndAnUnknownKindIsRefused) {
  ASSERT_FALSE(StudyKinds().empty());
  for (const std::string& k : StudyKinds()) EXPECT_NO_THROW((void)StudyResultSchema(k)) << k;
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
  // A stage's block or its error (OrError): the members of either.
  const ordered_json l = ResultSchemaOf("cycloid_ltca");
  EXPECT_TRUE(Declares(l, "/lubrication/power_loss_W/total"));
  EXPECT_TRUE(Declares(l, "/lubrication/error"));
  EXPECT_FALSE(Declares(l, "/lubrication/power_loss"));
}

TEST(ResultSchema, EveryPointerIntoAResultNamesADeclaredMember) {
  for (const std::string& kind : StudyKinds()) {
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

// The members that decide a run's status are marked on their declaration (Field::Decides), so the
// status is read from the typed result: a kind that writes a top-level converged, feasible or
// warning without the mark would have its status silently ignored.
TEST(ResultSchema, EveryTopLevelConvergedFeasibleOrWarningDecidesTheStatus) {
  size_t marked = 0;
  for (const std::string& kind : StudyKinds()) {
    SCOPED_TRACE(kind);
    const ordered_json s = ResultSchemaOf(kind);
    std::vector<std::string> named;
    for (const char* key : {"converged", "feasible", "warning"})
      if (s["properties"].contains(key)) named.push_back(key);
    std::vector<std::string> keys = DeclaredRunFactKeys(kind);
    std::sort(keys.begin(), keys.end());
    std::sort(named.begin(), named.end());
    EXPECT_EQ(keys, named);
    marked += keys.size();
  }
  EXPECT_GE(marked, 3u);  // cycloid_ltca's converged and warning, cycloid_crowning_tuning's feasible
}

// A small declared result: its facts come from the members marked Decides, typed, wherever the
// Serialize puts them; an unmarked member of the same name decides nothing.
struct FactsResult {
  struct Block {
    bool converged = false;
    template <typename Archive>
    void Serialize(Archive* a) { a->Visit("converged", &converged, Field()); }
  };
  std::optional<bool> converged;
  bool feasible = true;
  std::optional<std::string> warning;
  Block nested;
  double value = 1.5;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("value", &value, Field().Unit("mm"));
    a->Visit("nested", &nested, Field());
    a->Visit("converged", &converged, Field().Decides(RunFact::kConverged));
    a->Visit("feasible", &feasible, Field().Decides(RunFact::kFeasible));
    a->Visit("warning", &warning, Field().Decides(RunFact::kWarning));
  }
};

struct WrongFact {
  double converged = 0;
  template <typename Archive>
  void Serialize(Archive* a) { a->Visit("converged", &converged, Field().Decides(RunFact::kConverged)); }
};

TEST(ResultSchema, RunFactsAreReadFromTheTypedResult) {
  FactsResult r;
  RunFacts f = CollectRunFacts(r);
  EXPECT_FALSE(f.converged.has_value());  // the stage that sets it did not run
  EXPECT_EQ(f.feasible, std::optional<bool>(true));
  EXPECT_EQ(f.warning, "");
  r.converged = false;
  r.feasible = false;
  r.warning = "angle 3 did not converge";
  r.nested.converged = true;
  f = CollectRunFacts(r);
  EXPECT_EQ(f.converged, std::optional<bool>(false));
  EXPECT_EQ(f.feasible, std::optional<bool>(false));
  EXPECT_EQ(f.warning, "angle 3 did not converge");
  EXPECT_EQ(RunFactKeys<FactsResult>(), (std::vector<std::string>{"converged", "feasible", "warning"}));
  EXPECT_THROW((void)CollectRunFacts(WrongFact{}), std::logic_error);
}

// The status follows the typed facts, not result.json's text: a result whose converged member
// is false is not_converged with its warning as the reason, whatever its JSON says; infeasible
// likewise; without facts an analysis of a kind with no limits meets them.
TEST(ResultSchema, TheStatusFollowsTheTypedFacts) {
  const nlohmann::json study = {{"study", "no_kind_for_facts"}};
  {
    FactsResult r;
    r.converged = false;
    r.warning = "angle 3 did not converge";
    Outputs out;
    out.SetResult(r);
    EXPECT_EQ((*out.result())["converged"], false);
    EXPECT_EQ((*out.result())["value"], 1.5);
    SettleStatus("no_kind_for_facts", study, out);
    ASSERT_TRUE(out.status().has_value());
    EXPECT_EQ(*out.status(), Status::kNotConverged);
    EXPECT_EQ(out.status_reason(), "no_kind_for_facts: not converged: angle 3 did not converge");
  }
  {
    FactsResult r;
    r.feasible = false;
    Outputs out;
    out.SetResult(r);
    SettleStatus("no_kind_for_facts", study, out);
    EXPECT_EQ(*out.status(), Status::kInfeasible);
    EXPECT_EQ(out.status_reason(), "no_kind_for_facts: no feasible design");
  }
  {
    Outputs out;  // the same keys as raw JSON decide nothing: only declared members do
    out.SetResultJson({{"converged", false}, {"feasible", false}});
    SettleStatus("no_kind_for_facts", study, out);
    EXPECT_EQ(*out.status(), Status::kLimitsMet);
  }
  {
    FactsResult r;  // a kind's own status stands
    r.converged = false;
    Outputs out;
    out.SetResult(r);
    out.SetStatus(Status::kFeasibleVerified);
    SettleStatus("no_kind_for_facts", study, out);
    EXPECT_EQ(*out.status(), Status::kFeasibleVerified);
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
