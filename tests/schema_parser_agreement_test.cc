// The JSON Schemas `camopt schema KIND` prints and the C++ parsers of studies/ accept the same
// studies (docs/studies.md "Keeping the schemas in step with the parsers", docs/reliability.md
// item 13). Every kind is declared once (studies/kind.h, every registered kind) and has
// its schema emitted from the declaration. For every study kind, studies are generated from the
// kind's schema, starting from each
// example of that kind in studies/examples/: every optional property the schema declares added
// with a valid value, every enum value, every numeric and item-count bound (at the bound and just
// outside it), wrong types, a removed property and an unknown one, and the fields the parser
// knows (its "unknown field (known: …)" list) that the schema does not declare. Each is checked by
// a small JSON Schema validator (the subset of draft 2020-12 the camopt schemas use, below: no
// validator for C++ is installed as a Debian package) and by studies::CheckStudy, the checks of
// `camopt run` (the kind's Parse; nothing is run). The parser must accept exactly what the schema
// accepts and refuse with a StudyError (exit 2) what it refuses. A failure lists every
// disagreement, one line each.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/archive.h"
#include "studies/input.h"
#include "studies/kind.h"
#include "studies/schemas.h"
#include "studies/study.h"
#include "test_util.h"

namespace camopt {
namespace schema_parser_agreement_test {

namespace fs = std::filesystem;
using nlohmann::json;
using studies::Node;
using testing::ReadFile;
using testing::RunCamopt;
using testing::TempDir;
using testing::WriteFile;

// ---------------------------------------------------------------------------------------------
// A JSON Schema validator for the keywords the camopt schemas use: $ref (to #/$defs/…), type,
// const, enum, minimum, maximum, exclusiveMinimum, exclusiveMaximum, items, prefixItems, minItems, maxItems,
// contains, properties, required, additionalProperties, minProperties, dependentRequired, allOf,
// anyOf, oneOf, not, if/then/else, and the annotation x-rules (the rules between fields a kind
// declares, CrossFieldRule: not a validation keyword). An unknown keyword fails the test (so that
// a schema using a new keyword is not silently half-checked).

const std::set<std::string> kKnownKeywords = {
    "$schema", "$id", "$defs", "$ref", "title", "description", "$comment", "comment", "type",
    "const", "enum", "minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum", "items",
    "prefixItems", "minItems", "maxItems", "contains", "properties", "required", "additionalProperties",
    "minProperties", "dependentRequired", "allOf", "anyOf", "oneOf", "not", "if", "then", "else",
    "default", "x-rules"};

class Validator {
 public:
  explicit Validator(const json& root) : root_(root) {}

  /// The first error ("/path: reason"), empty when valid.
  std::string Check(const json& value) const { return Check(root_, value, ""); }
  /// The same against a part of the schema (e.g. an object's own schema).
  std::string CheckAgainst(const json& schema, const json& value) const { return Check(schema, value, ""); }

  const json& Resolve(const json& s) const {
    if (s.is_object() && s.contains("$ref")) {
      const std::string ref = s["$ref"].get<std::string>();
      if (ref.rfind("#/", 0) != 0) throw std::runtime_error("unsupported $ref " + ref);
      return Resolve(root_.at(json::json_pointer(ref.substr(1))));
    }
    return s;
  }

 private:
  static bool IsInteger(const json& v) {
    return v.is_number_integer() || (v.is_number_float() && std::floor(v.get<double>()) == v.get<double>());
  }
  static bool HasType(const json& v, const std::string& t) {
    if (t == "object") return v.is_object();
    if (t == "array") return v.is_array();
    if (t == "string") return v.is_string();
    if (t == "boolean") return v.is_boolean();
    if (t == "null") return v.is_null();
    if (t == "number") return v.is_number();
    if (t == "integer") return v.is_number() && IsInteger(v);
    throw std::runtime_error("unknown type " + t);
  }

