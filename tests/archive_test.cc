// The study declaration archives (studies/archive.h): the reader refuses what Node refuses with
// Node's own messages, the schema emitter states the declared bounds, defaults and enums, and the
// writer's output reads back to the same values; a declared result is written whole with its
// non-finite numbers refused by JSON path, and its schema says which members are always there.
#include "studies/archive.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace camopt::studies {
namespace archive_test {

using nlohmann::json;

struct Toy {
  struct Roller {
    double radius_mm = 2.5;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("radius_mm", &radius_mm, Field().Positive().Unit("mm").Desc("roller radius"));
    }
  };
  double length_mm = 0;
  int steps = 720;
  bool flag = true;
  std::string mode = "fast";
  std::optional<double> arm_mm;
  double angle_deg = 10;
  double poisson_ratio = 0.3;
  Roller roller;
  std::vector<double> speeds_rpm;
  std::vector<Roller> rollers;
  std::array<double, 2> range{0.0, 1.0};

  template <typename Archive>
  void Serialize(Archive* a) {
    a->Retired("time_step_s", "no longer used: give a tolerance");
    a->Visit("length_mm", &length_mm, Field().Required().Positive().Unit("mm").Desc("length"));
    a->Visit("steps", &steps, Field().AtLeast(36).AtMost(200000).Desc("angle steps"));
    a->Visit("flag", &flag, Field());
    a->Visit("mode", &mode, Field().OneOf({"fast", "slow"}));
    a->Visit("arm_mm", &arm_mm, Field().Positive().Default(7.0));
    a->Visit("angle_deg", &angle_deg, Field().Positive().Below(180, "an angle in (0, 180) deg"));
    a->Visit("poisson_ratio", &poisson_ratio, Field().In(0.0, 0.4999));
    a->Visit("roller", &roller, Field());
    a->Visit("speeds_rpm", &speeds_rpm, Field().In(0.01, 1e5));
    a->Visit("rollers", &rollers, Field().MinItems(1));
    a->Visit("range", &range, Field());
  }
};

// The message the reader of T gives for `study`, empty when it reads.
template <typename T = Toy>
std::string ReadError(const json& study) {
  try {
    (void)Read<T>(Node(&study, "t.json", ""));
  } catch (const StudyError& e) {
    return e.what();
  }
  return "";
}

// The message without the reader's "; W would fit" (Node's own readers do not say it).
std::string WithoutFit(std::string message) {
  const std::string tail = " would fit";
  const size_t at = message.rfind("; ");
  if (at != std::string::npos && message.size() > tail.size() &&
      message.compare(message.size() - tail.size(), tail.size(), tail) == 0)
    message.erase(at);
  return message;
}

// The message Node gives for the value at `key` of `object` read by `read`.
template <typename F>
std::string NodeError(const json& object, const std::string& key, F read) {
  try {
    read(Node(&object, "t.json", "")[key]);
  } catch (const StudyError& e) {
    return e.what();
  }
  return "";
}

const json kGood = {{"length_mm", 10.0}};

TEST(Archive, ReaderGivesNodesMessages) {
  const std::vector<json> values = {-1, 0, 0.5, "x", true, nullptr, json::array({1}), 1.5, 35, 36, 2e9, 0.6};
  for (const json& v : values) {
    SCOPED_TRACE(v.dump());
    json s = kGood;
    s["length_mm"] = v;
    EXPECT_EQ(WithoutFit(ReadError(s)), NodeError(s, "length_mm", [](const Node& n) { n.Positive(); }));
    s = kGood;
    s["steps"] = v;
    const std::string integer = NodeError(s, "steps", [](const Node& n) { n.Integer(36); });
    EXPECT_EQ(WithoutFit(ReadError(s)), integer.empty() ? "" : integer);
    s = kGood;
    s["poisson_ratio"] = v;
    EXPECT_EQ(WithoutFit(ReadError(s)), NodeError(s, "poisson_ratio", [](const Node& n) { n.NumberIn(0.0, 0.4999); }));
    s = kGood;
    s["flag"] = v;
    EXPECT_EQ(ReadError(s), NodeError(s, "flag", [](const Node& n) { n.Bool(); }));
    s = kGood;
    s["speeds_rpm"] = json::array({v});
    const json items = s["speeds_rpm"];
    std::string item_error;
    try {
      Node(&items, "t.json", "/speeds_rpm")[size_t{0}].NumberIn(0.01, 1e5);
    } catch (const StudyError& e) {
      item_error = e.what();
    }
    EXPECT_EQ(WithoutFit(ReadError(s)), item_error);
  }
}

