// One declaration per study kind: a struct names each of its fields once, with its unit, default,
// bounds and description, in a `Serialize` member that archives walk (the pattern of Drake's
// `common/yaml/yaml_io.h` and `common/name_value.h`; OpenMDAO's `options.declare(default, types,
// lower, upper, desc)` for what a field carries):
//
//   struct Load {
//     double turret_torque_Nm = 0.0;
//     double turret_inertia_kgm2 = 0.01;
//     template <typename Archive>
//     void Serialize(Archive* a) {
//       a->Visit("turret_torque_Nm", &turret_torque_Nm, Field().Desc("load on the turret").Unit("N·m"));
//       a->Visit("turret_inertia_kgm2", &turret_inertia_kgm2, Field().Positive().Unit("kg·m²"));
//     }
//   };
//
// Three archives walk a declaration:
//   - Read (JsonReader): the study file into the struct, with the messages of `Node` (file, JSON
//     path, expected, found) and its refusal of unknown fields (Node::CheckKnownFields), checked
//     before any field of the object is read;
//   - EmitSchema (SchemaEmitter): the JSON Schema (draft 2020-12) of the struct, a `description`
//     and a `default` for every field that has one, the bounds, enums, `required`,
//     `"additionalProperties": false`;
//   - WriteJson (JsonWriter): the struct back to JSON (an echo of the study as read, defaults
//     filled in).
// Defaults are the struct's initialisers; a field marked Required() has none. A std::optional
// member is absent when the file does not give it (Field::Default documents what absence means).
// Checks that span fields stay code, one function per kind, run after Read. Those JSON Schema can
// state (if/then, oneOf, dependentRequired) a struct gives in its schema with a static
// `nlohmann::ordered_json SchemaRules()`, whose keywords the emitter adds to the object's schema;
// those it cannot (an ordered range, a sum, a fit of the geometry) it declares with a static
// `std::vector<CrossFieldRule> CrossFieldRules()`, which the schema carries as the annotation
// "x-rules" (docs/studies.md "Rules between fields").
//
// Supported member types: double, int, bool, std::string (with OneOf: an enum; with Const: a
// constant), a struct with its own Serialize, std::optional of any of these, std::vector of any of
// these, std::array of numbers, std::variant of alternatives with distinct JSON types (BoolOr<T>:
// `true`, `false` or the object of a declared T), and nlohmann::json for a value read by shared
// code (its schema given with Field::Schema).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "studies/input.h"