  std::string Check(const json& schema, const json& v, const std::string& path) const {
    if (schema.is_boolean()) return schema.get<bool>() ? "" : path + ": false schema";
    for (auto it = schema.begin(); it != schema.end(); ++it)
      if (!kKnownKeywords.count(it.key()))
        throw std::runtime_error("schema keyword not supported by the test: " + it.key());
    if (schema.contains("$ref")) {
      const std::string e = Check(Resolve(schema), v, path);
      if (!e.empty()) return e;
    }
    if (schema.contains("type")) {
      const json& t = schema["type"];
      bool ok = false;
      if (t.is_string()) ok = HasType(v, t.get<std::string>());
      else
        for (const auto& x : t) ok = ok || HasType(v, x.get<std::string>());
      if (!ok) return path + ": not of type " + t.dump();
    }
    if (schema.contains("const") && !(v == schema["const"])) return path + ": not " + schema["const"].dump();
    if (schema.contains("enum")) {
      bool ok = false;
      for (const auto& x : schema["enum"]) ok = ok || v == x;
      if (!ok) return path + ": not one of " + schema["enum"].dump();
    }
    if (v.is_number()) {
      const double x = v.get<double>();
      if (schema.contains("minimum") && !(x >= schema["minimum"].get<double>())) return path + ": < minimum";
      if (schema.contains("maximum") && !(x <= schema["maximum"].get<double>())) return path + ": > maximum";
      if (schema.contains("exclusiveMinimum") && !(x > schema["exclusiveMinimum"].get<double>()))
        return path + ": <= exclusiveMinimum";
      if (schema.contains("exclusiveMaximum") && !(x < schema["exclusiveMaximum"].get<double>()))
        return path + ": >= exclusiveMaximum";
    }
    if (v.is_array()) {
      if (schema.contains("minItems") && v.size() < schema["minItems"].get<size_t>()) return path + ": too few items";
      if (schema.contains("maxItems") && v.size() > schema["maxItems"].get<size_t>()) return path + ": too many items";
      if (schema.contains("items"))
        for (size_t i = 0; i < v.size(); ++i) {
          const std::string e = Check(schema["items"], v[i], path + "/" + std::to_string(i));
          if (!e.empty()) return e;
        }
      if (schema.contains("prefixItems"))
        for (size_t i = 0; i < v.size() && i < schema["prefixItems"].size(); ++i) {
          const std::string e = Check(schema["prefixItems"][i], v[i], path + "/" + std::to_string(i));
          if (!e.empty()) return e;
        }
      if (schema.contains("contains")) {
        bool any = false;
        for (const auto& x : v) any = any || Check(schema["contains"], x, path).empty();
        if (!any) return path + ": contains nothing matching";
      }
    }
    if (v.is_object()) {
      if (schema.contains("minProperties") && v.size() < schema["minProperties"].get<size_t>())
        return path + ": too few properties";
      if (schema.contains("required"))
        for (const auto& r : schema["required"])
          if (!v.contains(r.get<std::string>())) return path + "/" + r.get<std::string>() + ": required";
      if (schema.contains("dependentRequired"))
        for (auto it = schema["dependentRequired"].begin(); it != schema["dependentRequired"].end(); ++it)
          if (v.contains(it.key()))
            for (const auto& r : it.value())
              if (!v.contains(r.get<std::string>())) return path + "/" + r.get<std::string>() + ": required with " + it.key();
      const json props = schema.value("properties", json::object());
      for (auto it = v.begin(); it != v.end(); ++it) {
        const std::string child = path + "/" + it.key();
        if (props.contains(it.key())) {
          const std::string e = Check(props[it.key()], it.value(), child);
          if (!e.empty()) return e;
        } else if (schema.contains("additionalProperties")) {
          const std::string e = Check(schema["additionalProperties"], it.value(), child);
          if (!e.empty()) return child + ": additional property not allowed";
        }
      }
    }
    if (schema.contains("allOf"))
      for (const auto& s : schema["allOf"]) {
        const std::string e = Check(s, v, path);
        if (!e.empty()) return e;
      }
    if (schema.contains("anyOf")) {
      std::string first;
      bool any = false;
      for (const auto& s : schema["anyOf"]) {
        const std::string e = Check(s, v, path);
        any = any || e.empty();
        if (first.empty()) first = e;
      }
      if (!any) return path + ": anyOf: " + first;
    }
    if (schema.contains("oneOf")) {
      int n = 0;
      std::string first;
      for (const auto& s : schema["oneOf"]) {
        const std::string e = Check(s, v, path);
        n += e.empty();
        if (first.empty()) first = e;
      }
      if (n != 1) return path + ": oneOf: " + std::to_string(n) + " branches match" + (n == 0 ? " (" + first + ")" : "");
    }
    if (schema.contains("not") && Check(schema["not"], v, path).empty()) return path + ": matches 'not'";
    if (schema.contains("if")) {
      const bool cond = Check(schema["if"], v, path).empty();
      const char* branch = cond ? "then" : "else";
      if (schema.contains(branch)) {
        const std::string e = Check(schema[branch], v, path);
        if (!e.empty()) return e;
      }
    }
    return "";
  }

  const json& root_;
};

// ---------------------------------------------------------------------------------------------
// Generating studies from a schema.

struct Case {
  std::string what;  ///< "KIND EXAMPLE: /json/path = value" and the like
  json study;
};

class Generator {
 public:
  Generator(const Validator& v, std::string label, std::vector<Case>& out) : v_(v), label_(std::move(label)), out_(out) {}