// A number that breaks its field's bounds, or a whole-number field's number that is not whole, is
// told what would fit: the nearest value the bounds hold (rounded for a whole number); nothing at
// an open bound of a real field, where there is no nearest value.
TEST(Archive, ReaderSaysWhatNumberWouldFit) {
  const auto error = [](const char* key, const json& v) {
    json s = kGood;
    s[key] = v;
    return ReadError(s);
  };
  EXPECT_EQ(error("steps", 35), "t.json: /steps: expected a whole number >= 36, found 35; 36 would fit");
  EXPECT_EQ(error("steps", 250.4), "t.json: /steps: expected a whole number >= 36, found 250.4; 250 would fit");
  EXPECT_EQ(error("steps", 2e9), "t.json: /steps: expected a whole number >= 36, found 2000000000.0; 200000 would fit");
  EXPECT_EQ(error("steps", 300000), "t.json: /steps: expected a whole number <= 200000, found 300000; 200000 would fit");
  EXPECT_EQ(error("poisson_ratio", 0.6), "t.json: /poisson_ratio: expected a number in [0, 0.4999], found 0.6; 0.4999 would fit");
  EXPECT_EQ(error("poisson_ratio", -0.1), "t.json: /poisson_ratio: expected a number in [0, 0.4999], found -0.1; 0 would fit");
  // Open bounds of a real field: no nearest value.
  EXPECT_EQ(error("length_mm", -1), "t.json: /length_mm: expected a number > 0, found -1");
  EXPECT_EQ(error("angle_deg", 200), "t.json: /angle_deg: expected an angle in (0, 180) deg, found 200");
  // Not a number at all: nothing to round.
  EXPECT_EQ(error("steps", "many"), "t.json: /steps: expected a whole number >= 36, found a string \"many\"");
}

TEST(Archive, ReaderMessagesForTheRest) {
  json s = json::object();
  EXPECT_EQ(ReadError(s), "t.json: /length_mm: missing required field");
  s = kGood;
  s["steps"] = 200001;
  EXPECT_EQ(ReadError(s), "t.json: /steps: expected a whole number <= 200000, found 200001; 200000 would fit");
  s = kGood;
  s["angle_deg"] = 180;
  EXPECT_EQ(ReadError(s), "t.json: /angle_deg: expected an angle in (0, 180) deg, found 180");
  s["angle_deg"] = 0;
  EXPECT_EQ(ReadError(s), "t.json: /angle_deg: expected a number > 0, found 0");
  s = kGood;
  s["mode"] = "medium";
  EXPECT_EQ(ReadError(s), "t.json: /mode: expected \"fast\" or \"slow\", found a string \"medium\"");
  s = kGood;
  s["time_step_s"] = 1e-5;
  EXPECT_EQ(ReadError(s), "t.json: /time_step_s: no longer used: give a tolerance");
  s = kGood;
  s["roller"] = {{"radius_mm", 1}, {"radius", 1}};
  EXPECT_EQ(ReadError(s), "t.json: /roller/radius: unknown field (known: radius_mm); did you mean \"radius_mm\"?");
  s = kGood;
  s["rollers"] = json::array();
  EXPECT_EQ(ReadError(s), "t.json: /rollers: expected an array of at least 1 items, found an array []");
  s["rollers"] = {{{"radius_mm", -2}}};
  EXPECT_EQ(ReadError(s), "t.json: /rollers/0/radius_mm: expected a number > 0, found -2");
  s = kGood;
  s["range"] = {1, 2, 3};
  EXPECT_EQ(ReadError(s), "t.json: /range: expected an array of 2 numbers, found an array [1,2,3]");
  // An unknown field is refused before any field is read, with every known field listed.
  s = {{"length_mm", -1}, {"lenght_mm", 1}};
  EXPECT_EQ(ReadError(s),
            "t.json: /lenght_mm: unknown field (known: angle_deg, arm_mm, flag, length_mm, mode, poisson_ratio, "
            "range, roller, rollers, speeds_rpm, steps, time_step_s); did you mean \"length_mm\"?");
  // A misspelt choice gets the nearest one (Node::Fail, studies/suggest.h).
  s = kGood;
  s["mode"] = "slwo";
  EXPECT_EQ(ReadError(s), "t.json: /mode: expected \"fast\" or \"slow\", found a string \"slwo\" (did you mean \"slow\"?)");
}