namespace camopt::studies {

/// A field that is `true`, `false` or the object of a declared T's settings (geometry_files,
/// analysis.monte_carlo): `true` means T's defaults. Read by JSON type; its schema is T's object
/// schema with `"type": ["boolean", "object"]`; written as the alternative it holds.
template <typename T>
using BoolOr = std::variant<bool, T>;

/// The settings a BoolOr field asks for: none when it is `false`, T's defaults when `true`.
template <typename T>
std::optional<T> Enabled(const BoolOr<T>& v) {
  if (const T* settings = std::get_if<T>(&v)) return *settings;
  if (std::get<bool>(v)) return T{};
  return std::nullopt;
}

/// A number of a result that may be ±inf or NaN (the stress of an undercut contact, an estimate
/// not made): itself, or null in JSON.
inline nlohmann::json NumberOrNull(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

/// A rule between fields of one object that JSON Schema cannot state (lo < hi, rollers = lobes + 1,
/// shares that sum to 1, a bolt circle that fits the part): the object's fields it spans, the rule
/// in words, and a piece of the message the parse refuses a study that breaks it with. The
/// parse (the kind's checks, or the model's CheckDesign) enforces it; the declaration puts it in
/// the schema ("x-rules": [{"fields", "rule", "message"}], an annotation validators ignore) and
/// in docs/studies.md, and the schema/parser agreement test excuses a refusal the schema does not
/// state only when a declared rule of an enclosing object names the field and the message.
struct CrossFieldRule {
  std::vector<std::string> fields;
  std::string rule;
  std::string message;
};

/// The members of a declared result that decide the run's status (RunStudy, studies/status.h), each
/// marked on its field with Field::Decides: a `converged` that is false gives "not_converged", a
/// `feasible` that is false "infeasible", and the `warning` is the reason given with either.
enum class RunFact { kNone, kConverged, kFeasible, kWarning };

/// What a declared field accepts and how it is documented, besides its C++ type. Built with
/// chained calls: `Field().Required().Positive().Unit("mm").Desc("…")`.
///
/// Numbers are checked in the order their bounds were added; the first bound's `expected` text is
/// also the message for a value of the wrong type. Without a text of its own a bound says what
/// Node says: "a number > 0", "a number >= 0", "a number in [lo, hi]", "a whole number >= n",
/// "a whole number <= n". An integer field needs a lower bound (AtLeast) first, as Node::Integer,
/// and is at most 1e9.
class Field {
 public:
  /// One check of a number: lo < x (lo_open) or lo <= x, and x < hi (hi_open) or x <= hi.
  struct Bound {
    std::optional<double> lo, hi;
    bool lo_open = false, hi_open = false;
    std::string expected;  ///< the message; empty: the standard text for the bound
  };

  /// What the field is, for the schema's `description` (a sentence fragment; the unit is added).
  Field& Desc(std::string text) { desc = std::move(text); return *this; }
  /// The unit of the number (also in the field's name): "[UNIT]" ends the description.
  Field& Unit(std::string u) { unit = std::move(u); return *this; }
  /// The file must give the field (no default; "missing required field").
  Field& Required() { required = true; return *this; }
  /// x > 0 ("a number > 0").
  Field& Positive(std::string expected = "") { return Above(0.0, std::move(expected)); }
  /// x >= 0 ("a number >= 0").
  Field& NonNegative(std::string expected = "") { return AtLeast(0.0, std::move(expected)); }
  /// x > lo.
  Field& Above(double lo, std::string expected = "") {
    bounds.push_back({lo, std::nullopt, true, false, std::move(expected)});
    return *this;
  }
  /// x >= lo (for an integer: "a whole number >= lo", and whole).
  Field& AtLeast(double lo, std::string expected = "") {
    bounds.push_back({lo, std::nullopt, false, false, std::move(expected)});
    return *this;
  }
  /// x < hi.
  Field& Below(double hi, std::string expected = "") {
    bounds.push_back({std::nullopt, hi, false, true, std::move(expected)});
    return *this;
  }
  /// x <= hi.
  Field& AtMost(double hi, std::string expected = "") {
    bounds.push_back({std::nullopt, hi, false, false, std::move(expected)});
    return *this;
  }
  /// lo <= x <= hi, one check ("a number in [lo, hi]").
  Field& In(double lo, double hi, std::string expected = "") {
    bounds.push_back({lo, hi, false, false, std::move(expected)});
    return *this;
  }
  /// A string from a list (the schema's `enum`); the message names them, or is `expected`.
  Field& OneOf(std::vector<std::string> values, std::string expected = "") {
    one_of = std::move(values);
    one_of_expected = std::move(expected);
    return *this;
  }
  /// A string that must be `value` (the schema's `const`; the root's "study").
  Field& Const(std::string value) { constant = std::move(value); return *this; }
  /// An array of at least n items.
  Field& MinItems(size_t n, std::string expected = "") {
    min_items = n;
    min_items_expected = std::move(expected);
    return *this;
  }
  /// The message for a value of the wrong shape (a fixed-size array: "an array of N numbers").
  Field& Expect(std::string text) { shape_expected = std::move(text); return *this; }
  /// A fixed-size array whose items' bounds, when broken, name the array and not the item (as
  /// Node::Range's checks of a [lo, hi] range do: "/variables/e_mm: expected …, found an array …").
  Field& NamesTheArray() { names_array = true; return *this; }
  /// A fixed-size array whose item i is at most maxima[i] (the schema's `prefixItems`), checked
  /// after every item is read; broken, the array is named with `expected` ("a grid of at most
  /// [256, 1024]").
  Field& ItemsAtMost(std::vector<double> maxima, std::string expected) {
    item_maxima = std::move(maxima);
    item_maxima_expected = std::move(expected);
    return *this;
  }
  /// What an absent std::optional field means, for the schema's `default`.
  Field& Default(nlohmann::json value) { documented_default = std::move(value); return *this; }
  /// The schema of a field kept as raw JSON (nlohmann::json) and read by shared code; on a number,
  /// keywords that replace the emitted ones (a parse that narrows the number in code, e.g. to a
  /// whole number with a message of its own: {"type": "integer", "minimum": 2}).
  Field& Schema(nlohmann::ordered_json fragment) { schema = std::move(fragment); return *this; }
  /// A result number that may be ±inf or NaN (a rigid element's compliance, an estimate not made):
  /// null in result.json, `"type": ["number", "null"]` in the result's schema. Without it a
  /// non-finite result number is an error naming its JSON path (ResultWriter).
  Field& NullWhenNotFinite() { null_when_not_finite = true; return *this; }
  /// A std::optional result member that is always in result.json, null when unset (a covariance
  /// that does not exist): required and nullable in the result's schema.
  Field& NullWhenAbsent() { null_when_absent = true; return *this; }
  /// A result member that decides the run's status (a top-level bool for kConverged and
  /// kFeasible, a string for kWarning; std::optional when a stage may not set it): RunStudy reads
  /// it from the typed Result (CollectRunFacts), never from result.json's text.
  Field& Decides(RunFact fact) { run_fact = fact; return *this; }

  std::string desc, unit;
  bool required = false;
  std::vector<Bound> bounds;
  std::vector<std::string> one_of;
  std::string one_of_expected;
  std::optional<std::string> constant;
  std::optional<size_t> min_items;
  std::string min_items_expected;
  std::string shape_expected;
  bool names_array = false;
  std::vector<double> item_maxima;
  std::string item_maxima_expected;
  nlohmann::json documented_default;  ///< null: none
  nlohmann::ordered_json schema;      ///< null: none
  bool null_when_not_finite = false;
  bool null_when_absent = false;
  RunFact run_fact = RunFact::kNone;
};

namespace archive_detail {

template <typename T> struct IsOptional : std::false_type {};
template <typename T> struct IsOptional<std::optional<T>> : std::true_type {};
template <typename T> struct IsVector : std::false_type {};
template <typename T> struct IsVector<std::vector<T>> : std::true_type {};
template <typename T> struct IsArray : std::false_type {};
template <typename T, size_t N> struct IsArray<std::array<T, N>> : std::true_type {};
template <typename T> struct IsBoolOr : std::false_type {};
template <typename T> struct IsBoolOr<std::variant<bool, T>> : std::true_type {};
template <typename T> struct IsVariant : std::false_type {};
template <typename... Ts> struct IsVariant<std::variant<Ts...>> : std::true_type {};
template <typename T> struct IsStringMap : std::false_type {};
template <typename T> struct IsStringMap<std::map<std::string, T>> : std::true_type {};

/// Collects the names a declaration visits (the known fields of its object).
class NameCollector {
 public:
  template <typename T>
  void Visit(const char* name, T*, const Field&) { names.insert(name); }
  void Retired(const char* name, const char*) { names.insert(name); }
  void Alias(const char*, const char*) {}
  std::set<std::string> names;
};

template <typename T>
concept Declared = requires(T& t, NameCollector* a) { t.Serialize(a); };

/// The JSON type a member of type T is written as ("object", "array", "boolean", "integer",
/// "number", "string"): how a std::variant member tells its alternatives apart.
template <typename T>
constexpr const char* JsonTypeOf() {
  if constexpr (Declared<T>) return "object";
  else if constexpr (IsVector<T>::value || IsArray<T>::value) return "array";
  else if constexpr (std::is_same_v<T, bool>) return "boolean";
  else if constexpr (std::is_same_v<T, int>) return "integer";
  else if constexpr (std::is_same_v<T, double>) return "number";
  else if constexpr (std::is_same_v<T, std::string>) return "string";
  else static_assert(sizeof(T) == 0, "a variant alternative the archives cannot tell apart by its JSON type");
}
/// Whether `j` is of the JSON type `type` (JsonTypeOf; an integer is also a number).
bool IsJsonType(const nlohmann::json& j, const std::string& type);
/// What a variant of these JSON types accepts, for its message ("true, false or an object",
/// "an object or an array").
std::string JsonTypesText(const std::vector<std::string>& types);
template <typename V, size_t... I>
std::vector<std::string> VariantJsonTypes(std::index_sequence<I...>) {
  return {JsonTypeOf<std::variant_alternative_t<I, V>>()...};
}
template <typename V>
std::vector<std::string> VariantJsonTypes() {
  return VariantJsonTypes<V>(std::make_index_sequence<std::variant_size_v<V>>{});
}

/// A number as Node's messages print it (ostream's default: 100000, 1e-13, 0.499).
std::string NumberText(double x);
/// The standard message of a bound ("a number > 0", "a whole number >= 36", …).
std::string BoundText(const Field::Bound& b, bool integer);
/// `"a" or "b"`, `one of "a", "b", "c"`.
std::string OneOfText(const std::vector<std::string>& values);

/// The schema of each alternative of the variant V (Emitter::Describe), appended to `one_of`.
template <typename Emitter, typename V, size_t... I>
void DescribeAlternatives(const Field& f, nlohmann::ordered_json& one_of, std::index_sequence<I...>) {
  const auto describe = [&](auto alternative) {
    nlohmann::ordered_json s = nlohmann::ordered_json::object();
    Emitter::Describe(&alternative, f, s);
    one_of.push_back(std::move(s));
  };
  (describe(std::variant_alternative_t<I, V>{}), ...);
}
/// A member's schema with its description ("the field's text [UNIT]"), when it has one.
nlohmann::ordered_json Described(const Field& f);

}  // namespace archive_detail

/// Reads a study file into a declared struct (see the top of this header).
class JsonReader {
 public:
  explicit JsonReader(const Node& node) : node_(node) {}

  /// Reads the member `name` of this object into *value (absent: kept, or fails when required).
  template <typename T>
  void Visit(const char* name, T* value, const Field& f) {
    if constexpr (archive_detail::IsOptional<T>::value) {
      if (!node_.Has(name)) return;
      typename T::value_type v{};
      ReadValue(node_[name], &v, f);
      *value = std::move(v);
    } else {
      if (!node_.Has(name)) {
        if (f.required) (void)node_[name];  // "missing required field"
        return;
      }
      ReadValue(node_[name], value, f);
    }
  }
  /// A field no longer read: refused with `message` when given (it stays a known field).
  void Retired(const char* name, const char* message) {
    if (node_.Has(name)) node_[name].FailWith(message);
  }
  /// `old_name` is an earlier name of `name` (both visited as fields): one of the two at most.
  void Alias(const char* name, const char* old_name) {
    if (node_.Has(name) && node_.Has(old_name))
      node_[old_name].FailWith(std::string("give either ") + name + " or its old name " + old_name + ", not both");
  }

  /// Reads the value at `n` (a whole struct, an array, a scalar).
  template <typename T>
  static void ReadValue(const Node& n, T* value, const Field& f) {
    using archive_detail::IsArray;
    using archive_detail::IsVector;
    if constexpr (archive_detail::Declared<T>) {
      archive_detail::NameCollector names;
      value->Serialize(&names);
      n.CheckKnownFields(names.names);
      JsonReader inner(n);
      value->Serialize(&inner);
    } else if constexpr (std::is_same_v<T, double>) {
      *value = ReadNumber(n, f, false);
    } else if constexpr (std::is_same_v<T, int>) {
      *value = static_cast<int>(ReadNumber(n, f, true));
    } else if constexpr (std::is_same_v<T, bool>) {
      *value = n.Bool();
    } else if constexpr (std::is_same_v<T, std::string>) {
      *value = ReadString(n, f);
    } else if constexpr (std::is_same_v<T, nlohmann::json>) {
      *value = n.json();
    } else if constexpr (archive_detail::IsVariant<T>::value) {
      ReadAlternative<T, 0>(n, value, f);
    } else if constexpr (IsVector<T>::value) {
      const std::vector<Node> items = n.Elements();
      if (f.min_items && items.size() < *f.min_items)
        n.Fail(!f.min_items_expected.empty() ? f.min_items_expected
                                             : "an array of at least " + std::to_string(*f.min_items) + " items");
      value->clear();
      for (const Node& item : items) {
        typename T::value_type v{};
        ReadValue(item, &v, f);
        value->push_back(std::move(v));
      }
    } else if constexpr (IsArray<T>::value) {
      const std::string expected =
          !f.shape_expected.empty() ? f.shape_expected : "an array of " + std::to_string(value->size()) + " numbers";
      const nlohmann::json& j = n.json();
      if (!j.is_array() || j.size() != value->size()) n.Fail(expected);
      for (const auto& item : j)
        if (!item.is_number()) n.Fail(expected);
      for (size_t i = 0; i < value->size(); ++i) {
        if constexpr (std::is_arithmetic_v<typename T::value_type>) {
          if (f.names_array) {
            (*value)[i] = static_cast<typename T::value_type>(
                ReadNumber(n, j[i], f, std::is_same_v<typename T::value_type, int>));
            continue;
          }
        }
        ReadValue(n[i], &(*value)[i], f);
      }
      for (size_t i = 0; i < value->size() && i < f.item_maxima.size(); ++i)
        if (double((*value)[i]) > f.item_maxima[i]) n.Fail(f.item_maxima_expected);
    } else {
      static_assert(sizeof(T) == 0, "a field type the archives do not know");
    }
  }

  /// Reads the alternative of the variant V whose JSON type the value at `n` has (the first from
  /// I on); none: fails with Field::Expect's text or the types accepted.
  template <typename V, size_t I>
  static void ReadAlternative(const Node& n, V* value, const Field& f) {
    if constexpr (I == std::variant_size_v<V>) {
      n.Fail(!f.shape_expected.empty() ? f.shape_expected
                                       : archive_detail::JsonTypesText(archive_detail::VariantJsonTypes<V>()));
    } else {
      using A = std::variant_alternative_t<I, V>;
      if (!archive_detail::IsJsonType(n.json(), archive_detail::JsonTypeOf<A>())) return ReadAlternative<V, I + 1>(n, value, f);
      A alternative{};
      ReadValue(n, &alternative, f);
      *value = std::move(alternative);
    }
  }

 private:
  static double ReadNumber(const Node& n, const Field& f, bool integer) { return ReadNumber(n, n.json(), f, integer); }
  /// The number `j`, its failures named at `n` (j itself, or an item of the array n).
  static double ReadNumber(const Node& n, const nlohmann::json& j, const Field& f, bool integer);
  static std::string ReadString(const Node& n, const Field& f);
  Node node_;
};

/// Emits the JSON Schema of a declared struct, member by member, into an object schema.
class SchemaEmitter {
 public:
  explicit SchemaEmitter(nlohmann::ordered_json* object) : object_(object) {}

  template <typename T>
  void Visit(const char* name, T* value, const Field& f) {
    nlohmann::ordered_json s = archive_detail::Described(f);
    if constexpr (archive_detail::IsOptional<T>::value) {
      typename T::value_type v{};
      Describe(&v, f, s);
      if (!f.documented_default.is_null()) s["default"] = f.documented_default;
    } else {
      Describe(value, f, s);
      if (!f.required && !f.constant && !archive_detail::Declared<T> &&
          !std::is_same_v<T, nlohmann::json>)
        s["default"] = WriteValue(*value);
    }
    (*object_)["properties"][name] = std::move(s);
    if (f.required) (*object_)["required"].push_back(name);
  }
  void Retired(const char*, const char*) {}
  /// Not both names: `"not": {"anyOf": [{"required": [name, old_name]}, …]}`.
  void Alias(const char* name, const char* old_name) {
    (*object_)["not"]["anyOf"].push_back({{"required", {name, old_name}}});
  }

  /// The schema keywords of a value of type T (its type, bounds, items, properties) into `s`.
  template <typename T>
  static void Describe(T* value, const Field& f, nlohmann::ordered_json& s) {
    using archive_detail::IsArray;
    using archive_detail::IsVector;
    if constexpr (archive_detail::Declared<T>) {
      s["type"] = "object";
      s["properties"] = nlohmann::ordered_json::object();
      SchemaEmitter inner(&s);
      value->Serialize(&inner);
      s["additionalProperties"] = false;
      if (s.contains("not")) {  // after the properties, for the reader of the schema
        nlohmann::ordered_json n = std::move(s["not"]);
        s.erase("not");
        s["not"] = std::move(n);
      }
      // Rules between the object's fields that JSON Schema can state (if/then, oneOf,
      // dependentRequired, not), when the struct has them: its parse checks the same in code.
      if constexpr (requires { T::SchemaRules(); }) {
        const nlohmann::ordered_json rules = T::SchemaRules();
        for (auto it = rules.begin(); it != rules.end(); ++it) s[it.key()] = it.value();
      }
      if constexpr (requires { T::CrossFieldRules(); })
        for (const CrossFieldRule& r : T::CrossFieldRules())
          s["x-rules"].push_back({{"fields", r.fields}, {"rule", r.rule}, {"message", r.message}});
    } else if constexpr (std::is_same_v<T, double> || std::is_same_v<T, int>) {
      s["type"] = std::is_same_v<T, int> ? "integer" : "number";
      NumberKeywords(f, std::is_same_v<T, int>, s);
      // A number the kind's parse narrows with a message of its own (a whole number read as a
      // number, so that a fraction gets that message): Field::Schema states the narrowing.
      for (auto it = f.schema.begin(); it != f.schema.end(); ++it) s[it.key()] = it.value();
    } else if constexpr (std::is_same_v<T, bool>) {
      s["type"] = "boolean";
    } else if constexpr (std::is_same_v<T, std::string>) {
      if (f.constant) s["const"] = *f.constant;
      else if (!f.one_of.empty()) s["enum"] = f.one_of;
      else s["type"] = "string";
    } else if constexpr (std::is_same_v<T, nlohmann::json>) {
      for (auto it = f.schema.begin(); it != f.schema.end(); ++it)
        if (!s.contains(it.key())) s[it.key()] = it.value();
    } else if constexpr (archive_detail::IsBoolOr<T>::value) {
      // true, false or the settings: the settings' object schema, which also takes a boolean.
      std::variant_alternative_t<1, T> settings{};
      Describe(&settings, Field(), s);
      s["type"] = {"boolean", "object"};
    } else if constexpr (archive_detail::IsVariant<T>::value) {
      // Alternatives told apart by their JSON type: that type list, and each one's schema.
      s["type"] = archive_detail::VariantJsonTypes<T>();
      s["oneOf"] = nlohmann::ordered_json::array();
      archive_detail::DescribeAlternatives<SchemaEmitter, T>(f, s["oneOf"],
                                                           std::make_index_sequence<std::variant_size_v<T>>{});
    } else if constexpr (IsVector<T>::value) {
      s["type"] = "array";
      if (f.min_items) s["minItems"] = *f.min_items;
      typename T::value_type item{};
      nlohmann::ordered_json is = nlohmann::ordered_json::object();
      Describe(&item, f, is);
      s["items"] = std::move(is);
    } else if constexpr (IsArray<T>::value) {
      s["type"] = "array";
      s["minItems"] = value->size();
      s["maxItems"] = value->size();
      typename T::value_type item{};
      nlohmann::ordered_json is = nlohmann::ordered_json::object();
      Describe(&item, f, is);
      s["items"] = std::move(is);
      if (!f.item_maxima.empty()) {
        s["prefixItems"] = nlohmann::ordered_json::array();
        for (double m : f.item_maxima)
          s["prefixItems"].push_back(
              {{"maximum", m == std::floor(m) ? nlohmann::ordered_json(static_cast<long long>(m)) : nlohmann::ordered_json(m)}});
      }
    } else {
      static_assert(sizeof(T) == 0, "a field type the archives do not know");
    }
  }

  /// A value as JSON (the defaults of the schema; JsonWriter).
  template <typename T>
  static nlohmann::ordered_json WriteValue(const T& value);

 private:
  static void NumberKeywords(const Field& f, bool integer, nlohmann::ordered_json& s);
  nlohmann::ordered_json* object_;
};

/// Writes a declared struct as JSON: every field, optional ones (and raw JSON ones) only when set.
class JsonWriter {
 public:
  explicit JsonWriter(nlohmann::ordered_json* object) : object_(object) {}
  template <typename T>
  void Visit(const char* name, T* value, const Field&) {
    if constexpr (archive_detail::IsOptional<T>::value) {
      if (*value) (*object_)[name] = SchemaEmitter::WriteValue(**value);
    } else if constexpr (std::is_same_v<T, nlohmann::json>) {
      if (!value->is_null()) (*object_)[name] = SchemaEmitter::WriteValue(*value);  // null: absent
    } else {
      (*object_)[name] = SchemaEmitter::WriteValue(*value);
    }
  }
  void Retired(const char*, const char*) {}
  void Alias(const char*, const char*) {}

 private:
  nlohmann::ordered_json* object_;
};

template <typename T>
nlohmann::ordered_json SchemaEmitter::WriteValue(const T& value) {
  if constexpr (archive_detail::Declared<T>) {
    nlohmann::ordered_json o = nlohmann::ordered_json::object();
    JsonWriter w(&o);
    const_cast<T&>(value).Serialize(&w);  // Serialize is not const; the writer only reads
    return o;
  } else if constexpr (archive_detail::IsVector<T>::value || archive_detail::IsArray<T>::value) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (const auto& x : value) a.push_back(WriteValue(x));
    return a;
  } else if constexpr (std::is_same_v<T, nlohmann::json>) {
    return nlohmann::ordered_json::parse(value.dump());
  } else if constexpr (archive_detail::IsVariant<T>::value) {
    return std::visit([](const auto& x) { return WriteValue(x); }, value);
  } else {
    return nlohmann::ordered_json(value);
  }
}

/// A result stage that may fail on its own without failing the run (the lubricated losses, an
/// output bearing's life, the torsional dynamics): its block, or {"error": why}.
struct StageError {
  std::string error;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("error", &error, Field().Desc("why the block was not computed (then its only key)"));
  }
};
template <typename T>
using OrError = std::variant<T, StageError>;