  /// The schema of an object value, with the properties of every branch (allOf, anyOf, oneOf,
  /// then, else, $ref) merged in: each is a property that can occur there.
  void Properties(const json& schema, std::map<std::string, json>& props) const {
    const json& s = v_.Resolve(schema);
    if (!s.is_object()) return;
    if (s.contains("properties"))
      for (auto it = s["properties"].begin(); it != s["properties"].end(); ++it)
        if (!props.count(it.key())) props[it.key()] = it.value();
    for (const char* k : {"allOf", "anyOf", "oneOf"})
      if (s.contains(k))
        for (const auto& b : s[k]) Properties(b, props);
    for (const char* k : {"then", "else"})
      if (s.contains(k)) Properties(s[k], props);
  }

  /// The types a schema allows ("" when it does not say: const / enum).
  std::vector<std::string> Types(const json& schema) const {
    const json& s = v_.Resolve(schema);
    std::vector<std::string> t;
    if (!s.is_object() || !s.contains("type")) return t;
    if (s["type"].is_string()) return {s["type"].get<std::string>()};
    for (const auto& x : s["type"]) t.push_back(x.get<std::string>());
    return t;
  }

  /// A valid value of a schema taken alone: its default, const, first enum value, or a number
  /// inside its bounds; objects get their required members.
  json ValidValue(const json& schema) const {
    const json& s = v_.Resolve(schema);
    if (s.contains("default")) return s["default"];
    if (s.contains("const")) return s["const"];
    if (s.contains("enum")) return s["enum"][0];
    const auto types = Types(s);
    const std::string t = types.empty() ? "number" : types[0];
    if (t == "number" || t == "integer") {
      const bool integer = t == "integer";
      double lo = -INFINITY, hi = INFINITY;
      if (s.contains("minimum")) lo = s["minimum"].get<double>();
      if (s.contains("exclusiveMinimum")) lo = s["exclusiveMinimum"].get<double>() + (integer ? 1 : 0.5);
      if (s.contains("maximum")) hi = s["maximum"].get<double>();
      if (s.contains("exclusiveMaximum")) hi = s["exclusiveMaximum"].get<double>() - (integer ? 1 : 0.5);
      double x = 1;
      if (std::isfinite(lo) && std::isfinite(hi)) x = integer ? std::ceil(lo) : 0.5 * (lo + hi);
      else if (std::isfinite(lo)) x = std::max(lo, 1.0);
      else if (std::isfinite(hi)) x = std::min(hi, 1.0);
      if (integer) return json(static_cast<long long>(std::ceil(x)));
      return json(x);
    }
    if (t == "string") return "x";
    if (t == "boolean") return true;
    if (t == "array") {
      const size_t n = s.contains("minItems") ? s["minItems"].get<size_t>() : 1;
      json a = json::array();
      for (size_t i = 0; i < n; ++i) a.push_back(s.contains("items") ? ValidValue(s["items"]) : json(1));
      return a;
    }
    if (t == "object") {
      json o = json::object();
      std::map<std::string, json> props;
      Properties(s, props);
      if (s.contains("required"))
        for (const auto& r : s["required"]) o[r.get<std::string>()] = ValidValue(props[r.get<std::string>()]);
      return o;
    }
    return nullptr;
  }

  void Add(const std::string& what, const json& study) { out_.push_back({label_ + ": " + what, study}); }