TEST(Archive, ReaderFillsDefaultsAndKeepsGivenValues) {
  const json s = {{"length_mm", 10.0}, {"arm_mm", 3.0}, {"rollers", {{{"radius_mm", 4}}, json::object()}},
                  {"roller", json::object()}, {"range", {-1, 2}}};
  const Toy t = Read<Toy>(Node(&s, "t.json", ""));
  EXPECT_EQ(t.length_mm, 10.0);
  EXPECT_EQ(t.steps, 720);
  EXPECT_EQ(t.mode, "fast");
  ASSERT_TRUE(t.arm_mm.has_value());
  EXPECT_EQ(*t.arm_mm, 3.0);
  EXPECT_EQ(t.roller.radius_mm, 2.5);
  ASSERT_EQ(t.rollers.size(), 2u);
  EXPECT_EQ(t.rollers[0].radius_mm, 4.0);
  EXPECT_EQ(t.rollers[1].radius_mm, 2.5);
  EXPECT_EQ(t.range[0], -1.0);
  EXPECT_EQ(t.range[1], 2.0);
  const json bare = kGood;
  EXPECT_FALSE(Read<Toy>(Node(&bare, "t.json", "")).arm_mm.has_value());
}

TEST(Archive, SchemaStatesTheDeclaration) {
  const json s = json::parse(EmitSchema<Toy>("toy", "a toy").dump());
  EXPECT_EQ(s["$schema"], "https://json-schema.org/draft/2020-12/schema");
  EXPECT_EQ(s["type"], "object");
  EXPECT_EQ(s["additionalProperties"], false);
  EXPECT_EQ(s["required"], json::array({"length_mm"}));
  const json& p = s["properties"];
  EXPECT_EQ(p["length_mm"], json({{"description", "length [mm]"}, {"type", "number"}, {"exclusiveMinimum", 0}}));
  EXPECT_EQ(p["steps"], json({{"description", "angle steps"}, {"type", "integer"}, {"minimum", 36},
                              {"maximum", 200000}, {"default", 720}}));
  EXPECT_EQ(p["mode"], json({{"enum", {"fast", "slow"}}, {"default", "fast"}}));
  EXPECT_EQ(p["arm_mm"], json({{"type", "number"}, {"exclusiveMinimum", 0}, {"default", 7.0}}));
  EXPECT_EQ(p["angle_deg"]["exclusiveMaximum"], 180);
  EXPECT_EQ(p["poisson_ratio"]["minimum"], 0.0);
  EXPECT_EQ(p["poisson_ratio"]["maximum"], 0.4999);
  EXPECT_EQ(p["roller"]["additionalProperties"], false);
  EXPECT_EQ(p["roller"]["properties"]["radius_mm"]["default"], 2.5);
  EXPECT_EQ(p["speeds_rpm"]["items"], json({{"type", "number"}, {"minimum", 0.01}, {"maximum", 1e5}}));
  EXPECT_EQ(p["rollers"]["minItems"], 1);
  EXPECT_EQ(p["range"]["minItems"], 2);
  EXPECT_EQ(p["range"]["maxItems"], 2);
  EXPECT_FALSE(p.contains("time_step_s"));  // retired: known to the reader only to be refused
}