/// A stage's result.json block: its result when it ran, else {"error": why} when it was asked
/// for, else none.
template <typename T>
std::optional<OrError<T>> StageBlock(const std::optional<T>& result, bool asked, const std::string& why) {
  if (result) return OrError<T>(*result);
  if (asked) return OrError<T>(StageError{why});
  return std::nullopt;
}

/// Writes a declared result as result.json's JSON (the same `Serialize` that `camopt schema KIND
/// --result` describes): every member, a std::optional one only when set, a std::map<std::string,
/// T> as an object. A number that is NaN or infinite throws NonFiniteResult naming its JSON path,
/// unless its field is NullWhenNotFinite (then null): no non-finite number reaches a result file.
class ResultWriter {
 public:
  ResultWriter(nlohmann::ordered_json* object, std::string path) : object_(object), path_(std::move(path)) {}
  template <typename T>
  void Visit(const char* name, T* value, const Field& f) {
    const std::string path = path_ + "/" + name;
    if constexpr (archive_detail::IsOptional<T>::value) {
      if (*value) (*object_)[name] = Value(**value, f, path);
      else if (f.null_when_absent) (*object_)[name] = nullptr;
    } else {
      (*object_)[name] = Value(*value, f, path);
    }
  }
  void Retired(const char*, const char*) {}
  void Alias(const char*, const char*) {}