  /// Every case for the value at `path` of `study` (present there), of schema `schema`.
  void Walk(const json& study, const std::string& path, const json& schema, int depth = 0) {
    if (depth > 8) return;
    const json& s = v_.Resolve(schema);
    const json::json_pointer ptr(path);
    const json& v = study.at(ptr);
    const auto set = [&](const json& x) {
      json c = study;
      c[ptr] = x;
      return c;
    };
    const std::string at = path.empty() ? "/" : path;
    // Enum values.
    if (s.contains("enum"))
      for (const auto& e : s["enum"])
        if (e != v) Add(at + " = " + e.dump(), set(e));
    // Wrong types.
    const auto types = Types(s);
    if (!types.empty()) {
      const auto allows = [&](const char* t) { return std::find(types.begin(), types.end(), t) != types.end(); };
      if (!allows("string")) Add(at + " = \"x\" (wrong type)", set("x"));
      if (!allows("number") && !allows("integer")) Add(at + " = 1 (wrong type)", set(1));
      if (allows("integer") && !allows("number")) Add(at + " = 1.5 (not whole)", set(1.5));
      if (!allows("object") && !allows("array") ) Add(at + " = {} (wrong type)", set(json::object()));
      if (!allows("boolean") && !allows("object") && !allows("array") && !allows("string") && !allows("number") &&
          !allows("integer"))
        Add(at + " = true (wrong type)", set(true));
    }
    // Numeric bounds: at the bound and just outside (one for integers, a relative 1e-6 for numbers).
    if (v.is_number()) {
      const bool integer = !types.empty() && types[0] == "integer";
      const auto step = [&](double b) { return integer ? 1.0 : std::max(1e-6, 1e-6 * std::abs(b)); };
      const auto num = [&](double x) { return integer ? json(static_cast<long long>(std::llround(x))) : json(x); };
      for (const char* k : {"minimum", "exclusiveMinimum"})
        if (s.contains(k)) {
          const double b = s[k].get<double>();
          Add(at + " = " + num(b).dump() + " (" + k + ")", set(num(b)));
          Add(at + " = " + num(b - step(b)).dump() + " (below " + k + ")", set(num(b - step(b))));
        }
      for (const char* k : {"maximum", "exclusiveMaximum"})
        if (s.contains(k)) {
          const double b = s[k].get<double>();
          Add(at + " = " + num(b).dump() + " (" + k + ")", set(num(b)));
          Add(at + " = " + num(b + step(b)).dump() + " (above " + k + ")", set(num(b + step(b))));
        }
    }
    if (v.is_array() && !v.empty()) {
      const json item = v.back();
      for (const char* k : {"minItems", "maxItems"})
        if (s.contains(k)) {
          const size_t n = s[k].get<size_t>();
          for (const size_t m : {n, std::string(k) == "minItems" ? n - 1 : n + 1}) {
            if (m > 64 || m == size_t(-1)) continue;
            json a = v;
            while (a.size() > m) a.erase(a.size() - 1);
            while (a.size() < m) a.push_back(item);
            if (a != v) Add(at + " with " + std::to_string(m) + " items (" + k + ")", set(a));
          }
        }
      if (s.contains("items")) {
        const json& is = v_.Resolve(s["items"]);
        if (v[0].is_number()) {
          // A list of numbers (mostly a range [lo, hi] or a grid [a, b]): the cases of one item,
          // a lower bound on the first item and an upper bound on the last, so that a range keeps
          // lo <= hi; every other case on the first item. Then every item equal (lo = hi).
          for (const size_t i : {size_t(0), v.size() - 1}) {
            std::vector<Case> cases;
            Generator inner(v_, label_, cases);
            inner.Walk(study, path + "/" + std::to_string(i), is, depth + 1);
            for (auto& c : cases) {
              const bool upper = c.what.find("aximum") != std::string::npos;
              if (v.size() > 1 && (i == 0) == upper) continue;
              out_.push_back(std::move(c));
            }
            if (v.size() == 1) break;
          }
          json same = v;
          for (auto& e : same) e = v[0];
          if (same != v) Add(at + " = " + same.dump() + " (all items equal)", set(same));
        } else {
          Walk(study, path + "/0", is, depth + 1);
        }
      }
    }
    if (v.is_object()) {
      std::map<std::string, json> props;
      Properties(s, props);
      const bool closed = s.contains("additionalProperties") && s["additionalProperties"] == false;
      if (closed) {
        json c = study;
        c[ptr]["zz_unknown_field"] = 1;
        Add(at + "/zz_unknown_field added (unknown)", c);
      }
      for (const auto& [name, ps] : props) {
        const std::string child = path + "/" + name;
        if (v.contains(name)) {
          json c = study;
          c[ptr].erase(name);
          Add(child + " removed", c);
          Walk(study, child, ps, depth + 1);
        } else {
          json c = study;
          c[ptr][name] = ValidValue(ps);
          Add(child + " added = " + c[ptr][name].dump(), c);
          if (depth < 6) Walk(c, child, ps, depth + 1);
        }
      }
    }
  }

