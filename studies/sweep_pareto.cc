#include "studies/sweep_pareto.h"

#include <algorithm>
#include <utility>

namespace camopt::studies::sweep {

bool Objectives(const Sweep& s, const CaseRecord& r, std::vector<double>& f) {
  f.clear();
  for (size_t i : s.minimize) {
    if (!r.outputs[i].is_number()) return false;
    f.push_back(r.outputs[i].get<double>());
  }
  for (size_t i : s.maximize) {
    if (!r.outputs[i].is_number()) return false;
    f.push_back(-r.outputs[i].get<double>());
  }
  return true;
}

std::vector<size_t> ObjectiveColumns(const Sweep& s) {
  std::vector<size_t> objectives = s.minimize;
  objectives.insert(objectives.end(), s.maximize.begin(), s.maximize.end());
  return objectives;
}

bool Maximized(const Sweep& s, size_t column) {
  return std::find(s.maximize.begin(), s.maximize.end(), column) != s.maximize.end();
}

std::vector<size_t> ParetoFront(const Sweep& s, const std::vector<CaseRecord>& records) {
  // Candidates in lexicographic order of their objectives: whatever dominates a point comes
  // before it, and (dominance being transitive) so does some point of the front that dominates
  // it, so each candidate is compared with the front found so far only.
  std::vector<std::pair<std::vector<double>, size_t>> candidates;
  std::vector<double> f;
  for (size_t i = 0; i < records.size(); ++i)
    if (records[i].status == "ok" && Objectives(s, records[i], f)) candidates.push_back({f, i});
  std::sort(candidates.begin(), candidates.end());
  std::vector<size_t> front;
  std::vector<const std::vector<double>*> front_values;
  for (const auto& [values, i] : candidates) {
    bool dominated = false;
    for (const auto* g : front_values) {
      bool no_worse = true, better = false;
      for (size_t k = 0; k < values.size(); ++k) {
        no_worse = no_worse && (*g)[k] <= values[k];
        better = better || (*g)[k] < values[k];
      }
      if (no_worse && better) {
        dominated = true;
        break;
      }
    }
    if (!dominated) {
      front.push_back(i);
      front_values.push_back(&values);
    }
  }
  std::sort(front.begin(), front.end());
  return front;
}

}  // namespace camopt::studies::sweep