  /// The JSON of one value at `path` (a whole result: "").
  template <typename T>
  static nlohmann::ordered_json Value(const T& value, const Field& f, const std::string& path) {
    if constexpr (archive_detail::Declared<T>) {
      nlohmann::ordered_json o = nlohmann::ordered_json::object();
      ResultWriter w(&o, path);
      const_cast<T&>(value).Serialize(&w);  // Serialize is not const; the writer only reads
      return o;
    } else if constexpr (std::is_same_v<T, double>) {
      if (std::isfinite(value)) return value;
      if (f.null_when_not_finite) return nullptr;
      throw NonFiniteResult(path.empty() ? "/" : path);
    } else if constexpr (archive_detail::IsVector<T>::value || archive_detail::IsArray<T>::value) {
      nlohmann::ordered_json a = nlohmann::ordered_json::array();
      size_t i = 0;
      for (const auto& x : value) a.push_back(Value(x, f, path + "/" + std::to_string(i++)));
      return a;
    } else if constexpr (archive_detail::IsStringMap<T>::value) {
      nlohmann::ordered_json o = nlohmann::ordered_json::object();
      for (const auto& [k, x] : value) o[k] = Value(x, f, path + "/" + k);
      return o;
    } else if constexpr (std::is_same_v<T, nlohmann::json>) {
      return nlohmann::ordered_json(value);
    } else if constexpr (archive_detail::IsVariant<T>::value) {
      return std::visit([&](const auto& alternative) { return Value(alternative, f, path); }, value);
    } else if constexpr (std::is_same_v<T, std::nullptr_t>) {
      return nullptr;  // a variant's null alternative (a block that may be null)
    } else {
      static_assert(std::is_integral_v<T> || std::is_same_v<T, std::string>,
                    "a result member type the archives do not know");
      return nlohmann::ordered_json(value);
    }
  }