 private:
  const Validator& v_;
  std::string label_;
  std::vector<Case>& out_;
};

// The schema of the value at `path` of `study` (properties of every branch followed).
json SchemaAt(const Validator& v, const json& schema, const json& study, const std::string& path) {
  json s = v.Resolve(schema);
  if (path.empty()) return s;
  const json::json_pointer ptr(path);
  const std::string head = path.substr(1, path.find('/', 1) == std::string::npos ? std::string::npos : path.find('/', 1) - 1);
  const std::string rest = path.substr(1 + head.size());
  std::vector<Case> none;
  if (study.is_array()) return SchemaAt(v, s.value("items", json::object()), study.at(std::stoul(head)), rest);
  std::map<std::string, json> props;
  Generator(v, "", none).Properties(s, props);
  return SchemaAt(v, props.count(head) ? props[head] : json::object(), study.at(head), rest);
}

// The rules between fields (the annotation "x-rules", CrossFieldRule) of the object schema `s`
// and of its branches (allOf, anyOf, oneOf, then, else), each as its JSON text.
void DeclaredRules(const Validator& v, const json& schema, std::vector<json>& out) {
  const json& s = v.Resolve(schema);
  if (!s.is_object()) return;
  if (s.contains("x-rules"))
    for (const json& r : s["x-rules"]) out.push_back(r);
  for (const char* k : {"allOf", "anyOf", "oneOf"})
    if (s.contains(k))
      for (const auto& b : s[k]) DeclaredRules(v, b, out);
  for (const char* k : {"then", "else"})
    if (s.contains(k)) DeclaredRules(v, s[k], out);
}

// The declared rule that excuses the parser's refusal of a case the schema accepts: one of an
// object on the case's path (the root or an enclosing object) that names the path's next field,
// or one of the changed value itself when it is an object, with a piece of the parser's message.
// Its JSON text, or empty when none does.
std::string ExcusingRule(const Validator& v, const json& schema, const json& study, const std::string& path,
                         const std::string& parser_error) {
  std::vector<std::string> fields;  // the path's segments
  for (size_t at = 0; at < path.size();) {
    const size_t next = path.find('/', at + 1);
    fields.push_back(path.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1));
    at = next == std::string::npos ? path.size() : next;
  }
  std::string prefix;
  for (size_t i = 0; i <= fields.size(); ++i) {
    const json::json_pointer ptr(prefix);
    if (!study.contains(ptr)) break;
    if (study.at(ptr).is_object()) {
      std::vector<json> rules;
      DeclaredRules(v, SchemaAt(v, schema, study, prefix), rules);
      for (const json& r : rules) {
        bool names = i == fields.size();
        for (const json& f : r["fields"]) names = names || f == fields[i];
        if (names && parser_error.find(r["message"].get<std::string>()) != std::string::npos) return r.dump();
      }
    }
    if (i < fields.size()) prefix += "/" + fields[i];
  }
  return "";
}

// Every rule declared anywhere in a kind's schema (its JSON text).
std::set<std::string> AllDeclaredRules(const json& s) {
  std::set<std::string> out;
  if (s.is_object() && s.contains("x-rules"))
    for (const json& r : s["x-rules"]) out.insert(r.dump());
  if (s.is_structured())
    for (const auto& x : s) {
      const std::set<std::string> inner = AllDeclaredRules(x);
      out.insert(inner.begin(), inner.end());
    }
  return out;
}

TEST(SchemaParserAgreement, EveryKindsParserAcceptsExactlyWhatItsSchemaAccepts) {
  const fs::path examples = fs::path(CAMOPT_SOURCE_DIR) / "studies" / "examples";
  std::map<std::string, std::vector<fs::path>> by_kind;
  for (const auto& e : fs::directory_iterator(examples))
    if (e.path().extension() == ".json") {
      std::ifstream in(e.path());
      const json j = json::parse(in);
      if (j.is_object() && j.contains("study")) by_kind[j["study"].get<std::string>()].push_back(e.path());
    }
  std::set<std::string> disagreements;
  std::set<std::string> used;                            // the declared rules some refusal met
  std::map<std::string, std::set<std::string>> declared;  // every declared rule and the kinds declaring it
  size_t cases = 0;
  for (const auto& kind : studies::StudyKinds()) {
    SCOPED_TRACE(kind);
    ASSERT_FALSE(by_kind[kind].empty()) << kind << ": no example in studies/examples/";
    const json schema = json::parse(studies::StudySchema(kind));
    const Validator validator(schema);
    for (const std::string& rule : AllDeclaredRules(schema)) declared[rule].insert(kind);
    std::sort(by_kind[kind].begin(), by_kind[kind].end());
    for (const auto& file : by_kind[kind]) {
      std::ifstream in(file);
      const json example = json::parse(in);
      std::vector<Case> generated;
      const std::string label = kind + " " + file.filename().string();
      generated.push_back({label + ": the example as it is", example});
      json described = example;
      described["description"] = "a description";
      generated.push_back({label + ": /description = \"a description\" (every kind)", described});
      Generator(validator, label, generated).Walk(example, "", schema);
      for (const auto& c : generated) {
        ++cases;
        const std::string schema_error = validator.Check(c.study);
        std::string parser_error;
        bool parser_ok = true;
        try {
          studies::CheckStudy(c.study, file.string());
        } catch (const studies::StudyError& e) {
          parser_ok = false;
          parser_error = e.what();
          parser_error = parser_error.substr(parser_error.find(": ") + 2);
        } catch (const std::exception& e) {
          parser_ok = false;
          parser_error = std::string("NOT A StudyError (exit 1): ") + e.what();
        }
        // A field the parser knows (its "known: …" list) that the schema does not declare.
        const auto known = parser_error.find("unknown field (known: ");
        const std::string at = c.what.find("/zz_unknown_field") == std::string::npos ? "" :
            c.what.substr(c.what.find(": ") + 2, c.what.find("/zz_unknown_field") - c.what.find(": ") - 2);
        if (known != std::string::npos && !at.empty() &&
            parser_error.rfind((at == "/" ? "" : at) + "/zz_unknown_field: unknown field", 0) == 0) {
          std::map<std::string, json> props;
          Generator(validator, label, generated).Properties(
              SchemaAt(validator, schema, c.study, at == "/" ? "" : at), props);
          std::string list = parser_error.substr(known + 22);
          list = list.substr(0, list.find(')'));
          std::istringstream names(list);
          for (std::string n; std::getline(names, n, ',');) {
            n.erase(0, n.find_first_not_of(' '));
            if (props.count(n)) continue;
            // Known to the parser only to refuse it with a better message is fine; accepted with
            // some value is a field the schema should declare.
            for (const json& x : {json(1), json(0.5), json("x"), json(true), json::array({1, 2})}) {
              json probe = c.study;
              json& parent = at == "/" ? probe : probe[json::json_pointer(at)];
              parent.erase("zz_unknown_field");
              parent[n] = x;
              bool accepted = true;
              try {
                studies::CheckStudy(probe, file.string());
              } catch (const std::exception&) {
                accepted = false;
              }
              if (accepted) {
                disagreements.insert(kind + ": " + (at == "/" ? "" : at) + "/" + n + " = " + x.dump() +
                                     "  [schema does not declare it; parser accepts]");
                break;
              }
            }
          }
        }
        const bool schema_ok = schema_error.empty();
        const bool bad_exception = parser_error.rfind("NOT A StudyError", 0) == 0;
        if (schema_ok == parser_ok && !bad_exception) continue;
        // The example file name is left out so that a disagreement found from several examples
        // of a kind is listed once.
        const std::string what = c.what.substr(c.what.find(": ") + 2);
        // A rule between fields only ever makes the parser stricter. Every rule JSON Schema can
        // state (if/then on another field, a tagged union) is in the schema; the others are
        // declared in it (x-rules): nothing else is excused.
        if (schema_ok && !parser_ok && !bad_exception) {
          // Matched on the path of the change and on the path the parser names.
          std::string rule = ExcusingRule(validator, schema, c.study, what.substr(0, what.find(' ')), parser_error);
          if (rule.empty() && parser_error.rfind('/', 0) == 0)
            rule = ExcusingRule(validator, schema, c.study, parser_error.substr(0, parser_error.find(": ")),
                                parser_error);
          if (!rule.empty()) {
            used.insert(rule);
            continue;
          }
        }
        disagreements.insert(kind + ": " + what + "  [schema " +
                             (schema_ok ? "accepts" : "refuses: " + schema_error) + "; parser " +
                             (parser_ok ? "accepts" : "refuses: " + parser_error) + "]");
      }
    }
  }
  // Every declared rule is met by a generated study that the parser refuses with its message: a
  // rule the parser does not check, or whose message changed, fails. A rule declared by a struct
  // that several kinds share (the motion's, checked by ParseMotionProgram for each) is met in one
  // of them at least: the generated studies of a kind whose examples have no B-spline or
  // polynomial segment cannot break those segments' rules.
  for (const auto& [rule, kinds] : declared) {
    std::string names;
    for (const std::string& k : kinds) names += (names.empty() ? "" : ", ") + k;
    EXPECT_TRUE(used.count(rule)) << "a declared rule between fields that no generated study breaks (" << names
                                  << "): " << rule;
  }
  std::ostringstream all;
  for (const auto& d : disagreements) all << "\n  " << d;
  EXPECT_TRUE(disagreements.empty()) << disagreements.size() << " disagreements in " << cases
                                     << " generated studies:" << all.str();
  EXPECT_GT(cases, 1000u);
}

// ---------------------------------------------------------------------------------------------

// The examples of a kind in studies/examples/, sorted.
std::vector<fs::path> ExamplesOf(const std::string& kind) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(fs::path(CAMOPT_SOURCE_DIR) / "studies" / "examples"))
    if (e.path().extension() == ".json") {
      std::ifstream in(e.path());
      const json j = json::parse(in);
      if (j.is_object() && j.value("study", "") == kind) out.push_back(e.path());
    }
  std::sort(out.begin(), out.end());
  return out;
}

