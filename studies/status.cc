#include "studies/status.h"
#include "studies/kind.h"

#include <map>

namespace camopt::studies {

const char* StatusName(Status status) {
  switch (status) {
    case Status::kOptimalVerified: return "optimal_verified";
    case Status::kFeasibleVerified: return "feasible_verified";
    case Status::kInfeasible: return "infeasible";
    case Status::kNotVerifiable: return "not_verifiable";
    case Status::kNotConverged: return "not_converged";
    case Status::kLimitsMet: return "limits_met";
    case Status::kLimitsExceeded: return "limits_exceeded";
  }
  return "not_converged";
}

std::optional<Status> StatusFromName(const std::string& name) {
  for (Status s : kAllStatuses)
    if (name == StatusName(s)) return s;
  return std::nullopt;
}

bool IsVerified(Status status) {
  return status == Status::kOptimalVerified || status == Status::kFeasibleVerified;
}

int ExitCode(Status status, bool strict) {
  switch (status) {
    case Status::kOptimalVerified:
    case Status::kLimitsMet: return 0;
    case Status::kFeasibleVerified:
    case Status::kLimitsExceeded: return strict ? 3 : 0;
    case Status::kInfeasible:
    case Status::kNotVerifiable:
    case Status::kNotConverged: return 3;
  }
  return 3;
}

Status SizingStatus(bool has_design, bool verification_ran, bool verified, bool converged) {
  if (!has_design) return Status::kInfeasible;
  if (verified) return converged ? Status::kOptimalVerified : Status::kFeasibleVerified;
  if (!verification_ran) return Status::kNotVerifiable;
  // The accurate model rejects the design the search ended on: after its tightening rounds when
  // the optimizer converged (the verification did not converge to a design that holds), or at an
  // infeasible stopping point of the optimizer.
  return converged ? Status::kNotConverged : Status::kInfeasible;
}

const std::vector<AskedBlock>& AskedBlocks(const std::string& kind) {
  static const std::vector<AskedBlock> none;
  const KindDescriptor* k = FindKind(kind);
  return k ? k->asked : none;
}

std::vector<std::string> MissingAnswers(const std::string& kind, const nlohmann::json& study,
                                        const nlohmann::json& result) {
  std::vector<std::string> missing;
  for (const AskedBlock& b : AskedBlocks(kind)) {
    bool asked = false;
    for (const std::string& a : b.asked) {
      const nlohmann::json::json_pointer p(a);
      // Given, and not switched off (false or null: not asked).
      asked = asked || (study.contains(p) && !study.at(p).is_null() && study.at(p) != false);
    }
    const nlohmann::json::json_pointer evaluate("/analysis/evaluate");
    if (!b.stages.empty() && study.contains(evaluate) && study.at(evaluate).is_array()) {
      bool staged = false;
      for (const nlohmann::json& stage : study.at(evaluate))
        for (const std::string& s : b.stages) staged = staged || stage == s;
      asked = asked && staged;
    }
    if (!asked) continue;
    const nlohmann::json::json_pointer answer(b.answer);
    // Absent, null, or a block that says why it was not computed ({"skipped": why}, {"error": why}).
    const nlohmann::json* a = result.contains(answer) ? &result.at(answer) : nullptr;
    std::string why;
    for (const char* k : {"skipped", "error"})
      if (a && a->is_object() && a->contains(k) && (*a)[k].is_string()) why = (*a)[k].get<std::string>();
    if (why.empty() && !b.reason.empty()) {
      const nlohmann::json::json_pointer reason(b.reason);
      if (result.contains(reason) && result.at(reason).is_string()) why = result.at(reason).get<std::string>();
    }
    if (!a || a->is_null() || !why.empty())
      missing.push_back(b.what + " (" + b.answer + (why.empty() ? "" : ": " + why) + ")");
  }
  return missing;
}

}  // namespace camopt::studies