TEST(Archive, WriterOutputReadsBackTheSame) {
  const json s = {{"length_mm", 10.0}, {"arm_mm", 3.0}, {"mode", "slow"}, {"speeds_rpm", {1, 2}},
                  {"rollers", {{{"radius_mm", 4}}}}};
  const json written = json::parse(WriteJson(Read<Toy>(Node(&s, "t.json", ""))).dump());
  EXPECT_EQ(written["length_mm"], 10.0);
  EXPECT_EQ(written["steps"], 720);
  EXPECT_EQ(written["mode"], "slow");
  EXPECT_EQ(written["rollers"][0]["radius_mm"], 4.0);
  EXPECT_EQ(written["speeds_rpm"], json({1.0, 2.0}));
  const json again = json::parse(WriteJson(Read<Toy>(Node(&written, "t.json", ""))).dump());
  EXPECT_EQ(again, written);
}

// A `true | false | {settings}` field (BoolOr): read by JSON type, `true` the settings' defaults.
struct Switched {
  struct Settings {
    int samples = 200;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("samples", &samples, Field().AtLeast(1).Desc("draws"));
    }
  };
  BoolOr<Settings> check = true;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("check", &check, Field().Desc("the check: true, false or its settings"));
  }
};

TEST(Archive, BoolOrReadsByJsonTypeAndStatesBothTypes) {
  auto read = [](const json& s) { return Read<Switched>(Node(&s, "t.json", "")); };
  const auto error = [](const json& s) { return ReadError<Switched>(s); };
  // Absent and true: the settings' defaults; false: none; an object: its values.
  ASSERT_TRUE(Enabled(read(json::object()).check));
  EXPECT_EQ(Enabled(read(json::object()).check)->samples, 200);
  EXPECT_EQ(Enabled(read({{"check", true}}).check)->samples, 200);
  EXPECT_FALSE(Enabled(read({{"check", false}}).check));
  EXPECT_EQ(Enabled(read({{"check", {{"samples", 7}}}}).check)->samples, 7);
  EXPECT_TRUE(std::holds_alternative<Switched::Settings>(read({{"check", json::object()}}).check));
  // Anything else names the field and the three forms; the object's own fields keep their messages.
  for (const json& v : {json(3), json("x"), json::array(), json(nullptr)})
    EXPECT_EQ(error({{"check", v}}).rfind("t.json: /check: expected true, false or an object, found ", 0), 0u)
        << v.dump();
  EXPECT_EQ(error({{"check", {{"samples", 0}}}}), "t.json: /check/samples: expected a whole number >= 1, found 0; 1 would fit");
  EXPECT_EQ(error({{"check", {{"sample", 3}}}}).rfind("t.json: /check/sample: unknown field (known: samples)", 0), 0u);
  // The schema: both types, the object's properties closed, the default `true`.
  const json schema = json::parse(EmitSchema<Switched>("toy", "t").dump());
  const json& c = schema["properties"]["check"];
  EXPECT_EQ(c["type"], json({"boolean", "object"}));
  EXPECT_EQ(c["properties"]["samples"]["minimum"], 1);
  EXPECT_EQ(c["additionalProperties"], false);
  EXPECT_EQ(c["default"], true);
  // The writer writes the alternative held, which reads back the same.
  for (const json& v : {json(true), json(false), json({{"samples", 9}})}) {
    const json s = {{"check", v}};
    const json written = json::parse(WriteJson(read(s)).dump());
    EXPECT_EQ(written, s);
  }
}


// A variant told apart by JSON type: {"file": …} or the list itself.
struct Listed {
  struct File {
    std::string file;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("file", &file, Field().Required().Desc("where the list is"));
    }
  };
  std::optional<std::variant<File, std::vector<double>>> items;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("items", &items, Field().Positive().MinItems(1, "a non-empty list").Desc("the list or its file"));
  }
};