// Every property of a schema (and of its nested objects and array items), by JSON path.
void Properties(const json& schema, const std::string& path, std::vector<std::pair<std::string, json>>& out) {
  if (schema.contains("properties"))
    for (auto it = schema["properties"].begin(); it != schema["properties"].end(); ++it) {
      out.push_back({path + "/" + it.key(), it.value()});
      Properties(it.value(), path + "/" + it.key(), out);
    }
  if (schema.contains("items")) Properties(schema["items"], path + "/items", out);
}

TEST(SchemaParserAgreement, DeclaredKindsHaveOneSchemaEmittedFromTheDeclaration) {
  for (const std::string& kind : studies::StudyKinds()) {
    SCOPED_TRACE(kind);
    const std::string* emitted = studies::DeclaredSchema(kind);
    ASSERT_NE(emitted, nullptr) << "not registered (CAMOPT_REGISTER_KIND)";
    EXPECT_EQ(studies::StudySchema(kind), *emitted);
    EXPECT_FALSE(fs::exists(fs::path(CAMOPT_SOURCE_DIR) / "studies" / "schema" / (kind + ".schema.json")))
        << "a hand-kept schema beside the declaration";
    const auto dir = TempDir("schema-" + kind);
    const auto cli = RunCamopt("schema " + kind + " > " + (dir / "s.json").string());
    EXPECT_EQ(cli.exit_code, 0);
    EXPECT_EQ(ReadFile(dir / "s.json"), *emitted);
    // A description for every field (its unit in it where the field has one).
    std::vector<std::pair<std::string, json>> props;
    Properties(json::parse(*emitted), "", props);
    EXPECT_GT(props.size(), 10u);
    for (const auto& [path, p] : props)
      EXPECT_TRUE(p.contains("description") || p.contains("const")) << path << ": no description";
  }
}