 private:
  nlohmann::ordered_json* object_;
  std::string path_;
};

/// What a declared result says about its own status (the members marked Field::Decides): unset
/// when the result has no such member or the stage that sets it did not run.
struct RunFacts {
  std::optional<bool> converged, feasible;
  std::string warning;
};

/// Reads the members of a declared result marked Field::Decides (top level: a forwarding
/// Serialize, as disc_cam's Result::Json, is the top level too) into RunFacts, and their names.
class RunFactCollector {
 public:
  template <typename T>
  void Visit(const char* name, T* value, const Field& f) {
    if (f.run_fact == RunFact::kNone) return;
    keys.push_back(name);
    using V = std::conditional_t<archive_detail::IsOptional<T>::value, typename OptionalValue<T>::type, T>;
    const V* v = nullptr;
    if constexpr (archive_detail::IsOptional<T>::value) v = *value ? &**value : nullptr;
    else v = value;
    if constexpr (std::is_same_v<V, bool>) {
      if (f.run_fact == RunFact::kConverged) { if (v) facts.converged = *v; return; }
      if (f.run_fact == RunFact::kFeasible) { if (v) facts.feasible = *v; return; }
    } else if constexpr (std::is_same_v<V, std::string>) {
      if (f.run_fact == RunFact::kWarning) { if (v) facts.warning = *v; return; }
    }
    throw std::logic_error(std::string("result member ") + name +
                           ": Decides(kConverged | kFeasible) needs a bool, Decides(kWarning) a string");
  }
  void Retired(const char*, const char*) {}
  void Alias(const char*, const char*) {}
  RunFacts facts;
  std::vector<std::string> keys;

