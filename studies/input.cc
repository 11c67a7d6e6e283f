#include "studies/input.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace camopt::studies {

namespace {
const nlohmann::json kMissing;  // null, for absent members
}

Node::Node(const nlohmann::json* value, std::string file, std::string path)
    : value_(value), file_(std::move(file)), path_(path.empty() ? "/" : std::move(path)) {}

std::string Describe(const nlohmann::json& value) {
  if (value.is_null()) return "null";
  std::string text = value.dump();
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  const char* kind = value.is_object()    ? "an object "
                     : value.is_array()   ? "an array "
                     : value.is_string()  ? "a string "
                     : value.is_boolean() ? "a boolean "
                                          : "";
  return kind + text;
}

void Node::Fail(const std::string& expected) const {
  throw StudyError(file_ + ": " + path_ + ": expected " + expected + ", found " + Describe(*value_));
}

void Node::FailWith(const std::string& message) const {
  throw StudyError(file_ + ": " + path_ + ": " + message);
}

void Node::CheckKnownFields(const std::set<std::string>& known) const {
  if (!value_->is_object()) Fail("an object");
  for (auto it = value_->begin(); it != value_->end(); ++it) {
    if (known.count(it.key())) continue;
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    (*this)[it.key()].FailWith("unknown field (known: " + list + ")");
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
    throw StudyError(file_ + ": " + child + ": missing required field");
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

nlohmann::json LoadStudyFile(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw StudyError(file + ": cannot open the study file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  try {
    return nlohmann::json::parse(buffer.str());
  } catch (const nlohmann::json::parse_error& e) {
    throw StudyError(file + ": /: expected valid JSON, found a syntax error at byte " +
                     std::to_string(e.byte));
  }
}

}  // namespace camopt::studies
