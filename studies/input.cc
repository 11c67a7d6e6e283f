#include "studies/input.h"

#include <filesystem>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <set>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "studies/suggest.h"

namespace camopt::studies {

namespace {
const nlohmann::json kMissing;  // null, for absent members
}

Node::Node(const nlohmann::json* value, std::string file, std::string path)
    : value_(value), file_(std::move(file)), path_(path.empty() ? "/" : std::move(path)) {}

namespace {

// Appends a short text of j to out, stopping once out is longer than limit: a huge or deeply
// nested value costs no more than the characters shown (the old dump() copied it all).
void AppendShort(const nlohmann::json& j, std::string& out, size_t limit) {
  if (out.size() > limit) return;
  if (j.is_object()) {
    out += '{';
    bool first = true;
    for (auto it = j.begin(); it != j.end() && out.size() <= limit; ++it) {
      if (!first) out += ',';
      first = false;
      out += nlohmann::json(it.key()).dump() + ':';
      AppendShort(*it, out, limit);
    }
    out += '}';
  } else if (j.is_array()) {
    out += '[';
    for (size_t i = 0; i < j.size() && out.size() <= limit; ++i) {
      if (i) out += ',';
      AppendShort(j[i], out, limit);
    }
    out += ']';
  } else if (j.is_string() && j.get_ref<const std::string&>().size() > limit) {
    out += nlohmann::json(j.get_ref<const std::string&>().substr(0, limit)).dump(
        -1, ' ', false, nlohmann::json::error_handler_t::replace);
  } else {
    out += j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  }
}

}  // namespace

double PlausibleLength(const Node& n, double scale_mm, const std::string& scale_name) {
  const double v = n.Positive();
  const double lo = 1e-6 * scale_mm, hi = 1e6 * scale_mm;
  if (!(v >= lo && v <= hi)) {
    std::ostringstream m;
    m.precision(4);
    if (std::isfinite(hi)) m << "a length between " << lo << " and " << hi << " mm";
    else m << "a length of at least " << lo << " mm";
    m << " (1e-6 to 1e6 times " << scale_name << ", " << scale_mm << " mm)";
    n.Fail(m.str());
  }
  return v;
}

std::string Describe(const nlohmann::json& value) {
  if (value.is_null()) return "null";
  std::string text;
  AppendShort(value, text, 60);
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  const char* kind = value.is_object()    ? "an object "
                     : value.is_array()   ? "an array "
                     : value.is_string()  ? "a string "
                     : value.is_boolean() ? "a boolean "
                                          : "";
  return kind + text;
}

void Node::Fail(const std::string& expected) const {
  const std::string found = Describe(*value_);
  std::string hint;
  if (value_->is_string())
    if (const std::string near = NearestName(value_->get<std::string>(), NamesInExpected(expected)); !near.empty())
      hint = " (did you mean \"" + near + "\"?)";
  throw StudyError(file_ + ": " + path_ + ": expected " + expected + ", found " + found + hint, file_, path_,
                   expected, found);
}

void Node::Fail(const std::string& expected, const std::string& would_fit) const {
  if (would_fit.empty()) Fail(expected);
  const std::string found = Describe(*value_);
  throw StudyError(file_ + ": " + path_ + ": expected " + expected + ", found " + found + "; " + would_fit +
                       " would fit",
                   file_, path_, expected, found);
}

void Node::FailWith(const std::string& message) const {
  throw StudyError(file_ + ": " + path_ + ": " + message, file_, path_, message, Describe(*value_));
}

void Node::CheckKnownFields(const std::set<std::string>& known) const {
  if (!value_->is_object()) Fail("an object");
  for (auto it = value_->begin(); it != value_->end(); ++it) {
    if (known.count(it.key())) continue;
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    const std::string near = NearestName(it.key(), std::vector<std::string>(known.begin(), known.end()));
    (*this)[it.key()].FailWith("unknown field (known: " + list + ")" +
                               (near.empty() ? "" : "; did you mean \"" + near + "\"?"));
  }
}

bool Node::Has(const std::string& key) const {
  return value_->is_object() && value_->contains(key);
}

Node Node::operator[](const std::string& key) const {
  const std::string child = (path_ == "/" ? "" : path_) + "/" + key;
  if (!value_->is_object()) Fail("an object with field \"" + key + "\"");
  auto it = value_->find(key);
  if (it == value_->end())
    throw StudyError(file_ + ": " + child + ": missing required field", file_, child,
                     "a required field", "nothing");
  return Node(&*it, file_, child);
}

Node Node::operator[](size_t i) const {
  if (!value_->is_array()) Fail("an array");
  const std::string child = (path_ == "/" ? "" : path_) + "/" + std::to_string(i);
  if (i >= value_->size())
    throw StudyError(file_ + ": " + child + ": missing array element");
  return Node(&(*value_)[i], file_, child);
}

std::vector<Node> Node::Elements() const {
  if (!value_->is_array()) Fail("an array");
  std::vector<Node> out;
  for (size_t i = 0; i < value_->size(); ++i) out.push_back((*this)[i]);
  return out;
}

double Node::Number() const {
  if (!value_->is_number()) Fail("a number");
  const double v = value_->get<double>();
  if (!std::isfinite(v)) Fail("a finite number");
  return v;
}

double Node::Positive() const {
  if (!value_->is_number() || !(value_->get<double>() > 0)) Fail("a number > 0");
  return Number();
}

double Node::NonNegative() const {
  if (!value_->is_number() || !(value_->get<double>() >= 0)) Fail("a number >= 0");
  return Number();
}

double Node::NumberIn(double lo, double hi) const {
  std::ostringstream os;
  os << "a number in [" << lo << ", " << hi << "]";
  if (!value_->is_number()) Fail(os.str());
  const double v = value_->get<double>();
  if (!(v >= lo && v <= hi)) Fail(os.str());
  return v;
}

int Node::Integer(int min_value) const {
  const std::string expected = "a whole number >= " + std::to_string(min_value);
  if (!value_->is_number()) Fail(expected);
  const double v = value_->get<double>();
  if (!(std::floor(v) == v) || v < min_value || v > 1e9) Fail(expected);
  return static_cast<int>(v);
}

std::string Node::String() const {
  if (!value_->is_string()) Fail("a string");
  return value_->get<std::string>();
}

bool Node::Bool() const {
  if (!value_->is_boolean()) Fail("true or false");
  return value_->get<bool>();
}

std::pair<double, double> Node::Range() const {
  if (!value_->is_array() || value_->size() != 2 || !(*value_)[0].is_number() ||
      !(*value_)[1].is_number())
    Fail("[lower, upper], two numbers");
  const double lo = (*this)[0].Number(), hi = (*this)[1].Number();
  if (!(lo <= hi)) Fail("[lower, upper] with lower <= upper");
  return {lo, hi};
}

double Node::NumberOr(const std::string& key, double fallback) const {
  return Has(key) ? (*this)[key].Number() : fallback;
}
double Node::PositiveOr(const std::string& key, double fallback) const {
  return Has(key) ? (*this)[key].Positive() : fallback;
}
double Node::NonNegativeOr(const std::string& key, double fallback) const {
  return Has(key) ? (*this)[key].NonNegative() : fallback;
}
int Node::IntegerOr(const std::string& key, int min_value, int fallback) const {
  return Has(key) ? (*this)[key].Integer(min_value) : fallback;
}
std::string Node::StringOr(const std::string& key, const std::string& fallback) const {
  return Has(key) ? (*this)[key].String() : fallback;
}
bool Node::BoolOr(const std::string& key, bool fallback) const {
  return Has(key) ? (*this)[key].Bool() : fallback;
}

InputLimits& CurrentInputLimits() {
  static InputLimits limits;
  return limits;
}

size_t FileBytesForWorkFactor(double factor) {
  const double bytes = static_cast<double>(InputLimits{}.max_file_bytes) * std::min(factor, 1e3);
  return bytes > 0 ? static_cast<size_t>(bytes) : 0;
}

std::string ReadFileCapped(const std::string& file, size_t max_bytes, const std::string& what) {
  const auto fail = [&](const std::string& why) -> std::string {
    throw StudyError(file + ": cannot read the " + what + ": " + why);
  };
  // O_NONBLOCK: opening a FIFO with no writer must not block; a regular file ignores it.
  const int fd = open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return fail(std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { close(fd); }
  } closer{fd};
  struct stat st {};
  if (fstat(fd, &st) != 0) return fail(std::strerror(errno));
  if (S_ISDIR(st.st_mode)) return fail("it is a folder");
  if (!S_ISREG(st.st_mode)) return fail("not a regular file (a device, FIFO or socket)");
  if (static_cast<unsigned long long>(st.st_size) > max_bytes)
    return fail("it has " + std::to_string(st.st_size) + " bytes, more than the limit of " +
                std::to_string(max_bytes) + " (raise it with --max-work-factor)");
  std::string text(static_cast<size_t>(st.st_size), '\0');
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = read(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return fail(std::strerror(errno));
    if (n == 0) break;  // shrank while reading
    done += static_cast<size_t>(n);
  }
  text.resize(done);
  return text;
}

namespace {

// "line L, column C" of a byte offset (1-based), for syntax errors.
std::string LineColumn(const std::string& text, size_t byte) {
  size_t line = 1, column = 1;
  for (size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// A SAX pass over the text before the value is built: it keeps the JSON path of the current
// value (only max_depth levels can exist) so that too deep nesting, an out-of-range number and a
// syntax error are reported with a path. nlohmann's parser itself is iterative.
class CheckingSax {
 public:
  CheckingSax(const std::string& text, const std::string& file, int max_depth)
      : text_(text), file_(file), max_depth_(max_depth) {}

  bool null() { return Value(); }
  bool boolean(bool) { return Value(); }
  bool number_integer(nlohmann::json::number_integer_t) { return Value(); }
  bool number_unsigned(nlohmann::json::number_unsigned_t) { return Value(); }
  bool number_float(nlohmann::json::number_float_t v, const std::string& raw) {
    // A literal with a non-zero digit that reads as 0 underflowed (1e-400): say so with its text
    // rather than letting a later check report "found 0.0".
    if (v == 0) {
      const std::string mantissa = raw.substr(0, raw.find_first_of("eE"));
      if (mantissa.find_first_of("123456789") != std::string::npos)
        throw StudyError(file_ + ": " + Path() + ": expected a number within the range of a double (" +
                         "about ±2.2e-308 … ±1.8e308, or 0), found " + raw.substr(0, 40));
    }
    return Value();
  }
  bool string(std::string&) { return Value(); }
  bool binary(nlohmann::json::binary_t&) { return Value(); }
  bool start_object(size_t) { return Open(false); }
  bool start_array(size_t) { return Open(true); }
  bool key(std::string& k) {
    // A key given twice: nlohmann keeps the last one silently (a study with "load_torque_Nm": 50
    // and then 5000 would compute 5000); refuse it with the path.
    if (!frames_.back().keys.insert(k).second) {
      frames_.back().key = k;
      throw StudyError(file_ + ": " + Path() + ": expected each key once in an object, found \"" +
                       k.substr(0, 40) + "\" a second time; keep one");
    }
    frames_.back().key = k;
    return true;
  }
  bool end_object() { return Close(); }
  bool end_array() { return Close(); }

  bool parse_error(size_t byte, const std::string& raw_token, const nlohmann::json::exception& e) {
    // The offending text, printable ASCII only (it may be invalid UTF-8 or control bytes).
    std::string token = raw_token;
    for (char& c : token)
      if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    if (e.id == 406)  // out_of_range: number overflow
      throw StudyError(file_ + ": " + Path() + ": expected a number within the range of a double (" +
                       "about ±1.8e308), found " + token.substr(0, 40));
    throw StudyError(file_ + ": " + Path() + ": expected valid JSON, found a syntax error at " +
                     LineColumn(text_, byte > 0 ? byte - 1 : 0) + " (near '" + token.substr(0, 20) +
                     "')");
  }

 private:
  struct Frame {
    bool array;
    size_t count = 0;
    std::string key;
    std::set<std::string> keys;  // of an object, so far
  };

  bool Value() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().count;
    return true;
  }
  bool Open(bool array) {
    if (static_cast<int>(frames_.size()) >= max_depth_)
      throw StudyError(file_ + ": " + Path() + ": expected at most " + std::to_string(max_depth_) +
                       " levels of nested arrays and objects, found deeper nesting");
    frames_.push_back(Frame{array, 0, {}, {}});
    return true;
  }
  bool Close() {
    frames_.pop_back();
    return Value();
  }
  // The path of the value being read (in an array: the element about to be counted).
  std::string Path() const {
    std::string p;
    for (const Frame& f : frames_) {
      p += "/";
      p += f.array ? std::to_string(f.count) : f.key;
    }
    return p.empty() ? "/" : p;
  }

  const std::string& text_;
  const std::string& file_;
  int max_depth_;
  std::vector<Frame> frames_;
};

}  // namespace

nlohmann::json ParseStudyText(const std::string& text, const std::string& file, int max_depth) {
  // nlohmann's lexer takes a NUL byte for the end of the input: whatever follows it would be
  // ignored without a word.
  if (const size_t at = text.find('\0'); at != std::string::npos)
    throw StudyError(file + ": /: expected a JSON text, found a NUL byte at byte " + std::to_string(at) + " of " +
                     std::to_string(text.size()) + " (remove it and what follows it, or save the file as text)");
  CheckingSax sax(text, file, max_depth);
  if (!nlohmann::json::sax_parse(text, &sax))
    throw StudyError(file + ": /: expected valid JSON, found a syntax error");
  // The text is known to be valid, shallow and in range: build the value.
  return nlohmann::json::parse(text);
}

void CheckFileInside(const std::string& file) {
  const InputLimits& limits = CurrentInputLimits();
  if (!limits.files_inside.empty()) {
    // Resolved before anything is opened, so the answer does not depend on whether it exists.
    std::error_code ec;
    const std::filesystem::path root = std::filesystem::weakly_canonical(limits.files_inside, ec);
    const std::filesystem::path p = std::filesystem::weakly_canonical(std::filesystem::absolute(file, ec), ec);
    const auto rel = p.lexically_relative(root);
    if (ec || root.empty() || rel.empty() || *rel.begin() == "..")
      throw StudyError(file + ": expected a file inside the folder " + limits.files_inside +
                       ", found a path that leads outside it (copy the file into the folder)");
  }
}

nlohmann::json LoadStudyFile(const std::string& file) {
  CheckFileInside(file);
  const InputLimits& limits = CurrentInputLimits();
  return ParseStudyText(ReadFileCapped(file, limits.max_file_bytes, "file"), file,
                        limits.max_depth);
}

}  // namespace camopt::studies