// docs/studies.md shows each declared kind's fields as `camopt schema KIND --table` prints them.
TEST(SchemaParserAgreement, DeclaredKindsFieldTablesInTheDocsAreTheEmittedOnes) {
  const std::string docs = ReadFile(fs::path(CAMOPT_SOURCE_DIR) / "docs" / "studies.md");
  for (const std::string& kind : studies::StudyKinds()) {
    const std::string table = studies::SchemaFieldTable(nlohmann::ordered_json::parse(studies::StudySchema(kind)));
    EXPECT_NE(docs.find("## " + kind + "\n"), std::string::npos) << kind;
    EXPECT_NE(docs.find(table), std::string::npos)
        << kind << ": docs/studies.md does not have the table of `camopt schema " << kind << " --table`:\n" << table;
  }
  // And the keys of each declared result.json (`camopt schema KIND --result --table`).
  for (const std::string& kind : studies::StudyKinds()) {
    const std::string table =
        studies::SchemaFieldTable(nlohmann::ordered_json::parse(studies::StudyResultSchema(kind)), true);
    EXPECT_NE(docs.find("<!-- camopt schema " + kind + " --result --table -->\n" + table), std::string::npos)
        << kind << ": docs/studies.md does not have the table of `camopt schema " << kind << " --result --table`:\n"
        << table;
  }
}

// Every property with a schema `default`, added where the study does not give it (inside objects
// the study gives, and in optional objects it leaves out, which are added whole).
int FillDefaults(const Validator& v, const json& schema, json& value) {
  const json& s = v.Resolve(schema);
  if (!value.is_object() || !s.contains("properties")) return 0;
  int filled = 0;
  for (auto it = s["properties"].begin(); it != s["properties"].end(); ++it) {
    const json& p = v.Resolve(it.value());
    if (!value.contains(it.key())) {
      if (p.contains("default")) {
        value[it.key()] = p["default"];
        ++filled;
      } else if (p.value("type", json()) == "object" && !p.contains("required") &&
                 !(s.contains("dependentRequired") && s["dependentRequired"].contains(it.key()))) {
        // (an object with required fields cannot be made of defaults alone, nor one that needs
        // another field the study may not have: lcr_analysis's "surfaces" needs "lubricant")
        // (nor one the object's rules forbid here: disc_cam's "tolerances" without a roller)
        json o = json::object();
        if (FillDefaults(v, p, o) > 0) {
          value[it.key()] = o;
          if (v.CheckAgainst(s, value).empty()) filled += FillDefaults(v, p, o);
          else value.erase(it.key());
        }
      }
    } else {
      filled += FillDefaults(v, p, value[it.key()]);
    }
  }
  return filled;
}