 private:
  template <typename T> struct OptionalValue { using type = T; };
  template <typename T> struct OptionalValue<std::optional<T>> { using type = T; };
};

/// The status-deciding members of a declared result (RunFactCollector).
template <typename T>
RunFacts CollectRunFacts(const T& result) {
  RunFactCollector c;
  const_cast<T&>(result).Serialize(&c);  // Serialize is not const; the collector only reads
  return c.facts;
}

/// The result.json keys of T that decide the status (for the registry and its test).
template <typename T>
std::vector<std::string> RunFactKeys() {
  RunFactCollector c;
  T value{};
  value.Serialize(&c);
  return c.keys;
}

/// Emits the JSON Schema of a declared result: a member not std::optional is always present
/// (`required`), every object closed (`"additionalProperties": false`), each number's unit in its
/// description.
class ResultSchemaEmitter {
 public:
  explicit ResultSchemaEmitter(nlohmann::ordered_json* object) : object_(object) {}
  template <typename T>
  void Visit(const char* name, T* value, const Field& f) {
    nlohmann::ordered_json s = archive_detail::Described(f);
    if constexpr (archive_detail::IsOptional<T>::value) {
      typename T::value_type v{};
      Describe(&v, f, s);
      if (f.null_when_absent) {
        (*object_)["required"].push_back(name);
        if (s.contains("type") && s["type"].is_string()) s["type"] = {s["type"], "null"};
        else if (s.contains("type") && std::find(s["type"].begin(), s["type"].end(), "null") == s["type"].end())
          s["type"].push_back("null");
      }
    } else {
      Describe(value, f, s);
      (*object_)["required"].push_back(name);
    }
    (*object_)["properties"][name] = std::move(s);
  }
  void Retired(const char*, const char*) {}
  void Alias(const char*, const char*) {}

