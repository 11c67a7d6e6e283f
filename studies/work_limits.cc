#include "studies/work_limits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numeric>

#include "sizing/lcr_min_size.h"
#include "studies/input.h"

namespace camopt::studies {

namespace {

using nlohmann::json;

const json kNull;

const json& Sub(const json& o, const char* key) {
  if (!o.is_object()) return kNull;
  auto it = o.find(key);
  return it == o.end() ? kNull : *it;
}

// A size from the raw file: a finite number >= 0, else the kind's default (the kind's own parser
// reports a value of the wrong type with its path).
double Size(const json& o, const char* key, double fallback) {
  const json& v = Sub(o, key);
  if (!v.is_number()) return fallback;
  const double x = v.get<double>();
  return std::isfinite(x) && x >= 0 ? x : fallback;
}

size_t Count(const json& v) { return v.is_array() || v.is_object() ? v.size() : 0; }

using Term = WorkTerm;
std::string Num(double v) { return WorkNumber(v); }

}  // namespace

std::string WorkNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

WorkEstimate LargestTerm(std::vector<WorkTerm> terms, double cap, std::string unit, double bytes_per_unit) {
  WorkEstimate e;
  e.cap = cap;
  e.unit = std::move(unit);
  double largest = -1;
  for (const Term& t : terms) {
    e.work += t.work;
    if (t.work > largest) {
      largest = t.work;
      e.path = t.path;
      e.detail = t.detail;
    }
  }
  e.memory_bytes = e.work * bytes_per_unit;
  return e;
}

namespace {

WorkEstimate Largest(std::vector<Term> terms, double cap, std::string unit, double bytes_per_unit) {
  return LargestTerm(std::move(terms), cap, std::move(unit), bytes_per_unit);
}

// Cells of a "grid": [nx, ny] (fallback when absent or not two numbers).
double GridCellsOr(const json& g, double fallback) {
  if (!(g.is_array() && g.size() == 2 && g[0].is_number() && g[1].is_number())) return fallback;
  return std::max(0.0, g[0].get<double>()) * std::max(0.0, g[1].get<double>());
}


WorkEstimate LcrMinSize(const json& s, double factor, const std::string& file) {
  const json& search = Sub(s, "search");
  const double lobes = Size(search, "max_lobes", 40);
  const json& diffs = Sub(search, "roller_lobe_difference");
  const double n_diffs = diffs.is_array() ? double(diffs.size()) : 1;
  const double starts = Size(Sub(s, "optimizer"), "starts", objectives::LcrMinSizeOptions{}.starts);
  double rollers = 1;
  const json& cat = Sub(s, "roller_catalogue");
  if (cat.is_array()) rollers = std::max<double>(1, cat.size());
  const json& cat_file = Sub(cat, "file");
  if (cat_file.is_string()) {
    // The catalogue file is checked here (regular file, size cap) so that /dev/zero or a huge
    // file is refused with the JSON path that names it, before any work.
    std::filesystem::path p(cat_file.get<std::string>());
    if (p.is_relative()) p = std::filesystem::path(file).parent_path() / p;
    std::error_code ec;
    // A missing file is the kind's to report (after its own checks of the study).
    if (std::filesystem::exists(p, ec)) {
      try {
        rollers = std::max<double>(1, Count(LoadStudyFile(p.string())));
      } catch (const StudyError& e) {
        throw StudyError(file + ": /roller_catalogue/file: " + e.what());
      }
    }
  }
  // A local optimization of the line model (24 samples per load period) is the unit (~30 ms); its
  // cost grows with the samples. Under the finite-length contact each candidate adds the 3D polish
  // (about 30 units at 20 slices, a slices solve costing ∝ N³) and the best design's verification
  // (half_space solves on the grid and on twice it each way: ≈ 40 units at 48×128).
  const json& opt = Sub(s, "optimizer");
  // Values outside what the parser accepts are counted at its bound: the parser's message names them.
  const double samples = std::clamp(Size(opt, "samples_per_period", 24), 4.0, 720.0);
  const double per_start = 0.5 + 0.5 * samples / 24.0;
  const double combos = lobes * n_diffs * rollers;
  std::vector<Term> terms = {{combos * starts * per_start, "/search/max_lobes",
                              Num(lobes) + " lobe counts × " + Num(n_diffs) + " roller-lobe differences × " +
                                  Num(rollers) + " catalogue rollers × " + Num(starts) + " starts × " +
                                  Num(per_start) + " (samples per period)"}};
  const json& contact = Sub(s, "contact");
  const json& model = Sub(contact, "model");
  const bool three_d = (model.is_string() && model.get<std::string>() != "line") ||
                       Sub(Sub(s, "fixed"), "crowning").is_object();
  if (three_d) {
    const double slices = std::clamp(Size(contact, "slices", 40), 4.0, 200.0);
    terms.push_back({combos * 30 * std::pow(slices / 20.0, 3), "/contact/slices",
                     Num(combos) + " candidates × 3D polish with " + Num(slices) + " slices"});
    const double cells = GridCellsOr(Sub(contact, "grid"), 64.0 * 256.0);
    terms.push_back({40 * 5 * cells / (48.0 * 128.0), "/contact/grid",
                     "half_space verification on " + Num(cells) + " cells and four times as many"});
  }
  // Bearing lives (docs/life.md): every dense check computes each rated bearing's life per duty
  // line, one force analysis per angle of its load period (about a third of a unit per line and
  // polish round of a start; a study's lines multiply it).
  const json& duty = Sub(s, "duty_cycle");
  if (duty.is_array() && duty.size() > 1)
    terms.push_back({combos * starts * per_start * double(duty.size()), "/duty_cycle",
                     Num(combos) + " candidates × " + Num(starts) + " starts × " + Num(double(duty.size())) +
                         " duty-cycle lines (each line's bearing lives in every dense check)"});
  // When nothing fits, the message names the limit that would fit (objectives::LimitToFit: up to 13
  // solves of the closest combination, each up to 8 polish rounds of an infeasible problem, measured
  // at about 4 units a round and start); a converged result prices its binding limits with fewer
  // re-solves than that. Counted always: whether anything fits is not known before the search.
  terms.push_back({13 * 8 * 4 * starts * per_start, "/limits",
                   "if nothing fits: up to 13 solves × 8 polish rounds × " + Num(starts) +
                       " starts to find the limit that would fit"});
  const json& mc = Sub(s, "monte_carlo");
  if (s.contains("robust")) {
    // Two Monte-Carlo checks (robust and nominal best): a sample of 720 angles ≈ 36 ms ≈ 1 unit.
    const double mc_samples = Size(mc, "samples", 200), mc_steps = Size(mc, "angle_steps", 720);
    terms.push_back({2 * mc_samples * mc_steps / 720.0, "/monte_carlo/samples",
                     "2 × " + Num(mc_samples) + " Monte-Carlo samples × " + Num(mc_steps) + " angles"});
  }
  return Largest(terms, 2e4 * factor, "local optimizations", 1000);
}

}  // namespace

namespace {
std::map<std::string, WorkEstimator>& EstimatorRegistry() {
  static std::map<std::string, WorkEstimator> registry;
  return registry;
}
}  // namespace

bool RegisterWorkEstimate(const std::string& kind, WorkEstimator estimator) {
  EstimatorRegistry()[kind] = std::move(estimator);
  return true;
}

WorkEstimate EstimateWork(const json& study, const std::string& file, double factor) {
  const json& kind_json = Sub(study, "study");
  const std::string kind = kind_json.is_string() ? kind_json.get<std::string>() : "";
  if (const auto it = EstimatorRegistry().find(kind); it != EstimatorRegistry().end())
    return it->second(study, file, factor);
  if (kind == "lcr_min_size") return LcrMinSize(study, factor, file);
  WorkEstimate none;
  none.cap = 1;
  return none;
}

void CheckWorkLimits(const json& study, const std::string& file, double factor) {
  const WorkEstimate e = EstimateWork(study, file, factor);
  const std::string raise = "; raise the caps with --max-work-factor (see docs/reliability.md)";
  if (e.work > e.cap)
    throw StudyError(file + ": " + e.path + ": the study needs about " + Num(e.work) + " " +
                     e.unit + " (" + e.detail + "), more than the cap of " + Num(e.cap) + raise);
  if (e.memory_bytes > kMaxMemoryBytes * factor)
    throw StudyError(file + ": " + e.path + ": the study needs about " + Num(e.memory_bytes / 1e9) +
                     " GB of memory (" + e.detail + "), more than the cap of " +
                     Num(kMaxMemoryBytes * factor / 1e9) + " GB" + raise);
}

}  // namespace camopt::studies
