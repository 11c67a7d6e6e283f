#include "studies/study.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include <unistd.h>

namespace camopt::studies {

namespace fs = std::filesystem;

void Progress::Update(double fraction, const std::string& detail) {
  if (quiet_) return;
  // On a terminal one line is rewritten in place (10 times a second at most); into a file or a
  // pipe, a plain line every 2 seconds and at the end.
  static const bool tty = isatty(2);
  const auto now = std::chrono::steady_clock::now();
  const auto every = tty ? std::chrono::milliseconds(100) : std::chrono::milliseconds(2000);
  if (shown_ && fraction < 1.0 && now - last_ < every) return;
  if (!shown_ && !tty && fraction >= 1.0) return;  // finished before the first line was due
  last_ = now;
  shown_ = true;
  char pct[16];
  std::snprintf(pct, sizeof pct, "%5.1f%%", 100.0 * std::clamp(fraction, 0.0, 1.0));
  std::cerr << (tty ? "\r" : "") << label_ << ": " << pct << (detail.empty() ? "" : "  ") << detail
            << (tty ? "\033[K" : "\n") << std::flush;
}

void Progress::Done() {
  if (quiet_ || !shown_) return;
  static const bool tty = isatty(2);
  if (tty) std::cerr << "\n" << std::flush;
  shown_ = false;
}

namespace {

std::map<std::string, StudyRunner>& Registry() {
  static std::map<std::string, StudyRunner> registry;
  return registry;
}

// Rejects NaN and infinities anywhere in a json tree, naming the path.
void CheckFiniteTree(const nlohmann::json& j, const std::string& path) {
  if (j.is_number_float() && !std::isfinite(j.get<double>()))
    throw std::runtime_error("internal error: non-finite number at " + path);
  if (j.is_object())
    for (auto it = j.begin(); it != j.end(); ++it) CheckFiniteTree(*it, path + "/" + it.key());
  if (j.is_array())
    for (size_t i = 0; i < j.size(); ++i) CheckFiniteTree(j[i], path + "/" + std::to_string(i));
}

}  // namespace

void Outputs::AddJson(const std::string& name, const nlohmann::json& value) {
  CheckFiniteTree(value, name);
  Add(name, value.dump(2) + "\n");
}

void Outputs::WriteAll(const std::string& dir) const {
  const fs::path out(dir);
  fs::create_directories(out);
  const fs::path staging = out / ".camopt-staging";
  fs::remove_all(staging);
  fs::create_directories(staging);
  for (const auto& [name, content] : files_) {
    std::ofstream f(staging / name, std::ios::binary);
    f << content;
    if (!f) throw std::runtime_error("cannot write " + (staging / name).string());
  }
  for (const auto& [name, content] : files_) fs::rename(staging / name, out / name);
  fs::remove_all(staging);
}

bool RegisterStudy(const std::string& kind, StudyRunner runner) {
  Registry()[kind] = std::move(runner);
  return true;
}

std::vector<std::string> StudyKinds() {
  std::vector<std::string> kinds;
  for (const auto& [k, v] : Registry()) kinds.push_back(k);
  return kinds;
}

Outputs RunStudy(const nlohmann::json& study, const RunContext& ctx) {
  const Node root(&study, ctx.study_file, "");
  if (!study.is_object()) root.Fail("a study object");
  const Node kind_node = root["study"];
  const std::string kind = kind_node.String();
  auto it = Registry().find(kind);
  if (it == Registry().end()) {
    std::string known;
    for (const auto& k : StudyKinds()) known += (known.empty() ? "" : ", ") + k;
    kind_node.Fail("a known study kind (" + known + ")");
  }
  Outputs outputs;
  it->second(root, ctx, outputs);
  return outputs;
}

void RunStudyFile(const std::string& file, const std::string& out_dir, const RunContext& ctx) {
  RunContext c = ctx;
  c.study_file = file;
  const nlohmann::json study = LoadStudyFile(file);
  const Outputs outputs = RunStudy(study, c);
  outputs.WriteAll(out_dir);
  if (!outputs.incomplete().empty()) throw StudyIncomplete(outputs.incomplete());
}

double Finite(double value, const std::string& what) {
  if (!std::isfinite(value)) throw std::runtime_error("internal error: " + what + " is not finite");
  return value;
}

}  // namespace camopt::studies