// Every property with a schema `default` removed (recursively).
void StripDefaults(const Validator& v, const json& schema, json& value) {
  const json& s = v.Resolve(schema);
  if (!value.is_object() || !s.contains("properties")) return;
  for (auto it = s["properties"].begin(); it != s["properties"].end(); ++it) {
    if (!value.contains(it.key())) continue;
    if (v.Resolve(it.value()).contains("default")) value.erase(it.key());
    else StripDefaults(v, it.value(), value[it.key()]);
  }
}

// `a` with only the members of objects that `b` has (recursively).
json Restrict(const json& a, const json& b) {
  if (!a.is_object() || !b.is_object()) return a;
  json out = json::object();
  for (auto it = b.begin(); it != b.end(); ++it)
    if (a.contains(it.key())) out[it.key()] = Restrict(a[it.key()], it.value());
  return out;
}

// The defaults the schema states are the values the parser uses: each example without the fields
// that have a default, and the same with every default written out, are accepted and read (the
// declaration's echo: every field as the kind uses it) to the same values.
TEST(SchemaParserAgreement, DeclaredDefaultsAreTheParsersDefaults) {
  for (const std::string& kind : studies::StudyKinds()) {
    const json schema = json::parse(studies::StudySchema(kind));
    const Validator validator(schema);
    ASSERT_NE(studies::FindKind(kind), nullptr) << kind;
    const studies::DeclaredEcho echo = studies::FindKind(kind)->echo;
    const auto examples = ExamplesOf(kind);
    ASSERT_FALSE(examples.empty()) << kind;
    for (const auto& file : examples) {
      SCOPED_TRACE(file.filename().string());
      std::ifstream in(file);
      const json example = json::parse(in);
      json bare = example;
      StripDefaults(validator, schema, bare);
      json filled = bare;
      const int n = FillDefaults(validator, schema, filled);
      EXPECT_GT(n, 0);
      EXPECT_EQ(validator.Check(filled), "");
      EXPECT_NO_THROW(studies::CheckStudy(bare, file.string()));
      EXPECT_NO_THROW(studies::CheckStudy(filled, file.string()));
      bare = json::parse(echo(bare, file.string()).dump());
      const json full = json::parse(echo(filled, file.string()).dump());
      // Fields left optional (absent: a meaning of their own) appear in the full echo only.
      EXPECT_EQ(Restrict(full, bare), bare);
    }
  }
}

// Every generated study the schema refuses is refused by the runner with a StudyError (the
// command line's exit code 2) of one line naming the file and the JSON path, before any work:
// checked in process (RunStudy, as `camopt run` calls it), and through the command line for a
// sample (the first refused case of each kind: exit 2, the line on stderr).
TEST(SchemaParserAgreement, DeclaredKindsRefuseWhatTheSchemaRefusesWithExit2) {
  int refused = 0, spawned = 0;
  for (const std::string& kind : studies::StudyKinds()) {
    const json schema = json::parse(studies::StudySchema(kind));
    const Validator validator(schema);
    const fs::path example_file = ExamplesOf(kind).front();
    std::ifstream in(example_file);
    const json example = json::parse(in);
    std::vector<Case> generated;
    Generator(validator, kind, generated).Walk(example, "", schema);
    const auto dir = TempDir("declared-cli-" + kind);
    const fs::path file = dir / "study.json";
    bool sampled = false;
    for (const Case& c : generated) {
      if (validator.Check(c.study).empty()) continue;
      studies::RunContext ctx;
      ctx.study_file = file.string();
      ctx.quiet = true;
      std::string message;
      try {
        studies::RunStudy(c.study, ctx);
        ADD_FAILURE() << c.what << ": ran, expected a refusal";
      } catch (const studies::StudyError& e) {
        message = e.what();
      }
      if (!message.empty()) {
        EXPECT_EQ(message.rfind(file.string() + ": /", 0), 0u) << c.what << "\n" << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << c.what << "\n" << message;
      }
      ++refused;
      if (sampled) continue;
      sampled = true;
      ++spawned;
      WriteFile(file, c.study.dump());
      const auto r = RunCamopt("run " + file.string() + " --quiet --out " + (dir / "out").string());
      EXPECT_EQ(r.exit_code, 2) << c.what << "\n" << r.stderr_text;
      EXPECT_EQ(r.stderr_text, "camopt: error: " + message + "\n") << c.what;
    }
  }
  EXPECT_GT(refused, 50);
  EXPECT_EQ(spawned, int(studies::StudyKinds().size()));
}

}  // namespace schema_parser_agreement_test
}  // namespace camopt