TEST(Archive, VariantReadsTheAlternativeOfItsJsonType) {
  auto read = [](const json& s) { return Read<Listed>(Node(&s, "t.json", "")); };
  const auto error = [](const json& s) { return ReadError<Listed>(s); };
  EXPECT_FALSE(read(json::object()).items);
  const auto file = read({{"items", {{"file", "a.json"}}}}).items;
  ASSERT_TRUE(file && std::holds_alternative<Listed::File>(*file));
  EXPECT_EQ(std::get<Listed::File>(*file).file, "a.json");
  const auto list = read({{"items", {1.5, 2}}}).items;
  ASSERT_TRUE(list && std::holds_alternative<std::vector<double>>(*list));
  EXPECT_EQ(std::get<std::vector<double>>(*list), (std::vector<double>{1.5, 2}));
  // Each alternative keeps its own checks; another JSON type names both.
  EXPECT_EQ(error({{"items", json::array()}}), "t.json: /items: expected a non-empty list, found an array []");
  EXPECT_EQ(error({{"items", {1, -1}}}), "t.json: /items/1: expected a number > 0, found -1");
  EXPECT_EQ(error({{"items", json::object()}}), "t.json: /items/file: missing required field");
  EXPECT_EQ(error({{"items", 3}}), "t.json: /items: expected an object or an array, found 3");
  // The schema: the type list and each alternative's schema.
  const json s = json::parse(EmitSchema<Listed>("toy", "t").dump())["properties"]["items"];
  EXPECT_EQ(s["type"], json({"object", "array"}));
  ASSERT_EQ(s["oneOf"].size(), 2u);
  EXPECT_EQ(s["oneOf"][0]["required"], json({"file"}));
  EXPECT_EQ(s["oneOf"][1]["minItems"], 1);
  EXPECT_EQ(s["oneOf"][1]["items"]["exclusiveMinimum"], 0);
  for (const json& v : {json({{"file", "b.json"}}), json({2.0, 3.0})}) {
    const json in = {{"items", v}};
    EXPECT_EQ(json::parse(WriteJson(read(in)).dump()), in);
  }
}

// Rules between fields: a range whose ends are two fields, inside a block.
struct Ranged {
  struct Span {
    double lo_mm = 0, hi_mm = 1;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("lo_mm", &lo_mm, Field().Unit("mm"));
      a->Visit("hi_mm", &hi_mm, Field().Unit("mm"));
    }
    static std::vector<CrossFieldRule> CrossFieldRules() { return {{{"lo_mm", "hi_mm"}, "lo_mm < hi_mm", "lo < hi"}}; }
  };
  Span span;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("span", &span, Field().Desc("the span"));
  }
};

TEST(Archive, CrossFieldRulesAreAnnotationsOfTheirObjectAndRowsOfTheTable) {
  const nlohmann::ordered_json schema = EmitSchema<Ranged>("toy", "t");
  const json s = json::parse(schema.dump());
  EXPECT_FALSE(s.contains("x-rules"));
  EXPECT_EQ(s["properties"]["span"]["x-rules"],
            json::parse(R"([{"fields": ["lo_mm", "hi_mm"], "rule": "lo_mm < hi_mm", "message": "lo < hi"}])"));
  const std::string table = SchemaFieldTable(schema);
  EXPECT_NE(table.find("Rules between fields"), std::string::npos) << table;
  EXPECT_NE(table.find("- `span.lo_mm`, `span.hi_mm`: lo_mm < hi_mm\n"), std::string::npos) << table;
  // Reading does not check the rule (the kind's parse does).
  const json in = {{"span", {{"lo_mm", 2}, {"hi_mm", 1}}}};
  EXPECT_EQ(Read<Ranged>(Node(&in, "t.json", "")).span.lo_mm, 2);
}

// A declared result (ResultWriter, ResultSchemaEmitter).
struct ToyResult {
  struct Row {
    double stiffness_N_per_mm = 0;
    std::optional<double> margin;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("stiffness_N_per_mm", &stiffness_N_per_mm, Field().NullWhenNotFinite().Unit("N/mm"));
      a->Visit("margin", &margin, Field().Desc("limit − value"));
    }
  };
  std::string study = "toy";
  double stress_MPa = 0;
  int count = 0;
  bool ok = false;
  std::optional<double> deflection_deg;
  std::vector<Row> rows;
  std::map<std::string, double> elasticity;
  std::optional<double> covariance;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Const("toy"));
    a->Visit("covariance", &covariance, Field().NullWhenAbsent());
    a->Visit("stress_MPa", &stress_MPa, Field().Unit("MPa").Desc("the largest stress"));
    a->Visit("count", &count, Field());
    a->Visit("ok", &ok, Field());
    a->Visit("deflection_deg", &deflection_deg, Field().Unit("deg"));
    a->Visit("rows", &rows, Field());
    a->Visit("elasticity", &elasticity, Field());
  }
};

