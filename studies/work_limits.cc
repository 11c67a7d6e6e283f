#include "studies/work_limits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numeric>

#include "studies/input.h"
#include "studies/kind.h"

namespace camopt::studies {

namespace {

using nlohmann::json;

const json kNull;

const json& Sub(const json& o, const char* key) {
  if (!o.is_object()) return kNull;
  auto it = o.find(key);
  return it == o.end() ? kNull : *it;
}

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

WorkEstimate EstimateWork(const json& study, const std::string& file, double factor) {
  const json& kind_json = Sub(study, "study");
  const std::string kind = kind_json.is_string() ? kind_json.get<std::string>() : "";
  if (const KindDescriptor* k = FindKind(kind); k && k->estimate) return k->estimate(study, file, factor);
  WorkEstimate none;
  none.cap = 1;
  return none;
}

void CheckWorkFactor(double factor) {
  // NaN passes every comparison a cap makes (each would be off), infinity lifts them all.
  if (!(factor >= 1e-6 && factor <= 1e6))
    throw StudyError("max_work_factor: expected a number between 1e-6 and 1e6, found " + Num(factor));
}

void CheckWorkLimits(const json& study, const std::string& file, double factor) {
  CheckWorkFactor(factor);
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
