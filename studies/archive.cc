#include "studies/archive.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <map>
#include <mutex>

namespace camopt::studies {

namespace archive_detail {

std::string NumberText(double x) {
  std::ostringstream os;
  os << x;
  return os.str();
}

std::string BoundText(const Field::Bound& b, bool integer) {
  if (!b.expected.empty()) return b.expected;
  const std::string a = integer ? "a whole number " : "a number ";
  const auto num = [&](double x) {
    return integer ? std::to_string(static_cast<long long>(x)) : NumberText(x);
  };
  if (b.lo && b.hi) return a + "in [" + num(*b.lo) + ", " + num(*b.hi) + "]";
  if (b.lo) return a + (b.lo_open ? "> " : ">= ") + num(*b.lo);
  if (b.hi) return a + (b.hi_open ? "< " : "<= ") + num(*b.hi);
  return integer ? "a whole number" : "a number";
}

nlohmann::ordered_json Described(const Field& f) {
  nlohmann::ordered_json s = nlohmann::ordered_json::object();
  const std::string d = f.desc + (f.unit.empty() ? "" : (f.desc.empty() ? "[" : " [") + f.unit + "]");
  if (!d.empty()) s["description"] = d;
  return s;
}

std::string OneOfText(const std::vector<std::string>& values) {
  if (values.size() == 1) return "\"" + values[0] + "\"";
  if (values.size() == 2) return "\"" + values[0] + "\" or \"" + values[1] + "\"";
  std::string text = "one of ";
  for (size_t i = 0; i < values.size(); ++i) text += (i ? ", \"" : "\"") + values[i] + "\"";
  return text;
}

bool IsJsonType(const nlohmann::json& j, const std::string& type) {
  if (type == "object") return j.is_object();
  if (type == "array") return j.is_array();
  if (type == "boolean") return j.is_boolean();
  if (type == "integer" || type == "number") return j.is_number();
  return type == "string" && j.is_string();
}

std::string JsonTypesText(const std::vector<std::string>& types) {
  std::vector<std::string> words;
  for (const std::string& t : types) {
    if (t == "boolean") {
      words.push_back("true");
      words.push_back("false");
    } else {
      words.push_back((t == "object" || t == "array" || t == "integer" ? "an " : "a ") + t);
    }
  }
  std::string text;
  for (size_t i = 0; i < words.size(); ++i)
    text += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
  return text;
}

}  // namespace archive_detail

namespace {

bool Passes(const Field::Bound& b, double v) {
  if (b.lo && !(b.lo_open ? v > *b.lo : v >= *b.lo)) return false;
  if (b.hi && !(b.hi_open ? v < *b.hi : v <= *b.hi)) return false;
  return true;
}

// Node::Integer's largest whole number.
constexpr double kLargestInteger = 1e9;

}  // namespace

namespace {

// What would fit a number that breaks a field's bounds (or, for a whole-number field, is not
// whole): the nearest value every bound holds, a whole number rounded; empty when it lands on an
// open bound of a real field (no nearest value there) or the bounds leave nothing.
std::string WouldFit(double v, const Field& f, bool integer) {
  if (!std::isfinite(v)) return "";
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
  for (const Field::Bound& b : f.bounds) {
    if (b.lo && (*b.lo > lo || (*b.lo == lo && b.lo_open))) lo = *b.lo, lo_open = b.lo_open;
    if (b.hi && (*b.hi < hi || (*b.hi == hi && b.hi_open))) hi = *b.hi, hi_open = b.hi_open;
  }
  if (integer) {
    lo = lo_open ? std::floor(lo) + 1 : std::ceil(lo);
    hi = std::min(hi_open ? std::ceil(hi) - 1 : std::floor(hi), kLargestInteger);
    lo_open = hi_open = false;
  }
  if (!(lo <= hi)) return "";
  const double x = std::clamp(integer ? std::round(v) : v, lo, hi);
  if ((x == lo && lo_open) || (x == hi && hi_open)) return "";
  if (std::floor(x) == x && std::abs(x) < 1e15) return std::to_string(static_cast<long long>(x));
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", x);
  return text;
}

}  // namespace

double JsonReader::ReadNumber(const Node& n, const nlohmann::json& j, const Field& f, bool integer) {
  using archive_detail::BoundText;
  const std::string first = f.bounds.empty() ? BoundText({}, integer) : BoundText(f.bounds[0], integer);
  if (!j.is_number()) n.Fail(first);
  const double v = j.get<double>();
  if (integer && (!(std::floor(v) == v) || v > kLargestInteger)) n.Fail(first, WouldFit(v, f, integer));
  for (const Field::Bound& b : f.bounds)
    if (!Passes(b, v)) n.Fail(BoundText(b, integer), WouldFit(v, f, integer));
  if (!std::isfinite(v)) n.Fail("a finite number");
  return v;
}

std::string JsonReader::ReadString(const Node& n, const Field& f) {
  const std::string s = n.String();
  if (f.constant && s != *f.constant) n.Fail("\"" + *f.constant + "\"");
  if (!f.one_of.empty() && std::find(f.one_of.begin(), f.one_of.end(), s) == f.one_of.end())
    n.Fail(f.one_of_expected.empty() ? archive_detail::OneOfText(f.one_of) : f.one_of_expected);
  return s;
}

void SchemaEmitter::NumberKeywords(const Field& f, bool integer, nlohmann::ordered_json& s) {
  // The tightest of the bounds on each side (an open bound wins a tie).
  std::optional<double> lo, hi;
  bool lo_open = false, hi_open = false;
  for (const Field::Bound& b : f.bounds) {
    if (b.lo && (!lo || *b.lo > *lo || (*b.lo == *lo && b.lo_open))) lo = b.lo, lo_open = b.lo_open;
    if (b.hi && (!hi || *b.hi < *hi || (*b.hi == *hi && b.hi_open))) hi = b.hi, hi_open = b.hi_open;
  }
  if (integer && (!hi || *hi > kLargestInteger)) hi = kLargestInteger, hi_open = false;
  const auto value = [&](double x) {
    // Whole bounds as whole numbers ("minimum": 0, not 0.0), which JSON Schema reads alike.
    return std::floor(x) == x && std::abs(x) < 1e15 ? nlohmann::ordered_json(static_cast<long long>(x))
                                         : nlohmann::ordered_json(x);
  };
  if (lo) s[lo_open ? "exclusiveMinimum" : "minimum"] = value(*lo);
  if (hi) s[hi_open ? "exclusiveMaximum" : "maximum"] = value(*hi);
}

namespace {

std::string Code(const nlohmann::ordered_json& v) { return "`" + v.dump() + "`"; }

// What a field's schema accepts, in words: "number > 0", "whole number in [36, 200000]", …
std::string Accepts(const nlohmann::ordered_json& s) {
  using archive_detail::NumberText;
  if (s.contains("const")) return Code(s["const"]);
  if (s.contains("enum")) {
    std::string text;
    for (size_t i = 0; i < s["enum"].size(); ++i)
      text += (i == 0 ? "" : i + 1 == s["enum"].size() ? " or " : ", ") + Code(s["enum"][i]);
    return text;
  }
  std::string type;
  const nlohmann::ordered_json t = s.value("type", nlohmann::ordered_json());
  const auto word = [](const std::string& name) {
    return name == "integer" ? std::string("whole number") : name == "boolean" ? std::string("true or false") : name;
  };
  if (t.is_string()) type = word(t.get<std::string>());
  for (size_t i = 0; t.is_array() && i < t.size(); ++i) type += (i ? " or " : "") + word(t[i].get<std::string>());
  if (t == "array" && s.contains("items")) {
    const std::string item = Accepts(s["items"]);
    type = "array of " + (s["items"].contains("properties") ? std::string("objects") : item);
    if (s.contains("minItems") && s.contains("maxItems") && s["minItems"] == s["maxItems"])
      type = "array of " + s["minItems"].dump() + " × " + item;
    else if (s.contains("minItems"))
      type += ", at least " + s["minItems"].dump();
  }
  const bool lo = s.contains("minimum") || s.contains("exclusiveMinimum");
  // A whole number's cap of 1e9 (every one has it) is left out of the words.
  const bool hi = (s.contains("maximum") && !(t == "integer" && s["maximum"] == kLargestInteger)) ||
                  s.contains("exclusiveMaximum");
  const auto num = [&](const char* k) { return NumberText(s[k].get<double>()); };
  if (lo && hi) {
    type += " in " + std::string(s.contains("minimum") ? "[" + num("minimum") : "(" + num("exclusiveMinimum")) +
            ", " + (s.contains("maximum") ? num("maximum") + "]" : num("exclusiveMaximum") + ")");
  } else if (lo) {
    type += s.contains("minimum") ? " >= " + num("minimum") : " > " + num("exclusiveMinimum");
  } else if (hi) {
    type += s.contains("maximum") ? " <= " + num("maximum") : " < " + num("exclusiveMaximum");
  }
  return type;
}

// A oneOf's alternatives as one schema for the table: the union of their types and of their keys
// (a key's schemas merged the same way), a key required only where every object alternative
// requires it, the first description found.
nlohmann::ordered_json MergedAlternatives(const std::vector<nlohmann::ordered_json>& alternatives) {
  nlohmann::ordered_json m = nlohmann::ordered_json::object();
  std::vector<std::string> types;
  const auto add_type = [&](const std::string& t) {
    if (std::find(types.begin(), types.end(), t) == types.end()) types.push_back(t);
  };
  std::vector<std::string> keys;
  std::vector<std::string> required;
  bool first_object = true;
  for (const nlohmann::ordered_json& a : alternatives) {
    if (a.contains("type")) {
      if (a["type"].is_string()) add_type(a["type"].get<std::string>());
      else for (const auto& t : a["type"]) add_type(t.get<std::string>());
    }
    if (!m.contains("description") && a.contains("description")) m["description"] = a["description"];
    if (!a.contains("properties")) continue;
    for (auto it = a["properties"].begin(); it != a["properties"].end(); ++it)
      if (std::find(keys.begin(), keys.end(), it.key()) == keys.end()) keys.push_back(it.key());
    std::vector<std::string> req;
    for (const auto& r : a.value("required", nlohmann::ordered_json::array())) req.push_back(r.get<std::string>());
    if (first_object) required = req;
    else
      required.erase(std::remove_if(required.begin(), required.end(),
                                    [&](const std::string& k) { return std::find(req.begin(), req.end(), k) == req.end(); }),
                     required.end());
    first_object = false;
  }
  if (types.size() == 1) m["type"] = types.front();
  else if (!types.empty()) m["type"] = types;
  std::vector<nlohmann::ordered_json> items;
  for (const nlohmann::ordered_json& a : alternatives)
    if (a.contains("items")) items.push_back(a["items"]);
  if (!items.empty()) m["items"] = items.size() == 1 ? items.front() : MergedAlternatives(items);
  for (const nlohmann::ordered_json& a : alternatives)  // a map's values (the first map alternative's)
    if (a.contains("additionalProperties") && a["additionalProperties"].is_object()) {
      m["additionalProperties"] = a["additionalProperties"];
      break;
    }
  if (keys.empty()) return m;
  m["properties"] = nlohmann::ordered_json::object();
  for (const std::string& k : keys) {
    std::vector<nlohmann::ordered_json> of_key;
    for (const nlohmann::ordered_json& a : alternatives)
      if (a.contains("properties") && a["properties"].contains(k)) of_key.push_back(a["properties"][k]);
    const bool same = std::all_of(of_key.begin(), of_key.end(), [&](const auto& x) { return x == of_key.front(); });
    m["properties"][k] = same ? of_key.front() : MergedAlternatives(of_key);
  }
  m["required"] = required;
  return m;
}

// A member's schema for the table: a oneOf (a block or its error, a block or null, two shapes)
// merged into one (MergedAlternatives), its own description kept.
nlohmann::ordered_json TableSchema(const nlohmann::ordered_json& p) {
  if (!p.contains("oneOf")) return p;
  std::vector<nlohmann::ordered_json> alternatives(p["oneOf"].begin(), p["oneOf"].end());
  nlohmann::ordered_json m = MergedAlternatives(alternatives);
  if (p.contains("description")) m["description"] = p["description"];
  return m;
}

void TableRows(const nlohmann::ordered_json& schema, const std::string& prefix, bool result, std::string& out) {
  if (!schema.contains("properties")) return;
  const nlohmann::ordered_json required = schema.value("required", nlohmann::ordered_json::array());
  for (auto it = schema["properties"].begin(); it != schema["properties"].end(); ++it) {
    const nlohmann::ordered_json p = TableSchema(it.value());
    const std::string path = prefix + it.key();
    std::string accepts = Accepts(p);
    const bool always = std::find(required.begin(), required.end(), it.key()) != required.end();
    if (result) accepts += always ? ", always" : ", not always";
    else if (always) accepts += ", required";
    else if (p.contains("default")) accepts += ", optional (" + p["default"].dump() + ")";
    else if (!p.contains("const")) accepts += ", optional";
    std::string meaning = p.value("description", "");
    for (char& c : meaning)
      if (c == '|') c = '/';
    out += "| `" + path + "` | " + accepts + " | " + meaning + " |\n";
    TableRows(p, path + ".", result, out);
    if (p.contains("items")) TableRows(p["items"], path + "[i].", result, out);
    // A map's entries (a declared std::map<std::string, T>): its value's rows under `<name>`.
    if (p.contains("additionalProperties") && p["additionalProperties"].is_object())
      TableRows(p["additionalProperties"], path + ".<name>.", result, out);
  }
}

// The rules between fields (CrossFieldRule, "x-rules") of the object `schema` and of those inside
// it, one list item each: its fields with their paths, then the rule.
void RuleRows(const nlohmann::ordered_json& schema, const std::string& prefix, std::string& out) {
  if (!schema.is_object()) return;
  if (schema.contains("x-rules"))
    for (const auto& r : schema["x-rules"]) {
      std::string fields;
      for (size_t i = 0; i < r["fields"].size(); ++i)
        fields += (i ? ", `" : "`") + prefix + r["fields"][i].get<std::string>() + "`";
      out += "- " + fields + ": " + r["rule"].get<std::string>() + "\n";
    }
  if (schema.contains("properties"))
    for (auto it = schema["properties"].begin(); it != schema["properties"].end(); ++it) {
      RuleRows(it.value(), prefix + it.key() + ".", out);
      if (it.value().contains("items")) RuleRows(it.value()["items"], prefix + it.key() + "[i].", out);
    }
}

}  // namespace

std::string SchemaFieldTable(const nlohmann::ordered_json& schema, bool result) {
  std::string out = result ? "| key | value | meaning |\n|---|---|---|\n" : "| field | accepts | meaning |\n|---|---|---|\n";
  TableRows(schema, "", result, out);
  std::string rules;
  RuleRows(schema, "", rules);
  if (!rules.empty())
    out += "\nRules between fields (the schema's \"x-rules\"; `camopt run` refuses a study that breaks one):\n\n" +
           rules;
  return out;
}

}  // namespace camopt::studies