  template <typename T>
  static void Describe(T* value, const Field& f, nlohmann::ordered_json& s) {
    if constexpr (archive_detail::Declared<T>) {
      s["type"] = "object";
      s["properties"] = nlohmann::ordered_json::object();
      ResultSchemaEmitter inner(&s);
      value->Serialize(&inner);
      s["additionalProperties"] = false;
    } else if constexpr (std::is_same_v<T, double>) {
      if (f.null_when_not_finite) s["type"] = {"number", "null"};
      else s["type"] = "number";
    } else if constexpr (std::is_same_v<T, bool>) {
      s["type"] = "boolean";
    } else if constexpr (std::is_integral_v<T>) {
      s["type"] = "integer";
    } else if constexpr (std::is_same_v<T, std::string>) {
      if (f.constant) s["const"] = *f.constant;
      else if (!f.one_of.empty()) s["enum"] = f.one_of;
      else s["type"] = "string";
    } else if constexpr (std::is_same_v<T, nlohmann::json>) {
      for (auto it = f.schema.begin(); it != f.schema.end(); ++it)
        if (!s.contains(it.key())) s[it.key()] = it.value();
    } else if constexpr (archive_detail::IsVector<T>::value || archive_detail::IsArray<T>::value) {
      s["type"] = "array";
      if constexpr (archive_detail::IsArray<T>::value) {
        s["minItems"] = value->size();
        s["maxItems"] = value->size();
      }
      typename T::value_type item{};
      nlohmann::ordered_json is = nlohmann::ordered_json::object();
      Describe(&item, f, is);
      s["items"] = std::move(is);
    } else if constexpr (archive_detail::IsStringMap<T>::value) {
      s["type"] = "object";
      typename T::mapped_type item{};
      nlohmann::ordered_json is = nlohmann::ordered_json::object();
      Describe(&item, f, is);
      s["additionalProperties"] = std::move(is);
    } else if constexpr (archive_detail::IsVariant<T>::value) {
      // One of the alternatives (OrError: the block or its error).
      s["oneOf"] = nlohmann::ordered_json::array();
      archive_detail::DescribeAlternatives<ResultSchemaEmitter, T>(
          f, s["oneOf"], std::make_index_sequence<std::variant_size_v<T>>{});
    } else if constexpr (std::is_same_v<T, std::nullptr_t>) {
      s["type"] = "null";  // std::variant<Block, std::nullptr_t>: the block or null
    } else {
      static_assert(sizeof(T) == 0, "a result member type the archives do not know");
    }
  }