TEST(Archive, ResultWriterWritesEveryMemberAndRefusesNonFiniteNumbersByPath) {
  ToyResult r;
  r.stress_MPa = 1234.5;
  r.count = 3;
  r.rows = {{7.0, 0.5}, {std::numeric_limits<double>::infinity(), std::nullopt}};
  r.elasticity = {{"width_mm", 1.5}, {"diameter_mm", -0.25}};
  const json j = WriteResult(r);
  EXPECT_EQ(j["stress_MPa"], 1234.5);
  EXPECT_EQ(j["count"], 3);
  EXPECT_EQ(j["ok"], false);
  EXPECT_FALSE(j.contains("deflection_deg"));  // an unset optional is absent
  EXPECT_TRUE(j.contains("covariance"));        // unless NullWhenAbsent: null
  EXPECT_TRUE(j["covariance"].is_null());
  EXPECT_EQ(j["rows"][0]["margin"], 0.5);
  EXPECT_TRUE(j["rows"][1]["stiffness_N_per_mm"].is_null());  // NullWhenNotFinite
  EXPECT_FALSE(j["rows"][1].contains("margin"));
  EXPECT_EQ(j["elasticity"], json({{"diameter_mm", -0.25}, {"width_mm", 1.5}}));
  // Keys sorted, as result.json has them.
  EXPECT_EQ(j.dump().rfind("{\"count\":3,\"covariance\":null,\"elasticity\":{\"diameter_mm\"", 0), 0u);
  const auto path_of = [](ToyResult x) -> std::string {
    try {
      (void)WriteResult(x);
    } catch (const NonFiniteResult& e) {
      return e.what();
    }
    return "";
  };
  ToyResult bad = r;
  bad.stress_MPa = std::nan("");
  EXPECT_EQ(path_of(bad), "/stress_MPa");
  bad = r;
  bad.rows[0].margin = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(path_of(bad), "/rows/0/margin");
  bad = r;
  bad.elasticity["width_mm"] = std::nan("");
  EXPECT_EQ(path_of(bad), "/elasticity/width_mm");
  bad = r;
  bad.deflection_deg = std::numeric_limits<double>::infinity();
  EXPECT_EQ(path_of(bad), "/deflection_deg");
}

TEST(Archive, ResultSchemaSaysWhatIsAlwaysThereAndWhatMayBeNull) {
  const nlohmann::ordered_json s = EmitResultSchema<ToyResult>("toy", "toy result");
  EXPECT_EQ(s["$id"], "https://camopt.invalid/schema/toy.result.schema.json");
  EXPECT_EQ(s["additionalProperties"], false);
  const auto& p = s["properties"];
  EXPECT_EQ(p["stress_MPa"]["type"], "number");
  EXPECT_EQ(p["stress_MPa"]["description"], "the largest stress [MPa]");
  EXPECT_EQ(p["count"]["type"], "integer");
  EXPECT_EQ(p["study"]["const"], "toy");
  EXPECT_EQ(p["rows"]["items"]["properties"]["stiffness_N_per_mm"]["type"], nlohmann::ordered_json({"number", "null"}));
  EXPECT_EQ(p["rows"]["items"]["required"], nlohmann::ordered_json({"stiffness_N_per_mm"}));
  EXPECT_EQ(p["elasticity"]["additionalProperties"]["type"], "number");
  EXPECT_EQ(p["covariance"]["type"], nlohmann::ordered_json({"number", "null"}));
  // Required: the members that are not std::optional, then the run's stamp (RunStudy).
  const std::vector<std::string> required = s["required"];
  for (const char* always : {"study", "covariance", "stress_MPa", "count", "ok", "rows", "elasticity", "status", "camopt_version",
                             "study_sha256", "warnings"})
    EXPECT_NE(std::find(required.begin(), required.end(), always), required.end()) << always;
  EXPECT_EQ(std::find(required.begin(), required.end(), "deflection_deg"), required.end());
  EXPECT_EQ(std::find(required.begin(), required.end(), "status_reason"), required.end());
  EXPECT_TRUE(p["status"]["enum"].size() == 7);
}

}  // namespace archive_test
}  // namespace camopt::studies
