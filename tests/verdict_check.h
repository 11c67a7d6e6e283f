// What a verdict must say, checked from a kind's registered headlines (studies/report.h) rather
// than through the code that writes the verdict: every limit the kind considers and the study did
// not set is named as not checked.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/report.h"
#include "studies/writers.h"

namespace camopt::testing {

/// The labels of the limits a kind's report considers (its registered headlines with a limit)
/// that `study` leaves unset, for values present in `result`: read from the registration
/// directly, so that a test can check the verdict (studies/report.cc) names each one.
inline std::vector<std::string> UnsetLimitLabels(const std::string& kind, const nlohmann::json& study,
                                                 const nlohmann::json& result) {
  auto at = [](const nlohmann::json& j, const std::string& pointer) -> const nlohmann::json* {
    if (pointer.empty() || pointer[0] != '/') return nullptr;
    const nlohmann::json::json_pointer p(pointer);
    return j.contains(p) ? &j.at(p) : nullptr;
  };
  std::vector<std::string> labels;
  const std::vector<studies::Headline>* headlines = studies::FindHeadlines(kind);
  if (!headlines) return labels;
  for (const studies::Headline& h : *headlines) {
    if (h.limit_pointer.empty() || std::isfinite(h.limit_value)) continue;
    const nlohmann::json* v = at(result, h.pointer);
    if (!v || !v->is_number()) continue;
    if (!h.only_with.empty() && !at(result, h.only_with)) continue;
    if (!h.not_with.empty() && at(result, h.not_with)) continue;
    const bool in_study = h.limit_pointer.rfind("study:", 0) == 0;
    const nlohmann::json* l = at(in_study ? study : result, h.limit_pointer.substr(in_study ? 6 : 0));
    if (!l || !l->is_number()) labels.push_back(h.label);
  }
  return labels;
}

/// report.html's verdict names every limit the kind considers and the study did not set
/// (UnsetLimitLabels), unless the answer has no design to check them on.
inline void ExpectVerdictNamesUnsetLimits(const std::string& kind, const nlohmann::json& study,
                                          const nlohmann::json& result, const std::string& report_html) {
  const std::string status = result.value("status", "");
  if (status == "infeasible" || status == "not_converged" || status == "not_verifiable") return;
  const size_t begin = report_html.find("<div class=\"verdict");
  ASSERT_NE(begin, std::string::npos) << "report.html has no verdict";
  const std::string verdict = report_html.substr(begin, report_html.find("</div>", begin) - begin);
  const std::vector<std::string> unset = UnsetLimitLabels(kind, study, result);
  if (unset.empty()) return;
  const size_t list = verdict.find("not checked, no limit set: ");
  ASSERT_NE(list, std::string::npos) << "the verdict does not say which limits were not checked: " << verdict;
  for (const std::string& label : unset)
    EXPECT_NE(verdict.find(studies::XmlText(label), list), std::string::npos)
        << "the verdict does not name the unset limit '" << label << "': " << verdict;
}

}  // namespace camopt::testing