 private:
  nlohmann::ordered_json* object_;
};

/// A declared result as result.json's JSON (ResultWriter; the keys sorted, as result.json has them).
/// @throws NonFiniteResult naming the JSON path of a number that is not finite.
template <typename T>
nlohmann::json WriteResult(const T& result) {
  return nlohmann::json(ResultWriter::Value(result, Field(), ""));
}

/// Adds the members every result.json gets from the run (RunStudy, studies/study.h: status,
/// status_reason, camopt_version, study_sha256, warnings) to a result's schema.
void AddRunStampToResultSchema(nlohmann::ordered_json& schema);

/// The JSON Schema (draft 2020-12) of a kind's result.json, declared by T: `camopt schema KIND
/// --result`.
template <typename T>
nlohmann::ordered_json EmitResultSchema(const std::string& kind, const std::string& title) {
  nlohmann::ordered_json s = nlohmann::ordered_json::object();
  s["$schema"] = "https://json-schema.org/draft/2020-12/schema";
  s["$id"] = "https://camopt.invalid/schema/" + kind + ".result.schema.json";
  s["title"] = title;
  T value{};
  ResultSchemaEmitter::Describe(&value, Field(), s);
  AddRunStampToResultSchema(s);
  return s;
}

/// Reads the declared struct T from `node`: unknown fields refused, each field checked, defaults
/// for the absent ones. @throws StudyError (exit 2) with the file and JSON path.
template <typename T>
T Read(const Node& node) {
  T value{};
  JsonReader::ReadValue(node, &value, Field());
  return value;
}

/// The JSON Schema (draft 2020-12) of a study kind declared by T, as `camopt schema KIND` prints it.
template <typename T>
nlohmann::ordered_json EmitSchema(const std::string& kind, const std::string& title) {
  nlohmann::ordered_json s = nlohmann::ordered_json::object();
  s["$schema"] = "https://json-schema.org/draft/2020-12/schema";
  s["$id"] = "https://camopt.invalid/schema/" + kind + ".schema.json";
  s["title"] = title;
  T value{};
  SchemaEmitter::Describe(&value, Field(), s);
  return s;
}

/// A declared struct as JSON (every field with its value, optional ones when set).
template <typename T>
nlohmann::ordered_json WriteJson(const T& value) {
  return SchemaEmitter::WriteValue(value);
}

/// The fields of a schema as a Markdown table (`| field | accepts | meaning |`, one row a field, nested
/// objects as `a.b`, array items as `a[i].b`), for the reference in docs/studies.md: `camopt schema
/// KIND --table` prints it. With `result`, of a result's schema (`camopt schema KIND --result
/// --table`): `| key | value | meaning |`, each key there "always" or "not always" (its description says when).
std::string SchemaFieldTable(const nlohmann::ordered_json& schema, bool result = false);

/// The study as its declaration reads it, written back (WriteJson(Read(study))): every field with
/// the value the kind uses, defaults filled in. @throws StudyError as Read.
using DeclaredEcho = nlohmann::ordered_json (*)(const nlohmann::json& study, const std::string& file);

}  // namespace camopt::studies
