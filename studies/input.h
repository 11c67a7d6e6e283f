// Reading a study file: every access knows its file and JSON path, so that a bad value is
// reported as one line naming the file, the path, what was expected and what was found.
#pragma once

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace camopt::studies {

/// A bad study file (exit code 2). what() is the whole one-line message.
class StudyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A view of one JSON value in a study file, with its path for error messages.
class Node {
 public:
  Node(const nlohmann::json* value, std::string file, std::string path);

  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }
  const nlohmann::json& json() const { return *value_; }

  bool Has(const std::string& key) const;
  /// A required member: throws "missing field" when absent or when this is not an object.
  Node operator[](const std::string& key) const;
  /// Element i of an array.
  Node operator[](size_t i) const;
  /// The elements of an array (throws when this is not an array).
  std::vector<Node> Elements() const;

  double Number() const;
  /// A number > 0.
  double Positive() const;
  /// A number >= 0.
  double NonNegative() const;
  /// A number in [lo, hi].
  double NumberIn(double lo, double hi) const;
  /// A whole number >= min_value.
  int Integer(int min_value) const;
  std::string String() const;
  bool Bool() const;
  /// A [lo, hi] pair of numbers with lo <= hi.
  std::pair<double, double> Range() const;

  /// Optional members with a default.
  double NumberOr(const std::string& key, double fallback) const;
  double PositiveOr(const std::string& key, double fallback) const;
  double NonNegativeOr(const std::string& key, double fallback) const;
  int IntegerOr(const std::string& key, int min_value, int fallback) const;
  std::string StringOr(const std::string& key, const std::string& fallback) const;
  bool BoolOr(const std::string& key, bool fallback) const;

  /// Rejects members not in `known` (a misspelt optional field would otherwise silently read as
  /// its default): "FILE: PATH/key: unknown field (known: …)". Also fails when this is not an object.
  void CheckKnownFields(const std::set<std::string>& known) const;

  /// Throws a StudyError "FILE: PATH: expected EXPECTED, found FOUND".
  [[noreturn]] void Fail(const std::string& expected) const;
  /// Throws a StudyError "FILE: PATH: MESSAGE" for errors that are not a type mismatch.
  [[noreturn]] void FailWith(const std::string& message) const;

 private:
  const nlohmann::json* value_;
  std::string file_;
  std::string path_;
};

/// A short description of a JSON value for messages: its text, cut to a sensible length.
std::string Describe(const nlohmann::json& value);

/// Parses a study file; throws StudyError for an unreadable file or invalid JSON.
nlohmann::json LoadStudyFile(const std::string& file);

}  // namespace camopt::studies
