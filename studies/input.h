// Reading a study file: every access knows its file and JSON path, so that a bad value is
// reported as one line naming the file, the path, what was expected and what was found.
#pragma once

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace camopt::studies {

/// A bad study file (exit code 2). what() is the whole one-line message. Errors raised through a
/// Node also carry its parts (for the Python module's camopt.StudyError): the file, the JSON path,
/// what was expected and what was found (empty when the message is not of that form).
class StudyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  StudyError(const std::string& message, std::string file, std::string path, std::string expected,
             std::string found)
      : std::runtime_error(message), file_(std::move(file)), path_(std::move(path)),
        expected_(std::move(expected)), found_(std::move(found)) {}
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  const std::string& expected() const { return expected_; }
  const std::string& found() const { return found_; }

 private:
  std::string file_, path_, expected_, found_;
};

/// A result number that came out NaN or infinite. The inputs passed their checks, so it means
/// the study's values are outside what the models can compute (a base radius of 1e308 mm, a
/// roller of 1e-6 mm): RunStudy reports it as a StudyError (exit 2) naming the study file.
class NonFiniteResult : public std::runtime_error {
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
  /// The same, with what would fit added: "...: expected E, found F; W would fit".
  [[noreturn]] void Fail(const std::string& expected, const std::string& would_fit) const;
  /// Throws a StudyError "FILE: PATH: MESSAGE" for errors that are not a type mismatch.
  [[noreturn]] void FailWith(const std::string& message) const;

 private:
  const nlohmann::json* value_;
  std::string file_;
  std::string path_;
};

/// A short description of a JSON value for messages: its text, cut to a sensible length.
std::string Describe(const nlohmann::json& value);

/// A length [mm] at `n`, > 0 and on the design's own scale: within [1e-6, 1e6] × scale_mm, the
/// size of the part it belongs to (named by scale_name, e.g. "the turret radius"). Fails with the
/// range that would fit: a part of 8e-12 mm or of a kilometre is a typing error, and the solid
/// modeller cannot close it.
double PlausibleLength(const Node& n, double scale_mm, const std::string& scale_name);

/// Limits on what is read, checked before anything is parsed or allocated for it.
struct InputLimits {
  /// Largest study or catalogue file read, in bytes (a real study is a few kB).
  size_t max_file_bytes = size_t{16} << 20;
  /// Deepest nesting of arrays and objects (real studies nest 4 levels).
  int max_depth = 64;
  /// Non-empty: every file LoadStudyFile reads (a roller catalogue, a sweep's base) must lie inside
  /// this folder once links are resolved; a path outside is refused with the same words whether or
  /// not it exists (the studio's boundary: `camopt serve` sets it to its folder, and passes it to
  /// its runs as --files-inside).
  std::string files_inside;
};
/// The limits LoadStudyFile uses (process-wide; the CLI raises them with --max-work-factor).
InputLimits& CurrentInputLimits();
/// The file-size cap for a work factor: the default max_file_bytes times the factor (at most
/// 1e3). Always from the default, so that runs in one process (the Python module, a fuzzer) do
/// not compound their factors.
size_t FileBytesForWorkFactor(double factor);

/// The whole content of a regular file of at most max_bytes: the type and size are checked
/// before reading, so /dev/zero, a FIFO or a huge file is refused at once. `what` names the file
/// in messages ("study file", "roller catalogue"). Throws StudyError with the OS reason.
std::string ReadFileCapped(const std::string& file, size_t max_bytes, const std::string& what);

/// Parses JSON text of `file`: nesting deeper than max_depth, numbers outside the range of a
/// double (1e400) and syntax errors are StudyErrors naming the file, the JSON path, and line and
/// column. No recursion over the value: a 100 000-deep text is refused, not a stack overflow.
nlohmann::json ParseStudyText(const std::string& text, const std::string& file, int max_depth);

/// Throws StudyError when CurrentInputLimits().files_inside is set and `file` lies outside it.
void CheckFileInside(const std::string& file);

/// Reads (ReadFileCapped) and parses (ParseStudyText) a study file with CurrentInputLimits().
nlohmann::json LoadStudyFile(const std::string& file);

}  // namespace camopt::studies
